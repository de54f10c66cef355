"""Every scene in ``tests/bad_scenes/`` is refused with one clear line and exit code 2.

The expected message fragment, location and error class of each scene are written in the
scene's first comment lines (see ``tests/bad_scenes/README.md``); they were worked out from
the scene by hand, not copied from the tool.
"""

from __future__ import annotations

import re
import tomllib
from pathlib import Path

import pytest

from polygon_method.common import errors
from polygon_method.cli import main
from polygon_method.common.errors import (
    AssemblyError,
    MobilityError,
    PolygonMethodError,
    SceneError,
    SingularStepError,
)
from polygon_method.scene import load_scene, parse_scene
from polygon_method.motion.solution import solve

HERE = Path(__file__).resolve().parent / "bad_scenes"
SIDECAR = tomllib.loads((HERE / "_expect.toml").read_text(encoding="utf-8"))


def _expectation(path: Path) -> dict:
    if path.name in SIDECAR:
        return SIDECAR[path.name]
    head = path.read_bytes()[:1000].decode("utf-8", errors="replace")
    found = dict(re.findall(r"^# (expect|where|error): (.*?)\s*$", head, flags=re.M))
    return found


SCENES = sorted(p for p in HERE.glob("*.toml") if not p.name.startswith("_"))
IDS = [p.stem for p in SCENES]


def test_corpus_is_large_and_every_scene_says_what_it_expects():
    assert len(SCENES) >= 40
    for path in SCENES:
        exp = _expectation(path)
        assert set(exp) == {"expect", "where", "error"}, path.name
        assert exp["error"] in {
            "SceneError",
            "MobilityError",
            "AssemblyError",
            "SingularStepError",
        }, path.name
    assert set(SIDECAR) <= {p.name for p in SCENES}


def _in_answers(path) -> bool:
    """A fault in ``[answers]``, which only the commands that check answers read."""
    return _expectation(path)["where"].startswith("[answers]")


def _command(path, tmp_path):
    """``solve``; for a fault in ``[variants]``, ``variants`` (the one command that reads
    that table: the others leave it unread); for one in ``[answers]``, ``check`` (solve,
    steps, draw and the others leave that table unread too)."""
    if path.stem.startswith("variants_"):
        return ["variants", str(path), "--count", "2", "-o", str(tmp_path / "out")]
    if _in_answers(path):
        return ["check", str(path)]
    return ["solve", str(path)]


@pytest.mark.parametrize("path", SCENES, ids=IDS)
def test_cli_solve_prints_one_line_and_exits_2(path, capsys, tmp_path):
    exp = _expectation(path)
    argv = _command(path, tmp_path)
    code = main(argv)
    out, err = capsys.readouterr()
    assert code == 2, err
    assert out == ""
    assert err.endswith("\n") and err.count("\n") == 1, err
    line = err.rstrip("\n")
    assert line.startswith(f"polygon-method {argv[0]}: ")
    assert str(path) in line  # names the file
    assert exp["expect"] in line
    if exp["where"] != "-":
        assert exp["where"] in line
    assert "Traceback" not in line and "internal error" not in line


_DRAWN = [p for p in SCENES if not p.stem.startswith("variants_") and not _in_answers(p)]


@pytest.mark.parametrize("path", _DRAWN, ids=[p.stem for p in _DRAWN])
def test_cli_draw_writes_nothing(path, tmp_path, capsys):
    target = tmp_path / "out.svg"
    code = main(["draw", str(path), "-o", str(target)])
    out, err = capsys.readouterr()
    assert code == 2, err
    assert err.count("\n") == 1 and _expectation(path)["expect"] in err
    assert not target.exists()
    assert list(tmp_path.iterdir()) == []  # no half-written temporary file either


