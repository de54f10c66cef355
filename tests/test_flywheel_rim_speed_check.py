"""A flywheel given by its rim's speed alone (no shaft speed) finds the rim's mass and not
its I, its radius or the greatest and least speeds: an answer file that gives one of these
is refused in one line saying the shaft's speed is what is missing (it had said "the scene
needs [flywheel]", of a scene that gives one, and "the rim's radius ([flywheel] radius,
diameter, rim_speed ...)" of a scene that gives its rim_speed)."""

from __future__ import annotations

from pathlib import Path

import pytest

from polygon_method.cli import main

SCENE = Path(__file__).resolve().parent / "textbook" / "flywheel" / "press_rim_speed_alone.toml"


@pytest.mark.parametrize(
    "key,value",
    [
        ("I_flywheel", '"40 kg m^2"'),
        ("speed_max", '"300 rpm"'),
        ("speed_min", '"290 rpm"'),
        ("rim_radius", '"1 m"'),
    ],
)
def test_what_the_rims_speed_alone_cannot_find_names_the_shafts_speed(tmp_path, capsys, key, value):
    answers = tmp_path / "a.toml"
    answers.write_text(f"[answers]\n{key} = {value}\n", encoding="utf-8")
    assert main(["check", str(SCENE), str(answers)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    assert f"[answers] {key} (line 2)" in err and "the shaft's mean speed" in err, err


def test_the_rims_mass_is_still_checked(tmp_path, capsys):
    """m = dE_max / (v^2 Cs), by hand from the file's own statement."""
    answers = tmp_path / "a.toml"
    answers.write_text('[answers]\nm_flywheel = "760.9 kg"\n', encoding="utf-8")
    assert main(["check", str(SCENE), str(answers), "--tolerance", "0.1%"]) == 0
    assert "right" in capsys.readouterr().out
