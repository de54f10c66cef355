"""Small things that were silently wrong: a link's force lost beside its torque, an
assembly hint as near to both positions, a negative speed marked right, an answer file's
duplicate key without its name."""

from __future__ import annotations

import pytest

from polygon_method import AssemblyError, SceneError, parse_scene, solve
from polygon_method.check import check_answers
from polygon_method.solver.compiler import compile_plan
from polygon_method.steps import Context
from polygon_method.scene import parse_answers

from scenes import FOURBAR


def test_a_link_with_a_torque_and_a_force_is_refused():
    with pytest.raises(SceneError, match="force under the name of the point"):
        parse_scene(
            FOURBAR + '[loads]\nCD = { torque = "20 N m cw", force = "2 kN", direction = 0 }\n'
        )


def test_an_assembly_hint_about_as_near_to_both_positions_is_refused():
    sc = parse_scene(FOURBAR)
    c_up = solve(sc).P["C"]
    # the two positions of C: their midpoint, moved 1 % of the way towards one of them
    st = compile_plan(sc).steps[1]
    (mx, my), (hx, hy) = st.candidates(dict(solve(sc).P), Context(sc.input.angle, 0.0, 0.0))
    mid = ((mx + 0.01 * hx) * 1e3, (my + 0.01 * hy) * 1e3)
    with pytest.raises(AssemblyError, match="matches neither position"):
        solve(parse_scene(FOURBAR + f"[assembly]\nC = [{mid[0]:.6f}, {mid[1]:.6f}]\n"))
    near = (c_up[0] * 1e3 + 3.0, c_up[1] * 1e3 + 3.0)  # a rough reading near the upper one
    got = solve(parse_scene(FOURBAR + f"[assembly]\nC = [{near[0]:.3f}, {near[1]:.3f}]\n"))
    assert got.P["C"] == pytest.approx(c_up, rel=1e-12)


def test_a_negative_speed_is_wrong_and_named():
    sc = parse_scene(FOURBAR)
    sol = solve(sc)
    v = sol.speed("C")
    tol, answers = parse_answers(f'[answers]\nv_C = "{-v:.6f} m/s"\n', sc)
    verdict = check_answers(sol, answers, tol)[0]
    assert not verdict.ok and verdict.mistake == "negative_magnitude"
    assert "never negative" in verdict.diagnosis


def test_a_duplicate_key_in_an_answer_file_is_named():
    sc = parse_scene(FOURBAR)
    with pytest.raises(SceneError) as err:
        parse_answers('[answers]\nv_C = "0.4 m/s"\nv_C = "0.5 m/s"\n', sc, file="a.toml")
    line = err.value.one_line()
    assert "duplicate key v_C" in line and "line 3" in line


def test_errors_the_plan_finds_name_the_line(tmp_path):
    from polygon_method import load_scene

    path = tmp_path / "s.toml"
    path.write_text(FOURBAR.replace("[input]", "[assembly]\nC = [1000, 1000]\n[input]"))
    with pytest.raises(AssemblyError) as err:
        solve(load_scene(path))
    assert "[assembly] C (line 9)" in err.value.one_line()
    path.write_text(FOURBAR.replace("CD = 56", "CD = 56\nBD = 70"))
    with pytest.raises(SceneError) as err:
        solve(load_scene(path))
    assert "[links] BD (line 8)" in err.value.one_line()


def test_dotted_keys_are_located_too(tmp_path):
    from polygon_method import load_scene

    path = tmp_path / "dotted.toml"
    path.write_text(
        "ground.A = [0, 0]\nground.D = [100, 0]\nlinks.AB = 50\nlinks.BC = -66\n"
        'links.CD = 56\ninput.crank = "AB"\ninput.angle = 60\n'
        'input.speed = "10.5 rad/s cw"\n'
    )
    with pytest.raises(SceneError) as err:
        load_scene(path)
    assert "[links] BC (line 4)" in err.value.one_line()


def _lever(length, gap, angle=90.0):
    """Crank O2-A of 100 mm about O2 = (0, 100 + gap): at 270 deg, A is ``gap`` mm above the
    lever's pivot O4 = (0, 0); the lever O4-P is ``length`` mm long."""
    return parse_scene(f"""
[ground]
O2 = [0, {100 + gap!r}]
O4 = [0, 0]
[links]
"O2-A" = 100
"O4-P" = {length!r}
[sliders]
A = {{ along = "O4-P" }}
[input]
crank = "O2-A"
angle = {angle!r}
speed = "10 rad/s ccw"
""")


def test_the_block_near_the_pivot_is_judged_against_the_crank_not_the_lever():
    """A 5 m lever with its block 3.5 mm from the pivot (a 100 mm crank): the lever's
    length does not make the block's offset any less exact, so it is solved, and agrees with
    the 50-digit reference; the same offset on a 100 mm lever has the same condition. A block
    0.05 mm from the pivot (5e-4 of the crank) is refused, whatever the lever."""
    import math

    from polygon_method import SingularStepError

    from reference import reference_solution

    long_, short = _lever(5000.0, 3.5, 270.0), _lever(100.0, 3.5, 270.0)
    a, b = solve(long_), solve(short)
    assert a.conditions[1] == pytest.approx(0.035, rel=1e-9)
    assert b.conditions[1] == pytest.approx(0.035, rel=1e-9)
    ref = reference_solution(long_, a.P)
    scale = max(math.hypot(*a.V[p]) for p in a.V)
    for p in ("A", "P"):
        for i in (0, 1):
            assert abs(a.V[p][i] - float(ref["velocities"][p][i])) <= 1e-9 * scale
    w = float(ref["omega"]["O4-P"])
    assert a.W["O4-P"] == pytest.approx(w, rel=1e-9)
    for length in (100.0, 5000.0):
        with pytest.raises(SingularStepError, match="pivot"):
            solve(_lever(length, 0.05, 270.0))


