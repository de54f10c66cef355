"""A rack meshing with a pinion: a block sliding on a fixed path (the rack's pitch line),
driven without slip by a gear turning about a fixed centre O.

The pitch point I is the foot of the perpendicular from O on the pitch line (pinion pitch
radius R_p = |OI|, n = (I - O) / R_p). No slip: the rack moves as the pinion's point at I,
``v_R = omega_B perp(I - O)``, which lies along the path; so with ``k = R_p perp(n) . u``
(+-R_p: which way the path runs past the pinion)::

    vs = k omega_B,   as = k alpha_B,   R = T + k K (theta - theta0) u

(T where the rack's point is at the stated crank angle, K the pinion's turning per radian
of the crank: 1 for the crank itself, the gear ratio for a gear meshing with it). A pinion
that turns as a linkage makes it (keyed to the rocker of a four-bar) has no such ratio: its
angle beta is read from its points (its centre O and its link's other point Q), and the
rack follows it, ``R = T + k (beta - beta0) u`` (beta0 at the stated instant; the turn
followed no further than half a turn either way). The velocity and acceleration are the
same, ``vs = k omega_B``, ``as = k alpha_B``. A pinion between two racks drives them in
opposite senses.

>>> rack_rates(-0.04, 10.0, 5.0)
(-0.4, -0.2)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..common.errors import SceneError
from ..common.numbers import in_units
from ..common.tolerances import LEAST_REACH, NO_RADIUS, SAME
from .base import Construction, DirectionLine, Step, Vector, absolute, image_label
from ..scene.teeth import formula
from .rolling_dims import angle_of, turned
from .rounding import EPS, line_rounding

__all__ = ["RackStep", "rack_rates", "recognise"]


def rack_rates(k, wb, ab):
    """(vs, as) of a rack on a pinion turning at wb, ab: ``k wb``, ``k ab``."""
    return k * wb, k * ab


def _rack_params(scene, pr, kb_rate, beta0=0.0):
    """(tx, ty, ux, uy, k, K, theta0, ox, oy, beta0): the rack's point at the stated angle,
    its path's direction, the pitch factor k, the pinion's rate K (0 where it turns as a
    linkage makes it) and then its angle at the stated instant beta0."""
    sl = scene.slider(pr.rim)
    (tx, ty), (ux, uy) = sl.through, sl.u
    ox, oy = scene.ground[pr.base_centre]
    d = (tx - ox) * -uy + (ty - oy) * ux  # signed distance of the line from O (along perp u)
    Rp = abs(d)
    where = f"[rolling] {pr.rim}"
    if Rp < NO_RADIUS:
        raise SceneError(
            f"the rack {pr.rim}'s path passes through the pinion's centre "
            f"{pr.base_centre}: a pinion of no radius",
            key=where,
            file=scene.file,
        )
    if pr.base_radius is not None and abs(pr.base_radius - Rp) > SAME * Rp:
        u = scene.length_unit
        raise SceneError(
            f"the contact leaves the pitch point: the rack's pitch line is "
            f"{in_units(Rp, u)} {scene.units} from {pr.base_centre}, not the "
            f"pinion's pitch radius {in_units(pr.base_radius, u)} {scene.units}",
            key=where,
            file=scene.file,
        )
    # I - O = d perp(u); v_I = omega perp(I - O) = -omega d u: k = -d
    return (tx, ty, ux, uy, -d, kb_rate, scene.input.angle, ox, oy, beta0)


def recognise(g, name):
    """A rack's point, once the pinion it meshes with is known and turning."""
    sc = g.scene
    if not sc.rolling:  # (the usual scene: nothing rolls)
        return None
    pr = next((r for r in sc.rolling if r.on == "rack" and r.rim == name), None)
    if pr is None or name in g.P or name in g.used_sliders:
        return None
    base = sc.link(pr.base)
    if not (g.known_link(base) and base.key in g.used_links):
        return None
    free, beta0 = None, 0.0
    if base.key == sc.input.crank:
        rate = 1.0
    else:
        rate = next(
            (getattr(st, "theta_rate", None) for st in g.steps if base.key in st.links), None
        )
        if rate is None:  # the pinion turns as a linkage makes it: its angle from its points
            O = pr.base_centre
            free, rate = (O, base.other(O)), 0.0
            (ox, oy), (qx, qy) = g.P[O], g.P[free[1]]
            beta0 = angle_of(qx - ox, qy - oy)
    g.used_sliders.add(name)
    return RackStep(
        g.next_index,
        name,
        base.key,
        pr.base_centre,
        _rack_params(sc, pr, rate, beta0),
        free=free,
        unit=g.unit,
        uname=g.uname,
        pressure_angle=pr.pressure_angle,
        teeth=pr.teeth,
    )


