"""The hand solution in the textbook's order (``polygon-method steps``).

1. configuration diagram (space scale, the given lengths and angles, how each point is
   found); 2. the input link's arithmetic; 3. the velocity diagram (scale, each
   construction in words); 4. read-offs (length on the drawing, the value it gives, the
   exact value), angular velocities with their senses, sliding and rubbing velocities, the
   input torque by power balance; 5. the acceleration table (centripetal v^2 / l,
   tangential, Coriolis), the acceleration diagram and its read-offs, angular
   accelerations.

Everything is read from the solution and its construction records
(:mod:`polygon_method.polygons.constructions`); no kinematics is recomputed here.

>>> from polygon_method import parse_scene, solve
>>> sol = solve(parse_scene('''
... [ground]
... O = [0, 0]
... [links]
... OA = 180
... AB = 600
... [sliders]
... B = { path = "horizontal" }
... [input]
... crank = "OA"
... angle = 45
... speed = "180 rpm ccw"
... '''))
>>> text = steps_text(sol)
>>> "omega_OA = 2 pi N / 60 = 2 pi x 180 / 60 = 18.85 rad/s ccw" in text
True
"""

from __future__ import annotations

import math
import re
import textwrap
from dataclasses import replace

from ..solver.derived import transmission_angle
from ..solver.given import working
from ..common.numbers import fixed as _fixed, fmt, sense_word
from .forces import force_blocks
from ..polygons.constructions import acceleration_constructions, velocity_constructions
from ..polygons.scales import DRAWING_PRECISION_CM, diagram_scales, extent, force_scale
from ..scene import FixedPath, GuideSlider, guide_words, split_name
from ..solver.kinematics import evaluate
from ..motion.solution import Solution, tidied

__all__ = ["steps_text", "steps_blocks", "read_off", "fmt", "sense_word"]

_WIDTH = 92


# --------------------------------------------------------------------------- numbers


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


def _key(sym: str, names) -> str:
    """``v_CB``; ``v_P-O4`` when a name has digits (as in answer keys)."""
    sep = "-" if any(len(n) > 1 for n in names) else ""
    return f"{sym}_{sep.join(names)}"


def _link_name(sol, key):
    return key


def _len_unit(sol, metres: float) -> str:
    return f"{fmt(metres / sol.scene.length_unit, 5)} {sol.scene.units}"


# --------------------------------------------------------------------------- document


class _Doc:
    """Blocks rendered as terminal text or Markdown."""

    def __init__(self):
        self.blocks = []

    def h(self, text):
        self.blocks.append(("h", text))

    def p(self, text):
        self.blocks.append(("p", text))

    def items(self, items):
        items = [i for i in items if i]
        if items:
            self.blocks.append(("list", items))

    def table(self, header, rows):
        if rows:
            self.blocks.append(("table", tuple(header), [tuple(map(str, r)) for r in rows]))

    def render(self, fmt_: str) -> str:
        out = []
        for b in self.blocks:
            kind = b[0]
            if fmt_ == "markdown":
                if kind == "h":
                    out.append(f"## {b[1]}")
                elif kind == "p":
                    out.append(b[1])
                elif kind == "list":
                    out.append("\n".join(f"- {i}" for i in b[1]))
                else:
                    esc = lambda c: c.replace("|", "\\|")  # noqa: E731
                    lines = ["| " + " | ".join(esc(c) for c in b[1]) + " |",
                             "|" + "|".join(" --- " for _ in b[1]) + "|"]
                    lines += ["| " + " | ".join(esc(c) for c in r) + " |" for r in b[2]]
                    out.append("\n".join(lines))
            else:
                if kind == "h":
                    out.append(f"{b[1]}\n{'=' * len(b[1])}")
                elif kind == "p":
                    out.append(textwrap.fill(b[1], _WIDTH))
                elif kind == "list":
                    out.append("\n".join(textwrap.fill(i, _WIDTH, initial_indent="  - ",
                                                       subsequent_indent="    ")
                                         for i in b[1]))
                else:
                    rows = [b[1]] + b[2]
                    w = [max(len(r[i]) for r in rows) for i in range(len(b[1]))]
                    lines = ["  " + "  ".join(c.ljust(x) for c, x in zip(b[1], w)).rstrip(),
                             "  " + "  ".join("-" * x for x in w)]
                    lines += ["  " + "  ".join(c.ljust(x) for c, x in zip(r, w)).rstrip()
                              for r in b[2]]
                    out.append("\n".join(lines))
        sep = "\n\n"
        return sep.join(out) + "\n"


