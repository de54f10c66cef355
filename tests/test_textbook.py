"""Textbook-style problems the tool was not built on (tests/textbook/*.toml), against
independent references.

Each scene is a Theory of Machines exercise with made-up numbers: four-bars of every
Grashof class and both assemblies, slider cranks (in-line, offset, inclined, vertical, on a
path through a named point), an oscillating cylinder, crank and slotted lever (also driven
from the lever), Whitworth and shaper quick returns, Watt and Stephenson six-bars, a stone
crusher and a toggle press, a block sliding on a moving coupler, a coupling rod, points on
links produced, plates, pins, loads, crank angular acceleration, rpm / rps / deg/s,
mm / cm / m / in / ft (with inches, "4 ft 6 in"), angles in a book's words (past the inner dead
centre, from the line of stroke), a block as the driver (an ellipse trammel with a point on
its bar, a slider crank driven from its piston, a collar on a fixed rod driving a lever).

Against the 50-digit reference (tests/reference.py) at 1e-9 of the size of each kind, also
with the crank turned to 0, 90, 180 and 270 deg (a driving block moved along its guide); the branch each [assembly] hint asks for
(and the default one) against the mirror image of the chosen position; the rubbing
velocities from the scene's pins and the reference's omegas; the input torque by virtual
work with the reference's velocities; every instantaneous centre as the point where its two
bodies move alike. Reports without rounding noise: tests/test_textbook_words.py.
"""

import math
from pathlib import Path

import mpmath
import pytest
from mpmath import mpf

from polygon_method import load_scene, solve
from polygon_method.solver.centres import locate
from polygon_method.scene import FixedPath, GuideSlider
from reference import reference_positions, reference_solution
from textbook_corpus import (
    FILES,
    HERE,
    REL,
    at_angle,
    turned_cases,
    guide_direction,
    other_position,
    solved,
    turned,
    worst_error,
)


@pytest.mark.parametrize("path", FILES, ids=[f.stem for f in FILES])
def test_matches_reference(path):
    scene, sol, ref = solved(path)
    assert ref["residual"] < mpf("1e-40")
    err, what = worst_error(scene, sol, ref)
    assert err < REL, f"{what}: relative error {err:.2e}"
    assert not sol.warnings  # every scene is well away from a toggle


HINTED = [
    (f, X)
    for f in FILES
    for X in load_scene(f).assembly
    if other_position(load_scene(f), solve(load_scene(f)).P, X) is not None
]


@pytest.mark.parametrize("path,X", HINTED, ids=[f"{f.stem}-{X}" for f, X in HINTED])
def test_assembly_hint_is_honoured(path, X):
    scene, sol, _ = solved(path)
    hint = scene.assembly[X]
    here, other = sol.P[X], other_position(scene, sol.P, X)
    if isinstance(hint, str):
        axis, sign = {"above": (1, 1), "below": (1, -1), "right": (0, 1), "left": (0, -1)}[hint]
        assert (here[axis] - other[axis]) * sign > 0, (here, other)
    else:
        assert math.dist(here, hint) < math.dist(other, hint), (here, other)


def _bodies_at_pin(scene, name, omega):
    """Every body a pin joins, with its omega (the reference's): links with the point as a
    joint, the link (plate) a carried point is on, the ground, a block pinned there."""
    out = {}
    for lk in scene.links:
        if name in (lk.p, lk.q):
            out[lk.key] = omega[lk.key]
    for cp in scene.points:
        if cp.name == name:
            out[scene.link(cp.link).key] = omega[scene.link(cp.link).key]
    if name in scene.ground:
        out["ground"] = 0
    for s in scene.sliders:
        if s.point == name:
            # (a peg in two slots: a block in each, the one in a moving slot turning with it)
            out[f"block {s.key}"] = (
                omega[scene.link(s.guide).key] if isinstance(s, GuideSlider) else 0
            )
    return out


PINNED = [f for f in FILES if load_scene(f).pins]


