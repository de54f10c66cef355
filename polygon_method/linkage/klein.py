"""Klein's construction: the slider crank's velocity and acceleration diagrams drawn on the
configuration diagram itself, for a crank turning at uniform speed (the book's quick
graphical check on the piston).

The crank O C (the crank pin C), the rod C P, the piston P on its line of stroke (unit
``u``; O on it for an in-line engine, or beside it):

1. Produce P C to meet at M the line through O square to the line of stroke. Triangle
   O C M is the velocity diagram turned through 90 deg, to the scale omega: ``v_C = w OC``,
   ``v_P = w OM``, ``v_PC = w CM`` (``v_P`` is ``w k x (M - O)``).
2. Draw the circle about C through M, and the circle on C P as diameter; their common chord
   K L (square to C P) meets C P at Q and the line through O along the stroke at N.
   ``CQ = CM^2 / CP`` (Q has the same power to both circles).
3. O C Q N is the acceleration diagram to the scale omega^2: ``a_C = w^2 CO`` (towards O),
   the rod's radial component ``w^2 CQ`` (from P towards C), its tangential component
   ``w^2 QN``, and the piston's acceleration ``a_P = w^2 (O - N)``: ``w^2 NO``, from N to O.

The circles meet (K and L exist) only where ``CM <= CP``; the chord's line, and so Q and N,
are there whether they meet or not. With the crank accelerating (alpha not 0) the
construction does not apply: the piston has a further ``alpha`` part it leaves out.

>>> k = construct((0.0, 0.0), (0.0, 1.0), (4.0, 0.0), (1.0, 0.0), 2.0)   # crank square to OP
>>> [round(c, 12) + 0.0 for c in k.M]       # the rod produced meets the perpendicular at C
[0.0, 1.0]
>>> [round(c, 12) + 0.0 for c in k.v_P]      # the piston moves with the crank pin: -w r
[-2.0, 0.0]
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .shapes import slider_crank_of

__all__ = ["Klein", "construct", "klein_of", "klein_blocks"]


@dataclass(frozen=True)
class Klein:
    """The points of Klein's construction (m) and what they give (SI)."""

    O: tuple
    C: tuple
    P: tuple
    u: tuple
    omega: float
    M: tuple
    Q: tuple
    N: tuple
    K: tuple | None
    L: tuple | None
    v_P: tuple
    v_PC: tuple
    a_P: tuple
    a_radial: tuple
    a_tangential: tuple

    def length(self, a, b) -> float:
        """The distance between two of the construction's named points, ``a`` and ``b`` (m)."""
        return math.dist(getattr(self, a), getattr(self, b))


def _meet(p, d, q, e):
    """The point where ``p + s d`` meets ``q + t e`` (None for parallel lines)."""
    den = d[0] * e[1] - d[1] * e[0]
    if den == 0:
        return None
    s = ((q[0] - p[0]) * e[1] - (q[1] - p[1]) * e[0]) / den
    return (p[0] + s * d[0], p[1] + s * d[1])


def construct(O, C, P, u, omega) -> Klein | None:
    """Klein's construction for crank pin ``C`` about ``O``, piston ``P`` on a line of stroke
    along unit ``u``, crank speed ``omega`` (rad/s, ccw positive); None where the rod stands
    square to the line of stroke (no M)."""
    n = (-u[1], u[0])
    rod = (P[0] - C[0], P[1] - C[1])
    M = _meet(C, rod, O, n)
    if M is None:
        return None
    cp2 = rod[0] ** 2 + rod[1] ** 2
    s = ((M[0] - C[0]) * rod[0] + (M[1] - C[1]) * rod[1]) / cp2  # M = C + s (P - C)
    Q = (C[0] + s * s * rod[0], C[1] + s * s * rod[1])  # CQ = CM^2 / CP
    perp = (-rod[1], rod[0])
    N = _meet(Q, perp, O, u)
    cm2 = s * s * cp2
    cq2 = s**4 * cp2
    K = L = None
    if cm2 >= cq2:
        h = math.sqrt((cm2 - cq2) / cp2)  # along the unit perp, |perp| = |rod|
        K = (Q[0] + h * perp[0], Q[1] + h * perp[1])
        L = (Q[0] - h * perp[0], Q[1] - h * perp[1])
    w, w2 = omega, omega * omega
    v_P = (-w * (M[1] - O[1]), w * (M[0] - O[0]))
    v_PC = (-w * (M[1] - C[1]), w * (M[0] - C[0]))
    a_P = (w2 * (O[0] - N[0]), w2 * (O[1] - N[1]))
    a_r = (w2 * (C[0] - Q[0]), w2 * (C[1] - Q[1]))
    a_t = (w2 * (Q[0] - N[0]), w2 * (Q[1] - N[1]))
    return Klein(O, C, P, u, omega, M, Q, N, K, L, v_P, v_PC, a_P, a_r, a_t)


