"""The ``[sliders]`` table (a part of the scene reader): a block on a fixed path, along a
link, in a yoke's slot, or a peg in two slots, each checked and turned into its record."""

from __future__ import annotations

import math
import re

from ..common.errors import SceneError
from ..common.tolerances import SAME
from ..common.units import UNITS
from .records import FixedPath, GuideSlider, YokeSlot, guide_words, split_name
from .table_help import _OFFSET, _suggest, _unit_at


class _Sliders:
    """The reader's methods for [sliders] (mixed into the reader)."""

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
            allowed = ("path", "through", "along", "direction", "offset")
            for k in spec:
                if k not in allowed:
                    raise self.error(f"unknown key '{k}'{_suggest(k, allowed)}", "sliders", name)
            if "offset" in spec and "along" not in spec:  # a line of stroke's offset
                raise self.error(
                    f"a fixed path takes no offset{_OFFSET}; "
                    'offset goes with along = "CP": a block in a slot of the lever CP '
                    "whose line misses the lever's centre line (or a peg's, or a yoke's slot)",
                    "sliders",
                    name,
                )
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
                out.append(self._guide_slider(name, spec, ground))
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

    def _guide_slider(self, name, spec, ground):
        """``P = { along = "CP" }``: a block at P sliding along the link CP between its ends
        (a link that is not fixed, given in [links])."""
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
                f"{name} is an end of {link.key}; a block slides along a link between its ends",
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
        offset = self._offset(spec["offset"], pts, name) if "offset" in spec else 0.0
        return GuideSlider(name, link.key, pts[0], pts[1], offset=offset)

    def _offset(self, raw, pts, name, looking=None):
        """An offset slot's distance from the link's line, signed to the left looking from
        the guide's first point to its second: a signed length (``offset = 40``, ``-40``,
        ``"40 mm"``) or with the side in words (``"40 mm left"``, ``"40 right"``)."""
        side, given = 1.0, raw
        if isinstance(raw, str):
            m = re.match(r"^\s*(.*?)[\s,]*\b(?:to\s+the\s+)?(left|right)\s*$", raw, re.I)
            if m:
                raw, side = m.group(1), (1.0 if m.group(2).lower() == "left" else -1.0)
                if raw.lstrip().startswith("-"):
                    raise self.error(
                        f"offset {raw!r} with a side: give the size alone, e.g. "
                        f'"{raw.strip().lstrip("-").strip()} {m.group(2)}"',
                        "sliders",
                        name,
                    )
            self._offset_side(raw, given, looking or f"from {pts[0]} to {pts[1]}", name)
        try:
            e = side * self.length(raw, "sliders", name, positive=False)
        except SceneError as exc:
            raise self.error(
                f"offset = {given!r}: {exc.message.rstrip('.')}; give the slot's distance off "
                'the link\'s line and its side, e.g. "30 mm left" (or a signed length)',
                "sliders",
                name,
            ) from None
        if e == 0.0:
            raise self.error(
                "offset = 0: the slot is on the link's own line; leave offset out",
                "sliders",
                name,
            )
        return e

    def _offset_side(self, raw, given, looking, name):
        """Words after an offset's length that are no side ("30 mm lfet", "30 mm up"):
        refused naming the side's two words, not as an unknown unit."""
        w = re.match(r"^\s*[-+]?[\d.]+(?:[eE][-+]?\d+)?\s*([A-Za-z]+)\s+(.+?)\s*$", raw)
        if w and w.group(1) in UNITS["length"]:
            side = w.group(2)
            hint = _suggest(side.lower(), ("left", "right"))
            if side.lower() in ("left", "right"):
                hint = ", given once"
            raise self.error(
                f"offset = {given!r}: the slot's side is left or right (looking {looking}), "
                f"not {side!r}{hint}",
                "sliders",
                name,
            )

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
        looking = f"along the slot ({label})"
        off = self._offset(spec["offset"], None, name, looking) if "offset" in spec else 0.0
        return YokeSlot(name, yoke, _unit_at(ang), label, offset=off)

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
        if abs(ux * dy - uy * dx) < SAME:
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
        offsets = self._peg_offsets(spec, guides, name)
        for guide, raw in zip(guides, offsets):
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
            off = 0.0 if raw is None else self._offset(raw, pts, name)
            out.append(GuideSlider(name, link.key, pts[0], pts[1], link.key, offset=off))
        if fixed:
            out.append(self.fixed_path(name, spec, ground, "ground"))
        elif "through" in spec:
            raise self.error(
                "through goes with path (a fixed slot); a peg in two slotted links has none",
                "sliders",
                name,
            )
        return out

    def _peg_offsets(self, spec, guides, name):
        """A peg's offsets, one a slot of a link: ``offset = "30 mm left"`` with one such
        slot (a fixed slot beside it), ``offset = ["30 mm left", 0]`` with two (0: the
        slot on its link's line). None where the scene gives none."""
        if "offset" not in spec:
            return [None] * len(guides)
        raw = spec["offset"]
        if len(guides) == 1:
            if isinstance(raw, list):
                raw = raw[0] if len(raw) == 1 else raw
            if isinstance(raw, list):
                raise self.error(
                    f"offset = {raw!r}: a peg in a fixed slot and the slot of {guides[0]} "
                    'has one offset, its slot\'s in the link: offset = "30 mm left"',
                    "sliders",
                    name,
                )
            return [raw]
        if not isinstance(raw, list) or len(raw) != len(guides):
            raise self.error(
                f"offset = {raw!r}: a peg in the slots of {guides[0]} and {guides[1]} takes "
                'one offset a slot, in their order: offset = ["30 mm left", 0] (0: the slot '
                "on its link's line)",
                "sliders",
                name,
            )
        if all(r in (0, "") for r in raw):
            raise self.error(
                "offset = [0, 0]: both slots are on their links' lines; leave offset out",
                "sliders",
                name,
            )
        return [None if r in (0, "") else r for r in raw]
