"""Gears and wheels beyond a planet on the crank: a planet on an arm that a linkage turns (a
rocker), a gear fixed to a moving link (Watt's sun and planet), a differential (the arm and
the sun both driven), a gear or wheel as what the motion is given on; and their refusals.

The references are independent of the tool's formulas: the tabular method of epicyclic
trains (arm fixed, then all locked: each input alone, then the sum), Willis' relation
written from the angles the scene's points make, and finite differences in the crank angle
of the positions the tool's array road gives (the wheel's angle followed from its arm and
its gear). The 50-digit constraint solve takes these scenes in tests/textbook
(rolling_planet_on_rocker, rolling_sun_and_planet, rolling_differential:
tests/test_textbook.py)."""

import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from polygon_method import load_scene, parse_scene, solve
from polygon_method.solver.compiler import compile_plan
from polygon_method.solver.kinematics import evaluate
from polygon_method.text.steptable import steps_text

HERE = Path(__file__).resolve().parent
TEXTBOOK = HERE / "textbook"
WORKED = HERE.parent / "worked_problems"

DIFFERENTIAL = """
units = "mm"
[ground]
O = [0, 0]
[links]
OA = {arm}
"O-G" = {rg}
AP = {rp}
[rolling]
AP = {{ on = "O-G"{inside} }}
[input]
crank = "OA"
angle = 35
speed = "{w1}"
acceleration = "{a1}"
[input.second]
crank = "O-G"
angle = -20
speed = "{w2}"
acceleration = "{a2}"
"""

# (arm, the driven gear's radius, the planet's, inside): a sun (outside) or a ring (inside)
TRAINS = [(100, 60, 40, False), (80, 120, 40, True), (75, 25, 50, False), (60, 100, 40, True)]
SPEEDS = [
    (7.5, -4.0, 3.0, 2.0),
    (-12.0, 12.0, 0.0, -30.0),
    (5.0, 0.5, 1.5, 0.0),
    (0.5, 9.0, 0.0, 4.0),
]


def _tabular(arm, rg, rp, inside, w_arm, w_gear):
    """The book's table: (1) arm fixed, the gear turned +1: the planet -e rg/rp (e = +1 on
    a sun, -1 in a ring); (2) all locked, +x. With the arm at y and the gear at x + y... the
    planet at y - e (rg/rp) x, x = w_gear - w_arm."""
    e = -1 if inside else 1
    x = w_gear - w_arm
    return w_arm - e * (rg / rp) * x


def _sensed(v, unit):
    return f"{abs(v)} {unit}" + (" ccw" if v > 0 else " cw" if v < 0 else "")


def _differential(arm, rg, rp, inside, w1, w2, a1, a2):
    w1, w2 = _sensed(w1, "rad/s"), _sensed(w2, "rad/s")
    a1, a2 = _sensed(a1, "rad/s^2"), _sensed(a2, "rad/s^2")
    return parse_scene(
        DIFFERENTIAL.format(
            arm=arm,
            rg=rg,
            rp=rp,
            w1=w1,
            w2=w2,
            a1=a1,
            a2=a2,
            inside=", inside = true" if inside else "",
        )
    )


@pytest.mark.parametrize("arm,rg,rp,inside", TRAINS)
@pytest.mark.parametrize("w1,w2,a1,a2", SPEEDS)
def test_differential_planet_by_the_tabular_method(arm, rg, rp, inside, w1, w2, a1, a2):
    """The arm and the sun (or ring) both driven: the planet's omega and alpha are the
    tabular method's; its points move as a rigid body about its centre on the arm."""
    sol = solve(_differential(arm, rg, rp, inside, w1, w2, a1, a2))
    size = abs(w1) + abs(w2) + 1.0
    assert sol.W["AP"] == pytest.approx(
        _tabular(arm, rg, rp, inside, w1, w2), rel=1e-12, abs=1e-12 * size
    )
    assert sol.Al["AP"] == pytest.approx(
        _tabular(arm, rg, rp, inside, a1, a2), rel=1e-12, abs=1e-12 * (abs(a1) + abs(a2) + 1.0)
    )
    # the planet's pitch point moves as the driven gear's (no slip)
    I, vI, _ = next(st for st in sol.plan.steps if st.kind == "rolling").contact_motion(sol)
    wg = w2
    vg = (-wg * I[1], wg * I[0])  # the gear turns about O at the origin
    assert math.dist(vI, vg) <= 1e-12 * size * (arm + rg) * 1e-3


