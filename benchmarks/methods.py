"""Other ways of solving the same mechanism, for comparison with the polygon construction.

Every method returns a :class:`Kinematics` record (SI, counter-clockwise positive) for the
scene's instant, so that its error against a 50-digit reference and its time per solve can
be charted side by side (``benchmarks/accuracy_speed.py``, ``docs/accuracy.md``):

``production``
    the plan's polygon construction, :func:`polygon_method.solve` (each step a 2x2 solve).
``shapely_polygons``
    the same construction, but each pair of direction lines intersected by shapely (GEOS)
    instead of the 2x2 solve (the positions use the same circle formulas).
``algebraic_fourbar``
    the lecture's algebraic position analysis of a four-bar (seed notes: S, P, Q, R and
    the quadratic in ``B_y``, which divides by ``A_x - d``); velocities and accelerations by
    differentiating that same formula in time (a second-order :class:`Jet`).
``newton_raphson``
    Newton-Raphson on the loop-closure (constraint) equations ``f(q, t) = 0``; then
    ``J q' = -f_t`` and ``J q'' = -gamma``: general and iterative.
``finite_differences``
    positions solved at ``t - h, t, t + h``; ``v = (x+ - x-) / 2h``,
    ``a = (x+ - 2 x0 + x-) / h^2``: truncation error ``O(h^2)``, rounding ``eps / h`` and
    ``eps / h^2``.
``hand_drawing``
    the construction drawn by hand at textbook scales (``1 cm = ...``) with a pencil's
    error on every line laid off and every direction drawn (:class:`Pencil`); Monte Carlo
    over many drawings.

shapely and numpy are imported only by the methods that need them.

>>> from polygon_method.scene import parse_scene
>>> sc = parse_scene('''
... [ground]
... A = [0, 0]
... D = [100, 0]
... [links]
... AB = 50
... BC = 66
... CD = 56
... [input]
... crank = "AB"
... angle = 60
... speed = "10.5 rad/s cw"
... ''')
>>> ks = [production(sc), algebraic_fourbar(sc), newton_raphson(sc), shapely_polygons(sc)]
>>> [f"{k.W['BC']:.6f}" for k in ks]
['5.150230', '5.150230', '5.150230', '5.150230']
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from polygon_method.common.errors import AssemblyError, PolygonMethodError, SingularStepError
from polygon_method.solver.compiler import compile_plan
from polygon_method.solver.plan import Carried, Context, Crank, Dyad, SliderDyad, SlottedLink
from polygon_method.scene import FixedPath, Scene

__all__ = [
    "Kinematics",
    "METHODS",
    "production",
    "shapely_polygons",
    "algebraic_fourbar",
    "newton_raphson",
    "finite_differences",
    "hand_drawing",
    "Pencil",
    "Jet",
    "textbook_scale",
    "is_fourbar",
]


@dataclass(frozen=True)
class Kinematics:
    """Positions, velocities, accelerations of points; omega, alpha of links; sliders.

    ``P, V, A``: point -> (x, y); ``W, Al``: link key -> omega, alpha; ``S``: slider point ->
    (sliding velocity, sliding acceleration). In a Monte Carlo run (``hand_drawing``) every
    number is a numpy array, one entry per drawing. ``info``: what the method reports
    about itself (iterations, step size, scales).
    """

    method: str
    P: dict
    V: dict
    A: dict
    W: dict
    Al: dict
    S: dict = field(default_factory=dict)
    info: dict = field(default_factory=dict)


def _perp(v):
    return (-v[1], v[0])


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def _add(a, b):
    return (a[0] + b[0], a[1] + b[1])


def _mul(k, v):
    return (k * v[0], k * v[1])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def _cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


# --------------------------------------------------------------------------- 1. production


def production(scene: Scene) -> Kinematics:
    """The plan's polygon construction (:func:`polygon_method.solve`)."""
    from polygon_method.motion.solution import solve

    sol = solve(scene)
    S = {k: (v[0], v[1]) for k, v in sol.S.items()}
    return Kinematics(
        "production", sol.P, sol.V, sol.A, sol.W, sol.Al, S, {"conditions": dict(sol.conditions)}
    )


# --------------------------------------------------------------------------- 2 & 6. walker


def _meet_2x2(p1, u1, p2, u2):
    """Intersection ``p1 + t u1`` of two lines: ``t = (p2 - p1) x u2 / (u1 x u2)``."""
    den = _cross(u1, u2)
    t = _cross(_sub(p2, p1), u2) / den
    return (p1[0] + t * u1[0], p1[1] + t * u1[1])


def _meet_shapely(p1, u1, p2, u2):
    """The same intersection by GEOS: two segments long enough to cross, intersected.

    A draftsman extends the lines as far as they need; the segments here reach
    ``2 |p2 - p1| / sin(angle between them)`` either side, so that they cross.
    """
    from shapely.geometry import LineString

    s = abs(_cross(u1, u2))
    gap = math.dist(p1, p2)
    reach = 2.0 * (gap + 1e-300) / s if s > 0 else math.inf
    if not math.isfinite(reach) or reach > 1e300:
        raise SingularStepError("the direction lines are parallel: shapely finds no intersection")
    reach = max(reach, 1e-300)
    l1 = LineString(
        [
            (p1[0] - reach * u1[0], p1[1] - reach * u1[1]),
            (p1[0] + reach * u1[0], p1[1] + reach * u1[1]),
        ]
    )
    l2 = LineString(
        [
            (p2[0] - reach * u2[0], p2[1] - reach * u2[1]),
            (p2[0] + reach * u2[0], p2[1] + reach * u2[1]),
        ]
    )
    x = l1.intersection(l2)
    if x.is_empty or x.geom_type != "Point":
        raise SingularStepError(
            f"shapely finds {x.geom_type if not x.is_empty else 'no'} "
            "intersection of the direction lines"
        )
    return (x.x, x.y)


