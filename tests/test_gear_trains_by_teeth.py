"""Gear trains a textbook states by their teeth alone (no [links]: the pitch radii m z / 2
and the arms the centre distances), each held to the chapter's hand arithmetic: the train
value of a compound, a reverted and an idler train (the product of driver over driven
teeth), Willis' formula for an epicyclic with its sun or its annulus fixed and driven, two
inputs, a compound planet; an internal pair driven by its ring; a rack and pinion. And
the words: a second gear on a wheel's shaft is "keyed to" it, a pinion inside a ring gear
meshes with "the ring gear"."""

import json
import math
import subprocess
import sys

import pytest

from polygon_method import parse_scene, solve
from polygon_method.cli import main
from polygon_method.text.steptable import steps_text

RPM = 2 * math.pi / 60


def _solve(body, units="mm"):
    return solve(parse_scene(f'units = "{units}"\n' + body))


def test_compound_train_value():
    """Gear 1 (20) drives 2 (50); 3 (15) keyed to 2's shaft drives 4 (45), module 4 mm:
    omega4 = omega1 (20/50)(15/45), two external meshes: the same sense."""
    sol = _solve("""
[ground]
O1 = [0, 0]
O2 = [140, 0]
O4 = [140, 120]
[rolling]
module = "4 mm"
"O2-B" = { on = "O1-A", teeth = 50, on_teeth = 20 }
"O4-C" = { on = "O2-B", teeth = 45, on_teeth = 15 }
[input]
crank = "O1-A"
angle = 0
speed = "1000 rpm cw"
""")
    w1 = -1000 * RPM
    assert sol.W["O1-A"] == pytest.approx(w1, rel=1e-12)
    assert sol.W["O2-B"] == pytest.approx(-w1 * 20 / 50, rel=1e-12)
    assert sol.W["O4-C"] == pytest.approx(w1 * (20 / 50) * (15 / 45), rel=1e-12)
    assert "meshing with the gear of 15 teeth keyed to the gear O2-B" in steps_text(sol)


def test_reverted_train_output_coaxial_with_the_input():
    """Gear 1 (20) and gear 4 (35) on one axis O1; 2 (40) and 3 (25) on the countershaft
    O2, 20 + 40 = 25 + 35 teeth, module 4 mm: O1O2 = 120 mm; omega4 = omega1 (20/40)(25/35)
    = 5/14 omega1, the same sense."""
    sol = _solve("""
[ground]
O1 = [0, 0]
O2 = [120, 0]
[rolling]
module = "4 mm"
"O2-B" = { on = "O1-A", teeth = 40, on_teeth = 20 }
"O1-C" = { on = "O2-B", teeth = 35, on_teeth = 25 }
[input]
crank = "O1-A"
angle = 0
speed = "1000 rpm cw"
""")
    assert sol.W["O1-C"] / sol.W["O1-A"] == pytest.approx(5 / 14, rel=1e-12)


def test_idler_changes_the_sense_back_not_the_ratio():
    """1 (20) -> idler 2 (30) -> 3 (40), module 4 mm; 3 takes the idler's teeth (no
    on_teeth): omega3 = omega1 20/40, the same sense."""
    sol = _solve("""
[ground]
O1 = [0, 0]
O2 = [100, 0]
O3 = [100, 140]
[rolling]
module = "4 mm"
"O2-B" = { on = "O1-A", teeth = 30, on_teeth = 20 }
"O3-C" = { on = "O2-B", teeth = 40 }
[input]
crank = "O1-A"
angle = 0
speed = "600 rpm ccw"
""")
    assert sol.W["O3-C"] == pytest.approx(sol.W["O1-A"] * 20 / 40, rel=1e-12)
    assert sol.W["O2-B"] == pytest.approx(-sol.W["O1-A"] * 20 / 30, rel=1e-12)


EPI = """
[ground]
O = [0, 0]
[rolling]
module = "5 mm"
{planet}
{other}
[input]
crank = "OA"
angle = 30
{speed}
"""


