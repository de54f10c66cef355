"""A sketch: what a diagram draws (lines, arrows, bodies, labels) in centimetres of paper,
with labels placed where they touch nothing (shapely boxes), before any matplotlib artist.
"""

from __future__ import annotations

import io
import math
import re
from dataclasses import dataclass, field

from ..common.tolerances import DISTINCT, ON_PAPER, ROUNDING
from ..polygons.scales import Scale, display_unit
from .style import (
    CLEAR,
    FONT,
    HEAD_HALF,
    HEAD_LEN,
    IMAGE_FACE,
    LABEL_PT,
    LINE_STYLE,
    NOTE_PT,
    PT_PER_CM,
    SMALL_PT,
    STYLE,
    TITLE_PT,
)

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
        t = Text(
            0,
            0,
            text,
            fontsize=size,
            fontfamily=FONT,
            fontweight=weight,
            ha="center",
            va="center",
            parse_math=False,
            figure=fig,
        )
        bb = t.get_window_extent(renderer)
        got = (bb.width / PT_PER_CM, bb.height / PT_PER_CM)
        _MEASURE[key] = got
    return got


# --------------------------------------------------------------------------- on paper

_PAPER_WORDS = (
    (re.compile(r"\^2\b"), "\u00b2"),  # m/s^2 -> m/s²
    (re.compile(r"(\d) ?deg\b"), "\\1\u00b0"),  # 40 deg -> 40°
    (re.compile(r"\bomega_"), "\u03c9_"),  # omega_BC -> ω_BC
    (re.compile(r"\balpha_"), "\u03b1_"),  # alpha_BC -> α_BC
)


def paper_words(text: str) -> str:
    """Words as a drawing writes them: the units' squares, the degrees and the Greek letters
    that the scene's text and the printed solution spell out in ASCII.

    >>> paper_words("from omega_O2-B = 200 rpm cw, alpha_O2-B = 10 rad/s^2 ccw (40 deg past)")
    'from ω_O2-B = 200 rpm cw, α_O2-B = 10 rad/s² ccw (40° past)'
    """
    for pattern, to in _PAPER_WORDS:
        text = pattern.sub(to, text)
    return text


# --------------------------------------------------------------------------- a sketch

