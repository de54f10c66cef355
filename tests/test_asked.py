"""A question asked without its answer (``[answers] v_C = "?"``, ``"? rpm"``) in every view:
read (the key checked as an answer's), answered by ``solve`` (text and ``--json``) and
``steps`` in the book's form, listed and not graded by ``check`` (exit code, ``--json``, a
class's table), asked of every student by ``variants`` and its key given, and the flywheel
chapter's. The values are held to independent references: the slider crank's and the
four-bar's closed forms at 50 digits (tests/reference.py), the 50-digit general solve for a
textbook problem, a punching press's energy by hand, a centre as the meeting of two lines.
"""

from __future__ import annotations

import csv
import json
import math
from pathlib import Path

import pytest

from polygon_method import parse_scene, solve
from polygon_method.check import asked_verdicts, check_answers
from polygon_method.cli import main
from polygon_method.common.numbers import textbook
from polygon_method.scene import asked_questions, load_scene
from reference import reference_fourbar_algebraic, reference_slider_crank, reference_solution

REL = 1e-9
HERE = Path(__file__).parent

FOURBAR = """
title = "Four-bar chain ABCD (Khurmi & Gupta's numbers)"
units = "mm"
[ground]
A = [0, 0]
D = [150, 0]
[links]
AB = 40
BC = 150
CD = 80
[assembly]
C = "above"
[input]
crank = "AB"
angle = 60
speed = "120 rpm cw"
[answers]
v_B = "0.503 m/s"
"""
QUESTIONS = """v_C = "?"
omega_CD = "? rpm"
omega_BC = "?"
alpha_CD = "? rad/s^2"
a_C = "?"
I_13 = "?"
"""

SLIDER = """
title = "Slider crank with a resisting force on the piston"
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 100
AB = 400
[sliders]
B = { path = "horizontal", through = [0, 0] }
[assembly]
B = "right"
[input]
crank = "OA"
angle = 60
speed = "300 rpm cw"
[pins]
A = { radius = 10 }
[loads]
B = { force = [-1000, 0] }
[masses]
[answers]
v_B = "?"
a_B = "? m/s^2"
omega_AB = "? rpm"
alpha_AB = "?"
rub_A = "? mm/s"
torque = "?"
F_B = "?"
N_B = "? kN"
"""


def _write(tmp_path, text, name="scene.toml"):
    p = tmp_path / name
    p.write_text(text)
    return p


def _solve_json(path, capsys, *extra):
    capsys.readouterr()
    assert main(["solve", str(path), "--json", *extra]) == 0
    return {a["key"]: a for a in json.loads(capsys.readouterr().out)["answers_asked"]}


def _close(x, ref, rel=REL):
    assert abs(x - float(ref)) <= rel * max(abs(float(ref)), 1e-300), (x, float(ref))


# ------------------------------------------------------------------------------ reading


def test_a_question_is_read_with_its_key_checked_and_its_unit():
    sc = parse_scene(FOURBAR + QUESTIONS)
    by = {a.key: a for a in sc.answers}
    assert not by["v_B"].asked and by["v_B"].value == 0.503
    assert by["v_C"].asked and by["v_C"].value is None and by["v_C"].raw == "?"
    assert (by["omega_CD"].kind, by["omega_CD"].names, by["omega_CD"].unit) == (
        "omega",
        ("C", "D"),
        "rpm",
    )
    assert by["I_13"].asked and by["I_13"].kind == "centre" and by["I_13"].names == (1, 3)
    # solve and steps read the questions alone, from the text: the same records
    assert asked_questions(parse_scene(FOURBAR + QUESTIONS, answers=False)) == tuple(
        a for a in sc.answers if a.asked
    )


