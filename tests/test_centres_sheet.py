"""The instantaneous-centre sheet of compact mechanisms (the Whitworth quick return, the
six-bar chains) measured in the written SVG: no two labels overlap, no label sits on a link,
a block or a hatch, and a centre off the sheet has an arrow that states where it is (its
distance from the crank's pivot and the direction, checked against the centre located by
Kennedy's theorem and against the arrow as drawn)."""

import math
import re
from pathlib import Path

import pytest
from shapely.geometry import LineString, Polygon

from polygon_method import load_scene, solve
from polygon_method.solver.centres import locate
from polygon_method.draw import render_pages
from test_draw import CM, SVGNS, Svg
from test_paper import _check_page, _said

ROOT = Path(__file__).resolve().parents[1]
COMPACT = [
    ROOT / "worked_problems" / "whitworth.toml",
    ROOT / "worked_problems" / "class3_six_bar.toml",
    ROOT / "tests" / "textbook" / "stephenson_six_bar.toml",
    ROOT / "tests" / "textbook" / "watt_six_bar.toml",
]

_SHEETS = {}


def _sheet(path):
    if path not in _SHEETS:
        sol = solve(load_scene(path))
        _SHEETS[path] = sol, render_pages(sol, "svg", "centres", paper="A4")
    return _SHEETS[path]


def _solids(svg):
    """The links, blocks, cylinders, brackets (as areas) and hatches (as lines) drawn."""
    out = []
    for gid, g in svg.groups.items():
        if gid.startswith(("link-", "block-", "cylinder-", "yoke-", "slot-")) or re.fullmatch(
            r"ground-[^-]+", gid
        ):
            for p in g.iter(SVGNS + "path"):
                pts = [
                    (float(x), float(y)) for x, y in re.findall(r"([-\d.]+) ([-\d.]+)", p.get("d"))
                ]
                if len(pts) >= 3:
                    out.append((gid, Polygon(pts).buffer(0)))
        elif gid.endswith("-hatch"):
            for p in g.iter(SVGNS + "path"):
                pts = [
                    (float(x), float(y)) for x, y in re.findall(r"([-\d.]+) ([-\d.]+)", p.get("d"))
                ]
                for a, b in zip(pts[0::2], pts[1::2]):
                    out.append((gid, LineString([a, b]).buffer(0.3)))
    return out


@pytest.mark.parametrize("path", COMPACT, ids=lambda p: p.stem)
def test_centre_labels_overlap_neither_each_other_nor_a_link_nor_a_hatch(path):
    sol, (datas, used, warnings, pages) = _sheet(path)
    assert not [w for w in warnings if "could not be placed" in w], warnings
    svg = Svg(datas[0])
    assert "panel-centres" in "".join(svg.groups)
    _check_page(svg, pages[0], "A4")
    labels = {
        gid: svg.text_box(gid)
        for gid in svg.groups
        if gid.startswith("label-") and svg.text_box(gid) is not None
    }
    names = sorted(labels)
    centres = [n for n in names if re.fullmatch(r"label-I\d+", n)]
    assert len(centres) == locate(sol, "I").n * (locate(sol, "I").n - 1) // 2
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            assert not labels[a].intersects(labels[b]), f"{a} and {b} overlap"
    solids = _solids(svg)
    assert sum(1 for gid, _ in solids if gid.startswith("link-")) == len(sol.scene.links)
    assert any(gid.endswith("-hatch") for gid, _ in solids)
    for gid, box in labels.items():
        for other, geom in solids:
            assert not box.intersects(geom), f"{gid} sits on {other}"


def test_a_centre_off_the_sheet_says_how_far_and_which_way():
    """A centre beyond what a sheet shows (the class-III six-bar's I13, 850 mm from O): its
    arrow points from the crank's pivot towards it, and its words give the distance and
    the angle (from +x, anticlockwise), both as the located centre has them; a centre at
    infinity (the Whitworth's I16, I34: a block on a fixed guide) states the direction of
    its line, along which its arrow points."""
    far = infinite = 0
    for path in COMPACT:
        sol, (datas, *_rest) = _sheet(path)
        svg = Svg(datas[0])
        ic = locate(sol, "I")
        sc = sol.scene
        pivot = sol.P[sc.input.pivot]
        for key in ic.order:
            c = ic.centres[key]
            if f"centre-{c.label}-shaft" not in svg.groups:
                assert c.point is not None  # drawn where it is
                continue
            said = _said(svg, f"label-{c.label}")
            tail = svg.path(f"centre-{c.label}-shaft")[0]
            tip = svg.path(f"centre-{c.label}-head")[0]
            drawn = math.degrees(math.atan2(-(tip[1] - tail[1]), tip[0] - tail[0]))
            if c.point is None:
                m = re.fullmatch(rf"{c.label}at\u221e,along([\d.]+)\u00b0", said)
                assert m, said
                along = math.degrees(math.atan2(c.direction[1], c.direction[0])) % 180
                assert float(m.group(1)) == pytest.approx(along, abs=0.051)
                assert min((drawn - along) % 180, 180 - (drawn - along) % 180) < 0.2
                infinite += 1
                continue
            m = re.fullmatch(
                rf"{c.label}:([\d.]+){sc.units}from{sc.input.pivot}"
                rf"at([\d.]+)\u00b0",
                said,
            )
            assert m, said
            dist = math.dist(c.point, pivot) / sc.length_unit
            angle = math.degrees(math.atan2(c.point[1] - pivot[1], c.point[0] - pivot[0])) % 360
            assert float(m.group(1)) == pytest.approx(dist, rel=6e-4)
            assert float(m.group(2)) == pytest.approx(angle, abs=0.051)
            assert min((drawn - angle) % 360, 360 - (drawn - angle) % 360) < 0.2
            # the centre is truly off the sheet: beyond the arrow's tip
            assert math.dist(c.point, pivot) / used_per_cm(svg, sol) > math.dist(tail, tip) / CM
            far += 1
    assert far >= 1 and infinite >= 2


def used_per_cm(svg, sol):
    """The centres diagram's scale, read from its own words on the sheet (SI per cm)."""
    from polygon_method.polygons.scales import parse_scale

    said = _said(svg, "note-centres-scale")
    value = re.fullmatch(r"1cm=([\d.]+)(\w+)", said)
    return parse_scale(f"1 cm = {value.group(1)} {value.group(2)}").per_cm
