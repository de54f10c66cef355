"""A turning-moment diagram stated on its own ([turning_moment], [press], [flywheel]):
against the closed forms worked by hand (a sinusoid's exact dE_max, the areas' running
sums, the press's share), and against mpmath at 30 digits (the crossings by its root
finder on the law written out again here, the energies by its quadrature), to 1e-9."""

import math

import mpmath
import pytest
from mpmath import mp, mpf

from polygon_method.forces.flywheel_cycle import curves, solve_cycle
from polygon_method.scene.energy import cycle_from_text

REL = 1e-9


def _solve(text):
    scene = cycle_from_text(text, "t.toml")
    return scene, solve_cycle(scene)


def _close(got, want, scale=None):
    scale = abs(want) if scale is None else scale
    assert abs(float(got) - float(want)) <= REL * max(scale, 1e-300), (got, want)


# -- closed forms by hand


def test_a_sinusoid_about_its_mean_swings_by_its_amplitude():
    """T - T_mean = 300 sin 2t - 500 cos 2t = A sin(2t - phi), A = sqrt(300^2 + 500^2):
    the energy swings by A between the crossings 2t = phi + k pi (int_0^{pi/2} A sin 2u du
    = A)."""
    _, c = _solve(
        '[turning_moment]\ntorque = "1000 + 300 sin 2theta - 500 cos 2theta"\n'
        '[flywheel]\nspeed = "300 rpm"\nplus_minus = "1.5%"\nradius = "0.5 m"\n'
    )
    A = math.hypot(300, 500)
    phi = math.atan2(500, 300)
    _close(c.T_mean, 1000)
    _close(c.work, 2000 * math.pi)
    _close(c.dE_max, A)
    want = [(phi + k * math.pi) / 2 for k in range(4)]
    for x, w in zip(c.crossings, want):
        _close(x.angle, w, 1.0)
    w = 300 * math.pi / 30
    _close(c.inertia, A / (w * w * 0.03))
    _close(c.mass, A / (w * w * 0.03) / 0.25)
    _close(c.power, 1000 * w)
    _close(c.speed_max, w * 1.015)
    _close(c.speed_min, w * 0.985)


def test_the_areas_running_sums_are_the_energies_at_the_crossings():
    """+52 -124 +92 -140 +85 -72 +107 mm^2, 1 mm = 600 N m, 1 mm = 3 deg: running sums
    0, 52, -72, 20, -120, -35, -107, 0; dE_max = 52 + 120 = 172 mm^2 of 600 x 3 pi/180 J."""
    _, c = _solve(
        "[turning_moment]\nareas = [52, -124, 92, -140, 85, -72, 107]\n"
        'torque_scale = "1 mm = 600 N m"\nangle_scale = "1 mm = 3 deg"\n'
        '[flywheel]\nspeed = "600 rpm"\nplus_minus = "1.5%"\nradius = "0.5 m"\n'
    )
    per = 600 * 3 * math.pi / 180
    assert [round(x.energy / per, 9) for x in c.crossings] == [0, 52, -72, 20, -120, -35, -107, 0]
    assert (c.crossings[c.i_max].letter, c.crossings[c.i_min].letter) == ("b", "e")
    _close(c.dE_max, 172 * per)
    w = 20 * math.pi
    _close(c.mass, 172 * per / (w * w * 0.03 * 0.25))


def test_a_scale_in_cm_and_areas_in_cm2():
    """1 cm = 15 kN m, 1 cm = 150 deg... an area of 1 cm^2 is 15000 x 150 pi / 180 J."""
    _, c = _solve(
        '[turning_moment]\nareas = [0.5, -1.5, 1.0]\narea_unit = "cm^2"\n'
        'torque_scale = "1 cm = 15 kN m"\nangle_scale = "1 cm = 150 deg"\n'
    )
    _close(c.dE_max, 1.5 * 15000 * 150 * math.pi / 180)


