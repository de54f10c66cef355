"""A four-bar whose rocker's speed is given steady (``omega_CD``, a rocker as the input):
the crank's speed and acceleration grow without bound towards the rocker's limit positions
(crank and coupler in line), where the crank is asked for tens of thousands of rad/s^2 by
a rocker turning at 3 rad/s. That is right, and the output says why: the condition of the
input, with the crank's speed growing as 1 / c and its acceleration as 1 / c^3.

The reference is independent of the tool: the rocker's angle in closed form as a function
of the crank's at 30 digits (mpmath), differentiated in time with the rocker's angle as the
input: ``omega_4 = theta_4' omega_2`` gives ``omega_2``, ``0 = alpha_4 = theta_4''
omega_2^2 + theta_4' alpha_2`` gives ``alpha_2``.
"""

from __future__ import annotations

import json
import math

import mpmath
import pytest

from polygon_method.cli import main
from polygon_method.motion.solution import solve
from polygon_method.scene import parse_scene

SCENE = """
title = "a four-bar driven by its rocker"
units = "in"
[ground]
A = [0, 0]
D = [14, 0]
[links]
AB = 4
BC = 12
CD = 9
[assembly]
C = "above"
[input]
crank = "AB"
angle = ANGLE
omega_CD = "3 rad/s cw"
"""


def reference(deg):
    """(omega_AB, alpha_AB, theta_4' the rocker's rate per rad/s of the crank), rad/s ccw."""
    with mpmath.workdps(30):

        def th4(t):
            bx, by = 4 * mpmath.cos(t), 4 * mpmath.sin(t)
            dx, dy = 14 - bx, -by
            d = mpmath.hypot(dx, dy)
            a = (144 - 81 + d**2) / (2 * d)  # from B along B -> D
            h = mpmath.sqrt(144 - a**2)
            cx, cy = bx + a * dx / d - h * dy / d, by + a * dy / d + h * dx / d  # C above
            return mpmath.atan2(cy, cx - 14)

        t = mpmath.radians(deg)
        d1, d2 = mpmath.diff(th4, t, 1), mpmath.diff(th4, t, 2)
        w2 = -3 / d1
        return float(w2), float(-d2 * w2**2 / d1), float(d1)


def limit_angle():
    """The crank's angle (deg) at the rocker's limit: crank and coupler in line, |AC| = 16."""
    return math.degrees(math.acos((16**2 + 14**2 - 9**2) / (2 * 16 * 14)))


@pytest.mark.parametrize("deg", [25.0, 28.5, 30.0, 33.0, 60.0, 150.0])
def test_the_crank_asked_by_a_steady_rocker(deg):
    sol = solve(parse_scene(SCENE.replace("ANGLE", str(deg))))
    w, a, d1 = reference(deg)
    assert sol.W["AB"] == pytest.approx(w, rel=1e-9)
    assert sol.Al["AB"] == pytest.approx(a, rel=1e-9)
    assert sol.plan.given.condition == pytest.approx(min(abs(d1), 1.0), rel=1e-9)


def test_near_the_limit_it_is_large_and_says_why(tmp_path, capsys):
    """28.5 deg, 5.6 deg short of the rocker's limit at 34.1 deg: the crank at about 20,000
    rad/s^2 for a rocker turning steadily at 3 rad/s; every view states the condition."""
    assert limit_angle() == pytest.approx(34.09, abs=0.01)
    _, a, d1 = reference(28.5)
    assert 15000 < a < 30000
    scene = tmp_path / "rocker.toml"
    scene.write_text(SCENE.replace("ANGLE", "28.5"))
    assert main(["solve", str(scene)]) == 0
    out = " ".join(capsys.readouterr().out.split())
    c = f"{abs(d1):.3g}"
    assert f"condition {c} of this input" in out
    assert "its acceleration as 1 / c^3 towards it" in out
    assert f"near a dead centre for this input (condition {c})" in out
    assert main(["steps", str(scene)]) == 0
    steps = " ".join(capsys.readouterr().out.split())
    assert f"condition {c} of this input" in steps and "1 / c^3" in steps
    assert main(["solve", "--json", str(scene)]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["input"]["given"]["condition"] == pytest.approx(abs(d1), rel=1e-9)
    assert any("1 / c^3" in n for n in d["notes"])
