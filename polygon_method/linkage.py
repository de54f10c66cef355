"""Linkage properties from the lecture: Grashof class, toggle positions, transmission angle,
range of the output, quick-return ratio, and the slider crank's approximate formulas.

Mechanisms covered
------------------
* **four-bar** (crank, coupler, output link pivoted on the ground): Grashof's classes
  (crank-rocker, rocker-crank, double crank, double rocker, non-Grashof triple rocker) and
  the special case S + L = P + Q with its change points (parallelogram, anti-parallelogram,
  deltoid);
* **slider crank**, in-line or offset: whether the crank turns fully, dead centres, stroke,
  quick return of the offset crank, and for the in-line one the textbook's approximate
  formulas (n = l / r) beside the exact values;
* **crank and slotted lever** (the block on the crank pin slides in a lever pivoted on the
  ground; Whitworth when the lever turns fully), with a ram or without;
* any other mechanism the plan builds: limit positions and change points of the crank,
  the transmission angle of every dyad, and the range of the last output pivoted on the
  ground or sliding on a fixed path, with its stationary positions and time ratio.

Everything over the cycle is found on the scene's own assembly branch (see
:mod:`polygon_method.tracking`), not on a formula that assumes one.

>>> from polygon_method.scene import parse_scene
>>> g = grashof(50, 66, 56, 100)   # crank, coupler, output, ground
>>> g.kind
'non-Grashof triple rocker'
>>> grashof(30, 90, 70, 100).kind
'crank-rocker'
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import TOL, SingularStepError
from .derived import transmission_angle
from .plan import compile_plan
from .scene import FixedPath, Scene
from .solution import solve
from .tracking import TWO_PI, Sweeper, degrees_fn, merge, run_arrays, valid_mask

__all__ = ["grashof", "Grashof", "analyse", "Linkage", "Stationary", "Transmission",
           "engine_formula_lines", "slider_crank_of"]

#: relative tolerance of the equality S + L = P + Q (and of equal lengths)
_EQUAL = 1e-9
_GRID = 3600


# --------------------------------------------------------------------------- Grashof


@dataclass(frozen=True)
class Grashof:
    """Grashof's classification of a four-bar from its lengths.

    ``s + l`` against ``p + q`` (shortest, longest, the other two); ``kind`` is one of
    ``crank-rocker``, ``rocker-crank``, ``double crank``, ``double rocker``,
    ``non-Grashof triple rocker``, or for ``s + l = p + q`` ``parallelogram``,
    ``anti-parallelogram``, ``deltoid``, ``rhombus`` or ``special Grashof <class>``.
    """

    crank: float
    coupler: float
    output: float
    ground: float
    s: float
    l: float
    p: float
    q: float
    shortest: str  # "crank", "coupler", "output", "ground"
    relation: str  # "<", ">", "="
    kind: str
    input_turns: bool  # can the crank turn fully (on some branch)?
    output_turns: bool

    @property
    def special(self) -> bool:
        return self.relation == "="


def _eq(a, b) -> bool:
    return abs(a - b) <= _EQUAL * max(abs(a), abs(b), 1e-300)


def grashof(crank, coupler, output, ground, *, crossed=None) -> Grashof:
    """Classify a four-bar: S + L < P + Q (Grashof) -> the shortest link turns fully
    relative to the others (crank-rocker if it is the crank, rocker-crank if the output,
    double crank if the ground, double rocker if the coupler); S + L > P + Q -> triple
    rocker; S + L = P + Q -> change points. ``crossed`` (for equal opposite links) tells a
    parallelogram (False) from an anti-parallelogram (True)."""
    lengths = {"crank": crank, "coupler": coupler, "output": output, "ground": ground}
    order = sorted(lengths, key=lambda k: lengths[k])
    s, l = lengths[order[0]], lengths[order[-1]]
    p, q = lengths[order[1]], lengths[order[2]]
    if _eq(s + l, p + q):
        rel = "="
    else:
        rel = "<" if s + l < p + q else ">"
    shortest = order[0]
    if rel == "<":
        kind = {"crank": "crank-rocker", "output": "rocker-crank", "ground": "double crank",
                "coupler": "double rocker"}[shortest]
        return Grashof(crank, coupler, output, ground, s, l, p, q, shortest, rel, kind,
                       shortest in ("crank", "ground"), shortest in ("output", "ground"))
    if rel == ">":
        return Grashof(crank, coupler, output, ground, s, l, p, q, shortest, rel,
                       "non-Grashof triple rocker", False, False)
    if _eq(crank, output) and _eq(coupler, ground):
        if _eq(crank, coupler):
            kind = "rhombus"
        else:
            kind = "anti-parallelogram" if crossed else "parallelogram"
    elif (_eq(crank, ground) and _eq(coupler, output)) or \
            (_eq(crank, coupler) and _eq(output, ground)):
        kind = "deltoid"
    else:
        kind = "special Grashof " + {"crank": "crank-rocker", "output": "rocker-crank",
                                     "ground": "double crank",
                                     "coupler": "double rocker"}[shortest]
    # with S + L = P + Q a shortest link turns fully relative to its neighbours (through
    # the change points); there may be two shortest links
    short = {k for k, v in lengths.items() if _eq(v, s)}
    turns_in = bool(short & {"crank", "ground"})
    turns_out = bool(short & {"output", "ground"})
    return Grashof(crank, coupler, output, ground, s, l, p, q, shortest, rel, kind,
                   turns_in, turns_out)


# --------------------------------------------------------------------------- what it is


@dataclass(frozen=True)
class FourBar:
    """Names and lengths of a four-bar found in the plan: crank O2-A (input), coupler A-B,
    output O4-B."""

    o2: str
    a: str
    b: str
    o4: str
    crank: str
    coupler: str
    output: str
    r2: float
    r3: float
    r4: float
    r1: float
    step: object  # the dyad step


@dataclass(frozen=True)
class SliderCrank:
    """Crank O-A, rod A-B, slider B on a fixed path at signed offset ``e`` from O."""

    o: str
    a: str
    b: str
    crank: str
    rod: str
    r: float
    l: float
    e: float
    u: tuple
    step: object  # the slider step

    @property
    def inline(self) -> bool:
        return abs(self.e) <= 1e-9 * self.l

    @property
    def n(self) -> float:
        return self.l / self.r


def _core_steps(plan):
    return [s for s in plan.steps if s.kind != "carried"]


def four_bar_of(scene: Scene):
    """The four-bar of the plan (crank + one dyad closing on a ground pivot), or None."""
    plan = compile_plan(scene)
    core = _core_steps(plan)
    if [s.kind for s in core] != ["crank", "dyad"]:
        return None
    cr, dy = core
    ends = {dy.b: (dy.link1, dy.l1), dy.d: (dy.link2, dy.l2)}
    if cr.tip not in ends:
        return None
    g = dy.d if dy.b == cr.tip else dy.b
    if g not in scene.ground:
        return None
    (cx, cy), (gx, gy) = scene.ground[cr.pivot], scene.ground[g]
    coupler, r3 = ends[cr.tip]
    output, r4 = ends[g]
    return FourBar(cr.pivot, cr.tip, dy.point, g, cr.link, coupler, output, cr.length, r3,
                   r4, math.hypot(gx - cx, gy - cy), dy)


def slider_crank_of(scene: Scene):
    """The slider crank of the plan (crank + rod + slider on a fixed path), or None."""
    plan = compile_plan(scene)
    core = _core_steps(plan)
    if [s.kind for s in core] != ["crank", "slider"]:
        return None
    cr, sd = core
    if sd.path is None or sd.b != cr.tip:
        return None
    (ox, oy) = scene.ground[cr.pivot]
    (qx, qy), (ux, uy) = sd.path.through, sd.path.u
    e = (ox - qx) * uy - (oy - qy) * ux  # signed distance of O from the path (ccw side +)
    return SliderCrank(cr.pivot, cr.tip, sd.point, cr.link, sd.link, cr.length, sd.length,
                       e, (ux, uy), sd)


def _slotted_of(scene: Scene):
    plan = compile_plan(scene)
    core = _core_steps(plan)
    if [s.kind for s in core[:2]] != ["crank", "slotted"]:
        return None
    cr, sl = core[0], core[1]
    if sl.point != cr.tip or sl.known not in scene.ground:
        return None
    return cr, sl


# --------------------------------------------------------------------------- the output


@dataclass(frozen=True)
class _Output:
    """The mechanism's output: a link pivoted on the ground (an angle) or a slider on a
    fixed path (a position along it)."""

    kind: str  # "rocker", "slider", "lever"
    name: str  # link key or slider point
    label: str
    pivot: str | None = None
    point: str | None = None
    path: FixedPath | None = None

    def value(self, fr):
        if self.kind == "slider":
            (qx, qy), (ux, uy) = self.path.through, self.path.u
            x, y = fr.P[self.point]
            return (x - qx) * ux + (y - qy) * uy
        (px, py), (x, y) = fr.P[self.pivot], fr.P[self.point]
        return np.arctan2(y - py, x - px)

    def rate(self, fr):
        if self.kind == "slider":
            return fr.S[self.point][0]
        return fr.W[self.name]


def _output_of(scene, plan):
    out = None
    for st in plan.steps:
        if st.kind == "dyad":
            for g, link in ((st.d, st.link2), (st.b, st.link1)):
                if g in scene.ground:
                    out = _Output("rocker", link, f"output link {link}", g, st.point)
                    break
        elif st.kind == "slider" and st.path is not None:
            out = _Output("slider", st.point, f"slider {st.point}", point=st.point,
                          path=st.path)
        elif st.kind == "slotted" and st.known in scene.ground:
            out = _Output("lever", st.guide, f"lever {st.guide}", st.known, st.new)
    return out


# --------------------------------------------------------------------------- over the cycle


class _Cycle:
    """Dense evaluation of the scene over the reachable crank angles, with refinement."""

    def __init__(self, scene, n=_GRID):
        self.sw = sw = Sweeper(scene)
        self.dom = dom = sw.domain
        self.plan = sw.plan
        span = TWO_PI if dom.full_turn else dom.hi - dom.lo
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
                out[int(k)] = (idx, run_arrays(self.dom.segments[int(k)][2], t[idx], self.sw.omega,
                                         self.sw.alpha, vel=False, acc=False))
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
            if b - a < 1e-13:
                break
        return t, best * sense

    def zeros(self, f, level=0.0, positions=False):
        """Crank angles where ``f - level`` changes sign over the cycle, refined."""
        g = f(self.fr) - level
        ok = ~(self.fr.bad if positions else self.bad)
        grid = self.grid
        if self.dom.full_turn:  # close the turn
            grid = np.append(grid, grid[0] + TWO_PI)
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
                if b - a < 1e-14:
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
        return run_arrays(plan, np.array([float(theta)]), self.sw.omega, self.sw.alpha,
                    vel=False, acc=False)


# --------------------------------------------------------------------------- results


@dataclass(frozen=True)
class Stationary:
    """A crank angle where the output stands still (a toggle when driven from the output)."""

    theta: float
    deg: float
    output: float  # rad (rocker, lever) or m (slider)
    what: str


@dataclass(frozen=True)
class Transmission:
    """The transmission angle of one dyad (acute, deg): now, and its extremes with the
    crank angles (deg) where they occur; ``below`` lists crank ranges under the lecture's
    40 deg."""

    point: str
    between: str
    now: float | None
    minimum: float
    at_min: float
    maximum: float
    at_max: float
    below: tuple

    @property
    def warn(self) -> bool:
        return self.minimum < TOL.transmission_warn_deg


@dataclass(frozen=True)
class Linkage:
    """Everything ``polygon-method linkage`` reports (angles in degrees)."""

    scene: Scene
    kind: str
    members: str
    grashof: Grashof | None
    classification: tuple  # lines
    turns_fully: bool
    range_deg: tuple | None
    input_toggles: tuple  # lines
    change_points: tuple  # lines
    output_label: str | None
    stationary: tuple  # Stationary
    output_range: tuple  # lines
    output_min: float | None
    output_max: float | None
    time_ratio: float | None
    time_lines: tuple
    transmission: tuple  # Transmission
    formulas: tuple  # lines
    notes: tuple

    def text(self) -> str:
        sc = self.scene
        out = [sc.title or sc.file or "mechanism", f"{self.kind}: {self.members}", ""]
        out.extend(self.classification)
        if self.change_points:
            out.extend(self.change_points)
        out.append("")
        out.append("toggle positions")
        out.extend("  " + x for x in self.input_toggles)
        if self.output_label:
            if self.stationary:
                out.append(f"  driving from the output ({self.output_label}): it cannot "
                           "drive the crank through")
                for s in self.stationary:
                    out.append(f"    crank at {s.deg:9.4f} deg: {s.what}")
            elif any("dwells" in n for n in self.notes):
                out.append(f"  driving from the output ({self.output_label}): it dwells over "
                           "whole ranges of the crank (see below)")
            else:
                out.append(f"  driving from the output ({self.output_label}): none (it never "
                           "stands still while the crank turns)")
        out.append("")
        for t in self.transmission:
            out.append(f"transmission angle at {t.point} ({t.between}, acute angle)")
            if t.now is not None:
                out.append(f"  now (crank at {math.degrees(sc.input.angle):g} deg): "
                           f"{t.now:.2f} deg")
            out.append(f"  over the motion: minimum {t.minimum:.2f} deg at crank "
                       f"{t.at_min:.2f} deg, maximum {t.maximum:.2f} deg at crank "
                       f"{t.at_max:.2f} deg")
            if t.warn:
                rng = ", ".join(f"{a:.2f} to {b:.2f}" + (" (through 0)" if b < a else "")
                                for a, b in t.below)
                out.append(f"  WARNING: below {TOL.transmission_warn_deg:g} deg (the "
                           f"lecture's advice) for crank angles {rng} deg")
        if self.output_range:
            out.append("")
            out.extend(self.output_range)
        if self.time_lines:
            out.extend(self.time_lines)
        if self.formulas:
            out.append("")
            out.extend(self.formulas)
        if self.notes:
            out.append("")
            out.extend(self.notes)
        return "\n".join(out)


def _mm(x, scene) -> str:
    return f"{x / scene.length_unit:.6g} {scene.units}"


def _dir_deg(x, y) -> float:
    return math.degrees(math.atan2(y, x))


_MAX_STATIONARY = 12  # more than this: the output dwells (a degenerate linkage)


def analyse(scene: Scene) -> Linkage:
    """The linkage's character: see the module docstring for what is covered."""
    plan = compile_plan(scene)
    cyc = _Cycle(scene)
    dom = cyc.dom
    fb = four_bar_of(scene)
    sk = slider_crank_of(scene)
    slot = _slotted_of(scene)
    notes = []
    g = None
    classification = []
    if fb is not None:
        kind = "four-bar"
        members = (f"ground {fb.o2}{fb.o4 if len(fb.o2) == 1 and len(fb.o4) == 1 else '-' + fb.o4}"
                   f" = {_mm(fb.r1, scene)}, crank {fb.crank} = {_mm(fb.r2, scene)} (input), "
                   f"coupler {fb.coupler} = {_mm(fb.r3, scene)}, output {fb.output} = "
                   f"{_mm(fb.r4, scene)}")
        fr0 = cyc.at(scene.input.angle, vel=False)
        crossed = _crossed(fr0, fb)
        g = grashof(fb.r2, fb.r3, fb.r4, fb.r1, crossed=crossed)
        classification = _grashof_lines(g, fb, scene)
    elif sk is not None:
        kind = "slider crank" + (" (in-line)" if sk.inline else " (offset)")
        members = (f"crank {sk.crank} = {_mm(sk.r, scene)}, connecting rod {sk.rod} = "
                   f"{_mm(sk.l, scene)}, slider {sk.b}"
                   + ("" if sk.inline else f", offset {_mm(abs(sk.e), scene)}"))
        full = sk.l >= sk.r + abs(sk.e) * (1 - 1e-12)
        classification = [
            (f"r + e = {_mm(sk.r + abs(sk.e), scene)} {'<=' if full else '>'} l = "
             f"{_mm(sk.l, scene)}: " + ("the crank turns fully" if full else
                                        "the crank cannot turn fully (it rocks)"))]
    elif slot is not None:
        cr, sl = slot
        (ox, oy), (kx, ky) = scene.ground[cr.pivot], scene.ground[sl.known]
        d = math.hypot(kx - ox, ky - oy)
        whit = cr.length > d
        kind = "Whitworth quick return" if whit else "crank and slotted lever"
        members = (f"crank {cr.link} = {_mm(cr.length, scene)}, lever {sl.guide} pivoted at "
                   f"{sl.known}, {cr.pivot}{sl.known if len(sl.known) == 1 else '-' + sl.known}"
                   f" = {_mm(d, scene)}")
        classification = [
            f"crank {_mm(cr.length, scene)} {'>' if whit else '<'} distance between the "
            f"pivots {_mm(d, scene)}: the lever "
            + ("turns fully (Whitworth)" if whit else "oscillates (quick return)")]
    else:
        kind = "mechanism"
        members = (f"{len(plan.steps)} construction steps; Grashof's classes apply to "
                   "four-bars only")
        classification = ["not a four-bar, slider crank or slotted lever: the crank's range, "
                          "the transmission angle of every dyad and the output's motion "
                          "follow from the cycle on the scene's branch"]
    turns = dom.full_turn
    rng = None
    if not turns:
        lo = cyc.deg(dom.lo)
        rng = (lo, lo + math.degrees(dom.hi - dom.lo))
        classification.append(f"on the scene's branch the crank {scene.input.crank} reaches "
                              f"{rng[0]:.4f} to {rng[1]:.4f} deg")
    # toggles driving from the input: the limits of the crank
    input_toggles = []
    crank = scene.input.crank
    if turns:
        input_toggles.append(f"driving from the input ({crank}): none, the crank turns fully "
                             "(no dyad comes into line)")
    else:
        input_toggles.append(f"driving from the input ({crank}): its limit positions")
        out = _output_of(scene, plan)
        for lp in dom.limits:
            fr = cyc.at(lp.theta, vel=False)
            extra = ""
            if out is not None:
                extra = f"; {out.label} at {_fmt_out(out, out.value(fr)[0], scene)}"
            input_toggles.append(f"  crank at {cyc.deg(lp.theta):9.4f} deg: {lp.why}{extra}")
    cps = []
    for cp in dom.change_points:
        cps.append(f"change point at crank angle {cyc.deg(cp.theta):.4f} deg: {cp.why}")
    if g is not None and g.special and not dom.change_points:
        cps.append("S + L = P + Q, but the scene's branch meets no change point in its range")
    # the output
    out = _output_of(scene, plan)
    stationary, out_lines, omin, omax, ratio, tlines = (), (), None, None, None, ()
    if out is not None:
        stationary, out_lines, omin, omax, ratio, tlines = _output_motion(cyc, out, scene,
                                                                          fb, sk, slot)
        if len(stationary) > _MAX_STATIONARY:  # a degenerate linkage: the output dwells
            notes.append(f"{out.label} stands still at {len(stationary)} of the sampled "
                         "crank angles: it dwells over whole ranges of the crank (a degenerate "
                         "linkage), so no single toggle positions are listed")
            stationary, ratio, tlines = (), None, ()
    trans = tuple(_transmission(cyc, st, scene) for st in plan.steps
                  if st.transmission() is not None)
    formulas = ()
    if sk is not None and sk.inline:
        try:
            solve(scene)  # the exact values exist at the scene's instant
        except SingularStepError as exc:
            notes.append("the approximate formulas are not compared at the scene's instant: "
                         f"{exc.step}: {exc.message}")
        else:
            formulas = tuple(_engine_lines(cyc, sk, scene))
    elif sk is not None:
        notes.append("the approximate formulas v = r w (sin t + sin 2t / 2n) etc. hold for an "
                     "in-line slider crank only")
    notes.extend(dom.notes)
    return Linkage(scene, kind, members, g, tuple(classification), turns, rng,
                   tuple(input_toggles), tuple(cps), out.label if out else None,
                   tuple(stationary), tuple(out_lines), omin, omax, ratio, tuple(tlines),
                   trans, formulas, tuple(notes))


