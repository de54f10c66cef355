"""A friction drive: a rolling contact that grips by friction alone (no teeth), and whether
it slips.

Two wheels held at their centres (``[rolling]`` on a circle or a gear, with ``preload``) are
pressed together by the stated preload: it is the normal force N at the contact (the
statics cannot split a push along the line of centres between the contact and the centres'
pins: the preload says it; what the mechanism adds along that line goes into the pins). A
wheel on a fixed line is pressed on it by the mechanism's own forces: N is the ground's
push the statics give. The contact carries the tangential force T its wheel's moments need
(``T = M_C / r``) and can carry at most ``mu N``: it holds while ``|T| <= mu N``, with a
margin ``mu N - |T|``, and slips beyond (a wheel whose N is not positive lifts off). The
largest torque the grip passes to the wheel about its centre is ``mu N r`` (to the gear it
rolls on ``mu N R``), the largest power ``mu N |v|``, v the contact point's speed along the
common tangent (the pitch line's).

Two friction wheels pressed together with 500 N, mu = 0.3, the driven one of radius 0.1 m
turning so that its rim moves at 3 m/s; it needs 120 N along the tangent:

>>> g = (0.3, 500.0, 0.1, 0.2, 3.0)
>>> capacity(g), margin(g, -120.0), max_torque(g), max_torque(g, base=True), max_power(g)
(150.0, 30.0, 15.0, 30.0, 450.0)
"""

from __future__ import annotations

from dataclasses import replace

from ..common.errors import SceneError
from ..common.numbers import fmt


def attach(contacts, motion, plan) -> list:
    """The contacts, each of a wheel the scene gives ``friction`` or a ``preload`` with its
    grip ``(mu or None, N, r, R or None, v or None)``: N the preload (or, on a line, the
    ground's push), r the wheel's radius, R the gear's or circle's (None on a line), v the
    contact point's speed along the common tangent (None on a line: it does not move)."""
    pairs = {pr.wheel: pr for pr in motion.scene.rolling if pr.grip}
    if not pairs:
        return contacts
    out = []
    for c in contacts:
        pr = pairs.get(c.wheel)
        if pr is None:
            out.append(c)
            continue
        preload, mu = pr.grip
        st = next((s for s in plan.steps if s.kind == "rolling" and s.wheel == c.wheel), None)
        R = v = None
        if st is not None and st.on != "line":
            R = st.dims[2]
            (ix, iy), (cx, cy) = c.point, motion.P[pr.centre]
            (vx, vy), w = motion.V[pr.centre], motion.W[pr.wheel]
            mx, my = c.m
            v = abs((vx - w * (iy - cy)) * -my + (vy + w * (ix - cx)) * mx)
            if st.on == "circle" or motion.scene.at_rest:  # a fixed circle's contact, or
                v = 0.0 * v  # one at rest (its velocities per rad/s: virtual), does not move
        N = c.normal if preload is None else preload
        out.append(replace(c, grip=(mu, N, pr.radius, R, v)))
    return out


def capacity(g):
    """The largest tangential force the grip carries, ``mu N`` (None without mu)."""
    return None if g[0] is None else g[0] * g[1]


def margin(g, t):
    """``mu N - |T|``: positive, the grip holds with that to spare; negative, it slips."""
    return capacity(g) - abs(t)


def max_torque(g, base=False):
    """The largest torque the grip passes about the wheel's centre, ``mu N r`` (``base``:
    about the gear's or circle's, ``mu N R``)."""
    r = g[3] if base else g[2]
    return None if g[0] is None or r is None else g[0] * g[1] * r


def max_power(g):
    """The largest power through the grip, ``mu N |v|`` (None on a line)."""
    return None if g[0] is None or g[4] is None else g[0] * g[1] * g[4]


