"""The commands on a scene that states a turning-moment diagram (or a punching press) and no
mechanism: ``solve`` (``--json``), ``steps``, ``check`` (a class: :mod:`.energy_class`),
``draw``, ``page``, ``variants``, ``sweep`` (``--summary``, ``--csv``, ``--plot``); the
others have nothing to do there and say so in one line. Only a scene the mechanism's reader
refuses comes here: the file is looked at for a
``[turning_moment]`` or ``[press]`` header, and where it has none the reader's refusal
stands. Here too a mechanism's engine's cycle for ``solve`` (:func:`engine_cycle`) and the
refusal of several cylinders' indicator diagrams that do not fit their engine
(:func:`check_cylinders`), and its sheet, ``draw --diagram cycle``
(:func:`draw_engine_cycle`)."""

from __future__ import annotations

import json
import os
import re
import stat
import sys
from pathlib import Path

from ..common.errors import PolygonMethodError, SceneError
from .asked import asked_json, asked_lines, no_answers, steps_answers
from .files import check_outputs, is_stdout, write_outputs

__all__ = ["route"]

_HEADER = re.compile(rb"(?m)^[ \t]*\[[ \t]*(turning_moment|press)[ \t]*\]")
_MOST = 1 << 20


def route(args):
    """The command to run for ``args`` where its scene states a turning-moment diagram,
    else None (the mechanism's commands run as ever)."""
    path = getattr(args, "scene", None)
    if not isinstance(path, str) or not path:
        return None
    try:
        st = os.stat(path)
    except (OSError, ValueError):
        return None
    if not stat.S_ISREG(st.st_mode) or st.st_size > _MOST:
        return None
    try:
        data = Path(path).read_bytes()
    except OSError:
        return None
    if (b"turning_moment" not in data and b"press" not in data) or not _HEADER.search(data):
        return None
    from ..scene.energy import cycle_from_text

    try:
        text = data.decode("utf-8-sig")
    except UnicodeDecodeError:
        return None
    try:
        scene = cycle_from_text(text, file=path)
    except PolygonMethodError as exc:
        raise exc.located(path)
    if scene is None:  # the header was inside a string: a mechanism's scene after all
        return None
    run = _COMMANDS.get(args.command)
    if run is None:
        raise SceneError(
            f"a turning-moment diagram with no mechanism: {args.command} has nothing to "
            "do here (solve, steps, check, draw, page, variants and sweep --summary/--csv/--plot "
            "do)",
            file=path,
            key="[turning_moment]" if scene.diagram is not None else "[press]",
        )
    return lambda a: run(a, scene)


def _solved(scene):
    from ..forces.flywheel_cycle import solve_cycle

    try:
        return solve_cycle(scene)
    except PolygonMethodError as exc:
        raise exc.located(scene.file)


def _shows_all(args, command) -> None:
    """``--answers`` refused where a turning-moment diagram's view shows every answer."""
    if getattr(args, "answers", None):
        raise PolygonMethodError(
            f"a turning-moment diagram's {command} shows every answer: leave out --answers "
            "(check grades it)",
            key="--answers",
        )


def _asked(scene, c) -> tuple:
    """The tool's answers to the questions the scene asks without their answers
    (``dE_max = "?"``): check's verdicts, marked asked; () where none is asked."""
    questions = [a for a in scene.answers if a.asked]
    if not questions:
        return ()
    from ..check.energy import cycle_verdicts

    try:
        return tuple(cycle_verdicts(scene, c, questions, None))
    except PolygonMethodError as exc:
        raise exc.located(scene.file)


def _solve(args, scene) -> int:
    _shows_all(args, "solve")
    c = _solved(scene)
    asked = _asked(scene, c)
    if args.json:
        d = {"title": scene.title, "scene": scene.file, "cycle": c.as_dict()}
        d.update(asked_json(asked))  # the "?" keys' answers
        print(json.dumps(d, indent=2, allow_nan=False))
    else:
        from ..text.energy import cycle_text

        print(cycle_text(scene, c))
        if asked:
            print("\n".join(asked_lines(asked)))
    return 0


