"""The answer keys of a turning-moment diagram stated on its own (the flywheel chapter):
``T_mean``, ``power``, ``dE_max``, ``E_stroke``, ``I_flywheel``, ``m_flywheel``, ``Cs``,
``speed_max``, ``speed_min``, ``alpha_at``, ``rim_radius``, ``rim_width``,
``rim_thickness``; with the classic slips, each worked again as the slip would have it: the
largest single area taken for dE_max, the coefficient of fluctuation taken as the range
either side of the mean (or as twice the whole range), the mean speed put in rpm where
rad/s belongs, a press's whole energy of a hole taken for dE_max.

They are computed answers: the tolerance is the answers' own, or three significant
figures.
"""

from __future__ import annotations

import math

from ..common.errors import SceneError
from ..forces.flywheel_cycle import ANSWER_FIELDS
from .verdicts import ROUNDING, Verdict, cs_slips
from ..common.tolerances import ROUNDING as ARITHMETIC, SAME

__all__ = ["cycle_verdicts", "CYCLE_UNITS"]

#: answer key -> (the record's field, SI unit, what it is)
CYCLE_UNITS = ANSWER_FIELDS
_NEEDS = {
    "T_mean": "a turning moment given as a law, segments or strokes, or the power (or the "
    "work of a cycle) beside dE_max (areas give no mean)",
    "power": "the mean speed ([flywheel] speed) and a law or segments, or a press",
    "E_stroke": "a punching press ([press])",
    "Ce": "the work of a cycle: a law, segments or strokes, or the power (or work) beside "
    "dE_max (areas give none)",
    "alpha_at": "[turning_moment] at, a crank angle, and [flywheel]",
    "rim_radius": "the rim's radius ([flywheel] radius, diameter, rim_speed or stress)",
    "rim_width": "the rim's section ([flywheel] width_to_thickness, width or thickness)",
    "rim_thickness": "the rim's section ([flywheel] width_to_thickness, width or thickness)",
}


def _slips(scene, c, key, correct) -> list:
    """(value, code, words) of each classic slip for ``key``."""
    out = []
    flywheel_keys = ("I_flywheel", "m_flywheel", "rim_width", "rim_thickness")
    if key in ("dE_max",) + flywheel_keys and c.form != "press" and c.areas:
        big = max(abs(a) for a in c.areas)
        if abs(big - c.dE_max) > SAME * c.dE_max:
            f = big / c.dE_max
            f = f if key not in ("rim_width", "rim_thickness") else math.sqrt(f)
            out.append(
                (
                    correct * f,
                    "largest_area",
                    "the largest single area taken for the maximum fluctuation of energy: "
                    "dE_max = E_max - E_min, the areas summed in order to the energies at "
                    "the crossings",
                )
            )
    if c.form == "press" and key in ("dE_max",) + flywheel_keys:
        f = 1.0 / (1.0 - scene.press.fraction)
        f = f if key not in ("rim_width", "rim_thickness") else math.sqrt(f)
        out.append(
            (
                correct * f,
                "whole_energy",
                "the whole energy of a hole taken for dE_max: the motor gives its share "
                "during the punching too, dE_max = E (1 - t_punching / t_cycle)",
            )
        )
    fw = scene.flywheel
    if key in ("I_flywheel", "m_flywheel") and fw is not None and fw.inertia is None:
        out += cs_slips(correct)
    if key in ("I_flywheel", "m_flywheel") and fw is not None and fw.inertia is None and fw.speed:
        out.append(
            (
                correct * (math.pi / 30) ** 2,
                "rpm_not_rad_per_s",
                "the mean speed put in rpm where rad/s belongs (I = dE_max / (w^2 Cs), "
                "w = 2 pi N / 60)",
            )
        )
    if key == "Cs" and fw is not None and fw.inertia is not None:
        out.append(
            (
                correct / 2,
                "cs_half_range",
                "the range either side of the mean given "
                "for Cs, which is the whole range (w_max - w_min) / w_mean",
            )
        )
    return out


def _refuse(ans, why):
    raise SceneError(f"{ans.key}: {why}", key=f"[answers] {ans.key}", line=ans.line)


def cycle_verdicts(scene, c, answers, tolerance) -> list:
    """The :class:`Verdict` on each answer against the solved cycle ``c``."""
    out = []
    for ans in answers:
        field, unit, what = CYCLE_UNITS[ans.key]
        correct = getattr(c, field)
        if correct is None:
            need = _NEEDS.get(ans.key, "[flywheel] (the speed and its fluctuation)")
            if ans.key == "m_flywheel":
                need = "the rim's radius or the radius of gyration in [flywheel]"
            fw = getattr(scene, "flywheel", None)
            if (
                fw is not None
                and fw.speed is None
                and ans.key not in _NEEDS.keys() - {"rim_radius"}
            ):
                need = (  # (the rim's speed alone: its mass is found, not I nor the speeds)
                    "the shaft's mean speed ([flywheel] speed): it gives the rim's speed "
                    "alone, which finds the rim's mass, not the flywheel's I, the rim's "
                    "radius or the greatest and least speeds"
                )
            _refuse(ans, f"no value to check against: the scene needs {need}")
        if ans.asked:  # a question without its answer: the value, not graded
            keep = ans.key in ("T_mean", "alpha_at")  # (signed: the rest are sizes)
            out.append(Verdict.asked_of(ans, correct if keep else abs(correct), unit, False))
            continue
        signed = ans.key in ("T_mean", "alpha_at") and ans.value < 0
        correct = correct if signed or ans.key in ("T_mean", "alpha_at") else abs(correct)
        given = ans.value if ans.key in ("T_mean", "alpha_at") else abs(ans.value)
        if ans.key in ("T_mean", "alpha_at") and not signed:
            correct = abs(correct)
        rel = tolerance
        rule = (
            f"{100 * rel:g} % (the answers' tolerance)"
            if rel is not None
            else "three significant figures (a computed answer)"
        )
        rel = rel if rel is not None else ROUNDING
        tol = rel * abs(correct)
        err = abs(given - correct)
        ok = err <= tol * (1 + ARITHMETIC)
        mistake = diagnosis = None
        if not ok:
            for v, code, words in _slips(scene, c, ans.key, correct):
                if abs(given - v) <= rel * abs(v) * (1 + ARITHMETIC):
                    mistake = code
                    diagnosis = (
                        f"{what} matches {words} ({f'{v:.4g} {unit}'.strip()}); the correct "
                        f"value is {f'{correct:.4g} {unit}'.strip()}"
                    )
                    break
        out.append(
            Verdict.judged(ans, given, correct, unit, tol, rule, ok, signed, mistake, diagnosis)
        )
    return out
