"""Today's inputs as a careless teacher or a mischievous student would write them: an offset
slot's distance and side, friction per guide and per pin, a rod's inertia by its swing, a
turning-moment diagram by its strokes, a second input given by a slider's speed, a load
against a link. Each bad one through every command that reads the scene (solve, solve
--json, steps, draw, check, sweep, linkage, centres, page): one line on stderr naming the
file and the key with its line, exit code 2, nothing on stdout, no output file written.
Good ones are held to closed forms (a block's distance from the lever's line is the slot's
offset; a rod's k_G^2 = g h T^2 / (4 pi^2) - h^2; a block's sliding from the velocities),
never to the tool's own output."""

from __future__ import annotations

import json
import math
import re
import subprocess
import sys
from pathlib import Path

import pytest

from polygon_method import parse_cycle, parse_scene, solve, solve_cycle
from polygon_method.cli import main

ROOT = Path(__file__).resolve().parent.parent
BOOK = ROOT / "tests/textbook"
OFFSET = (BOOK / "hunt5_offset_slot_lever.toml").read_text()
FRICTION = (BOOK / "friction_each_slider_crank_pins.toml").read_text()
SWUNG = (BOOK / "force_engine_rod_swung_as_pendulum.toml").read_text()
STROKES = (BOOK / "flywheel/strokes_four_triangles_areas.toml").read_text()
sys.path.insert(0, str(Path(__file__).parent))
from test_link_loads import SCENE as LINK_LOADS  # noqa: E402
from test_two_given_point_slider import SLOT  # noqa: E402

NUMBER_WORD = re.compile(r"(?<![A-Za-z])(nan|inf|infinity)(?![A-Za-z])", re.I)


def _replaced(text, old, new):
    assert old in text, old
    return text.replace(old, new)


def _commands(scene, out):
    return [
        ["solve", scene],
        ["solve", "--json", scene],
        ["steps", scene],
        ["draw", scene, "-o", str(out / "x.svg")],
        ["check", scene],
        ["sweep", scene, "--summary", "--steps", "12"],
        ["sweep", scene, "--csv", str(out / "x.csv"), "--steps", "12"],
        ["linkage", scene],
        ["centres", scene],
        ["page", scene, "-o", str(out / "x.html"), "--frames", "4"],
    ]


def _refused_everywhere(text, tmp_path, capsys, *words):
    """Every command refuses the scene in one line naming the file and ``words``; nothing
    on stdout, no output file written, the ones there before left as they were."""
    scene = tmp_path / "bad.toml"
    scene.write_text(text, encoding="utf-8")
    kept = {n: f"{n}: a file of the teacher's, kept" for n in ("x.svg", "x.csv", "x.html")}
    for n, content in kept.items():
        (tmp_path / n).write_text(content, encoding="utf-8")
    lines = []
    for argv in _commands(str(scene), tmp_path):
        assert main(argv) == 2, argv
        out, err = capsys.readouterr()
        errs = [x for x in err.splitlines() if not x.startswith("warning:")]
        assert len(errs) == 1 and not out.strip(), (argv, err, out[:300])
        assert "bad.toml" in errs[0] and "Traceback" not in err, errs[0]
        for w in words:
            assert w in errs[0], (w, errs[0])
        lines.append(errs[0].split(": ", 1)[1])
    assert sorted(p.name for p in tmp_path.iterdir()) == ["bad.toml", *sorted(kept)]
    for n, content in kept.items():  # (neither replaced nor half-written)
        assert (tmp_path / n).read_text(encoding="utf-8") == content
    assert len(set(lines)) == 1, lines  # the same words from every command
    return lines[0]


# ------------------------------------------------------------------ an offset slot

SLOT_LINE = 'offset = "30 mm left"'


@pytest.mark.parametrize(
    "offset, words",
    [
        ("0", "offset = 0"),
        ('"0 mm left"', "offset = 0"),
        ('"-30 mm left"', "with a side"),
        ('"1e9 mm left"', "absurd"),
        ('"nan mm left"', "cannot read"),
        ('"30 mm lfet"', "did you mean 'left'"),
        ('"30 mm up"', "left or right (looking from Q to B), not 'up'"),
        ('"30 mm left left"', "given once"),
        ('"30 mm ccw"', "not 'ccw'"),
        ('"30 rad left"', "not of length"),
        ('"left 30 mm"', "cannot read"),
        ('""', "cannot read"),
        ("true", "got true/false"),
        ("[30]", "got a list"),
    ],
)
def test_a_bad_offset_is_one_line_naming_the_slider(offset, words, tmp_path, capsys):
    text = _replaced(OFFSET, SLOT_LINE, f"offset = {offset}")
    _refused_everywhere(text, tmp_path, capsys, "[sliders] A (line 25)", words)


