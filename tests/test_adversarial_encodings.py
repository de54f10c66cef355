"""A scene or an answer file saved as UTF-16 or UTF-32 (Windows Notepad's "Unicode", with a
byte-order mark or without) is told its encoding in one line and asked for UTF-8: it had
been called "not a text file (it holds binary data)"; binary data is still called so."""

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

ENCODINGS = [
    ("utf-16", "UTF-16 text (little-endian, with a byte-order mark)"),
    ("utf-16-le", "UTF-16 text (little-endian)"),
    ("utf-16-be", "UTF-16 text (big-endian)"),
    ("utf-32", "UTF-32 text (little-endian, with a byte-order mark)"),
]


@pytest.mark.parametrize("encoding,words", ENCODINGS)
@pytest.mark.parametrize("command", ["solve", "steps", "sweep", "draw"])
def test_a_wide_scene_is_told_its_encoding(tmp_path, capsys, encoding, words, command):
    path = tmp_path / "s.toml"
    path.write_bytes(SCENE.encode(encoding))
    argv = [command, str(path)] + (["-o", str(tmp_path / "d.svg")] if command == "draw" else [])
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert not out and err.count("\n") == 1
    assert f"{words}: save the scene as UTF-8" in err, err
    assert list(tmp_path.iterdir()) == [path]


@pytest.mark.parametrize("encoding,words", ENCODINGS)
def test_a_wide_answer_file_is_told_its_encoding_by_check_and_page(
    tmp_path, capsys, encoding, words
):
    scene = tmp_path / "s.toml"
    scene.write_text(SCENE, encoding="utf-8")
    answers = tmp_path / "a.toml"
    answers.write_bytes('[answers]\nv_B = "0.4 m/s"\n'.encode(encoding))
    for argv in (
        ["check", str(scene), str(answers)],
        ["page", str(scene), "--answers", str(answers), "-o", str(tmp_path / "p.html")],
    ):
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and f"{words}: save the answers as UTF-8" in err, err
    assert not (tmp_path / "p.html").exists()


def test_binary_data_is_still_binary(tmp_path, capsys):
    path = tmp_path / "s.toml"
    path.write_bytes(bytes(range(256)) * 4)
    assert main(["solve", str(path)]) == 2
    assert "not a text file (it holds binary data)" in capsys.readouterr().err
