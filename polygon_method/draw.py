"""True-to-scale diagrams: the configuration (space) diagram, the velocity polygon and the
acceleration polygon, drawn as a student draws them, to a scale a ruler can check.

Everything drawn comes from the :class:`~polygon_method.solution.Solution` and the
construction records of :mod:`polygon_method.constructions`; nothing here redoes the
kinematics. Each diagram is laid out in *centimetres of paper*: a quantity ``q`` (SI) is
drawn ``q / per_cm`` cm long, and the figure is sized so that one unit of the axes is one
centimetre on the page (figure inches = extent in cm / 2.54, no tight-bbox rescaling).
Printed at 100 %, a vector drawn 3.92 cm long at ``1 cm = 0.1 m/s`` is 0.392 m/s.

The drawing functions take a matplotlib Axes and return the artists they made::

    draw_configuration(ax, sol, scale)   draw_velocity(ax, sol, scale)
    draw_acceleration(ax, sol, scale)

:func:`make_figure` puts one or all three side by side on a sheet of the right physical
size; :func:`render` returns SVG text, PNG or PDF bytes (the command line writes them).
matplotlib is imported only inside these functions, so that ``import polygon_method`` and
``solve`` stay fast.

Labels are placed by trying positions around each point (shapely boxes) and taking the
first whose box touches no line, arrow, outline or other label and is nearer to its own point
than to any other; a label that has to stand off gets a leader line.

>>> import polygon_method as pm
>>> sol = pm.solve(pm.parse_scene('''
... [ground]
... O = [0, 0]
... [links]
... OA = 150
... AB = 600
... [sliders]
... B = { path = "horizontal" }
... [input]
... crank = "OA"
... angle = 60
... speed = "10 rad/s ccw"
... '''))
>>> svg, scales, warnings = render(sol, "svg", "all")
>>> [str(s) for s in scales.values()]
['1 cm = 100 mm', '1 cm = 0.2 m/s', '1 cm = 2 m/s^2']
>>> svg.startswith("<?xml") and 'id="velocity-vector-0-shaft"' in svg
True
"""

from __future__ import annotations

import io
import math
import re
import sys
from dataclasses import dataclass, field

from .constructions import acceleration_constructions, image_label, velocity_constructions
from .errors import PolygonMethodError
from .scales import Scale, choose_scale, diagram_scales, parse_scale
from .scene import FixedPath

__all__ = ["draw_configuration", "draw_velocity", "draw_acceleration", "make_figure",
           "render", "svg_string", "choose_scales", "drawn_vectors",
           "DIAGRAMS", "CM_PER_INCH", "PT_PER_CM"]

CM_PER_INCH = 2.54
PT_PER_CM = 72.0 / 2.54
DIAGRAMS = ("configuration", "velocity", "acceleration")
KIND_OF_DIAGRAM = {"configuration": "length", "velocity": "velocity",
                   "acceleration": "acceleration"}
FORMATS = ("svg", "png", "pdf")
FONT = "DejaVu Sans"
PNG_DPI = 200

#: A4 portrait for one diagram, A4 landscape for the three side by side (cm)
SHEET_ONE = (21.0, 29.7)
SHEET_ALL = (29.7, 21.0)
MARGIN = 0.8  # sheet margin (cm)
GAP = 0.8  # between panels (cm)
#: the largest figure any scale may make (cm): beyond A0 it is a mistake in the scale
MAX_FIGURE_CM = 120.0

# sizes on paper (cm) and in points (text, line widths)
BAR = 0.28  # width of a link drawn as a bar
JOINT_R = 0.08  # a pin joint's circle
DOT_R = 0.045  # an image point
POLE_R = 0.06
HEAD_LEN, HEAD_HALF = 0.26, 0.075  # arrowheads
OVERSHOOT = 0.6  # how far a direction line runs past the points it joins
LABEL_PT, MARK_PT, NOTE_PT, TITLE_PT, SMALL_PT = 10.0, 7.5, 8.5, 10.5, 7.0
CLEAR = 0.05  # clearance of a label from any line (cm)

#: line styles of the vectors by kind (colour, width in pt, dashes or None)
STYLE = {
    "absolute": ("#000000", 1.5, None),
    "relative": ("#000000", 0.9, None),
    "sliding": ("#7b3294", 1.1, (5.0, 1.5, 1.0, 1.5)),
    "centripetal": ("#1f5fbf", 1.2, None),
    "tangential": ("#d95f02", 1.2, (4.0, 1.5)),
    "coriolis": ("#1a9641", 2.2, None),
}
#: which of two coinciding vectors is drawn (the first in this order)
PRIORITY = ("absolute", "coriolis", "centripetal", "tangential", "sliding", "relative")
LINE_STYLE = ("#777777", 0.6, (4.0, 2.5))  # construction (direction) lines
LEGEND_NAMES = {"absolute": "total (from the pole)", "relative": "relative (between images)",
                "centripetal": "centripetal component", "tangential": "tangential component",
                "coriolis": "Coriolis component", "sliding": "sliding component"}
BODY_FACE, BODY_EDGE = "#dde6f2", "#23395d"
IMAGE_FACE = "#f4d35e"


# --------------------------------------------------------------------------- scales


def display_unit(text: str) -> str:
    return text.replace("^2", "\u00b2")


def _scale_unit(kind: str, sol) -> str:
    return {"length": sol.scene.units, "velocity": "m/s", "acceleration": "m/s^2"}[kind]


def _extents_si(sol, diagram):
    """Width and height (SI) of what a diagram must show: the mechanism's points, or the
    pole and every point and vector end of a polygon."""
    if diagram == "configuration":
        pts = list(sol.P.values())
    else:
        pts = [(0.0, 0.0)] + [p for v in drawn_vectors(sol, diagram) for p in (v.start, v.end)]
        pts += list((sol.V if diagram == "velocity" else sol.A).values())
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    return max(xs) - min(xs), max(ys) - min(ys)