@pytest.mark.parametrize("path", PINNED, ids=[f.stem for f in PINNED])
def test_rubbing_velocities_by_hand(path):
    scene, sol, ref = solved(path)
    for pin in scene.pins:
        w = list(_bodies_at_pin(scene, pin.point, ref["omega"]).values())
        want = max(abs(a - b) for i, a in enumerate(w) for b in w[i + 1 :]) * mpf(pin.radius)
        got = sol.rubbing[pin.point].rubbing_velocity
        assert abs(got - float(want)) <= 1e-9 * max(float(want), 1e-12), pin.point


LOADED = [f for f in FILES if load_scene(f).loads]


@pytest.mark.parametrize("path", LOADED, ids=[f.stem for f in LOADED])
def test_input_torque_by_virtual_work(path):
    """T omega + sum F . v + sum T_L omega_L = 0 with the reference's velocities."""
    scene, sol, ref = solved(path)
    power = mpf(0)
    for load in scene.loads:
        if load.force is not None:
            v = ref["velocities"][load.target]
            power += mpf(load.force[0]) * v[0] + mpf(load.force[1]) * v[1]
        else:
            power += mpf(load.torque) * ref["omega"][scene.link(load.target).key]
    want = float(-power / mpf(scene.input.omega))
    assert sol.input_torque == pytest.approx(want, rel=1e-9, abs=1e-12)


#: the virtual displacements need the reference's positions at a turned crank angle, which
#: turn no gear of [rolling] with it (its no-slip relation is read at the scene's instant)
LOADED_NO_GEARS = [f for f in LOADED if not load_scene(f).rolling]


@pytest.mark.parametrize("path", LOADED_NO_GEARS, ids=[f.stem for f in LOADED_NO_GEARS])
def test_input_torque_by_virtual_displacements(path):
    """T = -(sum F . dr/dtheta + sum T_L dphi_L/dtheta), the derivatives central differences
    of the reference's positions at theta +- 1e-20 rad."""
    scene, sol, ref = solved(path)
    h, th = mpf("1e-20"), mpf(scene.input.angle)
    P = {s: reference_positions(scene, ref["positions"], th + s * h)[0] for s in (-1, 1)}
    work = mpf(0)  # per radian of the crank
    for load in scene.loads:
        if load.force is not None:
            d = [(P[1][load.target][k] - P[-1][load.target][k]) / (2 * h) for k in (0, 1)]
            work += mpf(load.force[0]) * d[0] + mpf(load.force[1]) * d[1]
        else:
            lk = scene.link(load.target)
            phi = {
                s: mpmath.atan2(P[s][lk.q][1] - P[s][lk.p][1], P[s][lk.q][0] - P[s][lk.p][0])
                for s in (-1, 1)
            }
            work += mpf(load.torque) * (phi[1] - phi[-1]) / (2 * h)
    assert sol.input_torque == pytest.approx(float(-work), rel=1e-9, abs=1e-12)


def test_corpus_covers_the_format():
    """The corpus states every construction the scene format can state."""
    scenes = [load_scene(f) for f in FILES]
    assert len(scenes) >= 15
    sliders = [s for sc in scenes for s in sc.sliders]
    assert any(
        isinstance(s, GuideSlider) and s.point in sc.ground for sc in scenes for s in sc.sliders
    )  # a swivel
    assert any(isinstance(s, GuideSlider) for s in sliders)
    labels = {s.label for s in sliders if isinstance(s, FixedPath)}
    assert {"horizontal", "vertical"} <= labels and len(labels) >= 4
    assert {sc.units for sc in scenes} == {"mm", "cm", "m", "in", "ft"}
    assert any(sc.input.angle_words for sc in scenes)  # an angle in a book's words
    assert any(sc.input.alpha for sc in scenes)
    assert {round(math.degrees(sc.input.angle)) % 360 for sc in scenes} >= {0, 90, 180, 270}
    assert any(cp.lam > 1 or cp.lam < 0 for sc in scenes for cp in sc.points)  # produced
    assert any(cp.mu for sc in scenes for cp in sc.points)  # a plate
    assert any(ld.torque is not None for sc in scenes for ld in sc.loads)
    assert any(ld.force is not None for sc in scenes for ld in sc.loads)
    driven = [sc for sc in scenes if sc.input.block is not None]  # a block as the driver,
    guides = {
        getattr(sc.slider(sc.input.block), "label", "a turning rod")  # on guides of
        for sc in driven
    }  # every kind, and a collar on a turning rod
    assert "a turning rod" in guides
    assert {"horizontal", "vertical"} < guides and any(sc.loads for sc in driven)


