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
