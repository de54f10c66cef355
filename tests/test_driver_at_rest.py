"""A driving block or a driving wheel at rest (``vs_A = 0``, ``omega_W = "0 rad/s"``) with
weights and loads: the force (torque) its driver needs to hold the mechanism; with an
acceleration too, the effort to start it from rest (every acceleration its tangential terms
alone, the start's acceleration times the motion per unit speed of the driver).

The reference is independent of the tool: the positions in closed form at 30 digits
(mpmath), their derivatives with respect to the driver's place (or the wheel's angle) by
mpmath's differentiation, and every body's Newton-Euler equations as one linear system
(``tests/newton_euler.py``): the driver's effort, the pin forces and the guides' (the
ground's) forces to 1e-9; the holding effort also the derivative of the potential energy
(with the loads' work) with respect to the driver's place.
"""

from __future__ import annotations

import mpmath
import pytest

from polygon_method.cli import main
from polygon_method.motion.solution import solve
from polygon_method.scene import parse_scene

from newton_euler import NewtonEuler

G = 9.81

TRAMMEL = """
title = "ellipse trammel held by its block"
units = "mm"
[ground]
O = [0, 0]
[links]
AB = 500
[points]
C = { on = "AB", along = 700 }
[sliders]
A = { path = "horizontal", through = "O" }
B = { path = "vertical", through = "O" }
[assembly]
B = "above"
[input]
block = "A"
s_A = S
vs_A = 0
ACC
[masses]
AB = { mass = 4, along = 250, gyration = 150 }
A = { mass = 2 }
B = { mass = 3 }
[gravity]
[loads]
C = { force = [30, -100] }
"""

WHEEL = """
title = "a wheel driver at rest"
units = "mm"
[ground]
O = [0, 0]
[links]
CA = 300
AB = 1200
[sliders]
B = { path = "horizontal", through = "O" }
[rolling]
CA = { on = "horizontal", through = [0, 0], angle = 135 }
[assembly]
B = "right"
[input]
wheel = "CA"
C = [0, 300]
omega_CA = "0 rad/s"
ACC
[masses]
CA = { mass = 20, along = 0, gyration = 200 }
AB = { mass = 8, along = 600, gyration = 350 }
B = { mass = 5 }
[gravity]
[loads]
B = { force = [-200, 0] }
"""


def _d(fn, x):
    """{name: derivative} of the points (x, y) and angles fn(x) gives."""
    out = {}
    for k, v in fn(x).items():
        if isinstance(v, tuple):
            out[k] = tuple(mpmath.diff(lambda t, k=k, i=i: fn(t)[k][i], x) for i in (0, 1))
        else:
            out[k] = mpmath.diff(lambda t, k=k: fn(t)[k], x)
    return out


def _trammel(s):
    A = (s, mpmath.mpf(0))
    B = (mpmath.mpf(0), mpmath.sqrt(mpmath.mpf("0.25") - s**2))
    C = (A[0] + mpmath.mpf("1.4") * (B[0] - A[0]), A[1] + mpmath.mpf("1.4") * (B[1] - A[1]))
    Gr = ((A[0] + B[0]) / 2, (A[1] + B[1]) / 2)
    return {"A": A, "B": B, "C": C, "G": Gr, "phi": mpmath.atan2(B[1] - A[1], B[0] - A[0])}


def trammel_reference(s, acc):
    """The driver's force on block A along +x, the pins and guides, at A's place ``s`` (m)
    and the start's acceleration ``acc`` (m/s^2 along +x; 0: held)."""
    with mpmath.workdps(30):
        s = mpmath.mpf(s)
        P, d = _trammel(s), _d(_trammel, s)
        a = {k: (acc * v[0], acc * v[1]) if isinstance(v, tuple) else acc * v for k, v in d.items()}
        ne = NewtonEuler(["AB", "A", "B"], about={"A": P["A"], "B": P["B"]}, mp=True)
        ne.pin("pA", P["A"], "AB", "A")
        ne.pin("pB", P["B"], "AB", "B")
        ne.along("NA", P["A"], (0, 1), "A", "frame")
        ne.along("NB", P["B"], (1, 0), "B", "frame")
        ne.along("F", P["A"], (1, 0), "A", "frame")
        ne.known("AB", (-4 * a["G"][0], -4 * a["G"][1] - 4 * G), P["G"], -4 * 0.15**2 * a["phi"])
        ne.known("AB", (30, -100), P["C"])
        ne.known("A", (-2 * a["A"][0], -2 * G), P["A"])
        ne.known("B", (-3 * a["B"][0], -3 * a["B"][1] - 3 * G), P["B"])
        x = {k: float(v) for k, v in ne.solve().items()}
        # the held force by the potential energy: F ds = dU - the load's work
        dU = 4 * G * d["G"][1] + 3 * G * d["B"][1] - (30 * d["C"][0] - 100 * d["C"][1])
        x["F_energy"] = float(dU)
        return x


