"""The drawings look like the textbook on every scene (the worked problems, the textbook
corpus, and a few turned to other crank angles), measured on the SVG with shapely: the
crank angle's arc keeps off other pins and the fixed-pivot brackets, the circle diagram's
numbers sit on their own chords clear of each other and of the other chords."""

import math
import re
from pathlib import Path

import pytest
from shapely.geometry import LineString, Point, Polygon

from polygon_method import load_scene, parse_scene, solve
from polygon_method.draw import svg_string
from test_draw import CM, WORKED, Svg

ROOT = Path(__file__).resolve().parents[1]
TEXTBOOK = sorted(str(p) for p in (ROOT / "tests" / "textbook").glob("*.toml"))
SCENES = WORKED + TEXTBOOK


def _turned(path, degrees):
    """The scene at another crank angle (each listed angle assembles: a failure to is a
    failure of the test, not a skip)."""
    text = re.sub(r"(?m)^angle *=.*$", f"angle = {degrees}", Path(path).read_text())
    return solve(parse_scene(text))


TURNED = [
    (ROOT / "worked_problems" / "whitworth.toml", 270),
    (ROOT / "worked_problems" / "whitworth.toml", 0),
    (ROOT / "worked_problems" / "whitworth.toml", 225),
    (ROOT / "worked_problems" / "crank_slotted_lever.toml", 270),
    (ROOT / "tests" / "textbook" / "toggle_press.toml", 90),
]


def _restated(path, **lines):
    """The scene with its ``[input]`` lines (``angle``, ``speed``) stated otherwise."""
    text = Path(path).read_text()
    for key, words in lines.items():
        text, n = re.subn(rf"(?m)^{key} *=.*$", f"{key} = {words!r}".replace("'", '"'), text)
        assert n == 1, key
    return solve(parse_scene(text))


#: scenes stated otherwise: a short crank (an eccentric, 0.5 cm drawn) whose pivot's bracket
#: can only sit in the crank angle's sector (-130 deg: cw from the downward vertical)
RESTATED = [
    (
        ROOT / "tests" / "textbook" / "hunt5_hackworth_valve_gear.toml",
        {"angle": "40 deg from the downward vertical, cw", "speed": "240 rpm cw"},
    ),
]


def _solutions():
    """Every scene driven by a crank (a driving block has no crank angle to mark)."""
    for p in SCENES:
        if load_scene(p).input.crank is None:
            continue
        yield Path(p).stem, lambda p=p: solve(load_scene(p))
    for p, a in TURNED:
        yield f"{Path(p).stem}@{a}", lambda p=p, a=a: _turned(p, a)
    for p, lines in RESTATED:
        yield f"{Path(p).stem}@{lines['angle']}", lambda p=p, lines=lines: _restated(p, **lines)


CASES = list(_solutions())


@pytest.mark.parametrize("case", CASES, ids=[c[0] for c in CASES])
def test_the_crank_angle_keeps_off_other_pins_and_brackets(case):
    sol = case[1]()
    svg = Svg(svg_string(sol, "configuration"))
    turns = sol.scene.input.angle / (2 * math.pi)
    # the arc is drawn exactly when the crank is off its reference line
    assert ("crank-angle" in svg.groups) == (abs(turns - round(turns)) > 1e-12)
    if "crank-angle" not in svg.groups:
        return
    arc = LineString(svg.path("crank-angle"))
    pivot = sol.scene.input.pivot
    brackets = [
        g for g in svg.groups if g.startswith("ground-") and not g.endswith(("-base", "-hatch"))
    ]
    for g in brackets:
        tri = Polygon(svg.path(g)).buffer(0)
        base = LineString(svg.path(f"{g}-base"))
        if g == f"ground-{pivot}":  # its own bracket may meet the arc only at the pin
            tri = tri.difference(Point(svg.path(g)[0]).buffer(0.45 * CM))
        assert not arc.intersects(tri.union(base.buffer(0.5))), f"the arc crosses {g}"
        label = svg.text_box("label-crank-angle")  # and its value is written off the bracket
        whole = Polygon(svg.path(g)).buffer(0).union(base.buffer(0.5))
        assert label is None or not label.intersects(whole), f"the angle's value is on {g}"
    joints = [
        g
        for g in svg.groups
        if g.startswith("joint-") and g not in (f"joint-{pivot}", f"joint-{sol.scene.input.tip}")
    ]
    for j in joints:
        centre = Polygon(svg.path(j)).centroid
        gap = arc.distance(centre) / CM
        assert gap >= 0.2, f"the arc passes {gap:.2f} cm from {j}"


