"""A force given in a passive cylinder (``[loads] "C-R" = { push = ... }``, a pull, oil
pressure on the bore or the annulus, a damper ``-c vs``): a two-force member's push at
both ends, the crank driven.

The references are independent of the tool: a crank-rocker four-bar whose rocker carries
the rod's end R of a cylinder pivoted on the frame at C, its positions in closed form at
30 digits (mpmath), their derivatives with respect to the crank angle by mpmath's
differentiation (the velocities omega d/dtheta, the accelerations omega^2 d2/dtheta2: the
crank turns steadily), and

- every body's Newton-Euler equations as one linear system (``tests/newton_euler.py``):
  the crank's torque and every pin force to 1e-9;
- the virtual power ``T omega + F vs + sum(W . v_G) - sum(m a_G . v_G) - sum(I alpha
  omega) = 0`` (vs the cylinder's rate of extension, ``d|R - C|/dt``): the torque again;
- the cylinder's force from the scene's words by hand (pressure times the bore's or the
  annulus's area, ``push - c vs``).
"""

from __future__ import annotations

import json
import math

import mpmath
import numpy as np
import pytest

from polygon_method.cli import main
from polygon_method.motion.solution import solve
from polygon_method.motion.sweeps import sweep
from polygon_method.scene import parse_scene

from newton_euler import NewtonEuler

G = 9.81
OMEGA = 2 * math.pi  # 60 rpm

SCENE = """
title = "four-bar with a cylinder on its rocker"
units = "mm"
[ground]
O = [0, 0]
Q = [300, 0]
C = [450, -150]
[links]
OA = 100
AB = 300
QB = 200
[points]
R = { on = "QB", along = 120 }
[cylinders]
"C-R" = {}
[assembly]
B = "above"
MASSES
[loads]
"C-R" = LOAD
[input]
crank = "OA"
angle = ANGLE
speed = SPEED
"""

MASSIVE = """[masses]
OA = { mass = 2, along = 50, gyration = 35 }
AB = { mass = 5, along = 150, from = "A", gyration = 90 }
QB = { mass = 3, along = 100, from = "Q", gyration = 60 }
[gravity]"""

LOADS = {  # the scene's words -> (push N, + apart; damping N s/m)
    '{ push = "2 kN" }': (2000.0, 0.0),
    '{ pull = "1.5 kN" }': (-1500.0, 0.0),
    '{ pressure = "5 N/mm^2", bore = 50 }': (5e6 * math.pi / 4 * 0.05**2, 0.0),
    '{ pressure = "5 N/mm^2", bore = 50, rod = 20 }': (
        -5e6 * math.pi / 4 * (0.05**2 - 0.02**2),
        0.0,
    ),
    '{ pressure = "50 bar", back = "20 bar", bore = 50, rod = 20 }': (
        5e6 * math.pi / 4 * 0.05**2 - 2e6 * math.pi / 4 * (0.05**2 - 0.02**2),
        0.0,
    ),
    '{ damping = "3000 N s/m" }': (0.0, 3000.0),
    '{ push = "500 N", damping = "2 kN s/m" }': (500.0, 2000.0),
}


def scene_text(load, angle=60.0, masses=MASSIVE, speed='"60 rpm ccw"'):
    return (
        SCENE.replace("MASSES", masses)
        .replace("LOAD", load)
        .replace("ANGLE", str(angle))
        .replace("SPEED", speed)
    )


def _place(th):
    """The points at crank angle ``th`` (rad), in m, and the links' angles."""
    A = (mpmath.mpf("0.1") * mpmath.cos(th), mpmath.mpf("0.1") * mpmath.sin(th))
    Q = (mpmath.mpf("0.3"), mpmath.mpf(0))
    dx, dy = Q[0] - A[0], Q[1] - A[1]
    d = mpmath.sqrt(dx**2 + dy**2)
    a = (mpmath.mpf("0.09") - mpmath.mpf("0.04") + d**2) / (2 * d)  # from A along AQ
    h = mpmath.sqrt(mpmath.mpf("0.09") - a**2)
    B = (A[0] + a * dx / d - h * dy / d, A[1] + a * dy / d + h * dx / d)  # left of A -> Q
    R = (Q[0] + mpmath.mpf("0.6") * (B[0] - Q[0]), Q[1] + mpmath.mpf("0.6") * (B[1] - Q[1]))
    return {
        "A": A,
        "B": B,
        "R": R,
        "G2": (A[0] / 2, A[1] / 2),
        "G3": (A[0] + (B[0] - A[0]) / 2, A[1] + (B[1] - A[1]) / 2),
        "G4": (Q[0] + (B[0] - Q[0]) / 2, Q[1] + (B[1] - Q[1]) / 2),
        "phi3": mpmath.atan2(B[1] - A[1], B[0] - A[0]),
        "phi4": mpmath.atan2(B[1] - Q[1], B[0] - Q[0]),
        "L": mpmath.sqrt((R[0] - mpmath.mpf("0.45")) ** 2 + (R[1] + mpmath.mpf("0.15")) ** 2),
    }


