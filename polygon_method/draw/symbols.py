"""The textbook's symbols on a configuration diagram: the ground's hatching, a block on its
guide, a slot, a yoke's bar, a shape a step draws (a wheel, a pitch circle, a cylinder), the
crank angle's arc and its label, each placed clear of the links."""

from __future__ import annotations

import math

from ..common.tolerances import ON_PAPER, ROUNDING
from .style import BAR, BLOCK_CLEAR, BLOCK_MIN, JOINT_R, MARK_PT, PIN_ZONE

__all__ = [
    "SLOT_W",
    "ARC_CLEAR",
    "ARC_GAP",
    "step_shape",
    "deg",
    "yoke_bar",
    "slot_half",
    "block_size",
    "rect",
    "fixed_guide",
    "ground_symbol",
    "crank_arc",
    "crank_angle_shapes",
    "crank_angle",
    "crank_angle_label",
]

#: the least distance (cm) of the crank-angle arc from another point
ARC_CLEAR = 0.25
#: the least gap (cm) between the crank-angle arc and a fixed pivot's bracket
ARC_GAP = 0.1


def step_shape(sk, shape, s, tag):
    """One of a step's shapes (``Step.shapes``, metres) drawn at ``s`` metres per cm;
    a contact point is returned (drawn with the joints)."""
    kind = shape[0]
    if kind == "circle":
        (cx, cy), r = (shape[1][0] / s, shape[1][1] / s), shape[2] / s
        pts = [
            (cx + r * math.cos(2 * math.pi * k / 96), cy + r * math.sin(2 * math.pi * k / 96))
            for k in range(97)
        ]
        sk.line(
            pts, gid=f"pitch-{tag}", color="#333333", lw=0.7, dashes=(6, 2, 1, 2), z=1, hint=False
        )
        return None
    if kind == "ground line":
        (x, y), (ux, uy), (nx, ny) = (shape[1][0] / s, shape[1][1] / s), shape[2], shape[3]
        a, b = (x - 2.0 * ux, y - 2.0 * uy), (x + 2.0 * ux, y + 2.0 * uy)
        sk.line([a, b], gid=f"rolling-line-{tag}", lw=1.0, z=2)
        hatch = []
        for i in range(14):
            t = -1.85 + i * 3.7 / 13
            p = (x + t * ux, y + t * uy)
            hatch.append((p, (p[0] - 0.18 * nx - 0.18 * ux, p[1] - 0.18 * ny - 0.18 * uy)))
        sk.segments(hatch, gid=f"rolling-line-{tag}-hatch", lw=0.5, z=2)
        return None
    if kind == "contact":
        return (shape[1][0] / s, shape[1][1] / s)
    return None


def deg(rad: float) -> str:
    """An angle (rad) as the drawing writes it: "45°"."""
    d = math.degrees(rad)
    return f"{d:.4g}\u00b0"


def yoke_bar(sc, sl, P):
    """The yoke of a Scotch yoke: a bar through its block Y along its slot, reaching past
    the pin's block at P on both sides (the slot's length over the pin's travel)."""
    from shapely.geometry import MultiPoint

    (yx, yy), (px, py), (dx, dy) = P[sl.yoke], P[sl.point], sl.direction
    t = (px - yx) * dx + (py - yy) * dy
    reach = max(abs(t), 1.0) + block_size(sc, sl.point, P)
    arm = None
    if getattr(sl, "offset", 0.0):  # an offset slot: the bar along it, an arm out to Y
        fx, fy = px - t * dx, py - t * dy  # the foot of Y on the slot's centre line
        arm = MultiPoint([(yx, yy), (fx, fy)]).convex_hull.buffer(BAR / 2, quad_segs=8)
        yx, yy = fx, fy
    ends = [(yx - reach * dx, yy - reach * dy), (yx + reach * dx, yy + reach * dy)]
    bar = MultiPoint(ends).convex_hull.buffer(BAR / 2, quad_segs=8)
    return bar if arm is None else bar.union(arm)


#: a slot's half-width (cm): the pin's circle and a little play
SLOT_W = 1.6 * JOINT_R


def slot_half(size):
    """Half the length of the slot drawn around a peg (cm), for a block of ``size``."""
    return 0.8 * size


def block_size(sc, point, P):
    """A slider block's length (cm): 0.9, less on short links so the block does not hide
    them, and less again where another pin lies near (the end of a short lever beside its
    block): the block never covers another point's pin (it is 0.55 as wide as long; at
    least 0.35 long)."""
    near = [math.dist(P[point], P[lk.other(point)]) for lk in sc.links if point in lk.points]
    size = min(0.9, max(0.5, 0.45 * min(near, default=2.0)))
    X = P[point]
    for q in sc.point_names:
        d = math.dist(P[q], X)
        if q == point or d < ON_PAPER:
            continue
        # the rectangle's half-diagonal reaches sqrt(1 + 0.55^2) / 2 of its length
        room = (d - JOINT_R - BLOCK_CLEAR) / (0.5 * math.hypot(1.0, 0.55))
        size = min(size, max(room, BLOCK_MIN))
    return size


