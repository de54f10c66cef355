"""Two inputs whose speeds are given on other links (a differential: the sun and the
annulus driven, the arm the output): the cranks' speeds found by a 2 x 2 solve, held to
Willis' formula by hand, to the same train with the cranks' speeds stated directly, and to
finite differences of the positions; a pairing that does not determine both inputs
refused; every view."""

import json
import math
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from polygon_method import parse_scene, solve
from polygon_method.motion.sweeps import sweep
from polygon_method.text.steptable import steps_text

RPM = 2 * math.pi / 60
ROOT = Path(__file__).resolve().parents[1]
BOOK = ROOT / "tests" / "textbook" / "differential_sun_and_annulus_driven.toml"
ZS, ZP, ZR = 30, 25, 80

TRAIN = """
units = "mm"
[ground]
O = [0, 0]
{ground}
[rolling]
module = "4 mm"
AP = {{ on = "O-Q", inside = true, teeth = 25, on_teeth = 80 }}
"O-S" = {{ on = "AP", teeth = 30 }}
{extra}
[input]
crank = "OA"
angle = 30
{first}
[input.second]
crank = "O-Q"
angle = 0
{second}
"""


def _text(first, second, extra="", ground=""):
    return TRAIN.format(first=first, second=second, extra=extra, ground=ground)


def _scene(first, second):
    return parse_scene(_text(first, second))


def _willis(ws, wr):
    return (ZS * ws + ZR * wr) / (ZS + ZR)


def test_sun_given_annulus_driven_willis():
    """The sun at 240 rpm cw, the annulus at 120 rpm ccw: the arm by Willis' formula; the
    sun turns at the speed given; the planet (omega_p - omega_a) / (omega_r - omega_a) =
    z_r / z_p."""
    sol = solve(_scene('"omega_O-S" = "240 rpm cw"', 'speed = "120 rpm ccw"'))
    ws, wr = -240 * RPM, 120 * RPM
    wa = _willis(ws, wr)
    assert sol.W["OA"] == pytest.approx(wa, rel=1e-12)
    assert sol.W["O-S"] == pytest.approx(ws, rel=1e-12)
    assert sol.W["O-Q"] == pytest.approx(wr, rel=1e-12)
    assert sol.W["AP"] == pytest.approx(wa + ZR / ZP * (wr - wa), rel=1e-12)
    note = next(n for n in sol.notes if "two cranks' speeds are found" in n)
    assert f"omega_OA = {abs(wa):.6g} rad/s ccw" in note


def test_both_given_on_other_links_with_rates():
    """The sun and the planet given (the arm and the annulus both found), with their
    rates: the speeds and the accelerations by Willis' formula, solved by hand."""
    sol = solve(
        _scene(
            '"omega_O-S" = "240 rpm cw"\n"alpha_O-S" = "3 rad/s^2 ccw"',
            'omega_AP = "300 rpm ccw"\nalpha_AP = "2 rad/s^2 cw"',
        )
    )
    # omega_s = (1 + zr/zs) wa - (zr/zs) wr and omega_p = wa + (zr/zp)(wr - wa)
    m = np.array([[1 + ZR / ZS, -ZR / ZS], [1 - ZR / ZP, ZR / ZP]])
    wa, wr = np.linalg.solve(m, [-240 * RPM, 300 * RPM])
    aa, ar = np.linalg.solve(m, [3.0, -2.0])
    assert sol.W["OA"] == pytest.approx(wa, rel=1e-12)
    assert sol.W["O-Q"] == pytest.approx(wr, rel=1e-12)
    assert sol.Al["OA"] == pytest.approx(aa, rel=1e-12)
    assert sol.Al["O-Q"] == pytest.approx(ar, rel=1e-12)
    assert sol.Al["OA"] == pytest.approx(_willis(sol.Al["O-S"], sol.Al["O-Q"]), rel=1e-12)
    assert sol.Al["O-S"] == pytest.approx(3.0, rel=1e-12)
    assert sol.Al["AP"] == pytest.approx(-2.0, rel=1e-12)