def _room(diagram: str, n: int):
    """(width, height) in cm left for the geometry of one panel on its sheet: the sheet
    less its margins, the gaps, a header and room for labels around the figure."""
    sw, sh = SHEET_ALL if n > 1 else SHEET_ONE
    w = (sw - 2 * MARGIN - (n - 1) * GAP) / min(n, 2)  # (the sheet is shared out later)
    h = sh - 2 * MARGIN
    header = 4.2 if diagram == "acceleration" else 3.0
    return w - 1.6, h - header - 1.6


def _fit_scale(sol, diagram, room) -> Scale:
    """The smallest textbook-round scale at which the diagram fits ``room`` (cm)."""
    ex, ey = _extents_si(sol, diagram)
    need = max(ex / room[0], ey / room[1])
    unit = _scale_unit(KIND_OF_DIAGRAM[diagram], sol)
    return choose_scale(need, 1.0, unit=unit)


def _coarser(scale: Scale) -> Scale:
    """The next round scale after ``scale`` (the drawing gets smaller)."""
    return choose_scale(scale.per_cm * (1 + 1e-9), 1.0, unit=scale.unit)


def _finer(scale: Scale) -> Scale:
    """The round scale before ``scale`` (the drawing gets larger)."""
    s = choose_scale(scale.per_cm / 2.6, 1.0, unit=scale.unit)
    while True:
        n = _coarser(s)
        if n.per_cm >= scale.per_cm * (1 - 1e-9):
            return s
        s = n


def choose_scales(sol, diagram: str = "all", given=None) -> dict:
    """First choice of each diagram's scale: ``given`` ones (by diagram name or kind) are
    kept, the others are the smallest textbook-round scales at which the diagram's points
    fit the room a panel can have on an A4 page (portrait for one diagram, landscape for
    three side by side). :func:`layout` then coarsens them until the labelled sheet fits."""
    names = DIAGRAMS if diagram == "all" else (diagram,)
    given = dict(given or {})
    out = {}
    for name in names:
        s = given.get(name) or given.get(KIND_OF_DIAGRAM[name])
        if s is None and len(names) == 1:  # one diagram: the scale `steps` states
            s = dict(zip(DIAGRAMS, diagram_scales(sol)))[name]
        out[name] = s if s is not None else _fit_scale(sol, name, _room(name, len(names)))
    return out


def parse_scales(texts) -> dict:
    """``--scale`` arguments (possibly repeated) -> {kind: Scale}; a kind given twice is an
    error."""
    out = {}
    for text in texts or ():
        try:
            s = parse_scale(text)
        except PolygonMethodError as exc:
            raise PolygonMethodError(exc.message, key="--scale") from None
        if s.kind in out:
            raise PolygonMethodError(f"two {s.kind} scales given ({out[s.kind]} and {s})",
                                     key="--scale")
        out[s.kind] = s
    return out


# --------------------------------------------------------------------------- text sizes

_MEASURE = {}


def _text_size(text: str, size: float, weight: str = "normal"):
    """(width, height) in cm of the layout box matplotlib gives ``text`` at ``size`` pt
    (measured with the SVG renderer, whose points are the page's points)."""
    key = (text, size, weight)
    got = _MEASURE.get(key)
    if got is None:
        from matplotlib.backends.backend_svg import RendererSVG
        from matplotlib.text import Text
        if "renderer" not in _MEASURE:
            from matplotlib.figure import Figure
            fig = Figure(dpi=72)
            _MEASURE["renderer"] = (RendererSVG(100, 100, io.StringIO(), image_dpi=72), fig)
        renderer, fig = _MEASURE["renderer"]
        t = Text(0, 0, text, fontsize=size, fontfamily=FONT, fontweight=weight,
                 ha="center", va="center", parse_math=False, figure=fig)
        bb = t.get_window_extent(renderer)
        got = (bb.width / PT_PER_CM, bb.height / PT_PER_CM)
        _MEASURE[key] = got
    return got


# --------------------------------------------------------------------------- a sketch


@dataclass
class _Label:
    text: str
    anchors: list
    size: float
    gid: str
    color: str = "#000000"
    weight: str = "normal"
    box: tuple | None = None  # (cx, cy, w, h) once placed
    point: bool = False  # names a point: must be nearer to it than to any other point
    leader: bool = False  # drawn with a leader line when far from its anchor


