"""The construction plan: an ordered tuple of steps, each finding one point as a hand
construction does.

Step kinds
----------
:class:`Crank`      the driving crank: its tip from the pivot, the angle and the speed.
:class:`Dyad`       RRR: a point joined to two known points by two links (circle-circle);
                    velocity: through b a line perpendicular to BC, through d one
                    perpendicular to DC, they meet at c.
:class:`SliderDyad` RRP: a point joined to a known point by a link and sliding on a guide,
                    fixed or moving (circle-line); through b a line perpendicular to BC,
                    through the guide's coincident point a line parallel to the guide.
:class:`SlottedLink` RPR: a block pinned at a known point slides along a link that turns about
                    another known point (crank and slotted lever, Whitworth, swivel); the
                    relative motion brings the Coriolis component 2 omega v.
:class:`Carried`    a point fixed on a known link; its image is found by similar triangles.

Each step emits a few lines of arithmetic (operators only: no ``math``/``np`` calls but the
crank's cos/sin and the shared position functions); the plan joins them into one
straight-line function, compiled once (:attr:`Plan.kernel`, printable with
:meth:`Plan.kernel_source`). The same function serves a single position (floats) and a whole
sweep (numpy arrays). ``perp(x, y) = (-y, x)`` turns a vector 90 deg counter-clockwise;
``omega x r = omega perp(r)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from .errors import TOL, AssemblyError, MobilityError, PolygonMethodError, SingularStepError
from .numbers import in_units as _mm
from .scene import FixedPath, GuideSlider, Scene, split_name

__all__ = ["Plan", "compile_plan", "Crank", "Dyad", "SliderDyad", "SlottedLink", "Carried",
           "Context"]




class Context:
    """What a kernel needs besides the state: the input motion and the maths for floats
    or arrays. In scalar mode a failing step raises; in array mode it is masked."""

    def __init__(self, theta, omega, alpha, *, array=False):
        self.theta, self.omega, self.alpha = theta, omega, alpha
        self.array = array
        self.cond = {}
        self.bad = None  # array mode: positions where a step failed
        self.failures = {}  # array mode: step index -> mask
        self.rubbing = {}  # pin -> rubbing velocity of each pair of bodies it joins
        if array:
            import numpy as np
            self.np = np
            self.cos, self.sin = np.cos, np.sin
        else:
            self.cos, self.sin = math.cos, math.sin

    def root(self, disc, scale2, step, why):
        """sqrt(disc), where disc < 0 means the step cannot assemble."""
        if self.array:
            np = self.np
            miss = disc < -TOL.closure * scale2
            if miss.any():
                self._fail(step, miss)
            return np.sqrt(np.maximum(disc, 0.0))
        if disc < -TOL.closure * scale2:
            raise AssemblyError(why(), step=step.label)
        return disc ** 0.5 if disc > 0 else 0.0

    def condition(self, step, value):
        """Record a step's condition measure (sine of the angle between its two lines)."""
        self.cond[step.index] = value

    def _fail(self, step, mask):
        prev = self.failures.get(step.index)
        self.failures[step.index] = mask if prev is None else (prev | mask)
        self.bad = mask if self.bad is None else (self.bad | mask)

    def safe(self, den, step):
        """A denominator that is never exactly zero (array mode: singular entries masked)."""
        if self.array:
            np = self.np
            zero = den == 0
            if zero.any():
                self._fail(step, zero)
                return np.where(zero, 1.0, den)
        return den


# --------------------------------------------------------------------------- positions
# The position of each step kind is one pure function (float or array), used both by the
# compiler (to choose the branch) and by the compiled kernel.


def dyad_xy(bx, by, dx, dy, l1, l2, sigma, ctx, step):
    """X with |XB| = l1, |XD| = l2: along BD by (l1^2 - l2^2 + e^2) / 2e, off it by h.

    ``4 e^2 h^2 = (l1+l2+e)(l1+l2-e)(e+l1-l2)(e-l1+l2)`` keeps h exact near a toggle.
    Returns x, y and the condition e h / (l1 l2) = |sin| of the angle at X.
    """
    ex, ey = dx - bx, dy - by
    e2 = ex * ex + ey * ey
    e = e2 ** 0.5
    if not ctx.array and e == 0:
        raise step.coincident()
    e = ctx.safe(e, step)
    q = (l1 + l2 + e) * (l1 + l2 - e) * (e + l1 - l2) * (e - l1 + l2)
    h = ctx.root(q, (l1 * l2) ** 2, step, lambda: step._why(e)) / (2 * e)
    along = (l1 * l1 - l2 * l2 + e2) / (2 * e)
    ux, uy = ex / e, ey / e
    return (bx + along * ux - sigma * h * uy, by + along * uy + sigma * h * ux,
            e * h / (l1 * l2))


def slider_xy(bx, by, qx, qy, ux, uy, ell, sigma, ctx, step):
    """X on the line Q + s u with |XB| = ell: s = -(Q - B).u +- sqrt(ell^2 - d^2),
    d = (Q - B) x u. Returns x, y and the condition sqrt(ell^2 - d^2) / ell = |r.u| / ell."""
    wx, wy = qx - bx, qy - by
    b = wx * ux + wy * uy
    dist = wx * uy - wy * ux
    half = ctx.root((ell - dist) * (ell + dist), ell * ell, step, lambda: step._why(dist))
    s = sigma * half - b
    return qx + s * ux, qy + s * uy, half / ell


