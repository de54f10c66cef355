"""The force step of the crank: the last one solved (a second driving crank's is the same,
solved in its place in the plan's reverse order: its own torque from its own moments). The frame holds it at its pivot O
and its driver turns it with the torque T; every other force on it is known by now::

    R_O = -F            (the frame's force on the crank at O)
    T = -(M - cross(O, F))      (the moments about O balance)

>>> solve(0.0, 0.0, (3.0, 4.0, 2.0))
((-3.0, -4.0), -2.0)
"""

from __future__ import annotations

import math

from ..common.numbers import fmt, quiet
from .bodies import NEGATED_PIN
from .records import FRAME, ForceStep, PinForce, Side


def solve(ox, oy, known):
    """(the frame's force on the crank at O, the driving torque T, ccw positive)."""
    fx, fy, m = known
    return (-fx, -fy), -(m - (ox * fy - oy * fx))  # cross(O, F) written out


def bodies(st) -> tuple:
    """The bodies the step moves: the crank."""
    return (st.link,)


def owns(st) -> dict:
    """The crank's tip acts, for loads and later pins, on the crank."""
    return {st.tip: st.link}


def bind(st, own, ix):
    pivot, link, i = st.pivot, st.link, ix(st.link)
    head = (NEGATED_PIN, pivot, link, FRAME)  # its raw pin entry: the force (-fx, -fy)

    def run(P, S, pins, guides):
        ox, oy = P[pivot]
        sx, sy, sm = S
        fx, fy = sx[i], sy[i]  # solve(ox, oy, known) written out
        torque = -(sm[i] - (ox * fy - oy * fx))  # and r = (-fx, -fy), made when read
        # sums_add(S, 0, -r, ox, oy) and the couple -torque: -r is (fx, fy) itself
        sx[0] = sx[0] + fx
        sy[0] = sy[0] + fy
        sm[0] = sm[0] + (ox * fy - oy * fx) + -torque  # the driver, on the frame, feels -T
        pins.append((head, fx, fy))
        return torque

    return run


def step(st, P, led, own):
    """The frame's force at the pivot and the driving torque. Returns as
    :func:`.dyad.step`."""
    k = led.of(st.link)
    ox, oy = P[st.pivot]
    r, torque = solve(ox, oy, k)
    led.add(FRAME, -r[0], -r[1], ox, oy)
    led.couple(FRAME, -torque)  # the driver, mounted on the frame, feels -T
    eq, drawing = (), None
    if isinstance(torque, float):
        known = led.known(st.link)

        def drawn():  # the crank's known forces, then the frame's at the pivot: closed
            return known + (Side("pin", st.link, FRAME, st.pivot, r, (ox, oy)),), (), ()

        drawing = drawn
        O = st.pivot
        # a driver elsewhere (a cylinder, a given block) leaves the crank no torque: its
        # rounding noise is written 0, on the size of the pivot's force times the mechanism's
        size_r = math.hypot(*r)
        size = size_r * max(math.dist(q, (ox, oy)) for q in P.values())
        t = quiet(torque, size)
        eq = (
            f"moments about {O}: T + M_{O} = 0, M_{O} = {fmt(-t if t else 0.0)} N m the "
            f"known forces' moment: T = {fmt(t)} N m",
            f"forces: F_{O} = -(the known forces) = ({fmt(quiet(r[0], size_r))}, "
            f"{fmt(quiet(r[1], size_r))}) N",
        )
    rec = ForceStep(
        st.index,
        st.kind,
        st.title,
        (st.link,),
        (k,),
        ((f"F_{st.pivot} on {st.link} by the frame", r), (f"T on {st.link}", torque)),
        1.0,
        "",
        eq,
        drawing,
    )
    return (PinForce(st.pivot, st.link, FRAME, r),), (), rec, torque
