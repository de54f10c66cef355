"""The page's forces, moving with the mechanism, looked at in headless Chromium at a desktop
width (1280 px) and on a phone (390 px): with the layer of the joints' forces turned on,
frame by frame, every body's drawn forces (its pin, guide and contact forces, the driver's,
its inertia force on its line, its loads and weight) and couples balance: their sum and
their moment about the origin are zero to 1e-9 of the frame's largest force (times the
mechanism's size). Each arrow is checked as drawn: it starts at its point of application
and runs along its force, as long as the stated force scale makes it. A joint's force is
drawn once, as the force on `on` by `by` (the book's F32): the other body feels its
opposite. The page loads with no error, never scrolls sideways, and the toggle hides and
shows the layer.

The balance is an independent check of what is drawn: the numbers are read back from the
drawn elements (their data, as the script drew them), the bodies summed here. Skips where
Playwright or Chromium is missing, as the other browser tests do."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from polygon_method import load_scene
from polygon_method.page.frames import frames
from polygon_method.page.html import page_html
from polygon_method.polygons.scales import parse_scale
from test_forces import with_forces
from test_forces_rolling import _driving_wheel, _with

ROOT = Path(__file__).resolve().parents[1]
WORKED = ROOT / "worked_problems"
FRAMES = 24
#: the frames stepped through on each page
STEPS = (0, 3, 7, 11, 16, 22)
WIDTHS = {"desktop": (1280, 900), "phone": (390, 844)}


def _scenes():
    racks = _with(
        ROOT / "tests" / "textbook" / "rolling_pinion_two_racks.toml",
        {"OA": {"mass": 1, "along": 0, "gyration": 30}, "R1": {"mass": 2}, "R2": {"mass": 3}},
        {"R1": {"force": [100, -30]}},
    )
    return {
        "fourbar": lambda: load_scene(WORKED / "fourbar_forces.toml"),
        "engine": lambda: load_scene(WORKED / "engine_forces.toml"),
        "gears": lambda: load_scene(WORKED / "gear_pair_forces.toml"),
        "racks": lambda: racks,
        "wheel": _driving_wheel,
        "yoke": lambda: with_forces(load_scene(WORKED / "scotch_yoke.toml"), 3),
        "slotted": lambda: with_forces(load_scene(WORKED / "crank_slotted_lever.toml"), 3),
        "peg": lambda: with_forces(load_scene(WORKED / "shaper_ram_pin_in_slot.toml"), 3),
        "block": lambda: with_forces(load_scene(WORKED / "ellipse_trammel.toml"), 3),
        "cylinder": lambda: with_forces(load_scene(WORKED / "tipper_cylinder.toml"), 3),
        "pulled": lambda: load_scene(WORKED / "cylinder_pull_on_rocker.toml"),  # a given force
        "spring": lambda: load_scene(WORKED / "cylinder_spring_damper_on_rocker.toml"),
        "triad": lambda: load_scene(WORKED / "class3_six_bar_forces.toml"),
    }


SCENES = _scenes()
PHONE = ("fourbar", "gears", "slotted")

READ = """(ks) => {
  const out = [], slider = document.getElementById('angle');
  const svg = document.getElementById('configuration');
  for (const k of ks) {
    slider.value = k; slider.dispatchEvent(new Event('input'));
    const items = [...svg.querySelectorAll('.force, .couple, .inertia-force, .inertia-couple')].map((e) => ({
      cls: e.getAttribute('class'), on: e.dataset.on, by: e.dataset.by || '', what: e.dataset.what || '',
      x: Number(e.dataset.x), y: Number(e.dataset.y), fx: Number(e.dataset.fx || 0),
      fy: Number(e.dataset.fy || 0), c: Number(e.dataset.c || 0),
      shown: getComputedStyle(e).display !== 'none',
      line: e.tagName === 'line' ? ['x1', 'y1', 'x2', 'y2'].map((a) => Number(e.getAttribute(a))) : null,
      title: (e.querySelector(':scope > title') || {}).textContent || '',
      box: (({left, top, right, bottom}) => [left, top, right, bottom])(e.getBoundingClientRect())}));
    const r = svg.getBoundingClientRect();
    out.push({k: k, per: Number(svg.dataset.perCm), items: items, panel: [r.left, r.top, r.right, r.bottom],
      scroll: [document.documentElement.scrollWidth, window.innerWidth]});
  }
  return out;
}"""


def _balance(frame, numbers):
    """Each body's sum of forces and of moments about the origin, from what is drawn; the
    frame's largest force and the size the moments are measured against."""
    sums = {b: [0.0, 0.0, 0.0] for b in numbers}
    big, size = 0.0, 0.0

    def add(body, fx, fy, x, y):
        if body in sums:  # (the frame's own balance is not asked for)
            s = sums[body]
            s[0] += fx
            s[1] += fy
            s[2] += x * fy - y * fx

    for it in frame["items"]:
        if it["cls"] in ("couple", "inertia-couple"):
            if it["on"] in sums:
                sums[it["on"]][2] += it["c"]
            continue
        fx, fy, x, y = it["fx"], it["fy"], it["x"], it["y"]
        big = max(big, math.hypot(fx, fy))
        size = max(size, math.hypot(x, y))
        add(it["on"], fx, fy, x, y)
        if it["by"]:  # a joint's force: its other body feels the opposite
            add(it["by"], -fx, -fy, x, y)
    return sums, big, size


