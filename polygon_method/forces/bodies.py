"""Each body's inertia and the loads on it, gathered as resultants before the pin forces
are solved.

A body's known forces are kept as one resultant ``(Fx, Fy, M)``, ``M`` about the frame's
origin: a force ``F`` at ``r`` adds ``F`` and ``cross(r, F)``, a couple ``C`` adds ``C``.
The moment about another point ``B`` is then ``M - cross(B, F)``.
"""

from __future__ import annotations

from ..scene.link_loads import load_force
from .engine import indicator_forces
from .records import FRAME, Inertia, Side, block


class Singular(Exception):
    """A force step's equations have no unique solution here (its words: why)."""


#: the first item of the head of a short road's raw pin entry holding a dyad's three pins
#: at once (``((THREE_PINS, c, l1, l2, b, ob, d, od), px, py, ex, ey, gx, gy)``: the pin
#: forces ``(px, py)``, ``(-ex, -ey)``, ``(-gx, -gy)``), expanded when the records are read
THREE_PINS = ("three pins",)
#: the same for one pin whose force is kept negated (``((NEGATED_PIN, point, on, by), fx,
#: fy)``: the force ``(-fx, -fy)``), as a crank's pivot keeps it
NEGATED_PIN = ("a negated pin",)


def any_zero(x) -> bool:
    """Whether ``x`` (a float, or an array over a sweep) is exactly zero anywhere."""
    z = x == 0
    return bool(z) if isinstance(z, bool) else bool(z.any())


def least(a, b):
    """The smaller of two floats, or entry by entry of arrays."""
    if isinstance(a, float) and isinstance(b, float):
        return a if a <= b else b
    import numpy as np

    return np.minimum(a, b)


def cross(ax, ay, bx, by):
    """``a x b`` (the z-component)."""
    return ax * by - ay * bx


def guided(qx, qy, known, xx, xy, n, r):
    """The one relation of a body pinned at Q (the pin force there unknown) that carries the
    known forces ``known = (Fx, Fy, M about the origin)`` and, at X, a push ``N n + r`` whose
    only unknown is N (a frictionless guide's normal force along the unit ``n``, with the
    known forces ``r`` passed on with it: a block's loads, a wheel's friction). Its moments
    about Q, where the pin force has no arm, then its force balance::

        cross(X - Q, N n + r) + M_Q = 0   =>   N = -(M_Q + cross(X - Q, r)) / cross(X - Q, n)
        F_Q = -(F + N n + r)

    Returns ``(N, the push N n + r, F_Q, cross(X - Q, n))``; N and the forces are None
    where ``cross(X - Q, n)`` is zero (X - Q along n: the moments cannot hold N). Floats or
    arrays over a sweep. A body pinned at the origin pushed at (1, 0) across by N (0, 1),
    with a couple of 2 N m ccw on it: N = -2, and the pin holds it with 2 N up:

    >>> guided(0.0, 0.0, (0.0, 0.0, 2.0), 1.0, 0.0, (0.0, 1.0), (0.0, 0.0))
    (-2.0, (0.0, -2.0), (-0.0, 2.0), 1.0)
    """
    fx, fy, m = known
    rx, ry = r[0], r[1]  # (a known resultant's moment, if given, is not used)
    nx, ny = n
    mq = m - (qx * fy - qy * fx)  # cross(Q, F), written out (the short road's too)
    ex, ey = xx - qx, xy - qy
    den = ex * ny - ey * nx  # cross(X - Q, n)
    if any_zero(den):
        return None, None, None, den
    N = -(mq + (ex * ry - ey * rx)) / den  # cross(X - Q, r)
    px, py = N * nx + rx, N * ny + ry
    return N, (px, py), (-(fx + px), -(fy + py)), den


def sums_of(S, i):
    """``(Fx, Fy, M about the origin)`` known on body ``i`` in the short road's sums ``S``:
    three lists by the body's number (the frame 0), ``(Fx, Fy, M)``."""
    return (S[0][i], S[1][i], S[2][i])


