"""The position given otherwise than by the crank's angle ([input] length_OR, s_B,
angle_CD): the crank angle found, against closed forms (the law of cosines, the slider
crank's and the four-bar's circle intersections), and the refusals."""

import math

import pytest

from polygon_method import solve
from polygon_method.cli import main
from polygon_method.scene import parse_scene
from scenes import seed

SLIDER = """
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 150
AB = 600
[sliders]
B = {{ path = "horizontal" }}
[input]
crank = "OA"
{pos}
speed = "10 rad/s ccw"
"""

FOURBAR = seed(
    top='units = "mm"\n', middle='[assembly]\nC = "above"\n', drive='{pos}\nspeed = "10.5 rad/s cw"'
)

TIPPER = """
units = "mm"
[ground]
Q = [0, 0]
O = [-1500, -300]
[links]
QR = 800
[cylinders]
"O-R" = {{}}
[input]
crank = "QR"
{pos}
vs_OR = "0.1 m/s extending"
"""


@pytest.mark.parametrize("x, near", [(700, 30), (700, -30), (500, 150), (740, None)])
def test_piston_place(x, near):
    """x = r cos t + sqrt(l^2 - r^2 sin^2 t): cos t = (x^2 + r^2 - l^2) / (2 x r)."""
    pos = f"s_B = {x}" + (f"\nnear = {near}" if near is not None else "")
    sol = solve(parse_scene(SLIDER.format(pos=pos)))
    r, l, xm = 0.15, 0.6, x / 1000
    t = math.acos((xm * xm + r * r - l * l) / (2 * xm * r))
    want = t if near is None or near > 0 else -t
    got = sol.scene.input.angle
    assert abs(math.remainder(got - want, 2 * math.pi)) < 1e-12
    assert abs(sol.P["B"][0] - xm) < 1e-14
    if near is None:
        assert any("set near" in n for n in sol.notes)


@pytest.mark.parametrize("phi", (100, 120, 140))
def test_rocker_angle(phi):
    """C = D + CD (cos phi, sin phi); B on the circles about A (AB) and C (BC), the
    branch whose crank angle is nearest near; t = atan2(B - A)."""
    sol = solve(parse_scene(FOURBAR.format(pos=f"angle_DC = {phi}\nnear = 60")))
    cx = 0.1 + 0.056 * math.cos(math.radians(phi))
    cy = 0.056 * math.sin(math.radians(phi))
    d = math.hypot(cx, cy)
    a = (0.05**2 - 0.066**2 + d * d) / (2 * d)
    h = math.sqrt(0.05**2 - a * a)
    ex, ey = cx / d, cy / d
    cands = [math.atan2(a * ey + s * h * ex, a * ex - s * h * ey) for s in (1, -1)]
    want = min(cands, key=lambda t: abs(math.remainder(t - math.radians(60), 2 * math.pi)))
    assert abs(math.remainder(sol.scene.input.angle - want, 2 * math.pi)) < 1e-11
    D, C = sol.P["D"], sol.P["C"]
    assert abs(math.atan2(C[1] - D[1], C[0] - D[0]) - math.radians(phi)) < 1e-11


@pytest.mark.parametrize("L", (1000, 1200, 1500))
def test_cylinder_length(L):
    """|R - O| = L with R = 0.8 (cos t, sin t): cos(t - psi) = (r^2 + s^2 - L^2) / 2rs."""
    sol = solve(parse_scene(TIPPER.format(pos=f"length_OR = {L}\nnear = 150")))
    r, s, psi = 0.8, math.hypot(1.5, 0.3), math.atan2(-0.3, -1.5)
    c = (r * r + s * s - (L / 1000) ** 2) / (2 * r * s)
    cands = [psi + k * math.acos(c) for k in (1, -1)]
    want = min(cands, key=lambda t: abs(math.remainder(t - math.radians(150), 2 * math.pi)))
    assert abs(math.remainder(sol.scene.input.angle - want, 2 * math.pi)) < 1e-11
    assert abs(sol.cylinder_length("O-R") - L / 1000) < 1e-13
    assert abs(sol.sliding_velocity("O-R") - 0.1) < 1e-12


BAD = [
    (TIPPER, "length_OR = 3000", "no angle of the crank"),
    (TIPPER, "length_OR = 1000\nangle = 30", "position twice"),
    (SLIDER, "angle = 30\nnear = 40", "near is a rough crank angle"),
    (SLIDER, "s_A = 300", "no slider A"),
    (FOURBAR, "angle_DX = 30", "two points of the scene"),
]


@pytest.mark.parametrize("scene, pos, words", BAD)
def test_refusals_one_line(tmp_path, capsys, scene, pos, words):
    f = tmp_path / "s.toml"
    f.write_text(scene.format(pos=pos))
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err and "[input]" in err, err


def test_views(tmp_path):
    f = tmp_path / "s.toml"
    f.write_text(TIPPER.format(pos="length_OR = 1200\nnear = 150"))
    for argv in (
        ["steps"],
        ["centres"],
        ["linkage"],
        ["draw", "-o", str(tmp_path / "d.svg")],
        ["sweep", "--steps", "36", "--summary"],
        ["page", "-o", str(tmp_path / "p.html")],
        ["solve", "--json"],
    ):
        assert main([argv[0], str(f), *argv[1:]]) == 0, argv
