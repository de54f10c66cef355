"""The force analysis drawn as the books draw it: each body alone (its free-body diagram, at
the configuration diagram's scale) with its forces as arrows at their points of application
and its couples as curved arrows, and each group's force polygon at one round force scale
for the whole sheet (``1 cm = 500 N``), closed, its sides named the book's way (``F32`` the
force on link 3 by link 2, the frame link 1), the unknowns' direction lines drawn through
the corners where the book draws them, meeting where the polygon closes.

Everything drawn is read from the force steps' records (:class:`~polygon_method.forces.
ForceStep` ``polygon``, ``unknown``, ``chords``; :class:`~polygon_method.forces.FreeBody`);
nothing here works a force out.
"""

from __future__ import annotations

import math
import re

from ..common.errors import PolygonMethodError
from ..forces import couple_label, number_sub, side_label
from ..common.numbers import fmt, sense_word
from ..polygons.scales import Scale, diagram_scales, force_scale, polygon_corners
from .sketch import _header, _Sketch, _text_size
from .style import (
    BAR,
    BODY_EDGE,
    BODY_FACE,
    DOT_R,
    FORCE_STYLE,
    HEAD_HALF,
    HEAD_LEN,
    JOINT_R,
    LABEL_PT,
    LINE_STYLE,
    MARK_PT,
    OVERSHOOT,
    SMALL_PT,
)

__all__ = ["force_layout", "FORCE_STYLE", "ARROW_CM"]

#: a whole pin force read across a polygon (the sum of its two components)
CHORD_STYLE = ("#000000", 0.9, (5.0, 2.0))
#: the length (cm) of a force's arrow on a free-body diagram: it shows the line of action
#: and the sense; the size is the polygon's
ARROW_CM = 1.5
#: the radius (cm) of a couple's curved arrow
COUPLE_R = 0.5
#: a side shorter than this fraction of the sheet's largest force is not drawn (rounding)
NEGLIGIBLE = 1e-9
#: the narrowest (cm) a panel's lines of words are wrapped to: a panel is as wide as its
#: drawing, or this, so that narrow polygons and free bodies share a page
LINES_CM = 7.0


def force_layout(sol, scales=None):
    """The panels of the forces sheet, ``[(name, scale, sketch)]`` in the order solved:
    each group's bodies alone (``free-body-N``, at the configuration diagram's scale, the
    one the step table states, or ``--scale``'s length) and its force polygon
    (``force-polygon-K``, at the sheet's force scale, :func:`~polygon_method.polygons.scales.
    force_scale`, or ``--scale``'s force)."""
    sc = sol.scene
    if not sc.has_forces:
        raise PolygonMethodError(
            "the forces sheet draws the force analysis, and the scene "
            "asks for none: give its [masses] (or [gravity])",
            file=sc.file,
            key="--diagram",
        )
    refused = sol.forces_refused
    if refused:
        raise PolygonMethodError(refused, file=sc.file, key="--diagram")
    f = sol.forces
    given = dict(scales or {})
    space = given.get("length") or diagram_scales(sol)[0]
    fs = given.get("force") or force_scale(f)
    big = max([math.hypot(*s.vector) for st in f.steps for s in _sides(st)] + [0.0])
    tiny = NEGLIGIBLE * big
    free = {fb.body: fb for fb in f.free}
    panels, drawn = [], set()
    for st in f.steps:
        notes, shown = {}, []
        for n, pg in enumerate(st.polygons):
            sides = [s for s in pg.polygon if math.hypot(*s.vector) > tiny]
            if len(sides) >= 3:
                shown.append((polygon_tag(st, n), pg))
            elif len(sides) == 2:  # a crank with no mass: two forces, no polygon to draw
                a, b = (side_label(s, f.numbers) for s in sides)
                for body in pg.bodies:
                    notes[body] = (
                        f"{b} = \u2212{a}: two forces only, equal and opposite (no polygon)",
                    )
        for body in st.bodies:
            if body in free and body not in drawn:
                drawn.add(body)
                num = f.numbers[body]
                tag = f"free-body-{num}"
                note = notes.get(body, ())
                panels.append((tag, space, _free_body(sol, free[body], space, tiny, tag, note)))
        for tag, pg in shown:
            panels.append((tag, fs, _polygon(sol, st, pg, fs, tiny, tag)))
    return panels, space, fs


def _sides(st):
    return [s for pg in st.polygons for s in pg.polygon]


