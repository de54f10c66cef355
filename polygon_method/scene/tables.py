"""The tables after [ground] and [links]: carried points, sliders, the input, assembly
hints, pins, loads and answers, each checked and turned into records (a part of the
scene reader)."""

from __future__ import annotations

import math
import re

from ..errors import SceneError, printable
from ..units import UNITS, did_you_mean
from .angles import candidates, is_book_form, read_angle
from .records import (ANSWER_KINDS, GIVEN_KINDS, INPUT_KEYS, Answer, CarriedPoint, Cylinder,
                      FixedPath, GivenRate, GuideSlider, Input, Load, Pin, PositionGiven,
                      YokeSlot, split_name)


def _unit_at(ang: float) -> tuple:
    """(cos, sin) of a direction (rad), exact where it is a whole number of right angles
    (a force "direction = 270" is straight down, not 1.8e-16 to the side; a path at
    "180 deg" is horizontal)."""
    q = ang / (math.pi / 2)
    k = round(q)
    if abs(q - k) <= 1e-12:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[k % 4]
    return (math.cos(ang), math.sin(ang))


#: a speed followed by a direction: up, down, left, right (upwards, to the left, ...), or
#: "at 30 deg"
_DIRECTED = re.compile(r"^(.*?\S)\s+(?:(up(?:wards?)?|down(?:wards?)?|(?:to the )?left(?:wards?)?|"
                       r"(?:to the )?right(?:wards?)?)|at\s+(.+))$", re.IGNORECASE)
_WORDS = {"up": (0.0, 1.0), "down": (0.0, -1.0), "left": (-1.0, 0.0), "right": (1.0, 0.0)}


def _extending(raw):
    """A cylinder's rate with a word: ``"0.2 m/s extending"`` -> 0.2 m/s, ``retracting`` ->
    its negative (a signed number: + extending)."""
    if isinstance(raw, str):
        m = re.match(r"^\s*(.*?\S)\s+(extending|retracting|outwards?|inwards?)\s*$", raw,
                     re.IGNORECASE)
        if m:
            text = m.group(1).strip()
            if m.group(2).lower() in ("retracting", "inward", "inwards"):
                text = text[1:] if text.startswith("-") else "-" + text.lstrip("+")
            return text
    return raw


def _given_key(key):
    """(prefix, names) of an [input] key naming a given motion or its rate (``vs_B`` ->
    ("vs", ("B",))), or None."""
    prefix, _, rest = key.partition("_")
    if prefix not in ("omega", "vs", "v", "alpha", "as", "a") or not rest:
        return None
    names = split_name(rest)
    if not names or len(names) > 2 or (prefix in ("omega", "alpha") and len(names) != 2) \
            or (prefix in ("v", "a") and len(names) != 1):
        return None  # vs_OR, as_OR: a cylinder's rate of extension
    return prefix, names


