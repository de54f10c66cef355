"""The classroom's commands on a turning-moment diagram stated on its own: ``check SCENE
answers/ [--gradebook FILE] [--variants DIR]`` (a whole class, each student against their
own variant where variants are graded) and ``variants SCENE --count N --seed S -o DIR``.
The class table, its summary and the gradebook are the linkage's
(:mod:`polygon_method.check.classroom`); the slips named are the diagram's
(:mod:`polygon_method.check.energy`)."""

from __future__ import annotations

from pathlib import Path

from ..common.errors import PolygonMethodError, SceneError, printable

__all__ = ["check_class", "make_variants", "one_file", "graded"]


def _text(path) -> str:
    from ..scene.reading import scene_text

    return scene_text(path)[1]


def one_file(f, scene, given=True) -> tuple:
    """``(tolerance, answers, variant, student)`` of one answer file (a file found by
    listing a directory is opened only where it is a regular one)."""
    from ..scene.energy import answer_file_from_text
    from .classroom import _listed

    if not given:
        _listed(Path(f))
    text = _text(f)
    try:
        return answer_file_from_text(text, str(f))
    except PolygonMethodError as exc:
        raise exc.located(str(f))


def _percent(args):
    """``--tolerance 5%`` (a per cent: the diagram's answers are of many units), or None."""
    from .classroom import _command_line_tolerance

    stated = _command_line_tolerance(getattr(args, "tolerance", None))
    if stated is None:
        return None
    if stated.absolute:
        raise SceneError(
            "a turning-moment diagram's answers take a per cent (--tolerance 2%)",
            key="--tolerance",
        )
    return stated.relative


class _CycleBook:
    """The variant scenes of ``--variants DIR`` by the id of each one's ``[variant]`` table,
    each solved once when a student first names it."""

    def __init__(self, folder, base):
        from .classroom import _VariantBook

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
        self.names, self._index, self.done = _VariantBook._names, None, {}

    def index(self):
        from ..scene.energy import load_cycle
        from .classroom import _listed

        if self._index is None:
            self._index = []
            for f in self.files:
                try:
                    _listed(f)
                    self._index.append((f, load_cycle(f)))
                except PolygonMethodError as exc:
                    self._index.append((f, exc))
        return self._index

    def find(self, named):
        """(id, scene, solved cycle) of the variant a student names; a
        :class:`SceneError` (that student's row) where it is not there once."""
        from ..forces.flywheel_cycle import solve_cycle

        want = self.names(named)
        hits = [
            (f, sc)
            for f, sc in self.index()
            if not isinstance(sc, Exception)
            and sc.variant is not None
            and self.names(sc.variant.id) & want
        ]
        if len(hits) != 1:
            raise SceneError(
                f"variant '{printable(named)}' is "
                + ("not" if not hits else f"in {len(hits)} files")
                + f" in {self.folder}"
                + (": remove the copies" if hits else ""),
                key="variant",
            )
        f, sc = hits[0]
        if self.base.title and sc.variant.of != self.base.title:
            raise SceneError(
                f"{f.name} is a variant of {sc.variant.of!r}, not of {self.base.title!r}",
                key="variant",
            )
        if f not in self.done:
            self.done[f] = solve_cycle(sc)
        return sc.variant.id, sc, self.done[f]


def graded(args, scene, c, files, stated) -> tuple:
    """``(scene, cycle, tolerance, answers, note)`` of ``check`` with one answer file (or
    the scene's own answers): with ``--variants``, the file's own variant's scene and
    cycle; a file that names a variant is refused unless graded against it (or the scene
    is that variant)."""
    from .classroom import _VariantBook

    variants = getattr(args, "variants", None)
    if not files:
        if variants:
            raise SceneError(
                "--variants grades answer files: give the students' files (or their directory)",
                key="--variants",
            )
        tolerance = stated if stated is not None else scene.tolerance
        return scene, c, tolerance, scene.answers, ""
    own, answers, named, _ = one_file(files[0], scene)
    tolerance = stated if stated is not None else own
    note = ""
    try:
        if variants:
            if named is None:
                raise SceneError('names no variant: add variant = "07"', key="variant")
            vid, scene, c = _CycleBook(variants, scene).find(named)
            note = f", graded against variant {vid}"
        elif named is not None and not (
            scene.variant is not None
            and _VariantBook._names(scene.variant.id) & _VariantBook._names(named)
        ):
            raise SceneError(
                f"names variant '{printable(named)}', and this scene is "
                + (f"variant '{printable(scene.variant.id)}'" if scene.variant else "not a variant")
                + ": grade it against its own variant (check --variants DIR, or that "
                "variant's own scene file)",
                key="variant",
            )
    except PolygonMethodError as exc:
        raise exc.located(str(files[0]))
    return scene, c, tolerance, answers, note


