"""A turning-moment diagram's class: ``variants`` from its ``[variants]`` table (each
variant's answer key held to the closed form worked here from the values the variant's own
file states, read with tomllib), ``check SCENE answers/ --gradebook`` and ``--variants``
(each student against their own variant, the diagram's slips named in the summary), and bad
input: one located line, exit 2, nothing written."""

import csv
import math
import tomllib
from pathlib import Path

import pytest

import polygon_method as pm
from polygon_method.cli import main

A = math.hypot(300, 500)  # T - 1000 = 300 sin 2t - 500 cos 2t swings the energy by A
LAW = """title = "A sinusoid about its mean"
[turning_moment]
torque = "1000 + 300 sin 2theta - 500 cos 2theta"
[flywheel]
speed = "300 rpm"
plus_minus = "1%"
radius = "0.5 m"
[answers]
dE_max = "583.1 J"
I_flywheel = "29.5 kg m^2"
m_flywheel = "118 kg"
[variants]
flywheel = { speed = { from = 250, to = 350, step = 25, unit = "rpm" }, plus_minus = ["1%", "1.5%", "2%"] }
"""
AREAS = """title = "Areas"
[turning_moment]
areas = [52, -124, 92, -140, 85, -72, 107]
torque_scale = "1 mm = 70 N m"
angle_scale = "1 mm = 4.5 deg"
[flywheel]
speed = "600 rpm"
plus_minus = "1.5%"
radius = "0.5 m"
[variants]
turning_moment = { torque_scale = ["1 mm = 60 N m", "1 mm = 70 N m", "1 mm = 80 N m"] }
flywheel = { speed = ["500 rpm", "600 rpm"] }
"""


def _write(d: Path, name: str, text: str) -> str:
    p = d / name
    p.write_text(text, encoding="utf-8")
    return str(p)


def _run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def _law_key(raw):
    """(dE_max, I, m) of a variant of LAW from its own file's numbers, by hand:
    I = A / (w^2 Cs), Cs twice the +-, m = I / R^2."""
    rpm = float(raw["flywheel"]["speed"].split()[0])
    cs = 2 * float(raw["flywheel"]["plus_minus"].rstrip("%")) / 100
    w = rpm * math.pi / 30
    inertia = A / (w * w * cs)
    return A, inertia, inertia / 0.25


@pytest.fixture
def law_class(tmp_path, capsys):
    base = _write(tmp_path, "law.toml", LAW)
    out = tmp_path / "class"
    code, text, err = _run(capsys, "variants", base, "--count", 6, "--seed", 7, "-o", out)
    assert code == 0, err
    return base, out


def test_each_variants_key_is_the_closed_form_of_its_own_numbers(law_class):
    base, out = law_class
    rows = list(csv.DictReader((out / "answer-key.csv").open(encoding="utf-8")))
    assert len(rows) == 6
    seen = set()
    for row in rows:
        raw = tomllib.loads((out / row["file"]).read_text(encoding="utf-8"))
        assert raw["variant"]["id"] == row["variant"] and "answers" not in raw
        assert "variants" not in raw
        pick = (raw["flywheel"]["speed"], raw["flywheel"]["plus_minus"])
        assert pick != ("300 rpm", "1%")  # never the base problem itself
        assert pick not in seen  # no two alike
        seen.add(pick)
        dE, inertia, mass = _law_key(raw)
        for key, want in (
            ("dE_max (J)", dE),
            ("I_flywheel (kg m^2)", inertia),
            ("m_flywheel (kg)", mass),
        ):
            assert abs(float(row[key]) - want) <= 1e-9 * want, (row, key)
        c = pm.solve_cycle(pm.load_cycle(out / row["file"]))
        assert abs(c.inertia - inertia) <= 1e-9 * inertia
    md = (out / "answer-key.md").read_text(encoding="utf-8")
    assert md.count("\n| 0") == 6
    sheet = (out / "problem-sheet.md").read_text(encoding="utf-8").split("## Variant ")[1:]
    assert len(sheet) == 6
    for part, row in zip(sheet, rows):  # each student is given their own numbers
        raw = tomllib.loads((out / row["file"]).read_text(encoding="utf-8"))
        assert part.startswith(row["variant"])
        assert f'[flywheel] speed = "{raw["flywheel"]["speed"]}"' in part
        assert f'[flywheel] plus_minus = "{raw["flywheel"]["plus_minus"]}"' in part
        assert "[turning_moment] torque = " in part and "Find: " in part


