"""RRP: a link and a slider. Point X is joined by a link to known B and slides on a
guide line: a fixed path, or a moving link whose two ends are known.

Position: X on the line Q + s u with |XB| = l: ``s = -(Q - B).u +- sqrt(l^2 - d^2)``,
d = (Q - B) x u. Velocity: through b a line perpendicular to BX, through the guide's point
coincident with X (o for a fixed path) a line parallel to the guide::

    w perp(r) - vs u = vX' - vB,   w = u x (vX' - vB) / (r.u),   vs = -r.(vX' - vB) / (r.u)

with r = X - B and X' the guide's point under the block. Acceleration: the right side
``aX' + 2 wG vs perp(u) - aB + w^2 r`` (with the Coriolis component on a moving guide).
Condition: |r.u| / l, the sine of the angle between the two direction lines.

>>> x, y, c = place(0.0, 0.3, 0.0, 0.0, 1.0, 0.0, 0.5, 1.0)   # a rod of 0.5 from (0, 0.3)
>>> round(x, 12), round(y, 12), round(c, 12)
(0.4, 0.0, 0.8)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .relations import coriolis
from ..common.numbers import in_units, condition_text
from ..common.tolerances import LEAST_REACH
from ..scene import FixedPath, GuideSlider, guide_words
from .rounding import line_rounding, plus, turning, two_lines, vhypot, vmax
from .slotted import under_label
from .base import (
    Construction,
    DirectionLine,
    Step,
    Vector,
    absolute,
    add,
    centripetal,
    image_label,
    perp,
    pole_text,
    relative,
    sub,
    tangential,
    unit,
)

__all__ = ["SliderDyad", "place", "velocity", "acceleration", "guide_point", "recognise"]


def place(bx, by, qx, qy, ux, uy, ell, sigma, ctx=None, step=None):
    """X on the line Q + s u with |XB| = ell. Returns x, y and the condition
    sqrt(ell^2 - d^2) / ell = |r.u| / ell."""
    wx, wy = qx - bx, qy - by
    b = wx * ux + wy * uy
    dist = wx * uy - wy * ux
    disc = (ell - dist) * (ell + dist)
    if ctx is None:
        half = max(disc, 0.0) ** 0.5
    else:
        half = ctx.root(disc, ell * ell, step, lambda: step.why(dist))
    s = sigma * half - b
    return qx + s * ux, qy + s * uy, half / ell


def guide_point(gx, gy, x, y, w, vgx, vgy):
    """The velocity of the guide's point under the block at (x, y): vG + w perp(X - G)."""
    return vgx - w * (y - gy), vgy + w * (x - gx)


def guide_point_acceleration(gx, gy, x, y, w, al, agx, agy):
    """The acceleration of the guide's point under the block: aG - w^2 (X - G) + al perp(X - G)."""
    px, py = x - gx, y - gy
    k = w * w
    return agx - k * px - al * py, agy - k * py + al * px


def velocity(rx, ry, ux, uy, wx, wy, vbx, vby, d=None):
    """(w, vs, vx, vy) with ``wx, wy`` = vX' - vB: the link's omega, the sliding velocity
    along u, the velocity of X."""
    if d is None:
        d = rx * ux + ry * uy
    w = (ux * wy - uy * wx) / d
    vs = -(rx * wx + ry * wy) / d
    return w, vs, vbx - w * ry, vby + w * rx


def acceleration(rx, ry, ux, uy, tx, ty, w, abx, aby, d=None):
    """(al, as, ax, ay) with ``tx, ty`` = aX' + Coriolis: the link's alpha, the sliding
    acceleration along u, the acceleration of X."""
    if d is None:
        d = rx * ux + ry * uy
    k = w * w
    qx = tx - abx + k * rx
    qy = ty - aby + k * ry
    al = (ux * qy - uy * qx) / d
    a_s = -(rx * qx + ry * qy) / d
    return al, a_s, abx - k * rx - al * ry, aby - k * ry + al * rx


