"""Two inputs whose speeds are given elsewhere (a differential whose sun and annulus
are driven, the arm the output): the two cranks' speeds found when the scene is compiled.

With two driven cranks every angular velocity is linear in their speeds: at the stated
instant the link X given turns at ``omega_X = w1 Y1 + w2 Y2``, ``Y1`` (``Y2``) its speed
per rad/s of the first (second) crank alone (the polygons drawn for each crank alone, as
the differential's step table does). Each input gives one equation: its crank's own speed
(``w_i = stated``) or a speed given elsewhere (``w1 Y1 + w2 Y2 = stated``); the two are
solved together (2 x 2). A slider's sliding velocity (``vs_X``) is linear in the cranks'
speeds as well, and so is a point's velocity component along a fixed direction: a point's
``v_X`` ("0.3 m/s at 30 deg") is read as its component along the stated direction (its
speed where it moves that way; a note says how it moves where it does not, refused past
30 deg). The accelerations are affine in the cranks' rates::

    alpha_X = a1 Y1 + a2 Y2 + H      (H: alpha_X with both cranks at their speeds, a = 0)

and are solved with the same rows. Where the two rows are parallel (the two given links'
speeds keep one ratio whatever the cranks do: they do not tell the two inputs apart) the
system is singular: refused, with its condition, the sine of the angle between the two
rows (each made of unit length), 1 for independent rows and 0 where singular.

>>> from polygon_method.scene import parse_scene
>>> from polygon_method.solver.compiler import compile_plan
>>> sc = parse_scene('''
... units = "mm"
... [ground]
... O = [0, 0]
... [rolling]
... module = "4 mm"
... AP = { on = "O-Q", inside = true, teeth = 24, on_teeth = 88 }
... "O-S" = { on = "AP", teeth = 40 }
... [input]
... crank = "OA"
... angle = 0
... "omega_O-S" = "1 rad/s ccw"
... [input.second]
... crank = "O-Q"
... angle = 0
... speed = "1 rad/s ccw"
... ''')
>>> round(compile_plan(sc).scene.input.omega, 12)   # everything turns together
1.0
"""

from __future__ import annotations

import math
from dataclasses import replace

from ..common.errors import TOL, SceneError, SingularStepError
from ..common.tolerances import DISTINCT, ROUNDING, SAME
from ..common.numbers import condition_text, sense
from ..scene import GIVEN_KINDS, key_line
from ..steps import Context

__all__ = ["needs_two", "complete_two", "held_over", "trial_speeds", "found_note", "FOUND"]


def needs_two(inp) -> bool:
    """Whether the scene's two inputs wait for a speed given on another link (not yet
    found)."""
    two = inp.second
    return (
        two is not None
        and two.block is None
        and (inp.given is not None or two.given is not None)
        and (inp.omega is None or two.omega is None)
    )


