"""The page printed as a class's handout, and used with a finger on a phone.

Without a browser: the page's step-by-step solution is written as a book prints it
(v<sub>B</sub>, ω<sub>BC</sub>, m/s², 60°, 10.5 × 0.05), where it printed the terminal's
ASCII (v_B, omega_BC, m/s^2, 60 deg, 10.5 x 0.05), and says every number the step table
says, in order (read from ``steps_blocks``, the same words ``steps`` prints).

In headless Chromium: printed (print media, at the width A4 leaves inside 12 mm margins,
186 mm = 703 CSS px), nothing is wider than the paper and no table is cut at its edge (a
wide table scrolled inside its box on the screen, which on paper is cut off), the play
button and the slider are left out and the angle kept, a diagram, a plot and a table's
row are never split across sheets, and the folded step table is opened for the paper and
folded again after; the PDF Chromium prints is A4, page by page. On a phone (390 px), the
controls are targets of 44 px at least (they were about 30 px)."""

import re
from html import unescape
from pathlib import Path

import pytest

from polygon_method import load_scene, solve
from polygon_method.cli import main
from polygon_method.text.steptable import steps_blocks

ROOT = Path(__file__).resolve().parents[1]
WORKED = ROOT / "worked_problems"
SCENES = ["fourbar_image_points", "crank_slotted_lever", "engine_forces", "collar_on_turning_rod"]
#: A4 less 12 mm margins each side, in CSS px (96 to the inch)
PRINTED = round((210 - 2 * 12) / 25.4 * 96)
A4_PT = (595.28, 841.89)


def _page(tmp_path, scene, frames="12"):
    out = tmp_path / f"{Path(scene).stem}.html"
    assert main(["page", str(WORKED / f"{scene}.toml"), "-o", str(out), "--frames", frames]) == 0
    return out


def _numbers(text):
    """The numbers of a text, squares and cubes left out (``^2`` is printed ²)."""
    text = re.sub(r"\^[23]\b|[²³]", "", text)
    return re.findall(r"\d+(?:\.\d+)?", text)


def _source_words(blocks):
    for b in blocks:
        if b[0] in ("h", "p"):
            yield b[1]
        elif b[0] == "list":
            yield from b[1]
        elif b[0] == "table":
            yield from b[1]
            for row in b[2]:
                yield from row


@pytest.mark.parametrize("scene", SCENES)
def test_the_step_table_on_the_page_is_written_as_a_book_prints_it(tmp_path, scene):
    html = _page(tmp_path, scene).read_text(encoding="utf-8")
    part = html[html.index("<h2>Step by step") : html.index("<footer>")]
    part = part[: part.index('<table id="check"')] if 'id="check"' in part else part
    shown = unescape(re.sub(r"<[^>]+>", " ", part))
    for ascii_ in ("^2", "omega", "alpha", " deg"):
        assert ascii_ not in shown, ascii_
    assert not re.search(r"(?<![\w-])[A-Za-z]_[A-Za-z0-9]", shown)  # v_B: v<sub>B</sub>
    assert not re.search(r"\d x \d", shown)  # 10.5 x 0.05: 10.5 × 0.05
    assert "ω" in shown and "²" in shown and "×" in shown
    assert "<sub>" in part and "x axis" not in shown.replace("x axis", "")  # (kept: words)
    blocks = steps_blocks(solve(load_scene(str(WORKED / f"{scene}.toml")))).blocks
    said = [n for w in _source_words(b for b in blocks if b[0] != "title") for n in _numbers(w)]
    assert _numbers(shown.replace("×", " ").replace("°", " "))[: len(said)] == said


OVERFLOW = """() => [...document.querySelectorAll('body *')]
  .filter(e => getComputedStyle(e).display !== 'none' && !e.closest('svg, #tooltip'))
  .filter(e => e.getBoundingClientRect().right > document.documentElement.clientWidth + 1
               || (e.tagName === 'TABLE' || e.classList.contains('scroll'))
                  && e.scrollWidth > e.clientWidth + 1)
  .map(e => e.tagName + '.' + e.className + ' ' + Math.round(e.getBoundingClientRect().right))"""


def _printed(browser, path):
    page = browser.new_page(viewport={"width": PRINTED, "height": 1000})
    page.goto(path.as_uri())
    page.emulate_media(media="print")
    return page


