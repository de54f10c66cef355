"""The instantaneous-centre method as a textbook writes it out: the links numbered, the
number of centres, the primary centres from the joints, each other centre by Kennedy's
theorem with the two lines that locate it, then the angular velocities by the
angular-velocity-ratio theorem and the velocities of the points (``polygon-method
centres``).

>>> from polygon_method import parse_scene, solve
>>> from polygon_method.solver.centres import locate
>>> sol = solve(parse_scene('''
... [ground]
... O = [0, 0]
... [links]
... OA = 150
... AB = 600
... [sliders]
... B = { path = "horizontal" }
... [input]
... crank = "OA"
... angle = 90
... speed = "10 rad/s ccw"
... '''))
>>> text = centres_text(locate(sol))
>>> "N = n (n - 1) / 2 = 4 x 3 / 2 = 6" in text, "I14  at infinity" in text
(True, True)
"""

from __future__ import annotations

import math

from ..solver.centres import Centre, Centres
from ..common.numbers import fmt, fmt_angular, quiet
from ..common.tolerances import SAME, crossing_angle

__all__ = ["centres_text"]


def _own(sol, body):
    """The link key whose omega bound is a body's (None: the largest of all links')."""
    return body if body in sol.W else None


def _size(sol) -> float:
    """The mechanism's size (m): its longest link or farthest point from the origin."""
    return max([lk.length for lk in sol.scene.links] + [math.hypot(*p) for p in sol.P.values()])


def _where(sol, c: Centre) -> str:
    u, name = sol.scene.length_unit, sol.scene.units
    if c.point is None:
        deg = math.degrees(math.atan2(c.direction[1], c.direction[0])) % 180.0
        if min(deg, 180.0 - deg) <= SAME:  # rounding noise about the x axis
            deg = 0.0
        return f"at infinity, direction {fmt(deg, 4)} deg"
    # rounding noise (a coordinate below TOL.negligible of the mechanism's size) is 0
    size = _size(sol)
    x, y = (quiet(v, size) for v in c.point)
    return f"({fmt(x / u, 6)}, {fmt(y / u, 6)}) {name}"


def _numbering_lines(ic: Centres) -> list[str]:
    """The title, the links numbered (the ground 1, the driver 2: the crank, a driving block
    or wheel, as the driver names itself) and the number of centres."""
    n = ic.n
    out = [f"{ic.sol.scene.title or 'Instantaneous centres'}: instantaneous centre method", ""]
    out.append(f"Links (the ground is 1, {ic.sol.plan.steps[0].driver_name} 2):")
    for k, name in enumerate(ic.bodies, 1):
        out.append(f"  {k}  {name}")
    out.append(f"Number of centres: N = n (n - 1) / 2 = {n} x {n - 1} / 2 = {n * (n - 1) // 2}")
    return out


def _centre_lines(ic: Centres) -> list[str]:
    """The primary centres from the joints, then each secondary centre by Kennedy's theorem
    with the two lines that locate it (or the common line and the velocities on it)."""
    sol = ic.sol
    out = ["", "Primary centres (from the joints):"]
    for key in ic.order:
        c = ic.centres[key]
        if c.primary:
            out.append(f"  {c.label:<5}{_where(sol, c):<40} {c.how}")
    secondary = [ic.centres[k] for k in ic.order if not ic.centres[k].primary]
    if secondary:
        out.append("")
        out.append(
            "Secondary centres by Kennedy's theorem (the three centres of any three "
            "links lie on one line):"
        )
        for c in secondary:
            (a, b), (p, q) = c.lines
            cond = (
                ""
                if c.condition >= 0.999 or c.point is None
                else f"; lines cross at {fmt(crossing_angle(c.condition), 3)} deg"
            )
            if "coincide" in c.how:  # located by the velocities on the common line
                same = "" if (a, b) == (p, q) else f" = {p.label}-{q.label}: the same line"
                out.append(
                    f"  {c.label:<5}{_where(sol, c):<40} on {a.label}-{b.label}{same}; "
                    f"on it where omega_{c.i} and omega_{c.j} give one velocity"
                )
                continue
            out.append(
                f"  {c.label:<5}{_where(sol, c):<40} on {a.label}-{b.label} and "
                f"{p.label}-{q.label}{cond}"
            )
    return out


