"""Twenty problems stated by a newcomer from the docs alone, in the words of other books than
the corpus's first ones (Ambekar, Bevan, Ballaney, Bansal & Brar, Jagdish Lal, Shigley &
Uicker, Mabie & Reinholtz, Mabie & Ocvirk, Martin, Wilson & Sadler, Erdman & Sandor): "angle
BAD = 60 deg", "the crank makes 45 deg with the line of stroke", "the crank makes 120 deg
with the line of centres", E "the midpoint" of BC, the second crank's angle from the
vertical, a collar on no link, a weight in newtons for a mass (tests/textbook/*.toml named
after those books).

Each file is compared here with a computation that shares nothing with the solver: the
motion as a function of time, t -> the loop-closure equations solved by Newton at 40 digits
(mpmath.findroot) from the figure's branch, differentiated in t by mpmath.diff (velocities
and accelerations at t = 0); or a closed form (the peg, the collar, the wheel, the gear
train, the cylinder, the engine's efforts); the torques by virtual power with those
kinematics. Every answer to 1e-9 relative; each file's [answers] (rounded as a book prints)
within its tolerance; the quick-return ratios of `linkage` against the dead-centre angles by
hand; the one statement the tool refuses (an `offset` key) refused in one line saying how.
"""

from __future__ import annotations

import math
from pathlib import Path

import mpmath
import pytest
from mpmath import mpf

from polygon_method import load_scene, parse_scene, solve
from polygon_method.check import check_answers
from polygon_method.common.errors import SceneError

HERE = Path(__file__).resolve().parent / "textbook"
REL = 1e-9
pi = mpmath.pi


@pytest.fixture(autouse=True)
def _digits():
    old = mpmath.mp.dps
    mpmath.mp.dps = 40
    yield
    mpmath.mp.dps = old


def _sol(name):
    return solve(load_scene(HERE / f"{name}.toml"))


def _close(got, want, scale=None):
    """|got - want| <= REL x max(|want|, scale): got a float or a pair, want mpf(s)."""
    if isinstance(want, (tuple, list)):
        d = math.hypot(float(got[0] - want[0]), float(got[1] - want[1]))
        size = float(mpmath.sqrt(want[0] ** 2 + want[1] ** 2))
    else:
        d, size = abs(float(got - want)), abs(float(want))
    assert d <= REL * max(size, scale or 0.0, 1e-300), (got, want)


def _cis(a):
    return mpmath.cos(a), mpmath.sin(a)


def _ang(p, q):
    """The direction p -> q of two solved points (a starting guess for Newton only)."""
    return mpf(math.atan2(q[1] - p[1], q[0] - p[0]))


def _motion(points_at):
    """(positions, velocities, accelerations) of ``points_at(t)`` (a dict of mp pairs) at
    t = 0, by differentiating in time at 40 digits."""
    P = points_at(mpf(0))
    out_v, out_a = {}, {}
    for k in P:
        comp = [lambda t, k=k, i=i: points_at(t)[k][i] for i in (0, 1)]
        out_v[k] = tuple(_rate(c, 1) for c in comp)
        out_a[k] = tuple(_rate(c, 2) for c in comp)
    return P, out_v, out_a


def _newton(residual, guess):
    """The root of ``residual(*q)`` nearest the figure's ``guess`` (Newton at 40 digits)."""
    q = mpmath.findroot(residual, guess, tol=mpf(10) ** -76)
    return list(q) if hasattr(q, "rows") else [q]


def _check_kinematics(sol, P, V, A):
    vs = max(float(mpmath.sqrt(v[0] ** 2 + v[1] ** 2)) for v in V.values())
    as_ = max(float(mpmath.sqrt(a[0] ** 2 + a[1] ** 2)) for a in A.values())
    for k in P:
        _close(sol.V[k], V[k], vs)
        _close(sol.A[k], A[k], as_)


def _fourbar(A, D, ab, bc, cd, theta, sol, B="B", C="C"):
    """Points of a four-bar with the crank at ``theta(t)``, C on the figure's branch."""
    g3, g4 = _ang(sol.P[B], sol.P[C]), _ang(D, sol.P[C])
    cache = {}

    def at(t):
        if t not in cache:
            th = theta(t)
            Bp = (A[0] + ab * mpmath.cos(th), A[1] + ab * mpmath.sin(th))

            def res(t3, t4):
                return (
                    Bp[0] + bc * mpmath.cos(t3) - D[0] - cd * mpmath.cos(t4),
                    Bp[1] + bc * mpmath.sin(t3) - D[1] - cd * mpmath.sin(t4),
                )

            t3, t4 = _newton(res, [g3, g4])
            cache[t] = Bp, (D[0] + cd * mpmath.cos(t4), D[1] + cd * mpmath.sin(t4)), t3, t4
        return cache[t]

    return at


def _rate(f, n):
    """The n-th derivative at t = 0 by central differences of step 1e-10 (Newton's roots
    are good to 1e-38: the rounding 1e-18 at worst, the truncation h^2 = 1e-20)."""
    return mpmath.diff(f, 0, n, h=mpf("1e-10"))


# -- the answers each file gives, as a book prints them


#: the twenty files (and one more), each with its [answers] as a book prints them
NEWCOMER = [
    "ambekar_fourbar_angle_bad_midpoint",
    "bansal_fourbar_pin_speed_retarding",
    "jagdish_lal_offset_slider_line_of_stroke",
    "jagdish_lal_slider_crank_centres",
    "bansal_whitworth_line_of_centres",
    "ballaney_slotted_lever_shaper",
    "hamilton_mabie_drag_link_quick_return",
    "bevan_toggle_crusher",
    "mabie_dump_body_cylinder",
    "erdman_five_bar_two_cranks_words",
    "hamilton_mabie_wheel_rod_slider",
    "wilson_sadler_compound_gear_train",
    "mabie_pin_rotating_and_fixed_slot",
    "martin_collar_on_turning_rod",
    "force_static_shigley_fourbar_coupler_load",
    "force_static_mabie_slider_crank_inches",
    "force_wilson_sadler_slider_crank_inertia",
    "force_bansal_steam_engine_efforts",
    "force_jagdish_lal_vertical_engine_weight",
    "force_static_ballaney_toggle_press",
    "ballaney_shaper_lever_in_ram_slot",
]


