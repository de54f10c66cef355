"""A sweep summary's extremes at the limit positions of a crank that rocks (or of a driving
block's travel): where the requested angles reach a limit, each quantity is evaluated at
the limit itself and taken when it is beyond the samples' (a slider's stroke ends there, the
transmission angle is 0 there), a transmission angle's minimum next to a change point is 0
at it, and a quantity that grows without bound towards a limit is marked so. ``red`` is the
summary's reducer (:class:`~polygon_method.linkage.summary._Reducer`): its sweeper ``sw``,
``scene``, the parameter's size of a radian ``rad``, its quantities and their sizes.
"""

from __future__ import annotations

import math

import numpy as np

from ..common.tolerances import AT_LIMIT, SAME, SMOOTH
from ..scene import FixedPath

__all__ = [
    "limits_in",
    "limit_positions",
    "change_point_minima",
    "at_limits",
    "unbounded_at_limits",
    "unbounded_sizes",
]

#: inward offsets (rad) from a limit position at which a quantity's value is compared with
#: its value at the limit itself (equal to :data:`SMOOTH` of its kind: it is finite and
#: smooth there)
_AT_LIMIT = (AT_LIMIT, 2 * AT_LIMIT)


def limit_positions(red, rows, theta, spacing):
    """Where the crank rocks, a slider's extreme place may be at a limit position of
    the crank (between two samples, where the velocities are not defined): its place
    there, from the positions alone, is an extreme too, so that the summary gives the
    same stroke as `linkage`. Only limits the requested angles reach are taken."""
    dom = red.sw.domain
    if dom.full_turn or not dom.limits or spacing is None:
        return
    mapped, _ = dom.map(np.asarray(theta, dtype=float))
    lims = [lp.theta for lp in dom.limits if np.min(np.abs(mapped - lp.theta)) <= 1.5 * spacing]
    if not lims:
        return
    fr = red.sw.evaluate(np.array(lims), vel=False, acc=False)
    by = {row[0]: row for row in rows}
    for s in red.scene.sliders:
        row = by.get(f"s_{s.key}")
        if row is None or not isinstance(s, FixedPath):
            continue
        (qx, qy), (ux, uy) = s.through, s.u
        x, y = fr.P[s.point]
        for t, v in zip(lims, (x - qx) * ux + (y - qy) * uy):
            v = float(v)
            if not math.isfinite(v):
                continue
            if v > row[2]:
                row[2], row[3] = v, t
            if v < row[4]:
                row[4], row[5] = v, t


def change_point_minima(red, rows, spacing, lo, hi):
    """At a change point the step's two assemblies meet: its transmission angle is 0
    there (the samples next to it, whose construction is not trusted, carry the refusal
    threshold's value instead). A row whose minimum is next to a followed change point
    of its step gets 0 at the change point's angle, where that is within the requested
    angles ``lo`` to ``hi``."""
    dom = red.sw.domain
    near = 2 * (spacing or 0.0) + 0.02 * red.rad
    for cp in dom.change_points:
        if not cp.followed:
            continue
        for row in rows:
            if row[0] != f"mu at {cp.point}" or row[5] is None:
                continue
            (tm,), _ = dom.map(np.array([row[5]]))
            d = cp.theta - float(tm)
            if dom.full_turn:
                d = (d + 0.5 * dom.period) % dom.period - 0.5 * dom.period
            if abs(d) < near and lo <= row[5] + d <= hi:
                row[4], row[5] = 0.0, row[5] + d


def limits_in(red, theta, spacing):
    """The limit positions within the requested angles: next to a sample (within one
    and a half spacings, mapped into the domain)."""
    dom = red.sw.domain
    if dom.full_turn or not dom.limits or not len(theta):
        return []
    t, _ = dom.map(np.asarray(theta, dtype=float))
    reach = 1.5 * (spacing or 0.0) + SAME
    out = []
    for lp in dom.limits:
        if float(np.min(np.abs(t - lp.theta))) <= reach:
            inward = -1.0 if abs(lp.theta - dom.hi) < abs(lp.theta - dom.lo) else 1.0
            out.append((lp, inward))
    return out