@pytest.mark.parametrize("offset", ['"600 mm left"', '"5000 mm right"'])
def test_an_offset_beyond_the_blocks_reach_is_named_at_its_step(offset, tmp_path, capsys):
    # the block is 312 mm from the pivot Q: a slot further off never comes near it
    text = _replaced(OFFSET, SLOT_LINE, f"offset = {offset}")
    line = _refused_everywhere(text, tmp_path, capsys, "step 2 (block A sliding on QB)")
    assert "less than the slot's offset" in line


def test_an_offset_on_a_fixed_path_is_refused(tmp_path, capsys):
    text = _replaced(
        OFFSET,
        'R = { path = "horizontal", through = "T" }',
        'R = { path = "horizontal", through = "T", offset = "30 mm" }',
    )
    line = _refused_everywhere(
        text, tmp_path, capsys, "[sliders] R", 'offset goes with along = "CP"'
    )
    # (a book's offset line of stroke: how it is stated)
    assert "an offset line of stroke is its through = [x, y] (40 mm below O: [0, -40])" in line


def _distance_from_line(p, a, b):
    """Signed distance of p from the line a -> b, positive on its left."""
    (px, py), (ax, ay), (bx, by) = p, a, b
    return ((bx - ax) * (py - ay) - (by - ay) * (px - ax)) / math.hypot(bx - ax, by - ay)


@pytest.mark.parametrize(
    "words, signed",
    [
        ('"30 mm left"', 0.030),
        ('"30 mm to the left"', 0.030),
        ('"30 mm Right"', -0.030),
        ("30", 0.030),
        ("-30", -0.030),
        ('"3 cm right"', -0.030),
        ('"1e-6 mm left"', 1e-9),
    ],
)
def test_the_block_is_the_offset_off_the_levers_line(words, signed):
    """Loop closure: the block A sits on the slot's line, ``signed`` m to the left of Q -> B,
    with the crank pin at its length from O; the words of the side read either case."""
    sol = solve(parse_scene(_replaced(OFFSET, SLOT_LINE, f"offset = {words}")))
    P = sol.P
    assert math.isclose(math.dist(P["O"], P["A"]), 0.1, rel_tol=1e-12)
    assert math.isclose(math.dist(P["Q"], P["B"]), 0.5, rel_tol=1e-12)
    assert _distance_from_line(P["A"], P["Q"], P["B"]) == pytest.approx(signed, abs=1e-15)


def test_a_vanishing_offset_agrees_with_the_plain_slot():
    """An offset of 1e-9 mm moves nothing by more than about 1e-12 m: the plain slot's
    velocities and accelerations to 1e-9 relative."""
    plain = solve(parse_scene(OFFSET.replace(", " + SLOT_LINE, "")))
    tiny = solve(parse_scene(_replaced(OFFSET, SLOT_LINE, 'offset = "1e-9 mm left"')))
    for name in ("QB", "BR"):
        for a, b in ((plain.W[name], tiny.W[name]), (plain.Al[name], tiny.Al[name])):
            assert math.isclose(a, b, rel_tol=1e-9, abs_tol=1e-12), (name, a, b)
    for p in ("A", "B", "R"):
        for a, b in ((plain.V[p], tiny.V[p]), (plain.A[p], tiny.A[p])):
            assert math.dist(a, b) <= 1e-9 * max(1.0, math.hypot(*a)), (p, a, b)


# ------------------------------------------------------------------ friction


FRICTION_LINES = "guides = 0.15\npins = { O = 0.05, A = 0.08, B = 0.12 }"


