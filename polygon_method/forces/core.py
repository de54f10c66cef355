"""The force solve's short road: planned once per scene, then only numbers.

What the force analysis needs from a scene and its kinematic plan is the same at every
instant: which body each point's forces act on (:func:`~polygon_method.forces.owners`),
each mass's body, centre (``lam``, ``mu`` on its link) and weight, each load's body, and
each group's bodies and points. :class:`ForcePlan` works all of that out once; its
:meth:`~ForcePlan.run` then adds the known forces on each body into numbered sums
(:class:`Sums`: the same additions, in the same order, as the
:class:`~polygon_method.forces.bodies.Ledger` makes them) and calls each group's equations
(its room's ``solve``, the one place they are written) in the plan's reverse order: the
function each room's ``bind`` gives, on floats for one instant or on arrays of crank
angles for a sweep alike.

It keeps the pin forces, the guides' forces, the driver's effort and the shaking force and
moment as plain numbers; the records a reader may ask for (:class:`~.records.Inertia`,
:class:`~.records.PinForce`, :class:`~.records.GuideForce`) are made from them when first
read, and the step records with their words and drawings (:class:`~.records.ForceStep`,
the free bodies) by the long road, the rooms' ``step``, only when a view reads them.

A plan with a group whose room has no ``bind`` (a yoke, a peg, a cylinder, a wheel, a
triad), or driven by a cylinder (whose force needs the walk twice), takes the long road
for everything: :attr:`ForcePlan.quick` is False.
"""

from __future__ import annotations

import weakref

from .bodies import Singular, centre
from .engine import indicator_force
from .records import FRAME, GuideForce, PinForce, block

__all__ = ["ForcePlan", "Sums", "force_plan"]


class Sums:
    """The resultant ``(Fx, Fy, M about the origin)`` of the known forces on each body,
    by the body's number (the frame 0): three lists, added to as the
    :class:`~polygon_method.forces.bodies.Ledger` adds (``t + f``, ``t + cross(r, f)``)."""

    __slots__ = ("fx", "fy", "m")

    def __init__(self, n):
        self.fx = [0.0] * n
        self.fy = [0.0] * n
        self.m = [0.0] * n

    def add(self, i, fx, fy, x, y):
        """A force ``(fx, fy)`` at ``(x, y)`` on body ``i``."""
        self.fx[i] = self.fx[i] + fx
        self.fy[i] = self.fy[i] + fy
        self.m[i] = self.m[i] + (x * fy - y * fx)

    def couple(self, i, c):
        """A couple ``c`` (N m, ccw positive) on body ``i``."""
        self.m[i] = self.m[i] + c

    def of(self, i):
        """``(Fx, Fy, M about the origin)`` known on body ``i``."""
        return (self.fx[i], self.fy[i], self.m[i])


class Numbering:
    """body name -> its number in the :class:`Sums` (the frame 0), given as first asked."""

    def __init__(self):
        self.index = {FRAME: 0}

    def __call__(self, body) -> int:
        """The number of ``body`` (a new one the first time it is named)."""
        i = self.index.get(body)
        if i is None:
            i = self.index[body] = len(self.index)
        return i


