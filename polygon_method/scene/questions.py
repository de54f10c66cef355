"""A question asked without its answer in ``[answers]`` (``v_C = "?"``, ``omega_BC = "? rpm"``;
a part of the answers' reader, :mod:`.answers`): its key checked as an answer's is, its
unit one of the key's kind, no sense (the answer gives it)."""

from __future__ import annotations

from dataclasses import replace

from ..common.errors import SceneError
from ..common.units import question_unit

__all__ = ["unit_kind"]


def unit_kind(kind: str) -> str:
    """The kind of quantity (a key of ``UNITS``) an answer of ``kind`` is (its
    :class:`Answer`'s ``kind``).

    >>> unit_kind("omega"), unit_kind("centre"), unit_kind("vu"), unit_kind("I_flywheel")
    ('angular_velocity', 'length', 'velocity', 'moment_of_inertia')
    """
    from .answer_keys import _KINDS, DRIVER_ANSWERS, ENGINE_ANSWERS
    from .cycle_answers import CYCLE_ANSWERS

    if kind in ("centre", "h"):
        return "length"
    if kind == "torque":
        return "torque"
    if kind in ENGINE_ANSWERS:
        return ENGINE_ANSWERS[kind]
    if kind in DRIVER_ANSWERS:
        return DRIVER_ANSWERS[kind]
    if kind in CYCLE_ANSWERS:  # time_ratio, stroke, theta, angle
        return CYCLE_ANSWERS[kind]
    if kind in ("vu", "au"):  # the guide's point under a block
        return "velocity" if kind == "vu" else "acceleration"
    return _KINDS[kind][0]


class _Questions:
    """The loader's method for a question of ``[answers]`` (mixed into
    :class:`.answers._Answers`)."""

    def question(self, key, unit, known, slider_names, pin_names, loads):
        """``v_C = "?"`` (or ``"? m/s"``: the unit its answer is to be given in): the key
        checked exactly as an answer's is (a stand-in value read in its place), the unit
        one of the key's kind (no sense: the answer gives it). An :class:`Answer` whose
        value is None (``asked``)."""
        from .answer_keys import ENGINE_ANSWERS

        centre = key.startswith("I_") and key not in ENGINE_ANSWERS  # (not I_flywheel)
        stand_in = [0, 0] if centre else 1
        ans = self._answer(key, stand_in, known, slider_names, pin_names, loads)
        if unit and ans.kind == "time_ratio":
            raise self.error(f'{key} is a bare number: ask "?"', "answers", key)
        if unit:
            try:
                question_unit(unit, unit_kind(ans.kind), "")
            except SceneError as exc:
                raise self.error(exc.message, "answers", key) from None
        return replace(ans, value=None, sense=None, raw=f"? {unit}".rstrip(), unit=unit or None)
