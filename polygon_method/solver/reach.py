"""Where a mechanism that cannot assemble at its stated input could: the crank's angles
(:func:`crank_reach`) or the driving block's places along its guide (:func:`block_reach`)
at which the steps compiled so far and the failing one assemble, in the words the compiler
adds to its refusal (:func:`reach_words`: what to do when the stated angle cannot)."""

from __future__ import annotations

import math

from ..common.numbers import in_units
from ..steps import Context
from .plan import Dims, Plan

__all__ = ["reach_words", "crank_reach", "block_reach"]


def reach_words(compiler, failing, n) -> str:
    """Where the crank can be set so that the compiler's steps so far and ``failing``
    assemble (each end to about 1e-4 deg; a block's place: :func:`block_reach`), ``n``
    angles tried over the turn."""
    sc, inp = compiler.scene, compiler.scene.input
    steps = tuple(compiler.steps) + (failing,)
    plan = Plan(
        steps,
        dict(sc.ground),
        sc,
        (),
        {},
        (),
        Dims(
            dict(sc.ground),
            tuple([st.params for st in steps]),
            inp.angle,
            inp.omega,
            inp.alpha,
            {},
        ),
    )

    def fails(theta):
        import numpy as np

        ctx = Context(np.asarray(theta, dtype=float), inp.omega, inp.alpha, array=True)
        with np.errstate(all="ignore"):
            plan.run(ctx, upto=0)
        if ctx.bad is None:
            return np.zeros(len(theta), dtype=bool)
        return np.broadcast_to(ctx.bad, (len(theta),))  # a step of fixed points: one

    if inp.block is not None:  # a block's place: a stretch of its guide either side
        return block_reach(compiler, fails, n)
    return crank_reach(compiler, fails, n)


def crank_reach(compiler, fails, n) -> str:
    """The ranges of the crank's angle at which nothing ``fails`` (an array of angles in,
    one flag each out), found on a grid of ``n`` over the turn about the stated angle and
    each end bisected."""
    inp = compiler.scene.input
    two_pi = 2.0 * math.pi
    grid = [inp.angle + two_pi * (k / n - 0.5) for k in range(n)]
    bad = fails(grid)
    crank = inp.crank
    if bad.all():
        return (
            f"no angle of the crank {crank} assembles it: the links are too short "
            "or too long (check the lengths)"
        )
    if not bad.any():
        return f"(it assembles at the angles either side: a limit of the crank {crank})"

    def edge(good, wrong):  # bisection between an angle that assembles and one that not
        for _ in range(24):
            mid = 0.5 * (good + wrong)
            if fails([mid])[0]:
                wrong = mid
            else:
                good = mid
        return math.degrees(good)

    h = two_pi / n
    ranges = []
    for i in range(n):
        if not bad[i] and bad[i - 1]:  # a range starts at i (the grid closes the turn)
            j = i
            while not bad[(j + 1) % n]:
                j += 1
            lo = edge(grid[i], grid[i] - h)
            hi = edge(grid[j % n] + two_pi * (j // n), grid[j % n] + two_pi * (j // n) + h)
            shown = (lo + 180.0) % 360.0 - 180.0  # from -180 to 180, the end follows
            ranges.append(f"{shown:.2f} to {shown + hi - lo:.2f} deg")
    return (
        f"the crank {crank} can be set only from "
        + ", or from ".join(ranges)
        + ": give an angle there"
    )


def block_reach(compiler, fails, n) -> str:
    """Where the driving block can be placed so that the steps so far assemble: its
    guide searched from its through point either way, as far as the links reach, past
    the stated place too (each end to about a millionth of that reach)."""
    sc, inp = compiler.scene, compiler.scene.input
    through = getattr(sc.slider(inp.block), "through", None)  # a collar: from its pivot
    span = (
        2.0 * sum(lk.length for lk in sc.links)
        + max((math.dist(xy, through) for xy in sc.ground.values()), default=0.0)
        if through is not None
        else sum(lk.length for lk in sc.links)
    )
    lo, hi = min(inp.angle, 0.0) - span, max(inp.angle, 0.0) + span
    grid = [lo + (hi - lo) * k / (n - 1) for k in range(n)]
    bad = fails(grid)
    name, u, uname = inp.block, compiler.unit, compiler.uname
    if bad.all():
        return (
            f"no place of the block {name} along its guide assembles it: the links "
            "are too short or too long (check the lengths)"
        )

    def edge(good, wrong):  # bisection between a place that assembles and one that not
        for _ in range(30):
            mid = 0.5 * (good + wrong)
            if fails([mid])[0]:
                wrong = mid
            else:
                good = mid
        return good

    ranges, i = [], 0
    while i < n:
        if bad[i]:
            i += 1
            continue
        j = i
        while j + 1 < n and not bad[j + 1]:
            j += 1
        a = "beyond" if i == 0 else in_units(edge(grid[i], grid[i - 1]), u)
        b = "beyond" if j == n - 1 else in_units(edge(grid[j], grid[j + 1]), u)
        ranges.append(f"{a} to {b} {uname}")
        i = j + 1
    return (
        f"the block {name} can be placed only from s_{name} = about "
        + ", or from ".join(ranges)
        + ": give a place there"
    )
