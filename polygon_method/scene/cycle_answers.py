"""The answers of the crank's cycle and of the configuration in ``[answers]`` (a part of the
answers' reader, :mod:`.answers`): a quick return's ratio of the time of the cutting stroke
to the return stroke (``time_ratio``, a bare number), a slider's length of stroke
(``stroke_X``, a length: bare in the scene's unit), a link's direction from +x
(``theta_XY``, from X to Y, ccw) and the angle at a joint (``angle_XYZ``, at Y between YX
and YZ): angles, bare in degrees. Their values: linkage/cycle_values.py; graded in
check/cycle.py."""

from __future__ import annotations

import math

from ..common.errors import printable
from .names import split_name
from .part_records import Answer

__all__ = ["CYCLE_ANSWERS", "bare", "ratio"]

#: the answers of the crank's cycle and of the configuration -> their unit kind: a quick
#: return's ratio of the cutting stroke's time to the return's (``time_ratio``), a slider's
#: length of stroke (``stroke_X``), a link's direction from +x (``theta_XY``, X to Y) and the
#: angle at a joint (``angle_XYZ``, at Y between YX and YZ); checked in check/cycle.py
CYCLE_ANSWERS = {"time_ratio": "ratio", "stroke": "length", "theta": "angle", "angle": "angle"}


def bare(value) -> bool:
    """A number without a unit (``20``, ``"20"``).

    >>> bare(20), bare("20.5"), bare("20 mm")
    (True, True, False)
    """
    try:
        float(str(value))
    except ValueError:
        return False
    return True


def ratio(value) -> float | None:
    """A ratio as a book writes it, a bare number or ``a:b``; None where it is no positive
    finite ratio.

    >>> ratio(2), ratio("1.71"), ratio("3 : 2"), ratio("2:0"), ratio("-1"), ratio("2 s")
    (2.0, 1.71, 1.5, None, None, None)
    """
    a, colon, b = str(value).partition(":")
    try:
        v = float(a) / float(b) if colon else float(a)
    except (ValueError, ZeroDivisionError):
        return None
    return v if math.isfinite(v) and v > 0 else None


class _CycleAnswers:
    """The loader's method for these keys (mixed into :class:`.answers._Answers`)."""

    def _cycle_answer(self, key, value, raw_text, line, known, slider_names, hint):
        """``time_ratio`` (a bare number), ``stroke_X`` (a length, bare in the scene's
        unit), ``theta_XY`` and ``angle_XYZ`` (angles, bare in degrees): an
        :class:`Answer`, or None for a key of another kind."""
        prefix, _, rest = key.partition("_")
        if key == "time_ratio":
            v = ratio(value)
            if v is None:
                raise self.error(
                    f"{key} is a ratio, a bare number (e.g. 1.5, or 3:2: the cutting "
                    f"stroke's time over the return's), got {printable(str(value))!r}",
                    "answers",
                    key,
                )
            return Answer(key, key, (), v, None, raw_text, line)
        if prefix not in CYCLE_ANSWERS or not rest:
            return None
        if prefix == "stroke":
            if rest not in slider_names:
                raise self.error(f"no slider {rest} in [sliders]{hint()}", "answers", key)
            names = (rest,)
            q = self.qty(
                value, "length", "answers", key, default_unit=self.unit, refuse_absurd=False
            )
            if bare(value):  # a bare length is in the scene's unit: say so
                raw_text = f"{raw_text} {self.unit}"
            return Answer(key, prefix, names, q.value, None, raw_text, line)
        names = split_name(rest)
        n = 2 if prefix == "theta" else 3
        if len(names) != n or len(set(names)) != n or not set(names) <= set(known):
            example = "theta_CD: the direction from C to D" if n == 2 else "angle_BCD: at C"
            raise self.error(
                f"{prefix}_{'XY' if n == 2 else 'XYZ'} names {n} different points of the "
                f"scene (e.g. {example}){hint()}",
                "answers",
                key,
            )
        q = self.qty(value, "angle", "answers", key, default_unit="deg", refuse_absurd=False)
        if bare(value):
            raw_text = f"{raw_text} deg"
        return Answer(key, prefix, names, q.value, None, raw_text, line)