def rect(c, u, length, width):
    """The corners of a rectangle centred at ``c``, its length along the unit ``u``."""
    ux, uy = u
    nx, ny = -uy, ux
    a, b = length / 2, width / 2
    return [
        (c[0] + sx * a * ux + sy * b * nx, c[1] + sx * a * uy + sy * b * ny)
        for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))
    ]


def fixed_guide(sk, sc, sl, P, s, away=None):
    """The line of stroke (chain-dotted, through the path's given point where that is
    among the mechanism's points: one given far along the path draws no line to it) and
    the guide's wall on the side away from the connecting link, hatched."""
    X = P[sl.point]
    ux, uy = sl.u
    nx, ny = -uy, ux
    tx, ty = sl.through[0] / s, sl.through[1] / s
    along = [(p[0] - X[0]) * ux + (p[1] - X[1]) * uy for p in P.values()]
    t_through = min(max((tx - X[0]) * ux + (ty - X[1]) * uy, min(along)), max(along))
    lo, hi = min(-1.8, t_through - 0.5), max(1.8, t_through + 0.5)
    sk.line(
        [(X[0] + lo * ux, X[1] + lo * uy), (X[0] + hi * ux, X[1] + hi * uy)],
        gid=f"stroke-{sl.point}",
        color="#555555",
        lw=0.5,
        dashes=(6, 2, 1, 2),
        z=1,
    )
    rod = away or next((P[lk.other(sl.point)] for lk in sc.links if sl.point in lk.points), None)
    side = 1.0
    if rod is not None and ((rod[0] - X[0]) * nx + (rod[1] - X[1]) * ny) > 0:
        side = -1.0
    off = 0.55 * block_size(sc, sl.point, P) / 2 + 0.02
    a = (X[0] - 1.6 * ux + side * off * nx, X[1] - 1.6 * uy + side * off * ny)
    b = (X[0] + 1.6 * ux + side * off * nx, X[1] + 1.6 * uy + side * off * ny)
    sk.line([a, b], gid=f"guide-{sl.point}", lw=1.0, z=2)
    hatch = []
    for i in range(12):
        t = -1.42 + i * 3.02 / 11
        p = (X[0] + t * ux + side * off * nx, X[1] + t * uy + side * off * ny)
        q = (p[0] + side * 0.18 * nx - 0.18 * ux, p[1] + side * 0.18 * ny - 0.18 * uy)
        hatch.append((p, q))
    sk.segments(hatch, gid=f"guide-{sl.point}-hatch", lw=0.5, z=2)
    far = (a[0] + side * 0.2 * nx, a[1] + side * 0.2 * ny)
    far2 = (b[0] + side * 0.2 * nx, b[1] + side * 0.2 * ny)
    from shapely.geometry import Polygon

    sk.obstacles.append(Polygon([a, b, far2, far]).buffer(0.02))
    sk.bounds.append(
        (
            min(a[0], far[0], b[0], far2[0]),
            min(a[1], far[1], b[1], far2[1]),
            max(a[0], far[0], b[0], far2[0]),
            max(a[1], far[1], b[1], far2[1]),
        )
    )


#: the turns of a fixed pivot's bracket tried, in 15 deg steps from below: nearest first
_BRACKET_TURNS = (0, *[k for j in range(1, 12) for k in (-j, j)], 12)


def _bracket_turn(g, near, solid, soft, zone) -> float:
    """The angle (rad) at which the bracket of the fixed pivot at ``g`` points from the pin
    (see :func:`ground_symbol`): the first clear of everything, else the least overlap."""
    from shapely.geometry import LineString, Point, Polygon
    from shapely.ops import unary_union

    bodies = unary_union(solid) if solid else None
    spots = [Point(p).buffer(0.12, quad_segs=4) for p in near]
    d, half, wide = 0.5, 0.3, 0.42
    best, best_cost = -math.pi / 2, (math.inf, math.inf)
    for k in _BRACKET_TURNS:
        th = -math.pi / 2 + k * math.pi / 12
        dx, dy = math.cos(th), math.sin(th)
        nx, ny = -dy, dx
        base = (g[0] + d * dx, g[1] + d * dy)
        far = (base[0] + 0.2 * dx, base[1] + 0.2 * dy)
        foot = (
            Polygon(
                [
                    g,
                    (base[0] + half * nx, base[1] + half * ny),
                    (base[0] - half * nx, base[1] - half * ny),
                ]
            )
            .union(
                Polygon(
                    [
                        (base[0] + wide * nx, base[1] + wide * ny),
                        (base[0] - wide * nx, base[1] - wide * ny),
                        (far[0] - wide * nx, far[1] - wide * ny),
                        (far[0] + wide * nx, far[1] + wide * ny),
                    ]
                )
            )
            .union(LineString([base, far]).buffer(0.01))
            .difference(zone)
        )
        hard = (foot.intersection(bodies).area if bodies is not None else 0.0) + sum(
            foot.intersection(q).area for q in spots
        )
        cost = (round(hard, 9), round(sum(foot.intersection(q).area for q in soft), 9))
        if cost == (0.0, 0.0):
            return th
        if cost < best_cost:
            best, best_cost = th, cost
    return best


