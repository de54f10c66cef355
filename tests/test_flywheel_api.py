"""The library's entry points for a turning-moment diagram stated on its own: ``load_scene``
refuses it in one line naming its reader; ``load_cycle`` / ``parse_cycle`` read it and
``solve_cycle`` solves it (held to the worked problem's hand-worked closed form);
``load_cycle`` refuses a mechanism's scene and bad files as ``load_scene`` does."""

import math

import pytest

import polygon_method as pm

PRESS = "worked_problems/flywheel/punching_press.toml"


def test_load_scene_names_the_diagrams_reader():
    with pytest.raises(pm.SceneError) as e:
        pm.load_scene(PRESS)
    msg = str(e.value)
    assert "\n" not in msg and "load_cycle" in msg and "[press]" in msg
    assert "(line 16)" in msg and msg.startswith(PRESS)
    with pytest.raises(pm.SceneError, match="load_cycle"):
        pm.parse_scene('[turning_moment]\ntorque = "1000 + 300 sin 2theta"\n')


def test_load_cycle_reads_and_solve_cycle_solves_the_press():
    """dE_max = E (1 - 1/8), E = F t / 2, F = tau pi d t (worked in the file by hand)."""
    c = pm.solve_cycle(pm.load_cycle(PRESS))
    t = 0.018
    E = 400e6 * math.pi * 0.025 * t * t / 2
    assert abs(c.E_stroke - E) <= 1e-9 * E
    assert abs(c.dE_max - E * 7 / 8) <= 1e-9 * E


def test_parse_cycle_of_a_law_gives_its_amplitude():
    s = pm.parse_cycle('[turning_moment]\ntorque = "1000 + 300 sin 2theta - 500 cos 2theta"\n')
    c = pm.solve_cycle(s)
    assert abs(c.dE_max - math.hypot(300, 500)) <= 1e-9 * 583


def test_load_cycle_refuses_what_is_not_a_diagram(tmp_path):
    with pytest.raises(pm.SceneError, match="load_scene"):
        pm.load_cycle("worked_problems/fourbar_image_points.toml")
    with pytest.raises(pm.SceneError, match="no such file"):
        pm.load_cycle(tmp_path / "none.toml")
    bad = tmp_path / "bad.toml"
    bad.write_bytes(b"[turning_moment]\x00")
    with pytest.raises(pm.SceneError, match="not a text file"):
        pm.load_cycle(bad)
    bad.write_text("[turning_moment]\nareas = [1, 2]\n", encoding="utf-8")
    with pytest.raises(pm.SceneError) as e:
        pm.load_cycle(bad)
    assert str(e.value).startswith(str(bad)) and "areas" in str(e.value)
    with pytest.raises(pm.SceneError, match="as a str"):
        pm.parse_cycle(b"[press]")