def _crossed(fr, fb: FourBar) -> bool:
    """A parallelogram has O2A parallel and equal to O4B, same way round."""
    (x2, y2), (xa, ya) = fr.P[fb.o2], fr.P[fb.a]
    (x4, y4), (xb, yb) = fr.P[fb.o4], fr.P[fb.b]
    d = math.hypot((xa - x2)[0] - (xb - x4)[0], (ya - y2)[0] - (yb - y4)[0])
    return d > 1e-6 * fb.r2


def _grashof_lines(g: Grashof, fb: FourBar, scene) -> list:
    names = {"crank": fb.crank, "coupler": fb.coupler, "output": fb.output,
             "ground": f"{fb.o2}{fb.o4}" if len(fb.o2) == len(fb.o4) == 1
             else f"{fb.o2}-{fb.o4}"}
    u = scene.length_unit
    rel = {"<": "<", ">": ">", "=": "="}[g.relation]
    head = (f"Grashof: S + L = {g.s / u:.6g} + {g.l / u:.6g} = {(g.s + g.l) / u:.6g} "
            f"{rel} P + Q = {g.p / u:.6g} + {g.q / u:.6g} = {(g.p + g.q) / u:.6g} "
            f"{scene.units} (shortest: {names[g.shortest]})")
    what = {
        "crank-rocker": f"Grashof crank-rocker: the crank {fb.crank} turns fully, the output "
                        f"{fb.output} rocks",
        "rocker-crank": f"Grashof rocker-crank: the output {fb.output} could turn fully, the "
                        f"input {fb.crank} only rocks",
        "double crank": f"Grashof double crank (drag link): {fb.crank} and {fb.output} both "
                        "turn fully",
        "double rocker": f"Grashof double rocker: the coupler {fb.coupler} turns fully "
                         f"relative to the others; {fb.crank} and {fb.output} only rock",
        "non-Grashof triple rocker": "non-Grashof triple rocker: no link turns fully; the "
                                     f"input {fb.crank} rocks between limit positions",
        "parallelogram": "special case S + L = P + Q: a parallelogram (opposite links "
                         "equal); at its change points all four pivots come into line and it "
                         "may turn into an anti-parallelogram",
        "anti-parallelogram": "special case S + L = P + Q: an anti-parallelogram (crossed, "
                              "opposite links equal); at its change points it may turn into "
                              "a parallelogram",
        "rhombus": "special case S + L = P + Q: a rhombus (all links equal; parallelogram and "
                   "deltoid), with change points",
        "deltoid": "special case S + L = P + Q: a deltoid (kite: adjacent links equal), with "
                   "change points",
    }.get(g.kind)
    if what is None:
        what = (f"special case S + L = P + Q ({g.kind[len('special Grashof '):]} as for "
                "Grashof), with change points where all four pivots come into line")
    return [head, what]