@dataclass
class _Sketch:
    """What a panel draws, in centimetres of paper, before any matplotlib artist exists:
    the items, the obstacles a label must keep clear of, and the labels to place."""

    items: list = field(default_factory=list)
    obstacles: list = field(default_factory=list)  # shapely geometries
    hints: list = field(default_factory=list)  # segments, for the direction a label avoids
    labels: list = field(default_factory=list)
    notes: list = field(default_factory=list)  # fixed texts (header)
    warnings: list = field(default_factory=list)
    bounds: list = field(default_factory=list)  # (xmin, ymin, xmax, ymax) of the content

    # -- primitives (coordinates in cm)
    def line(self, pts, gid=None, color="#000000", lw=0.8, dashes=None, z=3, obstacle=True,
             hint=True):
        pts = [tuple(map(float, p)) for p in pts]
        self.items.append(("line", pts, dict(color=color, lw=lw, dashes=dashes, z=z, gid=gid)))
        self._bound(pts)
        if obstacle and len(pts) > 1:
            from shapely.geometry import LineString
            self.obstacles.append(LineString(pts).buffer(lw / PT_PER_CM / 2))
        if hint:
            self.hints.extend(zip(pts[:-1], pts[1:]))

    def polygon(self, pts, gid=None, face="none", edge="#000000", lw=0.8, z=2, alpha=1.0,
                obstacle="area"):
        pts = [tuple(map(float, p)) for p in pts]
        self.items.append(("polygon", pts, dict(face=face, edge=edge, lw=lw, z=z, gid=gid,
                                                 alpha=alpha)))
        self._bound(pts)
        if obstacle:
            from shapely.geometry import LinearRing, Polygon
            g = Polygon(pts) if obstacle == "area" else LinearRing(pts)
            self.obstacles.append(g.buffer(lw / PT_PER_CM / 2) if obstacle == "edge" else g)

    def segments(self, segs, gid=None, color="#000000", lw=0.6, z=3):
        segs = [[tuple(map(float, a)), tuple(map(float, b))] for a, b in segs]
        self.items.append(("segments", segs, dict(color=color, lw=lw, z=z, gid=gid)))
        for s in segs:
            self._bound(s)

    def circle(self, center, r, gid=None, face="#ffffff", edge="#000000", lw=0.8, z=5,
               obstacle="area"):
        self.items.append(("circle", (tuple(map(float, center)), float(r)),
                           dict(face=face, edge=edge, lw=lw, z=z, gid=gid)))
        x, y = center
        self._bound([(x - r, y - r), (x + r, y + r)])
        if obstacle:
            from shapely.geometry import Point
            g = Point(center).buffer(r + lw / PT_PER_CM / 2, quad_segs=8)
            if obstacle == "edge":
                g = g.exterior.buffer(lw / PT_PER_CM / 2)
            self.obstacles.append(g)

    def arrow(self, start, end, gid, color, lw, dashes=None, z=4):
        """A vector: a shaft from ``start`` and a filled head whose tip is ``end``."""
        dx, dy = end[0] - start[0], end[1] - start[1]
        n = math.hypot(dx, dy)
        if n < 1e-9:
            return
        ux, uy = dx / n, dy / n
        hl = min(HEAD_LEN, 0.45 * n)
        hw = HEAD_HALF * hl / HEAD_LEN
        base = (end[0] - hl * ux, end[1] - hl * uy)
        neck = (end[0] - 0.7 * hl * ux, end[1] - 0.7 * hl * uy)
        self.line([start, neck], gid=f"{gid}-shaft", color=color, lw=lw, dashes=dashes, z=z,
                  hint=False)
        self.hints.append((tuple(start), tuple(end)))
        self.polygon([end, (base[0] - hw * uy, base[1] + hw * ux),
                      (base[0] + hw * uy, base[1] - hw * ux)], gid=f"{gid}-head", face=color,
                     edge=color, lw=0.4, z=z)

    def label(self, text, anchors, size=LABEL_PT, gid=None, color="#000000", weight="normal",
              point=False, leader=False):
        self.labels.append(_Label(text, [tuple(map(float, a)) for a in anchors], size,
                                  gid or f"label-{len(self.labels)}", color, weight,
                                  point=point, leader=leader or point))

    def note(self, x, y, text, size=NOTE_PT, ha="left", gid=None, weight="normal",
             color="#000000"):
        """Fixed text, ``(x, y)`` its left (or centre) and vertical middle."""
        w, h = _text_size(text, size, weight)
        cx = x + w / 2 if ha == "left" else x
        self.notes.append(_Label(text, [(cx, y)], size, gid or f"note-{len(self.notes)}",
                                 color, weight, (cx, y, w, h)))
        return w, h

    def _bound(self, pts):
        xs = [p[0] for p in pts]
        ys = [p[1] for p in pts]
        self.bounds.append((min(xs), min(ys), max(xs), max(ys)))

    # -- label placement
    def place_labels(self):
        """Give each label the first position around one of its anchors whose box clears
        every obstacle and every label placed before it (rings of growing distance, 16
        directions, the ones facing away from the lines at the anchor first)."""
        from shapely import STRtree, box
        from shapely.geometry import Point
        tree = STRtree(self.obstacles) if self.obstacles else None
        placed = []
        spots = [Point(lab.anchors[0]) for lab in self.labels if lab.point]
        for lab in self.labels:
            w, h = _text_size(lab.text, lab.size, lab.weight)
            best, clear_only, clashes = None, None, []
            for ring, gap in enumerate((0.06, 0.2, 0.38, 0.6, 0.9, 1.3)):
                options = []
                for ai, (ax, ay) in enumerate(lab.anchors):
                    away = self._incident(ax, ay)
                    for k in range(16):
                        th = math.pi / 4 + k * math.pi / 8
                        c, s = math.cos(th), math.sin(th)
                        edge = min(w / 2 / abs(c) if abs(c) > 1e-12 else math.inf,
                                   h / 2 / abs(s) if abs(s) > 1e-12 else math.inf)
                        cx, cy = ax + (gap + edge) * c, ay + (gap + edge) * s
                        clearance = min((_angle_between(th, a) for a in away), default=math.pi)
                        options.append((-round(clearance, 6), ai, k, cx, cy))
                options.sort()
                for _, ai, _, cx, cy in options:
                    b = box(cx - w / 2 - CLEAR, cy - h / 2 - CLEAR, cx + w / 2 + CLEAR,
                            cy + h / 2 + CLEAR)
                    hits = list(tree.query(b, predicate="intersects")) if tree else []
                    crowd = [p for p in placed if p.intersects(b)]
                    if hits or crowd:
                        clashes.append((b, hits, crowd, (cx, cy)))
                        continue
                    leader = None
                    if lab.leader and gap > 0.5:  # far from its point: a leader line to it
                        leader = _leader(lab.anchors[ai], (cx, cy, w, h))
                        if any(p.intersects(leader) for p in placed):
                            clashes.append((b, [], [], (cx, cy)))
                            continue
                    if lab.point:  # nearer to its own point than to any other?
                        here = Point(lab.anchors[ai])
                        own = b.distance(here)
                        others = [q.distance(b) for q in spots if q.distance(here) > 1e-9]
                        margin = min(others, default=math.inf) - own
                        if margin < 0.08:
                            if clear_only is None or margin > clear_only[0] + 1e-9:
                                clear_only = (margin, (cx, cy), leader)
                            continue
                    best = (cx, cy, leader)
                    break
                if best is not None:
                    break
            if best is None and clear_only is not None:
                best = (*clear_only[1], clear_only[2])
            if best is None:  # the least overlap
                best = (*min(clashes, key=lambda c: (
                    sum(self.obstacles[i].intersection(c[0]).area for i in c[1])
                    + sum(p.intersection(c[0]).area for p in c[2]) * 10))[3], None)
                self.warnings.append(f"label {lab.text!r} could not be placed clear of the "
                                     "lines")
            lab.box = (best[0], best[1], w, h)
            placed.append(box(best[0] - w / 2, best[1] - h / 2, best[0] + w / 2,
                              best[1] + h / 2))
            if best[2] is not None:
                placed.append(best[2].buffer(0.02))
                self.items.append(("line", list(best[2].coords),
                                   dict(color="#555555", lw=0.4, dashes=None, z=7,
                                        gid=f"leader-{lab.gid}")))

    def _incident(self, x, y):
        """Directions (angles) of the lines that leave the point (x, y)."""
        out = []
        for (x1, y1), (x2, y2) in self.hints:
            dx, dy = x2 - x1, y2 - y1
            L2 = dx * dx + dy * dy
            if L2 < 1e-18:
                continue
            t = ((x - x1) * dx + (y - y1) * dy) / L2
            if t < -1e-9 or t > 1 + 1e-9:
                continue
            px, py = x1 + t * dx, y1 + t * dy
            if math.hypot(px - x, py - y) > 1e-6:
                continue
            if t < 1 - 1e-9:
                out.append(math.atan2(dy, dx))
            if t > 1e-9:
                out.append(math.atan2(-dy, -dx))
        return out

    def content_box(self):
        boxes = list(self.bounds)
        for lab in self.labels:
            if lab.box:
                cx, cy, w, h = lab.box
                boxes.append((cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2))
        if not boxes:
            return (0.0, 0.0, 0.0, 0.0)
        return (min(b[0] for b in boxes), min(b[1] for b in boxes),
                max(b[2] for b in boxes), max(b[3] for b in boxes))

    def note_box(self):
        xs, ys = [], []
        for n in self.notes:
            cx, cy, w, h = n.box
            xs += [cx - w / 2, cx + w / 2]
            ys += [cy - h / 2, cy + h / 2]
        return (min(xs), min(ys), max(xs), max(ys))


