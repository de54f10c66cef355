"""The instantaneous-centre diagram: the mechanism to scale with every centre marked and
labelled (I13), the lines Kennedy's theorem used to find each one dashed, centres far off
the sheet shown by an arrow at the edge with their distance, centres at infinity by an
arrow and the sign of infinity; and beside it the circle diagram with its chords."""

from __future__ import annotations

import math

from ..common.tolerances import ON_PAPER, SAME, ULP
from ..polygons.scales import Scale
from .diagrams import _drive
from .mechanism import mechanism
from .sketch import _header, _Sketch, _text_size
from .style import SMALL_PT

CENTRE_COLOR = "#c0392b"
KENNEDY_LINE = ("#7f8c8d", 0.5, (3.0, 2.0))
#: where along its chord a centre's number may sit (fractions, most wanted first), and
#: the clearance (cm) beyond which a place is as good as any (half a centimetre)
_CHORD_SPOTS = (0.5, 0.45, 0.55, 0.4, 0.6, 0.35, 0.65, 0.3, 0.7, 0.25, 0.75, 0.2, 0.8)
_ROOM = 0.5
#: how far around the mechanism (times its size) the centres are drawn where they are;
#: less (``WINDOWS``, in turn) where that lets the paper hold the mechanism at a finer scale
WINDOW = 1.0
WINDOWS = (1.0, 0.75, 0.5)
#: the margin (times the mechanism's size) around the mechanism and the centres drawn
PAD = 0.3
#: the distances (cm) at which a label is tried around its centre: farther than on the
#: other diagrams, as centres crowd round the pins (a leader line leads back)
RINGS = (0.06, 0.2, 0.38, 0.6, 0.9, 1.3, 1.7, 2.2, 2.8)
#: how far (cm) a leader keeps from the labels and leaders placed before it: two leaders
#: side by side would read as one
LEADER_CLEAR = 0.12


def _window(P, centres=(), window=WINDOW):
    """The part of the plane the centres' diagram shows (cm): the mechanism and the
    centres within ``window`` times its size of it, with ``PAD`` times its size around
    them (no more: the rest of the sheet would only shrink the mechanism)."""
    xs = [p[0] for p in P.values()]
    ys = [p[1] for p in P.values()]
    w = max(max(xs) - min(xs), max(ys) - min(ys), 1.0)
    reach = (min(xs) - window * w, min(ys) - window * w, max(xs) + window * w, max(ys) + window * w)
    inside = [c for c in centres if _inside(reach, c)]
    xs += [c[0] for c in inside]
    ys += [c[1] for c in inside]
    pad = PAD * w
    return (
        max(min(xs) - pad, reach[0]),
        max(min(ys) - pad, reach[1]),
        min(max(xs) + pad, reach[2]),
        min(max(ys) + pad, reach[3]),
    )


def _inside(box, p):
    return box[0] <= p[0] <= box[2] and box[1] <= p[1] <= box[3]


def _clip(box, p, d):
    """The segment of the line p + t d inside ``box`` (Liang-Barsky), or None."""
    t0, t1 = -math.inf, math.inf
    for q, dq, lo, hi in ((p[0], d[0], box[0], box[2]), (p[1], d[1], box[1], box[3])):
        if abs(dq) < ULP:
            if not lo <= q <= hi:
                return None
            continue
        a, b = (lo - q) / dq, (hi - q) / dq
        t0, t1 = max(t0, min(a, b)), min(t1, max(a, b))
    if t0 > t1 or not (math.isfinite(t0) and math.isfinite(t1)):  # no direction: no line
        return None
    return (p[0] + t0 * d[0], p[1] + t0 * d[1]), (p[0] + t1 * d[0], p[1] + t1 * d[1])


def far_words(c, pivot_xy, pivot: str, unit: float, uname: str):
    """What the arrow of a centre off the sheet says, where it starts, and its direction:
    a centre at a distance from the crank's pivot (in the scene's unit), in the direction
    the arrow points, as the crank angle is measured (from +x, anticlockwise); a centre at
    infinity, the direction of the line it lies along (0 to 180 deg).

    >>> far_words(type("C", (), {"label": "I13", "point": (0.0, -2.0)})(), (0.0, 0.0),
    ...           "O", 0.001, "mm")
    ('I13: 2000 mm from O at 270\u00b0', (0.0, 0.0), (0.0, -2.0))
    """
    if c.point is not None:
        d = (c.point[0] - pivot_xy[0], c.point[1] - pivot_xy[1])
        far = math.hypot(*d) / unit
        angle = math.degrees(math.atan2(d[1], d[0])) % 360.0
        return (f"{c.label}: {far:.4g} {uname} from {pivot} at {_degrees(angle, 360)}", pivot_xy, d)
    d = c.direction
    angle = math.degrees(math.atan2(d[1], d[0])) % 180.0
    return f"{c.label} at \u221e, along {_degrees(angle, 180)}", None, d


