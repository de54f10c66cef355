"""A collar driven along a turning rod ([input] block on a [sliders] entry along a link):
the inverted slider crank driven by its sliding ("collar C slides along rod OA at 1.5 m/s
relative to the rod, slowing at 4 m/s^2; C is pinned to the crank DC").

Compared with a closed form derived here (O at the origin, D at (e, 0), OC = s, DC = r:
the rod's angle phi from the cosine rule, cos phi = (s^2 + e^2 - r^2) / (2 s e), sin phi
> 0 on the branch above; A = OA (cos phi, sin phi); B on the x axis, x_B = x_A +
sqrt(AB^2 - y_A^2); each differentiated in time by mpmath along s(t) = s0 + vs t + as
t^2 / 2), with the 50-digit constraint solve of tests/reference.py, and with finite
differences of the solver's own positions along the collar's stroke.
"""

import json
import math

import mpmath
import numpy as np
import pytest
from mpmath import mpf

from polygon_method import parse_scene, solve
from polygon_method.cli import main
from polygon_method.motion.sweeps import sweep
from polygon_method.solver.compiler import compile_plan
from reference import reference_solution
from textbook_corpus import worst_error

REL = 1e-9

SCENE = """
title = "collar"
units = "m"
[ground]
O = [0, 0]
D = [{e}, 0]
[links]
OA = {L}
DC = {r}
AB = {l}
[sliders]
C = {{ along = "{along}" }}
B = {{ path = "horizontal", through = "O" }}
[assembly]
C = "above"
B = "right"
[input]
block = "C"
{place}
vs_C = "{vs}"
as_C = "{acc}"
{extra}
"""

CASES = [  # e (OD), r (DC), s (OC), vs (outward), as (outward), OA, AB, along
    (0.3, 0.15, 0.35, 1.5, -4.0, 0.5, 0.4, "O-A"),
    (0.3, 0.15, 0.2, -0.8, 2.5, 0.5, 0.6, "A-O"),
    (0.25, 0.4, 0.5, 2.0, 0.0, 0.9, 1.0, "O-A"),  # a crank longer than OD: it turns fully
    (0.5, 0.2, 0.64, -3.0, 7.0, 1.2, 1.5, "O-A"),
]


def scene_text(e, r, s, vs, acc, L, l, along, extra="", place=None):
    return SCENE.format(
        e=e,
        r=r,
        L=L,
        l=l,
        along=along,
        vs=f"{vs} m/s",
        acc=f"{acc} m/s^2",
        extra=extra,
        place=f"s_C = {s}" if place is None else place,
    )


def closed_form(e, r, s0, vs, acc, L, l):
    """phi, omega_OA, alpha_OA, A, v_A, a_A, x_B, v_B, a_B, omega_DC, alpha_DC (mpf)."""
    e, r, s0, vs, acc, L, l = (mpf(x) for x in (e, r, s0, vs, acc, L, l))

    def s_of(t):
        return s0 + vs * t + acc * t * t / 2

    def phi(t):
        s = s_of(t)
        return mpmath.acos((s * s + e * e - r * r) / (2 * s * e))

    def C(t, k):
        s, p = s_of(t), phi(t)
        return s * (mpmath.cos(p) if k == 0 else mpmath.sin(p))

    def A(t, k):
        p = phi(t)
        return L * (mpmath.cos(p) if k == 0 else mpmath.sin(p))

    def xB(t):
        return A(t, 0) + mpmath.sqrt(l * l - A(t, 1) ** 2)

    def dc_angle(t):  # the direction D -> C, continuous about t = 0
        return mpmath.atan2(C(t, 1), C(t, 0) - e)

    d = mpmath.diff
    return {
        "phi": phi(0),
        "omega_OA": d(phi, 0, 1),
        "alpha_OA": d(phi, 0, 2),
        "C": (C(0, 0), C(0, 1)),
        "v_C": tuple(d(lambda t, k=k: C(t, k), 0, 1) for k in (0, 1)),
        "a_C": tuple(d(lambda t, k=k: C(t, k), 0, 2) for k in (0, 1)),
        "A": (A(0, 0), A(0, 1)),
        "v_A": tuple(d(lambda t, k=k: A(t, k), 0, 1) for k in (0, 1)),
        "a_A": tuple(d(lambda t, k=k: A(t, k), 0, 2) for k in (0, 1)),
        "x_B": xB(0),
        "v_B": d(xB, 0, 1),
        "a_B": d(xB, 0, 2),
        "omega_DC": d(dc_angle, 0, 1),
        "alpha_DC": d(dc_angle, 0, 2),
    }


