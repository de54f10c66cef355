"""Goodman's auxiliary-point construction of a class-III group (a triad) on the velocity
and the acceleration polygons: S, where two of the binary links (produced) meet, is a point
of the plate that moves perpendicular to both; its image is found first, then the third
vertex's, then the other two. The step's ``construction`` record, with its direction lines,
vectors and the book's words (:class:`..base.Construction`)."""

from __future__ import annotations

import math

from ..base import (
    Construction,
    DirectionLine,
    Vector,
    absolute,
    image_label,
    perp,
    pole_text,
    relative,
    sub,
    unit,
)

__all__ = ["construction"]


def construction(step, sol, ph):
    """The step's construction record on the polygon of phase ``ph``."""
    return (_velocity if ph == "velocity" else _acceleration)(step, sol, ph)


def _common(step, sol, ph):
    """What both polygons' constructions share: the points, the auxiliary point S and
    its image, the labels and the words of S."""
    P = sol.P
    i, j, m, S = step._aux(P)
    pts, kn, lk = step.points, step.knowns, step.links_
    Vi, Vj, Vm = pts[i], pts[j], pts[m]
    Ki, Kj, Km = kn[i], kn[j], kn[m]
    cond = sol.conditions.get(step.index, 1.0)
    lab = lambda p: image_label(sol, p, ph)  # noqa: E731
    w = sol.W[step.plate]
    prime = "'" if ph == "acceleration" else ""
    s_lab = step._aux_label(sol) + prime
    perp_to = lambda a, b: unit(*perp(sub(P[b], P[a])))  # noqa: E731
    D = sol.V if ph == "velocity" else sol.A
    x1, y1 = P[pts[0]]
    ref = D[pts[0]]
    if ph == "velocity":
        img_s = (ref[0] - w * (S[1] - y1), ref[1] + w * (S[0] - x1))
    else:
        al = sol.Al[step.plate]
        img_s = (
            ref[0] - al * (S[1] - y1) - w * w * (S[0] - x1),
            ref[1] + al * (S[0] - x1) - w * w * (S[1] - y1),
        )
    aux = f"S, where {Ki}{Vi} and {Kj}{Vj} (produced) meet, a point of the {step._plate_words}"
    return (
        P,
        i,
        j,
        m,
        S,
        pts,
        kn,
        lk,
        Vi,
        Vj,
        Vm,
        Ki,
        Kj,
        Km,
        cond,
        lab,
        w,
        s_lab,
        perp_to,
        D,
        img_s,
        aux,
    )


def _velocity(step, sol, ph):
    """Goodman's construction on the velocity polygon."""
    (
        P,
        i,
        j,
        m,
        S,
        pts,
        kn,
        lk,
        Vi,
        Vj,
        Vm,
        Ki,
        Kj,
        Km,
        cond,
        lab,
        w,
        s_lab,
        perp_to,
        D,
        img_s,
        aux,
    ) = _common(step, sol, ph)
    lines = (
        DirectionLine(
            D[Ki], perp_to(Ki, Vi), lab(Ki), f"perpendicular to {Ki}{Vi}", mark=f"\u22a5 {Ki}{Vi}"
        ),
        DirectionLine(
            D[Kj], perp_to(Kj, Vj), lab(Kj), f"perpendicular to {Kj}{Vj}", mark=f"\u22a5 {Kj}{Vj}"
        ),
        DirectionLine(
            img_s,
            unit(*perp(sub(P[Vm], S))),
            s_lab,
            f"perpendicular to S{Vm}",
            mark=f"\u22a5 S{Vm}",
        ),
        DirectionLine(
            D[Km], perp_to(Km, Vm), lab(Km), f"perpendicular to {Km}{Vm}", mark=f"\u22a5 {Km}{Vm}"
        ),
        DirectionLine(
            D[Vm], perp_to(Vm, Vi), lab(Vm), f"perpendicular to {Vm}{Vi}", mark=f"\u22a5 {Vm}{Vi}"
        ),
        DirectionLine(
            D[Vm], perp_to(Vm, Vj), lab(Vm), f"perpendicular to {Vm}{Vj}", mark=f"\u22a5 {Vm}{Vj}"
        ),
    )
    text = (
        f"auxiliary point (Goodman): {aux}, moves perpendicular to both lines; "
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
    return Construction(
        step.index,
        step.title,
        ph,
        ", ".join(lab(p) for p in pts),
        D[Vm],
        (),
        lines,
        found,
        text,
        cond,
        ((s_lab, img_s),),
    )


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
    (
        P,
        i,
        j,
        m,
        S,
        pts,
        kn,
        lk,
        Vi,
        Vj,
        Vm,
        Ki,
        Kj,
        Km,
        cond,
        lab,
        w,
        s_lab,
        perp_to,
        D,
        img_s,
        aux,
    ) = _common(step, sol, ph)
    W = sol.W

    def cen(start, X, Y, om, name):
        return _centripetal(P, start, X, Y, om, name)

    ci = cen(D[Ki], Vi, Ki, W[lk[i]], f"{Vi}{Ki}")
    cj = cen(D[Kj], Vj, Kj, W[lk[j]], f"{Vj}{Kj}")
    csi = cen(ci.end, S, Vi, w, f"S{Vi}")
    csj = cen(cj.end, S, Vj, w, f"S{Vj}")
    cm = cen(img_s, Vm, S, w, f"{Vm}S")
    ck = cen(D[Km], Vm, Km, W[lk[m]], f"{Vm}{Km}")
    cmi = cen(D[Vm], Vi, Vm, w, f"{Vi}{Vm}")
    cmj = cen(D[Vm], Vj, Vm, w, f"{Vj}{Vm}")
    lines = (
        _square(csi.end, perp_to(Ki, Vi), f"S{Vi}", Ki, Vi),
        _square(csj.end, perp_to(Kj, Vj), f"S{Vj}", Kj, Vj),
        _square(cm.end, unit(*perp(sub(P[Vm], S))), f"{Vm}S", "S", Vm),
        _square(ck.end, perp_to(Km, Vm), f"{Vm}{Km}", Km, Vm),
        _square(cmi.end, perp_to(Vm, Vi), f"{Vi}{Vm}", Vm, Vi),
        _square(cmj.end, perp_to(Vm, Vj), f"{Vj}{Vm}", Vm, Vj),
        _square(ci.end, perp_to(Ki, Vi), f"{Vi}{Ki}", Ki, Vi),
        _square(cj.end, perp_to(Kj, Vj), f"{Vj}{Kj}", Kj, Vj),
    )
    text = _acceleration_words(step, sol, ph, aux, s_lab, lab, (Vi, Vj, Vm), (Ki, Kj, Km))
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
    return Construction(
        step.index,
        step.title,
        ph,
        ", ".join(lab(p) for p in pts),
        D[Vm],
        (ci, cj, csi, csj, cm, ck, cmi, cmj),
        lines,
        found,
        text,
        cond,
        ((s_lab, img_s),),
    )
