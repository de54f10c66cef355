"""Following the scene's assembly branch over the crank's turn.

The same plan that :func:`~polygon_method.motion.solution.solve` runs for one instant is run
with ``Context(theta_array, omega, alpha, array=True)``: every step's formulas are plain
arithmetic, so one pass over a chunk of crank angles gives every position, velocity and
acceleration for all of them (a :class:`~polygon_method.solver.kinematics.Motion` of arrays).

The assembly branch is the scene's own, followed continuously from the scene's instant
(the crank speed and acceleration are the scene's at every angle):

* where the crank cannot turn fully (a non-Grashof input, or a dyad that stops
  assembling) the motion stops at the limit positions, where the discriminant of the
  failing step vanishes (:class:`LimitPosition`); angles beyond are left out, never filled
  with NaN or with the other branch;
* at a change point (the two assemblies of a step meet, as in a parallelogram with all
  its pivots in line) it follows the branch that is continuous in velocity and says so
  (:class:`ChangePoint`); if the two branches leave with the same velocity it stops there.

:class:`Sweeper` finds the :class:`Domain` once per plan and evaluates any crank angles on
it.
"""

from __future__ import annotations

import math
import weakref
from dataclasses import replace

import numpy as np

from ..common.errors import TOL, SceneError, SingularStepError
from ..common.tolerances import BESIDE_CHANGE, CHANGE_POINT, FLOOR, ROUNDING, SAME, ZERO_RESOLVED
from .compiler import compile_plan
from .plan import Context
from .domain import NEAR, TWO_PI, ChangePoint, Domain, LimitPosition, degrees_fn, fmt_deg
from .runs import array_motion, branch_steps, merge, run_arrays, tune_malloc, valid_mask
from ..scene import Scene

__all__ = [
    "Sweeper",
    "Domain",
    "LimitPosition",
    "ChangePoint",
    "run_arrays",
    "merge",
    "valid_mask",
    "degrees_fn",
    "fmt_deg",
    "tune_malloc",
    "TWO_PI",
    "CHUNK",
    "NEAR",
    "MAX_CYCLE_POINTS",
    "array_motion",
    "branch_steps",
]

#: crank angles evaluated per pass (about 32k: the temporaries of one pass stay in cache)
CHUNK = 32768
#: scouting grid for limit positions and change points, per turn of the crank
SCOUT = 4096
#: a step whose condition falls below this (and rises again) is checked for a change point
_CANDIDATE = 0.2
#: ... and is a change point where its refined minimum is below this
_CHANGE = CHANGE_POINT
#: the most points whose motion over the crank's cycle is followed (a sweep's summary of
#: 1000 takes about 10 s)
MAX_CYCLE_POINTS = 1000
#: a reachable range narrower than this (rad) is a locked linkage, not a motion
_LOCKED = 1e-5
#: the words a note opens with where a turn of the crank does not bring the mechanism back
_NOT_AGAIN = "after a full turn of the crank the mechanism is not where it started"
#: offset either side of a change point when comparing the branches' velocities (rad; for
#: a driving block, times the length that plays a radian's part: ``Step.parameter_scale``,
#: as for every offset below)
_DELTA = BESIDE_CHANGE
#: where the condition is measured either side of a change point, for its slope (rad)
_PROBE = 0.01
#: the widest a change point's neighbourhood is made (rad)
_WIDEST = 0.05


#: the domain of each plan (a plan is one scene's content), found once
_DOMAINS = weakref.WeakKeyDictionary()


def _variant(plan, flips):
    """The plan with the branch (sigma) of the steps in ``flips`` reversed."""
    if not flips:
        return plan
    steps = tuple(replace(s, sigma=-s.sigma) if s.index in flips else s for s in plan.steps)
    kw = {"steps": steps}
    if "_compiled" in getattr(plan, "__dataclass_fields__", {}):
        kw["_compiled"] = {}  # a new kernel for the new branches
    return replace(plan, **kw)


