"""``draw --animate``: the three diagrams over the crank's cycle as an animation file for
slides, from the same frames as the page (one sweep, the step table's scales).

GIF and HTML are made with matplotlib's animation module (``PillowWriter``, ``to_jshtml``),
imported only here and only when asked; SVG is written directly, its motion as SMIL
``<animate>`` elements (no script), so that it plays in a browser or a slide program.

>>> import polygon_method as pm
>>> from polygon_method.page import frames
>>> svg = animation(frames(pm.load_scene("worked_problems/fourbar_image_points.toml"), 8),
...                 "svg")
>>> svg.startswith("<svg") and svg.count("<animate ") > 10
True
"""

from __future__ import annotations

import io
import re
from html import escape

import numpy as np

from ..errors import PolygonMethodError, SceneError
from ..scales import DIAGRAMS, display_unit
from ..steps import image_name
from .data import diagram_box
from .frames import Frames, check_frames, need_frames

__all__ = ["animation", "shapes", "FPS"]

#: frames a second of the animations
FPS = 15
#: the SVG animation's text size, in cm of paper (it is drawn true to scale)
FONT_CM = 0.35
_COLOR = {"link": "#222222", "absolute": "#1f5fa8", "relative": "#c2410c"}


def _cm(fr: Frames, phase: str, scale, p):
    """(x, y) arrays in cm of paper (y up) of point ``p`` (or its image) over the frames."""
    n = len(fr)
    table = {"configuration": fr.res.P, "velocity": fr.res.V, "acceleration": fr.res.A}[phase]
    if phase != "configuration" and p in fr.sol.scene.ground:
        return np.zeros(n), np.zeros(n)
    x, y = table[p]
    return (np.broadcast_to(x, (n,)) / scale.per_cm, np.broadcast_to(y, (n,)) / scale.per_cm)


def shapes(fr: Frames):
    """Per diagram: (name, scale, box, lines, labels). ``lines``: (kind, (x1, y1, x2, y2)),
    ``labels``: (text, (x, y)), arrays over the frames in cm of paper, y up."""
    sc = fr.sol.scene
    links = [lk for lk in sc.links if not (lk.p in sc.ground and lk.q in sc.ground)]
    out = []
    for phase, scale in zip(DIAGRAMS, fr.scales):
        box = diagram_box(fr, phase, scale)
        P = {p: _cm(fr, phase, scale, p) for p in sc.point_names}
        lines, labels = [], []
        zero = np.zeros(len(fr))
        if phase == "configuration":
            for cp in sc.points:
                lk = sc.link(cp.link)
                for end in (lk.p, lk.q):
                    lines.append(("link", (*P[end], *P[cp.name])))
            lines += [("link", (*P[lk.p], *P[lk.q])) for lk in links]
            labels = [(p, P[p]) for p in sc.point_names]
        else:
            prime = "'" if phase == "acceleration" else ""
            lines += [("relative", (*P[lk.p], *P[lk.q])) for lk in links]
            lines += [("absolute", (zero, zero, *P[p])) for p in fr.moving]
            labels = [("o" + prime, (zero - 0.3, zero - 0.3))]
            labels += [(image_name(sc, p) + prime, P[p]) for p in fr.moving]
        out.append((phase, scale, box, lines, labels))
    return out


def animation(fr: Frames, fmt_: str):
    """The animation as GIF bytes, HTML text or SVG text (``fmt_``: "gif", "html" or
    "svg"; a GIF or HTML animation has at most :data:`MAX_PICTURE_FRAMES` frames)."""
    need_frames(fr)
    if fmt_ not in ("gif", "html", "svg"):
        raise SceneError(f"cannot animate to {fmt_!r}: gif, html or svg", key="-o")
    check_frames(len(fr), fmt_)
    if fmt_ == "svg":
        return _svg(fr)
    return _matplotlib(fr, fmt_)


def _title(fr, k) -> str:
    return f"{fr.sol.scene.title or 'mechanism'}: crank angle {fr.degrees[k] % 360:.1f}°"


