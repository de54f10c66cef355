"""Hydraulic cylinders ([cylinders]), against the 50-digit reference and closed forms.

The reference solves the mechanism without the cylinder (the cylinder joins two points the
rest already places); the cylinder's length, rate of extension, its acceleration and its
omega and alpha are then taken from the reference's ends by their own definitions
(L = |d|, L' = d.d'/L, L'' = (d.d'' + |d'|^2 - L'^2) / L, omega = d x d' / L^2, and
from d x d' = L^2 omega: alpha = (d x d'' - 2 L L' omega) / L^2), not by the solver's
relations.
"""

import dataclasses
import json
import math

import numpy as np
import pytest
from mpmath import mpf, sqrt

from polygon_method import solve
from polygon_method.cli import main
from polygon_method.solver.compiler import gruebler
from polygon_method.scene import parse_scene
from reference import reference_solution
from scenes import seed

REL = 1e-9

TIPPER = """
units = "mm"
[ground]
Q = [0, 0]
O = [{ox}, {oy}]
[links]
QR = 800
[points]
G = {{ on = "QR", along = 2400 }}
[cylinders]
"O-R" = {{ {stroke} }}
[input]
crank = "QR"
angle = {angle}
{given}
"""

# a four-bar whose coupler pin C is pushed by a cylinder from the frame (a loader's arm)
FOURBAR = seed(
    ground="E = [150, -60]\n", middle="[cylinders]\nEC = {{}}\n", drive="angle = {angle}\n{given}"
)


def _cyl_ref(ref, k, r):
    P, V, A = ref["positions"], ref["velocities"], ref["accelerations"]
    d = (P[r][0] - P[k][0], P[r][1] - P[k][1])
    dv = (V[r][0] - V[k][0], V[r][1] - V[k][1])
    da = (A[r][0] - A[k][0], A[r][1] - A[k][1])
    L = sqrt(d[0] ** 2 + d[1] ** 2)
    L1 = (d[0] * dv[0] + d[1] * dv[1]) / L
    L2 = (d[0] * da[0] + d[1] * da[1] + dv[0] ** 2 + dv[1] ** 2 - L1**2) / L
    w = (d[0] * dv[1] - d[1] * dv[0]) / L**2
    al = (d[0] * da[1] - d[1] * da[0] - 2 * L * L1 * w) / L**2
    return L, L1, L2, w, al


def _check_cylinder(sol, key, k, r, ref):
    L, L1, L2, w, al = _cyl_ref(ref, k, r)
    vsize = max(math.hypot(*v) for v in sol.V.values())
    asize = max(math.hypot(*a) for a in sol.A.values())
    wsize = max(abs(x) for x in sol.W.values())
    alsize = max(abs(x) for x in sol.Al.values()) + wsize**2
    assert abs(sol.cylinder_length(key) - L) <= REL * L
    assert abs(sol.sliding_velocity(key) - L1) <= REL * vsize
    assert abs(sol.sliding_acceleration(key) - L2) <= REL * asize
    assert abs(sol.omega(key) - w) <= REL * wsize
    assert abs(sol.alpha(key) - al) <= REL * alsize
    return L1, L2


@pytest.mark.parametrize("angle", (100, 130, 150, 170))
@pytest.mark.parametrize("o", ((-1500, -300), (-1200, 200)))
def test_cylinder_measured_against_reference(angle, o):
    sc = parse_scene(
        TIPPER.format(
            ox=o[0],
            oy=o[1],
            stroke="",
            angle=angle,
            given='speed = "0.2 rad/s cw"\nacceleration = "0.05 rad/s^2 ccw"',
        )
    )
    sol = solve(sc)
    ref = reference_solution(sc, dict(sol.P))
    _check_cylinder(sol, "O-R", "O", "R", ref)


@pytest.mark.parametrize("angle", (40, 60, 90))
def test_cylinder_on_a_coupler_pin(angle):
    sc = parse_scene(FOURBAR.format(angle=angle, given='speed = "10 rad/s ccw"'))
    sol = solve(sc)
    ref = reference_solution(sc, dict(sol.P))
    _check_cylinder(sol, "EC", "E", "C", ref)


