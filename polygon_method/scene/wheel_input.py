"""``[input] wheel = "CP"``: a wheel rolling without slip on a fixed line is the only
driver (a part of the scene reader).

The wheel CP (its entry in ``[rolling]``, on a line) rolls at ``omega_CP`` (with a sense),
``alpha_CP`` (optional, default 0: steady), or its centre's velocity ``vs_C`` and
acceleration ``as_C`` along the ground are given instead (signed along the line, or up,
down, left, right; ``omega = vs / (r t.u)``). Its centre C moves on the line parallel to the
ground at the wheel's radius r: the centre's path. The motion's parameter is C's place s
along that path (from the foot of the line's ``through`` point, along the line's direction
u), given by ``C = [x, y]`` or ``s_C``. No slip (t = perp(m), m the unit normal from the
ground to the centre)::

    v_C = omega r t,   a_C = alpha r t      so along u:  vs = omega r (t . u)

``travel = [from, to]`` (places s) is the stretch a sweep runs over; without it, one turn
of the wheel from the stated place, the way it rolls (2 pi r).
"""

from __future__ import annotations

import math


from ..common.tolerances import SAME
from .records import INPUT_KEYS, FixedPath, Input, split_name

__all__ = ["wheel_input", "centre_path"]


def centre_path(pr, centre):
    """The fixed path of the centre of the wheel ``pr`` (a :class:`RollingPair` on a line):
    through T + r m along u, keyed by the centre's point; its ``wheel`` names the wheel."""
    (tx, ty), (mx, my), r = pr.through, pr.m, pr.radius
    label = pr.label.removeprefix("the ").removesuffix(" line").removeprefix("line ")
    return FixedPath(centre, tuple(pr.u), (tx + r * mx, ty + r * my), label, wheel=pr.wheel)


def wheel_input(rd, spec, ground):
    """The :class:`Input` of a scene driven by a rolling wheel (``rd`` the scene reader)."""
    pr = _rolling_wheel(rd, spec, ground)
    C, W = pr.centre, pr.wheel
    w_key, v_key, as_key = f"omega_{W}", f"vs_{C}", f"as_{C}"
    _wheel_keys(rd, spec, C, W)
    path = centre_path(pr, C)
    (qx, qy), (ux, uy), (mx, my), r = path.through, path.u, pr.m, pr.radius
    along = -my * ux + mx * uy  # t . u, t = perp(m): +1 or -1
    omega, alpha = _wheel_motion(rd, spec, C, W, (ux, uy), r, along)
    s = _centre_place(rd, spec, C, (qx, qy), (ux, uy), r)
    stroke = _travel(rd, spec, s, omega * r * along, r)
    rd.driving_block = C  # (a torque answer is refused: the driver is given no crank)
    rd.driving_wheel = W  # (but with masses or gravity: the driver's torque on the wheel)
    rd.slider_points[C] = path
    return Input(
        None,
        None,
        C,
        s,
        omega * r * along,
        alpha * r * along,
        str(spec.get(w_key, spec.get(v_key))).strip(),
        block=C,
        stroke=stroke,
        wheel=W,
        wheel_given=tuple(k for k in (v_key, as_key) if k in spec),
    )


def _rolling_wheel(rd, spec, ground):
    """The rolling pair ``wheel`` names: a wheel of [rolling] on a ground line, its centre
    neither a ground point nor a block of [sliders]."""
    name = spec["wheel"]
    pts = split_name(name) if isinstance(name, str) else ()
    rolling = getattr(rd, "rolling_pairs", ()) or ()
    pr = next((p for p in rolling if len(pts) == 2 and {p.centre, p.rim} == set(pts)), None)
    if pr is None:
        raise rd.error(
            f"wheel = {name!r} names no wheel of [rolling] (the driving wheel is "
            'written as its link, centre first, e.g. wheel = "CP" with CP = { on '
            '= "horizontal", through = [0, 0] } in [rolling])',
            "input",
            "wheel",
        )
    if pr.on != "line":
        raise rd.error(
            f"the wheel {pr.wheel} rolls on {pr.label}, not on a fixed line: a wheel "
            "drives alone only rolling on a ground line (on a circle or a gear, "
            "make its arm or the gear the crank)",
            "input",
            "wheel",
        )
    C, W = pr.centre, pr.wheel
    if C in ground:
        raise rd.error(
            f"the wheel {W}'s centre {C} is a ground point: a wheel on a line rolls, "
            "its centre moves",
            "input",
            "wheel",
        )
    if C in rd.slider_points:
        raise rd.error(
            f"the wheel {W}'s centre {C} is also a block of [sliders]: its path is "
            "set by the wheel rolling on its line (remove it from [sliders])",
            "input",
            "wheel",
        )
    return pr


