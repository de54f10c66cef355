"""An estimated bound on the rounding error of every force, from the kinematic bounds
(:mod:`polygon_method.solver.errorbound`) and the condition of each group's solve.

Each force is relative to the force scale ``F`` of the instant (the largest pin force,
guide force, inertia force, load or weight); each torque to ``F L`` (``L`` the longest
link, the position scale). Along the force analysis' walk (the kinematic plan in reverse):

- the known forces on a body err by its inertia's error, ``m |a_G| eA / F`` with ``eA``
  the bound of its centre's acceleration (the largest of its link's ends, times ``1 + |lam|
  + 2 |mu|`` for a centre carried off the link), and ``I alpha eAl / (F L)`` for its couple;
  loads and weights are exact, their arms err by the positions' bound ``eP``; a damper's
  given force ``-c vs`` by ``c`` times its rate of extension's bound;
- a group's equations divide the known moments by a length ``D``: a dyad's ``min(|CB|,
  |CD|) c / 2`` (its determinate ``|CB| |CD| c``, c the sine at its middle pin), a
  slider's ``|XB| c``, a slotted lever's ``|KA|`` (the block's distance from the pivot),
  a yoke's or a peg's ``c L`` (a force balance that divides by ``c``), a driving
  cylinder's arm about the crank's pivot; so the group's forces err by
  ``(L / D) (K eps + e_known + 2 eP)``, with ``e_known`` the largest error of what is known
  on its bodies and ``eP`` of its points' positions; the crank, a driving block and a
  carried point divide by nothing (``D = L``);
- the bodies the group's reactions act on (solved later) take that error into what is
  known on them.

Near a toggle ``D`` goes to zero and the bound grows without limit: it saturates (never
inf), and a bound of 1 or more is **no useful bound** (null in the JSON, with the reason).
A driving cylinder's force is found from the whole walk (``F = -T0 / T1``): the walk's
bound is carried twice, the second time with the cylinder's error on the bodies at its
ends. The same formulas take floats (one instant) or arrays (a sweep).

With friction the walk is repeated until the friction settles (:mod:`.friction`): each
bound then takes in the passes not made (the last change between two passes times ``q /
(1 - q)``, ``q`` the passes' contraction as they measured it) and the rounding carried
round through the friction loads (divided by ``1 - q``): :func:`_settled`.
"""

from __future__ import annotations

from ..common.tolerances import FLOOR
from dataclasses import dataclass

from ..steps.rounding import CAP, EPS, USELESS
from ..steps.rounding import largest, vhypot, vmax
from .records import FRAME, block
from ..scene.cylinder_loads import stated

__all__ = ["ForceBounds", "force_bounds", "K"]

#: the rounding constant of one group's solve (a handful of operations, with a margin)
K = 16.0
#: the reason given where a force's bound is no useful bound
NO_BOUND = (
    "no useful bound: near a toggle a group's equations divide by a vanishing "
    "length, and its forces grow without bound"
)


@dataclass(frozen=True)
class ForceBounds:
    """Relative error bounds of the force analysis: ``pins`` (point, on, by) -> bound,
    ``guides`` (the guide's key) -> bound, ``effort`` the driver's (a torque relative to
    ``force * length``, a force relative to ``force``), ``second`` a second crank's torque
    or None, ``steps`` step index -> the bound of its forces, ``force`` and ``length`` the
    scales. ``worst``: the largest."""

    pins: dict
    guides: dict
    effort: object
    second: object
    steps: dict
    force: object
    length: float
    #: with friction, the contraction q of the walk's passes the bounds took in, else None
    contraction: object = None

    @property
    def worst(self):
        """The largest relative bound of any force."""
        return largest(
            list(self.pins.values())
            + list(self.guides.values())
            + [self.effort]
            + ([self.second] if self.second is not None else [])
        )


def _cap(x):
    if isinstance(x, float):
        return x if x < CAP else CAP
    import numpy as np

    return np.fmin(np.nan_to_num(x, nan=CAP, posinf=CAP), CAP)


