"""Validate the error bound of every quantity against the 50-digit reference, on random
mechanisms near every singular family.

    python benchmarks/error_bounds.py                 # 2,000 mechanisms a family (90 s)
    python benchmarks/error_bounds.py --cases 20      # fewer
    python benchmarks/error_bounds.py --family toggle # one family (may be repeated)
    python benchmarks/error_bounds.py --edge          # and every kind at its edges
    python benchmarks/error_bounds.py --json FILE     # every number
    python benchmarks/error_bounds.py --exponents     # and how the errors grow with 1/c

For each family of ``near_singular.py`` (a toggle, a change point, a slider's dead centre,
a block near its lever's pivot, a toggle carried through a second dyad or a slider), each
mechanism is drawn with the condition of its singular step log-uniform between 1e-3 (the
edge of the refusal band) and 1 (every other one between 1e-3 and 2e-3), with pins at its
joints and a force and a torque as loads. It is solved, its ``error_bounds`` computed,
and every quantity (positions, velocities and accelerations of the points, omega and
alpha of the links, the sliders' sliding velocity, sliding acceleration and Coriolis
component, each pin's rubbing velocity, the input torque) is compared with the reference
(``tests/reference.py``, Newton on the loop-closure equations in mpmath) relative to the
same size as its bound.

Printed: per family and per kind of quantity, how many were compared, the largest
``error / bound`` (the bound holds where it is at most 1) and the median, 90th percentile
and largest ``bound / error`` over the quantities whose error is above the reference's own
noise (how pessimistic the bound is); per
mechanism (the "case"), the median of its largest bound over its largest error.
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import math
import random
import statistics
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

from near_singular import FAMILIES, make  # noqa: E402
from polygon_method.solver.errorbound import error_bounds, scales  # noqa: E402
from polygon_method.common.errors import PolygonMethodError  # noqa: E402
from polygon_method.scene import parse_scene  # noqa: E402
from polygon_method.motion.solution import solve  # noqa: E402

#: digits of the reference: the worst amplification near the refusal band is 1/c^3 = 1e9
#: (nine digits lost of the reference's too), and errors of 1e-16 are to be measured
DIGITS = 40
#: "just outside the refusal band": conditions from 1e-3 up to this
EDGE = 2e-3
#: an error at or below this (relative, as the bounds) is the reference's own noise, not a
#: rounding of the tool's: counted as exact, not as a bound/error of 1e25
NOISE = 10.0 ** -(DIGITS - 8)


def load_reference(digits=DIGITS):
    """tests/reference.py at ``digits`` significant digits."""
    spec = importlib.util.spec_from_file_location(
        "pm_reference_eb", ROOT / "tests" / "reference.py"
    )
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    mod.DIGITS = digits  # used in a context (compare_case): the global precision stays
    with mod.mpmath.workdps(digits):
        mod.NEWTON_TOL = mod.mpf(10) ** (-(digits - 6))
    return mod


def compare_case(sol, ref_mod, ref_scene=None):
    """[(kind, name, error, bound)] for every quantity of ``sol``: the error against the
    reference and the bound, both relative to the same size (the bound's ``scales``, of
    the reference's values). ``ref_scene``: the scene the reference solves, if not the
    solution's own (the same scene with its inputs at full precision)."""
    sc = sol.scene
    with ref_mod.mpmath.workdps(ref_mod.DIGITS):
        r = ref_mod.reference_solution(sc if ref_scene is None else ref_scene, sol.P)
    bounds = error_bounds(sol)

    def fl(d):
        return {
            k: (tuple(float(x) for x in v) if isinstance(v, tuple) else float(v))
            for k, v in d.items()
        }

    class _Ref:  # the reference's values, to size the errors the same way as the bounds
        scene = sc
        V, A, W, Al = (fl(r["velocities"]), fl(r["accelerations"]), fl(r["omega"]), fl(r["alpha"]))

    ref_scales = {k: float(v) for k, v in scales(_Ref).items()}

    def f(a, b):
        return abs(float(a - b))

    out = []
    for p in sc.point_names:
        if p in sc.ground:
            continue
        for kind, d, dr, b in (
            ("position", sol.P, r["positions"], bounds.P),
            ("velocity", sol.V, r["velocities"], bounds.V),
            ("acceleration", sol.A, r["accelerations"], bounds.A),
        ):
            e = math.hypot(f(d[p][0], dr[p][0]), f(d[p][1], dr[p][1])) / ref_scales[kind]
            out.append((kind, p, e, b[p]))
    for lk in sc.links:
        k = lk.key
        out.append(("omega", k, f(sol.W[k], r["omega"][k]) / ref_scales["omega"], bounds.W[k]))
        out.append(("alpha", k, f(sol.Al[k], r["alpha"][k]) / ref_scales["alpha"], bounds.Al[k]))
    for x, v in r["sliders"].items():
        bv, ba, bc = bounds.S[x]
        s = sol.S[x]
        out.append(("sliding velocity", x, f(s[0], v["vs"]) / ref_scales["velocity"], bv))
        out.append(("sliding acceleration", x, f(s[1], v["as"]) / ref_scales["acceleration"], ba))
        out.append(
            (
                "coriolis",
                x,
                math.hypot(f(s[2], v["coriolis"][0]), f(s[3], v["coriolis"][1]))
                / ref_scales["acceleration"],
                bc,
            )
        )
    for cyl in getattr(sc, "cylinders", ()):  # its rates from its two pins' motion
        key = cyl.key
        q = cylinder_rates(r, cyl.barrel, cyl.rod)
        out.append(("omega", key, f(sol.W[key], q["omega"]) / ref_scales["omega"], bounds.W[key]))
        out.append(("alpha", key, f(sol.Al[key], q["alpha"]) / ref_scales["alpha"], bounds.Al[key]))
        bv, ba, bc = bounds.S[key]
        s = sol.S[key]
        out.append(("sliding velocity", key, f(s[0], q["vs"]) / ref_scales["velocity"], bv))
        out.append(("sliding acceleration", key, f(s[1], q["as"]) / ref_scales["acceleration"], ba))
        out.append(
            (
                "coriolis",
                key,
                math.hypot(f(s[2], q["coriolis"][0]), f(s[3], q["coriolis"][1]))
                / ref_scales["acceleration"],
                bc,
            )
        )
    for pin in sol.plan.pins:
        radius = sol.rubbing[pin[0]].radius
        want = max(
            (abs(r["omega"].get(a, 0) - r["omega"].get(b, 0)) * radius for a, b in pin[5]),
            default=0,
        )
        got = sol.rubbing[pin[0]].rubbing_velocity
        out.append(
            ("rubbing", pin[0], f(got, want) / (ref_scales["omega"] * radius), bounds.rubbing(pin))
        )
    if sc.loads:
        total, size = 0, 0.0
        for load in sc.loads:
            if load.force is not None:
                v = r["velocities"][load.target]
                total += load.force[0] * v[0] + load.force[1] * v[1]
                size += math.hypot(*load.force) * ref_scales["velocity"]
            else:
                key = sc.link(load.target).key
                total += load.torque * r["omega"][key]
                size += abs(load.torque) * ref_scales["omega"]
        want = -total / sc.input.omega
        out.append(
            (
                "input torque",
                "T",
                f(sol.input_torque, want) / (size / abs(sc.input.omega)),
                bounds.torque(sc),
            )
        )
    return out


def cylinder_rates(r, barrel, rod):
    """A cylinder's omega, alpha, rate of extension ``n'`` and its rate ``n''``, and its
    Coriolis component, from a reference solution ``r`` (``d = R - K``, ``n = |d|``, ``u =
    d / n``): ``n' = d.v / n``, ``n'' = (v.v + d.a) / n - (d.v)^2 / n^3``, ``omega = d x
    v / n^2``, ``alpha = d x a / n^2 - 2 n' omega / n``, Coriolis ``2 omega n' perp(u)``
    (``v, a`` the rod's pin's motion relative to the barrel's)."""
    P, V, A = r["positions"], r["velocities"], r["accelerations"]
    d = (P[rod][0] - P[barrel][0], P[rod][1] - P[barrel][1])
    v = (V[rod][0] - V[barrel][0], V[rod][1] - V[barrel][1])
    a = (A[rod][0] - A[barrel][0], A[rod][1] - A[barrel][1])
    n2 = d[0] * d[0] + d[1] * d[1]
    n = n2**0.5
    dv = d[0] * v[0] + d[1] * v[1]
    vs = dv / n
    acc = (v[0] * v[0] + v[1] * v[1] + d[0] * a[0] + d[1] * a[1]) / n - dv * dv / (n2 * n)
    w = (d[0] * v[1] - d[1] * v[0]) / n2
    al = (d[0] * a[1] - d[1] * a[0]) / n2 - 2 * vs * w / n
    cor = (-2 * w * vs * d[1] / n, 2 * w * vs * d[0] / n)
    return {"omega": w, "alpha": al, "vs": vs, "as": acc, "coriolis": cor}


def run(cases, seed=1, digits=DIGITS, families=None, lo=-3.0, edge=False):
    """{family: [(condition, [(kind, name, error, bound)])]} for ``cases`` mechanisms of
    each family (refused ones are counted as ``None`` rows). ``edge``: the families of
    ``edge_families.py`` too (every step kind at its edges, the numbers as a user writes
    them), each compared with the reference of its numbers at full precision."""
    ref_mod = load_reference(digits)
    out = {}
    if edge:
        from edge_families import FAMILIES as ALL, make as make_any, reference_scene
    else:
        ALL, make_any, reference_scene = FAMILIES, make, None
    for fam in families or ALL:
        rng = random.Random(f"{seed}-{fam}")
        rows = out[fam] = []
        for i in range(cases):
            # every other one just outside the refusal band (condition 1e-3 to 2e-3)
            c = 10.0 ** rng.uniform(lo, 0.0 if i % 2 else lo + math.log10(2.0))
            text = make_any(fam, rng, c)
            try:
                sol = solve(parse_scene(text))
            except PolygonMethodError:
                rows.append((c, None))
                continue
            exact = None if reference_scene is None else reference_scene(sol, text, ref_mod)
            rows.append((min(sol.conditions.values()), compare_case(sol, ref_mod, exact)))
    return out


def summary(results) -> dict:
    """Per family and kind: n, largest error/bound, median, 90th percentile and largest
    bound/error (errors above the reference's :data:`NOISE`); per
    family: cases, refused, median over cases of largest bound / largest error."""
    table = {}
    for fam, rows in results.items():
        kinds = {}
        case_ratios, worst_ratio, refused = [], 0.0, 0
        edge = []  # just outside the refusal band: (largest error, largest bound)
        for cond, qs in rows:
            if qs is None:
                refused += 1
                continue
            if cond < EDGE:
                edge.append((max(q[2] for q in qs), max(q[3] for q in qs)))
            for kind, _, e, b in qs:
                kinds.setdefault(kind, []).append((e, b))
                worst_ratio = max(worst_ratio, e / b)
            emax = max(e for _, _, e, _ in qs)
            bmax = max(b for _, _, _, b in qs)
            if emax > NOISE:
                case_ratios.append(bmax / emax)
        per = {}
        for kind, eb in kinds.items():
            nz = sorted(b / e for e, b in eb if e > NOISE)
            per[kind] = {
                "n": len(eb),
                "max_error_over_bound": max(e / b for e, b in eb),
                "median_bound_over_error": statistics.median(nz) if nz else None,
                "p90_bound_over_error": nz[int(0.9 * (len(nz) - 1))] if nz else None,
                "max_bound_over_error": nz[-1] if nz else None,
                "exact": len(eb) - len(nz),
            }
        table[fam] = {
            "cases": len(rows) - refused,
            "refused": refused,
            "max_error_over_bound": worst_ratio,
            "median_case_bound_over_error": (
                statistics.median(case_ratios) if case_ratios else None
            ),
            "max_case_bound_over_error": max(case_ratios, default=None),
            "edge": {
                "cases": len(edge),
                "median_largest_error": (statistics.median(e for e, _ in edge) if edge else None),
                "median_largest_bound": (statistics.median(b for _, b in edge) if edge else None),
                "max_error_over_bound": max((e / b for e, b in edge), default=None),
            },
            "kinds": per,
        }
    return table


def growth(results, kinds=("position", "velocity", "acceleration", "omega", "alpha")):
    """{family: {kind: p}}: how the largest errors grow as the condition falls, as eps/c^p:
    the 90th percentile of each mechanism's largest error of that kind, among those with
    the condition from 1e-3 to EDGE and those from 0.1 to 1, against the geometric mean of
    their conditions."""
    out = {}
    for fam, rows in results.items():
        out[fam] = {}
        for kind in kinds:
            lo, hi = [], []
            for c, qs in rows:
                e = max((q[2] for q in qs or () if q[0] == kind), default=0.0)
                if e > 0 and c < EDGE:
                    lo.append((c, e))
                elif e > 0 and 0.1 <= c < 1.0:
                    hi.append((c, e))
            if len(lo) < 10 or len(hi) < 10:
                continue

            def q90(v):
                v = sorted(x[1] for x in v)
                return v[int(0.9 * len(v))]

            def gmean(v):
                return math.exp(statistics.mean(math.log(x[0]) for x in v))

            out[fam][kind] = math.log(q90(lo) / q90(hi)) / math.log(gmean(hi) / gmean(lo))
    return out


def markdown(table) -> str:
    lines = [
        "| family | mechanisms | largest error / bound | median (largest bound / largest "
        "error) | largest (largest bound / largest error) | condition "
        f"{EDGE:g} down to the band: mechanisms, median largest error, median largest "
        "bound |",
        "| --- | --- | --- | --- | --- | --- |",
    ]
    for fam, t in table.items():
        e = t["edge"]
        edge = (
            f"{e['cases']}, {e['median_largest_error']:.2g}, {e['median_largest_bound']:.2g}"
            if e["cases"]
            else "-"
        )
        lines.append(
            f"| {fam} | {t['cases']} | {t['max_error_over_bound']:.2g} | "
            f"{t['median_case_bound_over_error']:.3g} | "
            f"{t['max_case_bound_over_error']:.3g} | {edge} |"
        )
    lines += [
        "",
        "| family | quantity | compared | largest error / bound | bound / error: "
        "median, 90th percentile, largest | error 0 (to the reference's digits) |",
        "| --- | --- | --- | --- | --- | --- |",
    ]

    def g(x):
        return "-" if x is None else f"{x:.3g}"

    for fam, t in table.items():
        for kind, k in t["kinds"].items():
            ratios = ", ".join(
                g(k[q])
                for q in ("median_bound_over_error", "p90_bound_over_error", "max_bound_over_error")
            )
            lines.append(
                f"| {fam} | {kind} | {k['n']} | {k['max_error_over_bound']:.2g} | "
                f"{ratios} | {k['exact']} |"
            )
    return "\n".join(lines)


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    p.add_argument("--cases", type=int, default=2000, help="mechanisms per family")
    p.add_argument("--seed", type=int, default=1)
    p.add_argument("--family", action="append", help="only this family (may be repeated)")
    p.add_argument(
        "--edge",
        action="store_true",
        help="also every step kind at its edges (edge_families.py): flat "
        "triangles, short sides, paths a hair off a right angle or through "
        "a far point, two ill-conditioned steps in a row, given motion, "
        "pegs, cylinders, rolling, triads, yokes",
    )
    p.add_argument("--json", help="write every number here")
    p.add_argument(
        "--exponents",
        action="store_true",
        help="also print how the errors grow: p of eps/c^p, per family and kind",
    )
    args = p.parse_args(argv)
    t0 = time.perf_counter()
    results = run(args.cases, args.seed, families=args.family, edge=args.edge)
    table = summary(results)
    print(markdown(table))
    if args.exponents:
        kinds = ("position", "velocity", "acceleration", "omega", "alpha")
        print("\n| family | " + " | ".join(kinds) + " |\n| --- |" + " --- |" * len(kinds))
        for fam, ps in growth(results, kinds).items():
            print(
                f"| {fam} | " + " | ".join(f"{ps[k]:.1f}" if k in ps else "-" for k in kinds) + " |"
            )
    print(
        f"\n{sum(t['cases'] for t in table.values())} mechanisms, {time.perf_counter() - t0:.0f} s"
    )
    if args.json:
        Path(args.json).write_text(
            json.dumps(
                {
                    "summary": table,
                    "cases": {
                        fam: [(c, None if qs is None else [list(q) for q in qs]) for c, qs in rows]
                        for fam, rows in results.items()
                    },
                }
            )
        )
    held = all(t["max_error_over_bound"] <= 1 for t in table.values())
    return 0 if held else 1


if __name__ == "__main__":
    sys.exit(main())
