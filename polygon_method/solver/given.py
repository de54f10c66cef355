"""The input's motion given on another quantity than the crank's speed.

A book may set the position by the crank's angle but give the motion elsewhere: "the
piston moves at 5 m/s", "the coupler turns at 3 rad/s cw", "B moves down at 3 m/s". The
polygons are linear in the crank's speed: at the crank's angle, with the crank turning at
1 rad/s (``alpha = 0``), every velocity is ``Y1`` per rad/s and every acceleration ``H``
per (rad/s)^2, so the given quantity is::

    Y = omega * Y1                      ->  omega = Y / Y1
    Y' = alpha * Y1 + omega^2 * H       ->  alpha = (Y' - omega^2 H) / Y1

(superposition: the motion due to the crank's alpha plus that due to its speed). Where
``Y1`` is zero the given quantity does not move whatever the crank's speed (a dead centre
for a piston): the crank's speed is unbounded, and the step says so with its condition,
``|Y1|`` over its size at the crank's tip (``r`` for a velocity, 1 for an omega).

>>> from polygon_method.scene import parse_scene
>>> from polygon_method.solver.compiler import compile_plan
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
... angle = 90
... vs_B = "-1.5 m/s"
... ''')
>>> plan = compile_plan(sc)
>>> round(sc.input.omega, 12)   # at 90 deg the piston moves as fast as the crank pin
10.0
"""

from __future__ import annotations

import math
from dataclasses import replace

from ..common.errors import TOL, SingularStepError
from ..common.numbers import condition_text, quiet, sense
from ..common.tolerances import DISTINCT, ROUNDING, SAME
from .plan import Context, Plan
from ..scene import GIVEN_KINDS

__all__ = [
    "resolve",
    "quantity",
    "Resolution",
    "completed",
    "stated",
    "working",
    "held",
    "placing",
    "place_roots",
]


class Resolution:
    """How the crank's speed was found from the given motion: ``omega``, ``alpha``, the
    quantity per rad/s (``per_omega``), its rate per (rad/s)^2 at a uniform crank
    (``per_omega2``), the ``condition`` and a note for the output."""

    __slots__ = ("omega", "alpha", "per_omega", "per_omega2", "condition", "notes", "rate")

    def __init__(self, omega, alpha, per_omega, per_omega2, condition, notes, rate=None):
        self.omega, self.alpha, self.rate = omega, alpha, rate
        self.per_omega, self.per_omega2 = per_omega, per_omega2
        self.condition, self.notes = condition, notes


def quantity(given, m, scene):
    """(value, rate) of a given angular velocity or sliding velocity in a filled State
    ``m`` (a point's speed is read along its motion where it is resolved)."""
    if given.kind == "omega":
        key = scene.link("-".join(given.names)).key
        return m.W[key], m.Al[key]
    s = m.S[given.names[0]]
    return s[0], s[1]


def resolve(plan: Plan) -> Resolution:
    """The crank's omega and alpha that give the scene's stated motion (see the module)."""
    sc = plan.scene
    inp, given = sc.input, sc.input.given
    label = f"the given motion {given.key} = {given.text}"
    m = plan.run(Context(inp.angle, 1.0, 0.0))
    notes = []
    direction = given.direction
    r = sc.link(inp.crank).length
    if given.kind == "v":
        (vx, vy) = m.V[given.names[0]]
        speed1 = math.hypot(vx, vy)
        size = r
        cond = speed1 / size
        _check(cond, label, given, inp)
        cos = (vx * direction[0] + vy * direction[1]) / speed1
        off = math.degrees(math.acos(max(-1.0, min(1.0, abs(cos)))))
        if off > 30.0:
            raise SingularStepError(
                f"{given.names[0]} cannot move as {given.key} = {given.text} says: here it "
                f"moves along {math.degrees(math.atan2(vy, vx)) % 180.0:.4g} deg (or the "
                f"opposite way), {off:.3g} deg from the stated direction; give its direction "
                "as the mechanism allows",
                step=f"[input] {given.key}",
            )
        if off > DISTINCT:
            notes.append(
                f"{given.key}: {given.names[0]} moves along "
                f"{math.degrees(math.atan2(vy, vx)) % 360.0:.6g} deg here, {off:.3g} "
                "deg from the stated direction: the stated speed is taken along its "
                "true direction"
            )
        sign = 1.0 if cos > 0 else -1.0
        y1 = sign * speed1  # the speed along the true direction, per rad/s
        direction = (sign * vx / speed1, sign * vy / speed1)
        h = m.A[given.names[0]][0] * direction[0] + m.A[given.names[0]][1] * direction[1]
        omega = given.value / y1
        # the rate of change of speed: a . (v / |v|), v = given.value * direction
        s = 1.0 if given.value > 0 else -1.0
        if given.rate is not None:
            alpha = (s * given.rate - omega * omega * h) / y1
        else:
            alpha = None
        if given.rate is None and inp.alpha is None:
            alpha = -omega * omega * h / y1  # steady: the rate of change of speed is 0
    else:
        for st in plan.steps:  # a cylinder at the end of its stroke: against its stop
            stop = st.stop_words(m.P, given.names[0], given.value)
            if stop:
                raise SingularStepError(f"{label}: {stop}", step=f"[input] {given.key}")
        y1, h = quantity(given, m, sc)
        size = 1.0 if given.kind == "omega" else r
        cond = abs(y1) / size
        _check(cond, label, given, inp)
        if given.kind == "omega" and _fixed_ratio(plan, sc.link("-".join(given.names)).key):
            cond = 1.0  # a gear train's ratio: the same at every angle, no dead centre
        omega = given.value / y1
        rate = given.rate if given.rate is not None else (0.0 if inp.alpha is None else None)
        alpha = None if rate is None else (rate - omega * omega * h) / y1
    if given.rate is None and inp.alpha is None:
        notes.append(
            f"{_rate_key(given)} = 0 is taken: the given motion is steady (give "
            f"{_rate_key(given)} or the crank's acceleration to set it)"
        )
    rate = given.rate if given.rate is not None else (0.0 if inp.alpha is None else None)
    if alpha is None:
        alpha = inp.alpha
    cond = min(cond, 1.0)
    return Resolution(omega, alpha, y1, h, cond, tuple(notes), rate)


