"""The candidates and their screening (a part of the variants' generator, :mod:`.`): index
tuples drawn without repeats (a small space whole), the base plan evaluated once over many
candidates (every dimension an array), and what makes a candidate the base problem itself."""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..common.tolerances import ROUNDING
from ..solver.kinematics import evaluate

#: a space of at most this many combinations is visited whole
ENUMERATE = 50_000
#: at most this many candidates are screened in a larger space
MAX_TRIED = 20_000


def _stack(values):
    """Per-candidate values (numbers, or tuples of them) as arrays (or tuples of arrays)."""
    first = values[0]
    if isinstance(first, tuple):
        return tuple(_stack([v[i] for v in values]) for i in range(len(first)))
    if isinstance(first, (int, float)):
        return np.array(values, dtype=float)
    return first


def _stack_dims(dl):
    d0 = dl[0]
    ground = {p: _stack([d.ground[p] for d in dl]) for p in d0.ground}
    steps = tuple(_stack([d.steps[i] for d in dl]) for i in range(len(d0.steps)))
    radii = {p: _stack([d.radii[p] for d in dl]) for p in d0.radii}
    return replace(
        d0,
        ground=ground,
        steps=steps,
        theta=_stack([d.theta for d in dl]),
        omega=_stack([d.omega for d in dl]),
        alpha=_stack([d.alpha for d in dl]),
        radii=radii,
    )


def screen(plan, scenes, min_condition):
    """For each candidate scene (of the plan's shape): does it assemble on the plan's
    branches with every step's condition at least ``min_condition``? Returns (mask, least
    condition per candidate), from one evaluation of the plan over all of them."""
    dims = _stack_dims([plan.dimensions(s) for s in scenes])
    m = evaluate(plan, dims=dims, array=True, upto=0)
    n = len(scenes)
    least = np.full(n, np.inf)
    for i, c in m.cond.items():
        least = np.minimum(least, np.broadcast_to(np.asarray(c, dtype=float), (n,)))
    ok = least >= min_condition
    if m.bad is not None:
        ok &= ~np.broadcast_to(np.asarray(m.bad, dtype=bool), (n,))
    ok &= np.isfinite(least)
    return ok, least


def _branches(plan) -> tuple:
    return tuple(getattr(st, "sigma", None) for st in plan.steps)


def _candidates(rng, sizes, total):
    """Index tuples in a random order without repeats: all of them for a small space, a
    sample for a large one."""
    if total <= ENUMERATE:
        for flat in rng.permutation(total):
            idx, rest = [], int(flat)
            for n in reversed(sizes):
                idx.append(rest % n)
                rest //= n
            yield tuple(reversed(idx))
        return
    seen = set()
    while len(seen) < min(total, MAX_TRIED):
        block = np.stack([rng.integers(0, n, size=256) for n in sizes], axis=1)
        for row in block:
            t = tuple(int(i) for i in row)
            if t not in seen:
                seen.add(t)
                yield t
                if len(seen) >= MAX_TRIED:
                    return


def _numbers(x):
    """The numbers in a nest of tuples, lists and dicts, in order."""
    if isinstance(x, dict):
        return [y for k in sorted(x, key=str) for y in _numbers(x[k])]
    if isinstance(x, (tuple, list)):
        return [y for v in x for y in _numbers(v)]
    if isinstance(x, (int, float)) and not isinstance(x, bool):
        return [float(x)]
    return []


def _problem(plan, sc):
    """What makes ``sc`` the problem it is, as numbers (SI): the plan's dimensions (ground,
    each step's, pin radii), the crank's speed and acceleration, its angle (over a turn),
    the loads."""
    d = plan.dimensions(sc)
    turn = 2 * math.pi
    theta = round(float(d.theta) % turn, 12) % turn
    loads = [(ld.target, ld.force, ld.torque) for ld in sc.loads]
    return (
        _numbers((d.ground, d.steps, d.radii, d.omega, d.alpha))
        + [theta]
        + _numbers([(f, t) for _, f, t in loads])
    )


def _same(a, b) -> bool:
    return len(a) == len(b) and all(
        abs(x - y) <= ROUNDING * max(1.0, abs(x), abs(y)) for x, y in zip(a, b)
    )
