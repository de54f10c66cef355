"""True-to-scale diagrams: the configuration (space) diagram, the velocity polygon and the
acceleration polygon, drawn as a student draws them, to a scale a ruler can check.

Everything drawn comes from the :class:`~polygon_method.motion.solution.Solution` and the
construction records of :mod:`polygon_method.polygons.constructions`; nothing here redoes the
kinematics. Each diagram is laid out in *centimetres of paper*: a quantity ``q`` (SI) is
drawn ``q / per_cm`` cm long, and the figure is sized so that one unit of the axes is one
centimetre on the page (figure inches = extent in cm / 2.54, no tight-bbox rescaling).
Printed at 100 %, a vector drawn 3.92 cm long at ``1 cm = 0.1 m/s`` is 0.392 m/s.

The drawing functions take a matplotlib Axes and return the artists they made::

    draw_configuration(ax, sol, scale)   draw_velocity(ax, sol, scale)
    draw_acceleration(ax, sol, scale)

:func:`make_figure` puts one or all three side by side on a sheet of the right physical
size; :func:`render` returns SVG text, PNG or PDF bytes of it. :func:`render_pages` lays
the same panels out on paper (A4, A3, letter; :mod:`.paper`), on more pages where they do
not fit one, never at other scales: what the command line writes.
matplotlib is imported only inside these functions, so that ``import polygon_method`` and
``solve`` stay fast.

Labels are placed by trying positions around each point (shapely boxes) and taking the
first whose box touches no line, arrow, outline or other label and is nearer to its own point
than to any other; a label that has to stand off gets a leader line.

>>> import polygon_method as pm
>>> sol = pm.solve(pm.parse_scene('''
... [ground]
... O = [0, 0]
... [links]
... OA = 150
... AB = 600
... [sliders]
... B = { path = "horizontal" }
... [input]
... crank = "OA"
... angle = 60
... speed = "10 rad/s ccw"
... '''))
>>> svg, scales, warnings = render(sol, "svg", "all")
>>> [str(s) for s in scales.values()]     # the scales the step table states
['1 cm = 50 mm', '1 cm = 0.2 m/s', '1 cm = 2 m/s^2']
>>> svg.startswith("<?xml") and 'id="velocity-vector-0-shaft"' in svg
True
"""

from __future__ import annotations

from ..polygons.constructions import drawn_vectors
from ..polygons.scales import DIAGRAMS, choose_scales, display_unit, parse_scales
from .paper import PAPER_NAMES, page_files, paginate, paper_name
from .sheet import (
    draw_acceleration,
    draw_configuration,
    draw_velocity,
    layout,
    make_figure,
    render,
    render_pages,
    svg_string,
)
from .style import CM_PER_INCH, FORMATS, PT_PER_CM

__all__ = [
    "draw_configuration",
    "draw_velocity",
    "draw_acceleration",
    "make_figure",
    "render",
    "render_pages",
    "paginate",
    "page_files",
    "paper_name",
    "PAPER_NAMES",
    "svg_string",
    "choose_scales",
    "parse_scales",
    "drawn_vectors",
    "layout",
    "display_unit",
    "DIAGRAMS",
    "FORMATS",
    "CM_PER_INCH",
    "PT_PER_CM",
]
