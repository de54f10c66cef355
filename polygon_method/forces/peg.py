"""The force step of a peg in two slots: the peg at P (a pin, its mass at P) slides in
slot 1 and slot 2 (each a moving link's, or a fixed one), frictionless: slot i pushes it
with ``N_i n_i`` (``n_i = perp(u_i)``), through P, and its body feels ``-N_i n_i`` at P.
The peg's force balance with the known forces on it (R: its loads, its inertia and the
pins of the links hung on it, solved before)::

    N_1 n_1 + N_2 n_2 + R = 0,   N_1 = -(R x n_2) / (n_1 x n_2),   N_2 = -(n_1 x R) / (n_1 x n_2)

with ``n_1 x n_2 = u_1 x u_2``: zero when the slots run parallel (the kinematics' own
singularity; the condition ``|u_1 x u_2|``).

Slot 1 along x, slot 2 along y, 3 N to the right and 4 N up on the peg: slot 2 takes the
3 N (N_2 = 3 along n_2 = (-1, 0)), slot 1 the 4 N (N_1 = -4 along n_1 = (0, 1)):

>>> solve((3.0, 4.0), (1.0, 0.0), (0.0, 1.0))
(-4.0, 3.0, 1.0)
"""

from __future__ import annotations

from .bodies import Singular, any_zero, cross
from ..common.numbers import fmt
from ..scene import FixedPath
from .records import FRAME, ForceStep, GuideForce, block, Side


def solve(known, u1, u2):
    """(N_1, N_2, the condition ``|u_1 x u_2|``)."""
    rx, ry = known[0], known[1]
    n1, n2 = (-u1[1], u1[0]), (-u2[1], u2[0])
    det = cross(*n1, *n2)
    if any_zero(det):
        return None, None, 0.0
    return -cross(rx, ry, *n2) / det, -cross(*n1, rx, ry) / det, abs(det)


def owns(st) -> dict:
    """The peg's point acts, for loads and later pins, on the peg."""
    return {st.point: block(st.point)}


def blocks(st) -> tuple:
    return (st.point,)


def _body(s, own):
    """The body a slot is: the frame, or its link (the frame's, if fixed to the ground)."""
    if isinstance(s, FixedPath):
        return FRAME
    return FRAME if own.get(s.first) == FRAME and own.get(s.second) == FRAME else s.guide


def step(st, P, led, own):
    """The two slots' normal forces on the peg; each slot's body feels its back. Returns as
    :func:`.dyad.step`."""
    X, pb = st.point, block(st.point)
    k = led.of(pb)
    (g1x, g1y, u1x, u1y), (g2x, g2y, u2x, u2y) = st.lines(P)
    n1, n2, cond = solve(k, (u1x, u1y), (u2x, u2y))
    if n1 is None:
        raise Singular(f"the two slots at {X} run parallel")
    x, y = P[X]
    known = led.known(pb)
    out = []
    for s, n, (ux, uy) in ((st.first, n1, (u1x, u1y)), (st.second, n2, (u2x, u2y))):
        g = GuideForce(X, n, (-uy, ux), _body(s, own), 0.0, s.key)
        led.add(
            g.by,
            -g.force[0],
            -g.force[1],
            x,
            y,
            side=Side("guide", g.by, pb, X, (-g.force[0], -g.force[1]), (x, y)),
        )
        out.append(g)
    eq, drawing = (), None
    if isinstance(n1, float):

        def drawing():
            # the pole, the peg's known forces, each slot's normal force: their lines meet
            # where it closes
            k = len(known)
            sides = tuple(Side("guide", pb, g.by, X, g.force, (x, y)) for g in out)
            return known + sides, ((k, out[0].n), (k + 1, out[1].n)), ()

        eq = (
            f"the peg: N_1 n_1 + N_2 n_2 + R = 0, R = ({fmt(k[0])}, {fmt(k[1])}) N the "
            f"known forces on it: N_1 = {fmt(n1)} N ({out[0].by}), N_2 = {fmt(n2)} N "
            f"({out[1].by})",
        )
    rec = ForceStep(
        st.index,
        "peg",
        st.title,
        (pb,),
        (k,),
        tuple((f"N_{g.key} on {pb} by {g.by}", g.normal) for g in out),
        cond,
        "the sine of the angle between the slots",
        eq,
        drawing,
    )
    return (), tuple(out), rec, None


def divisor(st, rec, P, L):
    """A force balance divided by ``|u_1 x u_2|``: ``c L``."""
    return rec.condition * L
