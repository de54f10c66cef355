"""The problem in words, as a textbook states it: one sentence a line, made from the scene's
records (lengths in the scene's own units, the crank's speed as the scene wrote it). The page
shows them above its diagrams; a class's problem sheet lists each variant's under "Given".

>>> import polygon_method as pm
>>> for line in given(pm.load_scene("worked_problems/whitworth.toml")):
...     print(line)
Fixed points: O4 at (0, 0) mm, O2 at (0, 50) mm.
Links: O2-A = 100 mm, O4-P = 150 mm, P-Q = 450 mm.
A block at A slides along link O4-P.
Slider Q moves on a fixed horizontal path through (0, 250) mm.
Of its two positions, P is the one near (98, 113) mm.
Of its two positions, Q is the one to the right.
The crank O2-A turns about O2; at the instant shown it makes 30° with the x axis (counter-clockwise), turning at 60 rpm cw (6.283 rad/s cw).
"""

from __future__ import annotations

import math

from ..solver.compiler import compile_plan
from ..common.numbers import fmt, sense
from ..scene.link_loads import across_words
from ..common.tolerances import ROUNDING
from ..scene import guide_words

__all__ = ["given"]


def _slot(sc, s) -> str:
    """One slot of a peg in words: ``the slot of link O4-B``, ``a fixed horizontal slot
    through (0, 450) mm``."""
    if hasattr(s, "guide") and s.offset:  # its line off the link's
        return (
            f"the slot of link {s.guide} (parallel to its line {s.first} -> {s.second}, "
            f"{_len(sc, abs(s.offset))} to the {'left' if s.offset > 0 else 'right'} of it)"
        )
    if hasattr(s, "guide"):
        return f"the slot of link {s.guide}"
    return f"a fixed {guide_words(s.label, 'slot')} through {_at(sc, s.through)}"


def _slider_sentence(sc, s) -> str | None:
    """A slider's sentence: a peg in two slots (said once, at its first slot), a yoke's slot, a
    block on a moving link or a slider on a fixed path; None for a peg's second slot (a
    driving wheel's centre is no block: said with the wheel)."""
    if s.slot:  # a peg in two slots: one sentence, at its first slot
        if s is sc.slots(s.point)[0]:
            return (
                f"A peg {s.point} runs in two slots: "
                + " and ".join(_slot(sc, t) for t in sc.slots(s.point))
                + "."
            )
        return None
    if hasattr(s, "yoke"):  # the slot of a translating yoke
        off = (
            f", its centre line {_len(sc, abs(s.offset))} to the "
            f"{'left' if s.offset > 0 else 'right'} of the yoke's line through {s.yoke}"
            if s.offset
            else ""
        )
        return (
            f"A block at {s.point} slides in the "
            f"{guide_words(s.label, 'slot', f'the yoke {s.yoke}')}{off}."
        )
    if hasattr(s, "guide") and s.offset:  # an offset slot
        return (
            f"A block at {s.point} slides in a slot of link {s.guide} parallel to its line "
            f"{s.first} -> {s.second}, {_len(sc, abs(s.offset))} to the "
            f"{'left' if s.offset > 0 else 'right'} of it."
        )
    if hasattr(s, "guide"):  # a block on a moving link (a scene record, not a step)
        return f"A block at {s.point} slides along link {s.guide}."
    path = guide_words(s.label)  # "horizontal path", "path at 30 deg"
    return f"Slider {s.point} moves on a fixed {path} through {_at(sc, s.through)}."


def _rolling_sentence(sc, r) -> str:
    """A wheel or gear rolling without slip (or a rack meshing with one): what rolls on what,
    and where it is at the instant shown."""
    if r.on == "rack":
        return (
            f"The block {r.rim} is a rack meshing with {r.label}; its point is at "
            f"{_at(sc, sc.slider(r.rim).through)} at the instant shown."
        )
    if r.teeth:  # gears by their teeth, as a book says them
        what = _gear_sentence(sc, r)
    elif r.on == "gear":
        what = (
            f"The {'ring gear' if r.ring else 'gear'} {r.wheel} (centre {r.centre}, "
            f"pitch radius {_len(sc, r.radius)}) meshes {'internally ' if r.inside else ''}with "
            f"{r.label}" + (" inside it" if r.ring else "")
        )
    else:
        on = (
            f"on {r.label} through {_at(sc, r.through)}"
            if r.on == "line"
            else f"{'inside' if r.inside else 'outside'} {r.label}"
        )
        what = (
            f"The wheel {r.wheel} (centre {r.centre}, radius {_len(sc, r.radius)}) rolls "
            f"without slipping {on}"
        )
    if r.base_radius:
        what += f" ({'pitch ' if r.teeth else ''}radius {_len(sc, r.base_radius)})"
    return (
        what
        + (
            f"; {r.wheel} is at {fmt(math.degrees(r.angle) % 360)}° at the instant shown"
            if r.angle is not None
            else f"; {r.rim} is its point in contact at the instant shown"
        )
        + "."
        + _grip_sentence(r)
    )


