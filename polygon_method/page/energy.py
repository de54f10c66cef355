"""The page of a turning-moment diagram stated on its own (no mechanism to animate): one
self-contained HTML file with the turning moment and the energy (and the flywheel's speed,
where the scene gives a flywheel) over the cycle, a cursor moving over the crank angle with
a slider and a play button, the values at the cursor, the book's table of the areas and the
energies at the crossings, the answers, the step table and, where there are answers, the
check table.

Everything shown is read from the solve (:func:`~polygon_method.forces.flywheel_cycle.
solve_cycle`) and its closed forms at each frame (:func:`~polygon_method.forces.
flywheel_cycle.at_angles`, :func:`~polygon_method.forces.flywheel_cycle.speed_at`): the
page works nothing out. The plots are drawn here as SVG; the small script (``energy.js``)
only moves the cursor and writes the values the data hold, already formatted.

>>> from polygon_method.scene.energy import parse_cycle
>>> from polygon_method.forces.flywheel_cycle import solve_cycle
>>> s = parse_cycle('[turning_moment]\\ntorque = "1000 + 300 sin 2theta"')
>>> html = cycle_page(s, solve_cycle(s), 36)
>>> html.startswith("<!DOCTYPE html>") and 'id="cycle"' in html and "http" not in html
True
"""

from __future__ import annotations

import math
from html import escape

import numpy as np

from ..common.tolerances import ROUNDING
from ..forces.flywheel_cycle import at_angles, curves, speed_at
from ..text.energy import FORMS, answer_lines, book_number as _g, cycle_steps
from .html import _asset, _json, check_html

__all__ = [
    "cycle_page",
    "book_table",
    "energy_words",
    "Plot",
    "plot_svg",
    "angle_ticks",
    "shaded",
    "marker",
]

_W, _H = 600, 250  # a plot's viewBox (px)
_L, _R, _T, _B = 74, 16, 30, 46  # its margins
_ABOVE, _BELOW = "#c8e6c9", "#ffcdd2"


_LEGEND = (
    "Shaded green where the turning moment is above the mean (resisting) line, the energy "
    "rising; red where it is below.",
    "The punching draws the energy of a hole while the motor gives its share all through the "
    "cycle (dashed): the flywheel gives the rest, and takes it back after.",
)


def _round_ticks(lo: float, hi: float, most: int = 6) -> list:
    """Round ticks (1, 2 or 5 x 10^k apart) over ``[lo, hi]``, at most about ``most``."""
    span = hi - lo
    if not span > 0:
        return [lo]
    raw = span / most
    k = 10 ** math.floor(math.log10(raw))
    step = next(m * k for m in (1, 2, 5, 10) if m * k >= raw)
    first = math.ceil(lo / step - ROUNDING)
    return [i * step for i in range(first, int(math.floor(hi / step + ROUNDING)) + 1)]


class Plot:
    """One plot's axes: data to viewBox pixels."""

    def __init__(self, x0, x1, ys):
        lo, hi = float(np.min(ys)), float(np.max(ys))
        pad = 0.08 * (hi - lo) if hi > lo else max(abs(hi), 1.0) * 0.1
        self.x0, self.x1, self.y0, self.y1 = x0, x1, lo - pad, hi + pad

    def px(self, x):
        """The viewBox x (px) of the data's ``x``."""
        return _L + (np.asarray(x, float) - self.x0) / (self.x1 - self.x0) * (_W - _L - _R)

    def py(self, y):
        """The viewBox y (px) of the data's ``y``."""
        return _H - _B - (np.asarray(y, float) - self.y0) / (self.y1 - self.y0) * (_H - _T - _B)

    def path(self, xs, ys) -> str:
        """An SVG path through the data's points, to the hundredth of a px."""
        pts = zip(self.px(xs), self.py(ys))
        return "M" + " L".join(f"{a:.2f},{b:.2f}" for a, b in pts)

    def frame(self, title, ytitle, xtitle, xticks, yticks=True) -> str:
        """The axes, grid, ticks and titles (``xticks``: (value, label) pairs; no ticks up
        a sketch's axis)."""
        out = [f'<text class="plot-title" x="{_L}" y="19">{escape(title)}</text>']
        bottom, right = _H - _B, _W - _R
        for v in _round_ticks(self.y0, self.y1) if yticks else ():
            y = float(self.py(v))
            out.append(f'<line class="grid" x1="{_L}" x2="{right}" y1="{y:.2f}" y2="{y:.2f}"/>')
            out.append(
                f'<text class="tick" x="{_L - 4}" y="{y + 3:.2f}" text-anchor="end">'
                f"{escape(_g(v) if v else '0')}</text>"
            )
        for v, label in xticks:
            x = float(self.px(v))
            out.append(f'<line class="grid" x1="{x:.2f}" x2="{x:.2f}" y1="{_T}" y2="{bottom}"/>')
            end = "end" if x > right - _R else "middle"  # the last kept inside the plot
            out.append(
                f'<text class="tick" x="{x:.2f}" y="{bottom + 16}" text-anchor="{end}">'
                f"{escape(label)}</text>"
            )
        out.append(
            f'<path class="axis" d="M{_L},{_T} L{_L},{bottom} L{right},{bottom}" fill="none"/>'
        )
        out.append(
            f'<text class="axis-title" x="{(_L + right) / 2:.1f}" y="{_H - 5}" '
            f'text-anchor="middle">{escape(xtitle)}</text>'
        )
        out.append(
            f'<text class="axis-title" transform="translate(14,{(_T + bottom) / 2:.1f}) '
            f'rotate(-90)" text-anchor="middle">{escape(ytitle)}</text>'
        )
        return "".join(out)


