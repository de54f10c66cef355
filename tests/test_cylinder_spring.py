"""A spring in a passive cylinder (``[loads] "C-R" = { stiffness, free_length }``): its
force ``k (L0 - L)`` from the cylinder's length at the instant, compressed pushing its ends
apart, stretched pulling them together, alone or with a push and a damper.

The references are independent of the tool (``tests/test_cylinder_force.py``'s four-bar
with the cylinder on its rocker, its positions in closed form at 30 digits): the matrix
Newton-Euler solve and the virtual power ``T omega + F vs + ... = 0`` at four crank angles,
one compressed and three stretched; over a full turn with the loads alone the spring is
conservative: the crank's work ``integral T dtheta`` is nought, and at each angle ``T omega
= d/dt (k (L - L0)^2 / 2)`` (the crank's power is what the spring stores: ``-F vs``), its
rate taken by finite differences of the sweep's length.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from polygon_method.cli import main
from polygon_method.motion.sweeps import sweep
from polygon_method.motion.solution import solve
from polygon_method.scene import parse_scene

from test_cylinder_force import OMEGA, _pin, reference, scene_text

K, L0 = 2000.0, 0.31  # 2 N/mm, 310 mm: compressed near 30 deg, stretched elsewhere
SPRINGS = {  # the scene's words -> (push N, damping N s/m)
    '{ stiffness = "2 N/mm", free_length = 310 }': (0.0, 0.0),
    '{ stiffness = "2 kN/m", free_length = "0.31 m", damping = "400 N s/m" }': (0.0, 400.0),
    '{ push = "50 N", stiffness = 2000, free_length = "31 cm" }': (50.0, 0.0),
}


@pytest.mark.parametrize("load", sorted(SPRINGS))
@pytest.mark.parametrize("angle", [30.0, 135.0, 250.0, 320.0])
def test_against_the_matrix_method_and_the_virtual_power(load, angle):
    push, damping = SPRINGS[load]
    sol = solve(parse_scene(scene_text(load, angle)))
    ref = reference(angle, push, damping, spring=(K, L0))
    assert (ref["L"] < L0) == (angle == 30.0)  # one compressed, the others stretched
    size = max(abs(v) for v in ref.values() if isinstance(v, float))
    f = sol.forces
    assert ref["T_power"] == pytest.approx(ref["T"], abs=1e-12 * size)
    assert f.input_torque == pytest.approx(ref["T"], abs=1e-9 * size)
    for pin, on, by in (("O", "OA", "frame"), ("A", "AB", "OA"), ("B", "AB", "QB")):
        got = _pin(f, pin, on, by)
        assert got == pytest.approx((ref[pin + ".x"], ref[pin + ".y"]), abs=1e-9 * size), pin
    F, u = ref["F"], ref["u"]
    assert _pin(f, "R", "QB", "C-R") == pytest.approx((F * u[0], F * u[1]), abs=1e-9 * size)
    d = sol.to_dict()["forces"]["cylinders"]["C-R"]
    assert d["force"] == pytest.approx(F, abs=1e-9 * size)
    assert d["length"] == pytest.approx(ref["L"], rel=1e-12)
    assert d["spring"] == pytest.approx(K * (L0 - ref["L"]), rel=1e-9)
    assert (d["stiffness"], d["free_length"]) == pytest.approx((K, L0), rel=1e-15)


@pytest.mark.parametrize("angle", [30.0, 250.0])
def test_the_loads_alone_the_virtual_power(angle):
    """An empty [masses]: ``T omega + F vs = 0``, F the spring's, and the power balance."""
    load = '{ stiffness = "2 N/mm", free_length = 310 }'
    sol = solve(parse_scene(scene_text(load, angle, masses="[masses]")))
    ref = reference(angle, 0.0, 0.0, massive=False, spring=(K, L0))
    want = -K * (L0 - ref["L"]) * ref["vs"] / OMEGA
    assert ref["T"] == pytest.approx(want, rel=1e-12)
    assert sol.forces.input_torque == pytest.approx(want, rel=1e-9)
    assert sol.input_torque == pytest.approx(want, rel=1e-9)