def _gear_sentence(sc, r) -> str:
    """A gear given by its teeth: ``The planet AP of 24 teeth (centre A, pitch radius 60 mm)
    meshes with the sun of 40 teeth about O``; a ring ``The ring gear O-Q of 88 teeth
    (...) meshes internally with the gear AP of 24 teeth inside it``."""
    noun = "ring gear" if r.ring else "planet" if r.on == "circle" else "gear"
    return (
        f"The {noun} {r.wheel} of {r.teeth[0]} teeth (centre {r.centre}, pitch radius "
        f"{_len(sc, r.radius)}) meshes {'internally ' if r.inside else ''}with {r.label}"
        + (" inside it" if r.ring else "")
    )


def _module_sentence(rolling) -> list:
    """The gears' module, where they are given by their teeth and one: ``The module is 5
    mm.``, ``The diametral pitch is 10 per inch.`` (each gear's where they differ)."""
    said = {r.wheel: _module_words(*r.teeth[2:]) for r in rolling if r.teeth and r.teeth[2]}
    if not said:
        return []
    if len(set(said.values())) == 1:
        what, value = next(iter(said.values()))
        return [f"The {what} is {value}."]
    return ["The gears' " + ", ".join(f"{w}: {a} {v}" for w, (a, v) in said.items()) + "."]


def _module_words(m, P):
    """(``module``, ``5 mm``) or (``diametral pitch``, ``10 per inch``)."""
    return ("module", f"{fmt(m * 1e3)} mm") if P is None else ("diametral pitch", f"{P:g} per inch")


def _grip_sentence(r) -> str:
    """A friction drive's: the wheels pressed together (no teeth), the friction coefficient."""
    if not r.grip:
        return ""
    preload, mu = r.grip
    out = (
        ""
        if preload is None
        else f" They grip by friction, pressed together with {fmt(preload)} N."
    )
    return out + (
        "" if mu is None else f" The coefficient of friction at the contact is {fmt(mu)}."
    )


def _shape_sentences(sc) -> list:
    """The mechanism's shape: fixed points, links, points on links, sliders, rolling contacts,
    which of two assembly positions, cylinders."""
    out = []
    if sc.ground:
        out.append(
            "Fixed points: "
            + ", ".join(f"{p} at {_at(sc, xy)}" for p, xy in sc.ground.items())
            + "."
        )
    out.append("Links: " + ", ".join(f"{lk.key} = {_len(sc, lk.length)}" for lk in sc.links) + ".")
    for cp in sc.points:
        out.append(f"Point {cp.name}: {cp.how}.")  # "on BC, 40 mm from B"
    out += [t for t in (_slider_sentence(sc, s) for s in sc.blocks) if t is not None]
    out += [_rolling_sentence(sc, r) for r in getattr(sc, "rolling", ())]
    out += _module_sentence(getattr(sc, "rolling", ()))
    for p, hint in sc.assembly.items():
        where = _SIDE.get(hint, hint) if isinstance(hint, str) else f"near {_at(sc, hint)}"
        out.append(f"Of its two positions, {p} is the one {where}.")
    for c in sc.cylinders:
        stroke = (
            f", its stroke {_len(sc, c.stroke[0])} to {_len(sc, c.stroke[1])}" if c.stroke else ""
        )
        out.append(
            f"A hydraulic cylinder {c.key}: its barrel pivoted at {c.barrel}, its rod "
            f"pinned at {c.rod}{stroke}."
        )
    return out