def test_the_same_seed_gives_the_same_variants(law_class, tmp_path, capsys):
    base, out = law_class
    again = tmp_path / "again"
    assert _run(capsys, "variants", base, "--count", 3, "--seed", 7, "-o", again)[0] == 0
    for i in (1, 2, 3):
        name = f"variant-0{i}.toml"
        assert (again / name).read_text() == (out / name).read_text()


def test_the_areas_scale_varies_the_energy(tmp_path, capsys):
    """dE_max = (52 + 120) mm^2 x (torque scale x 4.5 deg in rad); I from the speed."""
    base = _write(tmp_path, "areas.toml", AREAS)
    out = tmp_path / "cls"
    code, _, err = _run(capsys, "variants", base, "--count", 5, "--seed", 1, "-o", out)
    assert code == 0, err
    for row in csv.DictReader((out / "answer-key.csv").open(encoding="utf-8")):
        raw = tomllib.loads((out / row["file"]).read_text(encoding="utf-8"))
        scale = float(raw["turning_moment"]["torque_scale"].split("=")[1].split()[0])
        dE = 172 * scale * 4.5 * math.pi / 180
        w = float(raw["flywheel"]["speed"].split()[0]) * math.pi / 30
        assert abs(float(row["dE_max (J)"]) - dE) <= 1e-9 * dE
        assert abs(float(row["I_flywheel (kg m^2)"]) - dE / (w * w * 0.03)) <= 1e-9 * dE / (
            w * w * 0.03
        )
    # 3 x 2 combinations less the base problem: five, and no sixth
    code, _, err = _run(capsys, "variants", base, "--count", 6, "--seed", 1, "-o", tmp_path / "six")
    assert code == 2 and "only 5 of the 6 combinations" in err and "base problem" in err
    assert not (tmp_path / "six").exists()


def _answers(d, name, text):
    return _write(d, name, text)


def test_a_class_graded_against_each_students_variant(law_class, tmp_path, capsys):
    base, out = law_class
    raws = {
        r["variant"]: tomllib.loads((out / r["file"]).read_text(encoding="utf-8"))
        for r in csv.DictReader((out / "answer-key.csv").open(encoding="utf-8"))
    }
    ans = tmp_path / "answers"
    ans.mkdir()
    dE, i1, _ = _law_key(raws["01"])
    _, i2, _ = _law_key(raws["02"])
    _, i3, _ = _law_key(raws["03"])
    _answers(
        ans,
        "ann.toml",
        f'student = "Ann"\nvariant = "01"\n[answers]\ndE_max = "{dE:.4g} J"\nI_flywheel = "{i1:.4g} kg m^2"\n',
    )
    # Bob takes Cs as the range either side of the mean: twice the flywheel
    _answers(
        ans,
        "bob.toml",
        f'student = "Bob"\nvariant = 2\n[answers]\nI_flywheel = "{2 * i2:.4g} kg m^2"\n',
    )
    # Cy works in rpm: I x (pi/30)^2
    _answers(
        ans,
        "cy.toml",
        f'student = "Cy"\nvariant = "variant-03"\n[answers]\nI_flywheel = "{i3 * (math.pi / 30) ** 2:.4g} kg m^2"\n',
    )
    _answers(ans, "dee.toml", '[answers]\ndE_max = "583.1 J"\n')  # names no variant
    _answers(ans, "eve.toml", 'variant = "01"\n[answers]\nv_C = "1 m/s"\n')  # not a key here
    book = tmp_path / "grades.csv"
    code, text, err = _run(capsys, "check", base, ans, "--variants", out, "--gradebook", book)
    assert code == 0, err
    rows = {r["student"]: r for r in csv.DictReader(book.open(encoding="utf-8"))}
    assert rows["Ann"]["variant"] == "01" and rows["Ann"]["right"] == "2"
    assert rows["Bob"]["I_flywheel"] == "WRONG (Cs taken as the range either side of the mean)"
    assert rows["Cy"]["I_flywheel"] == "WRONG (the mean speed in rpm where rad/s belongs)"
    assert "names no variant" in rows["dee"]["error"]
    assert "v_C" in rows["eve"]["error"] and "[answers]" in rows["eve"]["error"]
    assert "3 of 5 answer files read" in text
    assert "Cs taken as the range either side of the mean: 1 student" in text
    # one file with --variants: exit 1 where an answer is wrong, against its variant
    code, text, _ = _run(capsys, "check", base, ans / "bob.toml", "--variants", out)
    assert code == 1 and "graded against variant 02" in text
    # without --variants a file that names one is refused, never graded against the base
    code, _, err = _run(capsys, "check", base, ans / "ann.toml")
    assert code == 2 and "--variants" in err and err.count("\n") == 1
    # the variant's own scene grades it
    assert _run(capsys, "check", out / "variant-01.toml", ans / "ann.toml")[0] == 0


