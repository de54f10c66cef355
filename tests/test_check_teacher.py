"""A checker a teacher can trust: the tolerance each file is checked with (and why), the
student's name, answer keys for the point under a block, another quantity of the problem
named, a decimal comma, a did-you-mean for a key, diagnoses in the scene's units.

Expected values come from closed forms written here (the four-bar's angular velocities,
the crank and slotted lever's lever angle and its finite differences), never from the
tool's own output.
"""

import csv
import io
import json
import math
from pathlib import Path

import pytest

from polygon_method import load_scene, parse_scene, solve
from polygon_method.check import check_answers
from polygon_method.cli import main
from polygon_method.scene import parse_answers
from test_check import FOURBAR, fourbar_closed_form

ROOT = Path(__file__).resolve().parent.parent
LEVER = ROOT / "worked_problems" / "crank_slotted_lever.toml"
INCHES = ROOT / "tests" / "textbook" / "fourbar_inches.toml"

W3, W4 = fourbar_closed_form()  # omega_BC, omega_CD of FOURBAR (AB 50, BC 66, CD 56 mm)
V_C, V_CB = abs(W4) * 0.056, abs(W3) * 0.066


def fourbar_file(tmp_path, extra=""):
    """FOURBAR as a scene file whose book tolerance is 1 %."""
    path = tmp_path / "fourbar.toml"
    path.write_text(FOURBAR + f'[answers]\ntolerance = "1%"\nv_C = "{V_C:.4f} m/s"\n' + extra)
    return path


def run(capsys, *argv):
    code = main(list(map(str, argv)))
    out = capsys.readouterr()
    return code, out.out, out.err


# --------------------------------------------------------------------------- tolerance


def test_command_line_tolerance_is_the_boundary(tmp_path, capsys):
    """--tolerance 5% passes an answer 4 % off and --tolerance 3% fails it; the check says
    the tolerance came from the command line."""
    scene = fourbar_file(tmp_path)
    ans = tmp_path / "ann.toml"
    ans.write_text(f'[answers]\nv_C = "{V_C * 1.04:.5f} m/s"\n')
    code, out, _ = run(capsys, "check", scene, ans, "--tolerance", "5%")
    assert code == 0 and "tolerance used: 5 %, from --tolerance on the command line" in out
    code, out, _ = run(capsys, "check", scene, ans, "--tolerance", "3 %")
    assert code == 1 and "WRONG" in out


def test_an_absolute_tolerance_applies_to_its_unit(tmp_path, capsys):
    """--tolerance 0.01 m/s: v_C 0.008 m/s off is right, 0.012 off is wrong; omega (another
    unit) takes the per cent given beside it."""
    scene = fourbar_file(tmp_path)
    ans = tmp_path / "a.toml"
    ans.write_text(
        f'[answers]\nv_C = "{V_C + 0.008:.5f} m/s"\nomega_BC = "{abs(W3) * 1.04:.4f} rad/s"\n'
    )
    code, out, _ = run(
        capsys, "check", scene, ans, "--tolerance", "0.01 m/s", "--tolerance", "5%", "--json"
    )
    got = {a["key"]: a for a in json.loads(out)["answers"]}
    assert got["v_C"]["verdict"] == "right" and "0.01 m/s" in got["v_C"]["rule"]
    assert got["omega_BC"]["verdict"] == "right" and "5 %" in got["omega_BC"]["rule"]
    ans.write_text(f'[answers]\nv_C = "{V_C + 0.012:.5f} m/s"\n')
    code, out, _ = run(capsys, "check", scene, ans, "--tolerance", "0.01 m/s")
    assert code == 1


@pytest.mark.parametrize("bad", ["5", "0.01 kg", "0 %", "150%", "-0.1 m/s"])
def test_a_bad_command_line_tolerance_is_one_line(tmp_path, capsys, bad):
    scene = fourbar_file(tmp_path)
    code, out, err = run(capsys, "check", scene, "--tolerance", bad)
    assert code == 2 and "--tolerance" in err and len(err.strip().splitlines()) == 1
    assert "Traceback" not in err


def test_the_books_tolerance_is_not_a_students(tmp_path, capsys):
    """The scene's [answers] tolerance (1 %) grades the scene's own answers; a student's
    file without one is checked by the default (a hand drawing, a few per cent), and the
    check says so; the file's own tolerance is used where it states one."""
    scene = fourbar_file(tmp_path)
    ans = tmp_path / "bob.toml"
    ans.write_text(f'[answers]\nv_C = "{V_C * 1.02:.5f} m/s"\n')  # 2 % off
    code, out, _ = run(capsys, "check", scene, ans, "--json")
    data = json.loads(out)
    assert code == 0 and data["tolerance_used"]["source"] == "default"
    assert "hand drawing" in data["answers"][0]["rule"]
    assert "not the scene's 1 %" in data["tolerance_used"]["why"]
    code, out, _ = run(capsys, "check", scene, "--json")  # the scene's own answers
    assert json.loads(out)["tolerance_used"]["source"] == "scene"
    ans.write_text(f'[answers]\ntolerance = "1.5%"\nv_C = "{V_C * 1.02:.5f} m/s"\n')
    code, out, _ = run(capsys, "check", scene, ans)
    assert code == 1 and "1.5 %, the answer file's own tolerance" in out