# --------------------------------------------------------------------------- sections


def _speed_working(sol) -> tuple[str, str]:
    """(how omega follows from the stated speed, the crank's omega with sense)."""
    inp = sol.scene.input
    w = inp.omega
    name = f"omega_{inp.crank}"
    result = f"{fmt(abs(w))} rad/s {sense_word(w)}"
    lines = working(sol.plan, fmt)
    if lines is not None:  # the motion given on another quantity: scaled from 1 rad/s
        return "; ".join(lines), result
    m = re.match(r"^\s*([-+]?[0-9.]+(?:[eE][-+]?\d+)?)\s*([^\s]*)", inp.speed_text)
    number, unit = (m.group(1), m.group(2).lower()) if m else ("", "")
    if unit in ("rpm", "r.p.m.", "r.p.m", "rev/min"):
        return (f"N = {number} rpm; {name} = 2 pi N / 60 = 2 pi x {number} / 60 = {result}",
                result)
    if unit in ("rps", "r.p.s.", "r.p.s", "rev/s"):
        return f"n = {number} rps; {name} = 2 pi n = 2 pi x {number} = {result}", result
    if unit == "deg/s":
        return f"{name} = {number} deg/s x pi / 180 = {result}", result
    return f"{name} = {result} (given)", result


def _config(doc, sol, space):
    sc = sol.scene
    u = sc.length_unit
    doc.h("1. Configuration diagram")
    doc.p(f"Space scale: {space.text} (the mechanism fits "
          f"{fmt(_extent_cm(sol.P.values(), space), 3)} cm of the page).")
    rows = []
    for lk in sc.links:
        fixed = " (fixed)" if lk.key in sol.plan.fixed_links else ""
        rows.append((lk.key + fixed, fmt(lk.length / u, 5), f"{space.cm(lk.length):.2f}"))
    doc.table(("link", f"length ({sc.units})", "on the drawing (cm)"), rows)
    g = [f"{n} ({fmt(x / u, 5)}, {fmt(y / u, 5)})" for n, (x, y) in sc.ground.items()]
    inp = sc.input
    facts = [f"fixed points ({sc.units}): " + ", ".join(g)]
    names = list(sc.ground)
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if not sc.has_link(a + b if len(a) == len(b) == 1 else f"{a}-{b}"):
                d = math.dist(sc.ground[a], sc.ground[b])
                if d > 0:
                    facts.append(f"{a}{b} = {fmt(d / u, 5)} {sc.units} (between the fixed "
                                 "points)")
    driver = sol.plan.steps[0]
    if not driver.periodic:  # a block driven along its guide: its place is given
        facts.append(f"driving {driver.title}, at s_{inp.tip} = {_len_unit(sol, inp.angle)} "
                     f"from {driver.origin} along it (given)")
        _slider_facts(facts, sc, u)
        _drawing(doc, sol, space, facts)
        return
    ang = math.degrees(inp.angle)
    said = f"{inp.angle_words}; " if inp.angle_words else ""
    crank_dir = f"crank {inp.crank} at {fmt(ang, 5)} deg ({said}direction {inp.pivot}" \
        f"{inp.tip}, counter-clockwise from the +x axis)"
    others = [n for n in sc.ground if n != inp.pivot]
    if len(others) == 1:
        ox, oy = sc.ground[inp.pivot]
        gx, gy = sc.ground[others[0]]
        ref = math.atan2(gy - oy, gx - ox)
        between = abs((inp.angle - ref + math.pi) % (2 * math.pi) - math.pi)
        crank_dir += f"; angle {others[0]}{inp.pivot}{inp.tip} = {fmt(math.degrees(between), 4)} deg"
    facts.append(crank_dir)
    _slider_facts(facts, sc, u)
    _drawing(doc, sol, space, facts)


