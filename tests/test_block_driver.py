"""A block on a fixed guide as the driver ([input] block): no link turns about the frame.

Compared with the ellipse trammel's closed form (A on the horizontal guide, B on the
vertical one through O, rod AB = L at angle t to the horizontal: x_A = L cos t,
y_B = L sin t, a point C of AB at AC = d: C = ((L - d) cos t, d sin t), an ellipse), with
the 50-digit constraint solve of tests/reference.py (the block's place along its path as
the parameter), and with finite differences of the solver's own positions in the
block's place.
"""

import json
import math

import mpmath
import numpy as np
import pytest
from mpmath import mpf

from drivers import check_derivatives, close, every_view, one_line, reference_errors
from polygon_method import load_scene, parse_scene, solve
from polygon_method.cli import main
from polygon_method.solver.compiler import compile_plan
from polygon_method.motion.sweeps import sweep

TRAMMEL = """
title = "trammel"
units = "mm"
[ground]
O = [0, 0]
[links]
AB = {L}
[points]
C = {{ on = "AB", along = {d} }}
[sliders]
A = {{ path = "horizontal", through = "O" }}
B = {{ path = "vertical", through = "O" }}
[assembly]
B = "above"
[input]
block = "A"
s_A = {s}
vs_A = "{vs} m/s"
as_A = "{acc} m/s^2"
{extra}
"""

CASES = [  # L, d (AC), s_A (mm), vs_A (m/s), as_A (m/s^2)
    (500, 700, 300, 2.0, -5.0),
    (500, 250, -120, -1.5, 3.0),
    (400, -150, 390, 0.7, 0.0),
    (650, 1000, 10, 4.0, 12.5),
]


def trammel(L, d, s, vs, acc, extra=""):
    return TRAMMEL.format(L=L, d=d, s=s, vs=vs, acc=acc, extra=extra)


def closed_form(L, d, s, vs, acc):
    """The trammel's positions, velocities, accelerations and the rod's omega, alpha (SI,
    from the angle t of A -> B's mirror: x_A = L cos t, y_B = L sin t)."""
    L, d, x = L / 1000, d / 1000, s / 1000
    t = math.acos(x / L)
    st, ct = math.sin(t), math.cos(t)
    td = -vs / (L * st)  # x_A' = -L sin t t'
    tdd = -(acc + L * ct * td * td) / (L * st)  # x_A'' = -L cos t t'^2 - L sin t t''
    a, b = L - d, d

    def pos(p, q):
        return (p * ct, q * st)

    def vel(p, q):
        return (-p * st * td, q * ct * td)

    def accel(p, q):
        return (-p * ct * td * td - p * st * tdd, -q * st * td * td + q * ct * tdd)

    return {
        "P": {"A": pos(L, 0), "B": pos(0, L), "C": pos(a, b)},
        "V": {"A": vel(L, 0), "B": vel(0, L), "C": vel(a, b)},
        "A": {"A": accel(L, 0), "B": accel(0, L), "C": accel(a, b)},
        # the rod A -> B points at pi - t: omega = -t', alpha = -t''
        "omega": -td,
        "alpha": -tdd,
        "vs_B": L * ct * td,
        "as_B": -L * st * td * td + L * ct * tdd,
    }


@pytest.mark.parametrize("case", CASES)
def test_solve_matches_the_closed_form(case):
    sol = solve(parse_scene(trammel(*case)))
    cf = closed_form(*case)
    vscale = max(math.hypot(*v) for v in cf["V"].values())
    ascale = max(math.hypot(*a) for a in cf["A"].values())
    for p in "ABC":
        assert close(sol.P[p], cf["P"][p], case[0] / 1000), p
        assert close(sol.V[p], cf["V"][p], vscale), p
        assert close(sol.A[p], cf["A"][p], ascale), p
    assert close(sol.W["AB"], cf["omega"], 0.0)
    assert close(sol.Al["AB"], cf["alpha"], ascale / (case[0] / 1000))
    assert close(sol.S["B"][0], cf["vs_B"], vscale)
    assert close(sol.S["B"][1], cf["as_B"], ascale)
    assert sol.S["A"][0] == case[3] and sol.S["A"][1] == case[4]  # the given motion