def test_slider_crank_driven_from_its_piston_by_hand():
    """The piston's place x = r cos t + sqrt(l^2 - r^2 sin^2 t) gives the crank's angle t
    (A above the line of stroke); x' = vs and x'' = as give omega and alpha of the crank
    (50 digits, differentiated by hand: x' = k(t) t', x'' = k'(t) t'^2 + k(t) t'')."""
    scene, sol, _ = solved(HERE / "block_piston_slider_crank.toml")
    mpmath.mp.dps = 50
    r, l, x = mpf("0.1"), mpf("0.4"), mpf("0.38")
    vs, acc = mpf(-4), mpf(30)
    c = (x * x + r * r - l * l) / (2 * r * x)  # the triangle OAB: cos t
    t = mpmath.acos(c)  # A above: 0 < t < pi

    def k(t):
        s, c = mpmath.sin(t), mpmath.cos(t)
        return -r * s - r * r * s * c / mpmath.sqrt(l * l - r * r * s * s)

    w = vs / k(t)
    al = (acc - mpmath.diff(k, t) * w * w) / k(t)
    assert sol.W["OA"] == pytest.approx(float(w), rel=1e-9)
    assert sol.Al["OA"] == pytest.approx(float(al), rel=1e-9)
    assert sol.P["A"] == pytest.approx(
        (float(r * mpmath.cos(t)), float(r * mpmath.sin(t))), rel=1e-12
    )


def _body_field(sol, name):
    """The velocity field of a body, from the polygon solution: (omega, point, velocity)."""
    sc = sol.scene
    if name == "ground":
        return 0.0, (0.0, 0.0), (0.0, 0.0)
    if name.startswith("block "):
        s = sc.slider(name.split()[1])  # by its key: a peg has a block in each slot
        w = sol.W[sc.link(s.guide).key] if isinstance(s, GuideSlider) else 0.0
        return w, sol.P[s.point], sol.V[s.point]
    if name.startswith(("barrel ", "rod ")):  # a cylinder's two bodies turn with its line
        cyl = sc.cylinder(name.split()[1])
        (bx, by), (rx, ry) = sol.P[cyl.barrel], sol.P[cyl.rod]
        (ux, uy), (vx, vy) = sol.V[cyl.barrel], sol.V[cyl.rod]
        w = ((rx - bx) * (vy - uy) - (ry - by) * (vx - ux)) / ((rx - bx) ** 2 + (ry - by) ** 2)
        end = cyl.barrel if name.startswith("barrel") else cyl.rod
        return w, sol.P[end], sol.V[end]
    lk = sc.link(name)
    return sol.W[lk.key], sol.P[lk.p], sol.V[lk.p]


def _v_at(field, X):
    w, (px, py), (vx, vy) = field
    return (vx - w * (X[1] - py), vy + w * (X[0] - px))


TWO_INPUTS = [f for f in FILES if load_scene(f).input.second is not None]
CENTRE_CASES = [
    pytest.param(f.read_text(encoding="utf-8"), id=f.stem) for f in FILES if f not in TWO_INPUTS
] + [
    pytest.param(at_angle(HERE / name, a), id=f"{Path(name).stem}-{a}")
    for name in ("slotted_lever_270.toml", "shaper_offset_ram.toml")
    for a in (90, 270)
]


