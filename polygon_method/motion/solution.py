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

from types import MappingProxyType

from ..solver.derived import input_torque as _torque
from ..solver.derived import PinRubbing, power_terms, plan_records as _records
from ..solver.centres import JSON_BODIES, centres_dict, locate
from ..solver.errorbound import bounds_dict, error_bounds
from ..common.errors import TOL, PolygonMethodError, SceneError
from ..solver.kinematics import Motion, hypot
from ..common.numbers import fmt_angular, quiet, sense  # noqa: F401  (re-exported)
from ..solver.compiler import PLANS_BY_ID, compile_plan
from ..steps.base import Context
from .structural import structural_warnings
from ..scene import FixedPath, Scene, loads_dict
from ..scene.force_records import rolling_body
from ..scene.teeth import teeth_records
from .json_safe import finite_only, useful_bounds
from .link_points import PAIR_KINDS, asked_dict, bounds_dict as pair_bounds_dict, pair_value

__all__ = ["solve", "Solution", "PinRubbing", "sense", "fmt_angular"]

_UNSET = object()  # a quantity not yet derived (its value may be None)

#: answer kind -> (its table of :class:`~.errorbound.ErrorBounds`, the size it is relative to)
_BOUND_OF = {
    "v": ("V", "velocity"),
    "a": ("A", "acceleration"),
    "omega": ("W", "omega"),
    "alpha": ("Al", "alpha"),
    "vs": ("S", "velocity"),
    "as": ("S", "acceleration"),
    "ac": ("S", "acceleration"),
}