def _fmt_out(out, v, scene) -> str:
    if out.kind == "slider":
        return f"{v / scene.length_unit:.6g} {scene.units} along the path"
    return f"{math.degrees(v):.4f} deg"


def _output_motion(cyc: _Cycle, out: _Output, scene, fb, sk, slot):
    dom = cyc.dom
    zs = cyc.zeros(out.rate)
    stats = []
    for t in zs:
        fr = cyc.at(t, vel=False)
        v = float(out.value(fr)[0])
        stats.append(Stationary(t, cyc.deg(t), v, _what_stationary(fr, out, scene, fb, sk,
                                                                   slot, v)))
    stats.sort(key=lambda s: s.deg)
    vals = [s.output for s in stats]
    if not dom.full_turn:
        for lp in dom.limits:
            fr = cyc.at(lp.theta, vel=False)
            vals.append(float(out.value(fr)[0]))
    lines = []
    omin = omax = None
    ratio, tlines = None, []
    if out.kind == "slider":
        all_v = out.value(cyc.fr)[~cyc.bad]
        if vals:
            omin, omax = min(vals + [float(all_v.min())]), max(vals + [float(all_v.max())])
            lines.append(f"{out.label}: moves between {_fmt_out(out, omin, scene)} and "
                         f"{_fmt_out(out, omax, scene)}: stroke "
                         f"{(omax - omin) / scene.length_unit:.6g} {scene.units}")
    else:
        ang = np.unwrap(out.value(cyc.fr)[~cyc.bad])
        span = float(ang.max() - ang.min()) if len(ang) else 0.0
        if dom.full_turn and abs(ang[-1] - ang[0]) > math.pi:
            lines.append(f"{out.label}: turns fully")
        elif vals:
            ref = float(ang[0])
            unwrapped = [ref + ((v - ref + math.pi) % TWO_PI) - math.pi for v in vals]
            omin, omax = min(unwrapped), max(unwrapped)
            shift = -TWO_PI * math.floor((omin + math.pi) / TWO_PI)  # omin in [-180, 180)
            omin, omax = omin + shift, omax + shift
            lines.append(f"{out.label}: swings between {math.degrees(omin):.4f} and "
                         f"{math.degrees(omax):.4f} deg: swing "
                         f"{math.degrees(omax - omin):.4f} deg")
        elif span:
            lines.append(f"{out.label}: moves through {math.degrees(span):.4f} deg")
    if dom.full_turn and len(stats) == 2:
        w = cyc.sw.omega
        t1, t2 = stats[0].theta, stats[1].theta
        arc1 = ((t2 - t1) * (1 if w > 0 else -1)) % TWO_PI  # crank turn from stat 1 to 2
        arc2 = TWO_PI - arc1
        mid = t1 + (1 if w > 0 else -1) * arc1 / 2
        fr = cyc.at(mid)
        sgn = float(out.rate(fr)[0])
        d1 = _direction(out, sgn)
        d2 = _direction(out, -sgn)
        slow, fast = max(arc1, arc2), min(arc1, arc2)
        ratio = slow / fast
        tlines.append(f"quick return: from crank {stats[0].deg:.4f} deg the crank turns "
                      f"{math.degrees(arc1):.4f} deg while {out.label} moves {d1}, then "
                      f"{math.degrees(arc2):.4f} deg while it moves {d2}")
        alpha = abs(math.degrees(arc1) - 180.0)
        tlines.append(f"  time ratio {ratio:.6f} = (180 + {alpha:.4f}) / (180 - {alpha:.4f})"
                      + ("  (equal strokes: no quick return)" if abs(ratio - 1) < 1e-9
                         else ""))
    elif not dom.full_turn:
        tlines.append("quick return: not applicable (the crank does not turn fully)")
    return tuple(stats), tuple(lines), omin, omax, ratio, tuple(tlines)


