"""What every table's reader shares (a part of the scene reader): a direction's unit vector,
exact on the axes, and the words of a message about an unknown key or point (a did-you-mean,
or the scene's points)."""

from __future__ import annotations

import math

from ..common.units import did_you_mean


def _unit_at(ang: float) -> tuple:
    """(cos, sin) of a direction (rad), exact where it is a whole number of right angles
    to the rounding of the angle (a force "direction = 270" is straight down, not 1.8e-16
    to the side; a path at "180 deg" is horizontal; "90.0000000001 deg" is not vertical:
    near a dead centre that hair matters)."""
    q = ang / (math.pi / 2)
    k = round(q)
    if abs(q - k) <= 4 * 2.0**-53 * max(1.0, abs(q)):
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[k % 4]
    return (math.cos(ang), math.sin(ang))


#: a key a book's words lead to (in [sliders], which says it with through), and how to say it
_OFFSET = ": an offset line of stroke is its through = [x, y] (40 mm below O: [0, -40])"


def _suggest(word, choices) -> str:
    hint = _OFFSET if word == "offset" and "through" in choices else None
    return hint or did_you_mean(word, list(choices))


def _which_point(name, known) -> str:
    """A did-you-mean, or else the scene's points, for a message about an unknown point."""
    names = sorted(known, key=lambda p: (p[0], len(p), p))
    hint = _suggest(name, names)
    if hint or not names:
        return hint
    listed = ", ".join(names[:12]) + (", ..." if len(names) > 12 else "")
    return f" (its points are {listed})"
