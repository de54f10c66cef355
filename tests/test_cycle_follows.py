"""linkage's cycle sampled finely enough to follow a differential's fast planet, not refused:
the sun and annulus driven (tests/textbook/differential_sun_and_annulus_driven.toml), the arm
at 21.82 rpm, the planet at 336 rpm, 15.4 times the arm's speed. linkage had refused it
("give the two inputs speeds of comparable size"): its usual 3600 samples over the period
put 15.4 deg of the planet's turn between two."""

import math
from fractions import Fraction
from pathlib import Path

from polygon_method import load_scene
from polygon_method.cli import main
from polygon_method.linkage.cycle import MOST_PER_SAMPLE, MOST_SAMPLES, samples_to_follow
from polygon_method.linkage.shapes import _GRID
from polygon_method.motion.sweeps import Sweeper

ROOT = Path(__file__).resolve().parent.parent
SCENE = ROOT / "tests/textbook/differential_sun_and_annulus_driven.toml"


def _ratios():
    """By hand (Willis): z_S 30, z_P 25, z_A 80; sun 240 rpm cw, annulus 120 rpm ccw."""
    ws, wa = Fraction(-240), Fraction(120)
    arm = (30 * ws + 80 * wa) / (30 + 80)  # 240/11 rpm ccw
    planet = arm + Fraction(80, 25) * (wa - arm)  # (w_P - w_arm) / (w_A - w_arm) = z_A / z_P
    return arm, wa / arm, planet / arm


def test_the_cycle_is_sampled_to_follow_the_planet():
    arm, annulus, planet = _ratios()
    assert (annulus, planet) == (Fraction(11, 2), Fraction(77, 5))
    turns = math.lcm(annulus.denominator, planet.denominator)  # 10 turns of the arm
    plan = Sweeper(load_scene(SCENE)).plan
    span = 2 * math.pi * turns
    n = samples_to_follow(plan, span, _GRID)
    assert _GRID < n <= MOST_SAMPLES
    assert float(planet) * span / n <= MOST_PER_SAMPLE  # at most 10 deg between samples


def test_linkage_of_the_differential_answers_with_its_period(capsys):
    assert main(["linkage", str(SCENE)]) == 0
    out = capsys.readouterr().out
    turns = math.lcm(*(r.denominator for r in _ratios()[1:]))
    assert f"the motion repeats every {turns} turns" in out
    assert "cannot follow" not in out