def test_point_c_traces_the_ellipse():
    L, d = 500, 700
    res = sweep(parse_scene(trammel(L, d, 300, 2.0, -5.0)))
    x, y = (np.asarray(c) for c in res.P["C"])
    a, b = (L - d) / 1000, d / 1000
    assert len(res) > 300
    assert np.max(np.abs((x / a) ** 2 + (y / b) ** 2 - 1.0)) < 1e-12


def test_solve_json_matches_the_closed_form(tmp_path, capsys):
    case = CASES[0]
    f = tmp_path / "t.toml"
    f.write_text(trammel(*case))
    assert main(["solve", "--json", str(f)]) == 0
    d = json.loads(capsys.readouterr().out)
    cf = closed_form(*case)
    assert d["input"] == {"block": "A", "s": 0.3, "vs": 2.0, "as": -5.0, "direction": [1.0, 0.0]}
    assert d["steps"][0]["kind"] == "block"
    for p in "BC":
        pt = d["points"][p]
        assert close(tuple(pt["velocity"]), cf["V"][p], 1.0)
        assert close(tuple(pt["acceleration"]), cf["A"][p], 1.0)
    assert close(d["links"]["AB"]["omega"], cf["omega"], 0.0)
    assert close(d["links"]["AB"]["alpha"], cf["alpha"], 0.0)
    assert close(d["sliders"]["B"]["sliding_velocity"], cf["vs_B"], 1.0)


def test_steps_draw_the_given_velocity_first(tmp_path, capsys):
    case = CASES[0]
    f = tmp_path / "t.toml"
    f.write_text(trammel(*case))
    assert main(["steps", str(f)]) == 0
    text = " ".join(capsys.readouterr().out.split())  # the lines as one (wrapped text)
    assert "2. Input block A" in text
    assert "from o draw oa = 2 m/s along the guide (to the right)" in text
    assert "from o' draw o'a' = 5 m/s^2 along the guide (to the left)" in text
    cf = closed_form(*case)
    assert f"= {abs(cf['omega']):.4g} rad/s ccw" in text
    assert f"= {abs(cf['alpha']):.4g} rad/s^2 ccw" in text


