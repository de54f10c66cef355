"""Speed of polygon-method against the issue's targets, and against PyPI peers if installed.

    python benchmarks/speed.py            # everything (about a minute)
    python benchmarks/speed.py --quick    # fewer repeats

Measures (medians of repeated runs; the machine's other load shows in the spread):

* one configuration, full analysis of ``worked_problems/fourbar_image_points.toml`` after
  loading (plan cached on the scene): ``solve(scene)`` plus rubbing and input torque;
* a full cycle of 3600 crank angles, every quantity (``sweep``), for a Grashof four-bar and
  for the image-points four-bar (non-Grashof: 3600 angles across its reachable range);
* 1,000,000 crank angles: ``sweep`` (all arrays kept) and ``summarize`` (reduced chunk by
  chunk), each in a fresh process for its peak memory;
* the command line end to end: ``sweep --steps 1000000 --summary`` and ``solve --json``
  (cold start; also checks that ``solve`` imports neither matplotlib nor shapely);
* the peers ``pylinkage`` and ``mechanism`` (``pip install polygon-method[peers]``) on the
  same four-bar, when they can be imported; the ratios are printed.

A benchmark, not a test: nothing here fails on time.
"""

from __future__ import annotations

import argparse
import json
import math
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PROBLEMS = ROOT / "worked_problems"
IMAGE_POINTS = PROBLEMS / "fourbar_image_points.toml"
GRASHOF = PROBLEMS / "fourbar_crank_acceleration.toml"  # AB 40, BC 120, CD 80, AD 100

TARGETS = {  # seconds
    "single": 15e-6,
    "cycle": 1.5e-3,
    "million": 0.2,
    "cli_million": 1.0,
    "cli_solve": 0.25,
}


def timeit(fn, repeat, number=1):
    """Median and minimum time of one call of ``fn`` over ``repeat`` runs of ``number``."""
    runs = []
    for _ in range(repeat):
        t = time.perf_counter()
        for _ in range(number):
            fn()
        runs.append((time.perf_counter() - t) / number)
    return statistics.median(runs), min(runs)


def fmt(t):
    if t < 1e-3:
        return f"{t * 1e6:8.2f} us"
    if t < 1:
        return f"{t * 1e3:8.3f} ms"
    return f"{t:8.3f} s "


def verdict(t, target):
    return f"target {fmt(target).strip():>9}: {'met' if t <= target else 'MISSED'}"


def run_child(code):
    """Run ``code`` in a fresh interpreter; it prints one JSON line, returned as a dict."""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=ROOT, check=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def bench_single(repeat):
    from polygon_method import load_scene, solve

    scene = load_scene(IMAGE_POINTS)
    solve(scene)  # compiles and caches the plan

    def full():  # and the rubbing table as objects, and the torque
        sol = solve(scene)
        sol.rubbing
        sol.input_torque
        return sol

    # solve() computes positions, velocities, accelerations, E, F, G and the rubbing
    # velocity of every pair at every pin (in the compiled kernel)
    solve_med, solve_min = timeit(lambda: solve(scene), repeat, 2000)
    full_med, _ = timeit(full, repeat, 2000)
    return {"single": solve_med, "single_min": solve_min, "single_tables": full_med}


def bench_cycle(repeat):
    import numpy as np

    from polygon_method import load_scene
    from polygon_method.sweeps import Sweeper, sweep

    out = {}
    g = load_scene(GRASHOF)
    th = np.linspace(0.0, 2 * math.pi, 3600, endpoint=False)
    t = time.perf_counter()
    res = sweep(g, th)
    out["cycle_cold"] = time.perf_counter() - t  # includes finding the branch's domain
    assert len(res) == 3600
    out["cycle"], out["cycle_min"] = timeit(lambda: sweep(g, th), repeat, 20)
    ip = load_scene(IMAGE_POINTS)
    dom = Sweeper(ip).domain
    th2 = dom.lo + (dom.hi - dom.lo) * (np.arange(3600) + 0.5) / 3600
    res = sweep(ip, th2)
    assert len(res) == 3600
    out["cycle_image_points"], _ = timeit(lambda: sweep(ip, th2), repeat, 20)
    return out