def words(c) -> str:
    """The grip at one instant in words: what it carries against what it can, and whether
    it holds (with its margin) or slips."""
    from .records import FRAME  # (the records read this module)

    g, t = c.grip, c.tangential
    mu, N = g[0], g[1]
    pressed = "the preload" if g[3] is not None else "the ground's push"
    if N <= 0:
        return (
            f"the ground would have to pull wheel {c.wheel} down (N = {fmt(N)} N): it lifts "
            "off the line and slips"
        )
    need = f"no slip needs a friction coefficient of at least |T| / N = {abs(t) / N:.3g}"
    if mu is None:
        return f"{need} (N = {fmt(N)} N {pressed}; friction = mu in [rolling] says if it slips)"
    cap, left = capacity(g), margin(g, t)
    head = (
        f"the grip of {c.wheel} carries |T| = {fmt(abs(t))} N of the mu N = {fmt(mu)} x "
        f"{fmt(N)} N = {fmt(cap)} N it can (N {pressed}): "
    )
    if left >= 0:
        verdict = (
            f"holds with a margin of {fmt(left)} N ({100 * abs(t) / cap:.3g} % of its grip used)"
        )
    else:
        verdict = f"slips (it needs {fmt(-left)} N more; {need})"
    most = f"; the largest torque it passes to {c.wheel} mu N r = {fmt(max_torque(g))} N m"
    if g[3] is not None and c.by == FRAME:  # a fixed circle: its contact does not move
        most += " (no power passes: its contact on the fixed circle does not move)"
    elif g[3] is not None:
        most += (
            f" (to the gear mu N R = {fmt(max_torque(g, True))} N m), the largest power mu N v "
            f"= {fmt(max_power(g))} W at the contact's speed v = {fmt(g[4])} m/s"
            + (" (at rest: no power passes)" if g[4] == 0 else "")
        )
    return head + verdict + most


def json(c) -> dict:
    """A friction drive's entries in the contact's JSON (none without a grip)."""
    g = c.grip
    if g is None:
        return {}
    out = {"normal_pressing": g[1] + 0.0}
    if g[3] is not None:
        out["preload"] = g[1] + 0.0
    if g[0] is None:
        return out
    return out | {
        "friction": g[0],
        "largest_tangential_force": capacity(g) + 0.0,
        "margin": margin(g, c.tangential) + 0.0,
        "slips": bool(g[1] <= 0 or margin(g, c.tangential) < 0),
        "max_torque": max_torque(g) + 0.0,
        "max_torque_on_base": None if g[3] is None else max_torque(g, True) + 0.0,
        "max_power": None if g[4] is None else max_power(g) + 0.0,
    }


def value(contacts, kind, body):
    """``Tmax``: the largest torque the grip passes about ``body``'s centre (the wheel's, or
    the gear's it grips); ``Pmax``: the largest power through the wheel ``body``'s grip."""
    for c in contacts:
        g = c.grip
        if g is None or g[0] is None:
            continue
        if c.wheel == body:
            got = max_torque(g) if kind == "Tmax" else max_power(g)
        elif kind == "Tmax" and c.by == body:
            got = max_torque(g, base=True)
        else:
            continue
        if got is not None:
            return got
    raise SceneError(f"{kind}: {body} is no wheel of a friction drive with friction stated")


def margins(f) -> list:
    """(name, unit, margin, words) of each friction drive with mu stated, for the sweep's
    columns and its summary: ``grip_L`` the margin ``mu N - |T|`` of wheel L's grip (N;
    below 0 it slips; where N is not positive, it lifts off: below 0 too)."""
    return [
        (
            f"grip_{c.wheel}",
            "N",
            margin(c.grip, c.tangential),
            "grip's margin mu N - |T|, < 0 slips",
        )
        for c in f.contacts
        if c.grip is not None and c.grip[0] is not None
    ]


def sweep_notes(extremes) -> tuple:
    """The sweep summary's verdict on each friction drive (``grip_L`` among ``extremes``):
    it holds over the range, its least margin at its worst angle, or it slips there."""
    out = []
    for e in extremes:
        if not e.name.startswith("grip_"):
            continue
        at = "at every angle" if e.at_min is None else f"at {e.at_min:.6g} deg"
        wheel = e.name[5:]
        if e.minimum >= 0:
            out.append(
                f"the grip of {wheel} holds over the range: its least margin mu N - |T| is "
                f"{fmt(e.minimum)} N, {at} (the worst angle)"
            )
        else:
            out.append(
                f"the grip of {wheel} slips: its margin mu N - |T| falls to {fmt(e.minimum)} N, "
                f"{at} (the worst angle)"
            )
    return tuple(out)
