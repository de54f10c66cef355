"""US books name the dead centres by the cylinder's ends: the head-end dead centre (the
piston at the cylinder head, farthest from the crank shaft: the inner dead centre) and the
crank-end one (the outer). By hand: an in-line engine, the piston to the right of O, the
crank turning cw; an offset engine, the head-end dead centre where crank and rod are in
line, at asin(e / (l + r)) to the line of stroke."""

import math

import pytest

from polygon_method import parse_scene

ENGINE = """
[ground]
O = [0, 0]
[links]
OA = 300
AB = 1200
[sliders]
B = {{ path = "horizontal", through = [0, {e}] }}
[input]
crank = "OA"
angle = "{words}"
speed = "150 rpm cw"
"""


@pytest.mark.parametrize(
    "words, e, deg",
    [
        ("45 deg from the head-end dead centre", 0, -45.0),
        ("45 deg past the head end dead center", 0, -45.0),
        ("45 deg past the crank-end dead centre", 0, 135.0),
        ("30 deg before the crank end dead centre", 0, -150.0),
        ("0 deg from the head-end dead centre", 150, math.degrees(math.asin(150 / 1500))),
    ],
)
def test_head_end_is_the_inner_dead_centre_crank_end_the_outer(words, e, deg):
    sc = parse_scene(ENGINE.format(words=words, e=e))
    assert math.degrees(sc.input.angle) == pytest.approx(deg, abs=1e-12)