def slotted_xy(kx, ky, ax, ay, length, sigma, ctx, step):
    """The free end N = K + L sigma (A - K) / |A - K| of a link through the block at A.
    Returns x, y and the condition min(1, |KA| / L)."""
    dx, dy = ax - kx, ay - ky
    m = (dx * dx + dy * dy) ** 0.5
    if not ctx.array and m <= TOL.singular * length:
        raise step.at_pivot()
    m = ctx.safe(m, step)
    f = sigma * length / m
    c = m / length
    return kx + f * dx, ky + f * dy, (ctx.np.minimum(c, 1.0) if ctx.array else min(c, 1.0))


# --------------------------------------------------------------------------- steps
# Each step emits straight-line code for the compiled kernel (see Plan.kernel). Names: a
# point X has X_x, X_y (position), X_vx, X_vy, X_ax, X_ay; link j has w_j, al_j; a slider
# at X has vs_X, as_X, cx_X, cy_X; step i's condition is c_i and its object S_i.


@dataclass(frozen=True)
class Step:
    index: int

    #: whether the step has two assemblies (a branch ``sigma`` to choose)
    branching = False

    @property
    def label(self) -> str:
        return f"step {self.index + 1} ({self.title})"

    def singular_why(self, c) -> str:
        """Why the step fails at condition ``c`` (below ``TOL.singular``)."""
        return f"the step is singular (condition {c:.2g})"

    def warning(self, c) -> str:
        """The warning line for a condition ``c`` below ``TOL.warn``."""
        return f"{self.label}: condition {c:.3g}"

    def limit_why(self) -> str:
        """Why the linkage cannot be assembled beyond a limit position of this step."""
        return "the linkage cannot be assembled beyond it"

    def condition_column(self):
        """(name, unit, words) of this step's condition in a sweep summary: the
        transmission angle for the steps whose condition is its sine."""
        return (f"mu at {self.finds[0]}", "deg", "transmission angle (acute)")

    def positions(self, P, ctx):
        """Place this step's point into ``P`` (one step at a time; the kernel does all)."""
        x, y, c = self.place(P, ctx)
        P[self.finds[0]] = (x, y)
        ctx.condition(self, c)

    def candidates(self, P, ctx):
        """The two assemblies as (midpoint, half the vector from one to the other)."""
        (x1, y1, _), (x2, y2, _) = self.place(P, ctx, 1.0), self.place(P, ctx, -1.0)
        return ((x1 + x2) / 2, (y1 + y2) / 2), ((x1 - x2) / 2, (y1 - y2) / 2)


@dataclass(frozen=True)
class Crank(Step):
    """Tip = pivot + r (cos theta, sin theta); v = omega perp(r); a = -omega^2 r + alpha perp(r)."""

    link: str
    pivot: str
    tip: str
    length: float
    kind: str = "crank"

    @property
    def finds(self):
        return (self.tip,)

    @property
    def links(self):
        return (self.link,)

    @property
    def title(self):
        return f"crank {self.link}"

    def place(self, P, ctx, sigma=None):
        ox, oy = P[self.pivot]
        r = self.length
        return ox + r * ctx.cos(ctx.theta), oy + r * ctx.sin(ctx.theta), 1.0

    def emit(self, n):
        O, T, r, i, j = self.pivot, self.tip, repr(self.length), self.index, n[self.link]
        pos = (f"{T}_x = {O}_x + {r} * cos(theta); {T}_y = {O}_y + {r} * sin(theta); "
               f"c_{i} = 1.0")
        vel = (f"w_{j} = omega; {T}_vx = {O}_vx - omega * ({T}_y - {O}_y); "
               f"{T}_vy = {O}_vy + omega * ({T}_x - {O}_x)")
        acc = (f"al_{j} = alpha; k = omega * omega\n"
               f"{T}_ax = {O}_ax - k * ({T}_x - {O}_x) - alpha * ({T}_y - {O}_y)\n"
               f"{T}_ay = {O}_ay - k * ({T}_y - {O}_y) + alpha * ({T}_x - {O}_x)")
        return pos, vel, acc


