"""RPR: a slotted link. A block pinned at known A slides along link K-N, which turns about
known K (crank and slotted lever, Whitworth, a swivel or trunnion).

Position: ``N = K + L sigma (A - K) / |A - K|``. Velocity: ``vA = vK + wG perp(d) + vs u``
with d = A - K; the two direction lines (perpendicular to KA through k, parallel to the
link through a) are at right angles::

    wG = (vA - vK) x u / -(d.u),   vs = (vA - vK).d / (d.u)

Acceleration: ``aA = aK - wG^2 d + aG perp(d) + 2 wG vs perp(u) + as u`` (the Coriolis
component 2 omega v). ``u`` is the guide's direction from its first point to its second, as
named. Condition: min(1, |KA| / rho): the block near the pivot makes the link's direction,
and so its motion, ill-defined. ``rho`` is the length of the links that place the block and
the pivot (the largest link at A or K other than the guide, e.g. the crank; the guide's own
length where there is none): the rounding of A and K is of their size, so the direction's
error is that over |KA|, whatever the lever's length.

An offset slot (``offset`` e: the slot's centre line parallel to the link's, e to the left
of K -> N): the block is at ``A - K = t w + e perp(w)`` with w the link's unit direction, so
``t = sigma sqrt(|KA|^2 - e^2)`` and ``w = (t d - e perp(d)) / |d|^2``. The relations above
hold as written (d.u = +-t); the condition is min(1, |t| / rho), nought where the slot's
line is square to KA (the block at the foot of the perpendicular from K: a limit position).

>>> x, y, c = place(0.0, 0.0, 0.3, 0.4, 1.0, 1.0, 1.0)
>>> round(x, 12), round(y, 12), c
(0.6, 0.8, 0.5)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .relations import coriolis, rigid_velocity
from ..common.errors import TOL, SingularStepError
from .offset_slot import image_words, place_offset, why
from ..common.tolerances import LEAST_REACH
from ..scene import GuideSlider
from .rounding import C_FLOOR, vhypot, vmax
from .base import (
    Construction,
    DirectionLine,
    Step,
    Vector,
    absolute,
    add,
    image_label,
    image_name,
    numbered,
    perp,
    pole_text,
    relative,
    sub,
    unit,
)

__all__ = ["SlottedLink", "place", "velocity", "acceleration", "recognise"]


def place(kx, ky, ax, ay, length, rho, sigma, ctx=None, step=None):
    """The free end N = K + L sigma (A - K) / |A - K| of a link through the block at A.
    Returns x, y and the condition min(1, |KA| / rho)."""
    dx, dy = ax - kx, ay - ky
    m = (dx * dx + dy * dy) ** 0.5
    if ctx is not None:
        if not ctx.array and m <= TOL.singular * rho:
            raise step.at_pivot()
        m = ctx.safe(m, step)
    f = sigma * length / m
    c = m / rho
    return kx + f * dx, ky + f * dy, (ctx.minimum(c, 1.0) if ctx is not None else min(c, 1.0))


def velocity(dx, dy, ux, uy, ex, ey, d=None):
    """(wG, vs) from d = A - K, the unit u along the guide and e = vA - vK."""
    if d is None:
        d = -(dx * ux + dy * uy)
    return (ex * uy - ux * ey) / d, -(dx * ex + dy * ey) / d


def acceleration(dx, dy, ux, uy, ex, ey, d=None):
    """(alG, as) from e = aA - aK + wG^2 d - Coriolis."""
    return velocity(dx, dy, ux, uy, ex, ey, d)


def _offset_errors(k, dp, dv, da, m, mt, amp, e, ea, w, al, vs, a_s):
    """The errors (absolute) of an offset slot's omega, vs, alpha, as, Coriolis and the
    lever's turn, from its points' errors ``dp``, ``dv``, ``da`` and its own rounding ``k``
    (its speeds' and accelerations' own, added by the caller). Every unknown is a quotient by t =
    d.u (``mt``), which the lever's turn moves by e (``amp`` = e / t): near the limit
    position, t -> 0, the quotients' numerators vanish with it and their rounding is what is
    divided (vs = d.e / t, omega = e x u / -t; as, alpha alike with e_a)."""
    turn = dp * (1 + amp) / m + k * (1 + amp)
    d_w = (dv + e * turn + k * e) / mt + w * amp * turn
    d_vs = (m * dv + e * (dp + k * m)) / mt + vs * amp * turn
    d_cor = 2 * (d_w * vs + w * d_vs)
    d_ea = da + 2 * w * d_w * m + d_cor  # the known side's error: its centripetal, Coriolis
    d_al = (d_ea + ea * turn + k * ea) / mt + al * amp * turn
    d_as = (ea * dp + m * d_ea + k * m * ea) / mt + a_s * amp * turn
    return d_w, d_vs, d_al, d_as, d_cor, turn


def recognise(g, name):
    """A block at a known point sliding on a link with one end known and ``name`` the other
    (tried when no point can be found otherwise)."""
    sc = g.scene
    for sl in sc.sliders:
        if not isinstance(sl, GuideSlider) or sl.slot or sl.point in g.used_sliders:
            continue
        guide = sc.link(sl.guide)
        if sl.point not in g.P or guide.key in g.used_links or name not in guide.points:
            continue
        ends = [p for p in guide.points if p in g.P]
        if len(ends) != 1:
            continue
        known = ends[0]
        g.used_sliders.add(sl.point)
        ref = _reference(sc, guide.key, (sl.point, known)) or guide.key
        # the offset to the left of K -> N (the scene's is to the left of first -> second)
        offset = sl.offset if sl.first == known else -sl.offset
        return SlottedLink(
            g.next_index,
            sl.point,
            guide.key,
            known,
            guide.other(known),
            guide.length,
            sl.first,
            sl.second,
            unit=g.unit,
            uname=g.uname,
            ref=ref,
            rho=sc.link(ref).length,
            offset=offset,
        )


def _reference(sc, guide, points):
    """The longest link (or plate) other than ``guide`` at any of ``points``: the size of
    what places them (None where no other link meets them)."""
    best = None
    for lk in sc.links:
        if (
            lk.key != guide
            and (lk.p in points or lk.q in points)
            and (best is None or lk.length > best.length)
        ):
            best = lk
    for p in points:
        cp = sc.carried(p)
        if cp is not None and cp.link != guide:
            lk = sc.link(cp.link)
            if best is None or lk.length > best.length:
                best = lk
    return None if best is None else best.key
    return None


def under_label(sol, X: str, phase: str = "velocity") -> str:
    """The image of the guide's point under the block at X: ``a1`` (``a1'``), or ``a2``
    and so on where the scene has a point A1 of its own (whose image is a1)."""
    sc = sol.scene
    taken = {image_name(sc, p) for p in sc.point_names} | {p.lower() for p in sc.point_names}
    return numbered(X.lower(), taken) + ("'" if phase == "acceleration" else "")


@dataclass(frozen=True)
class SlottedLink(Step):
    """RPR: a block pinned at known A slides along link K-N that turns about known K."""

    point: str  # the block's pin (known)
    guide: str
    known: str
    new: str
    length: float
    first: str
    second: str
    sigma: float = 1.0
    unit: float = 1e-3
    uname: str = "mm"
    #: the link whose length is the condition's scale (see the module), and that length
    ref: str = ""
    rho: float = 0.0
    #: an offset slot: its line this far (m) to the left of K -> N; 0 on the link's line
    offset: float = 0.0

    kind = "slotted"
    branching = True

    @property
    def finds(self):
        return (self.new,)

    @property
    def links(self):
        return (self.guide,)

    @property
    def needs(self):
        return (self.known, self.point)

    @property
    def title(self):
        return f"block {self.point} sliding on {self.guide}"

    @property
    def params(self):
        return (self.length, self.rho or self.length, self.offset)

    def dimensions(self, scene, bodies):
        length = scene.link(self.guide).length
        sl = scene.slider(self.point)
        off = getattr(sl, "offset", 0.0)
        return (
            length,
            scene.link(self.ref).length if self.ref else length,
            off if sl is None or sl.first == self.known else -off,
        )

    def drawn(self, prm, pencil, P):
        """An offset slot's circle about the pivot is drawn with the pencil's error; the
        slot through the pivot draws nothing of its own."""
        return (prm[0], prm[1], prm[2] + pencil()) if self.offset else prm

    def reach(self):
        return max(self.length, LEAST_REACH)

    def place(self, P, prm, ctx, sigma=None):
        (kx, ky), (ax, ay) = P[self.known], P[self.point]
        s = self.sigma if sigma is None else sigma
        if self.offset:
            return place_offset(kx, ky, ax, ay, prm[0], prm[1], prm[2], s, ctx, self)
        return place(kx, ky, ax, ay, prm[0], prm[1], s, ctx, self)

    def default_hint(self, P):
        return "block side"

    def bind(self, prm):
        """The step's three phases for dimensions ``prm``: functions of a State."""
        Ab, K, N, F1, F2, guide = (
            self.point,
            self.known,
            self.new,
            self.first,
            self.second,
            self.guide,
        )
        i, sigma, step, L, rho = self.index, self.sigma, self, prm[0], prm[1]
        e = prm[2] if self.offset else None

        def frame(P):
            (f1x, f1y), (f2x, f2y) = P[F1], P[F2]
            (ax, ay), (kx, ky) = P[Ab], P[K]
            return (f2x - f1x) / L, (f2y - f1y) / L, ax - kx, ay - ky

        def position(m):
            P = m.P
            if e is None:
                x, y, c = place(*P[K], *P[Ab], L, rho, sigma, m.ctx, step)
            else:
                x, y, c = place_offset(*P[K], *P[Ab], L, rho, e, sigma, m.ctx, step)
            P[N] = (x, y)
            m.cond[i] = c

        def velocity_(m):
            P, V = m.P, m.V
            ux, uy, dx, dy = frame(P)
            d = -(dx * ux + dy * uy)
            if m.array:
                d = m.ctx.safe(d, step)
            (vax, vay), (vkx, vky) = V[Ab], V[K]
            w, vs = velocity(dx, dy, ux, uy, vax - vkx, vay - vky, d)
            m.W[guide] = w
            m.S[Ab] = [vs, None, 0.0, 0.0]
            (nx, ny), (kx, ky) = P[N], P[K]
            V[N] = (vkx - w * (ny - ky), vky + w * (nx - kx))

        def acceleration_(m):
            P, A = m.P, m.A
            ux, uy, dx, dy = frame(P)
            d = -(dx * ux + dy * uy)
            if m.array:
                d = m.ctx.safe(d, step)
            w = m.W[guide]
            s = m.S[Ab]
            cx, cy = coriolis(w, s[0], ux, uy)
            k = w * w
            (aax, aay), (akx, aky) = A[Ab], A[K]
            al, a_s = acceleration(
                dx, dy, ux, uy, aax - akx + k * dx - cx, aay - aky + k * dy - cy, d
            )
            m.Al[guide] = al
            s[1], s[2], s[3] = a_s, cx, cy
            (nx, ny), (kx, ky) = P[N], P[K]
            px, py = nx - kx, ny - ky
            A[N] = (akx - k * px - al * py, aky - k * py + al * px)

        return position, velocity_, acceleration_

    rounding = 16.0

    def error_bound(self, walk, k, p_in, v_in, a_in):
        """The lever's direction is d = A - K over |d|, so the error of d (its points'
        error) turns it by that over |d|; the block's motion relative to the pivot (e,
        e_a), turned so, errs by e times that angle; omega = e x u / |d| and alpha = e_a x
        u / |d| divide once more. Its own rounding is relative to them: only what it is
        given is divided. The block's sliding velocity, sliding acceleration and Coriolis
        component go to ``walk.slide``."""
        K_, A_ = self.known, self.point
        m_, P, V, A = walk.motion, walk.P, walk.V, walk.A
        sizes = walk.sizes
        Ls, Vs, As = sizes["position"], sizes["velocity"], sizes["acceleration"]
        Om, Als = sizes["omega"], sizes["alpha"]
        n = self.new
        m = vmax(vhypot(P[A_][0] - P[K_][0], P[A_][1] - P[K_][1]), C_FLOOR * Ls)
        mt, amp = m, 0.0  # the divisor |d.u| and how the lever's turn moves it (offset e)
        if self.offset:  # d.u = t, along the slot from K's foot: the turn moves it by e
            (f1x, f1y), (f2x, f2y) = P[self.first], P[self.second]
            ln = vhypot(f2x - f1x, f2y - f1y)
            t = ((P[A_][0] - P[K_][0]) * (f2x - f1x) + (P[A_][1] - P[K_][1]) * (f2y - f1y)) / ln
            mt = vmax(abs(t), C_FLOOR * Ls)
            amp = abs(self.offset) / mt
        L = vhypot(P[n][0] - P[K_][0], P[n][1] - P[K_][1])
        vs = abs(m_.S[A_][0]) if A_ in m_.S else Vs
        a_s = abs(m_.S[A_][1]) if A_ in m_.S and m_.S[A_][1] is not None else As
        w = abs(m_.W.get(self.guide, 0.0))
        al = abs(m_.Al.get(self.guide, 0.0))
        e = vhypot(V[A_][0] - V[K_][0], V[A_][1] - V[K_][1])
        ea = vhypot(A[A_][0] - A[K_][0], A[A_][1] - A[K_][1]) + w * w * m + 2 * w * vs
        _, kv, ka = walk.own(self, k)  # its own rounding, of its own speeds and accelerations
        if self.offset:
            d_w, d_vs, d_al, d_as, d_cor, turn = _offset_errors(
                k, p_in * Ls, v_in * Vs, a_in * As, m, mt, amp, e, ea, w, al, vs, a_s
            )
            d_vs, d_as, d_cor = d_vs + kv * Vs, d_as + ka * As, d_cor + ka * As
        else:
            turn = p_in * Ls / m + k  # the lever's direction, rad
            d_w = (v_in * Vs + e * turn) / m + k * w  # omega, rad/s
            d_vs = v_in * Vs + e * turn + kv * Vs  # sliding velocity, m/s
            d_al = (a_in * As + ea * turn + 2 * d_w * vs + 2 * w * d_vs) / m + k * al
            d_as = a_in * As + ea * turn + 2 * w * d_w * m + ka * As
            d_cor = 2 * (d_w * vs + w * d_vs) + ka * As
        walk.slide[A_] = (d_vs / Vs, d_as / As, d_cor / As)
        p = k + p_in + turn * L / Ls
        v = kv + (v_in * Vs + L * d_w + w * L * turn) / Vs
        a = ka + (a_in * As + L * d_al + 2 * w * d_w * L + (w * w + al) * L * turn) / As
        return p, v, a, d_w / Om + k, d_al / Als + k

    def coriolis_left_out(self, sol):
        """What a polygon drawn without the Coriolis component gives (the classic slip of a
        crank and slotted lever): {(kind, name): value} for the lever's alpha (signed) and
        the size of its far end's acceleration. The line parallel to the slot is then drawn
        through a' itself: ``aA = aK - w^2 d + al perp(d) + as u``, solved as before."""
        P, A, K, N, Ab = sol.P, sol.A, self.known, self.new, self.point
        cx, cy = sol.coriolis(Ab)
        if cx == 0 and cy == 0:
            return {}
        (f1x, f1y), (f2x, f2y) = P[self.first], P[self.second]
        L = math.hypot(f2x - f1x, f2y - f1y)
        ux, uy = (f2x - f1x) / L, (f2y - f1y) / L
        dx, dy = P[Ab][0] - P[K][0], P[Ab][1] - P[K][1]
        k = sol.W[self.guide] ** 2
        ex, ey = A[Ab][0] - A[K][0] + k * dx, A[Ab][1] - A[K][1] + k * dy
        al, _ = acceleration(dx, dy, ux, uy, ex, ey)
        px, py = P[N][0] - P[K][0], P[N][1] - P[K][1]
        aN = (A[K][0] - k * px - al * py, A[K][1] - k * py + al * px)
        return {("alpha", self.guide): al, ("a", N): math.hypot(*aN)}

    # ----- failures and words
    def at_pivot(self):
        """The error for a block at the slotted link's pivot: the link's direction is undefined."""
        return SingularStepError(
            f"block {self.point} is at {self.known}, the pivot of "
            f"{self.guide}: the link's direction is undefined",
            step=self.label,
        )

    def singular_why(self, c) -> str:
        if self.offset:
            return why(self, "singular", c)
        return (
            f"block {self.point} is at {self.known}, the pivot of {self.guide} (condition "
            f"{c:.2g}): the link's direction is undefined"
        )

    def transmission(self):
        return None  # its condition is the block's distance from the pivot, not an angle

    def warning(self, c) -> str:
        if self.offset:
            return why(self, "warning", c)
        return (
            f"{self.label}: block {self.point} is close to {self.known}, the pivot of "
            f"{self.guide} (condition {c:.3g})"
        )

    def limit_why(self) -> str:
        if self.offset:
            return why(self, "limit")
        return f"block {self.point} reaches the pivot {self.known} of {self.guide}"

    def condition_column(self):
        return (
            f"cond step {self.index + 1}",
            "1",
            why(self, "column")
            if self.offset
            else f"|{self.known}{self.point}| / {self.ref or self.guide} (at most 1)",
        )

    def bodies(self):
        return (f"block {self.point}", self.guide)

    def orient(self):
        return {self.guide: (self.new, self.known)}

    def output(self, ground):
        if self.known in ground:  # a slotted lever about its fixed pivot
            return ("lever", self.guide, self.known, self.new)
        if self.point in ground:  # an oscillating cylinder: the link swings about the swivel
            return ("lever", self.guide, self.point, self.new)
        return None

    def position_words(self, L, which, angle_deg):
        if self.offset:
            return why(self, "position", L=L)
        return (
            f"{self.new}: {self.guide} passes through the block at {self.point}: draw the "
            f"line from {self.known} through {self.point} and mark {self.known}{self.new} = "
            f"{L(self.length)} on it"
        )

    # ----- the polygons
    def _n_words(self, k, n, c, ph) -> str:
        """How the lever's far end n follows from k and c (the image of the lever's point
        under the block): along k c produced, or by the image triangle (an offset slot)."""
        then = "then " if ph == "velocity" else ""
        if self.offset:
            return then + image_words(self, k, n, c)
        rule = f"{k}{n} / {k}{c} = {self.known}{self.new} / {self.known}{self.point}"
        return f"then {rule} gives {n}" if then else f"{n} follows by {rule}"

    def construction(self, sol, ph):
        P, Ab, K, N = sol.P, self.point, self.known, self.new
        cond = sol.conditions.get(self.index, 1.0)
        lab = lambda p: image_label(sol, p, ph)  # noqa: E731
        kA = sub(P[Ab], P[K])
        w = sol.W[self.guide]
        u = unit(*sub(P[self.second], P[self.first]))
        if ph == "velocity":
            V = sol.V
            coincident = add(V[K], rigid_velocity(kA[0], kA[1], w))
            c = under_label(sol, Ab, ph)  # the lever's point under the block (c1 at a swivel C)
            lines = (
                DirectionLine(
                    V[K],
                    unit(*perp(kA)),
                    lab(K),
                    f"perpendicular to {K}{Ab}",
                    mark=f"\u22a5 {K}{Ab}",
                ),
                DirectionLine(
                    V[Ab], u, lab(Ab), f"parallel to {self.guide}", mark=f"\u2225 {self.guide}"
                ),
            )
            text = (
                f"through {pole_text(sol, K, ph)} draw a line perpendicular to {K}{Ab} (the "
                f"point of {self.guide} under the block); through {lab(Ab)}, one parallel "
                f"to {self.guide} (the sliding); they meet at {c}; "
                f"{self._n_words(lab(K), lab(N), c, ph)}"
            )
            found = (
                Vector(
                    V[K],
                    coincident,
                    f"{lab(K)}{c}",
                    "relative",
                    f"v of the point of {self.guide} under {Ab}"
                    + ("" if K in sol.scene.ground else f", relative to {K}"),
                    "",
                ),
                Vector(
                    coincident,
                    V[Ab],
                    f"{c}{lab(Ab)}",
                    "sliding",
                    f"vs_{Ab}",
                    "sliding velocity of the block",
                ),
                absolute(sol, N, V, ph),
            )
            if K not in sol.scene.ground:  # the lever's image line k c1 produced to n
                found += (relative(sol, N, K, V, ph),)
            return Construction(
                self.index,
                self.title,
                ph,
                lab(N),
                V[N],
                (),
                lines,
                found,
                text,
                cond,
                ((c, coincident),),
            )
        return self._acceleration_polygon(sol, ph, kA, u, cond)

    def _acceleration_polygon(self, sol, ph, kA, u, cond):
        """The construction on the acceleration polygon (``kA``: K to the block on the
        configuration; ``u``: the guide's unit)."""
        A, Ab, K, N = sol.A, self.point, self.known, self.new
        lab = lambda p: image_label(sol, p, ph)  # noqa: E731
        w, al = sol.W[self.guide], sol.Al[self.guide]
        cen_end = add(A[K], (-w * w * kA[0], -w * w * kA[1]))
        under = add(cen_end, (-al * kA[1], al * kA[0]))
        cor = sol.coriolis(Ab)
        back = sub(A[Ab], cor)
        c = under_label(sol, Ab, ph)
        cen = Vector(
            A[K],
            cen_end,
            "cen",
            "centripetal",
            f"centripetal of {Ab}{K} on {self.guide}",
            f"omega^2 x {K}{Ab} = {w * w * math.hypot(*kA):.4g} m/s^2, towards {K}",
        )
        corv = Vector(
            back,
            A[Ab],
            "cor",
            "coriolis",
            f"Coriolis at {Ab}",
            f"2 omega_{self.guide} vs = {math.hypot(*cor):.4g} m/s^2, perpendicular "
            f"to {self.guide}",
        )
        lines = (
            DirectionLine(
                cen_end,
                unit(*perp(kA)),
                "the end of the centripetal",
                f"perpendicular to {K}{Ab}",
                mark=f"\u22a5 {K}{Ab}",
            ),
            DirectionLine(
                back,
                u,
                "the start of the Coriolis component",
                f"parallel to {self.guide}",
                mark=f"\u2225 {self.guide}",
            ),
        )
        text = (
            f"from {pole_text(sol, K, ph)} draw the centripetal of the point of "
            f"{self.guide} under the block ({cen.text}) and through its end a line "
            f"perpendicular to {K}{Ab}; from {lab(Ab)} draw the Coriolis component "
            f"backwards ({corv.text}) and through its start a line parallel to "
            f"{self.guide}; they meet at {c}; {self._n_words(lab(K), lab(N), c, ph)}"
        )
        found = (
            Vector(
                cen_end,
                under,
                "t",
                "tangential",
                f"tangential of {Ab}{K}",
                f"alpha_{self.guide} x {K}{Ab}",
            ),
            Vector(under, back, "s", "sliding", f"as_{Ab}", "sliding acceleration"),
            absolute(sol, N, A, ph),
        )
        if K not in sol.scene.ground:  # the lever's image line k' c1' produced to n'
            found += (relative(sol, N, K, A, ph),)
        return Construction(
            self.index,
            self.title,
            ph,
            lab(N),
            A[N],
            (cen, corv),
            lines,
            found,
            text,
            cond,
            ((c, under),),
        )
