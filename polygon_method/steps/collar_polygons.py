"""The driving collar's constructions on the velocity and the acceleration polygons
(:mod:`.collar`): the rod's point under the collar (its image c1), the given sliding
laid off along the rod, the Coriolis component on the acceleration polygon; the step's
``construction`` record, with its direction lines, vectors and the book's words."""

from __future__ import annotations

import math

from .base import (
    Construction,
    DirectionLine,
    Vector,
    absolute,
    add,
    image_label,
    perp,
    pole_text,
    sub,
    unit,
)
from .slotted import under_label

__all__ = ["construction"]


def construction(step, sol, ph):
    """The collar step's construction record on the polygon of phase ``ph``."""
    return (_velocity if ph == "velocity" else _acceleration)(step, sol, ph)


def _shared(step, sol, ph):
    """What both polygons read: KC and DC on the configuration, |KC|, the rod's unit, the
    collar's sliding velocity (along the rod's direction K to N), the label of the rod's
    point under C, and the sliding's words."""
    P, C, K, D, N = sol.P, step.point, step.pivot, step.fixed, step.end
    d1, d2 = sub(P[C], P[K]), sub(P[C], P[D])
    vs = sol.S[C][0] * step.sense_first
    speed = f"{abs(vs):.4g} m/s {step.sense(vs)}"
    return d1, d2, math.hypot(*d1), unit(*sub(P[N], P[K])), vs, under_label(sol, C, ph), speed


def _velocity(step, sol, ph):
    """The construction on the velocity polygon: the sliding from the pole, a line
    perpendicular to KC through its end, one perpendicular to DC through d."""
    C, K, D, N = step.point, step.pivot, step.fixed, step.end
    cond = sol.conditions.get(step.index, 1.0)
    lab = lambda p: image_label(sol, p, ph)  # noqa: E731
    d1, d2, s, w, vs, c1, speed = _shared(step, sol, ph)
    w_r = sol.W[step.rod]
    V = sol.V
    slide = (vs * w[0], vs * w[1])
    under = sub(V[C], slide)
    lines = (
        DirectionLine(
            slide,
            unit(*perp(d1)),
            f"the end of {c1}{lab(C)} drawn from {lab(K)}",
            f"perpendicular to {K}{C}",
            mark=f"\u22a5 {K}{C}",
        ),
        DirectionLine(
            V[D], unit(*perp(d2)), lab(D), f"perpendicular to {D}{C}", mark=f"\u22a5 {D}{C}"
        ),
    )
    given = (
        Vector(
            (0.0, 0.0),
            slide,
            f"{c1}{lab(C)}",
            "sliding",
            f"vs_{C}",
            f"the collar {C} slides along {step.rod} at {speed}, given",
        ),
    )
    text = (
        f"the collar {C} slides along {step.rod} at {speed}: {c1}{lab(C)} = "
        f"{abs(vs):.4g} m/s along {step.rod}, from the image {c1} of the rod's "
        f"point under {C}, which moves perpendicular to {K}{C}; so from "
        f"{pole_text(sol, K, ph)} draw {abs(vs):.4g} m/s along {step.rod} and "
        f"through its end a line perpendicular to {K}{C}; through "
        f"{pole_text(sol, D, ph)} a line perpendicular to {D}{C}; they meet at "
        f"{lab(C)}; {c1} is {abs(vs):.4g} m/s back along {step.rod} from it; "
        f"{lab(K)}{lab(N)} / {lab(K)}{c1} = {K}{N} / {K}{C} gives {lab(N)}"
    )
    found = (
        Vector(
            V[K],
            under,
            f"{lab(K)}{c1}",
            "relative",
            f"v of the rod's point under {C}",
            f"omega_{step.rod} x {K}{C} = {abs(w_r) * s:.4g} m/s",
        ),
        Vector(
            under,
            V[C],
            f"{c1}{lab(C)}",
            "sliding",
            f"vs_{C}",
            "the collar's sliding, given",
        ),
        absolute(sol, C, V, ph),
        absolute(sol, N, V, ph),
    )
    return Construction(
        step.index,
        step.title,
        ph,
        lab(C),
        V[C],
        given,
        lines,
        found,
        text,
        cond,
        ((c1, under),),
    )


