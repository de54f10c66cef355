"""Coulomb friction at the sliding guides and the pins (``[friction]``), on the same walk.

At a guide the block feels ``mu |N|`` along the guide, against its sliding relative to
the guide (``v_rel``: the block's point's velocity less that of the guide's point under
it); the guide's body feels it back. At a pin of radius r (``[pins]``) the force between
the two bodies is tangent to the friction circle of radius ``mu r``: the same force
through the pin's centre and a couple ``mu r |F|`` against the relative turning
``omega_on - omega_by`` (on ``on``; ``by`` feels it back; a block, which cannot turn on its
guide, passes its couple to the guide: the frame, or the link it slides on). Each friction force is known
once the normal forces are, which are known once the friction is: the walk is repeated
with the friction of the forces found before, until the forces settle (each pass changes
them by about mu r over the mechanism's arms, a small fraction; :data:`ROUNDS` passes at
most, else the mechanism is said to lock itself). Where nothing slides (relative velocity
zero) the friction is static and not determined by the statics: it is taken as zero there.

How far the forces may be off for the passes (:func:`settling`): the walk is linear in the
friction loads and each pass shrinks their change by the contraction ``q``, so the forces
of the last pass are off from the settled ones by at most ``q / (1 - q)`` times their last
change (a geometric tail); the rounding of each pass is carried on through the friction
loads, amplified by ``1 / (1 - q)`` at most. ``q`` is estimated from the passes (the
largest ratio of two successive changes measured above the rounding).

Every friction force works against the motion: its power ``-mu |N| |v_rel|`` at a guide,
``-mu r |F| |omega_rel|`` at a pin (:func:`power`), which the power balance then holds.

>>> sgn(-2.0), sgn(0.0), sgn(3.0)
(-1.0, 0.0, 1.0)
"""

from __future__ import annotations

import math

from ..common.tolerances import SETTLED
from ..steps.rounding import vhypot
from .records import FRAME, Side, block

#: the passes of the walk before friction is asked whether it is still settling (they have
#: settled when the loads change by less than ``SETTLED`` of the largest force:
#: common/tolerances.py); near locking the passes shrink their change slowly (by 0.905 a
#: pass with mu 0.5 where 0.552 locks): :func:`more_rounds` lets them go on, to
#: :data:`MOST_ROUNDS` at most
ROUNDS = 200
MOST_ROUNDS = 20_000


def more_rounds(moved, target, n) -> tuple:
    """(the passes in all the forces need to settle, the ratio their change shrinks by a
    pass) after ``n`` passes whose friction loads changed by ``moved`` (each pass's
    :func:`change`): the ratio of the last ten changes, geometric; where it is below 1 the
    passes it takes to bring the last change under ``target`` (N), and ten more; ``n`` (no
    more) where the changes do not shrink (the friction locks the mechanism: no forces
    balance it) or would need more than :data:`MOST_ROUNDS`.

    >>> more_rounds([0.5 ** k for k in range(12)], 0.5 ** 30, 12)
    (41, 0.5)
    """
    if len(moved) < 11 or not moved[-11] > 0.0 or not moved[-1] > 0.0:
        return n, 1.0
    r = (moved[-1] / moved[-11]) ** 0.1
    if not r < 1.0:
        return n, r
    need = n + math.ceil(math.log(target / moved[-1]) / math.log(r)) + 10
    return (need if need <= MOST_ROUNDS else n), r


def sgn(x):
    """+1, -1 or 0 (floats or arrays)."""
    return (x > 0) * 1.0 - (x < 0) * 1.0


def _omega(scene, motion, body):
    """A body's angular velocity: a link's; a block turns with its moving guide."""
    if body == FRAME:
        return 0.0
    if body.startswith("block "):
        sl = scene.slider(body[6:])
        guide = getattr(sl, "guide", None)
        return motion.W[scene.link(guide).key] if guide else 0.0
    return motion.W.get(body, 0.0)


