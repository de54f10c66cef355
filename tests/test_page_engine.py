"""An engine's turning-moment cycle on the mechanism's page (``page`` of a scene with
``[indicator]``): in headless Chromium at 1280 px and a phone's 390 px, the plotted
turning-moment curve, read back from the drawn path through the plot's axes, equals the
``sweep`` command's ``turning_moment`` column at the same crank angles (a separate run of
the CLI, not the page's code); the cursor follows the frame (its angle from the frame's
crank angle worked here: the scene's angle plus k steps of the cycle over N frames, in the
crank's sense, from the inner dead centre); the values at the cursor agree with the sweep
to the four figures shown; the page has no error, fetches nothing and never scrolls
sideways. A single four-stroke cylinder and a V-twin (two cylinders on one crank, the
inner dead centre of the first at 45 deg). Without Playwright or Chromium the browser
tests skip and say which is missing."""

import csv
import json
import math
import re
from pathlib import Path

import pytest

from polygon_method.cli import main

from test_energy_page import Opened, _agrees, _number

ROOT = Path(__file__).resolve().parents[1]
N = 90  # frames: 8 deg apart over a four-stroke's 720
#: (scene, the first cylinder's inner dead centre (deg from +x), the scene's crank angle)
ENGINES = {
    "single": (ROOT / "worked_problems" / "engine_flywheel.toml", 0.0, 390.0),
    "vtwin": (ROOT / "worked_problems" / "vtwin_flywheel.toml", 45.0, 435.0),
}
HALF = 0.5  # the curve's step (deg): 1441 points over 720


