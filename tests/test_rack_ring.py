"""A rack whose pinion a linkage turns (keyed to the rocker of a four-bar), and a ring gear
driven by the gear inside it (the output of an epicyclic train, or an internal pair on
fixed centres).

The references are independent of the tool's formulas: the four-bar by the algebraic
method in 50-digit arithmetic (tests/reference.py, ``reference_fourbar_algebraic``), the
rack then moving as the pinion's pitch point (v = R_p omega_4, a = R_p alpha_4 along the
path); the tabular method of epicyclic trains for the ring (arm fixed, then all locked);
finite differences in the crank angle of the positions the tool's array road gives. The
50-digit constraint solve takes the corpus scenes (tests/textbook/rolling_rack_on_rocker,
rolling_ring_output: tests/test_textbook.py)."""

import math
from pathlib import Path

import numpy as np
import pytest

from polygon_method import load_scene, parse_scene, solve
from polygon_method.common.errors import PolygonMethodError
from polygon_method.solver.compiler import compile_plan
from polygon_method.solver.kinematics import evaluate
from polygon_method.steps import Context
from reference import reference_fourbar_algebraic

HERE = Path(__file__).resolve().parent
TEXTBOOK = HERE / "textbook"
WORKED = HERE.parent / "worked_problems"

RACK = """
units = "mm"
[ground]
A = [0, 0]
D = [{d}, 0]
[links]
AB = {a}
BC = {b}
CD = {c}
[sliders]
R = {{ path = "horizontal", through = [{tx}, {ty}] }}
[rolling]
R = {{ on = "DC" }}
[assembly]
C = "above"
[input]
crank = "AB"
angle = {th}
speed = "{w}"
acceleration = "{al}"
"""

# (a, b, c, d, crank angle deg, omega, alpha, the rack's height below D): crank-rockers
RACKS = [
    (40, 120, 80, 140, 50, 20.0, -40.0, -50.0),
    (30, 100, 70, 110, 200, -7.0, 3.0, -25.0),
    (25, 90, 60, 95, 300, 12.0, 0.0, 35.0),
    (50, 150, 100, 160, 120, 4.0, 9.0, -80.0),
]


@pytest.mark.parametrize("a,b,c,d,th,w,al,h", RACKS)
def test_rack_on_a_rocker_moves_as_the_pinions_pitch_point(a, b, c, d, th, w, al, h):
    """The rack's sliding velocity and acceleration are the rocker's omega and alpha (the
    four-bar by the algebraic method, 50 digits) times the pitch radius, signed: the pitch
    point at (d, h) moves at omega_4 perp(I - D), along the path."""
    sc = parse_scene(
        RACK.format(
            a=a,
            b=b,
            c=c,
            d=d,
            th=th,
            w=_sensed(w, "rad/s"),
            al=_sensed(al, "rad/s^2"),
            tx=d + 7,
            ty=h,
        )
    )
    sol = solve(sc)
    ref = reference_fourbar_algebraic(
        a * 1e-3, b * 1e-3, c * 1e-3, d * 1e-3, math.radians(th), w, al, +1
    )
    w4, a4 = float(ref["omega4"]), float(ref["alpha4"])
    Rp = -h * 1e-3  # I - D = (0, h): v_I = w4 (-h, 0)
    assert sol.W["CD"] == pytest.approx(w4, rel=1e-9)
    assert sol.S["R"][0] == pytest.approx(w4 * Rp, rel=1e-9, abs=1e-12)
    assert sol.S["R"][1] == pytest.approx(a4 * Rp, rel=1e-9, abs=1e-12)


def _sensed(v, unit):
    return f"{abs(v)} {unit}" + (" ccw" if v > 0 else " cw" if v < 0 else "")


def _fd(plan, th0, name, h=1e-3):
    """(d/dtheta, d2/dtheta2) of point ``name`` at th0 by five-point differences of the
    array road's positions."""
    th = th0 + h * np.array([-2.0, -1.0, 0.0, 1.0, 2.0])
    m = evaluate(plan, theta=th, array=True, upto=0)
    x, y = (np.broadcast_to(np.asarray(c, dtype=float), th.shape) for c in m.P[name])
    d1 = [(c[0] - 8 * c[1] + 8 * c[3] - c[4]) / (12 * h) for c in (x, y)]
    d2 = [(-c[0] + 16 * c[1] - 30 * c[2] + 16 * c[3] - c[4]) / (12 * h * h) for c in (x, y)]
    return d1, d2


