"""The questions asked of two points of one link, in words: the point of the link with the
least absolute velocity (``vmin_BC``: the foot of the perpendicular from o to bc) and the
radial and tangential components of a relative acceleration (``ar_CB``, ``at_CB``). Only
what the scene's ``[answers]`` asks is written: ``solve``'s lines, ``steps``' items (the
values are :mod:`polygon_method.motion.link_points`')."""

from __future__ import annotations

from ..common.numbers import fmt
from ..motion.link_points import asked_pairs, components, least_speed, pair_bounds
from ..solver.errorbound import SHOWN

__all__ = ["pair_lines", "pair_items", "foot_name", "pair_shown_bounds"]


def _len(sol, metres: float) -> str:
    """A length (m) in the scene's own unit, to four figures: "1234 mm"."""
    return f"{fmt(metres / sol.scene.length_unit, 4)} {sol.scene.units}"


def _two(x: str, y: str) -> str:
    """Two points' names as one: "BC", "O4-B" where a name has digits (as the keys)."""
    return x + y if len(x) == len(y) == 1 else f"{x}-{y}"


def foot_name(sol, key=None) -> str:
    """The slowest point's name, as the books call it (P), or a letter the scene leaves free;
    where several ``vmin`` keys are asked, ``key``'s own: the first P, the next the next free
    letter (F, M, N, ...), so that no two feet share a name on one polygon."""
    taken = set(sol.scene.point_names)
    least = [k for k, kind, _ in asked_pairs(sol.scene) if kind == "vmin"]
    i = least.index(key) if key in least else 0
    free = [n for n in "PFMNQKZ" if n not in taken]
    free += [f"P{j}" for j in range(1, len(least) + len(taken) + 2) if f"P{j}" not in taken]
    return free[i]


def _least_words(sol, key, x, y, construction=False, scale=None) -> str:
    """The least speed on segment XY: where, and how much (with the construction)."""
    ls = least_speed(sol, x, y)
    b, c = x.lower(), y.lower()  # their images
    P = foot_name(sol, key)
    p = P.lower()
    if ls.where == "translating":
        return (
            f"{key} = {fmt(ls.speed, 4)} m/s: {_two(x, y)} does not turn (omega_{ls.link} = 0), so "
            f"every point of it moves alike, at {fmt(ls.speed, 4)} m/s ({b} and {c} are one "
            "point of the velocity diagram)"
        )
    cm = f" ({ls.foot_speed / scale.per_cm:.2f} cm at {scale.text})" if scale else ""
    foot = (
        f"from o draw o{p} perpendicular to {_two(b, c)}, meeting {_two(b, c)}"
        + (" produced" if ls.where != "between" else "")
        + f" at {p}: {_two(x, P)} = {_two(x, y)} x {_two(b, p)} / {_two(b, c)} = {_len(sol, ls.length)} x "
        f"{fmt(ls.fraction, 4)} = {_len(sol, ls.offset)}; v_{P} = o{p} = "
        f"{fmt(ls.foot_speed, 4)} m/s{cm}"
        if construction
        else f"the foot {p} of the perpendicular from o to {_two(b, c)}: {_two(x, P)} = "
        f"{_len(sol, ls.offset)} ({_two(x, P)} / {_two(x, y)} = {fmt(ls.fraction, 4)}), o{p} = "
        f"{fmt(ls.foot_speed, 4)} m/s"
    )
    if ls.where == "between":
        return f"{key} = {fmt(ls.speed, 4)} m/s at {P} on {_two(x, y)}: {foot}"
    end = x if ls.fraction < 0 else y
    return (
        f"{key} = {fmt(ls.speed, 4)} m/s at the end {end}: {foot}; {p} falls beyond "
        f"{end.lower()}, outside {_two(b, c)}, so the point of the link itself moving slowest is "
        f"its end {end} (o{p} is the least of {_two(x, y)} produced)"
    )


def _component_words(sol, key, kind, x, y) -> str:
    """One component of X's acceleration relative to Y, worked."""
    c = components(sol, x, y)
    w, al, r = abs(c.omega), abs(c.alpha), fmt(c.r, 4)
    if kind == "ar":
        return (
            f"{key} = omega_{c.link}^2 x {_two(x, y)} = {fmt(w, 4)}^2 x {r} = "
            f"{fmt(c.radial, 4)} m/s^2, along {_two(x, y)} from {x} towards {y} (centripetal)"
        )
    return (
        f"{key} = alpha_{c.link} x {_two(x, y)} = {fmt(al, 4)} x {r} = {fmt(c.tangential, 4)} "
        f"m/s^2, perpendicular to {_two(x, y)} (tangential)"
    )


def pair_lines(sol) -> list[str]:
    """``solve``'s lines for the asked ``vmin``, ``ar``, ``at`` keys (none when none)."""
    asked = asked_pairs(sol.scene)
    if not asked:
        return []
    lines = ["", "asked of two points of a link:"]
    for key, kind, (x, y) in asked:
        words = (
            _least_words(sol, key, x, y)
            if kind == "vmin"
            else _component_words(sol, key, kind, x, y)
        )
        lines.append(f"  {words}")
    return lines


def pair_items(sol, vscale) -> list[str]:
    """``steps``' items for the asked keys: the construction on the velocity diagram, the
    components worked (none when none are asked)."""
    return [
        _least_words(sol, key, x, y, construction=True, scale=vscale)
        if kind == "vmin"
        else _component_words(sol, key, kind, x, y)
        for key, kind, (x, y) in asked_pairs(sol.scene)
    ]


#: the numbers of an asked key's record that solve's text shows, by the words it lists them in
_SHOWN_PARTS = {"value": "{0}", "foot_speed": "{0}: op", "distance": "{0}: where along"}


def pair_shown_bounds(sol) -> list:
    """(quantity, bound) of the asked keys' numbers whose bound exceeds ``SHOWN`` (the
    value; for ``vmin`` op and the slowest point's distance along XY, relative to the
    positions' size), for ``solve``'s lines of estimated errors."""
    out = []
    for key, kind, (x, y) in asked_pairs(sol.scene):
        b = pair_bounds(sol, kind, x, y)
        for part, words in _SHOWN_PARTS.items():
            if part in b and b[part] > SHOWN:
                out.append((words.format(key), b[part]))
    return out
