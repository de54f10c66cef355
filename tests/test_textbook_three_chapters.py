"""Textbook problems of three chapters written as a student would state them, each held to a
computation of its own written here (nothing of the tool's solve): static force analysis
with friction at the pins and the slides, a coupler's inertia force and its offset, the
instantaneous centres by Kennedy's theorem, and a flywheel against a machine's torque given
in segments. Every view a student uses is run on each (solve, steps, draw, check with a
typical slip, page where it applies)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import mpmath
import pytest
from mpmath import mpf

from newton_euler import NewtonEuler
from polygon_method import load_scene, solve
from polygon_method.cli import main
from polygon_method.forces.bounds import force_bounds
from polygon_method.forces.engine import efforts
from polygon_method.forces.flywheel_cycle import curves, solve_cycle
from polygon_method.scene.energy import cycle_from_text

HERE = Path(__file__).resolve().parent / "textbook"
REL = 1e-9


def _run(capsys, *args):
    code = main([str(a) for a in args])
    out = capsys.readouterr()
    return code, out.out, out.err


# --- the flywheel: a machine's torque in segments against a motor's steady torque ----------

THREE_TURNS = HERE / "flywheel" / "segments_machine_three_turns.toml"


def _segments(angles, torques):
    """The piecewise-linear torque (mpmath) through the readings (deg, N m)."""
    a = [mpmath.radians(x) for x in angles]

    def f(th):
        for a0, a1, t0, t1 in zip(a, a[1:], torques, torques[1:]):
            if a0 <= th <= a1 and a1 > a0:
                return t0 + (t1 - t0) * (th - a0) / (a1 - a0)
        return mpf(torques[-1])

    return a, f


def test_machine_torque_in_segments_against_the_closed_energy_integration():
    """Khurmi's three-revolution machine: its mean, the crossings of the motor's steady
    torque, the fluctuation of energy and of speed, by mpmath's quadrature and root finding
    at 30 digits on the segments written out here."""
    mpmath.mp.dps = 30
    angles, R = [0, 180, 540, 720, 1080], [750, 3000, 3000, 750, 750]
    a, r = _segments(angles, R)
    cyc = a[-1]
    mean = mpmath.quad(r, a) / cyc
    roots = []
    for a0, a1 in zip(a, a[1:]):
        g0, g1 = r(a0) - mean, r(a1) - mean
        if g0 * g1 < 0:
            roots.append(mpmath.findroot(lambda x: r(x) - mean, (a0, a1), solver="bisect"))

    def energy(th):  # the motor's work less the machine's from the cycle's start
        pts = [x for x in a if x < th] + [th]
        return mean * th - mpmath.quad(r, pts)

    es = [energy(x) for x in roots]
    dE = max(es) - min(es)
    w = mpf(250) * 2 * mpmath.pi / 60
    inertia = mpf(500) * mpf("0.6") ** 2
    cs = dE / (inertia * w**2)

    c = solve_cycle(cycle_from_text(THREE_TURNS.read_text(encoding="utf-8"), str(THREE_TURNS)))
    assert c.T_mean == pytest.approx(float(mean), rel=REL)
    assert c.power == pytest.approx(float(mean * w), rel=REL)
    got = sorted(x.angle for x in c.crossings[:-1])
    assert got == pytest.approx([float(x) for x in roots], rel=REL)
    assert c.dE_max == pytest.approx(float(dE), rel=REL)
    assert c.Cs == pytest.approx(float(cs), rel=REL)
    assert c.speed_max == pytest.approx(float(w * (1 + cs / 2)), rel=REL)
    assert c.speed_min == pytest.approx(float(w * (1 - cs / 2)), rel=REL)
    # the speed is greatest where the machine starts to take more than the motor gives
    assert math.degrees(c.crossings[c.i_max].angle) == pytest.approx(90, rel=REL)


def test_machine_torque_in_segments_in_every_view(capsys, tmp_path):
    code, out, _ = _run(capsys, "solve", THREE_TURNS)
    assert code == 0
    assert "the driving torque constant (a motor's), the mean, the cycle 1080 deg" in out
    assert "the resisting torque in 5 readings at the same angles" in out
    assert "maximum fluctuation of energy dE_max = 8836 J" in out
    code, out, _ = _run(capsys, "steps", THREE_TURNS)
    assert code == 0 and "dE_max = 0 - (-8836) = 8836 J" in out
    assert _run(capsys, "draw", THREE_TURNS, "-o", tmp_path / "d.svg")[0] == 0
    assert _run(capsys, "page", THREE_TURNS, "-o", tmp_path / "p.html")[0] == 0
    csv = tmp_path / "c.csv"
    assert _run(capsys, "sweep", THREE_TURNS, "--csv", csv, "--steps", 12)[0] == 0
    rows = [line.split(",") for line in csv.read_text().splitlines()[1:]]
    for deg, tq, res, _ in rows:  # the motor's steady torque, the machine's readings
        assert float(tq) == pytest.approx(1875, rel=REL)
        want = {0: 750, 180: 3000, 540: 3000, 720: 750, 1080: 750}.get(round(float(deg)))
        assert want is None or float(res) == want  # a reading exactly, no rounding noise
    answers = tmp_path / "a.toml"
    answers.write_text('[answers]\ndE_max = "8836 J"\nCs = "3.581%"\n', encoding="utf-8")
    code, out, _ = _run(capsys, "check", THREE_TURNS, answers)
    assert code == 1 and "the range either side of the" in out and "(0.03581);" in out


def test_a_jump_in_the_machines_torque_is_drawn_upright(tmp_path):
    text = (
        '[turning_moment]\nangle = [0, 90, 90, 180, 360]\ntorque = "constant"\n'
        'resisting = [0, 0, 1000, 1000, 0]\n[flywheel]\nspeed = "250 rpm"\ncoefficient = 0.02\n'
    )
    sc = cycle_from_text(text, "jump.toml")
    c = solve_cycle(sc)
    th, tq, rs, _ = curves(sc, c, n=9)
    at90 = [r for t, r in zip(th, rs) if abs(t - math.pi / 2) < 1e-12]
    assert at90[0] == 0 and at90[-1] == 1000  # before the jump, then after it
    # by hand: 1000 N m held over 90 deg, then falling to nought over 180 deg: 1000 pi J
    assert c.T_mean == pytest.approx(1000 * (math.pi / 2 + math.pi / 2) / (2 * math.pi), rel=REL)


@pytest.mark.parametrize(
    "body, words",
    [
        ('angle = [0, 180, 360]\ntorque = "constant"\n', "needs the resisting torque's readings"),
        ('angle = [0, 180, 360]\ntorque = "constant"\nresisting = [0, 100]\n', "2 torques for 3"),
        # readings, not a sum: [20, 10, 20] is not a constant 50 (the mean 15 differs)
        ("angle = [0, 180, 360]\ntorque = [0, 100, 0]\nresisting = [20, 10, 20]\n", "differ"),
    ],
)
def test_a_machines_torque_in_segments_badly_given_is_one_line(tmp_path, capsys, body, words):
    f = tmp_path / "bad.toml"
    f.write_text(
        "[turning_moment]\n" + body + '[flywheel]\nspeed = "250 rpm"\ncoefficient = 0.02\n',
        encoding="utf-8",
    )
    code, out, err = _run(capsys, "solve", f)
    assert code == 2 and words in err and err.count("\n") == 1 and "Traceback" not in err


# --- static force analysis with friction at the pins and the slides ------------------------


def _with_friction(bodies, about, pins, guides, knowns, driver, omegas, mu_pin, mu_guide):
    """The matrix Newton-Euler method with Coulomb friction, repeated until the friction
    settles: each pin's couple ``mu r |F|`` against the relative turning of its two bodies,
    each guide's force ``mu |N|`` against the block's sliding, from the forces of the pass
    before (the first pass without). ``pins``: (name, at, on, by, r); ``guides``: (name, at,
    block, normal, along, sliding velocity); ``knowns``: (body, F, at, couple); the driver's
    torque ``T`` on ``driver`` by the frame. At mpmath's precision."""
    sizes, normals, last = {}, {}, None
    for _ in range(200):
        ne = NewtonEuler(bodies, about=about, mp=True)
        for name, at, on, by, r in pins:
            ne.pin(name, at, on, by)
            if name in sizes:
                c = -mu_pin * r * sizes[name] * mpmath.sign(omegas[on] - omegas.get(by, 0))
                ne.known(on, c=c)
                ne.known(by, c=-c)
        for name, at, block, n, u, vs in guides:
            ne.along(name, at, n, block, "frame")
            if name in normals:
                f = -mu_guide * abs(normals[name]) * mpmath.sign(vs)
                ne.known(block, (f * u[0], f * u[1]), at)
        for body, F, at, c in knowns:
            ne.known(body, F, at, c)
        ne.couple("T", driver, "frame")
        x = ne.solve()
        if last is not None and abs(last - x["T"]) < mpf(10) ** -30:
            return x
        last = x["T"]
        sizes = {n: mpmath.hypot(x[n + ".x"], x[n + ".y"]) for n, *_ in pins}
        normals = {n: x[n] for n, *_ in guides}
    raise AssertionError("the friction did not settle")


