"""The slips of the answers of two points of one link: the least speed (``vmin_BC``) taken
at the middle of the link, at its slower end, or on the link produced; the radial and
tangential components (``ar_CB``, ``at_CB``) swapped, omega not squared, another link's
omega or alpha used. The values are the solution's (:mod:`..motion.link_points`)."""

from __future__ import annotations

import math

from ..common.numbers import textbook as _g
from ..motion.link_points import components, least_speed
from .alternatives import _Candidate

__all__ = ["link_slips"]


def link_slips(sol, ans) -> list:
    """The candidates of the known slips for ``vmin_XY``, ``ar_XY`` or ``at_XY``."""
    x, y = ans.names
    if ans.kind == "vmin":
        return _least_speed_slips(sol, x, y)
    return _component_slips(sol, ans.kind, x, y)


def _least_speed_slips(sol, x, y) -> list:
    ls = least_speed(sol, x, y)
    if ls.where == "translating":
        return []
    (bx, by), (cx, cy) = sol.V[x], sol.V[y]
    mid = math.hypot(bx + cx, by + cy) / 2
    out = [
        _Candidate(
            mid,
            "midpoint_speed",
            f"the speed of the middle of {x}{y} ({_g(mid)} m/s); the slowest point is the "
            f"foot p of the perpendicular from o to {x.lower()}{y.lower()}, not the middle",
        )
    ]
    if ls.where == "between":
        end = min((x, y), key=sol.speed)
        out.append(
            _Candidate(
                sol.speed(end),
                "end_for_least",
                f"the slower end's speed, v_{end} ({_g(sol.speed(end))} m/s); the foot of "
                f"the perpendicular from o falls between {x.lower()} and {y.lower()}: "
                f"the least is op there",
            )
        )
    else:
        end = x if ls.fraction < 0 else y
        out.append(
            _Candidate(
                ls.foot_speed,
                "produced_for_link",
                f"op ({_g(ls.foot_speed)} m/s), the least of {x}{y} produced: the foot of "
                f"the perpendicular falls beyond {end.lower()}, so the least on the link "
                f"itself is at its end {end}, {_g(ls.speed)} m/s",
            )
        )
    return out


def _component_slips(sol, kind, x, y) -> list:
    c = components(sol, x, y)
    other = c.tangential if kind == "ar" else c.radial
    words = {"ar": "radial (omega^2 r)", "at": "tangential (alpha r)"}
    out = [
        _Candidate(
            other,
            "components_swapped",
            f"the {words['at' if kind == 'ar' else 'ar']} component given for the "
            f"{words[kind]} one ({_g(other)} m/s^2)",
        )
    ]
    if kind == "ar":
        out.append(
            _Candidate(
                abs(c.omega) * c.r,
                "omega_not_squared",
                f"omega r, not omega^2 r: {_g(abs(c.omega) * c.r)} is v_{x}{y} (m/s)",
            )
        )
    table = sol.W if kind == "ar" else sol.Al
    for key, w in table.items():  # another link's omega (alpha)
        what = "omega" if kind == "ar" else "alpha"
        if key == c.link or key in sol.plan.fixed_links or sol.shown(w, what, key) == 0:
            continue  # (a link at rest, or turning uniformly: no slip to name)
        v = w * w * c.r if kind == "ar" else abs(w) * c.r
        out.append(
            _Candidate(
                v,
                "other_link_rate",
                f"{what}_{key} (another link's) used: {what}_{c.link} is the one of {x}{y}",
            )
        )
    return out
