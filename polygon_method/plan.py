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

Every kernel is written with arithmetic operators on ``(x, y)`` pairs so that one code path
serves a single position (floats) and a whole sweep (numpy arrays). ``perp(x, y) = (-y, x)``
turns a vector 90 deg counter-clockwise; ``omega x r = omega perp(r)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from .errors import TOL, AssemblyError, MobilityError, PolygonMethodError, SingularStepError
from .scene import FixedPath, GuideSlider, Scene, split_name

__all__ = ["Plan", "compile_plan", "Crank", "Dyad", "SliderDyad", "SlottedLink", "Carried",
           "Context"]


def _mm(x: float, unit_len: float) -> str:
    return f"{x / unit_len:.6g}"


class Context:
    """What a kernel needs besides the state: the input motion and the maths for floats
    or arrays. In scalar mode a failing step raises; in array mode it is masked."""

    def __init__(self, theta, omega, alpha, *, array=False, scene=None):
        self.theta, self.omega, self.alpha = theta, omega, alpha
        self.array = array
        self.scene = scene
        self.cond = {}
        self.bad = None  # array mode: positions where a step failed
        self.failures = {}  # array mode: step index -> mask
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


# --------------------------------------------------------------------------- steps


@dataclass(frozen=True)
class Step:
    index: int

    @property
    def label(self) -> str:
        return f"step {self.index + 1} ({self.title})"


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

    def positions(self, P, ctx):
        ox, oy = P[self.pivot]
        r = self.length
        P[self.tip] = (ox + r * ctx.cos(ctx.theta), oy + r * ctx.sin(ctx.theta))
        ctx.condition(self, 1.0)

    def velocities(self, P, V, W, S, ctx):
        (ox, oy), (x, y) = P[self.pivot], P[self.tip]
        rx, ry = x - ox, y - oy
        w = ctx.omega
        vox, voy = V[self.pivot]
        V[self.tip] = (vox - w * ry, voy + w * rx)
        W[self.link] = w

    def accelerations(self, P, V, A, W, Al, S, ctx):
        (ox, oy), (x, y) = P[self.pivot], P[self.tip]
        rx, ry = x - ox, y - oy
        w, al = ctx.omega, ctx.alpha
        aox, aoy = A[self.pivot]
        A[self.tip] = (aox - w * w * rx - al * ry, aoy - w * w * ry + al * rx)
        Al[self.link] = al


