"""The force step of a hydraulic cylinder (barrel pivoted at K, rod pinned at R): a
two-force member, massless: its force ``F`` acts along K-R, pushing R away
from K with ``F u`` (``u = (R - K) / |R - K|``, ``F > 0`` pushing apart, the cylinder in
compression) and K with ``-F u``. It is the first group solved (the kinematic plan places
it last: nothing depends on it), so the bodies at K and R are solved with its push.

Where the motion is given on the cylinder (``vs_OR``: its rate of extension), the cylinder
drives: ``F`` is the driver's effort and the crank is not driven. Everything is linear in
the loads, so the force analysis is walked once with ``F = 0`` (the crank's torque T0),
once with ``F = 1 N`` alone (T1, the torque one newton in the cylinder gives the crank: its
arm), and ``F = -T0 / T1`` makes the crank's torque vanish; ``|T1|`` over the mechanism's
size is the condition (zero where the cylinder's line passes through the crank's pivot: a
toggle). A passive cylinder carries the force the scene gives in it (``[loads] "O-R"``: a
push or a pull, a pressure on its bore or annulus, a damper's ``-c vs``, vs its rate of
extension, a spring's ``k (L0 - L)``, L its length at the instant; :mod:`polygon_method.scene.cylinder_loads`), entered in the ledger before the
walk (:func:`stated`); without one it carries no force: a free, frictionless cylinder
without a pressure pushes nothing.

With friction at its pins (``[friction] pins``, a size at K or R) the friction circles put
a couple ``M`` on it (entered in the ledger by :mod:`.friction` under its key): it is no
longer a two-force member, and its pins' forces gain ``(M / L) n`` across its line (n the
unit along K-R turned 90 deg ccw, L its length; the cylinder's moments about K), tangent to
the friction circles.

>>> push(0.0, 0.0, 3.0, 4.0, 10.0)     # 10 N pushing R away from K = (0, 0), R = (3, 4)
(6.0, 8.0)
"""

from __future__ import annotations

from ..common.numbers import fmt
from ..common.tolerances import FLOOR
from .bodies import Singular, any_zero
from .records import ForceStep, PinForce, Side
from ..scene.cylinder_loads import length_of, stated as loaded


#: the mark of a passive cylinder's force given in the scene, in its step's found label
GIVEN = " (given)"


def given_forces(f) -> list:
    """(key, F) of each passive cylinder whose force the scene gives, from the force steps
    ``f.steps`` (F, N, + pushing its ends apart; arrays over a sweep)."""
    return [
        (rec.bodies[0], rec.found[0][1])
        for rec in f.steps
        if rec.kind == "cylinder" and GIVEN in rec.found[0][0]
    ]


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


def stated(scene, motion, led):
    """Enter each passive cylinder's given force in ``led.stated``: (F, the rate of
    extension it was taken at, the cylinder, at rest, its length). At rest (or starting
    from rest) nothing moves: a damper pushes nothing (a spring still does)."""
    for c in loaded(scene):
        rate = motion.S[c.key][0] * (0.0 if scene.at_rest else 1.0)
        n = length_of(c, motion.P)
        led.stated[c.key] = (c.force_at(rate, scene.at_rest, n), rate, c, scene.at_rest, n)


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
    given = led.stated.get(st.key)
    f = led.given.get(st.key, 0.0 if given is None else given[0])
    K, R = st.barrel, st.rod
    (kx, ky), (rx, ry) = P[K], P[R]
    fx, fy = push(kx, ky, rx, ry, f)
    couple = led.of(st.key)[2]  # the friction circles' couples at its pins, if any
    across = _nonzero(couple)
    if across:  # no longer a two-force member: a part across its line, M / L
        ax, ay = _across(kx, ky, rx, ry, couple)
        fx, fy = fx + ax, fy + ay
    ok, orr = own[K], own[R]
    led.add(orr, fx, fy, rx, ry, side=Side("pin", orr, st.key, R, (fx, fy), (rx, ry)))
    led.add(ok, -fx, -fy, kx, ky, side=Side("pin", ok, st.key, K, (-fx, -fy), (kx, ky)))
    eq, drawing = (), None
    if isinstance(fx, float):

        def drawing():  # its two pins' forces, equal and opposite (and its couple)
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
                else given_words(st.key, given, f)
                if given is not None
                else "the cylinder does not drive (the motion is not given on it): a free, "
                "frictionless cylinder carries no force"
            ),
            f"a two-force member: F u on the body at {R}, -F u on the body at {K} (u from "
            f"{K} to {R}, F + pushing them apart)"
            if not across
            else f"no longer a two-force member: the friction circles at its pins put a couple "
            f"M = {fmt(couple)} N m on it, so its pins' forces are tangent to them: F u + (M / "
            f"L) n on the body at {R}, the opposite on the body at {K} (u from {K} to {R}, F + "
            f"pushing them apart, n = u turned 90 deg ccw, L = |{K}{R}|)",
        )
    rec = ForceStep(
        st.index,
        "cylinder",
        st.title,
        (st.key,),
        ((0.0, 0.0, couple + 0.0),),
        ((f"F in {st.key}{GIVEN if given is not None else ''}, + pushing {K} and {R} apart", f),),
        led.conditions.get(st.key, 1.0),
        "the arm of the cylinder about the crank's pivot over the mechanism's size"
        if st.key in led.given
        else "",
        eq,
        drawing,
    )
    # the pins' forces on the cylinder by the bodies at its ends
    return (PinForce(R, st.key, orr, (-fx, -fy)), PinForce(K, st.key, ok, (fx, fy))), (), rec, None


