"""Full-cycle sweeps: the scene's construction plan evaluated over many crank angles at once.

The same plan that :func:`~polygon_method.solution.solve` runs for one instant is run with
``Context(theta_array, omega, alpha, array=True)``: every kernel is plain arithmetic, so
one pass over a chunk of crank angles gives every position, velocity and acceleration
for all of them (chunks of :data:`CHUNK` angles stay in cache; no Python loop over
positions).

The assembly branch is the scene's own, followed continuously from the scene's instant
(the crank speed and acceleration are the scene's at every angle):

* where the crank cannot turn fully (a non-Grashof input, or a dyad that stops
  assembling) the sweep stops at the limit positions, where the discriminant of the
  failing step vanishes, and reports them; angles beyond are left out, never filled with
  NaN or with the other branch;
* at a change point (the two assemblies of a step meet, as in a parallelogram with all
  its pivots in line) the sweep follows the branch that is continuous in velocity and
  says so; if the two branches leave with the same velocity it stops there.

>>> from polygon_method.scene import parse_scene
>>> sc = parse_scene('''
... [ground]
... O = [0, 0]
... [links]
... OA = 150
... AB = 600
... [sliders]
... B = { path = "horizontal" }
... [input]
... crank = "OA"
... angle = 0
... speed = "10 rad/s ccw"
... ''')
>>> res = sweep(sc, np.radians([30.0, 90.0, 150.0]))
>>> [round(float(v), 4) for v in res.sliding_velocity("B")]   # dx/dt, x = r cos t + ...
[-0.9137, -1.5, -0.5863]
"""

from __future__ import annotations

import io
import math
from dataclasses import dataclass, field, replace

import numpy as np

from .derived import input_torque, largest, pin_rubbing
from .errors import TOL, PolygonMethodError, SceneError, SingularStepError
from .plan import Context, compile_plan
from .scene import FixedPath, Scene

__all__ = ["sweep", "summarize", "SweepResult", "Summary", "Extreme", "LimitPosition",
           "ChangePoint", "Domain", "Sweeper", "run_sweep", "CHUNK"]

#: crank angles evaluated per pass (about 32k: the temporaries of one pass stay in cache)
CHUNK = 32768
#: scouting grid for limit positions and change points, per turn of the crank
SCOUT = 4096
TWO_PI = 2.0 * math.pi
#: a step whose condition falls below this (and rises again) is checked for a change point
_CANDIDATE = 0.2
#: ... and is a change point where its refined minimum is below this
_CHANGE = 1e-7
#: a reachable range narrower than this (rad) is a locked linkage, not a motion
_LOCKED = 1e-5
#: offset either side of a change point when comparing the branches' velocities (rad)
_DELTA = 1e-6
#: samples this close to a change point (rad) get their velocities and accelerations by
#: extrapolation from both sides (the construction is indeterminate there)
_NEAR = 2e-3


# --------------------------------------------------------------------------- records


@dataclass(frozen=True)
class LimitPosition:
    """A crank angle beyond which the sweep cannot go on the scene's branch.

    ``theta`` is in the sweep's domain (rad, continuous with the scene's angle); ``step``
    names the construction step that stops assembling (its discriminant vanishes there).
    """

    theta: float
    step: str
    why: str

    @property
    def degrees(self) -> float:
        return math.degrees(self.theta) % 360.0


@dataclass(frozen=True)
class ChangePoint:
    """A crank angle where a step's two assemblies meet (its condition reaches zero and
    rises again): the branch is indeterminate there. ``followed`` says whether the sweep
    went on (on the branch continuous in velocity) or stopped."""

    theta: float
    step: str
    point: str
    followed: bool
    flipped: bool
    why: str
    radius: float = _NEAR  # rad: closer than this the construction is not trusted

    @property
    def degrees(self) -> float:
        return math.degrees(self.theta) % 360.0


@dataclass(frozen=True)
class Domain:
    """The crank angles reachable from the scene's instant on its branch.

    ``lo <= theta <= hi`` (rad, continuous with the scene's angle); ``full_turn`` when the
    crank turns fully (then ``hi = lo + 2 pi``). ``segments`` are ``(start, end, plan)``
    with the plan (its branches) valid between change points.
    """

    lo: float
    hi: float
    full_turn: bool
    segments: tuple
    limits: tuple = ()
    change_points: tuple = ()
    notes: tuple = ()

    def map(self, theta):
        """Crank angles (rad, any turn) -> the same angles in ``[lo, lo + 2 pi)`` and a mask
        of those the crank reaches."""
        t = self.lo + np.mod(np.asarray(theta, dtype=float) - self.lo, TWO_PI)
        if self.full_turn:
            return t, np.ones(t.shape, dtype=bool)
        return t, t <= self.hi + 1e-12


# --------------------------------------------------------------------------- evaluation


class Frame:
    """One evaluation over an array of crank angles: dicts as ``Plan.evaluate`` returns them,
    every value an array of the same length, plus the condition of every step."""

    __slots__ = ("theta", "P", "V", "A", "W", "Al", "S", "cond", "bad", "n")

    def __init__(self, theta, P, V, A, W, Al, S, cond, bad):
        self.theta, self.P, self.V, self.A, self.W, self.Al, self.S = theta, P, V, A, W, Al, S
        self.cond, self.bad, self.n = cond, bad, len(theta)


def _full(v, n):
    """An array of length n from a kernel value: a float (a ground point, a fixed link)
    becomes a read-only broadcast view of it."""
    if isinstance(v, np.ndarray) and v.shape == (n,):
        return v
    return np.broadcast_to(np.float64(v if v is not None else 0.0), (n,))


def _run(plan, theta, omega, alpha, vel=True, acc=True) -> Frame:
    """Evaluate ``plan`` over one array of crank angles (one pass, no chunking)."""
    n = len(theta)
    ctx = Context(theta, omega, alpha, array=True)
    with np.errstate(all="ignore"):
        P, V, A, W, Al, S = plan.evaluate(ctx, velocities=vel, accelerations=acc)
    fix = lambda d: {k: (_full(v[0], n), _full(v[1], n)) for k, v in d.items()}  # noqa: E731
    P, V, A = fix(P), fix(V), fix(A)
    W = {k: _full(v, n) for k, v in W.items()}
    Al = {k: _full(v, n) for k, v in Al.items()}
    S = {k: (_full(v[0], n), _full(v[1], n), _full(v[2][0], n), _full(v[2][1], n))
         for k, v in S.items()} if acc else {k: (_full(v[0], n),) for k, v in S.items()}
    cond = {i: _full(c, n) for i, c in ctx.cond.items()}
    bad = ctx.bad if ctx.bad is not None else np.zeros(n, dtype=bool)
    return Frame(theta, P, V, A, W, Al, S, cond, bad)


