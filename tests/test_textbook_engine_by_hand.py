"""The engine problems of tests/textbook (the engine chapter: piston effort, inertia torque,
the flywheel from an indicator diagram) against the book's hand working done independently
here at 30 digits: the piston's motion from x = r cos t + sqrt(l^2 - r^2 sin^2 t) (mpmath's
derivatives), the forces by the book's formulas (F_N = F_P tan phi, F_Q = F_P / cos phi,
F_T = F_Q sin(t + phi)), the inertia torque by virtual power, the turning moment's mean,
its crossings and the fluctuation of energy by quadrature and root finding. To 1e-9."""

from pathlib import Path

import mpmath
import pytest
from mpmath import mpf

from polygon_method import load_scene, solve
from polygon_method.forces.engine import efforts
from polygon_method.linkage import turning_moment

HERE = Path(__file__).resolve().parent / "textbook"
REL = 1e-9


@pytest.fixture(autouse=True)
def _precision():
    """Each test sets mpmath's precision; the others' is restored after it."""
    old = mpmath.mp.dps
    yield
    mpmath.mp.dps = old


def close(got, want, rel=REL):
    assert abs(got - float(want)) <= rel * abs(float(want)), (got, float(want))


def _x(r, l, t):  # the piston's distance from the crank shaft, crank t from the i.d.c.
    return r * mpmath.cos(t) + mpmath.sqrt(l**2 - (r * mpmath.sin(t)) ** 2)


def test_piston_effort_thrusts_crank_effort_by_the_books_formulas():
    """engine_piston_effort.toml: r = 300 mm, l = 1.5 m, 250 kg reciprocating, 180 rpm,
    0.5 N/mm^2 on a 400 mm bore, 30 deg from the i.d.c. (ccw)."""
    mpmath.mp.dps = 30
    r, l, m = mpf("0.3"), mpf("1.5"), mpf(250)
    w, t = 180 * 2 * mpmath.pi / 60, mpmath.radians(30)
    a_piston = mpmath.diff(lambda u: _x(r, l, u), t, 2) * w**2  # +: away from the crank
    F_L = mpf("0.5e6") * mpmath.pi / 4 * mpf("0.4") ** 2  # towards the crank
    F_P = F_L + m * a_piston  # the inertia force -m a, towards the crank
    phi = mpmath.asin(r * mpmath.sin(t) / l)
    sc = load_scene(HERE / "engine_piston_effort.toml")
    sol = solve(sc)
    e = efforts(sc, sol.plan, sol.P, sol.forces)
    close(e.F_P, F_P)
    close(e.F_N, F_P * mpmath.tan(phi))
    close(e.F_Q, F_P / mpmath.cos(phi))
    close(e.F_T, F_P / mpmath.cos(phi) * mpmath.sin(t + phi))
    close(e.T, F_P / mpmath.cos(phi) * mpmath.sin(t + phi) * r)


def test_inertia_torque_with_the_rods_mass_by_virtual_power():
    """engine_rod_inertia.toml: r = 200, l = 800 mm; rod 60 kg, G 300 mm from the crank pin,
    k = 280 mm; 100 kg reciprocating; 300 rpm cw, 40 deg from the i.d.c. The driver's torque
    T balances the inertia forces' power: T w = sum m a_G . v_G + I alpha w_rod."""
    mpmath.mp.dps = 30
    r, l, ag = mpf("0.2"), mpf("0.8"), mpf("0.3")
    w, t0 = -300 * 2 * mpmath.pi / 60, mpmath.radians(-40)  # cw: the i.d.c. at 0 deg

    def place(k, s):  # coordinate k of: A (0, 1), B (2, 3), G (4, 5), the rod's angle (6)
        t = t0 + w * s
        A = (r * mpmath.cos(t), r * mpmath.sin(t))
        B = (_x(r, l, t), mpf(0))
        G = tuple(A[i] + ag / l * (B[i] - A[i]) for i in range(2))
        return (A + B + G + (mpmath.atan2(B[1] - A[1], B[0] - A[0]),))[k]

    d = [
        (mpmath.diff(lambda s: place(k, s), 0, 1), mpmath.diff(lambda s: place(k, s), 0, 2))
        for k in range(7)
    ]
    power = (
        60 * sum(d[k][0] * d[k][1] for k in (4, 5))
        + 100 * d[2][0] * d[2][1]
        + 60 * mpf("0.28") ** 2 * d[6][0] * d[6][1]
    )
    sol = solve(load_scene(HERE / "engine_rod_inertia.toml"))
    close(sol.forces.input_torque, power / w)


