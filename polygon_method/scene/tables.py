"""The tables after [ground] and [links]: carried points, sliders, the input, assembly
hints, pins, loads and answers, each checked and turned into records (a part of the
scene reader)."""

from __future__ import annotations

import math
import re

from ..common.errors import SceneError
from ..common.units import did_you_mean
from .angles import read_angle
from .triangle import along_length, apex, not_on_link, polar_points

from .records import (
    CarriedPoint,
    Cylinder,
    guide_words,
    FixedPath,
    GuideSlider,
    Load,
    Pin,
    YokeSlot,
    split_name,
)


def _unit_at(ang: float) -> tuple:
    """(cos, sin) of a direction (rad), exact where it is a whole number of right angles
    to the rounding of the angle (a force "direction = 270" is straight down, not 1.8e-16
    to the side; a path at "180 deg" is horizontal; "90.0000000001 deg" is not vertical:
    near a dead centre that hair matters)."""
    q = ang / (math.pi / 2)
    k = round(q)
    if abs(q - k) <= 4 * 2.0**-53 * max(1.0, abs(q)):
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[k % 4]
    return (math.cos(ang), math.sin(ang))


#: a key a book's words lead to (in [sliders], which says it with through), and how to say it
_OFFSET = ": an offset line of stroke is its through = [x, y] (40 mm below O: [0, -40])"


def _suggest(word, choices) -> str:
    hint = _OFFSET if word == "offset" and "through" in choices else None
    return hint or did_you_mean(word, list(choices))


def _which_point(name, known) -> str:
    """A did-you-mean, or else the scene's points, for a message about an unknown point."""
    names = sorted(known, key=lambda p: (p[0], len(p), p))
    hint = _suggest(name, names)
    if hint or not names:
        return hint
    listed = ", ".join(names[:12]) + (", ..." if len(names) > 12 else "")
    return f" (its points are {listed})"


