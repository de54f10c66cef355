"""Sweep summaries: the maxima and minima of every quantity over the crank's turn, with
the crank angles where they occur (refined between samples), reduced chunk by chunk so that
a million angles need little memory.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from ..solver.kinematics import Motion
from ..common.tolerances import REFINED, ROUNDING, SAME, TOL, crossing_angle
from ..scene import FixedPath, Scene
from ..motion.sweeps import (
    SweepResult,
    rubbing_arrays,
    select,
    torque_array,
    angles_ok,
    evaluate_all,
    stroke_places,
    sweep_angles,
)
from ..solver.compiler import compile_plan
from ..solver.tracking import CHUNK, TWO_PI, Sweeper, branch_steps, degrees_fn
from ..solver.tracking import tune_malloc, valid_mask
from ..motion.link_points import pair_quantities

from .summary_limits import (
    at_limits,
    change_point_minima,
    limit_positions,
    limits_in,
    unbounded_at_limits,
    unbounded_sizes,
)
from .summary_forces import at_singular, force_arrays, singular_note, spread
from ..forces.cylinder import given_forces
from .summary_noise import noise
from .summary_record import Extreme, Summary
from .cycle import aliased

__all__ = ["summarize", "summary_of", "Summary", "Extreme"]


#: angles times points evaluated at once when refining extremes (about 100 MB of arrays)
_REFINE_BUDGET = 1_000_000
#: local extremes of each sense kept per quantity and refined (the largest sampled first):
#: the true extreme may be at another local one than the sampled best
_CANDIDATES = 6


def _local_extremes(a):
    """Indices of the interior local maxima of the samples ``a`` (in their order)."""
    if len(a) < 3:
        return np.zeros(0, dtype=np.intp)
    mid = a[1:-1]
    ok = (mid >= a[:-2]) & (mid >= a[2:]) & ((mid > a[:-2]) | (mid > a[2:]))
    return np.nonzero(ok)[0] + 1


def _keep_best(keep: dict, c, index) -> None:
    """Keep in ``keep`` (angle index -> value) the best :data:`_CANDIDATES` local maxima of
    the samples ``c`` and of the run's two ends (maybe next to a limit position), with those
    kept from earlier chunks: ties go to the earlier kept, then to the earlier sample.

    A noisy quantity has local maxima by the thousand in a chunk: only the best few of the
    chunk can be among the best overall, so those are chosen in one stable sort of the
    chunk's candidates, and the dictionary sees only them (the same choice, in the same
    order, as offering it every one).

    >>> keep = {}
    >>> _keep_best(keep, np.array([0.0, 3.0, 1.0, 2.0, 0.5, 2.0, 1.0]), np.arange(7))
    >>> keep
    {1: 3.0, 3: 2.0, 5: 2.0, 0: 0.0, 6: 1.0}
    """
    ks = np.concatenate([_local_extremes(c), [0, len(c) - 1]]).astype(np.intp)
    if len(c) > 1 and len(ks) > _CANDIDATES:  # distinct: the chunk alone overflows
        ks = ks[np.sort(np.argsort(-c[ks], kind="stable")[:_CANDIDATES])]
        for k in ks:
            keep[int(index[k])] = float(c[k])
        top = sorted(keep.items(), key=lambda kv: -kv[1])[:_CANDIDATES]
        keep.clear()
        keep.update(top)
        return
    for k in ks:
        keep[int(index[k])] = float(c[k])
    if len(keep) > _CANDIDATES:  # the best few local extremes of each sense
        top = sorted(keep.items(), key=lambda kv: -kv[1])[:_CANDIDATES]
        keep.clear()
        keep.update(top)


class _Reducer:
    """Running maxima and minima over chunks (with the index where each occurs)."""

    def __init__(self, scene, sw: Sweeper):
        self.scene, self.sw = scene, sw
        self.plan = sw.plan
        self.best = {}  # name -> [max, imax, min, imin, unit, what]
        self.forces_left_out = None  # why the force analysis is not summarised, or None
        self.force_names = set()  # the names of the force analysis's quantities
        self.singular = {}  # angle -> why a group's force equations are singular there
        self.near = []  # angles where they are nearly so (left out of the force extremes)
        dom = sw.domain  # the parameter's size of a radian: a driving block's travel / 2 pi
        self.rad = 1.0 if dom.periodic else (dom.hi - dom.lo) / TWO_PI

    def values(self, fr: Motion):
        """(name, unit, array, what) of the quantities summarised, magnitudes made."""
        for name, unit, arr, what in self.quantities(fr):
            yield name, unit, (np.hypot(*arr) if isinstance(arr, tuple) else arr), what

    def quantities(self, fr: Motion):
        """(name, unit, array, what) of the quantities summarised; a magnitude comes as its
        (x, y) components, so that its extremes are found on the squares (no root over
        every sample) and the root taken where they are."""
        sc, plan = self.scene, self.plan
        ground = set(sc.ground)
        for p in sc.point_names:
            if p in ground:
                continue
            yield f"v_{p}", "m/s", tuple(fr.V[p]), "speed"
            yield f"a_{p}", "m/s^2", tuple(fr.A[p]), "acceleration"
        for lk in sc.links:
            if lk.p in ground and lk.q in ground:
                continue
            yield f"omega_{lk.key}", "rad/s", fr.W[lk.key], "ccw +"
            yield f"alpha_{lk.key}", "rad/s^2", fr.Al[lk.key], "ccw +"
        yield from pair_quantities(sc, fr)  # vmin_BC, ar_CB, at_CB: where the answers ask them
        for s in sc.sliders:
            vs, a_s, cx, cy = fr.S[s.key]
            if isinstance(s, FixedPath):
                (qx, qy), (ux, uy) = s.through, s.u
                x, y = fr.P[s.point]
                yield f"s_{s.key}", "m", (x - qx) * ux + (y - qy) * uy, "position on the path"
            yield f"vs_{s.key}", "m/s", vs, "sliding, signed"
            yield f"as_{s.key}", "m/s^2", a_s, "sliding, signed"
            if hasattr(s, "guide"):  # a moving guide that turns: its Coriolis component
                yield f"ac_{s.key}", "m/s^2", (cx, cy), "Coriolis"
        if getattr(plan, "pins", ()):
            for pin, r in rubbing_arrays(plan, fr.W, fr.n).items():
                yield f"rub_{pin}", "m/s", r, "rubbing"
        t = torque_array(sc, fr.V, fr.W, self.sw.omega, fr.n, fr.S, fr.P)
        if t is not None and not plan.steps[0].periodic:  # the force driving the block
            yield "force", "N", t, "input force, along the guide"
        elif t is not None:
            yield "torque", "N m", t, "input torque, ccw +"
        if sc.has_forces:
            yield from self.force_quantities(fr)
            yield from self.rod_quantities(fr)
        for st in branch_steps(plan):
            name, unit, words = st.condition_column()  # "deg": the sine, shown as the angle
            yield name, unit, fr.cond[st.index], words

    def force_quantities(self, fr: Motion):
        """The force analysis's quantities over the angles of ``fr`` (named as the sweep's
        CSV columns): the driver's torque (or force) with inertia, a second crank's, the
        shaking force (its size) and moment, each guide's normal force (signed), each pin
        force's size, an engine's piston effort, crank effort and turning moment. None where
        the analysis does not cover the plan or fails at one of the angles: then
        :attr:`forces_left_out` says why, and the summary says so."""
        from ..common.errors import PolygonMethodError
        from ..forces import analyse  # lazy: a scene without masses never loads forces/
        from ..forces.engine import cylinder_efforts, efforts

        try:
            got = force_arrays(self, fr, analyse)
            if got is None:  # (singular at every angle of ``fr``)
                return
            f, rows, P = got
            plan = self.plan if fr.plan is None else fr.plan
            e = efforts(self.scene, plan, P, f)
            cyl = cylinder_efforts(self.scene, plan, P, f) if e is None else ()
        except PolygonMethodError as exc:
            self.forces_left_out = exc.message
            return
        n = fr.n if rows is None else len(rows)
        for name, unit, arr, what in self._force_items(f, e, n, cyl):
            self.force_names.add(name)
            if isinstance(arr, tuple):
                arr = tuple(spread(a, rows, fr.n) for a in arr)
            else:
                arr = spread(arr, rows, fr.n)
            yield name, unit, arr, what

    def rod_quantities(self, fr: Motion):
        """A connecting rod's correction couple and its torque on the crank shaft over the
        angles of ``fr`` (the sweep's CSV columns; ``forces.rod``), none without such a rod."""
        from ..forces.rod import correction_arrays  # lazy, as the force analysis

        plan = self.plan if fr.plan is None else fr.plan
        got = correction_arrays(self.scene, plan, fr.W, fr.Al, fr.n)
        if got is not None:
            yield "correction_couple", "N m", got[0], "m alpha (l1 l3 - k_G^2), ccw +"
            if got[1] is not None:
                yield "correction_torque", "N m", got[1], "its torque on the crank shaft, ccw +"

    @staticmethod
    def _force_items(f, e, n, cylinders=()):
        """(name, unit, array, what) of :meth:`force_quantities` from the forces ``f`` and
        an engine's efforts ``e`` (or None) at ``n`` angles."""

        b = lambda v: np.broadcast_to(np.asarray(v, dtype=float), (n,))  # noqa: E731

        if f.driver in ("crank", "wheel"):  # (a driving wheel's: the torque on it)
            yield "torque_inertia", "N m", b(f.input_torque), "driving torque with inertia, ccw +"
        else:
            yield "force_inertia", "N", b(f.input_torque), "driving force with inertia"
        if f.second_crank is not None:  # a second crank's torque (N m), a second collar's force
            k, u = ("force", "N") if "block " in f.second_crank else ("torque", "N m")
            yield f"{k}2_inertia", u, b(f.second_torque), f"second input's {k}, with inertia"
        yield "shake", "N", (b(f.shaking_force[0]), b(f.shaking_force[1])), "shaking force"
        yield "shake_moment", "N m", b(f.shaking_moment), "shaking moment about O, ccw +"
        for g in f.guides:
            yield f"N_{g.point}", "N", b(g.normal), "guide's normal force, signed"
        from ..forces import holding_columns  # lazy, as in `force_quantities`
        from ..forces.grip import margins

        # a friction drive's grip, a fixed gear's holding torque: each one's worst angle
        for name, unit, v, what in margins(f) + holding_columns(f):
            yield name, unit, b(v), what
        for p in f.pins:
            yield (
                f"F_{p.point}_{p.on}_{p.by}".replace(" ", ""),
                "N",
                (b(p.force[0]), b(p.force[1])),
                "pin force",
            )
        for k, v in given_forces(f):  # a passive cylinder's given force (a damper's varies)
            yield f"F_{k}", "N", b(v), "force in the cylinder, + pushing apart"
        if e is not None:
            yield "piston_effort", "N", b(e.F_P), "towards the crank"
            yield "crank_effort", "N", b(e.F_T), "in the sense of rotation"
            yield "turning_moment", "N m", b(e.T), "in the sense of rotation"
        for c in cylinders:  # several cylinders on one crank
            yield f"piston_effort_{c.piston}", "N", b(c.F_P), "towards the crank"
            yield f"crank_effort_{c.piston}", "N", b(c.F_T), "in the sense of rotation"
        if cylinders:
            yield "turning_moment", "N m", b(sum(c.T for c in cylinders)), "of all the cylinders"

    @staticmethod
    def shown(unit, value):
        """A reduced value as shown: the transmission angle from its sine."""
        if unit == "deg":
            return crossing_angle(value)
        return value

    def add(self, fr: Motion, index):
        for name, unit, arr, what in self.quantities(fr):
            if isinstance(arr, tuple):  # a magnitude: extremes of x^2 + y^2
                x, y = arr
                if not len(x):
                    continue
                sq = x * x
                sq += y * y
                cand = sq
            else:
                cand = arr
            if not len(cand):
                continue
            gap = name in self.force_names and np.isnan(cand).any()  # (singular angles)
            if gap and np.isnan(cand).all():
                continue
            hi_of = np.where(np.isnan(cand), -np.inf, cand) if gap else cand
            lo_of = np.where(np.isnan(cand), np.inf, cand) if gap else cand
            i, j = int(np.argmax(hi_of)), int(np.argmin(lo_of))
            if isinstance(arr, tuple):
                hi, lo = math.hypot(x[i], y[i]), math.hypot(x[j], y[j])
            else:
                hi, lo = float(arr[i]), float(arr[j])
            b = self.best.get(name)
            if b is None:
                b = self.best[name] = [hi, int(index[i]), lo, int(index[j]), unit, what, {}, {}]
            else:
                if hi > b[0]:
                    b[0], b[1] = hi, int(index[i])
                if lo < b[2]:
                    b[2], b[3] = lo, int(index[j])
            for sense, keep in ((1.0, b[6]), (-1.0, b[7])):
                c = sense * np.asarray(cand, dtype=float)
                _keep_best(keep, np.where(np.isnan(c), -np.inf, c) if gap else c, index)

    def _refine(self, tasks, passes):
        """Zoom on sampled extremes, all at once: 17 points across each bracket a pass.
        ``tasks``: [name, sense, a, b, best value, best angle]; updated in place."""
        # a batch of brackets at a time: every angle evaluates every point, so all of them
        # at once would hold (brackets x points), quadratic in the scene's size (gigabytes
        # for a thousand points)
        batch = max(1, _REFINE_BUDGET // (17 * max(1, len(self.scene.point_names))))
        for _ in range(passes):
            live = [t for t in tasks if t[2] < t[3]]
            if not live:
                return
            for k in range(0, len(live), batch):
                self._refine_pass(live[k : k + batch])

    def _refine_pass(self, live):
        """One pass of :meth:`_refine` over the brackets ``live``."""
        sw = self.sw
        pts = np.concatenate([np.linspace(t[2], t[3], 17) for t in live])
        ok = angles_ok(sw, pts)
        fr = sw.evaluate(pts)
        invalid = valid_mask(fr, self.plan)
        if ok is not None:
            invalid |= ~ok
        q = {nm: arr for nm, _, arr, _ in self.values(fr)}
        for k, t in enumerate(live):
            name, sense = t[0], t[1]
            sl = slice(17 * k, 17 * k + 17)
            if name not in q:  # (the force analysis failed at these angles)
                t[3] = t[2]
                continue
            vals = q[name][sl] * sense
            vals = np.where(invalid[sl] | np.isnan(vals), -np.inf, vals)
            j = int(np.argmax(vals))
            if not np.isfinite(vals[j]):
                t[3] = t[2]  # give up on this one
                continue
            if vals[j] * sense * sense >= t[4] * sense:
                t[4], t[5] = float(vals[j] * sense), float(pts[sl][j])
            p = pts[sl]
            t[2], t[3] = p[max(j - 1, 0)], p[min(j + 1, 16)]

    def finish(self, theta, requested, evaluated, *, refine=True):
        """The :class:`Summary` of the chunks added, over the evaluated angles ``theta``:
        each quantity's extremes (shown as 0 within their own error bound), refined between
        samples, taken at the limit positions the angles reach, marked where unbounded."""
        dom = self.sw.domain
        n = len(theta)
        spacing = float(np.median(np.abs(np.diff(theta[:10001])))) if n > 2 else None
        notes = tuple(dom.notes) + self._forces_note() + aliased(self.scene, self.sw.plan, spacing)
        rows, tasks = self._rows(theta, spacing, refine)
        if tasks:
            self._refine_rows(tasks, spacing)
        if n and refine:
            at_limits(self, rows, theta, spacing)
        if n:
            change_point_minima(self, rows, spacing, float(np.min(theta)), float(np.max(theta)))
            limit_positions(self, rows, theta, spacing)
        deg = degrees_fn(dom)
        if dom.periodic and dom.turns == 1 and self.scene.cycle > 2 * math.pi:
            # a four-stroke engine's forces repeat after two turns: the angles within them
            deg = degrees_fn(replace(dom, turns=round(self.scene.cycle / (2 * math.pi))))
        unbounded = unbounded_at_limits(self, rows, theta, spacing) if n else {}
        where = {}  # (name, sense) -> why it is unbounded there, where not a limit position
        for key, (ts, words) in (
            at_singular(self, rows, spacing) if self.singular or self.near else {}
        ).items():
            if key not in unbounded:
                unbounded[key], where[key] = ts, words
        notes += singular_note(self, deg)
        unbounded_sizes(self, rows, unbounded, theta, spacing)
        for row in rows:  # an unbounded extreme is at the limit position, not a sample
            nm = row[0]
            if (nm, 1.0) in unbounded:
                row[3] = unbounded[(nm, 1.0)]
            if (nm, -1.0) in unbounded:
                row[5] = unbounded[(nm, -1.0)]
        extremes = tuple(
            Extreme(
                nm,
                u,
                self.shown(u, mx),
                None if tmx is None else deg(tmx),
                self.shown(u, mn),
                None if tmn is None else deg(tmn),
                what,
                bool(tasks),
                (nm, 1.0) in unbounded,
                (nm, -1.0) in unbounded,
                where.get((nm, 1.0), ""),
                where.get((nm, -1.0), ""),
            )
            for nm, u, mx, tmx, mn, tmn, what in rows
        )
        rng = None if dom.full_turn else (deg(dom.lo), deg(dom.hi))
        if any(e.name.startswith("grip_") for e in extremes):  # a friction drive's verdict
            from ..forces.grip import sweep_notes

            notes += sweep_notes(extremes)
        return Summary(
            self.scene,
            requested,
            evaluated,
            extremes,
            dom.limits,
            dom.change_points,
            notes,
            self._formulas(extremes),
            rng,
            deg,
        )

    def _rows(self, theta, spacing, refine):
        """(rows, tasks): each quantity's row ``[name, unit, max, its angle, min, its angle,
        what]`` (the angles None for a constant), its extremes within their own error bound
        written as 0; and the refinement tasks of its sampled local extremes
        (:meth:`_tasks`)."""
        n = len(theta)
        tasks, rows = [], []
        scales = self.scales()
        limits = [lp.theta for lp, _ in limits_in(self, theta, spacing)]
        noise = self._noise(theta)
        for name, (mx, imx, mn, imn, unit, what, cmax, cmin) in self.best.items():
            own = noise.get(name)  # each quantity's own error bound where it is reached
            if own is None:  # (a rubbing velocity, the input effort: the sizes the input sets)
                zmx = zmn = SAME * scales.get(unit, 0.0)
            else:
                zmx, zmn = own(imx), own(imn)
            mx, mn = (0.0 if abs(mx) <= zmx else mx), (0.0 if abs(mn) <= zmn else mn)
            scale = max(abs(mx), abs(mn))
            if n > 1 and (mx - mn <= TOL.negligible * scale or scale == 0.0):
                rows.append([name, unit, mx, None, mn, None, what])
                continue
            row = [name, unit, mx, float(theta[imx]), mn, float(theta[imn]), what]
            rows.append(row)
            if refine and spacing and spacing > ROUNDING:
                for sense, i, cand in ((1.0, imx, cmax), (-1.0, imn, cmin)):
                    tasks += self._tasks(row, sense, i, cand, theta, spacing, limits)
        return rows, tasks

    def _tasks(self, row, sense, i, cand, theta, spacing, limits):
        """The refinement tasks ``[name, sense, a, b, best value, best angle, row]`` of the
        sampled extreme at ``i`` and the local ones ``cand`` of one sense: a bracket of one
        spacing each side, where the sample is a local extreme (or next to a limit
        position), not next to a change point."""
        dom = self.sw.domain
        cps = [c.theta for c in dom.change_points]
        out = []
        for k in dict.fromkeys([i, *cand]):
            t = float(theta[k])
            if not (
                _interior(theta, k, spacing)
                or any(abs(lim - dom.map(np.array([t]))[0][0]) <= 1.5 * spacing for lim in limits)
            ):
                continue  # the end of the requested range: its own value
            a, b = t - spacing, t + spacing  # (beyond a limit: left out)
            (tm,), _ = dom.map(np.array([t]))
            if any(abs(tc - tm) < 2 * spacing + 0.02 * self.rad for tc in cps):
                continue  # values next to a change point are not refined
            val = (row[2] if sense > 0 else row[4]) if k == i else -sense * math.inf
            out.append([row[0], sense, a, b, val, t, row])
        return out

    def _refine_rows(self, tasks, spacing):
        """Refine the ``tasks`` (:meth:`_refine`, down to about :data:`REFINED` rad) and put each
        better extreme found into its row."""
        passes = max(1, min(12, math.ceil(math.log(2 * spacing / REFINED, 8))))
        self._refine(tasks, passes)
        for name, sense, _, _, val, t, row in tasks:
            if sense > 0 and val >= row[2]:
                row[2], row[3] = val, t
            elif sense < 0 and val <= row[4]:
                row[4], row[5] = val, t

    def _formulas(self, extremes) -> tuple:
        """The lines of an in-line slider crank's formulas (checked against the extremes)
        and an engine's turning moment and flywheel, or ()."""
        from . import engine_cycle_lines, engine_formula_lines

        formulas = tuple(engine_formula_lines(self.scene, {e.name: e for e in extremes}))
        cycle = engine_cycle_lines(self.scene)  # an engine's turning moment and flywheel
        if cycle:
            formulas += (("",) if formulas else ()) + tuple(cycle)
        return formulas

    def _noise(self, theta) -> dict:
        """name -> f(i): the absolute error bound of each quantity at sample ``i`` of
        ``theta`` (:func:`.summary_noise.noise`). Rubbing velocities and the input effort
        are not here (the sizes the input sets decide them, as before)."""
        return noise(self.scene, self.plan, self.sw, self.best, theta)

    def _forces_note(self) -> tuple:
        """Where the force analysis failed at some angle, none of its quantities is kept:
        the note saying so (else none)."""
        if self.forces_left_out is None:
            return ()
        for nm in self.force_names:
            self.best.pop(nm, None)
        return (f"the forces are not summarised: {self.forces_left_out}",)

    def scales(self) -> dict:
        """Typical sizes per unit, below a :data:`SAME` part of which a value is zero (rounding);
        forces and moments: the largest force, it times the longest length."""
        out = self._motion_scales()
        if self.force_names:
            size = lambda b: max(abs(b[0]), abs(b[2]))  # noqa: E731
            F = max([size(b) for b in self.best.values() if b[4] == "N"] + [0.0])
            out["N"] = F
            out["N m"] = max(
                [F * out["m"]] + [size(b) for b in self.best.values() if b[4] == "N m"]
            )
        return out

    def _motion_scales(self) -> dict:
        """The kinematic quantities' typical sizes per unit (see :meth:`scales`)."""
        sc = self.scene
        if not self.sw.driver.periodic:  # a block driver: the sizes its input sets
            v, a, w, k = self.sw.driver.input_scales(sc)
            return {
                "rad/s": w,
                "rad/s^2": k,
                "m/s": v,
                "m/s^2": a,
                "m": max([lk.length for lk in sc.links]),
            }
        w = abs(self.sw.omega)
        k = w * w + abs(self.sw.alpha)
        lengths = [lk.length for lk in sc.links] + [math.hypot(*xy) for xy in sc.ground.values()]
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
    return abs(d[0]) <= 1.5 * spacing and abs(d[1]) <= 1.5 * spacing and d[0] * d[1] < 0


def summarize(scene: Scene, angles=None, *, chunk: int = CHUNK, refine: bool = True) -> Summary:
    """Maxima and minima of every quantity over ``angles`` (rad; default every degree),
    reduced chunk by chunk: memory stays that of one chunk whatever the number of angles.
    Each extreme found between samples is then refined by zooming in on it."""
    if angles is None and not compile_plan(scene).steps[0].periodic:
        angles = stroke_places(scene)  # a driving block: its travel
    sw = Sweeper(scene)
    th_req = sweep_angles(angles, sw.domain.turns)
    sw.stated_branch()
    ok = angles_ok(sw, th_req)
    th = th_req if ok is None else th_req[ok]
    if len(th) > chunk:
        tune_malloc()
    red = _Reducer(scene, sw)
    n_valid = 0
    for sl, fr in evaluate_all(sw, th, chunk):
        bad = valid_mask(fr, sw.plan)
        index = np.arange(sl.start, sl.stop)
        if bad.any():
            fr = select(fr, ~bad)
            index = index[~bad]
        n_valid += len(index)
        red.add(fr, index)
    return red.finish(th, len(th_req), n_valid, refine=refine)


# --------------------------------------------------------------------------- command line


def summary_of(res: SweepResult, **kw) -> Summary:
    """The summary of a sweep already made (its own angles, no new evaluation but the
    refinement of the extremes)."""
    red = _Reducer(res.scene, Sweeper(res.scene))
    red.add(res, np.arange(len(res.theta)))
    return red.finish(res.theta, res.requested, len(res.theta), **kw)
