"""The force step of a driving block (``[input] block``): the last one solved, as the
crank's is. The block slides on a fixed, frictionless guide (unit ``u``, normal ``n =
perp(u)``); its driver (a ram, a screw, a hand) pushes it along the guide with the force
``F u``, the guide holds it with ``N n``; every other force on it (R, through its pin) is
known by now::

    F u + N n + R = 0   =>   F = -R . u,   N = -R . n

The driver's reaction ``-F u`` and the guide's ``-N n`` act on the frame at the block.

>>> solve((3.0, 4.0), (1.0, 0.0))     # 3 N against the guide's direction, 4 N across
(-3.0, -4.0)
"""

from __future__ import annotations

from ..common.numbers import fmt
from .bodies import sums_add, sums_of
from .records import FRAME, ForceStep, GuideForce, Side, block


def solve(known, u):
    """(F along u, N along n = perp(u)) that hold the block against ``known`` (Fx, Fy)."""
    rx, ry = known[0], known[1]
    ux, uy = u
    return -(rx * ux + ry * uy), -(-rx * uy + ry * ux)


def owns(st) -> dict:
    """The block's point acts, for loads and later pins, on the block."""
    return {st.point: block(st.point)}


def blocks(st) -> tuple:
    return (st.point,)


def bind(st, own, ix):
    x, bl = st.point, block(st.point)
    i = ix(bl)
    ux, uy = st.path.u

    def run(P, S, pins, guides):
        f, n = solve(sums_of(S, i), (ux, uy))
        guides.append((x, n, (-uy, ux), FRAME))
        xx, xy = P[x]
        sums_add(S, 0, -(f * ux + n * -uy), -(f * uy + n * ux), xx, xy)
        return f

    return run


def step(st, P, led, own):
    """The guide's normal force and the driver's force along the guide. Returns as
    :func:`.dyad.step`, the driver's force (N, signed along ``u``) in the torque's place."""
    x, bl = st.point, block(st.point)
    kb = led.of(bl)
    ux, uy = st.path.u
    f, n = solve(kb, (ux, uy))
    g = GuideForce(x, n, (-uy, ux), FRAME)
    xx, xy = P[x]
    known = led.known(bl)
    led.add(FRAME, -(f * ux + n * -uy), -(f * uy + n * ux), xx, xy)
    eq, drawing = (), None
    if isinstance(f, float):

        def drawing():
            # the pole, the block's known forces, the driver's force along the guide, the
            # guide's across it: their lines meet where it closes
            k = len(known)
            push = Side("driver", bl, FRAME, x, (f * ux, f * uy), (xx, xy))
            held = Side("guide", bl, FRAME, x, g.force, (xx, xy))
            return known + (push, held), ((k, (ux, uy)), (k + 1, g.n)), ()

        eq = (
            f"the block: F u + N n + R = 0, R = ({fmt(kb[0])}, {fmt(kb[1])}) N the known "
            f"forces on {bl}",
            f"F = -R . u = {fmt(f)} N (the driver's force along the guide), N = -R . n = "
            f"{fmt(n)} N (the guide's)",
        )
    rec = ForceStep(
        st.index,
        "block",
        st.title,
        (bl,),
        (kb,),
        ((f"N_{x} on {bl} by the guide", n), (f"F on {bl} by its driver, along the guide", f)),
        1.0,
        "",
        eq,
        drawing,
    )
    return (), (g,), rec, f