def complete_two(scene, compile_trial) -> tuple:
    """Find both cranks' speeds and accelerations from the speeds given on other links
    (see the module) and set them on ``scene``'s input (a scene is complete once
    compiled). ``compile_trial``: a scene to its plan. Returns the notes."""
    inp, two = scene.input, scene.input.second
    plan = compile_trial(trial_speeds(scene))
    k = next(i for i, st in enumerate(plan.steps) if st.kind == "second crank")

    def run(w1, a1, w2, a2):
        prm = plan.dims.steps[k]
        own = (prm[0], prm[1], w2, a2, prm[4], w1 if w1 else 1.0)
        dims = replace(plan.dims, steps=plan.dims.steps[:k] + (own,) + plan.dims.steps[k + 1 :])
        return plan.run(Context(inp.angle, w1, a1), dims=dims)

    ins = (inp, two)
    m1, m2 = run(1.0, 0.0, 0.0, 0.0), run(0.0, 0.0, 1.0, 0.0)
    per = [
        None if i.given is None else (_of(i.given, m1, scene)[0], _of(i.given, m2, scene)[0])
        for i in ins
    ]
    rows = [per[i] if ins[i].given is not None else _unit(i) for i in (0, 1)]
    rhs = [i.given.value if i.given is not None else i.omega for i in ins]
    w = _solve(rows, rhs, ins, "speeds")
    m0 = run(w[0], 0.0, w[1], 0.0)
    notes, arows, arhs = [n for n in (_along(x, m0, x is two) for x in ins) if n], [], []
    for i, x in enumerate(ins):
        g = x.given
        if g is not None and (g.rate is not None or x.alpha is None):
            if g.rate is None:
                notes.append(
                    f"{GIVEN_KINDS[g.kind]}_{g.key.partition('_')[2]} = 0 is taken: the given "
                    f"speed {g.key} is steady (give its rate or the crank's acceleration to "
                    "set it)"
                )
            arows.append(per[i])
            arhs.append(_rate_of(g) - _of(g, m0, scene)[1])
        else:
            arows.append(_unit(i))
            arhs.append(x.alpha if x.alpha is not None else 0.0)
    a = _solve(arows, arhs, ins, "accelerations")
    # an acceleration's rows hold the velocity terms (omega^2 r of the links turning at
    # the speeds found): its noise is on their size, not on the accelerations' own
    turning = max([abs(v) for v in w] + [0.0]) ** 2 * max([abs(v) for r in rows for v in r] + [1.0])
    w, a = _quiet(w, rhs), _quiet(a, arhs, ROUNDING * turning)
    if w[0] == 0.0:
        raise SingularStepError(
            f"the speeds given leave the crank {inp.crank} at rest (omega_{inp.crank} = 0 "
            "to rounding): the train then works as an ordinary one; state it with "
            f"{inp.crank} part of the frame",
            key=_where(ins),
        )
    cond = _condition(rows)
    done = replace(
        inp,
        omega=w[0],
        alpha=a[0],
        given=None,
        speed_text=_found(inp),
        found_from=tuple(x.given for x in ins if x.given is not None),
        second=replace(two, omega=w[1], alpha=a[1], given=None, speed_text=_found(two)),
    )
    object.__setattr__(scene, "input", done)
    return (_note(ins, per, w, a, cond),) + tuple(notes)


def trial_speeds(scene):
    """``scene`` with a trial speed (1 rad/s, no rate) on each crank whose speed is to be
    found (the positions, and the plan's shape, do not depend on them); ``scene`` itself
    where none is to be found."""
    inp = scene.input
    if not needs_two(inp):
        return scene
    two = inp.second
    trial = replace(
        inp,
        omega=1.0 if inp.omega is None else inp.omega,
        alpha=0.0 if inp.alpha is None else inp.alpha,
        given=None,
        second=replace(
            two,
            omega=1.0 if two.omega is None else two.omega,
            alpha=0.0 if two.alpha is None else two.alpha,
            given=None,
        ),
    )
    return replace(scene, input=trial)


#: how the note saying the two cranks' speeds found begins
FOUND = "the two cranks' speeds are found from the speeds given"


def found_note(plan) -> str | None:
    """The note saying how the two cranks' speeds were found (the step table's working),
    or None where they were stated."""
    if not plan.scene.input.found_from:
        return None
    return next((n for n in plan.notes if n.startswith(FOUND)), None)


def _of(g, m, scene):
    """(the given quantity, its rate) in the filled state ``m``: a link's omega and alpha,
    a slider's (or a cylinder's) sliding velocity and acceleration, or a point's velocity
    and acceleration along the stated direction (the components: linear in the cranks')."""
    if g.kind == "omega":
        key = scene.link("-".join(g.names)).key
        return m.W[key], m.Al[key]
    if g.kind == "vs":
        s = m.S[g.names[0]]
        return s[0], s[1]
    (vx, vy), (ax, ay), (dx, dy) = m.V[g.names[0]], m.A[g.names[0]], g.direction
    return vx * dx + vy * dy, ax * dx + ay * dy


