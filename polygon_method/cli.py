"""The ``polygon-method`` command: ``main(argv) -> int``.

Exit codes: 0 success; 1 ``check`` found a wrong answer; 2 bad input (one line on stderr,
never a traceback); 3 an internal error (a bug: please report it).
Only this module writes files, and it writes them whole or not at all.
"""

from __future__ import annotations

import argparse
import math
import json
import os
import sys
import tempfile
from pathlib import Path

from .errors import PolygonMethodError, SceneError

__all__ = ["main", "write_output"]


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit 2
        self.exit(2, f"{self.prog}: error: {message}\n")


def write_output(path, data, *, binary=False) -> None:
    """Write ``data`` to ``path`` atomically: a temporary file renamed into place."""
    path = Path(path)
    directory = path.parent if str(path.parent) else Path(".")
    if not directory.is_dir():
        raise PolygonMethodError(f"cannot write {path}: no directory {directory}")
    fd, tmp = tempfile.mkstemp(dir=directory, prefix=f".{path.name}.", suffix=".tmp")
    try:
        with os.fdopen(fd, "wb" if binary else "w", **({} if binary else
                                                       {"encoding": "utf-8"})) as fh:
            fh.write(data)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(tmp, 0o666 & ~umask)  # as an ordinary new file (mkstemp makes it 0600)
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except OSError:
            pass
        raise


def _cmd_solve(args) -> int:
    from .scene import load_scene
    from .solution import solve

    sol = solve(load_scene(args.scene))
    if args.json:
        print(json.dumps(sol.to_dict(), indent=2, allow_nan=False))
    else:
        from .report import solution_text
        print(solution_text(sol))
    return 0


def _cmd_plan(args) -> int:
    from .plan import compile_plan
    from .scene import load_scene

    print(compile_plan(load_scene(args.scene)))
    return 0


def _cmd_steps(args) -> int:
    from .scene import load_scene
    from .solution import solve
    from .steptable import steps_text

    print(steps_text(solve(load_scene(args.scene)), fmt=args.format))
    return 0


def _cmd_check(args) -> int:
    from .check import run_check

    return run_check(args)


def _cmd_draw(args) -> int:
    from .draw import run_draw

    return run_draw(args, write_output)


def _requested_angles(args):
    """Crank angles (rad) from ``--steps N`` or ``--from A --to B --step S`` (deg)."""
    import numpy as np
    ranged = any(v is not None for v in (args.start, args.stop, args.step))
    if args.steps is not None and ranged:
        raise SceneError("give either --steps N or --from A --to B --step S, not both")
    if ranged:
        if args.start is None or args.stop is None or args.step is None:
            raise SceneError("--from, --to and --step go together (degrees)")
        a, b, s = args.start, args.stop, args.step
        if not all(math.isfinite(v) for v in (a, b, s)):
            raise SceneError("--from, --to and --step must be finite numbers")
        if s == 0 or (b - a) * s < 0:
            raise SceneError(f"--step {s:g} does not lead from {a:g} to {b:g} deg")
        count = int(math.floor((b - a) / s + 1e-9)) + 1
        if count > 100_000_000:
            raise SceneError(f"{count} crank angles are too many (at most 10^8)")
        return np.radians(a + s * np.arange(count))
    n = 360 if args.steps is None else args.steps
    if n < 1:
        raise SceneError(f"--steps must be at least 1, got {n}")
    if n > 100_000_000:
        raise SceneError(f"--steps {n} is too many (at most 10^8)")
    return np.linspace(0.0, 2.0 * math.pi, n, endpoint=False)


def _cmd_sweep(args) -> int:
    """``polygon-method sweep SCENE [--steps N | --from A --to B --step S] [--csv FILE]
    [--plot FILE.svg] [--summary]``: print the summary; the CSV and the plot are written by
    ``write_output`` (whole or not at all)."""
    from .plots import plot_bytes
    from .scene import load_scene
    from .summary import summarize, summary_of
    from .sweeps import sweep

    plot = getattr(args, "plot", None)
    if plot and not plot.lower().endswith((".svg", ".png", ".pdf")):
        raise SceneError(f"--plot {plot}: the file must end in .svg, .png or .pdf")
    scene = load_scene(args.scene)
    angles = _requested_angles(args)
    want_summary = args.summary or not (args.csv or plot)
    if not (args.csv or plot):
        print(summarize(scene, angles).text())
        return 0
    res = sweep(scene, angles)
    if not len(res):
        raise PolygonMethodError("none of the requested crank angles can be reached "
                                 "on the scene's branch " + _limits_text(res.domain),
                                 file=scene.file)
    outputs = []
    if args.csv:
        outputs.append((args.csv, res.to_csv(), False))
    if plot:
        outputs.append((plot, plot_bytes(res, plot, points=_names(args, "points"),
                                         links=_names(args, "links")), True))
    for path, data, binary in outputs:
        write_output(path, data, binary=binary)
    if want_summary:
        print(summary_of(res).text())
    else:
        print(f"{len(res)} of {res.requested} crank angles evaluated"
              + (f"; {_limits_text(res.domain)}" if res.domain.limits else ""))
    return 0