def plot_svg(pid, label, body) -> str:
    """A plot's SVG (``pid`` its id) with the cursor's line and dot the script moves."""
    return (
        f'<svg class="plot cycle-plot" id="{pid}" viewBox="0 0 {_W} {_H}" role="img" '
        f'aria-label="{escape(label)}">{body}'
        f'<line class="cursor" id="{pid}-cursor" x1="0" x2="0" y1="{_T}" y2="{_H - _B}"/>'
        f'<circle class="cursor-dot" id="{pid}-dot" r="4" cx="0" cy="0"/></svg>'
    )


def angle_ticks(cycle_deg):
    """Round crank-angle ticks over a cycle of ``cycle_deg``: (value, label) pairs."""
    step = next(s for s in (15, 30, 45, 60, 90, 120, 180, 360) if cycle_deg / s <= 8)
    return [(v, f"{v:g}°") for v in np.arange(0, cycle_deg + ROUNDING, step)]


def shaded(p, x, T, R, cuts, flip: bool = False) -> str:
    """The areas between the turning moment ``T`` and the line ``R`` (at ``x``), shaded from
    one crossing to the next (``cuts``, with the ends; ``x``'s unit): green above, red below
    (``flip``: green below, red above, a machine's demand under the motor's mean)."""
    out = []
    for a, b in zip(cuts, cuts[1:]):
        m = (x >= a) & (x <= b)
        t_in, T_in, R_in = x[m], T[m], R[m]
        if len(t_in) < 2:
            continue
        above = (float(np.mean(T_in - R_in)) >= 0) != flip
        d = p.path(t_in, T_in) + " L" + p.path(t_in[::-1], R_in[::-1])[1:] + " Z"
        out.append(f'<path d="{d}" fill="{_ABOVE if above else _BELOW}" stroke="none"/>')
    return "".join(out)


def marker(p, x, y, tip, cls="crossing") -> str:
    """A dot at the data's (x, y) on the plot ``p`` that names itself (``tip``) on hover."""
    return (
        f'<circle class="{cls}" cx="{float(p.px(x)):.2f}" cy="{float(p.py(y)):.2f}" r="3.5">'
        f"<title>{escape(tip)}</title></circle>"
    )


def _crossing_tip(x) -> str:
    where = "" if x.angle is None else f" at {math.degrees(x.angle):.4g}°"
    e = "E" if x.energy == 0 else f"E {'+' if x.energy > 0 else '-'} {_g(abs(x.energy))} J"
    return f"crossing {x.letter}{where}: {e}"


