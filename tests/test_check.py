"""Answer checking: each known mistake, made on purpose, is named; right answers pass.

The wrong values are derived here independently of the solver: closed-form slider-crank
kinematics (x = r cos th + sqrt(l^2 - (r sin th - e)^2), phi' = -r w cos th / (l cos phi))
and the closed-form four-bar angular velocities (w3 = w2 a sin(t4 - t2) / (b sin(t3 - t4)),
w4 = w2 a sin(t2 - t3) / (c sin(t4 - t3))), with the mistake made in the arithmetic.
"""

import json
import math
from pathlib import Path

import pytest

from polygon_method import load_scene, parse_scene, solve
from polygon_method.check import check_answers
from polygon_method.cli import main
from polygon_method.common.errors import SceneError
from polygon_method.polygons.scales import parse_scale
from polygon_method.scene import parse_answers
from scenes import TRANSLATING_COUPLER, seed

ROOT = Path(__file__).resolve().parent.parent

R, L, E = 0.100, 0.350, 0.020  # crank, rod, offset (m)


def slider_scene(theta=30.0, speed="300 rpm ccw", branch="right", extra=""):
    return parse_scene(f"""
[ground]
O = [0, 0]
[links]
OA = 100
AB = 350
[sliders]
B = {{ path = "horizontal", through = [0, 20] }}
[assembly]
B = "{branch}"
[input]
crank = "OA"
angle = {theta}
speed = "{speed}"
[pins]
A = {{ diameter = 20 }}
[loads]
B = {{ force = "1 kN", direction = 180 }}
{extra}
""")


def slider_closed_form(theta_deg, w, s=1.0):
    """Closed-form offset slider crank: dict of v_A, v_B, v_BA, omega_AB (signed), x_B."""
    th = math.radians(theta_deg)
    h = R * math.sin(th) - E
    root = math.sqrt(L * L - h * h)
    x = R * math.cos(th) + s * root
    xdot = -R * w * math.sin(th) - s * h * R * w * math.cos(th) / root
    cos_phi = s * root / L
    w_ab = -R * w * math.cos(th) / (L * cos_phi)
    return {
        "v_A": abs(w) * R,
        "v_B": abs(xdot),
        "xdot": xdot,
        "v_BA": abs(w_ab) * L,
        "omega_AB": w_ab,
        "x": x,
    }


RPM = 2 * math.pi / 60


def verdict(scene, text):
    """Check the answers in ``text`` (an answer file) against the scene."""
    tol, answers = parse_answers(text, scene)
    return {v.key: v for v in check_answers(solve(scene), answers, tol)}


def one(scene, key, value, unit, sense=""):
    raw = f"{value!r} {unit}" + (f" {sense}" if sense else "")
    return verdict(scene, f'[answers]\n{key} = "{raw}"\n')[key]


# --------------------------------------------------------------------------- right answers


def test_right_answers_pass_under_the_drawing_rule():
    sc = slider_scene()
    cf = slider_closed_form(30, 300 * RPM)
    torque = 1000 * cf["xdot"] / (300 * RPM)  # T w + F.v = 0, F = -1000 x
    rub = abs(300 * RPM - cf["omega_AB"]) * 0.010
    text = f"""[answers]
v_A = "{cf["v_A"]:.3g} m/s"
v_B = "{cf["v_B"]:.3g} m/s"
v_BA = "{cf["v_BA"]:.3g} m/s"
omega_AB = "{abs(cf["omega_AB"]):.3g} rad/s {"ccw" if cf["omega_AB"] > 0 else "cw"}"
rub_A = "{rub:.3g} m/s"
torque = "{abs(torque):.3g} N m {"ccw" if torque > 0 else "cw"}"
"""
    got = verdict(sc, text)
    assert all(v.ok for v in got.values()), [(k, v.error, v.tolerance) for k, v in got.items()]
    assert all(v.mistake is None for v in got.values())


def test_stated_tolerance_is_the_boundary():
    sc = slider_scene()
    v_b = slider_closed_form(30, 300 * RPM)["v_B"]
    inside = verdict(sc, f'[answers]\ntolerance = "2%"\nv_B = "{v_b * 1.019!r} m/s"\n')
    outside = verdict(sc, f'[answers]\ntolerance = "2%"\nv_B = "{v_b * 1.021!r} m/s"\n')
    assert inside["v_B"].ok and not outside["v_B"].ok
    assert outside["v_B"].error == pytest.approx(0.021, rel=1e-6)