@pytest.mark.parametrize("text", CENTRE_CASES)
def test_every_centre_is_where_the_two_bodies_move_alike(text):
    """Each centre I_ij: the point where bodies i and j have one velocity (by the polygon's
    omegas and velocities); at infinity, the two bodies' relative motion is a translation
    perpendicular to its direction. A crank and slotted lever at mid-stroke (crank at 90 or
    270 deg: every Kennedy line through the known centres is the one line O1-O2) used to be
    refused: "Kennedy's theorem cannot locate I25, I26"."""
    from polygon_method import parse_scene

    sol = solve(parse_scene(text))
    ic = locate(sol)
    vmax = max(math.hypot(*v) for v in sol.V.values())
    wmax = max(abs(w) for w in sol.W.values())
    assert len(ic.centres) == ic.n * (ic.n - 1) // 2
    for (i, j), c in ic.centres.items():
        fi, fj = (_body_field(sol, ic.bodies[k - 1]) for k in (i, j))
        if c.point is None:
            assert abs(fi[0] - fj[0]) <= 1e-9 * wmax, c.label
            d = [a - b for a, b in zip(_v_at(fi, (0, 0)), _v_at(fj, (0, 0)))]
            assert abs(d[0] * c.direction[0] + d[1] * c.direction[1]) <= 1e-9 * vmax, c.label
            continue
        vi, vj = _v_at(fi, c.point), _v_at(fj, c.point)
        assert math.dist(vi, vj) <= 1e-9 * vmax, (c.label, vi, vj)
    for k in range(2, ic.n + 1):  # and the omegas by the ratio theorem are the polygon's
        assert ic.omegas[k] == pytest.approx(
            _body_field(sol, ic.bodies[k - 1])[0], rel=1e-9, abs=1e-9 * wmax
        )


@pytest.mark.parametrize("path", TWO_INPUTS, ids=[f.stem for f in TWO_INPUTS])
def test_two_inputs_centres_refused_in_one_line_saying_why(path):
    """With two inputs a centre of two bodies depends on the ratio of the input speeds:
    Kennedy's theorem does not reach every centre, and says so (docs/scene-format.md)."""
    from polygon_method.common.errors import SingularStepError

    with pytest.raises(SingularStepError, match="two inputs") as exc:
        locate(solved(path)[1])
    assert "\n" not in str(exc.value)


def test_answers_in_inch_units():
    """A problem set in inches gives its answers in in/s, ft/s^2 and lbf in (it was
    refused: "unknown unit 'in/s'")."""
    from polygon_method import parse_scene
    from polygon_method.check import check_answers

    scene, sol, ref = solved(HERE / "fourbar_inches.toml")
    v = float(mpmath_norm(ref["velocities"]["A"])) / 0.0254
    a = float(mpmath_norm(ref["accelerations"]["B"])) / 0.3048
    t = abs(sol.input_torque) / (4.4482216152605 * 0.0254)
    text = (
        (HERE / "fourbar_inches.toml").read_text(encoding="utf-8")
        + f"""
[answers]
tolerance = "0.01%"
v_A = "{v:.7g} in/s"
a_B = "{a:.7g} ft/s^2"
torque = "{t:.7g} lbf in"
"""
    )
    verdicts = check_answers(solve(parse_scene(text)))
    assert [vd.ok for vd in verdicts] == [True, True, True], verdicts


def mpmath_norm(v):
    import mpmath

    return mpmath.sqrt(v[0] ** 2 + v[1] ** 2)


_GOOD, _REFUSED = turned_cases()
TURNED = [pytest.param(f, a, id=f"{f.stem}-{a}") for f, a in _GOOD]


@pytest.mark.parametrize(
    "path,angle,exc", [pytest.param(f, a, e, id=f"{f.stem}-{a}") for f, a, e in _REFUSED]
)
def test_turned_where_refused_the_refusal_is_one_line_naming_the_step_and_it_is_true(
    path, angle, exc
):
    """Where a scene turned to 0/90/180/270 deg is refused, the refusal is one line naming
    the step, the [assembly] key or the given motion's [input] key, says why in numbers written without rounding noise,
    and is an assembly or singularity refusal (never another fault)."""
    import re

    from polygon_method.common.errors import AssemblyError, SingularStepError

    msg = str(exc)
    assert isinstance(exc, (AssemblyError, SingularStepError)), msg
    assert "\n" not in msg and re.search(r"step \d+ \(|\[assembly\] |\[input\] \w+ ", msg), msg
    assert not re.search(r"\de-1\d", msg), msg  # no 1.2e-14 for a zero