class Pencil:
    """The errors of drawing by hand, as standard deviations (normal, independent).

    Parameters
    ----------
    length_mm : float
        Error of every length laid off or set on the compass, and of every length read off
        the drawing with the scale rule (default 0.25 mm).
    angle_deg : float
        Error of every direction drawn (set square, protractor; default 0.25 deg).
    n : int
        Number of drawings simulated at once (each number becomes an array of n).
    seed : int
        Seed of the random generator (results are reproducible).

    ``Pencil(0, 0)`` draws exactly (used by :func:`shapely_polygons`).
    """

    def __init__(self, length_mm=0.25, angle_deg=0.25, n=1, seed=0):
        self.length_mm = float(length_mm)
        self.angle = math.radians(angle_deg)
        self.n = int(n)
        self.exact = self.length_mm == 0 and self.angle == 0
        if not self.exact:
            import numpy as np

            self.np = np
            self.rng = np.random.default_rng(seed)

    def _len(self):
        return self.rng.normal(0.0, self.length_mm, self.n)

    def _ang(self):
        return self.rng.normal(0.0, self.angle, self.n)

    def lay(self, vec, scale):
        """Lay off ``vec`` (SI) at ``scale`` (SI per mm): its length and direction err."""
        if self.exact:
            return vec
        np = self.np
        x, y = vec
        m = np.hypot(x, y)
        k = (m + self._len() * scale) / np.where(m == 0, 1.0, m)
        a = self._ang()
        c, s = np.cos(a), np.sin(a)
        return (k * (c * x - s * y), k * (s * x + c * y))

    def turn(self, u):
        """A direction drawn with the set square: ``u`` turned by the angle error."""
        if self.exact:
            return u
        a = self._ang()
        c, s = self.np.cos(a), self.np.sin(a)
        return (c * u[0] - s * u[1], s * u[0] + c * u[1])

    def radius(self, r, scale):
        """A compass set to ``r`` (SI) at ``scale``."""
        return r if self.exact else r + self._len() * scale

    def read(self, length, scale):
        """A length read off the drawing with the scale rule (SI)."""
        return length if self.exact else length + self._len() * scale


def _nice(x):
    """The smallest of 1, 2, 2.5, 5 x 10^k that is >= x (a scale a textbook would use)."""
    if x <= 0 or not math.isfinite(x):
        return 1.0
    k = math.floor(math.log10(x))
    for m in (1.0, 2.0, 2.5, 5.0, 10.0):
        if m * 10.0**k >= x * (1 - 1e-12):
            return m * 10.0**k
    return 10.0 ** (k + 1)


def textbook_scale(largest, paper_mm):
    """SI per mm so that ``largest`` fits in ``paper_mm`` at a round scale per cm.

    >>> textbook_scale(0.525, 100) * 10   # m/s per cm: "1 cm = 0.1 m/s"
    0.1
    """
    return _nice(largest / paper_mm * 10.0) / 10.0


