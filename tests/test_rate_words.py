"""Rates and ways in a book's words: "slowing down", "speeding up", "decelerating at",
"retarding", a load "down" or "to the left"; older books' unit spellings; and the refusals a
newcomer met (a zero crank speed in a statics problem, a block in [input.second], a zero mass
beside an inertia, a rate in words that cannot mean one thing).

Each expected value is what the words mean, worked out by hand here: slowing down is a rate
against the motion's sense (a crank turning cw slowing down has a ccw alpha), speeding up a
rate with it; "down" is -90 deg. First the words as read (the scene's input), then whole
scenes on every driver and given motion, each compared point by point with the same scene
written with the sense or direction worked out by hand."""

from __future__ import annotations

import math

import pytest

from polygon_method import SceneError, parse_scene, solve
from polygon_method.cli import main

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


# --------------------------------------------------------------------------- whole scenes by hand


FOUR_BAR = """
[ground]
A = [0, 0]
D = [200, 0]
[links]
AB = 60
BC = 180
CD = 120
[input]
crank = "AB"
angle = 45
{input}
"""

TRAMMEL = """
[ground]
O = [0, 0]
[links]
AB = 500
[sliders]
A = {{ path = "horizontal", through = "O" }}
B = {{ path = "vertical", through = "O" }}
[input]
block = "A"
s_A = 300
{input}
"""

VERTICAL = """
units = "ft"
[ground]
O = [0, 0]
[links]
OA = "9 in"
AB = "2 ft 6 in"
[sliders]
B = {{ path = "vertical" }}
[input]
crank = "OA"
angle = 30
{input}
"""

WHEEL_AND_ROD = """
[ground]
O = [0, 0]
[links]
CA = 300
AB = 1200
[sliders]
B = {{ path = "horizontal", through = "O" }}
[rolling]
CA = {{ on = "horizontal", through = [0, 0], angle = 135 }}
[assembly]
B = "right"
[input]
wheel = "CA"
C = [0, 300]
{input}
"""

TIPPER = """
[ground]
Q = [0, 0]
O = [-1500, -300]
[links]
QR = 800
[cylinders]
"O-R" = {{ stroke = [1000, 1900] }}
[input]
crank = "QR"
angle = 150
{input}
"""

# (scene, [input] in words, the same by hand)
BY_HAND = [
    (
        FOUR_BAR,
        'speed = "10 rad/s ccw"\nacceleration = "40 rad/s^2, slowing down"',
        'speed = "10 rad/s ccw"\nacceleration = "40 rad/s^2 cw"',
    ),
    (
        FOUR_BAR,
        'speed = "10 rad/s cw"\nacceleration = "40 rad/s^2 decelerating"',
        'speed = "10 rad/s cw"\nacceleration = "40 rad/s^2 ccw"',
    ),
    (
        FOUR_BAR,
        'speed = "10 rad/s cw"\nacceleration = "40 rad/s^2 speeding up"',
        'speed = "10 rad/s cw"\nacceleration = "40 rad/s^2 cw"',
    ),
    (
        FOUR_BAR,
        'omega_BC = "3 rad/s cw"\nalpha_BC = "12 rad/s^2, slowing down"',
        'omega_BC = "3 rad/s cw"\nalpha_BC = "12 rad/s^2 ccw"',
    ),
    (
        FOUR_BAR,
        'omega_BC = "3 rad/s ccw"\nalpha_BC = "12 rad/s^2 retarding"',
        'omega_BC = "3 rad/s ccw"\nalpha_BC = "12 rad/s^2 cw"',
    ),
    (
        TRAMMEL,
        'vs_A = "2 m/s right"\nas_A = "5 m/s^2, slowing down"',
        'vs_A = "2 m/s right"\nas_A = "5 m/s^2 left"',
    ),
    (
        TRAMMEL,
        'vs_A = "2 m/s left"\nas_A = "5 m/s^2 accelerating"',
        'vs_A = "2 m/s left"\nas_A = "5 m/s^2 left"',
    ),
    (
        VERTICAL,
        'vs_B = "12 ft/s downward"\nas_B = "40 ft/s^2 slowing down"',
        'vs_B = "12 ft/s downward"\nas_B = "40 ft/s^2 upward"',
    ),
    (
        VERTICAL,
        'v_B = "12 ft/s down"\na_B = "40 in/s^2 slowing down"',
        'v_B = "12 ft/s down"\na_B = "-40 in/s^2"',
    ),
    (
        WHEEL_AND_ROD,
        'omega_CA = "4 rad/s cw"\nalpha_CA = "2 rad/s^2 slowing down"',
        'omega_CA = "4 rad/s cw"\nalpha_CA = "2 rad/s^2 ccw"',
    ),
    (
        TIPPER,
        'vs_OR = "0.1 m/s retracting"\nas_OR = "0.02 m/s^2 slowing down"',
        'vs_OR = "0.1 m/s retracting"\nas_OR = "0.02 m/s^2 extending"',
    ),
]