def _acceleration(step, sol, ph):
    """The construction on the acceleration polygon: the centripetal of the rod's point
    under C, the Coriolis component and the given sliding acceleration from the pole; the
    centripetal of C about D from d'."""
    C, K, D, N = step.point, step.pivot, step.fixed, step.end
    cond = sol.conditions.get(step.index, 1.0)
    lab = lambda p: image_label(sol, p, ph)  # noqa: E731
    d1, d2, s, w, vs, c1, speed = _shared(step, sol, ph)
    A, al_r = sol.A, sol.Al[step.rod]
    a_s = sol.S[C][1] * step.sense_first
    given = _given_accelerations(step, sol, d1, d2, w, a_s)
    cen1, after_slide, cen2 = given[0].end, given[2].end, given[3].end
    under = add(cen1, (-al_r * d1[1], al_r * d1[0]))
    lines = (
        DirectionLine(
            after_slide,
            unit(*perp(d1)),
            "the end of the sliding acceleration",
            f"perpendicular to {K}{C}",
            mark=f"\u22a5 {K}{C}",
        ),
        DirectionLine(
            cen2,
            unit(*perp(d2)),
            f"the end of the centripetal of {C}{D}",
            f"perpendicular to {D}{C}",
            mark=f"\u22a5 {D}{C}",
        ),
    )
    text = (
        f"from {pole_text(sol, K, ph)} draw the centripetal of the rod's point under "
        f"{C} ({given[0].text}), then the Coriolis component 2 omega v "
        f"({given[1].text}), then the sliding acceleration {abs(a_s):.4g} m/s^2 "
        f"along {step.rod}; through its end a line perpendicular to {K}{C}; from "
        f"{pole_text(sol, D, ph)} the centripetal of {C} about {D} "
        f"({given[3].text}) and through its end a line perpendicular to {D}{C}; they "
        f"meet at {lab(C)}; {lab(N)} follows by {lab(K)}{lab(N)} / {lab(K)}{c1} = "
        f"{K}{N} / {K}{C}"
    )
    found = (
        Vector(
            after_slide,
            A[C],
            "t",
            "tangential",
            f"tangential of the rod's point under {C}",
            f"alpha_{step.rod} x {K}{C}",
        ),
        Vector(
            cen2,
            A[C],
            "t",
            "tangential",
            f"tangential of {C}{D}",
            f"alpha_{step.link} x {D}{C}",
        ),
        absolute(sol, C, A, ph),
        absolute(sol, N, A, ph),
    )
    return Construction(
        step.index,
        step.title,
        ph,
        lab(C),
        A[C],
        given,
        lines,
        found,
        text,
        cond,
        ((c1, under),),
    )


def _given_accelerations(step, sol, d1, d2, w, a_s):
    """The vectors known before the acceleration step: from the pole, the centripetal of
    the rod's point under C, the Coriolis component and the given sliding acceleration
    ``a_s`` (along ``w``), end to end; the centripetal of C about D from d' (at the pole)."""
    C, K, D = step.point, step.pivot, step.fixed
    w_r, w_d = sol.W[step.rod], sol.W[step.link]
    s = math.hypot(*d1)
    cor = sol.coriolis(C)
    cen1 = (-w_r * w_r * d1[0], -w_r * w_r * d1[1])
    after_cor = add(cen1, cor)
    after_slide = add(after_cor, (a_s * w[0], a_s * w[1]))
    cen2 = (-w_d * w_d * d2[0], -w_d * w_d * d2[1])
    return (
        Vector(
            (0.0, 0.0),
            cen1,
            "cen",
            "centripetal",
            f"centripetal of the rod's point under {C}",
            f"omega_{step.rod}^2 x {K}{C} = {w_r * w_r * s:.4g} m/s^2, towards {K}",
        ),
        Vector(
            cen1,
            after_cor,
            "cor",
            "coriolis",
            f"Coriolis at {C}",
            f"2 omega_{step.rod} vs = {math.hypot(*cor):.4g} m/s^2, perpendicular to {step.rod}",
        ),
        Vector(
            after_cor,
            after_slide,
            "s",
            "sliding",
            f"as_{C}",
            f"the collar's sliding acceleration {abs(a_s):.4g} m/s^2 {step.sense(a_s)}, given",
        ),
        Vector(
            (0.0, 0.0),
            cen2,
            "cen",
            "centripetal",
            f"centripetal of {C}{D}",
            f"omega_{step.link}^2 x {D}{C} = {w_d * w_d * math.hypot(*d2):.4g} m/s^2, towards {D}",
        ),
    )
