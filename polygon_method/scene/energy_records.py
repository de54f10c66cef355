"""The records of a turning-moment diagram stated on its own (the flywheel chapter): the
diagram given as areas, as a law of the crank angle or as a table of straight segments; a
punching press; the flywheel and its rim. Read by :mod:`polygon_method.scene.energy`.

A torque law is a sum of terms ``c``, ``c sin(k theta + phi)``, ``c cos(k theta + phi)``:

>>> law = Law((("const", 1000.0, 0.0, 0.0), ("sin", 300.0, 2.0, 0.0)), "1000 + 300 sin 2theta")
>>> round(law.value(math.pi / 4), 9)
1300.0
>>> round(law.integral(math.pi) - law.integral(0.0), 9) == round(1000 * math.pi, 9)
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["Law", "Table", "Diagram", "Press", "Rim", "CycleScene"]


@dataclass(frozen=True)
class Law:
    """``T(theta) = sum c f(k theta + phi)`` (N m), each term ``(f, c, k, phi)`` with ``f``
    one of "const", "sin", "cos" (``k`` and ``phi`` unused for a constant; ``phi`` rad);
    ``text``: as the scene wrote it."""

    terms: tuple
    text: str

    def value(self, th):
        """T at ``th`` (rad; a float or an array)."""
        sin, cos = (math.sin, math.cos) if np.ndim(th) == 0 else (np.sin, np.cos)
        out = 0.0
        for f, c, k, phi in self.terms:
            if f == "const":
                out = out + c
            elif f == "sin":
                out = out + c * sin(k * th + phi)
            else:
                out = out + c * cos(k * th + phi)
        return out + 0.0 * np.asarray(th) if np.ndim(th) else float(out)

    def integral(self, th):
        """An antiderivative of T at ``th``: ``c theta``, ``-c/k cos(k theta + phi)``,
        ``c/k sin(k theta + phi)``, summed (the integral's closed form)."""
        sin, cos = (math.sin, math.cos) if np.ndim(th) == 0 else (np.sin, np.cos)
        out = 0.0
        for f, c, k, phi in self.terms:
            if f == "const":
                out = out + c * th
            elif f == "sin":
                out = out - c / k * cos(k * th + phi)
            else:
                out = out + c / k * sin(k * th + phi)
        return out if np.ndim(th) else float(out)

    @property
    def corners(self) -> tuple:
        """Where T has a corner (none: a law is smooth)."""
        return ()


@dataclass(frozen=True)
class Table:
    """A turning moment of straight segments: ``angles`` (rad, not decreasing; a jump where
    one repeats) and ``torques`` (N m), linear between them."""

    angles: tuple
    torques: tuple
    text: str = ""

    def value(self, th):
        """T at ``th`` (rad; a float or an array): linear between the readings (at a jump,
        the value after it)."""
        a, t = np.asarray(self.angles), np.asarray(self.torques)
        x = np.asarray(th, dtype=float)
        i = np.clip(np.searchsorted(a, x, side="right") - 1, 0, len(a) - 2)
        a0, a1, t0, t1 = a[i], a[i + 1], t[i], t[i + 1]
        span = np.where(a1 > a0, a1 - a0, 1.0)
        out = np.where(x == a1, t1, t0 + (t1 - t0) * (x - a0) / span)  # a reading: its own
        return float(out) if np.ndim(out) == 0 else out

    def integral(self, th):
        """The area under the segments from the table's first angle to ``th`` (rad; a
        float), the trapezoids' exact sum."""
        a, t = self.angles, self.torques
        s = 0.0
        for a0, a1, t0, t1 in zip(a, a[1:], t, t[1:]):
            if th <= a0:
                break
            if a1 <= a0:
                continue
            b = min(th, a1)
            tb = t0 + (t1 - t0) * (b - a0) / (a1 - a0)
            s += 0.5 * (t0 + tb) * (b - a0)
        return s

    @property
    def corners(self) -> tuple:
        """Where T has a corner or a jump: every reading's angle."""
        return tuple(self.angles)


@dataclass(frozen=True)
class Diagram:
    """A turning-moment diagram over ``cycle`` rad of the crank. ``form`` is "areas"
    (``areas``: the energies between the diagram and the mean line, J, in order, positive
    above it; ``mm2``: the same as the book's mm^2 where it gave them, and ``per_mm2`` the
    energy of one mm^2, J) or "law" / "table" / "strokes" (``driving``: the engine's turning moment, a
    :class:`Law` or :class:`Table`; ``resisting``: the machine's, one of the same, or None:
    constant at the mean), or "energy" (the maximum fluctuation of energy given, alone or
    as a part of the work of a cycle: no diagram). ``at``: a crank angle (rad) where the
    angular acceleration is asked, or None. ``words``: how each item was read, the defaults
    named."""

    form: str
    cycle: float
    areas: tuple = ()
    mm2: tuple = ()
    per_mm2: float | None = None
    driving: object = None
    resisting: object = None
    at: float | None = None
    words: tuple = ()
    #: form "energy" (no diagram, the book's statement of the energy alone): the maximum
    #: fluctuation of energy given (J), and the net work of a cycle where known (J)
    fluctuation: float | None = None
    work: float | None = None


@dataclass(frozen=True)
class Press:
    """A punching (or riveting) press: ``energy`` the work of one hole (J), ``period`` the
    time of one cycle (s: 60 / holes a minute), ``fraction`` the part of the cycle the
    punching takes (its time over the period, or its crank angle over a turn). The motor
    gives ``energy / period`` all the time; during the punching the flywheel gives the rest,
    so ``dE_max = energy (1 - fraction)``. ``words``: how each item was read."""

    energy: float
    period: float
    fraction: float
    words: tuple = ()


@dataclass(frozen=True)
class Rim:
    """The flywheel of a diagram's scene (``[flywheel]``). ``coefficient`` Cs =
    (w_max - w_min) / w_mean, or None where ``inertia`` (kg m^2) is given instead (then Cs
    is found); ``speed`` the mean speed (rad/s). For the rim: ``radius`` (its mean radius,
    m), or ``gyration``, or found from ``rim_speed`` (m/s) or the hoop ``stress`` (Pa:
    sigma = rho v^2); ``density`` (kg/m^3); ``share`` of the flywheel's effect the rim gives;
    its section from ``ratio`` (width / thickness), ``width`` or ``thickness`` (m).
    ``words``: how each item was read, the defaults named. ``speed`` None: the shaft's
    speed not given, the rim's speed alone (its mass from ``m v^2 Cs = dE_max``)."""

    coefficient: float | None
    speed: float | None
    inertia: float | None = None
    radius: float | None = None
    gyration: float | None = None
    rim_speed: float | None = None
    stress: float | None = None
    density: float = 7200.0
    share: float = 1.0
    ratio: float | None = None
    width: float | None = None
    thickness: float | None = None
    words: tuple = ()


@dataclass(frozen=True)
class CycleScene:
    """A scene that states a turning-moment diagram (or a press) and no mechanism: its
    ``diagram`` or ``press`` (one of them), its ``flywheel`` (a :class:`Rim`, or None),
    ``answers`` (:class:`~polygon_method.scene.records.Answer` records), the answers'
    ``tolerance``; ``units`` the lengths' default unit; ``variant`` the ``[variant]`` table
    of a generated variant (a :class:`~polygon_method.scene.variation.VariantOf`) or
    None."""

    title: str
    file: str | None
    diagram: Diagram | None
    press: Press | None
    flywheel: Rim | None
    answers: tuple = ()
    tolerance: float | None = None
    source: str | None = None
    units: str = "mm"
    variant: object = None
