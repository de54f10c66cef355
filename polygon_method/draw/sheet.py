"""Painting sketches on matplotlib Axes, and the sheet: one diagram or all three side by
side on a page of the right physical size, rendered as SVG (byte-stable), PNG or PDF."""

from __future__ import annotations

import io

from ..common.errors import PolygonMethodError
from ..polygons.scales import (
    DIAGRAMS,
    GAP,
    KIND_OF_DIAGRAM,
    MARGIN,
    SHEET_ALL,
    choose_scales,
    coarser,
    diagram_scales,
    display_unit,
    parse_scale,
)
from .diagrams import _configuration, _polygon, _sketch
from .paper import (
    FOOTER,
    MARGIN as PAGE_MARGIN,
    PAPER_NAMES,
    PAPERS,
    fill,
    fits,
    paginate,
    paper_name,
    room,
)
from .sketch import _Sketch
from .style import CM_PER_INCH, FONT, FORMATS, MAX_FIGURE_CM, PNG_DPI, SMALL_PT

# --------------------------------------------------------------------------- painting

#: the room each panel keeps round its drawing (cm; :mod:`.paper`'s margin and gap outside it)
PANEL_PAD = 0.2


def _paint(ax, sk: _Sketch, pad: float = PANEL_PAD) -> list:
    """Make the matplotlib artists of a sketch on ``ax`` (data units: cm) and set the axes'
    limits to the panel's extent. Returns the artists."""
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
        a = _artist(ax, kind, geo, st)
        a.set_gid(unique(st["gid"]) if st["gid"] else None)
        a.set_clip_on(False)
        artists.append(a)
    for lab in sk.labels + sk.notes:
        cx, cy, w, h = lab.box
        t = ax.text(
            cx,
            cy,
            lab.text,
            fontsize=lab.size,
            fontfamily=FONT,
            fontweight=lab.weight,
            color=lab.color,
            ha="center",
            va="center",
            parse_math=False,
            zorder=8,
        )
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


def _artist(ax, kind, geo, st):
    """The matplotlib artist of one item of a sketch (a line, polygon, segments or circle),
    added to ``ax``."""
    from matplotlib.collections import LineCollection
    from matplotlib.lines import Line2D
    from matplotlib.patches import Circle, Polygon

    gid, z = st["gid"], st["z"]
    if kind == "line":
        a = Line2D(
            [p[0] for p in geo],
            [p[1] for p in geo],
            color=st["color"],
            linewidth=st["lw"],
            zorder=z,
            solid_capstyle="butt",
            dash_capstyle="butt",
            solid_joinstyle="round",
        )
        if st["dashes"]:
            a.set_dashes(st["dashes"])
        ax.add_line(a)
    elif kind == "polygon":
        a = Polygon(
            geo,
            closed=True,
            facecolor=st["face"],
            edgecolor=st["edge"],
            linewidth=st["lw"],
            zorder=z,
            alpha=st["alpha"] if st["alpha"] < 1 else None,
            joinstyle="miter" if gid and "head" in gid else "round",
        )
        ax.add_patch(a)
    elif kind == "segments":
        a = LineCollection(geo, colors=st["color"], linewidths=st["lw"], zorder=z)
        ax.add_collection(a, autolim=False)
    elif kind == "circle":
        a = Circle(
            geo[0],
            geo[1],
            facecolor=st["face"],
            edgecolor=st["edge"],
            linewidth=st["lw"],
            zorder=z,
        )
        ax.add_patch(a)
    else:  # pragma: no cover
        raise ValueError(kind)
    return a


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
    ``scale``: a :class:`~polygon_method.polygons.scales.Scale`, ``"1 cm = 20 mm"``, or None
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


#: the most points a drawing labels (placing each label clear of the others takes time
#: that grows faster than their number: about 30 s for 100 points)
MAX_DRAWN_POINTS = 80

#: a diagram drawn this many times smaller than the step table's scale draws it is a speck
#: (a polygon of at most 12 cm shrunk under 1.2 mm): a scale given by mistake
_SPECK = 100.0


