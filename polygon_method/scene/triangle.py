"""A point set out by its distances from two points (a carried point's triangle), and how
far its place may be off when the triangle is nearly flat.

The apex X of the triangle R1 R2 X with ``|R1 X| = d1``, ``|R2 X| = d2``, ``|R1 R2| = e``
lies ``along = (d1^2 - d2^2 + e^2) / 2e`` from R1 towards R2 and ``h`` off that line.
Written as ``h^2 = d1^2 - along^2`` the height cancels to nothing when the triangle is
nearly flat (``d1 + d2`` close to ``e``: a height of one part in ten billion of the sides
comes out as 0).
Here ``h = 2 area / e`` with the area by Heron's formula in the stable form (the sides
sorted, ``a >= b >= c``)::

    area = sqrt((a + (b + c)) (c - (a - b)) (c + (a - b)) (a + (b - c))) / 4

which is exact to a few roundings for any shape. What no formula can remove is the
rounding of the distances themselves (given in mm, held in metres): near flat the height
moves by ``dF / 2h`` for a change ``dF`` of ``F = h^2``, and never by more than
``sqrt(dF)``. :func:`apex` returns that as ``spread``.

>>> along, h, spread = apex(3.0, 4.0, 5.0)
>>> along, h
(1.8, 2.4)
>>> _, h, spread = apex(0.04, 0.06, 0.1)     # flat: on the line, to the rounding
>>> h, round(spread * 1e9, 1)        # nm
(0.0, 1.6)
"""

from __future__ import annotations

import math
import re

from ..common.tolerances import SAME
from ..common.units import UNITS
from .records import split_name

__all__ = ["apex", "not_on_link", "polar_points", "along_length", "ROUNDING"]

#: the rounding of a length given in the scene's unit and held in metres, relative
ROUNDING = 2.0**-52


def apex(d1: float, d2: float, e: float, rounding: float = ROUNDING):
    """(along, h, spread) of the apex at distances ``d1, d2`` from two points ``e`` apart:
    ``h >= 0`` its height over their line, ``spread`` (m) how far it may be from the apex
    of the distances as written (each of them, and ``e``, off by ``rounding`` of itself).
    A triangle that does not quite close (within the caller's tolerance) is flat: ``h =
    0``, and its spread includes the height that closing it would take."""
    along = ((d1 - d2) * (d1 + d2) + e * e) / (2 * e)
    a, b, c = sorted((d1, d2, e), reverse=True)
    prod = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c))
    short = 0.0
    if prod > 0:
        h = prod**0.5 / (2 * e)
    else:
        h = 0.0
        short = -prod / (4 * e * e)
    # F = h^2 = d1^2 - along^2: its change for each length off by `rounding` of itself
    far = abs(e - along)
    dF = 2 * rounding * (d1 * d1 * far + abs(along) * d2 * d2 + abs(along) * far * e) / e
    dF += 8 * ROUNDING * h * h  # the formula's own roundings
    dF += short
    dh = dF**0.5 if h == 0.0 else min(dF**0.5, dF / h)
    d_along = rounding * (d1 * d1 + d2 * d2 + far * e) / e + 4 * ROUNDING * abs(along)
    return along, h, dh + d_along


def polar_points(reader, table):
    """``[points]`` with each point given by its distance and angle from an end of its link
    (a coupler point as Norton and Uicker give it, "BE = 40 mm at 30 deg ccw from BC": ``E
    = { on = "BC", from = "B", along = 40, angle = 30 }``; the angle ccw from the line from
    ``from`` to the link's other end, or ``"30 deg cw"``) given instead by its distances
    from the link's two ends, the second by the cosine rule in a form that does not cancel,
    ``d2^2 = (d - L)^2 + 4 d L sin^2(a / 2)``, the triangle read ccw where the angle is
    between 0 and 180 deg. The other points as they are."""
    if not isinstance(table, dict) or not any(
        isinstance(s, dict) and "angle" in s and "on" in s for s in table.values()
    ):
        return table
    return {
        name: _polar(reader, spec, name)
        if isinstance(spec, dict) and "angle" in spec and "on" in spec
        else spec
        for name, spec in table.items()
    }


