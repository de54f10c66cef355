"""A verdict on one answer, and the verdicts as text and as JSON."""

from __future__ import annotations

import math
import textwrap
from dataclasses import dataclass

from ..common.numbers import textbook as _g
from ..common.units import ANSWER_UNITS, UNITS, implausible

#: relative error of a value rounded to three significant figures (the floor of every
#: tolerance)
ROUNDING = 0.005
_SIN30 = 0.5

#: answer kind -> the SI unit its value is written in
UNIT_OF = ANSWER_UNITS

#: the answer kinds the force analysis gives (computed, not drawn: three significant
#: figures, or the answers' tolerance; the force chapter's slips)
FORCE_KINDS = (
    *("F", "N", "Fc", "Fi", "Ci", "h", "force", "force2", "torque2", "Tmax", "Pmax", "Thold"),
)


#: answer kind -> the kind of quantity whose largest value sets what is rounding noise
_NOISE_KIND = {
    "v": "v",
    "vs": "v",
    "rub": "v",
    "a": "a",
    "as": "a",
    "ac": "a",
    "vI": "v",
    "aI": "a",
    "vu": "v",
    "au": "a",
    "omega": "omega",
    "alpha": "alpha",
    "vmin": "v",
    "ar": "a",
    "at": "a",
}


@dataclass(frozen=True)
class Verdict:
    """One answer checked.

    ``given`` and ``correct`` are in SI; both are signed (ccw positive, or along the guide)
    when the answer states a sense or a sign, else magnitudes. ``error`` and ``tolerance``
    are relative (fractions); ``error`` is None when the correct value is zero.
    """

    key: str
    raw: str
    given: float
    correct: float
    unit: str
    error: float | None
    tolerance: float
    tolerance_abs: float
    rule: str
    ok: bool
    signed: bool
    mistake: str | None = None
    diagnosis: str | None = None
    line: int | None = None
    correct_text: str | None = None  # how the correct value is shown, where not a number
    extra: dict | None = None  # more for the JSON (a centre's positions)
    also: tuple = ()  # the same quantity given again under another name: (key, raw, line, ok, given)
    column: str | None = None  # the quantity's one name in a class's table (omega_BC for omega_CB)
    asked: bool = False  # a question asked without its answer ("?"): not graded, its value shown

    @property
    def quantity(self) -> str:
        """The name a class's table and summary give this answer: one for every spelling of
        one quantity (``omega_CB`` is ``omega_BC``, as the scene names the link)."""
        return self.column or self.key

    @classmethod
    def judged(
        cls, ans, given, correct, unit, tol, rule, ok, signed, mistake=None, diagnosis=None
    ) -> "Verdict":
        """The verdict on answer ``ans`` (its key, text and line) of ``given`` against
        ``correct`` with the absolute tolerance ``tol``: error |given - correct| / |correct|
        (None where correct is nought) and tolerance tol / |correct| (infinite there)."""
        return cls(
            ans.key,
            ans.raw,
            given,
            correct,
            unit,
            abs(given - correct) / abs(correct) if correct else None,
            tol / abs(correct) if correct else math.inf,
            tol,
            rule,
            ok,
            signed,
            mistake,
            diagnosis,
            ans.line,
        )

    @classmethod
    def asked_of(cls, ans, correct, unit, signed, correct_text=None, extra=None) -> "Verdict":
        """A question asked without its answer (``v_C = "?"``): the tool's value
        ``correct`` (the one a given answer is checked against), not graded (``ok``: it
        makes nothing wrong)."""
        return cls(
            ans.key,
            ans.raw,
            None,
            correct,
            unit,
            None,
            math.inf,
            math.inf,
            ASKED_RULE,
            True,
            signed,
            line=ans.line,
            correct_text=correct_text,
            extra=extra,
            asked=True,
        )

    @property
    def warning(self) -> str | None:
        """Words warning of a given value beyond what a mechanism usually reaches (read
        and checked all the same: a mechanism near a toggle may produce it)."""
        kind = _KIND_OF_UNIT.get(self.unit)
        if kind is None or not isinstance(self.given, (int, float)):
            return None
        return implausible(self.given, kind)

    @property
    def error_percent(self):
        """The answer's relative error in per cent, or None when it has none (a missing answer)."""
        return None if self.error is None else 100.0 * self.error

    def to_dict(self) -> dict:
        """The verdict as the JSON of ``check --json`` records it (a question asked without
        its answer: ``verdict`` "asked", ``given`` null, ``correct`` the tool's value, and
        ``correct_text`` as the book gives it, in the unit asked for)."""
        if self.asked:
            return {
                "key": self.key,
                "given": None,
                "given_text": self.raw,
                "correct": self.correct,
                "correct_text": asked_text(self),
                "unit": self.unit,
                "verdict": "asked",
                "asked": True,
                "line": self.line,
                **(self.extra or {}),
            }
        return {
            "key": self.key,
            "given": self.given,
            "given_text": self.raw,
            "correct": self.correct,
            "unit": self.unit,
            "error_percent": self.error_percent,
            "tolerance_percent": 100.0 * self.tolerance,
            "rule": self.rule,
            "verdict": "right" if self.ok else "wrong",
            "mistake": self.mistake,
            "diagnosis": self.diagnosis,
            "line": self.line,
            **({"warning": self.warning} if self.warning else {}),
            **({"also": [_also_dict(a) for a in self.also]} if self.also else {}),
            **(self.extra or {}),
        }