def test_a_press_gives_the_energy_less_the_motors_share_while_it_punches():
    """Holes of 40 mm in plate 30 mm thick, ultimate shear 300 MPa: F = tau pi d t, E = F t
    / 2; 8 holes a minute, the punching a tenth of the cycle: dE = E (1 - 0.1); the motor
    E / 7.5 s; the flywheel between 180 and 160 rpm, rim radius 0.8 m."""
    _, c = _solve(
        '[press]\ndiameter = 40\nthickness = 30\nshear_strength = "300 MPa"\n'
        'holes_per_minute = 8\npunching_fraction = "1/10"\n'
        '[flywheel]\nmax_speed = "180 rpm"\nmin_speed = "160 rpm"\nradius = 800\n'
        "width_to_thickness = 2\n"
    )
    F = 300e6 * math.pi * 0.04 * 0.03
    E = F * 0.03 / 2
    _close(c.E_stroke, E)
    _close(c.dE_max, 0.9 * E)
    _close(c.power, E / 7.5)
    w1, w2 = 180 * math.pi / 30, 160 * math.pi / 30
    I = 0.9 * E / ((w1 * w1 - w2 * w2) / 2)  # dE = I (w1^2 - w2^2) / 2 = I w Cs w
    _close(c.inertia, I)
    m = I / 0.64
    _close(c.mass, m)
    A = m / (2 * math.pi * 0.8 * 7200)
    _close(c.rim_thickness, math.sqrt(A / 2))
    _close(c.rim_width, 2 * math.sqrt(A / 2))


def test_the_flywheel_given_finds_the_speeds_and_the_acceleration():
    """I = m k^2 given: Cs = dE / (I w^2); the angular acceleration (T - T_mean) / I."""
    _, c = _solve(
        '[turning_moment]\ntorque = "20000 + 9500 sin 2theta - 5700 cos 2theta"\n'
        'at = "45 deg"\n[flywheel]\nspeed = "300 rpm"\nmass = "1000 kg"\ngyration = 1200\n'
    )
    dE = math.hypot(9500, 5700)
    w = 10 * math.pi
    _close(c.Cs, dE / (1440 * w * w))
    _close(c.alpha_at, (9500 * 1 - 5700 * 0) / 1440)
    _close(c.speed_max - c.speed_min, w * dE / (1440 * w * w))


# -- against mpmath at 30 digits


def _reference(T, R, cycle):
    """(crossings, energies from the first, dE_max) of T - R over [0, cycle] at 30 digits:
    sign changes on a grid, mpmath's root finder, its quadrature between the roots."""
    q = lambda x: T(x) - R(x)  # noqa: E731
    n = 4000
    shift = mpf("0.0123")  # a grid off the round angles: a crossing at 0 is inside a step
    xs = [shift + cycle * mpf(i) / n for i in range(n + 1)]
    roots = []
    for a, b in zip(xs, xs[1:]):
        if q(a) * q(b) < 0:
            r = mp.findroot(q, (a, b), solver="anderson")
            r = r - cycle if r >= cycle else r
            roots.append(mpf(0) if abs(r - cycle) < mpf(10) ** -25 else r)  # 2 pi is 0
    roots.sort()
    es = [mpf(0)]
    for a, b in zip(roots, roots[1:]):
        es.append(es[-1] + mp.quad(q, [a, b]))
    return roots, es, max(es) - min(es)


