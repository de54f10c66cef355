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
as a default taken. With a module both gears are toothed: the one whose teeth the entry
leaves out has 2 r / m of the radius the scene fixes for it (its link or ``radius``, the
gear's ``on_radius``, else the centre distance less the wheel's), taken and said where
that is a whole number, refused where it is not. The gear a wheel meshes with is then
named by its teeth, as a book names it (:func:`gear_label`)."""

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
    """The module the [rolling] table states once for all its gears: (m in metres, words,
    the diametral pitch or None) or None."""
    raw = rd.raw["rolling"]
    said = next((k for k in TABLE_KEYS if k in raw), "module")  # the key a refusal names
    return _module(rd, {k: raw[k] for k in TABLE_KEYS if k in raw}, said)


def _module(rd, spec, key):
    """(m metres, how it was said, the diametral pitch P or None) from ``module`` or
    ``diametral_pitch`` in ``spec``, or None."""
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
        return m, f"module {m * 1e3:g} mm", None
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
        words = f"diametral pitch {p:g} per inch (module 25.4 / P = {25.4 / p:.6g} mm)"
        return _INCH / p, words, p
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
            add = "on_teeth = z (its pinion's)" if pair.on == "rack" else "teeth = z"
            raise rd.error(f"a module with no teeth: add {add}", "rolling", key)
        if not _meshes_teeth(spec, pair, out, scene_module):
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
        m, words, P = mod
        made = []  # the teeth made whole from a radius, where the entry states none
        if z is None and pair.on != "rack":  # the wheel's own, from its stated radius
            r0, said = _own_radius(rd, key, spec, link)
            z = _whole(rd, key, r0, mod, said, "teeth = z")
            made.append(f"{said}: {z} teeth")
        if zo is None:
            R0, said, alt = _gear_radius(
                rd, pair, ground, None if z is None else m * z / 2, "on_radius" in spec
            )
            if R0 is not None:
                zo = _whole(rd, key, R0, mod, said, "on_teeth = z", alt)
                made.append(f"{said}: {zo} teeth")
        r = None if z is None else m * z / 2
        R = None if zo is None else m * zo / 2
        sums = [(t, x) for t, x in ((z, r), (zo, R)) if t]
        note = (
            f"[rolling] {key}: {words}: pitch radius {formula(m, P)[0]} = "
            + " and ".join(f"{formula(m, P, t)[1]} = {_say(rd, x)}" for t, x in sums)
            + "".join(f"; {x}" for x in made)
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
        teeth=(z, zo) + ((None, None) if mod is None else mod[::2]),
        label=pair.label if zo is None else gear_label(pair, zo, out),
    )


def _meshes_teeth(spec, pair, out, module):
    """Whether a wheel whose entry names no teeth is a gear all the same: the table's
    module given and the gear it meshes with an earlier wheel given by its teeth (an
    annulus on a toothed planet: its teeth are then its radius's)."""
    if module is None or pair.on != "gear" or pair.grip is not None or "on_radius" in spec:
        return False
    return any(r.wheel == pair.base and r.teeth and r.teeth[0] for r in out)


def gear_label(pair, zo, out=()):
    """The gear (or fixed circle) a wheel meshes with, by its ``zo`` teeth, as a book says
    it: ``the sun of 40 teeth about O``, ``the fixed annulus of 88 teeth about O``, ``the
    gear O1-A of 20 teeth``, ``the ring gear O-Q of 88 teeth`` (the wheel inside it), ``the
    planet AP of 24 teeth`` (a wheel of ``out``, the pairs read before, on a fixed circle),
    ``the gear of 15 teeth keyed to the gear O2-B`` (a second gear on a wheel's shaft: a
    compound train), ``the pinion O1-A of 20 teeth`` (a rack's)."""
    if pair.on == "circle":
        what = "fixed annulus" if pair.inside else "sun"
        return f"the {what} of {zo} teeth about {pair.base_centre}"
    if pair.on == "rack":
        return f"the pinion {pair.base} of {zo} teeth"
    base = next((r for r in out if r.wheel == pair.base), None)
    what = "planet" if base is not None and base.on == "circle" else "gear"
    if pair.inside and not pair.ring:
        what = "ring gear"
    if base is not None and base.teeth and base.teeth[0] not in (None, zo):
        return f"the gear of {zo} teeth keyed to the {what} {pair.base}"
    return f"the {what} {pair.base} of {zo} teeth"


def _own_radius(rd, key, spec, link):
    """(r, words): the wheel's pitch radius as the scene states it, ``radius`` or else its
    link's length."""
    if "radius" in spec:
        r = rd.length(spec["radius"], "rolling", key)
        return r, f"{link.key}'s radius {_say(rd, r)}"
    return link.length, f"{link.key}'s radius {_say(rd, link.length)} (the link {link.key})"


def _gear_radius(rd, pair, ground, r, on_radius):
    """(R, words, alt) of the gear (or fixed circle) a wheel meshes with where the entry
    gives no ``on_teeth``: its ``on_radius`` (or the earlier wheel's radius), else the
    centre distance where the scene fixes it (two fixed centres, or the link joining them)
    less (inside: plus) the wheel's ``r``, as the contact makes it; ``alt(zf)`` the centre
    distances whole teeth would need. (None, None, None) where neither is known before the
    mechanism is placed."""
    what = _gear_words(pair)
    if pair.base_radius is not None:
        said = "on_radius" if on_radius else f"the gear {pair.base}'s radius"
        return pair.base_radius, f"{said} {_say(rd, pair.base_radius)}", None
    d, arm = _centre_distance(rd, pair, ground)
    if d is None or r is None:
        return None, None, None
    sign = -1 if pair.ring else 1 if pair.inside else 0  # R = d - r, d + r, r - d
    R = r - d if sign < 0 else d + r if sign > 0 else d - r
    if R <= 0:
        return None, None, None  # (the step refuses it: the wheel cannot reach)
    if sign < 0:  # the wheel a ring about the gear inside it
        how = f"{pair.wheel}'s {_say(rd, r)} less {arm} = {_say(rd, d)}"
    else:
        how = f"{arm} = {_say(rd, d)} {'plus' if sign > 0 else 'less'} {pair.wheel}'s {_say(rd, r)}"
    words = (
        f"{what} has no on_teeth or on_radius: its pitch radius from the centre distance, "
        f"{how} = {_say(rd, R)}"
    )

    def alt(zf):
        """The centre distances that would make the gear's teeth the whole numbers either
        side of ``zf``."""
        ds = ((t, R * t / zf) for t in (math.floor(zf), math.ceil(zf)) if t >= 1)
        ok = [
            f"{_say(rd, d)} ({t} teeth)"
            for t, Rt in ds
            for d in [r - Rt if sign < 0 else Rt - r if sign > 0 else Rt + r]
            if d > 0
        ]
        return f", or make {arm} " + " or ".join(ok) if ok else ""

    return R, words, alt


def _centre_distance(rd, pair, ground):
    """(d, its name) of the wheel's centre and its gear's where the scene fixes it before
    the mechanism is placed (two fixed points, or a link joining them), else (None, None)."""
    a, b = pair.centre, pair.base_centre
    if a is None or b is None:
        return None, None
    if a in ground and b in ground:
        return math.dist(ground[a], ground[b]), f"{b}{a}"
    arm = rd.index.get(frozenset((a, b)))
    return (None, None) if arm is None else (arm.length, arm.key)


def _gear_words(pair):
    """The gear a wheel meshes with, in words: ``the sun about O``, ``the fixed annulus
    about O``, ``the gear O1-A``."""
    if pair.on == "circle":
        return f"the {'fixed annulus' if pair.inside else 'sun'} about {pair.base_centre}"
    return f"the {'pinion' if pair.on == 'rack' else 'gear'} {pair.base}"


def placed_teeth(pr, R, d, say):
    """(z, words) of the gear a wheel of pair ``pr`` (given by its teeth and a module)
    meshes with, where the entry states neither its teeth nor its radius and the centre
    distance ``d`` is known only once the mechanism is placed (a planet on a coupler's
    point): ``R`` its pitch radius from it, ``say`` writes a length. ``z`` is None where
    2 R / m is no whole number: the words are then the refusal's, else the note's."""
    m, P = pr.teeth[2:]
    zf = 2 * R / m
    z = round(zf)
    how = (
        f"{_gear_words(pr)} has no on_teeth or on_radius: its pitch radius from the centre "
        f"distance {pr.base_centre}{pr.centre} = {say(d)} at the stated instant, "
        f"{say(R)}: {zf:.6g} teeth of "
        + (f"module {m * 1e3:.6g} mm" if P is None else f"diametral pitch {P:g} per inch")
    )
    if z >= 1 and abs(zf - z) <= SAME * zf:
        return z, f"[rolling] {pr.wheel}: {how.replace(f'{zf:.6g} teeth', f'{z} teeth')}"
    return None, f"{how} (the pitch diameter over the module), not a whole number: give on_teeth"


def _whole(rd, key, x, mod, said, give, alt=None):
    """The whole number of teeth a pitch radius ``x`` makes with the module: 2 x / m,
    refused where it is not whole (to :data:`SAME` of it), naming what to give."""
    m, words = mod[:2]
    zf = 2 * x / m
    z = round(zf)
    if z >= 1 and abs(zf - z) <= SAME * zf:
        return z
    raise rd.error(
        f"{said}: {zf:.6g} teeth of {words} (the pitch diameter over the module), not a "
        f"whole number: give {give}" + ("" if alt is None else alt(zf)),
        "rolling",
        key,
    )


def _from_centres(rd, key, pair, ground, z, zo):
    """(r, R, note) without a module: the teeth's ratio and the centre distance (two fixed
    centres, or the link joining them, the arm) fix the pitch radii."""
    if pair.on == "rack":  # its pinion's teeth make its pitch radius only with a module
        raise rd.error(
            'the module not given: give module = "4 mm" (or diametral_pitch) with the '
            "pinion's on_teeth, or on_radius instead",
            "rolling",
            key,
        )
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
    z, zo, m, P = teeth
    if m is None:
        return f"{z} teeth, pitch radius from the centre distance and the teeth {L(r)}"
    return f"{z} teeth, pitch radius {' = '.join(formula(m, P, z))} = {L(r)}"


def formula(m, P, z=None):
    """(the pitch radius's formula, its figures for ``z`` teeth): ``("m z / 2", "4 x 50 /
    2")``, the module in mm as a book quotes it; a US book's ``("z / (2 P)", "50 / (2 x
    10)")`` where the diametral pitch ``P`` gave it.

    >>> formula(0.004, None, 50), formula(0.00254, 10, 50)
    (('m z / 2', '4 x 50 / 2'), ('z / (2 P)', '50 / (2 x 10)'))
    """
    if P is not None:
        return "z / (2 P)", f"{z} / (2 x {P:g})"
    return "m z / 2", f"{m * 1e3:.6g} x {z} / 2"


def teeth_records(rolling):
    """The JSON's teeth of each gear given by them, by its link: ``{"teeth": {"teeth": z,
    "on_teeth": z_o, "module": m (m) or null}}``, and ``diametral_pitch`` (per inch) where
    a US book's gave the module."""
    return {
        r.wheel: {
            "teeth": dict(zip(("teeth", "on_teeth", "module"), r.teeth))
            | ({} if r.teeth[3] is None else {"diametral_pitch": r.teeth[3]})
        }
        for r in rolling
        if r.teeth
    }
