"""The driving collar: a collar C driven along a rod K-N that turns about its fixed pivot
K, its place along the rod (s = KC, from the pivot towards N), its sliding velocity
relative to the rod and the rate of it given; C is pinned to a link DC turning about the
fixed pivot D (the inverted slider crank driven by its sliding: "the collar slides along
the rod OA at 1.5 m/s relative to it"). The motion's parameter is s, as a driving block's
place along its fixed guide (:mod:`.block`).

Position: C is at |s| from K and at |DC| from D: a dyad's two circles (:func:`.dyad.place`,
the branch ``sigma``); the rod's direction w = (C - K) / s, its other end N = K + |KN| w.

Velocity: the rod's point under C (C1) moves at ``w_r perp(d1)``, d1 = C - K = s w, and the
collar slides on it at ``vs w``, so ``v_C = vs w + w_r perp(d1) = w_D perp(d2)``, d2 = C - D:
the dyad's relation with the sliding as its first point's velocity (:func:`.dyad.velocity`).

Acceleration: ``a_C = -w_r^2 d1 + al_r perp(d1) + 2 w_r vs perp(w) + as w = -w_D^2 d2 +
al_D perp(d2)``: the dyad's relation with the Coriolis component (:func:`.relations.coriolis`)
and the given sliding acceleration as its first point's (:func:`.dyad.acceleration`).

Condition: the dyad's, |sin| of the angle KCD, times min(1, |s| / |DC|): zero where the
rod's line passes through D (a dead centre: the sliding cannot change s there) and where
the collar is at the rod's pivot (the rod's direction is undefined).

Beyond the step contract it answers what the views ask where a step has it:
``problem_words`` (the problem's sentence), ``body_omega_source`` (the rod's omega is found,
not given) and ``coriolis_left_out`` (the checker's diagnosis).

>>> x, y, c = place(0.0, 0.0, 2.0, 0.0, 2 ** 0.5, 2 ** 0.5, 1.0, 2 ** 0.5)
>>> round(x, 12), round(y, 12), round(c, 12)
(1.0, 1.0, 1.0)
>>> w_r, w_d, vx, vy = velocity(1.0, 1.0, -1.0, 1.0, 2 ** -0.5, 2 ** -0.5, 2 ** 0.5)
>>> round(w_r, 12), round(w_d, 12)       # sliding out at 1.414 m/s along (1, 1)/1.414
(0.0, -1.0)
>>> round(vx, 12), round(vy, 12)   # along the rod, square to DC: the rod need not turn
(1.0, 1.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..common.errors import TOL, MobilityError, SingularStepError
from ..common.numbers import in_units
from ..common.tolerances import LEAST_REACH
from ..scene import GuideSlider
from . import collar_polygons, dyad
from .base import (
    Step,
    sub,
)
from .block import BlockDriver, at_rest_rate
from .relations import coriolis, rigid_acceleration, rigid_velocity

__all__ = ["CollarDriver", "place", "velocity", "acceleration", "driver", "is_collar"]


def place(kx, ky, dx, dy, s, r, sigma, rho, ctx=None, step=None):
    """C at |s| from K and r from D, on the side ``sigma`` of K -> D (the dyad's two
    circles); its condition the dyad's times min(1, |s| / rho)."""
    a = abs(s)
    x, y, c = dyad.place(kx, ky, dx, dy, a, r, sigma, ctx, step)
    k = a / rho
    return x, y, c * (ctx.minimum(k, 1.0) if ctx is not None else min(k, 1.0))


def velocity(d1x, d1y, d2x, d2y, wx, wy, vs, d=None):
    """(w_r, w_D, vCx, vCy): the rod's and the link DC's omega and the collar's velocity,
    from d1 = C - K, d2 = C - D, the rod's unit direction w and the sliding vs along it."""
    return dyad.velocity(d1x, d1y, d2x, d2y, vs * wx, vs * wy, 0.0, 0.0, d)


