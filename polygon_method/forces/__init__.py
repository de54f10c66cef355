"""The force analysis (static and inertia forces) on the kinematic plan, the textbook's
chapter after the velocity and acceleration polygons.

D'Alembert: each massive body carries its inertia force ``-m a_G`` at its centre of mass G
and the couple ``-I alpha`` (:mod:`.bodies`); with its weight and the scene's loads the
mechanism is then in equilibrium at the instant, and the pin forces follow group by group
in the reverse order of the kinematic plan, each group statically determinate: a dyad's
two links (:mod:`.dyad`), a link with its block on a fixed path (:mod:`.slider`), and last
the crank, whose moments give the driving torque (:mod:`.crank`). A point carried on a link
needs no step of its own: its loads and the pins there act on the link.

What is not written yet is refused in one line naming the step (a block on a moving guide,
a cylinder, rolling, a peg, a yoke, a triad, two inputs): no guess.

Sign rule: see :mod:`.records` (the force on one body by the other; ccw positive; moments
about the frame's origin).
"""

from __future__ import annotations

from ..errors import PolygonMethodError
from . import carried, crank, dyad, slider
from .bodies import Ledger, Singular, centre, cross, gather
from .records import (FRAME, Couple, Forces, ForceStep, FreeBody, GuideForce, Inertia,
                      PinForce, Side, block, couple_label, force_value, forces_dict,
                      number_sub, side_label)

#: the force step of each kind of kinematic step: its room (``owns(st)``: the bodies its
#: points act on; ``step(st, P, ledger, owners)``: its pin forces; ``covers(st)``, where
#: present: whether it covers this step of its kind)
ROOMS = {"crank": crank, "dyad": dyad, "slider": slider, "carried": carried}

__all__ = ["analyse", "Forces", "Inertia", "PinForce", "GuideForce", "ForceStep", "FRAME",
           "block", "centre", "cross", "Ledger", "forces_dict", "owners", "ROOMS",
           "force_value", "Side", "Couple", "FreeBody", "side_label", "couple_label", "number_sub"]

_NOT_YET = {
    "slider": "a block sliding on a moving link",
    "slotted": "a block sliding on a moving link",
    "cylinder": "a cylinder",
    "rolling": "rolling without slip",
    "wheel_centre": "a wheel's centre on a line",
    "rack": "a rack on a pinion",
    "peg": "a peg in slots",
    "yoke": "a yoke",
    "triad": "a triad (class-III group)",
    "second_crank": "a second driving crank",
}


def _refuse(scene, st, what):
    raise PolygonMethodError(
        f"forces: {what} is not solved for forces yet (step {st.index + 1}, {st.title}); "
        "the force analysis covers cranks, dyads, carried points and blocks on fixed paths",
        file=scene.file, key=_key(scene))


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
    if scene.input.second is not None:
        raise PolygonMethodError("forces: two driving cranks: one balance does not give "
                                 "two driving torques; the force analysis needs one input",
                                 file=scene.file, key=_key(scene))
    own = {p: FRAME for p in scene.ground}
    fixed = frame_links(scene)
    for st in plan.steps:
        room = ROOMS.get(st.kind)
        if room is None or not getattr(room, "covers", lambda s: True)(st):
            _refuse(scene, st, _NOT_YET.get(st.kind, f"a {st.kind} step"))
        own.update({p: FRAME if b in fixed else b for p, b in room.owns(st).items()})
    for m in scene.masses:  # a mass on a block the plan does not slide on a fixed path
        if m.block and own.get(m.body) != block(m.body):
            raise PolygonMethodError(f"forces: {m.body} is a block on no fixed path: its "
                                     "mass cannot be placed", file=scene.file,
                                     key=f"[masses] {m.body}")
    return own


def analyse(motion) -> Forces:
    """The :class:`Forces` at the instant of ``motion`` (a solved, one-instant
    :class:`~polygon_method.kinematics.Motion` of a scene with masses or gravity)."""
    scene, plan = motion.scene, motion.plan
    own = owners(scene, plan)
    records, led = gather(scene, motion, own)
    P = motion.P
    pins, guides, steps = [], [], []
    torque = None
    for st in reversed(plan.steps):
        try:
            p, g, rec, t = ROOMS[st.kind].step(st, P, led, own)
        except Singular as exc:
            raise PolygonMethodError(f"forces: {exc}: the pin forces are not determined here "
                                     f"(step {st.index + 1}, {st.title})",
                                     file=scene.file) from None
        pins += p
        guides += g
        if rec is not None:
            steps.append(rec)
        if t is not None:
            torque = t
    fx, fy, m = led.of(FRAME)
    one = isinstance(torque, float)  # the drawings' records, made when asked for
    drawing = (lambda: _numbers(scene, plan),
               (lambda numbers: _free_bodies(scene, P, numbers, records, pins, guides, led,
                                             torque)) if one else (lambda numbers: ()))
    return Forces(records, tuple(pins), tuple(guides), torque, (fx, fy), m - torque,
                  tuple(steps), {k: tuple(v) for k, v in led.applied.items()},
                  scene.input.crank, drawing)


def _numbers(scene, plan) -> dict:
    """body -> its number as the books number links: the frame 1, then each body in the
    order the plan finds it (the crank 2)."""
    fixed = frame_links(scene)
    out = {FRAME: 1}
    for st in plan.steps:
        for b in ROOMS[st.kind].bodies(st):
            if b not in fixed and b not in out:
                out[b] = len(out) + 1
    return out


def _free_bodies(scene, P, numbers, records, pins, guides, led, torque) -> tuple:
    """Each moving body alone (:class:`FreeBody`): its inertia force (the book's single
    force, through the offset point), weight and loads as the ledger holds them, every pin
    force on it (the stored record, or its opposite where the body is the record's ``by``),
    the guide's force on a block; its couples."""
    out = []
    for body, num in numbers.items():
        if body == FRAME:
            continue
        sides = [s for s in led.known(body) if s.what not in ("pin", "inertia")]
        sides[:0] = [Side("inertia", body, "", "", i.force,
                          i.G if i.offset is None else i.offset_point)
                     for i in records if i.body == body]  # the book's single force
        for p in pins:
            if p.on == body:
                sides.append(Side("pin", body, p.by, p.point, p.force, P[p.point]))
            elif p.by == body:
                sides.append(Side("pin", body, p.on, p.point, (-p.force[0], -p.force[1]),
                                  P[p.point]))
        sides += [Side("guide", body, FRAME, g.point, g.force, P[g.point]) for g in guides
                  if block(g.point) == body]
        couples = [Couple("inertia", body, i.couple) for i in records
                   if i.body == body and i.offset is None and i.couple != 0]
        couples += [Couple("load", body, e[1]) for e in led.applied.get(body, ())
                    if len(e) == 2]
        if body == scene.input.crank:
            couples.append(Couple("torque", body, torque))
        out.append(FreeBody(body, num, tuple(sides), tuple(couples)))
    return tuple(out)