def _variant(plan, flips):
    """The plan with the branch (sigma) of the steps in ``flips`` reversed."""
    if not flips:
        return plan
    steps = tuple(replace(s, sigma=-s.sigma) if s.index in flips else s for s in plan.steps)
    kw = {"steps": steps}
    if "_compiled" in getattr(plan, "__dataclass_fields__", {}):
        kw["_compiled"] = {}  # a new kernel for the new branches
    return replace(plan, **kw)


def _branch_steps(plan):
    return [s for s in plan.steps if s.branching]


class Sweeper:
    """Evaluates a scene's plan at any crank angles, on the assembly branch continuous with
    the scene's instant (see :class:`Domain`). The domain is found once per scene."""

    def __init__(self, scene: Scene):
        self.scene = scene
        self.plan = compile_plan(scene)
        inp = scene.input
        self.theta0, self.omega, self.alpha = inp.angle, inp.omega, inp.alpha
        dom = scene._cache.get("sweep_domain")
        if dom is None:
            dom = scene._cache["sweep_domain"] = self._explore()
        self.domain = dom
        if not dom.full_turn and dom.hi - dom.lo < _LOCKED:
            lp = dom.limits[0] if dom.limits else None
            raise SingularStepError(
                f"the crank can move only {math.degrees(dom.hi - dom.lo):.2g} deg from its "
                f"angle in the scene: the linkage is locked there"
                + (f" ({lp.why})" if lp else ""), step=lp.step if lp else None,
                file=scene.file)

    # ----- exploring the branch
    def _scout(self, plan, grid):
        return _run(plan, grid, self.omega, self.alpha, vel=False, acc=False)

    def _explore(self) -> Domain:
        t0 = self.theta0
        rsegs, rcps, rlim = self._walk(+1, TWO_PI)
        if rlim is None:  # the crank turns fully: show the turn centred on the scene's angle
            rsegs = [(a, min(b, t0 + math.pi), p) for a, b, p in rsegs if a < t0 + math.pi]
            rcps = [c for c in rcps if c.theta < t0 + math.pi]
            lsegs, lcps, llim = self._walk(-1, math.pi)
            lo, hi, full = t0 - math.pi, t0 + math.pi, True
            notes = []
            if llim is not None:  # cannot happen for a periodic motion; be safe
                lo, full = llim.theta, False
            elif self._flips(lsegs[-1][2]) != self._flips(rsegs[-1][2]):
                notes.append("after a full turn of the crank the linkage is on its other "
                             "branch: the motion repeats only every two turns; the sweep "
                             "shows the turn centred on the scene's instant")
            limits = tuple(x for x in (llim,) if x is not None)
        else:
            lsegs, lcps, llim = self._walk(-1, TWO_PI - (rlim.theta - t0))
            lo = llim.theta if llim is not None else rlim.theta - TWO_PI
            hi, full, notes = rlim.theta, False, []
            limits = tuple(x for x in (llim, rlim) if x is not None)
        segs = [(b, a, p) for a, b, p in reversed(lsegs)] + list(rsegs)
        merged = []
        for a, b, p in segs:  # neighbours on the same branches are one segment
            if merged and self._flips(merged[-1][2]) == self._flips(p):
                merged[-1] = (merged[-1][0], b, merged[-1][2])
            elif b > a or not merged:
                merged.append((a, b, p))
        segs = [(a, b, p) for a, b, p in merged if b > a] or merged[:1]
        cps = tuple(sorted(lcps + rcps, key=lambda c: c.theta))
        return Domain(lo, hi, full, tuple(segs), limits, cps, tuple(notes))

    def _flips(self, plan):
        return tuple(s.sigma for s in plan.steps if hasattr(s, "sigma"))

    def _walk(self, direction, budget):
        """Turn the crank from the scene's angle in ``direction`` for up to ``budget`` rad;
        returns the segments passed (in walking order, as ``(from, to, plan)``), the change
        points met and the limit position where it stopped (or None)."""
        plan, start, done = self.plan, self.theta0, 0.0
        segs, cps = [], []
        while budget - done > 1e-12:
            left = budget - done
            n = max(65, int(SCOUT * left / TWO_PI) + 2)
            grid = start + direction * np.linspace(0.0, left, n)
            fr = self._scout(plan, grid)
            fail = fr.bad | ~np.isfinite(fr.P[self.plan.steps[-1].finds[0]][0])
            k = int(np.argmax(fail)) if fail.any() else n
            if k == 0:  # the very first angle fails: we stand on a limit
                segs.append((start, start, plan))
                step = self._step_failing(plan, start) or "the plan"
                return segs, cps, LimitPosition(start, step, self._limit_why(plan, step))
            found = self._change_point(plan, grid, fr, k)
            if found is not None:
                tc, st = found
                new, cp = self._decide(plan, st, tc, direction)
                cps.append(cp)
                segs.append(self._seg(start, tc, plan, direction))
                if not cp.followed:
                    return segs, cps, LimitPosition(tc, st.label, cp.why)
                done += abs(tc - start)
                start, plan = tc, new
                continue
            if k < n:
                t_lim, step = self._refine_limit(plan, grid[k - 1], grid[k])
                segs.append(self._seg(start, t_lim, plan, direction))
                return segs, cps, LimitPosition(t_lim, step, self._limit_why(plan, step))
            segs.append(self._seg(start, grid[-1], plan, direction))
            return segs, cps, None
        return segs, cps, None

    @staticmethod
    def _seg(a, b, plan, direction):
        """A segment passed from ``a`` to ``b`` (either way round)."""
        return (a, b, plan)

    def _limit_why(self, plan, label) -> str:
        st = next((s for s in plan.steps if s.label == label), None)
        return st.limit_why() if st is not None else "the linkage cannot be assembled beyond it"

    def _refine_limit(self, plan, good, bad):
        """Bisect (33 points a pass) between an assembling and a failing crank angle to the
        angle where the failing step's discriminant vanishes."""
        step = None
        for _ in range(12):
            pts = np.linspace(good, bad, 33)
            fr = self._scout(plan, pts)
            j = int(np.argmax(fr.bad)) if fr.bad.any() else None
            if j is None:  # the failure was tangential: the far end assembles after all
                good = bad
                break
            if step is None:
                step = self._step_failing(plan, pts[j])
            if j == 0:
                break
            good, bad = pts[j - 1], pts[j]
            if abs(bad - good) < 1e-14:
                break
        return float(good), step or "the plan"

    def _step_failing(self, plan, theta):
        ctx = Context(np.array([theta]), self.omega, self.alpha, array=True)
        with np.errstate(all="ignore"):
            plan.evaluate(ctx, velocities=False, accelerations=False)
        for i in sorted(ctx.failures):
            if ctx.failures[i].any():
                return plan.steps[i].label
        return None

    def _change_point(self, plan, grid, fr, k):
        """The first change point on ``grid[:k]``: a local minimum of a step's condition
        that refines to zero (the two assemblies meet and part again)."""
        best = None
        for st in _branch_steps(plan):
            c = fr.cond[st.index][:k]
            if len(c) < 3:
                continue
            inner = (c[1:-1] <= c[:-2]) & (c[1:-1] <= c[2:]) & (c[1:-1] < _CANDIDATE)
            for i in np.nonzero(inner)[0] + 1:
                if best is not None and abs(grid[i] - grid[0]) >= abs(best[0] - grid[0]):
                    break
                tc, cmin = self._minimize(plan, st, grid[i - 1], grid[i + 1])
                if cmin < _CHANGE:
                    best = (tc, st)
                    break
        return best

    def _minimize(self, plan, st, a, b):
        """The crank angle where step ``st``'s condition is smallest in [a, b] (zooming)."""
        for _ in range(10):
            pts = np.linspace(a, b, 33)
            fr = self._scout(plan, pts)
            c = np.where(fr.bad, np.inf, fr.cond[st.index])
            j = int(np.argmin(c))
            a, b = pts[max(j - 1, 0)], pts[min(j + 1, 32)]
        return float(pts[j]), float(c[j])

    def _velocity_vector(self, plan, theta):
        fr = _run(plan, np.array([theta]), self.omega, self.alpha, acc=False)
        parts = [v for xy in fr.V.values() for v in xy] + list(fr.W.values())
        return np.array([float(p[0]) for p in parts])

    def _decide(self, plan, st, tc, direction):
        """At a change point: keep the branch or flip ``st``'s, whichever leaves with the
        velocity the linkage arrives with."""
        before = self._velocity_vector(plan, tc - direction * _DELTA)
        keep = self._velocity_vector(plan, tc + direction * _DELTA)
        flipped_plan = _variant(plan, {st.index})
        flip = self._velocity_vector(flipped_plan, tc + direction * _DELTA)
        scale = np.linalg.norm(before) + 1e-300
        dk, df = np.linalg.norm(keep - before), np.linalg.norm(flip - before)
        lo, hi = min(dk, df), max(dk, df)
        pt = st.finds[0]
        where = f"{st.label}: the two assemblies of {pt} meet"
        if lo <= 1e-3 * scale and lo < 0.1 * hi:
            flipped = df < dk
            new = flipped_plan if flipped else plan
            what = ("the branch continuous in velocity is followed" +
                    (f" ({pt} passes to its other side)" if flipped else ""))
            # where the condition is below a few times the singular limit, the values are
            # taken from both sides instead (see richardson)
            probe = 0.01
            c1 = self._scout(plan, np.array([tc - direction * probe])).cond[st.index][0]
            c2 = self._scout(new, np.array([tc + direction * probe])).cond[st.index][0]
            slope = max(min(c1, c2) / probe, 1e-12)
            radius = min(max(_NEAR, 4 * TOL.singular / slope), 0.05)
            return new, ChangePoint(tc, st.label, pt, True, flipped, f"{where}; {what}",
                                    radius)
        why = (f"{where}, and both branches leave with the same velocity: which one the "
               "linkage takes cannot be told (a third, phase-shifted crank would decide it); "
               "the sweep stops here")
        return plan, ChangePoint(tc, st.label, pt, False, False, why)

    # ----- evaluating
    def segment_plans(self, t):
        """For mapped angles ``t``: the index of the segment each lies in."""
        segs = self.domain.segments
        if len(segs) == 1:
            return np.zeros(t.shape, dtype=np.intp)
        bounds = np.array([b for _, b, _ in segs[:-1]])
        return np.searchsorted(bounds, t, side="left")

    def evaluate(self, theta, *, vel=True, acc=True):
        """Evaluate at crank angles ``theta`` (rad, any turn; all reachable), one pass.

        Returns a :class:`Frame` in the order given.
        """
        theta = np.asarray(theta, dtype=float)
        dom = self.domain
        if len(dom.segments) == 1 and (dom.full_turn or (
                len(theta) and dom.lo <= theta.min() and theta.max() <= dom.hi)):
            return _run(dom.segments[0][2], theta, self.omega, self.alpha, vel, acc)
        t, _ = dom.map(theta)
        seg = self.segment_plans(t)
        first = int(seg[0]) if len(seg) else 0
        if len(seg) and (seg == first).all():
            return _run(dom.segments[first][2], t, self.omega, self.alpha, vel, acc)
        frames = {}
        for s in np.unique(seg):
            idx = np.nonzero(seg == s)[0]
            frames[int(s)] = (idx, _run(dom.segments[int(s)][2], t[idx], self.omega,
                                        self.alpha, vel, acc))
        return _merge(theta, frames)

    def near_change_points(self, theta):
        """[(indices, h)]: the angles closer to a followed change point than its radius,
        and the step to take either side of them (twice the radius)."""
        cps = [c for c in self.domain.change_points if c.followed]
        if not cps:
            return []
        t, _ = self.domain.map(theta)
        out = []
        for c in cps:
            d = np.abs(t - c.theta)
            if self.domain.full_turn:
                d = np.minimum(d, TWO_PI - d)
            idx = np.nonzero(d < c.radius)[0]
            if len(idx):
                out.append((idx, 2.0 * c.radius))
        return out

    def richardson(self, theta, h=2.5 * _NEAR):
        """Velocities and accelerations at angles next to a change point, where the
        construction is indeterminate, from both sides: f(t) = [15 m(h) - 6 m(2h) + m(3h)]
        / 10, m(h) the mean of f(t - h) and f(t + h) (error O(h^6))."""
        th = np.asarray(theta, dtype=float)
        fr = {s: self.evaluate(th + s * h) for s in (-3, -2, -1, 1, 2, 3)}
        base = self.evaluate(th)

        def comb(get):
            m = [(get(fr[-k]) + get(fr[k])) / 2 for k in (1, 2, 3)]
            return (15 * m[0] - 6 * m[1] + m[2]) / 10

        V = {k: (comb(lambda f: f.V[k][0]), comb(lambda f: f.V[k][1])) for k in base.V}
        A = {k: (comb(lambda f: f.A[k][0]), comb(lambda f: f.A[k][1])) for k in base.A}
        W = {k: comb(lambda f: f.W[k]) for k in base.W}
        Al = {k: comb(lambda f: f.Al[k]) for k in base.Al}
        S = {k: tuple(comb(lambda f, j=j: f.S[k][j]) for j in range(len(v)))
             for k, v in base.S.items()}
        return Frame(th, base.P, V, A, W, Al, S, base.cond, base.bad)


