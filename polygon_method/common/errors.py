"""One error family and one tolerance policy.

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


class Tolerances:
    """The single tolerance policy of the tool.

    Attributes
    ----------
    singular : float
        A step whose condition measure (the sine of the angle between its two direction
        lines) is below this is singular: an error, never a number. 1e-3 is about 0.06 deg
        from a toggle, change point or dead centre: closer than that, rounding alone (which
        moves a circle intersection by about eps L / c, and the acceleration polygon by
        that over c^2 more) would put errors above 1e-6 of their size into the answers.
    warn : float
        Below this (sin 5 deg) the step is ill-conditioned: the answer is printed with a
        warning naming the step. A drawing error of 0.25 deg then moves the intersection
        by more than 3 %.
    closure : float
        Relative slack (of the lengths involved) within which a circle that just touches
        another circle or line counts as touching rather than missing.
    transmission_warn_deg : float
        The lecture's advice: keep the transmission angle above 40 deg.
    negligible : float
        A value smaller than this fraction of the largest of its kind in the same solution
        (a coupler that translates: omega 3e-13 beside 10 rad/s) is rounding noise: reports
        and step tables show it as 0 with no sense; the JSON keeps the raw number.
    """

    singular = 1e-3
    warn = 0.08715574274765817  # sin(5 deg)
    closure = 1e-12
    transmission_warn_deg = 40.0
    negligible = 1e-10


TOL = Tolerances()
