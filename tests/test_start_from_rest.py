"""Starting from rest with an acceleration: "the crank starts from rest with alpha = 200
rad/s^2; find the torque" (``[input] speed = 0`` with ``acceleration``). Nothing moves yet,
so every acceleration has its tangential terms alone: a point's is alpha dP/dtheta, a link's
angular acceleration alpha dphi/dtheta (no centripetal, no Coriolis component).

The reference is independent of the tool: the slider crank's positions in closed form at 30
digits (mpmath), their derivatives with respect to the crank angle by mpmath's
differentiation, the accelerations alpha times them, and on them the three bodies'
Newton-Euler equations as one linear system (``tests/newton_euler.py``): the driving torque,
every pin force and the guide's normal force to 1e-9; the torque also by the virtual power
with inertia (the virtual velocities per rad/s). A zero speed without an acceleration keeps
its meaning (the weights and loads held, no inertia).
"""

from __future__ import annotations


import mpmath
import numpy as np
import pytest

from polygon_method.cli import main
from polygon_method.motion.solution import solve
from polygon_method.motion.sweeps import sweep
from polygon_method.scene import parse_scene

from newton_euler import NewtonEuler

R, L = 0.1, 0.4
M_CRANK, K_CRANK, G_CRANK = 5.0, 0.04, 0.05  # kg, m (gyration), m from O
M_ROD, K_ROD, G_ROD = 10.0, 0.12, 0.15  # from A
M_BLOCK = 8.0
LOAD = (-300.0, 0.0)  # on the piston
G = 9.81

SCENE = """
title = "engine starting from rest"
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 100
AB = 400
[sliders]
B = { path = "horizontal", through = "O" }
[input]
crank = "OA"
angle = ANGLE
speed = SPEED
acceleration = "ALPHA"
[masses]
OA = { mass = 5, along = 50, gyration = 40 }
AB = { mass = 10, along = 150, gyration = 120 }
B = { mass = 8 }
[gravity]
[loads]
B = { force = [-300, 0] }
"""


def scene_text(angle=60.0, alpha="200 rad/s^2 ccw", speed="0"):
    text = SCENE.replace("ANGLE", str(angle)).replace("SPEED", speed)
    if alpha is None:
        return text.replace('acceleration = "ALPHA"\n', "")
    return text.replace("ALPHA", alpha)


def _points(th):
    """A, B and the three centres of mass at the crank angle ``th`` (mpmath)."""
    A = (R * mpmath.cos(th), R * mpmath.sin(th))
    B = (A[0] + mpmath.sqrt(L**2 - A[1] ** 2), mpmath.mpf(0))
    u = ((B[0] - A[0]) / L, (B[1] - A[1]) / L)
    return {
        "A": A,
        "B": B,
        "G_OA": (A[0] * G_CRANK / R, A[1] * G_CRANK / R),
        "G_AB": (A[0] + G_ROD * u[0], A[1] + G_ROD * u[1]),
        "phi_AB": mpmath.atan2(B[1] - A[1], B[0] - A[0]),
    }


def reference(angle_deg, alpha):
    """{'T', pin forces, 'N'} by the matrix method at 30 digits, the start from rest with
    the crank's ``alpha`` (0: at rest, held); and the virtual power's torque."""
    with mpmath.workdps(30):
        th = mpmath.radians(angle_deg)
        P = _points(th)
        d = {}
        for k, v in P.items():
            if isinstance(v, tuple):
                d[k] = tuple(mpmath.diff(lambda t, k=k, i=i: _points(t)[k][i], th) for i in (0, 1))
            else:
                d[k] = mpmath.diff(lambda t, k=k: _points(t)[k], th)

        def v1(k):  # per rad/s of the crank
            return d[k]

        a = {
            k: (alpha * v[0], alpha * v[1]) if isinstance(v, tuple) else alpha * v
            for k, v in d.items()
        }
        ne = NewtonEuler(["OA", "AB", "blockB"], about={"blockB": P["B"]}, mp=True)
        ne.pin("O", (0, 0), "OA", "frame")
        ne.pin("A", P["A"], "AB", "OA")
        ne.pin("B", P["B"], "AB", "blockB")
        ne.along("N", P["B"], (0, 1), "blockB", "frame")
        ne.couple("T", "OA", "frame")
        power = 0
        for body, m, k, g, phi in (
            ("OA", M_CRANK, K_CRANK, "G_OA", None),
            ("AB", M_ROD, K_ROD, "G_AB", "phi_AB"),
            ("blockB", M_BLOCK, 0, "B", None),
        ):
            w1 = 1 if body == "OA" else (v1(phi) if phi else 0)
            ne.known(body, (-m * a[g][0], -m * a[g][1] - m * G), P[g], -m * k**2 * alpha * w1)
            vg = v1(g)
            power += -m * (a[g][0] * vg[0] + a[g][1] * vg[1]) - m * G * vg[1]
            power += -m * k**2 * alpha * w1 * w1
        ne.known("blockB", LOAD, P["B"])
        power += LOAD[0] * v1("B")[0]
        x = ne.solve()
        out = {k: float(v) for k, v in x.items()}
        out["T_power"] = float(-power)  # T x 1 rad/s + the rest = 0
        return out


