"""The records a step gives to step tables and drawings (a polygon's vectors, its direction
lines, one step's construction) and the small helpers that build them: image letters, the
pole, vector arithmetic on pairs. ``perp(x, y) = (-y, x)`` turns a vector 90 deg
counter-clockwise, so that ``omega x r = omega perp(r)`` in the plane.

>>> perp(unit(3.0, 4.0))
(-0.8, 0.6)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

__all__ = [
    "Vector",
    "DirectionLine",
    "Construction",
    "image_name",
    "image_label",
    "numbered",
    "pole_text",
    "unit",
    "sub",
    "add",
    "perp",
    "relative",
    "absolute",
    "centripetal",
    "tangential",
]


@dataclass(frozen=True)
class Vector:
    """A segment of a polygon, from ``start`` to ``end`` (polygon coordinates, SI).

    ``kind``: ``absolute`` (from the pole), ``relative`` (between two images),
    ``centripetal``, ``tangential``, ``coriolis``, ``sliding``.
    """

    start: tuple
    end: tuple
    label: str  # e.g. "bc"
    kind: str
    name: str  # e.g. "v_CB" or "centripetal of CB"
    text: str  # how it is found: "omega_BC^2 x BC, parallel to BC, towards B"
    #: the points of the polygon's quantity the vector is: (C, B) of v_CB, (C,) of v_C;
    #: () for a component (centripetal, tangential, Coriolis, sliding)
    points: tuple = ()

    @property
    def magnitude(self) -> float:
        """The vector's length on the polygon (m/s or m/s^2)."""
        return math.hypot(self.end[0] - self.start[0], self.end[1] - self.start[1])


@dataclass(frozen=True)
class DirectionLine:
    """An infinite line of known direction through a known polygon point."""

    point: tuple
    direction: tuple  # unit vector
    through: str  # label of the point it is drawn through, e.g. "b"
    relation: str  # in words: "perpendicular to BC", "parallel to the path", ...
    mark: str = ""  # what the drawing writes beside the line: "\u22a5 BC", "\u2225 path"


@dataclass(frozen=True)
class Construction:
    """One plan step on one polygon."""

    step: int
    title: str
    phase: str  # "velocity" or "acceleration"
    finds: str  # the image label found, e.g. "c"
    point: tuple  # where it is
    given: tuple  # Vectors known before the step (drawn first)
    lines: tuple  # the two DirectionLines, or () for a direct step
    found: tuple  # Vectors the step determines
    text: str
    condition: float
    named: tuple = ()  # (label, point) of intermediate points the text names (a1')


def image_name(scene, point: str) -> str:
    """The image letter of ``point``: ``b`` for B. A moving point named O would take the
    pole's letter: it is ``o1`` instead (``o2`` and so on where the scene has an O1)."""
    own = point.lower()
    if own != "o" or point in scene.ground:
        return own
    return numbered("o", {p.lower() for p in scene.point_names})


def numbered(stem: str, taken) -> str:
    """``stem1``, or ``stem2`` and so on: the first not in ``taken`` (a letter of its own
    beside the scene's points: o1 for a moving O, a1 for the point under a block)."""
    k = 1
    while f"{stem}{k}" in taken:
        k += 1
    return f"{stem}{k}"


def image_label(sol, point: str, phase: str = "velocity") -> str:
    """``b`` for B on the velocity polygon, ``b'`` on the acceleration polygon; fixed
    points are the pole ``o``/``o'``."""
    prime = "'" if phase == "acceleration" else ""
    if point in sol.scene.ground:
        return "o" + prime
    return image_name(sol.scene, point) + prime


def pole_text(sol, point, phase):
    """Label for text: ``d (at o)`` for a fixed point that is not named O."""
    lab = image_label(sol, point, phase)
    own = point.lower() + ("'" if phase == "acceleration" else "")
    if lab != own:
        return f"{own} (at {lab})"
    return lab


def unit(x, y):
    """The unit vector along (x, y); (0, 0) for the zero vector."""
    n = math.hypot(x, y)
    return (x / n, y / n) if n else (0.0, 0.0)


def sub(a, b):
    """The difference a - b of two points or vectors."""
    return (a[0] - b[0], a[1] - b[1])


def add(a, b):
    """The sum a + b of two vectors."""
    return (a[0] + b[0], a[1] + b[1])


def perp(v):
    """``v`` turned 90 deg counter-clockwise."""
    return (-v[1], v[0])


def relative(sol, X, Y, D, phase, kind="relative"):
    """Vector from the image of Y to the image of X (v_XY)."""
    lx, ly = image_label(sol, X, phase), image_label(sol, Y, phase)
    sym = "v" if phase == "velocity" else "a"
    return Vector(D[Y], D[X], f"{ly}{lx}", kind, f"{sym}_{X}{Y}", "", (X, Y))


def absolute(sol, X, D, phase):
    """Vector from the pole to the image of X (v_X or a_X)."""
    o = "o" if phase == "velocity" else "o'"
    sym = "v" if phase == "velocity" else "a"
    return Vector(
        (0.0, 0.0), D[X], f"{o}{image_label(sol, X, phase)}", "absolute", f"{sym}_{X}", "", (X,)
    )


def centripetal(sol, X, B, link, ph):
    """Centripetal component of a_XB: w^2 |XB| along XB, towards B, drawn from b'."""
    w = sol.W[link]
    r = sub(sol.P[X], sol.P[B])
    start = sol.A[B]
    end = add(start, (-w * w * r[0], -w * w * r[1]))
    L = math.hypot(*r)
    return Vector(
        start,
        end,
        f"{image_label(sol, B, ph)}{X.lower()}c",
        "centripetal",
        f"centripetal of {X}{B}",
        f"v_{X}{B}^2 / {X}{B} = {w * w * L:.4g} m/s^2, parallel to {X}{B}, towards {B}",
    )


def tangential(sol, X, B, link, start):
    """Tangential component of a_XB: alpha x BX, perpendicular to BX, drawn from ``start``
    (the end of its centripetal component) to x'."""
    return Vector(
        start,
        sol.A[X],
        f"t{X}{B}",
        "tangential",
        f"tangential of {X}{B}",
        f"alpha_{link} x {B}{X}",
    )
