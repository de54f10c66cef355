"""``draw --animate``: the three diagrams over the crank's cycle as an animation file for
slides, from the same frames as the page (one sweep, the step table's scales).

GIF and HTML are made of the pictures of :mod:`.raster` (PIL; each polygon at its own round
scale per frame, the scales and the crank angle on each picture): the GIF is written a frame
at a time as each is drawn, the HTML is a player that needs nothing else (no network, no
icon fetched). SVG is written directly, its motion as SMIL ``<animate>`` elements (no
script), so that it plays in a browser or a slide program.

>>> import polygon_method as pm
>>> from polygon_method.page import frames
>>> svg = animation(frames(pm.load_scene("worked_problems/fourbar_image_points.toml"), 8),
...                 "svg")
>>> svg.startswith("<svg") and svg.count("<animate ") > 10
True
"""

from __future__ import annotations

import base64
import io
import json
from html import escape

import numpy as np

from ..draw.style import BODY_EDGE, STYLE
from ..common.errors import SceneError
from ..polygons.scales import DIAGRAMS, display_unit
from ..steps import image_name
from .data import diagram_box
from .frames import Frames, check_frames, need_frames
from .raster import Pictures

__all__ = ["animation", "shapes", "FPS"]

#: frames a second of the animations
FPS = 15
#: the SVG animation's text size, in cm of paper (it is drawn true to scale)
FONT_CM = 0.35
#: colour and width (cm) of each kind of line, as the drawings have them
_COLOR = {"link": BODY_EDGE, "absolute": STYLE["absolute"][0], "relative": STYLE["relative"][0]}
_WIDTH = {
    "link": 0.06,
    "absolute": STYLE["absolute"][1] * 2.54 / 72,
    "relative": STYLE["relative"][1] * 2.54 / 72,
}


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
    return _gif(fr) if fmt_ == "gif" else _html(fr)


def _gif(fr: Frames) -> bytes:
    """The GIF, each frame written as soon as it is drawn (one palette, stated once): the
    memory is the pictures' of one frame and the file itself."""
    from PIL import GifImagePlugin

    pics = Pictures(fr)
    out = io.BytesIO()
    ms = round(1000 / FPS)
    for k in range(len(fr)):
        im = pics.picture(k)
        if k == 0:
            head, _ = GifImagePlugin.getheader(im, info={"loop": 0, "duration": ms})
            out.write(b"".join(head))
        out.write(b"".join(GifImagePlugin.getdata(im, duration=ms)))
    out.write(b";")
    return out.getvalue()


_PLAYER_CSS = """body { font-family: system-ui, sans-serif; margin: 1em; color: #222; }
img { max-width: 100%; height: auto; display: block; border: 1px solid #ddd; }
.controls { display: flex; flex-wrap: wrap; gap: 0.5em; align-items: center; margin: 0.5em 0; }
.controls input[type=range] { flex: 1; min-width: 10em; }
button { font-size: 1em; padding: 0.2em 0.7em; }"""

_PLAYER_JS = """"use strict";
const F = JSON.parse(document.getElementById("frames").textContent);
const pic = document.getElementById("pic"), slider = document.getElementById("k");
const play = document.getElementById("play"), now = document.getElementById("now");
let k = 0, timer = null;
function show(j) {
  k = (j + F.pictures.length) % F.pictures.length;
  pic.src = F.pictures[k];
  slider.value = k;
  now.textContent = "frame " + (k + 1) + " of " + F.pictures.length + ", crank angle " + F.angles[k] + "\u00b0";
}
play.addEventListener("click", () => {
  if (timer === null) { timer = setInterval(() => show(k + 1), 1000 / F.fps); play.textContent = "\u275a\u275a pause"; }
  else { clearInterval(timer); timer = null; play.textContent = "\u25b6 play"; }
});
document.getElementById("back").addEventListener("click", () => show(k - 1));
document.getElementById("next").addEventListener("click", () => show(k + 1));
slider.addEventListener("input", () => show(Number(slider.value)));
show(0);"""


def _html(fr: Frames) -> str:
    """A player that needs nothing else (no network, no script or icon fetched): the
    pictures as PNG data, play/pause, a frame at a time, a slider."""
    pics = Pictures(fr)
    frames_ = []
    for k in range(len(fr)):
        buf = io.BytesIO()
        pics.picture(k).save(buf, format="PNG", compress_level=1)
        frames_.append("data:image/png;base64," + base64.b64encode(buf.getvalue()).decode())
    data = json.dumps(
        {
            "pictures": frames_,
            "fps": FPS,
            "angles": [f"{a % fr.cycle_degrees:.1f}" for a in fr.degrees],
        },
        separators=(",", ":"),
    )
    title = escape(fr.sol.scene.title or "mechanism")
    w, h = pics.size
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title}</title>
<style>
{_PLAYER_CSS}
</style>
</head>
<body>
<img id="pic" width="{w}" height="{h}" alt="{title}: the configuration diagram, the velocity and the acceleration polygons over the crank's cycle">
<div class="controls">
<button id="back" type="button" title="a frame back">\u25c0</button>
<button id="play" type="button">\u25b6 play</button>
<button id="next" type="button" title="a frame on">\u25b6</button>
<input type="range" id="k" min="0" max="{len(fr) - 1}" step="1" value="0" aria-label="frame">
<span id="now"></span>
</div>
<script type="application/json" id="frames">{data}</script>
<script>
{_PLAYER_JS}
</script>
</body>
</html>
"""


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
        g = [
            f'<svg x="{x_at:.3f}" y="1.2" width="{w:.3f}" height="{h:.3f}" '
            f'viewBox="{x0 - pad:.3f} {-y1 - pad:.3f} {w:.3f} {h:.3f}">',
            f'<text x="{x0 - pad + 0.2:.3f}" y="{-y1 - pad + fs:.3f}" font-size="{fs:.3f}">'
            f"{escape(phase)}, {escape(display_unit(scale.text))}</text>",
        ]
        for kind, (a, b, c, d) in lines:
            g.append(
                f'<line stroke="{_COLOR[kind]}" stroke-width="{_WIDTH[kind]:.3f}" '
                f'stroke-linecap="round">'
                + "".join(
                    f'<animate attributeName="{n}" values="{_values(v)}" {anim}/>'
                    for n, v in (("x1", a), ("y1", -b), ("x2", c), ("y2", -d))
                )
                + "</line>"
            )
        for text, (x, y) in labels:
            g.append(
                f'<text font-size="{fs:.3f}" font-style="italic">{escape(text)}'
                f'<animate attributeName="x" values="{_values(x + 0.2 * fs)}" {anim}/>'
                f'<animate attributeName="y" values="{_values(-y - 0.2 * fs)}" {anim}/>'
                "</text>"
            )
        g.append("</svg>")
        parts.append("\n".join(g))
        x_at += w + 0.5
        height = max(height, h + 1.5)
    title = escape(fr.sol.scene.title or "mechanism")
    deg = ";".join(f"{d % fr.cycle_degrees:.1f}" for d in fr.degrees)
    return (
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{x_at:.2f}cm" '
        f'height="{height:.2f}cm" viewBox="0 0 {x_at:.3f} {height:.3f}" '
        f'font-family="sans-serif">\n<title>{title}: the diagrams over the crank\'s cycle '
        f"({len(fr)} frames)</title>\n<desc>crank angles (deg): {deg}</desc>\n"
        + "\n".join(parts)
        + "\n</svg>\n"
    )
