"""The warm solve's figures counted in machine instructions, which no other load moves.

    python benchmarks/instructions.py               # every case (a few minutes)
    python benchmarks/instructions.py full floor    # only these
    python benchmarks/instructions.py --case full --count 2000   # one run (what is counted)

Each case runs in a fresh interpreter under valgrind's cachegrind (``--cache-sim=no``, the
hash seed fixed: with a random one the same run's count moves by a tenth; numpy's linear
algebra on one thread: its idle threads spin, a start's count moved by some tens of
millions from run to run), once making N
calls and once making none; the difference over N is the instructions per call. On a
machine shared with other work the times of ``speed.py`` and ``forces_speed.py`` jump from
minute to minute; these counts do not (they leave out what the time also holds: the misses
of the caches and the branches mispredicted, which make the warm solve's time ratio to the
floor larger than its instruction ratio).

Cases: ``solve`` (the seed's warm ``solve`` alone), ``full`` (and its rubbing at four pins
and the torque read, as ``speed.py`` times it), ``named`` (and every dict of the motion
read), ``floor`` and ``floor_tuple`` (``speed.floor_fourbar``: the same numbers by name, or
unnamed), ``kinematic`` and ``forces`` (``worked_problems/fourbar_forces.toml``: its warm
solve, and its warm force solve alone), ``chain1001`` and ``chain10001`` (a chain of dyads'
warm solve, per link; its time per link at 1,001, 10,001 and 100,001 links side by side:
``chain.py``), ``worked`` (the seed's worked file from text to solved, as ``solve``
reads it, its plan never seen), ``tomllib`` (Python's TOML reader on that text: the
yardstick of the 0.3 ms target) and ``fresh`` (``speed.py``'s four-bar never seen, from
its loaded scene to one solved position).

A benchmark, not a test: nothing here fails on time.
"""

from __future__ import annotations

import argparse
import importlib.util
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent))  # this tree's package, not an installed one
CASES = (
    "solve",
    "full",
    "named",
    "floor",
    "floor_tuple",
    "kinematic",
    "forces",
    "chain1001",
    "chain10001",
    "worked",
    "fresh",
    "tomllib",
)
#: calls counted per case (fewer for the long ones); a chain's count is per link
CALLS = {"chain1001": 20, "chain10001": 4, "worked": 300, "tomllib": 300, "fresh": 1000}


def _function(case):
    """The function one call of ``case`` makes, and what one call counts (links or 1)."""
    spec = importlib.util.spec_from_file_location("speed", HERE / "speed.py")
    speed = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(speed)

    from polygon_method import load_scene, parse_scene, solve

    if case.startswith("chain"):
        n = (int(case[5:]) - 1) // 2
        scene = parse_scene(speed.chain_text(n))
        solve(scene)
        return (lambda: solve(scene)), 2 * n + 1
    if case in ("worked", "fresh", "tomllib"):
        import tomllib

        from polygon_method.solver import compiler

        text = speed.IMAGE_POINTS.read_text()
        if case == "tomllib":
            return (lambda: tomllib.loads(text)), 1
        loaded = parse_scene(speed.FOURBAR_TEXT)

        def worked():  # as solve reads it: [variants] and [answers] left unread
            compiler._BY_ID.clear()
            compiler._BY_CONTENT.clear()
            return solve(parse_scene(text, variants=False, answers=False))

        def fresh():
            compiler._BY_ID.clear()
            compiler._BY_CONTENT.clear()
            return solve(loaded)

        return (worked if case == "worked" else fresh), 1
    if case in ("floor", "floor_tuple"):
        floor = speed.floor_fourbar()
        return (floor if case == "floor" else (lambda: floor(True))), 1
    if case in ("kinematic", "forces"):
        from polygon_method.forces import analyse

        scene = load_scene(speed.PROBLEMS / "fourbar_forces.toml")
        sol = solve(scene)
        analyse(sol)
        return ((lambda: solve(scene)) if case == "kinematic" else (lambda: analyse(sol))), 1
    scene = load_scene(speed.IMAGE_POINTS)
    solve(scene)

    def full():
        sol = solve(scene)
        for r in sol.rubbing.values():
            r.rubbing_velocity
        sol.input_torque
        return sol

    def named():
        sol = full()
        return sol.P, sol.V, sol.A, sol.W, sol.Al, sol.cond

    return {"solve": lambda: solve(scene), "full": full, "named": named}[case], 1


def _count(case, calls):
    """Instructions of a fresh interpreter making ``calls`` calls of ``case``."""
    # the hash seed fixed, and numpy's linear algebra on one thread: its worker threads
    # spin while they wait, and their count moved the start's by tens of millions
    env = dict(os.environ, PYTHONHASHSEED="0", OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    run = subprocess.run(
        [
            "valgrind",
            "--tool=cachegrind",
            "--cache-sim=no",
            "--cachegrind-out-file=/dev/null",
            sys.executable,  # as given: a virtual environment's link keeps its packages
            __file__,
            "--case",
            case,
            "--count",
            str(calls),
        ],
        capture_output=True,
        text=True,
        env=env,
    )
    found = re.search(r"I\s+refs:\s+([\d,]+)", run.stderr)
    if found is None or run.returncode != 0:
        raise SystemExit(f"valgrind gave no count for {case}:\n{run.stderr[-2000:]}")
    return int(found.group(1).replace(",", ""))


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("cases", nargs="*", choices=(*CASES, []), metavar="CASE")
    ap.add_argument("--case", help=argparse.SUPPRESS)
    ap.add_argument("--count", type=int, default=2000, help="calls counted per case")
    args = ap.parse_args(argv)
    if args.case:  # the child: warm, then the calls counted
        fn, _ = _function(args.case)
        fn()
        fn()
        for _ in range(args.count):
            fn()
        return
    if shutil.which("valgrind") is None:
        raise SystemExit("valgrind is not installed (apt-get install valgrind)")
    got = {}
    for case in args.cases or CASES:
        calls = CALLS.get(case, args.count)
        per = 1
        if case.startswith("chain"):
            per = int(case[5:])
        got[case] = (_count(case, calls) - _count(case, 0)) / calls / per
        unit = "per link" if per > 1 else "per call"
        print(f"{case:<12} {got[case]:>10,.0f} instructions {unit}", flush=True)
    for ours, floor, words in (
        ("full", "floor", "warm full solve / the floor"),
        ("named", "floor", "the same, its dicts read / the floor"),
        ("full", "floor_tuple", "warm full solve / the floor, unnamed"),
        ("forces", "kinematic", "force solve / its kinematic solve"),
        ("chain10001", "chain1001", "a chain's solve per link, 10,001 / 1,001 links"),
        ("worked", "tomllib", "the worked file, text -> solved / tomllib on it"),
    ):
        if ours in got and floor in got:
            print(f"{words:<48} {got[ours] / got[floor]:.2f}")


if __name__ == "__main__":
    main()