def test_flywheel_from_the_indicator_diagram_by_quadrature():
    """engine_indicator_flywheel.toml: r = 60, l = 240 mm, 100 mm bore, a two-stroke
    indicator table (bar against crank angle, linear between readings), 600 rpm, the
    speed within +-1.5 %, a rim of 200 mm radius."""
    mpmath.mp.dps = 30
    r, l, area = mpf("0.06"), mpf("0.24"), mpmath.pi / 4 * mpf("0.1") ** 2
    angles, bar = [0, 20, 60, 120, 180, 240, 300, 360], [30, 35, 18, 6, 1, 2, 8, 30]

    def p(t):
        d = mpmath.degrees(t)
        k = max(i for i in range(len(angles) - 1) if angles[i] <= d or i == 0)
        return (
            bar[k] + (bar[k + 1] - bar[k]) * (d - angles[k]) / (angles[k + 1] - angles[k])
        ) * mpf(100000)

    def T(t):  # the gas force towards the crank times the piston's lever: -F dx/dt
        return -p(t) * area * mpmath.diff(lambda u: _x(r, l, u), t)

    nodes = [mpmath.radians(a) for a in angles]
    work = sum(mpmath.quad(T, [nodes[i], nodes[i + 1]]) for i in range(len(nodes) - 1))
    mean = work / (2 * mpmath.pi)
    tm = turning_moment(load_scene(HERE / "engine_indicator_flywheel.toml"))
    close(tm.mean, mean)
    assert len(tm.crossings) == 2
    roots = [mpmath.findroot(lambda t: T(t) - mean, mpmath.radians(c)) for c in tm.crossings]
    for got, want in zip(tm.crossings, roots):
        assert abs(mpmath.radians(got) - want) <= 1e-9

    def E(t):  # the energy above the mean from 0 to t
        cuts = [n for n in nodes if n < t] + [t]
        return sum(
            mpmath.quad(lambda u: T(u) - mean, [cuts[i], cuts[i + 1]]) for i in range(len(cuts) - 1)
        )

    dE = abs(E(roots[1]) - E(roots[0]))
    close(tm.dE_max, dE)
    w = 600 * 2 * mpmath.pi / 60
    cs, _, inertia, mass = tm.flywheel
    close(cs, mpf("0.03"), 1e-15)
    close(inertia, dE / (w**2 * mpf("0.03")))
    close(mass, dE / (w**2 * mpf("0.03")) / mpf("0.2") ** 2)


def test_vertical_engine_weight_adds_to_the_piston_effort():
    """vertical_engine_weight_gas.toml: r = 100, l = 450 mm, the piston above the crank,
    20 kg reciprocating, 1.2 MPa on a 120 mm bore, 1000 rpm ccw, 40 deg past the t.d.c.:
    F_P = F_L + m a + m g towards the crank (a the piston's acceleration away from the
    crank: its inertia force -m a points towards the crank by m a; its weight pushes it
    towards the crank), the crank effort F_P sin(t + phi) / cos phi."""
    mpmath.mp.dps = 30
    r, l, m, g = mpf("0.1"), mpf("0.45"), mpf(20), mpf("9.81")
    w, t = 1000 * 2 * mpmath.pi / 60, mpmath.radians(40)
    a_away = mpmath.diff(lambda u: _x(r, l, u), t, 2) * w**2
    F_P = mpf("1.2e6") * mpmath.pi / 4 * mpf("0.12") ** 2 + m * a_away + m * g
    phi = mpmath.asin(r * mpmath.sin(t) / l)
    sc = load_scene(HERE / "vertical_engine_weight_gas.toml")
    sol = solve(sc)
    e = efforts(sc, sol.plan, sol.P, sol.forces)
    close(e.F_P, F_P)
    close(e.F_N, abs(F_P * mpmath.tan(phi)))
    close(e.F_T, F_P / mpmath.cos(phi) * mpmath.sin(t + phi))
    close(e.T, F_P / mpmath.cos(phi) * mpmath.sin(t + phi) * r)
