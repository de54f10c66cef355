"""The linkage's properties from its cycle: toggles, transmission angle, output range,
quick-return ratio, and the text that prints them."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from ..solver.derived import transmission_angle
from ..common.errors import TOL, SceneError, SingularStepError
from ..common.tolerances import DISTINCT, ROUNDING, SAME
from ..solver.compiler import compile_plan
from ..scene import Scene
from ..motion.solution import solve
from .cycle import _Cycle, stands_still
from .engine import _engine_lines
from .output_motion import (  # noqa: F401  (Stationary, path_origin re-exported)
    Stationary,
    output_motion,
    path_origin,
    shown_place,
)
from .shapes import (
    FourBar,
    Grashof,
    _output_of,
    four_bar_of,
    grashof,
    slider_crank_of,
    slotted_of,
    standing_steps,
)


# --------------------------------------------------------------------------- results


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
        """Whether the smallest transmission angle is below the lecture's advice (40 deg)."""
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
        """The report of ``polygon-method linkage``: Grashof, toggles, transmission angles, quick
        return."""
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
                out.append(
                    f"  driving from the output ({self.output_label}): it cannot "
                    "drive the crank through"
                )
                for s in self.stationary:
                    out.append(f"    crank at {s.deg:9.4f} deg: {s.what}")
            elif any("dwells" in n for n in self.notes):
                out.append(
                    f"  driving from the output ({self.output_label}): it dwells over "
                    "whole ranges of the crank (see below)"
                )
            else:
                out.append(
                    f"  driving from the output ({self.output_label}): none (it never "
                    "stands still while the crank turns)"
                )
        out.append("")
        for t in self.transmission:
            out.append(f"transmission angle at {t.point} ({t.between}, acute angle)")
            if t.now is not None:
                said = f", {sc.input.angle_words}" if sc.input.angle_words else ""
                out.append(
                    f"  now (crank at {_turn(math.degrees(sc.input.angle)):g} deg"
                    f"{said}): "
                    f"{t.now:.2f} deg"
                )
            out.append(
                f"  over the motion: minimum {t.minimum:.2f} deg at crank "
                f"{t.at_min:.2f} deg, maximum {t.maximum:.2f} deg at crank "
                f"{t.at_max:.2f} deg"
            )
            if t.warn:
                rng = ", ".join(
                    f"{a:.2f} to {b:.2f}" + (" (through 0)" if b < a else "") for a, b in t.below
                )
                out.append(
                    f"  WARNING: below {TOL.transmission_warn_deg:g} deg (the "
                    f"lecture's advice) for crank angles {rng} deg"
                )
        if self.output_range:
            if out[-1]:  # (no transmission angle above: one blank line is enough)
                out.append("")
            out.extend(self.output_range)
        if self.time_lines:
            out.extend(self.time_lines)
        if self.formulas:
            out.append("")
            out.extend(self.formulas)
        if self.notes:
            if out[-1]:  # (one blank line before them, never two)
                out.append("")
            out.extend(self.notes)
        # a value that rounds to zero is written 0.00, never -0.00
        return re.sub(r"(?<![\d.])-(0\.0+)(?![\d])", r"\1", "\n".join(out))


def _turn(d: float) -> float:
    """Degrees within one turn, [0, 360)."""
    d = d % 360.0
    return 0.0 if d >= 360.0 - 5e-4 else d


def _mm(x, scene) -> str:
    return f"{x / scene.length_unit:.6g} {scene.units}"


_MAX_STATIONARY = 12  # more samples still than this: the output dwells (a degenerate linkage)


def motion_over_cycle(cyc, out, scene, fb, sk, slot) -> tuple:
    """(dwell, :func:`output_motion`'s six) of the output ``out`` over the cycle ``cyc``:
    an output that dwells (:func:`_dwell`, a degenerate linkage) has no toggles and no
    quick return. The one definition of the output's stroke, swing and time ratio
    (``linkage`` prints them; the answers ``time_ratio`` and ``stroke_X`` read them)."""
    dwell = _dwell(cyc, out, scene)
    got = output_motion(cyc, out, scene, fb, sk, slot, dwells=bool(dwell))
    if dwell:
        got = ((), got[1], got[2], got[3], None, ())
    return dwell, got