def _merge(theta, frames) -> Frame:
    n = len(theta)
    any_fr = next(iter(frames.values()))[1]

    def put(get):
        out = np.empty(n)
        for idx, fr in frames.values():
            out[idx] = get(fr)
        return out

    P = {k: (put(lambda f: f.P[k][0]), put(lambda f: f.P[k][1])) for k in any_fr.P}
    V = {k: (put(lambda f: f.V[k][0]), put(lambda f: f.V[k][1])) for k in any_fr.V}
    A = {k: (put(lambda f: f.A[k][0]), put(lambda f: f.A[k][1])) for k in any_fr.A}
    W = {k: put(lambda f: f.W[k]) for k in any_fr.W}
    Al = {k: put(lambda f: f.Al[k]) for k in any_fr.Al}
    S = {k: tuple(put(lambda f, j=j: f.S[k][j]) for j in range(len(v)))
         for k, v in any_fr.S.items()}
    cond = {i: put(lambda f: f.cond[i]) for i in any_fr.cond}
    bad = np.zeros(n, dtype=bool)
    for idx, fr in frames.values():
        bad[idx] = fr.bad
    return Frame(theta, P, V, A, W, Al, S, cond, bad)


# --------------------------------------------------------------------------- the result


@dataclass(frozen=True)
class SweepResult:
    """Every quantity of ``solve`` as an array over the crank angles the linkage reaches.

    ``theta`` holds the requested crank angles (rad, in the order asked) that the crank
    reaches on the scene's branch; the others are counted in ``left_out`` and explained by
    ``limits`` / ``change_points``. ``P, V, A``: point -> (x, y) arrays (m, m/s, m/s^2);
    ``W, Al``: link -> omega, alpha (rad/s, rad/s^2, ccw positive); ``S``: slider ->
    (vs, as, coriolis x, coriolis y); ``conditions``: step index -> condition measure;
    ``rubbing``: pin -> rubbing velocity (m/s); ``input_torque``: N m or None.
    """

    scene: Scene
    theta: np.ndarray
    P: dict
    V: dict
    A: dict
    W: dict
    Al: dict
    S: dict
    conditions: dict
    rubbing: dict
    input_torque: np.ndarray | None
    requested: int
    left_out: int
    domain: Domain = field(repr=False)
    notes: tuple = ()

    @property
    def limits(self) -> tuple:
        return self.domain.limits

    @property
    def change_points(self) -> tuple:
        return self.domain.change_points

    @property
    def degrees(self) -> np.ndarray:
        return np.degrees(self.theta)

    def __len__(self):
        return len(self.theta)

    def speed(self, point, relative_to=None):
        vx, vy = self.V[point]
        if relative_to is not None:
            ux, uy = self.V[relative_to]
            vx, vy = vx - ux, vy - uy
        return np.hypot(vx, vy)

    def acceleration_magnitude(self, point, relative_to=None):
        ax, ay = self.A[point]
        if relative_to is not None:
            bx, by = self.A[relative_to]
            ax, ay = ax - bx, ay - by
        return np.hypot(ax, ay)

    def omega(self, link):
        return self.W[self.scene.link(link).key]

    def alpha(self, link):
        return self.Al[self.scene.link(link).key]

    def sliding_velocity(self, point):
        return self.S[point][0]

    def sliding_acceleration(self, point):
        return self.S[point][1]

    def columns(self):
        """(name, unit, array) of every quantity, the CSV's columns in order."""
        sc = self.scene
        cols = [("theta", "deg", self.degrees)]
        for p in sc.point_names:
            (x, y), (vx, vy), (ax, ay) = self.P[p], self.V[p], self.A[p]
            cols += [(f"x_{p}", "m", x), (f"y_{p}", "m", y), (f"vx_{p}", "m/s", vx),
                     (f"vy_{p}", "m/s", vy), (f"ax_{p}", "m/s^2", ax),
                     (f"ay_{p}", "m/s^2", ay)]
        for lk in sc.links:
            cols += [(f"omega_{lk.key}", "rad/s", self.W[lk.key]),
                     (f"alpha_{lk.key}", "rad/s^2", self.Al[lk.key])]
        for s in sc.sliders:
            vs, a_s, cx, cy = self.S[s.point]
            cols += [(f"vs_{s.point}", "m/s", vs), (f"as_{s.point}", "m/s^2", a_s),
                     (f"acx_{s.point}", "m/s^2", cx), (f"acy_{s.point}", "m/s^2", cy)]
        for pin, r in self.rubbing.items():
            cols.append((f"rub_{pin}", "m/s", r))
        if self.input_torque is not None:
            cols.append(("torque", "N m", self.input_torque))
        for st in compile_plan(sc).steps:
            if st.branching:
                cols.append((f"condition_step{st.index + 1}", "1", self.conditions[st.index]))
        return cols

    def to_csv(self) -> str:
        """One row per crank angle; the header names each quantity with its unit."""
        cols = self.columns()
        buf = io.StringIO()
        buf.write(",".join(f"{n} [{u}]" for n, u, _ in cols) + "\n")
        if len(self.theta):
            data = np.column_stack([np.asarray(a, dtype=float) for _, _, a in cols])
            np.savetxt(buf, data, delimiter=",", fmt="%.10g")
        return buf.getvalue()

    def summary(self, **kw) -> "Summary":
        """Maxima and minima with the crank angles where they occur (see :func:`summarize`)."""
        red = _Reducer(self.scene, Sweeper(self.scene))
        red.add(_frame_of(self), np.arange(len(self.theta)))
        return red.finish(self.theta, self.requested, len(self.theta), **kw)


