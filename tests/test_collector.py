"""A large plan's one instant runs with the cyclic garbage collector held off
(``solver/collector.py``): the numbers are those of the phased road and close every link,
no collection runs while the steps do, and the collector's setting is given back as it was,
after a solve that fails too."""

from __future__ import annotations

import gc
import math

import pytest

from polygon_method import parse_scene, solve
from polygon_method.common.errors import AssemblyError
from polygon_method.solver.collector import HELD_OFF_ABOVE, held_off
from polygon_method.solver.compiler import compile_plan
from polygon_method.solver.plan import Context

DYADS = 2 * HELD_OFF_ABOVE  # a plan of 2 * HELD_OFF_ABOVE + 1 steps: held off


def chain(n, last_ground=None):
    """A crank G0-P0, then n dyads: P(i) joined to P(i-1) and to ground G(i)."""
    grounds = [f"G{i} = [{100 * i}, 0]" for i in range(n + 1)]
    if last_ground is not None:
        grounds[-1] = f"G{n} = [{last_ground}, 0]"
    lines = ["[ground]", *grounds, "[links]", "G0P0 = 100"]
    for i in range(1, n + 1):
        lines += [f"P{i - 1}P{i} = 100", f"G{i}P{i} = 100"]
    lines += ["[input]", 'crank = "G0P0"', "angle = 80", 'speed = "10 rad/s ccw"']
    return parse_scene("\n".join(lines) + "\n")


def test_a_long_chain_is_held_off_and_a_textbook_plan_is_not():
    big = compile_plan(chain(DYADS))
    assert len(big.bind_instant(big.dims)) > HELD_OFF_ABOVE
    assert len(big.bind_own_instant()) == 1  # one function running them all
    small = compile_plan(chain(3))
    assert small.bind_own_instant() == small.instant_steps
    assert len(small.instant_steps) == 4  # each step's own function, as before


def test_the_held_off_solve_closes_every_link_and_is_the_phased_road_to_the_bit():
    scene = chain(DYADS)
    sol = solve(scene)
    plan = compile_plan(scene)
    inp = scene.input
    m = plan.run(Context(inp.angle, inp.omega, inp.alpha), plan.dims)
    for mine, theirs in ((sol.P, m.P), (sol.V, m.V), (sol.A, m.A), (sol.W, m.W), (sol.Al, m.Al)):
        assert mine == theirs and list(mine) == list(theirs)  # values and order
    assert sol.cond == m.cond
    # loop closure, independent of both roads: every link keeps its length, and the two ends
    # of a link have no relative velocity along it
    P, V = sol.P, sol.V
    links = [("G0", "P0")] + [
        (a, f"P{i}") for i in range(1, DYADS + 1) for a in (f"P{i - 1}", f"G{i}")
    ]
    for a, b in links:
        (ax, ay), (bx, by) = P[a], P[b]
        assert math.isclose(math.hypot(bx - ax, by - ay), 0.1, rel_tol=1e-9)  # 100 mm
        along = (V[b][0] - V[a][0]) * (bx - ax) + (V[b][1] - V[a][1]) * (by - ay)
        speed = max(math.hypot(*V[a]), math.hypot(*V[b]))
        assert abs(along) <= 1e-9 * 0.1 * speed


def test_every_step_runs_with_the_collector_off_and_it_is_on_again_after():
    seen = []

    def step(m):
        seen.append(gc.isenabled())
        m.append(len(seen))

    (held,) = held_off((step,) * (HELD_OFF_ABOVE + 1))
    done = []
    held(done)
    assert seen == [False] * (HELD_OFF_ABOVE + 1) and gc.isenabled()
    assert done == list(range(1, HELD_OFF_ABOVE + 2))  # each function once, in order

    def fails(m):
        raise AssemblyError("no crossing")

    (held,) = held_off((step,) * HELD_OFF_ABOVE + (fails,))
    seen.clear()
    with pytest.raises(AssemblyError):
        held([])
    assert seen == [False] * HELD_OFF_ABOVE and gc.isenabled()
    assert held_off((step,) * HELD_OFF_ABOVE) == (step,) * HELD_OFF_ABOVE  # not held


def test_the_collector_is_given_back_as_it_was():
    scene = chain(DYADS)
    assert gc.isenabled()
    solve(scene)
    assert gc.isenabled()
    gc.disable()
    try:
        solve(scene)
        assert not gc.isenabled()  # a program that runs with it off keeps it off
    finally:
        gc.enable()


def test_a_failing_long_chain_gives_the_collector_back():
    # the last dyad's ground point 1000 from the one before: its links of 100 cannot reach
    scene = chain(DYADS, last_ground=100 * DYADS + 1000)
    with pytest.raises(AssemblyError):
        solve(scene)
    assert gc.isenabled()