class _Walker:
    """The plan's construction walked once more: each pair of direction lines met by
    ``meet``, each line drawn with ``pencil``. Positions use the plan's circle formulas."""

    def __init__(self, scene, meet, pencil, scales=None):
        self.scene = scene
        self.plan = compile_plan(scene)
        self.meet = meet
        self.pen = pencil
        self.scales = scales or (1.0, 1.0, 1.0)

    def _drawn_dir(self, v):
        n = (v[0] * v[0] + v[1] * v[1]) ** 0.5
        return self.pen.turn((v[0] / n, v[1] / n))

    def _signed(self, rel, ref_dir, length_scale, link_len):
        """omega (or alpha) = sense x |measured segment| / link length."""
        m = (rel[0] * rel[0] + rel[1] * rel[1]) ** 0.5
        sense = _cross(ref_dir, rel)
        sgn = (sense > 0) * 2.0 - 1.0 if not isinstance(sense, float) else math.copysign(1.0, sense)
        return sgn * self.pen.read(m, length_scale) / link_len

    def _along(self, rel, u, scale):
        m = (rel[0] * rel[0] + rel[1] * rel[1]) ** 0.5
        d = _dot(rel, u)
        sgn = (d > 0) * 2.0 - 1.0 if not isinstance(d, float) else math.copysign(1.0, d)
        return sgn * self.pen.read(m, scale)

    # ----- configuration diagram
    def positions(self):
        sc, pen, sp = self.scene, self.pen, self.scales[0]
        P = {k: v for k, v in sc.ground.items()}
        for st in self.plan.steps:
            if isinstance(st, Crank):
                th = sc.input.angle
                P[st.tip] = _add(
                    P[st.pivot], pen.lay((st.length * math.cos(th), st.length * math.sin(th)), sp)
                )
            elif isinstance(st, Dyad):
                b, d = P[st.b], P[st.d]
                l1, l2 = pen.radius(st.l1, sp), pen.radius(st.l2, sp)
                e_ = _sub(d, b)
                e2 = _dot(e_, e_)
                e = e2**0.5
                along = (l1 * l1 - l2 * l2 + e2) / (2 * e)
                h2 = l1 * l1 - along * along
                h = self._sqrt(h2, st)
                u = (e_[0] / e, e_[1] / e)
                P[st.point] = (
                    b[0] + along * u[0] - st.sigma * h * u[1],
                    b[1] + along * u[1] + st.sigma * h * u[0],
                )
            elif isinstance(st, SliderDyad):
                q, u = self._guide(P, st)
                b = P[st.b]
                w = _sub(q, b)
                bb = _dot(w, u)
                dist = _cross(w, u)
                ell = pen.radius(st.length, sp)
                half = self._sqrt(ell * ell - dist * dist, st)
                P[st.point] = (
                    q[0] - bb * u[0] + st.sigma * half * u[0],
                    q[1] - bb * u[1] + st.sigma * half * u[1],
                )
            elif isinstance(st, SlottedLink):
                k, a = P[st.known], P[st.point]
                d = _sub(a, k)
                m = _dot(d, d) ** 0.5
                P[st.new] = _add(k, pen.lay(_mul(st.sigma * st.length / m, d), sp))
            elif isinstance(st, Carried):
                P[st.point] = self._image(P, st, sp)
        return P

    def _sqrt(self, h2, st):
        if isinstance(h2, float):
            if h2 < 0:
                if h2 < -1e-12 * step_len(st) ** 2:
                    raise AssemblyError("the arcs do not meet", step=st.label)
                return 0.0
            return h2**0.5
        np = self.pen.np
        return np.sqrt(np.maximum(h2, 0.0))

    def _guide(self, P, st):
        if st.path is not None:
            return st.path.through, self.pen.turn(st.path.u)
        g1, g2 = P[st.g1], P[st.g2]
        d = _sub(g2, g1)
        n = _dot(d, d) ** 0.5
        return g1, (d[0] / n, d[1] / n)

    def _image(self, D, st, scale):
        p, q = D[st.p], D[st.q]
        dq = _sub(q, p)
        off = (st.lam * dq[0] - st.mu * dq[1], st.lam * dq[1] + st.mu * dq[0])
        return _add(p, self.pen.lay(off, scale))

    # ----- velocity polygon
    def velocities(self, P):
        sc, pen, sv, sp = self.scene, self.pen, self.scales[1], self.scales[0]
        zero = (0.0, 0.0)
        V = {k: zero for k in sc.ground}
        W = dict(self.plan.fixed_links)
        S = {}
        for st in self.plan.steps:
            if isinstance(st, Crank):
                r = _sub(P[st.tip], P[st.pivot])
                w = sc.input.omega
                V[st.tip] = _add(V[st.pivot], pen.lay(_mul(w, _perp(r)), sv))
                W[st.link] = w
            elif isinstance(st, Dyad):
                x = P[st.point]
                r1, r2 = _sub(x, P[st.b]), _sub(x, P[st.d])
                vx = self.meet(
                    V[st.b], self._drawn_dir(_perp(r1)), V[st.d], self._drawn_dir(_perp(r2))
                )
                V[st.point] = vx
                W[st.link1] = self._signed(_sub(vx, V[st.b]), r1, sv, st.l1)
                W[st.link2] = self._signed(_sub(vx, V[st.d]), r2, sv, st.l2)
            elif isinstance(st, SliderDyad):
                x = P[st.point]
                r = _sub(x, P[st.b])
                _, u = self._guide(P, st)
                vg = self._guide_velocity(P, V, W, st, x, sv)
                vx = self.meet(V[st.b], self._drawn_dir(_perp(r)), vg, pen.turn(u))
                V[st.point] = vx
                W[st.link] = self._signed(_sub(vx, V[st.b]), r, sv, st.length)
                S[st.point] = [self._along(_sub(vx, vg), u, sv), None, vg]
            elif isinstance(st, SlottedLink):
                k, a = P[st.known], P[st.point]
                d = _sub(a, k)
                u = self._slot_u(P, st)
                va_ = self.meet(V[st.known], self._drawn_dir(_perp(d)), V[st.point], pen.turn(u))
                dl = pen.read(_dot(d, d) ** 0.5, sp)
                wg = self._signed(_sub(va_, V[st.known]), d, sv, dl)
                W[st.guide] = wg
                S[st.point] = [self._along(_sub(V[st.point], va_), u, sv), None, va_]
                rn = _sub(P[st.new], k)
                V[st.new] = _add(V[st.known], pen.lay(_mul(wg, _perp(rn)), sv))
            elif isinstance(st, Carried):
                V[st.point] = self._image(V, st, sv)
        return V, W, S

    def _slot_u(self, P, st):
        f, s = P[st.first], P[st.second]
        d = _sub(s, f)
        n = _dot(d, d) ** 0.5
        return (d[0] / n, d[1] / n)

    def _guide_velocity(self, P, V, W, st, x, sv):
        if st.path is not None:
            return (0.0, 0.0)
        g1 = P[st.g1]
        return _add(V[st.g1], self.pen.lay(_mul(W[st.guide], _perp(_sub(x, g1))), sv))

    # ----- acceleration polygon
    def accelerations(self, P, V, W, S):
        sc, pen, sa, sp = self.scene, self.pen, self.scales[2], self.scales[0]
        zero = (0.0, 0.0)
        A = {k: zero for k in sc.ground}
        Al = dict(self.plan.fixed_links)
        for st in self.plan.steps:
            if isinstance(st, Crank):
                r = _sub(P[st.tip], P[st.pivot])
                w, al = sc.input.omega, sc.input.alpha
                a = _add(A[st.pivot], pen.lay(_mul(-w * w, r), sa))
                if al:
                    a = _add(a, pen.lay(_mul(al, _perp(r)), sa))
                A[st.tip] = a
                Al[st.link] = al
            elif isinstance(st, Dyad):
                x = P[st.point]
                r1, r2 = _sub(x, P[st.b]), _sub(x, P[st.d])
                w1, w2 = W[st.link1], W[st.link2]
                n1 = _add(A[st.b], pen.lay(_mul(-w1 * w1, r1), sa))
                n2 = _add(A[st.d], pen.lay(_mul(-w2 * w2, r2), sa))
                ax = self.meet(n1, self._drawn_dir(_perp(r1)), n2, self._drawn_dir(_perp(r2)))
                A[st.point] = ax
                Al[st.link1] = self._signed(_sub(ax, n1), r1, sa, st.l1)
                Al[st.link2] = self._signed(_sub(ax, n2), r2, sa, st.l2)
            elif isinstance(st, SliderDyad):
                x = P[st.point]
                r = _sub(x, P[st.b])
                _, u = self._guide(P, st)
                w = W[st.link]
                n1 = _add(A[st.b], pen.lay(_mul(-w * w, r), sa))
                t = self._guide_acceleration(P, A, W, Al, S, st, x, u, sa)
                ax = self.meet(n1, self._drawn_dir(_perp(r)), t, pen.turn(u))
                A[st.point] = ax
                Al[st.link] = self._signed(_sub(ax, n1), r, sa, st.length)
                S[st.point][1] = self._along(_sub(ax, t), u, sa)
            elif isinstance(st, SlottedLink):
                k, a = P[st.known], P[st.point]
                d = _sub(a, k)
                u = self._slot_u(P, st)
                wg, vs = W[st.guide], S[st.point][0]
                n = _add(A[st.known], pen.lay(_mul(-wg * wg, d), sa))
                cor = _mul(2 * wg * vs, _perp(u))
                t = _sub(A[st.point], pen.lay(cor, sa))
                aa_ = self.meet(n, self._drawn_dir(_perp(d)), t, pen.turn(u))
                dl = pen.read(_dot(d, d) ** 0.5, sp)
                ag = self._signed(_sub(aa_, n), d, sa, dl)
                Al[st.guide] = ag
                S[st.point][1] = self._along(_sub(t, aa_), u, sa)
                rn = _sub(P[st.new], k)
                A[st.new] = _add(
                    _add(A[st.known], pen.lay(_mul(-wg * wg, rn), sa)),
                    pen.lay(_mul(ag, _perp(rn)), sa),
                )
            elif isinstance(st, Carried):
                A[st.point] = self._image(A, st, sa)
        return A, Al

    def _guide_acceleration(self, P, A, W, Al, S, st, x, u, sa):
        if st.path is not None:
            return (0.0, 0.0)
        pen = self.pen
        g1 = P[st.g1]
        px = _sub(x, g1)
        wg, ag, vs = W[st.guide], Al[st.guide], S[st.point][0]
        t = _add(A[st.g1], pen.lay(_mul(-wg * wg, px), sa))
        t = _add(t, pen.lay(_mul(ag, _perp(px)), sa))
        return _add(t, pen.lay(_mul(2 * wg * vs, _perp(u)), sa))

    def run(self, method):
        P = self.positions()
        V, W, S = self.velocities(P)
        A, Al = self.accelerations(P, V, W, S)
        Sx = {k: (v[0], v[1]) for k, v in S.items()}
        return Kinematics(
            method,
            P,
            V,
            A,
            W,
            Al,
            Sx,
            {
                "scales": dict(
                    zip(
                        ("space m/mm", "velocity m/s per mm", "acceleration m/s^2 per mm"),
                        self.scales,
                    )
                )
            },
        )


