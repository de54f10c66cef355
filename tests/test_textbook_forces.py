"""The force chapter's textbook corpus (tests/textbook/force_*.toml): static force analysis
of four-bars, slider cranks, quick-return and six-bar mechanisms under loads and couples
(the static ones with an empty ``[masses]`` table), the dynamic force analysis of massive
linkages at speed (shaking force and moment), shapers under the cutting force, and the
engine chapter (piston effort, thrusts, crank effort, a heavy connecting rod, vertical
engines with the parts' weight).

Against references that share nothing with the force solver:

- the driver's torque by virtual power, with the 50-digit kinematics of
  ``tests/reference.py``: ``T w + sum F.v + sum C w_L + sum m g.v_G - sum m a_G.v_G - sum
  I alpha w = 0``, G's motion from its link's end points;
- the shaking force and moment from the loads, weights and inertia alone (the same
  reference kinematics);
- Newton-Euler on every body of the file's own masses from the pin forces found;
- the engine chapter's closed forms at 50 digits (``tests/engines.py``), and for a heavy
  connecting rod the books' own second method, the equivalent dynamical system (two
  masses and the correction couple);
- the statics by hand (a two-force member's moments about a pivot);
- the book-style answers each file gives, by ``check`` within the file's tolerance.
"""

from __future__ import annotations

import math
from pathlib import Path

import mpmath
import pytest
from mpmath import mpf

from engines import _precision, closed_forms  # noqa: F401  (a fixture)
from polygon_method import load_scene, solve
from polygon_method.check import check_answers
from polygon_method.forces.engine import efforts
from reference import reference_solution
from test_forces import _newton_euler

HERE = Path(__file__).resolve().parent / "textbook"
FILES = sorted(HERE.glob("force_*.toml"))
REL = mpf("1e-9")
STATIC = [f for f in FILES if f.stem.startswith("force_static")]


def _solved(path):
    sol = solve(load_scene(path))
    sc = sol.scene  # the crank's angle found where the position is given otherwise
    mpmath.mp.dps = 50
    return sc, sol, reference_solution(sc, sol.P)


def _gas(sc, ld, ref):
    """A gas force on a piston, towards the crank's foot on the line of stroke (by hand)."""
    s = sc.slider(ld.target)
    u = [mpf(c) for c in s.u]
    O, B = ref["positions"][sc.link(sc.input.crank).p], ref["positions"][ld.target]
    ahead = (O[0] - B[0]) * u[0] + (O[1] - B[1]) * u[1]
    k = mpf(ld.toward) * (1 if ahead > 0 else -1)
    return (k * u[0], k * u[1])


def _external(sc, ref):
    """(force, point) of every load and weight and -m a_G; couples; the power of them all
    with the reference's velocities (50 digits)."""
    P, V, A = ref["positions"], ref["velocities"], ref["accelerations"]
    forces, couples, power = [], [], mpf(0)
    for ld in sc.loads:
        if ld.torque is not None:
            couples.append(mpf(ld.torque))
            power += mpf(ld.torque) * ref["omega"][sc.link(ld.target).key]
            continue
        F = _gas(sc, ld, ref) if ld.toward is not None else tuple(mpf(c) for c in ld.force)
        v = V[ld.target]
        power += F[0] * v[0] + F[1] * v[1]
        if ld.gas is None:  # (a gas force's reaction is on the cover: internal, whether
            forces.append((F, P[ld.target]))  # its direction is given or towards the crank)
    g = sc.gravity
    for m in sc.masses:
        if m.block:
            G, vG, aG, al, w = P[m.body], V[m.body], A[m.body], 0, 0
        else:
            lk = sc.link(m.body)

            def at(T, lk=lk, m=m):
                (px, py), (qx, qy) = T[lk.p], T[lk.q]
                dx, dy = qx - px, qy - py
                lam, mu = mpf(m.lam), mpf(m.mu)
                return (px + lam * dx - mu * dy, py + lam * dy + mu * dx)

            G, vG, aG = at(P), at(V), at(A)
            al, w = ref["alpha"][lk.key], ref["omega"][lk.key]
        mass = mpf(m.mass)
        gx, gy = (mpf(g.g) * mpf(g.direction[0]), mpf(g.g) * mpf(g.direction[1])) if g else (0, 0)
        W = (mass * gx, mass * gy)
        Fi = (W[0] - mass * aG[0], W[1] - mass * aG[1])
        forces.append((Fi, G))
        couples.append(-mpf(m.inertia) * al)
        power += Fi[0] * vG[0] + Fi[1] * vG[1] - mpf(m.inertia) * al * w
    return forces, couples, power


