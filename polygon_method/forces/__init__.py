"""The force analysis (static and inertia forces) on the kinematic plan, the textbook's
chapter after the velocity and acceleration polygons.

D'Alembert: each massive body carries its inertia force ``-m a_G`` at its centre of mass G
and the couple ``-I alpha`` (:mod:`.bodies`); with its weight and the scene's loads the
mechanism is then in equilibrium at the instant, and the pin forces follow group by group
in the reverse order of the kinematic plan, each group statically determinate: a dyad's
two links (:mod:`.dyad`), a link with its block on a guide (:mod:`.slider`), a block on
a slotted lever with the lever (:mod:`.slotted`), and last
the driver: the crank, whose moments give the driving torque (:mod:`.crank`; a second
driving crank the same, in its place: its own torque), or a driving block, whose force
balance gives the driver's force along its guide (:mod:`.driver`). A point carried on a link
needs no step of its own: its loads and the pins there act on the link.

A hydraulic cylinder is a two-force member (:mod:`.cylinder`); where the motion is given
on it, it is the driver and its force the driver's effort.

A wheel rolling on a fixed line is solved with the link that finds its centre
(:mod:`.wheel`): the ground's normal and tangential forces, and the friction no slip needs;
a wheel that drives the mechanism by its driver's torque (:mod:`.wheel_driver`). A gear,
or a planet on a circle, carries the tooth load along the line of action at the pressure
angle (:mod:`.rolling`); a rack likewise, held by its guide (:mod:`.rack`).

A triad's plate and three links are solved together (:mod:`.triad`: the textbook's 3x3
solve). A collar driven along its turning rod is solved with the rod and the link it is
pinned to, its driver's force along the rod the effort (:mod:`.collar`); a collar driven
along the crank as the second input by its own balance (:mod:`.second_collar`).

With ``[friction]`` the walk is repeated with the friction of the forces found before (at
the guides ``mu |N|``, at the pins the friction circle) until they settle (:mod:`.friction`);
how they settled (the passes' contraction) goes into the forces' bounds.

What is not written yet is refused in one line naming the step (a triad whose plate is
three links): no guess.

Sign rule: see :mod:`.records` (the force on one body by the other; ccw positive; moments
about the frame's origin).
"""

from __future__ import annotations

from dataclasses import replace

from ..common.errors import PolygonMethodError
from . import (
    carried,
    collar,
    crank,
    cylinder,
    driver,
    dyad,
    friction,
    grip,
    peg,
    rack,
    rolling,
    second_collar,
    slider,
    slotted,
    triad,
    wheel,
    wheel_driver,
    yoke,
)
from .bodies import Ledger, Singular, centre, cross, gather
from .collar import second_name
from .core import force_plan
from .values import effort_value, force_value, holding_columns
from .rest import still
from .records import (
    FRAME,
    Contact,
    Couple,
    Forces,
    ForceStep,
    FreeBody,
    GuideForce,
    Inertia,
    PinForce,
    Side,
    block,
)
from .labels import couple_label, number_sub, side_label
from .json_entry import forces_dict

