"""The force step of a driving wheel (``[input] wheel``): a wheel rolling without slip on
a fixed line is the only driver, its centre C the plan's first step; solved last, as a
crank is.

Its driver turns it with a torque ``tau`` (the stated effort: a motor on the wheel's axle,
its reaction on the frame as a crank's driver's is); the ground holds it at the contact
``I = C - r m`` with ``N m + T t`` (m the line's unit normal towards the wheel, ``t =
perp(m)``); every other force on it (R, M_C about C) is known by now::

    T = -R . t,    N = -R . m,    tau = r T - M_C

(the moments about C: ``M_C + tau + (I - C) x (T t) = M_C + tau - r T = 0``). The same
effort as a force at the centre, along the ground, instead of the torque does the same
work (``F v_C = tau omega``, ``v_C = omega r t``): ``F = tau / r`` along t, the ground's
grip then ``M_C / r``. No slip needs ``|T| / N`` of friction; ``N <= 0``: the wheel lifts
off.

A wheel of radius 0.5 m, its centre at (0, 0.5), pulled back by 10 N along -x at its
centre: the ground's grip holds it with 10 N along +x (T along t = -x is -10 N), whose
moment about the centre the driver's torque of 5 N m cw balances:

>>> [v + 0.0 for v in solve(0.0, 0.5, (-10.0, 0.0, 5.0), 0.5, (0.0, 1.0))]
[0.0, -10.0, -5.0]
"""

from __future__ import annotations

from ..common.numbers import fmt
from .bodies import cross
from .records import FRAME, Contact, ForceStep, Side


def solve(cx, cy, known, r, m):
    """(N along m, T along t = perp(m), the driver's torque tau on the wheel, ccw)."""
    fx, fy, mo = known
    mx, my = m
    tx, ty = -my, mx
    t = -(fx * tx + fy * ty)
    n = -(fx * mx + fy * my)
    return n, t, r * t - (mo - cross(cx, cy, fx, fy))


def normal(st) -> tuple:
    """The ground line's unit normal towards the wheel: ``m = (t . u)(u_y, -u_x)``."""
    ux, uy = st.path.u
    return (st.along * uy, -st.along * ux)


def centre_force(st, tau) -> tuple:
    """The driver's effort as a force at the centre along the ground instead of the torque:
    ``(tau / r) t`` (N)."""
    mx, my = normal(st)
    f = tau / st.radius
    return (-f * my, f * mx)


def owns(st) -> dict:
    """The wheel's centre acts, for loads and later pins, on the wheel."""
    return {st.point: st.wheel}


def bodies(st) -> tuple:
    return (st.wheel,)


def step(st, P, led, own):
    """The ground's contact force and the driver's torque on the wheel. Returns as
    :func:`.dyad.step`, the contact among the guides and the torque in its place."""
    W, C, r = st.wheel, st.point, st.radius
    kw = led.of(W)
    cx, cy = P[C]
    mx, my = normal(st)
    n, t, tau = solve(cx, cy, kw, r, (mx, my))
    ix, iy = cx - r * mx, cy - r * my
    contact = Contact(W, (ix, iy), n, t, (mx, my))
    known = led.known(W)
    led.add(FRAME, -contact.force[0], -contact.force[1], ix, iy)
    led.couple(FRAME, -tau)  # the driver, mounted on the frame, feels -tau
    eq, drawing = (), None
    if isinstance(tau, float):

        def drawing():
            # the pole, the wheel's known forces, the ground's grip along the line and its
            # push across it: their lines meet where it closes
            grip = Side("contact", W, FRAME, "I", (-t * my, t * mx), (ix, iy), "t")
            push = Side("contact", W, FRAME, "I", (n * mx, n * my), (ix, iy), "n")
            k = len(known)
            whole = Side("contact", W, FRAME, "I", contact.force, (ix, iy))
            return known + (grip, push), ((k, (-my, mx)), (k + 1, (mx, my))), ((whole, k, k + 2),)

        mc = kw[2] - cross(cx, cy, kw[0], kw[1])
        eq = (
            f"the wheel {W} alone: its driver's torque tau, the ground's N m + T t at the "
            f"contact I, the known forces R = ({fmt(kw[0])}, {fmt(kw[1])}) N, M_{C} = "
            f"{fmt(mc)} N m about its centre",
            f"along the ground: T = -R . t = {fmt(t)} N; across it: N = -R . m = {fmt(n)} N",
            f"moments about {C}: M_{C} + tau - r T = 0: tau = r T - M_{C} = {fmt(tau)} N m",
            f"or as a force at the centre along the ground: F = tau / r = {fmt(tau / r)} N "
            "(the same power)",
            contact.grip_words(),
        )
    rec = ForceStep(
        st.index,
        "rolling driver",
        st.title,
        (W,),
        (kw,),
        (
            (f"N at the contact of {W}", n),
            (f"T at the contact of {W}", t),
            (f"T on {W} by its driver", tau),
        ),
        1.0,
        "",
        eq,
        drawing,
    )
    return (), (contact,), rec, tau