def _panel_size(sk: _Sketch, pad=PANEL_PAD):
    x0, y0, x1, y1 = sk.content_box()
    n0, m0, n1, m1 = sk.note_box()
    return (max(x1, n1) - min(x0, n0) + 2 * pad, max(y1, m1) - min(y0, m0) + 2 * pad)


def layout(sol, diagram: str = "all", scales=None, centre_prefix: str = "I", paper=None):
    """The sketches and scales of a sheet: ``[(name, scale, sketch)]``. One diagram, one
    scale everywhere: each diagram is drawn at the scale the step table states (and the
    checker's tolerance uses), unless ``--scale`` gives another; the sheet's layout, not
    the scales, changes where the three do not fit side by side (:func:`rows`) or on one
    page of ``paper`` (:mod:`.paper`). The centres' diagram, whose scale no step table
    states, is coarsened until it fits a page of ``paper`` (without one, until it fits
    beside its circle diagram across an A4 landscape sheet)."""
    n = len(sol.scene.point_names)
    if n > MAX_DRAWN_POINTS:  # each label is placed clear of every line and label: minutes
        raise PolygonMethodError(
            f"the scene has {n} points: a drawing labels at most "
            f"{MAX_DRAWN_POINTS} (the page, `polygon-method page`, "
            "shows any number)",
            file=sol.scene.file,
        )
    if diagram == "centres":
        return _centres_layout(sol, scales, centre_prefix, paper)
    if diagram == "forces":  # free bodies and force polygons (:mod:`.forces`)
        from .forces import force_layout

        return force_layout(sol, scales)[0]
    names = DIAGRAMS if diagram == "all" else (diagram,)
    if diagram not in DIAGRAMS + ("all",):
        raise PolygonMethodError(
            f"unknown diagram {diagram!r}; use configuration, velocity, "
            "acceleration, all, centres or forces",
            key="--diagram",
        )
    given = dict(scales or {})
    stated = dict(zip(DIAGRAMS, diagram_scales(sol)))
    out = []
    for name in names:
        s = given.get(name) or given.get(KIND_OF_DIAGRAM[name]) or stated[name]
        sk = _sketch(sol, name, s)
        w, h = _panel_size(sk)
        if max(w, h) > MAX_FIGURE_CM:
            such = (  # never the very scale refused
                f" such as {display_unit(stated[name].text)}"
                if stated[name].per_cm > s.per_cm
                else " (--scale)"
            )
            raise PolygonMethodError(
                f"the {name} diagram at {display_unit(s.text)} would be "
                f"{max(w, h):.3g} cm across; use a coarser scale{such}",
                key="--scale",
            )
        if s.per_cm > _SPECK * stated[name].per_cm:
            raise PolygonMethodError(
                f"the {name} diagram at {display_unit(s.text)} would be a speck, "
                f"{s.per_cm / stated[name].per_cm:.3g} times smaller than at "
                f"{display_unit(stated[name].text)}, the scale of the step table; use a "
                "finer scale",
                key="--scale",
            )
        out.append((name, s, sk))
    return out


def rows(sizes, width=SHEET_ALL[0] - 2 * MARGIN):
    """Panels (their sizes, cm) flowed into rows no wider than an A4 landscape sheet's
    room: the three side by side where they fit, else on more rows. Returns lists of
    indices."""
    out, used = [[]], 0.0
    for k, (w, _) in enumerate(sizes):
        if out[-1] and used + GAP + w > width:
            out.append([])
            used = 0.0
        used += (GAP if out[-1] else 0.0) + w
        out[-1].append(k)
    return out