@pytest.mark.parametrize("path,angle", TURNED)
def test_turned_to_the_special_angles_matches_reference(path, angle):
    """Every scene with its crank at 0, 90, 180 and 270 deg (where it assembles on the
    scene's hints): dead centres, mid-strokes, links along the line of centres."""
    sol = turned(path, angle)
    ref = reference_solution(sol.scene, sol.P)
    err, what = worst_error(sol.scene, sol, ref)
    assert err < REL, f"{what}: relative error {err:.2e}"


DEFAULTED = [
    (f, s.point)
    for f in FILES
    for s in load_scene(f).sliders
    if s.point not in load_scene(f).assembly
    and s.point not in load_scene(f).ground
    and other_position(load_scene(f), solved(f)[1].P, s.point) is not None
]


@pytest.mark.parametrize("path,X", DEFAULTED, ids=[f"{f.stem}-{X}" for f, X in DEFAULTED])
def test_default_slider_position_is_the_one_farther_along_its_path(path, X):
    """scene-format.md: without a hint, a slider takes the position farther along its
    guide's direction (a path at -120 deg: down and to the left; a block on a moving link,
    from the guide's first point towards its second)."""
    scene, sol, _ = solved(path)
    u = guide_direction(scene, sol.P, X)
    here, other = sol.P[X], other_position(scene, sol.P, X)
    assert (here[0] - other[0]) * u[0] + (here[1] - other[1]) * u[1] > 0


def test_rocker_driven_through_a_block_is_the_output():
    """A rocker whose end slides on the moving input lever is the linkage's output: its
    swing (2 acos(O2-A / O2O4) = 132.84 deg, between the limit positions where it stands
    perpendicular to the lever) was not reported."""
    from polygon_method.linkage import analyse

    text = analyse(load_scene(HERE / "slotted_lever_driven.toml")).text()
    swing = math.degrees(2 * math.acos(120 / 300))
    assert (
        f"output link O2-A: swings between -156.4218 and -23.5782 deg: swing {swing:.4f} deg"
        in text
    ), text


def _free_ends(scene):
    """(block, pivot, free end) of each slotted link (a block at the crank's tip or at a
    fixed swivel) whose free end the scene leaves to the default."""
    out = []
    for s in scene.sliders:
        if not isinstance(s, GuideSlider) or not (
            s.point in scene.ground or s.point == scene.input.tip
        ):
            continue
        for end, pivot in ((s.first, s.second), (s.second, s.first)):
            if end not in scene.ground and end != scene.input.tip and end not in scene.assembly:
                out.append((s.point, pivot, end))
    return out


FREE_ENDS = [(f, e) for f in FILES for e in _free_ends(load_scene(f))]


@pytest.mark.parametrize("path,ends", FREE_ENDS, ids=[f"{f.stem}-{e[2]}" for f, e in FREE_ENDS])
def test_default_slotted_link_end_is_on_the_side_of_the_block(path, ends):
    """scene-format.md: without a hint, a slotted link's free end is on the side of the
    block (the oscillating cylinder's rod end C beyond the trunnion O)."""
    scene, sol, _ = solved(path)
    b, k, n = (sol.P[x] for x in ends)
    assert (n[0] - k[0]) * (b[0] - k[0]) + (n[1] - k[1]) * (b[1] - k[1]) > 0


