"""Quantities with units, parsed the way a problem states them.

>>> parse_quantity("50 mm", "length")
Quantity(value=0.05, sense=None)
>>> parse_quantity("180 rpm ccw", "angular_velocity", need_sense=True).value  # 2 pi 180/60
18.84955592153876
>>> parse_quantity("10.5 rad/s cw", "angular_velocity", need_sense=True)
Quantity(value=-10.5, sense='cw')
>>> parse_quantity("2 ft 6 in", "length").value == parse_quantity("30 in", "length").value
True

Values come back in SI (m, rad, rad/s, rad/s^2, N, m/s, m/s^2, N m, kg, kg m^2, Pa); a sense ``cw`` makes
the value negative (counter-clockwise positive).
"""

from __future__ import annotations

import difflib
import math
import re
from dataclasses import dataclass

from .errors import SceneError
from .typography import decimal_comma, long_integer_text, typographic

__all__ = [
    "Quantity",
    "parse_quantity",
    "UNITS",
    "LENGTH_UNITS",
    "ABSURD",
    "TINY",
    "format_unit_list",
    "suggest",
    "did_you_mean",
    "implausible",
    "ANSWER_UNITS",
    "question",
    "question_unit",
    "ABSOLUTE_TOLERANCES",
]

from .unit_tables import ABSURD, ANSWER_UNITS, LENGTH_UNITS, TINY, UNITS
from .unit_tables import SI_NAME as _SI_NAME

#: the kinds of answer an absolute tolerance may be given in (``check --tolerance "1 mm"``),
#: each with its SI unit: a centre's position, a stroke or an offset (a length); a link's
#: direction or a joint's angle (an angle); and the answers' own kinds
ABSOLUTE_TOLERANCES = (
    ("velocity", "m/s"),
    ("acceleration", "m/s^2"),
    ("angular_velocity", "rad/s"),
    ("angular_acceleration", "rad/s^2"),
    ("torque", "N m"),
    ("length", "m"),
    ("angle", "rad"),
)

#: sense words: the format's cw/ccw, and the spellings textbooks use
_SENSES = {
    "cw": "cw",
    "clockwise": "cw",
    "ccw": "ccw",
    "acw": "ccw",
    "anticlockwise": "ccw",
    "anti-clockwise": "ccw",
    "counterclockwise": "ccw",
    "counter-clockwise": "ccw",
    "c.w.": "cw",  # older books' abbreviations
    "a.c.w.": "ccw",
    "c.c.w.": "ccw",
}
_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_QUANTITY = re.compile(rf"^\s*({_NUMBER})\s*(.*?)\s*$")
#: a length in feet and inches, as US books write it: "2 ft 6 in" (a minus sign before it
#: applies to the whole: "-2 ft 6 in" is -2.5 ft)
_FEET_INCHES = re.compile(
    r"^\s*([-+]?)\s*(\d+\.?\d*|\.\d+)\s*(?:ft|feet|foot)\s+"
    r"(\d+\.?\d*|\.\d+)\s*(?:in|inch|inches)\s*$"
)


@dataclass(frozen=True)
class Quantity:
    """A parsed value in SI, with the sense it was given (``cw``/``ccw``) if any."""

    value: float
    sense: str | None = None


def format_unit_list(kind: str) -> str:
    """The units of one kind, for messages."""
    return ", ".join(u for u in UNITS[kind] if "." not in u)


def _edits(a: str, b: str) -> int:
    """Damerau-Levenshtein distance (a swap of two neighbours counts as one typo)."""
    d = [[i + j if i * j == 0 else 0 for j in range(len(b) + 1)] for i in range(len(a) + 1)]
    for i in range(1, len(a) + 1):
        for j in range(1, len(b) + 1):
            cost = a[i - 1] != b[j - 1]
            d[i][j] = min(d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + cost)
            if i > 1 and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                d[i][j] = min(d[i][j], d[i - 2][j - 2] + 1)
    return d[-1][-1]


