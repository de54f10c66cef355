"""The one-instant road (each step's position, velocity and acceleration fused into one
plain float function, ``bind_instant``) against the phased road (all positions, then all
velocities, then all accelerations, each phase calling the kind's module-level formulas):
a second way of computing the same numbers, which must agree to the last bit on random
mechanisms, not only on the worked problems."""

from __future__ import annotations

import math

import numpy as np
import pytest

from polygon_method import parse_scene, solve
from polygon_method.solver.compiler import compile_plan
from polygon_method.solver.plan import Context, State
from polygon_method.steps import Carried

SCENE = """
[ground]
A = [0, 0]
D = [{d!r}, 0]
[links]
AB = {a!r}
BC = {b!r}
CD = {c!r}
[points]
E = {{ on = "BC", along = {along!r} }}
F = {{ on = "BC", distances = {{ B = {fb!r}, C = {fc!r} }}, turn = "{turn}" }}
G = {{ on = "CD", along = 0 }}
H = {{ on = "CD", distances = {{ C = {gc!r}, D = {gd!r} }}, turn = "ccw" }}
[input]
crank = "AB"
angle = {angle!r}
speed = "{omega!r} rad/s {sense}"
acceleration = "{alpha!r} rad/s^2 ccw"
[pins]
A = {{ radius = 10 }}
B = {{ radius = 12 }}
C = {{ radius = 9 }}
D = {{ radius = 11 }}
"""


def _fourbars(n, seed):
    """Four-bars that assemble at their crank angle, away from a toggle (the angle at C
    between CB and CD at least 3 degrees): C is drawn first, the lengths measured."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        d = float(rng.uniform(50, 200))
        a = float(rng.uniform(10, 80))
        th = float(rng.uniform(0, 360))
        bx, by = a * math.cos(math.radians(th)), a * math.sin(math.radians(th))
        cx, cy = float(rng.uniform(-100, 300)), float(rng.uniform(-150, 150))
        b, c = math.hypot(cx - bx, cy - by), math.hypot(cx - d, cy)
        if min(b, c) < 5:
            continue
        sin_c = abs((bx - cx) * (-cy) - (by - cy) * (d - cx)) / (b * c)
        if sin_c < math.sin(math.radians(3)):
            continue
        fb, fc = float(rng.uniform(0.3, 1.5)) * b, float(rng.uniform(0.3, 1.5)) * b
        if not abs(fb - fc) < b < fb + fc:  # F's triangle must close
            continue
        gc = float(rng.uniform(0.2, 1.0)) * c
        gd = float(rng.uniform(0.2, 1.0)) * c + abs(c - gc)
        if not abs(gc - gd) < c < gc + gd:
            continue
        out.append(
            dict(
                d=d,
                a=a,
                b=b,
                c=c,
                angle=th,
                along=float(rng.uniform(-0.5, 1.5)) * b,
                fb=fb,
                fc=fc,
                gc=gc,
                gd=gd,
                turn=("cw", "ccw")[int(rng.integers(2))],
                omega=float(rng.uniform(0.5, 50)),
                sense=("cw", "ccw")[int(rng.integers(2))],
                alpha=float(rng.uniform(0, 500)),
            )
        )
    return out


@pytest.mark.parametrize("case", _fourbars(60, 22), ids=lambda c: f"{c['angle']:.0f}deg")
def test_a_random_four_bar_solves_to_the_last_bit_of_the_phased_road(case):
    scene = parse_scene(SCENE.format(**case))
    sol = solve(scene)
    plan = compile_plan(scene)
    assert [st.kind for st in plan.steps] == ["crank", "dyad"] + ["carried"] * 4
    inp = scene.input
    m = plan.run(Context(inp.angle, inp.omega, inp.alpha), plan.dims)
    for mine, theirs in (
        (sol.P, m.P),
        (sol.V, m.V),
        (sol.A, m.A),
        (sol.W, m.W),
        (sol.Al, m.Al),
        (sol.S, m.S),
    ):
        assert list(mine.items()) == list(theirs.items())  # the same order too
    # the conditions by step (a steady step's 1 is where a solve starts, not in step order)
    assert sol.cond == m.cond and set(sol.cond) == {st.index for st in plan.steps}


@pytest.mark.parametrize("lam, mu", [(0.0, 0.0), (0.0, -0.75), (0.4, 0.0), (1.3, 0.6)])
def test_points_carried_together_take_the_image_formula_term_by_term(lam, mu):
    """Points carried by the same two points are done in one function; each keeps the
    formula's terms that are not zero, as the phased road's ``_image`` does (a zero term
    left in would turn -0.0 into 0.0 or carry an inf into a nan)."""
    steps = (Carried(1, "X", "BC", "B", "C", lam, mu), Carried(2, "Y", "BC", "B", "C", mu, lam))
    prms = ((lam, mu), (mu, lam))

    def state():
        ctx = Context(0.0, 1.0, 0.0)
        return State(
            {"B": (-0.0, 1e300), "C": (3.0, -2.0)},
            {"B": (0.5, -0.0), "C": (-1.5, 2.5)},
            {"B": (-0.0, 7.0), "C": (2.0, -0.0)},
            {},
            {},
            {},
            ctx,
        )

    one, phased = state(), state()
    Carried.bind_group_instant(steps, prms)(one)
    for phase in Carried.bind_group(steps, prms):
        phase(phased)
    # a carried point is steady: its condition, 1, is where a plan's solve starts
    # (Plan.start_cond), not written by its one-instant function
    assert Carried.steady and one.cond == {} and phased.cond == {1: 1.0, 2: 1.0}
    for mine, theirs in ((one.P, phased.P), (one.V, phased.V), (one.A, phased.A)):
        assert list(mine.items()) == list(theirs.items())
        for k in mine:  # the sign of a zero too (== holds -0.0 equal to 0.0)
            assert [math.copysign(1.0, v) for v in mine[k]] == [
                math.copysign(1.0, v) for v in theirs[k]
            ]
