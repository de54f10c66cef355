"""The page's frames follow a wheel turning fast: a differential's planet turns 15.4 times
its arm over the arm's 10 turns, and 180 frames (20 deg of the arm apart) showed it jumping
308 deg from frame to frame (seeming to turn back), the page saying only that the frames
"may be aliased". Without ``--frames`` the page now takes as many frames as keep the planet
within 10 deg between two, and says so.

Measured on the page's own data, against Willis' formula worked here in fractions: the
planet's turning between two frames (from its points A and P), and its whole turning over
the period summed from those steps (only frames that follow it can add up to Willis')."""

import json
import math
import re
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest

from polygon_method.cli import main

ROOT = Path(__file__).resolve().parents[1]
DIFFERENTIAL = str(ROOT / "tests" / "textbook" / "differential_sun_and_annulus_driven.toml")
EPICYCLIC = str(ROOT / "worked_problems" / "rolling_epicyclic.toml")
SEED = str(ROOT / "worked_problems" / "fourbar_image_points.toml")
#: a direction read from two points given to six figures, 50 mm apart at 0.1 m: within
#: 2 x 5e-7 / 0.05 rad, about 0.0012 deg (deg)
ROUNDED = 0.005


def _page(tmp_path, capsys, path, *extra):
    out = tmp_path / "page.html"
    assert main(["page", path, "-o", str(out), *extra]) == 0
    html = out.read_text(encoding="utf-8")
    m = re.search(r'<script type="application/json" id="frames">(.*?)</script>', html, re.S)
    return html, json.loads(m.group(1).replace("<\\/", "</")), capsys.readouterr().out


def _steps(d, centre, rim):
    """The planet's turning (deg) from frame to frame, from two of its points."""
    c = np.asarray(d["P"][centre]).reshape(-1, 2)
    r = np.asarray(d["P"][rim]).reshape(-1, 2)
    ang = np.arctan2(r[:, 1] - c[:, 1], r[:, 0] - c[:, 0])
    step = np.diff(np.append(ang, ang[0]))  # the period closes on the first frame
    return np.degrees((step + math.pi) % (2 * math.pi) - math.pi)


def _willis():
    """The arm's and the planet's speeds (rpm, ccw +): sun 30 teeth at -240, annulus 80 at
    +120, planet 25."""
    arm = Fraction(30 * -240 + 80 * 120, 30 + 80)
    planet = arm + (120 - arm) * Fraction(80, 25)
    return arm, planet


def test_the_differentials_page_follows_its_planet(tmp_path, capsys):
    arm, planet = _willis()
    assert planet / arm == Fraction(77, 5)  # 15.4
    html, d, said = _page(tmp_path, capsys, DIFFERENTIAL)
    n = len(d["theta"])
    step = _steps(d, "A", "P")
    # (the page's positions are to six figures: AP's direction to about 0.002 deg)
    assert np.max(np.abs(step)) <= 10.0 + ROUNDED, np.max(np.abs(step))
    # the steps add up to Willis' turning over the period (10 turns of the arm)
    assert abs(np.sum(step) / 360 - float(planet / arm) * 10) < 1e-3
    arm_step = np.diff(d["theta"])
    assert np.allclose(np.abs(arm_step), 3600 / n, rtol=1e-6)
    assert n >= 3600 * 15.4 / 10
    assert "may be aliased" not in html
    assert f"{n} frames, not 180" in html and "at most 10 deg between two frames" in html
    assert f"{n} frames over 10 turns" in said and "not 180" in said


def test_asked_for_fewer_frames_the_page_says_they_may_be_aliased(tmp_path, capsys):
    html, d, said = _page(tmp_path, capsys, DIFFERENTIAL, "--frames", "180")
    assert len(d["theta"]) == 180
    # the planet turns ccw (Willis) 308 deg a frame: seen as 52 deg cw, turning back
    assert _willis()[1] > 0 and np.all(_steps(d, "A", "P") < -45)
    assert "may be aliased" in html and "not 180" not in html


def test_a_wheel_at_exactly_ten_degrees_a_frame_is_followed(tmp_path, capsys):
    """The worked epicyclic: its planet at 2.5 times its arm over 2 turns, 180 frames of
    4 deg: 10 deg a frame, which follows it (the page once said it did not, to rounding)."""
    html, d, _ = _page(tmp_path, capsys, EPICYCLIC)
    assert len(d["theta"]) == 180
    assert np.max(np.abs(_steps(d, "A", "P"))) <= 10.0 + ROUNDED
    assert "may be aliased" not in html and "not 180" not in html


def test_a_page_with_no_wheel_keeps_its_180_frames(tmp_path, capsys):
    html, d, said = _page(tmp_path, capsys, SEED)
    assert len(d["theta"]) == 180 and "not 180" not in said + html


def test_a_gif_of_the_differential_says_it_cannot_follow(tmp_path, capsys):
    """A GIF holds at most 360 pictures: too few for the planet (5544 would follow it), so
    it keeps its 180 and says they may be aliased; the gear's pitch circle with its words
    once stopped the GIF with an internal error."""
    out = tmp_path / "c.gif"
    assert main(["draw", DIFFERENTIAL, "--animate", "-o", str(out)]) == 0
    cap = capsys.readouterr()
    assert "180 frames;" in cap.out and "not 180" not in cap.out
    assert "the pictures may be aliased" in cap.err


TICKS = """() => ['plot-v', 'plot-w', 'plot-a'].map(id => document.getElementById(id))
  .map(s => [...s.querySelectorAll('text.tick[text-anchor=middle]')].map(t => {
    const b = t.getBBox(); return [t.textContent, b.x, b.x + b.width]; }))"""


@pytest.mark.parametrize(
    "scene, turned",
    [(DIFFERENTIAL, 3600), (str(ROOT / "worked_problems" / "engine_flywheel.toml"), 720)],
)
def test_the_plots_of_a_period_of_many_turns_have_separate_round_ticks(
    browser, tmp_path, scene, turned
):
    """The differential's plots over its 10 turns once had 11 ticks, 0° to 3600°, written
    over one another; now at most 7, whole turns apart, none touching the next."""
    out = tmp_path / "p.html"
    assert main(["page", scene, "-o", str(out), "--frames", "360"]) == 0
    page = browser.new_page(viewport={"width": 1280, "height": 900})
    try:
        page.goto(out.as_uri())
        plots = page.evaluate(TICKS)
    finally:
        page.close()
    assert len(plots) == 3
    for ticks in plots:
        said = [int(w.rstrip("°")) for w, _, _ in ticks]
        step = said[1] - said[0]
        assert 2 <= len(ticks) <= 7 and said[0] == 0 and said[-1] <= turned
        assert step % 360 == 0 if turned > 720 else step in (90, 180)
        assert all(b - a == step for a, b in zip(said, said[1:]))
        for (_, _, right), (_, left, _) in zip(ticks, ticks[1:]):
            assert left - right >= 2, ticks  # (viewBox units, about 4 px on the screen)
