"""The ``polygon-method`` command: ``main(argv) -> int``.

Exit codes: 0 success; 1 ``check`` found a wrong answer; 2 bad input (one line on stderr,
never a traceback); 3 an internal error (a bug: please report it).
Only this module writes files, and it writes them whole or not at all.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import stat
import sys
import tempfile
from pathlib import Path

from .errors import PolygonMethodError, SceneError, printable

__all__ = ["main", "write_output"]


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit 2
        self.exit(2, f"{self.prog}: error: {message}\n")


class _Target:
    """Where one output goes: a new or regular file (written beside it, then renamed over
    it), or a special file (a device, a pipe: written straight into it). A symbolic link is
    written through, never replaced."""

    def __init__(self, path, option, protect=()):
        self.shown, self.option = str(path), option
        real = Path(os.path.realpath(path))
        if real.is_dir():
            raise PolygonMethodError(f"cannot write {path}: it is a directory", key=option)
        for other in protect:
            if other and real.exists() and os.path.exists(other) and \
                    os.path.samefile(real, other):
                raise PolygonMethodError(f"cannot write {path}: it is the scene file "
                                         "itself", key=option)
        self.path = real
        self.special = real.exists() and not stat.S_ISREG(real.stat().st_mode)
        directory = real.parent
        if not self.special:
            if not directory.is_dir():
                raise PolygonMethodError(f"cannot write {path}: no directory {directory}",
                                         key=option)
            if not os.access(directory, os.W_OK | os.X_OK):
                raise PolygonMethodError(f"cannot write {path}: the directory {directory} is "
                                         "not writable", key=option)
            if real.exists() and not os.access(real, os.W_OK):
                raise PolygonMethodError(f"cannot write {path}: the file is read-only",
                                         key=option)
        self.tmp = None

    def fail(self, exc: OSError):
        return PolygonMethodError(f"cannot write {self.shown}: "
                                  f"{exc.strerror or type(exc).__name__}", key=self.option)

    def stage(self, data, binary):
        self.data, self.binary = data, binary
        if self.special:
            return
        fd, self.tmp = tempfile.mkstemp(dir=self.path.parent, prefix=f".{self.path.name}.",
                                        suffix=".tmp")
        try:
            with os.fdopen(fd, "wb" if binary else "w",
                           **({} if binary else {"encoding": "utf-8"})) as fh:
                fh.write(data)
            umask = os.umask(0)
            os.umask(umask)
            os.chmod(self.tmp, 0o666 & ~umask)  # as an ordinary new file (mkstemp: 0600)
        except OSError as exc:
            raise self.fail(exc) from None

    def commit(self):
        try:
            if self.special:
                with open(self.path, "wb" if self.binary else "w",
                          **({} if self.binary else {"encoding": "utf-8"})) as fh:
                    fh.write(self.data)
            else:
                os.replace(self.tmp, self.path)
                self.tmp = None
        except OSError as exc:
            raise self.fail(exc) from None

    def discard(self):
        if self.tmp is not None:
            try:
                os.unlink(self.tmp)
            except OSError:
                pass
            self.tmp = None


def check_outputs(paths, protect=()) -> list:
    """Every output path checked before anything is computed or written: ``paths`` as
    (path, option) pairs; ``protect``: files that must not be written over (the scene)."""
    return [_Target(path, option, protect) for path, option in paths]


def write_outputs(targets, datas) -> None:
    """Write every output or none: each regular file staged beside itself first; then the
    special files (a device, a pipe: written straight, so the first that fails stops
    everything before any file is replaced); then the staged files renamed into place."""
    try:
        for t, (data, binary) in zip(targets, datas):
            t.stage(data, binary)
        for t in sorted(targets, key=lambda t: not t.special):
            t.commit()
    finally:
        for t in targets:
            t.discard()


def write_output(path, data, *, binary=False, option=None, protect=()) -> None:
    """Write ``data`` to ``path`` whole or not at all (see :func:`write_outputs`)."""
    write_outputs(check_outputs([(path, option)], protect), [(data, binary)])


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


def _cmd_centres(args) -> int:
    """``polygon-method centres SCENE``: the instantaneous centre method."""
    from .centres import locate
    from .centretable import centres_text
    from .scene import load_scene
    from .solution import solve

    prefix = "" if getattr(args, "centre_labels", "I13") == "13" else "I"
    print(centres_text(locate(solve(load_scene(args.scene)), prefix)))
    return 0


def _cmd_steps(args) -> int:
    from .scene import load_scene
    from .solution import solve
    from .steptable import steps_text

    print(steps_text(solve(load_scene(args.scene)), fmt=args.format))
    return 0


def _finite(x):
    """A number JSON can carry: None for an infinite or undefined one."""
    return x if isinstance(x, (int, float)) and math.isfinite(x) else None


def _answer_files(paths):
    """The answer files named: files as given, a directory's *.toml in order."""
    out = []
    for p in paths:
        path = Path(p)
        if path.is_dir():
            out += sorted(str(q) for q in path.glob("*.toml"))
        else:
            out.append(p)
    return out


