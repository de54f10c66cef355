"""The engine chapter's answer keys: the piston effort and the crank effort at the instant,
and over the cycle the mean torque, the maximum fluctuation of energy and the flywheel
(its moment of inertia, its rim's mass); with the classic slips each solved again as the
slip would have it.

They are computed answers (no drawing to read): the tolerance is the answers' own, or
three significant figures.
"""

from __future__ import annotations

import math
from dataclasses import replace

from ..common.numbers import textbook
from ..common.tolerances import FLOOR, SAME
from ..common.errors import PolygonMethodError, SceneError
from ..forces.engine import efforts, engine_piston, engine_pistons, slider_crank
from ..linkage.engine_values import ENGINE_KEYS, INSTANT as _INSTANT, engine_value, split_key
from ..scene.answers import ENGINE_PER_PISTON
from ..scene.force_records import Friction
from ..linkage.flywheel import turning_moment
from ..linkage.rod_system import ROD_KEYS
from .rod_keys import rod_slips
from .verdicts import ROUNDING, Verdict, cs_slips

__all__ = ["ENGINE_KEYS", "engine_value", "engine_verdict"]


def _refuse(sol, ans, why):
    raise SceneError(f"{ans.key}: {why}", key=f"[answers] {ans.key}", line=ans.line)


def _slips(sol, full, correct):
    """(value, code, words) of each classic slip for the answer key ``full`` (a piston's
    own, ``piston_effort_B``: its cylinder's, the pistons' inertia left out)."""
    sc = sol.scene
    out = []
    key, piston = split_key(full)
    if key in ROD_KEYS:  # the rod's equivalent dynamical system: its own slips
        return rod_slips(sol, key, piston)
    fr = sc.friction
    if fr is not None and fr.active and key in _INSTANT:
        try:  # the books' F_P = F_L - F_I - R_F: the friction's part left out
            v = engine_value(sol, full, replace(sc, friction=Friction(0.0, 0.0)))
        except PolygonMethodError:
            v = None
        if v is not None:
            out.append(
                (
                    abs(v),
                    "friction_left_out",
                    "the friction left out (the guides' mu F_N against the piston's sliding, "
                    "the pins' friction circles)",
                )
            )
    blocks = [m for m in sc.masses if m.block]
    if piston is not None:  # one cylinder's: its piston's inertia (the others' touch it not)
        blocks = [m for m in blocks if m.body == piston]
    if blocks and key != "T_mean":  # (the inertia averages nothing over a cycle)
        try:
            if piston is not None:
                v = engine_value(
                    sol, full, replace(sc, masses=tuple(m for m in sc.masses if m not in blocks))
                )
            elif key in ("piston_effort", "crank_effort", "turning_moment"):
                v = _gas_alone(sol, key)
            elif key in ("rod_thrust", "side_thrust"):
                v = None  # (the closed forms give these from the piston effort alone)
            else:
                v = engine_value(
                    sol, key, replace(sc, masses=tuple(m for m in sc.masses if not m.block))
                )
        except PolygonMethodError:
            v = None
        if v is not None:
            out.append(
                (
                    abs(v),
                    "piston_inertia_left_out",
                    "the inertia of the reciprocating parts at "
                    f"{', '.join(m.body for m in blocks)} left out"
                    + (" (their mass, and its weight)" if piston and sc.gravity else ""),
                )
            )
    if key in ("I_flywheel", "m_flywheel") and sc.flywheel is not None:
        out += cs_slips(correct)
    if key in ("dE_max", "I_flywheel", "m_flywheel"):
        tm = turning_moment(sc)
        if tm.lobes:
            big = max(abs(lb.energy) for lb in tm.lobes)
            if abs(big - tm.dE_max) > SAME * tm.dE_max:
                f = big / tm.dE_max
                out.append(
                    (
                        correct * f,
                        "largest_area",
                        "the largest single area between the turning moment and its mean "
                        "taken for the fluctuation of energy: dE_max = E_max - E_min, the "
                        "energies at the crossings summed in order",
                    )
                )
    if key == "T_mean" and sc.indicators and sc.indicators[0].cycle > 2 * math.pi + 1:
        out.append(
            (
                2 * correct,
                "one_turn_cycle",
                "the work of a four-stroke cycle divided by one turn (2 pi) instead of two (4 pi)",
            )
        )
    return out