def test_the_files_each_solved_by_a_test_here():
    assert len(set(NEWCOMER)) == 21 and all((HERE / f"{n}.toml").exists() for n in NEWCOMER)
    rest = Path(__file__).read_text(encoding="utf-8").split("def test_the_files_answers")[-1]
    assert all(n in rest for n in NEWCOMER), [n for n in NEWCOMER if n not in rest]


@pytest.mark.parametrize("name", NEWCOMER)
def test_the_files_answers_hold_within_their_tolerance(name):
    sc = load_scene(HERE / f"{name}.toml")
    assert sc.answers and sc.tolerance is not None
    verdicts = check_answers(solve(sc))
    assert verdicts and all(v.ok for v in verdicts), [
        (v.key, v.given, v.correct) for v in verdicts if not v.ok
    ]


def test_ambekar_fourbar_angle_bad_and_midpoint():
    sol = _sol("ambekar_fourbar_angle_bad_midpoint")
    w = -2 * pi * 120 / 60
    at = _fourbar(
        (0, 0),
        (mpf("0.15"), 0),
        mpf("0.04"),
        mpf("0.15"),
        mpf("0.08"),
        lambda t: -pi / 3 + w * t,
        sol,
    )

    def pts(t):
        B, C, _, _ = at(t)
        return {"B": B, "C": C, "E": ((B[0] + C[0]) / 2, (B[1] + C[1]) / 2)}

    P, V, A = _motion(pts)
    assert sol.P["E"] == pytest.approx((float(P["E"][0]), float(P["E"][1])), abs=1e-15)
    _check_kinematics(sol, P, V, A)
    _close(sol.W["BC"], _rate(lambda t: at(t)[2], 1))
    _close(sol.W["CD"], _rate(lambda t: at(t)[3], 1))


def test_bansal_fourbar_pin_speed_retardation_and_e_produced():
    sol = _sol("bansal_fourbar_pin_speed_retarding")
    w, al = mpf(-24), mpf(20)  # 2.4 m/s over 0.1 m, cw; the retardation against it: ccw
    at = _fourbar(
        (0, 0),
        (mpf("0.3"), 0),
        mpf("0.1"),
        mpf("0.35"),
        mpf("0.2"),
        lambda t: pi / 4 + w * t + al * t * t / 2,
        sol,
    )

    def pts(t):
        B, C, _, _ = at(t)
        D = (mpf("0.3"), 0)
        return {"B": B, "C": C, "E": (D[0] + 1.5 * (C[0] - D[0]), D[1] + 1.5 * (C[1] - D[1]))}

    P, V, A = _motion(pts)
    _check_kinematics(sol, P, V, A)
    _close(sol.Al["BC"], _rate(lambda t: at(t)[2], 2))
    _close(sol.Al["CD"], _rate(lambda t: at(t)[3], 2))


def _slider_crank(r, l, e, theta, sol, A="A", B="B"):
    """A slider crank, O at the origin, the path y = e: the rod's angle and B's x."""
    phi0, x0 = _ang(sol.P[A], sol.P[B]), mpf(sol.P[B][0])
    cache = {}

    def at(t):
        if t not in cache:
            Ap = (r * mpmath.cos(theta(t)), r * mpmath.sin(theta(t)))

            def res(phi, x):
                return Ap[0] + l * mpmath.cos(phi) - x, Ap[1] + l * mpmath.sin(phi) - e

            phi, x = _newton(res, [phi0, x0])
            cache[t] = Ap, (x, e), phi
        return cache[t]

    return at


def test_jagdish_lal_offset_slider_crank_with_the_line_of_stroke():
    sol = _sol("jagdish_lal_offset_slider_line_of_stroke")
    w = -2 * pi * 300 / 60
    at = _slider_crank(mpf("0.1"), mpf("0.4"), mpf("-0.04"), lambda t: -pi / 4 + w * t, sol)
    P, V, A = _motion(lambda t: {"A": at(t)[0], "B": at(t)[1]})
    _check_kinematics(sol, P, V, A)
    _close(sol.W["AB"], _rate(lambda t: at(t)[2], 1))
    _close(sol.Al["AB"], _rate(lambda t: at(t)[2], 2))


def test_jagdish_lal_slider_crank_centres():
    sol = _sol("jagdish_lal_slider_crank_centres")
    w = -2 * pi * 300 / 60
    at = _slider_crank(mpf("0.1"), mpf("0.4"), 0, lambda t: -pi / 4 + w * t, sol)

    def pts(t):
        A, B, _ = at(t)
        return {"A": A, "B": B, "E": ((A[0] + B[0]) / 2, (A[1] + B[1]) / 2)}

    P, V, A = _motion(pts)
    _check_kinematics(sol, P, V, A)
    xB = P["B"][0]
    want = (xB, xB * mpmath.tan(-pi / 4))  # OA produced meets the normal at B
    from polygon_method.solver.centres import locate

    centres = locate(sol)
    I13 = centres.centres[(1, 3)].point
    _close(I13, want)
    # v_B = omega_AB x |B I13|, the rod turning about I13 (omega by the ratio theorem)
    _close(abs(centres.omegas[3]) * math.dist(sol.P["B"], I13), abs(V["B"][0]))


def _lever(O, Q, r, lever, rod, y_stroke, theta, sol):
    """A crank O-P (P a block on the lever through Q), the lever's end R at ``lever`` from
    Q, the rod R-S to S on the line y = y_stroke: (P, R, S, lever angle, rod angle)."""
    g = [_ang(Q, sol.P["R"]), _ang(sol.P["R"], sol.P["S"]), mpf(sol.P["S"][0])]
    cache = {}

    def at(t):
        if t not in cache:
            Pp = (O[0] + r * mpmath.cos(theta(t)), O[1] + r * mpmath.sin(theta(t)))

            def res(psi, phi, x):
                c, s = _cis(psi)
                R = (Q[0] + lever * c, Q[1] + lever * s)
                return (
                    (Pp[0] - Q[0]) * s - (Pp[1] - Q[1]) * c,  # P on the lever's line
                    R[0] + rod * mpmath.cos(phi) - x,
                    R[1] + rod * mpmath.sin(phi) - y_stroke,
                )

            psi, phi, x = _newton(res, g)
            R = (Q[0] + lever * mpmath.cos(psi), Q[1] + lever * mpmath.sin(psi))
            cache[t] = Pp, R, (x, mpf(y_stroke)), psi, phi
        return cache[t]

    return at


