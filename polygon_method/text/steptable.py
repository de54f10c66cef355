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

from ..solver.given import working
from ..solver.two_given import found_note
from ..steps.block import at_rest_rate
from ..common.numbers import fmt, sense_word
from .forces import force_blocks
from .cycle_steps import cycle_items
from .rod_steps import rod_items
from .link_points import pair_items
from .polygon_steps import (
    acceleration_section,
    extent_cm,
    length_words,
    polar_words,
    read_off,
    readoff_section,
    turn_words,
    velocity_section,
)
from ..polygons.scales import diagram_scales, force_scale
from ..scene import FixedPath, GuideSlider, guide_words
from ..solver.kinematics import evaluate
from ..motion.solution import Solution
from ..motion.tidy import tidied
from ..linkage.flywheel import cycle_blocks
from ..linkage.klein import klein_blocks

__all__ = ["steps_text", "steps_blocks", "read_off", "fmt", "sense_word"]

_WIDTH = 92


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
                    lines = [
                        "| " + " | ".join(esc(c) for c in b[1]) + " |",
                        "|" + "|".join(" --- " for _ in b[1]) + "|",
                    ]
                    lines += ["| " + " | ".join(esc(c) for c in r) + " |" for r in b[2]]
                    out.append("\n".join(lines))
            else:
                if kind == "h":
                    out.append(f"{b[1]}\n{'=' * len(b[1])}")
                elif kind == "p":
                    out.append(textwrap.fill(b[1], _WIDTH))
                elif kind == "list":
                    out.append(
                        "\n".join(
                            textwrap.fill(
                                i, _WIDTH, initial_indent="  - ", subsequent_indent="    "
                            )
                            for i in b[1]
                        )
                    )
                else:
                    rows = [b[1]] + b[2]
                    w = [max(len(r[i]) for r in rows) for i in range(len(b[1]))]
                    lines = [
                        "  " + "  ".join(c.ljust(x) for c, x in zip(b[1], w)).rstrip(),
                        "  " + "  ".join("-" * x for x in w),
                    ]
                    lines += [
                        "  " + "  ".join(c.ljust(x) for c, x in zip(r, w)).rstrip() for r in b[2]
                    ]
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
    found = found_note(sol.plan)
    if found is not None:  # two inputs' speeds found from speeds on other links
        return found, result
    lines = working(sol.plan, fmt)
    if lines is not None:  # the motion given on another quantity: scaled from 1 rad/s
        return "; ".join(lines), result
    if sol.scene.at_rest:  # the polygons per rad/s: the virtual velocities
        return (
            f"at rest ({name} = 0, about to turn {sense_word(w)}): the polygons are drawn "
            f"for {name} = {result}, the virtual velocities of the power balance (per rad/s "
            "of the crank; "
            + (
                f"starting with alpha = {fmt(abs(sol.scene.start_alpha))} rad/s^2 "
                f"{sense_word(sol.scene.start_alpha)}: the start's accelerations are alpha "
                "times these velocities, section 6; the acceleration diagram below, per "
                "rad/s with its centripetal terms, is not the start's)"
                if sol.scene.start_alpha
                else "no inertia)"
            ),
            result,
        )
    m = re.match(r"^\s*([-+]?[0-9.]+(?:[eE][-+]?\d+)?)\s*([^\s]*)", inp.speed_text)
    number, unit = (m.group(1), m.group(2).lower()) if m else ("", "")
    if unit in ("rpm", "r.p.m.", "r.p.m", "rev/min"):
        return (f"N = {number} rpm; {name} = 2 pi N / 60 = 2 pi x {number} / 60 = {result}", result)
    if unit in ("rps", "r.p.s.", "r.p.s", "rev/s"):
        return f"n = {number} rps; {name} = 2 pi n = 2 pi x {number} = {result}", result
    if unit == "deg/s":
        return f"{name} = {number} deg/s x pi / 180 = {result}", result
    return f"{name} = {result} (given)", result