def growth_words(res) -> str:
    """Why a crank's speed and acceleration found from a given motion may be large: the
    condition of this input (the quantity per rad/s of the crank, at most 1) and how they
    grow towards a dead centre for it (``omega = value / c``; at a steady given motion
    ``alpha = -omega^2 h / c``, h its rate per (rad/s)^2: as ``1 / c^3``); "" where the
    condition is 1 (nothing amplified).

    >>> from types import SimpleNamespace as NS
    >>> print(growth_words(NS(condition=0.1, rate=None)))
    condition 0.1 of this input: its value per rad/s of the crank, 0 at a dead centre for it as where a rocker given as the input reaches its limit; the crank's speed grows as 1 / c towards it
    """
    c = res.condition
    if not c < 1.0:
        return ""
    return (
        f"condition {c:.3g} of this input: its value per rad/s of the crank, 0 at a dead "
        "centre for it as where a rocker given as the input reaches its limit; the crank's "
        + (
            "speed grows as 1 / c and its acceleration as 1 / c^3 towards it"
            if res.rate is not None
            else "speed grows as 1 / c towards it"
        )
    )


def _fixed_ratio(plan, key) -> bool:
    """Whether link ``key`` turns at a fixed ratio of the crank (a gear of a train: its
    ``theta_rate``): a speed given on it divides by that ratio at every angle, so a small
    ratio is a reduction, not a dead centre."""
    return any(key in st.links and getattr(st, "theta_rate", None) is not None for st in plan.steps)


def _rate_key(given):
    """The [input] key of the given motion's rate (``alpha_BC``, ``as_B``, ``a_B``)."""
    return f"{GIVEN_KINDS[given.kind]}_{given.key.partition('_')[2]}"


def _check(cond, label, given, inp):
    if not cond >= TOL.singular:
        what = {
            "omega": f"link {''.join(given.names)} does not turn",
            "vs": f"the block {given.names[0]} does not slide",
            "v": f"{given.names[0]} does not move",
        }[given.kind]
        raise SingularStepError(
            f"{label} cannot set the crank's speed here: at this position {what} whatever "
            f"the crank {inp.crank}'s speed (a dead centre for this input; condition "
            f"{condition_text(cond)}): the crank's speed would be unbounded",
            step=f"[input] {given.key}",
        )


def completed(scene, res: Resolution):
    """The scene's input with the crank's omega and alpha found (the given motion kept)."""
    return replace(scene.input, omega=res.omega, alpha=res.alpha)


def stated(inp) -> str:
    """How the scene gives the motion, in words: ``the crank turns at 10 rad/s cw`` or
    ``vs_B = 5 m/s left`` (with its rate)."""
    g = inp.given
    if g is None:
        return inp.speed_text
    out = f"{g.key} = {g.text}"
    if g.rate is not None:
        out += f", {g.rate_key} = {g.rate_text}"
    return out


