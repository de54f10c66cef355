"""The page draws an offset slot as the configuration diagram does: the lever a plate (a
bracket) that carries the slot, the block on the slot's line, offset from the lever's line
by the stated offset at the drawing's stated scale. Measured in headless Chromium on the
drawn SVG at two crank angles and at a wide and a narrow window; the offset is read from
the scene's own words, not from the tool."""

import math
import tomllib
from pathlib import Path

import pytest

from polygon_method.cli import main

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "tests" / "textbook" / "hunt5_offset_slot_lever.toml"

_UNIT = {"mm": 1e-3, "cm": 1e-2, "m": 1.0}


def _stated_offset() -> float:
    """The slot's offset (m, + to the left looking from the guide's first point to its
    second), from the scene's words ``offset = "30 mm left"``."""
    spec = tomllib.loads(SCENE.read_text())["sliders"]["A"]
    size, unit, side = spec["offset"].split()
    assert side in ("left", "right") and spec["along"] == "QB"
    return float(size) * _UNIT[unit] * (1 if side == "left" else -1)


@pytest.fixture(scope="module")
def page_file(tmp_path_factory):
    path = tmp_path_factory.mktemp("offset") / "offset.html"
    assert main(["page", str(SCENE), "-o", str(path)]) == 0
    return path


_READ = """() => {
  const pts = (e) => e.getAttribute('points').trim().split(/\\s+/).map((p) => p.split(',').map(Number));
  const ln = document.getElementById('c-link-QB');
  const b = document.getElementById('c-bracket-A');
  return {
    block: pts(document.getElementById('c-block-A')),
    bracket: b && b.style.display !== 'none' ? pts(b) : null,
    Q: [Number(ln.getAttribute('x1')), Number(ln.getAttribute('y1'))],
    B: [Number(ln.getAttribute('x2')), Number(ln.getAttribute('y2'))],
    scale: document.getElementById('scale-configuration').textContent,
  };
}"""


def _inside(p, poly, tol) -> bool:
    """Is ``p`` inside the convex polygon ``poly`` (either turning), within ``tol``?"""
    sides = []
    for a, b in zip(poly, poly[1:] + poly[:1]):
        n = math.dist(a, b)
        if n > 0:
            sides.append(((b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])) / n)
    return all(s >= -tol for s in sides) or all(s <= tol for s in sides)


@pytest.mark.parametrize("width", [1280, 390])
def test_the_offset_slots_block_lies_on_the_slots_line_in_a_bracket_of_the_lever(
    browser, page_file, width
):
    offset = _stated_offset()
    page = browser.new_page(viewport={"width": width, "height": 900})
    try:
        page.goto(page_file.as_uri())
        seen = []
        for k in (0, 50):  # two crank angles (frames 100 deg apart)
            page.evaluate(
                "(k) => { const s = document.getElementById('angle'); s.value = k; "
                "s.dispatchEvent(new Event('input')); }",
                k,
            )
            d = page.evaluate(_READ)
            words = d["scale"].split()  # "1 cm = 50 mm": the drawing's stated scale
            assert words[:3] == ["1", "cm", "="], words
            per_mm = float(words[3]) * _UNIT[words[4]] / 10  # m per drawn mm (SVG's unit)
            # the drawing's y runs down: flip it so that "left of Q -> B" is the world's
            Q, B = (d["Q"][0], -d["Q"][1]), (d["B"][0], -d["B"][1])
            L = math.dist(Q, B)
            u = ((B[0] - Q[0]) / L, (B[1] - Q[1]) / L)

            def left(p):  # signed distance (m) of a drawn point to the left of QB
                return ((p[0] - Q[0]) * -u[1] + (-p[1] - Q[1]) * u[0]) * per_mm

            corners = d["block"]
            assert len(corners) == 4
            side = math.dist(corners[0], corners[1]) * per_mm
            dists = sorted(left(c) for c in corners)
            # two corners on each side of the slot's line, half the block's side off it: the
            # block's sides along the slot, its centre on the slot's line
            tol = 0.002 * per_mm * 2  # the drawing's coordinates rounded to 0.001 mm
            for got, want in zip(dists, [offset - side / 2] * 2 + [offset + side / 2] * 2):
                assert abs(got - want) < tol, (k, dists, offset, side)
            centre = (
                sum(c[0] for c in corners) / 4,
                sum(c[1] for c in corners) / 4,
            )
            along = [((c[0] - centre[0]) * u[0] - (c[1] - centre[1]) * u[1]) for c in corners]
            assert max(abs(abs(a) - abs(along[0])) for a in along) < 0.01
            # the bracket joins it to the lever: the plate holds the lever's line and the block
            assert d["bracket"], "no bracket drawn for the offset slot"
            for p in (d["Q"], d["B"], centre):
                assert _inside(p, d["bracket"], 0.01), (k, p, d["bracket"])
            seen.append(centre)
        assert math.dist(*seen) > 1.0  # the two angles put the block in two places
    finally:
        page.close()
