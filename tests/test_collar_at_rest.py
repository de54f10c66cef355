"""A driving collar at rest (``vs_C = 0``): the force its driver (a screw, a ram between the
rod and the collar) needs along the turning rod to hold the mechanism where it stands; with
``as_C`` too, the force to start it from rest (every acceleration its tangential terms
alone: the start's acceleration times the motion per m/s of the collar's sliding).

The reference is independent of the tool: the positions in closed form at 30 digits (the
collar C where the circle of radius s about the rod's pivot O meets the circle of DC about
D), their derivatives with respect to s by mpmath's differentiation, and the rod's, the
collar's and DC's Newton-Euler equations as one linear system (``tests/newton_euler.py``):
the driver's force, the normal force between the rod and the collar and every pin force to
1e-9; the holding force also the derivative of the potential energy (with the load's work)
with respect to s (virtual work).
"""

from __future__ import annotations

import mpmath
import numpy as np
import pytest

from polygon_method.check import check_answers
from polygon_method.cli import main
from polygon_method.motion.solution import solve
from polygon_method.motion.sweeps import sweep
from polygon_method.scene import parse_scene

from newton_euler import NewtonEuler

G = 9.81

COLLAR = """
title = "a collar held on its turning rod"
units = "m"
[ground]
O = [0, 0]
D = [0.4, 0]
[links]
OA = 0.8
DC = 0.25
[sliders]
C = { along = "O-A" }
[assembly]
C = "above"
[masses]
OA = { mass = "3 kg", along = 0.4, from = "O", gyration = 0.23 }
DC = { mass = "1.2 kg", along = 0.125, from = "D", gyration = 0.07 }
C = { mass = "0.5 kg" }
[gravity]
[loads]
A = { force = [20, -150] }
[input]
block = "C"
s_C = S
vs_C = 0
ACC
"""


def scene_text(s, acc=0.0):
    extra = "" if not acc else f'as_C = "{abs(acc)} m/s^2 {"outward" if acc > 0 else "towards O"}"'
    return COLLAR.replace("S", str(s)).replace("ACC", extra)


def _place(s):
    """The points and angles at OC = s (the collar above OD)."""
    d, r = mpmath.mpf("0.4"), mpmath.mpf("0.25")
    cx = (s**2 - r**2 + d**2) / (2 * d)
    C = (cx, mpmath.sqrt(s**2 - cx**2))
    phi = mpmath.atan2(C[1], C[0])
    psi = mpmath.atan2(C[1], C[0] - d)
    A = (mpmath.mpf("0.8") * mpmath.cos(phi), mpmath.mpf("0.8") * mpmath.sin(phi))
    G1 = (mpmath.mpf("0.4") * mpmath.cos(phi), mpmath.mpf("0.4") * mpmath.sin(phi))
    G2 = (d + mpmath.mpf("0.125") * mpmath.cos(psi), mpmath.mpf("0.125") * mpmath.sin(psi))
    return {"C": C, "A": A, "G1": G1, "G2": G2, "phi": phi, "psi": psi}


def _d(fn, x):
    out = {}
    for k, v in fn(x).items():
        if isinstance(v, tuple):
            out[k] = tuple(mpmath.diff(lambda t, k=k, i=i: fn(t)[k][i], x) for i in (0, 1))
        else:
            out[k] = mpmath.diff(lambda t, k=k: fn(t)[k], x)
    return out


def reference(s, acc):
    """The driver's force on the collar along the rod (+ outward), the normal force on the
    collar by the rod (along the rod's direction turned 90 deg ccw), the pins, at OC = ``s``
    and the start's sliding acceleration ``acc`` (m/s^2, + outward; 0: held)."""
    with mpmath.workdps(30):
        s = mpmath.mpf(s)
        P, d = _place(s), _d(_place, s)
        a = {k: (acc * v[0], acc * v[1]) if isinstance(v, tuple) else acc * v for k, v in d.items()}
        w = (mpmath.cos(P["phi"]), mpmath.sin(P["phi"]))
        n = (-w[1], w[0])
        ne = NewtonEuler(["OA", "C", "DC"], about={"C": P["C"]}, mp=True)
        ne.pin("O", (0, 0), "OA", "frame")
        ne.pin("D", (mpmath.mpf("0.4"), 0), "DC", "frame")
        ne.pin("pC", P["C"], "DC", "C")
        ne.along("N", P["C"], n, "C", "OA")
        ne.along("F", P["C"], w, "C", "OA")
        m1, m2, m3 = 3, mpmath.mpf("1.2"), mpmath.mpf("0.5")
        i1, i2 = m1 * mpmath.mpf("0.23") ** 2, m2 * mpmath.mpf("0.07") ** 2
        ne.known("OA", (-m1 * a["G1"][0], -m1 * a["G1"][1] - m1 * G), P["G1"], -i1 * a["phi"])
        ne.known("OA", (20, -150), P["A"])
        ne.known("DC", (-m2 * a["G2"][0], -m2 * a["G2"][1] - m2 * G), P["G2"], -i2 * a["psi"])
        ne.known("C", (-m3 * a["C"][0], -m3 * a["C"][1] - m3 * G), P["C"])
        x = {k: float(v) for k, v in ne.solve().items()}
        # held: F ds + the weights' and the load's work = 0 (virtual work)
        dU = G * (m1 * d["G1"][1] + m2 * d["G2"][1] + m3 * d["C"][1])
        x["F_energy"] = float(dU - (20 * d["A"][0] - 150 * d["A"][1]))
        return x