def _gas_alone(sol, key):
    """The piston or crank effort from the gas force alone (the closed forms, without the
    reciprocating parts' inertia)."""
    sc = sol.scene
    e = efforts(sc, sol.plan, sol.P, sol.forces)
    if e is None:  # (several cylinders: their pistons' inertia left out, below)
        return engine_value(
            sol, key, replace(sc, masses=tuple(m for m in sc.masses if not m.block))
        )
    blk = next(i for i in sol.forces.inertia if i.body == f"block {e.piston}")
    _, sd = slider_crank(sol.plan, e.piston)
    fx, fy = blk.force
    ux, uy = sd.path.u
    (bx, by), (ox, oy) = sol.P[e.piston], sol.P[sol.plan.steps[0].pivot]
    side = 1.0 if (bx - ox) * ux + (by - oy) * uy >= 0 else -1.0
    toward = -side * (fx * ux + fy * uy)  # the inertia force towards the crank
    F_P = e.F_P - toward
    if key == "piston_effort":
        return F_P
    return (e.T if key == "turning_moment" else e.F_T) * F_P / e.F_P if e.F_P else None


def _correct(sol, ans) -> float:
    """The right value of the engine chapter's answer ``ans``, or the answer refused (a
    :class:`SceneError` naming it) where the scene cannot give it."""
    key = ans.kind
    if key in _INSTANT and not sol.scene.has_forces:
        _refuse(
            sol,
            ans,
            (
                "the engine's efforts"
                if "thrust" in key or "effort" in key or key == "turning_moment"
                else "the shaking force and moment"
            )
            + " need the force analysis: give "
            "[masses] (the reciprocating parts), [gravity] or [indicator]",
        )
    try:
        correct = engine_value(sol, ans.key)
    except PolygonMethodError as exc:
        if exc.key and not exc.key.startswith("[answers]"):  # the scene's fault: its key
            raise exc.located(sol.scene.file) from None
        _refuse(sol, ans, exc.message)
    if correct is None:
        _refuse(sol, ans, "no value to check against: " + _why_none(sol, ans))
    return correct


def _why_none(sol, ans) -> str:
    """Why the scene has no value for the engine key ``ans``."""
    key = ans.kind
    if key == "I_flywheel":
        return "the scene has no [flywheel]"
    if key == "m_flywheel":
        return "give the flywheel's [flywheel] radius (or gyration) for its mass"
    pistons = cylinder_pistons(sol)
    if ans.names:
        if pistons:
            return f"{ans.names[0]} is no cylinder's piston of the engine ({', '.join(pistons)})"
        one = engine_piston(sol.scene, sol.plan)
        if one is not None:
            return f"{ans.names[0]} is not the engine's piston ({one})"
    elif pistons and key in ENGINE_PER_PISTON:
        return (
            f"several cylinders on one crank ({', '.join(pistons)}): name the piston, "
            f"{key}_{pistons[0]}"
        )
    return "the scene is no engine (a gas force on a slider crank's piston)"


def cylinder_pistons(sol) -> tuple:
    """The pistons of an engine of several cylinders on one crank (() for another)."""
    return engine_pistons(sol.scene, sol.plan)


def _slip(sol, key, given, correct, rel, unit) -> tuple:
    """(code, words) of the classic slip ``given`` matches (within ``rel``), or (None, None)."""
    what = ENGINE_KEYS[split_key(key)[0]][2]
    for v, code, words in _slips(sol, key, correct):
        if abs(given - v) <= max(rel * abs(v), FLOOR) * (1 + ROUNDING):
            return code, (
                f"{what} matches {words} "
                f"({textbook(v)} {unit}); the correct value is "
                f"{textbook(correct)} {unit}"
            )
    return None, None


def engine_verdict(sol, ans, tolerance) -> Verdict:
    """The :class:`Verdict` on one of the engine chapter's answers."""
    key = ans.kind
    correct = _correct(sol, ans)
    unit = ENGINE_KEYS[key][1]
    if key != "T_mean":  # sizes (a shaking moment's sense is not asked)
        correct = abs(correct)
    if ans.asked:  # a question without its answer: the value, not graded
        return Verdict.asked_of(ans, correct, unit, False)
    signed = key == "T_mean" and ans.value < 0
    given = ans.value if key == "T_mean" else abs(ans.value)
    rel = getattr(tolerance, "relative", tolerance)
    rule = (
        f"{100 * rel:g} % (the answers' tolerance)"
        if rel is not None
        else "three significant figures (a computed answer)"
    )
    rel = rel if rel is not None else ROUNDING
    tol = rel * abs(correct)
    if correct == 0.0 and key == "T_mean":
        # a mean of nought: to the tolerance of the greatest turning moment
        tm = turning_moment(sol.scene)
        tol = rel * max(abs(tm.T_max), abs(tm.T_min))
    err = abs(given - correct)
    ok = err <= tol * (1 + ROUNDING)
    mistake = diagnosis = None
    if not ok:
        mistake, diagnosis = _slip(sol, ans.key, given, correct, rel, unit)
    return Verdict.judged(ans, given, correct, unit, tol, rule, ok, signed, mistake, diagnosis)
