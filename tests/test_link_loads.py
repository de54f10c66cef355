"""A load's direction stated against a link ("perpendicular to BC, ccw", "along DC", "30 deg
ccw from CD"): it turns with the link. Checked against a Newton-Euler matrix solve written
here, with the positions in closed form (two circles' crossing) and the load's direction
by hand from them; at one instant (the power balance and the force analysis), stated
numerically instead (the same numbers), over a sweep (the load turning at every angle),
and the refusals."""

from __future__ import annotations

import math

import numpy as np
import pytest

from polygon_method import parse_scene, solve
from polygon_method.cli import main
from polygon_method.common.errors import SceneError
from polygon_method.common.numbers import fmt
from polygon_method.motion.sweeps import sweep

AB, BC, CD, AD = 0.2, 0.6, 0.4, 0.5  # m; a crank-rocker (200 + 600 <= 400 + 500)
BM, DE = 0.3, 0.25  # M on BC 300 mm from B (its middle), E on DC 250 mm from D

SCENE = """
title = "Four-bar with loads stated against its links"
units = "mm"

[ground]
A = [0, 0]
D = [500, 0]

[links]
AB = 200
BC = 600
CD = 400

[points]
M = {{ on = "BC", along = 300 }}
E = {{ on = "DC", along = 250 }}

[assembly]
C = "above"

[input]
crank = "AB"
angle = {angle}
speed = "1 rad/s ccw"

[masses]

[loads]
M = {{ force = "500 N", direction = {m} }}
E = {{ force = "200 N", direction = {e} }}
"""


def _scene(m, e, angle=60):
    return parse_scene(SCENE.format(m=m, e=e, angle=angle), file="links.toml")


def _positions(theta):
    """A, B, C, D, M, E (m) in closed form: C where the circles about B (BC) and D (CD)
    cross, on the side that puts C above AD at 60 deg (a crank-rocker's dyad keeps it)."""
    A, D = np.array([0.0, 0.0]), np.array([AD, 0.0])
    B = AB * np.array([math.cos(theta), math.sin(theta)])
    d = float(np.linalg.norm(D - B))
    u = (D - B) / d
    a = (BC**2 - CD**2 + d * d) / (2 * d)
    h = math.sqrt(BC**2 - a * a)
    C = B + a * u + h * np.array([-u[1], u[0]]) * _SIDE
    return A, B, C, D, B + BM / BC * (C - B), D + DE / CD * (C - D)


_SIDE = 1.0  # fixed below: the side of BD that C is on at 60 deg with C above AD


def _pick_side():
    global _SIDE
    for s in (1.0, -1.0):
        _SIDE = s
        if _positions(math.pi / 3)[2][1] > 0:
            return


_pick_side()


def _unit(p, q, turn_deg):
    """The direction p -> q turned by ``turn_deg`` (ccw positive), by hand."""
    ang = math.atan2(q[1] - p[1], q[0] - p[0]) + math.radians(turn_deg)
    return np.array([math.cos(ang), math.sin(ang)])


def _cross(r, f):
    return r[0] * f[1] - r[1] * f[0]


def _newton_euler(theta, load_m, load_e):
    """The torque on AB (ccw positive) holding the loads ``P_M``, ``P_E`` (N vectors), by
    the three bodies' equilibrium as one 9 x 9 linear system: unknowns F_A (frame on AB),
    F_B (AB on BC), F_C (BC on CD), F_D (frame on CD), T."""
    A, B, C, D, M, E = _positions(theta)
    K, rhs = np.zeros((9, 9)), np.zeros(9)
    # AB: F_A - F_B = 0; (B - A) x (-F_B) + T = 0
    K[0, 0], K[0, 2] = 1, -1
    K[1, 1], K[1, 3] = 1, -1
    K[2, 2], K[2, 3], K[2, 8] = (B - A)[1], -(B - A)[0], 1
    # BC: F_B - F_C + P_M = 0; (C - B) x (-F_C) + (M - B) x P_M = 0
    K[3, 2], K[3, 4], rhs[3] = 1, -1, -load_m[0]
    K[4, 3], K[4, 5], rhs[4] = 1, -1, -load_m[1]
    K[5, 4], K[5, 5], rhs[5] = (C - B)[1], -(C - B)[0], -_cross(M - B, load_m)
    # CD: F_C + F_D + P_E = 0; (C - D) x F_C + (E - D) x P_E = 0
    K[6, 4], K[6, 6], rhs[6] = 1, 1, -load_e[0]
    K[7, 5], K[7, 7], rhs[7] = 1, 1, -load_e[1]
    K[8, 4], K[8, 5], rhs[8] = -(C - D)[1], (C - D)[0], -_cross(E - D, load_e)
    return np.linalg.solve(K, rhs)


