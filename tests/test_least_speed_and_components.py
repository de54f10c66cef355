"""Two points of one link, as the books ask of them: the point with the least absolute
velocity (``vmin_BC``) and the radial and tangential components of a relative acceleration
(``ar_CB``, ``at_CB``).

Against independent references: the least speed by a brute-force search (golden section)
over the material points of the segment, their velocities by central finite differences of
the 50-digit loop-closure solve (tests/reference.py) at the crank turned either way; for a
slider crank also the closed form, |omega_rod| times the distance from the rod's
instantaneous centre (the crank produced meeting the normal to the stroke at B) to the rod;
the components as omega^2 r and alpha r with the reference's omega and alpha, and as the
parts of the reference's a_CB along and across CB. Then: every view shows them where asked
(and only there), check flags a wrong value and names the slips, and bad keys are refused
in one line.
"""

import json
import math
import subprocess
import sys
from pathlib import Path

import mpmath
import pytest
from mpmath import mpf

from polygon_method import load_scene, parse_scene, solve
from polygon_method.check import check_answers
from polygon_method.common.errors import SceneError
from polygon_method.motion.link_points import components, least_speed
from polygon_method.text.report import solution_text
from polygon_method.text.steptable import steps_text
from reference import reference_positions, reference_slider_crank, reference_solution

HERE = Path(__file__).resolve().parent
BOOK = HERE / "textbook" / "rattan_slider_crank_least_speed.toml"
REL = 1e-9


def _slider_crank(angle, answers="", extra=""):
    return f"""
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 480
AB = 1600
[points]
E = {{ on = "AB", along = -450 }}
{extra}
[sliders]
B = {{ path = "horizontal", through = "O" }}
[assembly]
B = "right"
[input]
crank = "OA"
angle = {angle}
speed = "20 rad/s ccw"
acceleration = "30 rad/s^2 cw"
[answers]
{answers}
"""


FOURBAR = """
units = "mm"
[ground]
O2 = [0, 0]
O4 = [380, 40]
[links]
"O2-A" = 120
AB = 350
"O4-B" = 260
[points]
C = {{ on = "AB", distances = {{ A = 200, B = 250 }}, turn = "ccw" }}
[input]
crank = "O2-A"
angle = {angle}
speed = "12 rad/s cw"
acceleration = "40 rad/s^2 ccw"
[assembly]
B = "above"
[answers]
{answers}
"""


def _fd_velocities(scene, P, names, h=mpf("1e-20")):
    """Each point's velocity by central differences of the reference's positions at the
    crank turned by +-h (d/dt = omega d/dtheta): no velocity formula of the tool's."""
    th, w = mpf(scene.input.angle), mpf(scene.input.omega)
    plus, _ = reference_positions(scene, P, th + h)
    minus, _ = reference_positions(scene, P, th - h)
    return {n: tuple(w * (plus[n][i] - minus[n][i]) / (2 * h) for i in range(2)) for n in names}


def _brute_least(Px, Py, Vx, Vy, lo=0, hi=1):
    """(s, speed): the slowest material point X + s (Y - X), s in [lo, hi], by golden
    section on the speed of each point (its velocity: the points' as differenced)."""

    def speed(s):
        return mpmath.hypot(Vx[0] + s * (Vy[0] - Vx[0]), Vx[1] + s * (Vy[1] - Vx[1]))

    a, b = mpf(lo), mpf(hi)
    g = (mpmath.sqrt(5) - 1) / 2
    for _ in range(260):
        c, d = b - g * (b - a), a + g * (b - a)
        if speed(c) < speed(d):
            b = d
        else:
            a = c
    s = (a + b) / 2
    return s, speed(s)


CASES = [
    ("slider", _slider_crank(60), "A", "B"),
    ("slider", _slider_crank(160), "A", "B"),  # the foot beyond b: the least at B
    ("slider", _slider_crank(20), "E", "B"),  # a point of the rod produced
    ("slider", _slider_crank(250), "B", "E"),
    ("fourbar", FOURBAR.format(angle=75, answers=""), "A", "B"),
    ("fourbar", FOURBAR.format(angle=75, answers=""), "C", "B"),  # a plate's two points
    ("fourbar", FOURBAR.format(angle=200, answers=""), "A", "C"),
]


