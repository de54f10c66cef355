"""Class-III groups (triads): a plate whose three vertices are each linked to a known
point, found together (polygon_method/steps/triad.py).

Against independent references: the 50-digit Newton solve of the scene's constraints
(tests/reference.py) at angles round the turn, finite differences of the swept positions
in time, the loop-closure residual of every swept position, the condition against numpy's
determinant of the normalised Jacobian, the assemblies found against a brute-force
search, the error bounds near a limit. The branch stated by [assembly] is kept, and
followed over the crank's turn.
"""

import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
from mpmath import mpf

from polygon_method import load_scene, parse_scene, solve
from polygon_method.solver.compiler import compile_plan
from polygon_method.common.errors import AssemblyError
from polygon_method.steps import triad
from polygon_method.solver.tracking import Sweeper, run_arrays
from reference import reference_solution
from textbook_corpus import worst_error

ROOT = Path(__file__).resolve().parent.parent
SIX = ROOT / "tests" / "textbook" / "class3_six_bar.toml"
WORKED = ROOT / "worked_problems" / "class3_six_bar.toml"


def at(text, angle):
    return re.sub(r"(?m)^angle = .*$", f"angle = {angle}", text)


def test_the_plan_has_one_triad_step_finding_three_points():
    plan = compile_plan(load_scene(SIX))
    kinds = [st.kind for st in plan.steps]
    assert kinds == ["crank", "triad", "carried"]
    st = plan.steps[1]
    assert st.finds == ("B", "C", "D") and set(st.links) == {"BC", "AB", "EC", "FD"}


@pytest.mark.parametrize("angle", [0, 45, 135, 200, 315])
def test_matches_the_50_digit_reference_round_the_turn(angle):
    """The branch at each angle is the one swept continuously from the scene's instant;
    the reference polishes the solver's positions and is compared to 1e-9."""
    text = SIX.read_text()
    sw = Sweeper(load_scene(SIX))
    fr = sw.evaluate(np.array([math.radians(angle)]))
    scene = parse_scene(at(text, angle))
    sol = solve(scene)
    for p in "BCD":  # the scene at this angle, hinted by B only, is on the swept branch
        assert math.dist(sol.P[p], (fr.P[p][0][0], fr.P[p][1][0])) < 1e-9
    ref = reference_solution(scene, sol.P)
    assert ref["residual"] < mpf("1e-40")
    err, what = worst_error(scene, sol, ref)
    assert err < 1e-9, f"{what}: {err:.2e}"


def test_velocities_and_accelerations_are_the_time_derivatives_of_positions():
    """Central differences of positions swept at theta +- k h (constant crank speed)."""
    sc = load_scene(SIX)
    plan = compile_plan(sc)
    w = 7.0
    t0 = math.radians(100.0)
    h = 1e-4  # s
    ks = np.array([-2, -1, 0, 1, 2], dtype=float)
    fr = run_arrays(plan, t0 + w * h * ks, w, 0.0)
    for p in "BCD":
        for c in (0, 1):
            x = fr.P[p][c]
            v = (8 * (x[3] - x[1]) - (x[4] - x[0])) / (12 * h)
            a = (-(x[4] + x[0]) + 16 * (x[3] + x[1]) - 30 * x[2]) / (12 * h * h)
            vs, as_ = fr.V[p][c][2], fr.A[p][c][2]
            assert abs(v - vs) < 1e-7 * (1 + abs(vs)), (p, c, v, vs)
            assert abs(a - as_) < 1e-3 * (1 + abs(as_)), (p, c, a, as_)
    for lk in ("AB", "BC", "EC", "FD"):
        assert np.isfinite(fr.W[lk]).all() and np.isfinite(fr.Al[lk]).all()