def klein_of(sol):
    """(the :class:`Klein` of ``sol``'s slider crank, its names (O, C, P)) or (None, why):
    a slider crank whose crank turns at uniform speed."""
    sk = slider_crank_of(sol.scene)
    if sk is None or sol.scene.input.second is not None:
        return None, "no slider crank"
    if sol.scene.input.alpha:
        return None, ("the crank accelerates: Klein's construction takes its speed as uniform")
    if sol.scene.at_rest:
        return None, "at rest: nothing moves (Klein's construction is of the piston's motion)"
    w = sol.W[sk.crank]
    k = construct(sol.P[sk.o], sol.P[sk.a], sol.P[sk.b], sk.u, w)
    if k is None:
        return None, "the rod stands square to the line of stroke"
    return k, (sk.o, sk.a, sk.b)


def klein_blocks(sol) -> list:
    """The ``steps`` document's blocks for Klein's construction (none for a mechanism that
    is no slider crank at uniform crank speed)."""
    k, names = klein_of(sol)
    if k is None:
        return []
    O, C, P = names
    sc = sol.scene
    u = sc.length_unit
    w = abs(k.omega)

    def ln(a, b):
        return f"{k.length(a, b) / u:.4g} {sc.units}"

    vp = math.hypot(*k.v_P)
    ap = math.hypot(*k.a_P)
    toward = (
        "towards"
        if (k.a_P[0] * (k.O[0] - k.P[0]) + k.a_P[1] * (k.O[1] - k.P[1])) > 0
        else "away from"
    )
    items = [
        f"Produce {P}{C} to meet at M the line through {O} square to the line of stroke. "
        f"Triangle {O}{C}M is the velocity diagram turned through 90 deg, to the scale "
        f"omega = {w:.6g} rad/s: {O}{C} = v_{C} / omega, {O}M = v_{P} / omega, {C}M = "
        f"v_{P}{C} / omega. {O}M = {ln('O', 'M')}, so v_{P} = omega x {O}M = {vp:.6g} m/s; "
        f"{C}M = {ln('C', 'M')}, so v_{P}{C} = {math.hypot(*k.v_PC):.6g} m/s.",
        f"With {C} as centre and {C}M as radius draw a circle; on {C}{P} as diameter draw "
        "another"
        + (
            "; they meet at K and L. Their common chord KL"
            if k.K is not None
            else f"; they do not meet here ({C}M > {C}{P}): their common chord's "
            "line, square to " + f"{C}{P} at Q,"
        )
        + f" meets {C}{P} at Q ({C}Q = {C}M^2 / {C}{P} = {ln('C', 'Q')}) and the line "
        f"through {O} along the stroke at N.",
        f"{O}{C}QN is the acceleration diagram to the scale omega^2 = {w * w:.6g} 1/s^2: "
        f"{C}{O} = a_{C} / omega^2, {C}Q = the radial part of a_{P}{C}, QN = its tangential "
        f"part ({math.hypot(*k.a_tangential):.6g} m/s^2), N{O} = a_{P} / omega^2. N{O} = "
        f"{ln('N', 'O')}, so a_{P} = omega^2 x N{O} = {ap:.6g} m/s^2, from N towards {O}: "
        f"{toward} the crank centre.",
    ]
    return [
        ("h", "Klein's construction (the slider crank at uniform crank speed)"),
        (
            "p",
            "A check on the piston drawn on the configuration diagram itself: the "
            "velocity and acceleration diagrams to the scales omega and omega^2.",
        ),
        ("list", items),
    ]
