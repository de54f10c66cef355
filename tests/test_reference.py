"""The solver against an independent 50-digit reference (tests/reference.py).

The reference solves the loop-closure equations by Newton-Raphson and the velocity and
acceleration by the constraint Jacobian; it is itself checked by finite differences in
time and against two closed forms (slider-crank, algebraic four-bar).
"""

import math

import mpmath
import pytest
from mpmath import mpf

from polygon_method.solver.compiler import compile_plan
from polygon_method.solver.plan import Context
from polygon_method.scene import parse_scene
from reference import (
    constraint_jacobian,
    constraint_residuals,
    reference_fourbar_algebraic,
    reference_positions,
    reference_slider_crank,
    reference_solution,
    theta_at,
)
from scenes import seed

REL = 1e-9  # solver (floats) against the reference

FOURBAR = seed(
    middle='[points]\nE = {{ on = "BC", along = 40 }}\n'
    'F = {{ on = "BC", distances = {{ B = 45, C = 30 }}, turn = "cw" }}\n',
    drive='angle = {angle}\nspeed = "10.5 rad/s cw"\n{acc}',
)

SLIDER_CRANK = """
[ground]
O = [0, 0]
[links]
OA = 40
AB = 140
[sliders]
B = {{ path = "horizontal", through = [0, {e}] }}
[input]
crank = "OA"
angle = {angle}
speed = "300 rpm cw"
{acc}
"""

SLOTTED_LEVER = """
[ground]
O2 = [0, 150]
O4 = [0, 0]
[links]
"O2-A" = 50
"O4-P" = 300
"P-Q" = 120
[sliders]
A = {{ along = "O4-P" }}
Q = {{ path = "horizontal", through = [0, 280] }}
[input]
crank = "O2-A"
angle = {angle}
speed = "12 rad/s ccw"
{acc}
"""

# trunnion: the ground point O is a block through which the moving link BC slides
SWIVEL = """
[ground]
A = [0, 0]
O = [120, 30]
[links]
AB = 40
BC = 200
{extra}
[points]
E = {{ on = "BC", along = -30 }}
[sliders]
O = {{ along = "BC" }}
[input]
crank = "AB"
angle = {angle}
speed = "20 rad/s ccw"
{acc}
"""

# four-bar plus a slider G driven from the coupler point F (on a 30 deg path)
SIX_LINK = seed(
    ground="T = [150, 0]\n",
    links="FG = 100\n",
    middle="[points]\n"
    'F = {{ on = "BC", distances = {{ B = 45, C = 30 }}, turn = "cw" }}\n'
    '[sliders]\nG = {{ path = "30 deg", through = "T" }}\n',
    drive='angle = {angle}\nspeed = "10.5 rad/s cw"\n{acc}',
)

# four-bar plus a block G, pinned to the rocker HG, sliding along the moving rocker CD
GUIDE_DYAD = seed(
    ground="H = [60, -40]\n",
    links="HG = 60\n",
    middle='[sliders]\nG = {{ along = "{guide}" }}\n',
    drive='angle = {angle}\nspeed = "10.5 rad/s cw"\n{acc}',
)

ACC = 'acceleration = "80 rad/s^2 ccw"'
SWIVEL_GROUND_LINK = '"A-O" = 123.69316876852982'  # = |AO|: only to get O past the loader