def _diff(th, n):
    """{name: n-th derivative with respect to the crank angle}."""
    out = {}
    for k, v in _place(th).items():
        if isinstance(v, tuple):
            out[k] = tuple(mpmath.diff(lambda t, k=k, i=i: _place(t)[k][i], th, n) for i in (0, 1))
        else:
            out[k] = mpmath.diff(lambda t, k=k: _place(t)[k], th, n)
    return out


BODIES = {  # link: (mass, centre, gyration, angle)
    "OA": (2, "G2", "0.035", None),
    "AB": (5, "G3", "0.09", "phi3"),
    "QB": (3, "G4", "0.06", "phi4"),
}


def reference(
    angle, push, damping, massive=True, omega=OMEGA, alpha=0.0, rest=False, spring=(0, 0)
):
    """The cylinder's force, the torque on the crank and the pin forces at the crank angle
    ``angle`` (deg) turning at ``omega`` rad/s ccw (``rest``: at rest where it stands, the
    velocities nought; ``spring``: (k N/m, L0 m), its force k (L0 - L), L the closed-form
    length), by the matrix method and by the virtual power."""
    with mpmath.workdps(30):
        th = mpmath.radians(angle)
        P, d1, d2 = _place(th), _diff(th, 1), _diff(th, 2)
        w = mpmath.mpf(0) if rest else mpmath.mpf(omega)
        vel = {k: (w * v[0], w * v[1]) if isinstance(v, tuple) else w * v for k, v in d1.items()}
        acc = {
            k: (w**2 * v[0] + alpha * d1[k][0], w**2 * v[1] + alpha * d1[k][1])
            if isinstance(v, tuple)
            else w**2 * v + alpha * d1[k]
            for k, v in d2.items()
        }
        vs = vel["L"]
        F = push - damping * vs + mpmath.mpf(spring[0]) * (mpmath.mpf(spring[1]) - P["L"])
        C = (mpmath.mpf("0.45"), mpmath.mpf("-0.15"))
        u = ((P["R"][0] - C[0]) / P["L"], (P["R"][1] - C[1]) / P["L"])
        ne = NewtonEuler(["OA", "AB", "QB"], mp=True)
        ne.pin("O", (0, 0), "OA", "frame")
        ne.pin("A", P["A"], "AB", "OA")
        ne.pin("B", P["B"], "AB", "QB")
        ne.pin("Q", (mpmath.mpf("0.3"), 0), "QB", "frame")
        ne.couple("T", "OA", "frame")
        ne.known("QB", (F * u[0], F * u[1]), P["R"])
        # the virtual power, per unit crank speed (the virtual velocities d1)
        power = F * d1["L"]
        for body, (m, g, k, phi) in BODIES.items():
            if not massive:
                continue
            inertia = m * mpmath.mpf(k) ** 2
            ang_acc = alpha if phi is None else acc[phi]
            fx, fy = -m * acc[g][0], -m * acc[g][1] - m * G
            ne.known(body, (fx, fy), P[g], -inertia * ang_acc)
            ang_vel = 1 if phi is None else d1[phi]
            power += fx * d1[g][0] + fy * d1[g][1] - inertia * ang_acc * ang_vel
        x = {k: float(v) for k, v in ne.solve().items()}
        x["T_power"] = float(-power)
        x["F"], x["vs"], x["L"] = float(F), float(vs), float(P["L"])
        x["R"] = tuple(float(c) for c in P["R"])
        x["u"] = tuple(float(c) for c in u)
        return x


