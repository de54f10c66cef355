"""polygon-method: planar mechanisms solved the way a Theory of Machines textbook does it.

>>> import polygon_method as pm
>>> scene = pm.parse_scene('''
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
>>> sol = pm.solve(scene)
>>> f"{sol.omega('BC'):.4f}"
'5.1502'
"""

from .errors import (AssemblyError, MobilityError, PolygonMethodError, SceneError,
                     SingularStepError)
from .compiler import compile_plan
from .plan import Plan
from .scene import Scene, load_scene, parse_scene
from .solution import Solution, solve

__version__ = "0.1.0"

__all__ = ["load_scene", "parse_scene", "solve", "compile_plan", "sweep", "Scene", "Plan",
           "Solution", "PolygonMethodError", "SceneError", "MobilityError", "AssemblyError",
           "SingularStepError", "__version__"]


def _solution_svg(sol):
    """The three diagrams as SVG, for Jupyter (``Solution._repr_svg_``)."""
    try:
        from .draw import svg_string
    except ImportError:  # drawing not available
        return None
    return svg_string(sol)


def _solution_report(sol) -> str:
    """The solution as text, the way ``polygon-method solve`` prints it."""
    from .report import solution_text
    return solution_text(sol)


# the views sit above the solution: they are attached here, at the top of the package
Solution._repr_svg_ = _solution_svg
Solution.report = _solution_report


def __getattr__(name):  # lazy: sweeps need numpy, which `solve` does not
    if name == "sweep":
        from .sweeps import sweep
        return sweep
    raise AttributeError(name)