CASES = {
    "fourbar": [FOURBAR.format(angle=a, acc="") for a in (60, 100, 290)],
    "fourbar_alpha": [FOURBAR.format(angle=a, acc=ACC) for a in (60, 280)],
    "slider_crank_inline": [SLIDER_CRANK.format(e=0, angle=a, acc="") for a in (45, 160, 300)],
    "slider_crank_offset": [SLIDER_CRANK.format(e=20, angle=a, acc="") for a in (45, 250)],
    "slider_crank_alpha": [SLIDER_CRANK.format(e=20, angle=a, acc=ACC) for a in (45, 250)],
    "slotted_lever": [SLOTTED_LEVER.format(angle=a, acc="") for a in (30, 120, 250)],
    "slotted_lever_alpha": [SLOTTED_LEVER.format(angle=a, acc=ACC) for a in (30,)],
    "slotted_lever_reversed": [
        SLOTTED_LEVER.replace('"O4-P" }}', '"P-O4" }}').format(angle=a, acc=ACC) for a in (30, 250)
    ],
    "guide_dyad": [
        GUIDE_DYAD.format(guide=g, angle=a, acc=acc)
        for g, a, acc in (("CD", 60, ""), ("DC", 60, ACC), ("CD", 290, ACC))
    ],
    "swivel": [SWIVEL.format(extra="", angle=a, acc="") for a in (50, 200)],
    "swivel_ground_link": [
        SWIVEL.format(extra=SWIVEL_GROUND_LINK, angle=a, acc=ACC) for a in (50, 200)
    ],
    "six_link": [SIX_LINK.format(angle=a, acc="") for a in (60, 280)],
    "six_link_alpha": [SIX_LINK.format(angle=a, acc=ACC) for a in (60,)],
}
PARAMS = [
    pytest.param(text, id=f"{name}-{i}")
    for name, texts in CASES.items()
    for i, text in enumerate(texts)
]
# scenes the loader accepts, for the tests of the reference itself
REF_PARAMS = [p for p in PARAMS if not p.id.startswith("swivel-")]


def solve(text):
    scene = parse_scene(text)
    plan = compile_plan(scene)
    inp = scene.input
    return scene, plan.evaluate(Context(inp.angle, inp.omega, inp.alpha))


_REF = {}


def reference(text):
    """(scene, solver output, reference) for a scene text, cached: each costs some ms."""
    if text not in _REF:
        scene, out = solve(text)
        _REF[text] = scene, out, reference_solution(scene, out[0])
    return _REF[text]


def _norm(v):
    return math.hypot(float(v[0]), float(v[1])) if isinstance(v, tuple) else abs(float(v))


def _diff(got, want):
    if isinstance(want, tuple):
        return math.hypot(float(mpf(got[0]) - want[0]), float(mpf(got[1]) - want[1]))
    return abs(float(mpf(got) - want))


def _check(errors, what, got, want, scale, rel):
    err = _diff(got, want) / max(_norm(want), scale)
    if not err < rel:

        def fmt(v):
            return (
                f"({float(v[0]):.12g}, {float(v[1]):.12g})"
                if isinstance(v, tuple)
                else f"{float(v):.12g}"
            )

        errors.append(f"{what}: expected {fmt(want)}, got {fmt(got)} (rel. error {err:.2e})")


def _scale(values, floor=1e-300):
    return max([_norm(v) for v in values] + [floor])


# --------------------------------------------------------------------------- solver vs reference


@pytest.mark.parametrize("text", PARAMS)
def test_solver_matches_reference(text):
    scene, (P, V, A, W, Al, S), ref = reference(text)
    errors = []
    for key, got, table in (
        ("position", P, "positions"),
        ("velocity", V, "velocities"),
        ("acceleration", A, "accelerations"),
    ):
        want = ref[table]
        scale = _scale(want.values())
        for name in scene.point_names:
            if name not in got:
                errors.append(f"{key} of {name}: missing")
                continue
            _check(errors, f"{key} of {name}", tuple(got[name]), want[name], scale, REL)
    for key, got, table in (("omega", W, "omega"), ("alpha", Al, "alpha")):
        want = ref[table]
        scale = _scale(want.values())
        for lk in scene.links:
            if lk.key not in got:
                errors.append(f"{key} of {lk.key}: missing")
                continue
            _check(errors, f"{key} of {lk.key}", got[lk.key], want[lk.key], scale, REL)
    vscale = _scale(ref["velocities"].values())
    ascale = _scale(ref["accelerations"].values())
    for sl in scene.sliders:
        want = ref["sliders"][sl.point]
        if sl.point not in S:
            errors.append(f"slider {sl.point}: missing")
            continue
        vs, a_s, cor = S[sl.point]
        _check(errors, f"sliding velocity at {sl.point}", vs, want["vs"], vscale, REL)
        _check(errors, f"sliding acceleration at {sl.point}", a_s, want["as"], ascale, REL)
        _check(errors, f"Coriolis at {sl.point}", tuple(cor), want["coriolis"], ascale, REL)
    assert not errors, "\n".join(errors)