def _leader(anchor, placed_box):
    """A thin line from a point towards its label's box, stopping short of both."""
    from shapely.geometry import LineString, Point, box
    from shapely.ops import nearest_points
    cx, cy, w, h = placed_box
    near = nearest_points(box(cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2),
                          Point(anchor))[0]
    dx, dy = near.x - anchor[0], near.y - anchor[1]
    n = math.hypot(dx, dy)
    ux, uy = dx / n, dy / n
    a, b = 0.1, n - 0.06
    return LineString([(anchor[0] + a * ux, anchor[1] + a * uy),
                       (anchor[0] + b * ux, anchor[1] + b * uy)])


def _angle_between(a, b):
    d = abs(a - b) % (2 * math.pi)
    return min(d, 2 * math.pi - d)


# --------------------------------------------------------------------------- header


def _header(sk: _Sketch, tag: str, title: str, scale: Scale, lines=(), legend=()):
    """Title, scale note, scale bar and (for the acceleration polygon) the legend, stacked
    above the content, left-aligned with it."""
    x0, y0, x1, y1 = sk.content_box()
    width = max(x1 - x0, 4.0)
    rows = []  # (height, draw(y_middle))

    def text_row(text, size, weight="normal", gid=None):
        h = _text_size(text, size, weight)[1]
        rows.append((h, lambda y: sk.note(x0, y, text, size, gid=gid, weight=weight)))

    text_row(title, TITLE_PT, "bold", gid=f"note-{tag}-title")
    text_row(display_unit(scale.text), NOTE_PT, gid=f"note-{tag}-scale")
    for ln in lines:
        text_row(ln, SMALL_PT, gid=f"note-{tag}-line-{len(rows)}")
    # scale bar: whole centimetres, labelled at both ends
    n = int(max(2, min(5, math.floor(max(width, 5.0) - 2.0))))
    end_text = display_unit(f"{_fmt_number(scale, n)} {scale.unit}")

    def bar(y):
        pts = [(x0 + 0.1, y), (x0 + 0.1 + n, y)]
        sk.line(pts, gid=f"{tag}-scale-bar", lw=1.2, obstacle=False, hint=False)
        sk.segments([((x0 + 0.1 + i, y - 0.08), (x0 + 0.1 + i, y + 0.08))
                     for i in range(n + 1)], gid=f"{tag}-scale-bar-ticks", lw=0.6)
        sk.note(x0 + 0.1, y - 0.3, "0", SMALL_PT, ha="center", gid=f"note-{tag}-bar-0")
        sk.note(x0 + 0.1 + n, y - 0.3, end_text, SMALL_PT, ha="center", gid=f"note-{tag}-bar-end")
        sk.note(x0 + 0.1 + n + 0.2 + _text_size(end_text, SMALL_PT)[0] / 2, y, f"({n} cm)",
                SMALL_PT, gid=f"note-{tag}-bar-cm")
    rows.append((0.65, lambda y: bar(y + 0.12)))
    for i, (kind, label) in enumerate(legend):
        def entry(y, kind=kind, label=label, i=i):
            color, lw, dashes = STYLE.get(kind, LINE_STYLE) if kind != "line" else LINE_STYLE
            if kind == "image":
                sk.polygon([(x0 + 0.1, y - 0.1), (x0 + 1.1, y - 0.1), (x0 + 0.6, y + 0.12)],
                           gid=f"{tag}-legend-{i}", face=IMAGE_FACE, edge=IMAGE_FACE, lw=0.4,
                           alpha=0.5, obstacle=None)
            else:
                sk.line([(x0 + 0.1, y), (x0 + 1.1, y)], gid=f"{tag}-legend-{i}", color=color, lw=lw,
                        dashes=dashes, obstacle=False, hint=False)
            sk.note(x0 + 1.3, y, label, SMALL_PT, gid=f"note-{tag}-legend-{i}")
        rows.append((0.36, entry))
    total = sum(h + 0.12 for h, _ in rows)
    y = y1 + 0.35 + total
    for h, draw in rows:
        y -= h / 2
        draw(y)
        y -= h / 2 + 0.12


def _fmt_number(scale: Scale, n: int) -> str:
    from decimal import Decimal
    return format((Decimal(scale.value) * n).normalize(), "f")


# --------------------------------------------------------------------------- configuration


