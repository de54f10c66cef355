"""The linkage over its cycle: the scene's plan on its branch, sampled and refined where
something stands still or turns over."""

from __future__ import annotations

import math

import numpy as np

from ..common.errors import SceneError

from ..common.tolerances import EXTREME_RESOLVED, SAME, ZERO_RESOLVED
from ..solver.tracking import Sweeper, degrees_fn, merge, run_arrays, valid_mask
from .shapes import _GRID


#: a range of positions narrower than this fraction of the longest link is rounding about a
#: standstill, not a stroke
STANDSTILL = SAME


def stands_still(span, scene) -> bool:
    """Whether a point whose positions span ``span`` (m) over the cycle stands still."""
    return span <= STANDSTILL * max(lk.length for lk in scene.links)


#: the most a wheel or a second crank may turn between two of the cycle's samples (rad):
#: past it the samples cannot follow its turning (a sun turning millions of times per turn
#: of its arm), and what they show of the cycle is aliased
MOST_PER_SAMPLE = math.radians(10.0)
#: the most samples a cycle is given to follow a fast wheel or second crank (20 times the
#: usual grid's): beyond them it is refused, saying why
MOST_SAMPLES = 72_000


def _fastest(plan):
    """(rate, step) of the wheel or second crank turning fastest at a fixed ratio of a
    periodic crank (its turn per radian of the crank's), or None."""
    rates = [
        (abs(r), st) for st in plan.steps if (r := getattr(st, "theta_rate", None)) is not None
    ]
    if not rates or not plan.steps[0].periodic:
        return None
    return max(rates, key=lambda t: t[0])


def samples_to_follow(plan, span, n) -> int:
    """``n`` samples over ``span`` rad of the crank, or more where a wheel or a second crank
    turning at a fixed ratio of it would turn more than :data:`MOST_PER_SAMPLE` between two
    (a differential's planet at 15 times its arm's speed: the cycle sampled finer, not
    refused), up to :data:`MOST_SAMPLES`."""
    fast = _fastest(plan)
    if fast is None:
        return n
    need = math.ceil(span * fast[0] / MOST_PER_SAMPLE * (1 - SAME))  # (10 deg is followed)
    return max(n, min(MOST_SAMPLES, need))


def _too_fast(scene, plan, h) -> str | None:
    """Why samples ``h`` rad of the crank apart cannot follow a wheel or a second crank
    turning at a fixed ratio of the crank (its turning between two samples past
    :data:`MOST_PER_SAMPLE`), with the spacing that would; None where they can."""
    fast = _fastest(plan)
    if fast is None:
        return None
    rate, st = fast
    if not rate * h > MOST_PER_SAMPLE * (1 + SAME):  # (10 deg, to rounding, follows it)
        return None
    return (
        f"{st.title} turns {rate:.3g} times as fast as the crank {scene.input.crank}: "
        f"the crank's cycle, sampled every {math.degrees(h):.3g} deg, cannot follow it "
        f"(it turns {math.degrees(rate * h):.3g} deg between two samples; samples "
        f"{math.degrees(MOST_PER_SAMPLE / rate):.3g} deg apart or closer would follow it)"
    )


def _followable(scene, plan, h) -> None:
    """Refuse, in one line, a cycle whose samples (``h`` rad of the crank apart) cannot
    follow a wheel or a second crank turning at a fixed ratio of the crank (:func:`_too_fast`)."""
    why = _too_fast(scene, plan, h)
    if why is None:
        return
    second = scene.input.second is not None
    raise SceneError(
        why
        + "; "
        + (
            "give the two inputs speeds of comparable size"
            if second
            else "drive the train from its fast end"
        ),
        file=scene.file,
        key="[input.second] speed" if second else "[rolling]",
    )


def aliased(scene, plan, spacing, what="the extremes below") -> tuple:
    """A sweep's note where its samples, ``spacing`` rad of the crank apart, cannot follow
    a wheel or a second crank (the check ``linkage`` refuses by): ``what`` it shows may be
    aliased; () where they can (or fewer than three samples give no spacing)."""
    why = None if spacing is None else _too_fast(scene, plan, spacing)
    if why is None:
        return ()
    return (f"{why}: {what} may be aliased, not the motion's own",)


def sweep_aliased(res, what) -> tuple:
    """:func:`aliased` of a sweep made (``res``: its angles, its scene and plan)."""
    th = np.asarray(res.theta, dtype=float)
    spacing = float(np.median(np.abs(np.diff(th)))) if len(th) > 2 else None
    return aliased(res.scene, res.plan, spacing, what)


