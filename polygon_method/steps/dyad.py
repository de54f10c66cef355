"""RRR dyad: a point joined by two links (or two sides of plates) to two known points.

Position: X with |XB| = l1, |XD| = l2, the intersection of two circles (the branch
``sigma`` says which). Velocity: through b a line perpendicular to BX, through d one
perpendicular to DX; they meet at x. In numbers, ``w1 perp(r1) - w2 perp(r2) = vD - vB``
with r1 = X - B, r2 = X - D::

    w1 = (vD - vB).r2 / (r1 x r2),   w2 = (vD - vB).r1 / (r1 x r2)

Acceleration: the same with the right side ``(aD - w2^2 r2) - (aB - w1^2 r1)`` (the
centripetal components drawn first, the tangential ones along the direction lines).
Condition: |r1 x r2| / (l1 l2), the sine of the transmission angle at X.

>>> x, y, c = place(0.0, 0.0, 2.0, 0.0, 2 ** 0.5, 2 ** 0.5, 1.0)
>>> round(x, 12), round(y, 12), round(c, 12)
(1.0, 1.0, 1.0)
>>> velocity(1.0, 1.0, -1.0, 1.0, 0.0, 1.0, 0.0, 0.0)   # B moves up at 1, D fixed: both cw
(-0.5, -0.5, 0.5, 0.5)
"""

from __future__ import annotations

from dataclasses import dataclass

from ..common.errors import TOL, AssemblyError, SingularStepError
from ..common.numbers import in_units, quiet
from ..common.tolerances import LEAST_REACH, crossing_angle
from ..scene import split_name
from .rounding import C_FLOOR, turning, vhypot, vmax, vmin
from .base import (
    Construction,
    DirectionLine,
    Step,
    absolute,
    centripetal,
    image_label,
    perp,
    pole_text,
    relative,
    sub,
    tangential,
    unit,
)

__all__ = ["Dyad", "place", "velocity", "acceleration", "recognise"]


def place(bx, by, dx, dy, l1, l2, sigma, ctx=None, step=None):
    """X with |XB| = l1, |XD| = l2, on the side ``sigma`` of B -> D.

    With e = |BD|: ``X = B + a (D - B) + sigma (h / e) perp(D - B)``, where
    ``a = (l1^2 - l2^2 + e^2) / 2e^2`` and ``h / e = sqrt(q) / 2e^2`` with
    ``q = 4 e^2 h^2 = ((l1+l2)^2 - e^2)(e^2 - (l1-l2)^2)``, computed from e^2 unrounded (no
    square root of e^2 is taken: h stays exact near a toggle). Returns x, y and the
    condition ``e h / (l1 l2) = sqrt(q) / (2 l1 l2)``, the |sin| of the angle at X.
    """
    ex, ey = dx - bx, dy - by
    e2 = ex * ex + ey * ey
    s, t = l1 + l2, l1 - l2
    q = (s * s - e2) * (e2 - t * t)
    if ctx is None or not ctx.array:
        if q > 0:  # two assemblies (e2 = 0 gives q <= 0)
            root = q**0.5
        else:
            if step is not None:
                if e2 == 0:
                    raise step.coincident()
                if q < -TOL.closure * (l1 * l2) ** 2:
                    raise AssemblyError(step.why(e2**0.5), step=step.label)
            root = 0.0
    else:
        e2 = ctx.safe(e2, step)
        root = ctx.root(q, (l1 * l2) ** 2, step, None)
    w = 0.5 / e2
    a = (l1 * l1 - l2 * l2 + e2) * w
    g = (sigma * root) * w
    return bx + a * ex - g * ey, by + a * ey + g * ex, root * (0.5 / (l1 * l2))


def velocity(r1x, r1y, r2x, r2y, vbx, vby, vdx, vdy, d=None):
    """(w1, w2, vx, vy): the angular velocities of XB and XD and the velocity of X.
    ``d`` is r1 x r2 if the caller has made it safe (arrays)."""
    if d is None:
        d = r1x * r2y - r1y * r2x
    wx, wy = vdx - vbx, vdy - vby
    w1 = (wx * r2x + wy * r2y) / d
    w2 = (wx * r1x + wy * r1y) / d
    return w1, w2, vbx - w1 * r1y, vby + w1 * r1x


