"""More of what an adversarial user gives every command: what once crashed (exit 3), named
no file, or answered silently wrong, each kept as a test of its kind.

Expected values come from the inputs themselves (a number the user wrote, a link that
cannot move, a count of lines), never from the code under test."""

from __future__ import annotations

import pytest

from polygon_method import load_scene, parse_scene, solve
from polygon_method.cli import main
from polygon_method.common.errors import PolygonMethodError, SceneError

from scenes import FOURBAR


def _one_line(capsys):
    captured = capsys.readouterr()
    lines = [x for x in captured.err.splitlines() if not x.startswith("warning:")]
    assert len(lines) == 1, captured.err
    assert not captured.out.strip(), captured.out
    return lines[0]


def _scene(tmp_path, text, name="s.toml"):
    path = tmp_path / name
    path.write_text(text)
    return str(path)


# ----------------------------------------------------------------- TOML's own edges


@pytest.mark.parametrize(
    "old, new, where",
    [
        ("BC = 66", "BC = " + "9" * 400, "[links] BC (line 6)"),
        ("angle = 60", "angle = -" + "1" * 30, "[input] angle (line 10)"),
        ("D = [100, 0]", "D = [100, " + "7" * 25 + "]", "[ground] D (line 3)"),
    ],
)
@pytest.mark.parametrize("command", ["solve", "sweep", "linkage"])
def test_an_integer_beyond_64_bits_is_one_line_not_an_overflow(
    tmp_path, capsys, old, new, where, command
):
    """TOML's integers are 64-bit; tomllib reads longer ones, which no float holds (it was
    an internal error, exit 3)."""
    path = _scene(tmp_path, FOURBAR.replace(old, new))
    assert main([command, path]) == 2
    line = _one_line(capsys)
    assert where in line and "64-bit" in line and "s.toml" in line


def test_a_long_integer_in_an_answer_file_or_a_variants_range_is_named(tmp_path, capsys):
    from polygon_method.scene import parse_answers

    sc = parse_scene(FOURBAR)
    with pytest.raises(SceneError, match="64-bit") as err:
        parse_answers("[answers]\nv_C = 1" + "0" * 30 + "\n", sc, file="ann.toml")
    assert "[answers] v_C (line 2)" in err.value.one_line()
    with pytest.raises(SceneError, match="64-bit") as err:
        parse_scene(FOURBAR + "[variants]\nBC = { from = 60, to = 1" + "0" * 40 + ", step = 1 }\n")
    assert "[variants] BC" in err.value.one_line()
    parse_scene(
        FOURBAR.replace("angle = 60", f"angle = {2**63 - 1}".replace(str(2**63 - 1), "60"))
    )  # an ordinary integer is still an integer


def test_parse_quantity_refuses_a_huge_integer_in_its_own_words():
    from polygon_method.common.units import parse_quantity

    with pytest.raises(SceneError, match="absurd"):
        parse_quantity(10**400, "length", default_unit="mm")


# ----------------------------------------------------------------- senses


@pytest.mark.parametrize(
    "key, value",
    [
        ("speed", "-10 rad/s cw"),
        ("speed", "-100 rpm ccw"),
        ("acceleration", "-5 rad/s^2 ccw"),
    ],
)
def test_a_negative_value_with_a_sense_is_refused_not_turned_round(key, value):
    """ "-10 rad/s cw" was taken as 10 rad/s ccw (minus clockwise): it reads two ways."""
    text = (
        FOURBAR.replace('speed = "10.5 rad/s cw"', f'speed = "10.5 rad/s cw"\n{key} = "{value}"')
        if key == "acceleration"
        else FOURBAR.replace('"10.5 rad/s cw"', f'"{value}"')
    )
    with pytest.raises(SceneError, match="reads two ways") as err:
        parse_scene(text)
    size = value.lstrip("-").rsplit(" ", 1)[0]
    assert f'"{size} cw"' in err.value.one_line()


def test_a_negative_speed_without_a_sense_is_shown_its_size_not_a_negative_example():
    with pytest.raises(SceneError) as err:
        parse_scene(FOURBAR.replace('"10.5 rad/s cw"', '"-10 rad/s"'))
    assert 'e.g. "10 rad/s ccw"' in err.value.one_line()


def test_a_negative_torque_answer_with_a_sense_is_refused_by_name():
    from polygon_method.scene import parse_answers

    sc = parse_scene(FOURBAR + '[loads]\nC = { force = "100 N", direction = 0 }\n')
    with pytest.raises(SceneError, match="reads two ways") as err:
        parse_answers('[answers]\ntorque = "-3 N m cw"\n', sc, file="a.toml")
    assert "[answers] torque (line 2)" in err.value.one_line()


