"""Adversarial inputs found by a scripted sweep of every command over hostile files and
options, each kept as a table of its class: the output holds no "nan" or "inf", a bad input
is one line naming its file, key or option with exit code 2, and no file is clobbered.

Expected values come from the inputs themselves (a number the user wrote, the scene's own
closed-form answer in its comment, a count of lines), never from the code under test."""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest

from polygon_method.cli import main

from scenes import FOURBAR

ROOT = Path(__file__).resolve().parent.parent

#: a word of the output that is no number a user can read
_NOT_A_NUMBER = re.compile(r"\b(nan|inf|infinity)\b", re.IGNORECASE)

#: v_C of the seed four-bar (closed-form positions and finite differences, not this
#: project's solver: worked_problems/fourbar_image_points.toml)
V_C = 0.4005


def _code(argv) -> int:
    """main's exit code, or argparse's (which exits)."""
    try:
        return main(argv)
    except SystemExit as exc:
        return exc.code


def _scene(tmp_path, text, name="s.toml"):
    path = tmp_path / name
    path.write_text(text, encoding="utf-8")
    return str(path)


# ------------------------------------------------- an answer of absurd size in the tables


@pytest.mark.parametrize("given", ["1e308", "-1e308", "1.7e308", "1e200", "4e306", "1e7"])
@pytest.mark.parametrize("command", ["check", "check-json"])
def test_an_answer_of_absurd_size_has_an_error_in_words_never_inf(tmp_path, capsys, given, command):
    """``v_C = "1e308 m/s"``: its error, 2.5e308 %, is past the largest float; the table
    wrote "inf %" (and a 300-digit per cent for 1e300)."""
    path = _scene(tmp_path, FOURBAR + f'\n[answers]\nv_C = "{given} m/s"\n')
    argv = ["check", "--json", path] if command == "check-json" else ["check", path]
    assert main(argv) == 1
    out = capsys.readouterr().out
    assert not _NOT_A_NUMBER.search(out), out
    if command == "check-json":
        record = json.loads(out)["answers"][0]
        assert record["verdict"] == "wrong" and abs(record["given"]) == abs(float(given))
        return
    row = next(line for line in out.splitlines() if line.startswith("v_C"))
    percent = 100 * abs(float(given) - V_C) / V_C
    if percent > 1.7976931348623157e308:
        assert "more than 1e+308 %" in row, row
    else:
        shown = float(re.search(r"([0-9.e+]+) %", row.split("m/s", 2)[-1]).group(1))
        assert shown == pytest.approx(percent, rel=5e-3), row
        assert len(row) < 100, row


# ------------------------------------------------------------------ options given twice

SEED = "worked_problems/fourbar_image_points.toml"