def _fourbar(a, b, c, d, theta, w2):
    """A four-bar A (0, 0), D (d, 0): B, C (above AD), omega of BC and CD, closed form."""
    B = (a * mpmath.cos(theta), a * mpmath.sin(theta))
    dx, dy = d - B[0], -B[1]
    L = mpmath.hypot(dx, dy)
    x = (b**2 - c**2 + L**2) / (2 * L)
    h = mpmath.sqrt(b**2 - x**2)
    ux, uy = dx / L, dy / L
    C = (B[0] + x * ux - h * uy, B[1] + x * uy + h * ux)
    if C[1] < 0:
        C = (B[0] + x * ux + h * uy, B[1] + x * uy - h * ux)
    vB = (-w2 * B[1], w2 * B[0])  # vB + w3 x (C - B) = w4 x (C - D)
    m = mpmath.matrix([[-(C[1] - B[1]), C[1]], [C[0] - B[0], -(C[0] - d)]])
    w3, w4 = mpmath.lu_solve(m, mpmath.matrix([-vB[0], -vB[1]]))
    return B, C, w3, w4


def _pin(sol, point):
    return next(p for p in sol.forces.pins if p.point == point).magnitude


def test_fourbar_with_friction_at_the_pins_against_the_matrix_method():
    """Rattan's four-link mechanism, friction circles at its four pins: the torque and every
    pin force to the 40-digit matrix method repeated until the friction settles."""
    mpmath.mp.dps = 40
    f = HERE / "friction_static_fourbar_pins.toml"
    B, C, w3, w4 = _fourbar(
        mpf("0.1"), mpf("0.3"), mpf("0.25"), mpf("0.35"), mpmath.radians(75), 10
    )
    A, D = (0, 0), (mpf("0.35"), 0)
    pins = [
        ("A", A, "AB", "frame", mpf("0.015")),
        ("B", B, "BC", "AB", mpf("0.0125")),
        ("C", C, "BC", "CD", mpf("0.0125")),
        ("D", D, "CD", "frame", mpf("0.015")),
    ]
    om = {"AB": mpf(10), "BC": w3, "CD": w4}
    args = (["AB", "BC", "CD"], {}, pins, [], [("CD", (0, 0), (0, 0), mpf(-40))], "AB", om)
    x = _with_friction(*args, mpf("0.2"), 0)
    sol = solve(load_scene(f))
    assert sol.forces.input_torque == pytest.approx(float(x["T"]), rel=REL)
    for name, *_ in pins:
        want = mpmath.hypot(x[name + ".x"], x[name + ".y"])
        assert _pin(sol, name) == pytest.approx(float(want), rel=REL)
    bare = _with_friction(*args, 0, 0)  # the slip: the friction left out
    assert sol.input_torque == pytest.approx(float(bare["T"]), rel=REL)


