"""The engine's turning-moment diagram over a cycle, the fluctuation of energy and the
flywheel (the engine chapter's last exercise).

The turning moment ``T`` is the torque the gas force and the inertia of the parts put on the
crank (the driver's torque with inertia, reversed), taken in the crank's sense of rotation:
positive where the engine drives. Over a cycle of ``Theta`` rad of the crank (one turn; two
for a four-stroke indicator diagram), from the inner dead centre:

- the mean torque ``T_mean = (1 / Theta) int T dphi`` (the work per cycle over Theta);
- the energy ``E(phi) = int_0^phi (T - T_mean) dphi``: the areas above and below the mean
  line, taken in order between its crossings; the speed is greatest where E is, least where
  E is least, and the maximum fluctuation of energy is ``dE_max = E_max - E_min``;
- the flywheel that keeps the speed within the coefficient of fluctuation
  ``Cs = (w_max - w_min) / w_mean``: ``I = dE_max / (w_mean^2 Cs)`` (from
  ``dE = I w_mean (w_max - w_min)``), and a rim's mass ``I / R^2`` (or ``I / k^2``).

Found exactly, not by counting samples: the crossings of the mean line are bracketed on a
fine grid and refined by bisection on the solved turning moment to the last bit of the
angle; every integral is a Gauss-Legendre rule on pieces no longer than 5 deg between the
places where T has a corner or a jump (the dead centres, the indicator table's angles and
the stroke places it gives) and the crossings, exact to rounding for T smooth on each piece.
Two crossings closer together than the grid (a quarter of a degree) are missed: a lobe that
thin holds no energy to speak of.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..common.tolerances import MEAN_NOUGHT, ROUNDING
from ..common.errors import PolygonMethodError
from ..forces import analyse
from ..forces.engine import (
    cylinder_efforts,
    cylinders,
    efforts,
    engine_piston as _piston,
    engine_pistons,
    geometry,
    piston_side,
)
from ..scene import Scene
from .flywheel_machine import machine_asks, machine_cycle, machine_lines, machine_moments_at
from ..motion.sweeps import sweep
from ..solver.compiler import compile_plan
from ..motion.solution import solve

__all__ = [
    "TurningMoment",
    "Lobe",
    "EngineCycle",
    "turning_moment",
    "engine_piston",
    "turning_moment_at",
    "cylinder_moments_at",
    "cycle_blocks",
]

_PIECE = math.radians(5.0)
_NODES, _WEIGHTS = np.polynomial.legendre.leggauss(20)
_GRID = math.radians(0.25)


@dataclass(frozen=True)
class Lobe:
    """One area between the turning moment and its mean, from one crossing to the next
    (phases in deg from the inner dead centre): ``energy`` (J) positive above the mean."""

    start: float
    end: float
    energy: float


@dataclass(frozen=True)
class TurningMoment:
    """The turning-moment diagram's numbers over one cycle (see the module's words).

    Phases are crank angles in deg from the inner dead centre (``theta_idc``, deg from +x)
    in the crank's sense of rotation; ``lobes`` in order from the first crossing;
    ``E_max``/``E_min`` the energy's extremes (J, from its value at the inner dead centre)
    at ``at_max``/``at_min``; ``flywheel``: (Cs, w_mean rad/s, I kg m^2, mass kg or None)
    when the scene asks for one."""

    cycle: float
    theta_idc: float
    sense: float
    mean: float
    work: float
    T_max: float
    at_T_max: float
    T_min: float
    at_T_min: float
    crossings: tuple
    lobes: tuple
    E_max: float
    at_max: float
    E_min: float
    at_min: float
    flywheel: tuple | None
    inertia_included: bool
    words: str = ""
    machine: bool = False  # a machine's turn at a steady speed (:mod:`.flywheel_machine`)

    @property
    def dE_max(self) -> float:
        """The maximum fluctuation of energy, E_max - E_min over the cycle (J)."""
        return self.E_max - self.E_min

    def lines(self, scene) -> list:
        """The summary's lines, in the book's words."""
        deg = math.degrees(self.cycle)
        said = machine_lines(self, scene) if self.machine else None
        out = [
            f"turning moment over the cycle ({deg:g} deg of the crank from the inner dead "
            f"centre at {self.theta_idc:.4f} deg, in the crank's sense of rotation; "
            + _basis(scene, self.inertia_included)
            + "; "
            + self.words
            + ")",
            f"  mean torque T_mean = {self.mean:.6g} N m (work per cycle {self.work:.6g} J; "
            + (
                "at rest: no power)"
                if scene.at_rest
                else f"at {abs(scene.input.omega) * 30 / math.pi:.6g} rpm, power "
                f"{self.mean * abs(scene.input.omega) / 1000:.6g} kW)"
            ),
            f"  greatest {'torque needed' if said else 'turning moment'} (on a 0.25 deg grid) {self.T_max:.6g} N m at "
            f"{self.at_T_max:.4f} deg, "
            f"least {self.T_min:.6g} N m at {self.at_T_min:.4f} deg",
        ]
        if said:
            out[0] = said[0]
        if self.lobes:
            out.append(
                (
                    said[1]
                    if said
                    else "  areas above (+) and below (-) the mean line, in order (J): "
                )
                + ", ".join(
                    f"{lb.energy:+.6g} ({lb.start:.3f} to {lb.end:.3f} deg)" for lb in self.lobes
                )
            )
        out.append(
            f"  maximum fluctuation of energy dE_max = E_max - E_min = {self.E_max:.6g}"
            f" - ({self.E_min:.6g}) = {self.dE_max:.6g} J ("
            + (
                "starting from rest: no speed yet to be greatest or least)"
                if scene.at_rest and scene.start_alpha
                else ("turning slowly, its inertia nought, " if scene.at_rest else "")
                + f"the speed {'would be ' if scene.at_rest else ''}greatest at "
                f"{self.at_max:.4f} deg, least at {self.at_min:.4f} deg)"
            )
        )
        if self.flywheel is not None:
            cs, w, inertia, mass = self.flywheel
            fw = scene.flywheel
            out.append(
                f"  flywheel: {fw.words}, mean speed {w:.6g} rad/s ({w * 30 / math.pi:.6g}"
                f" rpm): I = dE_max / (w^2 Cs) = {inertia:.6g} kg m^2"
            )
            if mass is not None:
                k = fw.radius if fw.radius is not None else fw.gyration
                what = "a rim of mean radius" if fw.radius is not None else "radius of gyration"
                out.append(
                    f"  {what} {k:.6g} m: mass m = I / {'R' if fw.radius else 'k'}^2 "
                    f"= {mass:.6g} kg"
                )
        return out

    def as_dict(self) -> dict:
        """The JSON's ``turning_moment`` entry (SI; phases in deg)."""
        out = {
            "cycle_deg": math.degrees(self.cycle),
            "inner_dead_centre_deg": self.theta_idc,
            "T_mean": self.mean,
            "work_per_cycle": self.work,
            "T_max": self.T_max,
            "at_T_max_deg": self.at_T_max,
            "T_min": self.T_min,
            "at_T_min_deg": self.at_T_min,
            "crossings_deg": list(self.crossings),
            "lobes": [
                {"from_deg": lb.start, "to_deg": lb.end, "energy": lb.energy} for lb in self.lobes
            ],
            "E_max": self.E_max,
            "at_E_max_deg": self.at_max,
            "E_min": self.E_min,
            "at_E_min_deg": self.at_min,
            "dE_max": self.dE_max,
            "inertia_included": self.inertia_included,
        }
        if self.machine:  # (the phases from the crank at 0 deg; E the motor's mean less T)
            out["machine"] = True
            del out["inner_dead_centre_deg"]
        if self.flywheel is not None:
            cs, w, inertia, mass = self.flywheel
            out["flywheel"] = {"Cs": cs, "omega_mean": w, "I": inertia, "mass": mass}
        return out


