"""A load's direction stated against a link (a part of the scene reader): ``"along CD"``
(from C towards D), ``"perpendicular to CD, ccw"`` (C->D turned 90 deg ccw), ``"30 deg ccw
from CD"``, ``"at 30 deg to CD, ccw"``. Such a direction turns with the link: the load's
force at any position is :func:`load_force` of the solved positions there (floats at one
instant, arrays over a sweep), the one place the power balance, the force analysis, the
words and the drawings take it from."""

from __future__ import annotations

import math
import re

import numpy as np

from ..common.errors import SceneError
from ..common.numbers import fmt
from .angles import _SENSE, _SENSE_RE
from .table_help import _unit_at

_S = rf"({_SENSE_RE})"  # the senses an angle takes (scene/angles.py's table)
_NAME = r"([A-Za-z][A-Za-z0-9]*(?:-[A-Za-z][A-Za-z0-9]*)?)"
_ALONG = re.compile(rf"(?:along|parallel to) {_NAME}", re.I)
_ACROSS = re.compile(
    rf"(?:perpendicular to|normal to|at right angles to|square to) {_NAME}(?: {_S})?", re.I
)
_AT = re.compile(
    rf"(?:at )?([0-9]+(?:\.[0-9]*)?|\.[0-9]+) ?(?:deg|degrees|°)"
    rf"(?: {_S})? (?:from|to|with) {_NAME}(?: {_S})?",
    re.I,
)


def _tidy(raw: str) -> str:
    text = raw.strip()
    text = re.sub(
        r"\banti[-\s]clockwise|\bcounter[-\s]clockwise", "anticlockwise", text, flags=re.I
    )
    text = re.sub(r"[,;()]", " ", text)
    text = re.sub(r"°", " deg", text)
    return re.sub(r"\s+", " ", text).strip()


def read_across(raw, split_name):
    """``(first point, second point, offset in rad or None, words as stated)`` of a
    direction stated against a link, or None where the words say none (a plain angle, a
    book's angle). The offset turns the direction first -> second (None: "perpendicular
    to CD" without its sense, refused once the positions say which way each points).
    Raises :class:`SceneError` for such words it cannot read."""
    if not isinstance(raw, str):
        return None
    text = _tidy(raw)
    low = text.lower()
    for word in (
        "along",
        "parallel to",
        "perpendicular to",
        "normal to",
        "at right angles to",
        "square to",
    ):
        if low == word or low.startswith(word + " "):
            break
    else:
        m = _AT.fullmatch(text)
        if not m or m.group(3).lower() in ("x", "horizontal", "vertical"):
            return None
        size, s1, name, s2 = m.groups()
        if s1 and s2:
            raise SceneError(f"'{raw.strip()}' gives two senses: give one, cw or ccw")
        sense = (s1 or s2 or "").lower()
        pts = split_name(name)
        if len(pts) != 2:  # (no link: "from IDC", "from M": an angle's words, or none)
            return None
        if not sense:
            raise SceneError(
                f"'{raw.strip()}' does not say which side of {name} the force is: "
                f"write '{size} deg ccw from {name}' or '{size} deg cw from {name}'"
            )
        off = _SENSE[sense] * math.radians(float(size))
        return (*pts, off, raw.strip())
    m = _ALONG.fullmatch(text) or _ACROSS.fullmatch(text)
    pts = split_name(m.group(1)) if m else ()
    if pts:
        _two_points(raw, m.group(1), pts)
    if not pts:
        raise SceneError(
            f"cannot read '{raw.strip()}' as a direction against a link: write e.g. "
            "'along CD' (from C towards D), 'perpendicular to CD, ccw' (C->D turned "
            "90 deg ccw) or '30 deg ccw from CD'"
        )
    if m.re is _ALONG:
        return (*pts, 0.0, raw.strip())
    sense = (m.group(2) or "").lower()
    return (*pts, _SENSE[sense] * math.pi / 2 if sense else None, raw.strip())


def _two_points(raw, name, pts) -> None:
    """A link named by its two points: 'along M' (a point) or 'along CDE' (a plate) names
    no direction (it was read as the link 'M0.0')."""
    if len(pts) != 2:
        raise SceneError(
            f"'{raw.strip()}': {name} is not a link's two points: name the link whose "
            "direction the force takes, e.g. 'along CD' (from C towards D)"
        )


