"""Two inputs, the second's speed given as a point's velocity (``v_X``) or a slider's
sliding velocity (``vs_X``), as books give it: both are linear in the two cranks' speeds,
so each is one row of the 2 x 2 solve. Checked against closed forms that import nothing
of the tool: the five-bar's C from its two circles and its velocity from the two rods'
constraints (C-B).(vC - vB) = 0, (C-D).(vC - vD) = 0; a block C on the turning rod ED
driven through BC, its sliding speed from (C-B).(vC - vB) = 0 with vC = s' u + s w2 n."""

from __future__ import annotations

import math
import subprocess
import sys

import numpy as np
import pytest

from polygon_method import parse_scene, solve
from polygon_method.common.errors import PolygonMethodError

FIVE_BAR = """
units = "mm"
[ground]
A = [0, 0]
E = [120, 0]
[links]
AB = 60
BC = 140
CD = 140
DE = 60
[assembly]
C = "above"
[input]
crank = "AB"
angle = 60
speed = "10 rad/s ccw"
[input.second]
crank = "ED"
angle = 120
{second}
"""


def _circles(p, r, q, s, up=True):
    """Where the circles about p (radius r) and q (radius s) cross, the upper one."""
    d = q - p
    L = float(np.hypot(*d))
    a = (r * r - s * s + L * L) / (2 * L)
    h = math.sqrt(r * r - a * a)
    u = d / L
    n = np.array([-u[1], u[0]])
    c1, c2 = p + a * u + h * n, p + a * u - h * n
    return c1 if (c1[1] > c2[1]) == up else c2


def _perp(v):
    return np.array([-v[1], v[0]])


def _five_bar(w1, w2, a1=0.0, a2=0.0):
    """C's position, velocity and acceleration, and omega_BC, by hand (m, SI)."""
    A, E = np.zeros(2), np.array([0.12, 0.0])
    t1, t2 = math.radians(60), math.radians(120)
    B = A + 0.06 * np.array([math.cos(t1), math.sin(t1)])
    D = E + 0.06 * np.array([math.cos(t2), math.sin(t2)])
    C = _circles(B, 0.14, D, 0.14)
    vB, vD = w1 * _perp(B - A), w2 * _perp(D - E)
    M = np.array([C - B, C - D])
    vC = np.linalg.solve(M, [np.dot(C - B, vB), np.dot(C - D, vD)])
    aB = a1 * _perp(B - A) - w1 * w1 * (B - A)
    aD = a2 * _perp(D - E) - w2 * w2 * (D - E)
    rhs = [
        np.dot(C - B, aB) - np.dot(vC - vB, vC - vB),
        np.dot(C - D, aD) - np.dot(vC - vD, vC - vD),
    ]
    aC = np.linalg.solve(M, rhs)
    r, v = C - B, vC - vB
    w_bc = float(r[0] * v[1] - r[1] * v[0]) / 0.14**2
    return C, vC, aC, w_bc


def _deg(v):
    return math.degrees(math.atan2(v[1], v[0])) % 360


def test_a_points_velocity_gives_the_second_cranks_speed():
    """C's speed along its true direction: the second crank's 5 rad/s cw found back."""
    _, vC, _, w_bc = _five_bar(10.0, -5.0)
    second = f'v_C = "{float(np.hypot(*vC))!r} m/s at {_deg(vC)!r} deg"'
    sol = solve(parse_scene(FIVE_BAR.format(second=second)))
    assert sol.omega("ED") == pytest.approx(-5.0, rel=1e-9)
    assert sol.omega("BC") == pytest.approx(w_bc, rel=1e-9)
    assert list(sol.V["C"]) == pytest.approx(list(vC), rel=1e-9, abs=1e-12)
    note = next(n for n in sol.notes if n.startswith("the two cranks' speeds are found"))
    assert "v_C" in note and "per rad/s of the crank AB" in note
    (found,) = sol.to_dict()["input"]["found_from"]
    assert found["direction"] == pytest.approx(list(vC / np.hypot(*vC)), rel=1e-12)
    assert not any("component along" in n and "deg from it" in n for n in sol.notes)


def test_its_rate_gives_the_second_cranks_acceleration():
    """v_C with its rate (the rate of C's speed, moving along the stated direction)."""
    _, vC, aC, _ = _five_bar(10.0, -5.0, 0.0, 30.0)
    d = vC / np.hypot(*vC)
    rate = float(np.dot(aC, d))
    text = f'v_C = "{float(np.hypot(*vC))!r} m/s at {_deg(vC)!r} deg"\na_C = "{rate!r} m/s^2"'
    sol = solve(parse_scene(FIVE_BAR.format(second=text)))
    assert sol.omega("ED") == pytest.approx(-5.0, rel=1e-9)
    assert sol.alpha("ED") == pytest.approx(30.0, rel=1e-9)
    assert sol.alpha("AB") == pytest.approx(0.0, abs=1e-9)


def test_a_direction_off_the_true_one_is_read_as_the_component_and_said():
    _, vC, _, _ = _five_bar(10.0, -5.0)
    ang = _deg(vC) + 12.0
    d = np.array([math.cos(math.radians(ang)), math.sin(math.radians(ang))])
    comp = float(np.dot(vC, d))
    sol = solve(parse_scene(FIVE_BAR.format(second=f'v_C = "{comp!r} m/s at {ang!r} deg"')))
    assert sol.omega("ED") == pytest.approx(-5.0, rel=1e-9)
    said = [n for n in sol.notes if "component along the stated direction" in n]
    assert said and "12 deg from it" in said[-1]


