"""The scene's [rolling] table: wheels and gears rolling without slip (a part of the scene
reader).

Each key is a wheel's link, written centre first (``CP``: centre C, P a point on the
wheel); its value says what the wheel rolls on::

    CP = { on = "horizontal", through = [0, 0] }   # a fixed line (or "vertical", "30 deg")
    "A-P" = { on = "O" }                            # outside a fixed circle about O (a sun)
    "A-P" = { on = "O", inside = true }             # inside a fixed ring about O
    "O2-Q" = { on = "O1-A" }                        # a gear meshing with gear O1-A
    "O-S" = { on = "C-B", on_radius = 30 }          # a gear about O driven by a gear fixed
                                                    # to link CB, centred at C (Watt's sun
                                                    # and planet)
    "O-Q" = { on = "A-P", ring = true }             # a ring (internal gear) about O driven
                                                    # by the planet A-P inside it

``radius`` is the wheel's rolling (pitch) radius (default: its link's length, the point
on the pitch circle); ``on_radius`` the circle's, when the problem states it (it must then
agree with the centre distance); ``angle`` the direction centre -> point at the stated
crank angle (default: towards the contact point); ``side`` which side of a line the wheel
is on (``above`` by default, ``right`` of a vertical line). ``pressure_angle`` (a gear, a
planet on a circle, a rack): the teeth's pressure angle, which sets the tooth load's line
of action in the force analysis (default 20 deg; 0 for a tangential force alone).
``preload`` (a circle or a gear): a friction drive, the wheels pressed together with this
force and gripping by friction (no teeth); ``friction``: the coefficient at the contact (a
line's wheel too), whether it slips (:func:`_grip`).
"""

from __future__ import annotations

import math
import re


from ..common.tolerances import ROUNDING
from .records import RollingPair, split_name
from .teeth import TABLE_KEYS, TEETH_KEYS, apply_teeth, table_module

_KEYS = (
    "on",
    "through",
    "radius",
    "on_radius",
    "inside",
    "angle",
    "side",
    "ring",
    "pressure_angle",
    "preload",
    "friction",
    *TEETH_KEYS,
)
_SIDES = ("above", "below", "left", "right")


def _unit_at(ang):
    q = ang / (math.pi / 2)
    k = round(q)
    if abs(q - k) <= ROUNDING:
        return ((1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0))[k % 4]
    return (math.cos(ang), math.sin(ang))


def _pressure_angle(rd, spec, key):
    """The teeth's pressure angle (rad) the pair states (or the table once for all its
    teeth: ``[rolling] pressure_angle = 14.5``), or None (the default, 20 deg); from 0 up to
    45 deg."""
    if "pressure_angle" not in spec:
        table = rd.raw.get("rolling", {})
        once = table.get("pressure_angle")  # stated once for all the table's teeth
        if once is None or isinstance(once, dict) or "preload" in spec or "friction" in spec:
            return None
        spec, key = {"pressure_angle": once}, "pressure_angle"
    a = rd.qty(spec["pressure_angle"], "angle", "rolling", key, default_unit="deg").value
    if not 0.0 <= a <= math.pi / 4 + ROUNDING:
        raise rd.error(
            f"pressure_angle = {spec['pressure_angle']!r}: from 0 to 45 deg (the "
            "teeth's angle, 20 deg by default)",
            "rolling",
            key,
        )
    return a


def _grip(rd, spec, key, line):
    """A friction drive's (preload N or None, friction coefficient or None), or None where
    the pair states neither: on a line mu alone (the statics give the ground's push), on a
    circle or a gear the preload (and mu), never with teeth."""
    if "preload" not in spec and "friction" not in spec:
        return None
    mu = spec.get("friction")
    if mu is not None and (
        isinstance(mu, bool) or not isinstance(mu, (int, float)) or not 0 < mu < 1
    ):
        raise rd.error(
            f"friction = {str(mu).lower() if isinstance(mu, bool) else repr(mu)}: the "
            "coefficient of friction at the contact, a number "
            "above 0 and below 1",
            "rolling",
            key,
        )
    if line:
        if "preload" in spec:
            raise rd.error(
                "preload: a wheel on a line is pressed on it by the mechanism's own forces "
                "(the statics give the ground's push): remove preload (friction = mu alone "
                "says whether it slips)",
                "rolling",
                key,
            )
        return (None, float(mu))
    if "preload" not in spec:
        raise rd.error(
            "friction: two wheels held at their centres grip only as hard as they are "
            'pressed together: give the force pressing them, preload = "500 N"',
            "rolling",
            key,
        )
    if "pressure_angle" in spec:
        raise rd.error(
            "preload: wheels pressed together grip by friction and have no teeth: "
            "remove pressure_angle (or preload, for gears)",
            "rolling",
            key,
        )
    p = rd.qty(spec["preload"], "force", "rolling", key, default_unit="N").value
    if not 0 < p < math.inf:
        raise rd.error(
            f"preload = {spec['preload']!r}: the force pressing the wheels together, above 0",
            "rolling",
            key,
        )
    return (p, None if mu is None else float(mu))