@dataclass(frozen=True)
class Dyad(Step):
    """RRR: point X with XB = l1 to known B and XD = l2 to known D.

    Position: along BD by ``(l1^2 - l2^2 + e^2) / 2e``, off it by ``h`` (sign = branch).
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

    def candidates(self, P, ctx):
        (bx, by), (dx, dy) = P[self.b], P[self.d]
        ex, ey = dx - bx, dy - by
        e2 = ex * ex + ey * ey
        l1, l2 = self.l1, self.l2
        e = e2 ** 0.5
        if not ctx.array and e == 0:
            if l1 == l2:
                raise SingularStepError(f"{self.b} and {self.d} coincide and {self.link1} = "
                                        f"{self.link2}: {self.point} may be anywhere on a circle",
                                        step=self.label)
            raise AssemblyError(self._why(e), step=self.label)
        e = ctx.safe(e, self)
        # 4 e^2 h^2 = (l1+l2+e)(l1+l2-e)(e+l1-l2)(e-l1+l2): exact near a toggle
        q = (l1 + l2 + e) * (l1 + l2 - e) * (e + l1 - l2) * (e - l1 + l2)
        h = ctx.root(q, (l1 * l2) ** 2, self, lambda: self._why(e)) / (2 * e)
        along = (l1 * l1 - l2 * l2 + e2) / (2 * e)
        ux, uy = ex / e, ey / e
        mx, my = bx + along * ux, by + along * uy
        return (mx, my), (-uy * h, ux * h), e, h

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
                    f"{_mm(e, u)} {self.uname} (short by {_mm(e - self.l1 - self.l2, u)} {self.uname})")
        return (f"cannot assemble {self.point}: |{self.side(1)} - {self.side(2)}| = "
                f"{_mm(abs(self.l1 - self.l2), u)} {self.uname} > {self.b}{self.d} = "
                f"{_mm(e, u)} {self.uname} (by {_mm(abs(self.l1 - self.l2) - e, u)} {self.uname})")

    unit: float = 1e-3
    uname: str = "mm"

    def positions(self, P, ctx):
        (mx, my), (hx, hy), e, h = self.candidates(P, ctx)
        s = self.sigma
        P[self.point] = (mx + s * hx, my + s * hy)
        ctx.condition(self, e * h / (self.l1 * self.l2))

    def velocities(self, P, V, W, S, ctx):
        (x, y), (bx, by), (dx, dy) = P[self.point], P[self.b], P[self.d]
        r1x, r1y, r2x, r2y = x - bx, y - by, x - dx, y - dy
        c = ctx.safe(r1x * r2y - r1y * r2x, self)
        (vbx, vby), (vdx, vdy) = V[self.b], V[self.d]
        wx, wy = vdx - vbx, vdy - vby
        w1 = (wx * r2x + wy * r2y) / c
        w2 = (wx * r1x + wy * r1y) / c
        V[self.point] = (vbx - w1 * r1y, vby + w1 * r1x)
        W[self.link1], W[self.link2] = w1, w2

    def accelerations(self, P, V, A, W, Al, S, ctx):
        (x, y), (bx, by), (dx, dy) = P[self.point], P[self.b], P[self.d]
        r1x, r1y, r2x, r2y = x - bx, y - by, x - dx, y - dy
        c = ctx.safe(r1x * r2y - r1y * r2x, self)
        w1, w2 = W[self.link1], W[self.link2]
        (abx, aby), (adx, ady) = A[self.b], A[self.d]
        k1, k2 = w1 * w1, w2 * w2
        qx = (adx - k2 * r2x) - (abx - k1 * r1x)
        qy = (ady - k2 * r2y) - (aby - k1 * r1y)
        a1 = (qx * r2x + qy * r2y) / c
        a2 = (qx * r1x + qy * r1y) / c
        A[self.point] = (abx - k1 * r1x - a1 * r1y, aby - k1 * r1y + a1 * r1x)
        Al[self.link1], Al[self.link2] = a1, a2


@dataclass(frozen=True)
class SliderDyad(Step):
    """RRP: point X with XB = l to known B, sliding on a guide line (fixed or a moving link).

    Position: X = Q + s u on the guide, s = -(Q - B).u +- sqrt(l^2 - ((Q - B) x u)^2).
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

    def _line(self, P):
        if self.path is not None:
            (qx, qy), (ux, uy) = self.path.through, self.path.u
            return qx, qy, ux, uy
        (gx, gy), (hx, hy) = P[self.g1], P[self.g2]
        ux, uy = hx - gx, hy - gy
        n = (ux * ux + uy * uy) ** 0.5
        return gx, gy, ux / n, uy / n

    def candidates(self, P, ctx):
        qx, qy, ux, uy = self._line(P)
        bx, by = P[self.b]
        wx, wy = qx - bx, qy - by
        b = wx * ux + wy * uy
        dist = wx * uy - wy * ux  # signed distance of B from the line
        ell = self.length
        half = ctx.root((ell - dist) * (ell + dist), ell * ell, self, lambda: self._why(dist))
        base = (qx - b * ux, qy - b * uy)
        return base, (half * ux, half * uy), half

    def _why(self, dist):
        u = self.unit
        where = f"path {self.path.label}" if self.path else f"line of {self.guide}"
        return (f"cannot assemble {self.point}: {self.link} = {_mm(self.length, u)} {self.uname} "
                f"< distance of {self.b} from the {where} = {_mm(abs(dist), u)} {self.uname}")

    def positions(self, P, ctx):
        base, (hx, hy), half = self.candidates(P, ctx)
        s = self.sigma
        P[self.point] = (base[0] + s * hx, base[1] + s * hy)
        ctx.condition(self, half / self.length)

    def _guide_point(self, P, V, W, x, y):
        """Velocity of the guide's point coinciding with X (zero on a fixed path)."""
        if self.path is not None:
            return 0.0, 0.0
        (gx, gy), (vgx, vgy) = P[self.g1], V[self.g1]
        wg = W[self.guide]
        return vgx - wg * (y - gy), vgy + wg * (x - gx)

    def velocities(self, P, V, W, S, ctx):
        (x, y), (bx, by) = P[self.point], P[self.b]
        _, _, ux, uy = self._line(P)
        rx, ry = x - bx, y - by
        den = ctx.safe(rx * ux + ry * uy, self)
        vgx, vgy = self._guide_point(P, V, W, x, y)
        vbx, vby = V[self.b]
        wx, wy = vgx - vbx, vgy - vby
        w = (ux * wy - uy * wx) / den
        vs = -(rx * wx + ry * wy) / den
        V[self.point] = (vbx - w * ry, vby + w * rx)
        W[self.link] = w
        S[self.point] = [vs, None, (0.0, 0.0)]

    def accelerations(self, P, V, A, W, Al, S, ctx):
        (x, y), (bx, by) = P[self.point], P[self.b]
        _, _, ux, uy = self._line(P)
        rx, ry = x - bx, y - by
        den = ctx.safe(rx * ux + ry * uy, self)
        w = W[self.link]
        vs = S[self.point][0]
        if self.path is None:
            (gx, gy), (agx, agy) = P[self.g1], A[self.g1]
            wg, ag = W[self.guide], Al[self.guide]
            px, py = x - gx, y - gy
            cx, cy = -2 * wg * vs * uy, 2 * wg * vs * ux
            tx = agx - wg * wg * px - ag * py + cx
            ty = agy - wg * wg * py + ag * px + cy
        else:
            cx = cy = tx = ty = 0.0
        abx, aby = A[self.b]
        qx, qy = tx - abx + w * w * rx, ty - aby + w * w * ry
        al = (ux * qy - uy * qx) / den
        a_s = -(rx * qx + ry * qy) / den
        A[self.point] = (abx - w * w * rx - al * ry, aby - w * w * ry + al * rx)
        Al[self.link] = al
        S[self.point][1] = a_s
        S[self.point][2] = (cx, cy)