def polygon_tag(st, n: int = 0) -> str:
    """The panel's name of a step's ``n``-th force polygon: ``force-polygon-2`` the first of
    step 2, ``force-polygon-2b`` its second (a triad's first link's, a collar's rod's)."""
    return f"force-polygon-{st.index + 1}" + ("" if n == 0 else chr(ord("a") + n))


def _unit(v):
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n)


def _what(body, numbers, sc):
    if body.startswith("block "):
        return f"block {numbers[body]}, at {body[6:]}"
    return f"link {numbers[body]}, {body}" + (" (the crank)" if body == sc.input.crank else "")


def _magnitude(v) -> str:
    return f"{fmt(math.hypot(*v))} N"


def _fit(sk, lines) -> list:
    """The panel's lines of words wrapped to the width of its drawing (at least
    :data:`LINES_CM`), after a comma or a semicolon where one is near enough, else at a
    space: a line too long goes on over the next, indented (a force's number and unit
    stay together)."""
    x0, _, x1, _ = sk.content_box()
    room = max(x1 - x0, LINES_CM)
    out = []
    for line in lines:
        cur = ""
        for part in re.split(r"(?<=[,;]) ", line):
            words = [part] if _text_size("    " + part, SMALL_PT)[0] <= room else part.split(" ")
            for word in words:
                more = f"{cur} {word}" if cur else word
                if cur.strip() and _text_size(more, SMALL_PT)[0] > room:
                    out.append(cur)
                    cur = "    " + word
                else:
                    cur = more
        out.append(cur)
    return out


def _wrap(items, width=70):
    lines, cur = [], ""
    for it in items:
        if cur and len(cur) + 2 + len(it) > width:
            lines.append(cur + ",")
            cur = it
        else:
            cur = f"{cur}, {it}" if cur else it
    return lines + ([cur] if cur else [])


# --------------------------------------------------------------------------- a free body


def _free_body(sol, fb, scale: Scale, tiny, tag, note=()) -> _Sketch:
    """One body alone (``fb``, a :class:`~polygon_method.forces.FreeBody`) at the
    configuration diagram's ``scale``: its outline and joints, its centre of mass and the
    inertia force's offset, an arrow for each force, a curved arrow for each couple, and
    its words."""
    sc, f = sol.scene, sol.forces
    s = scale.per_cm

    def cm(p):
        return (p[0] / s, p[1] / s)

    sk = _Sketch()
    numbers = f.numbers
    pts, body = _outline(sk, sol, fb, cm, tag)
    _joints(sk, fb, pts, tag)
    inertia = f.inertia_of(fb.body)
    if inertia is not None:
        _centre_of_mass(sk, sc, fb, inertia, pts, cm, s, numbers, tag)
    words = _force_arrows(sk, sol, fb, body, cm, tiny, numbers, tag)
    centre = (
        cm(inertia.G)
        if inertia is not None
        else tuple(sum(c) / len(pts) for c in zip(*pts.values()))
    )
    _couples(sk, fb, centre, numbers, tag)
    sk.place_labels()
    lines = (
        _wrap(words)
        + list(note)
        + ["the arrows give each force's line and sense; its size is the polygon's"]
    )
    if fb.body == sc.input.crank or any(c.what == "torque" for c in fb.couples):
        lines.append(
            "T: the driver's torque on the "
            + ("wheel" if f.driver == "wheel" else "crank")
            + " (ccw +)"
        )
    _header(sk, tag, f"Free body of {_what(fb.body, numbers, sc)}", scale, lines=_fit(sk, lines))
    return sk


