"""The answers of the crank's cycle and of the configuration, worked as a book works them
(``steps``' items, only where the scene's ``[answers]`` asks them, with a value or "?"): a
quick return's time ratio (the output's two extreme positions, the crank angles they occur
at, the crank's turn on the cutting and on the return stroke, their ratio), a slider's
stroke (its two extreme places and their distance), a link's direction (atan2 of the
coordinates) and the angle at a joint (the directions of its two lines). The numbers are
:mod:`polygon_method.linkage.cycle_values`' (the keys' one definition), not worked again."""

from __future__ import annotations

import math

from ..common.errors import PolygonMethodError
from ..linkage.cycle_values import direction, joint_angle, quick_return, stroke_ends
from ..linkage.output_motion import shown_place
from ..scene import split_name
from ..scene.reading import scene_table

__all__ = ["asked_cycle", "cycle_items"]

_KINDS = {"theta": 2, "angle": 3}


def asked_cycle(scene) -> tuple:
    """(key, kind, names) of each ``time_ratio``, ``stroke_X``, ``theta_XY``, ``angle_XYZ``
    the scene's ``[answers]`` asks, in its order (from its text where it was read without
    its answers; a key naming no slider or points of the scene is ``check``'s to refuse)."""
    if scene.answers:
        keys = [(a.key, a.kind, tuple(a.names)) for a in scene.answers]
    else:
        table = scene_table(scene).get("answers")
        keys = []
        for key in table if isinstance(table, dict) else ():
            kind, _, rest = key.partition("_")
            if key == "time_ratio":
                keys.append((key, key, ()))
            elif kind == "stroke":
                keys.append((key, kind, (rest,)))
            elif kind in _KINDS:
                keys.append((key, kind, tuple(split_name(rest))))
    points = set(scene.point_names)
    out = []
    for key, kind, names in keys:
        if kind == "time_ratio" or (kind == "stroke" and scene.slider(names[0]) is not None):
            out.append((key, kind, names))
        elif kind in _KINDS and len(set(names)) == _KINDS[kind] == len(names):
            if set(names) <= points:
                out.append((key, kind, names))
    return tuple(out)


def _deg(rad: float) -> str:
    return f"{math.degrees(rad):.4f} deg"


def _time_ratio_words(sol, key) -> str:
    out, stats, arc1, arc2, ratio = quick_return(sol.scene, key)
    s1, s2 = stats
    # the cutting stroke is the slower: the larger of the crank's two turns
    beta, alpha = max(arc1, arc2), min(arc1, arc2)
    first = "cutting" if arc1 >= arc2 else "return"
    second = "return" if first == "cutting" else "cutting"
    return (
        f"{key}: {out.label} stands still at its two extreme (dead) positions, "
        f"{shown_place(out, s1.output, sol.scene)} at crank angle {s1.deg:.4f} deg and "
        f"{shown_place(out, s2.output, sol.scene)} at crank angle {s2.deg:.4f} deg; "
        f"the crank turns {_deg(arc1)} from the first to the second ({first} "
        f"stroke) and {_deg(arc2)} back to the first ({second} stroke): "
        f"beta = {_deg(beta)} (cutting), alpha = {_deg(alpha)} (return), "
        f"beta + alpha = {_deg(beta + alpha)}; at uniform crank speed the times are as the "
        f"angles: {key} = beta / alpha = {math.degrees(beta):.4f} / "
        f"{math.degrees(alpha):.4f} = {ratio:.6g}"
    )


def _stroke_words(sol, key, point) -> str:
    sc = sol.scene
    omin, omax, path = stroke_ends(sc, point, key)
    u = sc.length_unit
    (qx, qy), (ux, uy) = path.through, path.u

    def at(v):
        return f"({(qx + v * ux) / u:.6g}, {(qy + v * uy) / u:.6g}) {sc.units}"

    low = f"({omin / u:.6g})" if omin < 0 else f"{omin / u:.6g}"
    return (
        f"{key}: over the crank's turn {point} moves along its path between its extreme "
        f"places {at(omin)} and {at(omax)} ({omin / u:.6g} and {omax / u:.6g} {sc.units} "
        f"along the path from ({qx / u:.6g}, {qy / u:.6g}) {sc.units}); {key} = their "
        f"distance = {omax / u:.6g} - {low} = {(omax - omin) / u:.6g} {sc.units}"
    )


def _theta_words(sol, key, x, y) -> str:
    sc, P = sol.scene, sol.P
    u = sc.length_unit
    dx, dy = (P[y][0] - P[x][0]) / u, (P[y][1] - P[x][1]) / u
    v = direction(P, x, y)
    return (
        f"{key}: from {x} to {y}, dx = {dx:.6g} {sc.units}, dy = {dy:.6g} {sc.units}; "
        f"{key} = atan2(dy, dx) = atan2({dy:.6g}, {dx:.6g}) = {_deg(v)} ccw from +x "
        f"({v:.6g} rad)"
    )


def _angle_words(sol, key, x, y, z) -> str:
    P = sol.P
    a, b = direction(P, y, x), direction(P, y, z)
    v = joint_angle(P, x, y, z)
    d = abs(a - b)
    more = f"; it exceeds 180 deg, so the angle is 360 deg - {_deg(d)}" if d > math.pi else ""
    return (
        f"{key}: at {y}, the direction of {y}{x} from +x is {_deg(a)} and of {y}{z} "
        f"{_deg(b)} (atan2 of the coordinates); their difference is {_deg(d)}{more}: "
        f"{key} = {_deg(v)} ({v:.6g} rad)"
    )


def _words(sol, key, kind, names) -> str:
    if kind == "time_ratio":
        return _time_ratio_words(sol, key)
    if kind == "stroke":
        return _stroke_words(sol, key, names[0])
    if kind == "theta":
        return _theta_words(sol, key, *names)
    return _angle_words(sol, key, *names)


def cycle_items(sol) -> list[str]:
    """``steps``' items for the asked cycle and configuration keys (none when none are
    asked); a key the mechanism cannot answer says why in its one line."""
    items = []
    for key, kind, names in asked_cycle(sol.scene):
        try:
            items.append(_words(sol, key, kind, names))
        except PolygonMethodError as exc:
            items.append(f"{key}: not answered: {exc.message.removeprefix(key + ': ')}")
    return items