# ----------------------------------------------------------------- a structure in the scene

STRUCTURE = FOURBAR.replace("D = [100, 0]", "D = [100, 0]\nE = [200, 0]\nG = [250, 0]").replace(
    "CD = 56", "CD = 56\nEF = 30\nFG = 30"
)


def test_links_that_never_move_are_swept_and_analysed():
    """EF and FG join two ground points: F is a fixed point placed by two links (a
    structure). The cycle's arrays met a step whose inputs are all fixed numbers (an
    internal error in sweep, linkage, page); now F stands still at its place, and the
    linkage's output is the four-bar's CD, never the standing FG."""
    import math

    import numpy as np

    from polygon_method import sweep
    from polygon_method.linkage import analyse

    sc = parse_scene(STRUCTURE)
    sw = sweep(sc, np.radians(np.arange(-90.0, 91.0, 15.0)))
    fx, fy = 225.0e-3, math.sqrt(30.0**2 - 25.0**2) * 1e-3  # the triangle E, F, G by hand
    assert np.all(np.abs(sw.P["F"][0] - fx) <= 1e-15)
    assert np.all(np.abs(sw.P["F"][1] - fy) <= 1e-15)
    assert np.all(sw.V["F"][0] == 0) and np.all(sw.V["F"][1] == 0)
    lk = analyse(sc)
    assert lk.output_label == "output link CD"
    assert [t.point for t in lk.transmission] == ["C"]  # F's never changes: not reported


@pytest.mark.parametrize("argv", [["sweep", "--steps", "8"], ["linkage"], ["steps"]])
def test_every_command_takes_a_scene_with_a_structure(tmp_path, capsys, argv):
    path = _scene(tmp_path, STRUCTURE)
    assert main([argv[0], path, *argv[1:]]) == 0, capsys.readouterr().err


def test_centres_that_cannot_be_located_name_the_scene_file(tmp_path, capsys):
    """EF and FG never move: their centres with a moving link are nowhere. The refusal
    named the step ("centres") but no file."""
    path = _scene(tmp_path, STRUCTURE)
    assert main(["centres", path]) == 2
    line = _one_line(capsys)
    assert line.startswith(f"polygon-method centres: {path}: centres: Kennedy's theorem")


# ----------------------------------------------------------------- answers


def test_an_answer_naming_a_centre_the_mechanism_has_not_names_its_file(tmp_path, capsys):
    """I_19 of a four-link chain: the message named no file (it was raised while
    checking, after the file was read)."""
    scene = _scene(tmp_path, FOURBAR)
    ans = _scene(tmp_path, "[answers]\nI_19 = [1, 2]\n", "ann.toml")
    assert main(["check", scene, ans]) == 2
    line = _one_line(capsys)
    assert "ann.toml: [answers] I_19 (line 2)" in line and "no centre I19" in line
    assert main(["check", _scene(tmp_path, FOURBAR + "[answers]\nI_19 = [1, 2]\n")]) == 2
    assert "s.toml: [answers] I_19 (line 13)" in _one_line(capsys)


def test_a_centre_answer_far_beyond_any_mechanism_is_a_units_slip():
    """I_24 = [1e300, 2] was graded 4.7e299 % off, a number of 300 digits in the table."""
    with pytest.raises(SceneError, match="absurd") as err:
        parse_scene(FOURBAR + "[answers]\nI_24 = [1e300, 2]\n")
    assert "[answers] I_24 (line 13)" in err.value.one_line()


# ----------------------------------------------------------------- options at their extremes

SEED = "worked_problems/fourbar_image_points.toml"


def test_a_seed_beyond_64_bits_is_refused_not_every_variant_turned_down(tmp_path, capsys):
    """Each variant file records its seed; TOML's integers are 64-bit. A larger seed
    turned every combination down as "does not solve" (widen the ranges, it said)."""
    from polygon_method.variants import MAX_SEED, generate

    assert MAX_SEED == 2**63 - 1
    out = tmp_path / "class"
    assert main(["variants", SEED, "--count", "2", "--seed", str(2**64), "-o", str(out)]) == 2
    line = _one_line(capsys)
    assert "--seed" in line and "64-bit" in line and not out.exists()
    with pytest.raises(PolygonMethodError, match="--seed"):
        generate(load_scene(SEED), 2, 2**63)
    assert main(["variants", SEED, "--count", "2", "--seed", str(2**63 - 1), "-o", str(out)]) == 0
    capsys.readouterr()
    assert load_scene(out / "variant-01.toml").variant.seed == 2**63 - 1