def _outline(sk, sol, fb, cm, tag):
    """The body's outline drawn (a block's box along its path; a link's, or a cylinder's,
    hull of its points): ``(its points by name, in cm; the outline, a shapely shape)``."""
    from shapely.geometry import MultiPoint, Polygon

    sc, f = sol.scene, sol.forces
    if fb.body.startswith("block "):
        point = fb.body[6:]
        X = cm(sol.P[point])
        g = next((g for g in f.guides if g.point == point), None)
        ux, uy = (g.n[1], -g.n[0]) if g is not None else (1.0, 0.0)
        a, b = 0.55, 0.32  # half length along the path, half height
        outline = [
            (X[0] + i * a * ux - j * b * uy, X[1] + i * a * uy + j * b * ux)
            for i, j in ((-1, -1), (1, -1), (1, 1), (-1, 1))
        ]
        pts = {point: X}
        # a force on the block away from its pin (a yoke's slot, at the crank pin): the body
        # reaches it
        pts.update({sd.point: cm(sd.at) for sd in fb.sides if sd.what == "guide" and sd.point})
        body = Polygon(outline)
        if len(pts) > 1:
            hull = MultiPoint(outline + list(pts.values())).convex_hull
            body = hull.buffer(BAR / 2, quad_segs=8)
            outline = list(body.exterior.coords)
        sk.polygon(
            outline, gid=f"{tag}-body", face=BODY_FACE, edge=BODY_EDGE, lw=0.8, z=2, obstacle="edge"
        )
        return pts, body
    cyl = sc.cylinder(fb.body)  # a cylinder (barrel and rod): one two-force member
    if cyl is not None:
        names = [cyl.barrel, cyl.rod]
    else:
        lk = sc.link(fb.body)
        names = [lk.p, lk.q] + [cp.name for cp in sc.points if cp.link == lk.key]
    pts = {n: cm(sol.P[n]) for n in names}
    pts.update({sd.point: cm(sd.at) for sd in fb.sides if sd.what == "contact"})
    body = MultiPoint(list(pts.values())).convex_hull.buffer(BAR / 2, quad_segs=8)
    sk.polygon(
        list(body.exterior.coords),
        gid=f"{tag}-body",
        face=BODY_FACE,
        edge=BODY_EDGE,
        lw=0.8,
        z=2,
        obstacle="edge",
    )
    return pts, body


def _joints(sk, fb, pts, tag):
    """Each of the body's points, named: a pin (a force acts there) open, else a dot."""
    for n, xy in pts.items():
        pin = any(sd.point == n and sd.what in ("pin", "guide") for sd in fb.sides)
        sk.circle(
            xy,
            JOINT_R if pin else DOT_R,
            gid=f"{tag}-joint-{n}",
            face="#ffffff" if pin else "#000000",
            z=6,
        )
        sk.label(n, [xy], LABEL_PT, gid=f"label-{tag}-point-{n}", point=True)


def _centre_of_mass(sk, sc, fb, inertia, pts, cm, s, numbers, tag):
    """The body's centre of mass G (where no point of it stands there) and the offset h
    of the book's single inertia force from G (where it shows)."""
    G = cm(inertia.G)
    if all(math.dist(G, xy) > 0.05 for xy in pts.values()):
        sk.circle(G, DOT_R, gid=f"{tag}-G", face="#000000", z=6)
        sk.label(
            "G" + number_sub(numbers, fb.body), [G], LABEL_PT, gid=f"label-{tag}-G", point=True
        )
    if inertia.offset is not None and abs(inertia.offset) / s > 0.05:
        H = cm(inertia.offset_point)
        sk.line([G, H], gid=f"{tag}-offset", color="#d95f02", lw=0.6, dashes=(2.0, 1.5), z=3)
        sk.label(
            f"h = {fmt(abs(inertia.offset) / sc.length_unit)} {sc.units}",
            [((G[0] + H[0]) / 2, (G[1] + H[1]) / 2)],
            MARK_PT,
            gid=f"label-{tag}-offset",
            color="#d95f02",
        )


def _force_arrows(sk, sol, fb, body, cm, tiny, numbers, tag) -> list:
    """An arrow of :data:`ARROW_CM` for each force on the body (above ``tiny``) at its
    point, from it or onto it, whichever keeps off the ``body``; named. Its words, ``F32 =
    120 N``, returned."""
    from shapely.geometry import LineString

    sc = sol.scene
    words = []
    for k, side in enumerate(fb.sides):
        if math.hypot(*side.vector) <= tiny:
            continue
        name = side_label(side, numbers)
        words.append(f"{name} = {_magnitude(side.vector)}")
        u = _unit(side.vector)
        at = cm(side.at)
        # from the point (a pull) or onto it (a push): whichever keeps off the body
        out = (at, (at[0] + ARROW_CM * u[0], at[1] + ARROW_CM * u[1]))
        into = ((at[0] - ARROW_CM * u[0], at[1] - ARROW_CM * u[1]), at)
        inside = [LineString(c).intersection(body).length for c in (out, into)]
        start, end = out if inside[0] <= inside[1] + 1e-9 else into
        if fb.body.startswith("block ") and side.what == "pin":
            # on a block (too small to keep off): the link's push drawn from the link's
            # side onto the pin, its pull from the pin towards the link
            lk = sc.link(side.by)
            q = cm(sol.P[lk.q if lk.p == side.point else lk.p])
            push = (at[0] - q[0]) * u[0] + (at[1] - q[1]) * u[1] > 0
            start, end = into if push else out
        color, lw, dashes = FORCE_STYLE[side.what]
        sk.arrow(start, end, f"{tag}-force-{k}", color, lw, dashes, z=5)
        far = end if (start, end) == out else start
        sk.label(
            name,
            [far, ((start[0] + end[0]) / 2, (start[1] + end[1]) / 2)],
            LABEL_PT,
            gid=f"label-{tag}-force-{k}",
            color=color,
        )
    return words


