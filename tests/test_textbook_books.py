"""Problems of the kinds the Theory of Machines books set, stated from the docs alone
(tests/textbook/: Khurmi & Gupta's worked examples, and problems of the kind of Rattan,
Sadhu Singh, Ballaney, Bevan, Hannah & Stephens, Ghosh & Mallik, Norton, Myszka, Waldron &
Kinzel, Uicker): inversions (the Whitworth quick return, a rotary engine with its crank
fixed, an oscillating cylinder driven by its piston's speed), an offset slider crank from
the inner dead centre, a slotted lever driving a four-bar (Coriolis), a bell-crank lever, a
Stephenson six-bar with a slider, a toggle, gears in a linkage, a cylinder on a rocker, a
slider driving a rocker, a crank retarding, the crank pin's linear speed, angles "with the
vertical" and "to the line of stroke, clockwise", and the force chapter.

Every scene is compared with the 50-digit reference at 1e-9 by tests/test_textbook.py (and
the force ones by tests/test_textbook_forces.py). Here: each file's answers, typed as the
book gives them (or worked by hand in closed form where the book's are not at hand: the
file says which), hold within the file's tolerance; the book's quick-return figures from
`linkage`; the book's drawn piston speed against the closed form; the geared five-bar's
torque by virtual displacements with both gears turned (by hand); the readings these
problems needed; and the one problem that cannot be stated (an offset slot) refused in one
line.
"""

from pathlib import Path

import mpmath
import pytest
from mpmath import mpf

from polygon_method import load_scene, parse_scene, solve
from polygon_method.check import check_answers
from polygon_method.common.errors import SceneError

HERE = Path(__file__).resolve().parent / "textbook"
BOOKS = [
    "khurmi_engine_rubbing_three_pins",
    "khurmi_whitworth_with_the_vertical",
    "khurmi_fourbar_retardation",
    "khurmi_slider_drives_rocker",
    "khurmi_rotary_engine",
    "myszka_cylinder_on_fourbar_rocker",
    "toggle_crank_speeding_up",
    "rattan_bell_crank_slider",
    "slotted_lever_drives_rocker",
    "norton_geared_five_bar",
    "crank_pin_linear_speed",
    "inclined_stroke_angle_cw",
    "sadhu_offset_slider_past_idc",
    "oscillating_cylinder_piston_speed",
    "waldron_stephenson_slider",
    "norton_fourbar_coupler_point_polar",
    "ghosh_mallik_fourbar_inclined_frame",
    "force_static_bell_crank",
    "force_static_geared_five_bar",
    "force_static_slider_drives_rocker",
    "force_rotary_engine_at_speed",
]


@pytest.mark.parametrize("name", BOOKS)
def test_the_books_answers_hold_within_the_files_tolerance(name):
    sc = load_scene(HERE / f"{name}.toml")
    assert sc.answers and sc.tolerance is not None
    verdicts = check_answers(solve(sc))
    assert verdicts and all(v.ok for v in verdicts), [
        (v.key, v.given, v.correct) for v in verdicts if not v.ok
    ]


def test_slotted_lever_inclination_time_ratio_and_stroke_are_the_books():
    """Khurmi & Gupta: the slotted bar at 30 deg to the vertical in its extreme positions,
    the time ratio 2, the stroke 450 mm (the lever's end, 450 mm, between its extremes)."""
    import math

    from polygon_method.linkage import analyse

    lk = analyse(load_scene(HERE / "khurmi_slotted_lever_time_ratio.toml"))
    lo, hi = math.degrees(lk.output_min), math.degrees(lk.output_max)
    assert 90 - lo == pytest.approx(30, abs=1e-9) and hi - 90 == pytest.approx(30, abs=1e-9)
    assert lk.time_ratio == pytest.approx(2, rel=1e-9)
    stroke = 0.45 * math.dist(
        (math.cos(lk.output_min), math.sin(lk.output_min)),
        (math.cos(lk.output_max), math.sin(lk.output_max)),
    )
    assert stroke == pytest.approx(0.450, rel=1e-9)