@dataclass(frozen=True)
class SlottedLink(Step):
    """RPR: a block pinned at known A slides along link K-U that turns about known K.

    Position: U = K + L sigma (A - K) / |A - K|.
    Velocity: ``vA = vK + wG perp(A - K) + vs u``; the two lines (perpendicular to KA through
    k, parallel to the link through a) are at right angles, so ``wG = (vA - vK) x ... / |KA|``.
    Acceleration: ``aA = aK - wG^2 (A - K) + aG perp(A - K) + 2 wG vs perp(u) + as u``.
    ``u`` is the guide's direction from its first point to its second, as named.
    Condition: |KA| / L (the block near the pivot makes the lever's motion ill-defined).
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

    def candidates(self, P, ctx):
        (kx, ky), (ax, ay) = P[self.known], P[self.point]
        dx, dy = ax - kx, ay - ky
        m = (dx * dx + dy * dy) ** 0.5
        if not ctx.array and m <= TOL.singular * self.length:
            raise SingularStepError(f"block {self.point} is at {self.known}, the pivot of "
                                    f"{self.guide}: the link's direction is undefined",
                                    step=self.label)
        m = ctx.safe(m, self)
        L = self.length
        return (kx, ky), (L * dx / m, L * dy / m), m

    def positions(self, P, ctx):
        (kx, ky), (hx, hy), m = self.candidates(P, ctx)
        s = self.sigma
        P[self.new] = (kx + s * hx, ky + s * hy)
        c = m / self.length
        ctx.condition(self, ctx.np.minimum(c, 1.0) if ctx.array else min(c, 1.0))

    def _u(self, P):
        (x1, y1), (x2, y2) = P[self.first], P[self.second]
        L = self.length
        return (x2 - x1) / L, (y2 - y1) / L

    def velocities(self, P, V, W, S, ctx):
        (kx, ky), (ax, ay) = P[self.known], P[self.point]
        ux, uy = self._u(P)
        dx, dy = ax - kx, ay - ky
        (vkx, vky), (vax, vay) = V[self.known], V[self.point]
        ex, ey = vax - vkx, vay - vky
        # [perp(d) u] [w, vs] = e;  det = -(d.u)
        det = ctx.safe(-(dx * ux + dy * uy), self)
        w = (ex * uy - ux * ey) / det
        vs = -(dx * ex + dy * ey) / det
        (nx, ny) = P[self.new]
        V[self.new] = (vkx - w * (ny - ky), vky + w * (nx - kx))
        W[self.guide] = w
        S[self.point] = [vs, None, (0.0, 0.0)]

    def accelerations(self, P, V, A, W, Al, S, ctx):
        (kx, ky), (ax, ay) = P[self.known], P[self.point]
        ux, uy = self._u(P)
        dx, dy = ax - kx, ay - ky
        w = W[self.guide]
        vs = S[self.point][0]
        (akx, aky), (aax, aay) = A[self.known], A[self.point]
        cx, cy = -2 * w * vs * uy, 2 * w * vs * ux
        ex = aax - akx + w * w * dx - cx
        ey = aay - aky + w * w * dy - cy
        det = ctx.safe(-(dx * ux + dy * uy), self)
        al = (ex * uy - ux * ey) / det
        a_s = -(dx * ex + dy * ey) / det
        nx, ny = P[self.new]
        px, py = nx - kx, ny - ky
        A[self.new] = (akx - w * w * px - al * py, aky - w * w * py + al * px)
        Al[self.guide] = al
        S[self.point][1] = a_s
        S[self.point][2] = (cx, cy)


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

    def _map(self, D):
        (px, py), (qx, qy) = D[self.p], D[self.q]
        dx, dy = qx - px, qy - py
        lam, mu = self.lam, self.mu
        return (px + lam * dx - mu * dy, py + lam * dy + mu * dx)

    def positions(self, P, ctx):
        P[self.point] = self._map(P)
        ctx.condition(self, 1.0)

    def velocities(self, P, V, W, S, ctx):
        V[self.point] = self._map(V)

    def accelerations(self, P, V, A, W, Al, S, ctx):
        A[self.point] = self._map(A)


# --------------------------------------------------------------------------- the plan


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
    pins: tuple = ()  # (point, radius, body names, their links or None, (("a|b", i, j), ...))

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
        ``S`` (slider -> [vs, as, coriolis]).
        """
        zero = (0.0, 0.0)
        P = dict(self.ground)
        try:
            for st in self.steps:
                st.positions(P, ctx)
            if not ctx.array:
                self._check(ctx)
        except PolygonMethodError as exc:  # name the scene file in the one-line message
            raise exc.located(self.scene.file)
        V, W, S = dict.fromkeys(self.ground, zero), dict(self.fixed_links), {}
        A, Al = dict.fromkeys(self.ground, zero), dict(self.fixed_links)
        if velocities:
            for st in self.steps:
                st.velocities(P, V, W, S, ctx)
        if accelerations:
            for st in self.steps:
                st.accelerations(P, V, A, W, Al, S, ctx)
        return P, V, A, W, Al, S

    def _check(self, ctx):
        for st in self.steps:
            c = ctx.cond.get(st.index, 1.0)
            if c < TOL.singular:
                raise SingularStepError(_singular_why(st, c), step=st.label)

    def step_for(self, point):
        return next((s for s in self.steps if point in s.finds), None)