def _cmd_class(args, scene, sol, files) -> int:
    """A whole class: a row per answer file, the summary, the gradebook."""
    from .check import check_answers, tolerances
    from .check.classroom import (Row, class_dict, class_text, gradebook_csv,
                                  gradebook_markdown, summary_text)
    from .scene import load_answers

    book = getattr(args, "gradebook", None)
    if book and not book.lower().endswith((".csv", ".md")):
        raise SceneError(f"--gradebook {book}: the file must end in .csv or .md",
                         key="--gradebook")
    targets = check_outputs([(book, "--gradebook")], protect=[args.scene]) if book else []
    tols = tolerances(sol)
    rows = []
    for f in files:
        student = Path(f).stem
        try:
            tolerance, answers = load_answers(f, scene)
            if tolerance is None:
                tolerance = scene.tolerance
            rows.append(Row(student, f, check_answers(sol, answers, tolerance, _tols=tols)))
        except PolygonMethodError as exc:  # a row with its error, never the whole run
            line = exc.one_line()
            where = f"{printable(str(f))}: "
            rows.append(Row(student, f, (), error=line[len(where):] if line.startswith(where)
                            else line))
    if getattr(args, "json", False):
        print(json.dumps(class_dict(rows), indent=2, allow_nan=False, default=_finite))
    else:
        print(f"{scene.title or args.scene}: {len(files)} answer files")
        print(class_text(rows))
        print()
        print(summary_text(rows))
    if targets:
        data = gradebook_csv(rows) if book.lower().endswith(".csv") else \
            gradebook_markdown(rows)
        write_outputs(targets, [(data, False)])
    return 0


def _cmd_check(args) -> int:
    """``polygon-method check SCENE [ANSWERS ...] [--json] [--gradebook FILE]``: one
    answer file (or the scene's answers): 0 all right, 1 any wrong; several, or a
    directory: the whole class, 0."""
    from .check import check_answers, verdicts_dict, verdicts_text
    from .scene import load_answers, load_scene
    from .solution import solve

    scene = load_scene(args.scene)
    sol = solve(scene)
    files = _answer_files(args.answers or [])
    if len(files) > 1 or (args.answers and Path(args.answers[0]).is_dir()) or \
            getattr(args, "gradebook", None):
        if not files:
            raise SceneError(f"no answer files in {', '.join(args.answers or ['(none)'])}",
                             key="answers")
        return _cmd_class(args, scene, sol, files)
    args.answers = files[0] if files else None
    if args.answers:
        tolerance, answers = load_answers(args.answers, scene)
    else:
        tolerance, answers = scene.tolerance, scene.answers
    if not answers:
        raise SceneError("nothing to check: the scene has no [answers] and no answer file "
                         "was given", file=args.scene, key="[answers]")
    verdicts = check_answers(sol, answers, tolerance)
    if getattr(args, "json", False):
        d = verdicts_dict(verdicts, args.scene, args.answers)
        for a in d["answers"]:
            for k in ("error_percent", "tolerance_percent"):
                a[k] = _finite(a[k])
        print(json.dumps(d, indent=2, allow_nan=False))
    else:
        title = f"{scene.title or args.scene}: answers from " + \
            (args.answers if args.answers else "the scene")
        print(verdicts_text(verdicts, title))
    return 0 if all(v.ok for v in verdicts) else 1