CIRCLES = [
    ROOT / "tests" / "textbook" / f"{name}.toml"
    for name in (
        "watt_six_bar",
        "stephenson_six_bar",
        "peaucellier",
        "stone_crusher",
        "shaper_offset_ram",
        "coupler_plate_four_points",
    )
] + [ROOT / "worked_problems" / "engine_analytical.toml"]


@pytest.mark.parametrize("path", CIRCLES, ids=lambda p: Path(p).stem)
def test_the_circle_diagram_numbers_sit_on_their_chords_clear_of_the_rest(path):
    """Each number of a centre found by Kennedy's theorem is written on its own chord,
    and touches no other chord, no other number and no link's point; on a four-link's
    circle (two chords crossing at its middle) it keeps 2 mm clear of the other chord."""
    from polygon_method.draw import render

    sol = solve(load_scene(path))
    svg = Svg(render(sol, "svg", "centres")[0])
    chords = {
        g[len("chord-") :]: LineString(svg.path(g))
        for g in svg.groups
        if g.startswith("chord-") and not g.startswith("chord-order-")
    }
    numbers = {
        g[len("chord-order-") :]: svg.text_box(g)
        for g in svg.groups
        if g.startswith("chord-order-") and not g.endswith("-patch")
    }
    points = [Polygon(svg.path(g)).buffer(0) for g in svg.groups if g.startswith("circle-point-")]
    assert numbers
    for label, ink in numbers.items():
        assert ink.centroid.distance(chords[label]) < 0.1 * CM, f"{label}'s number is off it"
        for other, chord in chords.items():
            if other != label:
                assert not ink.intersects(chord.buffer(0.5)), f"{label}'s number on {other}"
                if len(chords) == 6:
                    assert ink.distance(chord) > 0.2 * CM, f"{label}'s number by {other}"
        for other, ink2 in numbers.items():
            if other != label:
                assert not ink.intersects(ink2), f"{label}'s number on {other}'s"
        assert not any(ink.intersects(p) for p in points)


@pytest.mark.parametrize("name", ["toggle_press", "two_sliders_trammel", "drag_link"])
def test_a_point_s_label_sits_by_it_even_beside_a_nearer_point(name):
    """A point's label keeps by its point (within 4.5 mm) and nearer to it than to any
    other point, also where another point lies closer than the usual margin (the pole o
    of the toggle press, with d 0.6 mm from it)."""
    sol = solve(load_scene(ROOT / "tests" / "textbook" / f"{name}.toml"))
    svg = Svg(svg_string(sol, "all"))
    dots = {
        g[len("velocity-point-") :]: Polygon(svg.path(g)).centroid
        for g in svg.groups
        if g.startswith("velocity-point-")
    }
    for name, dot in dots.items():
        ink = svg.text_box(f"label-{name}")
        own = ink.distance(dot)
        assert own <= 0.45 * CM, f"{name}'s label is {own / CM:.2f} cm from it"
        for other, q in dots.items():
            if other != name:
                assert ink.distance(q) > own, f"{name}'s label is nearer {other}"


@pytest.mark.parametrize(
    "path",
    [
        ROOT / "worked_problems" / "crank_slotted_lever.toml",
        ROOT / "tests" / "textbook" / "watt_six_bar.toml",
        ROOT / "tests" / "textbook" / "toggle_press.toml",
    ],
    ids=lambda p: Path(p).stem,
)
def test_the_centres_diagram_shows_no_more_plane_than_its_centres_need(path):
    """Kennedy's lines reach no further than 0.3 of the mechanism's size beyond the
    mechanism and the centres drawn where they are, so the mechanism is drawn as large as
    the sheet allows (it was drawn in a square three times its size)."""
    from polygon_method.draw import render

    svg = Svg(render(solve(load_scene(path)), "svg", "centres")[0])
    joints = [Polygon(svg.path(g)).centroid for g in svg.groups if g.startswith("joint-")]
    rings = [
        Polygon(svg.path(g)).centroid
        for g in svg.groups
        if g.startswith("centre-") and not g.endswith(("-shaft", "-head"))
    ]
    xs, ys = [p.x for p in joints], [p.y for p in joints]
    size = max(max(xs) - min(xs), max(ys) - min(ys))
    xs += [p.x for p in rings]
    ys += [p.y for p in rings]
    ends = [q for g in svg.groups if g.startswith("kennedy-") for q in svg.path(g)]
    assert ends
    pad = 0.3 * size + 0.01 * CM
    assert min(q[0] for q in ends) >= min(xs) - pad and max(q[0] for q in ends) <= max(xs) + pad
    assert min(q[1] for q in ends) >= min(ys) - pad and max(q[1] for q in ends) <= max(ys) + pad


