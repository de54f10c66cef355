"""Slips of the pen: one digit differs, two are swapped, leading digits dropped, or the
student's own value for the same quantity copied with its leading digits lost."""

from __future__ import annotations

import re

from ..common.tolerances import SAME
from ..scene.answers import decimal_comma
from .alternatives import _Candidate


def _pointed(raw) -> str:
    """An answer as written, its decimal comma read as a point ("0,39 m/s": "0.39 m/s")."""
    return str(decimal_comma(str(raw)) or raw)


#: where a slip of the pen ranks among the mistakes (by their relative deviation): after
#: one the answer equals to its rounding, before one it only comes near
_SLIP_RANK = 0.005 * (1 + SAME)

_NUM = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def _digits(number: str):
    """(significant digits, exponent of the last digit) of a written number."""
    s = number.lstrip("+-")
    if "e" in s.lower():
        return None
    if "." in s:
        whole, frac = s.split(".")
    else:
        whole, frac = s, ""
    digits = (whole + frac).lstrip("0")
    return digits, -len(frac)


def _slip(raw: str, given: float, correct: float, signed: bool):
    """A slip of the pen: one digit differs, two are swapped, or leading digits dropped."""
    m = _NUM.search(_pointed(raw))
    if not m or float(m.group()) == 0 or correct == 0:
        return None
    written = m.group()
    factor = given / float(written)  # SI per written unit, with the sign of a sense
    target = correct / factor
    if not signed:
        target = abs(target)
    d = _digits(written)
    if d is None:
        return None
    digits, last = d
    if len(digits) < 2 or target <= 0:
        return None
    q = round(target / 10.0**last)
    right = str(q)
    if len(right) == len(digits):
        diff = [i for i in range(len(digits)) if digits[i] != right[i]]
        if len(diff) == 1 and diff[0] < len(digits) - 1:  # a last digit off is no slip
            return _Candidate(
                given,
                "transcription_slip",
                f"a slip of the pen: one digit differs ({written} written for {_written(q, last)})",
            )
        if (
            len(diff) == 2
            and diff[1] == diff[0] + 1
            and digits[diff[0]] == right[diff[1]]
            and digits[diff[1]] == right[diff[0]]
        ):
            return _Candidate(
                given,
                "transcription_slip",
                f"a slip of the pen: two digits swapped ({written} written for "
                f"{_written(q, last)})",
            )
    if len(right) > len(digits) and right.endswith(digits) and len(digits) >= 2:
        return _Candidate(
            given,
            "transcription_slip",
            f"a slip of the pen: leading digits dropped ({written} written for "
            f"{_written(q, last)})",
        )
    return None


def _written(q: int, last: int) -> str:
    if last >= 0:
        return str(q * 10**last)
    s = str(q).rjust(-last + 1, "0")
    return f"{s[:last]}.{s[last:]}"


def own_slip(d, ans):
    """A copying slip: the answer is the student's own value for the same quantity
    (v_BD and v_DB have one magnitude) with its leading digits lost: 36 for 2.36."""
    m = _NUM.search(_pointed(ans.raw))
    mine = _digits(m.group()) if m else None
    if mine is None or len(mine[0]) < 2:
        return None
    for other in d.given.values():
        if other.key == ans.key or other.kind != ans.kind or set(other.names) != set(ans.names):
            continue
        mo = _NUM.search(_pointed(other.raw))
        theirs = _digits(mo.group()) if mo else None
        if theirs and len(theirs[0]) > len(mine[0]) and theirs[0].endswith(mine[0]):
            return _Candidate(
                ans.value,
                "transcription_slip",
                f"a slip of the pen: {m.group()} is your own {other.key} = "
                f"{mo.group()} with its leading digits lost",
            )
    return None