def _also_dict(also) -> dict:
    """One answer graded with another of the same quantity, for the JSON."""
    key, raw, line, ok, _ = also
    return {"key": key, "given_text": raw, "line": line, "verdict": "right" if ok else "wrong"}


def also_words(v: Verdict) -> str | None:
    """The line under a row where the same quantity was given under several names
    (``omega_BC`` and ``omega_CB``: one link's angular velocity): graded once."""
    if not v.also:
        return None
    names = ", ".join(
        f"{key} = {raw}" + (f" (line {line})" if line else "") for key, raw, line, _, _ in v.also
    )
    same = all(given == v.given for *_, given in v.also)
    return f"also given as {names}: the same quantity, graded once" + (
        "" if same else " (right only if every value given for it is right)"
    )


#: the SI unit of an answer -> the kind of quantity (units.UNITS) it is given in
_KIND_OF_UNIT = {
    "m/s": "velocity",
    "m/s^2": "acceleration",
    "rad/s": "angular_velocity",
    "rad/s^2": "angular_acceleration",
    "N m": "torque",
    "N": "force",
    "m": "length",
    "W": "power",
    "J": "energy",
    "kg m^2": "moment_of_inertia",
    "kg": "mass",
}


def _given_unit(v: Verdict):
    """(unit, factor to SI) the answer was written in, where that is not the SI unit
    (``"125.7 in/s"`` -> ``("in/s", 0.0254)``), else None."""
    if not isinstance(v.raw, str):
        return None
    words = v.raw.split()[1:]
    if words and words[-1] in (
        "cw",
        "ccw",
        "clockwise",
        "anticlockwise",
        "acw",
        "counterclockwise",
    ):
        words = words[:-1]
    unit = " ".join(words)
    table = UNITS.get(_KIND_OF_UNIT.get(v.unit, ""), {})
    factor = table.get(unit)
    if not unit or factor is None or factor == 1.0:
        return None
    return unit, factor


#: the rule of a question asked without its answer
ASKED_RULE = "asked, no answer given: not graded"


def asked_text(v: Verdict) -> str:
    """The tool's value of a question asked without its answer, as a book gives its answer:
    in the unit asked for (``"? rpm"``: ``45.69 rpm cw``), else in SI (``0.3828 m/s``,
    ``4.785 rad/s cw``; a centre ``[x, y] mm``)."""
    if v.correct_text:
        return v.correct_text
    if v.unit == "":  # a fraction (a coefficient of fluctuation): "? %" in per cent
        pc = v.raw.split()[1:] == ["%"]
        return f"{_g(100 * v.correct)} %" if pc else _g(v.correct)
    along = (v.extra or {}).get("along")  # a sliding velocity's: its size, and which way
    x, own = (abs(v.correct) if along else v.correct), _given_unit(v)
    if own is None:
        text = _show(v, x)
    else:
        x = x / own[1]
        s = ("ccw" if x > 0 else "cw" if x < 0 else "") if v.signed and v.unit in _TURNING else ""
        text = f"{_g(abs(x) if s else x)} {own[0]}" + (f" {s}" if s else "")
    return f"{text} {along}" if along else text


def asked_dict(v: Verdict) -> dict:
    """A question's answer for ``solve --json``'s ``answers_asked``: its key, the value in
    SI and its unit, the text as a book gives it (in the unit asked for), the question as
    written and its line."""
    return {
        "key": v.key,
        "value": v.correct,
        "unit": v.unit,
        "text": asked_text(v),
        "asked_as": v.raw,
        "line": v.line,
        **(v.extra or {}),
    }


def asked_line(verdicts) -> str | None:
    """``Answers asked: v_C = 0.3828 m/s; omega_CD = 4.785 rad/s cw``: the questions asked
    without their answers (``"?"``) and the tool's answers, in the book's form; None where
    none is asked."""
    asked = [v for v in verdicts if v.asked]
    if not asked:
        return None
    return "Answers asked: " + "; ".join(f"{v.key} = {asked_text(v)}" for v in asked)


#: the SI units of quantities with a sense (cw, ccw)
_TURNING = ("rad/s", "rad/s^2", "N m")


def correct_text(v: Verdict) -> str:
    """How the check table (terminal and page) writes the correct value."""
    return v.correct_text or _show(v, v.correct)


def _show(v: Verdict, x: float) -> str:
    """The correct value in SI, and in the answer's own unit where it was another (a
    problem set in inches or rpm is answered in its units)."""
    own = _given_unit(v)
    if v.unit in _TURNING and v.signed:
        s = "ccw" if x > 0 else ("cw" if x < 0 else "")
        text = f"{_g(abs(x))} {v.unit}" + (f" {s}" if s else "")
        return text + (f" ({_g(abs(x) / own[1])} {own[0]})" if own else "")
    return f"{_g(x)} {v.unit}".rstrip() + (f" ({_g(x / own[1])} {own[0]})" if own else "")


