"""The force analysis in words: the lines of ``solve`` and the blocks of ``steps`` (the
book's order: a_G from the image, the inertia force and its offset, then each group's free
bodies and force equations, the crank last), for a scene with masses or gravity.

Vectors are written as a magnitude and a direction (deg ccw from +x), moments and torques
with their sense; rounding noise (below ``TOL.negligible`` of the largest force, or of its
moment over the mechanism's size) is written 0.
"""

from __future__ import annotations

import math

from ..solver.errorbound import SHOWN, USELESS
from ..forces import FRAME
from ..forces.bounds import NO_BOUND, force_bounds
from ..forces.cylinder import given_forces, given_line
from ..common.numbers import fmt, quiet, sense_word
from ..common.tolerances import FLOOR
from .force_polygons import body_name as _body, polygon_items as _polygon_items
from .force_engine import engine_lines, scales as _scales
from .force_words import acting, holding, known_words, outside_words, rest_blocks, start_words
from .force_words import symbol_words

__all__ = ["forces_lines", "force_blocks", "bound_lines", "engine_lines"]


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


def _wheel(c):
    """A rolling body in words: "wheel CP", "planet AP" (a gear by its teeth), "rack R"."""
    body = c.wheel
    if c.words:
        return c.words[0]
    return f"rack {body[6:]}" if body.startswith("block ") else f"wheel {body}"


def _base(c):
    """What a contact's body rolls on, in words."""
    if c.words:
        return c.words[1]
    if c.by != FRAME:
        return f"{'the pinion' if c.wheel.startswith('block ') else 'the gear'} {c.by}"
    circle = c.teeth is not None or (c.grip is not None and c.grip[3] is not None)
    return "the fixed circle" if circle else "the ground"


def _friction_lines(sol, f, F, M) -> list:
    """The friction the forces were found with: each force at a guide, each couple at a
    pin (on the first body; the other feels it back), and its power."""
    fr = sol.scene.friction
    if fr is None:
        return []
    out = [
        f"friction (Coulomb: {fr.words()}{', the friction circle mu r' * bool(fr.pins or fr.at_pins)}; "
        + (
            "at rest, the limiting static friction against the motion about to start, "
            "the effort to start it):"
            if sol.scene.at_rest
            else "against the sliding and the relative turning; where nothing slides it is "
            "not determined and taken as 0):"
        )
    ]
    seen = set()
    for it in f.friction:
        if it[1] in seen or it[0] == FRAME:  # (the reaction of one already said)
            continue
        seen.add(it[1])
        if len(it) == 3:
            out.append(f"  {it[1]}: couple {_moment(it[2], M)} on {it[0]}")
        else:
            out.append(f"  {it[1]}: {_vec(it[2], F)} on {_body(it[0])}")
    out += _cylinder_couples(sol, f, M)
    out.append(
        f"  friction power: {fmt(quiet(f.friction_power, M))} W (lost; the driver supplies it)"
        if not sol.scene.at_rest
        else f"  friction power per {_per(sol)}: {fmt(quiet(f.friction_power, M))} W "
        "(virtual: nothing moves yet)"
    )
    return out


def _per(sol) -> str:
    """What the motion is solved per at rest: 1 rad/s of the crank, 1 m/s of a driving
    block or collar, 1 rad/s of a driving wheel (the virtual velocities)."""
    return getattr(sol.plan.steps[0], "virtual_unit", "1 rad/s of the crank")


def _rate(sc) -> str:
    """The start's rate by name: a crank's alpha, a driving block's or collar's as."""
    return "alpha" if sc.input.crank is not None else f"as_{sc.input.tip}"


def _cylinder_couples(sol, f, M) -> list:
    """A line for each cylinder the friction circles at its pins put a couple on: it is no
    longer a two-force member."""
    out = []
    for key in sorted({c.key for c in sol.scene.cylinders}):
        each = [it[2] for it in f.friction if len(it) == 3 and it[0] == key]
        total = quiet(sum(each), sum(abs(c) for c in each))  # (cancelling: rounding)
        if isinstance(total, float) and total != 0.0:
            out.append(
                f"  cylinder {key}: the couples at its pins sum to {_moment(total, M)}: no "
                "longer a two-force member, its pins' forces are tangent to the friction "
                "circles (a part M / L across its line, L its length)"
            )
    return out


