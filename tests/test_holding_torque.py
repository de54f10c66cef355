"""The answer key ``Thold_O``: the torque the frame holds an epicyclic's fixed sun or annulus
with, about its centre O (ccw positive, or a sense), graded by ``check``, answered when
asked (``"?"``), its slips named (the sense, the ratio of teeth turned over), refused in
one line without the force analysis. Against the hand arithmetic of the chapter: the
torques on the train sum to nought (the input on the arm by the power balance with
Willis' ratio), and the holding torque from the planet's equal tooth loads times the
pitch radii (m z / 2)."""

import json
import math

import pytest

from polygon_method import parse_scene, solve
from polygon_method.cli import main

MODULE = 0.005  # m

TRAIN = """units = "mm"
[ground]
O = [0, 0]
[rolling]
module = "5 mm"
{planet}
{other}
[loads]
{load} = {{ torque = "100 N m cw" }}
[masses]
[input]
crank = "OA"
angle = 30
speed = "200 rpm ccw"
"""

SUN_FIXED = (
    'AP = { on = "O", teeth = 24, on_teeth = 40 }',
    '"O-Q" = { on = "AP", ring = true, teeth = 88 }',
    '"O-Q"',
    40,
    88,
)
ANNULUS_FIXED = (
    'AP = { on = "O", inside = true, teeth = 24, on_teeth = 88 }',
    '"O-S" = { on = "AP", teeth = 40 }',
    '"O-S"',
    88,
    40,
)


def _by_hand(z_fixed, z_out):
    """(the holding torque ccw +, the arm's torque): the planet's two tooth loads equal (its
    moments about its centre, no inertia), each gear's torque the load times its pitch
    radius; and the input on the arm by the power balance with Willis' ratio."""
    r_fixed, r_out = MODULE * z_fixed / 2, MODULE * z_out / 2
    load = 100 / r_out  # N along the tangent: the output's 100 N m at its pitch radius
    held = -load * r_fixed  # in the sense of the output's resistance (cw)
    # Willis, the fixed gear at rest: omega_out / omega_arm = 1 + z_fixed / z_out (both an
    # internal and an external pair: the train value -z_fixed / z_out with the arm fixed)
    t_arm = 100 * (1 + z_fixed / z_out)
    return held, t_arm


@pytest.mark.parametrize("case", [SUN_FIXED, ANNULUS_FIXED], ids=["sun", "annulus"])
def test_the_holding_torque_by_the_teeth_and_the_torques_summing_to_nought(case):
    planet, other, load, z_fixed, z_out = case
    sol = solve(parse_scene(TRAIN.format(planet=planet, other=other, load=load)))
    held, t_arm = _by_hand(z_fixed, z_out)
    assert held == pytest.approx(-100 * z_fixed / z_out, rel=1e-12)  # 45.45 or 220 N m cw
    assert t_arm + (-100) + held == pytest.approx(0, abs=1e-9)  # the three torques
    assert sol.value("Thold", ("O",)) == pytest.approx(held, rel=1e-9)
    assert sol.value("torque", ()) == pytest.approx(t_arm, rel=1e-9)
    # the tooth load along the line of action at the default 20 deg
    load_n = 100 / (MODULE * z_out / 2) / math.cos(math.radians(20))
    assert sol.value("Fc", ("A", "P")) == pytest.approx(load_n, rel=1e-9)


def _file(tmp_path, answers, case=SUN_FIXED, masses=True):
    planet, other, load, *_ = case
    text = TRAIN.format(planet=planet, other=other, load=load)
    if not masses:
        text = text.replace("[masses]\n", "")
    f = tmp_path / "train.toml"
    f.write_text(text + "[answers]\n" + answers, encoding="utf-8")
    return f


def _check(f, capsys):
    assert main(["check", "--json", str(f)]) in (0, 1)
    return json.loads(capsys.readouterr().out)["answers"]