CASES = [  # (M's words, E's words, M's load by hand, E's load by hand) at theta
    (
        '"perpendicular to BC, ccw"',
        '"30 deg ccw from CD"',
        lambda B, C, D: 500 * _unit(B, C, 90),
        lambda B, C, D: 200 * _unit(C, D, 30),
    ),
    (
        '"at 30 deg to BC, cw"',
        '"along DC"',
        lambda B, C, D: 500 * _unit(B, C, -30),
        lambda B, C, D: 200 * _unit(D, C, 0),
    ),
    (
        '"at right angles to CB, clockwise"',
        '"perpendicular to DC, ccw"',
        lambda B, C, D: 500 * _unit(C, B, -90),
        lambda B, C, D: 200 * _unit(D, C, 90),
    ),
]


@pytest.mark.parametrize("m,e,pm,pe", CASES)
def test_the_torque_by_virtual_power_is_newton_eulers(m, e, pm, pe):
    theta = math.radians(60)
    _, B, C, D, _, _ = _positions(theta)
    want = _newton_euler(theta, pm(B, C, D), pe(B, C, D))
    sol = solve(_scene(m, e))
    assert np.allclose([sol.P[k] for k in "BC"], [B, C], rtol=0, atol=1e-12)
    assert sol.input_torque == pytest.approx(want[8], rel=1e-9)
    assert sol.forces.input_torque == pytest.approx(want[8], rel=1e-9)
    got = {p.point: p.magnitude for p in sol.forces.pins}
    for k, (i, j) in zip("ABCD", ((0, 1), (2, 3), (4, 5), (6, 7))):
        assert got[k] == pytest.approx(math.hypot(want[i], want[j]), rel=1e-9)


def test_stated_numerically_it_gives_the_same_numbers():
    """The angle at the instant written as a plain number (by hand from the closed-form
    positions) gives the same torque, pin forces and printed solution."""
    _, B, C, D, _, _ = _positions(math.radians(60))
    dm = math.degrees(math.atan2(*(_unit(B, C, 90)[::-1]))) % 360
    de = math.degrees(math.atan2(*(_unit(C, D, 30)[::-1]))) % 360
    turned = solve(_scene('"perpendicular to BC, ccw"', '"30 deg ccw from CD"'))
    plain = solve(_scene(repr(dm), repr(de)))
    assert turned.input_torque == pytest.approx(plain.input_torque, rel=1e-12)
    a = {p.point: p.magnitude for p in turned.forces.pins}
    b = {p.point: p.magnitude for p in plain.forces.pins}
    assert a.keys() == b.keys()
    for k in a:
        assert a[k] == pytest.approx(b[k], rel=1e-12)
    for ld, want in zip(turned.scene.loads, (dm, de)):
        assert math.degrees(math.atan2(ld.force[1], ld.force[0])) % 360 == pytest.approx(
            want, abs=1e-10
        )


def test_a_sweep_turns_the_load_with_the_link_at_every_angle():
    degs = [0, 45, 100, 170, 230, 300]
    res = sweep(_scene('"perpendicular to BC, ccw"', '"30 deg ccw from CD"'), np.radians(degs))
    cols = {k: v for k, _, v in res.columns()}
    assert len(cols["torque"]) == len(degs)
    for i, d in enumerate(degs):
        th = math.radians(d)
        _, B, C, D, _, _ = _positions(th)
        want = _newton_euler(th, 500 * _unit(B, C, 90), 200 * _unit(C, D, 30))[8]
        assert cols["torque"][i] == pytest.approx(want, rel=1e-9)
        assert cols["torque_inertia"][i] == pytest.approx(want, rel=1e-9)


def test_the_words_say_it_as_stated_and_its_angle_now():
    _, B, C, _, _, _ = _positions(math.radians(60))
    deg = math.degrees(math.atan2(*(_unit(B, C, 90)[::-1]))) % 360
    sol = solve(_scene('"perpendicular to BC, ccw"', '"along DC"'))
    said = f"500 N perpendicular to BC, ccw (at {fmt(deg)} deg now)"
    assert any(said in n for n in sol.scene.reading_notes)