def _scale(sol, f):
    """The force scale: the largest force of the instant (never below the tiniest
    positive float: a mechanism with no force at all has nothing to err)."""
    sc = sol.scene
    vals = (
        [vhypot(*p.force) for p in f.pins]
        + [abs(g.normal) for g in f.guides]
        + [vhypot(*i.force) for i in f.inertia]
        + [vhypot(*ld.force) for ld in sc.loads if ld.force is not None]
    )
    if sc.gravity is not None:
        vals += [m.mass * sc.gravity.g for m in sc.masses]
    if f.driver not in ("crank", "wheel"):  # (a wheel's effort is a torque)
        vals.append(abs(f.input_torque))
    return vmax(largest(vals), FLOOR)


def _divisor(st, rec, P, L):
    """The length the group's equations divide by: its room's ``divisor`` (see the
    module); ``L`` (nothing divided) for a room without one."""
    from . import ROOMS

    room = ROOMS[st.kind]
    return room.divisor(st, rec, P, L) if hasattr(room, "divisor") else L


def _inertia_errors(sol, kb, F, L):
    """body -> the error of its inertia (relative to F; its couple's to F L)."""
    sc = sol.scene
    out = {}
    for m in sc.masses:
        if m.block:
            body, ea = block(m.body), kb.A.get(m.body, EPS)
            e = m.mass * ea * kb.scales["acceleration"] / F
        else:
            lk = sc.link(m.body)
            body = lk.key
            if body not in sol.W:
                continue
            ea = vmax(kb.A.get(lk.p, EPS), kb.A.get(lk.q, EPS)) * (
                1.0 + abs(m.lam) + 2.0 * abs(m.mu)
            )
            e = m.mass * ea * kb.scales["acceleration"] / F + m.inertia * kb.Al.get(
                body, EPS
            ) * kb.scales["alpha"] / (F * L)
        out[body] = vmax(out.get(body, 0.0), e)
    return out


def _walk(sol, f, kb, F, L, start):
    """One pass along the force steps (in the order solved): step index -> bound."""
    plan_steps = {st.index: st for st in sol.plan.steps}
    known = dict(start)
    out = {}
    for rec in f.steps:
        st = plan_steps[rec.index]
        pts = [p for p in (*st.needs, *st.finds) if p in kb.P]
        ep = largest([kb.P[p] for p in pts]) if pts else EPS
        e_in = largest([known.get(b, 0.0) for b in rec.bodies])
        D = _divisor(st, rec, sol.P, L)
        e = _cap((K * EPS + e_in + 2.0 * ep) * L / vmax(D, FLOOR))
        out[rec.index] = e
        for p in rec.pins:
            for b in (p.on, p.by):
                if b != FRAME and b not in rec.bodies:
                    known[b] = vmax(known.get(b, 0.0), e)
        for g in rec.guides:
            if g.by != FRAME and g.by not in rec.bodies:
                known[g.by] = vmax(known.get(g.by, 0.0), e)
    return out


