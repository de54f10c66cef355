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
    the first page (they went on two pages, the first mostly blank), the crank's on the
    second; the static four-bar likewise."""
    for name in FOUR_BARS:
        sol = solve(load_scene(ROOT / "worked_problems" / name))
        panels, sizes, pages = sheet_pages(sol, "forces")
        assert pages[0].panels == ("free-body-3", "free-body-4", "force-polygon-2"), name
        assert len(pages) == 2


def test_the_written_pages_are_on_their_paper_inside_the_margins():
    sol = solve(load_scene(ROOT / "worked_problems" / "static_fourbar_pin_forces.toml"))
    datas, used, warnings, pages = render_pages(sol, "svg", "forces", paper="A4")
    assert len(datas) == len(pages) == 2
    for data, page in zip(datas, pages):
        _check_page(Svg(data), page, "A4")