def _basis(scene, inertia) -> str:
    """What the turning moment over the cycle counts, in words: the inertia of the moving
    parts, or at rest none (nothing moves: the gas force and the weights), or starting from
    rest the start's alone (its alpha at every angle, no velocity: not a running cycle)."""
    rest, start = scene.at_rest, scene.start_alpha
    if rest and start and inertia:
        return (
            f"starting from rest at every angle, alpha_{scene.input.crank} = "
            f"{abs(start):.6g} rad/s^2 {'ccw' if start > 0 else 'cw'}: the gas force and the "
            "start's inertia alone (no velocity), not a running engine's cycle"
        )
    if inertia:
        return "with the inertia of the moving parts"
    if rest:
        weights = " and the weights" if scene.gravity is not None else " alone"
        return f"at rest: the gas force{weights}, no inertia (nothing moves)"
    return "no masses given: the gas force alone"


def engine_piston(scene: Scene):
    """The piston of an engine (see :func:`polygon_method.forces.engine.engine_piston`; of
    several cylinders on one crank, the first's), or None for a scene that is no engine."""
    if not scene.has_forces and not any(ld.gas for ld in scene.loads):
        return None
    plan = compile_plan(scene)
    one = _piston(scene, plan)
    if one is not None:
        return one
    many = engine_pistons(scene, plan)
    return many[0] if many else None


