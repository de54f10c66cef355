"""A steady gas pressure does no net work over a cycle: the engine's mean torque is exactly
nought (the closed form: the gas's work ``-p A (x(theta) - x(0))`` and the reciprocating
mass's D'Alembert work ``-(m / 2) (v^2 - v0^2)`` both return to nought after a turn), and
``solve`` writes 0, not the quadrature's rounding (-1.7e-13 N m before).

The energy over the turn is the same closed form, ``E(theta) = -p A (x - x0) - (m / 2)
omega^2 (x'^2 - x0'^2)`` with ``x = r cos theta + sqrt(l^2 - r^2 sin^2 theta)``; its
extremes (mpmath, 30 digits) give the fluctuation of energy the tool finds.
"""

from __future__ import annotations

import json
import math

import mpmath
import pytest

from polygon_method.cli import main
from polygon_method.linkage.flywheel import turning_moment
from polygon_method.scene import parse_scene

SCENE = """
title = "a steady-pressure engine with a flywheel"
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 60
AB = 240
[sliders]
B = { path = "horizontal", through = "O" }
[assembly]
B = "right"
[input]
crank = "OA"
angle = 30
speed = "3000 rpm ccw"
[masses]
MASS
[loads]
B = { pressure = "5 bar", bore = 100 }
[flywheel]
plus_minus = "1%"
radius = 150
"""

R, L, P, D = "0.06", "0.24", "5e5", "0.1"


def energy_extremes(mass):
    """dE_max by the closed form (J), at 30 digits."""
    with mpmath.workdps(30):
        r, l, w = mpmath.mpf(R), mpmath.mpf(L), 100 * mpmath.pi  # 3000 rpm
        force = mpmath.mpf(P) * mpmath.pi / 4 * mpmath.mpf(D) ** 2

        def x(t):
            return r * mpmath.cos(t) + mpmath.sqrt(l**2 - (r * mpmath.sin(t)) ** 2)

        def E(t):
            v = mpmath.diff(x, t) * w
            v0 = mpmath.diff(x, 0) * w
            return -force * (x(t) - x(0)) - mpmath.mpf(mass) / 2 * (v**2 - v0**2)

        ts = [2 * mpmath.pi * k / 720 for k in range(720)]
        es = [E(t) for t in ts]
        found = []
        for k in range(720):  # each sampled local extreme, refined where E' = 0
            a, b, c = es[k - 1], es[k], es[(k + 1) % 720]
            if (b - a) * (c - b) <= 0:
                t = mpmath.findroot(lambda t: mpmath.diff(E, t), ts[k])
                found.append(E(t))
        return float(max(found) - min(found))


@pytest.mark.parametrize("mass", ["", 'B = { mass = "1.2 kg" }'])
def test_a_steady_pressure_has_a_mean_of_nought(tmp_path, capsys, mass):
    text = SCENE.replace("MASS", mass)
    tm = turning_moment(parse_scene(text))
    assert tm.mean == 0.0 and tm.work == 0.0  # exactly: the closed form's nought
    m = 1.2 if mass else 0.0
    assert tm.dE_max == pytest.approx(energy_extremes(m), rel=1e-9)
    if not mass:  # the gas alone: the two strokes' areas, 2 r F each way
        assert tm.dE_max == pytest.approx(2 * 0.06 * 5e5 * math.pi / 4 * 0.01, rel=1e-12)
    scene = tmp_path / "steady.toml"
    scene.write_text(text)
    assert main(["solve", str(scene)]) == 0
    out = capsys.readouterr().out
    assert "mean torque T_mean = 0 N m (work per cycle 0 J;" in out
    assert "e-1" not in out.split("mean torque", 1)[1].splitlines()[0]
    assert main(["solve", "--json", str(scene)]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["turning_moment"]["T_mean"] == 0.0


def test_a_true_mean_is_kept():
    """A real mean, however small against the diagram's peaks, is not taken for rounding:
    the indicator diagram's engine keeps its 88.95 N m (tests/test_engine.py holds it)."""
    from pathlib import Path

    from polygon_method.scene import load_scene

    path = Path(__file__).resolve().parent.parent / "worked_problems/engine_flywheel.toml"
    tm = turning_moment(load_scene(path))
    assert tm.mean == pytest.approx(88.95, rel=1e-3)