@pytest.mark.parametrize(
    "kind,text,x,y", CASES, ids=[f"{c[0]}-{c[2]}{c[3]}-{i}" for i, c in enumerate(CASES)]
)
def test_least_speed_against_a_brute_force_search_of_the_reference(kind, text, x, y):
    scene = parse_scene(text)
    sol = solve(scene)
    ls = least_speed(sol, x, y)
    P, _ = reference_positions(scene, sol.P)
    V = _fd_velocities(scene, sol.P, (x, y))
    s, v = _brute_least(P[x], P[y], V[x], V[y])
    assert abs(ls.speed - float(v)) <= REL * max(float(v), sol.speed(x)), (ls, v)
    assert abs(ls.at - float(s)) < 1e-6  # (the search's own flatness at the least)
    # the line produced: the foot anywhere
    s_all, v_all = _brute_least(P[x], P[y], V[x], V[y], -20, 20)
    assert abs(ls.foot_speed - float(v_all)) <= REL * max(float(v_all), sol.speed(x))
    assert abs(ls.fraction - float(s_all)) < 1e-6
    inside = 0 <= s_all <= 1
    assert (ls.where == "between") == inside
    if not inside:  # the least on the link itself at the nearer end
        end = x if s_all < 0 else y
        assert ls.where == f"beyond {end}" and ls.at == (0.0 if end == x else 1.0)
        assert abs(ls.speed - sol.speed(end)) <= REL * sol.speed(end)


def test_the_cases_cover_a_foot_beyond_the_link():
    """The cases are not all of one kind: at 160 deg the foot falls beyond b."""
    assert least_speed(solve(parse_scene(_slider_crank(160))), "A", "B").where == "beyond B"
    assert least_speed(solve(parse_scene(_slider_crank(60))), "A", "B").where == "between"


@pytest.mark.parametrize("angle", [30, 60, 100, 140, 215, 300])
def test_least_speed_of_a_slider_cranks_rod_by_its_instantaneous_centre(angle):
    """The closed form: the rod turns about I (OA produced meets the normal to the stroke at
    B); the line AB's slowest point is the foot of the perpendicular from I, at |omega_rod|
    times I's distance from AB."""
    r, l, th = mpf("0.48"), mpf("1.6"), mpmath.radians(angle)
    ref = reference_slider_crank(r, l, 0, th, 20, -30)
    A = (r * mpmath.cos(th), r * mpmath.sin(th))
    B = (ref["x"], mpf(0))
    # I = t (cos th, sin th) with t cos th = x_B
    t = B[0] / mpmath.cos(th)
    I = (t * mpmath.cos(th), t * mpmath.sin(th))
    d = (B[0] - A[0], B[1] - A[1])
    dist = abs(d[0] * (I[1] - A[1]) - d[1] * (I[0] - A[0])) / mpmath.hypot(*d)
    want = abs(ref["omega_rod"]) * dist
    ls = least_speed(solve(parse_scene(_slider_crank(angle))), "A", "B")
    assert abs(ls.foot_speed - float(want)) <= REL * float(want)


@pytest.mark.parametrize("text,x,y", [(c[1], c[2], c[3]) for c in CASES])
def test_components_against_the_reference(text, x, y):
    scene = parse_scene(text)
    sol = solve(scene)
    ref = reference_solution(scene, sol.P)
    P, A = ref["positions"], ref["accelerations"]
    lk = next(
        lk
        for lk in scene.links
        if {x, y} <= {lk.p, lk.q} | {c.name for c in scene.points if c.link == lk.key}
    )
    w, al = ref["omega"][lk.key], ref["alpha"][lk.key]
    rv = (P[x][0] - P[y][0], P[x][1] - P[y][1])
    r = mpmath.hypot(*rv)
    c = components(sol, x, y)
    assert abs(c.radial - float(w * w * r)) <= REL * float(w * w * r)
    assert abs(c.tangential - float(abs(al) * r)) <= REL * max(float(abs(al) * r), 1e-300)
    # and as the parts of the reference's a_XY along and across XY: -omega^2 r along X->Y
    a = (A[x][0] - A[y][0], A[x][1] - A[y][1])
    along = -(a[0] * rv[0] + a[1] * rv[1]) / r  # towards Y: positive
    across = abs(rv[0] * a[1] - rv[1] * a[0]) / r
    assert abs(c.radial - float(along)) <= REL * float(abs(along))
    assert abs(c.tangential - float(across)) <= REL * float(abs(across))
    assert sol.value("ar", (x, y)) == c.radial and sol.value("at", (y, x)) == c.tangential


PARALLELOGRAM = """
units = "mm"
[ground]
O2 = [0, 0]
O4 = [400, 0]
[links]
"O2-A" = 100
AB = 400
"O4-B" = 100
[input]
crank = "O2-A"
angle = 70
speed = "10 rad/s ccw"
[assembly]
B = "above"
[answers]
vmin_AB = "1 m/s"
ar_BA = "0 m/s^2"
"""