def _slider_facts(facts, sc, u):
    for s in sc.sliders:
        if s.point == sc.input.block:  # the driving block: said above
            continue
        if s.slot:  # a peg in two slots
            facts.append(f"peg {s.point} in the slot of {s.guide}" if isinstance(s, GuideSlider)
                         else f"peg {s.point} in a fixed {guide_words(s.label, 'slot')} through "
                         f"({fmt(s.through[0] / u, 5)}, {fmt(s.through[1] / u, 5)})")
        elif isinstance(s, FixedPath) and any(getattr(t, "yoke", None) == s.point
                                              for t in sc.sliders):
            facts.append(f"yoke {s.point} on a {guide_words(s.label)} through "
                         f"({fmt(s.through[0] / u, 5)}, {fmt(s.through[1] / u, 5)})")
        elif isinstance(s, FixedPath):
            facts.append(f"slider {s.point} on a {guide_words(s.label)} through "
                         f"({fmt(s.through[0] / u, 5)}, {fmt(s.through[1] / u, 5)})")
        elif hasattr(s, "yoke"):  # the slot of a translating yoke
            facts.append(f"block {s.point} slides in the {guide_words(s.label, 'slot', f'yoke {s.yoke}')}")
        else:
            facts.append(f"block {s.point} slides along {s.guide}")


def _drawing(doc, sol, space, facts):
    sc, u = sol.scene, sol.scene.length_unit
    doc.items(facts)
    doc.p("Drawing the configuration:")
    doc.items([_position_words(sol, st, space) for st in sol.plan.steps])
    rows = [(p, fmt(sol.P[p][0] / u, 5), fmt(sol.P[p][1] / u, 5)) for p in sc.point_names]
    doc.table(("point", f"x ({sc.units})", f"y ({sc.units})"), rows)


def _extent_cm(points, scale):
    return extent(points) / scale.per_cm


def _which(sol, X):
    hint = sol.scene.assembly.get(X)
    if hint is None:
        return "as taken by default (see the notes)"
    if isinstance(hint, str):
        return f"the one {'to the ' if hint in ('left', 'right') else ''}{hint}"
    u = sol.scene.length_unit
    return f"the one near ({fmt(hint[0] / u, 4)}, {fmt(hint[1] / u, 4)})"


def _position_words(sol, st, space) -> str:
    L = lambda x: f"{_len_unit(sol, x)} ({space.cm(x):.2f} cm)"  # noqa: E731
    inp = sol.scene.input
    angle = (fmt(math.degrees(inp.angle), 5) if sol.plan.steps[0].periodic
             else _len_unit(sol, inp.angle))  # a block driver's place along its guide
    return st.position_words(L, lambda point: _which(sol, point), angle)


def _input(doc, sol):
    sc = sol.scene
    inp = sc.input
    driver = sol.plan.steps[0]
    own = driver.input_items(sc, fmt)
    if own is not None:  # a driver of its own words (a wheel rolling on the ground)
        doc.h(f"2. {own[0]}")
        doc.items(list(own[1]))
        return
    if not driver.periodic:  # a block driven along its guide: its velocity and rate given
        doc.h(f"2. Input block {inp.tip}")
        vs, a_s = inp.omega, inp.alpha
        doc.items([f"vs_{inp.tip} = {fmt(abs(vs))} m/s {driver.sense(vs)} along the guide "
                   "(given)",
                   f"as_{inp.tip} = {fmt(abs(a_s))} m/s^2 {driver.sense(a_s)} along the guide "
                   "(given)" if a_s else
                   f"as_{inp.tip} = 0 (the block moves at a steady speed)"])
        return
    doc.h(f"2. Input link {inp.crank}" + (f" and {inp.second.crank}" if inp.second else ""))
    working, _ = _speed_working(sol)
    r = sc.link(inp.crank).length
    v = sol.speed(inp.tip)
    items = [working,
             f"v_{inp.tip} = omega_{inp.crank} x {inp.crank} = {fmt(abs(inp.omega))} x "
             f"{fmt(r, 5)} = {fmt(v)} m/s, perpendicular to {inp.crank}"]
    if inp.alpha:
        items.append(f"alpha_{inp.crank} = {fmt(abs(inp.alpha))} rad/s^2 "
                     f"{sense_word(inp.alpha)} "
                     + ("(given)" if inp.given is None
                        else f"(found from {inp.given.rate_key or 'the given motion'}, "
                             "above)"))
    else:
        items.append(f"alpha_{inp.crank} = 0 (the crank turns at a uniform speed)")
    two = inp.second
    if two is not None:
        r2 = sc.link(two.crank).length
        items.append(f"the second input, {two.crank}: omega_{two.crank} = "
                     f"{fmt(abs(two.omega))} rad/s {sense_word(two.omega)} (given); v_{two.tip} "
                     f"= {fmt(abs(two.omega))} x {fmt(r2, 5)} = {fmt(sol.speed(two.tip))} m/s, "
                     f"perpendicular to {two.crank}; alpha_{two.crank} = "
                     f"{fmt(abs(two.alpha))} rad/s^2 {sense_word(two.alpha)}")
    doc.items(items)
    if two is not None:
        _superposition(doc, sol)


