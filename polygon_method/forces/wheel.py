"""The force step of a wheel rolling without slip on a fixed line, its centre C found by a
link B-C (the kinematic plan's "wheel centre" step). The group is the link and the wheel.

The ground touches the wheel at ``I = C - r m`` (``m`` the line's unit normal towards the
wheel, ``t = perp(m)`` along the line) with a normal force ``N m`` and a tangential
(friction) force ``T t``: without slip the contact point does not move, so neither works.
The wheel's moments about its centre, where the link's pin force has no arm (``cross(I -
C, T t) = -r T``)::

    T = M_C / r

with ``M_C`` the moment about C of the known forces on the wheel (its inertia couple, the
loads and the pins of the links hung on it, solved before). The link's moments about B,
with ``Q = N m + T t + R`` the wheel's push on it at C (R the known forces on the
wheel; :func:`.bodies.guided`, the relation the slider and the slotted link share)::

    N = -(M_B + (C - B) x (T t + R)) / ((C - B) x m)

``(C - B) x m = -(C - B) . t``: zero when the link stands square to the line (the
kinematics' own singularity). Then the link's balance gives the force on it at B,
``-(F + Q)``. No slip needs ``|T| <= mu N``: the least friction coefficient is ``|T| /
N``; ``N <= 0`` means the ground would have to pull: the wheel lifts off.

A wheel of radius 1 centred at C = (0, 1) on the x axis, a couple of 2 N m cw on it, the
link from B = (-1, 1) horizontal: friction 2 N to the right drives it, the link feels the
wheel's push of 2 N to the right and 0 across:

>>> N, T, Q, FB, c = solve(-1.0, 1.0, (0.0, 0.0, 0.0), 0.0, 1.0, (0.0, 0.0, -2.0), 1.0, (0.0, 1.0))
>>> [round(v, 12) + 0.0 for v in (N, T) + Q + FB], c
([0.0, -2.0, 2.0, 0.0, -2.0, 0.0], 1.0)
"""

from __future__ import annotations

from ..steps.rounding import vhypot
from .bodies import Singular, cross, guided, least, outer_pin, unit
from ..common.numbers import fmt
from .records import FRAME, Contact, ForceStep, PinForce, Side


def solve(bx, by, known_link, cx, cy, known_wheel, r, m):
    """(N, T, the wheel's push Q on the link at C, the force on the link at B, the
    condition ``|(C - B) . t| / |C - B|``)."""
    rx, ry, mw = known_wheel
    mx, my = m
    tx, ty = -my, mx
    t = (mw - cross(cx, cy, rx, ry)) / r
    # the link feels the wheel's push N m + (T t + R) at C
    n, q, fb, den = guided(bx, by, known_link, cx, cy, m, (t * tx + rx, t * ty + ry))
    if n is None:
        return None, None, None, None, 0.0
    return n, t, q, fb, abs(den) / vhypot(cx - bx, cy - by)


def owns(st) -> dict:
    """The wheel's centre acts, for loads and later pins, on the wheel."""
    return {st.point: st.wheel}


def divisor(st, rec, P, L):
    """The link's moments divide by ``(C - B) x m = |BC| c``; the wheel's by r."""
    (bx, by), (cx, cy) = P[st.b], P[st.point]
    d = rec.condition * vhypot(cx - bx, cy - by)
    return least(d, st.radius)  # entry by entry over a sweep


def step(st, P, led, own):
    """Solve the link's and the wheel's forces and the ground's contact force; enter the
    reaction at B and the contact's on the frame. Returns as :func:`.dyad.step`, the
    contact among the guides."""
    lk, C, wh = st.link, st.point, st.wheel
    kl, kw = led.of(lk), led.of(wh)
    (bx, by), (cx, cy) = P[st.b], P[C]
    mx, my = st.m
    n, t, q, fb, cond = solve(bx, by, kl, cx, cy, kw, st.radius, (mx, my))
    if n is None:
        raise Singular(f"{st.b}{C} stands square to the line the wheel rolls on")
    ob = own[st.b]
    ix, iy = cx - st.radius * mx, cy - st.radius * my
    contact = Contact(wh, (ix, iy), n, t, (mx, my))
    known_l, known_w = led.known(lk), led.known(wh)
    led.add(ob, -fb[0], -fb[1], bx, by, side=Side("pin", ob, lk, st.b, (-fb[0], -fb[1]), (bx, by)))
    led.add(FRAME, -contact.force[0], -contact.force[1], ix, iy)
    eq, drawing = (), None
    if isinstance(n, float):

        def drawing():
            # the pole, F_B along BC (found last), F_B square to BC (the link's moments
            # about C), the link's known forces, the wheel's, the ground's grip (the
            # wheel's moments about C), its push across the line (found last): closed
            B, Cp, I = (bx, by), (cx, cy), (ix, iy)
            whole_b = Side("pin", lk, ob, st.b, fb, B)
            bn, bt = outer_pin(whole_b, B, Cp)
            grip = Side("contact", wh, FRAME, "I", (-t * my, t * mx), I, "t")
            push = Side("contact", wh, FRAME, "I", (n * mx, n * my), I, "n")
            polygon = (bn, bt) + known_l + known_w + (grip, push)
            k = len(polygon)
            return (
                polygon,
                ((0, unit(B, Cp)), (k - 1, (mx, my))),
                (
                    (whole_b, 0, 2),
                    (Side("pin", lk, wh, C, q, Cp), 2 + len(known_l), 0),
                    (Side("contact", wh, FRAME, "I", contact.force, I), k - 2, k),
                ),
            )

        mc = kw[2] - cross(cx, cy, kw[0], kw[1])
        eq = (
            f"moments of wheel {wh} about {C}: M_{C} - r T = 0, M_{C} = {fmt(mc)} N m the "
            f"known forces': T = M_{C} / r = {fmt(t)} N (the ground's grip along the line)",
            f"moments of {lk} about {st.b}: N = {fmt(n)} N (the ground's push, normal to the line)",
            f"the wheel's push on {lk} at {C}: Q = N m + T t + R = ({fmt(q[0])}, "
            f"{fmt(q[1])}) N; forces on {lk}: F_{st.b} = ({fmt(fb[0])}, {fmt(fb[1])}) N",
            contact.grip_words(),
        )
    rec = ForceStep(
        st.index,
        "wheel centre",
        st.title,
        (lk, wh),
        (kl, kw),
        (
            (f"N at the contact of {wh}", n),
            (f"T at the contact of {wh}", t),
            (f"F_{C} on {lk} by {wh}", q),
            (f"F_{st.b} on {lk} by {ob}", fb),
        ),
        cond,
        f"cosine of the angle between {st.b}{C} and the line",
        eq,
        drawing,
    )
    return (PinForce(C, lk, wh, q), PinForce(st.b, lk, ob, fb)), (contact,), rec, None
