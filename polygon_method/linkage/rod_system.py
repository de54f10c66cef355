"""The engine chapter's equivalent dynamical system of a connecting rod, exactly (the answer
keys' one definition; read by ``check``, ``variants`` and ``steps``).

The rod (mass ``m``, length ``l`` between centres, G on the line of centres ``l1`` from the
small end B, the gudgeon pin, and ``l3 = l - l1`` from the big end A, the crank pin; radius
of gyration ``k_G`` about G) is replaced by two masses, one at B and one at a point L beyond
G, ``l2 = GL`` from G, with the same mass, centre and moment of inertia:

- ``l1 l2 = k_G^2``, so ``l2 = k_G^2 / l1``;
- ``m_B = m l2 / (l1 + l2)`` at the small end, ``m_L = m l1 / (l1 + l2)`` at L.

With the second mass at the crank pin A instead (``m l1 / l`` there, ``m l3 / l`` at B),
the two masses have the moment of inertia ``m l1 l3`` about G, not ``m k_G^2``: the
correction couple ``T' = m alpha (l1 l3 - k_G^2) = m alpha l1 (l - l1 - l2)`` (alpha the
rod's angular acceleration) must be applied against alpha, and reaches the crank shaft as
``T' omega_rod / omega`` (virtual power; for the in-line engine ``T' cos t / sqrt(n^2 -
sin^2 t)``).

>>> [round(x, 12) for x in two_mass(2.0, 0.1, 0.11**2)]  # Khurmi's: 2 kg, l1 100, k_G 110 mm
[1.095022624434, 0.904977375566, 0.121]
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..common.errors import PolygonMethodError
from ..forces.rod import correction_couple, rod_of, two_mass

__all__ = ["ROD_KEYS", "RodSystem", "correction_couple", "rod_system", "rod_value", "two_mass"]

#: answer key -> (unit kind, SI unit, what it is)
ROD_KEYS = {
    "m_small_end": ("mass", "kg", "the mass at the small end (the gudgeon pin)"),
    "m_L": ("mass", "kg", "the mass at L (the equivalent dynamical system's second point)"),
    "l_GL": ("length", "m", "L's distance from G (l2 = k_G^2 / l1)"),
    "correction_couple": ("torque", "N m", "the correction couple on the rod"),
    "correction_torque": ("torque", "N m", "the correction couple's torque on the crank shaft"),
}


@dataclass(frozen=True)
class RodSystem:
    """The connecting rod ``rod`` of the slider crank whose piston (small end) is ``small``,
    its big end ``big`` on the crank pin: ``m`` (kg), ``l`` (m), G ``l1`` from the small
    end, ``k2 = k_G^2``, the rod's angular acceleration ``alpha`` (rad/s^2, ccw +) and
    ``ratio`` = omega_rod / omega_crank (None with the crank at rest); ``how`` the words of
    its inertia (as ``[masses]`` gave it)."""

    rod: str
    small: str
    big: str
    m: float
    l: float
    l1: float
    k2: float
    alpha: float
    ratio: float | None
    how: str = ""

    def value(self, key, k2=None) -> float | None:
        """The value of the rod key ``key`` (with ``k2`` for k_G^2 where given: a slip's)."""
        k2 = self.k2 if k2 is None else k2
        m_b, m_l, l2 = two_mass(self.m, self.l1, k2)
        if key == "m_small_end":
            return m_b
        if key == "m_L":
            return m_l
        if key == "l_GL":
            return l2
        c = correction_couple(self.m, self.l, self.l1, k2, self.alpha)
        if key == "correction_couple":
            return c
        return None if self.ratio is None else c * self.ratio


def rod_system(sol, piston=None) -> RodSystem:
    """The :class:`RodSystem` of the scene's connecting rod (``piston``'s, where several
    slider cranks share the crank), or a :class:`PolygonMethodError` saying why not."""
    small, key, big, m, l, l1, k2, how = rod_of(sol.scene, sol.plan, piston)
    w = float(sol.W[sol.plan.steps[0].link])
    wr, ar = float(sol.W[key]), float(sol.Al[key])
    ratio = wr / w if w != 0.0 and math.isfinite(w) else None
    return RodSystem(key, small, big, m, l, l1, k2, ar, ratio, how)


def rod_value(sol, key, piston=None) -> float:
    """The exact value of the rod key ``key`` (``piston``'s rod where named)."""
    s = rod_system(sol, piston)
    v = s.value(key)
    if v is None:
        raise PolygonMethodError(
            "the crank is at rest: its torque from the correction couple is asked per "
            "rad/s of the crank (give its speed)"
        )
    return v
