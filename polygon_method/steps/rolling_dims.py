"""A rolling wheel's dimensions, read from its scene: what it rolls on and how its arm and
the gear it meshes with turn per radian of the crank (a fixed ratio, or None where a linkage
turns them and their angles are read from their points). The formulas and the step are in
:mod:`.rolling`."""

from __future__ import annotations

import math

from ..common.errors import AssemblyError, SceneError
from ..common.numbers import in_units
from ..common.tolerances import SAME
from ..scene import teeth as by_teeth

__all__ = [
    "GAP",
    "HALF",
    "pair_of",
    "rate",
    "arm_rate",
    "angle_of",
    "turned",
    "wheel_params",
    "follow_params",
    "gear_teeth",
    "placed_teeth",
]

#: how far (relative to the radii) a wheel's centre may leave its line or pitch circle
GAP = SAME
#: how far a link turning as a linkage makes it (a wheel's arm or gear, a rack's pinion)
#: may turn from the stated instant before its angle is refused (a turn of nearly pi
#: could be one the other way)
HALF = 0.95 * math.pi


def pair_of(scene, wheel):
    """The ``[rolling]`` pair whose wheel is ``wheel``."""
    return next(r for r in scene.rolling if r.wheel == wheel)


def rate(g, key):
    """The turning of link ``key`` per radian of the crank where it is a fixed ratio (the
    crank 1, a second crank the ratio of the speeds, a gear at a fixed ratio), else None
    (it turns as a linkage makes it: its angle is read from its points)."""
    inp = g.scene.input
    if inp.block is None and key == inp.crank:
        return 1.0
    return next((getattr(st, "theta_rate", None) for st in g.steps if key in st.links), None)


def arm_rate(g, C, O):
    """The turning per radian of the crank of the line of centres O -> C: 0 where both are
    fixed, a link's fixed ratio where one is fixed and the other the end of a link turning
    about it (the arm), else None (read from the two points)."""
    sc = g.scene
    if C in sc.ground and O in sc.ground:
        return 0.0
    for fixed, moving in ((O, C), (C, O)):
        if fixed in sc.ground:
            for lk in sc.links:
                if {lk.p, lk.q} == {fixed, moving} and lk.key in g.used_links:
                    return rate(g, lk.key)
    return None


def angle_of(x, y):
    """The direction of (x, y), radians."""
    return math.atan2(y, x)


def turned(dx, dy, a0, ctx, step, what):
    """The turn of direction (dx, dy) from the angle a0, in (-pi, pi]: refused beyond
    :data:`HALF` (masked in a sweep, an :class:`AssemblyError` at one instant naming
    ``what`` turned), where it could not be told from a turn the other way.

    >>> round(turned(0.0, 1.0, 0.0, type("C", (), {"array": False})(), None, "x"), 12)
    1.570796326795
    """
    c, s_ = (ctx.cos(a0), ctx.sin(a0)) if ctx.array else (math.cos(a0), math.sin(a0))
    x, y = c * dx + s_ * dy, c * dy - s_ * dx
    if ctx.array:
        t = ctx.np.arctan2(y, x)
        far = abs(t) > HALF
        if far is True or (far is not False and far.any()):
            ctx.fail(step, far)
        return t
    t = math.atan2(y, x)
    if abs(t) > HALF:
        raise AssemblyError(
            f"{what} has turned {math.degrees(abs(t)):.4g} deg from the stated "
            "instant: its angle cannot be followed past half a turn (solve the "
            "scene at that instant)",
            step=step.label,
        )
    return t


def follow_params(scene, bodies, pr, kb_rate, P):
    """(kd, K, psi0) of the wheel of pair ``pr`` whose angle follows its arm (a planet on a
    rocker), for a gear meshing with it: its turn from the stated instant is ``K (theta -
    theta0) + kd (psi - psi0)``, psi its line of centres' direction (not read from its own
    points, which could not tell a turn past half of one)."""
    prm = wheel_params(scene, bodies, pr, kd_rate=None, kb_rate=kb_rate, P=P)
    return (prm[3], prm[7], prm[10])


