"""The forces sheet fills a page before it starts another: its free bodies and polygons, in
the order solved, each onto the page being filled where that page still holds them all
(their own order first, else another), measured in the written pages as
``tests/test_paper.py`` measures them (the paper's size, everything inside the margins)."""

from __future__ import annotations

from pathlib import Path

import pytest

from polygon_method import load_scene, solve
from polygon_method.draw import render_pages
from polygon_method.draw.paper import GAP, fill, paginate, room
from polygon_method.draw.sheet import sheet_pages
from test_draw import Svg
from test_paper import _check_page

ROOT = Path(__file__).resolve().parents[1]
FOUR_BARS = ["fourbar_forces.toml", "static_fourbar_pin_forces.toml"]


def _area(page, sizes):
    return sum(sizes[k][0] * sizes[k][1] for k, _, _ in page.placed)


@pytest.mark.parametrize("name", FOUR_BARS + ["shaper_forces.toml", "collar_forces.toml"])
def test_each_page_is_filled_before_the_next_and_holds_its_panels(name):
    sol = solve(load_scene(ROOT / "worked_problems" / name))
    panels, sizes, pages = sheet_pages(sol, "forces")
    before = paginate(sizes, "A4")
    assert len(pages) <= len(before)
    seen = []
    for i, page in enumerate(pages):
        ks = [k for k, _, _ in page.placed]
        seen += sorted(ks)
        rw, rh = room("A4", page.orientation)
        boxes = [(x, y, x + sizes[k][0], y + sizes[k][1]) for k, x, y in page.placed]
        for a in boxes:  # inside the room, apart by the gap
            assert a[0] >= 0.6 - 1e-9 and a[2] <= 0.6 + rw + 1e-9 and a[3] <= 0.6 + rh + 1e-9
            for b in boxes:
                if a is not b:
                    apart = max(b[0] - a[2], a[0] - b[2], b[1] - a[3], a[1] - b[3])
                    assert apart >= GAP - 1e-9, (name, i, a, b)
        if i + 1 < len(pages):  # the next page's first panel did not fit this one
            nxt = min(k for k, _, _ in pages[i + 1].placed)
            assert fill([sizes[k] for k in ks + [nxt]], "A4")[0].count > 1
    assert seen == list(range(len(panels)))  # every panel once, the order kept across pages
    assert _area(pages[0], sizes) >= _area(before[0], sizes)


def test_the_four_bars_first_page_holds_both_links_and_their_polygon():
    """The worked four-bar (fourbar_forces.toml): the dyad's free bodies and its polygon on
    the first page (they went on two pages, the first mostly blank), then the crank's (on
    the same page since the panels' words wrap to their drawings: the crank's free body
    with them, its polygon on the second; and since the panels keep 2 mm round their
    drawings, not 3, and state their scale on their title's line, the crank's polygon on
    the first page too: one page); the static four-bar's whole sheet on one page (it took
    two)."""
    pages_of = {}
    for name in FOUR_BARS:
        sol = solve(load_scene(ROOT / "worked_problems" / name))
        panels, sizes, pages = sheet_pages(sol, "forces")
        assert pages[0].panels[:3] == ("free-body-3", "free-body-4", "force-polygon-2"), name
        pages_of[name] = [p.panels for p in pages]
    assert len(pages_of["fourbar_forces.toml"]) == 1
    assert pages_of["static_fourbar_pin_forces.toml"] == [
        ("free-body-3", "free-body-4", "force-polygon-2", "free-body-2")
    ]


@pytest.mark.parametrize(
    "name, count", [("static_fourbar_pin_forces.toml", 1), ("class3_six_bar_forces.toml", 2)]
)
def test_the_written_pages_are_on_their_paper_inside_the_margins(name, count):
    sol = solve(load_scene(ROOT / "worked_problems" / name))
    datas, used, warnings, pages = render_pages(sol, "svg", "forces", paper="A4")
    assert len(datas) == len(pages) == count
    for data, page in zip(datas, pages):
        _check_page(Svg(data), page, "A4")


def test_a_triads_sheet_shares_its_pages_and_its_words_stay_apart(tmp_path):
    """The triad whose plate is three links (tests/test_triad_three_links.py's scene): its
    panels' lines of words wrap to their drawings (at least 7 cm), so narrow polygons
    share a page: on A4 at most 4 pages (it took 7, each polygon about 17 cm wide for its
    words), each on its paper inside the margins, no line of words wider than 13 cm and no
    two lines of words of a page overlapping."""
    from test_triad_three_links import scene_text

    path = tmp_path / "tri.toml"
    path.write_text(scene_text(30.0), encoding="utf-8")
    sol = solve(load_scene(path))
    datas, used, warnings, pages = render_pages(sol, "svg", "forces", paper="A4")
    assert len(datas) == len(pages) <= 4
    assert sum(len(p.placed) for p in pages) == 14  # links 2 to 8, and 7 polygons
    for data, page in zip(datas, pages):
        svg = Svg(data)
        _check_page(svg, page, "A4")
        boxes = [svg.text_box(g) for g in svg.groups if g.startswith("note-") and "-line-" in g]
        boxes = [b for b in boxes if b is not None]
        assert len(boxes) > 5
        for i, a in enumerate(boxes):
            assert (a.bounds[2] - a.bounds[0]) / (72 / 2.54) <= 13.0, a.bounds
            for b in boxes[i + 1 :]:
                assert a.intersection(b).area <= 1e-6 * min(a.area, b.area), (a.bounds, b.bounds)