@pytest.mark.parametrize(
    "name", ["rolling_rack_on_rocker", "rolling_ring_output", "rolling_ring_on_rocker"]
)
@pytest.mark.parametrize("turn", [0.0, 0.4, -0.7, 1.5])
def test_positions_differentiated_give_the_velocity_and_acceleration(name, turn):
    """The rack's place followed from the rocker's turn, and the ring's angle from the
    planet's and the arm's, are the integrals of the no-slip relations: their positions
    differentiated in the crank angle (at 1 rad/s, uniform) are the polygons' velocities
    and accelerations."""
    sc = load_scene(TEXTBOOK / f"{name}.toml")
    plan = compile_plan(sc)
    th = sc.input.angle + turn
    ctx = Context(np.array([th]), 1.0, 0.0, array=True)
    m = plan.run(ctx)
    assert ctx.bad is None or not ctx.bad.any()
    checked = 0
    for p in ("R", "Q", "S"):
        if p not in m.P:
            continue
        d1, d2 = _fd(plan, th, p)
        v = [float(np.ravel(c)[0]) for c in m.V[p]]
        a = [float(np.ravel(c)[0]) for c in m.A[p]]
        assert math.hypot(d1[0] - v[0], d1[1] - v[1]) <= 1e-8 * (math.hypot(*v) + 1e-3), p
        assert math.hypot(d2[0] - a[0], d2[1] - a[1]) <= 1e-6 * (math.hypot(*a) + 1e-3), p
        checked += 1
    assert checked >= 1


RING = """
units = "mm"
[ground]
O = [0, 0]
[links]
OA = {arm}
AP = {rp}
"O-Q" = {rr}
[rolling]
AP = {{ on = "O", on_radius = {rs} }}
"O-Q" = {{ on = "AP", ring = true }}
[input]
crank = "OA"
angle = {th}
speed = "{w}"
acceleration = "{al}"
"""


def _ring_tabular(rs, rr, w_arm):
    """The book's table, sun fixed: (1) arm fixed, sun +1: planet -rs/rp, ring -rs/rr;
    (2) all locked +y. The sun at x + y = 0 with y = w_arm: the ring y - (rs/rr) x =
    w_arm (1 + rs/rr)."""
    x = -w_arm
    return w_arm - (rs / rr) * x


@pytest.mark.parametrize(
    "rs,rp,th,w,al",
    [
        (30, 30, 35, 8.0, -15.0),
        (60, 20, 170, -3.0, 2.0),
        (20, 45, 290, 11.0, 0.0),
        (45, 15, 0, 1.5, 7.0),
    ],
)
def test_ring_driven_by_a_planet_turns_by_the_tabular_method(rs, rp, th, w, al):
    """Arm input, sun fixed, the ring's speed found: omega_ring = (1 + T_s/T_r) omega_arm
    (and the same for alpha); the ring's point at the pitch point moves as the planet's."""
    rr = rs + 2 * rp
    sol = solve(
        parse_scene(
            RING.format(
                arm=rs + rp,
                rp=rp,
                rr=rr,
                rs=rs,
                th=th,
                w=_sensed(w, "rad/s"),
                al=_sensed(al, "rad/s^2"),
            )
        )
    )
    assert sol.W["O-Q"] == pytest.approx(_ring_tabular(rs, rr, w), rel=1e-12)
    assert sol.Al["O-Q"] == pytest.approx(_ring_tabular(rs, rr, al), rel=1e-12, abs=1e-12)
    st = next(s for s in sol.plan.steps if s.kind == "rolling" and s.wheel == "O-Q")
    I, vI, _ = st.contact_motion(sol)
    assert math.hypot(*I) == pytest.approx(rr * 1e-3, rel=1e-12)  # on the ring's pitch circle
    (ax, ay), wp = sol.P["A"], sol.W["AP"]
    vA = sol.V["A"]
    v_planet = (vA[0] - wp * (I[1] - ay), vA[1] + wp * (I[0] - ax))
    assert math.dist(vI, v_planet) <= 1e-12 * (abs(w) + 1) * rr


