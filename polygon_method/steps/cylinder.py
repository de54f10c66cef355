"""A hydraulic or pneumatic cylinder: a barrel pivoted at known K, its rod pinned at known R
(windows, dump bodies, excavator arms, landing gear). The step finds no new point: both ends
are placed by the rest of the mechanism; it finds the cylinder's length, its rate of
extension and its rate of change, and how fast barrel and rod turn.

It is a slotted link without a free end (the rod slides in the barrel, which turns about
K), so it uses the slotted link's relations (:mod:`.slotted`): with d = R - K, u = d / |d|,
``vR = vK + w perp(d) + vs u`` and ``aR = aK - w^2 d + al perp(d) + 2 w vs perp(u) + as u``
(the Coriolis component of the rod's end relative to the barrel). On the velocity polygon:
through k a line perpendicular to KR (the barrel's point under R, r1), through r one along
the cylinder; r1 r is the rate of extension.

Condition: min(1, |KR| / the longest link at K or R): a cylinder shrunk to nothing turns
anywhere. A cylinder with a stated ``stroke`` beyond it cannot be assembled.

>>> velocity_of(0.0, 2.0, 1.0, 0.5)   # R 2 above K, moving right at 1 and up at 0.5
(-0.5, 0.5)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..common.errors import TOL, AssemblyError, SingularStepError
from ..common.numbers import in_units
from ..common.tolerances import LEAST_REACH, ROUNDING, SAME
from .base import (
    Construction,
    DirectionLine,
    Step,
    Vector,
    add,
    image_label,
    perp,
    pole_text,
    sub,
    unit,
)
from .rounding import EPS, vhypot, vmax
from .relations import coriolis, rigid_velocity
from .slotted import velocity

__all__ = ["CylinderStep", "velocity_of", "recognise_all"]


def velocity_of(dx, dy, evx, evy):
    """(w, vs) of a cylinder K -> R with d = R - K and e = vR - vK: the barrel's omega and
    the rate of extension (the slotted link's relation with u = d / |d|)."""
    n = (dx * dx + dy * dy) ** 0.5
    ux, uy = dx / n, dy / n
    return velocity(dx, dy, ux, uy, evx, evy)


def _in_stroke(n, stroke) -> bool:
    """Whether the cylinder's length ``n`` lies in its ``stroke`` (least, most), its ends
    reached exactly held to them with the slack of rounding."""
    return stroke[0] * (1 - ROUNDING) <= n <= stroke[1] * (1 + ROUNDING)


def recognise_all(g):
    """The cylinders whose two ends are both known: one step each (added after the points
    are found; nothing in the mechanism depends on them but the given motion)."""
    out = []
    for cyl in g.scene.cylinders:
        if cyl.barrel in g.P and cyl.rod in g.P:
            ref = max(
                [
                    lk.length
                    for lk in g.scene.links
                    if cyl.barrel in lk.points or cyl.rod in lk.points
                ]
                + [LEAST_REACH]
            )
            step = CylinderStep(
                g.next_index + len(out),
                cyl.key,
                cyl.barrel,
                cyl.rod,
                ref,
                cyl.stroke,
                unit=g.unit,
                uname=g.uname,
            )
            n = math.dist(g.P[cyl.barrel], g.P[cyl.rod])
            if cyl.stroke is not None and not _in_stroke(n, cyl.stroke):
                raise AssemblyError(
                    step.why(n) + ": the mechanism cannot be in this position",
                    key=f"[cylinders] {cyl.key}",
                )
            out.append(step)
    return out


@dataclass(frozen=True)
class CylinderStep(Step):
    """A cylinder between known K (barrel pivot) and R (rod end): its length, extension
    rate and acceleration, and the barrel's omega and alpha (see the module)."""

    key: str
    barrel: str
    rod: str
    rho: float
    stroke: tuple | None = None
    unit: float = 1e-3
    uname: str = "mm"

    kind = "cylinder"

    @property
    def finds(self):
        return ()

    @property
    def links(self):
        return (self.key,)

    @property
    def needs(self):
        return (self.barrel, self.rod)

    @property
    def title(self):
        return f"cylinder {self.key}"

    @property
    def params(self):
        return (self.rho,)

    def dimensions(self, scene, bodies):
        return (self.rho,)

    def reach(self):
        return max(self.rho, LEAST_REACH)

    def place(self, P, prm, ctx, sigma=None):
        (kx, ky), (rx, ry) = P[self.barrel], P[self.rod]
        return rx, ry, min(1.0, math.hypot(rx - kx, ry - ky) / prm[0])

    def bind(self, prm):
        K, R, key, i, rho, step = self.barrel, self.rod, self.key, self.index, prm[0], self
        stroke = self.stroke

        def position(m):
            (kx, ky), (rx, ry) = m.P[K], m.P[R]
            n = ((rx - kx) ** 2 + (ry - ky) ** 2) ** 0.5
            if not m.array:
                if n <= TOL.singular * rho:
                    raise step.shrunk()
                if stroke is not None and not _in_stroke(n, stroke):
                    raise AssemblyError(step.why(n), step=step.label)
            elif stroke is not None:
                out = (n < stroke[0] * (1 - ROUNDING)) | (n > stroke[1] * (1 + ROUNDING))
                if out is True or (out is not False and out.any()):
                    m.ctx.fail(step, out)
            m.cond[i] = m.ctx.minimum(n / rho, 1.0)
            m.S[key] = [None, None, 0.0, 0.0]  # vs, as, Coriolis x, y (as a slider's)

        def velocity_(m):
            (kx, ky), (rx, ry) = m.P[K], m.P[R]
            (vkx, vky), (vrx, vry) = m.V[K], m.V[R]
            w, vs = velocity_of(rx - kx, ry - ky, vrx - vkx, vry - vky)
            m.W[key] = w
            m.S[key][0] = vs

        def acceleration_(m):
            (kx, ky), (rx, ry) = m.P[K], m.P[R]
            (akx, aky), (arx, ary) = m.A[K], m.A[R]
            dx, dy = rx - kx, ry - ky
            n = (dx * dx + dy * dy) ** 0.5
            ux, uy = dx / n, dy / n
            w = m.W[key]
            s = m.S[key]
            cx, cy = coriolis(w, s[0], ux, uy)
            k = w * w
            al, a_s = velocity(dx, dy, ux, uy, arx - akx + k * dx - cx, ary - aky + k * dy - cy)
            m.Al[key] = al
            s[1], s[2], s[3] = a_s, cx, cy

        return position, velocity_, acceleration_

    rounding = 16.0

    def error_bound(self, walk, k, p_in, v_in, a_in):
        """Its ends' errors over its length turn its direction; omega = e x u / |d| and
        alpha divide once more (the slotted link's rule, no free end)."""
        P, V, A, sizes, m_ = walk.P, walk.V, walk.A, walk.sizes, walk.motion
        K, R = self.barrel, self.rod
        Ls, Vs, As = sizes["position"], sizes["velocity"], sizes["acceleration"]
        n = vmax(vhypot(P[R][0] - P[K][0], P[R][1] - P[K][1]), EPS * Ls)
        e = vhypot(V[R][0] - V[K][0], V[R][1] - V[K][1])
        w, vs = abs(m_.W.get(self.key, 0.0)), abs(m_.S[self.key][0])
        ea = vhypot(A[R][0] - A[K][0], A[R][1] - A[K][1]) + w * w * n + 2 * w * vs
        _, kv, ka = walk.own(self, k)  # its own rounding, of its own speeds and accelerations
        turn = p_in * Ls / n + k
        d_w = (v_in * Vs + e * turn) / n + k * w
        d_vs = v_in * Vs + e * turn + kv * Vs
        d_al = (a_in * As + ea * turn + 2 * d_w * vs + 2 * w * d_vs) / n
        d_as = a_in * As + ea * turn + 2 * w * d_w * n + ka * As
        walk.slide[self.key] = (d_vs / Vs, d_as / As, 2 * (d_w * vs + w * d_vs) / As + ka)
        return p_in, v_in, a_in, d_w / sizes["omega"] + k, d_al / sizes["alpha"] + k

    # ----- words
    def shrunk(self):
        """The error for a cylinder whose two pins coincide: its direction is undefined."""
        return SingularStepError(
            f"cylinder {self.key} has no length here ({self.rod} is at "
            f"{self.barrel}): its direction is undefined",
            step=self.label,
        )

    def why(self, n):
        """Why the cylinder cannot reach length ``n`` (m): outside its stroke."""
        u, nm = self.unit, self.uname
        lo, hi = self.stroke
        return (
            f"cylinder {self.key} would be {in_units(n, u)} {nm} long here, outside its "
            f"stroke {in_units(lo, u)} to {in_units(hi, u)} {nm} (fully "
            f"{'closed' if n < lo else 'extended'})"
        )

    def stop_words(self, P, key, rate) -> str | None:
        """Extending (``rate`` > 0) at its full extension, or retracting at its least length,
        is against the end of its stroke (its length that end's to the answers' resolution,
        ``SAME``): it cannot."""
        if key != self.key or self.stroke is None or not rate:
            return None
        n, (lo, hi) = math.dist(P[self.barrel], P[self.rod]), self.stroke
        if n < hi * (1 - SAME) if rate > 0 else n > lo * (1 + SAME):
            return None
        u, nm = self.unit, self.uname
        return (
            f"the cylinder {self.key} is fully {'extended' if rate > 0 else 'closed'} here "
            f"({in_units(n, u)} {nm} long, the end of its stroke {in_units(lo, u)} to "
            f"{in_units(hi, u)} {nm}): it cannot {'extend' if rate > 0 else 'retract'}"
        )

    def singular_why(self, c) -> str:
        return f"cylinder {self.key} is shrunk to nothing (condition {c:.2g})"

    def warning(self, c) -> str:
        return (
            f"{self.label}: the rod end {self.rod} is close to the barrel's pivot "
            f"{self.barrel} (condition {c:.3g})"
        )

    def limit_why(self) -> str:
        return f"cylinder {self.key} reaches the end of its stroke"

    def condition_column(self):
        return (
            f"cond step {self.index + 1}",
            "1",
            f"|{self.barrel}{self.rod}| over the longest link at its ends (at most 1)",
        )

    def transmission(self):
        return None

    def bodies(self):
        return (f"barrel {self.key}", f"rod {self.key}")

    def orient(self):
        return {}

    def output(self, ground):
        return None

    def drawn(self, prm, pencil, P):
        return prm

    def default_hint(self, P):
        return "above"

    def position_words(self, L, which, angle_deg):
        return (
            f"cylinder {self.key}: join {self.barrel} (the barrel's pivot) to {self.rod} "
            f"(the rod's end) and measure its length"
        )

    # ----- the polygons
    def under(self, sol, ph):
        """The image of the barrel's point under the rod's end: ``r1`` (``r1'``)."""
        from .slotted import under_label

        return under_label(sol, self.rod, ph)

    def construction(self, sol, ph):
        P, K, R = sol.P, self.barrel, self.rod
        cond = sol.conditions.get(self.index, 1.0)
        lab = lambda p: image_label(sol, p, ph)  # noqa: E731
        d = sub(P[R], P[K])
        u = unit(*d)
        w = sol.W[self.key]
        s = sol.S[self.key]
        c = self.under(sol, ph)
        if ph == "velocity":
            V = sol.V
            under = add(V[K], rigid_velocity(d[0], d[1], w))
            lines = (
                DirectionLine(
                    V[K], unit(*perp(d)), lab(K), f"perpendicular to {K}{R}", mark=f"\u22a5 {K}{R}"
                ),
                DirectionLine(
                    V[R],
                    u,
                    lab(R),
                    f"along the cylinder {self.key}",
                    mark=f"along the cylinder {self.key}",
                ),
            )
            text = (
                f"through {pole_text(sol, K, ph)} draw a line perpendicular to {K}{R} (the "
                f"barrel's point under {R}); through {lab(R)}, one along the cylinder; "
                f"they meet at {c}: {c}{lab(R)} = {abs(s[0]):.4g} m/s is the rate of "
                f"{'extension' if s[0] >= 0 else 'retraction'}, {lab(K)}{c} / {K}{R} the "
                f"barrel's omega"
            )
            found = (
                Vector(
                    V[K],
                    under,
                    f"{lab(K)}{c}",
                    "relative",
                    f"v of the barrel's point under {R}",
                    "",
                ),
                Vector(
                    under, V[R], f"{c}{lab(R)}", "sliding", f"vs_{self.key}", "rate of extension"
                ),
            )
            return Construction(
                self.index, self.title, ph, c, under, (), lines, found, text, cond, ((c, under),)
            )
        return self._acceleration_polygon(sol, ph, d, u, c, cond)

    def _acceleration_polygon(self, sol, ph, d, u, c, cond):
        """The construction on the acceleration polygon (``d``: K to R on the
        configuration, ``u`` its unit; ``c``: the label of the barrel's point under R)."""
        A, K, R = sol.A, self.barrel, self.rod
        lab = lambda p: image_label(sol, p, ph)  # noqa: E731
        w, al, s = sol.W[self.key], sol.Al[self.key], sol.S[self.key]
        cen_end = add(A[K], (-w * w * d[0], -w * w * d[1]))
        under = add(cen_end, (-al * d[1], al * d[0]))
        cor = (s[2], s[3])
        back = sub(A[R], cor)
        cen = Vector(
            A[K],
            cen_end,
            "cen",
            "centripetal",
            f"centripetal of {R}{K} on the barrel",
            f"omega^2 x {K}{R} = {w * w * math.hypot(*d):.4g} m/s^2, towards {K}",
        )
        corv = Vector(
            back,
            A[R],
            "cor",
            "coriolis",
            f"Coriolis at {R}",
            f"2 omega vs = {math.hypot(*cor):.4g} m/s^2, perpendicular to the cylinder",
        )
        lines = (
            DirectionLine(
                cen_end,
                unit(*perp(d)),
                "the end of the centripetal",
                f"perpendicular to {K}{R}",
                mark=f"\u22a5 {K}{R}",
            ),
            DirectionLine(
                back,
                u,
                "the start of the Coriolis component",
                "along the cylinder",
                mark="along the cylinder",
            ),
        )
        text = (
            f"from {pole_text(sol, K, ph)} draw the centripetal of the barrel's point "
            f"under {R} ({cen.text}) and through its end a line perpendicular to {K}{R}; "
            f"from {lab(R)} draw the Coriolis component backwards ({corv.text}) and "
            f"through its start a line along the cylinder; they meet at {c}: the rod's "
            f"acceleration along the barrel is {s[1]:.4g} m/s^2"
        )
        found = (
            Vector(cen_end, under, "t", "tangential", f"tangential of {R}{K}", f"alpha x {K}{R}"),
            Vector(under, back, "s", "sliding", f"as_{self.key}", "acceleration of extension"),
        )
        return Construction(
            self.index,
            self.title,
            ph,
            c,
            under,
            (cen, corv),
            lines,
            found,
            text,
            cond,
            ((c, under),),
        )