def step_len(st):
    return max(getattr(st, "l1", 0.0), getattr(st, "l2", 0.0), getattr(st, "length", 0.0), 1e-9)


def shapely_polygons(scene: Scene) -> Kinematics:
    """The plan's construction with each pair of direction lines intersected by shapely
    (GEOS) instead of the 2x2 solve; positions by the same circle formulas."""
    return _Walker(scene, _meet_shapely, Pencil(0, 0)).run("shapely")


def hand_drawing(
    scene: Scene, n=1000, *, length_mm=0.25, angle_deg=0.25, seed=0, scales=None
) -> Kinematics:
    """``n`` simulated hand drawings of the construction (every number an array of n).

    Every line of the configuration diagram and of both polygons is drawn at a textbook
    scale (:func:`textbook_scale`: the mechanism in 150 mm of paper, each polygon in
    100 mm) with the :class:`Pencil`'s errors (standard deviations ``length_mm`` on every
    length laid off, set on the compass or read off; ``angle_deg`` on every direction).
    Angular velocities and accelerations are read as a measured length over the link's
    given length, as a student does. ``scales``: (space m/mm, m/s per mm, m/s^2 per mm)
    to override the automatic ones.
    """
    if scales is None:
        ref = production(scene)
        ext = [abs(c) for xy in ref.P.values() for c in xy]
        pts = list(ref.P.values())
        span = max(
            max(p[0] for p in pts) - min(p[0] for p in pts),
            max(p[1] for p in pts) - min(p[1] for p in pts),
            max(ext) * 1e-3,
        )
        vmax = max(math.hypot(*v) for v in ref.V.values())
        amax = max(math.hypot(*a) for a in ref.A.values())
        scales = (
            textbook_scale(span, 150.0),
            textbook_scale(vmax, 100.0),
            textbook_scale(amax, 100.0),
        )
    pen = Pencil(length_mm, angle_deg, n=n, seed=seed)
    k = _Walker(scene, _meet_2x2, pen, scales).run("hand drawing")
    k.info.update({"drawings": n, "pencil": f"{length_mm} mm, {angle_deg} deg (1 sd)"})
    return k


# --------------------------------------------------------------------------- 3. algebraic


class Jet:
    """A value with its first two time derivatives: ``(f, f', f'')``.

    Arithmetic follows the product and quotient rules, so any formula written with
    ``+ - * /``, :meth:`sqrt`, :func:`jcos`, :func:`jsin`, :func:`jatan2` is differentiated
    exactly as written (``(f g)'' = f'' g + 2 f' g' + f g''``).

    >>> t = Jet(0.0, 1.0, 0.0)       # time itself
    >>> y = t * t * 3.0
    >>> (y.d1, y.d2)
    (0.0, 6.0)
    """

    __slots__ = ("v", "d1", "d2")

    def __init__(self, v, d1=0.0, d2=0.0):
        self.v, self.d1, self.d2 = v, d1, d2

    @staticmethod
    def _j(x):
        return x if isinstance(x, Jet) else Jet(x)

    def __add__(self, o):
        o = Jet._j(o)
        return Jet(self.v + o.v, self.d1 + o.d1, self.d2 + o.d2)

    __radd__ = __add__

    def __sub__(self, o):
        o = Jet._j(o)
        return Jet(self.v - o.v, self.d1 - o.d1, self.d2 - o.d2)

    def __rsub__(self, o):
        return Jet._j(o) - self

    def __neg__(self):
        return Jet(-self.v, -self.d1, -self.d2)

    def __mul__(self, o):
        o = Jet._j(o)
        return Jet(
            self.v * o.v,
            self.d1 * o.v + self.v * o.d1,
            self.d2 * o.v + 2 * self.d1 * o.d1 + self.v * o.d2,
        )

    __rmul__ = __mul__

    def __truediv__(self, o):
        o = Jet._j(o)
        q = self.v / o.v
        q1 = (self.d1 - q * o.d1) / o.v
        q2 = (self.d2 - 2 * q1 * o.d1 - q * o.d2) / o.v
        return Jet(q, q1, q2)

    def __rtruediv__(self, o):
        return Jet._j(o) / self

    def sqrt(self):
        if self.v < 0:
            raise AssemblyError(
                f"negative discriminant {self.v:.3g}: the links cannot be "
                "assembled (the lecture's 'imaginary' solution)"
            )
        s = self.v**0.5
        s1 = self.d1 / (2 * s)
        return Jet(s, s1, (self.d2 - 2 * s1 * s1) / (2 * s))


