"""An engine's turning-moment diagram on the mechanism's page: for a scene with
``[indicator]`` (or ``[flywheel]``) whose crank turns fully, the turning moment over the
engine's cycle (two turns for a four-stroke) with the mean line, the areas between them
shaded and the crossings marked, the energy above E at the first crossing, a cursor on
both following the crank's angle as the mechanism moves, the values at the cursor, the
book's table of the areas and the flywheel's answer.

The plots and the table are the energy page's own (:mod:`.energy`, its script
``energy.js`` following the frames of ``page.js``); every number is the cycle's solve
(:func:`~polygon_method.linkage.flywheel.turning_moment`, and
:func:`~polygon_method.linkage.flywheel.energy_curve` at the curve's phases and at each
frame's): the page computes nothing. A machine driven at a steady speed
(:mod:`~polygon_method.linkage.flywheel_machine`) in its own words: the torque its crank
needs over a turn from 0 deg, the motor's mean torque, the energy the flywheel gains (green
where the demand is under the motor's mean).

>>> import polygon_method as pm
>>> from polygon_method.page import frames
>>> part = engine_part(frames(pm.load_scene("worked_problems/engine_flywheel.toml"), 36))
>>> part.data["cycleDeg"], len(part.data["cursor"][0][1]), 'id="plot-cycle-torque"' in part.html
(720.0, 36, True)
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from html import escape

import numpy as np

from ..common.errors import PolygonMethodError
from ..common.tolerances import ROUNDING
from ..linkage.flywheel import energy_curve, engine_piston, turning_moment
from ..linkage.flywheel_machine import machine_asks
from ..text.energy import book_number as _g
from .energy import Plot, angle_ticks, book_table, energy_words, marker, plot_svg, shaded

__all__ = ["EnginePart", "engine_part", "CURVE_POINTS"]

#: the words of an engine's cycle and of a machine's turn, where they differ
_ENGINE = {
    "x": "crank angle from the inner dead centre{first}",
    "T": "turning moment T",
    "mean": "mean torque T_mean",
    "E": "energy above E at the first crossing",
    "title": "turning moment T and the mean torque",
    "over": "over the engine's cycle",
    "head": "The turning-moment diagram over the engine's cycle",
    "shade": "where the turning moment is above the mean line (the energy rising), red "
    "where it is below",
}
_MACHINE = {
    "x": "crank angle from 0 deg",
    "T": "torque T the crank needs",
    "mean": "the motor's mean torque T_mean",
    "E": "energy the flywheel gains from the first crossing",
    "title": "torque T needed and the motor's mean",
    "over": "over a turn of the machine",
    "head": "The crank's torque over a turn: the flywheel",
    "shade": "where the torque the crank needs is below the motor's mean (the flywheel "
    "gaining energy), red where it is above",
}

#: the turning-moment curve's points over the cycle (0.5 deg apart over a four-stroke's 720)
CURVE_POINTS = 1441


@dataclass(frozen=True)
class EnginePart:
    """The page's section (``html``) and the data its script reads (``data``: the cursor's
    places and the values at each frame, as ``energy.js`` takes them; the curve's phases
    and turning moments in full precision, for anyone who reads the page)."""

    html: str
    data: dict


def _wants_cycle(fr) -> bool:
    sc = fr.sol.scene
    if not fr.full_turn or not (sc.indicators or sc.flywheel is not None):
        return False
    if getattr(fr.sol, "forces_refused", None):
        return False
    try:
        return engine_piston(sc) is not None or machine_asks(sc)
    except PolygonMethodError:
        return False


def _phases(fr, tm) -> np.ndarray:
    """Each frame's phase (rad from the first cylinder's inner dead centre, in the sense of
    rotation, in [0, cycle)): the crank's angle of the frame, as the cycle counts it."""
    th = np.asarray(fr.res.theta, dtype=float)
    ph = np.mod(tm.sense * (th - math.radians(tm.theta_idc)), tm.cycle)
    return np.where(ph >= tm.cycle, 0.0, ph)


def _letters(n: int) -> list:
    return [chr(ord("a") + k) if k < 26 else f"x{k}" for k in range(n)]


def _table_rows(tm) -> list:
    """The book's table: from a crossing to the next, the area, the energy at the end
    (E at the first crossing is E; the running sum, rounding's last bits taken as nought)."""
    names = _letters(len(tm.crossings))
    big = max((abs(lb.energy) for lb in tm.lobes), default=0.0)
    rows, run = [], 0.0
    for k, lb in enumerate(tm.lobes):
        run += lb.energy
        run = 0.0 if abs(run) <= ROUNDING * big * len(tm.lobes) else run  # (rounding)
        end = names[(k + 1) % len(names)]
        rows.append(
            (
                f"{names[k]} ({lb.start:.4f}°)",
                f"{end} ({lb.end:.4f}°)",
                f"{lb.energy:+.6g}",
                energy_words(run),
            )
        )
    return rows