def _curve_panels(scene, c, th):
    """The law's or the segments' plots: (svg texts, cursor rows per plot)."""
    th_s, tq_s, rs_s, es_s = curves(scene, c, 721)
    deg, cyc = np.degrees(th_s), math.degrees(c.cycle)
    ticks = angle_ticks(cyc)
    p = Plot(0.0, cyc, np.concatenate([tq_s, rs_s]))
    cuts = sorted({0.0, c.cycle} | {x.angle % c.cycle for x in c.crossings[:-1]})
    shade = shaded(p, deg, tq_s, rs_s, np.degrees(cuts))
    mean = "the mean torque" if scene.diagram.resisting is None else "the resisting torque"
    body = (
        p.frame(f"turning moment T and {mean}", "torque (N m)", "crank angle", ticks)
        + shade
        + f'<path class="series" d="{p.path(deg, rs_s)}" stroke="#1565c0" '
        'stroke-dasharray="6 4"/>' + f'<path class="series" d="{p.path(deg, tq_s)}" stroke="#111"/>'
    )
    _, rs_x, _ = at_angles(scene, c, [x.angle % c.cycle for x in c.crossings[:-1]])
    for x, r in zip(c.crossings[:-1], rs_x):
        body += marker(p, math.degrees(x.angle % c.cycle), r, _crossing_tip(x))
    tq, rs, es = at_angles(scene, c, th)
    panels = [
        (plot_svg("plot-torque", "turning moment over the cycle", body), p, np.degrees(th), tq)
    ]
    pe = Plot(0.0, cyc, es_s)
    body = pe.frame("energy above E at a", "energy (J)", "crank angle", ticks)
    body += f'<path class="series" d="{pe.path(deg, es_s)}" stroke="#111"/>'
    for x in c.crossings[:-1]:
        body += marker(pe, math.degrees(x.angle % c.cycle), x.energy, _crossing_tip(x))
    panels.append((plot_svg("plot-energy", "energy over the cycle", body), pe, np.degrees(th), es))
    if c.inertia is not None:
        ws = speed_at(c, es_s)
        pw = Plot(0.0, cyc, ws)
        body = pw.frame("the flywheel's speed", "speed (rad/s)", "crank angle", ticks)
        body += f'<path class="series" d="{pw.path(deg, ws)}" stroke="#6a1b9a"/>'
        panels.append(
            (
                plot_svg("plot-speed", "speed over the cycle", body),
                pw,
                np.degrees(th),
                speed_at(c, es),
            )
        )
    return panels, (tq, rs, es)


def _curve_rows(scene, c, th, tq, rs, es) -> list:
    """The values table's rows at each frame: (name, [text per frame])."""
    mean = "mean torque" if scene.diagram.resisting is None else "resisting torque R"
    rows = [
        ("crank angle θ", [f"{math.degrees(x):.4g}°" for x in th]),
        ("turning moment T", [f"{_g(v)} N m" for v in tq]),
        (mean, [f"{_g(v)} N m" for v in rs]),
        ("T − R", [f"{_g(v)} N m" for v in tq - rs]),
        ("energy above E at a", [f"{_g(v)} J" for v in es]),
    ]
    if c.inertia is not None:
        ws = speed_at(c, es)
        rows.append(("speed ω", [f"{_g(w)} rad/s ({_g(w * 30 / math.pi)} rpm)" for w in ws]))
        rows.append(
            ("angular acceleration (T − R) / I", [f"{_g(v)} rad/s²" for v in (tq - rs) / c.inertia])
        )
    return rows


def _areas_panels(c):
    """A diagram given as areas: the lobes sketched (widths not given), the energies at
    the crossings, the speeds there; the cursor steps over the crossings."""
    n = len(c.areas)
    idx = np.arange(n + 1)
    ticks = [(i, x.letter) for i, x in enumerate(c.crossings)]
    lobes = [a * math.pi / 2 for a in c.areas]  # a half sine of the lobe's area, unit width
    p = Plot(0.0, float(n), np.array(lobes + [0.0]))
    body = p.frame(
        "the areas about the mean line (a sketch)",
        "torque",
        "crossing",
        ticks,
        yticks=False,
    )
    for i, a in enumerate(c.areas):
        u = np.linspace(i, i + 1, 41)
        y = a * math.pi / 2 * np.sin(np.pi * (u - i))
        d = p.path(u, y) + " Z"
        fill = _ABOVE if a > 0 else _BELOW
        body += f'<path d="{d}" fill="{fill}" stroke="#111" stroke-width="0.8"><title>{escape(f"{a:+.6g} J")}</title></path>'
        body += (
            f'<text class="tick" x="{float(p.px(i + 0.5)):.2f}" y="{float(p.py(y[20] / 2)):.2f}" '
            f'text-anchor="middle">{escape(f"{_g(a)} J")}</text>'
        )
    body += f'<path class="series" d="{p.path([0, n], [0, 0])}" stroke="#1565c0" stroke-dasharray="6 4"/>'
    es = np.array([x.energy for x in c.crossings])
    panels = [(plot_svg("plot-torque", "the areas of the diagram", body), p, idx, np.zeros(n + 1))]
    pe = Plot(0.0, float(n), es)
    body = pe.frame("energy above E at a", "energy (J)", "crossing", ticks)
    body += f'<path class="series" d="{pe.path(idx, es)}" stroke="#111"/>'
    for i, x in enumerate(c.crossings[:-1]):
        body += marker(pe, i, x.energy, _crossing_tip(x))
    panels.append((plot_svg("plot-energy", "energy at the crossings", body), pe, idx, es))
    if c.inertia is not None:
        ws = speed_at(c, es)
        pw = Plot(0.0, float(n), ws)
        body = pw.frame("the flywheel's speed at the crossings", "speed (rad/s)", "crossing", ticks)
        body += f'<path class="series" d="{pw.path(idx, ws)}" stroke="#6a1b9a"/>'
        panels.append((plot_svg("plot-speed", "speed at the crossings", body), pw, idx, ws))
    rows = [
        ("crossing", [x.letter for x in c.crossings]),
        ("energy above E at a", [f"{_g(v)} J" for v in es]),
    ]
    if c.inertia is not None:
        rows.append(("speed ω", [f"{_g(w)} rad/s ({_g(w * 30 / math.pi)} rpm)" for w in ws]))
    return panels, rows


