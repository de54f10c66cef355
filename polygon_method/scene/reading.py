"""Reading a scene: TOML text (or a file) checked table by table into a :class:`Scene`,
every failure one :class:`SceneError` naming the file, key and line."""

from __future__ import annotations

from ..common.errors import PolygonMethodError, SceneError
from .source import (
    LineIndex,  # noqa: F401
    has_long_run as _has_long_run,  # noqa: F401  (its old name)
    key_line,  # noqa: F401
    line_of,  # noqa: F401
    parsed_table,
    toml_lines,
    toml_table,
)
from .records import Scene
from .file_text import MAX_SCENE_BYTES, scene_text  # noqa: F401  (read here, and by energy)
from .loader import MAX_POINTS, _Loader  # noqa: F401  (MAX_POINTS: the reader's bound)
from .answer_files import load_answers, parse_answers  # noqa: F401  (the package's)


def load_scene(path, *, variants: bool = True, answers: bool = True) -> Scene:
    """Read and check a scene file. Raises :class:`SceneError` naming file, key and line.
    With ``variants=False`` the ``[variants]`` table is left unread (``scene.variation``
    is None): for a command that makes no variants, which need not pay for reading it.
    With ``answers=False`` the ``[answers]`` table is left unread (``scene.answers`` is
    empty, ``scene.tolerance`` None): for a command that checks no answers. A file that
    states a turning-moment diagram with no mechanism (``[turning_moment]`` or ``[press]``)
    is refused in one line naming :func:`polygon_method.load_cycle`, its reader."""
    path, text = scene_text(path)
    try:
        return parse_scene(text, file=str(path), variants=variants, answers=answers)
    except PolygonMethodError as exc:
        raise exc.located(str(path))


def parse_scene(
    text: str, file: str | None = None, *, variants: bool = True, answers: bool = True
) -> Scene:
    """Parse scene text (TOML). See :func:`load_scene`."""
    if isinstance(text, (bytes, bytearray)):
        raise SceneError(
            "the scene's text is needed as a str: decode the bytes (UTF-8), or "
            "give the file to load_scene",
            file=file,
        )
    if not isinstance(text, str):
        raise SceneError(
            f"the scene's text (TOML) is needed as a str, not "
            f"{type(text).__name__}; load_scene reads a file",
            file=file,
        )
    if not text.strip():
        raise SceneError(
            "the file is empty; a scene needs [ground], [links] and [input]", file=file
        )
    raw = parsed_table(text, file, "a scene needs at most [x, y] pairs and small tables")
    if not raw:
        raise SceneError(
            "the file has no tables or keys (only comments); a scene needs "
            "[ground], [links] and [input]",
            file=file,
        )
    loader = _Loader(raw, text, file)
    loader.read_variants = variants
    loader.read_answers = answers
    return loader.scene()


def scene_table(scene: Scene) -> dict:
    """The TOML table a scene was read from (its text parsed again), for making variants
    of it; empty for a scene not read from text."""
    return toml_table("\n".join(toml_lines(scene._text))) if scene._text else {}


def scene_from_table(raw: dict, file: str | None = None) -> Scene:
    """A scene from a TOML table already parsed (checked exactly as a file's would be; the
    messages name no line)."""
    return _Loader(raw, "", file).scene()
