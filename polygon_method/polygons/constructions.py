"""What each plan step draws on the velocity and acceleration polygons.

Each step draws its own construction (``construction(sol, phase)`` in its module of
:mod:`polygon_method.steps`, from the same formulas the solver runs); this module collects
them per polygon for the step tables and the drawings. In the polygon plane a point's image is its
velocity (or acceleration) vector from the pole ``o`` (``o'``); the image of point B is
``b`` (``b'``), every fixed point is at the pole.

>>> from polygon_method import parse_scene, solve
>>> sol = solve(parse_scene('''
... [ground]
... A = [0, 0]
... D = [100, 0]
... [links]
... AB = 50
... BC = 66
... CD = 56
... [input]
... crank = "AB"
... angle = 60
... speed = "10.5 rad/s cw"
... '''))
>>> c = velocity_constructions(sol)[1]
>>> c.text
'through b draw a line perpendicular to BC; through d (at o), one perpendicular to DC; they meet at c'
"""

from __future__ import annotations

from ..common.tolerances import SAME
import math

from ..steps import Construction, DirectionLine, Vector, image_label

__all__ = [
    "Vector",
    "DirectionLine",
    "Construction",
    "velocity_constructions",
    "acceleration_constructions",
    "image_label",
    "drawn_vectors",
    "PRIORITY",
]

#: which of two coinciding vectors is drawn (the first in this order)
PRIORITY = ("absolute", "coriolis", "centripetal", "tangential", "sliding", "relative")


def velocity_constructions(sol) -> tuple:
    """The velocity polygon, step by step (one :class:`Construction` per plan step)."""
    return sol._get(
        "vcons", lambda: tuple(st.construction(sol, "velocity") for st in sol.plan.steps)
    )


def acceleration_constructions(sol) -> tuple:
    """The acceleration polygon, step by step."""
    return sol._get(
        "acons", lambda: tuple(st.construction(sol, "acceleration") for st in sol.plan.steps)
    )


def drawn_vectors(sol, phase: str) -> tuple:
    """The vectors a polygon shows, in drawing order: every given and found vector of the
    construction records, zero ones left out, and of two that coincide only one (a total
    before a component, a component before a relative vector). The n-th is drawn with
    gid ``{phase}-vector-{n}-shaft`` / ``-head``. A carried point's relative vector is
    left out: its image triangle (or the line it lies on) shows it."""
    cons = velocity_constructions(sol) if phase == "velocity" else acceleration_constructions(sol)
    steps = sol.plan.steps
    vecs = [
        v
        for c in cons
        for v in c.given + c.found
        if not (v.kind == "relative" and not steps[c.step].draws_relative)
    ]
    ref = max((v.magnitude for v in vecs), default=0.0)
    tol = SAME * ref
    keep = {}
    for v in vecs:
        if v.magnitude <= tol:
            continue
        key = None
        for k, w in keep.items():
            if math.dist(v.start, w.start) <= tol and math.dist(v.end, w.end) <= tol:
                key = k
                break
        if key is None:
            keep[len(keep)] = v
        elif PRIORITY.index(v.kind) < PRIORITY.index(keep[key].kind):
            keep[key] = v
    return tuple(keep.values())
