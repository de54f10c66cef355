"""The commands on a turning-moment diagram's scene: solve (and its JSON), steps, check (the
classic slips named), draw (byte for byte the same run to run), sweep; the other commands
and bad input: one located line, exit 2, nothing written."""

import json
import math

import pytest

from polygon_method.cli import main

AREAS = """title = "Areas"
[turning_moment]
areas = [52, -124, 92, -140, 85, -72, 107]
torque_scale = "1 mm = 70 N m"
angle_scale = "1 mm = 4.5 deg"
[flywheel]
speed = "600 rpm"
plus_minus = "1.5%"
radius = "0.5 m"
"""
LAW = """title = "Law"
[turning_moment]
torque = "1000 + 300 sin 2theta - 500 cos 2theta"
[flywheel]
speed = "300 rpm"
plus_minus = "1%"
radius = 600
width_to_thickness = 2
"""
PRESS = """[press]
energy = "12 kJ"
holes_per_minute = 10
punching_time = "1.5 s"
[flywheel]
max_speed = "240 rpm"
min_speed = "210 rpm"
gyration = "0.55 m"
"""


def _write(tmp_path, text, name="s.toml"):
    p = tmp_path / name
    p.write_text(text, encoding="utf-8")
    return str(p)


def _run(capsys, *argv):
    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_solve_json_is_finite_and_says_what_the_text_says(tmp_path, capsys):
    f = _write(tmp_path, LAW)
    code, out, _ = _run(capsys, "solve", f, "--json")
    assert code == 0
    d = json.loads(out)["cycle"]
    A = math.hypot(300, 500)
    assert abs(d["dE_max"] - A) <= 1e-9 * A
    assert [c["letter"] for c in d["crossings"]] == ["a", "b", "c", "d", "a"]
    assert d["rim_width"] == pytest.approx(2 * d["rim_thickness"], rel=1e-12)
    code, out, _ = _run(capsys, "solve", f)
    assert code == 0 and "dE_max = 583.1 J" in out and "(default)" in out


def test_steps_write_the_books_table(tmp_path, capsys):
    code, out, _ = _run(capsys, "steps", _write(tmp_path, AREAS))
    assert code == 0
    assert "E + 285.9" in out and "E - 659.7" in out  # 52 and -120 mm^2 of 5.498 J
    assert "dE_max = 285.9 - (-659.7) = 945.6 J" in out
    code, out, _ = _run(capsys, "steps", _write(tmp_path, PRESS, "p.toml"))
    assert code == 0 and "dE_max = 9000 J" in out


@pytest.mark.parametrize(
    "text,answer,slip",
    [
        (AREAS, 'dE_max = "769.7 J"', "largest_area"),  # the -140 mm^2 area alone
        (AREAS, 'I_flywheel = "15.97 kg m^2"', "cs_half_range"),
        (AREAS, 'I_flywheel = "3.992 kg m^2"', "cs_doubled"),
        (AREAS, 'I_flywheel = "0.08756 kg m^2"', "rpm_not_rad_per_s"),
        (PRESS, 'dE_max = "12000 J"', "whole_energy"),
    ],
)
def test_check_names_the_classic_slips(tmp_path, capsys, text, answer, slip):
    f = _write(tmp_path, text + "[answers]\n" + answer + "\n")
    code, out, _ = _run(capsys, "check", f, "--json")
    assert code == 1
    (v,) = json.loads(out)["answers"]
    assert v["mistake"] == slip


def test_check_reads_a_students_file(tmp_path, capsys):
    f = _write(tmp_path, AREAS)
    ans = _write(tmp_path, '[answers]\ndE_max = "945.6 J"\nm_flywheel = "31.94 kg"\n', "a.toml")
    code, out, _ = _run(capsys, "check", f, ans)
    assert code == 0 and "2 of 2 right" in out


@pytest.mark.parametrize("fmt", ["svg", "png", "pdf"])
@pytest.mark.parametrize("text", [AREAS, LAW, PRESS], ids=["areas", "law", "press"])
def test_draw_is_the_same_byte_for_byte(tmp_path, capsys, monkeypatch, fmt, text):
    monkeypatch.delenv("SOURCE_DATE_EPOCH", raising=False)
    f = _write(tmp_path, text)
    outs = []
    for k in (1, 2):
        out = tmp_path / f"x{k}.{fmt}"
        assert main(["draw", f, "-o", str(out)]) == 0
        outs.append(out.read_bytes())
    capsys.readouterr()
    assert outs[0] == outs[1] and len(outs[0]) > 1000