def _words_of(deg: float) -> str:
    """'up and to the left' for a direction at ``deg`` (from +x, ccw, in [0, 360))."""
    v = "up" if 0 < deg < 180 else "down" if deg > 180 else ""
    h = "to the right" if deg < 90 or deg > 270 else "to the left" if 90 < deg < 270 else ""
    return " and ".join(w for w in (v, h) if w)


def link_angle(across, P):
    """The direction (rad) of the load stated ``across`` (its link's first -> second point,
    turned by its offset) at the positions ``P``: floats at one instant, arrays over a
    sweep. An ambiguous "perpendicular to CD" (no sense) is refused, saying which way
    each sense points here."""
    a, b, off, words = across[:4]
    (ax, ay), (bx, by) = P[a], P[b]
    base = np.arctan2(by - ay, bx - ax)
    if off is None:
        if np.ndim(base):
            base = base.flat[0]
        said = []
        for s, k in (("ccw", 1.0), ("cw", -1.0)):
            deg = math.degrees(float(base) + k * math.pi / 2) % 360
            said.append(f"{s}: {_words_of(deg)}, at {deg:.1f} deg")
        raise SceneError(
            f"'{words}' does not say which side of {a}{b} the force points: add ', ccw' "
            f"or ', cw' ({a}->{b} turned 90 deg; here {'; '.join(said)})"
        )
    return base + off


def load_force(ld, P):
    """The force of load ``ld`` (N, (Fx, Fy)) at the positions ``P``: its stated vector,
    or, for a direction stated against a link, its size along the link's direction there
    plus the stated angle (floats at one instant, arrays over a sweep)."""
    if ld.across is None:
        return ld.force
    ang = link_angle(ld.across, P)
    mag = ld.across[4]
    if np.ndim(ang):
        return (mag * np.cos(ang), mag * np.sin(ang))
    ux, uy = _unit_at(float(ang))  # (exact along the axes, as a plain angle is)
    return (mag * ux, mag * uy)


def across_words(ld) -> str:
    """'500 N perpendicular to CD, ccw (at 123.4 deg now)': the load's direction as
    stated and its angle at the scene's instant (its force, completed when compiled)."""
    said = f"{fmt(ld.across[4])} N {ld.across[3]}"
    if ld.force is None:
        return said
    return f"{said} (at {fmt(math.degrees(math.atan2(ld.force[1], ld.force[0])) % 360)} deg now)"


def loads_dict(loads, P) -> dict:
    """``solve --json``'s ``loads`` (none without loads): each load by its target, a force
    as ``force`` [Fx, Fy] (N) and its ``direction`` (deg ccw from +x, in [0, 360)) at the
    instant, one stated against a link adding ``against`` (its two points, the direction
    first -> second), ``offset`` (deg ccw from it) and ``stated`` (the words); a torque
    as ``torque`` (N m, ccw +)."""
    out = {}
    for ld in loads:
        if ld.torque is not None:
            out[ld.target] = {"torque": ld.torque}
            continue
        f = ld.force if ld.across is None else load_force(ld, P)
        if f is None:
            continue
        fx, fy = float(f[0]) + 0.0, float(f[1]) + 0.0
        entry = {"force": [fx, fy], "direction": _degrees(fx, fy)}
        if ld.across is not None:
            a, b, off, words = ld.across[:4]
            entry |= {"against": [a, b], "offset": math.degrees(off), "stated": words}
        out[ld.target] = entry
    return {"loads": out} if out else {}


def direction_columns(loads, P) -> list:
    """``sweep``'s columns of the loads stated against a link: ``load_dir_M`` (deg ccw from
    +x, in [0, 360)), the direction at every row as the force analysis takes it."""
    return [
        (f"load_dir_{ld.target}", "deg", np.degrees(link_angle(ld.across, P)) % 360.0)
        for ld in loads
        if ld.across is not None and ld.torque is None
    ]


def _degrees(fx, fy) -> float:
    """A force's direction in degrees ccw from +x, in [0, 360) (0 for no force)."""
    return math.degrees(math.atan2(fy, fx)) % 360.0 + 0.0
