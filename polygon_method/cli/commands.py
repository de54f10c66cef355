"""The commands that solve and show one scene: solve, plan, centres, steps, draw (and its
animations), page, sweep, linkage. Each reads its files, prints and writes here only."""

from __future__ import annotations

import json
import math
import sys
from dataclasses import replace
from pathlib import Path

from ..common.errors import PolygonMethodError, SceneError
from ..common.tolerances import SAME
from .energy import check_cylinders, draw_engine_cycle, engine_cycle
from .asked import asked_json, asked_lines, asked_verdicts, no_answers, steps_answers
from .files import check_outputs, is_stdout, write_outputs


def _cmd_solve(args) -> int:
    from ..scene import load_scene
    from ..motion.solution import solve
    from .asked import asked_scene

    sol = solve(asked_scene(args, load_scene(args.scene, variants=False, answers=False)))
    cycle = engine_cycle(sol)  # an engine asked for its cycle: [indicator] or [flywheel]
    asked = asked_verdicts(sol, getattr(args, "answers", None) or args.scene)  # "?" keys
    if args.json:
        d = sol.to_dict()
        from ..linkage.engine_values import engine_dict

        engine = engine_dict(sol)  # an engine's efforts, each cylinder's
        if engine is not None:
            d["forces"]["engine"] = engine
        if cycle is not None:
            d["turning_moment"] = cycle.as_dict()
        d.update(asked_json(asked))  # the "?" keys' answers
        print(json.dumps(d, indent=2, allow_nan=False))
    else:
        from ..text.report import solution_text

        print(solution_text(sol))
        if cycle is not None:
            print("\n" + "\n".join(cycle.lines(sol.scene)))
        if asked:
            print("\n".join(asked_lines(asked)))
    return 0


def _cmd_plan(args) -> int:
    from ..solver.compiler import compile_plan
    from ..scene import load_scene

    print(compile_plan(load_scene(args.scene, variants=False, answers=False)))
    return 0


def _cmd_centres(args) -> int:
    """``polygon-method centres SCENE``: the instantaneous centre method."""
    from ..solver.centres import locate
    from ..text.centres import centres_text
    from ..scene import load_scene
    from ..motion.solution import solve

    prefix = "" if getattr(args, "centre_labels", "I13") == "13" else "I"
    print(
        centres_text(locate(solve(load_scene(args.scene, variants=False, answers=False)), prefix))
    )
    return 0


def _cmd_steps(args) -> int:
    from ..scene import load_scene
    from ..motion.solution import solve
    from ..text.steptable import steps_text
    from .asked import asked_scene

    sol = solve(asked_scene(args, load_scene(args.scene, variants=False, answers=False)))
    check_cylinders(sol.scene, sol)
    asked = asked_verdicts(sol, getattr(args, "answers", None) or args.scene)  # "?" keys
    print(steps_answers(steps_text(sol, fmt=args.format), asked, args.format))
    return 0


