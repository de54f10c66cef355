"""A character outside ASCII where TOML or a name expects ASCII is named in the one line of
the refusal, with its code point and the plain character it may stand for: a Greek capital
Eta typed for H, a no-break space before '=', a full-width digit, a stray byte-order mark
mid-file, an accented letter in a table's header, a Greek Beta in a quoted link name (the
line had said only "TOML syntax error: invalid statement", or "'Η' is not a point name" of
what looks like H). Through solve, every command that reads the scene, and an answer file."""

from __future__ import annotations

import pytest

from polygon_method.cli import main

SCENE = """title = "Four-bar"
[ground]
A = [0, 0]
D = [100, 0]
[links]
AB = 40
BC = 90
CD = 70
[input]
crank = "AB"
angle = 60
speed = "10 rad/s ccw"
"""

# (what is written for what, the line it is on, the words the refusal must hold)
CASES = [
    ("D = [100, 0]", "\u0397 = [100, 0]", 4, ["U+0397 GREEK CAPITAL LETTER ETA"]),
    ("CD = 70", "CD\u00a0= 70", 8, ["U+00A0 NO-BREAK SPACE", "written for ' '"]),
    ("BC = 90", "BC = \uff19\uff10", 7, ["U+FF19 FULLWIDTH DIGIT NINE", "written for '9'"]),
    ("BC = 90", "\ufeffBC = 90", 7, ["U+FEFF ZERO WIDTH NO-BREAK SPACE"]),
    ("[links]", "[l\u00ednks]", 5, ["U+00ED LATIN SMALL LETTER I WITH ACUTE"]),
    ("AB = 40", '"A\u0392" = 40', 6, ["[links]", "U+0392 GREEK CAPITAL LETTER BETA"]),
    ("D = [100, 0]", '"\u0397" = [100, 0]', 4, ["[ground]", "U+0397 GREEK CAPITAL LETTER ETA"]),
]


@pytest.mark.parametrize("old,new,line,words", CASES, ids=[c[1] for c in CASES])
@pytest.mark.parametrize("command", ["solve", "steps", "linkage", "centres"])
def test_a_character_outside_ascii_is_named_in_one_line(
    tmp_path, capsys, old, new, line, words, command
):
    path = tmp_path / "s.toml"
    path.write_text(SCENE.replace(old, new), encoding="utf-8")
    assert main([command, str(path)]) == 2
    out, err = capsys.readouterr()
    assert not out and err.count("\n") == 1, err
    assert f"line {line}" in err, err
    for w in words:
        assert w in err, err


def test_an_answer_file_with_a_greek_key_is_named(tmp_path, capsys):
    scene = tmp_path / "s.toml"
    scene.write_text(SCENE, encoding="utf-8")
    answers = tmp_path / "a.toml"
    answers.write_text('[answers]\nv_\u0392 = "1 m/s"\n', encoding="utf-8")
    assert main(["check", str(scene), str(answers)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "line 2" in err, err
    assert "U+0392 GREEK CAPITAL LETTER BETA" in err, err
