"""The ``[answers]`` table's refusals a teacher meets: an answer file's own keys
(``student``, ``variant``, ``title``) written inside ``[answers]`` get one line saying
where they belong; a sub-table ``[answers.extra]`` is refused at its line."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from polygon_method import parse_scene
from polygon_method.common.errors import SceneError
from polygon_method.scene import parse_answers
from scenes import seed

SCENE = seed(after='[answers]\nv_B = "0.5 m/s"\n')


def _refusal(fn):
    with pytest.raises(SceneError) as exc:
        fn()
    return exc.value


def test_student_inside_an_answer_files_answers_is_sent_above_the_heading():
    sc = parse_scene(seed())
    text = '[answers]\nv_C = "0.3 m/s"\nstudent = "Ann Smith"\n'
    err = _refusal(lambda: parse_answers(text, sc, file="ann.toml"))
    assert err.line == 3
    assert "student" in str(err) and "above the [answers] heading" in err.message
    assert "unknown answer key" not in err.message
    assert err.message.count("\n") == 0


@pytest.mark.parametrize("key", ["student", "name", "variant"])
def test_a_students_key_inside_a_scenes_answers_is_sent_to_the_answer_file(key):
    text = seed(after=f'[answers]\nv_B = "0.5 m/s"\n{key} = "07"\n')
    err = _refusal(lambda: parse_scene(text, file="s.toml"))
    assert err.line == text.splitlines().index(f'{key} = "07"') + 1
    assert "answer file, above its [answers] heading" in err.message
    assert "unknown answer key" not in err.message


def test_a_title_inside_a_scenes_answers_is_sent_to_the_top_of_the_scene():
    text = seed(after='[answers]\ntitle = "Four-bar"\n')
    err = _refusal(lambda: parse_scene(text))
    assert "top of the scene" in err.message and err.line == text.count("\n")


@pytest.mark.parametrize(
    "table",
    [
        '[answers]\nv_B = "0.5 m/s"\n\n[answers.extra]\nv_C = "0.3 m/s"\n',
        '[answers]\nv_B = "0.5 m/s"\nextra.v_C = "0.3 m/s"\n',
        '[answers]\nv_B = "0.5 m/s"\nextra = { v_C = "0.3 m/s" }\n',
    ],
)
def test_a_table_inside_answers_is_refused_at_its_line(table):
    text = seed(after=table)
    err = _refusal(lambda: parse_scene(text))
    lines = text.splitlines()
    want = next(i for i, s in enumerate(lines, 1) if "extra" in s)
    assert err.line == want
    assert "[answers.extra]" in str(err) and "unknown answer key" not in err.message


def test_an_answer_files_sub_table_has_its_line_too():
    sc = parse_scene(seed())
    text = '[answers]\nv_C = "0.3 m/s"\n[answers.extra]\nv_B = "1 m/s"\n'
    err = _refusal(lambda: parse_answers(text, sc, file="ann.toml"))
    assert err.line == 3


def test_the_command_line_says_it_in_one_line(tmp_path):
    scene = tmp_path / "s.toml"
    scene.write_text(seed())
    ans = tmp_path / "ann.toml"
    ans.write_text('[answers]\nv_C = "0.3 m/s"\nstudent = "Ann"\n')
    out = subprocess.run(
        [sys.executable, "-m", "polygon_method", "check", str(scene), str(ans)],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 2 and "Traceback" not in out.stderr
    assert out.stderr.count("\n") == 1 and "line 3" in out.stderr
    assert "above the [answers] heading" in out.stderr


FLYWHEEL = Path(__file__).resolve().parent.parent / "worked_problems" / "flywheel"


@pytest.mark.parametrize(
    "tail, says",
    [
        ('student = "Ann"\n', "above its [answers] heading"),
        ('[answers.extra]\nT_mean = "1 N m"\n', "takes no table inside it"),
    ],
)
def test_a_turning_moment_diagrams_answers_say_the_same(tmp_path, tail, says):
    """The diagram's own [answers] reader keeps the one rule (scene/energy_flywheel.py)."""
    text = (FLYWHEEL / "engine_areas_rim.toml").read_text().rstrip("\n") + "\n" + tail
    path = tmp_path / "d.toml"
    path.write_text(text)
    out = subprocess.run(
        [sys.executable, "-m", "polygon_method", "check", str(path)],
        capture_output=True,
        text=True,
    )
    want = len(text.splitlines()) - tail.count("\n") + 1
    assert out.returncode == 2 and out.stderr.count("\n") == 1
    assert says in out.stderr and f"(line {want})" in out.stderr


def test_a_diagrams_answer_file_sends_the_student_above_the_heading(tmp_path):
    ans = tmp_path / "ann.toml"
    ans.write_text('[answers]\nT_mean = "1 N m"\nstudent = "Ann"\n')
    out = subprocess.run(
        [
            sys.executable,
            "-m",
            "polygon_method",
            "check",
            str(FLYWHEEL / "engine_areas_rim.toml"),
            str(ans),
        ],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 2 and "line 3" in out.stderr
    assert "above the [answers] heading" in out.stderr


@pytest.mark.parametrize("value", ["1 mm", "1 deg", "0.01 m/s", "1 N m", "2 rad/s^2"])
def test_an_absolute_tolerance_in_a_file_is_sent_to_the_command_line(value):
    """``check --tolerance "1 mm"`` takes an absolute tolerance; a file's ``tolerance`` is
    a per cent: the refusal says where the absolute one goes (it said "'mm' is a unit of
    length, not of percent")."""
    sc = parse_scene(seed())
    text = f'[answers]\ntolerance = "{value}"\nv_C = "0.3 m/s"\n'
    err = _refusal(lambda: parse_answers(text, sc, file="ann.toml"))
    assert err.line == 2 and err.message.count("\n") == 0
    assert f"--tolerance '{value}'" in err.message and "per cent" in err.message
    ok = parse_answers(text.replace(value, "3%"), sc, file="ann.toml")
    assert ok is not None
