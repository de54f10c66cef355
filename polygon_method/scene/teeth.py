"""Gears given by their teeth (a part of the [rolling] reader): ``teeth = 20`` on a gear,
``on_teeth = 15`` for the gear it meshes with, and the module (``module = "4 mm"``; a bare
number is in mm, as the module always is) or the diametral pitch (``diametral_pitch = 10``,
teeth per inch of pitch diameter, US books) in the entry or once for the whole table::

    [rolling]
    module = "4 mm"
    "O2-B" = { on = "O1-A", teeth = 60, on_teeth = 20 }

The pitch radius is m z / 2 (z / (2 P)); a ``radius`` (else the link's length: the point on
the pitch circle) or ``on_radius`` stated too must agree. Without a module the teeth fix
the ratio of the radii, and the centre distance (two fixed centres, or the arm joining
them) fixes the radii: r = d z / (z + z_o) outside, d z / (z_o - z) inside a ring, said
as a default taken."""

from __future__ import annotations

import math
from dataclasses import replace

from ..common.tolerances import SAME
from .records import _ABSURD_LONG as ABSURD_LONG
from .records import _ABSURD_SHORT as ABSURD_SHORT

#: the keys this module reads, in an entry of [rolling]
TEETH_KEYS = ("teeth", "on_teeth", "module", "diametral_pitch")
#: the keys it reads once for the whole table (a value that is no wheel's table)
TABLE_KEYS = ("module", "diametral_pitch")
_INCH = 0.0254


def table_module(rd):
    """The module the [rolling] table states once for all its gears: (m in metres, words)
    or None."""
    raw = rd.raw["rolling"]
    said = next((k for k in TABLE_KEYS if k in raw), "module")  # the key a refusal names
    return _module(rd, {k: raw[k] for k in TABLE_KEYS if k in raw}, said)


def _module(rd, spec, key):
    """(m metres, how it was said) from ``module`` or ``diametral_pitch`` in ``spec``, or
    None."""
    if "module" in spec and "diametral_pitch" in spec:
        raise rd.error(
            "module and diametral_pitch both given: keep one (module = 25.4 / P mm)",
            "rolling",
            key,
        )
    if "module" in spec:
        raw = spec["module"]
        if isinstance(raw, bool):
            raise rd.error(f'module = {str(raw).lower()}: a length, e.g. "4 mm"', "rolling", key)
        m = rd.qty(raw, "length", "rolling", key, default_unit="mm").value
        if not 0 < m < math.inf:
            raise rd.error(f"module = {raw!r}: a length above 0", "rolling", key)
        _sized(rd, m, f"module = {raw!r}", key)
        return m, f"module {m * 1e3:g} mm"
    if "diametral_pitch" in spec:
        p = spec["diametral_pitch"]
        if isinstance(p, bool) or not isinstance(p, (int, float)) or not 0 < p < math.inf:
            raise rd.error(
                f"diametral_pitch = {p!r}: teeth per inch of pitch diameter, a bare number above 0 "
                "(diametral_pitch = 10)",
                "rolling",
                key,
            )
        _sized(rd, _INCH / p, f"diametral_pitch = {p!r}", key)
        return _INCH / p, f"diametral pitch {p:g} per inch (module 25.4 / P = {25.4 / p:.6g} mm)"
    return None


def _sized(rd, m, said, key):
    """Refused where a module (m) would make a gear no mechanism has: a tooth below the
    shortest length a scene may state, or one longer than the longest."""
    if not ABSURD_SHORT <= m <= ABSURD_LONG:
        raise rd.error(
            f"{said}: a module of {m:g} m is absurd for a gear; check the units", "rolling", key
        )


def _count(rd, spec, name, key):
    """The whole number of teeth ``spec[name]`` states, or None."""
    if name not in spec:
        return None
    z = spec[name]
    if isinstance(z, bool) or not isinstance(z, int) or z < 1:
        raise rd.error(
            f"{name} = {str(z).lower() if isinstance(z, bool) else repr(z)}: a gear's teeth "
            "are a whole number above 0",
            "rolling",
            key,
        )
    return z