@pytest.mark.parametrize(
    "argv, option",
    [
        (["sweep", SEED, "--steps", "12", "--steps", "24"], "--steps"),
        (["sweep", SEED, "--from", "0", "--from", "5", "--to", "9", "--step", "1"], "--from"),
        (["draw", SEED, "-o", "{tmp}/a.svg", "-o", "{tmp}/b.svg"], "-o/--output"),
        (["draw", SEED, "-o", "{tmp}/a.svg", "--paper", "A4", "--paper", "A3"], "--paper"),
        (
            ["draw", SEED, "-o", "{tmp}/a.svg", "--diagram", "all", "--diagram", "velocity"],
            "--diagram",
        ),
        (["page", SEED, "-o", "{tmp}/a.html", "--frames", "4", "--frames", "8"], "--frames"),
        (["steps", SEED, "--format", "text", "--format", "markdown"], "--format"),
        (["variants", SEED, "-o", "{tmp}/v", "--seed", "1", "--seed", "2"], "--seed"),
        (["check", SEED, "--gradebook", "{tmp}/g.csv", "--gradebook", "{tmp}/h.md"], "--gradebook"),
        (["centres", SEED, "--centre-labels", "13", "--centre-labels", "I13"], "--centre-labels"),
    ],
)
def test_an_option_given_twice_with_two_values_is_refused_and_nothing_written(
    tmp_path, capsys, argv, option
):
    """argparse keeps the last of ``-o a.svg -o b.svg`` silently: which one was meant?"""
    argv = [a.replace("{tmp}", str(tmp_path)) for a in argv]
    assert _code(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"{option} given twice" in err[0], err
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(
    "argv",
    [
        ["sweep", SEED, "--steps", "12", "--steps", "12"],
        ["steps", SEED, "--format", "markdown", "--format", "markdown"],
        ["solve", "--json", "--json", SEED],
    ],
)
def test_an_option_repeated_with_its_own_value_is_taken(capsys, argv):
    assert main(argv) == 0
    assert capsys.readouterr().out.strip()


# ------------------------------------------------------ a negative value after an option


@pytest.mark.parametrize(
    "argv, words",
    [
        (["check", SEED, "--tolerance", "-5%"], "'-5%': a per cent between 0 and 100"),
        (["sweep", SEED, "--from", "0", "--to", "-inf", "--step", "1"], "finite numbers"),
        (["sweep", SEED, "--from", "-nan", "--to", "5", "--step", "1"], "finite numbers"),
        (["sweep", SEED, "--steps", "-5"], "--steps must be at least 1, got -5"),
    ],
)
def test_a_negative_value_is_refused_in_its_options_words(capsys, argv, words):
    """``--tolerance -5%`` was "expected one argument": argparse took "-5%" for an option."""
    assert _code(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and words in err[0], err


# ------------------------------------------- a slider's path given by a far point on it

SLIDER_CRANK = (ROOT / "worked_problems/offset_slider_crank.toml").read_text(encoding="utf-8")


@pytest.mark.parametrize("far", ["[1e6, -40]", "[-5e5, -40]", "[20000, -40]"])
@pytest.mark.parametrize("diagram", ["configuration", "centres"])
def test_a_path_through_a_far_point_is_drawn_as_the_same_line_through_a_near_one(
    tmp_path, capsys, far, diagram
):
    """``through = [1e6, -40]`` names the horizontal line y = -40 as ``[0, -40]`` does; the
    line of stroke was drawn out to the far point: "the configuration diagram ... would be
    2e+04 cm across; use a coarser scale such as" the very scale refused (and the centres
    diagram, coarsened to 1 cm = 50 m, took minutes placing its labels)."""
    said = []
    for through in ("[0, -40]", far):
        path = _scene(tmp_path, SLIDER_CRANK.replace("[0, -40]", through), f"{len(said)}.toml")
        out = tmp_path / f"{len(said)}.svg"
        assert main(["draw", path, "-o", str(out), "--diagram", diagram]) == 0
        said.append(capsys.readouterr().out.split(":", 1)[1])
        assert out.stat().st_size > 0
    assert said[0] == said[1]


# --------------------------------------------------- a link in a loop among the variants


@pytest.mark.parametrize("where", ["variants", "answers"])
def test_a_link_in_a_loop_among_the_files_is_a_row_never_an_internal_error(tmp_path, capsys, where):
    """``variant-09.toml -> variant-09.toml`` in the variants' directory: ``Path.resolve``
    raised RuntimeError (exit 3, "internal error")."""
    base = str(ROOT / SEED)
    out = tmp_path / "class"
    assert main(["variants", base, "--count", "2", "--seed", "1", "-o", str(out)]) == 0
    answers = tmp_path / "answers"
    answers.mkdir()
    (answers / "amy.toml").write_text('variant = "01"\n[answers]\nv_C = "0.4 m/s"\n')
    loop = (out if where == "variants" else answers) / "variant-09.toml"
    loop.symlink_to(loop)
    book = tmp_path / "book.csv"
    capsys.readouterr()
    code = main(["check", base, str(answers), "--variants", str(out), "--gradebook", str(book)])
    captured = capsys.readouterr()
    assert code == 0, captured.err
    assert "internal error" not in captured.err
    rows = book.read_text().splitlines()
    assert rows[0].startswith("student") and any(r.startswith("amy,") for r in rows)
    assert len(rows) == (3 if where == "answers" else 2)


# ------------------------------------------- a directory that takes no new file (/proc)


@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="no /proc on this system")
@pytest.mark.parametrize(
    "argv, option",
    [
        (["sweep", SEED, "--steps", "12", "--csv", "/proc/x.csv"], "--csv"),
        (["draw", SEED, "--diagram", "velocity", "-o", "/proc/x.svg"], "-o"),
        (["page", SEED, "--frames", "4", "-o", "/proc/x.html"], "-o"),
    ],
)
def test_an_output_where_no_file_can_be_made_names_the_output_not_a_temporary(capsys, argv, option):
    """The temporary file beside the output could not be made: the line named
    "/proc/.x.csv.dco3etcc.tmp", a file the user never asked for."""
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1, err
    assert f"{option}: cannot write {argv[-1]}:" in err[0] and ".tmp" not in err[0], err


# ------------------------------------------- a [variants] table's example, as TOML


@pytest.mark.parametrize(
    "variants, words",
    [
        ("D = [[100, 0], [110, 0]]", "a point's variation says what varies"),
        ("BC = { from = 60, to = 72 }", "the range has no step"),
        ('BC = "60 to 72"', "give a range"),
    ],
)
def test_a_bad_variants_entry_shows_its_example_as_toml_a_reader_can_copy(
    tmp_path, capsys, variants, words
):
    """The examples were written "{ from = 60, to = 75, step = 1 }}" (an f-string's
    doubled brace in a plain string): each brace of the example must pair with one."""
    base = (ROOT / SEED).read_text(encoding="utf-8").split("[variants]")[0]
    path = _scene(tmp_path, base + "[variants]\n" + variants + "\n")
    assert main(["variants", path, "--count", "2", "-o", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and words in err[0], err
    example = err[0].split(words, 1)[1]
    depth = 0
    for ch in example:
        depth += {"{": 1, "}": -1}.get(ch, 0)
        assert depth >= 0, example
    assert depth == 0, example
    assert not (tmp_path / "out").exists()


# ------------------------------------------- a turning-moment diagram of countless areas

ENGINE_AREAS = (ROOT / "worked_problems/flywheel/engine_areas_rim.toml").read_text(encoding="utf-8")
_AREAS_LINE = "areas = [52, -124, 92, -140, 85, -72, 107]"


def _areas(n: int) -> str:
    return ENGINE_AREAS.replace(_AREAS_LINE, "areas = [" + ", ".join(["1, -1"] * (n // 2)) + "]")


@pytest.mark.parametrize(
    "argv",
    [
        ["solve", "{scene}"],
        ["steps", "{scene}"],
        ["check", "{scene}"],
        ["draw", "{scene}", "-o", "{tmp}/x.svg"],
        ["page", "{scene}", "-o", "{tmp}/x.html"],
    ],
)
@pytest.mark.parametrize("n", [102, 100000])
def test_a_diagram_of_countless_areas_is_one_line_before_minutes_of_drawing(
    tmp_path, capsys, argv, n
):
    """``areas = [1, -1, ...]`` 100000 long: ``draw`` ran for minutes (each area a lobe, a
    label and a lettered crossing)."""
    scene = _scene(tmp_path, _areas(n))
    argv = [a.replace("{scene}", scene).replace("{tmp}", str(tmp_path)) for a in argv]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and f"{n} areas: at most 100" in err[0], err
    assert "[turning_moment] areas" in err[0] and "s.toml" in err[0]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.toml"]


def test_a_diagram_of_a_hundred_areas_is_solved(tmp_path, capsys):
    """At the bound: alternate areas of +1 and -1 mm^2 swing the energy by one of them,
    1 mm^2 = 70 N m x 4.5 deg = 70 x 4.5 pi / 180 J."""
    assert main(["solve", "--json", _scene(tmp_path, _areas(100))]) == 0
    cycle = json.loads(capsys.readouterr().out)["cycle"]
    assert len(cycle["areas"]) == 100
    assert cycle["dE_max"] == pytest.approx(70 * 4.5 * math.pi / 180, rel=1e-12)


# --------------------------------------------------- a point used before it is set out

_E = 'E = { on = "BC", along = 40 }'


@pytest.mark.parametrize(
    "points, words",
    [
        (  # F set out from E, which is given below it
            'F = { on = "BC", distances = { E = 20, C = 30 }, turn = "cw" }\n' + _E,
            "E is not a point of link BC yet: E is set out on it below F in [points]; give E first",
        ),
        (  # the same, E named as on "CB"
            'F = { on = "BC", distances = { E = 20, C = 30 }, turn = "cw" }\n'
            'E = { on = "CB", along = 26 }',
            "E is set out on it below F in [points]; give E first",
        ),
        (  # a point of another link is no forward reference
            'F = { on = "BC", distances = { A = 20, C = 30 }, turn = "cw" }\n' + _E,
            "): A is not a point of link BC",
        ),
    ],
)
def test_a_point_set_out_from_one_given_below_it_says_to_give_that_one_first(
    tmp_path, capsys, points, words
):
    """The order of [points] matters (a point is set out from those above it): the line
    said only "E is not a point of link BC", though E is, further down."""
    text = FOURBAR.replace("[input]", "[points]\n" + points + "\n[input]")
    path = _scene(tmp_path, text)
    assert main(["solve", path]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "[points] F (line" in err[0], err
    assert words in err[0], err
    if "give E first" not in words:
        assert "yet" not in err[0], err
    else:  # and given first, the same points are solved
        lines = points.splitlines()
        swapped = _scene(tmp_path, text.replace(points, lines[1] + "\n" + lines[0]), "t.toml")
        assert main(["solve", swapped]) == 0


# ------------------------------------------- one quantity under two names: graded once

#: omega_BC of the seed four-bar, rad/s ccw (the scene's comment: closed-form positions and
#: finite differences, not this project's solver)
OMEGA_BC = 5.150


@pytest.mark.parametrize(
    "second, right",
    [
        ('omega_CB = "5.17 rad/s ccw"', True),  # the same value, the other order
        ('omega_CB = "5.1"', True),  # a size, no sense: still BC's
        ('omega_CB = "7 rad/s cw"', False),  # another value: one of the two is wrong
    ],
)
def test_one_quantity_under_two_names_is_graded_once(tmp_path, capsys, second, right):
    """``omega_BC`` and ``omega_CB`` are one link's angular velocity: the table graded
    both ("2 of 2 right"), counting one answer twice; now one row, the other name under it,
    right only if every value given for it is."""
    answers = _scene(
        tmp_path, f'[answers]\nomega_BC = "5.17 rad/s ccw"\n{second}\n', "answers.toml"
    )
    assert abs(5.17 - OMEGA_BC) / OMEGA_BC < 0.01  # (the first is right, to 0.4 %)
    code = main(["check", "--json", str(ROOT / SEED), answers])
    record = json.loads(capsys.readouterr().out)
    assert code == (0 if right else 1)
    assert len(record["answers"]) == 1 and record["right"] + record["wrong"] == 1
    row = record["answers"][0]
    assert row["key"] == "omega_BC" and row["correct"] == pytest.approx(OMEGA_BC, rel=1e-3)
    assert [a["key"] for a in row["also"]] == ["omega_CB"] and row["also"][0]["line"] == 3
    assert (row["verdict"] == "right") is right
    main(["check", str(ROOT / SEED), answers])
    text = capsys.readouterr().out
    assert "also given as omega_CB" in text and "graded once" in text
    assert text.strip().endswith("1 of 1 right" if right else "0 of 1 right, 1 wrong")


def test_a_relative_velocity_named_either_way_is_graded_once(tmp_path, capsys):
    """v_CB and v_BC: one relative velocity's size (0.3399 m/s, the scene's comment)."""
    answers = _scene(
        tmp_path, '[answers]\nv_CB = "0.34 m/s"\nv_BC = "0.34 m/s"\nv_C = "0.4005"\n', "a.toml"
    )
    assert main(["check", "--json", str(ROOT / SEED), answers]) == 0
    rows = json.loads(capsys.readouterr().out)["answers"]
    assert [r["key"] for r in rows] == ["v_CB", "v_C"]
    assert rows[0]["correct"] == pytest.approx(0.3399, rel=1e-3)


# ------------------------------------- typography a word processor puts in numbers


@pytest.mark.parametrize(
    "cd",
    [
        '"5.6\u00d710^1 mm"',  # 5.6 x 10^1
        '"5.6\u00b710\u00b9 mm"',  # a middle dot and a superscript power
        '"0.56\u00d710**2 mm"',
        '"55\u00bd mm"',  # a vulgar fraction: 55.5, not 56 (checked below)
        '"56\u00a0mm"',  # a non-breaking space
        '"56\u202fmm"',  # a narrow one
        '"5,6 cm"',  # a decimal comma
        '"56\u00b70 mm"',  # the British decimal point
    ],
)
def test_a_number_with_typographic_characters_is_read_as_it_means(tmp_path, capsys, cd):
    """``CD = "5.6×10^1 mm"``: "unknown unit '×10^1 mm'"; ``"−10.5 rad/s"``: "cannot read".
    Each form means CD = 56 mm (55.5 for the fraction): v_C agrees with the closed form."""
    text = FOURBAR.replace("CD = 56", f"CD = {cd}")
    assert main(["solve", "--json", _scene(tmp_path, text)]) == 0
    v = json.loads(capsys.readouterr().out)["points"]["C"]["velocity"]
    if "\u00bd" in cd:  # another length: only the reading is checked, by the position
        assert (
            main(["solve", "--json", _scene(tmp_path, FOURBAR.replace("CD = 56", "CD = 55.5"))])
            == 0
        )
        assert v == json.loads(capsys.readouterr().out)["points"]["C"]["velocity"]
        return
    assert math.hypot(*v) == pytest.approx(V_C, rel=1e-3)


@pytest.mark.parametrize("minus", ["\u2212", "\u2013", "\uff0d"])
def test_a_typographic_minus_in_an_answer_is_a_minus(tmp_path, capsys, minus):
    """``omega_CD = "−7.15 rad/s"`` (a minus sign pasted from a document): omega_CD is
    7.151 rad/s cw (the scene's comment), so the signed answer is right."""
    answers = _scene(tmp_path, f'[answers]\nomega_CD = "{minus}7.15 rad/s"\n', "a.toml")
    assert main(["check", "--json", str(ROOT / SEED), answers]) == 0
    row = json.loads(capsys.readouterr().out)["answers"][0]
    assert row["given"] == -7.15 and row["correct"] == pytest.approx(-7.151, rel=1e-3)


@pytest.mark.parametrize("bad, char", [("10\u2030 rad/s cw", "U+2030"), ("10 \u2126", "U+2126")])
def test_a_character_no_number_has_is_named_in_one_line(tmp_path, capsys, bad, char):
    """A character left that no number or unit has: one line naming it and its line."""
    text = FOURBAR.replace('"10.5 rad/s cw"', f'"{bad}"')
    assert main(["solve", _scene(tmp_path, text)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "[input] speed (line 11)" in err[0], err
    if char == "U+2030":
        assert char in err[0], err


def test_a_comma_that_reads_two_ways_in_a_scene_is_one_line(tmp_path, capsys):
    """``speed = "1,050 rpm cw"``: 1.05 or 1050? (was "unknown unit ',050 rpm'")."""
    text = FOURBAR.replace('"10.5 rad/s cw"', '"1,050 rpm cw"')
    assert main(["solve", _scene(tmp_path, text)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "reads two ways" in err[0], err


# ------------------------------------------------ a pin larger than the link it joins


@pytest.mark.parametrize("radius, warned", [(500, True), (60, True), (40, False)])
def test_a_pin_larger_than_its_link_is_warned_of(tmp_path, capsys, radius, warned):
    """A pin of radius 500 mm on a crank of 50 mm (its friction circle 150 mm) was taken
    silently. The crank AB is 50 mm: a radius past it is warned of, in the text and the
    JSON, with the friction circle where mu r passes it too."""
    text = FOURBAR + f"[pins]\nB = {{ radius = {radius} }}\n[masses]\n[friction]\npins = 0.3\n"
    path = _scene(tmp_path, text)
    assert main(["solve", "--json", path]) == 0
    warnings = [w for w in json.loads(capsys.readouterr().out)["warnings"] if "pin B" in w]
    assert bool(warnings) is warned
    if warned:
        assert "more than the link AB (50 mm)" in warnings[0]
        assert ("friction circle" in warnings[0]) is (0.3 * radius > 50)


# ------------------------------------------- a differential's output reversing often


def _slider_reversals(turns=4, n=400001):
    """The crank angles (deg, within the period) where the differential's slider Q turns
    back, by its closed-form position: the arm OA 100 at theta, the planet's point P 40
    from A turning 3.25 times as fast (40.84 / 12.566 rad/s, the scene's answer over its
    arm's speed: external mesh, (omega_p - omega_a) / (omega_s - omega_a) = -60 / 40),
    the rod PQ 150 to Q on the line through O."""
    t0 = math.radians(30.0)
    phi0 = math.atan2(0.07 - 0.05, 0.12124355652982143 - 0.08660254037844388)  # P - A at 30 deg
    k = 1 - 1.5 * (-0.5 - 1)  # 3.25
    import numpy as np

    th = np.linspace(t0 - turns * math.pi, t0 + turns * math.pi, n)
    xp = 0.1 * np.cos(th) + 0.04 * np.cos(phi0 + k * (th - t0))
    yp = 0.1 * np.sin(th) + 0.04 * np.sin(phi0 + k * (th - t0))
    d = np.diff(xp + np.sqrt(0.15**2 - yp**2))
    z = np.nonzero(np.sign(d[1:]) != np.sign(d[:-1]))[0]
    return sorted(np.degrees(th[z + 1]) % (360 * turns))


def test_a_slider_reversing_many_times_through_a_train_does_not_dwell(capsys):
    """linkage said the differential's slider "dwells over whole ranges of the crank" (26
    stationary positions were taken for a degenerate linkage): it reverses 26 times over
    the train's period of 4 turns, each listed where the closed form puts it."""
    expected = _slider_reversals()
    assert len(expected) == 26
    assert main(["linkage", str(ROOT / "worked_problems/differential_epicyclic.toml")]) == 0
    out = capsys.readouterr().out
    assert "dwells" not in out
    found = [float(m) for m in re.findall(r"crank at +([0-9.]+) deg: the output stands still", out)]
    assert found == pytest.approx(expected, abs=2e-3)


def test_a_second_input_far_faster_than_the_crank_is_one_line_not_an_alias(tmp_path, capsys):
    """The arm at 1.2e-5 rpm, the sun at 60 rpm: linkage ran for 17 s and said the slider
    dwells (3600 samples of a sun turning 5 million times a turn). One line, at once."""
    import time

    text = (ROOT / "worked_problems/differential_epicyclic.toml").read_text(encoding="utf-8")
    text = text.replace('speed = "120 rpm ccw"', 'speed = "1.2e-5 rpm ccw"').split("[answers]")[0]
    start = time.perf_counter()
    assert main(["linkage", _scene(tmp_path, text)]) == 2
    assert time.perf_counter() - start < 5
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "[input.second] speed" in err[0] and "cannot follow" in err[0], err


def test_a_sweep_too_coarse_for_a_second_input_says_its_extremes_may_be_aliased(tmp_path, capsys):
    """sweep --summary of the same scene printed the extremes of 360 samples of a planet
    turning 7.5 million times per turn of its arm, as if they were the motion's. It now
    says so in one line, by linkage's own check, with the spacing that would follow it:
    the planet's omega_P = omega_arm (1 + rS/rP) - omega_sun rS/rP (closed form, rS = 60,
    rP = 40), at most 10 deg between two samples."""
    text = (ROOT / "worked_problems/differential_epicyclic.toml").read_text(encoding="utf-8")
    text = text.split("[answers]")[0]
    arm, sun = 1.2e-5 * 2 * math.pi / 60, -2 * math.pi
    ratio = abs((arm * 2.5 - 1.5 * sun) / arm)
    assert main(["sweep", "--summary", _scene(tmp_path, text)]) == 0
    out = capsys.readouterr().out
    assert "aliased" not in out  # at 120 rpm the samples follow it
    fast = text.replace('speed = "120 rpm ccw"', 'speed = "1.2e-5 rpm ccw"')
    assert main(["sweep", "--summary", _scene(tmp_path, fast)]) == 0
    lines = [x for x in capsys.readouterr().out.splitlines() if "aliased" in x]
    assert len(lines) == 1, lines
    assert f"turns {ratio:.3g} times as fast as the crank OA" in lines[0], lines
    assert f"samples {10 / ratio:.3g} deg apart or closer would follow it" in lines[0], lines
    assert "the extremes below may be aliased" in lines[0], lines
    # the CSV's and the plot's values too, by the same check
    scene = _scene(tmp_path, fast)
    assert main(["sweep", scene, "--csv", str(tmp_path / "s.csv")]) == 0
    lines = [x for x in capsys.readouterr().out.splitlines() if "aliased" in x]
    assert len(lines) == 1 and "its values may be aliased" in lines[0], lines
    assert f"samples {10 / ratio:.3g} deg apart or closer would follow it" in lines[0], lines
    # and the page's, among its notes
    assert main(["page", scene, "-o", str(tmp_path / "s.html")]) == 0
    html = (tmp_path / "s.html").read_text(encoding="utf-8")
    assert html.count("the curves and the frames may be aliased") == 1


# ----------------------------------------------- an output that is a link to itself


@pytest.mark.parametrize("ring", [1, 2])
@pytest.mark.parametrize(
    "argv",
    [["draw", SEED, "--diagram", "velocity", "-o"], ["sweep", SEED, "--steps", "4", "--csv"]],
)
def test_an_output_that_is_a_link_round_to_itself_is_refused_and_kept(tmp_path, capsys, ring, argv):
    """``-o x.svg`` where x.svg -> x.svg: the link was replaced by the drawing."""
    links = [tmp_path / f"x{k}.svg" for k in range(ring)]
    for k, link in enumerate(links):
        link.symlink_to(links[(k + 1) % ring].name)
    assert main([*argv, str(links[0])]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "leads round to itself" in err[0], err
    assert all(link.is_symlink() for link in links)
    assert sorted(p.name for p in tmp_path.iterdir()) == sorted(link.name for link in links)


# --------------------------------------------- a driving block at rest: its header


def test_a_block_at_rest_is_said_at_rest_in_the_sweep_header(tmp_path, capsys):
    """``sweep --summary`` of a block at rest said "block A ... at 1 m/s to the left at
    every place", as if it moved; a crank's says "at rest, the motion per 1 rad/s
    (virtual)"."""
    text = (ROOT / "worked_problems/ellipse_trammel.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^vs_A = .*$", "vs_A = 0", text.split("[answers]")[0])
    text += '[masses]\nAB = { mass = "5 kg" }\n[gravity]\n'
    assert main(["sweep", "--summary", "--steps", "8", _scene(tmp_path, text)]) == 0
    head = capsys.readouterr().out.splitlines()[1]
    assert "at rest, the motion per 1 m/s to the left (virtual)" in head, head
    assert "start from rest with 5 m/s^2 to the left" in head, head


# ------------------------------------------ an integer past what str() converts


@pytest.mark.parametrize("reader", ["compiled", "tomllib"])
@pytest.mark.parametrize("where", ["scene", "answers"])
def test_an_integer_of_thousands_of_digits_is_one_line(
    tmp_path, capsys, monkeypatch, reader, where
):
    """``AB = 111...1`` (100,000 digits): str() of it raised ValueError past 4300 digits
    (exit 3, "internal error")."""
    from polygon_method.scene import source

    if reader == "tomllib":
        monkeypatch.setattr(source, "_fast_toml", None)
    digits = "1" * 100000
    if where == "scene":
        argv = ["solve", _scene(tmp_path, FOURBAR.replace("AB = 50", f"AB = {digits}"))]
    else:
        answers = _scene(tmp_path, f"[answers]\nv_C = {digits}\n", "a.toml")
        argv = ["check", str(ROOT / SEED), answers]
    assert main(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "100000 digits" in err[0], err
    assert ("line 5" if where == "scene" else "line 2") in err[0], err


# ------------------------------------------------ /dev/stdout when it is a pipe


@pytest.mark.skipif(not Path("/dev/stdout").exists(), reason="no /dev/stdout on this system")
def test_a_csv_to_dev_stdout_into_a_pipe_is_written(tmp_path):
    """``sweep --csv /dev/stdout | head``: the link resolves to /proc/self/fd/1 and on to
    "pipe:[208160]", a name no file has: "cannot write /dev/stdout: No such file or
    directory". It is the command's own standard output: written as ``--csv -`` is."""
    import subprocess
    import sys

    done = subprocess.run(
        [
            sys.executable,
            "-m",
            "polygon_method",
            "sweep",
            SEED,
            "--steps",
            "4",
            "--csv",
            "/dev/stdout",
        ],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    rows = done.stdout.splitlines()  # the CSV alone: the words go to stderr, as with -
    assert rows[0].startswith("theta [deg],"), rows[:1]
    # the seed's crank reaches -103.79 to 103.79 deg (BC + CD = BD there): 0, 90, 270
    assert [float(r.split(",")[0]) for r in rows[1:]] == [0.0, 90.0, 270.0]
    assert "3 of 4 crank angles" in done.stderr


def test_a_class_gives_one_column_to_one_quantity_under_either_name(tmp_path, capsys):
    """One student writes omega_BC, another omega_CB: the gradebook had two columns, and
    "most often wrong" counted them apart."""
    answers = tmp_path / "answers"
    answers.mkdir()
    (answers / "ann.toml").write_text('[answers]\nomega_BC = "5.15 rad/s ccw"\n')
    (answers / "bob.toml").write_text('[answers]\nomega_CB = "7.15 rad/s ccw"\n')  # CD's
    (answers / "cat.toml").write_text('[answers]\nomega_CB = "2 rad/s ccw"\n')
    book = tmp_path / "book.csv"
    assert main(["check", str(ROOT / SEED), str(answers), "--gradebook", str(book)]) == 0
    out = capsys.readouterr().out
    assert "omega_BC: 2 of 3 students" in out and "omega_CB:" not in out
    head, *rows = book.read_text().splitlines()
    assert head.split(",")[2:4] == ["omega_BC", "right"]
    assert [r.split(",")[2].split(" ")[0] for r in rows] == ["right", "WRONG", "WRONG"]


def test_a_negative_pin_speed_with_a_sense_is_worded_as_a_pin_speed(tmp_path, capsys):
    """``speed = "-3 m/s cw"``: "'m/s' is a unit of velocity, not of angular velocity",
    though "3 m/s cw" (the pin's speed) is read."""
    text = FOURBAR.replace('"10.5 rad/s cw"', '"-3 m/s cw"')
    assert main(["solve", _scene(tmp_path, text)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "reads two ways" in err[0] and '"3 m/s cw"' in err[0], err


def test_two_fixed_pivots_at_one_place_are_warned_of(tmp_path, capsys):
    """``D = [0, 0]`` beside ``A = [0, 0]``: the four-bar is a rigid triangle ABC turning
    about A (every link at the crank's omega, as a rigid body must), solved silently."""
    text = FOURBAR.replace("D = [100, 0]", "D = [0, 0]")
    assert main(["solve", "--json", _scene(tmp_path, text)]) == 0
    record = json.loads(capsys.readouterr().out)
    assert [w for w in record["warnings"] if "fixed pivots A and D are at one place" in w]
    assert all(record["links"][k]["omega"] == pytest.approx(-10.5) for k in ("AB", "BC", "CD"))


def test_the_scene_given_as_its_own_answer_file_is_named_a_scene(capsys):
    """``check SCENE SCENE``: "units: an answer file holds an [answers] table ... (did you
    mean 'notes'?)"; ``--gradebook x.txt`` said "--gradebook: --gradebook x.txt: ..."."""
    scene = str(ROOT / SEED)
    assert main(["check", scene, scene]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "this is a scene (it has [ground]), not an answer file" in err[0]
    assert main(["check", scene, scene, "--gradebook", "marks.txt"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].count("--gradebook") == 1, err


def test_the_centres_of_a_crank_at_rest_say_the_velocities_are_virtual(tmp_path, capsys):
    """``centres`` of a scene at rest wrote "omega_2 (O2-A) = 1 rad/s ccw (the input)", as
    if the crank turned at 1 rad/s: the velocities are the virtual ones, per rad/s."""
    text = (ROOT / "worked_problems/fourbar_forces.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^speed = .*$", "speed = 0", text.split("[answers]")[0])
    assert main(["centres", _scene(tmp_path, text)]) == 0
    line = next(s for s in capsys.readouterr().out.splitlines() if "omega_2 (O2-A)" in s)
    assert "at rest" in line and "virtual" in line, line


def _trammel_at_rest(tmp_path, start=True):
    text = (ROOT / "worked_problems/ellipse_trammel.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^vs_A = .*$", "vs_A = 0", text.split("[answers]")[0])
    if not start:
        text = re.sub(r"(?m)^as_A = .*$", "", text)
    return _scene(tmp_path, text + '[masses]\nAB = { mass = "5 kg" }\n[gravity]\n')


@pytest.mark.parametrize("start", [True, False])
def test_a_block_at_rest_is_said_at_rest_in_the_problem_and_under_the_drawings(tmp_path, start):
    """The problem's words (the page's "Given") said the block was "moving at 1 m/s to the
    left, steadily", and the drawings' caption "1 m/s to the left": at rest, that is the
    virtual speed the polygons are drawn for."""
    from polygon_method import solve
    from polygon_method.draw.diagrams import _drive
    from polygon_method.scene import load_scene
    from polygon_method.text.words import given

    scene = load_scene(_trammel_at_rest(tmp_path, start))
    words = next(g for g in given(scene) if "drives the mechanism" in g)
    assert "at rest, about to move to the" in words and "moving at" not in words, words
    assert ("acceleration of 5 m/s² to the left" in words) is start, words
    assert "at rest: the polygons per this speed (virtual)" in _drive(solve(scene))


def test_the_step_table_of_a_block_at_rest_gives_no_speed_as_given(tmp_path, capsys):
    """steps: "vs_A = 1 m/s to the left along the guide (given)" for a block at rest."""
    assert main(["steps", _trammel_at_rest(tmp_path)]) == 0
    out = capsys.readouterr().out
    section = out.split("2. Input block A", 1)[1].split("3. ", 1)[0]
    assert "(given)" not in section and "at rest (nothing moves yet)" in section, section
    assert "as_A = 0 in the polygons" in section and "steady speed" not in section, section
    assert "the start's as_A is taken in section 6" in " ".join(section.split()), section


def test_the_step_table_of_a_wheel_at_rest_gives_no_speed_as_given(tmp_path, capsys):
    """steps: "omega_CA = 1 rad/s ccw (given)" and "alpha_CA = 0 (the wheel rolls at a
    steady speed)" for a wheel at rest, starting at 2 rad/s^2 ccw."""
    text = (ROOT / "worked_problems/rolling_wheel_driver.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?m)^omega_CA = .*$", 'omega_CA = "0 rad/s"', text.split("[answers]")[0])
    text += '[masses]\nCA = { mass = "5 kg" }\n[gravity]\n'
    assert main(["steps", _scene(tmp_path, text)]) == 0
    section = capsys.readouterr().out.split("2. Input wheel CA", 1)[1].split("3. ", 1)[0]
    assert "(given)" not in section and "at rest (nothing moves yet)" in section, section
    assert "alpha_CA = 0 in the polygons" in section and "steady speed" not in section, section
