"""The mobility of a scene (:func:`gruebler`) and what is left over once its steps are
compiled (:func:`leftover`): a point no step finds, a link or a slider no step uses, a
rolling pair whose rim another step places: each refused in one line that says why
(under- or over-constrained, a block sliding freely, two inputs too many) and where."""

from __future__ import annotations

from ..common.errors import MobilityError
from ..scene import Scene

__all__ = ["gruebler", "leftover"]


def gruebler(scene: Scene) -> int:
    """Mobility M = 3 (n - 1) - 2 j - h: n bodies incl. ground and blocks, j lower pairs,
    h rolling pairs (each takes one freedom: no slip)."""
    ground = set(scene.ground)
    moving = [lk for lk in scene.links if not (lk.p in ground and lk.q in ground)]
    n = 1 + len(moving) + len(scene.sliders)
    bodies_at = {}
    for lk in moving:
        for p in lk.points:
            bodies_at.setdefault(p, set()).add(lk.key)
    for cp in scene.points:
        bodies_at.setdefault(cp.name, set()).add(scene.link(cp.link).key)
    for p in ground:
        bodies_at.setdefault(p, set()).add("ground")
    for s in scene.sliders:  # a peg in two slots: a block in each, pinned together
        bodies_at.setdefault(s.point, set()).add(f"block {s.key}")
    for c in scene.cylinders:  # barrel and rod: two bodies, a sliding pair between them
        n += 2
        bodies_at.setdefault(c.barrel, set()).add(f"barrel {c.key}")
        bodies_at.setdefault(c.rod, set()).add(f"rod {c.key}")
    j = sum(len(b) - 1 for b in bodies_at.values()) + len(scene.sliders) + len(scene.cylinders)
    return 3 * (n - 1) - 2 * j - len(scene.rolling)


def rolling_used(scene, steps):
    """Every rolling pair must set its wheel moving: a pair whose point another of the
    ``steps`` has placed (a driven crank, a dyad) is one constraint too many, never ignored."""
    sc = scene
    for pr in sc.rolling:
        if any(pr.rim in st.finds and st.kind in ("rolling", "rack") for st in steps):
            continue
        by = next((st for st in steps if pr.rim in st.finds), None)
        if by is None:
            continue  # not found at all: the mobility words below say why
        m = gruebler(sc)
        mob = f"mobility {m} (Gruebler: 3(n-1) - 2j - h)"
        if sc.input.second is not None and by.kind == "second crank":
            raise MobilityError(
                f"{mob}: two inputs over-determine the chain: the second crank "
                f"{sc.input.second.crank} is driven by its mesh ([rolling] {pr.wheel}) as "
                "well: remove [input.second] (or the mesh)",
                file=sc.file,
                key="[input.second] crank",
            )
        if by.kind == "crank" and pr.base is not None and pr.wheel in by.links:
            base = sc.link(pr.base)
            raise MobilityError(
                f"the gear {pr.wheel} is the crank, so it drives the mesh: write the "
                f'driven gear as the wheel, "{base.key}" = {{ on = "{pr.wheel}" }} '
                f"(centre first: {pr.base_centre})",
                file=sc.file,
                key=f"[rolling] {pr.wheel}",
            )
        raise MobilityError(
            f"{mob}: over-constrained: {pr.rim} is placed by step {by.title} and would "
            f"also be set by the rolling of {pr.wheel}: one constraint too many (remove "
            "a link or the rolling pair)",
            file=sc.file,
            key=f"[rolling] {pr.wheel}",
        )


def leftover(compiler):
    """Refuse what the compiled steps leave over (nothing, for a mechanism every step of
    which is found): a rolling pair too many, two inputs too many, a block sliding freely,
    a point not found, a link or a slider too many."""
    sc = compiler.scene
    rolling_used(sc, compiler.steps)
    names, P, used_links = compiler.names, compiler.P, compiler.used_links
    if (
        len(P) == len(names)
        and len(used_links) == len(sc.links)
        and len(compiler.used_sliders) == len(sc.sliders)
    ):
        return  # every point found, every link and slider used
    missing = [p for p in names if p not in P]
    extra_links = [lk.key for lk in sc.links if lk.key not in used_links]
    extra_sliders = list(
        dict.fromkeys(s.point for s in sc.sliders if s.key not in compiler.used_sliders)
    )
    if not missing and not extra_links and not extra_sliders:
        return
    m = gruebler(sc)
    mob = f"mobility {m} (Gruebler: 3(n-1) - 2j{' - h' if sc.rolling else ''})"
    _two_inputs(sc, m, mob)
    _free_blocks(sc, m, mob, missing, extra_sliders)
    if missing:
        _not_found(sc, m, mob, missing, used_links)
    _redundant(sc, mob, extra_links, extra_sliders)