LAWS = [
    (
        "three cylinders on a resisting law",
        '[turning_moment]\ntorque = "25 - 7.5 sin 3theta"\nunit = "kN m"\n'
        'resisting = "25 + 3.6 sin theta"\n',
        lambda x: 25000 - 7500 * mpmath.sin(3 * x),
        lambda x: 25000 + 3600 * mpmath.sin(x),
        2,
    ),
    (
        "phases and a half order over a four-stroke cycle",
        '[turning_moment]\ntorque = ["4000 + 2000 sin(theta - 30 deg)", '
        '"1500 cos(2theta + 45 deg) - 900 sin(theta/2)"]\ncycle = "4-stroke"\n',
        lambda x: (
            4000
            + 2000 * mpmath.sin(x - mpmath.pi / 6)
            + 1500 * mpmath.cos(2 * x + mpmath.pi / 4)
            - 900 * mpmath.sin(x / 2)
        ),
        None,
        4,
    ),
    (
        "a motor's constant torque driving a machine's law",
        '[turning_moment]\ntorque = "constant"\nresisting = "800 + 350 sin theta + 120 cos 3theta"\n',
        None,
        lambda x: 800 + 350 * mpmath.sin(x) + 120 * mpmath.cos(3 * x),
        2,
    ),
]


@pytest.mark.parametrize("name,text,T,R,turns", LAWS, ids=[x[0] for x in LAWS])
def test_a_law_against_mpmath(name, text, T, R, turns):
    """The cycle is ``turns`` pi; 30 digits in a context of its own (the other tests' precision
    is theirs)."""
    with mp.workdps(30):
        _law_against_mpmath(text, T, R, turns * mp.pi)


def _law_against_mpmath(text, T, R, cycle):
    if T is None:
        mean = mp.quad(R, [0, cycle]) / cycle
        T = lambda x: mean  # noqa: E731
    if R is None:
        mean = mp.quad(T, [0, cycle]) / cycle
        R = lambda x: mean  # noqa: E731
    _, c = _solve(text)
    roots, es, dE = _reference(T, R, cycle)
    assert len(c.crossings) - 1 == len(roots)
    for x, r, e in zip(c.crossings, roots, es):
        _close(x.angle, r, 1.0)
        _close(x.energy, e, float(dE))
    _close(c.dE_max, dE)
    _close(c.T_mean, mp.quad(T, [0, cycle]) / cycle)


def test_straight_segments_against_mpmath():
    """A triangle a stroke (a four-stroke engine's diagram drawn as triangles), with a jump:
    mpmath integrates the same readings as a function, piece by piece."""
    ang = [0, 90, 180, 270, 360, 450, 540, 540, 630, 720]
    tq = [0, -800, 0, -2600, 0, 18000, 0, 300, -900, 0]
    text = f'[turning_moment]\nangle = {ang}\ntorque = {tq}\ncycle = "4-stroke"\n'
    _, c = _solve(text)
    with mp.workdps(30):
        _segments_against_mpmath(c, ang, tq)


def _segments_against_mpmath(c, ang, tq):
    A = [mpmath.radians(a) for a in ang]

    def T(x):
        for i in range(len(A) - 1):
            if A[i] <= x <= A[i + 1] and A[i + 1] > A[i]:
                return tq[i] + (tq[i + 1] - tq[i]) * (x - A[i]) / (A[i + 1] - A[i])
        return mpf(0)

    pieces = sorted(set(A))
    mean = sum(mp.quad(T, [a, b]) for a, b in zip(pieces, pieces[1:])) / (4 * mpmath.pi)
    _close(c.T_mean, mean)
    R = lambda x: mean  # noqa: E731
    q = lambda x: T(x) - R(x)  # noqa: E731
    roots = []
    xs = [4 * mpmath.pi * mpf(i) / 2880 for i in range(2881)]
    for a, b in zip(xs, xs[1:]):
        if q(a) * q(b) < 0:
            roots.append(mp.findroot(q, (a, b), solver="bisect"))
    assert len(roots) == len(c.crossings) - 1
    for x, r in zip(c.crossings, roots):
        _close(x.angle, r, 1.0)
    es = [mpf(0)]
    for a, b in zip(roots, roots[1:]):
        cut = sorted({a, b} | {p for p in pieces if a < p < b})
        es.append(es[-1] + sum(mp.quad(q, [u, v]) for u, v in zip(cut, cut[1:])))
    _close(c.dE_max, max(es) - min(es))