@pytest.mark.parametrize(
    "scale", ["1 cm = 1e-300 m/s", "1 cm = 1e300 m/s", "1 cm = 1e20 m/s^2", "1 cm = 1e9 m"]
)
def test_an_absurd_scale_is_one_short_line(tmp_path, capsys, scale):
    """1e-300 m/s per cm printed the scale and the figure's size as numbers of 300
    digits; 1e300 m/s per cm drew a speck."""
    out = tmp_path / "d.svg"
    assert main(["draw", SEED, "-o", str(out), "--scale", scale]) == 2
    line = _one_line(capsys)
    assert len(line) < 250 and "absurd" in line and "--scale" in line
    assert not out.exists()


def test_a_scale_that_draws_a_speck_is_refused_and_a_coarse_one_is_not(tmp_path, capsys):
    out = tmp_path / "d.svg"
    v_max = max(solve(load_scene(SEED)).speed(p) for p in "BCEFG")  # about 0.53 m/s
    # 1000 m/s per cm: the polygon would be 0.5 mm / 1000 across
    assert main(["draw", SEED, "-o", str(out), "--scale", "1 cm = 1000 m/s"]) == 2
    assert "a speck" in _one_line(capsys) and not out.exists()
    # 1 m/s per cm: half a centimetre, small but drawn as asked
    assert v_max / 1.0 > 0.3
    assert main(["draw", SEED, "-o", str(out), "--scale", "1 cm = 1 m/s"]) == 0
    assert "velocity 1 cm = 1 m/s" in capsys.readouterr().out


def test_a_too_fine_scale_says_the_size_in_a_few_digits(tmp_path, capsys):
    out = tmp_path / "d.svg"
    assert main(["draw", SEED, "-o", str(out), "--scale", "1 cm = 1e-11 m/s"]) == 2
    line = _one_line(capsys)
    assert "e+10 cm across" in line and len(line) < 200


@pytest.mark.parametrize(
    "diagram, scale",
    [
        ("velocity", "1 cm = 1 m/s^2"),
        ("acceleration", "1 cm = 0.1 m/s"),
        ("centres", "1 cm = 0.1 m/s"),
        ("configuration", "1 cm = 1 m/s^2"),
    ],
)
def test_a_scale_for_a_diagram_not_drawn_is_refused_never_ignored(tmp_path, capsys, diagram, scale):
    out = tmp_path / "d.svg"
    assert main(["draw", SEED, "-o", str(out), "--diagram", diagram, "--scale", scale]) == 2
    line = _one_line(capsys)
    assert f"--diagram {diagram} draws no" in line and not out.exists()


# ----------------------------------------------------------------- the Python API


@pytest.mark.parametrize("bad", [None, 123, b"/no/such/file", "", "  ", "/tmp/a\x00b"])
def test_load_scene_of_what_names_no_file_is_a_scene_error(bad):
    """None and 123 were TypeErrors, a NUL byte a ValueError, "" read the directory "."."""
    with pytest.raises(SceneError) as err:
        load_scene(bad)
    assert "directory" not in str(err.value)


@pytest.mark.parametrize("bad", [None, 123, b"[ground]\nA = [0, 0]\n", ["A"]])
def test_parse_scene_of_what_is_no_text_is_a_scene_error(bad):
    with pytest.raises(SceneError, match="str"):
        parse_scene(bad)


def test_load_answers_and_parse_answers_refuse_what_is_not_theirs(tmp_path):
    from polygon_method.scene import load_answers, parse_answers

    sc = parse_scene(FOURBAR)
    with pytest.raises(SceneError):
        load_answers(None, sc)
    with pytest.raises(SceneError, match="str"):
        parse_answers(None, sc)
    with pytest.raises(SceneError, match="Scene"):
        parse_answers('[answers]\nv_C = "1 m/s"\n', FOURBAR)


@pytest.mark.parametrize(
    "field, value, words",
    [
        ("omega", 0.0, "zero: nothing moves"),
        ("omega", 1e300, "absurd"),
        ("omega", 1e-300, "absurd"),
        ("alpha", 1e300, "absurd"),
        ("angle", 1e300, "absurd"),
    ],
)
def test_a_scene_made_through_the_api_meets_the_files_bounds(field, value, words):
    """dataclasses.replace gave a zero speed (ZeroDivisionError in the input torque) or
    1e300 rad/s (OverflowError); a file could state neither."""
    import dataclasses

    sc = parse_scene(FOURBAR + '[loads]\nC = { force = "100 N", direction = 0 }\n')
    with pytest.raises(SceneError, match=words):
        dataclasses.replace(sc, input=dataclasses.replace(sc.input, **{field: value}))
    fine = dataclasses.replace(sc, input=dataclasses.replace(sc.input, omega=-3.0))
    assert solve(fine).omega("AB") == -3.0