def _polar(reader, spec, name):
    link, pts = reader.find_link(spec["on"], "points", name)
    start = spec.get("from", pts[0])
    if start not in link.points:
        raise reader.error(f"from = {start!r} is not an end of {link.key}", "points", name)
    if "along" not in spec or "distances" in spec or "turn" in spec:
        raise reader.error(
            "angle goes with along, the distance from the link's end named by from: "
            '{ on = "BC", from = "B", along = 40, angle = 30 } (30 deg ccw from BC)',
            "points",
            name,
        )
    a = reader.qty(spec["angle"], "angle", "points", name, default_unit="deg", allow_sense=True)
    d, L = reader.length(spec["along"], "points", name), link.length
    if abs(math.sin(a.value)) < SAME:  # on the link's line: along says it
        raise reader.error(
            f"angle = {spec['angle']!r} puts {name} on the line of {link.key}: give along "
            "alone (negative: beyond the start)",
            "points",
            name,
        )
    d2 = math.sqrt((d - L) ** 2 + 4 * d * L * math.sin(a.value / 2) ** 2)
    u = reader.scale()
    rest = {k: v for k, v in spec.items() if k not in ("along", "from", "angle")}
    turn = "ccw" if math.sin(a.value) > 0 else "cw"
    return {**rest, "distances": {start: d / u, link.other(start): d2 / u}, "turn": turn}


def not_on_link(reader, point, link, name, table) -> str:
    """Why ``point``, named in ``distances`` of ``name``, is no point of ``link``: it is
    not, or (in ``[points]``, whose points are set out in order) not yet, being set out on
    the link further down."""
    spec = reader.table("points").get(point) if table == "points" else None
    on = spec.get("on") if isinstance(spec, dict) else None
    if isinstance(on, str) and frozenset(split_name(on)) == frozenset(link.points):
        return (
            f"{point} is not a point of link {link.key} yet: {point} is set out on it below "
            f"{name} in [points]; give {point} first (a point is set out from those above it)"
        )
    return f"{point} is not a point of link {link.key}"


_LENGTHS = {u.lower() for u in UNITS["length"]}  # a link named as a unit (CM): "of CM"
_PART = re.compile(r"([0-9]*\.?[0-9]+)\s*(?:/\s*([0-9]+))?\s*(of\s+)?([A-Za-z][A-Za-z0-9-]*)")
_MIDDLE = re.compile(r"(?:the\s+)?(?:mid-?\s*point|middle)(?:\s+of\s+(\S+))?", re.IGNORECASE)


def along_length(reader, raw, link, table, name) -> float:
    """``along`` as a length (m): a number or a quantity in the scene's units, a book's
    "midpoint" (also "the middle", "the mid-point of BC"): half the link, or a part of it
    ("1/3 of BC", "0.4 BC", the link named as written or reversed).

    >>> class R:
    ...     length = staticmethod(lambda raw, *a, **k: float(raw))
    >>> class L:
    ...     p, q, length = "B", "C", 0.15
    >>> along_length(R, "the midpoint", L, "points", "E"), along_length(R, 0.04, L, "points", "E")
    (0.075, 0.04)
    >>> round(along_length(R, "1/3 of CB", L, "points", "E"), 15)
    0.05
    >>> L.p, L.q = "C", "M"     # a link CM: "4 cm" is a length, "0.4 of CM" a part
    >>> along_length(R, "0.4 of CM", L, "points", "E") == 0.4 * 0.15
    True
    """
    ends = (link.p + link.q).upper(), (link.q + link.p).upper()
    middle = _MIDDLE.fullmatch(raw.strip()) if isinstance(raw, str) else None
    if middle is not None:
        if middle.group(1) and middle.group(1).upper().replace("-", "") not in ends:
            raise reader.error(f"along = {raw!r}: {name} is on {link.key}", table, name)
        return link.length / 2
    part = _PART.fullmatch(raw.strip()) if isinstance(raw, str) else None
    named = part is not None and part.group(4).upper().replace("-", "") in ends
    if part is not None and part.group(3) and not named:  # "1/3 of CD" on BC
        raise reader.error(f"along = {raw!r}: {name} is on {link.key}", table, name)
    if named and (part.group(3) or part.group(4).lower() not in _LENGTHS):  # "1/3 of BC"
        if part.group(2) is not None and float(part.group(2)) == 0:
            raise reader.error(f"along = {raw!r}: a part of the link over nought", table, name)
        return float(part.group(1)) / float(part.group(2) or 1) * link.length
    return reader.length(raw, table, name, positive=False)