def test_perpendicular_without_its_sense_is_refused_saying_where_each_points(capsys):
    _, B, C, _, _, _ = _positions(math.radians(60))
    ccw = math.degrees(math.atan2(*(_unit(B, C, 90)[::-1]))) % 360
    cw = (ccw + 180) % 360
    sc = _scene('"perpendicular to BC"', '"along DC"')
    with pytest.raises(SceneError) as exc:
        solve(sc)
    msg = str(exc.value)
    assert "\n" not in msg and "[loads] M" in msg and "', ccw' or ', cw'" in msg
    assert "ccw: " in msg and f"at {ccw:.1f} deg" in msg and f"at {cw:.1f} deg" in msg


@pytest.mark.parametrize(
    "words,says",
    [
        ('"30 deg to BC"', "does not say which side of BC"),
        ('"along CE"', "no link CE in [links]"),
        ('"30 deg cw from BC, ccw"', "gives two senses"),
        ('"along the link"', "as a direction against a link"),
    ],
)
def test_refusals_in_one_line(words, says):
    with pytest.raises(SceneError) as exc:
        _scene(words, '"along DC"')
    msg = str(exc.value)
    assert "\n" not in msg and "[loads] M" in msg and says in msg


def test_the_cli_refuses_with_exit_code_two(tmp_path, capsys):
    f = tmp_path / "s.toml"
    f.write_text(SCENE.format(m='"perpendicular to BC"', e='"along DC"', angle=60))
    for cmd in ("solve", "sweep"):
        assert main([cmd, str(f)]) == 2
        err = capsys.readouterr().err.strip()
        assert "\n" not in err and "', ccw' or ', cw'" in err


def test_the_free_bodies_over_a_sweep_turn_the_load_too():
    """The free bodies' load (the force polygons', the page's arrows) at every angle."""
    degs = [10, 95, 250]
    res = sweep(_scene('"perpendicular to BC, ccw"', '"30 deg ccw from CD"'), np.radians(degs))
    f = res._forces()
    sides = [s for fb in f.free for s in fb.sides if s.what == "load" and s.point == "M"]
    assert len(sides) == 1
    fx, fy = (np.broadcast_to(c, (len(degs),)) for c in sides[0].vector)
    for i, d in enumerate(degs):
        _, B, C, _, _, _ = _positions(math.radians(d))
        assert np.allclose((fx[i], fy[i]), 500 * _unit(B, C, 90), rtol=1e-12, atol=1e-9)


def test_a_line_of_the_frame_is_read_too():
    """Two ground points make a fixed line: "perpendicular to AD, ccw" is straight up
    (exactly), "30 deg from AD, ccw" the plain 30 deg (AD along +x)."""
    up = solve(_scene('"perpendicular to AD, ccw"', '"30 deg from AD, ccw"'))
    assert up.scene.loads[0].force == (0.0, 500.0)
    plain = solve(_scene("90", "30"))
    assert up.input_torque == pytest.approx(plain.input_torque, rel=1e-12)
    assert any("along a line of the frame" in n for n in up.scene.reading_notes)


def test_the_torques_error_bound_holds_the_directions_error():
    """A direction from the positions carries their error: the input torque's bound is
    larger than with the same angle stated as a number (given exactly), and still tiny."""
    _, B, C, D, _, _ = _positions(math.radians(60))
    dm = math.degrees(math.atan2(*(_unit(B, C, 90)[::-1]))) % 360
    de = math.degrees(math.atan2(*(_unit(C, D, 30)[::-1]))) % 360
    turned = solve(_scene('"perpendicular to BC, ccw"', '"30 deg ccw from CD"'))
    plain = solve(_scene(repr(dm), repr(de)))
    a = turned.error_bounds.torque(turned.scene)
    b = plain.error_bounds.torque(plain.scene)
    assert b < a < 1e-10


@pytest.mark.parametrize(
    "words,first,second,turn",
    [
        ("Along CD", "C", "D", 0),
        ("parallel to DC", "D", "C", 0),
        ("normal to CD (ccw)", "C", "D", 90),
        ("square to CD, cw", "C", "D", -90),
        ("Perpendicular to BC, anti-clockwise", "B", "C", 90),
        ("30° cw from CD", "C", "D", -30),
        ("at 30 deg with CD, counter-clockwise", "C", "D", 30),
    ],
)
def test_the_words_a_book_uses(words, first, second, turn):
    from polygon_method.scene.link_loads import read_across
    from polygon_method.scene.names import split_name

    a, b, off, said = read_across(words, split_name)
    assert (a, b, said) == (first, second, words)
    assert math.degrees(off) == pytest.approx(turn, abs=1e-12)
