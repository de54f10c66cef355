"""The step table's polygon sections (``polygon-method steps`` sections 3 to 5): the velocity
diagram (its scale, each construction in words), the read-offs (length on the drawing, the
value it gives, the exact value), angular, sliding and rubbing velocities, the input torque by
power balance, the acceleration table (centripetal v^2 / l, tangential, Coriolis), the
acceleration diagram and its read-offs; and the number helpers the whole table shares.
Everything is read from the solution and its construction records; :mod:`.steptable`
orders the sections.
"""

from __future__ import annotations

import math

from ..common.numbers import fixed as _fixed, fmt, sense_word
from ..common.tolerances import ROUNDING
from ..polygons.constructions import acceleration_constructions, velocity_constructions
from ..polygons.scales import DRAWING_PRECISION_CM, extent
from ..scene import FixedPath, GuideSlider, guide_words
from ..scene.link_loads import across_words, load_force
from ..solver.derived import transmission_angle

__all__ = [
    "read_off",
    "key_of",
    "link_name",
    "length_words",
    "extent_cm",
    "turn_words",
    "polar_words",
    "velocity_section",
    "readoff_section",
    "acceleration_section",
]


def read_off(value: float, scale) -> tuple[float, float]:
    """(length read on the drawing in cm, the value it gives) for a vector of ``value``
    (SI) drawn at ``scale``: the length rounded to the drawing's precision (0.05 cm).

    >>> from polygon_method.polygons.scales import parse_scale
    >>> read_off(0.4005, parse_scale("1 cm = 0.05 m/s"))
    (8.0, 0.4)
    """
    q = DRAWING_PRECISION_CM
    cm = round(abs(value) / scale.per_cm / q) * q
    cm = round(cm, 2)
    return cm, cm * scale.per_cm


def key_of(sym: str, names) -> str:
    """``v_CB``; ``v_P-O4`` when a name has digits (as in answer keys)."""
    sep = "-" if any(len(n) > 1 for n in names) else ""
    return f"{sym}_{sep.join(names)}"


def link_name(sol, key):
    """The name a link goes by in the table: its key as the scene writes it."""
    return key


def length_words(sol, metres: float) -> str:
    """A length (m) in the scene's own unit, to five figures: "180 mm"."""
    return f"{fmt(metres / sol.scene.length_unit, 5)} {sol.scene.units}"


def extent_cm(points, scale):
    """How many cm of the drawing ``points`` span at ``scale``."""
    return extent(points) / scale.per_cm


def turn_words(w) -> str:
    """An angular velocity or acceleration in words: "5.15 rad/s cw", or 0."""
    if abs(w) <= ROUNDING:
        return "0"
    return f"{fmt(abs(w))} rad/s {sense_word(w)}"


def polar_words(v) -> str:
    """A vector as size and direction ("1.2 m/s at 135 deg"), or 0."""
    m = math.hypot(*v)
    if m <= ROUNDING * (1 + abs(v[0]) + abs(v[1])):
        return "0"
    ang = round(math.degrees(math.atan2(v[1], v[0])), 9) % 360  # no rounding noise off an axis
    return f"{fmt(m)} m/s at {fmt(ang, 4)} deg"


def _vector_name(v) -> str:
    """``v_CB`` style key for a construction Vector, with '-' where names have digits (a
    polygon's velocity or acceleration, by its points); a component's own name."""
    if v.points:
        return key_of(v.name[0], v.points)
    return v.name


def _vector_points(sol, v, c) -> tuple:
    """The points whose error bounds bound a construction vector's: the two of ``v_CB``,
    the one of ``v_C``; else those the step reads and finds (a centripetal, tangential or
    Coriolis component)."""
    names = set(sol.P)
    if v.points and all(p in names for p in v.points):
        return v.points
    st = sol.plan.steps[c.step] if 0 <= c.step < len(sol.plan.steps) else None
    got = tuple(p for p in ((*st.needs, *st.finds) if st is not None else ()) if p in names)
    return got or None