def _pin(f, point, on):
    (p,) = [p for p in f.pins if p.point == point and (p.on == on or p.by == on)]
    return p.force if p.on == on else (-p.force[0], -p.force[1])


@pytest.mark.parametrize("s", [0.3, 0.45, 0.6])
@pytest.mark.parametrize("acc", [0.0, 2.0, -3.5])
def test_a_driving_collar_at_rest_against_the_matrix_method(s, acc):
    sol = solve(parse_scene(scene_text(s, acc)))
    f = sol.forces
    ref = reference(s, acc)
    size = max(abs(v) for v in ref.values())
    assert sol.scene.at_rest and sol.scene.start_alpha == acc
    assert f.input_torque == pytest.approx(ref["F"], abs=1e-9 * size)
    if not acc:
        assert ref["F_energy"] == pytest.approx(ref["F"], abs=1e-12 * size)
        assert all(i.force == (0.0, 0.0) and i.couple == 0.0 for i in f.inertia)
    (g,) = f.guides
    assert g.normal == pytest.approx(ref["N"], abs=1e-9 * size)
    for point, on, key in (("O", "OA", "O"), ("D", "DC", "D"), ("C", "DC", "pC")):
        got = _pin(f, point, on)
        assert got[0] == pytest.approx(ref[key + ".x"], abs=1e-9 * size), point
        assert got[1] == pytest.approx(ref[key + ".y"], abs=1e-9 * size), point


@pytest.mark.parametrize("acc", [0.0, -2.0])
def test_the_sweep_holds_or_starts_it_at_every_place(acc):
    sc = parse_scene(scene_text(0.45, acc))
    places = np.array([0.2, 0.35, 0.5, 0.62])
    res = sweep(sc, places)
    cols = {n: np.asarray(a, dtype=float) for n, _, a in res.force_columns()}
    for s, F in zip(places, cols["force_inertia"]):
        ref = reference(float(s), acc)
        assert F == pytest.approx(ref["F"], abs=1e-9 * max(abs(v) for v in ref.values()))


def test_the_views_say_it(tmp_path, capsys):
    scene = tmp_path / "held.toml"
    scene.write_text(scene_text(0.45))
    assert main(["solve", str(scene)]) == 0
    out = capsys.readouterr().out
    assert (
        "(at rest: nothing moves yet; the velocities and accelerations below are per 1 m/s "
        "of the collar C along its rod" in out
    )
    assert "input force on collar C along OA (at rest: the weights and loads, no inertia)" in out
    assert main(["solve", "--json", str(scene)]) == 0
    assert '"at_rest": true' in capsys.readouterr().out
    assert main(["steps", str(scene)]) == 0
    steps = " ".join(capsys.readouterr().out.split())
    assert "6. Weights at rest (no inertia)" in steps
    assert (
        "at rest (nothing moves yet): the polygons are drawn per 1 m/s of the collar C along "
        "its rod, the virtual velocities of the power balance (no inertia)" in steps
    )
    assert "vs_C = 1 m/s outward along OA, relative to the rod (virtual: at rest)" in steps
    assert main(["sweep", str(scene), "--summary"]) == 0
    summary = capsys.readouterr().out
    assert (
        "collar C on the rod OA at rest, the motion per 1 m/s outward (virtual); the forces "
        "that hold it at every place" in summary
    )
    start = tmp_path / "start.toml"
    start.write_text(scene_text(0.45, -2.0))
    assert main(["solve", str(start)]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "starting from rest with as_C = 2 m/s^2 inward along its rod OA" in out
    assert main(["sweep", str(start), "--summary"]) == 0
    assert "the forces of a start from rest with 2 m/s^2 towards O" in capsys.readouterr().out
    assert main(["draw", "--forces", str(scene), "-o", str(tmp_path / "f.pdf")]) == 0
    assert (tmp_path / "f.pdf").stat().st_size > 1000


def test_the_check_takes_the_holding_force():
    ref = reference(0.45, 0.0)
    text = scene_text(0.45) + f'[answers]\nforce = "{abs(ref["F"]):.5g} N"\n'
    rows = check_answers(solve(parse_scene(text)))
    assert [r.ok for r in rows] == [True], rows
    wrong = text.replace(f"{abs(ref['F']):.5g}", f"{1.2 * abs(ref['F']):.5g}")
    assert [r.ok for r in check_answers(solve(parse_scene(wrong)))] == [False]


def test_a_zero_speed_without_masses_is_refused(tmp_path, capsys):
    scene = tmp_path / "bare.toml"
    scene.write_text(
        scene_text(0.45).split("[masses]")[0] + "[input]\nblock = 'C'\ns_C = 0.45\nvs_C = 0\n"
    )
    assert main(["solve", str(scene)]) == 2
    err = capsys.readouterr().err.strip()
    assert "vs_C is zero: nothing moves" in err and "[masses]" in err
    assert len(err.splitlines()) == 1