@dataclass(frozen=True)
class Dyad(Step):
    """RRR: point X with XB = l1 to known B and XD = l2 to known D.

    Velocity: ``w1 perp(r1) - w2 perp(r2) = vD - vB`` with r1 = X - B, r2 = X - D, so
    ``w1 = (vD - vB).r2 / (r1 x r2)``, ``w2 = (vD - vB).r1 / (r1 x r2)``.
    Acceleration: the same with the right side ``(aD - w2^2 r2) - (aB - w1^2 r1)``.
    Condition: |r1 x r2| / (l1 l2) = sine of the transmission angle at X.
    """

    point: str
    b: str
    link1: str
    l1: float
    d: str
    link2: str
    l2: float
    sigma: float = 1.0
    unit: float = 1e-3
    uname: str = "mm"
    kind: str = "dyad"

    @property
    def finds(self):
        return (self.point,)

    @property
    def links(self):
        return (self.link1, self.link2)

    @property
    def title(self):
        return f"dyad {self.link1}, {self.link2} at {self.point}"

    def place(self, P, ctx, sigma=None):
        (bx, by), (dx, dy) = P[self.b], P[self.d]
        s = self.sigma if sigma is None else sigma
        return dyad_xy(bx, by, dx, dy, self.l1, self.l2, s, ctx, self)

    branching = True

    def singular_why(self, c) -> str:
        return (f"{self.link1} and {self.link2} are in line (transmission angle "
                f"{math.degrees(math.asin(min(c, 1.0))):.3g} deg): a toggle position (or a "
                "change point, where the linkage may switch branch), where the direction "
                f"lines perpendicular to {self.link1} and {self.link2} are parallel and the "
                f"velocity of {self.point} is indeterminate")

    def warning(self, c) -> str:
        deg = math.degrees(math.asin(min(c, 1.0)))
        return (f"{self.label}: {self.link1} and {self.link2} are nearly in line (transmission "
                f"angle {deg:.3g} deg, condition {c:.3g}): near a toggle position the "
                "intersection of the direction lines is ill-conditioned")

    def limit_why(self) -> str:
        return (f"{self.side(1)} and {self.side(2)} come into line (a toggle: {self.point} "
                "cannot be assembled beyond it)")

    def coincident(self):
        if self.l1 == self.l2:
            return SingularStepError(f"{self.b} and {self.d} coincide and {self.side(1)} = "
                                     f"{self.side(2)}: {self.point} may be anywhere on a "
                                     "circle", step=self.label)
        return AssemblyError(self._why(0.0), step=self.label)

    def side(self, which) -> str:
        """The name of a side: the link itself, or ``BE on BC`` for a side of a plate."""
        key, k = (self.link1, self.b) if which == 1 else (self.link2, self.d)
        if set(split_name(key)) == {k, self.point}:
            return key
        return f"{k}{self.point} (on {key})"

    def _why(self, e):
        u = self.unit
        if self.l1 + self.l2 < e:
            return (f"cannot assemble {self.point}: {self.side(1)} + {self.side(2)} = "
                    f"{_mm(self.l1 + self.l2, u)} {self.uname} < {self.b}{self.d} = "
                    f"{_mm(e, u)} {self.uname} (short by {_mm(e - self.l1 - self.l2, u)} "
                    f"{self.uname})")
        return (f"cannot assemble {self.point}: |{self.side(1)} - {self.side(2)}| = "
                f"{_mm(abs(self.l1 - self.l2), u)} {self.uname} > {self.b}{self.d} = "
                f"{_mm(e, u)} {self.uname} (by {_mm(abs(self.l1 - self.l2) - e, u)} "
                f"{self.uname})")

    def emit(self, n):
        X, B, D, i = self.point, self.b, self.d, self.index
        j1, j2 = n[self.link1], n[self.link2]
        pos = (f"{X}_x, {X}_y, c_{i} = dyad_xy({B}_x, {B}_y, {D}_x, {D}_y, {self.l1!r}, "
               f"{self.l2!r}, {self.sigma!r}, ctx, S_{i})")
        vel = (f"r1x_{i} = {X}_x - {B}_x; r1y_{i} = {X}_y - {B}_y; "
               f"r2x_{i} = {X}_x - {D}_x; r2y_{i} = {X}_y - {D}_y\n"
               f"d_{i} = safe(r1x_{i} * r2y_{i} - r1y_{i} * r2x_{i}, S_{i})\n"
               f"wx = {D}_vx - {B}_vx; wy = {D}_vy - {B}_vy\n"
               f"w_{j1} = (wx * r2x_{i} + wy * r2y_{i}) / d_{i}; "
               f"w_{j2} = (wx * r1x_{i} + wy * r1y_{i}) / d_{i}\n"
               f"{X}_vx = {B}_vx - w_{j1} * r1y_{i}; {X}_vy = {B}_vy + w_{j1} * r1x_{i}")
        acc = (f"k1 = w_{j1} * w_{j1}; k2 = w_{j2} * w_{j2}\n"
               f"qx = ({D}_ax - k2 * r2x_{i}) - ({B}_ax - k1 * r1x_{i}); "
               f"qy = ({D}_ay - k2 * r2y_{i}) - ({B}_ay - k1 * r1y_{i})\n"
               f"al_{j1} = (qx * r2x_{i} + qy * r2y_{i}) / d_{i}; "
               f"al_{j2} = (qx * r1x_{i} + qy * r1y_{i}) / d_{i}\n"
               f"{X}_ax = {B}_ax - k1 * r1x_{i} - al_{j1} * r1y_{i}; "
               f"{X}_ay = {B}_ay - k1 * r1y_{i} + al_{j1} * r1x_{i}")
        return pos, vel, acc