def _frame_of(res: SweepResult) -> Frame:
    return Frame(res.theta, res.P, res.V, res.A, res.W, res.Al, res.S, res.conditions,
                 np.zeros(len(res.theta), dtype=bool))


def _rubbing(plan, W, n):
    radii = plan.dims.radii
    return {point: np.broadcast_to(largest(values), (n,)) if values else np.zeros(n)
            for point, values in pin_rubbing(plan, W, radii).items()}


def _torque(scene, V, W, omega, n):
    t = input_torque(scene, V, W, omega)
    return None if t is None else np.broadcast_to(t, (n,)) + 0.0


def _angles_ok(sw: Sweeper, theta):
    """Mask of the requested angles the crank reaches on the scene's branch."""
    if sw.domain.full_turn and not sw.domain.limits:
        return None
    _, ok = sw.domain.map(theta)
    return ok


def _valid(fr: Frame, plan):
    """Angles where every step assembled and no step is singular."""
    bad = fr.bad.copy()
    for st in _branch_steps(plan):
        bad |= fr.cond[st.index] < TOL.singular
    return bad


def _evaluate_all(sw: Sweeper, theta, chunk):
    """Evaluate ``theta`` (all reachable) in chunks; yields (slice, Frame)."""
    n = len(theta)
    for s in range(0, n, chunk):
        th = theta[s:s + chunk]
        fr = sw.evaluate(th)
        for idx, h in sw.near_change_points(th):
            _patch(fr, sw.richardson(th[idx], h), idx)
        yield slice(s, min(s + chunk, n)), fr