def acceleration(d1x, d1y, d2x, d2y, wx, wy, vs, a_s, w_r, w_d, d=None):
    """(al_r, al_D, aCx, aCy, corx, cory): the rod's and DC's alpha, the collar's
    acceleration and the Coriolis component 2 w_r vs perp(w)."""
    cx, cy = coriolis(w_r, vs, wx, wy)
    out = dyad.acceleration(d1x, d1y, d2x, d2y, w_r, w_d, a_s * wx + cx, a_s * wy + cy, 0.0, 0.0, d)
    return out + (cx, cy)


def driver(g, scene, mobility):
    """The collar driver of a scene whose ``[input] block`` slides along a moving rod (``g``
    the compiler): its rod pivoted on the frame, the collar pinned to one link about a
    fixed pivot. A one-line refusal otherwise."""
    name = scene.input.block
    sl = scene.slider(name)
    rod = scene.link(sl.guide)
    ground = scene.ground
    pivots = [p for p in rod.points if p in ground]
    key = f"[sliders] {name}"
    if len(pivots) != 1:
        raise MobilityError(
            f"the collar {name} is driven along the rod {rod.key}, which is pivoted on the "
            f"frame at {'both ends: it cannot turn' if pivots else 'neither end'}: a driving "
            "collar's rod turns about one fixed pivot (put it in [ground]); a collar on a "
            "rod that a linkage moves is a second input ([input.second] block, beside a "
            "crank)",
            file=scene.file,
            key=key,
        )
    K = pivots[0]
    N = rod.other(K)
    links = [lk for lk in scene.links if name in lk.points and lk.key != rod.key]
    to_ground = [lk for lk in links if lk.other(name) in ground]
    if len(to_ground) != 1:
        m = mobility(scene)
        raise MobilityError(
            f"mobility {m} (Gruebler: 3(n-1) - 2j): the collar {name}'s sliding along "
            f"{rod.key} sets one motion; the rod's turning needs one more relation: pin "
            f"{name} to a link about a fixed pivot (an inverted slider crank)"
            + (
                ', or drive the rod too: [input] crank = "' + rod.key + '" with the '
                f'collar as [input.second] block = "{name}"'
                if m == 2
                else ""
            ),
            file=scene.file,
            key=key,
        )
    crank = to_ground[0]
    D = crank.other(name)
    if D == K:
        raise MobilityError(
            f"the link {crank.key} joins the collar {name} to the rod's own "
            f"pivot {K}: the collar cannot slide",
            file=scene.file,
            key=key,
        )
    return CollarDriver(
        0,
        point=name,
        rod=rod.key,
        pivot=K,
        end=N,
        rod_length=rod.length,
        link=crank.key,
        fixed=D,
        length=crank.length,
        sense_first=1.0 if sl.first == K else -1.0,
        unit=g.unit,
        uname=g.uname,
        origin=K,
    )


