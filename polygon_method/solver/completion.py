"""A scene completed when it is compiled: the crank's angle found where the scene states the
position otherwise (``[input] length_OR``, ``s_B``, ``angle_DC``: :func:`place`), its omega
and alpha where it gives the motion on another quantity (``vs_B``, ``omega_BC``:
:func:`given_completed`), a gas force's direction towards the crank
(:func:`gas_towards_crank`). A scene is complete once compiled: every view reads it so."""

from __future__ import annotations

import math
from dataclasses import replace

from ..common.errors import AssemblyError, PolygonMethodError, SceneError
from ..common.numbers import fmt, in_units, sense
from ..common.tolerances import SAME
from ..scene import key_line
from ..scene.link_loads import across_words, load_force
from ..steps import Context
from .given import completed, growth_words, place_roots, resolve

__all__ = ["given_completed", "gas_towards_crank", "loads_along_links", "place"]


def given_completed(plan):
    """The plan with the crank's omega and alpha found from the scene's given motion
    (:mod:`polygon_method.solver.given`); the scene's input completed with them (a scene is
    complete once compiled: every view reads its crank's speed)."""
    sc = plan.scene
    try:
        res = resolve(plan)
    except PolygonMethodError as exc:
        if exc.line is None and (exc.step or "").startswith("[input]"):
            exc.line = key_line(sc, f"[input] {sc.input.given.key}")
            exc.key, exc.step = exc.step, None
        raise exc.located(sc.file)
    object.__setattr__(sc, "input", completed(sc, res))
    g = sc.input.given
    per = "m/s" if g.kind != "omega" else "rad/s"
    note = (
        f"the crank {sc.input.crank}'s speed is found from {g.key} = {g.text}: "
        f"{g.key} is {res.per_omega:.6g} {per} per rad/s of the crank, so omega_"
        f"{sc.input.crank} = {abs(res.omega):.6g} rad/s {sense(res.omega)}"
    )
    if res.rate is not None:
        note += (
            f", and from {g.rate_key or 'its rate'} = "
            f"{g.rate_text if g.rate is not None else '0 (steady)'}: alpha_"
            f"{sc.input.crank} = {abs(res.alpha):.6g} rad/s^2 {sense(res.alpha)}"
        )
    grows = growth_words(res)
    if grows:
        note += f" ({grows})"
    dims = replace(plan.dims, omega=res.omega, alpha=res.alpha)
    return replace(plan, dims=dims, notes=(note,) + res.notes + plan.notes, given=res)


def gas_towards_crank(plan, sc):
    """A gas force given without its direction pushes the piston towards the crank: along
    the piston's path, from the piston towards the foot of the crank centre, at the scene's
    instant (a piston stays on its side of the crank centre over the whole turn). The
    scene's loads are completed with it (a scene is complete once compiled)."""
    if not any(ld.toward is not None for ld in sc.loads):
        return
    first = plan.steps[0]
    pivot = getattr(first, "pivot", None)  # a driving crank's (a block driver has none)
    state = None
    loads, said = [], []  # the loads completed, and a note of each default taken
    for ld in sc.loads:
        if ld.toward is None:
            loads.append(ld)
            continue
        where = f"[loads] {ld.target}"
        path = next((s for s in sc.sliders if s.point == ld.target), None)
        if pivot is None or path is None or not hasattr(path, "through") or path.slot:
            raise SceneError(
                f"the gas force at {ld.target} pushes the piston towards the "
                "crank only for a piston on a fixed path driven by a crank: give "
                "its direction",
                file=sc.file,
                key=where,
                line=key_line(sc, where),
            )
        if state is None:
            inp = sc.input
            state = plan.run(Context(inp.angle, 0.0, 0.0), upto=0)
        (ox, oy), (x, y) = state.P[pivot], state.P[ld.target]
        ux, uy = path.u
        d = (ox - x) * ux + (oy - y) * uy
        size = max(lk.length for lk in sc.links)
        if abs(d) <= SAME * size:
            raise SceneError(
                f"the piston {ld.target} is level with the crank centre {pivot} "
                "along its path: towards the crank says no way: give the gas "
                "force's direction",
                file=sc.file,
                key=where,
                line=key_line(sc, where),
            )
        s = 1.0 if d > 0 else -1.0
        f = ld.toward
        loads.append(replace(ld, force=(f * s * ux + 0.0, f * s * uy + 0.0)))
        said.append(
            f"the gas force on the piston {ld.target} ({ld.gas[2]}: {fmt(abs(f))} N) "
            f"pushes it towards the crank centre {pivot} along its path, at "
            f"{fmt(math.degrees(math.atan2(s * uy, s * ux)) % 360)} deg (default; give "
            "its direction to choose)"
        )
    object.__setattr__(sc, "loads", tuple(loads))
    object.__setattr__(sc, "reading_notes", tuple(sc.reading_notes) + tuple(said))


