"""Pictures of the frames for the GIF and HTML animations of ``draw --animate``: the three
diagrams side by side, drawn with PIL one frame at a time, as the page draws them.

Each picture states the crank angle and each diagram's scale. The configuration diagram
keeps one scale over the cycle; each polygon is drawn, at each frame, at the smallest round
scale (1, 2 or 5 x 10^k per cm, a centimetre being 96/2.54 px as on the page) at which it
fills its panel; nothing is drawn outside its panel. Colours and dashes are the drawings'
own (:mod:`polygon_method.draw.style`). Every picture has the one palette the GIF states
once, so a frame is written as soon as it is drawn and none is kept.

>>> import polygon_method as pm
>>> from polygon_method.page.frames import frames
>>> pics = Pictures(frames(pm.load_scene("worked_problems/fourbar_image_points.toml"), 6))
>>> k = pics.fr.start                   # the scene's instant: 60 deg
>>> pics.size, [pics.scale_text(ph, k) for ph in ("configuration", "velocity")]
((910, 356), ['1 cm = 20 mm', '1 cm = 0.1 m/s'])
>>> pics.picture(k).size, pics.picture(k).mode
((910, 356), 'P')
"""

from __future__ import annotations

import math
from decimal import Decimal

import numpy as np

from ..common.tolerances import ON_PAPER, ROUNDING, SAME
from ..draw.style import (
    BODY_EDGE,
    BODY_FACE,
    HEAD_HALF,
    HEAD_LEN,
    IMAGE_FACE,
    LINE_STYLE,
    PITCH_STYLE,
    STYLE,
)
from ..polygons.scales import DIAGRAMS
from .data import page_data
from .frames import Frames

__all__ = ["Pictures", "round_up", "PX_PER_CM"]

PX_PER_CM = 96 / 2.54  # a centimetre of the screen, as on the page
PANEL, GAP, TOP, CAPTION = 290, 10, 34, 22  # px
FILL = {"configuration": 0.86, "velocity": 0.8, "acceleration": 0.8}
REST = 0.01  # a polygon under this share of its median size is at rest (as on the page)
SS = 1  # px of the drawing per px of the picture
PX_PER_PT = 96 / 72
_TITLE = {
    "configuration": "Configuration diagram",
    "velocity": "Velocity polygon",
    "acceleration": "Acceleration polygon",
}


def round_up(x) -> np.ndarray:
    """The smallest 1, 2 or 5 x 10^k at least ``x`` (positive, elementwise).

    >>> round_up([0.031, 0.2, 7.0, 1e-5]).tolist()
    [0.05, 0.2, 10.0, 1e-05]
    """
    x = np.asarray(x, dtype=float)
    e = np.floor(np.log10(x))
    m = x / 10.0**e
    step = np.select([m <= 1 + SAME, m <= 2 + SAME, m <= 5 + SAME], [1.0, 2.0, 5.0], 10.0)
    return np.array([float(f"{s * 10.0**k:.1g}") for s, k in zip(step.ravel(), e.ravel())])


def _hex(c: str) -> tuple:
    return tuple(int(c[i : i + 2], 16) for i in (1, 3, 5))


def _palette() -> list:
    """The GIF's one palette: greys, the drawings' colours, each faded towards white (the
    edges of smooth lines)."""
    cols = [(g, g, g) for g in range(0, 256, 17)]
    base = [c for c, _, _ in STYLE.values()] + [LINE_STYLE[0], PITCH_STYLE[0], BODY_EDGE]
    for c in dict.fromkeys(base):
        rgb = _hex(c)
        cols += [tuple(round(v + (255 - v) * f) for v in rgb) for f in (0, 0.35, 0.6)]
    return cols + [_hex(c) for c in (BODY_FACE, IMAGE_FACE, "#999999", "#bbbbbb")]


def _missing_glyphs(text: str) -> None:
    """Warn, in matplotlib's words, of each character of ``text`` the pictures' font (DejaVu
    Sans) has no glyph for: the command gathers them into one line (it is drawn as the
    font's empty box)."""
    import unicodedata
    import warnings
    from matplotlib import font_manager, ft2font

    font = ft2font.FT2Font(font_manager.findfont("DejaVu Sans"))
    for c in dict.fromkeys(text):
        if not c.isspace() and font.get_char_index(ord(c)) == 0:
            name = unicodedata.name(c, f"U+{ord(c):04X}")
            warnings.warn(f"Glyph {ord(c)} (\\N{{{name}}}) missing from font(s) DejaVu Sans.")


def _font(size: int):
    from PIL import ImageFont

    for name in ("DejaVuSans.ttf", "dejavu/DejaVuSans.ttf"):
        try:
            return ImageFont.truetype(name, size)
        except OSError:
            continue
    return ImageFont.load_default(size=size)