@pytest.mark.parametrize(
    "name, width",
    [(n, "desktop") for n in SCENES] + [(n, "phone") for n in PHONE],
)
def test_every_body_drawn_on_the_page_balances_frame_by_frame(browser, tmp_path, name, width):
    sc = SCENES[name]()
    fr = frames(sc, FRAMES)
    html = page_html(fr)
    path = tmp_path / f"{name}.html"
    path.write_text(html)
    w, h = WIDTHS[width]
    page = browser.new_page(viewport={"width": w, "height": h})
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("console", lambda m: errors.append(m.text) if m.type in ("error", "warning") else None)
    page.route("**/*", lambda r: r.continue_() if r.request.url == path.as_uri() else r.abort())
    page.goto(path.as_uri())
    shown = "() => [...document.querySelectorAll('#configuration .force')].filter((e) => getComputedStyle(e).display !== 'none').length"
    assert page.evaluate(shown) == 0  # the layer is off until asked for
    page.check("#show-forces")
    frames_read = page.evaluate(READ, list(STEPS))
    # (near a limit position the forces grow without bound: elsewhere they may be short)
    assert any(it["shown"] and it["cls"] == "force" for fr_ in frames_read for it in fr_["items"])
    numbers = page.evaluate(
        "() => JSON.parse(document.getElementById('frames').textContent).forces.numbers"
    )
    stated = page.evaluate("() => JSON.parse(document.getElementById('frames').textContent).forces")
    per = parse_scale(stated["text"].replace("\u00b2", "^2")).per_cm
    assert per == pytest.approx(stated["perCm"])
    assert stated["text"] in page.inner_text("figure figcaption")  # stated beside the panel
    if width == "phone":
        page.locator("#configuration").screenshot(path=str(tmp_path / f"{name}-phone.png"))
    page.close()
    assert not errors, errors
    bodies = set(numbers)
    for frame in frames_read:
        assert frame["scroll"][0] <= frame["scroll"][1], frame["scroll"]
        sums, big, size = _balance(frame, bodies)
        assert big > 0
        for body, (fx, fy, m) in sums.items():
            assert math.hypot(fx, fy) <= 1e-9 * big, (name, frame["k"], body, fx, fy)
            assert abs(m) <= 1e-9 * big * size, (name, frame["k"], body, m)
        # each body is in the picture: some force of it is drawn
        drawn = {it["on"] for it in frame["items"]} | {it["by"] for it in frame["items"]}
        assert bodies <= drawn, bodies - drawn
        # each arrow as drawn: from its point, along its force, at the stated scale
        for it in frame["items"]:
            assert it["title"].strip()
            if not it["shown"]:
                continue
            x0, y0, x1, y1 = frame["panel"]  # nothing drawn outside its panel
            b = it["box"]
            assert x0 - 1 <= b[0] and b[2] <= x1 + 1 and y0 - 1 <= b[1] and b[3] <= y1 + 1, (
                name,
                frame["k"],
                it["cls"],
                it["on"],
            )
            if it["line"] is None:
                continue
            x1, y1, x2, y2 = it["line"]
            assert x1 == pytest.approx(10 * it["x"] / frame["per"], abs=2e-3)
            assert -y1 == pytest.approx(10 * it["y"] / frame["per"], abs=2e-3)
            assert x2 - x1 == pytest.approx(10 * it["fx"] / per, abs=3e-3)
            assert y1 - y2 == pytest.approx(10 * it["fy"] / per, abs=3e-3)
    # the inertia forces' words: the same scale
    assert f'<b id="scale-inertia">{stated["text"]}</b>' in html or "scale-forces" in html
