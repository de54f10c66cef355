"""The force step of a rolling wheel's own point (the plan's "rolling" step).

On a fixed line the wheel grips by friction: its forces, with the ground's contact, are
solved with the link that finds its centre (:mod:`.wheel`), or, where the wheel drives the
mechanism, by the driver's step (:mod:`.wheel_driver`); this step has none of its own. The
wheel's point acts, for loads and later pins, on the wheel.

On a circle or a gear the wheel's centre C is held by a link (an arm, the frame): a
friction grip would leave the contact's normal force and the centre's pin force sharing a
direction the statics cannot split (a preload). Gear teeth decide it: the tooth load acts
along the line of action through the pitch point I, at the pressure angle phi to the common
tangent (20 deg unless the scene says), the teeth pushing apart. With ``m`` the unit normal
at I towards C (``I - C = -r m``, r the wheel's pitch radius), ``t = perp(m)`` and the
contact force ``F = N m + T t`` on the wheel, the wheel's moments about its centre, where
the pin force there has no arm (``cross(I - C, F) = -r T``)::

    T = M_C / r,    N = |T| tan phi,    F_C = -(R + F)

``M_C`` and ``R`` the moment about C and the resultant of the known forces on the wheel
(its inertia, loads, the pins of the links hung on it, solved before); ``F_C`` the force
on the wheel at its centre by the body that holds it. The gear (or the frame) it rolls on
feels ``-F`` at I, and the centre's body ``-F_C``. The wheel's moments divide by r alone:
never singular.

A gear of pitch radius 0.1 m about C = (0, 0.3), its pitch point with the gear below at
I = (0, 0.2), a couple of 5 N m ccw on it: the teeth push it with 50 N along -x (the
tangent's part) and 50 tan 20 deg = 18.2 N up, and its centre's pin holds it back:

>>> N, T, F, FC = solve(0.0, 0.3, (0.0, 0.0, 5.0), 0.1, (0.0, 1.0), 0.3490658503988659)
>>> [round(v, 9) + 0.0 for v in (N, T) + F + FC]
[18.198511713, 50.0, -50.0, 18.198511713, 50.0, -18.198511713]
"""

from __future__ import annotations

import math

from ..common.numbers import fmt, quiet
from ..steps.rounding import vhypot
from .bodies import cross, direction
from dataclasses import replace

from ..steps.rolling_words import noun
from .records import FRAME, Contact, ForceStep, PinForce, Side

#: the teeth's pressure angle where the scene gives none (rad): 20 deg, the standard
DEFAULT_PRESSURE_ANGLE = math.radians(20.0)


def covers(st) -> bool:
    """Every rolling step: a wheel on a line (its centre's step solves it), on a circle or
    on a gear (teeth)."""
    return True


def check(st, plan):
    """Why the plan cannot be solved for forces with this step, or None: a wheel on a line
    whose centre neither a link finds nor the driver moves (no group holds its contact)."""
    if st.on != "line":
        return None
    held = any(
        s is not st and st.centre in s.finds and getattr(s, "wheel", None) == st.wheel
        for s in plan.steps
    )
    return None if held else f"wheel {st.wheel} rolls on a line with its centre found by no link"


def owns(st) -> dict:
    return {st.rim: st.wheel}


def pressure_angle(st) -> tuple:
    """(the teeth's pressure angle, rad; whether the scene states it)."""
    a = getattr(st, "pressure_angle", None)
    return (DEFAULT_PRESSURE_ANGLE, False) if a is None else (a, True)


def solve(cx, cy, known, r, m, phi, apart=1.0, preload=None):
    """(N along m, T along t = perp(m), the contact force F on the wheel at I = C - r m, the
    force F_C on the wheel at its centre); floats, or arrays over a sweep. ``apart``: +1
    where the teeth's push points towards the wheel's centre (m), -1 for a ring (an
    internal gear: the gear inside pushes it outwards). ``preload``: a friction drive's,
    pressing the two apart with it instead of the teeth (``phi`` unused)."""
    fx, fy, mo = known
    mx, my = m
    t = (mo - cross(cx, cy, fx, fy)) / r
    n = apart * (abs(t) * math.tan(phi) if preload is None else preload + 0.0 * t)
    ffx, ffy = n * mx - t * my, n * my + t * mx
    return n, t, (ffx, ffy), (-(fx + ffx), -(fy + ffy))


def contact_frame(st, P):
    """(I, m): the pitch point and the unit normal there towards the wheel's centre (arrays
    welcome)."""
    (cx, cy), (ox, oy) = P[st.centre], P[st.base_centre]
    dx, dy = cx - ox, cy - oy
    d = vhypot(dx, dy)
    ux, uy = dx / d, dy / d
    R = st.dims[2]
    if getattr(st, "ring", False):  # the gear inside the ring: I on its far side
        return (ox - R * ux, oy - R * uy), (ux, uy)
    e = -1.0 if st.inside else 1.0
    return (ox + R * ux, oy + R * uy), (e * ux, e * uy)


def _vec_words(v) -> str:
    """``(x, y)`` of a force, noise about a zero component (below its size's) written 0."""
    size = math.hypot(v[0], v[1])
    return f"({fmt(quiet(v[0], size))}, {fmt(quiet(v[1], size))})"


def gear_words(st):
    """(the wheel, what it meshes with) in the step table's words where it is a gear given
    by its teeth ("planet AP of 24 teeth", "the sun of 40 teeth about O"), else None."""
    return (f"{noun(st)} {st.wheel}", st.where) if st.teeth else None