def jcos(x: Jet) -> Jet:
    c, s = math.cos(x.v), math.sin(x.v)
    return Jet(c, -s * x.d1, -c * x.d1 * x.d1 - s * x.d2)


def jsin(x: Jet) -> Jet:
    c, s = math.cos(x.v), math.sin(x.v)
    return Jet(s, c * x.d1, -s * x.d1 * x.d1 + c * x.d2)


def jatan2(y: Jet, x: Jet) -> Jet:
    """Angle of (x, y): ``phi' = (x y' - y x') / (x^2 + y^2)``, and its derivative."""
    m = x.v * x.v + y.v * y.v
    n = x.v * y.d1 - y.v * x.d1
    n1 = x.v * y.d2 - y.v * x.d2
    m1 = 2 * (x.v * x.d1 + y.v * y.d1)
    return Jet(math.atan2(y.v, x.v), n / m, (n1 * m - n * m1) / (m * m))


def is_fourbar(scene: Scene):
    """(crank step, dyad step) when the scene is a four-bar (plus carried points), else None:
    a crank whose tip is joined by a dyad to a ground pivot."""
    try:
        plan = compile_plan(scene)
    except PolygonMethodError:
        return None
    steps = plan.steps
    if not steps or not isinstance(steps[0], Crank):
        return None
    dyads = [s for s in steps if isinstance(s, Dyad)]
    others = [s for s in steps[1:] if not isinstance(s, (Dyad, Carried))]
    if len(dyads) != 1 or others:
        return None
    dy, cr = dyads[0], steps[0]
    anchors = {dy.b, dy.d}
    if cr.tip not in anchors or not (anchors - {cr.tip}) <= set(scene.ground):
        return None
    return cr, dy


def algebraic_fourbar(scene: Scene, branch=None) -> Kinematics:
    """The lecture's algebraic four-bar position analysis, differentiated in time.

    Frame: ``O2`` (the crank pivot) at the origin, ``O4`` at ``(d, 0)``; crank ``a``,
    coupler ``b``, rocker ``c``. ``A = a (cos t2, sin t2)``;
    ``S = (a^2 - b^2 + c^2 - d^2) / 2 (A_x - d)``, ``P = A_y^2 / (A_x - d)^2 + 1``,
    ``Q = 2 A_y (d - S) / (A_x - d)``, ``R = (d - S)^2 - c^2``,
    ``B_y = (-Q +- sqrt(Q^2 - 4 P R)) / 2P``, ``B_x = S - A_y B_y / (A_x - d)``.
    Every quantity is a :class:`Jet` in time, ``t2(t) = t2 + omega t + alpha t^2 / 2``, so
    velocities and accelerations are the exact derivatives of this formula. ``branch``: the
    sign of the root; by default the one nearest the plan's assembly. Raises
    :class:`SingularStepError` where ``A_x = d`` exactly (the formula divides by zero).
    """
    fb = is_fourbar(scene)
    if fb is None:
        raise PolygonMethodError("the algebraic method needs a four-bar (crank, coupler, rocker)")
    cr, dy = fb
    inp = scene.input
    o2, tip = scene.ground[cr.pivot], cr.tip
    rocker_pivot = dy.d if dy.b == tip else dy.b
    o4 = scene.ground[rocker_pivot]
    b_len = dy.l1 if dy.b == tip else dy.l2
    c_len = dy.l2 if dy.b == tip else dy.l1
    coupler = dy.link1 if dy.b == tip else dy.link2
    rocker = dy.link2 if dy.b == tip else dy.link1
    a, b, c = cr.length, b_len, c_len
    gx, gy = o4[0] - o2[0], o4[1] - o2[1]
    d = math.hypot(gx, gy)
    phi0 = math.atan2(gy, gx)
    cg, sg = gx / d, gy / d

    t2 = Jet(inp.angle - phi0, inp.omega, inp.alpha)
    ax, ay = a * jcos(t2), a * jsin(t2)
    den = ax - d
    if den.v == 0:
        raise SingularStepError(
            "A_x = d: the lecture's formula divides by A_x - d = 0", step="algebraic four-bar"
        )
    S = (a * a - b * b + c * c - d * d) / (2 * den)
    Pq = ay * ay / (den * den) + 1
    Qq = 2 * ay * (d - S) / den
    Rq = (d - S) * (d - S) - c * c
    disc = Qq * Qq - 4 * Pq * Rq

    def solve_b(sign):
        by = (-Qq + sign * disc.sqrt()) / (2 * Pq)
        bx = S - ay * by / den
        return bx, by

    def to_global(x, y):  # rotate the lecture frame back, translate to O2
        return (o2[0] + cg * x - sg * y, o2[1] + sg * x + cg * y)

    if branch is None:
        try:
            want = production(scene).P[dy.point]
        except PolygonMethodError:  # the plan refuses here: the figure's hint decides
            want = scene.assembly.get(dy.point, "above")
        cands = []
        for sgn in (1.0, -1.0):
            bx, by = solve_b(sgn)
            g = to_global(bx.v, by.v)
            if isinstance(want, str):
                axis, k = {"above": (1, -1), "below": (1, 1), "right": (0, -1), "left": (0, 1)}[
                    want
                ]
                cands.append((k * g[axis], sgn))
            else:
                cands.append((math.dist(g, want), sgn))
        branch = min(cands)[1]
    bx, by = solve_b(branch)

    def glob(x: Jet, y: Jet):
        return (
            Jet(o2[0] + cg * x.v - sg * y.v, cg * x.d1 - sg * y.d1, cg * x.d2 - sg * y.d2),
            Jet(o2[1] + sg * x.v + cg * y.v, sg * x.d1 + cg * y.d1, sg * x.d2 + cg * y.d2),
        )

    J = {
        cr.pivot: (Jet(o2[0]), Jet(o2[1])),
        rocker_pivot: (Jet(o4[0]), Jet(o4[1])),
        tip: glob(ax, ay),
        dy.point: glob(bx, by),
    }
    for name, xy in scene.ground.items():
        J.setdefault(name, (Jet(xy[0]), Jet(xy[1])))
    th3 = jatan2(by - ay, bx - ax)
    th4 = jatan2(by, bx - d)
    W = {cr.link: inp.omega, coupler: th3.d1, rocker: th4.d1}
    Al = {cr.link: inp.alpha, coupler: th3.d2, rocker: th4.d2}
    plan = compile_plan(scene)
    W.update(plan.fixed_links)
    Al.update(plan.fixed_links)
    for st in plan.steps:
        if isinstance(st, Carried):
            (px, py), (qx, qy) = J[st.p], J[st.q]
            dx, dy_ = qx - px, qy - py
            J[st.point] = (px + st.lam * dx - st.mu * dy_, py + st.lam * dy_ + st.mu * dx)
            W.setdefault(st.link, W.get(st.link))
    P = {k: (x.v, y.v) for k, (x, y) in J.items()}
    V = {k: (x.d1, y.d1) for k, (x, y) in J.items()}
    A = {k: (x.d2, y.d2) for k, (x, y) in J.items()}
    return Kinematics("algebraic", P, V, A, W, Al, {}, {"A_x - d": den.v, "branch": branch})


