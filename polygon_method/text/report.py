"""The solution as a terminal report (``polygon-method solve``)."""

from __future__ import annotations

import math

from ..solver.errorbound import NO_BOUND, SHOWN, USELESS, shown_bounds
from .forces import forces_lines
from .link_points import pair_lines, pair_shown_bounds
from ..solver.given import stated
from ..common.numbers import fmt, fmt_angular, sense
from ..motion.solution import Solution
from ..motion.tidy import tidied

__all__ = ["solution_text", "direction_deg"]

#: the most bounds the report lists (the largest first)
SHOWN_LINES = 12


def direction_deg(x: float, y: float) -> float:
    """Direction of a vector in degrees, ccw from +x, in [0, 360)."""
    d = math.degrees(math.atan2(y, x)) % 360.0
    return 0.0 if d >= 359.9995 else d


def _vec(x, y, digits=4, noise=0.0):
    """A vector's size and direction, or 0 within ``noise`` (its own error bound)."""
    m = math.hypot(x, y)
    if m <= noise:
        return "0"
    return f"{m:.{digits}g} at {direction_deg(x, y):.1f} deg"


def _rim(st) -> tuple:
    """The points a rolling step reads and finds: the contact's bound is theirs."""
    return tuple(dict.fromkeys((*st.needs, *st.finds)))


def _coord(x: float) -> str:
    """A coordinate to 4 decimals, never ``-0.0000`` (rounding noise about zero)."""
    s = f"{x:.4f}"
    return s[1:] if s.startswith("-") and float(s) == 0 else s


def _given_lines(sol: Solution) -> list[str]:
    """The title and the input(s): the crank's angle, speed and acceleration as given, or the
    block driver's own words; a second input's, and why two inputs give no torque."""
    sc = sol.scene
    inp = sc.input
    lines = [sc.title or (sc.file or "mechanism")]
    said = f" ({inp.angle_words})" if inp.angle_words else ""
    own = sol.plan.steps[0].input_words(sc)  # a block driver's; a crank's are written here
    if own is not None and sc.at_rest:  # a driving block or wheel at rest
        per = sol.plan.steps[0].virtual_unit
        lines.append(
            f"{own} (at rest: nothing moves yet; the velocities and accelerations below are "
            f"per {per}, the virtual velocities of the power balance"
            + (
                "; starting from rest that way, the start's accelerations (the tangential "
                "terms alone) are in the forces below)"
                if sc.start_alpha
                else ")"
            )
        )
    elif own is not None:
        lines.append(own)
    else:
        lines.append(
            f"crank {inp.crank} at {math.degrees(inp.angle):g} deg{said}, "
            + (
                f"at rest, about to turn {sense(inp.omega)} (the velocities and "
                f"accelerations below are per 1 rad/s {sense(inp.omega)} of the crank: the "
                "virtual velocities of the power balance)"
                if sc.at_rest and not sc.start_alpha
                else f"starting from rest {sense(inp.omega)}, "
                f"{fmt_angular(sc.start_alpha, 'rad/s^2')} (the velocities and accelerations "
                f"below are per 1 rad/s {sense(inp.omega)} of the crank, the virtual "
                "velocities of the power balance; the start's accelerations, the tangential "
                "terms alone, alpha times those velocities, are in the forces below)"
                if sc.at_rest
                else f"{fmt_angular(inp.omega, 'rad/s')}"
            )
            + (
                ""
                if ("rad/s" in inp.speed_text and inp.given is None) or sc.at_rest
                else f" ({'from ' if inp.given else ''}{stated(inp)})"
            )
            + (f", {fmt_angular(inp.alpha, 'rad/s^2')}" if inp.alpha else "")
        )
    two = inp.second
    if two is not None and two.block is not None:  # a collar sliding along the crank
        lines.append(f"second input: {sol.plan.steps[1].second_words(sc)} (two degrees of freedom)")
    elif two is not None:
        lines.append(
            f"second input: crank {two.crank} at {math.degrees(two.angle):g} deg, "
            f"{fmt_angular(two.omega, 'rad/s')}"
            + (f" ({two.speed_text})" if two.speed_text.startswith("found from") else "")
            + (f", {fmt_angular(two.alpha, 'rad/s^2')}" if two.alpha else "")
            + " (two degrees of freedom)"
        )
        if sc.loads:
            lines.append(
                "no input torque: with two inputs one power balance does not give "
                "the two driving torques"
            )
    return lines


def _point_lines(sol: Solution) -> list[str]:
    """The table of points: position, velocity and acceleration of each."""
    sc = sol.scene
    u = sc.length_unit
    lines = [
        "",
        f"{'point':<6} {'position (' + sc.units + ')':<24} {'velocity (m/s)':<24} "
        f"{'acceleration (m/s^2)':<24}",
    ]
    for p in sc.point_names:
        x, y = sol.P[p]
        pos = f"({_coord(x / u)}, {_coord(y / u)})"
        lines.append(
            f"{p:<6} {pos:<24} {_vec(*sol.V[p], noise=sol.noise('v', p)):<24} "
            f"{_vec(*sol.A[p], noise=sol.noise('a', p)):<24}"
        )
    return lines


