"""The driving wheel: a wheel rolling without slip on a fixed ground line is the only
driver ("the wheel rolls at 4 rad/s cw, 2 rad/s^2 ccw"); no link turns about the frame.

Its state is its centre C's place s along the centre's path (the line parallel to the
ground at the wheel's radius r, unit direction u): the plan's input ``theta``. No slip at
the contact I (``I - C = -r m``, m the unit normal from the ground to the centre, t =
perp(m) along the ground)::

    v_C = omega x (C - I) = omega r t           (I is the instantaneous centre)
    a_C = alpha r t                              (the centre moves on a straight line)
    a_I = a_C + alpha x (I - C) - omega^2 (I - C) = omega^2 r m   (towards the centre)

Along u (t . u = +-1): ``vs = omega r (t . u)``, ``as = alpha r (t . u)`` (the plan's
``omega`` and ``alpha``). The wheel's point P (and every point pinned to the rim) is then
placed by the rolling step from the centre's motion.

>>> centre_rates(-4.0, 2.0, 0.3, -1.0)   # 4 rad/s cw on the ground (t = -u): to the right
(1.2, -0.6)
>>> contact_acceleration(-4.0, 0.3)          # omega^2 r, towards the centre
4.8
"""

from __future__ import annotations

from dataclasses import dataclass

from ..common.numbers import in_units, sense as turn_sense
from .block import BlockDriver, at_rest_rate
from .base import Construction, absolute, image_label

__all__ = ["WheelDriver", "centre_rates", "contact_acceleration"]


def centre_rates(omega, alpha, r, along):
    """(vs, as) of the centre along its path's u: ``omega r (t . u)``, ``alpha r (t . u)``
    (a wheel rolling on a fixed line, t = perp(m), m the unit normal from the line to the
    centre; ``along`` = t . u, +1 or -1)."""
    return omega * r * along, alpha * r * along


def contact_acceleration(omega, r):
    """|a_I| = omega^2 r: the contact point's acceleration, towards the centre."""
    return omega * omega * r