#: the force step of each kind of kinematic step: its room (``owns(st)``: the bodies its
#: points act on; ``step(st, P, ledger, owners)``: its pin forces; ``covers(st)``, where
#: present: whether it covers this step of its kind; ``check(st, plan)``, where present: why
#: the plan cannot be solved with it, or None; ``blocks(st)``, where present: the slider
#: blocks of its group, each a body a mass may sit on; ``divisor(st, rec, P, L)``, where
#: present: the length its equations divide by (:mod:`.bounds`); ``drives(scene, st)``,
#: ``unit_ledger(st)``, ``effort(st, t0, t1, ledger)``, where present: whether it drives
#: the mechanism, and its force from the crank's torque without it and with 1 N in it;
#: ``bodies(st)``, where present: the bodies it moves, in the order the sheet numbers them,
#: else those of its force step; ``bind(st, own, ix)``, where present: its short road
#: (:mod:`.core`), a function ``f(P, S, pins, guides)`` doing what ``step`` does to the
#: numbered sums ``S`` (three lists, Fx, Fy and M by the body's number ``ix(name)``:
#: ``bodies.sums_add``, ``bodies.sums_of``), appending its pin forces ``(point, on, by,
#: force)`` and guides' ``(point, normal, n, by)`` and returning the driver's effort or
#: None, with no record made; None for a step with nothing to solve)
#: the members a room may give, said once above for every room
ROOM_CONTRACT = (
    "owns",
    "step",
    "covers",
    "check",
    "blocks",
    "divisor",
    "drives",
    "unit_ledger",
    "effort",
    "bodies",
    "bind",
)
ROOMS = {
    "crank": crank,
    "dyad": dyad,
    "slider": slider,
    "carried": carried,
    "slotted": slotted,
    "block": driver,
    "second crank": crank,
    "cylinder": cylinder,
    "yoke": yoke,
    "peg": peg,
    "rolling": rolling,
    "wheel centre": wheel,
    "triad": triad,
    "rack": rack,
    "rolling driver": wheel_driver,
    "collar": collar,
    "second collar": second_collar,
}

__all__ = [
    "holding_columns",
    "analyse",
    "Forces",
    "Inertia",
    "PinForce",
    "GuideForce",
    "ForceStep",
    "FRAME",
    "block",
    "centre",
    "cross",
    "Ledger",
    "forces_dict",
    "owners",
    "ROOMS",
    "force_value",
    "effort_value",
    "Side",
    "Couple",
    "FreeBody",
    "side_label",
    "couple_label",
    "number_sub",
]

_NOT_YET: dict = {}  # kind -> the words of a kind the force analysis does not cover yet


def _refuse(scene, st, what):
    raise PolygonMethodError(
        f"forces: {what} is not solved for forces yet (step {st.index + 1}, {st.title}); "
        "the force analysis covers cranks (one or two), driving blocks, dyads, carried "
        "points, blocks on fixed paths and on moving links, slotted levers, yokes, pegs, "
        "cylinders, wheels rolling on a line (driven or driving), gears, planets, racks, "
        "collars on turning rods (driving, or the second input) and triads",
        file=scene.file,
        key=_key(scene),
    )


def _key(scene):
    """The table that asked for the force analysis."""
    return "[masses]" if scene.masses else "[gravity]"


def frame_links(scene) -> set:
    """The links with both ends on the ground: parts of the frame (a point carried on one
    is the frame's; a mass on one moves nothing)."""
    return {lk.key for lk in scene.links if lk.p in scene.ground and lk.q in scene.ground}


def owners(scene, plan) -> dict:
    """point -> the body a load or a later link's pin at that point acts on: the frame for
    a ground point, the crank for its tip, a dyad's first link for its point, the block
    for a slider's point, the link for a point carried on it. Refuses a plan with a step
    the force analysis does not cover."""
    own = {p: FRAME for p in scene.ground}
    fixed = frame_links(scene)
    blocks = set()
    for st in plan.steps:
        room = ROOMS.get(st.kind)
        if room is None or not getattr(room, "covers", lambda s: True)(st):
            _refuse(scene, st, _NOT_YET.get(st.kind, f"a {st.kind} step"))
        why = getattr(room, "check", lambda s, p: None)(st, plan)
        if why:
            _refuse(scene, st, why)
        own.update({p: FRAME if b in fixed else b for p, b in room.owns(st).items()})
        blocks.update(getattr(room, "blocks", lambda s: ())(st))
    for m in scene.masses:  # a mass on a block no group of the plan has
        if m.block and m.body not in blocks:
            raise PolygonMethodError(
                f"forces: {m.body} is a block no force step carries: its mass cannot be placed",
                file=scene.file,
                key=f"[masses] {m.body}",
            )
    return own


