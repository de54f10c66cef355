"""The lengths a book never states, taken from the teeth (a part of the [links] reader).

A gear given by its teeth and a module (or a diametral pitch) in [rolling] may be left out
of [links]: its link (centre to a point on its pitch circle) is the pitch radius m z / 2.
An arm left out whose two ends are the centres of a meshing pair (a planet's centre and
its sun's, or its ring's) is the centre distance: r_sun + r_planet, or r_ring - r_planet.
Each length so taken is said among the notes."""

from __future__ import annotations

from ..common.tolerances import SAME
from .names import split_name
from .teeth import _agree, _count, _module, formula, table_module


def links_from_teeth(rd, index, ground):
    """[(key, p, q, length)]: the links [links] leaves out that the teeth fix (``index``:
    the stated links by their pair of points), each said in ``rd.read_notes``."""
    raw = rd.raw.get("rolling")
    if not isinstance(raw, dict):
        return []
    entries = [
        (k, s, split_name(k))
        for k, s in raw.items()
        if isinstance(s, dict) and len(split_name(k)) == 2
    ]
    table = table_module(rd) if entries else None
    radius, added = {}, []  # a wheel's pitch radius by its pair of points; the links taken
    for key, spec, pts in entries:
        pair, mod = frozenset(pts), _module(rd, spec, key) or table
        z = _count(rd, spec, "teeth", key)
        if "radius" in spec:
            radius[pair] = rd.length(spec["radius"], "rolling", key)
            if z is not None and mod is not None:  # checked before an arm is made of it
                _agree(rd, key, "radius", radius[pair], mod[0] * z / 2, f"teeth = {z} ({mod[1]})")
                if pair not in index:  # left out of [links]: its point on the pitch circle
                    added.append((key, *pts, radius[pair]))
                    rd.read_notes.append(
                        f"[links] {key} not given: its length the pitch radius, "
                        f"{_say(rd, radius[pair])}"
                    )
        elif pair in index:
            radius[pair] = index[pair].length
        elif z is not None and mod is not None:
            radius[pair] = mod[0] * z / 2
            added.append((key, *pts, radius[pair]))
            rd.read_notes.append(
                f"[links] {key} not given: its length the pitch radius from the teeth, "
                f"{' = '.join(formula(mod[0], mod[2], z))} = {_say(rd, radius[pair])}"
            )
        elif z is not None and (r := _by_centres(rd, key, spec, pts, (entries, index, ground))):
            radius[pair] = r
            added.append((key, *pts, r))
        elif z is not None:
            raise rd.error(
                f"no link {key} in [links] and no module to make its length from its "
                f'{z} teeth: give module = "4 mm" (or diametral_pitch), or {key} = its '
                "radius in [links]",
                "rolling",
                key,
            )
    racks = [(k, s, ()) for k, s in raw.items() if isinstance(s, dict) and len(split_name(k)) == 1]
    drivers = _drivers(rd, entries + racks, index, table)
    for key, p, q, r in drivers:
        radius[frozenset((p, q))] = r
    return _arms(rd, entries, (index, radius, table, ground)) + drivers + added


def _by_centres(rd, key, spec, pts, known):
    """A gear's pitch radius without a module (None where this does not fix it): its teeth
    z and its mate's z_o (``on_teeth``, or the teeth of the mate's own entry) in the ratio
    of the radii, and the distance d of the two centres (a stated arm joining them, or two
    fixed points): d z / (z + z_o) outside, d z / (z_o - z) inside a ring, d z / (z - z_o)
    for the ring itself; said in a note."""
    entries, index, ground = known
    on = spec.get("on")
    if not isinstance(on, str) or "module" in spec or "diametral_pitch" in spec:
        return None
    z = _count(rd, spec, "teeth", key)
    zo = _count(rd, spec, "on_teeth", key)
    mate = split_name(on)
    if zo is None:
        zo = next(
            (
                _count(rd, s, "teeth", k)
                for k, s, p in entries
                if frozenset(p) == frozenset(mate) and "teeth" in s
            ),
            None,
        )
    if z is None or zo is None or len(mate) not in (1, 2):
        return None
    a, b = pts[0], mate[0] if len(mate) == 1 else mate[0]
    if a in ground and b in ground:
        d = ((ground[a][0] - ground[b][0]) ** 2 + (ground[a][1] - ground[b][1]) ** 2) ** 0.5
    elif frozenset((a, b)) in index:
        d = index[frozenset((a, b))].length
    else:
        return None
    ring, inside = spec.get("ring") is True, spec.get("inside") is True
    den = z - zo if ring else zo - z if inside else z + zo
    if not den > 0 or not d > 0:
        return None
    r = d * z / den
    rd.read_notes.append(
        f"[links] {key} not given: its length the pitch radius, {_say(rd, r)} (the module "
        f"not given: from the centre distance {a}{b} and the teeth, d z / {den})"
    )
    return r