def test_at_rest_the_spring_still_pushes():
    load = '{ stiffness = "2 N/mm", free_length = 310, damping = "3000 N s/m" }'
    sol = solve(parse_scene(scene_text(load, 30.0, speed="0")))
    ref = reference(30.0, 0.0, 3000.0, rest=True, spring=(K, L0))
    assert ref["F"] == pytest.approx(K * (L0 - ref["L"]), rel=1e-15) and ref["F"] > 0
    size = max(abs(v) for v in ref.values() if isinstance(v, float))
    assert sol.forces.input_torque == pytest.approx(ref["T"], abs=1e-9 * size)
    assert sol.to_dict()["forces"]["cylinders"]["C-R"]["force"] == pytest.approx(ref["F"])


def test_over_a_turn_the_spring_is_conservative():
    """The loads alone over a full turn: the crank's torque does no net work (Simpson's rule
    on 720 steps), and at each angle ``T omega = d/dt (k (L - L0)^2 / 2)``, the rate of the
    sweep's own length column by central differences."""
    load = '{ stiffness = "2 N/mm", free_length = 310 }'
    sc = parse_scene(scene_text(load, masses="[masses]"))
    n = 720
    th = np.linspace(0.0, 2 * math.pi, n + 1)
    res = sweep(sc, th)
    cols = {name: np.asarray(a, dtype=float) for name, _, a in res.force_columns()}
    T = cols["torque_inertia"]
    h = th[1] - th[0]
    work = h / 3 * (T[0] + T[-1] + 4 * T[1:-1:2].sum() + 2 * T[2:-1:2].sum())
    scale = h * np.abs(T).sum()  # the work of |T|: what a slip would show against
    assert scale > 1.0 and abs(work) < 1e-9 * scale
    F = cols["F_C-R"]
    L = np.hypot(*(np.asarray(res.P["R"][i]) - np.asarray(res.P["C"][i]) for i in (0, 1)))
    assert F == pytest.approx(K * (L0 - L), rel=1e-12, abs=1e-9)
    assert (L < L0).any() and (L > L0).any()  # compressed and stretched within the turn
    U = 0.5 * K * (L - L0) ** 2
    dU = (U[2:] - U[:-2]) / (2 * h) * OMEGA  # dU/dt, second order in h
    err = np.abs(T[1:-1] * OMEGA - dU).max()  # the crank's power stores the spring's energy
    assert err < 1e-3 * np.abs(dU).max()  # the difference's h^2 error, far below a slip