@pytest.mark.parametrize(
    "line, words",
    [
        ('v_X = "?"', "[answers] v_X (line 19): no point X in the scene"),
        ('omega_BX = "?"', "[answers] omega_BX (line 19): no link BX in [links]"),
        ('omega_BC = "? m/s"', "'m/s' is a unit of velocity, not of angular velocity"),
        ('omega_BC = "? rad/s cw"', 'a question asks for the sense too: write "? rad/s"'),
        ('v_C = "??"', "unknown unit '?'"),
        ('F_B = "?"', "a force answer needs the force analysis"),
        ('v_C = "? cw"', 'velocity has no sense cw or ccw: write "? m/s"'),
        ('tolerance = "?"', "tolerance is the answers' allowance"),
        ('vmin_BD = "?"', "B and D are not two points of one link"),
        ('I_19 = "?"', "no centre I19"),
    ],
)
def test_a_bad_question_is_one_line_at_check_and_at_solve(tmp_path, capsys, line, words):
    path = _write(tmp_path, FOURBAR + line + "\n")
    # (the tolerance is check's alone: solve and steps leave it unread, as every value)
    for command in ("check",) if line.startswith("tolerance") else ("check", "solve", "steps"):
        capsys.readouterr()
        assert main([command, str(path)]) == 2
        err = capsys.readouterr().err
        assert words in err and err.count("\n") == 1 and "Traceback" not in err


def test_solve_reads_only_the_questions_and_a_scene_without_one_pays_nothing(
    tmp_path, capsys, monkeypatch
):
    # a fault in an answer given is check's (solve leaves it unread), not solve's
    path = _write(tmp_path, FOURBAR + 'v_C = "fast"\nomega_CD = "?"\n')
    got = _solve_json(path, capsys)
    assert list(got) == ["omega_CD"]
    assert main(["check", str(path)]) == 2
    # no "?" in the text: its [answers] is not parsed again (the seed's speed)
    from polygon_method.scene import answer_files

    def boom(*a, **k):
        raise AssertionError("parsed")

    monkeypatch.setattr(answer_files, "toml_table", boom)
    for f in ("fourbar_velocity_khurmi.toml", "offset_slider_crank.toml"):
        assert asked_questions(load_scene(HERE.parent / "worked_problems" / f, answers=False)) == ()


# ------------------------------------------------------------------------------ values


def test_the_four_bars_questions_against_the_closed_form(tmp_path, capsys):
    path = _write(tmp_path, FOURBAR + QUESTIONS)
    got = _solve_json(path, capsys)
    w = -2 * math.pi * 120 / 60
    refs = [
        reference_fourbar_algebraic(0.04, 0.15, 0.08, 0.15, math.radians(60), w, 0, b)
        for b in (1, -1)
    ]
    ref = max(refs, key=lambda r: r["B"][1])  # C above
    vc = math.hypot(*ref["vB"])
    ac = math.hypot(*ref["aB"])
    _close(got["v_C"]["value"], vc)
    _close(got["omega_CD"]["value"], ref["omega4"])
    _close(got["omega_BC"]["value"], ref["omega3"])
    _close(got["alpha_CD"]["value"], ref["alpha4"])
    _close(got["a_C"]["value"], ac)
    w4 = float(ref["omega4"])
    assert got["omega_CD"]["text"] == f"{textbook(abs(w4) * 30 / math.pi)} rpm cw"
    assert got["v_C"]["text"] == f"{textbook(vc)} m/s"
    # I_13: where the crank's line AB (through A at the origin) meets the rocker's line DC
    b = (0.04 * math.cos(math.radians(60)), 0.04 * math.sin(math.radians(60)))
    c = tuple(float(x) for x in ref["B"])
    d = (0.15, 0.0)
    u = (c[0] - d[0], c[1] - d[1])
    t = (d[0] * u[1] - d[1] * u[0]) / (b[0] * u[1] - b[1] * u[0])  # t b = d + s u
    i13 = (t * b[0], t * b[1])
    for x, r in zip(got["I_13"]["correct_position"], i13):
        _close(x, r)
    assert got["I_13"]["text"] == f"[{i13[0] * 1000:.2f}, {i13[1] * 1000:.2f}] mm"
    # the text ends with them, in the book's form and order
    capsys.readouterr()
    assert main(["solve", str(path)]) == 0
    last = capsys.readouterr().out.rstrip().splitlines()[-1]
    assert last.startswith(f"Answers asked: v_C = {textbook(vc)} m/s; omega_CD = ")
    assert [p.split(" = ")[0] for p in last[len("Answers asked: ") :].split("; ")] == [
        "v_C",
        "omega_CD",
        "omega_BC",
        "alpha_CD",
        "a_C",
        "I_13",
    ]


