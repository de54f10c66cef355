"""Image letters never take the pole's: a moving point named O is o1 (o2 where the scene
has an O1), on the step table, the drawings' labels, the page and the checker's words."""

from __future__ import annotations

import json
import re

import polygon_method as pm
from polygon_method.page import frames
from polygon_method.page.data import page_data
from polygon_method.steps import image_label, image_name, under_label
from polygon_method.text.steptable import steps_text

# a four-bar whose coupler point is named O (the pivots are O1 and O2)
SCENE = """
[ground]
O1 = [0, 0]
O2 = [100, 0]
[links]
O1-A = 40
A-O = 120
O-O2 = 80
[input]
crank = "O1-A"
angle = 60
speed = "10 rad/s ccw"
"""


def test_a_moving_O_is_not_the_pole():
    sol = pm.solve(pm.parse_scene(SCENE))
    assert image_name(sol.scene, "O") == "o3"  # o1, o2 are the pivots' own letters
    assert image_label(sol, "O") == "o3" and image_label(sol, "O", "acceleration") == "o3'"
    assert image_label(sol, "O1") == "o"  # a fixed point: the pole
    text = steps_text(sol)
    assert re.search(r"\bo3\b", text)
    # link A-O's relative velocity is a o3 (it was "ao", as if drawn to the pole)
    assert re.search(r"\b(ao3|o3a)\b", text) and not re.search(r"\b(ao|oo)\b", text)


def test_the_page_gets_its_letters_from_the_steps():
    sc = pm.parse_scene(SCENE)
    d = page_data(frames(sc, 12))
    assert d["images"]["O"] == "o3" and d["images"]["A"] == "a"
    assert json.dumps(d)  # the page's data stay JSON


def test_the_point_under_a_block_skips_every_letter_taken():
    sc = pm.load_scene("worked_problems/crank_slotted_lever.toml")
    sol = pm.solve(sc)
    block = [s.point for s in sc.sliders if hasattr(s, "guide")][0]
    lab = under_label(sol, block)
    taken = {image_name(sc, p) for p in sc.point_names}
    assert lab not in taken and lab.startswith(block.lower())