# --------------------------------------------------------------------------- 4. Newton


def _constraints(scene):
    """The loop-closure equations as (kind, data): links, the crank, carried points,
    sliders on fixed paths and on moving links."""
    g, inp = scene.ground, scene.input
    eqs = []
    for lk in scene.links:
        if lk.key == scene.link(inp.crank).key or (lk.p in g and lk.q in g):
            continue
        eqs.append(("link", lk.p, lk.q, lk.length))
    crank = scene.link(inp.crank)
    eqs.append(("crank", inp.pivot, inp.tip, crank.length))
    for cp in scene.points:
        lk = scene.link(cp.link)
        eqs.append(("carried", cp.name, lk.p, lk.q, cp.lam, cp.mu))
    for sl in scene.sliders:
        if isinstance(sl, FixedPath):
            eqs.append(("path", sl.point, sl.through, sl.u))
        else:
            eqs.append(("guide", sl.point, sl.first, sl.second))
    return eqs


def newton_raphson(scene: Scene, guess=None, *, tol=1e-15, max_iter=50) -> Kinematics:
    """Newton-Raphson on the constraint equations, in x, y of every moving point.

    ``f = 0`` with: ``|P - Q|^2 - L^2`` per link, ``T - O - r (cos t, sin t)`` for the crank,
    ``X - (P + lam (P Q) + mu perp(P Q))`` per carried point, ``(X - Q) x u`` per slider on
    a path, ``(X - G1) x (G2 - G1)`` per block on a moving link. ``q <- q - J^-1 f`` until the
    step is below ``tol`` (relative to the size of the mechanism). Velocities:
    ``J q' = -f_t``; accelerations: ``J q'' = -gamma`` (``gamma`` = the quadratic terms).
    ``guess``: starting positions (point -> (x, y)); by default the plan's positions 5 deg
    of crank earlier, as a sweep would continue.
    """
    import numpy as np

    inp = scene.input
    g = scene.ground
    names = [n for n in scene.point_names if n not in g]
    col = {n: i for i, n in enumerate(names)}
    eqs = _constraints(scene)
    rows = sum(2 if e[0] in ("crank", "carried") else 1 for e in eqs)
    if rows != 2 * len(names):
        raise PolygonMethodError(f"{rows} loop-closure equations for {2 * len(names)} unknowns")
    if guess is None:
        plan = compile_plan(scene)
        ctx = Context(inp.angle - math.radians(5.0), inp.omega, inp.alpha)
        guess = dict(g)
        try:
            for st in plan.steps:
                st.positions(guess, ctx)
        except PolygonMethodError:  # cannot assemble 5 deg earlier: start at the figure
            guess = production(scene).P
    q = np.array([c for n in names for c in guess[n]], dtype=float)
    th = inp.angle
    size = max(max((lk.length for lk in scene.links), default=1.0), 1e-12)

    def pos(q):
        P = dict(g)
        for n, i in col.items():
            P[n] = (q[2 * i], q[2 * i + 1])
        return P

    def system(q):
        P = pos(q)
        F = np.zeros(rows)
        J = np.zeros((rows, len(q)))
        r = 0

        def add(row, name, gx, gy):
            if name in col:
                J[row, 2 * col[name]] += gx
                J[row, 2 * col[name] + 1] += gy

        for e in eqs:
            kind = e[0]
            if kind == "link":
                _, p, qq, L = e
                dx, dy = P[p][0] - P[qq][0], P[p][1] - P[qq][1]
                F[r] = dx * dx + dy * dy - L * L
                add(r, p, 2 * dx, 2 * dy)
                add(r, qq, -2 * dx, -2 * dy)
                r += 1
            elif kind == "crank":
                _, o, t, L = e
                F[r] = P[t][0] - P[o][0] - L * math.cos(th)
                F[r + 1] = P[t][1] - P[o][1] - L * math.sin(th)
                add(r, t, 1, 0), add(r, o, -1, 0), add(r + 1, t, 0, 1), add(r + 1, o, 0, -1)
                r += 2
            elif kind == "carried":
                _, x, p, qq, lam, mu = e
                dx, dy = P[qq][0] - P[p][0], P[qq][1] - P[p][1]
                F[r] = P[x][0] - (P[p][0] + lam * dx - mu * dy)
                F[r + 1] = P[x][1] - (P[p][1] + lam * dy + mu * dx)
                add(r, x, 1, 0), add(r, p, -(1 - lam), -mu), add(r, qq, -lam, mu)
                add(r + 1, x, 0, 1), add(r + 1, p, mu, -(1 - lam)), add(r + 1, qq, -mu, -lam)
                r += 2
            elif kind == "path":
                _, x, (tx, ty), (ux, uy) = e
                F[r] = (P[x][0] - tx) * uy - (P[x][1] - ty) * ux
                add(r, x, uy, -ux)
                r += 1
            else:  # guide
                _, x, g1, g2 = e
                a = (P[x][0] - P[g1][0], P[x][1] - P[g1][1])
                b = (P[g2][0] - P[g1][0], P[g2][1] - P[g1][1])
                F[r] = a[0] * b[1] - a[1] * b[0]
                add(r, x, b[1], -b[0]), add(r, g2, -a[1], a[0])
                add(r, g1, a[1] - b[1], b[0] - a[0])
                r += 1
        return F, J

    it = 0
    for it in range(1, max_iter + 1):
        F, J = system(q)
        try:
            dq = np.linalg.solve(J, -F)
        except np.linalg.LinAlgError as exc:
            raise SingularStepError(
                f"the loop-closure Jacobian is singular ({exc})", step="Newton-Raphson"
            ) from None
        q = q + dq
        if not np.all(np.isfinite(q)):
            raise SingularStepError("Newton-Raphson diverged", step="Newton-Raphson")
        if np.max(np.abs(dq)) <= tol * size:
            break
    else:
        raise SingularStepError(
            f"Newton-Raphson did not converge in {max_iter} iterations", step="Newton-Raphson"
        )
    F, J = system(q)
    P = pos(q)
    w, al = inp.omega, inp.alpha
    ft = np.zeros(rows)
    r = 0
    for e in eqs:
        if e[0] == "crank":
            _, o, t, L = e
            rx, ry = P[t][0] - P[o][0], P[t][1] - P[o][1]
            ft[r], ft[r + 1] = w * ry, -w * rx  # d/dt of -(L cos th, L sin th)
        r += 2 if e[0] in ("crank", "carried") else 1
    qd = np.linalg.solve(J, -ft)
    V = dict.fromkeys(g, (0.0, 0.0))
    V.update({n: (qd[2 * i], qd[2 * i + 1]) for n, i in col.items()})
    gam = np.zeros(rows)
    r = 0
    for e in eqs:
        kind = e[0]
        if kind == "link":
            dv = _sub(V[e[1]], V[e[2]])
            gam[r] = 2 * _dot(dv, dv)
        elif kind == "crank":
            _, o, t, L = e
            rx, ry = P[t][0] - P[o][0], P[t][1] - P[o][1]
            gam[r], gam[r + 1] = w * w * rx + al * ry, w * w * ry - al * rx
        elif kind == "guide":
            _, x, g1, g2 = e
            gam[r] = 2 * _cross(_sub(V[x], V[g1]), _sub(V[g2], V[g1]))
        r += 2 if kind in ("crank", "carried") else 1
    qdd = np.linalg.solve(J, -gam)
    A = dict.fromkeys(g, (0.0, 0.0))
    A.update({n: (qdd[2 * i], qdd[2 * i + 1]) for n, i in col.items()})
    W, Al = _link_rates(scene, P, V, A)
    S = _slider_rates(scene, P, V, A, W, Al)
    return Kinematics(
        "Newton-Raphson",
        P,
        V,
        A,
        W,
        Al,
        S,
        {"iterations": it, "residual": float(np.max(np.abs(F)))},
    )


