"""Angles as books give them and lengths in feet (the scene reader).

The expected angles are worked out by hand from the words (a reference direction, a size
and a sense); the dead centres from the closed form of the slider crank (O, A, B in line,
|OB| = l + r at the inner one, l - r at the outer one) and, independently of any formula,
from the solver's own physics: at a dead centre the piston stands still. The scene in feet
is compared with the same mechanism written in metres with a plain angle from +x.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from polygon_method import parse_scene, solve
from polygon_method.cli import main
from polygon_method.common.errors import SceneError
from scenes import seed

ROOT = Path(__file__).resolve().parent.parent

ENGINE = """
title = "engine"
[ground]
O = [0, 0]
[links]
OA = {r}
AB = {l}
[sliders]
B = {{ path = "horizontal"{through} }}
{assembly}
[input]
crank = "OA"
angle = {angle!r}
speed = "10 rad/s {sense}"
"""


def engine(angle, sense="ccw", through="", assembly="", r=100, l=400):
    text = ENGINE.format(angle=angle, sense=sense, through=through, assembly=assembly, r=r, l=l)
    return parse_scene(text.replace("'", '"'))


FOURBAR = seed(drive='angle = "{angle}"\nspeed = "10 rad/s ccw"')


def fourbar(angle):
    return parse_scene(FOURBAR.format(angle=angle))


def deg(scene):
    """The crank angle in degrees, in [0, 360) (the reader gives (-180, 180])."""
    a = scene.input.angle
    assert -math.pi < a <= math.pi
    return math.degrees(a) % 360


# the words, and the angle from +x worked out by hand
HAND = [
    ("30 deg above the horizontal", 30),
    ("30 deg below the horizontal", 330),
    ("30 deg above the horizontal, left", 150),
    ("30 deg below the horizontal to the left", 210),
    ("30 deg below the horizontal on the left", 210),
    ("60 deg right of the vertical", 30),
    ("60 deg left of the vertical", 150),
    ("20 deg right of the downward vertical", 290),
    ("20 deg left of the downward vertical", 250),
    ("60 deg from the vertical, cw", 30),
    ("60 deg from the vertical, ccw", 150),
    ("60 deg cw from the vertical", 30),
    ("60° clockwise from the vertical", 30),
    ("60 deg from the vertical anticlockwise", 150),
    ("30 deg from the horizontal, cw", 330),
    ("45 deg ccw from +x", 45),
    ("45 deg measured from the x axis, cw", 315),
    ("0 deg from the vertical", 90),
    ("0 deg from the horizontal", 0),
    ("0.5 rad above the horizontal", math.degrees(0.5)),
    ("30 DEG BELOW THE HORIZONTAL", 330),
]


@pytest.mark.parametrize("words,want", HAND, ids=[w for w, _ in HAND])
def test_book_words_give_the_angle_worked_out_by_hand(words, want):
    sc = fourbar(words)
    assert deg(sc) == pytest.approx(want, rel=1e-12, abs=1e-12)
    assert sc.input.angle_words == words


def test_words_that_name_a_plain_angle_give_exactly_the_plain_angle():
    """ "60 deg right of the vertical" is the plain 30 deg to the last bit (so the two
    scenes' answers are identical, not merely close)."""
    assert fourbar("60 deg right of the vertical").input.angle == fourbar("30 deg").input.angle
    assert fourbar("30 deg below the horizontal").input.angle == fourbar("-30").input.angle
    assert fourbar("30 deg above the horizontal, left").input.angle == fourbar("150").input.angle


def test_plain_angles_are_read_as_before():
    assert fourbar("0.5 rad").input.angle == 0.5  # radians already worked
    assert fourbar("60 deg").input.angle == math.radians(60)
    assert fourbar("330").input.angle == math.radians(330)  # not turned into (-180, 180]
    sc = fourbar("60 deg")
    assert sc.input.angle_words is None and sc.reading_notes == ()
    assert not any("from +x" in n for n in solve(sc).notes)


AMBIGUOUS = [
    ("60 deg from the vertical", "right of the vertical"),
    ("30 deg from the horizontal", "above the horizontal"),
    ("60 deg from the downward vertical", "right of the downward vertical"),
]


@pytest.mark.parametrize("words,suggests", AMBIGUOUS, ids=[w for w, _ in AMBIGUOUS])
def test_an_angle_without_a_side_is_refused_with_the_unambiguous_forms(words, suggests):
    with pytest.raises(SceneError) as exc:
        fourbar(words)
    msg = str(exc.value)
    assert "[input] angle" in msg and "line 11" in msg, msg
    assert "to which side" in msg and suggests in msg, msg
    assert "\n" not in msg


BAD = [
    ("30 deg sideways of the horizontal", "cannot read"),
    ("30 deg from the moon", "measured from what"),
    ("-30 deg above the horizontal", "not negative"),
    ("400 deg above the horizontal", "full turn"),
    ("30 deg cw from the vertical ccw", "two senses"),
    ("30 deg past the vertical", "dead centre"),
]


@pytest.mark.parametrize("words,says", BAD, ids=[w for w, _ in BAD])
def test_bad_forms_are_refused_in_one_line_with_a_good_form(words, says):
    with pytest.raises(SceneError) as exc:
        fourbar(words)
    msg = str(exc.value)
    assert says in msg and "[input] angle" in msg and "\n" not in msg, msg


def test_a_dead_centre_without_a_slider_crank_is_refused(capsys, tmp_path):
    f = tmp_path / "fourbar.toml"
    f.write_text(FOURBAR.format(angle="30 deg past the inner dead centre"))
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and str(f) in err and "[input] angle" in err
    assert "no rod whose other end slides on a fixed path" in err


# ----------------------------------------------------------------- dead centres


def test_dead_centres_of_an_in_line_engine():
    """Piston on the right: the inner dead centre (pin at the piston, OB = l + r) is crank
    angle 0, the outer 180; past = in the crank's sense, before = against it."""
    assert deg(engine("30 deg past the inner dead centre")) == pytest.approx(30)
    assert deg(engine("30 deg past the inner dead centre", "cw")) == pytest.approx(330)
    assert deg(engine("30 deg before the IDC")) == pytest.approx(330)
    assert deg(engine("30 deg from the o.d.c.")) == pytest.approx(210)
    assert deg(engine("30 deg after the outer dead center", "cw")) == pytest.approx(150)
    assert deg(engine("30 deg past the top dead centre")) == pytest.approx(30)
    assert deg(engine("30 deg past the BDC")) == pytest.approx(210)
    # piston on the left: everything turns half a turn
    assert deg(engine("30 deg past the IDC", assembly='[assembly]\nB = "left"')) == pytest.approx(
        210
    )


def test_the_project_convention_for_the_inner_dead_centre():
    """worked_problems/engine_analytical.toml measures "60 deg from i.d.c." as angle = 60
    (crank pin at the piston); the words give the same answers to the last bit."""
    text = (ROOT / "worked_problems" / "engine_analytical.toml").read_text(encoding="utf-8")
    said = text.replace("angle = 60\n", 'angle = "60 deg from the i.d.c."\n')
    assert said != text
    a, b = solve(parse_scene(text)), solve(parse_scene(said))
    assert a.V["B"] == b.V["B"] and a.A["B"] == b.A["B"]


OFFSET = [  # r, l, e (path through (0, -e)), side, sense
    (100, 400, 30, "right", "ccw"),
    (100, 400, 30, "right", "cw"),
    (100, 400, 30, "left", "ccw"),
    (60, 240, -25, "left", "cw"),
    (50, 120, 65, "right", "ccw"),
]


@pytest.mark.parametrize("r,l,e,side,sense", OFFSET)
def test_offset_dead_centres_against_the_closed_form(r, l, e, side, sense):
    """Path y = -e, piston right of the pin: theta_IDC = -asin(e / (l + r)) (crank along
    O->B), theta_ODC = 180 deg - asin(e / (l - r)); the piston on the left mirrors them in
    the y axis (theta -> 180 deg - theta). And the solver's own physics: at either dead
    centre the piston stands still and O, A, B are in line."""
    idc = -math.asin(e / (l + r))
    odc = math.pi - math.asin(e / (l - r))
    if side == "left":
        idc, odc = math.pi - idc, math.pi - odc
    base = dict(
        through=f", through = [0, {-e}]",
        assembly=f'[assembly]\nB = "{side}"',
        sense=sense,
        r=r,
        l=l,
    )
    turn = 1 if sense == "ccw" else -1
    for words, want in (
        ("0 deg past the inner dead centre", idc),
        ("0 deg past the outer dead centre", odc),
        ("25 deg past the inner dead centre", idc + turn * math.radians(25)),
        ("40 deg before the ODC", odc - turn * math.radians(40)),
    ):
        sc = engine(words, **base)
        got = sc.input.angle
        assert math.cos(got - want) == pytest.approx(1, abs=1e-24) and math.sin(
            got - want
        ) == pytest.approx(0, abs=1e-12), (words, got, want)
        sol = solve(sc)
        if words.startswith("0 deg"):
            vb = math.hypot(*sol.V["B"])
            assert vb <= 1e-12 * abs(sc.input.omega) * r / 1000, (words, vb)
            (ox, oy), (ax, ay), (bx, by) = sol.P["O"], sol.P["A"], sol.P["B"]
            assert abs((ax - ox) * (by - oy) - (ay - oy) * (bx - ox)) <= 1e-15
            ob = math.dist((ox, oy), (bx, by)) * 1000
            assert ob == pytest.approx(l + r if "inner" in words else l - r, rel=1e-12)


def test_a_dead_centre_note_says_where_it_is():
    sol = solve(engine("30 deg past the inner dead centre", "cw"))
    assert sol.notes[0] == (
        "crank angle: '30 deg past the inner dead centre' = -30 deg from "
        "+x (the inner dead centre is at 0 deg, the crank turning cw)"
    )


def test_a_rough_position_of_the_piston_settles_its_side():
    """[assembly] B = [x, y] near the piston on the left: the dead centre of that side."""
    sc = engine("30 deg past the IDC", assembly="[assembly]\nB = [-500, 0]")
    assert deg(sc) == pytest.approx(210)
    assert solve(sc).P["B"][0] < 0


def test_no_inner_dead_centre_when_the_rod_cannot_reach():
    with pytest.raises(SceneError) as exc:
        engine("10 deg past the ODC", through=", through = [0, -350]")
    msg = str(exc.value)
    assert "no outer dead centre" in msg and "350 mm" in msg and "[input] angle" in msg


# ----------------------------------------------------------- paths and loads


def test_a_path_and_a_load_in_a_book_s_words():
    text = """
[ground]
O = [0, 0]
[links]
OA = 100
AB = 400
[sliders]
B = { path = "30 deg below the horizontal" }
[input]
crank = "OA"
angle = "45 deg from the line of stroke, ccw"
speed = "10 rad/s ccw"
[loads]
B = { force = "1 kN", direction = "180 deg from the line of stroke, ccw" }
"""
    sc = parse_scene(text)
    u = sc.sliders[0].u
    assert u == pytest.approx((math.cos(math.radians(-30)), math.sin(math.radians(-30))))
    assert deg(sc) == pytest.approx(15)
    assert sc.loads[0].force == pytest.approx((-1000 * u[0], -1000 * u[1]))
    sol = solve(sc)
    assert any(
        n.startswith("slider B's path: '30 deg below the horizontal' = -30 deg") for n in sol.notes
    ), sol.notes
    assert any("line of stroke is at -30 deg" in n for n in sol.notes), sol.notes
    # the line of stroke is not a path's reference, nor a dead centre
    with pytest.raises(SceneError, match="a slider's path is a line of stroke"):
        parse_scene(
            text.replace('"30 deg below the horizontal"', '"10 deg from the line of stroke, cw"')
        )
    with pytest.raises(SceneError, match=r"only \[input\] angle"):
        parse_scene(text.replace('"30 deg below the horizontal"', '"10 deg past the IDC"'))
    with pytest.raises(SceneError, match="does not say to which side"):
        parse_scene(
            text.replace(
                '"45 deg from the line of stroke, ccw"', '"45 deg from the line of stroke"'
            )
        )


# ------------------------------------------------------------------- feet


def test_feet_and_inches():
    sc = parse_scene("""
units = "ft"
[ground]
O = [0, 0]
[links]
OA = "6 in"
AB = "2 ft 6 in"
[sliders]
B = { path = "horizontal", through = [0, -0.25] }
[input]
crank = "OA"
angle = 30
speed = "600 rpm ccw"
""")
    assert sc.link("OA").length == pytest.approx(6 * 0.0254, rel=1e-15)
    assert sc.link("AB").length == pytest.approx(30 * 0.0254, rel=1e-15)
    assert sc.sliders[0].through == pytest.approx((0, -0.25 * 0.3048), rel=1e-15)
    with pytest.raises(SceneError, match="below 12"):
        parse_scene(FOURBAR.format(angle="30").replace("AB = 50", 'AB = "2 ft 14 in"'))
    with pytest.raises(SceneError, match="mm, cm, m, in or ft"):
        parse_scene('units = "yd"\n' + FOURBAR.format(angle="30"))


FEET = ROOT / "tests" / "textbook" / "engine_feet_offset.toml"


def test_a_scene_in_feet_matches_the_same_mechanism_in_si():
    """tests/textbook/engine_feet_offset.toml (feet, inches, "45 deg past the inner dead
    centre", cw) against the same engine in metres with the crank angle from +x worked
    out here: path 3 in below O, piston on the right, so theta = -asin(e / (l + r)) - 45
    deg."""
    from polygon_method import load_scene

    ft = solve(load_scene(FEET))
    r, l, e = 0.5 * 0.3048, (4 * 0.3048 + 6 * 0.0254), 3 * 0.0254
    theta = -math.asin(e / (l + r)) - math.radians(45)
    si = solve(
        parse_scene(f"""
units = "m"
[ground]
O = [0, 0]
[links]
OA = {r!r}
AB = {l!r}
[sliders]
B = {{ path = "horizontal", through = [0, {-e!r}] }}
[input]
crank = "OA"
angle = "{theta!r} rad"
speed = "{300 * 2 * math.pi / 60!r} rad/s cw"
[loads]
B = {{ force = [{-2000 * 4.4482216152605!r}, 0] }}
""")
    )
    for p in "OAB":
        for got, want, scale in ((ft.P, si.P, l), (ft.V, si.V, 1.0), (ft.A, si.A, 10.0)):
            assert got[p] == pytest.approx(want[p], rel=1e-9, abs=1e-12 * scale)
    for k in ("OA", "AB"):
        assert ft.W[k] == pytest.approx(si.W[k], rel=1e-9)
        assert ft.Al[k] == pytest.approx(si.Al[k], rel=1e-9)
    assert ft.input_torque == pytest.approx(si.input_torque, rel=1e-9)


def test_check_names_the_misread_dead_centre():
    """A student who measured "30 deg past the inner dead centre" from the outer one: the
    piston speed at that angle (closed form of the offset slider crank, path y = -e:
    x_B = r cos t + sqrt(l^2 - (r sin t + e)^2)) is diagnosed as that slip."""
    from polygon_method.check import check_answers

    r, l, e, w = 0.1, 0.4, 0.03, 10.0
    t = math.pi - math.asin(e / (l - r)) + math.radians(30)  # the outer dead centre + 30
    h = r * math.sin(t) + e
    v = abs(w * (-r * math.sin(t) - h * r * math.cos(t) / math.sqrt(l * l - h * h)))
    sc = engine(
        "30 deg past the inner dead centre",
        through=", through = [0, -30]",
        assembly=f'[assembly]\nB = "right"\n[answers]\nv_B = "{v:.6g} m/s"',
    )
    (verdict,) = check_answers(solve(sc))
    assert not verdict.ok
    assert "other dead centre" in str(verdict), verdict


def _offset_speed(t, r=0.1, l=0.4, e=0.03, w=10.0):
    """|v_B| of the offset slider crank (path y = -e, piston right) at crank angle t:
    x_B = r cos t + sqrt(l^2 - (r sin t + e)^2), differentiated by hand."""
    h = r * math.sin(t) + e
    return abs(w * (-r * math.sin(t) - h * r * math.cos(t) / math.sqrt(l * l - h * h)))


@pytest.mark.parametrize(
    "words,e,slip_deg,code_words",
    [
        ("30 deg below the horizontal", 0.03, 30, "above the horizontal instead of below"),
        ("60 deg right of the vertical", 0.03, 60, "from the horizontal instead of the vertical"),
        (
            "150 deg before the IDC",
            0.08,
            -math.degrees(math.asin(0.08 / 0.5)) + 150,
            "against the crank's rotation",
        ),
    ],
)
def test_check_names_the_other_misreadings(words, e, slip_deg, code_words):
    from polygon_method.check import check_answers

    v = _offset_speed(math.radians(slip_deg), e=e)
    through = f", through = [0, {-e * 1000:g}]"
    assert (
        abs(v - _offset_speed(solve(engine(words, through=through)).scene.input.angle, e=e))
        > 0.05 * v
    )  # a slip worth telling
    sc = engine(
        words, through=through, assembly=f'[assembly]\nB = "right"\n[answers]\nv_B = "{v:.6g} m/s"'
    )
    (verdict,) = check_answers(solve(sc))
    assert not verdict.ok and code_words in str(verdict), verdict