def _row(f, scene, c, stated, vbook, given):
    from ..check.classroom import Row
    from ..check.energy import cycle_verdicts

    student = printable(Path(f).stem)
    named = None
    try:
        own, answers, named, name = one_file(f, scene, given)
        student = printable(name) if name else student
        tolerance = stated if stated is not None else own
        vid, vscene, vc = None, scene, c
        if vbook is not None:
            if named is None:
                raise SceneError(
                    'names no variant: add variant = "07" (the number on the student\'s '
                    "problem sheet)",
                    key="variant",
                )
            vid, vscene, vc = vbook.find(named)
        elif named is not None:
            raise SceneError(
                f"names variant '{printable(named)}': grade it against its own variant "
                "with --variants DIR",
                key="variant",
            )
        if not answers:
            raise SceneError("no answers in its [answers]", key="[answers]")
        how = (
            "three significant figures (computed answers)"
            if tolerance is None
            else f"{100 * tolerance:g} % ({'--tolerance' if stated is not None else 'the file' + chr(39) + 's own'})"
        )
        verdicts = cycle_verdicts(vscene, vc, answers, tolerance)
        return Row(student, printable(str(f)), tuple(verdicts), variant=vid, tolerance=how)
    except PolygonMethodError as exc:  # a row with its error, never the whole run
        line, where = exc.one_line(), f"{printable(str(f))}: "
        return Row(
            student,
            printable(str(f)),
            (),
            error=line[len(where) :] if line.startswith(where) else line,
            variant=(printable(named) if named else "") if vbook else None,
        )


def check_class(args, scene, c, files) -> int:
    """A whole class of answer files: the table, the summary, the gradebook; 0 whatever
    the answers, 2 only on bad input that stops the run."""
    from .classroom import class_gradebook, class_report

    variants = getattr(args, "variants", None)
    vbook = _CycleBook(variants, scene) if variants else None
    book, targets = class_gradebook(args, files, vbook)
    stated = _percent(args)
    given = set(args.answers or ())
    rows = [_row(f, scene, c, stated, vbook, f in given) for f in files]
    return class_report(args, scene, rows, len(files), book, targets)


def make_variants(args, scene) -> int:
    """``variants SCENE --count N --seed S -o DIR``: a scene per student, the answer key
    (Markdown and CSV) and the problem sheet, written all or none."""
    from ..variants.energy import (
        cycle_key_csv,
        cycle_key_markdown,
        cycle_sheet_markdown,
        cycle_summary_text,
        cycle_variants,
    )
    from .classroom import variants_target, write_variant_files

    if getattr(args, "pdf", False):
        raise PolygonMethodError(
            "a turning-moment diagram's problem sheet is Markdown (no figure to draw): "
            "leave out --pdf",
            key="--pdf",
        )
    out, made = variants_target(args)
    try:
        vs = cycle_variants(_text(args.scene), args.scene, args.count, args.seed)
    except PolygonMethodError as exc:
        raise exc.located(args.scene)
    short = vs.shortfall()
    if short:
        raise PolygonMethodError(short, file=args.scene, key="[variants]")
    files = [(v.name, v.text, False) for v in vs.variants]
    files += [
        ("answer-key.md", cycle_key_markdown(vs), False),
        ("answer-key.csv", cycle_key_csv(vs), False),
        ("problem-sheet.md", cycle_sheet_markdown(vs), False),
    ]
    write_variant_files(args, out, made, files)
    print(cycle_summary_text(vs))
    print(
        f"written to {out}: {len(vs.variants)} scenes ({vs.variants[0].name} ... "
        f"{vs.variants[-1].name}), answer-key.md, answer-key.csv, problem-sheet.md"
    )
    return 0