def _superposition(doc, sol):
    """Two inputs: the velocity polygon as the sum of the polygons for each input alone
    (the velocities are linear in the two speeds), as a book draws it."""
    sc = sol.scene
    inp, two = sc.input, sc.input.second
    plan = sol.plan
    k = next(i for i, st in enumerate(plan.steps) if st.kind == "second crank")
    held = tuple(prm if i != k else prm[:2] + (0.0, 0.0) + prm[4:]
                 for i, prm in enumerate(plan.dims.steps))
    first = evaluate(plan, omega=inp.omega, alpha=0.0, upto=1,
                     dims=replace(plan.dims, steps=held))
    second = evaluate(plan, omega=0.0, alpha=0.0, upto=1)
    doc.p(f"Two inputs (two degrees of freedom): the velocities are linear in the two speeds, "
          f"so the velocity polygon is drawn for {inp.crank} alone ({two.crank} held), then "
          f"for {two.crank} alone ({inp.crank} held), and the two are added, image by image: "
          f"v = v' + v''.")
    rows = []
    for p in sc.point_names:
        if p in sc.ground:
            continue
        a, b = first.V[p], second.V[p]
        rows.append((p, _polar(a), _polar(b), _polar((a[0] + b[0], a[1] + b[1]))))
    doc.table(("point", f"v' ({inp.crank} alone)", f"v'' ({two.crank} alone)",
               "v = v' + v''"), rows)
    doc.p("The angular velocities add in the same way (for gears, the tabular method: each "
          "input alone, then the sum):")
    rows = [(lk.key, _turn(first.W[lk.key]), _turn(second.W[lk.key]),
             _turn(first.W[lk.key] + second.W[lk.key])) for lk in sc.links]
    doc.table(("link", f"omega' ({inp.crank} alone)", f"omega'' ({two.crank} alone)",
               "omega = omega' + omega''"), rows)


def _turn(w) -> str:
    if abs(w) <= 1e-12:
        return "0"
    return f"{fmt(abs(w))} rad/s {sense_word(w)}"


def _polar(v) -> str:
    m = math.hypot(*v)
    if m <= 1e-12 * (1 + abs(v[0]) + abs(v[1])):
        return "0"
    ang = round(math.degrees(math.atan2(v[1], v[0])), 9) % 360  # no 1e-15 deg off an axis
    return f"{fmt(m)} m/s at {fmt(ang, 4)} deg"


def _vector_name(v) -> str:
    """``v_CB`` style key for a construction Vector, with '-' where names have digits."""
    m = re.match(r"^(v|a|vs|as)_([A-Z0-9]+)$", v.name)
    if m:
        return _key(m.group(1), split_name(m.group(2)))
    return v.name


def _vector_points(sol, v, c) -> tuple:
    """The points whose error bounds bound a construction vector's: the two of ``v_CB``,
    the one of ``v_C``; else those the step reads and finds (a centripetal, tangential or
    Coriolis component)."""
    m = re.match(r"^(v|a)_([A-Z0-9]+)$", v.name)
    names = set(sol.P)
    if m:
        got = tuple(split_name(m.group(2)))
        if got and all(p in names for p in got):
            return got
    st = sol.plan.steps[c.step] if 0 <= c.step < len(sol.plan.steps) else None
    got = tuple(p for p in ((*st.needs, *st.finds) if st is not None else ()) if p in names)
    return got or None