def ground_symbol(sk, name, g, near, solid, soft=()):
    """A fixed pivot: a bracket (triangle) from the pin to a hatched base, below the pin
    where that keeps it off every link and block beyond the pin (``PIN_ZONE`` around it,
    where the link's rounded end and the bracket meet), off the points ``near`` it and off
    the ``soft`` shapes (the crank angle's sector and reference line); else turned as
    little from below as that needs (15 deg steps); else where it overlaps the links and
    points least, and of those the soft shapes least. Returns what it drew beyond the
    pin's zone (a shape)."""
    from shapely.geometry import LineString, MultiLineString, Point, Polygon

    zone = Point(g).buffer(PIN_ZONE, quad_segs=8)
    best = _bracket_turn(g, near, solid, soft, zone)
    dx, dy = math.cos(best), math.sin(best)
    nx, ny = -dy, dx
    d, half, wide = 0.5, 0.3, 0.42
    base = (g[0] + d * dx, g[1] + d * dy)
    tri = [
        g,
        (base[0] + half * nx, base[1] + half * ny),
        (base[0] - half * nx, base[1] - half * ny),
    ]
    sk.polygon(tri, gid=f"ground-{name}", face="#ffffff", edge="#000000", lw=0.8, z=4)
    sk.line(
        [(base[0] + wide * nx, base[1] + wide * ny), (base[0] - wide * nx, base[1] - wide * ny)],
        gid=f"ground-{name}-base",
        lw=1.0,
        z=4,
    )
    hatch = []
    for i in range(6):
        t = -wide + 0.17 + i * (2 * wide - 0.17) / 5
        p = (base[0] + t * nx, base[1] + t * ny)
        hatch.append((p, (p[0] + 0.17 * dx - 0.17 * nx, p[1] + 0.17 * dy - 0.17 * ny)))
    sk.segments(hatch, gid=f"ground-{name}-hatch", lw=0.5, z=4)
    far = (base[0] + 0.2 * dx, base[1] + 0.2 * dy)
    sk.obstacles.append(
        Polygon(
            [
                (base[0] + (wide + 0.2) * nx, base[1] + (wide + 0.2) * ny),
                (base[0] - (wide + 0.2) * nx, base[1] - (wide + 0.2) * ny),
                (far[0] - (wide + 0.2) * nx, far[1] - (wide + 0.2) * ny),
                (far[0] + (wide + 0.2) * nx, far[1] + (wide + 0.2) * ny),
            ]
        )
    )
    for p, q in hatch:
        sk._bound([p, q])
    # what was drawn, beyond the pin's own zone
    return (
        Polygon(tri)
        .union(
            LineString(
                [
                    (base[0] + wide * nx, base[1] + wide * ny),
                    (base[0] - wide * nx, base[1] - wide * ny),
                ]
            ).buffer(0.02)
        )
        .union(MultiLineString(hatch).buffer(0.02))
        .difference(zone)
    )


