"""Rolling without slip: a wheel or gear on a fixed line, on a fixed circle, or meshing
with a gear.

No slip: the wheel's point at the contact I has the velocity of the base's point there.
On a fixed line (unit normal m from the line to the centre C, t = perp(m) along it) that
velocity is zero, so ``v_C + omega perp(I - C) = 0`` with ``I - C = -r m``::

    omega = v_C . t / r,   alpha = a_C . t / r,   phi = phi0 + ((C - T) . t - s0) / r

(T a point of the line, s0 the centre's place at the stated crank angle). The contact point's
acceleration is not zero: ``a_I = omega^2 r m``, towards the centre.

On a circle of radius R about O, or on a gear of pitch radius R turning about O (omega_B),
with d = C - O turning at omega_d, ``e = +1`` outside and ``-1`` inside the circle::

    (omega - omega_d) r = -e (omega_B - omega_d) R
    omega = (1 + e R/r) omega_d - e (R/r) omega_B      (the same for alpha, with alpha_d)

(A ring about C meshing with a gear inside it, ``|d| = r - R``, the pitch point beyond
the gear, ``I = O - R d/|d|``: its no-slip relation is the internal pair's, e = -1.)
Here ``omega_d = d x v_d / |d|^2`` and ``alpha_d = d x a_d / |d|^2 - 2 (d x v_d)(d . v_d) /
|d|^4``. The wheel's angle follows the crank's (its centre is fixed or is the crank's tip, and
the base turns at a fixed ratio of the crank): ``phi = phi0 + K (theta - theta0)``. A gear
pair with both centres fixed: ``omega_2 = -e (r1 / r2) omega_1``; a planet on a fixed sun,
its arm the crank: ``omega_p = (1 + r_s / r_p) omega_arm`` (the same sense as the arm).

The point P of the wheel (its link CP, |CP| = l) is then ``C + l (cos phi, sin phi)``, and
``v_P = v_C + omega perp(P - C)``, ``a_P = a_C - omega^2 (P - C) + alpha perp(P - C)``.

>>> line_rates(-1.0, 0.0, 0.5, 2.0, 0.0, 4.0, 0.0)   # rolling to the right: clockwise
(-4.0, -8.0)
>>> circle_rates(0.3, 0.0, 0.0, 3.0, -30.0, 0.0, 3.0, -2.0, 0.0, 0.0)   # planet, fixed sun
(30.0, 0.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..common.tolerances import LEAST_REACH
from ..common.errors import AssemblyError, SceneError
from ..common.numbers import sense_word
from .rolling_contact import RollingContact, circle_rates, line_rates, rim_motion
from . import rolling_words as words
from .rolling_dims import GAP, arm_rate, follow_params, pair_of, rate, turned, wheel_params
from .rolling_dims import placed_teeth
from ..scene.teeth import gear_label
from .base import (
    Construction,
    Step,
    Vector,
    absolute,
    centripetal,
    image_label,
    pole_text,
    relative,
)

__all__ = ["RollingWheel", "line_rates", "circle_rates", "rim_motion", "recognise"]


def recognise(g, name):
    """The point of a rolling wheel, once its centre (and the gear it meshes with, and that
    gear's centre) is known: its arm and the gear may turn as any linkage makes them."""
    sc = g.scene
    if not sc.rolling:  # (the usual scene: nothing rolls)
        return None
    pr = sc.rolling_of(name)
    if pr is None or pr.on == "rack" or pr.centre not in g.P or pr.wheel in g.used_links:
        return None
    if pr.on == "line":
        (cx, cy), (tx, ty), (mx, my) = g.P[pr.centre], pr.through, pr.m
        s0 = (cx - tx) * -my + (cy - ty) * mx
        return RollingWheel(
            g.next_index,
            pr.wheel,
            pr.centre,
            name,
            pr.on,
            pr.label,
            wheel_params(sc, g.bodies, pr, s0=s0),
            unit=g.unit,
            uname=g.uname,
        )
    O = pr.base_centre
    if O not in g.P:
        return None
    base_free = None
    if pr.on == "gear":
        base = sc.link(pr.base)
        if not (g.known_link(base) and base.key in g.used_links):
            return None
        kb_rate = rate(g, base.key)
        if kb_rate is None:  # the gear turns as a linkage makes it: read from its points
            base_free = (O, base.other(O))
    else:
        kb_rate = 0.0
    kd_rate = arm_rate(g, pr.centre, O)
    prm = wheel_params(
        sc, g.bodies, pr, kd_rate=kd_rate, kb_rate=kb_rate, P=g.P, base_free=base_free
    )
    teeth = placed_teeth(g, pr, prm[2])  # (its gear's teeth found once placed: named by them)
    where = pr.label if teeth is pr.teeth else gear_label(pr, teeth[1], sc.rolling)
    follow = None
    if base_free is not None:  # a gear that is a wheel whose angle follows its arm: its turn
        bst = next((s for s in g.steps if pr.base in s.links), None)  # from its formula
        if (
            isinstance(bst, RollingWheel)
            and bst.on != "line"
            and bst.kd_rate is None
            and bst.base_free is None
        ):
            follow = (bst.centre, bst.base_centre, bst.kb_rate)
            prm += follow_params(sc, g.bodies, pair_of(sc, pr.base), bst.kb_rate, g.P)
    return RollingWheel(
        g.next_index,
        pr.wheel,
        pr.centre,
        name,
        pr.on,
        where,
        prm,
        base=pr.base,
        base_centre=O,
        inside=pr.inside,
        ring=pr.ring,
        kd_rate=kd_rate,
        kb_rate=kb_rate,
        base_free=base_free,
        follow=follow,
        unit=g.unit,
        uname=g.uname,
        pressure_angle=pr.pressure_angle,
        grip=pr.grip,
        teeth=teeth,
    )


@dataclass(frozen=True)
class RollingWheel(RollingContact, Step):
    """The point P of a wheel CP rolling without slip (see the module): its angle from the
    no-slip relation, ``v_P = v_C + omega perp(CP)``."""

    wheel: str
    centre: str
    rim: str
    on: str  # "line", "circle" or "gear"
    where: str  # what it rolls on, in words
    dims: tuple = ()
    base: str | None = None
    base_centre: str | None = None
    inside: bool = False
    #: the wheel is a ring (an internal gear) about its centre, the gear inside it
    #: (``inside`` true as well: the ratio of an internal pair)
    ring: bool = False
    kd_rate: float | None = 0.0  # the line of centres' turning per radian of the crank
    kb_rate: float | None = 0.0  # the base's turning per radian of the crank
    #: (the gear's centre, its other point) where the gear turns as a linkage makes it (its
    #: angle read from them); the line of centres is read from the two centres where
    #: ``kd_rate`` is None
    base_free: tuple | None = None
    #: where the gear is itself a wheel whose angle follows its arm (a planet on a rocker):
    #: (its centre, its arm's fixed centre, its kb_rate); its turn is then taken from its
    #: formula, ``K_b (theta - theta0) + kd_b (psi_b - psi0_b)`` (``dims[12:15]``)
    follow: tuple | None = None
    unit: float = 1e-3  # the scene's length unit (m), for messages
    uname: str = "mm"
    #: the teeth's pressure angle (rad) the scene states, or None (the default: the force
    #: analysis takes 20 deg and says so)
    pressure_angle: float | None = None
    #: a friction drive's (preload N, friction coefficient or None): no teeth; or None
    grip: tuple | None = None
    teeth: tuple | None = None  # a gear given by its teeth: (z, z of its gear, m or None)

    kind = "rolling"

    @property
    def theta_rate(self):
        """The wheel's turning per radian of the crank (a gear meshing with it reads it)."""
        if self.on == "line" or self.kd_rate is None or self.base_free is not None:
            return None  # it turns as the linkage makes it
        return self.dims[7]

    @property
    def finds(self):
        """The wheel's point P (its rim point, the end of its link CP)."""
        return (self.rim,)

    @property
    def links(self):
        """The wheel, whose omega and alpha follow from the no-slip relation."""
        return (self.wheel,)

    @property
    def needs(self):
        """The wheel's centre; on a circle or a gear, that circle's centre too (and the points its
        gear and its arm turn by, where the linkage turns them)."""
        if self.on == "line":
            return (self.centre,)
        more = (self.base_free[1],) if self.base_free else ()
        more += (self.follow[1],) if self.follow else ()
        return (self.centre, self.base_centre) + more

    @property
    def needs_links(self):
        """The gear it meshes with, whose omega enters its own (none on a line or a fixed
        circle)."""
        return (self.base,) if self.base else ()

    @property
    def title(self):
        """``wheel CA rolling on the line ...``, ``planet AP of 24 teeth meshing with the sun
        of 40 teeth about O`` (:func:`.rolling_words.title`)."""
        return words.title(self)

    @property
    def params(self):
        """Its dimensions as compiled (:func:`~polygon_method.steps.rolling_dims.wheel_params`)."""
        return self.dims

    #: its dimensions read the positions at the stated instant: on a line its centre's
    #: place, on a circle or a gear the centre distance and the arm's and the gear's angles
    instant_dimensions = True

    def dimensions(self, scene, bodies, P=None):
        """The same dimensions read from another scene of the same shape, at its stated instant
        ``P`` (a wheel on a line needs its centre's place there)."""
        pr = pair_of(scene, self.wheel)
        if self.on == "line":
            if P is None:
                raise SceneError(
                    f"wheel {self.wheel} rolls on a line: its dimensions need "
                    "its centre's place at the stated instant",
                    key=f"[rolling] {self.wheel}",
                    file=scene.file,
                )
            (cx, cy), (tx, ty), (mx, my) = P[pr.centre], pr.through, pr.m
            s0 = (cx - tx) * -my + (cy - ty) * mx
            return wheel_params(scene, bodies, pr, s0=s0)
        two = scene.input.second
        kb_rate = self.kb_rate
        if two is not None and self.base == scene.link(two.crank).key:
            kb_rate = two.omega / scene.input.omega  # the ratio of this scene's speeds
        prm = wheel_params(
            scene, bodies, pr, kd_rate=self.kd_rate, kb_rate=kb_rate, base_free=self.base_free, P=P
        )
        if self.follow is not None:
            prm += follow_params(scene, bodies, pair_of(scene, self.base), self.follow[2], P)
        return prm

    def drawn(self, prm, pencil, P):
        """The dimensions as a hand drawing sets them out: the link CP's length drawn with the
        pencil's error, the rest as given."""
        return (prm[0] + pencil(),) + tuple(prm[1:])

    def reach(self):
        """The larger of the link CP and the radius (a scale for its tolerances)."""
        return max(self.dims[0], self.dims[1], LEAST_REACH)

    def place(self, P, prm, ctx, sigma=None):
        """The point at the compiler's instant (the scene's own): a centre off its line or
        pitch circle there is the scene's error, named by its [rolling] key."""
        cx, cy = P[self.centre]
        phi = self._phi(P, prm, ctx)
        g = self.gap(P, prm)
        if not ctx.array and abs(g) > GAP:
            raise SceneError(self._off_words(cx, cy, prm), key=f"[rolling] {self.wheel}")
        ell = prm[0]
        return cx + ell * ctx.cos(phi), cy + ell * ctx.sin(phi), 1.0

    def _phi(self, P, prm, ctx):
        """The wheel's angle: on a line from its centre's place; on a circle or a gear
        ``phi0 + K (theta - theta0)`` for what turns at a fixed ratio of the crank, plus
        ``kd (psi - psi0)`` and ``kb (beta - beta0)`` for a line of centres and a gear that
        turn as a linkage makes them (their angles read from their points: no more than
        half a turn from the stated instant, else the position is refused, masked in a
        sweep: the wheel's angle could not be followed)."""
        cx, cy = P[self.centre]
        if self.on == "line":
            ell, r, tx, ty, mx, my, phi0, s0 = prm
            return phi0 + ((cx - tx) * -my + (cy - ty) * mx - s0) / r
        phi = prm[5] + prm[7] * (ctx.theta - prm[6])
        if self.kd_rate is None:
            ox, oy = P[self.base_centre]
            phi = phi + prm[3] * self._turned(cx - ox, cy - oy, prm[10], ctx)
        if self.follow is not None:  # the gear's turn from its own formula
            (bx, by), (qx, qy) = P[self.follow[0]], P[self.follow[1]]
            turn = prm[13] * (ctx.theta - prm[6]) + prm[12] * self._turned(
                bx - qx, by - qy, prm[14], ctx
            )
            phi = phi + prm[4] * turn
        elif self.base_free is not None:
            (bx, by), (qx, qy) = P[self.base_free[0]], P[self.base_free[1]]
            phi = phi + prm[4] * self._turned(qx - bx, qy - by, prm[11], ctx)
        return phi

    def _turned(self, dx, dy, a0, ctx):
        """The turn of direction (dx, dy) from the angle a0 (:func:`.rolling_dims.turned`)."""
        return turned(dx, dy, a0, ctx, self, f"the arm or the gear of wheel {self.wheel}")

    def gap(self, P, prm):
        """How far the centre is off its line (or its pitch circle), over the radii."""
        cx, cy = P[self.centre]
        if self.on == "line":
            ell, r, tx, ty, mx, my = prm[:6]
            return ((cx - tx) * mx + (cy - ty) * my - r) / r
        ell, r, R = prm[:3]
        ox, oy = P[self.base_centre]
        dx, dy = cx - ox, cy - oy
        want = r - R if self.ring else R - r if self.inside else R + r
        return ((dx * dx + dy * dy) ** 0.5 - want) / (R + r)

    def _check(self, P, prm, ctx):
        g = self.gap(P, prm)
        if ctx is None:
            return
        if ctx.array:
            bad = abs(g) > GAP
            if bad is True or (bad is not False and bad.any()):
                ctx.fail(self, bad)
        elif abs(g) > GAP:
            raise AssemblyError(self.why(g), step=self.label)

    def bind(self, prm):
        """The step's three phases for dimensions ``prm``: functions of a State."""
        C, X, W, i = self.centre, self.rim, self.wheel, self.index
        ell, r = prm[0], prm[1]
        line = self.on == "line"
        O, base = self.base_centre, self.base
        step = self
        if line:
            tx, ty = -prm[5], prm[4]  # t = perp(m)
        else:
            kd, kb = prm[3], prm[4]

        def position(m):
            P, ctx = m.P, m.ctx
            cx, cy = P[C]
            step._check(P, prm, ctx)
            phi = step._phi(P, prm, ctx)
            P[X] = (cx + ell * ctx.cos(phi), cy + ell * ctx.sin(phi))
            m.cond[i] = 1.0

        def rates(m, acc):
            V, A = m.V, m.A
            if line:
                return line_rates(tx, ty, r, *V[C], *(A[C] if acc else (0.0, 0.0)))
            (cx, cy), (ox, oy) = m.P[C], m.P[O]
            (vcx, vcy), (vox, voy) = V[C], V[O]
            if acc:
                (acx, acy), (aox, aoy) = A[C], A[O]
            else:
                acx = acy = aox = aoy = 0.0
            wb = m.W[base] if base else 0.0
            ab = m.Al[base] if base and acc else 0.0
            return circle_rates(
                cx - ox, cy - oy, vcx - vox, vcy - voy, acx - aox, acy - aoy, kd, kb, wb, ab
            )

        def velocity_(m):
            (cx, cy), (x, y) = m.P[C], m.P[X]
            w, _ = rates(m, False)
            vcx, vcy = m.V[C]
            m.W[W] = w
            m.V[X] = (vcx - w * (y - cy), vcy + w * (x - cx))

        def acceleration_(m):
            (cx, cy), (x, y) = m.P[C], m.P[X]
            w, al = rates(m, True)
            _, _, ax, ay = rim_motion(x - cx, y - cy, w, al, 0.0, 0.0, *m.A[C])
            m.Al[W] = al
            m.A[X] = (ax, ay)

        return position, velocity_, acceleration_

    def bind_instant(self, prm):
        """The three phases in a row for one instant, the same formulas as ``bind`` (its
        intermediates passed on: the centre, the wheel's angle, omega)."""
        C, X, W, i, step = self.centre, self.rim, self.wheel, self.index, self
        ell, r = prm[0], prm[1]
        O, base = self.base_centre, self.base
        cos, sin = math.cos, math.sin
        if self.on == "line":
            tx, ty = -prm[5], prm[4]  # t = perp(m)

            def instant(m):
                P, V, A = m.P, m.V, m.A
                cx, cy = P[C]
                step._check(P, prm, m.ctx)
                phi = step._phi(P, prm, m.ctx)
                x, y = cx + ell * cos(phi), cy + ell * sin(phi)
                P[X] = (x, y)
                rx, ry = x - cx, y - cy  # as the phases read it back (the same bits)
                m.cond[i] = 1.0
                vcx, vcy = V[C]
                acx, acy = A[C]
                w, al = line_rates(tx, ty, r, vcx, vcy, acx, acy)
                vx, vy, ax, ay = rim_motion(rx, ry, w, al, vcx, vcy, acx, acy)
                m.W[W], m.Al[W] = w, al
                V[X], A[X] = (vx, vy), (ax, ay)

            return instant
        kd, kb, phi0, th0, K = prm[3], prm[4], prm[5], prm[6], prm[7]
        fixed = self.kd_rate is not None and self.base_free is None

        def instant(m):
            P, V, A = m.P, m.V, m.A
            cx, cy = P[C]
            ox, oy = P[O]
            ctx = m.ctx
            step._check(P, prm, ctx)
            phi = phi0 + K * (ctx.theta - th0) if fixed else step._phi(P, prm, ctx)
            x, y = cx + ell * cos(phi), cy + ell * sin(phi)
            P[X] = (x, y)
            rx, ry = x - cx, y - cy  # as the phases read it back (the same bits)
            m.cond[i] = 1.0
            (vcx, vcy), (vox, voy) = V[C], V[O]
            (acx, acy), (aox, aoy) = A[C], A[O]
            w, al = circle_rates(
                cx - ox,
                cy - oy,
                vcx - vox,
                vcy - voy,
                acx - aox,
                acy - aoy,
                kd,
                kb,
                m.W[base] if base else 0.0,
                m.Al[base] if base else 0.0,
            )
            vx, vy, ax, ay = rim_motion(rx, ry, w, al, vcx, vcy, acx, acy)
            m.W[W], m.Al[W] = w, al
            V[X], A[X] = (vx, vy), (ax, ay)

        return instant

    rounding = 8.0

    def error_bound(self, walk, k, p_in, v_in, a_in):
        """The centre's errors (and the base's), times ``1 + l / r`` (the point is set out
        from the centre at l, the angle from the no-slip relation over r), plus its own
        rounding."""
        gain = 1.0 + self.dims[0] / self.dims[1]
        kp, kv, ka = walk.own(self, k)
        p, v, a = gain * p_in + kp, gain * v_in + kv, gain * a_in + ka
        return p, v, a, v, a

    # ----- words
    def why(self, g):
        """Why the wheel cannot roll here: its centre is off its line or pitch circle by ``g`` of
        the radii."""
        return (
            f"the centre {self.centre} of wheel {self.wheel} is off "
            + ("its line" if self.on == "line" else "its pitch circle")
            + f" by {abs(g):.3g} of the radii: the contact leaves the pitch point "
            "(the wheel would slip or lift)"
        )

    def singular_why(self, c):
        """Why it is singular: the wheel has left its contact."""
        return f"the wheel {self.wheel} has left its contact (condition {c:.2g})"

    def warning(self, c):
        """The warning near leaving its contact."""
        return f"{self.label}: the wheel {self.wheel} is near leaving its contact ({c:.3g})"

    def limit_why(self):
        """Why its motion ends: the wheel would leave what it rolls on (or, followed from its arm,
        the arm has turned half a turn)."""
        if self.on != "line" and self.theta_rate is None:
            return (
                f"the wheel {self.wheel} would leave {self.where}, or its arm or gear has "
                "turned half a turn from the stated instant: its angle is followed no "
                "further (solve the scene at a later instant to go on)"
            )
        return f"the wheel {self.wheel} would leave {self.where}"

    def transmission(self):
        """None: no transmission angle (no two links meet at a joint here)."""
        return None

    def condition_column(self):
        """None: its condition is no column of a sweep."""
        return None

    def bodies(self):
        """The wheel, the body it moves."""
        return (self.wheel,)

    def orient(self):
        """The wheel's line from its point P towards its centre (how the views draw it)."""
        return {self.wheel: (self.rim, self.centre)}

    def output(self, ground):
        """None: a wheel is no output of the linkage's analysis."""
        return None

    def default_hint(self, P):
        """``above``: the assembly hint where the scene gives none (it has one assembly)."""
        return "above"

    def position_words(self, L, which, angle_deg):
        """The step table's words for its position (:func:`.rolling_words.position_words`)."""
        return words.position_words(self, L)

    def construction(self, sol, ph):
        """What it draws on the ``ph`` polygon: the centre's vector, the rim point's relative to it
        at omega |CP|, and the contact's."""
        C, X, W = self.centre, self.rim, self.wheel
        lab = lambda p: image_label(sol, p, ph)  # noqa: E731
        cond = sol.conditions.get(self.index, 1.0)
        I, vI, aI = self.contact_motion(sol)
        w, al, r = sol.W[W], sol.Al[W], self.dims[1]
        if ph == "velocity":
            V = sol.V
            text = (
                words.omega_words(self, sol, w, vI) + f"; from {pole_text(sol, C, ph)} draw "
                f"{lab(C)}{lab(X)} perpendicular to {C}{X} = omega x {C}{X} = "
                f"{abs(w) * self.dims[0]:.4g} m/s"
            )
            found = (relative(sol, X, C, V, ph), absolute(sol, X, V, ph))
            return Construction(self.index, self.title, ph, lab(X), V[X], (), (), found, text, cond)
        A = sol.A
        cen = centripetal(sol, X, C, W, ph)
        tan = Vector(
            cen.end,
            A[X],
            f"{lab(X)}t",
            "tangential",
            f"tangential of {X}{C}",
            f"alpha x {C}{X} = {abs(al) * self.dims[0]:.4g} m/s^2, perpendicular to {C}{X}",
        )
        where = (
            f"omega^2 r = {w * w * r:.4g} m/s^2 towards the centre {C}"
            if self.on == "line"
            else f"{math.hypot(*aI):.4g} m/s^2"
        )
        why = (
            f"the tangential acceleration of {C} along the contact, over r"
            if self.on != "gear"
            else "the two gears' points at I have one tangential acceleration"
        )
        text = (
            f"alpha_{W} = {f'{abs(al):.4g} rad/s^2 {sense_word(al)}'.rstrip()} from the no-slip "
            f"relation ({why}); from "
            f"{pole_text(sol, C, ph)} draw the centripetal component {cen.text}, then the "
            f"tangential {tan.text}; its end is {lab(X)}. The contact point I is not at rest "
            f"in acceleration: a_I = {where}"
        )
        found = (cen, tan, relative(sol, X, C, A, ph), absolute(sol, X, A, ph))
        return Construction(self.index, self.title, ph, lab(X), A[X], (cen,), (), found, text, cond)