def _rack(rd, key, spec, ground, sliders, _suggest):
    """``R = { on = "O-A" }``: the block R on a fixed path is a rack, its pitch line the
    path, meshing with the gear O-A; the path's ``through`` is where R is at the stated
    crank angle."""
    sl = next((s for s in sliders if s.point == key), None)
    if sl is None or getattr(sl, "u", None) is None:
        raise rd.error(
            f"a rack is a block on a fixed path: add {key} to [sliders] with path "
            "and through (where the rack's point is at the instant shown)",
            "rolling",
            key,
        )
    if sl.through[1] is None:
        raise rd.error(
            f"the rack {key} needs its place: through = [x, y] in [sliders] (where "
            "its point is at the instant shown)",
            "rolling",
            key,
        )
    rack_keys = ("on", "on_radius", "on_teeth", "module", "diametral_pitch", "pressure_angle")
    for k in spec:
        if k not in rack_keys:
            raise rd.error(
                f"unknown key '{k}' for a rack"
                f"{_suggest(k, rack_keys)}; a rack has "
                "on (its pinion), on_radius (or on_teeth and module) and pressure_angle",
                "rolling",
                key,
            )
    if "on" not in spec:
        raise rd.error(
            f'the rack {key} has no pinion: add on = "O-A" (a gear turning about a ground point)',
            "rolling",
            key,
        )
    base, bpts = rd.find_link(spec["on"], "rolling", key)
    fixed = [p for p in bpts if p in ground]
    if len(fixed) != 1:
        raise rd.error(
            f"the pinion {base.key} must turn about a fixed centre: one of its ends a ground point",
            "rolling",
            key,
        )
    return RollingPair(
        key,
        None,
        key,
        0.0,
        "rack",
        f"the pinion {base.key}",
        base=base.key,
        base_centre=fixed[0],
        base_radius=(rd.length(spec["on_radius"], "rolling", key) if "on_radius" in spec else None),
        pressure_angle=_pressure_angle(rd, spec, key),
    )


def read_rolling(rd, ground, sliders, points) -> list:
    """The [rolling] table's pairs, checked (``rd`` is the scene reader)."""
    if "rolling" not in rd.raw:  # (the usual scene: nothing to import or check)
        return []
    from .table_help import _suggest  # the reader's own did-you-mean

    out = []
    wheels = set()
    module = table_module(rd)  # the table's module = "4 mm", for every gear in it
    for key, spec in rd.table("rolling").items():
        if key in TABLE_KEYS + ("pressure_angle",) and not isinstance(spec, dict):
            continue
        if not isinstance(spec, dict):
            raise rd.error(_EXAMPLE, "rolling", key)
        for k in spec:
            if k not in _KEYS:
                raise rd.error(f"unknown key '{k}'{_suggest(k, _KEYS)}", "rolling", key)
        if len(split_name(key)) == 1:  # a rack: a block on a fixed path, on a pinion
            pair = _rack(rd, key, spec, ground, sliders, _suggest)
            out.append(apply_teeth(rd, key, spec, pair, None, out, (module, ground)))
            continue
        link, pts = rd.find_link(key, "rolling", key)
        if link.key in wheels:
            raise rd.error(f"wheel {link.key} is named twice", "rolling", key)
        wheels.add(link.key)
        pair = _wheel(rd, key, spec, (link, pts), (ground, sliders, points), out, _suggest)
        out.append(apply_teeth(rd, key, spec, pair, link, out, (module, ground)))
    return out


#: the forms of a rolling wheel's table, for a message
_EXAMPLE = (
    'a rolling wheel is a table: { on = "horizontal", through = [0, 0] } '
    '(a ground line), { on = "O" } (a fixed circle about O) or { on = '
    '"O1-A" } (a gear)'
)


