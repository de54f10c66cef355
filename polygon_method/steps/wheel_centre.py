"""The centre of a wheel rolling on a fixed line, found from a link pinned to it.

The centre C of a wheel of radius r rolling on a line stays at r from the line: it moves on
the parallel line ``Q + s u``, Q = T + r m (T a point of the ground line, m its unit normal
towards the wheel). A link BC from a known point B then finds C as a slider on a fixed path
does (the same formulas, :mod:`.slider`), with no block: the wheel itself turns, found by
the next step (:mod:`.rolling`).

    w perp(r) - v_C = -v_B  along the two direction lines (perpendicular to BC, parallel
    to the line):  w = u x (-v_B) / (r.u),  v_C = v_B + w perp(r)

>>> x, y, c = place(0.0, 0.3, 0.0, 0.0, 1.0, 0.0, 0.5, 1.0)
>>> round(x, 12), round(y, 12)
(0.4, 0.0)
"""

from __future__ import annotations

from dataclasses import dataclass

from ..common.errors import TOL
from ..common.numbers import in_units, condition_text
from ..common.tolerances import LEAST_REACH
from .base import (
    Construction,
    DirectionLine,
    Step,
    absolute,
    centripetal,
    image_label,
    perp,
    pole_text,
    relative,
    sub,
    tangential,
    unit,
)
from .rounding import line_rounding
from .slider import acceleration, place, velocity

__all__ = ["WheelCentre", "place", "recognise"]


def recognise(g, name):
    """The centre of a wheel rolling on a line, with one free link to a known point."""
    sc = g.scene
    if not sc.rolling:  # (the usual scene: nothing rolls)
        return None
    pr = next((r for r in sc.rolling if r.centre == name and r.on == "line"), None)
    if pr is None:
        return None
    free = [f for f in g.free(name) if f[0] != pr.wheel]
    if not free:
        return None
    key, k, length = free[0]
    return WheelCentre(
        g.next_index,
        name,
        k,
        key,
        length,
        pr.wheel,
        pr.radius,
        pr.through,
        pr.u,
        pr.m,
        pr.label,
        unit=g.unit,
        uname=g.uname,
    )


