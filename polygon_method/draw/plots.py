"""Plots of a sweep: velocities and accelerations of points, omega and alpha of links
against the crank angle, the scene's own instant marked (matplotlib, imported lazily)."""

from __future__ import annotations

import math
import textwrap

import numpy as np

from ..common.tolerances import DISTINCT, ON_PAPER, PLOTTED_ZERO
from ..common.errors import PolygonMethodError, SceneError
from ..motion.solution import solve
from ..motion.link_points import asked_pairs, pair_quantities
from ..motion.sweeps import SweepResult
from ..solver.tracking import degrees_fn

__all__ = ["plot_bytes", "plot_figure", "typeset", "SERIES_COLORS", "MARKS", "MARK_NAMES"]

#: the plots' curves, in turn (matplotlib's own cycle, so the page's plots and
#: ``sweep --plot`` colour a quantity alike), and the marks across them: the angle shown,
#: the scene's stated instant, the limit positions, the change points (colour, pt, dashes)
SERIES_COLORS = (
    "#1f77b4",
    "#ff7f0e",
    "#2ca02c",
    "#d62728",
    "#9467bd",
    "#8c564b",
    "#e377c2",
    "#7f7f7f",
    "#bcbd22",
    "#17becf",
)
MARKS = {
    "now": ("#cc0000", 1.2, None),
    "instant": ("#4d4d4d", 0.8, (4.0, 2.0)),
    "limit": ("#d62728", 0.8, (1.0, 2.0)),
    "change": ("#9467bd", 0.8, (4.0, 1.5, 1.0, 1.5)),
}
MARK_NAMES = {
    "now": "the angle shown",
    "instant": "the scene's stated instant",
    "limit": "a limit position",
    "change": "a change point",
}

_MATH_SPECIAL = {c: "\\" + c for c in "_$%#&{}"}
_MATH_SPECIAL.update({"-": r"\text{-}", "^": r"\^{}", "~": r"\~{}", "\\": r"\backslash{}"})


def typeset(symbol: str, name: str) -> str:
    r"""A quantity's name as mathtext, its symbol with the point or link below:
    ``typeset("omega", "BC")`` is ω with BC as a subscript.

    >>> typeset("omega", "BC"), typeset("v", "O4-P")
    ('$\\omega_{\\mathrm{BC}}$', '$v_{\\mathrm{O4\\text{-}P}}$')
    """
    safe = "".join(_MATH_SPECIAL.get(c, c) for c in name)
    sym = "\\" + symbol if symbol in ("omega", "alpha") else symbol
    return f"${sym}_{{\\mathrm{{{safe}}}}}$"


def _mark(ax, x, kind):
    color, lw, dashes = MARKS[kind]
    line = ax.axvline(x, color=color, lw=lw)
    if dashes:
        line.set_dashes(dashes)


def _plotted(res: SweepResult, points, links) -> tuple:
    """The points and the links' keys to plot: those asked (each once; an unknown name is an
    error), else every moving point and every link not joining two ground points."""
    sc = res.scene
    ground = set(sc.ground)
    pts = tuple(dict.fromkeys(points or (p for p in sc.point_names if p not in ground)))
    for p in pts:  # (each once: "C,C" is not two curves under one name)
        if p not in res.P:
            raise SceneError(f"--points: no point {p} in the scene", file=sc.file)
    keys = []
    for name in links or [lk.key for lk in sc.links if not (lk.p in ground and lk.q in ground)]:
        if not sc.has_link(name):
            raise SceneError(f"--links: no link {name} in [links]", file=sc.file)
        if sc.link(name).key not in keys:  # BC and CB are one link
            keys.append(sc.link(name).key)
    return pts, keys