def test_every_view_says_it(tmp_path, capsys):
    scene = tmp_path / "spring.toml"
    scene.write_text(scene_text('{ stiffness = "2 N/mm", free_length = 310 }', 250.0))
    ref = reference(250.0, 0.0, 0.0, spring=(K, L0))
    assert main(["solve", str(scene)]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "a spring of 2 N/mm, free length 310 mm" in out
    assert "F = 2000 x (L0 - L) = 2000 x (0.31 - " in out
    assert "pulling its ends together" in out and "a spring stretched pulls" in out
    assert f"{ref['F']:.4g}" in out
    assert main(["steps", str(scene)]) == 0
    steps = " ".join(capsys.readouterr().out.split())
    assert "a spring of 2 N/mm" in steps and "cylinder C-R: F vs_CR" in steps
    csv = tmp_path / "s.csv"
    assert main(["sweep", str(scene), "--csv", str(csv)]) == 0
    assert "F_C-R [N]" in csv.read_text().splitlines()[0]
    capsys.readouterr()
    assert main(["sweep", str(scene), "--summary"]) == 0
    assert "force in the cylinder, + pushing apart" in capsys.readouterr().out
    assert main(["draw", "--forces", str(scene), "-o", str(tmp_path / "f.pdf")]) == 0
    assert "free body" in capsys.readouterr().out


def test_a_spring_on_the_driving_cylinder_is_refused(tmp_path, capsys):
    text = scene_text('{ stiffness = "2 N/mm", free_length = 310 }').replace(
        'speed = "60 rpm ccw"', 'vs_CR = "0.1 m/s"'
    )
    scene = tmp_path / "driving.toml"
    scene.write_text(text)
    assert main(["solve", str(scene)]) == 2
    err = capsys.readouterr().err.strip()
    assert "the cylinder C-R drives" in err and len(err.splitlines()) == 1


def test_the_stiffness_units(tmp_path, capsys):
    """N/mm, kN/m and lbf/in read; a damping's unit, an absurd and a tiny one refused."""
    for raw, si in (('"2 N/mm"', 2000.0), ('"2 kN/m"', 2000.0), ('"10 lbf/in"', 1751.268)):
        sc = parse_scene(scene_text(f"{{ stiffness = {raw}, free_length = 310 }}"))
        (c,) = [c for c in sc.cylinders if c.key == "C-R"]
        assert c.stiffness == pytest.approx(si, rel=1e-6)
    for raw, words in (('"2 N s/m"', "stiffness"), ('"1e13 N/m"', "absurd"), ('"1e-9 N/m"', "")):
        scene = tmp_path / "units.toml"
        scene.write_text(scene_text(f"{{ stiffness = {raw}, free_length = 310 }}"))
        assert main(["solve", str(scene)]) == 2
        err = capsys.readouterr().err.strip()
        assert words in err and len(err.splitlines()) == 1 and "C-R" in err, err


def test_the_worked_problem_and_its_answers():
    from pathlib import Path

    from polygon_method.check import check_answers
    from polygon_method.scene import load_scene

    path = Path(__file__).resolve().parent.parent / "worked_problems"
    sol = solve(load_scene(path / "cylinder_spring_damper_on_rocker.toml"))
    ref = reference(60.0, 0.0, 400.0, spring=(K, 0.25))
    assert ref["L"] > 0.25  # stretched: the spring pulls
    size = max(abs(v) for v in ref.values() if isinstance(v, float))
    assert sol.forces.input_torque == pytest.approx(ref["T"], abs=1e-9 * size)
    rows = check_answers(sol)
    assert len(rows) == 7 and all(r.ok for r in rows), rows
    assert abs(rows[1].given - ref["T"]) < 0.0005 * abs(ref["T"])  # the file's 4 figures
    assert abs(rows[6].given - abs(ref["F"])) < 0.0005 * abs(ref["F"])


@pytest.mark.parametrize(
    "slip, spring",
    [("spring_sense_turned", (-K, L0)), ("free_length_left_out", (K, 0.0))],
)
def test_check_names_the_springs_slips(slip, spring):
    """The torque a slip gives, worked by the matrix method with the slip's force (``k (L -
    L0)``, or ``-k L``), is named by ``check``; the right one is right."""
    from polygon_method.check import check_answers

    load = '{ stiffness = "2 N/mm", free_length = 310 }'
    for spr, ok in ((spring, False), ((K, L0), True)):
        ref = reference(250.0, 0.0, 0.0, spring=spr)
        way = "ccw" if ref["T"] > 0 else "cw"
        text = scene_text(load, 250.0) + f'[answers]\ntorque = "{abs(ref["T"]):.5g} N m {way}"\n'
        (row,) = check_answers(solve(parse_scene(text)))
        assert row.ok == ok and (ok or row.mistake == slip), row


@pytest.mark.parametrize("angle", [30.0, 250.0])
def test_the_bounds_hold_with_a_spring(angle):
    """Each force's stated error bound (a spring's force erring by k times its length's
    bound) holds against the 30-digit matrix method."""
    from polygon_method.forces.bounds import force_bounds

    load = '{ stiffness = "2 N/mm", free_length = 310, damping = "400 N s/m" }'
    sol = solve(parse_scene(scene_text(load, angle)))
    ref = reference(angle, 0.0, 400.0, spring=(K, L0))
    f, b = sol.forces, force_bounds(sol)
    assert 0 < b.effort < 1e-9
    assert abs(f.input_torque - ref["T"]) <= b.effort * b.force * b.length
    ref["R.x"], ref["R.y"] = ref["F"] * ref["u"][0], ref["F"] * ref["u"][1]  # F u on QB
    for pin, on, by in (("O", "OA", "frame"), ("B", "AB", "QB"), ("R", "QB", "C-R")):
        got = _pin(f, pin, on, by)
        err = math.hypot(got[0] - ref[pin + ".x"], got[1] - ref[pin + ".y"])
        (e,) = [v for (p, o, y), v in b.pins.items() if p == pin and {o, y} == {on, by}]
        assert err <= e * b.force, pin
