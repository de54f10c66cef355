"""A variant per student of a turning-moment diagram stated on its own (pure: the command
line reads and writes). The scene's ``[variants]`` names, for each of its tables
(``turning_moment``, ``press``, ``flywheel``), the keys that vary and their values
(:mod:`polygon_method.scene.energy_variation`). A candidate is one value of each, drawn
in ``numpy.random.default_rng(seed)``'s order (a space of at most
:data:`~polygon_method.variants.ENUMERATE` combinations visited whole, a larger one sampled
without repeats); it is written as a scene (the base scene's table with its values, no
``[answers]`` or ``[variants]``, a ``[variant]`` table naming it), read back by the
diagram's reader and solved (:func:`~polygon_method.forces.flywheel_cycle.solve_cycle`).
It is kept where it reads and solves (areas that add up to nought, a flywheel that holds
the speed), differs from every variant kept and is not the base problem itself.

The answer key holds the base scene's ``[answers]`` keys, else every answer the scene
gives a value to (:data:`~polygon_method.check.energy.CYCLE_UNITS`)."""

from __future__ import annotations

import csv
import io
from collections import Counter
from dataclasses import dataclass, replace

import numpy as np

from ..forces.flywheel_cycle import ANSWER_FIELDS as CYCLE_UNITS
from ..common.errors import PolygonMethodError, SceneError
from ..forces.flywheel_cycle import solve_cycle
from ..scene.energy import cycle_from_table, cycle_variation, parse_cycle
from ..scene.source import toml_table
from ..text.energy import book_number as _g
from . import ENUMERATE, MAX_SEED, MAX_VARIANTS, _candidates, _id_width, shortfall_line
from .toml_text import dump_toml

__all__ = [
    "CycleVariant",
    "CycleVariants",
    "cycle_variants",
    "cycle_key_csv",
    "cycle_key_markdown",
    "cycle_sheet_markdown",
    "cycle_summary_text",
]


@dataclass(frozen=True)
class CycleVariant:
    """One student's problem: its ``id`` and file ``name``, the scene's ``text``, the
    values chosen (``shown``: varied key -> text), its scene and solved cycle."""

    id: str
    name: str
    text: str
    shown: dict
    scene: object
    cycle: object


@dataclass(frozen=True)
class CycleVariants:
    """The variants of ``base`` (its :class:`CycleScene`), the ``varied`` keys, the answer
    key's ``keys``; ``space`` the combinations, ``tried`` how many were looked at,
    ``rejected`` why the others were turned down (reason -> count)."""

    base: object
    seed: int
    requested: int
    varied: tuple
    keys: tuple
    variants: tuple
    space: int
    tried: int
    exhaustive: bool
    rejected: dict

    def shortfall(self) -> str | None:
        """One line when fewer variants than asked were found, else None."""
        return shortfall_line(
            self,
            "each read and solved as a scene, none the base problem, no two alike",
            "widen the ranges",
        )


def _problem(scene) -> object:
    """What makes ``scene`` the problem it is: its records, without its name, file, words
    and answers (values equal in SI are the same problem)."""

    def bare(r):
        return None if r is None else replace(r, words=())

    return (bare(scene.diagram), bare(scene.press), bare(scene.flywheel))


def _keys(base, c) -> tuple:
    """The answer key's keys: the base's [answers] keys, else every one with a value."""
    if base.answers:
        return tuple(dict.fromkeys(a.key for a in base.answers))
    fw = base.flywheel
    given = set()
    if fw is not None:
        given |= {"Cs"} if fw.coefficient is not None else set()
        given |= {"rim_radius"} if fw.rim_speed is None and fw.stress is None else set()
        given |= {"rim_width"} if fw.width is not None else set()
        given |= {"rim_thickness"} if fw.thickness is not None else set()
    return tuple(
        k
        for k, (field, _, _) in CYCLE_UNITS.items()
        if getattr(c, field) is not None and k not in given
    )


def _checked(count, seed):
    if isinstance(count, bool) or not isinstance(count, int) or not 1 <= count <= MAX_VARIANTS:
        raise SceneError(f"--count {count!r}: between 1 and {MAX_VARIANTS}", key="--count")
    if isinstance(seed, bool) or not isinstance(seed, int) or not 0 <= seed <= MAX_SEED:
        raise SceneError(f"--seed {seed!r}: a whole number from 0 to {MAX_SEED}", key="--seed")


