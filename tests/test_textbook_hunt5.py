"""Kinematics problems in a book's words that the scene format could not state before
(tests/textbook/hunt5_*.toml): a block in a slot whose line misses the lever's pivot (an
offset slot, found by the slotted link), a lever's block in an offset slot of a turning arm
(found by the slider on a moving guide).

Each is set out here by hand, with nothing of the solver: the points as closed forms of the
crank angle theta at 40 digits (the slot's line as the tangent from the block to the circle
of the offset's radius about the pivot; a circle cut by a line), the velocities and
accelerations X' w and X'' w^2 (mpmath.diff in theta), each link's angle by atan2 likewise,
the sliding velocity and the Coriolis component 2 omega vs from those. Every quantity to
1e-9 of its kind's size; each file's [answers] (four figures of this reference) within its
tolerance by `check`.
"""

from __future__ import annotations

import math
from pathlib import Path

import mpmath
import numpy as np
import pytest
from mpmath import mpf

from polygon_method import load_scene, parse_scene, solve
from polygon_method.check import check_answers
from polygon_method.common.errors import PolygonMethodError

HERE = Path(__file__).resolve().parent / "textbook"
REL = 1e-9
pi = mpmath.pi


@pytest.fixture(autouse=True)
def _digits():
    old = mpmath.mp.dps
    mpmath.mp.dps = 40
    yield
    mpmath.mp.dps = old


def _d(f, th, n):
    return mpmath.diff(f, th, n)


def _motion(pos, th, w):
    """(position, velocity, acceleration) of a point given as pos(theta) -> (x, y), the crank
    turning at w (rad/s, ccw +) steadily."""
    out = []
    for c in (0, 1):
        f = lambda t, c=c: pos(t)[c]  # noqa: E731
        out.append((f(th), _d(f, th, 1) * w, _d(f, th, 2) * w * w))
    return tuple((out[0][i], out[1][i]) for i in range(3))


def _angle_rates(ang, th, w):
    """(omega, alpha) of a link whose direction is ang(theta)."""
    return _d(ang, th, 1) * w, _d(ang, th, 2) * w * w


def _close(got, want, scale, what):
    err = abs(float(mpf(got) - want)) / max(scale, 1e-300)
    assert err < REL, f"{what}: {got} against {float(want)} (relative {err:.2e})"


def _vclose(got, want, scale, what):
    err = math.hypot(float(mpf(got[0]) - want[0]), float(mpf(got[1]) - want[1])) / scale
    assert err < REL, f"{what}: {got} against ({float(want[0])}, {float(want[1])}) ({err:.2e})"


# --- a crank drives a lever through a block in an offset slot ----------------------------
R1, L1, BR1, E1 = mpf("0.1"), mpf("0.5"), mpf("0.2"), mpf("0.03")
Q1, YT1 = (mpf(0), mpf("-0.25")), mpf("0.2")


def _lever_angle(th):
    """The lever QB's direction: A - Q = t w + e perp(w), t > 0 (B on the block's side)."""
    ax, ay = R1 * mpmath.cos(th) - Q1[0], R1 * mpmath.sin(th) - Q1[1]
    t = mpmath.sqrt(ax * ax + ay * ay - E1 * E1)
    return mpmath.atan2(ay, ax) - mpmath.atan2(E1, t)


def _lever_B(th):
    p = _lever_angle(th)
    return (Q1[0] + L1 * mpmath.cos(p), Q1[1] + L1 * mpmath.sin(p))


def _lever_R(th):
    bx, by = _lever_B(th)
    return (bx + mpmath.sqrt(BR1 * BR1 - (YT1 - by) ** 2), YT1)