def given_line(scene, S, key, f, P=None) -> str:
    """``solve``'s line for a passive cylinder's given force ``f`` (one instant; ``S`` the
    motion's sliding rates, the cylinder's rate of extension among them; ``P`` the
    positions, for a spring's length)."""
    (c,) = [c for c in loaded(scene) if c.key == key]
    rate = 0.0 if scene.at_rest else S[key][0]
    n = length_of(c, P) if P is not None else None
    return given_words(key, (f, rate, c, scene.at_rest, n), f).removeprefix("the ")


def given_dict(scene, S, f, P=None) -> dict:
    """``solve --json``'s ``forces.cylinders``: each passive cylinder's given force (N, +
    pushing its ends apart), its parts and words (a spring's with ``P``, the positions)."""
    out = {}
    for key, v in given_forces(f):
        (c,) = [c for c in loaded(scene) if c.key == key]
        out[key] = {
            "force": v + 0.0,
            "given": c.words,
            "push": c.push + 0.0,  # a push, minus a pull, or a pressure times its area
            "damping": c.damping,
            "rate_of_extension": 0.0 if scene.at_rest else S[key][0] + 0.0,
            "sign": "+ pushing its ends apart",
        }
        if c.stiffness and P is not None:
            n = length_of(c, P)
            out[key].update(
                stiffness=c.stiffness,  # N/m
                free_length=c.free_length,  # m
                length=n + 0.0,  # m, at the instant
                spring=c.spring_at(n) + 0.0,  # k (L0 - L), N
            )
    return out


def given_words(key, given, f) -> str:
    """Where a passive cylinder's force comes from, in words (one instant)."""
    _, rate, c, at_rest, n = given
    way = (
        ", pushing its ends apart" if f > 0 else ", pulling its ends together" if f < 0 else ""
    )  # (a force of 0 pushes nothing)
    head = f"the force in the cylinder {key} is given ({c.words}): F = "
    if not c.damping and not c.stiffness:
        return f"{head}{fmt(f)} N{way}"
    terms, values, notes = [], [], []
    if c.push or c.damping or not c.stiffness:  # (a damper: "push - c vs" as ever)
        terms.append(fmt(c.push))
        values.append(fmt(c.push))
    if c.damping:
        terms.append(f"- {fmt(c.damping)} x vs")
        values.append(f"- {fmt(c.damping)} x {_paren(rate)}")
        notes.append(
            "vs the rate of extension, m/s; a damper resists it"
            + ("; at rest nothing moves: it pushes nothing" if at_rest else "")
        )
    if c.stiffness:
        terms.append(f"+ {fmt(c.stiffness)} x (L0 - L)")
        values.append(f"+ {fmt(c.stiffness)} x ({fmt(c.free_length)} - {fmt(n)})")
        notes.append(
            f"L = |{c.barrel}{c.rod}| its length, m; a spring "
            + (
                "compressed pushes"
                if n < c.free_length
                else "stretched pulls"
                if n > c.free_length
                else "at its free length pushes nothing"
            )
        )
    lhs = " ".join(terms).removeprefix("+ ")
    rhs = " ".join(values).removeprefix("+ ")
    return f"{head}{lhs} = {rhs} = {fmt(f)} N{way} ({'; '.join(notes)})"


def _across(kx, ky, rx, ry, couple):
    """The part across the line K-R of the force on the body at R that a couple ``couple``
    on the cylinder asks for: ``(M / L) n``, n the unit along K-R turned 90 deg ccw (the
    cylinder's moments: ``cross(R - K, -(M / L) n) + M = 0``)."""
    dx, dy = rx - kx, ry - ky
    m2 = dx * dx + dy * dy
    return -couple * dy / m2, couple * dx / m2


def _nonzero(x) -> bool:
    """Whether a couple is there: a float not 0, or an array with any entry not 0."""
    return x != 0 if isinstance(x, float) else bool(getattr(x, "any", lambda: x != 0)())


def divisor(st, rec, P, L):
    """A driving cylinder's force divides by its arm about the crank's pivot (its condition
    is that over the mechanism's size): ``c L``."""
    return rec.condition * L


def _paren(x) -> str:
    """A number as a factor: in brackets where negative (``2000 x (-0.15)``)."""
    return f"({fmt(x)})" if x < 0 else fmt(x)