def test_a_link_of_absurd_length_through_the_api_is_refused():
    import dataclasses

    sc = parse_scene(FOURBAR)
    long_ = dataclasses.replace(sc.links[0], length=1e300)
    with pytest.raises(SceneError, match="length between"):
        dataclasses.replace(sc, links=(long_,) + sc.links[1:])


@pytest.mark.parametrize("angles", ["abc", [1j], [1e300], [[0.1, 0.2]]])
def test_sweep_angles_that_are_no_crank_angles_are_a_scene_error(angles):
    from polygon_method import sweep

    with pytest.raises(SceneError, match="crank angles"):
        sweep(parse_scene(FOURBAR), angles)


@pytest.mark.parametrize("chunk", [0, -1, 1.5, True])
def test_a_sweep_chunk_is_a_whole_number(chunk):
    """chunk = -1 gave an empty sweep, 0 a ValueError."""
    from polygon_method import sweep

    with pytest.raises(SceneError, match="chunk"):
        sweep(parse_scene(FOURBAR), [0.0, 1.0], chunk=chunk)


# ----------------------------------------------------------------- answer files, names


def test_an_answer_file_with_a_byte_order_mark_is_read_as_a_scene_is(tmp_path, capsys):
    """A scene may start with a UTF-8 byte-order mark; an answer file saved by the same
    editor was a TOML syntax error at line 1, column 1."""
    scene = _scene(tmp_path, FOURBAR)
    v_c = solve(parse_scene(FOURBAR)).speed("C")
    ans = tmp_path / "ann.toml"
    ans.write_bytes(b"\xef\xbb\xbf" + f'[answers]\r\nv_C = "{v_c:.5f} m/s"\r\n'.encode())
    assert main(["check", scene, str(ans)]) == 0
    assert "right" in capsys.readouterr().out


@pytest.mark.parametrize(
    "text, where",
    [
        ('[answers]\n"v_C\\n" = "1 m/s"\n', "[answers] v_C\\n"),
        ('[answers]\n"omega_BC\\n" = "1 rad/s ccw"\n', "[answers] omega_BC\\n"),
    ],
)
def test_a_name_with_a_trailing_line_break_is_no_name(text, where):
    """`$` in a regular expression matches before a final line feed: "v_C\\n" was graded as
    v_C (and printed with the line break, splitting the table's row)."""
    from polygon_method.scene import parse_answers

    with pytest.raises(SceneError) as err:
        parse_answers(text, parse_scene(FOURBAR), file="a.toml")
    line = err.value.one_line()
    assert where in line and "\n" not in line


def test_a_point_or_link_name_with_a_trailing_line_break_is_refused():
    with pytest.raises(SceneError, match="not a point name"):
        parse_scene(FOURBAR.replace("A = [0, 0]", 'A = [0, 0]\n"D\\n" = [5, 5]'))
    with pytest.raises(SceneError, match="not a link name"):
        parse_scene(FOURBAR.replace("BC = 66", 'BC = 66\n"CD\\n" = 56'))


def test_a_value_with_a_line_break_is_shown_escaped_in_the_table(tmp_path, capsys):
    scene = _scene(tmp_path, FOURBAR)
    ans = _scene(
        tmp_path, '[answers]\nv_C = "0.4\\nm/s"\nomega_BC = "5.15\\trad/s ccw"\n', "ann.toml"
    )
    main(["check", scene, ans])
    rows = [x for x in capsys.readouterr().out.splitlines() if x.startswith(("v_C", "omega"))]
    assert len(rows) == 2 and "0.4\\nm/s" in rows[0] and "5.15\\trad/s" in rows[1]


def test_a_value_thousands_of_characters_long_is_quoted_short(tmp_path, capsys):
    scene = _scene(tmp_path, FOURBAR)
    ans = _scene(tmp_path, '[answers]\nv_C = "' + "9" * 5000 + ' m/s"\n', "ann.toml")
    assert main(["check", scene, ans]) == 2
    line = _one_line(capsys)
    assert len(line) < 300 and "(5004 characters)" in line and "[answers] v_C (line 2)" in line
    with pytest.raises(SceneError) as err:
        parse_scene(FOURBAR.replace('"10.5 rad/s cw"', '"10.5 ' + "r" * 3000 + '"'))
    assert len(err.value.one_line()) < 300


SLOTTED_IN_LINE = """[ground]
O2 = [0, 100]
O4 = [0, 0]
[links]
"O2-A" = 100
"O4-P" = 150
[sliders]
A = { along = "O4-P" }
[input]
crank = "O2-A"
angle = 90
speed = "10 rad/s ccw"
"""