def test_ring_gear_over_a_sweep_turns_by_the_tabular_method():
    """Over two turns of the arm the ring's angle from the stated instant is (1 + rs/rr)
    times the arm's (its points unwrapped)."""
    sc = parse_scene(
        RING.format(arm=60, rp=30, rr=90, rs=30, th=35, w="8 rad/s ccw", al="0 rad/s^2")
    )
    plan = compile_plan(sc)
    dth = np.linspace(0.0, 4 * math.pi, 401)
    m = evaluate(plan, theta=sc.input.angle + dth, array=True, upto=0)
    qx, qy = m.P["Q"]
    phi = np.unwrap(np.arctan2(qy, qx))
    assert np.allclose(phi - phi[0], (1 + 30 / 90) * dth, rtol=0, atol=1e-12)


def test_internal_pair_on_fixed_centres_turns_the_ring_the_same_way():
    """A pinion about B inside a ring about O (fixed centres): omega_ring = (r_p / r_r)
    omega_p, the same sense."""
    text = """
units = "mm"
[ground]
O = [0, 0]
B = [30, 0]
[links]
"B-A" = 40
"O-Q" = 70
[rolling]
"O-Q" = { on = "B-A", ring = true, angle = 90 }
[input]
crank = "B-A"
angle = 0
speed = "10 rad/s ccw"
acceleration = "4 rad/s^2 cw"
"""
    sol = solve(parse_scene(text))
    assert sol.W["O-Q"] == pytest.approx(10 * 40 / 70, rel=1e-13)
    assert sol.Al["O-Q"] == pytest.approx(-4 * 40 / 70, rel=1e-13)
    assert sol.P["Q"] == pytest.approx((0.0, 0.07), abs=1e-15)


@pytest.mark.parametrize(
    "rolling,words",
    [
        ('"O-Q" = { on = "AP", ring = true, inside = true }', "says the opposite"),
        ('"O-Q" = { on = "O", ring = true }', "not with a fixed circle"),
        ('"O-Q" = { on = "AP", ring = "yes" }', "ring = true or false"),
        ('"O-Q" = { on = "AP", ring = true, on_radius = 35 }', "r - R"),
    ],
)
def test_bad_rings_get_one_clear_line(rolling, words):
    text = f"""
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 60
AP = 30
"O-Q" = 90
[rolling]
AP = {{ on = "O", on_radius = 30 }}
{rolling}
[input]
crank = "OA"
angle = 35
speed = "8 rad/s ccw"
"""
    with pytest.raises(PolygonMethodError) as exc:
        solve(parse_scene(text))
    msg = str(exc.value)
    assert words in msg and "\n" not in msg and "[rolling] O-Q" in msg, msg


def test_ring_whose_planet_is_not_its_pitch_radius_is_refused():
    """The planet of pitch radius 30 on an arm of 60 cannot mesh inside a ring of 100: the
    centre distance 60 is not r - R = 70."""
    text = RING.format(arm=60, rp=30, rr=100, rs=30, th=35, w="8 rad/s ccw", al="0 rad/s^2")
    with pytest.raises(PolygonMethodError) as exc:
        solve(parse_scene(text))
    assert "the contact leaves the pitch point" in str(exc.value)
    assert "r - R = 70 mm" in str(exc.value)


def test_rack_follows_its_rocker_only_half_a_turn_and_says_so():
    """A sweep stops where the pinion's turn from the stated instant could be a turn the
    other way; at one instant beyond, the refusal is one line naming the pinion."""
    sc = load_scene(TEXTBOOK / "rolling_rack_on_rocker.toml")
    st = next(s for s in compile_plan(sc).steps if s.kind == "rack")
    assert "half a turn" in st.limit_why()
    assert st.free == ("D", "C")


@pytest.mark.parametrize("name", ["rack_rocker_pinion", "ring_gear_output"])
def test_worked_problems_check_against_their_answers(name):
    """The worked problems' answers (computed independently: the 50-digit constraint solve
    and the closed forms) pass ``check`` at their tolerance."""
    from polygon_method.check import check_answers

    sc = load_scene(WORKED / f"{name}.toml")
    got = check_answers(solve(sc))
    assert len(got) >= 5 and all(v.ok for v in got), [v for v in got if not v.ok]


def _ring_slider_x(th, th0, psi0, w_ratio, r, ell, e):
    """The block S of the ring's rod by hand: the ring's point Q at psi = psi0 + K (theta -
    theta0) on its pitch circle r about O (the tabular method's K = 1 + T_s/T_r), S on the
    line y = e, ell from Q, to the right."""
    psi = psi0 + w_ratio * (th - th0)
    qx, qy = r * np.cos(psi), r * np.sin(psi)
    return qx + np.sqrt(ell * ell - (qy - e) ** 2)