def _configuration(sol, scale: Scale) -> _Sketch:
    from shapely.geometry import MultiPoint
    sc = sol.scene
    s = scale.per_cm
    P = {k: (x / s, y / s) for k, (x, y) in sol.P.items()}
    sk = _Sketch()
    carried_on = {}
    for cp in sc.points:
        carried_on.setdefault(cp.link, []).append(cp.name)
    # frame: links between two ground points
    for lk in sc.links:
        if lk.p in sc.ground and lk.q in sc.ground:
            sk.line([P[lk.p], P[lk.q]], gid=f"frame-{lk.key}", color="#555555", lw=0.6,
                    dashes=(6, 2, 1, 2), z=1)
    # sliders on fixed paths: line of stroke, guide wall with hatching
    for sl in sc.sliders:
        if isinstance(sl, FixedPath):
            _fixed_guide(sk, sc, sl, P, s)
    # links as bars, a link with carried points as a plate
    for lk in sc.links:
        if lk.p in sc.ground and lk.q in sc.ground:
            continue
        pts = [P[lk.p], P[lk.q]] + [P[c] for c in carried_on.get(lk.key, ())]
        body = MultiPoint(pts).convex_hull.buffer(BAR / 2, quad_segs=8)
        sk.polygon(list(body.exterior.coords), gid=f"link-{lk.key}", face=BODY_FACE,
                   edge=BODY_EDGE, lw=0.8, z=2, obstacle="edge")
        for a in pts:
            for b in pts:
                if a < b:
                    sk.hints.append((a, b))
    # blocks
    for sl in sc.sliders:
        X = P[sl.point]
        if isinstance(sl, FixedPath):
            u = sl.u
        else:
            (x1, y1), (x2, y2) = P[sl.first], P[sl.second]
            n = math.hypot(x2 - x1, y2 - y1)
            u = ((x2 - x1) / n, (y2 - y1) / n)
        size = _block_size(sc, sl.point, P)
        sk.polygon(_rect(X, u, size, 0.55 * size), gid=f"block-{sl.point}", face="#ffffff",
                   edge="#000000", lw=0.9, z=3)
        sk.hints.append(((X[0] - size / 2 * u[0], X[1] - size / 2 * u[1]),
                         (X[0] + size / 2 * u[0], X[1] + size / 2 * u[1])))
    # pins at their given sizes
    for pin in sc.pins:
        r = pin.radius / s
        if r > JOINT_R * 1.2:
            sk.circle(P[pin.point], r, gid=f"pin-{pin.point}", face="none", edge="#8a8a8a",
                      lw=0.6, z=4, obstacle="edge")
    # ground pivots, hatched
    for g in sc.ground:
        away = [P[lk.other(g)] for lk in sc.links if g in lk.points
                and lk.other(g) not in sc.ground]
        away += [P[c] for lk in sc.links if g in lk.points for c in carried_on.get(lk.key, ())]
        if away:
            near = [P[p] for p in sc.point_names if p != g and 0 < math.dist(P[p], P[g]) < 1.2]
            _ground_symbol(sk, g, P[g], away + near)
    # the crank angle
    _crank_angle(sk, sc, P)
    # joints and points
    joints = set(sc.ground) | {p for lk in sc.links for p in lk.points} | \
        {sl.point for sl in sc.sliders}
    for name in sc.point_names:
        if name in joints:
            sk.circle(P[name], JOINT_R, gid=f"joint-{name}", z=6)
        else:
            sk.circle(P[name], DOT_R, gid=f"joint-{name}", face="#000000", z=6)
    for name in sc.point_names:
        sk.label(name, [P[name]], LABEL_PT, gid=f"label-{name}", point=True)
    _crank_angle_label(sk, sc, P)
    sk.place_labels()
    inp = sc.input
    drive = f"crank {inp.crank} at {_deg(inp.angle)}, {inp.speed_text}"
    if inp.alpha:
        from .numbers import fmt_angular
        drive += f", {fmt_angular(inp.alpha, 'rad/s²')}"
    _header(sk, "configuration", "Configuration diagram", scale, lines=[drive])
    return sk


def _deg(rad: float) -> str:
    d = math.degrees(rad)
    return f"{d:.4g}\u00b0"


def _block_size(sc, point, P):
    """A slider block's length (cm): 0.9, less on short links so the block does not hide
    them."""
    near = [math.dist(P[point], P[lk.other(point)]) for lk in sc.links if point in lk.points]
    return min(0.9, max(0.5, 0.45 * min(near, default=2.0)))


def _rect(c, u, length, width):
    ux, uy = u
    nx, ny = -uy, ux
    a, b = length / 2, width / 2
    return [(c[0] + sx * a * ux + sy * b * nx, c[1] + sx * a * uy + sy * b * ny)
            for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))]


def _fixed_guide(sk, sc, sl, P, s):
    """The line of stroke (chain-dotted, through the path's given point) and the guide's
    wall on the side away from the connecting link, hatched."""
    X = P[sl.point]
    ux, uy = sl.u
    nx, ny = -uy, ux
    tx, ty = sl.through[0] / s, sl.through[1] / s
    t_through = (tx - X[0]) * ux + (ty - X[1]) * uy
    lo, hi = min(-1.8, t_through - 0.5), max(1.8, t_through + 0.5)
    sk.line([(X[0] + lo * ux, X[1] + lo * uy), (X[0] + hi * ux, X[1] + hi * uy)],
            gid=f"stroke-{sl.point}", color="#555555", lw=0.5, dashes=(6, 2, 1, 2), z=1)
    rod = next((P[lk.other(sl.point)] for lk in sc.links if sl.point in lk.points), None)
    side = 1.0
    if rod is not None and ((rod[0] - X[0]) * nx + (rod[1] - X[1]) * ny) > 0:
        side = -1.0
    off = 0.55 * _block_size(sc, sl.point, P) / 2 + 0.02
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
    sk.bounds.append((min(a[0], far[0], b[0], far2[0]), min(a[1], far[1], b[1], far2[1]),
                      max(a[0], far[0], b[0], far2[0]), max(a[1], far[1], b[1], far2[1])))


