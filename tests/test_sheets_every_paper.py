"""The sheets of ``draw --forces`` and ``--diagram centres`` on the papers ``draw`` offers
besides A4 (the three diagrams' sheets are measured on every paper in ``test_paper.py``,
the turning-moment sheets in ``test_energy_sheets_print.py``): every worked force problem's
free bodies and force polygons on letter and A3, and the centres of worked problems of
every kind on letter and A3, read from the written SVG pages. Each page is its paper's size,
portrait or landscape; every word (its glyph outlines, placed as the SVG places them) and
every line, outline and arrowhead lies inside the page, 5 mm from its edge at least, where
printers print; and no two words overlap."""

import glob
import itertools
from pathlib import Path

import pytest

from polygon_method import load_scene, solve
from polygon_method.draw import render_pages
from test_draw import CM, SVGNS, Svg

ROOT = Path(__file__).resolve().parents[1]
PAPERS = {"A4": (21.0, 29.7), "A3": (29.7, 42.0), "letter": (21.59, 27.94)}
#: no mark nearer the paper's edge than this (cm)
EDGE = 0.5
#: two words' boxes may share this much (pt²: a hair of a glyph's antialiasing)
SHARED = 0.5


def _force_problems():
    for path in sorted(glob.glob(str(ROOT / "worked_problems" / "*.toml"))):
        text = Path(path).read_text(encoding="utf-8")
        if "\n[masses]" in text or "\n[gravity]" in text or text.startswith("[masses]"):
            yield path


CENTRES = [
    "fourbar_image_points",
    "crank_slotted_lever",
    "whitworth",
    "six_link_second_slider",
    "class3_six_bar",
    "rolling_wheel_rod_slider",
    "engine_forces",
]


def _check(svg_text, paper):
    svg = Svg(svg_text)
    W, H = svg.size_cm()
    assert sorted((W, H)) == pytest.approx(sorted(PAPERS[paper]), abs=1e-4)
    # a group of placed glyphs is words (the labels, the notes, the circle diagram's
    # numbers): its paths are the glyphs' outlines in the font's units, which text_box places
    glyphs = {
        g
        for g, el in svg.groups.items()
        if any(inner.find(f"{SVGNS}use") is not None for inner in el.findall(f"{SVGNS}g"))
    }
    words = [(gid, svg.text_box(gid)) for gid in sorted(glyphs | set(svg.texts()))]
    words = [(gid, b) for gid, b in words if b is not None]
    assert words
    marks = [(g, geo) for g, geo in svg.geometry() if g not in glyphs]
    for gid, shape in words + marks:
        x0, y0, x1, y1 = (v / CM for v in shape.bounds)
        assert x0 >= EDGE and y0 >= EDGE and x1 <= W - EDGE and y1 <= H - EDGE, (gid, paper)
    for (a, ba), (b, bb) in itertools.combinations(words, 2):
        assert ba.intersection(bb).area <= SHARED, (a, b, paper)


@pytest.mark.parametrize("paper", ["letter", "A3"])
@pytest.mark.parametrize("path", list(_force_problems()), ids=lambda p: Path(p).stem)
def test_the_forces_sheet_is_on_its_paper_with_everything_inside_and_clear(path, paper):
    svgs, _, warnings, pages = render_pages(solve(load_scene(path)), "svg", "forces", paper=paper)
    assert len(svgs) == len(pages) >= 1
    for text in svgs:
        _check(text, paper)


@pytest.mark.parametrize("paper", ["letter", "A3"])
@pytest.mark.parametrize("name", CENTRES)
def test_the_centres_sheet_is_on_its_paper_with_everything_inside_and_clear(name, paper):
    sol = solve(load_scene(str(ROOT / "worked_problems" / f"{name}.toml")))
    svgs, _, _, pages = render_pages(sol, "svg", "centres", paper=paper)
    assert len(svgs) == len(pages) >= 1
    for text in svgs:
        _check(text, paper)


def test_a_diagram_s_scale_stands_on_its_title_s_line_where_both_fit():
    """ "Configuration diagram   1 cm = 50 mm", as a book heads it: the scale's own line
    under the title was half a centimetre of every panel, and the slider crank worked
    analytically took two A4 pages for it (of the 237 worked and textbook sheets, 100
    took two pages, 88 with this, 75 with the panels' room 2 mm, not 3). Where the two
    are wider than the drawing (a narrow acceleration polygon) the scale stays under the
    title, clear of it."""
    path = str(ROOT / "worked_problems" / "engine_analytical.toml")
    svgs, _, _, pages = render_pages(solve(load_scene(path)), "svg", "all", paper="A4")
    assert len(pages) == 1
    svg = Svg(svgs[0])
    _check(svgs[0], "A4")
    for tag, beside in (("configuration", True), ("velocity", True), ("acceleration", False)):
        title = svg.text_box(f"note-{tag}-title").bounds
        scale = svg.text_box(f"note-{tag}-scale").bounds
        if beside:  # on the title's line (SVG y down), to its right
            assert scale[1] < title[3] and scale[3] > title[1], tag
            assert (scale[0] - title[2]) / CM >= 0.3, tag
        else:  # under it
            assert scale[1] >= title[3], tag
