"""The ``[answers]`` table (and a student's answer file, read the same way): each key
named as a book names the quantity (``v_C``, ``omega_BC``, ``a_C``, ``R_B``, ``torque``,
``I13``, the engine's and the forces' keys), its value and unit checked, its sense read;
an unknown key gets a "did you mean" hint. A decimal comma is read as a point."""

from __future__ import annotations

import math
import re

from ..common.errors import PolygonMethodError, SceneError, printable
from ..common.units import ABSOLUTE_TOLERANCES, UNITS, decimal_comma, parse_quantity, question
from .answer_keys import (
    _KINDS,
    DRIVER_ANSWERS,
    ENGINE_ANSWERS,
    ENGINE_PER_PISTON,
    PAIR_ANSWER_KINDS,
    under_block_names,
)
from .answer_names import _AnswerNames
from .records import UNDER_BLOCK_KINDS, Answer, split_name
from .cycle_answers import CYCLE_ANSWERS, _CycleAnswers, bare as _bare
from .questions import _Questions, unit_kind

__all__ = [
    "decimal_comma",
    "DRIVER_ANSWERS",
    "ENGINE_ANSWERS",
    "ENGINE_PER_PISTON",
    "under_block_names",
    "CYCLE_ANSWERS",
    "unit_kind",
    "PAIR_ANSWER_KINDS",
    "FILE_KEYS",
]

#: a file's own keys (an answer file's, a scene's) -> what each is, an example: written
#: inside [answers] they are said to belong above it
FILE_KEYS = {
    "student": ("the student's name", 'student = "A. Student"'),
    "name": ("the student's name", 'name = "A. Student"'),
    "variant": ("the student's variant", 'variant = "07"'),
    "title": ("the title", 'title = "..."'),
    "source": ("the source", 'source = "..."'),
    "notes": ("a note", 'notes = "..."'),
}

#: a centre answered as at infinity, optionally with the direction of its lines
_INFINITY = re.compile(r"^\s*(?:at\s+)?infinity\s*(?:[,;]\s*(?:along\s+)?(.*?))?\s*$", re.I)


