"""The turning-moment sheets that print (a diagram stated on its own, a punching press, an
engine's cycle and a machine's, ``draw --diagram cycle``): on every paper ``draw`` offers, measured in the
written files. Each SVG page is the paper's size (A4 21 x 29.7 cm, A3, letter 21.59 x
27.94 cm), says so at its foot, and every word on it (the heading, the axes' titles and
ticks, the legend, the answers) lies inside the page's margins and clear of every other
word (glyph outlines placed as the SVG places them, shapely boxes); the PNG is the paper
at 200 dpi. The answers are written as a book prints them (ΔEₘₐₓ, kg m², Cₛ, ω), not in
the terminal's ASCII (dE_max, kg m^2, Cs, w), which the sheets once carried; the press's
and the areas' sheets were refused on any paper but A4."""

import math
import re
import struct
from pathlib import Path

import pytest
from shapely.geometry import box

import test_draw
from polygon_method.cli import main
from test_draw import CM, SVGNS, XLINK, Svg, _apply

ROOT = Path(__file__).resolve().parents[1]
PAPERS = {"A4": (21.0, 29.7), "A3": (29.7, 42.0), "letter": (21.59, 27.94)}
SHEETS = {
    "engine cycle": (ROOT / "worked_problems" / "engine_flywheel.toml", ["--diagram", "cycle"]),
    "v-twin cycle": (ROOT / "worked_problems" / "vtwin_flywheel.toml", ["--diagram", "cycle"]),
    "machine cycle": (ROOT / "worked_problems" / "fourbar_flywheel.toml", ["--diagram", "cycle"]),
    "press": (ROOT / "worked_problems" / "flywheel" / "punching_press.toml", []),
    "areas": (ROOT / "worked_problems" / "flywheel" / "engine_areas_rim.toml", []),
}
#: no word nearer the paper's edge than this (cm): printers leave 4 to 6 mm blank
EDGE = 0.5


def _draw(tmp_path, name, paper, ext="svg"):
    scene, extra = SHEETS[name]
    out = tmp_path / f"sheet.{ext}"
    assert main(["draw", str(scene), *extra, "--paper", paper, "-o", str(out)]) == 0
    return out


def _transform(text):
    """test_draw's reading of an SVG transform, with rotate (an axis' title stands up)."""
    m = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0]
    for op, args in re.findall(r"(\w+)\(([^)]*)\)", text or ""):
        if op == "rotate":
            a = math.radians(float(args.split()[0]))
            t = test_draw._transform("")
            t[:4] = [math.cos(a), math.sin(a), -math.sin(a), math.cos(a)]
        else:
            t = test_draw._transform(f"{op}({args})")
        a0, b0, c0, d0, e0, f0 = m
        m = [
            a0 * t[0] + c0 * t[1],
            b0 * t[0] + d0 * t[1],
            a0 * t[2] + c0 * t[3],
            b0 * t[2] + d0 * t[3],
            a0 * t[4] + c0 * t[5] + e0,
            b0 * t[4] + d0 * t[5] + f0,
        ]
    return m


def _ink(svg, gid):
    """The ink box (pt) of the text group ``gid``: its glyph outlines, placed."""
    pts = []
    for inner in svg.groups[gid].findall(SVGNS + "g"):
        m = _transform(inner.get("transform"))
        for use in inner.iter(SVGNS + "use"):
            u = _transform(use.get("transform"))
            for q in svg.glyphs.get(use.get(XLINK)[1:], []):
                pts.append(_apply(m, _apply(u, q)))
    if not pts:
        return None
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return box(min(xs), min(ys), max(xs), max(ys))


def _words(text):
    """(what it says, its ink box in pt) of every piece of text drawn: matplotlib writes
    each as a group ``text_N`` of glyph outlines, after a comment of what it says."""
    svg = Svg(text)
    said = dict(re.findall(r'<g id="(text_\d+)">\s*<!-- (.*?) -->', text, re.S))
    out = []
    for gid in svg.groups:
        if gid.startswith("text_"):
            ink = _ink(svg, gid)
            if ink is not None:
                out.append((said.get(gid, gid), ink))
    return svg, out


@pytest.mark.parametrize("paper", PAPERS)
@pytest.mark.parametrize("name", SHEETS)
def test_the_sheet_is_its_paper_with_every_word_inside_and_clear(tmp_path, capsys, name, paper):
    text = _draw(tmp_path, name, paper).read_text(encoding="utf-8")
    assert paper in capsys.readouterr().out
    svg, words = _words(text)
    W, H = PAPERS[paper]
    assert svg.size_cm() == pytest.approx((W, H), abs=1e-4)
    assert len(words) > 10
    for said, ink in words:  # inside the page, EDGE from each edge
        x0, y0, x1, y1 = (v / CM for v in ink.bounds)
        assert x0 >= EDGE and y0 >= EDGE and x1 <= W - EDGE and y1 <= H - EDGE, (said, paper)
    for i, (a, box_a) in enumerate(words):
        for b, box_b in words[i + 1 :]:
            assert box_a.intersection(box_b).area <= 1e-6, (a, b)
    feet = [s for s, _ in words if s.startswith(f"{paper} portrait")]
    assert feet == [f"{paper} portrait ({W:g} x {H:g} cm)"]


@pytest.mark.parametrize("name", SHEETS)
def test_the_answers_are_written_as_a_book_prints_them(tmp_path, name):
    _, words = _words(_draw(tmp_path, name, "A4").read_text(encoding="utf-8"))
    said = " | ".join(s for s, _ in words)
    assert "ΔEₘₐₓ = " in said
    for ascii_ in ("dE_max", "^2", "T_mean", "Cs =", "w =", "E_max", "E_min"):
        assert ascii_ not in said, ascii_
    if name != "press":  # (a press's sheet gives its flywheel's speed in its heading)
        line = next(s for s, _ in words if s.startswith("ΔEₘₐₓ"))
        assert "kg m² (Cₛ = " in line and ", ω = " in line and " rad/s)" in line


@pytest.mark.parametrize("paper", PAPERS)
def test_the_png_is_the_paper_at_200_dpi(tmp_path, paper):
    data = _draw(tmp_path, "engine cycle", paper, "png").read_bytes()
    w, h = struct.unpack(">II", data[16:24])
    W, H = PAPERS[paper]
    # (matplotlib drops the part of a pixel: within one, 0.13 mm)
    assert abs(w - W / 2.54 * 200) < 1 and abs(h - H / 2.54 * 200) < 1
    at = data.index(b"pHYs")  # its physical size recorded: 200 dpi in pixels per metre
    assert struct.unpack(">IIB", data[at + 4 : at + 13]) == (7874, 7874, 1)