def _patch(fr: Frame, fix: Frame, idx):
    def put(arr, new):
        if arr.flags.writeable:  # read-only: a constant (ground point, fixed link)
            arr[idx] = new

    for k in fr.V:
        for j in (0, 1):
            put(fr.V[k][j], fix.V[k][j])
            put(fr.A[k][j], fix.A[k][j])
    for k in fr.W:
        put(fr.W[k], fix.W[k])
        put(fr.Al[k], fix.Al[k])
    for k, v in fr.S.items():
        for j in range(len(v)):
            put(v[j], fix.S[k][j])
    fr.bad[idx] = False
    for i in fr.cond:  # the construction is indeterminate here; the values come from both sides
        if fr.cond[i].flags.writeable:
            fr.cond[i][idx] = np.maximum(fr.cond[i][idx], TOL.singular)


_MALLOC_TUNED = []


def _tune_malloc():
    """Keep freed chunk temporaries on the heap (glibc): otherwise every pass over a chunk
    maps and faults fresh pages, which costs several times the arithmetic."""
    if _MALLOC_TUNED:
        return
    _MALLOC_TUNED.append(True)
    try:
        import ctypes
        import sys
        if not sys.platform.startswith("linux"):
            return
        libc = ctypes.CDLL("libc.so.6")
        libc.mallopt(-1, 64 << 20)  # M_TRIM_THRESHOLD
        libc.mallopt(-3, 4 << 20)  # M_MMAP_THRESHOLD
    except (OSError, AttributeError):
        pass


def _angles(angles):
    if angles is None:
        return np.radians(np.arange(360.0))
    th = np.atleast_1d(np.asarray(angles, dtype=float))
    if th.ndim != 1:
        raise SceneError("the crank angles must be a 1-D sequence")
    if not np.isfinite(th).all():
        raise SceneError("the crank angles must be finite numbers")
    return th


def sweep(scene: Scene, angles=None, *, chunk: int = CHUNK) -> SweepResult:
    """Every quantity of ``solve`` at each crank angle in ``angles`` (rad; default every
    degree of a turn), in one pass per chunk of angles.

    Angles the crank cannot reach on the scene's branch (beyond a limit position) are left
    out and reported (``left_out``, ``limits``), never filled with NaN or another branch.
    """
    th_req = _angles(angles)
    sw = Sweeper(scene)
    plan = sw.plan
    ok = _angles_ok(sw, th_req)
    th = th_req if ok is None else th_req[ok]
    n = len(th)
    if n > chunk:
        _tune_malloc()
    fr = None
    store = None
    for sl, part in _evaluate_all(sw, th, chunk):
        if sl.start == 0 and sl.stop == n:
            fr = part
        else:  # copy chunk by chunk into one block, so that the chunks' memory is reused
            if store is None:
                store = _Store(th, part)
            store.put(sl, part)
    if store is not None:
        fr = store.frame()
    elif fr is None:
        fr = _run(plan, th, sw.omega, sw.alpha)
    bad = _valid(fr, plan)
    notes = list(sw.domain.notes)
    if bad.any():
        notes.append(f"{int(bad.sum())} crank angle(s) at a singular position (a toggle "
                     "where the velocity is indeterminate) were left out")
        fr = _select(fr, ~bad)
        th = th[~bad]
    n = len(th)
    rub = _rubbing(plan, fr.W, n)
    torque = _torque(scene, fr.V, fr.W, sw.omega, n)
    return SweepResult(scene, th, fr.P, fr.V, fr.A, fr.W, fr.Al, fr.S, fr.cond, rub, torque,
                       len(th_req), len(th_req) - n, sw.domain, tuple(notes))


class _Store:
    """One block of rows (one allocation) that chunk frames are copied into."""

    def __init__(self, theta, first: Frame):
        self.theta, self.first = theta, first
        keys = []
        for k in first.P:
            keys += [("P", k, 0), ("P", k, 1)]
        for k in first.V:
            keys += [("V", k, 0), ("V", k, 1), ("A", k, 0), ("A", k, 1)]
        keys += [("W", k, None) for k in first.W] + [("Al", k, None) for k in first.Al]
        for k, v in first.S.items():
            keys += [("S", k, j) for j in range(len(v))]
        keys += [("cond", i, None) for i in first.cond]
        self.keys = keys
        self.block = np.empty((len(keys), len(theta)))
        self.bad = np.zeros(len(theta), dtype=bool)

    def put(self, sl, fr: Frame):
        for r, (kind, k, j) in enumerate(self.keys):
            v = getattr(fr, kind)[k]
            self.block[r, sl] = v if j is None else v[j]
        self.bad[sl] = fr.bad

    def frame(self) -> Frame:
        rows = dict(zip(self.keys, self.block))
        f = self.first
        P = {k: (rows[("P", k, 0)], rows[("P", k, 1)]) for k in f.P}
        V = {k: (rows[("V", k, 0)], rows[("V", k, 1)]) for k in f.V}
        A = {k: (rows[("A", k, 0)], rows[("A", k, 1)]) for k in f.A}
        W = {k: rows[("W", k, None)] for k in f.W}
        Al = {k: rows[("Al", k, None)] for k in f.Al}
        S = {k: tuple(rows[("S", k, j)] for j in range(len(v))) for k, v in f.S.items()}
        cond = {i: rows[("cond", i, None)] for i in f.cond}
        return Frame(self.theta, P, V, A, W, Al, S, cond, self.bad)


def _select(fr: Frame, keep) -> Frame:
    two = lambda d: {k: (v[0][keep], v[1][keep]) for k, v in d.items()}  # noqa: E731
    return Frame(fr.theta[keep], two(fr.P), two(fr.V), two(fr.A),
                 {k: v[keep] for k, v in fr.W.items()}, {k: v[keep] for k, v in fr.Al.items()},
                 {k: tuple(a[keep] for a in v) for k, v in fr.S.items()},
                 {i: c[keep] for i, c in fr.cond.items()}, fr.bad[keep])


# --------------------------------------------------------------------------- summaries


@dataclass(frozen=True)
class Extreme:
    """The largest and smallest value of one quantity over the sweep, with the crank angles
    (deg) where they occur. ``at_max``/``at_min`` are None for a constant quantity."""

    name: str
    unit: str
    maximum: float
    at_max: float | None
    minimum: float
    at_min: float | None
    what: str = ""
    refined: bool = False

    @property
    def constant(self) -> bool:
        return self.at_max is None