def _press_energy(c, press, t):
    """The flywheel's energy above its start (J) at the times ``t`` of the cycle (s): the
    punching draws E / t_punching while the motor gives E / t_cycle."""
    tp = press.fraction * press.period
    t = np.asarray(t, float)
    return np.where(t <= tp, -c.dE_max * t / tp, -c.dE_max + c.power * (t - tp))


def _press_panels(scene, c, n):
    press = scene.press
    P, tp = press.period, press.fraction * press.period
    t = np.linspace(0.0, P, n, endpoint=False)
    ticks = [(v, f"{_g(v) if v else '0'} s") for v in _round_ticks(0.0, P)]
    draw = c.E_stroke / tp
    p = Plot(0.0, P, np.array([0.0, draw, c.power]))
    body = p.frame(
        "the power the punching takes, and the motor's", "power (W)", "time in the cycle", ticks
    )
    body += f'<path class="series" d="{p.path([0, tp, tp, P], [draw, draw, 0, 0])}" stroke="#111"/>'
    body += f'<path class="series" d="{p.path([0, P], [c.power, c.power])}" stroke="#1565c0" stroke-dasharray="6 4"/>'
    taken = np.where(t < tp, draw, 0.0)
    panels = [(plot_svg("plot-torque", "power over the cycle", body), p, t, taken)]
    es = _press_energy(c, press, t)
    pe = Plot(0.0, P, np.array([0.0, -c.dE_max]))
    body = pe.frame(
        "the flywheel's energy above its start", "energy (J)", "time in the cycle", ticks
    )
    body += f'<path class="series" d="{pe.path([0, tp, P], [0, -c.dE_max, 0])}" stroke="#111"/>'
    for x, tt in zip(c.crossings[:2], (0.0, tp)):
        body += marker(pe, tt, x.energy, _crossing_tip(x))
    panels.append((plot_svg("plot-energy", "energy over the cycle", body), pe, t, es))
    rows = [
        ("time in the cycle", [f"{_g(v) if v else '0'} s" for v in t]),
        ("power the punching takes", [f"{_g(v) if v else '0'} W" for v in taken]),
        ("the motor's power", [f"{_g(c.power)} W"] * len(t)),
        ("the flywheel's energy above its start", [f"{_g(v) if v else '0'} J" for v in es]),
    ]
    if c.inertia is not None:
        ws = speed_at(c, es)
        pw = Plot(0.0, P, speed_at(c, np.array([0.0, -c.dE_max])))
        body = pw.frame("the flywheel's speed", "speed (rad/s)", "time in the cycle", ticks)
        body += f'<path class="series" d="{pw.path([0, tp, P], speed_at(c, [0, -c.dE_max, 0]))}" stroke="#6a1b9a"/>'
        panels.append((plot_svg("plot-speed", "speed over the cycle", body), pw, t, ws))
        rows.append(("speed ω", [f"{_g(w)} rad/s ({_g(w * 30 / math.pi)} rpm)" for w in ws]))
    return panels, rows


def _frames(scene, c, n):
    """(panels, rows, what the slider moves over) of the cycle's ``n`` frames."""
    if c.form == "press":
        panels, rows = _press_panels(scene, c, n)
        return panels, rows, f"{n} instants over one cycle of {_g(scene.press.period)} s"
    if c.form == "areas":
        panels, rows = _areas_panels(c)
        return panels, rows, "the crossings of the mean line (the areas give no angles)"
    th = np.linspace(0.0, c.cycle, n, endpoint=False)
    panels, (tq, rs, es) = _curve_panels(scene, c, th)
    rows = _curve_rows(scene, c, th, tq, rs, es)
    return panels, rows, f"{n} crank angles over the cycle of {math.degrees(c.cycle):g}°"


