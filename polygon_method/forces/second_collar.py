"""The force step of a collar driven along the crank as the second input (two degrees of
freedom: "rod OA turns at 3 rad/s while collar C slides out along it"): the crank K-N is
turned by its driver's torque, the collar is pushed along it by its own driver (a screw, a
ram between rod and collar) with ``F w`` (``w`` the crank's unit direction K -> N), and the
crank pushes it across with ``N n`` (``n = perp(w)``). Every other force on the collar (R,
through its pin C: its inertia and weight, a load at C, friction along the rod, the links
solved before) is known by now, so its balance gives both, as a driving block's on its
guide (:func:`.driver.solve`)::

    F w + N n + R = 0   =>   F = -R . w,   N = -R . n

The crank feels ``-(F w + N n)`` at C (the guide's push and the driver's reaction) and is
solved after it, in the plan's reverse order: its own torque.

>>> f, n = solve((3.0, 4.0), (0.0, 1.0))    # R: 3 N across a vertical crank, 4 N up it
>>> f + 0.0, n + 0.0
(-4.0, 3.0)
"""

from __future__ import annotations

from ..common.numbers import fmt
from .collar import axes
from .driver import solve
from .bodies import sums_add, sums_of
from .records import ForceStep, GuideForce, Side, block

__all__ = ["solve", "owns", "blocks", "bodies", "bind", "step"]


def owns(st) -> dict:
    """The collar's point acts, for loads and later pins, on the collar."""
    return {st.point: block(st.point)}


def blocks(st) -> tuple:
    return (st.point,)


def bodies(st) -> tuple:
    """The collar (the crank is the first input's)."""
    return (block(st.point),)


def bind(st, own, ix):
    C, K, N, rod = st.point, st.pivot, st.end, st.rod
    i, ir = ix(block(C)), ix(rod)

    def run(P, S, pins, guides):
        wx, wy = axes(P, K, N)
        f, n = solve(sums_of(S, i), (wx, wy))
        guides.append((C, n, (-wy, wx), rod))
        cx, cy = P[C]
        sums_add(S, ir, -(f * wx - n * wy), -(f * wy + n * wx), cx, cy)
        return f

    return run


def step(st, P, led, own):
    """The collar's balance: along the crank its driver's force, across it the normal
    force; the crank feels both back at C. Returns as :func:`.dyad.step`, the driver's
    force (N, signed outward along the crank) in the torque's place."""
    C, rod = st.point, st.rod
    bl = block(C)
    kb = led.of(bl)
    wx, wy = axes(P, st.pivot, st.end)
    f, n = solve(kb, (wx, wy))
    g = GuideForce(C, n, (-wy, wx), rod)
    cx, cy = P[C]
    led.add(rod, -(f * wx - n * wy), -(f * wy + n * wx), cx, cy)
    led.items.setdefault(rod, []).extend(  # (drawn: the guide's push back, the driver's)
        (
            Side("guide", rod, bl, C, (n * wy, -n * wx), (cx, cy)),
            Side("driver", rod, "", C, (-f * wx, -f * wy), (cx, cy)),
        )
    )
    known = led.known(bl)  # (before the driver's force is entered: its polygon)
    led.items.setdefault(bl, []).append(Side("driver", bl, "", C, (f * wx, f * wy), (cx, cy)))
    eq, drawing = (), None
    if isinstance(f, float):

        def drawing():
            # the pole, the collar's known forces, its driver's along the crank, the
            # crank's across it: their lines meet where it closes
            k = len(known)
            push = Side("driver", bl, rod, C, (f * wx, f * wy), (cx, cy))
            held = Side("guide", bl, rod, C, g.force, (cx, cy))
            return known + (push, held), ((k, (wx, wy)), (k + 1, g.n)), ()

        eq = (
            f"the collar: F w + N n + R = 0, R = ({fmt(kb[0])}, {fmt(kb[1])}) N the known "
            f"forces on {bl}, w along {rod} outward",
            f"F = -R . w = {fmt(f)} N (its driver's force along {rod}), N = -R . n = "
            f"{fmt(n)} N (the rod's); {rod} feels -(F w + N n) at {C}",
        )
    rec = ForceStep(
        st.index,
        "second collar",
        st.title,
        (bl,),
        (kb,),
        ((f"N_{C} on {bl} by {rod}", n), (f"F on {bl} by its driver, along {rod} (+ outward)", f)),
        1.0,
        "",
        eq,
        drawing,
    )
    return (), (g,), rec, f
