"""A translating slotted yoke (the Scotch yoke): the yoke Y is a block on a fixed path
(through Q along u), and the known pin P slides in the yoke's slot, the line through Y
along the fixed direction d (the yoke does not turn: no Coriolis component).

Position: Y = Q + s u on the line through P along d: ``s = (P - Q) x d / (u x d)``.
Condition: ``|u x d|``, the sine of the angle between the path and the slot.

Velocity: the yoke translates with ``vY = vs_Y u``; the pin slides along the slot,
``vP = vY + vs_P d``: through o a line parallel to the path, through p one parallel to the
slot, meeting at y::

    vs_Y = vP x d / (u x d),   vs_P = u x vP / (u x d)

Acceleration: the same with aP (no centripetal, no Coriolis: nothing turns). With a
crank r at theta and u perpendicular to d this is the closed form x = r cos theta.

An offset slot (its centre line e to the left of the line through Y along d): Y is on the
line through ``P - e perp(d)`` along d; the yoke translates, so the velocity and the
acceleration are as above.

>>> place(0.0, 0.0, 1.0, 0.0, 0.3, 0.4, 0.0, 1.0)   # path y = 0, slot vertical through P
(0.3, 0.0, 1.0)
>>> velocity(1.0, 0.0, 0.0, 1.0, 2.0, -1.0)   # vP = 2 u - 1 d
(2.0, -1.0)
"""

from __future__ import annotations

from dataclasses import dataclass

from ..common.errors import TOL, SingularStepError
from ..common.numbers import in_units, condition_text
from ..common.tolerances import LEAST_REACH
from ..scene import YokeSlot, guide_words
from .base import Construction, DirectionLine, Step, Vector, absolute, image_label
from .rounding import EPS, line_rounding, plus, two_lines

__all__ = ["Yoke", "place", "velocity", "acceleration", "recognise"]


def place(qx, qy, ux, uy, px, py, dx, dy, ctx=None, step=None):
    """The yoke's point Y on its path Q + s u, on the slot through P along d. Returns x, y
    and the condition |u x d|."""
    cross = ux * dy - uy * dx
    c = abs(cross)
    if ctx is not None and not ctx.array and c < TOL.singular:
        raise step.singular(c)
    s = ((px - qx) * dy - (py - qy) * dx) / cross
    return qx + s * ux, qy + s * uy, c


def velocity(ux, uy, dx, dy, vx, vy):
    """(vs_Y, vs_P) with vP = vs_Y u + vs_P d."""
    cross = ux * dy - uy * dx
    return (vx * dy - vy * dx) / cross, (ux * vy - uy * vx) / cross


def acceleration(ux, uy, dx, dy, ax, ay):
    """(as_Y, as_P) with aP = as_Y u + as_P d: the same 2x2 solve (nothing turns)."""
    return velocity(ux, uy, dx, dy, ax, ay)


def recognise(g, name):
    """The yoke ``name`` (a block on a fixed path) whose slot holds a known pin."""
    sc = g.scene
    path = g.slider(name)
    if path is None or name in g.used_sliders or not hasattr(path, "through"):
        return None
    pin = next((s for s in sc.sliders if isinstance(s, YokeSlot) and s.yoke == name), None)
    if pin is None or pin.point not in g.P or pin.point in g.used_sliders:
        return None
    g.used_sliders.update((name, pin.point))
    return Yoke(
        g.next_index,
        name,
        pin.point,
        path,
        pin,
        sc.link(sc.input.crank).length,
        unit=g.unit,
        uname=g.uname,
    )