def _rack_couple(f, g) -> bool:
    """Whether a guide's couple is a rack's (said with its normal force: the tooth load
    acts off the rack's point)."""
    return (
        any(c.wheel == f"block {g.point}" for c in f.contacts)
        and isinstance(g.couple, float)
        and g.couple != 0.0
    )


def _driver_lines(f, F, M, said):
    """The driver's effort: the crank's torque, or a driving block's force along its guide,
    and a second crank's torque."""
    if f.driver == "cylinder":
        v = quiet(f.input_torque, F)
        out = [
            f"input force in cylinder {f.crank}{said}: {fmt(abs(v))} N"
            + (
                ""
                if not v
                else " pushing its ends apart"
                if v > 0
                else " pulling its ends together"
            )
        ]
    elif f.driver == "block":
        v = quiet(f.input_torque, F)
        out = [
            f"input force on {f.crank} along its guide{said}: {fmt(abs(v))} N"
            + (
                ""
                if not v
                else " along the guide's direction"
                if v > 0
                else " against the guide's direction"
            )
        ]
    elif f.driver == "collar":
        out = [_collar_line(f, f.crank, f.input_torque, F, said)]
    elif f.driver == "wheel":
        out = [
            f"input torque on the wheel {f.crank}{said}: {_moment(f.input_torque, M)} (its "
            "driver's torque on it, the effort taken as a torque; as a force at its "
            f"centre along the ground instead: {_vec(f.centre_force, F)})"
        ]
    else:
        out = [f"input torque on {f.crank}{said}: {_moment(f.input_torque, M)}"]
    if f.second_crank is not None and f.second_crank.startswith("block "):
        out.append(_collar_line(f, f.second_crank, f.second_torque, F, said, " (the second input)"))
    elif f.second_crank is not None:
        out.append(
            f"input torque on {f.second_crank} (the second crank){said}: "
            f"{_moment(f.second_torque, M)}"
        )
    return out


def _collar_line(f, body, value, F, said, which=""):
    """A collar's driver's force along its rod (signed outward: from the rod's pivot)."""
    v = quiet(value, F)
    rod = next((g.by for g in f.guides if f"block {g.point}" == body), "its rod")
    return (
        f"input force on collar {body.removeprefix('block ')}{which} along {rod}{said}: "
        f"{fmt(abs(v))} N" + ("" if not v else " outward" if v > 0 else " inward")
    )


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
    out = [
        "",
        "forces (D'Alembert; SI, ccw positive; a pin's force is the force on the first "
        "body by the second)",
    ]
    if sc.gravity is not None:
        out.append(f"gravity: {sc.gravity.text}")
    out += _inertia_lines(sc, f, F, M)
    out.append(f"{'pin':<5} {'on':<10} {'by':<10} force")
    for p in f.pins:
        out.append(f"{p.point:<5} {p.on:<10} {_body(p.by):<10} {_vec(p.force, F)}")
    for g in f.guides:
        out.append(
            f"guide at {g.key}: normal force on block {g.point} {_vec(g.force, F)}"
            + (f"; its couple {_moment(g.couple, M)}" if _rack_couple(f, g) else "")
        )
    out += [given_line(sc, sol.S, k, v, sol.P) for k, v in given_forces(f)]  # a strut, a spring
    for c in f.contacts:
        out.append(
            f"contact of {_wheel(c)} with {_base(c)}: normal "
            f"{fmt(quiet(c.normal, F))} N, tangential {fmt(quiet(c.tangential, F))} N "
            f"({_vec(c.force, F)}); " + c.grip_words()
        )
    out += _friction_lines(sol, f, F, M)
    out += _driver_lines(
        f,
        F,
        M,
        f" (at rest: {acting(sc)}, no inertia)"
        if holding(sc)
        else f" (starting from rest: {acting(sc)}, the inertia of the start)"
        if sc.at_rest
        else " (inertia, weights, loads and friction)"
        if sc.friction is not None
        else " (inertia, weights and loads)"
        if sc.masses or sc.gravity
        else " (the loads alone: a static force analysis)",
    )
    out.append(
        f"shaking force on the frame: {_vec(f.shaking_force, F)}; shaking moment "
        f"about the origin: {_moment(f.shaking_moment, M)}" + outside_words(sol.scene)
    )
    out += engine_lines(sol)
    for st in f.steps:
        if st.condition < 0.0871557:  # sin 5 deg, as the kinematic warnings
            out.append(
                f"warning: forces, step {st.index + 1} ({st.title}): condition "
                f"{st.condition:.3g} ({st.why}): the pin forces grow as 1/condition"
            )
    out += bound_lines(sol, f)
    return out


