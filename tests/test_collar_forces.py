"""Forces on a collar sliding along a turning rod: driving (the inverted slider crank driven
by its sliding) and as the second input beside a crank, against independent references:

- the matrix method at 50 digits: every moving body's Newton-Euler equations (D'Alembert:
  the inertia force at G, the couple -I alpha, the weights, the loads) as one linear system
  in every pin force, each guide's normal force and couple, the collar drivers' forces
  along their rods and a crank's torque, on the 50-digit constraint solve's kinematics
  (``tests/reference.py``), not the tool's;
- the virtual power with inertia: the collar driver's force times the collar's sliding
  relative to its rod (from the tool's velocities, the rod's point under the collar found
  here), plus every load's and weight's power, equals the rate of the kinetic energy, to
  1e-9, at one instant and at every place of a sweep over the collar's travel;
- with friction, the same balance with the friction's power (never positive), the friction
  at the collar along the rod against its sliding.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import mpmath
import numpy as np
import pytest
from mpmath import mpf

from newton_euler import NewtonEuler
from reference import reference_solution
from polygon_method.forces import FRAME, analyse
from polygon_method.motion.solution import solve
from polygon_method.motion.sweeps import sweep
from polygon_method.scene import parse_scene

ROOT = Path(__file__).resolve().parent.parent

DRIVING = """
title = "collar driven along a turning rod, with masses"
units = "mm"
[ground]
O = [0, 0]
D = [300, 0]
[links]
OA = 500
DC = 150
AB = 400
[sliders]
C = { along = "O-A" }
B = { path = "horizontal", through = "O" }
[assembly]
C = "above"
B = "right"
[masses]
OA = { mass = "4 kg", distances = { O = 260, A = 250 }, turn = "ccw", gyration = 150 }
DC = { mass = "1.5 kg", along = 60, from = "D", gyration = 50 }
AB = { mass = "3 kg", distances = { A = 190, B = 230 }, turn = "cw", gyration = 120 }
C = { mass = "0.8 kg" }
B = { mass = "2.5 kg" }
[gravity]
direction = 250
[loads]
B = { force = [-300, 40] }
AB = { torque = "12 N m ccw" }
[input]
block = "C"
s_C = 350
vs_C = "1.5 m/s outward"
as_C = "4 m/s^2 towards O"
"""

SECOND = """
title = "collar sliding along a turning rod (two inputs), with masses"
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 1000
CB = 600
[sliders]
C = { along = "O-A" }
B = { path = "horizontal", through = "O" }
[assembly]
B = "right"
[masses]
OA = { mass = "6 kg", distances = { O = 480, A = 530 }, turn = "cw", gyration = 300 }
CB = { mass = "3 kg", along = 250, from = "C", gyration = 170 }
C = { mass = "1.2 kg" }
B = { mass = "2 kg" }
[gravity]
direction = 280
[loads]
B = { force = [150, -60] }
OA = { torque = "20 N m cw" }
[input]
crank = "OA"
angle = 40
speed = "3 rad/s ccw"
acceleration = "2 rad/s^2 cw"
[input.second]
block = "C"
s_C = 500
vs_C = "2 m/s outward"
as_C = "1 m/s^2 outward"
"""


def _mp(p):
    return (mpf(p[0]), mpf(p[1]))


def _matrix(sc, ref, pins, guides, torque, extra=()):
    """The matrix method at the current precision: ``pins`` (point, on, by) each two
    unknowns (the force on ``on`` by ``by``; ``by`` feels it back), ``guides`` (point,
    block, guide body, unit along the guide, driven) each the normal force along
    perp(unit) and the guide's couple on the block (and a driven collar's force along the
    unit), the guide's body feeling them back; ``torque``: the body a driver's torque
    turns, or None; ``extra``: more known loads, (body, force, point) or (body, couple).
    Moments about the origin. Returns the solution by name."""
    P, Acc, Al = ref["positions"], ref["accelerations"], ref["alpha"]

    def pos(n):
        return P[n] if n in P else _mp(sc.ground[n])

    def acc(n):
        return Acc[n] if n in Acc else (mpf(0), mpf(0))

    bodies = sorted(
        {b for p in pins for b in p[1:] if b != FRAME}
        | {b for g in guides for b in g[1:3] if b != FRAME}
    )
    ne = NewtonEuler(bodies, mp=True)
    for k, (point, on, by) in enumerate(pins):
        ne.pin(f"pin{k}", pos(point), on, by)
    for point, bl, gb, u, driven in guides:
        ne.along(f"N {point}", pos(point), (-u[1], u[0]), bl, gb)
        ne.couple(f"M {point}", bl, gb)
        if driven:
            ne.along(f"F {point}", pos(point), u, bl, gb)
    if torque is not None:
        ne.couple("T", torque)
    known = ne.known
    g = sc.gravity
    for m in sc.masses:
        if m.block:
            body, G, a, al = f"block {m.body}", pos(m.body), acc(m.body), mpf(0)
        else:
            lk = sc.link(m.body)
            lam, mu = mpf(m.lam), mpf(m.mu)

            def at(T, lk=lk, lam=lam, mu=mu):
                (px, py), (qx, qy) = T(lk.p), T(lk.q)
                dx, dy = qx - px, qy - py
                return (px + lam * dx - mu * dy, py + lam * dy + mu * dx)

            body, G, a, al = lk.key, at(pos), at(acc), Al[lk.key]
        mass = mpf(m.mass)
        W = (mass * mpf(g.g) * mpf(g.direction[0]), mass * mpf(g.g) * mpf(g.direction[1]))
        known(body, (W[0] - mass * a[0], W[1] - mass * a[1]), G, -mpf(m.inertia) * al)
    for ld in sc.loads:
        if ld.force is not None:
            body = f"block {ld.target}"  # a block's, else the moving link's at that point
            if body not in bodies:
                body = next(
                    lk.key for lk in sc.links if ld.target in lk.points and lk.key in bodies
                )
            known(body, _mp(ld.force), pos(ld.target))
        else:
            known(sc.link(ld.target).key, (0, 0), (0, 0), mpf(ld.torque))
    for it in extra:
        if it[0] != FRAME:
            known(*it) if len(it) == 3 else known(it[0], (0, 0), (0, 0), it[1])
    x = ne.solve()
    out = {pin: list(ne.vector(x, f"pin{k}")) for k, pin in enumerate(pins)}
    for point, *_, driven in guides:
        out[("N", point)], out[("M", point)] = x[f"N {point}"], x[f"M {point}"]
        if driven:
            out[("F", point)] = x[f"F {point}"]
    if torque is not None:
        out[("T",)] = x["T"]
    return out


def _unit(P, a, b):
    dx, dy = P[b][0] - P[a][0], P[b][1] - P[a][1]
    d = mpmath.sqrt(dx * dx + dy * dy)
    return (dx / d, dy / d)


@pytest.fixture
def digits():
    saved = mpmath.mp.dps
    mpmath.mp.dps = 50  # (the reference constraint solve polishes to 50 digits)
    yield
    mpmath.mp.dps = saved


def _compare(f, want, scale):
    """Every pin force, normal force, collar force and torque of ``f`` against the matrix
    method's, to 1e-9 of the largest force (a torque of it times ``scale``, m)."""
    big = max(float(mpmath.sqrt(v[0] ** 2 + v[1] ** 2)) for k, v in want.items() if len(k) == 3)
    for k, v in want.items():
        if len(k) == 3:  # a pin (point, on, by)
            got = f.pin(*k)
            assert math.hypot(got[0] - float(v[0]), got[1] - float(v[1])) <= 1e-9 * big, k
    for g in f.guides:
        assert abs(g.normal - float(want[("N", g.point)])) <= 1e-9 * big, g.point
        assert abs(float(want[("M", g.point)])) <= 1e-20 * big  # the guides hold no couple
    return big


