"""The ``[points]`` table (a part of the scene reader): carried points, each set out on its
link by ``along`` (with ``from``) or by ``distances`` with ``turn``, with how far the rounding
of its distances may move it (also a mass's centre on its link, ``[masses]``)."""

from __future__ import annotations

import math

from ..common.tolerances import TOL
from .records import CarriedPoint
from .table_help import _suggest
from .triangle import along_length, apex, not_on_link, polar_points


class _CarriedPoints:
    """The reader's methods for [points] (mixed into the reader)."""

    def carried_points(self, index, ground):
        table = polar_points(self, self.table("points"))
        local = {}  # link key -> {point: (x, y) in the link frame, P at 0, Q at (L, 0)}
        spreads = {}  # point -> how far its place on the link may be off (m)
        out = []
        for name, spec in table.items():
            self.point_name(name, "points")
            if name in ground:
                raise self.error(
                    f"{name} is a ground point and a carried point; a point has one role",
                    "points",
                    name,
                )
            if not isinstance(spec, dict) or "on" not in spec:
                raise self.error(
                    'a carried point is a table such as { on = "BC", along = '
                    '40 } or { on = "BC", distances = { B = 45, C = 30 }, turn '
                    '= "cw" }',
                    "points",
                    name,
                )
            allowed = ("on", "along", "from", "distances", "turn")
            for k in spec:
                if k not in allowed:
                    raise self.error(f"unknown key '{k}'{_suggest(k, allowed)}", "points", name)
            link, pts = self.find_link(spec["on"], "points", name)
            if name in link.points:
                raise self.error(
                    f"{name} is a joint of link {link.key}; it cannot also be carried on it",
                    "points",
                    name,
                )
            frame = local.setdefault(link.key, {link.p: (0.0, 0.0), link.q: (link.length, 0.0)})
            xy, how, spread, source = self.on_link(spec, link, pts, frame, "points", name, spreads)
            raw = self.table("points").get(name)
            if isinstance(raw, dict) and "angle" in raw:  # as the book gave it: at an angle
                how = self._polar_words(link, name, source)
            frame[name] = xy
            L = link.length
            spreads[name] = spread
            out.append(CarriedPoint(name, link.key, xy[0] / L, xy[1] / L, how, spread, source))
        return out

    def _polar_words(self, link, name, source) -> str:
        """A point given at a distance from a link's end and an angle from its line, as the
        book gave it ("OE = 40 mm at 120 deg ccw from OA"), with the other side the cosine
        rule makes (the triangle it is set out by)."""
        _, r1, d1, r2, d2, turn = source
        L = link.length
        deg = math.degrees(
            math.acos(max(-1.0, min(1.0, (d1 * d1 + L * L - d2 * d2) / (2 * d1 * L))))
        )
        return (
            f"on {link.key}, {r1}{name} = {self._words(d1)} at {deg:.6g} deg "
            f"{'ccw' if turn > 0 else 'cw'} from {r1}{r2} ({r2}{name} = {self._words(d2)} by "
            "the cosine rule)"
        )

    def on_link(self, spec, link, pts, frame, table, name, spreads=None):
        """(x, y) in the link's frame (P at 0, Q at (L, 0); ``frame`` the points known in
        it) of a place given as ``along`` (with ``from``) or ``distances`` with ``turn``, the
        words of it, how far the rounding of its distances and of the points it is set out
        from (``spreads``, by name) may move it, and how it was given (``source``)."""
        spreads = spreads or {}
        on = spec.get("on", link.key)
        has_along, has_dist = "along" in spec, "distances" in spec
        if has_along == has_dist:
            raise self.error(
                "give either along (with an optional from) or distances with turn", table, name
            )
        if has_along:
            return self._along_place(spec, link, pts, frame, table, name, on)
        return self._distances_place(spec, link, frame, table, name, on, spreads)

    def _along_place(self, spec, link, pts, frame, table, name, on):
        """:meth:`on_link` of a place given as ``along`` (with ``from``): on the link's line,
        produced beyond an end where it is longer or negative; set out exactly (no spread)."""
        start = spec.get("from", pts[0])
        if start not in link.points:
            raise self.error(f"from = {start!r} is not an end of {link.key}", table, name)
        if "turn" in spec:
            raise self.error("turn goes with distances, not with along", table, name)
        d = along_length(self, spec["along"], link, table, name)
        sx, sy = frame[start]
        ox, oy = frame[link.other(start)]
        t = d / link.length
        xy = (sx + t * (ox - sx), sy + t * (oy - sy))
        spread, source = 0.0, ("along", start, d)
        far = link.other(start)
        where = (
            f"{on} produced beyond {start}"
            if d < 0
            else f"{on} produced beyond {far}"
            if d > link.length
            else on
        )
        how = f"on {where}, {self._words(abs(d))} from {start}"
        return xy, how, spread, source

    def _distances_place(self, spec, link, frame, table, name, on, spreads):
        """:meth:`on_link` of a place given as ``distances`` from two points of the link with
        ``turn`` (how the triangle reads): the apex, and how far the rounding of the
        distances and of the two points may move it."""
        dist = spec["distances"]
        if not isinstance(dist, dict) or len(dist) != 2:
            raise self.error(
                "distances names two points of the link, e.g. { B = 45, C = 30 }", table, name
            )
        turn = spec.get("turn")
        if turn not in ("cw", "ccw"):
            raise self.error(
                'turn = "cw" or "ccw": how the triangle (the two points of distances, then '
                'this point) reads (a point "below BC", B to the left of C, reads cw)',
                table,
                name,
            )
        (r1, d1), (r2, d2) = dist.items()
        for r in (r1, r2):
            if r not in frame:  # (or not yet: given below in [points])
                raise self.error(not_on_link(self, r, link, name, table), table, name)
        d1 = self.length(d1, table, name)
        d2 = self.length(d2, table, name)
        (x1, y1), (x2, y2) = frame[r1], frame[r2]
        e = math.hypot(x2 - x1, y2 - y1)
        u = self.scale()
        if d1 + d2 < e * (1 - TOL.closure) or abs(d1 - d2) > e * (1 + TOL.closure):
            if d1 + d2 < e:
                why = (
                    f"{r1}{name} + {r2}{name} = {(d1 + d2) / u:g} < {r1}{r2} = "
                    f"{e / u:g} {self.unit}"
                )
            else:
                why = (
                    f"|{r1}{name} - {r2}{name}| = {abs(d1 - d2) / u:g} > {r1}{r2} = "
                    f"{e / u:g} {self.unit}"
                )
            raise self.error(f"the triangle {r1}{r2}{name} cannot close: {why}", table, name)
        # the height by Heron's formula in a stable form (never cancelled to 0 on a
        # nearly flat triangle), and how far the rounding of the distances and of the
        # points it is set out from may move the point
        along, h, spread = apex(d1, d2, e)
        gain = 1.0 + (d1 + d2) / e
        spread += gain * (spreads.get(r1, 0.0) + spreads.get(r2, 0.0))
        source = ("distances", r1, d1, r2, d2, 1 if turn == "ccw" else -1)
        ex, ey = (x2 - x1) / e, (y2 - y1) / e
        sign = 1.0 if turn == "ccw" else -1.0
        xy = (x1 + along * ex - sign * h * ey, y1 + along * ey + sign * h * ex)
        how = (
            f"on {on}, {r1}{name} = {self._words(d1)}, {r2}{name} = "
            f"{self._words(d2)}, {r1}{r2}{name} read {turn}"
        )
        return xy, how, spread, source
