"""The connecting rod of a slider crank on the driving crank, as the engine chapter's
equivalent dynamical system reads it: which rod, its mass ``m``, length ``l``, G ``l1`` from
the small end and ``k_G^2``; the two masses and the correction couple (the one definition:
the answer keys of :mod:`polygon_method.linkage.rod_system` and the sweep's columns
``correction_couple``, ``correction_torque`` read it, floats or arrays alike).

>>> [round(x, 12) for x in two_mass(2.0, 0.1, 0.11**2)]  # Khurmi's: 2 kg, l1 100, k_G 110 mm
[1.095022624434, 0.904977375566, 0.121]
"""

from __future__ import annotations

import numpy as np

from ..common.errors import PolygonMethodError
from .engine import slider_crank

__all__ = ["correction_arrays", "correction_couple", "rod_of", "two_mass"]


def two_mass(m, l1, k2) -> tuple:
    """(the mass at the small end, the mass at L, L's distance l2 from G) of a rod of mass
    ``m`` whose G is ``l1`` from the small end, ``k2`` its k_G^2: ``l1 l2 = k_G^2``."""
    l2 = k2 / l1
    return m * l2 / (l1 + l2), m * l1 / (l1 + l2), l2


def correction_couple(m, l, l1, k2, alpha):
    """``m alpha (l1 l3 - k_G^2)``, ``l3 = l - l1``: the two pin masses' moment of inertia
    about G less the rod's, times alpha; ccw positive (alpha ccw +): the couple added to the
    two pin masses' inertia couple ``-m l1 l3 alpha`` makes the rod's own ``-m k_G^2 alpha``
    (in the sense of alpha where l1 l3 > k_G^2; floats or arrays of alpha)."""
    return m * alpha * (l1 * (l - l1) - k2)


def _rods(sc, plan) -> list:
    """(piston, rod key, crank pin) of each slider crank on the driving crank."""
    first = plan.steps[0]
    tip = getattr(first, "tip", None)
    out = []
    for p in dict.fromkeys(s.point for s in sc.sliders):
        pair = slider_crank(plan, p)
        if pair is not None and tip is not None:
            lk = sc.link(pair[1].link)
            if {lk.p, lk.q} == {p, tip}:
                out.append((p, lk.key, tip))
    return list(dict.fromkeys(out))


def _one(sc, plan, piston) -> tuple:
    """(piston, rod key, crank pin) of the scene's rod (``piston``'s where named)."""
    rods = _rods(sc, plan)
    if piston is not None:
        rods = [r for r in rods if r[0] == piston]
        if not rods:
            raise PolygonMethodError(f"{piston} is no piston of a slider crank on the crank")
    if not rods:
        raise PolygonMethodError(
            "no connecting rod: the equivalent dynamical system is a slider crank's rod "
            "(a piston on a fixed path, pinned by a rod to the driving crank's pin)"
        )
    if len(rods) > 1:
        massive = [r for r in rods if any(m.body == r[1] for m in sc.masses)]
        if len(massive) != 1:
            raise PolygonMethodError(
                "several connecting rods on the crank: name the piston after the key ("
                + " or ".join(f"_{r[0]}" for r in rods)
                + ")"
            )
        rods = massive
    return rods[0]


def rod_of(sc, plan, piston=None) -> tuple:
    """(small end, rod key, big end, m, l, l1, k2, the words of its inertia) of the
    scene's connecting rod, or a :class:`PolygonMethodError` saying why there is none."""
    small, key, big = _one(sc, plan, piston)
    mass = next((m for m in sc.masses if m.body == key and not m.block), None)
    if mass is None or mass.mass <= 0:
        raise PolygonMethodError(
            f"the rod {key} has no mass: give it in [masses] (mass, centre, gyration)"
        )
    if mass.mu != 0.0:
        raise PolygonMethodError(
            f"the rod {key}'s centre of mass is off its line of centres: the two-mass "
            "system of the books takes G on it"
        )
    lk = sc.link(key)
    l1 = (mass.lam if lk.p == small else 1.0 - mass.lam) * lk.length
    if not l1 > 0.0:
        raise PolygonMethodError(
            f"the rod {key}'s centre of mass is at (or beyond) its small end {small}: "
            "no second point L (l2 = k_G^2 / l1)"
        )
    return small, key, big, mass.mass, lk.length, l1, mass.inertia / mass.mass, mass.how


def correction_arrays(sc, plan, W, Al, n) -> tuple | None:
    """(the correction couple, its torque on the crank shaft or None where the crank stands
    at some row) over ``n`` positions of a sweep (``W``, ``Al`` its omegas and alphas), or
    None where the scene has no rod the two-mass system takes."""
    try:
        _, key, _, m, l, l1, k2, _ = rod_of(sc, plan)
    except PolygonMethodError:
        return None
    a = np.broadcast_to(np.asarray(Al[key], dtype=float), (n,))
    c = correction_couple(m, l, l1, k2, a)
    w = np.broadcast_to(np.asarray(W[plan.steps[0].link], dtype=float), (n,))
    wr = np.broadcast_to(np.asarray(W[key], dtype=float), (n,))
    if not (np.all(w != 0.0) and np.all(np.isfinite(w))):
        return c, None
    return c, c * (wr / w)
