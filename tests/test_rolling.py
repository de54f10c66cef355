"""Rolling without slip ([rolling]): closed forms of the textbook, finite differences of
positions in time, the array road against the one-instant road, bad input and the speed of
the step. The 50-digit reference takes the rolling scenes of tests/textbook
(tests/test_textbook.py)."""

import math
import subprocess
import sys
from pathlib import Path

import mpmath
import numpy as np
import pytest

from polygon_method import load_scene, parse_scene, solve
from polygon_method.solver.compiler import compile_plan
from polygon_method.common.errors import PolygonMethodError
from polygon_method.solver.kinematics import evaluate
from polygon_method.steps import Context

HERE = Path(__file__).resolve().parent
ROLLING = sorted((HERE / "textbook").glob("rolling_*.toml")) + sorted(
    (HERE.parent / "worked_problems").glob("*rolling*.toml")
)

PLANET = """
[ground]
O = [0, 0]
[links]
OA = {arm}
AP = {rp}
[rolling]
AP = {{ on = "O"{inside} }}
[input]
crank = "OA"
angle = 35
speed = "{w} rad/s ccw"
acceleration = "{al} rad/s^2 ccw"
"""


@pytest.mark.parametrize(
    "arm,rp,inside", [(100, 40, False), (80, 40, True), (70, 20, False), (50, 75, True)]
)
def test_planet_on_a_fixed_sun_or_ring_turns_at_the_gear_ratio(arm, rp, inside):
    """Outside a fixed sun of radius rs = arm - rp: omega_p = (1 + rs / rp) omega_arm; inside a
    fixed ring of radius R = arm + rp: omega_p = (1 - R / rp) omega_arm (the other way)."""
    w, al = 7.5, 3.0
    sol = solve(
        parse_scene(
            PLANET.format(arm=arm, rp=rp, w=w, al=al, inside=", inside = true" if inside else "")
        )
    )
    ratio = 1 - (arm + rp) / rp if inside else 1 + (arm - rp) / rp
    assert sol.W["AP"] == pytest.approx(ratio * w, rel=1e-12)
    assert sol.Al["AP"] == pytest.approx(ratio * al, rel=1e-12)
    assert math.hypot(*sol.V["P"]) < 1e-12  # P starts at the contact: at rest


def test_gear_pair_ratio_and_the_point_at_the_pitch_point():
    """omega_2 = -(r1 / r2) omega_1; the pitch point of gear 2 moves as gear 1's."""
    sc = parse_scene("""
[ground]
O1 = [0, 0]
O2 = [90, 0]
[links]
"O1-A" = 36
"O2-B" = 54
[rolling]
"O2-B" = { on = "O1-A" }
[input]
crank = "O1-A"
angle = 0
speed = "40 rad/s cw"
acceleration = "10 rad/s^2 ccw"
""")
    sol = solve(sc)
    assert sol.W["O2-B"] == pytest.approx(40 * 36 / 54, rel=1e-12)
    assert sol.Al["O2-B"] == pytest.approx(-10 * 36 / 54, rel=1e-12)
    assert sol.V["B"] == pytest.approx(sol.V["A"], abs=1e-12)  # B at the pitch point
    # the tangential components match; the centripetal ones do not (a_B != a_A)
    assert sol.A["B"][1] == pytest.approx(sol.A["A"][1], abs=1e-12)
    assert sol.A["B"][0] != pytest.approx(sol.A["A"][0], abs=1e-3)


def test_wheel_on_the_ground_top_point_and_contact():
    """A wheel rolling on level ground: omega = -v_C / r, the top point moves at 2 v_C, and
    the contact point's acceleration is omega^2 r straight up (not zero)."""
    sc = load_scene(HERE / "textbook" / "rolling_wheel_on_ground.toml")
    sc2 = parse_scene(
        (HERE / "textbook" / "rolling_wheel_on_ground.toml")
        .read_text()
        .replace("angle = 60 }", "angle = 90 }")
    )
    for s in (sc, sc2):
        sol = solve(s)
        r = 0.05
        vc, ac = sol.V["C"], sol.A["C"]
        assert vc[1] == pytest.approx(0, abs=1e-12) and ac[1] == pytest.approx(0, abs=1e-12)
        assert sol.W["CP"] == pytest.approx(-vc[0] / r, rel=1e-12)
        assert sol.Al["CP"] == pytest.approx(-ac[0] / r, rel=1e-12)
        st = next(st for st in sol.plan.steps if st.contact_motion(sol) is not None)
        I, vI, aI = st.contact_motion(sol)
        assert I[1] == pytest.approx(0, abs=1e-15)
        assert math.hypot(*vI) < 1e-12
        assert aI[0] == pytest.approx(0, abs=1e-10)
        assert aI[1] == pytest.approx(sol.W["CP"] ** 2 * r, rel=1e-12)
    sol = solve(sc2)  # P at the top of the wheel
    assert sol.V["P"][0] == pytest.approx(2 * sol.V["C"][0], rel=1e-12)
    assert sol.value("aI", ("C", "P")) == pytest.approx(sol.W["CP"] ** 2 * 0.05, rel=1e-12)