@dataclass(frozen=True)
class SliderDyad(Step):
    """RRP: point X with XB = l to known B, sliding on a guide line (fixed or a moving link).

    Velocity: ``w perp(r) - vs u = vX' - vB`` (r = X - B, X' the guide's coincident point):
    ``w = u x (vX' - vB) / (r.u)``, ``vs = -r.(vX' - vB) / (r.u)``.
    Acceleration: right side ``aX' + 2 wG vs perp(u) - aB + w^2 r`` (Coriolis on a moving guide).
    Condition: |r.u| / l, the sine of the angle between the two direction lines.
    """

    point: str
    b: str
    link: str
    length: float
    path: FixedPath | None = None  # fixed guide
    guide: str | None = None  # moving guide link (both ends known)
    g1: str | None = None
    g2: str | None = None
    sigma: float = 1.0
    unit: float = 1e-3
    uname: str = "mm"
    kind: str = "slider"

    @property
    def finds(self):
        return (self.point,)

    @property
    def links(self):
        return (self.link,)

    @property
    def title(self):
        if self.path is None:
            where = f"link {self.guide}"
        elif self.path.label in ("horizontal", "vertical"):
            where = f"the {self.path.label} path"
        else:
            where = f"the path {self.path.label}"
        return f"link {self.link}, slider {self.point} on {where}"

    def line(self, P):
        """A point of the guide line and its unit direction."""
        if self.path is not None:
            (qx, qy), (ux, uy) = self.path.through, self.path.u
            return qx, qy, ux, uy
        (gx, gy), (hx, hy) = P[self.g1], P[self.g2]
        ux, uy = hx - gx, hy - gy
        m = (ux * ux + uy * uy) ** 0.5
        return gx, gy, ux / m, uy / m

    def place(self, P, ctx, sigma=None):
        qx, qy, ux, uy = self.line(P)
        bx, by = P[self.b]
        s = self.sigma if sigma is None else sigma
        return slider_xy(bx, by, qx, qy, ux, uy, self.length, s, ctx, self)

    branching = True

    def singular_why(self, c) -> str:
        return (f"{self.link} is perpendicular to the guide of {self.point} (sine {c:.2g}): a "
                f"dead centre for this step, where the line perpendicular to {self.link} is "
                "parallel to the guide")

    def warning(self, c) -> str:
        return (f"{self.label}: the line perpendicular to {self.link} is nearly parallel to "
                f"the guide (condition {c:.3g}): near a dead centre for this step")

    def limit_why(self) -> str:
        return (f"{self.link} stands perpendicular to the guide of {self.point} (it cannot "
                "reach the guide beyond it)")

    def _why(self, dist):
        u = self.unit
        where = f"path {self.path.label}" if self.path else f"line of {self.guide}"
        return (f"cannot assemble {self.point}: {self.link} = {_mm(self.length, u)} {self.uname} "
                f"< distance of {self.b} from the {where} = {_mm(abs(dist), u)} {self.uname}")

    def emit(self, n):
        X, B, i, j = self.point, self.b, self.index, n[self.link]
        if self.path is not None:
            (qx, qy), (ux, uy) = self.path.through, self.path.u
            line = f"ux_{i} = {ux!r}; uy_{i} = {uy!r}\n"
            args = f"{qx!r}, {qy!r}"
        else:
            G1, G2 = self.g1, self.g2
            line = (f"ux_{i} = {G2}_x - {G1}_x; uy_{i} = {G2}_y - {G1}_y; "
                    f"m = (ux_{i} * ux_{i} + uy_{i} * uy_{i}) ** 0.5; "
                    f"ux_{i} = ux_{i} / m; uy_{i} = uy_{i} / m\n")
            args = f"{G1}_x, {G1}_y"
        pos = (line + f"{X}_x, {X}_y, c_{i} = slider_xy({B}_x, {B}_y, {args}, ux_{i}, uy_{i}, "
               f"{self.length!r}, {self.sigma!r}, ctx, S_{i})")
        if self.path is not None:
            guide_v = f"wx = -{B}_vx; wy = -{B}_vy"
            guide_a = f"cx_{X} = 0.0; cy_{X} = 0.0; tx = 0.0; ty = 0.0"
        else:
            G1, g = self.g1, n[self.guide]
            guide_v = (f"wx = {G1}_vx - w_{g} * ({X}_y - {G1}_y) - {B}_vx; "
                       f"wy = {G1}_vy + w_{g} * ({X}_x - {G1}_x) - {B}_vy")
            guide_a = (f"cx_{X} = -2 * w_{g} * vs_{X} * uy_{i}; "
                       f"cy_{X} = 2 * w_{g} * vs_{X} * ux_{i}\n"
                       f"px = {X}_x - {G1}_x; py = {X}_y - {G1}_y; kg = w_{g} * w_{g}\n"
                       f"tx = {G1}_ax - kg * px - al_{g} * py + cx_{X}; "
                       f"ty = {G1}_ay - kg * py + al_{g} * px + cy_{X}")
        vel = (f"rx_{i} = {X}_x - {B}_x; ry_{i} = {X}_y - {B}_y\n"
               f"d_{i} = safe(rx_{i} * ux_{i} + ry_{i} * uy_{i}, S_{i})\n"
               f"{guide_v}\n"
               f"w_{j} = (ux_{i} * wy - uy_{i} * wx) / d_{i}; "
               f"vs_{X} = -(rx_{i} * wx + ry_{i} * wy) / d_{i}\n"
               f"{X}_vx = {B}_vx - w_{j} * ry_{i}; {X}_vy = {B}_vy + w_{j} * rx_{i}")
        acc = (f"{guide_a}\nk = w_{j} * w_{j}\n"
               f"qx = tx - {B}_ax + k * rx_{i}; qy = ty - {B}_ay + k * ry_{i}\n"
               f"al_{j} = (ux_{i} * qy - uy_{i} * qx) / d_{i}; "
               f"as_{X} = -(rx_{i} * qx + ry_{i} * qy) / d_{i}\n"
               f"{X}_ax = {B}_ax - k * rx_{i} - al_{j} * ry_{i}; "
               f"{X}_ay = {B}_ay - k * ry_{i} + al_{j} * rx_{i}")
        return pos, vel, acc