class _Answers(_AnswerNames, _Questions, _CycleAnswers):
    """The loader's ``[answers]`` methods (mixed into the loader with the other tables)."""

    def _engine_value(self, value, kind, key) -> float:
        """An engine answer's value (SI) of ``kind``, in its kind's first unit when bare: an
        effort, a turning moment, the cycle's energy or the flywheel's (one cylinder's, or
        one piston's of several); a bare length (``l_GL``) in the scene's unit."""
        return self.qty(
            value,
            kind,
            "answers",
            key,
            default_unit=self.unit if kind == "length" else next(iter(UNITS[kind])),
            allow_sense=False,
            refuse_absurd=False,
        ).value

    def driver_answer(self, key, value, raw_text, line, loads, forces):
        """``force`` (a driving block's, collar's or cylinder's force along its guide, N:
        a size, or signed along the guide, + outward for a collar), ``torque2`` and
        ``force2`` (a second input's effort: a second crank's torque, a second collar's
        force; the force analysis gives them)."""
        if key == "force" and not (loads or forces):
            raise self.error(
                "a driver's force answer needs [loads] to balance, or [masses]", "answers", key
            )
        if key != "force" and not forces:
            raise self.error(
                f"{key}: a second input's effort needs the force analysis (the power "
                "balance gives only the two efforts' weighted sum): give [masses] (empty "
                "for the loads alone) or [gravity]",
                "answers",
                key,
            )
        q = self.qty(
            value,
            DRIVER_ANSWERS[key],
            "answers",
            key,
            default_unit=next(iter(UNITS[DRIVER_ANSWERS[key]])),
            allow_sense=key == "torque2",
            refuse_absurd=False,
        )
        sense = q.sense or ("+" if str(value).lstrip().startswith("+") else None)
        return Answer(key, key, (), q.value, sense, raw_text, line)  # (+: signed, as -)

    def answers(self, known, sliders, pins, loads):
        spec = self.table("answers")
        tolerance = None
        out = []
        slider_names = {s.key: s for s in sliders}
        pin_names = {p.point for p in pins}
        for key, value in spec.items():
            if key == "tolerance":
                if question(value) is not None:
                    raise self.error(
                        'tolerance is the answers\' allowance, a per cent ("3%"): not a question',
                        "answers",
                        key,
                    )
                q = self._tolerance(value, key)
                if not 0 < q < 1:
                    raise self.error(
                        f"tolerance {value!r} must be between 0 and 100 %", "answers", key
                    )
                tolerance = q
                continue
            if isinstance(value, dict):  # [answers.extra], extra.v_C = ..., extra = {...}
                raise self._sub_table(key, value)
            if key in FILE_KEYS:
                raise self._misplaced(key)
            out.append(self.answer(key, value, known, slider_names, pin_names, loads))
        return tolerance, out

    def _tolerance(self, value, key) -> float:
        """The file's ``tolerance``, a per cent; a value with a unit of an answer (1 mm, 1
        deg, 0.01 m/s) refused saying where an absolute tolerance is given."""
        try:
            return self.qty(value, "percent", "answers", key, default_unit="%").value
        except SceneError:
            for kind, _ in ABSOLUTE_TOLERANCES:  # (what check --tolerance takes)
                try:
                    parse_quantity(str(value), kind)
                except PolygonMethodError:
                    continue
                shown = printable(" ".join(str(value).split()))
                raise self.error(
                    f"tolerance '{shown}': a file's tolerance is a per cent (\"3%\"); an "
                    f"absolute one is given to check on its command line: --tolerance "
                    f"'{shown}'",
                    "answers",
                    key,
                ) from None
            raise

    def _sub_table(self, key, value):
        """The error for a table inside ``[answers]``, at its header's line (or its first
        key's: a dotted ``extra.v_C``, an inline ``extra = {...}``)."""
        table = f"answers.{key}"
        line = self.line_of(table) or self.line_of("answers", key)
        for k in value:
            line = line or self.line_of(table, k)
        return SceneError(
            printable(
                "[answers] takes no table inside it: write each answer as a key = value "
                f"line under [answers] itself (e.g. {next(iter(value), 'v_C')} = ...)"
            ),
            file=self.file,
            key=printable(f"[{table}]"),
            line=line,
        )

    def _misplaced(self, key):
        """The error for an answer file's own key (``student``, ``variant``) or a file's
        (``title``) written inside ``[answers]``: where it belongs."""
        what, example = FILE_KEYS[key]
        if getattr(self, "answer_file", False):
            where = f"write it at the top of the file, above the [answers] heading ({example})"
        elif key in ("student", "name", "variant"):
            where = (
                f"it belongs at the top of the student's answer file, above its [answers] "
                f"heading ({example}); a scene's [answers] are the book's"
            )
        else:
            where = f"write it at the top of the scene, above its first [table] heading ({example})"
        return self.error(f"{key} is {what}, not an answer: {where}", "answers", key)

    def centre_answer(self, key, rest, value, line):
        """``I_13 = [x, y]``: the instantaneous centre of links 1 and 3 (textbook numbers:
        ground 1, crank 2), in the scene's units; ``I_1_12`` past link 9."""
        parts = rest.split("_") if "_" in rest else list(rest)
        named = len(parts) == 2 and not any(p.isdigit() for p in parts)
        if named:  # the scene's names: I_ground_BC, I_AB_CD
            for part in parts:
                if part.lower() != "ground":
                    self.find_link(part, "answers", key)
        elif (
            len(parts) != 2
            or not all(p.isdigit() and int(p) > 0 for p in parts)
            or int(parts[0]) == int(parts[1])
        ):
            raise self.error(
                "an instantaneous centre is I_ij with two different link "
                "numbers (ground 1, crank 2), e.g. I_13, or I_1_12 past 9, or "
                "two link names, e.g. I_ground_BC",
                "answers",
                key,
            )
        pair = tuple(parts) if named else tuple(sorted(int(p) for p in parts))
        if isinstance(value, str):  # "at infinity", or with the direction of its lines
            return Answer(
                key, "centre", pair, self.centre_at_infinity(key, value), None, value, line
            )
        if not (
            isinstance(value, list)
            and len(value) == 2
            and all(
                isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
                for v in value
            )
        ):
            raise self.error(
                f"a centre's answer is its position [x, y] in {self.unit}, or \"at "
                f'infinity" ("at infinity, 90 deg": the direction of its lines), got {value!r}',
                "answers",
                key,
            )
        for v in value:  # [1e300, 0]: a units slip, never an error of 1e299 per cent
            self.length(v, "answers", key, positive=False)
        u = self.scale()
        return Answer(
            key,
            "centre",
            pair,
            (value[0] * u, value[1] * u),
            None,
            f"[{value[0]:g}, {value[1]:g}] {self.unit}",
            line,
        )

    def centre_at_infinity(self, key, value) -> tuple:
        """``("infinity", direction)`` of a centre answered as at infinity: ``"at infinity"``
        (the direction not stated: None) or ``"at infinity, 90 deg"``, ``"..., vertical"``
        (the direction of the parallel lines it is the meeting point of, rad, mod pi)."""
        m = _INFINITY.match(value)
        if m is None:
            raise self.error(
                f'{value!r}: a centre is [x, y] in {self.unit}, or "at infinity" (with the '
                'direction of its lines: "at infinity, 90 deg", "at infinity, vertical")',
                "answers",
                key,
            )
        d = (m.group(1) or "").strip().lower()
        if not d:
            return ("infinity", None)
        if d in ("horizontal", "vertical"):
            return ("infinity", 0.0 if d == "horizontal" else math.pi / 2)
        q = self.qty(d, "angle", "answers", key, default_unit="deg")
        return ("infinity", q.value % math.pi)

    def answer(self, key, value, known, slider_names, pin_names, loads):
        """One key of [answers] (or of a student's file) and its value: an :class:`Answer`,
        the key checked against the scene (what it names is there, the force analysis
        asked for where it is a force) and the value read in the key's kind; or a question
        asked without its answer (``"?"``, ``"? rpm"``: :meth:`question`)."""
        unit = question(value)
        if unit is not None:
            return self.question(key, unit, known, slider_names, pin_names, loads)
        return self._answer(key, value, known, slider_names, pin_names, loads)

    def _answer(self, key, value, known, slider_names, pin_names, loads):
        """:meth:`answer` of a value (not a question)."""
        line = self.line_of("answers", key)
        forces = getattr(self, "scene_forces", None)  # an answer file: its scene's
        if forces is None:
            forces = "masses" in self.raw or "gravity" in self.raw or "indicator" in self.raw
            forces = forces or any(r.grip for r in getattr(self, "rolling_pairs", ()) or ())
        hint = lambda: self.key_hint(key, known, slider_names, pin_names, loads)  # noqa: E731
        read = decimal_comma(value)
        if read is None:
            raise self.error(
                f"'{printable(str(value))}': the comma reads two ways (a decimal "
                "comma, or thousands?): write the number with a decimal point, "
                'e.g. "1.25 m/s" or "1250 mm/s"',
                "answers",
                key,
            )
        raw_text, value = printable(str(value)), read
        if key == "torque":
            return self._torque_answer(key, value, raw_text, line, loads, forces)
        if key in DRIVER_ANSWERS:
            return self.driver_answer(key, value, raw_text, line, loads, forces)
        engine = self._engine_answer(key, value, raw_text, line, slider_names)
        if engine is not None:
            return engine
        cycle = self._cycle_answer(key, value, raw_text, line, known, slider_names, hint)
        if cycle is not None:
            return cycle
        prefix, _, rest = key.partition("_")
        if prefix == "I" and rest:
            return self.centre_answer(key, rest, value, line)
        if prefix not in _KINDS or not rest:
            raise self._unknown_key(key, hint)
        kind, what, sense_ok = _KINDS[prefix]
        if what in ("pin_force", "guide", "body", "contact", "drive", "held") and not forces:
            raise self.error(
                f"{key}: a force answer needs the force analysis: give [masses] or [gravity]",
                "answers",
                key,
            )
        if prefix in UNDER_BLOCK_KINDS and rest not in known:
            under = self.under_names(known, slider_names).get(rest)
            if under is not None:  # v_A1: the guide's point under the block at A
                q = self.qty(value, kind, "answers", key, default_unit=next(iter(UNITS[kind])))
                return Answer(
                    key, UNDER_BLOCK_KINDS[prefix], (under,), q.value, None, raw_text, line
                )
        names = (rest,) if what == "slider" and rest in slider_names else split_name(rest)
        if not names:
            raise self.error(f"'{rest}' is not a point or link name{hint()}", "answers", key)
        if what in ("pin_force", "guide", "body", "contact", "drive", "held"):
            names = self._force_names(key, prefix, rest, names, what, known, slider_names)
        else:
            names = self._motion_names(
                key, prefix, rest, names, what, known, slider_names, pin_names, hint
            )
        if prefix == "h":  # (a body's: the offset of its single inertia force)
            q = self.qty(
                value, "length", "answers", key, default_unit=self.unit, refuse_absurd=False
            )
            if _bare(value):  # a bare length is in the scene's unit: say so
                raw_text = f"{raw_text} {self.unit}"
            return Answer(key, prefix, names, q.value, None, raw_text, line)
        q = self.qty(
            value,
            kind,
            "answers",
            key,
            default_unit=next(iter(UNITS[kind])),
            allow_sense=sense_ok,
            refuse_absurd=False,
        )  # warned of when checked
        return Answer(key, prefix, names, q.value, q.sense, raw_text, line)

    def _engine_answer(self, key, value, raw_text, line, slider_names):
        """An engine chapter's answer (efforts, the cycle, the flywheel; ``piston_effort_B``
        one cylinder's of several), or None for a key of another kind."""
        kind = ENGINE_ANSWERS.get(key.rpartition("_")[0], ENGINE_ANSWERS.get(key))
        if kind == "length" and _bare(value):  # l_GL: a bare length is in the scene's unit
            raw_text = f"{raw_text} {self.unit}"
        if key in ENGINE_ANSWERS:  # the engine chapter's: efforts, the cycle, the flywheel
            value = self._engine_value(value, ENGINE_ANSWERS[key], key)
            return Answer(key, key, (), value, None, raw_text, line)
        base, _, piston = key.rpartition("_")
        if base in ENGINE_PER_PISTON and piston:  # piston_effort_B: one cylinder's of several
            if piston not in slider_names:
                raise self.error(
                    f"{key}: {piston} is no slider of the scene (name a cylinder's piston)",
                    "answers",
                    key,
                )
            value = self._engine_value(value, ENGINE_ANSWERS[base], key)
            return Answer(key, base, (piston,), value, None, raw_text, line)
        return None

    def _torque_answer(self, key, value, raw_text, line, loads, forces):
        """``torque``: the crank's driving torque, where a power balance (or the force
        analysis) gives it (not a driving block's: its effort is a force)."""
        if not loads and not forces:
            raise self.error(
                "a torque answer needs [loads] to balance, or [masses]", "answers", key
            )
        if getattr(self, "two_inputs", False) and not forces:
            raise self.error(
                "with two inputs one power balance does not give the two "
                "driving torques: no torque answer (the force analysis gives each: "
                "give [masses], empty for the loads alone; torque2 the second's)",
                "answers",
                key,
            )
        if getattr(self, "driving_block", None) and not (
            forces and getattr(self, "driving_wheel", None)
        ):
            raise self.error(
                f"the block {self.driving_block} drives the mechanism: its "
                "driving effort is a force along its guide, not a torque "
                "(solve prints it; its answer key is force)",
                "answers",
                key,
            )
        q = self.qty(
            value,
            "torque",
            "answers",
            key,
            default_unit="N m",
            allow_sense=True,
            refuse_absurd=False,
        )
        return Answer(key, "torque", (), q.value, q.sense, raw_text, line)
