"""The problem in words (page and problem sheet): every datum a student needs to solve the
problem by hand is stated, in the scene's own units, for every worked problem."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

import polygon_method as pm
from polygon_method.common.numbers import fmt
from polygon_method.scene import guide_words
from polygon_method.text.words import given


def g(x):  # a datum, unrounded
    return f"{x:.10g}"


SCENES = sorted((Path(__file__).parent.parent / "worked_problems").glob("*.toml"))


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_every_datum_is_stated(path):
    sc = pm.load_scene(path)
    text = "\n".join(given(sc))
    u = sc.length_unit
    for lk in sc.links:
        assert f"{lk.key} = {g(lk.length / u)} {sc.units}" in text
    for p, (x, y) in sc.ground.items():
        assert f"{p} at ({g(x / u)}, {g(y / u)}) {sc.units}" in text
    for s in sc.sliders:
        if getattr(s, "wheel", ""):  # a driving wheel's centre: said with the wheel
            pr = next(p for p in sc.rolling if p.wheel == s.wheel)
            assert f"The wheel {s.wheel} (radius {g(pr.radius / u)} {sc.units})" in text
            assert f"rolling without slip on {pr.label} at {sc.input.speed_text}" in text
            continue
        if s.slot:  # a peg in two slots: each slot named in its sentence
            assert f"A peg {s.point} runs in two slots: " in text
            if hasattr(s, "through"):
                tx, ty = s.through
                slot = guide_words(s.label, "slot")  # "horizontal slot", "slot at 30 deg"
                assert f"a fixed {slot} through ({g(tx / u)}, {g(ty / u)})" in text
            else:
                assert f"the slot of link {s.guide}" in text
        elif hasattr(s, "yoke"):  # the slot of a translating yoke
            slot = guide_words(s.label, "slot", f"the yoke {s.yoke}")
            assert f"A block at {s.point} slides in the {slot}" in text
        elif hasattr(s, "through"):
            tx, ty = s.through
            assert f"Slider {s.point} moves on a fixed" in text
            assert f"through ({g(tx / u)}, {g(ty / u)}) {sc.units}" in text
        else:
            assert f"A block at {s.point} slides along link {s.guide}" in text
    for p in sc.assembly:
        assert f"Of its two positions, {p} is the one " in text
    for cp in sc.points:  # on the link as the scene writes it (DC: measured from D)
        ends = sc.link(cp.link).points
        assert any(
            f"Point {cp.name}: on {k}" in text
            for k in (cp.link, "".join(ends[::-1]), "-".join(ends[::-1]))
        ), cp.name
    inp = sc.input
    if inp.block is None:
        assert f"makes {fmt(math.degrees(inp.angle) % 360)}°" in text
        assert inp.speed_text in text
    elif inp.wheel is not None:  # a driving wheel: its omega, alpha and its centre's place
        r = next(p for p in sc.rolling if p.wheel == inp.wheel).radius
        assert f"The wheel {inp.wheel} (radius" in text and inp.speed_text in text
        alpha = abs(inp.alpha) / r  # |a_C| = |alpha| r
        assert (f"and {fmt(alpha)} rad/s²" in text) == bool(inp.alpha)
        assert f"its centre {inp.block} is {g(abs(inp.angle) / u)} {sc.units} along" in text
    elif not hasattr(sc.slider(inp.block), "through"):  # a collar driven along its rod
        assert f"The collar {inp.block} slides along the rod" in text
        assert f"collar is {g(abs(inp.angle) / u)} {sc.units} from" in text
        assert f"sliding at {abs(inp.omega):.10g} m/s" in text
        assert (f"an acceleration of {abs(inp.alpha):.10g} m/s²" in text) == bool(inp.alpha)
    else:  # a driving block: its place along its guide, its speed and acceleration
        assert f"The block {inp.block} drives the mechanism" in text
        assert f"it is {g(abs(inp.angle) / u)} {sc.units} from" in text
        assert f"moving at {fmt(abs(inp.omega))} m/s" in text
        assert (f"an acceleration of {fmt(abs(inp.alpha))} m/s²" in text) == bool(inp.alpha)
    for pin in sc.pins:
        assert f"Pin at {pin.point}" in text
    assert len(given(sc)) == len(set(given(sc)))  # nothing said twice


def test_data_are_not_rounded():
    sc = pm.parse_scene("""
[ground]
A = [0, 0]
D = [100.123456, 0]
[links]
AB = 40.0625
BC = 123.4567
CD = 80
[input]
crank = "AB"
angle = 120
speed = "20 rad/s ccw"
""")
    text = "\n".join(given(sc))
    assert "D at (100.123456, 0) mm" in text
    assert "AB = 40.0625 mm, BC = 123.4567 mm, CD = 80 mm" in text


def test_a_path_at_an_angle_and_an_acceleration_are_said():
    sc = pm.parse_scene("""
[ground]
O = [0, 0]
[links]
OA = 50
AB = 200
[sliders]
B = { path = "30 deg", through = [0, -20] }
[input]
crank = "OA"
angle = 45
speed = "300 rpm ccw"
acceleration = "5 rad/s^2 cw"
""")
    lines = given(sc)
    assert "Slider B moves on a fixed path at 30 deg through (0, -20) mm." in lines
    crank = [x for x in lines if x.startswith("The crank")][0]
    assert "300 rpm ccw (31.42 rad/s ccw)" in crank
    assert "angular acceleration of 5 rad/s² cw" in crank
