"""A wheel rolling without slip on a ground line as the only driver ([input] wheel).

Compared with the closed form of the classic problem derived here (the wheel of radius r on
the ground y = 0, its centre C = (s, r); a rod AB pinned to the wheel at A, at l from C and
at angle phi, its end B sliding on a horizontal guide y = h; rolling without slip: phi' =
omega = -s' / r), with the 50-digit constraint solve of tests/reference.py (the centre's
place along the ground line as the parameter; an inclined line, a vertical guide), and with
finite differences of the solver's own positions in the centre's place.
"""

import json
import math

import pytest

from drivers import check_derivatives, close, every_view, one_line, reference_errors
from polygon_method import load_scene, parse_scene, solve
from polygon_method.cli import main
from polygon_method.motion.sweeps import stroke_places, sweep

WHEEL = """
title = "wheel, rod and slider"
units = "mm"
[ground]
O = [0, 0]
[links]
CA = {l}
AB = {L}
[sliders]
B = {{ path = "horizontal", through = [0, {h}] }}
[rolling]
CA = {{ on = "horizontal", through = [0, 0], radius = {r}, angle = {phi} }}
[assembly]
B = "right"
[input]
wheel = "CA"
s_C = {s}
omega_CA = "{w}"
alpha_CA = "{al}"
{extra}
"""

CASES = [  # r, l (CA), phi0 (deg), L, h, s (mm), omega, alpha (rad/s, rad/s^2, ccw +)
    (300, 300, 90, 1000, 0, 0, -4.0, 2.0),  # the book's: pinned to the rim at the top
    (300, 300, 30, 1200, 150, 250, 5.0, -3.0),
    (250, 150, 200, 900, 100, -400, -2.5, 0.0),  # a pin on a spoke
    (400, 400, -60, 1500, -50, 1000, 1.2, 7.5),
]


def scene_text(r, l, phi, L, h, s, w, al, extra=""):
    def ang(x, unit):
        return f"{abs(x)} {unit} {'ccw' if x > 0 else 'cw'}" if x else f"0 {unit}"

    return WHEEL.format(
        r=r, l=l, phi=phi, L=L, h=h, s=s, w=ang(w, "rad/s"), al=ang(al, "rad/s^2"), extra=extra
    )


def closed_form(r, l, phi, L, h, s, w, al):
    """Positions, velocities and accelerations of C, A, B (SI), the rod's omega and alpha
    and the contact point's acceleration, derived by hand (see the module)."""
    r, l, L, h, s = r / 1000, l / 1000, L / 1000, h / 1000, s / 1000
    p = math.radians(phi)
    c, sn = math.cos(p), math.sin(p)
    vs, a_s = -w * r, -al * r  # no slip: s' = -omega r (rolling right is clockwise)
    C, vC, aC = (s, r), (vs, 0.0), (a_s, 0.0)
    A = (s + l * c, r + l * sn)
    vA = (vs - l * w * sn, l * w * c)
    aA = (a_s - l * al * sn - l * w * w * c, l * al * c - l * w * w * sn)
    dy = A[1] - h
    q = math.sqrt(L * L - dy * dy)
    q1 = -dy * vA[1] / q
    q2 = -(vA[1] ** 2 + dy * aA[1] + q1 * q1) / q
    B, vB, aB = (A[0] + q, h), (vA[0] + q1, 0.0), (aA[0] + q2, 0.0)
    rel = (B[0] - A[0], B[1] - A[1])

    def cross(a, b):
        return a[0] * b[1] - a[1] * b[0]

    wAB = cross(rel, (vB[0] - vA[0], vB[1] - vA[1])) / (L * L)
    aAB = cross(rel, (aB[0] - aA[0], aB[1] - aA[1])) / (L * L)
    return {
        "P": {"C": C, "A": A, "B": B},
        "V": {"C": vC, "A": vA, "B": vB},
        "A": {"C": aC, "A": aA, "B": aB},
        "omega_AB": wAB,
        "alpha_AB": aAB,
        "aI": (0.0, w * w * r),
    }  # the contact point: omega^2 r, up towards the centre


@pytest.mark.parametrize("case", CASES)
def test_solve_matches_the_closed_form(case):
    sol = solve(parse_scene(scene_text(*case)))
    cf = closed_form(*case)
    for key, got in (("P", sol.P), ("V", sol.V), ("A", sol.A)):
        scale = max(math.hypot(*v) for v in cf[key].values())
        for p in "CAB":
            assert close(tuple(got[p]), cf[key][p], scale), (key, p, got[p], cf[key][p])
    w, al = case[6], case[7]
    assert close(sol.W["CA"], w, 0.0) and close(sol.Al["CA"], al, abs(w))
    assert close(sol.W["AB"], cf["omega_AB"], abs(w))
    assert close(sol.Al["AB"], cf["alpha_AB"], w * w + abs(al))


