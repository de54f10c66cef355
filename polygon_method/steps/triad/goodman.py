"""Goodman's auxiliary-point construction of a class-III group (a triad) on the velocity
and the acceleration polygons: S, where two of the binary links (produced) meet, is a point
of the plate that moves perpendicular to both; its image is found first, then the third
vertex's, then the other two. The step's ``construction`` record, with its direction lines,
vectors and the book's words (:class:`..base.Construction`)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..base import (
    Construction,
    DirectionLine,
    Vector,
    absolute,
    add,
    image_label,
    perp,
    pole_text,
    relative,
    sub,
    unit,
)
from ..relations import rigid_acceleration, rigid_velocity

__all__ = ["construction"]


def construction(step, sol, ph):
    """The step's construction record on the polygon of phase ``ph``."""
    return (_velocity if ph == "velocity" else _acceleration)(step, sol, ph)


@dataclass(frozen=True)
class _Goodman:
    """What both polygons' constructions share: the points (``V``: the vertices in the
    order i, j, m of the auxiliary point; ``K``: the known points they hang from), the
    auxiliary point S and its image, the labels and the words of S."""

    step: object
    sol: object
    ph: str
    i: int
    j: int
    m: int
    S: tuple
    V: tuple
    K: tuple
    D: dict
    w: float
    s_lab: str
    img_s: tuple
    aux: str

    @property
    def cond(self):
        """The step's condition (1 where the solution has none)."""
        return self.sol.conditions.get(self.step.index, 1.0)

    def lab(self, p):
        """The image label of point ``p`` on this polygon."""
        return image_label(self.sol, p, self.ph)

    def perp_to(self, a, b):
        """The unit direction perpendicular to ``ab`` on the configuration (each a point's
        name or a place: S)."""
        P = self.sol.P
        return unit(
            *perp(sub(P[b] if isinstance(b, str) else b, P[a] if isinstance(a, str) else a))
        )

    def record(self, given, lines, found, text):
        """The step's :class:`Construction` on this polygon."""
        return Construction(
            self.step.index,
            self.step.title,
            self.ph,
            ", ".join(self.lab(p) for p in self.step.points),
            self.D[self.V[2]],
            given,
            lines,
            found,
            text,
            self.cond,
            ((self.s_lab, self.img_s),),
        )


def _common(step, sol, ph) -> _Goodman:
    """The points, the auxiliary point S and its image (S a point of the plate: the rigid
    body's relations from the triad's first point), the labels and the words of S."""
    P = sol.P
    i, j, m, S = step._aux(P)
    pts, kn = step.points, step.knowns
    w = sol.W[step.plate]
    prime = "'" if ph == "acceleration" else ""
    s_lab = step._aux_label(sol) + prime
    D = sol.V if ph == "velocity" else sol.A
    x1, y1 = P[pts[0]]
    if ph == "velocity":
        img_s = add(D[pts[0]], rigid_velocity(S[0] - x1, S[1] - y1, w))
    else:
        img_s = add(D[pts[0]], rigid_acceleration(S[0] - x1, S[1] - y1, w, sol.Al[step.plate]))
    aux = (
        f"S, where {kn[i]}{pts[i]} and {kn[j]}{pts[j]} (produced) meet, a point of the "
        f"{step._plate_words}"
    )
    V, K = (pts[i], pts[j], pts[m]), (kn[i], kn[j], kn[m])
    return _Goodman(step, sol, ph, i, j, m, S, V, K, D, w, s_lab, img_s, aux)


def _velocity(step, sol, ph):
    """Goodman's construction on the velocity polygon."""
    g = _common(step, sol, ph)
    (Vi, Vj, Vm), (Ki, Kj, Km), D, lab, s_lab = g.V, g.K, g.D, g.lab, g.s_lab
    pts, kn = step.points, step.knowns

    def square(through, a, b):  # through a point's image (S's where ``through`` is None)
        start, label = (g.img_s, s_lab) if through is None else (D[through], lab(through))
        d = g.perp_to(g.S if a == "S" and through is None else a, b)
        return DirectionLine(start, d, label, f"perpendicular to {a}{b}", mark=f"\u22a5 {a}{b}")

    lines = (
        square(Ki, Ki, Vi),
        square(Kj, Kj, Vj),
        square(None, "S", Vm),
        square(Km, Km, Vm),
        square(Vm, Vm, Vi),
        square(Vm, Vm, Vj),
    )
    text = (
        f"auxiliary point (Goodman): {g.aux}, moves perpendicular to both lines; "
        f"through {pole_text(sol, Ki, ph)} draw a line perpendicular to {Ki}{Vi}, "
        f"through {pole_text(sol, Kj, ph)} one perpendicular to {Kj}{Vj}: they "
        f"meet at {s_lab}; through {s_lab} draw a line perpendicular to S{Vm}, "
        f"through {pole_text(sol, Km, ph)} one perpendicular to {Km}{Vm}: they meet "
        f"at {lab(Vm)}; through {lab(Vm)} draw lines perpendicular to {Vm}{Vi} and "
        f"{Vm}{Vj}: they cut the first two lines at {lab(Vi)} and {lab(Vj)}"
    )
    found = (
        tuple(relative(sol, V, K, D, ph) for V, K in zip(pts, kn))
        + (relative(sol, Vi, Vm, D, ph), relative(sol, Vj, Vm, D, ph))
        + tuple(absolute(sol, V, D, ph) for V in pts)
    )
    return g.record((), lines, found, text)


