"""Answers by the instantaneous-centre method: a centre's position ``I_13 = [x, y]``.

A centre is read off the configuration diagram, so its tolerance is the drawing rule's
half millimetre at the configuration scale, grown as ``1 / (2 sin gamma)`` where the two
lines that locate it cross at less than 30 deg, never less than 0.5 % of its distance from
the crank's pivot (or of the longest link, if that is more). The error is the distance from
the correct centre, relative to the same length.
"""

from __future__ import annotations

import math

from ..solver.centres import locate
from ..common.errors import PolygonMethodError, SceneError
from ..common.numbers import fmt, quiet
from ..polygons.scales import DRAWING_PRECISION_CM, diagram_scales
from .verdicts import ROUNDING, Verdict

__all__ = ["centre_verdict"]


def _asked(sol, ans, cache: list) -> tuple:
    """(the located centres, i, j) of the answer ``I_ij`` (its bodies by number or by the
    scene's names), refused with one line where it names no centre; ``cache`` keeps the
    located centres for the other answers."""
    if not cache:
        try:
            cache.append(locate(sol))
        except PolygonMethodError as exc:
            raise SceneError(
                f"{ans.key}: the centres cannot be located here: {exc.message}",
                key=f"[answers] {ans.key}",
                line=ans.line,
            ) from None
    ic = cache[0]
    if all(isinstance(x, int) for x in ans.names):
        i, j = ans.names
    else:  # by the scene's names
        i, j = sorted(1 if str(x).lower() == "ground" else ic._number(x) for x in ans.names)
        if i == j:
            raise SceneError(
                f"{ans.key}: both name the same body", key=f"[answers] {ans.key}", line=ans.line
            )
    if j > ic.n:
        raise SceneError(
            f"there are {ic.n} links (ground 1, {sol.plan.steps[0].driver_name} "
            f"2): no centre I{i}{j}",
            key=f"[answers] {ans.key}",
            line=ans.line,
        )
    return ic, i, j


def _another_centre(sol, ic, c, gx, gy, tol) -> tuple:
    """(code, words) where the wrong answer (gx, gy) is another centre than ``c`` (the
    links numbered otherwise), else (None, None)."""
    for other in ic.centres.values():
        if (
            other is not c
            and other.point is not None
            and math.hypot(gx - other.point[0], gy - other.point[1]) <= tol
        ):
            return "another_centre", (
                f"that is {other.label}, the centre of links {other.i} and "
                f"{other.j} (the links numbered otherwise: ground 1, "
                f"{sol.plan.steps[0].driver_name} 2, "
                f"then {', '.join(ic.bodies[2:])})"
            )
    return None, None


def _asked_centre(ans, c, pivot, longest, u, un) -> Verdict:
    """The centre a question asks for (``I_13 = "?"``): its place, or its direction at
    infinity, not graded."""
    if c.point is None:
        deg = math.degrees(math.atan2(c.direction[1], c.direction[0])) % 180.0
        text = f"at infinity, {fmt(deg, 4)} deg"
        return Verdict.asked_of(
            ans, None, "m", False, text, {"correct_direction": list(c.direction)}
        )
    cx, cy = c.point
    base = max(math.hypot(cx - pivot[0], cy - pivot[1]), longest)
    text = "[" + ", ".join(fmt(quiet(v, base) / u, 5) for v in (cx, cy)) + f"] {un}"
    return Verdict.asked_of(
        ans,
        math.hypot(cx - pivot[0], cy - pivot[1]),
        "m",
        False,
        text,
        {"correct_position": [cx, cy]},
    )