def test_centres_a_rounding_apart_draw_no_line_to_infinity(tmp_path, capsys):
    """The crank and lever in line: I13 falls on I14 but for 6e-15 mm of rounding, and the
    Kennedy line through them had no direction (a line clipped to infinity: an internal
    error while drawing). The sheet is drawn, with I13 where I14 is."""
    import xml.etree.ElementTree as ET
    from polygon_method.solver.centres import locate

    ic = locate(solve(parse_scene(SLOTTED_IN_LINE)))
    i13, i14 = ic.centre(1, 3).point, ic.centre(1, 4).point
    assert abs(i13[0] - i14[0]) < 1e-15 and abs(i13[1] - i14[1]) < 1e-15  # O4, by hand
    out = tmp_path / "c.svg"
    assert (
        main(["draw", _scene(tmp_path, SLOTTED_IN_LINE), "--diagram", "centres", "-o", str(out)])
        == 0
    ), capsys.readouterr().err
    root = ET.parse(out).getroot()
    width = float(root.get("width").rstrip("pt"))
    assert 0 < width < 2000


def test_a_centre_on_an_axis_is_printed_on_it_not_a_rounding_off(tmp_path, capsys):
    """I23 is the pin at A = (0, 200) mm by hand; it was printed (6.12323e-15, 200)."""
    assert main(["centres", _scene(tmp_path, SLOTTED_IN_LINE)]) == 0
    out = capsys.readouterr().out
    assert "I23  (0, 200) mm" in out and "e-15" not in out


def test_two_outputs_into_one_file_are_refused_before_anything_is_written(tmp_path, capsys):
    """--csv x.svg --plot x.svg wrote the CSV and then the plot over it: the CSV was lost
    without a word (also through a link to the other name)."""
    same = tmp_path / "same.svg"
    assert main(["sweep", SEED, "--steps", "10", "--csv", str(same), "--plot", str(same)]) == 2
    assert "are one file" in _one_line(capsys) and not same.exists()
    link = tmp_path / "link.csv"
    link.symlink_to(same)
    assert main(["sweep", SEED, "--steps", "10", "--csv", str(link), "--plot", str(same)]) == 2
    assert "--csv" in _one_line(capsys) and not same.exists()
    assert (
        main(
            ["sweep", SEED, "--steps", "10", "--csv", str(tmp_path / "a.csv"), "--plot", str(same)]
        )
        == 0
    )
    assert same.exists() and (tmp_path / "a.csv").read_text().startswith("theta")


# ----------------------------------------------------------------- what to do


def test_a_crank_set_where_the_links_cannot_meet_is_told_where_they_can():
    """A double rocker (AB 90, BC 66, CD 56, AD 100) at 90 deg: C cannot be assembled. The
    message said so but not what to do; now it gives the crank's range, here where BD =
    BC + CD by the law of cosines: cos(theta) = (90^2 + 100^2 - 122^2) / (2 90 100)."""
    import math

    from polygon_method import AssemblyError

    text = FOURBAR.replace("AB = 50", "AB = 90").replace("angle = 60", "angle = 90")
    with pytest.raises(AssemblyError) as err:
        solve(parse_scene(text))
    edge = math.degrees(math.acos((90**2 + 100**2 - 122**2) / (2 * 90 * 100)))
    assert f"can be set only from {-edge:.2f} to {edge:.2f} deg" in err.value.one_line()
    text = text.replace("angle = 90", "angle = 180")  # the same range, named the same way
    with pytest.raises(AssemblyError) as err:
        solve(parse_scene(text))
    assert f"from {-edge:.2f} to {edge:.2f} deg" in err.value.one_line()


def test_a_slider_out_of_reach_is_told_both_ranges_of_its_crank():
    """The bad scene: crank OA 150 at 90 deg, rod AB 100, B on the horizontal path
    through O. B reaches the path where |150 sin(theta)| <= 100: two ranges about 0 and
    180 deg, asin(100 / 150) either side."""
    import math

    from polygon_method import AssemblyError

    with pytest.raises(AssemblyError) as err:
        solve(load_scene("tests/bad_scenes/slider_cannot_reach.toml"))
    a = math.degrees(math.asin(100 / 150))
    assert (
        f"the crank OA can be set only from {-a:.2f} to {a:.2f} deg, or from "
        f"{180 - a:.2f} to {180 + a:.2f} deg: give an angle there"
    ) in err.value.one_line()


def test_links_that_meet_at_no_crank_angle_say_so():
    from polygon_method import AssemblyError

    text = FOURBAR.replace("BC = 66", "BC = 20").replace("CD = 56", "CD = 20")
    with pytest.raises(AssemblyError, match="no angle of the crank AB assembles it"):
        solve(parse_scene(text))