@pytest.mark.parametrize("path", FILES, ids=[f.stem for f in FILES])
def test_driver_torque_by_virtual_power_with_the_reference(path):
    sc, sol, ref = _solved(path)
    _, _, power = _external(sc, ref)
    if sc.input.block is None:
        want = -power / ref["omega"][sc.link(sc.input.crank).key]
    else:  # a driving block: its force along its guide, by its sliding velocity
        want = -power / ref["sliders"][sc.slider(sc.input.block).key]["vs"]
    assert abs(sol.forces.input_torque - want) <= REL * abs(want), (sol.forces.input_torque, want)


@pytest.mark.parametrize("path", FILES, ids=[f.stem for f in FILES])
def test_shaking_force_and_moment_from_the_loads_weights_and_inertia(path):
    sc, sol, ref = _solved(path)
    forces, couples, _ = _external(sc, ref)
    Fx, Fy = sum(F[0] for F, _ in forces), sum(F[1] for F, _ in forces)
    M = sum(r[0] * F[1] - r[1] * F[0] for F, r in forces) + sum(couples)
    scale = max((abs(F[0]) + abs(F[1]) for F, _ in forces), default=0)
    couple = sum(abs(c) for c in couples)
    got = sol.forces.shaking_force
    assert abs(got[0] - Fx) <= REL * scale and abs(got[1] - Fy) <= REL * scale, (got, Fx, Fy)
    arm = max(abs(c) for r in ref["positions"].values() for c in r)
    assert abs(sol.forces.shaking_moment - M) <= REL * (scale * arm + couple)


@pytest.mark.parametrize("path", FILES, ids=[f.stem for f in FILES])
def test_newton_euler_on_every_body_with_the_files_own_masses(path):
    sol = solve(load_scene(path))
    res = _newton_euler(sol, sol.forces)
    sc = sol.scene
    moving = {lk.key for lk in sc.links if not (lk.p in sc.ground and lk.q in sc.ground)}
    assert moving <= set(res)
    for body, (rf, rm, fs, ms) in res.items():
        assert rf <= 1e-9 * fs and rm <= 1e-9 * ms, (body, rf, rm)


@pytest.mark.parametrize("path", FILES, ids=[f.stem for f in FILES])
def test_the_book_style_answers_hold(path):
    sol = solve(load_scene(path))
    verdicts = check_answers(sol)
    assert verdicts and all(v.ok for v in verdicts), [
        (v.key, v.given, v.correct) for v in verdicts if not v.ok
    ]


def test_the_corpus_states_the_chapter():
    """At least 20 force problems: statics of every shape, dynamics, engines."""
    assert len(FILES) >= 20 and len(STATIC) >= 8
    scenes = [load_scene(f) for f in STATIC]
    assert all(sc.statics and not sc.masses and sc.gravity is None for sc in scenes)
    kinds = {type(s).__name__ for sc in map(load_scene, FILES) for s in sc.sliders}
    assert {"FixedPath", "GuideSlider"} <= kinds


def _area(d_mm):
    return mpmath.pi / 4 * (mpf(d_mm) / 1000) ** 2