def test_slider_crank_with_friction_at_the_slide_and_pins_against_the_matrix_method():
    mpmath.mp.dps = 40
    f = HERE / "friction_static_slider_crank_slide.toml"
    r, l, th, w2 = mpf("0.08"), mpf("0.32"), mpmath.radians(120), mpf(-20)
    A = (r * mpmath.cos(th), r * mpmath.sin(th))
    B = (A[0] + mpmath.sqrt(l**2 - A[1] ** 2), mpf(0))
    vA = (-w2 * A[1], w2 * A[0])
    w3 = -vA[1] / (B[0] - A[0])  # B moves along the line of stroke
    vs = vA[0] - w3 * (B[1] - A[1])
    pins = [
        ("O", (0, 0), "OA", "frame", 0),
        ("A", A, "AB", "OA", mpf("0.02")),
        ("B", B, "AB", "block", mpf("0.0125")),
    ]
    guides = [("N", B, "block", (0, 1), (1, 0), vs)]
    om = {"OA": w2, "AB": w3, "block": 0}
    load = [("block", (mpf(-1500), 0), B, 0)]
    x = _with_friction(
        ["OA", "AB", "block"], {"block": B}, pins, guides, load, "OA", om, mpf("0.1"), mpf("0.15")
    )
    sol = solve(load_scene(f))
    assert sol.forces.input_torque == pytest.approx(float(x["T"]), rel=REL)
    assert _pin(sol, "B") == pytest.approx(float(mpmath.hypot(x["B.x"], x["B.y"])), rel=REL)
    assert sol.forces.guides[0].normal == pytest.approx(float(x["N"]), rel=REL)


@pytest.mark.parametrize(
    "name, slip",
    [
        ("friction_static_fourbar_pins", "11.89 N m ccw"),
        ("friction_static_slider_crank_slide", "90.62 N m cw"),
        ("friction_static_slotted_lever", "13.85 N m ccw"),
        ("friction_static_shaper_ram_and_slot", "373.4 N m ccw"),
    ],
)
def test_friction_problems_in_every_view(capsys, tmp_path, name, slip):
    f = HERE / f"{name}.toml"
    code, out, _ = _run(capsys, "solve", f)
    assert (
        code == 0 and "input torque on" in out and "(inertia, weights, loads and friction)" in out
    )
    code, out, _ = _run(capsys, "steps", f)
    assert code == 0 and "friction power" in out
    code, out, _ = _run(capsys, "draw", f, "--forces", "-o", tmp_path / "f.svg")
    assert code == 0
    assert _run(capsys, "page", f, "-o", tmp_path / "p.html")[0] == 0
    code, out, _ = _run(capsys, "sweep", f, "--summary")
    line = next(x for x in out.splitlines() if x.startswith("torque_inertia"))
    assert "with inertia" not in line and "of the loads and friction (no body massive)" in line
    answers = tmp_path / "a.toml"
    answers.write_text(f'[answers]\ntorque = "{slip}"\n', encoding="utf-8")
    code, out, _ = _run(capsys, "check", f, answers)
    assert code == 1 and "mistake: the friction left out" in out
    assert "inertia" not in out.split("mistake:")[1]  # no inertia in a static problem


# --- a coupler's inertia force at its offset (Shigley & Uicker) ---------------------------

OFFSET = HERE / "force_fourbar_coupler_offset_accelerating.toml"


def test_coupler_inertia_force_offset_and_torque_against_newton_euler():
    """Closed-form positions of the four-bar, their crank-angle derivatives by mpmath
    (a = x'' w^2 + x' alpha), each body's inertia force and couple, the three bodies'
    equations as one 9 x 9 system at 40 digits."""
    mpmath.mp.dps = 40
    a, b, c, d = mpf("0.075"), mpf("0.25"), mpf("0.15"), mpf("0.3")
    th0, w, al = mpmath.radians(110), 240 * 2 * mpmath.pi / 60, mpf(60)

    def pos(th):
        B, C, _, _ = _fourbar(a, b, c, d, th, 1)
        return B, C

    def G3(th, k):
        B, C = pos(th)
        return B[k] + mpf("0.11") * (C[k] - B[k]) / b

    def G4(th, k):
        _, C = pos(th)
        return (d, 0)[k] + mpf("0.075") * (C[k] - (d, 0)[k]) / c

    def ang3(th):
        B, C = pos(th)
        return mpmath.atan2(C[1] - B[1], C[0] - B[0])

    def ang4(th):
        _, C = pos(th)
        return mpmath.atan2(C[1], C[0] - d)

    def acc(f):
        return mpmath.diff(f, th0, 2) * w**2 + mpmath.diff(f, th0, 1) * al

    aG3 = [acc(lambda t, k=k: G3(t, k)) for k in (0, 1)]
    aG4 = [acc(lambda t, k=k: G4(t, k)) for k in (0, 1)]
    al3, al4 = acc(ang3), acc(ang4)
    I3, I4 = 4 * mpf("0.09") ** 2, mpf("2.5") * mpf("0.055") ** 2
    B, C = pos(th0)
    ne = NewtonEuler(["AB", "BC", "CD"], mp=True)
    ne.pin("A", (0, 0), "AB", "frame")
    ne.pin("B", B, "BC", "AB")
    ne.pin("C", C, "BC", "CD")
    ne.pin("D", (d, 0), "CD", "frame")
    ne.known("BC", (-4 * aG3[0], -4 * aG3[1]), (G3(th0, 0), G3(th0, 1)), -I3 * al3)
    m4 = mpf("2.5")
    ne.known("CD", (-m4 * aG4[0], -m4 * aG4[1]), (G4(th0, 0), G4(th0, 1)), -I4 * al4 - 25)
    ne.couple("T", "AB", "frame")
    x = ne.solve()

    sol = solve(load_scene(OFFSET))
    f = sol.forces
    assert f.input_torque == pytest.approx(float(x["T"]), rel=REL)
    for name in "ABCD":
        assert _pin(sol, name) == pytest.approx(
            float(mpmath.hypot(x[name + ".x"], x[name + ".y"])), rel=REL
        )
    i3 = next(i for i in f.inertia if i.body == "BC")
    assert math.hypot(*i3.force) == pytest.approx(float(4 * mpmath.hypot(*aG3)), rel=REL)
    assert i3.couple == pytest.approx(float(-I3 * al3), rel=REL)
    # the single force's offset h = I alpha / (m a_G), on the side where its moment about G
    # is the couple -I alpha: h's sign along the force turned 90 deg ccw gives that moment
    h = I3 * al3 / (4 * mpmath.hypot(*aG3))
    assert abs(i3.offset) == pytest.approx(float(h), rel=REL)
    F = i3.force
    moment = i3.offset * (-F[1] * F[1] - F[0] * F[0]) / math.hypot(*F)  # (h n) x F, n = perp(F)/|F|
    assert moment == pytest.approx(float(-I3 * al3), rel=REL)


