"""The questions asked of two points of one link, in words: the point of the link with the
least absolute velocity (``vmin_BC``: the foot of the perpendicular from o to bc) and the
radial and tangential components of a relative acceleration (``ar_CB``, ``at_CB``). Only
what the scene's ``[answers]`` asks is written: ``solve``'s lines, ``steps``' items (the
values are :mod:`polygon_method.motion.link_points`')."""

from __future__ import annotations

from ..common.numbers import fmt
from ..motion.link_points import asked_pairs, components, least_speed

__all__ = ["pair_lines", "pair_items"]


def _len(sol, metres: float) -> str:
    """A length (m) in the scene's own unit, to four figures: "1234 mm"."""
    return f"{fmt(metres / sol.scene.length_unit, 4)} {sol.scene.units}"


def _foot(sol) -> str:
    """The slowest point's name, as the books call it (P), or a letter the scene leaves free."""
    return next((n for n in "PFMNQKZ" if n not in sol.scene.point_names), "P'")


def _least_words(sol, key, x, y, construction=False, scale=None) -> str:
    """The least speed on segment XY: where, and how much (with the construction)."""
    ls = least_speed(sol, x, y)
    b, c = x.lower(), y.lower()
    P, p = _foot(sol), _foot(sol).lower()
    if ls.where == "translating":
        return (
            f"{key} = {fmt(ls.speed, 4)} m/s: {x}{y} does not turn (omega_{ls.link} = 0), so "
            f"every point of it moves alike, at {fmt(ls.speed, 4)} m/s ({b} and {c} are one "
            "point of the velocity diagram)"
        )
    cm = f" ({ls.foot_speed / scale.per_cm:.2f} cm at {scale.text})" if scale else ""
    foot = (
        f"from o draw o{p} perpendicular to {b}{c}, meeting {b}{c}"
        + (" produced" if ls.where != "between" else "")
        + f" at {p}: {x}{P} = {x}{y} x {b}{p} / {b}{c} = {_len(sol, ls.length)} x "
        f"{fmt(ls.fraction, 4)} = {_len(sol, ls.offset)}; v_{P} = o{p} = "
        f"{fmt(ls.foot_speed, 4)} m/s{cm}"
        if construction
        else f"the foot {p} of the perpendicular from o to {b}{c}: {x}{P} = "
        f"{_len(sol, ls.offset)} ({x}{P} / {x}{y} = {fmt(ls.fraction, 4)}), o{p} = "
        f"{fmt(ls.foot_speed, 4)} m/s"
    )
    if ls.where == "between":
        return f"{key} = {fmt(ls.speed, 4)} m/s at {P} on {x}{y}: {foot}"
    end = x if ls.fraction < 0 else y
    return (
        f"{key} = {fmt(ls.speed, 4)} m/s at the end {end}: {foot}; {p} falls beyond "
        f"{end.lower()}, outside {b}{c}, so the point of the link itself moving slowest is "
        f"its end {end} (o{p} is the least of {x}{y} produced)"
    )


def _component_words(sol, key, kind, x, y) -> str:
    """One component of X's acceleration relative to Y, worked."""
    c = components(sol, x, y)
    w, al, r = abs(c.omega), abs(c.alpha), fmt(c.r, 4)
    if kind == "ar":
        return (
            f"{key} = omega_{c.link}^2 x {x}{y} = {fmt(w, 4)}^2 x {r} = "
            f"{fmt(c.radial, 4)} m/s^2, along {x}{y} from {x} towards {y} (centripetal)"
        )
    return (
        f"{key} = alpha_{c.link} x {x}{y} = {fmt(al, 4)} x {r} = {fmt(c.tangential, 4)} "
        f"m/s^2, perpendicular to {x}{y} (tangential)"
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
