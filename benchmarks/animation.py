"""Time and memory of ``draw --animate`` (GIF and HTML) and of ``page``, each in a fresh
process, for the seed four-bar at 180 frames (the default) and 360 (the most a GIF may
have).

    python benchmarks/animation.py [CHECKOUT]   # CHECKOUT: another copy, to compare

Each line: the command, the wall and processor time (medians of three runs) and the
process's peak resident memory. The machine's other load shows in the times. A benchmark, not a test:
nothing here fails on time.
"""

from __future__ import annotations

import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
SEED = ROOT / "worked_problems" / "fourbar_image_points.toml"


def run(args, root=ROOT) -> tuple[float, float, float]:
    """Wall time (s), processor time (s) and peak resident memory (MB) of one fresh
    process."""
    env = dict(os.environ, PYTHONPATH=str(root))
    code = (
        "import resource, sys; from polygon_method.cli import main; rc = main(sys.argv[1:]);"
        " r = resource.getrusage(resource.RUSAGE_SELF);"
        " print(r.ru_utime + r.ru_stime, r.ru_maxrss, file=sys.stderr); sys.exit(rc)"
    )
    t = time.perf_counter()
    done = subprocess.run(
        [sys.executable, "-c", code, *args],
        env=env,
        cwd=root,
        capture_output=True,
        text=True,
        check=True,
    )
    wall = time.perf_counter() - t
    cpu, kb = (float(x) for x in done.stderr.strip().splitlines()[-1].split())
    return wall, cpu, kb / 1024  # ru_maxrss is in KB on Linux


def main() -> None:
    root = Path(sys.argv[1]).resolve() if len(sys.argv) > 1 else ROOT  # another checkout
    with tempfile.TemporaryDirectory() as d:
        for what, frames in (("gif", 180), ("gif", 360), ("html", 180), ("page", 180)):
            out = Path(d) / f"cycle.{'html' if what == 'page' else what}"
            args = (
                ["page", str(SEED), "-o", str(out), "--frames", str(frames)]
                if what == "page"
                else ["draw", str(SEED), "--animate", "-o", str(out), "--frames", str(frames)]
            )
            runs = [run(args, root) for _ in range(3)]
            wall = statistics.median(r[0] for r in runs)
            cpu = statistics.median(r[1] for r in runs)
            peak = max(r[2] for r in runs)
            size = out.stat().st_size / 1e6
            print(
                f"{what:5s} {frames:4d} frames: {wall:6.2f} s ({cpu:6.2f} s of processor), "
                f"peak {peak:6.1f} MB, file {size:5.2f} MB"
            )


if __name__ == "__main__":
    main()