def _cmd_draw(args) -> int:
    """``polygon-method draw SCENE -o FILE.svg [--diagram ...] [--scale "1 cm = 0.1 m/s"]``:
    written whole or not at all, and not at all when the scene cannot be solved."""
    from .draw import FORMATS, display_unit, parse_scales, render
    from .scene import load_scene
    from .solution import solve

    out = Path(args.output)
    fmt = out.suffix.lower().lstrip(".")
    if fmt not in FORMATS:
        raise PolygonMethodError(f"cannot draw to {out}: the file name must end in .svg, .png "
                                 "or .pdf", key="-o")
    scales = parse_scales(getattr(args, "scale", None))
    targets = check_outputs([(out, "-o")], protect=[args.scene])
    sol = solve(load_scene(args.scene))
    diagram = getattr(args, "diagram", None) or "all"
    prefix = "" if getattr(args, "centre_labels", "I13") == "13" else "I"
    data, used, warnings = render(sol, fmt, diagram, scales, prefix)
    for w in list(sol.warnings) + warnings:
        print(f"warning: {w}", file=sys.stderr)
    write_outputs(targets, [(data, fmt != "svg")])
    print(f"{out}: " + "; ".join(f"{name} {display_unit(s.text)}" for name, s in used.items()))
    return 0


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
        if max(abs(a), abs(b)) > MAX_ANGLE_DEG:
            raise SceneError(f"--from and --to are crank angles in degrees, within "
                             f"+-{MAX_ANGLE_DEG:g} (got {a:g} and {b:g})")
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
    from .scene import load_scene
    from .summary import summarize, summary_of
    from .sweeps import sweep

    plot = getattr(args, "plot", None)
    if plot and not plot.lower().endswith((".svg", ".png", ".pdf")):
        raise SceneError(f"--plot {plot}: the file must end in .svg, .png or .pdf")
    if not plot and (getattr(args, "points", None) or getattr(args, "links", None)):
        raise SceneError("--points and --links choose what --plot draws: give --plot FILE "
                         "as well", key="--points" if getattr(args, "points", None)
                         else "--links")
    if getattr(args, "error_bound", False) and not args.csv:
        raise SceneError("--error-bound adds a column to the CSV: give --csv FILE as well",
                         key="--error-bound")
    wanted = [(path, option) for path, option in ((args.csv, "--csv"), (plot, "--plot"))
              if path]
    targets = check_outputs(wanted, protect=[args.scene])
    scene = load_scene(args.scene)
    angles = _requested_angles(args)
    if args.csv:
        need = _csv_bytes(scene, len(angles), getattr(args, "error_bound", False))
        if need > MAX_CSV_BYTES:
            raise SceneError(f"a CSV of {len(angles)} crank angles would need about "
                             f"{need / 2 ** 30:.1f} GiB of memory (at most "
                             f"{MAX_CSV_BYTES / 2 ** 30:g} GiB): ask for fewer --steps, or "
                             "--summary alone, which needs little memory at any count",
                             key="--csv")
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
        outputs.append((res.to_csv(getattr(args, "error_bound", False)), False))
    if plot:
        from .plots import plot_bytes
        outputs.append((plot_bytes(res, plot, points=_names(args, "points"),
                                   links=_names(args, "links")), True))
    write_outputs(targets, outputs)
    if want_summary:
        print(summary_of(res).text())
    else:
        print(f"{len(res)} of {res.requested} crank angles evaluated"
              + (f"; {_limits_text(res.domain)}" if res.domain.limits else ""))
    return 0


#: the largest crank angle (deg) a sweep's --from/--to may name
MAX_ANGLE_DEG = 1e6
#: the most memory a CSV may need (the arrays, their table and its text)
MAX_CSV_BYTES = 2 * 2 ** 30