@pytest.mark.parametrize(
    "name,O,r,lever,rod,y,theta0,rpm",
    [
        ("bansal_whitworth_line_of_centres", (0, "0.05"), "0.075", "0.15", "0.3", 0, -30, 240),
        ("ballaney_slotted_lever_shaper", (0, "0.3"), "0.15", "0.7", "0.2", "0.68", 150, -30),
    ],
)
def test_quick_return_lever_mechanisms(name, O, r, lever, rod, y, theta0, rpm):
    sol = _sol(name)
    w = 2 * pi * rpm / 60
    O = tuple(mpf(c) for c in O)
    at = _lever(
        O,
        (0, 0),
        mpf(r),
        mpf(lever),
        mpf(rod),
        mpf(y),
        lambda t: mpmath.radians(theta0) + w * t,
        sol,
    )
    P, V, A = _motion(lambda t: dict(zip("PRS", at(t)[:3])))
    _check_kinematics(sol, P, V, A)
    _close(sol.W["QR"], _rate(lambda t: at(t)[3], 1))
    _close(sol.Al["QR"], _rate(lambda t: at(t)[3], 2))
    # the Coriolis component 2 omega_lever v_sliding, v_sliding = d|QP|/dt
    QP = lambda t: mpmath.sqrt(at(t)[0][0] ** 2 + at(t)[0][1] ** 2)  # noqa: E731
    _close(math.hypot(*sol.coriolis("P")), 2 * abs(_rate(lambda t: at(t)[3], 1) * _rate(QP, 1)))


@pytest.mark.parametrize(
    "name,ratio,stroke",
    [
        # the return stroke: 180 - 2 asin(50/75) deg of the crank (P on the line through Q)
        ("bansal_whitworth_line_of_centres", None, mpf("0.3")),
        # the lever tangent to the crank circle: the return takes 2 acos(150/300) = 120 deg
        ("ballaney_slotted_lever_shaper", mpf(2), None),
    ],
)
def test_quick_return_ratios_by_hand(name, ratio, stroke):
    from polygon_method.linkage import analyse

    lk = analyse(load_scene(HERE / f"{name}.toml"))
    if ratio is None:
        back = pi - 2 * mpmath.asin(mpf(50) / 75)
        ratio = (2 * pi - back) / back
        assert float(ratio) == pytest.approx(2.7352, abs=1e-4)
    _close(lk.time_ratio, ratio)
    if stroke is not None:
        _close(lk.output_max - lk.output_min, stroke)


def test_hamilton_mabie_drag_link_ram_and_its_time_ratio():
    from polygon_method.linkage import analyse

    sol = _sol("hamilton_mabie_drag_link_quick_return")
    w = 2 * pi
    D = (mpf("0.05"), 0)
    at = _fourbar(
        (0, 0), D, mpf("0.1"), mpf("0.15"), mpf("0.125"), lambda t: mpmath.radians(75) + w * t, sol
    )

    def pts(t):
        B, C, _, t4 = at(t)
        E = (D[0] - mpf("0.1") * mpmath.cos(t4), -mpf("0.1") * mpmath.sin(t4))
        return {"B": B, "C": C, "E": E, "F": (E[0] + mpmath.sqrt(mpf("0.09") - E[1] ** 2), 0)}

    P, V, A = _motion(pts)
    _check_kinematics(sol, P, V, A)

    # the ram's ends: C on the line AD (D, E and F in line), C at x = 175 or -75 mm; the
    # crank angles there on the figure's branch (C above AD just before and after)
    def crank_at(cx):
        C = (mpf(cx), 0)
        d = abs(C[0])
        a = (mpf("0.01") - mpf("0.0225") + d * d) / (2 * d)
        h = mpmath.sqrt(mpf("0.01") - a * a)
        return [mpmath.atan2(s * h, a * mpmath.sign(C[0])) for s in (1, -1)]

    ends = [float(mpmath.degrees(e)) % 360 for e in crank_at("0.175") + crank_at("-0.075")]
    lk = analyse(load_scene(HERE / "hamilton_mabie_drag_link_quick_return.toml"))
    marks = sorted(s.deg for s in lk.stationary)
    assert len(marks) == 2 and all(min(abs(m - e) for e in ends) < 1e-9 for m in marks), marks
    ahead = (marks[1] - marks[0]) % 360  # the working stroke: the longer turn
    _close(lk.time_ratio, mpf(max(ahead, 360 - ahead)) / min(ahead, 360 - ahead))


def test_ballaney_shaper_ram_by_the_levers_angle():
    sol = _sol("ballaney_shaper_lever_in_ram_slot")
    w = -pi

    def lever(t):
        th = mpmath.radians(150) + w * t
        return mpmath.atan2(mpf("0.3") + mpf("0.15") * mpmath.sin(th), mpf("0.15") * mpmath.cos(th))

    def pts(t):
        psi = lever(t)
        R = (mpf("0.7") * mpmath.cos(psi), mpf("0.7") * mpmath.sin(psi))
        return {"R": R, "Y": (R[0], mpf("0.65"))}

    P, V, A = _motion(pts)
    _check_kinematics(sol, P, V, A)
    _close(sol.S["Y"][0], V["Y"][0])
    _close(sol.S["Y"][1], A["Y"][0])
    _close(sol.S["R"][0], V["R"][1])  # the pin's sliding in the vertical slot: R's dy/dt