def test_offset_slot_lever_by_hand():
    sol = solve(load_scene(HERE / "hunt5_offset_slot_lever.toml"))
    th, w = mpmath.radians(30), -2 * pi * 200 / 60
    A = lambda t: (R1 * mpmath.cos(t), R1 * mpmath.sin(t))  # noqa: E731
    pts = {"A": _motion(A, th, w), "B": _motion(_lever_B, th, w), "R": _motion(_lever_R, th, w)}
    vmax = max(float(mpmath.hypot(*m[1])) for m in pts.values())
    amax = max(float(mpmath.hypot(*m[2])) for m in pts.values())
    for name, (p, v, a) in pts.items():
        _vclose(sol.P[name], p, float(L1), f"position of {name}")
        _vclose(sol.V[name], v, vmax, f"velocity of {name}")
        _vclose(sol.A[name], a, amax, f"acceleration of {name}")
    wq, aq = _angle_rates(_lever_angle, th, w)
    _close(sol.W["QB"], wq, abs(w), "omega_QB")
    _close(sol.Al["QB"], aq, abs(float(aq)), "alpha_QB")
    # the block's sliding along the slot (u: Q -> B) and its Coriolis component 2 omega vs
    pa, va, aa = pts["A"]
    u = (mpmath.cos(_lever_angle(th)), mpmath.sin(_lever_angle(th)))
    rel = (pa[0] - Q1[0], pa[1] - Q1[1])
    under = (-wq * rel[1], wq * rel[0])  # the lever's point under A
    vs = (va[0] - under[0]) * u[0] + (va[1] - under[1]) * u[1]
    _close(sol.S["A"][0], vs, vmax, "vs_A")
    _vclose(sol.coriolis("A"), (-2 * wq * vs * u[1], 2 * wq * vs * u[0]), amax, "Coriolis at A")
    # the slot's line really is 30 mm to the left of Q -> B, through the block
    (bx, by), (ax_, ay_) = sol.P["B"], sol.P["A"]
    left = ((ax_ - 0.0) * -(by + 0.25) + (ay_ + 0.25) * bx) / 0.5
    assert abs(left - 0.03) < 1e-15


# --- a lever's block in an offset slot of a turning arm ----------------------------------
L2, E2, D2 = mpf("0.2"), mpf("-0.025"), (mpf("0.25"), mpf("0.1"))


def _arm_B(th):
    """B on the slot's line O + e perp(u) + s u (u the arm's direction), |DB| = 0.2: the
    left one of the two (the smaller s)."""
    u = (mpmath.cos(th), mpmath.sin(th))
    q = (-E2 * u[1] - D2[0], E2 * u[0] - D2[1])  # the line's point less D
    b = q[0] * u[0] + q[1] * u[1]
    s = -b - mpmath.sqrt(b * b - (q[0] ** 2 + q[1] ** 2 - L2 * L2))
    return (-E2 * u[1] + s * u[0], E2 * u[0] + s * u[1])


def test_rocker_in_offset_slot_of_arm_by_hand():
    sol = solve(load_scene(HERE / "hunt5_rocker_in_offset_slot_of_crank.toml"))
    th, w = mpmath.radians(20), 2 * pi * 120 / 60
    p, v, a = _motion(_arm_B, th, w)
    vmax, amax = float(w) * 0.3, float(w) ** 2 * 0.3  # the arm's tip C leads both
    _vclose(sol.P["B"], p, 0.3, "position of B")
    _vclose(sol.V["B"], v, vmax, "velocity of B")
    _vclose(sol.A["B"], a, amax, "acceleration of B")

    def rocker(t):
        bx, by = _arm_B(t)
        return mpmath.atan2(by - D2[1], bx - D2[0])

    wd, ad = _angle_rates(rocker, th, w)
    _close(sol.W["DB"], wd, float(w), "omega_DB")
    _close(sol.Al["DB"], ad, float(w) ** 2, "alpha_DB")
    u = (mpmath.cos(th), mpmath.sin(th))
    vs = (v[0] + w * p[1]) * u[0] + (v[1] - w * p[0]) * u[1]  # less omega x OB
    _close(sol.S["B"][0], vs, vmax, "vs_B")
    _vclose(sol.coriolis("B"), (-2 * w * vs * u[1], 2 * w * vs * u[0]), amax, "Coriolis")


# --- the slide valve driven by an eccentric on the crank shaft -----------------------------
EC, EV, R3, L3 = mpf("0.04"), mpf("1"), mpf("0.3"), mpf("1.2")


def _valve(th):
    """The eccentric's centre E, 120 deg ahead of the crank, and the valve V on the line of
    stroke through O, on the piston's side."""
    ex, ey = EC * mpmath.cos(th + 2 * pi / 3), EC * mpmath.sin(th + 2 * pi / 3)
    return (ex + mpmath.sqrt(EV * EV - ey * ey), mpf(0))