def _wheel_keys(rd, spec, C, W):
    """The keys of [input] a driving wheel W (centre C) takes: no other, its motion given
    once (on the wheel or on its centre)."""
    w_key, a_key, s_key = f"omega_{W}", f"alpha_{W}", f"s_{C}"
    v_key, as_key = f"vs_{C}", f"as_{C}"
    allowed = ("wheel", w_key, a_key, s_key, C, "travel", v_key, as_key)
    for k in spec:
        if k not in allowed:
            why = (
                "the wheel drives the mechanism: there is no crank, so no crank, angle, speed "
                "or acceleration (a wheel that a crank also drives is over-determined)"
                if k in INPUT_KEYS or k == "second"
                else "unknown key"
            )
            raise rd.error(
                f'{why}; with wheel = "{W}", [input] takes {w_key} (its angular '
                f"velocity) or {v_key} (its centre's velocity along the ground), "
                f"{a_key} or {as_key} (their rates), {C} = [x, y] or {s_key} (its "
                "centre's place) and travel = [from, to]",
                "input",
                k,
            )
    for one, other in ((w_key, v_key), (a_key, as_key)):
        if one in spec and other in spec:
            raise rd.error(
                f"[input] gives both {one} and {other}: one only (rolling without "
                f"slip, the centre moves at omega r)",
                "input",
                other,
            )
    if w_key not in spec and v_key not in spec:
        raise rd.error(
            f"[input] has no {w_key}: add the wheel's angular velocity, e.g. "
            f'{w_key} = "4 rad/s cw" (or its centre\'s, {v_key} = "2 m/s '
            'right")',
            "input",
        )


def _wheel_motion(rd, spec, C, W, u, r, along):
    """(omega, alpha) of the wheel: given, or from its centre's along the ground (``along``
    = t . u); at rest, per 1 rad/s."""
    w_key, a_key, v_key, as_key = f"omega_{W}", f"alpha_{W}", f"vs_{C}", f"as_{C}"
    ux, uy = u
    if v_key in spec:  # the centre's velocity along the ground: omega = vs / (r t.u)
        vs, _ = rd.directed(spec[v_key], "velocity", v_key, (ux, uy), need=False)
        omega = vs / (r * along)
    else:
        omega = rd.qty(spec[w_key], "angular_velocity", "input", w_key, need_sense=True).value
    raw_a = spec.get(a_key, spec.get(as_key, 0))
    if isinstance(raw_a, (int, float)) and not isinstance(raw_a, bool) and raw_a == 0:
        alpha = 0.0
    elif as_key in spec:
        acc = rd.rated(raw_a, "acceleration", "input", as_key, omega * r * along)
        if acc is None:
            acc, _ = rd.directed(raw_a, "acceleration", as_key, (ux, uy), need=False)
        alpha = acc / (r * along)
    else:
        alpha = rd.rated(raw_a, "angular_acceleration", "input", a_key, omega)
        if alpha is None:
            alpha = rd.qty(raw_a, "angular_acceleration", "input", a_key, need_sense=True).value
    if omega == 0:  # at rest (the weights held, or starting with alpha): per 1 rad/s
        omega, alpha = rd.at_rest_driver(omega, alpha, v_key if v_key in spec else w_key), 0.0
        rd.start_alpha = getattr(rd, "start_alpha", 0.0) * r * along  # (the centre's, m/s^2)
    return omega, alpha


def _centre_place(rd, spec, C, through, u, r):
    """The wheel's centre's place s along its path: ``s_C``, or ``C = [x, y]`` on it."""
    s_key, (qx, qy), (ux, uy) = f"s_{C}", through, u
    if (s_key in spec) == (C in spec):
        raise rd.error(
            f"[input] gives the wheel's place {'twice' if C in spec else 'not at all'}:"
            f" {C} = [x, y] (its centre) or {s_key} = 300 (the centre's place along "
            "the line from the foot of its through point), one only",
            "input",
            s_key if s_key in spec else None,
        )
    if s_key in spec:
        s = rd.length(spec[s_key], "input", s_key, positive=False)
    else:
        x, y = rd.coords(spec[C], "input", C)
        s = (x - qx) * ux + (y - qy) * uy
        off = -(x - qx) * uy + (y - qy) * ux
        if abs(off) > SAME * max(abs(x), abs(y), abs(s), rd.scale(), r):
            raise rd.error(
                f"{C} = {spec[C]} is {abs(off) / rd.scale():.6g} {rd.unit} off the "
                f"path of the wheel's centre ({r / rd.scale():.6g} {rd.unit} from "
                f"its ground line, on its side): give a point of it",
                "input",
                C,
            )
    return s


def _travel(rd, spec, s, vs, r):
    """``travel = [from, to]``: the stretch of places a sweep runs over (holding ``s``), or
    one turn of the wheel from ``s``, the way its centre moves (``vs``)."""
    if "travel" in spec:
        raw = spec["travel"]
        if not isinstance(raw, list) or len(raw) != 2:
            raise rd.error(
                "travel is [from, to]: the places of the wheel's centre along its "
                "line (as s), e.g. travel = [0, 1885]",
                "input",
                "travel",
            )
        a, b = (rd.length(v, "input", "travel", positive=False) for v in raw)
        if not a < b:
            raise rd.error(f"travel = {raw}: from must be less than to", "input", "travel")
        if not a <= s <= b:
            raise rd.error(
                f"the wheel's centre at s = {s / rd.scale():.6g} {rd.unit} is "
                f"outside its travel {raw}",
                "input",
                "travel",
            )
        stroke = (a, b)
    else:  # one turn of the wheel, the way it rolls
        turn = 2.0 * math.pi * r
        stroke = (s, s + turn) if vs > 0 else (s - turn, s)
    return stroke
