"""The flywheel of a machine driven at a steady speed (a four-bar with massive links and
loads), against an independent computation: the four-bar's positions in closed form at 40
digits, its velocities from the loop closure's derivative, the machine's energy H(theta) =
the kinetic energy at the steady speed + the potential of the weights and of the constant
loads; the driving torque by virtual power T = dH/dtheta (+ the crank's own resisting
couple), its mean by mpmath's quadrature, the crossings of the mean by mpmath's root finder,
and the energy the flywheel holds E = int (T_mean - T) dtheta between them. A hand example:
the rocker's resisting couple alone, whose energy swing is the couple times the rocker's
swing (the cosine rule at the two positions where the crank and the coupler are in line).
"""

from __future__ import annotations

import functools
import json
import math
import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import mpmath
import pytest

from polygon_method.common.errors import PolygonMethodError
from polygon_method.linkage.flywheel import turning_moment
from polygon_method.motion.solution import solve
from polygon_method.scene import load_scene, parse_scene

ROOT = Path(__file__).resolve().parent.parent
SCENE = ROOT / "worked_problems" / "fourbar_flywheel.toml"
REL = 1e-9

mp = mpmath.mp


def _fourbar(th):
    """(A, B, phi3, phi4, dphi3, dphi4): the four-bar O2 (0,0), O4 (0.3,0), 100/350/250 mm,
    B above, at the crank's angle th, the angular rates per unit crank rate."""
    r2, r3, r4, d = mp.mpf("0.1"), mp.mpf("0.35"), mp.mpf("0.25"), mp.mpf("0.3")
    A = mpmath.mpc(r2 * mpmath.cos(th), r2 * mpmath.sin(th))
    O4 = mpmath.mpc(d, 0)
    L = abs(O4 - A)
    a = (r3**2 - r4**2 + L**2) / (2 * L)
    h = mpmath.sqrt(r3**2 - a**2)
    u = (O4 - A) / L
    B = A + a * u + h * u * 1j  # (left of A -> O4: above)
    p3 = mpmath.arg(B - A)
    p4 = mpmath.arg(B - O4)
    # i r2 e^{i th} + i r3 e^{i p3} w3 = i r4 e^{i p4} w4 (per unit crank rate)
    e2, e3, e4 = 1j * (A), 1j * (B - A), 1j * (B - O4)
    m = mpmath.matrix([[e3.real, -e4.real], [e3.imag, -e4.imag]])
    w = mpmath.lu_solve(m, mpmath.matrix([-e2.real, -e2.imag]))
    return A, B, p3, p4, w[0], w[1]


def _energy(th, omega, heavy=True):
    """H: the kinetic energy at the crank's steady speed omega + the potential of the
    weights, of the 500 N load at E (down) and of the rocker's 20 N m cw couple."""
    A, B, p3, p4, w3, w4 = _fourbar(th)
    O4 = mpmath.mpc(mp.mpf("0.3"), 0)
    pot = 20 * p4  # a couple -20 (ccw) on the rocker: its potential +20 phi4
    if not heavy:
        return pot
    g = mp.mpf("9.81")
    u3 = (B - A) / abs(B - A)
    G2 = A * mp.mpf("0.5")
    G3 = (A + B) / 2
    hE = mpmath.sqrt(mp.mpf("0.2") ** 2 - mp.mpf("0.175") ** 2)
    E = G3 + hE * u3 * 1j
    G4 = B + (O4 - B) * mp.mpf("0.5")
    # velocities per unit crank rate: a point P of a link turning about Q at w: i w (P - Q)
    v2 = 1j * G2
    v3 = 1j * A + 1j * w3 * (G3 - A)
    v4 = 1j * w4 * (G4 - O4)
    kin = (
        2 * abs(v2) ** 2
        + mp.mpf("0.005")
        + 6 * abs(v3) ** 2
        + 6 * mp.mpf("0.11") ** 2 * w3**2
        + 4 * abs(v4) ** 2
        + 4 * mp.mpf("0.08") ** 2 * w4**2
    ) * (omega**2 / 2)
    pot += g * (2 * G2.imag + 6 * G3.imag + 4 * G4.imag) + 500 * E.imag
    return kin + pot


