"""A variant per student: the scene's ``[variants]`` table says what may vary and how; this
module chooses the variants (pure: no files are read or written here).

A candidate is a choice of one value for every varied key, drawn with
``numpy.random.default_rng(seed)``. Candidates are screened many at a time: the base
scene's plan (its steps and assembly branches) is evaluated once over all of them, with
every dimension an array (``Plan.dimensions`` of each candidate, stacked), and a candidate
passes where every step assembles, every step's condition is at least ``min_condition``
and the linkage keeps its class (Grashof's class of a four-bar, whether a slider crank's
crank turns fully, Whitworth or oscillating slotted lever; for any other mechanism,
whether the crank turns fully on its branch). Each chosen candidate is then written as a
scene, read back by the scene reader, compiled on its own (its assembly hints must choose
the base scene's branches) and solved plainly; only a variant that passes again is kept.
Candidates differ in at least one value (values that are equal in SI are listed once), so
no two variants are the same; a candidate whose every value is the base problem's (its
dimensions, crank angle over a turn, speed, loads) is no variant and is turned down.

Small spaces (at most :data:`ENUMERATE` combinations) are visited in a random order to
the end, so "only N variants exist" is exact; larger ones are sampled without repeats up
to :data:`MAX_TRIED` candidates.
"""

from __future__ import annotations

import copy
import math
from collections import Counter

import numpy as np

from ..common.errors import PolygonMethodError, SceneError
from ..solver.kinematics import evaluate
from ..solver.compiler import compile_plan
from ..scene import Scene, parse_scene, scene_from_table, scene_table
from ..motion.solution import solve
from ..motion.tidy import tidied
from .toml_text import dump_toml
from .linkage_class import _shape, linkage_class
from .questions import questions
from .records import Variant, VariantSet, shortfall_line
from .screening import (
    ENUMERATE,
    MAX_TRIED,
    _branches,
    _candidates,
    _problem,
    _same,
    screen,
)
from .screening import _stack_dims as _stack_dims  # (the tests')
from .papers import (
    answer,
    answer_key_csv,
    answer_key_markdown,
    sheet_markdown,
    sheet_pdf,
    summary_text,
)

__all__ = [
    "generate",
    "shortfall_line",
    "VariantSet",
    "Variant",
    "linkage_class",
    "dump_toml",
    "questions",
    "screen",
    "answer",
    "ENUMERATE",
    "MAX_TRIED",
    "MAX_VARIANTS",
    "MAX_SEED",
    "answer_key_csv",
    "answer_key_markdown",
    "sheet_markdown",
    "sheet_pdf",
    "summary_text",
]

#: the most variants one run makes
MAX_VARIANTS = 9999
#: the largest seed: each variant file records its seed, and TOML's integers are 64-bit
MAX_SEED = (1 << 63) - 1


def _put(raw, path, value):
    d = raw
    for p in path[:-1]:
        d = d[p]
    d[path[-1]] = value


def _id_width(count):
    return max(2, len(str(count)))


def _asked_for(scene: Scene, count: int, seed: int):
    """The scene's ``[variants]`` table, once the scene, the count and the seed are checked (a
    Scene with such a table; whole numbers in range)."""
    if not isinstance(scene, Scene):
        raise SceneError(
            f"a Scene is needed (load_scene(path) or parse_scene(text)), not {type(scene).__name__}"
        )
    var = scene.variation
    if var is None:
        raise SceneError(
            "the scene has no [variants] table: add one saying what may vary, "
            "e.g. [variants] BC = { from = 60, to = 75, step = 1 } (see "
            "docs/variants.md)",
            file=scene.file,
            key="[variants]",
        )
    for name, v, low, high in (("--count", count, 1, MAX_VARIANTS), ("--seed", seed, 0, MAX_SEED)):
        if (
            isinstance(v, bool)
            or not isinstance(v, (int, np.integer))
            or v < low
            or (high is not None and v > high)
        ):
            raise SceneError(
                f"{name} {v!r}: a whole number from {low}"
                + (f" to {high}" if high else "")
                + (
                    " (each variant file records it, and TOML's integers are 64-bit)"
                    if name == "--seed"
                    else ""
                ),
                key=name,
            )
    return var


def _built(picks, raw, var, scene: Scene, plan, base_problem, rejected: Counter) -> list:
    """The picked candidates as scenes ``(pick, table, scene)``: those that do not read as a
    scene, or ask the base problem itself, are counted in ``rejected`` and left out."""
    built = []
    for t in picks:
        r = copy.deepcopy(raw)
        for v in var.varied:  # every setting first, so that none undoes a value
            for path, value in v.setup:
                _put(r, path, copy.deepcopy(value))
        for v, i in zip(var.varied, t):
            _put(r, v.path, v.values[i])
        try:
            cand = scene_from_table(r, scene.file)
        except PolygonMethodError:
            rejected["does not read as a scene (a triangle that cannot close, ...)"] += 1
            continue
        try:
            same = _same(_problem(plan, cand), base_problem)
        except PolygonMethodError:
            same = False
        if same:  # every value as the base problem's: no variant
            rejected["the base problem itself"] += 1
            continue
        built.append((t, r, cand))
    return built