def test_annulus_fixed_sun_driven():
    """Annulus 88 fixed, sun 40 driven at 1000 rpm cw, planet 24, the arm the output:
    Willis, (omega_s - omega_a) / (0 - omega_a) = -88/40, omega_a = omega_s 40/128."""
    sol = _solve(
        EPI.format(
            planet='AP = { on = "O", inside = true, teeth = 24, on_teeth = 88 }',
            other='"O-S" = { on = "AP", teeth = 40 }',
            speed='"omega_O-S" = "1000 rpm cw"',
        )
    )
    ws, wa = -1000 * RPM, sol.W["OA"]
    assert sol.W["O-S"] == pytest.approx(ws, rel=1e-12)
    assert wa == pytest.approx(ws * 40 / 128, rel=1e-12)
    assert (sol.W["AP"] - wa) / (ws - wa) == pytest.approx(-40 / 24, rel=1e-12)


def test_sun_fixed_annulus_driven():
    """Sun 40 fixed, annulus 88 driven at 1000 rpm cw: omega_a = omega_r 88/128, the
    planet (omega_p - omega_a) / (0 - omega_a) = -40/24."""
    sol = _solve(
        EPI.format(
            planet='AP = { on = "O", teeth = 24, on_teeth = 40 }',
            other='"O-Q" = { on = "AP", ring = true, teeth = 88 }',
            speed='"omega_O-Q" = "1000 rpm cw"',
        )
    )
    wr, wa = -1000 * RPM, sol.W["OA"]
    assert wa == pytest.approx(wr * 88 / 128, rel=1e-12)
    assert (sol.W["AP"] - wa) / -wa == pytest.approx(-40 / 24, rel=1e-12)


def test_arm_and_sun_both_driven():
    """Arm 200 rpm ccw, sun 40 at 500 rpm cw (two inputs), the annulus 88 the output:
    (omega_r - omega_a) / (omega_s - omega_a) = -40/88."""
    sol = _solve(
        EPI.format(
            planet='AP = { on = "O-S", teeth = 24, on_teeth = 40 }',
            other='"O-Q" = { on = "AP", ring = true, teeth = 88 }',
            speed='speed = "200 rpm ccw"\n[input.second]\ncrank = "O-S"\nangle = 0\n'
            'speed = "500 rpm cw"',
        )
    )
    wa, ws = 200 * RPM, -500 * RPM
    assert sol.W["O-S"] == pytest.approx(ws, rel=1e-12)
    assert (sol.W["O-Q"] - wa) / (ws - wa) == pytest.approx(-40 / 88, rel=1e-12)
    assert (sol.W["AP"] - wa) / (ws - wa) == pytest.approx(-40 / 24, rel=1e-12)


def test_compound_planet():
    """Planet 20 on the fixed sun 40, its 25-tooth gear keyed to it driving the sun 35
    (40 + 20 = 35 + 25, module 4 mm): omega_s2 = omega_a (1 - (40/20)(25/35)) = -3/7
    omega_a."""
    sol = _solve("""
[ground]
O = [0, 0]
[rolling]
module = "4 mm"
AP = { on = "O", teeth = 20, on_teeth = 40 }
"O-S" = { on = "AP", teeth = 35, on_teeth = 25 }
[input]
crank = "OA"
angle = 30
speed = "700 rpm ccw"
""")
    assert sol.W["O-S"] == pytest.approx(-3 / 7 * sol.W["OA"], rel=1e-12)
    assert "gear of 25 teeth keyed to the planet AP" in steps_text(sol)


def test_ring_gear_drives_a_pinion_inside_it():
    """The ring (88) the crank, a pinion (24) on a fixed centre inside it: omega_p =
    omega_r 88/24, the same sense; the pinion meshes with "the ring gear"."""
    sol = _solve("""
[ground]
O = [0, 0]
O1 = [160, 0]
[rolling]
module = "5 mm"
"O1-A" = { on = "O-Q", inside = true, teeth = 24, on_teeth = 88 }
[input]
crank = "O-Q"
angle = 30
speed = "100 rpm ccw"
""")
    assert sol.W["O1-A"] == pytest.approx(sol.W["O-Q"] * 88 / 24, rel=1e-12)
    assert "meshing with the ring gear O-Q of 88 teeth" in steps_text(sol)