def crank_arc(sc, P, feet=()):
    """(pivot, signed angle, radius) of the crank-angle arc. The radius is 0.55 of the
    crank (0.45 to 1.4 cm, 0.6 short of the crank pin), moved (0.05 cm steps, nearest
    first, 0.45 cm at least, short of the crank pin) where that arc would pass within
    ``ARC_CLEAR`` of another point's pin or within ``ARC_GAP`` of a fixed pivot's bracket
    (``feet``: the shapes drawn), so that the arc is never read as part of another joint or
    its bracket; where none short of the crank pin does, the nearest beyond it that does
    (the crank produced to it); as it was where no radius clears them all."""
    inp = sc.input
    if inp.pivot is None:  # a block drives: no crank angle to mark (an empty arc)
        return (P[inp.tip], 0.0, 0.0)
    O = P[inp.pivot]
    # the angle the scene states, the way it states it (270 deg ccw is not 90 deg cw), less
    # whole turns
    th = math.copysign(math.fmod(abs(inp.angle), 2 * math.pi), inp.angle)
    if abs(abs(th) - 2 * math.pi) < ROUNDING:
        th = 0.0
    crank = math.dist(O, P[inp.tip])
    r = min(max(min(0.55 * crank, crank - 0.6), 0.45), 1.4)
    if abs(th) < ON_PAPER:
        return O, th, r
    others = [P[q] for q in sc.point_names if q not in (inp.pivot, inp.tip)]
    lo, hi = 0.45, max(0.45, min(1.4, crank - JOINT_R - ARC_CLEAR))

    def clear(rad):
        if not all(arc_distance(O, th, rad, q) >= ARC_CLEAR for q in others):
            return False
        line = arc_line(O, th, rad) if feet else None
        return all(line.distance(f) >= ARC_GAP for f in feet)

    if not clear(r):
        for k in range(1, 40):
            for cand in (r - 0.05 * k, r + 0.05 * k):
                if lo - ON_PAPER <= cand <= hi + ON_PAPER and clear(cand):
                    return O, th, cand
        # none short of the crank pin (a short crank, its pivot's bracket in the angle's
        # sector): beyond the pin, round the bracket, the crank produced to the arc
        beyond = max(hi, crank + JOINT_R + ARC_CLEAR)
        for k in range(40):
            if clear(beyond + 0.05 * k):
                return O, th, beyond + 0.05 * k
    return O, th, r


def arc_distance(O, th, r, q):
    """Distance from the point ``q`` to the arc of radius ``r`` about ``O`` from angle 0
    to ``th``."""
    phi = math.atan2(q[1] - O[1], q[0] - O[0])
    lo, hi = min(0.0, th), max(0.0, th)
    phi = (
        phi
        if lo <= phi <= hi
        else phi - 2 * math.pi
        if lo <= phi - 2 * math.pi <= hi
        else phi + 2 * math.pi
        if lo <= phi + 2 * math.pi <= hi
        else None
    )
    if phi is not None:
        return abs(math.dist(O, q) - r)
    return min(math.dist(q, (O[0] + r * math.cos(a), O[1] + r * math.sin(a))) for a in (0.0, th))


def arc_line(O, th, r):
    """The arc of radius ``r`` about ``O`` from 0 to ``th`` (rad) as a polyline (shapely)."""
    from shapely.geometry import LineString

    n = max(8, int(abs(math.degrees(th)) / 3))
    return LineString(
        [(O[0] + r * math.cos(th * i / n), O[1] + r * math.sin(th * i / n)) for i in range(n + 1)]
    )


def crank_angle_shapes(arc):
    """The crank angle's sector (out to a little beyond its arc) and reference line as
    shapes: where the angle is read, which a bracket keeps off."""
    from shapely.geometry import LineString, Polygon

    O, th, r = arc
    if abs(th) < ON_PAPER:
        return []
    n = max(8, int(abs(math.degrees(th)) / 3))
    arc = [
        (O[0] + (r + 0.1) * math.cos(th * i / n), O[1] + (r + 0.1) * math.sin(th * i / n))
        for i in range(n + 1)
    ]
    return [
        Polygon([O] + arc),
        LineString([(O[0] + PIN_ZONE, O[1]), (O[0] + r + 0.5, O[1])]).buffer(0.05),
    ]


def crank_angle(sk, arc, crank=math.inf):
    """The crank angle: a reference line along +x from the crank's pivot and an arc from it
    to the crank (of length ``crank``, cm), produced to the arc where the arc lies beyond it."""
    O, th, r = arc
    if abs(th) < ON_PAPER:
        return
    if r > crank:
        sk.line(
            [
                (O[0] + crank * math.cos(th), O[1] + crank * math.sin(th)),
                (O[0] + (r + 0.15) * math.cos(th), O[1] + (r + 0.15) * math.sin(th)),
            ],
            gid="crank-produced",
            color="#555555",
            lw=0.5,
            dashes=(6, 2, 1, 2),
            z=1,
        )
    sk.line(
        [O, (O[0] + r + 0.5, O[1])],
        gid="crank-reference",
        color="#555555",
        lw=0.5,
        dashes=(6, 2, 1, 2),
        z=1,
    )
    n = max(8, int(abs(math.degrees(th)) / 3))
    pts = [(O[0] + r * math.cos(th * i / n), O[1] + r * math.sin(th * i / n)) for i in range(n + 1)]
    sk.line(pts, gid="crank-angle", lw=0.6, z=3, hint=False)


def crank_angle_label(sk, arc):
    """The crank angle's value written beside its arc (``arc``: centre, angle, radius), where it is
    clear."""
    O, th, r = arc
    if abs(th) < ON_PAPER:
        return
    mids = [(O[0] + r * math.cos(th * f), O[1] + r * math.sin(th * f)) for f in (0.5, 0.3, 0.7)]
    sk.label(deg(abs(th)), mids, MARK_PT, gid="label-crank-angle", leader=True)


# --------------------------------------------------------------------------- polygons
