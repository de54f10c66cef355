"""A whole class at once: one row per student's answer file, a gradebook (CSV or
Markdown) and, first for the teacher, which questions were most often wrong and which
mistakes explain them.

>>> rows = [Row("ann", "ann.toml", (_v("v_C", True),)),
...         Row("bob", "bob.toml", (_v("v_C", False, "rpm_as_rad_s"),)),
...         Row("cy", "cy.toml", (), error="line 3: unknown answer key")]
>>> print(summary_text(rows).splitlines()[0])
2 of 3 answer files read (1 could not be: see its row); 1 of 2 answers right
"""

from __future__ import annotations

import csv
import io
from collections import Counter
from dataclasses import dataclass

__all__ = [
    "Row",
    "class_text",
    "summary_text",
    "gradebook_csv",
    "gradebook_markdown",
    "class_dict",
    "MISTAKE_WORDS",
]

#: the mistakes in a teacher's words (the codes ``check`` names)
MISTAKE_WORDS = {
    "rpm_as_rad_s": "rpm used as rad/s",
    "rad_s_as_rpm": "rad/s used as rpm",
    "rps_as_rad_s": "rev/s used as rad/s",
    "rad_s_as_rps": "rad/s used as rev/s",
    "rps_rpm": "rev/s and rpm confused",
    "diameter_as_radius": "a diameter used as a radius",
    "radius_as_diameter": "a radius used as a diameter",
    "relative_for_absolute": "a relative value given for an absolute one",
    "absolute_for_relative": "an absolute value given for a relative one",
    "other_branch": "the other assembly of the linkage",
    "sum_for_difference": "a sum of angular velocities where the difference applies",
    "difference_for_sum": "a difference of angular velocities where the sum applies",
    "wrong_omega_in_power_balance": "the wrong omega in the power balance",
    "coincident_for_block": "the guide's point under a block given for the block",
    "block_for_coincident": "the block given for the guide's point under it",
    "another_quantity": "another quantity of the problem given",
    "negative_magnitude": "a negative magnitude",
    "component_only": "one acceleration component only",
    "total_for_tangential": "the total acceleration for its tangential component",
    "not_divided_by_length": "omega or alpha not divided by the length",
    "absolute_over_length": "an absolute velocity over a link's length",
    "links_not_at_pin": "omegas of links that do not meet at the pin",
    "one_link_only": "one link's omega only at a pin",
    "one_pair": "one pair of bodies only at a pin",
    "force_times_speed": "F x v without the angle between them",
    # the flywheel chapter's (a turning-moment diagram, a press, an engine's cycle)
    "largest_area": "the largest single area taken for dE_max",
    "whole_energy": "a press's whole energy of a hole taken for dE_max",
    "rpm_not_rad_per_s": "the mean speed in rpm where rad/s belongs",
    "cs_half_range": "Cs taken as the range either side of the mean",
    "cs_doubled": "Cs taken as twice the whole range",
    "one_turn_cycle": "a four-stroke cycle's work divided by one turn",
    "coriolis_factor": "the Coriolis component without its factor 2",
    "coriolis_omitted": "the Coriolis component of a moving slot left out",
    "offset_left_out": "an offset slot drawn through the lever's line",
    "offset_other_side": "an offset slot taken on the other side of the lever",
    "angle_in_radians": "the crank angle taken in radians",
    "other_dead_centre": "the crank angle measured from the other dead centre",
    "against_rotation": "the crank angle measured against the rotation",
    "above_below": "above and below the horizontal confused",
    "from_horizontal": "the angle measured from the horizontal, not the vertical",
    "deg_rad": "degrees and radians confused",
    "mm_m": "millimetres and metres confused",
    "length_unit": "the problem's length unit taken for metres",
    "decimal_point": "the decimal point misplaced",
    "transcription_slip": "a slip of the pen",
    "carried_error": "an error carried from earlier answers",
    "another_centre": "the centre of other links",
    "centre_at_infinity": "a finite point for a centre at infinity",
    "centre_not_at_infinity": "a finite centre said to be at infinity",
    "centre_direction": "a centre at infinity in the wrong direction",
    "centre_direction_square": "a centre at infinity along the path, not square to it",
    # a quick return's times, a stroke, a link's angle (check/cycle.py)
    "inverse_ratio": "the return stroke's time over the cutting stroke's",
    "wrong_unit": "a stroke in the wrong unit",
    "other_end": "a link's direction from its other end",
    "from_minus_x": "a direction measured from -x",
    "supplement": "the supplement of the angle at a joint",
    # the connecting rod's equivalent dynamical system (check/rod_keys.py)
    "k_about_end": "k_G taken about an end of the rod",
    "masses_swapped": "the two masses of the dynamical system swapped",
    "from_small_end": "L's distance taken from the small end, not G",
    "couple_not_reduced": "the correction couple given for its torque on the shaft",
}