def test_the_default_is_never_tighter_than_half_a_millimetre_at_the_velocity_scale():
    sc = slider_scene()
    sol = solve(sc)
    v_b = slider_closed_form(30, 300 * RPM)["v_B"]
    vmax = max(
        math.dist(p, q)
        for p in list(sol.V.values()) + [(0, 0)]
        for q in list(sol.V.values()) + [(0, 0)]
    )
    # independent scale choice: smallest 1, 2, 2.5, 5 x 10^k with vmax / s <= 12 cm
    cands = sorted(m * 10.0**k for m in (1, 2, 2.5, 5) for k in range(-4, 4))
    s = next(c for c in cands if vmax / c <= 12 * (1 + 1e-12))
    band = 0.05 * s
    assert band > 0.005 * v_b  # the drawing, not the rounding floor, decides here
    ok = one(sc, "v_B", v_b + 0.98 * band, "m/s")
    assert ok.ok
    assert ok.tolerance_abs >= band * (1 - 1e-12)
    far = one(sc, "v_B", v_b * 1.25, "m/s")  # a quarter off: no careful drawing is
    assert not far.ok


def test_sense_is_checked_only_where_given():
    sc = slider_scene()
    w = slider_closed_form(30, 300 * RPM)["omega_AB"]
    assert one(sc, "omega_AB", abs(w), "rad/s").ok
    right = "ccw" if w > 0 else "cw"
    assert one(sc, "omega_AB", abs(w), "rad/s", right).ok


# --------------------------------------------------------------------------- each mistake


def test_rpm_used_as_rad_s():
    sc = slider_scene()
    wrong = slider_closed_form(30, 300.0)["v_B"]  # omega = N
    v = one(sc, "v_B", wrong, "m/s")
    assert not v.ok and v.mistake == "rpm_as_rad_s"
    assert "rpm used as rad/s" in v.diagnosis


def test_rps_and_rpm_confused():
    sc = slider_scene()
    wrong = slider_closed_form(30, 2 * math.pi * 300)["v_BA"]  # 300 taken as rps
    v = one(sc, "v_BA", wrong, "m/s")
    assert v.mistake == "rps_rpm"


def test_rad_s_taken_as_rpm():
    sc = slider_scene(speed="30 rad/s ccw")
    wrong = slider_closed_form(30, 30 * RPM)["v_B"]
    v = one(sc, "v_B", wrong, "m/s")
    assert v.mistake == "rad_s_as_rpm"


def test_relative_velocity_given_for_absolute():
    sc = slider_scene()
    cf = slider_closed_form(30, 300 * RPM)
    v = one(sc, "v_B", cf["v_BA"], "m/s")
    assert v.mistake == "relative_for_absolute" and "v_BA" in v.diagnosis


def test_absolute_velocity_given_for_relative():
    sc = slider_scene()
    cf = slider_closed_form(30, 300 * RPM)
    v = one(sc, "v_BA", cf["v_B"], "m/s")
    assert v.mistake == "absolute_for_relative" and "v_B" in v.diagnosis


def test_other_assembly_branch():
    sc = slider_scene(theta=60)
    wrong = slider_closed_form(60, 300 * RPM, s=-1.0)["v_B"]
    assert abs(wrong - slider_closed_form(60, 300 * RPM)["v_B"]) > 0.2
    v = one(sc, "v_B", wrong, "m/s")
    assert v.mistake == "other_branch" and "B left" in v.diagnosis


def test_diameter_used_as_radius():
    sc = slider_scene()
    w_ab = slider_closed_form(30, 300 * RPM)["omega_AB"]
    wrong = abs(300 * RPM - w_ab) * 0.020  # 20 mm is the diameter
    v = one(sc, "rub_A", wrong, "m/s")
    assert v.mistake == "diameter_as_radius"


def test_difference_where_the_sum_applies():
    # at 30 deg the rod turns cw while the crank turns ccw: the sum applies
    sc = slider_scene()
    w_ab = slider_closed_form(30, 300 * RPM)["omega_AB"]
    assert w_ab < 0
    wrong = abs(300 * RPM - abs(w_ab)) * 0.010
    v = one(sc, "rub_A", wrong, "m/s")
    assert v.mistake == "difference_for_sum"


def test_sum_where_the_difference_applies():
    # at 150 deg both turn ccw: the difference applies
    sc = slider_scene(theta=150)
    w_ab = slider_closed_form(150, 300 * RPM)["omega_AB"]
    assert w_ab > 0
    wrong = (300 * RPM + w_ab) * 0.010
    v = one(sc, "rub_A", wrong, "m/s")
    assert v.mistake == "sum_for_difference"


