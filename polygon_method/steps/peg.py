"""A peg in two slots: point P sits in the slots of two known bodies (a slotted link, or a
fixed slot) and goes where the two slots cross (a peg in a fixed slot driven by a slotted
lever, a peg in two slotted links).

Slot i is the line ``G_i + s u_i`` of its body: a fixed path (``G`` its point, ``u`` its
direction) or a moving link's centre line (``G`` its first point, ``u`` towards its second).
Position: ``s_1 = (G_2 - G_1) x u_2 / (u_1 x u_2)``, ``P = G_1 + s_1 u_1``. Condition:
``|u_1 x u_2|``, the sine of the angle between the slots (two parallel slots: no crossing).

Velocity: the point C_i of body i under the peg moves with ``vC_i = vG_i + w_i perp(P -
G_i)`` (zero for a fixed slot); the peg slides along each slot, ``vP = vC_i + vs_i u_i``:
through the image c_i of each a line parallel to slot i, meeting at p::

    vs_1 u_1 - vs_2 u_2 = vC_2 - vC_1 = e,   vs_1 = e x u_2 / (u_1 x u_2),
    vs_2 = e x u_1 / (u_1 x u_2)

Acceleration: ``aP = aC_i + 2 w_i vs_i perp(u_i) + as_i u_i`` (the Coriolis component of
each moving slot, laid off from c_i' first), with ``aC_i = aG_i - w_i^2 (P - G_i) + al_i
perp(P - G_i)``: the same 2x2 solve with ``e = (aC_2 + cor_2) - (aC_1 + cor_1)``.

>>> x, y, c = place(0.0, 0.0, 1.0, 0.0, 2.0, -1.0, 0.0, 1.0)   # y = 0 and x = 2
>>> x, y, c
(2.0, 0.0, 1.0)
>>> velocity(1.0, 0.0, 0.0, 1.0, 0.5, -0.25, 1.0)   # e = vs_1 u_1 - vs_2 u_2
(0.5, 0.25)
"""

from __future__ import annotations

from ..common.numbers import condition_text

from dataclasses import dataclass

from . import peg_polygons
from .peg_polygons import slot_labels, slot_words as _slot_words, under_labels
from .relations import coriolis, rigid_acceleration, rigid_velocity
from ..common.errors import TOL, SingularStepError
from ..common.tolerances import LEAST_REACH
from ..scene import FixedPath, GuideSlider
from .base import Step
from .rounding import C_FLOOR, line_rounding, plus, two_lines, vhypot, vmax

__all__ = [
    "Peg",
    "place",
    "slot_line",
    "velocity",
    "acceleration",
    "under_velocity",
    "under_acceleration",
    "under_point",
    "recognise",
    "under_labels",
    "slot_labels",
]


def place(g1x, g1y, u1x, u1y, g2x, g2y, u2x, u2y, ctx=None, step=None):
    """Where the slots G_1 + s u_1 and G_2 + t u_2 cross. Returns x, y and the condition
    |u_1 x u_2|."""
    cross = u1x * u2y - u1y * u2x
    c = abs(cross)
    if ctx is not None:
        if ctx.array:
            near = c < TOL.singular
            if near is True or (near is not False and near.any()):
                ctx.fail(step, near)
                cross = ctx.np.where(near, 1.0, cross)
        elif c < TOL.singular:
            raise step.singular(c)
    wx, wy = g2x - g1x, g2y - g1y
    s1 = (wx * u2y - wy * u2x) / cross
    return g1x + s1 * u1x, g1y + s1 * u1y, c


def velocity(u1x, u1y, u2x, u2y, ex, ey, cross):
    """(vs_1, vs_2) with e = vC_2 - vC_1 = vs_1 u_1 - vs_2 u_2 and cross = u_1 x u_2."""
    return (ex * u2y - ey * u2x) / cross, (ex * u1y - ey * u1x) / cross


def acceleration(u1x, u1y, u2x, u2y, ex, ey, cross):
    """(as_1, as_2) with e = (aC_2 + cor_2) - (aC_1 + cor_1): the same 2x2 solve."""
    return velocity(u1x, u1y, u2x, u2y, ex, ey, cross)