@pytest.mark.parametrize("case", CASES[:2])
def test_json_gives_the_wheel_and_its_contact(case, tmp_path, capsys):
    f = tmp_path / "w.toml"
    f.write_text(scene_text(*case))
    assert main(["solve", "--json", str(f)]) == 0
    d = json.loads(capsys.readouterr().out)
    cf = closed_form(*case)
    r, w, al = case[0] / 1000, case[6], case[7]
    assert d["input"]["wheel"] == "CA" and d["input"]["block"] == "C"
    assert close(d["input"]["omega"], w, 0.0) and close(d["input"]["alpha"], al, abs(w))
    assert close(d["input"]["vs"], -w * r, 0.0)  # no slip: v_C = omega r
    rolling = d["rolling"]["CA"]
    assert close(tuple(rolling["contact"]), (case[5] / 1000, 0.0), r)
    assert close(tuple(rolling["acceleration"]), cf["aI"], w * w * r)
    assert close(tuple(rolling["velocity"]), (0.0, 0.0), abs(w) * r)
    # the centre is the wheel's, not a slider's: with the wheel, along its ground line
    assert set(d["sliders"]) == {"B"} and set(d["error_bounds"]["sliders"]) == {"B"}
    assert rolling["centre"] == "C" and rolling["line"] == "horizontal"
    assert close(rolling["centre_velocity"], -w * r, 0.0)  # no slip: v_C = omega r
    assert close(rolling["centre_acceleration"], -al * r, abs(w) * r)
    assert 0 <= d["error_bounds"]["rolling"]["CA"]["centre_velocity"] < 1e-12


