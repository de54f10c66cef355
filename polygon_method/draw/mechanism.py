"""The mechanism on the configuration diagram, drawn to scale part by part: the frame, the
fixed guides, the links as bars and plates, cylinders, what the steps draw (pitch circles,
ground lines, contacts), yokes, blocks and slots, pins at their sizes, the hatched ground
pivots, the crank angle and the labelled points. Every place is in cm on the sketch (``P``),
and ``solid`` collects the outlines brackets and arcs keep clear of.
"""

from __future__ import annotations

import math

from ..polygons.scales import Scale
from ..scene import FixedPath
from .sketch import _Sketch
from .style import BAR, BODY_EDGE, BODY_FACE, DOT_R, JOINT_R, LABEL_PT, SMALL_PT
from .symbols import (
    SLOT_W,
    block_size,
    crank_angle,
    crank_angle_label,
    crank_angle_shapes,
    crank_arc,
    fixed_guide,
    ground_symbol,
    rect,
    slot_half,
    step_shape,
    yoke_bar,
)

__all__ = ["mechanism"]


def mechanism(sk: _Sketch, sol, scale: Scale, extra=None) -> dict:
    """The mechanism drawn on ``sk`` to ``scale`` (links, plates, blocks, guides, pins,
    ground symbols, the crank angle, labelled points); ``extra(sk, P)`` adds more before
    the labels are placed. Returns the points in cm."""
    sc = sol.scene
    s = scale.per_cm
    P = {k: (x / s, y / s) for k, (x, y) in sol.P.items()}
    carried_on = {}
    for cp in sc.points:
        carried_on.setdefault(cp.link, []).append(cp.name)
    solid = []  # (link key or block, its outline): what brackets and arcs keep clear of
    _frame(sk, sc, P)
    _fixed_guides(sk, sol, P, s)
    _links(sk, sc, P, carried_on, solid)
    _cylinders(sk, sc, P, solid)
    contacts = _step_shapes(sk, sol, s)
    _yokes(sk, sc, P, solid)
    _blocks(sk, sc, P, solid)
    pin_notes = _pins(sk, sc, P, s)
    arc = _ground_pivots(sk, sc, P, carried_on, solid)
    inp = sc.input
    crank_angle(sk, arc, math.dist(P[inp.pivot], P[inp.tip]) if inp.pivot else math.inf)
    _points(sk, sc, P, contacts, pin_notes)
    crank_angle_label(sk, arc)
    if extra is not None:
        extra(sk, P)
    sk.place_labels()
    return P


def _frame(sk, sc, P):
    """The frame: links between two ground points, dash-dotted."""
    for lk in sc.links:
        if lk.p in sc.ground and lk.q in sc.ground:
            sk.line(
                [P[lk.p], P[lk.q]],
                gid=f"frame-{lk.key}",
                color="#555555",
                lw=0.6,
                dashes=(6, 2, 1, 2),
                z=1,
            )


def _fixed_guides(sk, sol, P, s):
    """Sliders on fixed paths: the line of stroke and the guide wall with its hatching, on
    the side away from its rod (or from what a step keeps clear: a rack's pinion). A driving
    wheel's centre path has no block: its ground line is drawn by its step."""
    sc = sol.scene
    clear = {
        sh[1]: (sh[2][0] / s, sh[2][1] / s)
        for st in sol.plan.steps
        for sh in st.shapes(sol.P)
        if sh[0] == "guide clear of"
    }
    for sl in sc.blocks:  # (a driving wheel's centre path: its ground line is drawn)
        if isinstance(sl, FixedPath):
            fixed_guide(sk, sc, sl, P, s, clear.get(sl.point))


