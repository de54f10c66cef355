"""A rate in a book's words, after or before its size: "2 rad/s^2 slowing down",
"decelerating at 3 m/s^2", "an angular retardation of 30 rad/s^2", "increasing at the rate of
50 rad/s^2", "40 rad/s^2 in the direction of rotation": the words say whether the rate acts
with the motion it is the rate of (speeding it up) or against it."""

from __future__ import annotations

import re

__all__ = ["RATED", "slowing"]

#: the words that put a rate against the motion
_SLOWING = (
    r"slowing(?: down)?|decelerat(?:ing|ion)|retard(?:ing|ation)|decreasing|"
    r"(?:opposite to|against) (?:the )?(?:rotation|motion)"
)
_RATE_WORD = (
    rf"({_SLOWING}|speeding up|accelerating|increasing|"
    r"in the (?:same )?(?:sense|direction)(?: of (?:the )?(?:rotation|motion))?)"
)
#: (the words after the size, the words before it): their groups are (size, words), (words,
#: size)
RATED = (
    re.compile(rf"^(.*?\S)\s*,?\s+{_RATE_WORD}$", re.IGNORECASE),
    re.compile(
        rf"^(?:an? )?(?:angular )?{_RATE_WORD}\s+(?:(?:at|of)\s+)?(?:the rate of\s+)?(.+)$",
        re.IGNORECASE,
    ),
)


def slowing(word: str) -> bool:
    """Whether the rate's words put it against the motion.

    >>> slowing("an angular retardation".split()[-1]), slowing("in the direction of rotation")
    (True, False)
    >>> slowing("opposite to the rotation"), slowing("Slowing down")
    (True, True)
    """
    return re.fullmatch(_SLOWING, word.strip(), re.IGNORECASE) is not None