ENGINES = {  # file: (r, l, rpm, reciprocating mass, i.d.c. at deg from +x, sense, gas (N))
    # 0.6 N/mm^2 on the cover side of a 300 mm bore, 0.05 on the crank side less a 50 mm rod
    "force_engine_double_acting": (
        225,
        1000,
        200,
        180,
        0,
        1,
        0.6e6 * _area(300) - 0.05e6 * (_area(300) - _area(50)),
    ),
    "force_engine_petrol_from_idc": (60, 240, 1800, 1.2, 0, 1, 0.8e6 * _area(90)),
    "force_engine_khurmi_horizontal": (300, 1200, 250, 250, 0, 1, 0.35e6 * _area(500)),
    # the line of stroke at 60 deg: the weight's part along it (towards the crank) is a gas
    # force; its part across it, m g cos 60, adds to the side thrust
    "force_engine_inclined_weight": (
        100,
        400,
        1500,
        2,
        60,
        1,
        2e6 * _area(100) + 2 * mpf("9.81") * mpmath.sin(mpmath.pi / 3),
        2 * mpf("9.81") * mpmath.cos(mpmath.pi / 3),
    ),
}


@pytest.mark.parametrize("name", sorted(ENGINES))
def test_engine_efforts_by_the_closed_forms(name):
    r, l, rpm, m, idc, sg, gas, *across = ENGINES[name]
    sc, sol, ref = _solved(HERE / f"{name}.toml")
    e = efforts(sc, sol.plan, sol.P, sol.forces)
    theta = mpmath.degrees(mpmath.atan2(*reversed(ref["positions"]["A"])))
    want = closed_forms(idc, theta, r, l, rpm, m, gas, sg)
    want["F_N"] += sum(across)
    for got, key in ((e.F_P, "F_P"), (e.F_Q, "F_Q"), (e.F_N, "F_N"), (e.F_T, "F_T"), (e.T, "T")):
        scale = abs(want["F_Q"]) * (mpf(r) / 1000 if key == "T" else 1)
        assert abs(got - want[key]) <= REL * scale, key


HEAVY_RODS = {  # file: (r, l, rpm, sense, deg past the i.d.c., rod mass, G from the crank
    # pin, k, piston mass, gas force towards the crank (N), g along the stroke to the crank)
    "force_engine_heavy_rod": (150, 600, 600, -1, 30, 40, 200, 200, 50, 0, 0),
    "force_engine_vertical_rod_weight": (
        200,
        900,
        300,
        -1,
        60,
        90,
        350,
        300,
        120,
        1.2e6 * _area(250),
        mpf("9.81"),
    ),
}


def _equivalent_system(name):
    """(the turning moment with the rotation, its correction couple's part, the sense) of
    a heavy-rod engine by the books' equivalent dynamical system: the rod replaced by a mass
    at the gudgeon pin (reciprocating with the piston) and one at the crank pin (turning
    with the crank), ``m_B = m GA / l``, ``m_A = m GB / l`` (statically equivalent), and the
    correction couple ``-m (k^2 - GA GB) alpha_rod`` for the moment of inertia they leave
    out, carried to the crank by ``omega_rod / omega``; the parts' weights (a vertical
    engine: along the stroke, towards the crank) on the piston and at the crank pin. All in
    the engine's own frame (the piston along +x, the crank turning ccw), t from the i.d.c."""
    r, l, rpm, sg, deg, m, ga, k, mp, gas, g = HEAVY_RODS[name]
    R, L, GA, K = (mpf(x) / 1000 for x in (r, l, ga, k))
    GB = L - GA
    mB, mA = m * GA / L, m * GB / L
    w = 2 * mpmath.pi * rpm / 60
    t = mpmath.radians(deg)
    # the reciprocating parts (the piston and m_B): the closed forms, their weight a gas force
    recip = closed_forms(0, deg, r, l, rpm, mp + mB, gas + (mp + mB) * g)["T"]
    weight_at_pin = mA * g * R * mpmath.sin(t)  # m_A g (towards the crank) at A
    psi = lambda u: mpmath.pi - mpmath.asin(R * mpmath.sin(u) / L)  # noqa: E731  the rod B->A
    w_rod, a_rod = mpmath.diff(psi, t, 1) * w, mpmath.diff(psi, t, 2) * w**2
    correction = -m * (K**2 - GA * GB) * a_rod * w_rod / w
    return recip + weight_at_pin + correction, correction, sg


