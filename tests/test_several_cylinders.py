"""Several cylinders on one crank: a V-twin (two pistons whose rods share the crank pin, their
lines at 45 and 135 deg) and a three-cylinder radial (lines at 90, 210 and 330 deg), each
piston under its own gas pressure, every body massive, gravity. ``solve`` gives each
cylinder's piston effort, rod thrust, side thrust and crank effort and the turning moment of
them all; ``sweep`` and the summary their columns; ``check`` holds ``turning_moment``.

The reference is independent of the tool: the positions in closed form at 30 digits
(mpmath; each piston on its line through the crank centre, the rod's far root), the
velocities and accelerations by mpmath's differentiation in the crank angle (the crank
turning steadily), and every body's Newton-Euler equations as one linear system
(``tests/newton_euler.py``): the driving torque, each rod's force on the crank pin (its
crank effort), each piston pin's force (the rod thrust) and each guide's normal force (the
side thrust) to 1e-9; the piston effort from the gas force, the piston's weight and its
inertia along the line.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

from polygon_method.cli import main
from polygon_method.motion.solution import solve
from polygon_method.motion.sweeps import sweep
from polygon_method.scene import parse_scene

from newton_euler import NewtonEuler

R, L, G = 0.06, 0.24, 9.81
W = 3000 * math.pi / 30
BORE = 0.08
M_CRANK, G_CRANK, K_CRANK = 3.0, 0.02, 0.03
M_ROD, G_ROD, K_ROD = 1.2, 0.08, 0.07
M_PISTON = 0.8

#: name -> (its line's angle, deg; gas pressure, N/mm^2)
VTWIN = {"B": (45, 2.0), "C": (135, 0.5)}
RADIAL = {"B": (90, 1.5), "C": (210, 0.4), "D": (330, 0.9)}


def scene_text(cyl, angle):
    links = "\n".join(f"A{p} = 240" for p in cyl)
    sliders = "\n".join(f'{p} = {{ path = {a}, through = "O" }}' for p, (a, _) in cyl.items())
    masses = "\n".join(
        f"A{p} = {{ mass = {M_ROD}, along = 80, gyration = 70 }}\n{p} = {{ mass = {M_PISTON} }}"
        for p in cyl
    )
    loads = "\n".join(
        f'{p} = {{ pressure = "{pr} N/mm^2", bore = 80 }}' for p, (_, pr) in cyl.items()
    )
    return f"""