MILLION_SWEEP = """
import json, math, resource, time
import numpy as np
from polygon_method import load_scene
from polygon_method.sweeps import {fn}
scene = load_scene({path!r})
th = np.linspace(0.0, 2 * math.pi, 1_000_000, endpoint=False)
{fn}(scene, th[:3600])  # plan and domain cached, as after loading
best = 1e9
for _ in range({repeat}):
    t = time.perf_counter()
    r = {fn}(scene, th)
    best = min(best, time.perf_counter() - t)
    del r
rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
print(json.dumps({{"time": best, "rss_mb": rss}}))
"""


def bench_million(repeat):
    out = {}
    for fn in ("sweep", "summarize"):
        r = run_child(MILLION_SWEEP.format(fn=fn, path=str(GRASHOF), repeat=repeat))
        out[f"million_{fn}"] = r["time"]
        out[f"million_{fn}_rss"] = r["rss_mb"]
    return out


def bench_cli(repeat):
    out = {}
    runs = []
    for _ in range(max(3, repeat // 2)):
        t = time.perf_counter()
        subprocess.run([sys.executable, "-m", "polygon_method", "sweep", str(GRASHOF),
                        "--steps", "1000000", "--summary"], cwd=ROOT, check=True,
                       capture_output=True)
        runs.append(time.perf_counter() - t)
    out["cli_million"] = statistics.median(runs)
    runs = []
    for _ in range(max(5, repeat)):
        t = time.perf_counter()
        subprocess.run([sys.executable, "-m", "polygon_method", "solve", str(IMAGE_POINTS),
                        "--json"], cwd=ROOT, check=True, capture_output=True)
        runs.append(time.perf_counter() - t)
    out["cli_solve"] = statistics.median(runs)
    code = ("import sys, io, contextlib, json\n"
            "from polygon_method.cli import main\n"
            "with contextlib.redirect_stdout(io.StringIO()):\n"
            f"    main(['solve', {str(IMAGE_POINTS)!r}, '--json'])\n"
            "print(json.dumps({m: m in sys.modules for m in ('matplotlib', 'shapely')}))")
    out["solve_imports"] = run_child(code)
    return out


# --------------------------------------------------------------------------- peers


def bench_pylinkage(repeat):
    """pylinkage's four-bar factory, stepped with derivatives (positions, velocities,
    accelerations of the joints), one step per crank increment."""
    try:
        from pylinkage.mechanism import fourbar
    except ImportError:
        return None

    def make():
        m = fourbar(crank=0.04, coupler=0.12, rocker=0.08, ground=0.10,
                    omega=2 * math.pi / 3600, initial_angle=math.radians(120))
        m.set_input_velocity(m._driver_links[0], 20.0, 150.0)
        return m

    m = make()
    list(m.step_with_derivatives(iterations=10))
    per_cycle, _ = timeit(lambda: list(make().step_with_derivatives(iterations=3600)),
                          max(1, repeat // 3))
    out = {"pylinkage_cycle": per_cycle, "pylinkage_step": per_cycle / 3600}
    try:  # the numba path, where numba is installed
        import numba  # noqa: F401
        m = make()
        m.step_fast_with_kinematics(iterations=3600)
        out["pylinkage_numba_cycle"], _ = timeit(
            lambda: m.step_fast_with_kinematics(iterations=3600), repeat)
    except ImportError:
        pass
    return out


def bench_mechanism(repeat):
    """``mechanism`` (gabemorris12): vector loop solved by scipy's fsolve at each position,
    for position, velocity and acceleration."""
    try:
        import numpy as np
        from mechanism import Mechanism, Vector, get_joints
    except ImportError:
        return None

    n = 200

    def run():
        O, A, B, C = get_joints("O A B C")
        a = Vector((O, A), r=0.04)
        b = Vector((A, B), r=0.12)
        c = Vector((O, C), r=0.10, theta=0, style="ground")
        d = Vector((C, B), r=0.08)

        def loops(x, inp):
            return a(inp) + b(x[0]) - c() - d(x[1])

        th = math.radians(120) + np.linspace(0, 2 * math.pi, n, endpoint=False)
        m = Mechanism(vectors=(a, b, c, d), origin=O, loops=loops, pos=th,
                      vel=np.full(n, 20.0), acc=np.full(n, 150.0),
                      guess=(np.radians([20.0, 80.0]), np.array([3.0, 10.0]),
                             np.array([70.0, 30.0])))
        m.iterate()
        return m

    t, _ = timeit(run, max(1, repeat // 5))
    return {"mechanism_step": t / n, "mechanism_cycle": t / n * 3600}


# --------------------------------------------------------------------------- report


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer repeats")
    ap.add_argument("--json", action="store_true", help="print the numbers as JSON too")
    args = ap.parse_args(argv)
    repeat = 5 if args.quick else 15
    r = {}
    r.update(bench_single(repeat))
    r.update(bench_cycle(repeat))
    r.update(bench_million(max(2, repeat // 5)))
    r.update(bench_cli(repeat))
    peers = {}
    for fn in (bench_pylinkage, bench_mechanism):
        p = fn(repeat)
        if p:
            peers.update(p)
    r.update(peers)

    print(f"polygon-method speed ({sys.platform}, Python {sys.version.split()[0]})")
    print(f"one configuration, full analysis (solve: image points, rubbing): "
          f"{fmt(r['single'])}  (min {fmt(r['single_min']).strip()}; with the rubbing "
          f"table's objects and the torque {fmt(r['single_tables']).strip()})"
          f"  {verdict(r['single'], TARGETS['single'])}")
    print(f"full cycle, 3600 angles, every quantity (Grashof four-bar): {fmt(r['cycle'])}"
          f"  (first call, finding the branch: {fmt(r['cycle_cold']).strip()})"
          f"  {verdict(r['cycle'], TARGETS['cycle'])}")
    print(f"  3600 angles over the image-points four-bar's reachable range: "
          f"{fmt(r['cycle_image_points'])}")
    print(f"1,000,000 angles, sweep (all arrays kept): {fmt(r['million_sweep'])}, peak "
          f"{r['million_sweep_rss']:.0f} MB  {verdict(r['million_sweep'], TARGETS['million'])}")
    print(f"1,000,000 angles, summarize (reduced per chunk): {fmt(r['million_summarize'])}, "
          f"peak {r['million_summarize_rss']:.0f} MB  "
          f"{verdict(r['million_summarize'], TARGETS['million'])}")
    print(f"CLI sweep --steps 1000000 --summary, end to end: {fmt(r['cli_million'])}  "
          f"{verdict(r['cli_million'], TARGETS['cli_million'])}")
    print(f"CLI solve --json, cold start: {fmt(r['cli_solve'])}  "
          f"{verdict(r['cli_solve'], TARGETS['cli_solve'])}; imports: "
          + ", ".join(f"{k} {'YES' if v else 'no'}" for k, v in r["solve_imports"].items()))
    if "pylinkage_step" in r:
        print(f"pylinkage (step_with_derivatives): {fmt(r['pylinkage_step'])} per position, "
              f"{fmt(r['pylinkage_cycle'])} per 3600-angle cycle: "
              f"{r['pylinkage_step'] / r['single']:.1f}x our single position, "
              f"{r['pylinkage_cycle'] / r['cycle']:.0f}x our cycle")
        if "pylinkage_numba_cycle" in r:
            print(f"pylinkage (numba): {fmt(r['pylinkage_numba_cycle'])} per cycle: "
                  f"{r['pylinkage_numba_cycle'] / r['cycle']:.1f}x ours")
    else:
        print("pylinkage: not installed (pip install polygon-method[peers])")
    if "mechanism_step" in r:
        print(f"mechanism (fsolve): {fmt(r['mechanism_step'])} per position, "
              f"{fmt(r['mechanism_cycle'])} per 3600-angle cycle: "
              f"{r['mechanism_step'] / r['single']:.0f}x our single position, "
              f"{r['mechanism_cycle'] / r['cycle']:.0f}x our cycle")
    else:
        print("mechanism: not installed (pip install polygon-method[peers])")
    if args.json:
        print(json.dumps(r, default=str))
    return 0


if __name__ == "__main__":
    sys.exit(main())