@dataclass(frozen=True)
class Row:
    """One student's answer file: its verdicts, or the error that kept it from being read."""

    student: str
    file: str
    verdicts: tuple
    error: str | None = None
    variant: str | None = None  # the student's own variant, where variants are graded
    #: the tolerance the file was checked with: "default" (a careful hand drawing), or as
    #: stated ("5 %", "0.01 m/s"); None where not said
    tolerance: str | None = None

    @property
    def graded(self) -> tuple:
        """The file's answers given (a question left as ``"?"`` is not answered: counted
        as a key left out is)."""
        return tuple(v for v in self.verdicts if not v.asked)

    @property
    def right(self) -> int:
        """How many of the file's answers are right."""
        return sum(v.ok for v in self.graded)


def _v(key, ok, mistake=None):  # a verdict for the doctest
    from .verdicts import Verdict

    return Verdict(key, "", 0.0, 0.0, "m/s", 0.0, 0.0, 0.0, "", ok, False, mistake)


def _words(code):
    return MISTAKE_WORDS.get(code, (code or "").replace("_", " "))


def _keys(rows):
    keys = []
    for r in rows:
        for v in r.graded:
            if v.quantity not in keys:
                keys.append(v.quantity)
    return keys


def _with_variants(rows) -> bool:
    return any(r.variant is not None for r in rows)


def class_text(rows) -> str:
    """A row per student: right of total, and the wrong answers with their mistakes (and
    each student's variant, where variants are graded)."""
    out = []
    w = max([len(r.student) for r in rows] + [7])
    vw = max([len(r.variant or "-") for r in rows] + [7]) if _with_variants(rows) else 0

    def var(r):
        return f"{r.variant or '-':<{vw}}  " if vw else ""

    out.append(
        f"{'student':<{w}}  "
        + (f"{'variant':<{vw}}  " if vw else "")
        + f"{'right':>9}  wrong answers (mistake)"
    )
    for r in rows:
        if r.error:
            out.append(f"{r.student:<{w}}  {var(r)}{'-':>9}  could not be read: {r.error}")
            continue
        wrong = [
            f"{v.key} ({_words(v.mistake) if v.mistake else 'unexplained'})"
            for v in r.verdicts
            if not v.ok
        ]
        out.append(
            f"{r.student:<{w}}  {var(r)}{f'{r.right} of {len(r.graded)}':>9}  "
            + ("; ".join(wrong) if wrong else "-")
        )
    return "\n".join(out)


def tolerance_text(rows, book=None) -> str | None:
    """Which tolerance the files were checked with, and why: ``tolerance: the default
    (...) for 38 files; 3 % (the file's own or the command line's) for ann, bob``."""
    by = {}
    for r in rows:
        if r.error is None and r.tolerance is not None:
            by.setdefault(r.tolerance, []).append(r.student)
    if not by:
        return None
    parts = []
    for tol, who in sorted(by.items(), key=lambda kv: (kv[0] != "default", kv[0])):
        what = (
            "the default, what a careful hand drawing at the step table's scales allows"
            if tol == "default"
            else tol
        )
        whom = (
            f"{len(who)} file{'s' if len(who) != 1 else ''}"
            if len(by) == 1 or len(who) > 5
            else ", ".join(who)
        )
        parts.append(f"{what} for {whom}")
    text = "tolerance: " + "; ".join(parts)
    if book is not None and "default" in by:
        text += (
            f" (not the scene's {100 * book:g} %: that is the book's, for the scene's own "
            "answers; give --tolerance to set one)"
        )
    return text