@pytest.mark.parametrize("name", sorted(HEAVY_RODS))
def test_heavy_rod_by_the_equivalent_dynamical_system(name):
    turning, _, sg = _equivalent_system(name)
    sol = solve(load_scene(HERE / f"{name}.toml"))
    want = -sg * turning  # the driver's torque, ccw positive: against the turning moment
    assert abs(sol.forces.input_torque - want) <= REL * abs(want), (sol.forces.input_torque, want)


@pytest.mark.parametrize("name", sorted(HEAVY_RODS))
def test_the_correction_couple_left_out_is_named(name):
    """A student who puts the rod's two masses at its pins and forgets the correction
    couple: check names the slip (the value from the equivalent system without it)."""
    from polygon_method import parse_scene

    turning, correction, sg = _equivalent_system(name)
    text = (HERE / f"{name}.toml").read_text(encoding="utf-8")
    text = text[: text.index("[answers]")]
    slip = abs(turning - correction)
    sol = solve(parse_scene(f'{text}[answers]\ntorque = "{float(slip):.6g} N m"\n'))
    (v,) = check_answers(sol)
    assert not v.ok and v.mistake == "correction_couple_left_out", v
    assert abs(v.correct - abs(turning)) <= REL * abs(turning)


STATIC_TEXT = """
title = "slider crank held"
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 150
AB = 600
[sliders]
B = { path = "horizontal", through = "O" }
[input]
crank = "OA"
angle = 45
speed = "1 rad/s ccw"
[loads]
B = { force = "2 kN", direction = 180 }
"""


def test_an_empty_masses_table_asks_for_the_static_force_analysis():
    """docs/scene-format.md: an empty [masses] asks for the pin forces under the loads
    alone (it used to be read as no [masses]: the torque only, and a force answer refused).
    By hand: F_Q = F / cos phi, F_N = F tan phi, sin phi = r sin 45 deg / l."""
    from polygon_method import parse_scene
    from polygon_method.scene import scene_from_table, scene_table
    from polygon_method.text.steptable import steps_text

    assert solve(parse_scene(STATIC_TEXT)).forces is None
    sc = parse_scene(STATIC_TEXT + "[masses]\n")
    sol = solve(sc)
    phi = mpmath.asin(mpf("0.15") * mpmath.sin(mpmath.pi / 4) / mpf("0.6"))
    (pin,) = [p for p in sol.forces.pins if p.point == "B"]
    assert abs(mpmath.hypot(*pin.force) - 2000 / mpmath.cos(phi)) <= REL * 2000
    (gd,) = sol.forces.guides
    assert abs(abs(gd.normal) - 2000 * mpmath.tan(phi)) <= REL * 2000
    assert sol.forces.input_torque == pytest.approx(sol.input_torque, rel=1e-12)
    assert scene_from_table(scene_table(sc)).statics  # (a variant keeps it)
    assert "a static force analysis, no inertia forces" in " ".join(steps_text(sol).split())
    assert "input torque on OA (the loads alone: a static force analysis): 250.2 N m cw" in (
        sol.report()
    )
    text = STATIC_TEXT + '[masses]\n[answers]\ntolerance = "1%"\nF_B = "2032 N"\nN_B = "359.2 N"\n'
    assert all(v.ok for v in check_answers(solve(parse_scene(text))))