def test_a_driving_collar_against_the_matrix_method(digits):
    sc = parse_scene(DRIVING)
    sol = solve(sc)
    f = sol.forces
    ref = reference_solution(sc, sol.P)
    P = ref["positions"]
    P.update({k: _mp(v) for k, v in sc.ground.items()})
    want = _matrix(
        sc,
        ref,
        [
            ("O", "OA", FRAME),
            ("D", "DC", FRAME),
            ("C", "DC", "block C"),
            ("A", "AB", "OA"),
            ("B", "AB", "block B"),
        ],
        [
            ("C", "block C", "OA", _unit(P, "O", "A"), True),
            ("B", "block B", FRAME, (mpf(1), mpf(0)), False),
        ],
        None,
    )
    big = _compare(f, want, 0.5)
    assert f.driver == "collar" and f.crank == "block C"
    assert abs(f.input_torque - float(want[("F", "C")])) <= 1e-9 * big
    g = next(g for g in f.guides if g.point == "C")
    assert g.by == "OA"
    d = json.loads(json.dumps(sol.to_dict()))["forces"]
    assert d["input_force"] == f.input_torque and d["collar"] == "block C"


def test_a_second_collar_against_the_matrix_method(digits):
    sc = parse_scene(SECOND)
    sol = solve(sc)
    f = sol.forces
    ref = reference_solution(sc, sol.P)
    P = ref["positions"]
    P.update({k: _mp(v) for k, v in sc.ground.items()})
    want = _matrix(
        sc,
        ref,
        [("O", "OA", FRAME), ("C", "CB", "block C"), ("B", "CB", "block B")],
        [
            ("C", "block C", "OA", _unit(P, "O", "A"), True),
            ("B", "block B", FRAME, (mpf(1), mpf(0)), False),
        ],
        "OA",
    )
    big = _compare(f, want, 1.0)
    assert abs(f.input_torque - float(want[("T",)])) <= 1e-9 * big * 1.0
    assert f.second_crank == "block C"
    assert abs(f.second_torque - float(want[("F", "C")])) <= 1e-9 * big
    d = json.loads(json.dumps(sol.to_dict()))["forces"]
    assert d["second"] == {"block": "block C", "collar": True, "input_force": f.second_torque}


