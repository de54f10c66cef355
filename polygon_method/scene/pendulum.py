"""A link's moment of inertia from its swing as a compound pendulum (a part of the [masses]
reader): the books' "the connecting rod, suspended from the gudgeon pin, makes 21 complete
oscillations in 40 seconds" (``period = "1.905 s"`` or ``oscillations = "21 in 40 s"``, with
``about = "B"``, the end it swings about, or ``pivot_distance = 650``, the pivot's distance
from G where it hangs from another point).

A body of mass m swinging about a pivot at h from its centre of mass G has the period
``T = 2 pi sqrt(I_pivot / (m g h))``, so ``I_pivot = m g h T^2 / (4 pi^2)`` and, by the
parallel axes, ``I_G = I_pivot - m h^2``, ``k_G^2 = g h T^2 / (4 pi^2) - h^2``.

>>> round(gyration_squared(0.65, 1.87, 9.81), 6)   # Khurmi's rod: k_G = 0.377 m
0.142315
"""

from __future__ import annotations

import math
import re

from ..common.tolerances import ROUNDING
from ..common.unit_tables import ABSURD

__all__ = ["PENDULUM_KEYS", "gyration_squared", "swing_inertia"]

#: the [masses] keys of a link's swing as a pendulum
PENDULUM_KEYS = ("period", "oscillations", "pivot_distance")

_TIME = re.compile(r"^\s*((?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(s|sec|seconds?)?\s*$")
_COUNT = re.compile(
    r"^\s*((?:\d+\.?\d*|\.\d+))\s*(?:complete\s+)?(?:oscillations?|swings?)?\s*in\s*"
    r"((?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(s|sec|seconds?)?\s*$"
)


def gyration_squared(h: float, period: float, g: float) -> float:
    """k_G^2 (m^2) of a body swinging about a pivot at ``h`` (m) from G with ``period``
    (s): ``g h T^2 / (4 pi^2) - h^2``."""
    return g * h * period * period / (4.0 * math.pi * math.pi) - h * h


def _period(rd, spec, name) -> tuple:
    """(T in s, words) from ``period`` or ``oscillations``."""
    if ("period" in spec) == ("oscillations" in spec):
        raise rd.error(
            'give the swing\'s period = "1.905 s" or its oscillations = "21 in 40 s": one of them',
            "masses",
            name,
        )
    if "period" in spec:
        raw = spec["period"]
        m = _TIME.match(raw) if isinstance(raw, str) else None
        t = float(m.group(1)) if m else raw if isinstance(raw, (int, float)) else math.nan
        if isinstance(raw, bool) or not (t > 0 and math.isfinite(t)):
            raise rd.error(f'period = {raw!r}: a time, "1.905 s" (seconds)', "masses", name)
        return float(t), f"its period T = {t:.6g} s"
    raw = spec["oscillations"]
    m = _COUNT.match(raw) if isinstance(raw, str) else None
    n, s = (float(m.group(1)), float(m.group(2))) if m else (math.nan, math.nan)
    if not (n > 0 and s > 0 and math.isfinite(n) and math.isfinite(s)):
        raise rd.error(
            f'oscillations = {raw!r}: "21 in 40 s" (complete oscillations in a time)',
            "masses",
            name,
        )
    return s / n, f"{n:g} oscillations in {s:g} s: T = {s / n:.6g} s"


def swing_inertia(rd, spec, link, m, lam, mu, name, g) -> tuple:
    """(I_G kg m^2, words) of the link ``link`` of mass ``m``, its G at (lam, mu) on it,
    from its swing as a compound pendulum about its end ``about`` or a pivot at
    ``pivot_distance`` from G; ``g`` that of [gravity], else 9.81 m/s^2."""
    for k in ("inertia", "gyration"):
        if k in spec:
            raise rd.error(
                f"{k}: not with the swing's period (it gives the moment of inertia)",
                "masses",
                name,
            )
    T, said = _period(rd, spec, name)
    if ("about" in spec) == ("pivot_distance" in spec):
        raise rd.error(
            (
                "give the point the swing is about once: "
                if "about" in spec
                else "the swing needs the point it swings about: "
            )
            + 'about = "B" (an end of the link) or '
            "pivot_distance = 650 (the pivot's distance from G): one of them",
            "masses",
            name,
        )
    if "about" in spec:
        end = spec["about"]
        if end not in link.points:
            raise rd.error(f"about = {end!r}: an end of {link.key} it swings about", "masses", name)
        h = link.length * math.hypot(lam - (0.0 if end == link.p else 1.0), mu)
        where = f"about {end} (|{end}G| = {h:.6g} m)"
    else:
        h = rd.length(spec["pivot_distance"], "masses", name)
        where = f"about a pivot {h:.6g} m from G"
    if not h > 0:
        raise rd.error(
            f"G is at {spec.get('about')}, the point the swing is about (|{spec.get('about')}G| "
            "= 0): a body hung at its centre of mass does not swing; give the end it hung "
            "from or its pivot_distance from G",
            "masses",
            name,
        )
    k2 = gyration_squared(h, T, g)
    if not m * (k2 + h * h) <= ABSURD["moment_of_inertia"]:  # (also an overflow to inf)
        raise rd.error(
            f"a swing of {T:.6g} s {where} gives I_pivot = m g h T^2 / (4 pi^2) beyond "
            f"{ABSURD['moment_of_inertia']:g} kg m^2 (g = {g:g} m/s^2): absurd for a mechanism "
            "(check the period and its unit: seconds)",
            "masses",
            name,
        )
    if k2 < -ROUNDING * h * h:
        raise rd.error(
            f"a swing of {T:.6g} s {where} is quicker than a point mass's at G, 2 pi sqrt(h / "
            f"g) = {2 * math.pi * math.sqrt(h / g):.6g} s: no body has it (check "
            "the period, the pivot and G)",
            "masses",
            name,
        )
    k2 = max(k2, 0.0)
    rd.read_notes.append(
        f"[masses] {name}: swinging {where} as a compound pendulum, {said}: I_pivot = m g h "
        f"T^2 / (4 pi^2) = {m * (k2 + h * h):.6g} kg m^2, I_G = I_pivot - m h^2 = "
        f"{m * k2:.6g} kg m^2 (k_G = {math.sqrt(k2):.6g} m; g = {g:g} m/s^2)"
    )
    return m * k2, f"I_G = {m * k2:.6g} kg m^2 from its swing (k_G = {math.sqrt(k2):.6g} m)"