def percent_text(error, space: str = " ") -> str:
    """An answer's relative error in per cent as the tables write it: two decimals, in
    powers of ten past a million per cent, and past the largest float (an answer such as
    ``1e308 m/s``) what it is more than; "-" where there is none.

    >>> percent_text(0.0123), percent_text(2.5e300), percent_text(float("inf")), percent_text(None)
    ('1.23 %', '2.5e+302 %', 'more than 1e+308 %', '-')
    """
    if error is None:
        return "-"
    p = 100 * error
    if not math.isfinite(p):
        return f"more than 1e+308{space}%"
    return f"{p:.2f}{space}%" if p < 1e6 else f"{p:.3g}{space}%"


def verdicts_text(verdicts, title: str = "") -> str:
    """The verdicts as a terminal table, with the mistake named under a wrong answer."""
    rows = [("answer", "given", "correct", "error", "tolerance", "verdict")]
    for v in verdicts:
        err = percent_text(v.error)
        tol = "-" if not math.isfinite(v.tolerance) else f"{100 * v.tolerance:.2g} %"
        word = "asked" if v.asked else "right" if v.ok else "WRONG"
        rows.append((v.key, v.raw, correct_text(v), err, tol, word))
    widths = [max(len(r[i]) for r in rows) for i in range(6)]
    lines = [title] if title else []
    for i, r in enumerate(rows):
        lines.append("  ".join(c.ljust(w) for c, w in zip(r, widths)).rstrip())
        if i == 0:
            lines.append("  ".join("-" * w for w in widths))
            continue
        v = verdicts[i - 1]
        if v.asked:
            lines.append(f"    asked, no answer given: the tool's value is {asked_text(v)}")
        if v.also:
            lines.append(
                textwrap.fill(also_words(v), 92, initial_indent="    ", subsequent_indent="      ")
            )
        if not v.ok:
            lines.append(
                textwrap.fill(
                    f"mistake: {v.diagnosis}", 92, initial_indent="    ", subsequent_indent="      "
                )
                if v.diagnosis
                else "    mistake: none of the known ones explains it"
            )
    for v in verdicts:
        if v.warning:
            lines.append(f"warning: {v.key} = {v.raw}: {v.warning}")
    graded = [v for v in verdicts if not v.asked]
    lines.append("")
    if graded:
        lines.append("tolerance: " + "; ".join(_rules(v.rule for v in graded)))
    lines.append(count_text(verdicts))
    return "\n".join(lines)


def count_text(verdicts) -> str:
    """``2 of 3 right, 1 wrong; 2 asked, no answer given (not graded)``."""
    graded = [v for v in verdicts if not v.asked]
    wrong = sum(not v.ok for v in graded)
    asked = len(verdicts) - len(graded)
    text = f"{len(graded) - wrong} of {len(graded)} right" + (f", {wrong} wrong" if wrong else "")
    return text + (f"; {asked} asked, no answer given (not graded)" if asked else "")


def _rules(rules) -> list:
    """The rules used, each once: one rule built several ways is written once with its
    constructions after it ("...; built as: a; b" and "...; built as: c" -> one rule)."""
    built = "; built as: "
    heads: dict = {}
    for r in rules:
        head, _, how = r.partition(built)
        heads.setdefault(head, set())
        if how:
            heads[head].add(how)
    return [
        h + (f" (built as: {'; '.join(sorted(hows))})" if hows else "")
        for h, hows in sorted(heads.items())
    ]


def verdicts_dict(verdicts, scene: str | None = None, answers: str | None = None) -> dict:
    """The verdicts for ``check --json`` (SI values)."""
    wrong = sum(not v.ok for v in verdicts)
    asked = sum(v.asked for v in verdicts)
    return {
        "scene": scene,
        "answers_file": answers,
        "all_right": wrong == 0,
        "right": len(verdicts) - wrong - asked,
        "wrong": wrong,
        "asked": asked,
        "answers": [v.to_dict() for v in verdicts],
    }


def cs_slips(correct: float) -> list:
    """(value, code, words) of a flywheel's classic slips with the coefficient of
    fluctuation of speed, for a flywheel's ``correct`` I or mass (an engine's, or a
    diagram's on its own): Cs taken as the half range (I doubled) or as twice the range.

    >>> [(v, code) for v, code, _ in cs_slips(4.0)]
    [(8.0, 'cs_half_range'), (2.0, 'cs_doubled')]
    """
    return [
        (
            2 * correct,
            "cs_half_range",
            "the coefficient of fluctuation of speed taken as the range either side "
            "of the mean: Cs = (w_max - w_min) / w_mean is the whole range (+-1 % is "
            "Cs = 0.02)",
        ),
        (
            correct / 2,
            "cs_doubled",
            "the coefficient of fluctuation of speed taken as twice the whole range",
        ),
    ]
