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
from dataclasses import dataclass, replace

import numpy as np

from ..common.errors import PolygonMethodError, SceneError
from ..common.tolerances import ROUNDING
from ..common.units import ANSWER_UNITS
from ..solver.kinematics import evaluate
from ..linkage import four_bar_of, grashof, slider_crank_of, slotted_of
from ..linkage.cycle_values import CYCLE_SI
from ..linkage.engine_values import ENGINE_KEYS
from ..solver.compiler import compile_plan
from ..scene import Scene, parse_scene, scene_from_table, scene_table
from ..motion.solution import solve
from ..motion.tidy import tidied
from .toml_text import dump_toml
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

#: a space of at most this many combinations is visited whole
ENUMERATE = 50_000
#: at most this many candidates are screened in a larger space
MAX_TRIED = 20_000
#: the most variants one run makes
MAX_VARIANTS = 9999
#: the largest seed: each variant file records its seed, and TOML's integers are 64-bit
MAX_SEED = (1 << 63) - 1


# --------------------------------------------------------------------------- the class


def _shape(scene: Scene):
    """What kind of linkage the scene is, for keeping its class: ("four-bar", names),
    ("slider crank", names), ("slotted", names) or ("mechanism", None)."""
    fb = four_bar_of(scene)
    if fb is not None:
        return ("four-bar", (fb.crank, fb.coupler, fb.output, fb.o2, fb.o4))
    sk = slider_crank_of(scene)
    if sk is not None:
        return ("slider crank", (sk.o, sk.crank, sk.rod, sk.b))
    slot = slotted_of(scene)
    if slot is not None:
        crank, lever = slot
        return ("slotted", (crank.link, crank.pivot, lever.known))
    return ("mechanism", None)


def linkage_class(scene: Scene, shape=None) -> str:
    """The class a variant must keep, in words: "four-bar: crank-rocker", "slider crank:
    the crank turns fully", "slotted lever: Whitworth", "mechanism: the crank turns fully"."""
    kind, names = shape or _shape(scene)
    if kind == "four-bar":
        crank, coupler, output, o2, o4 = names
        (ax, ay), (dx, dy) = scene.ground[o2], scene.ground[o4]
        g = grashof(
            scene.link(crank).length,
            scene.link(coupler).length,
            scene.link(output).length,
            math.hypot(dx - ax, dy - ay),
        )
        return f"four-bar: {g.kind}"
    if kind == "slider crank":
        o, crank, rod, b = names
        (ox, oy) = scene.ground[o]
        path = scene.slider(b)
        (qx, qy), (ux, uy) = path.through, path.u
        e = abs((ox - qx) * uy - (oy - qy) * ux)
        r, ell = scene.link(crank).length, scene.link(rod).length
        return "slider crank: " + (
            "the crank turns fully" if ell >= (r + e) * (1 - ROUNDING) else "the crank rocks"
        )
    if kind == "slotted":
        crank, pivot, known = names
        (ox, oy), (kx, ky) = scene.ground[pivot], scene.ground[known]
        whit = scene.link(crank).length > math.hypot(kx - ox, ky - oy)
        return "slotted lever: " + (
            "Whitworth (the lever turns fully)" if whit else "oscillating lever"
        )
    from ..solver.tracking import Sweeper

    try:
        sw = Sweeper(scene)
        turns = sw.domain.full_turn
    except PolygonMethodError:
        return "mechanism: locked"
    if not sw.driver.periodic:  # a block driven along its guide
        return f"mechanism: driven by {sw.driver.title}"
    return "mechanism: " + ("the crank turns fully" if turns else "the crank rocks")


# --------------------------------------------------------------------------- records


@dataclass(frozen=True)
class Variant:
    """One student's problem: its id, file name, the values chosen (as the scene writes
    them, by ``[variants]`` key), its scene text, the scene read back and its solution."""

    id: str
    name: str
    values: dict
    shown: dict
    text: str
    scene: Scene
    solution: object
    least_condition: float
    linkage: str