def _axis(res: SweepResult) -> tuple:
    """The horizontal axis: the sorted abscissae ``x`` (a gap where angles are left out), the
    ``order`` and ``gaps`` that put any series on it, the scene's instant ``t0`` on it, and
    ``show``, an angle (rad) as its abscissa."""
    sc = res.scene
    dom = res.domain
    shift = 0.0
    if not dom.periodic:  # a driving block's places, in the scene's units
        deg = np.asarray(res.theta, dtype=float) / dom.unit
        t0 = sc.input.angle / dom.unit
    elif dom.full_turn:
        deg = res.degrees
        t0 = math.degrees(sc.input.angle)
    else:  # an axis continuous over the reachable range, starting in [-180, 180)
        shift = -360.0 * math.floor((math.degrees(dom.lo) + 180.0) / 360.0)
        deg = np.degrees(dom.map(res.theta)[0]) + shift
        t0 = math.degrees(float(dom.map(np.array([sc.input.angle]))[0][0])) + shift
    order = np.argsort(deg, kind="stable") if np.any(np.diff(deg) < 0) else slice(None)
    x = deg[order]
    if dom.full_turn and len(x):  # the scene's angle, shown in the plotted range: within
        # the motion's period where the range holds it (a four-stroke's 390 deg is not 30;
        # a planet back after several turns), else within a turn
        period = max(math.degrees(sc.cycle), 360.0 * dom.turns)
        for per in dict.fromkeys((period, 360.0)):
            k = math.floor((x.min() - t0) / per + 1.0)
            at = t0 + per * k if t0 + per * k <= x.max() + ON_PAPER else t0 + per * (k - 1)
            if x.min() - ON_PAPER <= at <= x.max() + ON_PAPER:
                break
        t0 = at
    gaps = np.nonzero(np.diff(x) > 1.5 * np.median(np.diff(x)))[0] + 1 if len(x) > 2 else []
    x = np.insert(x, gaps, np.nan)  # no line across angles left out
    show = (
        degrees_fn(dom)
        if dom.full_turn or not dom.periodic
        else (lambda t: math.degrees(float(dom.map(np.array([t]))[0][0])) + shift)
    )
    return x, order, gaps, t0, show


def _figure(sc, Figure) -> tuple:
    """The figure and its 2 x 2 panels; an engine's with its turning-moment diagram over the
    cycle below them, the width of both."""
    cycle = _engine_cycle(sc)
    if cycle is None:
        fig = Figure(figsize=(10, 7.5), layout="constrained")
        return fig, fig.subplots(2, 2, sharex=True)
    fig = Figure(figsize=(10, 10.5), layout="constrained")
    gs = fig.add_gridspec(3, 2, height_ratios=(1, 1, 1.1))
    first = fig.add_subplot(gs[0, 0])
    axes = [
        [first, fig.add_subplot(gs[0, 1], sharex=first)],
        [fig.add_subplot(gs[1, 0], sharex=first), fig.add_subplot(gs[1, 1], sharex=first)],
    ]
    for ax in axes[0]:
        ax.tick_params(labelbottom=False)
    _turning_moment_panel(fig.add_subplot(gs[2, :]), sc, *cycle)
    return fig, axes


def _panels(res: SweepResult, axes, pts, keys) -> list:
    """The four panels ``(axes, label, series)``: speeds (and sliding velocities),
    accelerations, omegas and alphas, each series ``(name, values, value at the instant)``."""
    sc = res.scene
    here = _scene_values(sc)
    asked = [  # vmin_BC, ar_CB, at_CB where the answers ask them: with the speeds, accelerations
        (_pair_name(key), unit, value, here.get(key))
        for key, unit, value, _ in pair_quantities(sc, res)
    ]
    return [
        (
            axes[0][0],
            "speed v (m/s)",
            [(typeset("v", p), res.speed(p), here.get(f"v_{p}")) for p in pts]
            + [
                (typeset("v", "s," + s.key), res.S[s.key][0], here.get(f"vs_{s.key}"))
                for s in sc.sliders
            ]
            + [(name, v, at) for name, unit, v, at in asked if unit == "m/s"],
        ),
        (
            axes[1][0],
            "acceleration a (m/s²)",
            [(typeset("a", p), res.acceleration_magnitude(p), here.get(f"a_{p}")) for p in pts]
            + [(name, v, at) for name, unit, v, at in asked if unit != "m/s"],
        ),
        (
            axes[0][1],
            "angular velocity ω (rad/s, ccw +)",
            [(typeset("omega", k), res.W[k], here.get(f"omega_{k}")) for k in keys],
        ),
        (
            axes[1][1],
            "angular acceleration α (rad/s², ccw +)",
            [(typeset("alpha", k), res.Al[k], here.get(f"alpha_{k}")) for k in keys],
        ),
    ]


def _pair_name(key: str) -> str:
    """An asked key of two points of a link as the books write it: v_min,AB; a^r_BA, a^t_BA."""
    kind, _, names = key.partition("_")
    if kind == "vmin":
        return typeset("v", "min," + names)
    return typeset("a", names).replace("$a_{", "$a^{" + kind[1] + "}_{", 1)


def _unit_scales(res: SweepResult) -> list:
    """The size of each panel's quantities the input sets (a speed, an acceleration, an omega,
    an alpha): below a tiny part of it a curve is a zero."""
    sc = res.scene
    if not res.domain.periodic:  # a driving block: the sizes its input sets
        return list(res.plan.steps[0].input_scales(sc))
    w, k = abs(sc.input.omega), sc.input.omega**2 + abs(sc.input.alpha)
    size = max([lk.length for lk in sc.links] + [1e-3])
    return [w * size, k * size, w, k]