def acceleration(r1x, r1y, r2x, r2y, w1, w2, abx, aby, adx, ady, d=None):
    """(al1, al2, ax, ay): the angular accelerations of XB and XD and the acceleration of X."""
    if d is None:
        d = r1x * r2y - r1y * r2x
    k1, k2 = w1 * w1, w2 * w2
    qx = (adx - k2 * r2x) - (abx - k1 * r1x)
    qy = (ady - k2 * r2y) - (aby - k1 * r1y)
    al1 = (qx * r2x + qy * r2y) / d
    al2 = (qx * r1x + qy * r1y) / d
    return al1, al2, abx - k1 * r1x - al1 * r1y, aby - k1 * r1y + al1 * r1x


def recognise(g, name):
    """Two bodies of ``name`` that each have one known point and are not used yet."""
    free = g.free(name)
    if len(free) >= 2:
        (k1, b1, l1), (k2, b2, l2) = free[0], free[1]
        return Dyad(len(g.steps), name, b1, k1, l1, b2, k2, l2, 1.0, g.unit, g.uname)
    return None


@dataclass(frozen=True)
class Dyad(Step):
    """RRR: point X with XB = l1 to known B and XD = l2 to known D (see the module)."""

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

    kind = "dyad"
    branching = True
    other_assembly_mistake = True

    @property
    def finds(self):
        return (self.point,)

    @property
    def links(self):
        return (self.link1, self.link2)

    @property
    def needs(self):
        return (self.b, self.d)

    @property
    def title(self):
        return f"dyad {self.link1}, {self.link2} at {self.point}"

    @property
    def params(self):
        return (self.l1, self.l2)

    def dimensions(self, scene, bodies):
        return (
            bodies.distance(self.link1, self.b, self.point),
            bodies.distance(self.link2, self.d, self.point),
        )

    def drawn(self, prm, pencil, P):
        return (prm[0] + pencil(), prm[1] + pencil())

    def reach(self):
        return max(self.l1, self.l2, LEAST_REACH)

    def place(self, P, prm, ctx, sigma=None):
        (bx, by), (dx, dy) = P[self.b], P[self.d]
        s = self.sigma if sigma is None else sigma
        return place(bx, by, dx, dy, prm[0], prm[1], s, ctx, self)

    def bind(self, prm):
        """The step's three phases for dimensions ``prm``: functions of a State."""
        X, B, D, j1, j2, i = self.point, self.b, self.d, self.link1, self.link2, self.index
        l1, l2, sigma, step = prm[0], prm[1], self.sigma, self

        def position(m):
            (bx, by), (dx, dy) = m.P[B], m.P[D]
            x, y, c = place(bx, by, dx, dy, l1, l2, sigma, m.ctx, step)
            m.P[X] = (x, y)
            m.cond[i] = c

        def velocity_(m):
            P, V = m.P, m.V
            (x, y), (bx, by), (dx, dy) = P[X], P[B], P[D]
            r1x, r1y, r2x, r2y = x - bx, y - by, x - dx, y - dy
            d = r1x * r2y - r1y * r2x
            if m.array:
                d = m.ctx.safe(d, step)
            w1, w2, vx, vy = velocity(r1x, r1y, r2x, r2y, *V[B], *V[D], d)
            m.W[j1] = w1
            m.W[j2] = w2
            V[X] = (vx, vy)

        def acceleration_(m):
            P, A, W = m.P, m.A, m.W
            (x, y), (bx, by), (dx, dy) = P[X], P[B], P[D]
            r1x, r1y, r2x, r2y = x - bx, y - by, x - dx, y - dy
            d = r1x * r2y - r1y * r2x
            if m.array:
                d = m.ctx.safe(d, step)
            al1, al2, ax, ay = acceleration(r1x, r1y, r2x, r2y, W[j1], W[j2], *A[B], *A[D], d)
            m.Al[j1] = al1
            m.Al[j2] = al2
            A[X] = (ax, ay)

        return position, velocity_, acceleration_

    def bind_instant(self, prm):
        """The three phases in a row for one instant, fused into one plain float function:
        :func:`place`, :func:`velocity` and :func:`acceleration` written out in the same
        operations in the same order (no call, no tuple passed between them), so every
        number is the phased road's to the last bit (a test holds the two roads equal on
        every worked problem and on random dyads). Where the circles do not cross, or B
        and D coincide, :func:`place` itself says why."""
        X, B, D, j1, j2, i = self.point, self.b, self.d, self.link1, self.link2, self.index
        l1, l2, sigma, step = prm[0], prm[1], self.sigma, self
        s, t = l1 + l2, l1 - l2
        ss, tt = s * s, t * t  # of q = (s^2 - e^2)(e^2 - t^2)
        ll = l1 * l1 - l2 * l2  # of a = (l1^2 - l2^2 + e^2) / 2e^2
        half = 0.5 / (l1 * l2)  # the condition sqrt(q) / (2 l1 l2)
        singular = TOL.singular

        def instant(m):
            P = m.P
            bx, by = P[B]
            dx, dy = P[D]
            # place
            ex = dx - bx
            ey = dy - by
            e2 = ex * ex + ey * ey
            q = (ss - e2) * (e2 - tt)
            if q > 0:
                root = q**0.5
            else:  # no crossing, or B on D: raises as place() does; else a toggle
                place(bx, by, dx, dy, l1, l2, sigma, m.ctx, step)
                root = 0.0
            w = 0.5 / e2
            a = (ll + e2) * w
            g = (sigma * root) * w
            x = bx + a * ex - g * ey
            y = by + a * ey + g * ex
            c = root * half
            P[X] = (x, y)
            m.cond[i] = c
            if c < singular:
                raise step.singular(c)
            # velocity
            r1x = x - bx
            r1y = y - by
            r2x = x - dx
            r2y = y - dy
            d = r1x * r2y - r1y * r2x
            V = m.V
            vbx, vby = V[B]
            vdx, vdy = V[D]
            wx = vdx - vbx
            wy = vdy - vby
            w1 = (wx * r2x + wy * r2y) / d
            w2 = (wx * r1x + wy * r1y) / d
            W = m.W
            W[j1] = w1
            W[j2] = w2
            V[X] = (vbx - w1 * r1y, vby + w1 * r1x)
            # acceleration
            A = m.A
            abx, aby = A[B]
            adx, ady = A[D]
            k1 = w1 * w1
            k2 = w2 * w2
            qx = (adx - k2 * r2x) - (abx - k1 * r1x)
            qy = (ady - k2 * r2y) - (aby - k1 * r1y)
            al1 = (qx * r2x + qy * r2y) / d
            al2 = (qx * r1x + qy * r1y) / d
            Al = m.Al
            Al[j1] = al1
            Al[j2] = al2
            A[X] = (abx - k1 * r1x - al1 * r1y, aby - k1 * r1y + al1 * r1x)

        return instant

    def error_bound(self, walk, k, p_in, v_in, a_in):
        """Component by component. Linearised, ``r1 . dX = r1 . dB`` and ``r2 . dX = r2 .
        dD`` (the same two rows for positions, velocities and accelerations), so ``dX =
        (-(u1 . dB) perp(u2) + (u2 . dD) perp(u1)) / c``: only the component of B's error
        along XB, and of D's along XD, is carried, across the other link. A chain of dyads
        then carries its errors without multiplying them by 1/c at every step where the
        geometry does not. ``walk.box`` keeps each point's error along x and y."""
        P, box = walk.P, walk.box
        g = 1.0 / vmax(walk.condition(self), C_FLOOR)
        B, D, X = self.b, self.d, self.point
        (x, y), (bx, by), (dx, dy) = P[X], P[B], P[D]
        r1x, r1y, r2x, r2y = x - bx, y - by, x - dx, y - dy
        n1 = vmax(vhypot(r1x, r1y), 1e-300)
        n2 = vmax(vhypot(r2x, r2y), 1e-300)
        u1x, u1y, u2x, u2y = abs(r1x / n1), abs(r1y / n1), abs(r2x / n2), abs(r2y / n2)

        def carry(phase, own):
            table = box.tables[phase]
            ebx, eby = box.of(phase, B)
            edx, edy = box.of(phase, D)
            s1 = vmin(u1x * ebx + u1y * eby, table.get(B, 0.0))  # |u . dB| <= |dB| too
            s2 = vmin(u2x * edx + u2y * edy, table.get(D, 0.0))
            box[(phase, X)] = (g * (s1 * u2y + s2 * u1y + own), g * (s1 * u2x + s2 * u1x + own))
            return g * (s1 + s2 + own)

        kp, kv, ka = walk.own(self, k)
        _, _, wv, wa, wr = walk.local(self)
        p = carry(0, kp)
        # each row r . (vX - vB) = 0 (and its acceleration) errs by |dr| |vX - vB| / |r|
        # = |dr| |omega| (|dr| |(alpha, omega^2)|) from the positions' error: where a short
        # link turns fast in a mechanism whose sizes a long one sets, that outgrows the
        # positions' error itself, so it is counted with the dyad's own links' omega and
        # alpha
        V, A, tab = walk.V, walk.A, box.tables
        # (``wv``, ``wa``: walk.local); and a velocity's error turns into an
        # acceleration's as 2 omega dv (``wr``)
        v = carry(1, kv + p * wv)
        a = carry(2, ka + p * wa + vmin(wr, walk.ratio) * v)
        # each link's omega from its own side: r x (vX - vB) / |r|^2 (a short side of a
        # large plate divides its ends' errors by its own length)
        turns = []
        for K, rx, ry in ((B, r1x, r1y), (D, r2x, r2y)):
            dv = vhypot(V[X][0] - V[K][0], V[X][1] - V[K][1])
            da = vhypot(A[X][0] - A[K][0], A[X][1] - A[K][1])
            turns.append(
                turning(
                    walk,
                    rx,
                    ry,
                    dv,
                    da,
                    p + tab[0].get(K, 0.0),
                    v + tab[1].get(K, 0.0),
                    a + tab[2].get(K, 0.0),
                    k,
                )
            )
        (w1, al1), (w2, al2) = turns
        return p, v, a, (vmax(v, w1), vmax(v, w2)), (vmax(a, al1), vmax(a, al2))

    # ----- failures and words
    def coincident(self):
        """The error when the two known points coincide: singular if the two sides are equal (the
        point may be anywhere on a circle), else no assembly."""
        if self.l1 == self.l2:
            return SingularStepError(
                f"{self.b} and {self.d} coincide and {self.side(1)} = "
                f"{self.side(2)}: {self.point} may be anywhere on a "
                "circle",
                step=self.label,
            )
        return AssemblyError(self.why(0.0), step=self.label)

    def side(self, which) -> str:
        """The name of a side: the link itself, or ``BE (on BC)`` for a side of a plate."""
        key, k = (self.link1, self.b) if which == 1 else (self.link2, self.d)
        if set(split_name(key)) == {k, self.point}:
            return key
        return f"{k}{self.point} (on {key})"

    def why(self, e):
        """Why the dyad cannot assemble with its known points ``e`` apart: too far for the two
        sides, or too near."""
        u, n = self.unit, self.uname
        e = quiet(e, self.l1 + self.l2)  # B on D to rounding (cos 180 deg): 0, not 1.2e-14
        if self.l1 + self.l2 < e:
            return (
                f"cannot assemble {self.point}: {self.side(1)} + {self.side(2)} = "
                f"{in_units(self.l1 + self.l2, u)} {n} < {self.b}{self.d} = "
                f"{in_units(e, u)} {n} (short by {in_units(e - self.l1 - self.l2, u)} {n})"
            )
        return (
            f"cannot assemble {self.point}: |{self.side(1)} - {self.side(2)}| = "
            f"{in_units(abs(self.l1 - self.l2), u)} {n} > {self.b}{self.d} = "
            f"{in_units(e, u)} {n} (by {in_units(abs(self.l1 - self.l2) - e, u)} {n})"
        )

    def singular_why(self, c) -> str:
        return (
            f"{self.link1} and {self.link2} are in line (transmission angle "
            f"{crossing_angle(c):.3g} deg): a toggle position (or a "
            "change point, where the linkage may switch branch), where the direction "
            f"lines perpendicular to {self.link1} and {self.link2} are parallel and the "
            f"velocity of {self.point} is indeterminate"
        )

    def warning(self, c) -> str:
        deg = crossing_angle(c)
        return (
            f"{self.label}: {self.link1} and {self.link2} are nearly in line (transmission "
            f"angle {deg:.3g} deg, condition {c:.3g}): near a toggle position the "
            "intersection of the direction lines is ill-conditioned"
        )

    def limit_why(self) -> str:
        return (
            f"{self.side(1)} and {self.side(2)} come into line (a toggle: {self.point} "
            "cannot be assembled beyond it)"
        )

    def condition_column(self):
        """Its condition is the sine of the transmission angle at the point it finds."""
        return (f"mu at {self.finds[0]}", "deg", "transmission angle (acute)")

    def transmission(self):
        return f"between {self.side(1)} and {self.side(2)}"

    def bodies(self):
        return (self.link1, self.link2)

    def orient(self):
        return {self.link1: (self.point, self.b), self.link2: (self.point, self.d)}

    def output(self, ground):
        for g, link in ((self.d, self.link2), (self.b, self.link1)):
            if g in ground:
                return ("rocker", link, g, self.point)
        return None

    def position_words(self, L, which, angle_deg):
        return (
            f"{self.point}: arcs of radius {self.link1} = {L(self.l1)} about {self.b} and "
            f"{self.link2} = {L(self.l2)} about {self.d} meet at {self.point} (of the two "
            f"intersections, {which(self.point)})"
        )

    # ----- the polygons
    def construction(self, sol, ph):
        P, X, B, D = sol.P, self.point, self.b, self.d
        cond = sol.conditions.get(self.index, 1.0)
        lab = lambda p: image_label(sol, p, ph)  # noqa: E731
        d1 = unit(*perp(sub(P[X], P[B])))
        d2 = unit(*perp(sub(P[X], P[D])))
        if ph == "velocity":
            V = sol.V
            lines = (
                DirectionLine(V[B], d1, lab(B), f"perpendicular to {B}{X}", mark=f"\u22a5 {B}{X}"),
                DirectionLine(V[D], d2, lab(D), f"perpendicular to {D}{X}", mark=f"\u22a5 {D}{X}"),
            )
            text = (
                f"through {pole_text(sol, B, ph)} draw a line perpendicular to {B}{X}; "
                f"through {pole_text(sol, D, ph)}, one perpendicular to {D}{X}; they meet "
                f"at {lab(X)}"
            )
            found = (
                relative(sol, X, B, V, ph),
                relative(sol, X, D, V, ph),
                absolute(sol, X, V, ph),
            )
            return Construction(
                self.index, self.title, ph, lab(X), V[X], (), lines, found, text, cond
            )
        A = sol.A
        c1 = centripetal(sol, X, B, self.link1, ph)
        c2 = centripetal(sol, X, D, self.link2, ph)
        lines = (
            DirectionLine(
                c1.end,
                d1,
                f"the end of the centripetal of {X}{B}",
                f"perpendicular to {B}{X}",
                mark=f"\u22a5 {B}{X}",
            ),
            DirectionLine(
                c2.end,
                d2,
                f"the end of the centripetal of {X}{D}",
                f"perpendicular to {D}{X}",
                mark=f"\u22a5 {D}{X}",
            ),
        )
        text = (
            f"from {pole_text(sol, B, ph)} draw the centripetal of {X}{B} ({c1.text}), and "
            f"through its end a line perpendicular to {B}{X}; from {pole_text(sol, D, ph)} "
            f"draw the centripetal of {X}{D} ({c2.text}), and through its end a line "
            f"perpendicular to {D}{X}; they meet at {lab(X)}"
        )
        found = (
            tangential(sol, X, B, self.link1, c1.end),
            tangential(sol, X, D, self.link2, c2.end),
            relative(sol, X, B, A, ph),
            relative(sol, X, D, A, ph),
            absolute(sol, X, A, ph),
        )
        return Construction(
            self.index, self.title, ph, lab(X), A[X], (c1, c2), lines, found, text, cond
        )