def shortfall_line(found, kept: str, widen: str) -> str | None:
    """One line when ``found`` (a set of variants: ``variants``, ``requested``, ``space``,
    ``tried``, ``exhaustive``, ``rejected``) holds fewer than asked, else None: how many
    of how many combinations made a good variant (``kept``: what a good one is), why the
    others were turned down, and what to do (``widen``: the ranges, or more)."""
    n = len(found.variants)
    if n >= found.requested:
        return None
    why = ", ".join(f"{k}: {v}" for k, v in sorted(found.rejected.items(), key=lambda kv: -kv[1]))
    where = (
        f"only {n} of the {found.space} combinations of [variants] make a good variant"
        if found.exhaustive
        else f"only {n} good variants found in {found.tried} of the {found.space} "
        "combinations of [variants]"
    )
    return (
        f"{where} ({kept}), not {found.requested}"
        + (f"; turned down: {why}" if why else "")
        + (f": widen the ranges or ask for --count {n}" if n else f": {widen}")
    )


@dataclass(frozen=True)
class VariantSet:
    """The variants made of a base scene: each variant, how many were asked for, the seed, the
    combinations the ranges allow and how many were screened."""

    base: Scene
    variants: tuple
    requested: int
    seed: int
    space: int  # combinations the ranges allow
    tried: int  # candidates screened
    exhaustive: bool  # every combination was screened
    rejected: dict  # why candidates were turned down -> how many
    linkage: str
    questions: tuple  # (key, kind, names, unit, signed, the unit asked or None)

    def shortfall(self) -> str | None:
        """One line when fewer variants than asked were found, else None."""
        return shortfall_line(
            self,
            f"assembled on the stated branch, every step's condition at least "
            f"{self.base.variation.min_text}, the class kept: {self.linkage}",
            "widen the ranges or lower min_condition",
        )


def _put(raw, path, value):
    d = raw
    for p in path[:-1]:
        d = d[p]
    d[path[-1]] = value


# --------------------------------------------------------------------------- questions


def _unit_of(kind) -> str:
    """The SI unit a class's answer key gives an answer of ``kind`` in."""
    if kind in CYCLE_SI:  # a quick return's times, a stroke, a link's angle
        return CYCLE_SI[kind]
    return ANSWER_UNITS[kind] if kind in ANSWER_UNITS else ENGINE_KEYS[kind][1]


def questions(scene: Scene) -> tuple:
    """What the answer key gives: the base scene's ``[answers]`` keys where it has them
    (centres aside), else every moving point's speed and acceleration, every moving link's
    omega and alpha, each slider's sliding velocity and acceleration, the input torque.
    Each as (key, kind, names, unit, signed, the unit a question asks its answer in: "rpm"
    of ``omega_BC = "? rpm"``, else None). A key asked without its answer (``"?"``) is a
    question as any other: the base's values are never the variants'."""
    asked = [a for a in scene.answers if a.kind != "centre"]
    if asked:
        return tuple(
            (
                a.key,
                a.kind,
                tuple(a.names),
                _unit_of(a.kind),
                a.kind in ("omega", "alpha", "vs", "as", "torque", "torque2"),
                getattr(a, "unit", None),
            )
            for a in asked
        )
    out = []
    ground = set(scene.ground)
    for p in scene.point_names:
        if p not in ground:
            out.append((f"v_{p}", "v", (p,), "m/s", False, None))
    for p in scene.point_names:
        if p not in ground:
            out.append((f"a_{p}", "a", (p,), "m/s^2", False, None))
    from ..scene import split_name

    # the crank's omega is given, unless the scene gives the motion on another quantity
    crank = scene.input.crank if scene.input.given is None else None
    for lk in scene.links:
        if not (lk.p in ground and lk.q in ground) and lk.key != crank:
            out.append((f"omega_{lk.key}", "omega", split_name(lk.key), "rad/s", True, None))
    for lk in scene.links:
        if not (lk.p in ground and lk.q in ground) and lk.key != crank:
            out.append((f"alpha_{lk.key}", "alpha", split_name(lk.key), "rad/s^2", True, None))
    for s in scene.sliders:
        out.append((f"vs_{s.point}", "vs", (s.point,), "m/s", True, None))
        out.append((f"as_{s.point}", "as", (s.point,), "m/s^2", True, None))
    for p in scene.pins:
        out.append((f"rub_{p.point}", "rub", (p.point,), "m/s", False, None))
    if scene.loads:
        out.append(("torque", "torque", (), "N m", True, None))
    return tuple(out)