def _wheel(rd, key, spec, named, scene, out, _suggest):
    """One wheel's :class:`RollingPair`: its link ``named`` (link, points: centre first),
    rolling on a ground line, a fixed circle or a gear (``out``: the pairs read before)."""
    (link, (centre, rim)), (ground, sliders, points) = named, scene
    _free_rim(rd, key, spec, (centre, rim), ground, sliders, points)
    radius = rd.length(spec["radius"], "rolling", key) if "radius" in spec else link.length
    inside = spec.get("inside", False)
    if not isinstance(inside, bool):
        raise rd.error("inside = true or false", "rolling", key)
    ring = spec.get("ring", False)
    if not isinstance(ring, bool):
        raise rd.error("ring = true or false", "rolling", key)
    if ring and inside:
        raise rd.error(
            "ring = true: the wheel is the ring and the gear it meshes with is "
            "inside it; inside = true says the opposite (keep one)",
            "rolling",
            key,
        )
    angle = (
        rd.qty(spec["angle"], "angle", "rolling", key, default_unit="deg").value
        if "angle" in spec
        else None
    )
    on = spec["on"]
    if not isinstance(on, str):
        raise rd.error(f"on = {on!r}: " + _EXAMPLE[_EXAMPLE.index("{") :], "rolling", key)
    line = on in ("horizontal", "vertical") or re.match(r"^\s*[-+.\d]", on)
    if ring and (line or on in ground):
        raise rd.error(
            f"ring = true: a ring meshes with a gear inside it (on = a gear's "
            f'link such as "A-P"), not with {"a line" if line else "a fixed circle"}',
            "rolling",
            key,
        )
    if line:
        return _on_line(
            rd, key, spec, link, (centre, rim), radius, angle, ground, sliders, _suggest
        )
    if "through" in spec or "side" in spec:
        raise rd.error(f"through/side belong to a line; on = {on!r} is a circle", "rolling", key)
    base_radius = rd.length(spec["on_radius"], "rolling", key) if "on_radius" in spec else None
    if on in ground:
        return RollingPair(
            link.key,
            centre,
            rim,
            radius,
            "circle",
            f"the fixed circle about {on}",
            base_centre=on,
            inside=inside,
            base_radius=base_radius,
            angle=angle,
            pressure_angle=_pressure_angle(rd, spec, key),
            grip=_grip(rd, spec, key, False),
        )
    wheel = (radius, angle, inside, ring, base_radius)
    return _on_gear(rd, key, spec, link, (centre, rim), wheel, ground, out, _suggest)


def _on_line(rd, key, spec, link, pts, radius, angle, ground, sliders, _suggest):
    """A wheel rolling on a ground line: its direction, a point of it, the wheel's side."""
    centre, rim = pts
    if "inside" in spec or "on_radius" in spec:
        raise rd.error("a line has no inside and no radius", "rolling", key)
    if "pressure_angle" in spec:
        raise rd.error(
            "a wheel on a line grips by friction: it has no teeth and no "
            "pressure angle (remove pressure_angle)",
            "rolling",
            key,
        )
    if "through" not in spec:
        raise rd.error(
            f"the ground line of wheel {key} needs a point: through = "
            "[x, y] or a ground point's name",
            "rolling",
            key,
        )
    u, through, label = _ground_line(rd, key, spec, ground, _suggest)
    m = _side(rd, key, spec, u, _suggest)
    if centre in ground:
        raise rd.error(
            f"the wheel's centre {centre} is a ground point: a wheel on a line rolls along it",
            "rolling",
            key,
        )
    if centre in {s.point for s in sliders}:
        raise rd.error(
            f"the wheel's centre {centre} moves along the line at the "
            "wheel's radius: remove its [sliders] entry",
            "rolling",
            key,
        )
    return RollingPair(
        link.key,
        centre,
        rim,
        radius,
        "line",
        label,
        u=u,
        through=through,
        m=m,
        angle=angle,
        grip=_grip(rd, spec, key, True),
    )


