"""The force step of a slider dyad (RRP): a link B-X whose end X is pinned to a block
sliding on a frictionless guide (unit ``u``; its normal ``n = perp(u)``): a fixed path, or
a moving link G1-G2 (``u`` along it, as the kinematics takes it), which then feels the
block's push ``-N n`` at X (the guide's body is solved later, in the reverse order).

Unknowns: ``P``, the force on the link at X by the block, and ``N``, the guide's normal
force on the block along ``n``. The block's loads pass through X (its mass is at its pin),
so its force balance is ``-P + N n + R = 0`` (R: the known forces on the block) and the
guide adds no couple. The link's moments about B, where its other pin force has no arm
(:func:`.bodies.guided`, the relation the slotted link and the wheel share)::

    cross(X - B, N n + R) + M_B = 0   =>   N = -(M_B + cross(X - B, R)) / cross(X - B, n)

with ``cross(X - B, n) = (X - B) . u``: zero when the link stands square to the path.
Then ``P = N n + R`` and the link's force balance gives the force on it at B, ``-(F + P)``.

>>> N, P, FB, c = solve(0.0, 0.0, (0.0, 0.0, 0.0), 1.0, 0.0, (-1.0, 0.0, 0.0), (1.0, 0.0))
>>> [round(v, 12) + 0.0 for v in (N,) + P + FB]   # 1 N pushing the block towards B
[0.0, -1.0, 0.0, 1.0, 0.0]
"""

from __future__ import annotations

from ..steps.rounding import vhypot
from .bodies import sums_add, sums_of, Singular, cross, guided, outer_pin, unit
from ..common.numbers import added, fmt
from .records import FRAME, ForceStep, GuideForce, PinForce, Side, block


def solve(bx, by, known_link, xx, xy, known_block, u, condition=True):
    """(N, P on the link at X by the block, the force on the link at B, the condition
    ``|(X - B) . u| / |X - B|``, None unless ``condition``).

    ``known_link``: ``(Fx, Fy, M about the origin)`` on the link; ``known_block``: the same
    on the block (its M is not used: its forces pass through X)."""
    ux, uy = u  # the link feels the block's push N n + R at X (n = perp(u))
    n, p, fb, den = guided(bx, by, known_link, xx, xy, (-uy, ux), known_block)
    if n is None:
        return None, None, None, 0.0
    if not condition:
        return n, p, fb, None
    ex, ey = xx - bx, xy - by
    return n, p, fb, abs(den) / (ex * ex + ey * ey) ** 0.5  # the link's length: never 0


def bodies(st) -> tuple:
    """The bodies the step moves: the link and its block."""
    return (st.link, block(st.point))


def owns(st) -> dict:
    """The slider's point acts, for loads and later pins, on its block."""
    return {st.point: block(st.point)}


def blocks(st) -> tuple:
    """The blocks this step's group has (a mass may sit on each)."""
    return (st.point,)


def guide(st, P, own):
    """(unit u along the guide, the body the guide is)."""
    if st.path is not None:
        return st.path.u, FRAME
    (gx, gy), (hx, hy) = P[st.g1], P[st.g2]
    ux, uy = hx - gx, hy - gy
    m = (ux * ux + uy * uy) ** 0.5
    body = FRAME if own.get(st.g1) == FRAME and own.get(st.g2) == FRAME else st.guide
    return (ux / m, uy / m), body


def bind(st, own, ix):
    lk, x, b = st.link, st.point, st.b
    bl, ob = block(x), own[st.b]
    il, ibl, ib = ix(lk), ix(bl), ix(ob)
    fixed = st.path is not None
    if fixed:
        u, gb = st.path.u, FRAME
        ig = 0
    else:  # a moving guide: its direction at each instant, its body known now
        gb = FRAME if own.get(st.g1) == FRAME and own.get(st.g2) == FRAME else st.guide
        ig = ix(gb)
    why = f"{b}{x} stands square to the guide"

    def run(P, S, pins, guides):
        (bx, by), (xx, xy) = P[b], P[x]
        v = u if fixed else guide(st, P, own)[0]
        n, p, fb, _ = solve(bx, by, sums_of(S, il), xx, xy, sums_of(S, ibl), v, False)
        if n is None:
            raise Singular(why)
        nv = (-v[1], v[0])
        guides.append((x, n, nv, gb))
        pins += ((x, lk, bl, p), (b, lk, ob, fb))
        sums_add(S, ib, -fb[0], -fb[1], bx, by)
        sums_add(S, ig, -(n * nv[0]), -(n * nv[1]), xx, xy)

    return run


