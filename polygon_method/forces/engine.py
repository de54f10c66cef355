"""The engine's gas force from its indicator diagram: the pressure on the piston at each
crank angle of the cycle, from the scene's ``[indicator]`` table (floats for one instant,
arrays over a sweep).

The slider crank: crank O A (``r``), rod A B (``l``), the piston B on a fixed path through Q
along unit ``u``; F the foot of O on the path, ``e = |OF|`` the offset, ``s`` the side of F
the piston is on (+1 along ``u``). At the inner dead centre the piston is farthest from O,
``B_i = F + s sqrt((l + r)^2 - e^2) u``, the crank pointing at it; at the outer dead centre
nearest, ``B_o = F + s sqrt((l - r)^2 - e^2) u``, the crank pointing away. The cycle's
phase is the crank angle from the inner dead centre in the crank's sense of rotation
(``sg``, the sign of omega), ``phi = sg (theta - theta_i) mod cycle``; the piston's place as a
fraction of the stroke from the inner dead centre is
``x = (sqrt((l + r)^2 - e^2) - s (B - F).u) / stroke``. The gas pushes the piston towards
the crank, ``-s u``, with the pressure times the area.

>>> import math
>>> round(table_pressure((0.0, math.pi), (10.0, 20.0), 2 * math.pi, math.pi / 2), 12)
15.0
>>> round(table_pressure((0.0, math.pi), (10.0, 20.0), 2 * math.pi, 3 * math.pi / 2), 12)
15.0
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..common.errors import PolygonMethodError
from ..scene import key_line
from ..common.tolerances import DISTINCT


@dataclass(frozen=True)
class SliderCrankGeometry:
    """The slider crank under an indicator diagram: the crank centre ``O``, the crank and
    rod lengths ``r``, ``l``, the path's unit ``u`` and the foot ``F`` of O on it, the offset
    ``e``, the piston's side ``s``, the crank's sense ``sg``; the dead centres' crank angles
    ``theta_i``, ``theta_o`` (rad from +x) and the stroke (m)."""

    crank: str
    piston: str
    O: tuple
    r: float
    l: float
    u: tuple
    F: tuple
    e: float
    s: float
    sg: float
    theta_i: float
    theta_o: float
    stroke: float

    @property
    def phase_o(self) -> float:
        """The outer dead centre's phase (rad after the inner, in the sense of rotation):
        pi for an in-line engine."""
        return (self.sg * (self.theta_o - self.theta_i)) % (2 * math.pi)

    def phase(self, theta):
        """The crank angle from the inner dead centre in the sense of rotation (rad, not
        reduced: reduce it by the cycle)."""
        return self.sg * (theta - self.theta_i)

    def fraction(self, bx, by):
        """The piston's place as a fraction of the stroke from the inner dead centre."""
        (fx, fy), (ux, uy) = self.F, self.u
        far = math.sqrt((self.l + self.r) ** 2 - self.e**2)
        return (far - self.s * ((bx - fx) * ux + (by - fy) * uy)) / self.stroke


def slider_crank(plan, piston: str):
    """(the driving crank's step, the step that slides the piston on its fixed path) where
    the piston's rod is pinned at the crank's tip, else None (asked of the steps: the
    driver's pivot and tip, a step finding the piston with a fixed ``path`` and its rod's
    other end ``b``)."""
    first = plan.steps[0]
    tip = getattr(first, "tip", None)
    if tip is None or getattr(first, "pivot", None) is None:
        return None
    for st in plan.steps[1:]:
        finds = st.finds if isinstance(st.finds, tuple) else (st.finds,)
        if piston in finds:
            ok = getattr(st, "path", None) is not None and getattr(st, "b", None) == tip
            return (first, st) if ok else None
    return None