def _degrees(angle: float, whole: int) -> str:
    """An angle to a tenth of a degree, 360 (or 180) written as 0."""
    text = f"{angle:.1f}".rstrip("0").rstrip(".")
    return ("0" if float(text) == whole else text) + "\u00b0"


def _solid_obstacles(sk):
    """On the centres' diagram a label keeps off the links' areas (not only their
    outlines: a centre's name inside a plate reads as a point of it), the cylinders and
    blocks, and every hatch; and a leader line keeps off them away from its own point."""
    from shapely.geometry import LineString, Polygon

    for kind, geo, st in sk.items:
        gid = st.get("gid") or ""
        if kind == "polygon" and gid.startswith(
            ("link-", "yoke-", "cylinder-", "block-", "slot-", "ground-")
        ):
            sk.solid.append(Polygon(geo).buffer(0.02))
        elif kind == "segments":
            sk.solid.extend(LineString(seg).buffer(0.03) for seg in geo)
    sk.obstacles.extend(sk.solid)


def _kennedy_lines(sk, ic, box, cm):
    """The lines that located the secondary centres (Kennedy's theorem), dashed, clipped to
    the window ``box``; ``cm``: a place in metres on the sketch (cm)."""
    color, lw, dashes = KENNEDY_LINE
    for key in ic.order:
        c = ic.centres[key]
        for a, b in c.lines:
            pts = [cm(x.point) for x in (a, b, c) if x.point is not None]
            if not pts:  # the line at infinity (two blocks on fixed guides): not drawn
                continue
            p0 = pts[0]
            p1 = max(pts[1:], key=lambda q: math.dist(q, p0), default=p0)
            if math.dist(p0, p1) > SAME * (box[2] - box[0]):
                d = (p1[0] - p0[0], p1[1] - p0[1])
            else:  # the known points at one place (two centres at one pin)
                inf = next((x for x in (a, b, c) if x.point is None), None)
                if inf is None:
                    continue  # a line through one point only: nothing to draw
                d = inf.direction
            seg = _clip(box, p0, d)
            if seg is not None:
                sk.line(
                    list(seg),
                    gid=f"kennedy-{c.label}-{a.label}-{b.label}",
                    color=color,
                    lw=lw,
                    dashes=dashes,
                    z=1,
                    obstacle="soft",
                    hint=False,
                )


def _centre_marks(sk, sol, ic, box, cm):
    """Each centre: a ring and its name where it is within the window ``box``, else an
    arrow at the edge towards it with its distance (from the crank's pivot; a driving block
    has none: from the first fixed point)."""
    unit, uname = sol.scene.length_unit, sol.scene.units
    mid = ((box[0] + box[2]) / 2, (box[1] + box[3]) / 2)
    pivot = sol.scene.input.pivot or next(iter(sol.scene.ground))
    for key in ic.order:
        c = ic.centres[key]
        if c.point is not None and _inside(box, cm(c.point)):
            where = cm(c.point)
            sk.circle(
                where,
                0.07,
                gid=f"centre-{c.label}",
                face="#ffffff",
                edge=CENTRE_COLOR,
                lw=1.0,
                z=7,
            )
            sk.label(
                c.label,
                [where],
                SMALL_PT + 1,
                gid=f"label-{c.label}",
                color=CENTRE_COLOR,
                point=True,
            )
            continue
        text, start, d = far_words(c, sol.P[pivot], pivot, unit, uname)
        start = cm(start) if start is not None else mid
        n = math.hypot(*d)
        d = (d[0] / n, d[1] / n)
        seg = _clip(box, start, d)
        tip = seg[1] if seg is not None else start
        tail = (tip[0] - 0.9 * d[0], tip[1] - 0.9 * d[1])
        sk.arrow(tail, tip, f"centre-{c.label}", CENTRE_COLOR, 1.0)
        sk.label(text, [tip], SMALL_PT, gid=f"label-{c.label}", color=CENTRE_COLOR, point=True)


def centres_sketch(sol, scale: Scale, ic, window: float = WINDOW) -> _Sketch:
    """The mechanism with its instantaneous centres (``ic``: a located ``Centres``), those
    within ``window`` times the mechanism's size of it where they are, the others by an
    arrow at the edge."""
    s = scale.per_cm
    sk = _Sketch()

    def cm(p):
        return (p[0] / s, p[1] / s)

    def extra(sk, P):
        _solid_obstacles(sk)
        box = _window(
            P,
            [cm(ic.centres[k].point) for k in ic.order if ic.centres[k].point is not None],
            window,
        )
        _kennedy_lines(sk, ic, box, cm)
        _centre_marks(sk, sol, ic, box, cm)

    sk.rings = RINGS
    sk.leader_clear = LEADER_CLEAR
    mechanism(sk, sol, scale, extra)
    n = ic.n
    _header(
        sk,
        "centres",
        "Instantaneous centres",
        scale,
        lines=[
            _drive(sol),
            f"{n} links, N = {n * (n - 1) // 2} centres; dashed: the lines of Kennedy's theorem",
        ],
    )
    return sk