def _plots(tm, x, T, E, fx, fT, fE, first):
    """The two plots' SVG and the cursor's places (viewBox px) at the frames."""
    say = _MACHINE if tm.machine else _ENGINE
    cyc = math.degrees(tm.cycle)
    ticks = angle_ticks(cyc)
    mean = np.full_like(T, tm.mean)
    xtitle = say["x"].format(first=first) + " (deg)"
    p = Plot(0.0, cyc, np.concatenate([T, [tm.mean]]))
    cuts = [0.0, *tm.crossings, cyc]
    body = (
        p.frame(say["title"], "torque (N m)", xtitle, ticks)
        + shaded(p, x, T, mean, cuts, flip=tm.machine)
        + f'<path class="series" id="cycle-mean" d="{p.path([0, cyc], [tm.mean, tm.mean])}" '
        'stroke="#1565c0" stroke-dasharray="6 4"/>'
        + f'<path class="series" id="cycle-curve" d="{p.path(x, T)}" stroke="#111"/>'
    )
    names = _letters(len(tm.crossings))
    running = np.concatenate([[0.0], np.cumsum([lb.energy for lb in tm.lobes])])
    for k, c in enumerate(tm.crossings):
        tip = f"crossing {names[k]} at {c:.4g}°: {energy_words(running[k])} J"
        body += marker(p, c, tm.mean, tip)
    pe = Plot(0.0, cyc, E)
    ebody = pe.frame(say["E"], "energy (J)", xtitle, ticks)
    ebody += f'<path class="series" d="{pe.path(x, E)}" stroke="#111"/>'
    for k, c in enumerate(tm.crossings):
        ebody += marker(pe, c, running[k], f"crossing {names[k]}: {energy_words(running[k])} J")
    svgs = plot_svg("plot-cycle-torque", f"{say['T'][:-2]} {say['over']}", body)
    svgs += plot_svg("plot-cycle-energy", f"energy {say['over']}", ebody)
    cursor = [
        ["plot-cycle-torque", _r(p.px(fx)), _r(p.py(fT))],
        ["plot-cycle-energy", _r(pe.px(fx)), _r(pe.py(fE))],
    ]
    axes = {"x0": p.x0, "x1": p.x1, "y0": p.y0, "y1": p.y1}
    return svgs, cursor, axes


def _r(a) -> list:
    return [round(float(v), 2) for v in np.asarray(a, dtype=float)]


def engine_part(fr) -> EnginePart | None:
    """The engine's cycle on the page of the frames ``fr``, or None for a scene that is no
    engine asking for its cycle (or whose crank does not turn fully)."""
    if not _wants_cycle(fr):
        return None
    sc = fr.sol.scene
    try:
        tm = turning_moment(sc)
        x, T, E, parts = energy_curve(sc, tm, CURVE_POINTS)
        ph = _phases(fr, tm)
        fx, fT, fE, _ = energy_curve(sc, tm, phase=ph)
    except PolygonMethodError as exc:
        html = f"<h2>The turning-moment diagram</h2><p>not found: {escape(exc.message)}</p>"
        return EnginePart(html, {})
    first = f" of {parts[0][0]}" if len(parts) > 1 else ""
    say = _MACHINE if tm.machine else _ENGINE
    svgs, cursor, axes = _plots(tm, x, T, E, fx, fT, fE, first)
    rows = [
        [say["x"].format(first=first), [f"{v:.4g}°" for v in fx]],
        [say["T"], [f"{_g(v)} N m" for v in fT]],
        [say["mean"], [f"{_g(tm.mean)} N m"] * len(fx)],
        ["T − T_mean", [f"{_g(v)} N m" for v in fT - tm.mean]],
        [say["E"], [f"{_g(v)} J" for v in fE]],
    ]
    data = {
        "n": len(fx),
        "follow": True,
        "table": "cycle-values",
        "cursor": cursor,
        "rows": rows,
        "cycleDeg": math.degrees(tm.cycle),
        "idcDeg": tm.theta_idc,
        "sense": tm.sense,
        "mean": tm.mean,
        "axes": axes,
        "curve": {"phase": [float(v) for v in x], "T": [float(v) for v in T]},
    }
    lines = tm.lines(sc)
    answers = "".join(
        f"<li>{escape(w.strip())}</li>"
        for w in lines[1:]
        if "areas above" not in w and "flywheel gains (+)" not in w
    )
    html = f"""<h2>{say["head"]}</h2>
<p class="legend-line">{escape(lines[0])}. The cursor follows the crank's angle as the
mechanism moves. Shaded green {say["shade"]}; hover over (or tap) a crossing for its
energy.</p>
<div class="cycle-plots">
{svgs}
</div>
<div class="columns">
<div>
<h3>At the current angle</h3>
<div class="scroll"><table id="cycle-values"><tbody></tbody></table></div>
</div>
<div>
<h3>The answers</h3>
<ul id="cycle-answers">{answers}</ul>
</div>
</div>
<h3>The areas and the energies at the crossings</h3>
{book_table(_table_rows(tm), "cycle-book")}"""
    return EnginePart(html, data)
