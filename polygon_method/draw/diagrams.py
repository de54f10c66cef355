"""The three diagrams as sketches: the configuration (space) diagram and the velocity and
acceleration polygons, read from the solution and the steps' construction records."""

from __future__ import annotations

import math
import re

from ..solver.given import stated
from ..polygons.constructions import (
    acceleration_constructions,
    drawn_vectors,
    image_label,
    velocity_constructions,
)
from ..common.numbers import fmt_angular
from ..polygons.scales import Scale
from ..scene import FixedPath
from .symbols import (
    SLOT_W,
    block_size,
    crank_angle,
    crank_angle_label,
    crank_angle_shapes,
    crank_arc,
    deg,
    fixed_guide,
    ground_symbol,
    rect,
    slot_half,
    step_shape,
    yoke_bar,
)
from .sketch import _header, _Sketch
from .style import (
    BAR,
    BODY_EDGE,
    BODY_FACE,
    DOT_R,
    IMAGE_FACE,
    JOINT_R,
    LABEL_PT,
    LEGEND_NAMES,
    LINE_STYLE,
    MARK_APART,
    MARK_PT,
    OVERSHOOT,
    POLE_R,
    SMALL_PT,
    STYLE,
)


# --------------------------------------------------------------------------- configuration


def _configuration(sol, scale: Scale) -> _Sketch:
    from .klein import draw_klein, klein_line

    sk = _Sketch()

    def extra(sk, P):
        _auxiliary(sk, sol, scale, P)
        draw_klein(sk, sol, scale, P)  # a slider crank at uniform crank speed

    _mechanism(sk, sol, scale, extra=extra)
    klein = klein_line(sol)
    _header(
        sk,
        "configuration",
        "Configuration diagram",
        scale,
        lines=[_drive(sol)] + ([klein] if klein else []),
    )
    return sk


def _auxiliary(sk, sol, scale, P):
    """The points a construction step adds (Goodman's auxiliary point S, where two links
    produced meet), dashed from the links' ends; one far outside the mechanism is left to
    the step table's words."""
    s = scale.per_cm
    xs = [x for x, _ in P.values()]
    ys = [y for _, y in P.values()]
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2
    reach = max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)
    for st in sol.plan.steps:
        for label, (x, y), ends in st.auxiliary(sol.P):
            xy = (x / s, y / s)
            if math.dist(xy, (cx, cy)) > 0.75 * reach:
                continue
            for e in ends:
                sk.line(
                    [P[e], xy],
                    gid=f"auxiliary-{label}-{e}",
                    color="#555555",
                    lw=0.5,
                    dashes=(2.0, 1.5),
                    z=1,
                )
            sk.circle(xy, DOT_R, gid=f"auxiliary-{label}", face="#000000", z=6)
            sk.label(label, [xy], LABEL_PT, gid=f"label-auxiliary-{label}", point=True)


def _drive(sol) -> str:
    inp = sol.scene.input
    own = sol.plan.steps[0].drive_caption(sol.scene)  # a block driver's; a crank's below
    if own is not None:
        return own
    said = f" ({inp.angle_words})" if inp.angle_words else ""
    drive = f"crank {inp.crank} at {deg(inp.angle)}{said}, " + (
        inp.speed_text
        if inp.given is None
        else f"{fmt_angular(inp.omega, 'rad/s')} (from {stated(inp)})"
    )
    if inp.alpha:
        drive += f", {fmt_angular(inp.alpha, 'rad/s²')}"
    if inp.second is not None and inp.second.block is not None:  # a collar on the crank
        drive += f"; {sol.plan.steps[1].second_words(sol.scene)}"
    elif inp.second is not None:
        two = inp.second
        drive += f"; {two.crank} at {deg(two.angle)}, {two.speed_text}"
    return drive


