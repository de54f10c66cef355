"""The summary of a sweep through a position where a group's force equations are exactly
singular: the parallel crank's dead points (at 0 deg exactly singular, at 180 deg a hair
from it by rounding). The forces are summarised, not left out: a pin force that grows
without bound towards a dead point is marked so (never a number that depends on the grid),
and the driving torque and the shaking force, bounded through it, have their extremes.

The reference is independent of the tool: the parallelogram's motion in closed form (A = r
e(theta), B = C + r e(theta), the coupler translating), and on it the three links'
Newton-Euler equations as one 9 x 9 system (``tests/newton_euler.py``) at 30 digits, which
gives the torque and the pin forces at any angle but the dead points; the torque also by the
virtual power with inertia. The summary's torque and shaking-force extremes are held to the
reference at their angles, and no angle of a dense grid (0.01 deg) goes beyond them, to
1e-9; each pin force the summary marks unbounded grows as 1 / d towards its dead point in
the reference (ten times a decade of d).
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

from polygon_method.linkage.summary import summarize
from polygon_method.scene import parse_scene

from newton_euler import NewtonEuler
from test_sweep_singular_forces import PARALLEL

R, C = 0.1, (0.3, 0.0)
W, ALPHA = 10.0, -4.0


@pytest.fixture(scope="module")
def scene():
    return parse_scene(PARALLEL)


@pytest.fixture(scope="module")
def summary(scene):
    return summarize(scene)


def _motion(th, num=math):
    """The parallelogram's points, velocities, accelerations, omegas and alphas at ``th``."""
    c, s = num.cos(th), num.sin(th)
    e, p = (c, s), (-s, c)
    A = (R * c, R * s)
    B = (C[0] + R * c, C[1] + R * s)
    v = (R * W * p[0], R * W * p[1])
    a = (R * (ALPHA * p[0] - W * W * e[0]), R * (ALPHA * p[1] - W * W * e[1]))
    P = {"O": (0, 0), "C": C, "A": A, "B": B}
    V = {"O": (0, 0), "C": (0, 0), "A": v, "B": v}
    Acc = {"O": (0, 0), "C": (0, 0), "A": a, "B": a}
    om = {"OA": W, "AB": 0, "CB": W}
    al = {"OA": ALPHA, "AB": 0, "CB": ALPHA}
    return P, V, Acc, om, al


def _carried(sc, m, T):
    lk = sc.link(m.body)
    (px, py), (qx, qy) = T[lk.p], T[lk.q]
    dx, dy = qx - px, qy - py
    return (px + m.lam * dx - m.mu * dy, py + m.lam * dy + m.mu * dx)


def _shake_and_power(sc, th):
    """The shaking force (the loads, weights and inertia forces of the moving bodies) and
    the torque by the virtual power with inertia, at the angles ``th`` (arrays)."""
    P, V, A, om, al = _motion(th, np)
    g = sc.gravity
    fx, fy, power = 0.0, 0.0, 0.0
    for ld in sc.loads:
        if ld.force is not None:
            v = V[ld.target]
            fx, fy = fx + ld.force[0], fy + ld.force[1]
            power = power + ld.force[0] * v[0] + ld.force[1] * v[1]
        else:
            power = power + ld.torque * om[ld.target]
    for m in sc.masses:
        key = sc.link(m.body).key
        v, a = _carried(sc, m, V), _carried(sc, m, A)
        wx, wy = m.mass * g.g * g.direction[0], m.mass * g.g * g.direction[1]
        fx, fy = fx + wx - m.mass * a[0], fy + wy - m.mass * a[1]
        power = power + wx * v[0] + wy * v[1] - m.mass * (a[0] * v[0] + a[1] * v[1])
        power = power - m.inertia * al[key] * om[key]
    return np.hypot(fx, fy), -power / W


