"""A collar driven along the turning crank as the second input (two degrees of freedom):
"rod OA turns at 3 rad/s ccw while collar C slides out along it at 2 m/s, accelerating at
1 m/s^2". The crank turns the rod; the collar's place along the rod (s = KC from the rod's
pivot K towards its other end N), its sliding vs relative to the rod and its rate are given
(``[input.second] block = "C"``).

Position: ``C = K + s w``, w the rod's unit direction K -> N; over a sweep of the crank the
collar slides with it at the ratio of their speeds, ``s = s0 + (vs / omega1)(theta -
theta0)`` (both driven at their stated rates). Velocity: the rod's point under C moves at
``omega_r perp(KC)`` (:func:`.relations.rigid_velocity`), the collar slides on it at ``vs
w``: ``v_C = omega_r perp(KC) + vs w``. Acceleration: ``a_C = -omega_r^2 KC + alpha_r
perp(KC) + 2 omega_r vs perp(w) + as w`` (:func:`.relations.rigid_acceleration`, the
Coriolis component :func:`.relations.coriolis`). The velocities are linear in the two
inputs: the polygon for both is the sum of the polygons for each alone (superposition).

>>> position(0.0, 0.0, 0.6, 0.8, 0.5)
(0.3, 0.4)
>>> [round(c, 12) for c in velocity(0.3, 0.4, 0.6, 0.8, 2.0, 1.0)]   # 2 rad/s ccw, out at 1 m/s
[-0.2, 1.4]
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..common.errors import MobilityError
from ..common.numbers import in_units
from ..common.tolerances import LEAST_REACH
from .base import Construction, DirectionLine, Step, Vector, absolute, add, image_label, sub, unit
from .relations import coriolis, rigid_acceleration, rigid_velocity
from .slotted import under_label

__all__ = ["SecondCollar", "second_collar", "position", "velocity", "acceleration"]


def position(kx, ky, wx, wy, s):
    """C = K + s w."""
    return kx + s * wx, ky + s * wy


def velocity(dx, dy, wx, wy, w_r, vs):
    """v_C = omega_r perp(d) + vs w, d = C - K (K fixed)."""
    vx, vy = rigid_velocity(dx, dy, w_r)
    return vx + vs * wx, vy + vs * wy


def acceleration(dx, dy, wx, wy, w_r, al_r, vs, a_s):
    """(a_Cx, a_Cy, corx, cory): a_C = -omega_r^2 d + alpha_r perp(d) + 2 omega_r vs
    perp(w) + as w, and the Coriolis component."""
    ax, ay = rigid_acceleration(dx, dy, w_r, al_r)
    cx, cy = coriolis(w_r, vs, wx, wy)
    return ax + cx + a_s * wx, ay + cy + a_s * wy, cx, cy


@dataclass(frozen=True)
class SecondCollar(Step):
    """C = K + s w on the crank's rod K-N, s following the crank at the ratio of the speeds;
    v_C = omega_r perp(KC) + vs w; a_C adds the Coriolis component and as w (see the
    module). The plan's second step where a collar slides along the crank as the second
    input."""

    point: str
    rod: str
    pivot: str
    end: str
    rod_length: float
    s: float = 0.0  # the collar's place at the scene's instant (m, outward)
    vs: float = 0.0
    a_s: float = 0.0
    angle1: float = 0.0  # the first crank's angle at the scene's instant
    omega1: float = 1.0  # the first crank's speed (the ratio over a sweep)
    sense_first: float = 1.0  # +1 where the [sliders] guide runs K -> N, else -1

    kind = "second collar"

    @property
    def finds(self):
        return (self.point,)

    @property
    def links(self):
        return ()

    @property
    def needs(self):
        return (self.pivot, self.end)

    @property
    def needs_links(self):
        return (self.rod,)

    @property
    def title(self):
        return f"collar {self.point} sliding along {self.rod} (the second input)"

    @property
    def params(self):
        return (self.s, self.vs, self.a_s, self.angle1, self.omega1)

    def dimensions(self, scene, bodies):
        two, one = scene.input.second, scene.input
        return (two.angle, two.omega, two.alpha, one.angle, one.omega)

    def held(self, prm):
        """Its dimensions with its own motion held (the first input alone)."""
        return (prm[0], 0.0, 0.0) + tuple(prm[3:])

    def reach(self):
        return max(self.rod_length, LEAST_REACH)

    def place(self, P, prm, ctx, sigma=None):
        (kx, ky), (nx, ny) = P[self.pivot], P[self.end]
        L = math.hypot(nx - kx, ny - ky)
        x, y = position(kx, ky, (nx - kx) / L, (ny - ky) / L, _s(ctx, prm))
        return x, y, 1.0

    def bind(self, prm):
        """The step's three phases for dimensions ``prm``: functions of a State."""
        C, K, N, rod, i, L, e = (
            self.point,
            self.pivot,
            self.end,
            self.rod,
            self.index,
            self.rod_length,
            self.sense_first,
        )
        vs, a_s = prm[1], prm[2]

        def frame(m):
            (kx, ky), (nx, ny), (cx, cy) = m.P[K], m.P[N], m.P[C]
            return cx - kx, cy - ky, (nx - kx) / L, (ny - ky) / L

        def position_(m):
            (kx, ky), (nx, ny) = m.P[K], m.P[N]
            m.P[C] = position(kx, ky, (nx - kx) / L, (ny - ky) / L, _s(m.ctx, prm))
            m.cond[i] = 1.0

        def velocity_(m):
            dx, dy, wx, wy = frame(m)
            vx, vy = velocity(dx, dy, wx, wy, m.W[rod], vs)
            m.V[C] = (m.V[K][0] + vx, m.V[K][1] + vy)
            m.S[C] = [e * vs, None, 0.0, 0.0]

        def acceleration_(m):
            dx, dy, wx, wy = frame(m)
            ax, ay, cx, cy = acceleration(dx, dy, wx, wy, m.W[rod], m.Al[rod], vs, a_s)
            m.A[C] = (m.A[K][0] + ax, m.A[K][1] + ay)
            sl = m.S[C]
            sl[1], sl[2], sl[3] = e * a_s, cx, cy

        return position_, velocity_, acceleration_

    # ----- the second input's words (a second crank's are in its own room)
    def sense(self, value):
        """Which way a signed value along the rod points: outward (from the pivot)."""
        return "outward" if value >= 0 else f"towards {self.pivot}"

    def second_record(self, scene):
        """The JSON ``input.second``: the collar, its rod, its place and sliding (SI,
        signed outward)."""
        two = scene.input.second
        return {
            "block": self.point,
            "collar": True,
            "rod": self.rod,
            "pivot": self.pivot,
            "s": two.angle,
            "vs": two.omega,
            "as": two.alpha,
            "sense": "outward",
        }

    def second_words(self, scene):
        """The second input in words: the collar's place and its sliding on the rod."""
        two = scene.input.second
        return (
            f"collar {self.point} at {self.pivot}{self.point} = "
            f"{in_units(two.angle, scene.length_unit)} {scene.units} on {self.rod}, "
            f"sliding at {abs(two.omega):.6g} m/s {self.sense(two.omega)} relative to the "
            "rod"
            + (
                f", accelerating at {abs(two.alpha):.6g} m/s^2 {self.sense(two.alpha)}"
                if two.alpha
                else ", steadily"
            )
        )

    def coriolis_left_out(self, sol):
        """The collar's acceleration drawn without its Coriolis component: a_C - 2 omega_r
        vs perp(w) (what the points after it then get is not followed)."""
        (ax, ay), (cx, cy) = sol.A[self.point], sol.coriolis(self.point)
        return {("a", self.point): math.hypot(ax - cx, ay - cy)} if cx or cy else {}

    # ----- words
    def singular_why(self, c) -> str:
        return f"the collar {self.point} is never singular (condition {c:.2g})"

    def warning(self, c) -> str:
        return f"{self.label}: condition {c:.3g}"

    def limit_why(self) -> str:
        return f"the collar {self.point} reaches the end of its rod"

    def condition_column(self):
        return None

    def transmission(self):
        return None

    def bodies(self):
        return (f"block {self.point}",)

    def orient(self):
        return {}

    def position_words(self, L, which, angle_deg):
        return (
            f"{self.point}: on the rod {self.rod}, {self.pivot}{self.point} = "
            f"{L(abs(self.s))} from {self.pivot} "
            f"{'towards' if self.s >= 0 else 'away from'} {self.end} (the second input)"
        )

    # ----- the polygons
    def construction(self, sol, ph):
        P, C, K, N = sol.P, self.point, self.pivot, self.end
        lab = lambda p: image_label(sol, p, ph)  # noqa: E731
        d = sub(P[C], P[K])
        w = unit(*sub(P[N], P[K]))
        c1 = under_label(sol, C, ph)
        s = sol.S[C]
        vs, a_s = s[0] * self.sense_first, s[1] * self.sense_first
        w_r, al_r = sol.W[self.rod], sol.Al[self.rod]
        if ph == "velocity":
            V = sol.V
            under = add(V[K], rigid_velocity(d[0], d[1], w_r))
            text = (
                f"{c1}, the image of the rod's point under {C}, divides {lab(K)}{lab(N)} "
                f"as {C} divides {K}{N} ({lab(K)}{c1} / {lab(K)}{lab(N)} = {K}{C} / "
                f"{K}{N}); the collar {C} slides along {self.rod} at {abs(vs):.4g} m/s "
                f"{self.sense(vs)}: from {c1} draw {c1}{lab(C)} = {abs(vs):.4g} m/s along "
                f"{self.rod}"
            )
            found = (
                Vector(
                    V[K], under, f"{lab(K)}{c1}", "relative", f"v of the rod's point under {C}", ""
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
            )
            return Construction(
                self.index, self.title, ph, lab(C), V[C], (), (), found, text, 1.0, ((c1, under),)
            )
        A = sol.A
        under = add(A[K], rigid_acceleration(d[0], d[1], w_r, al_r))
        cor = sol.coriolis(C)
        after = add(under, cor)
        text = (
            f"{c1}' divides {lab(K)}{lab(N)} as {C} divides {K}{N}; from it draw the "
            f"Coriolis component 2 omega_{self.rod} vs = {math.hypot(*cor):.4g} m/s^2 "
            f"perpendicular to {self.rod}, then the sliding acceleration "
            f"{abs(a_s):.4g} m/s^2 {self.sense(a_s)} along it: its end is {lab(C)}"
        )
        given = (
            Vector(
                under,
                after,
                "cor",
                "coriolis",
                f"Coriolis at {C}",
                f"2 omega_{self.rod} vs = {math.hypot(*cor):.4g} m/s^2, perpendicular "
                f"to {self.rod}",
            ),
        )
        found = (
            Vector(
                after, A[C], "s", "sliding", f"as_{C}", "the collar's sliding acceleration, given"
            ),
            absolute(sol, C, A, ph),
        )
        lines = (
            DirectionLine(
                after,
                w,
                "the end of the Coriolis component",
                f"along {self.rod}",
                mark=f"\u2225 {self.rod}",
            ),
        )
        return Construction(
            self.index, self.title, ph, lab(C), A[C], given, lines, found, text, 1.0, ((c1, under),)
        )


def second_collar(g, two):
    """The second input's step (``g`` the compiler, ``two`` the second input): a collar
    sliding along the crank that the first input turns; refused in one line otherwise."""
    sc, inp = g.scene, g.scene.input
    sl = sc.slider(two.block)
    rod = sc.link(sl.guide)
    if rod.key != sc.link(inp.crank).key:
        raise MobilityError(
            f"the second input's collar {two.block} slides along {rod.key}, "
            f"which is not the crank {inp.crank}: a collar as the second "
            "input slides along the crank that the first input turns",
            file=sc.file,
            key="[input.second] block",
        )
    K = rod.p if rod.p in sc.ground else rod.q
    g.used_sliders.add(sl.key)
    return SecondCollar(
        1,
        two.block,
        rod.key,
        K,
        rod.other(K),
        rod.length,
        two.angle,
        two.omega,
        two.alpha,
        inp.angle,
        inp.omega,
        1.0 if sl.first == K else -1.0,
    )


def _s(ctx, prm):
    """The collar's place: its own at the first crank's stated angle, sliding with the
    crank at the ratio of their rates."""
    return prm[0] + (prm[1] / prm[4]) * (ctx.theta - prm[3])