def _mechanism(sk: _Sketch, sol, scale: Scale, extra=None) -> dict:
    """The mechanism drawn on ``sk`` to ``scale`` (links, plates, blocks, guides, pins,
    ground symbols, the crank angle, labelled points); ``extra(sk, P)`` adds more before
    the labels are placed. Returns the points in cm."""
    from shapely.geometry import MultiPoint, Polygon

    sc = sol.scene
    s = scale.per_cm
    P = {k: (x / s, y / s) for k, (x, y) in sol.P.items()}
    carried_on = {}
    for cp in sc.points:
        carried_on.setdefault(cp.link, []).append(cp.name)
    solid = []  # (link key or block, its outline): what brackets and arcs keep clear of
    # frame: links between two ground points
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
    # sliders on fixed paths: line of stroke, guide wall with hatching (on the side away
    # from its rod, or from what a step keeps clear: a rack's pinion)
    clear = {
        sh[1]: (sh[2][0] / s, sh[2][1] / s)
        for st in sol.plan.steps
        for sh in st.shapes(sol.P)
        if sh[0] == "guide clear of"
    }
    for sl in sc.blocks:  # (a driving wheel's centre path: its ground line is drawn)
        if isinstance(sl, FixedPath):
            fixed_guide(sk, sc, sl, P, s, clear.get(sl.point))
    # links as bars, a link with carried points as a plate
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
    # cylinders: a wide barrel from its pivot, a narrow rod from its end, overlapping
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
    # what the steps draw besides links: pitch circles, ground lines, rolling contacts
    contacts = []
    for st in sol.plan.steps:
        for shape in st.shapes(sol.P):
            if shape[0] == "circle":  # about a point of the mechanism
                shape = ("circle", sol.P[shape[1]], shape[2])
            c = step_shape(sk, shape, s, f"{st.index + 1}-{len(contacts)}")
            if c is not None:
                contacts.append(c)
    # a translating yoke: a bar through its block along its slot, over the pin's block
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
    # blocks
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
            from shapely.geometry import LineString

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
    # pins at their given sizes, where that stays legible; a pin as large as the links it
    # joins is marked by its diameter instead of a circle that would swamp them
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
    # ground pivots, hatched, off the crank angle's sector where they can be; a bracket
    # that must sit in it is cleared by the arc drawn beyond it
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
    arc = crank_arc(sc, P, feet)
    # the crank angle
    crank_angle(sk, arc)
    # joints and points
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
    crank_angle_label(sk, arc)
    if extra is not None:
        extra(sk, P)
    sk.place_labels()
    return P


_POINT_LABEL = re.compile(r"^[a-z][0-9]*'?$")


