"""The page's forces on the configuration diagram, moving with the mechanism: each body's
inertia force on the book's single line (offset from G by h), and, as a layer the reader
turns on, every pin force, guide force, rolling contact, load, weight and driver's force
and every couple, all at one round force scale for the cycle.

Everything is read from the force analysis' free bodies over the sweep
(:attr:`~polygon_method.forces.Forces.free`, the same records the forces sheet draws): the
view works no force out. A pin, a guide or a contact joins two bodies: it is drawn once,
as the force on ``on`` by ``by`` (the book's ``F32``); the other body feels its opposite.
The numbers are kept to the last bit (not rounded as the motion's are), so that each body's
drawn forces can be checked to balance frame by frame.
"""

from __future__ import annotations

import numpy as np

from ..common.errors import PolygonMethodError
from ..common.tolerances import TOL
from ..motion import sweep_forces
from ..forces import FRAME, Side, analyse, couple_label, side_label
from ..polygons.scales import display_unit, newton_scale

__all__ = ["force_layers", "FORCES_CM"]

#: the longest force's arrow over the cycle on the page's configuration (cm)
FORCES_CM = 2.0
#: the kinds a joint's force is: drawn once for its two bodies
PAIRED = ("pin", "guide", "contact")


def _per_frame(x, n) -> np.ndarray:
    return np.broadcast_to(np.asarray(x, dtype=float), (n,))


def _flat(xy, n) -> list:
    """(x, y) per frame -> [x0, y0, x1, y1, ...], every bit kept."""
    x, y = (_per_frame(c, n) for c in xy)
    return [float(v) for v in np.column_stack([x, y]).ravel()]


def _where(res, body, n):
    """Per frame, where a body's couple is drawn: a block at its pin, a link or a cylinder
    half-way between its ends."""
    sc = res.scene
    if body.startswith("block "):
        return _flat(res.P[body[6:]], n)
    cyl = sc.cylinder(body)
    p, q = (cyl.barrel, cyl.rod) if cyl is not None else (sc.link(body).p, sc.link(body).q)
    (px, py), (qx, qy) = res.P[p], res.P[q]
    return _flat(((np.asarray(px) + qx) / 2, (np.asarray(py) + qy) / 2), n)


def offset_points(inertia, n, reach):
    """Per frame, the point of the single resultant's line nearest G, as a book draws the
    inertia force: ``G + (M / |F|^2) (Fy, -Fx)`` with M the couple ``-I alpha`` (its moment
    about G is then M); G itself where the body has no couple, no force, or where the line
    would lie farther than ``reach`` (the longest link) from G (the force nearly zero: the
    couple alone).

    >>> from types import SimpleNamespace as NS
    >>> i = NS(G=(0.0, 0.0), force=(10.0, 0.0), couple=-2.0)   # moment of F at H: -2
    >>> [round(float(c), 12) for c in np.ravel(offset_points(i, 1, 1.0))]
    [0.0, 0.2]
    """
    gx, gy = (_per_frame(c, n) for c in inertia.G)
    fx, fy = (_per_frame(c, n) for c in inertia.force)
    m = _per_frame(inertia.couple, n)
    f2 = fx * fx + fy * fy
    with np.errstate(divide="ignore", invalid="ignore"):
        k = np.where(f2 > 0, m / np.where(f2 > 0, f2, 1.0), 0.0)
    dx, dy = k * fy, -k * fx
    far = np.hypot(dx, dy) > reach
    dx, dy = np.where(far, 0.0, dx), np.where(far, 0.0, dy)
    return gx + dx, gy + dy


def _inertia(res, f, n) -> list:
    """Each massive body's inertia force through H, with the part of its couple the line
    does not carry (``C``: the couple where the force is drawn through G)."""
    reach = max(lk.length for lk in res.scene.links)
    out = []
    for i in f.inertia:
        hx, hy = offset_points(i, n, reach)
        gx, gy = (_per_frame(c, n) for c in i.G)
        through_g = (hx == gx) & (hy == gy)  # no line carries the couple: drawn alone
        rest = np.where(through_g, _per_frame(i.couple, n), 0.0)
        out.append(
            {
                "body": i.body,
                "label": side_label(
                    Side("inertia", i.body, "", "", (0.0, 0.0), (0.0, 0.0)), f.numbers
                ),
                "G": _flat(i.G, n),
                "F": _flat(i.force, n),
                "H": _flat((hx, hy), n),
                "C": [float(c) for c in rest],
            }
        )
    return out