def force_bounds(sol, f=None) -> ForceBounds:
    """The :class:`ForceBounds` of ``sol``'s force analysis (``f``: it, if at hand)."""
    f = sol.forces if f is None else f
    kb = sol.error_bounds
    L = float(kb.scales["position"])
    F = _scale(sol, f)
    start = _inertia_errors(sol, kb, F, L)
    for c in stated(sol.scene):  # a damper's force errs by c times its rate's error
        if c.damping and not sol.scene.at_rest:
            ev = kb.S[c.key][0] if c.key in kb.S else kb.V.get(c.rod, EPS) + kb.V.get(c.barrel, 0)
            start[c.key] = c.damping * ev * kb.scales["velocity"] / F
        if c.stiffness:  # a spring's by k times its length's error (its two ends')
            el = (kb.P.get(c.rod, EPS) + kb.P.get(c.barrel, 0)) * kb.scales["position"]
            start[c.key] = start.get(c.key, 0.0) + abs(c.stiffness) * el / F
    steps = _walk(sol, f, kb, F, L, start)
    driver = sol.plan.steps[0]  # the first input's step: a crank or a driving block
    by_index = {st.index: st for st in sol.plan.steps}
    cyl = (
        next((r for r in f.steps if r.bodies == (f.crank,)), None)
        if f.driver == "cylinder"
        else None
    )
    if cyl is not None:  # the effort comes from the whole walk
        D = _divisor(by_index[cyl.index], cyl, sol.P, L)
        e_f = _cap((K * EPS + steps[driver.index]) * L / vmax(D, FLOOR))
        start = dict(start)
        for p in cyl.pins:
            if p.by != FRAME:
                start[p.by] = vmax(start.get(p.by, 0.0), e_f)
        steps = _walk(sol, f, kb, F, L, start)
        steps[cyl.index] = e_f
    pins, guides = {}, {}
    for rec in f.steps:
        for p in rec.pins:
            pins[(p.point, p.on, p.by)] = steps[rec.index]
        for g in rec.guides:
            guides[g.key] = steps[rec.index]
    first = cyl.index if cyl is not None else driver.index
    second = next(
        (
            steps[r.index]
            for r in f.steps
            if f.second_crank is not None and r.bodies == (f.second_crank,)
        ),
        None,
    )
    b = ForceBounds(pins, guides, steps[first], second, steps, F, L)
    return _settled(b, f) if f.settling else b


def _settled(b, f) -> ForceBounds:
    """The bounds with friction (:func:`.friction.settling`): each force's bound ``e`` of
    the last pass becomes ``(e + t d) / (1 - q)``, ``d`` the last change between two passes
    (relative, as ``e``), ``t = q / (1 - q)`` the geometric tail of the passes left, and
    ``1 / (1 - q)`` the rounding carried round through the friction loads; no useful bound
    where the passes do not contract (``q >= 1``)."""
    q, d_force, d_effort, d_second = f.settling
    if not q < 1.0:
        return ForceBounds(
            {k: CAP for k in b.pins},
            {k: CAP for k in b.guides},
            CAP,
            None if b.second is None else CAP,
            {k: CAP for k in b.steps},
            b.force,
            b.length,
            q,
        )
    t, F, L = q / (1.0 - q), b.force, b.length

    def on(e, d):
        return _cap((e + t * d) / (1.0 - q))

    torque = f.driver in ("crank", "wheel")
    second = None
    if b.second is not None:
        two = 1.0 if f.second_crank.startswith("block ") else L
        second = on(b.second, d_second / (F * two))
    return ForceBounds(
        {k: on(e, d_force / F) for k, e in b.pins.items()},
        {k: on(e, d_force / F) for k, e in b.guides.items()},
        on(b.effort, d_effort / (F * (L if torque else 1.0))),
        second,
        {k: on(e, d_force / F) for k, e in b.steps.items()},
        F,
        L,
        q,
    )


def bounds_dict(b: ForceBounds) -> dict:
    """The ``forces`` entry of the JSON's ``error_bounds``: each bound, or None where it is
    no useful bound (``no_useful_bound`` then says how many and why)."""
    count = [0]

    def clean(x):
        if x < USELESS:
            return float(x)
        count[0] += 1
        return None

    pins = {}
    for (point, on, by), e in b.pins.items():
        pins.setdefault(point, []).append({"on": on, "by": by, "bound": clean(e)})
    d = {
        "relative_to": {"force": float(b.force), "moment": float(b.force * b.length)},
        "pins": pins,
        "guides": {k: clean(e) for k, e in b.guides.items()},
        "input": clean(b.effort),
    }
    if b.second is not None:
        d["second_input"] = clean(b.second)
    if b.contraction is not None:  # the friction's passes, taken in (see the module)
        d["friction_passes"] = {"contraction": float(b.contraction)}
    if count[0]:
        d["no_useful_bound"] = {"count": count[0], "reason": NO_BOUND}
    return d