def _cmd_draw(args) -> int:
    """``polygon-method draw SCENE -o FILE.svg [--diagram ...] [--scale "1 cm = 0.1 m/s"]``:
    written whole or not at all, and not at all when the scene cannot be solved."""
    from ..draw import FORMATS, display_unit, page_files, paper_name, parse_scales, render_pages
    from ..scene import load_scene
    from ..motion.solution import solve

    out = Path(args.output)
    fmt = out.suffix.lower().lstrip(".")
    if getattr(args, "forces", False):  # the same as --diagram forces
        _forces_flag(args)
    if getattr(args, "animate", False):
        if fmt not in ("gif", "html", "svg"):
            raise PolygonMethodError(
                f"cannot animate to {out}: the file name must end in .gif, .html or .svg", key="-o"
            )
        if args.diagram not in (None, "all") or args.scale or getattr(args, "centre_labels", None):
            raise PolygonMethodError(
                "--animate draws the three diagrams at the scales of "
                "the step table: leave out --diagram, --scale and "
                "--centre-labels",
                key="--animate",
            )
        no_answers(args, "--animate draws the diagrams alone")
        return _cmd_animate(args, out, fmt)
    if getattr(args, "frames", None) is not None:  # never silently ignored
        raise PolygonMethodError(
            "--frames counts the frames of --animate: give --animate as well", key="--frames"
        )
    if getattr(args, "centre_labels", None) and getattr(args, "diagram", None) != "centres":
        raise PolygonMethodError(
            "--centre-labels labels the centres of --diagram centres: give that as well",
            key="--centre-labels",
        )
    if fmt not in FORMATS:
        raise PolygonMethodError(
            f"cannot draw to {out}: the file name must end in .svg, .png or .pdf", key="-o"
        )
    if args.diagram == "cycle":  # an engine's turning-moment diagram and energy curve
        return draw_engine_cycle(args, out, fmt)
    scales = _drawn_scales(args, parse_scales(getattr(args, "scale", None)))
    paper = paper_name(getattr(args, "paper", None) or "A4")
    targets = check_outputs([(out, "-o")], protect=[args.scene, getattr(args, "answers", None)])
    from .asked import asked_scene

    sol = solve(asked_scene(args, load_scene(args.scene, variants=False, answers=False)))
    diagram = getattr(args, "diagram", None) or "all"
    prefix = "" if getattr(args, "centre_labels", "I13") == "13" else "I"
    try:  # a diagram too large for the paper is this scene's: the line names it
        datas, used, warnings, pages = render_pages(sol, fmt, diagram, scales, prefix, paper)
    except PolygonMethodError as exc:
        raise exc.located(args.scene)
    for w in list(sol.warnings) + warnings:
        print(f"warning: {w}", file=sys.stderr)
    files = [out] if fmt == "pdf" else page_files(out, len(pages))
    if len(files) > 1:  # a page a file: out-1.svg, out-2.svg, ...
        if targets[0].special:
            targets[0].probe()
            raise PolygonMethodError(
                f"the sheet has {len(pages)} pages on {paper} and {out} "
                f"is not a regular file: give a file name (one .{fmt} "
                f"file a page: NAME-1.{fmt}, NAME-2.{fmt}, ...) or write "
                "a .pdf",
                key="-o",
            )
        targets = check_outputs([(f, "-o") for f in files], protect=[args.scene])
    write_outputs(targets, [(d, fmt != "svg") for d in datas])
    scales_text = "; ".join(f"{name} {display_unit(s.text)}" for name, s in used.items())
    _print_drawn(out, fmt, files, pages, paper, scales_text)
    return 0


def _forces_flag(args) -> None:
    """``--forces``: the same as ``--diagram forces``, refused beside another diagram or
    ``--animate``."""
    if args.diagram not in (None, "all", "forces"):
        raise PolygonMethodError(
            f"--forces draws the forces sheet: leave out --diagram {args.diagram}",
            key="--forces",
        )
    if getattr(args, "animate", False):
        raise PolygonMethodError(
            "--forces draws a sheet on paper, not an animation (the "
            "page shows the inertia forces moving): leave out "
            "--animate",
            key="--forces",
        )
    args.diagram = "forces"


def _drawn_scales(args, scales) -> dict:
    """The scales ``--scale`` gives, each of a kind the asked diagram draws (one it does not
    draw is refused, never silently ignored)."""
    drawn = {
        "all": ("length", "velocity", "acceleration"),
        "centres": ("length",),
        "configuration": ("length",),
        "forces": ("length", "force"),
    }.get(args.diagram or "all", (args.diagram,))
    for kind, s in scales.items():
        if kind not in drawn:
            raise PolygonMethodError(
                f"{s.text} is {'an' if kind[0] == 'a' else 'a'} {kind} "
                f"scale, and --diagram {args.diagram} draws no {kind} "
                "diagram: leave it out",
                key="--scale",
            )
    return scales