def test_the_slider_cranks_questions_of_every_kind_against_the_closed_form(tmp_path, capsys):
    path = _write(tmp_path, SLIDER)
    got = _solve_json(path, capsys)
    w = -2 * math.pi * 300 / 60
    th = math.radians(60)
    ref = reference_slider_crank(0.1, 0.4, 0.0, th, w, 0.0)
    v, w_rod = float(ref["v"]), float(ref["omega_rod"])
    _close(got["v_B"]["value"], abs(v))
    _close(got["a_B"]["value"], abs(ref["a"]))
    _close(got["omega_AB"]["value"], w_rod)
    _close(got["alpha_AB"]["value"], ref["alpha_rod"])
    _close(got["rub_A"]["value"], abs(w - w_rod) * 0.010)
    # the torque by the power balance T w + F v = 0 (no inertia: [masses] empty)
    torque = -(-1000.0 * v) / w
    _close(got["torque"]["value"], torque)
    # a static slider crank: the rod carries F / cos phi, the guide F tan phi
    phi = math.asin(0.1 * math.sin(th) / 0.4)
    _close(got["F_B"]["value"], 1000 / math.cos(phi))
    _close(got["N_B"]["value"], 1000 * math.tan(phi))
    assert got["rub_A"]["text"] == f"{textbook(abs(w - w_rod) * 10)} mm/s"
    assert got["N_B"]["text"] == f"{textbook(math.tan(phi))} kN"
    sense = "ccw" if torque > 0 else "cw"
    assert got["torque"]["text"] == f"{textbook(abs(torque))} N m {sense}"
    assert got["omega_AB"]["text"].endswith(" rpm " + ("ccw" if w_rod > 0 else "cw"))
    # one definition: check's correct value is the same number
    verdicts = {v.key: v for v in check_answers(solve(load_scene(path)))}
    assert all(verdicts[k].asked and verdicts[k].correct == got[k]["value"] for k in got)


def test_an_answer_file_with_questions_is_answered_by_solve_and_steps(tmp_path, capsys):
    scene = _write(tmp_path, FOURBAR)
    answers = _write(tmp_path, '[answers]\nv_C = "?"\nomega_BC = "? rad/s"\n', "book.toml")
    got = _solve_json(scene, capsys, "--answers", str(answers))
    assert list(got) == ["v_C", "omega_BC"] and got["v_C"]["line"] == 2
    capsys.readouterr()
    assert main(["steps", str(scene), "--answers", str(answers)]) == 0
    out = capsys.readouterr().out.rstrip().splitlines()
    k = out.index("6. Answers")
    assert out[k + 1] == "=" * len("6. Answers") and out[k + 3].startswith("  - v_C = ")
    assert out[k + 4].startswith("  - omega_BC = ") and out[k + 4].endswith(" rad/s ccw")
    capsys.readouterr()
    assert main(["steps", str(scene), "--answers", str(answers), "--format", "markdown"]) == 0
    assert "## 6. Answers\n\n- v_C = " in capsys.readouterr().out


# ------------------------------------------------------------------------------ check


