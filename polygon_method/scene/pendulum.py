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

__all__ = [
    "PENDULUM_KEYS",
    "TWO_SWING_KEYS",
    "centre_from_two_swings",
    "gyration_squared",
    "swing_inertia",
    "two_swings",
]

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


#: the keys of a link swung about each end in turn (its G and its inertia found)
TWO_SWING_KEYS = ("swings", "knife_edge")
_NOT_WITH_SWINGS = ("centre", "along", "from", "distances", "turn", "inertia", "gyration")


def centre_from_two_swings(S: float, c1: float, c2: float) -> float | None:
    """h1, the first pivot's distance from G, of a body swung about two pivots S apart (G
    between them on their line) with ``c_i = g T_i^2 / (4 pi^2)``: both swings give the same
    ``k^2 = c_i h_i - h_i^2``, h2 = S - h1, which is linear in h1: ``h1 = S (c2 - S) / (c1 +
    c2 - 2 S)`` (None where the swings do not fix it).

    >>> round(centre_from_two_swings(1.0975, 0.8970656, 0.6765270), 4)   # Khurmi's rod
    0.7435
    """
    den = c1 + c2 - 2.0 * S
    if abs(den) <= ROUNDING * (c1 + c2):
        return None
    return S * (c2 - S) / den


def two_swings(rd, spec, link, m, name, g) -> tuple:
    """(lam, words of G, I_G, words of I) of a link swung about each of its ends in turn
    ("with a knife-edge through the small end it makes 100 oscillations in 190 s, through
    the big end 100 in 165 s"): ``swings = { B = "100 in 190 s", A = "100 in 165 s" }``, the
    knife-edges ``knife_edge = { B = 37.5, A = 60 }`` beyond each end's centre, away from G
    (the bore's radius; 0 unless given). Its G on the line of its ends and its I_G found."""
    for k in _NOT_WITH_SWINGS + PENDULUM_KEYS + ("about",):
        if k in spec:
            raise rd.error(
                f"{k}: not with swings (the two swings give the centre of mass and the inertia)",
                "masses",
                name,
            )
    sw, edges = spec["swings"], spec.get("knife_edge", {})
    ends = (link.p, link.q)
    if not isinstance(sw, dict) or set(sw) != set(ends):
        raise rd.error(
            f'swings = {{ {ends[1]} = "100 in 190 s", {ends[0]} = "100 in 165 s" }}: the swing '
            f"about each end of {link.key}, both",
            "masses",
            name,
        )
    if not isinstance(edges, dict) or not set(edges) <= set(ends):
        raise rd.error(
            f"knife_edge = {{ {ends[1]} = 37.5 }}: each pivot's distance beyond its end's "
            f"centre (the bore's radius), ends of {link.key}",
            "masses",
            name,
        )
    T, said, e = {}, [], {}
    for end in ends:
        T[end], w = _period(rd, _one_swing(sw[end]), name)
        e[end] = rd.length(edges[end], "masses", name) if end in edges else 0.0
        said.append(
            f"about {end}{f' (a knife-edge {e[end]:.6g} m beyond it)' if e[end] else ''}, {w}"
        )
    L, (p, q) = link.length, ends
    S = L + e[p] + e[q]
    c = {end: g * T[end] ** 2 / (4.0 * math.pi**2) for end in ends}
    h1 = centre_from_two_swings(S, c[p], c[q])
    x = None if h1 is None else h1 - e[p]  # |pG|
    k2 = None if h1 is None else c[p] * h1 - h1 * h1
    if x is None or not 0.0 <= x <= L or not k2 > 0:
        raise rd.error(
            f"the swings ({T[p]:.6g} s about {p}, {T[q]:.6g} s about {q}) put no centre of "
            f"mass between the ends of {link.key} (check the times and the knife-edges)",
            "masses",
            name,
        )
    rd.read_notes.append(
        f"[masses] {name}: swung " + "; ".join(said) + f": g T^2 / (4 pi^2) = {c[p]:.6g} and "
        f"{c[q]:.6g} m; both give k_G^2 = c h - h^2, h_{p} + h_{q} = {S:.6g} m: h_{p} = S (c_{q} "
        f"- S) / (c_{p} + c_{q} - 2 S) = {h1:.6g} m, so G is {x:.6g} m from {p} and k_G = "
        f"{math.sqrt(k2):.6g} m (g = {g:g} m/s^2)"
    )
    return (
        x / L,
        f"on {link.key}, {x:.6g} m from {p} (from the two swings)",
        m * k2,
        f"I_G = {m * k2:.6g} kg m^2 from the two swings (k_G = {math.sqrt(k2):.6g} m)",
    )


def _one_swing(raw) -> dict:
    """A swing's entry as the single-swing keys read it: a period ("1.9 s") or a count."""
    if isinstance(raw, str) and " in " in raw:
        return {"oscillations": raw}
    return {"period": raw}