def _joints(res, f, n) -> tuple:
    """(the arrows: each joint's force once, each load, weight and driver's force; the
    couples but the inertia's), from the free bodies."""
    arrows, couples, seen = [], [], set()
    for fb in f.free:
        for s in fb.sides:
            if s.what == "inertia":
                continue
            if s.what in PAIRED:
                key = (s.what, s.point, frozenset((s.on, s.by)))
                if key in seen:
                    continue
                seen.add(key)
            arrows.append(
                {
                    "what": s.what,
                    "on": s.on,
                    "by": s.by or None,
                    "label": side_label(s, f.numbers),
                    "point": s.point,
                    "at": _flat(s.at, n),
                    "F": _flat(s.vector, n),
                }
            )
        for c in fb.couples:
            if c.what != "inertia":  # (the inertia layer carries it)
                couples.append(
                    {
                        "what": c.what,
                        "on": c.on,
                        "label": couple_label(c, f.numbers),
                        "at": _where(res, c.on, n),
                        "C": [float(v) for v in _per_frame(c.value, n)],
                    }
                )
    return arrows, couples


def force_layers(res, n):
    """``(inertia, forces)`` of the page, or ``(None, None)`` without masses or where the
    force analysis does not cover the plan. ``inertia``: ``{"text", "perCm", "bodies":
    [{"body", "label", "G", "F", "H", "C"}]}``; ``forces``: ``{"text", "perCm",
    "arrows": [{"what", "on", "by", "label", "point", "at", "F"}], "couples": [{"what",
    "on", "label", "at", "C"}], "numbers": {body: its number}}``; both at one round force
    scale (the largest force over the cycle at most :data:`FORCES_CM`)."""
    if not res.scene.has_forces:
        return None, None
    try:
        at, rows, f = _determined(res)
        m = n if rows is None else len(rows)
        arrows, couples = _joints(at, f, m)
    except PolygonMethodError:
        return None, None
    bodies = _inertia(at, f, m)
    if rows is not None:  # frames where the forces are not determined: none drawn there
        for item in arrows + couples + bodies:
            _spread(item, rows, n)
    sizes = [np.hypot(b["F"][0::2], b["F"][1::2]) for b in bodies]
    sizes += [np.hypot(a["F"][0::2], a["F"][1::2]) for a in arrows]
    size = max((float(np.max(s)) for s in sizes), default=0.0)
    s = newton_scale(size, FORCES_CM)
    scale = {"text": display_unit(s.text), "perCm": s.per_cm}
    inertia = {**scale, "bodies": bodies} if bodies else None
    numbers = {b: k for b, k in f.numbers.items() if b != FRAME}
    forces = {**scale, "arrows": arrows, "couples": couples, "numbers": numbers}
    if rows is not None:  # (their frames' indices, for a reader or a test)
        forces["singular"] = sorted(set(range(n)) - {int(r) for r in rows})
    return inertia, forces


def _determined(res):
    """``(the sweep at the frames where the forces are determined, their indices or None
    for all, the forces there)``: a frame where a group's force equations are singular (a
    parallel crank's dead point), or within ``TOL.singular`` of it in their condition (the
    rounding's hair: forces of 1e19 N there, which would set the scale), is left out."""
    got = sweep_forces.by_rows(res, analyse)
    if got is None:
        raise PolygonMethodError("forces: not determined at any frame")
    f, rows, _ = got
    at = res if rows is None else sweep_forces.take(res, rows)
    near = sweep_forces.conditions(f, None, len(at.theta)) < TOL.singular
    if near.any():
        keep = np.flatnonzero(~near)
        rows = keep if rows is None else np.asarray(rows)[keep]
        at = sweep_forces.take(res, rows)
        f = analyse(at)
    return at, rows, f


def _spread(item, rows, n):
    """A layer's item over the ``rows`` of ``n`` frames: its forces and couples (``F``,
    ``C``) nought elsewhere (not drawn), its places those of the nearest frame kept."""
    m = len(rows)
    near = np.searchsorted(rows, np.arange(n)).clip(0, m - 1)
    alt = (near - 1).clip(0, m - 1)
    closer = np.where(
        np.abs(rows[alt] - np.arange(n)) < np.abs(rows[near] - np.arange(n)), alt, near
    )
    for key, v in item.items():
        if not isinstance(v, list) or len(v) not in (m, 2 * m):
            continue
        a = np.asarray(v, dtype=float).reshape(m, -1)
        full = a[closer]
        if key in ("F", "C"):
            full[np.setdiff1d(np.arange(n), rows)] = 0.0
        item[key] = [float(x) for x in full.ravel()]
