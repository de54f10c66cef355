"""Static friction where nothing slides yet: the effort to start the motion. A textbook
states it "find the torque needed to start the crank turning anticlockwise against the load;
the coefficient of static friction at the guide is 0.3": at rest (`speed = "0 rad/s ccw"`,
the sense the motion is to start in) with ``[friction]``, the friction is limiting, mu |N|
against the impending sliding. Held to a slider crank's statics solved by hand: the rod a
two-force member, the piston's balance with the friction against its impending motion, the
crank's moments; with the impending sense reversed the friction turns round.
"""

from __future__ import annotations

import math

import pytest

from polygon_method.motion.solution import solve
from polygon_method.scene import parse_scene

START = """
title = "slider crank at rest: the torque to start it"
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 150
AB = 600
[sliders]
B = { path = "horizontal", through = "O" }
[assembly]
B = "right"
[input]
crank = "OA"
angle = 60
speed = "0 rad/s ccw"
[masses]
[loads]
B = { force = [-1000, 0] }
[friction]
guides = 0.3
"""


def _by_hand(theta, mu, way):
    """(T, N, the rod's force): the piston's balance along and across the guide, the rod
    pushing it along e = (B - A)/l with f, the load -1000 N along x, the guide's push N
    across and the friction mu |N| along x against the piston's impending motion (``way``:
    the sign of its velocity along x); the crank's moments about O, T = A x (f e)."""
    r, l = 0.15, 0.6
    A = (r * math.cos(theta), r * math.sin(theta))
    B = (A[0] + math.sqrt(l * l - A[1] ** 2), 0.0)
    e = ((B[0] - A[0]) / l, (B[1] - A[1]) / l)
    # f e_x - 1000 - way mu |f e_y| = 0, with f > 0 (the rod pushes the piston)
    f = 1000 / (e[0] - way * mu * abs(e[1]))
    assert f > 0
    N = -f * e[1]
    return f * (A[0] * e[1] - A[1] * e[0]), N, f


@pytest.mark.parametrize("sense, way", [("ccw", -1.0), ("cw", 1.0)])
def test_the_torque_to_start_a_slider_crank_against_its_guides_static_friction(sense, way):
    """At 60 deg turning ccw the piston moves towards the crank (its velocity along -x), so
    the friction on it acts along +x; cw, the reverse."""
    sc = parse_scene(START.replace("0 rad/s ccw", f"0 rad/s {sense}"))
    assert sc.at_rest
    sol = solve(sc)
    vB = sol.V["B"][0]
    assert math.copysign(1.0, vB) == way  # the impending motion's sense, per rad/s
    f = sol.forces
    T, N, rod = _by_hand(math.radians(60), 0.3, way)
    assert abs(f.input_torque - T) <= 1e-9 * abs(T)
    (g,) = f.guides
    assert abs(g.normal * g.n[1] - N) <= 1e-9 * rod
    (fr,) = [it for it in f.friction if it[0] == "block B"]
    assert abs(fr[2][0] - (-way) * 0.3 * abs(N)) <= 1e-9 * rod  # against the motion
    held, _, _ = _by_hand(math.radians(60), 0.0, way)  # frictionless: to hold it
    # against the load (cw: the piston pushed out) starting takes more than holding; with
    # it (ccw: the load drives), the friction helps the driver hold back
    assert (abs(f.input_torque) > abs(held)) == (way > 0)
    assert f.friction_power < 0  # (virtual, per rad/s: against the motion about to start)


def test_the_words_say_the_friction_is_static_and_limiting(capsys, tmp_path):
    from polygon_method.cli import main

    path = tmp_path / "start.toml"
    path.write_text(START)
    assert main(["solve", str(path)]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "at rest, about to turn ccw" in out
    assert "limiting static friction" in out