def _sliding(sc, sol, name):
    """The collar's sliding along its rod relative to the rod, and the rod's unit
    direction, from the positions and velocities (the rod's point under the collar moves
    at omega x KC, K its fixed pivot)."""
    rod = sc.link(sc.slider(name).guide)
    K = rod.p if rod.p in sc.ground else rod.q
    (kx, ky), (nx, ny), (cx, cy) = sol.P[K], sol.P[rod.other(K)], sol.P[name]
    L = np.hypot(nx - kx, ny - ky)
    wx, wy = (nx - kx) / L, (ny - ky) / L
    om = sol.W[rod.key]
    vx, vy = sol.V[name][0] + om * (cy - ky), sol.V[name][1] - om * (cx - kx)
    return vx * wx + vy * wy


def _power_terms(sc, sol, f):
    """Every power of the balance: the drivers', the loads', the weights', the inertia's
    (-m a_G . v_G - I alpha omega, G's motion from its link's ends) and the friction's."""
    inp = sc.input
    terms = []
    if f.driver == "collar":
        terms.append(f.input_torque * _sliding(sc, sol, inp.block))
    else:
        terms.append(f.input_torque * sol.W[sc.link(inp.crank).key])
    if inp.second is not None:
        terms.append(f.second_torque * _sliding(sc, sol, inp.second.block))
    for ld in sc.loads:
        if ld.force is not None:
            v = sol.V[ld.target]
            terms.append(ld.force[0] * v[0] + ld.force[1] * v[1])
        else:
            terms.append(ld.torque * sol.W[sc.link(ld.target).key])
    g = sc.gravity
    for m in sc.masses:
        if m.block:
            v, a, al, w = sol.V[m.body], sol.A[m.body], 0.0, 0.0
        else:
            lk = sc.link(m.body)

            def at(T, lk=lk, m=m):
                (px, py), (qx, qy) = T[lk.p], T[lk.q]
                dx, dy = qx - px, qy - py
                return (px + m.lam * dx - m.mu * dy, py + m.lam * dy + m.mu * dx)

            v, a, al, w = at(sol.V), at(sol.A), sol.Al[lk.key], sol.W[lk.key]
        terms.append(m.mass * g.g * (g.direction[0] * v[0] + g.direction[1] * v[1]))
        terms.append(-m.mass * (a[0] * v[0] + a[1] * v[1]))
        terms.append(-m.inertia * al * w)
    terms.append(f.friction_power)
    return terms