def _csv_bytes(scene, n, error_bound=False) -> int:
    """About what a CSV of ``n`` rows needs: each of its columns as an array, in the table
    that is written and as text (8 + 8 + 18 bytes a number); with ``--error-bound``, the
    bounds of every quantity as arrays too."""
    cols = (1 + 6 * len(scene.point_names) + 2 * len(scene.links) + 4 * len(scene.sliders)
            + len(scene.pins) + 1 + len(scene.links))
    if error_bound:
        cols += 3 * len(scene.point_names) + 2 * len(scene.links) + 3 * len(scene.sliders) + 1
    return n * cols * 34


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
    """``polygon-method linkage SCENE``: print the linkage's properties."""
    from .linkage import analyse
    from .scene import load_scene

    print(analyse(load_scene(args.scene)).text())
    return 0


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
    s.add_argument("answers", nargs="*",
                   help="TOML files with an [answers] table (several, or a directory of "
                        "them: a whole class)")
    s.add_argument("--json", action="store_true")
    s.add_argument("--gradebook", help="FILE.csv or FILE.md: the class's gradebook")
    s.set_defaults(func=_cmd_check)

    s = sub.add_parser("draw", help="true-to-scale SVG/PNG/PDF diagrams")
    s.add_argument("scene")
    s.add_argument("-o", "--output", required=True, help="FILE.svg, .png or .pdf")
    s.add_argument("--diagram", choices=("configuration", "velocity", "acceleration", "all",
                                         "centres"), default="all")
    s.add_argument("--scale", action="append", default=[],
                   help='e.g. "1 cm = 0.1 m/s" (may be repeated: space, velocity, '
                        'acceleration)')
    s.add_argument("--centre-labels", choices=("I13", "13"), default="I13",
                   help="how the centres of --diagram centres are labelled")
    s.set_defaults(func=_cmd_draw)

    s = sub.add_parser("sweep", help="the whole crank cycle")
    s.add_argument("scene")
    s.add_argument("--steps", type=int, help="N crank angles over a turn (default 360)")
    s.add_argument("--from", dest="start", type=float, help="first crank angle (deg)")
    s.add_argument("--to", dest="stop", type=float, help="last crank angle (deg)")
    s.add_argument("--step", type=float, help="crank angle step (deg)")
    s.add_argument("--csv", help="FILE.csv: one row per crank angle")
    s.add_argument("--error-bound", action="store_true",
                   help="add to the CSV a column err_max: the largest estimated relative "
                        "error of any quantity at that angle")
    s.add_argument("--plot", help="FILE.svg, .png or .pdf")
    s.add_argument("--points", help="points to plot, e.g. C,E (default: all moving points)")
    s.add_argument("--links", help="links to plot, e.g. BC,CD (default: all moving links)")
    s.add_argument("--summary", action="store_true",
                   help="maxima and minima with their crank angles")
    s.set_defaults(func=_cmd_sweep)

    s = sub.add_parser("linkage", help="Grashof, toggle positions, transmission angle")
    s.add_argument("scene")
    s.set_defaults(func=_cmd_linkage)

    s = sub.add_parser("centres", help="instantaneous centres (Kennedy's theorem) and the "
                       "velocities they give")
    s.add_argument("scene")
    s.add_argument("--centre-labels", choices=("I13", "13"), default="I13",
                   help="label the centres I13 (default) or 13, as the course writes them")
    s.set_defaults(func=_cmd_centres)
    return p


def main(argv=None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    try:
        code = args.func(args)
        sys.stdout.flush()  # a full disk on standard output is one line too
        return code
    except PolygonMethodError as exc:
        print(f"polygon-method {args.command}: {exc.one_line()}", file=sys.stderr)
        return 2
    except OSError as exc:  # the system refused a read or a write (not a bug of ours)
        where = f"{printable(str(exc.filename))}: " if exc.filename else ""
        _quiet_stdout()
        print(f"polygon-method {args.command}: {where}{exc.strerror or exc}", file=sys.stderr)
        return 2
    except MemoryError:
        print(f"polygon-method {args.command}: not enough memory for this request (ask for "
              "fewer crank angles)", file=sys.stderr)
        return 2
    except KeyboardInterrupt:
        return 130
    except BrokenPipeError:
        return 0
    except Exception as exc:  # a bug: still one line, never a traceback
        print(f"polygon-method {args.command}: internal error ({type(exc).__name__}: {exc}); "
              "please report it with the scene file", file=sys.stderr)
        return 3


def _quiet_stdout():
    """After standard output failed, drop what is still buffered (so that the exit does not
    fail again)."""
    try:
        sys.stdout = open(os.devnull, "w")
    except OSError:
        pass


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