#: how much nearer (cm) a point's label is to its own point than to any other point
POINT_MARGIN = 0.08
#: the distances (cm) from its point at which a label is tried, nearest first
RINGS = (0.06, 0.2, 0.38, 0.6, 0.9, 1.3)


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
    apart: float = 0.0  # keeps this far (cm) from the points' labels, where it can


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
    #: the distances (cm) from its point at which a label is tried, nearest first
    rings: tuple = RINGS
    #: how far (cm) a leader line keeps from the labels and leaders placed before it
    leader_clear: float = 0.02
    #: the areas (shapely) a leader line keeps off, away from its own point
    solid: list = field(default_factory=list)
    #: lines a label keeps off where it can, and sits on where nothing else is clear (the
    #: centres' diagram's lines of Kennedy's theorem, which meet at the centres it names)
    soft: list = field(default_factory=list)

    # -- primitives (coordinates in cm)
    def line(
        self, pts, gid=None, color="#000000", lw=0.8, dashes=None, z=3, obstacle=True, hint=True
    ):
        pts = [tuple(map(float, p)) for p in pts]
        self.items.append(("line", pts, dict(color=color, lw=lw, dashes=dashes, z=z, gid=gid)))
        self._bound(pts)
        if obstacle and len(pts) > 1:
            from shapely.geometry import LineString

            g = LineString(pts).buffer(lw / PT_PER_CM / 2)
            (self.soft if obstacle == "soft" else self.obstacles).append(g)
        if hint:
            self.hints.extend(zip(pts[:-1], pts[1:]))

    def polygon(
        self, pts, gid=None, face="none", edge="#000000", lw=0.8, z=2, alpha=1.0, obstacle="area"
    ):
        pts = [tuple(map(float, p)) for p in pts]
        self.items.append(
            ("polygon", pts, dict(face=face, edge=edge, lw=lw, z=z, gid=gid, alpha=alpha))
        )
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

    def circle(
        self, center, r, gid=None, face="#ffffff", edge="#000000", lw=0.8, z=5, obstacle="area"
    ):
        self.items.append(
            (
                "circle",
                (tuple(map(float, center)), float(r)),
                dict(face=face, edge=edge, lw=lw, z=z, gid=gid),
            )
        )
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
        if n < ON_PAPER:
            return
        ux, uy = dx / n, dy / n
        hl = min(HEAD_LEN, 0.45 * n)
        hw = HEAD_HALF * hl / HEAD_LEN
        base = (end[0] - hl * ux, end[1] - hl * uy)
        neck = (end[0] - 0.7 * hl * ux, end[1] - 0.7 * hl * uy)
        self.line(
            [start, neck], gid=f"{gid}-shaft", color=color, lw=lw, dashes=dashes, z=z, hint=False
        )
        self.hints.append((tuple(start), tuple(end)))
        self.polygon(
            [end, (base[0] - hw * uy, base[1] + hw * ux), (base[0] + hw * uy, base[1] - hw * ux)],
            gid=f"{gid}-head",
            face=color,
            edge=color,
            lw=0.4,
            z=z,
        )

    def label(
        self,
        text,
        anchors,
        size=LABEL_PT,
        gid=None,
        color="#000000",
        weight="normal",
        point=False,
        leader=False,
        apart=0.0,
    ):
        self.labels.append(
            _Label(
                paper_words(text),
                [tuple(map(float, a)) for a in anchors],
                size,
                gid or f"label-{len(self.labels)}",
                color,
                weight,
                point=point,
                leader=leader or point,
                apart=apart,
            )
        )

    def note(self, x, y, text, size=NOTE_PT, ha="left", gid=None, weight="normal", color="#000000"):
        """Fixed text, ``(x, y)`` its left (or centre) and vertical middle."""
        text = paper_words(text)
        w, h = _text_size(text, size, weight)
        cx = x + w / 2 if ha == "left" else x
        self.notes.append(
            _Label(
                text,
                [(cx, y)],
                size,
                gid or f"note-{len(self.notes)}",
                color,
                weight,
                (cx, y, w, h),
            )
        )
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
        soft_tree = STRtree(self.soft) if self.soft else None
        placed, named = [], []  # every box placed; the boxes of the points' labels
        unplaced = []  # labels that overlap a line: one warning for them all
        spots = [Point(lab.anchors[0]) for lab in self.labels if lab.point]
        for lab in self.labels:
            w, h = _text_size(lab.text, lab.size, lab.weight)
            # a label kept apart from the points' labels (a line's mark, so that "perp EF"
            # is not read with e' beside it) first tries to be, then settles for less; and
            # one first keeps off the soft lines too
            for soft in (soft_tree, None) if soft_tree is not None else (None,):
                for apart in (lab.apart, 0.0) if lab.apart else (0.0,):
                    best, clear_only, clashes = self._place(
                        lab, w, h, tree, placed, named, spots, apart, soft
                    )
                    if best is not None:
                        break
                if best is not None:
                    break
            if best is None and clear_only is not None:
                best = (*clear_only[1], clear_only[2])
            if best is None:  # the least overlap
                best = (
                    *min(
                        clashes,
                        key=lambda c: (
                            sum(self.obstacles[i].intersection(c[0]).area for i in c[1])
                            + sum(p.intersection(c[0]).area for p in c[2]) * 10
                        ),
                    )[3],
                    None,
                )
                unplaced.append(repr(lab.text))
            lab.box = (best[0], best[1], w, h)
            placed.append(box(best[0] - w / 2, best[1] - h / 2, best[0] + w / 2, best[1] + h / 2))
            if lab.point:
                named.append(placed[-1])
            if best[2] is not None:  # a leader from a label set off to its point
                placed.append(best[2].buffer(self.leader_clear))
                self.items.append(
                    (
                        "line",
                        list(best[2].coords),
                        dict(color="#555555", lw=0.4, dashes=None, z=7, gid=f"leader-{lab.gid}"),
                    )
                )
        if unplaced:
            shown = ", ".join(unplaced[:6]) + (
                f" and {len(unplaced) - 6} more" if len(unplaced) > 6 else ""
            )
            self.warnings.append(
                f"label{'s' if len(unplaced) > 1 else ''} {shown} could not "
                "be placed clear of the lines"
            )

    def _place(self, lab, w, h, tree, placed, named, spots, apart, soft=None):
        """(best (cx, cy, leader) or None, the best position only clear of lines, the
        clashing positions) of one label: rings of growing distance around its anchors;
        with ``soft`` (a tree of the soft lines), only places clear of them too."""
        from shapely import box
        from shapely.geometry import Point

        best, clear_only, clashes = None, None, []
        for ring, gap in enumerate(self.rings):
            options = []
            for ai, (ax, ay) in enumerate(lab.anchors):
                away = self._incident(ax, ay)
                for k in range(16):
                    th = math.pi / 4 + k * math.pi / 8
                    c, s = math.cos(th), math.sin(th)
                    edge = min(
                        w / 2 / abs(c) if abs(c) > ROUNDING else math.inf,
                        h / 2 / abs(s) if abs(s) > ROUNDING else math.inf,
                    )
                    cx, cy = ax + (gap + edge) * c, ay + (gap + edge) * s
                    clearance = min((_angle_between(th, a) for a in away), default=math.pi)
                    options.append((-round(clearance, 6), ai, k, cx, cy))
            options.sort()
            for _, ai, _, cx, cy in options:
                b = box(
                    cx - w / 2 - CLEAR, cy - h / 2 - CLEAR, cx + w / 2 + CLEAR, cy + h / 2 + CLEAR
                )
                hits = list(tree.query(b, predicate="intersects")) if tree else []
                crowd = [p for p in placed if p.intersects(b)]
                if hits or crowd:
                    clashes.append((b, hits, crowd, (cx, cy)))
                    continue
                if apart and any(q.distance(b) < apart for q in named):
                    continue
                if soft is not None and len(soft.query(b, predicate="intersects")):
                    continue
                leader = None
                if lab.leader and gap > 0.5:  # far from its point: a leader line to it
                    leader = _leader(lab.anchors[ai], (cx, cy, w, h))
                    if any(p.intersects(leader) for p in placed) or _crosses(
                        leader, self.solid, lab.anchors[ai]
                    ):
                        clashes.append((b, [], [], (cx, cy)))
                        continue
                if lab.point:  # nearer to its own point than to any other?
                    here = Point(lab.anchors[ai])
                    own = b.distance(here)
                    others = [q.distance(b) for q in spots if q.distance(here) > ON_PAPER]
                    margin = min(others, default=math.inf) - own
                    # by 0.8 mm, or (a point closer than that to another, where no place
                    # can) by nine tenths of what the other point's distance allows
                    nearest = min(
                        (q.distance(here) for q in spots if q.distance(here) > ON_PAPER),
                        default=math.inf,
                    )
                    if margin < min(POINT_MARGIN, 0.9 * nearest):
                        if clear_only is None or margin > clear_only[0] + ON_PAPER:
                            clear_only = (margin, (cx, cy), leader)
                        continue
                best = (cx, cy, leader)
                break
            if best is not None:
                break
        return best, clear_only, clashes

    def _incident(self, x, y):
        """Directions (angles) of the lines that leave the point (x, y)."""
        out = []
        for (x1, y1), (x2, y2) in self.hints:
            dx, dy = x2 - x1, y2 - y1
            L2 = dx * dx + dy * dy
            if L2 < ON_PAPER * ON_PAPER:
                continue
            t = ((x - x1) * dx + (y - y1) * dy) / L2
            if t < -ON_PAPER or t > 1 + ON_PAPER:
                continue
            px, py = x1 + t * dx, y1 + t * dy
            if math.hypot(px - x, py - y) > DISTINCT:
                continue
            if t < 1 - ON_PAPER:
                out.append(math.atan2(dy, dx))
            if t > ON_PAPER:
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
        return (
            min(b[0] for b in boxes),
            min(b[1] for b in boxes),
            max(b[2] for b in boxes),
            max(b[3] for b in boxes),
        )

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
    near = nearest_points(box(cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2), Point(anchor))[0]
    dx, dy = near.x - anchor[0], near.y - anchor[1]
    n = math.hypot(dx, dy)
    ux, uy = dx / n, dy / n
    a, b = 0.1, n - 0.06
    return LineString(
        [(anchor[0] + a * ux, anchor[1] + a * uy), (anchor[0] + b * ux, anchor[1] + b * uy)]
    )


