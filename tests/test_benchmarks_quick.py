"""The chart script in its quick mode (few samples), so that it cannot rot.

It writes every chart (SVG and PNG) and the tables into a temporary folder; the numbers it
measures are checked against the tool's promise: the production path within 1e-9 of the
50-digit reference on the worked problems, and the lecture's algebraic formula failing as
A_x approaches d while the polygon construction does not.
"""

import importlib.util
import json
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def load_script():
    spec = importlib.util.spec_from_file_location(
        "accuracy_speed", ROOT / "benchmarks" / "accuracy_speed.py"
    )
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    return mod


def test_quick_run_writes_charts_and_tables(tmp_path):
    script = load_script()
    assert script.main(["--quick", "--out", str(tmp_path)]) == 0
    for stem in ("error_vs_time", "error_vs_singularity", "finite_difference_step"):
        svg = (tmp_path / f"{stem}.svg").read_text(encoding="utf-8")
        assert svg.lstrip().startswith("<?xml") and "</svg>" in svg
        assert (tmp_path / f"{stem}.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    res = json.loads((tmp_path / "results.json").read_text(encoding="utf-8"))
    prod = [r for r in res["worked"] if r["method"] == "production"]
    assert prod and all(r["error"] < 1e-9 for r in prod)
    hand = [r for r in res["worked"] if r["method"].startswith("hand drawing")]
    assert hand and all(1e-4 < r["error"] < 0.5 for r in hand)  # a pencil, not a solver
    ax = res["singular"]["algebraic: A_x to d"]["series"]
    closest = min(ax["production"])  # smallest |A_x - d|
    assert closest[1] < 1e-12
    assert min(ax["algebraic"])[1] > 1e-3  # the lecture's division by A_x - d
    md = (tmp_path / "results.md").read_text(encoding="utf-8")
    assert "| production |" in md and "95 % of drawings" in md
    # the stated error bound is charted next to the error, and holds at every point
    for case, d in res["singular"].items():
        bound = {x: b for x, b, _ in d["series"][script.BOUND]}
        for x, err, refused in d["series"]["production"]:
            if not refused:
                assert err <= bound[x], (case, x, err, bound[x])


def test_the_force_benchmark_runs_and_its_checks_hold(capsys):
    """``benchmarks/forces_speed.py --smoke``: the floor gives the force solve's numbers, the
    vectorised sweep's forces are the one-instant ones (its own checks, which raise); every
    figure it prints is a positive time. Nothing about how long anything took."""
    spec = importlib.util.spec_from_file_location(
        "forces_speed", ROOT / "benchmarks" / "forces_speed.py"
    )
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    assert mod.main(["--smoke", "--json"]) == 0
    out = capsys.readouterr().out
    res = json.loads(out[out.index("{") :])
    assert set(res["one"]) == set(mod.NAMES) == set(res["sweep"]) and res["angles"] == 360
    assert "floor" in res["one"]["fourbar_forces"]
    assert all(t > 0 for r in (*res["one"].values(), *res["sweep"].values()) for t in r.values())


def test_the_instruction_counts_count_what_they_say():
    """``benchmarks/instructions.py``: each case's call (run here once, without valgrind)
    computes what its name says: ``named`` gives the solve's dicts by name, the floor's
    numbers are the solve's (``speed.py`` checks them to 1e-12), the force case gives the
    worked problem's forces, a chain case counts its links."""

    spec = importlib.util.spec_from_file_location(
        "instructions", ROOT / "benchmarks" / "instructions.py"
    )
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    from polygon_method import load_scene, solve

    for case in mod.CASES:
        if case == "chain10001":  # (as chain1001, ten times longer)
            continue
        fn, per = mod._function(case)
        out = fn()
        assert per == (1001 if case == "chain1001" else 1), case
        if case == "named":
            sol = solve(load_scene(ROOT / "worked_problems" / "fourbar_image_points.toml"))
            assert out[0] == sol.P and out[2] == sol.A and set(out[3]) == {"AB", "BC", "CD"}
        if case == "forces":
            assert out.input_torque is not None
        if case == "worked":  # the seed's file read and solved anew: the loaded scene's motion
            sol = solve(load_scene(ROOT / "worked_problems" / "fourbar_image_points.toml"))
            assert out.P == sol.P and out.V == sol.V and out.plan is not sol.plan
        if case == "fresh":
            assert set(out.P) == {"A", "B", "C", "D"}
        if case == "tomllib":
            assert set(out) >= {"ground", "links", "input"}


def test_the_chain_benchmark_times_each_size_held_off_and_not(capsys):
    """``benchmarks/chain.py`` at two small sizes, one round: a row per size and its
    collections, the held-off road and the plan's functions unheld, and the plan given back
    its held-off functions after."""
    spec = importlib.util.spec_from_file_location("chain", ROOT / "benchmarks" / "chain.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    mod.BATCH_LINKS = 1000
    mod.main(["--rounds", "1", "403", "601"])
    out = capsys.readouterr().out
    lines = out.splitlines()
    rows = [x.split() for x in lines if x.lstrip().startswith(("403", "601")) and ":" not in x]
    assert [r[0] for r in rows] == ["403", "601", "403", "601"]  # times, then collections
    assert sum("links: read, planned and solved once" in x for x in lines) == 2
    assert rows[0][3] == "(1.000)" and "held" in rows[2] and "unheld" in rows[2]
    from polygon_method import parse_scene, solve
    from polygon_method.solver.compiler import compile_plan

    scene = parse_scene(mod._chain_text(403))
    solve(scene)
    assert len(compile_plan(scene).instant_steps) == 1  # 202 steps: held off
