"""The force steps of a collar sliding along a turning rod: the collar that drives (the
inverted slider crank driven by its sliding: the collar C on the rod K-N, pivoted on the
frame at K, pinned to the link DC about the fixed pivot D) and the collar that slides along
the crank as the second input.

The rod pushes the collar across itself with the normal force ``N n`` (``w`` the rod's
unit direction K -> N, ``n = perp(w)``), and the collar's driver (a screw, a ram between
rod and collar) pushes it along the rod with ``F w`` and the rod back with ``-F w``. The
collar's loads pass through its pin C (its mass is there; it turns with the rod, its own
moment of inertia left out as any block's), so the rod adds no couple. R: the known forces
on the collar (its inertia and weight, loads at C, friction along the rod, the pins of
the links solved before).

**The driving collar**: the rod, the collar and DC together. The rod's moments about K,
where its pin force has no arm and ``F w`` passes through K::

    cross(C - K, -(N n + F w)) + M_K = 0   =>   N = M_K / ((C - K) . w)

(zero at the pivot: the kinematics' own singularity). DC's moments about D with the
collar's force on it ``P = N n + F w + R`` (:func:`.bodies.guided`, with the push along
``w``)::

    cross(C - D, F w + N n + R) + M_D = 0   =>   F = -(M_D + cross(C - D, N n + R)) / cross(C - D, w)

(zero where the rod's line passes through D: the dead centre). Then DC's balance gives the
frame's force on it at D, the rod's the frame's at K, ``(N n + F w) - F_rod``.

**The second collar** (the crank K-N turned by its driver, the collar driven along it):
the collar's balance, along the rod the driver's force, across it the normal force, as a
driving block's on its guide (:func:`.driver.solve`); the crank feels ``-(N n + F w)`` at
C and is solved after it (its torque).

A collar 1 m out along the x axis, a couple of 2 N m ccw on the rod: the collar must push
the rod down (N = 2 up on the collar); DC pinned at D = (1, -1) square to the rod holds the
collar down with 2 N, and the driver pushes nothing:

>>> N, F, P, FD, FK, dd = solve((0.0, 0.0), (1.0, 0.0), (1.0, -1.0), (1.0, 0.0),
...     (0.0, 0.0, 2.0), (0.0, 0.0, 0.0), (0.0, 0.0, 0.0))
>>> [round(v, 12) + 0.0 for v in (N, F) + P + FD + FK]
[2.0, 0.0, 0.0, 2.0, 0.0, -2.0, 0.0, 2.0]
"""

from __future__ import annotations

from ..common.numbers import added, fmt
from ..steps.rounding import vhypot
from .bodies import sums_add, sums_of, Singular, any_zero, cross, guided, least
from .records import FRAME, ForcePolygon, ForceStep, GuideForce, PinForce, Side, block


def solve(K, C, D, w, known_rod, known_block, known_link):
    """(N, F, P on DC at C by the collar, the frame's force on DC at D, the frame's on the
    rod at K, ``cross(C - D, w)``); F and the forces None where that is zero (the dead
    centre), N too where the collar is at K. Floats or arrays over a sweep."""
    (kx, ky), (cx, cy), (dx, dy) = K, C, D
    wx, wy = w
    nx, ny = -wy, wx
    fx, fy, m = known_rod
    sw = (cx - kx) * wx + (cy - ky) * wy  # (C - K) . w = cross(C - K, n)
    if any_zero(sw):
        return None, None, None, None, None, 0.0
    n = (m - (kx * fy - ky * fx)) / sw  # M_K / ((C - K) . w)
    r = (n * nx + known_block[0], n * ny + known_block[1])
    f, p, fd, den = guided(dx, dy, known_link, cx, cy, (wx, wy), r)
    if f is None:
        return n, None, None, None, None, den
    gx, gy = n * nx + f * wx, n * ny + f * wy  # the rod's push on the collar, and back
    return n, f, p, fd, (gx - fx, gy - fy), den


def axes(P, K, N):
    """The rod's unit direction K -> N."""
    (kx, ky), (nx, ny) = P[K], P[N]
    ux, uy = nx - kx, ny - ky
    m = (ux * ux + uy * uy) ** 0.5
    return ux / m, uy / m


# ----- the driving collar (kind "collar")


def owns(st) -> dict:
    """The collar's point acts, for loads and later pins, on the collar; the rod's far end
    on the rod."""
    return {st.point: block(st.point), st.end: st.rod}