def analyse(motion) -> Forces:
    """The :class:`Forces` at the instant of ``motion`` (a solved, one-instant
    :class:`~polygon_method.solver.kinematics.Motion` of a scene with masses or gravity), or
    over its crank angles (a sweep: arrays). The numbers by the short road where every
    group has one (:mod:`.core`), the records when first read. With ``[friction]`` the
    walk is repeated with the friction of the forces found before until they settle
    (:mod:`.friction`)."""
    scene, plan = motion.scene, motion.plan
    fp = plan.force_plan  # made once per plan and scene (force_plan), kept on the plan
    if fp is not None and fp.fast and fp.scene is scene:  # the short road and nothing else
        return fp.run(motion)
    if scene.at_rest:  # the weights and loads alone, no inertia: nothing moves
        motion = still(motion)
    if fp is None or fp.scene is not scene:
        fp = force_plan(scene, plan)
    if scene.friction is not None:
        return _with_friction(motion, fp)
    if not fp.quick:
        return _forces(motion, fp, ())
    return fp.run(motion)


class _Long:
    """The records of the long road, made at once (the ``source`` of its :class:`Forces`:
    ``(_Long, the long road's tuple)``)."""

    @staticmethod
    def parts(source) -> tuple:
        return source[1][7:10]

    @staticmethod
    def story(source) -> tuple:
        return source[1][10:14]

    @staticmethod
    def resultant(source, body) -> tuple:
        return source[1][14](body)


def _with_friction(motion, fp) -> Forces:
    """The forces with the friction of the forces found before, until they settle (over a
    sweep, the forces near a limit position may grow past a float's range: quietly)."""
    if isinstance(motion.theta, float):
        return _passes(motion, fp)
    import numpy as np

    with np.errstate(all="ignore"):
        return _passes(motion, fp)


def _passes(motion, fp) -> Forces:
    """The walk repeated with the friction of the forces found before, until they settle."""
    scene = motion.scene
    before = last = None
    history = []  # the forces' largest changes from pass to pass (the bounds' estimate)
    moved = []  # the friction loads' (the first pass's: their size)
    n, limit = 0, friction.ROUNDS
    while True:
        f = _forces(motion, fp, before or ())
        now = friction.loads(scene, motion, f.pins, f.guides)
        if last is not None:
            history.append(friction.largest_changes(last, f))
        d = friction.change(before, now) if before is not None else friction.size(now)
        moved.append(d)
        scale = friction.scale(f)
        target = friction.SETTLED * scale
        if d <= target:
            settled = friction.settling(history, scale, moved)
            return replace(f, settling=settled)
        before, last, n = now, f, n + 1
        if n >= limit:  # still settling, near locking: as many passes as that takes
            limit, r = friction.more_rounds(moved, target, n)
            if limit <= n:
                break
    slow = f" (their change shrinking only {r:.4g} a pass)" if r < 1.0 else ""
    raise PolygonMethodError(
        f"forces: with friction the forces do not settle after {n} passes{slow}: the "
        "mechanism locks itself here, or nearly (the friction too large for the driver to "
        "move it)",
        file=scene.file,
        key="[friction]",
    )


def _forces(motion, fp, fric) -> Forces:
    """The long road's :class:`Forces`, with the friction loads ``fric`` known
    (:func:`.friction.loads`)."""
    whole = _long(motion, fp, fric)
    wheel = whole[4] == "wheel"
    return Forces(
        *whole[:7],
        (_Long, whole),
        centre_force=(wheel_driver.centre_force(motion.plan.steps[0], whole[0]) if wheel else None),
        friction=tuple(fric),
        friction_power=friction.power(motion, motion.scene, fric) if fric else 0.0,
    )