def _rate_of(g) -> float:
    """The given rate as the rate of :func:`_of`'s quantity: a point's is of its speed
    (+ speeding up), so along the stated direction it is signed as the speed is."""
    rate = g.rate or 0.0
    return (rate if g.value > 0 else -rate) if g.kind == "v" else rate


def _along(x, m, second) -> str | None:
    """A point's velocity given with two inputs is read as its component along the stated
    direction (one equation, linear in the two cranks' speeds): where the point found moves
    otherwise, a note says how it moves (refused where more than 30 deg off, as a single
    input's is); None for another given quantity, or a point moving as stated."""
    g = x.given
    if g is None or g.kind != "v":
        return None
    vx, vy = m.V[g.names[0]]
    speed = math.hypot(vx, vy)
    cos = (vx * g.direction[0] + vy * g.direction[1]) / speed if speed else 1.0
    off = math.degrees(math.acos(max(-1.0, min(1.0, cos if g.value > 0 else -cos))))
    if off > 30.0:
        raise SingularStepError(
            f"{g.names[0]} cannot move as {g.key} = {g.text} says with the other input as "
            f"given: it would move along {math.degrees(math.atan2(vy, vx)) % 360.0:.4g} deg, "
            f"{off:.3g} deg from the stated direction; give its direction as the mechanism "
            "allows",
            key=f"[input{'.second' if second else ''}] {g.key}",
        )
    if off <= DISTINCT:
        return None
    return (
        f"{g.key}: with two inputs the stated speed is {g.names[0]}'s velocity component along "
        f"the stated direction; {g.names[0]} moves along "
        f"{math.degrees(math.atan2(vy, vx)) % 360.0:.6g} deg here, {off:.3g} deg from it, at "
        f"{speed:.6g} m/s"
    )


def _unit(i):
    return (1.0, 0.0) if i == 0 else (0.0, 1.0)


def _condition(rows) -> float:
    """|det| of the rows each made of unit length (0 where a row is zero)."""
    (a, b), (c, d) = rows
    n1, n2 = math.hypot(a, b), math.hypot(c, d)
    if n1 == 0.0 or n2 == 0.0:
        return 0.0
    return abs(a * d - b * c) / (n1 * n2)


def _solve(rows, rhs, ins, what):
    """The two cranks' values from the two rows (Cramer), refused where singular."""
    cond = _condition(rows)
    if not cond >= TOL.singular:
        said = " and ".join(
            f"{x.given.key} = {x.given.text}"
            if x.given is not None
            else f"the crank {x.crank}'s own speed"
            for x in ins
        )
        raise SingularStepError(
            f"{said} do not determine both inputs: the two given speeds keep one ratio "
            f"whatever the cranks {ins[0].crank} and {ins[1].crank} do (their rows per "
            f"rad/s of each crank are parallel; condition {condition_text(cond)}), so the "
            f"cranks' {what} cannot be found: give a speed that tells them apart",
            key=_where(ins),
        )
    (a, b), (c, d) = rows
    det = a * d - b * c
    return ((rhs[0] * d - b * rhs[1]) / det, (a * rhs[1] - rhs[0] * c) / det)


def _found(x) -> str:
    return x.speed_text if x.given is None else _found_text(x.given)


def _found_text(g) -> str:
    """An input's speed in words where it is found from ``g``."""
    return f"found from {g.key} = {g.text}"


def _where(ins) -> str:
    """The key of the first speed given on another link (the line a refusal names)."""
    x = ins[0] if ins[0].given is not None else ins[1]
    return f"[input{'' if x is ins[0] else '.second'}] {x.given.key}"