def _print_drawn(out, fmt, files, pages, paper, scales_text) -> None:
    """What ``draw`` wrote: the file and its scales; for a sheet of several pages, each
    page's file (or the PDF's page) and its panels."""
    if len(pages) == 1:
        print(f"{out}: {pages[0].text}; {scales_text}")
        return
    print(
        f"{out if fmt == 'pdf' else ', '.join(map(str, files))}: {len(pages)} pages on "
        f"{paper} (the diagrams do not fit one at their scales); {scales_text}"
    )
    for f, p in zip(files * len(pages) if fmt == "pdf" else files, pages):
        print(
            f"  {f}: page {p.number}, {p.text}: "
            + ", ".join(_panel_name(name) for name in p.panels)
        )


def _panel_name(name: str) -> str:
    if name.startswith("free-body-"):
        return f"free body {name[10:]}"
    if name.startswith("force-polygon-"):
        return f"force polygon of step {name[14:]}"
    return _PANEL_NAMES.get(name, name)


_PANEL_NAMES = {
    "configuration": "configuration diagram",
    "velocity": "velocity polygon",
    "acceleration": "acceleration polygon",
    "centres": "centres diagram",
    "circle": "circle diagram",
}


def _frames(args, scene, fmt=None):
    """The scene's frames (``--frames``, or the default: :func:`~..page.frames.asked`)."""
    from ..page.frames import asked

    return asked(scene, args.frames, fmt)


def _cmd_page(args) -> int:
    """``polygon-method page SCENE -o page.html [--answers FILE] [--frames N]``: the page a
    student opens in a browser, written whole or not at all."""
    from ..check import check_answers, choose_tolerance
    from ..page import page_html
    from ..scene import load_answers, load_scene

    out = Path(args.output)
    if out.suffix.lower() not in (".html", ".htm"):
        raise PolygonMethodError(
            f"cannot write the page to {out}: the file name must end in .html", key="-o"
        )
    targets = check_outputs([(out, "-o")], protect=[args.scene, args.answers])
    scene = load_scene(args.scene)
    if args.answers:
        tolerance, answers, named = load_answers(args.answers, scene, with_variant=True)
        _own_variant(named, scene, args.answers)
        # as `check` grades: the file's own tolerance, else the default (the scene's is
        # the book's, for its own answers)
        tolerance = choose_tolerance(None, tolerance, scene.tolerance, False)[0]
        scene = replace(scene, answers=tuple(answers))  # what it asks: its keys' marks, steps
    else:
        tolerance, answers = scene.tolerance, scene.answers
    fr = _frames(args, scene)
    title = f"answers from {Path(args.answers).name if args.answers else 'the scene'}"
    try:
        verdicts = check_answers(fr.sol, answers, tolerance) if answers else None
    except PolygonMethodError as exc:
        raise exc.located(args.answers or args.scene)
    html = page_html(fr, verdicts=verdicts, answers_title=title)
    for w in fr.sol.warnings:
        print(f"warning: {w}", file=sys.stderr)
    write_outputs(targets, [(html, False)])
    from ..polygons.scales import display_unit

    turns = fr.res.domain.turns  # a gear train's period, or an engine's cycle
    cycle = (
        (
            "over a full turn"
            if fr.cycle_degrees == 360
            else f"over {turns} turns (the motion's period)"
            if turns > 1
            else f"over the whole cycle ({fr.cycle_degrees:g} deg)"
        )
        if fr.full_turn
        else f"over {fr.sol.plan.steps[0].travel} ({fr.limits_text})"
        if not fr.sol.plan.steps[0].periodic
        else f"between the limit positions ({fr.limits_text})"
    )
    print(
        f"{out}: {len(fr)} frames {cycle}{fr.said}; "
        + "; ".join(display_unit(s.text) for s in fr.scales)
        + f"; {len(html.encode()) / 1024:.0f} KiB"
    )
    return 0


def _own_variant(named, scene, file):
    """An answer file that names a variant is checked against that variant only (as
    ``check`` does): never silently against the base problem or another variant."""
    from .classroom import _VariantBook

    if named is None:
        return
    own = scene.variant
    if own is None or not (_VariantBook._names(own.id) & _VariantBook._names(named)):
        from ..common.errors import printable

        raise SceneError(
            f"names variant '{printable(named)}', and this scene is "
            + (f"variant '{printable(own.id)}'" if own else "not a variant")
            + ": give that variant's own scene (the file `variants -o DIR` wrote)",
            file=file,
            key="variant",
        )


