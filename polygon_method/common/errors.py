"""One error family (the tolerance policy, once here, is in :mod:`.tolerances`).

Every failure the tool reports is a :class:`PolygonMethodError`. It carries where the
problem is (file, table/key, line, plan step) so that the command line can print it as
one line::

    bad.toml: [links] BC (line 7): length must be positive, got -66 mm

Subclasses say what kind of failure it is:

* :class:`SceneError` -- the scene file itself is wrong (syntax, keys, units, roles).
* :class:`MobilityError` -- the mechanism is not a one-degree-of-freedom linkage that the
  construction steps can build (a :class:`SceneError`).
* :class:`AssemblyError` -- the links cannot be put together at this crank angle.
* :class:`SingularStepError` -- a construction step has parallel direction lines (toggle,
  dead centre, change point): the velocity or acceleration is indeterminate there.
"""

from __future__ import annotations

from .tolerances import TOL, Tolerances  # noqa: F401  (re-exported: their old home)

__all__ = [
    "PolygonMethodError",
    "SceneError",
    "MobilityError",
    "AssemblyError",
    "SingularStepError",
    "Tolerances",
    "TOL",
    "printable",
]


class PolygonMethodError(Exception):
    """Base of every error the tool raises on purpose.

    Parameters
    ----------
    message : str
        What is wrong and, where it helps, what to do.
    file, key, line, step : optional
        Where: the scene file, the table/key (``"[links] BC"``), the line in the file,
        the plan step (``"step 2 (dyad BC, CD at C)"``).
    """

    def __init__(self, message, *, file=None, key=None, line=None, step=None):
        super().__init__(message)
        self.message = message
        self.file = file
        self.key = key
        self.line = line
        self.step = step

    def located(self, file=None):
        """Return a copy that names ``file`` when it did not know it yet."""
        if self.file is None and file is not None:
            self.file = str(file)
        return self

    def one_line(self) -> str:
        """The error as one line: ``file: key (line n): step: message``."""
        parts = []
        if self.file:
            parts.append(printable(str(self.file)))
        where = printable(self.key or "")
        if self.line is not None:
            where = f"{where} (line {self.line})" if where else f"line {self.line}"
        if where:
            parts.append(where)
        if self.step:
            parts.append(printable(self.step))
        parts.append(printable(" ".join(str(self.message).split())))
        return ": ".join(parts)

    def __str__(self) -> str:
        return self.one_line()


def printable(text: str) -> str:
    r"""``text`` with line breaks and other control characters shown escaped, so that a
    message built from a file's name, a title or a key stays one clean line.

    >>> print(printable("bad\nname.toml"), printable("BC"))
    bad\nname.toml BC
    """
    if text.isprintable():
        return text
    return "".join(c if c.isprintable() or c == " " else repr(c)[1:-1] for c in text)


class SceneError(PolygonMethodError):
    """The scene file is not a valid problem statement."""


class MobilityError(SceneError):
    """Not a one-degree-of-freedom mechanism buildable from the construction steps."""


class AssemblyError(PolygonMethodError):
    """The links cannot be assembled at this position (a circle misses a circle or line)."""


class SingularStepError(PolygonMethodError):
    """A step's two direction lines are parallel: the step has no unique solution."""