def test_steady_block_has_no_acceleration_vector(tmp_path, capsys):
    f = tmp_path / "t.toml"
    f.write_text(trammel(400, -150, 390, 0.7, 0.0))
    assert main(["steps", str(f)]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "a' is at o': the block A moves steadily" in text
    assert "as_A = 0 (the block moves at a steady speed)" in text


def test_sweep_over_the_travel_matches_the_closed_form():
    L, d, vs, acc = 500, 250, -1.5, 3.0
    res = sweep(parse_scene(trammel(L, d, -120, vs, acc)))
    assert res.domain.lo == pytest.approx(-L / 1000, abs=1e-9)
    assert res.domain.hi == pytest.approx(L / 1000, abs=1e-9)
    errs = []
    for k in range(0, len(res), 7):
        s = float(res.theta[k]) * 1000
        cf = closed_form(L, d, s, vs, acc)
        for p in "BC":
            v = (float(res.V[p][0][k]), float(res.V[p][1][k]))
            a = (float(res.A[p][0][k]), float(res.A[p][1][k]))
            vscale = max(math.hypot(*x) for x in cf["V"].values())
            ascale = max(math.hypot(*x) for x in cf["A"].values())
            if not (close(v, cf["V"][p], vscale) and close(a, cf["A"][p], ascale)):
                errs.append((s, p))
        if not close(float(res.W["AB"][k]), cf["omega"], 0.0):
            errs.append((s, "omega"))
    assert not errs


def test_sweep_csv_and_summary(tmp_path, capsys):
    f = tmp_path / "t.toml"
    f.write_text(trammel(500, 700, 300, 2.0, -5.0))
    out = tmp_path / "s.csv"
    assert (
        main(["sweep", str(f), "--from", "-400", "--to", "400", "--step", "100", "--csv", str(out)])
        == 0
    )
    rows = out.read_text().splitlines()
    assert rows[0].startswith("s_A [m],")
    s = [float(r.split(",")[0]) for r in rows[1:]]
    assert s == pytest.approx([k / 10 for k in range(-4, 5)], abs=1e-15)
    head = rows[0].split(",")
    i = head.index("vy_B [m/s]")
    for r in rows[1:]:  # y_B' = -x_A x_A' / y_B
        x = float(r.split(",")[0])
        assert float(r.split(",")[i]) == pytest.approx(
            -x * 2.0 / math.sqrt(0.25 - x * x), rel=1e-9, abs=1e-12
        )
    capsys.readouterr()
    assert main(["sweep", str(f), "--steps", "100"]) == 0
    text = capsys.readouterr().out
    assert "the block A travels from s_A = -500 to 500 mm" in text
    assert "at (mm)" in text and "at (deg)" not in text


def test_stated_stroke_bounds_the_sweep():
    sc = parse_scene(trammel(500, 700, 300, 2.0, -5.0, "stroke = [-200, 400]"))
    res = sweep(sc)
    assert float(res.theta[0]) == pytest.approx(-0.2) and float(res.theta[-1]) == pytest.approx(0.4)
    assert res.left_out == 0


# --------------------------------------------------------------------------- the reference

REFERENCE_SCENES = [
    # inclined guides and a point off the rod
    """
[ground]
O = [0, 0]
[links]
AB = 420
[points]
C = { on = "AB", distances = { A = 300, B = 200 }, turn = "ccw" }
[sliders]
A = { path = "20 deg", through = "O" }
B = { path = "110 deg", through = [30, -40] }
[assembly]
B = "above"
[input]
block = "A"
s_A = 150
vs_A = "1.2 m/s"
as_A = "-7 m/s^2"
""",
    # a block driving a rocker through a coupler (the crank is not the parameter)
    """
[ground]
Q = [0, 0]
R = [400, 250]
[links]
AB = 300
"R-B" = 200
[sliders]
A = { path = "horizontal", through = "Q" }
[assembly]
B = "above"
[input]
block = "A"
A = [250, 0]
vs_A = "0.8 m/s left"
as_A = "2 m/s^2 right"
""",
    # two blocks and a second slider driven from a point on the rod
    """
[ground]
O = [0, 0]
[links]
AB = 600
CD = 350
[points]
C = { on = "AB", along = 250 }
[sliders]
A = { path = "vertical", through = "O" }
B = { path = "horizontal", through = [0, -100] }
D = { path = "30 deg", through = [500, 0] }
[assembly]
B = "right"
D = "above"
[input]
block = "A"
s_A = 200
vs_A = "3 m/s down"
""",
]


@pytest.mark.parametrize("text", REFERENCE_SCENES)
def test_solver_matches_the_50_digit_reference(text):
    assert not reference_errors(text, sliders=True)


@pytest.mark.parametrize("text", REFERENCE_SCENES)
def test_velocities_are_the_derivatives_of_the_positions(text):
    """dP/dt = dP/ds vs and d2P/dt2 = d2P/ds2 vs^2 + dP/ds as, the derivatives in the
    block's place s by central differences of the solver's own positions."""
    check_derivatives(text)


def test_centres_give_the_rod_its_omega(tmp_path, capsys):
    from polygon_method.solver.centres import locate

    case = CASES[0]
    sol = solve(parse_scene(trammel(*case)))
    ic = locate(sol)
    cf = closed_form(*case)
    i13 = ic.centres[(1, 3)].point  # the rod's centre with the ground: (x_A, y_B)
    assert close(i13, (cf["P"]["A"][0], cf["P"]["B"][1]), 0.5)
    assert close(ic.omega(3), cf["omega"], 0.0)


def test_the_worked_problem_checks():
    from polygon_method.check import check_answers

    sc = load_scene("worked_problems/ellipse_trammel.toml")
    verdicts = check_answers(solve(sc), sc.answers, sc.tolerance)
    assert len(verdicts) == 7 and all(v.ok for v in verdicts), verdicts


# --------------------------------------------------------------------------- every view, refusals


def test_every_view_takes_a_block_driver(tmp_path, capsys):
    f = tmp_path / "t.toml"
    f.write_text(
        trammel(500, 700, 300, 2.0, -5.0)
        + '[loads]\nB = { force = [0, -100] }\n[answers]\nomega_AB = "5 rad/s ccw"\n'
        + "[variants]\nAB = { from = 480, to = 520, step = 10 }\n"
    )
    every_view(f, tmp_path, more=[["variants", "--count", "2", "-o", str(tmp_path / "v")]])
    out = capsys.readouterr().out
    # the input force along the guide: F vs_A + F_B . v_B = 0
    assert "input force on block A: 75 N to the left along the guide" in out


BAD = [
    ('block = "Z"\nvs_A = "2 m/s"\ns_A = 300', "no block Z"),
    ('block = "A"\ns_A = 300', "has no vs_A"),
    ('block = "A"\nvs_A = "2 m/s"', "not at all"),
    ('block = "A"\nvs_A = "2 m/s"\ns_A = 300\nA = [300, 0]', "twice"),
    ('block = "A"\nvs_A = "2 m/s"\ns_A = 300\ncrank = "AB"', "there is no crank"),
    ('block = "A"\nvs_A = "2 m/s"\ns_A = 300\nspeed = "3 rad/s cw"', "there is no crank"),
    ('block = "A"\nvs_A = "2 m/s"\nA = [300, 10]', "off the guide"),
    ('block = "A"\nvs_A = "0 m/s"\ns_A = 300', "zero"),
    ('block = "A"\nvs_A = "2 m/s up"\ns_A = 300', "perpendicular"),
    ('block = "A"\nvs_A = "2 m/s"\ns_A = 300\nstroke = [-100, 200]', "outside its stroke"),
    ('block = "A"\nvs_A = "2 m/s"\ns_A = 300\nstroke = [400, 200]', "less than"),
    (
        'block = "A"\nvs_A = "2 m/s"\ns_A = 600',
        "can be placed only from s_A = about -500 to 500 mm",
    ),
]


@pytest.mark.parametrize("given, words", BAD)
def test_bad_block_input_one_line(tmp_path, capsys, given, words):
    text = TRAMMEL.split("[input]")[0].format(L=500, d=700) + "[input]\n" + given + "\n"
    f = tmp_path / "s.toml"
    f.write_text(text)
    assert main(["solve", str(f)]) == 2
    err = one_line(capsys)
    assert words in err, err
    assert "[input]" in err or "step 2" in err, err  # the key, or the step that fails


def test_a_torque_answer_is_refused(tmp_path, capsys):
    f = tmp_path / "t.toml"
    f.write_text(
        trammel(500, 700, 300, 2.0, -5.0)
        + '[loads]\nB = { force = [0, -100] }\n[answers]\ntorque = "3 N m"\n'
    )
    assert main(["check", str(f)]) == 2
    err = one_line(capsys)
    assert "a force along its guide" in err


def test_a_centre_answer_is_checked(tmp_path, capsys):
    f = tmp_path / "t.toml"  # I13 of the trammel: where the normals to the guides meet
    f.write_text(trammel(500, 700, 300, 2.0, -5.0) + "[answers]\nI_13 = [300, 400]\n")
    assert main(["check", str(f)]) == 0
    assert "1 of 1 right" in capsys.readouterr().out


def test_linkage_refuses_in_one_line(tmp_path, capsys):
    f = tmp_path / "t.toml"
    f.write_text(trammel(500, 700, 300, 2.0, -5.0))
    assert main(["linkage", str(f)]) == 2
    err = one_line(capsys)
    assert "block A" in err and "sweep" in err


def test_variants_refuse_a_crank_angle(tmp_path, capsys):
    f = tmp_path / "t.toml"
    f.write_text(
        trammel(500, 700, 300, 2.0, -5.0)
        + "[variants]\nangle = { from = 10, to = 30, step = 10 }\n"
    )
    assert main(["variants", str(f), "-o", str(tmp_path / "v")]) == 2
    err = one_line(capsys)
    assert "no crank angle to vary" in err


PARALLEL = """
[ground]
O = [0, 0]
[links]
AB = 300
[sliders]
A = { path = "horizontal", through = "O" }
B = { path = "horizontal", through = [0, 200] }
[assembly]
B = "right"
[input]
block = "A"
s_A = 0
vs_A = "1 m/s"
"""


def test_unbounded_travel_asks_for_a_stroke(tmp_path, capsys):
    """Two blocks on parallel guides: nothing stops A, so the sweep needs its stroke."""
    f = tmp_path / "t.toml"
    f.write_text(PARALLEL)
    assert main(["solve", str(f)]) == 0
    capsys.readouterr()
    assert main(["sweep", str(f)]) == 2
    err = one_line(capsys)
    assert "stroke = [from, to]" in err
    f.write_text(PARALLEL.replace("s_A = 0", "s_A = 0\nstroke = [-500, 500]"))
    res = sweep(load_scene(f))
    assert float(res.theta[0]) == pytest.approx(-0.5) and np.allclose(res.V["B"][0], 1.0)


# ----- a block driver through a change point: the sweep's offsets are in the driver's scale

#: block A on the horizontal guide through Q = (0, e), link AB = L, B on the circle OB = R
#: about O = (0, 0), with L = R + e: at s_A = 0, A, O and B are in line and the two
#: assemblies of B meet (d = |OA| = e = L - R touches the dyad's limit and leaves it).
CHANGE = """
units = "mm"
[ground]
O = [0, 0]
Q = [0, {e}]
[links]
AB = {L}
OB = {R}
[sliders]
A = {{ path = "horizontal", through = "Q" }}
[assembly]
B = [{bx:.4f}, {by:.4f}]
[input]
block = "A"
s_A = {s}
vs_A = "{vs} m/s"
as_A = "{acc} m/s^2"
"""


def _change_point_b(R, e, s):
    """B on the branch that passes through the change point smoothly (50 digits, SI, s in
    m): with B = R (sin psi, -cos psi) the loop |B - A| = L = R + e is
    s^2 - 2 R s sin psi - 2 R e (1 - cos psi) = 0, whose root through psi = 0 is
    tan(psi / 2) = s / (2 R + sqrt(4 R (R + e) - s^2)) (analytic across s = 0)."""
    R, e, s = mpf(R), mpf(e), mpf(s)
    psi = 2 * mpmath.atan(s / (2 * R + mpmath.sqrt(4 * R * (R + e) - s * s)))
    return R * mpmath.sin(psi), -R * mpmath.cos(psi), psi


@pytest.mark.parametrize("R, e, vs, acc", [(40, 60, 2.0, -3.0), (25, 200, -0.5, 7.0)])
def test_sweep_through_a_change_point_keeps_every_place_within_its_bound(R, e, vs, acc):
    """Every place sampled near the change point is kept (the offsets the sweep takes
    there are lengths in the driver's scale, not radians read as metres), and B's
    position, velocity and acceleration, and omega of OB, are those of the closed form
    (differentiated at 50 digits) within the sweep's own error bound of each."""
    mpmath.mp.dps = 50
    Rm, em = R / 1000, e / 1000
    s0 = -0.75 * R / 1000  # the scene's instant, on the smooth branch
    bx, by, _ = _change_point_b(Rm, em, s0)
    sc = parse_scene(
        CHANGE.format(
            e=e, L=R + e, R=R, s=s0 * 1000, bx=float(bx) * 1000, by=float(by) * 1000, vs=vs, acc=acc
        )
    )
    places = (
        np.array([-0.3, -1e-2, -1e-3, -3e-4, -1e-5, -1e-8, 1e-8, 1e-5, 3e-4, 1e-3, 1e-2, 0.3]) * Rm
    )
    res = sweep(sc, places)
    cps = res.domain.change_points
    assert len(cps) == 1 and cps[0].followed
    assert abs(cps[0].theta) < 1e-7 * Rm  # at s_A = 0, as the closed form has it (found
    # by zooming on the condition's minimum: to about 1e-8 of the scale)
    assert len(res) == len(places)  # none left out as unclosed next to the change point
    eb = res.error_bounds
    size = {k: np.broadcast_to(v, (len(res),)) for k, v in eb.scales.items()}
    for i, s in enumerate(np.asarray(res.theta)):
        x = lambda t: _change_point_b(Rm, em, t)[0]  # noqa: E731
        y = lambda t: _change_point_b(Rm, em, t)[1]  # noqa: E731
        psi = lambda t: _change_point_b(Rm, em, t)[2]  # noqa: E731
        want_p = (x(s), y(s))
        d1 = (mpmath.diff(x, s, 1), mpmath.diff(y, s, 1))
        d2 = (mpmath.diff(x, s, 2), mpmath.diff(y, s, 2))
        want_v = tuple(d * vs for d in d1)
        want_a = tuple(dd * vs * vs + d * acc for d, dd in zip(d1, d2))
        want_w = mpmath.diff(psi, s, 1) * vs  # OB turns with psi
        for got, want, bound, kind in (
            (res.P["B"], want_p, eb.P["B"], "position"),
            (res.V["B"], want_v, eb.V["B"], "velocity"),
            (res.A["B"], want_a, eb.A["B"], "acceleration"),
        ):
            err = math.hypot(float(got[0][i] - want[0]), float(got[1][i] - want[1]))
            b = float(np.broadcast_to(bound, (len(res),))[i])
            assert err <= b * float(size[kind][i]), (kind, s, err, b)
        err = abs(float(res.W["OB"][i] - want_w))
        b = float(np.broadcast_to(eb.W["OB"], (len(res),))[i])
        assert err <= b * float(size["omega"][i]), ("omega", s, err, b)


def test_the_block_states_the_scale_of_its_place():
    """A crank's parameter is its angle (a radian is 1); a block's place is a length: the
    shortest link pinned to it, and no more than a stated stroke over 2 pi."""
    sc = parse_scene(trammel(500, 700, 300, 2.0, -5.0))
    assert compile_plan(sc).steps[0].parameter_scale(sc) == 0.5
    sc = parse_scene(trammel(500, 700, 300, 2.0, -5.0, "stroke = [-100, 400]"))
    assert math.isclose(
        compile_plan(sc).steps[0].parameter_scale(sc), 0.5 / (2 * math.pi), rel_tol=1e-15
    )


# ----- a block on a moving guide as the driver: refused in one located line, saying why

ROD = """
units = "m"
[ground]
O = [0, 0]
[links]
OA = 1.0
[sliders]
B = {{ along = "OA" }}
[input]
{input}
"""


@pytest.mark.parametrize(
    "given, key, words",
    [
        (
            'block = "B"\ns_B = 0.5\nvs_B = "1.5 m/s"',
            "[sliders] B",
            "mobility 2 (Gruebler: 3(n-1) - 2j): the collar B's sliding along OA sets one motion; "
            "the rod's turning needs one more relation",
        ),
        (
            'crank = "OA"\nangle = 30\nspeed = "2 rad/s ccw"',
            "[sliders] B",
            "mobility 2 (Gruebler: 3(n-1) - 2j): the mechanism is under-constrained; the block B "
            "slides freely along its guide",
        ),
    ],
    ids=["as the block", "beside the crank"],
)
def test_a_block_driven_along_a_turning_rod_is_refused_in_one_line(
    tmp_path, capsys, given, key, words
):
    """ "The collar slides along the rotating rod at 1.5 m/s relative to it", with nothing
    else pinned to the collar: the collar's sliding alone, or the rod's turning alone, is
    one input of a mechanism of two (a free block on a turning rod is no over-constrained
    chain: its mobility is 2, n = 3 bodies, j = 2 joints); said so where the scene states
    it, with what would complete it."""
    f = tmp_path / "rod.toml"
    f.write_text(ROD.format(input=given))
    assert main(["solve", str(f)]) == 2
    err = one_line(capsys)
    assert words in err and key in err, err
    assert "[input.second] block" in err and "over-constrained" not in err, err