def test_sun_rate_given_annulus_accelerating():
    """The sun's rate given, the annulus's own acceleration stated: the arm's
    acceleration by Willis' formula on the rates."""
    sol = solve(
        _scene(
            '"omega_O-S" = "240 rpm cw"\n"alpha_O-S" = "4 rad/s^2 cw"',
            'speed = "120 rpm ccw"\nacceleration = "6 rad/s^2 ccw"',
        )
    )
    assert sol.Al["OA"] == pytest.approx(_willis(-4.0, 6.0), rel=1e-12)
    assert sol.Al["O-S"] == pytest.approx(-4.0, rel=1e-12)


def _said(x, unit):
    return f"{abs(x)!r} {unit} {'ccw' if x > 0 else 'cw'}"


def test_the_same_as_the_speeds_stated_directly():
    """The train with the cranks' speeds found equals the train with them stated: every
    point's velocity and acceleration, every link's omega and alpha."""
    found = solve(
        _scene(
            '"omega_O-S" = "240 rpm cw"\n"alpha_O-S" = "4 rad/s^2 cw"',
            'omega_AP = "300 rpm ccw"',
        )
    )
    wa, aa = found.W["OA"], found.Al["OA"]
    wr, ar = found.W["O-Q"], found.Al["O-Q"]
    direct = solve(
        _scene(
            f'speed = "{_said(wa, "rad/s")}"\nacceleration = "{_said(aa, "rad/s^2")}"',
            f'speed = "{_said(wr, "rad/s")}"\nacceleration = "{_said(ar, "rad/s^2")}"',
        )
    )
    for k in direct.W:
        assert found.W[k] == pytest.approx(direct.W[k], rel=1e-12, abs=1e-12)
        assert found.Al[k] == pytest.approx(direct.Al[k], rel=1e-12, abs=1e-12)
    for p in direct.V:
        assert np.allclose(found.V[p], direct.V[p], rtol=1e-12, atol=1e-12)
        assert np.allclose(found.A[p], direct.A[p], rtol=1e-12, atol=1e-12)
    assert found.W["AP"] == pytest.approx(300 * RPM, rel=1e-12)


def test_finite_differences_of_the_positions():
    """Over a sweep at the speeds found, the sun's angle changes with time at the speed
    given, and the planet's centre moves at its velocity: central differences of the
    positions (the gear's angle followed from the mechanism's own places)."""
    sc = _scene('"omega_O-S" = "240 rpm cw"', 'speed = "120 rpm ccw"')
    sol = solve(sc)
    th0, w1, h = sc.input.angle, sol.W["OA"], 1e-5
    res = sweep(sc, np.array([th0 - h, th0, th0 + h]))
    sx, sy = np.asarray(res.P["S"][0]), np.asarray(res.P["S"][1])
    phi = np.unwrap(np.arctan2(sy, sx))
    dt = h / w1  # the arm turns h in this time
    assert (phi[2] - phi[0]) / (2 * dt) == pytest.approx(-240 * RPM, rel=1e-7)
    ax, ay = np.asarray(res.P["A"][0]), np.asarray(res.P["A"][1])
    vx, vy = sol.V["A"]
    assert (ax[2] - ax[0]) / (2 * dt) == pytest.approx(vx, rel=1e-7)
    assert (ay[2] - ay[0]) / (2 * dt) == pytest.approx(vy, rel=1e-7)


def _cli(*args):
    return subprocess.run(
        [sys.executable, "-m", "polygon_method", *map(str, args)],
        capture_output=True,
        text=True,
        cwd=ROOT,
    )


def test_a_pairing_that_does_not_determine_both_inputs_is_refused(tmp_path):
    """The sun and a gear meshing with it about a fixed centre keep one ratio whatever the
    arm and the annulus do: refused in one line with the condition, exit 2."""
    f = tmp_path / "singular.toml"
    f.write_text(
        _text(
            '"omega_O-S" = "240 rpm cw"',
            '"omega_O2-G" = "360 rpm ccw"',
            extra='"O2-G" = { on = "O-S", teeth = 20 }',
            ground="O2 = [100, 0]",
        )
    )
    r = _cli("solve", f)
    assert r.returncode == 2, r.stderr
    line = r.stderr.strip()
    assert "\n" not in line and "Traceback" not in line
    assert "do not determine both inputs" in line and "condition 0" in line
    assert "[input] omega_O-S" in line