def _inertia_lines(sc, f, F, M) -> list:
    """The inertia table (each massive body's force -m a_G, couple and offset); at rest,
    the weights alone (each body's m g at G: nothing moves, no inertia)."""
    u = sc.length_unit
    if not f.inertia:
        return []
    if holding(sc):
        g = sc.gravity
        out = [
            "at rest: no inertia (nothing moves); the weights m g at G"
            + ("" if g is not None else ": none, the scene has no [gravity]")
        ]
        big = max([lk.length for lk in sc.links] + [abs(c) for i in f.inertia for c in i.G])
        for i in f.inertia if g is not None else ():
            w = (i.mass * g.g * g.direction[0], i.mass * g.g * g.direction[1])
            x, y = (fmt(quiet(c, big) / u) for c in i.G)  # (a vertical link's G: x 0, not 3e-15)
            out.append(
                f"{i.body:<10} {fmt(i.mass) + ' kg':<10} weight {_vec(w, F)} at G ({x}, {y}) "
                f"{sc.units}"
            )
        return out
    out = [start_words(sc)] if sc.at_rest else []
    out += [
        f"{'body':<10} {'mass (kg)':<10} {'inertia force -m a_G':<24} "
        f"{'couple -I alpha':<20} offset h ({sc.units})"
    ]
    for i in f.inertia:
        h = "-" if i.offset is None else fmt(abs(quiet(i.offset, M / max(F, FLOOR))) / u)
        out.append(
            f"{i.body:<10} {fmt(i.mass):<10} {_vec(i.force, F):<24} {_moment(i.couple, M):<20} {h}"
        )
    return out


def bound_lines(sol, f) -> list:
    """The forces whose estimated error bound exceeds :data:`SHOWN` (largest first), in the
    words of the kinematic bounds below the plan; empty where every force is closer."""
    b = force_bounds(sol, f)
    shown = [
        (f"F_{point} on {on} by {_body(by)}", e)
        for (point, on, by), e in b.pins.items()
        if e > SHOWN
    ]
    shown += [(f"N_{k} (guide)", e) for k, e in b.guides.items() if e > SHOWN]
    if b.effort > SHOWN:
        shown.append(
            ("the driver's " + ("torque" if f.driver in ("crank", "wheel") else "force"), b.effort)
        )
    if b.second is not None and b.second > SHOWN:
        two = f.second_crank.startswith("block ")
        shown.append(
            (
                f"the second {'collar' if two else 'crank'}'s driver's "
                + ("force" if two else "torque"),
                b.second,
            )
        )
    if not shown:
        return []
    out = [
        f"estimated error of the forces above {SHOWN:g} (the kinematic bounds through "
        "each group's equations, each dividing by its condition; relative to the largest "
        "force, a torque to it times the longest link):"
    ]
    for what, e in sorted(shown, key=lambda t: -t[1]):
        out.append(f"  {what}: {e:.2g}" if e < USELESS else f"  {what}: no useful bound")
    if any(not e < USELESS for _, e in shown):
        out.append(f"  ({NO_BOUND})")
    return out


