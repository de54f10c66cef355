"""An angle turned by whole turns into a half-turn's range, and written in degrees for the
notes (a part of the scene reader: a book's angle, a dead centre)."""

from __future__ import annotations

import math


def _half_turn(a, half):
    """``a`` turned by whole turns into (-half, half] (``half`` = 180 or pi).

    >>> _half_turn(330.0, 180.0), _half_turn(-180.0, 180.0), _half_turn(0.0, 180.0)
    (-30.0, 180.0, 0.0)
    """
    if -half < a <= half:
        return a + 0.0  # as it is, to the last bit (and never -0.0)
    d = (a + half) % (2 * half) - half
    return half if d == -half else d


def _deg(theta) -> str:
    """An angle (rad) in degrees for the notes, in (-180, 180]."""
    return f"{_half_turn(round(math.degrees(theta), 9), 180.0):g}"