def test_bevan_toggle():
    sol = _sol("bevan_toggle_crusher")
    w = 2 * pi * 180 / 60
    C = (mpf("0.3"), mpf("0.25"))
    g = [mpf(sol.P["B"][0]), mpf(sol.P["B"][1]), mpf(sol.P["D"][1])]

    def pts(t):
        th = pi / 4 + w * t
        Ap = (mpf("0.06") * mpmath.cos(th), mpf("0.06") * mpmath.sin(th))

        def res(x, y, yd):
            return (
                (x - Ap[0]) ** 2 + (y - Ap[1]) ** 2 - mpf("0.32") ** 2,
                (x - C[0]) ** 2 + (y - C[1]) ** 2 - mpf("0.2") ** 2,
                (x - C[0]) ** 2 + (y - yd) ** 2 - mpf("0.22") ** 2,
            )

        x, y, yd = _newton(res, g)
        return {"A": Ap, "B": (x, y), "D": (C[0], yd)}

    P, V, A = _motion(pts)
    _check_kinematics(sol, P, V, A)


def test_mabie_dump_body_by_the_cosine_rule():
    sol = _sol("mabie_dump_body_cylinder")
    d, b, L, L1 = mpf("0.4") * mpmath.sqrt(10), mpf("1.5"), mpf("1.6"), mpf("0.1")
    phi = mpmath.acos((d * d + b * b - L * L) / (2 * d * b))  # angle RQO
    w = L * L1 / (d * b * mpmath.sin(phi))
    al = (L1 * L1 - d * b * mpmath.cos(phi) * w * w) / (d * b * mpmath.sin(phi))
    theta = mpmath.atan2(-mpf("0.4"), mpf("1.2")) + phi  # R ccw of QO
    _close(sol.scene.input.angle, theta)
    _close(sol.W["QR"], w)
    _close(sol.Al["QR"], al)


def test_erdman_five_bar_second_crank_in_words():
    sol = _sol("erdman_five_bar_two_cranks_words")
    O5 = (mpf("0.08"), 0)
    g = [_ang(sol.P["A"], sol.P["B"]), _ang(sol.P["C"], sol.P["B"])]

    def state(t):
        t2 = pi / 3 + 10 * t
        t5 = 2 * pi / 3 - 5 * t + 10 * t * t  # 5 rad/s cw, slowing: 20 rad/s^2 ccw
        Ap = (mpf("0.04") * mpmath.cos(t2), mpf("0.04") * mpmath.sin(t2))
        Cp = (O5[0] + mpf("0.05") * mpmath.cos(t5), mpf("0.05") * mpmath.sin(t5))

        def res(t3, t4):
            return (
                Ap[0] + mpf("0.1") * mpmath.cos(t3) - Cp[0] - mpf("0.09") * mpmath.cos(t4),
                Ap[1] + mpf("0.1") * mpmath.sin(t3) - Cp[1] - mpf("0.09") * mpmath.sin(t4),
            )

        t3, t4 = _newton(res, g)
        return Ap, Cp, t3, t4

    def pts(t):
        Ap, Cp, t3, _ = state(t)
        return {
            "A": Ap,
            "C": Cp,
            "B": (Ap[0] + mpf("0.1") * mpmath.cos(t3), Ap[1] + mpf("0.1") * mpmath.sin(t3)),
        }

    P, V, A = _motion(pts)
    _check_kinematics(sol, P, V, A)
    _close(sol.W["AB"], _rate(lambda t: state(t)[2], 1))
    _close(sol.Al["BC"], _rate(lambda t: state(t)[3], 2))


def test_hamilton_mabie_wheel_rolling_drives_the_rod():
    sol = _sol("hamilton_mabie_wheel_rod_slider")
    r = mpf("0.25")

    def pts(t):
        s = 2 * t - t * t / 2  # 2 m/s right, 1 m/s^2 to the left
        C = (s, r)
        phi = pi / 4 - s / r  # rolling to the right turns it clockwise
        A = (C[0] + r * mpmath.cos(phi), C[1] + r * mpmath.sin(phi))
        return {"C": C, "A": A, "B": (A[0] + mpmath.sqrt(1 - A[1] ** 2), mpf(0))}

    P, V, A = _motion(pts)
    _check_kinematics(sol, P, V, A)
    _close(sol.W["CA"], mpf(-8))
    _close(sol.Al["CA"], mpf(4))


def test_wilson_sadler_compound_train_by_its_teeth():
    sol = _sol("wilson_sadler_compound_gear_train")
    w2 = -2 * pi * 1200 / 60
    _close(sol.W["O3-B"], -w2 * mpf(18) / 54)
    _close(sol.W["O5-C"], w2 * mpf(18) / 54 * mpf(20) / 60)


def test_mabie_pin_in_a_rotating_and_a_fixed_slot():
    sol = _sol("mabie_pin_rotating_and_fixed_slot")

    def th(t):
        return pi / 6 + 5 * t + 5 * t * t

    P, V, A = _motion(lambda t: {"P": (mpf("0.1"), mpf("0.1") * mpmath.tan(th(t)))})
    _check_kinematics(sol, P, V, A)
    # relative to the slot: d|O2P|/dt, and the Coriolis component 2 omega v_rel
    rel = _rate(lambda t: mpf("0.1") / mpmath.cos(th(t)), 1)
    _close(sol.S["P_O2-A"][0], rel)
    _close(math.hypot(*sol.coriolis("P_O2-A")), 2 * 5 * abs(rel))


def test_martin_collar_on_a_turning_rod():
    sol = _sol("martin_collar_on_turning_rod")

    def pts(t):
        r, th = mpf("0.5") + 3 * t - t * t / 2, pi / 6 + 2 * t - 2 * t * t
        return {"C": (r * mpmath.cos(th), r * mpmath.sin(th))}

    P, V, A = _motion(pts)
    _check_kinematics(sol, P, V, A)
    assert "C" in sol.scene.point_names
    # by hand in the rod's frame: v = (3, 1), a = (-3, 10) (radial, transverse)
    _close(math.hypot(*sol.V["C"]), mpmath.sqrt(10))
    _close(math.hypot(*sol.A["C"]), mpmath.sqrt(109))


# -- forces