def _is_ground_relative(sol, v) -> bool:
    """A relative vector to a fixed point duplicates the absolute one."""
    m = re.match(r"^(v|a)_([A-Z0-9]+)$", v.name)
    if not m:
        return False
    names = split_name(m.group(2))
    return len(names) == 2 and names[1] in sol.scene.ground


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
            rows.append((name, v.label, f"{cm:.2f}", f"{_fixed(val)} {unit}",
                         f"{fmt(mag)} {unit}"))
    return rows


def _velocity(doc, sol, vscale):
    doc.h("3. Velocity diagram")
    cons = velocity_constructions(sol)
    doc.p(f"Velocity scale: {vscale.text} (the diagram fits "
          f"{fmt(_extent_cm(list(sol.V.values()) + [(0.0, 0.0)], vscale), 3)} cm). Fixed "
          "points have their images at the pole o.")
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
                t += (f" (the lines cross at "
                      f"{fmt(transmission_angle(float(c.condition)), 3)} deg, condition "
                      f"{fmt(c.condition, 3)}" + ("; read carefully" if c.condition < 0.5
                                                  else "") + ")")
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
            items.append(f"omega_{lk.key} = {fmt(abs(w))} rad/s {sense_word(w)} "
                         + ("(the input)" if sc.input.given is None
                            else f"(the crank's, found from {sc.input.given.key})"))
            continue
        rel = _key("v", (lk.q, lk.p))
        items.append(f"omega_{lk.key} = {rel} / {lk.key} = {fmt(v)} / {fmt(lk.length, 5)} = "
                     f"{fmt(abs(w))} rad/s {sense_word(w)}".rstrip())
    for c in sc.cylinders:  # the barrel's point under the rod's end: omega x its length
        w = sol.shown(sol.W[c.key], "omega", c.key)
        L = sol.cylinder_length(c.key)
        items.append(f"omega_{c.key} = (the barrel's point under {c.rod}) / {c.barrel}{c.rod} "
                     f"= {fmt(abs(w) * L)} / {fmt(L, 5)} = {fmt(abs(w))} rad/s "
                     f"{sense_word(w)}".rstrip())
    return items


def _sliding_items(sol):
    out = []
    for s in sol.scene.sliders:
        if getattr(s, "wheel", ""):  # a driving wheel's centre: its velocity said above
            continue
        vs = sol.S[s.key][0]
        if vs == 0:  # (noise is 0 here: the solution is tidied)
            guide = (f"the {guide_words(s.label)}" if isinstance(s, FixedPath) else
                     f"the slot of yoke {s.yoke}" if hasattr(s, "yoke") else s.guide)
            out.append(f"vs_{s.key} = 0 m/s: {s.point} does not slide along {guide} at "
                       "this instant")
            continue
        if isinstance(s, FixedPath):
            along = f"along the {guide_words(s.label)} ({'+' if vs >= 0 else '-'} direction)"
        elif hasattr(s, "yoke"):
            along = (f"along the {guide_words(s.label, 'slot', f'yoke {s.yoke}')} ({'+' if vs >= 0 else '-'} "
                     "direction), relative to the yoke")
        else:
            along = (f"along {s.guide}, {'from ' + s.first + ' towards ' + s.second if vs >= 0 else 'from ' + s.second + ' towards ' + s.first}")
        out.append(f"vs_{s.key} = {fmt(abs(vs))} m/s {along}")
    return out


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
                rule = (f"{still} does not turn: rub = omega_{moving} r = {fmt(abs(w))} x {rr}")
            elif (wa > 0) != (wb > 0):
                rule = (f"{a} turns {sense_word(wa)}, {b} {sense_word(wb)} (opposite senses): "
                        f"rub = (omega_{a} + omega_{b}) r = ({fmt(abs(wa))} + {fmt(abs(wb))}) "
                        f"x {rr}")
            else:
                rule = (f"{a} and {b} both turn {sense_word(wa)}: rub = |omega_{a} - "
                        f"omega_{b}| r = |{fmt(abs(wa))} - {fmt(abs(wb))}| x {rr}")
            out.append(f"pin {name} (r = {_len_unit(sol, r.radius)}), {a} and {b}: {rule} = "
                       f"{fmt(val)} m/s")
        if len(r.pairs) > 1:
            out.append(f"pin {name}: the largest is {fmt(r.rubbing_velocity)} m/s")
    return out