def _links(sk, sc, P, carried_on, solid):
    """The links as bars, a link with carried points as a plate; a block sliding on the link
    beyond its ends: the link produced through the block."""
    from shapely.geometry import MultiPoint

    for lk in sc.links:
        if lk.p in sc.ground and lk.q in sc.ground:
            continue
        pts = [P[lk.p], P[lk.q]] + [P[c] for c in carried_on.get(lk.key, ())]
        # a block sliding on the link beyond its ends: the link produced through the block
        for sl in sc.sliders:
            if getattr(sl, "guide", None) == lk.key:
                (x1, y1), (x2, y2) = P[sl.first], P[sl.second]
                n = math.hypot(x2 - x1, y2 - y1)
                size = block_size(sc, sl.point, P)
                reach = slot_half(size) + SLOT_W if sl.slot else size / 2
                X, half = P[sl.point], reach + BAR / 2
                pts += [
                    (X[0] + k * half * (x2 - x1) / n, X[1] + k * half * (y2 - y1) / n)
                    for k in (-1, 1)
                ]
        body = MultiPoint(pts).convex_hull.buffer(BAR / 2, quad_segs=8)
        solid.append((lk.key, body))
        sk.polygon(
            list(body.exterior.coords),
            gid=f"link-{lk.key}",
            face=BODY_FACE,
            edge=BODY_EDGE,
            lw=0.8,
            z=2,
            obstacle="edge",
        )
        for a in pts:
            for b in pts:
                if a < b:
                    sk.hints.append((a, b))


def _cylinders(sk, sc, P, solid):
    """Cylinders: a wide barrel from its pivot, a narrow rod from its end, overlapping."""
    from shapely.geometry import Polygon

    for cyl in sc.cylinders:
        K, R = P[cyl.barrel], P[cyl.rod]
        n = math.dist(K, R)
        u = ((R[0] - K[0]) / n, (R[1] - K[1]) / n)
        barrel = 0.6 * n
        mid = (K[0] + u[0] * barrel / 2, K[1] + u[1] * barrel / 2)
        shape = rect(mid, u, barrel, 2.2 * BAR)
        sk.polygon(
            shape, gid=f"cylinder-{cyl.key}-barrel", face="#ffffff", edge="#000000", lw=0.9, z=3
        )
        solid.append((f"barrel {cyl.key}", Polygon(shape)))
        rod = 0.55 * n
        mid = (R[0] - u[0] * rod / 2, R[1] - u[1] * rod / 2)
        shape = rect(mid, u, rod, 0.8 * BAR)
        sk.polygon(
            shape, gid=f"cylinder-{cyl.key}-rod", face=BODY_FACE, edge=BODY_EDGE, lw=0.8, z=2
        )
        solid.append((f"rod {cyl.key}", Polygon(shape)))
        sk.hints.append((K, R))


def _step_shapes(sk, sol, s) -> list:
    """What the steps draw besides links (pitch circles, ground lines, rolling contacts):
    the contact points, in cm."""
    contacts = []
    for st in sol.plan.steps:
        for shape in st.shapes(sol.P):
            if shape[0] == "circle":  # about a point of the mechanism
                shape = ("circle", sol.P[shape[1]], shape[2])
            c = step_shape(sk, shape, s, f"{st.index + 1}-{len(contacts)}")
            if c is not None:
                contacts.append(c)
    return contacts


def _yokes(sk, sc, P, solid):
    """A translating yoke: a bar through its block along its slot, over the pin's block."""
    for sl in sc.sliders:
        if hasattr(sl, "yoke"):
            body = yoke_bar(sc, sl, P)
            solid.append((f"yoke {sl.yoke}", body))
            sk.polygon(
                list(body.exterior.coords),
                gid=f"yoke-{sl.yoke}",
                face=BODY_FACE,
                edge=BODY_EDGE,
                lw=0.8,
                z=2,
                obstacle="edge",
            )


def _blocks(sk, sc, P, solid):
    """The blocks, along their guides; a peg in two slots: the pin in a slot cut along each
    (no block). A driving wheel's centre has no block."""
    from shapely.geometry import LineString, Polygon

    for sl in sc.blocks:  # (a driving wheel's centre: no block there)
        X = P[sl.point]
        if isinstance(sl, FixedPath):
            u = sl.u
        elif hasattr(sl, "yoke"):
            u = sl.direction
        else:
            (x1, y1), (x2, y2) = P[sl.first], P[sl.second]
            n = math.hypot(x2 - x1, y2 - y1)
            u = ((x2 - x1) / n, (y2 - y1) / n)
        size = block_size(sc, sl.point, P)
        if sl.slot:  # a peg in two slots: the pin in a slot cut along each (no block)
            h = slot_half(size)
            cut = LineString(
                [(X[0] - h * u[0], X[1] - h * u[1]), (X[0] + h * u[0], X[1] + h * u[1])]
            ).buffer(SLOT_W, quad_segs=8)
            sk.polygon(
                list(cut.exterior.coords),
                gid=f"slot-{sl.key}",
                face="#ffffff",
                edge="#000000",
                lw=0.8,
                z=3,
            )
            solid.append((f"block {sl.key}", cut))
            sk.hints.append(
                ((X[0] - h * u[0], X[1] - h * u[1]), (X[0] + h * u[0], X[1] + h * u[1]))
            )
            continue
        sk.polygon(
            rect(X, u, size, 0.55 * size),
            gid=f"block-{sl.point}",
            face="#ffffff",
            edge="#000000",
            lw=0.9,
            z=3,
        )
        solid.append((f"block {sl.point}", Polygon(rect(X, u, size, 0.55 * size))))
        sk.hints.append(
            (
                (X[0] - size / 2 * u[0], X[1] - size / 2 * u[1]),
                (X[0] + size / 2 * u[0], X[1] + size / 2 * u[1]),
            )
        )


