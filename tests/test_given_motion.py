"""The input's motion given on another quantity than the crank's speed ([input] vs_B,
omega_BC, v_C with their rates), against the 50-digit reference.

The reference finds the crank's speed on its own: it solves the mechanism at the crank's
angle with the crank turning at 1 rad/s (mpmath, 50 digits), reads the given quantity per
rad/s, and solves again at the crank's omega and alpha that give it. It shares nothing with
``polygon_method.solver.given`` but the scene's data.
"""

import dataclasses
import math
import subprocess
import sys

import pytest
from mpmath import mpf

from polygon_method import SingularStepError, solve
from polygon_method.cli import main
from polygon_method.scene import parse_scene
from reference import reference_solution
from scenes import seed

REL = 1e-9

SLIDER = """
[ground]
O = [0, 0]
[links]
OA = 150
AB = 600
[sliders]
B = {{ path = "horizontal", through = [0, {e}] }}
[input]
crank = "OA"
angle = {angle}
{given}
"""

FOURBAR = seed(
    middle='[points]\nF = {{ on = "BC", distances = {{ B = 45, C = 30 }}, turn = "cw" }}\n',
    drive="angle = {angle}\n{given}",
)

SLOTTED = """
[ground]
O2 = [0, 150]
O4 = [0, 0]
[links]
"O2-A" = 50
"O4-P" = 300
"P-Q" = 120
[sliders]
A = {{ along = "O4-P" }}
Q = {{ path = "horizontal", through = [0, 280] }}
[input]
crank = "O2-A"
angle = {angle}
{given}
"""


def _ref_quantity(scene, ref, kind, names, direction=None):
    """(value, rate) of the given quantity in a reference solution (mpf)."""
    if kind == "omega":
        key = scene.link("-".join(names)).key
        return ref["omega"][key], ref["alpha"][key]
    if kind == "vs":
        s = ref["sliders"][names[0]]
        return s["vs"], s["as"]
    v, a = ref["velocities"][names[0]], ref["accelerations"][names[0]]
    return v[0] * direction[0] + v[1] * direction[1], a[0] * direction[0] + a[1] * direction[1]


def reference_given(scene, sol, kind, names, value, rate, direction=None, crank_alpha=None):
    """The 50-digit solution for the crank's speed that gives ``value`` and ``rate`` (0:
    the given motion steady), or with the crank's own ``crank_alpha``."""
    guess = dict(sol.P)
    unit = dataclasses.replace(
        scene, input=dataclasses.replace(scene.input, omega=1.0, alpha=0.0, given=None)
    )
    r1 = reference_solution(unit, guess)
    y1, h = _ref_quantity(scene, r1, kind, names, direction)
    w = mpf(value) / y1
    if crank_alpha is not None:
        al = mpf(crank_alpha)
    else:
        al = (mpf(rate or 0) - w * w * h) / y1
    full = dataclasses.replace(
        unit, input=dataclasses.replace(unit.input, omega=float(w), alpha=float(al))
    )
    # the float omega and alpha above only carry the reference's to the solver's scene: the
    # reference is solved at its own mpf values below by scaling (velocities linear in w)
    ref = reference_solution(full, guess)
    scale_v = w / mpf(full.input.omega)
    return w, al, ref, scale_v


def _compare(scene, sol, ref, w, al):
    assert abs(sol.scene.input.omega - w) <= REL * abs(w)
    assert abs(sol.scene.input.alpha - al) <= REL * (abs(al) + w * w)
    vs = max(math.hypot(*v) for v in sol.V.values())
    acc = max(math.hypot(*a) for a in sol.A.values())
    bounds = sol.error_bounds
    for p in scene.point_names:
        for got, want, size, b, sz in (
            (sol.V[p], ref["velocities"][p], vs, bounds.V[p], bounds.scales["velocity"]),
            (sol.A[p], ref["accelerations"][p], acc, bounds.A[p], bounds.scales["acceleration"]),
        ):
            err = float(math.hypot(got[0] - want[0], got[1] - want[1]))
            assert err <= REL * size, (p, got, want)
            assert err <= b * sz + 1e-300, (p, "the error bound does not hold", err, b * sz)
    for lk in scene.links:
        assert abs(sol.W[lk.key] - ref["omega"][lk.key]) <= REL * max(abs(w), 1)
        assert abs(sol.Al[lk.key] - ref["alpha"][lk.key]) <= REL * (abs(al) + w * w)


SLIDER_CASES = [
    (e, a, g)
    for e in (0, 40)
    for a in (30, 100, 200, 315)
    for g in (
        'vs_B = "5 m/s left"\nas_B = "-20 m/s^2"',
        'vs_B = "-2.5 m/s"',
        'vs_B = "3 m/s right"\nacceleration = 0',
    )
]


@pytest.mark.parametrize("e, angle, given", SLIDER_CASES)
def test_piston_given(e, angle, given):
    scene = parse_scene(SLIDER.format(e=e, angle=angle, given=given))
    sol = solve(scene)
    g = scene.input.given
    w, al, ref, _ = reference_given(
        scene,
        sol,
        "vs",
        ("B",),
        g.value,
        g.rate,
        crank_alpha=scene.input.alpha if "acceleration" in given else None,
    )
    _compare(scene, sol, ref, w, al)
    assert abs(sol.sliding_velocity("B") - g.value) <= REL * abs(g.value)
    if "acceleration" not in given:  # the given motion's rate, or 0: steady
        assert abs(sol.sliding_acceleration("B") - (g.rate or 0.0)) <= REL * (
            max(math.hypot(*a) for a in sol.A.values())
        )