def test_the_csv_curves_hold_the_law_and_its_integral():
    scene, c = _solve('[turning_moment]\ntorque = "1000 + 300 sin 2theta - 500 cos 2theta"\n')
    th, tq, rs, es = curves(scene, c, 73)
    a = c.crossings[0].angle
    for x, t, e in zip(th, tq, es):
        _close(t, 1000 + 300 * math.sin(2 * x) - 500 * math.cos(2 * x), 1000)
        exact = (-150 * math.cos(2 * x) - 250 * math.sin(2 * x)) - (
            -150 * math.cos(2 * a) - 250 * math.sin(2 * a)
        )
        _close(e, exact, 600)
    assert all(abs(r - 1000) <= 1e-9 * 1000 for r in rs)


def test_a_crossing_at_the_cycles_start_where_only_its_end_rounds_to_nought():
    """T = 5500 + 1600 sin 3theta crosses its mean at k x 60 deg, six times a turn (0 deg
    among them: there the law's value rounds to the mean only at 360 deg); the energies
    alternate between E and E - 2 x 1600 / 3 (int_0^{pi/3} 1600 sin 3t dt = 3200 / 3)."""
    _, c = _solve('[turning_moment]\ntorque = "5500 + 1600 sin 3theta"\n')
    got = c.crossings[:-1]
    assert len(got) == 6
    first = round(math.degrees(got[0].angle) / 60)
    for i, x in enumerate(got):
        _close(x.angle % (2 * math.pi), math.radians(60 * ((first + i) % 6)), 1.0)
    assert sorted({round(abs(a), 6) for a in c.areas}) == [round(3200 / 3, 6)]
    _close(c.dE_max, 3200 / 3)


@pytest.mark.parametrize(
    "angle,torque",
    [
        ([0, 180, 180, 360], [1500, 1500, 500, 500]),  # the jump back at the cycle's end
        ([0, 90, 180, 180, 360], [1500, 1500, 1500, 500, 500]),
        ([0, 0, 180, 180, 360], [500, 1500, 1500, 500, 500]),  # a jump at 0 stated too
    ],
)
def test_a_jump_across_the_cycles_end_is_a_crossing(angle, torque):
    """A torque of 1500 N m for half a turn and 500 N m for the other half, its mean 1000:
    the energy rises by 500 pi J over the first half and falls back over the second. The
    crossing at 0 deg (the segments end below the mean and start above it) had been missed
    (no reading there is nought), leaving one crossing and dE_max = 0."""
    _, c = _solve(
        f"[turning_moment]\nangle = {angle}\ntorque = {torque}\n"
        '[flywheel]\nspeed = "300 rpm"\nplus_minus = "1%"\n'
    )
    assert c.T_mean == pytest.approx(1000, rel=1e-12)
    assert c.dE_max == pytest.approx(500 * math.pi, rel=1e-12)
    angles = sorted(round(math.degrees(x.angle), 9) % 360 for x in c.crossings)
    assert angles[:3] == [0, 0, 180]  # a at 0 (and again a cycle on), b at 180
    assert math.degrees(c.crossings[c.i_max].angle) % 360 == pytest.approx(180)


def _exact_dE(ang, tq):
    """dE_max of straight segments by hand, in fractions: the energy at every corner and at
    every crossing of the mean within a segment (a parabola's value there), greatest less
    least (J, the angles in degrees)."""
    from fractions import Fraction as Fr

    a, t = [Fr(x) for x in ang], [Fr(x) for x in tq]
    mean = sum((t[i] + t[i + 1]) / 2 * (a[i + 1] - a[i]) for i in range(len(a) - 1)) / a[-1]
    E, seen = Fr(0), [Fr(0)]
    for i in range(len(a) - 1):
        L = a[i + 1] - a[i]
        if L == 0:
            continue
        q0, q1 = t[i] - mean, t[i + 1] - mean
        if q0 * q1 < 0:
            x = -q0 / (q1 - q0) * L
            seen.append(E + q0 * x + (q1 - q0) / L * x * x / 2)
        E += (q0 + q1) / 2 * L
        seen.append(E)
    return float(max(seen) - min(seen)) * math.pi / 180