def _pin(f, point, on, by):
    (p,) = [p for p in f.pins if p.point == point and {p.on, p.by} == {on, by}]
    return p.force if p.on == on else (-p.force[0], -p.force[1])


@pytest.mark.parametrize("load", sorted(LOADS))
@pytest.mark.parametrize("angle", [30.0, 135.0, 250.0, 320.0])
def test_against_the_matrix_method_and_the_virtual_power(load, angle):
    push, damping = LOADS[load]
    sol = solve(parse_scene(scene_text(load, angle)))
    ref = reference(angle, push, damping)
    size = max(abs(v) for v in ref.values() if isinstance(v, float))
    assert sol.P["R"] == pytest.approx(ref["R"], abs=1e-12)  # the branch and the place
    f = sol.forces
    assert ref["T_power"] == pytest.approx(ref["T"], abs=1e-12 * size)
    assert f.input_torque == pytest.approx(ref["T"], abs=1e-9 * size)
    for pin, on, by in (("O", "OA", "frame"), ("A", "AB", "OA"), ("B", "AB", "QB")):
        got = _pin(f, pin, on, by)
        assert got == pytest.approx((ref[pin + ".x"], ref[pin + ".y"]), abs=1e-9 * size), pin
    got = _pin(f, "Q", "QB", "frame")
    assert got == pytest.approx((ref["Q.x"], ref["Q.y"]), abs=1e-9 * size)
    # the cylinder: a two-force member, F u on the rocker at R and -F u on the frame at C
    F, u = ref["F"], ref["u"]
    on_rocker = _pin(f, "R", "QB", "C-R")
    assert on_rocker == pytest.approx((F * u[0], F * u[1]), abs=1e-9 * size)
    on_frame = _pin(f, "C", "frame", "C-R")
    assert on_frame == pytest.approx((-F * u[0], -F * u[1]), abs=1e-9 * size)
    d = sol.to_dict()["forces"]["cylinders"]["C-R"]
    assert d["force"] == pytest.approx(F, abs=1e-9 * size)
    assert d["rate_of_extension"] == pytest.approx(ref["vs"], rel=1e-12)


@pytest.mark.parametrize("load", ['{ push = "2 kN" }', '{ push = "500 N", damping = "2 kN s/m" }'])
def test_the_loads_alone_and_the_power_balance(load):
    """An empty [masses]: the static force analysis, the torque ``-F vs / omega``; the
    top-level power balance counts the cylinder's power too."""
    push, damping = LOADS[load]
    sol = solve(parse_scene(scene_text(load, 135.0, masses="[masses]")))
    ref = reference(135.0, push, damping, massive=False)
    want = -ref["F"] * ref["vs"] / OMEGA
    assert ref["T"] == pytest.approx(want, rel=1e-12)
    assert sol.forces.input_torque == pytest.approx(want, rel=1e-9)
    assert sol.input_torque == pytest.approx(want, rel=1e-9)


def test_at_rest_a_damper_pushes_nothing_and_a_push_is_held():
    load = '{ push = "2 kN", damping = "3000 N s/m" }'
    sol = solve(parse_scene(scene_text(load, 135.0, speed="0")))
    ref = reference(135.0, 2000.0, 3000.0, rest=True)
    assert ref["F"] == 2000.0  # (nothing moves: vs = 0)
    size = max(abs(v) for v in ref.values() if isinstance(v, float))
    assert sol.forces.input_torque == pytest.approx(ref["T"], abs=1e-9 * size)
    assert sol.to_dict()["forces"]["cylinders"]["C-R"]["force"] == 2000.0
    start = solve(
        parse_scene(scene_text(load, 135.0, speed="0") + 'acceleration = "20 rad/s^2 ccw"\n')
    )
    ref = reference(135.0, 2000.0, 3000.0, rest=True, alpha=20.0)
    assert start.forces.input_torque == pytest.approx(ref["T"], abs=1e-9 * size)