def test_a_slider_cranks_rod_at_a_crank_square_to_the_stroke_does_not_turn():
    """At 90 deg the rod's omega is 0 (its instantaneous centre at infinity): every point of
    it moves as the crank pin, omega x OA = 9.6 m/s; no division by a zero bc."""
    sol = solve(parse_scene(_slider_crank(90, 'vmin_AB = "9.6 m/s"')))
    ls = least_speed(sol, "A", "B")
    assert ls.where == "translating" and abs(ls.speed - 9.6) <= REL * 9.6
    assert "AB does not turn" in solution_text(sol) and all(v.ok for v in check_answers(sol))


def test_a_link_that_does_not_turn_moves_alike_everywhere():
    sol = solve(parse_scene(PARALLELOGRAM))
    ls = least_speed(sol, "A", "B")
    assert ls.where == "translating" and ls.fraction is None
    assert abs(ls.speed - 1.0) <= REL  # v_A = 10 x 0.1, every point's
    assert components(sol, "B", "A").radial == 0.0
    text = solution_text(sol)
    assert "AB does not turn (omega_AB = 0), so every point of it moves alike, at 1 m/s" in text
    assert all(v.ok for v in check_answers(sol))


# ----------------------------------------------------------------------------- the views


def test_every_view_shows_them_where_asked():
    sc = load_scene(BOOK)
    sol = solve(sc)
    text = solution_text(solve(load_scene(BOOK, answers=False)))  # as solve reads it
    assert "vmin_AB = 9.275 m/s at P on AB" in text
    assert "AP = 796.7 mm (AP / AB = 0.498)" in text
    assert (
        "ar_BA = omega_AB^2 x BA = 3.107^2 x 1.6 = 15.44 m/s^2, along BA from B towards A" in text
    )
    assert "at_BA = alpha_AB x BA = 105 x 1.6 = 168 m/s^2" in text
    steps = steps_text(solve(load_scene(BOOK, answers=False)))
    assert (
        "from o draw op perpendicular to ab, meeting ab at p: AP = AB x ap / ab = 1600 mm x "
        "0.498 = 796.7 mm; v_P = op = 9.275 m/s"
    ) in " ".join(steps.split())
    d = json.loads(json.dumps(sol.to_dict()))
    e = d["link_points"]["vmin_AB"]
    assert e["where"] == "between" and abs(e["distance"] - 0.79672451503019) < 1e-12
    assert abs(d["link_points"]["at_BA"]["tangential"] - 168.035093509602) < 1e-9
    assert all(v.ok for v in check_answers(sol))


def test_nothing_is_shown_where_nothing_is_asked():
    sol = solve(parse_scene(_slider_crank(60)))
    assert "link_points" not in sol.to_dict()
    assert "asked of two points" not in solution_text(sol)
    assert "Asked of two points" not in steps_text(sol)


def test_the_foot_beyond_the_link_is_said():
    sol = solve(parse_scene(_slider_crank(160, 'vmin_AB = "1 m/s"')))
    text = " ".join(solution_text(sol).split())
    ls = least_speed(sol, "A", "B")
    assert "at the end B" in text and "p falls beyond b, outside ab" in text
    assert ls.speed == pytest.approx(sol.speed("B"), rel=1e-15)


def test_the_cli_solve_and_json_read_the_keys_from_the_scene():
    run = lambda *a: subprocess.run(  # noqa: E731
        [sys.executable, "-m", "polygon_method", *a, str(BOOK)],
        capture_output=True,
        text=True,
        cwd=HERE.parent,
    )
    out = run("solve")
    assert out.returncode == 0 and "vmin_AB = 9.275 m/s" in out.stdout
    d = json.loads(run("solve", "--json").stdout)
    assert set(d["link_points"]) == {"vmin_AB", "ar_BA", "at_BA"}


# ----------------------------------------------------------------------------- check


def _verdict(text, key):
    sol = solve(parse_scene(text))
    return next(v for v in check_answers(sol) if v.key == key), sol


def test_check_flags_a_wrong_least_speed_and_names_the_midpoint():
    sol = solve(parse_scene(_slider_crank(160)))
    (ax, ay), (bx, by) = sol.V["A"], sol.V["B"]
    mid = math.hypot(ax + bx, ay + by) / 2
    v, _ = _verdict(_slider_crank(160, f'vmin_AB = "{mid:.4g} m/s"'), "vmin_AB")
    assert not v.ok and v.mistake == "midpoint_speed", v


def test_check_names_the_least_of_the_line_produced():
    sol = solve(parse_scene(_slider_crank(100)))  # op 8.54 m/s, v_B 8.94 m/s
    op = least_speed(sol, "A", "B").foot_speed
    answers = f'tolerance = "1%"\nvmin_AB = "{op:.4g} m/s"'  # (4.5 % from the right one)
    v, _ = _verdict(_slider_crank(100, answers), "vmin_AB")
    assert not v.ok and v.mistake == "produced_for_link", v