def _torque_items(sol):
    sc = sol.scene
    if sol.input_torque is None:
        return []
    inp = sc.input
    block = not sol.plan.steps[0].periodic  # a block driver: a force along its guide
    out = ["power balance (no friction, no inertia): "
           + (f"F vs_{inp.tip}" if block else f"T omega_{inp.crank}") + " + sum F . v = 0"]
    for load, (target, p) in zip(sc.loads, sol.power_terms):
        if load.force is not None:
            F = math.hypot(*load.force)
            v = sol.speed(target)
            if F * v > 0:  # (both may be positive and their product underflow to 0)
                vx, vy = sol.V[target]
                cos = (load.force[0] * vx + load.force[1] * vy) / (F * v)
                ang = math.degrees(math.acos(max(-1.0, min(1.0, cos))))
                out.append(f"{target}: F . v_{target} = {fmt(F)} N x {fmt(v)} m/s x "
                           f"cos {fmt(ang, 4)} deg = {fmt(p)} W")
            else:
                out.append(f"{target}: F . v_{target} = {fmt(p)} W")
        else:
            out.append(f"torque on {target}: T_{target} omega_{target} = "
                       f"{fmt(load.torque)} x {fmt(sol.W[target])} = {fmt(p)} W")
    total = sum(p for _, p in sol.power_terms)
    t = sol.input_torque
    if block:
        out.append(f"F = -(sum F . v) / vs_{inp.tip} = {fmt(-total)} / {fmt(inp.omega)} = "
                   f"{fmt(t)} N along the guide ({sol.plan.steps[0].sense(t)})")
        return out
    out.append(f"T = -(sum F . v) / omega_{inp.crank} = {fmt(-total)} / {fmt(inp.omega)} = "
               f"{fmt(abs(t))} N m {sense_word(t)}".rstrip())
    return out


def _readoffs(doc, sol, vscale):
    doc.h("4. Read-offs from the velocity diagram")
    doc.p(f"Lengths are read to {DRAWING_PRECISION_CM} cm; 'read' is what that length gives "
          f"at {vscale.text}, 'exact' the solver's value.")
    doc.table(("vector", "on the diagram", "length (cm)", "read", "exact"),
              _readoff_rows(sol, velocity_constructions(sol), vscale, "m/s"))
    doc.p("Angular velocities (omega = relative velocity / length; the sense is the way the "
          "relative velocity turns the link):")
    doc.items(_angular_velocity_items(sol))
    sliding = _sliding_items(sol)
    if sliding:
        doc.p("Sliding velocities (relative to the guide):")
        doc.items(sliding)
    if sol.scene.pins:
        doc.p("Rubbing velocities (|omega_1 - omega_2| r, with signed omegas: the sum of the "
              "magnitudes when the two turn in opposite senses, the difference when alike):")
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
            coriolis[g] = (f"2 omega v = 2 x {fmt(abs(sol.W[g]))} x {fmt(abs(vs))} = "
                           f"{fmt(cor)} (block {s.key}, perp. to {s.guide})")
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
        rows.append((lk.key, fmt(L, 5), f"{_key('v', (X, Y))} = {fmt(v)}",
                     f"{fmt(v)}^2 / {fmt(L, 5)} = {fmt(cen)}",
                     f"along {X}{Y}, towards {Y}", tcell,
                     coriolis.get(lk.key, "-")))
    return rows


