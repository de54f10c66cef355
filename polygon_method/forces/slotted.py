"""The force step of a slotted link (RPR): a block pinned at A (to the body that found A,
the crank of a crank and slotted lever) slides along the lever K-N, which turns about K
(the lever's pivot: the frame, or a body already solved for its motion). The group is the
block and the lever.

The guide is frictionless: its force on the block is ``N n`` (``n = perp(u)``, ``u`` the
lever's direction as the kinematics takes it). The block's loads pass through its pin A
(its mass is there), so the lever adds no couple and ``N n`` acts through A; the lever
feels ``-N n`` at A. The lever's moments about its pivot K, where its pin force has no
arm (:func:`.bodies.guided`, the relation the slider and the wheel share, with a push
``-N n`` and nothing else at A)::

    cross(A - K, -N n) + M_K = 0   =>   N = M_K / ((A - K) . u)

(``cross(d, perp(u)) = d . u``): zero when the block reaches the pivot (the kinematics'
own singularity). Then the lever's force balance gives the force on it at K,
``-(F - N n)``, and the block's the force on it at A by the crank, ``-(N n + R)`` (R: the
known forces on the block).

A lever K = (0, 0) up the y axis, the block at A = (0, 1); a couple of 2 N m ccw on the
lever: the block must push it with 2 N to the right, and the lever pushes the block back,
N = 2 along n = (-1, 0); the pivot holds the lever with 2 N to the left:

>>> N, FK, FA, c = solve(0.0, 0.0, (0.0, 0.0, 2.0), 0.0, 1.0, (0.0, 0.0, 0.0), (0.0, 1.0), 2.0)
>>> [round(v, 12) + 0.0 for v in (N,) + FK + FA], c
([2.0, -2.0, 0.0, 2.0, 0.0], 0.5)
"""

from __future__ import annotations

from ..steps.rounding import vhypot
from .bodies import sums_add, sums_of, Singular, cross, guided, least, outer_pin, split, unit
from ..common.numbers import fmt
from .records import ForceStep, GuideForce, PinForce, block, Side


def solve(kx, ky, known_lever, ax, ay, known_block, u, length, condition=True):
    """(N on the block along n, the force on the lever at K, the force on the block at A,
    the condition ``|A - K| / length``, at most 1; None unless ``condition``).

    ``known_lever``: ``(Fx, Fy, M about the origin)`` on the lever; ``known_block``: the same
    on the block (its M is not used: its forces pass through A)."""
    rx, ry = known_block[0], known_block[1]
    ux, uy = u
    nx, ny = -uy, ux
    # the lever feels -N n at A, nothing else there: N is minus the push guided() finds
    pushed, _, fk, den = guided(kx, ky, known_lever, ax, ay, (nx, ny), (0.0, 0.0))
    if pushed is None:
        return None, None, None, 0.0
    n = -pushed
    cond = least(abs(den) / length, 1.0) if condition else None
    return (n, fk, (-(n * nx + rx), -(n * ny + ry)), cond)


def owns(st) -> dict:
    """The lever's far end acts, for loads and later pins, on the lever."""
    return {st.new: st.guide}


def blocks(st) -> tuple:
    """The block of this group (a mass may sit on it, at its pin)."""
    return (st.point,)


def bind(st, own, ix):
    lv, a, k = st.guide, st.point, st.known
    bl = block(a)
    ok, oa = own[k], own[a]
    ilv, ibl, iok, ioa = ix(lv), ix(bl), ix(ok), ix(oa)
    first, second, length = st.first, st.second, st.length
    why = f"block {a} is at {k}, the pivot of {lv}"

    def run(P, S, pins, guides):
        (kx, ky), (ax, ay) = P[k], P[a]
        (fx1, fy1), (fx2, fy2) = P[first], P[second]
        ux, uy = fx2 - fx1, fy2 - fy1
        m = (ux * ux + uy * uy) ** 0.5
        ux, uy = ux / m, uy / m
        n, fk, fa, _ = solve(
            kx, ky, sums_of(S, ilv), ax, ay, sums_of(S, ibl), (ux, uy), length, False
        )
        if n is None:
            raise Singular(why)
        guides.append((a, n, (-uy, ux), lv))
        pins += ((k, lv, ok, fk), (a, bl, oa, fa))
        sums_add(S, iok, -fk[0], -fk[1], kx, ky)
        sums_add(S, ioa, -fa[0], -fa[1], ax, ay)

    return run