# ----------------------------------------------------------------- titles and file names in a page


@pytest.mark.parametrize(
    "title", ["<!--<script>", "</script><script>alert(1)</script>", "a <!-- b <script> c"]
)
def test_a_title_never_ends_or_runs_on_the_pages_data(tmp_path, capsys, title):
    """The page's data is JSON inside <script type="application/json">: "</" was escaped,
    but "<!--<script>" from a title put the HTML parser in a state where the element's
    own end tag does not end it (the rest of the page was read as script)."""
    import json
    import re

    text = open(SEED).read().split("[variants]")[0]
    text = re.sub(r"(?m)^title = .*$", "title = " + json.dumps(title), text)
    page = tmp_path / "p.html"
    ans = _scene(tmp_path, '[answers]\nv_C = "0.4 m/s"\n', "<!--<script>.toml")
    assert (
        main(["page", _scene(tmp_path, text), "-o", str(page), "--frames", "3", "--answers", ans])
        == 0
    ), capsys.readouterr().err
    html = page.read_text()
    m = re.search(r'<script type="application/json" id="frames">(.*?)</script>', html, re.S)
    data = m.group(1)
    assert "<" not in data  # no markup of any kind inside the element
    assert json.loads(data)["title"] == title


# ----------------------------------------------------------------- gigantic scenes


def _many_points(n):
    pts = "".join(f'E{i} = {{ on = "BC", along = {1 + 0.01 * i:.2f} }}\n' for i in range(n))
    return FOURBAR + "[points]\n" + pts


def test_a_scene_of_thousands_of_points_is_refused_by_its_count(tmp_path, capsys):
    """3000 points on one link: a sweep's summary held every point at every refining angle
    at once (gigabytes, killed after minutes)."""
    from polygon_method.scene.reading import MAX_POINTS
    from polygon_method.solver.tracking import MAX_CYCLE_POINTS

    with pytest.raises(SceneError, match=f"the scene has {MAX_POINTS + 1} points: at most"):
        parse_scene(_many_points(MAX_POINTS + 1 - 4))  # A, B, C, D and the carried ones
    path = _scene(tmp_path, _many_points(MAX_CYCLE_POINTS + 1 - 4))
    for argv in (["sweep", path, "--steps", "4"], ["linkage", path]):
        assert main(argv) == 2
        assert f"has {MAX_CYCLE_POINTS + 1} points: the crank's cycle" in _one_line(capsys)
    assert main(["solve", path]) == 0


def test_refining_extremes_a_batch_at_a_time_finds_the_same_extremes(monkeypatch):
    """The summary refines its extremes a batch of brackets at a time (bounded memory);
    the batches change nothing: the same extremes, at the same angles, as all at once."""
    import numpy as np

    from polygon_method.linkage import summary

    sc = load_scene(SEED)
    angles = np.radians(np.arange(-100.0, 100.0, 2.0))
    whole = summary.summarize(sc, angles)
    monkeypatch.setattr(summary, "_REFINE_BUDGET", 17 * 7 * 3)  # three brackets a batch
    parts = summary.summarize(sc, angles)
    assert [(e.name, e.maximum, e.at_max, e.minimum, e.at_min) for e in whole.extremes] == [
        (e.name, e.maximum, e.at_max, e.minimum, e.at_min) for e in parts.extremes
    ]


def test_a_drawing_of_too_many_labels_is_refused_before_minutes_of_placing(tmp_path, capsys):
    """300 carried points: the labels' placement ran for over five minutes."""
    import time

    from polygon_method.draw.sheet import MAX_DRAWN_POINTS

    path = _scene(tmp_path, _many_points(MAX_DRAWN_POINTS - 3))
    out = tmp_path / "d.svg"
    t0 = time.perf_counter()
    assert main(["draw", path, "-o", str(out)]) == 2
    assert time.perf_counter() - t0 < 5
    assert f"has {MAX_DRAWN_POINTS + 1} points: a drawing labels at most" in _one_line(capsys)
    assert not out.exists()
    assert main(["page", path, "-o", str(tmp_path / "p.html"), "--frames", "3"]) == 0


def test_labels_that_cannot_be_placed_are_one_warning_per_diagram(tmp_path, capsys):
    """Forty labels crowded on one link were forty warning lines."""
    path = _scene(tmp_path, _many_points(40))
    assert main(["draw", path, "-o", str(tmp_path / "d.svg"), "--diagram", "configuration"]) == 0
    warnings = [x for x in capsys.readouterr().err.splitlines() if x.startswith("warning:")]
    assert len(warnings) == 1 and "more could not be placed" in warnings[0]


