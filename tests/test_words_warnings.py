"""Words a teacher would write, and warnings that say why: a path "at 30 deg" named as a
teacher names it, a triangle with a fixed corner named by its own letters, a point on a
fixed pivot or on the frame, lengths in metres that look like millimetres; `linkage`
says where positions along a path are measured from, and the sweep's extreme place of a
slider at a limit position is the one `linkage` gives (and the closed form)."""

import math
import re
from pathlib import Path

import pytest

from polygon_method import load_scene, parse_scene, solve
from polygon_method.cli import main

ROOT = Path(__file__).resolve().parent.parent
SCENES = sorted((ROOT / "worked_problems").glob("*.toml")) + sorted(
    (ROOT / "tests" / "textbook").glob("*.toml")
)


def out_of(capsys, *argv):
    assert main(list(map(str, argv))) == 0
    return capsys.readouterr().out


@pytest.mark.parametrize(
    "path",
    [p for p in SCENES if "deg" in p.read_text() or "slot" in p.read_text()],
    ids=lambda p: p.stem,
)
def test_no_path_is_the_at_30_deg_path(path, capsys):
    text = out_of(capsys, "steps", path) + out_of(capsys, "solve", path)
    assert not re.search(r"\b(the|a|its) at -?\d", text), re.findall(r".{30}\bat -?\d.{20}", text)


def test_a_path_at_an_angle_is_named_as_a_teacher_names_it(capsys):
    text = out_of(capsys, "steps", ROOT / "tests" / "textbook" / "inclined_slider.toml")
    assert "along the path at 30 deg" in text and "on a path at 30 deg through" in text


def test_a_triangle_with_a_fixed_corner_keeps_its_letters(capsys):
    """G on CD with D fixed: triangle cdg, d at the pole o (not "triangle cog")."""
    text = " ".join(
        out_of(capsys, "steps", ROOT / "worked_problems" / "fourbar_image_points.toml").split()
    )
    assert "triangle cdg (d at the pole o) similar to CDG" in text
    assert "triangle cog" not in text and "triangle c'o'g'" not in text


FOURBAR = """
[ground]
A = [0, 0]
D = [100, 0]
[links]
AB = 50
BC = 66
CD = 56
{extra_link}
[points]
{points}
[assembly]
C = "above"
[input]
crank = "AB"
angle = 60
speed = "10.5 rad/s cw"
"""


def test_a_point_on_a_fixed_pivot_is_warned_about():
    sol = solve(
        parse_scene(
            FOURBAR.format(extra_link="", points='E = { on = "AB", from = "A", along = 0 }')
        )
    )
    assert sol.speed("E") == 0.0
    assert any(
        "E is placed on the fixed pivot A" in w and "does not move" in w for w in sol.warnings
    ), sol.warnings


def test_a_point_on_the_frame_is_warned_about():
    sol = solve(
        parse_scene(
            FOURBAR.format(
                extra_link="AD = 100", points='F = { on = "AD", from = "A", along = 30 }'
            )
        )
    )
    assert sol.speed("F") == 0.0
    assert any("F is on link AD, whose ends are both fixed" in w for w in sol.warnings)


def test_no_structural_warning_for_the_worked_problems():
    for path in SCENES:
        sol = solve(load_scene(path))
        assert not any(
            "fixed pivot" in w or "sits on the frame" in w or "units =" in w for w in sol.warnings
        ), (path.stem, sol.warnings)


def test_lengths_in_metres_that_look_like_millimetres_are_warned_about(capsys):
    """A 150 m crank at 300 rpm (its pin at 4712 m/s): said, with the way out; the same
    engine in mm, and an engine given in metres (0.1 m crank), are not."""
    text = (ROOT / "worked_problems" / "slider_crank_midpoint.toml").read_text()
    metres = re.sub(r'^units = "mm"', 'units = "m"', text, flags=re.M)
    assert metres != text
    sol = solve(parse_scene(metres))
    pin = 300 * 2 * math.pi / 60 * 150
    hit = [w for w in sol.warnings if 'units = "m"' in w]
    assert hit and f"{pin:.4g} m/s" in hit[0] and 'write units = "mm"' in hit[0]
    assert not any("units" in w for w in solve(parse_scene(text)).warnings)