def summary_text(rows, book=None) -> str:
    """The class summary: how many files were read, the questions most often wrong, the
    mistakes that explain them (most students first), and the tolerance used (``book``:
    the scene's own tolerance, which is not a student's)."""
    read = [r for r in rows if r.error is None]
    total = sum(len(r.graded) for r in read)
    right = sum(r.right for r in read)
    out = [
        f"{len(read)} of {len(rows)} answer files read"
        + (f" ({len(rows) - len(read)} could not be: see its row)" if len(read) < len(rows) else "")
        + f"; {right} of {total} answers right"
    ]
    tol = tolerance_text(rows, book)
    if tol:
        out.append(tol)
    wrong_by_key = Counter(v.quantity for r in read for v in r.graded if not v.ok)
    asked = Counter(v.quantity for r in read for v in r.graded)
    if wrong_by_key:
        out.append("most often wrong:")
        for key, n in sorted(wrong_by_key.items(), key=lambda kv: (-kv[1], kv[0])):
            out.append(f"  {key}: {n} of {asked[key]} students")
    students_by_mistake = Counter()
    for r in read:
        for code in {v.mistake for v in r.verdicts if not v.ok and v.mistake}:
            students_by_mistake[code] += 1
    if students_by_mistake:
        out.append("mistakes behind them:")
        for code, n in sorted(students_by_mistake.items(), key=lambda kv: (-kv[1], kv[0])):
            out.append(f"  {_words(code)}: {n} student{'s' if n != 1 else ''}")
    return "\n".join(out)


def _table(rows):
    keys = _keys(rows)
    variants = _with_variants(rows)
    tols = any(r.tolerance is not None for r in rows)
    head = (
        ["student", "file"]
        + (["variant"] if variants else [])
        + keys
        + ["right", "of", "error"]
        + (["tolerance"] if tols else [])
    )
    body = []
    for r in rows:
        by_key = {v.quantity: v for v in r.graded}  # a "?": no answer, as a key left out
        cells = [r.student, r.file] + ([r.variant or ""] if variants else [])
        for k in keys:
            v = by_key.get(k)
            cells.append(
                ""
                if v is None
                else ("right" if v.ok else f"WRONG ({_words(v.mistake)})" if v.mistake else "WRONG")
            )
        cells += [
            str(r.right) if r.error is None else "",
            str(len(r.graded)) if r.error is None else "",
            r.error or "",
        ]
        if tols:
            cells.append(r.tolerance or "")
        body.append(cells)
    return head, body


def _inert(cell) -> str:
    """A cell a spreadsheet shows as text: one that would start a formula (a student's
    file named ``=HYPERLINK(...).toml``) gets a leading apostrophe."""
    cell = str(cell)
    return "'" + cell if cell[:1] in ("=", "+", "-", "@", "\t", "\r") else cell


def gradebook_csv(rows) -> str:
    """The gradebook as CSV: one row per file, a column per answer key (cells that would start a
    spreadsheet formula made inert)."""
    head, body = _table(rows)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(head)
    w.writerows([[_inert(c) for c in cells] for cells in body])
    return buf.getvalue()


def gradebook_markdown(rows, book=None) -> str:
    """The gradebook as a Markdown table: one row per file, a column per answer key."""
    head, body = _table(rows)

    def cell(x):
        return str(x).replace("|", "\\|")

    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    out += ["| " + " | ".join(cell(c) for c in cells) + " |" for cells in body]
    return "\n".join(out) + "\n\n" + summary_text(rows, book) + "\n"


def class_dict(rows, book=None) -> dict:
    """The class for ``check --json``."""
    return {
        "students": [
            {
                "student": r.student,
                "file": r.file,
                "error": r.error,
                **({"variant": r.variant} if _with_variants(rows) else {}),
                **({"tolerance": r.tolerance} if r.tolerance is not None else {}),
                "right": r.right,
                "answers": [v.to_dict() for v in r.verdicts],
            }
            for r in rows
        ],
        "summary": summary_text(rows, book).splitlines(),
    }
