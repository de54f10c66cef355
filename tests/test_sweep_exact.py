"""Sweep summaries near limits: the extremes are found by solving (every sampled local
extreme refined, the limit positions evaluated at their exact angles), so they do not
change with the number of samples; a quantity that grows without bound towards a limit
position is marked so; crank angles are within one turn; the CSV keeps full precision.
Compared with closed forms of the offset slider crank and the four-bar (mpmath,
tests/reference.py) and the law of cosines, never with the tool's own output."""

from __future__ import annotations

import csv
import io
import math
import re

import mpmath
import numpy as np
import pytest

from reference import reference_slider_crank
from polygon_method import parse_scene
from polygon_method.cli import main
from polygon_method.linkage.summary import summarize

ENGINE = """
units = "mm"
[ground]
O = [0, 0]
[links]
OA = {r}
AB = {l}
[sliders]
B = {{ path = "horizontal", through = [0, {e}] }}
[assembly]
B = "right"
[input]
crank = "OA"
angle = {angle}
speed = "{w} rad/s ccw"
"""

FOURBAR = """
units = "mm"
[ground]
O2 = [0, 0]
O4 = [{d}, 0]
[links]
"O2-A" = {a}
"A-B" = {b}
"B-O4" = {c}
[assembly]
B = "above"
[input]
crank = "O2-A"
angle = {angle}
speed = "{w} rad/s ccw"
"""

STEPS = (7, 13, 37, 360)


def _angles(n):
    return np.radians(np.arange(n) * 360.0 / n)


@pytest.mark.parametrize(
    "r, l, e, w", [(50, 200, 0, 10.0), (60, 170, 25, 3.0), (45, 310, -40, 120.0)]
)
def test_piston_speed_maximum_is_exact_and_does_not_depend_on_the_samples(r, l, e, w):
    sc = parse_scene(ENGINE.format(r=r, l=l, e=e, angle=30, w=w))

    def v(th):
        return reference_slider_crank(r / 1000, l / 1000, e / 1000, th, w, 0)["v"]

    def dv(th):
        return mpmath.diff(v, th)

    # the largest |v|: stationary points of v, bracketed on a fine grid, solved by mpmath
    grid = [2 * mpmath.pi * k / 720 for k in range(721)]
    best = max(abs(v(t)) for t in grid)
    for k in range(720):
        if dv(grid[k]) * dv(grid[k + 1]) < 0:
            t = mpmath.findroot(dv, (grid[k], grid[k + 1]), solver="anderson")
            best = max(best, abs(v(t)))
    got = [summarize(sc, _angles(n)).extreme("v_B").maximum for n in STEPS]
    for g in got:
        assert g == pytest.approx(float(best), rel=1e-9)


@pytest.mark.parametrize(
    "a, b, c, d",
    [(150, 450, 300, 200), (120, 300, 150, 250), (90, 240, 200, 120), (100, 330, 250, 150)],
)
def test_transmission_minimum_is_zero_at_the_toggle(a, b, c, d):
    # a non-Grashof crank: it stops where A-B and B-O4 fold into line, at the crank angles
    # where O4A = b - c (law of cosines), and reaches the range between them through 180
    cos = (a * a + d * d - (b - c) ** 2) / (2 * a * d)
    assert abs(cos) < 1 and d + a < b + c  # the family applies
    t = math.degrees(math.acos(cos))
    lims = [t, 360 - t]
    sc = parse_scene(FOURBAR.format(a=a, b=b, c=c, d=d, angle=180, w=10.0))
    for n in STEPS[1:]:
        s = summarize(sc, _angles(n))
        mu = s.extreme("mu at B")
        assert mu.minimum == 0.0
        assert min(abs(mu.at_min - t) for t in lims) < 1e-6
        assert 0 <= mu.at_min < 360
        # every quantity of the driven side grows without bound at a toggle of the crank
        for name in ("omega_A-B", "omega_B-O4", "alpha_A-B", "alpha_B-O4"):
            e = s.extreme(name)
            assert e.max_unbounded or e.min_unbounded, name
        for name in ("v_B", "a_B"):
            assert s.extreme(name).max_unbounded, name


