"""The peg's words and constructions (:mod:`.peg`): its slots named, the images of the
slotted bodies' points under the peg (``p1``, ``p2``), and the step's ``construction``
record on the velocity and the acceleration polygons (a line parallel to each slot through
its body's point under the peg, past the Coriolis component of a turning slot)."""

from __future__ import annotations

import math

from ..common.numbers import in_units
from ..scene import FixedPath
from .base import (
    Construction,
    DirectionLine,
    Vector,
    absolute,
    add,
    image_label,
    image_name,
    numbered,
    pole_text,
    sub,
    unit,
)
from .relations import rigid_acceleration, rigid_velocity

__all__ = ["slot_words", "under_labels", "slot_labels", "construction"]


def slot_words(s, unit=None, uname="mm") -> str:
    """``the slot of OA`` or ``the fixed slot (horizontal)``; an offset slot with its line
    where ``unit`` (m) is given (``the slot of OA (parallel to OA, 30 mm to the left of its
    line O -> A)``), else ``the offset slot of OA``."""
    if isinstance(s, FixedPath):
        return f"the fixed slot ({s.label})"
    e = getattr(s, "offset", 0.0)
    if not e:
        return f"the slot of {s.guide}"
    if unit is None:
        return f"the offset slot of {s.guide}"
    side = "left" if e > 0 else "right"
    return (
        f"the slot of {s.guide} (parallel to {s.guide}, {in_units(abs(e), unit)} {uname} to "
        f"the {side} of its line {s.first} -> {s.second})"
    )


def under_labels(sol, X: str, phase: str = "velocity") -> tuple:
    """The images of the two slotted bodies' points under the peg at X: ``p1`` and ``p2``
    (primed on the acceleration polygon), numbered past the scene's own points; the pole
    for a fixed slot."""
    sc = sol.scene
    taken = {image_name(sc, p) for p in sc.point_names} | {p.lower() for p in sc.point_names}
    prime = "'" if phase == "acceleration" else ""
    out = []
    for s in sol.scene.slots(X):
        if isinstance(s, FixedPath):
            out.append("o" + prime)
            continue
        lab = numbered(X.lower(), taken)
        taken.add(lab)
        out.append(lab + prime)
    return tuple(out)


def slot_labels(sol, X: str) -> dict:
    """slider key -> the velocity image letter of its slotted body's point under the peg."""
    return dict(zip((s.key for s in sol.scene.slots(X)), under_labels(sol, X)))


def construction(step, sol, ph):
    """The peg's construction record on the polygon of phase ``ph``: through the image of
    each slotted body's point under the peg a line parallel to its slot (past the Coriolis
    component of a turning slot on the acceleration polygon); the two lines meet at the
    peg's image."""
    X = step.point
    cond = sol.conditions.get(step.index, 1.0)
    lab = image_label(sol, X, ph)
    unders = under_labels(sol, X, ph)
    D = sol.V if ph == "velocity" else sol.A
    given, lines, found, named, parts = [], [], [], [], []
    for s, tl in zip(step.slots, unders):
        if isinstance(s, FixedPath):
            one = _fixed_slot(step, sol, ph, s, tl, lab)
        elif ph == "velocity":
            one = _turning_slot_velocity(step, sol, s, tl, lab)
        else:
            one = _turning_slot_acceleration(step, sol, s, tl, lab)
        g, line, f, nm, part = one
        given += g
        lines.append(line)
        found.append(f)
        named += nm
        parts.append(part)
    text = "; ".join(parts) + f"; the two lines meet at {lab}"
    found.append(absolute(sol, X, D, ph))
    return Construction(
        step.index,
        step.title,
        ph,
        lab,
        D[X],
        tuple(given),
        tuple(lines),
        tuple(found),
        text,
        cond,
        tuple(named),
    )


def _fixed_slot(step, sol, ph, s, tl, lab):
    """A fixed slot's part of the construction: (given vectors, its line, the sliding
    vector found, the named points, its words)."""
    X, words = step.point, slot_words(s)
    D = sol.V if ph == "velocity" else sol.A
    u, start = s.u, (0.0, 0.0)
    line = DirectionLine(start, u, tl, f"parallel to {words}", mark=f"\u2225 {words}")
    found = Vector(
        start,
        D[X],
        f"{tl}{lab}",
        "sliding",
        f"{'vs' if ph == 'velocity' else 'as'}_{s.key}",
        f"sliding {ph} of {X} in {words}",
    )
    return (), line, found, (), f"through {tl} (a fixed slot) one parallel to {words}"


