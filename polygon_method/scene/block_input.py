"""A driving block (a part of the scene reader): ``[input] block``, a block on its fixed guide
or a collar sliding along a turning rod (also as ``[input.second]``), its sliding, place and
stroke."""

from __future__ import annotations

import math
import re

from ..common.errors import printable
from ..common.tolerances import SAME
from ..common.units import UNITS
from .records import INPUT_KEYS, FixedPath, Input

#: "1.5 m/s outward", "2 m/s towards O", "inwards", "away from O": the sliding's sense
_SENSE = re.compile(
    r"^\s*(.*?\S)\s*,?\s+(outwards?|inwards?|(?:towards?|away from)\s+"
    r"([A-Z][0-9]*))\s*$",
    re.IGNORECASE,
)


def outward(raw, pivot, other):
    """A collar's rate as a scene gives it, signed outward (from the pivot towards the rod's
    other end): ``"1.5 m/s outward"``, ``"2 m/s towards O"`` (its pivot: inward), ``"away
    from O"``; a plain signed quantity unchanged. Returns (text, sign) or None for a word
    naming neither end of the rod."""
    if not isinstance(raw, str):
        return raw, 1.0
    m = _SENSE.match(raw)
    if not m:
        return raw, 1.0
    word, name = m.group(2).lower(), m.group(3)
    if name is None:
        return m.group(1), (-1.0 if word.startswith("in") else 1.0)
    if name not in (pivot, other):
        return None
    toward = word.startswith("toward")
    return m.group(1), (1.0 if toward == (name == other) else -1.0)