def _crosses(leader, solid, anchor):
    """Whether a leader line crosses one of the ``solid`` areas other than those at its own
    point (the link whose pin it labels, the plate a centre lies in)."""
    if not solid:
        return False
    from shapely.geometry import Point

    here = Point(anchor).buffer(0.15)
    return any(g.intersects(leader) and not g.intersects(here) for g in solid)


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

    # the scale on the title's line, as a book heads a diagram ("Velocity polygon  1 cm =
    # 0.05 m/s"), where the two fit the drawing's width: its own line was a half
    # centimetre of every panel's height that sent sheets to a second page
    said = display_unit(scale.text)
    tw, th = _text_size(title, TITLE_PT, "bold")
    sw, sh = _text_size(said, NOTE_PT)
    if tw + SCALE_GAP + sw <= width:

        def heading(y):
            sk.note(x0, y, title, TITLE_PT, gid=f"note-{tag}-title", weight="bold")
            sk.note(x0 + tw + SCALE_GAP, y, said, NOTE_PT, gid=f"note-{tag}-scale")

        rows.append((max(th, sh), heading))
    else:
        text_row(title, TITLE_PT, "bold", gid=f"note-{tag}-title")
        text_row(said, NOTE_PT, gid=f"note-{tag}-scale")
    for ln in lines:
        text_row(ln, SMALL_PT, gid=f"note-{tag}-line-{len(rows)}")
    # scale bar: whole centimetres, labelled at both ends
    n = int(max(2, min(5, math.floor(max(width, 5.0) - 2.0))))
    end_text = display_unit(f"{_fmt_number(scale, n)} {scale.unit}")

    def bar(y):
        pts = [(x0 + 0.1, y), (x0 + 0.1 + n, y)]
        sk.line(pts, gid=f"{tag}-scale-bar", lw=1.2, obstacle=False, hint=False)
        sk.segments(
            [((x0 + 0.1 + i, y - 0.08), (x0 + 0.1 + i, y + 0.08)) for i in range(n + 1)],
            gid=f"{tag}-scale-bar-ticks",
            lw=0.6,
        )
        sk.note(x0 + 0.1, y - 0.3, "0", SMALL_PT, ha="center", gid=f"note-{tag}-bar-0")
        sk.note(x0 + 0.1 + n, y - 0.3, end_text, SMALL_PT, ha="center", gid=f"note-{tag}-bar-end")
        sk.note(
            x0 + 0.1 + n + 0.2 + _text_size(end_text, SMALL_PT)[0] / 2,
            y,
            f"({n} cm)",
            SMALL_PT,
            gid=f"note-{tag}-bar-cm",
        )

    rows.append((0.65, lambda y: bar(y + 0.12)))
    for i, (kind, label) in enumerate(legend):
        rows.append(
            (
                0.36,
                lambda y, i=i, kind=kind, label=label: _legend_entry(
                    sk, tag, i, kind, label, x0, y
                ),
            )
        )
    total = sum(h + 0.12 for h, _ in rows)
    y = y1 + 0.35 + total
    for h, draw in rows:
        y -= h / 2
        draw(y)
        y -= h / 2 + 0.12