def close(got, want, scale):
    return abs(float(mpf(got) - want)) <= REL * float(scale)


@pytest.mark.parametrize("case", CASES)
def test_the_collar_agrees_with_the_closed_form(case):
    e, r, s, vs, acc, L, l, along = case
    sol = solve(parse_scene(scene_text(*case)))
    want = closed_form(e, r, s, vs, acc, L, l)
    V = max(abs(vs), float(mpmath.norm(want["v_A"])))
    Aw = max(abs(acc), float(mpmath.norm(want["a_A"])), float(mpmath.norm(want["a_C"])))
    for k in (0, 1):
        assert close(sol.P["A"][k], want["A"][k], L)
        assert close(sol.P["C"][k], want["C"][k], L)
        assert close(sol.V["A"][k], want["v_A"][k], V)
        assert close(sol.V["C"][k], want["v_C"][k], V)
        assert close(sol.A["A"][k], want["a_A"][k], Aw)
        assert close(sol.A["C"][k], want["a_C"][k], Aw)
    assert close(sol.P["B"][0], want["x_B"], L + l)
    assert close(sol.V["B"][0], want["v_B"], V)
    assert close(sol.A["B"][0], want["a_B"], Aw)
    w = max(abs(float(want["omega_OA"])), abs(float(want["omega_DC"])))
    assert close(sol.W["OA"], want["omega_OA"], w)
    assert close(sol.W["DC"], want["omega_DC"], w)
    al = max(abs(float(want["alpha_OA"])), abs(float(want["alpha_DC"]))) + w * w
    assert close(sol.Al["OA"], want["alpha_OA"], al)
    assert close(sol.Al["DC"], want["alpha_DC"], al)
    # the sliding relative to the rod is the given one, signed along the guide as named;
    # the Coriolis component is 2 omega_OA vs, across the rod
    sign = 1.0 if along == "O-A" else -1.0
    assert sol.S["C"][0] == pytest.approx(sign * vs, rel=1e-15)
    assert sol.S["C"][1] == pytest.approx(sign * acc, rel=1e-15, abs=1e-300)
    cor = 2 * abs(float(want["omega_OA"])) * abs(vs)
    assert math.isclose(math.hypot(*sol.coriolis("C")), cor, rel_tol=REL)


@pytest.mark.parametrize("case", CASES)
def test_the_collar_agrees_with_the_50_digit_constraint_solve(case):
    sc = parse_scene(scene_text(*case))
    sol = solve(sc)
    err, what = worst_error(sc, sol, reference_solution(sc, sol.P))
    assert err < REL, what


@pytest.mark.parametrize("case", CASES[:2])
def test_finite_differences_of_positions_along_the_stroke(case):
    """v = P'(s) vs and a = P''(s) vs^2 + P'(s) as, the derivatives in s by a five-point
    stencil on the solver's own positions at neighbouring places of the collar."""
    e, r, s, vs, acc, L, l, along = case
    h = 2e-4
    P = {
        k: solve(parse_scene(scene_text(e, r, s + k * h, vs, acc, L, l, along))).P
        for k in (-2, -1, 0, 1, 2)
    }
    sol = solve(parse_scene(scene_text(*case)))
    for X in ("A", "B", "C"):
        for c in (0, 1):
            f = {k: P[k][X][c] for k in P}
            d1 = (f[-2] - 8 * f[-1] + 8 * f[1] - f[2]) / (12 * h)
            d2 = (-f[-2] + 16 * f[-1] - 30 * f[0] + 16 * f[1] - f[2]) / (12 * h * h)
            assert abs(sol.V[X][c] - d1 * vs) <= REL * (abs(vs) + math.hypot(*sol.V[X]))
            assert abs(sol.A[X][c] - (d2 * vs * vs + d1 * acc)) <= 1e-8 * math.hypot(*sol.A[X]), (
                X,
                c,
            )