def test_rack_and_pinion_by_teeth_the_pinion_left_out():
    """A pinion of 20 teeth, module 4 mm (40 mm), left out of [links], at 300 rpm ccw over
    a rack below it: v_R = omega r = 10 pi x 0.04 m/s, to the right."""
    sol = _solve("""
[ground]
O1 = [0, 0]
[sliders]
R = { path = "horizontal", through = [0, -40] }
[rolling]
R = { on = "O1-A", on_teeth = 20, module = "4 mm" }
[input]
crank = "O1-A"
angle = 0
speed = "300 rpm ccw"
""")
    assert sol.V["R"][0] == pytest.approx(300 * RPM * 0.04, rel=1e-12)
    assert abs(sol.V["R"][1]) <= 1e-15
    assert any(n.startswith("[links] O1-A not given") for n in sol.notes)
    out = " ".join(steps_text(sol).split())
    assert "rack R on the pinion O1-A of 20 teeth" in out, out


def test_a_rack_with_a_module_and_no_teeth_asks_for_on_teeth(tmp_path):
    """A rack's teeth are not counted: the line asks for its pinion's, on_teeth."""
    f = tmp_path / "r.toml"
    f.write_text(
        'units = "mm"\n[ground]\nO1 = [0, 0]\n[links]\n"O1-A" = 40\n[sliders]\nR = { path = '
        '"horizontal", through = [0, -40] }\n[rolling]\nR = { on = "O1-A", module = "4 mm" }\n'
        '[input]\ncrank = "O1-A"\nangle = 0\nspeed = "300 rpm ccw"\n',
        encoding="utf-8",
    )
    out = subprocess.run(
        [sys.executable, "-m", "polygon_method", "solve", str(f)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    lines = out.stderr.strip().splitlines()
    assert out.returncode == 2 and len(lines) == 1, out.stderr
    assert "[rolling] R (line" in lines[0] and "add on_teeth" in lines[0], lines[0]


HOLD = """
[ground]
O = [0, 0]
[rolling]
module = "5 mm"
{planet}
{other}
[input]
crank = "OA"
angle = 30
speed = "200 rpm ccw"
[loads]
{load} = {{ torque = "100 N m cw" }}
[gravity]
"""


@pytest.mark.parametrize(
    "planet,other,load,held",
    [
        # the sun fixed, 100 N m cw resisting the annulus: the sun held with 100 x 40/88
        (
            'AP = { on = "O", teeth = 24, on_teeth = 40 }',
            '"O-Q" = { on = "AP", ring = true, teeth = 88 }',
            '"O-Q"',
            -100 * 40 / 88,
        ),
        # the annulus fixed, 100 N m cw resisting the sun: the annulus held with 100 x 88/40
        (
            'AP = { on = "O", inside = true, teeth = 24, on_teeth = 88 }',
            '"O-S" = { on = "AP", teeth = 40 }',
            '"O-S"',
            -100 * 88 / 40,
        ),
    ],
)
def test_the_torque_holding_the_fixed_gear(planet, other, load, held, capsys, tmp_path):
    """The book's holding torque on the fixed wheel of an epicyclic (no friction, the arm
    turning uniformly, no masses): the torques on the train sum to nought, so the fixed
    gear is held with the output torque times z_fixed / z_output, in its sense; and the
    input torque is the power balance's. Said in the contact's words, in the JSON."""
    text = HOLD.format(planet=planet, other=other, load=load)
    sol = _solve(text)
    w_out = sol.W[load.strip('"')]
    t_in = 100 * w_out / sol.W["OA"]  # T_in w_a = 100 w_out (the load cw, ccw positive)
    assert sol.input_torque == pytest.approx(t_in, rel=1e-9)
    assert held == pytest.approx(-(t_in - 100), rel=1e-9)  # the three torques sum to 0
    f = tmp_path / "hold.toml"
    f.write_text('units = "mm"\n' + text, encoding="utf-8")
    assert main(["solve", "--json", str(f)]) == 0
    contact = json.loads(capsys.readouterr().out)["forces"]["contacts"]["AP"]
    assert contact["holding_torque"] == pytest.approx(held, rel=1e-9)
    assert main(["solve", str(f)]) == 0
    out = capsys.readouterr().out
    fixed = "the sun of 40 teeth" if "40 }" in planet else "the fixed annulus of 88 teeth"
    assert f"contact of planet AP with {fixed} about O" in out, out
    assert f"the frame holds {fixed} about O with {abs(held):.4g} N m cw" in out, out


def test_two_planets_in_series_on_one_arm():
    """Sun 30 fixed; planet 1 (15) on it, planet 2 (15) meshing with planet 1, both on the
    arm (B carried on OA, 90 mm from O); the annulus 60 (90 + 30 = 120 mm) about O.
    Arm fixed: ring / sun = (-30/15)(-15/15)(15/60) = +1/2, so omega_r = omega_a (1 -
    1/2); planet 2: (omega_2 - omega_a) / (0 - omega_a) = (-30/15)(-15/15) = 2."""
    sol = _solve("""
[ground]
O = [0, 0]
[links]
OA = 90
[points]
B = { on = "OA", distances = { O = 90, A = 60 }, turn = "cw" }
[rolling]
module = "4 mm"
AP = { on = "O", teeth = 15, on_teeth = 30 }
BQ = { on = "A-P", teeth = 15 }
"O-R" = { on = "BQ", ring = true, teeth = 60 }
[input]
crank = "OA"
angle = 30
speed = "100 rpm ccw"
""")
    wa = sol.W["OA"]
    assert sol.W["O-R"] == pytest.approx(wa / 2, rel=1e-12)
    assert sol.W["BQ"] == pytest.approx(-wa, rel=1e-12)


def test_arm_and_annulus_both_driven():
    """Arm 200 rpm ccw, annulus 88 at 100 rpm cw (the second input), the sun 40 the output:
    (omega_s - omega_a) / (omega_r - omega_a) = -88/40: 200 + 2.2 x 300 = 860 rpm ccw; the
    planet (omega_p - omega_a) / (omega_r - omega_a) = 88/24: -900 rpm."""
    sol = _solve(
        EPI.format(
            planet='AP = { on = "O-Q", inside = true, teeth = 24, on_teeth = 88 }',
            other='"O-S" = { on = "AP", teeth = 40 }',
            speed='speed = "200 rpm ccw"\n[input.second]\ncrank = "O-Q"\nangle = 0\n'
            'speed = "100 rpm cw"',
        )
    )
    assert sol.W["O-S"] == pytest.approx(860 * RPM, rel=1e-12)
    assert sol.W["AP"] == pytest.approx(-900 * RPM, rel=1e-12)
    assert "meshing with the ring gear O-Q of 88 teeth" in steps_text(sol)


def test_a_rack_pinion_by_teeth_without_a_module_asks_for_one(tmp_path):
    """on_teeth without a module on a rack: a rack has no second gear's teeth to share a
    centre distance with, so the line asks for the module (or on_radius), not for 'the
    teeth of both gears'."""
    f = tmp_path / "r.toml"
    f.write_text(
        'units = "mm"\n[ground]\nO1 = [0, 0]\n[links]\n"O1-A" = 40\n[sliders]\nR = { path = '
        '"horizontal", through = [0, -40] }\n[rolling]\nR = { on = "O1-A", on_teeth = 20 }\n'
        '[input]\ncrank = "O1-A"\nangle = 0\nspeed = "300 rpm ccw"\n',
        encoding="utf-8",
    )
    out = subprocess.run(
        [sys.executable, "-m", "polygon_method", "solve", str(f)],
        capture_output=True,
        text=True,
        timeout=120,
    )
    lines = out.stderr.strip().splitlines()
    assert out.returncode == 2 and len(lines) == 1, out.stderr
    assert "[rolling] R (line" in lines[0] and "pinion's on_teeth" in lines[0], lines[0]
    assert "both gears" not in lines[0]


def test_a_reduction_given_on_its_output_is_no_dead_centre():
    """A 20:1 compound reduction (20/50 x 15/120) with the speed given on its output, 100
    rpm: the crank turns at 2000 rpm, and nothing warns of a dead centre (the ratio is the
    same at every angle: it had warned 'near a dead centre for this input (condition
    0.05)')."""
    sol = _solve("""
[ground]
O1 = [0, 0]
O2 = [140, 0]
O4 = [140, 270]
[rolling]
module = "4 mm"
"O2-B" = { on = "O1-A", teeth = 50, on_teeth = 20 }
"O4-C" = { on = "O2-B", teeth = 120, on_teeth = 15 }
[input]
crank = "O1-A"
angle = 0
"omega_O4-C" = "100 rpm ccw"
""")
    assert sol.W["O1-A"] == pytest.approx(2000 * RPM, rel=1e-12)
    assert sol.W["O4-C"] == pytest.approx(100 * RPM, rel=1e-12)
    assert not sol.warnings, sol.warnings
    assert not any("dead centre" in n for n in sol.notes), sol.notes
