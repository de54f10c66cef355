"""A sweep summary's force quantities where the force analysis cannot be had at every angle:
the angles a chunk holds that the kinematics does not reach are left to it (the summary
refines its extremes on brackets that may cross a limit position), and where a group's force
equations are exactly singular at an angle (a parallel crank's dead point: the coupler and
the rocker in one line) the forces are found at every other angle
(:func:`~polygon_method.motion.sweep_forces.by_rows`) and the singular angle is kept, to be
looked at closely when the summary is finished (:func:`at_singular`): a force that grows
without bound towards it is marked so, one that stays bounded has there its limit from
either side. ``red`` is the summary's reducer
(:class:`~polygon_method.linkage.summary._Reducer`).
"""

from __future__ import annotations

import numpy as np

from ..common.errors import PolygonMethodError
from ..common.tolerances import REFINED, TOL
from ..motion import sweep_forces
from ..motion.sweeps import select
from ..solver.domain import NEAR
from ..solver.kinematics import Motion
from ..solver.tracking import valid_mask

__all__ = ["force_arrays", "at_singular", "singular_note"]

#: offsets (rad, or of the parameter's radian) from a singular angle at which a force is
#: probed for growing without bound (as 1 / d: four times a step): outside the span next to
#: a change point where the kinematics is not trusted (``NEAR``)
_PROBES = (32 * NEAR, 8 * NEAR, 2 * NEAR)
#: the offset h of the limit's estimate: the values at +-h, +-2h, +-3h (their even
#: expansion's terms in h^2 and h^4 taken out: truncation ~ h^6, some 14 digits down from the
#: quantity's size for one smooth over a radian)
_H = 2 * NEAR


def _motion(red, fr, keep) -> Motion:
    """The motion ``fr`` at the angles ``keep`` (a mask, or None for all), with its scene."""
    m = fr if keep is None else select(fr, keep)
    return Motion(
        red.scene, fr.plan or red.plan, m.theta, m.P, m.V, m.A, m.W, m.Al, m.S, m.cond, m.bad
    )


def force_arrays(red, fr, analyse):
    """``(forces, rows, P)`` (None where there is no such angle) of the force analysis ``analyse`` over the angles of ``fr``
    that the kinematics reaches and where the groups' equations are not singular nor within
    :data:`TOL.singular <polygon_method.common.tolerances.Tolerances.singular>` of it
    (``rows`` their indices in ``fr``, None for all; ``P`` the positions there): the angles
    left out are put in ``red.singular`` (exactly singular: angle -> the words) and
    ``red.near`` (nearly). Raises the analysis's error where it fails otherwise."""
    n = len(fr.theta)
    bad = valid_mask(fr, red.plan) if fr.bad is not None else np.zeros(n, dtype=bool)
    ok = np.flatnonzero(~bad)
    m = _motion(red, fr, None if len(ok) == n else ~bad)
    cut = lambda mo, rows: _motion(red, mo, _mask(len(mo.theta), rows))  # noqa: E731
    try:
        f = analyse(m)
        rows = None
    except PolygonMethodError as exc:
        if sweep_forces.UNDETERMINED not in exc.message:
            raise
        got = sweep_forces.by_rows(m, analyse, cut)
        if got is None:  # (singular at every angle here: a limit position's)
            return None
        f, rows, why = got
        for i, words in why.items():
            _keep_singular(red, float(m.theta[i]), words)
    at = m if rows is None else cut(m, rows)
    cond = sweep_forces.conditions(f, None, len(at.theta))
    near = (cond < TOL.singular) & (not getattr(red, "probing", False))
    if near.any():  # (rounding leaves a singular angle's equations a hair from singular)
        red.near.extend(float(t) for t in np.asarray(at.theta, dtype=float)[near])
        good = np.flatnonzero(~near)
        rows = good if rows is None else np.asarray(rows)[good]
        if not len(rows):
            return None
        f = analyse(cut(m, rows))
        at = cut(m, rows)
    keep = ok if rows is None else ok[rows]
    return f, (None if len(keep) == n else keep), at.P