def _forces(text):
    sol = solve(parse_scene(text))
    return sol, sol.forces


def _pin(f, point, on, by):
    for p in f.pins:
        if (p.point, p.on, p.by) == (point, on, by):
            return p.force
        if (p.point, p.on, p.by) == (point, by, on):
            return (-p.force[0], -p.force[1])
    raise KeyError((point, on, by))


@pytest.mark.parametrize("angle", [30.0, 60.0, 135.0, 250.0])
@pytest.mark.parametrize("alpha", [200.0, -150.0])
def test_the_start_against_the_matrix_method(angle, alpha):
    text = scene_text(angle, f"{abs(alpha)} rad/s^2 {'ccw' if alpha > 0 else 'cw'}")
    sol, f = _forces(text)
    ref = reference(angle, alpha)
    size = max(abs(v) for v in ref.values())
    assert f.input_torque == pytest.approx(ref["T"], abs=1e-9 * size)
    assert ref["T_power"] == pytest.approx(ref["T"], abs=1e-12 * size)
    for pin, on, by in (("O", "OA", "frame"), ("A", "AB", "OA"), ("B", "AB", "block B")):
        got = _pin(f, pin, on, by)
        assert got[0] == pytest.approx(ref[pin + ".x"], abs=1e-9 * size), pin
        assert got[1] == pytest.approx(ref[pin + ".y"], abs=1e-9 * size), pin
    (g,) = f.guides
    assert g.normal == pytest.approx(ref["N"], abs=1e-9 * size)  # (the guide is horizontal)
    assert sol.scene.at_rest and sol.scene.start_alpha == alpha


def test_at_rest_without_an_acceleration_still_holds_the_weights():
    sol, f = _forces(scene_text(60.0, None))
    ref = reference(60.0, 0.0)
    size = max(abs(v) for v in ref.values())
    assert sol.scene.start_alpha == 0.0
    assert f.input_torque == pytest.approx(ref["T"], abs=1e-9 * size)
    assert all(i.force == (0.0, 0.0) for i in f.inertia)


def test_the_sweep_starts_from_rest_at_every_angle():
    sc = parse_scene(scene_text())
    degs = np.array([10.0, 75.0, 160.0, 300.0])
    res = sweep(sc, np.radians(degs))
    cols = {n: np.asarray(a, dtype=float) for n, _, a in res.force_columns()}
    for deg, T in zip(degs, cols["torque_inertia"]):
        ref = reference(float(deg), 200.0)
        assert T == pytest.approx(ref["T"], abs=1e-9 * max(abs(v) for v in ref.values()))


def test_the_views_say_it(tmp_path, capsys):
    scene = tmp_path / "start.toml"
    scene.write_text(scene_text())
    assert main(["solve", str(scene)]) == 0
    text = capsys.readouterr().out
    assert "starting from rest ccw, 200 rad/s^2 ccw" in text
    assert "tangential terms alone" in text and "the inertia of the start" in text
    assert "at rest: no inertia" not in text
    d = solve(parse_scene(scene_text())).to_dict()
    assert d["at_rest"] is True and d["start_alpha"] == 200.0
    assert main(["steps", str(scene)]) == 0
    steps = " ".join(capsys.readouterr().out.split())
    assert "Starting from rest with alpha_OA = 200 rad/s^2 ccw" in steps
    assert "Weights at rest (no inertia)" not in steps
    assert "the start's alpha is taken in section 6" in steps


def test_the_check_names_the_holding_torque_as_the_inertia_left_out(tmp_path, capsys):
    held = reference(60.0, 0.0)["T"]
    scene = tmp_path / "start.toml"
    way = "ccw" if held > 0 else "cw"
    scene.write_text(scene_text() + f'[answers]\ntorque = "{abs(held):.6g} N m {way}"\n')
    main(["check", str(scene)])
    out = capsys.readouterr().out
    assert "inertia_left_out" in out or "the inertia left out" in out


@pytest.mark.parametrize(
    "speed, alpha, words",
    [
        ('"0 rad/s cw"', "200 rad/s^2 ccw", "turns the way it accelerates"),
    ],
)
def test_refused_in_one_line(tmp_path, capsys, speed, alpha, words):
    scene = tmp_path / "bad.toml"
    scene.write_text(scene_text(60.0, alpha, speed))
    assert main(["solve", str(scene)]) == 2
    err = capsys.readouterr().err.strip()
    assert words in err and len(err.splitlines()) == 1 and "speed" in err


def test_no_masses_refused_with_the_reason(tmp_path, capsys):
    text = scene_text().split("[masses]")[0]
    scene = tmp_path / "bare.toml"
    scene.write_text(text)
    assert main(["solve", str(scene)]) == 2
    err = capsys.readouterr().err.strip()
    assert "starting from rest" in err and len(err.splitlines()) == 1