def _suggest(word, choices) -> str:
    return did_you_mean(word, list(choices))


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
        table = self.table("points")
        local = {}  # link key -> {point: (x, y) in the link frame, P at 0, Q at (L, 0)}
        out = []
        for name, spec in table.items():
            self.point_name(name, "points")
            if name in ground:
                raise self.error(f"{name} is a ground point and a carried point; a point has "
                                 "one role", "points", name)
            if not isinstance(spec, dict) or "on" not in spec:
                raise self.error("a carried point is a table such as { on = \"BC\", along = "
                                 "40 } or { on = \"BC\", distances = { B = 45, C = 30 }, turn "
                                 "= \"cw\" }", "points", name)
            allowed = ("on", "along", "from", "distances", "turn")
            for k in spec:
                if k not in allowed:
                    raise self.error(f"unknown key '{k}'{_suggest(k, allowed)}", "points", name)
            link, pts = self.find_link(spec["on"], "points", name)
            if name in link.points:
                raise self.error(f"{name} is a joint of link {link.key}; it cannot also be "
                                 "carried on it", "points", name)
            frame = local.setdefault(link.key, {link.p: (0.0, 0.0), link.q: (link.length, 0.0)})
            has_along, has_dist = "along" in spec, "distances" in spec
            if has_along == has_dist:
                raise self.error("give either along (with an optional from) or distances "
                                 "with turn", "points", name)
            if has_along:
                start = spec.get("from", pts[0])
                if start not in link.points:
                    raise self.error(f"from = {start!r} is not an end of {link.key}",
                                     "points", name)
                if "turn" in spec:
                    raise self.error("turn goes with distances, not with along", "points", name)
                d = self.length(spec["along"], "points", name, positive=False)
                sx, sy = frame[start]
                ox, oy = frame[link.other(start)]
                t = d / link.length
                xy = (sx + t * (ox - sx), sy + t * (oy - sy))
                far = link.other(start)
                where = (f"{spec['on']} produced beyond {start}" if d < 0 else
                         f"{spec['on']} produced beyond {far}" if d > link.length else
                         spec['on'])
                how = f"on {where}, {self._words(abs(d))} from {start}"
            else:
                dist = spec["distances"]
                if not isinstance(dist, dict) or len(dist) != 2:
                    raise self.error("distances names two points of the link, e.g. "
                                     "{ B = 45, C = 30 }", "points", name)
                turn = spec.get("turn")
                if turn not in ("cw", "ccw"):
                    raise self.error("turn = \"cw\" or \"ccw\": how the triangle (the two "
                                     "points of distances, then this point) reads", "points",
                                     name)
                (r1, d1), (r2, d2) = dist.items()
                for r in (r1, r2):
                    if r not in frame:
                        raise self.error(f"{r} is not a point of link {link.key}", "points",
                                         name)
                d1 = self.length(d1, "points", name)
                d2 = self.length(d2, "points", name)
                (x1, y1), (x2, y2) = frame[r1], frame[r2]
                e = math.hypot(x2 - x1, y2 - y1)
                u = self.scale()
                if d1 + d2 < e * (1 - 1e-12) or abs(d1 - d2) > e * (1 + 1e-12):
                    if d1 + d2 < e:
                        why = (f"{r1}{name} + {r2}{name} = {(d1 + d2) / u:g} < {r1}{r2} = "
                               f"{e / u:g} {self.unit}")
                    else:
                        why = (f"|{r1}{name} - {r2}{name}| = {abs(d1 - d2) / u:g} > {r1}{r2} = "
                               f"{e / u:g} {self.unit}")
                    raise self.error(f"the triangle {r1}{r2}{name} cannot close: {why}",
                                     "points", name)
                along = (d1 * d1 - d2 * d2 + e * e) / (2 * e)
                h = math.sqrt(max(d1 * d1 - along * along, 0.0))
                ex, ey = (x2 - x1) / e, (y2 - y1) / e
                sign = 1.0 if turn == "ccw" else -1.0
                xy = (x1 + along * ex - sign * h * ey, y1 + along * ey + sign * h * ex)
                how = (f"on {spec['on']}, {r1}{name} = {self._words(d1)}, {r2}{name} = "
                       f"{self._words(d2)}, {r1}{r2}{name} read {turn}")
            frame[name] = xy
            L = link.length
            out.append(CarriedPoint(name, link.key, xy[0] / L, xy[1] / L, how))
        return out

    def sliders(self, index, ground, carried):
        out = []
        for name, spec in self.table("sliders").items():
            self.point_name(name, "sliders")
            if not isinstance(spec, dict):
                raise self.error("a slider is a table: { path = \"horizontal\", through = "
                                 "[x, y] } or { along = \"CP\" }", "sliders", name)
            allowed = ("path", "through", "along", "direction")
            for k in spec:
                if k not in allowed:
                    raise self.error(f"unknown key '{k}'{_suggest(k, allowed)}", "sliders", name)
            if isinstance(spec.get("along"), str) and spec["along"].startswith("block "):
                out.append(self.yoke_slot(name, spec, ground))
                continue
            if "direction" in spec:
                raise self.error("direction goes with along = \"block Y\" (the slot of a "
                                 "translating yoke Y)", "sliders", name)
            if "along" in spec and (isinstance(spec["along"], list) or "path" in spec):
                out.extend(self.peg(name, spec, ground, carried))
                continue
            if "along" in spec:
                if "through" in spec:
                    raise self.error("a block slides either on a fixed path or along a link, "
                                     "not both (a peg in a fixed slot and in the slot of a "
                                     "link: along = \"OA\" with path = ...)", "sliders", name)
                guide = spec["along"]
                if len(split_name(guide)) == 2 and not self.index.get(frozenset(
                        split_name(guide))) and any(p in self.ground
                                                    for p in split_name(guide)):
                    raise self.error(
                        f"the guide {guide} is not in [links]: add it with its length, e.g. "
                        f"\"{guide}\" = 500 (if the problem does not give the lever's length, "
                        "any length will do: it only places the end of the lever)", "sliders", name)
                link, pts = self.find_link(guide, "sliders", name)
                if name in link.points:
                    raise self.error(f"{name} is an end of {link.key}; a block slides along a "
                                     "link between its ends", "sliders", name)
                if all(p in ground for p in pts):
                    raise self.error(f"{link.key} is fixed (both ends are ground points): "
                                     "use path/through for a fixed guide", "sliders", name)
                out.append(GuideSlider(name, link.key, pts[0], pts[1]))
                continue
            if name in ground:
                raise self.error(f"{name} is a ground point; it cannot slide on a fixed path",
                                 "sliders", name)
            if name in carried:
                raise self.error(f"{name} is carried on a link and also slides on a fixed "
                                 "path: one constraint too many", "sliders", name)
            out.append(self.fixed_path(name, spec, ground))
        for sl in out:  # a yoke's slot: its yoke is a block on a fixed path, not along it
            if isinstance(sl, YokeSlot):
                self.check_yoke(sl, out)
        return out

    def yoke_slot(self, name, spec, ground):
        """``P = { along = "block Y", direction = "vertical" }``: a block at P in the slot of
        the yoke Y (a block on a fixed path), the slot through Y along ``direction``."""
        yoke = spec["along"][len("block "):].strip()
        if "path" in spec or "through" in spec:
            raise self.error("a block slides either on a fixed path or in a yoke's slot, not "
                             "both", "sliders", name)
        if name in ground:
            raise self.error(f"{name} is a ground point; it cannot slide in a moving yoke",
                             "sliders", name)
        if yoke == name:
            raise self.error(f"{name} cannot slide in its own slot: the yoke is another "
                             "block, e.g. along = \"block Y\"", "sliders", name)
        if "direction" not in spec:
            raise self.error("the yoke's slot has no direction: add direction = "
                             "\"vertical\", \"horizontal\" or an angle such as \"60 deg\"",
                             "sliders", name)
        ang, label = self.direction(spec["direction"], name)
        return YokeSlot(name, yoke, _unit_at(ang), label)

    def check_yoke(self, sl, sliders):
        """The yoke of a slot is a block on a fixed path, its slot across that path."""
        name, yoke = sl.point, sl.yoke
        path = next((s for s in sliders if s.point == yoke and not s.slot), None)
        if not isinstance(path, FixedPath):
            raise self.error(f"along = \"block {yoke}\": {yoke} must be a block on a fixed "
                             f"path in [sliders] (the yoke), e.g. {yoke} = {{ path = "
                             "\"horizontal\" }", "sliders", name)
        (ux, uy), (dx, dy) = path.u, sl.direction
        if abs(ux * dy - uy * dx) < 1e-9:
            raise self.error(f"a pin in two parallel slots: the slot of block {yoke} runs "
                             f"{sl.label}, along the yoke's own {path.label} path, so "
                             "nothing moves the yoke", "sliders", name)

    def direction(self, value, name):
        """(angle in rad, label) of a direction: "horizontal", "vertical" or an angle."""
        if isinstance(value, str) and not re.match(r"^\s*[-+.\d]", value) \
                and value not in ("horizontal", "vertical"):
            raise self.error(f"{value!r}: use \"horizontal\", \"vertical\" or an "
                             "angle such as \"30 deg\"" + _suggest(value, ("horizontal",
                                                                          "vertical")),
                             "sliders", name)
        if value == "horizontal":
            return 0.0, "horizontal"
        if value == "vertical":
            return math.pi / 2, "vertical"
        ang = self.qty(value, "angle", "sliders", name, default_unit="deg").value
        return ang, f"at {math.degrees(ang):g} deg"

    def fixed_path(self, name, spec, ground, slot=""):
        """The fixed path of ``spec`` (its path and through) for the slider at ``name``."""
        if "path" not in spec:
            raise self.error("the slider's path has no direction: add path = "
                             "\"horizontal\", \"vertical\" or an angle such as \"30 deg\"",
                             "sliders", name)
        path = spec["path"]
        if isinstance(path, str) and not re.match(r"^\s*[-+.\d]", path) \
                and path not in ("horizontal", "vertical"):
            raise self.error(f"path = {path!r}: use \"horizontal\", \"vertical\" or an "
                             "angle such as \"30 deg\" or \"30 deg below the horizontal\""
                             + _suggest(path, ("horizontal", "vertical")),
                             "sliders", name)
        if path == "horizontal":
            ang, label = 0.0, "horizontal"
        elif path == "vertical":
            ang, label = math.pi / 2, "vertical"
        else:
            # a book's words are in the notes; the label keeps the tables' width
            book = self.book_angle(path, "path", "sliders", name, f"slider {name}'s path")
            ang = book.value if book is not None else self.qty(
                path, "angle", "sliders", name, default_unit="deg").value
            label = f"at {math.degrees(ang):g} deg"
        through = spec.get("through")
        if through is None:
            through = ("input pivot", None)
        elif isinstance(through, str):
            if through not in ground:
                raise self.error(f"through = {through!r} is not a ground point"
                                 f"{_suggest(through, ground)}", "sliders", name)
            through = ground[through]
        else:
            through = self.coords(through, "sliders", name)
        u = _unit_at(ang)
        record = FixedPath(name, u, through, label, slot)
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
            raise self.error("a peg sits in two slots: along = [\"OA\", \"QB\"] (two "
                             "slotted links), or along = \"OA\" with path = ... (a link's "
                             f"slot and a fixed one); got {len(guides) + fixed}", "sliders",
                             name)
        if name in ground:
            raise self.error(f"{name} is a ground point; a peg in two slots moves along "
                             "them", "sliders", name)
        if name in carried:
            raise self.error(f"{name} is carried on a link and also sits in two slots: two "
                             "constraints too many", "sliders", name)
        out, seen = [], []
        for guide in guides:
            if not isinstance(guide, str):
                raise self.error(f"along = {guide!r}: a slot is named by its link, e.g. "
                                 "\"OA\"", "sliders", name)
            link, pts = self.find_link(guide, "sliders", name)
            if name in link.points:
                raise self.error(f"{name} is an end of {link.key}; a peg slides in the slot "
                                 "of a link between its ends", "sliders", name)
            if all(p in ground for p in pts):
                raise self.error(f"{link.key} is fixed (both ends are ground points): use "
                                 "path/through for a fixed slot", "sliders", name)
            if link.key in seen:
                raise self.error(f"a pin in two parallel slots: both are the slot of "
                                 f"{link.key}, so the peg can be anywhere along it",
                                 "sliders", name)
            seen.append(link.key)
            out.append(GuideSlider(name, link.key, pts[0], pts[1], link.key))
        if fixed:
            out.append(self.fixed_path(name, spec, ground, "ground"))
        elif "through" in spec:
            raise self.error("through goes with path (a fixed slot); a peg in two slotted "
                             "links has none", "sliders", name)
        return out

    def cylinders(self, known):
        """``[cylinders] "O-R" = {}``: a cylinder, barrel pivoted at O, rod pinned at R;
        optionally ``{ stroke = [closed, extended] }`` (pin-to-pin lengths)."""
        out = []
        for key, spec in self.table("cylinders").items():
            pts = split_name(key)
            if len(pts) != 2 or pts[0] == pts[1]:
                raise self.error(f"{key!r} is not a cylinder's name: its barrel's pivot, then "
                                 "its rod's end, e.g. \"O-R\" or OR", "cylinders", key)
            for p in pts:
                if p not in known:
                    raise self.error(f"no point {p} in the scene{_which_point(p, known)}: a "
                                     "cylinder joins two points of the mechanism (a ground "
                                     "point or a link's joint)", "cylinders", key)
            if frozenset(pts) in self.index:
                raise self.error(f"{key} is also a rigid link in [links]: a cylinder changes "
                                 "its length; remove one of them", "cylinders", key)
            if not isinstance(spec, dict) or set(spec) - {"stroke"}:
                raise self.error("a cylinder is {} or { stroke = [closed, extended] }",
                                 "cylinders", key)
            stroke = spec.get("stroke")
            if stroke is not None:
                if not (isinstance(stroke, list) and len(stroke) == 2):
                    raise self.error("stroke = [closed, extended]: its shortest and longest "
                                     "pin-to-pin lengths", "cylinders", key)
                lo, hi = (self.length(v, "cylinders", key) for v in stroke)
                if not lo < hi:
                    raise self.error(f"stroke {stroke}: the closed length must be shorter "
                                     "than the extended one", "cylinders", key)
                stroke = (lo, hi)
            if any({c.barrel, c.rod} == set(pts) for c in out):
                raise self.error("the same two points have a cylinder already", "cylinders",
                                 key)
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

    def dead_centres(self, link, pivot, tip, ground):
        """The candidate dead centres of the slider crank that ``link`` drives, for
        :func:`.angles.read_angle`: ``[(inner, outer, keeps)]``."""
        rods = [(lk, s) for lk in self.index.values() if tip in lk.points and lk is not link
                for s in self.fixed if s.point == lk.other(tip)]
        if len(rods) != 1:
            raise SceneError(
                "a dead centre is where the crank and the rod of a slider crank are in line; "
                + (f"crank {link.key} drives no rod whose other end slides on a fixed path "
                   "in [sliders]: give the angle from +x, the horizontal or the vertical"
                   if not rods else f"crank {link.key} drives {len(rods)} slider rods "
                   f"({', '.join(lk.key for lk, _ in rods)}): give the angle from +x"))
        (rod, slider), = rods
        through = ground[pivot] if slider.through[1] is None else slider.through
        hint = self.raw.get("assembly")
        hint = hint.get(slider.point) if isinstance(hint, dict) else None
        if isinstance(hint, list) and len(hint) == 2:
            try:
                hint = tuple(self.length(c, "assembly", slider.point, positive=False)
                             for c in hint)
            except SceneError:
                hint = None  # refused when [assembly] is read, by its own key
        return candidates(ground[pivot], link.length, rod.length, through, slider.u, hint,
                          (self.unit, self.scale()))

    def input(self, index, ground):
        if "input" not in self.raw:
            raise SceneError("missing [input] table: which link is the crank, its angle and "
                             "speed", file=self.file, key="[input]")
        spec = self.table("input")
        second = None
        if "second" in spec:  # a second driving crank: two degrees of freedom
            second = self.second_input(spec["second"], ground)
            spec = {k: v for k, v in spec.items() if k != "second"}
        placed = None
        at = [k for k in spec if k.partition("_")[0] in ("length", "s", "angle")
              and k.partition("_")[2]]
        if at:  # the position given otherwise than by the crank's angle
            if "angle" in spec or len(at) > 1:
                raise self.error(f"[input] gives the position twice ({', '.join(['angle'] * ('angle' in spec) + at)}): "
                                 "one only (the crank's angle is then found)", "input", at[-1])
            placed = self.placed_at(at[0], spec[at[0]], spec.get("near"))
            spec = {k: v for k, v in spec.items() if k not in (at[0], "near")}
        elif "near" in spec:
            raise self.error("near is a rough crank angle choosing among those that give a "
                             "position stated otherwise (length_OR, s_B, angle_CD): there is "
                             "none", "input", "near")
        rates = {k: _given_key(k) for k in spec if k not in INPUT_KEYS}
        for k, parsed in rates.items():
            if parsed is None:
                raise self.error(f"unknown key{_suggest(k, INPUT_KEYS)}; [input] takes crank, "
                                 "angle, speed, acceleration, or the given motion named as an "
                                 "answer key (omega_BC, vs_B, v_B and alpha_BC, as_B, a_B)",
                                 "input", k)
        given_keys = [k for k, p in rates.items() if p[0] in GIVEN_KINDS]
        rate_keys = [k for k, p in rates.items() if p[0] not in GIVEN_KINDS]
        if len(given_keys) > 1:
            raise self.error(f"[input] gives the motion twice ({', '.join(given_keys)}): a "
                             "mechanism of one degree of freedom takes one input", "input",
                             given_keys[1])
        if given_keys and "speed" in spec:
            raise self.error(f"[input] gives both the crank's speed and {given_keys[0]}: one "
                             "input only (remove speed to find the crank's from "
                             f"{given_keys[0]})", "input", given_keys[0])
        for k in ("crank",) + (() if placed else ("angle",)) + (() if given_keys else ("speed",)):
            if k not in spec:
                example = {"crank": "crank = \"AB\"", "angle": "angle = 60",
                           "speed": "speed = \"10 rad/s ccw\""}[k]
                raise self.error(f"[input] has no {k}: add e.g. {example}", "input")
        link, pts = self.find_link(spec["crank"], "input", "crank")
        on_ground = [p for p in pts if p in ground]
        if not on_ground:
            raise self.error(f"crank {link.key} is not pinned to the ground: neither "
                             f"{pts[0]} nor {pts[1]} is in [ground]", "input", "crank")
        if len(on_ground) == 2:
            raise self.error(f"crank {link.key} has both ends in [ground]; it cannot turn",
                             "input", "crank")
        pivot = on_ground[0]
        tip = link.other(pivot)
        said = ()
        if placed is not None:  # a provisional angle: the one that gives it is found later
            spec = dict(spec, angle=math.degrees(placed.near) if placed.near is not None else 0)
        if not is_book_form(spec["angle"]):
            angle = self.qty(spec["angle"], "angle", "input", "angle", default_unit="deg").value
        speed = None if given_keys else self.qty(spec["speed"], "angular_velocity", "input",
                                                  "speed", need_sense=True)
        if is_book_form(spec["angle"]):  # a dead centre is passed in the crank's sense
            if given_keys and re.search(r"\b(past|before|after|beyond)\b", str(spec["angle"]),
                                        re.IGNORECASE):
                raise self.error(f"{spec['angle']!r}: past or before a dead centre follows the "
                                 "crank's sense, which a given motion leaves to be found; give "
                                 "the angle from +x, the horizontal or the vertical", "input",
                                 "angle")
            book = self.book_angle(spec["angle"], "angle", "input", "angle", "crank angle",
                                   dead=lambda: self.dead_centres(link, pivot, tip, ground),
                                   sense=None if speed is None else speed.value)
            angle = book.value
            said = (book.words, angle, book.slips, f"crank angle: {book.note}")
        acc = spec.get("acceleration", 0 if not given_keys else None)
        if acc is None:
            alpha = None
        elif isinstance(acc, (int, float)) and not isinstance(acc, bool) and acc == 0:
            alpha = 0.0
        else:
            alpha = self.qty(acc, "angular_acceleration", "input", "acceleration",
                             need_sense=True).value
        if given_keys and second is not None:
            raise self.error(f"{given_keys[0]} with two inputs: give each crank's speed (a "
                             "motion given elsewhere sets one input only)", "input",
                             given_keys[0])
        if given_keys:
            given = self.given_rate(given_keys[0], rate_keys, spec, index)
            if given.rate is not None and "acceleration" in spec:
                raise self.error(f"[input] gives both the crank's acceleration and "
                                 f"{given.rate_key}: one only", "input", given.rate_key)
            return Input(link.key, pivot, tip, angle, None, alpha, given.text, given,
                         said=said, placed=placed)
        if rate_keys:
            raise self.error(f"{rate_keys[0]} is the rate of a given motion, but [input] gives "
                             "the crank's speed: give the crank's acceleration instead",
                             "input", rate_keys[0])
        if speed.value == 0:
            raise self.error("the crank speed is zero: nothing moves", "input", "speed")
        self.two_inputs = second is not None
        if second is not None and second.crank == link.key:
            raise self.error(f"the second input is the crank {link.key} again: name another "
                             "link pivoted on the ground", "input.second", "crank")
        return Input(link.key, pivot, tip, angle, speed.value, alpha, str(spec["speed"]),
                     said=said, second=second, placed=placed)

    def placed_at(self, key, raw, near):
        """``length_OR = 850`` (two points' distance, a cylinder's length), ``s_B = 300`` (a
        slider's place on its path from its through point), ``angle_CD = 30`` (the direction
        C -> D): the position as a book gives it; ``near``: a rough crank angle."""
        kind, _, rest = key.partition("_")
        names = split_name(rest)
        if kind == "s":
            sl = self.slider_points.get(names[0]) if len(names) == 1 else None
            if not isinstance(sl, FixedPath):
                raise self.error(f"s_{rest}: no slider {rest} on a fixed path in [sliders] (s_B "
                                 "is B's place along its path, from its through point)",
                                 "input", key)
            value = self.length(raw, "input", key, positive=False)
        elif kind == "length":
            if len(names) != 2 or any(n not in self.known for n in names):
                raise self.error(f"length_{rest}: two points of the scene, e.g. length_OR (the "
                                 "distance O to R, a cylinder's length)", "input", key)
            value = self.length(raw, "input", key)
        else:
            if len(names) != 2 or any(n not in self.known for n in names):
                raise self.error(f"angle_{rest}: two points of the scene, e.g. angle_CD (the "
                                 "direction C -> D)", "input", key)
            value = self.qty(raw, "angle", "input", key, default_unit="deg").value
        near_v = None if near is None else self.qty(near, "angle", "input", "near",
                                                    default_unit="deg").value
        text = printable(str(raw))
        if isinstance(raw, (int, float)) and not isinstance(raw, bool):
            text += " deg" if kind == "angle" else f" {self.unit}"
        return PositionGiven(key, kind, tuple(names), value, near_v, text)

    def second_input(self, spec, ground):
        """``[input.second]``: a second driving crank, with its crank, angle, speed and
        (optional) acceleration, read as the first's."""
        if not isinstance(spec, dict):
            raise self.error("the second input is a table: [input.second] with crank, "
                             "angle, speed", "input", "second")
        for k in spec:
            if k not in INPUT_KEYS:
                raise self.error(f"unknown key{_suggest(k, INPUT_KEYS)}; the second input "
                                 "takes crank, angle, speed, acceleration", "input.second", k)
        for k in ("crank", "angle", "speed"):
            if k not in spec:
                raise self.error(f"[input.second] has no {k}", "input.second")
        link, pts = self.find_link(spec["crank"], "input.second", "crank")
        on_ground = [p for p in pts if p in ground]
        if len(on_ground) != 1:
            raise self.error(f"the second crank {link.key} must turn about one ground point",
                             "input.second", "crank")
        pivot = on_ground[0]
        angle = self.qty(spec["angle"], "angle", "input.second", "angle",
                         default_unit="deg").value
        speed = self.qty(spec["speed"], "angular_velocity", "input.second", "speed",
                         need_sense=True)
        if speed.value == 0:
            raise self.error("the second crank's speed is zero: give it, or make it part of "
                             "the frame", "input.second", "speed")
        acc = spec.get("acceleration", 0)
        alpha = 0.0 if (isinstance(acc, (int, float)) and not isinstance(acc, bool)
                        and acc == 0) else self.qty(acc, "angular_acceleration",
                                                    "input.second", "acceleration",
                                                    need_sense=True).value
        return Input(link.key, pivot, link.other(pivot), angle, speed.value, alpha,
                     str(spec["speed"]))

    def given_rate(self, key, rate_keys, spec, index) -> GivenRate:
        """``omega_BC = "3 rad/s cw"``, ``vs_B = "1.5 m/s up"``, ``v_B = "3 m/s down"`` in
        [input], with its rate (``alpha_BC``, ``as_B``, ``a_B``) if given."""
        kind, names = _given_key(key)
        rate_kind = GIVEN_KINDS[kind]
        for r in rate_keys:
            rk, rnames = _given_key(r)
            if rk != rate_kind or rnames != names:
                raise self.error(f"{r} does not go with {key}: the given motion's rate is "
                                 f"{rate_kind}_{'-'.join(names) if len(names) > 1 and any(len(n) > 1 for n in names) else ''.join(names)}",
                                 "input", r)
        rate_key = rate_keys[0] if rate_keys else None
        raw, raw_rate = spec[key], spec.get(rate_key) if rate_key else None
        text = printable(str(raw))
        rate_text = None if raw_rate is None else printable(str(raw_rate))
        direction = None
        if kind == "omega":
            if len(names) != 2 or frozenset(names) not in index:
                raise self.error(f"no link {''.join(names)} in [links]", "input", key)
            value = self.qty(raw, "angular_velocity", "input", key, need_sense=True).value
            rate = None if raw_rate is None else (
                0.0 if raw_rate == 0 else self.qty(raw_rate, "angular_acceleration", "input",
                                                   rate_key, need_sense=True).value)
            names = index[frozenset(names)].points
        else:
            point = names[0] if len(names) == 1 else None
            if kind == "vs" and point is None:  # a cylinder's rate of extension
                cyl = self.find_cylinder(names)
                if cyl is None:
                    raise self.error(f"no cylinder {'-'.join(names)} in [cylinders]", "input",
                                     key)
                names, u = (cyl.key,), (1.0, 0.0)  # signed: + extending
                raw = _extending(raw)
                raw_rate = None if raw_rate is None else _extending(raw_rate)
            elif kind == "vs":
                sl = self.slider_points.get(point)
                if sl is None:
                    raise self.error(f"no slider {''.join(names)} in [sliders]", "input", key)
                u = getattr(sl, "u", None)
            else:
                if point is None or point not in self.known:
                    raise self.error(f"no point {''.join(names)} in the scene", "input", key)
                u = None
            value, direction = self.directed(raw, "velocity", key, u, need=kind == "v")
            rate = None
            if raw_rate is not None:
                rate, _ = self.directed(raw_rate, "acceleration", rate_key,
                                        u if kind == "vs" else None, need=False)
        if value == 0:
            raise self.error(f"{key} is zero: it does not set the crank's speed (give the "
                             "crank's speed instead)", "input", key)
        return GivenRate(key, kind, tuple(names), value, rate, direction, text, rate_key,
                         rate_text)

    def find_cylinder(self, names):
        return next((c for c in self.cylinder_list if {c.barrel, c.rod} == set(names)), None)

    def directed(self, raw, kind, key, u, need):
        """A speed (or its rate) with an optional direction word: ``"3 m/s down"``,
        ``"1.5 m/s up"``, ``"2 m/s at 30 deg"``. Returns (value, unit direction): with a
        guide ``u``, the value is signed along u and the direction is u."""
        text = raw.strip() if isinstance(raw, str) else raw
        d = None
        if isinstance(text, str):
            m = _DIRECTED.match(text)
            if m:
                text, word, ang = m.group(1), m.group(2), m.group(3)
                if ang is not None:
                    d = _unit_at(self.qty(ang, "angle", "input", key, default_unit="deg").value)
                else:
                    d = _WORDS[word.lower().rstrip("s").replace("to the ", "").replace("ward", "")]
        value = self.qty(text, kind, "input", key, default_unit=next(iter(UNITS[kind]))).value
        if u is not None:
            if d is not None:
                along = d[0] * u[0] + d[1] * u[1]
                if abs(along) < 1e-9:
                    raise self.error(f"{raw!r}: the guide is perpendicular to that direction; "
                                     "give the speed along the guide, signed, or up, down, "
                                     "left, right", "input", key)
                value = value * (1.0 if along > 0 else -1.0)
            return value, tuple(u)
        if d is None:
            if need:
                raise self.error(f"{raw!r}: say which way the point moves, e.g. \"3 m/s down\" "
                                 "or \"3 m/s at 240 deg\" (up, down, left, right or an angle)",
                                 "input", key)
            return value, None
        return value, d

    def assembly(self, known):
        out = {}
        for name, hint in self.table("assembly").items():
            if name not in known:
                raise self.error(f"no point {name} in the scene{_which_point(name, known)}",
                                 "assembly", name)
            if isinstance(hint, str):
                if hint not in ("above", "below", "left", "right"):
                    raise self.error(f"{hint!r}: use above, below, left, right or a rough "
                                     "position [x, y]", "assembly", name)
                out[name] = hint
            else:
                out[name] = self.coords(hint, "assembly", name)
        return out

    def pins(self, known):
        out = []
        for name, spec in self.table("pins").items():
            if name not in known:
                raise self.error(f"no point {name} in the scene{_which_point(name, known)}",
                                 "pins", name)
            if not isinstance(spec, dict) or len(spec) != 1 or \
                    next(iter(spec)) not in ("diameter", "radius"):
                raise self.error("a pin is { diameter = 30 } or { radius = 15 }", "pins", name)
            (k, v), = spec.items()
            size = self.length(v, "pins", name)
            out.append(Pin(name, size / 2 if k == "diameter" else size, k))
        return out

    def loads(self, known):
        out = []
        for name, spec in self.table("loads").items():
            if not isinstance(spec, dict):
                raise self.error("a load is { force = \"2 kN\", direction = 0 }, { force = "
                                 "[Fx, Fy] } or, on a link, { torque = \"20 N m cw\" }",
                                 "loads", name)
            allowed = ("force", "direction", "torque")
            for k in spec:
                if k not in allowed:
                    raise self.error(f"unknown key '{k}'{_suggest(k, allowed)}", "loads", name)
            if "torque" in spec:
                if "force" in spec or "direction" in spec:
                    raise self.error("a torque acts on a link, a force at a point: give the "
                                     "force under the name of the point it acts at",
                                     "loads", name)
                if not self.index.get(frozenset(split_name(name))):
                    raise self.error(f"a torque acts on a link; no link {name} in [links]",
                                     "loads", name)
                t = self.qty(spec["torque"], "torque", "loads", name, need_sense=True).value
                out.append(Load(self.index[frozenset(split_name(name))].key, torque=t))
                continue
            if name not in known:
                raise self.error(f"load on unknown point {name}{_which_point(name, known)}",
                                 "loads", name)
            f = spec.get("force")
            if f is None:
                raise self.error("a load needs force", "loads", name)
            if isinstance(f, list):
                if len(f) != 2 or "direction" in spec:
                    raise self.error("force = [Fx, Fy] in N (no direction with a vector)",
                                     "loads", name)
                fx, fy = (self.qty(c, "force", "loads", name, default_unit="N").value
                          for c in f)
            else:
                mag = self.qty(f, "force", "loads", name, default_unit="N").value
                if "direction" not in spec:
                    raise self.error("a force needs a direction (deg, ccw from +x)",
                                     "loads", name)
                book = self.book_angle(spec["direction"], "direction", "loads", name,
                                       f"direction of the force at {name}")
                ang = book.value if book is not None else self.qty(
                    spec["direction"], "angle", "loads", name, default_unit="deg").value
                ux, uy = _unit_at(ang)
                fx, fy = mag * ux, mag * uy
            out.append(Load(name, force=(fx, fy)))
        return out

    def answers(self, known, sliders, pins, loads):
        spec = self.table("answers")
        tolerance = None
        out = []
        slider_names = {s.key: s for s in sliders}
        pin_names = {p.point for p in pins}
        for key, value in spec.items():
            if key == "tolerance":
                q = self.qty(value, "percent", "answers", key, default_unit="%").value
                if not 0 < q < 1:
                    raise self.error(f"tolerance {value!r} must be between 0 and 100 %",
                                     "answers", key)
                tolerance = q
                continue
            out.append(self.answer(key, value, known, slider_names, pin_names, loads))
        return tolerance, out

    def centre_answer(self, key, rest, value, line):
        """``I_13 = [x, y]``: the instantaneous centre of links 1 and 3 (textbook numbers:
        ground 1, crank 2), in the scene's units; ``I_1_12`` past link 9."""
        parts = rest.split("_") if "_" in rest else list(rest)
        named = len(parts) == 2 and not any(p.isdigit() for p in parts)
        if named:  # the scene's names: I_ground_BC, I_AB_CD
            for part in parts:
                if part.lower() != "ground":
                    self.find_link(part, "answers", key)
        elif len(parts) != 2 or not all(p.isdigit() and int(p) > 0 for p in parts) or \
                int(parts[0]) == int(parts[1]):
            raise self.error("an instantaneous centre is I_ij with two different link "
                             "numbers (ground 1, crank 2), e.g. I_13, or I_1_12 past 9, or "
                             "two link names, e.g. I_ground_BC", "answers", key)
        if not (isinstance(value, list) and len(value) == 2 and
                all(isinstance(v, (int, float)) and not isinstance(v, bool) and
                    math.isfinite(v) for v in value)):
            raise self.error(f"a centre's answer is its position [x, y] in {self.unit}, "
                             f"got {value!r}", "answers", key)
        for v in value:  # [1e300, 0]: a units slip, never an error of 1e299 per cent
            self.length(v, "answers", key, positive=False)
        pair = tuple(parts) if named else tuple(sorted(int(p) for p in parts))
        u = self.scale()
        return Answer(key, "centre", pair, (value[0] * u, value[1] * u), None,
                      f"[{value[0]:g}, {value[1]:g}] {self.unit}", line)

    def answer(self, key, value, known, slider_names, pin_names, loads):
        line = self.line_of("answers", key)
        if key == "torque":
            if not loads:
                raise self.error("a torque answer needs [loads] to balance", "answers", key)
            if getattr(self, "two_inputs", False):
                raise self.error("with two inputs one power balance does not give the two "
                                 "driving torques: no torque answer", "answers", key)
            q = self.qty(value, "torque", "answers", key, default_unit="N m", allow_sense=True)
            return Answer(key, "torque", (), q.value, q.sense, printable(str(value)), line)
        prefix, _, rest = key.partition("_")
        if prefix == "I" and rest:
            return self.centre_answer(key, rest, value, line)
        if prefix not in ANSWER_KINDS or not rest:
            examples = ["v_C", "a_C", "v_CB", "omega_BC", "alpha_BC", "vs_D", "as_D", "ac_A",
                        "rub_B", "torque"]
            raise self.error(f"unknown answer key{_suggest(key, examples)}; keys are v_X, "
                             "a_X, v_XY, a_XY, omega_L, alpha_L, vs_X, as_X, ac_X, rub_X, "
                             "torque, I_ij (a centre), vI_L, aI_L (a wheel's contact point)", "answers", key)
        kind, what, sense_ok = ANSWER_KINDS[prefix]
        names = (rest,) if what == "slider" and rest in slider_names else split_name(rest)
        if not names:
            raise self.error(f"'{rest}' is not a point or link name", "answers", key)
        if what == "point":
            if len(names) > 2:
                raise self.error("v_X or v_XY: one or two points", "answers", key)
            for n in names:
                if n not in known:
                    raise self.error(f"no point {n} in the scene{_which_point(n, known)}",
                                     "answers", key)
        elif what == "link" and len(names) == 2 and self.find_cylinder(names):
            names = tuple(split_name(self.find_cylinder(names).key))
        elif what == "slider" and len(names) == 2 and self.find_cylinder(names) and \
                prefix in ("vs", "as"):
            names = (self.find_cylinder(names).key,)
        elif what == "link":
            if len(names) != 2 or frozenset(names) not in self.index:
                raise self.error(f"no link {rest} in [links]"
                                 f"{_suggest(rest, [lk.key for lk in self.index.values()])}",
                                 "answers", key)
        elif what == "slider":
            if len(names) != 1 or names[0] not in slider_names:
                slots = [k for k, s in slider_names.items() if s.point == rest]
                if slots:  # a peg in two slots: which one?
                    raise self.error(f"{rest} sits in two slots: name the slot, "
                                     + " or ".join(f"{prefix}_{k}" for k in slots),
                                     "answers", key)
                raise self.error(f"no slider {rest} in [sliders]", "answers", key)
        elif what == "wheel":  # the wheel's point at its rolling contact
            wheels = {r.wheel for r in getattr(self, "rolling_pairs", ())}
            lk = self.index.get(frozenset(names)) if len(names) == 2 else None
            if lk is None or lk.key not in wheels:
                raise self.error(f"{prefix}_{rest}: {rest} is no wheel of [rolling] (the key "
                                 "names a rolling wheel's link, e.g. aI_CP)", "answers", key)
        elif what == "pin":
            if len(names) != 1 or names[0] not in pin_names:
                raise self.error(f"rubbing at {rest} needs its size in [pins]", "answers", key)
        q = self.qty(value, kind, "answers", key, default_unit=next(iter(UNITS[kind])),
                     allow_sense=sense_ok)
        return Answer(key, prefix, names, q.value, q.sense, printable(str(value)), line)