def test_sweep_of_an_epicyclic_train_covers_its_whole_period():
    """The ring turns 4/3 times per turn of the arm: the mechanism is back after 3 turns.
    The default sweep takes every degree of the 3 turns, the summary says so, and the
    block's place at each of the 1080 angles is the one by hand (not a turn's values
    taken again: the places a turn apart differ)."""
    from polygon_method.linkage.summary import summarize
    from polygon_method.motion.sweeps import sweep

    sc = load_scene(TEXTBOOK / "rolling_ring_output.toml")
    res = sweep(sc)
    assert res.domain.turns == 3 and len(res.theta) == 1080
    x = np.asarray(res.P["S"][0], dtype=float)
    want = _ring_slider_x(
        np.asarray(res.theta), sc.input.angle, math.radians(120), 4 / 3, 0.09, 0.2, -0.04
    )
    assert np.max(np.abs(x - want)) <= 1e-12
    assert np.max(np.abs(x[:360] - x[360:720])) > 1e-3  # a turn apart: not the same
    summary = summarize(sc)
    assert "the motion repeats every 3 turns" in summary.text()
    assert summary.requested == 1080
    s = summary.extreme("s_S")
    dense = _ring_slider_x(np.linspace(0, 6 * math.pi, 200001), 0.0, 0.0, 4 / 3, 0.09, 0.2, -0.04)
    assert s.maximum == pytest.approx(dense.max(), rel=1e-9)
    assert s.minimum == pytest.approx(dense.min(), rel=1e-9)


def test_a_stated_range_over_several_turns_is_taken_as_stated():
    """Angles asked over three turns are taken on their own turns (the period is three),
    so the sweep's places are the ones by hand at each angle asked."""
    from polygon_method.motion.sweeps import sweep

    sc = load_scene(TEXTBOOK / "rolling_ring_output.toml")
    th = np.radians(np.arange(-400.0, 700.0, 7.0))
    res = sweep(sc, th)
    x = np.asarray(res.P["S"][0], dtype=float)
    want = _ring_slider_x(th, sc.input.angle, math.radians(120), 4 / 3, 0.09, 0.2, -0.04)
    assert len(res.theta) == len(th) and np.max(np.abs(x - want)) <= 1e-12


def test_a_driving_wheel_swept_over_three_turns_of_its_travel():
    """A wheel rolling on the ground as the driver, its travel three turns (2 pi r each):
    the sweep runs over all of it, and the block's place at every place of the centre is
    the one by hand (no slip: phi = phi0 - s / r; B on the ground, the rod's length from A)."""
    from polygon_method.motion.sweeps import sweep

    text = (WORKED / "rolling_wheel_driver.toml").read_text(encoding="utf-8")
    text = text.split("[answers]")[0].replace(
        'alpha_CA = "2 rad/s^2 ccw"', 'alpha_CA = "2 rad/s^2 ccw"\ntravel = [0, 5655]'
    )
    sc = parse_scene(text)
    res = sweep(sc)
    s = np.asarray(res.theta, dtype=float)
    assert s.min() == pytest.approx(0.0, abs=1e-12) and s.max() == pytest.approx(5.655)
    r, ell = 0.3, 1.2
    phi = math.radians(135) - s / r
    ax, ay = s + r * np.cos(phi), r + r * np.sin(phi)
    want = ax + np.sqrt(ell * ell - ay * ay)
    assert np.max(np.abs(np.asarray(res.P["B"][0], dtype=float) - want)) <= 1e-12
    assert any("end of its travel" in lp.why for lp in res.domain.limits)


VARIED = [
    (
        "rolling_wheel_rod_slider",
        WORKED,
        "\n[variants]\nOA = { from = 50, to = 70, step = 5 }\n"
        "angle = { from = 30, to = 60, step = 5 }\n",
    ),
    (
        "rack_rocker_pinion",
        WORKED,
        "\n[variants]\nAB = { from = 35, to = 45, step = 5 }\n"
        "angle = { from = 30, to = 90, step = 10 }\n",
    ),
    (
        "rolling_planet_on_rocker",
        TEXTBOOK,
        "\n[variants]\nAB = { from = 45, to = 55, step = 5 }\n"
        "angle = { from = 40, to = 80, step = 10 }\n",
    ),
    (
        "rolling_ring_on_rocker",
        TEXTBOOK,
        "\n[variants]\nAB = { from = 45, to = 55, step = 5 }\n"
        "angle = { from = 40, to = 80, step = 10 }\n",
    ),
    (
        "ring_gear_output",
        WORKED,
        "\n[variants]\nangle = { from = 0, to = 350, step = 10 }\n"
        'speed = ["60 rpm ccw", "90 rpm ccw", "120 rpm ccw"]\n',
    ),
]


