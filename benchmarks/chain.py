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

A benchmark, not a test: nothing here fails on time.
"""

from __future__ import annotations

import argparse
import gc
import importlib.util
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
    times = {(n, way): [] for n in sizes for way in WAYS}
    ratios = {(n, way): [] for n in sizes for way in WAYS}
    for _ in range(args.rounds):
        for way in WAYS:
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
    heads = [f"{a}, {'kept' if k else 'dropped'}" for a, k in WAYS]
    print(f"{'links':>8}" + "".join(f"  {h:>18}" for h in heads))
    for n in sizes:
        cells = [
            f"{min(times[n, w]) * 1e6:6.3f} us ({statistics.median(ratios[n, w]):.3f})"
            for w in WAYS
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
