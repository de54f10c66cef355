"""Accuracy against speed, and accuracy near singular positions, for every method.

    python benchmarks/accuracy_speed.py            # full run (a few minutes)
    python benchmarks/accuracy_speed.py --quick    # few samples (CI runs this)
    python benchmarks/accuracy_speed.py --out DIR  # charts elsewhere (default benchmarks/charts)
    python benchmarks/accuracy_speed.py --stability-only   # only the chart near singular positions

Writes, into the output folder:

* ``error_vs_time.svg/.png``: error against time per solve, one marker per method, one
  point per worked problem;
* ``error_vs_singularity.svg/.png``: error against the distance to a singular position,
  per method: a toggle (transmission angle to 0), ``A_x`` to ``d`` (the algebraic method's
  division), a slider-crank at dead centre, a parallelogram at its change point, with the
  error bound the tool states for its own answers (dashed) next to its actual error;
* ``finite_difference_step.svg/.png``: the finite-difference step-size trade-off;
* ``results.json`` (every number) and ``results.md`` (the tables quoted in
  docs/accuracy.md, with the hand-drawing errors per quantity).

The error of a result is the largest error of any of its quantities, each relative to the
size of that kind of quantity over the mechanism at that instant
(:func:`polygon_method.methods.compare`), against a 50-digit mpmath reference (Newton on
the loop-closure equations, ``tests/reference.py``). A method that refuses (raises a clear
error) is drawn as an open marker at the top of the chart.
"""

from __future__ import annotations

import argparse
import glob
import importlib.util
import json
import math
import sys
import time
import timeit
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(HERE))

import methods as M  # noqa: E402
from polygon_method.common.errors import PolygonMethodError  # noqa: E402
from polygon_method.scene import load_scene, parse_scene  # noqa: E402

REFUSED = 10.0  # where a refusal is drawn (errors are never that large)
BOUND = "production: stated error bound"  # the series of the tool's own error bound
FLOOR = 1e-17  # an error of exactly 0 is drawn here (log scale)
HAND_SECONDS = 1800.0  # a careful hand drawing of both polygons: about half an hour
PENCIL = (0.25, 0.25)  # mm, deg: one standard deviation of each line drawn or read