def test_coupler_offset_problem_in_every_view(capsys, tmp_path):
    code, out, _ = _run(capsys, "solve", OFFSET)
    assert code == 0 and "offset h (mm)" in out and "16.26" in out
    code, out, _ = _run(capsys, "steps", OFFSET)
    assert code == 0 and "h = I alpha / (m a_G)" in out
    assert _run(capsys, "draw", OFFSET, "--forces", "-o", tmp_path / "f.svg")[0] == 0
    assert _run(capsys, "page", OFFSET, "-o", tmp_path / "p.html")[0] == 0
    answers = tmp_path / "a.toml"
    answers.write_text(
        '[answers]\ntorque = "13.22 N m ccw"\nCi_BC = "2.535 N m ccw"\nh_BC = "16.26 m"\n',
        encoding="utf-8",
    )
    code, out, _ = _run(capsys, "check", OFFSET, answers)
    out = " ".join(out.split())  # (the diagnoses are wrapped)
    assert code == 1
    assert "mistake: the power balance without the inertia forces" in out
    assert "the offset in mm given as m" in out  # h's unit: mm written as m
    assert "offset h = I alpha / (m a_G) on the wrong side of G" in out  # the couple's sense


# --- instantaneous centres by Kennedy's theorem, by hand geometry ---------------------------


def _meet(p1, p2, q1, q2):
    """Where the line p1 p2 meets the line q1 q2 (mpmath)."""
    d1, d2 = (p2[0] - p1[0], p2[1] - p1[1]), (q2[0] - q1[0], q2[1] - q1[1])
    t = ((q1[0] - p1[0]) * d2[1] - (q1[1] - p1[1]) * d2[0]) / (d1[0] * d2[1] - d1[1] * d2[0])
    return (p1[0] + t * d1[0], p1[1] + t * d1[1])


def _dist(a, b):
    return mpmath.hypot(a[0] - b[0], a[1] - b[1])


def _centres(path):
    from polygon_method.solver.centres import locate

    sol = solve(load_scene(path))
    return sol, locate(sol)


def _at(ic, i, j, unit=1e-3):
    c = ic.centre(i, j)
    return (c.point[0] / unit, c.point[1] / unit)  # in mm


def _close(got, want, scale):
    assert math.dist(got, (float(want[0]), float(want[1]))) <= REL * scale, (got, want)


def test_fourbar_centres_and_coupler_point_by_kennedy():
    mpmath.mp.dps = 40
    sol, ic = _centres(HERE / "centres_fourbar_coupler_point.toml")
    w2 = -120 * 2 * mpmath.pi / 60
    B, C, _, _ = _fourbar(mpf(200), mpf(500), mpf(400), mpf(600), mpmath.radians(60), w2)
    A, D = (0, 0), (mpf(600), 0)
    bc = _dist(B, C)  # E: BE = 300, CE = 350, the triangle B C E anticlockwise
    xe = (300**2 - 350**2 + bc**2) / (2 * bc)
    he = mpmath.sqrt(300**2 - xe**2)
    ux, uy = (C[0] - B[0]) / bc, (C[1] - B[1]) / bc
    E = (B[0] + xe * ux - he * uy, B[1] + xe * uy + he * ux)
    I13, I24 = _meet(A, B, D, C), _meet(A, D, B, C)  # Kennedy: I12 I23 with I14 I34; ...
    assert ic.n == 4 and len(ic.centres) == 6  # N = 4 x 3 / 2
    _close(_at(ic, 1, 3), I13, 1000)
    _close(_at(ic, 2, 4), I24, 1000)
    # the angular-velocity-ratio theorem, the senses from the side the centre falls on
    s3 = 1 if (B[0] - A[0]) * (B[0] - I13[0]) + (B[1] - A[1]) * (B[1] - I13[1]) > 0 else -1
    w3 = w2 * _dist(B, A) / _dist(B, I13) * s3
    w4 = w2 * _dist(I24, A) / _dist(I24, D) * (1 if (I24[0] - A[0]) * (I24[0] - D[0]) > 0 else -1)
    assert sol.W["BC"] == pytest.approx(float(w3), rel=REL)
    assert sol.W["CD"] == pytest.approx(float(w4), rel=REL)
    assert math.hypot(*sol.V["E"]) == pytest.approx(float(abs(w3) * _dist(E, I13) / 1000), rel=REL)


def test_six_link_two_sliders_centres_by_kennedy():
    mpmath.mp.dps = 40
    sol, ic = _centres(HERE / "centres_six_link_two_sliders.toml")
    O, th = (mpf(0), mpf(0)), mpmath.radians(45)
    A = (150 * mpmath.cos(th), 150 * mpmath.sin(th))
    B = (A[0] + mpmath.sqrt(600**2 - A[1] ** 2), mpf(0))
    C = (A[0] + (B[0] - A[0]) / 3, A[1] + (B[1] - A[1]) / 3)
    D = (mpf(300), C[1] + mpmath.sqrt(500**2 - (300 - C[0]) ** 2))
    I13 = _meet(O, A, B, (B[0], B[1] + 1))  # OA produced; the normal to B's path
    I15 = _meet(I13, C, D, (D[0] + 1, D[1]))  # I13 I35; the normal to D's path
    I25 = _meet(O, I15, A, C)  # I12 I15; I23 I35
    I26 = _meet(O, (1, 0), I25, D)  # I12 I16; I25 I56
    assert ic.n == 6 and len(ic.centres) == 15  # N = 6 x 5 / 2
    for (i, j), want in {(1, 3): I13, (1, 5): I15, (2, 5): I25, (2, 6): I26}.items():
        _close(_at(ic, i, j), want, 1000)
    w2 = 2 * mpmath.pi
    assert math.hypot(*sol.V["D"]) == pytest.approx(float(w2 * _dist(O, I26) / 1000), rel=REL)
    w3 = w2 * _dist(A, O) / _dist(A, I13)
    w5 = w3 * _dist(C, I13) / _dist(C, I15)
    assert abs(sol.W["CD"]) == pytest.approx(float(w5), rel=REL)
    # the two blocks' centres with the frame are at infinity, square to their paths
    assert ic.centre(1, 4).point is None and abs(ic.centre(1, 4).direction[0]) < 1e-15
    assert ic.centre(1, 6).point is None and abs(ic.centre(1, 6).direction[1]) < 1e-15