#: what each kind of force step does, as its paragraph says it
#: a triad whose plate is three links: its sides' polygons after the links'
_TRIANGLE = (
    "The plate's three links: the first polygon is the triangle's as one plate; after the "
    "links' come the first two sides' together, as a dyad's about their common pin (the "
    "hanging links' forces on them now known, the third side's forces on them split along "
    "each side and square to it: their lines meet where it closes, the pin between them "
    "read across), and the third side's (two forces alone, equal and opposite along it, "
    "where it carries nothing of its own)"
)
_STEP_HEADS = {
    "dyad": "moments of each link about its other end give the pin force between them; each "
    "link's force balance its end's",
    "slider": "moments of the link about its other end give the guide's normal force; the block's"
    " force balance the pin force; the link's the force at its other end",
    "slotted": "moments of the lever about its pivot give the normal force between it and the "
    "block; the lever's force balance the force at its pivot; the block's the force at"
    " its pin",
    "crank": "the frame holds the crank at its pivot; the moments about the pivot give the "
    "driving torque",
    "second crank": "the frame holds the second crank at its pivot; the moments about the pivot "
    "give its own driving torque",
    "cylinder": "a two-force member: its force along its line, pushing (or pulling) the bodies at"
    " its ends (with friction at its pins, tangent to their friction circles: said below)",
    "yoke": "the yoke's balance along its path gives the slot's force on the block; across it the"
    " path's normal force, its moments the path's couple; the block's balance the crank's"
    " force on it",
    "peg": "the peg's balance gives each slot's normal force",
    "triad": "each link's moments about its known end give its force across it; the plate's three"
    " equations together (a 3x3 solve) the forces along the links; each link's balance "
    "the rest. The plate's polygon closes with the three links' forces on it (each across "
    "its link, then along it: their lines drawn through the corners); a link that carries "
    "forces or a couple of its own has its polygon too (the plate's force on it across and "
    "along it, its known forces, the force at its known end closing it), a link that "
    "carries none is a two-force member",
    "wheel centre": "the wheel's moments about its centre give the ground's grip; the link's "
    "moments about its other end the ground's normal force; the balances the pin "
    "forces",
    "block": "the block's force balance: along the guide the driver's force, across it the "
    "guide's normal force",
    "collar": "the rod's moments about its pivot give the normal force between rod and collar "
    "(the driver's force along the rod has no arm there); the moments of the collar's link "
    "about its fixed pivot the driver's force along the rod; the balances the pin forces. "
    "The collar's polygon, then the rod's (its known forces, the collar's push and the "
    "driver's back at the collar, the pivot's force closing it) and the link's (the "
    "collar's force on it, its known forces, its pivot's force closing it)",
    "second collar": "the collar's force balance: along the crank its driver's force, across it "
    "the crank's normal force; the crank feels both back",
    "rolling": "the tooth load along the line of action, at the pressure angle to the common "
    "tangent through the pitch point; the wheel's moments about its centre give its "
    "part along the tangent, the teeth push apart with that times tan phi; the "
    "wheel's force balance the pin force at its centre",
    "rack": "the tooth load along the line of action, at the pressure angle to the pitch line; "
    "the rack's balance along its guide gives its part along the guide, across it the "
    "guide's normal force, its moments the guide's couple",
    "rolling driver": "the driving wheel alone, last: the balance along and across the ground "
    "gives the ground's grip and push at the contact, the moments about its "
    "centre the driver's torque",
}


