"""The flywheel of a machine driven at a steady speed (not an engine): a four-bar, a slider
crank press, any mechanism whose crank a motor turns, with masses on its links and loads on
them. The torque the crank needs at each angle, turning at the steady speed (the force
analysis's driving torque with inertia; without masses the loads' power balance), is the
machine's demand ``T``; the motor gives its mean ``T_mean`` all the time (the work per turn
over 2 pi). Where the motor gives more than the machine takes the flywheel gains energy:
``E(phi) = int_0^phi (T_mean - T) dphi``, the speed greatest where E is, least where E is
least, and ``dE_max = E_max - E_min``; the flywheel ``I = dE_max / (w^2 Cs)`` as for an
engine (:mod:`.flywheel` does the integration, the crossings and the arithmetic: here only
the torque over the turn and the words).

The turn runs from the crank at 0 deg (from +x) in its sense of rotation.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..common.errors import PolygonMethodError
from ..motion.sweeps import sweep
from ..solver.compiler import compile_plan
from ..solver.tracking import Sweeper

__all__ = ["MachineCycle", "machine_cycle", "machine_moments_at", "machine_asks"]


@dataclass(frozen=True)
class MachineCycle:
    """A machine's turn (see the module): it starts at the crank's angle ``theta_i`` (rad
    from +x) in the sense ``sg`` (+1 ccw); ``esign`` = -1: the energy is the motor's mean
    less the demand. ``parts`` and ``many`` as an engine's cycle has them (none, one)."""

    crank: str
    sg: float
    theta_i: float = 0.0
    parts: tuple = ()
    many: bool = False
    words: str = ""
    machine: bool = True
    esign: float = -1.0


def machine_asks(scene) -> bool:
    """Whether the scene asks for a machine's flywheel: ``[flywheel]`` on a mechanism with
    masses or loads that is no engine (the caller has found no piston)."""
    return scene.flywheel is not None and bool(scene.masses or scene.loads)


def _refuse(scene, why):
    raise PolygonMethodError(f"a machine's flywheel needs {why}", file=scene.file, key="[flywheel]")


def machine_cycle(scene) -> MachineCycle:
    """The machine's turn, or its refusal in one line (a driver that is no crank turning at
    a steady speed, nothing to load it)."""
    if not (scene.masses or scene.loads):
        _refuse(scene, "masses ([masses]) or loads ([loads]) to make the crank's torque vary")
    inp = scene.input
    first = compile_plan(scene).steps[0]  # the driver (asked, not the scene read)
    if inp.second is not None or first.effort_key != "input_torque" or not first.periodic:
        _refuse(scene, "one crank driving the mechanism through whole turns (a motor's shaft)")
    if inp.omega is None or inp.omega == 0:
        _refuse(scene, 'the crank\'s steady speed in [input] (speed = "120 rpm")')
    if inp.alpha not in (None, 0.0):
        _refuse(
            scene,
            "the crank at a steady speed: its acceleration 0 in [input] (the flywheel "
            "holds it nearly steady; the fluctuation is what it leaves)",
        )
    dom = Sweeper(scene).domain
    if not dom.full_turn:
        _refuse(scene, "a crank that turns whole turns (this one stops at a limit position)")
    if dom.turns != 1 or dom.turn_only or dom.notes:  # (the torque is no turn's)
        _refuse(
            scene,
            "a motion that repeats every turn of the crank: "
            + (dom.notes[0] if dom.notes else f"this one repeats every {dom.turns} turns"),
        )
    sg = 1.0 if inp.omega > 0 else -1.0
    words = (
        f"a machine driven at a steady {abs(inp.omega) * 30 / math.pi:.6g} rpm: the torque "
        f"{inp.crank} needs at each angle, the motor's the mean"
    )
    return MachineCycle(inp.crank, sg, 0.0, (), False, words)


def machine_moments_at(scene, g: MachineCycle, phase) -> tuple:
    """((the crank, the torque it needs at each phase, N m in its sense of rotation),): the
    driving torque with inertia of the force analysis at each phase (rad from 0 deg), or the
    loads' power balance without masses."""
    phase = np.asarray(phase, dtype=float)
    theta = g.theta_i + g.sg * phase
    res = sweep(scene, theta)
    if len(res.theta) != len(theta):
        raise PolygonMethodError(
            "the machine's turn passes a position where it cannot be solved (a limit "
            "position): no torque over the turn",
            file=scene.file,
            key="[flywheel]",
        )
    if scene.has_forces:
        from ..forces import analyse  # lazy, as in the sweep's forces

        T = analyse(res).input_torque
    else:
        T = res.input_torque
    return ((g.crank, g.sg * np.broadcast_to(np.asarray(T, dtype=float), theta.shape)),)


def machine_lines(tm, scene) -> list:
    """A machine's words where an engine's lines speak of the inner dead centre and the
    areas above the mean: (the head line, the areas' line's head)."""
    basis = "with the inertia of the moving parts" if tm.inertia_included else "no masses"
    loads = " and the loads" if scene.loads else ""
    return [
        f"the crank's torque over a turn ({basis}{loads}; from the crank at 0 deg, in its "
        f"sense of rotation; {tm.words}; the flywheel gains where the motor's mean torque "
        "exceeds the torque the machine needs)",
        "  energy the flywheel gains (+) and gives (-) between the crossings of the mean, "
        "in order (J): ",
    ]