@pytest.mark.parametrize("text", [DRIVING, SECOND], ids=["driving", "second"])
def test_virtual_power_with_inertia(text):
    sc = parse_scene(text)
    sol = solve(sc)
    terms = _power_terms(sc, sol, sol.forces)
    assert abs(sum(terms)) <= 1e-9 * sum(abs(t) for t in terms)
    assert abs(terms[0]) > 1e-3 * sum(abs(t) for t in terms)  # the driver does work


@pytest.mark.parametrize("text", [DRIVING, SECOND], ids=["driving", "second"])
def test_virtual_power_at_every_place_of_a_sweep(text):
    """The vectorised forces over the collar's travel (or the crank's turn, the collar
    sliding with it, as far as it stays on its rod): the balance at every place."""
    sc = parse_scene(text)
    res = sweep(sc, None if sc.input.block else np.radians(np.arange(3.0, 360.0, 7.0)))
    f = analyse(res)
    terms = _power_terms(sc, res, f)
    total = sum(terms)
    scale = sum(np.abs(t) for t in terms)
    fine = np.ones(len(res), dtype=bool)
    for st in f.steps:
        fine &= np.broadcast_to(st.condition, fine.shape) > 1e-6
    assert fine.sum() >= 12
    assert np.all((np.abs(total) <= 1e-9 * scale)[fine])


@pytest.mark.parametrize("base", [DRIVING, SECOND], ids=["driving", "second"])
def test_friction_at_the_collar_works_against_its_sliding(base):
    """With friction at the guides and the pins the balance holds with the friction's
    power; the friction along the rod opposes the collar's sliding on it, mu |N|."""
    text = base.replace("[input]\n", "[friction]\nguides = 0.15\npins = 0.1\n[input]\n", 1)
    text = text.replace(
        "[sliders]",
        "[pins]\nC = { radius = 10 }\nO = { radius = 20 }\nB = { radius = 12 }\n[sliders]",
    )
    sc = parse_scene(text)
    sol = solve(sc)
    f = sol.forces
    terms = _power_terms(sc, sol, f)
    assert f.friction_power < 0
    assert abs(sum(terms)) <= 1e-9 * sum(abs(t) for t in terms)
    g = next(g for g in f.guides if g.point == "C")
    fr = next(it for it in f.friction if it[0] == "block C")
    wx, wy = g.n[1], -g.n[0]
    along = fr[2][0] * wx + fr[2][1] * wy
    assert abs(abs(along) - 0.15 * abs(g.normal)) <= 1e-12 * abs(g.normal)
    assert along * _sliding(sc, sol, "C") < 0
    frictionless = solve(parse_scene(base)).forces
    assert f.input_torque != frictionless.input_torque
    assert f.second_torque != frictionless.second_torque or sc.input.second is None


def test_the_words_and_steps_of_a_collar(tmp_path, capsys):
    from polygon_method.cli import main

    for text, words in (
        (DRIVING, "input force on collar C along OA (inertia, weights and loads): "),
        (SECOND, "input force on collar C (the second input) along OA (inertia, "),
    ):
        path = tmp_path / "collar.toml"
        path.write_text(text)
        assert main(["solve", str(path)]) == 0
        out = capsys.readouterr().out
        assert words in out and "not solved for forces" not in out
        assert main(["steps", str(path)]) == 0
        out = capsys.readouterr().out
        assert "the collar: " in out or "moments of OA about O" in out