class ForcePlan:
    """What the force analysis of ``scene`` on ``plan`` needs, worked out once (see the
    module). ``own``: point -> the body its forces act on; ``quick``: whether every group
    has its short road; ``driving``: a step that drives the mechanism by a force found
    from the walk (a cylinder), or None."""

    def __init__(self, scene, plan):
        from . import ROOMS, owners  # the rooms (this module is one of their helpers)
        self.scene, self.plan = scene, plan
        self.own = own = owners(scene, plan)  # refuses what the analysis does not cover
        self.driving = next((st for st in plan.steps
                             if getattr(ROOMS[st.kind], "drives", lambda sc, s: False)(scene, st)),
                            None)
        self.quick = self.driving is None and all(hasattr(ROOMS[st.kind], "bind")
                                                  for st in plan.steps)
        if not self.quick:
            return
        ix = Numbering()
        self._masses(scene, ix)
        self._loads(scene, own, ix)
        first = plan.steps[0]
        self.steps = tuple((st, ROOMS[st.kind].bind(st, own, ix), st is first)
                           for st in reversed(plan.steps))
        self.size = len(ix.index)
        inp = scene.input
        if first.kind == "block":  # the driver the plan starts with: a block
            self.driver = (block(first.point), "block")
        else:
            self.driver = (inp.crank, "crank")
        self.second = None if inp.second is None else scene.link(inp.second.crank).key

    def _masses(self, scene, ix):
        """Each mass as (body number, block's point or None, link's ends, lam, mu, its
        link's key, its record's fields, its weight): in the scene's order, as
        :func:`~.bodies.gather` takes them."""
        grav = scene.gravity
        fixed = {lk.key for lk in scene.links if lk.p in scene.ground and lk.q in scene.ground}
        out = []
        for m in scene.masses:
            if m.body in fixed:  # a part of the frame: it neither moves nor loads
                continue
            if m.block:
                body, where = block(m.body), (m.body, None, None)
            else:
                lk = scene.link(m.body)
                body, where = lk.key, (None, lk.p, lk.q)
            weight = None
            if grav is not None:
                w = m.mass * grav.g
                weight = (w * grav.direction[0], w * grav.direction[1])
            out.append((ix(body), body, *where, m.lam, m.mu, m.mass, m.inertia, m.how,
                        weight))
        self.masses = tuple(out)

    def _loads(self, scene, own, ix):
        """Each load as (body number or None for a couple's, point, force or couple, gas);
        the indicator's piston and its body's number."""
        out = []
        for ld in scene.loads:
            if ld.force is not None:
                body = own.get(ld.target, FRAME)
                if body == FRAME:
                    continue
                out.append((ix(body), ld.target, ld.force, ld.gas))
            else:
                out.append((None, ix(ld.target), ld.torque, None))
        self.loads = tuple(out)
        ind = scene.indicator
        self.indicator = None if ind is None else (ind.piston,
                                                   ix(own.get(ind.piston, FRAME)))

    def run(self, motion):
        """The numbers of the force analysis at ``motion``'s instant (or over its angles):
        (the inertia's raw fields, pin forces, guide forces as tuples, the first driver's
        effort, a second crank's torque, the frame's resultant)."""
        P, A, Al = motion.P, motion.A, motion.Al
        S = Sums(self.size)
        add, couple = S.add, S.couple
        inertia = []
        for i, body, pt, p, q, lam, mu, mass, moment, how, weight in self.masses:
            if pt is not None:
                G, a_G, alpha = P[pt], A[pt], 0.0
            else:
                G, a_G, alpha = centre(P, lam, mu, p, q), centre(A, lam, mu, p, q), Al[body]
            fx, fy = -mass * a_G[0], -mass * a_G[1]
            inertia.append((body, mass, moment, G, a_G, alpha, how))
            add(i, fx, fy, G[0], G[1])
            couple(i, -moment * alpha)
            if weight is not None:
                add(i, weight[0], weight[1], G[0], G[1])
        for i, target, f, gas in self.loads:
            if i is None:  # a couple on a link
                couple(target, f)
                continue
            x, y = P[target]
            add(i, f[0], f[1], x, y)
            if gas:  # the gas pushes the cylinder's cover (the frame) as hard, back
                add(0, -f[0], -f[1], x, y)
        if self.indicator is not None:
            piston, i = self.indicator
            fx, fy, _, _ = indicator_force(self.scene, motion)
            x, y = P[piston]
            add(i, fx, fy, x, y)
            add(0, -fx, -fy, x, y)
        pins, guides = [], []
        effort = second = None
        for st, fn, first in self.steps:
            try:
                t = fn(P, S, pins, guides)
            except Singular as exc:
                from ..common.errors import PolygonMethodError
                raise PolygonMethodError(f"forces: {exc}: the pin forces are not determined "
                                         f"here (step {st.index + 1}, {st.title})",
                                         file=self.scene.file) from None
            if t is not None:
                if first:
                    effort = t
                else:
                    second = t
        return inertia, pins, guides, effort, second, S.of(0)


def records(inertia, pins, guides) -> tuple:
    """(:class:`~.records.Inertia` s, :class:`~.records.PinForce` s,
    :class:`~.records.GuideForce` s) from :meth:`ForcePlan.run`'s raw tuples."""
    from .bodies import inertia_record
    return (tuple(inertia_record(*r) for r in inertia),
            tuple(PinForce(*p) for p in pins),
            tuple(GuideForce(*g) for g in guides))


_PLANS: dict = {}  # id(scene) -> (weak reference to the scene, plan, ForcePlan)


def force_plan(scene, plan) -> ForcePlan:
    """The :class:`ForcePlan` of ``scene`` on ``plan``, made once while the scene lives
    (its refusal, for a plan the analysis does not cover, raised on every call)."""
    ident = id(scene)
    hit = _PLANS.get(ident)
    if hit is not None and hit[0]() is scene and hit[1] is plan:
        return hit[2]
    fp = ForcePlan(scene, plan)
    try:
        ref = weakref.ref(scene, lambda r, ident=ident: _forget(r, ident))
    except TypeError:  # a scene that takes no weak reference: not kept
        return fp
    _PLANS[ident] = (ref, plan, fp)
    return fp


def _forget(ref, ident):
    hit = _PLANS.get(ident)
    if hit is not None and hit[0] is ref:
        del _PLANS[ident]