def _on_gear(rd, key, spec, link, pts, wheel, ground, out, _suggest):
    """A wheel in mesh with a gear (a link about its ground end, or fixed to a moving link),
    or a ring about the gear inside it; ``wheel``: its radius, angle, inside, ring and the
    gear's stated radius, as read."""
    centre, rim = pts
    on = spec["on"]
    radius, angle, inside, ring, base_radius = wheel
    if len(split_name(on)) != 2:
        raise rd.error(
            f"on = {on!r} is no line, ground point or gear (a link such as "
            '"O1-A")' + _suggest(on, list(ground) + ["horizontal", "vertical"]),
            "rolling",
            key,
        )
    base, bpts = rd.find_link(on, "rolling", key)
    fixed = [p for p in bpts if p in ground]
    if len(fixed) == 2:
        raise rd.error(
            f"the gear {base.key} is fixed (both its ends are ground points): "
            f'write on = "{fixed[0]}" for a fixed circle about {fixed[0]}',
            "rolling",
            key,
        )
    if base.key == link.key:
        raise rd.error("a wheel cannot roll on itself", "rolling", key)
    # a gear about its ground end; else fixed to a moving link, centred at its first
    # point as written (a planet fixed to a coupler: on = "C-B", centre C)
    gc = fixed[0] if fixed else bpts[0]
    if gc == centre:
        raise rd.error(
            f"the gear {base.key} and the wheel {link.key} have one centre "
            f"{centre}: gears in mesh have two",
            "rolling",
            key,
        )
    if ring and base_radius is None:  # the gear inside it a wheel: its pitch radius
        base_radius = next((r.radius for r in out if r.wheel == base.key), None)
    return RollingPair(
        link.key,
        centre,
        rim,
        radius,
        "gear",
        f"the gear {base.key}",
        base=base.key,
        base_centre=gc,
        inside=inside or ring,
        base_radius=base_radius,
        angle=angle,
        ring=ring,
        pressure_angle=_pressure_angle(rd, spec, key),
        grip=_grip(rd, spec, key, False),
    )


def _free_rim(rd, key, spec, pts, ground, sliders, points):
    """A wheel's table says what it rolls on, and its rim point (its link's second point)
    is a free joint: no ground point, carried point or slider."""
    centre, rim = pts
    if "on" not in spec:
        raise rd.error(
            f"the rolling wheel {key} has no ground line or circle: add on = "
            '"horizontal" with through = [x, y] (a line), on = "O" (a '
            'fixed circle about O) or on = "O1-A" (a gear)',
            "rolling",
            key,
        )
    if rim in ground:
        raise rd.error(
            f"{rim} is a ground point: write the wheel's link centre first, "
            f"then a point on the wheel ({rim}{centre}?)",
            "rolling",
            key,
        )
    if rim in points:
        raise rd.error(
            f"{rim} is a carried point: the wheel's link ends at a joint", "rolling", key
        )
    if rim in {s.point for s in sliders}:
        raise rd.error(
            f"{rim} slides on a guide and rolls with a wheel: one constraint too many",
            "rolling",
            key,
        )


def _ground_line(rd, key, spec, ground, _suggest):
    """(u, through, label): the ground line a wheel rolls on (``on``: horizontal, vertical
    or an angle), through a point or a ground point."""
    on = spec["on"]
    if on == "horizontal":
        ang, label = 0.0, "the horizontal line"
    elif on == "vertical":
        ang, label = math.pi / 2, "the vertical line"
    else:
        ang = rd.qty(on, "angle", "rolling", key, default_unit="deg").value
        label = f"the line at {math.degrees(ang):g} deg"
    through = spec["through"]
    if isinstance(through, str):
        if through not in ground:
            raise rd.error(
                f"through = {through!r} is not a ground point{_suggest(through, ground)}",
                "rolling",
                key,
            )
        through = ground[through]
    else:
        through = rd.coords(through, "rolling", key)
    return _unit_at(ang), through, label


def _side(rd, key, spec, u, _suggest):
    """The unit normal m from the line (along ``u``) towards the wheel's centre: on the
    ``side`` given, else above (right of a vertical line)."""
    side = spec.get("side")
    if side is not None and side not in _SIDES:
        raise rd.error(
            f"side = {side!r}: above, below, left or right{_suggest(str(side), _SIDES)}",
            "rolling",
            key,
        )
    m = (-u[1], u[0])
    vertical = abs(m[1]) <= ROUNDING
    want = side or ("right" if vertical else "above")
    axis, sign = {"above": (1, 1), "below": (1, -1), "right": (0, 1), "left": (0, -1)}[want]
    if abs(m[axis]) <= ROUNDING:
        raise rd.error(
            f"side = {want!r}: a {'vertical' if vertical else 'horizontal'}"
            f" line has {'a left and a right' if vertical else 'an above and a below'}",
            "rolling",
            key,
        )
    if m[axis] * sign < 0:
        m = (-m[0], -m[1])
    return m