@dataclass(frozen=True)
class CollarDriver(BlockDriver):
    """C at |s| from K on the rod K-N and at |DC| from D; v_C = vs w + w_r perp(KC) =
    w_D perp(DC); a_C adds the Coriolis component and the sliding acceleration (see the
    module). The plan's first step where a collar is driven along its rod."""

    point: str = ""
    rod: str = ""
    pivot: str = ""
    end: str = ""  # the rod's other end N
    rod_length: float = 0.0
    link: str = ""  # the link DC
    fixed: str = ""  # its fixed pivot D
    length: float = 0.0
    sense_first: float = 1.0  # +1 where the rod's [sliders] guide runs K -> N, else -1
    sigma: float = 1.0
    unit: float = 1e-3
    uname: str = "mm"
    path: object = None
    origin: str = ""

    kind = "collar"
    branching = True
    error_bound = Step.error_bound  # the rule of two direction lines (a dyad's)
    rounding = 48.0

    @property
    def finds(self):
        return (self.point, self.end)

    @property
    def links(self):
        return (self.rod, self.link)

    @property
    def needs(self):
        return (self.pivot, self.fixed)

    @property
    def title(self):
        return f"collar {self.point} on the rod {self.rod}"

    @property
    def where(self):
        """The collar's guide in words: its rod."""
        return f"the rod {self.rod}"

    @property
    def params(self):
        return (self.length, self.rod_length)

    def dimensions(self, scene, bodies):
        return (scene.link(self.link).length, scene.link(self.rod).length)

    def drawn(self, prm, pencil, P):
        return (prm[0] + pencil(), prm[1] + pencil())

    def reach(self):
        return max(self.length, self.rod_length, LEAST_REACH)

    def default_hint(self, P):
        return "above"

    def place(self, P, prm, ctx, sigma=None):
        (kx, ky), (dx, dy) = P[self.pivot], P[self.fixed]
        s = self.sigma if sigma is None else sigma
        return place(kx, ky, dx, dy, ctx.theta, prm[0], s, prm[0], ctx, self)

    def assemble(self, g):
        """The branch as a dyad's (the [assembly] hint of C), and the rod's other end."""
        s = g.ctx.theta
        if abs(s) <= TOL.singular * self.length:
            raise self.at_pivot()
        step, (x, y) = g.choose_branch(self)
        (kx, ky) = g.P[self.pivot]
        f = self.rod_length / s
        return step, {self.point: (x, y), self.end: (kx + f * (x - kx), ky + f * (y - ky))}

    def positions(self, P, ctx):
        """Place the collar and the rod's other end into ``P`` (at the plan's dimensions)."""
        x, y, c = self.place(P, self.params, ctx)
        kx, ky = P[self.pivot]
        f = self.rod_length / ctx.theta
        P[self.point] = (x, y)
        P[self.end] = (kx + f * (x - kx), ky + f * (y - ky))
        ctx.cond[self.index] = c

    def bind(self, prm):
        """The step's three phases for dimensions ``prm``: functions of a State."""
        C, K, N, D, i, step = self.point, self.pivot, self.end, self.fixed, self.index, self
        rod, link, e, sigma = self.rod, self.link, self.sense_first, self.sigma
        r, L = prm

        def frame(m):
            (kx, ky), (cx, cy), (dx, dy) = m.P[K], m.P[C], m.P[D]
            s = m.ctx.theta
            if m.array:
                s = m.ctx.safe(s, step)
            d1x, d1y = cx - kx, cy - ky
            return d1x, d1y, cx - dx, cy - dy, d1x / s, d1y / s

        def position(m):
            ctx = m.ctx
            s = ctx.theta
            (kx, ky), (dx, dy) = m.P[K], m.P[D]
            if not m.array and abs(s) <= TOL.singular * r:
                raise step.at_pivot()
            x, y, c = place(kx, ky, dx, dy, s, r, sigma, r, ctx, step)
            if m.array:
                s = ctx.safe(s, step)
            f = L / s
            m.P[C] = (x, y)
            m.P[N] = (kx + f * (x - kx), ky + f * (y - ky))
            m.cond[i] = c

        def velocity_(m):
            d1x, d1y, d2x, d2y, wx, wy = frame(m)
            d = d1x * d2y - d1y * d2x
            if m.array:
                d = m.ctx.safe(d, step)
            vs = m.ctx.omega
            w_r, w_d, vx, vy = velocity(d1x, d1y, d2x, d2y, wx, wy, vs, d)
            m.W[rod], m.W[link] = w_r, w_d
            m.V[C] = (vx, vy)
            (kx, ky), (nx, ny) = m.P[K], m.P[N]
            m.V[N] = rigid_velocity(nx - kx, ny - ky, w_r)
            m.S[C] = [e * vs, None, 0.0, 0.0]

        def acceleration_(m):
            d1x, d1y, d2x, d2y, wx, wy = frame(m)
            d = d1x * d2y - d1y * d2x
            if m.array:
                d = m.ctx.safe(d, step)
            vs, a_s = m.ctx.omega, m.ctx.alpha
            w_r, w_d = m.W[rod], m.W[link]
            al_r, al_d, ax, ay, cx, cy = acceleration(
                d1x, d1y, d2x, d2y, wx, wy, vs, a_s, w_r, w_d, d
            )
            m.Al[rod], m.Al[link] = al_r, al_d
            m.A[C] = (ax, ay)
            (kx, ky), (nx, ny) = m.P[K], m.P[N]
            m.A[N] = rigid_acceleration(nx - kx, ny - ky, w_r, al_r)
            sl = m.S[C]
            sl[1], sl[2], sl[3] = e * a_s, cx, cy

        return position, velocity_, acceleration_

    def bind_instant(self, prm):
        """The three phases in a row for one instant, the rod's frame made once: the same
        formulas on the same numbers as :meth:`bind` (equal to the last bit)."""
        C, K, N, D, i, step = self.point, self.pivot, self.end, self.fixed, self.index, self
        rod, link, e, sigma = self.rod, self.link, self.sense_first, self.sigma
        r, L = prm
        small = TOL.singular

        def instant(m):
            ctx, P = m.ctx, m.P
            s, vs, a_s = ctx.theta, ctx.omega, ctx.alpha
            (kx, ky), (dx, dy) = P[K], P[D]
            if abs(s) <= small * r:
                raise step.at_pivot()
            x, y, c = place(kx, ky, dx, dy, s, r, sigma, r, ctx, step)
            f = L / s
            P[C] = (x, y)
            P[N] = (nx, ny) = (kx + f * (x - kx), ky + f * (y - ky))
            m.cond[i] = c
            if c < small:
                raise step.singular(c)
            d1x, d1y, d2x, d2y = x - kx, y - ky, x - dx, y - dy
            wx, wy = d1x / s, d1y / s
            d = d1x * d2y - d1y * d2x
            w_r, w_d, vx, vy = velocity(d1x, d1y, d2x, d2y, wx, wy, vs, d)
            m.W[rod], m.W[link] = w_r, w_d
            m.V[C] = (vx, vy)
            m.V[N] = rigid_velocity(nx - kx, ny - ky, w_r)
            al_r, al_d, ax, ay, cx, cy = acceleration(
                d1x, d1y, d2x, d2y, wx, wy, vs, a_s, w_r, w_d, d
            )
            m.Al[rod], m.Al[link] = al_r, al_d
            m.A[C] = (ax, ay)
            m.A[N] = rigid_acceleration(nx - kx, ny - ky, w_r, al_r)
            m.S[C] = [e * vs, e * a_s, cx, cy]

        return instant

    # ----- the driver protocol (the rest is the driving block's)
    def parameter(self, scene) -> tuple:
        """(name, symbol, unit): the collar's place along its rod from the pivot."""
        return (f"place of collar {self.point} on {self.rod}", f"s_{self.point}", f" {scene.units}")

    def parameter_scale(self, scene) -> float:
        """The length along the rod that plays the part of a crank's radian: the link DC's
        (no more than a stated stroke over 2 pi)."""
        scale = self.length
        stroke = scene.input.stroke
        if stroke is not None and stroke[1] != stroke[0]:
            scale = min(scale, abs(stroke[1] - stroke[0]) / (2.0 * math.pi))
        return scale

    def input_record(self, scene):
        """The JSON ``input``: the collar, its rod and pivot, its place s from the pivot,
        its sliding velocity vs and acceleration as relative to the rod (SI, signed
        outward: from the pivot towards the rod's other end), its stated stroke."""
        inp = scene.input
        d = {
            "block": self.point,
            "collar": True,
            "rod": self.rod,
            "pivot": self.pivot,
            "s": inp.angle,
            "vs": inp.omega,
            "as": inp.alpha,
            "sense": "outward",
        }
        if inp.stroke is not None:
            d["stroke"] = list(inp.stroke)
        return d

    travel = "the collar's travel along its rod"

    def drive_caption(self, scene):
        inp = scene.input
        return (
            f"collar {self.point} at {self.pivot}{self.point} = "
            f"{in_units(inp.angle, scene.length_unit)} {scene.units}, sliding "
            f"{abs(inp.omega):.4g} m/s {self.sense(inp.omega)} along {self.rod}"
            + (f", {abs(inp.alpha):.4g} m/s² {self.sense(inp.alpha)}" if inp.alpha else "")
        )

    def input_words(self, scene):
        """The printed solution's line for the input: the collar's place on its rod and
        its sliding relative to the rod."""
        inp, u = scene.input, scene.length_unit
        vs, a_s = inp.omega, inp.alpha
        words = (
            f"collar {self.point} on the rod {self.rod} (pivoted at {self.pivot}) at "
            f"s_{self.point} = {self.pivot}{self.point} = {in_units(inp.angle, u)} "
            f"{scene.units}, "
        )
        if scene.at_rest:  # nothing moves: the sense it is about to slide in
            return words + f"about to slide {self.sense(vs)} along the rod"
        words += f"sliding at {abs(vs):.6g} m/s {self.sense(vs)} relative to the rod"
        return words + (
            f", accelerating at {abs(a_s):.6g} m/s^2 {self.sense(a_s)}" if a_s else ", steadily"
        )

    def effort_words(self, effort):
        """The force the rod exerts on the collar along the rod, from the power balance
        (F vs + sum of the loads' powers = 0: vs the sliding relative to the rod)."""
        return (
            f"input force on collar {self.point}: {abs(effort):.4g} N "
            f"{self.sense(effort)} along {self.rod} (power balance, no friction or "
            "inertia)"
        )

    @property
    def virtual_unit(self):
        """What the motion is solved per at rest: the collar's sliding along its rod."""
        return f"1 m/s of the collar {self.point} along its rod"

    @property
    def driver_name(self):
        """Body 2 of the centres' numbering: the rod the collar is driven along."""
        return f"the rod {self.rod}, along which the collar {self.point} is driven,"

    def body_omega(self, sol):
        """The rod's omega (body 2 of the centres: it turns about its fixed pivot)."""
        return sol.W[self.rod]

    body_omega_source = "the rod's, from the collar's given sliding by the velocity polygon"

    def input_items(self, scene, fmt):
        """The step table's input section: the collar's sliding relative to its rod."""
        inp, C = scene.input, self.point
        vs, a_s = inp.omega, inp.alpha
        along = f"along {self.rod}, relative to the rod (given)"
        return (
            f"Input collar {C} on the rod {self.rod}",
            (
                f"vs_{C} = {fmt(abs(vs))} m/s {self.sense(vs)} {along}",
                f"as_{C} = {fmt(abs(a_s))} m/s^2 {self.sense(a_s)} {along}"
                if a_s
                else f"as_{C} = 0 {at_rest_rate(scene, '1 m/s', f'as_{C}')}"
                if scene.at_rest
                else f"as_{C} = 0 (the collar slides at a steady speed along the rod)",
            ),
        )

    def problem_words(self, scene):
        """The problem's sentence: the rod, the collar's place and its sliding on the rod."""
        inp, u = scene.input, scene.length_unit
        vs, a_s = inp.omega, inp.alpha
        return (
            f"The collar {self.point} slides along the rod {self.rod}, which turns about "
            f"the fixed pivot {self.pivot}; {self.point} is pinned to the link "
            f"{self.link} about the fixed pivot {self.fixed}. At the instant shown the "
            f"collar is {abs(inp.angle) / u:.10g} {scene.units} from {self.pivot}, "
            + (
                f"at rest, about to slide {self.sense(vs)} along the rod"
                if scene.at_rest
                else f"sliding at {abs(vs):.10g} m/s {self.sense(vs)} relative to the rod"
            )
            + (
                f", with an acceleration of {abs(a_s):.10g} m/s² {self.sense(a_s)} relative to it"
                if a_s
                else ""
                if scene.at_rest
                else ", steadily"
            )
            + "."
        )

    def parameter_words(self):
        return f"the place s_{self.point} of the collar {self.point} along its rod {self.rod}"

    def rates(self, scene):
        """(vs, as) the collar is driven at along its rod: the scene's input."""
        return scene.input.omega, scene.input.alpha

    def sense(self, value):
        """Which way a signed value along the rod points: outward (from the pivot)."""
        return "outward" if value >= 0 else f"towards {self.pivot}"

    # ----- words
    def at_pivot(self):
        """The error for a collar at the rod's pivot: the rod's direction is undefined."""
        return SingularStepError(
            f"the collar {self.point} is at {self.pivot}, the pivot of "
            f"the rod {self.rod} (condition 0: {self.pivot}{self.point} "
            f"/ {self.link} = 0): the rod's direction is undefined",
            step=self.label,
        )

    def why(self, e):
        """Why the collar cannot be at this place: the arcs about the two pivots ``e`` apart
        do not meet (beyond a dead centre)."""
        u, n = self.unit, self.uname
        return (
            f"the collar {self.point} cannot be at this place on {self.rod}: "
            f"{self.fixed}{self.point} = {in_units(self.length, u)} {n} "
            f"and {self.pivot}{self.fixed} = {in_units(e, u)} {n} let it be only from "
            f"{in_units(abs(e - self.length), u)} to {in_units(e + self.length, u)} {n} "
            "(its dead centres)"
        )

    def coincident(self):
        """The error where the rod's pivot and the link's coincide."""
        return SingularStepError(
            f"the pivots {self.pivot} and {self.fixed} coincide: the collar cannot slide",
            step=self.label,
        )

    def coriolis_left_out(self, sol):
        """What a polygon drawn without the Coriolis component gives: {(kind, name):
        value} for the rod's and DC's alpha (signed) and the sizes of a_C and a_N. The
        two tangential lines then close ``cor`` less: ``x perp(d1) - y perp(d2) = cor``,
        the rod's alpha moved by x, DC's by y."""
        P, C, K, D, N = sol.P, self.point, self.pivot, self.fixed, self.end
        d1, d2 = sub(P[C], P[K]), sub(P[C], P[D])
        cx, cy = sol.coriolis(C)
        if cx == 0 and cy == 0:
            return {}
        d = d1[0] * d2[1] - d1[1] * d2[0]
        x, y = (cx * d2[0] + cy * d2[1]) / d, (cx * d1[0] + cy * d1[1]) / d
        rn = sub(P[N], P[K])
        aC, aN = sol.A[C], sol.A[N]
        return {
            ("alpha", self.rod): sol.Al[self.rod] + x,
            ("alpha", self.link): sol.Al[self.link] + y,
            ("a", C): math.hypot(aC[0] - y * d2[1], aC[1] + y * d2[0]),
            ("a", N): math.hypot(aN[0] - x * rn[1], aN[1] + x * rn[0]),
        }

    def singular_why(self, c) -> str:
        return (
            f"the collar {self.point} is at the rod's pivot {self.pivot}, or the rod "
            f"{self.rod}'s line passes through {self.fixed} (a dead centre: {self.pivot}, "
            f"{self.point}, {self.fixed} in line, condition {c:.2g}): sliding along the "
            f"rod cannot move {self.point} there, the rod's speed would be unbounded"
        )

    def warning(self, c) -> str:
        return (
            f"{self.label}: near a dead centre of the collar ({self.pivot}, {self.point}, "
            f"{self.fixed} nearly in line, or {self.point} near {self.pivot}; condition "
            f"{c:.3g})"
        )

    def limit_why(self) -> str:
        return (
            f"the collar {self.point} reaches a dead centre: the rod {self.rod}'s line "
            f"passes through {self.fixed}"
        )

    def condition_column(self):
        return (
            f"cond step {self.index + 1}",
            "1",
            f"|sin {self.pivot}{self.point}"
            f"{self.fixed}| x min(1, {self.pivot}{self.point} / {self.link})",
        )

    def transmission(self):
        return None

    def bodies(self):
        return (self.rod, f"block {self.point}", self.link)

    def orient(self):
        return {self.rod: (self.end, self.pivot), self.link: (self.point, self.fixed)}

    def output(self, ground):
        return None

    def position_words(self, L, which, place):
        return (
            f"{self.point}: an arc about {self.pivot} of radius {self.pivot}{self.point} = "
            f"{place} and an arc about {self.fixed} of radius {self.fixed}{self.point} = "
            f"{L(self.length)} meet at {self.point} ({which(self.point)}); the rod {self.rod} is the "
            f"line from {self.pivot} through {self.point}, {self.pivot}{self.end} = "
            f"{L(self.rod_length)}"
        )

    # ----- the polygons
    def construction(self, sol, ph):
        return collar_polygons.construction(self, sol, ph)


def is_collar(scene) -> bool:
    """Whether the scene's driving block slides along a moving rod (a collar)."""
    name = scene.input.block
    return (
        name is not None
        and scene.input.wheel is None
        and isinstance(scene.slider(name), GuideSlider)
    )