# --------------------------------------------------------------------------- the reference itself


@pytest.mark.parametrize("text", REF_PARAMS)
def test_reference_closes_loops(text):
    scene, _, ref = reference(text)
    assert ref["residual"] < mpf("1e-40")
    assert constraint_residuals(scene, ref["positions"]) < mpf("1e-30")
    # and the links really keep their lengths (the crank's is not an equation of the system)
    P = ref["positions"]
    for lk in scene.links:
        if lk.p in scene.ground and lk.q in scene.ground:
            continue
        d = mpmath.sqrt((P[lk.p][0] - P[lk.q][0]) ** 2 + (P[lk.p][1] - P[lk.q][1]) ** 2)
        assert abs(d - mpf(lk.length)) < mpf("1e-35"), lk.key


@pytest.mark.parametrize("text", REF_PARAMS)
def test_reference_jacobian_is_the_derivative(text):
    """The hand-written Jacobian against mpmath.diff of the residuals, entry by entry."""
    from reference import _system  # noqa: PLC0415 -- a private helper, for this check only

    scene, _, ref = reference(text)
    P = dict(ref["positions"])
    th = mpf(scene.input.angle)
    J, names = constraint_jacobian(scene, P, th)
    for j, name in enumerate(names):
        for c in (0, 1):

            def f(h, i=None):
                Q = dict(P)
                xy = list(Q[name])
                xy[c] += h
                Q[name] = tuple(xy)
                return _system(scene, Q, th)[0]

            h = mpf("1e-20")
            Fp, Fm = f(h), f(-h)
            for i in range(J.rows):
                num = (Fp[i] - Fm[i]) / (2 * h)
                assert abs(num - J[i, 2 * j + c]) < mpf("1e-25"), (i, name, c)


@pytest.mark.parametrize("text", REF_PARAMS)
def test_reference_velocity_is_time_derivative(text):
    """Central differences in time of the Newton positions give v and a."""
    scene, _, ref = reference(text)
    P = ref["positions"]
    h1, h2 = mpf("1e-15"), mpf("1e-12")
    p1 = {s: reference_positions(scene, P, theta_at(scene, s * h1))[0] for s in (-1, 1)}
    p2 = {s: reference_positions(scene, P, theta_at(scene, s * h2))[0] for s in (-1, 1)}
    vscale = _scale(ref["velocities"].values())
    ascale = _scale(ref["accelerations"].values())
    errors = []
    for n in scene.point_names:
        v = tuple((p1[1][n][k] - p1[-1][n][k]) / (2 * h1) for k in (0, 1))
        a = tuple((p2[1][n][k] - 2 * P[n][k] + p2[-1][n][k]) / h2**2 for k in (0, 1))
        _check(errors, f"d/dt position of {n}", v, ref["velocities"][n], vscale, 1e-20)
        _check(errors, f"d2/dt2 position of {n}", a, ref["accelerations"][n], ascale, 1e-15)
    assert not errors, "\n".join(errors)