class Solution(Motion):
    """The :class:`~polygon_method.solver.kinematics.Motion` at the scene's instant (floats, SI),
    with what a textbook asks of it: rubbing, torque, warnings, the JSON contract."""

    __slots__ = ("_cache", "ctx", "array")  # ctx, array: what the plan's steps read

    def __init__(self, scene, plan, P, V, A, W, Al, S, cond, theta=None):
        self.scene, self.plan, self.theta = scene, plan, theta
        self.P, self.V, self.A, self.W, self.Al, self.S = P, V, A, W, Al, S
        self.cond, self.bad = cond, None
        self._cache = {}
        self.ctx, self.array = None, False  # solve: the instant the plan filled it at

    def _get(self, name, make):
        c = self._cache
        value = c.get(name, _UNSET)
        if value is _UNSET:
            value = c[name] = make()
        return value

    def speed(self, point, relative_to=None) -> float:
        """The size of ``point``'s velocity (relative to ``relative_to``), m/s."""
        return hypot(*self.velocity(point, relative_to))

    # ----- derived quantities
    @property
    def R(self) -> dict:
        """pin -> rubbing velocity of each pair of bodies it joins."""
        return {p: r.values for p, r in self.rubbing.items()}

    @property
    def rubbing(self) -> dict:
        """Pin -> :class:`PinRubbing`, for every pin with a size in ``[pins]``.

        At each pin, for each pair of bodies it joins: ``|w1 - w2| r`` (signed omegas: the
        sum of the magnitudes when they turn in opposite senses, the difference when alike)."""
        c = self._cache
        r = c.get("rubbing")
        if r is None:
            r = c["rubbing"] = _records(self.plan, self.W)
        return r

    @property
    def power_terms(self) -> list:
        """(what, power in W) of each load: F . v for forces, T w for torques on links."""
        return self._get("power", lambda: power_terms(self.scene, self.V, self.W, self.S, self.P))

    @property
    def input_torque(self):
        """T on the crank, ccw positive: T w + sum(F . v) = 0. None without loads."""
        sc = self.scene
        if not sc.loads and not sc.cylinders:  # (the usual scene: nothing to balance)
            return None
        c = self._cache
        t = c.get("torque", _UNSET)  # None is a value (no loads): a sentinel, not a raise
        if t is _UNSET:
            t = c["torque"] = _torque(sc, self.V, self.W, sc.input.omega, self.S, self.P)
        return t

    @property
    def cylinder_force(self):
        """(cylinder, F) where the motion is given as a cylinder's rate of extension vs (the
        cylinder drives: the effort is a force along it, not a torque on the crank): F by
        power balance, ``F vs = T omega``, + pushing its ends apart. None otherwise (no
        loads, another driver, a standstill)."""
        sc, t = self.scene, self.input_torque
        g = sc.input.given
        if t is None or g is None or g.kind != "vs" or g.value == 0 or sc.input.second:
            return None
        key = next((c.key for c in sc.cylinders if c.key == g.names[0]), None)
        return None if key is None else (key, t * sc.input.omega / g.value)

    @property
    def forces(self):
        """The force analysis (:class:`~polygon_method.forces.Forces`) where the scene gives
        masses or gravity, else None. Raises a one-line
        :class:`~polygon_method.common.errors.PolygonMethodError` for a plan with a step the force
        analysis does not cover (see :attr:`forces_refused`)."""
        if not self.scene.has_forces:
            return None
        return self._get("forces", self._analyse)

    def _analyse(self):
        from ..forces import analyse  # lazy: a scene without masses never loads forces/
        from ..scene import key_line

        try:
            return analyse(self)
        except PolygonMethodError as exc:  # name the key's line where it names a key
            if exc.line is None and exc.key:
                exc.line = key_line(self.scene, exc.key)
            raise

    @property
    def forces_refused(self):
        """Why the force analysis was refused (one line), or None."""
        if not self.scene.has_forces:
            return None
        try:
            self.forces
        except PolygonMethodError as exc:
            return exc.message
        return None

    # ----- conditioning
    @property
    def error_bounds(self):
        """The estimated error bound of every quantity
        (:class:`~polygon_method.solver.errorbound.ErrorBounds`: ``P, V, A, W, Al, S``, relative to
        ``scales``; ``worst``), from the conditions of the steps each depends on."""
        return self._get("error_bounds", lambda: error_bounds(self))

    @property
    def warnings(self) -> tuple:
        """One line per ill-conditioned step (condition below sin 5 deg), then what the
        scene says that is likely not meant (a point on a fixed pivot or on the frame,
        lengths in metres that look like millimetres)."""

        def make():
            out = tuple(
                st.warning(c)
                for st in self.plan.steps
                if (c := self.cond.get(st.index, 1.0)) < TOL.warn
            )
            out += structural_warnings(self)
            res = self.plan.given
            if res is not None and res.condition < TOL.warn:
                g = self.scene.input.given
                out += (
                    f"[input] {g.key}: near a dead centre for this input (condition "
                    f"{res.condition:.3g}): the crank's speed found from it (as 1 / c)"
                    + (" and its acceleration (as 1 / c^3)" if res.rate is not None else "")
                    + " are large and very sensitive to it",
                )
            return out

        return self._get("warnings", make)

    @property
    def notes(self) -> tuple:
        """How the scene's words were read, then the defaults the plan took."""
        said = self.scene.input.angle_note
        return ((said,) if said else ()) + tuple(self.scene.reading_notes) + tuple(self.plan.notes)

    # ----- presentation
    @property
    def scales(self) -> dict:
        """The largest value of each kind in this solution (for :meth:`shown`)."""

        def make():
            w = max((abs(x) for x in self.W.values()), default=0.0)
            return {
                "v": max((hypot(*v) for v in self.V.values()), default=0.0),
                "a": max((hypot(*a) for a in self.A.values()), default=0.0),
                "omega": w,
                "alpha": max((abs(x) for x in self.Al.values()), default=0.0) + w * w,
            }

        return self._get("scales", make)

    def noise(self, kind, name=None) -> float:
        """The absolute error bound of a quantity: its own relative bound
        (:attr:`error_bounds`) times the size of its kind it is relative to. ``kind``:
        "v", "a" (``name`` a point, or a tuple of points: a relative vector, the sum of
        theirs), "omega", "alpha" (a link's key), "vs", "as", "ac" (a slider's key);
        without a name, the largest of that kind. 0 where the bound is no useful bound
        (1 or more of its size): then nothing is hidden, the report says why.
        """
        b = self.error_bounds
        table, size = _BOUND_OF[kind]
        size = b.scales[size]
        if table == "S":
            j = ("vs", "as", "ac").index(kind)
            vals = (
                [b.S.get(name, (0.0,) * 3)[j]] if name is not None else [t[j] for t in b.S.values()]
            )
        else:
            t = getattr(b, table)
            names = (name,) if isinstance(name, str) else name
            vals = [t.get(n, 0.0) for n in names] if names is not None else list(t.values())
            if names is not None and len(vals) > 1:
                vals = [sum(vals)]
        e = max(vals, default=0.0)
        if not e < 1.0:  # inf, nan or >= 1: no useful bound, hide nothing
            return 0.0
        return float(e * size)

    def shown(self, value, kind, name=None):
        """``value`` as reports show it: 0 where it is within its own error bound
        (:meth:`noise`: ``kind`` "v", "a", "omega", "alpha", "vs", "as", "ac" and the
        quantity's ``name``): rounding noise about a true zero, not a motion. Only noise is
        hidden: a value above its bound is shown however small beside the largest of its
        kind (an acceleration of 40 m/s^2 beside 7e11 near a toggle)."""
        lim = self.noise(kind, name)
        return 0.0 if abs(value) <= lim else value

    # ----- output
    def _pairs_dict(self) -> dict:
        """The JSON's sliders, cylinders and pins (each key only where the scene has them)."""
        sc = self.scene
        d = {}
        if sc.blocks:  # a driving wheel's centre is no slider: see the rolling entry
            d["sliders"] = {
                s.key: {
                    "sliding_velocity": self.S[s.key][0],
                    "sliding_acceleration": self.S[s.key][1],
                    "coriolis": list(self.coriolis(s.key)),
                    "guide": (
                        s.label
                        if isinstance(s, FixedPath)
                        else f"block {s.yoke}"
                        if hasattr(s, "yoke")
                        else s.along  # (the link from the point the sliding is signed from)
                    ),
                    **({"offset": s.offset} if getattr(s, "offset", 0.0) else {}),  # (m)
                }
                for s in sc.blocks
            }
        if sc.cylinders:
            d["cylinders"] = {
                c.key: {
                    "length": self.cylinder_length(c.key),
                    "extension_rate": self.S[c.key][0],
                    "extension_acceleration": self.S[c.key][1],
                    "coriolis": [self.S[c.key][2], self.S[c.key][3]],
                    "omega": self.W[c.key],
                    "alpha": self.Al[c.key],
                    "barrel": c.barrel,
                    "rod": c.rod,
                }
                for c in sc.cylinders
            }
        if sc.pins:
            d["pins"] = {}
            for name, r in self.rubbing.items():
                entry = {"rubbing_velocity": r.rubbing_velocity, "radius": r.radius}
                if len(r.bodies) > 2:
                    entry["pairs"] = dict(r.pairs)
                d["pins"][name] = entry
        return d

    def _input_dict(self) -> dict:
        """The JSON's input: the block driver's record or the crank's angle and rates, a second
        input's, and the stated velocity it was found from (with its condition)."""
        sc, inp = self.scene, self.scene.input
        own = self.plan.steps[0].input_record(sc)  # a block driver's place and rates
        d = (
            own
            if own is not None
            else {"crank": inp.crank, "angle": inp.angle, "omega": inp.omega, "alpha": inp.alpha}
        )
        if inp.second is not None:
            two = inp.second
            d["second"] = (
                {"crank": two.crank, "angle": two.angle, "omega": two.omega, "alpha": two.alpha}
                if two.block is None
                else self.plan.steps[1].second_record(sc)
            )  # a collar's
        d.update(inp.found_record())  # two inputs' speeds found from other links' speeds
        res = self.plan.given
        if res is not None:
            g = inp.given
            d["given"] = {
                "key": g.key,
                "value": g.value,
                "rate_key": g.rate_key,
                "rate": g.rate,
                "per_omega": res.per_omega,
                "per_omega2": res.per_omega2,
                "condition": res.condition,
            }
        return d

    def _rolling_dict(self) -> dict:
        """The JSON's rolling contacts (a gear's teeth; a driving wheel's centre, its line)."""
        contacts = {}
        for st in self.plan.steps:
            c = st.contact_motion(self)
            if c is not None:
                contacts[st.bodies()[0]] = c
        if not contacts:
            return {}
        d = {
            k: {"contact": list(c[0]), "velocity": list(c[1]), "acceleration": list(c[2])}
            | teeth_records(self.scene.rolling).get(k, {})  # a gear given by its teeth
            for k, c in contacts.items()
        }
        for s in self.scene.wheel_paths:
            d.setdefault(s.wheel, {}).update(
                {
                    "centre": s.point,
                    "centre_velocity": self.S[s.key][0],
                    "centre_acceleration": self.S[s.key][1],
                    "line": s.label,
                }
            )
        return {"rolling": d}

    def to_dict(self) -> dict:
        """The JSON contract of ``solve --json`` (SI, ccw positive)."""
        sc = self.scene
        d = {
            "title": sc.title,
            "points": {
                p: {
                    "position": list(self.P[p]),
                    "velocity": list(self.V[p]),
                    "acceleration": list(self.A[p]),
                }
                for p in sc.point_names
            },
            "links": {
                lk.key: {"omega": self.W[lk.key], "alpha": self.Al[lk.key]} for lk in sc.links
            },
        }
        d.update(self._pairs_dict())
        if self.input_torque is not None:  # (loads; two inputs: no one torque)
            # a block driver: the force along its guide (N, signed along it)
            d[self.plan.steps[0].effort_key] = self.input_torque
        d["input"] = self._input_dict()
        refused = self.forces_refused
        if sc.has_forces:
            from ..forces import forces_dict  # lazy, as in `forces`

            d["forces"] = None if refused else forces_dict(self.forces)
            if not refused and any(hasattr(c, "push") for c in sc.cylinders):
                from ..forces.cylinder import given_dict  # a strut's, a damper's force

                d["forces"]["cylinders"] = given_dict(sc, self.S, self.forces, self.P)
            if sc.at_rest:  # the weights and loads alone; the motion per rad/s of the crank
                d["at_rest"] = True
                if sc.start_alpha:  # starting from rest: the inertia of the start
                    d["start_alpha"] = sc.start_alpha
        d.update(self._rolling_dict(), **asked_dict(self), **loads_dict(sc.loads, self.P))
        warnings = list(self.warnings)
        if refused:
            warnings.append(refused)
        bodies = 1 + sum(len(st.bodies()) for st in self.plan.steps)
        if bodies <= JSON_BODIES:
            try:
                d["centres"] = centres_dict(locate(self))
            except PolygonMethodError as exc:
                warnings.append(f"instantaneous centres: {exc.message}")
        d["steps"] = [
            {
                "step": st.index + 1,
                "kind": st.kind,
                "title": st.title,
                "finds": list(st.finds),
                "condition": self.cond.get(st.index, 1.0),
            }
            for st in self.plan.steps
        ]
        d["warnings"] = warnings
        d["notes"] = list(self.notes)
        bounds = bounds_dict(self, self.error_bounds) | pair_bounds_dict(self)  # (vmin_BC ...)
        d["error_bounds"] = useful_bounds(bounds)
        if sc.has_forces and not refused:  # each force's bound, null where none is useful
            from ..forces.bounds import bounds_dict as force_bounds_dict, force_bounds

            d["error_bounds"]["forces"] = force_bounds_dict(force_bounds(self))
        return finite_only(d)

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
            return hypot(*self.coriolis(names[0]))
        if kind == "rub":
            return self.rubbing[names[0]].rubbing_velocity
        if kind == "torque":
            if not self.scene.has_forces:
                return self.input_torque
            f = self.forces
            if f.driver not in ("crank", "wheel"):  # a block's or cylinder's effort: a force
                raise SceneError(
                    f"torque: {f.crank} drives this mechanism with a force, not "
                    "a torque (solve gives it as the input force)"
                )
            return f.input_torque
        if kind in ("force", "torque2", "force2"):  # a driver's effort but the crank's torque
            if (
                kind == "force"
                and not self.scene.has_forces
                and self.plan.steps[0].effort_key == "input_force"
            ):
                return self.input_torque  # (the loads' power balance)
            from ..forces import effort_value  # lazy, as in `forces`

            return effort_value(self.forces, kind)
        if kind in ("F", "N", "Fc", "Fi", "Ci", "h", "Tmax", "Pmax", "Thold"):
            from ..forces import force_value  # lazy, as in `forces`

            if kind in ("Tmax", "Pmax"):  # a friction drive's wheel, or the gear it grips
                names = (self.scene.link("-".join(names)).key,)
            return force_value(
                self.forces, kind, rolling_body(self.scene, names) if kind == "Fc" else names[0]
            )
        if kind in PAIR_KINDS:  # two points of one link (vmin_BC, ar_CB, at_CB)
            return pair_value(self, kind, names)
        if kind in ("vu", "au"):  # the guide's point under a block (v_A1, a_A1)
            return hypot(
                *self.under_block(names[0], "velocity" if kind == "vu" else "acceleration")
            )
        if kind in ("vI", "aI"):  # the wheel's point at its rolling contact
            wheel = self.scene.link("-".join(names)).key
            for st in self.plan.steps:
                got = st.contact_motion(self) if wheel in st.links else None
                if got is not None:
                    return hypot(*got[1 if kind == "vI" else 2])
        raise KeyError(kind)


