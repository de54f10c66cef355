"""Friction at a hydraulic cylinder's pins (``[friction] pins`` with a size at its ends):
the friction circles put a couple on the cylinder, which is then no longer a two-force
member: its pins' forces keep the axial force (the pressure's, or the driver's) and gain a
part across the line, ``M / L``, which reaches the crank's torque.

The reference is independent of the tool: the crank-rocker of ``test_cylinder_force.py``
(positions in closed form at 30 digits, their derivatives by mpmath), its cylinder taken
as two bodies, the rod pinned to the rocker at R and the barrel to the frame at C, held
together by the slide (an unknown force across the line and an unknown couple) and pushed
apart by the given force. Every body's Newton-Euler equations are one linear system; the
friction couples ``-mu r |F| sgn(omega_rel)`` at R and C are taken from the pin forces of
the solve before, repeated until they settle at 30 digits. The torque again by the virtual
power with the friction's power ``sum c omega_rel``.
"""

from __future__ import annotations

import math

import mpmath
import pytest

from polygon_method.cli import main
from polygon_method.motion.solution import solve
from polygon_method.scene import parse_scene

from newton_euler import NewtonEuler
from test_cylinder_force import BODIES, G, OMEGA, _diff, _pin, _place, scene_text

MU = 0.2
RADII = {"R": "0.03", "C": "0.01"}  # different: the two couples do not cancel

FRICTION = """
[friction]
pins = 0.2
[pins]
R = { diameter = 60 }
C = { diameter = 20 }
"""

_C = (mpmath.mpf("0.45"), mpmath.mpf("-0.15"))


def _phic(th):
    R = _place(th)["R"]
    return mpmath.atan2(R[1] - _C[1], R[0] - _C[0])


def _sgn(x):
    return (x > 0) - (x < 0)


def reference(angle, push, massive=True, driving=None, couple=0):
    """The torque on the crank (or, ``driving`` the cylinder's rate of extension in m/s,
    the cylinder's force with the crank undriven), the pin forces and the friction couples
    at crank angle ``angle`` (deg) turning at 60 rpm ccw; ``couple`` a load on the crank."""
    with mpmath.workdps(30):
        th = mpmath.radians(angle)
        P, d1, d2 = _place(th), _diff(th, 1), _diff(th, 2)
        dphic = mpmath.diff(_phic, th)
        dL = d1["L"]
        w = mpmath.mpf(OMEGA) if driving is None else mpmath.mpf(driving) / dL
        acc = {
            k: (w**2 * v[0], w**2 * v[1]) if isinstance(v, tuple) else w**2 * v
            for k, v in d2.items()
        }
        u = ((P["R"][0] - _C[0]) / P["L"], (P["R"][1] - _C[1]) / P["L"])
        n = (-u[1], u[0])
        rel = {"R": _sgn(dphic - d1["phi4"]) * _sgn(w), "C": _sgn(dphic) * _sgn(w)}
        cR = cC = mpmath.mpf(0)
        for _ in range(200):
            ne = NewtonEuler(["OA", "AB", "QB", "rod", "barrel"], mp=True)
            ne.pin("O", (0, 0), "OA", "frame")
            ne.pin("A", P["A"], "AB", "OA")
            ne.pin("B", P["B"], "AB", "QB")
            ne.pin("Q", (mpmath.mpf("0.3"), 0), "QB", "frame")
            ne.pin("R", P["R"], "rod", "QB")
            ne.pin("C", _C, "barrel", "frame")
            ne.along("N", P["R"], n, "rod", "barrel")  # the slide: across the line
            ne.couple("Mp", "rod", "barrel")  # and a couple
            if driving is None:
                ne.couple("T", "OA", "frame")
                ne.known("rod", (push * u[0], push * u[1]), P["R"])
                ne.known("barrel", (-push * u[0], -push * u[1]), _C)
            else:
                ne.along("F", P["R"], u, "rod", "barrel")  # the driver's force: unknown
            ne.known("OA", c=couple)
            ne.known("rod", c=cR)
            ne.known("QB", c=-cR)
            ne.known("barrel", c=cC)
            for body, (m, g, k, phi) in BODIES.items():
                if massive:
                    ang_acc = 0 if phi is None else acc[phi]
                    ne.known(body, (-m * acc[g][0], -m * acc[g][1] - m * G), P[g])
                    ne.known(body, c=-m * mpmath.mpf(k) ** 2 * ang_acc)
            x = ne.solve()
            nR = -MU * mpmath.mpf(RADII["R"]) * mpmath.hypot(x["R.x"], x["R.y"]) * rel["R"]
            nC = -MU * mpmath.mpf(RADII["C"]) * mpmath.hypot(x["C.x"], x["C.y"]) * rel["C"]
            if abs(nR - cR) + abs(nC - cC) < mpmath.mpf(10) ** -26:
                break
            cR, cC = nR, nC
        out = {k: float(v) for k, v in x.items()}
        out.update(cR=float(cR), cC=float(cC), omega=float(w))
        if driving is None:  # the virtual power per unit crank speed, the friction's too
            power = push * dL + cR * (dphic - d1["phi4"]) + cC * dphic
            for body, (m, g, k, phi) in BODIES.items():
                if massive:
                    fx, fy = -m * acc[g][0], -m * acc[g][1] - m * G
                    ang = 0 if phi is None else acc[phi]
                    power += fx * d1[g][0] + fy * d1[g][1]
                    power -= m * mpmath.mpf(k) ** 2 * ang * (1 if phi is None else d1[phi])
            out["T_power"] = float(-power)
        return out


