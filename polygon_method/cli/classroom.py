"""The commands of the classroom: check (one answer file, or a whole class with its
gradebook, each student against their own variant) and variants (a scene per student)."""

from __future__ import annotations

import json
import math
import os
import re
from pathlib import Path

from ..common.errors import PolygonMethodError, SceneError, printable
from .files import check_outputs, write_outputs


def _finite(x):
    """A number JSON can carry: None for an infinite or undefined one."""
    return x if isinstance(x, (int, float)) and math.isfinite(x) else None


def _json(d) -> str:
    """``d`` as JSON, every infinite or undefined number in it (an error of a per cent
    against a right value of 0) written as null."""

    def clean(x):
        if isinstance(x, float):
            return _finite(x)
        if isinstance(x, dict):
            return {k: clean(v) for k, v in x.items()}
        if isinstance(x, (list, tuple)):
            return [clean(v) for v in x]
        return x

    return json.dumps(clean(d), indent=2, allow_nan=False)


def _command_line_tolerance(values):
    """``--tolerance 5%`` (and ``--tolerance 0.01 m/s``, one per unit) as a
    :class:`~polygon_method.check.Stated`, or None when not given."""
    from ..check import SOURCES, Stated
    from ..scene.answers import decimal_comma
    from ..common.units import ABSOLUTE_TOLERANCES, parse_quantity

    if not values:
        return None
    relative, absolute = None, []
    for raw in values:
        text = decimal_comma(raw.strip())
        shown = printable(raw)
        if text is None or not text:
            raise SceneError(
                f"'{shown}': write a per cent (5%) or a value with "
                "its unit (0.01 m/s), with a decimal point",
                key="--tolerance",
            )
        if text.endswith("%"):
            try:
                q = parse_quantity(text, "percent", default_unit="%").value
            except PolygonMethodError:
                q = math.nan
            if not 0 < q < 1:
                raise SceneError(
                    f"'{shown}': a per cent between 0 and 100 (e.g. 5%)", key="--tolerance"
                )
            if relative is not None:
                raise SceneError(
                    f"'{shown}': a second per cent; give one (and "
                    "values with a unit for one kind of answer each)",
                    key="--tolerance",
                )
            relative = q
            continue
        if re.search(r"\b(cw|ccw|(anti|counter)-?clockwise|clockwise)$", text, re.I):
            raise SceneError(  # (it said "neither ... angular velocity" of '1 rad/s cw')
                f"'{shown}': a tolerance is a positive size, with no sense (cw or ccw)",
                key="--tolerance",
            )
        for kind, si in ABSOLUTE_TOLERANCES:
            try:
                q = parse_quantity(text, kind)
            except PolygonMethodError:
                continue
            if not q.value > 0 or q.sense is not None:
                raise SceneError(f"'{shown}': a tolerance is a positive size", key="--tolerance")
            first = next((t for u, _, t in absolute if u == si), None)
            if first is not None:  # ("1 deg" then "2 deg" said "a second tolerance in rad")
                raise SceneError(
                    f"'{shown}': a second tolerance for the answers in {si} (the first "
                    f"'{first}'); give one for each kind of answer",
                    key="--tolerance",
                )
            absolute.append((si, q.value, " ".join(text.split())))
            break
        else:
            raise SceneError(
                f"'{shown}' is neither a per cent (5%) nor a value with a unit of "
                "velocity, acceleration, angular velocity or acceleration, torque, "
                "length or angle (0.01 m/s, 1 mm, 1 deg)",
                key="--tolerance",
            )
    return Stated(relative, tuple(absolute), source=SOURCES["command line"])


def _row_tolerance(tolerance, source) -> str:
    """A student's tolerance for the class table: "default", "5 % (--tolerance)", "3 %
    (the file's own)"."""
    if tolerance is None:
        return "default"
    return f"{tolerance.text()} ({'--tolerance' if source == 'command line' else 'the file' + chr(39) + 's own'})"


def _answer_files(paths):
    """The answer files named: files as given, a directory's *.toml in order."""
    out = []
    for p in paths:
        path = Path(p)
        if path.is_dir():
            out += sorted(str(q) for q in path.glob("*.toml"))
        else:
            out.append(p)
    return out


def _listed(path: Path):
    """A file found by listing a directory is opened only if it is a regular file (or a
    directory, which the reader names): a pipe or a device would be waited on for ever."""
    if path.exists() and not path.is_file() and not path.is_dir():
        raise SceneError(
            "not a regular file (a pipe or a device): not read", file=printable(str(path))
        )


