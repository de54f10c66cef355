"""The engine chapter: the gas force as books give it (towards the crank, a double-acting
cylinder), the indicator diagram over a whole cycle.

Every number is compared with the slider crank's closed forms computed here at 50 digits
(the piston's place ``x = r cos t + sqrt(l^2 - r^2 sin^2 t)`` differentiated by mpmath,
the piston effort, the rod's thrust, the turning moment
``T = F_P r (sin t + sin 2t / (2 sqrt(n^2 - sin^2 t)))``) and with the indicator's pressure
interpolated here, to 1e-9.
"""

from __future__ import annotations

import math
from pathlib import Path

import mpmath
import pytest

from engines import ENGINE, _precision, closed_forms, engine  # noqa: F401  (a fixture)
from polygon_method.common.errors import PolygonMethodError, SceneError
from polygon_method.scene import load_scene, parse_scene
from polygon_method.motion.solution import solve


def closed(theta_idc, theta, r, l, rpm, m, F_gas, sg=1):
    """(turning moment in the sense of rotation, thrust in the rod, side thrust) of
    :func:`engines.closed_forms`, as floats."""
    cf = closed_forms(theta_idc, theta, r, l, rpm, m, F_gas, sg)
    return float(cf["T"]), float(abs(cf["F_Q"])), float(abs(cf["F_N"]))


def close(got, want, rel=1e-9):
    assert abs(got - want) <= rel * max(abs(want), 1e-300), (got, want)


@pytest.mark.parametrize(
    "side, sense, theta",
    [("right", "ccw", 60), ("right", "cw", 200), ("left", "ccw", 100), ("left", "cw", 310)],
)
def test_the_gas_force_pushes_towards_the_crank_by_default(side, sense, theta):
    p, bore = 2.0, 100
    gas = f'[loads]\nB = {{ pressure = "{p} N/mm^2", bore = {bore} }}\n'
    sc = engine(theta, side=side, sense=sense, extra=gas)
    sol = solve(sc)
    ((fx, fy),) = [ld.force for ld in sc.loads]
    assert fy == 0.0 and (fx < 0) == (side == "right")  # towards O from the piston's side
    F = p * 1e6 * math.pi / 4 * (bore / 1000) ** 2
    idc = 0 if side == "right" else 180
    sg = 1 if sense == "ccw" else -1
    T, F_Q, F_N = closed(idc, theta, 150, 600, 1800, 2.5, F, sg)
    close(-sg * sol.forces.input_torque, T)  # the driver holds the turning moment back
    close(math.hypot(*sol.forces.pin("B", "AB")), F_Q)
    close(abs(sol.forces.guides[0].normal), F_N)
    # the same as the direction stated
    d = 180 if side == "right" else 0
    same = engine(
        theta,
        side=side,
        sense=sense,
        extra=f'[loads]\nB = {{ pressure = "{p} N/mm^2", bore = {bore}, direction = {d} }}\n',
    )
    close(solve(same).forces.input_torque, sol.forces.input_torque, 1e-15)


def test_a_double_acting_cylinder_takes_the_rod_off_the_crank_side():
    """Cover side p1 on the bore's circle, crank side p2 on the circle less the rod's."""
    p1, p2, bore, rod = 0.8, 0.15, 300, 50
    gas = (
        f'[loads]\nB = {{ pressure = "{p1} N/mm^2", back = "{p2} N/mm^2", bore = {bore}, '
        f"rod = {rod} }}\n"
    )
    sc = engine(125, extra=gas)
    A = math.pi / 4 * 0.3**2
    a = math.pi / 4 * 0.05**2
    F = p1 * 1e6 * A - p2 * 1e6 * (A - a)
    T, _, _ = closed(0, 125, 150, 600, 1800, 2.5, F)
    close(-solve(sc).forces.input_torque, T)
    # the rod alone (no back pressure): the pressure on the crank side's annulus, as before
    sc = engine(
        125,
        extra=f'[loads]\nB = {{ pressure = "{p1} N/mm^2", bore = {bore}, '
        f"rod = {rod}, direction = 180 }}\n",
    )
    T, _, _ = closed(0, 125, 150, 600, 1800, 2.5, p1 * 1e6 * (A - a))
    close(-solve(sc).forces.input_torque, T)