def step(st, P, led, own):
    """Solve the lever's and the block's forces; enter the reactions at K and A on the
    bodies there. Returns as :func:`.dyad.step`."""
    lv, a, k = st.guide, st.point, st.known
    bl = block(a)
    kl, kb = led.of(lv), led.of(bl)
    (kx, ky), (ax, ay) = P[k], P[a]
    (fx1, fy1), (fx2, fy2) = P[st.first], P[st.second]
    ux, uy = fx2 - fx1, fy2 - fy1
    m = (ux * ux + uy * uy) ** 0.5
    ux, uy = ux / m, uy / m
    n, fk, fa, cond = solve(kx, ky, kl, ax, ay, kb, (ux, uy), st.length)
    if n is None:
        raise Singular(f"block {a} is at {k}, the pivot of {lv}")
    ok, oa = own[k], own[a]
    g = GuideForce(a, n, (-uy, ux), lv)
    known_l, known_b = led.known(lv), led.known(bl)
    led.add(ok, -fk[0], -fk[1], kx, ky, side=Side("pin", ok, lv, k, (-fk[0], -fk[1]), (kx, ky)))
    led.add(oa, -fa[0], -fa[1], ax, ay, side=Side("pin", oa, bl, a, (-fa[0], -fa[1]), (ax, ay)))
    eq, drawing = (), None
    if isinstance(cond, float):  # one instant: the working in words, the force polygon

        def drawing():
            # the pole, F_K along KA (found last), F_K square to KA (the lever's moments
            # about A), the lever's known forces, the block's, the force on the block at A
            # along the lever (the block's balance along it) and across it (found last)
            K, A = (kx, ky), (ax, ay)
            whole_k = Side("pin", lv, ok, k, fk, K)
            kn, kt = outer_pin(whole_k, K, A)
            whole_a = Side("pin", bl, oa, a, fa, A)
            along, across = split(whole_a, (ux, uy))
            polygon = (kn, kt) + known_l + known_b + (along, across)
            last = len(polygon)
            back = Side("guide", lv, bl, a, (-g.force[0], -g.force[1]), A)
            return (
                polygon,
                ((0, unit(K, A)), (last - 1, g.n)),
                ((whole_k, 0, 2), (whole_a, last - 2, last), (back, 2 + len(known_l), last)),
            )

        mk = kl[2] - cross(kx, ky, kl[0], kl[1])
        eq = (
            f"moments of {lv} about {k}: ({a} - {k}) x (-N n) + M_{k} = 0, M_{k} = "
            f"{fmt(mk)} N m the known forces' on {lv}",
            f"N = M_{k} / (({a} - {k}) . u) = {fmt(mk)} / {fmt((ax - kx) * ux + (ay - ky) * uy)}"
            f" = {fmt(n)} N, the lever's push on {bl} (the block pushes the lever back)",
            f"forces on {lv}: F_{k} = -(the known forces - N n) = ({fmt(fk[0])}, {fmt(fk[1])}) N",
            f"the block: F_{a} = -(N n + R) = ({fmt(fa[0])}, {fmt(fa[1])}) N on {bl} by "
            f"{oa}, R = ({fmt(kb[0])}, {fmt(kb[1])}) N the known forces on it",
        )
    rec = ForceStep(
        st.index,
        "slotted",
        st.title,
        (lv, bl),
        (kl, kb),
        (
            (f"N_{a} on {bl} by {lv}", n),
            (f"F_{k} on {lv} by {ok}", fk),
            (f"F_{a} on {bl} by {oa}", fa),
        ),
        cond,
        f"|{k}{a}| / {lv}: the block's distance from the lever's pivot",
        eq,
        drawing,
    )
    return (PinForce(k, lv, ok, fk), PinForce(a, bl, oa, fa)), (g,), rec, None


def divisor(st, rec, P, L):
    """The length the step's equations divide by: the block's distance from the pivot."""
    (kx, ky), (ax, ay) = P[st.known], P[st.point]
    return vhypot(ax - kx, ay - ky)
