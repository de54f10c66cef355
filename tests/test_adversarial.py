"""An adversarial user of page, draw --animate, variants and check --variants: what once
crashed, lost a file or gave a silently wrong result, each kept as a test of its kind.

The expected values never come from the code under test: a student's answers are those of
the variant file they were written for (solved on its own), lengths and positions are
read back from the files written, counts are counted here."""

from __future__ import annotations

import csv
import tomllib

import pytest

from polygon_method import load_scene, parse_scene, solve
from polygon_method.cli import main
from polygon_method.common.errors import PolygonMethodError

FOURBAR = """
title = "Four-bar for a class"
units = "mm"

[ground]
A = [0, 0]
D = [100, 0]

[links]
AB = 30
BC = 90
CD = 70

[assembly]
C = "above"

[input]
crank = "AB"
angle = 60
speed = "120 rpm cw"

[answers]
v_C = "0.3 m/s"
omega_BC = "3 rad/s"

[variants]
BC = { from = 80, to = 100, step = 1 }
angle = { from = 30, to = 90, step = 10 }
"""


def _err_line(capsys):
    err = capsys.readouterr().err
    lines = [x for x in err.splitlines() if not x.startswith("warning:")]
    assert len(lines) == 1, err
    return lines[0]


def _answers_for(variant_file, named):
    """A student's right answers to the variant in ``variant_file`` (solved on its own)."""
    sol = solve(load_scene(variant_file))
    return (
        f"variant = {named}\n[answers]\n"
        f'v_C = "{sol.speed("C"):.6f} m/s"\n'
        f'omega_BC = "{abs(sol.omega("BC")):.6f} rad/s"\n'
    )


@pytest.fixture
def klass(tmp_path):
    base = tmp_path / "base.toml"
    base.write_text(FOURBAR)
    out = tmp_path / "class"
    assert main(["variants", str(base), "--count", "4", "--seed", "3", "-o", str(out)]) == 0
    answers = tmp_path / "answers"
    answers.mkdir()
    return base, out, answers


def _book(tmp_path, base, answers, out, capsys):
    book = tmp_path / "book.csv"
    assert (
        main(["check", str(base), str(answers), "--variants", str(out), "--gradebook", str(book)])
        == 0
    )
    capsys.readouterr()
    return {r["student"]: r for r in csv.DictReader(book.open())}


def test_a_student_is_graded_against_the_variant_whose_id_they_name(tmp_path, klass, capsys):
    """A renamed variant file is still found by its id; a copy of another variant under
    the name "03.toml" never pairs a student with the wrong variant."""
    base, out, answers = klass
    (out / "variant-02.toml").rename(out / "bobs-problem.toml")
    (answers / "bob.toml").write_text(_answers_for(out / "bobs-problem.toml", '"02"'))
    (out / "03.toml").write_text((out / "variant-04.toml").read_text())  # a stray copy
    (answers / "cy.toml").write_text(_answers_for(out / "variant-03.toml", '"3"'))
    (answers / "dee.toml").write_text(_answers_for(out / "variant-04.toml", "4"))
    (answers / "eve.toml").write_text(_answers_for(out / "variant-01.toml", '"variant-01"'))
    graded = _book(tmp_path, base, answers, out, capsys)
    assert graded["bob"]["variant"] == "02" and graded["bob"]["right"] == "2"
    assert graded["cy"]["variant"] == "03" and graded["cy"]["right"] == "2"
    # 04 is in two files now: an error on that row, never a guess
    assert "is in 2 files" in graded["dee"]["error"] and graded["dee"]["right"] == ""
    assert graded["eve"]["right"] == "2"


@pytest.mark.parametrize(
    "named",
    [
        '"²"',
        '"٣"',
        '"0\\u001b3"',
        '"../x"',
        "-3",
        '"variant"',
        '"answer-key"',
        "99999999999999999999",
    ],
)
def test_an_odd_variant_name_is_that_students_row_never_a_crash(tmp_path, klass, capsys, named):
    base, out, answers = klass
    (answers / "ann.toml").write_text(_answers_for(out / "variant-03.toml", named))
    (answers / "zed.toml").write_text(_answers_for(out / "variant-01.toml", '"01"'))
    graded = _book(tmp_path, base, answers, out, capsys)
    if named == '"٣"':  # an Arabic-Indic three is the number 3
        assert graded["ann"]["right"] == "2"
    else:
        assert graded["ann"]["error"] and "\n" not in graded["ann"]["error"]
    assert graded["zed"]["right"] == "2"


