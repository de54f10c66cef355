"""The page: one self-contained HTML file (inline SVG, script and style; nothing fetched).

It holds the problem in words, the three diagrams with a crank-angle slider and a play
button (drawn by ``page.js`` from the frame arrays of :mod:`.data`), the main values at the
current angle, the sweep plots, the step-by-step solution at the scene's instant (the step
table's blocks as HTML tables) and, where there are answers, the check table.

>>> import polygon_method as pm
>>> from polygon_method.page import frames
>>> html = page_html(frames(pm.load_scene("worked_problems/fourbar_image_points.toml"), 36))
>>> html.startswith("<!DOCTYPE html>") and 'id="frames"' in html and 'src="http' not in html
True
"""

from __future__ import annotations

import json
import math
import re
from html import escape
from importlib.resources import files

from ..check.verdicts import also_words, asked_text, correct_text, count_text, percent_text
from ..draw.style import (
    BODY_EDGE,
    BODY_FACE,
    FORCE_STYLE,
    IMAGE_FACE,
    LEAST_STYLE,
    LEGEND_NAMES,
    LINE_STYLE,
    STYLE,
)
from ..common.numbers import fmt
from ..draw.plots import MARK_NAMES, MARKS
from ..text.steptable import steps_blocks
from ..text.words import given
from .data import page_data
from .frames import Frames, need_frames

__all__ = ["page_html", "blocks_html", "check_html", "legend_html"]


def _asset(name: str) -> str:
    return files(__package__).joinpath(name).read_text(encoding="utf-8")


#: the step table's ASCII as a book prints it (the page's own values already are): a
#: square, omega and alpha, a quantity's subscript, a product's times, degrees
_BOOK = (
    (re.compile(r"\bomega(s?)\b"), r"ω\1"),
    (re.compile(r"\balpha\b"), "α"),
    (re.compile(r"\bomega_"), "ω_"),
    (re.compile(r"\balpha_"), "α_"),
    (re.compile(r"(?<=[\w).²]) x (?=[\w(ω])(?!axis|-axis)"), " × "),
    (re.compile(r"(?<![\w-])([A-Za-zωα])_([A-Za-z0-9]+(?:-[A-Za-z0-9]+)?)"), r"\1<sub>\2</sub>"),
    (re.compile(r"(?<=\d) deg\b"), "°"),
    (re.compile(r"\^2\b"), "²"),
    (re.compile(r"\^3\b"), "³"),
)


def book_html(text: str) -> str:
    """``text`` (the step table's words, ASCII) as HTML written as a book prints it.

    >>> book_html("omega_BC = v_CB / BC = 0.3399 / 0.066 = 5.15 rad/s; alpha x AB")
    'ω<sub>BC</sub> = v<sub>CB</sub> / BC = 0.3399 / 0.066 = 5.15 rad/s; α × AB'
    >>> book_html("v_B = omega_AB x AB")
    'v<sub>B</sub> = ω<sub>AB</sub> × AB'
    >>> book_html("v_BA^2 / BA = 5.513 m/s^2 at 30 deg with the x axis, 10.5 x 0.05")
    'v<sub>BA</sub>² / BA = 5.513 m/s² at 30° with the x axis, 10.5 × 0.05'
    """
    out = escape(text)
    for pattern, to in _BOOK:
        out = pattern.sub(to, out)
    return out


def blocks_html(blocks) -> str:
    """The step table's blocks (headings, paragraphs, lists, tables) as HTML, written as a
    book prints them (:func:`book_html`)."""
    out = []
    for b in blocks:
        kind = b[0]
        if kind == "title":
            continue
        if kind == "h":
            out.append(f"<h3>{book_html(b[1])}</h3>")
        elif kind == "p":
            out.append(f"<p>{book_html(b[1])}</p>")
        elif kind == "list":
            out.append("<ul>" + "".join(f"<li>{book_html(i)}</li>" for i in b[1]) + "</ul>")
        else:
            head = "".join(f"<th>{book_html(c)}</th>" for c in b[1])
            rows = "".join(
                "<tr>" + "".join(f"<td>{book_html(c)}</td>" for c in r) + "</tr>" for r in b[2]
            )
            out.append(
                f'<div class="scroll"><table><thead><tr>{head}</tr></thead><tbody>{rows}'
                "</tbody></table></div>"
            )
    return "\n".join(out)