@pytest.mark.parametrize("scene, words, by_hand", BY_HAND)
def test_slowing_down_is_the_sense_against_the_motion(scene, words, by_hand):
    a = solve(parse_scene(scene.format(input=words)))
    b = solve(parse_scene(scene.format(input=by_hand)))
    for n in b.P:
        for tab in ("V", "A"):
            p, q = getattr(a, tab)[n], getattr(b, tab)[n]
            assert math.dist(p, q) <= 1e-12 * (1 + math.hypot(*q)), (n, tab)
    assert any(math.hypot(*v) > 0 for v in b.A.values())  # the rate matters here


def test_a_points_speed_slowing_down_has_its_tangential_acceleration_against_it():
    """v_B = 12 ft/s down, a_B = 40 ft/s^2 slowing down: B's acceleration along its
    velocity is -40 ft/s^2 (B slides on a line: it is its whole acceleration)."""
    sol = solve(
        parse_scene(VERTICAL.format(input='v_B = "12 ft/s down"\na_B = "40 ft/s^2 slowing down"'))
    )
    (vx, vy), (ax, ay) = sol.V["B"], sol.A["B"]
    assert vy == pytest.approx(-12 * 0.3048, rel=1e-12)
    assert (ax * vx + ay * vy) / math.hypot(vx, vy) == pytest.approx(-40 * 0.3048, rel=1e-12)


@pytest.mark.parametrize(
    "text, says",
    [
        (
            SLIDER.format(
                drive='speed = "10 rad/s cw"\nacceleration = "4 rad/s^2 ccw slowing down"'
            ),
            "not both",
        ),
        (
            SLIDER.format(drive='vs_B = "1 m/s"\nacceleration = "4 rad/s^2 slowing down"'),
            "give the rate with its sense",
        ),
        (
            TRAMMEL.format(input='vs_A = "2 m/s right"\nas_A = "5 m/s^2 left, slowing down"'),
            "not both",
        ),
        (
            FOUR_BAR.format(
                input='speed = "10 rad/s ccw"\nacceleration = "40 rad/s^2 cw slowing down"'
            ),
            "not both",
        ),
        (
            FOUR_BAR.format(
                input='omega_BC = "3 rad/s cw"\nacceleration = "40 rad/s^2 slowing down"'
            ),
            "with its sense",
        ),
    ],
)
def test_rate_words_refused_in_one_line_where_they_cannot_mean_one_thing(
    text, says, tmp_path, capsys
):
    """A sense and "slowing down" both, or a rate in words on another quantity than the one
    whose motion is given: one line from the reader, and from ``solve`` exit 2 with that line
    on stderr (the command line run in process)."""
    with pytest.raises(SceneError) as e:
        parse_scene(text)
    assert says in str(e.value) and "\n" not in str(e.value)
    f = tmp_path / "s.toml"
    f.write_text(text, encoding="utf-8")
    code = main(["solve", str(f)])
    err = capsys.readouterr().err
    assert code == 2 and "Traceback" not in err
    assert len(err.strip().splitlines()) == 1 and says in err


@pytest.mark.parametrize(
    "text, kind, si",
    [
        ("15 rad/sec", "angular_velocity", 15.0),
        ("2 rev/sec", "angular_velocity", 4 * math.pi),
        ("40 rad/sec^2", "angular_acceleration", 40.0),
        ("3 m/sec", "velocity", 3.0),
        ("12 ft/sec", "velocity", 12 * 0.3048),
        ("72 km/hr", "velocity", 20.0),
        ("5 m/sec^2", "acceleration", 5.0),
        ("40 ft/s2", "acceleration", 40 * 0.3048),
        ("100 kgf", "force", 980.665),
        ("5 kgf/cm^2", "pressure", 5 * 9.80665 / 1e-4),
    ],
)
def test_older_books_unit_spellings(text, kind, si):
    """sec for s, km/hr, and the gravitational units (1 kgf = 9.80665 N, by definition)."""
    from polygon_method.common.units import parse_quantity

    assert parse_quantity(text, kind).value == pytest.approx(si, rel=1e-15)