def _two_inputs(sc, m, mob):
    """A second input where the chain has fewer than two freedoms: refused."""
    if sc.input.second is not None and m < 2:
        raise MobilityError(
            f"{mob}: two inputs over-determine the chain (a mechanism of {m} degree"
            f"{'' if m == 1 else 's'} of freedom takes {max(m, 0)} input"
            f"{'' if m == 1 else 's'}): remove [input.second]",
            file=sc.file,
            key="[input.second] crank",
        )


def _free_blocks(sc, m, mob, missing, extra_sliders):
    """Blocks on a guide alone (no link, no carried point) are all that is missing: a
    motion too many, refused with the second input that would drive one."""
    free = [
        p
        for p in extra_sliders
        if m > 1
        and p not in sc.ground
        and not any(p in (lk.p, lk.q) for lk in sc.links)
        and not any(cp.name == p for cp in sc.points)
    ]
    if free and set(missing) <= set(free):  # a block on a guide alone: a motion too many
        one = len(free) == 1
        raise MobilityError(
            f"{mob}: the mechanism is under-constrained; the block"
            f"{'' if one else 's'} {', '.join(free)} slide{'s' if one else ''} freely "
            f"along {'its guide' if one else 'their guides'}: nothing places "
            f"{'it' if one else 'them'} (pin {'it' if one else 'them'} to a link; or drive "
            f"{'it' if one else 'one'} along its guide as a second input: [input.second] "
            f'block = "{free[0]}" with vs_{free[0]}, s_{free[0]})',
            file=sc.file,
            key=f"[sliders] {', '.join(free)}",
        )


def _not_found(sc, m, mob, missing, used_links):
    """Points no step finds: refused as under-constrained, over-constrained or a
    construction the steps do not make, at the unused links that hold them."""
    if m > 1:
        why = (
            f"{mob}: the mechanism is under-constrained; "
            f"{', '.join(missing)} {'is' if len(missing) == 1 else 'are'} not "
            "determined by the crank (add the missing link or slider"
            + (
                ", or a second driven crank: [input.second]"
                if m == 2 and sc.input.second is None
                else ""
            )
            + ")"
        )
    elif m < 1:
        why = (
            f"{mob}: the mechanism is over-constrained (a structure); "
            f"{', '.join(missing)} cannot move"
        )
    else:
        why = (
            f"{', '.join(missing)} cannot be found by the construction steps "
            "(crank, dyad, slider, slotted link, carried point, rolling wheel, triad, "
            "peg in two slots, yoke): the chain needs "
            "a construction these steps do not make, or a part is missing"
        )
    loose = [
        lk.key
        for lk in sc.links
        if lk.key not in used_links and (lk.p in missing or lk.q in missing)
    ]
    where = f"[links] {', '.join(loose)}" if loose else "[links]"
    raise MobilityError(why, file=sc.file, key=where)


def _redundant(sc, mob, extra_links, extra_sliders):
    """Every point found, but links or sliders left unused: a constraint too many each."""
    parts = []
    if extra_links:
        parts.append(
            f"link{'s' if len(extra_links) > 1 else ''} "
            f"{', '.join(extra_links)} {'is' if len(extra_links) == 1 else 'are'}"
            " redundant (both ends already fixed by the other links): remove "
            f"{'it' if len(extra_links) == 1 else 'them'} or check the scene"
        )
    if extra_sliders:
        one = len(extra_sliders) == 1
        names, be = ", ".join(extra_sliders), "is" if one else "are"
        parts.append(
            f"slider{'' if one else 's'} {names} {be} redundant ({names} {be} "
            "already placed by the other links and the crank: "
            f"{'its path adds' if one else 'their paths add'} a constraint, not "
            f"a motion): remove {'it' if one else 'them'} or check the scene"
        )
    where = (
        f"[links] {', '.join(extra_links)}"
        if extra_links
        else f"[sliders] {', '.join(extra_sliders)}"
    )
    raise MobilityError(f"{mob}: over-constrained: " + "; ".join(parts), file=sc.file, key=where)