def _centripetal(P, start, X, Y, om, name):
    """The centripetal component of X about Y (each a point's name or a place), drawn from
    ``start``: om^2 XY, towards Y."""
    r = sub(P[X] if isinstance(X, str) else X, P[Y] if isinstance(Y, str) else Y)
    end = (start[0] - om * om * r[0], start[1] - om * om * r[1])
    return Vector(
        start,
        end,
        f"c{name}",
        "centripetal",
        f"centripetal of {name}",
        f"{om * om * math.hypot(*r):.4g} m/s^2, parallel to {name}, towards its second point",
    )


def _square(start, direction, of, a, b):
    """The line through the end of the centripetal component ``of`` (at ``start``),
    perpendicular to ``ab``."""
    return DirectionLine(
        start,
        direction,
        f"the end of the centripetal of {of}",
        f"perpendicular to {a}{b}",
        mark=f"\u22a5 {a}{b}",
    )


def _acceleration_words(step, sol, ph, aux, s_lab, lab, V, K):
    """The sentence of Goodman's construction on the acceleration polygon (``V``: the three
    vertices, ``K``: the known points they hang from)."""
    (Vi, Vj, Vm), (Ki, Kj, Km) = V, K
    return (
        f"auxiliary point (Goodman): {aux}; from {pole_text(sol, Ki, ph)} draw the "
        f"centripetal of {Vi}{Ki} and from its end the centripetal of S{Vi} (both "
        f"along {Ki}{Vi}), and through the end a line perpendicular to {Ki}{Vi}; the "
        f"same from {pole_text(sol, Kj, ph)} along {Kj}{Vj}: the two lines meet at "
        f"{s_lab}; from {s_lab} the centripetal of {Vm}S and a line perpendicular to "
        f"S{Vm}, from {pole_text(sol, Km, ph)} the centripetal of {Vm}{Km} and a line "
        f"perpendicular to {Km}{Vm}: they meet at {lab(Vm)}; from {lab(Vm)} the "
        f"centripetals of {Vi}{Vm} and {Vj}{Vm} and lines perpendicular to {Vm}{Vi} "
        f"and {Vm}{Vj}; they cut the lines perpendicular to {Ki}{Vi} and {Kj}{Vj} "
        f"drawn through the ends of the centripetals of {Vi}{Ki} and {Vj}{Kj} at "
        f"{lab(Vi)} and {lab(Vj)} (omega of the {step._plate_words} from the velocity "
        "polygon)"
    )


def _acceleration(step, sol, ph):
    """Goodman's construction on the acceleration polygon (the centripetal components
    first, omega from the velocity polygon)."""
    g = _common(step, sol, ph)
    (Vi, Vj, Vm), (Ki, Kj, Km), D, lab, w, S = g.V, g.K, g.D, g.lab, g.w, g.S
    P, pts, kn, lk, perp_to = sol.P, step.points, step.knowns, step.links_, g.perp_to
    i, j, m = g.i, g.j, g.m
    W = sol.W

    def cen(start, X, Y, om, name):
        return _centripetal(P, start, X, Y, om, name)

    ci = cen(D[Ki], Vi, Ki, W[lk[i]], f"{Vi}{Ki}")
    cj = cen(D[Kj], Vj, Kj, W[lk[j]], f"{Vj}{Kj}")
    csi = cen(ci.end, S, Vi, w, f"S{Vi}")
    csj = cen(cj.end, S, Vj, w, f"S{Vj}")
    cm = cen(g.img_s, Vm, S, w, f"{Vm}S")
    ck = cen(D[Km], Vm, Km, W[lk[m]], f"{Vm}{Km}")
    cmi = cen(D[Vm], Vi, Vm, w, f"{Vi}{Vm}")
    cmj = cen(D[Vm], Vj, Vm, w, f"{Vj}{Vm}")
    lines = (
        _square(csi.end, perp_to(Ki, Vi), f"S{Vi}", Ki, Vi),
        _square(csj.end, perp_to(Kj, Vj), f"S{Vj}", Kj, Vj),
        _square(cm.end, perp_to(S, Vm), f"{Vm}S", "S", Vm),
        _square(ck.end, perp_to(Km, Vm), f"{Vm}{Km}", Km, Vm),
        _square(cmi.end, perp_to(Vm, Vi), f"{Vi}{Vm}", Vm, Vi),
        _square(cmj.end, perp_to(Vm, Vj), f"{Vj}{Vm}", Vm, Vj),
        _square(ci.end, perp_to(Ki, Vi), f"{Vi}{Ki}", Ki, Vi),
        _square(cj.end, perp_to(Kj, Vj), f"{Vj}{Kj}", Kj, Vj),
    )
    text = _acceleration_words(step, sol, ph, g.aux, g.s_lab, lab, (Vi, Vj, Vm), (Ki, Kj, Km))
    found = (
        tuple(
            Vector(
                c.end,
                D[V],
                f"t{V}{K}",
                "tangential",
                f"tangential of {V}{K}",
                f"alpha_{k} x {K}{V}",
            )
            for c, V, K, k in ((ci, Vi, Ki, lk[i]), (cj, Vj, Kj, lk[j]), (ck, Vm, Km, lk[m]))
        )
        + tuple(relative(sol, V, K, D, ph) for V, K in zip(pts, kn))
        + tuple(absolute(sol, V, D, ph) for V in pts)
    )
    return g.record((ci, cj, csi, csj, cm, ck, cmi, cmj), lines, found, text)
