"""The ``polygon-method`` command: ``main(argv) -> int``.

Exit codes: 0 success; 1 ``check`` found a wrong answer; 2 bad input (one line on stderr,
never a traceback); 3 an internal error (a bug: please report it).
Only this package reads and writes files and prints, and it writes them whole or not at
all (:mod:`.files`). The commands live in :mod:`.commands` (one scene: solve, steps, draw,
page, sweep, ...) and :mod:`.classroom` (check, variants).
"""

from __future__ import annotations

import argparse
import contextlib
import os
import re
import sys
import unicodedata
import warnings

from ..common.errors import PolygonMethodError, printable
from .classroom import _cmd_check, _cmd_variants
from .commands import (
    DEFAULT_FRAMES,
    _cmd_centres,
    _cmd_draw,
    _cmd_linkage,
    _cmd_page,
    _cmd_plan,
    _cmd_solve,
    _cmd_steps,
    _cmd_sweep,
)
from .asked import ANSWERS_HELP, ASKED_HELP
from .files import check_outputs, write_output, write_outputs

__all__ = ["main", "build_parser", "write_output", "write_outputs", "check_outputs"]


class _Once(argparse.Action):
    """An option of one value given twice with two values (``--steps 12 --steps 24``,
    ``-o a.svg -o b.svg``) is refused: which one was meant? (argparse keeps the last.)"""

    def __call__(self, parser, namespace, values, option_string=None):
        seen = namespace.__dict__.setdefault("_given", {})
        if self.dest in seen and seen[self.dest] != values:
            parser.error(
                f"{'/'.join(self.option_strings)} given twice ({seen[self.dest]} and {values}): "
                "give it once"
            )
        seen[self.dest] = values
        setattr(namespace, self.dest, values)


class _Parser(argparse.ArgumentParser):
    def error(self, message):  # one line, exit 2
        self.exit(2, f"{self.prog}: error: {message}\n")

    def add_argument(self, *args, **kwargs):
        if args and args[0].startswith("-") and kwargs.get("action", "store") == "store":
            kwargs["action"] = _Once
        return super().add_argument(*args, **kwargs)


def _add_solve(sub) -> None:
    """The sub-command solve's arguments: the scene, --json."""
    s = sub.add_parser("solve", help="solve a scene at its stated instant")
    s.add_argument("scene")
    s.add_argument("--json", action="store_true", help="machine-readable output (SI)")
    s.add_argument("--answers", help=ASKED_HELP)
    s.set_defaults(func=_cmd_solve)


def _add_plan(sub) -> None:
    """The sub-command plan's argument: the scene."""
    s = sub.add_parser("plan", help="print the construction plan")
    s.add_argument("scene")
    s.set_defaults(func=_cmd_plan)


def _add_steps(sub) -> None:
    """The sub-command steps' arguments: the scene, --format."""
    s = sub.add_parser("steps", help="the hand solution, step by step")
    s.add_argument("scene")
    s.add_argument("--format", choices=("text", "markdown"), default="text")
    s.add_argument("--answers", help=ASKED_HELP)
    s.set_defaults(func=_cmd_steps)


def _add_check(sub) -> None:
    """The sub-command check's arguments: the scene, the answer files, the gradebook, the
    variants and the tolerances."""
    s = sub.add_parser("check", help="check answers against the solution")
    s.add_argument("scene")
    s.add_argument(
        "answers",
        nargs="*",
        help="TOML files with an [answers] table (several, or a directory of them: a whole class)",
    )
    s.add_argument("--json", action="store_true")
    s.add_argument("--gradebook", help="FILE.csv or FILE.md: the class's gradebook")
    s.add_argument(
        "--variants",
        help="DIR: the variant scenes `variants -o DIR` wrote; each "
        'answer file is graded against the variant it names (variant = "07")',
    )
    s.add_argument(
        "--tolerance",
        action="append",
        metavar="TOL",
        help="the tolerance for every answer file: a per cent (5%%) or a value with "
        "its unit for the answers in that unit (0.01 m/s; 1 mm for the lengths, a "
        "centre's position, a stroke; 1 deg for the angles, a link's direction); may be "
        "given again for another unit. Without it: the answer file's own, else what a "
        "careful hand drawing allows (a scene's own tolerance is the book's, "
        "for the scene's answers)",
    )
    s.set_defaults(func=_cmd_check)