@dataclass(frozen=True)
class WheelDriver(BlockDriver):
    """The centre C of the driving wheel ``wheel`` (radius ``radius``, m) on its path (see
    the module): ``C = Q + s u``, ``v_C = vs u``, ``a_C = as u``. The plan's first step
    where a wheel drives (``[input] wheel``)."""

    wheel: str = ""
    radius: float = 0.0
    ground_words: str = ""  # the ground line in words ("the horizontal line")
    along: float = 1.0  # t . u: +1 where the wheel's t runs along the path's u

    kind = "rolling driver"

    @property
    def title(self):
        return f"wheel {self.wheel} rolling on {self.ground_words}: its centre {self.point}"

    def omega_alpha(self, vs, a_s):
        """The wheel's (omega, alpha) from its centre's (vs, as) along u."""
        k = self.along / self.radius
        return vs * k, a_s * k

    # ----- the driver protocol
    def body_omega(self, sol):
        """The wheel's omega: it turns about its contact point with the ground."""
        return self.omega_alpha(sol.S[self.point][0], 0.0)[0]

    travel = "the wheel's travel"

    def parameter(self, scene) -> tuple:
        """(name, symbol, unit): the wheel's centre's place along its line."""
        return (
            f"place of centre {self.point} of wheel {self.wheel}",
            f"s_{self.point}",
            f" {scene.units}",
        )

    def input_record(self, scene):
        """The JSON ``input``: the block's record of the centre (its place, vs, as, its
        line's direction) with the wheel, its omega, alpha and radius."""
        d = super().input_record(scene)
        w, al = self.omega_alpha(scene.input.omega, scene.input.alpha)
        d.update(wheel=self.wheel, omega=w, alpha=al, radius=self.radius)
        return d

    def drive_caption(self, scene):
        """The line under the drawings: the wheel's omega (and alpha), its centre's place."""
        inp = scene.input
        w, al = self.omega_alpha(inp.omega, inp.alpha)
        return (
            f"wheel {self.wheel} rolling at {abs(w):.4g} rad/s {turn_sense(w)}"
            + (f", {abs(al):.4g} rad/s² {turn_sense(al)}" if al else "")
            + f", centre {self.point} at s = {in_units(inp.angle, scene.length_unit)} "
            f"{scene.units}"
        )

    def input_scales(self, scene):
        """(v, a, omega, alpha): |omega| r, omega^2 r + |alpha| r, |omega|, omega^2 +
        |alpha| (the wheel's own sizes: the contact's acceleration is omega^2 r)."""
        vs, a_s = abs(scene.input.omega), abs(scene.input.alpha)
        r = self.radius
        w, al = vs / r, a_s / r
        return vs, w * w * r + a_s, w, w * w + al

    def input_words(self, scene):
        """The printed solution's line for the input: the wheel's omega and alpha, its
        centre's place and velocity by the no-slip relation."""
        inp, u = scene.input, scene.length_unit
        w, al = self.omega_alpha(inp.omega, inp.alpha)
        r, C = self.radius, self.point
        if scene.at_rest:  # nothing moves: the senses it is about to turn and move in
            return (
                f"wheel {self.wheel} (radius {in_units(r, u)} {scene.units}) on "
                f"{self.ground_words} (no slip), about to turn {turn_sense(w)}: its "
                f"centre {C} at s_{C} = {in_units(inp.angle, u)} {scene.units}, about to move "
                f"{self.sense(inp.omega)}; its contact point I the instantaneous centre"
            )
        words = (
            f"wheel {self.wheel} (radius {in_units(r, u)} {scene.units}) rolls without "
            f"slip on {self.ground_words} at omega = {abs(w):.6g} rad/s {turn_sense(w)}"
            + (f", alpha = {abs(al):.6g} rad/s^2 {turn_sense(al)}" if al else ", steadily")
            + f": its centre {C} at s_{C} = {in_units(inp.angle, u)} {scene.units} moves "
            f"at omega r = {abs(inp.omega):.6g} m/s {self.sense(inp.omega)}"
        )
        if inp.alpha:
            words += (
                f", accelerating at alpha r = {abs(inp.alpha):.6g} m/s^2 {self.sense(inp.alpha)}"
            )
        return (
            words + f"; its contact point I is the instantaneous centre (v_I = 0, a_I = "
            f"omega^2 r = {contact_acceleration(w, r):.6g} m/s^2 towards {C})"
        )

    def input_items(self, scene, fmt):
        """The step table's input: the wheel's omega and alpha (given), then its centre's
        velocity and acceleration by the no-slip relation, and the contact point's."""
        inp, C, r = scene.input, self.point, self.radius
        w, al = self.omega_alpha(inp.omega, inp.alpha)
        W = self.wheel
        on_centre = inp.wheel_given  # the centre's velocity (acceleration) given instead
        items = [
            (
                f"v_{C} = {fmt(abs(inp.omega))} m/s {self.sense(inp.omega)} (given); the "
                f"wheel rolls without slip on {self.ground_words}, radius r = {fmt(r)} m, so "
                f"omega_{W} = v_{C} / r = {fmt(abs(w))} rad/s {turn_sense(w)}"
            )
            if f"vs_{C}" in on_centre
            else f"omega_{W} = {fmt(abs(w))} rad/s {turn_sense(w)} (given); the wheel rolls "
            f"without slip on {self.ground_words}, radius r = {fmt(r)} m",
            (
                f"a_{C} = {fmt(abs(inp.alpha))} m/s^2 {self.sense(inp.alpha)} (given), so "
                f"alpha_{W} = a_{C} / r = {fmt(abs(al))} rad/s^2 {turn_sense(al)}"
            )
            if f"as_{C}" in on_centre and al
            else f"alpha_{W} = {fmt(abs(al))} rad/s^2 {turn_sense(al)} (given)"
            if al
            else f"alpha_{W} = 0 {at_rest_rate(scene, '1 rad/s', f'alpha_{W}')}"
            if scene.at_rest
            else f"alpha_{W} = 0 (the wheel rolls at a steady speed)",
            f"the wheel rolls: its centre moves at omega r = {fmt(abs(w))} x {fmt(r)} = "
            f"{fmt(abs(inp.omega))} m/s along the ground, {self.sense(inp.omega)}; its "
            "contact point I is the instantaneous centre (v_I = 0)",
            (
                f"a_{C} = alpha r = {fmt(abs(al))} x {fmt(r)} = {fmt(abs(inp.alpha))} m/s^2 "
                f"{self.sense(inp.alpha)}"
                if al
                else f"a_{C} = 0 (alpha = 0)"
            )
            + "; the contact point's acceleration is not zero: a_I = omega^2 r = "
            f"{fmt(contact_acceleration(w, r))} m/s^2 towards {C}",
        ]
        return f"Input wheel {W}", items

    def effort_words(self, effort):
        """The driving force at the wheel's centre along the ground (power balance)."""
        return (
            f"input force at the centre {self.point} of wheel {self.wheel}: {abs(effort):.4g} "
            f"N {self.sense(effort)} along the ground, i.e. a torque of "
            f"{abs(effort) * self.radius:.4g} N m about the contact point (power balance, no "
            "friction or inertia)"
        )

    def parameter_words(self):
        return (
            f"the place s_{self.point} of the centre {self.point} of the rolling wheel "
            f"{self.wheel} along its line"
        )

    virtual_unit = "1 rad/s of the wheel"

    @property
    def driver_name(self):
        """Body 2 of the centres' numbering: the wheel (its centre's path is no block)."""
        return f"the driving wheel {self.wheel}"

    def singular_why(self, c) -> str:
        return f"the rolling wheel {self.wheel} is never singular (condition {c:.2g})"

    def limit_why(self) -> str:
        return (
            f"the wheel {self.wheel} has rolled to the end of its travel (one turn of the "
            "wheel from the stated place, unless [input] travel states the stretch: "
            "several turns, if the problem asks)"
        )

    def bodies(self):
        return (self.wheel,)

    def position_words(self, L, which, place):
        return (
            f"{self.point}: the centre of wheel {self.wheel} (radius {L(self.radius)}), "
            f"rolling on {self.ground_words}, at s_{self.point} = {place} along it"
        )

    def construction(self, sol, ph):
        C, W = self.point, self.wheel
        cond = sol.conditions.get(self.index, 1.0)
        lab = image_label(sol, C, ph)
        o = "o" if ph == "velocity" else "o'"
        vs, a_s = sol.S[C][0], sol.S[C][1]
        w, al = self.omega_alpha(vs, a_s)
        r = self.radius
        if ph == "velocity":
            v = absolute(sol, C, sol.V, ph)
            text = (
                f"the wheel {W} rolls: its contact point I is the instantaneous centre "
                f"(v_I = 0, i at {o}); its centre moves at omega r = {abs(w):.4g} x "
                f"{r:.4g} = {abs(vs):.4g} m/s along the ground: from {o} draw {o}{lab} = "
                f"{abs(vs):.4g} m/s {self.sense(vs)}"
            )
            return Construction(self.index, self.title, ph, lab, sol.V[C], (), (), (v,), text, cond)
        a = absolute(sol, C, sol.A, ph)
        aI = contact_acceleration(w, r)
        if a_s:
            text = (
                f"the centre {C} moves on a straight line: a_{C} = alpha r = {abs(al):.4g} "
                f"x {r:.4g} = {abs(a_s):.4g} m/s^2 {self.sense(a_s)}: from {o} draw "
                f"{o}{lab}; the contact point's acceleration is not zero: omega^2 r = "
                f"{aI:.4g} m/s^2 towards {C}"
            )
            found = (a,)
        else:
            text = (
                f"{lab} is at {o}: "
                + (
                    f"alpha = 0 {at_rest_rate(sol.scene, '1 rad/s', f'alpha_{self.wheel}')}"
                    if sol.scene.at_rest
                    else f"the centre {C} moves steadily on a straight line (alpha = 0)"
                )
                + "; the contact point's acceleration is not zero: omega^2 r = "
                f"{aI:.4g} m/s^2 towards {C}"
            )
            found = ()
        return Construction(self.index, self.title, ph, lab, sol.A[C], (), (), found, text, cond)
