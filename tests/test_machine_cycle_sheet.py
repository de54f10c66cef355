"""``draw --diagram cycle`` of a machine driven at a steady speed (the four-bar of
worked_problems/fourbar_flywheel.toml), measured in the written SVG against the independent
solve of test_flywheel_steady_machine (the four-bar in closed form at 40 digits, the torque
by virtual power as the rate of the machine's energy): the curve's drawn points read back
through the plot's own tick marks (its stated scales) are the torque the crank needs, the
dash-dot lines stand at the crossings of the mean, the mean line at the motor's torque, each
area's label is the energy between its crossings, and every label lies inside the plot,
clear of the others. (The sheet on its paper, every word inside it and clear of every
other, and the answers' spelling: test_energy_sheets_print.)"""

from __future__ import annotations

import math
import re
from pathlib import Path

import mpmath
import pytest

from polygon_method.cli import main
from test_energy_sheets_print import _words
from test_flywheel_steady_machine import _energy, _reference

ROOT = Path(__file__).resolve().parent.parent
SCENE = ROOT / "worked_problems" / "fourbar_flywheel.toml"
OMEGA = 8 * math.pi  # 240 rpm
NUM = r"(-?[\d.]+)"


def _torque(deg):
    """The torque the crank needs at ``deg`` (N m, ccw), by virtual power at 40 digits."""
    with mpmath.workdps(40):
        th = mpmath.radians(mpmath.mpf(deg))
        return float(mpmath.diff(lambda t: _energy(t, mpmath.mpf(OMEGA)), th))


def _value(label):
    return float(label.replace("−", "-"))


def _scale(chunk, axis):
    """The axis' map from drawn pt to its value, read from its ticks: each tick's grid line
    and the number written under it (a straight line through every one of them)."""
    ticks = re.findall(
        rf'<g id="{axis}tick_\d+">\s*<g id="line2d_\d+">\s*<path d="M {NUM} {NUM}.*?<!-- (.*?) -->',
        chunk,
        re.S,
    )
    pairs = [(float(x if axis == "x" else y), _value(s)) for x, y, s in ticks]
    assert len(pairs) >= 4
    (p0, v0), (p1, v1) = pairs[0], pairs[-1]
    k = (v1 - v0) / (p1 - p0)
    for p, v in pairs:  # every tick on the one straight scale
        assert v0 + k * (p - p0) == pytest.approx(v, abs=1e-6 * abs(v1 - v0))
    return lambda p: v0 + k * (p - p0)


def _path(chunk, style):
    """The points (pt) of the paths in ``chunk`` drawn in ``style``."""
    out = []
    for d in re.findall(r'<path d="([^"]*)"[^>]*style="[^"]*' + re.escape(style), chunk):
        out.append([(float(a), float(b)) for a, b in re.findall(rf"[ML] {NUM} {NUM}", d)])
    return out


@pytest.fixture(scope="module")
def sheet(tmp_path_factory):
    out = tmp_path_factory.mktemp("cycle") / "machine.svg"
    assert main(["draw", str(SCENE), "--diagram", "cycle", "-o", str(out)]) == 0
    return out.read_text(encoding="utf-8")


def test_the_curve_is_the_torque_at_the_sheets_scales(sheet):
    top = sheet.split('<g id="axes_1">')[1].split('<g id="axes_2">')[0]
    sx, sy = _scale(top, "x"), _scale(top, "y")
    curve = max(_path(top, "stroke: #000000; stroke-width: 1.2"), key=len)  # (not the legend's)
    assert len(curve) > 100
    assert sx(curve[0][0]) == pytest.approx(0.0, abs=1e-6)
    assert sx(curve[-1][0]) == pytest.approx(360.0, abs=1e-4)
    size = 60.0  # N m: the torque's swing is +-60 N m
    for px, py in curve[:: max(1, len(curve) // 24)]:
        deg = sx(px)
        assert sy(py) == pytest.approx(_torque(deg), abs=1e-6 * size), deg
    mean, cross, E = _reference(OMEGA)
    line = _path(top, "stroke: #1565c0")[0]  # (the legend's after it)
    assert all(sy(y) == pytest.approx(mean, abs=1e-6 * size) for _, y in line)
    dashes = _path(top, "stroke: #757575")
    assert sorted(sx(p[0][0]) for p in dashes) == pytest.approx(cross, abs=1e-5)
    # each area's label: the energy between its crossings (+ where the flywheel gains)
    areas = [(E[(k + 1) % len(E)] - E[k]) for k in range(len(E))]
    said = [_value(s[:-2]) for s in re.findall(r"<!-- (−?\+?[\d.]+ J) -->", top)]
    assert sorted(said) == pytest.approx(sorted(areas), rel=5e-4)
    assert sum(areas) == pytest.approx(0.0, abs=1e-9)


def test_the_area_labels_lie_inside_the_plot_and_clear(sheet):
    _, words = _words(sheet)
    box = _path(sheet.split('<g id="axes_1">')[1], "fill: #ffffff")[0]
    xs, ys = [p[0] for p in box], [p[1] for p in box]
    labels = [(s, ink) for s, ink in words if re.fullmatch(r"[+−][\d.]+ J", s)]
    assert len(labels) == 4
    for s, ink in labels:
        x0, y0, x1, y1 = ink.bounds
        assert min(xs) < x0 and x1 < max(xs) and min(ys) < y0 and y1 < max(ys), s
    for i, (a, ia) in enumerate(words):
        for b, ib in words[i + 1 :]:
            assert ia.intersection(ib).area <= 1e-6, (a, b)
    said = " | ".join(s for s, _ in words)
    assert "ΔEₘₐₓ = 93.53 J" in said and "I = 3.702 kg m²" in said and "m = 92.54 kg" in said
    assert "torque T the crank needs" in said and "the motor's mean" in said


def test_the_sheet_is_the_same_whatever_the_callers_matplotlib_settings(
    sheet, tmp_path, monkeypatch
):
    """A program that sets matplotlib's ``svg.fonttype`` to "none" for its own charts (the
    accuracy benchmark did, globally, run in process by a test) gets the same sheet: its
    text as paths, byte for byte (these tests had failed after it, in the same worker)."""
    import matplotlib

    monkeypatch.setitem(matplotlib.rcParams, "svg.fonttype", "none")
    out = tmp_path / "machine.svg"
    assert main(["draw", str(SCENE), "--diagram", "cycle", "-o", str(out)]) == 0
    assert out.read_text(encoding="utf-8") == sheet