@dataclass(frozen=True)
class RackStep(Step):
    """R = T + k K (theta - theta0) u; vs = k omega_B, as = k alpha_B (see the module)."""

    point: str
    base: str
    base_centre: str
    dims: tuple = ()
    #: (the pinion's centre, its link's other point) where the pinion turns as a linkage
    #: makes it (its angle read from them), else None (a fixed ratio of the crank)
    free: tuple | None = None
    unit: float = 1e-3
    uname: str = "mm"
    #: the teeth's pressure angle (rad) the scene states, or None (the force analysis'
    #: default, 20 deg)
    pressure_angle: float | None = None
    #: the pinion given by its teeth: (None, its teeth, the module m), or None
    teeth: tuple | None = None

    kind = "rack"

    @property
    def finds(self):
        return (self.point,)

    @property
    def links(self):
        return ()

    @property
    def needs(self):
        return (self.base_centre,) + ((self.free[1],) if self.free else ())

    @property
    def needs_links(self):
        return (self.base,)

    @property
    def title(self):
        return f"rack {self.point} on {self._pinion}"

    @property
    def _pinion(self):
        """``the pinion O1-A``, ``the pinion O1-A of 20 teeth`` where its teeth are given."""
        of = f" of {self.teeth[1]} teeth" if self.teeth and self.teeth[1] else ""
        return f"the pinion {self.base}{of}"

    @property
    def params(self):
        return self.dims

    @property
    def instant_dimensions(self):
        """A pinion turned by a linkage: its angle at the stated instant is read there."""
        return self.free is not None

    def dimensions(self, scene, bodies, P=None):
        pr = next(r for r in scene.rolling if r.on == "rack" and r.rim == self.point)
        if self.free is None:
            return _rack_params(scene, pr, self.dims[5])
        if P is None:
            raise SceneError(
                f"the pinion {self.base} of rack {self.point} turns as a linkage "
                "makes it: its dimensions need its angle at the stated instant",
                key=f"[rolling] {self.point}",
                file=scene.file,
            )
        (ox, oy), (qx, qy) = P[self.free[0]], P[self.free[1]]
        return _rack_params(scene, pr, 0.0, angle_of(qx - ox, qy - oy))

    def drawn(self, prm, pencil, P):
        return (prm[0] + pencil(), prm[1] + pencil()) + tuple(prm[2:])

    def reach(self):
        return max(abs(self.dims[4]), LEAST_REACH)

    def place(self, P, prm, ctx, sigma=None):
        tx, ty, ux, uy, k, K, th0 = prm[:7]
        return tx + (s := self._travel(P, prm, ctx)) * ux, ty + s * uy, 1.0

    def _travel(self, P, prm, ctx):
        """How far the rack has moved along its path from T: ``k K (theta - theta0)``, or
        ``k (beta - beta0)`` for a pinion turned by a linkage (its turn read from its
        points, no more than half a turn: beyond, refused, masked in a sweep)."""
        k, K, th0 = prm[4], prm[5], prm[6]
        if self.free is None:
            return k * K * (ctx.theta - th0)
        (ox, oy), (qx, qy) = P[self.free[0]], P[self.free[1]]
        return k * turned(qx - ox, qy - oy, prm[9], ctx, self, f"the pinion {self.base}")

    def bind(self, prm):
        """The step's three phases for dimensions ``prm``: functions of a State."""
        X, base, i, step = self.point, self.base, self.index, self
        ux, uy, k = prm[2], prm[3], prm[4]

        def position(m):
            x, y, _ = step.place(m.P, prm, m.ctx)
            m.P[X] = (x, y)
            m.cond[i] = 1.0

        def velocity_(m):
            vs, _ = rack_rates(k, m.W[base], 0.0)
            m.S[X] = [vs, None, 0.0, 0.0]
            m.V[X] = (vs * ux, vs * uy)

        def acceleration_(m):
            _, a_s = rack_rates(k, 0.0, m.Al[base])
            m.S[X][1] = a_s
            m.A[X] = (a_s * ux, a_s * uy)

        return position, velocity_, acceleration_

    def bind_instant(self, prm):
        """The three phases in a row for one instant (the same formulas)."""
        X, base, i, step = self.point, self.base, self.index, self
        tx, ty, ux, uy, k, K, th0 = prm[:7]

        def instant(m):
            s = step._travel(m.P, prm, m.ctx)
            m.P[X] = (tx + s * ux, ty + s * uy)
            m.cond[i] = 1.0
            vs, a_s = rack_rates(k, m.W[base], m.Al[base])
            m.S[X] = [vs, a_s, 0.0, 0.0]
            m.V[X] = (vs * ux, vs * uy)
            m.A[X] = (a_s * ux, a_s * uy)

        return instant

    rounding = 8.0

    def error_bound(self, walk, k, p_in, v_in, a_in):
        """The pinion's errors (its omega and alpha times the pitch radius), plus the
        rounding of the rack's own formula (counted against its own numbers,
        ``walk.own``) and of its path's numbers, as a slider counts
        them (:func:`.rounding.line_rounding`): ``R = T + s u`` is rounded to the digits of
        the path's point T (far from the mechanism, far along the path), and the pitch
        factor ``k = -(T - O) x u`` cancels ``|T - O|`` down to the pitch radius, so
        ``vs = k omega`` and ``as = k alpha`` err by ``(K eps + du) |T - O| / |k|`` of
        themselves (``du`` the rounding of the path's direction, none along an axis)."""
        kp, kv, ka = walk.own(self, k)
        tx, ty, ux, uy, kk = self.dims[:5]
        ox, oy = self.dims[7], self.dims[8]
        x, y = walk.P[self.point]
        sz = walk.sizes
        axis = ux == 0.0 or uy == 0.0  # a horizontal or vertical path: u is exact
        angle = math.atan2(uy, ux)
        du = 0.0 if axis else 4 * EPS * max(1.0, abs(angle))
        own = line_rounding(self.rounding, tx, ty, x, y, sz["position"], None if axis else angle)
        pitch = (self.rounding * EPS + du) * math.hypot(tx - ox, ty - oy) / abs(kk)
        vs, a_s = walk.motion.S[self.point][0], walk.motion.S[self.point][1]
        v = v_in + kv + pitch * abs(vs) / sz["velocity"]
        a = a_in + ka + pitch * abs(a_s) / sz["acceleration"]
        return p_in + kp + own, v, a, v, a

    # ----- what the views ask
    def contact(self, P):
        """The pitch point of the rack and its pinion, from the positions ``P``."""
        ox, oy = P[self.base_centre]
        d = -self.dims[4]
        ux, uy = self.dims[2], self.dims[3]
        return (ox - d * uy, oy + d * ux)

    def contact_motion(self, sol):
        """(I, v, a): the pitch point and the rack's motion (a translation: every point of
        the rack has it)."""
        return self.contact(sol.P), tuple(sol.V[self.point]), tuple(sol.A[self.point])

    def contacts(self, P):
        return (
            (
                self.base,
                f"block {self.point}",
                self.contact(P),
                f"the pitch point of rack {self.point} and pinion {self.base} (no slip)",
            ),
        )

    def shapes(self, P):
        return (
            ("circle", self.base_centre, abs(self.dims[4])),
            ("contact", self.contact(P)),
            ("guide clear of", self.point, P[self.base_centre]),
        )

    # ----- words
    def why(self, g):
        """Why the rack cannot be placed: it leaves its pinion."""
        return f"the rack {self.point} leaves its pinion {self.base}"

    def singular_why(self, c):
        return f"the rack {self.point} has left its pinion (condition {c:.2g})"

    def warning(self, c):
        return f"{self.label}: the rack {self.point} is near leaving its pinion ({c:.3g})"

    def limit_why(self):
        if self.free is not None:
            return (
                f"the pinion {self.base} of rack {self.point} has turned half a turn from "
                "the stated instant: its angle is followed no further (solve the scene at "
                "a later instant to go on)"
            )
        return f"the rack {self.point} would leave its pinion {self.base}"

    def transmission(self):
        return None

    def condition_column(self):
        return None

    def bodies(self):
        return (f"block {self.point}",)

    def orient(self):
        return {}

    def output(self, ground):
        return ("slider", self.point)

    def default_hint(self, P):
        return "above"

    def position_words(self, L, which, angle_deg):
        return (
            f"{self.point}: the rack's point, on its pitch line at {L(abs(self.dims[4]))} "
            f"from {self.base_centre}"
            + (
                f" ({' = '.join(formula(self.teeth[2], self.teeth[3], self.teeth[1]))})"
                if self.teeth
                else ""
            )
            + f", moved along it as far as {self._pinion} rolls it"
        )

    def construction(self, sol, ph):
        X = self.point
        lab = image_label(sol, X, ph)
        u = (self.dims[2], self.dims[3])
        o = "o" if ph == "velocity" else "o'"
        if ph == "velocity":
            D, w, sym = sol.V, sol.W[self.base], "v"
            text = (
                f"equal velocities at the pitch point (no slip): the rack moves as the "
                f"pinion's point at I, "
                f"v_{X} = omega_{self.base} x {self.base_centre}I = {abs(w):.4g} x "
                f"{abs(self.dims[4]):.4g} = {math.hypot(*D[X]):.4g} m/s; from {o} draw "
                f"{o}{lab} parallel to the path"
            )
        else:
            D, al, sym = sol.A, sol.Al[self.base], "a"
            text = (
                f"the rack translates: a_{X} = alpha_{self.base} x {self.base_centre}I = "
                f"{abs(al):.4g} x {abs(self.dims[4]):.4g} = {math.hypot(*D[X]):.4g} m/s^2 "
                f"along the path (the pinion's point at I has besides the centripetal "
                f"omega^2 R_p = {sol.W[self.base] ** 2 * abs(self.dims[4]):.4g} m/s^2 "
                f"towards {self.base_centre}: the contact point's acceleration is not "
                f"zero); from {o} draw {o}{lab} "
                "parallel to the path"
            )
        found = (
            absolute(sol, X, D, ph),
            Vector((0.0, 0.0), D[X], f"{o}{lab}", "sliding", f"{sym}s_{X}", "along the path"),
        )
        line = DirectionLine((0.0, 0.0), u, o, "parallel to the path", mark="\u2225 path")
        return Construction(self.index, self.title, ph, lab, D[X], (), (line,), found, text, 1.0)