@pytest.mark.parametrize("s", [0.3, -0.2, 0.45])
@pytest.mark.parametrize("acc", [0.0, -2.0, 3.5])
def test_a_driving_block_at_rest(s, acc):
    extra = "" if not acc else f'as_A = "{abs(acc)} m/s^2 {"right" if acc > 0 else "left"}"'
    text = TRAMMEL.replace("S", str(s * 1000)).replace("ACC", extra)
    sol = solve(parse_scene(text))
    f = sol.forces
    ref = trammel_reference(s, acc)
    size = max(abs(v) for v in ref.values())
    assert sol.scene.at_rest and sol.scene.start_alpha == acc
    assert f.driver != "crank"
    assert f.input_torque == pytest.approx(ref["F"], abs=1e-9 * size)
    if not acc:
        assert ref["F_energy"] == pytest.approx(ref["F"], abs=1e-12 * size)
    normals = {g.point: g.normal for g in f.guides}
    assert abs(normals["A"]) == pytest.approx(abs(ref["NA"]), abs=1e-9 * size)
    assert abs(normals["B"]) == pytest.approx(abs(ref["NB"]), abs=1e-9 * size)
    for p in f.pins:
        want = ref["pA.x"], ref["pA.y"]
        if p.point == "B":
            want = ref["pB.x"], ref["pB.y"]
        sign = 1.0 if p.on == "AB" else -1.0
        assert sign * p.force[0] == pytest.approx(want[0], abs=1e-9 * size), p.point
        assert sign * p.force[1] == pytest.approx(want[1], abs=1e-9 * size), p.point


R, LROD = mpmath.mpf("0.3"), mpmath.mpf("1.2")


def _wheel(psi):
    """The wheel's angle ``psi`` (rad, ccw; 135 deg now): rolling on y = 0, its centre moves
    -R per radian ccw."""
    C = (-R * (psi - mpmath.radians(135)), R)
    A = (C[0] + R * mpmath.cos(psi), C[1] + R * mpmath.sin(psi))
    B = (A[0] + mpmath.sqrt(LROD**2 - A[1] ** 2), mpmath.mpf(0))
    return {
        "C": C,
        "A": A,
        "B": B,
        "I": (C[0], mpmath.mpf(0)),
        "G": ((A[0] + B[0]) / 2, (A[1] + B[1]) / 2),
        "phi": mpmath.atan2(B[1] - A[1], B[0] - A[0]),
    }


def wheel_reference(alpha):
    with mpmath.workdps(30):
        psi = mpmath.radians(135)
        P, d = _wheel(psi), _d(_wheel, psi)
        a = {
            k: (alpha * v[0], alpha * v[1]) if isinstance(v, tuple) else alpha * v
            for k, v in d.items()
        }
        ne = NewtonEuler(["CA", "AB", "B"], about={"B": P["B"]}, mp=True)
        ne.pin("I", P["I"], "CA", "frame")
        ne.couple("tau", "CA", "frame")
        ne.pin("pA", P["A"], "AB", "CA")
        ne.pin("pB", P["B"], "AB", "B")
        ne.along("NB", P["B"], (0, 1), "B", "frame")
        ne.known("CA", (-20 * a["C"][0], -20 * a["C"][1] - 20 * G), P["C"], -20 * 0.2**2 * alpha)
        ne.known("AB", (-8 * a["G"][0], -8 * a["G"][1] - 8 * G), P["G"], -8 * 0.35**2 * a["phi"])
        ne.known("B", (-5 * a["B"][0] - 200, -5 * G), P["B"])
        x = {k: float(v) for k, v in ne.solve().items()}
        dU = 8 * G * d["G"][1] - (-200 * d["B"][0])  # (the wheel's centre keeps its height)
        x["tau_energy"] = float(dU)
        return x