class _VariantBook:
    """The variant scenes of ``check --variants DIR``, by the id in each one's ``[variant]``
    table (not by its file's name: a copied or renamed file cannot pair a student with the
    wrong variant), each solved once when a student first names it."""

    def __init__(self, folder, base):
        self.folder, self.base = Path(folder), base
        if not self.folder.is_dir():
            raise SceneError(
                f"--variants {folder}: not a directory of variant scenes", key="--variants"
            )
        self.files = sorted(self.folder.glob("*.toml"))
        if not self.files:
            raise SceneError(
                f"--variants {folder}: no variant scenes (*.toml) in it", key="--variants"
            )
        self.done = {}
        self._index = None

    @staticmethod
    def _names(text):
        """The names a variant goes by: "variant-07.toml", "variant-07", "Variant 07", "07",
        "7" are one."""
        text = text.strip().lower()
        if text.endswith(".toml"):
            text = text[:-5]
        bare = re.sub(r"^variant[\s_-]*", "", text)
        return {text, bare} | ({str(int(bare))} if bare.isdecimal() else set())

    def index(self):
        """[(file, its scene or the error that kept it from being read)], read once."""
        from ..scene import load_scene

        if self._index is None:
            self._index, seen = [], set()
            for f in self.files:
                real = os.path.realpath(f)  # a link in a loop is itself (resolve raises)
                if real in seen:  # a link to a variant listed already: one variant
                    continue
                seen.add(real)
                try:
                    _listed(f)
                    self._index.append((f, load_scene(f)))
                except PolygonMethodError as exc:
                    self._index.append((f, exc))
        return self._index

    def find(self, named):
        """(id, solution, tolerances) of the variant a student names; raises a
        :class:`PolygonMethodError` (that student's row) if it is not there, or if two
        files hold it."""
        from ..check import tolerances
        from ..motion.solution import solve

        want = self._names(named)
        hits = [
            (f, sc)
            for f, sc in self.index()
            if not isinstance(sc, Exception)
            and sc.variant is not None
            and self._names(sc.variant.id) & want
        ]
        if not hits:
            named_so = [(f, sc) for f, sc in self.index() if self._names(f.name) & want]
            if named_so:  # a file of that name that is no variant of its own
                f, sc = named_so[0]
                if isinstance(sc, Exception):
                    raise SceneError(
                        f"{f.name} in {self.folder} cannot be read: {sc.one_line()}", key="variant"
                    )
                raise SceneError(
                    f"{f.name} in {self.folder} is not a generated variant "
                    + (
                        "(it has no [variant] table)"
                        if sc.variant is None
                        else f"'{printable(named)}' (it holds variant '{printable(sc.variant.id)}')"
                    ),
                    key="variant",
                )
            shown = ", ".join(f.name for f in self.files[:3]) + (
                ", ..." if len(self.files) > 3 else ""
            )
            raise SceneError(
                f"variant '{printable(named)}' is not in {self.folder} (its variants: {shown})",
                key="variant",
            )
        if len(hits) > 1:
            raise SceneError(
                f"variant '{printable(named)}' is in {len(hits)} files of "
                f"{self.folder} ({', '.join(f.name for f, _ in hits[:3])}): "
                "remove the copies",
                key="variant",
            )
        f, sc = hits[0]
        if f not in self.done:
            try:
                base_title = self.base.title or ""
                if base_title and sc.variant.of != base_title:
                    raise SceneError(
                        f"{f.name} is a variant of {sc.variant.of!r}, not of {base_title!r}",
                        key="variant",
                    )
                sol = solve(sc)
                self.done[f] = (sc.variant.id, sol, tolerances(sol), None)
            except PolygonMethodError as exc:
                self.done[f] = (None, None, None, exc)
        vid, sol, tols, exc = self.done[f]
        if exc is not None:
            raise exc
        return vid, sol, tols


def _graded_against(named, scene, sol, tols, book):
    """The solution a student's answers are graded against: their own variant's (with
    ``--variants``), or the scene's own."""
    if book is not None:
        if named is None:
            raise SceneError(
                'names no variant: add variant = "07" (the number on the student\'s problem sheet)',
                key="variant",
            )
        return book.find(named)
    if named is not None:
        own = scene.variant
        if own is None or not (_VariantBook._names(own.id) & _VariantBook._names(named)):
            raise SceneError(
                f"names variant '{printable(named)}': grade it against its own "
                "variant with --variants DIR (the directory `variants -o` "
                "wrote)",
                key="variant",
            )
        return own.id, sol, tols
    return None, sol, tols