def test_the_same_link_given_twice_is_refused(tmp_path):
    f = tmp_path / "twice.toml"
    f.write_text(_text('"omega_O-S" = "240 rpm cw"', '"omega_O-S" = "100 rpm ccw"'))
    r = _cli("solve", f)
    assert r.returncode == 2 and "do not determine both inputs" in r.stderr


def test_the_book_problem_in_every_view():
    """The book's problem: check (its answer key on the arm's omega), solve, --json,
    steps and sweep each say the crank speeds found."""
    r = _cli("check", BOOK)
    assert r.returncode == 0, r.stderr
    assert "3 of 3 right" in r.stdout
    r = _cli("solve", BOOK)
    assert r.returncode == 0 and "found from omega_O-S = 240 rpm cw" in r.stdout
    assert "two cranks' speeds are found" in r.stdout
    r = _cli("solve", "--json", BOOK)
    d = json.loads(r.stdout)
    wa = _willis(-240 * RPM, 120 * RPM)
    assert d["input"]["omega"] == pytest.approx(wa, rel=1e-12)
    assert d["input"]["second"]["omega"] == pytest.approx(120 * RPM, rel=1e-12)
    assert d["input"]["found_from"][0]["key"] == "omega_O-S"
    assert any("two cranks' speeds are found" in n for n in d["notes"])
    r = _cli("steps", BOOK)
    assert r.returncode == 0 and "two cranks' speeds are" in r.stdout
    r = _cli("sweep", BOOK)
    assert r.returncode == 0, r.stderr


def test_a_sweep_holds_a_gear_trains_given_speeds():
    """Over the arm's turn the sun keeps the speed given (a gear train: fixed ratios)."""
    sc = _scene('"omega_O-S" = "240 rpm cw"', 'speed = "120 rpm ccw"')
    res = sweep(sc)
    assert np.allclose(res.W["O-S"], -240 * RPM, rtol=1e-12)


def test_a_sweep_that_cannot_hold_a_couplers_speed_is_refused(tmp_path):
    """A five-bar with the second input's speed given on a coupler: at the speeds found at
    the stated instant the coupler's speed drifts over the sweep: refused in one line
    (exit 2), while solve answers the instant."""
    text = (ROOT / "worked_problems" / "five_bar_two_inputs.toml").read_text()
    text = text.replace('speed = "5 rad/s cw"', 'omega_CD = "1 rad/s ccw"')
    text = text[: text.index("[answers]")]
    f = tmp_path / "five.toml"
    f.write_text(text)
    sol = solve(parse_scene(text))
    assert sol.W["CD"] == pytest.approx(1.0, rel=1e-12)
    assert sol.W["AB"] == pytest.approx(10.0, rel=1e-12)
    r = _cli("sweep", f)
    assert r.returncode == 2
    assert "held only at the stated instant" in r.stderr and "\n" not in r.stderr.strip()


def test_steps_text_says_the_speeds_found():
    sol = solve(_scene('"omega_O-S" = "240 rpm cw"', 'speed = "120 rpm ccw"'))
    assert "two cranks' speeds are found" in steps_text(sol)


def test_the_crank_acceleration_stated_beside_the_given_speed():
    """The arm's own acceleration stated, the sun's speed given without its rate: the
    sun's acceleration by Willis' formula on the rates (the annulus uniform)."""
    sc = _scene(
        '"omega_O-S" = "240 rpm cw"\nacceleration = "2 rad/s^2 ccw"', 'speed = "120 rpm ccw"'
    )
    sol = solve(sc)
    assert sol.Al["OA"] == pytest.approx(2.0, rel=1e-12)
    # alpha_a = (zs alpha_s + zr 0) / (zs + zr)
    assert sol.Al["O-S"] == pytest.approx(2.0 * (ZS + ZR) / ZS, rel=1e-12)
    assert sol.W["OA"] == pytest.approx(_willis(-240 * RPM, 120 * RPM), rel=1e-12)


def test_the_arms_position_stated_otherwise():
    """The arm's angle given as a direction (angle_OA): found, then both speeds."""
    text = _text('"omega_O-S" = "240 rpm cw"', 'speed = "120 rpm ccw"').replace(
        "angle = 30\n", "angle_OA = 50\n", 1
    )
    sol = solve(parse_scene(text))
    assert math.degrees(sol.scene.input.angle) == pytest.approx(50.0, abs=1e-9)
    assert sol.W["OA"] == pytest.approx(_willis(-240 * RPM, 120 * RPM), rel=1e-12)