def test_junk_in_the_variants_directory_is_named_not_fatal(tmp_path, klass, capsys):
    base, out, answers = klass
    (out / "notes.toml").write_text("this = = is not TOML")
    (answers / "ann.toml").write_text(_answers_for(out / "variant-01.toml", '"notes"'))
    (answers / "bob.toml").write_text(_answers_for(out / "variant-02.toml", '"2"'))
    graded = _book(tmp_path, base, answers, out, capsys)
    assert "notes.toml" in graded["ann"]["error"] and "cannot be read" in graded["ann"]["error"]
    assert graded["bob"]["right"] == "2"


def test_the_gradebook_is_never_written_over_a_file_the_command_reads(tmp_path, klass, capsys):
    base, out, answers = klass
    ann = answers / "ann.csv"  # an answer file may have any name
    ann.write_text(_answers_for(out / "variant-01.toml", '"01"'))
    bob = answers / "bob.toml"
    bob.write_text(_answers_for(out / "variant-02.toml", '"02"'))
    before = ann.read_bytes()
    assert (
        main(
            [
                "check",
                str(base),
                str(ann),
                str(bob),
                "--variants",
                str(out),
                "--gradebook",
                str(ann),
            ]
        )
        == 2
    )
    assert "which this command reads" in _err_line(capsys)
    assert ann.read_bytes() == before
    link = tmp_path / "key.md"
    link.symlink_to(bob)
    assert (
        main(
            [
                "check",
                str(base),
                str(ann),
                str(bob),
                "--variants",
                str(out),
                "--gradebook",
                str(link),
            ]
        )
        == 2
    )
    _err_line(capsys)
    assert bob.read_text().startswith("variant = ")


def test_a_student_file_name_with_a_line_break_stays_one_row(tmp_path, klass, capsys):
    base, out, answers = klass
    (answers / "new\nline.toml").write_text(_answers_for(out / "variant-01.toml", '"01"'))
    (answers / "bob.toml").write_text(_answers_for(out / "variant-02.toml", '"02"'))
    book = tmp_path / "book.md"
    assert (
        main(["check", str(base), str(answers), "--variants", str(out), "--gradebook", str(book)])
        == 0
    )
    printed = capsys.readouterr().out
    rows = [x for x in book.read_text().splitlines() if x.startswith("|")]
    assert len(rows) == 2 + 2  # the head, its rule and one row per student
    assert any(x.startswith("new\\nline ") for x in printed.splitlines())


SLIDER = """
title = "Slider crank on an inclined path"
units = "mm"

[ground]
O = [0, 0]

[links]
OA = 40
AB = 160

[sliders]
B = { path = "20 deg" }

[assembly]
B = "right"

[input]
crank = "OA"
angle = 60
speed = "100 rpm ccw"

[pins]
A = { radius = 10 }
"""


def test_every_varied_value_is_in_the_file_written(tmp_path, capsys):
    """x and y of a path that passes through the crank's pivot (no `through` written):
    each variant's file holds the pair its sheet names, and the four pairs are the four
    combinations of the lists (one key's setting once undid the other's value)."""
    base = tmp_path / "base.toml"
    base.write_text(SLIDER + "\n[variants]\nB = { x = [0, 5], y = [-10, 10] }\n")
    out = tmp_path / "class"
    assert main(["variants", str(base), "--count", "4", "-o", str(out)]) == 0
    pairs = set()
    for k in range(1, 5):
        text = (out / f"variant-{k:02d}.toml").read_text()
        through = tuple(tomllib.loads(text)["sliders"]["B"]["through"])
        header = text.splitlines()[0]  # "... x of the path of slider B 5 mm, y of ... -10 mm"
        x = float(header.split("x of the path of slider B ")[1].split()[0])
        y = float(header.split("y of the path of slider B ")[1].split()[0])
        assert through == (x, y)
        pairs.add(through)
    assert pairs == {(0, -10), (0, 10), (5, -10), (5, 10)}