class _Tables:
    """The scene reader's methods for one table each (mixed into the reader)."""

    def _words(self, metres: float) -> str:
        """A length (m) in the scene's unit, as the step tables write it: ``280 mm``."""
        return f"{metres / self.scale():.6g} {self.unit}"

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
            frame[name] = xy
            L = link.length
            spreads[name] = spread
            out.append(CarriedPoint(name, link.key, xy[0] / L, xy[1] / L, how, spread, source))
        return out

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
        else:
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
            if d1 + d2 < e * (1 - 1e-12) or abs(d1 - d2) > e * (1 + 1e-12):
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

    def sliders(self, index, ground, carried):
        out = []
        for name, spec in self.table("sliders").items():
            self.point_name(name, "sliders")
            if not isinstance(spec, dict):
                raise self.error(
                    'a slider is a table: { path = "horizontal", through = '
                    '[x, y] } or { along = "CP" }',
                    "sliders",
                    name,
                )
            allowed = ("path", "through", "along", "direction")
            for k in spec:
                if k not in allowed:
                    raise self.error(f"unknown key '{k}'{_suggest(k, allowed)}", "sliders", name)
            if isinstance(spec.get("along"), str) and spec["along"].startswith("block "):
                out.append(self.yoke_slot(name, spec, ground))
                continue
            if "direction" in spec:
                raise self.error(
                    'direction goes with along = "block Y" (the slot of a translating yoke Y)',
                    "sliders",
                    name,
                )
            if "along" in spec and (isinstance(spec["along"], list) or "path" in spec):
                out.extend(self.peg(name, spec, ground, carried))
                continue
            if "along" in spec:
                if "through" in spec:
                    raise self.error(
                        "a block slides either on a fixed path or along a link, "
                        "not both (a peg in a fixed slot and in the slot of a "
                        'link: along = "OA" with path = ...)',
                        "sliders",
                        name,
                    )
                guide = spec["along"]
                if (
                    len(split_name(guide)) == 2
                    and not self.index.get(frozenset(split_name(guide)))
                    and any(p in self.ground for p in split_name(guide))
                ):
                    raise self.error(
                        f"the guide {guide} is not in [links]: add it with its length, e.g. "
                        f'"{guide}" = 500 (if the problem does not give the lever\'s length, '
                        "any length will do: it only places the end of the lever)",
                        "sliders",
                        name,
                    )
                link, pts = self.find_link(guide, "sliders", name)
                if name in link.points:
                    raise self.error(
                        f"{name} is an end of {link.key}; a block slides along a "
                        "link between its ends",
                        "sliders",
                        name,
                    )
                if all(p in ground for p in pts):
                    raise self.error(
                        f"{link.key} is fixed (both ends are ground points): "
                        "use path/through for a fixed guide",
                        "sliders",
                        name,
                    )
                out.append(GuideSlider(name, link.key, pts[0], pts[1]))
                continue
            if name in ground:
                raise self.error(
                    f"{name} is a ground point; it cannot slide on a fixed path", "sliders", name
                )
            if name in carried:
                raise self.error(
                    f"{name} is carried on a link and also slides on a fixed "
                    "path: one constraint too many",
                    "sliders",
                    name,
                )
            out.append(self.fixed_path(name, spec, ground))
        for sl in out:  # a yoke's slot: its yoke is a block on a fixed path, not along it
            if isinstance(sl, YokeSlot):
                self.check_yoke(sl, out)
        return out

    def yoke_slot(self, name, spec, ground):
        """``P = { along = "block Y", direction = "vertical" }``: a block at P in the slot of
        the yoke Y (a block on a fixed path), the slot through Y along ``direction``."""
        yoke = spec["along"][len("block ") :].strip()
        if "path" in spec or "through" in spec:
            raise self.error(
                "a block slides either on a fixed path or in a yoke's slot, not both",
                "sliders",
                name,
            )
        why = (
            f"{name} is a ground point; it cannot slide in a moving yoke"
            if name in ground
            else f'{name} cannot slide in its own slot: the yoke is another block, e.g. along = "block Y"'
            if yoke == name
            else "the yoke's slot has no direction: add direction = "
            '"vertical", "horizontal" or an angle such as "60 deg"'
            if "direction" not in spec
            else None
        )
        if why:
            raise self.error(why, "sliders", name)
        ang, label = self.direction(spec["direction"], name)
        return YokeSlot(name, yoke, _unit_at(ang), label)

    def check_yoke(self, sl, sliders):
        """The yoke of a slot is a block on a fixed path, its slot across that path."""
        name, yoke = sl.point, sl.yoke
        path = next((s for s in sliders if s.point == yoke and not s.slot), None)
        if not isinstance(path, FixedPath):
            raise self.error(
                f'along = "block {yoke}": {yoke} must be a block on a fixed '
                f"path in [sliders] (the yoke), e.g. {yoke} = {{ path = "
                '"horizontal" }',
                "sliders",
                name,
            )
        (ux, uy), (dx, dy) = path.u, sl.direction
        if abs(ux * dy - uy * dx) < 1e-9:
            raise self.error(
                f"a pin in two parallel slots: the slot of block {yoke} runs "
                f"{sl.label}, along the yoke's own {guide_words(path.label)}, so "
                "nothing moves the yoke",
                "sliders",
                name,
            )

    def direction(self, value, name):
        """(angle in rad, label) of a direction: "horizontal", "vertical" or an angle."""
        if (
            isinstance(value, str)
            and not re.match(r"^\s*[-+.\d]", value)
            and value not in ("horizontal", "vertical")
        ):
            raise self.error(
                f'{value!r}: use "horizontal", "vertical" or an '
                'angle such as "30 deg"' + _suggest(value, ("horizontal", "vertical")),
                "sliders",
                name,
            )
        if value == "horizontal":
            return 0.0, "horizontal"
        if value == "vertical":
            return math.pi / 2, "vertical"
        ang = self.qty(value, "angle", "sliders", name, default_unit="deg").value
        return ang, f"at {math.degrees(ang):g} deg"

    def fixed_path(self, name, spec, ground, slot=""):
        """The fixed path of ``spec`` (its path and through) for the slider at ``name``."""
        if "path" not in spec:
            raise self.error(
                "the slider's path has no direction: add path = "
                '"horizontal", "vertical" or an angle such as "30 deg"',
                "sliders",
                name,
            )
        path = spec["path"]
        if (
            isinstance(path, str)
            and not re.match(r"^\s*[-+.\d]", path)
            and path not in ("horizontal", "vertical")
        ):
            raise self.error(
                f'path = {path!r}: use "horizontal", "vertical" or an '
                'angle such as "30 deg" or "30 deg below the horizontal"'
                + _suggest(path, ("horizontal", "vertical")),
                "sliders",
                name,
            )
        if path == "horizontal":
            ang, label = 0.0, "horizontal"
        elif path == "vertical":
            ang, label = math.pi / 2, "vertical"
        else:
            # a book's words are in the notes; the label keeps the tables' width
            book = self.book_angle(path, "path", "sliders", name, f"slider {name}'s path")
            ang = (
                book.value
                if book is not None
                else self.qty(path, "angle", "sliders", name, default_unit="deg").value
            )
            label = f"at {math.degrees(ang):g} deg"
        through = spec.get("through")
        if through is None:
            through = ("input pivot", None)
        elif isinstance(through, str):
            if through not in ground:
                raise self.error(
                    f"through = {through!r} is not a ground point{_suggest(through, ground)}",
                    "sliders",
                    name,
                )
            through = ground[through]
        else:
            through = self.coords(through, "sliders", name)
        u = _unit_at(ang)
        record = FixedPath(name, u, through, label, slot, ang)
        if not slot:  # a slider's line of stroke (for angles measured from it)
            self.strokes[name] = ang
            self.fixed.append(record)
        return record

    def peg(self, name, spec, ground, carried):
        """A peg in two slots: ``along = ["OA", "QB"]`` (two slotted links) or ``along =
        "OA"`` with ``path`` (and ``through``): the slot of a link and a fixed slot. Two
        records, one per slot, named ``P_OA`` and ``P_QB`` or ``P_ground``."""
        along = spec["along"]
        guides = along if isinstance(along, list) else [along]
        fixed = "path" in spec
        if len(guides) + fixed != 2 or not guides:
            raise self.error(
                'a peg sits in two slots: along = ["OA", "QB"] (two '
                'slotted links), or along = "OA" with path = ... (a link\'s '
                f"slot and a fixed one); got {len(guides) + fixed}",
                "sliders",
                name,
            )
        if name in ground:
            raise self.error(
                f"{name} is a ground point; a peg in two slots moves along them", "sliders", name
            )
        if name in carried:
            raise self.error(
                f"{name} is carried on a link and also sits in two slots: two constraints too many",
                "sliders",
                name,
            )
        out, seen = [], []
        for guide in guides:
            if not isinstance(guide, str):
                raise self.error(
                    f'along = {guide!r}: a slot is named by its link, e.g. "OA"', "sliders", name
                )
            link, pts = self.find_link(guide, "sliders", name)
            if name in link.points:
                raise self.error(
                    f"{name} is an end of {link.key}; a peg slides in the slot "
                    "of a link between its ends",
                    "sliders",
                    name,
                )
            if all(p in ground for p in pts):
                raise self.error(
                    f"{link.key} is fixed (both ends are ground points): use "
                    "path/through for a fixed slot",
                    "sliders",
                    name,
                )
            if link.key in seen:
                raise self.error(
                    f"a pin in two parallel slots: both are the slot of "
                    f"{link.key}, so the peg can be anywhere along it",
                    "sliders",
                    name,
                )
            seen.append(link.key)
            out.append(GuideSlider(name, link.key, pts[0], pts[1], link.key))
        if fixed:
            out.append(self.fixed_path(name, spec, ground, "ground"))
        elif "through" in spec:
            raise self.error(
                "through goes with path (a fixed slot); a peg in two slotted links has none",
                "sliders",
                name,
            )
        return out

    def cylinders(self, known):
        """``[cylinders] "O-R" = {}``: a cylinder, barrel pivoted at O, rod pinned at R;
        optionally ``{ stroke = [closed, extended] }`` (pin-to-pin lengths)."""
        out = []
        for key, spec in self.table("cylinders").items():
            pts = split_name(key)
            if len(pts) != 2 or pts[0] == pts[1]:
                raise self.error(
                    f"{key!r} is not a cylinder's name: its barrel's pivot, then "
                    'its rod\'s end, e.g. "O-R" or OR',
                    "cylinders",
                    key,
                )
            for p in pts:
                if p not in known:
                    raise self.error(
                        f"no point {p} in the scene{_which_point(p, known)}: a "
                        "cylinder joins two points of the mechanism (a ground "
                        "point or a link's joint)",
                        "cylinders",
                        key,
                    )
            if frozenset(pts) in self.index:
                raise self.error(
                    f"{key} is also a rigid link in [links]: a cylinder changes "
                    "its length; remove one of them",
                    "cylinders",
                    key,
                )
            if not isinstance(spec, dict) or set(spec) - {"stroke"}:
                raise self.error(
                    "a cylinder is {} or { stroke = [closed, extended] }", "cylinders", key
                )
            stroke = spec.get("stroke")
            if stroke is not None:
                if not (isinstance(stroke, list) and len(stroke) == 2):
                    raise self.error(
                        "stroke = [closed, extended]: its shortest and longest pin-to-pin lengths",
                        "cylinders",
                        key,
                    )
                lo, hi = (self.length(v, "cylinders", key) for v in stroke)
                if not lo < hi:
                    raise self.error(
                        f"stroke {stroke}: the closed length must be shorter than the extended one",
                        "cylinders",
                        key,
                    )
                stroke = (lo, hi)
            if any({c.barrel, c.rod} == set(pts) for c in out):
                raise self.error("the same two points have a cylinder already", "cylinders", key)
            out.append(Cylinder(key, pts[0], pts[1], stroke))
        return out

    def book_angle(self, raw, where, table, key, what, **kw):
        """An angle in a book's words (:mod:`.angles`), its reading noted (the crank's is
        noted with the crank: a copy of the scene at another angle has no such note); None
        for a plain angle."""
        try:
            book = read_angle(raw, where, strokes=self.strokes, **kw)
        except SceneError as exc:
            raise self.error(exc.message, table, key) from None
        if book is not None and where != "angle":
            self.read_notes.append(f"{what}: {book.note}")
        return book

    def assembly(self, known):
        out = {}
        for name, hint in self.table("assembly").items():
            if name not in known:
                raise self.error(
                    f"no point {name} in the scene{_which_point(name, known)}", "assembly", name
                )
            if isinstance(hint, str):
                if hint not in ("above", "below", "left", "right"):
                    raise self.error(
                        f"{hint!r}: use above, below, left, right or a rough position [x, y]",
                        "assembly",
                        name,
                    )
                out[name] = hint
            else:
                out[name] = self.coords(hint, "assembly", name)
        return out

    def pins(self, known):
        out = []
        for name, spec in self.table("pins").items():
            if name not in known:
                raise self.error(
                    f"no point {name} in the scene{_which_point(name, known)}", "pins", name
                )
            if (
                not isinstance(spec, dict)
                or len(spec) != 1
                or next(iter(spec)) not in ("diameter", "radius")
            ):
                raise self.error("a pin is { diameter = 30 } or { radius = 15 }", "pins", name)
            ((k, v),) = spec.items()
            size = self.length(v, "pins", name)
            out.append(Pin(name, size / 2 if k == "diameter" else size, k))
        return out

    def loads(self, known):
        out = []
        for name, spec in self.point_loads():  # (a cylinder's: scene/cylinder_loads.py)
            if not isinstance(spec, dict):
                raise self.error(
                    'a load is { force = "2 kN", direction = 0 }, { force = '
                    '[Fx, Fy] } or, on a link, { torque = "20 N m cw" }',
                    "loads",
                    name,
                )
            if "couple" in spec and "torque" not in spec:  # a book's "a couple of 50 N m"
                spec = {("torque" if k == "couple" else k): v for k, v in spec.items()}
            allowed = ("force", "direction", "torque", "pressure", "bore", "rod", "back")
            for k in spec:
                if k not in allowed:
                    raise self.error(f"unknown key '{k}'{_suggest(k, allowed)}", "loads", name)
            if "pressure" in spec or "bore" in spec or "rod" in spec or "back" in spec:
                out.append(self.gas_load(name, spec))
                continue
            if "torque" in spec:
                if "force" in spec or "direction" in spec:
                    raise self.error(
                        "a torque acts on a link, a force at a point: give the "
                        "force under the name of the point it acts at",
                        "loads",
                        name,
                    )
                if not self.index.get(frozenset(split_name(name))):
                    raise self.error(
                        f"a torque acts on a link; no link {name} in [links]", "loads", name
                    )
                t = self.qty(spec["torque"], "torque", "loads", name, need_sense=True).value
                out.append(Load(self.index[frozenset(split_name(name))].key, torque=t))
                continue
            if name not in known:
                raise self.error(
                    f"load on unknown point {name}{_which_point(name, known)}", "loads", name
                )
            f = spec.get("force")
            if f is None:
                raise self.error("a load needs force", "loads", name)
            if isinstance(f, list):
                if len(f) != 2 or "direction" in spec:
                    raise self.error(
                        "force = [Fx, Fy] in N (no direction with a vector)", "loads", name
                    )
                fx, fy = (self.qty(c, "force", "loads", name, default_unit="N").value for c in f)
            else:
                mag = self.qty(f, "force", "loads", name, default_unit="N").value
                if "direction" not in spec:
                    raise self.error("a force needs a direction (deg, ccw from +x)", "loads", name)
                book = self.book_angle(
                    spec["direction"],
                    "direction",
                    "loads",
                    name,
                    f"direction of the force at {name}",
                )
                ang = (
                    book.value
                    if book is not None
                    else self.qty(
                        spec["direction"], "angle", "loads", name, default_unit="deg"
                    ).value
                )
                ux, uy = _unit_at(ang)
                fx, fy = mag * ux, mag * uy
            out.append(Load(name, force=(fx, fy)))
        return out

    def gas_load(self, name, spec):
        """A gas force on a piston: pressure times the piston's area (the bore's circle, less
        the piston rod's on the crank side of a double-acting cylinder), along
        ``direction``; without a direction, towards the crank (worked out when the scene is
        compiled). ``back``: a double-acting cylinder's crank-side pressure, on the bore's
        circle less the rod's, pushing the other way (``pressure`` then acts on the whole
        bore, the cover side)."""
        if name not in self.slider_points:
            raise self.error(f"a gas pressure acts on a piston: {name} is no slider", "loads", name)
        for k in ("pressure", "bore"):
            if k not in spec:
                raise self.error(
                    f"a gas force needs pressure and bore (and direction, the "
                    f"way the gas pushes the piston, deg ccw from +x, when not "
                    f"towards the crank): no {k}",
                    "loads",
                    name,
                )
        if "force" in spec or "torque" in spec:
            raise self.error(
                "give the gas force by pressure and bore, or a force, not both", "loads", name
            )
        p = self.qty(spec["pressure"], "pressure", "loads", name).value
        bore = self.length(spec["bore"], "loads", name)
        area = math.pi / 4 * bore * bore
        rod_area = 0.0
        words = f"{spec['pressure']} on a {self._words(bore)} bore"
        if "rod" in spec:
            rod = self.length(spec["rod"], "loads", name)
            if rod >= bore:
                raise self.error(
                    f"the piston rod ({self._words(rod)}) must be thinner than "
                    f"the bore ({self._words(bore)})",
                    "loads",
                    name,
                )
            rod_area = math.pi / 4 * rod * rod
            if "back" not in spec:
                area -= rod_area
                words += f" less a {self._words(rod)} rod"
        f = p * area
        if "back" in spec:  # double-acting: the cover side's pressure less the crank side's
            back = self.qty(spec["back"], "pressure", "loads", name).value
            f -= back * (area - rod_area)
            words += f" (the cover side) against {spec['back']} on the crank side" + (
                f" less a {self._words(math.sqrt(rod_area * 4 / math.pi))} rod" if rod_area else ""
            )
            p, area = f / area, area  # the net pressure on the whole bore
        if "direction" not in spec:
            return Load(name, force=None, gas=(p, area, words), toward=f)
        book = self.book_angle(
            spec["direction"], "direction", "loads", name, f"direction of the gas force at {name}"
        )
        ang = (
            book.value
            if book is not None
            else self.qty(spec["direction"], "angle", "loads", name, default_unit="deg").value
        )
        ux, uy = _unit_at(ang)
        return Load(name, force=(f * ux, f * uy), gas=(p, area, words))
