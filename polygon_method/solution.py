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

from .derived import input_torque as _torque
from .derived import PinRubbing, pin_records, power_terms
from .centres import JSON_BODIES, centres_dict, locate
from .errorbound import bounds_dict, error_bounds
from .errors import TOL, PolygonMethodError
from .kinematics import Motion, hypot
from .numbers import fmt_angular, quiet, sense  # noqa: F401  (re-exported)
from .compiler import compile_plan
from .plan import Context
from .scene import FixedPath, Scene

__all__ = ["solve", "Solution", "PinRubbing", "sense", "fmt_angular"]

_UNSET = object()  # a quantity not yet derived (its value may be None)


class Solution(Motion):
    """The :class:`~polygon_method.kinematics.Motion` at the scene's instant (floats, SI),
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
        sum of the magnitudes when they turn in opposite senses, the difference when alike).
        """
        c = self._cache
        r = c.get("rubbing")
        if r is None:
            r = c["rubbing"] = pin_records(self.plan.pins, self.W, self.plan.dims.radii)
        return r

    @property
    def power_terms(self) -> list:
        """(what, power in W) of each load: F . v for forces, T w for torques on links."""
        return self._get("power", lambda: power_terms(self.scene, self.V, self.W))

    @property
    def input_torque(self):
        """T on the crank, ccw positive: T w + sum(F . v) = 0. None without loads."""
        c = self._cache
        t = c.get("torque", _UNSET)  # None is a value (no loads): a sentinel, not a raise
        if t is _UNSET:
            t = c["torque"] = _torque(self.scene, self.V, self.W, self.scene.input.omega)
        return t

    # ----- conditioning
    @property
    def error_bounds(self):
        """The estimated error bound of every quantity
        (:class:`~polygon_method.errorbound.ErrorBounds`: ``P, V, A, W, Al, S``, relative to
        ``scales``; ``worst``), from the conditions of the steps each depends on."""
        return self._get("error_bounds", lambda: error_bounds(self))

    @property
    def warnings(self) -> tuple:
        """One line per ill-conditioned step (condition below sin 5 deg), then what the
        scene says that is likely not meant (a point on a fixed pivot or on the frame,
        lengths in metres that look like millimetres)."""
        def make():
            out = tuple(st.warning(c) for st in self.plan.steps
                        if (c := self.cond.get(st.index, 1.0)) < TOL.warn)
            out += _structural_warnings(self)
            res = self.plan.given
            if res is not None and res.condition < TOL.warn:
                g = self.scene.input.given
                out += (f"[input] {g.key}: near a dead centre for this input (condition "
                        f"{res.condition:.3g}): the crank's speed found from it is very "
                        "sensitive to it",)
            return out
        return self._get("warnings", make)

    @property
    def notes(self) -> tuple:
        """How the scene's words were read, then the defaults the plan took."""
        said = self.scene.input.angle_note
        return ((said,) if said else ()) + tuple(self.scene.reading_notes) + \
            tuple(self.plan.notes)

    # ----- presentation
    @property
    def scales(self) -> dict:
        """The largest value of each kind in this solution (for :meth:`shown`)."""
        def make():
            w = max((abs(x) for x in self.W.values()), default=0.0)
            return {"v": max((hypot(*v) for v in self.V.values()), default=0.0),
                    "a": max((hypot(*a) for a in self.A.values()), default=0.0),
                    "omega": w,
                    "alpha": max((abs(x) for x in self.Al.values()), default=0.0) + w * w}
        return self._get("scales", make)

    def shown(self, value, kind):
        """``value`` as reports show it: 0 where it is below ``TOL.negligible`` of the
        largest of its ``kind`` ("v", "a", "omega", "alpha"): rounding noise, not a motion."""
        return quiet(value, self.scales[kind])

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
            d["sliders"] = {s.key: {"sliding_velocity": self.S[s.key][0],
                                    "sliding_acceleration": self.S[s.key][1],
                                    "coriolis": list(self.coriolis(s.key)),
                                      "guide": (s.label if isinstance(s, FixedPath) else
                                                f"block {s.yoke}" if hasattr(s, "yoke")
                                                else s.guide)}
                            for s in sc.sliders}
        if sc.cylinders:
            d["cylinders"] = {c.key: {"length": self.cylinder_length(c.key),
                                      "extension_rate": self.S[c.key][0],
                                      "extension_acceleration": self.S[c.key][1],
                                      "coriolis": [self.S[c.key][2], self.S[c.key][3]],
                                      "omega": self.W[c.key], "alpha": self.Al[c.key],
                                      "barrel": c.barrel, "rod": c.rod}
                              for c in sc.cylinders}
        if sc.pins:
            d["pins"] = {}
            for name, r in self.rubbing.items():
                entry = {"rubbing_velocity": r.rubbing_velocity, "radius": r.radius}
                if len(r.bodies) > 2:
                    entry["pairs"] = dict(r.pairs)
                d["pins"][name] = entry
        if sc.loads and sc.input.second is None:  # two inputs: no one torque
            d["input_torque"] = self.input_torque
        inp = sc.input
        d["input"] = {"crank": inp.crank, "angle": inp.angle, "omega": inp.omega,
                      "alpha": inp.alpha}
        if inp.second is not None:
            two = inp.second
            d["input"]["second"] = {"crank": two.crank, "angle": two.angle,
                                    "omega": two.omega, "alpha": two.alpha}
        res = self.plan.given
        if res is not None:
            g = inp.given
            d["input"]["given"] = {"key": g.key, "value": g.value, "rate_key": g.rate_key,
                                   "rate": g.rate, "per_omega": res.per_omega,
                                   "per_omega2": res.per_omega2,
                                   "condition": res.condition}
        contacts = {}
        for st in self.plan.steps:
            c = st.contact_motion(self)
            if c is not None:
                contacts[st.bodies()[0]] = c
        if contacts:  # the wheel's point at each rolling contact
            d["rolling"] = {k: {"contact": list(c[0]), "velocity": list(c[1]),
                                "acceleration": list(c[2])} for k, c in contacts.items()}
        warnings = list(self.warnings)
        bodies = 1 + sum(len(st.bodies()) for st in self.plan.steps)
        if bodies <= JSON_BODIES:
            try:
                d["centres"] = centres_dict(locate(self))
            except PolygonMethodError as exc:
                warnings.append(f"instantaneous centres: {exc.message}")
        d["steps"] = [{"step": st.index + 1, "kind": st.kind, "title": st.title,
                       "finds": list(st.finds),
                       "condition": self.cond.get(st.index, 1.0)}
                      for st in self.plan.steps]
        d["warnings"] = warnings
        d["notes"] = list(self.notes)
        d["error_bounds"] = bounds_dict(self, self.error_bounds)
        return d

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
            return self.input_torque
        if kind in ("vu", "au"):  # the guide's point under a block (v_A1, a_A1)
            return hypot(*self.under_block(names[0], "velocity" if kind == "vu"
                                           else "acceleration"))
        if kind in ("vI", "aI"):  # the wheel's point at its rolling contact
            wheel = self.scene.link("-".join(names)).key
            for st in self.plan.steps:
                got = st.contact_motion(self) if wheel in st.links else None
                if got is not None:
                    return hypot(*got[1 if kind == "vI" else 2])
        raise KeyError(kind)