def _virtual_torque(sol, loads, masses=()):
    """T on the crank by virtual power at 40 digits: T w + sum F.v + sum C w_L - sum m a.v -
    sum I alpha w = 0; ``loads`` [(force (Fx, Fy), velocity)] and couples [(C, w)]."""
    w = mpf(sol.scene.input.omega)
    power = sum(F[0] * v[0] + F[1] * v[1] for F, v in loads)
    for m, a, v, inertia, al, om in masses:
        power -= m * (a[0] * v[0] + a[1] * v[1]) + inertia * al * om
    return -power / w


def test_shigley_static_fourbar_by_virtual_work():
    sol = _sol("force_static_shigley_fourbar_coupler_load")
    at = _fourbar(
        (0, 0),
        (mpf("0.15"), 0),
        mpf("0.06"),
        mpf("0.18"),
        mpf("0.12"),
        lambda t: pi / 3 + t,
        sol,
        "A",
        "B",
    )
    k = mpmath.radians(20)

    def C(t):
        Bp, _, t3, _ = at(t)
        return (Bp[0] + mpf("0.09") * mpmath.cos(t3 + k), Bp[1] + mpf("0.09") * mpmath.sin(t3 + k))

    vC = tuple(_rate(lambda t, i=i: C(t)[i], 1) for i in (0, 1))
    F = tuple(500 * c for c in _cis(mpmath.radians(225)))
    w4 = _rate(lambda t: at(t)[3], 1)
    T = -(F[0] * vC[0] + F[1] * vC[1] + (-20) * w4)
    _close(sol.forces.input_torque, T)
    _close(sol.input_torque, T)


def test_mabie_static_slider_crank_in_inches():
    sol = _sol("force_static_mabie_slider_crank_inches")
    r, l, F = mpf("0.0508"), mpf("0.2032"), 100 * mpf("4.4482216152605")
    th = mpmath.radians(120)
    dx = mpmath.diff(
        lambda a: r * mpmath.cos(a) + mpmath.sqrt(l * l - (r * mpmath.sin(a)) ** 2), th
    )
    _close(sol.forces.input_torque, F * dx)  # the load pushes -x: T w = F dx/dtheta w
    assert float(F * dx) == pytest.approx(-151.0 * 0.1129848290276167, rel=0.01)


def test_wilson_sadler_inertia_torque_by_virtual_power():
    sol = _sol("force_wilson_sadler_slider_crank_inertia")
    w = 2 * pi * 2000 / 60
    at = _slider_crank(mpf("0.1"), mpf("0.45"), 0, lambda t: pi / 3 + w * t, sol)

    def G(t):
        A, B, _ = at(t)
        return {"G": tuple(A[i] + (B[i] - A[i]) / 3 for i in (0, 1)), "B": B}

    _, V, A = _motion(G)
    om, al = _rate(lambda t: at(t)[2], 1), _rate(lambda t: at(t)[2], 2)
    I = 3 * mpf("0.14") ** 2
    T = _virtual_torque(sol, [], [(3, A["G"], V["G"], I, al, om), (2, A["B"], V["B"], 0, 0, 0)])
    _close(sol.forces.input_torque, T)


def _engine(r, l, theta, w, m, F_gas, g_along=0):
    """The engine chapter's closed forms, theta from the inner dead centre: the piston's
    exact acceleration towards the crank, the piston effort, the rod's thrust, the side
    thrust, the crank effort and the turning moment."""
    n = l / r
    x = lambda a: r * (1 - mpmath.cos(a)) + l * (1 - mpmath.sqrt(1 - (mpmath.sin(a) / n) ** 2))  # noqa: E731
    acc = -mpmath.diff(x, theta, 2) * w * w  # towards the crank (x from the i.d.c. grows away)
    FP = F_gas - m * (-acc) + m * g_along
    phi = mpmath.asin(mpmath.sin(theta) / n)
    FQ = FP / mpmath.cos(phi)
    return {
        "approx": m * w * w * r * (mpmath.cos(theta) + mpmath.cos(2 * theta) / n),
        "piston_effort": FP,
        "rod_thrust": FQ,
        "side_thrust": FP * mpmath.tan(phi),
        "crank_effort": FQ * mpmath.sin(theta + phi),
        "turning_moment": FQ * mpmath.sin(theta + phi) * r,
        "inertia": -m * acc,
    }


def _efforts(sol):
    from polygon_method.forces.engine import efforts

    e = efforts(sol.scene, sol.plan, sol.P, sol.forces)
    return {
        "piston_effort": e.F_P,
        "rod_thrust": e.F_Q,
        "side_thrust": e.F_N,
        "crank_effort": e.F_T,
        "turning_moment": e.T,
    }


def test_bansal_steam_engine_efforts_by_the_closed_forms():
    sol = _sol("force_bansal_steam_engine_efforts")
    w = 2 * pi * 200 / 60
    gas = mpf("0.5e6") * pi * mpf("0.4") ** 2 / 4
    want = _engine(mpf("0.3"), mpf("1.2"), pi / 6, w, 200, gas)
    got = _efforts(sol)
    for key in ("piston_effort", "rod_thrust", "side_thrust", "crank_effort", "turning_moment"):
        _close(abs(got[key]), abs(want[key]))
    # the book's approximate inertia force, within half a per cent of the exact
    assert abs(float(want["approx"] / want["inertia"]) - 1) < 0.005


def test_jagdish_lal_vertical_engine_with_its_weight_in_newtons():
    sc = load_scene(HERE / "force_jagdish_lal_vertical_engine_weight.toml")
    sol = solve(sc)
    m = mpf(12) / mpf("9.81")
    assert any("12 N" in n and "W / g" in n for n in sol.notes)
    w = 2 * pi * 1800 / 60
    gas = mpf("0.8e6") * pi * mpf("0.1") ** 2 / 4
    # at the top the piston is above the crank: its weight pushes it towards the crank
    want = _engine(mpf("0.06"), mpf("0.25"), mpmath.radians(20), w, m, gas, g_along=mpf("9.81"))
    got = _efforts(sol)
    for key in ("piston_effort", "side_thrust", "turning_moment"):
        _close(abs(got[key]), abs(want[key]))