@dataclass(frozen=True)
class SlottedLink(Step):
    """RPR: a block pinned at known A slides along link K-N that turns about known K.

    Position: N = K + L sigma (A - K) / |A - K|.
    Velocity: ``vA = vK + wG perp(A - K) + vs u``; the two direction lines (perpendicular to
    KA through k, parallel to the link through a) are at right angles:
    ``wG = (vA - vK) x u / -(d.u)``, ``vs = (vA - vK).d / (d.u)`` with d = A - K.
    Acceleration: ``aA = aK - wG^2 d + aG perp(d) + 2 wG vs perp(u) + as u``.
    ``u`` is the guide's direction from its first point to its second, as named.
    Condition: min(1, |KA| / L) (the block near the pivot makes the link's motion ill-defined).
    """

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
    kind: str = "slotted"

    @property
    def finds(self):
        return (self.new,)

    @property
    def links(self):
        return (self.guide,)

    @property
    def title(self):
        return f"block {self.point} sliding on {self.guide}"

    def place(self, P, ctx, sigma=None):
        (kx, ky), (ax, ay) = P[self.known], P[self.point]
        s = self.sigma if sigma is None else sigma
        return slotted_xy(kx, ky, ax, ay, self.length, s, ctx, self)

    branching = True

    def warning(self, c) -> str:
        return (f"{self.label}: block {self.point} is close to {self.known}, the pivot of "
                f"{self.guide} (condition {c:.3g})")

    def limit_why(self) -> str:
        return f"block {self.point} reaches the pivot {self.known} of {self.guide}"

    def condition_column(self):
        return (f"cond step {self.index + 1}", "1", f"|{self.known}{self.point}| / {self.guide}")

    def at_pivot(self):
        return SingularStepError(f"block {self.point} is at {self.known}, the pivot of "
                                 f"{self.guide}: the link's direction is undefined",
                                 step=self.label)

    def emit(self, n):
        A, K, N, i, g = self.point, self.known, self.new, self.index, n[self.guide]
        F1, F2, L = self.first, self.second, repr(self.length)
        pos = (f"{N}_x, {N}_y, c_{i} = slotted_xy({K}_x, {K}_y, {A}_x, {A}_y, {L}, "
               f"{self.sigma!r}, ctx, S_{i})")
        vel = (f"ux_{i} = ({F2}_x - {F1}_x) / {L}; uy_{i} = ({F2}_y - {F1}_y) / {L}\n"
               f"dx_{i} = {A}_x - {K}_x; dy_{i} = {A}_y - {K}_y\n"
               f"d_{i} = safe(-(dx_{i} * ux_{i} + dy_{i} * uy_{i}), S_{i})\n"
               f"ex = {A}_vx - {K}_vx; ey = {A}_vy - {K}_vy\n"
               f"w_{g} = (ex * uy_{i} - ux_{i} * ey) / d_{i}; "
               f"vs_{A} = -(dx_{i} * ex + dy_{i} * ey) / d_{i}\n"
               f"{N}_vx = {K}_vx - w_{g} * ({N}_y - {K}_y); "
               f"{N}_vy = {K}_vy + w_{g} * ({N}_x - {K}_x)")
        acc = (f"cx_{A} = -2 * w_{g} * vs_{A} * uy_{i}; cy_{A} = 2 * w_{g} * vs_{A} * ux_{i}\n"
               f"k = w_{g} * w_{g}\n"
               f"ex = {A}_ax - {K}_ax + k * dx_{i} - cx_{A}; "
               f"ey = {A}_ay - {K}_ay + k * dy_{i} - cy_{A}\n"
               f"al_{g} = (ex * uy_{i} - ux_{i} * ey) / d_{i}; "
               f"as_{A} = -(dx_{i} * ex + dy_{i} * ey) / d_{i}\n"
               f"px = {N}_x - {K}_x; py = {N}_y - {K}_y\n"
               f"{N}_ax = {K}_ax - k * px - al_{g} * py; {N}_ay = {K}_ay - k * py + al_{g} * px")
        return pos, vel, acc


@dataclass(frozen=True)
class Carried(Step):
    """X = P + lam (Q - P) + mu perp(Q - P); the same for v and a (the image point)."""

    point: str
    link: str
    p: str
    q: str
    lam: float
    mu: float
    how: str = ""
    kind: str = "carried"

    @property
    def finds(self):
        return (self.point,)

    @property
    def links(self):
        return ()

    @property
    def title(self):
        return f"point {self.point} on {self.link}"

    def place(self, P, ctx, sigma=None):
        (px, py), (qx, qy) = P[self.p], P[self.q]
        dx, dy = qx - px, qy - py
        return px + self.lam * dx - self.mu * dy, py + self.lam * dy + self.mu * dx, 1.0

    def emit(self, n):
        X, p, q, lam, mu = self.point, self.p, self.q, repr(self.lam), repr(self.mu)
        out = []
        for s in ("", "v", "a"):
            dx, dy = f"({q}_{s}x - {p}_{s}x)", f"({q}_{s}y - {p}_{s}y)"
            x, y = f"{X}_{s}x = {p}_{s}x", f"{X}_{s}y = {p}_{s}y"
            if self.lam:
                x, y = f"{x} + {lam} * {dx}", f"{y} + {lam} * {dy}"
            if self.mu:
                x, y = f"{x} - {mu} * {dy}", f"{y} + {mu} * {dx}"
            out.append(f"{x}; {y}")
        out[0] += f"; c_{self.index} = 1.0"
        return tuple(out)