@dataclass(frozen=True)
class Yoke(Step):
    """The yoke ``point`` on its fixed ``path``, placed by the pin ``pin`` in its slot
    (``slot``: the scene's :class:`YokeSlot`)."""

    point: str
    pin: str
    path: object
    slot: object
    size: float = 1.0  # the crank's length: a scale
    unit: float = 1e-3
    uname: str = "mm"

    kind = "yoke"
    branching = False

    @property
    def finds(self):
        return (self.point,)

    @property
    def links(self):
        return ()

    @property
    def needs(self):
        return (self.pin,)

    @property
    def needs_links(self):
        return ()

    @property
    def title(self):
        return (
            f"yoke {self.point} on the {guide_words(self.path.label)}, pin {self.pin} in its slot"
        )

    @property
    def params(self):
        (qx, qy), (ux, uy), (dx, dy) = self.path.through, self.path.u, self.slot.direction
        return (qx, qy, ux, uy, dx, dy, self.slot.offset)

    def dimensions(self, scene, bodies):
        path, slot = scene.slider(self.point), scene.slider(self.pin)
        (qx, qy), (ux, uy), (dx, dy) = path.through, path.u, slot.direction
        return (qx, qy, ux, uy, dx, dy, slot.offset)

    def drawn(self, prm, pencil, P):
        """The path's point as a hand drawing places it (the directions are given), and an
        offset slot's line."""
        e = prm[6] + pencil() if prm[6] else prm[6]
        return (prm[0] + pencil(), prm[1] + pencil()) + tuple(prm[2:6]) + (e,)

    def reach(self):
        return max(self.size, LEAST_REACH)

    def place(self, P, prm, ctx, sigma=None):
        qx, qy, ux, uy, dx, dy, e = prm
        px, py = P[self.pin]
        return place(qx, qy, ux, uy, px + e * dy, py - e * dx, dx, dy, ctx, self)

    def default_hint(self, P):
        return "above"  # one position only: never asked

    def bind(self, prm):
        """The step's three phases for dimensions ``prm``: functions of a State."""
        Y, X, i, step = self.point, self.pin, self.index, self
        qx, qy, ux, uy, dx, dy, e = prm

        def position(m):  # (an offset slot: the line through P - e perp(d))
            px, py = m.P[X]
            x, y, c = place(qx, qy, ux, uy, px + e * dy, py - e * dx, dx, dy, m.ctx, step)
            m.P[Y] = (x, y)
            m.cond[i] = c

        def velocity_(m):
            vy, vp = velocity(ux, uy, dx, dy, *m.V[X])
            m.S[Y] = [vy, None, 0.0, 0.0]
            m.S[X] = [vp, None, 0.0, 0.0]
            m.V[Y] = (vy * ux, vy * uy)

        def acceleration_(m):
            ay, ap = acceleration(ux, uy, dx, dy, *m.A[X])
            m.S[Y][1] = ay
            m.S[X][1] = ap
            m.A[Y] = (ay * ux, ay * uy)

        return position, velocity_, acceleration_

    def bind_instant(self, prm):
        """The three phases in a row (the position raises where the slot runs along the
        path)."""
        position, velocity_, acceleration_ = self.bind(prm)

        def instant(m):
            position(m)
            velocity_(m)
            acceleration_(m)

        return instant

    rounding = 48.0

    def error_bound(self, walk, k, p_in, v_in, a_in):
        """Two direction lines (the path, the slot) at the condition |u x d|, the path's
        own numbers in the rounding (:func:`.rounding.line_rounding`, and the slot's
        angle's); the yoke's and the pin's sliding quantities err as the yoke's velocity
        and acceleration."""
        (qx, qy), (x, y) = self.path.through, walk.P[self.point]
        extra = (
            line_rounding(
                self.rounding,
                qx,
                qy,
                x,
                y,
                walk.sizes["position"],
                getattr(self.path, "angle", None),
            )
            + 4 * EPS
        )
        p, v, a, w, al = two_lines(
            walk.condition(self),
            walk.ratio,
            plus(walk.own(self, k), extra),
            p_in,
            v_in,
            a_in,
            walk.couple(self),
        )
        walk.slide[self.point] = walk.slide[self.pin] = (v, a, a)
        return p, v, a, w, al

    # ----- failures and words
    def why(self, *_):
        """Why the yoke cannot be placed: its slot runs along its path."""
        return f"a pin in two parallel slots: the slot of yoke {self.point} runs along its path"

    def singular(self, c):
        """The error for a slot parallel to the yoke's path at condition ``c``."""
        return SingularStepError(self.singular_why(c), step=self.label)

    def singular_why(self, c) -> str:
        return (
            f"a pin in two parallel slots: the slot of yoke {self.point} is parallel to "
            f"its {guide_words(self.path.label)} (sine {condition_text(c)}): nothing moves "
            "the yoke"
        )

    def warning(self, c) -> str:
        return (
            f"{self.label}: the slot of yoke {self.point} is nearly parallel to its path "
            f"(condition {c:.3g})"
        )

    def limit_why(self) -> str:
        return f"the slot of yoke {self.point} turns parallel to its path"

    def transmission(self):
        return None

    def condition_column(self):
        return (
            f"cond step {self.index + 1}",
            "1",
            f"sine of the angle between the slot of {self.point} and its path",
        )

    def bodies(self):
        return (f"block {self.pin}", f"block {self.point}")

    def orient(self):
        return {}

    def output(self, ground):
        return ("slider", self.point)

    def position_words(self, L, which, angle_deg):
        (qx, qy) = self.path.through
        u, n = self.unit, self.uname
        e = self.slot.offset
        line = (
            f"the line through {self.pin} along the yoke's slot ({self.slot.label})"
            if not e
            else f"the line along the yoke's slot ({self.slot.label}) {L(abs(e))} to the "
            f"{'right' if e > 0 else 'left'} of {self.pin} (the yoke's line through "
            f"{self.point}: the slot's centre line, through {self.pin}, is "
            f"to its {'left' if e > 0 else 'right'})"
        )
        return (
            f"{self.point}: {line} cuts the {guide_words(self.path.label)} through "
            f"({in_units(qx, u)}, {in_units(qy, u)}) {n} at {self.point}"
        )

    # ----- the polygons
    def construction(self, sol, ph):
        Y, X = self.point, self.pin
        cond = sol.conditions.get(self.index, 1.0)
        D = sol.V if ph == "velocity" else sol.A
        sym = "vs" if ph == "velocity" else "as"
        lab, lx = image_label(sol, Y, ph), image_label(sol, X, ph)
        o = "o" if ph == "velocity" else "o'"
        lines = (
            DirectionLine(
                (0.0, 0.0),
                self.path.u,
                o,
                f"parallel to the {guide_words(self.path.label)}",
                mark=f"\u2225 the {guide_words(self.path.label)}",
            ),
            DirectionLine(
                D[X],
                self.slot.direction,
                lx,
                f"parallel to the slot ({self.slot.label})",
                mark=f"\u2225 the slot ({self.slot.label})",
            ),
        )
        what = "velocity" if ph == "velocity" else "acceleration"
        text = (
            f"the yoke translates: through {o} draw a line parallel to its "
            f"{guide_words(self.path.label)}; through {lx}, one parallel to its slot "
            f"({self.slot.label}), the pin's sliding {what}; they meet at {lab} (no "
            "Coriolis component: the slot does not turn)"
        )
        found = (
            absolute(sol, Y, D, ph),
            Vector(
                D[Y],
                D[X],
                f"{lab}{lx}",
                "sliding",
                f"{sym}_{X}",
                f"sliding {what} of {X} in the slot of {Y}",
            ),
        )
        return Construction(self.index, self.title, ph, lab, D[Y], (), lines, found, text, cond)
