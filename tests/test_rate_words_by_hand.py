"""A rate given as books give it, relative to the motion it is the rate of ("12 rad/s^2,
slowing down", "5 m/s^2 speeding up"; also decelerating, retarding, accelerating), on every
driver and given motion: each scene is compared, point by point, with the same scene
written with the sense or direction worked out by hand (a crank turning ccw and slowing
down has its alpha cw, ...); the refusals are one line. And older books' unit spellings.
(The words' own tests: tests/test_rate_words.py.)"""

import math
import subprocess
import sys

import pytest

from polygon_method import parse_scene, solve
from polygon_method.common.errors import SceneError

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

WHEEL = """
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
SAME = [
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
        WHEEL,
        'omega_CA = "4 rad/s cw"\nalpha_CA = "2 rad/s^2 slowing down"',
        'omega_CA = "4 rad/s cw"\nalpha_CA = "2 rad/s^2 ccw"',
    ),
    (
        TIPPER,
        'vs_OR = "0.1 m/s retracting"\nas_OR = "0.02 m/s^2 slowing down"',
        'vs_OR = "0.1 m/s retracting"\nas_OR = "0.02 m/s^2 extending"',
    ),
]


@pytest.mark.parametrize("scene, words, by_hand", SAME)
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
    "scene, words, says",
    [
        (TRAMMEL, 'vs_A = "2 m/s right"\nas_A = "5 m/s^2 left, slowing down"', "not both"),
        (
            FOUR_BAR,
            'speed = "10 rad/s ccw"\nacceleration = "40 rad/s^2 cw slowing down"',
            "not both",
        ),
        (
            FOUR_BAR,
            'omega_BC = "3 rad/s cw"\nacceleration = "40 rad/s^2 slowing down"',
            "with its sense",
        ),
    ],
)
def test_refused_in_one_line(scene, words, says, tmp_path):
    with pytest.raises(SceneError) as e:
        parse_scene(scene.format(input=words))
    assert says in str(e.value) and "\n" not in str(e.value)
    f = tmp_path / "s.toml"
    f.write_text(scene.format(input=words), encoding="utf-8")
    run = subprocess.run(
        [sys.executable, "-m", "polygon_method", "solve", str(f)], capture_output=True, text=True
    )
    assert run.returncode == 2 and "Traceback" not in run.stderr
    assert len(run.stderr.strip().splitlines()) == 1 and says in run.stderr


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