@dataclass(frozen=True)
class Plan:
    """An ordered tuple of construction steps for one scene, branches chosen.

    ``print(plan)`` lists the steps as a hand solution would take them.
    """

    steps: tuple
    ground: dict
    scene: Scene = field(repr=False)
    notes: tuple = ()
    fixed_links: dict = field(default_factory=dict)
    pins: tuple = ()  # (point, radius, body names, their links or None, "a|b" keys, (i, j))
    _compiled: dict = field(default_factory=dict, repr=False, compare=False)

    def bodies_at(self, point) -> tuple:
        """The bodies a pin at ``point`` joins: (name, link whose omega it has, or None for
        a body that does not turn: the ground, a block on a fixed path)."""
        sc = self.scene
        out = []
        if point in sc.ground:
            out.append(("ground", None))
        for lk in sc.links:
            if point in lk.points:
                out.append((lk.key, lk.key))
        cp = sc.carried(point)
        if cp is not None:
            out.append((cp.link, cp.link))
        sl = sc.slider(point)
        if isinstance(sl, FixedPath):
            out.append((f"block {point}", None))
        elif isinstance(sl, GuideSlider):
            out.append((f"block {point}", sc.link(sl.guide).key))
        return tuple(out)

    def __str__(self):
        lines = [f"plan: {len(self.steps)} steps"]
        for st in self.steps:
            lines.append(f"  {st.index + 1}. {st.title}: finds {', '.join(st.finds)}")
        return "\n".join(lines)

    def evaluate(self, ctx, *, velocities=True, accelerations=True):
        """Run the plan: positions, then the velocity polygon, then the acceleration one.

        Returns dicts ``P, V, A`` (point -> (x, y)), ``W, Al`` (link -> omega, alpha) and
        ``S`` (slider -> [vs, as, coriolis]); the phases not asked for come back empty.
        With ``Context(..., array=True)`` every value is an array over the crank angles.
        """
        try:
            return self.kernel(ctx.theta, ctx.omega, ctx.alpha, ctx, velocities,
                               accelerations)
        except PolygonMethodError as exc:  # name the scene file in the one-line message
            raise exc.located(self.scene.file)

    @property
    def kernel(self):
        """The plan compiled to one straight-line Python function (built once).

        Each step contributes its lines (see the steps' ``emit``); the same function
        serves a float crank angle and an array of them.
        """
        fn = self._compiled.get("kernel")
        if fn is None:
            fn = self._compiled["kernel"] = self._build_kernel()
        return fn

    def kernel_source(self) -> str:
        return self._source()[0]

    def _source(self):
        sc = self.scene
        n = {lk.key: j for j, lk in enumerate(sc.links)}
        head = ["def kernel(theta, omega, alpha, ctx, vel, acc):",
                "    cos = ctx.cos; sin = ctx.sin; safe = ctx.safe"]
        for name, (x, y) in self.ground.items():
            head.append(f"    {name}_x = {x!r}; {name}_y = {y!r}; "
                        f"{name}_vx = {name}_vy = {name}_ax = {name}_ay = 0.0")
        for key in self.fixed_links:
            head.append(f"    w_{n[key]} = al_{n[key]} = 0.0")
        parts = [st.emit(n) for st in self.steps]
        body = list(head)

        def block(lines):
            for text in lines:
                body.extend("    " + line for line in text.split("\n"))

        pts = sc.point_names
        sliders = [s.point for s in sc.sliders]
        block(p[0] for p in parts)
        body.append("    cond = ctx.cond = {" + ", ".join(f"{st.index}: c_{st.index}"
                                                   for st in self.steps) + "}")
        body.append("    if not ctx.array: check(cond)")
        body.append("    P = {" + ", ".join(f"{p!r}: ({p}_x, {p}_y)" for p in pts) + "}")
        body.append("    if not vel: return P, {}, {}, {}, {}, {}")
        block(p[1] for p in parts)
        body.append("    V = {" + ", ".join(f"{p!r}: ({p}_vx, {p}_vy)" for p in pts) + "}")
        body.append("    W = {" + ", ".join(f"{lk.key!r}: w_{j}" for j, lk in
                                             enumerate(sc.links)) + "}")
        rub = []
        for point, radius, _, links, _, pairs in self.pins:
            w = [f"w_{n[lk]}" if lk is not None else "0.0" for lk in links]
            vals = "".join(f"abs({w[i]} - {w[j]}) * {radius!r}, " for i, j in pairs)
            rub.append(f"{point!r}: ({vals})")
        body.append("    ctx.rubbing = {" + ", ".join(rub) + "}")
        body.append("    if not acc: return P, V, {}, W, {}, {" + ", ".join(
            f"{p!r}: [vs_{p}, None, (0.0, 0.0)]" for p in sliders) + "}")
        block(p[2] for p in parts)
        body.append("    A = {" + ", ".join(f"{p!r}: ({p}_ax, {p}_ay)" for p in pts) + "}")
        body.append("    Al = {" + ", ".join(f"{lk.key!r}: al_{j}" for j, lk in
                                              enumerate(sc.links)) + "}")
        body.append("    S = {" + ", ".join(f"{p!r}: [vs_{p}, as_{p}, (cx_{p}, cy_{p})]"
                                             for p in sliders) + "}")
        body.append("    return P, V, A, W, Al, S")
        env = {"dyad_xy": dyad_xy, "slider_xy": slider_xy, "slotted_xy": slotted_xy,
               "check": self._check}
        env.update({f"S_{st.index}": st for st in self.steps})
        return "\n".join(body) + "\n", env

    def _build_kernel(self):
        src, env = self._source()
        code = compile(src, f"<plan of {self.scene.file or 'scene'}>", "exec")
        exec(code, env)
        return env["kernel"]

    def _check(self, cond):
        for st in self.steps:
            c = cond[st.index]
            if c < TOL.singular:
                raise SingularStepError(st.singular_why(c), step=st.label)


# --------------------------------------------------------------------------- compiling


def compile_plan(scene: Scene) -> Plan:
    """Compile the scene's constraint graph into a plan and choose each assembly branch.

    Raises :class:`MobilityError` when the scene is not a one-degree-of-freedom mechanism
    that these steps can build, :class:`AssemblyError` when it cannot be put together at the
    given crank angle.
    """
    cached = scene._cache.get("plan")
    if cached is not None:
        return cached
    try:
        plan = _Compiler(scene).run()
    except PolygonMethodError as exc:  # name the scene file in the one-line message
        raise exc.located(scene.file)
    scene._cache["plan"] = plan
    return plan


def gruebler(scene: Scene) -> int:
    """Mobility M = 3 (n - 1) - 2 j (lower pairs only): n bodies incl. ground and blocks."""
    ground = set(scene.ground)
    moving = [lk for lk in scene.links if not (lk.p in ground and lk.q in ground)]
    n = 1 + len(moving) + len(scene.sliders)
    bodies_at = {}
    for lk in moving:
        for p in lk.points:
            bodies_at.setdefault(p, set()).add(lk.key)
    for cp in scene.points:
        bodies_at.setdefault(cp.name, set()).add(scene.link(cp.link).key)
    for p in ground:
        bodies_at.setdefault(p, set()).add("ground")
    for s in scene.sliders:
        bodies_at.setdefault(s.point, set()).add(f"block {s.point}")
    j = sum(len(b) - 1 for b in bodies_at.values()) + len(scene.sliders)
    return 3 * (n - 1) - 2 * j