@pytest.mark.parametrize("scene", ["fourbar_image_points", "engine_flywheel"])
def test_the_printed_page_fits_the_paper_and_leaves_the_controls_out(browser, tmp_path, scene):
    page = _printed(browser, _page(tmp_path, scene))
    try:
        page.evaluate("window.dispatchEvent(new Event('beforeprint'))")
        assert page.evaluate("document.documentElement.scrollWidth") <= PRINTED
        assert page.evaluate(OVERFLOW) == []
        shown = page.evaluate(
            """() => [...document.querySelectorAll('#play, #angle, #angle-now')]
               .map(e => getComputedStyle(e).display !== 'none')"""
        )
        assert shown == [False, False, True]
        assert re.match(r"θ = \d", page.inner_text("#angle-now"))
        kept = page.evaluate(
            """() => [...document.querySelectorAll('figure, svg.plot, tbody tr')]
               .map(e => getComputedStyle(e).breakInside)"""
        )
        assert kept and set(kept) == {"avoid"}
        pdf = page.pdf(format="A4", margin={k: "12mm" for k in ("top", "bottom", "left", "right")})
    finally:
        page.close()
    boxes = re.findall(rb"/MediaBox\s*\[\s*0 0 ([\d.]+) ([\d.]+)\s*\]", pdf)
    # (Chromium rounds the sheet to its own units: within 1.5 pt, half a millimetre)
    assert boxes and all((float(w), float(h)) == pytest.approx(A4_PT, abs=1.5) for w, h in boxes)


def test_the_folded_step_table_is_printed_open_and_folded_again(browser, tmp_path):
    out = tmp_path / "press.html"
    assert main(["page", str(WORKED / "flywheel" / "punching_press.toml"), "-o", str(out)]) == 0
    page = _printed(browser, out)
    try:
        opened = "() => [...document.querySelectorAll('details')].map(d => d.open)"
        before = page.evaluate(opened)
        assert False in before  # the step table, folded on the screen
        page.evaluate("window.dispatchEvent(new Event('beforeprint'))")
        assert all(page.evaluate(opened))
        assert page.evaluate(OVERFLOW) == []
        page.evaluate("window.dispatchEvent(new Event('afterprint'))")
        assert page.evaluate(opened) == before
    finally:
        page.close()


@pytest.mark.parametrize("scene", ["fourbar_image_points", "flywheel/punching_press"])
def test_on_a_phone_the_controls_are_targets_for_a_finger(browser, tmp_path, scene):
    out = tmp_path / "p.html"
    assert main(["page", str(WORKED / f"{scene}.toml"), "-o", str(out)]) == 0
    page = browser.new_page(viewport={"width": 390, "height": 844}, has_touch=True)
    try:
        page.goto(out.as_uri())
        for sel in ("#play", "#angle"):
            box = page.locator(sel).bounding_box()
            assert box["height"] >= 44 and box["width"] >= 44, (sel, box)
        assert page.evaluate("document.documentElement.scrollWidth") <= 390
    finally:
        page.close()


#: the least size (CSS px) a word of the page is drawn at, on a desktop and on a phone
#: (the plots' ticks were 8.2 px at 1280 px, a turning-moment plot's 8.1 px at 390 px)
READABLE = 10.5

SIZES = """() => {
  const out = [];
  for (const t of document.querySelectorAll('svg text')) {
    if (t.closest('defs') || !t.textContent.trim() || !t.getClientRects().length) continue;
    const m = t.getScreenCTM(), svg = t.ownerSVGElement;
    const r = t.getBoundingClientRect(), s = svg.getBoundingClientRect();
    const size = parseFloat(getComputedStyle(t).fontSize) * Math.hypot(m.a, m.b);
    const inside = r.left >= s.left - 1 && r.right <= s.right + 1;
    out.push([svg.id + ': ' + t.textContent.slice(0, 30), size, inside]);
  }
  for (const e of document.querySelectorAll('body *')) {
    if (e.closest('svg') || !e.getClientRects().length) continue;
    if (![...e.childNodes].some((n) => n.nodeType === 3 && n.textContent.trim())) continue;
    out.push([e.tagName + ': ' + e.textContent.trim().slice(0, 30), parseFloat(getComputedStyle(e).fontSize), true]);
  }
  return out;
}"""


@pytest.mark.parametrize("width", [1280, 390])
@pytest.mark.parametrize(
    "scene", ["fourbar_image_points", "engine_flywheel", "flywheel/punching_press"]
)
def test_every_word_of_the_page_is_readable_and_inside_its_plot(browser, tmp_path, scene, width):
    out = tmp_path / "p.html"
    assert main(["page", str(WORKED / f"{scene}.toml"), "-o", str(out), "--frames", "36"]) == 0
    page = browser.new_page(viewport={"width": width, "height": 900})
    try:
        page.goto(out.as_uri())
        sizes = page.evaluate(SIZES)
    finally:
        page.close()
    assert len(sizes) > 50
    small = [(w, round(s, 1)) for w, s, _ in sizes if s < READABLE]
    assert small == []
    assert [w for w, _, inside in sizes if not inside] == []