@dataclass(frozen=True)
class EngineCycle:
    """The slider cranks whose turning moments make the diagram: ``parts``, each (its
    indicator or None, its :class:`~polygon_method.forces.engine.SliderCrankGeometry`, its
    lag: rad after the first's inner dead centre); ``many`` for several cylinders on one
    crank (their turning moments summed); the phase counts from the first's inner dead
    centre ``theta_i`` in the sense ``sg``."""

    parts: tuple
    many: bool
    words: str = ""

    @property
    def theta_i(self) -> float:
        """The first cylinder's inner dead centre (rad from +x): the diagram's start."""
        return self.parts[0][1].theta_i

    @property
    def sg(self) -> float:
        """The crank's sense of rotation (+1 ccw, -1 cw)."""
        return self.parts[0][1].sg


def _geometry(scene) -> EngineCycle:
    piston = engine_piston(scene)
    if piston is None and machine_asks(scene):
        return machine_cycle(scene)
    if piston is None:
        raise PolygonMethodError(
            "the turning moment over a cycle is an engine's: a slider "
            "crank with a gas force on its piston ([loads] pressure, or "
            "[indicator])",
            file=scene.file,
        )
    plan = compile_plan(scene)
    sol = solve(scene)
    many = engine_pistons(scene, plan)
    if not many:
        g = geometry(scene, plan, piston, piston_side(scene, plan, sol.P, piston))
        return EngineCycle(((scene.indicator, g, 0.0),), False)
    cyl = {c.ind.piston: c for c in cylinders(scene, plan, sol.P)}
    parts, words = [], []
    for p in many:
        if p in cyl:
            c = cyl[p]
            parts.append((c.ind, c.g, c.lag))
            if len(parts) > 1:
                how = "given" if c.lag_given else "the least: its first inner dead centre"
                words.append(f"{p}'s cycle {math.degrees(c.lag):.6g} deg after {many[0]}'s ({how})")
            continue
        g = geometry(scene, plan, p, piston_side(scene, plan, sol.P, p))
        g0 = parts[0][1] if parts else g
        parts.append((None, g, (g0.sg * (g.theta_i - g0.theta_i)) % (2 * math.pi)))
    head = f"the cylinders {', '.join(many)} on one crank, their turning moments summed"
    return EngineCycle(tuple(parts), True, "; ".join([head] + words))


def turning_moment_at(scene: Scene, g, phase):
    """The turning moment (N m, in the sense of rotation) at the phases ``phase`` (rad from
    the inner dead centre, an array), solved with the forces at each (``g``: the
    :class:`EngineCycle`; of several cylinders, the sum of their turning moments)."""
    parts = cylinder_moments_at(scene, g, phase)
    return parts[0][1] if len(parts) == 1 else sum(T for _, T in parts)