def _load_sentence(ld) -> str | None:
    """A load's sentence: gas pressure on a piston, a force at a point or a torque on a link
    (None for a load of none of these)."""
    if ld.gas is not None and ld.force is None:  # towards the crank, not yet compiled
        return (
            f"The gas pressure on the piston {ld.target} is {ld.gas[2]}, pushing "
            "it towards the crank."
        )
    if ld.gas is not None:
        fx, fy = ld.force
        return (
            f"The gas pressure on the piston {ld.target} is {ld.gas[2]}, pushing "
            f"it at {fmt(math.degrees(math.atan2(fy, fx)) % 360)}°."
        )
    if ld.across is not None:  # turning with a link: as stated, and its angle now
        return f"A force of {across_words(ld)} acts at {ld.target}."
    if ld.force is not None:
        fx, fy = ld.force
        return (
            f"A force of {fmt(math.hypot(fx, fy))} N acts at {ld.target} at "
            f"{fmt(math.degrees(math.atan2(fy, fx)) % 360)}°."
        )
    if ld.torque is not None:
        return f"A torque of {fmt(abs(ld.torque))} N m {sense(ld.torque)} acts on link {ld.target}."
    return None


def _force_sentences(sc) -> list:
    """The forces' data: pins' sizes, loads, masses, gravity, the indicator diagram and the
    flywheel."""
    out = []
    for pin in sc.pins:
        size = pin.radius * (2 if pin.given == "diameter" else 1)
        out.append(f"Pin at {pin.point}: {pin.given} {_len(sc, size)}.")
    out += [t for t in (_load_sentence(ld) for ld in sc.loads) if t is not None]
    for m in sc.masses:
        what = f"The block {m.body}" if m.block else f"Link {m.body}"
        out.append(
            f"{what} has a mass of {_given(m.mass)} kg" + ("." if m.block else f", its {m.how}.")
        )
    if sc.gravity is not None:
        out.append(f"Gravity acts: {sc.gravity.text}.")
    elif sc.statics and not sc.masses:  # an empty [masses]
        out.append("The links' masses are neglected: a static force analysis.")
    for k, ind in enumerate(getattr(sc, "indicators", ())):
        lag = ""
        if k and ind.lag is not None:
            lag = f", its cycle {math.degrees(ind.lag):g} deg of the crank after the first's"
        out.append(
            f"The gas pressure on the piston {ind.piston} over the cycle is "
            f"given by its {ind.words}{lag}."
        )
    if sc.flywheel is not None:
        out.append(f"A flywheel is to keep the speed steady: {sc.flywheel.words}.")
    return out


def given(sc) -> list:
    """The scene's data as a textbook states it, one sentence a line."""
    out = _shape_sentences(sc)
    driver = compile_plan(sc).steps[0]  # what drives: asked of the plan's first step
    own = getattr(driver, "problem_words", lambda sc: None)(sc)  # a driving collar's
    if own is not None:  # a driver of its own words (a collar driven along its rod)
        out.append(own)
    elif not driver.periodic:  # a block driven along its guide, or a wheel rolling: its place
        out.append(
            _wheel_words(sc, driver.finds[0])
            if sc.input.wheel is not None
            else _block_words(sc, driver.finds[0])
        )
    else:
        _crank_words(sc, out)
    return out + _force_sentences(sc)


def _crank_words(sc, out):
    """The driving crank (and a second one) in words, appended to ``out``."""
    inp = sc.input
    words = (
        f"The crank {inp.crank} turns about {inp.pivot}; at the instant shown it makes "
        f"{fmt(math.degrees(inp.angle) % 360)}° with the x axis (counter-clockwise"
        + (f"; {inp.angle_words}" if inp.angle_words else "")
        + ")"
    )
    g = inp.given
    found = bool(getattr(inp, "found_from", ())) and inp.speed_text.startswith("found from")
    if g is not None:
        words += f". At this instant {_given_words(g, sc.cylinder(g.names[0]) is not None)}"
    elif found:  # two inputs' speeds found from speeds given on gears: the question
        words += f", its speed {inp.speed_text}"
    else:
        words += f", turning at {inp.speed_text}"
    if g is None and not found and "rad/s" not in inp.speed_text:
        words += f" ({fmt(abs(inp.omega))} rad/s {sense(inp.omega)})"
    if inp.alpha and g is None:
        words += (
            f", with an angular acceleration of {fmt(abs(inp.alpha))} rad/s² {sense(inp.alpha)}"
        )
    out.append(words + ".")
    two = inp.second
    if two is not None and two.block is not None:  # a collar sliding along the crank
        step = compile_plan(sc).steps[1]
        out.append(f"At the same time the {step.second_words(sc)}.")
    elif two is not None:
        out.append(
            f"A second crank {two.crank} is driven too, about {two.pivot}: at the "
            f"instant shown it makes {fmt(math.degrees(two.angle) % 360)}° with the x "
            f"axis, "
            + ("its speed " if two.speed_text.startswith("found from") else "turning at ")
            + two.speed_text
            + (
                f", with an angular acceleration of {fmt(abs(two.alpha))} rad/s² {sense(two.alpha)}"
                if two.alpha
                else ""
            )
            + "."
        )