def cycle_variants(text: str, file: str | None, count: int, seed: int) -> CycleVariants:
    """``count`` variants of the diagram's scene ``text`` (see the module's words)."""
    _checked(count, seed)
    base = parse_cycle(text, file)
    varied = cycle_variation(text, file)
    if not varied:
        raise SceneError(
            "the scene has no [variants]: say what varies, e.g. flywheel = { speed = "
            '["250 rpm", "300 rpm"] }',
            file=file,
            key="[variants]",
        )
    c0 = solve_cycle(base)
    raw = {k: v for k, v in toml_table(text).items() if k not in ("answers", "variants", "variant")}
    sizes = [len(v) for v in varied]
    space = int(np.prod(sizes, dtype=object))
    width = _id_width(count)
    rng = np.random.default_rng(seed)
    seen, kept, rejected, tried = {_problem(base)}, [], Counter(), 0
    for idx in _candidates(rng, sizes, space):
        tried += 1
        trial = {k: (dict(v) if isinstance(v, dict) else v) for k, v in raw.items()}
        for v, i in zip(varied, idx):
            trial[v.table][v.key] = v.values[i]
        try:
            sc = cycle_from_table(trial, file)
            solve_cycle(sc)  # (a flywheel too light, a law that never crosses: turned down)
        except PolygonMethodError as exc:
            rejected[exc.message.split(":")[0][:60]] += 1
            continue
        mark = _problem(sc)
        if mark in seen:
            rejected["the base problem itself" if mark == _problem(base) else "a repeat"] += 1
            continue
        seen.add(mark)
        vid = f"{len(kept) + 1:0{width}d}"
        shown = {v.name: v.shown[i] for v, i in zip(varied, idx)}
        trial["variant"] = {"id": vid, "of": base.title or "", "seed": seed}
        head = f"Variant {vid} of {base.title or file} (seed {seed}): " + ", ".join(
            f"{k} {x}" for k, x in shown.items()
        )
        out = dump_toml(trial, head)
        sc = parse_cycle(out, f"variant-{vid}.toml")  # read back as a student's file is
        kept.append(CycleVariant(vid, f"variant-{vid}.toml", out, shown, sc, solve_cycle(sc)))
        if len(kept) >= count:
            break
    return CycleVariants(
        base,
        seed,
        count,
        varied,
        _keys(base, c0),
        tuple(kept),
        space,
        tried,
        space <= ENUMERATE,
        dict(rejected),
    )


def _answer(c, key) -> float | None:
    field = CYCLE_UNITS[key][0]
    x = getattr(c, field)
    return None if x is None else float(x)


def cycle_key_csv(vs) -> str:
    """One row per variant: its id, file, the values chosen, then each answer in SI, in full
    (the shortest text that reads back as the same double; empty where it has none)."""
    names = [v.name for v in vs.varied]
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["variant", "file"] + names + [f"{k} ({CYCLE_UNITS[k][1] or '1'})" for k in vs.keys])
    for v in vs.variants:
        vals = [_answer(v.cycle, k) for k in vs.keys]
        w.writerow(
            [v.id, v.name]
            + [v.shown[n] for n in names]
            + ["" if x is None else repr(x) for x in vals]
        )
    return buf.getvalue()


def cycle_key_markdown(vs) -> str:
    """The teacher's answer key: one row per variant, its values and its answers (four
    significant figures; the CSV has them in full)."""
    names = [v.name for v in vs.varied]
    out = [
        f"# Answer key: {vs.base.title or vs.base.file}",
        "",
        f"{len(vs.variants)} variants, seed {vs.seed}. Values to four significant figures "
        "(the CSV has them in full); grade with `polygon-method check BASE ANSWERS "
        "--variants DIR`.",
        "",
        "| variant | "
        + " | ".join(names + [f"{k} ({CYCLE_UNITS[k][1] or '1'})" for k in vs.keys])
        + " |",
        "|---|" + "---|" * (len(names) + len(vs.keys)),
    ]
    for v in vs.variants:
        vals = [_answer(v.cycle, k) for k in vs.keys]
        cells = [v.id] + [v.shown[n] for n in names] + ["-" if x is None else _g(x) for x in vals]
        out.append("| " + " | ".join(str(c).replace("|", "\\|") for c in cells) + " |")
    return "\n".join(out) + "\n"


def cycle_sheet_markdown(vs) -> str:
    """Each student's problem with their own numbers (how the scene was read, in words)
    and the questions."""
    out = [f"# {vs.base.title or vs.base.file}: problem sheet", ""]
    for v in vs.variants:
        out.append(f"## Variant {v.id}")
        out.append("")
        out.append("Given (as the scene file states it):")
        out.append("")
        out += [f"- {line}" for line in _given(v.text)]
        out.append("")
        out.append("Read as:")
        out.append("")
        out += [f"- {w}" for w in v.cycle.words]
        out.append("")
        out.append("Find: " + ", ".join(f"{CYCLE_UNITS[k][2]} ({k})" for k in vs.keys) + ".")
        out.append("")
    return "\n".join(out)


def _given(text) -> list:
    """The variant's tables as ``[table] key = value`` lines (its ``[variant]`` and title
    left out): what the student is given, exactly."""
    from .toml_text import _value

    raw = toml_table(text)
    return [
        f"[{t}] {k} = {_value(x)}"
        for t in ("turning_moment", "press", "flywheel")
        if isinstance(raw.get(t), dict)
        for k, x in raw[t].items()
    ]


def cycle_summary_text(vs) -> str:
    """One line per variant and what varied, as ``variants`` prints it."""
    lines = [
        f"{vs.base.title or vs.base.file}: {len(vs.variants)} variants (seed {vs.seed}) of "
        f"{vs.space} combinations, {vs.tried} tried"
    ]
    for v in vs.variants:
        lines.append(f"  {v.name}: " + ", ".join(f"{k} {x}" for k, x in v.shown.items()))
    return "\n".join(lines)