def _long(motion, fp, fric=()) -> tuple:
    """The long road, every record made: (the effort, shaking force, shaking moment, the
    driver's name and kind, a second crank's torque and link; inertia, pins, guides;
    steps, applied, contacts, the drawings' functions; body -> its known resultant).
    ``fric``: the friction loads."""
    scene, plan, own = motion.scene, motion.plan, fp.own
    records_, led = gather(scene, motion, own)
    cylinder.stated(scene, motion, led)  # a force given in a passive cylinder
    friction.apply(led, fric)
    inp = scene.input
    driving = fp.driving
    if driving is not None:  # the walk is linear in the driver's force: walk it twice
        room = ROOMS[driving.kind]
        t0 = _walk(scene, plan, motion.P, _copy(led), own)[3]
        t1 = _walk(scene, plan, motion.P, room.unit_ledger(driving), own)[3]
        try:
            room.effort(driving, t0, t1, led)
        except Singular as exc:
            raise PolygonMethodError(
                f"forces: {exc}: its force is not determined here (step "
                f"{driving.index + 1}, {driving.title})",
                file=scene.file,
            ) from None
    pins, guides, steps, torque, second, contacts = _walk(scene, plan, motion.P, led, own)
    contacts = grip.attach(contacts, motion, plan)  # a friction drive's: holds or slips
    fx, fy, m = led.of(FRAME)  # the drivers' reactions are the frame's too
    if driving is not None:
        name, kind, effort = driving.key, driving.kind, led.given[driving.key]
    elif plan.steps[0].kind in ("block", "collar"):  # a driving block, or a collar
        name, kind, effort = block(plan.steps[0].point), plan.steps[0].kind, torque
    elif plan.steps[0].kind == "rolling driver":  # a wheel: the torque on it
        name, kind, effort = plan.steps[0].wheel, "wheel", torque
    else:
        name, kind, effort = inp.crank, "crank", torque
    return (
        effort,
        (fx, fy),
        m,
        name,
        kind,
        second,
        second_name(scene, plan),
        records_,
        tuple(pins),
        tuple(guides),
        tuple(steps),
        {k: tuple(v) for k, v in led.applied.items()},
        tuple(contacts),
        _drawing(
            scene,
            plan,
            motion.P,
            records_,
            pins,
            guides,
            led,
            torque,
            steps,
            contacts,
            _second_torque(scene, plan, second),
        ),
        led.of,
    )


def _second_torque(scene, plan, second):
    """(a second driving crank, its torque) for its free body, or None (a second collar's
    effort is a force, drawn on the collar)."""
    two = second_name(scene, plan)
    return None if two is None or two.startswith("block ") else (two, second)


def _drawing(scene, plan, P, records, pins, guides, led, torque, steps, contacts, second=None):
    """What the drawings read, made when first asked for: the bodies' numbers and each
    body's free body (``second``: a second driving crank and its torque, or None)."""
    first = plan.steps[0]
    driven = scene.input.crank if first.kind != "rolling driver" else first.wheel
    push = None
    if first.kind == "block" and torque is not None:  # a driving block: its driver's force
        (ux, uy), x = first.path.u, first.point
        push = Side("driver", block(x), FRAME, x, (torque * ux, torque * uy), P[x])
    return (
        lambda: _numbers(scene, plan, steps),
        lambda numbers: _free_bodies(
            scene, P, numbers, records, pins, guides, led, torque, contacts, driven, push, second
        ),
    )


def _copy(led):
    """A ledger of the same known forces (the first walk must not change the one kept)."""
    out = Ledger()
    out.total = dict(led.total)
    out.stated = led.stated
    return out


def _walk(scene, plan, P, led, own):
    """The plan's steps in reverse, each group solved from ``led``: (pins, guides, force
    steps, the crank's torque, a second crank's torque)."""
    pins, guides, contacts, steps = [], [], [], []
    torque = second = None
    for st in reversed(plan.steps):
        try:
            p, g, rec, t = ROOMS[st.kind].step(st, P, led, own)
        except Singular as exc:
            raise PolygonMethodError(
                f"forces: {exc}: the pin forces are not determined here "
                f"(step {st.index + 1}, {st.title})",
                file=scene.file,
            ) from None
        pins += p
        for x in g:
            (contacts if isinstance(x, Contact) else guides).append(x)
        if rec is not None:
            steps.append(replace(rec, pins=tuple(p), guides=tuple(g)))
        if t is not None:  # the first input's torque (or force), or a second crank's
            if st is plan.steps[0]:
                torque = t
            else:
                second = t
    return pins, guides, steps, torque, second, contacts