def test_the_books_drawn_piston_speed_is_high_by_its_drawing():
    """Khurmi & Gupta's steam engine: v_P = omega r (sin t + sin 2t / (2 sqrt(n^2 -
    sin^2 t))) = 7.861 m/s by hand; the book's 8.15 m/s, read off its diagram, is 3.7 %
    high, so the file's tolerance is 4 %, and at 3 % check calls it wrong."""
    sc = load_scene(HERE / "khurmi_engine_rubbing_three_pins.toml")
    sol = solve(sc)
    mpmath.mp.dps = 30
    t, n, w, r = mpmath.pi / 4, mpf(4), 6 * mpmath.pi, mpf("0.5")
    exact = (
        w * r * (mpmath.sin(t) + mpmath.sin(2 * t) / (2 * mpmath.sqrt(n**2 - mpmath.sin(t) ** 2)))
    )
    assert abs(sol.S["P"][0]) == pytest.approx(float(exact), rel=1e-12)
    assert 0.03 < (8.15 - float(exact)) / float(exact) < 0.04
    text = (HERE / "khurmi_engine_rubbing_three_pins.toml").read_text(encoding="utf-8")
    at3 = check_answers(solve(parse_scene(text.replace('tolerance = "4%"', 'tolerance = "3%"'))))
    assert [v.key for v in at3 if not v.ok] == ["v_P"]


def test_geared_five_bar_torque_by_virtual_displacements_with_both_gears_turned():
    """T = -(F . dB/dth2 + T5 dth5/dth2), th5 = th5_0 - (R2 / R5)(th2 - th2_0): both
    gears turned (the corpus's virtual-displacement test turns no gear), B by the
    circle-circle intersection at 40 digits."""
    mpmath.mp.dps = 40
    sol = solve(load_scene(HERE / "force_static_geared_five_bar.toml"))
    t0, ratio = mpmath.radians(45), mpf(50) / 100

    def bx(th2):
        th5 = mpmath.radians(120) - ratio * (th2 - t0)
        A = (40 * mpmath.cos(th2), 40 * mpmath.sin(th2))
        D = (150 + 60 * mpmath.cos(th5), 60 * mpmath.sin(th5))
        dx, dy = D[0] - A[0], D[1] - A[1]
        d = mpmath.sqrt(dx * dx + dy * dy)
        a = (160**2 - 140**2 + d * d) / (2 * d)
        h = mpmath.sqrt(160**2 - a * a)
        c = [
            (A[0] + a * dx / d + s * h * dy / d, A[1] + a * dy / d - s * h * dx / d)
            for s in (1, -1)
        ]
        return max(c, key=lambda p: p[1])[0] / 1000  # B above, in m

    want = -(-200 * mpmath.diff(bx, t0) + (-5) * (-ratio))
    assert sol.input_torque == pytest.approx(float(want), rel=1e-9)
    assert sol.forces.input_torque == pytest.approx(float(want), rel=1e-9)


BASE = """units = "mm"
[ground]
O = [0, 0]
[links]
OA = 100
AB = 300
[sliders]
B = { path = "30 deg" }
[input]
crank = "OA"
"""


@pytest.mark.parametrize(
    "words,deg",
    [
        ("60 deg with the vertical, cw", 30),
        ("makes an angle of 60 deg with the vertical, clockwise", 30),
        ("inclined at 20 deg to the horizontal, ccw", 20),
        ("inclined at 45 deg to the line of stroke, clockwise", -15),
        ("makes 45 deg with the line of stroke, ccw", 75),
        ("60 deg with the downward vertical, ccw", -30),
    ],
)
def test_angles_with_and_to_a_reference_read_as_from_it(words, deg):
    """ "makes 60 deg with the vertical", "inclined at 45 deg to the line of stroke": the
    angle from that reference (by hand: +90 - 60, the path's 30 - 45, ...)."""
    import math

    sc = parse_scene(BASE + f'angle = "{words}"\nspeed = "10 rad/s ccw"\n')
    assert math.degrees(sc.input.angle) == pytest.approx(deg, abs=1e-12)