def _centres_layout(sol, scales=None, prefix="I", paper=None):
    """The centres sheet: the mechanism with its centres (to scale, coarsened until one page
    of ``paper`` holds it, the circle diagram beside it where there is room, else on a page
    of its own; without a paper, until an A4 landscape sheet holds both side by side) and
    the circle diagram (not to scale)."""
    from ..solver.centres import locate
    from .centres import CIRCLE_SMALL, WINDOWS, centres_sketch, circle_sketch

    ic = locate(sol, prefix)
    given = dict(scales or {})
    s = given.get("centres") or given.get("length")
    fixed = s is not None
    if s is None:
        s = choose_scales(sol, "configuration")["configuration"]
    circle = circle_sketch(ic)
    cw, ch = _panel_size(circle)
    room_w, room_h = SHEET_ALL[0] - 2 * MARGIN - GAP - cw, SHEET_ALL[1] - 2 * MARGIN

    def pages(*sizes):  # how many pages of ``paper`` they take (0: more than it holds)
        try:
            return len(paginate(list(sizes), paper))
        except PolygonMethodError:
            return 0

    sk = centres_sketch(sol, s, ic)
    if paper is None:  # the old rule: both side by side across A4 landscape
        for _ in range(12):
            w, h = _panel_size(sk)
            if fixed or (w <= room_w and h <= room_h):
                break
            s = coarser(s)
            sk = centres_sketch(sol, s, ic)
    else:  # the finest scale at which a page holds the diagram and the circle diagram
        # (showing less of the plane around the mechanism, a smaller circle), unless one
        # round step coarser shows more centres where they are with every label clear;
        # else the diagram alone, the circle diagram on a page of its own
        small = circle_sketch(ic, CIRCLE_SMALL)

        def largest(scale, both=True):  # (centres in place, sketch, circle) or None
            for window in WINDOWS:
                here = (
                    sk
                    if (scale, window) == (s, WINDOWS[0])
                    else centres_sketch(sol, scale, ic, window)
                )
                size = _panel_size(here)
                for c in (circle, small) if both else (circle,):
                    if pages(size, _panel_size(c)) == (1 if both else 2):
                        return _in_place(here), here, c
            return None

        for _ in range(12):
            fine = largest(s)
            if fixed:
                sk, circle = fine[1:] if fine else (sk, circle)
                break
            rough = largest(coarser(s)) if fine is None or fine[0] < len(ic.order) else None
            if rough is not None and (
                fine is None or (rough[0] > fine[0] and not rough[1].warnings)
            ):
                s, sk, circle = coarser(s), rough[1], rough[2]
                break
            if fine is None:
                fine = largest(s, both=False)
            if fine is not None:
                sk, circle = fine[1:]
                break
            s = coarser(s)
            sk = centres_sketch(sol, s, ic)
    w, h = _panel_size(sk)
    if max(w, h) > MAX_FIGURE_CM:
        raise PolygonMethodError(
            f"the centres diagram at {display_unit(s.text)} would be "
            f"{max(w, h):.3g} cm across; use a coarser scale",
            key="--scale",
        )
    sk.warnings.extend(ic.warnings)
    return [("centres", s, sk), ("circle", None, circle)]


def _in_place(sk) -> int:
    """How many centres a centres' sketch draws where they are (not as arrows)."""
    return sum(
        1
        for kind, _, st in sk.items
        if kind == "circle" and (st["gid"] or "").startswith("centre-")
    )


def make_figure(sol, diagram: str = "all", scales=None, centre_prefix: str = "I"):
    """A matplotlib Figure of the physical size of its content: one axes per diagram, each
    positioned so that one data unit is one centimetre on the page.

    Returns ``(figure, {diagram: Scale}, warnings)``."""
    from matplotlib.figure import Figure

    panels = layout(sol, diagram, scales, centre_prefix)
    sizes = [_panel_size(sk) for _, _, sk in panels]
    lines = rows(sizes) if len(panels) > 1 else [[0]]
    widths = [sum(sizes[k][0] for k in r) + GAP * (len(r) - 1) for r in lines]
    heights = [max(sizes[k][1] for k in r) for r in lines]
    W = 2 * MARGIN + max(widths)
    H = 2 * MARGIN + sum(heights) + GAP * (len(lines) - 1)
    fig = Figure(figsize=(W / CM_PER_INCH, H / CM_PER_INCH), dpi=72)
    warnings = []
    top = MARGIN
    for r, row_h in zip(lines, heights):
        x = MARGIN
        for k in r:
            name, scale, sk = panels[k]
            w, h = sizes[k]
            ax = fig.add_axes((x / W, (H - top - h) / H, w / W, h / H))
            ax.set_gid(f"panel-{name}")
            _paint(ax, sk)
            warnings += [f"{name}: {m}" for m in sk.warnings]
            x += w + GAP
        top += row_h + GAP
    return fig, {name: scale for name, scale, _ in panels if scale is not None}, warnings


