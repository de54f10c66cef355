"""Small cranks and crowded pivots drawn legibly, measured on the SVG with shapely: the
fixed-pivot bracket keeps off the links beyond their common pin, a slider block does not
swallow another pin, and the crank angle's label sits by its arc."""

import math
from pathlib import Path

import pytest
from shapely.geometry import LineString, Point, Polygon

from polygon_method import load_scene, solve
from polygon_method.draw import svg_string
from test_draw import CM, WORKED, Svg

#: the pin's own neighbourhood (cm): the bracket and the link's rounded end meet there
PIN_ZONE = 0.3


def _sheet(path):
    return Svg(svg_string(solve(load_scene(path)), "configuration"))


def _polygon(svg, gid):
    return Polygon(svg.path(gid)).buffer(0)


def _pivoted(path):
    """Whether the scene has a fixed pivot (a ground point at a link's or a cylinder's end),
    which the sheet draws with a bracket (an ellipse trammel's guides cross at a point that
    is no pivot)."""
    sc = load_scene(path)
    ends = {p for lk in sc.links for p in lk.points} | {
        p for c in sc.cylinders for p in (c.barrel, c.rod)
    }
    return any(g in ends for g in sc.ground)


@pytest.mark.parametrize("path", [p for p in WORKED if _pivoted(p)], ids=lambda p: Path(p).stem)
def test_fixed_pivot_brackets_keep_off_the_links(path):
    svg = _sheet(path)
    links = [g for g in svg.groups if g.startswith("link-")]
    brackets = [
        g for g in svg.groups if g.startswith("ground-") and not g.endswith(("-base", "-hatch"))
    ]
    assert brackets
    for g in brackets:
        tri = _polygon(svg, g)
        pin = Point(svg.path(g)[0])  # the bracket's apex is the pin
        base = LineString(svg.path(f"{g}-base")).buffer(0.5)
        outside = tri.union(base).difference(pin.buffer(PIN_ZONE * CM))
        for lk in links:
            overlap = outside.intersection(_polygon(svg, lk)).area
            assert overlap < 1e-3, f"{g} overlaps {lk} by {overlap:.3g} pt^2"


@pytest.mark.parametrize("path", WORKED, ids=lambda p: Path(p).stem)
def test_a_block_does_not_swallow_another_pin(path):
    svg = _sheet(path)
    blocks = [g for g in svg.groups if g.startswith("block-")]
    joints = [g for g in svg.groups if g.startswith("joint-")]
    for b in blocks:
        rect = _polygon(svg, b)
        for j in joints:
            if j == "joint-" + b[len("block-") :]:
                continue
            circle = Polygon(svg.path(j)).buffer(0)
            assert not rect.intersects(circle), f"{j} lies on {b}"


def _crank_angle_drawn(path):
    """Whether the sheet draws the crank angle's arc: a crank off its reference line
    (``test_draw_looks.py`` holds the sheet to this rule)."""
    inp = load_scene(path).input
    turns = inp.angle / (2 * math.pi)
    return inp.crank is not None and abs(turns - round(turns)) > 1e-12


@pytest.mark.parametrize(
    "path", [p for p in WORKED if _crank_angle_drawn(p)], ids=lambda p: Path(p).stem
)
def test_the_crank_angle_label_sits_by_its_arc(path):
    svg = _sheet(path)
    assert "crank-angle" in svg.groups
    arc = LineString(svg.path("crank-angle"))
    label = svg.text_box("label-crank-angle")
    if label.distance(arc) <= 0.4 * CM:
        return
    # set off where the arc is crowded (a pitch circle across it): a leader joins the two
    assert "leader-label-crank-angle" in svg.groups, f"{label.distance(arc) / CM:.2f} cm away"
    leader = LineString(svg.path("leader-label-crank-angle"))
    ends = [Point(leader.coords[0]), Point(leader.coords[-1])]
    assert min(e.distance(arc) for e in ends) <= 0.1 * CM
    assert min(e.distance(label) for e in ends) <= 0.2 * CM


CORE = ("FOURBAR", "SIX_LINK", "SLOTTED_LEVER", "WHITWORTH", "OFFSET_SLIDER")


def _draws_lines(path):
    """Whether the scene's polygons draw direction lines: not a train of gears driven by
    cranks only (each gear by its ratio, test_steps.py)."""
    from polygon_method.solver.compiler import compile_plan

    return not all(
        st.kind in ("crank", "second crank")
        or (st.kind == "rolling" and st.on in ("gear", "circle"))
        for st in compile_plan(load_scene(path)).steps
    )


@pytest.mark.parametrize(
    "scene", [p for p in WORKED if _draws_lines(p)] + list(CORE), ids=lambda p: Path(p).stem
)
def test_a_line_mark_is_not_read_with_a_point_label(scene):
    """A construction line's mark ("perp EF") keeps 1.5 mm from every image point's label,
    so that it is never read as one text with e' beside it (the worked problems and the
    core tests' scenes)."""
    import test_core
    from polygon_method import parse_scene

    sc = parse_scene(getattr(test_core, scene)) if scene in CORE else load_scene(scene)
    svg = Svg(svg_string(solve(sc), "all"))
    labels = [g for g in svg.groups if g.startswith("label-")]
    marks = [g for g in labels if "-mark-" in g]
    points = [
        g
        for g in labels
        if "-mark-" not in g
        and g != "label-crank-angle"
        and not g.startswith("label-pin-")
        and not g[len("label-") :][:1].isupper()
    ]
    assert marks and points
    for m in marks:
        for p in points:
            gap = svg.text_box(m).distance(svg.text_box(p)) / CM
            assert gap >= 0.15, f"{m} is {gap:.2f} cm from {p}"