def test_towards_the_crank_needs_a_crank_and_a_side():
    text = ENGINE.format(r=150, l=600, theta=30, rpm=100, m=1, side="right", sense="ccw")
    text = text.replace('path = "horizontal", through = "O"', 'path = "vertical", through = "O"')
    text = text.replace('B = "right"', 'B = "above"')
    sc = parse_scene(text + '[loads]\nB = { pressure = "1 bar", bore = 50 }\n')
    ((fx, fy),) = [ld.force for ld in (solve(sc).scene.loads)]
    assert fx == 0.0 and fy < 0  # a vertical engine, the piston above: the gas pushes down
    # a piston on a moving guide has no crank to push towards: refused in one line
    bad = parse_scene(BASE_SLOTTED + '[loads]\nB = { pressure = "1 bar", bore = 50 }\n')
    with pytest.raises(PolygonMethodError) as exc:
        solve(bad)
    assert "towards the crank" in str(exc.value) and "give its direction" in str(exc.value)


BASE_SLOTTED = """
units = "mm"
[ground]
O = [0, 0]
C = [0, -200]
[links]
OB = 100
CD = 400
[sliders]
B = { along = "CD" }
[input]
crank = "OB"
angle = 30
speed = "10 rad/s ccw"
"""


# --------------------------------------------------------------------------- indicator


def _interp(xs, ps, x):
    """Linear interpolation written out (the test's own)."""
    for (x0, p0), (x1, p1) in zip(zip(xs, ps), zip(xs[1:], ps[1:])):
        if x0 <= x <= x1:
            return p0 + (p1 - p0) * (x - x0) / (x1 - x0)
    raise AssertionError(x)


ANGLES = [0, 20, 60, 120, 180, 240, 300, 360, 420, 480, 540, 600, 660, 720]
PRESS = [3, 35, 20, 8, 2, 0.5, -0.2, -0.5, -0.4, 0.2, 1.0, 2.0, 2.5, 3]  # bar


@pytest.mark.parametrize("theta", [15, 95, 200, 333, 380, 455, 610, 719])
def test_a_four_stroke_indicator_against_the_crank_angle(theta):
    ind = (
        f'[indicator]\nbore = 80\ncycle = "4-stroke"\nunit = "bar"\nangle = {ANGLES}\n'
        f"pressure = {PRESS}\n"
    )
    sc = engine(theta, extra=ind)
    F = _interp(ANGLES, PRESS, theta % 720) * 1e5 * math.pi / 4 * 0.08**2
    T, F_Q, _ = closed(0, theta, 150, 600, 1800, 2.5, F)
    f = solve(sc).forces
    close(-f.input_torque, T)
    close(math.hypot(*f.pin("B", "AB")), F_Q)


STROKE = [0, 0.1, 0.25, 0.5, 0.75, 1]
ROWS = [
    [1.0, 0.9, 0.9, 0.9, 0.9, 0.9],  # suction, from i.d.c.
    [8.0, 6.0, 4.0, 2.5, 1.5, 0.9],  # compression, read from i.d.c.
    [40.0, 30.0, 16.0, 8.0, 5.0, 3.0],  # expansion
    [1.2, 1.2, 1.2, 1.2, 1.2, 3.0],
]  # exhaust


