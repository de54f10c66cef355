"""The classic slips of the connecting rod's equivalent dynamical system (``m_small_end``,
``m_L``, ``l_GL``, ``correction_couple``, ``correction_torque``), each worked as the slip
would have it with the values' own formulas (:mod:`polygon_method.linkage.rod_system`):
k_G taken about an end (the parallel axes, ``k^2 = k_G^2 + d^2``), the two masses swapped,
L measured from the small end, the couple on the rod given for its torque on the shaft."""

from __future__ import annotations

from ..common.errors import PolygonMethodError
from ..linkage.rod_system import rod_system

__all__ = ["rod_slips"]


def rod_slips(sol, key, piston=None) -> list:
    """(value, code, words) of each classic slip for the rod key ``key``."""
    try:
        s = rod_system(sol, piston)
    except PolygonMethodError:
        return []
    out = []
    l3 = s.l - s.l1
    for end, pin, d in (("small end", s.small, s.l1), ("big end", s.big, l3)):
        if key == "l_GL" and pin == s.small:  # (k_B^2 / l1 = l1 + l2: from_small_end's)
            continue
        v = s.value(key, s.k2 + d * d)
        if v is not None:
            out.append(
                (
                    abs(v),
                    "k_about_end",
                    f"the radius of gyration taken about the {end} {pin} "
                    f"(k^2 = k_G^2 + {d:.6g}^2), not about G",
                )
            )
    if key in ("m_small_end", "m_L"):
        other = "m_L" if key == "m_small_end" else "m_small_end"
        out.append(
            (
                s.value(other),
                "masses_swapped",
                "the two masses swapped: m l2 / (l1 + l2) is at the small end, "
                "m l1 / (l1 + l2) at L",
            )
        )
    if key == "l_GL":
        out.append(
            (
                s.l1 + s.value("l_GL"),
                "from_small_end",
                "L's distance from the small end (l1 + l2), not from G (or k_G taken "
                "about the small end: k^2 / l1 is the same)",
            )
        )
    if key == "correction_torque" and s.ratio is not None:
        out.append(
            (
                abs(s.value("correction_couple")),
                "couple_not_reduced",
                "the correction couple on the rod, not its torque on the crank shaft "
                "(times omega_rod / omega = cos t / sqrt(n^2 - sin^2 t))",
            )
        )
    return out