def test_ballaney_toggle_press_by_virtual_work():
    sol = _sol("force_static_ballaney_toggle_press")
    Q = (0, mpf("0.4"))
    g = [mpf(sol.P["B"][0]), mpf(sol.P["B"][1]), mpf(sol.P["R"][1])]

    def yR(th):
        Ap = (mpf("0.08") * mpmath.cos(th), mpf("0.08") * mpmath.sin(th))

        def res(x, y, yr):
            return (
                (x - Ap[0]) ** 2 + (y - Ap[1]) ** 2 - mpf("0.09"),
                x * x + (y - Q[1]) ** 2 - mpf("0.0625"),
                x * x + (y - yr) ** 2 - mpf("0.0625"),
            )

        return _newton(res, g)[2]

    T = -(10000 * mpmath.diff(yR, pi / 6))
    _close(sol.forces.input_torque, T)


# -- statements the docs led to and the tool refused or read wrong before


def test_an_offset_key_is_refused_saying_how_an_offset_is_stated():
    text = (HERE / "jagdish_lal_offset_slider_line_of_stroke.toml").read_text(encoding="utf-8")
    bad = text.replace("through = [0, -40] }", "offset = 40 }")
    with pytest.raises(SceneError) as exc:
        parse_scene(bad)
    msg = str(exc.value)
    assert "\n" not in msg and "[sliders] B" in msg and "its through = [x, y]" in msg, msg


@pytest.mark.parametrize(
    "words,deg",
    [
        ("angle BAD = 60 deg, ccw", 60),
        ("angle DAB = 60 deg, cw", -60),
        ("the crank makes 60 deg with the line of centres, cw", -60),
        ("the crank AB makes 60 deg with the line of centres, ccw", 60),
        ("crank AB is inclined at 30 deg to the horizontal, ccw", 30),
    ],
)
def test_a_books_sentence_about_the_crank_reads_as_its_angle(words, deg):
    text = (HERE / "ambekar_fourbar_angle_bad_midpoint.toml").read_text(encoding="utf-8")
    sc = parse_scene(text.replace('"angle BAD = 60 deg, cw"', f'"{words}"'))
    assert math.degrees(sc.input.angle) == pytest.approx(deg, abs=1e-12)


@pytest.mark.parametrize(
    "words,said",
    [
        ("angle BAD = 60 deg", 'add the sense, e.g. "60 deg from AD, ccw"'),
        ("angle BDA = 60 deg, ccw", "vertex D (its middle letter) is not the crank's pivot A"),
        ("angle BAC = 60 deg, ccw", "one of B and C must be a ground point"),
    ],
)
def test_an_angle_bad_stated_wrong_is_refused_in_one_line(words, said):
    text = (HERE / "ambekar_fourbar_angle_bad_midpoint.toml").read_text(encoding="utf-8")
    with pytest.raises(SceneError) as exc:
        parse_scene(text.replace('"angle BAD = 60 deg, cw"', f'"{words}"'))
    msg = str(exc.value)
    assert "\n" not in msg and "[input] angle" in msg and said in msg, msg


@pytest.mark.parametrize("words", ["midpoint", "the mid-point", "the middle of BC", "Midpoint"])
def test_a_midpoint_is_half_the_link(words):
    text = (HERE / "ambekar_fourbar_angle_bad_midpoint.toml").read_text(encoding="utf-8")
    sol = solve(parse_scene(text.replace('along = "midpoint"', f'along = "{words}"')))
    B, C = sol.P["B"], sol.P["C"]
    assert sol.P["E"] == pytest.approx(((B[0] + C[0]) / 2, (B[1] + C[1]) / 2), abs=1e-16)


def test_a_wheel_without_ground_is_told_to_give_its_floors_point():
    text = (HERE / "hamilton_mabie_wheel_rod_slider.toml").read_text(encoding="utf-8")
    bad = text.replace("[ground]\nO = [0, 0]\n", "").replace('through = "O"', "through = [0, 0]")
    with pytest.raises(SceneError) as exc:
        parse_scene(bad)
    msg = str(exc.value)
    assert "\n" not in msg and "missing [ground]" in msg and "wheel rolling on the floor" in msg


def test_a_weight_for_a_mass_is_read_by_the_scenes_g():
    text = (HERE / "force_jagdish_lal_vertical_engine_weight.toml").read_text(encoding="utf-8")
    sc = parse_scene(text.replace("[gravity]\n", '[gravity]\ng = "9.80665 m/s^2"\n'))
    assert sc.mass_of("B").mass == pytest.approx(12 / 9.80665, rel=1e-15)
    kgf = parse_scene(text.replace('"12 N"', '"2 kgf"'))
    assert kgf.mass_of("B").mass == pytest.approx(2 * 9.80665 / 9.81, rel=1e-12)


@pytest.mark.parametrize(
    "words,deg",
    [("theta2 = 30 deg", 30), ("θ2 = 30°", 30), ("at 30 deg", 30), ("theta = 30 deg, cw", -30)],
)
def test_a_us_books_theta2_and_an_at_read_as_the_plain_angle(words, deg):
    text = (HERE / "ambekar_fourbar_angle_bad_midpoint.toml").read_text(encoding="utf-8")
    sc = parse_scene(text.replace('"angle BAD = 60 deg, cw"', f'"{words}"'))
    assert math.degrees(sc.input.angle) == pytest.approx(deg, abs=1e-12)


def test_a_speed_with_a_comma_before_its_sense():
    text = (HERE / "ambekar_fourbar_angle_bad_midpoint.toml").read_text(encoding="utf-8")
    sc = parse_scene(text.replace('"120 rpm clockwise"', '"120 rpm, clockwise"'))
    assert sc.input.omega == pytest.approx(-4 * math.pi, rel=1e-15)


@pytest.mark.parametrize("words", ["perpendicular to CD", "along CD", "at right angles to CD"])
def test_a_load_across_a_link_the_scene_has_not_is_refused_naming_it(words):
    """(A direction against a link of the scene is read: tests/test_link_loads.py.)"""
    text = (HERE / "force_static_shigley_fourbar_coupler_load.toml").read_text(encoding="utf-8")
    with pytest.raises(SceneError) as exc:
        parse_scene(text.replace("direction = 225", f'direction = "{words}"'))
    msg = str(exc.value)
    assert "\n" not in msg and "[loads] C" in msg and "no link CD in [links]" in msg