def _ground_symbol(sk, name, g, away):
    """A fixed pivot: a bracket (triangle) from the pin to a hatched base, turned away from
    the links that leave it (below it where that is clear)."""
    out = [math.atan2(p[1] - g[1], p[0] - g[0]) for p in away if math.dist(p, g) > 1e-9]
    q = math.pi / 4
    best, best_c = -math.pi / 2, -1.0
    for th, need in ((-2 * q, 45), (4 * q, 60), (0.0, 60), (2 * q, 60), (-3 * q, 60),
                     (-q, 60), (3 * q, 60), (q, 60)):
        c = min((_angle_between(th, a) for a in out), default=math.pi)
        if c >= math.radians(need):
            best = th
            break
        if c > best_c:
            best, best_c = th, c
    dx, dy = math.cos(best), math.sin(best)
    nx, ny = -dy, dx
    d, half, wide = 0.5, 0.3, 0.42
    base = (g[0] + d * dx, g[1] + d * dy)
    tri = [g, (base[0] + half * nx, base[1] + half * ny),
           (base[0] - half * nx, base[1] - half * ny)]
    sk.polygon(tri, gid=f"ground-{name}", face="#ffffff", edge="#000000", lw=0.8, z=4)
    sk.line([(base[0] + wide * nx, base[1] + wide * ny),
             (base[0] - wide * nx, base[1] - wide * ny)], gid=f"ground-{name}-base", lw=1.0,
            z=4)
    hatch = []
    for i in range(6):
        t = -wide + 0.17 + i * (2 * wide - 0.17) / 5
        p = (base[0] + t * nx, base[1] + t * ny)
        hatch.append((p, (p[0] + 0.17 * dx - 0.17 * nx, p[1] + 0.17 * dy - 0.17 * ny)))
    sk.segments(hatch, gid=f"ground-{name}-hatch", lw=0.5, z=4)
    from shapely.geometry import Polygon
    far = (base[0] + 0.2 * dx, base[1] + 0.2 * dy)
    sk.obstacles.append(Polygon([(base[0] + (wide + 0.2) * nx, base[1] + (wide + 0.2) * ny),
                                 (base[0] - (wide + 0.2) * nx, base[1] - (wide + 0.2) * ny),
                                 (far[0] - (wide + 0.2) * nx, far[1] - (wide + 0.2) * ny),
                                 (far[0] + (wide + 0.2) * nx, far[1] + (wide + 0.2) * ny)]))
    for p, q in hatch:
        sk._bound([p, q])


def _crank_arc(sc, P):
    inp = sc.input
    O = P[inp.pivot]
    th = math.remainder(inp.angle, 2 * math.pi)
    crank = math.dist(O, P[inp.tip])
    r = min(max(min(0.55 * crank, crank - 0.6), 0.45), 1.4)
    return O, th, r


def _crank_angle(sk, sc, P):
    """The crank angle: a reference line along +x from the crank's pivot and an arc from it
    to the crank."""
    O, th, r = _crank_arc(sc, P)
    if abs(th) < 1e-9:
        return
    sk.line([O, (O[0] + r + 0.5, O[1])], gid="crank-reference", color="#555555", lw=0.5,
            dashes=(6, 2, 1, 2), z=1)
    n = max(8, int(abs(math.degrees(th)) / 3))
    pts = [(O[0] + r * math.cos(th * i / n), O[1] + r * math.sin(th * i / n))
           for i in range(n + 1)]
    sk.line(pts, gid="crank-angle", lw=0.6, z=3, hint=False)


def _crank_angle_label(sk, sc, P):
    O, th, r = _crank_arc(sc, P)
    if abs(th) < 1e-9:
        return
    mids = [(O[0] + r * math.cos(th * f), O[1] + r * math.sin(th * f)) for f in (0.5, 0.3, 0.7)]
    sk.label(_deg(abs(th)), mids, MARK_PT, gid="label-crank-angle", leader=True)


# --------------------------------------------------------------------------- polygons


def drawn_vectors(sol, phase: str) -> tuple:
    """The vectors a polygon shows, in drawing order: every given and found vector of the
    construction records, zero ones left out, and of two that coincide only one (a total
    before a component, a component before a relative vector). The n-th is drawn with
    gid ``{phase}-vector-{n}-shaft`` / ``-head``. A carried point's relative vector is
    left out: its image triangle (or the line it lies on) shows it."""
    cons = velocity_constructions(sol) if phase == "velocity" else \
        acceleration_constructions(sol)
    steps = sol.plan.steps
    vecs = [v for c in cons for v in c.given + c.found
            if not (v.kind == "relative" and steps[c.step].kind == "carried")]
    ref = max((v.magnitude for v in vecs), default=0.0)
    tol = 1e-9 * ref
    keep = {}
    for v in vecs:
        if v.magnitude <= tol:
            continue
        key = None
        for k, w in keep.items():
            if (math.dist(v.start, w.start) <= tol and math.dist(v.end, w.end) <= tol):
                key = k
                break
        if key is None:
            keep[len(keep)] = v
        elif PRIORITY.index(v.kind) < PRIORITY.index(keep[key].kind):
            keep[key] = v
    return tuple(keep.values())


_RELATION = [(re.compile(r"^perpendicular to (.+)$"), "\u22a5 {}"),
             (re.compile(r"^parallel to the path.*$"), "\u2225 path"),
             (re.compile(r"^parallel to (.+)$"), "\u2225 {}")]


def _relation_mark(text: str) -> str:
    for pat, fmt in _RELATION:
        m = pat.match(text)
        if m:
            return fmt.format(*m.groups())
    return text


_POINT_LABEL = re.compile(r"^[a-z][0-9]*'?$")