@pytest.mark.parametrize(
    "friction, key, words",
    [
        ("guides = 0.15\npins = { O = 0.05, Z = 0.08 }", "pins", "'Z' is not a joint"),
        ("guides = 0.15\npins = { O = -0.05 }", "pins", "pins.O = -0.05"),
        ("guides = 0.15\npins = { O = 1.5 }", "pins", "up to (not) 1"),
        ("guides = 0.15\npins = { O = 1.0 }", "pins", "up to (not) 1"),
        ("guides = 0.15\npins = {}", "pins", "names none"),
        ("guides = {}\npins = { O = 0.05 }", "guides", "names none"),
        ("guides = { Q = 0.1 }", "guides", "'Q' is not a sliding block's point"),
        ("guides = -0.1", "guides", "a coefficient of friction"),
        ("guides = 1", "guides", "a coefficient of friction"),
        ("guides = nan", "guides", "a coefficient of friction"),
        ("guides = inf", "guides", "a coefficient of friction"),
        ('guides = "10%"', "guides", "a coefficient of friction"),
        ("guides = true", "guides", "a coefficient of friction"),
        ('pins = "-2 mm"', "pins", "must be positive"),
        ('pins = "0 mm"', "pins", "must be positive"),
        ('pins = "2 rad"', "pins", "not of length"),
        ('pins = { O = 0.05, radius = "2 mm" }', "pins", "'radius' is not a joint"),
        ("pins = { AB = 0.1 }", "pins", "'AB' is not a joint"),
        ("pins = [0.1]", "pins", "a coefficient of friction"),
        ("guide = 0.1", "guide", "did you mean 'guides'"),
    ],
)
def test_bad_friction_is_one_line_naming_its_key(friction, key, words, tmp_path, capsys):
    text = _replaced(FRICTION, FRICTION_LINES, friction)
    _refused_everywhere(text, tmp_path, capsys, f"[friction] {key} (line 4", words)


def test_a_coefficient_at_a_pin_of_no_size_shows_how_to_give_its_circle(tmp_path, capsys):
    text = _replaced(
        FRICTION, "[pins]\nO = { diameter = 50 }\nA = { diameter = 40 }\nB = { diameter = 25 }", ""
    )
    line = _refused_everywhere(text, tmp_path, capsys, "[friction] pins (line 42)")
    # (it closed its example with a brace too many: 'pins = { O = "5 mm" }})')
    assert line.endswith('(pins = { O = "5 mm" })'), line


# ------------------------------------------------------------------ a rod swung as a pendulum

SWING = 'oscillations = "21 in 40 s", about = "B"'


@pytest.mark.parametrize(
    "swing, words",
    [
        # (an enormous period: I_G came out inf -- 'inf' in the output, NaN in the
        # forces, or an OverflowError, exit 3)
        ('period = "1e300 s", about = "B"', "absurd for a mechanism"),
        ('period = "1e150 s", about = "B"', "absurd for a mechanism"),
        ('period = 1e300, about = "B"', "absurd for a mechanism"),
        ('oscillations = "1 in 1e300 s", about = "B"', "absurd for a mechanism"),
        ('period = "1e6 s", about = "B"', "absurd for a mechanism"),
        ('period = "1e-300 s", about = "B"', "quicker than a point mass"),
        ('oscillations = "100 in 1 s", about = "B"', "quicker than a point mass"),
        ('oscillations = "0 in 40 s", about = "B"', "complete oscillations in a time"),
        ('oscillations = "21 in -40 s", about = "B"', "complete oscillations in a time"),
        ('oscillations = "nan in 40 s", about = "B"', "complete oscillations in a time"),
        ('period = "0 s", about = "B"', "a time"),
        ('period = "1.9 m", about = "B"', "a time"),
        ('oscillations = "21 in 40 s", period = "1.9 s", about = "B"', "one of them"),
        ('oscillations = "21 in 40 s"', "needs the point it swings about"),
        # (both: it said the swing "needs the point it swings about")
        ('oscillations = "21 in 40 s", pivot_distance = 600, about = "B"', "once"),
        ('oscillations = "21 in 40 s", about = "O"', "an end of AB"),
        ('oscillations = "21 in 40 s", pivot_distance = 0', "must be positive"),
        ('oscillations = "21 in 40 s", about = "B", inertia = "5 kg m^2"', "not with the swing"),
    ],
)
def test_a_bad_swing_is_one_line_naming_the_rod(swing, words, tmp_path, capsys):
    _refused_everywhere(
        _replaced(SWUNG, SWING, swing), tmp_path, capsys, "[masses] AB (line 35)", words
    )