def _steps(args, scene) -> int:
    from ..text.energy import cycle_steps

    _shows_all(args, "steps")
    c = _solved(scene)
    text = cycle_steps(scene, c)
    markdown = getattr(args, "format", "text") == "markdown"
    text = steps_answers(text, _asked(scene, c), "text")
    print(f"```\n{text}\n```" if markdown else text)
    return 0


def _check(args, scene) -> int:
    from ..check.energy import cycle_verdicts
    from ..check.verdicts import verdicts_dict, verdicts_text
    from .classroom import _answer_files
    from .energy_class import _percent, check_class, graded

    files = _answer_files(args.answers or [])
    c = _solved(scene)
    if (
        len(files) > 1
        or (args.answers and Path(args.answers[0]).is_dir())
        or getattr(args, "gradebook", None)
    ):
        if not files:
            raise SceneError(
                f"no answer files in {', '.join(args.answers or ['(none)'])}", key="answers"
            )
        return check_class(args, scene, c, files)
    stated = _percent(args)
    scene, c, tolerance, answers, note = graded(args, scene, c, files, stated)
    source = files[0] if files else args.scene
    if not answers:
        raise SceneError(
            "nothing to check: the scene has no [answers] and no answer file was given",
            file=args.scene,
            key="[answers]",
        )
    try:
        verdicts = cycle_verdicts(scene, c, answers, tolerance)
    except PolygonMethodError as exc:
        raise exc.located(source)
    why = (
        "three significant figures (computed answers)"
        if tolerance is None
        else f"{100 * tolerance:g} % (--tolerance)"
        if stated is not None
        else f"{100 * tolerance:g} % (the answers' own)"
    )
    if getattr(args, "json", False):
        d = verdicts_dict(verdicts, args.scene, files[0] if files else None)
        d["tolerance_used"] = {"why": why}
        print(json.dumps(d, indent=2, allow_nan=False))
    else:
        title = f"{scene.title or args.scene}: answers from {source}{note}"
        print(verdicts_text(verdicts, title))
    return 0 if all(v.ok for v in verdicts) else 1


def _page(args, scene) -> int:
    """``page SCENE -o page.html [--answers FILE] [--frames N]``: the diagram's page."""
    from ..check.energy import cycle_verdicts
    from ..page import check_frames
    from ..page.energy import cycle_page

    out = Path(args.output)
    if out.suffix.lower() not in (".html", ".htm"):
        raise PolygonMethodError(
            f"cannot write the page to {out}: the file name must end in .html", key="-o"
        )
    _drawn(scene, "-o")
    n = check_frames(180 if args.frames is None else args.frames)
    answers_file = getattr(args, "answers", None)
    targets = check_outputs([(out, "-o")], protect=[scene.file, answers_file])
    from .energy_class import graded

    c = _solved(scene)  # (an answer file naming another variant is refused, as check does)
    _, _, tolerance, answers, _ = graded(
        args, scene, c, [answers_file] if answers_file else [], None
    )
    verdicts = None
    if answers:
        try:
            verdicts = cycle_verdicts(scene, c, answers, tolerance)
        except PolygonMethodError as exc:
            raise exc.located(answers_file or scene.file)
    title = f"answers from {Path(answers_file).name if answers_file else 'the scene'}"
    html = cycle_page(scene, c, n, verdicts=verdicts, answers_title=title)
    write_outputs(targets, [(html, False)])
    over = "the crossings" if c.form == "areas" else f"{n} frames over the cycle"
    print(f"{out}: the turning-moment diagram over {over}; {len(html.encode()) / 1024:.0f} KiB")
    return 0