def test_a_crank_at_rest_holds_its_weights_and_loads():
    """A crank at rest (speed 0) with [masses] and [gravity]: the weights and the loads
    alone, no inertia. By virtual work with the closed-form positions: T = 2000 dx_B/dtheta
    + m g (r/2) cos theta (x_B = r cos theta + sqrt(l^2 - r^2 sin^2 theta)); without
    [gravity] or [masses] a zero speed is refused, saying how to state it."""
    from polygon_method import parse_scene
    from polygon_method.common.errors import SceneError

    text = STATIC_TEXT.replace('"1 rad/s ccw"', '"0 rad/s"')
    with pytest.raises(SceneError, match=r"give \[masses\] and \[gravity\]"):
        parse_scene(text)
    sol = solve(parse_scene(text + "[masses]\nOA = { mass = 2 }\n[gravity]\n"))
    th, r, l = mpmath.pi / 4, mpf("0.15"), mpf("0.6")
    dx = -r * mpmath.sin(th) - r * r * mpmath.sin(th) * mpmath.cos(th) / mpmath.sqrt(
        l * l - (r * mpmath.sin(th)) ** 2
    )
    T = 2000 * dx + 2 * mpf("9.81") * r / 2 * mpmath.cos(th)
    assert abs(sol.forces.input_torque - float(T)) <= 1e-9 * abs(float(T))


def test_the_turning_moment_is_an_answer_key_and_its_slip_is_named():
    """Khurmi's "turning moment on the crank shaft" (`turning_moment`, it was refused as an
    unknown key, "did you mean 'shaking_moment'?"): held to the closed forms, and the
    reciprocating parts' inertia left out (the closed forms with m = 0) named."""
    from polygon_method import parse_scene

    r, l, rpm, m, idc, sg, gas = ENGINES["force_engine_double_acting"]
    T = closed_forms(idc, 45, r, l, rpm, m, gas, sg)["T"]
    T0 = closed_forms(idc, 45, r, l, rpm, 0, gas, sg)["T"]
    text = (HERE / "force_engine_double_acting.toml").read_text(encoding="utf-8")
    text = text[: text.index("[answers]")]
    for given, ok, slip in ((T, True, None), (T0, False, "piston_inertia_left_out")):
        sol = solve(parse_scene(f'{text}[answers]\nturning_moment = "{float(given):.6g} N m"\n'))
        (v,) = check_answers(sol)
        assert v.ok is ok and v.mistake == slip, v
        assert abs(v.correct - T) <= REL * T


def test_a_static_problem_per_student_says_it_is_static(tmp_path, capsys):
    """variants of a static force analysis: each problem says the masses are neglected and
    asks for the force polygons (it asked for the velocity and acceleration polygons); the
    key's pin forces are each variant's statics (its rod a two-force member: the pins B
    and C carry one force, and A's is B's)."""
    import csv

    from polygon_method.cli import main

    root = Path(__file__).resolve().parent.parent / "worked_problems"
    scene = tmp_path / "static.toml"
    scene.write_text(
        (root / "static_fourbar_pin_forces.toml").read_text(encoding="utf-8")
        + "\n[variants]\nangle = { from = 40, to = 80, step = 5 }\n",
        encoding="utf-8",
    )
    assert (
        main(["variants", str(scene), "--count", "3", "--seed", "2", "-o", str(tmp_path / "v")])
        == 0
    )
    capsys.readouterr()
    sheet = (tmp_path / "v" / "problem-sheet.md").read_text(encoding="utf-8")
    assert sheet.count("The links' masses are neglected: a static force analysis.") == 3
    assert sheet.count("Find, by the force polygons (a static force analysis):") == 3
    assert "velocity and acceleration polygons" not in sheet
    rows = list(csv.DictReader((tmp_path / "v" / "answer-key.csv").open(encoding="utf-8")))
    assert len(rows) == 3
    for row in rows:  # by hand: C above AD, BC a two-force member, moments of DC about D
        t = math.radians(float(row["angle"].split()[0]))
        B, D = (200 * math.cos(t), 200 * math.sin(t)), (500.0, 0.0)
        d = math.dist(B, D)
        a = (d * d + 600**2 - 400**2) / (2 * d)  # from B along BD to the chord
        h = math.sqrt(600**2 - a * a)
        ex, ey = (D[0] - B[0]) / d, (D[1] - B[1]) / d
        C = max(
            ((B[0] + a * ex - s * h * ey, B[1] + a * ey + s * h * ex) for s in (1, -1)),
            key=lambda c: c[1],
        )
        u = ((C[0] - B[0]) / 600, (C[1] - B[1]) / 600)
        E = (D[0] + 250 * (C[0] - D[0]) / 400, D[1] + 250 * (C[1] - D[1]) / 400)
        P = (100 * math.cos(math.radians(150)), 100 * math.sin(math.radians(150)))
        m = ((E[0] - D[0]) * P[1] - (E[1] - D[1]) * P[0]) / 1000
        F = -m / (((C[0] - D[0]) * u[1] - (C[1] - D[1]) * u[0]) / 1000)
        # F u on DC at C, so -F u on AB at B: the driver's torque balances its moment about A
        T = F * (B[0] * u[1] - B[1] * u[0]) / 1000
        for k in ("F_A (N)", "F_B (N)", "F_C (N)"):
            assert float(row[k]) == pytest.approx(abs(F), rel=1e-9)
        assert float(row["torque (N m)"]) == pytest.approx(T, rel=1e-9)