def _piston(th):
    ay = R3 * mpmath.sin(th)
    return (R3 * mpmath.cos(th) + mpmath.sqrt(L3 * L3 - ay * ay), mpf(0))


def test_valve_eccentric_by_hand():
    sol = solve(load_scene(HERE / "hunt5_valve_eccentric_on_crank_shaft.toml"))
    th, w = mpmath.radians(45), 2 * pi * 180 / 60
    amax = float(w) ** 2 * 0.3  # the crank pin's
    for name, pos in (("V", _valve), ("B", _piston)):
        p, v, a = _motion(pos, th, w)
        _vclose(sol.P[name], p, 1.2, f"position of {name}")
        _vclose(sol.V[name], v, float(w) * 0.3, f"velocity of {name}")
        _vclose(sol.A[name], a, amax, f"acceleration of {name}")

    def rod(t):
        ex, ey = EC * mpmath.cos(t + 2 * pi / 3), EC * mpmath.sin(t + 2 * pi / 3)
        return mpmath.atan2(-ey, _valve(t)[0] - ex)

    w_rod, _ = _angle_rates(rod, th, w)
    _close(sol.W["EV"], w_rod, float(w), "omega_EV")
    # the sheave (r = 120 mm) turns in the strap at the crank's speed less the rod's
    _close(
        sol.rubbing["E"].rubbing_velocity, mpf("0.12") * abs(w - w_rod), float(w) * 0.12, "rub_E"
    )


# --- two blocks on one link, their guides at 60 deg --------------------------------------
def _trammel(s):
    """A = (s, 0), B = t (cos 60, sin 60) with |AB| = 0.5, the root above the line."""
    t = s / 2 + mpmath.sqrt(mpf("0.25") - 3 * s * s / 4)
    return (s, mpf(0)), (t / 2, t * mpmath.sqrt(3) / 2)


def test_two_blocks_guides_at_60_by_hand():
    sol = solve(load_scene(HERE / "hunt5_two_blocks_guides_at_60.toml"))
    s0, v, a = mpf("-0.3"), mpf(-2), mpf(5)  # A's place, velocity and acceleration along +x

    def rates(f):
        return f(s0), mpmath.diff(f, s0) * v, mpmath.diff(f, s0, 2) * v * v + mpmath.diff(f, s0) * a

    for name, pick in (("B", lambda s: _trammel(s)[1]), ("C", None)):
        if pick is None:  # C the midpoint of AB
            pick = lambda s: tuple((p + q) / 2 for p, q in zip(*_trammel(s)))  # noqa: E731
        px, vx, ax_ = rates(lambda s: pick(s)[0])
        py, vy, ay = rates(lambda s: pick(s)[1])
        _vclose(sol.P[name], (px, py), 0.5, f"position of {name}")
        _vclose(sol.V[name], (vx, vy), 2.0, f"velocity of {name}")
        _vclose(sol.A[name], (ax_, ay), 5.0, f"acceleration of {name}")

    def rod(s):
        (ax0, ay0), (bx, by) = _trammel(s)
        return mpmath.atan2(by - ay0, bx - ax0)

    _, w, al = rates(rod)
    _close(sol.W["AB"], w, 4.0, "omega_AB")
    _close(sol.Al["AB"], al, 5.0 / 0.5, "alpha_AB")


@pytest.mark.parametrize(
    "name",
    [
        "hunt5_offset_slot_lever",
        "hunt5_rocker_in_offset_slot_of_crank",
        "hunt5_valve_eccentric_on_crank_shaft",
        "hunt5_oscillating_cylinder_offset_trunnion",
        "hunt5_two_blocks_guides_at_60",
        "hunt5_swinging_link_block_on_offset_pin",
        "hunt5_pantograph_tracing_point",
        "hunt5_hackworth_valve_gear",
        "hunt5_bell_crank_angled_offset_slot",
        "hunt5_rocker_arm_through_offset_swivel",
    ],
)
def test_book_answers(name):
    verdicts = [v for v in check_answers(solve(load_scene(HERE / f"{name}.toml"))) if v.given]
    assert len(verdicts) >= 4 and all(v.ok for v in verdicts), [
        (v.key, v.given, v.correct) for v in verdicts if not v.ok
    ]