def _cmd_class(args, scene, sol, files) -> int:
    """A whole class: a row per answer file, the summary, the gradebook."""
    from ..check import check_answers, choose_tolerance, tolerances
    from ..check.classroom import Row
    from ..scene import load_answers

    variants = getattr(args, "variants", None)
    vbook = _VariantBook(variants, scene) if variants else None
    book, targets = class_gradebook(args, files, vbook)
    tols = tolerances(sol)
    stated = _command_line_tolerance(getattr(args, "tolerance", None))
    rows = []
    given = set(args.answers or ())  # named on the command line (a pipe given is read)
    for f in files:
        student = printable(Path(f).stem)
        named = None
        try:
            if f not in given:
                _listed(Path(f))
            own, answers, named, name = load_answers(f, scene, with_variant=True, with_student=True)
            if name:
                student = printable(name)
            tolerance, source, _ = choose_tolerance(stated, own, scene.tolerance, False)
            vid, vsol, vtols = _graded_against(named, scene, sol, tols, vbook)
            rows.append(
                Row(
                    student,
                    printable(str(f)),
                    check_answers(vsol, answers, tolerance, _tols=vtols),
                    variant=vid if vbook is None else (vid or ""),
                    tolerance=_row_tolerance(tolerance, source),
                )
            )
        except PolygonMethodError as exc:  # a row with its error, never the whole run
            line = exc.one_line()
            where = f"{printable(str(f))}: "
            rows.append(
                Row(
                    student,
                    printable(str(f)),
                    (),
                    error=line[len(where) :] if line.startswith(where) else line,
                    variant=(printable(named) if named else "") if vbook else None,
                )
            )
    return class_report(args, scene, rows, len(files), book, targets, scene.tolerance)


def class_gradebook(args, files, vbook) -> tuple:
    """(``--gradebook``'s file or None, its write targets): refused in one line unless it
    ends in .csv or .md, or where it would write over a file the class reads (the scene,
    an answer file, a variant)."""
    book = getattr(args, "gradebook", None)
    if book and not book.lower().endswith((".csv", ".md")):
        raise SceneError(f"{book}: the file must end in .csv or .md", key="--gradebook")
    inputs = [args.scene, *files, *(vbook.files if vbook else ())]
    return book, (check_outputs([(book, "--gradebook")], protect=inputs) if book else [])


def class_report(args, scene, rows, count, book, targets, tolerance=None) -> int:
    """A class's rows printed (``--json``, or the table and the summary) and its gradebook
    written; 0 whatever the answers (``tolerance``: the book's, where the scene states one)."""
    from ..check.classroom import (
        class_dict,
        class_text,
        gradebook_csv,
        gradebook_markdown,
        summary_text,
    )

    variants = getattr(args, "variants", None)
    if getattr(args, "json", False):
        print(_json(class_dict(rows, book=tolerance)))
    else:
        print(
            f"{scene.title or args.scene}: {count} answer files"
            + (f", each graded against its own variant in {variants}" if variants else "")
        )
        print(class_text(rows))
        print()
        print(summary_text(rows, book=tolerance))
    if targets:
        data = (
            gradebook_csv(rows)
            if book.lower().endswith(".csv")
            else gradebook_markdown(rows, book=tolerance)
        )
        write_outputs(targets, [(data, False)])
    return 0


def _cmd_check(args) -> int:
    """``polygon-method check SCENE [ANSWERS ...] [--json] [--gradebook FILE] [--variants
    DIR]``: one answer file (or the scene's answers): 0 all right, 1 any wrong; several, or
    a directory: the whole class, 0. With ``--variants``, each answer file is graded
    against the variant it names."""
    from ..check import check_answers, choose_tolerance, verdicts_dict, verdicts_text
    from ..scene import load_answers, load_scene
    from ..motion.solution import solve

    stated = _command_line_tolerance(getattr(args, "tolerance", None))
    scene = load_scene(args.scene)
    sol = solve(scene)
    files = _answer_files(args.answers or [])
    if (
        len(files) > 1
        or (args.answers and Path(args.answers[0]).is_dir())
        or getattr(args, "gradebook", None)
    ):
        if not files:
            raise SceneError(
                f"no answer files in {', '.join(args.answers or ['(none)'])}", key="answers"
            )
        return _cmd_class(args, scene, sol, files)
    args.answers = files[0] if files else None
    variants = getattr(args, "variants", None)
    title = f"{scene.title or args.scene}: answers from " + (
        args.answers if args.answers else "the scene"
    )
    if args.answers:
        own, answers, named, student = load_answers(
            args.answers, scene, with_variant=True, with_student=True
        )
        if student:
            title += f" ({printable(student)})"
        tolerance, source, why = choose_tolerance(stated, own, scene.tolerance, False)
        try:
            vid, sol, _ = _graded_against(
                named, scene, sol, None, _VariantBook(variants, scene) if variants else None
            )
        except PolygonMethodError as exc:
            raise exc.located(args.answers)
        if vid and variants:
            title += f", graded against variant {vid}"
    else:
        if variants:
            raise SceneError(
                "--variants grades answer files: give the students' files (or their directory)",
                key="--variants",
            )
        answers = scene.answers
        tolerance, source, why = choose_tolerance(stated, None, scene.tolerance, True)
    if not answers:
        raise SceneError(
            "nothing to check: the scene has no [answers] and no answer file was given",
            file=args.scene,
            key="[answers]",
        )
    try:
        verdicts = check_answers(sol, answers, tolerance)
    except PolygonMethodError as exc:  # a centre the mechanism has not (I_19 of four links)
        raise exc.located(args.answers or args.scene)
    if getattr(args, "json", False):
        d = verdicts_dict(verdicts, args.scene, args.answers)
        d["tolerance_used"] = {"source": source, "why": why}
        print(_json(d))
    else:
        graded = any(not a.asked for a in answers)  # (questions alone: no tolerance used)
        print(verdicts_text(verdicts, f"{title}\ntolerance used: {why}" if graded else title))
    return 0 if all(v.ok for v in verdicts) else 1


