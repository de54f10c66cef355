"""The force step of a hydraulic cylinder (barrel pivoted at K, rod pinned at R): a
two-force member, massless, frictionless: its force ``F`` acts along K-R, pushing R away
from K with ``F u`` (``u = (R - K) / |R - K|``, ``F > 0`` pushing apart, the cylinder in
compression) and K with ``-F u``. It is the first group solved (the kinematic plan places
it last: nothing depends on it), so the bodies at K and R are solved with its push.

Where the motion is given on the cylinder (``vs_OR``: its rate of extension), the cylinder
drives: ``F`` is the driver's effort and the crank is not driven. Everything is linear in
the loads, so the force analysis is walked once with ``F = 0`` (the crank's torque T0),
once with ``F = 1 N`` alone (T1, the torque one newton in the cylinder gives the crank: its
arm), and ``F = -T0 / T1`` makes the crank's torque vanish; ``|T1|`` over the mechanism's
size is the condition (zero where the cylinder's line passes through the crank's pivot: a
toggle). Otherwise a cylinder carries no force: a free, frictionless cylinder without a
pressure pushes nothing.

>>> push(0.0, 0.0, 3.0, 4.0, 10.0)     # 10 N pushing R away from K = (0, 0), R = (3, 4)
(6.0, 8.0)
"""

from __future__ import annotations

from ..common.numbers import fmt
from ..common.tolerances import FLOOR
from .bodies import Singular, any_zero
from .records import ForceStep, PinForce, Side


def push(kx, ky, rx, ry, f):
    """The cylinder's force on the body at R (the body at K feels its opposite)."""
    dx, dy = rx - kx, ry - ky
    m = (dx * dx + dy * dy) ** 0.5
    return f * dx / m, f * dy / m


def owns(st) -> dict:
    return {}


def drives(scene, st) -> bool:
    """Whether the motion is given on this cylinder (it is then the driver)."""
    g = scene.input.given
    return (
        g is not None
        and g.kind == "vs"
        and g.names == (st.key,)
        and scene.input.block is None
        and scene.input.second is None
    )


def unit_ledger(st):
    """A ledger with 1 N in the cylinder and nothing else."""
    from .bodies import Ledger

    led = Ledger()
    led.given[st.key] = 1.0
    return led


def effort(st, t0, t1, led):
    """Enter the driving cylinder's force ``F = -T0 / T1`` (T0 the crank's torque without
    it, T1 with 1 N in it alone: its arm about the crank's pivot) and its condition ``|T1|
    / rho`` (at most 1) in ``led``."""
    if any_zero(t1):
        raise Singular(
            f"the line of cylinder {st.key} passes through the crank's pivot: it "
            "cannot turn the crank"
        )
    cond = abs(t1) / (st.rho if st.rho > 0 else FLOOR)
    if isinstance(cond, float):
        cond = min(cond, 1.0)
    else:  # a sweep
        import numpy as np

        cond = np.minimum(cond, 1.0)
    led.given[st.key] = -t0 / t1
    led.conditions[st.key] = cond


def step(st, P, led, own):
    """The cylinder's push on the bodies at its ends (``led.given``: its force, 0 where it
    does not drive). Returns as :func:`.dyad.step`."""
    f = led.given.get(st.key, 0.0)
    K, R = st.barrel, st.rod
    (kx, ky), (rx, ry) = P[K], P[R]
    fx, fy = push(kx, ky, rx, ry, f)
    ok, orr = own[K], own[R]
    led.add(orr, fx, fy, rx, ry, side=Side("pin", orr, st.key, R, (fx, fy), (rx, ry)))
    led.add(ok, -fx, -fy, kx, ky, side=Side("pin", ok, st.key, K, (-fx, -fy), (kx, ky)))
    eq, drawing = (), None
    if isinstance(fx, float):

        def drawing():  # a two-force member: its two pins' forces, equal and opposite
            return (
                (
                    Side("pin", st.key, orr, R, (-fx, -fy), (rx, ry)),
                    Side("pin", st.key, ok, K, (fx, fy), (kx, ky)),
                ),
                (),
                (),
            )

        eq = (
            (
                f"the cylinder drives: F = -T0 / T1 = {fmt(f)} N, T0 the crank's torque "
                "without it, T1 with 1 N in it alone"
                if st.key in led.given
                else "the cylinder does not drive (the motion is not given on it): a free, "
                "frictionless cylinder carries no force"
            ),
        )
    rec = ForceStep(
        st.index,
        "cylinder",
        st.title,
        (st.key,),
        ((0.0, 0.0, 0.0),),
        ((f"F in {st.key}, + pushing {K} and {R} apart", f),),
        led.conditions.get(st.key, 1.0),
        "the arm of the cylinder about the crank's pivot over the mechanism's size"
        if st.key in led.given
        else "",
        eq,
        drawing,
    )
    # the pins' forces on the cylinder by the bodies at its ends
    return (PinForce(R, st.key, orr, (-fx, -fy)), PinForce(K, st.key, ok, (fx, fy))), (), rec, None


def divisor(st, rec, P, L):
    """A driving cylinder's force divides by its arm about the crank's pivot (its condition
    is that over the mechanism's size): ``c L``."""
    return rec.condition * L