def cylinder_moments_at(scene: Scene, g, phase) -> tuple:
    """((piston, its turning moment at each phase, N m), ...): each cylinder's part of the
    turning moment (one for a single cylinder), at the phases ``phase`` (rad)."""
    if getattr(g, "machine", False):
        return machine_moments_at(scene, g, phase)
    phase = np.asarray(phase, dtype=float)
    theta = g.theta_i + g.sg * phase
    res = sweep(scene, theta)
    if len(res.theta) != len(theta):
        raise PolygonMethodError(
            "the engine's cycle passes a position where it cannot be "
            "solved: no turning moment over the cycle",
            file=scene.file,
        )
    f = analyse(res)
    es = cylinder_efforts(scene, res.plan, res.P, f) if g.many else ()
    es = es or (efforts(scene, res.plan, res.P, f),)
    return tuple((e.piston, np.broadcast_to(e.T, theta.shape)) for e in es)


def _breaks(scene, eng, cycle) -> list:
    """The phases (rad) where the turning moment may have a corner or a jump: each
    cylinder's dead centres, its indicator's readings (or the stroke's places), in its own
    phase shifted by its lag."""
    out = {0.0, cycle}
    for ind, g, lag in eng.parts:
        own = set()
        k = 0.0
        while k < cycle:
            own |= {k, k + g.phase_o}
            k += 2 * math.pi
        if ind is not None and ind.against == "angle":
            own |= {x % cycle for x in ind.x}
        elif ind is not None:  # the stroke's places, on each stroke
            starts = sorted(p for p in own if p < cycle)
            for a, b in zip(starts, starts[1:] + [cycle]):
                for x in ind.x:
                    own.add(_phase_at_fraction(g, a, b, x))
        out |= {(p + lag) % cycle for p in own}
    return sorted(p for p in out if 0.0 <= p <= cycle)


def _fraction(g, phase):
    """The piston's place as a fraction of the stroke at ``phase`` (closed form)."""
    th = g.theta_i + g.sg * phase
    (ox, oy), (fx, fy), (ux, uy) = g.O, g.F, g.u
    ax, ay = ox + g.r * math.cos(th) - fx, oy + g.r * math.sin(th) - fy
    au, an = ax * ux + ay * uy, -ax * uy + ay * ux
    d = g.s * au + math.sqrt(g.l * g.l - an * an)  # the piston's distance from F
    return (math.sqrt((g.l + g.r) ** 2 - g.e**2) - d) / g.stroke


def _phase_at_fraction(g, a, b, x):
    """The phase in [a, b] (one stroke) where the piston is at the fraction ``x``."""
    fa = _fraction(g, a) - x
    if fa == 0:
        return a
    for _ in range(200):
        m = 0.5 * (a + b)
        if m in (a, b):
            break
        fm = _fraction(g, m) - x
        if (fm > 0) == (fa > 0):
            a, fa = m, fm
        else:
            b = m
    return 0.5 * (a + b)


def _integrals(scene, g, edges):
    """The integral of the turning moment over each piece between ``edges`` (rad)."""
    xs, ws, owner = [], [], []
    for i, (a, b) in enumerate(zip(edges, edges[1:])):
        n = max(1, math.ceil((b - a) / _PIECE))
        for j in range(n):
            lo, hi = a + (b - a) * j / n, a + (b - a) * (j + 1) / n
            half = 0.5 * (hi - lo)
            xs.append(lo + half * (1.0 + _NODES))
            ws.append(half * _WEIGHTS)
            owner.append(np.full(len(_NODES), i))
    T = turning_moment_at(scene, g, np.concatenate(xs))
    return np.bincount(np.concatenate(owner), np.concatenate(ws) * T, len(edges) - 1)


def _bisect(scene, g, lo, hi, mean):
    """The crossings of the mean in each bracket [lo, hi] (arrays), to the last bit."""
    flo = turning_moment_at(scene, g, lo) - mean
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        if np.all((mid == lo) | (mid == hi)):
            break
        fm = turning_moment_at(scene, g, mid) - mean
        same = (fm > 0) == (flo > 0)
        lo, flo = np.where(same, mid, lo), np.where(same, fm, flo)
        hi = np.where(same, hi, mid)
    return 0.5 * (lo + hi)


