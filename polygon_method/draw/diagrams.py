"""The three diagrams as sketches: the configuration (space) diagram and the velocity and
acceleration polygons, read from the solution and the steps' construction records."""

from __future__ import annotations

import math
import re

from ..common.tolerances import ON_PAPER, ROUNDING, SAME
from ..solver.given import stated
from ..polygons.constructions import (
    acceleration_constructions,
    drawn_vectors,
    image_label,
    velocity_constructions,
)
from ..common.numbers import fmt_angular
from ..polygons.scales import Scale
from .symbols import (
    deg,
)
from .mechanism import mechanism
from ..motion.link_points import asked_pairs, least_speed
from ..text.link_points import foot_name
from .sketch import _header, _Sketch

from .style import (
    DOT_R,
    IMAGE_FACE,
    LABEL_PT,
    LEAST_STYLE,
    LEGEND_NAMES,
    LINE_STYLE,
    MARK_APART,
    MARK_PT,
    OVERSHOOT,
    POLE_R,
    STYLE,
)


# --------------------------------------------------------------------------- configuration


def _configuration(sol, scale: Scale) -> _Sketch:
    from .klein import draw_klein, klein_line

    sk = _Sketch()

    def extra(sk, P):
        _auxiliary(sk, sol, scale, P)
        draw_klein(sk, sol, scale, P)  # a slider crank at uniform crank speed

    mechanism(sk, sol, scale, extra=extra)
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
    reach = max(max(xs) - min(xs), max(ys) - min(ys), ON_PAPER)
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
    rest = getattr(sol.scene, "at_rest", False)  # the polygons per unit speed: virtual
    if own is not None:
        return own + ("; at rest: the polygons per this speed (virtual)" if rest else "")
    said = f" ({inp.angle_words})" if inp.angle_words else ""
    drive = f"crank {inp.crank} at {deg(inp.angle)}{said}, " + (
        f"at rest: the polygons per {fmt_angular(inp.omega, 'rad/s')} (virtual)"
        if rest
        else inp.speed_text
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


_POINT_LABEL = re.compile(r"^[a-z][0-9]*'?$")


def _polygon(sol, scale: Scale, phase: str) -> _Sketch:
    """The velocity or acceleration polygon (``phase``) to ``scale``: the image triangles,
    the construction lines with their marks, the vectors, the pole and the image points
    named, and the legend."""
    s = scale.per_cm
    D = sol.V if phase == "velocity" else sol.A
    cm = lambda p: (p[0] / s, p[1] / s)  # noqa: E731
    cons = velocity_constructions(sol) if phase == "velocity" else acceleration_constructions(sol)
    vectors = drawn_vectors(sol, phase)
    ref = max([v.magnitude for v in vectors] + [math.hypot(*p) for p in D.values()] + [0.0])
    tol = SAME * ref if ref else ROUNDING
    sk = _Sketch()
    _images(sk, sol, cons, D, cm, phase)
    marks = _construction_lines(sk, cons, tol, s, phase)
    for n, v in enumerate(vectors):
        color, lw, dashes = STYLE[v.kind]
        sk.arrow(cm(v.start), cm(v.end), f"{phase}-vector-{n}", color, lw, dashes)
    pole = "o" + ("" if phase == "velocity" else "'")
    names = _image_points(sol, cons, D, tol, phase, pole)
    if phase == "velocity":  # vmin_XY asked: op square to xy, its foot p
        _least_speed(sk, sol, cm, names)
    _named_points(sk, names, pole, cm, phase)
    for text, anchors, gid in marks:
        sk.label(text, anchors, MARK_PT, gid=f"label-{gid}", color="#555555", apart=MARK_APART)
    sk.place_labels()
    _legend(sk, sol, scale, phase, vectors, cons)
    return sk


def _least_speed(sk, sol, cm, names):
    """For each ``vmin_XY`` the answers ask: op drawn from the pole square to xy, its foot
    named (p, or the letter the steps give it), xy produced to it where it falls outside,
    within a quarter of the polygon's size past its extent (the scale is the polygon's: a
    foot far beyond it is left to the step table's words)."""
    box = [(0.0, 0.0)] + list(sol.V.values())
    lo, hi = [min(q[i] for q in box) for i in (0, 1)], [max(q[i] for q in box) for i in (0, 1)]
    room = max(hi[0] - lo[0], hi[1] - lo[1]) / 4  # a quarter of the polygon's size past it
    for key, kind, (x, y) in asked_pairs(sol.scene):
        ls = least_speed(sol, x, y) if kind == "vmin" else None
        if ls is None or ls.fraction is None:  # (a link that does not turn has no foot)
            continue
        (bx, by), (cx, cy), t = sol.V[x], sol.V[y], ls.fraction
        foot = (bx + t * (cx - bx), by + t * (cy - by))
        if not all(lo[i] - room <= foot[i] <= hi[i] + room for i in (0, 1)):
            continue
        ends = [(0.0, 0.0)] + ([] if ls.where == "between" else [sol.V[x if t < 0 else y]])
        color, lw, dashes = LEAST_STYLE
        for i, end in enumerate(ends):  # op; xy produced to p
            sk.line(
                [cm(end), cm(foot)],
                gid=f"velocity-least-{x}-{y}-{i}",
                color=color,
                lw=lw,
                dashes=dashes,
                z=2,
            )
        names.setdefault(tuple(foot), []).append(foot_name(sol, key).lower())


def _images(sk, sol, cons, D, cm, phase):
    """The image triangles, lightly shaded, and a point on a link produced: the image line
    produced to its image (qr produced to t)."""
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


def _construction_lines(sk, cons, tol, s, phase) -> list:
    """The construction lines, dashed, through the point they start from and just past
    every point found on them: their marks to place, (text, anchors, gid)."""
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
    return marks


def _image_points(sol, cons, D, tol, phase, pole) -> dict:
    """{place: [names]}: the pole, every image point, the intermediate points the steps'
    texts name, and the ends of vectors named by their labels (points within ``tol`` of
    each other share one place)."""
    names = {}

    def name_at(xy, text):
        for k in names:
            if math.dist(k, xy) <= tol:
                if text not in names[k]:
                    names[k].append(text)
                return
        names[tuple(xy)] = [text]

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
    return names


def _named_points(sk, names, pole, cm, phase):
    """Each place of ``names`` as a dot (the pole larger), labelled, the pole's first."""
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


def _legend(sk, sol, scale, phase, vectors, cons):
    """The polygon's heading and its legend: the kinds of vectors drawn, the lines."""
    steps = sol.plan.steps
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


def _sketch(sol, diagram: str, scale: Scale) -> _Sketch:
    if diagram == "configuration":
        return _configuration(sol, scale)
    return _polygon(sol, scale, diagram)