def test_linkage_says_where_along_the_path_is_measured_from(capsys):
    text = out_of(capsys, "linkage", ROOT / "worked_problems" / "offset_slider_crank.toml")
    scene = load_scene(ROOT / "worked_problems" / "offset_slider_crank.toml")
    qx, qy = (c / scene.length_unit for c in scene.slider("B").through)
    assert f"measured from ({qx:g}, {qy:g}) mm, + to the right" in text


def _two_slider_limit_place():
    """The two-slider problem (crank 300 at O, AB 1200 with B on the x axis, C on AB 450
    from B, CD 450 with D on the vertical line x = 1040): at the crank's limit position CD
    is horizontal, so C is at x = 590 and D at C's height. Bisection on the crank angle
    between -90 and -150 deg for C_x = 590; returns D's height (mm)."""

    def cx(t):
        ax, ay = 300 * math.cos(t), 300 * math.sin(t)
        bx = ax + math.sqrt(1200**2 - ay**2)
        return bx + 450 / 1200 * (ax - bx), 450 / 1200 * ay

    lo, hi = math.radians(-150), math.radians(-90)
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if (cx(mid)[0] - 590) * (cx(lo)[0] - 590) > 0:
            lo = mid
        else:
            hi = mid
    return cx(0.5 * (lo + hi))[1]


def test_the_sweep_and_linkage_give_one_stroke(capsys):
    """Where the crank rocks, the slider's extreme place is at the crank's limit position:
    the sweep's summary and `linkage` both give it, as the closed form does."""
    path = ROOT / "worked_problems" / "two_slider_mechanism.toml"
    want = _two_slider_limit_place()  # about -99.19 mm
    sweep = out_of(capsys, "sweep", path)
    row = next(ln for ln in sweep.splitlines() if ln.startswith("s_D "))
    low = float(row.split()[4])
    assert low * 1e3 == pytest.approx(want, rel=1e-5)
    link = out_of(capsys, "linkage", path)
    got = float(re.search(r"slider D: moves between (-?[\d.]+) mm", link).group(1))
    assert got == pytest.approx(want, rel=1e-5)


def test_the_pivots_near_a_point_are_those_every_pivot_tried_finds():
    """The pivots within a distance of each point, looked up in cells (linear in the scene's
    size), are those found by trying every pivot (in the ground's order): points on a pivot,
    a hair inside and outside the distance, on cell edges, far off and not finite."""
    import random

    from polygon_method.motion.structural import _ground_near

    rng = random.Random(7)
    lim = 1e-9
    ground = {f"G{i}": (rng.uniform(-1, 1), rng.uniform(-1, 1)) for i in range(40)}
    ground["twin"] = ground["G3"]  # two pivots at one place: both, in order
    ground["edge"] = (2 * lim * 5, -2 * lim * 7)  # on a cell's corner
    ground["huge"] = (1e300, 0.0)  # beyond a cell's range: tried by every point
    P = {}
    for n, (G, (gx, gy)) in enumerate(ground.items()):
        for k, d in enumerate((0.0, 0.999 * lim, 1.001 * lim, 0.5 * lim, 3 * lim)):
            a = rng.uniform(0, 2 * math.pi)
            P[f"X{n}_{k}"] = (gx + d * math.cos(a), gy + d * math.sin(a))
    P["far"] = (1e305, -1e305)
    P["inf"] = (math.inf, 0.0)
    P["nan"] = (math.nan, 0.0)
    near = _ground_near(ground, P, lim)
    found = 0
    for X, (x, y) in P.items():
        every = [(G, g) for G, g in ground.items() if not math.hypot(x - g[0], y - g[1]) > lim]
        assert near(X) == every, X
        found += bool(every)
    assert found >= 2 * len(ground)  # the cases near a pivot were generated