def _drawn(scene, key) -> None:
    """Refused: a drawing of a scene that states the fluctuation of energy alone (no
    diagram to draw)."""
    if scene.diagram is not None and scene.diagram.form == "energy":
        raise PolygonMethodError(
            "the maximum fluctuation of energy is given, not the turning-moment diagram: "
            "nothing to draw (solve, steps and check read it)",
            file=scene.file,  # (the scene's doing: named, as every refusal of a scene is)
            key=key,
        )


def _sheet(scene, out, key, paper="A4") -> int:
    from ..draw import paper_name
    from ..draw.energy import cycle_sheet

    _drawn(scene, key)
    paper = paper_name(paper)

    fmt = out.suffix.lower().lstrip(".")
    if fmt not in ("svg", "png", "pdf"):
        raise PolygonMethodError(
            f"cannot draw to {out}: the file name must end in .svg, .png or .pdf", key=key
        )
    targets = check_outputs([(out, key)], protect=[scene.file])
    c = _solved(scene)
    write_outputs(targets, [(cycle_sheet(scene, c, fmt, paper), fmt != "svg")])
    print(f"{out}: the turning-moment diagram and the energy over the cycle, on {paper} portrait")
    return 0


def _draw(args, scene) -> int:
    given = {
        "animate": getattr(args, "animate", False),
        "forces": getattr(args, "forces", False),
        "diagram": getattr(args, "diagram", "all") not in (None, "all"),
        "scale": bool(getattr(args, "scale", None)),
        "frames": getattr(args, "frames", None) is not None,
        "centre-labels": getattr(args, "centre_labels", None) not in (None, "I13"),
        "answers": bool(getattr(args, "answers", None)),
    }
    for flag, on in given.items():
        if on:
            raise PolygonMethodError(
                "a turning-moment diagram's sheet is one drawing (on --paper): leave it out",
                key=f"--{flag}",
            )
    return _sheet(scene, Path(args.output), "-o", getattr(args, "paper", None) or "A4")


def _sweep(args, scene) -> int:
    _shows_all(args, "sweep")
    for flag in ("start", "stop", "step", "points", "links", "error_bound"):
        if getattr(args, flag, None) not in (None, False):
            name = {"start": "from", "stop": "to"}.get(flag, flag).replace("_", "-")
            raise PolygonMethodError(
                f"--{name}: a turning-moment diagram is swept over its whole cycle "
                "(--steps N crank angles in the CSV); leave it out",
                key=f"--{name}",
            )
    steps = getattr(args, "steps", None)
    if steps is not None and not 2 <= steps <= 1_000_000:
        raise PolygonMethodError("--steps: 2 to 1,000,000 crank angles", key="--steps")
    done = False
    if getattr(args, "csv", None):
        _csv(scene, Path(args.csv), (steps or 360) + 1)
        done = True
    if getattr(args, "plot", None):
        _sheet(scene, Path(args.plot), "--plot")
        done = True
    if getattr(args, "summary", False) or not done:
        from ..text.energy import cycle_text

        # (a CSV on standard output keeps it to itself: the words go to stderr)
        words = sys.stderr if getattr(args, "csv", None) and is_stdout(args.csv) else sys.stdout
        print(cycle_text(scene, _solved(scene)), file=words)
    return 0


def _csv(scene, out, n) -> None:
    from ..forces.flywheel_cycle import curves

    if scene.diagram is None or scene.diagram.form in ("areas", "energy"):
        raise PolygonMethodError(
            "the diagram is given as areas (or a press, or its fluctuation of energy alone): "
            "no curve to tabulate over the crank angle",
            file=scene.file,
            key="--csv",
        )
    to_stdout = is_stdout(out)  # the CSV on standard output (-, /dev/stdout)
    targets = None if to_stdout else check_outputs([(out, "--csv")], protect=[scene.file])
    c = _solved(scene)
    th, tq, rs, es = curves(scene, c, n)
    rows = ["angle_deg,torque,resisting,energy"]
    for x, t, r, e in zip(th, tq, rs, es):
        row = f"{x * 57.29577951308232:.12g},{t:.12g},{r:.12g},{e:.12g}"
        if row != rows[-1]:  # (a corner on the grid is drawn twice, a jump upright: one row)
            rows.append(row)
    text = "\n".join(rows) + "\n"
    if to_stdout:
        sys.stdout.write(text)
    else:
        write_outputs(targets, [(text.encode(), True)])
    print(f"{out}: {len(rows) - 1} crank angles", file=sys.stderr)