def test_crank_and_slotted_lever_centres_by_kennedy():
    mpmath.mp.dps = 40
    sol, ic = _centres(HERE / "centres_crank_slotted_lever.toml")
    O4, O2, th = (mpf(0), mpf(0)), (mpf(0), mpf(300)), mpmath.radians(150)
    A = (120 * mpmath.cos(th), 300 + 120 * mpmath.sin(th))
    n = (-A[1], A[0])  # square to the slot O4 A
    I13 = _meet(O2, A, O4, (O4[0] + n[0], O4[1] + n[1]))
    I24 = _meet(O2, O4, A, (A[0] + n[0], A[1] + n[1]))
    _close(_at(ic, 1, 3), I13, 1000)
    _close(_at(ic, 2, 4), I24, 1000)
    w2 = 90 * 2 * mpmath.pi / 60
    w4 = w2 * _dist(O2, I24) / _dist(O4, I24)  # I24 beyond both pivots: the same sense
    assert sol.W["O4-P"] == pytest.approx(float(w4), rel=REL)
    assert math.hypot(*sol.V["P"]) == pytest.approx(float(w4 * mpf("0.5")), rel=REL)
    c34 = ic.centre(3, 4)
    assert c34.point is None
    assert abs(c34.direction[0] * A[0] + c34.direction[1] * A[1]) <= 1e-12 * _dist(A, O4)


@pytest.mark.parametrize(
    "name",
    [
        "centres_fourbar_coupler_point",
        "centres_six_link_two_sliders",
        "centres_crank_slotted_lever",
    ],
)
def test_centres_problems_in_every_view(capsys, tmp_path, name):
    f = HERE / f"{name}.toml"
    code, out, _ = _run(capsys, "centres", f)
    assert code == 0 and "Number of centres: N = n (n - 1) / 2" in out
    assert "angular-velocity-ratio theorem" in out
    assert _run(capsys, "draw", f, "--diagram", "centres", "-o", tmp_path / "c.svg")[0] == 0
    assert _run(capsys, "check", f)[0] == 0


def test_a_centre_at_infinity_answered_in_words(capsys, tmp_path):
    """Khurmi writes "I14 at infinity, perpendicular to the path": such an answer is read,
    its direction checked, and the slips named: the path's own direction given, a finite
    centre said to be at infinity; a finite point for it stays wrong."""
    f = HERE / "centres_six_link_two_sliders.toml"
    answers = tmp_path / "a.toml"
    answers.write_text(
        "[answers]\n"
        'I_14 = "at infinity"\n'  # its direction not stated: right
        'I_46 = "infinity, along 119.7 deg"\n'
        'I_16 = "at infinity, vertical"\n'  # the path's direction: square to the lines
        'I_13 = "at infinity"\n'  # finite
        "I_34 = [696.6, 0]\n",
        encoding="utf-8",
    )
    code, out, _ = _run(capsys, "check", f, answers)
    flat = " ".join(out.split())
    assert code == 1 and "3 of 5 right" in flat
    assert "the direction square to I16's lines given: it is at infinity along 0 deg" in flat
    assert "I13 is at [696.62, 696.62] mm, not at infinity" in flat
    code, out, _ = _run(capsys, "check", f, answers, "--json")
    rows = {r["key"]: r for r in json.loads(out)["answers"]}
    assert rows["I_16"]["mistake"] == "centre_direction_square"
    assert rows["I_13"]["mistake"] == "centre_not_at_infinity"
    assert rows["I_14"]["verdict"] == "right" and rows["I_14"]["given"] is None
    answers.write_text('[answers]\nI_14 = "infinite"\n', encoding="utf-8")
    code, _, err = _run(capsys, "check", f, answers)
    assert code == 2 and err.count("\n") == 1 and '"at infinity"' in err and "line 2" in err


# --- friction in a slotted lever's slot: the forces and how far they may be off -------------

SLOT = HERE / "friction_static_slotted_lever.toml"


