"""The motion record: what a plan's evaluation gives, at one instant or at many.

:class:`Motion` holds positions, velocities and accelerations of every point, omega and
alpha of every link, the sliding velocity, sliding acceleration and Coriolis component of
every slider, and the condition of every step: floats for one configuration
(:func:`polygon_method.motion.solution.solve`), numpy arrays for many (a sweep over crank angles,
or many mechanisms of one shape). Everything derived (rubbing, torque, transmission
angle) is computed from it (:mod:`polygon_method.solver.derived`).

>>> from polygon_method.scene import parse_scene
>>> from polygon_method.solver.compiler import compile_plan
>>> sc = parse_scene('''
... [ground]
... O = [0, 0]
... [links]
... OA = 150
... AB = 600
... [sliders]
... B = { path = "horizontal" }
... [input]
... crank = "OA"
... angle = 90
... speed = "10 rad/s ccw"
... ''')
>>> m = evaluate(compile_plan(sc), upto=1)          # positions and velocities only
>>> round(m.speed("B"), 6), m.A == {}
(1.5, True)
"""

from __future__ import annotations

from dataclasses import replace

from ..common.errors import SceneError
from .plan import Context, Dims, Plan
from ..steps.relations import rigid_acceleration, rigid_velocity
from ..steps.rounding import vhypot as hypot  # |(x, y)| for floats or arrays

__all__ = ["Motion", "evaluate", "hypot"]


class Motion:
    """Positions, velocities and accelerations of a mechanism (SI, ccw positive).

    ``P, V, A``: point -> (x, y); ``W, Al``: link key -> omega, alpha; ``S``: slider point ->
    (vs, as, coriolis x, coriolis y); ``cond``: step index -> condition measure; ``theta``:
    the crank angle(s); ``bad``: in array mode, the entries where a step failed (or None).
    Phases not evaluated are empty dicts.
    """

    __slots__ = ("scene", "plan", "theta", "P", "V", "A", "W", "Al", "S", "cond", "bad")

    def __init__(self, scene, plan, theta, P, V, A, W, Al, S, cond, bad=None):
        self.scene, self.plan, self.theta = scene, plan, theta
        self.P, self.V, self.A, self.W, self.Al, self.S = P, V, A, W, Al, S
        self.cond, self.bad = cond, bad

    # ----- points
    def _lookup(self, table, name, what):
        try:
            return table[name]
        except (KeyError, TypeError):
            raise self._unknown(name, what) from None

    def _unknown(self, name, what):
        known = {"point": self.P, "link": self.W, "slider": self.S}[what]
        if what == "point" and name in self.P and not self.V:
            return SceneError(f"the velocities of {name} were not evaluated (positions only)")
        return SceneError(f"no {what} {name!r} here; the {what}s are " + ", ".join(map(str, known)))

    def position(self, point):
        """The position of ``point``, (x, y) in m."""
        return self._lookup(self.P, point, "point")

    def velocity(self, point, relative_to=None):
        """Velocity of ``point`` (relative to ``relative_to``: v_XY = v_X - v_Y)."""
        vx, vy = self._lookup(self.V, point, "point")
        if relative_to is None:
            return (vx, vy)
        ux, uy = self._lookup(self.V, relative_to, "point")
        return (vx - ux, vy - uy)

    def acceleration(self, point, relative_to=None):
        """Acceleration of ``point`` (relative to ``relative_to``: a_XY = a_X - a_Y), m/s^2."""
        ax, ay = self._lookup(self.A, point, "point")
        if relative_to is None:
            return (ax, ay)
        bx, by = self._lookup(self.A, relative_to, "point")
        return (ax - bx, ay - by)

    def speed(self, point, relative_to=None):
        """The size of ``point``'s velocity (relative to ``relative_to``), m/s."""
        return hypot(*self.velocity(point, relative_to))

    def acceleration_magnitude(self, point, relative_to=None):
        """The size of ``point``'s acceleration (relative to ``relative_to``), m/s^2."""
        return hypot(*self.acceleration(point, relative_to))

    # ----- links
    def _key(self, link):
        if self.scene is None:
            return link
        try:
            return self.scene.link(link).key
        except (SceneError, TypeError, AttributeError):
            cyl = self.scene.cylinder(link) if isinstance(link, str) else None
            if cyl is not None:  # a cylinder turns as a link does
                return cyl.key
            raise self._unknown(link, "link") from None

    def cylinder_length(self, name):
        """The pin-to-pin length of cylinder ``name`` (m)."""
        cyl = self.scene.cylinder(name)
        if cyl is None:
            raise SceneError(f"no cylinder {name!r} in [cylinders]")
        (rx, ry), (kx, ky) = self.P[cyl.rod], self.P[cyl.barrel]
        return hypot(rx - kx, ry - ky)

    def omega(self, link):
        """The angular velocity of ``link`` ("BC" or "CB"), rad/s, ccw positive."""
        return self._lookup(self.W, self._key(link), "link")

    def alpha(self, link):
        """The angular acceleration of ``link``, rad/s^2, ccw positive."""
        return self._lookup(self.Al, self._key(link), "link")

    # ----- sliders
    def sliding_velocity(self, point):
        """The velocity of the block at ``point`` along its guide (relative to the guide), m/s,
        signed along the guide's direction."""
        return self._lookup(self.S, point, "slider")[0]

    def sliding_acceleration(self, point):
        """The acceleration of the block at ``point`` along its guide (relative to the guide),
        m/s^2."""
        return self._lookup(self.S, point, "slider")[1]

    def coriolis(self, point):
        """The Coriolis component of the block at ``point`` on a turning guide, 2 omega x v_s, as
        (x, y) in m/s^2 ((0, 0) on a fixed path)."""
        s = self._lookup(self.S, point, "slider")
        return (s[2], s[3])

    def under_block(self, slider, phase="velocity"):
        """The velocity (``phase`` "velocity") or acceleration of the point of the guide link
        that lies under the block ``slider`` (a1, a1' on the polygons), from the guide's
        end K: ``v_K + omega x KA`` and ``a_K - omega^2 KA + alpha x KA``."""
        sl = self.scene.slider(slider)
        g = self.scene.link(sl.guide)
        (kx, ky), (x, y) = self.P[g.p], self.P[sl.point]
        rx, ry = x - kx, y - ky
        w = self.W[g.key]
        if phase == "velocity":
            vx, vy = self.V[g.p]
            dx, dy = rigid_velocity(rx, ry, w)
            return (vx + dx, vy + dy)
        ax, ay = self.A[g.p]
        dx, dy = rigid_acceleration(rx, ry, w, self.Al[g.key])
        return (ax + dx, ay + dy)

    @property
    def conditions(self) -> dict:
        """Each step's condition measure (step index -> the sine of the angle between its two
        direction lines, or its own measure)."""
        return self.cond

    @property
    def n(self) -> int:
        """How many positions: the length of ``theta`` (1 for one instant)."""
        return len(self.theta) if hasattr(self.theta, "__len__") else 1