class _Compiler:
    def __init__(self, scene: Scene):
        self.scene = scene
        self.unit = scene.length_unit
        self.uname = scene.units
        self.ctx = Context(scene.input.angle, scene.input.omega, scene.input.alpha)
        self.P = dict(scene.ground)
        self.steps = []
        self.used_links = {lk.key for lk in scene.links
                           if lk.p in scene.ground and lk.q in scene.ground}
        self.used_sliders = set()
        self.notes = []
        self._bodies = {}

    def add(self, step):
        step = self.choose_branch(step)
        x, y, _ = step.place(self.P, self.ctx)
        self.P[step.finds[0]] = (x, y)
        self.steps.append(step)
        self.used_links.update(step.links)

    def run(self) -> Plan:
        sc = self.scene
        inp = sc.input
        crank = sc.link(inp.crank)
        self.add(Crank(0, crank.key, inp.pivot, inp.tip, crank.length))
        progress = True
        while progress:
            progress = False
            for name in sc.point_names:
                if name in self.P:
                    continue
                if self.try_point(name):
                    progress = True
                    break
            if not progress:
                progress = self.try_slotted()
        self.finish()
        fixed = {lk.key: 0.0 for lk in sc.links if lk.p in sc.ground and lk.q in sc.ground}
        plan = Plan(tuple(self.steps), dict(sc.ground), sc, tuple(self.notes), fixed)
        pins = []
        for pin in sc.pins:
            joined = plan.bodies_at(pin.point)
            pairs = tuple((f"{a[0]}|{b[0]}", i, j) for i, a in enumerate(joined)
                          for j, b in enumerate(joined) if j > i)
            pins.append((pin.point, pin.radius, tuple(b for b, _ in joined),
                         tuple(lk for _, lk in joined), tuple(k for k, _, _ in pairs),
                         tuple((i, j) for _, i, j in pairs)))
        pins = tuple(pins)
        return replace(plan, pins=pins)

    def known_link(self, link):
        return link.p in self.P and link.q in self.P

    def body(self, key) -> dict:
        """Points of link ``key`` in its own frame: P at (0, 0), Q at (L, 0), carried points
        at (lam L, mu L). A link with carried points is one rigid body (a plate)."""
        b = self._bodies.get(key)
        if b is None:
            sc = self.scene
            lk = sc.link(key)
            b = {lk.p: (0.0, 0.0), lk.q: (lk.length, 0.0)}
            for cp in sc.points:
                if cp.link == lk.key:
                    b[cp.name] = (cp.lam * lk.length, cp.mu * lk.length)
            self._bodies[key] = b
        return b

    def bodies_of(self, name):
        return [lk.key for lk in self.scene.links if name in self.body(lk.key)]

    def carried_step(self, name, key, refs, how=""):
        """X = R1 + lam (R2 - R1) + mu perp(R2 - R1) from the body's own frame."""
        b = self.body(key)
        (x1, y1), (x2, y2), (x, y) = b[refs[0]], b[refs[1]], b[name]
        dx, dy = x2 - x1, y2 - y1
        n2 = dx * dx + dy * dy
        lam = ((x - x1) * dx + (y - y1) * dy) / n2
        mu = (dx * (y - y1) - dy * (x - x1)) / n2
        return Carried(len(self.steps), name, key, refs[0], refs[1], lam, mu, how)

    def try_point(self, name) -> bool:
        sc = self.scene
        cp = sc.carried(name)
        free = []  # (body link key, known point K of it, |KX|)
        for key in self.bodies_of(name):
            b = self.body(key)
            known = [p for p in b if p in self.P]
            lk = sc.link(key)
            if len(known) >= 2:
                ends = [p for p in lk.points if p in self.P]
                refs = ends if len(ends) == 2 else known[:2]
                if key not in self.used_links and name in lk.points:
                    continue  # both ends known, the link unused: redundant, reported later
                how = cp.how if cp is not None and cp.link == key else ""
                self.add(self.carried_step(name, key, refs, how))
                return True
            if len(known) == 1 and key not in self.used_links:
                k = known[0]
                (kx, ky), (x, y) = b[k], b[name]
                free.append((key, k, math.hypot(x - kx, y - ky)))
        sl = sc.slider(name)
        if sl is not None and name not in self.used_sliders and free:
            key, k, length = free[0]
            if isinstance(sl, FixedPath):
                self.used_sliders.add(name)
                self.add(SliderDyad(len(self.steps), name, k, key, length,
                                    path=sl, unit=self.unit, uname=self.uname))
                return True
            guide = sc.link(sl.guide)
            if self.known_link(guide) and guide.key in self.used_links:
                self.used_sliders.add(name)
                self.add(SliderDyad(len(self.steps), name, k, key, length,
                                    guide=guide.key, g1=sl.first, g2=sl.second,
                                    unit=self.unit, uname=self.uname))
                return True
        if len(free) >= 2:
            (k1, b1, l1), (k2, b2, l2) = free[0], free[1]
            self.add(Dyad(len(self.steps), name, b1, k1, l1, b2, k2, l2, unit=self.unit,
                          uname=self.uname))
            return True
        return False

    def try_slotted(self) -> bool:
        sc = self.scene
        for sl in sc.sliders:
            if not isinstance(sl, GuideSlider) or sl.point in self.used_sliders:
                continue
            guide = sc.link(sl.guide)
            if sl.point not in self.P or guide.key in self.used_links:
                continue
            ends = [p for p in guide.points if p in self.P]
            if len(ends) != 1:
                continue
            known = ends[0]
            self.used_sliders.add(sl.point)
            self.add(SlottedLink(len(self.steps), sl.point, guide.key, known,
                                 guide.other(known), guide.length, sl.first, sl.second,
                                 unit=self.unit, uname=self.uname))
            return True
        return False

    def choose_branch(self, step):
        if not isinstance(step, (Dyad, SliderDyad, SlottedLink)):
            return step
        sc = self.scene
        name = step.finds[0]
        plus = step.place(self.P, self.ctx, 1.0)[:2]
        minus = step.place(self.P, self.ctx, -1.0)[:2]
        hint = sc.assembly.get(name)
        if hint is None:
            default = self.default_hint(step)
            sigma = self.pick(name, default, plus, minus, step, default=True)
            sep = math.dist(plus, minus)
            if sep > 1e-9 * step_scale(step):
                side = default if isinstance(default, str) else "farther along the guide"
                self.notes.append(f"{name}: of its two positions the one {side} was taken "
                                  f"(default; set [assembly] {name} to choose)")
        else:
            sigma = self.pick(name, hint, plus, minus, step)
        return replace(step, sigma=sigma)

    def default_hint(self, step):
        if isinstance(step, SliderDyad):
            if step.path is not None:
                ux, uy = step.path.u
            else:
                (x1, y1), (x2, y2) = self.P[step.g1], self.P[step.g2]
                ux, uy = x2 - x1, y2 - y1
            return (ux, uy)  # along the guide's direction
        if isinstance(step, SlottedLink):
            return "block side"
        return "above"

    def pick(self, name, hint, plus, minus, step, default=False):
        sep = math.dist(plus, minus)
        scale = step_scale(step)
        if sep <= 1e-12 * scale:
            return 1.0
        if hint == "block side":
            return 1.0
        if isinstance(hint, tuple) and default:
            ux, uy = hint
            d = (plus[0] - minus[0]) * ux + (plus[1] - minus[1]) * uy
            return 1.0 if d >= 0 else -1.0
        if isinstance(hint, str):
            axis, want = {"above": (1, 1), "below": (1, -1), "right": (0, 1),
                          "left": (0, -1)}[hint]
            d = (plus[axis] - minus[axis]) * want
            if abs(d) <= 1e-9 * scale:
                if default:  # level: take the right-hand one
                    return 1.0 if plus[0] >= minus[0] else -1.0
                other = "left/right" if axis == 1 else "above/below"
                raise AssemblyError(
                    f"assembly {name} = \"{hint}\" matches neither position: both are at the "
                    f"same {'height' if axis == 1 else 'x'} ({self.fmt(plus)} and "
                    f"{self.fmt(minus)}); use {other} or a rough position [x, y]",
                    key=f"[assembly] {name}", file=self.scene.file)
            return 1.0 if d > 0 else -1.0
        d1, d2 = math.dist(hint, plus), math.dist(hint, minus)
        reach = max(getattr(step, "l1", 0), getattr(step, "l2", 0),
                    getattr(step, "length", 0))
        if min(d1, d2) > reach or abs(d1 - d2) <= 1e-9 * scale:
            raise AssemblyError(
                f"assembly {name} = {self.fmt(hint)} matches neither position of {name} "
                f"({self.fmt(plus)} or {self.fmt(minus)}); give a rough position near the "
                "one the figure shows", key=f"[assembly] {name}",
                file=self.scene.file)
        return 1.0 if d1 < d2 else -1.0

    def fmt(self, xy):
        return f"[{_mm(xy[0], self.unit)}, {_mm(xy[1], self.unit)}]"

    def finish(self):
        sc = self.scene
        missing = [p for p in sc.point_names if p not in self.P]
        extra_links = [lk.key for lk in sc.links if lk.key not in self.used_links]
        extra_sliders = [s.point for s in sc.sliders if s.point not in self.used_sliders]
        if not missing and not extra_links and not extra_sliders:
            return
        m = gruebler(sc)
        mob = f"mobility {m} (Gruebler: 3(n-1) - 2j)"
        if missing:
            if m > 1:
                why = (f"{mob}: the mechanism is under-constrained; "
                       f"{', '.join(missing)} {'is' if len(missing) == 1 else 'are'} not "
                       "determined by the crank (add the missing link or slider)")
            elif m < 1:
                why = (f"{mob}: the mechanism is over-constrained (a structure); "
                       f"{', '.join(missing)} cannot move")
            else:
                why = (f"{', '.join(missing)} cannot be found by the construction steps "
                       "(crank, dyad, slider, slotted link, carried point): the chain needs "
                       "a construction these steps do not make, or a part is missing")
            loose = [lk.key for lk in sc.links
                     if lk.key not in self.used_links and (lk.p in missing or lk.q in missing)]
            where = f"[links] {', '.join(loose)}" if loose else "[links]"
            raise MobilityError(why, file=sc.file, key=where)
        parts = []
        if extra_links:
            parts.append(f"link{'s' if len(extra_links) > 1 else ''} "
                         f"{', '.join(extra_links)} {'is' if len(extra_links) == 1 else 'are'}"
                         " redundant (both ends already fixed by the other links): remove "
                         f"{'it' if len(extra_links) == 1 else 'them'} or check the scene")
        if extra_sliders:
            parts.append(f"slider{'s' if len(extra_sliders) > 1 else ''} "
                         f"{', '.join(extra_sliders)} cannot slide (already fixed)")
        where = (f"[links] {', '.join(extra_links)}" if extra_links
                 else f"[sliders] {', '.join(extra_sliders)}")
        raise MobilityError(f"{mob}: over-constrained: " + "; ".join(parts), file=sc.file,
                            key=where)


def step_scale(step) -> float:
    return max(getattr(step, "l1", 0.0), getattr(step, "l2", 0.0), getattr(step, "length", 0.0),
               1e-9)
