"""The answer keys of the crank's cycle and of the configuration: a quick return's ratio of
the time of the cutting stroke to the return stroke (``time_ratio``), a slider's length of
stroke (``stroke_X``), a link's direction from +x (``theta_XY``) and the angle at a joint
(``angle_XYZ``); graded by ``check`` with their slips, asked ``"?"`` and answered by
``solve``, refused in one line where they do not apply. Against closed forms written here
from the geometry: the crank and slotted lever's extreme positions tangent to the crank
circle, the offset slider crank's dead centres, a four-bar's positions by the cosine rule;
and a book's answers (Khurmi & Gupta's shaper, tests/textbook)."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest

from polygon_method import parse_scene, solve
from polygon_method.check import asked_verdicts, check_answers
from polygon_method.cli import main
from polygon_method.scene import load_scene

REL = 1e-9
HERE = Path(__file__).parent
SHAPER = HERE / "textbook" / "khurmi_shaper_ram_time_ratio_stroke.toml"


def _slotted(d, r, L, rod, h, answers):
    """A crank and slotted lever shaper: lever pivot Q, crank centre O at d above it, crank
    r, lever QR = L, the ram S on a horizontal line h above Q, driven by the rod RS."""
    return f"""
units = "mm"
[ground]
Q = [0, 0]
O = [0, {d}]
[links]
OP = {r}
QR = {L}
RS = {rod}
[sliders]
P = {{ along = "QR" }}
S = {{ path = "horizontal", through = [0, {h}] }}
[input]
crank = "OP"
angle = 40
speed = "30 rpm cw"
[answers]
{answers}
"""


def _offset(r, l, e, answers, speed="100 rad/s ccw"):
    """An offset slider crank: crank OA = r about O, rod AB = l, B on y = e."""
    return f"""