def test_a_rod_hung_at_its_centre_of_mass_is_named_so(tmp_path, capsys):
    """G at B, the end it swings about: it said the swing 'is quicker than a point mass's at
    G, 2 pi sqrt(h / g) = 0 s'."""
    text = _replaced(SWUNG, 'along = 400, from = "A"', 'along = 1000, from = "A"')
    line = _refused_everywhere(text, tmp_path, capsys, "[masses] AB (line 35)")
    assert "G is at B" in line and "quicker" not in line, line


@pytest.mark.parametrize(
    "swing, period, h",
    [
        ('oscillations = "21 in 40 s", about = "B"', 40 / 21, 0.6),
        ('oscillations = "21 in 40 s", about = "A"', 40 / 21, 0.4),
        ('period = "2.5 s", pivot_distance = 650', 2.5, 0.65),
        ('oscillations = "21 oscillations in 40 seconds", about = "B"', 40 / 21, 0.6),
    ],
)
def test_the_swing_gives_the_compound_pendulums_inertia(swing, period, h):
    """The input torque with the swing's inertia equals that with I_G = m (g h T^2 / (4
    pi^2) - h^2) stated outright (the compound pendulum, by hand)."""
    k2 = 9.81 * h * period**2 / (4 * math.pi**2) - h * h
    swung = solve(parse_scene(_replaced(SWUNG, SWING, swing)))
    stated = solve(parse_scene(_replaced(SWUNG, SWING, f'inertia = "{60 * k2!r} kg m^2"')))
    assert math.isclose(swung.forces.input_torque, stated.forces.input_torque, rel_tol=1e-12)
    plain = solve(parse_scene(_replaced(SWUNG, SWING, 'inertia = "0 kg m^2"')))
    assert abs(swung.forces.input_torque - plain.forces.input_torque) > 1.0  # (the inertia counts)


# ------------------------------------------------------------------ strokes and areas

STROKE_LINE = "strokes = [-0.45e-3, -1.7e-3, 6.8e-3, -0.65e-3]"


@pytest.mark.parametrize(
    "strokes, words",
    [
        # (works of 3e306 J went through: 1.2e307 J a cycle, overflow warnings from numpy)
        ("strokes = [1e300, 1e300, 1e300, 1e300]", "absurd; check the scales"),
        ("strokes = [-1e6, -1e6, 1e7, -1e6]", "absurd; check the scales"),
        ("strokes = [0, 0, 0, 0]", "no net work"),
        ("strokes = []", "each stroke's work"),
        ("strokes = [1e-3, nan, 0, 0]", "each stroke's work"),
        ("strokes = [1, 2, 3]", "540 deg, not 720"),
    ],
)
def test_bad_strokes_are_one_line(strokes, words, tmp_path, capsys):
    text = _replaced(STROKES, STROKE_LINE, strokes)
    _refused_everywhere(text, tmp_path, capsys, "[turning_moment]", words)


@pytest.mark.parametrize("works", ['"1e300 J"', '"2e12 J"'])
def test_strokes_given_as_huge_energies_are_refused(works, tmp_path, capsys):
    text = _replaced(STROKES, STROKE_LINE, f'strokes = ["0 J", "-1 J", {works}, "0 J"]')
    text = _replaced(text, 'area_scale = "1 m^2 = 3 MN m"\n', "")
    _refused_everywhere(text, tmp_path, capsys, "[turning_moment] strokes", "absurd")


# ------------------------------------------------------------------ a second input's speed


@pytest.mark.parametrize(
    "second, key",
    [
        ('vs_C = "1 m/s at 30 deg"', "vs_C"),
        ('vs_C = "1 m/s at 210 deg"', "vs_C"),
        ('vs_C = "1 m/s up"', "vs_C"),
        # (a collar's words: "unknown unit 'm/s outward'")
        ('vs_C = "1 m/s outward"', "vs_C"),
        ('vs_C = "1 m/s towards D"', "vs_C"),
        ('vs_C = "1 m/s"\nas_C = "2 m/s^2 at 30 deg"', "as_C"),
    ],
)
def test_a_way_in_the_plane_for_sliding_along_a_turning_link_is_refused(
    second, key, tmp_path, capsys
):
    """The block C slides along the turning link ED: "at 30 deg" and "at 210 deg" (the
    opposite way) were both read as +1 m/s, the words dropped."""
    line = _refused_everywhere(
        SLOT.format(second=second), tmp_path, capsys, f"[input.second] {key}"
    )
    assert "signed along the link" in line and "from E towards D" in line, line