def _structural_warnings(sol) -> tuple:
    """Lines for what the scene says that is likely not meant: a moving point placed on a
    fixed pivot, or on a link that is fixed (its velocity is zero because of where it
    sits, not because of the motion), and lengths in metres that look like millimetres."""
    sc = sol.scene
    out = []
    size = max([lk.length for lk in sc.links] + [1e-300])
    u, unit = sc.length_unit, sc.units
    fixed = sol.plan.fixed_links
    for cp in sc.points:
        lk = sc.link(cp.link)
        if lk.key in fixed:
            out.append(f"point {cp.name} is on link {lk.key}, whose ends are both fixed: it "
                       "sits on the frame, so its velocity and acceleration are zero (was it "
                       "meant to be on a moving link?)")
    for X in sc.point_names:
        if X in sc.ground:
            continue
        for G, g in sc.ground.items():
            if hypot(sol.P[X][0] - g[0], sol.P[X][1] - g[1]) > 1e-9 * size:
                continue
            cp = sc.carried(X)
            lk = sc.link(cp.link) if cp is not None else None
            if lk is not None and lk.key in fixed:
                break  # said above
            if lk is not None and G in lk.points:
                out.append(f"point {X} is placed on the fixed pivot {G} (on link {lk.key}, "
                           f"0 {unit} from {G}): it does not move, so its velocity and "
                           "acceleration are zero")
            else:
                out.append(f"point {X} is at the fixed pivot {G} at this instant (the "
                           f"mechanism passes through {G}'s place, at ({g[0] / u:g}, "
                           f"{g[1] / u:g}) {unit}): check the figure")
            break
    if unit == "m" and sc.links:
        lengths = [lk.length for lk in sc.links]
        crank = sc.link(sc.input.crank)
        pin = abs(sc.input.omega or 0.0) * crank.length
        if min(lengths) >= 5.0 and pin > 60.0:
            out.append(f"units = \"m\", yet the links are {min(lengths):g} to "
                       f"{max(lengths):g} m long (the crank pin would move at {pin:.4g} m/s): "
                       "if the lengths are millimetres, write units = \"mm\"")
    return tuple(out)