def test_the_gradebook_reads_the_students_name_and_tolerance(tmp_path, capsys):
    scene = fourbar_file(tmp_path)
    d = tmp_path / "class"
    d.mkdir()
    (d / "s01.toml").write_text(f'student = "Ada  Lovelace"\n[answers]\nv_C = "{V_C:.4f} m/s"\n')
    (d / "s02.toml").write_text(f'[answers]\ntolerance = "2%"\nv_C = "{V_C:.4f} m/s"\n')
    (d / "s03.toml").write_text('name = 7\n[answers]\nv_C = "1 m/s"\n')
    book = tmp_path / "book.csv"
    code, out, _ = run(capsys, "check", scene, d, "--gradebook", book)
    assert code == 0
    rows = {r["file"]: r for r in csv.DictReader(io.StringIO(book.read_text()))}
    assert rows[str(d / "s01.toml")]["student"] == "Ada Lovelace"
    assert rows[str(d / "s02.toml")]["student"] == "s02"  # no name: the file's
    assert rows[str(d / "s01.toml")]["tolerance"] == "default"
    assert rows[str(d / "s02.toml")]["tolerance"].startswith("2 %")
    assert "name is the student's name" in rows[str(d / "s03.toml")]["error"]
    assert "Ada Lovelace" in out and "not the scene's 1 %" in out


# --------------------------------------------------------------------------- the point under a block


def lever_closed_form(theta):
    """Crank and slotted lever: crank O2A = r at theta from O2 = (0, h) above the lever's
    pivot O4 = (0, 0), turning at w. Returns phi (the lever's angle), |O4A| and the point
    of the lever at distance d0 from O4 as a function of theta."""
    r, h = 0.12, 0.3
    ax, ay = r * math.cos(theta), h + r * math.sin(theta)
    return math.atan2(ay, ax), math.hypot(ax, ay)


def test_the_point_under_the_block_has_answer_keys():
    """v_A1 and a_A1 (the lever's point under the block A, a1 and a1' on the polygons) are
    checked against the closed form: |v_A1| = r w |cos(theta - phi)|, and a_A1 from
    finite differences of the lever's point at the block's distance, in time."""
    sc = load_scene(LEVER)
    th, w = sc.input.angle, sc.input.omega
    phi, d0 = lever_closed_form(th)
    v_a1 = 0.12 * abs(w) * abs(math.cos(th - phi))
    dt = 1e-4 / abs(w)

    def point(t):
        p, _ = lever_closed_form(th + w * t)
        return d0 * math.cos(p), d0 * math.sin(p)

    (x0, y0), (x1, y1), (x2, y2) = point(-dt), point(0.0), point(dt)
    a_a1 = math.hypot(x2 - 2 * x1 + x0, y2 - 2 * y1 + y0) / dt**2
    fd_v = math.hypot(x2 - x0, y2 - y0) / (2 * dt)
    assert fd_v == pytest.approx(v_a1, rel=1e-6)  # the closed form and the differences agree
    sol = solve(sc)
    _, answers = parse_answers(
        f'[answers]\nv_A1 = "{v_a1:.6g} m/s"\na_A1 = "{a_a1:.6g} m/s^2"\n', sc
    )
    vs = check_answers(sol, answers, None)
    assert all(v.ok for v in vs), vs
    assert vs[0].correct == pytest.approx(v_a1, rel=1e-9)
    assert vs[1].correct == pytest.approx(a_a1, rel=1e-6)
    # the block's own velocity given for the lever's point under it: named
    v_a = 0.12 * abs(w)
    _, answers = parse_answers(f'[answers]\nv_A1 = "{v_a:.4g} m/s"\n', sc)
    v = check_answers(sol, answers, None)[0]
    assert not v.ok and v.mistake == "block_for_coincident" and "(a1)" in v.diagnosis


def test_the_coriolis_component_has_a_key_per_slider():
    """ac_A = 2 omega_lever vs_A, from the closed form (omega_lever = phi', vs = r w
    sin(theta - phi)); every slider of the worked problems has its key."""
    sc = load_scene(LEVER)
    th, w = sc.input.angle, sc.input.omega
    phi, d = lever_closed_form(th)
    w_lever = 0.12 * w * math.cos(th - phi) / d
    vs = 0.12 * w * math.sin(th - phi)
    _, answers = parse_answers(f'[answers]\nac_A = "{2 * abs(w_lever * vs):.6g} m/s^2"\n', sc)
    v = check_answers(solve(sc), answers, None)[0]
    assert v.ok and v.correct == pytest.approx(2 * abs(w_lever * vs), rel=1e-9)


# --------------------------------------------------------------------------- other quantities


