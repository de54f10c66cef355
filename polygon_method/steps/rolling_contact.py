"""The no-slip relations of a rolling wheel written once (its omega and alpha on a line or
on a circle, the motion of its rim's point) and what the views ask of its contact: the
contact point I, the motion of the wheel's point there, the pitch circles and ground line
drawn, the tabular method's slips (the formulas: :mod:`.rolling`).

>>> rim_motion(0.0, -0.5, -4.0, 0.0, 2.0, 0.0, 0.0, 0.0)  # the contact point: at rest
(0.0, 0.0, 0.0, 8.0)
"""

from __future__ import annotations

import math

from ..common.numbers import in_units
from .construction import sub
from .relations import rigid_acceleration, rigid_velocity
from .rolling_words import circle_words

__all__ = ["line_rates", "circle_rates", "rim_motion", "RollingContact"]


def line_rates(tx, ty, r, vx, vy, ax, ay):
    """(omega, alpha) of a wheel of radius r rolling on a fixed line along t = perp(m),
    its centre moving at v, a: ``v.t / r``, ``a.t / r``."""
    return (vx * tx + vy * ty) / r, (ax * tx + ay * ty) / r


def circle_rates(dx, dy, vdx, vdy, adx, ady, kd, kb, wb, ab):
    """(omega, alpha) of a wheel rolling on a circle: ``kd omega_d + kb omega_B``,
    ``kd alpha_d + kb alpha_B``, d = C - O the line of centres (its velocity vd and
    acceleration ad), kd = 1 + e R/r, kb = -e R/r."""
    n2 = dx * dx + dy * dy
    c = dx * vdy - dy * vdx
    wd = c / n2
    ad = (dx * ady - dy * adx) / n2 - 2.0 * c * (dx * vdx + dy * vdy) / (n2 * n2)
    return kd * wd + kb * wb, kd * ad + kb * ab


def rim_motion(rx, ry, w, al, vcx, vcy, acx, acy):
    """(vx, vy, ax, ay) of the wheel's point at C + r: ``v_C + w perp(r)``,
    ``a_C - w^2 r + al perp(r)``: the rigid body's relations (:mod:`.relations`)."""
    dvx, dvy = rigid_velocity(rx, ry, w)
    dax, day = rigid_acceleration(rx, ry, w, al)
    return vcx + dvx, vcy + dvy, acx + dax, acy + day


class RollingContact:
    """What the views ask of a rolling wheel's contact (a part of
    :class:`~polygon_method.steps.rolling.RollingWheel`, which holds the fields read here:
    ``centre``, ``base_centre``, ``on``, ``ring``, ``inside``, ``dims``, ``wheel``,
    ``base``, ``where``, ``unit``, ``uname``)."""

    def contact(self, P):
        """The contact point I (the instantaneous centre of the wheel and what it rolls on)
        and the unit normal m from I towards the centre."""
        cx, cy = P[self.centre]
        if self.on == "line":
            ell, r, tx, ty, mx, my = self.dims[:6]
            return (cx - r * mx, cy - r * my), (mx, my)
        R = self.dims[2]
        ox, oy = P[self.base_centre]
        n = math.hypot(cx - ox, cy - oy)
        ux, uy = (cx - ox) / n, (cy - oy) / n
        if self.ring:  # the gear inside the ring: I on its far side from the ring's centre
            return (ox - R * ux, oy - R * uy), (ux, uy)
        e = -1.0 if self.inside else 1.0
        return (ox + R * ux, oy + R * uy), (e * ux, e * uy)

    def contact_motion(self, sol):
        """(I, v_I, a_I): the contact point and the velocity and acceleration of the wheel's
        point there (v_I is the base's point's velocity: no slip)."""
        I, _ = self.contact(sol.P)
        rx, ry = sub(I, sol.P[self.centre])
        vx, vy, ax, ay = rim_motion(
            rx, ry, sol.W[self.wheel], sol.Al[self.wheel], *sol.V[self.centre], *sol.A[self.centre]
        )
        return I, (vx, vy), (ax, ay)

    def ratio_slips(self, sol):
        """The tabular method's classic slips for a wheel on a circle or a gear whose arm
        turns: (value of omega, code, words) for the turning relative to the arm given as
        the wheel's own (the row 'all locked' left out) and, on a gear, the ratio of fixed
        centres (the arm's motion left out)."""
        if self.on == "line":
            return ()
        (cx, cy), (ox, oy) = sol.P[self.centre], sol.P[self.base_centre]
        (vcx, vcy), (vox, voy) = sol.V[self.centre], sol.V[self.base_centre]
        dx, dy = cx - ox, cy - oy
        wd = (dx * (vcy - voy) - dy * (vcx - vox)) / (dx * dx + dy * dy)
        if wd == 0.0:
            return ()
        w = sol.W[self.wheel]
        out = [
            (
                w - wd,
                "arm_row_left_out",
                "the turning relative to the arm given as the "
                "wheel's own: the tabular method's row 'all locked' (+ the arm's turn) left "
                "out",
            )
        ]
        if self.base:
            out.append(
                (
                    self.dims[4] * sol.W[self.base],
                    "arm_taken_fixed",
                    "the gear ratio of fixed centres used: the arm's motion left out",
                )
            )
        return tuple(out)

    def shapes(self, P):
        """The wheel's pitch circle, what it rolls on (a circle, or the ground line hatched
        on the far side) and the contact point; a gear's circles also say whose they are,
        by the teeth."""
        I, (mx, my) = self.contact(P)
        own, base = circle_words(self)  # a gear's by its teeth (the page's tooltips), or ()
        out = [("circle", self.centre, self.dims[1]) + own]
        if self.on == "line":
            out.append(("ground line", I, (-my, mx), (mx, my)))
        else:
            out.append(("circle", self.base_centre, self.dims[2]) + base)
        out.append(("contact", I))
        return tuple(out)

    def contacts(self, P):
        """The contact point: the centre of the wheel and what it rolls on (no slip)."""
        I, _ = self.contact(P)
        return (
            (
                self.base or "ground",
                self.wheel,
                I,
                f"the pitch point of {self.wheel} meshing with {self.where} (no slip)"
                if self.teeth
                else f"the contact of {self.wheel} rolling on {self.where} (no slip)",
            ),
        )

    def _off_words(self, cx, cy, prm):
        """Why the wheel cannot roll at the stated instant: its centre (cx, cy) is off its
        line, or the contact leaves the pitch point (the centre distance is not the radii's)."""
        r = prm[1]
        if self.on == "line":
            tx, ty, mx, my = prm[2:6]
            d = (cx - tx) * mx + (cy - ty) * my
            return (
                f"at the stated crank angle the centre {self.centre} of wheel {self.wheel} "
                f"is {in_units(d, self.unit)} {self.uname} from {self.where}, not its radius "
                f"{in_units(r, self.unit)} {self.uname}: "
                "the wheel cannot roll on it there (check the line's through, the radius "
                "and the links that place the centre)"
            )
        dist = math.hypot(cx - prm[8], cy - prm[9])
        return (
            f"at the stated crank angle the centre {self.centre} of wheel {self.wheel} is "
            f"{in_units(dist, self.unit)} {self.uname} from {self.base_centre}: the contact "
            "leaves the pitch "
            "point (check the radii)"
        )
