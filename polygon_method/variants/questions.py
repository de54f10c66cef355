"""What a class's answer key gives (a part of the variants' generator, :mod:`.`): the base
scene's ``[answers]`` keys, else every moving point's and link's motion, each in the SI
unit the key gives it."""

from __future__ import annotations

from ..common.units import ANSWER_UNITS
from ..linkage.cycle_values import CYCLE_SI
from ..linkage.engine_values import ENGINE_KEYS
from ..scene import Scene


def _unit_of(kind) -> str:
    """The SI unit a class's answer key gives an answer of ``kind`` in."""
    if kind in CYCLE_SI:  # a quick return's times, a stroke, a link's angle
        return CYCLE_SI[kind]
    return ANSWER_UNITS[kind] if kind in ANSWER_UNITS else ENGINE_KEYS[kind][1]


def questions(scene: Scene) -> tuple:
    """What the answer key gives: the base scene's ``[answers]`` keys where it has them
    (centres aside), else every moving point's speed and acceleration, every moving link's
    omega and alpha, each slider's sliding velocity and acceleration, the input torque.
    Each as (key, kind, names, unit, signed, the unit a question asks its answer in: "rpm"
    of ``omega_BC = "? rpm"``, else None). A key asked without its answer (``"?"``) is a
    question as any other: the base's values are never the variants'."""
    asked = [a for a in scene.answers if a.kind != "centre"]
    if asked:
        return tuple(
            (
                a.key,
                a.kind,
                tuple(a.names),
                _unit_of(a.kind),
                a.kind in ("omega", "alpha", "vs", "as", "torque", "torque2"),
                getattr(a, "unit", None),
            )
            for a in asked
        )
    out = []
    ground = set(scene.ground)
    for p in scene.point_names:
        if p not in ground:
            out.append((f"v_{p}", "v", (p,), "m/s", False, None))
    for p in scene.point_names:
        if p not in ground:
            out.append((f"a_{p}", "a", (p,), "m/s^2", False, None))
    from ..scene import split_name

    # the crank's omega is given, unless the scene gives the motion on another quantity
    crank = scene.input.crank if scene.input.given is None else None
    for lk in scene.links:
        if not (lk.p in ground and lk.q in ground) and lk.key != crank:
            out.append((f"omega_{lk.key}", "omega", split_name(lk.key), "rad/s", True, None))
    for lk in scene.links:
        if not (lk.p in ground and lk.q in ground) and lk.key != crank:
            out.append((f"alpha_{lk.key}", "alpha", split_name(lk.key), "rad/s^2", True, None))
    for s in scene.sliders:
        out.append((f"vs_{s.point}", "vs", (s.point,), "m/s", True, None))
        out.append((f"as_{s.point}", "as", (s.point,), "m/s^2", True, None))
    for p in scene.pins:
        out.append((f"rub_{p.point}", "rub", (p.point,), "m/s", False, None))
    if scene.loads:
        out.append(("torque", "torque", (), "N m", True, None))
    return tuple(out)
