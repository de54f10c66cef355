"""Where the time of a scene never solved before goes: from its text to one solved position,
stage by stage (the TOML, the reading into a checked ``Scene``, compiling the plan, the
first solve), each the least of many small batches (the least is the machine's own speed:
a shared machine only adds to it).

    python benchmarks/reading.py                 # the seed's worked file, stage by stage
    python benchmarks/reading.py FILE.toml       # another scene
    python benchmarks/reading.py --profile 30    # and cProfile's 30 costliest functions
    python benchmarks/reading.py --count 200     # only N never-seen solves from the text,
                                                 # for valgrind (below); with --loaded,
                                                 # from the loaded scene (no reading)
    python benchmarks/reading.py --side-by-side 150   # the two figures with their targets,
                                                 # taken in turn with pylinkage's build

The two figures and their targets: the seed's worked file from text to solved, as ``solve``
reads it, at most 0.3 ms (the issue set it on a machine where ``tomllib`` read that file
in 0.45 ms, so the side-by-side rounds also time ``tomllib`` on it: at most two thirds of
that, on any machine); a mechanism never seen (``speed.py``'s four-bar), from its loaded
scene to one solved position, at most 0.8 of pylinkage building the same four-bar and
stepping it once. ``--side-by-side N`` takes the three in turn, in small batches, N rounds,
each figure the least (a shared machine's load comes and goes: a figure measured a minute
after its peer is compared with another machine).

Counted in instructions, which the machine's other load does not move, by
``python benchmarks/instructions.py worked fresh tomllib``; or by hand (the difference of
200 runs and none, the hash seed fixed, numpy's threads held to one: idle, they spin, and
move the count from run to run)::

    OPENBLAS_NUM_THREADS=1 PYTHONHASHSEED=0 valgrind --tool=cachegrind --cache-sim=no \
        --cachegrind-out-file=/dev/null \
        python benchmarks/reading.py --count 200     # and again with --count 0

``solve`` reads a scene as ``parse_scene(text, variants=False, answers=False)`` does: its
``[variants]`` and ``[answers]`` left unread (``check`` reads the answers, ``variants``
the variants). The plan caches are emptied before each compile, as for a scene never seen.
A benchmark, not a test: nothing here fails on time (``speed.py`` holds the targets).
"""

from __future__ import annotations

import argparse
import cProfile
import pstats
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # this tree's package, not an installed one
SEED = ROOT / "worked_problems" / "fourbar_image_points.toml"


def least(fn, batches=300, number=10):
    """The least time of one call of ``fn`` over ``batches`` batches of ``number`` calls."""
    best = float("inf")
    for _ in range(batches):
        t = time.perf_counter()
        for _ in range(number):
            fn()
        best = min(best, (time.perf_counter() - t) / number)
    return best


def stages(text):
    """(name, function) of each stage of a scene read from ``text`` and solved."""
    from polygon_method import parse_scene, solve
    from polygon_method.scene.reading import toml_table
    from polygon_method.solver import compiler

    def fresh():
        compiler._BY_ID.clear()
        compiler._BY_CONTENT.clear()

    scene = parse_scene(text, variants=False, answers=False)

    def compile_only():
        fresh()
        return compiler.compile_plan(scene)

    def compile_and_solve():
        fresh()
        return solve(scene)

    def text_to_solved():
        fresh()
        return solve(parse_scene(text, variants=False, answers=False))

    return [
        ("the TOML (a compiled reader)", lambda: toml_table(text)),
        ("text -> checked Scene", lambda: parse_scene(text, variants=False, answers=False)),
        ("Scene -> plan (compiled)", compile_only),
        ("Scene -> one solved position", compile_and_solve),
        ("warm solve (plan cached)", lambda: solve(scene)),
        ("text -> solved, never seen", text_to_solved),
    ]