def _fmt_number(scale: Scale, n: int) -> str:
    from decimal import Decimal

    return format((Decimal(scale.value) * n).normalize(), "f")


#: the room between a diagram's title and its scale on the title's line (cm)
SCALE_GAP = 0.5


def _legend_entry(sk: _Sketch, tag: str, i: int, kind: str, label: str, x0: float, y: float):
    """The legend's ``i``-th entry at the height ``y``: its line (an image's triangle) and
    its words."""
    color, lw, dashes = STYLE.get(kind, LINE_STYLE) if kind != "line" else LINE_STYLE
    if kind == "image":
        sk.polygon(
            [(x0 + 0.1, y - 0.1), (x0 + 1.1, y - 0.1), (x0 + 0.6, y + 0.12)],
            gid=f"{tag}-legend-{i}",
            face=IMAGE_FACE,
            edge=IMAGE_FACE,
            lw=0.4,
            alpha=0.5,
            obstacle=None,
        )
    else:
        sk.line(
            [(x0 + 0.1, y), (x0 + 1.1, y)],
            gid=f"{tag}-legend-{i}",
            color=color,
            lw=lw,
            dashes=dashes,
            obstacle=False,
            hint=False,
        )
    sk.note(x0 + 1.3, y, label, SMALL_PT, gid=f"note-{tag}-legend-{i}")