def _theta_series(scene, h):
    inp = scene.input
    t = np.array([-2 * h, -h, 0.0, h, 2 * h])
    return inp.angle + inp.omega * t + inp.alpha * t * t / 2


@pytest.mark.parametrize("path", ROLLING, ids=lambda p: p.stem)
def test_velocities_and_accelerations_are_the_time_derivatives_of_positions(path):
    """Central differences (fourth order) of the positions over five instants."""
    scene = load_scene(path)
    sol = solve(scene)
    plan = compile_plan(scene)
    h = 1e-3 / abs(scene.input.omega)
    th = _theta_series(scene, h)
    m = evaluate(plan, theta=th, array=True, upto=0)
    assert m.bad is None or not np.any(m.bad)
    vmax = max(math.hypot(*v) for v in sol.V.values())
    amax = max(math.hypot(*a) for a in sol.A.values())
    for X in scene.point_names:
        for k in (0, 1):
            x = np.broadcast_to(np.asarray(m.P[X][k], dtype=float), (5,))
            v = (x[0] - 8 * x[1] + 8 * x[3] - x[4]) / (12 * h)
            a = (-x[0] + 16 * x[1] - 30 * x[2] + 16 * x[3] - x[4]) / (12 * h * h)
            assert abs(v - sol.V[X][k]) <= 1e-7 * vmax, (X, k, v, sol.V[X][k])
            assert abs(a - sol.A[X][k]) <= 1e-5 * amax, (X, k, a, sol.A[X][k])


@pytest.mark.parametrize("path", ROLLING, ids=lambda p: p.stem)
def test_array_road_is_the_one_instant_road(path):
    """The phases on arrays of crank angles give what one instant gives at each angle."""
    scene = load_scene(path)
    plan = compile_plan(scene)
    th = scene.input.angle + np.array([-0.4, 0.0, 0.3, 1.1])
    m = evaluate(plan, theta=th, array=True)
    for j, t in enumerate(th):
        one = plan.instant(Context(float(t), scene.input.omega, scene.input.alpha))
        for X in scene.point_names:
            for D, Dm in ((one.P, m.P), (one.V, m.V), (one.A, m.A)):
                got = np.broadcast_to(np.asarray(Dm[X][0], dtype=float), th.shape)[j]
                assert got == pytest.approx(D[X][0], rel=1e-12, abs=1e-12)
        for lk in one.W:
            assert np.broadcast_to(m.W[lk], th.shape)[j] == pytest.approx(
                one.W[lk], rel=1e-12, abs=1e-12
            )


def test_gear_train_turns_through_the_ratio_over_a_turn():
    """Not periodic in the crank: after one turn of gear 1 (r1 = 4) gear 3 (chain 4 -> 6 ->
    8) has turned 4/8 of a turn, the same way as gear 1."""
    scene = load_scene(HERE / "textbook" / "rolling_gear_train.toml")
    plan = compile_plan(scene)
    th0 = scene.input.angle
    m = evaluate(plan, theta=np.array([th0, th0 + 2 * math.pi]), array=True, upto=0)
    (cx, cy) = scene.ground["O3"]
    a0, a1 = (math.atan2(m.P["C"][1][j] - cy, m.P["C"][0][j] - cx) for j in (0, 1))
    assert (a1 - a0) % (2 * math.pi) == pytest.approx(math.pi, abs=1e-9)


def _run(text, tmp_path):
    f = tmp_path / "s.toml"
    f.write_text(text)
    return subprocess.run(
        [sys.executable, "-m", "polygon_method", "solve", str(f)],
        capture_output=True,
        text=True,
        env={"PYTHONPATH": str(HERE.parent), "PATH": ""},
    )


BASE = """[ground]
O = [0, 100]
G = [0, 0]
[links]
OA = 60
AC = 200
CP = 50
[rolling]
CP = {spec}
[input]
crank = "OA"
angle = 45
speed = "20 rad/s cw"
"""