def blocks(st) -> tuple:
    """The collar: a block a mass may sit on (at its pin)."""
    return (st.point,)


def bodies(st) -> tuple:
    """The bodies the step moves, as the sheet numbers them: the rod, the collar, DC."""
    return (st.rod, block(st.point), st.link)


def _words(st):
    c, k, d = st.point, st.pivot, st.fixed
    return (
        f"the collar {c} is at {k}, the pivot of {st.rod}",
        f"{st.rod}'s line passes through {d}",
    )


def bind(st, own, ix):
    C, K, N, D, rod, link = st.point, st.pivot, st.end, st.fixed, st.rod, st.link
    bl = block(C)
    ir, ibl, il = ix(rod), ix(bl), ix(link)
    at_pivot, dead = _words(st)

    def run(P, S, pins, guides):
        w = axes(P, K, N)
        n, f, p, fd, fk, _ = solve(
            P[K], P[C], P[D], w, sums_of(S, ir), sums_of(S, ibl), sums_of(S, il)
        )
        if f is None:
            raise Singular(at_pivot if n is None else dead)
        guides.append((C, n, (-w[1], w[0]), rod))
        pins += ((C, link, bl, p), (D, link, FRAME, fd), (K, rod, FRAME, fk))
        (dx, dy), (kx, ky) = P[D], P[K]
        sums_add(S, 0, -fd[0], -fd[1], dx, dy)
        sums_add(S, 0, -fk[0], -fk[1], kx, ky)
        return f

    return run


def condition(P, st, den):
    """|sin| of the angle between DC and the rod, times min(1, KC / DC): the kinematic
    step's condition, what the force equations divide by over their lengths."""
    (kx, ky), (cx, cy), (dx, dy) = P[st.pivot], P[st.point], P[st.fixed]
    dc = vhypot(cx - dx, cy - dy)
    return abs(den) / dc * least(vhypot(cx - kx, cy - ky) / dc, 1.0)


def step(st, P, led, own):
    """The collar's group: the normal force between rod and collar, the driver's force
    along the rod, the pins at C, D and K. Returns as :func:`.dyad.step`, the driver's
    force (N, signed outward along the rod) in the torque's place."""
    C, K, D, rod, link = st.point, st.pivot, st.fixed, st.rod, st.link
    bl = block(C)
    kr, kb, kl = led.of(rod), led.of(bl), led.of(link)
    w = axes(P, K, st.end)
    n, f, p, fd, fk, den = solve(P[K], P[C], P[D], w, kr, kb, kl)
    if f is None:
        raise Singular(_words(st)[0] if n is None else _words(st)[1])
    nv = (-w[1], w[0])
    g = GuideForce(C, n, nv, rod)
    (kx, ky), (cx, cy), (dx, dy) = P[K], P[C], P[D]
    led.add(FRAME, -fd[0], -fd[1], dx, dy)
    led.add(FRAME, -fk[0], -fk[1], kx, ky)
    # the drawings: the driver's force on the collar, and on the rod its and the guide's back
    # (before the driver's force is entered: the polygons)
    known_b, known_r, known_l = led.known(bl), led.known(rod), led.known(link)
    led.items.setdefault(bl, []).append(Side("driver", bl, "", C, (f * w[0], f * w[1]), P[C]))
    led.items.setdefault(rod, []).extend(
        (
            Side("guide", rod, bl, C, (-n * nv[0], -n * nv[1]), P[C]),
            Side("driver", rod, "", C, (-f * w[0], -f * w[1]), P[C]),
        )
    )
    cond = condition(P, st, den)
    eq, drawing = (), None
    if isinstance(f, float):

        def drawing():
            return polygons(st, P, (n, f, p, fd, fk), w, (known_b, known_r, known_l))

        mk = kr[2] - cross(kx, ky, kr[0], kr[1])
        md = kl[2] - cross(dx, dy, kl[0], kl[1])
        sw = (cx - kx) * w[0] + (cy - ky) * w[1]
        r = (n * nv[0] + kb[0], n * nv[1] + kb[1])
        eq = (
            f"moments of {rod} about {K}: ({C} - {K}) x (-(N n + F w)) + M_{K} = 0 (F w "
            f"along the rod has no arm), M_{K} = {fmt(mk)} N m the known forces' on {rod}",
            f"N = M_{K} / (({C} - {K}) . w) = {fmt(mk)} / {fmt(sw)} = {fmt(n)} N, the rod's "
            f"push on {bl} across the rod",
            f"moments of {link} about {D}: ({C} - {D}) x (F w + N n + R) + M_{D} = 0, R = "
            f"({fmt(kb[0])}, {fmt(kb[1])}) N the known forces on {bl}, M_{D} = {fmt(md)} N m",
            f"F = -(M_{D} + ({C} - {D}) x (N n + R)) / (({C} - {D}) x w) = -({fmt(md)} "
            f"{added(cross(cx - dx, cy - dy, r[0], r[1]))}) / {fmt(den)} = {fmt(f)} N, the "
            f"driver's force on {bl} along {rod} (+ outward)",
            f"the collar: F_{C} = F w + N n + R = ({fmt(p[0])}, {fmt(p[1])}) N on {link}",
            f"forces on {link}: F_{D} = ({fmt(fd[0])}, {fmt(fd[1])}) N; on {rod}: F_{K} = "
            f"F w + N n - (the known forces) = ({fmt(fk[0])}, {fmt(fk[1])}) N",
        )
    rec = ForceStep(
        st.index,
        "collar",
        st.title,
        (rod, bl, link),
        (kr, kb, kl),
        (
            (f"N_{C} on {bl} by {rod}", n),
            (f"F on {bl} by its driver, along {rod} (+ outward)", f),
            (f"F_{C} on {link} by {bl}", p),
            (f"F_{D} on {link} by the frame", fd),
            (f"F_{K} on {rod} by the frame", fk),
        ),
        cond,
        f"|sin {K}{C}{D}| x min(1, {K}{C} / {link}): the rod's line through {D}, or the "
        f"collar at {K}",
        eq,
        drawing,
    )
    pins = (PinForce(C, link, bl, p), PinForce(D, link, FRAME, fd), PinForce(K, rod, FRAME, fk))
    return pins, (g,), rec, f


