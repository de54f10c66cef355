"""The force step of a Scotch yoke: the yoke Y translates on a fixed path (unit ``u``,
normal ``n_u = perp(u)``); the block pinned at P (the crank pin) slides in its slot (unit
``d``, normal ``n_d = perp(d)``). The group is the yoke and the block; frictionless.

The slot's force on the block is ``N_d n_d`` through P (the block's loads pass through its
pin); the yoke feels ``-N_d n_d`` at P. The path holds the yoke with ``N_u n_u`` and, as a
prismatic pair, a couple ``C`` (the yoke cannot turn). The yoke's force balance along
``u`` has only the slot's force and the known ones (R_Y)::

    -N_d (n_d . u) + R_Y . u = 0   =>   N_d = R_Y . u / (n_d . u)

``n_d . u = -(u x d)``: zero when the slot runs along the path (the kinematics' own
singularity; its condition ``|u x d|``). Then across the path ``N_u = N_d (n_d . n_u) -
R_Y . n_u``, the moments about Y ``C = -(M_Y + (P - Y) x (-N_d n_d))``, and the block's
balance the crank's force on it at P, ``-(N_d n_d + R_P)``.

A horizontal path, a vertical slot, 10 N pushing the yoke to the right at Y = (0, 0), the
pin at P = (0, 1): the slot's force on the block is 10 N to the right (N_d = -10 along
n_d = (-1, 0)), the crank holds the block with 10 N to the left, and the path must hold
the yoke with a couple of 10 N m cw (the block pushes it back 1 m above the load's line):

>>> Nd, Nu, C, FP, c = solve(0.0, 0.0, (10.0, 0.0, 0.0), 0.0, 1.0, (0.0, 0.0), (1.0, 0.0), (0.0, 1.0))
>>> [round(v, 12) + 0.0 for v in (Nd, Nu, C) + FP], c
([-10.0, 0.0, -10.0, -10.0, 0.0], 1.0)
"""

from __future__ import annotations

from .bodies import Singular, any_zero, cross, split
from ..common.numbers import fmt
from .records import FRAME, ForceStep, GuideForce, PinForce, block, Side


def solve(yx, yy, known_yoke, px, py, known_block, u, d):
    """(N_d, N_u, C, the force on the block at P by the crank, the condition ``|u x d|``).

    ``known_yoke``: ``(Fx, Fy, M about the origin)`` on the yoke; ``known_block`` ``(Fx,
    Fy)`` on the block (through P)."""
    fx, fy, m = known_yoke
    rx, ry = known_block[0], known_block[1]
    (ux, uy), (dx, dy) = u, d
    ndx, ndy = -dy, dx
    nux, nuy = -uy, ux
    den = ndx * ux + ndy * uy
    cond = abs(cross(ux, uy, dx, dy))
    if any_zero(den):
        return None, None, None, None, 0.0
    nd = (fx * ux + fy * uy) / den
    nu = nd * (ndx * nux + ndy * nuy) - (fx * nux + fy * nuy)
    my = m - cross(yx, yy, fx, fy)
    c = -(my + cross(px - yx, py - yy, -nd * ndx, -nd * ndy))
    return nd, nu, c, (-(nd * ndx + rx), -(nd * ndy + ry)), cond


def owns(st) -> dict:
    """The yoke's point acts, for loads and later pins, on the yoke."""
    return {st.point: block(st.point)}


def blocks(st) -> tuple:
    """The yoke (its mass at Y: it translates) and the block in its slot."""
    return (st.point, st.pin)


def step(st, P, led, own):
    """Solve the yoke's and the block's forces; enter the crank's reaction at P and the
    path's on the frame. Returns as :func:`.dyad.step`."""
    Y, X = st.point, st.pin
    yb, xb = block(Y), block(X)
    ky, kx = led.of(yb), led.of(xb)
    (yx, yy), (px, py) = P[Y], P[X]
    u, d = st.path.u, st.slot.direction
    nd, nu, c, fp, cond = solve(yx, yy, ky, px, py, kx, u, d)
    if nd is None:
        raise Singular(f"the slot of yoke {Y} runs along its path")
    op = own[X]
    slot = GuideForce(X, nd, (-d[1], d[0]), yb)
    path = GuideForce(Y, nu, (-u[1], u[0]), FRAME, c)
    known_y, known_x = led.known(yb), led.known(xb)
    led.add(op, -fp[0], -fp[1], px, py, side=Side("pin", op, xb, X, (-fp[0], -fp[1]), (px, py)))
    led.add(FRAME, -path.force[0], -path.force[1], yx, yy)
    led.couple(FRAME, -c)
    eq, drawing = (), None
    if isinstance(nd, float):  # one instant (its condition is a number even over a sweep)

        def drawing():
            # the pole, the path's normal force (found last), the yoke's known forces, the
            # block's, the crank's force on the block along the slot (the block's balance
            # along it), across the slot (found last): the two lines meet at the pole
            Pp, Yp = (px, py), (yx, yy)
            held = Side("guide", yb, FRAME, Y, path.force, Yp)
            whole = Side("pin", xb, op, X, fp, Pp)
            along, across = split(whole, d)
            polygon = (held,) + known_y + known_x + (along, across)
            k = len(polygon)
            back = Side("guide", yb, xb, X, (-slot.force[0], -slot.force[1]), Pp)
            return (
                polygon,
                ((0, path.n), (k - 1, slot.n)),
                ((whole, k - 2, k), (back, 1 + len(known_y), k)),
            )

        eq = (
            f"the yoke along its path: -N_d (n_d . u) + R_Y . u = 0, R_Y = ({fmt(ky[0])}, "
            f"{fmt(ky[1])}) N the known forces on {yb}: N_d = {fmt(nd)} N (the slot's "
            f"force on {xb})",
            f"across the path: N_u = {fmt(nu)} N; moments about {Y}: the path's couple "
            f"C = {fmt(c)} N m",
            f"the block: F_{X} = -(N_d n_d + R) = ({fmt(fp[0])}, {fmt(fp[1])}) N on {xb} by {op}",
        )
    rec = ForceStep(
        st.index,
        "yoke",
        st.title,
        (yb, xb),
        (ky, kx),
        (
            (f"N_{X} on {xb} by {yb}", nd),
            (f"N_{Y} on {yb} by the path", nu),
            (f"C on {yb} by the path", c),
            (f"F_{X} on {xb} by {op}", fp),
        ),
        cond,
        "the sine of the angle between the slot and the path",
        eq,
        drawing,
    )
    return (PinForce(X, xb, op, fp),), (slot, path), rec, None


def divisor(st, rec, P, L):
    """A force balance divided by ``|u x d|``: ``c L``."""
    return rec.condition * L