@pytest.mark.parametrize(
    "table, words",
    [
        ("BC = [80, 85]\nCB = [90]", "BC and CB both vary link BC"),
        ("A = { radius = [5, 6], diameter = [14] }", "both vary pin A"),
    ],
)
def test_two_keys_for_one_quantity_are_refused(table, words):
    text = FOURBAR.split("[variants]")[0] + "[pins]\nA = { radius = 5 }\n[variants]\n" + table
    with pytest.raises(PolygonMethodError, match=words):
        parse_scene(text)


def test_moving_a_path_along_itself_is_refused():
    """x of a horizontal path (y of a vertical one) changes no mechanism: every variant
    would be the same problem under other numbers."""
    text = SLIDER.replace('"20 deg"', '"horizontal"')
    with pytest.raises(PolygonMethodError, match="changes nothing"):
        parse_scene(text + "\n[variants]\nB = { x = [0, 5] }\n")
    parse_scene(text + "\n[variants]\nB = { y = [0, 5] }\n")  # across the path: a variant
    with pytest.raises(PolygonMethodError, match="changes nothing"):
        parse_scene(
            text.replace('"horizontal"', '"vertical"') + "\n[variants]\nB = { y = [0, 5] }\n"
        )


SEED = "worked_problems/fourbar_image_points.toml"


@pytest.mark.parametrize("n", [0, 1, -1, 2.5, "10", True, None, float("nan"), 3601, 10**9])
def test_frames_through_the_api_are_a_whole_number_in_range(n):
    from polygon_method.page import frames

    with pytest.raises(PolygonMethodError, match="--frames"):
        frames(load_scene(SEED), n)


def test_an_animation_is_of_a_format_it_knows_and_a_size_it_can_hold():
    from polygon_method.page import MAX_PICTURE_FRAMES, animation, frames

    fr = frames(load_scene(SEED), 4)
    for fmt in ("png", "SVG", None, "gif "):
        with pytest.raises(PolygonMethodError, match="cannot animate"):
            animation(fr, fmt)
    big = frames(load_scene(SEED), MAX_PICTURE_FRAMES + 1)
    assert animation(big, "svg").count("<animate ") > 0  # vector: fine
    for fmt in ("gif", "html"):
        with pytest.raises(PolygonMethodError, match="--frames"):
            animation(big, fmt)


def test_an_animation_never_holds_fewer_frames_than_it_says():
    """The HTML player holds every frame it states (matplotlib's player once dropped the
    frames beyond its size limit with no more than a log line)."""
    import json
    import re
    from polygon_method.page import animation, frames

    fr = frames(load_scene(SEED), 6)
    html = animation(fr, "html")
    data = json.loads(
        re.search(r'<script type="application/json" id="frames">(.*?)</script>', html, re.S).group(
            1
        )
    )
    assert len(data["pictures"]) == len(data["angles"]) == 6
    assert all(p.startswith("data:image/png;base64,") for p in data["pictures"])


@pytest.mark.parametrize("ext", ["gif", "html"])
def test_too_many_picture_frames_is_one_line_before_anything_is_computed(tmp_path, capsys, ext):
    from polygon_method.page import MAX_PICTURE_FRAMES

    out = tmp_path / f"cycle.{ext}"
    out.write_text("keep me")
    assert (
        main(["draw", SEED, "--animate", "-o", str(out), "--frames", str(MAX_PICTURE_FRAMES + 1)])
        == 2
    )
    assert f"from 2 to {MAX_PICTURE_FRAMES}" in _err_line(capsys)
    assert out.read_text() == "keep me"


@pytest.mark.parametrize(
    "count, seed, words",
    [
        (0, 0, "--count 0"),
        (-1, 0, "--count -1"),
        (2.5, 0, "--count 2.5"),
        ("3", 0, "--count"),
        (10**6, 0, "to 9999"),
        (3, -1, "--seed -1"),
        (3, 1.5, "--seed 1.5"),
        (3, None, "--seed None"),
        (True, 0, "--count True"),
    ],
)
def test_generate_through_the_api_refuses_odd_counts_and_seeds(count, seed, words):
    from polygon_method.variants import generate

    with pytest.raises(PolygonMethodError, match=words.replace("+", r"\+")):
        generate(parse_scene(FOURBAR), count, seed)


