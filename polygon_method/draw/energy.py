"""The sheet of a turning-moment diagram stated on its own (A4, portrait): above, the
turning moment against the crank angle with the resisting (mean) line, the areas between
them shaded and the crossings lettered a, b, ...; below, the energy E against the crank
angle, its greatest and least marked and dE_max between them. A diagram given as areas has
no angles: its lobes are drawn one to a stretch of equal width (a sketch, so named), the
energy as its running sums. A press: the power the punching takes and the motor gives,
and the flywheel's energy over one cycle. Byte for byte the same run to run
(:func:`~polygon_method.draw.sheet.figure_data`)."""

from __future__ import annotations

import math

import numpy as np

from ..forces.flywheel_cycle import curves
from .paper import PAPERS
from ..text.energy import book_number as _g
from .heading import flywheel_line, foot, heading
from .sheet import figure_data
from .style import PNG_DPI

__all__ = ["cycle_sheet"]

_CM = 2.54
_ABOVE, _BELOW = "#c8e6c9", "#ffcdd2"


def cycle_sheet(scene, c, fmt: str, paper: str = "A4"):
    """The sheet's file data (SVG text, PNG or PDF bytes) for the solved cycle ``c``, on
    ``paper`` (portrait)."""
    from matplotlib.figure import Figure

    w, h = PAPERS[paper]
    fig = Figure(figsize=(w / _CM, h / _CM), dpi=100)
    top = fig.add_axes((0.12, 0.56, 0.80, 0.34))
    low = fig.add_axes((0.12, 0.10, 0.80, 0.34))
    heading(fig, scene.title or "Turning-moment diagram", (w, h), 13, top=0.90)
    if c.form == "press":
        _press(scene, c, top, low)
    elif c.form == "areas":
        _areas(c, top, low)
    else:
        _curve(scene, c, top, low)
    inertia = c.inertia
    foot(fig, (w, h), paper, flywheel_line(c.dE_max, inertia, c.Cs, c.speed, c.mass))
    for ax in (top, low):
        ax.grid(True, lw=0.3, color="#bbbbbb")
    return figure_data(fig, fmt, **({"dpi": PNG_DPI} if fmt == "png" else {}))


def _curve(scene, c, top, low):
    th, tq, rs, es = curves(scene, c)
    deg = np.degrees(th)
    top.plot(deg, tq, color="black", lw=1.2, label="turning moment T")
    top.plot(
        deg,
        rs,
        color="#1565c0",
        lw=1.0,
        ls="--",
        label="mean torque" if scene.diagram.resisting is None else "resisting torque",
    )
    top.fill_between(deg, tq, rs, where=tq >= rs, color=_ABOVE, interpolate=True, lw=0)
    top.fill_between(deg, tq, rs, where=tq < rs, color=_BELOW, interpolate=True, lw=0)
    span = float(np.max(tq) - np.min(np.minimum(tq, rs))) or 1.0
    for x in c.crossings[:-1]:
        y = float(np.interp(x.angle, th, rs))
        top.plot([math.degrees(x.angle)], [y], "o", color="black", ms=3)
        top.annotate(x.letter, (math.degrees(x.angle), y + 0.03 * span), ha="center")
    top.set_xlim(0, math.degrees(c.cycle))
    top.set_xlabel("crank angle (deg)")
    top.set_ylabel("torque (N m)")
    top.set_title(f"turning moment; Tₘₑₐₙ = {_g(c.T_mean)} N m", fontsize=10)
    top.legend(loc="upper right", fontsize=8)
    low.plot(deg, es, color="black", lw=1.2)
    low.set_xlim(0, math.degrees(c.cycle))
    _extremes(c, low, lambda x: math.degrees(x.angle))
    low.set_xlabel("crank angle (deg)")


def _extremes(c, ax, where):
    hi, lo = c.crossings[c.i_max], c.crossings[c.i_min]
    for x, col in ((hi, "#2e7d32"), (lo, "#c62828")):
        ax.plot([where(x)], [x.energy], "o", color=col, ms=5)
        ax.annotate(
            f"{x.letter}: E"
            + (f" {'+' if x.energy > 0 else '-'} {_g(abs(x.energy))} J" if x.energy else ""),
            (where(x), x.energy),
            textcoords="offset points",
            xytext=(6, 6),
            fontsize=8,
        )
    ax.axhline(hi.energy, color="#2e7d32", lw=0.6, ls=":")
    ax.axhline(lo.energy, color="#c62828", lw=0.6, ls=":")
    ax.set_ylabel("energy above E at a (J)")
    ax.set_title(f"energy; ΔEₘₐₓ = Eₘₐₓ − Eₘᵢₙ = {_g(c.dE_max)} J", fontsize=10)


def _areas(c, top, low):
    n = len(c.areas)
    for i, a in enumerate(c.areas):
        x = np.linspace(i, i + 1, 41)
        y = a * math.pi / 2 * np.sin(np.pi * (x - i))  # a half sine of the lobe's area
        top.fill_between(x, 0, y, color=_ABOVE if a > 0 else _BELOW, lw=0.8, edgecolor="black")
        top.annotate(f"{a:+.4g} J", (i + 0.5, y[20] / 2), ha="center", fontsize=8)
    top.axhline(0, color="#1565c0", lw=1.0, ls="--")
    for i, x in enumerate(c.crossings):
        top.annotate(x.letter, (i, 0), textcoords="offset points", xytext=(0, -12), ha="center")
    top.set_xlim(0, n)
    top.set_xticks([])
    top.set_yticks([])
    top.set_title(
        "the areas above and below the mean line (a sketch: widths not given)", fontsize=10
    )
    xs = list(range(n + 1))
    low.plot(xs, [x.energy for x in c.crossings], "-o", color="black", ms=3)
    low.set_xticks(xs, [x.letter for x in c.crossings])
    _extremes(c, low, lambda x: c.crossings.index(x))
    low.set_xlabel("crossing of the mean line")


def _press(scene, c, top, low):
    f = scene.press.fraction
    t = scene.press.period
    top.step(
        [0, f * t, t],
        [c.E_stroke / (f * t), 0, 0],
        where="post",
        color="black",
        label="power the punching takes",
    )
    top.axhline(c.power, color="#1565c0", ls="--", label=f"the motor's {_g(c.power)} W")
    top.set_xlim(0, t)
    top.set_xlabel("time in the cycle (s)")
    top.set_ylabel("power (W)")
    top.legend(loc="upper right", fontsize=8)
    top.set_title("a punching press over one cycle", fontsize=10)
    low.plot([0, f * t, t], [0, -c.dE_max, 0], color="black")
    low.set_xlim(0, t)
    low.set_xlabel("time in the cycle (s)")
    low.set_ylabel("flywheel's energy (J)")
    low.set_title(f"ΔEₘₐₓ = E (1 − {_g(f)}) = {_g(c.dE_max)} J", fontsize=10)