def place(scene, compile_trial) -> tuple:
    """Set the scene's crank angle to the one that gives the position it states otherwise
    (``[input] length_OR``, ``s_B``, ``angle_CD``): the mechanism is compiled at a trial
    angle (``near``, else the first of a turn's grid that assembles), the turn searched for
    the angles that give it, and the one nearest ``near`` (else the first from 0 deg) taken.
    The scene is then compiled at it, its branches chosen there (``compile_trial``: a
    scene to its plan, the compiler's own run). Returns the notes."""
    inp = scene.input
    pl = inp.placed
    trials = ([pl.near] if pl.near is not None else []) + [
        math.radians(d) for d in range(0, 360, 10)
    ]
    plan = None
    for t in trials:
        trial = replace(scene, input=replace(inp, angle=t, placed=replace(pl, found=True)))
        try:
            plan = compile_trial(trial)
            break
        except PolygonMethodError:
            continue
    key = f"[input] {pl.key}"
    if plan is None:
        raise AssemblyError(
            f"{pl.key} = {pl.text}: the mechanism assembles at no crank angle of {inp.crank}",
            key=key,
        )
    roots, seen = place_roots(plan)
    if not roots:
        unit = 1.0 if pl.kind == "angle" else scene.length_unit
        what = (
            f"; over the turn it runs from {in_units(seen[0] + pl.value, unit)} to "
            f"{in_units(seen[1] + pl.value, unit)} {scene.units}"
            if seen is not None and pl.kind != "angle"
            else ""
        )
        raise AssemblyError(
            f"{pl.key} = {pl.text}: no angle of the crank {inp.crank} gives it{what}", key=key
        )
    if pl.near is not None:
        theta = min(roots, key=lambda t: abs(math.remainder(t - pl.near, 2 * math.pi)))
    else:
        theta = min(roots, key=lambda t: t % (2 * math.pi))
    shown = ", ".join(
        f"{math.degrees(t) % 360:.6g}" for t in sorted(roots, key=lambda t: t % (2 * math.pi))
    )
    note = (
        f"the crank {inp.crank}'s angle is found from {pl.key} = {pl.text}: "
        f"{math.degrees(theta) % 360:.10g} deg"
    )
    if len(roots) > 1:
        note += (
            f" (of the crank angles that give it, {shown} deg, the "
            + ("one nearest near" if pl.near is not None else "first from 0 deg")
            + "; set near = a rough angle to choose)"
        )
    object.__setattr__(scene, "input", replace(inp, angle=theta, placed=replace(pl, found=True)))
    return (note,)


def loads_along_links(plan, sc):
    """A force stated against a link ("perpendicular to CD, ccw") turns with the link: its
    vector at the scene's instant, from the positions there (:func:`load_force`, the one
    place every view takes it from), completes the scene's loads; an ambiguous
    "perpendicular to CD" (no sense) is refused, saying which way each sense points."""
    state = plan.run(Context(sc.input.angle, 0.0, 0.0), upto=0)
    loads, said = [], []
    for ld in sc.loads:
        if ld.across is None:
            loads.append(ld)
            continue
        try:
            f = load_force(ld, state.P)
        except SceneError as exc:
            where = f"[loads] {ld.target}"
            raise SceneError(
                exc.message, file=sc.file, key=where, line=key_line(sc, where)
            ) from None
        loads.append(replace(ld, force=(f[0] + 0.0, f[1] + 0.0)))
        fixed = all(p in sc.ground for p in ld.across[:2])  # (two ground points: the frame's)
        how = "along a line of the frame" if fixed else "turning with the link"
        said.append(f"the force at {ld.target}: {across_words(loads[-1])}, {how}")
    old = tuple(n for n in sc.reading_notes if not n.startswith("the force at "))
    object.__setattr__(sc, "loads", tuple(loads))
    object.__setattr__(sc, "reading_notes", old + tuple(said))
