"""The sheet of an engine's cycle (``draw --diagram cycle``, A4 portrait): above, the
turning moment against the crank angle from the (first cylinder's) inner dead centre with
the mean line, the areas between them shaded, each labelled with its energy, and the
crossings marked (of several cylinders on one crank the sum, each cylinder's own dashed
under it); below, the energy E above its value at the first crossing, its greatest and
least marked and dE_max between them. A machine driven at a steady speed
(:mod:`~polygon_method.linkage.flywheel_machine`) on the same sheet in its own words: the
torque its crank needs over a turn from the crank at 0 deg, the motor's mean torque, the
energy the flywheel gains (the motor's mean less the demand). The
numbers are the cycle's solve (:func:`~polygon_method.linkage.flywheel.turning_moment`);
the energy curve is its integral piece by piece, not a sum of samples. Byte for byte the
same run to run (:func:`~polygon_method.draw.sheet.figure_data`)."""

from __future__ import annotations

import math

import numpy as np

from ..linkage.flywheel import energy_curve, turning_moment
from ..text.energy import book_number as _g
from .paper import PAPERS
from .heading import flywheel_line, foot, heading
from .sheet import figure_data
from .style import PNG_DPI

__all__ = ["engine_cycle_sheet"]

_CM = 2.54
_GAIN, _GIVE = "#c8e6c9", "#ffcdd2"
#: an area narrower than this part of the cycle is not labelled (its words would not fit)
_NARROW = 0.04
_ENGINE = {
    "T": "turning moment T",
    "mean": "mean Tₘₑₐₙ",
    "x": "crank angle from the inner dead centre{first} (deg, with the rotation)",
    "y": "turning moment (N m)",
    "E": "energy E above E at the first crossing (J)",
    "words": "the turning-moment diagram",
}
_MACHINE = {
    "T": "torque T the crank needs",
    "mean": "the motor's mean Tₘₑₐₙ",
    "x": "crank angle from 0 deg (deg, with the rotation)",
    "y": "torque the crank needs (N m)",
    "E": "energy the flywheel gains from the first crossing (J)",
    "words": "the crank's torque over a turn",
}
_DASHED = ("#6a1b9a", "#ef6c00", "#00838f", "#ad1457", "#558b2f", "#4e342e")


def engine_cycle_sheet(scene, fmt: str, paper: str = "A4"):
    """(the sheet's file data: SVG text, PNG or PDF bytes; its words) for the engine's
    cycle of ``scene``, on ``paper`` (portrait)."""
    from matplotlib.figure import Figure

    tm = turning_moment(scene)
    x, T, E, parts = energy_curve(scene, tm)
    w, h = PAPERS[paper]
    fig = Figure(figsize=(w / _CM, h / _CM), dpi=100)
    top = fig.add_axes((0.12, 0.56, 0.80, 0.34))
    low = fig.add_axes((0.12, 0.10, 0.80, 0.34))
    heading(fig, scene.title or "Turning-moment diagram", (w, h), 11, top=0.90)
    many = len(parts) > 1
    say = _MACHINE if tm.machine else _ENGINE
    top.plot(x, T, color="black", lw=1.2, label=say["T"] + (" (the sum)" if many else ""))
    for k, (piston, t) in enumerate(parts if many else ()):
        top.plot(x, t, color=_DASHED[k % len(_DASHED)], lw=0.7, ls="--", label=f"cylinder {piston}")
    top.axhline(tm.mean, color="#1565c0", lw=1.0, label=f"{say['mean']} = {_g(tm.mean)} N m")
    gain = (T - tm.mean) * (-1.0 if tm.machine else 1.0)  # (a machine's: the motor's less T)
    for where, colour, said in (
        (gain >= 0, _GAIN, "gains (+ J)"),
        (gain <= 0, _GIVE, "gives (− J)"),
    ):
        top.fill_between(
            x, T, tm.mean, where=where, color=colour, interpolate=True, label=f"the flywheel {said}"
        )
    for c in tm.crossings:
        top.axvline(c, color="#757575", lw=0.6, ls="-.")
    _label_areas(top, tm, x, T)
    first = f" of {parts[0][0]}" if many else ""
    for ax in (top, low):
        ax.set_xlim(0.0, math.degrees(tm.cycle))
        ax.set_xlabel(say["x"].format(first=first))
        ax.grid(True, lw=0.3, color="#bbbbbb")
    top.set_ylabel(say["y"])
    top.legend(fontsize=8, loc="best")
    low.plot(x, E, color="black", lw=1.2)
    low.set_ylabel(say["E"])
    hi, lo = _at_crossing(tm, tm.at_max), _at_crossing(tm, tm.at_min)
    low.plot([tm.at_max], [hi], "o", color="#2e7d32")
    low.plot([tm.at_min], [lo], "o", color="#c62828")
    low.annotate(
        "",
        xy=(tm.at_max, hi),
        xytext=(tm.at_max, lo),
        arrowprops=dict(arrowstyle="<->", color="#455a64", lw=0.8),
    )
    low.text(tm.at_max, (hi + lo) / 2, f"  ΔEₘₐₓ = {_g(tm.dE_max)} J", fontsize=9, va="center")
    fly = tm.flywheel or (None,) * 4
    cs, om, inertia, mass = fly
    foot(fig, (w, h), paper, flywheel_line(tm.dE_max, inertia, cs, om, mass))
    words = f"{paper} portrait: {say['words']} and the energy curve"
    return figure_data(fig, fmt, **({"dpi": PNG_DPI} if fmt == "png" else {})), words


def _label_areas(ax, tm, x, T) -> None:
    """Each area between the curve and the mean labelled with its energy (J, + where the
    flywheel gains) halfway from the mean to the curve's farthest point in it; an area
    that wraps past the cycle's end at the middle of its wider piece; one narrower than
    :data:`_NARROW` of the cycle left to the table (``steps``)."""
    span = math.degrees(tm.cycle)
    for lb in tm.lobes:
        a, b = lb.start, lb.end
        pieces = [(a, b)] if b > a else [(a, span), (0.0, b)]
        a, b = max(pieces, key=lambda p: p[1] - p[0])
        if b - a < _NARROW * span:
            continue
        at, ha = (a + b) / 2, "center"
        if len(pieces) > 1:  # (at the cycle's edge, its words kept inside the plot)
            at, ha = (span - 0.01 * span, "right") if b == span else (0.01 * span, "left")
        inside = (x >= a) & (x <= b)
        d = T[inside] - tm.mean
        far = float(d[int(np.argmax(np.abs(d)))]) if d.size else 0.0
        ax.text(
            at,
            tm.mean + far / 2,
            f"{'+' if lb.energy >= 0 else '−'}{_g(abs(lb.energy))} J",
            fontsize=7,
            ha=ha,
            va="center",
            parse_math=False,
        )


def _at_crossing(tm, angle) -> float:
    """E at the crossing at ``angle`` (deg) above E at the first: the areas before it."""
    if angle not in tm.crossings:
        return 0.0
    return float(sum(lb.energy for lb in tm.lobes[: tm.crossings.index(angle)]))
