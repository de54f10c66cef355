"""The configuration's scale holds what the diagram draws beyond the joints: a ring the
planet rolls in, a Scotch yoke's slot. Both once made `draw` refuse its own default scale
on A4 (the ring drawn at a scale chosen for the arm alone)."""

from __future__ import annotations

from polygon_method import parse_scene, solve
from polygon_method.draw.sheet import render_pages
from polygon_method.polygons.scales import SPACE_FIT_CM, diagram_scales

RING = """
units = "m"
[ground]
O = [0, 0]
[links]
"O-A" = 0.3
"A-P" = 0.1
[rolling]
"A-P" = { on = "O", inside = true, angle = 210 }
[input]
crank = "O-A"
angle = 30
speed = "5 rad/s ccw"
"""

YOKE = """
units = "in"
[ground]
O = [0, 0]
[links]
OA = 3
[sliders]
Y = { path = "horizontal", through = "O" }
A = { along = "block Y", direction = "vertical" }
[input]
crank = "OA"
angle = 120
speed = "120 rpm ccw"
"""


def test_ring_is_inside_the_configuration_scale():
    sol = solve(parse_scene(RING))
    space = diagram_scales(sol)[0]
    assert 2 * 0.4 <= space.per_cm * SPACE_FIT_CM  # the ring's diameter, 0.3 + 0.1 radius
    render_pages(sol, "svg")  # on A4 at the stated scale: no refusal


def test_yoke_slot_is_inside_the_configuration_scale():
    sol = solve(parse_scene(YOKE))
    space = diagram_scales(sol)[0]
    # the slot reaches the pin's height, 3 sin 60 in, on both sides of the path
    assert 2 * 3 * 0.0254 * 3**0.5 / 2 <= space.per_cm * SPACE_FIT_CM
    render_pages(sol, "svg")