#: what makes a file the same byte for byte run to run: SVG ids from a fixed salt (else
#: matplotlib draws them at random), its text drawn as paths whatever the caller's own
#: matplotlib settings (as the sheets' ``_rc``), and no date or software stamp in any format
STABLE_RC = {"svg.hashsalt": "polygon-method", "svg.fonttype": "path"}
STABLE_METADATA = {
    "svg": {"Date": None},
    "png": {"Software": None},
    "pdf": {"CreationDate": None, "ModDate": None, "Producer": None},
}


def figure_data(fig, fmt: str, **kw):
    """A matplotlib figure as the file of ``fmt`` (SVG text, PNG or PDF bytes), the same
    byte for byte every run (:data:`STABLE_RC`, :data:`STABLE_METADATA`): every drawing and
    plot the tool writes goes through here."""
    import matplotlib

    with matplotlib.rc_context(STABLE_RC):
        buf = io.StringIO() if fmt == "svg" else io.BytesIO()
        fig.savefig(buf, format=fmt, metadata=STABLE_METADATA[fmt], **kw)
    return buf.getvalue()


def _rc():
    return {
        **STABLE_RC,
        "svg.fonttype": "path",
        "font.family": FONT,
        "path.simplify": False,
        "svg.image_inline": True,
    }


def render(sol, fmt: str = "svg", diagram: str = "all", scales=None, centre_prefix: str = "I"):
    """The sheet as SVG text (deterministic: fixed hash salt, no date) or PNG/PDF bytes.

    Returns ``(data, {diagram: Scale}, warnings)``."""
    import matplotlib

    if fmt not in FORMATS:
        raise PolygonMethodError(f"cannot draw {fmt!r}: use svg, png or pdf")
    with matplotlib.rc_context(_rc()):
        fig, used, warnings = make_figure(sol, diagram, scales, centre_prefix)
        data = figure_data(fig, fmt, **({"dpi": PNG_DPI} if fmt == "png" else {}))
        return data, used, warnings


# --------------------------------------------------------------------------- on paper

_WHAT = {
    "configuration": "configuration diagram",
    "velocity": "velocity polygon",
    "acceleration": "acceleration polygon",
    "centres": "centres diagram",
    "circle": "circle diagram",
}


def _what(name: str) -> str:
    """What a panel is, in words (``free-body-3``: the free body of link 3)."""
    if name.startswith("free-body-"):
        return f"free body of {name[10:]}"
    if name.startswith("force-polygon-"):
        return f"force polygon of step {name[14:]}"
    return _WHAT[name]


def sheet_pages(
    sol, diagram: str = "all", scales=None, centre_prefix: str = "I", paper: str = "A4"
):
    """The panels of a sheet (:func:`layout`) and the pages of ``paper`` they go on
    (:func:`.paper.paginate`): ``(panels, sizes, pages)``. A panel larger than the paper
    at its scale is one line naming the diagram, its scale and what to do (a larger paper,
    or a coarser ``--scale``, which the step table then does not state)."""
    panels = layout(sol, diagram, scales, centre_prefix, paper)
    sizes = [_panel_size(sk) for _, _, sk in panels]
    paper = paper_name(paper)
    given = dict(scales or {})
    for (name, s, _), size in zip(panels, sizes):
        if fits(size, paper):
            continue
        rw, rh = room(paper, "portrait")
        what = f"the {_what(name)}" + (f" at {display_unit(s.text)}" if s is not None else "")
        bigger = sorted(
            (p for p in PAPER_NAMES if p != paper and fits(size, p)),
            key=lambda p: PAPERS[p][0] * PAPERS[p][1],
        )
        advice = (
            f"draw it on {bigger[0]} (--paper {bigger[0]}) or at a coarser --scale"
            if bigger
            else "draw it at a coarser --scale"
        )
        asked = name in given or KIND_OF_DIAGRAM.get(name) in given or name == "centres"
        raise PolygonMethodError(
            f"{what} is {size[0]:.3g} x {size[1]:.3g} cm: more than {paper} holds inside its "
            f"margins ({rw:.3g} x {rh:.3g} cm, either way round); {advice}",
            key="--scale" if asked and given else "--paper",
        )
    names = [name for name, _, _ in panels]
    # the forces sheet's many panels: each page filled before another is started
    pages = (fill if diagram == "forces" else paginate)(sizes, paper, panels=names)
    return panels, sizes, pages


