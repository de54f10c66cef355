"""Scene files: a mechanism problem as a textbook states it (see ``docs/scene-format.md``).

The reader checks every table and key,
turns quantities into SI and resolves names, so that everything after it works on a
:class:`Scene` that is known to be well formed (whether the links can be assembled is the
plan's business).

>>> s = parse_scene('''
... [ground]
... A = [0, 0]
... D = [100, 0]
... [links]
... AB = 50
... BC = 66
... CD = 56
... [input]
... crank = "AB"
... angle = 60
... speed = "10.5 rad/s cw"
... ''')
>>> s.link("CB").length
0.066
>>> s.input.omega
-10.5
"""

from __future__ import annotations

from .answer_files import asked_questions
from .reading import (
    key_line,
    load_answers,
    load_scene,
    parse_answers,
    parse_scene,
    scene_from_table,
    scene_table,
)
from .records import (
    ANSWER_KINDS,
    GIVEN_KINDS,
    Answer,
    CarriedPoint,
    Cylinder,
    FixedPath,
    Flywheel,
    GivenRate,
    Gravity,
    GuideSlider,
    Indicator,
    Input,
    Link,
    Load,
    Mass,
    Pin,
    PositionGiven,
    Scene,
    YokeSlot,
    guide_words,
    split_name,
)
from .variation import Variation, VariantOf, Varied
from .link_loads import direction_columns, loads_dict

__all__ = [
    "Scene",
    "Link",
    "CarriedPoint",
    "FixedPath",
    "GuideSlider",
    "YokeSlot",
    "Input",
    "Pin",
    "Load",
    "Answer",
    "load_scene",
    "parse_scene",
    "split_name",
    "ANSWER_KINDS",
    "parse_answers",
    "load_answers",
    "asked_questions",
    "key_line",
    "scene_table",
    "scene_from_table",
    "Variation",
    "Varied",
    "VariantOf",
    "GivenRate",
    "GIVEN_KINDS",
    "Cylinder",
    "PositionGiven",
    "Mass",
    "Gravity",
    "guide_words",
    "Indicator",
    "Flywheel",
    "loads_dict",
    "direction_columns",
]
