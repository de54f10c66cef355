"""How numbers are written: one place for every view (report, step table, check, drawings,
sweep summaries, linkage properties).

>>> fmt(18.849555921538759), fmt(0.0660), fmt(216.6367), fmt(0)
('18.85', '0.066', '216.6', '0')
>>> fmt_angular(-10.5, "rad/s")
'10.5 rad/s cw'
"""

from __future__ import annotations

import math

from .errors import TOL

__all__ = [
    "article",
    "fmt",
    "fixed",
    "textbook",
    "working",
    "sense",
    "sense_word",
    "fmt_angular",
    "in_units",
    "quiet",
    "condition_text",
]


def article(words: str) -> str:
    """``words`` after "a" or "an" as it is read aloud: a number is "an" where it is read
    from an eight, an eleven or an eighteen ("an 80 mm bore", "an 11 mm pin", "an 18 kN
    load", "a 110 mm bore", "a 1.8 m rod").

    >>> article("80 mm"), article("110 mm"), article("11.5 mm"), article("18000 N"), article("1.8 m")
    ('an 80 mm', 'a 110 mm', 'an 11.5 mm', 'an 18000 N', 'a 1.8 m')
    """
    head = words.split(" ", 1)[0].split(".", 1)[0].lstrip("+-")
    if head.startswith("8"):
        return f"an {words}"
    if head[:2] in ("11", "18") and len(head) in (2, 5, 8):  # eleven, eleven thousand, million
        return f"an {words}"
    return f"a {words}"


def quiet(x, scale):
    """``x``, or 0 where it is at most ``TOL.negligible`` of ``scale``: rounding noise about
    a true zero (a coordinate on an axis, a link that does not turn) is written 0, not
    1.6e-15 with a sense. Floats, or numpy arrays entry by entry.

    >>> quiet(1.6e-15, 10.0), quiet(-0.25, 10.0)
    (0.0, -0.25)
    """
    lim = TOL.negligible * scale
    if isinstance(x, (int, float)) and isinstance(lim, (int, float)):
        return 0.0 if abs(x) <= lim else x
    import numpy as np

    return np.where(np.abs(x) <= lim, 0.0, x)


def condition_text(c: float) -> str:
    """A condition (a sine, a ratio: at most 1) as a refusal writes it: two figures, and a
    rounding-noise size about a true zero written 0 (a peg's two slots exactly parallel,
    a piston exactly at its dead centre), not 1.2e-16.

    >>> condition_text(1.2e-16), condition_text(0.0042), condition_text(0.5)
    ('0', '0.0042', '0.5')
    """
    return "0" if abs(c) <= TOL.negligible else f"{c:.2g}"


def fmt(x: float, digits: int = 4) -> str:
    """A value to ``digits`` significant figures, without an exponent for usual sizes."""
    if x == 0 or not math.isfinite(x):
        return "0" if x == 0 else str(x)
    s = f"{x:.{digits}g}"
    if "e" in s:
        mag = math.floor(math.log10(abs(x)))
        if -6 <= mag < 0:
            s = f"{x:.{digits - 1 - mag}f}".rstrip("0").rstrip(".")
        elif mag >= digits:
            s = f"{x:.0f}"
    return s


def fixed(x: float, digits: int = 3) -> str:
    """Three significant figures, trailing zeros kept (a value read off a drawing).

    >>> fixed(0.4), fixed(12.5)
    ('0.400', '12.5')
    """
    if x == 0:
        return "0"
    if abs(x) >= 10**digits:
        return f"{x:.0f}"
    s = f"{x:#.{digits}g}"
    return s.rstrip(".") if "e" not in s else fmt(x, digits)


def textbook(x: float) -> str:
    """A value as a textbook writes it: four significant figures, a large one in whole
    units as a book writes a force of 51 601 N (no exponent below 1e7), an exponent only
    for a tiny or an absurd size.

    >>> textbook(0.39183), textbook(0), textbook(1.5e-7), textbook(51601.2), textbook(-16559.4)
    ('0.3918', '0', '1.5000e-07', '51601', '-16559')
    """
    if x == 0:
        return "0"
    s = f"{x:.4g}"
    if "e" in s:
        s = f"{x:.0f}" if 1e4 <= abs(x) < 1e7 else f"{x:.4e}"
    return s


def added(x: float) -> str:
    """A term added in a worked sum as a book writes it, its sign the operator.

    >>> added(9.273), added(-222.5)
    ('+ 9.273', '- 222.5')
    """
    return f"- {fmt(-x)}" if x < 0 else f"+ {fmt(x)}"


def working(x: float) -> str:
    """A number as written in working: up to five significant figures."""
    return f"{x:.5g}"


def sense(value: float) -> str:
    """``ccw`` for a positive angular quantity, ``cw`` for a negative one, '' for zero."""
    return "ccw" if value > 0 else ("cw" if value < 0 else "")


#: the same word, under the name the step tables use
sense_word = sense


def fmt_angular(value: float, unit: str, digits: int = 4) -> str:
    """``5.15 rad/s ccw``: magnitude (written as :func:`fmt` writes it, as the step table
    does: no exponent for usual sizes), unit and sense.

    >>> fmt_angular(11842.41, "rad/s^2"), fmt_angular(2.5e-5, "rad/s")
    ('11842 rad/s^2 ccw', '0.000025 rad/s ccw')
    """
    s = sense(value)
    return f"{fmt(abs(value), digits)} {unit}" + (f" {s}" if s else "")


def in_units(x: float, unit_len: float) -> str:
    """A length in metres written in the scene's unit (``unit_len`` metres), 6 digits."""
    return f"{x / unit_len:.6g}"