@pytest.mark.parametrize("arm,rg,rp,inside", TRAINS)
def test_differential_superposition_table_adds_to_the_solution(arm, rg, rp, inside):
    """The step table's omega rows: the arm alone (the gear held) is the planet's omega on a
    fixed gear, the gear alone (the arm held) the fixed-centre ratio -e rg/rp; their sum
    the combined solve."""
    w1, w2 = 7.5, -4.0
    sol = solve(_differential(arm, rg, rp, inside, w1, w2, 0.0, 0.0))
    text = steps_text(sol)
    row = next(
        line for line in text.splitlines() if line.strip().startswith("AP ") and "rad/s" in line
    )
    e = -1 if inside else 1
    alone_arm, alone_gear = (1 + e * rg / rp) * w1, -e * (rg / rp) * w2
    for value in (alone_arm, alone_gear, sol.W["AP"]):
        assert f"{abs(value):.4g}".rstrip("0").rstrip(".") in row, (value, row)
    assert alone_arm + alone_gear == pytest.approx(sol.W["AP"], rel=1e-12)


def test_differential_planet_angle_over_a_sweep_by_the_tabular_method():
    """Over a sweep the gear turns with the arm at the ratio of their speeds; the planet's
    angle from the stated instant is the tabular method's, y - e (rg/rp) x, in angles."""
    arm, rg, rp, w1, w2 = 100, 60, 40, 7.5, -4.0
    sc = _differential(arm, rg, rp, False, w1, w2, 0.0, 0.0)
    plan = compile_plan(sc)
    th0 = sc.input.angle
    dth = np.linspace(0.0, 4 * math.pi, 401)
    m = evaluate(plan, theta=th0 + dth, array=True, upto=0)
    (ax, ay), (px, py) = m.P["A"], m.P["P"]
    phi = np.unwrap(np.arctan2(np.asarray(py) - ay, np.asarray(px) - ax))
    want = phi[0] + _tabular(arm, rg, rp, False, dth, dth * w2 / w1)
    assert np.allclose(phi, want, rtol=0, atol=1e-12)


def _fd(plan, th0, name, h=1e-3):
    """(d/dtheta, d2/dtheta2) of point ``name`` at th0 by five-point differences of the
    array road's positions (error about h^4)."""
    th = th0 + h * np.array([-2.0, -1.0, 0.0, 1.0, 2.0])
    m = evaluate(plan, theta=th, array=True, upto=0)
    x, y = (np.broadcast_to(np.asarray(c, dtype=float), th.shape) for c in m.P[name])
    d1 = [(c[0] - 8 * c[1] + 8 * c[3] - c[4]) / (12 * h) for c in (x, y)]
    d2 = [(-c[0] + 16 * c[1] - 30 * c[2] + 16 * c[3] - c[4]) / (12 * h * h) for c in (x, y)]
    return d1, d2


@pytest.mark.parametrize("name", ["rolling_planet_on_rocker", "rolling_sun_and_planet"])
@pytest.mark.parametrize("turn", [0.0, 0.3, 2.5, -1.0])  # the rod PQ reaches its path
def test_positions_differentiated_give_the_velocity_and_acceleration(name, turn):
    """The wheel's angle, followed from its arm (a rocker) or its gear (a connecting rod),
    is the integral of the no-slip relation: its points' positions differentiated in the
    crank angle (at 1 rad/s, uniform) are the velocities and accelerations of the polygons."""
    sc = load_scene(TEXTBOOK / f"{name}.toml")
    plan = compile_plan(sc)
    th = sc.input.angle + turn
    from polygon_method.steps import Context

    ctx = Context(np.array([th]), 1.0, 0.0, array=True)
    m = plan.run(ctx)
    assert ctx.bad is None or not ctx.bad.any()  # assembled there
    for p in sc.point_names:
        (vx, vy), (ax, ay) = m.V[p], m.A[p]
        d1, d2 = _fd(plan, th, p)
        scale = max(math.hypot(*[float(np.ravel(c)[0]) for c in m.V[q]]) for q in m.V) + 1e-3
        assert (
            math.hypot(d1[0] - float(np.ravel(vx)[0]), d1[1] - float(np.ravel(vy)[0]))
            <= 1e-8 * scale
        ), p
        scale_a = max(math.hypot(*[float(np.ravel(c)[0]) for c in m.A[q]]) for q in m.A)
        assert (
            math.hypot(d2[0] - float(np.ravel(ax)[0]), d2[1] - float(np.ravel(ay)[0]))
            <= 1e-6 * scale_a
        ), p


