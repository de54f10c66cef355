"""Sheets that print: every worked and textbook problem's sheet on A4, A3 and letter, measured
in the written files (the SVG's width and height, the PDF's MediaBox of every page), every
drawn thing inside the page's margins, and the stated scales true on the paper (the crank
measured from its pivot to its pin against the scene's crank length; the crank pin's
velocity against omega times that length; the scale read back from the sheet's own text)."""

import glob
import math
import re
import subprocess
import sys
import unicodedata
from pathlib import Path

import pytest

from polygon_method import load_scene, solve
from polygon_method.draw import drawn_vectors, layout, page_files, paginate, render_pages
from polygon_method.draw.paper import FOOTER, MARGIN, PAPERS, room
from polygon_method.draw.sheet import _panel_size, write_pages
from polygon_method.common.errors import PolygonMethodError
from polygon_method.polygons.scales import diagram_scales
from test_draw import CM, SVGNS, WORKED, XLINK, Svg

ROOT = Path(__file__).resolve().parents[1]
TEXTBOOK = sorted(glob.glob(str(ROOT / "tests" / "textbook" / "*.toml")))
PROBLEMS = WORKED + TEXTBOOK
PT = 72 / 2.54  # points per cm


def _stem(path):
    return f"{Path(path).parent.name}/{Path(path).stem}"


_CHARS = {}


def _said(svg, gid):
    """The text of a note, read back from the glyphs the SVG draws it with (a glyph's id
    ends in its index in the font: the font's character map names it; a ligature is
    written out), spaces left out."""
    if not _CHARS:
        from matplotlib import font_manager
        from matplotlib.ft2font import FT2Font
        from polygon_method.draw.style import FONT

        font = FT2Font(font_manager.findfont(FONT))
        _CHARS.update(
            {glyph: chr(code) for code, glyph in sorted(font.get_charmap().items(), reverse=True)}
        )
    out = []
    for use in svg.groups[gid].iter(SVGNS + "use"):
        code = re.search(r"-([0-9a-f]+)$", use.get(XLINK))
        out.append(_CHARS[int(code.group(1), 16)])
    return unicodedata.normalize("NFKC", "".join(out)).replace(" ", "")