title = "{len(cyl)} cylinders on one crank"
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 60
{links}
[sliders]
{sliders}
[assembly]
{chr(10).join(f'{p} = "{"above" if a < 180 else "below"}"' for p, (a, _) in cyl.items())}
[input]
crank = "OA"
angle = {angle}
speed = "3000 rpm ccw"
[masses]
OA = {{ mass = {M_CRANK}, along = 20, gyration = 30 }}
{masses}
[gravity]
[loads]
{loads}
"""


def _points(th, cyl):
    A = (R * mpmath.cos(th), R * mpmath.sin(th))
    out = {"A": A, "G_OA": (A[0] * G_CRANK / R, A[1] * G_CRANK / R)}
    for p, (deg, _) in cyl.items():
        u = (mpmath.cos(mpmath.radians(deg)), mpmath.sin(mpmath.radians(deg)))
        along, across = A[0] * u[0] + A[1] * u[1], A[0] * u[1] - A[1] * u[0]
        t = along + mpmath.sqrt(L**2 - across**2)
        B = (t * u[0], t * u[1])
        e = ((B[0] - A[0]) / L, (B[1] - A[1]) / L)
        out[p] = B
        out["G" + p] = (A[0] + G_ROD * e[0], A[1] + G_ROD * e[1])
        out["phi" + p] = mpmath.atan2(e[1], e[0])
    return out


def reference(cyl, angle_deg):
    """The matrix method's unknowns at the crank angle, and each piston's effort."""
    with mpmath.workdps(30):
        th = mpmath.radians(angle_deg)
        P = _points(th, cyl)
        acc = {}
        for k, v in P.items():
            if isinstance(v, tuple):
                acc[k] = tuple(
                    W**2 * mpmath.diff(lambda t, k=k, i=i: _points(t, cyl)[k][i], th, 2)
                    for i in (0, 1)
                )
            else:
                acc[k] = W**2 * mpmath.diff(lambda t, k=k: _points(t, cyl)[k], th, 2)
        bodies = ["OA"] + [f"A{p}" for p in cyl] + [f"b{p}" for p in cyl]
        ne = NewtonEuler(bodies, about={f"b{p}": P[p] for p in cyl}, mp=True)
        ne.pin("O", (0, 0), "OA", "frame")
        ne.couple("T", "OA", "frame")
        ne.known("OA", (0, -M_CRANK * G), P["G_OA"])  # (steady: a_G towards O)
        ne.known("OA", (-M_CRANK * acc["G_OA"][0], -M_CRANK * acc["G_OA"][1]), P["G_OA"])
        efforts = {}
        for p, (deg, pr) in cyl.items():
            u = (mpmath.cos(mpmath.radians(deg)), mpmath.sin(mpmath.radians(deg)))
            ne.pin("A" + p, P["A"], "A" + p, "OA")
            ne.pin("P" + p, P[p], "A" + p, "b" + p)
            ne.along("N" + p, P[p], (-u[1], u[0]), "b" + p, "frame")
            a, ag = acc[p], acc["G" + p]
            ne.known("A" + p, (-M_ROD * ag[0], -M_ROD * ag[1] - M_ROD * G), P["G" + p])
            ne.known("A" + p, c=-M_ROD * K_ROD**2 * acc["phi" + p])
            gas = pr * 1e6 * mpmath.pi / 4 * BORE**2
            fb = (-gas * u[0] - M_PISTON * a[0], -gas * u[1] - M_PISTON * a[1] - M_PISTON * G)
            ne.known("b" + p, fb, P[p])
            efforts[p] = -(fb[0] * u[0] + fb[1] * u[1])  # towards the crank: -u
        x = ne.solve()
        out = {k: float(v) for k, v in x.items()}
        for p in cyl:  # the rod's force on the crank at its pin, across it (ccw)
            fx, fy = -x["A" + p + ".x"], -x["A" + p + ".y"]
            out["F_T" + p] = float((P["A"][0] * fy - P["A"][1] * fx) / R)
            out["F_P" + p] = float(efforts[p])
        return out


@pytest.mark.parametrize("cyl", [VTWIN, RADIAL], ids=["v-twin", "radial"])
@pytest.mark.parametrize("angle", [30.0, 200.0])
def test_each_cylinder_against_the_matrix_method(cyl, angle):
    sol = solve(parse_scene(scene_text(cyl, angle)))
    f = sol.forces
    ref = reference(cyl, angle)
    size = max(abs(v) for v in ref.values())
    assert f.input_torque == pytest.approx(ref["T"], abs=1e-9 * size * R)
    from polygon_method.forces.engine import cylinder_efforts

    es = cylinder_efforts(sol.scene, sol.plan, sol.P, f)
    assert [e.piston for e in es] == list(cyl)
    for e in es:
        p = e.piston
        assert e.F_P == pytest.approx(ref["F_P" + p], abs=1e-9 * size)
        assert e.F_T == pytest.approx(ref["F_T" + p], abs=1e-9 * size)
        assert e.T == pytest.approx(ref["F_T" + p] * R, abs=1e-9 * size * R)
        assert e.F_Q == pytest.approx(math.hypot(ref[f"P{p}.x"], ref[f"P{p}.y"]), abs=1e-9 * size)
        assert e.F_N == pytest.approx(abs(ref["N" + p]), abs=1e-9 * size)


def test_the_views_say_each_cylinder_and_the_whole(tmp_path, capsys):
    scene = tmp_path / "v.toml"
    scene.write_text(scene_text(VTWIN, 30.0))
    assert main(["solve", str(scene)]) == 0
    out = capsys.readouterr().out
    ref = reference(VTWIN, 30.0)
    total = (ref["F_TB"] + ref["F_TC"]) * R
    assert "engine, cylinder B: piston effort" in out and "engine, cylinder C:" in out
    assert f"sum F_T r = {total:.4g} N m" in out
    right = tmp_path / "answers.toml"
    right.write_text(
        scene_text(VTWIN, 30.0) + f'[answers]\nturning_moment = "{abs(total):.5g} N m"\n'
    )
    main(["check", str(right)])
    assert "1 of 1 right" in capsys.readouterr().out


def test_the_sweep_has_each_cylinder_and_their_sum():
    sc = parse_scene(scene_text(RADIAL, 0.0))
    degs = np.array([15.0, 100.0, 250.0])
    res = sweep(sc, np.radians(degs))
    cols = {n: np.asarray(a, dtype=float) for n, _, a in res.force_columns()}
    assert {"piston_effort_B", "crank_effort_D", "turning_moment"} <= set(cols)
    for i, deg in enumerate(degs):
        ref = reference(RADIAL, float(deg))
        size = max(abs(v) for v in ref.values())
        total = sum(ref["F_T" + p] for p in RADIAL) * R
        assert cols["turning_moment"][i] == pytest.approx(total, abs=1e-9 * size * R)
        assert cols["crank_effort_C"][i] == pytest.approx(ref["F_TC"], abs=1e-9 * size)
