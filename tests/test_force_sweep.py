"""The force analysis over a sweep, in vectorised calls, against the one-instant solve and
against the virtual-power balance; and its short road (numbers only, planned once per
scene) against its long road (every record with its words).

- 3600 crank angles of every worked problem with forces: the sweep's forces (the same
  group-by-group equations on arrays of crank angles) equal the one-instant solve's at
  each angle, to 1e-12 of the largest force there;
- the power balance with inertia (virtual power: ``T w + sum F.v + sum C w + sum m g.v_G -
  sum m a_G.v_G - sum I alpha w = 0``, G's velocity and acceleration computed here from the
  links' ends) at every one of 3600 angles of the worked problems and of every force
  problem of the corpus given masses, to 1e-9;
- the short road and the long road give the same numbers to the last bit, at one instant
  and over a sweep, on every force problem.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from polygon_method.forces import ROOMS, analyse
from polygon_method.forces import _long as long_road
from polygon_method.forces.core import force_plan
from polygon_method.motion.solution import Solution, solve
from polygon_method.motion.sweeps import sweep
from polygon_method.scene import load_scene
from polygon_method.solver.compiler import compile_plan
from polygon_method.steps.base import Instant
from test_forces import CASES, _driver_power, _kin, with_forces

ROOT = Path(__file__).resolve().parent.parent
WORKED = [
    ROOT / "worked_problems" / f"{n}.toml"
    for n in ("fourbar_forces", "engine_forces", "shaper_forces", "engine_flywheel")
]
N = 3600


def solve_at(scene, theta):
    """The one-instant solve at crank angle ``theta`` on the plan's branch: ``solve``'s road
    (the plan's one-instant functions), at another angle than the scene's."""
    plan = compile_plan(scene)
    inp = scene.input
    sol = object.__new__(Solution)
    ctx = object.__new__(Instant)
    ctx.theta, ctx.omega, ctx.alpha, ctx.cond = theta, inp.omega, inp.alpha, {}
    plan.instant(ctx, sol)
    sol.scene, sol.plan, sol.theta, sol.bad, sol._cache = scene, plan, theta, None, {}
    return sol


def test_solve_at_is_solve_at_the_scenes_own_angle():
    sc = load_scene(WORKED[0])
    a, b = solve(sc), solve_at(sc, sc.input.angle)
    assert a.P == b.P and a.A == b.A and a.Al == b.Al
    assert analyse(a).input_torque == analyse(b).input_torque


def _numbers(f, n=None):
    """name -> value (arrays broadcast to ``n`` positions): the effort, a second crank's
    torque, the shaking force and moment, every pin force's and guide force's components,
    every inertia force and couple."""
    out = {
        "effort": f.input_torque,
        "shake_x": f.shaking_force[0],
        "shake_y": f.shaking_force[1],
        "shake_m": f.shaking_moment,
    }
    if f.second_torque is not None:
        out["second"] = f.second_torque
    for k, p in enumerate(f.pins):
        out[f"pin{k} {p.point} {p.on} {p.by} x"] = p.force[0]
        out[f"pin{k} {p.point} {p.on} {p.by} y"] = p.force[1]
    for k, g in enumerate(f.guides):
        out[f"guide{k} {g.key}"] = g.normal
    for i in f.inertia:
        out[f"inertia {i.body} x"], out[f"inertia {i.body} y"] = i.force
        out[f"couple {i.body}"] = i.couple
    if n is not None:
        out = {k: np.broadcast_to(v, (n,)) for k, v in out.items()}
    return out


@pytest.mark.parametrize("path", WORKED, ids=lambda p: p.stem)
def test_the_vectorised_sweep_is_the_one_instant_solve_at_every_angle(path):
    sc = load_scene(path)
    theta = np.radians(np.arange(N) * (360.0 / N))
    res = sweep(sc, theta)
    assert len(res) == N
    f = analyse(res)
    assert isinstance(f.input_torque, np.ndarray) and f.input_torque.shape == (N,)
    many = _numbers(f, N)
    size = max(lk.length for lk in sc.links)  # a moment is compared as a force at this arm
    worst = 0.0
    for k, th in enumerate(theta):
        one = _numbers(analyse(solve_at(sc, float(th))))
        assert one.keys() == many.keys()
        big = max(abs(v) for v in one.values())
        for key, v in one.items():
            arm = (
                size if key in ("effort", "second", "shake_m") or key.startswith("couple") else 1.0
            )
            err = abs(many[key][k] - v) / (big * arm)
            worst = max(worst, err)
            assert err <= 1e-12, (path.stem, math.degrees(th), key, many[key][k], v)
    assert worst < 1e-12


def _power_terms(sc, res, f):
    """The virtual-power terms (arrays over the sweep), G's motion from the links' ends."""
    terms = _driver_power(sc, res, f)
    for ld in sc.loads:
        if ld.across is not None:  # stated against a link: it turns with it, angle by angle
            a, b, off, _, size = ld.across
            (ax, ay), (bx, by), v = res.P[a], res.P[b], res.V[ld.target]
            t = np.arctan2(by - ay, bx - ax) + off
            terms.append(size * (np.cos(t) * v[0] + np.sin(t) * v[1]))
        elif ld.force is not None:
            v = res.V[ld.target]
            terms.append(ld.force[0] * v[0] + ld.force[1] * v[1])
        else:
            terms.append(ld.torque * res.W[ld.target])
    for c in sc.cylinders:  # a passive cylinder's given force (a spring's k (L0 - L)): F vs
        if hasattr(c, "push"):
            vs = res.S[c.key][0]
            (kx, ky), (rx, ry) = res.P[c.barrel], res.P[c.rod]
            L = ((rx - kx) ** 2 + (ry - ky) ** 2) ** 0.5
            spring = c.stiffness * (c.free_length - L) if c.stiffness else 0.0
            terms.append((c.push - c.damping * vs + spring) * vs)
    g = sc.gravity
    for m in sc.masses:
        G, v, a, al, w = _kin(res, m)
        if g is not None:
            terms.append(m.mass * g.g * (g.direction[0] * v[0] + g.direction[1] * v[1]))
        terms.append(-m.mass * (a[0] * v[0] + a[1] * v[1]))
        terms.append(-m.inertia * al * w)
    return terms


def _balance(sc, res):
    """(|the sum of the power terms| / the sum of their sizes, the positions away from a
    toggle: every group's condition above 1e-6) at every angle of ``res``."""
    f = analyse(res)
    terms = _power_terms(sc, res, f)
    n = len(res)
    total = sum(np.broadcast_to(t, (n,)) for t in terms)
    scale = sum(np.abs(np.broadcast_to(t, (n,))) for t in terms)
    fine = np.ones(n, dtype=bool)
    for st in f.steps:
        fine &= np.broadcast_to(st.condition, (n,)) > 1e-6
    # where every term is exactly 0 (an engine at its dead centre: nothing moves but the
    # crank, and its torque is 0) the balance is 0 = 0; a torque off by any amount there
    # is a term of its own, and the ratio 1
    rel = np.abs(total) / np.where(scale > 0, scale, 1.0)
    return rel, fine


@pytest.mark.parametrize("path", WORKED[:3], ids=lambda p: p.stem)
def test_the_worked_sweeps_balance_power_at_every_one_of_3600_angles(path):
    sc = load_scene(path)
    res = sweep(sc, np.radians(np.arange(N) * (360.0 / N)))
    assert len(res) == N
    rel, fine = _balance(sc, res)
    assert fine.all()
    assert np.all(rel <= 1e-9), float(rel.max())


@pytest.mark.parametrize("path", CASES)
def test_every_force_problem_balances_power_over_3600_angles(path):
    sc = with_forces(load_scene(path), 11)
    # a crank: 3600 angles between the tenths of a degree (a parallel crank's dead points,
    # where a sweep's force analysis is refused, are at whole degrees); a block: its stroke
    theta = None if sc.input.block else np.radians((np.arange(N) + 0.5) * (360.0 / N))
    res = sweep(sc, theta)
    assert len(res) >= 9
    rel, fine = _balance(sc, res)
    assert fine.sum() >= 9
    assert np.all(rel[fine] <= 1e-9), float(rel[fine].max())


def _same(a, b) -> bool:
    """Equal to the last bit (floats, tuples, arrays)."""
    if isinstance(a, tuple):
        return len(a) == len(b) and all(_same(x, y) for x, y in zip(a, b))
    if isinstance(a, np.ndarray) or isinstance(b, np.ndarray):
        return np.array_equal(
            np.broadcast_to(a, np.shape(b) or np.shape(a)),
            np.broadcast_to(b, np.shape(a) or np.shape(b)),
        )
    return a == b and type(a) is type(b) or (a is None and b is None)


def _roads(motion):
    """(the short road's Forces, the long road's fields)."""
    fp = force_plan(motion.scene, motion.plan)
    assert fp.quick
    return analyse(motion), long_road(motion, fp)


def _check_roads(f, whole):
    effort, shake, moment, name, kind, second, second_crank, inertia, pins, guides = whole[:10]
    assert _same(f.input_torque, effort) and _same(f.shaking_force, shake)
    assert _same(f.shaking_moment, moment) and (f.crank, f.driver) == (name, kind)
    assert _same(f.second_torque, second) and f.second_crank == second_crank
    assert [(p.point, p.on, p.by) for p in f.pins] == [(p.point, p.on, p.by) for p in pins]
    assert all(_same(a.force, b.force) for a, b in zip(f.pins, pins))
    assert [(g.point, g.by) for g in f.guides] == [(g.point, g.by) for g in guides]
    assert all(_same(a.normal, b.normal) and _same(a.n, b.n) for a, b in zip(f.guides, guides))
    assert [i.body for i in f.inertia] == [i.body for i in inertia]
    for a, b in zip(f.inertia, inertia):
        assert _same(a.G, b.G) and _same(a.a_G, b.a_G) and _same(a.force, b.force)
        assert _same(a.couple, b.couple) and _same(a.offset, b.offset)


QUICK = [
    c
    for c in CASES
    if all(hasattr(ROOMS[st.kind], "bind") for st in compile_plan(load_scene(c.values[0])).steps)
]


def test_the_short_road_covers_the_common_kinds():
    kinds = {st.kind for c in QUICK for st in compile_plan(load_scene(c.values[0])).steps}
    assert {"crank", "dyad", "slider", "carried", "slotted", "block"} <= kinds
    assert len(QUICK) >= 10


@pytest.mark.parametrize("path", QUICK)
@pytest.mark.parametrize("seed", [5, 6])
def test_the_short_road_is_the_long_road_to_the_last_bit(path, seed):
    sc = with_forces(load_scene(path), seed)
    _check_roads(*_roads(solve(sc)))
    theta = None if sc.input.block else np.radians(np.arange(0.5, 360.0, 7.0))
    _check_roads(*_roads(sweep(sc, theta)))


@pytest.mark.parametrize("path", WORKED, ids=lambda p: p.stem)
def test_the_worked_problems_take_the_short_road(path):
    sc = load_scene(path)
    _check_roads(*_roads(solve(sc)))
    _check_roads(*_roads(sweep(sc, np.radians(np.arange(0.0, 360.0, 1.0)))))


@pytest.mark.parametrize("path", CASES)
def test_a_bodys_resultant_is_what_its_group_knew_on_it(path):
    # the engine's piston effort reads it (Forces.resultant) where the long road's step
    # records kept it; by either road, at one instant
    sol = solve(with_forces(load_scene(path), 7))
    f = analyse(sol)
    checked = 0
    for rec in f.steps:
        for body, known in zip(rec.bodies, rec.known):
            assert _same(tuple(f.resultant(body)), tuple(known)), (rec.title, body)
            checked += 1
    assert checked >= 1


def test_a_wheels_force_bounds_over_a_sweep():
    # sweep --csv --error-bound of a wheel rolling on the ground with masses: the wheel's
    # divisor (the link's arm, at most the wheel's radius) taken entry by entry
    path = ROOT / "tests" / "textbook" / "rolling_wheel_on_ground.toml"
    sc = with_forces(load_scene(path), 1)
    res = sweep(sc, np.radians(np.arange(0.5, 360.0, 7.0)))
    cols = {name: a for name, _, a in res.columns(error_bound=True)}
    err = np.broadcast_to(cols["err_forces"], (len(res),))
    assert np.all(np.isfinite(err)) and np.all(err >= 0) and np.all(err < 1e-6)