def _link_rates(scene, P, V, A):
    """omega = r x v_rel / |r|^2, alpha = r x a_rel / |r|^2 for each link (r = Q - P)."""
    W, Al = {}, {}
    for lk in scene.links:
        r = _sub(P[lk.q], P[lk.p])
        r2 = _dot(r, r)
        W[lk.key] = _cross(r, _sub(V[lk.q], V[lk.p])) / r2
        Al[lk.key] = _cross(r, _sub(A[lk.q], A[lk.p])) / r2
    return W, Al


def _slider_rates(scene, P, V, A, W, Al):
    """(sliding velocity, sliding acceleration) of each slider relative to its guide."""
    S = {}
    for sl in scene.sliders:
        x = sl.point
        if isinstance(sl, FixedPath):
            S[x] = (_dot(V[x], sl.u), _dot(A[x], sl.u))
            continue
        g1, g2 = sl.first, sl.second
        d = _sub(P[g2], P[g1])
        n = _dot(d, d) ** 0.5
        u = (d[0] / n, d[1] / n)
        key = scene.link(sl.guide).key
        wg, ag = W[key], Al[key]
        rel = _sub(P[x], P[g1])
        vx_ = _add(V[g1], _mul(wg, _perp(rel)))
        vs = _dot(_sub(V[x], vx_), u)
        ax_ = _add(_add(A[g1], _mul(-wg * wg, rel)), _mul(ag, _perp(rel)))
        cor = _mul(2 * wg * vs, _perp(u))
        S[x] = (vs, _dot(_sub(_sub(A[x], ax_), cor), u))
    return S


# --------------------------------------------------------------------------- 5. FD