def geometry(scene, plan, piston: str, side: float) -> SliderCrankGeometry:
    """The slider crank of ``plan`` whose piston is ``piston`` (``side``: +1 where the
    piston is along the path's ``u`` from the foot of the crank centre). Refuses, in one
    line, a mechanism that is no slider crank there, or a crank at rest."""
    pair = slider_crank(plan, piston)
    if pair is None:
        raise PolygonMethodError(
            f"[indicator]: the piston {piston} must slide on a fixed path, "
            "pinned by a rod to the driving crank's pin (a slider crank)",
            file=scene.file,
            key="[indicator] piston",
            line=key_line(scene, "[indicator] piston"),
        )
    first, sd = pair
    w = scene.input.omega
    if not w:
        raise PolygonMethodError(
            "[indicator]: the cycle runs in the crank's sense of rotation: give the crank a speed",
            file=scene.file,
            key="[input] speed",
            line=key_line(scene, "[input] speed"),
        )
    ox, oy = scene.ground[first.pivot]
    r, l = first.length, sd.length
    (qx, qy), (ux, uy) = sd.path.through, sd.path.u
    t = (ox - qx) * ux + (oy - qy) * uy
    fx, fy = qx + t * ux, qy + t * uy
    e = math.hypot(ox - fx, oy - fy)
    if l <= r + e:
        raise PolygonMethodError(
            f"[indicator]: the crank {first.link} cannot turn fully (l <= r + e): no engine cycle",
            file=scene.file,
            key="[indicator]",
            line=key_line(scene, "[indicator]"),
        )
    far, near = math.sqrt((l + r) ** 2 - e * e), math.sqrt((l - r) ** 2 - e * e)
    bi = (fx + side * far * ux, fy + side * far * uy)
    bo = (fx + side * near * ux, fy + side * near * uy)
    th_i = math.atan2(bi[1] - oy, bi[0] - ox)
    th_o = math.atan2(oy - bo[1], ox - bo[0])
    return SliderCrankGeometry(
        first.link,
        piston,
        (ox, oy),
        r,
        l,
        (ux, uy),
        (fx, fy),
        e,
        side,
        1.0 if w > 0 else -1.0,
        th_i,
        th_o,
        far - near,
    )


def table_pressure(xs, ps, cycle, phase):
    """The pressure of an angle table at ``phase`` (rad, any), linear between the table's
    angles and round the cycle (from its last angle to its first plus the cycle)."""
    xs, ps = list(xs), list(ps)
    if xs[0] > 0.0 or xs[-1] < cycle:
        xs, ps = [xs[-1] - cycle] + xs + [xs[0] + cycle], [ps[-1]] + ps + [ps[0]]
    ph = np.mod(phase, cycle)
    out = np.interp(ph, xs, ps)
    return float(out) if np.ndim(out) == 0 else out


def stroke_of(g: SliderCrankGeometry, phase, cycle):
    """The index of the stroke (0, 1, ...) each phase falls in: the strokes run from dead
    centre to dead centre, the first from the inner one."""
    ph = np.mod(phase, cycle)
    turn = np.floor(ph / (2 * math.pi))
    k = 2 * turn + (np.mod(ph, 2 * math.pi) >= g.phase_o)
    return k.astype(int) if np.ndim(k) else int(k)


def pressure(ind, g: SliderCrankGeometry, theta, bx, by, phase=None):
    """The indicator's pressure (Pa) at crank angle ``theta`` (the piston at ``(bx, by)``;
    ``phase``, where given, the cylinder's own phase: see :func:`cylinders`)."""
    phase = g.phase(theta) if phase is None else phase
    if ind.against == "angle":
        return table_pressure(ind.x, ind.p, ind.cycle, phase)
    x = np.clip(g.fraction(bx, by), 0.0, 1.0)
    k = stroke_of(g, phase, ind.cycle)
    rows = np.array([np.interp(x, ind.x, row) for row in ind.p])
    out = np.choose(k, rows) if np.ndim(k) else rows[k]
    return float(out) if np.ndim(out) == 0 else out


def piston_side(scene, plan, P, piston) -> float:
    """+1 where the piston lies along its path's ``u`` from the foot of the crank centre
    (at the first of the positions ``P``; a piston keeps its side over a turn)."""
    pair = slider_crank(plan, piston)
    if pair is None:
        geometry(scene, plan, piston, 1.0)  # refuses in its words
    first, sd = pair
    (ox, oy), (bx, by) = scene.ground[first.pivot], P[piston]
    ux, uy = sd.path.u
    d = np.ravel((bx - ox) * ux + (by - oy) * uy)
    return 1.0 if d[0] >= 0 else -1.0