def test_a_class_of_the_base_scene_and_a_markdown_gradebook(tmp_path, capsys):
    base = _write(tmp_path, "law.toml", LAW)
    ans = tmp_path / "a"
    ans.mkdir()
    _answers(ans, "one.toml", '[answers]\ndE_max = "583.1 J"\nI_flywheel = "29.53 kg m^2"\n')
    _answers(ans, "two.toml", '[answers]\ndE_max = "866.0 J"\n')
    book = tmp_path / "g.md"
    code, text, _ = _run(capsys, "check", base, ans, "--gradebook", book, "--tolerance", "1%")
    assert code == 0
    md = book.read_text(encoding="utf-8")
    assert "| one |" in md and "| two |" in md and "1 % (--tolerance)" in md
    assert "2 of 2 answer files read; 2 of 3 answers right" in md


BAD = [
    ("flywheel = { colour = [1, 2] }", "[variants] flywheel", "does not give colour"),
    ("wheel = { speed = [1, 2] }", "[variants] wheel", "unknown table"),
    ('flywheel = { speed = ["300 rpn", "310 rpm"] }', "[variants] flywheel", "speed"),
    ("press = { energy = [1, 2] }", "[variants] press", "no [press]"),
    (
        'flywheel = { speed = { from = 5, to = 1, step = 1, unit = "rpm" } }',
        "[variants] flywheel",
        "empty",
    ),
]


@pytest.mark.parametrize("line,where,words", BAD, ids=[b[2] for b in BAD])
def test_a_bad_variants_table_is_one_located_line(tmp_path, capsys, line, where, words):
    text = LAW.split("[variants]")[0] + "[variants]\n" + line + "\n"
    base = _write(tmp_path, "law.toml", text)
    code, _, err = _run(capsys, "variants", base, "--count", 2, "--seed", 1, "-o", tmp_path / "o")
    assert code == 2 and err.count("\n") == 1, err
    assert where in err and words in err and "(line 13)" in err, err
    assert not (tmp_path / "o").exists()


def test_variants_needs_a_variants_table_and_no_pdf(tmp_path, capsys):
    base = _write(tmp_path, "law.toml", LAW.split("[variants]")[0])
    code, _, err = _run(capsys, "variants", base, "--count", 2, "-o", tmp_path / "o")
    assert code == 2 and "[variants]" in err
    base = _write(tmp_path, "law2.toml", LAW)
    code, _, err = _run(capsys, "variants", base, "--count", 2, "-o", tmp_path / "o", "--pdf")
    assert code == 2 and "--pdf" in err