def test_the_sweep_gives_the_force_and_torque_over_a_cycle():
    load = '{ push = "500 N", damping = "2 kN s/m" }'
    sc = parse_scene(scene_text(load))
    degs = np.array([10.0, 100.0, 200.0, 290.0])
    res = sweep(sc, np.radians(degs))
    cols = {n: np.asarray(a, dtype=float) for n, _, a in res.force_columns()}
    for k, deg in enumerate(degs):
        ref = reference(float(deg), 500.0, 2000.0)
        size = max(abs(v) for v in ref.values() if isinstance(v, float))
        assert cols["F_C-R"][k] == pytest.approx(ref["F"], abs=1e-9 * size)
        assert cols["torque_inertia"][k] == pytest.approx(ref["T"], abs=1e-9 * size)
    # the loads' power balance over the sweep (no inertia) counts the damper too
    ref = reference(float(degs[1]), 500.0, 2000.0, massive=False)
    assert float(np.asarray(res.input_torque)[1]) == pytest.approx(ref["T"], rel=1e-9)


def test_every_view_says_it(tmp_path, capsys):
    scene = tmp_path / "damper.toml"
    scene.write_text(scene_text('{ push = "500 N", damping = "2 kN s/m" }'))
    ref = reference(60.0, 500.0, 2000.0)
    assert main(["solve", str(scene)]) == 0
    out = capsys.readouterr().out
    line = [s for s in out.splitlines() if s.startswith("force in the cylinder C-R is given")]
    assert len(line) == 1 and "a push of 500 N, a damper of 2 kN s/m" in line[0]
    assert f"= {ref['F']:.4g} N, pushing its ends apart" in line[0]
    assert main(["solve", "--json", str(scene)]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["forces"]["cylinders"]["C-R"]["damping"] == 2000.0
    assert main(["steps", str(scene)]) == 0
    steps = " ".join(capsys.readouterr().out.split())
    assert "the force in the cylinder C-R is given" in steps
    assert "a two-force member: F u on the body at R, -F u on the body at C" in steps
    assert main(["sweep", str(scene), "--summary"]) == 0
    assert "force in the cylinder, + pushing apart" in capsys.readouterr().out
    assert main(["draw", "--forces", str(scene), "-o", str(tmp_path / "f.pdf")]) == 0
    assert "free body" in capsys.readouterr().out


@pytest.mark.parametrize(
    "load, words",
    [
        ('{ pressure = "5 N/mm^2", bore = -50 }', "length must be positive"),
        ('{ pressure = "5 N/mm^2" }', "needs pressure and bore"),
        ("{ bore = 50 }", "needs pressure and bore"),
        ('{ pressure = "5 N/mm^2", bore = 50, rod = 60 }', "must be thinner than the bore"),
        ('{ pressure = "5 N/mm^2", bore = 50, back = "1 bar" }', "give the rod's diameter"),
        ('{ push = "2 kN", pull = "1 kN" }', "give one of push, pull and pressure"),
        ('{ push = "-2 kN" }', "say pull instead"),
        ('{ pressure = "-5 N/mm^2", bore = 50 }', "is below a vacuum"),
        # below any gauge's resolution (1 mPa): subnormal forces and powers, or a text
        # that reads as 0.0 though it says otherwise
        ('{ pressure = "1e-300 Pa", bore = 50 }', "'1e-300 Pa' is absurdly small"),
        ('{ pressure = "1e-310 Pa", bore = 50, rod = 20 }', "absurdly small"),
        ('{ pressure = "1e-330 N/mm^2", bore = 50 }', "absurdly small"),
        ('{ pressure = "-1e-300 bar", bore = 50 }', "absurdly small"),
        ('{ pressure = "5 N/mm^2", bore = 50, rod = 20, back = "1e-300 Pa" }', "absurdly small"),
        ('{ push = "1e-330 N" }', "absurdly small"),
        ('{ damping = "1e-300 N s/m" }', "absurdly small"),
        ('{ pressure = "5 N/mm^2", bore = 50, rod = 20, back = "-2 bar" }', "is below a vacuum"),
        ('{ damping = "-30 N s/m" }', "a damper resists its motion"),
        ('{ force = "2 kN", direction = 30 }', "acts along its line"),
        ("{ stiffness = 3 }", "needs its stiffness and its free length"),
        ('{ stiffness = "-2 N/mm", free_length = 250 }', "is not positive"),
        ('{ stiffness = "2 N/mm", free_length = -250 }', "is not positive"),
        ('{ stiffness = "2 N/mm", free_length = 0 }', "is not positive"),
        ("{ free_length = 250 }", "no stiffness"),
        ('{ stiffness = "2 kg", free_length = 250 }', "stiffness"),
        ('"2 kN"', "push"),
    ],
)
def test_bad_input_is_one_line(tmp_path, capsys, load, words):
    scene = tmp_path / "bad.toml"
    scene.write_text(scene_text(load))
    assert main(["solve", str(scene)]) == 2
    err = capsys.readouterr().err.strip()
    assert words in err and len(err.splitlines()) == 1 and "[loads]" in err and "C-R" in err


def test_a_force_on_the_driving_cylinder_is_refused(tmp_path, capsys):
    text = scene_text('{ push = "2 kN" }').replace('speed = "60 rpm ccw"', 'vs_CR = "0.1 m/s"')
    scene = tmp_path / "driving.toml"
    scene.write_text(text)
    assert main(["solve", str(scene)]) == 2
    err = capsys.readouterr().err.strip()
    assert "the cylinder C-R drives" in err and "found, not given" in err
    assert len(err.splitlines()) == 1


def test_without_the_force_analysis_it_is_refused(tmp_path, capsys):
    scene = tmp_path / "bare.toml"
    scene.write_text(scene_text('{ push = "2 kN" }', masses=""))
    assert main(["solve", str(scene)]) == 2
    err = capsys.readouterr().err.strip()
    assert "applied by the force analysis" in err and len(err.splitlines()) == 1


def test_the_worked_problem_and_its_answers():
    from pathlib import Path

    from polygon_method.check import check_answers
    from polygon_method.scene import load_scene

    path = Path(__file__).resolve().parent.parent / "worked_problems/cylinder_pull_on_rocker.toml"
    sol = solve(load_scene(path))
    push = -5e6 * math.pi / 4 * (0.05**2 - 0.02**2)
    ref = reference(60.0, push, 0.0)
    size = max(abs(v) for v in ref.values() if isinstance(v, float))
    assert sol.forces.input_torque == pytest.approx(ref["T"], abs=1e-9 * size)
    rows = check_answers(sol)
    assert len(rows) == 7 and all(r.ok for r in rows), rows
    assert abs(rows[1].given - ref["T"]) < 0.0005 * abs(ref["T"])  # the file's 4 figures


@pytest.mark.parametrize(
    "load, slip, push, damping",
    [
        (
            '{ pressure = "5 N/mm^2", bore = 50, rod = 20 }',
            "rod_area_not_taken_off",
            -5e6 * math.pi / 4 * 0.05**2,
            0.0,
        ),
        ('{ push = "2 kN" }', "cylinder_force_left_out", 0.0, 0.0),
        ('{ push = "500 N", damping = "2 kN s/m" }', "damper_sense_turned", 500.0, -2000.0),
    ],
)
def test_check_names_the_cylinders_slips(load, slip, push, damping):
    """The torque a slip gives, worked by the matrix method with the slip's force, is
    named by ``check``."""
    from polygon_method.check import check_answers

    ref = reference(135.0, push, damping)
    way = "ccw" if ref["T"] > 0 else "cw"
    text = scene_text(load, 135.0) + f'[answers]\ntorque = "{abs(ref["T"]):.5g} N m {way}"\n'
    (row,) = check_answers(solve(parse_scene(text)))
    assert not row.ok and row.mistake == slip, row


def test_named_either_way_and_not_twice(tmp_path, capsys):
    """``"R-C"`` names the same cylinder (its force still + pushing the ends apart); two
    entries for one cylinder, or a push under a name that is no cylinder, are refused."""
    text = scene_text('{ push = "2 kN" }', 135.0).replace('"C-R" = { push', '"R-C" = { push')
    sol = solve(parse_scene(text))
    ref = reference(135.0, 2000.0, 0.0)
    assert sol.forces.input_torque == pytest.approx(ref["T"], rel=1e-9)
    scene = tmp_path / "twice.toml"
    scene.write_text(
        text.replace('"R-C" = { push = "2 kN" }', 'RC = { push = "2 kN" }\nCR = {pull = 1}')
    )
    assert main(["solve", str(scene)]) == 2
    err = capsys.readouterr().err.strip()
    assert "the cylinder C-R is loaded twice" in err and len(err.splitlines()) == 1
    scene.write_text(text.replace('[cylinders]\n"C-R" = {}\n', ""))
    assert main(["solve", str(scene)]) == 2
    err = capsys.readouterr().err.strip()
    assert "no cylinder R-C in [cylinders]" in err and len(err.splitlines()) == 1


@pytest.mark.parametrize("angle", [30.0, 135.0, 250.0])
def test_the_bounds_hold_with_a_damper(angle):
    """Each force's stated error bound (``forces/bounds.py``, a damper's force erring by c
    times its rate's bound) holds against the 30-digit matrix method."""
    from polygon_method.forces.bounds import force_bounds

    sol = solve(parse_scene(scene_text('{ push = "500 N", damping = "2 kN s/m" }', angle)))
    ref = reference(angle, 500.0, 2000.0)
    f, b = sol.forces, force_bounds(sol)
    assert 0 < b.effort < 1e-9
    assert abs(f.input_torque - ref["T"]) <= b.effort * b.force * b.length
    for pin, on, by in (("O", "OA", "frame"), ("A", "AB", "OA"), ("B", "AB", "QB")):
        got = _pin(f, pin, on, by)
        err = math.hypot(got[0] - ref[pin + ".x"], got[1] - ref[pin + ".y"])
        (e,) = [v for (p, o, y), v in b.pins.items() if p == pin and {o, y} == {on, by}]
        assert err <= e * b.force, pin


def test_a_pressure_below_the_atmosphere_pulls_and_is_said_to(tmp_path, capsys):
    """-0.5 bar gauge on the cap side pulls the rod in with 0.5e5 pi/4 d^2 (closed form);
    below a vacuum (-1.01325 bar) is refused above."""
    scene = tmp_path / "vacuum.toml"
    scene.write_text(scene_text('{ pressure = "-0.5 bar", bore = 50 }'))
    assert main(["solve", str(scene)]) == 0
    line = next(x for x in capsys.readouterr().out.splitlines() if "is given (" in x)
    f = 0.5e5 * math.pi / 4 * 0.05**2
    assert f"F = -{f:.4g} N" in line and "pulling the rod in" in line, line
    assert "pushing the rod out" not in line, line


def _floats(doc):
    """Every number in a --json document."""
    if isinstance(doc, dict):
        for v in doc.values():
            yield from _floats(v)
    elif isinstance(doc, list):
        for v in doc:
            yield from _floats(v)
    elif isinstance(doc, float):
        yield doc


@pytest.mark.parametrize("pressure", ["0.002 Pa", "-0.002 Pa"])
def test_a_pressure_just_above_the_least_is_exact_and_no_junk(tmp_path, capsys, pressure):
    """Just above the least pressure read (1 mPa), a 50 mm bore's force p pi/4 D^2 (a few
    micronewtons) and the crank's torque agree with the matrix method to 1e-9 of the
    loads' size, and no number of the --json is subnormal, inf or NaN."""
    p = float(pressure.split()[0])
    push = p * math.pi / 4 * 0.05**2
    scene = tmp_path / "small.toml"
    scene.write_text(scene_text(f'{{ pressure = "{pressure}", bore = 50 }}', masses="[masses]"))
    ref = reference(60.0, push, 0.0, massive=False)
    sol = solve(parse_scene(scene.read_text()))
    assert sol.forces.input_torque == pytest.approx(ref["T"], rel=1e-9)
    assert ref["T_power"] == pytest.approx(ref["T"], rel=1e-12)
    assert main(["solve", "--json", str(scene)]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["forces"]["cylinders"]["C-R"]["force"] == pytest.approx(push, rel=1e-12)
    for x in _floats(doc):
        assert math.isfinite(x) and (x == 0 or abs(x) >= 2.2250738585072014e-308), x


@pytest.mark.parametrize("load", ['{ pressure = "0 Pa", bore = 50, rod = 20 }', '{ push = "0 N" }'])
def test_no_force_is_said_so(tmp_path, capsys, load):
    """A gauge pressure of nought (or a push of 0 N) pushes nothing: its line says F = 0 N
    with no way it acts (it said "pulling the rod in ... F = 0 N, pushing its ends apart")."""
    scene = tmp_path / "nought.toml"
    scene.write_text(scene_text(load))
    assert main(["solve", str(scene)]) == 0
    line = next(x for x in capsys.readouterr().out.splitlines() if "is given (" in x)
    assert line.endswith("F = 0 N"), line
    assert "pulling" not in line and "pushing" not in line, line