@functools.lru_cache(maxsize=None)
def _reference(omega, heavy=True, crank_couple=0):
    """(T_mean, the crossings (deg), E at each crossing): the independent solve at 40 dps."""
    with mpmath.workdps(40):
        omega = mpmath.mpf(omega)

        def T(th):
            return mpmath.diff(lambda t: _energy(t, omega, heavy), th) + crank_couple

        two_pi = 2 * mpmath.pi
        mean = mpmath.quad(T, mpmath.linspace(0, two_pi, 9)) / two_pi
        grid = [two_pi * k / 360 for k in range(361)]
        f = [T(t) - mean for t in grid]
        cross = [
            mpmath.findroot(lambda t: T(t) - mean, (grid[k], grid[k + 1]), solver="anderson")
            for k in range(360)
            if (f[k] > 0) != (f[k + 1] > 0)
        ]
        # E = int_0^th (mean - T): the energy the flywheel holds, from theta = 0
        H0 = _energy(mpmath.mpf(0), omega, heavy)
        E = [(mean - crank_couple) * c - (_energy(c, omega, heavy) - H0) for c in cross]
        return float(mean), [float(mpmath.degrees(c)) for c in cross], [float(e) for e in E]


def _close(a, b, scale):
    assert abs(a - b) <= REL * scale, (a, b)


def test_machine_flywheel_against_virtual_power_at_40_digits():
    sc = load_scene(SCENE)
    tm = turning_moment(sc)
    omega = 240 * math.pi / 30
    mean, cross, E = _reference(omega)
    assert tm.machine
    assert abs(tm.mean) <= 1e-9 * tm.T_max and abs(mean) < 1e-30  # (all loads conservative)
    assert len(tm.crossings) == len(cross) == 4
    for a, b in zip(tm.crossings, cross):
        assert abs(a - b) <= 1e-9 * 360
    dE = max(E) - min(E)
    _close(tm.dE_max, dE, dE)
    for k, lb in enumerate(tm.lobes):
        _close(lb.energy, E[(k + 1) % len(E)] - E[k], dE)
    assert abs(tm.at_max - cross[E.index(max(E))]) <= 1e-9 * 360  # the speed greatest
    assert abs(tm.at_min - cross[E.index(min(E))]) <= 1e-9 * 360
    with mpmath.workdps(40):  # the greatest and least torque on the grid, point by point
        for at, T in ((tm.at_T_max, tm.T_max), (tm.at_T_min, tm.T_min)):
            th = mpmath.radians(mpmath.mpf(at))
            ref = float(mpmath.diff(lambda t: _energy(t, mpmath.mpf(omega)), th))
            _close(T, ref, abs(ref))
    cs, w, inertia, mass = tm.flywheel
    assert cs == 0.04 and w == pytest.approx(omega, rel=1e-15)
    _close(inertia, dE / (omega**2 * 0.04), inertia)
    _close(mass, dE / (omega**2 * 0.04) / 0.2**2, mass)


def test_a_resisting_couple_on_the_crank_gives_the_mean():
    """A 5 N m couple resisting the crank itself: the motor's mean grows by 5 N m, the energy
    swing is the same (the couple is steady)."""
    sc = load_scene(SCENE)
    text = SCENE.read_text().replace(
        '"B-O4" = { torque = "20 N m cw" }',
        '"B-O4" = { torque = "20 N m cw" }\n"O2-A" = { torque = "5 N m cw" }',
    )
    sc2 = parse_scene(text)
    a, b = turning_moment(sc), turning_moment(sc2)
    _close(b.mean, 5.0, 5.0)
    _close(b.dE_max, a.dE_max, a.dE_max)