# --------------------------------------------------------------------------- screening


def _stack(values):
    """Per-candidate values (numbers, or tuples of them) as arrays (or tuples of arrays)."""
    first = values[0]
    if isinstance(first, tuple):
        return tuple(_stack([v[i] for v in values]) for i in range(len(first)))
    if isinstance(first, (int, float)):
        return np.array(values, dtype=float)
    return first


def _stack_dims(dl):
    d0 = dl[0]
    ground = {p: _stack([d.ground[p] for d in dl]) for p in d0.ground}
    steps = tuple(_stack([d.steps[i] for d in dl]) for i in range(len(d0.steps)))
    radii = {p: _stack([d.radii[p] for d in dl]) for p in d0.radii}
    return replace(
        d0,
        ground=ground,
        steps=steps,
        theta=_stack([d.theta for d in dl]),
        omega=_stack([d.omega for d in dl]),
        alpha=_stack([d.alpha for d in dl]),
        radii=radii,
    )


def screen(plan, scenes, min_condition):
    """For each candidate scene (of the plan's shape): does it assemble on the plan's
    branches with every step's condition at least ``min_condition``? Returns (mask, least
    condition per candidate), from one evaluation of the plan over all of them."""
    dims = _stack_dims([plan.dimensions(s) for s in scenes])
    m = evaluate(plan, dims=dims, array=True, upto=0)
    n = len(scenes)
    least = np.full(n, np.inf)
    for i, c in m.cond.items():
        least = np.minimum(least, np.broadcast_to(np.asarray(c, dtype=float), (n,)))
    ok = least >= min_condition
    if m.bad is not None:
        ok &= ~np.broadcast_to(np.asarray(m.bad, dtype=bool), (n,))
    ok &= np.isfinite(least)
    return ok, least


def _branches(plan) -> tuple:
    return tuple(getattr(st, "sigma", None) for st in plan.steps)


# --------------------------------------------------------------------------- generation


def _candidates(rng, sizes, total):
    """Index tuples in a random order without repeats: all of them for a small space, a
    sample for a large one."""
    if total <= ENUMERATE:
        for flat in rng.permutation(total):
            idx, rest = [], int(flat)
            for n in reversed(sizes):
                idx.append(rest % n)
                rest //= n
            yield tuple(reversed(idx))
        return
    seen = set()
    while len(seen) < min(total, MAX_TRIED):
        block = np.stack([rng.integers(0, n, size=256) for n in sizes], axis=1)
        for row in block:
            t = tuple(int(i) for i in row)
            if t not in seen:
                seen.add(t)
                yield t
                if len(seen) >= MAX_TRIED:
                    return


def _numbers(x):
    """The numbers in a nest of tuples, lists and dicts, in order."""
    if isinstance(x, dict):
        return [y for k in sorted(x, key=str) for y in _numbers(x[k])]
    if isinstance(x, (tuple, list)):
        return [y for v in x for y in _numbers(v)]
    if isinstance(x, (int, float)) and not isinstance(x, bool):
        return [float(x)]
    return []


def _problem(plan, sc):
    """What makes ``sc`` the problem it is, as numbers (SI): the plan's dimensions (ground,
    each step's, pin radii), the crank's speed and acceleration, its angle (over a turn),
    the loads."""
    d = plan.dimensions(sc)
    turn = 2 * math.pi
    theta = round(float(d.theta) % turn, 12) % turn
    loads = [(ld.target, ld.force, ld.torque) for ld in sc.loads]
    return (
        _numbers((d.ground, d.steps, d.radii, d.omega, d.alpha))
        + [theta]
        + _numbers([(f, t) for _, f, t in loads])
    )


def _same(a, b) -> bool:
    return len(a) == len(b) and all(
        abs(x - y) <= ROUNDING * max(1.0, abs(x), abs(y)) for x, y in zip(a, b)
    )


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
