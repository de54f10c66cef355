"""The flywheel chapter's textbook problems (tests/textbook/flywheel/*.toml): each a book's
kind of problem with made-up numbers, its answers worked by hand in the file's comment (the
book's method, rounded as a book prints them), held within the answers' tolerance."""

from pathlib import Path

import pytest

from polygon_method.check.energy import cycle_verdicts
from polygon_method.cli import main
from polygon_method.forces.flywheel_cycle import solve_cycle
from polygon_method.scene.energy import cycle_from_text

HERE = Path(__file__).resolve().parent / "textbook" / "flywheel"
FILES = sorted(HERE.glob("*.toml"))


def test_the_corpus_holds_every_kind():
    kinds = {}
    for f in FILES:
        c = solve_cycle(cycle_from_text(f.read_text(encoding="utf-8"), str(f)))
        kinds[c.form] = kinds.get(c.form, 0) + 1
    assert len(FILES) >= 10
    assert set(kinds) == {"areas", "law", "table", "press", "strokes", "energy"}


@pytest.mark.parametrize("path", FILES, ids=[f.stem for f in FILES])
def test_every_answer_of_the_book_is_right(path, capsys):
    scene = cycle_from_text(path.read_text(encoding="utf-8"), str(path))
    assert scene.answers and scene.tolerance is not None
    assert "answers worked by hand" in (scene.source or "")
    verdicts = cycle_verdicts(scene, solve_cycle(scene), scene.answers, scene.tolerance)
    wrong = [(v.key, v.raw, v.correct) for v in verdicts if not v.ok]
    assert not wrong
    assert main(["check", str(path)]) == 0
    assert "WRONG" not in capsys.readouterr().out


WORKED = sorted((HERE.parent.parent.parent / "worked_problems" / "flywheel").glob("*.toml"))


@pytest.mark.parametrize("path", WORKED, ids=[f.stem for f in WORKED])
def test_the_worked_problems_flag_exactly_the_students_slips(path):
    """Each worked problem carries the answers worked by hand in its comment and one
    student's slip (marked on its line): that one is wrong and named, the rest right."""
    text = path.read_text(encoding="utf-8")
    slips = {
        line.split("=")[0].strip() for line in text.splitlines() if "the student's slip" in line
    }
    scene = cycle_from_text(text, str(path))
    verdicts = cycle_verdicts(scene, solve_cycle(scene), scene.answers, scene.tolerance)
    assert slips and {v.key for v in verdicts if not v.ok} == slips
    assert all(v.mistake for v in verdicts if not v.ok)
