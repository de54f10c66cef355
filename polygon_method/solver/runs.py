"""One pass of a plan over an array of crank angles (:func:`run_arrays`: a
:class:`~polygon_method.solver.kinematics.Motion` of arrays, constants kept as one number
each), the motions of several index sets made one (:func:`merge`), and which angles are
valid (:func:`valid_mask`); :mod:`.tracking` chooses the angles and the branches."""

from __future__ import annotations

import numpy as np

from ..common.errors import TOL
from .given import held
from .kinematics import Motion
from .plan import Context

__all__ = ["run_arrays", "merge", "valid_mask", "branch_steps", "tune_malloc", "array_motion"]

_MALLOC_TUNED = []


def tune_malloc():
    """Keep freed temporaries on the heap (glibc): otherwise every pass over an array of
    crank angles maps and faults fresh pages, which costs as much as the arithmetic (twice,
    for 3600 angles). Once per process."""
    if _MALLOC_TUNED:
        return
    _MALLOC_TUNED.append(True)
    try:
        import ctypes
        import sys

        if not sys.platform.startswith("linux"):
            return
        libc = ctypes.CDLL("libc.so.6")
        libc.mallopt(-1, 64 << 20)  # M_TRIM_THRESHOLD
        libc.mallopt(-3, 4 << 20)  # M_MMAP_THRESHOLD
    except (OSError, AttributeError):
        pass


def array_motion(theta, P, V, A, W, Al, S, cond, bad) -> Motion:
    """A motion of arrays (no scene, no plan: what the sweep's records are built from)."""
    return Motion(None, None, theta, P, V, A, W, Al, S, cond, bad)


def _full(v, n, const):
    """An array of length n from an evaluated value. A constant (a ground point, a fixed
    link, the crank's speed) stays one number: a read-only zero-stride view of it, shared
    by every column of that value (``const``), with no memory per angle."""
    if isinstance(v, np.ndarray) and v.shape == (n,):
        return v
    x = float(v) if v is not None else 0.0
    view = const.get(x)
    if view is None:
        view = const[x] = np.broadcast_to(np.float64(x), (n,))
    return view


def run_arrays(plan, theta, omega, alpha, vel=True, acc=True) -> Motion:
    """Evaluate ``plan`` over one array of crank angles (one pass, no chunking)."""
    n = len(theta)
    tune_malloc()
    unbounded = None
    if getattr(plan, "given", None) is not None and vel:  # the given motion held
        omega, alpha = held(plan, theta)
        unbounded = ~(np.isfinite(omega) & np.isfinite(alpha))  # at a dead centre of it
        if unbounded.any():
            omega, alpha = np.where(unbounded, 1.0, omega), np.where(unbounded, 0.0, alpha)
        else:
            unbounded = None
    ctx = Context(theta, omega, alpha, array=True)
    upto = 2 if (vel and acc) else (1 if vel else 0)
    with np.errstate(all="ignore"):
        m = plan.run(ctx, upto=upto)
    const = {}

    def fix(d):
        return {k: (_full(v[0], n, const), _full(v[1], n, const)) for k, v in d.items()}

    P = fix(m.P)
    V = fix(m.V) if upto >= 1 else {}
    A = fix(m.A) if upto >= 2 else {}
    W = {k: _full(v, n, const) for k, v in m.W.items()} if upto >= 1 else {}
    Al = {k: _full(v, n, const) for k, v in m.Al.items()} if upto >= 2 else {}
    S = {k: tuple(_full(x, n, const) for x in v) for k, v in m.S.items()} if upto >= 1 else {}
    cond = {i: _full(c, n, const) for i, c in ctx.cond.items()}
    bad = ctx.bad if ctx.bad is not None else np.zeros(n, dtype=bool)
    if unbounded is not None:
        bad = bad | unbounded
    return array_motion(theta, P, V, A, W, Al, S, cond, bad)


def branch_steps(plan):
    """The plan's steps that have two assemblies (a branch to follow)."""
    return [s for s in plan.steps if s.branching]


def merge(theta, frames) -> Motion:
    """One motion from the motions of several index sets (``frames``: key -> (index, motion))."""
    n = len(theta)
    any_fr = next(iter(frames.values()))[1]

    def put(get):
        out = np.empty(n)
        for idx, fr in frames.values():
            out[idx] = get(fr)
        return out

    P = {k: (put(lambda f: f.P[k][0]), put(lambda f: f.P[k][1])) for k in any_fr.P}
    V = {k: (put(lambda f: f.V[k][0]), put(lambda f: f.V[k][1])) for k in any_fr.V}
    A = {k: (put(lambda f: f.A[k][0]), put(lambda f: f.A[k][1])) for k in any_fr.A}
    W = {k: put(lambda f: f.W[k]) for k in any_fr.W}
    Al = {k: put(lambda f: f.Al[k]) for k in any_fr.Al}
    S = {
        k: tuple(put(lambda f, j=j: f.S[k][j]) for j in range(len(v))) for k, v in any_fr.S.items()
    }
    cond = {i: put(lambda f: f.cond[i]) for i in any_fr.cond}
    bad = np.zeros(n, dtype=bool)
    for idx, fr in frames.values():
        bad[idx] = fr.bad
    return array_motion(theta, P, V, A, W, Al, S, cond, bad)


def valid_mask(fr: Motion, plan):
    """Angles where a step failed or is singular (True: not valid)."""
    bad = fr.bad.copy()
    for st in branch_steps(plan):
        bad |= fr.cond[st.index] < TOL.singular
    return bad