def test_a_slider_speed_signed_along_its_link_reverses_the_second_crank():
    """vs_C = +1 and -1 m/s: C's sliding found from the solved motion (the rate of |EC| by
    the velocities, d|EC|/dt = (v_C - v_E) . u) is the stated one."""
    for sdot in (1.0, -1.0):
        sol = solve(parse_scene(SLOT.format(second=f'vs_C = "{sdot} m/s"')))
        (ex, ey), (cx, cy) = sol.P["E"], sol.P["C"]
        d = math.hypot(cx - ex, cy - ey)
        u = ((cx - ex) / d, (cy - ey) / d)
        # the velocity of C less that of the point of ED under it (omega x EC)
        w = sol.W["ED"]
        rel = (sol.V["C"][0] + w * (cy - ey), sol.V["C"][1] - w * (cx - ex))
        assert math.isclose(rel[0] * u[0] + rel[1] * u[1], sdot, rel_tol=1e-9)


# ------------------------------------------------------------------ through a subprocess


def test_a_huge_period_through_the_command_line_is_exit_2_and_strict_json(tmp_path):
    f = tmp_path / "s.toml"
    f.write_text(_replaced(SWUNG, SWING, 'period = "1e150 s", about = "B"'), encoding="utf-8")
    r = subprocess.run(
        [sys.executable, "-m", "polygon_method", "solve", "--json", str(f)],
        capture_output=True,
        text=True,
        timeout=120,
        cwd=ROOT,
    )
    assert r.returncode == 2 and not r.stdout and len(r.stderr.splitlines()) == 1, r.stderr
    assert "[masses] AB (line 35)" in r.stderr and "Traceback" not in r.stderr
    ok = subprocess.run(
        [
            sys.executable,
            "-m",
            "polygon_method",
            "solve",
            "--json",
            str(BOOK / "hunt5_offset_slot_lever.toml"),
        ],
        capture_output=True,
        text=True,
        timeout=120,
        cwd=ROOT,
    )
    assert ok.returncode == 0, ok.stderr
    json.loads(ok.stdout, parse_constant=lambda x: pytest.fail(f"{x} in the JSON"))
    assert not NUMBER_WORD.search(ok.stdout.replace("at infinity", ""))


# ------------------------------------------------------------------ loads against a link


@pytest.mark.parametrize(
    "direction, words",
    [
        # (a point for a link: "no link M0.0 in [links]")
        ('"along M"', "M is not a link's two points"),
        ('"along CDE"', "CDE is not a link's two points"),
        ('"perpendicular to M, ccw"', "M is not a link's two points"),
        # (the word alone: "a direction along the link turns with the link and is not
        # read", which a load against a link now is)
        ('"along"', "'along CD' (from C towards D)"),
        ('"perpendicular to"', "'along CD' (from C towards D)"),
        ('"30 deg ccw from M"', "measured from what?"),
        ('"30 deg ccw from IDC"', "a dead centre is a position of the crank"),
        ('"along CZ"', "no link CZ in [links]"),
        ('"perpendicular to CD"', "does not say which side of CD"),
        ('"30 deg from CD"', "does not say which side of CD"),
        ('"-30 deg ccw from CD"', "not negative"),
        ('"along CD, ccw"', "cannot read"),
    ],
)
def test_a_load_against_no_link_is_one_line(direction, words, tmp_path, capsys):
    text = LINK_LOADS.format(m=direction, e="270", angle=60)
    _refused_everywhere(text, tmp_path, capsys, "[loads] M (line 29)", words)


# ------------------------------------------------------------------ check --tolerance