def solve(scene: Scene) -> Solution:
    """Compile (once per scene content) and evaluate the plan at the scene's crank angle.

    Raises :class:`~polygon_method.common.errors.AssemblyError` or
    :class:`~polygon_method.common.errors.SingularStepError` where the construction fails.
    """
    hit = PLANS_BY_ID.get(id(scene))  # compile_plan's first look, without its call
    if hit is not None and hit[0]() is scene:
        plan = hit[1]
        inp = scene.input
        kept = hit[2]  # (input, its one-instant context) of the last solve of this scene
        ctx = kept[1] if kept[0] is inp else _kept_context(hit, inp)
    else:
        plan = compile_plan(scene)
        inp = scene.input  # (completed when compiled)
        ctx = _instant(inp.angle, inp.omega, inp.alpha, _NO_COND)
    sol = _new(Solution)  # Solution(scene, plan, ...): filled in here, by the plan too
    steps = plan.instant_steps or plan.bind_own_instant()
    sol.cond = plan.start_cond.copy()  # the steady steps' 1 (they do not write it)
    # plan.instant(ctx, sol) (= plan.run(ctx), one instant) written out: one call fewer
    # (its fields read here as Plan.instant reads them: keep the two alike)
    zero = plan.zero_motion
    fixed = plan.fixed_links
    sol.P = plan.ground.copy()
    sol.V = zero.copy()
    sol.A = zero.copy()
    sol.W = fixed.copy()
    sol.Al = fixed.copy()
    sol.S = {}
    sol.ctx = ctx
    sol.array = False  # one instant
    try:
        for f in steps:
            f(sol)
    except PolygonMethodError as exc:  # name the scene file in the one-line message
        raise exc.located(plan.scene.file)
    sol.scene = scene
    sol.plan = plan
    sol.theta = inp.angle
    sol.bad = None
    sol._cache = {}
    return sol


_new = object.__new__
_instant = Context.instant
_NO_COND = MappingProxyType({})  # a kept context's conditions: each solve writes its own


def _kept_context(entry, inp):
    """The one-instant context of ``inp``'s angle, speed and acceleration, kept in the
    scene's cache entry for its next solve (read-only conditions: each solve's own are the
    solution's ``cond``)."""
    ctx = _instant(inp.angle, inp.omega, inp.alpha, _NO_COND)
    entry[2] = (inp, ctx)
    return ctx