def _mean(scene, g, breaks, cycle) -> tuple:
    """(the work per cycle, the mean torque, the grid, the turning moment on it): a mean at
    most :data:`MEAN_NOUGHT` of the largest turning moment is rounding about a true nought
    (a steady pressure does no net work over a turn): written 0."""
    work = float(_integrals(scene, g, breaks).sum())
    mean = work / cycle
    grid = np.unique(
        np.concatenate([np.linspace(0.0, cycle, int(round(cycle / _GRID)) + 1), breaks])
    )
    T = turning_moment_at(scene, g, grid)
    if abs(mean) <= MEAN_NOUGHT * float(np.abs(T).max()):
        mean = work = 0.0
    return work, mean, grid, T


def turning_moment(scene: Scene) -> TurningMoment:
    """The turning-moment diagram's numbers over the engine's cycle (see the module)."""
    g = _geometry(scene)
    ind = scene.indicator
    cycle = scene.cycle
    breaks = _breaks(scene, g, cycle)
    work, mean, grid, T = _mean(scene, g, breaks, cycle)
    d = T - mean
    size = max(float(np.abs(T).max()), abs(mean), 1e-300)
    exact = np.nonzero(d[:-1] == 0.0)[0]
    flip = np.nonzero((d[:-1] != 0.0) & (d[1:] != 0.0) & ((d[:-1] > 0) != (d[1:] > 0)))[0]
    cross = list(grid[exact])
    if len(flip):
        cross += list(_bisect(scene, g, grid[flip], grid[flip + 1], mean))
    cross = sorted(c for c in cross if 0.0 <= c < cycle)
    rd = math.degrees
    i_max, i_min = int(np.argmax(T)), int(np.argmin(T))
    if not cross or float(np.abs(d).max()) <= ROUNDING * size:  # a steady turning moment
        lobes, E_max, at_max, E_min, at_min = (), 0.0, 0.0, 0.0, 0.0
        cross = []
    else:
        edges = sorted(set(breaks) | set(cross))
        parts = (_integrals(scene, g, edges) - mean * np.diff(edges)) * getattr(g, "esign", 1.0)
        E = np.concatenate([[0.0], np.cumsum(parts)])  # E at each edge, from the i.d.c.
        at = {e: E[k] for k, e in enumerate(edges)}
        Ec = [at[c] for c in cross]
        k_max, k_min = int(np.argmax(Ec)), int(np.argmin(Ec))
        E_max, at_max, E_min, at_min = Ec[k_max], rd(cross[k_max]), Ec[k_min], rd(cross[k_min])
        lobes = []
        for k, c in enumerate(cross):
            nxt = cross[k + 1] if k + 1 < len(cross) else cross[0] + cycle
            e_next = Ec[k + 1] if k + 1 < len(cross) else Ec[0]  # the cycle closes on itself
            lobes.append(
                Lobe(
                    rd(c),
                    rd(nxt) % math.degrees(cycle) if nxt >= cycle else rd(nxt),
                    e_next - Ec[k],
                )
            )
        lobes = tuple(lobes)
    fly = None
    if scene.flywheel is not None:
        fw = scene.flywheel
        w = fw.speed if fw.speed is not None else abs(scene.input.omega)
        inertia = float(E_max - E_min) / (w * w * fw.coefficient)
        k = fw.radius if fw.radius is not None else fw.gyration
        fly = (fw.coefficient, w, inertia, inertia / (k * k) if k is not None else None)
    words = (
        g.words
        if getattr(g, "machine", False)
        else ind.words
        if ind is not None
        else "; ".join(ld.gas[2] for ld in scene.loads if ld.gas is not None)
    )
    if g.many:
        each = [f"{i.piston}: {i.words}" for i in scene.indicators]
        gas = [f"{ld.target}: {ld.gas[2]}" for ld in scene.loads if ld.gas is not None]
        words = "; ".join([g.words] + each + gas)
    return TurningMoment(
        cycle,
        math.degrees(g.theta_i),
        g.sg,
        mean,
        work,
        float(T[i_max]),
        rd(grid[i_max]),
        float(T[i_min]),
        rd(grid[i_min]),
        tuple(rd(c) for c in cross),
        lobes,
        float(E_max),
        at_max,
        float(E_min),
        at_min,
        fly,
        bool(scene.masses) and not (scene.at_rest and not scene.start_alpha),  # (at rest
        # nothing moves: no inertia; starting from rest, the start's)
        words,
        getattr(g, "machine", False),
    )