def _link_lines(sol: Solution) -> list[str]:
    """The table of links: length, omega and alpha with cw/ccw."""
    sc = sol.scene
    u = sc.length_unit
    lines = ["", f"{'link':<8} {'length (' + sc.units + ')':<14} {'omega':<22} {'alpha':<22}"]
    for lk in sc.links:
        w, al = (
            sol.shown(sol.W[lk.key], "omega", lk.key),
            sol.shown(sol.Al[lk.key], "alpha", lk.key),
        )
        lines.append(
            f"{lk.key:<8} {lk.length / u:<14.6g} {fmt_angular(w, 'rad/s'):<22} "
            f"{fmt_angular(al, 'rad/s^2'):<22}"
        )
    return lines


def _slider_lines(sol: Solution) -> list[str]:
    """The table of sliders: sliding velocity and acceleration and the Coriolis component
    (nothing without sliders)."""
    sc = sol.scene
    blocks = sc.blocks  # (not a driving wheel's centre: a point above)
    if not blocks:
        return []
    guides = {}
    for s in blocks:
        guide = getattr(s, "label", None) or getattr(s, "along", "")
        if getattr(s, "offset", 0.0):  # an offset slot: its line's distance off the link's
            guide += f" slot {fmt(abs(s.offset) / sc.length_unit, 4)} {'left' if s.offset > 0 else 'right'}"
        guides[s.key] = guide
    wide = max(16, *(len(g) for g in guides.values()))
    lines = [
        "",
        f"{'slider':<8} {'guide':<{wide}} {'sliding v (m/s)':<18} "
        f"{'sliding a (m/s^2)':<20} {'Coriolis (m/s^2)':<24}",
    ]
    for s in blocks:
        vs, a_s, cor = sol.S[s.key][0], sol.S[s.key][1], sol.coriolis(s.key)
        vs, a_s = sol.shown(vs, "vs", s.key), sol.shown(a_s, "as", s.key)
        lines.append(
            f"{s.key:<8} {guides[s.key]:<{wide}} {vs:<18.5g} {a_s:<20.5g} "
            f"{_vec(*cor, noise=sol.noise('ac', s.key)):<24}"
        )
    return lines


def _cylinder_lines(sol: Solution) -> list[str]:
    """The table of cylinders: length, extension and its rate, omega and alpha (nothing
    without cylinders)."""
    sc = sol.scene
    if not sc.cylinders:
        return []
    u = sc.length_unit
    lines = [
        "",
        f"{'cylinder':<10} {'length (' + sc.units + ')':<14} {'extension (m/s)':<17} "
        f"{'its rate (m/s^2)':<18} {'omega':<20} {'alpha':<22}",
    ]
    for cyl in sc.cylinders:
        n = sol.cylinder_length(cyl.key)
        vs = sol.shown(sol.S[cyl.key][0], "vs", cyl.key)
        a_s = sol.shown(sol.S[cyl.key][1], "as", cyl.key)
        w = sol.shown(sol.W[cyl.key], "omega", cyl.key)
        al = sol.shown(sol.Al[cyl.key], "alpha", cyl.key)
        lines.append(
            f"{cyl.key:<10} {n / u:<14.6g} {vs:<17.5g} {a_s:<18.5g} "
            f"{fmt_angular(w, 'rad/s'):<20} {fmt_angular(al, 'rad/s^2'):<22}"
        )
    return lines


def _rolling_lines(sol: Solution) -> list[str]:
    """The table of rolling contacts: the wheel's point at each contact, no slip, not at rest
    in acceleration (nothing without rolling steps)."""
    sc = sol.scene
    u = sc.length_unit
    contacts = [(st, st.contact_motion(sol)) for st in sol.plan.steps]
    contacts = [(st.bodies()[0], c, _rim(st)) for st, c in contacts if c is not None]
    if not contacts:
        return []
    lines = [
        "",
        f"{'rolling':<8} {'contact (' + sc.units + ')':<24} {'velocity (m/s)':<24} "
        f"{'acceleration (m/s^2)':<24}",
    ]
    for k, (I, v, a), rim in contacts:
        pos = f"({_coord(I[0] / u)}, {_coord(I[1] / u)})"
        lines.append(
            f"{k:<8} {pos:<24} {_vec(*v, noise=sol.noise('v', rim)):<24} "
            f"{_vec(*a, noise=sol.noise('a', rim)):<24}"
        )
    return lines