def _config(doc, sol, space):
    sc = sol.scene
    u = sc.length_unit
    doc.h("1. Configuration diagram")
    doc.p(
        f"Space scale: {space.text} (the mechanism fits "
        f"{fmt(extent_cm(sol.P.values(), space), 3)} cm of the page)."
    )
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
        for b in names[i + 1 :]:
            if not sc.has_link(a + b if len(a) == len(b) == 1 else f"{a}-{b}"):
                d = math.dist(sc.ground[a], sc.ground[b])
                if d > 0:
                    facts.append(f"{a}{b} = {fmt(d / u, 5)} {sc.units} (between the fixed points)")
    driver = sol.plan.steps[0]
    if not driver.periodic:  # a block driven along its guide: its place is given
        facts.append(
            f"driving {driver.title}, at s_{inp.tip} = {length_words(sol, inp.angle)} "
            f"from {driver.origin} along it (given)"
        )
        _slider_facts(facts, sc, u, driver.finds[0])
        _drawing(doc, sol, space, facts)
        return
    ang = math.degrees(inp.angle)
    said = f"{inp.angle_words}; " if inp.angle_words else ""
    crank_dir = (
        f"crank {inp.crank} at {fmt(ang, 5)} deg ({said}direction {inp.pivot}"
        f"{inp.tip}, counter-clockwise from the +x axis)"
    )
    others = [n for n in sc.ground if n != inp.pivot]
    if len(others) == 1:
        ox, oy = sc.ground[inp.pivot]
        gx, gy = sc.ground[others[0]]
        ref = math.atan2(gy - oy, gx - ox)
        between = abs((inp.angle - ref + math.pi) % (2 * math.pi) - math.pi)
        crank_dir += (
            f"; angle {others[0]}{inp.pivot}{inp.tip} = {fmt(math.degrees(between), 4)} deg"
        )
    facts.append(crank_dir)
    _slider_facts(facts, sc, u)
    _drawing(doc, sol, space, facts)


def _slider_facts(facts, sc, u, block=None):
    for s in sc.sliders:
        if s.point == block:  # the driving block: said above
            continue
        if s.slot:  # a peg in two slots
            facts.append(
                f"peg {s.point} in the slot of {s.guide}"
                + (_offset_words(s, u, sc.units) if s.offset else "")
                if isinstance(s, GuideSlider)
                else f"peg {s.point} in a fixed {guide_words(s.label, 'slot')} through "
                f"({fmt(s.through[0] / u, 5)}, {fmt(s.through[1] / u, 5)})"
            )
        elif isinstance(s, FixedPath) and any(
            getattr(t, "yoke", None) == s.point for t in sc.sliders
        ):
            facts.append(
                f"yoke {s.point} on a {guide_words(s.label)} through "
                f"({fmt(s.through[0] / u, 5)}, {fmt(s.through[1] / u, 5)})"
            )
        elif isinstance(s, FixedPath):
            facts.append(
                f"slider {s.point} on a {guide_words(s.label)} through "
                f"({fmt(s.through[0] / u, 5)}, {fmt(s.through[1] / u, 5)})"
            )
        elif hasattr(s, "yoke"):  # the slot of a translating yoke
            facts.append(
                f"block {s.point} slides in the {guide_words(s.label, 'slot', f'yoke {s.yoke}')}"
                + (_yoke_offset_words(s, u, sc.units) if s.offset else "")
            )
        elif s.offset:  # an offset slot: its line off the link's
            facts.append(
                f"block {s.point} slides in a slot of {s.guide}{_offset_words(s, u, sc.units)}"
            )
        else:
            facts.append(f"block {s.point} slides along {s.guide}")


def _offset_words(s, u, units):
    """An offset slot's line: `` parallel to its line A -> B, 15 mm to the left of it``."""
    return (
        f" parallel to its line {s.first} -> {s.second}, {fmt(abs(s.offset) / u, 5)} {units} "
        f"to the {'left' if s.offset > 0 else 'right'} of it"
    )


def _yoke_offset_words(s, u, units):
    """A yoke's offset slot: ``, its centre line 20 mm to the left of the yoke's line through
    Y``."""
    return (
        f", its centre line {fmt(abs(s.offset) / u, 5)} {units} to the "
        f"{'left' if s.offset > 0 else 'right'} of the yoke's line through {s.yoke}"
    )


def _drawing(doc, sol, space, facts):
    sc, u = sol.scene, sol.scene.length_unit
    doc.items(facts)
    doc.p("Drawing the configuration:")
    doc.items([_position_words(sol, st, space) for st in sol.plan.steps])
    rows = [(p, fmt(sol.P[p][0] / u, 5), fmt(sol.P[p][1] / u, 5)) for p in sc.point_names]
    doc.table(("point", f"x ({sc.units})", f"y ({sc.units})"), rows)