def test_hand_example_rocker_couple_alone():
    """Loads alone (no masses): the crank needs T = 20 w4 / w2; the flywheel's energy swing
    is 20 N m times the rocker's swing, between the rocker's extremes where the crank and
    the coupler are in line (O2B = 350 + 100 and 350 - 100 mm; the cosine rule at O4)."""
    text = SCENE.read_text()
    keep = []
    skip = False
    for line in text.splitlines():
        if line.startswith("["):
            skip = line.strip() in ("[masses]", "[gravity]")
        if skip or line.startswith("E = { force"):
            continue
        keep.append(line)
    sc = parse_scene("\n".join(keep) + "\n")
    assert not sc.masses and sc.gravity is None
    tm = turning_moment(sc)

    def psi(L):
        return math.acos((0.25**2 + 0.3**2 - L**2) / (2 * 0.25 * 0.3))

    swing = psi(0.45) - psi(0.25)
    dE = 20 * swing
    _close(tm.dE_max, dE, dE)
    assert abs(tm.mean) <= 1e-12 * abs(tm.T_max)
    omega = 8 * math.pi
    _close(tm.flywheel[2], dE / (omega**2 * 0.04), tm.flywheel[2])
    assert not tm.inertia_included
    # the crossings: the rocker at its extremes (w4 = 0), the crank and coupler in line
    mean, cross, E = _reference(omega, heavy=False)
    for a, b in zip(tm.crossings, cross):
        assert abs(a - b) <= 1e-9 * 360


def _run(*args):
    return subprocess.run(
        [sys.executable, "-m", "polygon_method", *args],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )


def test_views_solve_json_steps_summary_check(tmp_path):
    tm = turning_moment(load_scene(SCENE))
    omega = 240 * math.pi / 30
    _, _, E = _reference(omega)  # the answers from the independent solve, to 5 figures
    dE = max(E) - min(E)
    r = _run("solve", str(SCENE))
    assert r.returncode == 0, r.stderr
    assert "the crank's torque over a turn" in r.stdout and "I = dE_max" in r.stdout
    r = _run("solve", str(SCENE), "--json")
    d = json.loads(r.stdout)["turning_moment"]
    assert d["machine"] and d["dE_max"] == tm.dE_max
    r = _run("steps", str(SCENE))
    assert r.returncode == 0, r.stderr
    assert "running sum" in r.stdout and "I = dE_max" in r.stdout
    assert "The crank's torque over a turn: the flywheel" in r.stdout
    r = _run("sweep", str(SCENE), "--summary")
    assert r.returncode == 0, r.stderr
    assert "maximum fluctuation of energy" in r.stdout
    ans = tmp_path / "a.toml"
    I = dE / (omega**2 * 0.04)
    ans.write_text(
        SCENE.read_text().split("[answers]")[0]
        + f'\n[answers]\ntolerance = "0.5%"\ndE_max = "{dE:.5g} J"\n'
        f'I_flywheel = "{I:.5g} kg m^2"\nT_mean = "0 N m"\n'
    )
    r = _run("check", str(ans))
    assert r.returncode == 0, r.stdout + r.stderr


def test_refusals_in_one_line():
    sc = load_scene(SCENE)
    bad = replace(sc, input=replace(sc.input, alpha=3.0))
    with pytest.raises(PolygonMethodError, match="steady speed"):
        turning_moment(bad)
    sol = solve(sc)
    assert sol.scene.flywheel is not None


def test_draw_cycle_of_a_machine_and_its_refusal_in_one_line(tmp_path):
    """The machine's sheet is drawn (measured in test_machine_cycle_sheet); a machine that
    cannot turn at a steady speed is refused in one line, no file written."""
    r = _run("draw", str(SCENE), "--diagram", "cycle", "-o", str(tmp_path / "c.pdf"))
    assert r.returncode == 0 and (tmp_path / "c.pdf").read_bytes().startswith(b"%PDF")
    bad = tmp_path / "bad.toml"
    bad.write_text(SCENE.read_text().replace("acceleration = 0", 'acceleration = "3 rad/s^2 ccw"'))
    r = _run("draw", str(bad), "--diagram", "cycle", "-o", str(tmp_path / "b.pdf"))
    assert r.returncode == 2 and r.stderr.count("\n") == 1 and "steady speed" in r.stderr
    assert not (tmp_path / "b.pdf").exists()


PRESS = """
title = "a slider crank press run by a motor"
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 100
AB = 400
[sliders]
B = { path = "horizontal", through = "O" }
[assembly]
B = "right"
[input]
crank = "OA"
angle = 30
speed = "300 rpm ccw"
acceleration = 0
[masses]
B = { mass = "10 kg" }
[loads]
B = { force = "1000 N", direction = 180 }
[flywheel]
coefficient = 0.03
gyration = 250
"""