def _add_variants(sub) -> None:
    """The sub-command variants' arguments: the scene, how many, the seed, the output folder,
    --pdf."""
    s = sub.add_parser(
        "variants", help="a variant of the scene per student, the answer key and the problem sheet"
    )
    s.add_argument("scene")
    s.add_argument("--count", type=int, default=40, help="how many variants (default 40)")
    s.add_argument(
        "--seed",
        type=int,
        default=0,
        help="the random seed (the same seed gives the same variants)",
    )
    s.add_argument(
        "-o",
        "--output",
        required=True,
        help="DIR: the variants, answer key and problem sheet are written into it",
    )
    s.add_argument("--pdf", action="store_true", help="the problem sheet as PDF too")
    s.set_defaults(func=_cmd_variants)


def _add_draw(sub) -> None:
    """The sub-command draw's arguments: the scene, the output file, which diagram, the scales,
    the paper, the centres' labels, --animate and its frames."""
    s = sub.add_parser("draw", help="true-to-scale SVG/PNG/PDF diagrams")
    s.add_argument("scene")
    s.add_argument("-o", "--output", required=True, help="FILE.svg, .png or .pdf")
    s.add_argument(
        "--diagram",
        choices=("configuration", "velocity", "acceleration", "all", "centres", "forces", "cycle"),
        default="all",
    )
    s.add_argument(
        "--forces",
        action="store_true",
        help="the free-body diagrams and force polygons (the same as --diagram "
        "forces; the scene gives [masses] or [gravity])",
    )
    s.add_argument(
        "--scale",
        action="append",
        default=[],
        help='e.g. "1 cm = 0.1 m/s" (may be repeated: space, velocity, '
        'acceleration, force: "1 cm = 500 N")',
    )
    s.add_argument(
        "--paper",
        default="A4",
        help="A4 (default), A3 or letter: the sheet is drawn on it, portrait or "
        "landscape, on more pages where the diagrams do not fit one at "
        "their scales",
    )
    s.add_argument(
        "--centre-labels",
        choices=("I13", "13"),
        help="how the centres of --diagram centres are labelled (default I13)",
    )
    s.add_argument(
        "--animate",
        action="store_true",
        help="the three diagrams over the crank's cycle (-o FILE.gif, .html or .svg)",
    )
    s.add_argument("--answers", help=ASKED_HELP)
    s.add_argument(
        "--frames",
        type=int,
        help=f"frames of --animate over the cycle (default {DEFAULT_FRAMES}, or as many more "
        "as follow a wheel turning fast)",
    )
    s.set_defaults(func=_cmd_draw)


def _add_page(sub) -> None:
    """The sub-command page's arguments: the scene, the output file, the answers to check, the
    frames."""
    s = sub.add_parser(
        "page",
        help="one self-contained HTML page: the diagrams moving with "
        "the crank, values, plots, the steps and the check",
    )
    s.add_argument("scene")
    s.add_argument("-o", "--output", required=True, help="FILE.html")
    s.add_argument("--answers", help=ANSWERS_HELP)
    s.add_argument(
        "--frames",
        type=int,
        help=f"frames over the cycle (default {DEFAULT_FRAMES}, or as many more as "
        "follow a wheel turning fast)",
    )
    s.set_defaults(func=_cmd_page)