@pytest.mark.parametrize("angle", (110, 150))
@pytest.mark.parametrize("rate", (None, "0.03 m/s^2", "-0.02 m/s^2"))
def test_extension_rate_given(angle, rate):
    """vs_OR = 0.1 m/s extending (and its rate, 0 by default: steady): the body's omega and
    alpha resolved in the reference by its own 50-digit solve at 1 rad/s."""
    given = 'vs_OR = "0.1 m/s extending"' + (f'\nas_OR = "{rate}"' if rate else "")
    sc = parse_scene(TIPPER.format(ox=-1500, oy=-300, stroke="", angle=angle, given=given))
    sol = solve(sc)
    unit = dataclasses.replace(
        sc, input=dataclasses.replace(sc.input, omega=1.0, alpha=0.0, given=None)
    )
    r1 = reference_solution(unit, dict(sol.P))
    _, y1, h, _, _ = _cyl_ref(r1, "O", "R")
    w = mpf("0.1") / y1
    want = mpf(rate.split()[0]) if rate else mpf(0)
    al = (want - w * w * h) / y1
    assert abs(sol.omega("QR") - w) <= REL * abs(w)
    assert abs(sol.alpha("QR") - al) <= REL * (abs(al) + w * w)
    full = dataclasses.replace(
        unit, input=dataclasses.replace(unit.input, omega=float(w), alpha=float(al))
    )
    ref = reference_solution(full, dict(sol.P))
    L1, L2 = _check_cylinder(sol, "O-R", "O", "R", ref)
    assert abs(L1 - mpf("0.1")) <= REL and abs(L2 - want) <= 1e-9 * (1 + abs(float(al)))


def test_retracting_is_negative():
    sc = parse_scene(
        TIPPER.format(ox=-1500, oy=-300, stroke="", angle=150, given='vs_OR = "0.1 m/s retracting"')
    )
    sol = solve(sc)
    assert abs(sol.sliding_velocity("O-R") + 0.1) <= REL * 0.1
    assert sol.omega("QR") > 0  # the body falls back (ccw at 150 deg with O behind)


def test_stroke_limits_are_the_sweeps_limit_positions():
    """|R - O| = stroke end, R = 0.8 (cos t, sin t): cos(t - phi) = (r^2 + s^2 - L^2) / 2rs."""
    o = (-1.5, -0.3)
    sc = parse_scene(
        TIPPER.format(
            ox=-1500,
            oy=-300,
            stroke="stroke = [1000, 1900]",
            angle=150,
            given='vs_OR = "0.1 m/s extending"',
        )
    )
    from polygon_method.motion.sweeps import sweep

    sw = sweep(sc, np.radians(np.arange(0.0, 360.0, 5.0)))
    lims = sorted(math.degrees(e.theta) % 360 for e in sw.domain.limits)
    r, s, phi = 0.8, math.hypot(*o), math.atan2(o[1], o[0])
    want = []
    for L in (1.0, 1.9):
        c = (r * r + s * s - L * L) / (2 * r * s)
        for sgn in (1, -1):
            t = math.degrees(phi + sgn * math.acos(c)) % 360
            if 60 < t < 200:
                want.append(t)
    assert len(lims) == 2 and len(want) == 2
    for a, b in zip(lims, sorted(want)):
        assert abs(a - b) < 1e-6
    # the extension rate is held over the sweep
    assert all(abs(v - 0.1) < 1e-12 for v in sw.S["O-R"][0])


def test_outside_the_stroke_is_refused(tmp_path, capsys):
    f = tmp_path / "t.toml"
    f.write_text(
        TIPPER.format(
            ox=-1500,
            oy=-300,
            stroke="stroke = [1000, 1900]",
            angle=200,
            given='speed = "1 rad/s cw"',
        )
    )
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "[cylinders] O-R" in err and "stroke" in err


def test_gruebler_counts_barrel_and_rod():
    sc = parse_scene(
        TIPPER.format(ox=-1500, oy=-300, stroke="", angle=150, given='speed = "1 rad/s cw"')
    )
    assert gruebler(sc) == 1  # ground, body, barrel, rod: 3*3 - 2*4


