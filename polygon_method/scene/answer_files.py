"""An answer file (a part of the scene reader): an ``[answers]`` table on its own (a
student's, with their name and variant), read against the scene it answers."""

from __future__ import annotations

import re

from ..common.errors import PolygonMethodError, SceneError
from .file_text import MAX_SCENE_BYTES, _path_of, _read_start, wide_text
from .loader import _Loader
from .records import Scene
from ..common.units import question
from .source import parsed_table, toml_lines, toml_table
from .table_help import _suggest

_ANSWER_FILE_KEYS = ("answers", "title", "student", "name", "notes", "source", "variant")


def parse_answers(
    text: str,
    scene: Scene,
    file: str | None = None,
    *,
    with_variant: bool = False,
    with_student: bool = False,
):
    """Read an answer file (an ``[answers]`` table, e.g. a student's) against ``scene``.

    Keys and values follow the scene's ``[answers]`` rules. Returns
    ``(tolerance or None, tuple of Answer)``, and with ``with_variant`` the variant the
    file names (``variant = "07"``, a number, or a variant's file name; None if it names
    none) as a third item, and with ``with_student`` the student's name the file gives
    (``student = "A. Student"``, or ``name``; None if it gives none) after it; raises
    :class:`SceneError` naming the key.
    """
    raw = _answer_table(text, scene, file)
    loader = _answer_loader(raw, text, file, scene)
    tolerance, answers = loader.answers(
        set(scene.point_names), scene.sliders, scene.pins, scene.loads
    )
    student = _student(raw, loader, file)
    if not with_variant:
        return (tolerance, tuple(answers)) + ((student,) if with_student else ())
    variant = _variant(raw, loader, file)
    return (tolerance, tuple(answers), (variant.strip() if variant else None)) + (
        (student,) if with_student else ()
    )


#: a value that may be a question in a TOML text: ``= "?``, ``= '?`` (a scene without one
#: pays for nothing more than this search)
_QUESTION_TEXT = re.compile(r"""=[ \t]*["'][ \t]*\?""")


def asked_questions(scene: Scene) -> tuple:
    """The questions asked without their answers (``v_C = "?"``, ``"? rpm"``), each an
    :class:`Answer` whose value is None, in their order: among ``scene.answers`` where they
    were read (``check``, or an answer file put in their place: ``--answers FILE``), else
    from the scene's text (``solve``, ``steps`` leave ``[answers]`` unread: only its
    ``"?"`` keys are read here, checked as ``check`` checks them, and only where the text
    has one). A fault in one is a :class:`SceneError` naming its key and line."""
    if scene.answers:
        return tuple(a for a in scene.answers if a.asked)
    text = scene._text
    if not text or "?" not in text or not _QUESTION_TEXT.search(text):
        return ()
    table = toml_table("\n".join(toml_lines(text))).get("answers")
    if not isinstance(table, dict):
        return ()
    asked = {k: v for k, v in table.items() if k != "tolerance" and question(v) is not None}
    if not asked:
        return ()
    loader = _answer_loader({"answers": asked}, text, scene.file, scene)
    return tuple(loader.answers(set(scene.point_names), scene.sliders, scene.pins, scene.loads)[1])


def _answer_loader(raw, text, file, scene) -> _Loader:
    """A reader of ``raw``'s ``[answers]`` against ``scene`` (its names, links, sliders,
    forces), its lines found in ``text``."""
    loader = _Loader(raw, text, file)
    loader.check_integers()
    loader.unit = scene.units
    loader.index = scene._link_index
    loader.cylinder_list = scene.cylinders
    loader.two_inputs = scene.input.second is not None
    loader.scene_forces = scene.has_forces
    loader.driving_block = scene.input.block
    loader.driving_wheel = scene.input.wheel
    loader.rolling_pairs = scene.rolling
    loader.ground = scene.ground
    loader.answer_file = True
    return loader