def _keep_singular(red, t, words):
    """Keep the singular angle ``t`` in ``red.singular`` unless it is there already (the
    refinement's brackets may meet it again, maybe a turn on)."""
    dom = red.sw.domain
    for ts in red.singular:
        d = t - ts
        if dom.periodic:
            d = (d + 0.5 * dom.period) % dom.period - 0.5 * dom.period
        if abs(d) <= REFINED * red.rad:
            return
    red.singular[t] = words


def _mask(n, rows):
    out = np.zeros(n, dtype=bool)
    out[rows] = True
    return out


def spread(arr, rows, n):
    """``arr`` over the ``rows`` of ``n`` angles, NaN at the others (a force not found
    there: the reducer passes over it)."""
    if rows is None:
        return arr
    full = np.full(n, np.nan)
    full[rows] = arr
    return full


def at_singular(red, rows, spacing) -> dict:
    """(name, sense) -> (angle, words) of every force quantity that grows without bound
    towards an angle where a group's force equations are exactly singular; the others'
    rows take there their limit from either side where it is beyond their extremes.

    A quantity is probed at 0.064, 0.016 and 0.004 rad either side (:data:`_PROBES`; for a
    driving block, those parts of its travel over 2 pi; a side beyond the block's travel is
    not probed): it is unbounded in a sense where, on one side, it grows with that sign by
    more than twice a step (as 1 / d does, four times). Else its value at the angle is the
    limit of its values either side (:func:`_limits`: the mean of the two sides at
    h = 0.004 rad, 2 h and 3 h, extrapolated to 0 in h^2; one side alone, where the other
    is beyond the travel: the cubic through h, 2 h, 3 h, 4 h)."""
    found = {}
    dom = red.sw.domain
    by = {row[0]: row for row in rows if row[0] in red.force_names}
    _resolve_near(red, spacing)
    for ts, words in sorted(dict(red.singular).items()):
        if _near_limit(red, ts, spacing):
            continue  # (a limit position's: unbounded_at_limits)
        sides = [
            s
            for s in (-1.0, 1.0)
            if dom.periodic or dom.lo <= ts + s * red.rad * max(_PROBES) <= dom.hi
        ]
        if not sides:
            continue
        for s in sides:
            probe = ts + s * red.rad * np.array(_PROBES)
            q = _force_values(red, probe)
            for nm, vals in q.items():
                for sense in (1.0, -1.0):
                    v = sense * vals
                    if np.all(np.isfinite(v)) and v[0] > 0 and v[1] > 2 * v[0] and v[2] > 2 * v[1]:
                        found.setdefault((nm, sense), (ts, words))
        limit = _limits(red, ts, sides)
        for nm, row in by.items():
            if (nm, 1.0) in found or (nm, -1.0) in found or nm not in limit:
                continue
            v = limit[nm]
            if row[3] is None or not np.isfinite(v):
                continue
            if v > row[2]:
                row[2], row[3] = v, ts
            if v < row[4]:
                row[4], row[5] = v, ts
    return found


def _gap(red, a, b) -> float:
    """The parameter's distance from ``b`` to ``a`` (a turn's multiple taken out where the
    crank turns fully)."""
    d = a - b
    dom = red.sw.domain
    if dom.periodic:
        d = (d + 0.5 * dom.period) % dom.period - 0.5 * dom.period
    return d


def _near_limit(red, t, spacing) -> bool:
    """Whether ``t`` is next to a limit position (its forces grow there with its motion)."""
    reach = 2 * (spacing or 0.0) + 0.02 * red.rad
    return any(abs(_gap(red, t, lp.theta)) <= reach for lp in red.sw.domain.limits)