def solve(scene: Scene) -> Solution:
    """Compile (once per scene content) and evaluate the plan at the scene's crank angle.

    Raises :class:`~polygon_method.errors.AssemblyError` or
    :class:`~polygon_method.errors.SingularStepError` where the construction fails.
    """
    plan = compile_plan(scene)
    inp = scene.input
    sol = _new(Solution)  # Solution(scene, plan, ...): filled in here, by the plan too
    plan.instant(Context(inp.angle, inp.omega, inp.alpha), sol)  # = plan.run(ctx), one instant
    sol.scene = scene
    sol.plan = plan
    sol.theta = inp.angle
    sol.bad = None
    sol._cache = {}
    return sol


_new = object.__new__



def tidied(sol: Solution) -> Solution:
    """``sol`` with its rounding noise set to exact zeros, for reports that write every
    number out (the step table, the centres): a component below ``TOL.negligible`` of the
    largest of its kind (a position of the mechanism's size) is 0, so a link that does not
    turn has no sense and a block that does not slide no Coriolis component."""
    sc = sol.scene
    k = sol.scales
    size = max([lk.length for lk in sc.links]
               + [hypot(*p) for p in sol.P.values()] + [0.0])

    def vec(d, scale):
        return {n: (quiet(x, scale), quiet(y, scale)) for n, (x, y) in d.items()}

    def num(d, kind):
        return {n: sol.shown(x, kind) for n, x in d.items()}

    S = {n: (sol.shown(s[0], "v"), sol.shown(s[1], "a"))
         + tuple(quiet(c, k["a"]) for c in s[2:]) for n, s in sol.S.items()}
    out = Solution(sc, sol.plan, vec(sol.P, size), vec(sol.V, k["v"]), vec(sol.A, k["a"]),
                   num(sol.W, "omega"), num(sol.Al, "alpha"), S, sol.cond, sol.theta)
    for rec in out.rubbing.values():  # |w1 - w2| r of two equal omegas: 0
        rec.values = tuple(quiet(v, k["omega"] * rec.radius) for v in rec.values)
        rec.rubbing_velocity = max(rec.values, default=0.0)
    t = out.input_torque
    if t is not None:
        # each load's power is noise against |F| v (|T_L| omega), the torque against their
        # sum over the crank's omega
        sizes = [hypot(*ld.force) * k["v"] if ld.force is not None
                 else abs(ld.torque) * k["omega"] for ld in sc.loads]
        out._cache["power"] = [(what, quiet(p, bound))
                               for (what, p), bound in zip(out.power_terms, sizes)]
        out._cache["torque"] = quiet(t, sum(sizes) / abs(sc.input.omega))
    return out