BAD = [
    ('"O-X" = {}', "no point X"),
    ("QR = {}", "also a rigid link"),
    ('"O-R" = { stroke = [1900, 1000] }', "shorter"),
    ('"O-R" = { bore = 50 }', "stroke"),
]


@pytest.mark.parametrize("line, words", BAD)
def test_bad_cylinder_one_line(tmp_path, capsys, line, words):
    text = TIPPER.format(ox=-1500, oy=-300, stroke="", angle=150, given='speed = "1 rad/s cw"')
    text = text.replace('"O-R" = {  }', line)
    f = tmp_path / "t.toml"
    f.write_text(text)
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err, err


def test_every_view(tmp_path, capsys):
    f = tmp_path / "t.toml"
    f.write_text(
        TIPPER.format(
            ox=-1500,
            oy=-300,
            stroke="stroke = [1000, 1900]",
            angle=150,
            given='vs_OR = "0.1 m/s extending"',
        )
        + '[answers]\nvs_OR = "0.1 m/s"\nomega_OR = "0.0323 rad/s ccw"\n'
    )
    assert main(["solve", "--json", str(f)]) == 0
    d = json.loads(capsys.readouterr().out)
    assert set(d["cylinders"]["O-R"]) >= {"length", "extension_rate", "omega", "alpha"}
    for argv in (
        ["steps"],
        ["check"],
        ["centres"],
        ["linkage"],
        ["plan"],
        ["draw", "-o", str(tmp_path / "d.svg")],
        ["sweep", "--steps", "36", "--summary"],
        ["page", "-o", str(tmp_path / "p.html")],
    ):
        assert main([argv[0], str(f), *argv[1:]]) == 0, argv
    out = capsys.readouterr().out
    assert "cylinder O-R" in out


def test_csv_has_the_cylinder_and_holds_its_rate(tmp_path):
    """The sweep's CSV carries the cylinder's length and rates; the rate of extension is the
    stated one at every angle, and the length is |R - O| from the CSV's own positions (the
    CSV writes ten significant figures)."""
    import csv

    f = tmp_path / "t.toml"
    f.write_text(
        TIPPER.format(ox=-1500, oy=-300, stroke="", angle=150, given='vs_OR = "0.1 m/s extending"')
    )
    out = tmp_path / "s.csv"
    assert main(["sweep", str(f), "--steps", "36", "--csv", str(out)]) == 0
    rows = list(csv.DictReader(out.open()))
    assert rows
    for r in rows:
        assert abs(float(r["vs_O-R [m/s]"]) - 0.1) < 1e-10
        L = math.hypot(float(r["x_R [m]"]) + 1.5, float(r["y_R [m]"]) + 0.3)
        assert abs(float(r["length_O-R [m]"]) - L) < 1e-9 * L


def test_variants_of_a_given_motion_cannot_vary_the_crank_speed(tmp_path, capsys):
    f = tmp_path / "t.toml"
    f.write_text(
        TIPPER.format(ox=-1500, oy=-300, stroke="", angle=150, given='vs_OR = "0.1 m/s extending"')
        + '[variants]\nspeed = { from = 1, to = 2, step = 1, unit = "rad/s" }\n'
    )
    assert main(["variants", str(f), "--count", "2", "-o", str(tmp_path / "v")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "[variants] speed" in err and "vs_OR" in err


def test_step_table_reads_the_cylinder_omega_off_the_polygon():
    """The step table's omega of the cylinder: the barrel's point under the rod's end over
    the cylinder's length, equal to the reference's omega (four figures, as printed)."""
    from polygon_method.text.steptable import steps_text

    sc = parse_scene(
        TIPPER.format(ox=-1500, oy=-300, stroke="", angle=150, given='speed = "0.2 rad/s cw"')
    )
    sol = solve(sc)
    ref = reference_solution(sc, dict(sol.P))
    w = float(_cyl_ref(ref, "O", "R")[3])
    line = next(x for x in steps_text(sol).splitlines() if "omega_O-R =" in x)
    assert f"= {float(f'{abs(w):.4g}'):g} rad/s {'ccw' if w > 0 else 'cw'}" in line, line