def wheel_params(scene, bodies, pr, *, s0=None, kd_rate=0.0, kb_rate=0.0, P=None, base_free=None):
    """The step's dimensions, read from ``scene``: for a line (l, r, tx, ty, mx, my, phi0,
    s0); for a circle (l, r, R, kd, kb, phi0, theta0, K, ox, oy, psi0, beta0), K the
    wheel's turning per radian of the crank due to what turns at a fixed ratio of it
    (``kd kd_rate + kb kb_rate``, a rate None counting 0: read from the points instead),
    psi0 the line of centres' angle and beta0 the gear's (its centre to its other point)
    at the stated instant. ``P``: the positions there (the compiler's); without them the
    centre is a fixed point or the crank's tip."""
    ell = bodies.distance(pr.wheel, pr.centre, pr.rim)
    r = pr.radius
    if pr.on == "line":
        (tx, ty), (mx, my) = pr.through, pr.m
        phi0 = pr.angle if pr.angle is not None else math.atan2(-my, -mx)
        return (ell, r, tx, ty, mx, my, phi0, s0)
    inp = scene.input
    where = f"[rolling] {pr.wheel}"
    C0, O = _centres(scene, pr, P, kd_rate, base_free, where)
    dist = math.dist(C0, O)
    e = -1.0 if pr.inside else 1.0
    ring = getattr(pr, "ring", False)  # the wheel a ring about the gear (e = -1 too)
    R = (dist - r) if e > 0 else (r - dist) if ring else (dist + r)
    if R <= 0 or dist == 0:
        raise SceneError(
            f"the wheel {pr.wheel} (radius {in_units(r, scene.length_unit)} "
            f"{scene.units}) cannot "
            + (
                f"be a ring about {pr.label}"
                if ring
                else f"roll {'outside' if e > 0 else 'inside'} {pr.label}"
            )
            + f": its centre is {in_units(dist, scene.length_unit)} "
            f"{scene.units} from {pr.base_centre}"
            + ("" if e < 0 else " (not more than its radius: inside = true?)")
            + (" (not less than its radius)" if ring else ""),
            key=where,
            file=scene.file,
        )
    if pr.base_radius is not None and abs(pr.base_radius - R) > GAP * (R + r):
        u, n = scene.length_unit, scene.units
        want = r - pr.base_radius if ring else pr.base_radius + e * r
        raise SceneError(
            f"the contact leaves the pitch point: the centre distance "
            f"{pr.base_centre}{pr.centre} = {in_units(dist, u)} {n} is not "
            f"{'r - R' if ring else 'R + r' if e > 0 else 'R - r'} = "
            f"{in_units(want, u)} {n} "
            f"(R = {in_units(pr.base_radius, u)}, r = {in_units(r, u)}): "
            "the gears would not mesh",
            key=where,
            file=scene.file,
        )
    _whole_gear(scene, pr, R, dist, where)
    kd, kb = 1.0 + e * R / r, -e * R / r
    dx, dy = C0[0] - O[0], C0[1] - O[1]
    g = 1.0 if ring else e  # towards the contact: I - C = -g r (C - O) / |C - O|
    phi0 = pr.angle if pr.angle is not None else math.atan2(-g * dy, -g * dx)
    psi0 = angle_of(dx, dy)
    beta0 = 0.0
    if base_free is not None:
        (bx, by), (qx, qy) = P[base_free[0]], P[base_free[1]]
        beta0 = angle_of(qx - bx, qy - by)
    K = kd * (kd_rate or 0.0) + kb * (kb_rate or 0.0)
    return (ell, r, R, kd, kb, phi0, inp.angle, K, O[0], O[1], psi0, beta0)


def gear_teeth(scene, pr, R, dist):
    """(z, words) of the gear a wheel given by its teeth and a module meshes with, its
    radius ``R`` from the centre distance ``dist`` at the stated instant (neither its teeth
    nor its radius stated, nor the distance fixed by the scene: :func:`placed_teeth`);
    None where the scene states them (or gives no module)."""
    teeth = getattr(pr, "teeth", None)
    if not teeth or teeth[2] is None or teeth[1] is not None or pr.base_radius is not None:
        return None
    u = scene.length_unit
    return by_teeth.placed_teeth(pr, R, dist, lambda x: f"{in_units(x, u)} {scene.units}")


def placed_teeth(g, pr, R):
    """The teeth of pair ``pr`` (its own, its gear's, the module) as the compiler ``g``
    places it; its gear's found from the centre distance at the stated instant where the
    scene could not fix them, said in a note of the plan."""
    found = gear_teeth(g.scene, pr, R, math.dist(g.P[pr.centre], g.P[pr.base_centre]))
    if found is None:
        return pr.teeth
    if found[1] not in g.notes:
        g.notes.append(found[1])
    return (pr.teeth[0], found[0], *pr.teeth[2:])


def _whole_gear(scene, pr, R, dist, where):
    """Refused where the gear a wheel meshes with, its radius from the centre distance at
    the stated instant, would have teeth that are no whole number of the module."""
    found = gear_teeth(scene, pr, R, dist)
    if found is not None and found[0] is None:
        raise SceneError(found[1], key=where, file=scene.file)


def _centres(scene, pr, P, kd_rate, base_free, where):
    """The wheel's centre and its gear's (or circle's) centre at the stated instant: from
    the positions ``P`` where given, else each a fixed point or the crank's tip; refused
    where a linkage turns the arm or the gear and no positions are given."""
    inp = scene.input
    if P is not None:
        return P[pr.centre], P[pr.base_centre]
    if (
        kd_rate is None
        or base_free is not None
        or pr.base_centre not in scene.ground
        or (pr.centre not in scene.ground and pr.centre != inp.tip)
    ):
        raise SceneError(
            f"the wheel {pr.wheel}'s arm or gear turns as a linkage makes it: "
            "its dimensions need the positions at the stated instant",
            key=where,
            file=scene.file,
        )
    O = scene.ground[pr.base_centre]
    if pr.centre in scene.ground:
        return scene.ground[pr.centre], O
    L = scene.link(inp.crank).length  # the crank's tip at the stated angle
    return (O[0] + L * math.cos(inp.angle), O[1] + L * math.sin(inp.angle)), O