def _answer_table(text, scene, file) -> dict:
    """The answer file's TOML table, checked to be one: an ``[answers]`` table, not empty,
    and the few keys beside it (not a scene's tables)."""
    if not isinstance(text, str):
        raise SceneError(
            f"the answer file's text (TOML) is needed as a str, not {type(text).__name__}",
            file=file,
        )
    if not isinstance(scene, Scene):
        raise SceneError(
            f"a Scene is needed to read answers against, not {type(scene).__name__}", file=file
        )
    raw = parsed_table(text, file, 'an answer file needs only key = "value" lines')
    scene_tables = [k for k in ("ground", "links", "input") if isinstance(raw.get(k), dict)]
    if scene_tables:  # the scene itself, or another, given as the answers
        raise SceneError(
            f"this is a scene (it has [{scene_tables[0]}]), not an answer file: an answer "
            "file holds an [answers] table (and optionally title, student)",
            file=file,
            key=f"[{scene_tables[0]}]",
        )
    for key in raw:
        if key not in _ANSWER_FILE_KEYS:
            raise SceneError(
                "an answer file holds an [answers] table (and optionally title, "
                f"student){_suggest(key, _ANSWER_FILE_KEYS)}",
                file=file,
                key=key,
            )
    if not isinstance(raw.get("answers"), dict) or not raw["answers"]:
        raise SceneError("no [answers] table (or it is empty)", file=file, key="[answers]")
    return raw


def _student(raw, loader, file):
    """The student's name the answer file gives (``student``, or ``name``), its spaces
    made single; None if it gives none."""
    student = None
    for key in ("student", "name"):
        if key in raw and student is None:
            if not isinstance(raw[key], str) or not raw[key].strip():
                raise SceneError(
                    f'{key} is the student\'s name, a string: {key} = "A. Student"',
                    file=file,
                    key=key,
                    line=loader.top_line(key),
                )
            student = " ".join(raw[key].split())
    return student


def _variant(raw, loader, file):
    """The variant the answer file names (``variant = "07"``, a number, or a variant's file
    name); None if it names none."""
    variant = raw.get("variant")
    if isinstance(variant, int) and not isinstance(variant, bool):
        variant = f"{variant:02d}"
    if variant is not None and (not isinstance(variant, str) or not variant.strip()):
        raise SceneError(
            'variant names the student\'s variant: variant = "07" (or its '
            'file name, "variant-07.toml")',
            file=file,
            key="variant",
            line=loader.top_line("variant"),
        )
    return variant


def load_answers(path, scene: Scene, *, with_variant: bool = False, with_student: bool = False):
    """Read an answer file from ``path``; see :func:`parse_answers`."""
    path = _path_of(path, "answer")
    try:
        data = _read_start(path)
        if len(data) > MAX_SCENE_BYTES:
            raise SceneError(
                f"larger than {MAX_SCENE_BYTES >> 20} MiB: not an answer file", file=str(path)
            )
        if wide_text(data):
            raise SceneError(f"{wide_text(data)}: save the answers as UTF-8", file=str(path))
        text = data.decode("utf-8-sig")  # a byte-order mark is fine, as in a scene
    except FileNotFoundError:
        raise SceneError("no such file", file=str(path)) from None
    except IsADirectoryError:
        raise SceneError("is a directory, not an answer file", file=str(path)) from None
    except UnicodeDecodeError as exc:
        raise SceneError(f"not UTF-8 text (byte {exc.start})", file=str(path)) from None
    except OSError as exc:
        raise SceneError(f"cannot read: {exc.strerror}", file=str(path)) from None
    if "\x00" in text:
        raise SceneError("not a text file (it holds binary data)", file=str(path))
    try:
        return parse_answers(
            text, scene, file=str(path), with_variant=with_variant, with_student=with_student
        )
    except PolygonMethodError as exc:
        raise exc.located(str(path))
