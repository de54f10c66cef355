"""Friction near locking: a short slider crank (OA 80, AB 90 mm, 80 deg, 1.5 kN against the
block) with mu at the slide close to where it locks (mu = u_x / u_y of the rod's direction,
0.5523). The passes of the force walk shrink their change only slowly there (0.905 a pass
at mu 0.5): they go on while they settle, and the forces are the block's balance by hand
at 40 digits; past locking the tool says the mechanism locks (no forces balance it)."""

from __future__ import annotations

import mpmath
import pytest
from mpmath import mpf

from polygon_method import parse_scene, solve
from polygon_method.common.errors import PolygonMethodError

SCENE = """
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 80
AB = 90
[sliders]
B = { path = "horizontal" }
[input]
crank = "OA"
angle = 80
speed = "20 rad/s clockwise"
[masses]
[loads]
B = { force = "1.5 kN", direction = "to the left" }
[friction]
guides = MU
"""


def _by_hand(mu):
    """(the rod's thrust, the guide's normal force, the crank's torque, ccw +) from the
    block's balance: F u_x - P - mu N = 0 (the block slides to the right, friction to the
    left), N = F |u_y|; the rod a two-force member; the crank's torque A x F u."""
    mpmath.mp.dps = 40
    th = mpmath.radians(80)
    ax, ay = 80 * mpmath.cos(th) / 1000, 80 * mpmath.sin(th) / 1000
    bx = ax + mpmath.sqrt(mpf("0.09") ** 2 - ay**2)
    ux, uy = (bx - ax) / mpf("0.09"), -ay / mpf("0.09")  # from A to B
    F = mpf(1500) / (ux - mpf(mu) * -uy)
    return F, F * -uy, ax * F * uy - ay * F * ux


@pytest.mark.parametrize("mu", ["0.3", "0.5", "0.54", "0.55"])
def test_friction_near_locking_settles_to_the_blocks_balance(mu):
    sol = solve(parse_scene(SCENE.replace("MU", mu)))
    assert sol.S["B"][0] > 0  # the block slides to the right (friction to the left)
    F, N, T = _by_hand(mu)
    f = sol.forces
    (guide,) = f.guides
    pin_b = next(p for p in f.pins if p.point == "B")
    assert abs(guide.normal) == pytest.approx(float(N), rel=1e-9)
    assert pin_b.magnitude == pytest.approx(float(F), rel=1e-9)
    assert f.input_torque == pytest.approx(float(T), rel=1e-9)


@pytest.mark.parametrize("mu", ["0.56", "0.8"])
def test_friction_past_locking_says_the_mechanism_locks(mu):
    assert float(_by_hand(mu)[0]) < 0  # no compressive thrust balances the block
    with pytest.raises(PolygonMethodError, match="locks itself here") as exc:
        solve(parse_scene(SCENE.replace("MU", mu))).forces
    assert "\n" not in str(exc.value) and "[friction]" in str(exc.value)