def _holding(st, P, I, F):
    """On a fixed circle, the torque the frame holds it with: the circle's balance about
    its centre O against the push -F of the wheel at I, ``(I - O) x F``; else None."""
    if st.on != "circle":
        return None
    ox, oy = P[st.base_centre]
    return cross(I[0] - ox, I[1] - oy, F[0], F[1])


def divisor(st, rec, P, L):
    """The wheel's moments divide by its pitch radius."""
    return L if st.on == "line" else st.dims[1]


def step(st, P, led, own):
    """A gear's (or a planet's) tooth load and its centre's pin force; the reactions on the
    gear it rolls on (the frame for a fixed circle) and on the centre's body. Returns as
    :func:`.dyad.step`, the contact among the guides. On a line: nothing of its own."""
    if st.on == "line":
        return (), (), None, None
    W, C = st.wheel, st.centre
    kw = led.of(W)
    cx, cy = P[C]
    r = st.dims[1]
    (ix, iy), m = contact_frame(st, P)
    phi, stated = pressure_angle(st)
    preload = st.grip[0] if st.grip else None
    apart = -1.0 if getattr(st, "ring", False) else 1.0
    n, t, F, FC = solve(cx, cy, kw, r, m, phi, apart, preload)
    base = FRAME if st.on == "circle" else st.base
    oc = own[C]
    contact = Contact(W, (ix, iy), n, t, m, base, None if preload else phi, stated)
    held = _holding(st, P, (ix, iy), F)
    about = st.base_centre if held is not None else None
    contact = replace(contact, words=gear_words(st), holding=held, about=about)
    known = led.known(W)
    led.add(
        base, -F[0], -F[1], ix, iy, side=Side("contact", base, W, "I", (-F[0], -F[1]), (ix, iy))
    )
    led.add(oc, -FC[0], -FC[1], cx, cy, side=Side("pin", oc, W, C, (-FC[0], -FC[1]), (cx, cy)))
    eq, drawing = (), None
    if preload is not None:
        return _grip_step(st, P, contact, kw, known, F, FC, oc, base)
    if isinstance(t, float):

        def drawing():
            # the pole, the tooth load (its size from the moments about C, along the line
            # of action), the wheel's known forces, the centre's force: closed
            tooth = Side("contact", W, base, "I", F, (ix, iy))
            line = direction(F, (-m[1] + math.tan(phi) * m[0], m[0] + math.tan(phi) * m[1]))
            pin = Side("pin", W, oc, C, FC, (cx, cy))
            return (tooth,) + known + (pin,), ((0, line),), ()

        mc = kw[2] - cross(cx, cy, kw[0], kw[1])
        by = st.where if st.teeth else "the fixed circle" if base == FRAME else base
        eq = (
            f"the tooth load on {W} by {by} acts at the pitch point I along the line of "
            f"action, at the pressure angle {contact.angle_words()} to the common tangent, "
            "the teeth pushing apart",
            f"moments of {W} about its centre {C} (the pin force there has no arm): "
            f"M_{C} - r T = 0, M_{C} = {fmt(mc)} N m the known forces', r = {fmt(r)} m: "
            f"T = M_{C} / r = {fmt(t)} N (along the common tangent)",
            f"N = |T| tan phi = {fmt(n)} N (pushing {W} away from {by}: "
            + ("outwards, a ring" if getattr(st, "ring", False) else "towards its centre")
            + "); the tooth load "
            f"|T| / cos phi = {fmt(contact.load)} N",
            f"forces on {W}: F_{C} = -(the known forces + the tooth load) = {_vec_words(FC)} N",
        )
    rec = ForceStep(
        st.index,
        "rolling",
        st.title,
        (W,),
        (kw,),
        (
            (
                f"F_I on {W} by {'the frame' if base == FRAME else base} (the tooth load "
                "along the line of action)",
                F,
            ),
            (f"F_{C} on {W} by {'the frame' if oc == FRAME else oc}", FC),
        ),
        1.0,
        "",
        eq,
        drawing,
    )
    return (PinForce(C, W, oc, FC),), (contact,), rec, None


def _grip_step(st, P, contact, kw, known, F, FC, oc, base):
    """A friction drive's step: the preload across, the wheel's moments along the tangent,
    the centre's pin closing its polygon (every side known but that one)."""
    W, C = st.wheel, st.centre
    (cx, cy), (ix, iy), t, r = P[C], contact.point, contact.tangential, st.dims[1]
    by = "the fixed circle" if base == FRAME else base
    eq, drawing = (), None
    if isinstance(t, float):

        def drawing():
            grip = Side("contact", W, base, "I", F, (ix, iy))
            return (grip,) + known + (Side("pin", W, oc, C, FC, (cx, cy)),), (), ()

        mc = kw[2] - cross(cx, cy, kw[0], kw[1])
        eq = (
            f"{W} and {by} grip by friction, pressed together with the preload: the normal "
            f"force at the contact N = {fmt(st.grip[0])} N (what the mechanism adds along "
            "the line of centres goes into the centres' pins)",
            f"moments of {W} about its centre {C} (the pin force there has no arm): "
            f"M_{C} - r T = 0, M_{C} = {fmt(mc)} N m the known forces', r = {fmt(r)} m: "
            f"T = M_{C} / r = {fmt(t)} N (along the common tangent)",
            f"forces on {W}: F_{C} = -(the known forces + the contact's) = {_vec_words(FC)} N",
        )
    rec = ForceStep(
        st.index,
        "rolling",
        st.title,
        (W,),
        (kw,),
        (
            (f"F_I on {W} by {by} (the grip: the preload across, T along the tangent)", F),
            (f"F_{C} on {W} by {'the frame' if oc == FRAME else oc}", FC),
        ),
        1.0,
        "",
        eq,
        drawing,
    )
    return (PinForce(C, W, oc, FC),), (contact,), rec, None
