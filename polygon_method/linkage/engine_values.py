"""The engine chapter's answers, exactly: the piston effort, the crank effort, the turning
moment, the thrusts and the shaking force at the instant, and over the cycle the mean
torque, the maximum fluctuation of energy and the flywheel; read by ``check`` (each answer
against it) and ``variants`` (each variant's key)."""

from __future__ import annotations

import math

from ..common.tolerances import SAME
from ..forces.engine import cylinder_efforts, efforts
from ..motion.solution import solve
from ..scene.answers import ENGINE_PER_PISTON as PER_PISTON
from .flywheel import turning_moment
from .rod_system import ROD_KEYS, rod_value

__all__ = ["ENGINE_KEYS", "INSTANT", "PER_PISTON", "engine_dict", "engine_value", "split_key"]

#: answer key -> (unit kind, SI unit, what it is)
ENGINE_KEYS = {
    "piston_effort": ("force", "N", "the piston effort"),
    "crank_effort": ("force", "N", "the crank effort"),
    "turning_moment": ("torque", "N m", "the turning moment on the crank shaft"),
    "T_mean": ("torque", "N m", "the mean turning moment"),
    "dE_max": ("energy", "J", "the maximum fluctuation of energy"),
    "I_flywheel": ("moment_of_inertia", "kg m^2", "the flywheel's moment of inertia"),
    "m_flywheel": ("mass", "kg", "the flywheel's mass"),
    "rod_thrust": ("force", "N", "the thrust in the connecting rod"),
    "side_thrust": ("force", "N", "the side thrust on the cylinder walls"),
    "shaking_force": ("force", "N", "the shaking force on the frame"),
    "shaking_moment": ("torque", "N m", "the shaking moment about the frame's origin"),
    **ROD_KEYS,  # the connecting rod's equivalent dynamical system (rod_system.py)
}
#: the keys read from the force analysis at the instant (the rest from the cycle)
INSTANT = (
    "piston_effort",
    "crank_effort",
    "turning_moment",
    "rod_thrust",
    "side_thrust",
    "shaking_force",
    "shaking_moment",
)


def split_key(key) -> tuple:
    """(the engine key, the piston or None) of an answer key: ``piston_effort_B`` ->
    ("piston_effort", "B"); a key of the whole engine -> (key, None); else (None, None).

    >>> split_key("crank_effort_B1"), split_key("T_mean"), split_key("v_B")
    (('crank_effort', 'B1'), ('T_mean', None), (None, None))
    """
    if key in ENGINE_KEYS:
        return key, None
    base, _, piston = key.rpartition("_")
    return (base, piston) if base in PER_PISTON and piston else (None, None)


def _effort(e, key):
    return {
        "piston_effort": e.F_P,
        "crank_effort": e.F_T,
        "turning_moment": e.T,
        "rod_thrust": e.F_Q,
        "side_thrust": e.F_N,
    }[key]


def engine_value(sol, key, scene=None):
    """The exact value of ``key`` for ``scene`` (default the solution's), or None where the
    scene cannot give it (a piston's own key, ``piston_effort_B``: that cylinder's)."""
    sc = scene or sol.scene
    key, piston = split_key(key)
    if key in ROD_KEYS:  # the rod's equivalent dynamical system (sizes, as the rest)
        return abs(rod_value(sol if scene is None else solve(sc), key, piston))
    if key in INSTANT:
        s = sol if scene is None else solve(sc)
        if not sc.has_forces:
            return None
        if key == "shaking_force":
            return math.hypot(*s.forces.shaking_force)
        if key == "shaking_moment":
            return s.forces.shaking_moment
        e = efforts(sc, s.plan, s.P, s.forces)
        if e is None:  # several cylinders on one crank: each one's, or the turning moment
            cs = cylinder_efforts(sc, s.plan, s.P, s.forces)
            if piston is not None:
                c = next((c for c in cs if c.piston == piston), None)
                return None if c is None else abs(_effort(c, key))
            return abs(sum(c.T for c in cs)) if cs and key == "turning_moment" else None
        if piston is not None and piston != e.piston:
            return None
        return abs(_effort(e, key))
    tm = turning_moment(sc)
    if key == "T_mean":  # a mean within rounding of nought (SAME of the greatest) is nought
        return tm.mean if abs(tm.mean) > SAME * max(abs(tm.T_max), abs(tm.T_min)) else 0.0
    if key == "dE_max":
        return tm.dE_max
    if tm.flywheel is None:
        return None
    return tm.flywheel[2] if key == "I_flywheel" else tm.flywheel[3]


def engine_dict(sol) -> dict | None:
    """The JSON of an engine's efforts at the instant (``solve --json``'s ``engine``; SI,
    each effort signed as ``solve`` prints it: the piston effort towards the crank, the
    crank effort and turning moment in the sense of rotation): one cylinder's, or of several
    on one crank each one's under ``cylinders`` and the turning moment of them all; None for
    a scene that is no engine (or whose forces are refused)."""
    sc = sol.scene
    if not sc.has_forces or sol.forces_refused:
        return None

    def one(e):
        return {
            "piston": e.piston,
            "rod": e.rod,
            "piston_effort": float(e.F_P),
            "rod_thrust": float(e.F_Q),
            "side_thrust": float(e.F_N),
            "crank_effort": float(e.F_T),
            "turning_moment": float(e.T),
        }

    e = efforts(sc, sol.plan, sol.P, sol.forces)
    if e is not None:
        return one(e)
    cs = cylinder_efforts(sc, sol.plan, sol.P, sol.forces)
    if not cs:
        return None
    return {"cylinders": [one(c) for c in cs], "turning_moment": float(sum(c.T for c in cs))}