def sums_add(S, i, fx, fy, x, y):
    """A force ``(fx, fy)`` at ``(x, y)`` on body ``i`` added to the sums ``S``, as the
    :class:`Ledger` adds it (``t + f``, ``t + cross(r, f)``)."""
    sx, sy, sm = S
    sx[i] = sx[i] + fx
    sy[i] = sy[i] + fy
    sm[i] = sm[i] + (x * fy - y * fx)


def centre(P, lam, mu, p, q):
    """``p + lam (q - p) + mu perp(q - p)`` (a point carried on a link, its image on the
    velocity and the acceleration polygons alike)."""
    (px, py), (qx, qy) = P[p], P[q]
    dx, dy = qx - px, qy - py
    return (px + lam * dx - mu * dy, py + lam * dy + mu * dx)


def inertia_record(body, mass, inertia, G, a_G, alpha, how=""):
    """:class:`Inertia`: ``-m a_G``, ``-I alpha`` and the offset ``I alpha / (m |a_G|)``."""
    fx, fy = -mass * a_G[0], -mass * a_G[1]
    f = (fx * fx + fy * fy) ** 0.5
    couple = -inertia * alpha
    if isinstance(f, float):
        offset = inertia * alpha / f if f > 0 else None
    else:  # a sweep (arrays): the force and the couple; no single line
        offset = None
    return Inertia(body, mass, inertia, G, a_G, alpha, (fx, fy), couple, offset, how)


class Ledger:
    """The resultants of the known forces on each body, filled as the solution goes on."""

    def __init__(self):
        self.total = {}
        self.applied = {}
        #: a driving cylinder's force (N), by its key, and the condition it was found with
        self.given = {}
        self.conditions = {}
        #: a passive cylinder's force given in the scene (N, + pushing apart), by its key
        self.stated = {}
        self.items = {}  # body -> the known forces one by one (:class:`Side`), in order

    def add(self, body, fx, fy, x, y, what=None, side=None):
        """A force ``(fx, fy)`` acting at ``(x, y)`` on ``body`` (``side``: the same as a
        force polygon draws it)."""
        t = self.total.get(body, (0.0, 0.0, 0.0))
        self.total[body] = (t[0] + fx, t[1] + fy, t[2] + cross(x, y, fx, fy))
        if what is not None:
            self.applied.setdefault(body, []).append((what, (fx, fy), (x, y)))
        if side is not None:
            self.items.setdefault(body, []).append(side)

    def known(self, body) -> tuple:
        """The known forces on ``body`` one by one (:class:`Side`), so far."""
        return tuple(self.items.get(body, ()))

    def couple(self, body, c, what=None):
        """Add a known couple ``c`` (N m, ccw positive) on ``body``, with its words ``what`` for the
        step table."""
        t = self.total.get(body, (0.0, 0.0, 0.0))
        self.total[body] = (t[0], t[1], t[2] + c)
        if what is not None:
            self.applied.setdefault(body, []).append((what, c))

    def of(self, body):
        """``(Fx, Fy, M about the origin)`` known on ``body``."""
        return self.total.get(body, (0.0, 0.0, 0.0))