def _tables(n, seed=7):
    import random

    rnd = random.Random(seed)
    out = []
    while len(out) < n:
        ang = [0] + sorted(rnd.choice([0, 30, 45, 90, 120, 180, 270, 360]) for _ in range(5))
        ang = [x for i, x in enumerate(ang + [360]) if (ang + [360])[: i + 1].count(x) <= 2]
        tq = [rnd.choice([500, 1000, 1500, 2000, rnd.randint(0, 3000)]) for _ in ang]
        if len(set(tq)) > 1:
            out.append((ang, tq))
    return out


CASES = [
    ([0, 30, 30, 270, 360], [2000, 1500, 1500, 500, 1000]),  # ends on the mean, jumps up
    ([0, 0, 45, 45, 90, 360, 360], [776, 500, 2000, 2000, 1500, 1500, 500]),
    ([0, 90, 180, 270, 360], [2000, 1000, 1000, 0, 1000]),  # a segment along the mean
    ([0, 90, 90, 270, 270, 360], [1500, 1500, 1000, 1000, 500, 500]),  # jumps onto it
]


@pytest.mark.parametrize("ang,tq", CASES + _tables(60), ids=lambda v: str(v))
def test_segments_dE_max_against_the_energy_at_every_corner_by_hand(ang, tq):
    """Segments that end on the mean line and jump off it, run along it or jump onto it: a
    run of noughts is a crossing where the sign changes across it (two such tables had
    given dE_max = 0: the crossing at the cycle's start was missed where the mean's
    rounding left the last reading a hair off nought)."""
    _, c = _solve(
        f"[turning_moment]\nangle = {ang}\ntorque = {tq}\n"
        '[flywheel]\nspeed = "300 rpm"\nplus_minus = "1%"\n'
    )
    want = _exact_dE(ang, tq)
    assert want > 0
    _close(c.dE_max, want)


@pytest.mark.parametrize("thickness,stroke", [(32, 100), (10, 150), (45, 50)])
def test_a_punchs_stroke_sets_the_punching_time(thickness, stroke):
    """ "The punch has a stroke of 100 mm": the punching takes t / (2 s) of the cycle (the
    stroke half a turn of the crank), so dE_max = E (1 - t / 2 s); the rim's mass from its
    speed, dE_max / (v^2 Cs), whatever the flywheel's speed (by hand)."""
    e = 7 * math.pi * 38 * thickness  # J: 7 N m per mm^2 of the sheared area pi d t
    for rpm in (150, 300):
        _, c = _solve(
            f"[press]\ndiameter = 38\nthickness = {thickness}\n"
            f'energy_per_area = "7 J/mm^2"\ntime = "10 s"\nstroke = {stroke}\n'
            f'[flywheel]\nspeed = "{rpm} rpm"\nrim_speed = "25 m/s"\ncoefficient = 0.03\n'
        )
        dE = e * (1 - thickness / (2 * stroke))
        _close(c.dE_max, dE)
        _close(c.mass, dE / (25**2 * 0.03))


def test_a_punchs_stroke_needs_the_plates_thickness_and_is_one_way_of_timing():
    from polygon_method.common.errors import SceneError

    for press, word in (
        ('energy = "6 kJ"\ntime = "10 s"\nstroke = 100\n', "thickness"),
        (
            'energy = "6 kJ"\nthickness = 20\ntime = "10 s"\nstroke = 100\npunching_angle = 30\n',
            "one of them",
        ),
    ):
        with pytest.raises(SceneError, match=word):
            _solve(f'[press]\n{press}[flywheel]\nspeed = "150 rpm"\ncoefficient = 0.03\n')