def _pins(sk, sc, P, s) -> list:
    """Pins at their given sizes where that stays legible; a pin as large as the links it
    joins is marked by its diameter instead of a circle that would swamp them: those notes,
    (point, text)."""
    pin_notes = []
    for pin in sc.pins:
        r = pin.radius / s
        near = [
            math.dist(P[pin.point], P[lk.other(pin.point)])
            for lk in sc.links
            if pin.point in lk.points
        ]
        if r > 0.3 * min(near, default=math.inf):
            dia = 2 * pin.radius / sc.length_unit
            pin_notes.append((pin.point, f"\u2300 {dia:.4g} {sc.units}"))
        elif r > JOINT_R * 1.2:
            sk.circle(
                P[pin.point],
                r,
                gid=f"pin-{pin.point}",
                face="none",
                edge="#8a8a8a",
                lw=0.6,
                z=4,
                obstacle="edge",
            )
    return pin_notes


def _ground_pivots(sk, sc, P, carried_on, solid):
    """The ground pivots, hatched, off the crank angle's sector where they can be (a bracket
    that must sit in it is cleared by the arc drawn beyond it): the crank angle's arc."""
    arc = crank_arc(sc, P)
    feet = []
    for g in sc.ground:
        away = [
            P[lk.other(g)] for lk in sc.links if g in lk.points and lk.other(g) not in sc.ground
        ]
        away += [P[c] for lk in sc.links if g in lk.points for c in carried_on.get(lk.key, ())]
        away += [P[c.rod] for c in sc.cylinders if c.barrel == g]
        away += [P[c.barrel] for c in sc.cylinders if c.rod == g]
        sl = sc.slider(g)
        if sl is not None and not isinstance(sl, FixedPath):  # a block at a fixed swivel
            away += [P[p] for p in (sl.first, sl.second) if p not in sc.ground]
        if away:
            near = [P[p] for p in sc.point_names if p != g and 0 < math.dist(P[p], P[g]) < 1.2]
            feet.append(
                ground_symbol(sk, g, P[g], near, [b for _, b in solid], crank_angle_shapes(arc))
            )
    return crank_arc(sc, P, feet)


def _points(sk, sc, P, contacts, pin_notes):
    """The joints (rings) and carried points (dots) with their names, the rolling contacts
    (I, or I1, I2, ...) and the pins' diameters."""
    joints = (
        set(sc.ground)
        | {p for lk in sc.links for p in lk.points}
        | {sl.point for sl in sc.sliders}
        | {p for c in sc.cylinders for p in (c.barrel, c.rod)}
    )
    for name in sc.point_names:
        if name in joints:
            sk.circle(P[name], JOINT_R, gid=f"joint-{name}", z=6)
        else:
            sk.circle(P[name], DOT_R, gid=f"joint-{name}", face="#000000", z=6)
    for name in sc.point_names:
        sk.label(name, [P[name]], LABEL_PT, gid=f"label-{name}", point=True)
    for k, xy in enumerate(contacts):  # the contact: the wheel's centre with what it rolls on
        sk.circle(xy, DOT_R, gid=f"contact-{k}", face="#000000", z=6)
        sk.label(
            "I" if "I" not in sc.point_names and len(contacts) == 1 else f"I{k + 1}",
            [xy],
            SMALL_PT,
            gid=f"label-contact-{k}",
            point=True,
        )
    for name, text in pin_notes:
        sk.label(text, [P[name]], SMALL_PT, gid=f"label-pin-{name}", color="#666666", point=True)