def _cmd_animate(args, out, fmt) -> int:
    """``draw SCENE --animate -o cycle.gif`` (.gif, .html or .svg)."""
    from ..page import animation
    from ..scene import load_scene

    from ..page import check_frames

    if args.frames is not None:
        check_frames(args.frames, fmt)  # before anything is computed
    targets = check_outputs([(out, "-o")], protect=[args.scene])
    fr = _frames(args, load_scene(args.scene, variants=False, answers=False), fmt)
    data = animation(fr, fmt)
    write_outputs(targets, [(data, isinstance(data, bytes))])
    scales = (
        "; ".join(s.text for s in fr.scales)
        if fmt == "svg"
        else "each polygon at its own round scale per frame, written on each picture"
    )
    for note in fr.aliased("the pictures"):  # as the page says it
        print(f"warning: {note}", file=sys.stderr)
    print(f"{out}: {len(fr)} frames{fr.said}; {scales}")
    return 0


def _requested_angles(args, scene=None):
    """Crank angles (rad) from ``--steps N`` (over the scene's cycle: a turn, two for a
    four-stroke engine) or ``--from A --to B --step S`` (deg); for a block driver, its
    places (m) from ``--steps N`` (over its travel, both ends) or ``--from A --to B --step
    S`` (the scene's length unit)."""
    import numpy as np

    ranged = any(v is not None for v in (args.start, args.stop, args.step))
    if args.steps is not None and ranged:
        raise SceneError("give either --steps N or --from A --to B --step S, not both")
    if scene is not None and not _driver(scene).periodic:  # a block driven along its guide
        return _requested_places(args, scene, ranged)
    if ranged:
        if args.start is None or args.stop is None or args.step is None:
            raise SceneError("--from, --to and --step go together (degrees)")
        a, b, s = args.start, args.stop, args.step
        if not all(math.isfinite(v) for v in (a, b, s)):
            raise SceneError("--from, --to and --step must be finite numbers")
        if max(abs(a), abs(b)) > MAX_ANGLE_DEG:
            raise SceneError(
                f"--from and --to are crank angles in degrees, within "
                f"+-{MAX_ANGLE_DEG:g} (got {a:g} and {b:g})"
            )
        count = _range_count(a, b, s, "deg", "crank angles")
        return np.radians(a + s * np.arange(count))
    n = 360 if args.steps is None else args.steps
    if n < 1:
        raise SceneError(f"--steps must be at least 1, got {n}")
    if n > 100_000_000:
        raise SceneError(f"--steps {n} is too many (at most 10^8)")
    turns = _period_turns(scene) if scene is not None else 1  # N a turn, over the period
    return np.linspace(0.0, 2.0 * math.pi * turns, n * turns, endpoint=False)


def _period_turns(scene) -> int:
    """How many turns of the crank the motion takes to repeat: a four-stroke engine's gas
    force two, a wheel turning a fraction of a turn more per turn of the crank several;
    else 1."""
    turns = max(1, round(scene.cycle / (2.0 * math.pi)))
    if getattr(scene, "rolling", ()):
        from ..solver.tracking import Sweeper

        turns = max(turns, Sweeper(scene).domain.turns)
    return turns


def _range_count(a, b, s, unit, what) -> int:
    """How many values ``--from a --to b --step s`` asks for (both ends, where the step
    lands on the last), refused in one short line where the step leads nowhere or the
    count is past 10^8 (a count past any float, ``(b - a) / s`` infinite, too).

    >>> _range_count(0.0, 10.0, 2.5, "deg", "crank angles")
    5
    """
    if s == 0 or (b - a) * s < 0:
        raise SceneError(f"--step {s:g} does not lead from {a:g} to {b:g} {unit}")
    ratio = (b - a) / s  # float arithmetic: inf past the largest float, never an error
    if not ratio < 100_000_000:
        many = f"{ratio + 1:.3g}" if math.isfinite(ratio) else "more than 1e308"
        raise SceneError(
            f"--from {a:g} --to {b:g} --step {s:g} asks for {many} {what}: too many (at most 10^8)"
        )
    return int(math.floor(ratio + SAME)) + 1