@pytest.mark.parametrize("angle", (60, 100, 290))
def test_coupler_given(angle):
    scene = parse_scene(
        FOURBAR.format(angle=angle, given='omega_BC = "3 rad/s cw"\nalpha_BC = "12 rad/s^2 ccw"')
    )
    sol = solve(scene)
    w, al, ref, _ = reference_given(scene, sol, "omega", ("B", "C"), -3.0, 12.0)
    _compare(scene, sol, ref, w, al)
    assert abs(sol.omega("BC") + 3.0) <= REL * 3 and abs(sol.alpha("BC") - 12.0) <= REL * 12


@pytest.mark.parametrize("angle", (40, 80))
def test_point_velocity_given(angle):
    """v_F = 0.8 m/s in the direction the reference finds F moving (written to 17 digits
    as an angle), speeding up at 3 m/s^2."""
    probe = parse_scene(FOURBAR.format(angle=angle, given='speed = "1 rad/s ccw"'))
    ref1 = reference_solution(probe, dict(solve(probe).P))
    vx, vy = (float(c) for c in ref1["velocities"]["F"])
    heading = math.degrees(math.atan2(-vy, -vx))  # the opposite of its motion at ccw
    scene = parse_scene(
        FOURBAR.format(angle=angle, given=f'v_F = "0.8 m/s at {heading!r} deg"\na_F = "3 m/s^2"')
    )
    sol = solve(scene)
    d = (math.cos(math.radians(heading)), math.sin(math.radians(heading)))
    w, al, ref, _ = reference_given(scene, sol, "v", ("F",), 0.8, 3.0, d)
    assert w < 0  # F moves the other way when the crank turns cw
    _compare(scene, sol, ref, w, al)
    assert abs(sol.speed("F") - 0.8) <= REL


@pytest.mark.parametrize("angle", (20, 110))
def test_slotted_lever_given(angle):
    scene = parse_scene(SLOTTED.format(angle=angle, given='vs_Q = "0.4 m/s right"'))
    sol = solve(scene)
    w, al, ref, _ = reference_given(scene, sol, "vs", ("Q",), 0.4, None)
    _compare(scene, sol, ref, w, al)


def test_dead_centre_refused_with_condition():
    scene = parse_scene(SLIDER.format(e=0, angle=0, given='vs_B = "5 m/s"'))
    with pytest.raises(SingularStepError) as exc:
        solve(scene)
    assert "dead centre" in exc.value.message and "condition" in exc.value.message


def test_near_dead_centre_warns_and_bound_holds():
    scene = parse_scene(SLIDER.format(e=0, angle=3, given='vs_B = "5 m/s"\nas_B = 0'))
    sol = solve(scene)
    assert any("dead centre" in w for w in sol.warnings)
    g = scene.input.given
    w, al, ref, _ = reference_given(scene, sol, "vs", ("B",), g.value, g.rate)
    _compare(scene, sol, ref, w, al)


BAD = [
    ('vs_B = "5 m/s"\nspeed = "10 rad/s cw"', "both the crank's speed"),
    ('vs_B = "5 m/s"\nomega_AB = "1 rad/s cw"', "gives the motion twice"),
    ('vs_B = "5 m/s"\nalpha_AB = "1 rad/s^2 cw"', "does not go with"),
    ('v_A = "5 m/s"', "say which way"),
    ('vs_C = "5 m/s"', "no slider C"),
    ('vs_B = "5 m/s"\nas_B = 1\nacceleration = "2 rad/s^2 cw"', "one only"),
    ('vs_B = "0 m/s"', "zero"),
    ('vs_B = "5 m/s up"', "perpendicular"),
    ('speed = "10 rad/s cw"\nas_B = 3', "rate of a given motion"),
]


@pytest.mark.parametrize("given, words", BAD)
def test_bad_given_one_line(tmp_path, capsys, given, words):
    f = tmp_path / "s.toml"
    f.write_text(SLIDER.format(e=0, angle=30, given=given))
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err and "[input]" in err, err


def test_every_view_takes_a_given_motion(tmp_path):
    f = tmp_path / "s.toml"
    f.write_text(
        SLIDER.format(e=20, angle=60, given='vs_B = "5 m/s left"\nas_B = -20')
        + '[answers]\nomega_OA = "40 rad/s ccw"\n'
    )
    for argv in (
        ["solve", "--json"],
        ["steps"],
        ["check"],
        ["centres"],
        ["linkage"],
        ["draw", "-o", str(tmp_path / "d.svg")],
        ["sweep", "--steps", "36", "--summary"],
        ["page", "-o", str(tmp_path / "p.html")],
    ):
        code = main([argv[0], str(f), *argv[1:]])
        assert code in (0, 1), argv  # check: 1 when an answer is wrong


def test_entry_point_prints_the_found_speed(tmp_path):
    f = tmp_path / "s.toml"
    f.write_text(SLIDER.format(e=0, angle=90, given='vs_B = "1.5 m/s left"'))
    out = subprocess.run(
        [sys.executable, "-m", "polygon_method", "solve", str(f)],
        capture_output=True,
        text=True,
        check=True,
    ).stdout
    # at 90 deg the piston moves as fast as the crank pin: omega = 1.5 / 0.15
    assert "crank OA at 90 deg, 10 rad/s ccw (from vs_B = 1.5 m/s left)" in out