units = "mm"
[ground]
O = [0, 0]
[links]
OA = {r}
AB = {l}
[sliders]
B = {{ path = "horizontal", through = [0, {e}] }}
[input]
crank = "OA"
angle = 50
speed = "{speed}"
[answers]
{answers}
"""


def _asked(text) -> dict:
    sol = solve(parse_scene(text))
    return {v.key: v for v in asked_verdicts(sol, sol.scene.answers)}


@pytest.mark.parametrize(
    "d,r,L,rod,h",
    [(300, 150, 700, 200, 680), (400, 100, 600, 250, 590), (250, 150, 500, 150, 480)],
)
def test_slotted_lever_time_ratio_and_stroke_by_the_tangent_positions(d, r, L, rod, h):
    """The lever's extreme positions are tangent to the crank circle, at alpha = asin(r/d)
    either side of the line of centres: the crank turns 180 + 2 alpha on the cutting
    stroke, 180 - 2 alpha on the return; the lever's end swings through the chord
    2 L sin(alpha) = 2 L r / d, and the ram, its rod's other end at the same height at the
    two extremes, moves as far."""
    alpha = math.degrees(math.asin(r / d))
    got = _asked(_slotted(d, r, L, rod, h, 'time_ratio = "?"\nstroke_S = "? mm"'))
    assert got["time_ratio"].correct == pytest.approx(
        (180 + 2 * alpha) / (180 - 2 * alpha), rel=REL
    )
    assert got["stroke_S"].correct == pytest.approx(2 * L * r / d * 1e-3, rel=REL)


@pytest.mark.parametrize("r,l,e", [(50, 200, 30), (80, 300, 60), (40, 120, 10), (60, 250, -40)])
def test_offset_slider_crank_stroke_and_time_ratio_by_its_dead_centres(r, l, e):
    """The dead centres: crank and rod in line, extended (the slider at sqrt((l + r)^2 -
    e^2) from the crank's centre along the line, the crank at asin(e / (l + r))) and folded
    (at sqrt((l - r)^2 - e^2), the crank at 180 + asin(e / (l - r))): the stroke is their
    distance apart, the crank turns 180 + beta between them one way and 180 - beta the
    other, beta = asin(e / (l - r)) - asin(e / (l + r))."""
    stroke = math.sqrt((l + r) ** 2 - e**2) - math.sqrt((l - r) ** 2 - e**2)
    beta = abs(math.asin(e / (l - r)) - math.asin(e / (l + r)))
    got = _asked(_offset(r, l, e, 'time_ratio = "?"\nstroke_B = "?"'))
    assert got["stroke_B"].correct == pytest.approx(stroke * 1e-3, rel=REL)
    assert got["time_ratio"].correct == pytest.approx((math.pi + beta) / (math.pi - beta), rel=REL)
    assert got["stroke_B"].correct_text.endswith(" mm")  # in the scene's unit


def test_in_line_slider_crank_strokes_take_equal_times_and_its_stroke_is_twice_the_crank():
    got = _asked(_offset(50, 200, 0, 'time_ratio = "?"\nstroke_B = "?"'))
    assert got["time_ratio"].correct == pytest.approx(1.0, rel=REL)
    assert got["stroke_B"].correct == pytest.approx(0.100, rel=REL)


FOURBAR = """
units = "mm"
[ground]
A = [0, 0]
D = [{d}, 0]
[links]
AB = {a}
BC = {b}
CD = {c}
[assembly]
C = "above"
[input]
crank = "AB"
angle = {t}
speed = "10 rad/s ccw"
[answers]
theta_CD = "?"
theta_BC = "? rad"
angle_BCD = "?"
angle_ABC = "?"
theta_DC = "?"
"""


@pytest.mark.parametrize(
    "a,b,c,d,t", [(40, 150, 80, 150, 60), (95, 60, 120, 70, 120), (30, 90, 70, 100, 250)]
)
def test_link_angles_against_the_four_bars_closed_form_positions(a, b, c, d, t):
    """B = a (cos t, sin t); C where the circles about B (radius b) and D (radius c) meet,
    the upper one: each direction by atan2, each joint's angle by the cosine rule."""
    bx, by = a * math.cos(math.radians(t)), a * math.sin(math.radians(t))
    bd = math.hypot(d - bx, by)
    phi = math.atan2(-by, d - bx)  # B to D
    beta = math.acos((b * b + bd * bd - c * c) / (2 * b * bd))  # at B, between BD and BC
    cands = [
        (bx + b * math.cos(phi + s * beta), by + b * math.sin(phi + s * beta)) for s in (1, -1)
    ]
    cx, cy = max(cands, key=lambda p: p[1])
    assert math.hypot(cx - d, cy) == pytest.approx(c, rel=1e-12)
    got = _asked(FOURBAR.format(a=a, b=b, c=c, d=d, t=t))  # (SI: rad)
    deg = lambda x: x % (2 * math.pi)  # noqa: E731
    assert got["theta_CD"].correct == pytest.approx(deg(math.atan2(-cy, d - cx)), rel=REL)
    assert got["theta_DC"].correct == pytest.approx(deg(math.atan2(cy, cx - d)), rel=REL)
    theta_bc = math.atan2(cy - by, cx - bx) % (2 * math.pi)
    assert float(got["theta_BC"].correct_text.split()[0]) == pytest.approx(theta_bc, rel=1e-3)
    assert got["theta_BC"].correct == pytest.approx(theta_bc, rel=REL)
    bcd = math.acos((b * b + c * c - bd * bd) / (2 * b * c))
    ac = math.hypot(cx, cy)
    abc = math.acos((a * a + b * b - ac * ac) / (2 * a * b))
    assert got["angle_BCD"].correct == pytest.approx(bcd, rel=REL)
    assert got["angle_ABC"].correct == pytest.approx(abc, rel=REL)
    words = float(got["angle_BCD"].correct_text.removesuffix(" deg"))  # in degrees, 4 figures
    assert words == pytest.approx(math.degrees(bcd), rel=5e-4)


def test_the_books_shaper_ratio_and_stroke_are_right_and_asked_are_answered(tmp_path, capsys):
    """Khurmi & Gupta: the time ratio 2, the stroke 450 mm, graded right; asked "?" the
    same keys are answered by solve's "Answers asked" line, in the book's numbers."""
    verdicts = check_answers(solve(load_scene(SHAPER)))
    assert [v.key for v in verdicts] == ["time_ratio", "stroke_Y"]
    assert all(v.ok for v in verdicts)
    assert verdicts[0].correct == pytest.approx(2.0, rel=REL)
    assert verdicts[1].correct == pytest.approx(0.450, rel=REL)
    asked = tmp_path / "asked.toml"
    asked.write_text('[answers]\ntime_ratio = "?"\nstroke_Y = "?"\n')
    capsys.readouterr()
    assert main(["solve", str(SHAPER), "--answers", str(asked)]) == 0
    out = capsys.readouterr().out
    assert "Answers asked: time_ratio = 2; stroke_Y = 450 mm" in out
    assert main(["solve", str(SHAPER), "--answers", str(asked), "--json"]) == 0
    got = {a["key"]: a for a in json.loads(capsys.readouterr().out)["answers_asked"]}
    assert got["time_ratio"]["value"] == pytest.approx(2.0, rel=REL)
    assert got["stroke_Y"]["value"] == pytest.approx(0.450, rel=REL)
    assert main(["steps", str(SHAPER), "--answers", str(asked)]) == 0
    assert "stroke_Y = 450 mm" in capsys.readouterr().out


@pytest.mark.parametrize(
    "key,given,code",
    [
        ("time_ratio", "0.5", "inverse_ratio"),  # return over cutting
        ("time_ratio", '"2:1"', None),  # as a book writes a ratio
        ("time_ratio", '"1 : 2"', "inverse_ratio"),
        ("stroke_Y", '"450 m"', "wrong_unit"),
        ("stroke_Y", '"45 cm"', None),  # the right stroke in another unit: right
        ("stroke_Y", "0.45", "wrong_unit"),  # metres written bare in a scene in mm
    ],
)
def test_the_classic_slips_are_named(key, given, code):
    text = SHAPER.read_text().split("[answers]")[0] + f"[answers]\n{key} = {given}\n"
    (v,) = check_answers(solve(parse_scene(text)))
    assert v.ok == (code is None) and v.mistake == code


def test_a_links_direction_from_its_other_end_and_an_angles_supplement_are_named():
    text = FOURBAR.format(a=40, b=150, c=80, d=150, t=60).split("[answers]")[0]
    sol = solve(parse_scene(text + "[answers]\ntheta_CD = 10\n"))
    true = (
        math.degrees(math.atan2(*(sol.P["D"][1] - sol.P["C"][1], sol.P["D"][0] - sol.P["C"][0])))
        % 360
    )
    bcd = math.degrees(
        check_answers(solve(parse_scene(text + "[answers]\nangle_BCD = 10\n")))[0].correct
    )  # (SI: rad)
    cases = [
        (f"theta_CD = {(true + 180) % 360}", "other_end", False),
        (f"theta_CD = {true - 360}", None, True),  # -x deg is 360 - x deg
        (f"angle_BCD = {180 - bcd}", "supplement", False),
    ]
    for line, code, ok in cases:
        (v,) = check_answers(solve(parse_scene(text + f"[answers]\n{line}\n")))
        assert (v.ok, v.mistake) == (ok, code), line


BAD = [
    ("double_rocker.toml", 'time_ratio = "?"', "time_ratio: the crank AB does not turn fully"),
    ("drag_link.toml", 'time_ratio = "?"', "no quick return"),
    ("khurmi_shaper_ram_time_ratio_stroke.toml", 'stroke_A = "?"', "not a fixed path"),
    ("khurmi_shaper_ram_time_ratio_stroke.toml", 'stroke_Z = "?"', "no slider Z"),
    ("khurmi_shaper_ram_time_ratio_stroke.toml", 'time_ratio = "? s"', "a bare number"),
    ("khurmi_shaper_ram_time_ratio_stroke.toml", "time_ratio = -2", "a ratio, a bare number"),
    ("khurmi_shaper_ram_time_ratio_stroke.toml", 'angle_PA = "?"', "angle_XYZ names 3"),
    ("khurmi_shaper_ram_time_ratio_stroke.toml", 'theta_PP = "?"', "theta_XY names 2"),
]


@pytest.mark.parametrize("name,line,words", BAD)
def test_a_key_that_does_not_apply_is_refused_in_one_line(tmp_path, capsys, name, line, words):
    text = (HERE / "textbook" / name).read_text().split("[answers]")[0]
    path = tmp_path / name
    path.write_text(text + f"\n[answers]\n{line}\n")
    # (solve reads only the questions: a value given is check's alone)
    for command in ("check", "solve") if '"?' in line else ("check",):
        capsys.readouterr()
        assert main([command, str(path)]) == 2
        err = capsys.readouterr().err
        assert words in err and err.count("\n") == 1 and "Traceback" not in err, err


def test_a_driving_collar_has_no_crank_to_time(tmp_path, capsys):
    src = HERE.parent / "worked_problems" / "collar_on_turning_rod.toml"
    path = tmp_path / "collar.toml"
    path.write_text(src.read_text().split("[answers]")[0] + '\n[answers]\ntime_ratio = "?"\n')
    assert main(["solve", str(path)]) == 2
    assert "no crank turns" in capsys.readouterr().err


def test_a_solve_not_asked_the_cycle_pays_nothing(monkeypatch):
    """The cycle is sampled only where time_ratio or stroke_X is asked: a link's angle, or
    no such key, never builds it."""
    import polygon_method.linkage.cycle_values as cv

    def refuse(*_):
        raise AssertionError("the cycle was sampled")

    monkeypatch.setattr(cv, "_Cycle", refuse)
    text = FOURBAR.format(a=40, b=150, c=80, d=150, t=60)
    sol = solve(parse_scene(text))
    assert len(asked_verdicts(sol, sol.scene.answers)) == 5
    sol = solve(load_scene(SHAPER))
    with pytest.raises(AssertionError):
        check_answers(sol)


def test_a_direction_between_points_that_coincide_is_refused(tmp_path, capsys):
    """At the crank's 0 deg B stands on the ground point E: BE has no direction."""
    path = tmp_path / "coincide.toml"
    path.write_text(
        'units = "mm"\n[ground]\nA = [0, 0]\nD = [150, 0]\nE = [40, 0]\n[links]\nAB = 40\n'
        'BC = 150\nCD = 80\nDE = 110\n[input]\ncrank = "AB"\nangle = 0\n'
        'speed = "10 rad/s ccw"\n[answers]\ntheta_BE = "?"\n'
    )
    assert main(["solve", str(path)]) == 2
    err = capsys.readouterr().err
    assert "theta_BE: B and E coincide at the instant" in err and err.count("\n") == 1


def test_a_class_answer_key_gives_each_variants_ratio_and_stroke(tmp_path, capsys):
    """variants: each variant's crank r, its ratio (180 + 2 alpha) / (180 - 2 alpha) and
    its ram's stroke 2 L sin(alpha), alpha = asin(r / 240), in SI."""
    import csv

    text = SHAPER.read_text().split("[answers]")[0]
    text += '[answers]\ntime_ratio = "?"\nstroke_Y = "?"\n[variants]\nOA = { from = 100, to = 130, step = 10 }\n'
    path = tmp_path / "shaper.toml"
    path.write_text(text)
    out = tmp_path / "out"
    assert main(["variants", str(path), "--count", "3", "-o", str(out)]) == 0
    rows = list(csv.DictReader((out / "answer-key.csv").open()))
    assert len(rows) == 3
    for row in rows:
        r = float(row["OA"].split()[0])
        alpha = math.asin(r / 240)
        ratio = (math.pi + 2 * alpha) / (math.pi - 2 * alpha)
        assert float(row["time_ratio ()"]) == pytest.approx(ratio, rel=REL)
        assert float(row["stroke_Y (m)"]) == pytest.approx(2 * 0.450 * r / 240, rel=REL)


def _whitworth(c, r, p, q, h):
    return f"""
units = "mm"
[ground]
O4 = [0, 0]
O2 = [0, {c}]
[links]
"O2-A" = {r}
"O4-P" = {p}
"P-Q" = {q}
[sliders]
A = {{ along = "O4-P" }}
Q = {{ path = "horizontal", through = [0, {h}] }}
[assembly]
Q = "right"
[input]
crank = "O2-A"
angle = 30
speed = "60 rpm cw"
[answers]
time_ratio = "?"
stroke_Q = "?"
"""


@pytest.mark.parametrize("c,r,p,q,h", [(50, 100, 150, 450, 250), (60, 120, 100, 400, 200)])
def test_whitworth_ratio_and_stroke_by_the_rams_dead_points(c, r, p, q, h):
    """The ram Q stands still where the rod PQ lies along the lever O4P: extended (O4Q =
    p + q) and folded (O4Q = q - p, P on the far side of O4); its stroke is the two places
    apart. The block A on the lever's line through O4 (on P's side) meets the crank circle
    about O2 at s = c sin(phi) + sqrt(c^2 sin^2(phi) + r^2 - c^2) from O4: the crank's
    angles there split its turn into the two strokes."""
    x1, x2 = math.sqrt((p + q) ** 2 - h * h), math.sqrt((q - p) ** 2 - h * h)
    phis = (math.atan2(h, x1), math.atan2(h, x2) + math.pi)  # the lever, O4 to P

    def crank(phi):
        s = c * math.sin(phi) + math.sqrt((c * math.sin(phi)) ** 2 + r * r - c * c)
        return math.atan2(s * math.sin(phi) - c, s * math.cos(phi))

    arc = (crank(phis[1]) - crank(phis[0])) % (2 * math.pi)
    ratio = max(arc, 2 * math.pi - arc) / min(arc, 2 * math.pi - arc)
    got = _asked(_whitworth(c, r, p, q, h))
    assert got["stroke_Q"].correct == pytest.approx((x1 - x2) * 1e-3, rel=REL)
    assert got["time_ratio"].correct == pytest.approx(ratio, rel=REL)


def test_the_ratio_and_the_stroke_of_one_output_are_one_search(monkeypatch):
    import polygon_method.linkage.cycle_values as cv

    seen = []
    real = cv.motion_over_cycle

    def spy(*args, **kw):
        seen.append(args[1].name)
        return real(*args, **kw)

    monkeypatch.setattr(cv, "motion_over_cycle", spy)
    scene = load_scene(SHAPER)  # (a scene of its own: none kept from another test)
    assert [v.ok for v in check_answers(solve(scene))] == [True, True]
    assert seen == ["Y"]


def test_a_direction_near_nought_is_held_to_a_right_angles_tolerance():
    """A direction written near 0 deg was held to 0.5 % of itself (1.5 deg: +-0.0075 deg) and
    the same direction written as -358.5 deg to +-1.8 deg: both are now held to 0.5 % of a
    right angle at the least (0.45 deg), the direction's true place by atan2 of the
    positions."""
    text = FOURBAR.format(a=40, b=150, c=80, d=150, t=60).split("[answers]")[0]
    sol = solve(parse_scene(text))
    true = math.degrees(math.atan2(sol.P["C"][1] - sol.P["B"][1], sol.P["C"][0] - sol.P["B"][0]))
    tol = 0.005 * 90
    for off, ok in ((0.4 * tol, True), (-0.9 * tol, True), (1.1 * tol, False), (-1.2 * tol, False)):
        for written in (true + off, true + off - 360):  # the same direction, two ways
            answers = f'[answers]\ntolerance = "0.5%"\ntheta_BC = {written}\n'
            (v,) = check_answers(solve(parse_scene(text + answers)))
            assert v.ok == ok, (written, true)
