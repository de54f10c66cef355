"""The [input] table (a part of the scene reader): the driving crank, its angle (or the
position it gives, stated otherwise: ``length_OR``, ``s_B``, ``angle_DC``), its speed (or
the motion given on another quantity: ``vs_B``, ``omega_BC``, ``v_C``), a second driven
crank (``[input.second]``), and the slider crank's dead centres for angles in a book's
words."""

from __future__ import annotations

import math
import re

from ..common.errors import SceneError, printable
from ..common.tolerances import SAME
from ..common.units import UNITS
from .angles import candidates, is_book_form
from .crank_speed import crank_speed, link_angle, second_crank_angle
from .piston_words import towards_the_crank
from .rate_words import RATED as _RATED, slowing as _slowing
from .records import GIVEN_KINDS, INPUT_KEYS, FixedPath, GivenRate, Input, PositionGiven, split_name
from .tables import _suggest, _unit_at
from .wheel_input import wheel_input

#: a speed followed by a direction: up, down, left, right (upwards, to the left, ...), or
#: "at 30 deg"
_DIRECTED = re.compile(
    r"^(.*?\S)\s+(?:(up(?:wards?)?|down(?:wards?)?|(?:to the )?left(?:wards?)?|"
    r"(?:to the )?right(?:wards?)?)|at\s+(.+))$",
    re.IGNORECASE,
)
_WORDS = {"up": (0.0, 1.0), "down": (0.0, -1.0), "left": (-1.0, 0.0), "right": (1.0, 0.0)}
#: a sense or a way in a rate's text (refused beside "slowing down": one or the other)
_SENSE_OR_WAY = re.compile(
    r"(^\s*[-+])|\b(cw|ccw|acw|clockwise|anticlockwise|"
    r"counterclockwise|counter-clockwise|anti-clockwise|up|down|left|"
    r"right|upwards?|downwards?|at|extending|retracting)\b",
    re.IGNORECASE,
)


_WAYS = r"(extending|retracting|lengthening|shortening|outwards?|inwards?)"


def _extending(raw):
    """A cylinder's rate with a word: ``"0.2 m/s extending"`` (``"0.2 m/s, extending"``,
    ``"extending at 0.2 m/s"``) -> 0.2 m/s, ``retracting`` -> its negative (a signed
    number: + extending)."""
    if isinstance(raw, str):
        m = re.match(rf"^\s*(.*?\S)\s*,?\s+{_WAYS}\s*$", raw, re.IGNORECASE)
        m = m or re.match(rf"^\s*(){_WAYS}\s+(?:at\s+)?(.*?\S)\s*$", raw, re.IGNORECASE)
        if m:
            text = (m.group(1) or m.group(3)).strip()
            if m.group(2).lower() in ("retracting", "shortening", "inward", "inwards"):
                text = text[1:] if text.startswith("-") else "-" + text.lstrip("+")
            return text
    return raw


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


def _given_key(key):
    """(prefix, names) of an [input] key naming a given motion or its rate (``vs_B`` ->
    ("vs", ("B",))), or None."""
    prefix, _, rest = key.partition("_")
    if prefix not in ("omega", "vs", "v", "alpha", "as", "a") or not rest:
        return None
    names = split_name(rest)
    if (
        not names
        or len(names) > 2
        or (prefix in ("omega", "alpha") and len(names) != 2)
        or (prefix in ("v", "a") and len(names) != 1)
    ):
        return None  # vs_OR, as_OR: a cylinder's rate of extension
    return prefix, names


