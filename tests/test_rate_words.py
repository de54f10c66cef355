"""Rates and ways in a US book's words: "slowing down", "speeding up", "decelerating at",
a load "down" or "to the left"; and the refusals a newcomer met (a zero crank speed in a
statics problem, a block in [input.second], a zero mass beside an inertia).

Each expected value is what the words mean, worked out by hand here: slowing down is a
rate against the motion's sense (a crank turning cw slowing down has a ccw alpha), speeding
up a rate with it; "down" is -90 deg."""

from __future__ import annotations

import math

import pytest

from polygon_method import SceneError, parse_scene

from scenes import seed

SLIDER = """
units = "ft"
[ground]
O = [0, 0]
[links]
OA = 0.5
AB = 1.75
[sliders]
B = {{ path = "horizontal", through = "O" }}
[input]
crank = "OA"
angle = 60
{drive}
"""

BLOCK = """
[ground]
O = [0, 0]
[links]
AB = 500
[sliders]
A = {{ path = "horizontal", through = "O" }}
B = {{ path = "vertical", through = "O" }}
[input]
block = "B"
s_B = 300
vs_B = "{vs}"
as_B = "{acc}"
"""

WHEEL = """
units = "m"
[ground]
O = [0, 0]
[links]
CA = 0.15
[rolling]
CA = {{ on = "horizontal", through = "O", angle = 90 }}
[input]
wheel = "CA"
C = [0, 0.15]
omega_CA = "{w}"
alpha_CA = "{al}"
"""

CYLINDER = seed(
    ground="O = [120, -60]\n",
    middle='[points]\nR = { on = "AB", along = 40 }\n[cylinders]\n"O-R" = {}\n',
    drive='angle = 60\nvs_OR = "0.2 m/s {way}"\nas_OR = "{rate}"',
)
FIVE_BAR = """
units = "in"
[ground]
A = [0, 0]
E = [4, 0]
[links]
AB = 2
BC = 5
CD = 5
ED = 2
[input]
crank = "AB"
angle = 60
speed = "10 rad/s ccw"
[input.second]
crank = "ED"
angle = 120
speed = "{speed}"
acceleration = "{acc}"
"""
FT = 0.3048


@pytest.mark.parametrize(
    "speed,acc,alpha",
    [
        ("10 rad/s cw", "4 rad/s^2 slowing down", 4.0),  # cw, slowing: ccw
        ("10 rad/s cw", "4 rad/s^2 speeding up", -4.0),
        ("10 rad/s ccw", "decelerating at 4 rad/s^2", -4.0),
        ("10 rad/s ccw", "4 rad/s^2, accelerating", 4.0),
        ("10 rad/s cw", "retarding at 4 rad/s^2", 4.0),
    ],
)
def test_crank_acceleration_in_words(speed, acc, alpha):
    sc = parse_scene(seed(drive=f'angle = 60\nspeed = "{speed}"\nacceleration = "{acc}"'))
    assert sc.input.alpha == pytest.approx(alpha, rel=1e-15)


@pytest.mark.parametrize(
    "speed,acc,alpha",
    [("5 rad/s cw", "2 rad/s^2 slowing down", 2.0), ("5 rad/s cw", "2 rad/s^2 speeding up", -2.0)],
)
def test_second_crank_acceleration_in_words(speed, acc, alpha):
    sc = parse_scene(FIVE_BAR.format(speed=speed, acc=acc))
    assert sc.input.second.alpha == pytest.approx(alpha, rel=1e-15)


@pytest.mark.parametrize(
    "vs,acc,rate",
    [
        ("10 ft/s left", "20 ft/s^2 slowing down", 20 * FT),
        ("10 ft/s left", "20 ft/s^2 speeding up", -20 * FT),
        ("10 ft/s right", "slowing down at 20 ft/s^2", -20 * FT),
    ],
)
def test_piston_rate_in_words(vs, acc, rate):
    sc = parse_scene(SLIDER.format(drive=f'vs_B = "{vs}"\nas_B = "{acc}"'))
    assert sc.input.given.rate == pytest.approx(rate, rel=1e-15)


def test_coupler_and_point_rates_in_words():
    sc = parse_scene(
        SLIDER.format(drive='omega_AB = "3 rad/s cw"\nalpha_AB = "1 rad/s^2 slowing down"')
    )
    assert sc.input.given.rate == pytest.approx(1.0, rel=1e-15)  # against cw: ccw
    sc = parse_scene(
        SLIDER.format(drive='v_A = "2 ft/s at 150 deg"\na_A = "3 ft/s^2 slowing down"')
    )
    assert sc.input.given.rate == pytest.approx(-3 * FT, rel=1e-15)  # its speed falls


@pytest.mark.parametrize(
    "way,rate,want",
    [
        ("extending", "0.1 m/s^2 slowing down", -0.1),
        ("retracting", "0.1 m/s^2 slowing down", 0.1),
        ("retracting", "0.1 m/s^2 speeding up", -0.1),
    ],
)
def test_cylinder_rate_in_words(way, rate, want):
    sc = parse_scene(CYLINDER.replace("{way}", way).replace("{rate}", rate))
    assert sc.input.given.rate == pytest.approx(want, rel=1e-15)