def test_a_full_turn_closes_every_loop_and_comes_back_to_the_same_assembly():
    sc = load_scene(SIX)
    sw = Sweeper(sc)
    assert sw.domain.full_turn
    th = np.linspace(sw.domain.lo, sw.domain.lo + 2 * math.pi, 3601)
    fr = sw.evaluate(th)
    assert not fr.bad.any()
    P = fr.P
    lengths = {
        "AB": ("A", "B", 0.110),
        "EC": ("E", "C", 0.122),
        "FD": ("F", "D", 0.101),
        "BC": ("B", "C", 0.078),
    }
    for a, b, L in lengths.values():
        r = np.hypot(np.asarray(P[a][0]) - P[b][0], np.asarray(P[a][1]) - P[b][1])
        assert np.max(np.abs(r - L)) < 1e-14
    for p in "BCD":  # continuous: no jump to another assembly between neighbours
        step = np.hypot(np.diff(P[p][0]), np.diff(P[p][1]))
        assert step.max() < 5e-4
        assert math.dist((P[p][0][0], P[p][1][0]), (P[p][0][-1], P[p][1][-1])) < 1e-12


def test_array_mode_equals_one_instant_at_each_angle():
    sc = load_scene(SIX)
    plan = compile_plan(sc)
    angles = np.radians(np.arange(0.0, 360.0, 7.5))
    fr = run_arrays(plan, angles, sc.input.omega, sc.input.alpha)
    text = SIX.read_text()
    for k in (0, 11, 29, 47):
        sol = solve(parse_scene(at(text, math.degrees(angles[k]))))
        for p in "BCD":
            assert math.dist(sol.V[p], (fr.V[p][0][k], fr.V[p][1][k])) < 1e-12
            assert math.dist(sol.A[p], (fr.A[p][0][k], fr.A[p][1][k])) < 1e-10


def _brute_force(K, prm, n=36):
    """Assemblies by a brute-force grid of starts (B on its circle, the plate's angle),
    each by plain Newton on the three closing equations with numpy's linear solve, all
    starts at once (an independent search)."""
    l1, l2, l3, u2x, u2y, u3x, u3y = prm
    phi, th = np.meshgrid(
        np.linspace(0, 2 * math.pi, n, endpoint=False),
        np.linspace(-math.pi, math.pi, n, endpoint=False),
    )
    q = np.stack(
        [K[0][0] + l1 * np.cos(phi.ravel()), K[0][1] + l1 * np.sin(phi.ravel()), th.ravel()], axis=1
    )
    u = np.array([[0.0, 0.0], [u2x, u2y], [u3x, u3y]])
    Ks = np.array(K)
    for _ in range(80):
        c, s = np.cos(q[:, 2]), np.sin(q[:, 2])
        R = np.stack([np.stack([c, -s], 1), np.stack([s, c], 1)], 1)  # N x 2 x 2
        V = q[:, None, :2] + np.einsum("nij,kj->nki", R, u)  # N x 3 x 2
        r = V - Ks[None]
        F = np.sum(r * r, axis=2) - np.array(prm[:3]) ** 2
        d = V - V[:, :1]
        J = np.stack(
            [2 * r[..., 0], 2 * r[..., 1], 2 * (d[..., 0] * r[..., 1] - d[..., 1] * r[..., 0])],
            axis=2,
        )
        ok = np.abs(np.linalg.det(J)) > 1e-30
        J[~ok] = np.eye(3)
        dq = np.linalg.solve(J, F[..., None])[..., 0]
        q = q - np.clip(dq, -0.05, 0.05)
    good = np.all(np.isfinite(q), axis=1) & (np.max(np.abs(F), axis=1) < 1e-15)
    found = []
    for qq in q[good]:
        qq = (qq[0], qq[1], math.remainder(qq[2], 2 * math.pi))
        if all(math.dist(qq[:2], f[:2]) > 1e-6 for f in found):
            found.append(qq)
    return found


def test_every_assembly_is_found():
    sc = load_scene(SIX)
    plan = compile_plan(sc)
    st = plan.steps[1]
    P = solve(sc).P
    K = tuple(P[k] for k in st.knowns)
    mine = triad.assemblies(K, st.params)
    ref = _brute_force([np.array(k) for k in K], st.params)
    assert len(mine) == len(ref) == st.count == 2
    for q in ref:
        assert min(math.dist(q[:2], m[:2]) for m in mine) < 1e-12