@dataclass(frozen=True)
class Summary:
    """Extremes of every quantity, the reachable range and the notes of a sweep.

    Crank angles are in degrees: in [0, 360) when the crank turns fully, otherwise
    continuous across the reachable range (which may then run below 0 or above 360).
    """

    scene: Scene
    requested: int
    evaluated: int
    extremes: tuple
    limits: tuple
    change_points: tuple
    notes: tuple = ()
    formulas: tuple = ()  # lines comparing a textbook's approximate formula with the exact
    range_deg: tuple | None = None  # (lo, hi) where the crank cannot turn fully
    deg: object = field(default=math.degrees, repr=False, compare=False)  # rad -> shown deg

    def extreme(self, name) -> Extreme:
        """The entry of one quantity (``v_C``, ``omega_BC``, ``vs_B``, ``mu at C``...)."""
        for e in self.extremes:
            if e.name == name:
                return e
        raise KeyError(name)

    def text(self) -> str:
        sc = self.scene
        inp = sc.input
        out = [f"sweep of {sc.title or sc.file or 'the mechanism'}",
               f"crank {inp.crank} at {abs(inp.omega):.6g} rad/s "
               f"{'ccw' if inp.omega > 0 else 'cw'}"
               + (f", {inp.alpha:+.6g} rad/s^2" if inp.alpha else "")
               + f" at every angle; {self.evaluated} of {self.requested} crank angles "
               "evaluated"]
        deg = self.deg
        if self.limits and self.range_deg is not None:
            lo, hi = self.range_deg
            out.append(f"the crank cannot turn fully: it reaches {lo:.4f} to {hi:.4f} deg "
                       "on the scene's branch")
            for lp in self.limits:
                out.append(f"  limit position at {_fmt_deg(deg(lp.theta))} deg: {lp.step}: "
                           f"{lp.why}")
        if self.evaluated < self.requested:
            out.append(f"  {self.requested - self.evaluated} requested angle(s) are left out "
                       "(beyond the limit positions, or singular)")
        for cp in self.change_points:
            out.append(f"change point at crank angle {_fmt_deg(deg(cp.theta))} deg: {cp.why}")
        out.extend(self.notes)
        out.append("")
        if self.extremes:
            w = max(len(e.name) for e in self.extremes)
            out.append(f"{'quantity':<{w}}  {'unit':<7} {'maximum':>12} {'at (deg)':>10}"
                       f" {'minimum':>12} {'at (deg)':>10}")
            for e in self.extremes:
                if e.constant:
                    out.append(f"{e.name:<{w}}  {e.unit:<7} {e.maximum:>12.6g} "
                               f"{'(constant)':>10}")
                    continue
                out.append(f"{e.name:<{w}}  {e.unit:<7} {e.maximum:>12.6g} "
                           f"{_fmt_deg(e.at_max, 3):>10} {e.minimum:>12.6g} "
                           f"{_fmt_deg(e.at_min, 3):>10}"
                           + (f"  {e.what}" if e.what else ""))
        if self.formulas:
            out.append("")
            out.extend(self.formulas)
        return "\n".join(out)


def _fmt_deg(d, digits=4) -> str:
    s = f"{d:.{digits}f}"
    return s if s.strip("-0.") else f"{0.0:.{digits}f}"


def _degrees_fn(dom: Domain):
    """Radians in the domain -> the degrees shown: [0, 360) for a full turn, else continuous
    over the reachable range, shifted by whole turns so that it starts in [-180, 180)."""
    if dom.full_turn:
        def deg(t):
            d = math.degrees(t) % 360.0
            return 0.0 if d >= 360.0 - 5e-4 else d
        return deg
    shift = -360.0 * math.floor((math.degrees(dom.lo) + 180.0) / 360.0)

    def deg(t):
        (tm,), _ = dom.map(np.array([t]))
        return math.degrees(float(tm)) + shift
    return deg