def _polygon(sol, scale: Scale, phase: str) -> _Sketch:
    s = scale.per_cm
    D = sol.V if phase == "velocity" else sol.A
    prime = "" if phase == "velocity" else "'"
    cm = lambda p: (p[0] / s, p[1] / s)  # noqa: E731
    cons = velocity_constructions(sol) if phase == "velocity" else \
        acceleration_constructions(sol)
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
            sk.polygon(tri, gid=f"{phase}-image-{st.point}", face=IMAGE_FACE, edge="#b08d00",
                       lw=0.5, alpha=0.45, z=1, obstacle="edge")
    # construction lines, dashed, through the point they start from
    marks = []
    for c in cons:
        on = [c.point] + [p for v in c.given + c.found for p in (v.start, v.end)]
        for i, ln in enumerate(c.lines):
            (px, py), (dx, dy) = ln.point, ln.direction
            ts = [0.0] + [((q[0] - px) * dx + (q[1] - py) * dy) for q in on
                          if abs((q[0] - px) * dy - (q[1] - py) * dx) <= tol]
            lo, hi = min(ts) / s - OVERSHOOT, max(ts) / s + OVERSHOOT
            a = (px / s + lo * dx, py / s + lo * dy)
            b = (px / s + hi * dx, py / s + hi * dy)
            color, lw, dashes = LINE_STYLE
            sk.line([a, b], gid=f"{phase}-line-{c.step}-{i}", color=color, lw=lw,
                    dashes=dashes, z=2)
            marks.append((_relation_mark(ln.relation), [b, a], f"{phase}-mark-{c.step}-{i}"))
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
        for ln in c.lines:
            if _POINT_LABEL.match(ln.through):
                name_at(ln.point, ln.through)
        for v in c.given + c.found:
            for k, labs in list(names.items()):
                if math.dist(k, v.start) <= tol:
                    for lab in labs:
                        rest = v.label[len(lab):] if v.label.startswith(lab) else ""
                        if _POINT_LABEL.match(rest) and rest not in labs:
                            if not any(math.dist(k2, v.end) <= tol for k2 in names):
                                name_at(v.end, rest)
                    break
    for xy, labs in names.items():
        r = POLE_R if pole in labs else DOT_R
        sk.circle(cm(xy), r, gid=f"{phase}-point-{'-'.join(labs).replace(chr(39), 'p')}",
                  face="#000000", z=6)
    for xy, labs in sorted(names.items(), key=lambda kv: pole not in kv[1]):
        labs = [pole] + [x for x in labs if x != pole] if pole in labs else labs
        sk.label(", ".join(labs), [cm(xy)], LABEL_PT,
                 gid=f"label-{'-'.join(labs).replace(chr(39), 'p')}", point=True)
    for text, anchors, gid in marks:
        sk.label(text, anchors, MARK_PT, gid=f"label-{gid}",
                 color="#555555")
    sk.place_labels()
    if phase == "velocity":
        legend = [("line", "construction line (\u22a5 / \u2225 to a link)")]
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


# --------------------------------------------------------------------------- painting


def _paint(ax, sk: _Sketch, pad: float = 0.3) -> list:
    """Make the matplotlib artists of a sketch on ``ax`` (data units: cm) and set the axes'
    limits to the panel's extent. Returns the artists."""
    from matplotlib.collections import LineCollection
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle, Polygon

    artists = []
    used = set()

    def unique(gid):  # SVG ids must be unique (a point B1's image b1 and a coincident b1)
        base, k = gid, 1
        while gid in used:
            k += 1
            gid = f"{base}-{k}"
        used.add(gid)
        return gid

    for kind, geo, st in sk.items:
        gid, z = st["gid"], st["z"]
        if kind == "line":
            a = Line2D([p[0] for p in geo], [p[1] for p in geo], color=st["color"],
                       linewidth=st["lw"], zorder=z, solid_capstyle="butt",
                       dash_capstyle="butt", solid_joinstyle="round")
            if st["dashes"]:
                a.set_dashes(st["dashes"])
            ax.add_line(a)
        elif kind == "polygon":
            a = Polygon(geo, closed=True, facecolor=st["face"], edgecolor=st["edge"],
                        linewidth=st["lw"], zorder=z, alpha=st["alpha"] if st["alpha"] < 1
                        else None, joinstyle="miter" if gid and "head" in gid else "round")
            ax.add_patch(a)
        elif kind == "segments":
            a = LineCollection(geo, colors=st["color"], linewidths=st["lw"], zorder=z)
            ax.add_collection(a, autolim=False)
        elif kind == "circle":
            a = Circle(geo[0], geo[1], facecolor=st["face"], edgecolor=st["edge"],
                       linewidth=st["lw"], zorder=z)
            ax.add_patch(a)
        else:  # pragma: no cover
            raise ValueError(kind)
        a.set_gid(unique(gid) if gid else None)
        a.set_clip_on(False)
        artists.append(a)
    for lab in sk.labels + sk.notes:
        cx, cy, w, h = lab.box
        t = ax.text(cx, cy, lab.text, fontsize=lab.size, fontfamily=FONT,
                    fontweight=lab.weight, color=lab.color, ha="center", va="center",
                    parse_math=False, zorder=8)
        t.set_gid(unique(lab.gid))
        t.set_clip_on(False)
        artists.append(t)
    x0, y0, x1, y1 = sk.content_box()
    if sk.notes:
        n0, m0, n1, m1 = sk.note_box()
        x0, y0, x1, y1 = min(x0, n0), min(y0, m0), max(x1, n1), max(y1, m1)
    ax.set_xlim(x0 - pad, x1 + pad)
    ax.set_ylim(y0 - pad, y1 + pad)
    ax.set_aspect("equal")
    ax.set_axis_off()
    return artists


def _scale_arg(sol, diagram, scale):
    if scale is None:
        return choose_scales(sol, diagram)[diagram]
    if isinstance(scale, str):
        return parse_scale(scale, KIND_OF_DIAGRAM[diagram])
    return scale


def draw_configuration(ax, sol, scale=None) -> list:
    """Draw the configuration (space) diagram on ``ax`` in centimetres of paper: links as
    bars (a link carrying a point as a plate), hatched ground pivots, slider blocks and
    guides, pins at their given sizes, point labels, the crank angle, the scale.
    ``scale``: a :class:`~polygon_method.scales.Scale`, ``"1 cm = 20 mm"``, or None
    (chosen to fit A4). Returns the artists."""
    return _paint(ax, _configuration(sol, _scale_arg(sol, "configuration", scale)))


