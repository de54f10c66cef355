"""A chain of dyads' warm solve: its time per link at 1,001, 10,001 and 100,001 links,
side by side in one run (flat when a dyad's cost does not grow with the mechanism).

    python benchmarks/chain.py                       # 1,001, 10,001 and 100,001 links
    python benchmarks/chain.py --rounds 15 1001 10001

The chain is ``speed.chain_text``'s (a crank, then dyads, each joined to the last and to
ground). 100,001 links are 100,002 points, past the scene reader's cap of 20,000 (a
textbook mechanism has a few dozen): the cap is raised here for this benchmark alone.

Each round times every size in turn, a batch of solves of some 40,000 links in all (one
solve at 100,001 links), in two ways: ``dropped``, each solution freed before the next
solve (as ``instructions.py`` counts it), and ``kept``, the last solution alive while the
next is made, as a program that reads one position while solving the next (the objects
it keeps are then the cyclic garbage collector's to look at); and each of those as it ran
before the plan held the collector off while its steps run (``solver/collector.py``): the
same functions, not held (``unheld``). The sizes are timed back to back, the smallest
before and after the others: a shared machine's speed drifts from second to second, by
half at times, and the ratio of two batches far apart means little. Printed: the least
time per link over the rounds, in brackets the median over the rounds of its ratio to the
smallest chain's in the same round, and the collector's collections per solve (young,
middle, full) in the ``kept`` batches. Run it twice to see its noise. The instructions,
which no other load moves: ``python benchmarks/instructions.py chain1001 chain10001``.

Beside them, the floor (:func:`floor_chain`): plain Python float code for the same chain,
its numbers kept by name in dicts as a solve keeps them (checked against the solve to 1e-9).
It makes as many tuples and dict entries as a solve, so its time per link grows with the
chain as the memory's reach does: what the solve's growth has beyond the floor's is the
solve's own.

A benchmark, not a test: nothing here fails on time.
"""

from __future__ import annotations

import argparse
import gc
import importlib.util
import math
import statistics
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))  # this tree's package, not an installed one

#: links solved per timed batch (at least one solve)
BATCH_LINKS = 40_000