def centre_verdict(sol, ans, tolerance, cache: list) -> Verdict:
    """The verdict on ``I_ij = [x, y]`` (``cache``: a list that keeps the located centres
    for the other answers). ``tolerance``: a relative one (0.01), a stated one (its
    length, ``--tolerance 1 mm``, else its per cent; its angle for a centre at infinity's
    direction) or None (the drawing rule)."""
    absolute = tolerance.absolute_for("m") if hasattr(tolerance, "absolute_for") else None
    turn = tolerance.absolute_for("rad") if hasattr(tolerance, "absolute_for") else None
    source = getattr(tolerance, "source", None)
    tolerance = getattr(tolerance, "relative", tolerance)
    ic, i, j = _asked(sol, ans, cache)
    c = ic.centre(i, j)
    sc = sol.scene
    u, un = sc.length_unit, sc.units
    pivot = sol.P[sc.input.pivot or next(iter(sc.ground))]  # a block driver: no pivot
    longest = max(lk.length for lk in sc.links)
    if ans.asked:  # a question without its answer: where the centre is, not graded
        return _asked_centre(ans, c, pivot, max(longest, 1e-300), u, un)
    if ans.value[0] == "infinity":
        return _at_infinity(sol, ans, c, turn and (math.degrees(turn[0]), f"{turn[1]} ({source})"))
    gx, gy = ans.value
    if c.point is None:
        deg = math.degrees(math.atan2(c.direction[1], c.direction[0])) % 180.0
        return Verdict(
            ans.key,
            ans.raw,
            math.hypot(gx - pivot[0], gy - pivot[1]),
            math.inf,
            "m",
            None,
            math.inf,
            math.inf,
            "a centre at infinity",
            False,
            False,
            "centre_at_infinity",
            f"{c.label} is at infinity (direction {fmt(deg, 4)} deg): {c.how}",
            ans.line,
            f"at infinity, {fmt(deg, 4)} deg",
            {"given_position": [gx, gy], "correct_direction": list(c.direction)},
        )
    cx, cy = c.point
    base = max(math.hypot(cx - pivot[0], cy - pivot[1]), longest)
    err = math.hypot(gx - cx, gy - cy)
    if absolute is not None:  # --tolerance 1 mm: a drawing's
        tol, rule = absolute[0], f"{absolute[1]} ({source})"
    elif tolerance is not None:
        tol, rule = tolerance * base, f"{100 * tolerance:g} % (stated)"
    else:
        space = diagram_scales(sol)[0]
        grow = 1.0 if c.condition >= 0.5 else 1.0 / (2.0 * c.condition)
        tol = max(DRAWING_PRECISION_CM * space.per_cm * grow, ROUNDING * base)
        rule = (
            f"a centre: {10 * DRAWING_PRECISION_CM:g} mm on the configuration diagram at "
            f"{space.text}, / (2 sin gamma) where its lines cross under 30 deg"
        )
    ok = err <= tol * (1 + ROUNDING)
    mistake, diagnosis = (None, None) if ok else _another_centre(sol, ic, c, gx, gy, tol)
    return Verdict(
        ans.key,
        ans.raw,
        math.hypot(gx - pivot[0], gy - pivot[1]),
        math.hypot(cx - pivot[0], cy - pivot[1]),
        "m",
        err / base,
        tol / base,
        tol,
        rule,
        ok,
        False,
        mistake,
        diagnosis,
        ans.line,
        "["
        + ", ".join(fmt(quiet(v, base) / u, 5) for v in (cx, cy))
        + f"] {un}",  # (noise about an axis: 0)
        {"given_position": [gx, gy], "correct_position": [cx, cy]},
    )


#: how far a centre at infinity's direction may be off (deg): a line's direction as drawn
DIRECTION_TOLERANCE_DEG = 1.0


def _at_infinity(sol, ans, c, stated=None) -> Verdict:
    """The verdict on a centre answered as at infinity (``"at infinity"``, or with the
    direction of the parallel lines it is the meeting point of, mod 180 deg); ``stated``:
    (deg, words) of an angle's tolerance stated (``--tolerance 0.5 deg``), else 1 deg."""
    sc = sol.scene
    said = ans.value[1]
    within, how = stated or (DIRECTION_TOLERANCE_DEG, f"{DIRECTION_TOLERANCE_DEG:g} deg")
    rule = f"a centre at infinity: its direction within {how}"
    if c.point is not None:
        cx, cy = c.point
        where = "[" + ", ".join(fmt(v / sc.length_unit, 5) for v in (cx, cy)) + f"] {sc.units}"
        words = f"{c.label} is at {where}, not at infinity: {c.how}"
        return Verdict(
            ans.key, ans.raw, math.inf, math.hypot(cx, cy), "m", None, math.inf, math.inf, rule, False,
            False, "centre_not_at_infinity", words, ans.line, where,
            {"correct_position": [cx, cy]},
        )  # fmt: skip
    deg = math.degrees(math.atan2(c.direction[1], c.direction[0])) % 180.0
    off = 0.0 if said is None else abs((math.degrees(said) - deg + 90.0) % 180.0 - 90.0)
    ok = off <= within
    mistake = words = None
    if not ok:
        mistake, words = "centre_direction", f"{c.label}'s lines run at {fmt(deg, 4)} deg: {c.how}"
        if abs(off - 90.0) <= within:
            mistake = "centre_direction_square"
            words = (
                f"the direction square to {c.label}'s lines given: it is at infinity along "
                f"{fmt(deg, 4)} deg (a block on a path: perpendicular to the path), {c.how}"
            )
    return Verdict(
        ans.key, ans.raw, math.inf, math.inf, "m", None, math.inf, math.inf, rule, ok, False, mistake,
        words, ans.line, f"at infinity, {fmt(deg, 4)} deg",
        {"correct_direction": list(c.direction)},
    )  # fmt: skip