def _add_sweep(sub) -> None:
    """The sub-command sweep's arguments: the scene, the crank angles, the CSV, the plot and
    its points and links, --summary."""
    s = sub.add_parser("sweep", help="the whole crank cycle")
    s.add_argument("scene")
    s.add_argument(
        "--steps",
        type=int,
        help="N crank angles a turn, over the motion's "
        "period: a turn, two for a four-stroke engine, several where a wheel comes "
        "back only after several (default 360)",
    )
    s.add_argument("--from", dest="start", type=float, help="first crank angle (deg)")
    s.add_argument("--to", dest="stop", type=float, help="last crank angle (deg)")
    s.add_argument("--step", type=float, help="crank angle step (deg)")
    s.add_argument("--csv", help="FILE.csv: one row per crank angle (- : on standard output)")
    s.add_argument(
        "--error-bound",
        action="store_true",
        help="add to the CSV a column err_max: the largest estimated relative "
        "error of any quantity at that angle",
    )
    s.add_argument("--plot", help="FILE.svg, .png or .pdf")
    s.add_argument("--points", help="points to plot, e.g. C,E (default: all moving points)")
    s.add_argument("--links", help="links to plot, e.g. BC,CD (default: all moving links)")
    s.add_argument(
        "--summary", action="store_true", help="maxima and minima with their crank angles"
    )
    s.add_argument("--answers", help=ASKED_HELP)
    s.set_defaults(func=_cmd_sweep)


def _add_linkage(sub) -> None:
    """The sub-command linkage's argument: the scene."""
    s = sub.add_parser("linkage", help="Grashof, toggle positions, transmission angle")
    s.add_argument("scene")
    s.set_defaults(func=_cmd_linkage)


def _add_centres(sub) -> None:
    """The sub-command centres' arguments: the scene, the centres' labels."""
    s = sub.add_parser(
        "centres", help="instantaneous centres (Kennedy's theorem) and the velocities they give"
    )
    s.add_argument("scene")
    s.add_argument(
        "--centre-labels",
        choices=("I13", "13"),
        default="I13",
        help="label the centres I13 (default) or 13, as the course writes them",
    )
    s.set_defaults(func=_cmd_centres)


def build_parser() -> argparse.ArgumentParser:
    """The command line's parser: one sub-command per job (solve, steps, draw, page, ...)."""
    p = _Parser(
        prog="polygon-method",
        description="Planar mechanisms by the relative-velocity (polygon) method.",
    )
    from .. import __version__

    p.add_argument("--version", action="version", version=f"polygon-method {__version__}")
    sub = p.add_subparsers(dest="command", metavar="COMMAND", parser_class=_Parser)
    sub.required = True
    for add in (
        _add_solve,
        _add_plan,
        _add_steps,
        _add_check,
        _add_variants,
        _add_draw,
        _add_page,
        _add_sweep,
        _add_linkage,
        _add_centres,
    ):
        add(sub)
    return p


#: a negative value argparse takes for an option: an exponent ("-1e3", "-2.5E-4"), a per cent
#: ("-5%"), an infinity ("-inf"); its own rule knows "-30" and "-0.5" only
_NEGATIVE_EXPONENT = re.compile(r"^-(\d|\.\d|inf|nan)", re.IGNORECASE)


def _negative_values(argv: list) -> list:
    """``--from -1e3`` as ``--from=-1e3``: a negative number in exponent form (or a negative
    per cent, an infinity) after a long option is that option's value, as "-30" is, and
    is then refused in that option's words."""
    out = []
    for tok in argv:
        if (
            out
            and _NEGATIVE_EXPONENT.match(tok)
            and out[-1].startswith("--")
            and "=" not in out[-1]
        ):
            out[-1] = f"{out[-1]}={tok}"
        else:
            out.append(tok)
    return out