def test_with_the_vertical_without_its_side_is_refused_saying_which_forms_do():
    with pytest.raises(SceneError) as exc:
        parse_scene(BASE + 'angle = "makes 60 deg with the vertical"\nspeed = "1 rad/s ccw"\n')
    msg = str(exc.value)
    assert "\n" not in msg and "[input] angle" in msg and "right of the vertical" in msg


@pytest.mark.parametrize(
    "words,alpha",
    [
        ("an angular retardation of 30 rad/s^2", -30.0),
        ("a retardation of 30 rad/s^2", -30.0),
        ("30 rad/s^2 retardation", -30.0),
        ("deceleration of 30 rad/s^2", -30.0),
        ("30 rad/s^2, retarding", -30.0),
        ("30 rad/s^2 opposite to the rotation", -30.0),
        ("30 rad/s^2, decreasing", -30.0),
        ("increasing at the rate of 30 rad/s^2", 30.0),
        ("30 rad/s^2 in the direction of rotation", 30.0),
        ("30 rad/s^2 in the same sense", 30.0),
    ],
)
def test_a_rate_in_the_books_words_acts_against_or_with_the_speed(words, alpha):
    """The crank turning at 10 rad/s ccw: a retardation acts cw, an increase ccw."""
    sc = parse_scene(BASE + f'angle = 30\nspeed = "10 rad/s ccw"\nacceleration = "{words}"\n')
    assert sc.input.alpha == alpha


@pytest.mark.parametrize(
    "speed,omega",
    [
        ("3 m/s cw", -30.0),
        ("3 m/s ccw", 30.0),
        ("300 mm/s anticlockwise", 3.0),
        ("10 rad/s cw", -10.0),
    ],
)
def test_a_cranks_speed_may_be_its_pins_linear_speed(speed, omega):
    """ "The crank pin moves at 3 m/s": omega = v / r, r = OA = 100 mm."""
    sc = parse_scene(BASE + f'angle = 30\nspeed = "{speed}"\n')
    assert sc.input.omega == pytest.approx(omega, rel=1e-15)


def test_a_second_cranks_speed_may_be_its_pins_linear_speed():
    text = (HERE.parent.parent / "worked_problems" / "five_bar_two_inputs.toml").read_text(
        encoding="utf-8"
    )
    sc = parse_scene(text)
    assert sc.input.second.omega == -5.0  # "5 rad/s cw"
    r = sc.link(sc.input.second.crank).length
    fast = text.replace('speed = "5 rad/s cw"', f'speed = "{5 * r!r} m/s cw"')
    assert parse_scene(fast).input.second.omega == pytest.approx(-5.0, rel=1e-14)


@pytest.mark.parametrize("speed", ["3 m/s", "3 kg"])
def test_a_linear_speed_without_a_sense_or_a_wrong_unit_is_refused_in_one_line(speed):
    with pytest.raises(SceneError) as exc:
        parse_scene(BASE + f'angle = 30\nspeed = "{speed}"\n')
    assert "\n" not in str(exc.value) and "[input] speed" in str(exc.value)


def test_an_offset_slot_cannot_be_stated_and_is_refused_in_one_line():
    """A rocker whose slot does not pass through its pivot (Uicker's and Norton's offset
    slot) has no statement: a block slides along a link's centre line only. Made of a
    triangle of links it is refused in one line naming them (no construction places it)."""
    text = """units = "mm"
[ground]
O2 = [0, 0]
O4 = [150, 0]
[links]
"O2-A" = 50
"O4-C" = 200
"O4-M" = 40
"M-C" = 196
[sliders]
A = { along = "M-C" }
[input]
crank = "O2-A"
angle = 60
speed = "100 rpm ccw"
"""
    with pytest.raises(SceneError) as exc:
        parse_scene(text) and solve(parse_scene(text))
    assert "\n" not in str(exc.value) and "cannot be found" in str(exc.value)


FOURBAR = """units = "mm"
[ground]
A = [0, 0]
D = [100, 0]
[links]
AB = 40
BC = 120
CD = 80
[input]
crank = "AB"
angle = 40
speed = "25 rad/s ccw"
[points]
"""


