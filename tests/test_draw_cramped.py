"""Small cranks and crowded pivots drawn legibly, measured on the SVG with shapely: the
fixed-pivot bracket keeps off the links beyond their common pin, a slider block does not
swallow another pin, and the crank angle's label sits by its arc."""

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


@pytest.mark.parametrize("path", WORKED, ids=lambda p: Path(p).stem)
def test_fixed_pivot_brackets_keep_off_the_links(path):
    svg = _sheet(path)
    links = [g for g in svg.groups if g.startswith("link-")]
    brackets = [g for g in svg.groups if g.startswith("ground-") and
                not g.endswith(("-base", "-hatch"))]
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
            if j == "joint-" + b[len("block-"):]:
                continue
            circle = Polygon(svg.path(j)).buffer(0)
            assert not rect.intersects(circle), f"{j} lies on {b}"


@pytest.mark.parametrize("path", WORKED, ids=lambda p: Path(p).stem)
def test_the_crank_angle_label_sits_by_its_arc(path):
    svg = _sheet(path)
    if "crank-angle" not in svg.groups:
        return
    arc = LineString(svg.path("crank-angle"))
    label = svg.text_box("label-crank-angle")
    assert label.distance(arc) <= 0.4 * CM, f"{label.distance(arc) / CM:.2f} cm away"