_LEVER = """
units = "mm"
[ground]
Q = [0, -130]
O = [0, 0]
[links]
OA = 100
QB = 500
[sliders]
A = { along = "QB", offset = OFFSET }
[input]
crank = "OA"
angle = ANGLE
speed = "200 rpm cw"
"""


def _lever(offset="30", angle="0"):
    return _LEVER.replace("OFFSET", offset).replace("ANGLE", angle)


@pytest.mark.parametrize(
    "offset, words",
    [
        ("0", "offset = 0: the slot is on the link's own line"),
        ('"-30 left"', 'give the size alone, e.g. "30 left"'),
    ],
)
def test_an_offset_misstated_is_one_line(offset, words):
    with pytest.raises(PolygonMethodError) as exc:
        parse_scene(_lever(offset))
    assert words in str(exc.value) and "\n" not in str(exc.value)


def test_a_block_nearer_the_pivot_than_the_offset_is_refused_naming_both():
    with pytest.raises(PolygonMethodError) as exc:
        solve(parse_scene(_lever("170")))  # |QA| = hypot(100, 130) < 170 at 0 deg
    msg = str(exc.value)
    assert "block A is 164.012 mm from Q, less than the slot's offset of 170 mm" in msg


def test_the_slot_square_to_the_block_is_a_limit_refused_at_and_warned_near():
    # |QA| = 30 = the offset at 270 deg: the block at the foot of Q's perpendicular
    with pytest.raises(PolygonMethodError) as exc:
        solve(parse_scene(_lever("30", "-90")))
    assert "stands square to QA (condition 0)" in str(exc.value)
    near = solve(parse_scene(_lever("30", "-89.9")))
    assert any("nearly square to QA" in w for w in near.warnings)


def test_the_guide_named_from_its_far_end_turns_the_side_over():
    """along = "BQ" (first B, the lever's far end) looks the other way along the lever: its
    "30 right" is "QB"'s "30 left", the same slot, the same motion."""
    one = solve(parse_scene(_lever('"30 left"', "20")))
    two = solve(parse_scene(_lever('"30 right"', "20").replace('"QB"', '"BQ"')))
    for p in ("A", "B"):
        for got, want in zip(two.P[p] + two.V[p] + two.A[p], one.P[p] + one.V[p] + one.A[p]):
            assert abs(got - want) < 1e-12
    assert abs(two.S["A"][0] + one.S["A"][0]) < 1e-12  # signed the other way along it


def test_the_offset_sign_and_words_agree():
    """'30 mm left' is offset = 30 and '30 right' is -30: the block is that far to the
    left (right) of Q -> B."""
    for words, side in (('"30 mm left"', 1), ("30", 1), ('"30 right"', -1), ("-30", -1)):
        sol = solve(parse_scene(_lever(words)))
        (qx, qy), (bx, by), (ax, ay) = sol.P["Q"], sol.P["B"], sol.P["A"]
        left = ((bx - qx) * (ay - qy) - (by - qy) * (ax - qx)) / 0.5
        assert abs(left - side * 0.03) < 1e-15
        assert sol.to_dict()["sliders"]["A"]["offset"] == side * 0.03  # the JSON's, SI


def test_a_collar_driven_along_its_rod_takes_no_offset():
    text = """
units = "mm"
[ground]
O = [0, 0]
D = [400, 0]
[links]
OA = 600
DC = 250
[sliders]
C = { along = "OA", offset = 20 }
[input]
block = "C"
s_C = 350
vs_C = "1.5 m/s outward"
"""
    with pytest.raises(PolygonMethodError) as exc:
        parse_scene(text)
    assert "takes no offset" in str(exc.value)