@pytest.mark.parametrize(
    "spec,start,turn",
    [
        ('{ on = "BC", from = "B", along = 60, angle = 30 }', "B", 30),
        ('{ on = "BC", along = 60, angle = "30 deg cw" }', "B", -30),
        ('{ on = "BC", from = "C", along = 50, angle = 140 }', "C", 140),
        ('{ on = "CB", from = "C", along = 50, angle = -100 }', "C", -100),
    ],
)
def test_a_point_at_a_distance_and_an_angle_from_a_links_end(spec, start, turn):
    """P = S + d (cos(g + a), sin(g + a)), g the direction from S to the link's other end
    (by hand, from the solved ends)."""
    import math

    sol = solve(parse_scene(FOURBAR + f"P = {spec}\n"))
    S, O = sol.P[start], sol.P["C" if start == "B" else "B"]
    g = math.atan2(O[1] - S[1], O[0] - S[0]) + math.radians(turn)
    d = 0.06 if start == "B" else 0.05
    assert sol.P["P"] == pytest.approx((S[0] + d * math.cos(g), S[1] + d * math.sin(g)), abs=1e-15)


@pytest.mark.parametrize(
    "spec,words",
    [
        ('{ on = "BC", from = "B", along = 60, angle = 180 }', "on the line of BC"),
        ('{ on = "BC", from = "B", angle = 30 }', "angle goes with along"),
        ('{ on = "BC", distances = { B = 50, C = 80 }, angle = 30 }', "angle goes with along"),
        ('{ on = "BC", from = "A", along = 60, angle = 30 }', "is not an end of BC"),
        ('{ on = "BC", from = "B", along = -60, angle = 30 }', "positive"),
    ],
)
def test_a_point_at_an_angle_stated_wrong_is_refused_in_one_line(spec, words):
    with pytest.raises(SceneError) as exc:
        parse_scene(FOURBAR + f"P = {spec}\n")
    msg = str(exc.value)
    assert "\n" not in msg and "[points] P" in msg and words in msg, msg


INCLINED = """units = "mm"
[ground]
A = [0, 0]
D = [90, -40]
[links]
AB = 40
BC = 100
CD = 70
[input]
crank = "AB"
speed = "25 rad/s ccw"
"""


@pytest.mark.parametrize(
    "words,turn",
    [
        ("60 deg from AD, ccw", 60),
        ("60 deg from DA, cw", -60),
        ("60 deg from the line of centres, ccw", 60),
        ("makes 60 deg with the line of centers, clockwise", -60),
        ("30 deg from the fixed link, ccw", 30),
    ],
)
def test_a_cranks_angle_from_the_line_of_centres(words, turn):
    """A book's "angle BAD = 60 deg" on a frame drawn inclined: the direction A -> D,
    atan2(-40, 90), turned by the angle (by hand)."""
    import math

    sc = parse_scene(INCLINED + f'angle = "{words}"\n')
    want = math.degrees(math.atan2(-40, 90)) + turn
    assert math.degrees(sc.input.angle) == pytest.approx(want, abs=1e-12)


@pytest.mark.parametrize(
    "words,said",
    [
        ("60 deg from AD", 'add the sense, e.g. "60 deg from AD, ccw"'),
        ("60 deg from AB, ccw", "AB is no line of two ground points through the crank's pivot A"),
    ],
)
def test_an_angle_from_the_line_of_centres_stated_wrong_is_refused_in_one_line(words, said):
    with pytest.raises(SceneError) as exc:
        parse_scene(INCLINED + f'angle = "{words}"\n')
    msg = str(exc.value)
    assert "\n" not in msg and "[input] angle" in msg and said in msg, msg


def test_the_line_of_centres_of_a_frame_of_three_points_must_be_named():
    text = INCLINED.replace("D = [90, -40]", "D = [90, -40]\nE = [0, 200]") + (
        'angle = "60 deg from the line of centres, ccw"\n'
    )
    with pytest.raises(SceneError) as exc:
        parse_scene(text)
    assert "the frame has 3 points" in str(exc.value) and "\n" not in str(exc.value)