@pytest.mark.parametrize("name,folder,table", VARIED, ids=[v[0] for v in VARIED])
def test_variants_of_rolling_scenes_each_match_the_reference(name, folder, table):
    """Variants of a wheel rolling on a line, a rack on a rocker's pinion, a planet on a
    rocker and an epicyclic train's ring: each variant's solution is its own scene's by
    the 50-digit constraint solve, and the screen's evaluation over all candidates at
    once (the wheel's place and the arm's angles read at each one's instant) gives the
    positions a plain solve gives."""
    from mpmath import mpf
    from polygon_method.variants import generate, screen
    from reference import reference_solution
    from textbook_corpus import REL, worst_error

    text = (folder / f"{name}.toml").read_text(encoding="utf-8").split("[answers]")[0] + table
    sc = parse_scene(text, file=f"{name}.toml")
    made = generate(sc, 4, seed=2)
    assert len(made.variants) == 4
    plan = compile_plan(sc)
    scenes = [v.scene for v in made.variants]
    ok, _ = screen(plan, scenes, 0.0)
    assert ok.all()
    from polygon_method.solver.kinematics import evaluate as ev
    from polygon_method.variants import _stack_dims

    m = ev(plan, dims=_stack_dims([plan.dimensions(s) for s in scenes]), array=True)
    for k, v in enumerate(made.variants):
        sol = solve(v.scene)
        ref = reference_solution(v.scene, sol.P)
        assert ref["residual"] < mpf("1e-40")
        err, what = worst_error(v.scene, sol, ref)
        assert err < REL, f"variant {v.id}: {what}: relative error {err:.2e}"
        for p in v.scene.point_names:
            got = [float(np.ravel(c)[k] if np.ndim(c) else c) for c in m.P[p]]
            assert math.dist(got, sol.P[p]) <= 1e-12, (v.id, p)


def test_a_ring_whose_contact_acceleration_is_taken_as_zero_is_diagnosed():
    """The ring's point at the pitch point has omega_ring^2 r_ring towards O (the arm
    steady); a student's 0 is named: the two gears' velocities are equal there, not their
    accelerations."""
    from polygon_method.check import check_answers

    text = (WORKED / "ring_gear_output.toml").read_text(encoding="utf-8").split("[answers]")[0]
    sc = parse_scene(text + '[answers]\n"aI_O-Q" = "0 m/s^2"\n')
    (v,) = check_answers(solve(sc))
    w = 120 * 2 * math.pi / 60 * (1 + 40 / 80)
    assert v.correct == pytest.approx(w * w * 0.08, rel=1e-12)
    assert not v.ok and v.mistake == "contact_acceleration_zero"
    assert "velocities equal at the pitch point" in v.diagnosis


def test_a_ring_on_a_rockers_planet_is_followed_over_the_whole_turn():
    """The planet on the rocker turns three times as far as the rocker: read from its own
    points its angle could not be followed past half a turn. The ring takes the planet's
    turn from its formula instead, so the sweep covers the crank's whole turn, and at each
    angle the ring turns (1 + R_s/r_ring) times the rocker (Willis, the sun fixed), from
    the stated instant."""
    from polygon_method.motion.sweeps import sweep

    sc = load_scene(TEXTBOOK / "rolling_ring_on_rocker.toml")
    res = sweep(sc)
    assert len(res.theta) == 360 and res.domain.full_turn
    (cx, cy), (qx, qy) = res.P["C"], res.P["Q"]
    rocker = np.unwrap(np.arctan2(np.asarray(cy), np.asarray(cx) - 0.12))
    ring = np.unwrap(np.arctan2(np.asarray(qy), np.asarray(qx) - 0.12))
    th = np.asarray(res.theta)
    k0 = int(np.argmin(np.abs(th - sc.input.angle)))
    # (1e-9 rad: next to the rod's change point the sweep takes its values from both sides)
    assert np.allclose(ring - ring[k0], 1.5 * (rocker - rocker[k0]), rtol=0, atol=1e-9)
