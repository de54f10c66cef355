"""What a scene says that is likely not meant, found in its solved position: a moving point
placed on a fixed pivot or on a link whose ends are both fixed, and lengths in metres that
look like millimetres (the solution's warnings after the ill-conditioned steps')."""

from __future__ import annotations

import math

from ..common.tolerances import FLOOR, SAME
from ..solver.kinematics import hypot

__all__ = ["structural_warnings"]


def _ground_near(ground, P, lim):
    """``near(X)``: the fixed pivots within ``lim`` of point X (``hypot <= lim``), in the
    ground's order. The pivots are kept in square cells of side ``2 lim``, so a point looks
    only at the nine cells about its own: linear in the size of the scene where trying every
    pivot for every point was quadratic (a 10,001-link chain has 5,001 pivots and 5,000
    points). A coordinate that does not fit a cell (not finite, or beyond a float's range
    over ``2 lim``) is tried against every pivot, as before."""
    cell = 2.0 * lim
    cells, loose = {}, []

    def key(x, y):
        i, j = x / cell, y / cell
        if math.isfinite(i) and math.isfinite(j):
            return math.floor(i), math.floor(j)
        return None

    for n, (G, g) in enumerate(ground.items()):
        k = key(g[0], g[1])
        if k is None:
            loose.append((n, G, g))
        else:
            cells.setdefault(k, []).append((n, G, g))
    everything = list(cells.values()) + [loose]

    def near(X):
        x, y = P[X]
        k = key(x, y)
        if k is None:
            groups = everything
        else:
            i, j = k
            groups = [cells.get((i + a, j + b), ()) for a in (-1, 0, 1) for b in (-1, 0, 1)]
            groups.append(loose)
        found = [
            (n, G, g) for grp in groups for n, G, g in grp if not hypot(x - g[0], y - g[1]) > lim
        ]
        return [(G, g) for _, G, g in sorted(found, key=lambda t: t[0])]

    return near


def structural_warnings(sol) -> tuple:
    """Lines for what the scene says that is likely not meant: a moving point placed on a
    fixed pivot, or on a link that is fixed (its velocity is zero because of where it
    sits, not because of the motion), and lengths in metres that look like millimetres."""
    sc = sol.scene
    out = []
    size = max([lk.length for lk in sc.links] + [FLOOR])
    u, unit = sc.length_unit, sc.units
    fixed = sol.plan.fixed_links
    for cp in sc.points:
        lk = sc.link(cp.link)
        if lk.key in fixed:
            out.append(
                f"point {cp.name} is on link {lk.key}, whose ends are both fixed: it "
                "sits on the frame, so its velocity and acceleration are zero (was it "
                "meant to be on a moving link?)"
            )
    near = _ground_near(sc.ground, sol.P, SAME * size)
    ground = list(sc.ground)
    for k, G in enumerate(ground):  # two fixed pivots at one place: one pivot named twice?
        for H, h in near(G):
            if ground.index(H) > k:
                out.append(
                    f"the fixed pivots {G} and {H} are at one place, ({h[0] / u:g}, "
                    f"{h[1] / u:g}) {unit} (was one meant to be elsewhere?)"
                )
    for X in sc.point_names:
        if X in sc.ground:
            continue
        for G, g in near(X):
            cp = sc.carried(X)
            lk = sc.link(cp.link) if cp is not None else None
            if lk is not None and lk.key in fixed:
                break  # said above
            if lk is not None and G in lk.points:
                out.append(
                    f"point {X} is placed on the fixed pivot {G} (on link {lk.key}, "
                    f"0 {unit} from {G}): it does not move, so its velocity and "
                    "acceleration are zero"
                )
            else:
                out.append(
                    f"point {X} is at the fixed pivot {G} at this instant (the "
                    f"mechanism passes through {G}'s place, at ({g[0] / u:g}, "
                    f"{g[1] / u:g}) {unit}): check the figure"
                )
            break
    out += _pin_warnings(sc)
    if unit == "m" and sc.links:
        lengths = [lk.length for lk in sc.links]
        crank = sc.link(sc.input.crank) if sc.input.crank is not None else None
        pin = abs(sc.input.omega or 0.0) * crank.length if crank is not None else 0.0
        if min(lengths) >= 5.0 and pin > 60.0:
            out.append(
                f'units = "m", yet the links are {min(lengths):g} to '
                f"{max(lengths):g} m long (the crank pin would move at {pin:.4g} m/s): "
                'if the lengths are millimetres, write units = "mm"'
            )
    return tuple(out)


def _pin_warnings(sc) -> list:
    """A pin whose radius is more than a link it joins (a pin of 500 mm in a crank of
    100 mm: an eccentric's sheave may be so, a slip of the unit more often), and the
    friction circle, where friction acts at the pins, past that link's length."""
    out = []
    u, unit = sc.length_unit, sc.units
    for pin in sc.pins:
        mu = sc.friction.pin(pin.point) if sc.friction is not None else 0.0
        links = [lk for lk in sc.links if pin.point in (lk.p, lk.q)]
        if not links:
            continue
        short = min(links, key=lambda lk: lk.length)
        if pin.radius <= short.length:
            continue
        line = (
            f"pin {pin.point}'s radius ({pin.radius / u:g} {unit}) is more than the link "
            f"{short.key} ({short.length / u:g} {unit}) it joins (an eccentric's sheave "
            "may be; else check its size and unit)"
        )
        if mu * pin.radius > short.length:
            line += (
                f"; its friction circle (mu r = {mu * pin.radius / u:g} {unit}) is larger "
                "than that link: the friction couple at it is taken as stated"
            )
        out.append(line)
    return out
