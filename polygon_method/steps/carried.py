"""A point carried on a known link (or plate): its image is found by similar triangles.

``X = P + lam (Q - P) + mu perp(Q - P)`` from two known points P, Q of the same body; the
same holds for the velocity and acceleration images (triangle pqx similar to PQX, read the
same way round). ``mu = 0``: x on the line pq (produced if lam is outside 0..1).

>>> image(1.0, 2.0, 3.0, 2.0, 0.5, 0.5)
(2.0, 3.0)
"""

from __future__ import annotations

from dataclasses import dataclass

from ..common.tolerances import LEAST_REACH
from .base import Construction, Step, absolute, image_label, image_name, relative
from .rounding import vhypot, vmax

__all__ = ["Carried", "image", "recognise"]


def image(px, py, qx, qy, lam, mu):
    """P + lam (Q - P) + mu perp(Q - P): a position, a velocity or an acceleration image."""
    dx, dy = qx - px, qy - py
    return px + lam * dx - mu * dy, py + lam * dy + mu * dx


def _image(px, py, qx, qy, lam, mu):
    # the same as image(), skipping zero terms (exactly as a hand construction does)
    dx = qx - px
    dy = qy - py
    if lam:
        if mu:
            return px + lam * dx - mu * dy, py + lam * dy + mu * dx
        return px + lam * dx, py + lam * dy
    if mu:
        return px - mu * dy, py + mu * dx
    return px, py


def _one_instant(p, q, X, i, lam, mu):
    """``bind_group_instant``'s function for one point carried by ``p, q`` whose ``lam``
    and ``mu`` are both non-zero (a point off the line PQ): the same operations in the same
    order, the loop and its tests of zero terms left out."""

    def instant(m):
        P = m.P
        V = m.V
        A = m.A
        px, py = P[p]
        qx, qy = P[q]
        dx = qx - px
        dy = qy - py
        P[X] = (px + lam * dx - mu * dy, py + lam * dy + mu * dx)
        px, py = V[p]
        qx, qy = V[q]
        dx = qx - px
        dy = qy - py
        V[X] = (px + lam * dx - mu * dy, py + lam * dy + mu * dx)
        px, py = A[p]
        qx, qy = A[q]
        dx = qx - px
        dy = qy - py
        A[X] = (px + lam * dx - mu * dy, py + lam * dy + mu * dx)

    return instant


def _two_instant(p, q, X, i, lam, _, Y, j, lam2, mu2):
    """``bind_group_instant``'s function for two points carried by ``p, q``: the first on
    the line PQ (its ``mu`` zero), the second off it (a coupler's point on the line and one
    beside it, the seed's E and F): the same operations in the same order, unrolled."""

    def instant(m):
        P = m.P
        V = m.V
        A = m.A
        px, py = P[p]
        qx, qy = P[q]
        dx = qx - px
        dy = qy - py
        vx, vy = V[p]
        qx, qy = V[q]
        vdx = qx - vx
        vdy = qy - vy
        ax, ay = A[p]
        qx, qy = A[q]
        adx = qx - ax
        ady = qy - ay
        P[X] = (px + lam * dx, py + lam * dy)
        V[X] = (vx + lam * vdx, vy + lam * vdy)
        A[X] = (ax + lam * adx, ay + lam * ady)
        P[Y] = (px + lam2 * dx - mu2 * dy, py + lam2 * dy + mu2 * dx)
        V[Y] = (vx + lam2 * vdx - mu2 * vdy, vy + lam2 * vdy + mu2 * vdx)
        A[Y] = (ax + lam2 * adx - mu2 * ady, ay + lam2 * ady + mu2 * adx)

    return instant