def _inertia_blocks(sol, f, F, M) -> list:
    """Section 6: the inertia forces (D'Alembert), the paragraph and each body's table row."""
    sc = sol.scene
    u = sc.length_unit
    blocks = [("h", "6. Inertia forces (D'Alembert)")]
    if holding(sc) and f.inertia:  # nothing moves: the weights alone
        return [("h", "6. Weights at rest (no inertia)")] + rest_blocks(sc, f, F, _vec)
    if not f.inertia:  # an empty [masses]: the static force analysis of the loads
        return [("h", "6. No inertia forces (a static force analysis)")] + [
            (
                "p",
                "No masses (the scene's [masses] is empty): a static force analysis, no "
                "inertia forces; the loads"
                + (f" and gravity ({sc.gravity.text}) act." if sc.gravity else " alone act."),
            )
        ]
    if sc.at_rest:  # starting from rest: the accelerations of the start
        blocks.append(
            (
                "p",
                start_words(sc)[0].upper()
                + start_words(sc)[1:]
                + f": the acceleration diagram of the start is the velocity diagram per "
                f"{_per(sol)} (section 2's virtual velocities) scaled by {_rate(sc)}, and "
                f"each a_G below is {_rate(sc)} times v_G there (the acceleration diagram drawn "
                f"per {_per(sol)}, with its centripetal terms, is not the start's).",
            )
        )
    blocks.append(
        (
            "p",
            "Each body's centre of mass G is a point of the body: its image g on "
            "the acceleration diagram gives a_G (a_G = a_P + lam (a_Q - a_P) + mu "
            "perp(a_Q - a_P), as for any point carried on the link). The inertia "
            "force m a_G acts opposite to a_G; the inertia couple is -I alpha. The "
            "book's single force: m a_G along a line offset from G by h = I alpha / "
            "(m a_G), on the side where its moment about G has the couple's sense."
            + (
                f" Gravity: {sc.gravity.text}, each weight m g at G."
                if sc.gravity
                else " No gravity (the scene gives no [gravity])."
            ),
        )
    )
    rows = []
    for i in f.inertia:
        a = math.hypot(*i.a_G)
        h = "-" if i.offset is None else fmt(abs(quiet(i.offset, M / max(F, FLOOR))) / u)
        rows.append(
            (
                i.body,
                fmt(i.mass),
                fmt(i.inertia),
                i.how,
                f"{fmt(a)} m/s^2",
                _vec(i.force, F),
                _moment(i.couple, M),
                h,
            )
        )
    blocks.append(
        (
            "table",
            (
                "body",
                "m (kg)",
                "I_G (kg m^2)",
                "G",
                "a_G",
                "m a_G, opposite to a_G",
                "-I alpha",
                f"h ({sc.units})",
            ),
            rows,
        )
    )
    return blocks


def _groups_intro(f, scale, sc=None) -> list:
    """Section 7's heading and paragraphs: how a group is solved, and the force scale and the
    bodies' numbers when the polygons are drawn at ``scale``."""
    blocks = [("h", "7. Forces, group by group (the construction's groups in reverse)")]
    blocks.append(
        (
            "p",
            "Each group's bodies are statically determinate: the moments about "
            "the pins whose forces are not yet known give the pin force between them, "
            "then each body's force balance the rest. 'Known' is the resultant of "
            + known_words(sc)
            + " and the forces of the groups solved before (the moment about the origin).",
        )
    )
    if scale is not None:
        names = ", ".join(f"{n} {'the frame' if b == FRAME else b}" for b, n in f.numbers.items())
        blocks.append(
            (
                "p",
                f"Force scale: {scale.text}, one scale for every polygon (the "
                "largest at most 12 cm across). The bodies are numbered as the books "
                f"number links ({names}); F_32 is the force on 3 by 2"
                + symbol_words(sc)
                + ". Each polygon starts at its pole "
                "with the known forces head to tail and each outer pin's force square "
                "to its link (^t, from that link's moments about the group's middle "
                "pin); the lines of the forces along the links (^n) and of a guide's "
                "normal force, drawn through the corners, meet where it closes. A block's "
                "pin force is split along its guide or slot (^n) and across it (^t); a "
                "contact's force normal to it (^n) and along it (^t); a gear's tooth load, "
                "from its moments about its centre, lies along the line of action, and the "
                "force at its centre closes its polygon.",
            )
        )
    return blocks