def _names(args, what):
    raw = getattr(args, what, None)
    if not raw:
        return None
    return tuple(x.strip() for x in raw.split(",") if x.strip())


def _limits_text(dom) -> str:
    if not dom.limits:
        return ""
    return ("(limit positions at " + " and ".join(f"{lp.degrees:.4f} deg" for lp in dom.limits)
            + ")")


def _cmd_linkage(args) -> int:
    from .linkage import run_linkage

    return run_linkage(args)


def build_parser() -> argparse.ArgumentParser:
    p = _Parser(prog="polygon-method",
                description="Planar mechanisms by the relative-velocity (polygon) method.")
    from . import __version__
    p.add_argument("--version", action="version", version=f"polygon-method {__version__}")
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True

    s = sub.add_parser("solve", help="solve a scene at its stated instant")
    s.add_argument("scene")
    s.add_argument("--json", action="store_true", help="machine-readable output (SI)")
    s.set_defaults(func=_cmd_solve)

    s = sub.add_parser("plan", help="print the construction plan")
    s.add_argument("scene")
    s.set_defaults(func=_cmd_plan)

    s = sub.add_parser("steps", help="the hand solution, step by step")
    s.add_argument("scene")
    s.add_argument("--format", choices=("text", "markdown"), default="text")
    s.set_defaults(func=_cmd_steps)

    s = sub.add_parser("check", help="check answers against the solution")
    s.add_argument("scene")
    s.add_argument("answers", nargs="?", help="a TOML file with an [answers] table")
    s.add_argument("--json", action="store_true")
    s.set_defaults(func=_cmd_check)

    s = sub.add_parser("draw", help="true-to-scale SVG/PNG/PDF diagrams")
    s.add_argument("scene")
    s.add_argument("-o", "--output", required=True, help="FILE.svg, .png or .pdf")
    s.add_argument("--diagram", choices=("configuration", "velocity", "acceleration", "all"),
                   default="all")
    s.add_argument("--scale", action="append", default=[],
                   help='e.g. "1 cm = 0.1 m/s" (may be repeated: space, velocity, '
                        'acceleration)')
    s.set_defaults(func=_cmd_draw)

    s = sub.add_parser("sweep", help="the whole crank cycle")
    s.add_argument("scene")
    s.add_argument("--steps", type=int, help="N crank angles over a turn (default 360)")
    s.add_argument("--from", dest="start", type=float, help="first crank angle (deg)")
    s.add_argument("--to", dest="stop", type=float, help="last crank angle (deg)")
    s.add_argument("--step", type=float, help="crank angle step (deg)")
    s.add_argument("--csv", help="FILE.csv: one row per crank angle")
    s.add_argument("--plot", help="FILE.svg, .png or .pdf")
    s.add_argument("--points", help="points to plot, e.g. C,E (default: all moving points)")
    s.add_argument("--links", help="links to plot, e.g. BC,CD (default: all moving links)")
    s.add_argument("--summary", action="store_true",
                   help="maxima and minima with their crank angles")
    s.set_defaults(func=_cmd_sweep)

    s = sub.add_parser("linkage", help="Grashof, toggle positions, transmission angle")
    s.add_argument("scene")
    s.set_defaults(func=_cmd_linkage)
    return p


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        return args.func(args)
    except PolygonMethodError as exc:
        print(f"polygon-method {args.command}: {exc.one_line()}", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        return 0
    except Exception as exc:  # a bug: still one line, never a traceback
        print(f"polygon-method {args.command}: internal error ({type(exc).__name__}: {exc}); "
              "please report it with the scene file", file=sys.stderr)
        return 3


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
