"""The slider crank's approximate textbook formulas beside the exact values."""

from __future__ import annotations

import math

import numpy as np

from ..common.tolerances import ROUNDING
from ..scene import Scene
from ..solver.tracking import TWO_PI
from .cycle import _Cycle, stands_still
from .shapes import SliderCrank, slider_crank_of


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
    px, py = cyc.fr.P[sk.b]  # the stroke over the sampled cycle
    along = np.broadcast_to((px - ox) * d[0] + (py - oy) * d[1], cyc.grid.shape)[~cyc.bad]
    if not len(along) or stands_still(float(along.max() - along.min()), scene):
        return [
            f"in-line slider crank: slider {sk.b} stands still on this branch (it stays "
            f"at the crank centre {sk.o}, the rod being as long as the crank): the "
            "approximate formulas do not apply"
        ]
    vx, vy = fr0.V[sk.b]
    ax, ay = fr0.A[sk.b]
    xe = l + r - float(((x - ox) * d[0] + (y - oy) * d[1])[0])
    ve = -float((vx * d[0] + vy * d[1])[0])
    ae = -float((ax * d[0] + ay * d[1])[0])
    ale = sg * al
    xa = r * ((1 - math.cos(t)) + math.sin(t) ** 2 / (2 * n))
    va = r * W * (math.sin(t) + math.sin(2 * t) / (2 * n))
    aa = r * W * W * (math.cos(t) + math.cos(2 * t) / n) + r * ale * (
        math.sin(t) + math.sin(2 * t) / (2 * n)
    )
    wr = abs(float(fr0.W[sk.rod][0]))
    alr = abs(float(fr0.Al[sk.rod][0]))
    wra = W * abs(math.cos(t)) / n
    alra = W * W * abs(math.sin(t)) / n
    rows = [
        ("piston displacement from i.d.c. x", "m", xe, xa, "r [(1 - cos t) + sin^2 t / 2n]"),
        ("piston velocity v (toward the crank)", "m/s", ve, va, "r w (sin t + sin 2t / 2n)"),
        (
            "piston acceleration a (toward the crank)",
            "m/s^2",
            ae,
            aa,
            "r w^2 (cos t + cos 2t / n)" + (" + r alpha (sin t + sin 2t / 2n)" if al else ""),
        ),
        (f"rod {sk.rod}: |omega|", "rad/s", wr, wra, "w cos t / n"),
        (f"rod {sk.rod}: |alpha|", "rad/s^2", alr, alra, "w^2 sin t / n"),
    ]
    out = [
        f"in-line slider crank: n = l / r = {n:.6g}; crank {math.degrees(t):.4f} deg from "
        "inner dead centre (t, in the sense of rotation)"
        + ("; the formulas take the crank speed as uniform" if al else "")
    ]
    wlab = max(len(rw[0]) for rw in rows)
    out.append(f"  {'quantity':<{wlab}} {'exact':>12} {'formula':>12} {'error':>9}  formula")
    sizes = {
        "m": r,
        "m/s": r * W,
        "m/s^2": r * (W * W + abs(al)),
        "rad/s": W,
        "rad/s^2": W * W + abs(al),
    }
    for name, unit, ex, ap, form in rows:
        err = _err(ap, ex, sizes[unit])
        zero = ROUNDING * sizes[unit]  # rounding noise about a true zero is written 0
        ex, ap = (0.0 if abs(v) <= zero else v for v in (ex, ap))
        out.append(f"  {name:<{wlab}} {ex:>12.6g} {ap:>12.6g} {err:>9}  {form} ({unit})")
    out.append(_max_velocity_line(cyc, sk, d, th_idc, sg * W))
    return out


def _max_velocity_line(cyc: _Cycle, sk: SliderCrank, d, th_idc, w) -> str:
    """The maximum piston velocity, exact (refined over the cycle) and by the formula
    ``cos t = (-n + sqrt(n^2 + 8)) / 4``; ``d`` the line of stroke towards the inner dead
    centre, at the crank's angle ``th_idc``, ``w`` the crank's omega."""
    r, n, W = sk.r, sk.n, abs(w)
    sg = 1.0 if w > 0 else -1.0
    tm, vm = cyc.extreme(lambda fr: -(fr.V[sk.b][0] * d[0] + fr.V[sk.b][1] * d[1]), 1.0)
    tmx = (sg * (tm - th_idc)) % TWO_PI
    c = (-n + math.sqrt(n * n + 8)) / 4
    ts = math.acos(c)
    vs = r * W * (math.sin(ts) + math.sin(2 * ts) / (2 * n))
    return (
        f"  maximum piston velocity: exact {vm:.6g} m/s at {math.degrees(tmx):.4f} deg "
        f"from i.d.c.; formula {vs:.6g} m/s at {math.degrees(ts):.4f} deg "
        f"(cos t = (-n + sqrt(n^2 + 8)) / 4 = {c:.6g}), error {_err(vs, vm, r * W).strip()}"
    )


def _err(approx, exact, size) -> str:
    """The formula's error in per cent of the exact value; "n/a" where the exact value is
    zero (to rounding, :data:`ROUNDING` of the quantity's ``size``) and the formula's is not."""
    zero = ROUNDING * size
    if abs(exact) <= zero:
        return "0" if abs(approx) <= zero else "n/a"
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