@pytest.mark.parametrize(
    "tolerances, words",
    [
        # (it said "a second tolerance in rad" for two given in degrees)
        (
            ["1 deg", "2 deg"],
            "'2 deg': a second tolerance for the answers in rad (the first '1 deg')",
        ),
        (["1 mm", "0.1 cm"], "(the first '1 mm')"),
        (["5%", "3%"], "a second per cent"),
        (["0%"], "between 0 and 100"),
        (["100%"], "between 0 and 100"),
        (["nan%"], "between 0 and 100"),
        (["-1 mm"], "a positive size"),
        (["0 deg"], "a positive size"),
        (["1 rad/s cw"], "a positive size"),
        (["1 N"], "neither a per cent"),
        (["1 mm lfet"], "neither a per cent"),
        ([""], "write a per cent"),
    ],
)
def test_a_bad_tolerance_is_one_line_and_writes_no_gradebook(tolerances, words, tmp_path, capsys):
    ans = tmp_path / "ann.toml"
    ans.write_text('[answers]\nv_R = "2.53 m/s"\nvs_A = "?"\n', encoding="utf-8")
    book = tmp_path / "g.csv"
    argv = ["check", str(BOOK / "hunt5_offset_slot_lever.toml"), str(ans)]
    for t in tolerances:
        argv += ["--tolerance", t]
    assert main([*argv, "--gradebook", str(book)]) == 2
    out, err = capsys.readouterr()
    assert not out and len(err.splitlines()) == 1 and "--tolerance" in err, err
    assert words in err, err
    assert not book.exists()


# ------------------------------------------------------------------ a class of today's scenes

CLASS = {
    "ann": '[answers]\nv_R = "2.53 m/s"\nomega_QB = "5.3 rad/s cw"\n',
    "bob": '[answers]\nv_R = "?"\n',
    "cat": '[answers]\nvs_A = "1 m/s at 30 deg"\n',
    "dan": '[answers]\nv_R = "nan m/s"\n',
    "eve": '[answers]\nv_R = "1e400 m/s"\n',
    "fay": '[answers]\ntorque = "98 N m cw"\n',
    "gus": '[answers]\ntolerance = "-5%"\nv_R = "2.5 m/s"\n',
    "hal": "[answers]\nv_R = [[[[[[[[[[1]]]]]]]]]]\n",
    "ida": 'v_R = "2.53 m/s"\n',
    "jon": '[answers]\nomega_QB = "? rad/s cw"\n',
}


@pytest.mark.parametrize(
    "scene",
    [
        "hunt5_offset_slot_lever.toml",
        "friction_each_slider_crank_pins.toml",
        "force_engine_rod_swung_as_pendulum.toml",
        "flywheel/press_frictional_losses.toml",
    ],
)
def test_a_class_of_careless_answer_files_is_graded_each_in_its_row(scene, tmp_path, capsys):
    """Every student has a row (graded, or why the file could not be read), whatever the
    others wrote; the JSON is strict and the gradebook written whole."""
    folder = tmp_path / "class"
    folder.mkdir()
    for name, text in CLASS.items():
        (folder / f"{name}.toml").write_text(text, encoding="utf-8")
    book = tmp_path / "g.csv"
    code = main(["check", "--json", str(BOOK / scene), str(folder), "--gradebook", str(book)])
    out, err = capsys.readouterr()
    assert code in (0, 1) and "Traceback" not in err, err
    data = json.loads(out, parse_constant=lambda x: pytest.fail(f"{x} in the JSON"))
    text = json.dumps(data)
    for name in CLASS:
        assert name in text, name
    rows = book.read_text(encoding="utf-8").splitlines()
    assert len(rows) >= 1 + len(CLASS), rows
    assert not NUMBER_WORD.search(book.read_text(encoding="utf-8").replace("nan m/s", ""))


# ------------------------------------------------------------------ dE_max as a part, a press's losses

PART = (BOOK / "flywheel/energy_fluctuation_part_of_the_work.toml").read_text()
PRESS = (BOOK / "flywheel/press_frictional_losses.toml").read_text()


@pytest.mark.parametrize(
    "part, words",
    [
        ('"0%"', "above 0 and below 1000%"),
        ('"-15%"', "above 0 and below 1000%"),
        # (refused as not "above 0")
        ('"1e300%"', "above 0 and below 1000%"),
        ('"nan%"', "cannot read"),
        ('"15 percent"', "unknown unit 'percent'"),
        ("0.15", "has no unit"),
    ],
)
def test_a_bad_part_of_the_work_is_one_line(part, words, tmp_path, capsys):
    text = _replaced(PART, 'dE_max = "15%"', f"dE_max = {part}")
    _refused_everywhere(text, tmp_path, capsys, "[turning_moment] dE_max (line 16)", words)