@pytest.mark.parametrize(
    "speed,omega",
    [
        ("120 rpm c.w.", -1),
        ("120 rpm a.c.w.", 1),
        ("120 rpm counter clockwise", 1),
        ("120 rpm anti clockwise", 1),
    ],
)
def test_older_books_senses(speed, omega):
    text = (HERE / "ambekar_fourbar_angle_bad_midpoint.toml").read_text(encoding="utf-8")
    sc = parse_scene(text.replace('"120 rpm clockwise"', f'"{speed}"'))
    assert sc.input.omega == pytest.approx(omega * 4 * math.pi, rel=1e-15)
    turned = parse_scene(text.replace('"angle BAD = 60 deg, cw"', '"60 deg from AD, a.c.w."'))
    assert math.degrees(turned.input.angle) == pytest.approx(60, abs=1e-12)


@pytest.mark.parametrize("words", ["60 deg from DA, cw", "angle CDA = 60 deg, cw"])
def test_a_rockers_angle_from_the_frame_in_words_sets_the_position(words):
    """ "When angle CDA = 60 deg" (C above AD): angle_DC = "60 deg from DA, cw", the
    direction D -> C at 180 - 60 = 120 deg; the crank angle found puts C there (by hand: D +
    CD (cos 120, sin 120)), and B is 150 mm from it."""
    text = (HERE / "ambekar_fourbar_angle_bad_midpoint.toml").read_text(encoding="utf-8")
    text = text.replace('angle = "angle BAD = 60 deg, cw"', f'angle_DC = "{words}"')
    sol = solve(parse_scene(text))
    C = (0.15 + 0.08 * math.cos(math.radians(120)), 0.08 * math.sin(math.radians(120)))
    assert sol.P["C"] == pytest.approx(C, abs=1e-15)
    assert math.dist(sol.P["B"], C) == pytest.approx(0.15, rel=1e-14)
    assert any("angle_DC" in n and "120 deg" in n for n in sol.notes)


@pytest.mark.parametrize(
    "name,words",
    [
        ("martin_collar_on_turning_rod", "not within 12 turns (the second input moves on"),
        ("erdman_five_bar_two_cranks_words", "every 2 turns (the second input moves on"),
    ],
)
def test_a_sweep_of_two_inputs_says_why_a_turn_does_not_bring_it_back(name, words):
    """The second crank turns half a turn cw per turn of the first (5 / 10): back after 2;
    the collar slides on: never. The note named a wheel, which neither has."""
    from polygon_method import sweep

    notes = " ".join(sweep(load_scene(HERE / f"{name}.toml")).notes)
    assert words in notes and "wheel" not in notes, notes


@pytest.mark.parametrize(
    "words", ["angle CO5O2 = 60 deg, cw", "60 deg from O5O2, cw", "30 deg left of the vertical"]
)
def test_the_second_cranks_angle_in_the_words_of_the_first(words):
    """O5C at 120 deg: 60 deg clockwise from O5 -> O2 (180 deg), or 30 deg left of the
    vertical (by hand)."""
    text = (HERE / "erdman_five_bar_two_cranks_words.toml").read_text(encoding="utf-8")
    sc = parse_scene(text.replace('"makes 30 deg with the vertical, ccw"', f'"{words}"'))
    assert math.degrees(sc.input.second.angle) == pytest.approx(120, abs=1e-12)


PISTON = """units = "mm"
[ground]
O = [0, 0]
[links]
OA = 100
AB = 400
[sliders]
B = {{ path = "horizontal" }}
{hint}
[input]
crank = "OA"
angle = 30
vs_B = "{v}"
as_B = "20 m/s^2 towards the crank"
"""


@pytest.mark.parametrize(
    "hint,v,sign",
    [
        ("", "5 m/s towards the crank", -1),  # the piston right of O: towards it is -x
        ("", "5 m/s away from the crank", 1),
        ('[assembly]\nB = "left"', "5 m/s towards the crank", 1),
        ("[assembly]\nB = [-300, 0]", "5 m/s, toward the crank shaft", 1),
    ],
)
def test_the_piston_moves_towards_the_crank(hint, v, sign):
    """ "The piston moves at 5 m/s towards the crank": x_B = r cos t + s sqrt(l^2 - r^2
    sin^2 t) (s the side), the crank's omega = v_B / (dx_B/dt) (by hand, 40 digits)."""
    sol = solve(parse_scene(PISTON.format(hint=hint, v=v)))
    side = 1 if not hint else -1
    r, l, t = mpf("0.1"), mpf("0.4"), pi / 6

    def x(a):
        return r * mpmath.cos(a) + side * mpmath.sqrt(l * l - (r * mpmath.sin(a)) ** 2)

    assert (x(t) > 0) == (side > 0)
    _close(sol.S["B"][0], sign * 5)
    _close(sol.scene.input.omega, sign * 5 / mpmath.diff(x, t))
    _close(sol.S["B"][1], -20 * (1 if x(t) > 0 else -1))


def test_towards_the_crank_with_the_position_given_otherwise_is_refused():
    text = PISTON.format(hint="", v="5 m/s towards the crank").replace("angle = 30", "s_B = 450")
    with pytest.raises(SceneError) as exc:
        parse_scene(text)
    assert "\n" not in str(exc.value) and "left, right, up or down" in str(exc.value)


@pytest.mark.parametrize(
    "old,new",
    [
        ('"O4-B" = { torque = "20 N m cw" }', '"O4-B" = { couple = "20 N m cw" }'),
        ('"O4-B" = { torque = "20 N m cw" }', '"O4-B" = { torque = "2000 N cm cw" }'),
        ('"O4-B" = { torque = "20 N m cw" }', '"O4-B" = { torque = "20 N-m cw" }'),
    ],
)
def test_a_couple_and_its_units_as_books_write_them(old, new):
    """ "A couple of 20 N m acts on link 4", in N cm: the same torque on the crank as the
    file's (the virtual-work test above holds that one)."""
    text = (HERE / "force_static_shigley_fourbar_coupler_load.toml").read_text(encoding="utf-8")
    want = solve(parse_scene(text)).forces.input_torque
    assert old in text
    assert solve(parse_scene(text.replace(old, new))).forces.input_torque == pytest.approx(
        want, rel=1e-14
    )