def test_peaucellier_point_moves_on_its_straight_line():
    """Closed form: D is the inverse of C (OC x OD = OA^2 - AC^2 = 20000 mm^2) and C runs on
    a circle through O, so D stays on the line x = 20000 / (2 OQ) = 100 mm: its x, and the
    x components of its velocity and acceleration, are 100 mm, 0, 0 at any crank angle."""
    for angle in (20, 45, 60, 80):  # (the figure's D: left of C, until they meet at 90)
        sol = turned(HERE / "peaucellier.toml", angle)
        assert sol is not None
        vs, as_ = sol.scales["v"], sol.scales["a"]
        assert sol.P["D"][0] == pytest.approx(0.1, abs=1e-15)
        assert abs(sol.V["D"][0]) <= 1e-12 * vs and abs(sol.A["D"][0]) <= 1e-12 * as_
        oc, od = math.hypot(*sol.P["C"]), math.hypot(*sol.P["D"])
        assert oc * od == pytest.approx(0.15**2 - 0.05**2, rel=1e-13)


def _two_given(f) -> bool:
    inp = load_scene(f).input
    return inp.second is not None and (inp.given or inp.second.given) is not None


FOUND = [f for f in FILES if _two_given(f)]
GIVEN = [f for f in FILES if load_scene(f).input.given is not None and f not in FOUND]


@pytest.mark.parametrize("path", FOUND, ids=[f.stem for f in FOUND])
def test_the_reference_moves_the_two_inputs_given_speeds_as_stated(path):
    """Two inputs whose speeds are given on other links (a differential's sun and
    annulus): the 50-digit reference, solved at both cranks' speeds the tool found, turns
    each given link at its stated speed and rate (0 where none is given), to 1e-9."""
    scene, sol, ref = solved(path)
    assert scene.input.found_from
    for g in scene.input.found_from:
        key = scene.link("-".join(g.names)).key
        assert abs(ref["omega"][key] - mpf(g.value)) <= REL * abs(g.value)
        rate = mpf(g.rate or 0)
        assert abs(ref["alpha"][key] - rate) <= REL * max(abs(rate), g.value**2)


@pytest.mark.parametrize("path", GIVEN, ids=[f.stem for f in GIVEN])
def test_the_reference_moves_the_given_quantity_as_stated(path):
    """A motion given on another quantity (a piston's, a coupler's, a cylinder's rate of
    extension): the 50-digit reference, solved at the crank's speed the tool found, moves
    that quantity at the stated value and rate (the rate 0 where none is given), to 1e-9:
    so the found speed and acceleration are right."""
    scene, sol, ref = solved(path)
    g = scene.input.given
    if g.kind == "omega":
        key = scene.link("-".join(g.names)).key
        got, rate = ref["omega"][key], ref["alpha"][key]
    elif g.kind == "vs" and scene.cylinder(g.names[0]) is not None:
        cyl = scene.cylinder(g.names[0])
        d = [ref["positions"][cyl.rod][k] - ref["positions"][cyl.barrel][k] for k in (0, 1)]
        v = [ref["velocities"][cyl.rod][k] - ref["velocities"][cyl.barrel][k] for k in (0, 1)]
        a = [ref["accelerations"][cyl.rod][k] - ref["accelerations"][cyl.barrel][k] for k in (0, 1)]
        L = mpmath.sqrt(d[0] ** 2 + d[1] ** 2)
        got = (d[0] * v[0] + d[1] * v[1]) / L  # L' and L'' of L^2 = d . d
        rate = (v[0] ** 2 + v[1] ** 2 + d[0] * a[0] + d[1] * a[1] - got**2) / L
    elif g.kind == "vs":
        s = ref["sliders"][g.names[0]]
        got, rate = s["vs"], s["as"]
    else:
        v, a = ref["velocities"][g.names[0]], ref["accelerations"][g.names[0]]
        u = g.direction
        got = v[0] * u[0] + v[1] * u[1]
        rate = a[0] * u[0] + a[1] * u[1]
    want_rate = mpf(g.rate or 0) if scene.input.alpha is None or g.rate is not None else None
    assert abs(got - mpf(g.value)) <= REL * abs(g.value)
    if want_rate is not None:
        assert abs(rate - want_rate) <= REL * max(abs(want_rate), abs(g.value) ** 2, 1e-300)