def test_one_component_given_for_a_relative_acceleration():
    """a_BA of the rod: omega_AB^2 AB alone (the closed form's omega) is the centripetal
    component without the tangential one, and the checker says which is missing."""
    sc = slider_scene()
    w_ab = slider_closed_form(30, 300 * RPM)["omega_AB"]
    v = one(sc, "a_BA", w_ab * w_ab * L, "m/s^2")
    assert not v.ok and v.mistake == "component_only"
    assert "only the centripetal component" in v.diagnosis and "a_BA" in v.diagnosis


def fourbar_closed_form(theta2_deg=60.0, w2=-10.5, a=0.05, b=0.066, c=0.056, d=0.1):
    """Closed-form four-bar (C above AD): link angles and w3 (BC), w4 (DC)."""
    t2 = math.radians(theta2_deg)
    bx, by = a * math.cos(t2), a * math.sin(t2)
    # C: |C - B| = b, |C - D| = c, D = (d, 0), the upper intersection
    ex, ey = d - bx, -by
    e = math.hypot(ex, ey)
    along = (b * b - c * c + e * e) / (2 * e)
    h = math.sqrt(b * b - along * along)
    ux, uy = ex / e, ey / e
    cands = [(bx + along * ux - s * h * uy, by + along * uy + s * h * ux) for s in (1, -1)]
    cx, cy = max(cands, key=lambda p: p[1])
    t3 = math.atan2(cy - by, cx - bx)
    t4 = math.atan2(cy, cx - d)
    w3 = w2 * a * math.sin(t4 - t2) / (b * math.sin(t3 - t4))
    w4 = w2 * a * math.sin(t2 - t3) / (c * math.sin(t4 - t3))
    return w3, w4


FOURBAR = seed(
    middle='[assembly]\nC = "above"\n',
    after="[pins]\nA = { radius = 30 }\nB = { radius = 40 }\n[loads]\nC = { force = [0, -500] }\n",
)


def test_closed_form_fourbar_agrees():
    w3, w4 = fourbar_closed_form()
    sol = solve(parse_scene(FOURBAR))
    assert sol.omega("BC") == pytest.approx(w3, rel=1e-9)
    assert sol.omega("CD") == pytest.approx(w4, rel=1e-9)


def test_angular_velocities_of_links_that_do_not_meet_at_the_pin():
    w3, w4 = fourbar_closed_form()
    # pin A joins the ground and AB; the student adds omega_BC
    wrong = (10.5 + abs(w3)) * 0.030
    v = one(parse_scene(FOURBAR), "rub_A", wrong, "m/s")
    assert v.mistake == "links_not_at_pin" and "BC" in v.diagnosis


def test_wrong_angular_velocity_in_the_power_balance():
    sc = slider_scene()
    cf = slider_closed_form(30, 300 * RPM)
    power = -1000 * cf["xdot"]
    wrong = abs(power / cf["omega_AB"])  # divided by the rod's omega
    v = one(sc, "torque", wrong, "N m")
    assert v.mistake == "wrong_omega_in_power_balance" and "omega_AB" in v.diagnosis


def test_wrong_sense():
    w3, _ = fourbar_closed_form()
    sense = "cw" if w3 > 0 else "ccw"  # the wrong one
    v = one(parse_scene(FOURBAR), "omega_BC", abs(w3), "rad/s", sense)
    assert not v.ok and v.mistake == "sense"


def test_mm_per_s_given_as_m_per_s():
    sc = slider_scene()
    v_b = slider_closed_form(30, 300 * RPM)["v_B"]
    v = one(sc, "v_B", round(v_b * 1000, 1), "m/s")
    assert v.mistake == "mm_m"


def test_degrees_per_second_given_as_rad_per_s():
    _, w4 = fourbar_closed_form()
    v = one(parse_scene(FOURBAR), "omega_CD", math.degrees(abs(w4)), "rad/s")
    assert v.mistake == "deg_rad"


def test_crank_angle_in_degrees_used_as_radians():
    sc = slider_scene()
    wrong = slider_closed_form(math.degrees(30.0), 300 * RPM)["v_B"]  # sin(30 rad)
    v = one(sc, "v_B", wrong, "m/s")
    assert v.mistake == "angle_in_radians"


def test_slip_of_the_pen():
    sc = slider_scene()
    v_ba = slider_closed_form(30, 300 * RPM)["v_BA"]
    s = f"{v_ba:.2f}"
    first = "1" if s[0] != "1" else "7"
    wrong = first + s[1:]  # the leading digit miswritten, e.g. 2.73 -> 1.73
    v = one(sc, "v_BA", float(wrong), "m/s")
    assert v.mistake == "transcription_slip"