@pytest.mark.parametrize(
    "theta, side, sense",
    [
        (30, "right", "ccw"),
        (250, "right", "ccw"),
        (400, "right", "ccw"),
        (650, "right", "ccw"),
        (120, "left", "cw"),
        (-300, "left", "cw"),
    ],
)
def test_a_four_stroke_indicator_against_the_stroke(theta, side, sense):
    ind = (
        f'[indicator]\nbore = 80\ncycle = "4-stroke"\nunit = "bar"\nstroke = {STROKE}\n'
        f"pressure = {ROWS}\n"
    )
    sc = engine(theta, side=side, sense=sense, extra=ind)
    idc = 0 if side == "right" else 180
    sg = 1 if sense == "ccw" else -1
    phase = (sg * (theta - idc)) % 720
    t = math.radians(phase)
    r, l = 0.15, 0.6
    x = (l + r - (r * math.cos(t) + math.sqrt(l * l - (r * math.sin(t)) ** 2))) / (2 * r)
    p = _interp(STROKE, ROWS[int(phase // 180)], x)
    F = p * 1e5 * math.pi / 4 * 0.08**2
    T, _, _ = closed(idc, theta, 150, 600, 1800, 2.5, F, sg)
    close(-sg * solve(sc).forces.input_torque, T)


@pytest.mark.parametrize(
    "extra, words",
    [
        ('[indicator]\nbore = 80\nunit = "bar"\nangle = [0, 360]\n', "no pressure"),
        ('[indicator]\nbore = 80\nunit = "bars"\nangle = [0, 360]\npressure = [1, 1]\n', "unit"),
        ('[indicator]\nunit = "bar"\nangle = [0, 360]\npressure = [1, 1]\n', "give bore"),
        ('[indicator]\nbore = 80\nunit = "bar"\nangle = [0, 400]\npressure = [1, 1]\n', "0 to 360"),
        ('[indicator]\nbore = 80\nunit = "bar"\nangle = [0, 0]\npressure = [1, 1]\n', "increase"),
        ('[indicator]\nbore = 80\nunit = "bar"\nangle = [0, 90]\npressure = [1]\n', "at least two"),
        (
            '[indicator]\nbore = 80\nunit = "bar"\nstroke = [0, 1]\npressure = [[1, 1]]\n',
            "one row per stroke",
        ),
        (
            '[indicator]\nbore = 80\nunit = "bar"\nangle = [0, 1]\nstroke = [0, 1]\npressure = [1, 1]\n',
            "one of them",
        ),
        (
            '[indicator]\nbore = 80\nunit = "bar"\ncycle = "3-stroke"\nangle = [0, 1]\npressure = [1, 1]\n',
            "4-stroke",
        ),
        (
            '[indicator]\npiston = "A"\nbore = 80\nunit = "bar"\nangle = [0, 1]\npressure = [1, 1]\n',
            "no slider",
        ),
        (
            '[indicator]\nbore = 80\nunit = "bar"\nangle = [0, 1]\npresure = [1, 1]\n',
            "did you mean",
        ),
    ],
)
def test_a_bad_indicator_is_one_located_line(extra, words):
    with pytest.raises(SceneError) as exc:
        engine(30, extra=extra)
    assert words in str(exc.value) and "[indicator]" in str(exc.value)


# --------------------------------------------------------------------------- the cycle


def _xdd(t, R, L):
    """The piston's d^2x/dt^2 (per unit crank speed squared), x = R cos t + sqrt(L^2 -
    R^2 sin^2 t), written out."""
    S = L**2 - (R * mpmath.sin(t)) ** 2
    return (
        -R * mpmath.cos(t)
        - R**2 * mpmath.cos(2 * t) / mpmath.sqrt(S)
        - R**4 * mpmath.sin(2 * t) ** 2 / (4 * S ** mpmath.mpf(1.5))
    )


class _Reference:
    """The in-line engine's turning moment over its cycle at 30 digits, from the closed
    forms and the indicator's pressure interpolated here; the mean, the crossings, the
    energies and the flywheel by mpmath's quadrature and root finding."""

    def __init__(self, r, l, rpm, m, area, cycle, pressure, breaks):
        mpmath.mp.dps = 30
        self.R, self.L = mpmath.mpf(r), mpmath.mpf(l)
        self.w = 2 * mpmath.pi * rpm / 60
        self.m, self.area, self.cycle, self.p = m, area, cycle, pressure
        self.breaks = sorted(set([mpmath.mpf(0), cycle] + list(breaks)))

    def T(self, t):
        R, L = self.R, self.L
        F_P = self.p(t) * self.area + self.m * self.w**2 * _xdd(t, R, L)  # towards O
        n = L / R
        return (
            F_P
            * R
            * (mpmath.sin(t) + mpmath.sin(2 * t) / (2 * mpmath.sqrt(n**2 - mpmath.sin(t) ** 2)))
        )

    def integral(self, a, b):
        """The integral of T from ``a`` to ``b``: each piece between the pressure's breaks
        integrated once and kept (the mean and every running energy add them up)."""
        if not hasattr(self, "_pieces"):
            self._pieces = {}
        total, x = mpmath.mpf(0), a
        for brk in [y for y in self.breaks if a < y < b] + [b]:
            if (x, brk) not in self._pieces:
                self._pieces[x, brk] = mpmath.quad(self.T, [x, brk], method="gauss-legendre")
            total += self._pieces[x, brk]
            x = brk
        return total

    def solve(self, known=()):
        """(mean, crossings, dE_max); ``known``: crossings known exactly (where the mean
        line passes through a zero of the turning moment, at a dead centre). The crossings
        are bracketed on a grid of 720 (two crossings closer than a 720th of the cycle
        would be missed here: the counts would differ and the test fail)."""
        mean = self.integral(0, self.cycle) / self.cycle
        g = lambda t: self.T(t) - mean  # noqa: E731
        grid = [self.cycle * k / 720 for k in range(721)]
        gs = [g(t) for t in grid]
        cross = list(known)
        for a, b, ga, gb in zip(grid, grid[1:], gs, gs[1:]):
            if any(a <= c <= b for c in known):
                continue
            if (ga > 0) != (gb > 0):
                cross.append(mpmath.findroot(g, (a, b), solver="anderson"))
        # one cycle, [0, cycle): its end is its start
        cross = sorted(c for c in cross if c < self.cycle * (1 - mpmath.mpf(10) ** -20))
        E, done, at = [], mpmath.mpf(0), mpmath.mpf(0)
        for c in cross:  # from the last break before c: the pieces before it are kept
            last = max([at] + [y for y in self.breaks if at < y < c])
            done += self.integral(at, last) + mpmath.quad(
                self.T, [last, c], method="gauss-legendre"
            )
            at = c
            E.append(done - mean * c)
        return mean, cross, max(E) - min(E)


def _check_cycle(sc, ref, rel=1e-9, known=()):
    from polygon_method.linkage import turning_moment

    tm = turning_moment(sc)
    mean, cross, dE = ref.solve(known)
    # the mean to 1e-9 of itself, or of the greatest turning moment where it is nought
    assert abs(tm.mean - float(mean)) <= rel * max(abs(float(mean)), abs(tm.T_max)), tm.mean
    assert len(tm.crossings) == len(cross)
    for got, want in zip(tm.crossings, cross):
        assert abs(math.radians(got) - float(want)) <= 1e-9, (got, float(mpmath.degrees(want)))
    close(tm.dE_max, float(dE), rel)
    assert abs(sum(lb.energy for lb in tm.lobes)) <= 1e-9 * float(dE)  # the cycle closes
    return tm


def test_the_written_out_acceleration_is_the_derivative():
    mpmath.mp.dps = 30
    R, L, t = mpmath.mpf("0.15"), mpmath.mpf("0.6"), mpmath.mpf("0.7")
    x = lambda u: R * mpmath.cos(u) + mpmath.sqrt(L**2 - (R * mpmath.sin(u)) ** 2)  # noqa
    assert abs(_xdd(t, R, L) - mpmath.diff(x, t, 2)) < mpmath.mpf(10) ** -25


def test_the_four_stroke_cycle_against_the_crank_angle_table():
    ind = (
        f'[indicator]\nbore = 80\ncycle = "4-stroke"\nunit = "bar"\nangle = {ANGLES}\n'
        f"pressure = {PRESS}\n[flywheel]\ncoefficient = 0.02\nradius = 300\n"
    )
    sc = engine(60, extra=ind)
    area = mpmath.pi / 4 * mpmath.mpf("0.08") ** 2
    nodes = [mpmath.radians(a) for a in ANGLES]
    vals = [mpmath.mpf(p) * 100000 for p in PRESS]

    def p(t):
        d = min(max(mpmath.degrees(t), 0), 720)  # the cycle's ends, to rounding
        for k in range(len(ANGLES) - 1):
            if ANGLES[k] <= d <= ANGLES[k + 1]:
                return vals[k] + (vals[k + 1] - vals[k]) * (t - nodes[k]) / (
                    nodes[k + 1] - nodes[k]
                )
        raise AssertionError(d)

    ref = _Reference(
        "0.15", "0.6", 1800, 2.5, area, 4 * mpmath.pi, p, nodes + [mpmath.pi * k for k in range(5)]
    )
    tm = _check_cycle(sc, ref)
    w = 1800 * math.pi / 30
    close(tm.flywheel[2], tm.dE_max / (w * w * 0.02), 1e-15)
    close(tm.flywheel[3], tm.flywheel[2] / 0.09, 1e-15)


def test_the_four_stroke_cycle_against_the_stroke_table():
    ind = (
        f'[indicator]\nbore = 80\ncycle = "4-stroke"\nunit = "bar"\nstroke = {STROKE}\n'
        f"pressure = {ROWS}\n"
    )
    sc = engine(60, extra=ind)
    R, L = mpmath.mpf("0.15"), mpmath.mpf("0.6")

    def frac(t):
        return (L + R - (R * mpmath.cos(t) + mpmath.sqrt(L**2 - (R * mpmath.sin(t)) ** 2))) / (
            2 * R
        )

    def p(t):
        k = min(int(t / mpmath.pi), 3)
        x = frac(t)
        row = ROWS[k]
        for j in range(len(STROKE) - 1):
            if STROKE[j] <= x <= STROKE[j + 1] + mpmath.mpf(10) ** -25:
                return 100000 * (
                    row[j]
                    + (mpmath.mpf(row[j + 1]) - row[j])
                    * (x - STROKE[j])
                    / (mpmath.mpf(STROKE[j + 1]) - STROKE[j])
                )
        return 100000 * mpmath.mpf(row[-1] if x > 1 else row[0])

    breaks = [mpmath.pi * k for k in range(5)]
    for k in range(4):
        for xv in STROKE[1:-1]:
            breaks.append(
                mpmath.findroot(
                    lambda t: frac(t) - xv,
                    (mpmath.pi * k + 1e-12, mpmath.pi * (k + 1) - 1e-12),
                    solver="anderson",
                )
            )
    area = mpmath.pi / 4 * mpmath.mpf("0.08") ** 2
    _check_cycle(sc, _Reference("0.15", "0.6", 1800, 2.5, area, 4 * mpmath.pi, p, breaks))


def test_a_steady_gas_force_averages_nothing_over_a_turn():
    """A constant pressure pushes the piston towards the crank on both strokes: what it
    gives on the out stroke it takes back on the return; the inertia averages nothing."""
    sc = engine(30, extra='[loads]\nB = { pressure = "2 N/mm^2", bore = 100 }\n')
    area = mpmath.pi / 4 * mpmath.mpf("0.1") ** 2
    ref = _Reference(
        "0.15", "0.6", 1800, 2.5, area, 2 * mpmath.pi, lambda t: mpmath.mpf(2) * 10**6, [mpmath.pi]
    )
    # the mean is nought and so is the turning moment at the dead centres: both cross there
    tm = _check_cycle(sc, ref, known=(mpmath.mpf(0), mpmath.pi))
    assert abs(tm.mean) <= 1e-9 * abs(tm.T_max)


def test_the_sweep_writes_the_turning_moment_and_the_summary_the_flywheel():
    import numpy as np
    from polygon_method.linkage.summary import summary_of
    from polygon_method.motion.sweeps import sweep

    ind = (
        f'[indicator]\nbore = 80\ncycle = "4-stroke"\nunit = "bar"\nangle = {ANGLES}\n'
        f'pressure = {PRESS}\n[flywheel]\nplus_minus = "1%"\ngyration = 250\n'
    )
    sc = engine(60, extra=ind)
    th = np.radians([10.0, 95.0, 400.0, 700.0])
    res = sweep(sc, th)
    cols = {n: (u, v) for n, u, v in res.columns()}
    area = math.pi / 4 * 0.08**2
    for k, d in enumerate([10.0, 95.0, 400.0, 700.0]):
        T, _, _ = closed(0, d, 150, 600, 1800, 2.5, _interp(ANGLES, PRESS, d) * 1e5 * area)
        close(float(cols["turning_moment"][1][k]), T)
        close(float(cols["crank_effort"][1][k]), T / 0.15)
    assert cols["turning_moment"][0] == "N m" and "piston_effort" in cols
    text = summary_of(sweep(sc)).text()
    assert "mean torque T_mean" in text and "maximum fluctuation of energy dE_max" in text
    assert "Cs = 2 x 0.01 = 0.02" in text and "I = dE_max / (w^2 Cs)" in text
    assert "mass m = I / k^2" in text


def test_the_sweep_of_a_four_stroke_runs_over_its_720_degree_cycle(tmp_path, capsys):
    """`sweep --steps N --csv` of a four-stroke engine: N angles a turn over its two turns (the
    indicator table's 0 to 720 deg), the turning moment at each the closed form's under
    the pressure interpolated here: at 90 deg (suction) and 450 deg (expansion) they
    differ."""
    from polygon_method.cli import main

    ind = (
        f'[indicator]\nbore = 80\ncycle = "4-stroke"\nunit = "bar"\nangle = {ANGLES}\n'
        f"pressure = {PRESS}\n"
    )
    f = tmp_path / "e.toml"
    f.write_text(
        ENGINE.format(r=150, l=600, theta=60, rpm=1800, m=2.5, side="right", sense="ccw") + ind
    )
    out = tmp_path / "e.csv"
    assert main(["sweep", str(f), "--steps", "4", "--csv", str(out)]) == 0
    capsys.readouterr()
    rows = [r.split(",") for r in out.read_text().splitlines()]
    i = rows[0].index("turning_moment [N m]")
    degs = [float(r[0]) for r in rows[1:]]
    assert degs == pytest.approx([90.0 * k for k in range(8)], abs=1e-9)
    area = math.pi / 4 * 0.08**2
    for d, r in zip(degs, rows[1:]):
        T, _, _ = closed(0, d, 150, 600, 1800, 2.5, _interp(ANGLES, PRESS, d) * 1e5 * area)
        assert abs(float(r[i]) - T) <= 1e-9 * max(abs(T), 1.0), (d, float(r[i]), T)
    assert abs(float(rows[2][i]) - float(rows[6][i])) > 1.0  # 90 and 450 deg


def test_the_plot_has_the_turning_moment_diagram_below():
    import numpy as np
    from polygon_method.linkage import turning_moment
    from polygon_method.draw.plots import plot_figure
    from polygon_method.motion.sweeps import sweep

    sc = engine(
        60,
        extra=f'[indicator]\nbore = 80\ncycle = "4-stroke"\nunit = "bar"\n'
        f"angle = {ANGLES}\npressure = {PRESS}\n",
    )
    fig = plot_figure(sweep(sc, np.radians(np.arange(0.0, 360.0, 10.0))))
    panel = fig.axes[-1]
    assert len(fig.axes) == 5 and "turning moment" in panel.get_ylabel()
    assert panel.get_xlim() == (0.0, 720.0)
    ticks = panel.get_xticks()
    assert all(t % 90 == 0 for t in ticks)  # round ticks
    mean = turning_moment(sc).mean
    assert any(
        abs(ln.get_ydata()[0] - mean) <= 1e-12 * abs(mean)
        for ln in panel.lines
        if len(ln.get_ydata()) == 2
    )
    # a mechanism that is no engine keeps its four panels
    plain = parse_scene(
        ENGINE.format(r=150, l=600, theta=30, rpm=100, m=1, side="right", sense="ccw")
    )
    assert len(plot_figure(sweep(plain, np.radians([0.0, 90.0, 180.0]))).axes) == 4
    # the worked four-stroke at 390 deg (30 deg into its second turn), swept over its cycle:
    # its instant is marked at 390 deg, where its gas force is, not at 30 deg
    sc = load_scene(
        Path(__file__).resolve().parent.parent / "worked_problems" / "engine_flywheel.toml"
    )
    fig = plot_figure(sweep(sc, np.radians(np.arange(0.0, 720.0, 10.0))))
    marks = {
        float(ln.get_xdata()[0])
        for ax in fig.axes[:4]
        for ln in ax.lines
        if ln.get_linestyle() != "-" and len(set(ln.get_xdata())) == 1
    }
    assert marks == {390.0}, marks


# --------------------------------------------------------------------------- Klein

OFFSET = """
units = "mm"
[ground]
O = [0, 0]
[links]
OA = {r}
AB = {l}
[sliders]
B = {{ path = "horizontal", through = [0, {e}] }}
[assembly]
B = "{side}"
[input]
crank = "OA"
angle = {theta}
speed = "{rpm} rpm {sense}"
"""


@pytest.mark.parametrize(
    "theta, e, side, sense",
    [
        (60, 0, "right", "ccw"),
        (200, 0, "right", "cw"),
        (130, 0, "left", "ccw"),
        (35, -40, "right", "ccw"),
        (290, 50, "left", "cw"),
        (95, 30, "right", "ccw"),
    ],
)
def test_klein_gives_the_piston_as_the_closed_form(theta, e, side, sense):
    """The piston's place ``x(t) = r cos t + s sqrt(l^2 - (r sin t - e)^2)`` along the line
    of stroke (y = e), differentiated by mpmath: v = x' w, a = x'' w^2 (uniform speed)."""
    from polygon_method.linkage.klein import klein_of

    r, l, rpm = 150, 600, 300
    sc = parse_scene(OFFSET.format(r=r, l=l, e=e, theta=theta, rpm=rpm, side=side, sense=sense))
    sol = solve(sc)
    k, names = klein_of(sol)
    assert names == ("O", "A", "B")
    mpmath.mp.dps = 40
    R, L, E = mpmath.mpf(r) / 1000, mpmath.mpf(l) / 1000, mpmath.mpf(e) / 1000
    s = 1 if side == "right" else -1
    w = (1 if sense == "ccw" else -1) * 2 * mpmath.pi * rpm / 60

    def x(t):
        return R * mpmath.cos(t) + s * mpmath.sqrt(L**2 - (R * mpmath.sin(t) - E) ** 2)

    t = mpmath.radians(theta)
    v, a = mpmath.diff(x, t, 1) * w, mpmath.diff(x, t, 2) * w**2
    scale_v, scale_a = float(R * abs(w)), float(R * w**2)
    assert abs(k.v_P[0] - float(v)) <= 1e-9 * scale_v and abs(k.v_P[1]) <= 1e-9 * scale_v
    assert abs(k.a_P[0] - float(a)) <= 1e-9 * scale_a and abs(k.a_P[1]) <= 1e-9 * scale_a
    # and the polygon's
    assert math.dist(k.v_P, sol.V["B"]) <= 1e-9 * scale_v
    assert math.dist(k.a_P, sol.A["B"]) <= 1e-9 * scale_a
    # the rod's: v_BA from triangle OAM, its angular velocity from the polygon
    wr = sol.W["AB"]
    (ax_, ay_), (bx, by) = sol.P["A"], sol.P["B"]
    assert math.dist(k.v_PC, (-wr * (by - ay_), wr * (bx - ax_))) <= 1e-9 * scale_v
    # the construction's circles: K and L on both, the chord square to the rod
    if k.K is not None:
        for pt in (k.K, k.L):
            assert abs(math.dist(pt, k.C) - math.dist(k.M, k.C)) <= 1e-12
            mid = ((k.C[0] + k.P[0]) / 2, (k.C[1] + k.P[1]) / 2)
            assert abs(math.dist(pt, mid) - math.dist(k.C, k.P) / 2) <= 1e-12


def test_klein_is_in_steps_and_not_for_an_accelerating_crank():
    from polygon_method.text.steptable import steps_text

    sc = parse_scene(OFFSET.format(r=150, l=600, e=0, theta=60, rpm=250, side="right", sense="ccw"))
    text = steps_text(solve(sc))
    assert "Klein's construction" in text and "a_B = omega^2 x NO" in text
    acc = parse_scene(
        OFFSET.format(r=150, l=600, e=0, theta=60, rpm=250, side="right", sense="ccw")
        + 'acceleration = "5 rad/s^2 ccw"\n'
    )
    assert "Klein's construction" not in steps_text(solve(acc))


def test_klein_is_drawn_on_the_configuration_diagram_to_scale():
    from polygon_method.draw.diagrams import _configuration
    from polygon_method.polygons.scales import diagram_scales

    sc = parse_scene(
        OFFSET.format(r=150, l=600, e=-40, theta=35, rpm=250, side="right", sense="ccw")
    )
    sol = solve(sc)
    space = diagram_scales(sol)[0]
    sk = _configuration(sol, space)
    drawn = {opts["gid"]: pts for kind, pts, opts in sk.items if kind == "line"}
    (n, o) = drawn["klein-NO"]
    w = abs(sol.W["OA"])
    # N O, to the diagram's scale, is a_B / omega^2; O M is v_B / omega
    assert abs(math.dist(n, o) * space.per_cm - math.hypot(*sol.A["B"]) / w**2) <= 1e-9
    (o2, m) = drawn["klein-OM"]
    assert abs(math.dist(o2, m) * space.per_cm - math.hypot(*sol.V["B"]) / w) <= 1e-9
    assert any("Klein's construction" in lab.text for lab in sk.notes)


# --------------------------------------------------------------------------- check


def _verdicts(sc, answers):
    from polygon_method.check import check_answers
    from polygon_method.scene import parse_answers

    _, ans = parse_answers("[answers]\n" + answers, sc)
    return {v.key: v for v in check_answers(solve(sc), ans)}


def test_the_engine_answer_keys_and_their_slips():
    from polygon_method.linkage import turning_moment

    ind = (
        f'[indicator]\nbore = 80\ncycle = "4-stroke"\nunit = "bar"\nangle = {ANGLES}\n'
        f'pressure = {PRESS}\n[flywheel]\nplus_minus = "1%"\nradius = 300\n'
    )
    sc = engine(60, extra=ind)
    tm = turning_moment(sc)
    I, m = tm.flywheel[2], tm.flywheel[3]
    big = max(abs(lb.energy) for lb in tm.lobes)
    got = _verdicts(
        sc,
        f'T_mean = "{tm.mean:.5g} N m"\ndE_max = "{tm.dE_max:.5g} J"\n'
        f'I_flywheel = "{2 * I:.5g} kg m^2"\nm_flywheel = "{m:.5g} kg"\n',
    )
    assert got["T_mean"].ok and got["dE_max"].ok and got["m_flywheel"].ok
    assert not got["I_flywheel"].ok and got["I_flywheel"].mistake == "cs_half_range"
    got = _verdicts(sc, f'dE_max = "{big:.5g} J"\nT_mean = "{2 * tm.mean:.5g} N m"\n')
    assert got["dE_max"].mistake == "largest_area"
    assert got["T_mean"].mistake == "one_turn_cycle"
    # the piston's inertia left out: the gas force's efforts, from the closed forms
    F = _interp(ANGLES, PRESS, 60) * 1e5 * math.pi / 4 * 0.08**2
    T_gas, _, _ = closed(0, 60, 150, 600, 1800, 0.0, F)
    T_all, _, _ = closed(0, 60, 150, 600, 1800, 2.5, F)
    got = _verdicts(sc, f'crank_effort = "{T_gas / 0.15:.5g} N"\npiston_effort = "{F:.5g} N"\n')
    for k in ("crank_effort", "piston_effort"):
        assert not got[k].ok and got[k].mistake == "piston_inertia_left_out", k
    close(got["crank_effort"].correct, abs(T_all) / 0.15)


def test_engine_answer_keys_are_refused_where_the_scene_cannot_give_them():
    sc = engine(60, extra='[loads]\nB = { pressure = "2 N/mm^2", bore = 100 }\n')
    with pytest.raises(SceneError) as exc:
        _verdicts(sc, 'I_flywheel = "2 kg m^2"\n')
    assert "[flywheel]" in str(exc.value) and "I_flywheel" in str(exc.value)
    with pytest.raises(SceneError) as exc:
        _verdicts(sc, 'dE_max = "2 parsecs"\n')
    assert "dE_max" in str(exc.value)


def test_large_values_are_written_as_the_step_table_writes_them():
    """The rod's alpha of the worked four-stroke engine (about 1.2e4 rad/s^2) in the printed
    solution: a plain number, no exponent, as `steps` writes it, and the closed form's
    alpha to its last digit shown (phi = asin(sin t / n), differentiated twice at 50 digits)."""
    import re
    from pathlib import Path
    from polygon_method.scene import load_scene
    from polygon_method.text.report import solution_text

    sc = load_scene(
        Path(__file__).resolve().parent.parent / "worked_problems" / "engine_flywheel.toml"
    )
    row = next(line for line in solution_text(solve(sc)).splitlines() if line.startswith("AB "))
    mpmath.mp.dps = 50
    R, L, w = mpmath.mpf("0.06"), mpmath.mpf("0.24"), 2 * mpmath.pi * 50

    def phi(t):
        return mpmath.asin(R * mpmath.sin(t) / L)

    alpha = float(abs(mpmath.diff(phi, mpmath.radians(390), 2) * w * w))
    shown = re.search(r"([0-9.e+]+) rad/s\^2", row).group(1)
    assert "e" not in row and abs(float(shown) - alpha) <= 0.5, (row, alpha)
