"""A scene or answer file's text (a part of the scene reader): its bytes read at most
``MAX_SCENE_BYTES`` (a named pipe without waiting for ever), refused in one line where the
path names no file or the bytes are not UTF-8 text."""

from __future__ import annotations

import os
import stat
from pathlib import Path

from ..common.errors import SceneError, printable

#: the most a scene file may hold: a scene is a page of text (``/dev/zero`` is not read on)
MAX_SCENE_BYTES = 1 << 20


def scene_text(path) -> tuple:
    """``(path, text)`` of a scene file: its bytes read (at most ``MAX_SCENE_BYTES``; a
    named pipe without waiting for ever), refused in one line where they are not UTF-8
    text. Shared by :func:`load_scene` and :func:`polygon_method.scene.energy.load_cycle`."""
    path = _path_of(path, "scene")
    try:
        data = _read_start(path)
    except FileNotFoundError:
        raise SceneError("no such file", file=str(path)) from None
    except IsADirectoryError:
        raise SceneError("is a directory, not a scene file", file=str(path)) from None
    except OSError as exc:
        raise SceneError(f"cannot read: {exc.strerror}", file=str(path)) from None
    if len(data) > MAX_SCENE_BYTES:
        raise SceneError(
            f"larger than {MAX_SCENE_BYTES >> 20} MiB: not a scene file (a "
            "scene is a page of TOML text)",
            file=str(path),
        )
    other = wide_text(data)
    if other:
        raise SceneError(f"{other}: save the scene as UTF-8", file=str(path))
    if b"\x00" in data:
        raise SceneError(
            "not a text file (it holds binary data); a scene is TOML text", file=str(path)
        )
    try:
        text = data.decode("utf-8-sig")  # a byte-order mark (some Windows editors) is fine
    except UnicodeDecodeError as exc:
        raise SceneError(
            f"not UTF-8 text (byte {exc.start}); save the scene as UTF-8", file=str(path)
        ) from None
    return path, text


def wide_text(data: bytes) -> str:
    """Words naming the encoding of text saved as UTF-16 or UTF-32 (by its byte-order mark,
    or without one by the noughts every other byte of plain text), which reads as bytes of
    nought, not as binary data; '' for anything else.

    >>> wide_text("AB = 5".encode("utf-16")), wide_text("AB = 5".encode("utf-16-be"))
    ('UTF-16 text (little-endian, with a byte-order mark)', 'UTF-16 text (big-endian)')
    >>> wide_text(b"AB = 5"), wide_text(b"\\x00\\x01\\x02\\x03")
    ('', '')
    """
    for bom, name in (
        (b"\xff\xfe\x00\x00", "UTF-32 text (little-endian, with a byte-order mark)"),
        (b"\x00\x00\xfe\xff", "UTF-32 text (big-endian, with a byte-order mark)"),
        (b"\xff\xfe", "UTF-16 text (little-endian, with a byte-order mark)"),
        (b"\xfe\xff", "UTF-16 text (big-endian, with a byte-order mark)"),
    ):
        if data.startswith(bom):
            return name
    even, odd = data[0:200:2], data[1:200:2]
    if len(data) >= 8 and len(data) % 2 == 0:
        if not odd.strip(b"\x00") and even.isascii() and even.strip(b"\x00"):
            return "UTF-16 text (little-endian)"
        if not even.strip(b"\x00") and odd.isascii() and odd.strip(b"\x00"):
            return "UTF-16 text (big-endian)"
    return ""


def _read_start(path) -> bytes:
    """The first ``MAX_SCENE_BYTES + 1`` bytes of ``path``. A named pipe is opened without
    waiting for a writer (a plain open would wait for ever where none comes): what a writer
    has put in is read, and a pipe that nobody writes into reads as empty."""
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0)
    fd = os.open(path, flags)
    try:
        if hasattr(os, "set_blocking"):
            os.set_blocking(fd, True)  # then read as any file: to the end, or the limit
        fh = os.fdopen(fd, "rb")
    except BaseException:
        os.close(fd)
        raise
    with fh:
        data = fh.read(MAX_SCENE_BYTES + 1)
        if not data and stat.S_ISFIFO(os.fstat(fh.fileno()).st_mode):
            raise SceneError(
                "a named pipe that nothing is writing into: nothing to read "
                "(start its writer first, or give the file itself)",
                file=str(path),
            )
        return data


def _path_of(path, what) -> Path:
    """``path`` as a :class:`Path`, or a :class:`SceneError` for what names no file (None,
    a number, an empty name, a NUL byte)."""
    if isinstance(path, bytes):
        path = os.fsdecode(path)
    if not isinstance(path, (str, os.PathLike)):
        raise SceneError(
            f"a {what} file's path is needed (a str or a Path), not {type(path).__name__}"
        )
    if not str(path).strip():
        raise SceneError(f"an empty file name: name the {what} file")
    if "\x00" in str(path):
        raise SceneError(f"a file name cannot hold a NUL byte: {printable(str(path))}")
    return Path(path)