def _resolve_near(red, spacing):
    """Each run of angles where the force equations were nearly singular (their condition
    below ``TOL.singular``), not next to an exactly singular angle already kept or a limit
    position, gets its singular angle in ``red.singular``: a change point of the
    kinematics there (the two assemblies meet: the force equations are singular with the
    motion's), else the least of the condition, zoomed on (17 angles across the bracket a
    pass, down to about ``REFINED``)."""
    reach = 2 * (spacing or 0.0) + 0.02 * red.rad
    for t in sorted(set(red.near)):
        if any(abs(_gap(red, t, ts)) <= reach for ts in red.singular) or _near_limit(
            red, t, spacing
        ):
            continue
        cps = [cp for cp in red.sw.domain.change_points if abs(_gap(red, t, cp.theta)) <= reach]
        if cps:
            cp = min(cps, key=lambda c: abs(_gap(red, t, c.theta)))
            _keep_singular(
                red, t + _gap(red, cp.theta, t), f"a change point of the motion: {cp.why}"
            )
            continue
        _keep_singular(red, *_least_condition(red, t, spacing or 0.02 * red.rad))


def _least_condition(red, t, spacing):
    """(angle, words) of the least condition of the force equations within ``spacing`` of
    ``t``."""
    from ..forces import analyse

    a, b = t - spacing, t + spacing
    best = t
    for _ in range(16):
        pts = np.linspace(a, b, 17)
        fr = red.sw.evaluate(pts)
        m = _motion(red, fr, None)
        try:
            f = analyse(m)
        except PolygonMethodError as exc:
            if sweep_forces.UNDETERMINED not in exc.message:
                break
            got = sweep_forces.by_rows(
                m, analyse, lambda mo, rows: _motion(red, mo, _mask(17, rows))
            )
            if got is not None and got[2]:
                i, words = next(iter(got[2].items()))
                return float(pts[i]), words
            break
        c = sweep_forces.conditions(f, None, 17)
        j = int(np.argmin(np.where(np.isfinite(c), c, np.inf)))
        best = float(pts[j])
        a, b = pts[max(j - 1, 0)], pts[min(j + 1, 16)]
        if b - a <= REFINED * red.rad:
            break
    return best, "the condition of the force equations falls to 0 there"


def _force_values(red, angles) -> dict:
    """name -> the force quantities' values at ``angles`` (none singular)."""
    fr = red.sw.evaluate(np.asarray(angles, dtype=float))
    red.probing = True  # (the probes are near the singular angle on purpose)
    try:
        return {
            nm: np.asarray(arr, dtype=float)
            for nm, _, arr, _ in red.values(fr)
            if nm in red.force_names
        }
    finally:
        red.probing = False


def _limits(red, ts, sides) -> dict:
    """name -> each force quantity's limit at the singular angle ``ts`` (see
    :func:`at_singular`)."""
    h = red.rad * _H
    if len(sides) == 2:  # S(k h), the mean of the two sides, at h^2 = 1, 4, 9: at 0
        q = _force_values(red, ts + h * np.array([-1.0, 1.0, -2.0, 2.0, -3.0, 3.0]))
        return {
            nm: 0.75 * (v[0] + v[1]) - 0.3 * (v[2] + v[3]) + 0.05 * (v[4] + v[5])
            for nm, v in q.items()
        }
    q = _force_values(red, ts + sides[0] * h * np.array([1.0, 2.0, 3.0, 4.0]))
    return {nm: 4 * v[0] - 6 * v[1] + 4 * v[2] - v[3] for nm, v in q.items()}


def singular_note(red, deg) -> tuple:
    """The summary's note of the angles (a driving block's places) where the force
    equations are singular."""
    out = []
    for ts, words in sorted(red.singular.items()):
        at = (
            f"crank angle {deg(ts):.4f} deg"
            if red.sw.domain.periodic
            else f"{deg(ts):.6g} {red.scene.units}"
        )
        out.append(
            f"the force equations are singular at {at}: {words}; there each force is the "
            "limit of its values either side, or is marked as growing without bound"
        )
    return tuple(out)