def test_variants_refused_in_one_line(tmp_path):
    f = tmp_path / "v.toml"
    f.write_text(BOOK.read_text() + "\n[variants]\nangle = { from = 30, to = 60, step = 5 }\n")
    r = _cli("variants", f, "--count", "2", "-o", tmp_path / "out")
    assert r.returncode == 2
    assert "speeds are given on other links" in r.stderr and "\n" not in r.stderr.strip()


def test_a_rest_of_the_arm_is_refused_not_rounding_noise(tmp_path):
    """Sun 240 cw, annulus 90 ccw: 30 x -240 + 80 x 90 = 0, the arm at rest: refused (the
    train is then an ordinary one), never a speed of rounding noise."""
    f = tmp_path / "rest.toml"
    f.write_text(_text('"omega_O-S" = "240 rpm cw"', 'speed = "90 rpm ccw"'))
    r = _cli("solve", f)
    assert r.returncode == 2 and "at rest" in r.stderr


def test_steps_say_which_speeds_were_found_and_which_given():
    """The step table: the arm's speed found from the sun's, the annulus's given; with
    both found, the annulus's found too, never '(given)' for a speed found."""
    text = steps_text(solve(_scene('"omega_O-S" = "240 rpm cw"', 'speed = "120 rpm ccw"')))
    assert "omega_OA = 2.285 rad/s ccw (the crank's, found from omega_O-S = 240 rpm cw)" in text
    assert "omega_O-Q = 12.57 rad/s ccw (given)" in text
    text = steps_text(solve(_scene('"omega_O-S" = "240 rpm cw"', 'omega_AP = "300 rpm ccw"')))
    assert "(found above)" in text and "rad/s ccw (given)" not in text


def test_a_five_bars_coupler_speed_against_the_50_digit_reference():
    """A linkage, not a train: the five-bar's second input given as the coupler CD's
    speed and rate; the general 50-digit solve at both cranks' speeds found turns CD at
    the stated speed and rate (so the 2 x 2 solve, with its velocity terms, is right)."""
    from mpmath import mpf
    from reference import reference_solution

    text = (ROOT / "worked_problems" / "five_bar_two_inputs.toml").read_text()
    text = text.replace(
        'speed = "5 rad/s cw"', 'omega_CD = "1 rad/s ccw"\nalpha_CD = "4 rad/s^2 cw"'
    )
    text = text[: text.index("[answers]")]
    sol = solve(parse_scene(text))
    ref = reference_solution(sol.scene, sol.P)
    assert abs(ref["omega"]["CD"] - 1) <= mpf("1e-9")
    assert abs(ref["alpha"]["CD"] + 4) <= mpf("1e-9") * 4
    assert abs(ref["omega"]["AB"] - 10) <= mpf("1e-9") * 10


def test_the_problem_words_state_the_given_speed_not_the_answer():
    """The problem's words (page, sheet) state what is given: the arm's speed is the
    question, found from the sun's; it read "turning at found from omega_O-S = ..., (2.285
    rad/s ccw)", the answer given away in broken words."""
    from polygon_method import load_scene
    from polygon_method.text.words import given

    text = " ".join(given(load_scene(BOOK)))
    assert "its speed found from omega_O-S = 240 rpm cw." in text
    assert "turning at found" not in text
    arm = (30 * -240 + 80 * 120) / 110 * RPM  # Willis: 21.82 rpm ccw, the answer
    assert f"{arm:.4g}" not in text and "2.285" not in text
    assert "turning at 120 rpm ccw" in text  # the annulus: its own speed, given


def test_the_configuration_says_a_gear_turning_against_the_crank_the_other_way():
    """The sun turns -240 / (240/11) = -11 times the arm's angle (Willis, both inputs at
    their speeds): the step table read 'turns -11 times the crank's angle'."""
    sol = solve(parse_scene(BOOK.read_text(encoding="utf-8")))
    arm = (30 * -240 + 80 * 120) / 110  # rpm ccw, by Willis' formula
    k = -240 / arm
    assert k == pytest.approx(-11, rel=1e-12)
    text = steps_text(sol)
    assert f"turns {abs(k):.4g} times the crank's angle the other way" in " ".join(text.split())
    assert "turns -" not in text