def _direction(out, sgn) -> str:
    if out.kind == "slider":
        return "forward (+ along the path)" if sgn > 0 else "back (- along the path)"
    return "ccw" if sgn > 0 else "cw"


def _what_stationary(fr, out, scene, fb, sk, slot, v) -> str:
    val = _fmt_out(out, v, scene)
    if fb is not None:
        (x2, y2), (xa, ya), (xb, yb) = fr.P[fb.o2], fr.P[fb.a], fr.P[fb.b]
        dot = float(((xa - x2) * (xb - xa) + (ya - y2) * (yb - ya))[0])
        how = "extended" if dot > 0 else "folded"
        return f"{fb.crank} and {fb.coupler} in line ({how}); {out.label} at {val}"
    if sk is not None:
        (xo, yo), (xa, ya), (xb, yb) = fr.P[sk.o], fr.P[sk.a], fr.P[sk.b]
        dot = float(((xa - xo) * (xb - xa) + (ya - yo) * (yb - ya))[0])
        if dot > 0:
            return (f"dead centre, {sk.crank} and {sk.rod} in line (extended: inner dead "
                    f"centre, slider farthest from {sk.o}); slider at {val}")
        return (f"dead centre, {sk.crank} and {sk.rod} in line (folded: outer dead centre, "
                f"slider nearest {sk.o}); slider at {val}")
    if slot is not None and out.kind == "lever":
        cr, _ = slot
        return f"the crank {cr.link} is perpendicular to the lever; {out.label} at {val}"
    return f"the output stands still; {out.label} at {val}"