def test_the_sweep_runs_between_the_dead_centres_and_agrees_with_one_solve():
    """Over the collar's travel the array road gives the one-instant solve's numbers; the
    travel ends where the rod's line passes through D: OC = OD -+ DC."""
    case = CASES[0]
    e, r = case[0], case[1]
    sc = parse_scene(scene_text(*case))
    res = sweep(sc)  # its travel: from the first to the last place where it assembles
    s = np.asarray(res.theta)
    assert s.min() >= e - r - 1e-12 and s.max() <= e + r + 1e-12
    assert s.min() < e - r + 0.01 and s.max() > e + r - 0.01
    for i in range(0, len(s), 37):
        one = solve(parse_scene(scene_text(e, r, float(s[i]), *case[3:])))
        for X in ("A", "C"):
            for c in (0, 1):
                assert math.isclose(
                    res.A[X][c][i],
                    one.A[X][c],
                    rel_tol=1e-12,
                    abs_tol=1e-12 * math.hypot(*one.A[X]),
                )


def test_the_json_states_the_collar_and_the_force_along_the_rod(capsys, tmp_path):
    """The input force by power balance: F vs (relative to the rod) + F_B . v_B = 0."""
    f = tmp_path / "c.toml"
    f.write_text(scene_text(*CASES[0]) + "\n[loads]\nB = { force = [-300, 0] }\n")
    assert main(["solve", "--json", str(f)]) == 0
    d = json.loads(capsys.readouterr().out)
    inp = d["input"]
    assert inp["block"] == "C" and inp["collar"] and inp["rod"] == "OA" and inp["pivot"] == "O"
    assert inp["s"] == 0.35 and inp["vs"] == 1.5 and inp["as"] == -4.0
    vB = d["points"]["B"]["velocity"][0]
    assert math.isclose(d["input_force"] * 1.5, 300 * vB, rel_tol=1e-12)