def test_slotted_lever_with_friction_in_the_slot_and_its_error_bounds(capsys):
    """The crank and slotted lever against a couple on the lever, mu 0.1 in the slot: the
    torque, the slot's normal force and the pivots' forces to the 40-digit matrix method
    repeated until the friction settles (the block slides in along the slot). The friction
    acts along the slot, through O4: the second pass's friction reproduces the first's, and
    the forces' error bounds are the rounding's (they read 0.19 of the largest force
    before: the first pass's change, from no friction to its friction, taken for a
    settling change)."""
    mpmath.mp.dps = 40
    O4, O2, th = (mpf(0), mpf(0)), (mpf(0), mpf("0.3")), mpmath.radians(150)
    A = (mpf("0.12") * mpmath.cos(th), mpf("0.3") + mpf("0.12") * mpmath.sin(th))
    L = mpmath.hypot(*A)
    u, n = (A[0] / L, A[1] / L), (-A[1] / L, A[0] / L)
    w2 = 90 * 2 * mpmath.pi / 60
    vA = (-w2 * (A[1] - O2[1]), w2 * A[0])
    vs = vA[0] * u[0] + vA[1] * u[1]  # along the slot, outward +
    assert vs < 0
    normal, last = None, None
    for _ in range(50):
        ne = NewtonEuler(["crank", "block", "lever"], about={"block": A}, mp=True)
        ne.pin("O2", O2, "crank", "frame")
        ne.pin("A", A, "block", "crank")
        ne.along("N", A, n, "block", "lever")
        ne.pin("O4", O4, "lever", "frame")
        if normal is not None:  # the lever's friction on the block, against its sliding
            f = -mpf("0.1") * abs(normal) * mpmath.sign(vs)
            ne.known("block", (f * u[0], f * u[1]), A)
            ne.known("lever", (-f * u[0], -f * u[1]), A)
        ne.known("lever", c=mpf(-60))
        ne.couple("T", "crank", "frame")
        x = ne.solve()
        if last is not None and abs(last - x["T"]) < mpf(10) ** -30:
            break
        last, normal = x["T"], x["N"]
    sol = solve(load_scene(SLOT))
    f = sol.forces
    assert f.input_torque == pytest.approx(float(x["T"]), rel=REL)
    assert abs(f.guides[0].normal) == pytest.approx(float(abs(x["N"])), rel=REL)
    for name in ("O2", "A", "O4"):
        want = mpmath.hypot(x[name + ".x"], x[name + ".y"])
        assert _pin(sol, name) == pytest.approx(float(want), rel=REL)
    b = force_bounds(sol)
    assert b.contraction == 0.0  # the loads reproduced themselves
    assert max(b.pins.values()) < 1e-12 and b.effort < 1e-12
    # and each still bounds the error against the 40-digit solve
    assert abs(f.input_torque - float(x["T"])) <= b.effort * b.force * b.length
    for p in f.pins:  # the pivots' forces, on the crank and the lever by the frame
        if p.point in ("O2", "O4"):
            err = max(abs(float(p.force[k] - x[p.point + (".x", ".y")[k]])) for k in (0, 1))
            assert err <= b.pins[(p.point, p.on, p.by)] * b.force, p
    code, out, _ = _run(capsys, "solve", SLOT)
    assert code == 0 and "estimated error of the forces" not in out
    answers_ok = _run(capsys, "check", SLOT)[0] == 0
    assert answers_ok


# --- a punching press given the punch's stroke --------------------------------------------

PRESS = HERE / "flywheel" / "press_stroke_shear_strength.toml"


def test_press_with_the_punchs_stroke_by_the_books_formulas():
    """F = tau pi d t, E = F t / 2, the punching t / (2 s) of the cycle, dE_max = E (1 -
    t / (2 s)) = I (w1^2 - w2^2) / 2, written out at 30 digits."""
    mpmath.mp.dps = 30
    F = mpf(300e6) * mpmath.pi * mpf("0.03") * mpf("0.02")
    E = F * mpf("0.02") / 2
    dE = E * (1 - mpf(20) / (2 * 100))
    w1, w2 = (mpf(n) * 2 * mpmath.pi / 60 for n in (200, 180))
    inertia = 2 * dE / (w1**2 - w2**2)
    c = solve_cycle(cycle_from_text(PRESS.read_text(encoding="utf-8"), str(PRESS)))
    assert c.E_stroke == pytest.approx(float(E), rel=REL)
    assert c.power == pytest.approx(float(E / 5), rel=REL)
    assert c.dE_max == pytest.approx(float(dE), rel=REL)
    assert c.inertia == pytest.approx(float(inertia), rel=REL)
    assert c.mass == pytest.approx(float(inertia / mpf("0.36")), rel=REL)


def test_press_with_the_punchs_stroke_in_every_view(capsys, tmp_path):
    code, out, _ = _run(capsys, "solve", PRESS)
    assert code == 0 and "the punching t / (2 s) = 20 mm / (2 x 100 mm) of the cycle" in out
    assert _run(capsys, "steps", PRESS)[0] == 0
    assert _run(capsys, "draw", PRESS, "-o", tmp_path / "d.svg")[0] == 0
    assert _run(capsys, "page", PRESS, "-o", tmp_path / "p.html")[0] == 0
    answers = tmp_path / "a.toml"
    answers.write_text('[answers]\ndE_max = "5655 J"\n', encoding="utf-8")  # the whole hole's
    code, out, _ = _run(capsys, "check", PRESS, answers)
    assert code == 1 and "the whole energy of a hole taken for dE_max" in " ".join(out.split())
    for body, words in (
        ('energy = "6 kJ"\nholes_per_minute = 6\nstroke = 100\n', "needs the plate's thickness"),
        (
            'energy = "6 kJ"\nthickness = 20\nholes_per_minute = 6\nstroke = 100\n'
            'punching_time = "1 s"\n',
            "one of them",
        ),
        ('force = "300 kN"\nthickness = 20\nholes_per_minute = 6\nstroke = 5\n', "0 to 1"),
    ):
        f = tmp_path / "bad.toml"
        f.write_text("[press]\n" + body + '[flywheel]\nspeed = "200 rpm"\ncoefficient = 0.1\n')
        code, _, err = _run(capsys, "solve", f)
        assert code == 2 and words in err and err.count("\n") == 1, err


def test_wheel_rolling_on_the_floor_centres_by_kennedy():
    """The point of contact is the wheel's centre with the floor (no slip); the rest by
    Kennedy's theorem and the angular-velocity-ratio theorem, by hand geometry."""
    mpmath.mp.dps = 40
    sol, ic = _centres(HERE / "centres_wheel_rolling_crank_rod.toml")
    O, th = (mpf(0), mpf(150)), mpmath.radians(120)
    A = (80 * mpmath.cos(th), 150 + 80 * mpmath.sin(th))
    C = (A[0] + mpmath.sqrt(300**2 - (A[1] - 100) ** 2), mpf(100))
    I14 = (C[0], mpf(0))
    I13 = _meet(O, A, I14, C)  # I12 I23; I14 I34
    I24 = _meet(O, I14, A, C)  # I12 I14; I23 I34
    for (i, j), want in {(1, 4): I14, (1, 3): I13, (2, 4): I24}.items():
        _close(_at(ic, i, j), want, 1000)
    w2 = -100 * 2 * mpmath.pi / 60
    side = 1 if (I24[0] - O[0]) * (I24[0] - I14[0]) > 0 else -1
    w4 = w2 * _dist(I24, O) / _dist(I24, I14) * side
    assert sol.W["CP"] == pytest.approx(float(w4), rel=REL)
    assert math.hypot(*sol.V["P"]) == pytest.approx(float(abs(w4) * 200 / 1000), rel=REL)