def _polygon(sol, scale: Scale, phase: str) -> _Sketch:
    s = scale.per_cm
    D = sol.V if phase == "velocity" else sol.A
    prime = "" if phase == "velocity" else "'"
    cm = lambda p: (p[0] / s, p[1] / s)  # noqa: E731
    cons = velocity_constructions(sol) if phase == "velocity" else acceleration_constructions(sol)
    vectors = drawn_vectors(sol, phase)
    ref = max([v.magnitude for v in vectors] + [math.hypot(*p) for p in D.values()] + [0.0])
    tol = 1e-9 * ref if ref else 1e-12
    sk = _Sketch()
    # image triangles, lightly shaded
    steps = sol.plan.steps
    for c in cons:
        st = steps[c.step]
        if st.image_by_similar_triangle:
            tri = [cm(D[st.p]), cm(D[st.q]), cm(D[st.point])]
            sk.polygon(
                tri,
                gid=f"{phase}-image-{st.point}",
                face=IMAGE_FACE,
                edge="#b08d00",
                lw=0.5,
                alpha=0.45,
                z=1,
                obstacle="edge",
            )
    # a point on a link produced: the image line produced to its image (qr produced to t)
    for c in cons:
        produced = steps[c.step].produced()
        if produced is not None:
            a, x = produced
            sk.line(
                [cm(D[a]), cm(D[x])],
                gid=f"{phase}-produced-{x}",
                color="#000000",
                lw=0.6,
                dashes=(2.0, 1.5),
                z=2,
            )
    # construction lines, dashed, through the point they start from
    marks = []
    for c in cons:
        on = [c.point] + [p for v in c.given + c.found for p in (v.start, v.end)]
        for i, ln in enumerate(c.lines):
            (px, py), (dx, dy) = ln.point, ln.direction
            ts = [0.0] + [
                ((q[0] - px) * dx + (q[1] - py) * dy)
                for q in on
                if abs((q[0] - px) * dy - (q[1] - py) * dx) <= tol
            ]
            lo, hi = min(ts) / s - OVERSHOOT, max(ts) / s + OVERSHOOT
            a = (px / s + lo * dx, py / s + lo * dy)
            b = (px / s + hi * dx, py / s + hi * dy)
            color, lw, dashes = LINE_STYLE
            sk.line(
                [a, b], gid=f"{phase}-line-{c.step}-{i}", color=color, lw=lw, dashes=dashes, z=2
            )
            marks.append((ln.mark or ln.relation, [b, a], f"{phase}-mark-{c.step}-{i}"))
    # vectors
    for n, v in enumerate(vectors):
        color, lw, dashes = STYLE[v.kind]
        sk.arrow(cm(v.start), cm(v.end), f"{phase}-vector-{n}", color, lw, dashes)
    # points: the pole, every image point, the named intermediate points
    names = {}

    def name_at(xy, text):
        for k in names:
            if math.dist(k, xy) <= tol:
                if text not in names[k]:
                    names[k].append(text)
                return
        names[tuple(xy)] = [text]

    pole = "o" + prime
    name_at((0.0, 0.0), pole)
    for p in sol.scene.point_names:
        if p not in sol.scene.ground:
            name_at(D[p], image_label(sol, p, phase))
    for c in cons:
        for text, xy in c.named:  # the intermediate points the step's text names (a1')
            name_at(xy, text)
        for ln in c.lines:
            if _POINT_LABEL.match(ln.through):
                name_at(ln.point, ln.through)
        for v in c.given + c.found:
            for k, labs in list(names.items()):
                if math.dist(k, v.start) <= tol:
                    for lab in labs:
                        rest = v.label[len(lab) :] if v.label.startswith(lab) else ""
                        if _POINT_LABEL.match(rest) and rest not in labs:
                            if not any(math.dist(k2, v.end) <= tol for k2 in names):
                                name_at(v.end, rest)
                    break
    for xy, labs in names.items():
        r = POLE_R if pole in labs else DOT_R
        sk.circle(
            cm(xy),
            r,
            gid=f"{phase}-point-{'-'.join(labs).replace(chr(39), 'p')}",
            face="#000000",
            z=6,
        )
    for xy, labs in sorted(names.items(), key=lambda kv: pole not in kv[1]):
        labs = [pole] + [x for x in labs if x != pole] if pole in labs else labs
        sk.label(
            ", ".join(labs),
            [cm(xy)],
            LABEL_PT,
            gid=f"label-{'-'.join(labs).replace(chr(39), 'p')}",
            point=True,
        )
    for text, anchors, gid in marks:
        sk.label(text, anchors, MARK_PT, gid=f"label-{gid}", color="#555555", apart=MARK_APART)
    sk.place_labels()
    if phase == "velocity":
        legend = [("line", "construction line (\u22a5 / \u2225 to a link)")]
        if any(v.kind == "sliding" for v in vectors):  # a block's velocity along its guide
            legend.append(("sliding", LEGEND_NAMES["sliding"]))
        if any(steps[c.step].image_by_similar_triangle for c in cons):
            legend.append(("image", "image of a link triangle"))
        _header(sk, phase, "Velocity polygon", scale, legend=legend)
    else:
        kinds = []
        for v in vectors:
            if v.kind not in kinds:
                kinds.append(v.kind)
        order = ["centripetal", "tangential", "coriolis", "sliding", "absolute", "relative"]
        legend = [(k, LEGEND_NAMES[k]) for k in order if k in kinds]
        legend.append(("line", "construction line"))
        _header(sk, phase, "Acceleration polygon", scale, legend=legend)
    return sk


def _sketch(sol, diagram: str, scale: Scale) -> _Sketch:
    if diagram == "configuration":
        return _configuration(sol, scale)
    return _polygon(sol, scale, diagram)