def _acceleration(doc, sol, ascale):
    sc = sol.scene
    doc.h("5. Accelerations")
    doc.table(("link", "length (m)", "relative velocity (m/s)", "centripetal v^2/l (m/s^2)",
               "its direction", "tangential (m/s^2)", "Coriolis (m/s^2)"),
              _acceleration_table(sol))
    cons = acceleration_constructions(sol)
    doc.p(f"Acceleration scale: {ascale.text} (the diagram fits "
          f"{fmt(_extent_cm(list(sol.A.values()) + [(0.0, 0.0)], ascale), 3)} cm). Fixed "
          "points have their images at the pole o'.")
    items = []
    for c in cons:
        t = f"Step {c.step + 1} ({c.title}): {c.text}"
        set_out = [f"{g.name} {ascale.cm(g.magnitude):.2f} cm" for g in c.given
                   if g.magnitude > 0]
        if set_out:
            t += "; lengths to set out: " + ", ".join(set_out)
        items.append(t)
    doc.items(items)
    doc.p(f"Read-offs (lengths to {DRAWING_PRECISION_CM} cm at {ascale.text}):")
    doc.table(("vector", "on the diagram", "length (cm)", "read", "exact"),
              _readoff_rows(sol, cons, ascale, "m/s^2"))
    items = []
    orient = _orient(sol)
    for lk in sc.links:
        if lk.key in sol.plan.fixed_links:
            continue
        al = sol.shown(sol.Al[lk.key], "alpha", lk.key)
        if lk.key == sc.input.crank:
            items.append((f"alpha_{lk.key} = {fmt(abs(al))} rad/s^2 {sense_word(al)} "
                          + ("(the input)" if sc.input.given is None
                             else "(the crank's, found above)")).replace("  ", " "))
            continue
        X, Y = orient[lk.key]
        tan = abs(al) * lk.length
        items.append(f"alpha_{lk.key} = tangential of {_key('a', (X, Y))} / {lk.key} = "
                     f"{fmt(tan)} / {fmt(lk.length, 5)} = {fmt(abs(al))} rad/s^2 "
                     f"{sense_word(al)}".rstrip())
    doc.p("Angular accelerations (alpha = tangential component / length):")
    doc.items(items)
    sl = []
    for s in sc.sliders:
        if getattr(s, "wheel", ""):  # a driving wheel's centre: its acceleration said above
            continue
        a_s = sol.S[s.key][1]
        cor = math.hypot(*sol.coriolis(s.key))
        t = f"as_{s.key} = {fmt(a_s)} m/s^2 (signed along the guide)"
        if isinstance(s, GuideSlider):
            t += f"; Coriolis component {fmt(cor)} m/s^2"
        sl.append(t)
    if sl:
        doc.p("Sliding accelerations:")
        doc.items(sl)


def steps_blocks(sol: Solution) -> _Doc:
    """The hand solution as a document (headings, paragraphs, lists, tables). Rounding
    noise is written as 0 (:func:`~polygon_method.motion.solution.tidied`)."""
    sol = tidied(sol)
    sc = sol.scene
    space, vscale, ascale = diagram_scales(sol)
    doc = _Doc()
    doc.blocks.append(("title", sc.title or sc.file or "mechanism"))
    _config(doc, sol, space)
    _input(doc, sol)
    _velocity(doc, sol, vscale)
    _readoffs(doc, sol, vscale)
    _acceleration(doc, sol, ascale)
    fscale = force_scale(sol.forces) if sc.has_forces and not sol.forces_refused else None
    doc.blocks += force_blocks(sol, fscale)
    tail = [f"warning: {w}" for w in sol.warnings] + [f"note: {n}" for n in sol.notes]
    if tail:
        doc.h("Notes")
        doc.items(tail)
    return doc


def steps_text(sol: Solution, fmt: str = "text") -> str:
    """The hand solution, step by step: ``fmt`` is ``"text"`` (terminal) or ``"markdown"``."""
    if fmt not in ("text", "markdown"):
        raise ValueError(f"format {fmt!r}: use text or markdown")
    doc = steps_blocks(sol)
    title = doc.blocks[0][1]
    doc.blocks = doc.blocks[1:]
    body = doc.render(fmt)
    head = f"# {title}\n\n" if fmt == "markdown" else f"{title}\n{'#' * len(title)}\n\n"
    return head + body