@pytest.mark.parametrize(
    "path, degrees",
    [
        (ROOT / "tests" / "textbook" / "slotted_lever_270.toml", 270),
        (ROOT / "tests" / "textbook" / "engine_inline_270.toml", 270),
        (ROOT / "worked_problems" / "whitworth.toml", 30),
        (ROOT / "worked_problems" / "whitworth.toml", 225),
        (ROOT / "worked_problems" / "fourbar_acceleration.toml", -60),
    ],
    ids=lambda x: Path(x).stem if isinstance(x, Path) else str(x),
)
def test_the_crank_angle_is_drawn_as_the_scene_states_it(path, degrees):
    """The arc sweeps the stated angle from +x, the stated way round (270 deg ccw is not
    drawn as 90 deg cw), and its label reads it."""
    import math

    sol = _turned(path, degrees)
    text = svg_string(sol, "configuration")
    svg = Svg(text)
    arc = svg.path("crank-angle")
    o = Polygon(svg.path(f"joint-{sol.scene.input.pivot}")).centroid
    sweep = 0.0
    for (x1, y1), (x2, y2) in zip(arc, arc[1:]):  # SVG's y points down
        a1, a2 = math.atan2(o.y - y1, x1 - o.x), math.atan2(o.y - y2, x2 - o.x)
        sweep += math.remainder(a2 - a1, 2 * math.pi)
    assert math.degrees(sweep) == pytest.approx(degrees, abs=0.5)
    assert math.degrees(math.atan2(o.y - arc[0][1], arc[0][0] - o.x)) == pytest.approx(0, abs=0.5)
    label = text[text.index('id="label-crank-angle"') :]
    assert label.split("<!--")[1].split("-->")[0].strip() == f"{abs(degrees)}\u00b0"


def _with_blocks_on_moving_links():
    from polygon_method.scene import FixedPath

    return [p for p in SCENES if any(not isinstance(sl, FixedPath) for sl in load_scene(p).sliders)]


@pytest.mark.parametrize("path", _with_blocks_on_moving_links(), ids=lambda p: Path(p).stem)
def test_a_block_on_a_moving_link_sits_on_that_link_drawn(path):
    """A block sliding on a moving link sits on the link as drawn: where the block is
    beyond the link's ends (block_on_coupler: G on BC produced) the link is drawn produced
    through it."""
    from polygon_method.scene import FixedPath

    sol = solve(load_scene(path))
    blocks = [sl for sl in sol.scene.sliders if not isinstance(sl, FixedPath)]
    svg = Svg(svg_string(sol, "configuration"))
    for sl in blocks:  # (a Scotch yoke's block sits on the yoke's bar)
        body = f"link-{sl.guide}" if hasattr(sl, "guide") else f"yoke-{sl.yoke}"
        link = Polygon(svg.path(body)).buffer(0)
        pin = Polygon(svg.path(f"joint-{sl.point}")).centroid
        assert link.contains(pin), f"{sl.point} hangs off {body}"


@pytest.mark.parametrize("path", TEXTBOOK, ids=lambda p: Path(p).stem)
def test_textbook_sheets_labels_clear_and_on_the_sheet(path):
    """The textbook corpus's sheets as the worked problems' are checked: no label on
    another label or on any line, arrow or outline, and every text inside the sheet."""
    from shapely.geometry import box
    from polygon_method.draw import render
    from test_draw import _check_labels

    text, _, warnings = render(solve(load_scene(path)), "svg", "all")
    assert warnings == []
    svg = _check_labels(text)
    w, h = svg.size_cm()
    sheet = box(0, 0, w * CM, h * CM)
    for gid in svg.texts():
        ink = svg.text_box(gid)
        assert ink is None or sheet.contains(ink), f"{gid} is off the sheet"


@pytest.mark.parametrize(
    "name",
    [
        "block_on_coupler",
        "double_rocker",
        "stone_crusher",
        "whitworth_180",
        "shaper_offset_ram",
        "watt_six_bar",
    ],
)
def test_a_label_far_from_its_point_has_a_leader_and_a_near_one_none(name):
    """A point's label more than 6 mm from its point has a leader line to it; one within
    3 mm has none."""
    sol = solve(load_scene(ROOT / "tests" / "textbook" / f"{name}.toml"))
    svg = Svg(svg_string(sol, "all"))
    for g in svg.groups:
        for pre in ("joint-", "velocity-point-", "acceleration-point-"):
            if not g.startswith(pre) or f"label-{g[len(pre) :]}" not in svg.groups:
                continue
            label = f"label-{g[len(pre) :]}"
            gap = svg.text_box(label).distance(Polygon(svg.path(g)).centroid) / CM
            if gap > 0.6:
                assert f"leader-{label}" in svg.groups, f"{label}: {gap:.2f} cm, no leader"
            if gap < 0.3:
                assert f"leader-{label}" not in svg.groups, f"{label}: {gap:.2f} cm, a leader"