@pytest.mark.parametrize("angle", [30.0, 135.0, 250.0, 320.0])
def test_a_passive_cylinders_pin_friction_reaches_the_torque(angle):
    push = -5e6 * math.pi / 4 * (0.05**2 - 0.02**2)
    text = scene_text('{ pressure = "5 N/mm^2", bore = 50, rod = 20 }', angle) + FRICTION
    f = solve(parse_scene(text)).forces
    ref = reference(angle, push)
    size = max(abs(v) for v in ref.values())
    assert abs(ref["cR"] + ref["cC"]) > 10.0  # the couple on the cylinder: not negligible
    assert ref["T_power"] == pytest.approx(ref["T"], abs=1e-12 * size)
    assert f.input_torque == pytest.approx(ref["T"], abs=1e-9 * size)
    for pin, on, by in (("O", "OA", "frame"), ("A", "AB", "OA"), ("B", "AB", "QB")):
        got = _pin(f, pin, on, by)
        assert got == pytest.approx((ref[pin + ".x"], ref[pin + ".y"]), abs=1e-9 * size), pin
    assert _pin(f, "Q", "QB", "frame") == pytest.approx((ref["Q.x"], ref["Q.y"]), abs=1e-9 * size)
    assert _pin(f, "R", "C-R", "QB") == pytest.approx((ref["R.x"], ref["R.y"]), abs=1e-9 * size)
    assert _pin(f, "C", "C-R", "frame") == pytest.approx((ref["C.x"], ref["C.y"]), abs=1e-9 * size)
    # the power balance with inertia and friction holds on the tool's own numbers
    assert f.input_torque * OMEGA == pytest.approx(ref["T_power"] * OMEGA, abs=1e-9 * size)


@pytest.mark.parametrize("angle", [30.0, 60.0, 135.0])
def test_a_driving_cylinders_pin_friction_reaches_its_force(angle):
    """The cylinder drives (``vs_CR``), a couple of 20 N m cw loads the crank, the links
    massless: the cylinder's force with the friction couples at its pins."""
    text = (
        scene_text('{ push = "1 N" }', angle, masses="[masses]")
        .replace('"C-R" = { push = "1 N" }', 'OA = { torque = "20 N m cw" }')
        .replace('speed = "60 rpm ccw"', 'vs_CR = "0.1 m/s"')
        + FRICTION
    )
    sol = solve(parse_scene(text))
    ref = reference(angle, 0, massive=False, driving=0.1, couple=-20)
    size = max(abs(v) for v in ref.values())
    assert sol.W["OA"] == pytest.approx(ref["omega"], rel=1e-12)
    assert abs(ref["cR"] + ref["cC"]) > 1e-3 * abs(ref["F"])  # not negligible
    assert sol.forces.input_torque == pytest.approx(ref["F"], abs=1e-9 * size)
    assert _pin(sol.forces, "R", "C-R", "QB") == pytest.approx(
        (ref["R.x"], ref["R.y"]), abs=1e-9 * size
    )


def test_the_words_say_the_cylinder_carries_a_couple(tmp_path, capsys):
    scene = tmp_path / "fric.toml"
    scene.write_text(scene_text('{ pressure = "5 N/mm^2", bore = 50, rod = 20 }', 135.0) + FRICTION)
    assert main(["steps", str(scene)]) == 0
    steps = " ".join(capsys.readouterr().out.split())
    assert "no longer a two-force member" in steps
    assert main(["solve", str(scene)]) == 0
    out = capsys.readouterr().out
    assert "tangent to the friction circles" in out