def test_planet_on_a_rocker_turns_by_willis_relation():
    """A planet on the rocker CD of a four-bar, on a fixed sun about D: omega_p = (1 + R/r)
    omega_CD and alpha_p = (1 + R/r) alpha_CD (R = |DC| - r: here 60, r = 30)."""
    sol = solve(load_scene(TEXTBOOK / "rolling_planet_on_rocker.toml"))
    assert sol.W["CP"] == pytest.approx(3.0 * sol.W["CD"], rel=1e-13)
    assert sol.Al["CP"] == pytest.approx(3.0 * sol.Al["CD"], rel=1e-13)


def test_sun_and_planet_sun_turns_twice_per_turn_of_the_arm():
    """Watt's sun and planet (equal gears, the planet fixed to the rod): omega_sun = 2
    omega_arm - omega_rod at every instant, and after a whole turn of the arm the rod is
    back and the sun has turned twice."""
    sc = load_scene(TEXTBOOK / "rolling_sun_and_planet.toml")
    sol = solve(sc)
    assert sol.W["OS"] == pytest.approx(2 * sol.W["OC"] - sol.W["CB"], rel=1e-13)
    assert sol.Al["OS"] == pytest.approx(2 * sol.Al["OC"] - sol.Al["CB"], rel=1e-13)
    plan = compile_plan(sc)
    th0 = sc.input.angle
    th = th0 + np.linspace(0.0, 2 * math.pi, 73)
    m = evaluate(plan, theta=th, array=True, upto=0)
    (sx, sy), (cx, cy), (bx, by) = m.P["S"], m.P["C"], m.P["B"]
    sun = np.unwrap(np.arctan2(sy, sx))
    rod = np.unwrap(np.arctan2(np.asarray(by) - cy, np.asarray(bx) - cx))
    arm = np.unwrap(np.arctan2(cy, cx))
    assert np.allclose(sun - sun[0], 2 * (arm - arm[0]) - (rod - rod[0]), atol=1e-12)
    assert sun[-1] - sun[0] == pytest.approx(4 * math.pi, abs=1e-12)


DRAG_LINK = """
units = "mm"
[ground]
A = [0, 0]
D = [30, 0]
[links]
AB = 100
BC = 110
CD = 120
CP = 40
[rolling]
CP = { on = "D", angle = 0 }
[assembly]
C = "above"
[input]
crank = "AB"
angle = 60
speed = "10 rad/s ccw"
"""


def test_an_arm_turning_fully_through_a_linkage_is_followed_half_a_turn_then_refused():
    """On a drag link the follower CD turns fully, but not at a fixed ratio of the crank:
    its angle is read from its points, which cannot tell a turn past half of one from a
    turn the other way. The sweep's positions there are masked (never a wrong angle), and
    where it is followed the planet turns at (1 + R/r) the arm, R = 80, r = 40."""
    sc = parse_scene(DRAG_LINK)
    plan = compile_plan(sc)
    th = sc.input.angle + np.linspace(0.0, 2 * math.pi, 361)
    from polygon_method.steps import Context

    ctx = Context(th, 1.0, 0.0, array=True)
    m = plan.run(ctx, upto=0)
    k = next(st.index for st in plan.steps if st.kind == "rolling")
    bad = np.broadcast_to(ctx.failures[k], th.shape)
    (cx, cy), (px, py) = m.P["C"], m.P["P"]
    arm = np.arctan2(cy, np.asarray(cx) - 30.0e-3)
    turned = np.abs(np.angle(np.exp(1j * (arm - arm[0]))))
    assert bad.any() and (~bad).any()
    assert np.all(bad == (turned > 0.95 * math.pi))
    ok = ~bad
    wheel = np.arctan2(np.asarray(py) - cy, np.asarray(px) - cx)
    want = np.angle(np.exp(1j * (wheel[0] + 3.0 * np.angle(np.exp(1j * (arm - arm[0]))))))
    assert np.allclose(np.angle(np.exp(1j * (wheel - want)))[ok], 0.0, atol=1e-12)