def page_figure(panels, sizes, page):
    """The matplotlib Figure of one page: the paper's size, each panel placed so that one
    data unit is one centimetre on the paper, and the line naming the paper at its foot.
    Returns ``(figure, warnings)``."""
    from matplotlib.figure import Figure

    W, H = page.size
    fig = Figure(figsize=(W / CM_PER_INCH, H / CM_PER_INCH), dpi=72)
    warnings = []
    for k, x, y in page.placed:
        name, _, sk = panels[k]
        w, h = sizes[k]
        ax = fig.add_axes((x / W, (H - y - h) / H, w / W, h / H))
        ax.set_gid(f"panel-{name}")
        _paint(ax, sk)
        warnings += [f"{name}: {m}" for m in sk.warnings]
    t = fig.text(
        PAGE_MARGIN / W,
        (PAGE_MARGIN + FOOTER / 2) / H,
        page.footer(),
        fontsize=SMALL_PT,
        fontfamily=FONT,
        ha="left",
        va="center",
        parse_math=False,
    )
    t.set_gid("note-sheet-paper")
    return fig, warnings


def render_pages(
    sol,
    fmt: str = "svg",
    diagram: str = "all",
    scales=None,
    centre_prefix: str = "I",
    paper: str = "A4",
):
    """The sheet on ``paper`` (A4, A3, letter; portrait or landscape, whichever holds the
    panels): a PDF of as many pages as it needs, or one SVG text (byte-stable) or PNG per
    page. Returns ``(datas, {diagram: Scale}, warnings, pages)``: ``datas`` has one item
    for a PDF, one a page otherwise."""
    import matplotlib

    if fmt not in FORMATS:
        raise PolygonMethodError(f"cannot draw {fmt!r}: use svg, png or pdf")
    with matplotlib.rc_context(_rc()):
        panels, sizes, pages = sheet_pages(sol, diagram, scales, centre_prefix, paper)
    datas, warnings = write_pages(panels, sizes, pages, fmt)
    if diagram == "forces":  # one scale for the free bodies, one for the polygons
        used = {}
        for name, s, _ in panels:
            used.setdefault("free bodies" if name.startswith("free-body") else "force polygons", s)
        return datas, used, warnings, pages
    return datas, {name: s for name, s, _ in panels if s is not None}, warnings, pages


def write_pages(panels, sizes, pages, fmt: str = "svg"):
    """The pages of :func:`sheet_pages` as one PDF (``[bytes]``) or as SVG texts or PNGs,
    one a page. Returns ``(datas, warnings)``."""
    import matplotlib

    with matplotlib.rc_context(_rc()):
        figures, warnings = [], []
        for page in pages:
            fig, w = page_figure(panels, sizes, page)
            figures.append(fig)
            warnings += w
        if fmt == "pdf":
            from matplotlib.backends.backend_pdf import PdfPages

            buf = io.BytesIO()
            with PdfPages(buf, metadata=STABLE_METADATA["pdf"]) as pdf:
                for fig in figures:
                    pdf.savefig(fig)
            return [buf.getvalue()], warnings
        datas = [
            figure_data(fig, fmt, **({"dpi": PNG_DPI} if fmt == "png" else {})) for fig in figures
        ]
        return datas, warnings


def svg_string(sol, diagram: str = "all", scales=None) -> str:
    """The three diagrams side by side as SVG text (``Solution._repr_svg_``)."""
    return render(sol, "svg", diagram, scales)[0]