def test_the_assembly_hint_chooses_and_the_default_is_a_note():
    text = SIX.read_text()
    sol = solve(load_scene(SIX))
    other = text.replace("B = [100, 80]", "B = [120, 22]")  # the second assembly's B
    alt = solve(parse_scene(other))
    assert math.dist(alt.P["B"], sol.P["B"]) > 0.01
    ref = reference_solution(alt.scene, alt.P)  # a true assembly too
    assert ref["residual"] < mpf("1e-40")
    assert worst_error(alt.scene, alt, ref)[0] < 1e-9
    bare = solve(parse_scene(text.replace("B = [100, 80]", "")))
    assert any("triad's 2 assemblies" in n for n in bare.notes)
    with pytest.raises(AssemblyError, match="as near one assembly"):
        solve(parse_scene(text.replace("B = [100, 80]", "B = [109.9, 51.3]")))


def test_condition_is_the_hadamard_ratio_of_the_normalised_jacobian():
    rng = np.random.default_rng(5)
    for _ in range(20):
        V = [tuple(rng.normal(size=2)) for _ in range(3)]
        K = [tuple(rng.normal(size=2) * 3) for _ in range(3)]
        G = np.mean(V, axis=0)
        rho = math.sqrt(np.mean([np.sum((np.array(v) - G) ** 2) for v in V]))
        rows = []
        for v, k in zip(V, K):
            u = (np.array(v) - k) / np.linalg.norm(np.array(v) - k)
            d = np.array(v) - G
            rows.append([u[0], u[1], (d[0] * u[1] - d[1] * u[0]) / rho])
        N = np.array(rows)
        want = abs(np.linalg.det(N)) / np.prod(np.linalg.norm(N, axis=1))
        assert abs(triad.condition(V, K) - want) < 1e-12
    # three lines through one point: singular
    V = [(1.0, 0.0), (0.0, 1.0), (-1.0, -0.5)]
    K = [(3.0, 0.0), (0.0, 2.0), (-2.0, -1.0)]  # all on lines through the origin
    assert triad.condition(V, K) < 1e-15