class Pictures:
    """The frames ``fr`` as pictures (``picture(k)``, a palette image ``size`` px)."""

    def __init__(self, fr: Frames):
        from PIL import Image

        self.fr, self.d = fr, page_data(fr)
        d, n = self.d, len(fr)
        self.n = n
        self.size = (3 * PANEL + 4 * GAP, TOP + CAPTION + PANEL + GAP)

        def arr(flat):
            return np.asarray(flat, dtype=float).reshape(n, 2)

        ground = {
            p: np.broadcast_to(np.asarray(xy, dtype=float), (n, 2)) for p, xy in d["ground"].items()
        }
        zero = np.zeros((n, 2))
        self.xy = {
            "configuration": {**ground, **{p: arr(d["P"][p]) for p in d["points"]}},
            "velocity": {**{p: zero for p in ground}, **{p: arr(d["V"][p]) for p in d["points"]}},
            "acceleration": {
                **{p: zero for p in ground},
                **{p: arr(d["A"][p]) for p in d["points"]},
            },
        }
        self.W = {key: np.asarray(w, dtype=float) for key, w in d["W"].items()}
        self.S = {key: [np.asarray(c, dtype=float) for c in s] for key, s in d["S"].items()}
        self.view = {ph: self._views(ph) for ph in DIAGRAMS}
        pal = Image.new("P", (1, 1))
        flat = [v for c in _palette() for v in c]
        pal.putpalette(flat + [255] * (768 - len(flat)))
        self._pal = pal
        self._font = _font(13 * SS)
        self._big = _font(15 * SS)
        self._masks = {}  # each text's rendering, made once

    def text(self, im, xy, words, font, anchor="la"):
        """``words`` on ``im`` at ``xy`` (left-top, or the middle with ``anchor="mm"``),
        black, each different text rendered once."""
        from PIL import Image, ImageDraw

        key = (words, id(font))
        if key not in self._masks:
            x0, y0, x1, y1 = font.getbbox(words)
            mask = Image.new("L", (max(1, x1 - x0), max(1, y1 - y0)), 0)
            ImageDraw.Draw(mask).text((-x0, -y0), words, fill=255, font=font)
            self._masks[key] = (mask, y0)
        mask, y0 = self._masks[key]
        w, h = mask.size
        x, y = (xy[0] - w / 2, xy[1] - h / 2) if anchor == "mm" else (xy[0], xy[1] + y0)
        x, y = round(x), round(y)
        im.paste((0, 0, 0), (x, y, x + w, y + h), mask)
        return w, h

    def __len__(self):
        return self.n

    # ------------------------------------------------------------------ what is drawn
    def under(self, phase, s):
        """The image of the guide's point under a block, and where its Coriolis component
        starts (SI, per frame): v_X = v_X1 + vs u; a_X = a_X1 + as u + coriolis."""
        P = self.xy["configuration"]
        g = P[s["guide"][1]] - P[s["guide"][0]]
        u = g / np.maximum(np.hypot(g[:, 0], g[:, 1]), 1e-300)[:, None]
        S = self.S[s["key"]]
        cor = np.zeros((self.n, 2)) if phase == "velocity" else np.column_stack([S[2], S[3]])
        along = S[0] if phase == "velocity" else S[1]
        back = self.xy[phase][s["point"]] - cor
        return back - along[:, None] * u, back

    def knee(self, link):
        """Where a link's centripetal component ends, its tangential one starts (SI)."""
        p, q, key = link
        P, w = self.xy["configuration"], self.W[key]
        return self.xy["acceleration"][p] - (w * w)[:, None] * (P[q] - P[p])

    def _vertices(self, phase):
        d, xy = self.d, self.xy[phase]
        if phase == "configuration":
            out = list(xy.values())
            for c, r, *_ in d["wheels"]:
                out += [xy[c] - r, xy[c] + r]
            return out
        out = [np.zeros((self.n, 2))] + [xy[p] for p in d["points"]]
        if phase == "acceleration":
            out += [self.knee(lk) for lk in d["links"]]
        for s in d["sliders"]:
            if "guide" in s:
                out += list(self.under(phase, s))
        return out

    def _views(self, phase):
        """Per frame: SI per cm and the centre (SI) of the panel."""
        v = np.stack(self._vertices(phase))  # (points, frames, 2)
        lo, hi = v.min(axis=0), v.max(axis=0)
        if phase == "configuration":  # one box over the cycle
            lo = np.broadcast_to(lo.min(axis=0), lo.shape)
            hi = np.broadcast_to(hi.max(axis=0), hi.shape)
        size = (hi - lo).max(axis=1)
        rest = max(REST * float(np.median(size)), ROUNDING)
        need = np.maximum(hi - lo, rest).max(axis=1) / (FILL[phase] * PANEL / PX_PER_CM)
        f = self.d["unit"] if phase == "configuration" else 1.0
        return round_up(need / f) * f, (lo + hi) / 2

    def scale_text(self, phase, k) -> str:
        """The round scale of ``phase``'s panel in frame ``k``: "1 cm = 0.5 m/s"."""
        per = self.view[phase][0][k]
        f, unit = (
            (self.d["unit"], self.d["units"])
            if phase == "configuration"
            else (1.0, {"velocity": "m/s", "acceleration": "m/s²"}[phase])
        )
        v = Decimal(f"{per / f:.1g}")
        return f"1 cm = {format(v.normalize(), 'f')} {unit}"

    # ------------------------------------------------------------------ drawing
    def picture(self, k: int):
        """Frame ``k``: the three panels, the crank angle and the scales (a palette image)."""
        from PIL import Image, ImageDraw

        W, H = self.size
        im = Image.new("RGB", (W * SS, H * SS), "white")
        dr = ImageDraw.Draw(im)
        title = self.d["title"]
        if len(title) > 70:
            title = title[:69] + "…"
        if k == 0:
            _missing_glyphs(title)
        w, _ = self.text(im, (GAP * SS, 8 * SS), title, self._big)
        name, symbol, unit = self.fr.parameter
        at = self.fr.degrees[k]
        self.text(
            im,
            (GAP * SS + w + 24 * SS, 8 * SS),
            f"{name} {symbol} = {at % self.fr.cycle_degrees if unit == '°' else at:.1f}{unit}",
            self._big,
        )
        for i, phase in enumerate(DIAGRAMS):
            x0 = (GAP + i * (PANEL + GAP)) * SS
            self.text(
                im,
                (x0, (TOP + 2) * SS),
                f"{_TITLE[phase]}: {self.scale_text(phase, k)}",
                self._font,
            )
            panel = Image.new("RGB", (PANEL * SS, PANEL * SS), "white")
            _Panel(self, phase, k, panel).draw()
            im.paste(panel, (x0, (TOP + CAPTION) * SS))
            dr.rectangle(
                [x0, (TOP + CAPTION) * SS, x0 + PANEL * SS - 1, (TOP + CAPTION + PANEL) * SS - 1],
                outline="#bbbbbb",
                width=SS,
            )
        if SS > 1:
            im = im.reduce(SS)
        return im.quantize(palette=self._pal, dither=Image.Dither.NONE)