def test_every_view_says_the_offset_slot(capsys, tmp_path):
    """steps sets the slot out as a book does (the tangent from the block to the circle of
    the offset's radius) and finds the lever's end by its image triangle; solve's table and
    the problem's words name the slot's offset; sweep --summary and check run."""
    from polygon_method.cli import main

    path = str(HERE / "hunt5_offset_slot_lever.toml")
    assert main(["steps", path]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "draw the circle of radius 30 mm (0.60 cm) about Q and from A the tangent" in out
    assert "b completes the triangle oa1b similar to QAB" in out
    assert "b' completes the triangle o'a1'b' similar to QAB" in out
    assert "block A slides in a slot of QB parallel to its line Q -> B, 30 mm to the left" in out
    assert main(["solve", path]) == 0
    assert "QB slot 30 left" in capsys.readouterr().out
    assert main(["sweep", "--summary", path]) == 0
    assert "ac_A" in capsys.readouterr().out
    assert main(["check", path]) == 0
    assert "5 of 5 right" in capsys.readouterr().out
    from polygon_method.text.words import given

    assert (
        "A block at A slides in a slot of link QB parallel to its line Q -> B, 30 mm to the "
        "left of it." in given(load_scene(path))
    )


@pytest.mark.parametrize(
    "offset, words",
    [
        ('"30 upward"', "offset = '30 upward': unknown unit 'upward'"),
        ('"left"', "offset = 'left': cannot read ''"),
        ('"30 deg"', "offset = '30 deg': 'deg' is a unit of angle"),
        ("[1, 2]", "offset = [1, 2]: expected a number"),
    ],
)
def test_an_offset_not_a_length_is_one_line_naming_the_key(offset, words):
    with pytest.raises(PolygonMethodError) as exc:
        parse_scene(_lever(offset))
    msg = str(exc.value)
    assert words in msg and 'e.g. "30 mm left"' in msg and "\n" not in msg


def test_a_greatest_value_at_a_change_point_is_not_read_as_noise():
    """Q 130 mm under O, the crank 100 mm, the slot 30 mm off: at 270 deg |QA| = 30 mm, the
    slot's line touches the block (a change point, followed continuous in velocity), and
    there the Coriolis component is greatest. The sweep's sample there is its Richardson
    extrapolation; its bound is that of the angles it is made from, not the plan's at a
    condition of nought (which called 46.74 m/s^2 noise: "ac_A 0 (constant)"). The value:
    2 omega vs on the branch that keeps omega_QB continuous (the lever's angle by the
    tangent, differentiated at 40 digits just before 270 deg)."""
    from polygon_method.linkage.summary import summarize

    e, q, r, w = mpf("0.03"), mpf("-0.13"), mpf("0.1"), -2 * pi * 200 / 60

    def lever(t):
        ax, ay = r * mpmath.cos(t), r * mpmath.sin(t) - q
        return mpmath.atan2(ay, ax) - mpmath.atan2(e, -mpmath.sqrt(ax * ax + ay * ay - e * e))

    th = mpmath.radians(270) - mpmath.radians(mpf("1e-9"))
    wq = mpmath.diff(lever, th) * w
    rel, u = (
        (r * mpmath.cos(th), r * mpmath.sin(th) - q),
        (mpmath.cos(lever(th)), mpmath.sin(lever(th))),
    )
    v = (-r * mpmath.sin(th) * w + wq * rel[1], r * mpmath.cos(th) * w - wq * rel[0])
    want = abs(2 * wq * (v[0] * u[0] + v[1] * u[1]))
    ext = {x.name: x for x in summarize(parse_scene(_lever("30", "10"))).extremes}["ac_A"]
    assert ext.at_max is not None and abs(ext.at_max - 270) < 1e-6
    assert abs(ext.maximum - float(want)) < 1e-6 * float(want)


def test_pantograph_copies_the_tracing_point_at_a_third_over_its_travel():
    """O, Q, P stay in line with OQ = OP / 3 (C a third of the way up OB, D a third of the
    way down BP, CBDQ a parallelogram: Q = O + (P - O) / 3 whatever B does), so Q's
    velocity and acceleration are P's over three at every place of its travel."""
    from polygon_method.motion.sweeps import sweep

    scene = load_scene(HERE / "hunt5_pantograph_tracing_point.toml")
    res = sweep(scene, np.linspace(0.05, 0.45, 41))
    assert len(res.theta) == 41
    for what in ("P", "V", "A"):
        got, want = getattr(res, what)["Q"], getattr(res, what)["P"]
        for c in (0, 1):
            assert np.max(np.abs(np.asarray(got[c]) - np.asarray(want[c]) / 3)) < 1e-12 * 3


def test_the_other_tangent_is_the_other_assembly():
    """[assembly] C = "left" takes the other tangent from the trunnion O to the circle of
    the offset about B: O - B = t w + e perp(w) with t the other way (e = -15 mm, to the
    right of B -> C), C = B + BC w."""
    path = HERE / "hunt5_oscillating_cylinder_offset_trunnion.toml"
    text = path.read_text(encoding="utf-8").replace('C = "right"', 'C = "left"')
    sol = solve(parse_scene(text))
    th = mpmath.radians(120)
    b = (mpf("0.06") * mpmath.cos(th), mpf("0.06") * mpmath.sin(th))
    d = (mpf("0.24") - b[0], -b[1])
    m2, e = d[0] ** 2 + d[1] ** 2, mpf("-0.015")
    t = -mpmath.sqrt(m2 - e * e)  # the default is the block's side, t > 0
    w = ((t * d[0] + e * d[1]) / m2, (t * d[1] - e * d[0]) / m2)
    _vclose(sol.P["C"], (b[0] + mpf("0.32") * w[0], b[1] + mpf("0.32") * w[1]), 0.32, "C")
    assert sol.P["C"][0] < sol.P["B"][0]


def test_the_coriolis_component_left_out_of_the_lever_is_named():
    """The crank and slotted lever's classic slip: the line parallel to the slot drawn
    through a' itself, not through the start of 2 omega vs. Its alpha_QB solved by hand
    from the closed form (a_A = -omega^2 QA + alpha perp(QA) + as u, in mpmath), given as
    the answer, is named by check; the right one is not."""
    th, w = mpmath.radians(30), -2 * pi * 200 / 60
    _, _, aa = _motion(lambda t: (R1 * mpmath.cos(t), R1 * mpmath.sin(t)), th, w)
    wq, _ = _angle_rates(_lever_angle, th, w)
    d = (R1 * mpmath.cos(th) - Q1[0], R1 * mpmath.sin(th) - Q1[1])
    u = (mpmath.cos(_lever_angle(th)), mpmath.sin(_lever_angle(th)))
    rhs = mpmath.matrix([aa[0] + wq * wq * d[0], aa[1] + wq * wq * d[1]])
    al, _ = mpmath.lu_solve(mpmath.matrix([[-d[1], u[0]], [d[0], u[1]]]), rhs)
    sense = "ccw" if al > 0 else "cw"
    path = HERE / "hunt5_offset_slot_lever.toml"
    text = path.read_text(encoding="utf-8")
    text = (
        text[: text.index("[answers]")]
        + f'[answers]\nalpha_QB = "{abs(float(al)):.4g} rad/s^2 {sense}"\n'
    )
    (verdict,) = check_answers(solve(parse_scene(text)))
    assert not verdict.ok and verdict.mistake == "coriolis_omitted"
    assert "Coriolis component 2 omega v of block A sliding on QB" in verdict.diagnosis
    assert abs(float(al)) > 2 * 40.74  # not a rounding of the right answer


def test_the_coriolis_component_left_out_of_a_moving_guide_is_named():
    """The rocker DB's block runs in the turning arm's slot: without 2 omega vs the line
    parallel to the slot goes through the arm's point under B itself. alpha_DB so, by hand
    from the closed form (a_B1 = -omega^2 OB for the arm turning steadily about O;
    -w_DB^2 DB + alpha perp(DB) = a_B1 + as u, in mpmath), is named by check."""
    th, w = mpmath.radians(20), 2 * pi * 120 / 60
    p, _, _ = _motion(_arm_B, th, w)

    def rocker(t):
        bx, by = _arm_B(t)
        return mpmath.atan2(by - D2[1], bx - D2[0])

    wd, _ = _angle_rates(rocker, th, w)
    r = (p[0] - D2[0], p[1] - D2[1])
    u = (mpmath.cos(th), mpmath.sin(th))
    rhs = mpmath.matrix([-w * w * p[0] + wd * wd * r[0], -w * w * p[1] + wd * wd * r[1]])
    al, _ = mpmath.lu_solve(mpmath.matrix([[-r[1], -u[0]], [r[0], -u[1]]]), rhs)
    path = HERE / "hunt5_rocker_in_offset_slot_of_crank.toml"
    text = path.read_text(encoding="utf-8")
    sense = "ccw" if al > 0 else "cw"
    text = (
        text[: text.index("[answers]")]
        + f'[answers]\nalpha_DB = "{abs(float(al)):.4g} rad/s^2 {sense}"\n'
    )
    (verdict,) = check_answers(solve(parse_scene(text)))
    assert not verdict.ok and verdict.mistake == "coriolis_omitted", verdict
    assert "left out of the acceleration polygon" in verdict.diagnosis


@pytest.mark.parametrize(
    "e, code, words",
    [
        ("0", "offset_left_out", "the slot of QB drawn through its line QB (its offset of 30 mm"),
        ("-0.03", "offset_other_side", "the slot of QB taken 30 mm to the right of its line"),
    ],
)
def test_an_offset_slot_drawn_otherwise_is_named(e, code, words):
    """A student who draws the slot through the lever's pivot (or on its other side): the
    lever's omega by the tangent's closed form with that offset (0, or -30 mm), given as
    the answer, is named by check."""
    e = mpf(e)

    def angle(t):
        ax, ay = R1 * mpmath.cos(t) - Q1[0], R1 * mpmath.sin(t) - Q1[1]
        return mpmath.atan2(ay, ax) - mpmath.atan2(e, mpmath.sqrt(ax * ax + ay * ay - e * e))

    wq, _ = _angle_rates(angle, mpmath.radians(30), -2 * pi * 200 / 60)
    text = (HERE / "hunt5_offset_slot_lever.toml").read_text(encoding="utf-8")
    text = text[: text.index("[answers]")] + f'[answers]\nomega_QB = "{-float(wq):.4g} rad/s cw"\n'
    (verdict,) = check_answers(solve(parse_scene(text)))
    assert not verdict.ok and verdict.mistake == code and words in verdict.diagnosis, verdict


def test_steps_sets_out_the_block_on_the_offset_slot_of_a_moving_guide(capsys):
    from polygon_method.cli import main

    assert main(["steps", str(HERE / "hunt5_rocker_in_offset_slot_of_crank.toml")]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert (
        "B: an arc of radius DB = 200 mm (10.00 cm) about D cuts the line of the slot of OC, "
        "parallel to OC and 25 mm (1.25 cm) to the right of it (looking from O to C), at B"
    ) in out


def test_the_offset_slot_quick_return_time_ratio_and_stroke():
    """The lever with its offset slot is a quick return: the ram's dead points where
    d s_R / d theta = 0 (s_R by the tangent's closed form, roots by mpmath.findroot from a
    degree's scan), its stroke their distance apart and the time ratio the crank's turns
    between them, the larger over the smaller."""

    def s_r(th):
        p = _lever_angle(th)
        bx, by = Q1[0] + L1 * mpmath.cos(p), Q1[1] + L1 * mpmath.sin(p)
        return bx + mpmath.sqrt(BR1 * BR1 - (YT1 - by) ** 2)

    ds = lambda t: mpmath.diff(s_r, t)  # noqa: E731
    scan = [float(ds(mpmath.radians(k))) for k in range(361)]
    roots = [
        mpmath.findroot(ds, mpmath.radians(k + 0.5))
        for k in range(360)
        if scan[k] * scan[k + 1] < 0
    ]
    assert len(roots) == 2
    stroke = abs(s_r(roots[0]) - s_r(roots[1]))
    turn = float(mpmath.degrees(roots[1] - roots[0])) % 360
    ratio = max(turn, 360 - turn) / min(turn, 360 - turn)
    text = (HERE / "hunt5_offset_slot_lever.toml").read_text(encoding="utf-8")
    text = text[: text.index("[answers]")] + '[answers]\ntime_ratio = "?"\nstroke_R = "?"\n'
    got = {v.key: v.correct for v in check_answers(solve(parse_scene(text)))}
    assert abs(got["time_ratio"] - ratio) < 1e-9 * ratio
    assert abs(got["stroke_R"] - float(stroke)) < 1e-9 * float(stroke)


@pytest.mark.parametrize(
    "name, angle",
    [
        ("hunt5_offset_slot_lever", None),
        ("hunt5_rocker_in_offset_slot_of_crank", None),
        ("hunt5_oscillating_cylinder_offset_trunnion", None),
        ("lever", "-89.9"),  # the slot nearly square to QA: condition 0.002
    ],
)
def test_offset_slots_within_their_error_bounds(name, angle):
    """Every quantity within its own error bound of the 40-digit Newton reference (the
    offset in its guide equation), near the slot's limit position too."""
    from error_bounds import compare_case, load_reference

    if angle is None:
        sol = solve(load_scene(HERE / f"{name}.toml"))
    else:
        sol = solve(parse_scene(_lever("30", angle)))
        assert min(sol.conditions.values()) < 0.01
    for kind, what, err, bound in compare_case(sol, load_reference(40)):
        assert err <= bound, (kind, what, err, bound)


def test_an_offset_slots_sweep_bounds_are_the_solves_bounds():
    """The same bound formulas on arrays: each sample of a sweep has a solve's bounds."""
    from polygon_method.motion.sweeps import sweep
    from polygon_method.solver.errorbound import error_bounds
    from polygon_method.solver.kinematics import evaluate

    scene = load_scene(HERE / "hunt5_offset_slot_lever.toml")
    res = sweep(scene, [0.3, 1.7, 2.9, 4.4])
    b = error_bounds(res)
    for i, th in enumerate(res.theta):
        one = error_bounds(evaluate(res.plan, theta=float(th)))
        for table, single in ((b.P, one.P), (b.V, one.V), (b.A, one.A), (b.W, one.W)):
            for k, v in single.items():
                got = v if isinstance(table[k], float) else table[k][i]
                assert got == pytest.approx(v, rel=1e-6, abs=1e-30), (k, th)
        for got, want in zip(b.S["A"], one.S["A"]):
            assert (got if isinstance(got, float) else got[i]) == pytest.approx(want, rel=1e-6)


def test_an_offset_slots_force_analysis_by_virtual_power():
    """The force analysis walks the lever with its block pushed across the offset slot
    (the normal force at A, off the lever's line): its driving torque is the virtual power's,
    T omega + sum(F.v) + sum(m g.v_G - m a_G.v_G - I alpha omega) = 0, from the motion
    (held to the reference above)."""
    text = (HERE / "hunt5_offset_slot_lever.toml").read_text(encoding="utf-8")
    text = text[: text.index("[answers]")] + (
        "[masses]\n"
        'QB = { mass = "12 kg", along = 250, inertia = "0.3 kg m^2" }\n'
        'BR = { mass = "3 kg", along = 100, inertia = "0.012 kg m^2" }\n'
        'A = { mass = "1.5 kg" }\nR = { mass = "20 kg" }\n'
        "[gravity]\n"
        '[loads]\nR = { force = "800 N", direction = 180 }\n'
    )
    sol = solve(parse_scene(text))
    V, A, W, Al = sol.V, sol.A, sol.W, sol.Al

    def dot(a, b):
        return a[0] * b[0] + a[1] * b[1]

    def mid(D, p, q):
        return ((D[p][0] + D[q][0]) / 2, (D[p][1] + D[q][1]) / 2)

    g, power = (0.0, -9.81), dot((-800.0, 0.0), V["R"])
    for m, inertia, p, q in ((12, 0.3, "Q", "B"), (3, 0.012, "B", "R")):
        vg, ag = mid(V, p, q), mid(A, p, q)
        power += m * dot(g, vg) - m * dot(ag, vg) - inertia * Al[p + q] * W[p + q]
    for m, p in ((1.5, "A"), (20, "R")):
        power += m * dot(g, V[p]) - m * dot(A[p], V[p])
    want = -power / W["OA"]
    got = sol.forces.input_torque
    assert abs(got - want) < 1e-9 * max(abs(want), 800 * 0.1)


def test_linkage_says_the_slots_offset_and_whether_the_crank_turns_fully(capsys):
    """|OQ - OA| = 150 mm is the nearest the block comes to Q: a slot 30 mm off lets the
    crank turn fully, one 170 mm off does not (the lever cannot reach the block there)."""
    from polygon_method.cli import main

    assert main(["linkage", str(HERE / "hunt5_offset_slot_lever.toml")]) == 0
    out = capsys.readouterr().out
    assert "lever QB pivoted at Q, OQ = 250 mm, its slot 30 mm off its line" in out
    assert "comes within |OQ - OA| = 150 mm of Q, never nearer than the offset" in out
    from polygon_method.linkage import analyse

    far = parse_scene(_lever("170", "90").replace("Q = [0, -130]", "Q = [0, -250]"))
    words = " ".join(analyse(far).classification)
    assert "nearer than the offset: the crank cannot turn fully" in words