@pytest.mark.parametrize(
    "spec,words",
    [
        ('{ through = "G" }', "no ground line or circle"),
        ('{ on = "horizontal" }', "needs a point: through"),
        ('{ on = "horizontal", through = "X" }', "not a ground point"),
        ('{ on = "horizontal", through = "G", radus = 5 }', "unknown key 'radus'"),
        ('{ on = "horizontal", through = "G", side = "left" }', "horizontal line has an above"),
        ('{ on = "CA" }', "have one centre"),  # a gear on a moving link: centred at C
        ('"horizontal"', "a rolling wheel is a table"),
    ],
)
def test_bad_rolling_input_gets_one_clear_line(spec, words, tmp_path):
    out = _run(BASE.format(spec=spec), tmp_path)
    assert out.returncode == 2, out.stderr
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and words in lines[0], out.stderr
    assert "[rolling] CP" in lines[0] and "line 9" in lines[0] and "s.toml" in lines[0]


def test_gears_whose_centre_distance_is_not_the_sum_of_the_radii_are_refused(tmp_path):
    text = PLANET.format(arm=100, rp=40, w=1, al=0, inside="").replace(
        'on = "O"', 'on = "O", on_radius = 55'
    )
    out = _run(text, tmp_path)
    assert out.returncode == 2
    assert "contact leaves the pitch point" in out.stderr and "R + r = 95 mm" in out.stderr
    assert len(out.stderr.strip().splitlines()) == 1
    too_small = PLANET.format(arm=30, rp=40, w=1, al=0, inside="")
    out = _run(too_small, tmp_path)
    assert out.returncode == 2 and "inside = true?" in out.stderr


def test_a_wheel_whose_centre_leaves_its_line_is_refused():
    """A wheel carried by the crank itself is at its radius from the line at the stated angle
    only: elsewhere the step says the contact leaves the pitch point (scalar mode) and masks
    those angles (array mode)."""
    sc = parse_scene("""[ground]
O = [0, 0]
[links]
OC = 50
CP = 50
[rolling]
CP = { on = "horizontal", through = "O" }
[input]
crank = "OC"
angle = 90
speed = "10 rad/s ccw"
""")
    sol = solve(sc)  # at the stated angle C is at its radius from the line
    assert sol.W["CP"] == pytest.approx(-sol.V["C"][0] / 0.05, rel=1e-12)
    plan = compile_plan(sc)
    with pytest.raises(PolygonMethodError, match="off its line"):
        plan.instant(Context(sc.input.angle + 0.3, sc.input.omega, 0.0))
    m = evaluate(plan, theta=sc.input.angle + np.array([0.0, 0.3]), array=True, upto=0)
    assert list(m.bad) == [False, True]


def test_check_keys_and_the_contact_at_rest_slip():
    """aI_CP is omega^2 r (the 50-digit-free closed form); an answer of 0 for it, and a_P
    found as if the contact point were at rest (|a_P - a_I|), are diagnosed as that slip."""
    from polygon_method.check import check_answers
    from polygon_method.scene import parse_answers

    path = HERE.parent / "worked_problems" / "rolling_wheel_rod_slider.toml"
    sc = load_scene(path)
    sol = solve(sc)
    I, vI, aI = next(
        st.contact_motion(sol) for st in sol.plan.steps if st.contact_motion(sol) is not None
    )
    at_rest = math.hypot(sol.A["P"][0] - aI[0], sol.A["P"][1] - aI[1])
    _, answers = parse_answers(
        f'[answers]\naI_CP = 0\nvI_CP = 0\na_P = "{at_rest:.4f} m/s^2"\n'
        f'omega_CP = "{abs(sol.W["CP"]):.4f} rad/s cw"\n',
        sc,
    )
    v = {x.key: x for x in check_answers(sol, answers)}
    assert v["aI_CP"].correct == pytest.approx(sol.W["CP"] ** 2 * 0.05, rel=1e-12)
    assert not v["aI_CP"].ok and v["aI_CP"].mistake == "contact_acceleration_zero"
    assert v["vI_CP"].ok  # no slip: at rest
    assert not v["a_P"].ok and v["a_P"].mistake == "contact_acceleration_zero"
    assert v["omega_CP"].ok
    with pytest.raises(PolygonMethodError, match="no wheel of \\[rolling\\]"):
        parse_answers("[answers]\naI_AC = 1\n", sc)