def test_the_steps_lay_off_the_sliding_and_the_coriolis_component(capsys, tmp_path):
    f = tmp_path / "c.toml"
    f.write_text(scene_text(*CASES[0]))
    assert main(["steps", str(f)]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "the collar C slides along OA at 1.5 m/s outward: c1c = 1.5 m/s along OA" in out
    assert "Coriolis component 2 omega v" in out
    assert "Input collar C on the rod OA" in out


def test_the_checker_finds_the_coriolis_component_left_out(tmp_path, capsys):
    """alpha_OA drawn without 2 omega v: the tangential line perpendicular to OC closes the
    polygon short by the Coriolis component, alpha_OA moving by cor.DC / (OC x DC)."""
    case = CASES[0]
    sc = parse_scene(scene_text(*case))
    sol = solve(sc)
    P = sol.P
    d1 = (P["C"][0], P["C"][1])
    d2 = (P["C"][0] - case[0], P["C"][1])
    cx, cy = sol.coriolis("C")
    wrong = sol.Al["OA"] + (cx * d2[0] + cy * d2[1]) / (d1[0] * d2[1] - d1[1] * d2[0])
    assert abs(wrong - sol.Al["OA"]) > 0.1 * abs(sol.Al["OA"])
    f, a = tmp_path / "c.toml", tmp_path / "a.toml"
    f.write_text(scene_text(*case))
    a.write_text(
        f'[answers]\nalpha_OA = "{abs(wrong):.4f} rad/s^2 {"ccw" if wrong > 0 else "cw"}"\n'
    )
    assert main(["check", str(f), str(a)]) == 1
    out = " ".join(capsys.readouterr().out.split())
    assert "the Coriolis component 2 omega v of collar C on the rod OA left out" in out


@pytest.mark.parametrize(
    "place, words",
    [
        ("s_C = 0.45", "the rod OA's line passes through D"),  # OC = OD + DC: a dead centre
        ("s_C = 0.15", "the rod OA's line passes through D"),  # OC = OD - DC
    ],
)
def test_a_dead_centre_is_refused_with_its_condition(tmp_path, capsys, place, words):
    f = tmp_path / "c.toml"
    f.write_text(scene_text(*CASES[0], place=place))
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err and "condition" in err, err


def test_near_a_dead_centre_the_condition_says_so():
    e, r = CASES[0][:2]
    sol = solve(parse_scene(scene_text(*CASES[0], place=f"s_C = {e + r - 1e-6}")))
    c = sol.conditions[0]
    # |sin OCD| from the cosine rule, times min(1, OC / DC) = 1 here
    s = e + r - 1e-6
    cos_c = (s * s + r * r - e * e) / (2 * s * r)
    assert math.isclose(c, math.sqrt(1 - cos_c * cos_c), rel_tol=1e-6)
    assert any("dead centre" in w for w in sol.warnings)


def test_the_collar_placed_by_its_coordinates():
    """C = [x, y]: its distance from the pivot, and the assembly nearest the point."""
    e, r, s = CASES[0][:3]
    one = solve(parse_scene(scene_text(*CASES[0])))
    x, y = one.P["C"]
    two = solve(
        parse_scene(
            scene_text(*CASES[0], place=f"C = [{x!r}, {-y!r}]")
            .replace('C = "above"', 'B = "right"')
            .replace('[assembly]\nB = "right"\nB = "right"', '[assembly]\nB = "right"')
        )
    )
    assert math.isclose(two.P["C"][0], x, rel_tol=1e-12)
    assert math.isclose(two.P["C"][1], -y, rel_tol=1e-12)


@pytest.mark.parametrize(
    "text, key, words",
    [
        (
            "[ground]\nO = [0, 0]\nD = [0.3, 0]\n[links]\nOQ = 0.1\nQR = 0.5\nDC = 0.15\n"
            '[sliders]\nC = { along = "QR" }\n[input]\nblock = "C"\ns_C = 0.1\nvs_C = "1 m/s"\n',
            "[input] block",
            "pivoted on the frame at neither end",
        ),
        (
            "[ground]\nO = [0, 0]\nD = [0.3, 0]\n[links]\nOA = 0.5\nDC = 0.15\n[sliders]\n"
            'C = { along = "OA" }\n[input]\nblock = "C"\ns_C = 0.35\nvs_C = "1 m/s towards D"\n',
            "[input] vs_C",
            "towards which end of the rod OA",
        ),
        (
            "[ground]\nO = [0, 0]\nD = [0.3, 0]\n[links]\nOA = 0.5\nDC = 0.15\n[sliders]\n"
            'C = { along = "OA" }\n[input]\nblock = "C"\ns_C = 0.35\nvs_C = "1 m/s"\n'
            'speed = "3 rad/s"\n',
            "[input] speed",
            "there is no crank",
        ),
        (
            "[ground]\nO = [0, 0]\nD = [0.3, 0]\n[links]\nOA = 0.5\nDC = 0.15\n[sliders]\n"
            'C = { along = "OA" }\n[input]\nblock = "C"\ns_C = 0.7\nvs_C = "1 m/s"\n',
            "collar C on the rod OA",
            "its dead centres",
        ),
    ],
)
def test_bad_collar_input_is_one_line(tmp_path, capsys, text, key, words):
    f = tmp_path / "bad.toml"
    f.write_text(text)
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and key in err and words in err, err


def test_the_other_views_run(tmp_path, capsys):
    """centres (the rod's omega from the sliding, the ratio theorem for DC), draw, page,
    the summary over the travel, variants."""
    f = tmp_path / "c.toml"
    f.write_text(
        scene_text(*CASES[0]) + "\n[variants]\nDC = { from = 0.14, to = 0.16, step = 0.005 }\n"
    )
    sol = solve(parse_scene(scene_text(*CASES[0])))
    assert main(["centres", str(f)]) == 0
    out = capsys.readouterr().out
    assert f"{abs(sol.W['DC']):.4g} rad/s cw" in out
    assert main(["draw", str(f), "-o", str(tmp_path / "c.svg")]) == 0
    assert main(["page", str(f), "-o", str(tmp_path / "c.html")]) == 0
    assert main(["sweep", "--summary", str(f)]) == 0
    out = capsys.readouterr().out
    assert "the rod OA's line passes through D" in out
    assert main(["variants", str(f), "-o", str(tmp_path / "v"), "--count", "3"]) == 0
    assert compile_plan(parse_scene(scene_text(*CASES[0]))).steps[0].kind == "collar"


def test_the_force_analysis_with_masses_is_given(tmp_path, capsys):
    """With masses the force analysis is solved (no longer refused): the driver's force
    along the rod with inertia, beside the power balance's without it (tests/
    test_collar_forces.py holds it to the matrix method)."""
    f = tmp_path / "m.toml"
    f.write_text(scene_text(*CASES[0]) + "\n[masses]\nOA = { mass = 2 }\n")
    assert main(["solve", str(f)]) == 0
    out = capsys.readouterr().out
    assert "not solved for forces" not in out
    assert (
        len([ln for ln in out.splitlines() if ln.startswith("input force on collar C along")]) == 1
    )


# ----- the collar as the second input: the rod turned by the crank, the collar sliding

TWO = """
title = "two"
units = "m"
[ground]
O = [0, 0]
[links]
OA = {L}
CB = {l}
[sliders]
C = {{ along = "O-A" }}
B = {{ path = "horizontal", through = "O" }}
[assembly]
B = "right"
[input]
crank = "OA"
angle = {th}
speed = "{w} rad/s"
acceleration = {al}
[input.second]
block = "C"
s_C = {s}
vs_C = "{vs} m/s"
as_C = "{acc} m/s^2"
"""


def two_text(L, l, th, w, al, s, vs, acc):
    def turn(x, unit):
        return f"{abs(x)} {unit} {'ccw' if x >= 0 else 'cw'}"

    return TWO.format(
        L=L, l=l, th=th, w=abs(w), al=f'"{turn(al, "rad/s^2")}"' if al else 0, s=s, vs=vs, acc=acc
    ).replace(f'speed = "{abs(w)} rad/s"', f'speed = "{turn(w, "rad/s")}"')


TWO_CASES = [  # OA, CB, theta (deg), omega, alpha, s, vs, as
    (1.0, 0.6, 40, 3.0, 0.0, 0.5, 2.0, 1.0),
    (0.8, 0.9, 120, -2.0, 5.0, 0.3, -1.5, 0.5),
    (1.2, 0.7, -30, 4.0, -1.0, -0.4, 0.6, -3.0),  # the collar beyond the pivot
]


def two_closed_form(L, l, th, w, al, s0, vs, acc):
    """C = s (cos t, sin t), x_B = x_C + sqrt(l^2 - y_C^2), with t(t) and s(t) given."""
    th, w, al, s0, vs, acc, l = (mpf(x) for x in (math.radians(th), w, al, s0, vs, acc, l))

    def C(t, k):
        a, s = th + w * t + al * t * t / 2, s0 + vs * t + acc * t * t / 2
        return s * (mpmath.cos(a) if k == 0 else mpmath.sin(a))

    def xB(t):
        return C(t, 0) + mpmath.sqrt(l * l - C(t, 1) ** 2)

    def cb(t):  # the direction C -> B
        return mpmath.atan2(-C(t, 1), xB(t) - C(t, 0))

    d = mpmath.diff
    return {
        "v_C": tuple(d(lambda t, k=k: C(t, k), 0, 1) for k in (0, 1)),
        "a_C": tuple(d(lambda t, k=k: C(t, k), 0, 2) for k in (0, 1)),
        "v_B": d(xB, 0, 1),
        "a_B": d(xB, 0, 2),
        "omega_CB": d(cb, 0, 1),
        "alpha_CB": d(cb, 0, 2),
    }


@pytest.mark.parametrize("case", TWO_CASES)
def test_two_inputs_agree_with_the_closed_form_and_the_reference(case):
    L, l, th, w, al, s, vs, acc = case
    sc = parse_scene(two_text(*case))
    sol = solve(sc)
    want = two_closed_form(*case)
    V = float(mpmath.norm(want["v_C"])) + abs(float(want["v_B"]))
    Aw = float(mpmath.norm(want["a_C"])) + abs(float(want["a_B"]))
    for k in (0, 1):
        assert close(sol.V["C"][k], want["v_C"][k], V)
        assert close(sol.A["C"][k], want["a_C"][k], Aw)
    assert close(sol.V["B"][0], want["v_B"], V)
    assert close(sol.A["B"][0], want["a_B"], Aw)
    ww = abs(float(want["omega_CB"])) + abs(w)
    assert close(sol.W["CB"], want["omega_CB"], ww)
    assert close(sol.Al["CB"], want["alpha_CB"], abs(float(want["alpha_CB"])) + ww * ww)
    assert math.isclose(math.hypot(*sol.coriolis("C")), 2 * abs(w * vs), rel_tol=1e-12)
    err, what = worst_error(sc, sol, reference_solution(sc, sol.P))
    assert err < REL, what


def test_two_inputs_superpose_in_the_steps(tmp_path, capsys):
    """v = v' + v'': the rod's turning alone (the collar held on it) gives C the rod's
    point's velocity; the collar's sliding alone gives C vs along the rod."""
    case = TWO_CASES[0]
    f = tmp_path / "two.toml"
    f.write_text(two_text(*case))
    assert main(["steps", str(f)]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "drawn for OA alone (the collar C held), then for the collar C alone (OA held)" in out
    # C: OA alone, omega x OC = 3 x 0.5 = 1.5 m/s at 130 deg; the collar alone 2 m/s at 40
    assert "C 1.5 m/s at 130 deg 2 m/s at 40 deg" in out
    assert "from c1 draw c1c = 2 m/s along OA" in out
    assert main(["solve", "--json", str(f)]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["input"]["second"]["collar"] and d["input"]["second"]["vs"] == 2.0


@pytest.mark.parametrize(
    "text, key, words",
    [
        # a collar on a rod the first crank does not turn
        (
            two_text(1, 0.6, 40, 3, 0, 0.5, 2, 0)
            .replace("[ground]\nO = [0, 0]\n", "[ground]\nO = [0, 0]\nQ = [0.5, 0]\n")
            .replace("[links]\nOA = 1\n", "[links]\nOA = 1\nQR = 0.3\nRA = 0.8\n")
            .replace('crank = "OA"', 'crank = "QR"'),
            "[input.second] block",
            "which is not the crank QR",
        ),
        # the collar pinned to a crank as well: one input too many (mobility 1)
        (
            two_text(1, 0.6, 40, 3, 0, 0.5, 2, 0)
            .replace("[ground]\nO = [0, 0]\n", "[ground]\nO = [0, 0]\nD = [0.3, 0]\n")
            .replace("[links]\n", "[links]\nDC = 0.3\n"),
            "[input.second]",
            "two inputs over-determine the chain",
        ),
        # a block on a fixed guide given a velocity beside the crank's speed
        (
            "[ground]\nO = [0, 0]\n[links]\nOA = 0.1\nAB = 0.4\n[sliders]\nB = { path = "
            '"horizontal" }\n[input]\ncrank = "OA"\nangle = 30\nspeed = "10 rad/s"\n'
            'vs_B = "1 m/s"\n',
            "[input] vs_B",
            "one input only",
        ),
        (
            "[ground]\nO = [0, 0]\n[links]\nOA = 0.1\nAB = 0.4\n[sliders]\nB = { path = "
            '"horizontal" }\n[input]\ncrank = "OA"\nangle = 30\nspeed = "10 rad/s"\n'
            '[input.second]\nblock = "B"\ns_B = 0.45\nvs_B = "1 m/s"\n',
            "[input.second] block",
            "a block on a fixed guide as a second input is not solved",
        ),
    ],
)
def test_bad_two_input_collars_are_one_line(tmp_path, capsys, text, key, words):
    f = tmp_path / "bad.toml"
    f.write_text(text)
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and key in err and words in err, err


@pytest.mark.parametrize("case", CASES)
def test_the_one_instant_road_is_the_phased_road_to_the_last_bit(case):
    """The collar's bind_instant (its frame made once) against its three phases."""
    from polygon_method.solver.plan import Context

    sc = parse_scene(scene_text(*case))
    sol = solve(sc)
    plan = compile_plan(sc)
    inp = sc.input
    m = plan.run(Context(inp.angle, inp.omega, inp.alpha), plan.dims)
    for mine, theirs in (
        (sol.P, m.P),
        (sol.V, m.V),
        (sol.A, m.A),
        (sol.W, m.W),
        (sol.Al, m.Al),
        (sol.S, m.S),
        (sol.cond, m.cond),
    ):
        assert sorted(mine.items()) == sorted(theirs.items())


def test_the_checker_finds_the_second_inputs_coriolis_left_out(tmp_path, capsys):
    """a_C without 2 omega vs: |a_C - cor|, by hand from the closed form's a_C."""
    case = TWO_CASES[0]
    want = two_closed_form(*case)
    w, vs = case[3], case[6]
    th = math.radians(case[2])
    cor = (-2 * w * vs * math.sin(th), 2 * w * vs * math.cos(th))  # 2 omega vs perp(w)
    wrong = math.hypot(float(want["a_C"][0]) - cor[0], float(want["a_C"][1]) - cor[1])
    f, a = tmp_path / "two.toml", tmp_path / "a.toml"
    f.write_text(two_text(*case))
    a.write_text(f'[answers]\na_C = "{wrong:.4f} m/s^2"\n')
    assert main(["check", str(f), str(a)]) == 1
    out = " ".join(capsys.readouterr().out.split())
    assert "the Coriolis component 2 omega v of collar C sliding along OA" in out
