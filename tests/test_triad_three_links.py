"""A triad whose plate is made of three links (a class-III six-bar: the triangle BC, CD, DB
hung from the crank's rod AB and the rockers EC, FD): every link a body of its own, massive,
gravity, loads at two vertices and a couple on a side. The force analysis solves the
triangle as one plate for the three hanging links' forces, then the pins between its sides.

The reference is independent of the tool: the 50-digit constraint solve's kinematics
(``tests/reference.py``) and on it the seven bodies' Newton-Euler equations as one 21 x 21
system (``tests/newton_euler.py``) at 30 digits, a pin joining three bodies written as two
pin forces: the driving torque and every pin force the tool reports to 1e-9 of the largest.
A load at a vertex acts on the body that owns it (B and C the plate's first side BC, D the
second side CD), as the tool says.
"""

from __future__ import annotations

from pathlib import Path

import mpmath
from mpmath import mpf
import pytest

from polygon_method import load_scene
from polygon_method.cli import main
from polygon_method.forces import FRAME
from polygon_method.motion.solution import solve
from polygon_method.scene import parse_scene

from newton_euler import NewtonEuler
from reference import reference_solution

ROOT = Path(__file__).resolve().parent.parent
MASSES = """
[masses]
OA = { mass = 0.5, along = 10 }
AB = { mass = 1.1, along = 55, gyration = 35 }
BC = { mass = 0.8, distances = { B = 45, C = 45 }, turn = "ccw", gyration = 25 }
CD = { mass = 0.7, along = 35, gyration = 22 }
DB = { mass = 0.75, along = 36, gyration = 23 }
EC = { mass = 1.2, along = 61, gyration = 38 }
FD = { mass = 1.0, along = 50, gyration = 31 }
[gravity]
direction = 250
[loads]
C = { force = [15, -40] }
D = { force = [-10, 5] }
CD = { torque = "0.8 N m ccw" }
"""

PINS = [
    ("O", "OA", FRAME),
    ("A", "AB", "OA"),
    ("B", "AB", "BC"),
    ("B", "BC", "DB"),
    ("C", "EC", "BC"),
    ("C", "BC", "CD"),
    ("D", "FD", "CD"),
    ("D", "CD", "DB"),
    ("E", "EC", FRAME),
    ("F", "FD", FRAME),
]
OWNER = {"C": "BC", "D": "CD"}


def scene_text(angle):
    text = (ROOT / "tests" / "textbook" / "class3_triangle_plate.toml").read_text()
    return text.replace("angle = 30", f"angle = {angle}") + MASSES


def reference(sc, sol):
    with mpmath.workdps(50):
        ref = reference_solution(sc, sol.P)
    with mpmath.workdps(30):
        P, Acc, Al = ref["positions"], ref["accelerations"], ref["alpha"]

        def pos(n):
            return P[n] if n in P else tuple(mpf(c) for c in sc.ground[n])

        def acc(n):
            return Acc[n] if n in Acc else (mpf(0), mpf(0))

        bodies = ["OA", "AB", "BC", "CD", "DB", "EC", "FD"]
        ne = NewtonEuler(bodies, mp=True)
        for point, on, by in PINS:
            ne.pin(f"{point} {on} {by}", pos(point), on, by)
        ne.couple("T", "OA", FRAME)
        g = sc.gravity
        for m in sc.masses:
            lk = sc.link(m.body)
            lam, mu = mpf(m.lam), mpf(m.mu)

            def at(T, lk=lk, lam=lam, mu=mu):
                (px, py), (qx, qy) = T(lk.p), T(lk.q)
                dx, dy = qx - px, qy - py
                return (px + lam * dx - mu * dy, py + lam * dy + mu * dx)

            mass = mpf(m.mass)
            G, a = at(pos), at(acc)
            wx, wy = mass * mpf(g.g) * mpf(g.direction[0]), mass * mpf(g.g) * mpf(g.direction[1])
            ne.known(lk.key, (wx - mass * a[0], wy - mass * a[1]), G, -mpf(m.inertia) * Al[lk.key])
        for ld in sc.loads:
            if ld.force is not None:
                ne.known(OWNER[ld.target], tuple(mpf(c) for c in ld.force), pos(ld.target))
            else:
                ne.known(ld.target, c=mpf(ld.torque))
        x = ne.solve()
        return {k: float(v) for k, v in x.items()}


@pytest.mark.parametrize("angle", [30.0, 110.0, 250.0])
def test_the_three_link_plate_against_the_matrix_method(angle):
    sc = parse_scene(scene_text(angle))
    sol = solve(sc)
    f = sol.forces
    ref = reference(sc, sol)
    size = max(abs(v) for v in ref.values())
    assert f.input_torque == pytest.approx(ref["T"], abs=1e-9 * size)
    seen = set()
    for p in f.pins:
        for point, on, by in PINS:
            if p.point != point or {p.on, p.by} != {on, by}:
                continue
            sign = 1.0 if p.on == on else -1.0
            name = f"{point} {on} {by}"
            assert sign * p.force[0] == pytest.approx(ref[name + ".x"], abs=1e-9 * size), name
            assert sign * p.force[1] == pytest.approx(ref[name + ".y"], abs=1e-9 * size), name
            seen.add(name)
    assert len(seen) == len(PINS)


def test_the_views_give_it(tmp_path, capsys):
    scene = tmp_path / "tri.toml"
    scene.write_text(scene_text(30.0))
    assert main(["solve", str(scene)]) == 0
    out = capsys.readouterr().out
    assert "not solved for forces yet" not in out and "input torque on OA (inertia" in out
    assert main(["steps", str(scene)]) == 0
    steps = " ".join(capsys.readouterr().out.split())
    assert "the plate's sides: BC's moments about B and CD's about D" in steps
    for whose in ("BC and CD and DB", "AB", "EC", "FD", "BC and CD", "DB"):  # (in this order)
        assert f"force polygon of {whose} at " in steps, whose
        steps = steps[steps.index(f"force polygon of {whose} at ") + 1 :]
    sol = solve(load_scene(scene))
    assert sol.to_dict()["forces"] is not None