def polygons(st, P, found, w, knowns):
    """The group's force polygons: the collar's (the pole, its known forces, DC's force on
    it from DC's moments, the driver's along the rod and the rod's across it, their lines
    drawn: closed), the rod's (its known forces, the collar's push and the driver's back at
    C, the frame's force at K closing it) and DC's (the collar's force on it, its known
    forces, the frame's at D closing it). ``found``: (N, F, P, F_D, F_K) of :func:`solve`;
    ``knowns``: the known forces (:class:`Side` s) on the collar, the rod and DC. Returns
    (polygon, unknown, chords, every :class:`ForcePolygon`)."""
    C, K, D, rod, link = st.point, st.pivot, st.fixed, st.rod, st.link
    bl = block(C)
    n, f, p, fd, fk = found
    known_b, known_r, known_l = knowns
    nv = (-w[1], w[0])
    along, across = (f * w[0], f * w[1]), (n * nv[0], n * nv[1])
    k = len(known_b)
    pin = Side("pin", bl, link, C, (-p[0], -p[1]), P[C])
    push = Side("driver", bl, rod, C, along, P[C])
    held = Side("guide", bl, rod, C, across, P[C])
    first = ForcePolygon((bl,), known_b + (pin, push, held), ((k + 1, w), (k + 2, nv)))
    back = (
        Side("guide", rod, bl, C, (-across[0], -across[1]), P[C]),
        Side("driver", rod, bl, C, (-along[0], -along[1]), P[C]),
    )
    rod_p = known_r + back + (Side("pin", rod, FRAME, K, fk, P[K]),)
    link_p = (Side("pin", link, bl, C, p, P[C]),) + known_l
    link_p += (Side("pin", link, FRAME, D, fd, P[D]),)
    polys = (first, ForcePolygon((rod,), rod_p), ForcePolygon((link,), link_p))
    return first.polygon, first.unknown, (), polys


def divisor(st, rec, P, L):
    """The lengths the equations divide by: ``(C - K) . w`` (the collar's distance from the
    pivot) and ``cross(C - D, w) = |DC| sin``: the smaller."""
    (kx, ky), (cx, cy), (dx, dy) = P[st.pivot], P[st.point], P[st.fixed]
    kc = vhypot(cx - kx, cy - ky)
    dc = vhypot(cx - dx, cy - dy)
    return least(kc, rec.condition / least(kc / dc, 1.0) * dc)


def second_name(scene, plan):
    """The second input's body in the force records: a second crank's link, a second
    collar's block (``block C``: its effort is a force along the crank), or None."""
    second = scene.input.second
    if second is None:
        return None
    st = plan.steps[1] if len(plan.steps) > 1 else None
    if st is not None and st.kind == "second collar":
        return block(st.point)
    return scene.link(second.crank).key