def _chain_text(links):
    spec = importlib.util.spec_from_file_location("speed", HERE / "speed.py")
    speed = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(speed)
    return speed.chain_text((links - 1) // 2)


def _scenes(sizes):
    """Each size's scene, its plan compiled, and its one-instant functions held off and not
    (``solve`` runs what the plan's ``instant_steps`` holds)."""
    from polygon_method import parse_scene, solve
    from polygon_method.scene import reading
    from polygon_method.solver.compiler import compile_plan

    cap = reading.MAX_POINTS
    reading.MAX_POINTS = max(cap, 2 * max(sizes))  # this benchmark alone: see above
    try:
        out = {}
        for links in sizes:
            t = time.perf_counter()
            scene = parse_scene(_chain_text(links))
            solve(scene)
            plan = compile_plan(scene)  # the plan solve found (its cache)
            out[links] = scene, plan, plan.instant_steps, plan.bind_instant(plan.dims)
            took = time.perf_counter() - t
            print(f"{links:>8,} links: read, planned and solved once in {took:.2f} s")
        return out
    finally:
        reading.MAX_POINTS = cap


def _batch(scene, calls, kept):
    """Seconds for ``calls`` warm solves of ``scene``."""
    from polygon_method import solve

    if kept:
        sol = solve(scene)
        t = time.perf_counter()
        for _ in range(calls):
            sol = solve(scene)
        t = time.perf_counter() - t
        del sol
        return t
    t = time.perf_counter()
    for _ in range(calls):
        solve(scene)
    return time.perf_counter() - t


def _collections(scene, calls):
    """The collector's collections per solve, by generation, solutions kept."""
    from polygon_method import solve

    count = [0, 0, 0]

    def seen(phase, info):
        if phase == "start":
            count[info["generation"]] += 1

    sol = solve(scene)
    gc.callbacks.append(seen)
    try:
        for _ in range(calls):
            sol = solve(scene)
    finally:
        gc.callbacks.remove(seen)
    del sol
    return [c / calls for c in count]


WAYS = (("held", False), ("held", True), ("unheld", False), ("unheld", True))


def floor_chain(plan):
    """The floor for a chain: plain Python float code for the same chain (the crank, then
    each dyad's place, velocity and acceleration written out as straight-line arithmetic,
    the numbers kept by name in dicts as a solve keeps them), its branch and dimensions
    read from ``plan``. Its time per link grows with the chain as the memory's reach does
    (it makes as many tuples and dict entries as a solve): the solve's growth beside it is
    what the solve adds. Returns the function."""
    steps = plan.steps
    crank = steps[0]
    ground = plan.ground
    r = crank.params[0]  # the crank's length (m)
    ox, oy = ground[crank.pivot]
    dyads = []
    for st in steps[1:]:
        l1, l2 = st.params
        dyads.append((st.point, st.b, st.d, st.link1, st.link2, l1, l2, st.sigma))
    inp = plan.scene.input
    theta, omega, alpha = inp.angle, inp.omega, inp.alpha
    cos, sin = math.cos, math.sin

    def floor():
        P = dict(ground)
        V = dict.fromkeys(ground, (0.0, 0.0))
        A = dict(V)
        bx = ox + r * cos(theta)
        by = oy + r * sin(theta)
        rx, ry = bx - ox, by - oy
        P[crank.tip] = (bx, by)
        V[crank.tip] = (-omega * ry, omega * rx)
        A[crank.tip] = (-omega * omega * rx - alpha * ry, -omega * omega * ry + alpha * rx)
        W = {crank.link: omega}
        Al = {crank.link: alpha}
        for X, B, D, j1, j2, l1, l2, sigma in dyads:
            bx, by = P[B]
            dx, dy = P[D]
            ex, ey = dx - bx, dy - by
            e2 = ex * ex + ey * ey
            root = (((l1 + l2) ** 2 - e2) * (e2 - (l1 - l2) ** 2)) ** 0.5
            a = (l1 * l1 - l2 * l2 + e2) / (2 * e2)
            g = sigma * root / (2 * e2)
            x, y = bx + a * ex - g * ey, by + a * ey + g * ex
            P[X] = (x, y)
            r1x, r1y, r2x, r2y = x - bx, y - by, x - dx, y - dy
            d = r1x * r2y - r1y * r2x
            (vbx, vby), (vdx, vdy) = V[B], V[D]
            wx, wy = vdx - vbx, vdy - vby
            w1 = (wx * r2x + wy * r2y) / d
            w2 = (wx * r1x + wy * r1y) / d
            W[j1], W[j2] = w1, w2
            V[X] = (vbx - w1 * r1y, vby + w1 * r1x)
            (abx, aby), (adx, ady) = A[B], A[D]
            qx = (adx - w2 * w2 * r2x) - (abx - w1 * w1 * r1x)
            qy = (ady - w2 * w2 * r2y) - (aby - w1 * w1 * r1y)
            a1 = (qx * r2x + qy * r2y) / d
            Al[j1], Al[j2] = a1, (qx * r1x + qy * r1y) / d
            A[X] = (abx - w1 * w1 * r1x - a1 * r1y, aby - w1 * w1 * r1y + a1 * r1x)
        return P, V, A, W, Al

    return floor


def _floor_agrees(scene, floor):
    """The floor gives the solve's numbers (to 1e-9 of each kind's size: the crank's
    length r, omega r, (omega^2 + |alpha|) r, omega, omega^2 + |alpha|), or its time means
    nothing."""
    from polygon_method import solve

    sol = solve(scene)
    w, al = abs(scene.input.omega), abs(scene.input.alpha)
    r = sol.plan.steps[0].params[0]
    sizes = (r, w * r, (w * w + al) * r, w, w * w + al)
    for mine, theirs, size in zip(floor(), (sol.P, sol.V, sol.A, sol.W, sol.Al), sizes):
        assert mine.keys() == theirs.keys()
        vals = [(a, b) for k in mine for a, b in zip(*(map(_flat, (mine[k], theirs[k]))))]
        assert all(abs(a - b) <= 1e-9 * size for a, b in vals)


def _flat(v):
    return v if isinstance(v, tuple) else (v,)


def _floor_round(floors, sizes, calls):
    """The floor's time per link of each size in one round (as :func:`_round`)."""
    out = {}
    for n in (*sizes, sizes[0]):
        f = floors[n]
        t = time.perf_counter()
        for _ in range(calls[n]):
            f()
        t = (time.perf_counter() - t) / calls[n] / n
        out[n] = (out[n] + t) / 2 if n in out else t
    return out


def _round(scenes, sizes, calls, way):
    """Time per link of each size in one round, the sizes back to back, the smallest timed
    before and after the others (its mean: a machine whose speed drifts moves both)."""
    out = {}
    for n in (*sizes, sizes[0]):
        scene, plan, held, unheld = scenes[n]
        object.__setattr__(plan, "instant_steps", held if way[0] == "held" else unheld)
        t = _batch(scene, calls[n], way[1]) / calls[n] / n
        out[n] = (out[n] + t) / 2 if n in out else t
    return out


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("links", nargs="*", type=int, default=[1001, 10001, 100001])
    ap.add_argument("--rounds", type=int, default=15, help="rounds of batches")
    args = ap.parse_args(argv)
    sizes = sorted(set(args.links))
    scenes = _scenes(sizes)
    calls = {n: max(1, BATCH_LINKS // n) for n in sizes}
    floors = {}
    for n in sizes:
        floors[n] = floor_chain(scenes[n][1])
        _floor_agrees(scenes[n][0], floors[n])
    ways = (*WAYS, ("floor", False))
    times = {(n, way): [] for n in sizes for way in ways}
    ratios = {(n, way): [] for n in sizes for way in ways}
    for _ in range(args.rounds):
        for way in ways:
            if way[0] == "floor":
                got = _floor_round(floors, sizes, calls)
            else:
                got = _round(scenes, sizes, calls, way)
            for n in sizes:
                times[n, way].append(got[n])
                ratios[n, way].append(got[n] / got[sizes[0]])
    counts = {}
    for n in sizes:
        scene, plan, held, unheld = scenes[n]
        for name, fns in (("held", held), ("unheld", unheld)):
            object.__setattr__(plan, "instant_steps", fns)
            counts[n, name] = _collections(scene, max(4, calls[n]))
        object.__setattr__(plan, "instant_steps", held)
    heads = [f"{a}, {'kept' if k else 'dropped'}" for a, k in WAYS] + ["the floor"]
    print(f"{'links':>8}" + "".join(f"  {h:>18}" for h in heads))
    for n in sizes:
        cells = [
            f"{min(times[n, w]) * 1e6:6.3f} us ({statistics.median(ratios[n, w]):.3f})"
            for w in ways
        ]
        print(f"{n:>8,}" + "".join(f"  {c:>18}" for c in cells))
    print(
        f"time per link, least of {args.rounds} rounds (in brackets the median over the rounds"
        f" of its ratio to {sizes[0]:,} links in the same round)"
    )
    print("collections per solve, solutions kept (young, middle, full):")
    for n in sizes:
        words = [
            f"{name} " + ", ".join(f"{c:.2f}" for c in counts[n, name])
            for name in ("held", "unheld")
        ]
        print(f"{n:>8,}  " + "; ".join(words))


if __name__ == "__main__":
    main()