def test_slider_crank_machine_closed_form():
    """The block's kinetic energy at the steady speed and the potential of the steady 1000 N
    on it (x = r cos t + sqrt(l^2 - r^2 sin^2 t)): H = m (w x')^2 / 2 + 1000 x, the crank's
    torque dH/dt, its mean nought, dE_max = max H - min H (mpmath's roots of H' at 40
    digits from a 1 deg grid)."""
    tm = turning_moment(parse_scene(PRESS))
    w = 10 * math.pi
    with mpmath.workdps(40):
        r, l, m = mpmath.mpf("0.1"), mpmath.mpf("0.4"), 10

        def x(t):
            return r * mpmath.cos(t) + mpmath.sqrt(l**2 - (r * mpmath.sin(t)) ** 2)

        def H(t):
            return m * (w * mpmath.diff(x, t)) ** 2 / 2 + 1000 * x(t)

        def dH(t):
            return mpmath.diff(H, t)

        grid = [2 * mpmath.pi * k / 360 for k in range(361)]
        f = [dH(t) for t in grid]
        roots = [
            mpmath.findroot(dH, (grid[k], grid[k + 1]), solver="anderson")
            for k in range(360)
            if f[k] != 0 and (f[k] > 0) != (f[k + 1] > 0)
        ] + [t for t, v in zip(grid[:-1], f) if v == 0]
        hs = [H(t) for t in roots] + [H(mpmath.mpf(0)), H(mpmath.pi)]  # (dead centres)
        dE = float(max(hs) - min(hs))
    assert abs(tm.mean) <= 1e-12 * tm.T_max
    _close(tm.dE_max, dE, dE)
    _close(tm.flywheel[2], dE / (w * w * 0.03), tm.flywheel[2])
    _close(tm.flywheel[3], dE / (w * w * 0.03) / 0.25**2, tm.flywheel[3])


@pytest.mark.parametrize(
    "old, new, words",
    [
        ("acceleration = 0", 'acceleration = "2 rad/s^2 ccw"', "steady speed"),
        (
            '[masses]\nB = { mass = "10 kg" }\n[loads]\nB = { force = "1000 N", direction = 180 }\n',
            "",
            "the flywheel is an engine's or a machine's",
        ),
    ],
)
def test_refused_in_one_line_by_the_command(tmp_path, old, new, words):
    assert old in PRESS
    p = tmp_path / "press.toml"
    p.write_text(PRESS.replace(old, new))
    r = _run("solve", str(p))
    assert r.returncode == 2 and r.stderr.count("\n") == 1, r.stderr
    assert words in r.stderr and "[flywheel]" in r.stderr


def test_refused_where_the_motion_repeats_only_after_several_turns(tmp_path):
    """An epicyclic train whose ring turns 4/3 times a turn of the arm, a rod from the ring
    to a block: back after 3 turns, so no turn's torque; refused in one line."""
    text = (ROOT / "tests" / "textbook" / "rolling_ring_output.toml").read_text()
    text = text.replace('acceleration = "15 rad/s^2 cw"', "acceleration = 0")
    text = text.split("[answers]")[0]
    p = tmp_path / "ring.toml"
    p.write_text(text + '\n[masses]\nS = { mass = "2 kg" }\n[flywheel]\ncoefficient = 0.02\n')
    r = _run("solve", str(p))
    assert r.returncode == 2 and r.stderr.count("\n") == 1, r.stderr
    assert "repeats every 3 turns" in r.stderr


def test_turning_clockwise_the_same_swing():
    """The machine's energy H depends on the place and w^2 alone (every load here is
    steady): run clockwise, the crank's torque in its sense is -dH/dtheta, the turn read
    the other way, and dE_max is the same range of H; the crossings mirror (360 - phi)."""
    a = turning_moment(load_scene(SCENE))
    b = turning_moment(parse_scene(SCENE.read_text().replace("240 rpm ccw", "240 rpm cw")))
    _close(b.dE_max, a.dE_max, a.dE_max)
    mirrored = sorted((360.0 - c) % 360.0 for c in a.crossings)
    for x, y in zip(b.crossings, mirrored):
        assert abs(x - y) <= 1e-9 * 360