def _couples(sk, fb, centre, numbers, tag):
    """A curved arrow round ``centre`` for each couple on the body (each a little wider
    than the one before), with its value and sense."""
    for k, c in enumerate(fb.couples):
        if c.value == 0:
            continue
        r = COUPLE_R * (1 + 0.45 * k)
        _curved_arrow(sk, centre, r, c.value > 0, f"{tag}-couple-{k}")
        text = f"{couple_label(c, numbers)} = {fmt(abs(c.value))} N m {sense_word(c.value)}"
        sk.label(
            text,
            [(centre[0], centre[1] + r), (centre[0], centre[1] - r)],
            LABEL_PT,
            gid=f"label-{tag}-couple-{k}",
            color="#000000",
        )


def _curved_arrow(sk, centre, r, ccw, gid):
    """A couple: three quarters of a circle round ``centre`` with a head showing its
    sense."""
    a0, sweep = math.radians(-135), math.radians(270) * (1 if ccw else -1)
    if not ccw:
        a0 = math.radians(-45)
    n = 40
    pts = [
        (centre[0] + r * math.cos(a0 + sweep * i / n), centre[1] + r * math.sin(a0 + sweep * i / n))
        for i in range(n + 1)
    ]
    end = pts[-1]
    a = a0 + sweep
    tx, ty = (-math.sin(a), math.cos(a)) if ccw else (math.sin(a), -math.cos(a))
    hl = HEAD_LEN
    base = (end[0] - hl * tx, end[1] - hl * ty)
    sk.line(pts[:-3], gid=f"{gid}-arc", color="#000000", lw=1.1, z=5)
    sk.polygon(
        [
            end,
            (base[0] - HEAD_HALF * ty, base[1] + HEAD_HALF * tx),
            (base[0] + HEAD_HALF * ty, base[1] - HEAD_HALF * tx),
        ],
        gid=f"{gid}-head",
        face="#000000",
        edge="#000000",
        lw=0.4,
        z=5,
    )


# --------------------------------------------------------------------------- a polygon


def _along(a, b):
    """Where a side's label is tried, nearest its middle first."""
    return [
        (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1])) for t in (0.5, 0.35, 0.65, 0.2, 0.8)
    ]


def _polygon(sol, st, pg, scale: Scale, tiny, tag) -> _Sketch:
    """One force polygon (``pg`` of step ``st``) at the sheet's force ``scale``: the
    unknowns' direction lines, its sides head to tail from the pole and the whole forces
    read across it, each named, with a row of words each."""
    f = sol.forces
    numbers = f.numbers
    s = scale.per_cm
    corners = [(x / s, y / s) for x, y in polygon_corners(pg)]
    sides = pg.polygon
    sk = _Sketch()
    nonzero = [math.hypot(*sd.vector) > tiny for sd in sides]
    name = _namer(sides, nonzero, numbers)
    _direction_lines(sk, pg, corners, tag)
    also, chords = _chords(pg, sides, nonzero, name, numbers, tiny)
    rows = _polygon_sides(sk, pg, sides, nonzero, name, also, corners, scale, tag)
    rows += _chord_arrows(sk, chords, corners, numbers, scale, tag)
    sk.circle(corners[0], DOT_R * 1.3, gid=f"{tag}-pole", face="#000000", z=6)
    sk.place_labels()
    bodies = ", ".join(_what(b, numbers, sol.scene) for b in pg.bodies)
    lines = [
        f"step {st.index + 1}, {st.title}: {bodies}; link 1 the frame",
        "F\u2083\u2082: the force on 3 by 2 (\u1d57 square to its link, guide or contact, "
        "\u207f along the link or guide, normal to a contact)",
    ] + rows
    _header(sk, tag, "Force polygon", scale, lines=_fit(sk, lines))
    return sk