def _draw_panel(res: SweepResult, ax, label, series, unit_scale, axis) -> bool:
    """One panel's curves, the instant's values marked, its vertical range (cut near a limit
    position, a constant drawn as one), the instant, limits and change points marked; True
    where the range was cut."""
    x, order, gaps, t0, show = axis
    clipped = False
    big = []
    for i, (name, y, y0) in enumerate(series):
        yy = np.insert(np.asarray(y, dtype=float)[order], gaps, np.nan)
        (line,) = ax.plot(x, yy, lw=1.2, label=name, color=SERIES_COLORS[i % len(SERIES_COLORS)])
        if y0 is not None:
            ax.plot([t0], [y0], "o", color=line.get_color(), ms=5)
        if len(y):
            big.append((np.nanpercentile(np.abs(yy), 90), np.nanmax(np.abs(yy))))
    ax.ticklabel_format(axis="y", useOffset=False)
    if big and res.limits:  # values grow without bound near a limit position
        typical, top = max(b[0] for b in big), max(b[1] for b in big)
        if typical > 0 and top > 8 * typical:
            lo = min(0.0, *(np.nanmin(np.asarray(y, dtype=float)) for _, y, _ in series))
            ax.set_ylim(max(lo, -3 * typical), 3 * typical)
            clipped = True
    elif big:  # a constant (up to rounding) is drawn as one, not as magnified noise
        ys = np.concatenate([np.asarray(y, dtype=float) for _, y, _ in series])
        lo, hi = float(np.nanmin(ys)), float(np.nanmax(ys))
        size = max(abs(lo), abs(hi))
        if hi - lo <= DISTINCT * size or size < PLOTTED_ZERO * unit_scale:
            pad = 0.1 * size if size >= PLOTTED_ZERO * unit_scale else 1.0
            ax.set_ylim(0.5 * (lo + hi) - pad, 0.5 * (lo + hi) + pad)
    _mark(ax, t0, "instant")
    for lp in res.limits:
        _mark(ax, show(lp.theta), "limit")
    for cp in res.change_points:
        _mark(ax, show(cp.theta), "change")
    ax.set_ylabel(label)
    ax.grid(True, lw=0.3)
    if series:
        ax.legend(fontsize=8, ncol=2)
    return clipped


def _titles(res: SweepResult, fig, axes, clipped: bool) -> None:
    """The lower panels' axis label (the crank angle, or a driving block's place) and the
    figure's title: the scene's, what the dashes mark, and whether a range was cut."""
    sc = res.scene
    driver = res.plan.steps[0]  # a block or collar driver: its place is the axis
    name, sym, _ = driver.parameter(sc)  # as the driver names it: "place of collar C on DC"
    for ax in axes[1]:
        ax.set_xlabel("crank angle θ (°)" if driver.periodic else f"{name}, {sym} ({sc.units})")
    title = sc.title or sc.file or "mechanism"
    key = (
        f"crank {sc.input.crank}; dashed: the scene's instant "
        f"({math.degrees(sc.input.angle):g} deg)"
        if driver.periodic
        else f"input: the {name}; dashed: the scene's instant ({sym} = "
        f"{sc.input.angle / sc.length_unit:g} {sc.units})"
        + ("; dotted red: limit positions" if res.limits else "")
        + ("; dash-dot: change points" if res.change_points else "")
    )
    lines = textwrap.wrap(title, 90) + textwrap.wrap(key, 110)  # within the figure's width
    if clipped:
        lines.append(
            "(the vertical scale is cut: values grow without bound near the limit positions)"
        )
    fig.suptitle("\n".join(lines), fontsize=10)


def plot_figure(res: SweepResult, *, points=None, links=None):
    """Velocities and accelerations of ``points`` and omega, alpha of ``links`` against the
    crank angle, with the scene's own instant marked (matplotlib, imported here only)."""
    import matplotlib

    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    pts, keys = _plotted(res, points, links)
    axis = _axis(res)
    fig, axes = _figure(res.scene, Figure)
    clipped = False
    for (ax, label, series), unit_scale in zip(_panels(res, axes, pts, keys), _unit_scales(res)):
        clipped = _draw_panel(res, ax, label, series, unit_scale, axis) or clipped
    _titles(res, fig, axes, clipped)
    return fig


