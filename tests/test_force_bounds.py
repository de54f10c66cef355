"""The force analysis' error bounds against the 50-digit reference.

A four-bar driven towards its crank's limit position (its dyad's toggle): the kinematics at
50 digits by the independent constraint solve (``tests/reference.py``), the pin forces and
the torque by the matrix method (the three links' Newton-Euler equations as one 9 x 9
linear system) in mpmath at 50 digits. The tool's forces must lie within their bounds,
and the bounds must grow as the toggle nears (and be shown, in the text and the JSON).
"""

from __future__ import annotations

import json
import math

import mpmath
import numpy as np
import pytest
from mpmath import mpf

from newton_euler import NewtonEuler
from reference import reference_solution
from polygon_method.solver.errorbound import SHOWN
from polygon_method.forces import FRAME
from polygon_method.forces.bounds import NO_BOUND, ForceBounds, bounds_dict, force_bounds
from polygon_method.scene import parse_scene
from polygon_method.motion.solution import solve

TEXT = """
units = "m"
[ground]
O2 = [0, 0]
O4 = [0.2, 0]
[links]
"O2-A" = 0.1
"A-B" = 0.15
"B-O4" = 0.14
[assembly]
B = "above"
[input]
crank = "O2-A"
angle = %r
speed = "120 rpm ccw"
acceleration = "30 rad/s^2 cw"
[masses]
"O2-A" = { mass = "1 kg", along = 0.04 }
"A-B" = { mass = "3 kg", distances = { A = 0.06, B = 0.1 }, turn = "ccw", gyration = 0.05 }
"B-O4" = { mass = "2 kg", along = 0.07, gyration = 0.045 }
[gravity]
[loads]
B = { force = [40, -25] }
"""
#: the crank's limit: |O4 A| = AB + BO4 (0.29 m), A at 0.1 m from O2, O4 0.2 m away
LIMIT = math.degrees(math.acos(-(0.29**2 - 0.05) / 0.04))


@pytest.fixture(autouse=True)
def _precision():
    dps = mpmath.mp.dps
    yield
    mpmath.mp.dps = dps


def _matrix_mp(sc, ref):
    """{(point, on, by): force}, torque: the four-bar's Newton-Euler equations at 50
    digits on the reference kinematics (moments about the origin)."""
    P, Acc, Al = ref["positions"], ref["accelerations"], ref["alpha"]
    g = sc.gravity

    def pos(n):
        return P[n] if n in P else tuple(mpf(c) for c in sc.ground[n])

    def acc(n):
        return Acc[n] if n in Acc else (mpf(0), mpf(0))

    def at(T, lk, lam, mu):
        (px, py), (qx, qy) = T(lk.p), T(lk.q)
        dx, dy = qx - px, qy - py
        return (px + lam * dx - mu * dy, py + lam * dy + mu * dx)

    ne = NewtonEuler(["O2-A", "A-B", "B-O4"], mp=True)
    ne.pin("O2", pos("O2"), "O2-A", FRAME)
    ne.pin("A", pos("A"), "A-B", "O2-A")
    ne.pin("B", pos("B"), "B-O4", "A-B")
    ne.pin("O4", pos("O4"), "B-O4", FRAME)
    ne.couple("T", "O2-A")
    for m in sc.masses:
        lk = sc.link(m.body)
        lam, mu = mpf(m.lam), mpf(m.mu)
        G, a = at(pos, lk, lam, mu), at(acc, lk, lam, mu)
        ne.known(
            lk.key,
            (m.mass * (g.g * g.direction[0] - a[0]), m.mass * (g.g * g.direction[1] - a[1])),
            G,
            -mpf(m.inertia) * Al[lk.key],
        )
    for ld in sc.loads:
        ne.known("A-B", tuple(mpf(c) for c in ld.force), pos(ld.target))
    x = ne.solve()
    return {
        ("O2", "O2-A", FRAME): ne.vector(x, "O2"),
        ("A", "A-B", "O2-A"): ne.vector(x, "A"),
        ("B", "B-O4", "A-B"): ne.vector(x, "B"),
        ("O4", "B-O4", FRAME): ne.vector(x, "O4"),
    }, x["T"]


def test_the_force_bounds_hold_and_grow_towards_the_toggle():
    mpmath.mp.dps = 50
    bounds = []
    for delta in (20.0, 1.0, 1e-2, 1e-4):
        sc = parse_scene(TEXT % (LIMIT - delta))
        sol = solve(sc)
        f = sol.forces
        b = force_bounds(sol)
        pins, T = _matrix_mp(sc, _reference(sc, sol))
        for (point, on, by), want in pins.items():
            got = f.pin(point, on, by)
            err = float(mpmath.sqrt((got[0] - want[0]) ** 2 + (got[1] - want[1]) ** 2))
            bound = b.pins.get((point, on, by), b.pins.get((point, by, on)))
            assert err <= bound * b.force, (delta, point, err / b.force, bound)
        assert abs(float(f.input_torque - T)) <= b.effort * b.force * b.length
        bounds.append(b.worst)
    assert all(later > 10 * earlier for earlier, later in zip(bounds, bounds[1:]))
    assert bounds[-1] > SHOWN  # near the toggle the forces' bounds are shown


def _reference(sc, sol):
    return reference_solution(sc, sol.P)


def test_the_bounds_are_shown_in_the_text_the_steps_and_the_json():
    from polygon_method.text.report import solution_text
    from polygon_method.text.steptable import steps_text

    sol = solve(parse_scene(TEXT % (LIMIT - 1e-4)))
    b = force_bounds(sol)
    text = solution_text(sol)
    assert "estimated error of the forces above 1e-09" in text
    assert f"the driver's torque: {b.effort:.2g}" in text
    assert f"estimated error of these forces: {b.worst:.2g} of the largest force" in steps_text(sol)
    d = json.loads(json.dumps(sol.to_dict(), allow_nan=False))["error_bounds"]["forces"]
    assert d["input"] == b.effort and d["pins"]["B"][0]["bound"] == b.pins[("B", "A-B", "B-O4")]
    assert d["relative_to"]["force"] == b.force
    # far from the toggle nothing is shown
    sol = solve(parse_scene(TEXT % (LIMIT - 40)))
    assert "estimated error of the forces" not in solution_text(sol)


def test_no_useful_bound_is_null_with_its_reason():
    b = ForceBounds(
        {("B", "A-B", "B-O4"): 3.0, ("A", "A-B", "O2-A"): 1e-12},
        {"X": 1e100},
        1e100,
        None,
        {},
        10.0,
        0.5,
    )
    d = json.loads(json.dumps(bounds_dict(b), allow_nan=False))
    assert d["pins"]["B"][0]["bound"] is None and d["pins"]["A"][0]["bound"] == 1e-12
    assert d["guides"]["X"] is None and d["input"] is None
    assert d["no_useful_bound"] == {"count": 3, "reason": NO_BOUND}


def test_the_sweep_gives_the_forces_worst_bound():
    from polygon_method.motion.sweeps import sweep

    sc = parse_scene(TEXT % 60.0)
    res = sweep(sc, np.radians(np.linspace(0.0, LIMIT - 1e-3, 40)))
    cols = {name: a for name, _, a in res.columns(error_bound=True)}
    err = cols["err_forces"]
    assert np.all(np.isfinite(err)) and len(err) == 40
    assert err[-1] > 100 * err[0]  # grows towards the toggle
    one = force_bounds(solve(parse_scene(TEXT % float(res.degrees[-1])))).worst
    assert err[-1] == pytest.approx(one, rel=1e-3)
