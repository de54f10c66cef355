"""The linkage's properties from its cycle: toggles, transmission angle, output range,
quick-return ratio, and the text that prints them."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

import numpy as np

from ..solver.derived import transmission_angle
from ..common.errors import TOL, SceneError, SingularStepError
from ..common.tolerances import ROUNDING, SAME
from ..solver.compiler import compile_plan
from ..scene import Scene
from ..motion.solution import solve
from ..solver.tracking import TWO_PI
from .cycle import _Cycle, stands_still
from .engine import _engine_lines
from .shapes import (
    FourBar,
    Grashof,
    _Output,
    _output_of,
    four_bar_of,
    grashof,
    slider_crank_of,
    slotted_of,
    standing_steps,
)


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


def _dir_deg(x, y) -> float:
    return math.degrees(math.atan2(y, x))


_MAX_STATIONARY = 12  # more than this: the output dwells (a degenerate linkage)


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
            extra = f"; {out.label} at {_fmt_out(out, out.value(fr)[0], scene)}"
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
        stationary, out_lines, omin, omax, ratio, tlines = _output_motion(
            cyc, out, scene, fb, sk, slot
        )
        if len(stationary) > _MAX_STATIONARY:  # a degenerate linkage: the output dwells
            notes.append(
                f"{out.label} stands still at {len(stationary)} of the sampled "
                "crank angles: it dwells over whole ranges of the crank (a degenerate "
                "linkage), so no single toggle positions are listed"
            )
            stationary, ratio, tlines = (), None, ()
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
    return d > 1e-6 * fb.r2


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


def path_origin(path, scene) -> str:
    """Where a position "along the path" is measured from, and which way is +: "from
    (0, 40) mm, + to the right"."""
    (qx, qy), (ux, uy) = path.through, path.u
    u = scene.length_unit
    ang = math.degrees(math.atan2(uy, ux))
    way = {
        0: "to the right",
        90: "upwards",
        180: "to the left",
        -180: "to the left",
        -90: "downwards",
    }.get(round(ang, 9), f"at {ang:.4g} deg")
    return f"from ({qx / u:.6g}, {qy / u:.6g}) {scene.units}, + {way}"


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
        stats.append(
            Stationary(t, cyc.deg(t), v, _what_stationary(fr, out, scene, fb, sk, slot, v))
        )
    stats.sort(key=lambda s: s.deg)
    vals = [s.output for s in stats]
    if not dom.full_turn:
        for lp in dom.limits:
            fr = cyc.at(lp.theta, vel=False)
            vals.append(float(out.value(fr)[0]))
    elif dom.turn_only:  # a turn that does not close: its two ends bound the range
        for t in (dom.lo, dom.hi):
            vals.append(float(out.value(cyc.at(t, vel=False))[0]))
    lines = []
    omin = omax = None
    ratio, tlines = None, []
    # the output's range is a matter of positions: every sample that assembles counts,
    # also those where the velocities are indeterminate (a nearly locked linkage has no other)
    placed = ~cyc.fr.bad
    if out.kind == "slider":
        all_v = out.value(cyc.fr)[placed]
        lines.append(
            f"{out.label}: its place along the path is measured {path_origin(out.path, scene)}"
        )
        if vals and len(all_v):
            omin, omax = min(vals + [float(all_v.min())]), max(vals + [float(all_v.max())])
            if stands_still(omax - omin, scene):  # rounding about a standstill, no stroke
                mid = 0.5 * (omin + omax)
                omin = omax = 0.0 if stands_still(abs(mid), scene) else mid
                lines.append(
                    f"{out.label}: stands still at {_fmt_out(out, omin, scene)}: no stroke"
                )
            else:
                lines.append(
                    f"{out.label}: moves between {_fmt_out(out, omin, scene)} and "
                    f"{_fmt_out(out, omax, scene)}: stroke "
                    f"{(omax - omin) / scene.length_unit:.6g} {scene.units}"
                )
    else:
        ang = np.unwrap(out.value(cyc.fr)[placed])
        span = float(ang.max() - ang.min()) if len(ang) else 0.0
        if dom.full_turn and len(ang) and abs(ang[-1] - ang[0]) > math.pi:
            lines.append(f"{out.label}: turns fully")
        elif vals and len(ang):
            ref = float(ang[0])
            unwrapped = [ref + ((v - ref + math.pi) % TWO_PI) - math.pi for v in vals]
            omin, omax = min(unwrapped), max(unwrapped)
            shift = -TWO_PI * math.floor((omin + math.pi) / TWO_PI)  # omin in [-180, 180)
            omin, omax = omin + shift, omax + shift
            lines.append(
                f"{out.label}: swings between {math.degrees(omin):.4f} and "
                f"{math.degrees(omax):.4f} deg: swing "
                f"{math.degrees(omax - omin):.4f} deg"
            )
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
        tlines.append(
            f"quick return: from crank {stats[0].deg:.4f} deg the crank turns "
            f"{math.degrees(arc1):.4f} deg while {out.label} moves {d1}, then "
            f"{math.degrees(arc2):.4f} deg while it moves {d2}"
        )
        alpha = abs(math.degrees(arc1) - 180.0)
        tlines.append(
            f"  time ratio {ratio:.6f} = (180 + {alpha:.4f}) / (180 - {alpha:.4f})"
            + ("  (equal strokes: no quick return)" if abs(ratio - 1) < SAME else "")
        )
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
            return (
                f"dead centre, {sk.crank} and {sk.rod} in line (extended: inner dead "
                f"centre, slider farthest from {sk.o}); slider at {val}"
            )
        return (
            f"dead centre, {sk.crank} and {sk.rod} in line (folded: outer dead centre, "
            f"slider nearest {sk.o}); slider at {val}"
        )
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