def _is_ground_relative(sol, v) -> bool:
    """A relative vector to a fixed point duplicates the absolute one."""
    return len(v.points) == 2 and v.points[1] in sol.scene.ground


def _readoff_rows(sol, constructions, scale, unit):
    """(name, label, length cm, read value, exact value) of every vector a construction
    finds; the crank's own vector is set out, not read (its length is exact)."""
    rows, seen = [], set()
    kind = "v" if unit == "m/s" else "a"
    for c in constructions:
        for v in c.found:
            name = _vector_name(v)
            if name in seen or _is_ground_relative(sol, v) or v.kind == "centripetal":
                continue
            seen.add(name)
            mag = sol.shown(v.magnitude, kind, _vector_points(sol, v, c))  # equal images: 0
            if c.step == 0 and c.phase == "velocity":
                cm, val = scale.cm(mag), mag
            else:
                cm, val = read_off(mag, scale)
            rows.append((name, v.label, f"{cm:.2f}", f"{_fixed(val)} {unit}", f"{fmt(mag)} {unit}"))
    return rows


def velocity_section(doc, sol, vscale):
    """Section 3: the velocity scale and each construction of the velocity diagram, in the order
    drawn."""
    doc.h("3. Velocity diagram")
    cons = velocity_constructions(sol)
    doc.p(
        f"Velocity scale: {vscale.text} (the diagram fits "
        f"{fmt(extent_cm(list(sol.V.values()) + [(0.0, 0.0)], vscale), 3)} cm). Fixed "
        "points have their images at the pole o."
    )
    items = []
    for c in cons:
        t = f"Step {c.step + 1} ({c.title}): {c.text}"
        if c.step == 0:
            t += f"; at {vscale.text} that is {vscale.cm(c.found[0].magnitude):.2f} cm"
        for g in c.given:
            t += f"; set out {g.name} = {fmt(g.magnitude)} m/s ({vscale.cm(g.magnitude):.2f} cm)"
        if c.lines:
            if sol.plan.steps[c.step].transmission() is None:  # no transmission angle
                t += f" (condition {fmt(c.condition, 3)})"
            else:
                t += (
                    f" (the lines cross at "
                    f"{fmt(transmission_angle(float(c.condition)), 3)} deg, condition "
                    f"{fmt(c.condition, 3)}"
                    + ("; read carefully" if c.condition < 0.5 else "")
                    + ")"
                )
        items.append(t)
    doc.items(items)


def _angular_velocity_items(sol):
    sc = sol.scene
    items = []
    for lk in sc.links:
        if lk.key in sol.plan.fixed_links:
            continue
        w = sol.shown(sol.W[lk.key], "omega", lk.key)
        v = sol.shown(sol.speed(lk.q, lk.p), "v", (lk.q, lk.p))
        if lk.key == sc.input.crank:
            items.append(
                f"omega_{lk.key} = {fmt(abs(w))} rad/s {sense_word(w)} "
                + (
                    f"(the crank's, {sc.input.speed_text})"
                    if sc.input.found_from and sc.input.speed_text.startswith("found from")
                    else "(the input)"
                    if sc.input.given is None
                    else f"(the crank's, found from {sc.input.given.key})"
                )
            )
            continue
        rel = key_of("v", (lk.q, lk.p))
        items.append(
            f"omega_{lk.key} = {rel} / {lk.key} = {fmt(v)} / {fmt(lk.length, 5)} = "
            f"{fmt(abs(w))} rad/s {sense_word(w)}".rstrip()
        )
    for c in sc.cylinders:  # the barrel's point under the rod's end: omega x its length
        w = sol.shown(sol.W[c.key], "omega", c.key)
        L = sol.cylinder_length(c.key)
        items.append(
            f"omega_{c.key} = (the barrel's point under {c.rod}) / {c.barrel}{c.rod} "
            f"= {fmt(abs(w) * L)} / {fmt(L, 5)} = {fmt(abs(w))} rad/s "
            f"{sense_word(w)}".rstrip()
        )
    return items