class _Panel:
    """One diagram of one frame, drawn in pixels of the (supersampled) panel."""

    def __init__(self, pics: Pictures, phase: str, k: int, im):
        from PIL import ImageDraw

        self.p, self.phase, self.k = pics, phase, k
        self.per, centre = pics.view[phase][0][k], pics.view[phase][1][k]
        self.c = centre
        self.im, self.dr = im, ImageDraw.Draw(im)
        self.px = PX_PER_CM * SS / self.per  # px per SI unit

    def at(self, a) -> tuple:
        half = PANEL * SS / 2
        return (half + (a[0] - self.c[0]) * self.px, half - (a[1] - self.c[1]) * self.px)

    def pt(self, name) -> tuple:
        return self.at(self.p.xy[self.phase][name][self.k])

    def line(self, a, b, kind, head=False):
        color, width, dash = STYLE.get(kind) or {"line": LINE_STYLE, "pitch": PITCH_STYLE}[kind]
        w = max(1, round(width * PX_PER_PT * SS))
        L, half = HEAD_LEN * PX_PER_CM * SS, HEAD_HALF * PX_PER_CM * SS
        dx, dy = b[0] - a[0], b[1] - a[1]
        n = math.hypot(dx, dy)
        if n < ON_PAPER:
            return
        ux, uy = dx / n, dy / n
        end = (b[0] - ux * L * 0.8, b[1] - uy * L * 0.8) if head and n > L else b
        if dash:
            self._dashed(a, end, color, w, [d * width * PX_PER_PT * SS for d in dash])
        else:
            self.dr.line([a, end], fill=color, width=w)
        if head and n > L:
            self.dr.polygon(
                [
                    b,
                    (b[0] - ux * L - uy * half, b[1] - uy * L + ux * half),
                    (b[0] - ux * L + uy * half, b[1] - uy * L - ux * half),
                ],
                fill=color,
            )

    def _dashed(self, a, b, color, w, pattern):
        n = math.hypot(b[0] - a[0], b[1] - a[1])
        ux, uy = (b[0] - a[0]) / n, (b[1] - a[1]) / n
        t, j = 0.0, 0
        while t < n:
            step = max(pattern[j % len(pattern)], 1.0)
            if j % 2 == 0:
                s = min(t + step, n)
                self.dr.line(
                    [(a[0] + ux * t, a[1] + uy * t), (a[0] + ux * s, a[1] + uy * s)],
                    fill=color,
                    width=w,
                )
            t += step
            j += 1

    def label(self, text, at, away=(0.7, -0.7)):
        x = at[0] + away[0] * 10 * SS
        y = at[1] + away[1] * 10 * SS
        hw, hh = 4 * SS * len(text) + 2, 8 * SS + 2  # kept inside the panel
        x = min(max(x, hw), PANEL * SS - hw)
        y = min(max(y, hh), PANEL * SS - hh)
        self.p.text(self.im, (x, y), text, self.p._font, anchor="mm")

    def dot(self, at, r, fill="black", outline=None):
        r *= SS
        self.dr.ellipse(
            [at[0] - r, at[1] - r, at[0] + r, at[1] + r], fill=fill, outline=outline, width=SS
        )

    def _bracket(self, s) -> list:
        """An offset slot's bracket: the convex hull of the link's ends and the slot along
        the link through the block, a little past the block (as the page's script draws)."""
        from shapely.geometry import MultiPoint

        a, b, c = (self.pt(p) for p in (*s["guide"], s["point"]))
        n = math.dist(a, b) or 1.0
        h = 8 * SS
        ends = [
            (c[0] + j * h * (b[0] - a[0]) / n, c[1] + j * h * (b[1] - a[1]) / n) for j in (-1, 1)
        ]
        return list(MultiPoint([a, b, *ends]).convex_hull.exterior.coords)

    def draw(self):
        d, k, ph = self.p.d, self.k, self.phase
        edge = BODY_EDGE
        if ph == "configuration":
            for p, q, c in d["plates"]:
                self.dr.polygon([self.pt(p), self.pt(q), self.pt(c)], fill=BODY_FACE, outline=edge)
            for s in d["sliders"]:  # an offset slot: the link a plate carrying it
                if s.get("offset"):
                    self.dr.polygon(self._bracket(s), fill=BODY_FACE, outline=edge)
            for s in d["sliders"]:
                if "u" in s:
                    c, u = self.pt(s["point"]), (s["u"][0], -s["u"][1])
                    big = 2 * PANEL * SS
                    self.line(
                        (c[0] - big * u[0], c[1] - big * u[1]),
                        (c[0] + big * u[0], c[1] + big * u[1]),
                        "line",
                    )
            for c, r, *_ in d["wheels"]:
                x, y = self.pt(c)
                rr = r * self.px
                self.dr.ellipse([x - rr, y - rr, x + rr, y + rr], outline=PITCH_STYLE[0], width=SS)
            for p, q, _ in d["links"]:
                self.dr.line([self.pt(p), self.pt(q)], fill=edge, width=3 * SS)
            for s in d["sliders"]:
                x, y = self.pt(s["point"])
                h = 6 * SS
                self.dr.rectangle(
                    [x - h, y - h, x + h, y + h], fill=BODY_FACE, outline=edge, width=SS
                )
            for p in d["ground"]:
                x, y = self.pt(p)
                h = 8 * SS
                self.dr.polygon(
                    [(x, y), (x - 0.6 * h, y + h), (x + 0.6 * h, y + h)],
                    fill="#999999",
                    outline="#222222",
                )
            for p in list(d["ground"]) + d["points"]:
                self.dot(self.pt(p), 3, fill="white", outline=edge)
                self.label(p, self.pt(p))
            return
        prime = "'" if ph == "acceleration" else ""
        for p, q, c in d["plates"]:
            self.dr.polygon([self.pt(p), self.pt(q), self.pt(c)], fill=IMAGE_FACE)
        if ph == "acceleration":
            for lk in d["links"]:
                kn = self.at(self.p.knee(lk)[k])
                self.line(self.pt(lk[0]), kn, "centripetal", head=True)
                self.line(kn, self.pt(lk[1]), "tangential", head=True)
        for p, q, _ in d["links"]:
            self.line(self.pt(p), self.pt(q), "relative")
        for s in d["sliders"]:
            if "guide" not in s:
                continue
            u1, back = (self.at(a[k]) for a in self.p.under(ph, s))
            self.line(self.pt(s["guide"][0]), u1, "relative")
            self.line(u1, back, "sliding", head=True)
            if ph == "acceleration":
                self.line(back, self.pt(s["point"]), "coriolis", head=True)
            self.dot(u1, 2)
            self.label(d["under"][s["key"]] + prime, u1, (-0.7, 0.7))
        o = self.at((0.0, 0.0))
        for p in d["points"]:
            self.line(o, self.pt(p), "absolute", head=True)
        self.dot(o, 2.5)
        self.label("o" + prime, o, (-0.8, 0.6))
        for p in d["points"]:
            a = self.pt(p)
            n = math.hypot(a[0] - o[0], a[1] - o[1]) or 1.0
            self.dot(a, 1.8)
            self.label(d["images"][p] + prime, a, ((a[0] - o[0]) / n, (a[1] - o[1]) / n))