@pytest.mark.parametrize("path", SCENES, ids=IDS)
def test_api_raises_one_family_with_the_location(path):
    exp = _expectation(path)
    with pytest.raises(PolygonMethodError) as info:
        solve(load_scene(path))
    exc = info.value
    assert type(exc).__name__ == exp["error"]
    assert isinstance(exc, getattr(errors, exp["error"]))
    assert exc.file == str(path)
    assert exp["expect"] in exc.message
    if exp["where"] != "-":
        where = " ".join(str(x) for x in (exc.key, exc.line, exc.step) if x is not None)
        assert exc.key or exc.step, "a location: table/key or step"
        for part in re.split(r" \(line (\d+)\)", exp["where"]):
            if part.isdigit():
                assert exc.line == int(part)
            elif part:
                assert part in f"{exc.key} {exc.step}", where
    # the CLI prints exactly this line
    assert str(path) in exc.one_line() and "\n" not in exc.one_line()


COMMANDS = [
    ["plan"],
    ["steps"],
    ["check"],
    ["linkage"],
    ["sweep", "--csv", "OUT.csv"],
    ["solve", "--json"],
]


@pytest.mark.parametrize("path", SCENES, ids=IDS)
def test_every_command_refuses_cleanly(path, tmp_path, capsys):
    """A fault of the scene stops every command; one of the instant (cannot assemble, a
    toggle) may leave plan, linkage and sweep working. A fault in ``[variants]`` stops the
    commands that read that table (``check``, which finds a student's variant, and
    ``variants``); the others do not read it and work; so does a fault in ``[answers]``,
    which only ``check`` reads. Never an internal error."""
    scene_fault = _expectation(path)["error"] in ("SceneError", "MobilityError")
    in_variants = path.stem.startswith("variants_") or _in_answers(path)
    for i, cmd in enumerate(COMMANDS):
        where = tmp_path / str(i)
        where.mkdir()
        argv = [cmd[0], str(path)] + [str(where / a) if a == "OUT.csv" else a for a in cmd[1:]]
        code = main(argv)
        out, err = capsys.readouterr()
        if in_variants:
            assert code == (2 if cmd[0] == "check" else 0), (cmd, err)
        assert code in ((2,) if scene_fault else (0, 2)) or in_variants, (cmd, err)
        if code == 2:
            assert out == "" and err.count("\n") == 1, (cmd, err)
            assert list(where.iterdir()) == [], cmd


def test_error_family():
    assert issubclass(SceneError, PolygonMethodError)
    assert issubclass(MobilityError, SceneError)
    assert issubclass(AssemblyError, PolygonMethodError)
    assert issubclass(SingularStepError, PolygonMethodError)
    assert not issubclass(AssemblyError, SceneError)


def test_parse_scene_without_a_file_still_names_key_and_line():
    text = (HERE / "length_negative.toml").read_text(encoding="utf-8")
    with pytest.raises(SceneError) as info:
        parse_scene(text)
    exc = info.value
    assert exc.file is None and exc.key == "[links] BC" and exc.line == 9
    assert exc.one_line() == "[links] BC (line 9): length must be positive, got -66"


def test_step_errors_carry_the_step_and_no_key():
    with pytest.raises(AssemblyError) as info:
        solve(load_scene(HERE / "cannot_assemble_short.toml"))
    assert info.value.step.startswith("step 2 ")
    with pytest.raises(SingularStepError) as info:
        solve(load_scene(HERE / "toggle_at_stated_angle.toml"))
    assert info.value.step.startswith("step 2 ")


@pytest.mark.parametrize(
    "argv, fragment",
    [
        (["solve", "no/such/scene.toml"], "no such file"),
        (["solve", "."], "is a directory"),
        (["plan", str(HERE / "mobility_under_fivebar.toml")], "under-constrained"),
        (["plan", str(HERE / "unit_typo_rmp.toml")], "did you mean 'rpm'"),
    ],
)
def test_other_commands_and_missing_files(argv, fragment, capsys):
    assert main(argv) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and fragment in err