@dataclass(frozen=True)
class WheelCentre(Step):
    """C on the line parallel to the ground line at the wheel's radius, |BC| = l."""

    point: str
    b: str
    link: str
    length: float
    wheel: str
    radius: float
    through: tuple
    u: tuple
    m: tuple
    where: str
    sigma: float = 1.0
    unit: float = 1e-3
    uname: str = "mm"

    kind = "wheel centre"
    branching = True
    other_assembly_mistake = True

    @property
    def finds(self):
        return (self.point,)

    @property
    def links(self):
        return (self.link,)

    @property
    def needs(self):
        return (self.b,)

    @property
    def needs_links(self):
        return ()

    @property
    def title(self):
        return f"link {self.link}, centre {self.point} of wheel {self.wheel} on {self.where}"

    @property
    def params(self):
        (tx, ty), (ux, uy), (mx, my), r = self.through, self.u, self.m, self.radius
        return (self.length, tx + r * mx, ty + r * my, ux, uy)

    def dimensions(self, scene, bodies):
        pr = next(r for r in scene.rolling if r.wheel == self.wheel)
        (tx, ty), (ux, uy), (mx, my), r = pr.through, pr.u, pr.m, pr.radius
        return (bodies.distance(self.link, self.b, self.point), tx + r * mx, ty + r * my, ux, uy)

    def drawn(self, prm, pencil, P):
        return (prm[0] + pencil(), prm[1] + pencil(), prm[2] + pencil(), prm[3], prm[4])

    def reach(self):
        return max(self.length, LEAST_REACH)

    def place(self, P, prm, ctx, sigma=None):
        bx, by = P[self.b]
        s = self.sigma if sigma is None else sigma
        return place(bx, by, prm[1], prm[2], prm[3], prm[4], prm[0], s, ctx, self)

    def default_hint(self, P):
        return self.u  # farther along the line

    def bind(self, prm):
        """The step's three phases for dimensions ``prm``: functions of a State."""
        X, B, link, i, sigma, step = self.point, self.b, self.link, self.index, self.sigma, self
        ell, qx, qy, ux, uy = prm

        def position(m):
            x, y, c = place(*m.P[B], qx, qy, ux, uy, ell, sigma, m.ctx, step)
            m.P[X] = (x, y)
            m.cond[i] = c

        def velocity_(m):
            (x, y), (bx, by) = m.P[X], m.P[B]
            rx, ry = x - bx, y - by
            vbx, vby = m.V[B]
            d = rx * ux + ry * uy
            if m.array:
                d = m.ctx.safe(d, step)
            w, _, vx, vy = velocity(rx, ry, ux, uy, -vbx, -vby, vbx, vby, d)
            m.W[link] = w
            m.V[X] = (vx, vy)

        def acceleration_(m):
            (x, y), (bx, by) = m.P[X], m.P[B]
            rx, ry = x - bx, y - by
            d = rx * ux + ry * uy
            if m.array:
                d = m.ctx.safe(d, step)
            al, _, ax, ay = acceleration(rx, ry, ux, uy, 0.0, 0.0, m.W[link], *m.A[B], d)
            m.Al[link] = al
            m.A[X] = (ax, ay)

        return position, velocity_, acceleration_

    def bind_instant(self, prm):
        """The three phases in a row for one instant, its condition checked (the same
        formulas as ``bind``, the intermediates passed on)."""
        X, B, link, i, sigma, step = self.point, self.b, self.link, self.index, self.sigma, self
        ell, qx, qy, ux, uy = prm

        def instant(m):
            P = m.P
            bx, by = P[B]
            x, y, c = place(bx, by, qx, qy, ux, uy, ell, sigma, m.ctx, step)
            P[X] = (x, y)
            m.cond[i] = c
            if c < TOL.singular:
                raise step.singular(c)
            rx, ry = x - bx, y - by
            vbx, vby = m.V[B]
            d = rx * ux + ry * uy
            w, _, vx, vy = velocity(rx, ry, ux, uy, -vbx, -vby, vbx, vby, d)
            m.W[link] = w
            m.V[X] = (vx, vy)
            al, _, ax, ay = acceleration(rx, ry, ux, uy, 0.0, 0.0, w, *m.A[B], d)
            m.Al[link] = al
            m.A[X] = (ax, ay)

        return instant

    rounding = 48.0

    def error_bound(self, walk, k, p_in, v_in, a_in):
        """The rule of two direction lines (:mod:`.rounding`), as for a slider, the
        line's own numbers in the rounding (:func:`.rounding.line_rounding`)."""
        (qx, qy), (x, y) = self.through, walk.P[self.point]
        k = k + line_rounding(self.rounding, qx, qy, x, y, walk.sizes["position"])
        return Step.error_bound(self, walk, k, p_in, v_in, a_in)

    # ----- words
    def why(self, dist):
        """Why the wheel's centre cannot be placed: its link is shorter than the known end's
        distance ``dist`` from the centre's line."""
        u, n = self.unit, self.uname
        return (
            f"cannot assemble {self.point}: {self.link} = {in_units(self.length, u)} {n} "
            f"< distance of {self.b} from the line of the wheel's centre = "
            f"{in_units(abs(dist), u)} {n}"
        )

    def singular_why(self, c):
        return (
            f"{self.link} is perpendicular to the line of the wheel's centre {self.point} "
            f"(sine {condition_text(c)}): a dead centre for this step"
        )

    def warning(self, c):
        return (
            f"{self.label}: the line perpendicular to {self.link} is nearly parallel to "
            f"the ground line (condition {c:.3g}): near a dead centre for this step"
        )

    def limit_why(self):
        return f"{self.link} stands perpendicular to the ground line of wheel {self.wheel}"

    def transmission(self):
        return f"between {self.link} and the normal to the ground line of wheel {self.wheel}"

    def condition_column(self):
        return (f"mu at {self.point}", "deg", "transmission angle (acute)")

    def bodies(self):
        return (self.link,)

    def orient(self):
        return {self.link: (self.point, self.b)}

    def output(self, ground):
        return None

    def position_words(self, L, which, angle_deg):
        return (
            f"{self.point}: an arc of radius {self.link} = {L(self.length)} about {self.b} "
            f"cuts the line at {L(self.radius)} from {self.where} (the wheel's centre) at "
            f"{self.point} ({which(self.point)})"
        )

    def construction(self, sol, ph):
        P, X, B = sol.P, self.point, self.b
        cond = sol.conditions.get(self.index, 1.0)
        lab = lambda p: image_label(sol, p, ph)  # noqa: E731
        d1 = unit(*perp(sub(P[X], P[B])))
        o = "o" if ph == "velocity" else "o'"
        rel = f"parallel to {self.where} (the centre moves along it)"
        if ph == "velocity":
            V = sol.V
            lines = (
                DirectionLine(V[B], d1, lab(B), f"perpendicular to {B}{X}", mark=f"\u22a5 {B}{X}"),
                DirectionLine((0.0, 0.0), self.u, o, rel, mark=f"\u2225 {self.where}"),
            )
            text = (
                f"through {pole_text(sol, B, ph)} draw a line perpendicular to {B}{X}; "
                f"through {o}, one {rel}; they meet at {lab(X)}"
            )
            found = (relative(sol, X, B, V, ph), absolute(sol, X, V, ph))
            return Construction(
                self.index, self.title, ph, lab(X), V[X], (), lines, found, text, cond
            )
        A = sol.A
        c1 = centripetal(sol, X, B, self.link, ph)
        lines = (
            DirectionLine(
                c1.end,
                d1,
                f"the end of the centripetal of {X}{B}",
                f"perpendicular to {B}{X}",
                mark=f"\u22a5 {B}{X}",
            ),
            DirectionLine((0.0, 0.0), self.u, o, rel, mark=f"\u2225 {self.where}"),
        )
        text = (
            f"from {pole_text(sol, B, ph)} draw the centripetal of {X}{B} ({c1.text}) and "
            f"through its end a line perpendicular to {B}{X}; through {o}, one {rel}; "
            f"they meet at {lab(X)}"
        )
        found = (
            tangential(sol, X, B, self.link, c1.end),
            relative(sol, X, B, A, ph),
            absolute(sol, X, A, ph),
        )
        return Construction(
            self.index, self.title, ph, lab(X), A[X], (c1,), lines, found, text, cond
        )
