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

import importlib
import importlib.abc
import importlib.util
import sys

from .common.errors import (
    AssemblyError,
    MobilityError,
    PolygonMethodError,
    SceneError,
    SingularStepError,
)
from .solver.compiler import compile_plan
from .solver.plan import Plan
from .scene import Scene, load_scene, parse_scene
from .motion.solution import Solution, solve

__version__ = "0.1.0"

__all__ = [
    "load_scene",
    "parse_scene",
    "load_cycle",
    "parse_cycle",
    "solve_cycle",
    "solve",
    "compile_plan",
    "sweep",
    "Scene",
    "Plan",
    "Solution",
    "PolygonMethodError",
    "SceneError",
    "MobilityError",
    "AssemblyError",
    "SingularStepError",
    "__version__",
]


def _solution_svg(sol):
    """The three diagrams as SVG, for Jupyter (``Solution._repr_svg_``)."""
    try:
        from .draw import svg_string
    except ImportError:  # drawing not available
        return None
    return svg_string(sol)


def _solution_report(sol) -> str:
    """The solution as text, the way ``polygon-method solve`` prints it."""
    from .text.report import solution_text

    return solution_text(sol)


# the views sit above the solution: they are attached here, at the top of the package
Solution._repr_svg_ = _solution_svg
Solution.report = _solution_report


# Where the modules that once stood at the top of the package live now (one folder per
# layer, see docs/architecture.md). `import polygon_method.kinematics` and the like keep
# working: the old name is the same module object as the new one.
MOVED = {
    "errors": "common.errors",
    "units": "common.units",
    "numbers": "common.numbers",
    "plan": "solver.plan",
    "given": "solver.given",
    "compiler": "solver.compiler",
    "kinematics": "solver.kinematics",
    "tracking": "solver.tracking",
    "errorbound": "solver.errorbound",
    "derived": "solver.derived",
    "centres": "solver.centres",
    "solution": "motion.solution",
    "sweeps": "motion.sweeps",
    "constructions": "polygons.constructions",
    "scales": "polygons.scales",
    "summary": "linkage.summary",
    "report": "text.report",
    "words": "text.words",
    "steptable": "text.steptable",
    "forcereport": "text.forces",
    "centretable": "text.centres",
    "plots": "draw.plots",
}


class _OldNames(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Finds ``polygon_method.<old name>`` as the module at its new place."""

    def find_spec(self, fullname, path=None, target=None):
        head, _, rest = fullname.partition(".")
        if head == __name__ and rest in MOVED:
            return importlib.util.spec_from_loader(fullname, self)
        return None

    def create_module(self, spec):
        module = importlib.import_module(f"{__name__}.{MOVED[spec.name.partition('.')[2]]}")
        spec.loader_state = module.__spec__
        return module

    def exec_module(self, module):
        # the import system stamped the old name's spec on the module: give it its own back
        module.__spec__ = module.__spec__.loader_state


if not any(isinstance(f, _OldNames) for f in sys.meta_path):
    sys.meta_path.append(_OldNames())


def __getattr__(name):  # lazy: sweeps need numpy, which `solve` does not
    if name == "sweep":
        from .motion.sweeps import sweep

        return sweep
    if name in ("load_cycle", "parse_cycle"):  # a turning-moment diagram on its own
        from .scene import energy

        return getattr(energy, name)
    if name == "solve_cycle":
        from .forces.flywheel_cycle import solve_cycle

        return solve_cycle
    raise AttributeError(name)