def _turner(scene, body):
    """The body a couple on ``body`` turns: a block cannot turn on its guide, which takes
    the couple (a fixed path: the frame; a moving link: the link)."""
    if not body.startswith("block "):
        return body
    guide = getattr(scene.slider(body[6:]), "guide", None)
    return scene.link(guide).key if guide else FRAME


def _guide_velocity(scene, motion, by, X):
    """The velocity of the guide's point under the block at X (the guide ``by``)."""
    if by == FRAME:
        return 0.0, 0.0
    x, y = motion.P[X]
    if by.startswith("block "):  # a translating yoke
        return tuple(motion.V[by[6:]])
    lk = scene.link(by)
    (px, py), (vx, vy), w = motion.P[lk.p], motion.V[lk.p], motion.W[lk.key]
    return vx - w * (y - py), vy + w * (x - px)


def loads(scene, motion, pins, guides) -> tuple:
    """The friction of the forces found: ((body, what, (fx, fy), (x, y)) forces at guides,
    (body, what, couple) couples at pins), with their reactions, and the friction power
    (each term's); the frame's share too (the shaking force and moment count it)."""
    fr = scene.friction
    out = []
    if fr.any_guides:
        for g in guides:
            X = g.point
            mu = fr.guide(X, g.key)
            if not mu:
                continue
            vx, vy = motion.V[X]
            gx, gy = _guide_velocity(scene, motion, g.by, X)
            ux, uy = g.n[1], -g.n[0]  # along the guide
            vs = (vx - gx) * ux + (vy - gy) * uy
            f = -mu * abs(g.normal) * sgn(vs)
            x, y = motion.P[X]
            slot = g.key[len(X) + 1 :] if g.key != X else ""  # a peg's two slots apart
            where = "the fixed slot" if slot == "ground" else f"the slot of {slot}"
            what = f"friction in {where} at {X}" if slot else f"friction at the guide of {X}"
            out.append((block(X), what, (f * ux, f * uy), (x, y)))
            out.append((g.by, what, (-f * ux, -f * uy), (x, y)))  # (the frame: shaking)
    if fr.any_pins:
        radius = {p.point: p.radius for p in scene.pins}
        for p in pins:
            rho = fr.radius(p.point, radius.get(p.point))  # mu r, or the circle stated
            if not rho:
                continue
            rel = _omega(scene, motion, p.on) - _omega(scene, motion, p.by)
            c = -rho * vhypot(p.force[0], p.force[1]) * sgn(rel)
            what = f"friction at pin {p.point}"
            for body, cc in ((p.on, c), (p.by, -c)):
                out.append((_turner(scene, body), what, cc))
    return tuple(out)


def apply(led, items):
    """Enter the friction ``items`` (:func:`loads`) in the ledger as known loads, each
    force's ``by`` the body it rubs on (the pair of a guide's friction share its words: the
    block's on the guide's body, the reaction on the block), so that a peg's two slots'
    frictions are told apart (``\u03bcN\u2085\u2082``, ``\u03bcN\u2085\u2084``)."""
    pair = {}
    for it in items:
        if len(it) == 4:
            pair.setdefault(it[1], []).append(it[0])
    for it in items:
        if len(it) == 3:
            led.couple(it[0], it[2], it[1])
        else:
            body, what, (fx, fy), (x, y) = it
            by = next((b for b in pair[what] if b != body), "")
            led.add(
                body,
                fx,
                fy,
                x,
                y,
                what,
                Side("friction", body, by, what.split()[-1], (fx, fy), (x, y)),
            )


def scale(f) -> float:
    """The largest pin or guide force of the analysis ``f`` (N; at least 1e-300)."""
    vals = [
        float(getattr(v, "max", lambda v=v: v)())
        for v in [vhypot(p.force[0], p.force[1]) for p in f.pins]
        + [abs(g.normal) for g in f.guides]
    ]
    return max(vals + [1e-300])