def test_a_triad_that_cannot_close_is_one_line_and_exit_code_2(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(SIX.read_text().replace("FD = 101", "FD = 30"))
    r = subprocess.run(
        [sys.executable, "-m", "polygon_method", "solve", str(bad)],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )
    assert r.returncode == 2
    assert r.stderr.count("\n") == 1 and "cannot assemble the triad B, C, D" in r.stderr
    assert "Traceback" not in r.stderr


LIMITED = """
[ground]
O = [0, 0]
E = [120, 230]
F = [270, 20]
[links]
OA = 40
AB = 92
BC = 78
EC = 108
FD = 108
[points]
D = { on = "BC", distances = { B = 73, C = 71 }, turn = "cw" }
[assembly]
B = [100, 80]
[input]
crank = "OA"
angle = 60
speed = "10 rad/s ccw"
"""


def test_a_sweep_stops_at_the_triads_limits_where_its_condition_vanishes():
    sc = parse_scene(LIMITED)
    sw = Sweeper(sc)
    dom = sw.domain
    assert not dom.full_turn and len(dom.limits) == 2
    plan = compile_plan(sc)
    for lim in dom.limits:
        assert "triad" in lim.step and "meet in one point" in lim.why
        inside = lim.theta + math.copysign(1e-6, sc.input.angle - lim.theta)
        fr = run_arrays(plan, np.array([inside]), 10.0, 0.0, vel=False, acc=False)
        assert not fr.bad.any() and fr.cond[1][0] < 1e-2, (lim, fr.cond[1])
        beyond = lim.theta - math.copysign(1e-6, sc.input.angle - lim.theta)
        fr = run_arrays(plan, np.array([beyond]), 10.0, 0.0, vel=False, acc=False)
        assert fr.bad.all()


def _designed(seed):
    """A class-III six-bar drawn at random, its lengths measured off the drawing (so the
    drawing is an exact assembly): (scene text, the drawn B, C, D in mm)."""
    rng = np.random.default_rng(seed)
    r, ang = rng.uniform(10, 30), rng.uniform(0, 360)
    A = (r * math.cos(math.radians(ang)), r * math.sin(math.radians(ang)))
    G = np.array([120.0, 90.0]) + rng.normal(size=2) * 10
    V = [
        tuple(G + 45 * np.array([math.cos(t), math.sin(t)]) * rng.uniform(0.8, 1.2))
        for t in np.radians([200, 320, 80]) + rng.normal(size=3) * 0.2
    ]
    B, C, D = V
    E = tuple(
        np.array(C) + rng.uniform(90, 130) * np.array([math.cos(a), math.sin(a)])
        for a in [rng.uniform(1.5, 2.5)]
    )[0]
    F = tuple(
        np.array(D) + rng.uniform(90, 130) * np.array([math.cos(a), math.sin(a)])
        for a in [rng.uniform(-1.5, -0.5)]
    )[0]
    d = math.dist
    turn = "cw" if (C[0] - B[0]) * (D[1] - B[1]) - (C[1] - B[1]) * (D[0] - B[0]) < 0 else "ccw"
    text = f"""
[ground]
O = [0, 0]
E = [{float(E[0])!r}, {float(E[1])!r}]
F = [{float(F[0])!r}, {float(F[1])!r}]
[links]
OA = {float(r)!r}
AB = {float(d(A, B))!r}
BC = {float(d(B, C))!r}
EC = {float(d(E, C))!r}
FD = {float(d(F, D))!r}
[points]
D = {{ on = "BC", distances = {{ B = {float(d(B, D))!r}, C = {float(d(C, D))!r} }}, turn = "{turn}" }}
[assembly]
B = [{float(B[0])!r}, {float(B[1])!r}]
C = [{float(C[0])!r}, {float(C[1])!r}]
[input]
crank = "OA"
angle = {float(ang)!r}
speed = "{float(rng.uniform(50, 300))!r} rpm ccw"
acceleration = "{float(rng.uniform(1, 50))!r} rad/s^2 cw"
"""
    return text, {"B": B, "C": C, "D": D}


@pytest.mark.parametrize("seed", range(8))
def test_random_triads_solve_their_drawing_and_match_the_reference(seed):
    text, drawn = _designed(seed)
    sol = solve(parse_scene(text))
    for p, xy in drawn.items():  # the drawing is an exact assembly: it is found again
        assert math.dist(sol.P[p], (xy[0] * 1e-3, xy[1] * 1e-3)) < 1e-12, p
    ref = reference_solution(sol.scene, sol.P)
    assert worst_error(sol.scene, sol, ref)[0] < 1e-9


def test_a_plate_of_three_links_is_the_same_triad_as_a_plate_with_a_carried_point():
    TRI = ROOT / "tests" / "textbook" / "class3_triangle_plate.toml"
    tri = solve(
        parse_scene(
            at(TRI.read_text(), 60).replace("90 rpm cw", "120 rpm ccw")
            + 'acceleration = "30 rad/s^2 cw"\n'
        )
    )
    plate = solve(load_scene(SIX))
    assert [st.kind for st in tri.plan.steps] == ["crank", "triad"]
    for p in "BCD":
        assert math.dist(tri.P[p], plate.P[p]) < 1e-12
        assert math.dist(tri.V[p], plate.V[p]) < 1e-12
        assert math.dist(tri.A[p], plate.A[p]) < 1e-10
    for side in ("BC", "CD", "DB"):  # every side turns with the plate
        assert abs(tri.W[side] - plate.W["BC"]) < 1e-12
        assert abs(tri.Al[side] - plate.Al["BC"]) < 1e-10
    # its mirror image is a family of assemblies of its own: hinted, it is found
    st = tri.plan.steps[1]
    K = tuple(tri.P[k] for k in st.knowns)
    mirrored = triad.assemblies(K, st.params[:6] + (-st.params[6],))
    same = triad.assemblies(K, st.params)
    assert st.count == len(mirrored) + len(same)


def test_check_names_the_other_assembly_of_the_triad():
    """Answers of the other assembly (found by the brute-force search, solved by the
    50-digit reference) are diagnosed as the other branch."""
    from polygon_method.check import check_answers
    from polygon_method.scene import parse_answers

    sc = load_scene(WORKED)
    sol = solve(sc)
    st = sol.plan.steps[1]
    K = tuple(sol.P[k] for k in st.knowns)
    prm = st.params
    others = [
        q
        for q in _brute_force([np.array(k) for k in K], prm)
        if math.dist(q[:2], sol.P["B"]) > 1e-6
    ]
    assert others
    q = others[0]
    guess = dict(sol.P)
    guess.update(zip("BCD", triad.vertices(*q, prm, math.cos, math.sin)))
    ref = reference_solution(sc, guess)
    vB = ref["velocities"]["B"]
    wrong = float(mpmath_hypot(vB))
    assert abs(wrong - math.hypot(*sol.V["B"])) > 0.1
    tol, ans = parse_answers(f'[answers]\nv_B = "{wrong!r} m/s"\n', sc)
    v = {x.key: x for x in check_answers(sol, ans, tol)}["v_B"]
    assert v.mistake == "other_branch" and "the other assembly" in v.diagnosis


def mpmath_hypot(v):
    import mpmath

    return mpmath.sqrt(v[0] ** 2 + v[1] ** 2)


def test_an_angle_beyond_the_triads_limits_is_refused_with_the_range_the_sweep_reaches():
    """The refusal's range comes from a search of all assemblies at each angle; the
    sweep's limits from continuation of the scene's assembly: the two agree."""
    sc = parse_scene(LIMITED)
    lims = sorted(math.degrees(lim.theta) for lim in Sweeper(sc).domain.limits)
    with pytest.raises(AssemblyError) as exc:
        solve(parse_scene(LIMITED.replace("angle = 60", "angle = 100")))
    msg = str(exc.value)
    assert "no position of the plate BC reaches the links AB, EC, FD" in msg
    lo, hi = (float(x) for x in re.search(r"from (-?[\d.]+) to (-?[\d.]+) deg", msg).groups())
    assert abs(lo - lims[0]) < 0.01 and abs(hi - lims[1]) < 0.01


@pytest.mark.parametrize("delta", [3.0, 0.3, 0.03, 0.003])
def test_the_error_bound_holds_near_the_triads_limit(delta):
    """Approaching the limit (the condition falls like the root of the distance) every
    error against the 50-digit reference stays within its bound."""
    from polygon_method.solver.errorbound import error_bounds

    hi = max(math.degrees(lim.theta) for lim in Sweeper(parse_scene(LIMITED)).domain.limits)
    text = LIMITED.replace("angle = 60", f"angle = {hi - delta!r}").replace(
        "B = [100, 80]", "B = [99, 70]"
    )
    sol = solve(parse_scene(text))
    ref = reference_solution(sol.scene, sol.P)
    b = error_bounds(sol)
    sz = b.scales
    worst = 0.0
    for p in "BCD":
        for tab, got, bound, size in (
            ("positions", sol.P, b.P, sz["position"]),
            ("velocities", sol.V, b.V, sz["velocity"]),
            ("accelerations", sol.A, b.A, sz["acceleration"]),
        ):
            err = math.dist(got[p], tuple(float(c) for c in ref[tab][p]))
            worst = max(worst, err / (bound[p] * size))
    for lk in ("AB", "BC", "EC", "FD"):
        worst = max(
            worst,
            abs(sol.W[lk] - float(ref["omega"][lk])) / (b.W[lk] * sz["omega"]),
            abs(sol.Al[lk] - float(ref["alpha"][lk])) / (b.Al[lk] * sz["alpha"]),
        )
    assert worst <= 1.0, worst
    assert sol.conditions[1] < 0.6


def test_at_the_limit_the_triad_is_refused_as_singular_with_its_words():
    from polygon_method.common.errors import SingularStepError

    hi = max(math.degrees(lim.theta) for lim in Sweeper(parse_scene(LIMITED)).domain.limits)
    text = LIMITED.replace("angle = 60", f"angle = {hi - 1e-9!r}").replace(
        "B = [100, 80]", "B = [99, 70]"
    )
    with pytest.raises(SingularStepError, match="the lines of AB, EC, FD meet in one point"):
        solve(parse_scene(text))