def side_by_side(text, rounds):
    """{name: least seconds per call} of the worked file from ``text`` to solved, the
    four-bar never seen from its loaded scene, and pylinkage's build and step, taken in
    turn in small batches over ``rounds`` rounds."""
    from speed import FOURBAR_TEXT, _pylinkage_build_and_step

    from polygon_method import parse_scene, solve
    from polygon_method.solver import compiler

    loaded = parse_scene(FOURBAR_TEXT)

    def worked():
        compiler._BY_ID.clear()
        compiler._BY_CONTENT.clear()
        return solve(parse_scene(text, variants=False, answers=False))

    def fresh():
        compiler._BY_ID.clear()
        compiler._BY_CONTENT.clear()
        return solve(loaded)

    import tomllib

    batches = {"worked": (worked, 5), "fresh": (fresh, 10)}
    batches["pylinkage"] = (_pylinkage_build_and_step, 10)
    # the machine's yardstick: Python's own TOML reader on the same text (the 0.3
    # ms was set where it took 0.45 ms: two thirds of it on any machine)
    batches["tomllib"] = (lambda: tomllib.loads(text), 5)
    best = dict.fromkeys(batches, float("inf"))
    for fn, _ in batches.values():
        fn()  # imports and first-call costs out of the way
    clock = time.perf_counter
    for _ in range(rounds):
        for name, (fn, n) in batches.items():
            t = clock()
            for _ in range(n):
                fn()
            best[name] = min(best[name], (clock() - t) / n)
    return best


def _print_side_by_side(text, rounds):
    try:
        best = side_by_side(text, rounds)
    except ImportError:  # pylinkage not installed: pip install '.[peers]'
        print("pylinkage is not installed (pip install '.[peers]')")
        return
    from importlib.metadata import version

    worked, ratio = best["worked"], best["fresh"] / best["pylinkage"]
    yard = worked / best["tomllib"]
    print(f"side by side, the least of {rounds} rounds (pylinkage {version('pylinkage')}):")
    print(
        f"  the worked file, text -> solved    {worked * 1e6:8.1f} us   "
        f"at most 300 us: {'met' if worked <= 3e-4 else 'not met'}"
    )
    print(
        f"    against tomllib reading the same text ({best['tomllib'] * 1e6:.1f} us): "
        f"{yard:.3f}   at most 0.667 (0.3 ms where it took 0.45): "
        f"{'met' if yard <= 2 / 3 else 'not met'}"
    )
    print(
        f"  a four-bar never seen, loaded -> solved {best['fresh'] * 1e6:6.1f} us, pylinkage's "
        f"build and step {best['pylinkage'] * 1e6:.1f} us: {ratio:.3f}   "
        f"at most 0.8: {'met' if ratio <= 0.8 else 'not met'}"
    )


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene", nargs="?", default=str(SEED))
    parser.add_argument("--profile", type=int, default=0, metavar="N")
    parser.add_argument("--count", type=int, default=None, metavar="N")
    parser.add_argument("--loaded", action="store_true")
    parser.add_argument("--side-by-side", type=int, default=0, metavar="ROUNDS")
    args = parser.parse_args(argv)
    text = Path(args.scene).read_text()
    if args.side_by_side:
        return _print_side_by_side(text, args.side_by_side)
    rows = stages(text)
    if args.count is not None:  # for counting instructions: warm, then N whole runs
        whole = rows[3 if args.loaded else -1][1]
        for _ in range(20 + args.count):
            whole()
        return
    for name, fn in rows:
        fn()  # imports and first-call costs out of the way
    print(f"{Path(args.scene).name}: least of 300 batches of 10")
    for name, fn in rows:
        print(f"  {name:32s} {least(fn) * 1e6:9.1f} us")
    if args.profile:
        whole = rows[-1][1]
        prof = cProfile.Profile()
        prof.enable()
        for _ in range(2000):
            whole()
        prof.disable()
        pstats.Stats(prof).sort_stats("tottime").print_stats(args.profile)


if __name__ == "__main__":
    main()
