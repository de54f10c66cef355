"""The driving crank: its tip from the fixed pivot, the crank angle and speed.

Position: ``T = O + r (cos theta, sin theta)``. Velocity: ``v_T = omega perp(r)`` (oa
perpendicular to OA, omega x OA). Acceleration: ``a_T = -omega^2 r + alpha perp(r)``
(centripetal towards O, tangential perpendicular to OA).

>>> velocity(0.0, 0.05, -10.0)
(0.5, -0.0)
>>> acceleration(0.0, 0.05, -10.0, 0.0)
(-0.0, -5.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..common.tolerances import LEAST_REACH
from .relations import rigid_acceleration, rigid_velocity
from .base import Construction, Step, Vector, absolute, centripetal, image_label, pole_text, sub
from .rounding import EPS, vhypot, vmax

__all__ = ["Crank", "velocity", "acceleration"]


#: the crank's pin relative to its pivot: the rigid-body relations (``relations``)
velocity = rigid_velocity
acceleration = rigid_acceleration


@dataclass(frozen=True)
class Crank(Step):
    """Tip = pivot + r (cos theta, sin theta); v = omega perp(r); a = -omega^2 r + alpha perp(r)."""

    link: str
    pivot: str
    tip: str
    length: float

    kind = "crank"
    steady = True  # nothing intersected: its condition is 1 at every instant

    @property
    def finds(self):
        return (self.tip,)

    @property
    def links(self):
        return (self.link,)

    @property
    def needs(self):
        return (self.pivot,)

    @property
    def title(self):
        return f"crank {self.link}"

    @property
    def params(self):
        return (self.length,)

    def dimensions(self, scene, bodies):
        return (scene.link(self.link).length,)

    def drawn(self, prm, pencil, P):
        return (prm[0] + pencil(),)

    def reach(self):
        return max(self.length, LEAST_REACH)

    def place(self, P, prm, ctx, sigma=None):
        ox, oy = P[self.pivot]
        r = prm[0]
        return ox + r * ctx.cos(ctx.theta), oy + r * ctx.sin(ctx.theta), 1.0

    def bind(self, prm):
        """The step's three phases for dimensions ``prm``: functions of a State."""
        O, T, link, i, r = self.pivot, self.tip, self.link, self.index, prm[0]

        def position(m):  # its condition is 1: nothing to intersect
            ctx = m.ctx
            ox, oy = m.P[O]
            m.P[T] = (ox + r * ctx.cos(ctx.theta), oy + r * ctx.sin(ctx.theta))
            m.cond[i] = 1.0

        def velocity_(m):
            P = m.P
            (ox, oy), (tx, ty), (vox, voy) = P[O], P[T], m.V[O]
            omega = m.ctx.omega
            vx, vy = velocity(tx - ox, ty - oy, omega)
            m.W[link] = omega
            m.V[T] = (vox + vx, voy + vy)

        def acceleration_(m):
            P, ctx = m.P, m.ctx
            (ox, oy), (tx, ty), (aox, aoy) = P[O], P[T], m.A[O]
            ax, ay = acceleration(tx - ox, ty - oy, ctx.omega, ctx.alpha)
            m.Al[link] = ctx.alpha
            m.A[T] = (aox + ax, aoy + ay)

        return position, velocity_, acceleration_

    def bind_instant(self, prm):
        """The three phases in a row for one instant, fused into one plain float function:
        the position and :func:`velocity`, :func:`acceleration` (the rigid-body relations)
        written out in the same operations, so every number is the phased road's to the
        last bit (a test holds the two roads equal)."""
        O, T, link, r = self.pivot, self.tip, self.link, prm[0]
        cos, sin = math.cos, math.sin  # one instant: floats

        def instant(m):
            ctx = m.ctx
            P = m.P
            ox, oy = P[O]
            theta = ctx.theta
            tx = ox + r * cos(theta)
            ty = oy + r * sin(theta)
            P[T] = (tx, ty)  # (its condition, 1: the plan's start_cond)
            omega = ctx.omega
            rx = tx - ox
            ry = ty - oy
            V = m.V
            vox, voy = V[O]
            m.W[link] = omega
            V[T] = (vox + -omega * ry, voy + omega * rx)  # omega perp(r)
            A = m.A
            aox, aoy = A[O]
            alpha = ctx.alpha
            k = omega * omega  # -omega^2 r + alpha perp(r)
            m.Al[link] = alpha
            A[T] = (aox + (-k * rx - alpha * ry), aoy + (-k * ry + alpha * rx))

        return instant

    rounding = 8.0

    def error_bound(self, walk, k, p_in, v_in, a_in):
        """T = O + r (cos, sin): its position errs by the rounding of O's coordinates and
        r; its velocity and acceleration are made from T - O, so they err relative to the
        tip's own motion (omega r, (omega^2 + |alpha|) r) by the rounding of the
        coordinates over r."""
        P, sizes = walk.P, walk.sizes
        omega, alpha = self.rates(walk.motion.scene)
        (ox, oy), (tx, ty) = P[self.pivot], P[self.tip]
        r = vhypot(tx - ox, ty - oy)
        p = self.rounding * EPS * (vhypot(ox, oy) + r) / sizes["position"]
        gain = self.rounding * EPS * vmax((vhypot(ox, oy) + vhypot(tx, ty)) / r, 1.0)
        v = gain * abs(omega) * r / sizes["velocity"]
        a = gain * (omega**2 + abs(alpha)) * r / sizes["acceleration"]
        return p, v, a, v, a

    def rates(self, scene):
        """(omega, alpha) the crank is driven at: the scene's input."""
        return scene.input.omega, scene.input.alpha

    def input_scales(self, scene):
        """(v, a, omega, alpha): the least sizes of each kind the input sets (the error
        bounds are relative to them): omega r, (omega^2 + |alpha|) r, omega, omega^2 +
        |alpha| of the crank driving the mechanism (the driver protocol)."""
        inp = scene.input
        r = scene.link(inp.crank).length
        w = abs(inp.omega)
        w2 = inp.omega**2 + abs(inp.alpha)
        return w * r, w2 * r, w, w2

    # ----- words
    def singular_why(self, c) -> str:
        return f"the crank {self.link} is never singular (condition {c:.2g})"

    def warning(self, c) -> str:
        return f"{self.label}: condition {c:.3g}"

    def limit_why(self) -> str:
        return "the linkage cannot be assembled beyond it"

    def condition_column(self):
        return None  # its condition is always 1

    def transmission(self):
        return None

    def bodies(self):
        """The bodies this step sets moving, in the textbook's numbering order."""
        return (self.link,)

    def orient(self):
        return {self.link: (self.tip, self.pivot)}

    def position_words(self, L, which, angle_deg):
        """The configuration diagram's line for this step (``L`` writes a length)."""
        return (
            f"{self.pivot}{self.tip}: from {self.pivot} draw {self.pivot}{self.tip} = "
            f"{L(self.length)} at {angle_deg} deg"
        )

    #: the words a construction sentence opens with, and says of a crank with no alpha
    lead = ""
    uniform = " (no tangential component: the crank turns uniformly)"

    def construction(self, sol, ph):
        O, T = self.pivot, self.tip
        cond = sol.conditions.get(self.index, 1.0)
        lab = lambda p: image_label(sol, p, ph)  # noqa: E731
        if ph == "velocity":
            V = sol.V
            w = sol.W[self.link]
            v = absolute(sol, T, V, ph)
            text = (
                f"{self.lead}from {pole_text(sol, O, ph)} draw {lab(O)}{lab(T)} "
                f"perpendicular to {O}{T}, = omega x {O}{T} = "
                f"{abs(w):.4g} x {self.length:.4g} = {v.magnitude:.4g} m/s"
            )
            return Construction(self.index, self.title, ph, lab(T), V[T], (), (), (v,), text, cond)
        A = sol.A
        cen = centripetal(sol, T, O, self.link, ph)
        al = sol.Al[self.link]
        r = sub(sol.P[T], sol.P[O])
        tan = Vector(
            cen.end,
            A[T],
            f"{lab(T)}t",
            "tangential",
            f"tangential of {T}{O}",
            f"alpha x {O}{T} = {abs(al) * math.hypot(*r):.4g} m/s^2, perpendicular to {O}{T}",
        )
        text = (
            f"{self.lead}from {pole_text(sol, O, ph)} draw the centripetal component "
            f"{cen.text}"
            + (f"; add the tangential component {tan.text}" if al else self.uniform)
            + f"; its end is {lab(T)}"
        )
        found = (cen, tan, absolute(sol, T, A, ph)) if al else (cen, absolute(sol, T, A, ph))
        return Construction(self.index, self.title, ph, lab(T), A[T], (cen,), (), found, text, cond)
