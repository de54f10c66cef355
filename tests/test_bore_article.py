"""A bore's words take the article a book would read aloud: "an 80 mm bore", "a 110 mm
bore" (the reader wrote "on a 80 mm bore"); the force in the note is p pi d^2 / 4, by hand."""

import math

from polygon_method import parse_scene, solve

SCENE = """
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 60
AB = 240
[sliders]
B = {{ path = "horizontal" }}
[input]
crank = "OA"
angle = 40
speed = "100 rad/s ccw"
[masses]
[loads]
B = {{ pressure = "1 N/mm^2", bore = {bore} }}
"""


def _note(bore):
    sol = solve(parse_scene(SCENE.format(bore=bore)))
    return next(n for n in sol.notes if "bore" in n)


def test_an_eighty_millimetre_bore_reads_an():
    note = _note(80)
    assert "1 N/mm^2 on an 80 mm bore" in note
    assert f"{math.pi / 4 * 80**2:.0f} N" in note  # 1 N/mm^2 x pi 80^2 / 4 = 5027 N


def test_other_bores_read_a_or_an_as_spoken():
    assert "on a 110 mm bore" in _note(110)
    assert "on an 11 mm bore" in _note(11)
    assert "on a 250 mm bore" in _note(250)


def test_a_piston_pressure_below_a_vacuum_is_refused_as_the_indicator_refuses_it():
    # -0.5 N/mm^2 gauge is -5 bar: below the -1.01325 bar of a perfect vacuum; -0.05 N/mm^2
    # (-0.5 bar, a suction stroke) is a pressure a piston can feel: its force p pi d^2 / 4
    import pytest

    from polygon_method.common.errors import SceneError

    with pytest.raises(SceneError, match=r"\[loads\] B .*below a vacuum"):
        parse_scene(SCENE.format(bore=80).replace('"1 N/mm^2"', '"-0.5 N/mm^2"'))
    scene = parse_scene(SCENE.format(bore=80).replace('"1 N/mm^2"', '"-0.05 N/mm^2"'))
    (load,) = scene.loads
    p, area, _ = load.gas  # (gauge pressure Pa, area m^2, words)
    assert p * area == pytest.approx(-0.05e6 * math.pi / 4 * 0.08**2, rel=1e-12)
