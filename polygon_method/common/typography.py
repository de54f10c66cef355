"""The typography a word processor or a PDF puts in a number, read as the plain
characters it means (a minus sign, a power of ten, a vulgar fraction, a non-breaking space,
a decimal comma), or refused in one line naming the character."""

from __future__ import annotations

import re
import unicodedata

from .errors import SceneError

__all__ = ["typographic", "decimal_comma", "long_integer_text"]


def _clip(raw, most=60) -> str:
    """``raw`` as a message quotes it: a long value cut short."""
    text = str(raw)
    return text if len(text) <= most else f"{text[:40]}... ({len(text)} characters)"


#: the signs a word processor or a PDF puts for a minus: the minus sign, the en dash, the
#: figure dash, the hyphens, the small and the full-width hyphen-minus
_MINUSES = "\u2212\u2013\u2012\u2010\u2011\ufe63\uff0d"
#: a degree written with a look-alike: the masculine ordinal, the ring above
_DEGREES = "\u00ba\u02da"
_SUPERSCRIPTS = str.maketrans(
    "\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079\u207b\u207a", "0123456789-+"
)
#: "1.2 × 10^3", "1.2x10**-3", "1.2·10³": a power of ten after a number
_TIMES_TEN = re.compile(
    r"(?<=[\d.])\s*[\u00d7x*\u00b7\u22c5]\s*10\s*"
    r"(?:(?:\^|\*\*)\s*([-+]?\d+)|([\u207b\u207a]?[\u2070\u00b9\u00b2\u00b3\u2074-\u2079]+))"
)
#: a whole number and a vulgar fraction: "2½", "2 ½", "½"
_FRACTION = re.compile(r"(\d*)[ \u00a0\u2009\u202f]?([\u00bc-\u00be\u2150-\u215e])")
#: the spaces a word processor puts between a number and its unit
_SPACES = re.compile(r"[\u00a0\u2000-\u200b\u202f\u205f\u3000]")


def typographic(raw: str, where: str = "", marks: str = "\u00b0\u00b2") -> str:
    """A quantity's text with the typography a word processor or a PDF puts in numbers read
    as the plain characters it means: a minus sign or a dash before a number (U+2212, the
    en dash), a power of ten (``"1.2×10^3"``, ``"1.2·10⁻³"``), a vulgar fraction (``"2½"``),
    non-breaking and thin spaces, a degree's look-alikes, a middle dot between digits (the
    British decimal point); a character still left that no number or unit has is one line
    naming it.

    >>> typographic("\u221210.5 rad/s"), typographic("1.2\u00d710^3 mm"), typographic("2\u00bd in")
    ('-10.5 rad/s', '1.2e3 mm', '2.5 in')
    >>> typographic("1.2\u00b710\u207b\u00b3 m"), typographic("0\u00b75 m"), typographic("30\u00ba")
    ('1.2e-3 m', '0.5 m', '30\u00b0')
    """
    text = _SPACES.sub(" ", raw)
    text = re.sub(f"[{_MINUSES}]\\s*(?=[\\d.\u00bc-\u00be\u2150-\u215e])", "-", text)
    text = _TIMES_TEN.sub(lambda m: "e" + (m.group(1) or m.group(2).translate(_SUPERSCRIPTS)), text)
    text = re.sub(r"(?<=\d)[\u00b7\u22c5](?=\d)", ".", text)
    text = _FRACTION.sub(lambda m: _fraction(m.group(1), m.group(2)), text)
    text = re.sub(f"(?<=[\\d ])[{_DEGREES}]", "\u00b0", text)
    for ch in text:
        if not ch.isascii() and not (ch.isdigit() or ch.isalpha() or ch in marks):
            name = unicodedata.name(ch, "a character")
            raise SceneError(
                f"'{_clip(raw)}': the character '{ch}' (U+{ord(ch):04X} {name}) is no part "
                "of a number or a unit here; write the quantity in plain characters, "
                'e.g. "-10.5 rad/s cw", "1.2e3 mm"',
                key=where,
            )
    return text


def _fraction(whole: str, vulgar: str) -> str:
    """A whole number and a vulgar fraction as a decimal: ("2", "½") -> "2.5"."""
    return repr(int(whole or 0) + unicodedata.numeric(vulgar))


_COMMA_NUMBER = re.compile(r"^(\s*[-+]?)(\d*),(\d+)(?![\d.,])(.*)$", re.S)


def decimal_comma(value):
    """``value`` with its decimal comma read as a point (``"0,39 m/s"`` -> ``"0.39 m/s"``),
    or ``value`` as it is; None where the comma reads two ways (``"1,250 m/s"``: 1.25 or
    1250?).

    >>> decimal_comma("0,39 m/s"), decimal_comma("12,5 rad/s cw"), decimal_comma("1,250")
    ('0.39 m/s', '12.5 rad/s cw', None)
    """
    if not isinstance(value, str):
        return value
    if not value.isascii():  # "−0,39 m/s": its typography first
        try:
            value = typographic(value)
        except SceneError:  # (worded where it is read)
            return value
    m = _COMMA_NUMBER.match(value)
    if not m:
        return value
    sign, whole, frac, rest = m.groups()
    if whole.lstrip("0") and len(frac) == 3:  # a thousands separator, or a decimal comma?
        return None
    return f"{sign}{whole or '0'}.{frac}{rest}"


def long_integer_text(value: int) -> str:
    """An integer too long to quote as a message quotes it: its sign, first digits and how
    many it has, also past what ``str`` converts (4300 digits).

    >>> long_integer_text(-(10**30)), long_integer_text(10**5000)
    ('-100000...(31 digits)', '(5001 digits)')
    """
    sign = "-" if value < 0 else ""
    try:
        digits = str(abs(value))
    except ValueError:  # past str's limit: count them from its bits
        count = int(abs(value).bit_length() * 0.30102999566398120) + 1
        if 10 ** (count - 1) > abs(value):
            count -= 1
        return f"{sign}({count} digits)"
    return f"{sign}{digits[:6]}...({len(digits)} digits)"


def character_words(ch: str) -> str:
    """A character outside ASCII named as a refusal names it, with the plain one it may
    have been written for.

    >>> character_words("\u0397"), character_words("\uff11")
    ("'\u0397' (U+0397 GREEK CAPITAL LETTER ETA)", "'\uff11' (U+FF11 FULLWIDTH DIGIT ONE), written for '1'?")
    """
    plain = unicodedata.normalize("NFKC", ch)
    like = f", written for '{plain}'?" if plain != ch and plain.isascii() else ""
    return f"'{ch}' (U+{ord(ch):04X} {unicodedata.name(ch, 'a character')}){like}"


def odd_in_name(name) -> str:
    """'' for a name in ASCII; else words naming its first character outside it (a Greek
    capital Eta looks like H), for a refusal of the name."""
    ch = next((c for c in str(name) if not c.isascii()), None)
    return "" if ch is None else f"; its character {character_words(ch)} is not ASCII"