def load_reference():
    """tests/reference.py, imported by path (the benchmark is not a test)."""
    spec = importlib.util.spec_from_file_location("pm_reference", ROOT / "tests" / "reference.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


REF = None


def reference(scene, guess):
    """The 50-digit reference as a Kinematics, on the branch nearest ``guess``."""
    r = REF.reference_solution(scene, guess)
    return M.Kinematics(
        "reference",
        r["positions"],
        r["velocities"],
        r["accelerations"],
        r["omega"],
        r["alpha"],
        {k: (v["vs"], v["as"]) for k, v in r["sliders"].items()},
    )


def peers():
    """The optional PyPI peers that are installed (name -> function)."""
    out = {}
    try:
        import peers as pe
    except ImportError:
        return out
    for name, fn, mod in (
        ("mechanism (PyPI)", pe.mechanism_fourbar, "mechanism"),
        ("pylinkage (PyPI)", pe.pylinkage_fourbar, "pylinkage"),
    ):
        if importlib.util.find_spec(mod) is not None:
            out[name] = fn
    return out


def per_solve(fn, quick):
    """Seconds per call: the best of a few repeats of an auto-ranged loop."""
    t = timeit.Timer(fn)
    if quick:
        return min(t.repeat(2, 2)) / 2
    n, _ = t.autorange()
    return min(t.repeat(5, n)) / n


def methods_for(scene, quick, peer_fns):
    """(name, callable returning Kinematics) of each method that applies to ``scene``."""
    out = [(name, (lambda f=f: f(scene))) for name, f in M.METHODS.items() if name != "algebraic"]
    if M.is_fourbar(scene) is not None:
        out.insert(2, ("algebraic", lambda: M.algebraic_fourbar(scene)))
        guess = M.production(scene)
        for name, fn in peer_fns.items():
            out.append((name, (lambda fn=fn: fn(scene, guess))))
    return out


def sweep_per_position(scene, n):
    """The production kernels on a whole sweep (numpy): time per position."""
    import numpy as np
    from polygon_method.solver.compiler import compile_plan
    from polygon_method.solver.plan import Context

    plan = compile_plan(scene)
    inp = scene.input
    th = inp.angle + np.linspace(-1e-3, 1e-3, n)

    def run():
        ctx = Context(th, inp.omega, inp.alpha, array=True)
        return plan.evaluate(ctx)

    return run


# --------------------------------------------------------------------------- worked problems


def worked(quick, drawings, peer_fns):
    files = sorted(glob.glob(str(ROOT / "worked_problems" / "*.toml")))
    cranked = []
    for f in files:  # the other methods of the chart (hand drawing, peers) take a crank
        try:
            sc = load_scene(f)
            block = sc.input.block
            geared = bool(sc.rolling) or sc.input.second is not None
        except PolygonMethodError:
            block, geared = None, False  # (said below, where it is skipped)
        if block is not None:
            print(
                f"skip {Path(f).name}: driven by block {block}, and the other methods take a crank",
                file=sys.stderr,
            )
        elif geared:
            print(
                f"skip {Path(f).name}: gears or a second crank, which the other methods "
                "do not draw",
                file=sys.stderr,
            )
        else:
            cranked.append(f)
    files = cranked
    if quick:
        files = files[:3]
    rows = []
    for f in files:
        try:
            scene = load_scene(f)
            prod = M.production(scene)
        except PolygonMethodError as exc:
            print(f"skip {Path(f).name}: {exc.one_line()}", file=sys.stderr)
            continue
        ref = reference(scene, prod.P)
        name = Path(f).stem
        for mname, call in methods_for(scene, quick, peer_fns):
            try:
                kin = call()
                err = M.compare(kin, ref, scene)
                secs = per_solve(call, quick)
            except Exception as exc:  # noqa: BLE001 (any failure of a method: refused)
                rows.append(
                    dict(problem=name, method=mname, error=None, seconds=None, refused=str(exc))
                )
                continue
            rows.append(
                dict(
                    problem=name,
                    method=mname,
                    error=float(err["all"]),
                    seconds=secs,
                    kinds={k: float(v) for k, v in err.items()},
                )
            )
        # the production kernels on a numpy sweep: per position
        import numpy as np

        n = 64 if quick else 4096
        run = sweep_per_position(scene, n)
        secs = per_solve(run, quick) / n
        P, V, A, W, Al, S = run()
        mid = n // 2  # not at the instant: use its own reference
        th_mid = float(np.linspace(-1e-3, 1e-3, n)[mid])
        sc2 = _at_angle(scene, scene.input.angle + th_mid)
        ref2 = reference(sc2, M.production(sc2).P)
        kin = M.Kinematics(
            "sweep",
            {
                k: (float(np.broadcast_to(x, n)[mid]), float(np.broadcast_to(y, n)[mid]))
                for k, (x, y) in P.items()
            },
            {
                k: (float(np.broadcast_to(x, n)[mid]), float(np.broadcast_to(y, n)[mid]))
                for k, (x, y) in V.items()
            },
            {
                k: (float(np.broadcast_to(x, n)[mid]), float(np.broadcast_to(y, n)[mid]))
                for k, (x, y) in A.items()
            },
            {k: float(np.broadcast_to(v, n)[mid]) for k, v in W.items()},
            {k: float(np.broadcast_to(v, n)[mid]) for k, v in Al.items()},
        )
        rows.append(
            dict(
                problem=name,
                method="production, numpy sweep (per position)",
                error=float(M.compare(kin, ref2, sc2)["all"]),
                seconds=secs,
            )
        )
        hd = M.hand_drawing(scene, drawings, length_mm=PENCIL[0], angle_deg=PENCIL[1])
        e = M.compare(hd, ref, scene)["all"]
        rows.append(
            dict(
                problem=name,
                method="hand drawing (median of %d)" % drawings,
                error=float(np.median(e)),
                seconds=HAND_SECONDS,
                p95=float(np.percentile(e, 95)),
                p05=float(np.percentile(e, 5)),
            )
        )
    return rows


def _at_angle(scene, angle):
    """The same scene at another crank angle (rad)."""
    from dataclasses import replace

    return replace(scene, input=replace(scene.input, angle=angle))


# --------------------------------------------------------------------------- singular cases

FOURBAR = """
[ground]
A = [0, 0]
D = [{d}, 0]
[links]
AB = {a}
BC = {b}
CD = {c}
[assembly]
C = {asm}
[input]
crank = "AB"
angle = "{angle!r} rad"
speed = "10 rad/s ccw"
acceleration = "5 rad/s^2 ccw"
"""

SLIDER = """
[ground]
O = [0, 0]
[links]
OA = 40
AB = 140
[sliders]
B = {{ path = "horizontal" }}
[input]
crank = "OA"
angle = "{angle!r} rad"
speed = "300 rpm ccw"
acceleration = "50 rad/s^2 ccw"
"""


def _fourbar(a, b, c, d, angle, asm='"above"'):
    return parse_scene(FOURBAR.format(a=a, b=b, c=c, d=d, angle=angle, asm=asm))


def transmission_deg(P, B, C, D):
    """Transmission angle at C (acute angle between CB and CD), degrees."""
    u = (float(P[B][0] - P[C][0]), float(P[B][1] - P[C][1]))
    v = (float(P[D][0] - P[C][0]), float(P[D][1] - P[C][1]))
    s = abs(u[0] * v[1] - u[1] * v[0]) / (math.hypot(*u) * math.hypot(*v))
    return math.degrees(math.asin(min(s, 1.0)))


def singular_cases(quick):
    """name -> (x label, [(x, scene, reference guess)])."""
    ks = [1, 3, 6] if quick else [k / 2 for k in range(1, 19)]
    cases = {}
    # 1. toggle: a triple rocker driven to its limit (BC and CD in line at 180 deg)
    pts = []
    for k in ks:
        ang = math.pi - 10.0 ** (-k)
        sc = _fourbar(20, 70, 50, 100, ang)
        pts.append((None, sc, _toggle_guess(ang)))
    cases["toggle: transmission angle to 0"] = ("transmission angle at C (deg)", pts)
    # 2. A_x -> d: a = 130, d = 100: A_x = d at cos(theta) = 100/130 (a regular position)
    th0 = math.acos(100 / 130)
    pts = []
    for k in ks:
        for sgn in (1,):
            ang = th0 + sgn * 10.0 ** (-k - 1)
            sc = _fourbar(130, 60, 50, 100, ang, asm='"right"')
            pts.append((abs(130 * math.cos(ang) - 100) / 100, sc, M.production(sc).P))
    cases["algebraic: A_x to d"] = ("|A_x - d| / d", pts)
    # 3. slider-crank near inner dead centre
    pts = []
    for k in ks:
        sc = parse_scene(SLIDER.format(angle=10.0 ** (-k)))
        pts.append((math.degrees(10.0 ** (-k)), sc, M.production(sc).P))
    cases["slider-crank at dead centre"] = ("crank angle from dead centre (deg)", pts)
    # 4. parallelogram a = c = 40, b = d = 100 near its change point (0 deg)
    pts = []
    for k in ks:
        ang = 10.0 ** (-k)
        bx, by = 0.04 * math.cos(ang), 0.04 * math.sin(ang)
        g = {"A": (0.0, 0.0), "D": (0.1, 0.0), "B": (bx, by), "C": (bx + 0.1, by)}
        sc = _fourbar(40, 100, 40, 100, ang, asm=f"[{(bx + 0.1) * 1e3!r}, {by * 1e3!r}]")
        pts.append((math.degrees(ang), sc, g))
    cases["parallelogram at its change point"] = ("crank angle from the change point (deg)", pts)
    return cases


def _toggle_guess(ang):
    """C above BD by the two circles (AB = 20, BC = 70, CD = 50, AD = 100); a tiny offset
    keeps the reference's Newton off the exactly singular straight line."""
    bx, by = 0.02 * math.cos(ang), 0.02 * math.sin(ang)
    ex, ey = 0.1 - bx, -by
    e = math.hypot(ex, ey)
    along = (0.07**2 - 0.05**2 + e * e) / (2 * e)
    h = max(math.sqrt(max(0.07**2 - along * along, 0.0)), 1e-9)
    ux, uy = ex / e, ey / e
    cx, cy = bx + along * ux - h * uy, by + along * uy + h * ux
    if cy < by + (cx - bx) * ey / ex:
        cx, cy = bx + along * ux + h * uy, by + along * uy - h * ux
    return {"A": (0.0, 0.0), "D": (0.1, 0.0), "B": (bx, by), "C": (cx, cy)}


def singular(quick, drawings, peer_fns):
    out = {}
    for case, (xlabel, pts) in singular_cases(quick).items():
        series = {}
        for x, scene, guess in pts:
            try:
                ref = reference(scene, guess)
            except (ArithmeticError, ZeroDivisionError):
                continue
            if x is None:
                x = transmission_deg(ref.P, "B", "C", "D")
            calls = [(n, (lambda f=f: f(scene))) for n, f in M.METHODS.items()]
            if M.is_fourbar(scene) is not None:
                g = M.Kinematics(
                    "guess", {k: tuple(map(float, v)) for k, v in ref.P.items()}, {}, {}, {}, {}
                )
                calls += [(n, (lambda fn=fn: fn(scene, g))) for n, fn in peer_fns.items()]
            for name, call in calls:
                if name == "algebraic" and M.is_fourbar(scene) is None:
                    continue
                try:
                    kin = call()
                    e = float(M.compare(kin, ref, scene)["all"])
                    if not math.isfinite(e):
                        e = REFUSED
                    series.setdefault(name, []).append((x, e, False))
                except Exception:  # noqa: BLE001 (any failure of a method: refused)
                    series.setdefault(name, []).append((x, REFUSED, True))
            try:  # the bound the tool states for its own answer, next to its error
                from polygon_method.solver.errorbound import error_bounds
                from polygon_method.motion.solution import solve

                b = float(error_bounds(solve(scene)).worst)
                series.setdefault(BOUND, []).append((x, b, False))
            except PolygonMethodError:
                pass
            try:
                import numpy as np

                hd = M.hand_drawing(scene, drawings, length_mm=PENCIL[0], angle_deg=PENCIL[1])
                e = M.compare(hd, ref, scene)["all"]
                e = float(np.median(e)) if np.all(np.isfinite(e)) else REFUSED
                series.setdefault("hand drawing (median)", []).append((x, e, False))
            except PolygonMethodError:
                series.setdefault("hand drawing (median)", []).append((x, REFUSED, True))
        out[case] = {"xlabel": xlabel, "series": series}
    return out


# --------------------------------------------------------------------------- FD step


def fd_steps(quick):
    scene = load_scene(_seed_fourbar())
    ref = reference(scene, M.production(scene).P)
    w = abs(scene.input.omega)
    hs = [10.0 ** (-k) / w for k in ([1, 4, 7] if quick else [x / 2 for x in range(2, 21)])]
    rows = []
    for h in hs:
        try:
            e = M.compare(M.finite_differences(scene, h), ref, scene)
        except PolygonMethodError:
            continue
        rows.append(
            dict(
                h=h,
                crank_step_deg=math.degrees(h * w),
                velocity=float(max(e["velocity"], e["omega"])),
                acceleration=float(max(e["acceleration"], e["alpha"])),
            )
        )
    return rows


def _seed_fourbar():
    f = ROOT / "worked_problems" / "fourbar_image_points.toml"
    if f.exists():
        return f
    return sorted(glob.glob(str(ROOT / "worked_problems" / "*.toml")))[0]


# --------------------------------------------------------------------------- hand drawing


def hand_table(drawings):
    """Per quantity: median and 95th percentile of |error| / |value| over the drawings."""
    import numpy as np

    out = {}
    for f in ("fourbar_image_points", "engine_analytical", "crank_slotted_lever"):
        path = ROOT / "worked_problems" / f"{f}.toml"
        if not path.exists():
            continue
        scene = load_scene(path)
        ref = reference(scene, M.production(scene).P)
        hd = M.hand_drawing(scene, drawings, length_mm=PENCIL[0], angle_deg=PENCIL[1])
        rows = []

        def add(q, val, true):
            true = float(true)
            if abs(true) < 1e-9:
                return
            rel = np.abs(np.asarray(val) - true) / abs(true)
            rows.append((q, true, float(np.median(rel)), float(np.percentile(rel, 95))))

        for p in scene.point_names:
            if p in scene.ground:
                continue
            tv = math.hypot(*map(float, ref.V[p]))
            add(f"v_{p}", np.hypot(*hd.V[p]), tv)
        for lk in scene.links:
            if (
                lk.key in hd.W
                and not (lk.p in scene.ground and lk.q in scene.ground)
                and lk.key != scene.link(scene.input.crank).key
            ):
                add(f"omega_{lk.key}", hd.W[lk.key], ref.W[lk.key])
        for p in scene.point_names:
            if p in scene.ground:
                continue
            add(f"a_{p}", np.hypot(*hd.A[p]), math.hypot(*map(float, ref.A[p])))
        for lk in scene.links:
            if (
                lk.key in hd.Al
                and not (lk.p in scene.ground and lk.q in scene.ground)
                and lk.key != scene.link(scene.input.crank).key
            ):
                add(f"alpha_{lk.key}", hd.Al[lk.key], ref.Al[lk.key])
        for k, (vs, a_s) in ref.S.items():
            if k in hd.S:
                add(f"vs_{k}", hd.S[k][0], vs)
        sp, sv, sa = (hd.info["scales"][k] for k in hd.info["scales"])
        out[f] = dict(
            scales=dict(
                space=f"1 cm = {sp * 10:g} m",
                velocity=f"1 cm = {sv * 10:g} m/s",
                acceleration=f"1 cm = {sa * 10:g} m/s^2",
            ),
            rows=rows,
        )
    return out


# --------------------------------------------------------------------------- charts

STYLE = {
    "production": ("o", "#1f77b4"),
    "production, numpy sweep (per position)": ("s", "#17becf"),
    "shapely": ("D", "#ff7f0e"),
    "algebraic": ("^", "#2ca02c"),
    "Newton-Raphson": ("v", "#d62728"),
    "finite differences": ("P", "#9467bd"),
    "mechanism (PyPI)": ("X", "#8c564b"),
    "pylinkage (PyPI)": ("*", "#e377c2"),
    "hand drawing": ("h", "#7f7f7f"),
}


def _style(name):
    for k, v in STYLE.items():
        if name.startswith(k) and (k != "production" or name == "production"):
            return v
    return ("o", "black")


def _save(fig, out, stem):
    fig.savefig(out / f"{stem}.svg", bbox_inches="tight")
    fig.savefig(out / f"{stem}.png", dpi=110, bbox_inches="tight")


def chart_time(rows, out, plt):
    fig, ax = plt.subplots(figsize=(8, 5.5))
    seen = set()
    for r in rows:
        if r.get("error") is None:
            continue
        m, c = _style(r["method"])
        label = r["method"] if r["method"] not in seen else None
        seen.add(r["method"])
        y = max(r["error"], FLOOR)
        if "p95" in r:
            ax.errorbar(
                [r["seconds"]],
                [y],
                yerr=[[y - max(r["p05"], FLOOR)], [r["p95"] - y]],
                fmt=m,
                color=c,
                label=label,
                alpha=0.7,
                capsize=3,
            )
        else:
            ax.plot([r["seconds"]], [y], m, color=c, label=label, alpha=0.8, ms=8)
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.axhline(1e-9, color="0.6", lw=0.8, ls="--")
    ax.text(ax.get_xlim()[0], 1.3e-9, " 1e-9: the tool's promise", color="0.4", fontsize=8)
    ax.set_xlabel("time per solve (s); hand drawing: a nominal half hour")
    ax.set_ylabel("largest error / size of that quantity")
    ax.set_title("Worked problems: error against time per solve (one point per problem)")
    ax.legend(fontsize=8, loc="center left", bbox_to_anchor=(1.0, 0.5))
    ax.grid(True, which="major", alpha=0.3)
    _save(fig, out, "error_vs_time")
    plt.close(fig)


def chart_singular(data, out, plt):
    fig, axes = plt.subplots(2, 2, figsize=(12, 9))
    for ax, (case, d) in zip(axes.flat, data.items()):
        for name, pts in d["series"].items():
            m, c = _style(name)
            pts = sorted(pts)
            if name == BOUND:  # a dashed line in the production's colour, no markers
                ax.plot(
                    [p[0] for p in pts],
                    [max(p[1], FLOOR) for p in pts],
                    "--",
                    color=_style("production")[1],
                    lw=1.6,
                    label=name,
                )
                continue
            xs = [p[0] for p in pts]
            ys = [max(p[1], FLOOR) for p in pts]
            ax.plot(xs, ys, "-", color=c, alpha=0.5, lw=1)
            ok = [(x, y) for (x, y, r) in zip(xs, ys, [p[2] for p in pts]) if not r]
            bad = [(x, y) for (x, y, r) in zip(xs, ys, [p[2] for p in pts]) if r]
            if ok:
                ax.plot(*zip(*ok), m, color=c, label=name, ms=6, alpha=0.85)
            if bad:
                ax.plot(*zip(*bad), m, mfc="none", color=c, ms=9, label=None if ok else name)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(FLOOR / 2, REFUSED * 5)
        ax.axhline(1e-9, color="0.6", lw=0.8, ls="--")
        ax.set_xlabel(d["xlabel"] + "  (singular position at the left)")
        ax.set_ylabel("largest error / size of that quantity")
        ax.set_title(case, fontsize=10)
        ax.grid(True, alpha=0.3)
        ax.invert_xaxis()
    handles, labels = [], []
    for ax in axes.flat:
        for h, lab in zip(*ax.get_legend_handles_labels()):
            if lab not in labels:
                handles.append(h)
                labels.append(lab)
    fig.legend(handles, labels, loc="lower center", ncol=4, fontsize=8)
    fig.suptitle(
        "Error near singular positions (open marker at the top: the method refused with an error)",
        fontsize=11,
    )
    fig.tight_layout(rect=(0, 0.06, 1, 0.97))
    _save(fig, out, "error_vs_singularity")
    plt.close(fig)


def chart_fd(rows, out, plt):
    fig, ax = plt.subplots(figsize=(6.5, 4.5))
    xs = [r["crank_step_deg"] for r in rows]
    ax.plot(xs, [max(r["velocity"], FLOOR) for r in rows], "o-", label="velocities, omega")
    ax.plot(xs, [max(r["acceleration"], FLOOR) for r in rows], "s-", label="accelerations, alpha")
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("step (deg of crank turn, omega h)")
    ax.set_ylabel("largest error / size of that quantity")
    ax.set_title("Finite differences: truncation (right) against rounding (left)")
    ax.grid(True, alpha=0.3)
    ax.legend()
    _save(fig, out, "finite_difference_step")
    plt.close(fig)


# --------------------------------------------------------------------------- report


def markdown(rows, sing, fd, hand, drawings, peer_fns):
    lines = ["# Accuracy and speed: measured numbers", ""]
    lines.append(
        "Largest error of any quantity, relative to the size of that kind of quantity "
        "over the mechanism; time per solve (best of repeats)."
    )
    lines.append("")
    methods = []
    for r in rows:
        if r["method"] not in methods:
            methods.append(r["method"])
    lines.append("| method | median error | worst error | median time per solve |")
    lines.append("| --- | --- | --- | --- |")
    for m in methods:
        rs = [r for r in rows if r["method"] == m and r.get("error") is not None]
        if not rs:
            continue
        es = sorted(r["error"] for r in rs)
        ts = sorted(r["seconds"] for r in rs)
        t = ts[len(ts) // 2]
        tt = "about 30 min (nominal)" if m.startswith("hand") else _fmt_t(t)
        lines.append(f"| {m} | {es[len(es) // 2]:.1e} | {es[-1]:.1e} | {tt} |")
    if not peer_fns:
        lines.append("")
        lines.append("(`mechanism` and `pylinkage` are not installed: skipped.)")
    lines.append("")
    lines.append("## Near singular positions")
    for case, d in sing.items():
        lines.append("")
        lines.append(f"### {case}")
        lines.append("")
        names = list(d["series"])
        xs = sorted({p[0] for s in d["series"].values() for p in s}, reverse=True)
        lines.append(f"| {d['xlabel']} | " + " | ".join(names) + " |")
        lines.append("| --- " * (len(names) + 1) + "|")
        for x in xs:
            cells = []
            for n in names:
                v = next(((e, r) for (xx, e, r) in d["series"][n] if xx == x), None)
                cells.append("" if v is None else ("refused" if v[1] else f"{v[0]:.1e}"))
            lines.append(f"| {x:.3g} | " + " | ".join(cells) + " |")
    lines.append("")
    lines.append("## Finite differences: step size")
    lines.append("")
    lines.append("| crank step (deg) | velocity error | acceleration error |")
    lines.append("| --- | --- | --- |")
    for r in fd:
        lines.append(
            f"| {r['crank_step_deg']:.3g} | {r['velocity']:.1e} | {r['acceleration']:.1e} |"
        )
    lines.append("")
    lines.append(
        f"## Hand drawing: {drawings} simulated drawings, pencil error "
        f"{PENCIL[0]} mm and {PENCIL[1]} deg (one standard deviation)"
    )
    for name, h in hand.items():
        lines.append("")
        sc = h["scales"]
        lines.append(
            f"### {name} (space {sc['space']}, velocity {sc['velocity']}, "
            f"acceleration {sc['acceleration']})"
        )
        lines.append("")
        lines.append("| quantity | true value | median error | 95 % of drawings within |")
        lines.append("| --- | --- | --- | --- |")
        for q, true, med, p95 in h["rows"]:
            lines.append(f"| {q} | {true:.4g} | {100 * med:.2g} % | {100 * p95:.2g} % |")
    return "\n".join(lines) + "\n"


def _fmt_t(t):
    if t < 1e-6:
        return f"{t * 1e9:.0f} ns"
    if t < 1e-3:
        return f"{t * 1e6:.1f} us"
    return f"{t * 1e3:.2f} ms"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="few samples (CI)")
    ap.add_argument("--out", default=str(HERE / "charts"), help="output folder")
    ap.add_argument("--drawings", type=int, help="simulated hand drawings per case")
    ap.add_argument(
        "--stability-only",
        action="store_true",
        help="redraw only the chart near singular positions (and its data in results.json)",
    )
    args = ap.parse_args(argv)
    global REF
    REF = load_reference()
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    # reproducible SVG ids, text as text: for these charts only (set globally, they were
    # left behind for whatever a caller drew next in the same process)
    with matplotlib.rc_context({"svg.hashsalt": "polygon-method", "svg.fonttype": "none"}):
        return _charts(args, plt)


def _charts(args, plt) -> int:
    """The run of :func:`main` after its arguments and matplotlib's settings."""
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    drawings = args.drawings or (50 if args.quick else 2000)
    peer_fns = {} if args.quick else peers()
    t0 = time.perf_counter()
    if args.stability_only:
        sing = singular(args.quick, drawings, peer_fns)
        chart_singular(sing, out, plt)
        res = out / "results.json"
        if res.exists():
            data = json.loads(res.read_text(encoding="utf-8"))
            data["singular"] = sing
            res.write_text(json.dumps(data, indent=1, default=str), encoding="utf-8")
        print(f"stability chart in {out} ({time.perf_counter() - t0:.1f} s)")
        return 0
    rows = worked(args.quick, drawings, peer_fns)
    sing = singular(args.quick, drawings, peer_fns)
    fd = fd_steps(args.quick)
    hand = hand_table(drawings)
    chart_time(rows, out, plt)
    chart_singular(sing, out, plt)
    chart_fd(fd, out, plt)
    md = markdown(rows, sing, fd, hand, drawings, peer_fns)
    (out / "results.md").write_text(md, encoding="utf-8")
    (out / "results.json").write_text(
        json.dumps(
            {
                "worked": rows,
                "singular": sing,
                "finite_differences": fd,
                "hand_drawing": hand,
                "pencil": {"length_mm": PENCIL[0], "angle_deg": PENCIL[1]},
                "drawings": drawings,
                "quick": args.quick,
            },
            indent=1,
            default=str,
        ),
        encoding="utf-8",
    )
    print(f"charts and tables in {out} ({time.perf_counter() - t0:.1f} s)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