def suggest(word, choices) -> str | None:
    """The choice a typo most likely meant, or None.

    Fewest typos first (a swapped pair counts as one), then the same length, then the
    order of ``choices``.

    >>> suggest("rmp", ["rad/s", "rpm", "rps"]), suggest("mn", ["mm", "cm", "m"])
    ('rpm', 'mm')
    >>> suggest("zzz", ["mm", "cm"]) is None, suggest("Z", ["A", "B"]) is None
    (True, True)
    """
    word = str(word)
    choices = [str(c) for c in choices]
    if not word or not choices or len(word) > 60:
        return None
    limit = min(max(1, (len(word) + 1) // 3), len(word) - 1)  # "Z" does not suggest "A"
    ranked = sorted(
        (_edits(word.lower(), c.lower()), len(c) != len(word), i, c) for i, c in enumerate(choices)
    )
    if ranked[0][0] <= limit:
        return ranked[0][3]
    close = difflib.get_close_matches(word, choices, n=1, cutoff=0.6)
    return close[0] if close else None


def did_you_mean(word, choices) -> str:
    """`` (did you mean 'X'?)`` or an empty string."""
    best = suggest(word, choices)
    return f" (did you mean '{best}'?)" if best is not None else ""


def _unit_factor(unit: str, kind: str, where: str) -> float:
    table = UNITS[kind]
    if unit in table:
        return table[unit]
    spaced = re.sub(r"(?<=[A-Za-z])[-.](?=[A-Za-z])", " ", unit)  # "kg-m^2", "kg.m^2"
    if spaced in table:
        return table[spaced]
    folded = {u.lower(): f for u, f in table.items()}
    if unit.lower() in folded and kind not in ("force", "pressure"):
        return folded[unit.lower()]
    other = next((k for k, t in UNITS.items() if unit in t), None)
    if other is not None:
        raise SceneError(
            f"'{_clip(unit)}' is a unit of {other.replace('_', ' ')}, "
            f"not of {kind.replace('_', ' ')} (use {format_unit_list(kind)})",
            key=where,
        )
    raise SceneError(
        f"unknown unit '{_clip(unit)}'{did_you_mean(unit, table)}; use {format_unit_list(kind)}",
        key=where,
    )


#: the kinds of quantity with a sense (cw, ccw)
_TURNING_KINDS = ("angular_velocity", "angular_acceleration", "torque")
#: a question asked without its answer: ``"?"``, or ``"? rpm"`` (the unit of its answer)
_QUESTION = re.compile(r"^\s*\?\s*(.*?)\s*$", re.S)


def question(raw) -> str | None:
    """The unit a question asks its answer in (``"? rpm"``: ``"rpm"``; a bare ``"?"``:
    ``""``); None where ``raw`` is no question (a value).

    >>> question("?"), question(" ? m/s "), question("0.4 m/s"), question(0.4)
    ('', 'm/s', None, None)
    """
    if not isinstance(raw, str):
        return None
    m = _QUESTION.match(raw)
    return None if m is None else m.group(1)


def question_unit(unit: str, kind: str, where: str = "") -> float:
    """The factor to SI of a question's unit (``"rpm"`` of ``"? rpm"``), checked to be a
    unit of ``kind``; a sense after it is refused (the answer gives the sense)."""
    words = unit.split()
    if words and words[-1].lower() in _SENSES and kind not in _TURNING_KINDS:
        raise SceneError(
            f"'? {_clip(unit)}': {kind.replace('_', ' ')} has no sense cw or ccw: write "
            f'"? {" ".join(words[:-1]) or format_unit_list(kind).split(", ")[0]}"',
            key=where,
        )
    if words and words[-1].lower() in _SENSES:
        raise SceneError(
            f"'? {_clip(unit)}': a question asks for the sense too: write "
            f'"? {" ".join(words[:-1]) or format_unit_list(kind).split(", ")[0]}" '
            "(the answer gives cw or ccw)",
            key=where,
        )
    return _unit_factor(unit, kind, where)


def parse_quantity(
    raw,
    kind: str,
    *,
    where: str = "",
    default_unit: str | None = None,
    need_sense: bool = False,
    allow_sense: bool = False,
    refuse_absurd: bool = True,
) -> Quantity:
    """Parse a bare number or a ``"value unit [cw|ccw]"`` string into SI.

    Parameters
    ----------
    raw : int, float or str
        ``50``, ``"50 mm"``, ``"10.5 rad/s cw"``.
    kind : str
        A key of :data:`UNITS`.
    where : str
        The scene key, for error messages.
    default_unit : str, optional
        The unit of a bare number; without it a bare number is an error.
    need_sense, allow_sense : bool
        Whether ``cw``/``ccw`` must / may follow.
    refuse_absurd : bool
        Whether a value beyond :data:`ABSURD` is an error (a scene's input); an answer is
        read whatever its size (the mechanism may produce it) and warned of instead
        (:func:`implausible`).
    """
    q = _at_once(raw, kind, default_unit, need_sense, allow_sense, refuse_absurd)
    if q is not None:
        return q
    return _whole_way(raw, kind, where, default_unit, need_sense, allow_sense, refuse_absurd)


#: the characters of a number as a quantity's text writes it: of these, what ``float``
#: reads is what :data:`_NUMBER` matches (no underscores, no words such as ``inf``)
_NUMBER_CHARS = frozenset("0123456789.eE+-")


def _at_once(raw, kind, default_unit, need_sense, allow_sense, refuse_absurd):
    """The usual quantity read without a regular expression: a bare number in its default
    unit, or ``"number unit"`` or ``"number unit sense"`` with the kind's unit as its table
    writes it; None for anything else and for a value the whole way refuses, which
    :func:`parse_quantity` then reads the whole way (and words). The same value and
    sense as the whole way, to the last bit (a test holds the two equal)."""
    t = type(raw)
    if t is int or t is float:
        if default_unit is None or need_sense or not -1e300 < raw < 1e300:
            return None
        factor = UNITS[kind].get(default_unit)
        value, sense = float(raw), None
    elif t is str:
        words = raw.split()
        n = len(words)
        if n != 2 and n != 3 or not _NUMBER_CHARS.issuperset(words[0]):
            return None
        factor = UNITS[kind].get(words[1])
        sense = _SENSES.get(words[2].lower()) if n == 3 else None
        if n == 3 and sense is None:
            return None
        try:
            value = float(words[0])
        except ValueError:
            return None
        if sense is not None and (value < 0 or not (need_sense or allow_sense)):
            return None
        if need_sense and sense is None and value != 0:
            return None
    else:
        return None
    if factor is None or not math.isfinite(value):
        return None
    si = value * factor
    if refuse_absurd and kind in ABSURD and not abs(si) <= ABSURD[kind]:
        return None
    if kind in TINY and abs(si) < TINY[kind] and (si != 0 or t is str and _nonzero(words[0])):
        return None
    return Quantity(-si if sense == "cw" else si, sense)


def _whole_way(raw, kind, where, default_unit, need_sense, allow_sense, refuse_absurd):
    """:func:`parse_quantity` the whole way: every form, every refusal worded."""
    if isinstance(raw, bool) or not isinstance(raw, (int, float, str)):
        raise SceneError(
            f'expected a number or a string such as "50 mm", got {_kind_of(raw)}', key=where
        )
    if isinstance(raw, str) and (not raw.isascii() or "10^" in raw or "10**" in raw):
        # "−10.5 rad/s", "1.2×10^3 mm", "2½ in", "1.2*10^3 mm"
        raw = typographic(raw, where, _UNIT_MARKS)
    if isinstance(raw, str) and "," in raw:  # "10,5 rad/s": a decimal comma
        read = decimal_comma(raw)
        if read is None:
            raise SceneError(
                f"'{_clip(raw)}': the comma reads two ways (a decimal comma, or "
                'thousands?): write the number with a decimal point, e.g. "1.25" or "1250"',
                key=where,
            )
        raw = read
    if kind == "length" and isinstance(raw, str) and _FEET_INCHES.match(raw):
        return _feet_and_inches(raw, where)
    if isinstance(raw, str):
        value, factor, sense = _read_text(raw, kind, where, default_unit)
    else:
        (value, factor), sense = _read_number(raw, kind, where, default_unit, need_sense), None
    if not math.isfinite(value):
        raise SceneError(f"'{_clip(raw)}' is not a finite number", key=where)
    _check_sense(raw, value, sense, where, need_sense, allow_sense)
    si = value * factor
    _check_size(raw, si, kind, where, refuse_absurd)
    if sense == "cw":
        si = -si
    return Quantity(si, sense)


#: the characters outside ASCII that units are spelt with (the degree sign, a superscript two)
_UNIT_MARKS = "".join(sorted({c for t in UNITS.values() for u in t for c in u if not c.isascii()}))


def _feet_and_inches(raw: str, where: str) -> Quantity:
    """A length in feet and inches (``5 ft 3 in``, ``-1' 6"``) in metres; inches of a foot or
    more are an error."""
    sign, feet, inches = _FEET_INCHES.match(raw).groups()
    si = float(feet) * UNITS["length"]["ft"] + float(inches) * UNITS["length"]["in"]
    if float(inches) >= 12:
        raise SceneError(
            f"'{_clip(raw)}': {inches} in is a foot or more; write the feet and "
            'the inches below 12, or the whole in one unit ("30 in")',
            key=where,
        )
    return Quantity(-si if sign == "-" else si)


def _read_text(raw: str, kind: str, where: str, default_unit: str | None) -> tuple:
    """A ``"value unit [cw|ccw]"`` string's value, its unit's factor to SI and its sense (None
    without one); two senses, no number or no unit (without ``default_unit``) are errors."""
    sense = None
    text = raw.strip()
    # "120 rpm, clockwise", "... counter clockwise" as a book writes them
    words = re.sub(
        r"(?i)\b(counter|anti) clockwise", r"\1clockwise", text.replace(", ", " ")
    ).split()
    if words and words[-1].lower() in _SENSES:
        sense = _SENSES[words[-1].lower()]
        text = " ".join(words[:-1])
        if len(words) > 2 and words[-2].lower() in _SENSES:  # "10 rad/s cw ccw"
            raise SceneError(f"'{_clip(raw)}' gives two senses: give one, cw or ccw", key=where)
    m = _QUANTITY.match(text)
    if not m:
        raise SceneError(
            f"cannot read '{_clip(raw)}' as a quantity (a number, then a unit)", key=where
        )
    value = float(m.group(1))
    unit = m.group(2).strip()
    if not unit:
        if default_unit is None:
            raise SceneError(
                f"'{_clip(raw)}' has no unit; write it as e.g. "
                f'"{m.group(1)} {format_unit_list(kind).split(", ")[0]}"',
                key=where,
            )
        unit = default_unit
    return value, _unit_factor(unit, kind, where), sense


def _read_number(raw, kind: str, where: str, default_unit: str | None, need_sense=False) -> tuple:
    """A bare number's value and ``default_unit``'s factor to SI; without a default unit, or an
    integer too large for a float, an error."""
    try:
        value = float(raw)
    except OverflowError:  # an integer of hundreds of digits
        raise SceneError(
            f"the integer {long_integer_text(raw)} is "
            "absurd for a mechanism; check the value and its unit",
            key=where,
        ) from None
    if default_unit is None:
        raise SceneError(
            f"{raw} has no unit; write it as a string such as "
            f'"{raw} {format_unit_list(kind).split(", ")[0]}{" ccw" if need_sense else ""}"',
            key=where,
        )
    return value, _unit_factor(default_unit, kind, where)


def _check_sense(raw, value: float, sense, where: str, need_sense: bool, allow_sense: bool) -> None:
    """Refuse a sense where none belongs, a negative value with a sense (it reads two ways) and
    a missing sense where one is needed (a zero needs none)."""
    if sense is not None and not (need_sense or allow_sense):
        raise SceneError(f"'{_clip(raw)}': a sense (cw/ccw) does not belong here", key=where)
    if sense is not None and value < 0:  # "-10 rad/s cw": cw, or ccw (minus cw)?
        raise SceneError(
            f"'{_clip(raw)}': a negative value with a sense reads two ways; give the "
            f'size and its sense ("{_clip(_magnitude(raw))} cw" or "... ccw")',
            key=where,
        )
    if need_sense and sense is None and value != 0:
        raw_size = _clip(_magnitude(raw) if value < 0 else str(raw).strip())
        raise SceneError(
            f"'{_clip(raw)}' has no sense: add cw or ccw (e.g. \"{raw_size} ccw\")", key=where
        )


def _check_size(raw, si: float, kind: str, where: str, refuse_absurd: bool) -> None:
    """Refuse a value absurdly large (when ``refuse_absurd``) or absurdly small for a
    mechanism, in SI, for the kinds :data:`ABSURD` and :data:`TINY` bound."""
    if refuse_absurd and kind in ABSURD and not abs(si) <= ABSURD[kind]:
        raise SceneError(
            f"'{_clip(raw)}' is absurd for a mechanism (more than {ABSURD[kind]:g} "
            f"{_SI_NAME[kind]}); check the value and its unit",
            key=where,
        )
    if kind in TINY and abs(si) < TINY[kind] and (si != 0 or _nonzero(_number_text(raw))):
        raise SceneError(
            f"'{_clip(raw)}' is absurdly small for a mechanism (less than "
            f"{TINY[kind]:g} {_SI_NAME[kind]}); check the value and its unit",
            key=where,
        )


def _number_text(raw) -> str:
    """The number a quantity's text begins with (``"1e-330 Pa"`` -> ``"1e-330"``), or ""."""
    m = _QUANTITY.match(raw) if isinstance(raw, str) else None
    return m.group(1) if m else ""


def _nonzero(number: str) -> bool:
    """Whether a number's text is other than zero, though it may read as 0.0: ``"1e-330"``
    underflows (a digit other than 0 before its exponent).

    >>> _nonzero("1e-330"), _nonzero("0.000e5"), _nonzero("-0")
    (True, False, False)
    """
    return any(c in "123456789" for c in number.lower().partition("e")[0])


def implausible(value: float, kind: str) -> str | None:
    """Words warning of a value beyond :data:`ABSURD` for its ``kind`` (an answer: a units
    slip, or a mechanism near a toggle that really moves so fast), or None.

    >>> implausible(2.5e9, "angular_acceleration")[:40]
    'more than 1e+09 rad/s^2: far beyond what'
    """
    if kind in ABSURD and not abs(value) <= ABSURD[kind]:
        return (
            f"more than {ABSURD[kind]:g} {_SI_NAME[kind]}: far beyond what a mechanism "
            "usually reaches; check the value and its unit (it is checked as given)"
        )
    return None


def _clip(raw, most=60) -> str:
    """``raw`` as a message quotes it: a long value cut short, so the line stays short."""
    text = str(raw)
    return text if len(text) <= most else f"{text[:40]}... ({len(text)} characters)"


def _magnitude(raw) -> str:
    """``raw`` without its minus sign and its sense: "-10 rad/s cw" -> "10 rad/s"."""
    words = str(raw).strip().split()
    if words and words[-1].lower() in _SENSES:
        words = words[:-1]
    return " ".join(words).lstrip("-").lstrip()


def _kind_of(raw) -> str:
    if isinstance(raw, bool):
        return "true/false"
    if isinstance(raw, dict):
        return "a table"
    if isinstance(raw, list):
        return "a list"
    return type(raw).__name__
