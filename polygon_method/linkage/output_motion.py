"""The output's motion over the crank's cycle: where it stands still (the toggles, a slider
crank's dead centres, with why), its range (a slider's stroke, a lever's swing, or that it
turns fully) and the quick-return ratio of the two strokes, with the lines that print them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..common.tolerances import SAME
from ..solver.tracking import TWO_PI
from .cycle import _Cycle, stands_still
from .shapes import _Output

__all__ = ["Stationary", "output_motion", "stroke_turns", "path_origin", "shown_place"]


@dataclass(frozen=True)
class Stationary:
    """A crank angle where the output stands still (a toggle when driven from the output)."""

    theta: float
    deg: float
    output: float  # rad (rocker, lever) or m (slider)
    what: str


def output_motion(cyc: _Cycle, out: _Output, scene, fb, sk, slot, dwells=False):
    """(stationary, lines, min, max, time ratio, quick-return lines) of the output ``out``
    over the cycle ``cyc``; ``fb``, ``sk``, ``slot``: the four-bar, slider crank or slotted
    lever the scene is (or None), which name the toggles. An output that ``dwells`` (its
    rate nought to rounding over whole ranges: a degenerate linkage) has no single toggle
    positions: its rounding's hundreds of sign changes are not refined one by one (seconds
    of work thrown away), its range is its place's extremes, refined."""
    stats = [] if dwells else _stationary(cyc, out, scene, fb, sk, slot)
    vals = _ends(cyc, out, stats) + (_extremes(cyc, out) if dwells else [])
    # the output's range is a matter of positions: every sample that assembles counts,
    # also those where the velocities are indeterminate (a nearly locked linkage has no other)
    if out.kind == "slider":
        lines, omin, omax = _stroke(cyc, out, scene, vals)
    else:
        lines, omin, omax = _swing(cyc, out, vals)
    ratio, tlines = _quick_return(cyc, out, stats)
    return tuple(stats), tuple(lines), omin, omax, ratio, tuple(tlines)


def _stationary(cyc, out, scene, fb, sk, slot) -> list:
    """Where the output stands still (its rate 0), in the order of the crank's angle."""
    stats = []
    for t in cyc.zeros(out.rate):
        fr = cyc.at(t, vel=False)
        v = float(out.value(fr)[0])
        stats.append(
            Stationary(t, cyc.deg(t), v, _what_stationary(fr, out, scene, fb, sk, slot, v))
        )
    stats.sort(key=lambda s: s.deg)
    return stats


def _extremes(cyc, out) -> list:
    """The output's least and largest place over the cycle, each refined (an angle taken
    within half a turn of its first sample's)."""
    if out.kind == "slider":
        f = out.value
    else:
        ok = ~cyc.fr.bad
        ref = float(out.value(cyc.fr)[ok][0]) if ok.any() else 0.0

        def f(fr):
            return ref + (out.value(fr) - ref + math.pi) % TWO_PI - math.pi

    return [cyc.extreme(f, sense, positions=True)[1] for sense in (-1.0, 1.0)]


def _ends(cyc, out, stats) -> list:
    """The output's places where it may be extreme: where it stands still, at the crank's
    limit positions, and at the two ends of a turn that does not close."""
    dom = cyc.dom
    vals = [s.output for s in stats]
    if not dom.full_turn:
        for lp in dom.limits:
            fr = cyc.at(lp.theta, vel=False)
            vals.append(float(out.value(fr)[0]))
    elif dom.turn_only:  # a turn that does not close: its two ends bound the range
        for t in (dom.lo, dom.hi):
            vals.append(float(out.value(cyc.at(t, vel=False))[0]))
    return vals


def _stroke(cyc, out, scene, vals):
    """(lines, min, max) of a slider's place along its path: its stroke, or that it stands
    still (rounding about a standstill is no stroke)."""
    omin = omax = None
    all_v = out.value(cyc.fr)[~cyc.fr.bad]
    lines = [f"{out.label}: its place along the path is measured {path_origin(out.path, scene)}"]
    if vals and len(all_v):
        omin, omax = min(vals + [float(all_v.min())]), max(vals + [float(all_v.max())])
        if stands_still(omax - omin, scene):  # rounding about a standstill, no stroke
            mid = 0.5 * (omin + omax)
            omin = omax = 0.0 if stands_still(abs(mid), scene) else mid
            lines.append(f"{out.label}: stands still at {shown_place(out, omin, scene)}: no stroke")
        else:
            lines.append(
                f"{out.label}: moves between {shown_place(out, omin, scene)} and "
                f"{shown_place(out, omax, scene)}: stroke "
                f"{(omax - omin) / scene.length_unit:.6g} {scene.units}"
            )
    return lines, omin, omax


def _swing(cyc, out, vals):
    """(lines, min, max) of a lever's angle: it turns fully, or its swing (the angles in
    [-180, 180) deg), or the angle it moves through."""
    dom = cyc.dom
    omin = omax = None
    lines = []
    ang = np.unwrap(out.value(cyc.fr)[~cyc.fr.bad])
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
    return lines, omin, omax


def _quick_return(cyc, out, stats):
    """(time ratio, lines): where the crank turns fully and the output stands still twice,
    the crank's turn during each stroke and their ratio; not applicable where it rocks."""
    dom = cyc.dom
    if dom.full_turn and len(stats) == 2:
        w = cyc.sw.omega
        arc1, arc2 = stroke_turns(cyc, stats)
        mid = stats[0].theta + (1 if w > 0 else -1) * arc1 / 2
        sgn = float(out.rate(cyc.at(mid))[0])
        d1, d2 = _direction(out, sgn), _direction(out, -sgn)
        ratio = max(arc1, arc2) / min(arc1, arc2)
        alpha = abs(math.degrees(arc1) - 180.0)
        return ratio, [
            f"quick return: from crank {stats[0].deg:.4f} deg the crank turns "
            f"{math.degrees(arc1):.4f} deg while {out.label} moves {d1}, then "
            f"{math.degrees(arc2):.4f} deg while it moves {d2}",
            f"  time ratio {ratio:.6f} = (180 + {alpha:.4f}) / (180 - {alpha:.4f})"
            + ("  (equal strokes: no quick return)" if abs(ratio - 1) < SAME else ""),
        ]
    if not dom.full_turn:
        return None, ["quick return: not applicable (the crank does not turn fully)"]
    return None, []


def stroke_turns(cyc, stats) -> tuple:
    """(arc1, arc2), rad: the crank's turn, in its own sense, from the output's first
    standstill ``stats[0]`` to its second, then on round to the first (their sum 2 pi)."""
    t1, t2 = stats[0].theta, stats[1].theta
    arc1 = ((t2 - t1) * (1 if cyc.sw.omega > 0 else -1)) % TWO_PI
    return arc1, TWO_PI - arc1


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


def shown_place(out, v, scene) -> str:
    """The output's place as shown: a slider's along its path, a lever's angle."""
    if out.kind == "slider":
        return f"{v / scene.length_unit:.6g} {scene.units} along the path"
    return f"{math.degrees(v):.4f} deg"


def _direction(out, sgn) -> str:
    """Which way the output moves where its rate has the sign ``sgn``."""
    if out.kind == "slider":
        return "forward (+ along the path)" if sgn > 0 else "back (- along the path)"
    return "ccw" if sgn > 0 else "cw"


def _what_stationary(fr, out, scene, fb, sk, slot, v) -> str:
    """Why the output stands still at ``fr`` (a toggle: which links are in line), and
    where it is."""
    val = shown_place(out, v, scene)
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