@pytest.mark.parametrize("head", ["title = 5\n", 'title = ["a"]\n', "[title]\nx = 1\n"])
def test_a_title_that_is_no_string_names_its_line_and_the_form(head):
    with pytest.raises(SceneError) as err:
        parse_scene(head + FOURBAR)
    line = err.value.one_line()
    assert line.startswith('title (line 1): title must be a string: title = "')


def test_a_file_with_lone_carriage_returns_is_told_its_line_endings():
    """Lines ended by CR alone (an old Mac editor) are one line to TOML: the syntax error
    at "line 1, column 9" said nothing of why."""
    text = FOURBAR.replace("\n", "\r")
    with pytest.raises(SceneError, match="lone carriage return") as err:
        parse_scene(text)
    assert "line 1" in err.value.one_line()
    assert parse_scene(FOURBAR.replace("\n", "\r\n")).links[1].length == pytest.approx(0.066)


def test_a_plot_of_one_point_or_link_named_twice_draws_one_curve_each(tmp_path):
    """--points C,C --links BC,CB drew each curve twice, two legend entries of one name."""
    import numpy as np

    from polygon_method import sweep
    from polygon_method.draw.plots import plot_figure

    res = sweep(load_scene(SEED), np.radians(np.arange(-90.0, 91.0, 10.0)))
    fig = plot_figure(res, points=("C", "C"), links=("BC", "CB"))
    labels = [
        ln.get_label()
        for ax in fig.axes
        for ln in ax.get_lines()
        if not ln.get_label().startswith("_")
    ]
    assert sorted(labels) == sorted(
        [
            "$a_{\\mathrm{C}}$",
            "$\\alpha_{\\mathrm{BC}}$",
            "$\\omega_{\\mathrm{BC}}$",
            "$v_{\\mathrm{C}}$",
        ]
    )


def test_a_list_of_names_of_only_commas_is_refused_not_taken_as_all(tmp_path, capsys):
    plot = tmp_path / "p.svg"
    assert main(["sweep", SEED, "--steps", "12", "--points", ",,", "--plot", str(plot)]) == 2
    assert "--points ',,' names no point" in _one_line(capsys) and not plot.exists()


def test_a_limit_at_an_undecidable_change_point_names_its_step_once():
    """AD 1e-8 mm shorter than a parallelogram's: at 0 deg the two assemblies meet and
    leave with one velocity, a limit of the sweep. Its words repeated the step's label
    ("step 2 (...): step 2 (...): the two assemblies ...")."""
    from polygon_method.linkage.summary import summarize

    text = (
        FOURBAR.replace("D = [100, 0]", "D = [65.99999999, 0]")
        .replace("AB = 50", "AB = 56")
        .replace('"10.5 rad/s cw"', '"10 rad/s ccw"')
    )
    s = summarize(parse_scene(text))
    (lp,) = [lp for lp in s.limits if "the two assemblies" in lp.why]
    assert not lp.why.startswith("step") and lp.step.startswith("step 2")
    assert s.text().count("step 2 (dyad BC, CD at C): step 2") == 0


def test_a_named_pipe_with_no_writer_is_one_line_not_a_wait(tmp_path):
    """A scene or answer file that is a named pipe nobody writes into: the open waited
    for ever. Now it reads at once; with nothing in it, it says so."""
    import os
    import subprocess
    import sys

    fifo = tmp_path / "scene.toml"
    os.mkfifo(fifo)
    for argv in (["solve", str(fifo)], ["check", SEED, str(fifo)]):
        run = subprocess.run(
            [sys.executable, "-m", "polygon_method", *argv],
            capture_output=True,
            text=True,
            timeout=60,
        )
        assert run.returncode == 2 and "named pipe that nothing is writing into" in run.stderr
        assert len(run.stderr.splitlines()) == 1


def test_a_scene_through_a_pipe_with_its_writer_is_read_whole():
    import subprocess
    import sys

    text = open(SEED).read()
    run = subprocess.run(
        [sys.executable, "-m", "polygon_method", "solve", "/dev/stdin"],
        input=text,
        capture_output=True,
        text=True,
        timeout=60,
    )
    assert run.returncode == 0 and "crank AB at 60 deg" in run.stdout


def test_an_output_that_is_a_named_pipe_with_no_reader_is_one_line_not_a_wait(tmp_path):
    """-o or --csv onto a named pipe nobody reads: the write waited for ever."""
    import os
    import subprocess
    import sys

    for name, argv in (
        ("d.svg", ["draw", SEED, "-o"]),
        ("s.csv", ["sweep", SEED, "--steps", "5", "--csv"]),
    ):
        fifo = tmp_path / name
        os.mkfifo(fifo)
        run = subprocess.run(
            [sys.executable, "-m", "polygon_method", *argv, str(fifo)],
            capture_output=True,
            text=True,
            timeout=60,
        )
        assert run.returncode == 2, run.stderr
        assert "a named pipe that nothing is reading from" in run.stderr
        assert len(run.stderr.splitlines()) == 1