def test_check_names_swapped_components_and_another_links_omega():
    sol = solve(parse_scene(_slider_crank(60)))
    c = components(sol, "B", "A")
    v, _ = _verdict(_slider_crank(60, f'ar_BA = "{c.tangential:.4g} m/s^2"'), "ar_BA")
    assert not v.ok and v.mistake == "components_swapped", v
    crank = 20.0**2 * c.r  # the crank's omega squared
    v, _ = _verdict(_slider_crank(60, f'ar_BA = "{crank:.4g} m/s^2"'), "ar_BA")
    assert not v.ok and v.mistake == "other_link_rate", v
    v, _ = _verdict(_slider_crank(60, f'at_AB = "{c.radial:.4g} m/s^2"'), "at_AB")
    assert not v.ok and v.mistake == "components_swapped", v
    v, _ = _verdict(_slider_crank(60, f'at_AB = "{c.tangential:.4g} m/s^2"'), "at_AB")
    assert v.ok


def test_a_key_of_two_points_of_no_one_link_is_refused_in_one_line():
    sol = solve(parse_scene(_slider_crank(60, 'vmin_OB = "1 m/s"')))
    with pytest.raises(SceneError) as e:
        check_answers(sol)
    assert "O and B are not two points of one link" in str(e.value)
    assert "vmin_OB" in str(e.value)
    with pytest.raises(SceneError, match="names two points of one link"):
        parse_scene(_slider_crank(60, 'ar_AA = "1 m/s^2"'))
    with pytest.raises(SceneError, match="did you mean 'vmin_AB'"):
        parse_scene(_slider_crank(60, 'vmin_Ab = "1 m/s"'))


def test_a_students_answer_file_and_either_order_of_the_names():
    """An answer file reads the keys as the scene does; vmin_BA is vmin_AB, ar_AB is ar_BA
    (one size): each graded once, in the first name's row."""
    from polygon_method.scene import parse_answers

    sol = solve(load_scene(BOOK, answers=False))
    _, answers = parse_answers(
        '[answers]\nvmin_BA = "9.28 m/s"\nvmin_AB = "9.27 m/s"\nar_AB = "15.4 m/s^2"\n',
        sol.scene,
    )
    verdicts = check_answers(sol, answers)
    assert [v.key for v in verdicts] == ["vmin_BA", "ar_AB"]
    assert verdicts[0].also and verdicts[0].column == "vmin_AB" and all(v.ok for v in verdicts)


def test_the_default_tolerance_is_a_careful_hand_drawings():
    """Read off the drawn polygons as v_B is: op from the drawn a and b, v_BA^2 / BA with
    the drawn v_BA, the tangential component between the drawn images; each says how it is
    built, and none is tighter than the points' own read-offs would make it."""
    text = BOOK.read_text().replace('tolerance = "1%"', "")
    sol = solve(parse_scene(text))
    got = {v.key: v for v in check_answers(sol)}
    assert "built as: op, p the foot of the perpendicular" in got["vmin_AB"].rule
    assert "built as: v_XY^2 / XY" in got["ar_BA"].rule
    assert got["vmin_AB"].tolerance > 0.01 and got["at_BA"].tolerance > 0.01
    # v^2 / r doubles the relative error of the drawn v_BA (omega_AB's is v_BA's)
    assert got["ar_BA"].tolerance > 1.5 * got["omega_AB"].tolerance


def test_the_velocity_polygon_draws_op_where_asked(tmp_path):
    """draw: op from the pole square to ab, its foot p named; ab produced to p where p falls
    beyond b (at 120 deg); nothing where vmin is not asked."""

    def drawn(text):
        scene = tmp_path / "s.toml"
        scene.write_text(text)
        out = tmp_path / "v.svg"
        subprocess.run(
            [sys.executable, "-m", "polygon_method", "draw", str(scene), "--diagram", "velocity"]
            + ["-o", str(out)],
            check=True,
            capture_output=True,
            cwd=HERE.parent,
        )
        return out.read_text()

    between = drawn(_slider_crank(60, 'vmin_AB = "9 m/s"'))
    assert 'id="velocity-least-A-B-0"' in between and "velocity-least-A-B-1" not in between
    beyond = drawn(_slider_crank(120, 'vmin_AB = "7 m/s"'))
    assert 'id="velocity-least-A-B-1"' in beyond  # ab produced to p
    assert "velocity-least" not in drawn(_slider_crank(60))
