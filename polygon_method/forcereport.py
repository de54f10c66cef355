"""The force analysis in words: the lines of ``solve`` and the blocks of ``steps`` (the
book's order: a_G from the image, the inertia force and its offset, then each group's free
bodies and force equations, the crank last), for a scene with masses or gravity.

Vectors are written as a magnitude and a direction (deg ccw from +x), moments and torques
with their sense; rounding noise (below ``TOL.negligible`` of the largest force, or of its
moment over the mechanism's size) is written 0.
"""

from __future__ import annotations

import math

from .forces import FRAME
from .forces.engine import efforts
from .numbers import fmt, quiet, sense_word

__all__ = ["forces_lines", "force_blocks", "engine_lines"]


def _scales(sol, f):
    """(the largest force, the largest force times the mechanism's size)."""
    forces = [math.hypot(*i.force) for i in f.inertia] + [p.magnitude for p in f.pins] + \
        [abs(g.normal) for g in f.guides] + \
        [math.hypot(*ld.force) for ld in sol.scene.loads if ld.force is not None]
    if sol.scene.gravity is not None:
        forces += [m.mass * sol.scene.gravity.g for m in sol.scene.masses]
    size = max([math.hypot(*p) for p in sol.P.values()]
               + [lk.length for lk in sol.scene.links])
    F = max(forces, default=0.0)
    couples = [abs(i.couple) for i in f.inertia] + \
        [abs(ld.torque) for ld in sol.scene.loads if ld.torque is not None]
    return F, max([F * size] + couples)


def _vec(v, scale):
    x, y = quiet(v[0], scale), quiet(v[1], scale)
    m = math.hypot(x, y)
    if m == 0:
        return "0 N"
    d = math.degrees(math.atan2(y, x)) % 360.0
    return f"{fmt(m)} N at {0.0 if d >= 359.95 else d:.1f} deg"


def _moment(c, scale, unit="N m"):
    c = quiet(c, scale)
    return f"{fmt(abs(c))} {unit} {sense_word(c)}".rstrip() if c else f"0 {unit}"


def _body(name):
    return "the frame" if name == FRAME else name


def forces_lines(sol) -> list:
    """The force analysis' lines of the ``solve`` report (empty without masses or gravity;
    one line when the plan has a step the analysis does not cover)."""
    sc = sol.scene
    if not sc.has_forces:
        return []
    refused = sol.forces_refused
    if refused:
        return ["", refused]
    f = sol.forces
    F, M = _scales(sol, f)
    u = sc.length_unit
    out = ["", "forces (D'Alembert; SI, ccw positive; a pin's force is the force on the first "
           "body by the second)"]
    if sc.gravity is not None:
        out.append(f"gravity: {sc.gravity.text}")
    if f.inertia:
        out.append(f"{'body':<10} {'mass (kg)':<10} {'inertia force -m a_G':<24} "
                   f"{'couple -I alpha':<20} offset h ({sc.units})")
        for i in f.inertia:
            h = "-" if i.offset is None else fmt(abs(quiet(i.offset, M / max(F, 1e-300))) / u)
            out.append(f"{i.body:<10} {fmt(i.mass):<10} {_vec(i.force, F):<24} "
                       f"{_moment(i.couple, M):<20} {h}")
    out.append(f"{'pin':<5} {'on':<10} {'by':<10} force")
    for p in f.pins:
        out.append(f"{p.point:<5} {p.on:<10} {_body(p.by):<10} {_vec(p.force, F)}")
    for g in f.guides:
        out.append(f"guide at {g.point}: normal force on block {g.point} {_vec(g.force, F)}")
    out.append(f"input torque on {f.crank} (inertia, weights and loads): "
               f"{_moment(f.input_torque, M)}")
    out.append(f"shaking force on the frame: {_vec(f.shaking_force, F)}; shaking moment "
               f"about the origin: {_moment(f.shaking_moment, M)}")
    out += engine_lines(sol)
    for st in f.steps:
        if st.condition < 0.0871557:  # sin 5 deg, as the kinematic warnings
            out.append(f"warning: forces, step {st.index + 1} ({st.title}): condition "
                       f"{st.condition:.3g} ({st.why}): the pin forces grow as 1/condition")
    return out


