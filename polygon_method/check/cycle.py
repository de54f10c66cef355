"""The answers of the crank's cycle and of the configuration: a quick return's ratio of the
time of the cutting stroke to the return stroke (``time_ratio``), a slider's length of
stroke (``stroke_X``), a link's direction from +x (``theta_XY``) and the angle at a joint
(``angle_XYZ``); with the classic slips (the inverse ratio, return over cutting; the
stroke in the wrong unit, a power of ten off; the direction from the link's other end; the
angle's supplement).

They are computed answers (no drawing to read): the tolerance is the answers' own, or
three significant figures.
"""

from __future__ import annotations

import math
from dataclasses import replace

from ..common.errors import PolygonMethodError, SceneError
from ..common.numbers import textbook
from ..common.tolerances import FLOOR
from ..common.units import UNITS
from ..linkage.cycle_values import CYCLE_KEYS, CYCLE_SI, cycle_value, words
from .verdicts import ROUNDING, Verdict

__all__ = ["CYCLE_KEYS", "cycle_verdict"]

#: the size a direction's or an angle's tolerance is taken of (deg), whatever its value
RIGHT_ANGLE = 90.0


def _correct(sol, ans) -> float:
    """The right value (a ratio, m, or deg), or the answer refused in one line naming it."""
    try:
        v = cycle_value(sol, ans.kind, ans.names, ans.key)
    except PolygonMethodError as exc:
        if exc.key and not exc.key.startswith("[answers]"):  # the scene's fault: its key
            raise exc.located(sol.scene.file) from None
        raise SceneError(exc.message, key=f"[answers] {ans.key}", line=ans.line) from None
    if ans.kind in ("theta", "angle"):
        return math.degrees(v)
    return v


def _own_unit(sol, ans) -> tuple:
    """(unit, factor from the verdict's unit) a stroke or angle is shown in: the unit asked
    for or written, else the scene's length unit (a stroke) or degrees."""
    words = str(ans.raw).split()[1:]
    unit = " ".join(words)
    if ans.kind == "stroke":
        if unit in UNITS["length"]:
            return unit, UNITS["length"][unit]
        return sol.scene.units, sol.scene.length_unit
    if unit == "rad":
        return "rad", 180 / math.pi  # (degrees in a radian)
    return "deg", 1.0


def _slips(sol, ans, correct) -> list:
    """(value, code, words) of each classic slip for ``ans``."""
    kind = ans.kind
    if kind == "time_ratio":
        return [
            (
                1 / correct,
                "inverse_ratio",
                "the return stroke's time over the cutting stroke's (the ratio is the "
                "cutting stroke's time over the return's, the larger over the smaller)",
            )
        ]
    if kind == "stroke":
        return [
            (correct * 10.0**k, "wrong_unit", "the stroke in the wrong unit (a power of ten off)")
            for k in (-3, -2, -1, 1, 2, 3)
        ]
    if kind == "theta":
        return [
            ((correct + 180) % 360, "other_end", "the direction from the link's other end"),
            ((180 - correct) % 360, "from_minus_x", "the angle measured from -x, not +x"),
        ]
    return [(180 - correct, "supplement", "the angle's supplement (the other side of the joint)")]


def _angle_off(given, correct) -> float:
    """How far a direction given is from the correct one, round the circle (deg)."""
    d = abs(given - correct) % 360
    return min(d, 360 - d)


def cycle_verdict(sol, ans, tolerance) -> Verdict:
    """The :class:`Verdict` on a ``time_ratio``, ``stroke_X``, ``theta_XY`` or ``angle_XYZ``
    answer (or the value of the question asked without its answer)."""
    kind = ans.kind
    correct = _correct(sol, ans)
    unit = CYCLE_KEYS[kind][1]
    if ans.asked:  # a question without its answer: the value, not graded
        text = None
        if kind != "time_ratio":
            own, f = _own_unit(sol, ans)
            text = f"{textbook(correct / f)} {own}"
        if kind in ("theta", "angle"):  # (solve --json's value in SI, as every other's)
            return Verdict.asked_of(ans, math.radians(correct), "rad", False, correct_text=text)
        return Verdict.asked_of(ans, correct, unit, False, correct_text=text)
    given = math.degrees(ans.value) if kind in ("theta", "angle") else ans.value
    rel = getattr(tolerance, "relative", tolerance)
    source = getattr(tolerance, "source", None) or "the answers' tolerance"
    stated = getattr(tolerance, "absolute_for", lambda unit: None)(CYCLE_SI[kind])
    rule = (
        f"{stated[1]} ({source})"  # --tolerance 1 mm, 1 deg: a drawing's
        if stated is not None
        else f"{100 * rel:g} % ({source})"
        if rel is not None
        else "three significant figures (a computed answer)"
    )
    rel = rel if rel is not None else ROUNDING
    if kind == "theta":  # a direction: round the circle, -30 deg is 330 deg
        err = _angle_off(given, correct)
        near = given - ((given - correct + 180) % 360 - 180)  # correct, written as given is
        correct_shown = near
    else:
        err = abs(given - correct)
        correct_shown = correct
    # a direction or an angle: its tolerance that of a right angle, however it is written
    # (near 0 deg, or as 1.5 rather than -358.5, it was held tighter than any other)
    size = RIGHT_ANGLE if kind in ("theta", "angle") else abs(correct_shown)
    tol = max(rel * size, FLOOR)
    if stated is not None:  # (in the unit graded: deg for an angle)
        tol = math.degrees(stated[0]) if kind in ("theta", "angle") else stated[0]
    ok = err <= tol * (1 + ROUNDING)
    mistake = diagnosis = None
    if not ok:
        for v, code, what in _slips(sol, ans, correct):
            off = _angle_off(given, v) if kind == "theta" else abs(given - v)
            slack = rel * (RIGHT_ANGLE if kind in ("theta", "angle") else abs(v))
            slack = tol if stated is not None else max(slack, FLOOR)
            if off <= slack * (1 + ROUNDING):
                mistake = code
                diagnosis = (
                    f"{words(kind, ans.names)} matches {what} ({textbook(v)} {unit}".rstrip()
                    + f"); the correct value is {textbook(correct)} {unit}".rstrip()
                )
                break
    if kind in ("theta", "angle"):  # graded in degrees, recorded in SI (rad) as every other
        v = Verdict.judged(
            ans,
            math.radians(given),
            math.radians(correct_shown),
            "rad",
            math.radians(tol),
            rule,
            ok,
            False,
            mistake,
            diagnosis,
        )
        return replace(v, correct_text=f"{textbook(correct_shown)} deg")
    return Verdict.judged(ans, given, correct_shown, unit, tol, rule, ok, False, mistake, diagnosis)