@pytest.mark.parametrize("part", ["15%", "150%", "193%"])
def test_a_part_of_the_work_is_that_part_of_a_cycles_work(part):
    """dE_max = Ce P (2 pi / w) for a revolution's cycle at the flywheel's mean speed (100
    rpm, 185 kW); a gas engine's Ce of 1.93 is a book's value, above one."""
    cyc = solve_cycle(parse_cycle(_replaced(PART, 'dE_max = "15%"', f'dE_max = "{part}"')))
    work = 185e3 * 2 * math.pi / (100 * 2 * math.pi / 60)
    assert math.isclose(cyc.dE_max, float(part[:-1]) / 100 * work, rel_tol=1e-12)
    # the flywheel of it: I = dE / (Cs w^2), Cs = 2 x 1 % (plus or minus)
    w = 100 * 2 * math.pi / 60
    assert math.isclose(cyc.inertia, cyc.dE_max / (0.02 * w * w), rel_tol=1e-12)


@pytest.mark.parametrize(
    "losses, words",
    [
        ('"-1/6"', "from 0 to below 1000%"),
        ('"1/0"', "from 0 to below 1000%"),
        ('"0/0"', "from 0 to below 1000%"),
        ("10", "from 0 to below 1000%"),
        ('"1/6 of the work"', "a part of the punching's work"),
        ("nan", "a part of the punching's work"),
    ],
)
def test_bad_losses_are_one_line(losses, words, tmp_path, capsys):
    text = _replaced(PRESS, 'losses = "1/6"', f"losses = {losses}")
    _refused_everywhere(text, tmp_path, capsys, "[press] losses (line 21)", words)


@pytest.mark.parametrize(
    "pins, at",
    [
        ('pins = { O = "30 mm", A = 0.08 }', "at O, 30 mm"),  # O's pin: 50 mm across
        ('pins = { B = "12.5 mm" }', "at B, 12.5 mm"),  # B's: 25 mm across, exactly
        ('pins = "20 mm"', "at A, 20 mm"),  # every pin: A's is 40 mm across
    ],
)
def test_a_friction_circle_no_smaller_than_its_pin_is_refused(pins, at, tmp_path, capsys):
    """Its radius is mu r with mu below 1: a circle as large as the pin itself was read."""
    text = _replaced(FRICTION, "pins = { O = 0.05, A = 0.08, B = 0.12 }", pins)
    line = _refused_everywhere(text, tmp_path, capsys, "[friction] pins (line 42)", at)
    assert "is not smaller than the pin itself" in line, line


def test_a_friction_circle_inside_its_pin_is_mu_r():
    """A circle stated as mu r of its pin gives the answer of the coefficient itself."""
    by_mu = solve(parse_scene(FRICTION))
    by_circle = solve(
        parse_scene(
            _replaced(
                FRICTION,
                "pins = { O = 0.05, A = 0.08, B = 0.12 }",
                'pins = { O = "1.25 mm", A = "1.6 mm", B = "1.5 mm" }',
            )
        )
    )
    assert math.isclose(by_mu.forces.input_torque, by_circle.forces.input_torque, rel_tol=1e-9)


@pytest.mark.parametrize(
    "scene, argv",
    [
        ("flywheel/areas_multicylinder.toml", ["sweep", "--csv", "x.csv"]),
        ("flywheel/press_frictional_losses.toml", ["sweep", "--csv", "x.csv"]),
        ("flywheel/energy_fluctuation_part_of_the_work.toml", ["sweep", "--csv", "x.csv"]),
        ("flywheel/energy_fluctuation_part_of_the_work.toml", ["draw", "-o", "x.svg"]),
        ("flywheel/energy_fluctuation_part_of_the_work.toml", ["page", "-o", "x.html"]),
    ],
)
def test_a_diagram_with_nothing_to_tabulate_or_draw_names_its_file(scene, argv, tmp_path, capsys):
    """Areas, a press, a fluctuation stated alone: no curve. The refusal named only the
    option ('polygon-method sweep: --csv: the diagram is given as areas ...'), not the
    scene that has no curve; the file there before is left as it was."""
    out = tmp_path / argv[-1]
    out.write_text("a file of the teacher's", encoding="utf-8")
    path = str(BOOK / scene)
    assert main([argv[0], path, *argv[1:-1], str(out)]) == 2
    stdout, err = capsys.readouterr()
    assert not stdout and len(err.splitlines()) == 1, err
    assert f"{Path(scene).name}: {argv[1]}: " in err, err
    assert out.read_text(encoding="utf-8") == "a file of the teacher's"