def test_another_quantity_of_the_problem_is_named():
    """omega_BC given for omega_CD, v_CB for v_C: named, with the key given."""
    sc = parse_scene(FOURBAR)
    sol = solve(sc)
    _, answers = parse_answers(
        f'[answers]\nomega_CD = "{abs(W3):.4f} rad/s"\nv_C = "{V_CB:.4f} m/s"\n', sc
    )
    om, vc = check_answers(sol, answers, None)
    assert not om.ok and om.mistake == "another_quantity"
    assert "you gave omega_BC" in om.diagnosis and "for omega_CD" in om.diagnosis
    assert not vc.ok and "you gave v_CB" in vc.diagnosis and "for the absolute v_C" in vc.diagnosis
    # with a sense: omega_BC's size, with CD's sense
    sense = "cw" if W4 < 0 else "ccw"
    _, answers = parse_answers(f'[answers]\nomega_CD = "{abs(W3):.4f} rad/s {sense}"\n', sc)
    om = check_answers(sol, answers, None)[0]
    assert not om.ok and "you gave omega_BC" in om.diagnosis


def test_the_right_answer_is_never_called_another_quantity():
    """A quantity equal to another (omega of the coupler of a parallelogram equals zero
    and so on) is right when it is right: the asked one is matched first."""
    sc = parse_scene(FOURBAR)
    _, answers = parse_answers(f'[answers]\nomega_CD = "{abs(W4):.4f} rad/s"\n', sc)
    assert check_answers(solve(sc), answers, None)[0].ok


# --------------------------------------------------------------------------- reading


def test_a_decimal_comma_is_read():
    sc = parse_scene(FOURBAR)
    _, answers = parse_answers('[answers]\nv_C = "0,39 m/s"\nomega_BC = "5,2 rad/s ccw"\n', sc)
    assert answers[0].value == pytest.approx(0.39) and answers[0].raw == "0,39 m/s"
    assert answers[1].value == pytest.approx(5.2)


def test_an_ambiguous_comma_is_one_line(tmp_path, capsys):
    scene = fourbar_file(tmp_path)
    ans = tmp_path / "a.toml"
    ans.write_text('[answers]\nv_C = "1,250 m/s"\n')
    code, _, err = run(capsys, "check", scene, ans)
    assert code == 2 and "reads two ways" in err and "v_C" in err
    assert len(err.strip().splitlines()) == 1


@pytest.mark.parametrize(
    "key, meant",
    [
        ("v_c", "v_C"),
        ("omega_bc", "omega_BC"),
        ("w_BC", "omega_BC"),
        ("V_CB", "v_CB"),
        ("omega_BX", "omega_BC"),
    ],
)
def test_an_unknown_key_says_what_was_meant(tmp_path, capsys, key, meant):
    scene = fourbar_file(tmp_path)
    ans = tmp_path / "a.toml"
    unit = "rad/s" if meant.startswith("omega") else "m/s"
    ans.write_text(f'[answers]\n{key} = "0.39 {unit}"\n')
    code, _, err = run(capsys, "check", scene, ans)
    assert code == 2 and f"did you mean '{meant}'?" in err, err
    assert len(err.strip().splitlines()) == 1


# --------------------------------------------------------------------------- units


def test_a_diagnosis_keeps_the_scenes_units():
    """A scene in inches: the diameter for the radius is said in inches (0.75 in), and a
    velocity in in/s written as m/s is named."""
    sc = load_scene(INCHES)
    sol = solve(sc)
    # pin A joins the crank O2-A and the coupler A-B: |w2 - w3| r, r = 0.375 in; the
    # closed form in inches (omega does not depend on the unit): crank 2 at 180 deg,
    # coupler 6.5, rocker 4, ground 7, 10 rps cw, B above
    w2 = -20 * math.pi
    w3, _ = fourbar_closed_form(180.0, w2, 2.0, 6.5, 4.0, 7.0)
    rub = abs(w2 - w3) * 0.375 * 0.0254
    _, answers = parse_answers(f'[answers]\nrub_A = "{2 * rub:.4g} m/s"\n', sc)
    v = check_answers(sol, answers, None)[0]
    assert v.mistake == "diameter_as_radius" and "0.75 in" in v.diagnosis
    assert "mm" not in v.diagnosis


def test_a_slip_of_the_pen_is_found_in_a_number_with_a_decimal_comma():
    """v_C with its first digit miswritten, in a decimal comma: still a slip of the pen
    (the digits compared with the closed form's)."""
    sc = parse_scene(FOURBAR)
    right = f"{V_C:.4f}"
    wrong = ("1" if right[2] != "1" else "2") if right.startswith("0.") else None
    assert wrong is not None
    written = f"0,{wrong}{right[3:]}"
    _, answers = parse_answers(f'[answers]\nv_C = "{written} m/s"\n', sc)
    v = check_answers(solve(sc), answers, None)[0]
    assert not v.ok and v.mistake == "transcription_slip", (written, v.diagnosis)