def _transmission(cyc: _Cycle, st, scene) -> Transmission:
    def mu(fr):
        return transmission_angle(fr.cond[st.index])

    between = st.transmission()
    now = None
    t0 = scene.input.angle
    fr0 = cyc.at(cyc.dom.map(np.array([t0]))[0][0], vel=False)
    if not fr0.bad[0]:
        now = float(mu(fr0)[0])
    tmin, vmin = cyc.extreme(mu, -1.0, positions=True)
    tmax, vmax = cyc.extreme(mu, 1.0, positions=True)
    # in line at a limit position or a change point of this step: exactly 0 there
    for ev in tuple(cyc.dom.limits) + tuple(cyc.dom.change_points):
        if ev.step == st.label:
            tmin, vmin = ev.theta, 0.0
            break
    below = []
    lim = TOL.transmission_warn_deg
    if vmin < lim:
        below = _intervals_below(cyc, mu, lim)
    return Transmission(st.finds[0], between, now, vmin, cyc.deg(tmin), vmax, cyc.deg(tmax),
                        tuple(below))


def _intervals_below(cyc: _Cycle, f, lim):
    """Crank ranges (deg, as shown) where ``f < lim``, their ends refined."""
    low = (f(cyc.fr) < lim) | cyc.fr.bad
    grid, n = cyc.grid, len(cyc.grid)
    runs, k = [], 0
    while k < n:
        if low[k]:
            m = k
            while m + 1 < n and low[m + 1]:
                m += 1
            runs.append([k, m])
            k = m + 1
        else:
            k += 1
    full = cyc.dom.full_turn
    if full and len(runs) > 1 and runs[0][0] == 0 and runs[-1][1] == n - 1:
        runs[0][0] = runs[-1][0] - n  # joins across the seam of the turn
        runs.pop()
    crossings = cyc.zeros(f, lim, positions=True)

    def end(idx, side):
        if not full and (idx < 0 or idx >= n):
            return cyc.dom.lo if idx < 0 else cyc.dom.hi
        t = grid[idx % n] + TWO_PI * (idx // n) + side * cyc.h / 2
        near = [c for c in crossings if abs(((c - t + math.pi) % TWO_PI) - math.pi) <= cyc.h]
        return near[0] if near else t

    out = []
    for a, b in runs:
        ta = cyc.dom.lo if (not full and a == 0) else end(a, -1)
        tb = cyc.dom.hi if (not full and b == n - 1) else end(b, +1)
        if not full:
            lo = cyc.deg(cyc.dom.lo)
            out.append((lo + math.degrees(ta - cyc.dom.lo), lo + math.degrees(tb - cyc.dom.lo)))
        else:
            out.append((cyc.deg(ta), cyc.deg(tb)))
    return out


# --------------------------------------------------------------------------- slider crank


def _engine_lines(cyc: _Cycle, sk: SliderCrank, scene) -> list:
    """The in-line slider crank's approximate formulas beside the exact values."""
    inp = scene.input
    r, l, n = sk.r, sk.l, sk.n
    w, al = inp.omega, inp.alpha
    sg = 1.0 if w > 0 else -1.0
    W = abs(w)
    fr0 = cyc.at(cyc.dom.map(np.array([inp.angle]))[0][0])
    d = _idc_direction(fr0, sk)
    th_idc = math.atan2(d[1], d[0])
    t = (sg * (inp.angle - th_idc)) % TWO_PI
    x, y = fr0.P[sk.b]
    (ox, oy) = scene.ground[sk.o]
    vx, vy = fr0.V[sk.b]
    ax, ay = fr0.A[sk.b]
    xe = l + r - float(((x - ox) * d[0] + (y - oy) * d[1])[0])
    ve = -float((vx * d[0] + vy * d[1])[0])
    ae = -float((ax * d[0] + ay * d[1])[0])
    ale = sg * al
    xa = r * ((1 - math.cos(t)) + math.sin(t) ** 2 / (2 * n))
    va = r * W * (math.sin(t) + math.sin(2 * t) / (2 * n))
    aa = r * W * W * (math.cos(t) + math.cos(2 * t) / n) + r * ale * (
        math.sin(t) + math.sin(2 * t) / (2 * n))
    wr = abs(float(fr0.W[sk.rod][0]))
    alr = abs(float(fr0.Al[sk.rod][0]))
    wra = W * abs(math.cos(t)) / n
    alra = W * W * abs(math.sin(t)) / n
    rows = [("piston displacement from i.d.c. x", "m", xe,
             xa, "r [(1 - cos t) + sin^2 t / 2n]"),
            ("piston velocity v (toward the crank)", "m/s", ve, va,
             "r w (sin t + sin 2t / 2n)"),
            ("piston acceleration a (toward the crank)", "m/s^2", ae, aa,
             "r w^2 (cos t + cos 2t / n)" + (" + r alpha (sin t + sin 2t / 2n)" if al
                                            else "")),
            (f"rod {sk.rod}: |omega|", "rad/s", wr, wra, "w cos t / n"),
            (f"rod {sk.rod}: |alpha|", "rad/s^2", alr, alra, "w^2 sin t / n")]
    out = [f"in-line slider crank: n = l / r = {n:.6g}; crank {math.degrees(t):.4f} deg from "
           "inner dead centre (t, in the sense of rotation)"
           + ("; the formulas take the crank speed as uniform" if al else "")]
    wlab = max(len(rw[0]) for rw in rows)
    out.append(f"  {'quantity':<{wlab}} {'exact':>12} {'formula':>12} {'error':>9}  formula")
    for name, unit, ex, ap, form in rows:
        err = _err(ap, ex)
        out.append(f"  {name:<{wlab}} {ex:>12.6g} {ap:>12.6g} {err:>9}  {form} ({unit})")
    # maximum piston velocity: exact (refined over the cycle) and by the formula
    dvec = d

    tm, vm = cyc.extreme(lambda fr: -(fr.V[sk.b][0] * dvec[0] + fr.V[sk.b][1] * dvec[1]), 1.0)
    tmx = (sg * (tm - th_idc)) % TWO_PI
    c = (-n + math.sqrt(n * n + 8)) / 4
    ts = math.acos(c)
    vs = r * W * (math.sin(ts) + math.sin(2 * ts) / (2 * n))
    out.append(f"  maximum piston velocity: exact {vm:.6g} m/s at {math.degrees(tmx):.4f} deg "
               f"from i.d.c.; formula {vs:.6g} m/s at {math.degrees(ts):.4f} deg "
               f"(cos t = (-n + sqrt(n^2 + 8)) / 4 = {c:.6g}), error {_err(vs, vm).strip()}")
    return out


def _err(approx, exact) -> str:
    if exact == 0:
        return "0" if approx == 0 else "n/a"
    return f"{100.0 * (approx - exact) / abs(exact):+.3f} %"


def _idc_direction(fr, sk: SliderCrank):
    """Unit vector from the crank centre towards the slider's side of the path (the line of
    stroke, pointing at the inner dead centre)."""
    (xo, yo) = fr.P[sk.o]
    xb, yb = fr.P[sk.b]
    ux, uy = sk.u
    s = float(((xb - xo) * ux + (yb - yo) * uy)[0])
    return (ux, uy) if s >= 0 else (-ux, -uy)


def engine_formula_lines(scene: Scene, extremes=None) -> list:
    """For an in-line slider crank: the approximate formulas beside the exact values (for
    ``sweep --summary``); nothing for other mechanisms."""
    sk = slider_crank_of(scene)
    if sk is None or not sk.inline:
        return []
    cyc = _Cycle(scene, n=720)
    if not cyc.dom.full_turn:
        return []
    return _engine_lines(cyc, sk, scene)


# --------------------------------------------------------------------------- command line
