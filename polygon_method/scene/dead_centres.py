"""The dead centres of a slider crank (a part of the scene reader), for a crank angle a book
measures from one ("30 deg past the inner dead centre": :mod:`.angles`).

Dead centres of a slider crank (crank O A = r, rod A B = l, B on a straight path through
Q along unit u; B on the side ``s`` of A along u, +1 unless [assembly] says otherwise):
O, A and B are in line. At the inner dead centre the crank pin points at the piston and
the piston is farthest from the crank shaft, ``|OB| = l + r`` (A between O and B: the
books' "x = (l + r) - (l cos phi + r cos theta) from the i.d.c.", the project's
``worked_problems/engine_analytical.toml``; also "top dead centre", TDC); at the outer
dead centre it is nearest, ``|OB| = l - r`` (O between A and B; "bottom dead centre",
BDC). With F the foot of O on the path and ``e = |OF|`` (the offset),
``B = F + s sqrt(|OB|^2 - e^2) u``; the crank points along O->B at the inner dead centre
and the other way at the outer one: for a horizontal path below O (``e`` below) and the
piston on the right, ``theta_IDC = -asin(e / (l + r))`` and
``theta_ODC = 180 deg - asin(e / (l - r))``.
"""

from __future__ import annotations

import math

from ..common.errors import SceneError
from ..common.tolerances import SAME, TOL
from .angle_turns import _half_turn


def side_along(hint, u) -> int:
    """Which of the two slider positions (+1: the one farther along ``u``) an [assembly]
    hint word takes, as the compiler picks: the default (None) the one farther along the
    path; above/below/right/left the one on that side (+1 where the path has no such
    component: the compiler refuses the hint in its own words)."""
    if not isinstance(hint, str):
        return 1
    axis, want = {"above": (1, 1), "below": (1, -1), "right": (0, 1), "left": (0, -1)}.get(
        hint, (0, 0)
    )
    return -1 if u[axis] * want < -SAME else 1


def dead_centres(pivot, r, l, through, u, side, unit=("m", 1.0)) -> tuple:
    """(inner, outer) dead-centre crank angles (rad) of a slider crank: pivot O, crank r,
    rod l, path through ``through`` along unit ``u``, slider on ``side`` (+1 / -1) of the
    crank pin along u (lengths in m; ``unit`` (name, metres) for the messages). Raises
    :class:`SceneError` where the rod cannot reach.

    >>> i, o = dead_centres((0, 0), 1, 4, (0, 0), (1, 0), 1)   # in-line, path +x
    >>> round(math.degrees(i), 9), round(math.degrees(o), 9)
    (0.0, 180.0)
    """
    ox, oy = pivot
    qx, qy = through
    ux, uy = u
    t0 = (ox - qx) * ux + (oy - qy) * uy
    fx, fy = qx + t0 * ux, qy + t0 * uy  # the foot of O on the path
    e = math.hypot(ox - fx, oy - fy)
    name, k = unit
    out = []
    for reach, words in ((l + r, "inner"), (l - r, "outer")):
        if reach <= 0:
            raise SceneError(
                f"no {words} dead centre: the rod ({l / k:g} {name}) is not "
                f"longer than the crank ({r / k:g} {name})"
            )
        if reach < e * (1 + TOL.closure):
            raise SceneError(
                f"no {words} dead centre: the rod and crank in line reach "
                f"{reach / k:g} {name}, less than the line of stroke's offset "
                f"{e / k:g} {name} from the crank's pivot (the crank cannot turn "
                "a full turn)"
            )
        t = side * math.sqrt(reach * reach - e * e)
        bx, by = fx + t * ux - ox, fy + t * uy - oy
        ang = math.atan2(by, bx)
        out.append(ang + math.pi if words == "outer" else ang)
    return tuple(_half_turn(a, math.pi) for a in out)


def candidates(pivot, r, l, through, u, hint, unit=("m", 1.0)) -> list:
    """The dead centres of a slider crank as :func:`read_angle` takes them,
    ``[(inner, outer, keeps)]``: one candidate for the piston's side that an [assembly]
    word (or none) sets; for a rough position ``hint = (x, y)``, one per side, each with a
    test of the final crank angle: whether the position is nearer the piston on that side
    there (as the compiler picks it)."""
    if not isinstance(hint, tuple):
        return [(*dead_centres(pivot, r, l, through, u, side_along(hint, u), unit), None)]
    (ox, oy), (qx, qy), (ux, uy) = pivot, through, u

    def keeps(side):
        def test(theta):
            ax, ay = ox + r * math.cos(theta), oy + r * math.sin(theta)
            t = (ax - qx) * ux + (ay - qy) * uy
            fx, fy = qx + t * ux, qy + t * uy  # the foot of the crank pin on the path
            h2 = l * l - (ax - fx) ** 2 - (ay - fy) ** 2
            if h2 <= 0:
                return False
            h = math.sqrt(h2)
            ahead = math.dist((fx + h * ux, fy + h * uy), hint)
            behind = math.dist((fx - h * ux, fy - h * uy), hint)
            return (ahead < behind) == (side > 0)

        return test

    return [(*dead_centres(pivot, r, l, through, u, side, unit), keeps(side)) for side in (1, -1)]