class _Reducer:
    """Running maxima and minima over chunks (with the index where each occurs)."""

    def __init__(self, scene, sw: Sweeper):
        self.scene, self.sw = scene, sw
        self.plan = sw.plan
        self.best = {}  # name -> [max, imax, min, imin, unit, what]

    def quantities(self, fr: Frame):
        """(name, unit, array, what) of the quantities summarised."""
        sc, plan = self.scene, self.plan
        ground = set(sc.ground)
        for p in sc.point_names:
            if p in ground:
                continue
            yield f"v_{p}", "m/s", np.hypot(*fr.V[p]), "speed"
            yield f"a_{p}", "m/s^2", np.hypot(*fr.A[p]), "acceleration"
        for lk in sc.links:
            if lk.p in ground and lk.q in ground:
                continue
            yield f"omega_{lk.key}", "rad/s", fr.W[lk.key], "ccw +"
            yield f"alpha_{lk.key}", "rad/s^2", fr.Al[lk.key], "ccw +"
        for s in sc.sliders:
            vs, a_s, cx, cy = fr.S[s.point]
            if isinstance(s, FixedPath):
                (qx, qy), (ux, uy) = s.through, s.u
                x, y = fr.P[s.point]
                yield f"s_{s.point}", "m", (x - qx) * ux + (y - qy) * uy, "position on the path"
            yield f"vs_{s.point}", "m/s", vs, "sliding, signed"
            yield f"as_{s.point}", "m/s^2", a_s, "sliding, signed"
            if not isinstance(s, FixedPath):
                yield f"ac_{s.point}", "m/s^2", np.hypot(cx, cy), "Coriolis"
        if getattr(plan, "pins", ()):
            for pin, r in _rubbing(plan, fr.W, fr.n).items():
                yield f"rub_{pin}", "m/s", r, "rubbing"
        t = _torque(sc, fr.V, fr.W, self.sw.omega, fr.n)
        if t is not None:
            yield "torque", "N m", t, "input torque, ccw +"
        for st in _branch_steps(plan):
            name, unit, words = st.condition_column()  # "deg": the sine, shown as the angle
            yield name, unit, fr.cond[st.index], words

    @staticmethod
    def shown(unit, value):
        """A reduced value as shown: the transmission angle from its sine."""
        if unit == "deg":
            return math.degrees(math.asin(min(max(value, -1.0), 1.0)))
        return value

    def add(self, fr: Frame, index):
        for name, unit, arr, what in self.quantities(fr):
            if not len(arr):
                continue
            i, j = int(np.argmax(arr)), int(np.argmin(arr))
            b = self.best.get(name)
            if b is None:
                self.best[name] = [float(arr[i]), int(index[i]), float(arr[j]), int(index[j]),
                                   unit, what]
                continue
            if arr[i] > b[0]:
                b[0], b[1] = float(arr[i]), int(index[i])
            if arr[j] < b[2]:
                b[2], b[3] = float(arr[j]), int(index[j])

    def _refine(self, tasks, passes):
        """Zoom on sampled extremes, all at once: 17 points across each bracket a pass.
        ``tasks``: [name, sense, a, b, best value, best angle]; updated in place."""
        sw = self.sw
        for _ in range(passes):
            live = [t for t in tasks if t[2] < t[3]]
            if not live:
                return
            pts = np.concatenate([np.linspace(t[2], t[3], 17) for t in live])
            ok = _angles_ok(sw, pts)
            fr = sw.evaluate(pts)
            invalid = _valid(fr, self.plan)
            if ok is not None:
                invalid |= ~ok
            q = {nm: arr for nm, _, arr, _ in self.quantities(fr)}
            for k, t in enumerate(live):
                name, sense = t[0], t[1]
                sl = slice(17 * k, 17 * k + 17)
                vals = np.where(invalid[sl], -np.inf, q[name][sl] * sense)
                j = int(np.argmax(vals))
                if not np.isfinite(vals[j]):
                    t[3] = t[2]  # give up on this one
                    continue
                if vals[j] * sense * sense >= t[4] * sense:
                    t[4], t[5] = float(vals[j] * sense), float(pts[sl][j])
                p = pts[sl]
                t[2], t[3] = p[max(j - 1, 0)], p[min(j + 1, 16)]

    def finish(self, theta, requested, evaluated, *, refine=True):
        sw = self.sw
        dom = sw.domain
        n = len(theta)
        spacing = None
        if n > 2:
            step = np.abs(np.diff(theta[:10001]))
            spacing = float(np.median(step))
        cps = [c.theta for c in dom.change_points]
        tasks, rows = [], []
        scales = self._scales()
        for name, (mx, imx, mn, imn, unit, what) in self.best.items():
            zero = 1e-9 * scales.get(unit, 0.0)  # rounding about a true zero
            mx, mn = (0.0 if abs(mx) <= zero else mx), (0.0 if abs(mn) <= zero else mn)
            scale = max(abs(mx), abs(mn))
            if n > 1 and (mx - mn <= 1e-10 * scale or scale == 0.0):
                rows.append([name, unit, mx, None, mn, None, what])
                continue
            row = [name, unit, mx, float(theta[imx]), mn, float(theta[imn]), what]
            rows.append(row)
            if not (refine and spacing and spacing > 1e-12):
                continue
            for sense, i in ((1.0, imx), (-1.0, imn)):
                if not _interior(theta, i, spacing):
                    continue
                t = float(theta[i])
                a, b = t - spacing, t + spacing
                (tm,), _ = dom.map(np.array([t]))
                if any(abs(tc - tm) < 2 * spacing + 0.02 for tc in cps):
                    continue  # values next to a change point are not refined
                tasks.append([name, sense, a, b, row[2] if sense > 0 else row[4], t, row])
        if tasks:
            passes = max(1, min(12, math.ceil(math.log(2 * spacing / 1e-11, 8))))
            self._refine(tasks, passes)
            for name, sense, _, _, val, t, row in tasks:
                if sense > 0:
                    row[2], row[3] = val, t
                else:
                    row[4], row[5] = val, t
        deg = _degrees_fn(dom)
        extremes = tuple(Extreme(nm, u, self.shown(u, mx), None if tmx is None else deg(tmx),
                                 self.shown(u, mn), None if tmn is None else deg(tmn), what,
                                 bool(tasks))
                         for nm, u, mx, tmx, mn, tmn, what in rows)
        formulas = ()
        try:
            from .linkage import engine_formula_lines
            formulas = tuple(engine_formula_lines(self.scene, {e.name: e for e in extremes}))
        except ImportError:
            formulas = ()
        rng = None
        if not dom.full_turn:
            rng = (deg(dom.lo), deg(dom.lo) + math.degrees(dom.hi - dom.lo))
        return Summary(self.scene, requested, evaluated, extremes, dom.limits,
                       dom.change_points, tuple(dom.notes), formulas, rng, deg)

    def _scales(self) -> dict:
        """Typical sizes per unit, below a 1e-9 part of which a value is zero (rounding)."""
        sc = self.scene
        w = abs(self.sw.omega)
        k = w * w + abs(self.sw.alpha)
        lengths = [lk.length for lk in sc.links] + [math.hypot(*xy) for xy in
                                                    sc.ground.values()]
        L = max(lengths) if lengths else 1.0
        return {"rad/s": w, "rad/s^2": k, "m/s": w * L, "m/s^2": k * L, "m": L}


def _interior(theta, i, spacing) -> bool:
    """Whether sample i has neighbours (in the order asked, the ends joined) about
    ``spacing`` away on both sides, so that the extreme found there is a local one and not
    the end of the requested range."""
    n = len(theta)
    if n < 3:
        return False
    t = theta[i]
    d = [(theta[(i + k) % n] - t + math.pi) % TWO_PI - math.pi for k in (-1, 1)]
    return (abs(d[0]) <= 1.5 * spacing and abs(d[1]) <= 1.5 * spacing and d[0] * d[1] < 0)


def summarize(scene: Scene, angles=None, *, chunk: int = CHUNK, refine: bool = True) -> Summary:
    """Maxima and minima of every quantity over ``angles`` (rad; default every degree),
    reduced chunk by chunk: memory stays that of one chunk whatever the number of angles.
    Each extreme found between samples is then refined by zooming in on it."""
    th_req = _angles(angles)
    sw = Sweeper(scene)
    ok = _angles_ok(sw, th_req)
    th = th_req if ok is None else th_req[ok]
    if len(th) > chunk:
        _tune_malloc()
    red = _Reducer(scene, sw)
    n_valid = 0
    for sl, fr in _evaluate_all(sw, th, chunk):
        bad = _valid(fr, sw.plan)
        index = np.arange(sl.start, sl.stop)
        if bad.any():
            fr = _select(fr, ~bad)
            index = index[~bad]
        n_valid += len(index)
        red.add(fr, index)
    return red.finish(th, len(th_req), n_valid, refine=refine)


# --------------------------------------------------------------------------- command line


def _requested_angles(args):
    """Crank angles (rad) from ``--steps N`` or ``--from A --to B --step S`` (deg)."""
    ranged = any(v is not None for v in (args.start, args.stop, args.step))
    if args.steps is not None and ranged:
        raise SceneError("give either --steps N or --from A --to B --step S, not both")
    if ranged:
        if args.start is None or args.stop is None or args.step is None:
            raise SceneError("--from, --to and --step go together (degrees)")
        a, b, s = args.start, args.stop, args.step
        if not all(math.isfinite(v) for v in (a, b, s)):
            raise SceneError("--from, --to and --step must be finite numbers")
        if s == 0 or (b - a) * s < 0:
            raise SceneError(f"--step {s:g} does not lead from {a:g} to {b:g} deg")
        count = int(math.floor((b - a) / s + 1e-9)) + 1
        if count > 100_000_000:
            raise SceneError(f"{count} crank angles are too many (at most 10^8)")
        return np.radians(a + s * np.arange(count))
    n = 360 if args.steps is None else args.steps
    if n < 1:
        raise SceneError(f"--steps must be at least 1, got {n}")
    if n > 100_000_000:
        raise SceneError(f"--steps {n} is too many (at most 10^8)")
    return np.linspace(0.0, TWO_PI, n, endpoint=False)