def test_shaper_with_friction_at_the_ram_and_in_the_slot_against_the_matrix_method():
    """Five bodies (the crank, the block, the lever, PQ, the ram), 13 unknowns, the ram's
    guide's and the slot's friction against their sliding, repeated until it settles."""
    mpmath.mp.dps = 40
    O1, O2, th = (mpf(0), mpf(0)), (mpf(0), mpf("-0.3")), mpmath.radians(30)
    A = (mpf("0.12") * mpmath.cos(th), mpf("0.12") * mpmath.sin(th))
    L = _dist(A, O2)
    u = ((A[0] - O2[0]) / L, (A[1] - O2[1]) / L)
    n = (-u[1], u[0])
    P = (O2[0] + mpf("0.6") * u[0], O2[1] + mpf("0.6") * u[1])
    Q = (P[0] + mpmath.sqrt(mpf("0.2") ** 2 - (mpf("0.32") - P[1]) ** 2), mpf("0.32"))
    vA = (-A[1], A[0])  # the crank at 1 rad/s ccw
    vs = vA[0] * u[0] + vA[1] * u[1]  # the block along the slot, outward +
    wl = (vA[0] * n[0] + vA[1] * n[1]) / L
    vP = (-wl * (P[1] - O2[1]), wl * (P[0] - O2[0]))
    vQ = vP[0] + vP[1] / (Q[0] - P[0]) * (Q[1] - P[1])  # the ram along its guide
    NQ = NA = last = None
    for _ in range(100):
        ne = NewtonEuler(
            ["crank", "block", "lever", "PQ", "ram"], about={"block": A, "ram": Q}, mp=True
        )
        ne.pin("O1", O1, "crank", "frame")
        ne.pin("A", A, "block", "crank")
        ne.along("NA", A, n, "block", "lever")
        ne.pin("O2", O2, "lever", "frame")
        ne.pin("P", P, "PQ", "lever")
        ne.pin("Q", Q, "PQ", "ram")
        ne.along("NQ", Q, (0, 1), "ram", "frame")
        ne.known("ram", (mpf(3000), 0), Q)
        if NQ is not None:
            f = -mpf("0.1") * abs(NQ) * mpmath.sign(vQ)
            ne.known("ram", (f, 0), Q)
            g = -mpf("0.1") * abs(NA) * mpmath.sign(vs)
            ne.known("block", (g * u[0], g * u[1]), A)
            ne.known("lever", (-g * u[0], -g * u[1]), A)
        ne.couple("T", "crank", "frame")
        x = ne.solve()
        if last is not None and abs(last - x["T"]) < mpf(10) ** -30:
            break
        last, NQ, NA = x["T"], x["NQ"], x["NA"]
    sol = solve(load_scene(HERE / "friction_static_shaper_ram_and_slot.toml"))
    f = sol.forces
    assert f.input_torque == pytest.approx(float(x["T"]), rel=REL)
    normals = {g.point: abs(g.normal) for g in f.guides}
    assert normals["Q"] == pytest.approx(float(abs(x["NQ"])), rel=REL)
    assert normals["A"] == pytest.approx(float(abs(x["NA"])), rel=REL)
    for name in ("O1", "O2", "P", "Q"):
        want = mpmath.hypot(x[name + ".x"], x[name + ".y"])
        assert _pin(sol, name) == pytest.approx(float(want), rel=REL)


# --- a flywheel given by its rim's speed alone ---------------------------------------------

RIM = HERE / "flywheel" / "press_rim_speed_alone.toml"


def test_flywheel_from_its_rims_speed_alone():
    """Khurmi's "the mean speed of the flywheel is 20 m/s": dE_max = I w^2 Cs = m (w R)^2
    Cs = m v^2 Cs, the radius and the shaft's speed not needed (30 digits)."""
    mpmath.mp.dps = 30
    E = 6 * mpmath.pi * 30 * 25  # J: 6 J per mm^2 of the sheared area pi d t
    dE = E * (1 - mpf(25) / (2 * 90))
    c = solve_cycle(cycle_from_text(RIM.read_text(encoding="utf-8"), str(RIM)))
    assert c.E_stroke == pytest.approx(float(E), rel=REL)
    assert c.power == pytest.approx(float(E / 8), rel=REL)
    assert c.dE_max == pytest.approx(float(dE), rel=REL)
    assert c.mass == pytest.approx(float(dE / (20**2 * mpf("0.04"))), rel=REL)
    assert c.inertia is None and c.speed is None and c.rim_radius is None  # not stated


def test_flywheel_from_its_rims_speed_alone_in_every_view(capsys, tmp_path):
    code, out, _ = _run(capsys, "solve", RIM)
    assert code == 0 and "rim's mass m = dE_max / (v^2 Cs) = 760.9 kg" in out
    assert "I and R need the shaft's speed" in out
    code, out, _ = _run(capsys, "steps", RIM)
    assert code == 0 and "m = 12174 / (20^2 x 0.04) = 760.9 kg." in out
    assert _run(capsys, "draw", RIM, "-o", tmp_path / "d.svg")[0] == 0
    assert _run(capsys, "page", RIM, "-o", tmp_path / "p.html")[0] == 0
    code, out, _ = _run(capsys, "solve", RIM, "--json")
    cyc = json.loads(out)["cycle"]
    assert cyc["speed"] is None and cyc["inertia"] is None and cyc["mass"] > 0
    answers = tmp_path / "a.toml"
    answers.write_text('[answers]\nm_flywheel = "1522 kg"\nI_flywheel = "10 kg m^2"\n')
    code, out, err = _run(capsys, "check", RIM, answers)  # I: nothing to check it against
    assert code == 2 and "I_flywheel" in err and err.count("\n") == 1
    answers.write_text('[answers]\nm_flywheel = "1522 kg"\n')  # Cs taken as +-4 %
    code, out, _ = _run(capsys, "check", RIM, answers)
    assert code == 1 and "range either side of the mean" in " ".join(out.split())
    bad = tmp_path / "bad.toml"  # a section needs the radius: the shaft's speed
    bad.write_text(RIM.read_text(encoding="utf-8").replace("[answers]", "width = 100\n[answers]"))
    code, _, err = _run(capsys, "solve", bad)
    assert code == 2 and "needs its radius" in err and err.count("\n") == 1


