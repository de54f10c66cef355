"""Writing a command's outputs: every path checked before anything is computed, every file
written whole or not at all, through symbolic links and into special files, never over the
scene."""

from __future__ import annotations

import errno
import os
import stat
import sys
import tempfile
from pathlib import Path

from ..common.errors import PolygonMethodError, printable

__all__ = ["check_outputs", "write_outputs", "write_output", "is_stdout"]


def is_stdout(path) -> bool:
    """Whether ``path`` is ``-`` or names this process's standard output (``/dev/stdout``,
    ``/proc/self/fd/1``: into a pipe or a file the shell opened), to be written as ``-`` is:
    straight, with the command's words on stderr (never a file renamed over the one the shell
    holds open)."""
    if str(path) == "-":
        return True
    try:
        mine, there = os.fstat(sys.stdout.fileno()), os.stat(path)
    except (OSError, ValueError, AttributeError):  # (no stdout, a captured one, a bad name)
        return False
    return (mine.st_dev, mine.st_ino) == (there.st_dev, there.st_ino)


class _Target:
    """Where one output goes: a new or regular file (written beside it, then renamed over
    it), or a special file (a device, a pipe: written straight into it). A symbolic link is
    written through, never replaced."""

    def __init__(self, path, option, protect=()):
        self.shown, self.option = str(path), option
        if not str(path).strip():
            raise PolygonMethodError("an empty file name", key=option)
        try:
            os.stat(path)
        except OSError as exc:  # a link to itself, or in a ring of links: never replaced
            if exc.errno == errno.ELOOP:
                raise PolygonMethodError(
                    f"cannot write {path}: a symbolic link that leads round to itself "
                    "(a loop): it names no file; give another output",
                    key=option,
                ) from None
        except ValueError:  # (a NUL in the name: refused below, as before)
            pass
        real = Path(os.path.realpath(path))
        if not real.exists() and os.path.exists(path):  # a pipe or a socket behind a link
            real = Path(path)  # (/dev/stdout -> /proc/self/fd/1 -> "pipe:[123]"): opened as named
        if real.is_dir():
            raise PolygonMethodError(f"cannot write {path}: it is a directory", key=option)
        for k, other in enumerate(protect):
            if other and real.exists() and os.path.exists(other) and os.path.samefile(real, other):
                what = (
                    "the scene file itself"
                    if k == 0
                    else f"{printable(str(other))}, which this command reads"
                )
                raise PolygonMethodError(f"cannot write {path}: it is {what}", key=option)
        self.path = real
        self.special = real.exists() and not stat.S_ISREG(real.stat().st_mode)
        directory = real.parent
        if not self.special:
            if not directory.is_dir():
                raise PolygonMethodError(
                    f"cannot write {path}: no directory {directory}", key=option
                )
            if not os.access(directory, os.W_OK | os.X_OK):
                raise PolygonMethodError(
                    f"cannot write {path}: the directory {directory} is not writable", key=option
                )
            if real.exists() and not os.access(real, os.W_OK):
                raise PolygonMethodError(f"cannot write {path}: the file is read-only", key=option)
        self.tmp = None

    def fail(self, exc: OSError):
        if exc.errno == errno.ENXIO and self.special and stat.S_ISFIFO(self.path.stat().st_mode):
            return PolygonMethodError(
                f"cannot write {self.shown}: a named pipe that nothing "
                "is reading from (start its reader first)",
                key=self.option,
            )
        return PolygonMethodError(
            f"cannot write {self.shown}: {exc.strerror or type(exc).__name__}", key=self.option
        )

    def stage(self, data, binary):
        self.data, self.binary = data, binary
        if self.special:
            return
        try:  # a directory that takes no new file (/proc) is the output's failure
            fd, self.tmp = tempfile.mkstemp(
                dir=self.path.parent, prefix=f".{self.path.name}.", suffix=".tmp"
            )
        except OSError as exc:
            raise self.fail(exc) from None
        try:
            with os.fdopen(
                fd, "wb" if binary else "w", **({} if binary else {"encoding": "utf-8"})
            ) as fh:
                fh.write(data)
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(self.tmp, 0o666 & ~umask)  # as an ordinary new file (mkstemp: 0600)
        except OSError as exc:
            raise self.fail(exc) from None

    def commit(self):
        try:
            if self.special:  # a pipe is opened without waiting for a reader that may
                fd = os.open(
                    self.path,  # never come (ENXIO where none is there)
                    os.O_WRONLY | getattr(os, "O_NONBLOCK", 0),
                )
                try:
                    if hasattr(os, "set_blocking"):
                        os.set_blocking(fd, True)
                    fh = os.fdopen(
                        fd,
                        "wb" if self.binary else "w",
                        **({} if self.binary else {"encoding": "utf-8"}),
                    )
                except BaseException:
                    os.close(fd)
                    raise
                with fh:
                    fh.write(self.data)
            else:
                os.replace(self.tmp, self.path)
                self.tmp = None
        except OSError as exc:
            raise self.fail(exc) from None

    def probe(self):
        """For a special file: fail as writing would (a named pipe nothing reads from),
        without writing (a reader there sees the end of an empty file)."""
        if not self.special:
            return
        try:
            os.close(os.open(self.path, os.O_WRONLY | getattr(os, "O_NONBLOCK", 0)))
        except OSError as exc:
            raise self.fail(exc) from None

    def discard(self):
        if self.tmp is not None:
            try:
                os.unlink(self.tmp)
            except OSError:
                pass
            self.tmp = None


def check_outputs(paths, protect=()) -> list:
    """Every output path checked before anything is computed or written: ``paths`` as
    (path, option) pairs; ``protect``: files that must not be written over (the scene
    first, then any other file the command reads)."""
    targets = [_Target(path, option, protect) for path, option in paths]
    seen = {}
    for t in targets:  # two outputs into one file: the one written last would be all of it
        if t.path in seen and not t.special:
            first = seen[t.path]
            raise PolygonMethodError(
                f"{first.option} {first.shown} and {t.option} {t.shown} "
                "are one file: give each output its own",
                key=t.option,
            )
        seen[t.path] = t
    return targets


def write_outputs(targets, datas) -> None:
    """Write every output or none: each regular file staged beside itself first; then the
    special files (a device, a pipe: written straight, so the first that fails stops
    everything before any file is replaced); then the staged files renamed into place."""
    try:
        for t, (data, binary) in zip(targets, datas):
            t.stage(data, binary)
        for t in sorted(targets, key=lambda t: not t.special):
            t.commit()
    finally:
        for t in targets:
            t.discard()


def write_output(path, data, *, binary=False, option=None, protect=()) -> None:
    """Write ``data`` to ``path`` whole or not at all (see :func:`write_outputs`)."""
    write_outputs(check_outputs([(path, option)], protect), [(data, binary)])