def _wheel_words(sc, centre) -> str:
    """The driving wheel in words: what it rolls on, its radius, its centre's place."""
    inp = sc.input
    pr = next(p for p in sc.rolling if p.wheel == inp.wheel)
    (ux, uy), (mx, my) = sc.slider(centre).u, pr.m
    alpha = inp.alpha * (-my * ux + mx * uy) / pr.radius  # a_C = alpha r along t = perp(m)
    acc = f" and {fmt(abs(alpha))} rad/s² {'ccw' if alpha > 0 else 'cw'}" if alpha else ", steadily"
    w = inp.omega * (-my * ux + mx * uy)  # its sense of turning (at rest: about to)
    how = (
        f"at rest on {pr.label}, about to roll without slip turning {'ccw' if w > 0 else 'cw'}"
        if sc.at_rest
        else f"rolling without slip on {pr.label} at {inp.speed_text}{acc}"
    )
    return (
        f"The wheel {inp.wheel} (radius {_len(sc, pr.radius)}) drives the mechanism, "
        f"{how}; at the instant shown "
        f"its centre {centre} is {_len(sc, abs(inp.angle))} along the line from the "
        "foot of its given point. Its contact point is its instantaneous centre."
    )


def _block_words(sc, block) -> str:
    """The driving block in words: its guide, its place and its motion."""
    inp = sc.input
    path = sc.slider(block)
    named = [p for p, xy in sc.ground.items() if xy == path.through]
    origin = named[0] if named else _at(sc, path.through)
    guide = (
        f"the {path.label} guide"
        if path.label in ("horizontal", "vertical")
        else f"the guide at {path.label}"
    )
    vs, a_s = inp.omega, inp.alpha

    def way(v):
        ux, uy = path.u if v >= 0 else (-path.u[0], -path.u[1])
        for (wx, wy), word in (
            ((1, 0), "to the right"),
            ((-1, 0), "to the left"),
            ((0, 1), "upwards"),
            ((0, -1), "downwards"),
        ):
            if abs(ux - wx) < ROUNDING and abs(uy - wy) < ROUNDING:
                return word
        return f"at {fmt(math.degrees(math.atan2(uy, ux)) % 360)}°"

    return (
        f"The block {block} drives the mechanism, sliding on {guide} through "
        f"{origin}; at the instant shown it is {_len(sc, abs(inp.angle))} from {origin}"
        + (f" ({'+' if inp.angle >= 0 else '-'} along the guide)" if inp.angle else "")
        + (
            f", at rest, about to move {way(vs)}"
            + (
                f" (starting with an acceleration of {fmt(abs(sc.start_alpha))} m/s² "
                f"{way(sc.start_alpha)})"
                if sc.start_alpha
                else ""
            )
            if sc.at_rest
            else f", moving at {fmt(abs(vs))} m/s {way(vs)}"
            + (
                f", with an acceleration of {fmt(abs(a_s))} m/s² {way(a_s)}"
                if a_s
                else ", steadily"
            )
        )
        + "."
    )


_SIDE = {"left": "to the left", "right": "to the right"}


def _len(sc, metres: float) -> str:
    return f"{_given(metres / sc.length_unit)} {sc.units}"


def _at(sc, xy) -> str:
    x, y = xy
    return f"({_given(x / sc.length_unit)}, {_given(y / sc.length_unit)}) {sc.units}"


def _given(x: float) -> str:
    """A datum as the scene gave it (ten significant figures: no rounding of the data, and
    no trace of the conversion to SI and back)."""
    return f"{x:.10g}"


def _given_words(g, cylinder=False) -> str:
    """The given motion as a book states it: ``the block B slides at 5 m/s left``."""
    name = "-".join(g.names) if any(len(n) > 1 for n in g.names) else "".join(g.names)
    what = {
        "omega": f"link {name} turns at {g.text}",
        "vs": (
            f"the cylinder {g.names[0]} extends at {g.text}"
            if cylinder
            else f"the block {name} slides along its guide at {g.text}"
        ),
        "v": f"{name} moves at {g.text}",
    }[g.kind]
    if g.rate is not None:
        what += (
            f", its {'angular acceleration' if g.kind == 'omega' else 'acceleration'} "
            f"being {g.rate_text}"
        )
    return what