def _omega_line(ic: Centres, k: int) -> str:
    """Link ``k``'s angular velocity and where it comes from: the input, a translation, or the
    angular-velocity-ratio theorem from another link's."""
    sol = ic.sol
    w = ic.omegas[k]
    name = ic.bodies[k - 1]
    c1j = ic.centre(1, k)
    rest = (  # at rest: the motion per unit speed, the virtual velocities
        "; at rest: per unit of the input's speed, the virtual velocities"
        if getattr(sol.scene, "at_rest", False)
        else ""
    )
    if k == 2 and c1j.point is None:  # a block driven along its guide
        v = sol.V[sol.plan.steps[0].finds[0]]
        return (
            f"  omega_{k} ({name}) = 0: {name} translates at "
            f"{math.hypot(*v):.4g} m/s along its guide (the input{rest})"
        )
    if k == 2:
        return (
            f"  omega_{k} ({name}) = {fmt_angular(w, 'rad/s')} "
            f"({getattr(sol.plan.steps[0], 'body_omega_source', 'the input')}{rest})"
        )
    i = ic.ratio_from.get(k, 2)
    if i == 2 and ic.centre(1, 2).point is None:  # from the driving block's velocity
        return (
            f"  omega_{k} ({name}) = {fmt_angular(sol.shown(w, 'omega'), 'rad/s')} "
            f"(from the velocity of {ic.bodies[i - 1]} at "
            f"{ic.centre(i, k).label}, over its distance from {c1j.label})"
        )
    if c1j.point is None:
        return f"  omega_{k} ({name}) = 0: I1{k} is at infinity, {name} translates"
    return (
        f"  omega_{k} ({name}) = "
        f"{fmt_angular(sol.shown(w, 'omega', _own(sol, name)), 'rad/s')} "
        f"(from omega_{i} with {ic.centre(1, i).label}, {ic.centre(1, k).label}, "
        f"{ic.centre(i, k).label})"
    )


def _velocity_lines(ic: Centres) -> list[str]:
    """Each moving point's velocity: omega times its distance from its link's centre with the
    ground (or the link's translation)."""
    sol = ic.sol
    sc = sol.scene
    out = ["", "Velocities of the points (v = omega x distance from the centre with the ground):"]
    size = _size(sol)
    for p in sc.point_names:
        if p in sc.ground:
            continue
        k = ic.body_of(p)
        vx, vy = ic.velocity(p, k)
        v = sol.shown(math.hypot(vx, vy), "v", p)
        c = ic.centre(1, k)
        if c.point is None:
            out.append(f"  v_{p} = {fmt(v)} m/s (link {k} translates)")
            continue
        # 0 where the point is the centre (noise apart)
        r = quiet(math.hypot(sol.P[p][0] - c.point[0], sol.P[p][1] - c.point[1]), size)
        out.append(
            f"  v_{p} = omega_{k} x {p}-{c.label} = "
            f"{fmt(abs(sol.shown(ic.omegas[k], 'omega', _own(sol, ic.bodies[k - 1]))))} x "
            f"{fmt(r / sc.length_unit, 5)} {sc.units} = {fmt(v)} m/s"
        )
    return out


def centres_text(ic: Centres) -> str:
    """The instantaneous centres as ``centres`` prints them: the links numbered, each centre with
    how it was found, the omegas from the centres."""
    out = _numbering_lines(ic) + _centre_lines(ic)
    out += [
        "",
        "Angular velocities (angular-velocity-ratio theorem: omega_j / omega_i = "
        "I1i-Iij / I1j-Iij):",
    ]
    out += [_omega_line(ic, k) for k in range(2, ic.n + 1)]
    out += _velocity_lines(ic)
    out += [f"warning: {w}" for w in ic.warnings]
    return "\n".join(out)