def run_sweep(args, write) -> int:
    """``polygon-method sweep SCENE [--steps N | --from A --to B --step S] [--csv FILE]
    [--plot FILE.svg] [--summary]``: print the summary; the CSV and the plot are written by
    ``write(path, data, binary=...)``, the command line's (whole or not at all)."""
    from .scene import load_scene

    plot = getattr(args, "plot", None)
    if plot and not plot.lower().endswith((".svg", ".png", ".pdf")):
        raise SceneError(f"--plot {plot}: the file must end in .svg, .png or .pdf")
    scene = load_scene(args.scene)
    angles = _requested_angles(args)
    want_summary = args.summary or not (args.csv or plot)
    if not (args.csv or plot):
        print(summarize(scene, angles).text())
        return 0
    res = sweep(scene, angles)
    if not len(res):
        raise PolygonMethodError("none of the requested crank angles can be reached "
                                 "on the scene's branch " + _limits_text(res.domain),
                                 file=scene.file)
    outputs = []
    if args.csv:
        outputs.append((args.csv, res.to_csv(), False))
    if plot:
        outputs.append((plot, plot_bytes(res, plot, points=_names(args, "points"),
                                         links=_names(args, "links")), True))
    for path, data, binary in outputs:
        write(path, data, binary=binary)
    if want_summary:
        print(res.summary().text())
    else:
        print(f"{len(res)} of {res.requested} crank angles evaluated"
              + (f"; {_limits_text(res.domain)}" if res.domain.limits else ""))
    return 0


def _names(args, what):
    raw = getattr(args, what, None)
    if not raw:
        return None
    return tuple(x.strip() for x in raw.split(",") if x.strip())


def _limits_text(dom: Domain) -> str:
    if not dom.limits:
        return ""
    return ("(limit positions at " + " and ".join(f"{lp.degrees:.4f} deg" for lp in dom.limits)
            + ")")


# --------------------------------------------------------------------------- plots


def plot_bytes(res: SweepResult, path: str, *, points=None, links=None) -> bytes:
    """Velocities and accelerations of ``points`` and omega, alpha of ``links`` against the
    crank angle, with the scene's own instant marked (matplotlib, imported here only)."""
    import matplotlib
    matplotlib.use("Agg")
    from matplotlib.figure import Figure

    sc = res.scene
    ground = set(sc.ground)
    pts = points or tuple(p for p in sc.point_names if p not in ground)
    for p in pts:
        if p not in res.P:
            raise SceneError(f"--points: no point {p} in the scene", file=sc.file)
    keys = []
    for name in links or [lk.key for lk in sc.links
                          if not (lk.p in ground and lk.q in ground)]:
        if not sc.has_link(name):
            raise SceneError(f"--links: no link {name} in [links]", file=sc.file)
        keys.append(sc.link(name).key)
    dom = res.domain
    if dom.full_turn:
        deg = res.degrees
        t0 = math.degrees(sc.input.angle)
    else:  # continuous over the reachable range
        show = _degrees_fn(dom)
        shift = show(dom.lo) - math.degrees(dom.lo)
        deg = np.degrees(dom.map(res.theta)[0]) + shift
        t0 = math.degrees(float(dom.map(np.array([sc.input.angle]))[0][0])) + shift
    order = np.argsort(deg, kind="stable") if np.any(np.diff(deg) < 0) else slice(None)
    x = deg[order]
    if dom.full_turn and len(x):  # the scene's angle, shown in the plotted range
        k = math.floor((x.min() - t0) / 360.0 + 1.0)
        t0 = t0 + 360.0 * k if t0 + 360.0 * k <= x.max() + 1e-9 else t0 + 360.0 * (k - 1)
    gaps = np.nonzero(np.diff(x) > 1.5 * np.median(np.diff(x)))[0] + 1 if len(x) > 2 else []
    x = np.insert(x, gaps, np.nan)  # no line across angles left out
    here = _scene_values(sc)
    fig = Figure(figsize=(10, 7.5), layout="constrained")
    axes = fig.subplots(2, 2, sharex=True)
    panels = [
        (axes[0][0], "velocity (m/s)", [(f"v_{p}", res.speed(p), here.get(f"v_{p}"))
                                        for p in pts]
         + [(f"vs_{s.point}", res.S[s.point][0], here.get(f"vs_{s.point}"))
            for s in sc.sliders]),
        (axes[1][0], "acceleration (m/s^2)",
         [(f"a_{p}", res.acceleration_magnitude(p), here.get(f"a_{p}")) for p in pts]),
        (axes[0][1], "angular velocity (rad/s, ccw +)",
         [(f"omega_{k}", res.W[k], here.get(f"omega_{k}")) for k in keys]),
        (axes[1][1], "angular acceleration (rad/s^2, ccw +)",
         [(f"alpha_{k}", res.Al[k], here.get(f"alpha_{k}")) for k in keys]),
    ]
    clipped = False
    w, k = abs(sc.input.omega), sc.input.omega ** 2 + abs(sc.input.alpha)
    size = max([lk.length for lk in sc.links] + [1e-3])
    scales = [w * size, k * size, w, k]
    for (ax, label, series), unit_scale in zip(panels, scales):
        big = []
        for name, y, y0 in series:
            yy = np.insert(np.asarray(y, dtype=float)[order], gaps, np.nan)
            line, = ax.plot(x, yy, lw=1.2, label=name)
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
            if hi - lo <= 1e-6 * size or size < 1e-8 * unit_scale:
                pad = 0.1 * size if size >= 1e-8 * unit_scale else 1.0
                ax.set_ylim(0.5 * (lo + hi) - pad, 0.5 * (lo + hi) + pad)
        ax.axvline(t0, color="0.3", ls="--", lw=0.8)
        show = _degrees_fn(dom)
        for lp in res.limits:
            ax.axvline(show(lp.theta), color="tab:red", ls=":", lw=0.8)
        for cp in res.change_points:
            ax.axvline(show(cp.theta), color="tab:purple", ls="-.", lw=0.8)
        ax.set_ylabel(label)
        ax.grid(True, lw=0.3)
        if series:
            ax.legend(fontsize=7, ncol=2)
    for ax in axes[1]:
        ax.set_xlabel("crank angle (deg)")
    title = sc.title or sc.file or "mechanism"
    fig.suptitle(f"{title}: crank {sc.input.crank}, dashed: the scene's instant "
                 f"({math.degrees(sc.input.angle):g} deg)"
                 + ("; dotted red: limit positions" if res.limits else "")
                 + ("; dash-dot: change points" if res.change_points else "")
                 + ("\n(the vertical scale is cut: values grow without bound near the "
                    "limit positions)" if clipped else ""), fontsize=10)
    buf = io.BytesIO()
    fmt = path.rsplit(".", 1)[-1].lower()
    fig.savefig(buf, format=fmt, **({"metadata": {"Date": None}} if fmt == "svg" else {}))
    return buf.getvalue()


def _scene_values(scene) -> dict:
    """The scene's own instant (the marked points), or nothing where it is singular."""
    from .solution import solve
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
        out[f"vs_{s.point}"] = sol.S[s.point][0]
    return out