def indicator_force(scene, motion):
    """(Fx, Fy, p, the geometry) of the indicator's gas force on the piston at ``motion``'s
    crank angles: the pressure times the area, towards the crank."""
    ind = scene.indicator
    P = motion.P
    side = piston_side(scene, motion.plan, P, ind.piston)
    g = geometry(scene, motion.plan, ind.piston, side)
    bx, by = P[ind.piston]
    p = pressure(ind, g, motion.theta, bx, by)
    f = -g.s * p * ind.area
    return f * g.u[0], f * g.u[1], p, g


@dataclass(frozen=True)
class Cylinder:
    """One cylinder of several on one crank under its indicator diagram: its table ``ind``,
    its slider crank ``g``, the diagram's reference (the first cylinder's geometry ``g0``)
    and ``lag`` (rad): its cycle's phase is the first's less the lag."""

    ind: object
    g: SliderCrankGeometry
    g0: SliderCrankGeometry
    lag: float
    lag_given: bool

    def phase(self, theta):
        """The cylinder's own phase (rad from its inner dead centre, this cycle's)."""
        return self.g0.phase(theta) - self.lag


def cylinders(scene, plan, P) -> tuple:
    """Each indicator's :class:`Cylinder` (in the scene's order), the first the diagram's
    reference. A later cylinder's cycle begins at its own inner dead centre, ``lag`` after
    the first's (the scene's, or the least such angle); a lag that misses its inner dead
    centre is refused in one line that names the lags it may have."""
    out = []
    for ind in scene.indicators:
        g = geometry(scene, plan, ind.piston, piston_side(scene, plan, P, ind.piston))
        g0 = out[0].g if out else g
        turn = 2 * math.pi
        least = (g0.sg * (g.theta_i - g0.theta_i)) % turn
        lag = least if ind.lag is None else ind.lag
        miss = (lag - least) % turn
        if min(miss, turn - miss) > DISTINCT:
            first = out[0].ind.piston
            can = ", ".join(
                f"{math.degrees(least + k * turn):.6g}"
                for k in range(round(ind.cycle / turn))
                if least + k * turn < ind.cycle
            )
            raise PolygonMethodError(
                f"lag = {math.degrees(lag):.6g} deg: {ind.piston}'s inner dead centre comes "
                f"{math.degrees(least):.6g} deg of the crank after {first}'s, and its cycle "
                f"begins there: lag = {can} (deg)",
                file=scene.file,
                key=f"[indicator.{ind.piston}] lag",
                line=key_line(scene, f"[indicator.{ind.piston}] lag"),
            )
        out.append(Cylinder(ind, g, g0, lag, ind.lag is not None))
    return tuple(out)


def indicator_forces(scene, motion) -> tuple:
    """((piston, Fx, Fy, p), ...): each indicator's gas force at ``motion``'s crank
    angles, in its own phase (one piston's, or several cylinders' on one crank)."""
    if scene.indicator is not None:
        fx, fy, p, _ = indicator_force(scene, motion)
        return ((scene.indicator.piston, fx, fy, p),)
    out = []
    for c in cylinders(scene, motion.plan, motion.P):
        bx, by = motion.P[c.ind.piston]
        p = pressure(c.ind, c.g, motion.theta, bx, by, c.phase(motion.theta))
        f = -c.g.s * p * c.ind.area
        out.append((c.ind.piston, f * c.g.u[0], f * c.g.u[1], p))
    return tuple(out)


def engine_piston(scene, plan):
    """The piston of an engine: the point the indicator or a gas force acts on, sliding on a
    fixed path pinned by a rod to the driving crank's pin; None for a scene that is no
    engine (no gas force, or not a slider crank there)."""
    if scene.indicator is not None:  # (with another cylinder's gas force: several)
        return None if _other_cylinders(scene, plan) else scene.indicator.piston
    gas = [ld.target for ld in scene.loads if ld.gas is not None]
    if len(gas) != 1 or scene.indicators:
        return None
    return gas[0] if slider_crank(plan, gas[0]) is not None else None