def recognise(g, name):
    """A slider whose point has one free body with a known point, on a fixed path or on a
    guide link already found."""
    sc = g.scene
    sl = g.slider(name)
    if sl is None or name in g.used_sliders:
        return None
    free = g.free(name)
    if not free:
        return None
    key, k, length = free[0]
    if isinstance(sl, FixedPath):
        g.used_sliders.add(name)
        return SliderDyad(g.next_index, name, k, key, length, path=sl, unit=g.unit, uname=g.uname)
    if isinstance(sl, GuideSlider):
        guide = sc.link(sl.guide)
        if g.known_link(guide) and guide.key in g.used_links:
            g.used_sliders.add(name)
            return SliderDyad(
                g.next_index,
                name,
                k,
                key,
                length,
                guide=guide.key,
                g1=sl.first,
                g2=sl.second,
                unit=g.unit,
                uname=g.uname,
                offset=sl.offset,
            )
    return None


@dataclass(frozen=True)
class SliderDyad(Step):
    """RRP: point X with XB = l to known B, sliding on a guide line (see the module)."""

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
    #: a moving guide's offset slot: its line this far (m) to the left of g1 -> g2
    offset: float = 0.0

    kind = "slider"
    branching = True
    other_assembly_mistake = True

    @property
    def finds(self):
        return (self.point,)

    @property
    def links(self):
        return (self.link,)

    @property
    def needs(self):
        return (self.b,) if self.path is not None else (self.b, self.g1, self.g2)

    @property
    def needs_links(self):
        return () if self.path is not None else (self.guide,)

    @property
    def title(self):
        if self.path is None:
            where = f"link {self.guide}"
        elif self.path.label in ("horizontal", "vertical"):
            where = f"the {guide_words(self.path.label)}"
        else:
            where = f"the path {self.path.label}"
        return f"link {self.link}, slider {self.point} on {where}"

    @property
    def params(self):
        if self.path is None:
            return (self.length, self.offset)
        (qx, qy), (ux, uy) = self.path.through, self.path.u
        return (self.length, qx, qy, ux, uy)

    def dimensions(self, scene, bodies):
        ell = bodies.distance(self.link, self.b, self.point)
        if self.path is None:
            return (ell, scene.slider(self.point).offset)
        path = scene.slider(self.point)
        (qx, qy), (ux, uy) = path.through, path.u
        return (ell, qx, qy, ux, uy)

    def drawn(self, prm, pencil, P):
        if self.path is None:  # (an offset slot's line set off with the pencil too)
            return (prm[0] + pencil(), prm[1] + pencil() if self.offset else prm[1])
        return (prm[0] + pencil(), prm[1] + pencil(), prm[2] + pencil(), prm[3], prm[4])

    def reach(self):
        return max(self.length, LEAST_REACH)

    def line(self, P, prm=None):
        """A point of the guide line and its unit direction (an offset slot's line: its
        point the offset to the left of g1)."""
        prm = self.params if prm is None else prm
        if self.path is not None:
            return prm[1], prm[2], prm[3], prm[4]
        (gx, gy), (hx, hy) = P[self.g1], P[self.g2]
        ux, uy = hx - gx, hy - gy
        m = (ux * ux + uy * uy) ** 0.5
        ux, uy = ux / m, uy / m
        return gx - prm[1] * uy, gy + prm[1] * ux, ux, uy

    def place(self, P, prm, ctx, sigma=None):
        qx, qy, ux, uy = self.line(P, prm)
        bx, by = P[self.b]
        s = self.sigma if sigma is None else sigma
        return place(bx, by, qx, qy, ux, uy, prm[0], s, ctx, self)

    def default_hint(self, P):
        _, _, ux, uy = self.line(P)
        return (ux, uy)  # along the guide's direction

    def bind(self, prm):
        """The step's three phases for dimensions ``prm``: functions of a State."""
        X, B, link, i, sigma, step = self.point, self.b, self.link, self.index, self.sigma, self
        ell = prm[0]
        fixed = self.path is not None
        G1, G2, guide = self.g1, self.g2, self.guide
        if fixed:
            qx, qy, fux, fuy = prm[1], prm[2], prm[3], prm[4]
        off = None if fixed or not self.offset else prm[1]

        def line(P):
            if fixed:
                return qx, qy, fux, fuy
            (gx, gy), (hx, hy) = P[G1], P[G2]
            ux, uy = hx - gx, hy - gy
            n = (ux * ux + uy * uy) ** 0.5
            return gx, gy, ux / n, uy / n

        def position(m):
            P = m.P
            gx, gy, ux, uy = line(P)
            x, y, c = place(*P[B], gx, gy, ux, uy, ell, sigma, m.ctx, step)
            P[X] = (x, y)
            m.cond[i] = c

        def position_offset(m):  # the offset slot's line, off to the left of g1 -> g2
            P = m.P
            gx, gy, ux, uy = line(P)
            x, y, c = place(*P[B], gx - off * uy, gy + off * ux, ux, uy, ell, sigma, m.ctx, step)
            P[X] = (x, y)
            m.cond[i] = c

        def velocity_(m):
            P, V = m.P, m.V
            (x, y), (bx, by) = P[X], P[B]
            gx, gy, ux, uy = line(P)
            rx, ry = x - bx, y - by
            vbx, vby = V[B]
            if fixed:
                wx, wy = -vbx, -vby
            else:
                cx, cy = guide_point(gx, gy, x, y, m.W[guide], *V[G1])
                wx, wy = cx - vbx, cy - vby
            d = rx * ux + ry * uy
            if m.array:
                d = m.ctx.safe(d, step)
            w, vs, vx, vy = velocity(rx, ry, ux, uy, wx, wy, vbx, vby, d)
            m.W[link] = w
            m.S[X] = [vs, None, 0.0, 0.0]
            V[X] = (vx, vy)

        def acceleration_(m):
            P, A = m.P, m.A
            (x, y), (bx, by) = P[X], P[B]
            gx, gy, ux, uy = line(P)
            rx, ry = x - bx, y - by
            s = m.S[X]
            if fixed:
                cx = cy = tx = ty = 0.0
            else:
                wg = m.W[guide]
                cx, cy = coriolis(wg, s[0], ux, uy)
                tx, ty = guide_point_acceleration(gx, gy, x, y, wg, m.Al[guide], *A[G1])
                tx, ty = tx + cx, ty + cy
            d = rx * ux + ry * uy
            if m.array:
                d = m.ctx.safe(d, step)
            al, a_s, ax, ay = acceleration(rx, ry, ux, uy, tx, ty, m.W[link], *A[B], d)
            m.Al[link] = al
            s[1], s[2], s[3] = a_s, cx, cy
            A[X] = (ax, ay)

        return (position if off is None else position_offset), velocity_, acceleration_

    def coriolis_left_out(self, sol):
        """What a polygon drawn without the Coriolis component of a moving guide gives: the
        line parallel to the guide through the image of the guide's point under the block,
        not through the end of 2 omega vs. {(kind, name): value}: the rod's alpha (signed)
        and the size of the block's acceleration; nothing on a fixed path."""
        if self.path is not None:
            return {}
        P, A, X, B = sol.P, sol.A, self.point, self.b
        (x, y), (bx, by), (gx, gy) = P[X], P[B], P[self.g1]
        u = unit(*sub(P[self.g2], P[self.g1]))
        t = guide_point_acceleration(
            gx, gy, x, y, sol.W[self.guide], sol.Al[self.guide], *A[self.g1]
        )
        al, _, ax, ay = acceleration(x - bx, y - by, *u, *t, sol.W[self.link], *A[B])
        return {("alpha", self.link): al, ("a", X): math.hypot(ax, ay)}

    # ----- failures and words
    def why(self, dist):
        """Why the block cannot be placed: its link is shorter than the known end's distance
        ``dist`` from the path."""
        u, n = self.unit, self.uname
        where = (
            f"path {self.path.label}"
            if self.path
            else f"line of {self.guide}"
            if not self.offset
            else f"line of the slot of {self.guide} (offset {in_units(abs(self.offset), u)} {n})"
        )
        return (
            f"cannot assemble {self.point}: {self.link} = {in_units(self.length, u)} {n} "
            f"< distance of {self.b} from the {where} = {in_units(abs(dist), u)} {n}"
        )

    def singular_why(self, c) -> str:
        return (
            f"{self.link} is perpendicular to the guide of {self.point} "
            f"(sine {condition_text(c)}): a "
            f"dead centre for this step, where the line perpendicular to {self.link} is "
            "parallel to the guide"
        )

    def warning(self, c) -> str:
        return (
            f"{self.label}: the line perpendicular to {self.link} is nearly parallel to "
            f"the guide (condition {c:.3g}): near a dead centre for this step"
        )

    def limit_why(self) -> str:
        return (
            f"{self.link} stands perpendicular to the guide of {self.point} (it cannot "
            "reach the guide beyond it)"
        )

    def condition_column(self):
        """Its condition is the sine of the transmission angle at the point it finds."""
        return (f"mu at {self.finds[0]}", "deg", "transmission angle (acute)")

    def transmission(self):
        return f"between {self.link} and the normal to the path of {self.point}"

    def bodies(self):
        return (self.link, f"block {self.point}")

    def orient(self):
        return {self.link: (self.point, self.b)}

    def output(self, ground):
        if self.path is not None:
            return ("slider", self.point)
        if self.b in ground:  # a rocker about its fixed pivot, its end sliding on a moving link
            return ("rocker", self.link, self.b, self.point)
        return None

    def position_words(self, L, which, angle_deg):
        where = (
            f"the {guide_words(self.path.label, of=self.point)}"
            if self.path is not None
            else f"the line of {self.guide}"
            if not self.offset
            else f"the line of the slot of {self.guide}, parallel to {self.g1}{self.g2} and "
            f"{L(abs(self.offset))} to the {'left' if self.offset > 0 else 'right'} of it "
            f"(looking from {self.g1} to {self.g2}),"
        )
        return (
            f"{self.point}: an arc of radius {self.link} = {L(self.length)} about {self.b} "
            f"cuts {where} at {self.point} ({which(self.point)})"
        )

    def error_bound(self, walk, k, p_in, v_in, a_in):
        """Two direction lines (:mod:`.rounding`), with the path's own numbers in its
        rounding: a path through a point far from the mechanism is rounded to that point's
        digits (``X = Q + s u`` cancels ``|Q|``), and its direction, read as an angle, is
        off by the angle's rounding, which moves the line by that times ``|XQ|`` and turns
        the velocity and acceleration lines by it. The rod's omega and alpha from its own
        length (:func:`.rounding.turning`)."""
        P, V, A, sz = walk.P, walk.V, walk.A, walk.sizes
        X, B = self.point, self.b
        (x, y), (bx, by) = P[X], P[B]
        own = k
        if self.path is not None:
            (qx, qy) = self.path.through
            own = k + line_rounding(
                self.rounding, qx, qy, x, y, sz["position"], getattr(self.path, "angle", None)
            )
        p, v, a, _, _ = two_lines(
            walk.condition(self),
            walk.ratio,
            plus(walk.own(self, k), own - k),
            p_in,
            v_in,
            a_in,
            walk.couple(self),
        )
        tab = walk.box.tables
        dv = vhypot(V[X][0] - V[B][0], V[X][1] - V[B][1])
        da = vhypot(A[X][0] - A[B][0], A[X][1] - A[B][1])
        w, al = turning(
            walk,
            x - bx,
            y - by,
            dv,
            da,
            p + tab[0].get(B, 0.0),
            v + tab[1].get(B, 0.0),
            a + tab[2].get(B, 0.0),
            own,
        )
        return p, v, a, vmax(v, w), vmax(a, al)

    # ----- the polygons
    def construction(self, sol, ph):
        P, X, B = sol.P, self.point, self.b
        cond = sol.conditions.get(self.index, 1.0)
        lab = lambda p: image_label(sol, p, ph)  # noqa: E731
        d1 = unit(*perp(sub(P[X], P[B])))
        (x, y) = P[X]
        if ph == "velocity":
            V = sol.V
            given = ()
            if self.path is not None:
                u, through, tl = self.path.u, (0.0, 0.0), "o"
                rel = f"parallel to the path ({self.path.label})"
                mark = "\u2225 path"
            else:
                g1 = P[self.g1]
                u = unit(*sub(P[self.g2], g1))
                through = guide_point(*g1, x, y, sol.W[self.guide], *V[self.g1])
                tl = under_label(sol, X, ph)
                rel = f"parallel to {self.guide}"
                mark = f"\u2225 {self.guide}"
                given = (
                    Vector(
                        V[self.g1],
                        through,
                        f"{lab(self.g1)}{tl}",
                        "relative",
                        f"v of the point of {self.guide} under {X}",
                        f"omega_{self.guide} x {self.g1}{X}",
                    ),
                )
            lines = (
                DirectionLine(V[B], d1, lab(B), f"perpendicular to {B}{X}", mark=f"\u22a5 {B}{X}"),
                DirectionLine(through, u, tl, rel, mark=mark),
            )
            text = (
                f"through {pole_text(sol, B, ph)} draw a line perpendicular to {B}{X}; "
                f"through {tl}, one {rel}; they meet at {lab(X)}"
            )
            found = (
                relative(sol, X, B, V, ph),
                absolute(sol, X, V, ph),
                Vector(through, V[X], f"{tl}{lab(X)}", "sliding", f"vs_{X}", "sliding velocity"),
            )
            return Construction(
                self.index, self.title, ph, lab(X), V[X], given, lines, found, text, cond
            )
        return self._acceleration_polygon(sol, ph, d1, cond)

    def _acceleration_polygon(self, sol, ph, d1, cond):
        """The construction on the acceleration polygon (``d1``: the unit perpendicular to
        BX on the configuration)."""
        P, A, X, B = sol.P, sol.A, self.point, self.b
        lab = lambda p: image_label(sol, p, ph)  # noqa: E731
        (x, y) = P[X]
        c1 = centripetal(sol, X, B, self.link, ph)
        given = [c1]
        if self.path is not None:
            u, through, tl = self.path.u, (0.0, 0.0), "o'"
            rel = f"parallel to the path ({self.path.label})"
            mark = "\u2225 path"
        else:
            g1 = P[self.g1]
            u = unit(*sub(P[self.g2], g1))
            under = guide_point_acceleration(
                *g1, x, y, sol.W[self.guide], sol.Al[self.guide], *A[self.g1]
            )
            cor = sol.coriolis(X)
            through = add(under, cor)
            tl = "the end of the Coriolis component"
            rel = f"parallel to {self.guide}"
            mark = f"\u2225 {self.guide}"
            given += [
                Vector(
                    A[self.g1],
                    under,
                    under_label(sol, X, ph),
                    "relative",
                    f"a of the point of {self.guide} under {X}",
                    "",
                ),
                Vector(
                    under,
                    through,
                    "cor",
                    "coriolis",
                    f"Coriolis at {X}",
                    f"2 omega_{self.guide} vs = {math.hypot(*cor):.4g} m/s^2",
                ),
            ]
        lines = (
            DirectionLine(
                c1.end,
                d1,
                f"the end of the centripetal of {X}{B}",
                f"perpendicular to {B}{X}",
                mark=f"\u22a5 {B}{X}",
            ),
            DirectionLine(through, u, tl, rel, mark=mark),
        )
        text = (
            f"from {pole_text(sol, B, ph)} draw the centripetal of {X}{B} ({c1.text}) and "
            f"through its end a line perpendicular to {B}{X}; through {tl}, one {rel}; "
            f"they meet at {lab(X)}"
        )
        found = (
            tangential(sol, X, B, self.link, c1.end),
            Vector(
                through,
                A[X],
                f"{tl}{lab(X)}" if self.path is not None else "s",
                "sliding",
                f"as_{X}",
                "sliding acceleration",
            ),
            relative(sol, X, B, A, ph),
            absolute(sol, X, A, ph),
        )
        return Construction(
            self.index, self.title, ph, lab(X), A[X], tuple(given), lines, found, text, cond
        )
