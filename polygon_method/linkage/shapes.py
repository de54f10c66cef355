"""What the linkage is: Grashof's class of a four-bar, and the four-bar, slider crank or
slotted lever a plan makes (asked of its steps' kinds), with its output."""

from __future__ import annotations

from ..common.tolerances import FLOOR, SAME
import math
from dataclasses import dataclass

import numpy as np

from ..solver.compiler import compile_plan
from ..scene import FixedPath, Scene

#: relative tolerance of the equality S + L = P + Q (and of equal lengths)
_EQUAL = SAME
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
        """A change-point (special Grashof) linkage: s + l equals p + q."""
        return self.relation == "="


def _eq(a, b) -> bool:
    return abs(a - b) <= _EQUAL * max(abs(a), abs(b), FLOOR)


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
        kind = {
            "crank": "crank-rocker",
            "output": "rocker-crank",
            "ground": "double crank",
            "coupler": "double rocker",
        }[shortest]
        return Grashof(
            crank,
            coupler,
            output,
            ground,
            s,
            l,
            p,
            q,
            shortest,
            rel,
            kind,
            shortest in ("crank", "ground"),
            shortest in ("output", "ground"),
        )
    if rel == ">":
        return Grashof(
            crank,
            coupler,
            output,
            ground,
            s,
            l,
            p,
            q,
            shortest,
            rel,
            "non-Grashof triple rocker",
            False,
            False,
        )
    if _eq(crank, output) and _eq(coupler, ground):
        if _eq(crank, coupler):
            kind = "rhombus"
        else:
            kind = "anti-parallelogram" if crossed else "parallelogram"
    elif (_eq(crank, ground) and _eq(coupler, output)) or (
        _eq(crank, coupler) and _eq(output, ground)
    ):
        kind = "deltoid"
    else:
        kind = (
            "special Grashof "
            + {
                "crank": "crank-rocker",
                "output": "rocker-crank",
                "ground": "double crank",
                "coupler": "double rocker",
            }[shortest]
        )
    # with S + L = P + Q a shortest link turns fully relative to its neighbours (through
    # the change points); there may be two shortest links
    short = {k for k, v in lengths.items() if _eq(v, s)}
    turns_in = bool(short & {"crank", "ground"})
    turns_out = bool(short & {"output", "ground"})
    return Grashof(
        crank, coupler, output, ground, s, l, p, q, shortest, rel, kind, turns_in, turns_out
    )


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
        """The path passes through the crank's pivot (offset e = 0)."""
        return abs(self.e) <= SAME * self.l

    @property
    def n(self) -> float:
        """The ratio of the rod's length to the crank's, n = l / r."""
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
    return FourBar(
        cr.pivot,
        cr.tip,
        dy.point,
        g,
        cr.link,
        coupler,
        output,
        cr.length,
        r3,
        r4,
        math.hypot(gx - cx, gy - cy),
        dy,
    )


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
    return SliderCrank(
        cr.pivot, cr.tip, sd.point, cr.link, sd.link, cr.length, sd.length, e, (ux, uy), sd
    )


def slotted_of(scene: Scene):
    """The crank and the slotted link of a crank and slotted lever (the block at the crank
    pin, the lever about a ground pivot), or None."""
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


def standing_steps(scene, plan) -> set:
    """The indices of the steps that find a point from fixed points only (a pivot placed
    by two links from ground points: a structure, not a moving part): they drive nothing
    and their transmission angle never changes."""
    fixed, still = set(scene.ground), set()
    for st in plan.steps[1:]:
        if set(st.needs) <= fixed:
            fixed.update(st.finds)
            still.add(st.index)
    return still


def _output_of(scene, plan):
    out = None
    still = standing_steps(scene, plan)
    for st in plan.steps:  # the last step that drives something is the output
        if st.index in still:
            continue
        o = st.output(scene.ground)
        if o is None:
            continue
        if o[0] == "rocker":
            out = _Output("rocker", o[1], f"output link {o[1]}", o[2], o[3])
        elif o[0] == "slider":
            out = _Output("slider", o[1], f"slider {o[1]}", point=o[1], path=scene.slider(o[1]))
        else:
            out = _Output("lever", o[1], f"lever {o[1]}", o[2], o[3])
    return out