def check_html(verdicts, title: str) -> str:
    """The check table: each answer given, correct, error, tolerance, verdict, diagnosis."""
    rows = []
    for v in verdicts:
        # a number and its per cent never split across lines (a no-break space)
        err = percent_text(v.error, "\u00a0")
        tol = "-" if not math.isfinite(v.tolerance) else f"{100 * v.tolerance:.2g}\u00a0%"
        verdict = '<span class="right">right</span>' if v.ok else '<span class="wrong">WRONG</span>'
        why = "" if v.ok else escape(v.diagnosis or "none of the known mistakes explains it")
        if v.asked:  # a question without its answer: the value, not graded
            verdict = '<span class="asked">asked</span>'
            why = escape(f"asked, no answer given: the tool's value is {asked_text(v)}")
        if v.also:  # the same quantity under two names: graded once
            why = (why + " " if why else "") + escape(also_words(v))
        rows.append(
            "<tr>"
            + "".join(f"<td>{escape(c)}</td>" for c in (v.key, v.raw, correct_text(v), err, tol))
            + f"<td>{verdict}</td><td>{why}</td></tr>"
        )
    rules = "; ".join(sorted({v.rule for v in verdicts if not v.asked}))
    return (
        f'<p>{escape(title)}</p><div class="scroll"><table id="check"><thead><tr><th>'
        "answer</th><th>given</th><th>correct</th><th>error</th><th>tolerance</th><th>"
        f"verdict</th><th>mistake</th></tr></thead><tbody>{''.join(rows)}</tbody></table></div>"
        + (f"<p>tolerance: {escape(rules)}. " if rules else "<p>")
        + f"{escape(count_text(verdicts))}.</p>"
    )


def _json(d) -> str:
    """JSON safe inside a <script> element: no "<" at all, so neither "</script" nor
    "<!--" (which, before a "<script", keeps the element open past its end tag) from a
    title or a file name can end it or run it on."""
    return json.dumps(d, separators=(",", ":"), allow_nan=False).replace("<", "\\u003c")


_CAPTION = {
    "configuration": "Configuration diagram",
    "velocity": "Velocity polygon (pole o; image points in lower case)",
    "acceleration": "Acceleration polygon (pole o'; image points b', c', ...)",
}

#: the legend's entries, in its order: the vectors' kinds, then the plots' marks
_KINDS = ("absolute", "relative", "centripetal", "tangential", "sliding", "coriolis")


def _swatch(color: str, width_pt: float, dashes, *, head: bool = False) -> str:
    """A short line drawn as the page draws that kind (px: 1 pt is 4/3 px)."""
    w = 4 * width_pt / 3
    dash = f' stroke-dasharray="{" ".join(f"{d * w:.2f}" for d in dashes)}"' if dashes else ""
    tip = f'<path d="M30,2 L38,6 L30,10 z" fill="{color}"/>' if head else ""
    return (
        f'<svg class="sw" width="40" height="12" viewBox="0 0 40 12" aria-hidden="true">'
        f'<line x1="1" y1="6" x2="{31 if head else 39}" y2="6" stroke="{color}" '
        f'stroke-width="{w:.2f}"{dash}/>{tip}</svg>'
    )


