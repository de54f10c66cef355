"""A rate or a speed in a book's words (a part of the scene reader): a rate "slowing down" or
"speeding up" against the motion it is the rate of, and a speed with the way it goes ("3 m/s
down", "2 m/s at 30 deg"), signed along a guide where there is one."""

from __future__ import annotations

import re

from ..common.tolerances import SAME
from ..common.units import UNITS
from .rate_words import RATED as _RATED, slowing as _slowing
from .table_help import _unit_at

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


class _Rates:
    """The reader's methods for a rate or a speed in words (of [input], a driving block's,
    a driving wheel's)."""

    def rated(self, raw, kind, table, key, motion):
        """A rate in a book's words, ``"2 rad/s^2 slowing down"`` (``decelerating``,
        ``retarding``) or ``"... speeding up"`` (``accelerating``): its size against (with)
        the sense of ``motion``, the signed value it is the rate of (an omega, a sliding
        velocity, a rate of extension; +1 for a point's speed). None where ``raw`` has no
        such words (the caller reads it as before).

        >>> class R(_Rates):
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

    def directed(self, raw, kind, key, u, need, table="input"):
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
                    d = _unit_at(self.qty(ang, "angle", table, key, default_unit="deg").value)
                else:
                    d = _WORDS[word.lower().rstrip("s").replace("to the ", "").replace("ward", "")]
        value = self.qty(text, kind, table, key, default_unit=next(iter(UNITS[kind]))).value
        if u is not None:
            if d is not None:
                along = d[0] * u[0] + d[1] * u[1]
                if abs(along) < SAME:
                    raise self.error(
                        f"{raw!r}: the guide is perpendicular to that direction; "
                        "give the speed along the guide, signed, or up, down, "
                        "left, right",
                        table,
                        key,
                    )
                value = value * (1.0 if along > 0 else -1.0)
            return value, tuple(u)
        if d is None:
            if need:
                raise self.error(
                    f'{raw!r}: say which way the point moves, e.g. "3 m/s down" '
                    'or "3 m/s at 240 deg" (up, down, left, right or an angle)',
                    table,
                    key,
                )
            return value, None
        return value, d