def _dwell(cyc, out, scene) -> int:
    """How many of the cycle's samples the output stands still at, its rate nought to
    rounding against its largest, where they are more than :data:`_MAX_STATIONARY` (it
    dwells over whole ranges of the crank: a degenerate linkage); else 0. An output that
    merely reverses many times (a slider driven through a gear train, 26 times over the
    train's period) does not dwell: its reversals are its toggles. One whose place spans
    nothing over the cycle stands still at every sample (its rate is all rounding, the
    largest too: hundreds of its sign changes were listed as toggles)."""
    rate = np.abs(np.asarray(out.rate(cyc.fr), dtype=float))[~cyc.bad]
    rate = rate[np.isfinite(rate)]
    if not len(rate):
        return 0
    place = np.asarray(out.value(cyc.fr), dtype=float)[~cyc.fr.bad]
    if out.kind != "slider":  # an angle: its arc at the longest link's length
        place = np.unwrap(place) * max(lk.length for lk in scene.links)
    if len(place) > _MAX_STATIONARY and stands_still(float(np.ptp(place)), scene):
        return len(rate)
    still = int(np.count_nonzero(rate <= SAME * float(rate.max())))
    return still if still > _MAX_STATIONARY else 0


def _four_bar_character(scene: Scene, cyc, fb) -> tuple:
    """A four-bar's kind, members, Grashof record and classification lines."""
    kind = "four-bar"
    members = (
        f"ground {fb.o2}{fb.o4 if len(fb.o2) == 1 and len(fb.o4) == 1 else '-' + fb.o4}"
        f" = {_mm(fb.r1, scene)}, crank {fb.crank} = {_mm(fb.r2, scene)} (input), "
        f"coupler {fb.coupler} = {_mm(fb.r3, scene)}, output {fb.output} = "
        f"{_mm(fb.r4, scene)}"
    )
    fr0 = cyc.at(scene.input.angle, vel=False)
    crossed = _crossed(fr0, fb)
    g = grashof(fb.r2, fb.r3, fb.r4, fb.r1, crossed=crossed)
    classification = _grashof_lines(g, fb, scene)
    return kind, members, g, classification


def _slider_crank_character(scene: Scene, sk) -> tuple:
    """A slider crank's kind, members and whether its crank turns fully (r + e <= l)."""
    kind = "slider crank" + (" (in-line)" if sk.inline else " (offset)")
    members = (
        f"crank {sk.crank} = {_mm(sk.r, scene)}, connecting rod {sk.rod} = "
        f"{_mm(sk.l, scene)}, slider {sk.b}"
        + ("" if sk.inline else f", offset {_mm(abs(sk.e), scene)}")
    )
    full = sk.l >= sk.r + abs(sk.e) * (1 - ROUNDING)
    classification = [
        (
            f"r + e = {_mm(sk.r + abs(sk.e), scene)} {'<=' if full else '>'} l = "
            f"{_mm(sk.l, scene)}: "
            + ("the crank turns fully" if full else "the crank cannot turn fully (it rocks)")
        )
    ]
    return kind, members, None, classification


def _slotted_character(scene: Scene, slot) -> tuple:
    """A slotted lever's kind (Whitworth where the crank is longer than the distance between
    the pivots, else crank and slotted lever), members and whether the lever turns fully."""
    cr, sl = slot
    (ox, oy), (kx, ky) = scene.ground[cr.pivot], scene.ground[sl.known]
    d = math.hypot(kx - ox, ky - oy)
    whit = cr.length > d
    kind = "Whitworth quick return" if whit else "crank and slotted lever"
    members = (
        f"crank {cr.link} = {_mm(cr.length, scene)}, lever {sl.guide} pivoted at "
        f"{sl.known}, {cr.pivot}{sl.known if len(sl.known) == 1 else '-' + sl.known}"
        f" = {_mm(d, scene)}"
    )
    classification = [
        f"crank {_mm(cr.length, scene)} {'>' if whit else '<'} distance between the "
        f"pivots {_mm(d, scene)}: the lever "
        + ("turns fully (Whitworth)" if whit else "oscillates (quick return)")
    ]
    if sl.offset:  # the block never nearer the lever's pivot than the slot's offset
        e, near = abs(sl.offset), abs(d - cr.length)
        members += f", its slot {_mm(e, scene)} off its line"
        classification.append(
            f"the slot {_mm(e, scene)} off the lever's line: the block comes within "
            f"|{cr.pivot}{sl.known} - {cr.link}| = {_mm(near, scene)} of {sl.known}, "
            + (
                "never nearer than the offset: the crank turns fully"
                if near >= e
                else "nearer than the offset: the crank cannot turn fully"
            )
        )
    return kind, members, None, classification