def legend_html(kinds=_KINDS, least=False) -> str:
    """The legend of the colours and dashes, the same as ``draw``'s and the plots'
    (``least``: op square to xy, where a ``vmin_XY`` is asked)."""
    items = [_swatch(*STYLE[k], head=k != "relative") + escape(LEGEND_NAMES[k]) for k in kinds]
    items.append(_swatch(*LINE_STYLE) + "a path or a guide")
    if least:
        items.append(_swatch(*LEAST_STYLE) + "op square to xy: p, the slowest point's image")
    items.append(
        f'<span class="sw box" style="background:{BODY_FACE};border-color:'
        f'{BODY_EDGE}"></span>a link carrying a third point'
    )
    items.append(f'<span class="sw box" style="background:{IMAGE_FACE}"></span>its image')
    marks = [_swatch(*MARKS[k]) + escape(MARK_NAMES[k]) for k in ("now", "instant")]
    return (
        '<div class="legend"><p><b>Legend</b> (as on the drawings of <code>draw</code> '
        "and the plots of <code>sweep --plot</code>):</p><ul>"
        + "".join(f"<li>{i}</li>" for i in items)
        + "</ul><p>On the plots:</p><ul>"
        + "".join(f"<li>{i}</li>" for i in marks)
        + "</ul></div>"
    )


def _cycle_words(fr: Frames) -> str:
    """What the frames go over: a full turn, a block's travel or the range between the crank's
    limit positions (and what the polygons do near its ends)."""
    block = not fr.sol.plan.steps[0].periodic  # a block driven along its guide
    turns = round(fr.cycle_degrees / 360)
    gears = fr.res.domain.turns > 1  # a gear train back only after several turns
    return (
        (
            "a full turn of the crank"
            if turns == 1
            else f"{turns} turns of the crank (the motion repeats only after them)"
            if gears
            else f"the engine's whole cycle, {turns} turns of the crank ({fr.cycle_degrees:g}°)"
        )
        if fr.full_turn
        else f"the block's travel ({fr.limits_text}): near an end where the mechanism stops "
        "assembling the polygons grow without bound and run off their panels"
        if block
        else f"the range between the limit positions ({fr.limits_text}): the crank cannot "
        "turn fully, and near its limit positions the polygons grow without bound (their "
        "scales grow with them)"
    )


def _sw(kind: str) -> str:
    """A force's colour in words for the caption: a short bar of its colour."""
    c = FORCE_STYLE[kind][0]
    return f'<span class="sw" style="display:inline-block;width:1em;height:0.25em;background:{c}"></span>'


def _forces_caption(d: dict) -> str:
    """The configuration's caption's forces: the inertia forces' scale, and the toggle of
    the layer of the other forces (at the same scale)."""
    out = ""
    if d.get("inertia"):
        text = escape(d["inertia"]["text"])
        out += f'; inertia forces (each on its line h from G): <b id="scale-inertia">{text}</b>'
    if d.get("forces"):
        text = escape(d["forces"]["text"])
        out += (
            '; <label class="toggle"><input type="checkbox" id="show-forces"> the pin '
            f"({_sw('pin')}), guide ({_sw('guide')}) and contact ({_sw('contact')}) forces, "
            f"loads ({_sw('load')}), weights ({_sw('weight')}) and couples</label> "
            + ("(the same scale)" if d.get("inertia") else f'at <b id="scale-forces">{text}</b>')
        )
    return out


def _figures_html(d: dict) -> str:
    """Each diagram's figure: its caption with its scale (the configuration's with the inertia
    forces' scale too) and the empty SVG the script draws into."""
    figs = []
    for s in d["scales"]:
        diagram = s["diagram"]
        forces = "" if diagram != "configuration" else _forces_caption(d)
        figs.append(
            f'<figure><figcaption>{escape(_CAPTION[diagram])}: <b class="scale" '
            f'id="scale-{diagram}">{escape(s["text"])}</b>{forces}</figcaption>'
            f'<svg class="diagram" id="{diagram}" '
            f'role="img" '
            f'aria-label="{diagram} diagram"></svg></figure>'
        )
    return "".join(figs)


def _engine_script(eng) -> str:
    """An engine's cycle's data and the energy page's script that moves its cursor."""
    if not eng or not eng.data:
        return ""
    return (
        f'<script type="application/json" id="cycle">{_json(eng.data)}</script>\n'
        f"<script>\n{_asset('energy.js')}</script>"
    )


