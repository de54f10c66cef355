"""A solution as the reports write it: its rounding noise set to exact zeros."""

from __future__ import annotations

from ..common.numbers import quiet
from ..solver.kinematics import hypot
from .solution import Solution

__all__ = ["tidied"]


def tidied(sol: Solution) -> Solution:
    """``sol`` with its rounding noise set to exact zeros, for reports that write every
    number out (the step table, the centres): a velocity, acceleration, omega, alpha,
    sliding velocity or acceleration within its own error bound (:meth:`Solution.noise`)
    is 0, so a link that does not turn has no sense and a block that does not slide no
    Coriolis component; a position below ``TOL.negligible`` of the mechanism's size is 0.
    A value above its bound stays, however small beside the largest of its kind."""
    sc = sol.scene
    size = max([lk.length for lk in sc.links] + [hypot(*p) for p in sol.P.values()] + [0.0])

    def vec(d, kind):
        if kind is None:
            return {n: (quiet(x, size), quiet(y, size)) for n, (x, y) in d.items()}
        out = {}
        for n, (x, y) in d.items():  # a component within the vector's bound: 0
            lim = sol.noise(kind, n)
            out[n] = (0.0 if abs(x) <= lim else x, 0.0 if abs(y) <= lim else y)
        return out

    def num(d, kind):
        return {n: sol.shown(x, kind, n) for n, x in d.items()}

    def slide(n, s):
        vs, a_s = sol.shown(s[0], "vs", n), sol.shown(s[1], "as", n)
        lim = sol.noise("ac", n)
        return (vs, a_s) + tuple(0.0 if abs(c) <= lim else c for c in s[2:])

    S = {n: slide(n, s) for n, s in sol.S.items()}
    out = Solution(
        sc,
        sol.plan,
        vec(sol.P, None),
        vec(sol.V, "v"),
        vec(sol.A, "a"),
        num(sol.W, "omega"),
        num(sol.Al, "alpha"),
        S,
        sol.cond,
        sol.theta,
    )
    b = sol.error_bounds
    k = b.scales
    for pin, rec in zip(sol.plan.pins, out.rubbing.values()):  # |w1 - w2| r of equal omegas
        e = b.rubbing(pin)
        lim = e * k["omega"] * rec.radius if e < 1.0 else 0.0
        rec.values = tuple(0.0 if abs(v) <= lim else v for v in rec.values)
        rec.rubbing_velocity = max(rec.values, default=0.0)
    t = out.input_torque
    if t is not None:
        # each load's power within its bound (the bound of the velocity or omega it takes,
        # times |F| or |T_L|), the torque within theirs over the crank's omega
        sizes = [
            hypot(*ld.force) * k["velocity"]
            if ld.force is not None
            else abs(ld.torque) * k["omega"]
            for ld in sc.loads
        ]
        e = b.torque(sc)
        e = e if e < 1.0 else 0.0
        loads = [
            b.V.get(ld.target, 0.0)
            if ld.force is not None
            else b.W.get(sc.link(ld.target).key, 0.0)
            for ld in sc.loads
        ]
        out._cache["power"] = [
            (what, 0.0 if abs(p) <= (el if el < 1.0 else 0.0) * sz else p)
            for (what, p), el, sz in zip(out.power_terms, loads, sizes)
        ] + out.power_terms[len(sc.loads) :]  # (a passive cylinder's F vs: kept)
        out._cache["torque"] = 0.0 if abs(t) <= e * sum(sizes) / abs(sc.input.omega) else t
    return out