def working(plan, fmt) -> list:
    """The step table's lines for a crank speed found from the given motion (``fmt``
    writes a number): the polygons drawn for 1 rad/s first, then scaled, as a book
    does when the speed is given elsewhere; None where the crank's speed is given."""
    res, inp = plan.given, plan.scene.input
    if res is None:
        return None
    g, c = inp.given, inp.crank
    what = g.key + (" (along its motion)" if g.kind == "v" else "")
    unit = "rad/s" if g.kind == "omega" else "m/s"
    rate_unit = "rad/s^2" if g.kind == "omega" else "m/s^2"
    out = [
        f"the motion is given: {g.key} = {g.text} = {fmt(g.value)} {unit}; draw the "
        f"velocity polygon for omega_{c} = 1 rad/s ccw: on it {what} = "
        f"{fmt(res.per_omega)} {unit}; every velocity is proportional to omega_{c}, so "
        f"omega_{c} = {fmt(g.value)} / {fmt(res.per_omega)} = {fmt(abs(res.omega))} rad/s "
        f"{sense(res.omega)}"
    ]
    if res.rate is not None:
        rate_key = g.rate_key or _rate_key(g)
        # a true zero (the cylinder's line through the crank's pivot, square to it) is
        # written 0, on the size of the quantity per rad/s or, in m, of the crank
        h = quiet(
            res.per_omega2,
            max(abs(res.per_omega), 1.0 if g.kind == "omega" else plan.scene.link(c).length),
        )
        out.append(
            f"the acceleration polygon for the crank turning uniformly at 1 rad/s "
            f"gives {rate_key} = {fmt(h)} {rate_unit}; every "
            f"acceleration is alpha_{c} x (the velocity polygon at 1 rad/s) + "
            f"omega_{c}^2 x (that acceleration polygon), so alpha_{c} = "
            f"({fmt(res.rate)} - {fmt(abs(res.omega))}^2 x {fmt(h)}) / "
            f"{fmt(res.per_omega)} = {fmt(abs(res.alpha))} rad/s^2 "
            f"{sense(res.alpha)}"
        )
    grows = growth_words(res)
    if res.condition < TOL.warn:
        grows += (
            ": near a dead centre for this input, the crank's speed is very sensitive to "
            "the given motion"
        )
    if grows:
        out.append(grows)
    return out


def held(plan, theta):
    """(omega, alpha) arrays of the crank over the crank angles ``theta`` that hold the
    given motion at its stated value and rate (a cylinder extending at its stated rate, a
    piston at its stated speed) over a sweep: the same relation as :func:`resolve`, at each
    angle, from one evaluation at 1 rad/s. Where the quantity does not move (a dead centre)
    the crank's speed is unbounded: those angles are masked by the caller (inf)."""
    import numpy as np

    res, inp = plan.given, plan.scene.input
    g = inp.given
    ctx = Context(theta, 1.0, 0.0, array=True)
    with np.errstate(all="ignore"):
        m = plan.run(ctx)
        if g.kind == "v":
            (vx, vy), (ax, ay) = m.V[g.names[0]], m.A[g.names[0]]
            sp = np.hypot(vx, vy)
            v0x, v0y = _dir0(plan)
            # the way it moves at the scene's instant, followed continuously
            turn = np.where(vx * v0x + vy * v0y >= 0, 1.0, -1.0) * np.sign(res.per_omega)
            y1 = turn * sp
            h = turn * (ax * vx + ay * vy) / np.where(sp > 0, sp, 1.0)
            value = g.value
            rate = None if res.rate is None else (res.rate if g.value > 0 else -res.rate)
        else:
            y1, h = quantity(g, m, plan.scene)
            value, rate = g.value, res.rate
        size = 1.0 if g.kind == "omega" else plan.scene.link(inp.crank).length
        # where the quantity hardly moves the crank's speed is unbounded (as resolve says)
        y1 = np.where(np.abs(y1) >= TOL.singular * size, y1, np.nan)
        omega = value / y1
        alpha = (
            (rate - omega * omega * h) / y1 if rate is not None else np.full_like(omega, inp.alpha)
        )
    return omega, alpha


def _dir0(plan):
    """The direction a point given a velocity moves in at the scene's instant (1 rad/s)."""
    m = plan.run(Context(plan.scene.input.angle, 1.0, 0.0))
    vx, vy = m.V[plan.scene.input.given.names[0]]
    return vx, vy


# --------------------------------------------------------------------------- the position


