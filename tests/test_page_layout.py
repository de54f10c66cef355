"""The page of every worked problem, looked at in headless Chromium at a desktop width and
on a phone (390 px): at 24 crank angles each polygon fills a good part of its panel (where
the motion is not near rest), nothing is drawn outside its panel, each drawn point and
vector has a tooltip of its own (an SVG <title>), the scale stated beside each diagram is
round and is the one it is drawn at, and on the phone the page never scrolls sideways.

One page load per problem and width; the frames are stepped with the page's own slider.
The measures are the browser's (getBoundingClientRect of what is drawn against the panel's),
and what is "near rest" is found from the frames' velocities and accelerations, not from
the page's script. Skips where Playwright or Chromium is missing, as the other browser
tests do."""

import glob
import json
import math
from pathlib import Path

import numpy as np
import pytest

from polygon_method.cli import main


ROOT = Path(__file__).resolve().parents[1]
WORKED = sorted(glob.glob(str(ROOT / "worked_problems" / "*.toml")))
WIDTHS = {"desktop": (1280, 900), "phone": (390, 844)}
ANGLES = 24
#: a polygon at most this share of its median size over the cycle is "near rest"
NEAR_REST = 0.05
#: a polygon spans at least this share of its panel (across or up, the larger)
SPAN = 0.25
#: rounding of the browser's pixel boxes
PX = 1.0

# One frame measured in the page: each diagram's panel and everything drawn in it
# (CSS px), the stated scale, whether every drawn point and vector has a <title>.
MEASURE = """(ks) => {
  const out = [], slider = document.getElementById('angle');
  for (const k of ks) {
    slider.value = k; slider.dispatchEvent(new Event('input'));
    const f = {k: k, panels: {}, scroll: [document.documentElement.scrollWidth, window.innerWidth]};
    for (const id of ['configuration', 'velocity', 'acceleration']) {
      const svg = document.getElementById(id), r = svg.getBoundingClientRect();
      const drawn = [...svg.querySelectorAll('line, circle, polygon, polyline, path, text')]
        .filter((e) => !e.closest('defs') && getComputedStyle(e).display !== 'none');
      const box = (e) => { const b = e.getBoundingClientRect(); return [b.left, b.top, b.right, b.bottom]; };
      const untitled = drawn.filter((e) => !(e.querySelector(':scope > title') &&
        e.querySelector(':scope > title').textContent.trim())).map((e) => e.outerHTML.slice(0, 80));
      f.panels[id] = {panel: [r.left, r.top, r.right, r.bottom],
        items: drawn.map((e) => [e.tagName, e.getAttribute('class') || '', box(e)]),
        vectors: drawn.filter((e) => e.tagName !== 'text').map(box),
        untitled: untitled, scale: document.getElementById('scale-' + id).textContent,
        perCm: Number(svg.dataset.perCm)};
    }
    out.push(f);
  }
  return out;
}"""


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    d = tmp_path_factory.mktemp("layout")
    out = {}

    def page(scene):
        if scene not in out:
            path = d / (Path(scene).stem + ".html")
            assert main(["page", scene, "-o", str(path)]) == 0
            out[scene] = path
        return out[scene]

    return page


def _extents(data, table) -> np.ndarray:
    """Per frame, the extent (SI) of a polygon: its images and the pole (the frames' own
    vectors, not the page's drawing)."""
    n = len(data["theta"])
    xy = [np.zeros((n, 2))] + [np.array(data[table][p]).reshape(n, 2) for p in data["points"]]
    xy = np.stack(xy)  # (points, frames, 2)
    return np.max(xy.max(axis=0) - xy.min(axis=0), axis=1)


def _round(scale: str, unit: str) -> bool:
    words = scale.split()
    if words[:3] != ["1", "cm", "="] or len(words) != 5 or words[4] != unit:
        return False
    v = float(words[3])
    m = v / 10 ** math.floor(math.log10(v) + 1e-12)
    return min(abs(m - r) for r in (1, 2, 5)) < 1e-9


@pytest.mark.parametrize("width", sorted(WIDTHS))
@pytest.mark.parametrize("scene", WORKED, ids=lambda s: Path(s).stem)
def test_every_angle_fills_its_panels_and_stays_inside(browser, pages, scene, width):
    w, h = WIDTHS[width]
    page = browser.new_page(viewport={"width": w, "height": h})
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    try:
        page.goto(pages(scene).as_uri())
        data = json.loads(page.evaluate("document.getElementById('frames').textContent"))
        n = len(data["theta"])
        ks = sorted({round(j * (n - 1) / (ANGLES - 1)) for j in range(ANGLES)})
        assert len(ks) == ANGLES
        frames = page.evaluate(MEASURE, ks)
    finally:
        page.close()
    assert errors == []
    units = {"configuration": data["units"], "velocity": "m/s", "acceleration": "m/s²"}
    size = {"velocity": _extents(data, "V"), "acceleration": _extents(data, "A")}
    rest = {k: NEAR_REST * float(np.median(v)) for k, v in size.items()}
    filled = 0
    for f in frames:
        k = f["k"]
        if width == "phone":  # the page never scrolls sideways
            assert f["scroll"][0] <= f["scroll"][1], (k, f["scroll"])
        for phase, p in f["panels"].items():
            x0, y0, x1, y1 = p["panel"]
            assert x1 <= w + PX  # the panel itself is on the screen's width
            for tag, cls, (a, b, c, d) in p["items"]:
                assert a >= x0 - PX and b >= y0 - PX and c <= x1 + PX and d <= y1 + PX, (
                    phase,
                    k,
                    tag,
                    cls,
                    (a, b, c, d),
                    p["panel"],
                )
            assert p["untitled"] == [], (phase, k, p["untitled"])
            assert _round(p["scale"], units[phase]), (phase, k, p["scale"])
            if phase == "configuration" or size[phase][k] <= rest[phase]:
                continue
            vx = np.array(p["vectors"])
            across = (vx[:, 2].max() - vx[:, 0].min()) / (x1 - x0)
            up = (vx[:, 3].max() - vx[:, 1].min()) / (y1 - y0)
            assert max(across, up) >= SPAN, (phase, k, across, up, p["scale"])
            filled += 1
    assert filled >= ANGLES  # the test looked at polygons, not only at rest frames


def test_the_animation_player_works_offline(browser, tmp_path):
    """draw --animate to HTML opened with every request but its own file refused: nothing
    else is asked for, play moves the frames, and its buttons have text (no icon font)."""
    out = tmp_path / "cycle.html"
    assert (
        main(
            [
                "draw",
                str(ROOT / "worked_problems" / "crank_slotted_lever.toml"),
                "--animate",
                "-o",
                str(out),
                "--frames",
                "12",
            ]
        )
        == 0
    )
    page = browser.new_page(viewport={"width": 390, "height": 844})
    asked, errors = [], []
    url = out.as_uri()

    def route(r):
        asked.append(r.request.url)
        if r.request.url == url or r.request.url.startswith("data:"):
            r.continue_()
        else:
            r.abort()

    page.route("**/*", route)
    page.on("pageerror", lambda e: errors.append(str(e)))
    try:
        page.goto(url)
        first = page.text_content("#now")
        page.click("#play")
        page.wait_for_timeout(500)
        page.click("#play")
        assert page.text_content("#now") != first
        assert all(page.text_content(b).strip() for b in ("#play", "#back", "#next"))
        assert page.evaluate("document.documentElement.scrollWidth <= innerWidth")
    finally:
        page.close()
    assert errors == [] and [a for a in asked if not a.startswith("data:")] == [url]