@pytest.mark.parametrize("inertia", ["0.0588 kg-m^2", "0.0588 kg.m^2", "588 kg-cm^2"])
def test_a_moment_of_inertia_with_a_hyphen_or_a_dot(inertia):
    text = (HERE / "force_wilson_sadler_slider_crank_inertia.toml").read_text(encoding="utf-8")
    sc = parse_scene(text.replace("gyration = 140", f'inertia = "{inertia}"'))
    assert sc.mass_of("AB").inertia == pytest.approx(0.0588, rel=1e-14)  # 3 kg x 0.14^2


def test_a_wheel_left_out_of_links_is_told_it_is_a_link():
    text = (HERE / "hamilton_mabie_wheel_rod_slider.toml").read_text(encoding="utf-8")
    with pytest.raises(SceneError) as exc:
        parse_scene(text.replace("CA = 0.25\n", ""))
    msg = str(exc.value)
    assert "\n" not in msg and "[rolling] CA" in msg and "CA = its radius" in msg, msg


def test_the_ram_force_for_a_given_crank_torque_by_scaling_the_load():
    """The book's other question: the ram's force that a torque of 100 N m on the crank holds.
    Linear in the load: P = 10 kN x 100 / T; stated with P, the crank needs 100 N m (and the
    virtual work of the test above gives the same)."""
    text = (HERE / "force_static_ballaney_toggle_press.toml").read_text(encoding="utf-8")
    T = solve(parse_scene(text)).forces.input_torque
    P = 10000 * 100 / abs(T)
    again = solve(parse_scene(text.replace('force = "10 kN"', f'force = "{P!r} N"')))
    assert abs(again.forces.input_torque) == pytest.approx(100, rel=1e-12)


@pytest.mark.parametrize(
    "words,sign",
    [
        ("0.1 m/s, extending", 1),
        ("extending at 0.1 m/s", 1),
        ("retracting at 100 mm/s", -1),
        ("0.1 m/s lengthening", 1),
        ("0.1 m/s shortening", -1),
    ],
)
def test_a_cylinders_rate_in_a_books_order_of_words(words, sign):
    """The dump body's omega by the cosine rule (the test above), the sign by the way the
    cylinder moves ("extending at 0.1 m/s" was read as a direction "at 0.1 m/s")."""
    text = (HERE / "mabie_dump_body_cylinder.toml").read_text(encoding="utf-8")
    sol = solve(parse_scene(text.replace('"0.1 m/s extending"', f'"{words}"')))
    want = _sol("mabie_dump_body_cylinder").W["QR"]
    assert sol.W["QR"] == pytest.approx(sign * want, rel=1e-13)


def test_a_collars_sliding_after_a_comma():
    text = (HERE / "martin_collar_on_turning_rod.toml").read_text(encoding="utf-8")
    sol = solve(parse_scene(text.replace('"3 m/s outward"', '"3 m/s, outward"')))
    _close(math.hypot(*sol.V["C"]), mpmath.sqrt(10))


def test_a_bare_speed_is_told_its_unit_and_its_sense_at_once():
    text = (HERE / "ambekar_fourbar_angle_bad_midpoint.toml").read_text(encoding="utf-8")
    with pytest.raises(SceneError) as exc:
        parse_scene(text.replace('speed = "120 rpm clockwise"', "speed = 10"))
    assert '"10 rad/s ccw"' in str(exc.value) and "\n" not in str(exc.value)


@pytest.mark.parametrize(
    "given",
    [
        'inertia = "0.1263 kg m^2", about = "A"',
        f'gyration = {1000 * math.sqrt(0.1263 / 3)!r}, about = "A"',
    ],
)
def test_a_moment_of_inertia_about_an_end_by_the_parallel_axes(given):
    """The rod of 3 kg with G 150 mm from A and k_G = 140 mm: I_A = 3 (0.14^2 + 0.15^2) =
    0.1263 kg m^2 (by hand); stated about A it is the same rod (the same torque)."""
    text = (HERE / "force_wilson_sadler_slider_crank_inertia.toml").read_text(encoding="utf-8")
    sc = parse_scene(text.replace("gyration = 140", given))
    assert sc.mass_of("AB").inertia == pytest.approx(0.0588, rel=1e-12)
    want = _sol("force_wilson_sadler_slider_crank_inertia").forces.input_torque
    assert solve(sc).forces.input_torque == pytest.approx(want, rel=1e-12)


def test_a_moment_of_inertia_about_an_end_below_m_d_squared_is_refused():
    text = (HERE / "force_wilson_sadler_slider_crank_inertia.toml").read_text(encoding="utf-8")
    with pytest.raises(SceneError) as exc:
        parse_scene(text.replace("gyration = 140", 'inertia = "0.05 kg m^2", about = "A"'))
    assert "no body has it" in str(exc.value) and "\n" not in str(exc.value)


@pytest.mark.parametrize(
    "words,part",
    [("1/3 of BC", 1 / 3), ("0.4 BC", 0.4), ("2/3 of CB", 2 / 3), ("40 mm", 0.04 / 0.15)],
)
def test_a_part_of_a_link(words, part):
    """E "one third of BC from B": B + part (C - B) (by hand, from the solved ends); a length
    with its unit is still a length."""
    text = (HERE / "ambekar_fourbar_angle_bad_midpoint.toml").read_text(encoding="utf-8")
    sol = solve(parse_scene(text.replace('along = "midpoint"', f'along = "{words}"')))
    B, C = sol.P["B"], sol.P["C"]
    want = (B[0] + part * (C[0] - B[0]), B[1] + part * (C[1] - B[1]))
    assert sol.P["E"] == pytest.approx(want, abs=1e-15)
