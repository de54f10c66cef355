"""A piston's given motion as a book words it: "the piston moves at 5 m/s towards the crank",
"... accelerating at 20 m/s^2 away from the crank" (``[input] vs_B``, ``as_B``).

The way is read along the piston's path: towards the crank's pivot O from where the piston
is at the stated crank angle. With the crank pin A at the crank's angle and the rod AB of
length l, B is where the circle of radius l about A meets the path (through Q along u): the
foot F of A on the path, ``B = F + s sqrt(l^2 - |AF|^2) u``, s the side the scene's
[assembly] hint takes (the one farther along u without one, as the compiler takes it; for a
rough position, the nearer). "Towards the crank" is then the sign of ``(O - B) . u``.
"""

from __future__ import annotations

import math
import re

from .angles import side_along
from .records import FixedPath

__all__ = ["towards_the_crank"]

_TOWARDS = re.compile(
    r"^\s*(.*?)\s*,?\s*\b(towards|toward|away from)\s+the\s+crank(?:\s+(?:shaft|centre|center))?"
    r"\s*$",
    re.IGNORECASE,
)


def towards_the_crank(reader, slider, *given) -> tuple:
    """Each ``(raw, key)`` of ``given`` (a speed and its rate) with its "towards the crank"
    (or "away from the crank") turned into a sign along the path of ``slider``, where it is
    a :class:`FixedPath`; else as it is. ``reader.crank_now`` is (pivot, tip, angle rad,
    crank link) at the stated angle, or None where the crank's angle is still to be found
    (the position given otherwise: refused, the way is not known)."""
    if not isinstance(slider, FixedPath):
        return tuple(raw for raw, _ in given)
    return tuple(_signed(reader, raw, key, slider, reader.crank_now) for raw, key in given)


def _signed(reader, raw, key, slider, crank):
    """``raw`` signed along the slider's path for its words, or as it is."""
    m = _TOWARDS.match(raw) if isinstance(raw, str) else None
    if m is None:
        return raw
    if crank is None:
        raise reader.error(
            f"{raw!r}: towards the crank depends on where the piston is, which the position "
            "given otherwise leaves to be found; say the way as left, right, up or down",
            "input",
            key,
        )
    pivot, tip, theta, link = crank
    rods = [lk for lk in reader.index.values() if set(lk.points) == {tip, slider.point}]
    if not rods:
        raise reader.error(
            f"{raw!r}: towards the crank is read for a piston whose rod is pinned to the "
            f"crank pin {tip}; say the way as left, right, up or down",
            "input",
            key,
        )
    (ox, oy), (ux, uy) = reader.ground[pivot], slider.u
    qx, qy = (ox, oy) if slider.through[1] is None else slider.through
    ax, ay = ox + link.length * math.cos(theta), oy + link.length * math.sin(theta)
    t = (ax - qx) * ux + (ay - qy) * uy
    fx, fy = qx + t * ux, qy + t * uy  # the foot of the crank pin on the path
    h2 = rods[0].length ** 2 - (ax - fx) ** 2 - (ay - fy) ** 2
    if h2 < 0:
        raise reader.error(
            f"{raw!r}: the rod cannot reach the path at the stated crank angle", "input", key
        )
    h = math.sqrt(h2)
    hint = reader.raw.get("assembly", {}).get(slider.point)
    if isinstance(hint, list):  # a rough position: the nearer of the two
        near = reader.coords(hint, "assembly", slider.point)
        side = min((1, -1), key=lambda s: math.dist(near, (fx + s * h * ux, fy + s * h * uy)))
    else:
        side = side_along(hint, (ux, uy))
    bx, by = fx + side * h * ux, fy + side * h * uy
    ahead = (ox - bx) * ux + (oy - by) * uy
    if ahead == 0:
        raise reader.error(
            f"{raw!r}: the piston is level with the crank's centre across its path; say "
            "the way as left, right, up or down",
            "input",
            key,
        )
    sign = (1 if ahead > 0 else -1) * (-1 if m.group(2).lower().startswith("away") else 1)
    size = m.group(1).strip()
    if size.startswith(("-", "+")):  # a signed size: its sign as well
        sign, size = (-sign if size[0] == "-" else sign), size[1:].strip()
    return size if sign > 0 else f"-{size}"