def _character(scene: Scene, plan, cyc, fb, sk, slot) -> tuple:
    """The mechanism's kind, its members in words, its Grashof record (a four-bar's, else
    None) and the lines that classify it."""
    if fb is not None:
        return _four_bar_character(scene, cyc, fb)
    if sk is not None:
        return _slider_crank_character(scene, sk)
    if slot is not None:
        return _slotted_character(scene, slot)
    members = f"{len(plan.steps)} construction steps; Grashof's classes apply to four-bars only"
    classification = [
        "not a four-bar, slider crank or slotted lever: the crank's range, "
        "the transmission angle of every dyad and the output's motion "
        "follow from the cycle on the scene's branch"
    ]
    return "mechanism", members, None, classification


def _input_toggles(scene: Scene, plan, cyc, turns: bool) -> list:
    """The toggles driving from the input: none where the crank turns fully, else its limit
    positions (with the output's place at each)."""
    dom = cyc.dom
    crank = scene.input.crank
    if turns:
        return [
            f"driving from the input ({crank}): none, the crank turns fully "
            "(no dyad comes into line)"
        ]
    input_toggles = [f"driving from the input ({crank}): its limit positions"]
    out = _output_of(scene, plan)
    for lp in dom.limits:
        fr = cyc.at(lp.theta, vel=False)
        extra = ""
        if out is not None:
            extra = f"; {out.label} at {shown_place(out, out.value(fr)[0], scene)}"
        input_toggles.append(f"  crank at {cyc.deg(lp.theta):9.4f} deg: {lp.why}{extra}")
    return input_toggles


def _change_points(cyc, g) -> list:
    """The change points on the scene's branch, or that a special Grashof linkage meets none."""
    dom = cyc.dom
    cps = [
        f"change point at crank angle {cyc.deg(cp.theta):.4f} deg: {cp.why}"
        for cp in dom.change_points
    ]
    if g is not None and g.special and not dom.change_points:
        cps.append("S + L = P + Q, but the scene's branch meets no change point in its range")
    return cps


def _formulas(scene: Scene, cyc, sk, notes: list) -> tuple:
    """An in-line slider crank's approximate formulas compared with the exact values (a note
    instead where they do not apply or the scene's instant is singular)."""
    if sk is not None and sk.inline:
        try:
            solve(scene)  # the exact values exist at the scene's instant
        except SingularStepError as exc:
            notes.append(
                "the approximate formulas are not compared at the scene's instant: "
                f"{exc.step}: {exc.message}"
            )
        else:
            return tuple(_engine_lines(cyc, sk, scene))
    elif sk is not None:
        notes.append(
            "the approximate formulas v = r w (sin t + sin 2t / 2n) etc. hold for an "
            "in-line slider crank only"
        )
    return ()