def _namer(sides, nonzero, numbers):
    """A side's name by its index: a component whose partner is nil is named as the whole
    force (``F34``, not ``F34t``)."""

    def name(k):  # a component whose partner is nil is the whole force
        sd = sides[k]
        if sd.part:
            partner = next(
                (
                    j
                    for j, o in enumerate(sides)
                    if j != k
                    and o.what == sd.what
                    and o.on == sd.on
                    and o.by == sd.by
                    and o.point == sd.point
                ),
                None,
            )
            if partner is not None and not nonzero[partner]:
                from dataclasses import replace

                return side_label(replace(sd, part=""), numbers)
        return side_label(sd, numbers)

    return name


def _direction_lines(sk, pg, corners, tag):
    """The direction lines of the unknowns, through the corner the book draws them from."""
    for k, u in pg.unknown:
        known = corners[k + 1] if k == 0 else corners[k]
        ends = [corners[k], corners[k + 1]]
        ts = [(p[0] - known[0]) * u[0] + (p[1] - known[1]) * u[1] for p in ends]
        lo, hi = min(ts + [0.0]) - OVERSHOOT, max(ts + [0.0]) + OVERSHOOT
        if hi - lo < 2.0:
            lo, hi = lo - 0.5, hi + 0.5
        color, lw, dashes = LINE_STYLE
        sk.line(
            [
                (known[0] + lo * u[0], known[1] + lo * u[1]),
                (known[0] + hi * u[0], known[1] + hi * u[1]),
            ],
            gid=f"{tag}-line-{k}",
            color=color,
            lw=lw,
            dashes=dashes,
            z=1,
            obstacle=False,
        )


def _chords(pg, sides, nonzero, name, numbers, tiny):
    """The whole forces read across the polygon: ``(also, chords)``, a chord that is one
    side named with it (side index -> `` = F32``, or its opposite), the others to draw."""
    also = {}
    chords = []
    for c, i, j in pg.chords:
        if math.hypot(*c.vector) <= tiny:
            continue
        between = [k for k in range(min(i, j), max(i, j)) if nonzero[k]]
        if len(between) == 1:  # the chord is that one side: named with it
            k = between[0]
            same = c.vector[0] * sides[k].vector[0] + c.vector[1] * sides[k].vector[1] > 0
            other = side_label(c, numbers)
            if not same:
                also[k] = f" = \u2212{other}"
            elif other != name(k):
                also[k] = f" = {other}"
            continue
        chords.append((c, i, j))
    return also, chords


def _polygon_sides(sk, pg, sides, nonzero, name, also, corners, scale, tag) -> list:
    """Each side of the polygon (not nil) an arrow from corner to corner, named; its row
    of words (size in N and cm, whether found) returned."""
    rows = []
    for k, sd in enumerate(sides):
        if not nonzero[k]:
            continue
        text = name(k) + also.get(k, "")
        color, lw, dashes = FORCE_STYLE[sd.what]
        a, b = corners[k], corners[k + 1]
        sk.arrow(a, b, f"{tag}-side-{k}", color, lw, dashes, z=4)
        sk.label(text, _along(a, b), LABEL_PT, gid=f"label-{tag}-side-{k}", color=color)
        found = " (found)" if any(k == u for u, _ in pg.unknown) else ""
        rows.append(
            f"{text}: {_magnitude(sd.vector)}, {scale.cm(math.hypot(*sd.vector)):.2f} cm{found}"
        )
    return rows


def _chord_arrows(sk, chords, corners, numbers, scale, tag) -> list:
    """Each whole force read across the polygon, a dashed arrow from corner to corner; its
    row of words returned."""
    rows = []
    for n, (c, i, j) in enumerate(chords):
        color, lw, dashes = CHORD_STYLE
        a, b = corners[i], corners[j]
        sk.arrow(a, b, f"{tag}-chord-{n}", color, lw, dashes, z=3)
        text = side_label(c, numbers)
        sk.label(text, _along(a, b), LABEL_PT, gid=f"label-{tag}-chord-{n}", color=color)
        rows.append(
            f"{text}: {_magnitude(c.vector)}, {scale.cm(math.hypot(*c.vector)):.2f} cm (across)"
        )
    return rows
