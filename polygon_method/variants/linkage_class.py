"""The class a variant keeps (a part of the variants' generator, :mod:`.`): what kind of
linkage the base scene is, and its class in words (Grashof's for a four-bar, whether a
slider crank's crank turns fully, Whitworth or oscillating slotted lever, else whether the
crank turns fully on its branch)."""

from __future__ import annotations

import math

from ..common.errors import PolygonMethodError
from ..common.tolerances import ROUNDING
from ..linkage import four_bar_of, grashof, slider_crank_of, slotted_of
from ..scene import Scene


def _shape(scene: Scene):
    """What kind of linkage the scene is, for keeping its class: ("four-bar", names),
    ("slider crank", names), ("slotted", names) or ("mechanism", None)."""
    fb = four_bar_of(scene)
    if fb is not None:
        return ("four-bar", (fb.crank, fb.coupler, fb.output, fb.o2, fb.o4))
    sk = slider_crank_of(scene)
    if sk is not None:
        return ("slider crank", (sk.o, sk.crank, sk.rod, sk.b))
    slot = slotted_of(scene)
    if slot is not None:
        crank, lever = slot
        return ("slotted", (crank.link, crank.pivot, lever.known))
    return ("mechanism", None)


def linkage_class(scene: Scene, shape=None) -> str:
    """The class a variant must keep, in words: "four-bar: crank-rocker", "slider crank:
    the crank turns fully", "slotted lever: Whitworth", "mechanism: the crank turns fully"."""
    kind, names = shape or _shape(scene)
    if kind == "four-bar":
        crank, coupler, output, o2, o4 = names
        (ax, ay), (dx, dy) = scene.ground[o2], scene.ground[o4]
        g = grashof(
            scene.link(crank).length,
            scene.link(coupler).length,
            scene.link(output).length,
            math.hypot(dx - ax, dy - ay),
        )
        return f"four-bar: {g.kind}"
    if kind == "slider crank":
        o, crank, rod, b = names
        (ox, oy) = scene.ground[o]
        path = scene.slider(b)
        (qx, qy), (ux, uy) = path.through, path.u
        e = abs((ox - qx) * uy - (oy - qy) * ux)
        r, ell = scene.link(crank).length, scene.link(rod).length
        return "slider crank: " + (
            "the crank turns fully" if ell >= (r + e) * (1 - ROUNDING) else "the crank rocks"
        )
    if kind == "slotted":
        crank, pivot, known = names
        (ox, oy), (kx, ky) = scene.ground[pivot], scene.ground[known]
        whit = scene.link(crank).length > math.hypot(kx - ox, ky - oy)
        return "slotted lever: " + (
            "Whitworth (the lever turns fully)" if whit else "oscillating lever"
        )
    from ..solver.tracking import Sweeper

    try:
        sw = Sweeper(scene)
        turns = sw.domain.full_turn
    except PolygonMethodError:
        return "mechanism: locked"
    if not sw.driver.periodic:  # a block driven along its guide
        return f"mechanism: driven by {sw.driver.title}"
    return "mechanism: " + ("the crank turns fully" if turns else "the crank rocks")