class Sweeper:
    """Evaluates a scene's plan at any crank angles, on the assembly branch continuous with
    the scene's instant (see :class:`Domain`). The domain is found once per scene."""

    def __init__(self, scene: Scene):
        self.scene = scene
        n = len(scene.point_names)
        if n > MAX_CYCLE_POINTS:  # every angle evaluates every point, and extremes are
            raise SceneError(  # refined for each: minutes for thousands
                f"the scene has {n} points: the crank's cycle (sweep, linkage, page, "
                f"--animate) is followed for at most {MAX_CYCLE_POINTS}; solve and steps "
                "take more",
                file=scene.file,
            )
        self.plan = compile_plan(scene)
        inp = scene.input
        self.theta0, self.omega, self.alpha = inp.angle, inp.omega, inp.alpha
        self.driver = self.plan.steps[0]
        #: how much of the parameter plays a radian's part (1 for a crank; for a driving
        #: block, a length along its guide): the offsets near a change point scale with it
        self.scale = self.driver.parameter_scale(scene)
        #: the parameter's scouting span: a turn of a crank; a block's guide as far as the
        #: links reach either side of its place (a length)
        self.period = TWO_PI if self.driver.periodic else _block_span(scene, self.driver)
        dom = _DOMAINS.get(self.plan)
        if dom is None:
            dom = _DOMAINS[self.plan] = self._explore() if self.driver.periodic else self._stroke()
        self.domain = dom
        if not dom.periodic and dom.hi - dom.lo < _LOCKED * self.period / TWO_PI:
            lp = dom.limits[0] if dom.limits else None
            u = scene.length_unit
            raise SingularStepError(
                f"the block {self.driver.finds[0]} can move only {(dom.hi - dom.lo) / u:.2g} "
                f"{scene.units} from its place in the scene: the linkage is locked there"
                + (f" ({lp.why})" if lp else ""),
                step=lp.step if lp else None,
                file=scene.file,
            )
        if dom.periodic and not dom.full_turn and dom.hi - dom.lo < _LOCKED:
            lp = dom.limits[0] if dom.limits else None
            raise SingularStepError(
                f"the crank can move only {math.degrees(dom.hi - dom.lo):.2g} deg from its "
                f"angle in the scene: the linkage is locked there" + (f" ({lp.why})" if lp else ""),
                step=lp.step if lp else None,
                file=scene.file,
            )

    def stated_branch(self) -> None:
        """Raise as :func:`~polygon_method.motion.solution.solve` does where the scene's own instant
        is singular (a toggle or a change point, where both assemblies meet): the branch the
        scene states cannot be told there, so a sweep of values does not start from it."""
        self.plan.run(Context(self.theta0, self.omega, self.alpha), upto=0)

    # ----- exploring the branch
    def _scout(self, plan, grid):
        return run_arrays(plan, grid, self.omega, self.alpha, vel=False, acc=False)

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
                notes.append(
                    "after a full turn of the crank the linkage is on its other "
                    "branch: the motion repeats only every two turns; the sweep "
                    "shows the turn centred on the scene's instant"
                )
            limits = tuple(x for x in (llim,) if x is not None)
            if not notes and full:
                turns = self._turns(rsegs[-1][2], t0)
                wide = self._several_turns(turns) if turns is not None and turns > 1 else None
                if wide is not None:  # the whole period: every turn until it repeats
                    return wide
                notes += self._repeats(turns, t0)
        else:
            lsegs, lcps, llim = self._walk(-1, TWO_PI - (rlim.theta - t0))
            lo = llim.theta if llim is not None else rlim.theta - TWO_PI
            hi, full, notes = rlim.theta, False, []
            limits = tuple(x for x in (llim, rlim) if x is not None)
        segs = self._joined([(b, a, p) for a, b, p in reversed(lsegs)] + list(rsegs))
        cps = tuple(sorted(lcps + rcps, key=lambda c: c.theta))
        return Domain(
            lo,
            hi,
            full,
            tuple(segs),
            limits,
            cps,
            tuple(notes),
            turn_only=bool(notes) and full and notes[-1].startswith(_NOT_AGAIN),
        )

    def _joined(self, segs):
        """Neighbouring segments on the same branches joined into one."""
        merged = []
        for a, b, p in segs:
            if merged and self._flips(merged[-1][2]) == self._flips(p):
                merged[-1] = (merged[-1][0], b, merged[-1][2])
            elif b > a or not merged:
                merged.append((a, b, p))
        return [(a, b, p) for a, b, p in merged if b > a] or merged[:1]

    def _turns(self, plan, t0):
        """After how many turns of the crank the mechanism is where it started: 1, up to
        12 (a wheel turning 2.5 times per turn of its arm: 2), or None (not within 12)."""
        k = np.arange(13.0)
        fr = run_arrays(plan, t0 + TWO_PI * k, self.omega, self.alpha, vel=False, acc=False)
        size = max((lk.length for lk in self.scene.links), default=1.0)
        xy = np.array(
            [
                c
                for p in fr.P.values()
                for c in (np.broadcast_to(p[0], k.shape), np.broadcast_to(p[1], k.shape))
            ]
        )
        same = np.all(np.abs(xy - xy[:, :1]) <= SAME * size, axis=0)
        return next((int(i) for i in range(1, 13) if same[i]), None)

    def _several_turns(self, n):
        """The domain of a motion that repeats every ``n`` turns of the crank: the ``n``
        turns centred on the scene's instant, followed on its branch (None where it stops
        assembling within them: then the one turn is shown, as before)."""
        t0, half = self.theta0, n * math.pi
        rsegs, rcps, rlim = self._walk(+1, half)
        lsegs, lcps, llim = self._walk(-1, half)
        if rlim is not None or llim is not None:
            return None
        segs = self._joined([(b, a, p) for a, b, p in reversed(lsegs)] + list(rsegs))
        cps = tuple(sorted(lcps + rcps, key=lambda c: c.theta))
        lo, hi = math.degrees(t0 - half), math.degrees(t0 + half)
        note = (
            f"{_NOT_AGAIN}: the motion repeats every {n} turns ({self._why_not_again()}); "
            "the sweep, its ranges and extremes "
            f"and the page take the whole period, {n} turns of the crank from {lo:.6g} to "
            f"{hi:.6g} deg (centred on the scene's instant), angles written within it "
            f"(0 to {360 * n} deg)"
        )
        return Domain(t0 - half, t0 + half, True, tuple(segs), (), cps, (note,), turns=n)

    def _why_not_again(self) -> str:
        """Why a turn of the crank does not bring the mechanism back, in words."""
        if self.scene.rolling:
            return "a wheel turns a fraction of a turn more per turn of the crank"
        return "the second input moves on at its own rate, not back with the crank"

    def _repeats(self, n, t0) -> list:
        """[] where the mechanism is where it started after a turn of the crank; else the
        note saying after how many turns it is, or that it is not within 12, and that the
        turn shown is the one centred on the scene's instant."""
        if n == 1:
            return []
        when = f"only every {n} turns" if n is not None else "not within 12 turns"
        lo, hi = math.degrees(t0 - math.pi), math.degrees(t0 + math.pi)
        return [
            f"{_NOT_AGAIN}: the motion repeats {when} ({self._why_not_again()}); "
            "ranges and extremes are over the turn "
            f"centred on the scene's instant, the crank from {lo:.6g} to {hi:.6g} deg"
        ]

    def _stroke(self) -> Domain:
        """The places a driving block reaches from the scene's on its branch: its stated
        stroke, cut short where the mechanism stops assembling; without a stroke, the
        first and last places that assemble, which must lie within the links' reach."""
        sc, t0 = self.scene, self.theta0
        stroke = sc.input.stroke
        ends, segs, cps, limits = [], [], [], []
        for direction in (-1, +1):
            end = None if stroke is None else stroke[(direction + 1) // 2]
            budget = self.period if end is None else abs(end - t0)
            wsegs, wcps, lim = self._walk(direction, budget)
            if lim is None and end is None:
                raise SceneError(
                    f"the block {self.driver.finds[0]} can travel {('back', 'on')[(direction + 1) // 2]} from its place "
                    f"without limit (nothing in the mechanism stops it within "
                    f"{self.period / sc.length_unit:.6g} {sc.units}): state its stroke, "
                    "[input] stroke = [from, to]",
                    file=sc.file,
                    key="[input] stroke",
                )
            if lim is None:
                lim = LimitPosition(end, self.driver.label, self.driver.limit_why())
            limits.append(lim)
            ends.append(lim.theta)
            cps += wcps
            segs += [(b, a, p) for a, b, p in reversed(wsegs)] if direction < 0 else wsegs
        merged = []
        for a, b, p in segs:
            if merged and self._flips(merged[-1][2]) == self._flips(p):
                merged[-1] = (merged[-1][0], b, merged[-1][2])
            elif b > a or not merged:
                merged.append((a, b, p))
        segs = [(a, b, p) for a, b, p in merged if b > a] or merged[:1]
        cps = tuple(sorted(cps, key=lambda c: c.theta))
        return Domain(
            ends[0], ends[1], False, tuple(segs), tuple(limits), cps, (), False, sc.length_unit
        )

    def _flips(self, plan):
        return tuple(s.sigma for s in plan.steps if hasattr(s, "sigma"))

    def _walk(self, direction, budget):
        """Turn the crank from the scene's angle in ``direction`` for up to ``budget`` rad;
        returns the segments passed (in walking order, as ``(from, to, plan)``), the change
        points met and the limit position where it stopped (or None)."""
        plan, start, done = self.plan, self.theta0, 0.0
        segs, cps = [], []
        while budget - done > ROUNDING * self.scale:
            left = budget - done
            n = max(65, int(SCOUT * left / self.period) + 2)
            grid = start + direction * np.linspace(0.0, left, n)
            fr = self._scout(plan, grid)
            last = next(st for st in reversed(self.plan.steps) if st.finds)
            fail = fr.bad | ~np.isfinite(fr.P[last.finds[0]][0])
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
                if not cp.followed:  # its words without the step, as a limit's why is
                    why = cp.why.removeprefix(f"{st.label}: ")
                    return segs, cps, LimitPosition(tc, st.label, why)
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
            if abs(bad - good) < ZERO_RESOLVED * self.scale:
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
        for st in branch_steps(plan):
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
        fr = run_arrays(plan, np.array([theta]), self.omega, self.alpha, acc=False)
        parts = [v for xy in fr.V.values() for v in xy] + list(fr.W.values())
        return np.array([float(p[0]) for p in parts])

    def _decide(self, plan, st, tc, direction):
        """At a change point: keep the branch or flip ``st``'s, whichever leaves with the
        velocity the linkage arrives with."""
        k = self.scale  # a radian, or the length along its guide a driving block takes for one
        before = self._velocity_vector(plan, tc - direction * _DELTA * k)
        keep = self._velocity_vector(plan, tc + direction * _DELTA * k)
        flipped_plan = _variant(plan, {st.index})
        flip = self._velocity_vector(flipped_plan, tc + direction * _DELTA * k)
        scale = np.linalg.norm(before) + FLOOR
        dk, df = np.linalg.norm(keep - before), np.linalg.norm(flip - before)
        lo, hi = min(dk, df), max(dk, df)
        pt = st.finds[0]
        where = f"{st.label}: the two assemblies of {pt} meet"
        if lo <= 1e-3 * scale and lo < 0.1 * hi:
            flipped = df < dk
            new = flipped_plan if flipped else plan
            what = "the branch continuous in velocity is followed" + (
                f" ({pt} passes to its other side)" if flipped else ""
            )
            # where the condition is below a few times the singular limit, the values are
            # taken from both sides instead (see richardson)
            probe = _PROBE * k
            c1 = self._scout(plan, np.array([tc - direction * probe])).cond[st.index][0]
            c2 = self._scout(new, np.array([tc + direction * probe])).cond[st.index][0]
            slope = max(min(c1, c2) / probe, ROUNDING / k)  # a slope of rounding: none
            radius = min(max(NEAR * k, 4 * TOL.singular / slope), _WIDEST * k)
            return new, ChangePoint(tc, st.label, pt, True, flipped, f"{where}; {what}", radius)
        why = (
            f"{where}, and both branches leave with the same velocity: which one the "
            "linkage takes cannot be told (a third, phase-shifted crank would decide it); "
            "the sweep stops here"
        )
        return plan, ChangePoint(tc, st.label, pt, False, False, why, NEAR * k)

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
        if len(dom.segments) == 1 and (
            (dom.full_turn and not dom.turn_only)
            or (len(theta) and dom.lo <= theta.min() and theta.max() <= dom.hi)
        ):
            return run_arrays(dom.segments[0][2], theta, self.omega, self.alpha, vel, acc)
        t, _ = dom.map(theta)
        seg = self.segment_plans(t)
        first = int(seg[0]) if len(seg) else 0
        if len(seg) and (seg == first).all():
            return run_arrays(dom.segments[first][2], t, self.omega, self.alpha, vel, acc)
        frames = {}
        for s in np.unique(seg):
            idx = np.nonzero(seg == s)[0]
            frames[int(s)] = (
                idx,
                run_arrays(dom.segments[int(s)][2], t[idx], self.omega, self.alpha, vel, acc),
            )
        return merge(theta, frames)

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
                d = np.minimum(d, self.domain.period - d)
            idx = np.nonzero(d < c.radius)[0]
            if len(idx):
                out.append((idx, 2.0 * c.radius))
        return out

    def richardson(self, theta, h=None):
        """Positions, velocities and accelerations at angles next to a change point, where
        the construction is indeterminate, from both sides: f(t) = [15 m(h) - 6 m(2h) + m(3h)]
        / 10, m(h) the mean of f(t - h) and f(t + h) (error O(h^6)); ``h`` by default
        2.5 times the neighbourhood's least radius (in the driver's scale)."""
        if h is None:
            h = 2.5 * NEAR * self.scale
        th = np.asarray(theta, dtype=float)
        fr = {s: self.evaluate(th + s * h) for s in (-3, -2, -1, 1, 2, 3)}
        base = self.evaluate(th)

        def comb(get):
            m = [(get(fr[-k]) + get(fr[k])) / 2 for k in (1, 2, 3)]
            return (15 * m[0] - 6 * m[1] + m[2]) / 10

        P = {k: (comb(lambda f: f.P[k][0]), comb(lambda f: f.P[k][1])) for k in base.P}
        V = {k: (comb(lambda f: f.V[k][0]), comb(lambda f: f.V[k][1])) for k in base.V}
        A = {k: (comb(lambda f: f.A[k][0]), comb(lambda f: f.A[k][1])) for k in base.A}
        W = {k: comb(lambda f: f.W[k]) for k in base.W}
        Al = {k: comb(lambda f: f.Al[k]) for k in base.Al}
        S = {
            k: tuple(comb(lambda f, j=j: f.S[k][j]) for j in range(len(v)))
            for k, v in base.S.items()
        }
        return array_motion(th, P, V, A, W, Al, S, base.cond, base.bad)


def _block_span(scene, driver) -> float:
    """How far along its guide a driving block is searched for the ends of its travel,
    either side of its place: twice the links' lengths and the ground's extent (m)."""
    path = scene.slider(driver.finds[0])
    through = getattr(path, "through", None)  # a collar on its rod: from the rod's pivot
    return (
        2.0 * sum(lk.length for lk in scene.links)
        + max((math.dist(xy, through) for xy in scene.ground.values()), default=0.0)
        if through is not None
        else 2.0 * sum(lk.length for lk in scene.links)
    )