@pytest.mark.parametrize(
    "vs,acc,want",
    [
        ("3 m/s down", "2 m/s^2 slowing down", 2.0),
        ("3 m/s down", "2 m/s^2 speeding up", -2.0),
        ("3 m/s up", "2 m/s^2 slowing down", -2.0),
    ],
)
def test_driving_block_rate_in_words(vs, acc, want):
    sc = parse_scene(BLOCK.format(vs=vs, acc=acc))
    assert sc.input.alpha == pytest.approx(want, rel=1e-15)  # a block's as, along +y


@pytest.mark.parametrize(
    "w,al,want",
    [
        ("13 rad/s cw", "20 rad/s^2 slowing down", 20.0),
        ("13 rad/s ccw", "20 rad/s^2 slowing down", -20.0),
    ],
)
def test_driving_wheel_rate_in_words(w, al, want):
    sc = parse_scene(WHEEL.format(w=w, al=al))
    # the centre's acceleration along the ground (+x) is -alpha r
    assert sc.input.alpha == pytest.approx(-want * 0.15, rel=1e-12)


@pytest.mark.parametrize(
    "drive,words",
    [
        ('speed = "10 rad/s cw"\nacceleration = "4 rad/s^2 ccw slowing down"', "not both"),
        ('vs_B = "1 m/s"\nacceleration = "4 rad/s^2 slowing down"', "give the rate with its sense"),
    ],
)
def test_rate_words_refused_where_they_cannot_mean_one_thing(drive, words):
    with pytest.raises(SceneError, match=words) as e:
        parse_scene(SLIDER.format(drive=drive))
    assert "\n" not in str(e.value)


@pytest.mark.parametrize(
    "words,deg",
    [
        ("down", -90),
        ("downward", -90),
        ("vertically downwards", -90),
        ("up", 90),
        ("to the left", 180),
        ("right", 0),
        ("straight down", -90),
    ],
)
def test_load_direction_as_a_way(words, deg):
    sc = parse_scene(seed(after=f'[loads]\nC = {{ force = "1 kN", direction = "{words}" }}\n'))
    (ld,) = sc.loads
    fx, fy = ld.force
    assert math.atan2(fy, fx) == pytest.approx(math.radians(deg), abs=1e-15)
    assert math.hypot(fx, fy) == pytest.approx(1000.0, rel=1e-15)


def test_zero_speed_says_how_to_state_a_statics_problem():
    with pytest.raises(SceneError, match="give any speed"):
        parse_scene(seed(drive='angle = 60\nspeed = "0 rad/s"'))


def test_a_block_in_the_second_input_that_is_no_collar_is_one_line():
    with pytest.raises(SceneError, match=r"\[input.second\] block") as e:
        parse_scene(seed(after='[input.second]\nblock = "C"\n'))
    assert "\n" not in str(e.value)


def test_zero_mass_beside_an_inertia_says_how_to_state_a_balanced_crank():
    with pytest.raises(SceneError, match="balanced crank"):
        parse_scene(seed(after='[masses]\nAB = { mass = 0, centre = "A", inertia = 0.01 }\n'))


RACK = """
units = "m"
[ground]
O = [0, 0]
[links]
CA = 0.15
[rolling]
CA = {{ on = "{on}", through = "O", angle = 90 }}
[input]
wheel = "CA"
s_C = 0
{drive}
"""


@pytest.mark.parametrize(
    "on,drive,omega,alpha",
    [
        # on a horizontal line, above it: the centre moves right when the wheel turns cw
        ("horizontal", 'vs_C = "2 m/s right"\nas_C = "3 m/s^2 slowing down"', -2 / 0.15, 3 / 0.15),
        ("horizontal", 'vs_C = "2 m/s left"\nas_C = "3 m/s^2 left"', 2 / 0.15, 3 / 0.15),
        ("horizontal", 'vs_C = "-2 m/s"\nalpha_CA = "1 rad/s^2 cw"', 2 / 0.15, -1.0),
        ("horizontal", 'omega_CA = "4 rad/s cw"\nas_C = "0.3 m/s^2 speeding up"', -4.0, -2.0),
    ],
)
def test_a_driving_wheel_given_by_its_centre(on, drive, omega, alpha):
    """ "The gear's centre moves right at 2 m/s, slowing down at 3 m/s^2": rolling without
    slip, omega = -v_C / r (cw to move right on a line below the wheel), alpha = -a_C / r;
    the wheel's own omega and alpha worked out by hand here."""
    from polygon_method import solve

    sol = solve(parse_scene(RACK.format(on=on, drive=drive)))
    assert sol.W["CA"] == pytest.approx(omega, rel=1e-14)
    assert sol.Al["CA"] == pytest.approx(alpha, rel=1e-14)
    # the top point moves at twice the centre's speed
    assert sol.V["A"][0] == pytest.approx(-2 * 0.15 * omega, rel=1e-14)


def test_a_driving_wheel_given_twice_is_refused_in_one_line():
    with pytest.raises(SceneError, match="one only") as e:
        parse_scene(
            RACK.format(on="horizontal", drive='omega_CA = "4 rad/s cw"\nvs_C = "0.6 m/s right"')
        )
    assert "\n" not in str(e.value)
