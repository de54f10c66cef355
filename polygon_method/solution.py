"""Solve a scene at its stated instant and collect what a textbook asks for.

>>> from polygon_method.scene import parse_scene
>>> sol = solve(parse_scene('''
... [ground]
... O = [0, 0]
... [links]
... OA = 150
... AB = 600
... [sliders]
... B = { path = "horizontal" }
... [input]
... crank = "OA"
... angle = 90
... speed = "10 rad/s ccw"
... '''))
>>> round(sol.speed("B"), 6)   # at 90 deg the piston moves as fast as the crank pin
1.5
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from .errors import TOL
from .numbers import fmt_angular, sense  # noqa: F401  (re-exported)
from .plan import Context, Plan, compile_plan
from .scene import FixedPath, Scene



def cached(method):
    """A property computed once per Solution (functools.cached_property takes a lock in
    Python 3.11, which costs more than the arithmetic here)."""
    name = method.__name__

    def get(self):
        cache = self._cache
        try:
            return cache[name]
        except KeyError:
            value = cache[name] = method(self)
            return value

    get.__doc__ = method.__doc__
    return property(get)


__all__ = ["solve", "Solution", "PinRubbing", "sense", "fmt_angular"]


class PinRubbing:
    """Rubbing velocity at a pin: ``|w1 - w2| r`` for each pair of bodies the pin joins.

    Attributes: ``point``, ``radius``, ``pairs`` ({"AB|BC": v}), ``bodies`` ({body: omega})
    and ``rubbing_velocity`` (the largest pair).
    """

    __slots__ = ("point", "radius", "_keys", "_values", "_names", "_omegas")

    def __init__(self, point, radius, keys, values, names, omegas):
        self.point, self.radius = point, radius
        self._keys, self._values, self._names, self._omegas = keys, values, names, omegas

    @property
    def pairs(self) -> dict:
        return dict(zip(self._keys, self._values))

    @property
    def bodies(self) -> dict:
        return dict(zip(self._names, self._omegas))

    @property
    def rubbing_velocity(self) -> float:
        return max(self._values, default=0.0)

    def __repr__(self):
        return f"PinRubbing({self.point!r}, radius={self.radius!r}, pairs={self.pairs!r})"


@dataclass(frozen=True)
class Solution:
    """Positions, velocities, accelerations of every point and link at one instant (SI)."""

    scene: Scene
    plan: Plan
    P: dict
    V: dict
    A: dict
    W: dict
    Al: dict
    S: dict
    conditions: dict
    R: dict = field(default_factory=dict, repr=False)  # pin -> rubbing of each pair
    _cache: dict = field(default_factory=dict, repr=False, compare=False)

    # ----- points
    def position(self, point):
        return self.P[point]

    def velocity(self, point, relative_to=None):
        """Velocity of ``point`` (relative to ``relative_to``: v_XY = v_X - v_Y)."""
        vx, vy = self.V[point]
        if relative_to is None:
            return (vx, vy)
        ux, uy = self.V[relative_to]
        return (vx - ux, vy - uy)

    def acceleration(self, point, relative_to=None):
        ax, ay = self.A[point]
        if relative_to is None:
            return (ax, ay)
        bx, by = self.A[relative_to]
        return (ax - bx, ay - by)

    def speed(self, point, relative_to=None) -> float:
        return math.hypot(*self.velocity(point, relative_to))

    def acceleration_magnitude(self, point, relative_to=None) -> float:
        return math.hypot(*self.acceleration(point, relative_to))

    # ----- links
    def omega(self, link) -> float:
        return self.W[self.scene.link(link).key]

    def alpha(self, link) -> float:
        return self.Al[self.scene.link(link).key]

    # ----- sliders
    def sliding_velocity(self, point) -> float:
        return self.S[point][0]

    def sliding_acceleration(self, point) -> float:
        return self.S[point][1]

    def coriolis(self, point):
        return self.S[point][2]

    # ----- derived quantities
    @cached
    def rubbing(self) -> dict:
        """Pin -> :class:`PinRubbing`, for every pin with a size in ``[pins]``.

        At each pin, for each pair of bodies it joins: ``|w1 - w2| r`` (signed omegas: the
        sum of the magnitudes when they turn in opposite senses, the difference when alike).
        """
        W, R = self.W, self.R
        return {point: PinRubbing(point, radius, keys, R[point], names,
                                  [W[lk] if lk is not None else 0.0 for lk in links])
                for point, radius, names, links, keys, _ in self.plan.pins}

    @cached
    def power_terms(self) -> list:
        """(what, power in W) of each load: F . v for forces, T w for torques on links."""
        out = []
        for load in self.scene.loads:
            if load.force is not None:
                fx, fy = load.force
                vx, vy = self.V[load.target]
                out.append((load.target, fx * vx + fy * vy))
            else:
                out.append((load.target, load.torque * self.W[load.target]))
        return out

    @cached
    def input_torque(self):
        """T on the crank, ccw positive: T w + sum(F . v) = 0. None without loads."""
        if not self.scene.loads:
            return None
        return -sum(p for _, p in self.power_terms) / self.scene.input.omega

    # ----- conditioning
    @cached
    def warnings(self) -> tuple:
        """One line per ill-conditioned step (condition below sin 5 deg)."""
        out = []
        for st in self.plan.steps:
            c = self.conditions.get(st.index, 1.0)
            if c < TOL.warn:
                out.append(st.warning(c))
        return tuple(out)

    @property
    def notes(self) -> tuple:
        return self.plan.notes

    # ----- presentation
    @cached
    def scales(self) -> dict:
        """The largest value of each kind in this solution (for :meth:`shown`)."""
        w = max((abs(x) for x in self.W.values()), default=0.0)
        return {"v": max((math.hypot(*v) for v in self.V.values()), default=0.0),
                "a": max((math.hypot(*a) for a in self.A.values()), default=0.0),
                "omega": w,
                "alpha": max((abs(x) for x in self.Al.values()), default=0.0) + w * w}

    def shown(self, value, kind):
        """``value`` as reports show it: 0 where it is below ``TOL.negligible`` of the
        largest of its ``kind`` ("v", "a", "omega", "alpha"): rounding noise, not a motion."""
        return 0.0 if abs(value) <= TOL.negligible * self.scales[kind] else value

    # ----- output
    def to_dict(self) -> dict:
        """The JSON contract of ``solve --json`` (SI, ccw positive)."""
        sc = self.scene
        d = {"title": sc.title,
             "points": {p: {"position": list(self.P[p]), "velocity": list(self.V[p]),
                            "acceleration": list(self.A[p])} for p in sc.point_names},
             "links": {lk.key: {"omega": self.W[lk.key], "alpha": self.Al[lk.key]}
                       for lk in sc.links}}
        if sc.sliders:
            d["sliders"] = {s.point: {"sliding_velocity": self.S[s.point][0],
                                      "sliding_acceleration": self.S[s.point][1],
                                      "coriolis": list(self.S[s.point][2]),
                                      "guide": (s.label if isinstance(s, FixedPath)
                                                else s.guide)}
                            for s in sc.sliders}
        if sc.pins:
            d["pins"] = {}
            for name, r in self.rubbing.items():
                entry = {"rubbing_velocity": r.rubbing_velocity, "radius": r.radius}
                if len(r.bodies) > 2:
                    entry["pairs"] = dict(r.pairs)
                d["pins"][name] = entry
        if sc.loads:
            d["input_torque"] = self.input_torque
        d["steps"] = [{"step": st.index + 1, "kind": st.kind, "title": st.title,
                       "finds": list(st.finds),
                       "condition": self.conditions.get(st.index, 1.0)}
                      for st in self.plan.steps]
        d["warnings"] = list(self.warnings)
        d["notes"] = list(self.notes)
        return d

    def report(self) -> str:
        """The solution as text, the way ``polygon-method solve`` prints it."""
        from .report import solution_text
        return solution_text(self)

    def _repr_svg_(self):  # Jupyter
        try:
            from .draw import svg_string
        except ImportError:  # drawing not available
            return None
        return svg_string(self)

    def value(self, kind: str, names: tuple):
        """The exact value behind an answer key (``kind`` as in ``[answers]``)."""
        if kind == "v":
            return self.speed(*names)
        if kind == "a":
            return self.acceleration_magnitude(*names)
        if kind == "omega":
            return self.omega("-".join(names))
        if kind == "alpha":
            return self.alpha("-".join(names))
        if kind == "vs":
            return self.sliding_velocity(names[0])
        if kind == "as":
            return self.sliding_acceleration(names[0])
        if kind == "ac":
            return math.hypot(*self.coriolis(names[0]))
        if kind == "rub":
            return self.rubbing[names[0]].rubbing_velocity
        if kind == "torque":
            return self.input_torque
        raise KeyError(kind)


def solve(scene: Scene) -> Solution:
    """Compile (once per scene) and evaluate the plan at the scene's crank angle.

    Raises :class:`~polygon_method.errors.AssemblyError` or
    :class:`~polygon_method.errors.SingularStepError` where the construction fails.
    """
    plan = compile_plan(scene)
    inp = scene.input
    ctx = Context(inp.angle, inp.omega, inp.alpha)
    P, V, A, W, Al, S = plan.evaluate(ctx)
    return Solution(scene, plan, P, V, A, W, Al, S, ctx.cond, ctx.rubbing)

