"""The force solve's short road: planned once per scene, then only numbers.

What the force analysis needs from a scene and its kinematic plan is the same at every
instant: which body each point's forces act on (:func:`~polygon_method.forces.owners`),
each mass's body, centre (``lam``, ``mu`` on its link) and weight, each load's body, and
each group's bodies and points. :class:`ForcePlan` works all of that out once; its
:meth:`~ForcePlan.run` then adds the known forces on each body into numbered sums
(three lists, ``(Fx, Fy, M about the origin)`` by the body's number, the frame 0: the
same additions, in the same order, as the :class:`~polygon_method.forces.bodies.Ledger`
makes them; :func:`~.bodies.sums_add`, :func:`~.bodies.sums_of`) and calls each group's
equations (its room's ``solve``, the one place they are written) in the plan's reverse
order: the function each room's ``bind`` gives, on floats for one instant or on arrays
of crank angles for a sweep alike.

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

import functools
import weakref

from .bodies import THREE_PINS, Singular, centre, inertia_record, sums_add, sums_of
from .collar import second_name
from ..scene.link_loads import load_force
from .engine import indicator_forces
from .records import FRAME, Forces, GuideForce, PinForce, block

__all__ = ["ForcePlan", "force_plan"]


class Numbering:
    """body name -> its number in the sums (the frame 0), given as first asked."""

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
    has its short road; ``fast``: that, and the scene neither at rest nor with friction
    (its forces are :meth:`run` alone); ``driving``: a step that drives the mechanism by a force found
    from the walk (a cylinder), or None."""

    def __init__(self, scene, plan):
        from . import ROOMS, owners  # the rooms (this module is one of their helpers)

        self.scene, self.plan = scene, plan
        self.own = own = owners(scene, plan)  # refuses what the analysis does not cover
        self.driving = next(
            (
                st
                for st in plan.steps
                if getattr(ROOMS[st.kind], "drives", lambda sc, s: False)(scene, st)
            ),
            None,
        )
        self.quick = self.driving is None and all(
            hasattr(ROOMS[st.kind], "bind") for st in plan.steps
        )
        # the short road and nothing about it: not at rest, no friction
        self.fast = self.quick and not scene.at_rest and scene.friction is None
        if not self.quick:
            return
        ix = Numbering()
        self._masses(scene, ix)
        self._loads(scene, own, ix)
        first = plan.steps[0]
        bound = ((st, ROOMS[st.kind].bind(st, own, ix), st is first) for st in reversed(plan.steps))
        self.steps = tuple(b for b in bound if b[1] is not None)  # skip what solves nothing
        self.zeros = [0.0] * len(ix.index)
        self.index = ix.index
        inp = scene.input
        if first.kind in ("block", "collar"):  # the driver the plan starts with: a block
            self.driver = (block(first.point), first.kind)
        else:
            self.driver = (inp.crank, "crank")
        self.second = second_name(scene, plan)

    def _masses(self, scene, ix):
        """Each mass, in the scene's order as :func:`~.bodies.gather` takes them, as what
        the hot loop reads (body number, a block's point or None, its link's ends and key,
        lam, mu, ``-m``, ``-I``, its weight or None) and, beside it, what only its record
        reads (body, m, I, how)."""
        grav = scene.gravity
        fixed = {lk.key for lk in scene.links if lk.p in scene.ground and lk.q in scene.ground}
        hot, cold = [], []
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
            # -m a_G and -I alpha with -m and -I taken once: the same products
            hot.append((ix(body), *where, body, m.lam, m.mu, -m.mass, -m.inertia, weight))
            cold.append((body, m.mass, m.inertia, m.how))
        self.masses, self.mass_records = tuple(hot), tuple(cold)
        # what run reads: a link's masses, then a block's (a body is a link or a block,
        # never both, so the sums are added to in each body's own order)
        self.on_links = tuple(
            h[:1] + h[2:9] + (h[9] or (None, None)) for h in hot if h[1] is None
        )  # (i, p, q, key, lam, mu, -m, -I, weight x, weight y or None, None)
        self.on_blocks = tuple((h[0], h[1], h[7], h[8], h[9]) for h in hot if h[1] is not None)

    def _loads(self, scene, own, ix):
        """Each load as (body number or None for a couple's, point, force or couple, gas);
        the indicator's piston and its body's number."""
        out = []
        for ld in scene.loads:
            if ld.force is not None:
                body = own.get(ld.target, FRAME)
                if body == FRAME:
                    continue
                out.append((ix(body), ld.target, ld.force if ld.across is None else ld, ld.gas))
            else:
                out.append((None, ix(ld.target), ld.torque, None))
        self.loads = tuple(out)
        self.indicators = tuple(ix(own.get(i.piston, FRAME)) for i in scene.indicators)

    def run(self, motion):
        """The :class:`~.records.Forces` at ``motion``'s instant (or over its angles): its
        numbers (the effort, the shaking force and moment: the frame's sums); its records
        made when first read, from the raw pin and guide forces kept."""
        P, A, Al = motion.P, motion.A, motion.Al
        z = self.zeros  # the sums: (Fx, Fy, M) by the body's number, three lists
        S = (sx, sy, sm) = (z[:], z[:], z[:])
        for i, p, q, body, lam, mu, nm, ni, wx, wy in self.on_links:  # G, a_G: as centre
            (px, py), (qx, qy) = P[p], P[q]
            dx, dy = qx - px, qy - py
            gx, gy = px + lam * dx - mu * dy, py + lam * dy + mu * dx
            (px, py), (qx, qy) = A[p], A[q]
            dx, dy = qx - px, qy - py
            fx = nm * (px + lam * dx - mu * dy)  # -m a_G
            fy = nm * (py + lam * dy + mu * dx)
            # sums_add(S, i, fx, fy, gx, gy), the couple -I alpha, the weight's: in order
            if wx is None:
                sx[i] = sx[i] + fx
                sy[i] = sy[i] + fy
                sm[i] = sm[i] + (gx * fy - gy * fx) + ni * Al[body]
            else:
                sx[i] = sx[i] + fx + wx
                sy[i] = sy[i] + fy + wy
                sm[i] = sm[i] + (gx * fy - gy * fx) + ni * Al[body] + (gx * wy - gy * wx)
        for i, pt, nm, ni, weight in self.on_blocks:  # a block: its point, no turning
            (gx, gy), (ax, ay) = P[pt], A[pt]
            fx, fy = nm * ax, nm * ay
            sx[i] = sx[i] + fx
            sy[i] = sy[i] + fy
            sm[i] = sm[i] + (gx * fy - gy * fx) + ni * 0.0
            if weight is not None:
                fx, fy = weight
                sx[i] = sx[i] + fx
                sy[i] = sy[i] + fy
                sm[i] = sm[i] + (gx * fy - gy * fx)
        for i, target, f, gas in self.loads:
            if i is None:  # a couple on a link: added to its moment
                sm[target] = sm[target] + f
                continue
            x, y = P[target]
            fx, fy = f if isinstance(f, tuple) else load_force(f, P)  # (turning with a link)
            sx[i] = sx[i] + fx  # sums_add(S, i, fx, fy, x, y)
            sy[i] = sy[i] + fy
            sm[i] = sm[i] + (x * fy - y * fx)
            if gas:  # the gas pushes the cylinder's cover (the frame) as hard, back
                sums_add(S, 0, -fx, -fy, x, y)
        if self.indicators:
            for i, (piston, fx, fy, _) in zip(
                self.indicators, indicator_forces(self.scene, motion)
            ):
                x, y = P[piston]
                sums_add(S, i, fx, fy, x, y)
                sums_add(S, 0, -fx, -fy, x, y)
        pins, guides = [], []
        effort = second = None
        for st, fn, first in self.steps:
            try:
                t = fn(P, S, pins, guides)
            except Singular as exc:
                raise self._singular(st, exc) from None
            if t is not None:
                if first:
                    effort = t
                else:
                    second = t
        # the record's fields put straight into its dictionary (its frozen __init__ sets
        # them one by one through object.__setattr__: three times as long)
        f = _new(Forces)
        d = f.__dict__
        d["input_torque"] = effort
        d["shaking_force"] = (sx[0], sy[0])
        d["shaking_moment"] = sm[0]
        d["crank"], d["driver"] = self.driver
        d["second_torque"] = second
        d["second_crank"] = self.second
        d["source"] = (self, motion, pins, guides, S)
        return f

    def _singular(self, st, exc):
        """The one-line error of a group whose pin forces are not determined."""
        from ..common.errors import PolygonMethodError

        return PolygonMethodError(
            f"forces: {exc}: the pin forces are not determined "
            f"here (step {st.index + 1}, {st.title})",
            file=self.scene.file,
        )

    # what its :class:`~.records.Forces` asks of its ``source``, (this plan, the motion, the
    # raw pin and guide forces, the sums), when first read

    def parts(self, source) -> tuple:
        """(inertia, pins, guides) records (:meth:`records`)."""
        return self.records(*source[1:4])

    def story(self, source) -> tuple:
        """(steps, applied, contacts, the drawings' functions): the long road's."""
        from . import _long  # the walk with its words (this module is one of its helpers)

        return _long(source[1], self)[10:14]

    def resultant(self, source, body) -> tuple:
        """``body``'s resultant in the sums (zero for a body with none)."""
        i = self.index.get(body)
        return (0.0, 0.0, 0.0) if i is None else sums_of(source[4], i)

    def records(self, motion, pins, guides) -> tuple:
        """(:class:`~.records.Inertia` s, :class:`~.records.PinForce` s,
        :class:`~.records.GuideForce` s) from :meth:`run`'s raw tuples; each mass's G and
        a_G found again from ``motion`` as :meth:`run` found them (the same arithmetic)."""
        P, A, Al = motion.P, motion.A, motion.Al
        inertia = []
        for (_, pt, p, q, key, lam, mu, _, _, _), (body, mass, moment, how) in zip(
            self.masses, self.mass_records
        ):
            if pt is None:
                G, a_G, alpha = centre(P, lam, mu, p, q), centre(A, lam, mu, p, q), Al[key]
            else:
                G, a_G, alpha = P[pt], A[pt], 0.0
            inertia.append(inertia_record(body, mass, moment, G, a_G, alpha, how))
        return tuple(inertia), pin_forces(pins), tuple(GuideForce(*g) for g in guides)