def _under(step, sol, s):
    """The velocity and the acceleration of the point of slot ``s``'s turning link under
    the peg: the rigid body's relations from its first point."""
    g1 = s.first
    r = sub(sol.P[step.point], sol.P[g1])
    w, al = sol.W[s.guide], sol.Al.get(s.guide, 0.0)
    return (
        add(sol.V[g1], rigid_velocity(*r, w)),
        add(sol.A.get(g1, (0.0, 0.0)), rigid_acceleration(*r, w, al)),
    )


def _turning_slot_velocity(step, sol, s, tl, lab):
    """A slot in a turning link, on the velocity polygon: (given vectors, its line, the
    sliding vector found, the named points, its words)."""
    X, g1, ph = step.point, s.first, "velocity"
    u = unit(*sub(sol.P[s.second], sol.P[g1]))
    vc, _ = _under(step, sol, s)
    given = Vector(
        sol.V[g1],
        vc,
        f"{image_label(sol, g1, ph)}{tl}",
        "relative",
        f"v of the point of {s.guide} under {X}",
        f"omega_{s.guide} x {g1}{X}, perpendicular to {g1}{X}",
    )
    line = DirectionLine(vc, u, tl, f"parallel to {s.guide}", mark=f"\u2225 {s.guide}")
    part = (
        f"from {pole_text(sol, g1, ph)} draw {image_label(sol, g1, ph)}{tl} = omega_"
        f"{s.guide} x {g1}{X} perpendicular to {g1}{X} ({tl}: the point "
        f"of {s.guide} under the peg) and through {tl} a line parallel "
        f"to {s.guide}"
    )
    found = Vector(
        vc,
        sol.V[X],
        f"{tl}{lab}",
        "sliding",
        f"vs_{s.key}",
        f"sliding velocity of {X} in {slot_words(s)}",
    )
    return (given,), line, found, ((tl, vc),), part


def _turning_slot_acceleration(step, sol, s, tl, lab):
    """A slot in a turning link, on the acceleration polygon (its point under the peg,
    the Coriolis component laid off from it): (given vectors, its line, the sliding
    vector found, the named points, its words)."""
    X, g1, ph = step.point, s.first, "acceleration"
    u = unit(*sub(sol.P[s.second], sol.P[g1]))
    _, ac = _under(step, sol, s)
    cor = sol.coriolis(s.key)
    end = add(ac, cor)
    given = (
        Vector(
            sol.A[g1],
            ac,
            f"{image_label(sol, g1, ph)}{tl}",
            "relative",
            f"a of the point of {s.guide} under {X}",
            f"omega_{s.guide}^2 x {g1}{X} towards {g1} and alpha_{s.guide} x {g1}{X}",
        ),
        Vector(
            ac,
            end,
            f"cor {s.key}",
            "coriolis",
            f"Coriolis at {X} in {s.guide}",
            f"2 omega_{s.guide} vs_{s.key} = "
            f"{math.hypot(*cor):.4g} m/s^2, perpendicular to {s.guide}",
        ),
    )
    line = DirectionLine(
        end,
        u,
        f"the end of the Coriolis component in {s.guide}",
        f"parallel to {s.guide}",
        mark=f"\u2225 {s.guide}",
    )
    part = (
        f"from {pole_text(sol, g1, ph)} draw {tl}, the acceleration of the point of "
        f"{s.guide} under the peg, lay off from {tl} the Coriolis component 2 omega_"
        f"{s.guide} vs_{s.key} = {math.hypot(*cor):.4g} m/s^2 perpendicular "
        f"to {s.guide}, and through its end a line parallel to {s.guide}"
    )
    found = Vector(
        end,
        sol.A[X],
        "s",
        "sliding",
        f"as_{s.key}",
        f"sliding acceleration of {X} in {slot_words(s)}",
    )
    return given, line, found, ((tl, ac),), part