def slot_line(gx, gy, hx, hy, e=0.0):
    """A moving slot's line (point, unit direction) in link G -> H: its centre line, or e to
    the left of it (an offset slot: the point G + e perp(u))."""
    ux, uy = hx - gx, hy - gy
    n = (ux * ux + uy * uy) ** 0.5
    ux, uy = ux / n, uy / n
    return gx - e * uy, gy + e * ux, ux, uy


def under_velocity(gx, gy, x, y, w, vgx, vgy):
    """The velocity of the slotted body's point under the peg at (x, y): vG + w perp(P - G)."""
    rx, ry = rigid_velocity(x - gx, y - gy, w)
    return vgx + rx, vgy + ry


def under_acceleration(gx, gy, x, y, w, al, agx, agy):
    """Its acceleration: aG - w^2 (P - G) + al perp(P - G)."""
    rx, ry = rigid_acceleration(x - gx, y - gy, w, al)
    return agx + rx, agy + ry


def under_point(gx, gy, x, y, w, al, vgx, vgy, agx, agy):
    """Both: the velocity and the acceleration of the point under the peg."""
    return (
        under_velocity(gx, gy, x, y, w, vgx, vgy),
        under_acceleration(gx, gy, x, y, w, al, agx, agy),
    )


def recognise(g, name):
    """A peg in two slots whose bodies are both known: fixed, or a link whose two ends and
    omega are found."""
    sc = g.scene
    slots = g.slots(name)
    if len(slots) != 2 or any(s.key in g.used_sliders for s in slots):
        return None
    sizes = []
    for s in slots:
        if isinstance(s, GuideSlider):
            guide = sc.link(s.guide)
            if not (g.known_link(guide) and guide.key in g.used_links):
                return None
            sizes.append(guide.length)
    g.used_sliders.update(s.key for s in slots)
    size = max(sizes) if sizes else sc.link(sc.input.crank).length
    return Peg(g.next_index, name, slots[0], slots[1], size, unit=g.unit, uname=g.uname)


