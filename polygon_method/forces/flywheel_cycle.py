"""A turning-moment diagram stated on its own (areas, a law, straight segments) or a punching
press: the energies at the crossings of the mean line, the maximum fluctuation of energy,
the flywheel and its rim, the speeds (the flywheel chapter of the books).

Over a cycle of ``Theta`` rad of the crank, with the driving torque ``T`` and the resisting
torque ``R`` (constant at the mean where the scene gives none):

- ``T_mean = (1 / Theta) int T dtheta``; the power ``T_mean w``;
- ``E(theta) = int_0^theta (T - R) dtheta``, the energy above its value at 0; its extremes
  are at the crossings (``T = R``), and ``dE_max = E_max - E_min``: the book's table of
  the areas between the crossings and their running sums. Given as areas, the running sums
  of the areas are the energies at the crossings (from the first);
- the flywheel: ``dE_max = I w^2 Cs`` (``Cs = (w_max - w_min) / w_mean``, the whole
  range; ``w_max, w_min = w (1 +- Cs / 2)``): ``I`` from Cs, or Cs from a given I; the
  angular acceleration ``(T - R) / I`` at a crank angle;
- the rim: its mass ``m = share I / R^2`` (the mass at its mean radius; ``I / k^2`` with
  a radius of gyration), its radius from a rim speed (``R = v / w``) or a hoop stress
  (``sigma = rho v^2``), its section ``A = m / (2 pi R rho)`` as width times thickness;
- a press: the motor gives the energy of a hole ``E`` over the whole cycle, evenly, so
  during the punching (a fraction ``f`` of the cycle) the flywheel gives
  ``dE_max = E (1 - f)``; the motor's power ``E / t_cycle``.

Every integral is the law's or the segments' closed form; the crossings are bracketed on a
grid of a quarter of a degree (and the segments' corners) and bisected to the last bit. Two
crossings closer together than the grid are missed (a lobe that thin holds no energy to
speak of).

>>> from polygon_method.scene.energy_records import CycleScene, Diagram, Law, Rim
>>> law = Law((("const", 1000.0, 0, 0), ("sin", 300.0, 2.0, 0.0)), "")
>>> d = Diagram("law", 2 * math.pi, driving=law)
>>> c = solve_cycle(CycleScene("", None, d, None, Rim(0.02, 20.0)))
>>> round(c.T_mean, 9), round(c.dE_max, 9)     # 300 sin 2theta from 0 to pi/2: 300 J
(1000.0, 300.0)
>>> round(c.inertia, 9)                         # 300 / (20^2 x 0.02)
37.5
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..common.errors import SceneError
from ..common.tolerances import FLOOR, MEAN_NOUGHT, ROUNDING, SAME

__all__ = [
    "ANSWER_FIELDS",
    "CycleEnergy",
    "Crossing",
    "solve_cycle",
    "letters",
    "curves",
    "at_angles",
    "speed_at",
]

_GRID = math.radians(0.25)

#: each answer key of a diagram's scene -> (its field of :class:`CycleEnergy`, SI unit, what
#: it is): what ``check`` holds and a variant's answer key lists
ANSWER_FIELDS = {
    "T_mean": ("T_mean", "N m", "the mean torque"),
    "power": ("power", "W", "the power"),
    "dE_max": ("dE_max", "J", "the maximum fluctuation of energy"),
    "E_stroke": ("E_stroke", "J", "the energy of one hole"),
    "I_flywheel": ("inertia", "kg m^2", "the flywheel's moment of inertia"),
    "m_flywheel": ("mass", "kg", "the flywheel's mass"),
    "Cs": ("Cs", "", "the coefficient of fluctuation of speed"),
    "Ce": ("Ce", "", "the coefficient of fluctuation of energy"),
    "speed_max": ("speed_max", "rad/s", "the greatest speed"),
    "speed_min": ("speed_min", "rad/s", "the least speed"),
    "alpha_at": ("alpha_at", "rad/s^2", "the angular acceleration"),
    "rim_radius": ("rim_radius", "m", "the rim's mean radius"),
    "rim_width": ("rim_width", "m", "the rim's width"),
    "rim_thickness": ("rim_thickness", "m", "the rim's thickness"),
}


@dataclass(frozen=True)
class Crossing:
    """A crossing of the mean (or resisting) line: its letter (a, b, ...), its crank angle
    (rad; None for a diagram given as areas) and the energy there (J, from the start)."""

    letter: str
    angle: float | None
    energy: float


@dataclass(frozen=True)
class CycleEnergy:
    """The cycle's numbers (SI; see the module's words). ``areas``: the energies between
    the crossings in order (J; the first from crossing a); ``crossings``: the
    :class:`Crossing` records, the last the first again a cycle on; ``i_max``/``i_min``:
    the crossings where E is greatest and least. The flywheel's fields are None where the
    scene gives no [flywheel] (or not what they need). ``words``: the defaults and how
    the scene was read."""

    form: str
    cycle: float
    T_mean: float | None
    work: float | None
    areas: tuple
    crossings: tuple
    i_max: int
    i_min: int
    dE_max: float
    speed: float | None = None
    Cs: float | None = None
    inertia: float | None = None
    speed_max: float | None = None
    speed_min: float | None = None
    power: float | None = None
    alpha_at: float | None = None
    rim_radius: float | None = None
    rim_speed: float | None = None
    mass: float | None = None
    rim_area: float | None = None
    rim_width: float | None = None
    rim_thickness: float | None = None
    E_stroke: float | None = None
    #: the coefficient of fluctuation of energy, dE_max over the work of a cycle (where the
    #: work is known and positive: not for areas alone, nor a press)
    Ce: float | None = None
    words: tuple = field(default=())

    @property
    def E_max(self) -> float:
        """The greatest energy at a crossing (J, above E at a)."""
        return self.crossings[self.i_max].energy

    @property
    def E_min(self) -> float:
        """The least energy at a crossing (J, above E at a)."""
        return self.crossings[self.i_min].energy

    def as_dict(self) -> dict:
        """The JSON of ``solve --json`` (SI; angles in deg)."""
        d = {
            "form": self.form,
            "cycle_deg": math.degrees(self.cycle),
            "T_mean": self.T_mean,
            "work_per_cycle": self.work,
            "areas": list(self.areas),
            "crossings": [
                {
                    "letter": c.letter,
                    "angle_deg": None if c.angle is None else math.degrees(c.angle),
                    "energy": c.energy,
                }
                for c in self.crossings
            ],
            "E_max": {"at": self.crossings[self.i_max].letter, "energy": self.E_max},
            "E_min": {"at": self.crossings[self.i_min].letter, "energy": self.E_min},
            "dE_max": self.dE_max,
        }
        for k in (
            "E_stroke",
            "Ce",
            "speed",
            "Cs",
            "inertia",
            "speed_max",
            "speed_min",
            "power",
            "alpha_at",
            "rim_radius",
            "rim_speed",
            "mass",
            "rim_area",
            "rim_width",
            "rim_thickness",
        ):
            d[k] = getattr(self, k)
        d["notes"] = list(self.words)
        return d


def letters(n: int) -> list:
    """The crossings' letters a, b, ..., z, a1, b1, ... (``n`` of them)."""
    return [chr(97 + i % 26) + (str(i // 26) if i >= 26 else "") for i in range(n)]


def solve_cycle(scene) -> "CycleEnergy":
    """The :class:`CycleEnergy` of a :class:`~polygon_method.scene.energy_records.CycleScene`."""
    words = []
    if scene.press is not None:
        p = scene.press
        dE = p.energy * (1.0 - p.fraction)
        base = dict(
            form="press",
            cycle=2 * math.pi,
            T_mean=None,
            work=p.energy,
            areas=(-dE, dE),
            crossings=tuple(
                Crossing(x, None, e) for x, e in zip("aba", (0.0, -dE, 0.0))
            ),  # back to a
            i_max=0,
            i_min=1,
            dE_max=dE,
            power=p.energy / p.period,
            E_stroke=p.energy,
        )
        words += list(p.words)
        words.append(
            f"the flywheel gives the energy of a hole less what the motor gives while it is "
            f"punched: dE_max = E (1 - {p.fraction:.6g})"
        )
    else:
        d = scene.diagram
        words += list(d.words)
        base = _areas(d) if d.form == "areas" else _given(d) if d.form == "energy" else _curve(d)
        work = base.get("work")
        if work is not None and work > 0:
            base["Ce"] = base["dE_max"] / work
    return _flywheel(scene, base, words)


def _areas(d) -> dict:
    # the running sums of the numbers as the book gives them (exact where they are whole),
    # in energy: no rounding noise where the book's areas come back to nought
    given, per = (d.mm2, d.per_mm2) if d.mm2 else (d.areas, 1.0)
    run = [math.fsum(given[:k]) * per for k in range(len(given) + 1)]
    if abs(run[-1]) <= ROUNDING * max(abs(a) for a in d.areas):
        run[-1] = 0.0
    n = len(run)
    names = letters(n - 1) + ["a"]
    cross = tuple(Crossing(names[i], None, run[i]) for i in range(n))
    e = run[:-1]  # (the last is the first a cycle on)
    return dict(
        form="areas",
        cycle=d.cycle,
        T_mean=None,
        work=None,
        areas=tuple(d.areas),
        crossings=cross,
        i_max=int(np.argmax(e)),
        i_min=int(np.argmin(e)),
        dE_max=max(e) - min(e),
    )


def _given(d) -> dict:
    """The book's energy alone (no diagram): dE_max as given, the mean torque from the work
    of a cycle where it is known; the energy least at a and greatest at b, where they are
    the diagram does not say (no angles)."""
    dE = d.fluctuation
    return dict(
        form="energy",
        cycle=d.cycle,
        T_mean=None if d.work is None else d.work / d.cycle,
        work=d.work,
        areas=(),
        crossings=tuple(Crossing(x, None, e) for x, e in zip("aba", (0.0, dE, 0.0))),
        i_max=1,
        i_min=0,
        dE_max=dE,
    )


def _curve(d) -> dict:
    """A law's or a table's diagram: the mean, the crossings, the energies."""
    T, R, cyc = d.driving, d.resisting, d.cycle
    steady = not getattr(T, "terms", True)  # torque = "constant": at the resisting's mean
    mean_R = None if R is None else (R.integral(cyc) - R.integral(0.0)) / cyc
    mean_T = mean_R if steady else (T.integral(cyc) - T.integral(0.0)) / cyc
    grid = np.linspace(0.0, cyc, max(16, int(math.ceil(cyc / _GRID))) + 1)
    corners = [c for c in T.corners + (R.corners if R is not None else ()) if 0 < c < cyc]
    grid = np.unique(np.concatenate([grid, corners]))
    if not steady and abs(mean_T) <= MEAN_NOUGHT * float(np.max(np.abs(T.value(grid)))):
        mean_T = 0.0  # rounding about a true nought

    def drive(x):
        return mean_T + 0.0 * x if steady else T.value(x)

    def resist(x):
        return mean_T + 0.0 * x if R is None else R.value(x)

    scale = float(np.max(np.abs(drive(grid)))) + float(np.max(np.abs(resist(grid))))
    if R is not None and abs(mean_T - mean_R) > SAME * scale:
        raise SceneError(
            f"the driving torque's mean ({mean_T:.6g} N m) and the resisting torque's "
            f"({mean_R:.6g} N m) differ: the speed would not return after a cycle (leave "
            "resisting out for a resisting torque constant at the mean)",
            key="[turning_moment] resisting",
        )

    def q(x):
        return drive(x) - resist(x)

    def energy(x):
        dT = mean_T * x if steady else T.integral(x) - T.integral(0.0)
        dR = mean_T * x if R is None else R.integral(x) - R.integral(0.0)
        return float(dT - dR)

    qs = q(grid)
    if float(np.max(np.abs(qs))) <= ROUNDING * max(scale, FLOOR):
        raise SceneError(
            "the turning moment equals the resisting torque all through the cycle: "
            "no fluctuation of energy, no flywheel to find",
            key="[turning_moment] torque",
        )
    roots = _roots(q, grid, qs)
    if not roots:
        raise SceneError(
            "the turning moment never crosses the resisting torque over the cycle: the "
            "engine gains (or loses) speed every cycle (check the resisting torque)",
            key="[turning_moment] torque",
        )
    e0 = energy(roots[0])
    es = [energy(r) - e0 for r in roots]  # from the first crossing, as the books count
    big = max(abs(e) for e in es)
    es = [0.0 if abs(e) <= ROUNDING * big else e for e in es]  # rounding noise is nought
    n = len(roots)
    names = letters(n)
    cross = [Crossing(names[i], roots[i], es[i]) for i in range(n)]
    cross.append(Crossing("a", roots[0] + cyc, es[0]))
    areas = tuple(es[i + 1] - es[i] for i in range(n - 1)) + (
        energy(cyc) - es[-1] if n > 1 else 0.0,
    )
    if n == 1:
        areas = ()
    return dict(
        form=d.form,
        cycle=cyc,
        T_mean=mean_T,
        work=mean_T * cyc,
        areas=areas,
        crossings=tuple(cross),
        i_max=_first(es, max),
        i_min=_first(es, min),
        dE_max=max(es) - min(es),
        _q=q,
    )


def _roots(q, grid, qs) -> list:
    """The crossings of ``q`` (T - R) over the cycle's ``grid`` (``qs`` its values there):
    each sign change bisected; a run of noughts on the grid (one reading, or a segment
    along the line) a crossing where it begins, if the sign changes across it; the cycle's
    start a crossing if the sign before its end and after its start differ (the cycle
    repeats: a nought there, or segments that end on one side and start on the other)."""
    qs = np.where(np.abs(qs) <= SAME * np.max(np.abs(qs)), 0.0, qs)  # a rounding is nought
    signed = np.flatnonzero(qs)
    roots = [0.0] if qs[signed[-1]] * qs[signed[0]] < 0 else []
    last = None  # the last value not nought before a run of noughts
    for i in range(len(grid) - 1):
        a, b, qa, qb = grid[i], grid[i + 1], qs[i], qs[i + 1]
        if qa * qb < 0:
            roots.append(_bisect(q, float(a), float(b), qa))
        elif qa != 0.0 and qb == 0.0:
            last = i
        elif qa == 0.0 and qb != 0.0 and last is not None and qs[last] * qb < 0:
            roots.append(float(grid[last + 1]))
    return roots


def _bisect(f, a, b, fa):
    """The root of ``f`` between ``a`` and ``b`` (a sign change) to the last bit."""
    for _ in range(200):
        m = 0.5 * (a + b)
        if m <= a or m >= b:
            break
        fm = float(f(m))
        if fm == 0.0:
            return m
        if (fm < 0) == (fa < 0):
            a, fa = m, fm
        else:
            b = m
    return 0.5 * (a + b)


def _first(es, most) -> int:
    """The first crossing whose energy is the greatest (``most`` max) or the least (min),
    energies a rounding apart being equal (three cylinders' equal lobes: the first, as the
    book reads them, not the one the rounding of the running sum lifts).

    >>> _first([0.0, 7.853981633974483, 0.0, 7.853981633974485], max)
    1
    """
    best = most(es)
    tol = ROUNDING * (max(es) - min(es))
    return next(i for i, e in enumerate(es) if abs(e - best) <= tol)


def _flywheel(scene, base, words) -> CycleEnergy:
    q = base.pop("_q", None)
    fw, d = scene.flywheel, scene.diagram
    if fw is None:
        return CycleEnergy(**base, words=tuple(words))
    words += list(fw.words)
    w, dE = fw.speed, base["dE_max"]
    if w is None:  # the rim's speed alone: m v^2 Cs = dE_max (I w^2 = m v^2)
        v, cs = fw.rim_speed, fw.coefficient
        share = "" if fw.share == 1 else f"{fw.share:.6g} "
        words.append(f"the rim's mass m = {share}dE_max / (v^2 Cs)")
        out = dict(base, Cs=cs, rim_speed=v, mass=fw.share * dE / (v * v * cs))
        return CycleEnergy(**out, words=tuple(words))
    out = dict(base, speed=w)
    if base["T_mean"] is not None:
        out["power"] = base["T_mean"] * w
    if fw.inertia is None:
        cs = fw.coefficient
        inertia = dE / (w * w * cs)
    else:
        inertia = fw.inertia
        cs = dE / (inertia * w * w)
        if not cs < 2:
            raise SceneError(
                f"the flywheel ({inertia:.4g} kg m^2) is too light: the speed would "
                f"swing by {cs:.3g} of its mean (more than all of it)",
                key="[flywheel] inertia",
            )
    out.update(Cs=cs, inertia=inertia, speed_max=w * (1 + cs / 2), speed_min=w * (1 - cs / 2))
    if d is not None and d.at is not None and q is not None:
        out["alpha_at"] = float(q(d.at % d.cycle)) / inertia
    if fw.gyration is not None:
        out["mass"] = inertia / fw.gyration**2
        words.append("the flywheel's mass m = I / k^2")
    elif fw.radius is not None:
        R = fw.radius
        m = fw.share * inertia / (R * R)
        area = m / (2 * math.pi * R * fw.density)
        out.update(rim_radius=R, rim_speed=w * R, mass=m, rim_area=area)
        words.append(
            "the rim's mass m = I / R^2 (the rim's mass at its mean radius)"
            if fw.share == 1
            else f"the rim's mass m = {fw.share:.6g} I / R^2 (its share of the effect)"
        )
        if fw.ratio is not None:
            t = math.sqrt(area / fw.ratio)
            out.update(rim_thickness=t, rim_width=fw.ratio * t)
        elif fw.width is not None:
            out.update(rim_width=fw.width, rim_thickness=area / fw.width)
        elif fw.thickness is not None:
            out.update(rim_thickness=fw.thickness, rim_width=area / fw.thickness)
    return CycleEnergy(**out, words=tuple(words))


def curves(scene, c, n: int = 1441) -> tuple:
    """``(theta, T, R, E)`` over the cycle at ``n`` evenly spaced crank angles (rad) and the
    segments' corners (a jump drawn upright): the driving and resisting torques (N m) and
    the energy from its value at the first crossing (J), for the drawing and the CSV of a
    diagram given as a law or segments."""
    d = scene.diagram
    T, R = d.driving, d.resisting
    th = np.linspace(0.0, d.cycle, n)
    corners = [x for x in T.corners + (R.corners if R is not None else ()) if 0 <= x <= d.cycle]
    th = np.sort(np.concatenate([th, corners, corners]))
    steady = not getattr(T, "terms", True)
    tq = c.T_mean + 0.0 * th if steady else np.array([T.value(float(x)) for x in th])
    rs = c.T_mean + 0.0 * th if R is None else np.array([R.value(float(x)) for x in th])
    for curve, values in ((T, tq), (R, rs)):  # at a jump, the value before it at the
        if curve is None or not curve.corners:  # first of the pair (a law has no corner)
            continue
        for i in range(1, len(th)):
            if th[i] == th[i - 1] and i + 1 < len(th):
                values[i - 1] = _before(curve, th[i])
    return th, tq, rs, _energies(scene, c, th)


def _energies(scene, c, th):
    """E at each crank angle of ``th`` (rad) above E at the first crossing, a (J): the
    closed forms' ``int_a^theta (T - R) dtheta``."""
    d = scene.diagram
    T, R = d.driving, d.resisting
    steady = not getattr(T, "terms", True)

    def energy(x):
        dT = c.T_mean * x if steady else T.integral(x) - T.integral(0.0)
        dR = c.T_mean * x if R is None else R.integral(x) - R.integral(0.0)
        return dT - dR

    base = energy(c.crossings[0].angle)
    return np.array([energy(float(x)) - base for x in th])


def at_angles(scene, c, th) -> tuple:
    """``(T, R, E)`` at the crank angles ``th`` (rad, within the cycle; a sequence) of a
    diagram given as a law or segments: the driving and resisting torques (N m; at a
    segments' jump, the value after it) and the energy above E at a (J), as arrays."""
    d = scene.diagram
    T, R = d.driving, d.resisting
    th = np.asarray(th, dtype=float)
    steady = not getattr(T, "terms", True)
    tq = c.T_mean + 0.0 * th if steady else np.array([T.value(float(x)) for x in th])
    rs = c.T_mean + 0.0 * th if R is None else np.array([R.value(float(x)) for x in th])
    return tq, rs, _energies(scene, c, th)


def speed_at(c, energy):
    """The flywheel's speed (rad/s) where the energy above E at a is ``energy`` (J; a float
    or an array), or None without a flywheel: its kinetic energy less its least,
    ``I (w^2 - w_min^2) / 2 = E - E_min``. With ``w_max, w_min = w (1 +- Cs / 2)`` and
    ``dE_max = I w^2 Cs`` this is exact at both ends: ``I (w_max^2 - w_min^2) / 2 =
    I w (w Cs) = dE_max``.

    >>> from types import SimpleNamespace as N
    >>> c = N(inertia=2.0, speed_min=9.0, crossings=(N(energy=0.0), N(energy=-19.0)), i_min=1)
    >>> round(float(speed_at(c, 0.0)), 12)        # sqrt(81 + 2 x 19 / 2)
    10.0
    """
    if c.inertia is None:
        return None
    e_min = c.crossings[c.i_min].energy
    return np.sqrt(c.speed_min**2 + 2.0 * (np.asarray(energy, dtype=float) - e_min) / c.inertia)


def _before(T, x):
    """A table's value just before ``x`` (at a jump, the value the segment ends on)."""
    a, t = T.angles, T.torques
    for i in range(len(a) - 1):
        if a[i] < x <= a[i + 1] and a[i + 1] > a[i]:
            return t[i] + (t[i + 1] - t[i]) * (x - a[i]) / (a[i + 1] - a[i])
    return T.value(x)
