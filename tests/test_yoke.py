"""The Scotch yoke (``Y = { path = ... }`` and ``P = { along = "block Y", direction = ...
}``): against the closed form x = r cos(theta), and its refusals."""

from __future__ import annotations

import math

import pytest

from polygon_method import parse_scene, solve
from polygon_method.cli import main
from polygon_method.solver.compiler import gruebler

YOKE = """
[ground]
O = [0, 0]
[links]
OP = 80
[sliders]
Y = {{ path = "horizontal" }}
P = {{ along = "block Y", direction = "vertical" }}
[input]
crank = "OP"
angle = {angle}
speed = "{w} rad/s ccw"
acceleration = "{al}"
"""


@pytest.mark.parametrize("angle", [0, 35, 90, 140, 180, 222, 270, 333])
def test_the_yoke_moves_as_r_cos_theta(angle):
    """x = r cos th, v = -r w sin th, a = -r (al sin th + w^2 cos th); the pin relative to
    the yoke: y = r sin th, its sliding velocity r w cos th and acceleration r (al cos th
    - w^2 sin th). Nothing turns: no Coriolis component."""
    r, w, al = 0.08, 25.0, -40.0
    sol = solve(parse_scene(YOKE.format(angle=angle, w=w, al="40 rad/s^2 cw")))
    th = math.radians(angle)
    c, s = math.cos(th), math.sin(th)
    vscale, ascale = r * abs(w), r * (w * w + abs(al))
    assert sol.P["Y"] == pytest.approx((r * c, 0.0), abs=1e-12)
    assert sol.V["Y"][0] == pytest.approx(-r * w * s, abs=1e-12 * vscale)
    assert sol.A["Y"][0] == pytest.approx(-r * (al * s + w * w * c), abs=1e-12 * ascale)
    assert sol.S["Y"][:2] == pytest.approx(
        [-r * w * s, -r * (al * s + w * w * c)], abs=1e-12 * ascale
    )
    assert sol.S["P"][0] == pytest.approx(r * w * c, abs=1e-12 * vscale)
    assert sol.S["P"][1] == pytest.approx(r * (al * c - w * w * s), abs=1e-12 * ascale)
    assert sol.coriolis("P") == (0.0, 0.0) and sol.coriolis("Y") == (0.0, 0.0)


def test_gruebler_counts_the_yoke_and_the_pins_block():
    # crank, the block at P, the yoke: n = 4; the pivot, the pin, two sliding pairs: j = 4
    assert gruebler(parse_scene(YOKE.format(angle=40, w=10, al="0 rad/s^2"))) == 1


def test_every_view_takes_the_yoke(tmp_path, capsys):
    scene = tmp_path / "yoke.toml"
    scene.write_text(YOKE.format(angle=40, w=10, al="0 rad/s^2"), encoding="utf-8")
    for args in (
        ["solve", "--json", str(scene)],
        ["steps", str(scene)],
        ["centres", str(scene)],
        ["sweep", "--summary", str(scene)],
        ["linkage", str(scene)],
        ["draw", str(scene), "-o", str(tmp_path / "y.svg"), "--paper", "A3"],
        ["page", str(scene), "-o", str(tmp_path / "y.html")],
    ):
        assert main(args) == 0, args
    out = " ".join(capsys.readouterr().out.split())
    assert "through p, one parallel to its slot (vertical)" in out
    assert "stroke 160 mm" in out  # twice the crank
    assert "I13 at infinity" in out  # the pin's block translates with the yoke
    assert 'id="yoke-Y"' in (tmp_path / "y.svg").read_text(encoding="utf-8")
