"""The crank angles a sweep may reach on the scene's branch (:class:`Domain`), the limit
positions that bound them (:class:`LimitPosition`) and the change points inside them
(:class:`ChangePoint`), and how their angles are written; :mod:`.tracking` finds them."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..common.tolerances import ROUNDING

__all__ = ["Domain", "LimitPosition", "ChangePoint", "TWO_PI", "NEAR", "fmt_deg", "degrees_fn"]

TWO_PI = 2.0 * math.pi
#: samples this close to a change point (rad) get their velocities and accelerations by
#: extrapolation from both sides (the construction is indeterminate there)
NEAR = 2e-3


@dataclass(frozen=True)
class LimitPosition:
    """A crank angle beyond which the sweep cannot go on the scene's branch.

    ``theta`` is in the sweep's domain (rad, continuous with the scene's angle); ``step``
    names the construction step that stops assembling (its discriminant vanishes there).
    """

    theta: float
    step: str
    why: str

    @property
    def degrees(self) -> float:
        """The crank angle of the limit position in degrees, within one turn."""
        return math.degrees(self.theta) % 360.0


@dataclass(frozen=True)
class ChangePoint:
    """A crank angle where a step's two assemblies meet (its condition reaches zero and
    rises again): the branch is indeterminate there. ``followed`` says whether the sweep
    went on (on the branch continuous in velocity) or stopped."""

    theta: float
    step: str
    point: str
    followed: bool
    flipped: bool
    why: str
    #: closer than this the construction is not trusted (rad; a driving block's place: m)
    radius: float = NEAR

    @property
    def degrees(self) -> float:
        """The crank angle of the change point in degrees, within one turn."""
        return math.degrees(self.theta) % 360.0


@dataclass(frozen=True)
class Domain:
    """The crank angles reachable from the scene's instant on its branch.

    ``lo <= theta <= hi`` (rad, continuous with the scene's angle); ``full_turn`` when the
    crank turns fully (then ``hi = lo + 2 pi turns``: the whole period of the motion,
    ``turns`` turns of the crank where a wheel turns a fraction of a turn more per turn of
    the crank and the mechanism is back only after several). ``segments`` are ``(start, end, plan)``
    with the plan (its branches) valid between change points.
    """

    lo: float
    hi: float
    full_turn: bool
    segments: tuple
    limits: tuple = ()
    change_points: tuple = ()
    notes: tuple = ()
    #: False where the parameter is a block driver's place along its guide (m): nothing
    #: repeats, ``lo`` and ``hi`` are the ends of its stroke
    periodic: bool = True
    #: a block driver's places are shown in the scene's length unit: metres per unit
    unit: float = 1.0
    #: a full turn after which the mechanism is not where it started (a wheel that turns a
    #: fraction of a turn more per turn of the crank): every angle is taken on this turn
    #: (``map``), and the notes say after how many turns the motion repeats
    turn_only: bool = False
    #: the motion's period in turns of the crank (a full turn's domain spans all of them)
    turns: int = 1

    @property
    def period(self) -> float:
        """The crank's turn over which the motion repeats (rad): 2 pi times ``turns``."""
        return TWO_PI * self.turns

    def map(self, theta):
        """Crank angles (rad, any turn) -> the same angles in ``[lo, lo + period)`` and a mask
        of those the crank reaches (a block driver's places: themselves, and a mask of those
        in its stroke)."""
        if not self.periodic:
            t = np.asarray(theta, dtype=float)
            tol = ROUNDING * max(abs(self.lo), abs(self.hi), self.hi - self.lo)
            return t, (t >= self.lo - tol) & (t <= self.hi + tol)
        t = self.lo + np.mod(np.asarray(theta, dtype=float) - self.lo, self.period)
        if self.full_turn:
            return t, np.ones(t.shape, dtype=bool)
        return t, t <= self.hi + ROUNDING


def fmt_deg(d, digits=4) -> str:
    """An angle in degrees to ``digits`` decimals, never "-0.0000"."""
    s = f"{d:.{digits}f}"
    return s if s.strip("-0.") else f"{0.0:.{digits}f}"


def degrees_fn(dom: Domain):
    """Radians -> the degrees shown, within one turn, [0, 360): for a full turn and for a
    crank that reaches only a range alike (a range that passes 0 is written "300 to 40
    (through 0)"). A block driver's places (m) are shown in the scene's length unit
    instead; a motion that repeats only after several turns, within them ([0, 1080) for
    three)."""
    if not dom.periodic:
        return lambda t: float(t) / dom.unit
    whole = 360.0 * dom.turns

    def deg(t):
        d = math.degrees(t) % whole
        return 0.0 if d >= whole - 5e-4 else d

    return deg