def test_a_direction_far_off_is_refused_in_one_line(tmp_path):
    _, vC, _, _ = _five_bar(10.0, -5.0)
    path = tmp_path / "s.toml"
    second = f'v_C = "0.1 m/s at {_deg(vC) + 80.0!r} deg"'
    path.write_text(FIVE_BAR.format(second=second))
    out = subprocess.run(
        [sys.executable, "-m", "polygon_method", "solve", str(path)],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 2 and "Traceback" not in out.stderr
    assert out.stderr.count("\n") == 1 and "[input.second] v_C" in out.stderr


SLOT = """
units = "mm"
[ground]
A = [0, 0]
E = [150, 0]
[links]
AB = 50
BC = 100
ED = 200
[sliders]
C = {{ along = "E-D" }}
[assembly]
C = [78, 124]
[input]
crank = "AB"
angle = 75
speed = "10 rad/s ccw"
[input.second]
crank = "ED"
angle = 120
{second}
"""


def _slot(w1, w2):
    """The block C on the rod ED (s from E along it) driven through BC: s and s'."""
    A, E = np.zeros(2), np.array([0.15, 0.0])
    B = 0.05 * np.array([math.cos(math.radians(75)), math.sin(math.radians(75))])
    u = np.array([math.cos(math.radians(120)), math.sin(math.radians(120))])
    # |E + s u - B| = 0.1: s^2 + 2 s (E - B).u + |E - B|^2 - 0.01 = 0, the far root
    b, c = np.dot(E - B, u), np.dot(E - B, E - B) - 0.01
    s = -b + math.sqrt(b * b - c)
    C = E + s * u
    vB = w1 * _perp(B - A)
    sdot = (np.dot(C - B, vB) - s * w2 * np.dot(C - B, _perp(u))) / np.dot(C - B, u)
    return s, float(sdot)


def test_a_sliders_sliding_speed_gives_the_second_cranks_speed():
    s, sdot = _slot(10.0, -4.0)
    sol = solve(parse_scene(SLOT.format(second=f'vs_C = "{sdot!r} m/s"')))
    assert math.hypot(*(np.array(sol.P["C"]) - np.array([0.15, 0.0]))) == pytest.approx(s)
    assert sol.omega("ED") == pytest.approx(-4.0, rel=1e-9)
    assert sol.sliding_velocity("C") == pytest.approx(sdot, rel=1e-9)
    note = next(n for n in sol.notes if n.startswith("the two cranks' speeds are found"))
    assert "vs_C" in note and "m/s per rad/s" in note and "condition" in note


def test_the_same_speeds_as_when_stated_and_in_the_json():
    _, sdot = _slot(10.0, -4.0)
    stated = solve(parse_scene(SLOT.format(second='speed = "4 rad/s cw"')))
    rate = stated.sliding_acceleration("C")  # the rate that holds the crank steady
    second = f'vs_C = "{sdot!r} m/s"\nas_C = "{rate!r} m/s^2"'
    given = solve(parse_scene(SLOT.format(second=second)))
    for k in ("AB", "BC", "ED"):
        assert given.omega(k) == pytest.approx(stated.omega(k), rel=1e-9)
        assert given.alpha(k) == pytest.approx(stated.alpha(k), rel=1e-9, abs=1e-9)
    found = given.to_dict()["input"]["found_from"]
    assert found[0]["key"] == "vs_C" and found[0]["value"] == pytest.approx(sdot)


def test_a_sliders_speed_that_cannot_tell_the_inputs_apart_is_refused():
    """Both inputs given as C's sliding speed: two parallel rows, refused with the
    condition (they cannot tell the two cranks apart)."""
    text = SLOT.format(second='vs_C = "1 m/s"').replace('speed = "10 rad/s ccw"', 'vs_C = "1 m/s"')
    with pytest.raises(PolygonMethodError) as exc:
        solve(parse_scene(text))
    assert "do not determine both inputs" in exc.value.message


def test_a_sweep_cannot_hold_a_sliders_speed_and_says_so(tmp_path):
    _, sdot = _slot(10.0, -4.0)
    path = tmp_path / "s.toml"
    path.write_text(SLOT.format(second=f'vs_C = "{sdot!r} m/s"'))
    out = subprocess.run(
        [sys.executable, "-m", "polygon_method", "sweep", str(path), "--steps", "8"],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 2 and "Traceback" not in out.stderr
    assert "held only at the stated instant" in out.stderr and "m/s or m/s^2" in out.stderr


def test_the_step_table_says_the_speeds_found_from_the_sliders(tmp_path):
    _, sdot = _slot(10.0, -4.0)
    path = tmp_path / "s.toml"
    path.write_text(SLOT.format(second=f'vs_C = "{sdot!r} m/s"'))
    out = subprocess.run(
        [sys.executable, "-m", "polygon_method", "steps", str(path)],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 0, out.stderr
    assert "vs_C" in out.stdout and "condition" in out.stdout