def _drivers(rd, entries, index, table):
    """The gears named only by ``on`` with ``on_teeth`` and a module (a driving gear with
    no [rolling] entry of its own, a rack's pinion), left out of [links]: (key, p, q, m z /
    2)."""
    wheels = {frozenset(split_name(k)) for k, _, _ in entries}
    out = {}
    for key, spec, _ in entries:
        on, mod = spec.get("on"), _module(rd, spec, key) or table
        pts = split_name(on) if isinstance(on, str) else ()
        pair = frozenset(pts)
        if len(pts) != 2 or pair in index or pair in wheels or pair in out or mod is None:
            continue
        zo = _count(rd, spec, "on_teeth", key)
        if zo is not None and "on_radius" not in spec:
            out[pair] = (on, *pts, mod[0] * zo / 2)
            rd.read_notes.append(
                f"[links] {on} not given: its length the pitch radius from the teeth, "
                f"{' = '.join(formula(mod[0], mod[2], zo))} = {_say(rd, out[pair][3])}"
            )
    return list(out.values())


def _arms(rd, entries, known):
    """The arms left out: a link between the centres of a meshing pair, one moving and
    held by no stated link but its wheels, as long as the centre distance."""
    index, radius, table, ground = known
    wheels = {frozenset(split_name(k)) for k, _, _ in entries}
    held = {p for pair in index if pair not in wheels for p in pair}
    for tab in ("points", "sliders"):  # a carried point, a block: held already
        held.update(rd.raw[tab] if isinstance(rd.raw.get(tab), dict) else ())
    arms = {}
    for key, spec, pts in entries:
        base = _base(rd, key, spec, (radius, table, ground))
        r = radius.get(frozenset(pts))
        if base is None or r is None:
            continue
        (o, big), a = base, pts[0]
        moving = [p for p in (o, a) if p not in ground]
        if len(moving) != 1 or moving[0] in held or frozenset((o, a)) in index:
            continue
        d = r - big if spec.get("ring") is True else big - r if spec.get("inside") else r + big
        o, a = (a, o) if o in moving else (o, a)  # the arm from its fixed end
        name = f"{o}{a}" if split_name(f"{o}{a}") == (o, a) else f"{o}-{a}"
        pair = frozenset((o, a))
        if pair in arms and abs(arms[pair][3] - d) > SAME * d:
            raise rd.error(
                f"the arm {name} (not in [links]) is {_say(rd, arms[pair][3])} from one "
                f"pair's teeth and {_say(rd, d)} from this one's: state {name} in [links]",
                "rolling",
                key,
            )
        if d > 0 and pair not in arms:
            arms[pair] = (name, o, a, d)
            two = (r, big) if spec.get("ring") is True else (big, r)
            how = " - ".join(_say(rd, x)[: -len(rd.unit) - 1] for x in two)
            how = how if spec.get("ring") is True or spec.get("inside") else how.replace("-", "+")
            rd.read_notes.append(
                f"[links] {name} not given: the arm carrying {a}, its length the centre "
                f"distance of {key} and the gear it meshes with, from the teeth: {how} = "
                f"{_say(rd, d)}"
            )
    _no_arm(rd, entries, (index, arms, held, ground))
    return list(arms.values())


def _no_arm(rd, entries, known):
    """Refused: a planet on a fixed circle given by its teeth, neither the circle's size
    (on_teeth, on_radius) nor its arm stated, nor the arm made from another pair's teeth:
    nothing fixes the centre distance (it was refused as '[input] crank: no link OA')."""
    index, arms, held, ground = known
    for key, spec, (a, _) in entries:
        o = spec.get("on")
        if not isinstance(o, str) or o not in ground or a in ground or a in held:
            continue  # (a wheel on a gear or a line, its centre fixed or held by a link)
        arm = frozenset((o, a))
        if "teeth" not in spec or "on_teeth" in spec or "on_radius" in spec:
            continue
        if arm in index or arm in arms:
            continue
        name = f"{o}{a}" if split_name(f"{o}{a}") == (o, a) else f"{o}-{a}"
        raise rd.error(
            f"the arm {name} is not in [links] and the circle about {o} has no on_teeth or "
            f"on_radius: nothing fixes their centre distance: give on_teeth (its teeth) or "
            f"{name} in [links]",
            "rolling",
            key,
        )


def _base(rd, key, spec, known):
    """(centre, pitch radius) of the gear or fixed circle a wheel meshes with, where the
    teeth (or stated lengths) give it; else None."""
    radius, table, ground = known
    on = spec.get("on")
    if not isinstance(on, str):
        return None
    if "on_radius" in spec:
        big = rd.length(spec["on_radius"], "rolling", key)
    elif "on_teeth" in spec and (_module(rd, spec, key) or table):
        big = (_module(rd, spec, key) or table)[0] * _count(rd, spec, "on_teeth", key) / 2
    else:
        big = radius.get(frozenset(split_name(on)))
    if on in ground:
        return None if big is None else (on, big)
    bpts = split_name(on)
    if len(bpts) != 2 or big is None:
        return None
    fixed = [p for p in bpts if p in ground]
    return (fixed[0] if fixed else bpts[0], big)


def _say(rd, x):
    return f"{x / rd.scale():.6g} {rd.unit}"
