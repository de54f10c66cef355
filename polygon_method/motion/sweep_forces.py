"""A sweep's forces where a group's equations are exactly singular at some of its angles (a
parallel crank's dead point, the coupler and the rocker in one line: the moments about the
pins cannot hold the force between them). The force analysis is vectorised over the whole
sweep and refuses it all when one angle is singular; here the angles are halved until each
singular one stands alone, the forces are found at every other angle, and the singular
angles are said row by row: their force cells are left empty (a masked entry: never a NaN
or an infinity in the CSV), and ``condition_forces`` is 0 there (elsewhere the least
condition of the groups' equations, 1 best).

A sweep of n angles with k singular ones costs about 2 k log2(n) vectorised analyses more;
one with none, nothing more.
"""

from __future__ import annotations

import numpy as np

from ..common.errors import PolygonMethodError

#: the words of the force analysis where a group's equations have no unique solution (its
#: pin forces, or a driving cylinder's force: ``... is not determined here``)
UNDETERMINED = "not determined here"


def take(res, rows):
    """The sweep ``res`` (a :class:`~.sweeps.SweepResult`) at the angles ``rows`` only
    (indices, in order): every array over its angles cut to them."""
    n = len(res.theta)

    def cut(v):
        if isinstance(v, dict):
            return {k: cut(x) for k, x in v.items()}
        if isinstance(v, tuple):
            return tuple(cut(x) for x in v)
        if isinstance(v, np.ndarray) and v.ndim and v.shape[0] == n:
            return v[rows]
        return v

    return type(res)(
        res.scene,
        res.plan,
        res.theta[rows],
        cut(res.P),
        cut(res.V),
        cut(res.A),
        cut(res.W),
        cut(res.Al),
        cut(res.S),
        cut(res.cond),
        cut(res.rubbing),
        cut(res.input_torque),
        res.requested,
        res.left_out,
        res.domain,
        res.notes,
    )


def _undetermined(exc) -> bool:
    return UNDETERMINED in exc.message


def by_rows(res, analyse, cut=take):
    """``(forces, rows, why)``: the force analysis ``analyse`` over the whole sweep ``res``
    (``rows`` None); or, where a group's equations are exactly singular at some angles, over
    the others (``forces`` over ``cut(res, rows)``, ``rows`` their indices) and ``why``,
    each singular angle's index -> the words; None where the analysis covers no angle (or
    not the plan). ``cut`` takes the angles ``rows`` of ``res`` (:func:`take` for a
    sweep)."""
    try:
        return analyse(res), None, {}
    except PolygonMethodError as exc:
        if not _undetermined(exc):
            return None
    good, why = [], {}
    stack = [np.arange(len(res.theta))]
    while stack:
        rows = stack.pop()
        try:
            analyse(cut(res, rows))
        except PolygonMethodError as exc:
            if not _undetermined(exc):
                return None
            if len(rows) == 1:
                why[int(rows[0])] = exc.message
            else:
                half = len(rows) // 2
                stack += [rows[half:], rows[:half]]
            continue
        good.append(rows)
    if not good:
        return None
    rows = np.sort(np.concatenate(good))
    return analyse(cut(res, rows)), rows, why


def spread(cols, rows, n):
    """The columns ``(name, unit, array over rows)`` over all ``n`` angles: masked (empty in
    the CSV) where the forces are not determined."""
    mask = np.ones(n, dtype=bool)
    mask[rows] = False
    out = []
    for name, unit, a in cols:
        full = np.zeros(n)
        full[rows] = np.asarray(a, dtype=float)
        out.append((name, unit, np.ma.masked_array(full, mask)))
    return out


def conditions(f, rows, n):
    """``condition_forces``: the least condition of the force groups' equations at each of
    ``n`` angles (1 best), 0 where they are singular (not in ``rows``; ``rows`` None: all)."""
    m = np.ones(len(rows) if rows is not None else n)
    for st in f.steps:
        m = np.minimum(m, np.broadcast_to(np.asarray(st.condition, dtype=float), m.shape))
    if rows is None:
        return m
    full = np.zeros(n)
    full[rows] = m
    return full


def csv_rows(data_cols) -> str:
    """CSV lines of the columns (arrays, some masked): full precision, a masked entry an empty
    cell."""
    lines = []
    cols = [(np.ma.getdata(a).astype(float), np.ma.getmaskarray(a)) for a in data_cols]
    n = len(cols[0][0]) if cols else 0
    for i in range(n):
        lines.append(",".join("" if m[i] else f"{float(d[i]):.17g}" for d, m in cols))
    return "".join(line + "\n" for line in lines)