def _sliding_items(sol):
    out = []
    for s in sol.scene.blocks:  # (a driving wheel's centre: its velocity said above)
        vs = sol.S[s.key][0]
        if vs == 0:  # (noise is 0 here: the solution is tidied)
            guide = (
                f"the {guide_words(s.label)}"
                if isinstance(s, FixedPath)
                else f"the slot of yoke {s.yoke}"
                if hasattr(s, "yoke")
                else s.guide
            )
            out.append(
                f"vs_{s.key} = 0 m/s: {s.point} does not slide along {guide} at this instant"
            )
            continue
        out.append(f"vs_{s.key} = {fmt(abs(vs))} m/s {sliding_words(s, vs)}")
    return out


def sliding_words(s, value) -> str:
    """Which way a sliding velocity or acceleration ``value`` (signed along the guide of
    slider ``s``) points, in words: "along QR, from Q towards R", "along the horizontal
    path (- direction)"."""
    if isinstance(s, FixedPath):
        return f"along the {guide_words(s.label)} ({'+' if value >= 0 else '-'} direction)"
    if hasattr(s, "yoke"):
        return (
            f"along the {guide_words(s.label, 'slot', f'yoke {s.yoke}')} "
            f"({'+' if value >= 0 else '-'} direction), relative to the yoke"
        )
    a, b = (s.first, s.second) if value >= 0 else (s.second, s.first)
    return f"along {s.guide}, from {a} towards {b}"


def _rubbing_items(sol):
    out = []
    for name, r in sol.rubbing.items():
        rr = fmt(r.radius, 5)
        if not r.pairs:
            out.append(f"pin {name}: joins only {', '.join(r.bodies) or 'nothing'}: no rubbing")
            continue
        for pair, val in r.pairs.items():
            a, b = pair.split("|")
            wa, wb = r.bodies[a], r.bodies[b]
            if wa == 0 or wb == 0:
                moving, w = (b, wb) if wa == 0 else (a, wa)
                still = a if wa == 0 else b
                rule = f"{still} does not turn: rub = omega_{moving} r = {fmt(abs(w))} x {rr}"
            elif (wa > 0) != (wb > 0):
                rule = (
                    f"{a} turns {sense_word(wa)}, {b} {sense_word(wb)} (opposite senses): "
                    f"rub = (omega_{a} + omega_{b}) r = ({fmt(abs(wa))} + {fmt(abs(wb))}) "
                    f"x {rr}"
                )
            else:
                rule = (
                    f"{a} and {b} both turn {sense_word(wa)}: rub = |omega_{a} - "
                    f"omega_{b}| r = |{fmt(abs(wa))} - {fmt(abs(wb))}| x {rr}"
                )
            out.append(
                f"pin {name} (r = {length_words(sol, r.radius)}), {a} and {b}: {rule} = "
                f"{fmt(val)} m/s"
            )
        if len(r.pairs) > 1:
            out.append(f"pin {name}: the largest is {fmt(r.rubbing_velocity)} m/s")
    return out