def test_sweep_of_a_drag_link_planet_stops_where_the_arm_cannot_be_followed(tmp_path):
    out = _run(DRAG_LINK, tmp_path, "sweep", "--summary")
    assert out.returncode == 0, out.stderr
    assert "wheel CP" in out.stdout and "half a turn from the stated instant" in out.stdout


def test_a_gear_as_the_driver_through_the_given_motion():
    """ "Gear 2 turns at 200 rpm cw": the train's first gear (the crank) is found, omega_1 =
    -omega_2 r2 / r1 (gears on fixed centres, external)."""
    text = (TEXTBOOK / "rolling_gear_train.toml").read_text(encoding="utf-8")
    text = text.replace('speed = "300 rpm ccw"', '"omega_O2-B" = "200 rpm cw"')
    text = text.replace('acceleration = "50 rad/s^2 ccw"', '"alpha_O2-B" = "5 rad/s^2 ccw"')
    sol = solve(parse_scene(text))
    w2 = -200 * 2 * math.pi / 60
    assert sol.W["O2-B"] == pytest.approx(w2, rel=1e-13)
    assert sol.W["O1-A"] == pytest.approx(-w2 * 6 / 4, rel=1e-13)
    assert sol.Al["O1-A"] == pytest.approx(-5.0 * 6 / 4, rel=1e-12)


def test_a_wheel_as_the_driver_through_the_given_motion():
    """ "The wheel rolls at 4 rad/s cw": its centre moves at omega r along the ground (r =
    50 mm), and the crank's speed that gives it is found."""
    text = (WORKED / "rolling_wheel_rod_slider.toml").read_text(encoding="utf-8")
    text = text.replace('speed = "20 rad/s cw"', 'omega_CP = "4 rad/s cw"')
    sol = solve(parse_scene(text))
    assert sol.W["CP"] == pytest.approx(-4.0, rel=1e-13)
    assert sol.V["C"][0] == pytest.approx(4.0 * 0.05, rel=1e-13)
    assert sol.V["C"][1] == pytest.approx(0.0, abs=1e-15)


def _run(text, tmp_path, *args):
    f = tmp_path / "s.toml"
    f.write_text(text)
    cmd = [sys.executable, "-m", "polygon_method", *args, str(f)]
    return subprocess.run(
        cmd, capture_output=True, text=True, env={"PYTHONPATH": str(HERE.parent), "PATH": ""}
    )


OVER = """
[ground]
O1 = [0, 0]
O2 = [100, 0]
[links]
"O1-A" = 40
"O2-B" = 60
[rolling]
"O2-B" = { on = "O1-A", angle = 90 }
[input]
crank = "O1-A"
angle = 20
speed = "300 rpm ccw"
[input.second]
crank = "O2-B"
angle = 90
speed = "10 rad/s cw"
"""


def test_a_second_driver_on_a_meshed_gear_over_determines_the_chain(tmp_path):
    """Both gears of a pair driven: one line, naming [input.second] (it was solved with the
    mesh silently ignored)."""
    out = _run(OVER, tmp_path, "solve")
    assert out.returncode == 2, out.stdout
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and "over-determine" in lines[0] and "[input.second]" in lines[0]


@pytest.mark.parametrize(
    "name,old,new",
    [
        ("rolling_sun_and_planet", "on_radius = 100", "on_radius = 90"),
        ("rolling_planet_on_rocker", "on_radius = 60", "on_radius = 70"),
        ("rolling_differential", "OS = 6", "OS = 7"),
    ],
)
def test_a_pair_whose_contact_leaves_the_pitch_point_is_refused_in_one_line(
    name, old, new, tmp_path
):
    text = (TEXTBOOK / f"{name}.toml").read_text(encoding="utf-8")
    assert old in text
    bad = text.replace(old, new)
    if name == "rolling_differential":  # the sun larger than the centre distance allows
        bad = bad.replace(
            'AP = { on = "OS", angle = 45 }', 'AP = { on = "OS", on_radius = 7, angle = 45 }'
        )
    out = _run(bad, tmp_path, "solve")
    assert out.returncode == 2, out.stdout
    lines = out.stderr.strip().splitlines()
    assert len(lines) == 1 and "pitch point" in lines[0] and "[rolling]" in lines[0], lines