def _requested_places(args, scene, ranged):
    """A driving block's places along its guide (m) for a sweep."""
    import numpy as np
    from ..motion.sweeps import stroke_places

    uname, u = scene.units, scene.length_unit
    if ranged:
        if args.start is None or args.stop is None or args.step is None:
            raise SceneError(f"--from, --to and --step go together (the {_what(scene)})")
        a, b, s = args.start, args.stop, args.step
        if not all(math.isfinite(v) for v in (a, b, s)):
            raise SceneError("--from, --to and --step must be finite numbers")
        far = MAX_PLACE_M / u  # the farthest place a scene may state, in its units
        if max(abs(a), abs(b)) > far:
            raise SceneError(
                f"--from and --to are the {_what(scene, unit=False)}, in {uname}, "
                f"within +-{far:g} (got {a:g} and {b:g})"
            )
        count = _range_count(a, b, s, uname, "places")
        return (a + s * np.arange(count)) * u
    n = 361 if args.steps is None else args.steps
    if n < 1:
        raise SceneError(f"--steps must be at least 1, got {n}")
    if n > 100_000_000:
        raise SceneError(f"--steps {n} is too many (at most 10^8)")
    return stroke_places(scene, n)


def _sweep_flags(args):
    """``sweep``'s options that go together checked (a flag never silently ignored): the
    plot's file name, given back."""
    plot = getattr(args, "plot", None)
    if plot and not plot.lower().endswith((".svg", ".png", ".pdf")):
        raise SceneError(f"--plot {plot}: the file must end in .svg, .png or .pdf")
    if not plot and (getattr(args, "points", None) or getattr(args, "links", None)):
        raise SceneError(
            "--points and --links choose what --plot draws: give --plot FILE as well",
            key="--points" if getattr(args, "points", None) else "--links",
        )
    if getattr(args, "error_bound", False) and not args.csv:
        raise SceneError(
            "--error-bound adds a column to the CSV: give --csv FILE as well", key="--error-bound"
        )
    return plot


def _cmd_sweep(args) -> int:
    """``polygon-method sweep SCENE [--steps N | --from A --to B --step S] [--csv FILE]
    [--plot FILE.svg] [--summary]``: print the summary; the CSV and the plot are written by
    ``write_output`` (whole or not at all)."""
    from ..scene import load_scene
    from ..linkage.cycle import sweep_aliased
    from ..linkage.summary import summarize, summary_of
    from ..motion.sweeps import sweep

    plot = _sweep_flags(args)
    to_stdout = bool(args.csv) and is_stdout(args.csv)  # (-, /dev/stdout: the words on stderr)
    wanted = [
        (path, option)
        for path, option in ((None if to_stdout else args.csv, "--csv"), (plot, "--plot"))
        if path
    ]
    targets = check_outputs(wanted, protect=[args.scene, getattr(args, "answers", None)])
    from .asked import asked_scene

    scene = asked_scene(args, load_scene(args.scene, variants=False, answers=False))
    check_cylinders(scene)
    angles = _requested_angles(args, scene)
    if args.csv:
        need = _csv_bytes(scene, len(angles), getattr(args, "error_bound", False))
        if need > MAX_CSV_BYTES:
            raise SceneError(
                f"a CSV of {len(angles)} crank angles would need about "
                f"{need / 2**30:.1f} GiB of memory (at most "
                f"{MAX_CSV_BYTES / 2**30:g} GiB): ask for fewer --steps, or "
                "--summary alone, which needs little memory at any count",
                key="--csv",
            )
    want_summary = args.summary or not (args.csv or plot)
    if not (args.csv or plot):
        print(summarize(scene, angles).text())
        return 0
    res = sweep(scene, angles)
    if not len(res):
        raise PolygonMethodError(
            f"none of the requested {_what(scene)} can be reached "
            "on the scene's branch " + _limits_text(res.domain),
            file=scene.file,
        )
    outputs = []
    if args.csv and not to_stdout:
        outputs.append((res.to_csv(getattr(args, "error_bound", False)), False))
    if plot:
        from ..draw.plots import plot_bytes

        outputs.append(
            (
                plot_bytes(res, plot, points=_names(args, "points"), links=_names(args, "links")),
                True,
            )
        )
    write_outputs(targets, outputs)
    words = sys.stderr if to_stdout else sys.stdout
    if to_stdout:
        sys.stdout.write(res.to_csv(getattr(args, "error_bound", False)))
    if want_summary:
        print(summary_of(res).text(), file=words)
    else:
        print(
            f"{len(res)} of {res.requested} {_what(scene)} evaluated"
            + (f" {_limits_text(res.domain)}" if res.domain.limits else ""),
            file=words,
        )
        for note in sweep_aliased(res, "its values"):  # (the summary says it in its notes)
            print(note, file=words)
    return 0