def gather(scene, motion, owner):
    """(inertia records, the :class:`Ledger` of inertia, weights and loads per body).

    ``owner``: point -> the body a load at that point acts on (the frame for a ground
    point: a load there is not the mechanism's)."""
    P, A, Al = motion.P, motion.A, motion.Al
    grav = scene.gravity
    led = Ledger()
    records = []
    fixed = {lk.key for lk in scene.links if lk.p in scene.ground and lk.q in scene.ground}
    for m in scene.masses:
        if m.body in fixed:  # a part of the frame: it neither moves nor loads the mechanism
            continue
        if m.block:
            G, a_G, alpha, body = P[m.body], A[m.body], 0.0, block(m.body)
        else:
            lk = scene.link(m.body)
            G = centre(P, m.lam, m.mu, lk.p, lk.q)
            a_G = centre(A, m.lam, m.mu, lk.p, lk.q)
            alpha, body = Al[lk.key], lk.key
        rec = inertia_record(body, m.mass, m.inertia, G, a_G, alpha, m.how)
        records.append(rec)
        led.add(
            body,
            rec.force[0],
            rec.force[1],
            G[0],
            G[1],
            side=Side("inertia", body, "", "", rec.force, G),
        )  # (its line: free bodies)
        led.couple(body, rec.couple)
        if grav is not None:
            w = m.mass * grav.g
            wx, wy = w * grav.direction[0], w * grav.direction[1]
            led.add(
                body,
                wx,
                wy,
                G[0],
                G[1],
                f"weight of {body}",
                Side("weight", body, "", "", (wx, wy), G),
            )
    for ld in scene.loads:
        if ld.force is not None:
            body = owner.get(ld.target, FRAME)
            if body == FRAME:
                continue
            x, y = P[ld.target]
            f = load_force(ld, P)  # (a force against a link turns with it)
            led.add(
                body,
                f[0],
                f[1],
                x,
                y,
                f"gas force at {ld.target}" if ld.gas else f"load at {ld.target}",
                Side("gas" if ld.gas else "load", body, "", ld.target, f, (x, y)),
            )
            if ld.gas:  # the gas pushes the cylinder's cover (the frame) as hard, back
                led.add(FRAME, -f[0], -f[1], x, y)  # along the same line
        else:
            led.couple(ld.target, ld.torque, f"couple on {ld.target}")
    for piston, fx, fy, p in indicator_forces(scene, motion):  # the indicators' gas forces
        x, y = P[piston]
        body = owner.get(piston, FRAME)
        what = (
            f"gas force at {piston} (indicator: {p / 1e5:.6g} bar)"
            if isinstance(p, float)
            else None
        )
        led.add(body, fx, fy, x, y, what)
        led.add(FRAME, -fx, -fy, x, y)
    return tuple(records), led


def along(f, p, q):
    """(the component of ``f`` along the line p -> q, the rest: square to it), as a force
    polygon splits an outer pin's force (the square part from the link's moments, the
    part along the link found where the direction lines meet).

    >>> along((3.0, 4.0), (0.0, 0.0), (2.0, 0.0))
    ((3.0, 0.0), (0.0, 4.0))
    """
    ex, ey = q[0] - p[0], q[1] - p[1]
    k = (f[0] * ex + f[1] * ey) / (ex * ex + ey * ey)
    n = (k * ex, k * ey)
    return n, (f[0] - n[0], f[1] - n[1])


def unit(p, q):
    """The unit vector from ``p`` to ``q``."""
    ex, ey = q[0] - p[0], q[1] - p[1]
    d = (ex * ex + ey * ey) ** 0.5
    return (ex / d, ey / d)


def outer_pin(side_whole, p, q):
    """The two sides (along the link p -> q, square to it) of an outer pin's force, as the
    polygon draws them (:class:`Side` s with ``part`` ``n`` and ``t``)."""
    n, t = along(side_whole.vector, p, q)
    w = side_whole
    return (
        Side(w.what, w.on, w.by, w.point, n, w.at, "n"),
        Side(w.what, w.on, w.by, w.point, t, w.at, "t"),
    )


def split(side, u):
    """The two sides of a force (a :class:`Side`) along the unit ``u`` (``part`` ``n``) and
    square to it (``t``), as a polygon draws a force whose part along a guide or a slot is
    found first and the rest where the direction lines meet.

    >>> [s.vector for s in split(Side("pin", "a", "b", "X", (3.0, 4.0), (0.0, 0.0)), (0.0, 1.0))]
    [(0.0, 4.0), (3.0, 0.0)]
    """
    ux, uy = u
    fx, fy = side.vector
    k = fx * ux + fy * uy
    n = (k * ux, k * uy)
    w = side
    return (
        Side(w.what, w.on, w.by, w.point, n, w.at, "n"),
        Side(w.what, w.on, w.by, w.point, (fx - n[0], fy - n[1]), w.at, "t"),
    )


def direction(v, fallback):
    """The unit along ``v``, or ``fallback`` where ``v`` is nil (a force's line known
    before its size: a tooth load's line of action)."""
    n = (v[0] * v[0] + v[1] * v[1]) ** 0.5
    return (v[0] / n, v[1] / n) if n > 0 else fallback