def _notes(fr) -> str:
    """The sweep's notes as list items, and where its frames cannot follow a second input
    (``linkage``'s check), that its curves may be aliased."""
    said = fr.res.notes + fr.aliased("the curves and the frames")
    if fr.followed:  # the count raised to follow a wheel: said, as every default is
        said += (f"{len(fr)} frames, {fr.followed}.",)
    return "".join(f"<li>{escape(n)}</li>" for n in said)


def page_html(fr: Frames, *, verdicts=None, answers_title: str = "") -> str:
    """The page for the frames ``fr``: an HTML document as text."""
    sc = need_frames(fr).sol.scene
    source = sc.source
    d = page_data(fr)
    title = d["title"]
    name, symbol, unit = fr.parameter
    block = not fr.sol.plan.steps[0].periodic  # a block driven along its guide
    cycle = _cycle_words(fr)
    notes = _notes(fr)
    check = ""
    if verdicts:
        check = f"<h2>Answers checked</h2>\n{check_html(verdicts, answers_title)}"
    from .engine_cycle import engine_part  # (it reads the energy page's parts, which read ours)

    eng = engine_part(fr)
    return f"""<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{escape(title)}</title>
<style>
{_asset("page.css")}
{_asset("energy.css") if eng else ""}
</style>
</head>
<body>
<h1>{escape(title)}</h1>
{f'<p class="source">{escape(source)}</p>' if source else ""}
<details open><summary><b>The problem</b></summary>
<ul>{"".join(f"<li>{escape(w)}</li>" for w in given(sc))}</ul>
</details>
<div class="controls">
<button id="play" type="button">▶ play</button>
<label for="angle">{name}</label>
<input type="range" id="angle" min="0" max="{len(fr) - 1}" step="1" value="{fr.start}">
<span id="angle-now"></span>
</div>
<p class="legend-line">{len(fr)} frames over {escape(cycle)}. The configuration diagram keeps
one scale over the cycle; each polygon is drawn, at each angle, at the round scale
(1, 2 or 5 x 10<sup>k</sup> per cm) at which it fills its panel, stated above it (a centimetre
of the screen as the browser measures it, 96 px = 2.54 cm; the step-by-step solution states
the scales of a drawing on paper). The stated instant is {symbol} =
{fmt(sc.input.angle / sc.length_unit) + unit if block else fmt(math.degrees(sc.input.angle) % fr.cycle_degrees) + unit}{escape(f" ({sc.input.angle_words})" if sc.input.angle_words else "")}. Hover over a vector or a point for its
value, or tap it.</p>
{f"<ul>{notes}</ul>" if notes else ""}
<div class="diagrams">
{_figures_html(d)}
</div>
{legend_html(_KINDS if d["under"] else _KINDS[:4], bool(d["least"]))}
<div class="columns">
<div>
<h2>Values at the current angle</h2>
<div class="scroll"><table id="values"><tbody></tbody></table></div>
</div>
<div>
<h2>Over the cycle</h2>
<div class="plots">
<svg class="plot" id="plot-v" viewBox="0 0 320 210" role="img" aria-label="speeds over the cycle"></svg>
<svg class="plot" id="plot-w" viewBox="0 0 320 210" role="img" aria-label="angular velocities over the cycle"></svg>
<svg class="plot" id="plot-a" viewBox="0 0 320 210" role="img" aria-label="accelerations over the cycle"></svg>
</div>
</div>
</div>
{eng.html if eng else ""}
<h2>Step by step, at the stated instant</h2>
{blocks_html(steps_blocks(fr.sol).blocks)}
{check}
<footer>Made by polygon-method: the relative-velocity method, exact to rounding; the frames
are one sweep of the scene on its own branch.</footer>
<div id="tooltip" hidden></div>
<script type="application/json" id="frames">{_json(d)}</script>
<script>
{_asset("page.js")}
</script>
{_engine_script(eng)}
</body>
</html>
"""