# --------------------------------------------------------------------------- over the cycle


class _Cycle:
    """Dense evaluation of the scene over the reachable crank angles, with refinement."""

    def __init__(self, scene, n=_GRID):
        self.sw = sw = Sweeper(scene)
        self.dom = dom = sw.domain
        self.plan = sw.plan
        span = dom.period if dom.full_turn else dom.hi - dom.lo
        n = samples_to_follow(sw.plan, span, n)
        _followable(scene, sw.plan, span / n)
        self.grid = dom.lo + span * (np.arange(n) + 0.5) / n
        self.h = span / n
        self.fr = sw.evaluate(self.grid)
        self.bad = valid_mask(self.fr, self.plan)
        self.deg = degrees_fn(dom)

    def evaluate(self, pts, positions=False):
        """A frame at crank angles ``pts`` (in the domain) and the mask of those where it is
        not to be used: not assembled, or (unless ``positions``) singular."""
        pts = np.asarray(pts, dtype=float)
        lo, hi = self.dom.lo, self.dom.hi
        if not self.dom.full_turn:
            pts = np.clip(pts, lo, hi)
        if positions:
            t, _ = self.dom.map(pts)
            seg = self.sw.segment_plans(t)
            fr = None
            bad = np.zeros(len(pts), dtype=bool)
            out = {}
            for k in np.unique(seg):
                idx = np.nonzero(seg == k)[0]
                out[int(k)] = (
                    idx,
                    run_arrays(
                        self.dom.segments[int(k)][2],
                        t[idx],
                        self.sw.omega,
                        self.sw.alpha,
                        vel=False,
                        acc=False,
                    ),
                )
            fr = merge(t, out)
            return fr, fr.bad | bad
        fr = self.sw.evaluate(pts)
        return fr, valid_mask(fr, self.plan)

    def extreme(self, f, sense, positions=False):
        """(crank angle, value) of the largest ``sense * f`` over the cycle, refined."""
        base_bad = self.fr.bad if positions else self.bad
        vals = np.where(base_bad, -np.inf, f(self.fr) * sense)
        i = int(np.argmax(vals))
        t, best = float(self.grid[i]), float(vals[i])
        a, b = t - self.h, t + self.h
        for _ in range(14):
            pts = np.linspace(a, b, 17)
            fr, bad = self.evaluate(pts, positions)
            v = np.where(bad, -np.inf, f(fr) * sense)
            j = int(np.argmax(v))
            if not np.isfinite(v[j]):
                break
            if v[j] >= best:
                t, best = float(pts[j]), float(v[j])
            a, b = pts[max(j - 1, 0)], pts[min(j + 1, 16)]
            if b - a < EXTREME_RESOLVED:
                break
        return t, best * sense

    def zeros(self, f, level=0.0, positions=False):
        """Crank angles where ``f - level`` changes sign over the cycle, refined."""
        g = f(self.fr) - level
        ok = ~(self.fr.bad if positions else self.bad)
        grid = self.grid
        if self.dom.full_turn and not self.dom.turn_only:  # close the turn (a turn after
            # which the mechanism is not where it started is not closed: its seam is no zero)
            grid = np.append(grid, grid[0] + self.dom.period)
            g = np.append(g, g[0])
            ok = np.append(ok, ok[0])
        s = np.sign(g)
        idx = np.nonzero(ok[:-1] & ok[1:] & (s[:-1] * s[1:] <= 0) & (s[:-1] != 0))[0]
        out = []
        for i in idx:
            a, b = grid[i], grid[i + 1]
            ga = g[i]
            for _ in range(10):
                pts = np.linspace(a, b, 33)
                fr, bad = self.evaluate(pts, positions)
                v = f(fr) - level
                ch = np.nonzero((np.sign(v[1:]) != np.sign(ga)) & ~bad[1:])[0]
                if not len(ch):
                    break
                j = ch[0] + 1
                a, b = pts[j - 1], pts[j]
                if b - a < ZERO_RESOLVED:
                    break
            out.append(0.5 * (a + b))
        return out

    def at(self, theta, vel=True):
        """One evaluation at a crank angle in the domain (positions only with vel=False)."""
        if vel:
            fr, bad = self.evaluate([theta])
            return fr
        seg = self.sw.segment_plans(np.array([theta]))
        plan = self.dom.segments[int(seg[0])][2]
        return run_arrays(
            plan, np.array([float(theta)]), self.sw.omega, self.sw.alpha, vel=False, acc=False
        )