def _singular_why(st, c):
    if isinstance(st, Dyad):
        return (f"{st.link1} and {st.link2} are in line (transmission angle "
                f"{math.degrees(math.asin(min(c, 1.0))):.3g} deg): a toggle position, where the "
                f"direction lines perpendicular to {st.link1} and {st.link2} are parallel and "
                f"the velocity of {st.point} is indeterminate")
    if isinstance(st, SliderDyad):
        return (f"{st.link} is perpendicular to the guide of {st.point} (sine {c:.2g}): a dead "
                f"centre for this step, where the line perpendicular to {st.link} is parallel "
                "to the guide")
    return f"the step is singular (condition {c:.2g})"


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
        self.ctx = Context(scene.input.angle, scene.input.omega, scene.input.alpha,
                           scene=scene)
        self.P = dict(scene.ground)
        self.steps = []
        self.used_links = {lk.key for lk in scene.links
                           if lk.p in scene.ground and lk.q in scene.ground}
        self.used_sliders = set()
        self.notes = []
        self._bodies = {}

    def add(self, step):
        step = self.choose_branch(step)
        step.positions(self.P, self.ctx)
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
                         tuple(lk for _, lk in joined), pairs))
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
        base, off, *_ = step.candidates(self.P, self.ctx)
        plus = (base[0] + off[0], base[1] + off[1])
        minus = (base[0] - off[0], base[1] - off[1])
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
