"""A machine's flywheel on the mechanism's page (``page`` of worked_problems/
fourbar_flywheel.toml: a four-bar a motor turns at 240 rpm): the curve's numbers are the
torque the crank needs by virtual power at 40 digits (test_flywheel_steady_machine's
independent solve, not the page's code); in headless Chromium at 1280 px and a phone's
390 px the drawn curve read back through the plot's axes is that torque, the cursor
follows the frame (frame k at the scene's 60 deg + 360 k / N, ccw, from 0 deg) with the
torque at the cursor's dot and in the values' table, the areas are shaded green where the
flywheel gains (the demand under the motor's mean), the answers are the worked problem's,
the page never scrolls sideways. Without Playwright or Chromium the browser tests skip."""

import re
from pathlib import Path

import pytest

from polygon_method.cli import main
from test_energy_page import Opened, _agrees
from test_flywheel_steady_machine import _reference
from test_machine_cycle_sheet import OMEGA, _torque
from test_page_engine import _axes, _cycle_data, _path_points

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "worked_problems" / "fourbar_flywheel.toml"
N = 72  # frames: 5 deg apart
START = 60.0  # the scene's crank angle
SIZE = 60.0  # N m: the torque swings +-60 N m


@pytest.fixture(scope="module")
def page(tmp_path_factory):
    path = tmp_path_factory.mktemp("machine_page") / "machine.html"
    assert main(["page", str(SCENE), "-o", str(path), "--frames", str(N)]) == 0
    return path


def test_the_curves_numbers_are_the_torque_by_virtual_power(page):
    d = _cycle_data(page)
    assert d["cycleDeg"] == 360.0 and d["idcDeg"] == 0.0 and d["sense"] == 1.0
    phase, T = d["curve"]["phase"], d["curve"]["T"]
    assert len(T) == 1441 and phase[0] == 0.0 and phase[-1] == 360.0
    for k in range(0, 1441, 97):
        assert T[k] == pytest.approx(_torque(phase[k]), abs=1e-9 * SIZE), phase[k]
    assert d["mean"] == pytest.approx(_reference(OMEGA)[0], abs=1e-9 * SIZE)
    html = page.read_text(encoding="utf-8")
    assert "The crank's torque over a turn: the flywheel" in html
    assert "inner dead centre" not in html.split('id="plot-cycle-torque"')[1].split("</svg>")[0]


@pytest.mark.parametrize("width", [1280, 390])
def test_the_drawn_curve_and_the_cursor_follow_the_torque(browser, page, width, tmp_path):  # noqa: F811
    o = Opened(browser, page, width)
    assert o.fits()
    d = _cycle_data(page)
    ax, box = d["axes"], _axes(o, "plot-cycle-torque")

    def to_data(px, py):
        x = ax["x0"] + (px - box["left"]) / (box["right"] - box["left"]) * (ax["x1"] - ax["x0"])
        y = ax["y0"] + (box["bottom"] - py) / (box["bottom"] - box["top"]) * (ax["y1"] - ax["y0"])
        return x, y

    px_deg = (ax["x1"] - ax["x0"]) / (box["right"] - box["left"])
    px_nm = (ax["y1"] - ax["y0"]) / (box["bottom"] - box["top"])
    pts = _path_points(o.page.evaluate("document.getElementById('cycle-curve').getAttribute('d')"))
    assert len(pts) == 1441
    for k in range(0, 1441, 120):
        x, y = to_data(*pts[k])
        assert abs(x - k * 0.25) <= 0.006 * px_deg
        assert abs(y - _torque(k * 0.25)) <= 0.006 * px_nm, (k, y)
    # green where the flywheel gains: the shaded area's middle below the mean (0 here)
    fills = o.page.evaluate(
        "Array.from(document.querySelectorAll('#plot-cycle-torque path[fill]'))"
        ".filter(p => p.getAttribute('stroke') === 'none')"
        ".map(p => [p.getAttribute('fill'), p.getAttribute('d')])"
    )
    assert len(fills) >= 4
    for fill, dd in fills:  # (the area's outline: the curve and the mean line back)
        ys = [to_data(*q)[1] for q in _path_points(dd)]
        below = sum(ys) / len(ys) < d["mean"]
        assert (fill == "#c8e6c9") == below and fill in ("#c8e6c9", "#ffcdd2"), fill
    for k in (0, 5, 31, 50, 71):
        o.slide(k)
        phase = (START + 360.0 * k / N) % 360.0
        cx = float(
            o.page.evaluate(
                "document.getElementById('plot-cycle-torque-cursor').getAttribute('x1')"
            )
        )
        assert abs(to_data(cx, 0)[0] - phase) <= 0.006 * px_deg, k
        cy = float(
            o.page.evaluate("document.getElementById('plot-cycle-torque-dot').getAttribute('cy')")
        )
        t = _torque(phase)
        assert abs(to_data(0, cy)[1] - t) <= 0.006 * px_nm, k
        v = dict(
            o.page.evaluate(
                "Array.from(document.querySelectorAll('#cycle-values tr')).map(r => "
                "[r.cells[0].textContent, r.cells[1].textContent])"
            )
        )
        assert _agrees(v["crank angle from 0 deg"], phase, 360), (k, v)
        assert _agrees(v["torque T the crank needs"], t, SIZE), (k, v, t)
        assert o.fits()
    answers = o.page.evaluate("document.getElementById('cycle-answers').textContent")
    assert re.search(r"dE_max = .*= 93\.525\d* J", answers), answers
    assert "3.70" in answers
    o.page.screenshot(path=str(tmp_path / f"machine_{width}.png"), full_page=True)
    o.close()