def _matrix(sc, th):
    """The 9 x 9 Newton-Euler solve at ``th`` (mpmath, 30 digits): {unknown: value}."""
    with mpmath.workdps(30):
        th = mpmath.mpf(th)
        P, V, A, om, al = _motion(th, mpmath)
        ne = NewtonEuler(["OA", "AB", "CB"], mp=True)
        ne.pin("O", P["O"], "OA", "frame")
        ne.pin("A", P["A"], "AB", "OA")
        ne.pin("B", P["B"], "AB", "CB")
        ne.pin("C", P["C"], "CB", "frame")
        ne.couple("T", "OA", "frame")
        g = sc.gravity
        for m in sc.masses:
            key = sc.link(m.body).key
            G, a = _carried(sc, m, P), _carried(sc, m, A)
            ne.known(key, (m.mass * g.g * g.direction[0], m.mass * g.g * g.direction[1]), G)
            ne.known(key, (-m.mass * a[0], -m.mass * a[1]), G, -m.inertia * al[key])
        for ld in sc.loads:
            if ld.force is not None:
                ne.known("AB", ld.force, P[ld.target])  # (B: found by the dyad's first link)
            else:
                ne.known(ld.target, c=ld.torque)
        x = ne.solve()
        return {k: float(v) for k, v in x.items()}


def test_the_forces_are_summarised_with_the_dead_points_named(summary):
    names = {e.name for e in summary.extremes}
    assert {"torque_inertia", "shake", "shake_moment"} <= names
    assert sum(n.startswith("F_") for n in names) == 4
    assert not any("not summarised" in n for n in summary.notes)
    said = [n for n in summary.notes if n.startswith("the force equations are singular")]
    assert len(said) == 2 and "0.0000 deg" in said[0] and "180.0000 deg" in said[1]
    text = summary.text()
    assert "nan" not in text.lower() and "+unbounded" in text


def test_the_pin_forces_grow_without_bound_towards_a_dead_point(scene, summary):
    for e in summary.extremes:
        if not e.name.startswith("F_"):
            continue
        assert e.max_unbounded and not e.min_unbounded, e.name
        assert min(abs(e.at_max - 0.0), abs(e.at_max - 180.0), abs(e.at_max - 360.0)) < 1e-9
        th0 = math.radians(e.at_max)
        pin = e.name.split("_")[1]
        sizes = []
        for d in (1e-3, 1e-4, 1e-5):
            x = _matrix(scene, th0 + d)
            sizes.append(math.hypot(x[pin + ".x"], x[pin + ".y"]))
        assert sizes[1] > 9 * sizes[0] and sizes[2] > 9 * sizes[1], (e.name, sizes)
        assert e.minimum > 0 and not e.constant


def test_the_bounded_extremes_are_the_references(scene, summary):
    dense = np.radians(np.arange(0.0, 360.0, 0.01))
    shake, torque = _shake_and_power(scene, dense)
    for name, ref in (("torque_inertia", torque), ("shake", shake)):
        e = summary.extreme(name)
        assert not (e.max_unbounded or e.min_unbounded)
        size = max(abs(ref).max(), 1.0)
        assert ref.max() <= e.maximum + 1e-9 * size and ref.min() >= e.minimum - 1e-9 * size
        for value, at in ((e.maximum, e.at_max), (e.minimum, e.at_min)):
            there = _shake_and_power(scene, np.array([math.radians(at)]))
            got = there[0] if name == "shake" else there[1]
            assert value == pytest.approx(float(got[0]), abs=1e-9 * size), (name, at)


def test_the_matrix_method_agrees_with_the_virtual_power(scene):
    """(The two references agree with each other away from the dead points.)"""
    for deg in (10.0, 95.0, 200.0, 333.0):
        th = math.radians(deg)
        T = _matrix(scene, th)["T"]
        _, ref = _shake_and_power(scene, np.array([th]))
        assert T == pytest.approx(float(ref[0]), rel=1e-12, abs=1e-12)