class _Input:
    """The [input] table's methods of the scene reader."""

    def rated(self, raw, kind, table, key, motion):
        """A rate in a book's words, ``"2 rad/s^2 slowing down"`` (``decelerating``,
        ``retarding``) or ``"... speeding up"`` (``accelerating``): its size against (with)
        the sense of ``motion``, the signed value it is the rate of (an omega, a sliding
        velocity, a rate of extension; +1 for a point's speed). None where ``raw`` has no
        such words (the caller reads it as before).

        >>> class R(_Input):
        ...     def qty(self, raw, kind, *a, **k): return parse_quantity(raw, kind)
        >>> from ..common.units import parse_quantity
        >>> R().rated("2 rad/s^2 slowing down", "angular_acceleration", "input", "a", -4.0)
        2.0
        >>> R().rated("speeding up at 3 m/s^2", "acceleration", "input", "as_B", -1.5)
        -3.0
        """
        if not isinstance(raw, str):
            return None
        text = raw.strip()
        m = _RATED[0].match(text)
        size_text, word = (m.group(1), m.group(2)) if m else (None, None)
        if m is None:
            m = _RATED[1].match(text)
            if m is None:
                return None
            word, size_text = m.group(1), m.group(2)
        if _SENSE_OR_WAY.search(size_text):
            raise self.error(
                f"{raw!r}: give the rate's sense (or way), or say slowing down / "
                "speeding up, not both",
                table,
                key,
            )
        if motion is None:
            raise self.error(
                f"{raw!r}: slowing down or speeding up says the rate's sense "
                "from the motion's, which is found here, not given: give the "
                "rate with its sense",
                table,
                key,
            )
        size = abs(self.qty(size_text, kind, table, key).value)
        slowing = _slowing(word)
        return (-size if slowing else size) * (1.0 if motion >= 0 else -1.0)

    def dead_centres(self, link, pivot, tip, ground):
        """The candidate dead centres of the slider crank that ``link`` drives, for
        :func:`.angles.read_angle`: ``[(inner, outer, keeps)]``."""
        rods = [
            (lk, s)
            for lk in self.index.values()
            if tip in lk.points and lk is not link
            for s in self.fixed
            if s.point == lk.other(tip)
        ]
        if len(rods) != 1:
            raise SceneError(
                "a dead centre is where the crank and the rod of a slider crank are in line; "
                + (
                    f"crank {link.key} drives no rod whose other end slides on a fixed path "
                    "in [sliders]: give the angle from +x, the horizontal or the vertical"
                    if not rods
                    else f"crank {link.key} drives {len(rods)} slider rods "
                    f"({', '.join(lk.key for lk, _ in rods)}): give the angle from +x"
                )
            )
        ((rod, slider),) = rods
        through = ground[pivot] if slider.through[1] is None else slider.through
        hint = self.raw.get("assembly")
        hint = hint.get(slider.point) if isinstance(hint, dict) else None
        if isinstance(hint, list) and len(hint) == 2:
            try:
                hint = tuple(self.length(c, "assembly", slider.point, positive=False) for c in hint)
            except SceneError:
                hint = None  # refused when [assembly] is read, by its own key
        return candidates(
            ground[pivot],
            link.length,
            rod.length,
            through,
            slider.u,
            hint,
            (self.unit, self.scale()),
        )

    def input(self, index, ground):
        if "input" not in self.raw:
            raise SceneError(
                "missing [input] table: which link is the crank, its angle and speed",
                file=self.file,
                key="[input]",
            )
        spec = self.table("input")
        if "block" in spec:  # a block on a fixed guide drives the mechanism: no crank
            return self.block_input(spec, ground)
        if "wheel" in spec:  # a wheel rolling on a ground line drives it: no crank
            return wheel_input(self, spec, ground)
        second = None
        if "second" in spec:  # a second driving crank: two degrees of freedom
            second = self.second_input(spec["second"], ground)
            spec = {k: v for k, v in spec.items() if k != "second"}
        placed = None
        at = [
            k
            for k in spec
            if k.partition("_")[0] in ("length", "s", "angle") and k.partition("_")[2]
        ]
        if at:  # the position given otherwise than by the crank's angle
            if "angle" in spec or len(at) > 1:
                raise self.error(
                    f"[input] gives the position twice ({', '.join(['angle'] * ('angle' in spec) + at)}): "
                    "one only (the crank's angle is then found)",
                    "input",
                    at[-1],
                )
            placed = self.placed_at(at[0], spec[at[0]], spec.get("near"))
            spec = {k: v for k, v in spec.items() if k not in (at[0], "near")}
        elif "near" in spec:
            raise self.error(
                "near is a rough crank angle choosing among those that give a "
                "position stated otherwise (length_OR, s_B, angle_CD): there is "
                "none",
                "input",
                "near",
            )
        rates = {k: _given_key(k) for k in spec if k not in INPUT_KEYS}
        for k, parsed in rates.items():
            if parsed is None:
                raise self.error(
                    f"unknown key{_suggest(k, INPUT_KEYS)}; [input] takes crank, "
                    "angle, speed, acceleration, or the given motion named as an "
                    "answer key (omega_BC, vs_B, v_B and alpha_BC, as_B, a_B)",
                    "input",
                    k,
                )
        given_keys = [k for k, p in rates.items() if p[0] in GIVEN_KINDS]
        rate_keys = [k for k, p in rates.items() if p[0] not in GIVEN_KINDS]
        if len(given_keys) > 1:
            raise self.error(
                f"[input] gives the motion twice ({', '.join(given_keys)}): a "
                "mechanism of one degree of freedom takes one input",
                "input",
                given_keys[1],
            )
        if given_keys and "speed" in spec:
            raise self.error(
                f"[input] gives both the crank's speed and {given_keys[0]}: one "
                "input only (remove speed to find the crank's from "
                f"{given_keys[0]})",
                "input",
                given_keys[0],
            )
        for k in ("crank",) + (() if placed else ("angle",)) + (() if given_keys else ("speed",)):
            if k not in spec:
                example = {
                    "crank": 'crank = "AB"',
                    "angle": "angle = 60",
                    "speed": 'speed = "10 rad/s ccw"',
                }[k]
                raise self.error(f"[input] has no {k}: add e.g. {example}", "input")
        link, pts = self.find_link(spec["crank"], "input", "crank")
        on_ground = [p for p in pts if p in ground]
        rolling = self.raw.get("rolling")
        if (
            not on_ground
            and isinstance(rolling, dict)
            and any(set(split_name(k)) == set(pts) for k in rolling)
        ):
            raise self.error(
                f"{link.key} is a rolling wheel, not a crank: on a line it drives "
                f'alone as wheel = "{link.key}" with omega_{link.key} (no '
                "crank); with a crank in the chain, give the wheel's motion as "
                f"omega_{link.key} (the crank's speed is then found)",
                "input",
                "crank",
            )
        if not on_ground:
            raise self.error(
                f"crank {link.key} is not pinned to the ground: neither "
                f"{pts[0]} nor {pts[1]} is in [ground]",
                "input",
                "crank",
            )
        if len(on_ground) == 2:
            raise self.error(
                f"crank {link.key} has both ends in [ground]; it cannot turn", "input", "crank"
            )
        pivot = on_ground[0]
        tip = link.other(pivot)
        said = ()
        if placed is not None:  # a provisional angle: the one that gives it is found later
            spec = dict(spec, angle=math.degrees(placed.near) if placed.near is not None else 0)
        if not is_book_form(spec["angle"]):
            angle = self.qty(spec["angle"], "angle", "input", "angle", default_unit="deg").value
        speed = (
            None
            if given_keys
            else self.rest_speed(spec["speed"])  # at rest: a bare nought needs no unit
            or crank_speed(self, spec["speed"], link)
        )
        if is_book_form(spec["angle"]):  # a dead centre is passed in the crank's sense
            if given_keys and re.search(
                r"\b(past|before|after|beyond)\b", str(spec["angle"]), re.IGNORECASE
            ):
                raise self.error(
                    f"{spec['angle']!r}: past or before a dead centre follows the "
                    "crank's sense, which a given motion leaves to be found; give "
                    "the angle from +x, the horizontal or the vertical",
                    "input",
                    "angle",
                )
            book = self.book_angle(
                spec["angle"],
                "angle",
                "input",
                "angle",
                "crank angle",
                dead=lambda: self.dead_centres(link, pivot, tip, ground),
                sense=None if speed is None else speed.value,
                centres=(pivot, ground),
            )
            angle = book.value
            said = (book.words, angle, book.slips, f"crank angle: {book.note}")
        acc = spec.get("acceleration", 0 if not given_keys else None)
        if acc is None:
            alpha = None
        elif isinstance(acc, (int, float)) and not isinstance(acc, bool) and acc == 0:
            alpha = 0.0
        else:
            alpha = self.rated(
                acc,
                "angular_acceleration",
                "input",
                "acceleration",
                None if speed is None else speed.value,
            )
            if alpha is None:
                alpha = self.qty(
                    acc, "angular_acceleration", "input", "acceleration", need_sense=True
                ).value
        if given_keys and second is not None:
            raise self.error(
                f"{given_keys[0]} with two inputs: give each crank's speed (a "
                "motion given elsewhere sets one input only)",
                "input",
                given_keys[0],
            )
        if given_keys:  # (the crank as stated, for "the piston moves towards the crank")
            self.crank_now = None if placed is not None else (pivot, tip, angle, link)
            given = self.given_rate(given_keys[0], rate_keys, spec, index)
            if given.rate is not None and "acceleration" in spec:
                raise self.error(
                    f"[input] gives both the crank's acceleration and {given.rate_key}: one only",
                    "input",
                    given.rate_key,
                )
            return Input(
                link.key,
                pivot,
                tip,
                angle,
                None,
                alpha,
                given.text,
                given,
                said=said,
                placed=placed,
            )
        if rate_keys:
            raise self.error(
                f"{rate_keys[0]} is the rate of a given motion, but [input] gives "
                "the crank's speed: give the crank's acceleration instead",
                "input",
                rate_keys[0],
            )
        if speed.value == 0:  # at rest: the weights and loads alone, per rad/s of the crank
            speed, alpha = self.at_rest_speed(alpha, speed.sense, second is not None), 0.0
        self.two_inputs = second is not None
        if second is not None and second.crank == link.key:
            raise self.error(
                f"the second input is the crank {link.key} again: name another "
                "link pivoted on the ground",
                "input.second",
                "crank",
            )
        return Input(
            link.key,
            pivot,
            tip,
            angle,
            speed.value,
            alpha,
            str(spec["speed"]),
            said=said,
            second=second,
            placed=placed,
        )

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
        vs_key, as_key, s_key = f"vs_{name}", f"as_{name}", f"s_{name}"
        if vs_key not in spec:
            raise self.error(
                f"[input] has no {vs_key}: add the block's velocity, e.g. {vs_key} "
                '= "2 m/s right"',
                "input",
            )
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
        rod, pts = self.find_link(sl.guide, table, "block")
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
        vs_key, as_key, s_key = f"vs_{name}", f"as_{name}", f"s_{name}"
        if vs_key not in spec:
            raise self.error(
                f"[{table}] has no {vs_key}: add the collar's sliding along its "
                f'rod, e.g. {vs_key} = "1.5 m/s outward" (or "towards {K}")',
                table,
            )

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

    def placed_at(self, key, raw, near):
        """``length_OR = 850`` (two points' distance, a cylinder's length), ``s_B = 300`` (a
        slider's place on its path from its through point), ``angle_CD = 30`` (the direction
        C -> D): the position as a book gives it; ``near``: a rough crank angle."""
        kind, _, rest = key.partition("_")
        names = split_name(rest)
        if kind == "s":
            sl = self.slider_points.get(names[0]) if len(names) == 1 else None
            if not isinstance(sl, FixedPath):
                raise self.error(
                    f"s_{rest}: no slider {rest} on a fixed path in [sliders] (s_B "
                    "is B's place along its path, from its through point)",
                    "input",
                    key,
                )
            value = self.length(raw, "input", key, positive=False)
        elif kind == "length":
            if len(names) != 2 or any(n not in self.known for n in names):
                raise self.error(
                    f"length_{rest}: two points of the scene, e.g. length_OR (the "
                    "distance O to R, a cylinder's length)",
                    "input",
                    key,
                )
            value = self.length(raw, "input", key)
        else:
            if len(names) != 2 or any(n not in self.known for n in names):
                raise self.error(
                    f"angle_{rest}: two points of the scene, e.g. angle_CD (the direction C -> D)",
                    "input",
                    key,
                )
            value = link_angle(self, raw, key, names, self.ground)
        near_v = (
            None
            if near is None
            else self.qty(near, "angle", "input", "near", default_unit="deg").value
        )
        text = printable(str(raw))
        if isinstance(raw, (int, float)) and not isinstance(raw, bool):
            text += " deg" if kind == "angle" else f" {self.unit}"
        return PositionGiven(key, kind, tuple(names), value, near_v, text)

    def second_input(self, spec, ground):
        """``[input.second]``: a second driving crank, with its crank, angle, speed and
        (optional) acceleration, read as the first's."""
        if not isinstance(spec, dict):
            raise self.error(
                "the second input is a table: [input.second] with crank, angle, speed",
                "input",
                "second",
            )
        if "block" in spec:  # a collar sliding along the turning crank
            sl = self.slider_points.get(spec["block"]) if isinstance(spec["block"], str) else None
            if sl is None or not hasattr(sl, "guide") or sl.slot:
                raise self.error(
                    f"{spec['block']!r}: the second input's block is a collar "
                    'sliding along a turning rod, C = { along = "O-A" } in '
                    "[sliders] (a block on a fixed guide as a second input is "
                    "not solved)",
                    "input.second",
                    "block",
                )
            return self.collar_input(spec, sl, ground, table="input.second")
        for k in spec:
            if k not in INPUT_KEYS:
                why = (
                    " (a block driven along a turning link, the collar on a rotating rod, "
                    "is not solved yet; a block on a fixed guide drives alone as [input] "
                    "block)"
                    if k == "block" or k.startswith(("vs_", "as_", "s_"))
                    else ""
                )
                raise self.error(
                    f"unknown key{_suggest(k, INPUT_KEYS)}; the second input "
                    f"takes crank, angle, speed, acceleration{why}",
                    "input.second",
                    k,
                )
        for k in ("crank", "angle", "speed"):
            if k not in spec:
                raise self.error(f"[input.second] has no {k}", "input.second")
        link, pts = self.find_link(spec["crank"], "input.second", "crank")
        on_ground = [p for p in pts if p in ground]
        if len(on_ground) != 1:
            raise self.error(
                f"the second crank {link.key} must turn about one ground point",
                "input.second",
                "crank",
            )
        pivot = on_ground[0]
        speed = crank_speed(self, spec["speed"], link, "input.second")
        angle = second_crank_angle(self, spec["angle"], link, pivot, ground, speed.value)
        if speed.value == 0:
            raise self.error(
                "the second crank's speed is zero: give it, or make it part of the frame",
                "input.second",
                "speed",
            )
        acc = spec.get("acceleration", 0)
        alpha = (
            0.0
            if (isinstance(acc, (int, float)) and not isinstance(acc, bool) and acc == 0)
            else self.rated(
                acc, "angular_acceleration", "input.second", "acceleration", speed.value
            )
        )
        if alpha is None:
            alpha = self.qty(
                acc, "angular_acceleration", "input.second", "acceleration", need_sense=True
            ).value
        return Input(
            link.key, pivot, link.other(pivot), angle, speed.value, alpha, str(spec["speed"])
        )

    def given_rate(self, key, rate_keys, spec, index) -> GivenRate:
        """``omega_BC = "3 rad/s cw"``, ``vs_B = "1.5 m/s up"``, ``v_B = "3 m/s down"`` in
        [input], with its rate (``alpha_BC``, ``as_B``, ``a_B``) if given."""
        kind, names = _given_key(key)
        rate_kind = GIVEN_KINDS[kind]
        for r in rate_keys:
            rk, rnames = _given_key(r)
            if rk != rate_kind or rnames != names:
                raise self.error(
                    f"{r} does not go with {key}: the given motion's rate is "
                    f"{rate_kind}_{'-'.join(names) if len(names) > 1 and any(len(n) > 1 for n in names) else ''.join(names)}",
                    "input",
                    r,
                )
        rate_key = rate_keys[0] if rate_keys else None
        raw, raw_rate = spec[key], spec.get(rate_key) if rate_key else None
        text = printable(str(raw))
        rate_text = None if raw_rate is None else printable(str(raw_rate))
        direction = None
        if kind == "omega":
            if len(names) != 2 or frozenset(names) not in index:
                raise self.error(f"no link {''.join(names)} in [links]", "input", key)
            value = self.qty(raw, "angular_velocity", "input", key, need_sense=True).value
            rate = (
                None
                if raw_rate is None
                else (
                    0.0
                    if raw_rate == 0
                    else self.rated(raw_rate, "angular_acceleration", "input", rate_key, value)
                )
            )
            if rate is None and raw_rate is not None:
                rate = self.qty(
                    raw_rate, "angular_acceleration", "input", rate_key, need_sense=True
                ).value
            names = index[frozenset(names)].points
        else:
            point = names[0] if len(names) == 1 else None
            if kind == "vs" and point is None:  # a cylinder's rate of extension
                cyl = self.find_cylinder(names)
                if cyl is None:
                    raise self.error(f"no cylinder {'-'.join(names)} in [cylinders]", "input", key)
                names, u = (cyl.key,), (1.0, 0.0)  # signed: + extending
                raw = _extending(raw)
                if raw_rate is not None and not (
                    isinstance(raw_rate, str) and any(r.match(raw_rate.strip()) for r in _RATED)
                ):  # slowing: kept
                    raw_rate = _extending(raw_rate)
            elif kind == "vs":
                sl = self.slider_points.get(point)
                if sl is None:
                    raise self.error(f"no slider {''.join(names)} in [sliders]", "input", key)
                u = getattr(sl, "u", None)
                raw, raw_rate = towards_the_crank(self, sl, (raw, key), (raw_rate, rate_key))
            else:
                if point is None or point not in self.known:
                    raise self.error(f"no point {''.join(names)} in the scene", "input", key)
                u = None
            value, direction = self.directed(raw, "velocity", key, u, need=kind == "v")
            rate = None
            if raw_rate is not None:  # a point's speed: its rate is of the speed (+1)
                rate = self.rated(
                    raw_rate, "acceleration", "input", rate_key, value if kind == "vs" else 1.0
                )
            if raw_rate is not None and rate is None:
                rate, _ = self.directed(
                    raw_rate, "acceleration", rate_key, u if kind == "vs" else None, need=False
                )
        if value == 0:
            raise self.error(
                f"{key} is zero: it does not set the crank's speed (give the "
                "crank's speed instead)",
                "input",
                key,
            )
        return GivenRate(key, kind, tuple(names), value, rate, direction, text, rate_key, rate_text)

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
                if abs(along) < SAME:
                    raise self.error(
                        f"{raw!r}: the guide is perpendicular to that direction; "
                        "give the speed along the guide, signed, or up, down, "
                        "left, right",
                        "input",
                        key,
                    )
                value = value * (1.0 if along > 0 else -1.0)
            return value, tuple(u)
        if d is None:
            if need:
                raise self.error(
                    f'{raw!r}: say which way the point moves, e.g. "3 m/s down" '
                    'or "3 m/s at 240 deg" (up, down, left, right or an angle)',
                    "input",
                    key,
                )
            return value, None
        return value, d