def pin_forces(pins) -> tuple:
    """The :class:`~.records.PinForce` s of :meth:`ForcePlan.run`'s raw pin entries, in
    order: an entry whose first item is a head (a tuple) is a dyad's three pins
    (``THREE_PINS`` first) or one pin kept negated (``NEGATED_PIN``: a crank's pivot)."""
    out = []
    for p in pins:
        head = p[0]
        if head.__class__ is not tuple:
            out.append(PinForce(*p))
        elif head[0] is THREE_PINS:
            _, c, l1, l2, b, ob, d, od = head
            _, px, py, ex, ey, gx, gy = p
            out.append(PinForce(c, l1, l2, (px, py)))
            out.append(PinForce(b, l1, ob, (-ex, -ey)))
            out.append(PinForce(d, l2, od, (-gx, -gy)))
        else:  # NEGATED_PIN
            _, point, on, by = head
            out.append(PinForce(point, on, by, (-p[1], -p[2])))
    return tuple(out)


_new = object.__new__
_PLANS: dict = {}  # id(scene) -> (weak reference to the scene, plan, ForcePlan)


def force_plan(scene, plan) -> ForcePlan:
    """The :class:`ForcePlan` of ``scene`` on ``plan``, made once while the scene lives
    (its refusal, for a plan the analysis does not cover, raised on every call)."""
    ident = id(scene)
    hit = _PLANS.get(ident)
    if hit is not None and hit[0]() is scene and hit[1] is plan:
        return hit[2]
    fp = ForcePlan(scene, plan)
    if plan.scene is scene:  # kept on the plan too: analyse reads it there, without a call
        object.__setattr__(plan, "force_plan", fp)
    try:
        ref = weakref.ref(scene, functools.partial(_forget, ident=ident))
    except TypeError:  # a scene that takes no weak reference: not kept
        return fp
    while len(_PLANS) >= _KEEP:  # the force plan holds its scene: bounded, or none would go
        _PLANS.pop(next(iter(_PLANS)))
    _PLANS[ident] = (ref, plan, fp)
    return fp


#: the force plans kept at once (a class's worth of scenes)
_KEEP = 256


def _forget(ref, ident, plans=_PLANS):
    """A scene has gone: drop its force plan (the table bound at definition, so that a
    scene collected while the interpreter shuts down finds it still)."""
    hit = plans.get(ident)
    if hit is not None and hit[0] is ref:
        del plans[ident]