def test_a_large_correct_value_is_written_whole_as_a_book_writes_it(capsys):
    """The check table's correct value of five or six figures is the book's 50641 N, not
    5.0641e+04 N."""
    code, out, _ = _run(
        capsys, "check", HERE.parent.parent / "worked_problems" / "engine_forces.toml"
    )
    assert code == 0 and "50641 N (50.64 kN)" in out and "e+04" not in out


# --- an engine's efforts with friction at the crosshead guides -----------------------------

CROSSHEAD = HERE / "friction_engine_crosshead.toml"


def test_engine_efforts_with_crosshead_friction_by_the_closed_forms():
    """The piston's exact acceleration (OB = r cos t + sqrt(l^2 - r^2 sin^2 t) differentiated
    twice by mpmath at 50 digits; the books' w^2 r (cos t + cos 2t / n) is its first two
    terms), the rod a two-force member: along the stroke F_Q cos phi = F_L + F_I -+ mu F_Q
    sin phi, the friction against the piston's sliding (towards the crank here)."""
    mpmath.mp.dps = 50
    r, n, t = mpf("0.25"), mpf("4.4"), mpmath.radians(120)
    w, m, mu = 200 * 2 * mpmath.pi / 60, 180, mpf("0.08")
    F_L = mpf("0.6e6") * mpmath.pi / 4 * mpf("0.3") ** 2

    def ob(x):
        return r * mpmath.cos(x) + mpmath.sqrt((n * r) ** 2 - (r * mpmath.sin(x)) ** 2)

    a = w**2 * mpmath.diff(ob, t, 2)  # along OB, + away from the crank
    assert mpmath.diff(ob, t) < 0  # (the piston moves towards the crank)
    toward = F_L + m * a  # the gas force and the inertia force -m a, towards the crank
    phi = mpmath.asin(mpmath.sin(t) / n)
    # the piston moves towards the crank (past 0 < t < 180 deg, from the i.d.c.): the
    # friction on it acts away from the crank
    F_Q = toward / (mpmath.cos(phi) + mu * mpmath.sin(phi))
    want = {
        "piston_effort": F_Q * mpmath.cos(phi),
        "rod_thrust": F_Q,
        "side_thrust": F_Q * mpmath.sin(phi),
        "crank_effort": F_Q * mpmath.sin(t + phi),
        "turning_moment": F_Q * mpmath.sin(t + phi) * r,
    }
    sol = solve(load_scene(CROSSHEAD))
    e = efforts(sol.scene, sol.plan, sol.P, sol.forces)
    got = {
        "piston_effort": e.F_P,
        "rod_thrust": e.F_Q,
        "side_thrust": e.F_N,
        "crank_effort": e.F_T,
        "turning_moment": e.T,
    }
    for k, v in want.items():
        assert abs(got[k]) == pytest.approx(float(v), rel=REL), k
    # the driver's torque (the machine's resistance) is the turning moment's opposite:
    # the crank turns cw, the engine drives it cw, so the resisting torque is ccw
    assert sol.forces.input_torque == pytest.approx(float(want["turning_moment"]), rel=REL)


def test_engine_with_crosshead_friction_in_every_view(capsys, tmp_path):
    code, out, _ = _run(capsys, "solve", CROSSHEAD)
    assert code == 0 and "with the guide's friction 0.08 F_N against its sliding" in out
    assert _run(capsys, "steps", CROSSHEAD)[0] == 0
    assert _run(capsys, "draw", CROSSHEAD, "--forces", "-o", tmp_path / "f.svg")[0] == 0
    assert _run(capsys, "page", CROSSHEAD, "-o", tmp_path / "p.html")[0] == 0
    assert _run(capsys, "check", CROSSHEAD)[0] == 0
    answers = tmp_path / "a.toml"
    answers.write_text('[answers]\npiston_effort = "54.52 kN"\nturning_moment = "10.44 kN m"\n')
    code, out, _ = _run(capsys, "check", CROSSHEAD, answers)
    flat = " ".join(out.split())
    assert code == 1 and flat.count("matches the friction left out") == 2
    assert "(54523 N); the correct value is 53661 N" in flat  # whole, as the book writes it


# --- a multi-cylinder engine's areas, the first below the mean line -----------------------

BELOW = HERE / "flywheel" / "areas_starting_below.toml"


def test_areas_starting_below_the_mean_by_exact_running_sums(capsys):
    """The running sums of the book's whole mm^2, exactly (fractions), times the scales:
    dE_max, I and the rim; and no rounding noise where the areas come back to nought (the
    table read 'E - 2.3874e-12' at its end, and the words 'the areas add up to -2.387e-12
    J (the book's rounding), not nought')."""
    from fractions import Fraction

    mpmath.mp.dps = 30
    areas = [-30, 410, -280, 320, -330, 250, -360, 20]
    run = [sum(Fraction(a) for a in areas[:k]) for k in range(len(areas) + 1)]
    assert run[-1] == 0
    per = 600 * 3 * mpmath.pi / 180  # J per mm^2
    dE = (max(run) - min(run)) * per
    w = 300 * 2 * mpmath.pi / 60
    inertia = dE / (w**2 * mpf("0.03"))
    sc = cycle_from_text(BELOW.read_text(encoding="utf-8"), str(BELOW))
    c = solve_cycle(sc)
    assert c.dE_max == pytest.approx(float(dE), rel=REL)
    assert c.inertia == pytest.approx(float(inertia), rel=REL)
    assert c.mass == pytest.approx(float(inertia / mpf("0.49")), rel=REL)
    assert [x.energy for x in c.crossings] == pytest.approx([float(r * per) for r in run], rel=REL)
    assert c.crossings[-1].energy == 0.0  # back to E, exactly
    for cmd in ("solve", "steps"):
        code, out, _ = _run(capsys, cmd, BELOW)
        assert code == 0 and "e-1" not in out and "add up to" not in out
    code, out, _ = _run(capsys, "steps", BELOW)
    assert out.split("h     a")[1].split("\n")[0].rstrip().endswith("E")