def test_no_diagnosis_for_an_unexplained_error():
    sc = slider_scene()
    v_b = slider_closed_form(30, 300 * RPM)["v_B"]
    v = one(sc, "v_B", v_b * 1.137, "m/s")
    assert not v.ok and v.mistake is None


# --------------------------------------------------------------------------- the notes


def test_worked_fourbar_notes():
    sc = load_scene(ROOT / "worked_problems" / "fourbar_image_points.toml")
    got = {v.key: v for v in check_answers(solve(sc))}
    wrong = {k for k, v in got.items() if not v.ok}
    assert wrong == {"v_CB"}
    assert got["v_CB"].mistake == "transcription_slip"
    assert "0.34" in got["v_CB"].diagnosis


def test_worked_toggle_notes():
    sc = load_scene(ROOT / "worked_problems" / "toggle_mechanism.toml")
    got = {v.key: v for v in check_answers(solve(sc))}
    wrong = {k for k, v in got.items() if not v.ok}
    assert wrong == {"v_BD", "rub_A", "torque"}
    assert got["v_BD"].mistake == "transcription_slip"  # 36 printed for the 2.36 used next
    assert "v_DB = 2.36" in got["v_BD"].diagnosis
    assert got["rub_A"].mistake == "links_not_at_pin"
    assert got["torque"].mistake == "wrong_omega_in_power_balance"
    assert "omega_CB" in got["torque"].diagnosis


# --------------------------------------------------------------------------- command line


def test_cli_exit_codes_and_json(tmp_path, capsys):
    scene = ROOT / "worked_problems" / "toggle_mechanism.toml"
    assert main(["check", str(scene), "--json"]) == 1
    d = json.loads(capsys.readouterr().out)
    assert d["wrong"] == 3 and not d["all_right"]
    assert {a["key"] for a in d["answers"] if a["verdict"] == "wrong"} == {
        "v_BD",
        "rub_A",
        "torque",
    }
    good = tmp_path / "good.toml"
    good.write_text(
        'student = "A. Student"\n[answers]\nv_D = "2.04 m/s"\nomega_AB = "2.58 rad/s ccw"\n'
    )
    assert main(["check", str(scene), str(good)]) == 0
    out = capsys.readouterr().out
    assert "2 of 2 right" in out


@pytest.mark.parametrize(
    "text, words",
    [
        ('[answers]\nv_Q = "1 m/s"\n', "no point Q"),
        ('[answer]\nv_D = "1 m/s"\n', "answers"),
        ('[answers]\nv_D = "fast"\n', "v_D"),
        ("[answers\n", "TOML"),
        ('[answers]\nomega_AB = "2 m/s"\n', "omega_AB"),
    ],
)
def test_cli_bad_answer_file(tmp_path, capsys, text, words):
    scene = ROOT / "worked_problems" / "toggle_mechanism.toml"
    bad = tmp_path / "bad.toml"
    bad.write_text(text)
    assert main(["check", str(scene), str(bad)]) == 2
    err = capsys.readouterr().err
    assert words in err and "Traceback" not in err and len(err.strip().splitlines()) == 1


def test_cli_nothing_to_check(tmp_path, capsys):
    p = tmp_path / "s.toml"
    p.write_text(FOURBAR)
    assert main(["check", str(p)]) == 2
    assert "nothing to check" in capsys.readouterr().err


def test_parse_answers_rejects_foreign_tables():
    with pytest.raises(SceneError, match="answer file"):
        parse_answers('[links]\nAB = 5\n[answers]\nv_B = "1 m/s"\n', parse_scene(FOURBAR))


def test_parse_scale_round_trip():
    s = parse_scale("2 cm = 1 m/s")
    assert s.per_cm == 0.5 and s.text == "1 cm = 0.5 m/s"
    with pytest.raises(SceneError):
        parse_scale("1 cm = 0.1 rad/s")


def test_zero_answer_for_a_translating_coupler_is_right(tmp_path):
    """A parallelogram's coupler translates: omega_BC = 0 exactly (closed form); the
    solver's ~1e-15 of rounding must not make a student's 0 wrong or print 100 % error."""
    from polygon_method.check import check_answers
    from polygon_method.scene import parse_answers

    scene = parse_scene(TRANSLATING_COUPLER)
    sol = solve(scene)
    _, answers = parse_answers('[answers]\nomega_BC = "0 rad/s"\nalpha_BC = "0 rad/s^2"\n', scene)
    verdicts = check_answers(sol, answers, None)
    assert all(v.ok for v in verdicts), verdicts
    assert all(v.correct == 0 for v in verdicts)