@pytest.mark.parametrize("alpha", [0.0, 2.0, -1.5])
def test_a_driving_wheel_at_rest(alpha):
    extra = "" if not alpha else f'alpha_CA = "{abs(alpha)} rad/s^2 {"ccw" if alpha > 0 else "cw"}"'
    sol = solve(parse_scene(WHEEL.replace("ACC", extra)))
    f = sol.forces
    ref = wheel_reference(alpha)
    size = max(abs(v) for v in ref.values())
    assert f.input_torque == pytest.approx(ref["tau"], abs=1e-9 * size)
    if not alpha:
        assert ref["tau_energy"] == pytest.approx(ref["tau"], abs=1e-12 * size)
    (c,) = f.contacts
    assert c.force[0] == pytest.approx(ref["I.x"], abs=1e-9 * size)
    assert c.force[1] == pytest.approx(ref["I.y"], abs=1e-9 * size)


def test_the_views_say_a_block_is_held(tmp_path, capsys):
    scene = tmp_path / "held.toml"
    scene.write_text(TRAMMEL.replace("S", "300").replace("ACC", ""))
    assert main(["solve", str(scene)]) == 0
    out = capsys.readouterr().out
    assert (
        "(at rest: nothing moves yet; the velocities and accelerations below are per 1 m/s" in out
    )
    assert "(at rest: the weights and loads, no inertia)" in out
    assert main(["solve", "--json", str(scene)]) == 0
    assert '"at_rest": true' in capsys.readouterr().out


def test_a_zero_speed_without_masses_is_refused(tmp_path, capsys):
    scene = tmp_path / "bare.toml"
    scene.write_text(TRAMMEL.replace("S", "300").replace("ACC", "").split("[masses]")[0])
    assert main(["solve", str(scene)]) == 2
    err = capsys.readouterr().err.strip()
    assert "vs_A is zero: nothing moves" in err and "[masses]" in err
    assert len(err.splitlines()) == 1


@pytest.mark.parametrize("acc", [0.0, 2.0])
def test_a_block_at_rest_is_not_said_to_move(tmp_path, capsys, acc):
    """At rest the block does not move "at a steady speed", its polygons are per 1 m/s (not
    per rad/s), and no view says it moves at 1 m/s."""
    from polygon_method.scene import load_scene
    from polygon_method.text.words import given

    scene = tmp_path / "held.toml"
    extra = f'as_A = "{acc} m/s^2 right"' if acc else ""
    text = TRAMMEL.replace("S", "300").replace("ACC", extra)
    scene.write_text(text + "[friction]\nguides = 0.1\n")
    assert main(["steps", str(scene)]) == 0
    steps = " ".join(capsys.readouterr().out.split())
    assert main(["solve", str(scene)]) == 0
    out = " ".join(capsys.readouterr().out.split())
    page = " ".join(given(load_scene(scene)))
    for text in (steps, out, page):
        assert "steady speed" not in text and "steadily" not in text
        assert "per rad/s" not in text and "rad/s of the crank" not in text
        assert "moving at 1 m/s" not in text
    assert "as_A = 0 in the polygons per 1 m/s (at rest: nothing moves yet;" in steps
    assert "friction power per 1 m/s of the block" in steps
    assert "about to move to the right (at rest: nothing moves yet;" in out
    assert "at rest, about to move to the right" in page
    if acc:
        assert "velocity diagram per 1 m/s of the block (section 2's virtual" in steps
        assert "the start's as_A is taken in section 6" in steps


def test_a_wheel_at_rest_is_not_said_to_roll_steadily(tmp_path, capsys):
    scene = tmp_path / "wheel.toml"
    scene.write_text(WHEEL.replace("ACC", ""))
    assert main(["steps", str(scene)]) == 0
    steps = " ".join(capsys.readouterr().out.split())
    assert main(["solve", str(scene)]) == 0
    out = " ".join(capsys.readouterr().out.split())
    for text in (steps, out):
        assert "steady speed" not in text and "steadily" not in text
    assert "alpha_CA = 0 in the polygons per 1 rad/s (at rest" in steps
    assert "about to turn ccw" in out
    assert main(["sweep", str(scene), "--summary"]) == 0
    head = capsys.readouterr().out.splitlines()[1]
    assert "at rest, the motion per 1 rad/s of the wheel" in head and "m/s to the" not in head