def _variants(args, scene) -> int:
    from .energy_class import make_variants

    return make_variants(args, scene)


_COMMANDS = {
    "solve": _solve,
    "steps": _steps,
    "check": _check,
    "draw": _draw,
    "sweep": _sweep,
    "page": _page,
    "variants": _variants,
}


def engine_cycle(sol):
    """The turning moment over an engine's cycle, for ``solve``, where the scene asks for
    the cycle (an indicator diagram, or a flywheel); else None (``sweep --summary`` gives
    it for any engine)."""
    sc = sol.scene
    if not sc.indicators and sc.flywheel is None:
        return None
    from ..common.errors import PolygonMethodError
    from ..linkage.flywheel import engine_piston, turning_moment
    from ..linkage.flywheel_machine import machine_asks

    if sc.indicators and sol.forces_refused:
        sol.forces  # the indicator's own refusal, in its words (a lag, a piston)
    if sc.has_forces and sol.forces_refused and not sc.indicators:
        sol.forces  # (the force analysis's own refusal, in its words)
    if engine_piston(sc) is None and machine_asks(sc):
        return turning_moment(sc)  # a machine driven at a steady speed: its flywheel
    if sol.forces_refused or engine_piston(sc) is None:
        if sc.flywheel is not None:
            raise PolygonMethodError(
                "the flywheel is an engine's or a machine's: a slider crank "
                "with a gas force on its piston ([loads] pressure, or "
                "[indicator]), or a mechanism with [masses] or [loads] driven by a crank",
                file=sc.file,
                key="[flywheel]",
            )
        return None
    return turning_moment(sc)


def check_cylinders(scene, sol=None) -> None:
    """Refuse, in the indicator's one line, several cylinders' indicator diagrams that do not
    fit their engine (a lag off a cylinder's inner dead centre, a piston that is no slider
    crank's): the views that would only note it refuse it."""
    if len(scene.indicators) < 2:
        return
    from ..forces.engine import cylinders
    from ..motion.solution import solve

    sol = sol or solve(scene)
    cylinders(scene, sol.plan, sol.P)


def draw_engine_cycle(args, out, fmt) -> int:
    """``draw --diagram cycle``: an engine's cycle, or a machine's turn at a steady speed
    with its flywheel, on A4 (refused for another scene)."""
    from ..draw import paper_name
    from ..draw.engine_cycle import engine_cycle_sheet
    from ..linkage.flywheel import engine_piston
    from ..scene import load_scene

    if args.scale or getattr(args, "centre_labels", None):
        raise PolygonMethodError(
            "--diagram cycle draws at its own scales: leave out --scale", key="--scale"
        )
    no_answers(args, "--diagram cycle draws the turning moment over the cycle")
    targets = check_outputs([(out, "-o")], protect=[args.scene])
    scene = load_scene(args.scene, variants=False, answers=False)
    check_cylinders(scene)
    if engine_piston(scene) is None and scene.flywheel is None:
        raise PolygonMethodError(
            "--diagram cycle draws an engine's turning-moment diagram (a slider crank with "
            "a gas force on its piston: [loads] pressure, or [indicator]) or a machine's "
            "([flywheel] on a mechanism with masses or loads its crank turns at a steady speed)",
            file=scene.file,
            key="--diagram",
        )
    data, words = engine_cycle_sheet(scene, fmt, paper_name(getattr(args, "paper", None) or "A4"))
    write_outputs(targets, [(data, fmt != "svg")])
    print(f"{out}: {words}")
    return 0
