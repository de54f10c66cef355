"""A force step's polygons in words, for the ``steps`` document: each side at the force
scale, in the order drawn, the pin forces read across it."""

from __future__ import annotations

import math

from ..common.tolerances import FLOOR, SAME
from ..forces import FRAME, side_label

__all__ = ["body_name", "polygon_items"]


def body_name(name):
    """A body as the words name it: the frame by that name."""
    return "the frame" if name == FRAME else name


def polygon_items(st, f, scale, F) -> list:
    """A step's force polygons in words: each side at ``scale`` (cm), in the order drawn
    (where the step draws several, each named by its body)."""
    polys = st.polygons
    items = []
    for pg in polys:
        items += _one_polygon(pg, f, scale, F, len(polys) > 1)
    return items


def _one_polygon(pg, f, scale, F, named) -> list:
    tiny = SAME * max(F, FLOOR)  # as the sheet leaves a side out (draw.forces.NEGLIGIBLE)
    sides = [
        f"{side_label(sd, f.numbers, unicode=False)} {scale.cm(math.hypot(*sd.vector)):.2f}"
        " cm" + (" (found)" if any(k == u for u, _ in pg.unknown) else "")
        for k, sd in enumerate(pg.polygon)
        if math.hypot(*sd.vector) > tiny
    ]
    whose = f" of {' and '.join(body_name(b) for b in pg.bodies)}" if named else ""
    items = [
        f"force polygon{whose} at {scale.text}, from its pole, head to tail: "
        + ", ".join(sides)
        + "; it closes on the pole"
    ]
    across = [
        f"{side_label(c, f.numbers, unicode=False)} {scale.cm(math.hypot(*c.vector)):.2f} cm"
        for c, _, _ in pg.chords
        if math.hypot(*c.vector) > tiny
    ]
    if across:
        items.append("read across it (whole pin forces): " + ", ".join(across))
    return items
