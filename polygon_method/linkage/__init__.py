"""Linkage properties from the lecture: Grashof class, toggle positions, transmission angle,
range of the output, quick-return ratio, and the slider crank's approximate formulas.

Mechanisms covered
------------------
* **four-bar** (crank, coupler, output link pivoted on the ground): Grashof's classes
  (crank-rocker, rocker-crank, double crank, double rocker, non-Grashof triple rocker) and
  the special case S + L = P + Q with its change points (parallelogram, anti-parallelogram,
  deltoid);
* **slider crank**, in-line or offset: whether the crank turns fully, dead centres, stroke,
  quick return of the offset crank, and for the in-line one the textbook's approximate
  formulas (n = l / r) beside the exact values;
* **crank and slotted lever** (the block on the crank pin slides in a lever pivoted on the
  ground; Whitworth when the lever turns fully), with a ram or without;
* any other mechanism the plan builds: limit positions and change points of the crank,
  the transmission angle of every dyad, and the range of the last output pivoted on the
  ground or sliding on a fixed path, with its stationary positions and time ratio.

Everything over the cycle is found on the scene's own assembly branch (see
:mod:`polygon_method.solver.tracking`), not on a formula that assumes one.

>>> from polygon_method.scene import parse_scene
>>> g = grashof(50, 66, 56, 100)   # crank, coupler, output, ground
>>> g.kind
'non-Grashof triple rocker'
>>> grashof(30, 90, 70, 100).kind
'crank-rocker'
"""

from __future__ import annotations

from .analysis import Linkage, Stationary, Transmission, analyse
from .engine import engine_formula_lines
from .flywheel import TurningMoment, engine_cycle_lines, turning_moment
from .shapes import FourBar, Grashof, SliderCrank, four_bar_of, grashof, slider_crank_of, slotted_of

__all__ = [
    "grashof",
    "Grashof",
    "analyse",
    "Linkage",
    "Stationary",
    "Transmission",
    "engine_formula_lines",
    "slider_crank_of",
    "four_bar_of",
    "slotted_of",
    "FourBar",
    "SliderCrank",
    "TurningMoment",
    "turning_moment",
    "engine_cycle_lines",
]