def _rubbing_lines(sol: Solution) -> list[str]:
    """The table of pins: radius and rubbing velocity, each pair's where a pin joins more than
    two bodies (nothing without pins)."""
    sc = sol.scene
    if not sc.pins:
        return []
    u = sc.length_unit
    lines = ["", "pin   radius (" + sc.units + ")  rubbing velocity (m/s)"]
    for name, r in tidied(sol).rubbing.items():  # two equal omegas rub at 0
        if not r.pairs:
            lines.append(
                f"{name:<5} {r.radius / u:<12.6g} 0 (the pin joins only "
                f"{', '.join(r.bodies) or 'nothing'})"
            )
            continue
        detail = "; ".join(f"{k}: {v:.4g}" for k, v in r.pairs.items())
        lines.append(
            f"{name:<5} {r.radius / u:<12.6g} {r.rubbing_velocity:.4g}"
            + (f"   ({detail})" if len(r.pairs) > 1 else "")
        )
    return lines


def _torque_lines(sol: Solution) -> list[str]:
    """The input torque by power balance, or the block driver's or driving cylinder's
    effort (nothing without one)."""
    if sol.input_torque is None:
        return []
    sc = sol.scene
    driver = sol.plan.steps[0]
    tidy = tidied(sol)  # from the velocities without rounding noise
    t = tidy.input_torque
    if driver.input_words(sc) is not None:
        said = driver.effort_words(t)
        if sc.at_rest:  # (per unit speed of the driver: the loads' virtual power)
            said = said.replace("(power balance, no friction or inertia)", "").rstrip()
            said += " (the loads' power balance, without the weights)"
        return ["", said]
    if tidy.cylinder_force is not None:  # the power T omega goes in as F vs along it
        cylinder, f = tidy.cylinder_force
        way = "pushing its ends apart" if f >= 0 else "pulling its ends together"
        return [
            "",
            f"input force in cylinder {cylinder}: {fmt(abs(f))} N {way} "
            "(power balance, no friction or inertia)",
        ]
    return [
        "",
        f"input torque on {sc.input.crank}: {fmt_angular(t, 'N m')} "
        + (
            "(the loads' power balance, without the weights)"
            if sc.at_rest
            else "(power balance, no friction or inertia)"
        ),
    ]


def _plan_lines(sol: Solution) -> list[str]:
    """The plan: each step, what it finds and its condition."""
    lines = [
        "",
        "plan (condition: the sine of the angle between the step's two direction "
        "lines, unless it says otherwise):",
    ]
    for st in sol.plan.steps:
        c = sol.conditions.get(st.index, 1.0)
        col = st.condition_column()
        own = f" = {col[2]}" if col is not None and col[1] != "deg" else ""
        lines.append(
            f"  {st.index + 1}. {st.title}: finds "
            f"{', '.join(st.finds) or 'its length and rates (no new point)'}"
            f"   condition {c:.3g}{own}"
        )
    return lines


def _bound_lines(sol: Solution) -> list[str]:
    """The estimated error bounds above the shown threshold, the largest first, at most
    ``SHOWN_LINES`` of them (nothing when none is above it)."""
    bounds = shown_bounds(sol, sol.error_bounds) + pair_shown_bounds(sol)
    bounds.sort(key=lambda t: -t[1])  # (vmin_BC ... where asked, among the others)
    if not bounds:
        return []
    lines = [
        f"estimated error above {SHOWN:g} (rounding times 1/condition along "
        "each quantity's steps; relative to the largest of its kind):"
    ]
    for what, b in bounds[:SHOWN_LINES]:
        lines.append(f"  {what}: {b:.2g}" if b < USELESS else f"  {what}: no useful bound")
    useless = sum(1 for _, b in bounds if not b < USELESS)
    if useless:
        lines.append(f"  ({useless} quantit{'y has' if useless == 1 else 'ies have'} {NO_BOUND})")
    if len(bounds) > SHOWN_LINES:
        lines.append(
            f"  ... and {len(bounds) - SHOWN_LINES} more (every bound: solve --json, error_bounds)"
        )
    return lines


def solution_text(sol: Solution) -> str:
    """The solution as ``solve`` prints it: the given, positions, velocities, accelerations, omegas
    and alphas with cw/ccw, sliders, rubbing, the input torque, warnings and error bounds."""
    lines = _given_lines(sol)
    for part in (
        _point_lines,
        _link_lines,
        _slider_lines,
        _cylinder_lines,
        _rolling_lines,
        _rubbing_lines,
        _torque_lines,
    ):
        lines += part(sol)
    lines += pair_lines(sol)  # vmin_BC, ar_CB, at_CB: where the answers ask them
    lines += forces_lines(sol)
    lines += _plan_lines(sol)
    lines += _bound_lines(sol)
    lines += [f"warning: {w}" for w in sol.warnings]
    lines += [f"note: {n}" for n in sol.notes]
    return "\n".join(lines)