def test_a_bounded_force_at_its_dead_point_is_its_limit(scene):
    """Angles that start at the dead point, where the torque is least: the summary's
    minimum is there, the limit of the torque from beside it (the walk cannot find it at
    the dead point itself), to 1e-9 of the virtual power's torque there."""
    s = summarize(scene, np.radians(np.arange(0.0, 8.01, 0.5)))
    e = s.extreme("torque_inertia")
    dense = np.radians(np.arange(0.0, 8.0001, 0.001))
    _, ref = _shake_and_power(scene, dense)
    assert int(np.argmin(ref)) == 0  # (the premise: least at the dead point)
    size = max(abs(ref).max(), 1.0)
    assert e.at_min == pytest.approx(0.0, abs=1e-12)
    assert e.minimum == pytest.approx(float(ref[0]), abs=1e-9 * size)
    assert ref.max() <= e.maximum + 1e-9 * size


ROCKER = """
title = "crank-rocker driven by its rocker, with masses"
units = "mm"
[ground]
O = [0, 0]
C = [300, 0]
[links]
CD = 250
DA = 280
OA = 100
[assembly]
A = [0, 100]
[input]
crank = "CD"
angle = 100
speed = "10 rad/s ccw"
[masses]
CD = { mass = 1.5, along = 120, gyration = 60 }
DA = { mass = 2, along = 140, gyration = 80 }
OA = { mass = 1, along = 50, gyration = 30 }
[gravity]
[loads]
OA = { torque = "3 N m cw" }
"""


def test_a_rocking_input_refines_its_force_minima_and_marks_the_limits():
    """The driving rocker's limit positions are toggles of the driven crank: the pin forces
    grow without bound there (marked), and their least values, between the limits, are
    refined beyond the grid (the refinement's brackets cross the limits: the forces are
    found at the angles the kinematics reaches): no angle of a dense sweep goes below them,
    and each is the sweep's own value at its angle."""
    from polygon_method.motion.sweeps import sweep

    sc = parse_scene(ROCKER)
    s = summarize(sc)
    lo, hi = s.range_deg
    dense = sweep(sc, np.radians(np.arange(lo + 0.5, hi - 0.5, 0.002)))
    cols = {n: np.asarray(a, dtype=float) for n, _, a in dense.force_columns()}
    pins = [e for e in s.extremes if e.name.startswith("F_")]
    assert len(pins) == 4
    for e in pins:
        assert e.max_unbounded and not e.min_unbounded
        assert e.minimum > 1.0 and "+unbounded" in s.text()
        assert cols[e.name].min() >= e.minimum - 1e-9 * e.minimum
        there = np.asarray(
            dict((n, a) for n, _, a in sweep(sc, [math.radians(e.at_min)]).force_columns())[e.name],
            dtype=float,
        )[0]
        assert there == pytest.approx(e.minimum, rel=1e-9)
        assert e.minimum > cols[e.name].min() - 1e-6 * e.minimum  # (refined: to the grid's)


def test_the_page_draws_the_forces_but_at_the_dead_points(scene):
    """The page's force layer over a turn through both dead points: the frames there are
    named and carry no force (none drawn); every other frame's arrows are the forces of the
    sweep without those frames; the force scale is set by them (not by the 1e19 N the
    rounding leaves at 180 deg)."""
    from polygon_method.motion.sweeps import sweep
    from polygon_method.page.force_layer import force_layers

    degs = np.arange(0.0, 360.0, 7.5)
    res = sweep(scene, np.radians(degs))
    inertia, forces = force_layers(res, len(degs))
    assert forces is not None and inertia is not None
    dead = [int(i) for i in np.flatnonzero((degs == 0.0) | (degs == 180.0))]
    assert forces["singular"] == dead
    clear = [i for i in range(len(degs)) if i not in dead]
    _, ref = force_layers(sweep(scene, np.radians(degs[clear])), len(clear))
    largest = 0.0
    for a, b in zip(forces["arrows"], ref["arrows"]):
        F = np.asarray(a["F"]).reshape(-1, 2)
        assert np.all(np.isfinite(F)) and np.all(F[dead] == 0.0)
        assert np.array_equal(F[clear], np.asarray(b["F"]).reshape(-1, 2))
        largest = max(largest, float(np.max(np.hypot(*F.T))))
    assert forces["perCm"] == ref["perCm"] and largest < 1e5