def analyse(scene: Scene) -> Linkage:
    """The linkage's character: see the module docstring for what is covered."""
    plan = compile_plan(scene)
    if not plan.steps[0].periodic:  # no crank turns: Grashof, quick return, toggles of a turn
        raise SceneError(
            f"linkage analyses a crank's turn (Grashof, toggles, quick return): "
            f"this mechanism is driven by {plan.steps[0].title}, whose travel "
            "`sweep` follows (its ends, every quantity's extremes)",
            file=scene.file,
            key="[input] wheel" if scene.input.wheel else "[input] block",
        )
    cyc = _Cycle(scene)
    dom = cyc.dom
    fb = four_bar_of(scene)
    sk = slider_crank_of(scene)
    slot = slotted_of(scene)
    notes = []
    kind, members, g, classification = _character(scene, plan, cyc, fb, sk, slot)
    turns = dom.full_turn
    rng = None
    if not turns:
        rng = (cyc.deg(dom.lo), cyc.deg(dom.hi))
        classification.append(
            f"on the scene's branch the crank {scene.input.crank} reaches "
            f"{rng[0]:.4f} to {rng[1]:.4f} deg" + (" (through 0)" if rng[1] < rng[0] else "")
        )
    input_toggles = _input_toggles(scene, plan, cyc, turns)  # the limits of the crank
    cps = _change_points(cyc, g)
    # the output
    out = _output_of(scene, plan)
    stationary, out_lines, omin, omax, ratio, tlines = (), (), None, None, None, ()
    if out is not None:
        dwell, (stationary, out_lines, omin, omax, ratio, tlines) = motion_over_cycle(
            cyc, out, scene, fb, sk, slot
        )
        if dwell:  # a degenerate linkage: the output dwells
            every = dwell == int(np.count_nonzero(~cyc.bad))
            notes.append(
                f"{out.label} stands still at {'all ' if every else ''}{dwell} of the "
                "sampled crank angles (its rate nought to rounding): it dwells over "
                f"{'the whole cycle' if every else 'whole ranges of the crank'} (a "
                "degenerate linkage), so no single toggle positions are listed"
            )
    still = standing_steps(scene, plan)
    trans = tuple(
        _transmission(cyc, st, scene)
        for st in plan.steps
        if st.transmission() is not None and st.index not in still
    )
    formulas = _formulas(scene, cyc, sk, notes)
    notes.extend(dom.notes)
    return Linkage(
        scene,
        kind,
        members,
        g,
        tuple(classification),
        turns,
        rng,
        tuple(input_toggles),
        tuple(cps),
        out.label if out else None,
        tuple(stationary),
        tuple(out_lines),
        omin,
        omax,
        ratio,
        tuple(tlines),
        trans,
        formulas,
        tuple(notes),
    )


def _crossed(fr, fb: FourBar) -> bool:
    """A parallelogram has O2A parallel and equal to O4B, same way round."""
    (x2, y2), (xa, ya) = fr.P[fb.o2], fr.P[fb.a]
    (x4, y4), (xb, yb) = fr.P[fb.o4], fr.P[fb.b]
    d = math.hypot((xa - x2)[0] - (xb - x4)[0], (ya - y2)[0] - (yb - y4)[0])
    return d > DISTINCT * fb.r2


def _grashof_lines(g: Grashof, fb: FourBar, scene) -> list:
    names = {
        "crank": fb.crank,
        "coupler": fb.coupler,
        "output": fb.output,
        "ground": f"{fb.o2}{fb.o4}" if len(fb.o2) == len(fb.o4) == 1 else f"{fb.o2}-{fb.o4}",
    }
    u = scene.length_unit
    rel = {"<": "<", ">": ">", "=": "="}[g.relation]
    head = (
        f"Grashof: S + L = {g.s / u:.6g} + {g.l / u:.6g} = {(g.s + g.l) / u:.6g} "
        f"{rel} P + Q = {g.p / u:.6g} + {g.q / u:.6g} = {(g.p + g.q) / u:.6g} "
        f"{scene.units} (shortest: {names[g.shortest]})"
    )
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
        what = (
            f"special case S + L = P + Q ({g.kind[len('special Grashof ') :]} as for "
            "Grashof), with change points where all four pivots come into line"
        )
    return [head, what]


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
    return Transmission(
        st.finds[0], between, now, vmin, cyc.deg(tmin), vmax, cyc.deg(tmax), tuple(below)
    )


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
        per = cyc.dom.period
        t = grid[idx % n] + per * (idx // n) + side * cyc.h / 2
        near = [c for c in crossings if abs(((c - t + per / 2) % per) - per / 2) <= cyc.h]
        return near[0] if near else t

    out = []
    for a, b in runs:
        ta = cyc.dom.lo if (not full and a == 0) else end(a, -1)
        tb = cyc.dom.hi if (not full and b == n - 1) else end(b, +1)
        out.append((cyc.deg(ta), cyc.deg(tb)))
    return out