def _torque_items(sol):
    sc = sol.scene
    if sol.input_torque is None:
        return []
    inp = sc.input
    block = not sol.plan.steps[0].periodic  # a block driver: a force along its guide
    out = [
        "power balance (no friction, no inertia): "
        + (f"F vs_{inp.tip}" if block else f"T omega_{inp.crank}")
        + " + sum F . v = 0"
    ]
    for load, (target, p) in zip(sc.loads, sol.power_terms):
        if load.force is not None:
            fx, fy = load_force(load, sol.P)  # (a force against a link: at this instant)
            F = math.hypot(fx, fy)
            v = sol.speed(target)
            said = "" if load.across is None else f" (F: {across_words(load)})"
            if F * v > 0:  # (both may be positive and their product underflow to 0)
                vx, vy = sol.V[target]
                cos = (fx * vx + fy * vy) / (F * v)
                ang = math.degrees(math.acos(max(-1.0, min(1.0, cos))))
                out.append(
                    f"{target}: F . v_{target} = {fmt(F)} N x {fmt(v)} m/s x "
                    f"cos {fmt(ang, 4)} deg = {fmt(p)} W{said}"
                )
            else:
                out.append(f"{target}: F . v_{target} = {fmt(p)} W{said}")
        else:
            out.append(
                f"torque on {target}: T_{target} omega_{target} = "
                f"{fmt(load.torque)} x {fmt(sol.W[target])} = {fmt(p)} W"
            )
    for what, p in sol.power_terms[len(sc.loads) :]:  # a passive cylinder's given force
        key = what.removeprefix("cylinder ")
        out.append(f"{what}: F vs_{key.replace('-', '')} = {fmt(p)} W (its given force)")
    total = sum(p for _, p in sol.power_terms)
    t = sol.input_torque
    if block:
        out.append(
            f"F = -(sum F . v) / vs_{inp.tip} = {fmt(-total)} / {fmt(inp.omega)} = "
            f"{fmt(t)} N along the guide ({sol.plan.steps[0].sense(t)})"
        )
        return out
    out.append(
        f"T = -(sum F . v) / omega_{inp.crank} = {fmt(-total)} / {fmt(inp.omega)} = "
        f"{fmt(abs(t))} N m {sense_word(t)}".rstrip()
    )
    if sol.cylinder_force is not None:  # the cylinder drives: its force, not a torque
        key, f = sol.cylinder_force
        out.append(
            f"the cylinder {key} drives: F vs_{key} = T omega_{inp.crank}, F = {fmt(t)} x "
            f"{fmt(inp.omega)} / {fmt(inp.given.value)} = {fmt(abs(f))} N "
            + ("pushing its ends apart" if f >= 0 else "pulling its ends together")
        )
    return out


def readoff_section(doc, sol, vscale):
    """Section 4: each vector read off the velocity diagram (its length in cm, what it gives, the
    exact value), then the angular, sliding and rubbing velocities and the input torque."""
    doc.h("4. Read-offs from the velocity diagram")
    doc.p(
        f"Lengths are read to {DRAWING_PRECISION_CM} cm; 'read' is what that length gives "
        f"at {vscale.text}, 'exact' the solver's value."
    )
    doc.table(
        ("vector", "on the diagram", "length (cm)", "read", "exact"),
        _readoff_rows(sol, velocity_constructions(sol), vscale, "m/s"),
    )
    doc.p(
        "Angular velocities (omega = relative velocity / length; the sense is the way the "
        "relative velocity turns the link):"
    )
    doc.items(_angular_velocity_items(sol))
    sliding = _sliding_items(sol)
    if sliding:
        doc.p("Sliding velocities (relative to the guide):")
        doc.items(sliding)
    if sol.scene.pins:
        doc.p(
            "Rubbing velocities (|omega_1 - omega_2| r, with signed omegas: the sum of the "
            "magnitudes when the two turn in opposite senses, the difference when alike):"
        )
        doc.items(_rubbing_items(sol))
    if sol.input_torque is not None:
        doc.p("Input torque:" if sol.plan.steps[0].periodic else "Input force:")
        doc.items(_torque_items(sol))


def _orient(sol):
    """link key -> (X, Y): its relative motion as the plan takes it (X relative to Y)."""
    out = {}
    for st in sol.plan.steps:
        out.update(st.orient())
    for lk in sol.scene.links:
        out.setdefault(lk.key, (lk.q, lk.p))
    return out