def _sweep_column(scene, start, stop, step, tmp_path, name="t") -> list:
    """The ``turning_moment`` column of ``sweep --csv`` (N m, in the sense of rotation)."""
    out = tmp_path / f"{name}.csv"
    argv = ["sweep", str(scene), "--from", repr(start), "--to", repr(stop), "--step", repr(step)]
    assert main(argv + ["--csv", str(out)]) == 0
    with out.open(encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    return [(float(r["theta [deg]"]), float(r["turning_moment [N m]"])) for r in rows]


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    d = tmp_path_factory.mktemp("engine_pages")
    out = {}
    for name, (scene, _, _) in ENGINES.items():
        path = d / f"{name}.html"
        assert main(["page", str(scene), "-o", str(path), "--frames", str(N)]) == 0
        out[name] = path
    return out


def _cycle_data(path) -> dict:
    html = path.read_text(encoding="utf-8")
    m = re.search(r'<script type="application/json" id="cycle">(.*?)</script>', html, re.S)
    return json.loads(m.group(1))


@pytest.mark.parametrize("name", sorted(ENGINES))
def test_the_curves_numbers_are_the_sweeps_turning_moment(pages, name, tmp_path):
    """The page's curve (its data, full precision) is the sweep's column at the same crank
    angles, to 1e-9 of the largest turning moment."""
    scene, idc, _ = ENGINES[name]
    d = _cycle_data(pages[name])
    assert d["cycleDeg"] == 720.0 and d["idcDeg"] == pytest.approx(idc, abs=1e-9)
    col = _sweep_column(scene, idc, idc + 720.0, HALF, tmp_path)
    assert len(col) == len(d["curve"]["T"]) == 1441
    size = max(abs(t) for _, t in col)
    for (theta, t), ph, got in zip(col, d["curve"]["phase"], d["curve"]["T"]):
        assert abs(theta - idc - ph) <= 1e-9
        assert abs(got - t) <= 1e-9 * size, (theta, got, t)


def test_no_cycle_on_a_page_without_an_engine(tmp_path):
    path = tmp_path / "fourbar.html"
    assert (
        main(["page", str(ROOT / "worked_problems" / "fourbar_image_points.toml"), "-o", str(path)])
        == 0
    )
    html = path.read_text(encoding="utf-8")
    assert 'id="cycle"' not in html and "plot-cycle-torque" not in html


def _path_points(d: str) -> list:
    return [tuple(map(float, p.split(","))) for p in re.findall(r"-?[\d.]+,-?[\d.]+", d)]


def _axes(o, pid) -> dict:
    """The plot's pixels of its axes' box (viewBox px), from the drawn axis path."""
    d = o.page.evaluate(f"document.querySelector('#{pid} path.axis').getAttribute('d')")
    (left, top), (_, bottom), (right, _) = _path_points(d)
    return {"left": left, "top": top, "bottom": bottom, "right": right}


@pytest.mark.parametrize("width", [1280, 390])
@pytest.mark.parametrize("name", sorted(ENGINES))
def test_the_drawn_curve_and_the_cursor_follow_the_sweep(browser, pages, name, width, tmp_path):  # noqa: F811
    scene, idc, start = ENGINES[name]
    col = [t for _, t in _sweep_column(scene, idc, idc + 720.0, HALF, tmp_path)]
    size = max(abs(t) for t in col)
    o = Opened(browser, pages[name], width)
    assert o.fits()
    # the axes' data range: the ticks' labels give the scale, read back from two of them
    d = _cycle_data(pages[name])
    ax, box = d["axes"], _axes(o, "plot-cycle-torque")

    def to_data(px, py):
        x = ax["x0"] + (px - box["left"]) / (box["right"] - box["left"]) * (ax["x1"] - ax["x0"])
        y = ax["y0"] + (box["bottom"] - py) / (box["bottom"] - box["top"]) * (ax["y1"] - ax["y0"])
        return x, y

    # the tick labelled 360° is drawn where the axes say 360 deg is
    ticks = o.page.evaluate(
        "Array.from(document.querySelectorAll('#plot-cycle-torque text.tick')).map(t => "
        "[t.textContent, +t.getAttribute('x')])"
    )
    x360 = next(x for t, x in ticks if t == "360°")
    assert abs(to_data(x360, 0)[0] - 360.0) <= 1e-6
    drawn = o.page.evaluate("document.getElementById('cycle-curve').getAttribute('d')")
    pts = _path_points(drawn)
    assert len(pts) == 1441
    px_deg = (ax["x1"] - ax["x0"]) / (box["right"] - box["left"])
    px_nm = (ax["y1"] - ax["y0"]) / (box["bottom"] - box["top"])
    for k, (px, py) in enumerate(pts):
        x, y = to_data(px, py)
        assert abs(x - k * HALF) <= 0.006 * px_deg  # to the SVG's hundredth of a pixel
        assert abs(y - col[k]) <= 0.006 * px_nm, (k, y, col[k])
    # the cursor follows the frame: frame k is at the scene's angle + 720 k / N (ccw)
    frames_at = [start + 720.0 * k / N for k in range(N)]
    at_frames = _sweep_column(scene, frames_at[0], frames_at[-1], 720.0 / N, tmp_path, "f")
    assert len(at_frames) == N
    for k in (0, 7, 31, 44, 60, 89):
        o.slide(k)
        phase = (frames_at[k] - idc) % 720.0
        for pid in ("plot-cycle-torque", "plot-cycle-energy"):
            cx = float(
                o.page.evaluate(f"document.getElementById('{pid}-cursor').getAttribute('x1')")
            )
            assert abs(to_data(cx, 0)[0] - phase) <= 0.006 * px_deg, (k, pid)
        cy = float(
            o.page.evaluate("document.getElementById('plot-cycle-torque-dot').getAttribute('cy')")
        )
        theta, t = at_frames[k]
        assert abs(theta - frames_at[k]) <= 1e-9
        assert abs(to_data(0, cy)[1] - t) <= 0.006 * px_nm
        v = dict(
            o.page.evaluate(
                "Array.from(document.querySelectorAll('#cycle-values tr')).map(r => "
                "[r.cells[0].textContent, r.cells[1].textContent])"
            )
        )
        angle_row = next(x for n, x in v.items() if n.startswith("crank angle"))
        assert _agrees(angle_row, phase, 720), (k, v)
        assert _agrees(v["turning moment T"], t, size), (k, v, t)
        assert o.fits()
    # playing moves the cursor with the mechanism
    o.page.click("#play")
    o.page.wait_for_timeout(400)
    o.page.click("#play")
    k = int(o.page.evaluate("document.getElementById('angle').value"))
    cx = float(
        o.page.evaluate("document.getElementById('plot-cycle-torque-cursor').getAttribute('x1')")
    )
    assert abs(to_data(cx, 0)[0] - (frames_at[k] - idc) % 720.0) <= 0.006 * px_deg
    answers = o.page.evaluate("document.getElementById('cycle-answers').textContent")
    assert "dE_max" in answers and "I = dE_max / (w^2 Cs)" in answers
    if name == "single":  # the worked problem's answers, worked independently (its header)
        assert "= 1125.47 J" in answers and "= 0.570168 kg m^2" in answers
    rows = o.table("#cycle-book")
    assert rows and rows[-1][3] == "E"  # the cycle closes: back at the first crossing
    areas = [_number(r[2]) for r in rows]  # six figures each: the sum is nought to their ulps
    ulps = sum(10 ** (math.floor(math.log10(abs(a))) - 5) for a in areas)
    assert abs(sum(areas)) <= 0.5 * ulps * (1 + 1e-9)
    o.page.screenshot(path=str(tmp_path / f"{name}_{width}.png"), full_page=True)
    o.close()


@pytest.mark.parametrize("width", [1280, 390])
@pytest.mark.parametrize("name", sorted(ENGINES))
def test_the_kinematic_plots_axis_reads_in_order(browser, pages, name, width):  # noqa: F811
    """The speeds', omegas' and accelerations' plots run over the four-stroke's 720 deg from
    the scene's angle (435 deg for the V-twin): their ticks were written within the cycle,
    "540°, 0°, 180°, 360°". They are the angle turned from the first frame, in order; the
    marker at frame k (the scene's angle + 720 k / N, worked here) stands on the tick of
    that angle turned, and the readout gives the frame's crank angle within the cycle."""
    _, _, start = ENGINES[name]
    o = Opened(browser, pages[name], width)
    assert o.fits()
    for pid in ("plot-v", "plot-w", "plot-a"):
        got = o.page.evaluate(
            f"Array.from(document.querySelectorAll('#{pid} text.tick'))"
            ".filter(t => t.getAttribute('text-anchor') === 'middle')"
            ".map(t => [t.textContent, +t.getAttribute('x')])"
        )
        labels = [float(t.rstrip("°")) for t, _ in got]
        assert labels == [0.0, 180.0, 360.0, 540.0], (pid, got)
        assert [x for _, x in got] == sorted(x for _, x in got)
        title = o.page.evaluate(f"document.querySelector('#{pid} text.axis-title').textContent")
        assert title == f"crank angle turned (ccw) from θ = {start:.1f}°", title
        for k in (0, 45, 67):  # 0, 360 and 536 deg turned
            o.slide(k)
            turned = 720.0 * k / N
            marker = float(o.page.get_attribute(f"#{pid}-marker", "x1"))
            tick = {t: x for (t, x) in zip(labels, (x for _, x in got))}
            if turned in tick:
                assert abs(marker - tick[turned]) <= 0.01, (pid, k, marker, tick)
            now = o.page.text_content("#angle-now").strip()
            assert now == f"θ = {(start + turned) % 720.0:.1f}°", now
    o.close()