def placing(scene):
    """``g(P)``: how far the positions ``P`` are from the position the scene states
    otherwise than by the crank's angle (:class:`~polygon_method.scene.PositionGiven`), zero
    where they give it; floats or arrays. For a direction, ``sin(phi - value)``, with
    ``cos(phi - value)`` to tell the direction from its opposite (``ahead``)."""
    pl = scene.input.placed
    if pl.kind == "length":
        a, b = pl.names

        def g(P):
            (ax, ay), (bx, by) = P[a], P[b]
            return ((bx - ax) ** 2 + (by - ay) ** 2) ** 0.5 - pl.value

        return g, None
    if pl.kind == "s":
        sl = scene.slider(pl.names[0])
        (qx, qy), (ux, uy) = sl.through, sl.u
        x = pl.names[0]

        def g(P):
            px, py = P[x]
            return (px - qx) * ux + (py - qy) * uy - pl.value

        return g, None
    a, b = pl.names
    c, s_ = math.cos(pl.value), math.sin(pl.value)

    def g(P):
        (ax, ay), (bx, by) = P[a], P[b]
        dx, dy = bx - ax, by - ay
        n = (dx * dx + dy * dy) ** 0.5
        return (c * dy - s_ * dx) / n  # sin(phi - value)

    def ahead(P):
        (ax, ay), (bx, by) = P[a], P[b]
        return c * (bx - ax) + s_ * (by - ay) > 0

    return g, ahead


def place_roots(plan, grid=720):
    """The crank angles (rad, in one turn from the plan's own) that give the stated
    position: sign changes of ``g`` over a grid of the turn, each refined by bisection to
    the last bit; with the plan's branches. Returns (roots, the range of the quantity seen
    over the turn as (min, max) or None)."""
    import numpy as np

    sc = plan.scene
    g, ahead = placing(sc)
    theta0 = sc.input.angle
    th = theta0 + np.linspace(0.0, 2.0 * math.pi, grid + 1)
    ctx = Context(th, 1.0, 0.0, array=True)
    with np.errstate(all="ignore"):
        m = plan.run(ctx, upto=0)
        val = np.asarray(g(m.P), dtype=float) * np.ones(len(th))
    ok = np.isfinite(val)
    if ctx.bad is not None:
        ok &= ~np.broadcast_to(ctx.bad, th.shape)
    seen = (float(val[ok].min()), float(val[ok].max())) if ok.any() else None

    def f(t):
        try:
            mm = plan.run(Context(t, 1.0, 0.0), upto=0)
        except Exception:  # noqa: BLE001  (cannot assemble there: no root)
            return None
        return g(mm.P), (ahead(mm.P) if ahead is not None else True)

    roots = []
    for i in range(grid):
        if not (ok[i] and ok[i + 1]):
            continue
        a, b = float(th[i]), float(th[i + 1])
        fa, fb = val[i], val[i + 1]
        if fa == 0.0:
            cand = a
        elif fa * fb < 0:
            for _ in range(80):  # bisection to the last bit
                mid = 0.5 * (a + b)
                r = f(mid)
                if r is None or mid in (a, b):
                    break
                if (r[0] < 0) == (fa < 0):
                    a, fa = mid, r[0]
                else:
                    b = mid
            cand = 0.5 * (a + b)
        else:
            continue
        r = f(cand)
        if r is not None and r[1]:
            roots.append(math.remainder(cand, 2.0 * math.pi))
    scale = max([lk.length for lk in sc.links] + [abs(sc.input.placed.value)])
    edges = _edge_roots(th, ok, f, scale)  # a stroke's end, exactly: no sign change there
    roots += [t for t, v, met in edges if met]
    if edges and seen is not None:  # the range seen reaches the ends found
        ends = [v for _, v, _ in edges]
        seen = (min(seen[0], *ends), max(seen[1], *ends))
    out = []
    for t in roots:  # a root at a grid point may be found twice
        if all(abs(math.remainder(t - u, 2.0 * math.pi)) > ROUNDING for u in out):
            out.append(t)
    return out, seen


def _edge_roots(th, ok, f, scale) -> list:
    """Where the mechanism stops assembling between two grid angles (a cylinder's stroke
    ends, a dyad's reach), the last angle that assembles, by bisection to the last bit;
    ``(angle, the quantity there less the value stated, whether it is met there to
    rounding)`` for each: a root where it is met (``length_OR`` at a stroke's end: no sign change brackets
    it). ``f`` the quantity less the stated value and its direction check, or None."""
    out = []
    for i in range(len(th) - 1):
        if bool(ok[i]) == bool(ok[i + 1]):
            continue
        good, bad = (float(th[i]), float(th[i + 1])) if ok[i] else (float(th[i + 1]), float(th[i]))
        for _ in range(80):
            mid = 0.5 * (good + bad)
            if mid in (good, bad):
                break
            if f(mid) is None:
                bad = mid
            else:
                good = mid
        r = f(good)
        if r is None:
            continue
        met = abs(r[0]) <= SAME * scale and bool(r[1])
        out.append((math.remainder(good, 2.0 * math.pi), r[0], met))
    return out