def size(a) -> float:
    """The largest of the friction loads ``a`` (:func:`loads`): their change from none."""
    none = tuple(x[:2] + (0.0,) if len(x) == 3 else x[:2] + ((0.0, 0.0), x[3]) for x in a)
    return change(none, a)


def change(a, b) -> float:
    """The largest change between two passes' friction loads (N, or N m over a length)."""
    if a is None or len(a) != len(b):
        return float("inf")
    worst = 0.0
    for x, y in zip(a, b):
        if len(x) == 3:
            d = abs(x[2] - y[2])
        else:
            d = abs(x[2][0] - y[2][0]) + abs(x[2][1] - y[2][1])
        worst = max(worst, float(getattr(d, "max", lambda: d)()))
    return worst


#: a change between two passes smaller than this, relative to the largest force, is rounding
#: noise: no ratio of the contraction is read from it
NOISE = 1000.0 * SETTLED
#: the contraction taken where the passes settle too fast to measure it (two passes or
#: their changes already in the noise): the friction then moves nothing measurable
UNMEASURED = 0.5


def largest_changes(a, b) -> tuple:
    """(the largest change of a pin force's component or a guide's normal force, of the
    driver's effort, of a second input's effort) from the analysis ``a`` to ``b`` (N or
    N m; the largest over a sweep's angles)."""

    def most(x):
        return float(getattr(x, "max", lambda: x)())

    forces = [0.0]
    for p, r in zip(a.pins, b.pins):
        forces += [most(abs(p.force[0] - r.force[0])), most(abs(p.force[1] - r.force[1]))]
    forces += [most(abs(g.normal - h.normal)) for g, h in zip(a.guides, b.guides)]
    second = 0.0 if a.second_torque is None else most(abs(a.second_torque - b.second_torque))
    return max(forces), most(abs(a.input_torque - b.input_torque)), second


def settling(history, scale, loads=()) -> tuple:
    """(q, the forces' last change, the effort's, the second effort's) from the passes'
    :func:`largest_changes` (``history``, in order) and the force scale (N): q the largest
    ratio of two successive changes of the forces above :data:`NOISE`. Where none is
    measured (the passes settled at the second), the ratio of the friction loads' last two
    changes (``loads``: each pass's :func:`change` of them, the first their :func:`size`;
    the walk is linear in them, so the forces' next change shrinks as they do: nought
    where the second pass's loads reproduce the first's), else :data:`UNMEASURED`. The
    bounds (:mod:`.bounds`) add ``q / (1 - q)`` times the last changes and divide by
    ``1 - q``.

    >>> settling([(8.0, 1.0, 0.0), (2.0, 0.25, 0.0), (0.5, 0.0625, 0.0)], 100.0)
    (0.25, 0.5, 0.0625, 0.0)
    >>> settling([(16.0, 2.0, 0.0)], 160.0, (16.0, 0.0))  # the loads reproduced themselves
    (0.0, 16.0, 2.0, 0.0)
    """
    noise = NOISE * scale
    ratios = [b[0] / a[0] for a, b in zip(history, history[1:]) if a[0] > noise and b[0] > noise]
    if not ratios:
        ratios = [b / a for a, b in zip(loads, loads[1:]) if a > noise]
    q = max(ratios) if ratios else UNMEASURED
    last = history[-1] if history else (0.0, 0.0, 0.0)
    return (q,) + tuple(last)


def power(motion, scene, items) -> float:
    """The friction's power (W, never positive): each force times its point's velocity
    relative to the body it acts on's partner, each couple times its body's omega (the
    reactions included: the relative motion)."""
    total = 0.0
    for it in items:
        if len(it) == 3:
            total = total + it[2] * _omega(scene, motion, it[0])
        else:
            body, what, (fx, fy), (x, y) = it
            X = what.split()[-1]
            if body.startswith("block ") and body[6:] == X:
                vx, vy = motion.V[X]
            else:  # the guide's body: its own point under the block
                vx, vy = _guide_velocity(scene, motion, body, X)
            total = total + fx * vx + fy * vy
    return total