def draw_velocity(ax, sol, scale=None) -> list:
    """Draw the velocity polygon on ``ax`` (cm of paper): pole o, vectors from o, the
    dashed construction lines marked perpendicular/parallel, image triangles shaded, the
    scale note and bar. Returns the artists."""
    return _paint(ax, _polygon(sol, _scale_arg(sol, "velocity", scale), "velocity"))


def draw_acceleration(ax, sol, scale=None) -> list:
    """Draw the acceleration polygon on ``ax`` (cm of paper): pole o', centripetal,
    tangential and Coriolis components in their own styles, the totals, image points, the
    scale note. Returns the artists."""
    return _paint(ax, _polygon(sol, _scale_arg(sol, "acceleration", scale), "acceleration"))


# --------------------------------------------------------------------------- the sheet


def _panel_size(sk: _Sketch, pad=0.3):
    x0, y0, x1, y1 = sk.content_box()
    n0, m0, n1, m1 = sk.note_box()
    return (max(x1, n1) - min(x0, n0) + 2 * pad, max(y1, m1) - min(y0, m0) + 2 * pad)


def layout(sol, diagram: str = "all", scales=None):
    """The sketches and scales of a sheet: ``[(name, scale, sketch)]``. Scales not given
    start as the largest round ones a panel could take and, while the sheet overflows A4,
    the widest panel (or one too tall) is made one round step coarser."""
    names = DIAGRAMS if diagram == "all" else (diagram,)
    if diagram not in DIAGRAMS + ("all",):
        raise PolygonMethodError(f"unknown diagram {diagram!r}; use configuration, velocity, "
                                 "acceleration or all", key="--diagram")
    given = dict(scales or {})
    scale = choose_scales(sol, diagram, given)
    fixed = {n: (given.get(n) or given.get(KIND_OF_DIAGRAM[n])) is not None for n in names}
    sw, sh = SHEET_ALL if len(names) > 1 else SHEET_ONE
    room_w, room_h = sw - 2 * MARGIN - (len(names) - 1) * GAP, sh - 2 * MARGIN
    sketches = {n: _sketch(sol, n, scale[n]) for n in names}
    for _ in range(8 * len(names)):  # coarsen the widest (or a too tall) panel until it fits
        size = {n: _panel_size(sketches[n]) for n in names}
        free = [n for n in names if not fixed[n]]
        tall = [n for n in free if size[n][1] > room_h]
        if not tall and sum(w for w, _ in size.values()) <= room_w:
            break
        if not free:
            break
        n = tall[0] if tall else max(free, key=lambda k: size[k][0])
        scale[n] = _coarser(scale[n])
        sketches[n] = _sketch(sol, n, scale[n])
    def fits(trial):
        size = [_panel_size(trial[n]) for n in names]
        return (sum(w for w, _ in size) <= room_w and all(h <= room_h for _, h in size))

    if len(names) > 1 and fits(sketches):  # use the room left: a step finer where it fits
        # (one diagram keeps the scale `steps` states, so the two agree)
        for _ in range(4):
            better = False
            for n in sorted(free, key=lambda k: k == "configuration"):
                trial = dict(sketches)
                finer = _finer(scale[n])
                trial[n] = _sketch(sol, n, finer)
                if fits(trial):
                    scale[n], sketches, better = finer, trial, True
            if not better:
                break
    out = []
    for name in names:
        w, h = _panel_size(sketches[name])
        if max(w, h) > MAX_FIGURE_CM:
            raise PolygonMethodError(
                f"the {name} diagram at {display_unit(scale[name].text)} would be "
                f"{max(w, h):.0f} cm across; use a coarser scale such as "
                f"{display_unit(choose_scales(sol, name)[name].text)}", key="--scale")
        out.append((name, scale[name], sketches[name]))
    return out


def make_figure(sol, diagram: str = "all", scales=None):
    """A matplotlib Figure of the physical size of its content: one axes per diagram, each
    positioned so that one data unit is one centimetre on the page.

    Returns ``(figure, {diagram: Scale}, warnings)``."""
    from matplotlib.figure import Figure

    panels = layout(sol, diagram, scales)
    sizes = [_panel_size(sk) for _, _, sk in panels]
    W = 2 * MARGIN + sum(w for w, _ in sizes) + GAP * (len(sizes) - 1)
    H = 2 * MARGIN + max(h for _, h in sizes)
    fig = Figure(figsize=(W / CM_PER_INCH, H / CM_PER_INCH), dpi=72)
    x = MARGIN
    warnings = []
    for (name, scale, sk), (w, h) in zip(panels, sizes):
        ax = fig.add_axes((x / W, (H - MARGIN - h) / H, w / W, h / H))
        ax.set_gid(f"panel-{name}")
        _paint(ax, sk)
        warnings += [f"{name}: {m}" for m in sk.warnings]
        x += w + GAP
    return fig, {name: scale for name, scale, _ in panels}, warnings


def _rc():
    return {"svg.hashsalt": "polygon-method", "svg.fonttype": "path", "font.family": FONT,
            "path.simplify": False, "svg.image_inline": True}


def render(sol, fmt: str = "svg", diagram: str = "all", scales=None):
    """The sheet as SVG text (deterministic: fixed hash salt, no date) or PNG/PDF bytes.

    Returns ``(data, {diagram: Scale}, warnings)``."""
    import matplotlib

    if fmt not in FORMATS:
        raise PolygonMethodError(f"cannot draw {fmt!r}: use svg, png or pdf")
    with matplotlib.rc_context(_rc()):
        fig, used, warnings = make_figure(sol, diagram, scales)
        if fmt == "svg":
            buf = io.StringIO()
            fig.savefig(buf, format="svg", metadata={"Date": None})
            return buf.getvalue(), used, warnings
        buf = io.BytesIO()
        if fmt == "png":
            fig.savefig(buf, format="png", dpi=PNG_DPI, metadata={"Software": None})
        else:
            fig.savefig(buf, format="pdf", metadata={"CreationDate": None, "ModDate": None,
                                                     "Producer": None})
        return buf.getvalue(), used, warnings


def svg_string(sol, diagram: str = "all", scales=None) -> str:
    """The three diagrams side by side as SVG text (``Solution._repr_svg_``)."""
    return render(sol, "svg", diagram, scales)[0]