@pytest.mark.parametrize("line", ["source = 5", "notes = [1, 2]", "notes = { a = 1 }"])
def test_free_text_that_is_not_text_is_refused_on_its_line(tmp_path, line):
    """``source`` and ``notes`` are free text: a number, a list or a table is a slip that
    was silently ignored."""
    from polygon_method import load_scene

    path = tmp_path / "s.toml"
    path.write_text(line + "\n" + FOURBAR)
    with pytest.raises(SceneError) as err:
        load_scene(path)
    key = line.split()[0]
    assert f"{key} (line 1)" in err.value.one_line() and "string" in err.value.one_line()


def test_every_integer_beyond_64_bits_is_written_with_a_long_run():
    """The scene reader walks its values for integers beyond TOML's 64 bits only where the
    text has a run of 16 digits: every such integer, in every way TOML writes integers
    (decimal, with underscores, hex, octal, binary), has one."""
    import random

    from polygon_method.scene.reading import _has_long_run

    rnd = random.Random(5)
    values = [1 << 63, (1 << 63) + 1, -(1 << 63) - 1, 10**19, 10**400]
    values += [rnd.randrange(1 << 63, 1 << 200) for _ in range(200)]
    for v in values:
        a = abs(v)
        for text in (
            str(v),
            f"{v:_}",
            f"0x{a:x}",
            f"0o{a:o}",
            f"0o{a:_o}",
            f"0x{a:_x}",
            f"0b{a:b}",
            f"0b{a:_b}",
        ):
            assert _has_long_run(f"BC = {text}"), text
    assert not _has_long_run('BC = 66\nspeed = "10.5 rad/s cw"')


def test_the_long_run_is_found_as_the_regular_expression_finds_it():
    """The run is looked for in the text's bytes (one translation, where a regular
    expression tries every position); the regular expression ``[0-9A-Fa-f_]{16,}`` is the
    reference, on random texts of digits, letters, non-ASCII characters (whose UTF-8 bytes
    are no digits) and lone surrogates."""
    import random
    import re

    from polygon_method.scene.reading import _has_long_run

    reference = re.compile(r"[0-9A-Fa-f_]{16,}")
    rnd = random.Random(7)
    alphabet = '0123456789abcdefABCDEF_ gxyz=\n"é中\u00e9\ud800\U0001f600'
    found = 0
    for _ in range(3000):
        text = "".join(
            rnd.choice(alphabet) if rnd.random() < 0.3 else rnd.choice("0123abcF_")
            for _ in range(rnd.randrange(10, 60))
        )
        want = reference.search(text) is not None
        found += want
        assert _has_long_run(text) == want, repr(text)
    assert 300 < found < 2700  # both answers drawn often


def test_an_integer_beyond_64_bits_in_hex_or_with_underscores_is_refused():
    for text in ("0x1_0000_0000_0000_0000", "9_223_372_036_854_775_808"):
        with pytest.raises(SceneError, match="beyond TOML's 64-bit integers"):
            parse_scene(FOURBAR.replace("BC = 66", f"BC = {text}"))


def test_a_negative_number_in_exponent_form_is_an_option_s_value(capsys):
    """``--from -1e1`` was read as an unknown option (argparse knows -10, not -1e1); it is
    the same sweep as ``--from -10``."""
    from polygon_method.cli import main

    scene = "worked_problems/fourbar_crank_acceleration.toml"
    assert main(["sweep", scene, "--from", "-10", "--to", "10", "--step", "10"]) == 0
    plain = capsys.readouterr().out
    assert main(["sweep", scene, "--from", "-1e1", "--to", "1e1", "--step", "1e1"]) == 0
    assert capsys.readouterr().out == plain and "3 of 3 crank angles" in plain


def test_a_two_letter_name_is_split_as_the_regular_expressions_split_it():
    """``split_name`` reads two capitals at once; every other name by the expressions of a
    link's name and a point's name, which are the reference here for every name of two
    characters drawn from letters, digits, dashes, spaces and non-ASCII letters."""
    import string

    from polygon_method.scene.records import _LINK_NAME, POINT_NAME, split_name

    def reference(name):
        if not _LINK_NAME.match(name) or name.endswith("-"):
            return ()
        return tuple(POINT_NAME.findall(name))

    chars = string.ascii_letters + string.digits + "-_ \u00c4\u00c9\u00df\u01c5\n"
    names = [a + b for a in chars for b in chars]
    assert sum(bool(reference(n)) for n in names) > 700  # the fast road taken, and not
    for name in names:
        assert split_name(name) == reference(name), repr(name)