def test_an_output_pipe_with_its_reader_gets_the_whole_file(tmp_path):
    import os
    import subprocess
    import sys
    import threading

    fifo = tmp_path / "s.csv"
    os.mkfifo(fifo)
    got = []
    reader = threading.Thread(target=lambda: got.append(open(fifo).read()))
    reader.start()
    run = subprocess.run(
        [sys.executable, "-m", "polygon_method", "sweep", SEED, "--steps", "5", "--csv", str(fifo)],
        capture_output=True,
        text=True,
        timeout=60,
    )
    reader.join(timeout=60)
    assert run.returncode == 0, run.stderr
    rows = got[0].splitlines()
    assert rows[0].startswith("theta") and len(rows) == 1 + 3  # 3 of 5 angles reachable


@pytest.mark.parametrize("speed", ["10 rad/s cw ccw", "10 rad/s ccw ccw", "10 rpm cw clockwise"])
def test_a_speed_with_two_senses_is_told_so(speed):
    """ "10 rad/s cw ccw" was an unknown unit 'rad/s cw' (did you mean 'rad/s'?)."""
    with pytest.raises(SceneError, match="gives two senses: give one") as err:
        parse_scene(FOURBAR.replace('"10.5 rad/s cw"', f'"{speed}"'))
    assert "[input] speed (line 11)" in err.value.one_line()


def test_links_between_fixed_points_that_cannot_meet_say_no_angle_helps():
    """EF + FG = 60 mm between ground points 248 mm apart: the crank's angle changes
    nothing. Saying where the crank could be set met a step of fixed points only (its
    failure a single true, not an array per angle): an internal error."""
    from polygon_method import AssemblyError

    # AB 20: the four-bar turns fully (20 + 100 < 66 + 56), so only F's step fails
    text = STRUCTURE.replace("E = [200, 0]", "E = [2, 0]").replace("AB = 50", "AB = 20")
    with pytest.raises(AssemblyError) as err:
        solve(parse_scene(text))
    line = err.value.one_line()
    assert "EF + FG = 60 mm < EG = 248 mm" in line and "no angle of the crank AB" in line


def test_frames_times_points_are_bounded_before_anything_is_computed(tmp_path, capsys):
    """3600 frames of a thousand points made a 200 MB page (1.7 GB of memory)."""
    from polygon_method.page.frames import MAX_FRAME_POINTS

    n = 400 - 4
    path = _scene(tmp_path, _many_points(n))
    frames = MAX_FRAME_POINTS // 400 + 1
    page = tmp_path / "p.html"
    assert main(["page", path, "-o", str(page), "--frames", str(frames)]) == 2
    line = _one_line(capsys)
    assert (
        f"--frames {frames} of 400 points" in line
        and f"give at most {MAX_FRAME_POINTS // 400} frames" in line
        and not page.exists()
    )


from hypothesis import given, settings, strategies as st  # noqa: E402

_coord = st.floats(-1e4, 1e4, allow_nan=False, allow_infinity=False)


@settings(max_examples=300, deadline=None)
@given(st.lists(st.tuples(_coord, _coord), max_size=40))
def test_a_diagrams_extent_is_its_farthest_pair(points):
    """The extent (which sets every scale) from the convex hull's corners equals the
    farthest pair found by trying every pair (it tried every pair: the step table of a
    thousand points spent seconds there)."""
    import itertools
    import math

    from polygon_method.polygons.scales import extent

    brute = max((math.dist(p, q) for p, q in itertools.combinations(points, 2)), default=0.0)
    assert extent(points) == brute


def test_compiling_a_plate_of_many_points_looks_at_each_a_few_times(monkeypatch):
    """Each point found pushed every unfound point of its plate onto the heap again:
    N^2 / 2 pushes for N carried points on one link (4.5 million for 3000: seconds before
    anything was solved). The plan is the same: the points in the scene's order."""
    import heapq

    from polygon_method.solver import compiler

    pushes = []
    real = heapq.heappush
    monkeypatch.setattr(compiler.heapq, "heappush", lambda h, x: (pushes.append(x), real(h, x))[1])
    n = 400
    plan = compiler._Compiler(parse_scene(_many_points(n))).run()
    assert len(pushes) <= 4 * (n + 4)
    found = [st.finds[0] for st in plan.steps]
    assert found[:2] == ["B", "C"] and found[2 : 2 + n] == [f"E{i}" for i in range(n)]