def finite_differences(scene: Scene, h=None) -> Kinematics:
    """Central differences in time of the plan's positions (``h``: the time step, s; by
    default the time of a 1e-4 rad crank turn, near the best for accelerations).

    ``v = (x(h) - x(-h)) / 2h``, ``a = (x(h) - 2 x(0) + x(-h)) / h^2``; link angles and
    slider coordinates the same way. Error ~ ``h^2 x''' / 6`` + ``eps x / h`` for v, and
    ``h^2 x'''' / 12`` + ``4 eps x / h^2`` for a: the best ``h`` balances the two.
    """
    import numpy as np

    inp = scene.input
    if h is None:
        h = 1e-4 / max(abs(inp.omega), (abs(inp.alpha) * 1e-4) ** 0.5, 1e-300)
    plan = compile_plan(scene)
    t = np.array([-h, 0.0, h])
    theta = inp.angle + inp.omega * t + 0.5 * inp.alpha * t * t
    ctx = Context(theta, inp.omega, inp.alpha, array=True)
    P3 = dict(plan.ground)
    for st in plan.steps:
        st.positions(P3, ctx)
    if ctx.bad is not None and ctx.bad.any():
        raise AssemblyError(
            "the mechanism cannot be assembled within +-h of the instant", step="finite differences"
        )
    P3 = {
        k: (np.broadcast_to(np.asarray(x, float), 3), np.broadcast_to(np.asarray(y, float), 3))
        for k, (x, y) in P3.items()
    }

    def d1(f):
        return (f[2] - f[0]) / (2 * h)

    def d2(f):
        return (f[2] - 2 * f[1] + f[0]) / (h * h)

    P = {k: (float(x[1]), float(y[1])) for k, (x, y) in P3.items()}
    V = {k: (float(d1(x)), float(d1(y))) for k, (x, y) in P3.items()}
    A = {k: (float(d2(x)), float(d2(y))) for k, (x, y) in P3.items()}
    W, Al = {}, {}
    for lk in scene.links:
        (px, py), (qx, qy) = P3[lk.p], P3[lk.q]
        ang = np.unwrap(np.arctan2(qy - py, qx - px))
        ang = ang - ang[1]  # angles near zero: keep the digits for the differences
        W[lk.key], Al[lk.key] = float(d1(ang)), float(d2(ang))
    S = {}
    for sl in scene.sliders:
        x, y = P3[sl.point]
        if isinstance(sl, FixedPath):
            s = (x - sl.through[0]) * sl.u[0] + (y - sl.through[1]) * sl.u[1]
        else:
            (gx, gy), (hx, hy) = P3[sl.first], P3[sl.second]
            dx, dy = hx - gx, hy - gy
            n = np.hypot(dx, dy)
            s = ((x - gx) * dx + (y - gy) * dy) / n
        s = s - s[1]
        S[sl.point] = (float(d1(s)), float(d2(s)))
    return Kinematics("finite differences", P, V, A, W, Al, S, {"h": h})


METHODS = {
    "production": production,
    "shapely": shapely_polygons,
    "algebraic": algebraic_fourbar,
    "Newton-Raphson": newton_raphson,
    "finite differences": finite_differences,
}
"""The deterministic methods by name (``hand_drawing`` is a Monte Carlo run)."""


# --------------------------------------------------------------------------- errors


def reference_scales(ref: Kinematics, scene: Scene) -> dict:
    """The size of each kind of quantity over the mechanism at this instant, to measure
    errors against (never a value that happens to be near zero):

    position: the longest link; velocity: the largest point speed (at least omega r of the
    crank); acceleration: the largest point acceleration (at least (omega^2 + |alpha|) r);
    omega: the largest |omega| (at least the crank's); alpha: the largest |alpha| (at least
    omega^2 + |alpha| of the crank).
    """
    inp = scene.input
    r = scene.link(inp.crank).length
    w2 = inp.omega**2 + abs(inp.alpha)

    def mag(v):
        return float(abs(v[0]) ** 2 + abs(v[1]) ** 2) ** 0.5

    return {
        "position": max(lk.length for lk in scene.links),
        "velocity": max([abs(inp.omega) * r] + [mag(v) for v in ref.V.values()]),
        "acceleration": max([w2 * r] + [mag(a) for a in ref.A.values()]),
        "omega": max([abs(inp.omega)] + [float(abs(w)) for w in ref.W.values()]),
        "alpha": max([w2] + [float(abs(a)) for a in ref.Al.values()]),
    }


def compare(kin: Kinematics, ref: Kinematics, scene: Scene) -> dict:
    """Largest error of each kind of quantity, relative to :func:`reference_scales`.

    Keys: position, velocity, acceleration, omega, alpha, sliding (velocity and
    acceleration of sliders, each on the velocity and acceleration scales), and ``all``
    (the largest). Quantities a method does not give are skipped. Works on floats, mpmath
    numbers (the reference) and numpy arrays (Monte Carlo: one error per drawing).
    """
    sc = reference_scales(ref, scene)
    out = {}

    def put(kind, errs):
        errs = [e for e in errs if e is not None]
        if not errs:
            return
        m = errs[0]
        for e in errs[1:]:
            m = _emax(m, e)
        out[kind] = _emax(out[kind], m) if kind in out else m

    def vec(a, b, scale):
        return _hyp(_diff(a[0], b[0]), _diff(a[1], b[1])) / scale

    for kind, d, dr in (
        ("position", kin.P, ref.P),
        ("velocity", kin.V, ref.V),
        ("acceleration", kin.A, ref.A),
    ):
        put(kind, [vec(d[k], dr[k], sc[kind]) for k in dr if k in d])
    for kind, d, dr in (("omega", kin.W, ref.W), ("alpha", kin.Al, ref.Al)):
        put(kind, [abs(_diff(d[k], dr[k])) / sc[kind] for k in dr if k in d and d[k] is not None])
    sl = []
    for k, (vs, a_s) in ref.S.items():
        if k in kin.S:
            sl.append(abs(_diff(kin.S[k][0], vs)) / sc["velocity"])
            sl.append(abs(_diff(kin.S[k][1], a_s)) / sc["acceleration"])
    put("sliding", sl)
    put("all", list(out.values()))
    return out


def _diff(value, ref):
    """value - ref as a float (or a float array): a 50-digit reference is subtracted
    before rounding when the value is a single number."""
    if isinstance(value, (int, float)):
        d = value - ref
        return float(d)
    return value - float(ref)


def _hyp(x, y):
    if isinstance(x, float) and isinstance(y, float):
        return math.hypot(x, y)
    return (x * x + y * y) ** 0.5


def _emax(a, b):
    if isinstance(a, float) and isinstance(b, float):
        return a if a >= b else b
    import numpy as np

    return np.maximum(a, b)