def test_check_grades_the_book_answer_in_either_sense_word(tmp_path, capsys):
    (v,) = _check(_file(tmp_path, 'Thold_O = "45.45 N m cw"\n'), capsys)
    assert v["verdict"] == "right"
    assert v["correct"] == pytest.approx(-100 * 40 / 88, rel=1e-9)
    (v,) = _check(_file(tmp_path, 'Thold_O = "220 N m cw"\n', ANNULUS_FIXED), capsys)
    assert v["verdict"] == "right"


@pytest.mark.parametrize(
    "case,given,code",
    [
        (SUN_FIXED, "45.45 N m ccw", "sense"),
        (SUN_FIXED, "220 N m cw", "teeth_ratio_inverted"),  # 100 x 88/40
        (ANNULUS_FIXED, "45.45 N m cw", "teeth_ratio_inverted"),  # 100 x 40/88
        (ANNULUS_FIXED, "220 N m ccw", "sense"),
        # another shaft's torque for it: the output machine's, or the arm's (by hand,
        # 100 (1 + z_fixed / z_out): 145.5 and 320 N m ccw)
        (SUN_FIXED, "100 N m cw", "shaft_torque_for_holding"),
        (SUN_FIXED, "145.5 N m ccw", "shaft_torque_for_holding"),
        (ANNULUS_FIXED, "100 N m cw", "shaft_torque_for_holding"),
        (ANNULUS_FIXED, "320 N m ccw", "shaft_torque_for_holding"),
    ],
)
def test_the_slips_are_named(case, given, code, tmp_path, capsys):
    (v,) = _check(_file(tmp_path, f'Thold_O = "{given}"\n', case), capsys)
    assert v["verdict"] == "wrong" and v["mistake"] == code, v
    if code == "teeth_ratio_inverted":
        assert "88/40" in v["diagnosis"] or "40/88" in v["diagnosis"]


def test_asked_it_is_answered_in_solve(tmp_path, capsys):
    f = _file(tmp_path, 'Thold_O = "?"\n')
    assert main(["solve", str(f)]) == 0
    out = capsys.readouterr().out
    assert "Answers asked: Thold_O = 45.45 N m cw" in out, out


@pytest.mark.parametrize(
    "answers,masses,words",
    [
        ('Thold_O = "45 N m"\n', False, "needs the force analysis: give [masses] or [gravity]"),
        ('Thold_A = "45 N m"\n', True, "no gear of [rolling] rolls on a fixed circle about A"),
        ('Thold_O = "?"\n', False, "needs the force analysis"),
    ],
)
def test_refused_in_one_line(answers, masses, words, tmp_path, capsys):
    f = _file(tmp_path, answers, masses=masses)
    assert main(["check", str(f)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and words in err[0] and "Thold_" in err[0], err


def test_over_a_sweep_the_arms_and_planets_weights_leave_it_alone():
    """Heavy arm and planet, gravity on: the planet's weight and its inertia force act at
    its centre (its mass there, at A), so its moments about A still make its two tooth
    loads equal: the sun is held with 100 x 40/88 at every angle (the sweep's ``Thold_O``
    column), while the arm's torque changes with the weights."""
    import numpy as np

    from polygon_method.motion.sweeps import sweep

    planet, other, load, *_ = SUN_FIXED
    text = TRAIN.format(planet=planet, other=other, load=load).replace(
        "[masses]\n",
        '[masses]\nOA = { mass = "4 kg" }\nAP = { mass = "2 kg", along = 0, from = "A", gyration = 40 }\n',
    )
    sc = parse_scene(text + "[gravity]\n")
    res = sweep(sc, np.radians([0.0, 50.0, 130.0, 200.0, 290.0]))
    cols = {n: np.asarray(a, dtype=float) for n, _, a in res.force_columns()}
    assert cols["Thold_O"] == pytest.approx([-100 * 40 / 88] * 5, rel=1e-9)
    assert np.ptp(cols["torque_inertia"]) > 1.0  # (the weights do change the arm's)