def _acceleration_table(sol):
    sc = sol.scene
    orient = _orient(sol)
    coriolis = {}
    for s in sc.sliders:
        if isinstance(s, GuideSlider):
            g = sc.link(s.guide).key
            vs = sol.S[s.key][0]
            cor = math.hypot(*sol.coriolis(s.key))
            coriolis[g] = (
                f"2 omega v = 2 x {fmt(abs(sol.W[g]))} x {fmt(abs(vs))} = "
                f"{fmt(cor)} (block {s.key}, perp. to {s.guide})"
            )
    rows = []
    for lk in sc.links:
        if lk.key in sol.plan.fixed_links:
            continue
        X, Y = orient[lk.key]
        v = sol.shown(sol.speed(X, Y), "v", (X, Y))  # two equal images: 0
        L = lk.length
        cen = v * v / L
        al = sol.Al[lk.key]
        tan = abs(al) * L
        if lk.key == sc.input.crank:
            tcell = f"alpha x {lk.key} = {fmt(tan)}"
        else:
            tcell = f"perp. to {X}{Y}; found: {fmt(tan)}"
        rows.append(
            (
                lk.key,
                fmt(L, 5),
                f"{key_of('v', (X, Y))} = {fmt(v)}",
                f"{fmt(v)}^2 / {fmt(L, 5)} = {fmt(cen)}",
                f"along {X}{Y}, towards {Y}",
                tcell,
                coriolis.get(lk.key, "-"),
            )
        )
    return rows


def acceleration_section(doc, sol, ascale):
    """Section 5: the acceleration table (centripetal, tangential, Coriolis components), the
    acceleration diagram's constructions and its read-offs, the angular accelerations."""
    sc = sol.scene
    doc.h("5. Accelerations")
    doc.table(
        (
            "link",
            "length (m)",
            "relative velocity (m/s)",
            "centripetal v^2/l (m/s^2)",
            "its direction",
            "tangential (m/s^2)",
            "Coriolis (m/s^2)",
        ),
        _acceleration_table(sol),
    )
    cons = acceleration_constructions(sol)
    doc.p(
        f"Acceleration scale: {ascale.text} (the diagram fits "
        f"{fmt(extent_cm(list(sol.A.values()) + [(0.0, 0.0)], ascale), 3)} cm). Fixed "
        "points have their images at the pole o'."
    )
    items = []
    for c in cons:
        t = f"Step {c.step + 1} ({c.title}): {c.text}"
        set_out = [f"{g.name} {ascale.cm(g.magnitude):.2f} cm" for g in c.given if g.magnitude > 0]
        if set_out:
            t += "; lengths to set out: " + ", ".join(set_out)
        items.append(t)
    doc.items(items)
    doc.p(f"Read-offs (lengths to {DRAWING_PRECISION_CM} cm at {ascale.text}):")
    doc.table(
        ("vector", "on the diagram", "length (cm)", "read", "exact"),
        _readoff_rows(sol, cons, ascale, "m/s^2"),
    )
    items = []
    orient = _orient(sol)
    for lk in sc.links:
        if lk.key in sol.plan.fixed_links:
            continue
        al = sol.shown(sol.Al[lk.key], "alpha", lk.key)
        if lk.key == sc.input.crank:
            items.append(
                (
                    f"alpha_{lk.key} = {fmt(abs(al))} rad/s^2 {sense_word(al)} "
                    + (
                        "(the input)"
                        if sc.input.given is None
                        and not (sc.input.found_from and sc.input.speed_text.startswith("found"))
                        else "(the crank's, found above)"
                    )
                ).replace("  ", " ")
            )
            continue
        X, Y = orient[lk.key]
        tan = abs(al) * lk.length
        items.append(
            f"alpha_{lk.key} = tangential of {key_of('a', (X, Y))} / {lk.key} = "
            f"{fmt(tan)} / {fmt(lk.length, 5)} = {fmt(abs(al))} rad/s^2 "
            f"{sense_word(al)}".rstrip()
        )
    doc.p("Angular accelerations (alpha = tangential component / length):")
    doc.items(items)
    sl = []
    for s in sc.blocks:  # (a driving wheel's centre: its acceleration said above)
        a_s = sol.S[s.key][1]
        cor = math.hypot(*sol.coriolis(s.key))
        t = f"as_{s.key} = {fmt(a_s)} m/s^2 (signed along the guide)"
        if isinstance(s, GuideSlider):
            t = t.replace("the guide", f"{s.along}, from {s.first} towards {s.second}")
            t += f"; Coriolis component {fmt(cor)} m/s^2"
        sl.append(t)
    if sl:
        doc.p("Sliding accelerations:")
        doc.items(sl)