@pytest.mark.parametrize(
    "pins, key",
    [
        ('pins = "0.1"', "pins = '0.1'"),  # (a 0.1 mm circle, where a coefficient was meant)
        ('pins = { O = "0.08", A = 0.08 }', "pins.O = '0.08'"),
        ('pins = { O = "2" }', "pins.O = '2'"),
    ],
)
def test_a_number_in_quotes_at_the_pins_is_no_circle(pins, key, tmp_path, capsys):
    """A coefficient in quotes was read as a friction circle of that many millimetres."""
    text = _replaced(FRICTION, "pins = { O = 0.05, A = 0.08, B = 0.12 }", pins)
    line = _refused_everywhere(text, tmp_path, capsys, "[friction] pins (line 42)", key)
    assert "takes its unit" in line and "a bare number" in line, line


@pytest.mark.parametrize("mu", [0.0, 0.1, 0.3, 0.45])
@pytest.mark.parametrize("angle", [80, 250, 300])
def test_the_slides_friction_by_hand_on_a_short_rod(mu, angle):
    """A short rod (OA 80, AB 90 mm), no masses, 1.5 kN to the left on the block, mu at
    the slide alone: the block's balance along the path T (e_x - mu s |e_y|) = 1500 N (T
    the rod's thrust along A -> B, s the way the block slides), the crank's torque T (A x
    e) -- the books' slider crank with friction, by hand."""
    text = _replaced(FRICTION, FRICTION_LINES, f"guides = {mu}")
    text = _replaced(text, "AB = 320", "AB = 90")
    sol = solve(parse_scene(_replaced(text, "angle = 120", f"angle = {angle}")))
    r, ln, th = 0.08, 0.09, math.radians(angle)
    ax, ay = r * math.cos(th), r * math.sin(th)
    root = math.sqrt(ln * ln - ay * ay)
    ex, ey = root / ln, -ay / ln
    vb = (-r * math.sin(th) - r * r * math.sin(th) * math.cos(th) / root) * -20.0
    s = math.copysign(1.0, vb)
    thrust = 1500.0 / (ex - mu * s * abs(ey))
    torque = thrust * (ax * ey - ay * ex)  # (ccw +)
    assert math.isclose(sol.forces.input_torque, torque, rel_tol=1e-9), (
        sol.forces.input_torque,
        torque,
    )


@pytest.mark.parametrize("angle", ['"60 deg from the vertical, cw"', "10", "200"])
def test_the_offset_slots_forces_agree_with_virtual_power(angle):
    """A 10 kg lever QB (a point mass at its middle) and 500 N against the ram R: the crank's
    torque by D'Alembert and the offset slot's reactions equals the power balance
    tau w = -(F_R . v_R - m a_G . v_G), from the solved velocities and accelerations."""
    text = OFFSET.split("[answers]")[0].replace(
        'angle = "60 deg from the vertical, cw"', f"angle = {angle}"
    )
    text += '[masses]\nQB = { mass = "10 kg" }\n[loads]\nR = { force = "500 N", direction = "to the left" }\n'
    sol = solve(parse_scene(text))
    vg = [(sol.V["Q"][i] + sol.V["B"][i]) / 2 for i in (0, 1)]
    ag = [(sol.A["Q"][i] + sol.A["B"][i]) / 2 for i in (0, 1)]
    power = -500.0 * sol.V["R"][0] - 10.0 * (ag[0] * vg[0] + ag[1] * vg[1])
    assert math.isclose(sol.forces.input_torque, -power / sol.W["OA"], rel_tol=1e-9)


def test_a_swing_under_an_absurd_gravity_names_g(tmp_path, capsys):
    text = _replaced(
        SWUNG, 'B = { mass = "80 kg" }', 'B = { mass = "80 kg" }\n[gravity]\ng = "1e12 m/s^2"'
    )
    line = _refused_everywhere(text, tmp_path, capsys, "[masses] AB (line 35)", "absurd")
    assert "(g = 1e+12 m/s^2)" in line, line