def _book_table(c) -> str:
    """The book's table: from, to, the area between, the energy at the end (E at a = E)."""

    def where(x):
        return x.letter if x.angle is None else f"{x.letter} ({math.degrees(x.angle):.4f}°)"

    rows = []
    for i in range(len(c.crossings) - 1):
        a, b = c.crossings[i], c.crossings[i + 1]
        area = c.areas[i] if i < len(c.areas) else b.energy - a.energy
        rows.append((where(a), where(b), f"{area:+.6g}", energy_words(b.energy)))
    return book_table(rows)


def energy_words(e: float) -> str:
    """The energy at a crossing in the book's words: E, E + 12.5, E − 3 (J)."""
    return "E" if e == 0 else f"E {'+' if e > 0 else '−'} {_g(abs(e))}"


def book_table(rows, tid: str = "book") -> str:
    """The book's table of the areas between the crossings: each row (from, to, the area
    (J), the energy at the end) as text, in a box that scrolls on a phone."""
    body = "".join(
        "<tr>" + "".join(f"<td>{escape(x)}</td>" for x in cells) + "</tr>" for cells in rows
    )
    return (
        f'<div class="scroll"><table id="{tid}"><thead><tr><th>from</th><th>to</th>'
        f"<th>area (J)</th><th>energy at the end (J)</th></tr></thead><tbody>{body}"
        "</tbody></table></div>"
    )


def cycle_page(scene, c, frames: int = 180, *, verdicts=None, answers_title: str = "") -> str:
    """The page of the solved cycle ``c`` of ``scene`` (a
    :class:`~polygon_method.scene.energy_records.CycleScene`): an HTML document as text."""
    panels, rows, over = _frames(scene, c, frames)
    n = len(rows[0][1])
    data = {
        "n": n,
        "cursor": [
            [_pid(svg), [round(float(v), 2) for v in p.px(x)], _ys(p, y)] for svg, p, x, y in panels
        ],
        "rows": [[name, vals] for name, vals in rows],
    }
    title = scene.title or "Turning-moment diagram"
    check = ""
    if verdicts:
        check = f"<h2>Answers checked</h2>\n{check_html(verdicts, answers_title)}"
    answers = "".join(f"<li>{escape(w.strip())}</li>" for w in answer_lines(c))
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{escape(title)}</title>
<style>
{_asset("page.css")}
{_asset("energy.css")}
</style>
</head>
<body>
<h1>{escape(title)}</h1>
{f'<p class="source">{escape(scene.source)}</p>' if scene.source else ""}
<details open><summary><b>The problem</b>: {escape(FORMS[c.form])}</summary>
<ul>{"".join(f"<li>{escape(w)}</li>" for w in c.words)}</ul>
</details>
<div class="controls">
<button id="play" type="button">▶ play</button>
<label for="angle">{escape(rows[0][0])}</label>
<input type="range" id="angle" min="0" max="{n - 1}" step="1" value="0">
<span id="angle-now"></span>
</div>
<p class="legend-line">The cursor moves over {escape(over)}. {_LEGEND[c.form == "press"]}
Hover over (or tap) a crossing for its energy.</p>
<div class="cycle-plots">
{"".join(svg for svg, _, _, _ in panels)}
</div>
<div class="columns">
<div>
<h2>Values at the cursor</h2>
<div class="scroll"><table id="values"><tbody></tbody></table></div>
</div>
<div>
<h2>The answers</h2>
<ul id="answers">{answers}</ul>
</div>
</div>
<h2>{"The energies over the cycle" if c.form == "press" else "The areas and the energies at the crossings"}</h2>
{_book_table(c)}
<details><summary><b>Step by step</b></summary>
<pre class="scroll">{escape(cycle_steps(scene, c))}</pre>
</details>
{check}
<footer>Made by polygon-method: the turning-moment diagram's integrals and crossings in
closed form (the crossings bisected to the last bit).</footer>
<script type="application/json" id="cycle">{_json(data)}</script>
<script>
{_asset("energy.js")}
</script>
</body>
</html>
"""


def _pid(svg: str) -> str:
    """The id of a plot's SVG text."""
    return svg.split('id="', 1)[1].split('"', 1)[0]


def _ys(p, y) -> list:
    return [round(float(v), 2) for v in p.py(y)]