#: frames of a page or an animation (as :data:`polygon_method.page.DEFAULT_FRAMES`)
DEFAULT_FRAMES = 180
#: the largest crank angle (deg) a sweep's --from/--to may name
MAX_ANGLE_DEG = 1e6
#: the farthest place (m) a driving block's sweep may name (as the farthest a scene states)
MAX_PLACE_M = 1e4
#: the most memory a CSV may need (the arrays, their table and its text)
MAX_CSV_BYTES = 2 * 2**30


def _csv_bytes(scene, n, error_bound=False) -> int:
    """About what a CSV of ``n`` rows needs: each of its columns as an array, in the table
    that is written and as text (8 + 8 + 18 bytes a number); with ``--error-bound``, the
    bounds of every quantity as arrays too."""
    cols = (
        1
        + 6 * len(scene.point_names)
        + 2 * len(scene.links)
        + 4 * len(scene.sliders)
        + len(scene.pins)
        + 1
        + len(scene.links)
    )
    if scene.has_forces:  # the torque with inertia, the shaking force, guides, pin forces
        cols += 4 + len(scene.sliders) + 3 * len(scene.links)
    if error_bound:
        cols += 3 * len(scene.point_names) + 2 * len(scene.links) + 3 * len(scene.sliders) + 1
    return n * cols * 34


def _names(args, what):
    raw = getattr(args, what, None)
    if not raw:
        return None
    names = tuple(x.strip() for x in raw.split(",") if x.strip())
    if not names:  # ",," is not "all of them"
        raise SceneError(
            f"--{what} {raw!r} names no {what[:-1]}: give names such as "
            + ("C,E" if what == "points" else "BC,CD"),
            key=f"--{what}",
        )
    return names


def _driver(scene):
    """The plan's first step, which drives the mechanism (the driver protocol)."""
    from ..solver.compiler import compile_plan

    return compile_plan(scene).steps[0]


def _what(scene, unit: bool = True) -> str:
    """What a sweep's parameter values are, in words, as the driver names its parameter:
    "places of collar C on DC (mm)" (without the unit: "places of collar C on DC")."""
    driver = _driver(scene)
    if driver.periodic:
        return "crank angles"
    name = driver.parameter(scene)[0]  # "place of block C", "place of collar C on DC"
    if name.startswith("place "):
        name = "places " + name[len("place ") :]
    return f"{name} ({scene.units})" if unit else name


def _limits_text(dom) -> str:
    if not dom.limits:
        return ""
    if not dom.periodic:  # a block driver: the ends of its travel, in the scene's units
        return (
            "(its travel ends at s = "
            + " and ".join(f"{lp.theta / dom.unit:.6g}" for lp in dom.limits)
            + ")"
        )
    return "(limit positions at " + " and ".join(f"{lp.degrees:.4f} deg" for lp in dom.limits) + ")"


def _cmd_linkage(args) -> int:
    """``polygon-method linkage SCENE``: print the linkage's properties."""
    from ..linkage import analyse
    from ..scene import load_scene

    print(analyse(load_scene(args.scene, variants=False, answers=False)).text())
    return 0