def test_sweep_summary_and_csv(tmp_path, capsys):
    f = _write(tmp_path, LAW)
    code, out, _ = _run(capsys, "sweep", f, "--summary")
    assert code == 0 and "dE_max" in out
    csv = tmp_path / "c.csv"
    code, _, _ = _run(capsys, "sweep", f, "--csv", str(csv), "--steps", "36")
    rows = csv.read_text().splitlines()
    assert code == 0 and rows[0] == "angle_deg,torque,resisting,energy" and len(rows) == 38
    for row in rows[1:]:
        x, t, r, _ = map(float, row.split(","))
        th = math.radians(x)
        assert abs(t - (1000 + 300 * math.sin(2 * th) - 500 * math.cos(2 * th))) < 1e-9 * 1000
        assert abs(r - 1000) < 1e-9 * 1000


def test_a_diagrams_csv_on_standard_output(tmp_path, capsys, monkeypatch):
    """``--csv -``: the CSV on standard output, the summary on stderr, no file named '-'."""
    monkeypatch.chdir(tmp_path)
    f = _write(tmp_path, LAW)
    code, out, err = _run(capsys, "sweep", f, "--csv", "-", "--steps", "36", "--summary")
    rows = out.splitlines()
    assert code == 0 and rows[0] == "angle_deg,torque,resisting,energy" and len(rows) == 38
    x, t, _, _ = map(float, rows[10].split(","))
    th = math.radians(x)
    assert abs(t - (1000 + 300 * math.sin(2 * th) - 500 * math.cos(2 * th))) < 1e-9 * 1000
    assert "dE_max" in err and not (tmp_path / "-").exists()


BAD = [
    ("plan", AREAS, "[turning_moment]", "nothing to do"),
    (
        "solve",
        AREAS.replace("areas = [52,", "areas = [520,"),
        "[turning_moment] areas",
        "not nought",
    ),
    (
        "solve",
        AREAS.replace('"1 mm = 70 N m"', '"70 N m"'),
        "[turning_moment] torque_scale",
        "1 mm",
    ),
    ("solve", LAW.replace("sin 2theta", "sin 2phi"), "[turning_moment] torque", "cannot read"),
    ("solve", LAW.replace('plus_minus = "1%"', ""), "[flywheel] coefficient", "one of them"),
    ("solve", LAW + "[ground]\nO = [0, 0]\n", "[ground]", "stands alone"),
    ("solve", LAW.replace("[flywheel]", "[flywheel]\ncolour = 1"), "[flywheel] colour", "unknown"),
    (
        "solve",
        PRESS.replace('punching_time = "1.5 s"', 'punching_angle = "400 deg"'),
        "[press] punching_angle",
        "0 to 1",
    ),
    ("solve", PRESS.replace("holes_per_minute = 10\n", ""), "[press] holes_per_minute", "one of"),
    (
        "solve",
        LAW.replace("[turning_moment]", '[turning_moment]\nresisting = "900"'),
        "[turning_moment] resisting",
        "differ",
    ),
    ("draw", LAW, "--diagram", "one drawing"),
    ("check", LAW, "[answers]", "nothing to check"),
    ("check", LAW + '[answers]\nE_stroke = "3 kJ"\n', "[answers] E_stroke", "press"),
]


@pytest.mark.parametrize("cmd,text,where,words", BAD, ids=[f"{b[0]}-{b[2]}" for b in BAD])
def test_bad_input_is_one_located_line_and_exit_2(tmp_path, capsys, cmd, text, where, words):
    f = _write(tmp_path, text)
    extra = {"draw": ["-o", str(tmp_path / "x.svg"), "--diagram", "velocity"]}.get(cmd, [])
    code, out, err = _run(capsys, cmd, f, *extra)
    assert code == 2, (out, err)
    assert err.count("\n") == 1 and where in err and words in err, err
    assert "Traceback" not in err
    assert not (tmp_path / "x.svg").exists()