def evaluate(
    plan: Plan,
    theta=None,
    omega=None,
    alpha=None,
    *,
    dims: Dims | None = None,
    upto: int = 2,
    array: bool = False,
    points=None,
    links=None,
) -> Motion:
    """Evaluate ``plan`` (at its own scene's dimensions, or at ``dims``) and return the
    :class:`Motion`. ``upto``: 0 positions only, 1 with velocities, 2 with accelerations.
    ``theta``/``omega``/``alpha`` default to the dimensions' own; with ``array=True`` they
    (and any dimension) may be numpy arrays. ``points``/``links``: evaluate only the steps
    these depend on (the motion then holds those and what they need)."""
    if points is not None or links is not None:
        if dims is not None:
            keep = {st.index for st in plan.restricted(points or (), links or ()).steps}
            dims = replace(
                dims, steps=tuple(p for st, p in zip(plan.steps, dims.steps) if st.index in keep)
            )
        plan = plan.restricted(points or (), links or ())
    d = plan.dims if dims is None else dims
    ctx = Context(
        d.theta if theta is None else theta,
        d.omega if omega is None else omega,
        d.alpha if alpha is None else alpha,
        array=array,
    )
    m = plan.run(ctx, dims, upto)
    return Motion(
        plan.scene,
        plan,
        ctx.theta,
        m.P,
        m.V if upto >= 1 else {},
        m.A if upto >= 2 else {},
        m.W if upto >= 1 else {},
        m.Al if upto >= 2 else {},
        m.S,
        ctx.cond,
        ctx.bad,
    )