def test_check_lists_a_question_and_does_not_grade_it(tmp_path, capsys):
    path = _write(tmp_path, FOURBAR + QUESTIONS)
    capsys.readouterr()
    assert main(["check", str(path)]) == 0  # v_B right, the rest asked
    out = capsys.readouterr().out
    sol = solve(load_scene(path))
    vc = sol.speed("C")
    assert f"asked, no answer given: the tool's value is {textbook(vc)} m/s" in out
    assert "1 of 1 right; 6 asked, no answer given (not graded)" in out
    wrong = _write(tmp_path, FOURBAR.replace("0.503", "0.603") + QUESTIONS, "wrong.toml")
    capsys.readouterr()
    assert main(["check", str(wrong)]) == 1
    assert "0 of 1 right, 1 wrong; 6 asked" in capsys.readouterr().out
    assert main(["check", str(path), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert (d["all_right"], d["right"], d["wrong"], d["asked"]) == (True, 1, 0, 6)
    row = next(a for a in d["answers"] if a["key"] == "v_C")
    assert row["verdict"] == "asked" and row["asked"] and row["given"] is None
    _close(row["correct"], vc, 1e-15)


def test_check_of_questions_alone_names_no_tolerance(tmp_path, capsys):
    """Nothing graded, no tolerance used: the line "tolerance used: ..." is for graded
    answers only (it was printed above a table of questions alone)."""
    path = _write(tmp_path, FOURBAR.replace('v_B = "0.503 m/s"\n', "") + QUESTIONS)
    capsys.readouterr()
    assert main(["check", str(path)]) == 0
    out = capsys.readouterr().out
    assert "tolerance used" not in out
    assert "0 of 0 right; 6 asked, no answer given (not graded)" in out


def test_a_class_counts_a_question_as_not_answered(tmp_path, capsys):
    scene = _write(tmp_path, FOURBAR)
    sol = solve(load_scene(scene))
    vc, w3 = sol.speed("C"), sol.omega("B-C")
    given = f'v_C = "{vc:.4f} m/s"\n'
    omega = f'omega_BC = "{abs(w3) * 1.3:.4f} rad/s"\n'  # wrong
    answers = tmp_path / "answers"
    answers.mkdir()
    (answers / "ann.toml").write_text('student = "ann"\n[answers]\n' + given + omega)
    (answers / "bob.toml").write_text('student = "bob"\n[answers]\nv_C = "?"\n' + omega)
    (answers / "cy.toml").write_text('student = "cy"\n[answers]\n' + omega)  # v_C left out
    book = tmp_path / "book.csv"
    capsys.readouterr()
    assert main(["check", str(scene), str(answers), "--gradebook", str(book)]) == 0
    out = capsys.readouterr().out
    rows = {r["student"]: r for r in csv.DictReader(book.open())}
    assert (rows["ann"]["v_C"], rows["ann"]["right"], rows["ann"]["of"]) == ("right", "1", "2")
    # bob's "?" counts as cy's key left out: an empty cell, not in "of"
    for who in ("bob", "cy"):
        assert (rows[who]["v_C"], rows[who]["right"], rows[who]["of"]) == ("", "0", "1")
    assert "1 of 4 answers right" in out and "omega_BC: 3 of 3 students" in out
    capsys.readouterr()
    assert main(["check", str(scene), str(answers), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    bob = next(s for s in d["students"] if s["student"] == "bob")
    assert bob["right"] == 0 and [a["verdict"] for a in bob["answers"]] == ["asked", "wrong"]


def test_the_page_marks_a_question_asked():
    from polygon_method.page.html import check_html

    sol = solve(parse_scene(FOURBAR + QUESTIONS))
    html = check_html(check_answers(sol), "answers from the scene")
    assert html.count('<span class="asked">asked</span>') == 6
    assert f"the tool&#x27;s value is {textbook(sol.speed('C'))} m/s" in html
    assert "1 of 1 right; 6 asked, no answer given (not graded)." in html


# ------------------------------------------------------------------------------ variants


def test_variants_ask_the_question_and_their_key_answers_it_in_the_unit_asked(tmp_path):
    from test_variants import FOURBAR as BASE, _dims, _fourbar_by_hand

    from polygon_method.variants import generate
    from polygon_method.variants.papers import answer_key_markdown, sheet_markdown

    text = BASE.replace('omega_BC = "3 rad/s"', 'omega_BC = "? rpm"').replace(
        'v_C = "0.3 m/s"', 'v_C = "?"'
    )
    vs = generate(parse_scene(text, file="base.toml"), 5, 7)
    assert [q[0] for q in vs.questions] == ["v_C", "omega_BC", "alpha_CD"]
    sheet = sheet_markdown(vs)
    assert sheet.count("the angular velocity of link BC (`omega_BC`, in rpm)") == 5
    assert sheet.count("the velocity of C (`v_C`)") == 5
    rows = [r for r in answer_key_markdown(vs).splitlines() if r.startswith("| 0")]
    for v, row in zip(vs.variants, rows):
        assert "[answers]" not in v.text  # the variant's file: no answers, no questions
        *_, w3, _, vc = _fourbar_by_hand(*_dims(v.text)[:6])
        cells = [c.strip() for c in row.strip("|").split("|")]
        vc_cell, w_cell = cells[-3], cells[-2]
        assert vc_cell == f"{textbook(vc)} m/s"
        assert w_cell == f"{textbook(abs(w3) * 30 / math.pi)} rpm {'ccw' if w3 > 0 else 'cw'}"


# ------------------------------------------------------------------------------ flywheel


def test_the_flywheel_chapters_questions_against_the_hand_working(tmp_path, capsys):
    text = (HERE.parent / "worked_problems" / "flywheel" / "punching_press.toml").read_text()
    text = text.replace('power = "1018 W"', 'power = "? kW"').replace(
        'dE_max = "5089 J"', 'dE_max = "?"'
    )
    path = _write(tmp_path, text)
    # a hole's energy: half the greatest shearing force over the plate's thickness
    e_hole = 0.5 * (math.pi * 0.025 * 0.018 * 400e6) * 0.018
    capsys.readouterr()
    assert main(["solve", str(path), "--json"]) == 0
    got = {a["key"]: a for a in json.loads(capsys.readouterr().out)["answers_asked"]}
    _close(got["power"]["value"], e_hole * 12 / 60)
    _close(got["dE_max"]["value"], e_hole * (1 - 1 / 8))
    assert got["power"]["text"] == f"{textbook(e_hole * 12 / 60 / 1000)} kW"
    capsys.readouterr()
    assert main(["check", str(path)]) == 0  # the student's slip is gone with dE_max asked
    out = capsys.readouterr().out
    assert f"the tool's value is {textbook(e_hole * 7 / 8)} J" in out
    assert "3 of 3 right; 2 asked, no answer given (not graded)" in out
    capsys.readouterr()
    assert main(["steps", str(path)]) == 0
    assert f"  - dE_max = {textbook(e_hole * 7 / 8)} J" in capsys.readouterr().out
    bad = _write(tmp_path, text.replace('"? kW"', '"? rpm"'), "bad.toml")
    assert main(["check", str(bad)]) == 2
    assert "power" in capsys.readouterr().err


# ------------------------------------------------------------------------------ a book's problem


def test_a_books_problem_in_words_ends_with_its_answers(capsys):
    """Khurmi & Gupta's Whitworth problem: "Determine the velocity of the slider S ...
    Find also the angular velocity of the link RS and the velocity of the sliding block T
    on the slotted lever QT." The book's answer is given for v_S; the other two are asked
    with "?", and solve answers them as the book's answers read, held to the 50-digit
    general solve."""
    path = HERE / "textbook" / "khurmi_whitworth_with_the_vertical.toml"
    scene = load_scene(path)
    sol = solve(scene)
    ref = reference_solution(scene, sol.P)
    w = float(ref["omega"][scene.link("RS").key])
    vs = float(ref["sliders"]["P"]["vs"])
    (x, y) = asked_verdicts(sol, [q for q in scene.answers if q.asked])
    _close(x.correct, w)
    _close(y.correct, vs)
    sl = scene.slider("P")  # the reference's vs is along first -> second
    a, b = (sl.first, sl.second) if vs > 0 else (sl.second, sl.first)
    capsys.readouterr()
    assert main(["solve", str(path)]) == 0
    out = capsys.readouterr().out
    assert out.rstrip().splitlines()[-1] == (
        f"Answers asked: omega_RS = {textbook(abs(w))} rad/s {'ccw' if w > 0 else 'cw'}; "
        f"vs_P = {textbook(abs(vs))} m/s along QR, from {a} towards {b}"
    )
    assert check_answers(sol)[0].ok  # the book's v_S still graded


def test_the_engine_chapters_questions_against_the_closed_form(tmp_path, capsys):
    text = (HERE.parent / "worked_problems" / "engine_forces.toml").read_text()
    text = text[: text.index("[answers]")] + (
        '[answers]\npiston_effort = "? kN"\nrod_thrust = "?"\ncrank_effort = "?"\n'
        'turning_moment = "? kN m"\n'
    )
    got = _solve_json(_write(tmp_path, text), capsys)
    w, th, r, l = 2 * math.pi * 250 / 60, math.radians(60), 0.3, 1.2
    a = float(reference_slider_crank(r, l, 0.0, th, w, 0.0)["a"])
    gas = 0.35e6 * math.pi * 0.5**2 / 4  # towards the crank: -x
    fp = abs(-gas - 250 * a)  # the gas force less the reciprocating parts' inertia
    phi = math.asin(r * math.sin(th) / l)
    _close(got["piston_effort"]["value"], fp)
    _close(got["rod_thrust"]["value"], fp / math.cos(phi))
    _close(got["crank_effort"]["value"], fp * math.sin(th + phi) / math.cos(phi))
    _close(got["turning_moment"]["value"], fp * math.sin(th + phi) / math.cos(phi) * r)
    assert got["piston_effort"]["text"] == f"{textbook(fp / 1000)} kN"


def test_a_diagrams_variants_ask_its_questions_and_key_them_by_the_closed_form(tmp_path, capsys):
    """dE_max of T = 1000 + 300 sin 2t - 500 cos 2t is A = sqrt(300^2 + 500^2) (the energy
    swings by A about its mean); I = A / (w^2 Cs), each variant's own speed and Cs."""
    import tomllib

    import test_energy_class as energy

    text = energy.LAW.replace('dE_max = "583.1 J"', 'dE_max = "?"').replace(
        'I_flywheel = "29.5 kg m^2"', 'I_flywheel = "? kg m^2"'
    )
    base, out = _write(tmp_path, text), tmp_path / "cls"
    capsys.readouterr()
    assert main(["variants", str(base), "--count", "3", "--seed", "1", "-o", str(out)]) == 0
    rows = list(csv.DictReader((out / "answer-key.csv").open(encoding="utf-8")))
    for row in rows:
        raw = tomllib.loads((out / row["file"]).read_text(encoding="utf-8"))
        assert "answers" not in raw
        w = float(raw["flywheel"]["speed"].split()[0]) * math.pi / 30
        cs = 2 * float(raw["flywheel"]["plus_minus"].rstrip("%")) / 100
        a = math.hypot(300, 500)
        _close(float(row["dE_max (J)"]), a)
        _close(float(row["I_flywheel (kg m^2)"]), a / (w * w * cs))
    sheet = (out / "problem-sheet.md").read_text(encoding="utf-8")
    assert sheet.count("(dE_max), the flywheel's moment of inertia (I_flywheel)") == 3


def test_a_fraction_asked_in_per_cent_and_a_mean_against_the_hand_working(tmp_path, capsys):
    """T = 1000 + 300 sin 2t: the mean 1000 N m, the energy swings by 300 J (150 either
    side), so a flywheel of 40 kg m^2 at 300 rpm holds Cs = 300 / (I w^2)."""
    text = (
        'title = "x"\n[turning_moment]\ntorque = "1000 + 300 sin 2theta"\n[flywheel]\n'
        'speed = "300 rpm"\ninertia = "40 kg m^2"\n[answers]\nCs = "? %"\nT_mean = "?"\n'
    )
    got = _solve_json(_write(tmp_path, text), capsys)
    cs = 300 / (40 * (300 * math.pi / 30) ** 2)
    _close(got["Cs"]["value"], cs)
    _close(got["T_mean"]["value"], 1000.0)
    assert got["Cs"]["text"] == f"{textbook(100 * cs)} %"
    assert got["T_mean"]["text"] == "1000 N m"


def test_a_diagrams_class_counts_a_question_as_not_answered(tmp_path, capsys):
    """T = 1000 + 300 sin 2t: T_mean 1000 N m, dE_max 300 J (by hand); bob leaves dE_max
    as "?": an empty cell, as a key left out, and not among his answers."""
    scene = _write(
        tmp_path,
        'title = "x"\n[turning_moment]\ntorque = "1000 + 300 sin 2theta"\n[flywheel]\n'
        'speed = "300 rpm"\ninertia = "40 kg m^2"\n',
    )
    answers = tmp_path / "answers"
    answers.mkdir()
    (answers / "ann.toml").write_text(
        'student = "ann"\n[answers]\nT_mean = "1000 N m"\ndE_max = "300 J"\n'
    )
    (answers / "bob.toml").write_text(
        'student = "bob"\n[answers]\nT_mean = "1000 N m"\ndE_max = "?"\n'
    )
    book = tmp_path / "book.csv"
    capsys.readouterr()
    assert main(["check", str(scene), str(answers), "--gradebook", str(book)]) == 0
    rows = {r["student"]: r for r in csv.DictReader(book.open())}
    assert (rows["ann"]["dE_max"], rows["ann"]["right"], rows["ann"]["of"]) == ("right", "2", "2")
    assert (rows["bob"]["dE_max"], rows["bob"]["right"], rows["bob"]["of"]) == ("", "1", "1")
    assert "3 of 3 answers right" in capsys.readouterr().out


def test_an_engines_cycle_keys_asked_beside_its_efforts(tmp_path, capsys):
    """I_flywheel = "?" is the engine's key (not a centre I_ij); its value and dE_max's
    against the file's answers worked by hand to four figures."""
    text = (HERE.parent / "worked_problems" / "engine_flywheel.toml").read_text()
    head, answers = text.split("[answers]")
    book = {
        line.split("=")[0].strip(): float(line.split('"')[1].split()[0])
        for line in answers.splitlines()
        if line.strip().startswith(("dE_max", "I_flywheel", "T_mean"))
    }
    asked = answers
    for key in book:
        asked = "\n".join(
            f'{key} = "?"' if line.strip().startswith(key + " ") else line
            for line in asked.splitlines()
        )
    got = _solve_json(_write(tmp_path, head + "[answers]" + asked), capsys)
    assert list(got) == ["T_mean", "dE_max", "I_flywheel"]
    for key, want in book.items():
        assert abs(got[key]["value"] - want) <= 5e-4 * want, (key, got[key]["value"], want)


def _every_answer_asked(text: str) -> str:
    """The scene with each value of its [answers] (its tolerance aside) made "?"."""
    head, rest = text.split("\n[answers]", 1)
    body, sep, tail = rest.partition("\n[")
    lines = [
        line.split("=")[0].rstrip() + ' = "?"'
        if "=" in line and not line.lstrip().startswith(("tolerance", "#"))
        else line
        for line in body.splitlines()
    ]
    return head + "\n[answers]" + "\n".join(lines) + sep + tail


WORKED = [
    f
    for f in sorted((HERE.parent / "worked_problems").glob("*.toml"))
    if "\n[answers]" in f.read_text()
]


@pytest.mark.parametrize("path", WORKED, ids=[f.stem for f in WORKED])
def test_every_worked_problems_answers_asked_are_the_values_check_grades(path, tmp_path, capsys):
    """Each worked problem with its every answer asked as "?" (every kind of key: the
    force chapter's, the engine's, centres, sliding, a cylinder's, ...): solve, steps and
    check answer it, and each value is the one check grades the book's answer against."""
    asked = _write(tmp_path, _every_answer_asked(path.read_text()))
    got = _solve_json(asked, capsys)
    for command in ("steps", "check"):
        assert main([command, str(asked)]) == 0
    graded = {v.key: v for v in check_answers(solve(load_scene(path)))}
    assert set(graded) <= set(got)
    for key, v in graded.items():
        value = got[key]["value"]
        assert abs(abs(value) - abs(v.correct)) <= 1e-12 * abs(v.correct), key