class _BlockInput:
    """The reader's methods for a driving block or collar in [input]."""

    def block_input(self, spec, ground):
        """``block = "A"``: the block A, on its fixed path of [sliders], drives the mechanism;
        ``vs_A`` its velocity along the guide (signed, or up/down/left/right), ``as_A`` its
        acceleration (default 0: steady), ``s_A`` its place along the guide from the path's
        through point (or ``A = [x, y]``, a point of the guide), ``stroke = [a, b]`` the
        range of s a sweep runs over (optional)."""
        name = spec["block"]
        if not isinstance(name, str):
            raise self.error(
                'block names the driving block\'s point, e.g. block = "A"', "input", "block"
            )
        sl = self.slider_points.get(name)
        if sl is not None and hasattr(sl, "guide") and not sl.slot:  # along a moving rod
            return self.collar_input(spec, sl, ground)
        if not isinstance(sl, FixedPath) or sl.slot:
            raise self.error(
                f"no block {name} on a fixed path in [sliders] (the driving block "
                'slides on a fixed straight guide: A = { path = "horizontal" })',
                "input",
                "block",
            )
        self._block_keys(spec, name)
        vs_key, as_key = f"vs_{name}", f"as_{name}"
        through = sl.through if sl.through[1] is not None else next(iter(ground.values()))
        u = sl.u
        vs, _ = self.directed(spec[vs_key], "velocity", vs_key, u, need=False)
        raw_as = spec.get(as_key, 0)
        if isinstance(raw_as, (int, float)) and not isinstance(raw_as, bool) and raw_as == 0:
            acc = 0.0
        else:
            acc = self.rated(raw_as, "acceleration", "input", as_key, vs)
            if acc is None:
                acc, _ = self.directed(raw_as, "acceleration", as_key, u, need=False)
        if vs == 0:  # at rest (the weights held, or starting with acc): per 1 m/s
            vs, acc = self.at_rest_driver(vs, acc, vs_key), 0.0
        s = self._place_on_guide(spec, name, through, u)
        stroke = self.stroke(
            spec,
            s,
            "input",
            "the block's places along its guide (as s), e.g. stroke = [-400, 400]",
            "block",
        )
        self.driving_block = name  # (a torque answer is refused: a block is driven by a force)
        return Input(
            None, None, name, s, vs, acc, printable(str(spec[vs_key])), block=name, stroke=stroke
        )

    def _block_keys(self, spec, name):
        """The keys of [input] that a driving block ``name`` takes: no other, its velocity
        given."""
        allowed = ("block", f"s_{name}", f"vs_{name}", f"as_{name}", name, "stroke")
        for k in spec:
            if k not in allowed:
                why = (
                    "a block drives the mechanism: there is no crank, so no crank, angle, "
                    "speed or acceleration"
                    if k in INPUT_KEYS or k == "second"
                    else "unknown key"
                )
                raise self.error(
                    f'{why}; with block = "{name}", [input] takes vs_{name} (its '
                    f"velocity), as_{name} (its acceleration), s_{name} or {name} = "
                    "[x, y] (its place) and stroke = [from, to]",
                    "input",
                    k,
                )
        vs_key = f"vs_{name}"
        if vs_key not in spec:
            raise self.error(
                f"[input] has no {vs_key}: add the block's velocity, e.g. {vs_key} "
                '= "2 m/s right"',
                "input",
            )

    def _place_on_guide(self, spec, name, through, u):
        """The driving block's place s (m) along its guide (unit ``u``) from the path's
        through point: ``s_A``, or ``A = [x, y]``, a point of the guide; one of them."""
        s_key = f"s_{name}"
        if (s_key in spec) == (name in spec):
            raise self.error(
                f"[input] gives the block's place {'twice' if name in spec else 'not at all'}:"
                f" {s_key} = 300 (along its guide from its through point) or {name} = "
                "[x, y], one only",
                "input",
                s_key if s_key in spec else None,
            )
        if s_key in spec:
            s = self.length(spec[s_key], "input", s_key, positive=False)
        else:
            x, y = self.coords(spec[name], "input", name)
            s = (x - through[0]) * u[0] + (y - through[1]) * u[1]
            off = -(x - through[0]) * u[1] + (y - through[1]) * u[0]
            if abs(off) > SAME * max(abs(x), abs(y), abs(s), self.scale()):
                raise self.error(
                    f"{name} = {spec[name]} is {abs(off) / self.scale():.6g} "
                    f"{self.unit} off the guide of {name}: give a point of it",
                    "input",
                    name,
                )
        return s

    def stroke(self, spec, s, table, example, what):
        """``stroke = [a, b]`` of a driving block or collar at place ``s``: (a, b) in m, or
        None where the table gives none."""
        if "stroke" not in spec:
            return None
        raw = spec["stroke"]
        if not isinstance(raw, list) or len(raw) != 2:
            raise self.error(f"stroke is [from, to]: {example}", table, "stroke")
        a, b = (self.length(v, table, "stroke", positive=False) for v in raw)
        if not a < b:
            raise self.error(f"stroke = {raw}: from must be less than to", table, "stroke")
        if not a <= s <= b:
            raise self.error(
                f"the {what}'s place s = {s / self.scale():.6g} {self.unit} is "
                f"outside its stroke {raw}",
                table,
                "stroke",
            )
        return (a, b)

    def collar_input(self, spec, sl, ground, table="input"):
        """``block = "C"`` for a collar C of [sliders] sliding along a rod (``C = { along =
        "O-A" }``): ``vs_C`` its sliding relative to the rod (signed outward, from the rod's
        fixed pivot towards its other end, or "outward", "towards O"), ``as_C`` the rate of
        it (default 0), ``s_C`` its place along the rod from the pivot (or ``C = [x, y]``),
        ``stroke = [a, b]`` the places a sweep runs over (optional)."""
        name = sl.point
        rod, K, N = self._collar_rod(sl, ground, table)
        self._collar_keys(spec, name, rod, K, table)
        vs_key, as_key, s_key = f"vs_{name}", f"as_{name}", f"s_{name}"
        vs = self.collar_rate(spec, vs_key, "velocity", rod.key, K, N, table)
        acc = (
            self.collar_rate(spec, as_key, "acceleration", rod.key, K, N, table)
            if as_key in spec
            else 0.0
        )
        if vs == 0:  # at rest (the weights held, or starting with acc): per 1 m/s
            if table != "input":
                raise self.error(f"{vs_key} is zero: nothing moves", table, vs_key)
            vs, acc = self.at_rest_driver(vs, acc, vs_key), 0.0
        if (s_key in spec) == (name in spec):
            raise self.error(
                f"[{table}] gives the collar's place "
                f"{'twice' if name in spec else 'not at all'}: {s_key} = 300 (from "
                f"the rod's pivot {K} towards {N}) or {name} = [x, y], one only",
                table,
                s_key if s_key in spec else None,
            )
        hint = None
        if s_key in spec:
            s = self.length(spec[s_key], table, s_key, positive=False)
        else:
            x, y = self.coords(spec[name], table, name)
            s = math.hypot(x - ground[K][0], y - ground[K][1])
            hint = (x, y)
        stroke = self.stroke(
            spec,
            s,
            table,
            f"the collar's places along its rod from {K} (as s), e.g. stroke = [100, 400]",
            "collar",
        )
        if table == "input":
            self.driving_block = name
        self.collar_hint = (name, hint) if hint is not None else None
        return Input(
            None, None, name, s, vs, acc, printable(str(spec[vs_key])), block=name, stroke=stroke
        )

    def _collar_rod(self, sl, ground, table):
        """(rod, K, N): the rod the driving collar ``sl`` slides along, turning about its one
        pivot K of [ground]; N its other end."""
        name = sl.point
        rod, pts = self.find_link(sl.guide, table, "block")
        if sl.offset:
            raise self.error(
                f"the collar {name} driven along {rod.key} sits on the rod's own line: its "
                f"[sliders] entry takes no offset (an offset slot is for a block the "
                "mechanism moves)",
                table,
                "block",
            )
        pivots = [p for p in pts if p in ground]
        if len(pivots) != 1:
            raise self.error(
                f"the collar {name} slides along the rod {rod.key}, which is "
                "pivoted on the frame at "
                + ("both ends: it cannot turn" if pivots else "neither end")
                + ": the rod of a driving collar turns about one point of "
                "[ground]"
                + (
                    ""
                    if table != "input" or pivots
                    else " (a rod that a crank moves: drive the crank, with "
                    f'the collar as [input.second] block = "{name}")'
                ),
                table,
                "block",
            )
        K = pivots[0]
        N = rod.other(K)
        return rod, K, N

    def _collar_keys(self, spec, name, rod, K, table):
        """The keys of [input] (or [input.second]) that a driving collar ``name`` on ``rod``
        takes: no other, its sliding given."""
        allowed = ("block", f"s_{name}", f"vs_{name}", f"as_{name}", name, "stroke")
        for k in spec:
            if k not in allowed:
                why = (
                    "unknown key"
                    if k not in INPUT_KEYS and k != "second"
                    else "a collar drives the mechanism: there is no crank, so no crank, "
                    "angle, speed or acceleration"
                    if table == "input"
                    else "the second input is the collar's sliding (the crank is [input]'s)"
                )
                raise self.error(
                    f'{why}; with block = "{name}" (a collar on the rod '
                    f"{rod.key}), [{table}] takes vs_{name} (its sliding along the "
                    f"rod), as_{name}, s_{name} (its place from {K}) or {name} = "
                    "[x, y], and stroke = [from, to]",
                    table,
                    k,
                )
        vs_key = f"vs_{name}"
        if vs_key not in spec:
            raise self.error(
                f"[{table}] has no {vs_key}: add the collar's sliding along its "
                f'rod, e.g. {vs_key} = "1.5 m/s outward" (or "towards {K}")',
                table,
            )

    def collar_rate(self, spec, key, kind, rod, K, N, table):
        """A collar's sliding (or its rate) along its rod K-N, signed outward."""
        said = outward(spec[key], K, N)
        if said is None:
            raise self.error(
                f"{spec[key]!r}: towards which end of the rod {rod}? say "
                f'"outward", "towards {K}" or "towards {N}"',
                table,
                key,
            )
        text, sign = said
        if isinstance(text, (int, float)) and not isinstance(text, bool) and text == 0:
            return 0.0
        return sign * self.qty(text, kind, table, key, default_unit=next(iter(UNITS[kind]))).value