def _of_the_class(built: list, shape, cls, rejected: Counter) -> list:
    """The built candidates of the base problem's linkage class (all of them for a mechanism
    without one); the others are counted in ``rejected``."""
    if shape[0] == "mechanism":
        return built
    kept = []
    for b in built:
        if linkage_class(b[2], shape) == cls:
            kept.append(b)
        else:
            rejected["another linkage class"] += 1
    return kept


def generate(scene: Scene, count: int, seed: int, *, batch: int | None = None) -> VariantSet:
    """Choose ``count`` variants of ``scene`` (see the module docstring), reproducibly
    from ``seed``. Fewer are returned where fewer exist (:meth:`VariantSet.shortfall`)."""
    var = _asked_for(scene, count, seed)
    solve(scene)  # the base problem itself must solve (else its error, as solve gives it)
    plan = compile_plan(scene)
    if scene.input.found_from:  # each candidate's two speeds would be found anew
        raise SceneError(
            "variants of a scene whose two inputs' speeds are given on other links "
            f"({', '.join(g.key for g in scene.input.found_from)}) are not made: state "
            "each crank's speed to vary it",
            key="[variants]",
            file=scene.file,
        )
    branches = _branches(plan)
    shape = _shape(scene)
    cls = linkage_class(scene, shape)
    raw = scene_table(scene)
    for k in ("variants", "answers", "variant"):
        raw.pop(k, None)
    title = scene.title or (scene.file or "scene")
    sizes = [len(v) for v in var.varied]
    total = math.prod(sizes)
    rng = np.random.default_rng(seed)
    width = _id_width(count)
    batch = batch or max(4 * count, 64)
    found, rejected, tried = [], Counter(), 0
    qs = questions(scene)
    base_problem = _problem(plan, scene)
    gen = _candidates(rng, sizes, total)
    while len(found) < count:
        picks = []
        for t in gen:
            picks.append(t)
            if len(picks) >= batch:
                break
        if not picks:
            break
        tried += len(picks)
        built = _built(picks, raw, var, scene, plan, base_problem, rejected)
        kept = _of_the_class(built, shape, cls, rejected) if built else []
        if not kept:
            continue
        ok, least = screen(plan, [b[2] for b in kept], var.min_condition)
        for good, b in zip(ok, kept):
            if not good:
                rejected["does not assemble, or a step's condition below the minimum"] += 1
                continue
            if len(found) >= count:
                break
            v = _confirm(
                b, len(found) + 1, width, var, plan, title, seed, shape, cls, branches, rejected
            )
            if v is not None:
                found.append(v)
    return VariantSet(
        scene, tuple(found), count, seed, total, tried, tried >= total, dict(rejected), cls, qs
    )


def _hints_moved(r, plan, sc):
    """An assembly hint given as a rough position is the base figure's: in a variant it
    becomes the point's position on the base scene's branch (to 1e-4 of the mechanism's
    size, whatever the scene's unit: 0.01 mm of a 450 mm linkage, 0.00001 m of a 0.45 m
    one), so that the variant's file shows its own figure."""
    hints = r.get("assembly", {})
    if not any(isinstance(h, list) for h in hints.values()):
        return r
    m = evaluate(plan, dims=plan.dimensions(sc), upto=0)
    u = sc.length_unit
    size = max([lk.length for lk in sc.links] + [0.0]) / u
    digits = max(1, -math.floor(math.log10(size * 1e-4))) if size > 0 else 1
    r["assembly"] = {
        p: (
            [_round(m.P[p][0] / u, digits), _round(m.P[p][1] / u, digits)]
            if isinstance(h, list) and p in m.P
            else h
        )
        for p, h in hints.items()
    }
    return r


def _round(x, digits=1):
    y = round(float(x), digits)
    return int(y) if y.is_integer() else y


def _confirm(b, k, width, var, plan, title, seed, shape, cls, branches, rejected):
    """Write the candidate as a scene, read it back and solve it plainly: a Variant, or
    None (with the reason counted) where it does not pass again."""
    t, r, sc0 = b
    vid = f"{k:0{width}d}"
    name = f"variant-{vid}.toml"
    try:
        r = _hints_moved(copy.deepcopy(r), plan, sc0)
    except PolygonMethodError:
        rejected["does not solve"] += 1
        return None
    r = dict(r)
    r["title"] = f"{title}, variant {vid}"
    values = {v.key: v.values[i] for v, i in zip(var.varied, t)}
    shown = {v.key: v.shown[i] for v, i in zip(var.varied, t)}
    r["variant"] = {"id": vid, "of": title, "seed": int(seed)}
    header = f'Variant {vid} of "{title}" (seed {seed}): ' + ", ".join(
        f"{v.label} {shown[v.key]}" for v in var.varied
    )
    text = dump_toml(r, header)
    try:
        sc = parse_scene(text, file=name)
        if _branches(compile_plan(sc)) != branches:
            rejected["its assembly hints choose the other branch"] += 1
            return None
        sol = solve(sc)
    except PolygonMethodError:
        rejected["does not solve"] += 1
        return None
    least = min(sol.conditions.values(), default=1.0)
    if least < var.min_condition:
        rejected["does not assemble, or a step's condition below the minimum"] += 1
        return None
    got = linkage_class(sc, shape)
    if got != cls:
        rejected["another linkage class"] += 1
        return None
    # the key's values without rounding noise (a rod that does not turn: 0, not 3.7e-15)
    return Variant(vid, name, values, shown, text, sc, tidied(sol), least, got)