def recognise(g, name):
    """A body of ``name`` with two known points."""
    P, frame = g.P, g.bodies.frame
    for key in g.bodies_of(name):
        b = frame(key)
        if len(b) == 2:  # a plain link: its other end alone is no second known point
            continue
        known = [p for p in b if p in P]
        if len(known) >= 2:
            lk = g.bodies.link(key)
            cp = g.carried(name)
            if key not in g.used_links and name in lk.points:
                continue  # both ends known, the link unused: redundant, reported later
            ends = [p for p in lk.points if p in P]
            refs = ends if len(ends) == 2 else known[:2]
            how = cp.how if cp is not None and cp.link == key else ""
            lam, mu = g.bodies.coefficients(key, refs[0], refs[1], name)
            return Carried(g.next_index, name, key, refs[0], refs[1], lam, mu, how)
    return None


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

    kind = "carried"
    steady = True  # nothing intersected: its condition is 1 at every instant
    draws_relative = False

    @property
    def image_by_similar_triangle(self):
        return self.mu != 0

    @property
    def finds(self):
        return (self.point,)

    @property
    def links(self):
        return ()

    @property
    def needs(self):
        return (self.p, self.q)

    @property
    def title(self):
        return f"point {self.point} on {self.link}"

    @property
    def params(self):
        return (self.lam, self.mu)

    def dimensions(self, scene, bodies):
        return bodies.coefficients(self.link, self.p, self.q, self.point)

    def drawn(self, prm, pencil, P):
        (px, py), (qx, qy) = P[self.p], P[self.q]
        L = ((qx - px) ** 2 + (qy - py) ** 2) ** 0.5  # the point is set out from p and q
        return (prm[0] + pencil(L), prm[1] + pencil(L))

    def condition_column(self):
        return None

    def reach(self):
        """Its distance from the first point it is carried by, over the line of the two
        (a scale only: a carried point has one position)."""
        return max(LEAST_REACH, (self.lam * self.lam + self.mu * self.mu) ** 0.5)

    def singular_why(self, c) -> str:
        return f"the point {self.point} is carried on {self.link}: it is never singular"

    def warning(self, c) -> str:
        return f"{self.label}: condition {c:.3g}"

    def limit_why(self) -> str:
        return "the linkage cannot be assembled beyond it"

    def transmission(self):
        return None

    def bodies(self):
        return ()  # it moves with the body it is carried on

    def orient(self):
        return {}

    def place(self, P, prm, ctx, sigma=None):
        x, y = _image(*P[self.p], *P[self.q], prm[0], prm[1])
        return x, y, 1.0

    def bind(self, prm):
        """The step's three phases for dimensions ``prm``: functions of a State (a group
        of one, see ``bind_group``)."""
        return Carried.bind_group((self,), (prm,))

    @property
    def group_key(self):
        return (self.p, self.q)

    @staticmethod
    def _group(steps, prms):
        """What the phases of points carried by the same two points share: those points
        ``p, q``, each point's (name, step index, lam, mu), and the image formula (zero
        terms skipped for floats, every term for arrays of dimensions)."""
        items = tuple((st.point, st.index, prm[0], prm[1]) for st, prm in zip(steps, prms))
        scalar = all(isinstance(v, (int, float)) for it in items for v in it[2:])
        return steps[0].p, steps[0].q, items, (_image if scalar else image)

    @staticmethod
    def bind_group(steps, prms):
        """The phases of several points carried by the same two points (E, F, G on BC),
        in one call each: the same image formula."""
        p, q, items, img = Carried._group(steps, prms)

        def position(m):
            P, cond = m.P, m.cond
            (px, py), (qx, qy) = P[p], P[q]
            for X, i, lam, mu in items:
                P[X] = img(px, py, qx, qy, lam, mu)
                cond[i] = 1.0

        def velocity(m):
            V = m.V
            (px, py), (qx, qy) = V[p], V[q]
            for X, _, lam, mu in items:
                V[X] = img(px, py, qx, qy, lam, mu)

        def acceleration(m):
            A = m.A
            (px, py), (qx, qy) = A[p], A[q]
            for X, _, lam, mu in items:
                A[X] = img(px, py, qx, qy, lam, mu)

        return position, velocity, acceleration

    def bind_instant(self, prm):
        """The three phases in a row for one instant (the same formula, see ``bind``)."""
        return Carried.bind_group_instant((self,), (prm,))

    @staticmethod
    def bind_group_instant(steps, prms):
        """The three phases of ``bind_group`` in a row, for one instant: for floats the
        image formula written out (``Q - P`` of each polygon taken once for all the points
        carried by P and Q, zero terms skipped as :func:`_image` skips them), the same
        operations in the same order, so every number is the phased road's to the last
        bit (a test holds the two roads equal)."""
        p, q, items, img = Carried._group(steps, prms)
        if img is not _image:  # dimensions not plain floats: the formula itself

            def instant(m):
                P = m.P
                V = m.V
                A = m.A
                px, py = P[p]
                qx, qy = P[q]
                vpx, vpy = V[p]
                vqx, vqy = V[q]
                apx, apy = A[p]
                aqx, aqy = A[q]
                for X, i, lam, mu in items:
                    P[X] = img(px, py, qx, qy, lam, mu)
                    V[X] = img(vpx, vpy, vqx, vqy, lam, mu)
                    A[X] = img(apx, apy, aqx, aqy, lam, mu)

            return instant
        if len(items) == 1 and items[0][2] and items[0][3]:
            return _one_instant(p, q, *items[0])  # (no loop, no zero term to test)
        if len(items) == 2 and items[0][2] and not items[0][3] and items[1][2] and items[1][3]:
            return _two_instant(p, q, *items[0], *items[1])

        def instant(m):
            P = m.P
            V = m.V
            A = m.A
            px, py = P[p]
            qx, qy = P[q]
            dx = qx - px
            dy = qy - py
            vx, vy = V[p]
            qx, qy = V[q]
            vdx = qx - vx
            vdy = qy - vy
            ax, ay = A[p]
            qx, qy = A[q]
            adx = qx - ax
            ady = qy - ay
            for X, i, lam, mu in items:
                if lam:
                    if mu:
                        P[X] = (px + lam * dx - mu * dy, py + lam * dy + mu * dx)
                        V[X] = (vx + lam * vdx - mu * vdy, vy + lam * vdy + mu * vdx)
                        A[X] = (ax + lam * adx - mu * ady, ay + lam * ady + mu * adx)
                    else:
                        P[X] = (px + lam * dx, py + lam * dy)
                        V[X] = (vx + lam * vdx, vy + lam * vdy)
                        A[X] = (ax + lam * adx, ay + lam * ady)
                elif mu:
                    P[X] = (px - mu * dy, py + mu * dx)
                    V[X] = (vx - mu * vdy, vy + mu * vdx)
                    A[X] = (ax - mu * ady, ay + mu * adx)
                else:
                    P[X] = (px, py)
                    V[X] = (vx, vy)
                    A[X] = (ax, ay)

        return instant

    rounding = 8.0

    def error_bound(self, walk, k, p_in, v_in, a_in):
        """The errors of the two points it is carried by, times ``1 + (|XP| + |XQ|) /
        |PQ|`` (how far out of its base it reaches), plus its own rounding, plus how far
        its place on the body may be off from the numbers it is given (its ``spread``:
        large only on a nearly flat triangle, whose height is ill-conditioned)."""
        P = walk.P
        x = self.point
        if self.p in P and self.q in P and x in P:
            (px, py), (ax, ay), (bx, by) = P[x], P[self.p], P[self.q]
            gain = 1.0 + (vhypot(px - ax, py - ay) + vhypot(px - bx, py - by)) / vhypot(
                bx - ax, by - ay
            )
        else:
            gain = 1.0
        kp, kv, ka = walk.own(self, k)
        p, v, a = gain * p_in + kp, gain * v_in + kv, gain * a_in + ka
        spread = walk.spread.get(x, 0.0)
        if spread and self.p in P and self.q in P:
            # its place on the body is off by `spread` (m): it turns and accelerates with
            # the body, |omega| = |vQ - vP| / |PQ|, |(alpha, omega^2)| = |aQ - aP| / |PQ|
            sz, V, A = walk.sizes, walk.V, walk.A
            pq = vmax(vhypot(bx - ax, by - ay), 1e-300)
            q_, p_ = self.q, self.p
            w = vhypot(V[q_][0] - V[p_][0], V[q_][1] - V[p_][1]) / pq
            acc = vhypot(A[q_][0] - A[p_][0], A[q_][1] - A[p_][1]) / pq
            p = p + spread / sz["position"]
            v = v + spread * w / sz["velocity"]
            a = a + spread * acc / sz["acceleration"]
        return p, v, a, v, a

    def produced(self):
        if self.mu != 0 or 0.0 <= self.lam <= 1.0:
            return None
        return (self.q if self.lam < 0 else self.p, self.point)

    def position_words(self, L, which, angle_deg):
        return f"{self.point}: {self.how or 'on ' + self.link}"

    def construction(self, sol, ph):
        lab = lambda p: image_label(sol, p, ph)  # noqa: E731
        D = sol.V if ph == "velocity" else sol.A
        X, p, q = self.point, self.p, self.q
        # a fixed end keeps its own letter in the figure's name, said to be at the pole:
        # "triangle cdg (d at the pole o)", not "triangle cog"
        own = lambda P: image_name(sol.scene, P) + ("'" if ph == "acceleration" else "")  # noqa: E731
        poles = [P for P in (p, q) if lab(P) != own(P)]
        at_pole = "".join(f" ({own(P)} at the pole {lab(P)})" for P in poles)
        if self.mu == 0:
            text = (
                f"{own(p)}{lab(X)} / {own(p)}{own(q)} = {p}{X} / {p}{q} = {self.lam:.4g}: "
                f"{lab(X)} on {own(p)}{own(q)}"
                + (" produced" if not 0 <= self.lam <= 1 else "")
                + at_pole
            )
        else:
            text = (
                f"triangle {own(p)}{own(q)}{lab(X)}{at_pole} similar to {p}{q}{X}, read "
                f"the same way round ({'ccw' if self.mu > 0 else 'cw'}): {lab(X)} is the "
                f"image of {X}"
            )
        found = (absolute(sol, X, D, ph), relative(sol, X, p, D, ph))
        return Construction(
            self.index,
            self.title,
            ph,
            lab(X),
            D[X],
            (),
            (),
            found,
            text,
            sol.conditions.get(self.index, 1.0),
        )