#: a corpus problem kept here, not in tests/textbook (the corpus's generic force tests,
#: tests/test_force_sweep.py's among them, are written for frictionless scenes)
FRICTION = """# Of the kind of Ghosh & Mallik, "Static force analysis with friction": the slider crank
# of force_static_slider_crank.toml with Coulomb friction at the guide, mu = 0.1 (the pins
# frictionless); own numbers. Crank OA = 150 mm, rod AB = 600 mm, the crank at 45 deg
# turning ccw (the slider moving towards O); 2 kN pushes the slider towards O. Find the
# thrust in the rod, the guide's normal reaction and the torque on the crank.
#
# Answers worked by hand here (not read from the tool), to four figures: the slider moves
# towards O, the friction mu N on it away from O; with the rod's thrust C at phi to the
# line of stroke (sin phi = r sin 45 / l), N = C sin phi and C (cos phi + mu sin phi) =
# 2000: C = 1996 N, N = 352.9 N; T = C r sin(45 deg + phi) = 245.8 N m (cw: the load
# drives, the crank is held back), 4.4 N m less than without friction.
source = "Ghosh-Mallik-style statics with friction, own numbers; answers by hand"
title = "Slider crank held against a force on the piston, with friction at the guide"
units = "mm"

[ground]
O = [0, 0]

[links]
OA = 150
AB = 600

[sliders]
B = { path = "horizontal", through = "O" }

[input]
crank = "OA"
angle = 45
speed = "1 rad/s ccw"

[friction]
guides = 0.1

[masses]

[loads]
B = { force = "2 kN", direction = 180 }

[answers]
tolerance = "1%"
F_B = "1996 N"
N_B = "352.9 N"
torque = "245.8 N m cw"
"""


def test_static_slider_crank_with_friction_at_the_guide_by_hand():
    """The slider moves towards O (the crank ccw at 45 deg), the friction mu N on it away
    from O: N = C sin phi, C (cos phi + mu sin phi) = F, T = C r sin(45 deg + phi); and the
    answers the problem gives."""
    from polygon_method import parse_scene

    sol = solve(parse_scene(FRICTION))
    assert all(v.ok for v in check_answers(sol))
    mpmath.mp.dps = 30
    r, l, F, mu, t = mpf("0.15"), mpf("0.6"), mpf(2000), mpf("0.1"), mpmath.pi / 4
    phi = mpmath.asin(r * mpmath.sin(t) / l)
    C = F / (mpmath.cos(phi) + mu * mpmath.sin(phi))
    (pin,) = [p for p in sol.forces.pins if p.point == "B"]
    (gd,) = sol.forces.guides
    assert abs(mpmath.hypot(*pin.force) - C) <= REL * F
    assert abs(abs(gd.normal) - C * mpmath.sin(phi)) <= REL * F
    assert abs(sol.forces.input_torque + C * r * mpmath.sin(t + phi)) <= REL * F * r
