"""An engine's efforts in words, for ``solve``: the piston effort, the thrust in the rod,
the side thrust, the crank effort and the turning moment at the instant; for several
cylinders on one crank (a V-twin, a radial) each cylinder's and the turning moment of them
all. With the force lines' scales (:func:`scales`: below ``TOL.negligible`` of the largest
force, or of its moment over the mechanism's size, a value is written 0).
"""

from __future__ import annotations

import math

from ..common.numbers import fmt, quiet
from ..forces.engine import cylinder_efforts, efforts
from .force_words import holding

__all__ = ["engine_lines", "scales"]


def scales(sol, f):
    """(the largest force, the largest force times the mechanism's size)."""
    forces = (
        [math.hypot(*i.force) for i in f.inertia]
        + [p.magnitude for p in f.pins]
        + [abs(g.normal) for g in f.guides]
        + [math.hypot(*ld.force) for ld in sol.scene.loads if ld.force is not None]
    )
    if sol.scene.gravity is not None:
        forces += [m.mass * sol.scene.gravity.g for m in sol.scene.masses]
    size = max([math.hypot(*p) for p in sol.P.values()] + [lk.length for lk in sol.scene.links])
    F = max(forces, default=0.0)
    couples = [abs(i.couple) for i in f.inertia] + [
        abs(ld.torque) for ld in sol.scene.loads if ld.torque is not None
    ]
    return F, max([F * size] + couples)


def engine_lines(sol) -> list:
    """An engine's efforts at the instant, in the book's words (none for another scene)."""
    f = sol.forces
    e = efforts(sol.scene, sol.plan, sol.P, f)
    if e is None:
        return _cylinders_lines(sol, f)
    F, M = scales(sol, f)
    q = lambda v: fmt(quiet(v, F))  # noqa: E731
    # at rest and not starting: nothing moves, so no inertia (said so)
    parts = "weight (at rest: no inertia)" if holding(sol.scene) else "inertia and weight"
    fr = sol.scene.friction
    mu = fr.guide(e.piston) if fr is not None else 0.0
    if mu:  # the books' F_P = F_L - F_I - R_F
        parts += f", with the guide's friction {mu:g} F_N against its sliding"
    return [
        f"engine: piston effort F_P = {q(e.F_P)} N (along the line of stroke, towards "
        f"the crank: the gas force and the reciprocating parts' {parts}); "
        f"thrust in the rod {e.rod} F_Q = {q(e.F_Q)} N; side thrust on the cylinder "
        f"walls F_N = {q(e.F_N)} N",
        f"engine: crank effort F_T = {q(e.F_T)} N (across the crank {e.crank} at its pin, "
        f"in the sense of rotation); turning moment T = F_T r = {fmt(quiet(e.T, M))} N m "
        "(positive: with the rotation, the engine driving)",
    ]


def _cylinders_lines(sol, f) -> list:
    """An engine of several cylinders on one crank: each cylinder's efforts, and the turning
    moment of them all (none for another scene)."""
    es = cylinder_efforts(sol.scene, sol.plan, sol.P, f)
    if not es:
        return []
    F, M = scales(sol, f)
    q = lambda v: fmt(quiet(v, F))  # noqa: E731
    out = [
        f"engine, cylinder {e.piston}: piston effort F_P = {q(e.F_P)} N (towards the crank); "
        f"thrust in the rod {e.rod} F_Q = {q(e.F_Q)} N; side thrust F_N = {q(e.F_N)} N; "
        f"crank effort F_T = {q(e.F_T)} N; its turning moment F_T r = {fmt(quiet(e.T, M))} N m"
        for e in es
    ]
    total = sum(e.T for e in es)
    out.append(
        f"engine: turning moment of the {len(es)} cylinders on the crank {es[0].crank} "
        f"T = sum F_T r = {fmt(quiet(total, M))} N m (positive: with the rotation, the "
        "engine driving; each rod's crank effort across the crank at the common pin)"
    )
    return out