@pytest.mark.parametrize("r, l, e", [(100, 80, 0), (100, 120, 50), (90, 60, -20)])
def test_engine_that_cannot_turn_its_stroke_ends_at_the_limits(r, l, e):
    # the rod stands perpendicular to the path where r sin(theta) - e = +-l: the crank's
    # limits; the pin's x there is the block's (D = 0)
    lims = []
    for s in (e + l, e - l):
        if abs(s) < r:
            t = math.degrees(math.asin(s / r))
            lims += [t % 360, (180 - t) % 360]
    assert lims  # the family applies
    sc = parse_scene(ENGINE.format(r=r, l=l, e=e, angle=math.degrees(math.asin(e / r)), w=5.0))
    R, L, E = r / 1000, l / 1000, e / 1000

    def x(th):
        return reference_slider_crank(R, L, E, th, 1, 0)["x"]

    def reach(th):
        return abs(R * mpmath.sin(th) - E) < L

    # the reachable part through the scene's angle, on a fine grid, its stationary points
    # solved, and its ends (the limits)
    start = math.asin(e / r)
    up = [start + 2 * mpmath.pi * k / 1440 for k in range(0, 721)]
    down = [start - 2 * mpmath.pi * k / 1440 for k in range(1, 721)]
    ok = []
    for side in (down, up):  # the connected run through the scene's angle
        run = []
        for g in side:
            if not reach(g):
                break
            run.append(g)
        ok = run[::-1] + ok if side is down else ok + run

    def nearest_limit(g):  # the limit just beyond an end of the run
        return min(
            (math.radians(t) for t in lims),
            key=lambda t: abs((t - float(g) + math.pi) % (2 * math.pi) - math.pi),
        )

    vals = [R * math.cos(nearest_limit(g)) for g in (ok[0], ok[-1])] + [x(g) for g in ok]
    for g0, g1 in zip(ok, ok[1:]):
        d0, d1 = mpmath.diff(x, g0), mpmath.diff(x, g1)
        if g1 - g0 < 0.01 and d0 * d1 < 0:
            vals.append(
                x(mpmath.findroot(lambda t: mpmath.diff(x, t), (g0, g1), solver="anderson"))
            )
    top, bottom = float(max(vals)), float(min(vals))
    for n in STEPS[1:]:
        s = summarize(sc, _angles(n))
        pos = s.extreme("s_B")
        assert pos.maximum == pytest.approx(top, rel=1e-9)
        assert pos.minimum == pytest.approx(bottom, rel=1e-9)
        mu = s.extreme("mu at B")
        assert mu.minimum == 0.0 and min(abs(mu.at_min - t) for t in lims) < 1e-6
        assert all(
            0 <= e.at_max < 360 and 0 <= e.at_min < 360 for e in s.extremes if not e.constant
        )
        rod = s.extreme("alpha_AB")  # alpha_rod ~ 1 / D^3 as D -> 0
        assert rod.max_unbounded or rod.min_unbounded


@pytest.mark.parametrize("scene_angle", [0.0, 90.0, -80.0, 400.0])
def test_linkage_and_summary_angles_within_one_turn(capsys, tmp_path, scene_angle):
    # a non-Grashof crank (50 + 100 > 66 + 56) whose reachable range passes 0 deg: its
    # limits are where BC and CD fold, A-C = CD - BC ... or extend, A-C = BC + CD
    text = f"""
units = "mm"
[ground]
A = [0, 0]
D = [100, 0]
[links]
AB = 50
BC = 66
CD = 56
[assembly]
C = "above"
[input]
crank = "AB"
angle = {scene_angle}
speed = "10 rad/s ccw"
"""
    f = tmp_path / "wide.toml"
    f.write_text(text)
    cos = (50**2 + 100**2 - (66 + 56) ** 2) / (2 * 50 * 100)  # BD = BC + CD
    lim = math.degrees(math.acos(cos))
    assert main(["linkage", str(f)]) == 0
    out = capsys.readouterr().out
    angles = [float(m) for m in re.findall(r"crank (?:at |angle )?\s*(-?[\d.]+) deg", out)]
    assert len(angles) >= 2 and all(0 <= a < 360 for a in angles)
    assert any(abs(a - lim) < 1e-3 for a in angles)
    assert any(abs(a - (360 - lim)) < 1e-3 for a in angles)
    s = summarize(parse_scene(text), _angles(360))
    assert s.range_deg == pytest.approx((360 - lim, lim), abs=1e-6)
    assert "(through 0)" in s.text()
    for e in s.extremes:
        if not e.constant:
            assert 0 <= e.at_max < 360 and 0 <= e.at_min < 360


def test_csv_has_full_precision(tmp_path):
    # a four-bar 9 m from the origin: link lengths recomputed from the CSV to 1e-12
    off = 9000.0
    text = f"""
units = "mm"
[ground]
A = [{off}, {off / 3}]
D = [{off + 100}, {off / 3}]
[links]
AB = 50
BC = 66
CD = 56
[input]
crank = "AB"
angle = 60
speed = "10.5 rad/s cw"
"""
    f = tmp_path / "far.toml"
    f.write_text(text)
    out = tmp_path / "far.csv"
    assert main(["sweep", str(f), "--steps", "72", "--csv", str(out)]) == 0
    rows = list(csv.DictReader(io.StringIO(out.read_text())))
    assert len(rows) > 10
    for row in rows:
        P = {p: (float(row[f"x_{p} [m]"]), float(row[f"y_{p} [m]"])) for p in "ABCD"}
        for (p, q), n in ((("A", "B"), 0.050), (("B", "C"), 0.066), (("C", "D"), 0.056)):
            assert math.dist(P[p], P[q]) == pytest.approx(n, rel=1e-12)