def write_variant_files(args, out, made: bool, files: list) -> None:
    """Write ``files`` ((name, data, binary) each) into the variants' directory ``out``
    (made here when ``made``, and removed again if nothing could be written into it),
    never over the scene; refused in one line where ``out`` holds variants of an earlier
    run that these would not replace (they would be paired with the wrong students)."""
    names = {f[0] for f in files}
    if not made:
        stale = sorted(p.name for p in out.glob("variant-*.toml") if p.name not in names)
        if stale:
            raise PolygonMethodError(
                f"{out} holds {stale[0]}"
                + (f" and {len(stale) - 1} more" if len(stale) > 1 else "")
                + " from an earlier run that this one would not "
                "replace: remove them or write to a new directory",
                key="-o",
            )
    if made:
        out.mkdir()
    try:
        targets = check_outputs([(out / name, "-o") for name, _, _ in files], protect=[args.scene])
        write_outputs(targets, [(data, binary) for _, data, binary in files])
    except BaseException:
        if made:
            try:
                out.rmdir()  # only if nothing was written into it
            except OSError:
                pass
        raise


def variants_target(args) -> tuple:
    """(the directory, whether it is to be made) of ``variants -o``, its count and seed
    checked first: one clear line for each bad one, before anything is solved."""
    from ..variants import MAX_SEED, MAX_VARIANTS

    if args.count < 1 or args.count > MAX_VARIANTS:
        raise SceneError(f"--count {args.count}: between 1 and {MAX_VARIANTS}", key="--count")
    if not 0 <= args.seed <= MAX_SEED:
        raise SceneError(
            f"--seed {args.seed}: a whole number from 0 to {MAX_SEED} (each "
            "variant file records it, and TOML's integers are 64-bit)",
            key="--seed",
        )
    if not args.output.strip():
        raise PolygonMethodError("an empty path: name the directory to write into", key="-o")
    out = Path(args.output)
    if out.is_symlink() and not out.exists():
        raise PolygonMethodError(
            f"cannot write into {out}: it is a link to {os.readlink(out)}, which does not exist",
            key="-o",
        )
    made = not out.exists()
    if out.exists() and not out.is_dir():
        raise PolygonMethodError(f"cannot write into {out}: it is not a directory", key="-o")
    if made and not out.parent.is_dir():
        raise PolygonMethodError(f"cannot write into {out}: no directory {out.parent}", key="-o")
    return out, made


def _cmd_variants(args) -> int:
    """``polygon-method variants SCENE --count N --seed S -o DIR [--pdf]``: a scene per
    student, the answer key (Markdown and CSV) and the problem sheet, written all or none;
    fewer good variants than asked: one line, exit 2, nothing written."""
    from ..scene import load_scene
    from ..variants import (
        answer_key_csv,
        answer_key_markdown,
        generate,
        sheet_markdown,
        sheet_pdf,
        summary_text,
    )

    out, made = variants_target(args)
    scene = load_scene(args.scene)
    vs = generate(scene, args.count, args.seed)
    short = vs.shortfall()
    if short:
        raise PolygonMethodError(short, file=args.scene, key="[variants]")
    files = [(v.name, v.text, False) for v in vs.variants]
    files += [
        ("answer-key.md", answer_key_markdown(vs), False),
        ("answer-key.csv", answer_key_csv(vs), False),
        ("problem-sheet.md", sheet_markdown(vs), False),
    ]
    if args.pdf:  # each student's figure, drawn by the views
        from ..draw import draw_configuration

        files.append(("problem-sheet.pdf", sheet_pdf(vs, figure=draw_configuration), True))
    write_variant_files(args, out, made, files)
    print(summary_text(vs))
    print(
        f"written to {out}: {len(vs.variants)} scenes ({vs.variants[0].name} ... "
        f"{vs.variants[-1].name}), answer-key.md, answer-key.csv, problem-sheet.md"
        + (", problem-sheet.pdf" if args.pdf else "")
    )
    return 0