def _centre(svg, gid):
    pts = svg.path(gid)
    xs, ys = [p[0] for p in pts], [p[1] for p in pts]
    return ((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2)


def _pdf_pages(data):
    """The MediaBox of every page of a PDF (pt), from its page objects (not compressed)."""
    text = data.decode("latin-1")
    boxes = re.findall(r"/Type /Page\b.*?/MediaBox \[\s*([-\d.\s]+)\]", text, flags=re.S)
    return [tuple(float(x) for x in b.split()) for b in boxes]


def _drawn_boxes(svg):
    """The bounding box (pt) of every path drawn (not a glyph's outline in its
    definitions) and of every text (its glyphs, placed)."""
    glyphs = {id(p) for d in svg.root.iter(SVGNS + "defs") for p in d.iter(SVGNS + "path")}
    out = []
    for gid, g in svg.groups.items():
        if gid.startswith(("figure_", "axes_", "patch_", "panel-")):
            continue
        if any(True for _ in g.iter(SVGNS + "use")):
            b = svg.text_box(gid)
            if b is not None:
                out.append(b.bounds)
            continue
        for p in g.iter(SVGNS + "path"):
            if id(p) in glyphs:
                continue
            pts = [
                (float(x), float(y))
                for x, y in re.findall(r"(-?[\d.]+) (-?[\d.]+)", p.get("d") or "")
            ]
            if pts:
                out.append(
                    (
                        min(x for x, _ in pts),
                        min(y for _, y in pts),
                        max(x for x, _ in pts),
                        max(y for _, y in pts),
                    )
                )
    return out


def _check_page(svg, page, paper):
    """The page is the paper's size (either way round), and everything drawn on it lies
    inside its margins."""
    w, h = svg.size_cm()
    pw, ph = PAPERS[paper]
    want = (pw, ph) if page.orientation == "portrait" else (ph, pw)
    assert (w, h) == pytest.approx(want, abs=1e-4), (paper, page.orientation)
    boxes = _drawn_boxes(svg)
    assert len(boxes) > 10
    x0 = min(b[0] for b in boxes) / CM
    y0 = min(b[1] for b in boxes) / CM
    x1 = max(b[2] for b in boxes) / CM
    y1 = max(b[3] for b in boxes) / CM
    tol = 0.02  # a line's half width at a panel's padding
    assert x0 >= MARGIN - tol and y0 >= MARGIN - tol, (x0, y0)
    assert x1 <= w - MARGIN + tol and y1 <= h - MARGIN + tol, (x1, y1, w, h)
    assert "note-sheet-paper" in svg.groups
    said = _said(svg, "note-sheet-paper")
    assert said.startswith(f"{paper}{page.orientation}") and "100%" in said, said


def _check_scales(svg, sol, used):
    """Every panel on the page states its scale (read from the page), the one the step
    table states; the crank and the crank pin's velocity measure true to it."""
    sc = sol.scene
    inp = sc.input
    for name, s in used.items():
        if f"note-{name}-scale" not in svg.groups:
            continue
        said = _said(svg, f"note-{name}-scale")
        assert said == s.text.replace(" ", "").replace("^2", "2"), (said, s.text)
    measured = 0
    # the crank, or for a mechanism driven by a block, its first link between two joints
    # (none in a trammel, whose one link joins two blocks, nor on a sheet without the
    # configuration diagram: the polygons' page of two)
    first = (
        next(lk for lk in sc.links if lk.key == inp.crank)
        if inp.crank is not None
        else next(
            (
                lk
                for lk in sc.links
                if f"joint-{lk.p}" in svg.groups and f"joint-{lk.q}" in svg.groups
            ),
            None,
        )
    )
    if (
        first is not None
        and f"joint-{first.p}" in svg.groups
        and "note-configuration-scale" in svg.groups
    ):
        got = math.dist(_centre(svg, f"joint-{first.p}"), _centre(svg, f"joint-{first.q}"))
        assert got / CM * used["configuration"].per_cm == pytest.approx(first.length, rel=1e-5)
        measured += 1
    if "note-velocity-scale" in svg.groups and inp.block is not None:
        collar = not hasattr(sc.slider(inp.block), "through")  # its sliding is given
        kind, name = ("sliding", f"vs_{inp.block}") if collar else ("absolute", f"v_{inp.block}")
        n = next(
            k
            for k, v in enumerate(drawn_vectors(sol, "velocity"))
            if v.kind == kind and v.name == name
        )
        tail = svg.path(f"velocity-vector-{n}-shaft")[0]
        tip = svg.path(f"velocity-vector-{n}-head")[0]
        got = math.dist(tail, tip) / CM * used["velocity"].per_cm
        assert got == pytest.approx(abs(inp.omega), rel=1e-5)  # the block's given speed
        measured += 1
    elif "note-velocity-scale" in svg.groups and inp.pivot in sc.ground:
        crank = next(lk for lk in sc.links if lk.key == inp.crank)
        n = next(
            k
            for k, v in enumerate(drawn_vectors(sol, "velocity"))
            if v.kind == "absolute" and v.name == f"v_{inp.tip}"
        )
        tail = svg.path(f"velocity-vector-{n}-shaft")[0]
        tip = svg.path(f"velocity-vector-{n}-head")[0]
        got = math.dist(tail, tip) / CM * used["velocity"].per_cm
        assert got == pytest.approx(abs(inp.omega) * crank.length, rel=1e-5)
        measured += 1
    return measured


_PANELS = {}


def _panels(path):
    if path not in _PANELS:
        sol = solve(load_scene(path))
        panels = layout(sol, "all")
        _PANELS[path] = sol, panels, [_panel_size(sk) for _, _, sk in panels]
    return _PANELS[path]


#: the worked problems written on every paper (the others written on A4 and laid out on
#: A3 and letter): a four-bar, a slider crank, a six-bar, a quick return, gears, an engine
ALL_PAPERS = (
    "fourbar_image_points",
    "offset_slider_crank",
    "six_link_second_slider",
    "whitworth",
    "gear_train_given_gear",
    "engine_forces",
)


def _cases():
    """Each worked problem written on A4 as SVG and PDF, six of them on the three papers,
    the rest laid out on A3 and letter (the pages' sizes and places, not written); each
    textbook problem written on A4 as SVG, and laid out on A3 and letter (the corpus is 91
    problems, and writing each three times over, and as PDF, is minutes of the suite)."""
    for path in WORKED:
        every = Path(path).stem in ALL_PAPERS
        yield pytest.param(
            path,
            ("A4", "A3", "letter") if every else ("A4",),
            () if every else ("A3", "letter"),
            True,
            id=_stem(path),
        )
    for path in TEXTBOOK:
        yield pytest.param(path, ("A4",), ("A3", "letter"), False, id=_stem(path))


def test_the_worked_problems_written_on_every_paper_exist():
    assert {Path(p).stem for p in WORKED} >= set(ALL_PAPERS)


@pytest.mark.parametrize("path,written,laid_out,pdf", list(_cases()))
def test_every_sheet_is_on_its_paper_inside_the_margins_and_true_to_scale(
    path, written, laid_out, pdf
):
    sol, panels, sizes = _panels(path)
    used = {name: s for name, s, _ in panels}
    # the scales the step table states, on every paper
    assert [used[n].text for n in ("configuration", "velocity", "acceleration")] == [
        s.text for s in diagram_scales(sol)
    ]
    for paper in written + laid_out:
        pages = paginate(sizes, paper, panels=[name for name, _, _ in panels])
        assert sorted(k for p in pages for k, _, _ in p.placed) == [0, 1, 2]  # each once
        for page in pages:
            W, H = page.size
            assert sorted(page.size) == sorted(PAPERS[paper])
            for k, x, y in page.placed:  # inside the margins, clear of the foot's line
                assert x >= MARGIN - 1e-9 and y >= MARGIN - 1e-9
                assert x + sizes[k][0] <= W - MARGIN + 1e-9
                assert y + sizes[k][1] <= H - MARGIN - FOOTER + 1e-9
            # panels on one page do not overlap one another
            rects = [(x, y, x + sizes[k][0], y + sizes[k][1]) for k, x, y in page.placed]
            for i, a in enumerate(rects):
                for b in rects[i + 1 :]:
                    assert (
                        a[2] <= b[0] + 1e-9
                        or b[2] <= a[0] + 1e-9
                        or a[3] <= b[1] + 1e-9
                        or b[3] <= a[1] + 1e-9
                    )
        if paper not in written:
            continue
        svgs, warnings = write_pages(panels, sizes, pages, "svg")
        assert warnings == [] and len(svgs) == len(pages)
        measured = 0
        for text, page in zip(svgs, pages):
            svg = Svg(text)
            _check_page(svg, page, paper)
            measured += _check_scales(svg, sol, used)
        assert measured == 2  # the crank and its pin's velocity, each on some page
        if not pdf:
            continue
        (data,), _ = write_pages(panels, sizes, pages, "pdf")
        boxes = _pdf_pages(data)
        assert len(boxes) == len(pages)
        for box, page in zip(boxes, pages):
            assert (box[2] - box[0], box[3] - box[1]) == pytest.approx(
                (page.size[0] * PT, page.size[1] * PT), abs=1e-3
            )


def test_a4_holds_every_sheet_on_at_most_two_pages_and_a3_on_one():
    """Not a rule of the layout: what the worked and textbook problems come to (a sheet
    that needed three A4 pages, or two A3 pages, would be worth a look)."""
    for path in PROBLEMS:
        _, panels, sizes = _panels(path)
        assert len(paginate(sizes, "A4")) <= 2, path
        assert len(paginate(sizes, "A3")) == 1, path


def test_the_layout_keeps_order_and_never_shrinks():
    # three that fit side by side on landscape A4 (28.1 cm of room) go there
    (page,) = paginate([(9.0, 10.0), (9.0, 11.0), (8.0, 13.5)], "A4")
    assert page.orientation == "landscape" and [k for k, _, _ in page.placed] == [0, 1, 2]
    xs = [x for _, x, _ in page.placed]
    assert xs == sorted(xs)
    # one of 19.9 cm is too wide for portrait A4 (19.8 cm inside the margins), not landscape
    (page,) = paginate([(19.9, 10.0)], "A4")
    assert page.orientation == "landscape"
    (page,) = paginate([(19.7, 27.9)], "A4")
    assert page.orientation == "portrait"
    # too tall for A4 either way: two pages, in order
    pages = paginate([(15.0, 20.0), (15.0, 20.0)], "A4")
    assert [p.placed[0][0] for p in pages] == [0, 1] and [p.count for p in pages] == [2, 2]
    assert room("A4", "portrait") == pytest.approx((21.0 - 2 * MARGIN, 29.7 - 2 * MARGIN - FOOTER))
    assert paginate([(15.0, 20.0), (15.0, 20.0)], "A3")[0].orientation == "landscape"


def test_a_diagram_larger_than_the_paper_is_one_line():
    with pytest.raises(PolygonMethodError) as e:
        paginate(
            [(25.0, 30.0)],
            "A4",
            names=["the velocity polygon at 1 cm = 0.01 m/s"],
            advice="; draw it on A3 (--paper A3) or at a coarser --scale",
        )
    text = str(e.value)
    assert "\n" not in text and "velocity polygon at 1 cm = 0.01 m/s" in text
    assert "25 x 30 cm" in text and "--paper A3" in text
    with pytest.raises(PolygonMethodError, match="unknown paper 'B5'"):
        paginate([(5.0, 5.0)], "B5")


def test_page_files_are_named_predictably():
    assert [str(p) for p in page_files("d/sheet.png", 1)] == ["d/sheet.png"]
    assert [p.name for p in page_files("d/sheet.png", 2)] == ["sheet-1.png", "sheet-2.png"]


def _draw(argv):
    """``main(["draw", ...])`` in this process: (exit code, stdout, stderr)."""
    import contextlib
    import io

    from polygon_method.cli import main

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(["draw"] + [str(a) for a in argv])
    return code, out.getvalue(), err.getvalue()


def test_the_command_writes_a_file_a_page_and_says_which(tmp_path):
    """The real entry point once (a process, as a user runs it), then ``main`` in this
    process for the rest."""
    scene = ROOT / "worked_problems" / "fourbar_image_points.toml"
    run = [sys.executable, "-m", "polygon_method", "draw", str(scene)]
    env = {"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"}
    out = subprocess.run(
        run + ["-o", str(tmp_path / "s.svg")], capture_output=True, text=True, env=env
    )
    assert out.returncode == 0, out.stderr
    files = sorted(p.name for p in tmp_path.iterdir())
    _, panels, sizes = _panels(str(scene))
    pages = paginate(sizes, "A4")
    want = [p.name for p in page_files(tmp_path / "s.svg", len(pages))]
    assert files == sorted(want)
    for name in want:
        assert str(tmp_path / name) in out.stdout
    # the same bytes again
    code, _, err = _draw([scene, "-o", tmp_path / "t.svg"])
    assert code == 0, err
    for a, b in zip(
        page_files(tmp_path / "s.svg", len(pages)), page_files(tmp_path / "t.svg", len(pages))
    ):
        assert a.read_bytes() == b.read_bytes()
    # A3 holds it on one page, under the name given; a PDF is one file of as many pages
    code, said, _ = _draw([scene, "-o", tmp_path / "a3.pdf", "--paper", "a3"])
    assert code == 0 and "A3" in said
    assert len(_pdf_pages((tmp_path / "a3.pdf").read_bytes())) == 1
    code, _, _ = _draw([scene, "-o", tmp_path / "a4.pdf"])
    assert code == 0
    assert len(_pdf_pages((tmp_path / "a4.pdf").read_bytes())) == len(pages)
    # a paper it does not know, and a scale that makes a diagram larger than the paper:
    # one line each, exit 2, nothing written
    for extra, words in (
        (["--paper", "B5"], "unknown paper 'B5'"),
        (["--scale", "1 cm = 0.01 m/s"], "more than A4 holds"),
    ):
        code, _, err = _draw([scene, "-o", tmp_path / "bad.svg"] + extra)
        assert code == 2 and words in err, err
        assert len(err.strip().splitlines()) == 1
        assert not list(tmp_path.glob("bad*"))


def test_every_page_of_render_pages_states_its_paper():
    sol = solve(load_scene(ROOT / "worked_problems" / "whitworth.toml"))
    for paper in ("A4", "letter"):
        datas, used, warnings, pages = render_pages(sol, "svg", "velocity", paper=paper)
        (text,), (page,) = datas, pages
        svg = Svg(text)
        _check_page(svg, page, paper)
        assert list(used) == ["velocity"]