def _matplotlib(fr: Frames, fmt_: str):
    import matplotlib
    from matplotlib.animation import FuncAnimation
    from matplotlib.figure import Figure

    panels = shapes(fr)
    # no frame of the HTML player may be dropped for its size (matplotlib's default
    # limit is 20 MB, about 650 frames): the count of frames is bounded instead
    with matplotlib.rc_context({"font.family": "DejaVu Sans",
                                "animation.embed_limit": 4096.0}):
        fig = Figure(figsize=(12, 4.4), dpi=80)
        fig.subplots_adjust(left=0.01, right=0.99, bottom=0.02, top=0.86, wspace=0.06)
        title = fig.suptitle(_title(fr, 0), fontsize=11)
        artists = []
        for i, (phase, scale, box, lines, labels) in enumerate(panels):
            ax = fig.add_subplot(1, 3, i + 1)
            x0, y0, x1, y1 = box
            pad = 0.08 * max(x1 - x0, y1 - y0, 4)
            ax.set_xlim(x0 - pad, x1 + pad)
            ax.set_ylim(y0 - pad, y1 + pad)
            ax.set_aspect("equal")
            ax.set_xticks([])
            ax.set_yticks([])
            ax.set_title(f"{phase}, {display_unit(scale.text)}", fontsize=9)
            for kind, (a, b, c, d) in lines:
                ln, = ax.plot([a[0], c[0]], [b[0], d[0]], color=_COLOR[kind],
                              lw=2.2 if kind == "link" else 1.6,
                              marker="o" if kind == "link" else None, ms=3)
                artists.append((ln, "line", (a, b, c, d)))
            for text, (x, y) in labels:
                t = ax.text(x[0], y[0], f" {text}", fontsize=9, style="italic",
                            ha="left", va="bottom")
                artists.append((t, "text", (x, y)))

        def draw(k):
            title.set_text(_title(fr, k))
            for a, kind, v in artists:
                if kind == "line":
                    a.set_data([v[0][k], v[2][k]], [v[1][k], v[3][k]])
                else:
                    a.set_position((v[0][k], v[1][k]))
            return []

        anim = FuncAnimation(fig, draw, frames=len(fr), interval=1000 / FPS, blit=False)
        if fmt_ == "html":
            html = anim.to_jshtml(fps=FPS, default_mode="loop")
            _all_there(len(re.findall(r'frames\[\d+\] = "data:', html)), fr)
            return html
        writer = _GifWriter(fps=FPS)
        anim.save("cycle.gif", writer=writer)
        _all_there(len(writer._frames), fr)
        return writer.data


def _all_there(made: int, fr: Frames):
    """Every frame is in the animation, or an error (never fewer frames than stated)."""
    if made != len(fr):
        raise PolygonMethodError(f"the animation holds {made} of its {len(fr)} frames: ask "
                                 "for fewer --frames", key="--frames")


def _gif_writer_class():
    from matplotlib.animation import PillowWriter

    class GifWriter(PillowWriter):
        """PillowWriter whose GIF is kept in memory (the command line writes the file),
        each frame kept as the GIF will hold it (a palette image: a third of the memory
        of its colours)."""

        def grab_frame(self, **kw):
            super().grab_frame(**kw)
            im = self._frames[-1]
            if im.mode == "RGB":
                from PIL import Image
                self._frames[-1] = im.convert("P", palette=Image.Palette.ADAPTIVE)

        def finish(self):
            buf = io.BytesIO()
            self._frames[0].save(buf, format="GIF", save_all=True,
                                 append_images=self._frames[1:],
                                 duration=int(1000 / self.fps), loop=0)
            self.data = buf.getvalue()

    return GifWriter


def _GifWriter(**kw):  # noqa: N802 (a class made on first use: matplotlib stays lazy)
    return _gif_writer_class()(**kw)


def _values(a) -> str:
    return ";".join(f"{x:.3f}" for x in np.asarray(a).tolist())


def _svg(fr: Frames) -> str:
    """The animation as an SVG with SMIL: each line's ends and each label move through the
    frames (discrete values, one frame every 1/FPS s)."""
    panels = shapes(fr)
    dur = f"{len(fr) / FPS:.3f}s"
    anim = f'dur="{dur}" repeatCount="indefinite" calcMode="discrete"'
    parts, x_at, height = [], 0.0, 0.0
    for phase, scale, box, lines, labels in panels:
        x0, y0, x1, y1 = box
        pad = 0.08 * max(x1 - x0, y1 - y0, 4)
        w, h = x1 - x0 + 2 * pad, y1 - y0 + 2 * pad
        fs = FONT_CM
        g = [f'<svg x="{x_at:.3f}" y="1.2" width="{w:.3f}" height="{h:.3f}" '
             f'viewBox="{x0 - pad:.3f} {-y1 - pad:.3f} {w:.3f} {h:.3f}">',
             f'<text x="{x0 - pad + 0.2:.3f}" y="{-y1 - pad + fs:.3f}" font-size="{fs:.3f}">'
             f'{escape(phase)}, {escape(display_unit(scale.text))}</text>']
        for kind, (a, b, c, d) in lines:
            g.append(f'<line stroke="{_COLOR[kind]}" stroke-width="{fs * 0.1:.3f}" '
                     f'stroke-linecap="round">' + "".join(
                         f'<animate attributeName="{n}" values="{_values(v)}" {anim}/>'
                         for n, v in (("x1", a), ("y1", -b), ("x2", c), ("y2", -d)))
                     + "</line>")
        for text, (x, y) in labels:
            g.append(f'<text font-size="{fs:.3f}" font-style="italic">{escape(text)}'
                     f'<animate attributeName="x" values="{_values(x + 0.2 * fs)}" {anim}/>'
                     f'<animate attributeName="y" values="{_values(-y - 0.2 * fs)}" {anim}/>'
                     "</text>")
        g.append("</svg>")
        parts.append("\n".join(g))
        x_at += w + 0.5
        height = max(height, h + 1.5)
    title = escape(fr.sol.scene.title or "mechanism")
    deg = ";".join(f"{d % 360:.1f}" for d in fr.degrees)
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{x_at:.2f}cm" '
            f'height="{height:.2f}cm" viewBox="0 0 {x_at:.3f} {height:.3f}" '
            f'font-family="sans-serif">\n<title>{title}: the diagrams over the crank\'s cycle '
            f'({len(fr)} frames)</title>\n<desc>crank angles (deg): {deg}</desc>\n' + "\n".join(parts)
            + "\n</svg>\n")