def test_random_planets_and_gear_pairs_against_the_gear_ratio_and_time_derivatives():
    """Random dimensions (seeded): a planet on a fixed sun or in a fixed ring, the arm the
    crank, with its point at a random angle; the gear ratio and the time derivatives of the
    point's position."""
    rng = np.random.default_rng(20)
    for _ in range(30):
        inside = bool(rng.integers(2))
        rp = float(rng.uniform(10, 60))
        arm = float(rng.uniform(rp + 5, 150)) if not inside else float(rng.uniform(5, 150))
        w = float(rng.uniform(1, 30)) * (1 if rng.integers(2) else -1)
        al = float(rng.uniform(0, 50))
        sc = parse_scene(f"""[ground]
O = [0, 0]
[links]
OA = {arm}
AP = {rp * float(rng.uniform(0.3, 1.5))}
[rolling]
AP = {{ on = "O", radius = {rp}{", inside = true" if inside else ""}, angle = {float(rng.uniform(0, 360))} }}
[input]
crank = "OA"
angle = {float(rng.uniform(0, 360))}
speed = "{abs(w)} rad/s {"ccw" if w > 0 else "cw"}"
acceleration = "{al} rad/s^2 ccw"
""")
        sol = solve(sc)
        R = (arm + rp) / rp if inside else (arm - rp) / rp
        ratio = 1 - R if inside else 1 + R
        assert sol.W["AP"] == pytest.approx(ratio * w, rel=1e-11)
        assert sol.Al["AP"] == pytest.approx(ratio * al, rel=1e-11)
        h = 1e-3 / abs(w)
        th = _theta_series(sc, h)
        m = evaluate(compile_plan(sc), theta=th, array=True, upto=0)
        for k in (0, 1):
            x = np.asarray(m.P["P"][k], dtype=float)
            v = (x[0] - 8 * x[1] + 8 * x[3] - x[4]) / (12 * h)
            a = (-x[0] + 16 * x[1] - 30 * x[2] + 16 * x[3] - x[4]) / (12 * h * h)
            vmax, amax = math.hypot(*sol.V["P"]) + 1e-3, math.hypot(*sol.A["P"]) + 1e-3
            assert abs(v - sol.V["P"][k]) <= 1e-7 * vmax
            assert abs(a - sol.A["P"][k]) <= 1e-5 * amax


def test_a_centre_off_its_line_at_the_stated_angle_is_the_scenes_error(tmp_path):
    out = _run(
        """[ground]
O = [0, 0]
[links]
OC = 50
CP = 40
[rolling]
CP = { on = "horizontal", through = "O" }
[input]
crank = "OC"
angle = 90
speed = "10 rad/s ccw"
""",
        tmp_path,
    )
    assert out.returncode == 2
    line = out.stderr.strip()
    assert "\n" not in line and "[rolling] CP (line 7)" in line
    assert "is 50 mm from the horizontal line, not its radius 40 mm" in line


def test_a_pinion_between_two_racks_drives_them_opposite_ways():
    """vs = -(signed distance of the pitch line from O) omega: the rack below the pinion
    moves with the pinion's lowest point, the one above the other way; as likewise."""
    sc = load_scene(HERE / "textbook" / "rolling_pinion_two_racks.toml")
    sol = solve(sc)
    w, al = sc.input.omega, sc.input.alpha
    assert sol.S["R1"][0] == pytest.approx(0.04 * w, rel=1e-12)
    assert sol.S["R2"][0] == pytest.approx(-0.04 * w, rel=1e-12)
    assert sol.S["R1"][1] == pytest.approx(0.04 * al, rel=1e-12)
    assert sol.V["R1"][1] == 0.0 and sol.A["R2"][1] == 0.0


@pytest.mark.parametrize(
    "sliders,rolling,words",
    [
        ('R = { path = "horizontal" }', 'R = { on = "OA" }', "needs its place: through"),
        ("", 'R = { on = "OA" }', "a rack is a block on a fixed path"),
        (
            'R = { path = "horizontal", through = [0, -40] }',
            'R = { on = "OA", radius = 4 }',
            "unknown key 'radius' for a rack",
        ),
        (
            'R = { path = "horizontal", through = [0, -40] }',
            'R = { on = "OA", on_radius = 30 }',
            "the contact leaves the pitch point",
        ),
    ],
)
def test_bad_racks_get_one_clear_line(sliders, rolling, words, tmp_path):
    out = _run(
        f"""[ground]
O = [0, 0]
[links]
OA = 40
RS = 100
[sliders]
{sliders}
S = {{ path = "vertical", through = [90, 0] }}
[rolling]
{rolling}
[input]
crank = "OA"
angle = 30
speed = "10 rad/s ccw"
""",
        tmp_path,
    )
    assert out.returncode == 2, out.stderr
    assert len(out.stderr.strip().splitlines()) == 1 and words in out.stderr, out.stderr
    assert "[rolling] R" in out.stderr