def test_steps_say_the_wheel_rolls(tmp_path, capsys):
    f = tmp_path / "w.toml"
    f.write_text(scene_text(*CASES[0]))
    assert main(["steps", str(f)]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "Input wheel CA" in out
    assert "its centre moves at omega r = 4 x 0.3 = 1.2 m/s along the ground" in out
    assert "its contact point I is the instantaneous centre" in out
    assert "a_I = omega^2 r = 4.8 m/s^2 towards C" in out


def test_centres_put_the_wheel_about_its_contact(tmp_path, capsys):
    from polygon_method.solver.centres import locate

    case = CASES[1]
    sol = solve(parse_scene(scene_text(*case)))
    ic = locate(sol)
    assert close(ic.centres[(1, 2)].point, (case[5] / 1000, 0.0), 0.3)  # I12: the contact
    assert close(ic.omega(2), case[6], 0.0)
    assert close(ic.omega(3), closed_form(*case)["omega_AB"], abs(case[6]))


# --------------------------------------------------------------------------- the reference

REFERENCE_SCENES = [
    # an inclined ground line, the wheel below it, a vertical guide
    """
[ground]
O = [0, 0]
[links]
CP = 180
PB = 700
[sliders]
B = { path = "vertical", through = [600, 0] }
[rolling]
CP = { on = "20 deg", through = [0, 0], side = "below", angle = 140 }
[assembly]
B = "below"
[input]
wheel = "CP"
s_C = 200
omega_CP = "6 rad/s ccw"
alpha_CP = "4 rad/s^2 cw"
""",
    # the wheel rolls; a link pinned at its centre drives a crank (now a follower)
    """
[ground]
O = [900, 300]
[links]
CP = 300
CB = 700
OB = 250
[rolling]
CP = { on = "horizontal", through = [0, 0] }
[assembly]
B = "above"
[input]
wheel = "CP"
C = [0, 300]
omega_CP = "4 rad/s cw"
alpha_CP = "1.5 rad/s^2 cw"
""",
    # a spoke point driving a rod and a rocker
    """
[ground]
O = [0, 0]
D = [900, 100]
[links]
CP = 120
PB = 800
BD = 450
[rolling]
CP = { on = "horizontal", through = [0, 0], radius = 200, angle = 250 }
[assembly]
B = "above"
[input]
wheel = "CP"
s_C = 150
omega_CP = "3 rad/s cw"
alpha_CP = "10 rad/s^2 cw"
""",
]


@pytest.mark.parametrize("text", REFERENCE_SCENES)
def test_solver_matches_the_50_digit_reference(text):
    assert not reference_errors(text)


@pytest.mark.parametrize("text", REFERENCE_SCENES + [scene_text(*CASES[1])])
def test_velocities_are_the_derivatives_of_the_positions(text):
    """dP/dt = dP/ds vs and d2P/dt2 = d2P/ds2 vs^2 + dP/ds as, the derivatives in the
    centre's place s by central differences of the solver's own positions."""
    check_derivatives(text)


def test_sweep_runs_over_one_turn_and_matches_the_closed_form():
    """Without a travel, the sweep is one turn of the wheel (2 pi r) the way it rolls; at
    each place the rim point and the slider are where the closed form puts them."""
    case = CASES[1]
    sc = parse_scene(scene_text(*case))
    res = sweep(sc, stroke_places(sc, 13))
    r, s0 = case[0] / 1000, case[5] / 1000
    assert len(res.theta) == 13  # the mechanism assembles over the whole turn
    assert float(res.theta[0]) == pytest.approx(s0 - 2 * math.pi * r, abs=1e-12)  # ccw: left
    assert float(res.theta[-1]) == pytest.approx(s0, abs=1e-12)
    for k, s in enumerate(res.theta):
        s = float(s)
        phi = case[2] + math.degrees((s0 - s) / r)  # no slip: the wheel turns -ds / r
        cf = closed_form(case[0], case[1], phi, *case[3:5], s * 1000, *case[6:])
        for p in "CAB":
            got = (float(res.P[p][0][k]), float(res.P[p][1][k]))
            assert close(got, cf["P"][p], 1.0), (p, s)


def test_a_stated_travel_bounds_the_sweep():
    sc = parse_scene(scene_text(*CASES[0], extra="travel = [-100, 400]"))
    res = sweep(sc, stroke_places(sc, 6))
    assert float(res.theta[0]) == pytest.approx(-0.1) and float(res.theta[-1]) == pytest.approx(0.4)


# --------------------------------------------------------------------------- every view, answers


def test_every_view_takes_a_wheel_driver(tmp_path, capsys):
    f = tmp_path / "t.toml"
    f.write_text(
        scene_text(*CASES[0]) + '[loads]\nB = { force = [-100, 0] }\n[answers]\nv_C = "1.2 m/s"\n'
    )
    every_view(f, tmp_path)
    out = " ".join(capsys.readouterr().out.split())
    # the power balance by hand: F v_C + F_B . v_B = 0, v_C = omega r = 1.2 m/s, v_B = 2 v_C
    # (the rod translates at this instant): F = 100 x 2.4 / 1.2 = 200 N, F r = 60 N m
    assert (
        "input force at the centre C of wheel CA: 200 N to the right along the ground, "
        "i.e. a torque of 60 N m about the contact point" in out
    )
    svg = (tmp_path / "d.svg").read_text()
    assert 'id="rolling-line' in svg and 'id="contact-' in svg  # the hatched ground, I
    assert 'id="block-C"' not in svg and 'id="guide-C"' not in svg  # no block at the centre


def test_check_keys_and_the_contact_slip(tmp_path, capsys):
    """The book's answers (by hand: v_C = omega r, a_I = omega^2 r, v_B = 2 omega r with
    the rod instantaneously translating); the contact's acceleration taken as zero is
    named."""
    f = tmp_path / "t.toml"
    f.write_text(
        scene_text(*CASES[0]) + '[answers]\nv_C = "1.2 m/s"\naI_CA = "4.8 m/s^2"\n'
        'omega_AB = "0 rad/s"\nv_B = "2.4 m/s"\nv_A = "2.4 m/s"\n'
    )
    assert main(["check", str(f)]) == 0
    assert "5 of 5 right" in capsys.readouterr().out
    f.write_text(scene_text(*CASES[0]) + '[answers]\naI_CA = "0 m/s^2"\n')
    main(["check", str(f)])
    out = " ".join(capsys.readouterr().out.split())
    assert "1 wrong" in out and "omega^2 r towards the centre" in out


def test_variants_are_made_and_each_matches_the_reference(tmp_path, capsys):
    """Variants of a driving wheel's scene (the rod's length varied; once refused): each
    variant's file solves to its own 50-digit constraint solve."""
    from mpmath import mpf
    from reference import reference_solution
    from textbook_corpus import REL, worst_error

    f = tmp_path / "t.toml"
    f.write_text(scene_text(*CASES[0]) + "[variants]\nAB = { from = 900, to = 1100, step = 50 }\n")
    assert main(["variants", str(f), "--count", "3", "-o", str(tmp_path / "v")]) == 0
    capsys.readouterr()
    files = sorted((tmp_path / "v").glob("variant-*.toml"))
    assert len(files) == 3
    for path in files:
        sc = load_scene(path)
        sol = solve(sc)
        ref = reference_solution(sc, sol.P)
        assert ref["residual"] < mpf("1e-40")
        err, what = worst_error(sc, sol, ref)
        assert err < REL, f"{path.name}: {what}: {err:.2e}"


def test_linkage_refuses_in_one_line(tmp_path, capsys):
    f = tmp_path / "t.toml"
    f.write_text(scene_text(*CASES[0]))
    assert main(["linkage", str(f)]) == 2
    err = one_line(capsys)
    assert "wheel CA" in err


def test_the_force_analysis_takes_a_wheel_driver(tmp_path, capsys):
    """With masses the wheel driver is solved for its forces (tests/test_forces_rolling.py
    holds them to the matrix method): a force answer is judged, not refused, and the
    driver's torque on the wheel is said."""
    f = tmp_path / "t.toml"
    f.write_text(
        scene_text(*CASES[0]) + '[masses]\nAB = { mass = "5 kg" }\n[answers]\nF_B = "10 N"\n'
    )
    assert main(["check", str(f)]) != 2
    out = " ".join(capsys.readouterr().out.split())
    assert "F_B" in out
    assert main(["solve", str(f)]) == 0
    assert "input torque on the wheel CA" in capsys.readouterr().out


def test_the_worked_problem_checks():
    from polygon_method.check import check_answers

    sc = load_scene("worked_problems/rolling_wheel_driver.toml")
    verdicts = check_answers(solve(sc), sc.answers, sc.tolerance)
    assert verdicts and all(v.ok for v in verdicts), verdicts


BASE = scene_text(*CASES[0]).split("[input]")[0]
BAD = [
    ('wheel = "CZ"\nomega_CA = "4 rad/s cw"\ns_C = 0', "names no wheel"),
    ('wheel = "CA"\ns_C = 0', "has no omega_CA"),
    ('wheel = "CA"\nomega_CA = "4 rad/s"\ns_C = 0', "sense"),
    ('wheel = "CA"\nomega_CA = "4 rad/s cw"', "not at all"),
    ('wheel = "CA"\nomega_CA = "4 rad/s cw"\ns_C = 0\nC = [0, 300]', "twice"),
    ('wheel = "CA"\nomega_CA = "4 rad/s cw"\ns_C = 0\ncrank = "CA"', "over-determined"),
    ('wheel = "CA"\nomega_CA = "4 rad/s cw"\ns_C = 0\nspeed = "3 rad/s cw"', "no crank"),
    ('wheel = "CA"\nomega_CA = "4 rad/s cw"\nC = [0, 250]', "off the path"),
    ('wheel = "CA"\nomega_CA = "0 rad/s"\ns_C = 0', "zero"),
    ('wheel = "CA"\nomega_CA = "4 rad/s cw"\ns_C = 0\ntravel = [100, 200]', "outside its travel"),
    ('wheel = "CA"\nomega_CA = "4 rad/s cw"\ns_C = 0\ntravel = [200, -100]', "less than"),
]


@pytest.mark.parametrize("given, words", BAD)
def test_bad_wheel_input_one_line(tmp_path, capsys, given, words):
    f = tmp_path / "s.toml"
    f.write_text(BASE + "[input]\n" + given + "\n")
    assert main(["solve", str(f)]) == 2
    err = one_line(capsys)
    assert words in err and "[input]" in err, err


def test_a_wheel_on_a_circle_cannot_drive_alone(tmp_path, capsys):
    f = tmp_path / "s.toml"
    f.write_text(
        BASE.replace('on = "horizontal", through = [0, 0], radius = 300', 'on = "O"').replace(
            "[ground]\nO = [0, 0]", "[ground]\nO = [0, -600]"
        )
        + '[input]\nwheel = "CA"\nomega_CA = "4 rad/s cw"\ns_C = 0\n'
    )
    assert main(["solve", str(f)]) == 2
    err = one_line(capsys)
    assert "ground line" in err, err


def test_a_wheel_named_as_the_crank_is_told_how(tmp_path, capsys):
    f = tmp_path / "s.toml"
    f.write_text(BASE + '[input]\ncrank = "CA"\nangle = 90\nspeed = "4 rad/s cw"\n')
    assert main(["solve", str(f)]) == 2
    err = one_line(capsys)
    assert 'drives alone as wheel = "CA"' in err, err