def apply_teeth(rd, key, spec, pair, link, out, table):
    """``pair`` (a :class:`RollingPair` as read) with its pitch radii from the teeth its
    entry states (``radius``, ``base_radius`` and ``teeth`` = (z, z of the gear, m or None));
    unchanged where it states none. ``out``: the pairs read before; ``table``: the
    table's module (m, words) or None, and the ground points."""
    scene_module, ground = table
    z, zo = _count(rd, spec, "teeth", key), _count(rd, spec, "on_teeth", key)
    own = _module(rd, spec, key)
    if z is None and zo is None:
        if own is not None:
            raise rd.error("a module with no teeth: add teeth = z", "rolling", key)
        return pair
    if pair.on == "line":
        raise rd.error(
            "a wheel on a line grips by friction: it has no teeth (a rack is a block of "
            "[sliders] meshing with a pinion)",
            "rolling",
            key,
        )
    if pair.grip is not None:
        raise rd.error("preload: a friction drive has no teeth (remove one)", "rolling", key)
    if pair.on == "rack" and z is not None:
        raise rd.error("teeth: a rack's are not counted; on_teeth is its pinion's", "rolling", key)
    if zo is None and pair.on == "gear" and "on_radius" not in spec:  # the gear's own teeth
        zo = next((r.teeth[0] for r in out if r.wheel == pair.base and r.teeth), None)
    mod = own or scene_module
    if mod is not None:
        m, words = mod
        r = None if z is None else m * z / 2
        R = None if zo is None else m * zo / 2
        note = f"[rolling] {key}: {words}: pitch radius m z / 2 = " + " and ".join(
            f"{m * 1e3:.6g} x {t} / 2 = {_say(rd, x)}" for t, x in ((z, r), (zo, R)) if t
        )
    else:
        r, R, note = _from_centres(rd, key, pair, ground, z, zo)
    how = "the centre distance's share" if mod is None else mod[1]
    if r is not None:
        stated = rd.length(spec["radius"], "rolling", key) if "radius" in spec else link.length
        said = "radius" if "radius" in spec else f"the link {link.key}"
        _agree(rd, key, said, stated, r, f"teeth = {z} ({how})")
    if R is not None and pair.base_radius is not None:
        said = "on_radius" if "on_radius" in spec else f"the gear {pair.base}'s radius"
        _agree(rd, key, said, pair.base_radius, R, f"{zo} teeth ({how})")
    rd.read_notes.append(note)
    return replace(
        pair,
        radius=pair.radius if r is None else r,
        base_radius=pair.base_radius if R is None else R,
        teeth=(z, zo, None if mod is None else mod[0]),
    )


def _from_centres(rd, key, pair, ground, z, zo):
    """(r, R, note) without a module: the teeth's ratio and the centre distance (two fixed
    centres, or the link joining them, the arm) fix the pitch radii."""
    if z is None or zo is None or pair.on not in ("gear", "circle"):
        raise rd.error(
            'the module not given: give module = "4 mm" (or diametral_pitch), or the '
            "teeth of both gears (teeth and on_teeth) with their centres a known distance "
            "apart",
            "rolling",
            key,
        )
    a, b = pair.centre, pair.base_centre
    arm = rd.index.get(frozenset((a, b)))
    if a in ground and b in ground:
        d = math.dist(ground[a], ground[b])
    elif arm is not None:
        d = arm.length
    else:
        raise rd.error(
            f"the module not given and the centres {a} and {b} are not a known distance "
            'apart (two fixed points, or a link joining them): give module = "4 mm"',
            "rolling",
            key,
        )
    sign = -1 if pair.ring else 1 if pair.inside else 0
    den = z + zo if sign == 0 else (zo - z) * sign
    if den <= 0:
        raise rd.error(
            f"teeth = {z}, on_teeth = {zo}: a ring has more teeth than the gear inside it",
            "rolling",
            key,
        )
    r, R = d * z / den, d * zo / den
    note = (
        f"[rolling] {key}: the module not given: the pitch radii from the centre distance "
        f"{a}{b} = {_say(rd, d)} and the teeth ({z} and {zo}), {_say(rd, r)} and {_say(rd, R)}"
    )
    return r, R, note


def _agree(rd, key, said, stated, want, teeth):
    """Refused where a radius stated beside the teeth is not theirs."""
    if abs(stated - want) > SAME * max(stated, want):
        raise rd.error(
            f"{said} is {_say(rd, stated)} but {teeth} make the pitch radius {_say(rd, want)}"
            + (" (a point off the pitch circle: state radius as well)" if "link" in said else ""),
            "rolling",
            key,
        )


def _say(rd, x):
    return f"{x / rd.scale():.6g} {rd.unit}"


def pitch_words(teeth, r, L):
    """The step table's words for a wheel's pitch radius: ``radius m z / 2 = ...`` where
    the scene gives it by its teeth (``L`` formats a length), else ``radius ...``."""
    if not teeth or teeth[0] is None:
        return f"radius {L(r)}"
    z, zo, m = teeth
    if m is None:
        return f"{z} teeth, pitch radius from the centre distance and the teeth {L(r)}"
    return f"{z} teeth, pitch radius m z / 2 = {m * 1e3:.6g} x {z} / 2 = {L(r)}"


def teeth_records(rolling):
    """The JSON's teeth of each gear given by them, by its link: ``{"teeth": {"teeth": z,
    "on_teeth": z_o, "module": m (m) or null}}``."""
    return {
        r.wheel: {"teeth": dict(zip(("teeth", "on_teeth", "module"), r.teeth))}
        for r in rolling
        if r.teeth
    }