def _planet_slider_range():
    """The slider Q of the planet on a fixed sun (tests/textbook), by hand over the two
    turns of the arm centred on the scene's instant: A = 100 (cos t, sin t) mm, the spoke
    AP = 30 at phi = 90 deg + (1 + 60/40)(t - 30 deg) (no slip on the sun), Q on the x axis
    150 from P (to the right). Its least and largest place: the interior stationary points
    (mpmath, 30 digits) and the two ends. The planet turns 2.5 times a turn: the motion
    repeats only every 2 turns, its whole period."""
    with mpmath.workdps(30):  # (the 50-digit reference's precision left as it is)
        return _planet_range_at_working_precision()


def _planet_range_at_working_precision():
    t0 = mpmath.radians(30)

    def q(t):
        ax, ay = 100 * mpmath.cos(t), 100 * mpmath.sin(t)
        phi = mpmath.pi / 2 + mpmath.mpf(5) / 2 * (t - t0)
        px, py = ax + 30 * mpmath.cos(phi), ay + 30 * mpmath.sin(phi)
        return (px + mpmath.sqrt(150**2 - py**2)) / 1000

    lo, hi = t0 - 2 * mpmath.pi, t0 + 2 * mpmath.pi
    vals = [q(lo), q(hi)]  # the period's two ends (the same place)
    n = 1440
    grid = [lo + (hi - lo) * k / n for k in range(n + 1)]
    for a, b, c in zip(grid, grid[1:], grid[2:]):
        qa, qb, qc = q(a), q(b), q(c)
        if (qb - qa) * (qc - qb) <= 0:  # a stationary point between a and c
            t = mpmath.findroot(lambda t: mpmath.diff(q, t), b)
            vals.append(q(t))
    return float(min(vals)), float(max(vals))


def test_sweep_and_linkage_agree_on_a_planets_slider_range():
    """A planet on a fixed sun turns 2.5 times per turn of its arm: after a turn of the
    crank the mechanism is not where it started, after two it is. The sweep took its
    angles on one turn (0 to 360 deg) and linkage on another (centred on the scene's
    instant), and their slider strokes disagreed; both now take the whole period, the two
    turns centred on the scene's instant, say so, and agree with the range by hand over
    it."""
    from polygon_method.linkage import analyse
    from polygon_method.linkage.summary import summarize

    scene = load_scene(HERE / "textbook" / "rolling_planet_fixed_sun.toml")
    lo, hi = _planet_slider_range()
    lk = analyse(scene)
    s = summarize(scene).extreme("s_Q")
    for got_lo, got_hi in ((lk.output_min, lk.output_max), (s.minimum, s.maximum)):
        assert math.isclose(got_lo, lo, rel_tol=1e-9), (got_lo, lo)
        assert math.isclose(got_hi, hi, rel_tol=1e-9), (got_hi, hi)
    words = "the motion repeats every 2 turns"
    assert words in lk.text() and words in summarize(scene).text()
    assert summarize(scene).requested == 720  # every degree of the two turns


def test_default_space_scale_fits_the_pitch_circles():
    """A planet (radius 50) on an arm of 150 about a fixed sun (radius 100): the sun's and
    the planet's pitch circles span x from -100 to 200 (300 mm), wider than the joints
    (O to C, 150 mm). The configuration's default scale fits that span in 15 cm, so the
    drawing fits A4 without --scale (it was chosen for the joints alone: 1 cm = 10 mm,
    30 cm of sun)."""
    from polygon_method.polygons.scales import SPACE_FIT_CM, diagram_scales

    sol = solve(
        parse_scene(
            PLANET.format(arm=150, rp=50, inside="", w=10, al=0).replace("angle = 35", "angle = 0")
        )
    )
    space = diagram_scales(sol)[0]
    span_mm = 300.0  # by hand: the sun's left edge (-100) to the planet's right (150 + 50)
    assert span_mm / (space.per_cm * 1000.0) <= SPACE_FIT_CM
    assert span_mm / 10.0 > SPACE_FIT_CM  # the joints' scale (1 cm = 10 mm) would not fit