def engine_cycle_lines(scene: Scene) -> list:
    """The turning-moment diagram's lines for ``sweep --summary`` (an engine's; nothing for
    another mechanism, or one line saying why an engine's cycle cannot be taken)."""
    try:
        if engine_piston(scene) is None and not machine_asks(scene):
            return []
    except PolygonMethodError:
        return []
    try:
        return turning_moment(scene).lines(scene)
    except PolygonMethodError as exc:
        return [f"turning moment over the cycle: not found ({exc.message})"]


def cycle_blocks(sol) -> list:
    """The ``steps`` document's blocks for an engine that asks for its cycle (``[indicator]``
    or ``[flywheel]``): the turning moment over the cycle, the book's table of the areas
    between it and the mean line with their running sums, the fluctuation of energy and the
    flywheel; none for another scene."""
    sc = sol.scene
    if not sc.indicators and sc.flywheel is None:
        return []
    try:
        if sol.forces_refused or (engine_piston(sc) is None and not machine_asks(sc)):
            return []
        tm = turning_moment(sc)
    except PolygonMethodError as exc:
        return [("h", "The turning-moment diagram"), ("p", f"not found: {exc.message}")]
    lines = tm.lines(sc)
    head = "The crank's torque over a turn: the flywheel" if tm.machine else None
    out = [("h", head or "The turning-moment diagram"), ("p", lines[0])]
    rows, run = [], 0.0
    big = max((abs(lb.energy) for lb in tm.lobes), default=0.0)
    for k, lb in enumerate(tm.lobes):
        run += lb.energy
        run = 0.0 if abs(run) <= ROUNDING * big * len(tm.lobes) else run  # (rounding)
        rows.append(
            (
                str(k + 1),
                f"{lb.start:.3f}",
                f"{lb.end:.3f}",
                f"{lb.energy:+.6g}",
                f"{run:+.6g}",
            )
        )
    if rows:
        out.append(
            (
                "table",
                ("area", "from (deg)", "to (deg)", "energy (J)", "running sum (J)"),
                rows,
            )
        )
    areas = ("areas above", "energy the flywheel gains")  # (the table has them)
    rest = [ln.strip() for ln in lines[1:] if not ln.strip().startswith(areas)]
    out.append(("list", rest))
    return out


def energy_curve(scene: Scene, tm: TurningMoment, n: int = 1441, phase=None) -> tuple:
    """``(phase deg, T, E, parts)`` over the cycle at ``n`` evenly spaced phases from the
    first cylinder's inner dead centre (or at the phases ``phase``, rad in [0, cycle), in any
    order: a page's frames): the turning moment (N m; of several cylinders the
    sum, ``parts`` each one's as (piston, T)) and the energy ``E = int (T - T_mean) dphi``
    above its value at the first crossing of the mean (J), each piece between neighbouring
    phases (and the corners and crossings) integrated by the Gauss-Legendre rule of the
    cycle's solve: exact to rounding, not a sum of samples."""
    g = _geometry(scene)
    phase = np.linspace(0.0, tm.cycle, n) if phase is None else np.asarray(phase, dtype=float)
    parts = [(p, np.asarray(T, dtype=float)) for p, T in cylinder_moments_at(scene, g, phase)]
    T = parts[0][1] if len(parts) == 1 else sum(t for _, t in parts)
    cross = [math.radians(c) for c in tm.crossings]
    edges = sorted(set(phase.tolist()) | set(_breaks(scene, g, tm.cycle)) | set(cross))
    sE = getattr(g, "esign", 1.0)  # (a machine's: the motor's mean less the torque it needs)
    E = np.concatenate(
        [[0.0], np.cumsum((_integrals(scene, g, edges) - tm.mean * np.diff(edges)) * sE)]
    )
    at = dict(zip(edges, E))
    base = at[cross[0]] if cross else 0.0
    return np.degrees(phase), T, np.array([at[p] for p in phase.tolist()]) - base, tuple(parts)