def test_the_worked_collar_and_its_written_answers(digits):
    """worked_problems/collar_forces.toml against the 9 x 9 matrix method: the tool to
    1e-9, the file's written answers (and the screw's force in its comment) to their four
    figures."""
    from polygon_method.scene import load_scene

    sc = load_scene(ROOT / "worked_problems" / "collar_forces.toml")
    sol = solve(sc)
    f = sol.forces
    ref = reference_solution(sc, sol.P)
    P = ref["positions"]
    P.update({k: _mp(v) for k, v in sc.ground.items()})
    want = _matrix(
        sc,
        ref,
        [("O", "OA", FRAME), ("D", "DC", FRAME), ("C", "DC", "block C")],
        [("C", "block C", "OA", _unit(P, "O", "A"), True)],
        None,
    )
    big = _compare(f, want, 0.8)
    assert abs(f.input_torque - float(want[("F", "C")])) <= 1e-9 * big
    import tomllib

    size = {k[0]: float(mpmath.sqrt(v[0] ** 2 + v[1] ** 2)) for k, v in want.items() if len(k) == 3}
    size["N_C"] = abs(float(want[("N", "C")]))
    answers = tomllib.loads((ROOT / "worked_problems" / "collar_forces.toml").read_text())[
        "answers"
    ]
    for key in ("F_O", "F_D", "F_C", "N_C"):
        value = float(answers[key].split()[0])
        assert abs(size[key if key == "N_C" else key[2:]] - value) <= 5e-4 * value, key
    assert abs(float(want[("F", "C")]) + 117.1) <= 5e-4 * 117.1  # towards O (the comment's)


def test_the_bounds_hold_and_grow_towards_the_dead_centre(digits):
    """The driving collar's forces near its dead centre (the rod's line through D, s_C ->
    OD + DC = 450 mm) against the 50-digit matrix method: each within its stated bound,
    the bound growing as the dead centre nears (its condition 0.64 to 0.030, the driver's
    force 490 N to 58 MN)."""
    from polygon_method.forces.bounds import force_bounds

    worst = []
    for s in (400.0, 440.0, 449.0, 449.9):
        sc = parse_scene(DRIVING.replace("s_C = 350", f"s_C = {s}"))
        sol = solve(sc)
        f, b = sol.forces, force_bounds(sol)
        ref = reference_solution(sc, sol.P)
        P = ref["positions"]
        P.update({k: _mp(v) for k, v in sc.ground.items()})
        want = _matrix(
            sc,
            ref,
            [
                ("O", "OA", FRAME),
                ("D", "DC", FRAME),
                ("C", "DC", "block C"),
                ("A", "AB", "OA"),
                ("B", "AB", "block B"),
            ],
            [
                ("C", "block C", "OA", _unit(P, "O", "A"), True),
                ("B", "block B", FRAME, (mpf(1), mpf(0)), False),
            ],
            None,
        )
        for key, e in b.pins.items():
            got, w = f.pin(*key), want[key]
            err = float(mpmath.sqrt((got[0] - w[0]) ** 2 + (got[1] - w[1]) ** 2))
            assert err <= e * b.force, (s, key, err / b.force, e)
        for g in f.guides:
            assert abs(float(g.normal - want[("N", g.point)])) <= b.guides[g.point] * b.force
        assert abs(float(f.input_torque - want[("F", "C")])) <= b.effort * b.force
        worst.append(b.worst)
    assert all(later > 3 * earlier for earlier, later in zip(worst, worst[1:])), worst