@dataclass(frozen=True)
class Efforts:
    """The engine chapter's forces at the instant (floats, or arrays over a sweep): the
    piston effort ``F_P`` (the net force on the piston along the line of stroke, towards
    the crank: the gas force, the reciprocating parts' inertia force and weight), the
    thrust in the rod ``F_Q`` (its size at the piston pin), the side thrust on the cylinder
    walls ``F_N`` (the guide's normal force's size), the crank effort ``F_T`` (the rod's
    force on the crank pin across the crank, in the sense of rotation) and the turning
    moment ``T = F_T r`` (N m, in the sense of rotation; the driver's torque with inertia,
    reversed, where the crank carries no mass)."""

    piston: str
    rod: str
    crank: str
    F_P: object
    F_Q: object
    F_N: object
    F_T: object
    T: object
    r: float


def efforts(scene, plan, P, f) -> Efforts | None:
    """:class:`Efforts` of an engine from its force analysis ``f`` at positions ``P``."""
    piston = engine_piston(scene, plan)
    if piston is None:
        return None
    return _efforts_of(scene, plan, P, f, piston)


def engine_pistons(scene, plan) -> tuple:
    """The pistons of an engine of several cylinders on one crank (a V-twin's two on one
    crank pin, a radial's): every point a gas force acts on, when there are two or more and
    each slides on a fixed path pinned by a rod to the driving crank's pin; else ()."""
    named = [i.piston for i in scene.indicators]
    if scene.indicator is not None:  # one indicator: with other cylinders' gas forces
        others = _other_cylinders(scene, plan)
        return tuple(dict.fromkeys(named + others)) if others else ()
    gas = named + [ld.target for ld in scene.loads if ld.gas is not None]
    gas = tuple(dict.fromkeys(gas))
    if len(gas) < 2 or any(slider_crank(plan, p) is None for p in gas):
        return ()
    return gas


def _other_cylinders(scene, plan) -> list:
    """The slider cranks' pistons under a ``[loads]`` gas force besides the indicators'."""
    named = {i.piston for i in scene.indicators}
    gas = [ld.target for ld in scene.loads if ld.gas is not None and ld.target not in named]
    return [p for p in gas if slider_crank(plan, p) is not None]


def cylinder_efforts(scene, plan, P, f) -> tuple:
    """Each cylinder's :class:`Efforts` of an engine of several cylinders on one crank
    (:func:`engine_pistons`), in the scene's order: its piston effort, its rod's thrust,
    its side thrust, its rod's crank effort across the common crank and the turning moment
    that rod gives (their sum is the engine's turning moment); () for another scene."""
    return tuple(_efforts_of(scene, plan, P, f, p) for p in engine_pistons(scene, plan))


def _efforts_of(scene, plan, P, f, piston) -> Efforts:
    """The :class:`Efforts` of the slider crank whose piston is ``piston``."""
    first, sd = slider_crank(plan, piston)
    side = piston_side(scene, plan, P, piston)
    ux, uy = sd.path.u
    tx, ty = -side * ux, -side * uy  # towards the crank
    kb = f.resultant(f"block {piston}")  # what its step knew on it
    F_P = kb[0] * tx + kb[1] * ty
    q = f.pin(piston, sd.link)
    F_Q = (q[0] * q[0] + q[1] * q[1]) ** 0.5
    gd = next(g for g in f.guides if g.point == piston)
    F_N = abs(gd.normal)
    sg = 1.0 if scene.input.omega >= 0 else -1.0
    # the rod's force on the crank at its pin, across the crank (the sense of rotation)
    fa = f.pin(first.tip, first.link, sd.link)
    (ox, oy), (ax, ay) = P[first.pivot], P[first.tip]
    r = first.length
    F_T = sg * ((ax - ox) * fa[1] - (ay - oy) * fa[0]) / r
    return Efforts(piston, sd.link, first.link, F_P, F_Q, F_N, F_T, F_T * r, r)