@dataclass(frozen=True)
class Peg(Step):
    """A peg at ``point`` in two slots (``first``, ``second``: the scene's slider records of
    its two slots, each a :class:`FixedPath` or a :class:`GuideSlider`)."""

    point: str
    first: object
    second: object
    #: the longest slotted link (the crank's length where none): a scale
    size: float = 1.0
    unit: float = 1e-3
    uname: str = "mm"

    kind = "peg"
    branching = False

    @property
    def finds(self):
        return (self.point,)

    @property
    def links(self):
        return ()

    @property
    def slots(self):
        """The peg's two slots, first and second."""
        return (self.first, self.second)

    @property
    def needs(self):
        return tuple(
            p for s in self.slots if isinstance(s, GuideSlider) for p in (s.first, s.second)
        )

    @property
    def needs_links(self):
        return tuple(s.guide for s in self.slots if isinstance(s, GuideSlider))

    @property
    def title(self):
        return f"peg {self.point} in {_slot_words(self.first)} and {_slot_words(self.second)}"

    def _words(self, s) -> str:
        """Slot ``s`` in words, an offset slot with its line."""
        return _slot_words(s, self.unit, self.uname)

    @property
    def params(self):
        return self._fixed(self.first) + self._fixed(self.second)

    @staticmethod
    def _fixed(s):
        """A fixed slot's point and direction; a moving one's offset (its line this far to
        the left of its link's, first -> second), then zeros (its line read from P)."""
        if isinstance(s, FixedPath):
            (qx, qy), (ux, uy) = s.through, s.u
            return (qx, qy, ux, uy)
        return (s.offset, 0.0, 0.0, 0.0)

    def dimensions(self, scene, bodies):
        return self._fixed(scene.slider(self.first.key)) + self._fixed(
            scene.slider(self.second.key)
        )

    def drawn(self, prm, pencil, P):
        """A fixed slot's point as a hand drawing places it (its direction is given); an
        offset slot's line set off with the pencil too."""
        out = list(prm)
        for j, s in ((0, self.first), (4, self.second)):
            if isinstance(s, FixedPath):
                out[j] += pencil()
                out[j + 1] += pencil()
            elif s.offset:
                out[j] += pencil()
        return tuple(out)

    def reach(self):
        return max(self.size, LEAST_REACH)

    def lines(self, P, prm=None):
        """(gx, gy, ux, uy) of each slot: fixed from ``prm``, moving from the positions (an
        offset slot's point its offset to the left of the link's first point)."""
        prm = self.params if prm is None else prm
        out = []
        for j, s in ((0, self.first), (4, self.second)):
            if isinstance(s, FixedPath):
                out.append(prm[j : j + 4])
            else:
                out.append(slot_line(*P[s.first], *P[s.second], prm[j]))
        return out

    def place(self, P, prm, ctx, sigma=None):
        a, b = self.lines(P, prm)
        return place(*a, *b, ctx, self)

    def default_hint(self, P):
        return "above"  # one position only: never asked

    def bind(self, prm):
        """The step's three phases for dimensions ``prm``: functions of a State."""
        X, i, step = self.point, self.index, self
        spec = []
        for j, s in ((0, self.first), (4, self.second)):
            if isinstance(s, FixedPath):
                spec.append((True, s.key, None, None, None, prm[j : j + 4]))
            else:
                spec.append((False, s.key, s.guide, s.first, s.second, prm[j]))
        (f1, k1, L1, a1, b1, q1), (f2, k2, L2, a2, b2, q2) = spec

        def line(P, fixed, g1, g2, q):
            return q if fixed else slot_line(*P[g1], *P[g2], q)

        def frames(P):
            return line(P, f1, a1, b1, q1), line(P, f2, a2, b2, q2)

        def position(m):
            P = m.P
            s1, s2 = frames(P)
            x, y, c = place(*s1, *s2, m.ctx, step)
            P[X] = (x, y)
            m.cond[i] = c

        def under_v(m, fixed, guide, g, x, y):
            if fixed:
                return 0.0, 0.0
            return under_velocity(*m.P[g], x, y, m.W[guide], *m.V[g])

        def under_a(m, fixed, guide, g, x, y):
            if fixed:
                return (0.0, 0.0), 0.0
            w = m.W[guide]
            return under_acceleration(*m.P[g], x, y, w, m.Al[guide], *m.A[g]), w

        def cross_of(m, s1, s2):
            cr = s1[2] * s2[3] - s1[3] * s2[2]
            return m.ctx.safe(cr, step) if m.array else cr

        def velocity_(m):
            P = m.P
            x, y = P[X]
            s1, s2 = frames(P)
            c1, c2 = under_v(m, f1, L1, a1, x, y), under_v(m, f2, L2, a2, x, y)
            vs1, vs2 = velocity(
                s1[2], s1[3], s2[2], s2[3], c2[0] - c1[0], c2[1] - c1[1], cross_of(m, s1, s2)
            )
            m.S[k1] = [vs1, None, 0.0, 0.0]
            m.S[k2] = [vs2, None, 0.0, 0.0]
            m.V[X] = (c1[0] + vs1 * s1[2], c1[1] + vs1 * s1[3])

        def acceleration_(m):
            P = m.P
            x, y = P[X]
            s1, s2 = frames(P)
            (d1, w1), (d2, w2) = under_a(m, f1, L1, a1, x, y), under_a(m, f2, L2, a2, x, y)
            t1, t2 = m.S[k1], m.S[k2]
            cx1, cy1 = coriolis(w1, t1[0], s1[2], s1[3])
            cx2, cy2 = coriolis(w2, t2[0], s2[2], s2[3])
            e1x, e1y = d1[0] + cx1, d1[1] + cy1
            as1, as2 = acceleration(
                s1[2],
                s1[3],
                s2[2],
                s2[3],
                d2[0] + cx2 - e1x,
                d2[1] + cy2 - e1y,
                cross_of(m, s1, s2),
            )
            t1[1], t1[2], t1[3] = as1, cx1, cy1
            t2[1], t2[2], t2[3] = as2, cx2, cy2
            m.A[X] = (e1x + as1 * s1[2], e1y + as1 * s1[3])

        return position, velocity_, acceleration_

    def bind_instant(self, prm):
        """The three phases in a row (the position raises where the slots are parallel)."""
        position, velocity_, acceleration_ = self.bind(prm)

        def instant(m):
            position(m)
            velocity_(m)
            acceleration_(m)

        return instant

    rounding = 48.0

    def error_bound(self, walk, k, p_in, v_in, a_in):
        """Two direction lines (the slots) at the condition |u_1 x u_2|; a moving slot's
        direction is its link's, so its points' error turns it by that over the link's
        length, which moves the crossing by as much times the peg's distance from the
        slot's point. The sliding quantities err as the peg's velocity and acceleration."""
        P = walk.P
        Ls = walk.sizes["position"]
        x, y = P[self.point]
        k0 = k
        for s in self.slots:  # a fixed slot's own numbers
            if hasattr(s, "through"):
                k = k + line_rounding(
                    self.rounding, s.through[0], s.through[1], x, y, Ls, getattr(s, "angle", None)
                )
        lever = 1.0
        for s in self.slots:
            if isinstance(s, GuideSlider):
                (gx, gy), (hx, hy) = P[s.first], P[s.second]
                x, y = P[self.point]
                far = vhypot(x - gx, y - gy) / vmax(vhypot(hx - gx, hy - gy), C_FLOOR * Ls)
                lever = vmax(lever, 1.0 + far)
        p, v, a, w, al = two_lines(
            walk.condition(self),
            walk.ratio,
            plus(walk.own(self, k0), k - k0),
            p_in * lever,
            v_in * lever,
            a_in * lever,
            walk.couple(self),
        )
        for s in self.slots:
            walk.slide[s.key] = (v, a, a)
        return p, v, a, w, al

    # ----- failures and words
    def why(self, *_):
        """Why the peg cannot be placed: its two slots do not cross."""
        return (
            f"a pin in two parallel slots: {self._words(self.first)} and "
            f"{self._words(self.second)} do not cross"
        )

    def singular(self, c):
        """The error for slots that are parallel at condition ``c``."""
        return SingularStepError(self.singular_why(c), step=self.label)

    def singular_why(self, c) -> str:
        return (
            f"a pin in two parallel slots: {self._words(self.first)} and "
            f"{self._words(self.second)} are parallel (sine {condition_text(c)}): they do "
            f"not cross at one point, and {self.point} is undetermined"
        )

    def warning(self, c) -> str:
        return (
            f"{self.label}: {self._words(self.first)} and {self._words(self.second)} "
            f"are nearly parallel (condition {c:.3g}): the peg {self.point} is "
            "ill-determined"
        )

    def limit_why(self) -> str:
        return (
            f"{self._words(self.first)} and {self._words(self.second)} turn parallel: "
            f"the peg {self.point} runs off along them"
        )

    def transmission(self):
        return None

    def condition_column(self):
        return (
            f"cond step {self.index + 1}",
            "1",
            f"sine of the angle between the two slots of {self.point}",
        )

    def bodies(self):
        return tuple(f"block {s.key}" for s in self.slots)

    def orient(self):
        return {}

    def output(self, ground):
        return None

    def position_words(self, L, which, angle_deg):
        def drawn(s):  # an offset slot: its line drawn parallel to the link's, so far off
            if isinstance(s, FixedPath) or not s.offset:
                return _slot_words(s)
            side = "left" if s.offset > 0 else "right"
            return (
                f"the slot of {s.guide} (drawn parallel to {s.guide}, {L(abs(s.offset))} to "
                f"the {side} of its line {s.first} -> {s.second})"
            )

        return f"{self.point}: {drawn(self.first)} and {drawn(self.second)} cross at {self.point}"

    # ----- the polygons
    def construction(self, sol, ph):
        return peg_polygons.construction(self, sol, ph)