def _numbers(scene, plan, steps) -> dict:
    """body -> its number as the books number links: the frame 1, then each body in the
    order the plan finds it (the crank 2); a room that does not name its bodies is read
    from its force step's (``steps``)."""
    solved = {rec.index: rec.bodies for rec in steps}
    fixed = frame_links(scene)
    out = {FRAME: 1}
    for st in plan.steps:
        room = ROOMS[st.kind]
        bodies = room.bodies(st) if hasattr(room, "bodies") else solved.get(st.index, ())
        for b in bodies:
            if b not in fixed and b not in out:
                out[b] = len(out) + 1
    return out


def _nonzero(x) -> bool:
    """Whether a value is to be drawn: a float that is not 0, or any array (a sweep)."""
    return x != 0 if isinstance(x, float) else True


def _free_bodies(
    scene, P, numbers, records, pins, guides, led, torque, contacts, driven, push=None, second=None
) -> tuple:
    """Each moving body alone (:class:`FreeBody`): its inertia force (the book's single
    force, through the offset point), weight and loads as the ledger holds them, every pin
    force on it (the stored record, or its opposite where the body is the record's ``by``),
    the guide's force on a block (and back on the guide's body, where that is solved with
    the block: a slotted lever, a yoke), a contact force (the ground's on a wheel, the
    teeth's on a gear or a rack, and back on the gear that pushes), a driving block's
    driver's force (``push``); its couples (``driven``: the body the driver's torque turns).
    Over a sweep the same records hold arrays (the inertia force at G with its couple)."""
    out = []
    for body, num in numbers.items():
        if body == FRAME:
            continue
        sides = [s for s in led.known(body) if s.what not in ("pin", "inertia", "contact")]
        sides[:0] = [
            Side("inertia", body, "", "", i.force, i.G if i.offset is None else i.offset_point)
            for i in records
            if i.body == body
        ]  # the book's single force
        for p in pins:
            if p.on == body:
                sides.append(Side("pin", body, p.by, p.point, p.force, P[p.point]))
            elif p.by == body:
                sides.append(
                    Side("pin", body, p.on, p.point, (-p.force[0], -p.force[1]), P[p.point])
                )
        sides += [
            Side("guide", body, g.by, g.point, g.force, P[g.point])
            for g in guides
            if block(g.point) == body
        ]
        had = {(s.point, s.by) for s in sides if s.what == "guide"}
        sides += [  # a guide's body solved with the block feels its force back
            Side("guide", body, block(g.point), g.point, (-g.force[0], -g.force[1]), P[g.point])
            for g in guides
            if g.by == body and (g.point, block(g.point)) not in had
        ]
        if push is not None and push.on == body:
            sides.append(push)
        for k, c in enumerate(reversed(contacts)):  # (in the plan's order, as drawn)
            name = "I" if len(contacts) == 1 else f"I{k + 1}"
            if c.wheel == body:
                sides.append(Side("contact", body, c.by, name, c.force, c.point))
            elif c.by == body:
                sides.append(
                    Side("contact", body, c.wheel, name, (-c.force[0], -c.force[1]), c.point)
                )
        couples = [
            Couple("inertia", body, i.couple)
            for i in records
            if i.body == body and i.offset is None and _nonzero(i.couple)
        ]
        couples += [
            Couple("friction", body, e[1], e[0].split()[-1])
            if e[0].startswith("friction")
            else Couple("load", body, e[1])
            for e in led.applied.get(body, ())
            if len(e) == 2
        ]
        couples += [
            Couple("guide", body, g.couple)
            for g in guides
            if block(g.point) == body and g.couple is not None and _nonzero(g.couple)
        ]
        if body == driven:
            couples.append(Couple("torque", body, torque))
        if second is not None and body == second[0]:
            couples.append(Couple("torque", body, second[1]))
        out.append(FreeBody(body, num, tuple(sides), tuple(couples)))
    return tuple(out)