def step(st, P, led, own):
    """Solve the link's and the block's forces; enter the reaction at B and the block's
    push on the guide (the frame). Returns as :func:`.dyad.step`."""
    lk, x = st.link, st.point
    bl = block(x)
    kl, kb = led.of(lk), led.of(bl)
    (bx, by), (xx, xy) = P[st.b], P[x]
    u, gb = guide(st, P, own)
    n, p, fb, cond = solve(bx, by, kl, xx, xy, kb, u)
    if n is None:
        raise Singular(f"{st.b}{x} stands square to the guide")
    ob = own[st.b]
    ux, uy = u
    g = GuideForce(x, n, (-uy, ux), gb)
    known_l, known_b = led.known(lk), led.known(bl)
    led.add(ob, -fb[0], -fb[1], bx, by, side=Side("pin", ob, lk, st.b, (-fb[0], -fb[1]), (bx, by)))
    led.add(
        gb,
        -g.force[0],
        -g.force[1],
        xx,
        xy,
        side=None
        if gb == FRAME
        else Side("guide", gb, bl, x, (-g.force[0], -g.force[1]), (xx, xy)),
    )
    eq = ()
    drawing = None
    if isinstance(cond, float):  # one instant: the working in words, the force polygon

        def drawn():
            B, X = (bx, by), (xx, xy)
            whole_b = Side("pin", lk, ob, st.b, fb, B)
            bn, bt = outer_pin(whole_b, B, X)
            # the pole, F_B along BX (found last), F_B square to BX, the link's known
            # forces, the block's, the guide's normal force (found last): closed
            polygon = (bn, bt) + known_l + known_b + (Side("guide", bl, gb, x, g.force, X),)
            k = len(polygon)
            return (
                polygon,
                ((0, unit(B, X)), (k - 1, g.n)),
                ((whole_b, 0, 2), (Side("pin", lk, bl, x, p, X), 2 + len(known_l), 0)),
            )

        drawing = drawn
        B = st.b
        mb = kl[2] - cross(bx, by, kl[0], kl[1])
        ex, ey = xx - bx, xy - by
        eq = (
            f"moments of {lk} about {B}: ({x} - {B}) x (N n + R) + M_{B} = 0, R = "
            f"({fmt(kb[0])}, {fmt(kb[1])}) N the known forces on the block, M_{B} = "
            f"{fmt(mb)} N m those on {lk}",
            f"N = -(M_{B} + ({x} - {B}) x R) / (({x} - {B}) . u) = -({fmt(mb)} "
            f"{added(cross(ex, ey, kb[0], kb[1]))}) / {fmt(ex * ux + ey * uy)} = {fmt(n)} N",
            f"the block: F_{x} = N n + R = ({fmt(p[0])}, {fmt(p[1])}) N on {lk}",
            f"forces on {lk}: F_{B} = -(the known forces + F_{x}) = ({fmt(fb[0])}, {fmt(fb[1])}) N",
        )
    rec = ForceStep(
        st.index,
        "slider",
        st.title,
        (lk, bl),
        (kl, kb),
        (
            (f"N_{x} on {bl} by the guide", n),
            (f"F_{x} on {lk} by {bl}", p),
            (f"F_{st.b} on {lk} by {ob}", fb),
        ),
        cond,
        f"cosine of the angle between {st.b}{x} and the guide",
        eq,
        drawing,
    )
    return (PinForce(x, lk, bl, p), PinForce(st.b, lk, ob, fb)), (g,), rec, None


def divisor(st, rec, P, L):
    """The length the step's equations divide by: ``(X - B) . u = |XB| c``."""
    (bx, by), (xx, xy) = P[st.b], P[st.point]
    return rec.condition * vhypot(xx - bx, xy - by)