def _found_item(name, val, F, M) -> str:
    """One force or torque a step finds, in words with its unit and sign convention."""
    if isinstance(val, tuple):
        return f"{name} = {_vec(val, F)}"
    if name.startswith(("N at the contact", "T at the contact")):  # (not a torque T)
        return f"{name} = {fmt(quiet(val, F))} N (" + (
            "normal to the line, + pushing the wheel off it)"
            if name[0] == "N"
            else "along the line, + along perp(m))"
        )
    if name.startswith(("T ", "C ")):  # a torque, a guide's couple
        return f"{name} = {_moment(val, M)}"
    if name.startswith("F in "):  # a cylinder's force
        return f"{name} = {fmt(quiet(val, F))} N"
    if name.startswith("F "):
        return f"{name} = {fmt(quiet(val, F))} N (+ along the guide's direction)"
    return f"{name} = {fmt(quiet(val, F))} N (along the guide's normal, + to its left)"


def _step_blocks(st, f, scale, F, M, bounds) -> list:
    """One group's paragraph and list: the known forces, the equations, what it finds, its
    polygon's sides at ``scale``, its condition and its error bound."""
    items = []
    for body, (fx, fy, m) in zip(st.bodies, st.known):
        items.append(
            f"known on {body}: {_vec((fx, fy), F)}, moment about the origin {_moment(m, M)}"
        )
    items += list(st.equations)
    items += [_found_item(name, val, F, M) for name, val in st.found]
    if scale is not None:
        items += _polygon_items(st, f, scale, F)
    if st.why:
        items.append(f"condition {st.condition:.3g} ({st.why})")
    e = bounds.steps.get(st.index, 0.0)
    if e > SHOWN:
        items.append(
            f"estimated error of these forces: {e:.2g} of the largest force"
            if e < USELESS
            else f"estimated error of these forces: {NO_BOUND}"
        )
    head = _STEP_HEADS.get(st.kind, "")
    if st.kind == "triad" and len(st.bodies) == 6:  # (a plate of three links)
        head += f". {_TRIANGLE}"
    return [("p", f"Step {st.index + 1}, {st.title}: {head}."), ("list", items)]


def _driver_blocks(f, F, M, sol=None) -> list:
    """Section 8: the driving torque, the shaking force and moment, the guides' forces (and
    the friction, where the scene gives it)."""
    fric = [] if sol is None else [line.strip() for line in _friction_lines(sol, f, F, M)]
    what = "inertia, weights and loads" if sol is None else acting(sol.scene)
    what += "" if "inertia" in what else ", no inertia"
    said = (
        f" ({what}; its power balances theirs and the friction's loss)"
        if fric and not sol.scene.at_rest
        else f" ({what}; its power per {_per(sol)}, the motion about to start, balances theirs)"
        if fric
        else f" ({what}; its power balances theirs)"
    )
    items = (
        fric
        + [line + said for line in _driver_lines(f, F, M, "")]
        + [
            f"shaking force (on the frame, through its pins and guides): "
            f"{_vec(f.shaking_force, F)}",
            f"shaking moment about the origin (with the driver's reaction): "
            f"{_moment(f.shaking_moment, M)}",
        ]
    )
    items += [
        f"guide at {g.key}: {_vec(g.force, F)} on block {g.point}"
        + (f", its couple {_moment(g.couple, M)}" if _rack_couple(f, g) else "")
        for g in f.guides
    ]
    items += [
        f"contact of {_wheel(c)} with {_base(c)}: {_vec(c.force, F)} on it; " + c.grip_words()
        for c in f.contacts
    ]
    return [("h", "8. The driving torque and the frame"), ("list", items)]


def force_blocks(sol, scale=None) -> list:
    """The ``steps`` document's blocks for the forces (``("h", text)``, ``("p", text)``,
    ``("list", items)``, ``("table", header, rows)``), numbered after section 5;
    ``scale``: the force polygons' scale, when the sides are to be given in cm at it."""
    sc = sol.scene
    if not sc.has_forces:
        return []
    refused = sol.forces_refused
    if refused:
        return [("h", "6. Forces"), ("p", refused)]
    f = sol.forces
    F, M = _scales(sol, f)
    blocks = _inertia_blocks(sol, f, F, M)
    blocks += _groups_intro(f, scale, sc)
    bounds = force_bounds(sol, f)
    for st in f.steps:
        blocks += _step_blocks(st, f, scale, F, M, bounds)
    blocks += _driver_blocks(f, F, M, sol)
    return blocks