def _note(ins, per, w, a, cond) -> str:
    """The note every view prints: how the cranks' speeds were found."""
    parts = []
    for x, p in zip(ins, per):
        if x.given is not None:
            parts.append(
                f"{x.given.key} = {x.given.text} is {p[0] + 0.0:.6g} "
                f"{'rad/s' if x.given.kind == 'omega' else 'm/s'} per rad/s of the crank "
                f"{ins[0].crank} and {p[1] + 0.0:.6g} per rad/s of the crank {ins[1].crank}"
                + (" (its component along the stated direction)" if x.given.kind == "v" else "")
            )
        else:
            parts.append(f"the crank {x.crank} turns at its own stated speed")
    out = (
        f"{FOUND} (" + "; ".join(parts) + "): "
        f"solving the two together, omega_{ins[0].crank} = {abs(w[0]):.6g} rad/s "
        f"{sense(w[0])} and omega_{ins[1].crank} = {abs(w[1]):.6g} rad/s {sense(w[1])}, "
        f"alpha_{ins[0].crank} = {_rate(a[0])} and alpha_{ins[1].crank} = {_rate(a[1])}"
    )
    out += f" (condition {cond:.3g} of the two equations: 1 independent, 0 singular)"
    if cond < TOL.warn:
        out += (
            ": near singular, the cranks' speeds are very sensitive to the speeds given "
            "(they grow as 1 / condition)"
        )
    return out


def held_over(scene, fr) -> None:
    """Refuse a sweep that would not hold the speeds the two cranks' were found from: over
    a sweep both cranks turn at the speeds found at the stated instant, which holds a speed
    given elsewhere only where it keeps fixed ratios to the two (a gear train); elsewhere (a
    coupler of a linkage, a point's or a slider's speed) it would drift from the value
    stated and the numbers would answer another question. ``fr``: the sweep's motion."""
    import numpy as np

    inp = scene.input
    turning = max(abs(inp.omega), abs(inp.second.omega))
    for g in inp.found_from:
        q, r = _of(g, fr, scene)
        w, al = np.asarray(q, dtype=float), np.asarray(r, dtype=float)
        rate = _rate_of(g) if g.rate is not None else None
        angular = g.kind == "omega"
        reach = 1.0 if angular else max(lk.length for lk in scene.links)
        size = max(abs(g.value), turning * reach)
        with np.errstate(invalid="ignore"):
            off = _worst(np.abs(w - g.value))
            off_a = _worst(np.abs(al - rate)) if rate is not None else 0.0
        where = f"[input{'.second' if inp.second.speed_text == _found_text(g) else ''}] {g.key}"
        if off > SAME * size or off_a > SAME * max(
            abs(rate or 0.0), size * (size if angular else turning)
        ):
            units = "rad/s or rad/s^2" if angular else "m/s or m/s^2"
            raise SceneError(
                f"sweep: {g.key} = {g.text} is held only at the stated instant: with both "
                f"cranks at the speeds found there, {g.key} drifts by up to "
                f"{max(off, off_a):.3g} ({units}) over the sweep (it does not keep fixed "
                "ratios to the two cranks); solve each angle as its own scene",
                key=where,
                file=scene.file,
                line=key_line(scene, where),
            )


def _rate(a) -> str:
    return f"{abs(a):.6g} rad/s^2" + (f" {sense(a)}" if sense(a) else "")


def _worst(d) -> float:
    """The largest of ``d`` over the rows evaluated (a row left out, NaN, is not one)."""
    import numpy as np

    d = np.asarray(d, dtype=float).ravel()
    d = d[np.isfinite(d)]
    return float(d.max()) if d.size else 0.0


def _quiet(x, rhs, noise=0.0):
    """The two values found, each written 0 where it is rounding noise: below ``SAME`` of
    the size of the values and of the right-hand sides they are found from, or below
    ``noise`` (an acceleration's: the rounding of the velocity terms its rows hold)."""
    size = max(abs(v) for v in (*x, *rhs))
    least = max(SAME * size, noise)
    return tuple(0.0 if abs(v) <= least else v for v in x)
