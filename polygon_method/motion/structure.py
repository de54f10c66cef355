"""What a scene says that is likely not meant, found in its solution: a moving point placed
on a fixed pivot or on a link whose ends are both fixed (its velocity is zero because of
where it sits, not because of the motion), and lengths in metres that look like millimetres.
"""

from __future__ import annotations

from ..common.tolerances import FLOOR, SAME
from ..solver.kinematics import hypot

__all__ = ["structural_warnings"]


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
    for X in sc.point_names:
        if X in sc.ground:
            continue
        for G, g in sc.ground.items():
            if hypot(sol.P[X][0] - g[0], sol.P[X][1] - g[1]) > SAME * size:
                continue
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