def _which(sol, X):
    hint = sol.scene.assembly.get(X)
    if hint is None:
        return "as taken by default (see the notes)"
    if isinstance(hint, str):
        return f"the one {'to the ' if hint in ('left', 'right') else ''}{hint}"
    u = sol.scene.length_unit
    return f"the one near ({fmt(hint[0] / u, 4)}, {fmt(hint[1] / u, 4)})"


def _position_words(sol, st, space) -> str:
    L = lambda x: f"{length_words(sol, x)} ({space.cm(x):.2f} cm)"  # noqa: E731
    inp = sol.scene.input
    angle = (
        fmt(math.degrees(inp.angle), 5)
        if sol.plan.steps[0].periodic
        else length_words(sol, inp.angle)
    )  # a block driver's place along its guide
    return st.position_words(L, lambda point: _which(sol, point), angle)


def _at_rest_items(sc, driver, items) -> list:
    """A block's, a collar's or a wheel's input lines, at rest: the driver's zero stated
    first, its unit speed in the polygons the virtual velocities, not given."""
    if not sc.at_rest:
        return items
    a = sc.start_alpha
    return [
        f"at rest (nothing moves yet): the polygons are drawn per {driver.virtual_unit}, the "
        "virtual velocities of the power balance ("
        + (
            f"starting from rest with {fmt(abs(a))} m/s^2"
            f"{' of its centre' if 'rad/s' in driver.virtual_unit else ''}: the start's "
            "accelerations are that times these velocities, section 6; the acceleration "
            "diagram below, at this unit speed, is not the start's)"
            if a
            else "no inertia)"
        )
    ] + [x.replace("(given)", "(virtual: at rest)") for x in items]


def _input(doc, sol):
    sc = sol.scene
    inp = sc.input
    driver = sol.plan.steps[0]
    own = driver.input_items(sc, fmt)
    if own is not None:  # a driver of its own words (a wheel rolling on the ground)
        doc.h(f"2. {own[0]}")
        doc.items(_at_rest_items(sc, driver, list(own[1])))
        return
    if not driver.periodic:  # a block driven along its guide: its velocity and rate given
        doc.h(f"2. Input block {inp.tip}")
        vs, a_s = inp.omega, inp.alpha
        items = [
            f"vs_{inp.tip} = {fmt(abs(vs))} m/s {driver.sense(vs)} along the guide (given)",
            f"as_{inp.tip} = {fmt(abs(a_s))} m/s^2 {driver.sense(a_s)} along the guide (given)"
            if a_s
            else f"as_{inp.tip} = 0 {at_rest_rate(sc, '1 m/s', f'as_{inp.tip}')}"
            if sc.at_rest
            else f"as_{inp.tip} = 0 (the block moves at a steady speed)",
        ]
        doc.items(_at_rest_items(sc, driver, items))
        return
    second = inp.second and (inp.second.crank or f"collar {inp.second.block}")
    doc.h(f"2. Input link {inp.crank}" + (f" and {second}" if inp.second else ""))
    working, _ = _speed_working(sol)
    r = sc.link(inp.crank).length
    v = sol.speed(inp.tip)
    items = [
        working,
        f"v_{inp.tip} = omega_{inp.crank} x {inp.crank} = {fmt(abs(inp.omega))} x "
        f"{fmt(r, 5)} = {fmt(v)} m/s, perpendicular to {inp.crank}",
    ]
    if inp.alpha:
        items.append(
            f"alpha_{inp.crank} = {fmt(abs(inp.alpha))} rad/s^2 "
            f"{sense_word(inp.alpha)} "
            + (
                "(found above)"
                if inp.found_from and inp.speed_text.startswith("found from")
                else "(given)"
                if inp.given is None
                else f"(found from {inp.given.rate_key or 'the given motion'}, above)"
            )
        )
    else:
        items.append(
            f"alpha_{inp.crank} = 0 in the polygons per rad/s (the start's alpha is taken "
            "in section 6)"
            if sol.scene.start_alpha
            else f"alpha_{inp.crank} = 0 (the crank turns at a uniform speed)"
        )
    two = inp.second
    if two is not None and two.block is not None:  # a collar sliding along the crank
        items.append(f"the second input: {sol.plan.steps[1].second_words(sc)} (given)")
    elif two is not None:
        r2 = sc.link(two.crank).length
        items.append(
            f"the second input, {two.crank}: omega_{two.crank} = "
            f"{fmt(abs(two.omega))} rad/s {sense_word(two.omega)} "
            f"({'found above' if two.speed_text.startswith('found from') else 'given'}); v_{two.tip} "
            f"= {fmt(abs(two.omega))} x {fmt(r2, 5)} = {fmt(sol.speed(two.tip))} m/s, "
            f"perpendicular to {two.crank}; alpha_{two.crank} = "
            f"{fmt(abs(two.alpha))} rad/s^2 {sense_word(two.alpha)}"
        )
    doc.items(items)
    if two is not None:
        _superposition(doc, sol)