def test_no_good_variant_at_all_asks_for_no_count_of_zero(tmp_path, capsys):
    base = tmp_path / "base.toml"
    base.write_text(FOURBAR.split("[variants]")[0] + "[variants]\nBC = [300, 301]\n")
    assert main(["variants", str(base), "--count", "2", "-o", str(tmp_path / "o")]) == 2
    line = _err_line(capsys)
    assert "only 0 of the 2" in line and "--count 0" not in line
    assert not (tmp_path / "o").exists()


def test_a_long_problem_goes_on_over_the_page_of_the_pdf_sheet():
    """A problem longer than a page (many points, every point's speed and acceleration
    asked): every line of it is on a page, none below the page's foot."""
    from polygon_method.variants import generate
    from polygon_method.variants.papers import sheet_pages, sheet_sections

    names = "EFGHIJKLMNOPQRSTUVW"
    pts = "".join(f'{p} = {{ on = "BC", along = {5 + 4 * k} }}\n' for k, p in enumerate(names))
    text = FOURBAR.split("[answers]")[0].replace("[assembly]", f"[points]\n{pts}\n[assembly]")
    # (three angles: one of them may be the base problem, which is no variant)
    vs = generate(parse_scene(text + "[variants]\nangle = [50, 55, 60]\n"), 2, 0)
    wanted = [x.replace("`", "") for _, lines in sheet_sections(vs) for x in lines if x]
    assert len(wanted) > 2 * 45  # more than a page each
    shown, pages = [], 0
    for fig in sheet_pages(vs):
        pages += 1
        for t in fig.texts:
            assert t.get_position()[1] >= 0.03, t.get_text()
            shown.append(t.get_text())
    assert pages > 2
    joined = " ".join(shown)
    for line in wanted:  # each line (wrapped at 90 characters) is there
        assert all(word in joined for word in line.split()[:3]), line


