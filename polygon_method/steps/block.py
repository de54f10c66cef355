"""The driving block: a block on a fixed straight guide whose place along it is the
motion's parameter (an ellipse trammel driven by its block A, two blocks driven along
their paths): no link of the mechanism need turn about the frame.

Position: ``X = Q + s u`` (Q the guide's through point, u its unit direction, s the
parameter: the plan's input ``theta``). Velocity: ``v_X = vs u`` (oa along the guide, of the
given size: the plan's input ``omega``). Acceleration: ``a_X = as u`` (the given rate: the
plan's input ``alpha``; the guide is fixed, so no centripetal and no Coriolis component).

>>> place(0.0, 0.0, 1.0, 0.0, 0.3)
(0.3, 0.0, 1.0)
>>> velocity(0.6, 0.8, 2.0)
(1.2, 1.6)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..common.numbers import in_units
from ..common.tolerances import LEAST_REACH, ROUNDING
from ..scene import FixedPath
from .base import Construction, Step, absolute, image_label
from .rounding import EPS, vhypot

__all__ = ["BlockDriver", "place", "velocity", "acceleration"]


def place(qx, qy, ux, uy, s):
    """X = Q + s u; its condition is 1 (nothing to intersect)."""
    return qx + s * ux, qy + s * uy, 1.0


def velocity(ux, uy, vs):
    """v_X = vs u."""
    return vs * ux, vs * uy


def acceleration(ux, uy, a_s):
    """a_X = as u."""
    return a_s * ux, a_s * uy


def at_rest_rate(scene, unit, name) -> str:
    """The words after a driver's zero rate of speed at rest: the polygons are drawn per
    ``unit`` of the driver (its virtual speed), nothing moves yet (``name``: the rate's
    key, which a start from rest takes in the forces' section).

    >>> from types import SimpleNamespace as NS
    >>> at_rest_rate(NS(start_alpha=0.0), "1 m/s", "as_A")
    'in the polygons per 1 m/s (at rest: nothing moves yet; the virtual velocities)'
    """
    return f"in the polygons per {unit} (at rest: nothing moves yet; " + (
        f"the start's {name} is taken in section 6)"
        if scene.start_alpha
        else "the virtual velocities)"
    )


@dataclass(frozen=True)
class BlockDriver(Step):
    """X = Q + s u; v = vs u; a = as u (see the module). The plan's first step where a
    block drives the mechanism (``[input] block``)."""

    point: str
    path: FixedPath
    origin: str = ""  # the guide's through point in words ("O", "[0, 0] mm")
    unit: float = 1e-3
    uname: str = "mm"

    kind = "block"
    #: the motion's parameter is a length along a guide, not a crank's angle (the driver
    #: protocol: see :attr:`Step.periodic`)
    periodic = False

    @property
    def finds(self):
        return (self.point,)

    @property
    def links(self):
        return ()

    @property
    def needs(self):
        return ()

    @property
    def title(self):
        return f"block {self.point} on {self.where}"

    @property
    def where(self):
        """The guide in words: "the horizontal guide", "the guide at 30 deg"."""
        lab = self.path.label
        return f"the {lab} guide" if lab in ("horizontal", "vertical") else f"the guide {lab}"

    @property
    def params(self):
        (qx, qy), (ux, uy) = self.path.through, self.path.u
        return (qx, qy, ux, uy)

    def dimensions(self, scene, bodies):
        path = scene.slider(self.point)
        (qx, qy), (ux, uy) = path.through, path.u
        return (qx, qy, ux, uy)

    def drawn(self, prm, pencil, P):
        return (prm[0] + pencil(), prm[1] + pencil(), prm[2], prm[3])

    def reach(self):
        (qx, qy) = self.path.through
        return max(abs(qx), abs(qy), LEAST_REACH)

    def place(self, P, prm, ctx, sigma=None):
        return place(prm[0], prm[1], prm[2], prm[3], ctx.theta)

    def bind(self, prm):
        """The step's three phases for dimensions ``prm``: functions of a State."""
        X, i = self.point, self.index
        qx, qy, ux, uy = prm

        def position(m):  # its condition is 1: nothing to intersect
            x, y, _ = place(qx, qy, ux, uy, m.ctx.theta)
            m.P[X] = (x, y)
            m.cond[i] = 1.0

        def velocity_(m):
            vs = m.ctx.omega
            m.V[X] = velocity(ux, uy, vs)
            m.S[X] = [vs, None, 0.0, 0.0]

        def acceleration_(m):
            a_s = m.ctx.alpha
            m.A[X] = acceleration(ux, uy, a_s)
            m.S[X][1] = a_s

        return position, velocity_, acceleration_

    rounding = 8.0

    def error_bound(self, walk, k, p_in, v_in, a_in):
        """X = Q + s u: its position errs by the rounding of Q and s u; its velocity and
        acceleration are the given ones times the unit direction (one rounding each)."""
        P, sizes = walk.P, walk.sizes
        vs, a_s = self.rates(walk.motion.scene)
        qx, qy = self.path.through
        x, y = P[self.point]
        p = self.rounding * EPS * (vhypot(qx, qy) + vhypot(x, y)) / sizes["position"]
        v = self.rounding * EPS * abs(vs) / sizes["velocity"]
        a = self.rounding * EPS * abs(a_s) / sizes["acceleration"]
        return p, v, a, 0.0, 0.0

    def rates(self, scene):
        """(vs, as) the block is driven at: the scene's input."""
        return scene.input.omega, scene.input.alpha

    # ----- the driver protocol
    effort_key = "input_force"  # the force along its guide (N, signed along it)

    def parameter(self, scene) -> tuple:
        """(name, symbol, unit): the block's place along its guide, in the scene's unit."""
        return (f"place of block {self.point}", f"s_{self.point}", f" {scene.units}")

    def parameter_scale(self, scene) -> float:
        """The length along the guide that plays the part of a crank's radian: the
        shortest link pinned to the block (moving the block by that much turns it through
        about a radian; the shortest link of all where none is), and no more than the
        stated stroke over 2 pi (a crank's turn is 2 pi radians)."""
        X = self.point
        own = [lk.length for lk in scene.links if X in (lk.p, lk.q) and lk.length > 0]
        every = [lk.length for lk in scene.links if lk.length > 0]
        scale = min(own or every or [self.reach()])
        stroke = scene.input.stroke
        if stroke is not None and stroke[1] != stroke[0]:
            scale = min(scale, abs(stroke[1] - stroke[0]) / (2.0 * math.pi))
        return scale

    def input_record(self, scene):
        """The JSON ``input``: the block, its place s, velocity vs and acceleration as along
        its guide (SI), the guide's direction and its stated stroke."""
        inp = scene.input
        d = {
            "block": self.point,
            "s": inp.angle,
            "vs": inp.omega,
            "as": inp.alpha,
            "direction": list(scene.slider(self.point).u),
        }
        if inp.stroke is not None:
            d["stroke"] = list(inp.stroke)
        return d

    travel = "the block's travel"

    def drive_caption(self, scene):
        """The line under the drawings: the block's place, its velocity and acceleration."""
        inp = scene.input
        return (
            f"block {self.point} at s = {in_units(inp.angle, scene.length_unit)} "
            f"{scene.units}, {abs(inp.omega):.4g} m/s {self.sense(inp.omega)}"
            + (f", {abs(inp.alpha):.4g} m/s² {self.sense(inp.alpha)}" if inp.alpha else "")
        )

    def input_scales(self, scene):
        """(v, a, omega, alpha): the least sizes of each kind the input sets (the error
        bounds are relative to them): |vs|, |as| of the block, and for turning, the same
        over the longest link L (|vs| / L, vs^2 / L^2 + |as| / L)."""
        vs, a_s = abs(scene.input.omega), abs(scene.input.alpha)
        L = max(lk.length for lk in scene.links)
        return vs, vs * vs / L + a_s, vs / L, (vs * vs / L + a_s) / L

    def input_words(self, scene):
        """The printed solution's line for the input: the block's place, its velocity and
        acceleration along the guide."""
        inp, u = scene.input, scene.length_unit
        vs, a_s = inp.omega, inp.alpha
        words = (
            f"block {self.point} on {self.where} at s_{self.point} = "
            f"{in_units(inp.angle, u)} {scene.units} from {self.origin}, "
        )
        if scene.at_rest:  # nothing moves: the sense it is about to move in
            return words + f"about to move {self.sense(vs)}"
        words += f"moving at {abs(vs):.6g} m/s {self.sense(vs)}"
        return words + (
            f", accelerating at {abs(a_s):.6g} m/s^2 {self.sense(a_s)}" if a_s else ", steadily"
        )

    def effort_words(self, effort):
        """The driving force on the block along its guide, from the power balance
        (F vs + sum of the loads' powers = 0)."""
        return (
            f"input force on block {self.point}: {abs(effort):.4g} N {self.sense(effort)}"
            " along the guide (power balance, no friction or inertia)"
        )

    def parameter_words(self):
        """What the motion's parameter is, in words (a sweep's domain, a table's column)."""
        return f"the place s_{self.point} of the block {self.point} along its guide"

    #: what the motion is solved per where the driver is at rest (its virtual speed)
    virtual_unit = "1 m/s of the block"

    @property
    def driver_name(self):
        """Body 2 of the centres' numbering: the block itself."""
        return f"the driving block {self.point}"

    # ----- words
    def singular_why(self, c) -> str:
        return f"the block {self.point} is never singular (condition {c:.2g})"

    def warning(self, c) -> str:
        return f"{self.label}: condition {c:.3g}"

    def limit_why(self) -> str:
        return f"the block {self.point} reaches the end of its stroke"

    def condition_column(self):
        return None  # its condition is always 1

    def transmission(self):
        return None

    def bodies(self):
        """The bodies this step sets moving, in the textbook's numbering order."""
        return (f"block {self.point}",)

    def orient(self):
        return {}

    def output(self, ground):
        return None

    def position_words(self, L, which, place):
        """The configuration diagram's line for this step (``L`` writes a length; ``place``
        the block's place s, written)."""
        return (
            f"{self.point}: on {self.where} through {self.origin}, {self.point} at "
            f"s_{self.point} = {place} from {self.origin} along it"
        )

    def construction(self, sol, ph):
        X = self.point
        cond = sol.conditions.get(self.index, 1.0)
        lab = image_label(sol, X, ph)
        o = "o" if ph == "velocity" else "o'"
        vs, a_s = sol.S[X][0], sol.S[X][1]
        sense = self.sense
        if ph == "velocity":
            v = absolute(sol, X, sol.V, ph)
            text = (
                f"from {o} draw {o}{lab} = {abs(vs):.4g} m/s along the guide "
                f"({sense(vs)}): the block {X}'s velocity, given"
            )
            return Construction(self.index, self.title, ph, lab, sol.V[X], (), (), (v,), text, cond)
        a = absolute(sol, X, sol.A, ph)
        if a_s:
            text = (
                f"from {o} draw {o}{lab} = {abs(a_s):.4g} m/s^2 along the guide "
                f"({sense(a_s)}): the block {X}'s acceleration, given"
            )
            found = (a,)
        else:
            text = (
                f"{lab} is at {o}: as_{X} = 0 {at_rest_rate(sol.scene, '1 m/s', f'as_{X}')}"
                if sol.scene.at_rest
                else f"{lab} is at {o}: the block {X} moves steadily along its fixed guide (no "
                "acceleration)"
            )
            found = ()
        return Construction(self.index, self.title, ph, lab, sol.A[X], (), (), found, text, cond)

    def sense(self, value):
        """Which way a signed value along the guide points, in the book's words."""
        ux, uy = self.path.u
        if value < 0:
            ux, uy = -ux, -uy
        for (wx, wy), word in (
            ((1, 0), "to the right"),
            ((-1, 0), "to the left"),
            ((0, 1), "upwards"),
            ((0, -1), "downwards"),
        ):
            if abs(ux - wx) < ROUNDING and abs(uy - wy) < ROUNDING:
                return word
        return f"at {math.degrees(math.atan2(uy, ux)) % 360:.4g} deg"