def main(argv=None) -> int:
    """Run the command line on ``argv`` (``sys.argv[1:]`` when None); the exit code: 0 done, 2 a bad
    scene or argument (one line on stderr), 3 an internal error."""
    parser = build_parser()
    args = parser.parse_args(_negative_values(list(sys.argv[1:] if argv is None else argv)))
    vars(args).pop("_given", None)  # what _Once kept to see an option given twice
    for dest, value in vars(args).items():  # an empty name is never "not given"
        if isinstance(value, str) and dest != "command" and not value.strip():
            flag = {"output": "-o", "scene": "SCENE"}.get(dest, "--" + dest.replace("_", "-"))
            print(f"polygon-method {args.command}: {flag}: an empty value", file=sys.stderr)
            return 2
    try:
        with _glyphs(args.command):
            code = _run(args)
        sys.stdout.flush()  # a full disk on standard output is one line too
        return code
    except PolygonMethodError as exc:
        if exc.step and getattr(args, "scene", None):  # a step of the scene's mechanism
            exc.located(args.scene)
        print(f"polygon-method {args.command}: {exc.one_line()}", file=sys.stderr)
        return 2
    except BrokenPipeError:  # the reader went away (``... | head``): nothing to say
        _quiet_stdout()
        return 0
    except OSError as exc:  # the system refused a read or a write (not a bug of ours)
        where = f"{printable(str(exc.filename))}: " if exc.filename else ""
        _quiet_stdout()
        print(f"polygon-method {args.command}: {where}{exc.strerror or exc}", file=sys.stderr)
        return 2
    except MemoryError:
        print(
            f"polygon-method {args.command}: not enough memory for this request (ask for "
            "fewer crank angles)",
            file=sys.stderr,
        )
        return 2
    except KeyboardInterrupt:
        return 130
    except Exception as exc:  # a bug: still one line, never a traceback
        print(
            f"polygon-method {args.command}: internal error ({type(exc).__name__}: {exc}); "
            "please report it with the scene file",
            file=sys.stderr,
        )
        return 3


def _run(args) -> int:
    """The command on its scene; where the scene is refused as a mechanism's, the commands
    of a turning-moment diagram stated on its own, if it is one (so that a mechanism's scene
    pays nothing for them)."""
    try:
        return args.func(args)
    except PolygonMethodError:
        from .energy import route

        other = route(args)
        if other is None:
            raise
    return other(args)


#: matplotlib's warning of a character its font cannot draw (one per character and figure)
_GLYPH = re.compile(r"Glyph \d+ \((.*)\) missing from font\(s\) (.*)\.$")


@contextlib.contextmanager
def _glyphs(command):
    """Characters the plot font lacks (a title in another script, an emoji): said once, in
    one line, instead of a warning per character and per figure (they are drawn as the
    font's empty box). Other warnings pass as they come, under the filters in force: none
    is recorded (a warning raised at each of millions of points, recorded, once held
    gigabytes)."""
    missing, fonts = {}, set()
    with warnings.catch_warnings():
        warnings.filterwarnings("always", message=r"Glyph \d+ \(")
        shown = warnings.showwarning

        def show(message, category, filename, lineno, file=None, line=None):
            m = _GLYPH.match(str(message))
            if m:
                missing.setdefault(_glyph_char(m.group(1)), None)
                fonts.add(m.group(2))
            else:
                shown(message, category, filename, lineno, file, line)

        warnings.showwarning = show
        try:
            yield
        finally:
            if missing:
                print(
                    f"polygon-method {command}: note: the plot font "
                    f"({', '.join(sorted(fonts))}) has no glyph for "
                    f"{' '.join(missing)}: drawn as an empty box (the text files keep "
                    "them)",
                    file=sys.stderr,
                )


def _glyph_char(name: str) -> str:
    """The character of matplotlib's ``\\N{CJK UNIFIED IDEOGRAPH-6A5F}`` (or its name)."""
    m = re.match(r"^\\N\{(.*)\}$", name)
    if m:
        try:
            return unicodedata.lookup(m.group(1))
        except KeyError:
            return m.group(1)
    return name


def _quiet_stdout():
    """After standard output failed, drop what is still buffered (so that the exit does not
    fail again)."""
    try:
        sys.stdout = open(os.devnull, "w")
    except OSError:
        pass


if __name__ == "__main__":  # pragma: no cover
    sys.exit(main())