#: the circle diagram's radius (cm), and the smaller one where that keeps it on the page
CIRCLE_RADIUS, CIRCLE_SMALL = 2.6, 1.9


def _chord_numbers(sk, chords, pos):
    """Each secondary centre's number on its own chord, on a white patch, where it keeps
    clearest of the other chords, the other numbers and the links' points ``pos``."""
    from shapely.geometry import Point, box

    taken = [Point(p).buffer(0.3) for p in pos.values()]
    nth = 0
    for c, chord in chords:
        if c.primary:
            continue
        nth += 1
        text = f"{nth}"
        w, h = _text_size(text, SMALL_PT)
        w, h = w + 0.08, h + 0.02
        others = [g for d, g in chords if d is not c]
        best = None
        for t in _CHORD_SPOTS:
            m = chord.interpolate(t, normalized=True)
            patch = box(m.x - w / 2, m.y - h / 2, m.x + w / 2, m.y + h / 2)
            gap = min([patch.distance(g) for g in others + taken] + [_ROOM])
            if best is None or gap > best[0] + ON_PAPER:
                best = (gap, m.x, m.y, patch)
        _, x, y, patch = best
        taken.append(patch)
        sk.polygon(
            list(patch.exterior.coords),
            gid=f"chord-order-{c.label}-patch",
            face="#ffffff",
            edge="#ffffff",
            lw=0.0,
            z=3,
            obstacle=None,
        )
        sk.note(x, y, text, SMALL_PT, ha="center", gid=f"chord-order-{c.label}", color="#1f5fbf")


def _circle_notes(sk):
    """The labels placed, and the diagram's title and key above it."""
    sk.place_labels()
    x0, y0, x1, y1 = sk.content_box()
    top = y1 + 0.4
    rows = [
        "Circle diagram",
        "solid: primary centres (joints)",
        "dashed: by Kennedy's theorem,",
        "numbered as found",
    ]
    for i, text in enumerate(reversed(rows)):
        sk.note(
            x0,
            top + 0.45 * i,
            text,
            SMALL_PT + (3.5 if i == len(rows) - 1 else 0),
            gid=f"note-circle-{i}",
            weight="bold" if i == len(rows) - 1 else "normal",
        )


def circle_sketch(ic, radius: float = CIRCLE_RADIUS) -> _Sketch:
    """The circle diagram: the links as points 1..n round a circle, a chord for each centre
    (solid: primary, from a joint; dashed: by Kennedy's theorem, numbered in the order
    found)."""
    from shapely.geometry import LineString

    sk = _Sketch()
    n = ic.n
    pos = {
        k: (
            radius * math.cos(math.pi / 2 - 2 * math.pi * (k - 1) / n),
            radius * math.sin(math.pi / 2 - 2 * math.pi * (k - 1) / n),
        )
        for k in range(1, n + 1)
    }
    ring = [
        (radius * math.cos(2 * math.pi * t / 96), radius * math.sin(2 * math.pi * t / 96))
        for t in range(97)
    ]
    sk.line(ring, gid="circle", color="#999999", lw=0.5, obstacle=False, hint=False, z=1)
    chords = []  # (centre, its chord as a line)
    for key in ic.order:
        c = ic.centres[key]
        a, b = pos[c.i], pos[c.j]
        chords.append((c, LineString([a, b])))
        if c.primary:
            sk.line(
                [a, b],
                gid=f"chord-{c.label}",
                color="#000000",
                lw=0.9,
                z=2,
                obstacle=False,
                hint=False,
            )
        else:
            sk.line(
                [a, b],
                gid=f"chord-{c.label}",
                color="#1f5fbf",
                lw=0.9,
                dashes=(4, 2),
                z=2,
                obstacle=False,
                hint=False,
            )
    _chord_numbers(sk, chords, pos)
    for k, p in pos.items():
        sk.circle(p, 0.09, gid=f"circle-point-{k}", face="#000000", z=6)
        out = (p[0] * (1 + 0.5 / radius), p[1] * (1 + 0.5 / radius))
        sk.label(str(k), [out], SMALL_PT + 2, gid=f"circle-label-{k}", weight="bold")
    _circle_notes(sk)
    return sk