def test_a_class_as_json_with_an_error_against_a_right_value_of_zero(tmp_path, capsys):
    """v_A of a ground point and alpha of a crank at constant speed are 0: a wrong answer
    is an infinite per cent off, written as null (it was an internal error)."""
    import json

    base = tmp_path / "base.toml"
    base.write_text(FOURBAR)
    answers = tmp_path / "answers"
    answers.mkdir()
    (answers / "ann.toml").write_text('[answers]\nv_A = "0.1 m/s"\nalpha_AB = "1 rad/s^2 cw"\n')
    (answers / "bob.toml").write_text('[answers]\nv_A = "0 m/s"\n')
    assert main(["check", str(base), str(answers), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    ann = next(s for s in d["students"] if s["student"] == "ann")
    assert [a["error_percent"] for a in ann["answers"]] == [None, None]
    assert main(["check", str(base), str(answers / "ann.toml"), "--json"]) == 1
    assert json.loads(capsys.readouterr().out)["right"] == 0


def test_the_page_checks_a_variants_answers_against_that_variant_only(tmp_path, klass, capsys):
    base, out, answers = klass
    ann = answers / "ann.toml"
    ann.write_text(_answers_for(out / "variant-03.toml", '"03"'))
    page = tmp_path / "page.html"
    for scene in (base, out / "variant-04.toml"):
        assert main(["page", str(scene), "-o", str(page), "--answers", str(ann)]) == 2
        assert "names variant '03'" in _err_line(capsys)
        assert not page.exists()
    assert main(["page", str(out / "variant-03.toml"), "-o", str(page), "--answers", str(ann)]) == 0
    assert page.exists()


def test_crank_angles_a_turn_apart_are_one_problem():
    """0, 360 and -360 deg (and 30 and 390) put the mechanism in one position: two
    students given them would have the same problem under other numbers."""
    text = FOURBAR.split("[variants]")[0]
    sc = parse_scene(
        text + '[variants]\nangle = [0, 360, -360, 30, 390, "6.283185307179586 rad"]\n'
    )
    (angle,) = sc.variation.varied
    assert len(angle) == 2
    sc = parse_scene(text + "[variants]\nangle = { from = -720, to = 720, step = 90 }\n")
    assert len(sc.variation.varied[0]) == 4


@pytest.mark.parametrize(
    "argv, option",
    [
        (["--frames", "10"], "--frames"),
        (["--centre-labels", "13"], "--centre-labels"),
        (["--diagram", "velocity", "--centre-labels", "I13"], "--centre-labels"),
        (["--animate", "--centre-labels", "13"], "--animate"),
    ],
)
def test_a_draw_option_that_would_do_nothing_is_refused(tmp_path, capsys, argv, option):
    out = tmp_path / "d.svg"
    assert main(["draw", SEED, "-o", str(out), *argv]) == 2
    assert f": {option}: " in _err_line(capsys)
    assert not out.exists()


def test_a_gradebook_cell_never_starts_a_spreadsheet_formula(tmp_path, klass, capsys):
    base, out, answers = klass
    for name in ("=HYPERLINK(1)", "+1", "@SUM(A1)", "-2", "ann"):
        (answers / f"{name}.toml").write_text(_answers_for(out / "variant-01.toml", '"01"'))
    book = tmp_path / "book.csv"
    assert (
        main(["check", str(base), str(answers), "--variants", str(out), "--gradebook", str(book)])
        == 0
    )
    capsys.readouterr()
    for row in list(csv.reader(book.open()))[1:]:
        assert all(not c or c[0] not in "=+-@" for c in row), row
    names = [r["student"] for r in csv.DictReader(book.open())]
    assert sorted(names) == sorted(["'=HYPERLINK(1)", "'+1", "'@SUM(A1)", "'-2", "ann"])


def test_the_page_is_never_written_over_its_answer_file(tmp_path, capsys):
    ans = tmp_path / "answers.html"  # an answer file may have any name
    ans.write_text('[answers]\nv_C = "0.4 m/s"\n')
    assert main(["page", SEED, "-o", str(ans), "--answers", str(ans)]) == 2
    assert "which this command reads" in _err_line(capsys)
    assert ans.read_text() == '[answers]\nv_C = "0.4 m/s"\n'


def test_the_views_api_refuses_what_is_not_theirs_with_an_error_of_the_family():
    from polygon_method.page import animation, page_html
    from polygon_method.variants import generate

    sc = load_scene(SEED)
    for bad in (sc, solve(sc), None, "page.html"):
        with pytest.raises(PolygonMethodError, match="frames of a scene are needed"):
            page_html(bad)
        with pytest.raises(PolygonMethodError, match="frames of a scene are needed"):
            animation(bad, "svg")
    with pytest.raises(PolygonMethodError, match="a Scene is needed"):
        generate(SEED, 3, 0)


from hypothesis import given, settings, strategies as st  # noqa: E402


@settings(max_examples=300, deadline=None)
@given(st.text(), st.text(), st.text(min_size=1))
def test_a_variants_file_reads_back_whatever_its_strings_hold(title, header, key):
    """Any title, header or key (control characters, DEL, line separators, quotes,
    backslashes): the TOML written reads back to the same table."""
    from polygon_method.variants import dump_toml

    raw = {"title": title, "units": "mm", "points": {key: {"on": title, "along": 1.5}}}
    assert tomllib.loads(dump_toml(raw, header)) == raw


def test_a_title_with_control_characters_still_gives_variants(tmp_path, capsys):
    base = tmp_path / "base.toml"
    base.write_text(
        FOURBAR.replace(
            'title = "Four-bar for a class"', 'title = "Four-bar\\u001b\\u007f\\u2028 for a class"'
        )
    )
    out = tmp_path / "class"
    assert main(["variants", str(base), "--count", "3", "-o", str(out)]) == 0
    for k in (1, 2, 3):
        title = tomllib.loads((out / f"variant-0{k}.toml").read_text())["title"]
        assert title.startswith("Four-bar\x1b\x7f\u2028 for a class")


@pytest.mark.parametrize("brk", ["\u2028", "\x85", "\u2029"])
def test_a_line_break_that_toml_does_not_count_moves_no_line_number(brk):
    """U+2028, U+2029 or NEL in a comment is no new line for TOML: the message names the
    key's line as an editor numbers it (line feeds only)."""
    text = FOURBAR.split("[variants]")[0].replace("[links]", f"# a{brk}comment\n[links]")
    text = text.replace("BC = 90", "BC = -90")
    n = text.split("\n").index("BC = -90") + 1
    with pytest.raises(PolygonMethodError) as e:
        parse_scene(text)
    assert e.value.line == n


def test_no_frame_is_shown_twice_when_the_instant_is_on_the_grid():
    """The seed four-bar at 0 deg: its limits are symmetric about 0, so an odd grid between
    them holds 0 already; the frames still run one way, n of them, the instant among them."""
    import numpy as np
    from polygon_method.page import frames

    text = open(SEED).read().replace("angle = 60", "angle = 0", 1)
    sc = parse_scene(text)
    for n in (2, 3, 4, 5, 24, 25, 50, 51):
        fr = frames(sc, n)
        d = fr.degrees
        assert len(fr) == n
        assert np.all(np.diff(d) > 0) or np.all(np.diff(d) < 0), d
        assert d[fr.start] == 0.0


def test_a_list_of_values_is_bounded_as_a_range_is():
    from polygon_method.scene.variation import MAX_VALUES

    values = ", ".join(str(80 + k * 1e-4) for k in range(MAX_VALUES + 1))
    with pytest.raises(PolygonMethodError, match=f"more than {MAX_VALUES}"):
        parse_scene(FOURBAR.split("[variants]")[0] + f"[variants]\nBC = [{values}]\n")


def test_the_page_grades_an_answer_file_as_check_does(tmp_path, capsys):
    """The scene states tolerance = "3%", the book's: an answer file with none is graded by
    `check` at the default (a hand drawing's tolerance, saying so), and so on the page."""
    import json
    import re

    v_c = solve(load_scene(SEED)).speed("C")
    ans = tmp_path / "ann.toml"
    ans.write_text(f'[answers]\nv_C = "{v_c * 0.971:.6f} m/s"\n')  # 2.9 % low
    assert main(["check", SEED, str(ans), "--json"]) == 0
    got = json.loads(capsys.readouterr().out)
    assert got["tolerance_used"]["source"] == "default"
    verdict = got["answers"][0]
    assert "hand drawing" in verdict["rule"]
    page = tmp_path / "p.html"
    assert main(["page", SEED, "-o", str(page), "--answers", str(ans), "--frames", "4"]) == 0
    capsys.readouterr()
    table = re.search(r'<table id="check">.*?</table>', page.read_text(), re.S).group(0)
    assert "right" in table and "WRONG" not in table
    assert f"{verdict['tolerance_percent']:.2g}\u00a0%" in table  # (a no-break space)


def test_a_pipe_in_a_listed_directory_is_a_row_never_a_wait(tmp_path, klass):
    """A named pipe among the answer files or the variant scenes would be waited on for
    ever if opened: it is named as not read, and the class is graded."""
    import os
    import subprocess
    import sys

    base, out, answers = klass
    (answers / "ann.toml").write_text(_answers_for(out / "variant-01.toml", '"01"'))
    os.mkfifo(answers / "pipe.toml")
    os.mkfifo(out / "zz.toml")
    book = tmp_path / "book.csv"
    run = subprocess.run(
        [
            sys.executable,
            "-m",
            "polygon_method",
            "check",
            str(base),
            str(answers),
            "--variants",
            str(out),
            "--gradebook",
            str(book),
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert run.returncode == 0, run.stderr
    graded = {r["student"]: r for r in csv.DictReader(book.open())}
    assert graded["ann"]["right"] == "2"
    assert "not a regular file" in graded["pipe"]["error"]


def test_a_link_to_a_variant_is_the_same_variant_not_a_copy(tmp_path, klass, capsys):
    base, out, answers = klass
    (out / "latest.toml").symlink_to(out / "variant-02.toml")
    (answers / "bob.toml").write_text(_answers_for(out / "variant-02.toml", '"02"'))
    graded = _book(tmp_path, base, answers, out, capsys)
    assert graded["bob"]["right"] == "2", graded["bob"]["error"]