@pytest.mark.parametrize("text", [p for p in REF_PARAMS if "slider_crank" in p.id])
def test_reference_slider_crank_closed_form(text):
    scene, _, ref = reference(text)
    inp = scene.input
    (sl,) = scene.sliders
    e = sl.through[1]
    assert scene.ground[inp.pivot] == (0.0, 0.0) and sl.u == (1.0, 0.0)
    crank, rod = scene.link(inp.crank), scene.link("AB")
    cf = reference_slider_crank(crank.length, rod.length, e, inp.angle, inp.omega, inp.alpha)
    tol = mpf("1e-30")
    P, V, A = ref["positions"]["B"], ref["velocities"]["B"], ref["accelerations"]["B"]
    assert abs(P[0] - cf["x"]) < tol * abs(cf["x"])
    assert abs(P[1] - mpf(e)) < tol
    vscale, ascale = abs(cf["v"]) + 1, abs(cf["a"]) + 1
    assert abs(V[0] - cf["v"]) < tol * vscale and abs(V[1]) < tol * vscale
    assert abs(A[0] - cf["a"]) < tol * ascale and abs(A[1]) < tol * ascale
    assert abs(ref["sliders"]["B"]["vs"] - cf["v"]) < tol * vscale
    assert abs(ref["sliders"]["B"]["as"] - cf["a"]) < tol * ascale
    # rod A->B: the same angle as the closed form's B -> piston
    wr, ar = ref["omega"][rod.key], ref["alpha"][rod.key]
    assert abs(wr - cf["omega_rod"]) < tol * (abs(cf["omega_rod"]) + 1)
    assert abs(ar - cf["alpha_rod"]) < tol * (abs(cf["alpha_rod"]) + 1)


@pytest.mark.parametrize("text", [p for p in REF_PARAMS if p.id.startswith("fourbar")])
def test_reference_fourbar_algebraic(text):
    """Notes' O2, A, B, O4 = our A, B, C, D; a, b, c, d = AB, BC, CD, AD."""
    scene, _, ref = reference(text)
    inp = scene.input
    assert scene.ground["A"] == (0.0, 0.0) and scene.ground["D"][1] == 0.0
    args = (
        scene.link("AB").length,
        scene.link("BC").length,
        scene.link("CD").length,
        scene.ground["D"][0],
        inp.angle,
        inp.omega,
        inp.alpha,
    )
    P = ref["positions"]
    sols = [reference_fourbar_algebraic(*args, branch=b) for b in (1, -1)]
    alg = min(sols, key=lambda s: abs(s["B"][1] - P["C"][1]) + abs(s["B"][0] - P["C"][0]))
    tol = mpf("1e-30")

    def close(x, y, scale):
        return all(abs(x[k] - y[k]) < tol * scale for k in (0, 1))

    assert close(alg["A"], P["B"], 1) and close(alg["B"], P["C"], 1)
    vs = _scale(ref["velocities"].values())
    as_ = _scale(ref["accelerations"].values())
    assert close(alg["vA"], ref["velocities"]["B"], vs)
    assert close(alg["vB"], ref["velocities"]["C"], vs)
    assert close(alg["aA"], ref["accelerations"]["B"], as_)
    assert close(alg["aB"], ref["accelerations"]["C"], as_)
    ws = _scale(ref["omega"].values())
    als = _scale(ref["alpha"].values())
    assert abs(alg["omega3"] - ref["omega"]["BC"]) < tol * ws
    assert abs(alg["omega4"] - ref["omega"]["CD"]) < tol * ws
    assert abs(alg["alpha3"] - ref["alpha"]["BC"]) < tol * als
    assert abs(alg["alpha4"] - ref["alpha"]["CD"]) < tol * als


def test_reference_omega_of_crank_and_carried_point_geometry():
    scene, _, ref = reference(CASES["fourbar"][0])
    assert ref["omega"]["AB"] == mpf(scene.input.omega)
    assert ref["alpha"]["AB"] == mpf(scene.input.alpha)
    P = ref["positions"]

    def dist(a, b):
        return mpmath.sqrt((P[a][0] - P[b][0]) ** 2 + (P[a][1] - P[b][1]) ** 2)

    assert abs(dist("B", "E") - mpf("0.040")) < 1e-15
    assert abs(dist("B", "F") - mpf("0.045")) < 1e-15
    assert abs(dist("C", "F") - mpf("0.030")) < 1e-15
    bc = (P["C"][0] - P["B"][0], P["C"][1] - P["B"][1])
    bf = (P["F"][0] - P["B"][0], P["F"][1] - P["B"][1])
    assert bc[0] * bf[1] - bc[1] * bf[0] < 0  # B, C, F read clockwise