def _engine_cycle(scene):
    """(the :class:`~polygon_method.linkage.TurningMoment`, phases in deg, the turning
    moment at each) of an engine, or None for another mechanism (or one whose cycle cannot
    be taken)."""
    from ..linkage.flywheel import _geometry, cylinder_moments_at, engine_piston, turning_moment

    try:
        if engine_piston(scene) is None:
            return None
        tm = turning_moment(scene)
        g = _geometry(scene)
    except PolygonMethodError:
        return None
    phase = np.linspace(0.0, tm.cycle, int(round(math.degrees(tm.cycle) * 2)) + 1)
    parts = [(p, np.asarray(T, dtype=float)) for p, T in cylinder_moments_at(scene, g, phase)]
    T = parts[0][1] if len(parts) == 1 else sum(t for _, t in parts)
    return tm, np.degrees(phase), T, tuple(parts) if g.many else (), g.parts[0][1].piston


def _turning_moment_panel(ax, scene, tm, x, T, parts=(), first=""):
    """The turning-moment diagram: T against the crank angle from the inner dead centre,
    the mean line, the areas above it and below it shaded, the crossings marked; of several
    cylinders on one crank (``parts``: each one's turning moment), each thin and dashed,
    T their sum, the angle from the first cylinder's inner dead centre."""
    from matplotlib.ticker import MultipleLocator

    total = "turning moment T (the sum)" if parts else "turning moment T"
    ax.plot(x, T, lw=1.3, color=SERIES_COLORS[0], label=total)
    for k, (piston, t) in enumerate(parts):
        color = SERIES_COLORS[(4 + k) % len(SERIES_COLORS)]
        ax.plot(x, t, lw=0.7, ls="--", color=color, label=f"cylinder {piston}")
    ax.axhline(tm.mean, color=SERIES_COLORS[3], lw=1.0, label=f"mean T_mean = {tm.mean:.4g} N m")
    ax.fill_between(
        x,
        T,
        tm.mean,
        where=T >= tm.mean,
        color=SERIES_COLORS[2],
        alpha=0.25,
        interpolate=True,
        label="above the mean (+)",
    )
    ax.fill_between(
        x,
        T,
        tm.mean,
        where=T <= tm.mean,
        color=SERIES_COLORS[1],
        alpha=0.25,
        interpolate=True,
        label="below the mean (-)",
    )
    ax.axhline(0.0, color="#4d4d4d", lw=0.6)
    for c in tm.crossings:
        _mark(ax, c, "change")
    ax.set_xlim(0.0, math.degrees(tm.cycle))
    ax.xaxis.set_major_locator(MultipleLocator(90.0 if tm.cycle > 2 * math.pi + 1 else 30.0))
    ax.set_xlabel(
        "crank angle from the inner dead centre"
        + (f" of {first}" if parts else "")
        + ", in the sense of rotation (°)"
    )
    ax.set_ylabel("turning moment T (N m, + driving)")
    words = f"dE_max = {tm.dE_max:.4g} J"
    if tm.flywheel is not None:
        words += f"; flywheel I = {tm.flywheel[2]:.4g} kg m²"
        if tm.flywheel[3] is not None:
            words += f", rim mass {tm.flywheel[3]:.4g} kg"
    ax.set_title(
        f"turning-moment diagram over the cycle ({words}); dash-dot: the crossings of the mean",
        fontsize=9,
    )
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8, ncol=4, loc="best", framealpha=0.85)


def plot_bytes(res: SweepResult, path: str, *, points=None, links=None) -> bytes:
    """:func:`plot_figure` as the bytes of the file ``path`` names (SVG, PNG or PDF)."""
    from .sheet import figure_data

    fig = plot_figure(res, points=points, links=links)
    data = figure_data(fig, path.rsplit(".", 1)[-1].lower())
    return data.encode() if isinstance(data, str) else data


def _scene_values(scene) -> dict:
    """The scene's own instant (the marked points), or nothing where it is singular."""
    try:
        sol = solve(scene)
    except PolygonMethodError:
        return {}
    out = {}
    for p in scene.point_names:
        out[f"v_{p}"] = sol.speed(p)
        out[f"a_{p}"] = sol.acceleration_magnitude(p)
    for lk in scene.links:
        out[f"omega_{lk.key}"] = sol.W[lk.key]
        out[f"alpha_{lk.key}"] = sol.Al[lk.key]
    for s in scene.sliders:
        out[f"vs_{s.key}"] = sol.S[s.key][0]
    for key, kind, names in asked_pairs(scene):
        out[key] = sol.value(kind, names)
    return out