@pytest.mark.parametrize("kind", ["v", "a"])
def test_the_point_under_the_block_given_for_the_block_is_named(kind):
    """The classic slotted-lever slip: a1 (a1') read off for the block A itself. The value
    is computed here independently: v = w perp(KA), a = -w^2 KA + al perp(KA)."""
    import math
    from pathlib import Path

    from polygon_method import load_scene, solve
    from polygon_method.scene import parse_answers

    sc = load_scene(
        Path(__file__).resolve().parent.parent / "worked_problems" / "crank_slotted_lever.toml"
    )
    sol = solve(sc)
    lever = sc.link("O4-P")
    (kx, ky), (x, y) = sol.P["O4"], sol.P["A"]
    rx, ry = x - kx, y - ky
    w, al = sol.W[lever.key], sol.Al[lever.key]
    value = (
        math.hypot(-w * ry, w * rx)
        if kind == "v"
        else math.hypot(-w * w * rx - al * ry, -w * w * ry + al * rx)
    )
    unit = "m/s" if kind == "v" else "m/s^2"
    tol, answers = parse_answers(f'[answers]\n{kind}_A = "{value:.4f} {unit}"\n', sc)
    v = check_answers(sol, answers, tol)[0]
    assert not v.ok and v.mistake == "coincident_for_block", v.diagnosis
    assert "under the block" in v.diagnosis


def test_textbook_drawn_answers_pass_without_a_stated_tolerance():
    """A careful hand drawing is a few per cent off: Khurmi & Gupta's drawn answers and five
    plausible hand answers to the seed four-bar are right under the default tolerance,
    while the known mistakes are still caught (the other tests of this module)."""
    from pathlib import Path
    from polygon_method.scene import parse_answers

    root = Path(__file__).resolve().parent.parent / "worked_problems"
    book = load_scene(root / "fourbar_velocity_khurmi.toml")
    sol = solve(book)
    answers = [a for a in book.answers]
    vs = check_answers(sol, answers, None)  # the book's answers, no stated tolerance
    assert sum(v.ok for v in vs) >= 0.9 * len(vs), [(v.key, v.error) for v in vs]
    seed = load_scene(root / "fourbar_image_points.toml")
    sol = solve(seed)
    _, hand = parse_answers(
        """[answers]
v_C = "0.395 m/s"
omega_BC = "5.1 rad/s"
omega_CD = "7.0 rad/s"
a_C = "5.9 m/s^2"
alpha_CD = "92 rad/s^2"
""",
        seed,
    )
    vs = check_answers(sol, hand, None)
    assert all(v.ok for v in vs), [(v.key, v.error, v.tolerance) for v in vs]
    assert all("hand drawing" in v.rule for v in vs)


def test_a_whole_class_at_once(tmp_path, capsys):
    """A directory of answer files: a row each (an unreadable one is a row with its error),
    the class summary with the questions most often wrong and the mistakes behind them, and
    a gradebook as CSV."""
    import csv
    import io
    from pathlib import Path

    from polygon_method.cli import main

    scene = Path(__file__).resolve().parent.parent / "worked_problems" / "fourbar_image_points.toml"
    sol = solve(load_scene(scene))
    v, w = sol.speed("C"), abs(sol.W["BC"])
    d = tmp_path / "class"
    d.mkdir()
    for i in range(40):
        (d / f"s{i:02d}.toml").write_text(
            f'[answers]\nv_C = "{v:.4f} m/s"\nomega_BC = "{w:.3f} rad/s"\n'
        )
    for i in range(3):  # rpm read as rad/s: omega = N
        (d / f"t{i}.toml").write_text(
            f'[answers]\nv_C = "{v:.4f} m/s"\nomega_BC = "{w * 60 / (2 * math.pi):.3f} rad/s"\n'
        )
    (d / "zz.toml").write_text("answers = [\n")
    book = tmp_path / "book.csv"
    assert main(["check", str(scene), str(d), "--gradebook", str(book)]) == 0
    out = capsys.readouterr().out
    assert "43 of 44 answer files read" in out
    assert "omega_BC: 3 of 43 students" in out
    assert "rpm used as rad/s: 3 students" in out
    assert "could not be read: line 1" in out or "could not be read:" in out
    table = list(csv.DictReader(io.StringIO(book.read_text())))
    assert len(table) == 44
    by = {r["student"]: r for r in table}
    assert by["s00"]["v_C"] == "right" and by["t0"]["omega_BC"].startswith("WRONG")
    assert by["zz"]["error"] and by["zz"]["right"] == ""
