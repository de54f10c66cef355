"""The error bound of the forces with friction (the walk repeated until the friction
settles) against a converged 50-digit solve: the matrix method (every moving body's
Newton-Euler equations as one linear system, ``test_collar_forces._matrix``) on the
50-digit constraint solve's kinematics, with the friction of the forces found before as
known loads, repeated until the forces agree to 1e-40 (Coulomb friction at the guides,
``mu |N|`` against the sliding relative to the guide, and at the pins the friction
circle's couple ``mu r |F|`` against the relative turning, a block's passed to its guide).

The stated bound must hold and must not be absurdly loose: with the passes stopped early
(the settling threshold loosened, so that the passes not made are what the forces miss),
the bound is within 100 times the true error; at the tool's own threshold it holds.
"""

from __future__ import annotations

import mpmath
import pytest
from mpmath import mpf

from reference import reference_solution
from test_collar_forces import DRIVING, _matrix, _mp, _unit
from polygon_method.forces import FRAME, friction
from polygon_method.forces.bounds import force_bounds
from polygon_method.motion.solution import solve
from polygon_method.scene import parse_scene

MU_GUIDES, MU_PINS = mpf("0.15"), mpf("0.1")
RADII = {"C": 10, "D": 15, "O": 20, "A": 12, "B": 12}  # mm

SCENE = DRIVING.replace(
    "[input]",
    "[friction]\nguides = 0.15\npins = 0.1\n[pins]\n"
    + "".join(f"{k} = {{ radius = {r} }}\n" for k, r in RADII.items())
    + "[input]",
)

PINS = [
    ("O", "OA", FRAME),
    ("D", "DC", FRAME),
    ("C", "DC", "block C"),
    ("A", "AB", "OA"),
    ("B", "AB", "block B"),
]
GUIDE_OF = {"block C": "OA", "block B": FRAME}


@pytest.fixture
def digits():
    saved = mpmath.mp.dps
    mpmath.mp.dps = 50
    yield
    mpmath.mp.dps = saved


def _settled_reference(sc, sol):
    """The forces with friction at 50 digits, iterated until they settle to 1e-40."""
    ref = reference_solution(sc, sol.P)
    P, V, W = ref["positions"], ref["velocities"], ref["omega"]
    P.update({k: _mp(v) for k, v in sc.ground.items()})
    V.update({k: (mpf(0), mpf(0)) for k in sc.ground})
    u_rod = _unit(P, "O", "A")
    guides = [
        ("C", "block C", "OA", u_rod, True),
        ("B", "block B", FRAME, (mpf(1), mpf(0)), False),
    ]

    def omega(body):
        if body == FRAME:
            return mpf(0)
        if body.startswith("block "):
            return omega(GUIDE_OF[body])
        return W[body]

    def sliding(point, gb, u):
        vx, vy = V[point]
        if gb != FRAME:  # the rod's point under the collar (the rod turns about O)
            x, y = P[point][0] - P["O"][0], P[point][1] - P["O"][1]
            vx, vy = vx + W[gb] * y, vy - W[gb] * x
        return vx * u[0] + vy * u[1]

    extra, before = [], None
    for _ in range(200):
        want = _matrix(sc, ref, PINS, guides, None, extra)
        extra = []
        for point, bl, gb, u, _ in guides:
            fr = -MU_GUIDES * abs(want[("N", point)]) * mpmath.sign(sliding(point, gb, u))
            extra += [(bl, (fr * u[0], fr * u[1]), P[point])]
            extra += [(gb, (-fr * u[0], -fr * u[1]), P[point])]
        for point, on, by in PINS:
            F = want[(point, on, by)]
            r = mpf(RADII[point]) / 1000
            c = -MU_PINS * r * mpmath.sqrt(F[0] ** 2 + F[1] ** 2)
            c *= mpmath.sign(omega(on) - omega(by))
            extra += [(GUIDE_OF.get(on, on), c), (GUIDE_OF.get(by, by), -c)]
        now = [want[("F", "C")]] + [want[("N", g[0])] for g in guides]
        now += [c for p in PINS for c in want[p]]
        if before is not None and max(abs(a - b) for a, b in zip(now, before)) < mpf(10) ** -40:
            return want
        before = now
    raise AssertionError("the 50-digit friction passes do not settle")


def _errors(sol, want):
    """(relative error, its bound) of every pin force, normal force and the driver's force."""
    f = sol.forces
    b = force_bounds(sol)
    F = b.force
    out = []
    for p in PINS:
        got, w = f.pin(*p), want[p]
        err = float(mpmath.sqrt((got[0] - w[0]) ** 2 + (got[1] - w[1]) ** 2)) / F
        out.append((err, b.pins[p]))
    for g in f.guides:
        out.append((abs(float(g.normal - want[("N", g.point)])) / F, b.guides[g.point]))
    out.append((abs(float(f.input_torque - want[("F", "C")])) / F, b.effort))
    return out


def test_the_bound_holds_at_the_tools_own_threshold(digits):
    sc = parse_scene(SCENE)
    sol = solve(sc)
    assert sol.forces.settling and 0 < sol.forces.settling[0] < 1
    want = _settled_reference(sc, sol)
    for err, bound in _errors(sol, want):
        assert err <= bound, (err, bound)
    d = sol.to_dict()["error_bounds"]["forces"]
    assert d["friction_passes"] == {"contraction": sol.forces.settling[0]}


@pytest.mark.parametrize("threshold", [1e-5, 1e-8])
def test_the_bound_of_passes_stopped_early_holds_and_is_not_loose(digits, monkeypatch, threshold):
    sc = parse_scene(SCENE)
    exact = _settled_reference(sc, solve(sc))
    monkeypatch.setattr(friction, "SETTLED", threshold)
    sol = solve(parse_scene(SCENE))
    errors = _errors(sol, exact)
    worst = max(e for e, _ in errors)
    assert worst > 1e-4 * threshold  # the passes not made are what the forces miss
    for err, bound in errors:
        assert err <= bound, (err, bound)
    assert max(b for _, b in errors) <= 100 * worst
