"""The layout's search against the plain one it replaced: every arrangement of the panels
that cuts straight across tried in order (side by side before stacked, each cut after the
first panel before after the second, ...), the first that fits either way round taken;
every way of cutting the panels into runs tried, fewest runs first. Both written out here,
at random sizes: the pages are the same, panel for panel, to the last bit."""

from itertools import combinations

import numpy as np
import pytest

from polygon_method.common.tolerances import ON_PAPER
from polygon_method.draw.paper import GAP, MARGIN, PAPERS, paginate, room


def _every_arrangement(items):
    if len(items) == 1:
        k, (w, h) = items[0]
        return [(w, h, [(k, 0.0, 0.0)])]
    out = []
    for across in (True, False):
        for cut in range(1, len(items)):
            for a in _every_arrangement(items[:cut]):
                for b in _every_arrangement(items[cut:]):
                    if across:
                        w, h = a[0] + GAP + b[0], max(a[1], b[1])
                        pos = a[2] + [(k, x + a[0] + GAP, y) for k, x, y in b[2]]
                    else:
                        w, h = max(a[0], b[0]), a[1] + GAP + b[1]
                        pos = a[2] + [(k, x, y + a[1] + GAP) for k, x, y in b[2]]
                    out.append((w, h, pos))
    return out


def _plain_page(items, paper):
    for w, h, pos in _every_arrangement(items):
        for orientation in ("portrait", "landscape"):
            rw, rh = room(paper, orientation)
            if w <= rw + ON_PAPER and h <= rh + ON_PAPER:
                left = MARGIN + (rw - w) / 2
                return orientation, tuple((k, left + x, MARGIN + y) for k, x, y in pos)
    return None


def _plain_pages(sizes, paper):
    n = len(sizes)
    for cuts in range(n):
        for at in combinations(range(1, n), cuts):
            bounds = (0,) + at + (n,)
            pages = [
                _plain_page([(k, sizes[k]) for k in range(bounds[i], bounds[i + 1])], paper)
                for i in range(len(bounds) - 1)
            ]
            if all(p is not None for p in pages):
                return pages
    raise AssertionError("one panel a page always fits")


def _cases():
    rng = np.random.default_rng(20261126)
    for case in range(60):
        n = int(rng.integers(1, 7))
        paper = list(PAPERS)[case % 3]
        big = 6.0 + 16.0 * rng.random()  # from small panels that share a page to big ones
        sizes = [
            (round(float(2 + big * rng.random()), 2), round(float(2 + big * rng.random()), 2))
            for _ in range(n)
        ]
        yield pytest.param(sizes, paper, id=f"{case}-{paper}-{n}")


@pytest.mark.parametrize("sizes,paper", list(_cases()))
def test_the_pages_are_those_the_plain_search_finds(sizes, paper):
    pages = paginate(sizes, paper)
    assert [(p.orientation, p.placed) for p in pages] == _plain_pages(sizes, paper)


def test_twelve_panels_are_laid_out():
    """Twelve small panels: 120 million arrangements of the twelve (the plain search would
    take hours): one A4 page holds them all, inside its margins."""
    sizes = [(4.0 + 0.1 * k, 3.0 + 0.05 * k) for k in range(12)]
    (page,) = paginate(sizes, "A4")
    assert sorted(k for k, _, _ in page.placed) == list(range(12))
    W, H = page.size
    for k, x, y in page.placed:
        assert MARGIN - 1e-9 <= x and x + sizes[k][0] <= W - MARGIN + 1e-9
        assert MARGIN - 1e-9 <= y and y + sizes[k][1] <= H - MARGIN + 1e-9