def engine_lines(sol) -> list:
    """An engine's efforts at the instant, in the book's words (none for another scene)."""
    f = sol.forces
    e = efforts(sol.scene, sol.plan, sol.P, f)
    if e is None:
        return []
    F, M = _scales(sol, f)
    q = lambda v: fmt(quiet(v, F))  # noqa: E731
    return [f"engine: piston effort F_P = {q(e.F_P)} N (along the line of stroke, towards "
            f"the crank: the gas force and the reciprocating parts' inertia and weight); "
            f"thrust in the rod {e.rod} F_Q = {q(e.F_Q)} N; side thrust on the cylinder "
            f"walls F_N = {q(e.F_N)} N",
            f"engine: crank effort F_T = {q(e.F_T)} N (across the crank {e.crank} at its pin, "
            f"in the sense of rotation); turning moment T = F_T r = {fmt(quiet(e.T, M))} N m "
            "(positive: with the rotation, the engine driving)"]


def force_blocks(sol) -> list:
    """The ``steps`` document's blocks for the forces (``("h", text)``, ``("p", text)``,
    ``("list", items)``, ``("table", header, rows)``), numbered after section 5."""
    sc = sol.scene
    if not sc.has_forces:
        return []
    refused = sol.forces_refused
    if refused:
        return [("h", "6. Forces"), ("p", refused)]
    f = sol.forces
    F, M = _scales(sol, f)
    u = sc.length_unit
    blocks = [("h", "6. Inertia forces (D'Alembert)")]
    blocks.append(("p", "Each body's centre of mass G is a point of the body: its image g on "
                   "the acceleration diagram gives a_G (a_G = a_P + lam (a_Q - a_P) + mu "
                   "perp(a_Q - a_P), as for any point carried on the link). The inertia "
                   "force m a_G acts opposite to a_G; the inertia couple is -I alpha. The "
                   "book's single force: m a_G along a line offset from G by h = I alpha / "
                   "(m a_G), on the side where its moment about G has the couple's sense."
                   + (f" Gravity: {sc.gravity.text}, each weight m g at G." if sc.gravity
                      else " No gravity (the scene gives no [gravity]).")))
    rows = []
    for i in f.inertia:
        a = math.hypot(*i.a_G)
        h = "-" if i.offset is None else fmt(abs(quiet(i.offset, M / max(F, 1e-300))) / u)
        rows.append((i.body, fmt(i.mass), fmt(i.inertia), i.how,
                     f"{fmt(a)} m/s^2",
                     _vec(i.force, F), _moment(i.couple, M), h))
    blocks.append(("table", ("body", "m (kg)", "I_G (kg m^2)", "G", "a_G", "m a_G, opposite "
                             "to a_G", "-I alpha", f"h ({sc.units})"), rows))
    blocks.append(("h", "7. Forces, group by group (the construction's groups in reverse)"))
    blocks.append(("p", "Each group's bodies are statically determinate: the moments about "
                   "the pins whose forces are not yet known give the pin force between them, "
                   "then each body's force balance the rest. 'Known' is the resultant of the "
                   "inertia force and couple, the weight, the loads and the forces of the "
                   "groups solved before (the moment about the origin)."))
    for st in f.steps:
        items = []
        for body, (fx, fy, m) in zip(st.bodies, st.known):
            items.append(f"known on {body}: {_vec((fx, fy), F)}, moment about the origin "
                         f"{_moment(m, M)}")
        items += list(st.equations)
        for name, val in st.found:
            if isinstance(val, tuple):
                items.append(f"{name} = {_vec(val, F)}")
            elif name.startswith("T "):
                items.append(f"{name} = {_moment(val, M)}")
            else:
                items.append(f"{name} = {fmt(quiet(val, F))} N (along the path's normal, "
                             "+ to its left)")
        if st.why:
            items.append(f"condition {st.condition:.3g} ({st.why})")
        head = {"dyad": "moments of each link about its other end give the pin force "
                        "between them; each link's force balance its end's",
                "slider": "moments of the link about its other end give the guide's normal "
                          "force; the block's force balance the pin force; the link's the "
                          "force at its other end",
                "crank": "the frame holds the crank at its pivot; the moments about the "
                         "pivot give the driving torque"}.get(st.kind, "")
        blocks.append(("p", f"Step {st.index + 1}, {st.title}: {head}."))
        blocks.append(("list", items))
    blocks.append(("h", "8. The driving torque and the frame"))
    items = [f"input torque on {f.crank}: {_moment(f.input_torque, M)} (inertia, weights and "
             "loads; its power balances theirs)",
             f"shaking force (on the frame, through its pins and guides): "
             f"{_vec(f.shaking_force, F)}",
             f"shaking moment about the origin (with the driver's reaction): "
             f"{_moment(f.shaking_moment, M)}"]
    items += [f"guide at {g.point}: {_vec(g.force, F)} on block {g.point}" for g in f.guides]
    blocks.append(("list", items))
    return blocks