@pytest.mark.parametrize(
    "name", ["rolling_planet_on_rocker", "rolling_sun_and_planet", "rolling_differential"]
)
@pytest.mark.parametrize(
    "command",
    [
        ("solve", "--json"),
        ("steps",),
        ("centres",),
        ("sweep", "--summary"),
        ("linkage",),
        ("plan",),
    ],
)
def test_every_view_works_or_refuses_in_one_located_line(name, command, tmp_path):
    text = (TEXTBOOK / f"{name}.toml").read_text(encoding="utf-8")
    out = _run(text, tmp_path, *command)
    if out.returncode == 0:
        assert out.stdout.strip() and "Traceback" not in out.stderr
    else:
        lines = out.stderr.strip().splitlines()
        assert out.returncode == 2 and len(lines) == 1 and "s.toml" in lines[0], out.stderr


COUPLER_ARM = """
units = "mm"
[ground]
A = [0, 0]
D = [120, 0]
[links]
AB = 50
BC = 130
CD = 90
"C-P" = 40
[rolling]
"C-P" = { on = "B-C", on_radius = 90, angle = 20 }
[assembly]
C = "above"
[input]
crank = "AB"
angle = 60
speed = "10 rad/s ccw"
acceleration = "20 rad/s^2 cw"
"""


def test_a_planet_meshing_with_a_gear_fixed_to_its_own_arm_turns_with_the_arm():
    """The coupler BC as the arm and as the gear (a gear fixed to it at B, the planet at
    C): relative to the arm nothing turns, so the planet turns with the coupler (kd + kb =
    1: the tabular method's row 'all locked')."""
    sol = solve(parse_scene(COUPLER_ARM))
    assert sol.W["C-P"] == pytest.approx(sol.W["BC"], rel=1e-13)
    assert sol.Al["C-P"] == pytest.approx(sol.Al["BC"], rel=1e-13)


@pytest.mark.parametrize(
    "given,code",
    [
        # the planet's turning relative to the arm: -(r_s/r_p)(omega_s - omega_arm) = 1.5 x
        # (2 pi + 4 pi) = 28.27 rad/s ccw (the row 'all locked' left out)
        ("28.27 rad/s ccw", "arm_row_left_out"),
        # the ratio of fixed centres: -(r_s/r_p) omega_s = 1.5 x 2 pi = 9.425 rad/s ccw
        ("9.425 rad/s ccw", "arm_taken_fixed"),
    ],
)
def test_check_names_the_tabular_methods_slips(given, code):
    """A differential's planet answered with a classic slip of the tabular method is
    diagnosed as that slip (the values by hand, above)."""
    from polygon_method.check import check_answers

    text = (WORKED / "differential_epicyclic.toml").read_text(encoding="utf-8")
    text = text.replace('omega_AP = "40.84 rad/s ccw"', f'omega_AP = "{given}"')
    assert given in text
    verdicts = check_answers(solve(parse_scene(text)))
    v = next(v for v in verdicts if v.key == "omega_AP")
    assert not v.ok and v.mistake == code, (v.mistake, v.diagnosis)


def test_a_gear_as_the_crank_drives_the_gears_written_on_it(tmp_path):
    """ "Gear 2 turns at 300 rpm ccw and drives gears 1 and 3": gear 2 is the crank and the
    others are wheels on it (omega_1 = -(r2/r1) omega_2 = -1.5 omega_2, omega_3 = -(r2/r3)
    omega_2 = -0.75 omega_2); the mesh written the other way round is refused, saying how
    to write it."""
    text = (TEXTBOOK / "rolling_gear_train.toml").read_text(encoding="utf-8")
    turned = text.replace('crank = "O1-A"', 'crank = "O2-B"').replace(
        "angle = 20\n", "angle = 90\n"
    )
    out = _run(turned, tmp_path, "solve")
    lines = out.stderr.strip().splitlines()
    assert out.returncode == 2 and len(lines) == 1, out.stderr
    assert '"O1-A" = { on = "O2-B" }' in lines[0] and "[rolling] O2-B" in lines[0]
    good = turned.replace(
        '"O2-B" = { on = "O1-A", angle = 90 }', '"O1-A" = { on = "O2-B", angle = 200 }'
    )
    sol = solve(parse_scene(good))
    w2 = 300 * 2 * math.pi / 60
    assert sol.W["O2-B"] == pytest.approx(w2, rel=1e-13)
    assert sol.W["O1-A"] == pytest.approx(-1.5 * w2, rel=1e-13)
    assert sol.W["O3-C"] == pytest.approx(-0.75 * w2, rel=1e-13)
