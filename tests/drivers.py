"""What the tests of a driver other than a crank share (a block on a fixed guide, a wheel
rolling on a ground line): both take the driver's place ``s`` along its line as the motion's
parameter, so the same independent checks apply to both.

- :func:`close`: a value (or a vector) within ``REL`` of the reference, relative to the
  larger of its own size and a scale of its kind;
- :func:`reference_errors`: the solver against the 50-digit constraint solve of
  ``tests/reference.py`` at the scene's instant;
- :func:`check_derivatives`: the velocities and accelerations against central differences
  of the solver's own positions in ``s``;
- :func:`every_view`: each command the driver must take, run on one scene file;
- :func:`one_line`: the refusal a command printed, one line.
"""

import math

import mpmath
import pytest
from mpmath import mpf

from polygon_method import parse_scene
from polygon_method.cli import main
from polygon_method.solver.compiler import compile_plan
from polygon_method.solver.plan import Context
from reference import reference_solution

REL = 1e-9


def close(got, want, scale):
    """Whether ``got`` is ``want`` to ``REL`` of the larger of its size and ``scale``."""
    if isinstance(want, tuple):
        err = math.hypot(got[0] - want[0], got[1] - want[1])
        size = max(math.hypot(*want), scale)
    else:
        err, size = abs(got - want), max(abs(want), scale)
    return err <= REL * size


def reference_errors(text, sliders=False) -> list:
    """Where the solve of the scene ``text`` at its instant differs from the 50-digit
    reference: positions, velocities, accelerations of every point, omega and alpha of
    every link (and, with ``sliders``, each slider's vs and as), each relative to the
    largest of its kind. Empty when all agree; the reference's own loop closure is checked."""
    scene = parse_scene(text)
    plan = compile_plan(scene)
    inp = scene.input
    P, V, A, W, Al, S = plan.evaluate(Context(inp.angle, inp.omega, inp.alpha))
    ref = reference_solution(scene, P)
    assert ref["residual"] < mpf("1e-40")
    errs = []
    for key, got, table in (
        ("P", P, "positions"),
        ("V", V, "velocities"),
        ("A", A, "accelerations"),
    ):
        want = ref[table]
        scale = max(float(mpmath.sqrt(x**2 + y**2)) for x, y in want.values())
        for p in scene.point_names:
            w = (float(want[p][0]), float(want[p][1]))
            if not close(tuple(got[p]), w, scale):
                errs.append((key, p, got[p], w))
    wscale = max(abs(float(x)) for x in ref["omega"].values())
    ascale = max(abs(float(x)) for x in ref["alpha"].values())
    for lk in scene.links:
        if not close(W[lk.key], float(ref["omega"][lk.key]), wscale):
            errs.append(("omega", lk.key))
        if not close(Al[lk.key], float(ref["alpha"][lk.key]), ascale):
            errs.append(("alpha", lk.key))
    for sl in scene.sliders if sliders else ():
        want = ref["sliders"][sl.point]
        if not close(S[sl.point][0], float(want["vs"]), 1e-12):
            errs.append(("vs", sl.point))
        if not close(S[sl.point][1], float(want["as"]), 1e-12):
            errs.append(("as", sl.point))
    return errs


def check_derivatives(text, h=1e-4):
    """dP/dt = dP/ds vs and d2P/dt2 = d2P/ds2 vs^2 + dP/ds as, the derivatives in the
    driver's place s by central differences of the solver's own positions."""
    scene = parse_scene(text)
    plan = compile_plan(scene)
    inp = scene.input
    s0, vs, a_s = inp.angle, inp.omega, inp.alpha

    def at(s):
        return plan.evaluate(Context(s, vs, a_s))[0]

    P0, (Pm, Pp) = at(s0), (at(s0 - h), at(s0 + h))
    _, V, A, *_ = plan.evaluate(Context(s0, vs, a_s))
    for p in scene.point_names:
        for c in (0, 1):
            d1 = (Pp[p][c] - Pm[p][c]) / (2 * h)
            d2 = (Pp[p][c] - 2 * P0[p][c] + Pm[p][c]) / (h * h)
            assert V[p][c] == pytest.approx(d1 * vs, rel=1e-6, abs=1e-6)
            assert A[p][c] == pytest.approx(d2 * vs * vs + d1 * a_s, rel=1e-4, abs=1e-4)


def every_view(f, tmp_path, more=()):
    """Run every command a driver must take on the scene file ``f`` (and the commands
    ``more``, each an argument list after the scene), each to exit 0."""
    for argv in [
        ["solve"],
        ["solve", "--json"],
        ["steps"],
        ["check"],
        ["centres"],
        ["draw", "-o", str(tmp_path / "d.svg")],
        ["draw", "--animate", "-o", str(tmp_path / "a.svg")],
        ["draw", "--diagram", "centres", "-o", str(tmp_path / "c.svg")],
        ["sweep", "--plot", str(tmp_path / "p.svg")],
        ["sweep", "--steps", "36", "--summary"],
        ["sweep", "--csv", str(tmp_path / "s.csv")],
        ["page", "-o", str(tmp_path / "p.html")],
        *more,
    ]:
        assert main([argv[0], str(f), *argv[1:]]) == 0, argv


def one_line(capsys) -> str:
    """The refusal a command wrote to stderr: asserted to be one line, returned stripped."""
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1, err
    return err