def _superposition(doc, sol):
    """Two inputs: the velocity polygon as the sum of the polygons for each input alone
    (the velocities are linear in the two speeds), as a book draws it."""
    sc = sol.scene
    inp, two = sc.input, sc.input.second
    plan = sol.plan
    k = next(i for i, st in enumerate(plan.steps) if st.kind in ("second crank", "second collar"))
    held = tuple(
        prm if i != k else plan.steps[k].held(prm) for i, prm in enumerate(plan.dims.steps)
    )
    name2 = two.crank or f"the collar {two.block}"  # its speed, or its sliding, held
    first = evaluate(plan, omega=inp.omega, alpha=0.0, upto=1, dims=replace(plan.dims, steps=held))
    second = evaluate(plan, omega=0.0, alpha=0.0, upto=1)
    doc.p(
        f"Two inputs (two degrees of freedom): the velocities are linear in the two speeds, "
        f"so the velocity polygon is drawn for {inp.crank} alone ({name2} held), then "
        f"for {name2} alone ({inp.crank} held), and the two are added, image by image: "
        f"v = v' + v''."
    )
    rows = []
    for p in sc.point_names:
        if p in sc.ground:
            continue
        a, b = first.V[p], second.V[p]
        rows.append((p, polar_words(a), polar_words(b), polar_words((a[0] + b[0], a[1] + b[1]))))
    doc.table(("point", f"v' ({inp.crank} alone)", f"v'' ({name2} alone)", "v = v' + v''"), rows)
    doc.p(
        "The angular velocities add in the same way (for gears, the tabular method: each "
        "input alone, then the sum):"
    )
    rows = [
        (
            lk.key,
            turn_words(first.W[lk.key]),
            turn_words(second.W[lk.key]),
            turn_words(first.W[lk.key] + second.W[lk.key]),
        )
        for lk in sc.links
    ]
    doc.table(
        (
            "link",
            f"omega' ({inp.crank} alone)",
            f"omega'' ({name2} alone)",
            "omega = omega' + omega''",
        ),
        rows,
    )


def steps_blocks(sol: Solution) -> _Doc:
    """The hand solution as a document (headings, paragraphs, lists, tables). Rounding
    noise is written as 0 (:func:`~polygon_method.motion.tidy.tidied`)."""
    sol = tidied(sol)
    sc = sol.scene
    space, vscale, ascale = diagram_scales(sol)
    doc = _Doc()
    doc.blocks.append(("title", sc.title or sc.file or "mechanism"))
    _config(doc, sol, space)
    _input(doc, sol)
    velocity_section(doc, sol, vscale)
    readoff_section(doc, sol, vscale)
    acceleration_section(doc, sol, ascale)
    asked = pair_items(sol, vscale)  # vmin_BC, ar_CB, at_CB: where the answers ask them
    if asked:
        doc.h("Asked of two points of a link")
        doc.items(asked)
    worked = cycle_items(sol)  # time_ratio, stroke_X, theta_XY, angle_XYZ: where asked
    if worked:
        doc.h("Asked of the cycle and the configuration")
        doc.items(worked)
    rod = rod_items(sol)  # m_small_end, m_L, l_GL, the correction couple: where asked
    if rod:
        doc.h("Asked of the connecting rod: its equivalent dynamical system")
        doc.items(rod)
    fscale = force_scale(sol.forces) if sc.has_forces and not sol.forces_refused else None
    doc.blocks += force_blocks(sol, fscale)
    doc.blocks += klein_blocks(sol)  # a slider crank at uniform crank speed
    doc.blocks += cycle_blocks(sol)  # an engine asked for its cycle: the areas, the flywheel
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