@pytest.mark.parametrize("text", [DRIVING, SECOND], ids=["driving", "second"])
def test_the_collars_force_polygon(digits, text):
    """The collar's force polygon (its known forces, DC's pin force on it where DC holds
    it, its driver's force along the rod, the rod's normal force across it): each found
    side the matrix method's force, the unknowns' lines along their sides, closed to 1e-9
    of its largest side."""
    sc = parse_scene(text)
    sol = solve(sc)
    f = sol.forces
    ref = reference_solution(sc, sol.P)
    P = ref["positions"]
    P.update({k: _mp(v) for k, v in sc.ground.items()})
    w = _unit(P, "O", "A")
    guides = [
        ("C", "block C", "OA", w, True),
        ("B", "block B", FRAME, (mpf(1), mpf(0)), False),
    ]
    if sc.input.block:
        pins = [
            ("O", "OA", FRAME),
            ("D", "DC", FRAME),
            ("C", "DC", "block C"),
            ("A", "AB", "OA"),
            ("B", "AB", "block B"),
        ]
        want = _matrix(sc, ref, pins, guides, None)
    else:
        pins = [("O", "OA", FRAME), ("C", "CB", "block C"), ("B", "CB", "block B")]
        want = _matrix(sc, ref, pins, guides, "OA")
    st = next(s for s in f.steps if s.kind in ("collar", "second collar"))
    poly = st.polygon
    big = max(math.hypot(*sd.vector) for sd in poly)
    assert math.hypot(sum(sd.vector[0] for sd in poly), sum(sd.vector[1] for sd in poly)) <= (
        1e-9 * big
    )
    N, F = want[("N", "C")], want[("F", "C")]
    expect = {
        "driver": (F * w[0], F * w[1]),
        "guide": (-N * w[1], N * w[0]),
    }
    if sc.input.block:  # DC's pin force on the collar: the opposite of the collar's on DC
        expect["pin"] = tuple(-c for c in want[("C", "DC", "block C")])
    for sd in poly:
        if sd.what in expect:
            e = expect.pop(sd.what)
            assert math.hypot(sd.vector[0] - float(e[0]), sd.vector[1] - float(e[1])) <= (
                1e-9 * big
            ), sd.what
    assert expect == {}
    for k, (dx, dy) in st.unknown:
        vx, vy = poly[k].vector
        assert abs(vx * dy - vy * dx) <= 1e-9 * big and poly[k].what in ("driver", "guide")
    if sc.input.block:  # the rod's and DC's polygons beside the collar's
        _the_rod_and_link_polygons(sc, st, ref, want, w)


def _known_side(sc, ref, sd):
    """An inertia force, a weight or a load on a body, from the scene and the 50-digit
    kinematics."""
    if sd.what == "load":
        return _mp(next(ld.force for ld in sc.loads if ld.target == sd.point))
    m = next(m for m in sc.masses if (f"block {m.body}" if m.block else m.body) == sd.on)
    mass, g = mpf(m.mass), sc.gravity
    if sd.what == "weight":
        return (mass * mpf(g.g) * mpf(g.direction[0]), mass * mpf(g.g) * mpf(g.direction[1]))
    A = ref["accelerations"]

    def acc(n):
        return A[n] if n in A else (mpf(0), mpf(0))

    if m.block:
        a = acc(m.body)
    else:
        lk = sc.link(m.body)
        (px, py), (qx, qy) = acc(lk.p), acc(lk.q)
        lam, mu = mpf(m.lam), mpf(m.mu)
        a = (px + lam * (qx - px) - mu * (qy - py), py + lam * (qy - py) + mu * (qx - px))
    return (-mass * a[0], -mass * a[1])


def _the_rod_and_link_polygons(sc, st, ref, want, w):
    """The driving collar's rod OA (its known forces, the collar's push and the driver's
    force back at C, the frame's at O closing it) and link DC (the collar's force on it,
    its known forces, the frame's at D closing it): every side the matrix method's force
    (or the scene's and the 50-digit kinematics' inertia, weight, load), each closed."""
    polys = st.polygons
    assert [pg.bodies for pg in polys] == [("block C",), ("OA",), ("DC",)]
    N, F = want[("N", "C")], want[("F", "C")]
    for pg in polys[1:]:
        sides = pg.polygon
        big = max(math.hypot(*sd.vector) for sd in sides)
        assert math.hypot(sum(sd.vector[0] for sd in sides), sum(sd.vector[1] for sd in sides)) <= (
            1e-9 * big
        )
        for sd in sides:
            if sd.what in ("inertia", "weight", "load"):
                e = _known_side(sc, ref, sd)
            elif sd.what == "guide":  # the collar's push on the rod across it
                e = (N * w[1], -N * w[0])
            elif sd.what == "driver":  # the driver's force back on the rod
                e = (-F * w[0], -F * w[1])
            elif (sd.point, sd.on, sd.by) in want:
                e = want[(sd.point, sd.on, sd.by)]
            else:
                e = tuple(-c for c in want[(sd.point, sd.by, sd.on)])
            got = sd.vector
            assert math.hypot(got[0] - float(e[0]), got[1] - float(e[1])) <= 1e-9 * big, sd