def at_limits(red, rows, theta, spacing):
    """Each quantity evaluated at the limit positions within the requested angles, the
    crank's exact angles there, and taken as the maximum or minimum where it is beyond
    the samples': the transmission angle is 0 there, a block's travel ends there. A
    quantity is taken only where it is finite and smooth at the limit (its values one and
    two :data:`AT_LIMIT` inside agree with it to :data:`SMOOTH` of its kind); one that grows without bound
    there is marked so (:func:`unbounded_at_limits`)."""
    scales = red.scales()
    for lp, inward in limits_in(red, theta, spacing):
        pts = lp.theta + inward * red.rad * np.array((0.0,) + _AT_LIMIT)
        fr = red.sw.evaluate(pts)
        q = {nm: (u, np.asarray(arr, dtype=float)) for nm, u, arr, _ in red.values(fr)}
        for row in rows:
            nm = row[0]
            if nm not in q:
                continue
            u, vals = q[nm]
            v = float(vals[0])
            if not math.isfinite(v):
                continue
            exact = u == "deg" or nm.startswith("s_")  # positions: exact at the limit
            if not exact:
                tol = SMOOTH * max(scales.get(u, 0.0), abs(v))
                if not (np.all(np.isfinite(vals)) and np.all(np.abs(vals - v) <= tol)):
                    continue
            if row[3] is None:  # a constant stays one
                continue
            if v > row[2]:
                row[2], row[3] = v, float(lp.theta)
            if v < row[4]:
                row[4], row[5] = v, float(lp.theta)


def unbounded_at_limits(red, rows, theta, spacing) -> dict:
    """(name, sense) -> the limit position's angle, for every quantity that grows
    without bound towards a limit position within the requested angles (a toggle of the
    driven side: velocities as 1 / sqrt(d), accelerations as 1 / d^1.5, d the crank's
    distance from the limit), wherever its sampled extreme is. The quantity is probed
    at 1e-2, 1e-3 and 1e-4 rad from the limit (for a driving block, those parts of its
    travel over 2 pi); it is unbounded where its size grows,
    with one sign, by more than twice each decade (as d^-0.5 does, 3.2 times: a
    quantity that tends to a finite value, even one that passes 0 near the first
    probe, does not grow so over the last decade)."""
    found = {}
    for lp, inward in limits_in(red, theta, spacing):
        probe = lp.theta + inward * red.rad * np.array([1e-2, 1e-3, 1e-4])
        fr = red.sw.evaluate(probe)
        q = {nm: np.asarray(arr, dtype=float) for nm, _, arr, _ in red.values(fr)}
        for nm, u, mx, tmx, mn, tmn, what in rows:
            if u == "deg" or nm not in q or tmx is None:
                continue
            vals = q[nm]
            for sense in (1.0, -1.0):
                v = sense * vals
                if (
                    np.all(np.isfinite(v)) and v[0] > 0 and v[1] > 2.0 * v[0] and v[2] > 2.0 * v[1]
                ):  # (d^-0.5 grows 3.2 times a decade)
                    found.setdefault((nm, sense), lp.theta)
    return found


def unbounded_sizes(red, rows, unbounded, theta, spacing):
    """Each unbounded end's value (``unbounded``: (name, sense) -> the angle it grows
    towards) made its value 1e-2 rad (of the parameter) from that angle, inward of a limit
    position, the larger of the two sides elsewhere: a size of the quantity no grid decides
    (the sample or refinement nearest the angle would: 1e13 N for a pin force refined to
    within REFINED of a toggle), which the table writes as unbounded and against which the
    other end's rounding noise is judged."""
    if not unbounded:
        return
    dom = red.sw.domain
    inward = {lp.theta: s for lp, s in limits_in(red, theta, spacing)}
    where = []  # (name, sense, angle probed)
    for (nm, sense), t in unbounded.items():
        for s in [inward[t]] if t in inward else [-1.0, 1.0]:
            p = t + s * red.rad * 1e-2
            if dom.periodic or dom.lo <= p <= dom.hi:
                where.append((nm, sense, p))
    if not where:
        return
    fr = red.sw.evaluate(np.array([p for _, _, p in where]))
    q = {nm: np.asarray(arr, dtype=float) for nm, _, arr, _ in red.values(fr)}
    got = {}
    for k, (nm, sense, _) in enumerate(where):
        v = sense * float(q[nm][k]) if nm in q else math.nan
        if math.isfinite(v) and v > got.get((nm, sense), -math.inf):
            got[(nm, sense)] = v
    for row in rows:
        for sense, i in ((1.0, 2), (-1.0, 4)):
            if (row[0], sense) in got:
                row[i] = sense * got[(row[0], sense)]
