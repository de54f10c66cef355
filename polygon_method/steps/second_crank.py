"""A second driving crank (two degrees of freedom: a five-bar with two driven cranks, a
link hung from two driven cranks). Its tip from its fixed pivot, its own angle, speed and
acceleration (``[input.second]``); everything else in the plan follows from both cranks.

Position: ``T = O + r (cos theta2, sin theta2)``; over a sweep of the first crank the second
turns with it at the ratio of their speeds, ``theta2 = theta2_0 + (omega2 / omega1)(theta -
theta_0)`` (both cranks driven at their stated speeds). Velocity and acceleration are the
first crank's relations (:mod:`.crank`): ``v_T = omega2 perp(r)``, ``a_T = -omega2^2 r +
alpha2 perp(r)``. The velocities of the mechanism are linear in the two speeds: the
polygon for both is the sum of the polygons for each alone (superposition), which the
step table shows.

>>> from polygon_method.steps.crank import velocity
>>> velocity(0.0, 0.1, 5.0)     # the second crank's tip, straight up, 5 rad/s ccw
(-0.5, 0.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .base import Step
from .crank import Crank, acceleration, velocity

__all__ = ["SecondCrank"]


@dataclass(frozen=True)
class SecondCrank(Crank):
    """A second driven crank: tip = pivot + r (cos theta2, sin theta2), theta2 following the
    first crank at the ratio of their speeds; v = omega2 perp(r); a = -omega2^2 r +
    alpha2 perp(r). What it finds, reads and sets moving is the first crank's."""

    angle: float = 0.0
    omega: float = 0.0
    alpha: float = 0.0
    angle1: float = 0.0  # the first crank's angle at the scene's instant
    omega1: float = 1.0  # the first crank's speed (the ratio over a sweep)

    kind = "second crank"
    bind_instant = Step.bind_instant  # its three phases in a row (not the first crank's)

    @property
    def title(self):
        return f"second crank {self.link}"

    @property
    def theta_rate(self):
        """Its turning per radian of the first crank (a gear meshing with it reads it)."""
        return self.omega / self.omega1 if self.omega1 else None

    @property
    def params(self):
        return (self.length, self.angle, self.omega, self.alpha, self.angle1, self.omega1)

    def dimensions(self, scene, bodies):
        two, one = scene.input.second, scene.input
        return (scene.link(self.link).length, two.angle, two.omega, two.alpha, one.angle, one.omega)

    def drawn(self, prm, pencil, P):
        return (prm[0] + pencil(),) + tuple(prm[1:])

    def place(self, P, prm, ctx, sigma=None):
        ox, oy = P[self.pivot]
        th = _theta2(ctx, prm)
        return ox + prm[0] * ctx.cos(th), oy + prm[0] * ctx.sin(th), 1.0

    def bind(self, prm):
        O, T, link, i = self.pivot, self.tip, self.link, self.index
        r, w2, a2 = prm[0], prm[2], prm[3]

        def position(m):
            ctx = m.ctx
            ox, oy = m.P[O]
            th = _theta2(ctx, prm)
            m.P[T] = (ox + r * ctx.cos(th), oy + r * ctx.sin(th))
            m.cond[i] = 1.0

        def velocity_(m):
            (ox, oy), (tx, ty), (vox, voy) = m.P[O], m.P[T], m.V[O]
            vx, vy = velocity(tx - ox, ty - oy, w2)
            m.W[link] = w2
            m.V[T] = (vox + vx, voy + vy)

        def acceleration_(m):
            (ox, oy), (tx, ty), (aox, aoy) = m.P[O], m.P[T], m.A[O]
            ax, ay = acceleration(tx - ox, ty - oy, w2, a2)
            m.Al[link] = a2
            m.A[T] = (aox + ax, aoy + ay)

        return position, velocity_, acceleration_

    def rates(self, scene):
        """(omega, alpha) it is driven at: its own (the first crank's error rule)."""
        return self.omega, self.alpha

    def held(self, prm):
        """Its dimensions with its own speed held (the first input alone)."""
        return tuple(prm[:2]) + (0.0, 0.0) + tuple(prm[4:])

    # ----- words (the rest, and the error bound, are the first crank's)
    lead = "the second input: "
    uniform = ""

    def singular_why(self, c) -> str:
        return f"the second crank {self.link} is never singular (condition {c:.2g})"

    def position_words(self, L, which, angle_deg):
        return (
            f"{self.pivot}{self.tip}: from {self.pivot} draw {self.pivot}{self.tip} = "
            f"{L(self.length)} at {math.degrees(self.angle):.5g} deg (the second input)"
        )


def _theta2(ctx, prm):
    """The second crank's angle: its own at the first crank's stated angle, turning with
    the first at the ratio of their speeds."""
    return prm[1] + (prm[2] / prm[5]) * (ctx.theta - prm[4])
