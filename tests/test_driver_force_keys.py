"""The answer keys of a driver's effort other than the crank's torque (``force``: a driving
block's or collar's force along its guide; ``force2``: a collar driven along the crank as
the second input; ``torque`` beside it) and the slips a student makes with them, against
the 50-digit matrix method (every moving body's Newton-Euler equations as one linear
system on the 50-digit constraint solve's kinematics, ``tests/test_collar_forces.py``):

- the right value within three significant figures is right, signed or as a size;
- the guide's normal force given for the driver's force, the whole pin force at the block,
  the inertia left out (the same matrix with every acceleration nought: the weights and
  loads alone) and the direction along the guide reversed are each named;
- a second input's effort has its own key, the first crank's torque beside it.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import mpmath
import pytest
from mpmath import mpf

from reference import reference_solution
from test_collar_forces import DRIVING, SECOND, _matrix, _mp, _unit
from polygon_method.check import check_answers
from polygon_method.common.errors import SceneError
from polygon_method.forces import FRAME
from polygon_method.motion.solution import solve
from polygon_method.scene import parse_scene

ROOT = Path(__file__).resolve().parent.parent

TRAMMEL = """
title = "ellipse trammel driven by its block, with masses"
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
[masses]
AB = { mass = "6 kg", along = 300, from = "A", gyration = 160 }
A = { mass = "2 kg" }
B = { mass = "1.5 kg" }
[gravity]
[loads]
B = { force = [40, -250] }
[input]
block = "A"
s_A = 300
vs_A = "2 m/s right"
as_A = "5 m/s^2 left"
"""


@pytest.fixture
def digits():
    saved = mpmath.mp.dps
    mpmath.mp.dps = 50
    yield
    mpmath.mp.dps = saved


def _still(ref):
    """The reference kinematics with every acceleration nought (the inertia left out)."""
    zero = (mpf(0), mpf(0))
    return {
        **ref,
        "accelerations": {k: zero for k in ref["accelerations"]},
        "alpha": {k: mpf(0) for k in ref["alpha"]},
    }


def _reference(text, pins, guides, torque):
    """(scene, solution, the matrix method's unknowns, the same with the inertia left out)."""
    sc = parse_scene(text)
    sol = solve(sc)
    ref = reference_solution(sc, sol.P)
    P = ref["positions"]
    P.update({k: _mp(v) for k, v in sc.ground.items()})
    g = [
        (pt, bl, gb, _unit(P, *u) if isinstance(u[0], str) else u, dr)
        for pt, bl, gb, u, dr in guides
    ]
    return sc, sol, _matrix(sc, ref, pins, g, torque), _matrix(sc, _still(ref), pins, g, torque)


def _driving():
    return _reference(
        DRIVING,
        [
            ("O", "OA", FRAME),
            ("D", "DC", FRAME),
            ("C", "DC", "block C"),
            ("A", "AB", "OA"),
            ("B", "AB", "block B"),
        ],
        [
            ("C", "block C", "OA", ("O", "A"), True),
            ("B", "block B", FRAME, (mpf(1), mpf(0)), False),
        ],
        None,
    )


def _trammel():
    return _reference(
        TRAMMEL,
        [("A", "AB", "block A"), ("B", "AB", "block B")],
        [
            ("A", "block A", FRAME, (mpf(1), mpf(0)), True),
            ("B", "block B", FRAME, (mpf(0), mpf(1)), False),
        ],
        None,
    )


def _with_answers(sc, text):
    """The scene's text with an ``[answers]`` table added."""
    return sc._text + "\n" + text


def _check(sc, key, given):
    """The verdict on ``key = given`` checked against ``sc``'s solution."""
    answers = parse_scene(_with_answers(sc, f'[answers]\n{key} = "{given}"\n')).answers
    return check_answers(solve(sc), answers)[0]


def _size(v):
    return float(mpmath.sqrt(v[0] ** 2 + v[1] ** 2))


@pytest.mark.parametrize("which", ["collar", "trammel"])
def test_a_drivers_force_and_its_slips_against_the_matrix_method(digits, which):
    sc, sol, want, still = _driving() if which == "collar" else _trammel()
    X = sc.input.block
    F = float(want[("F", X)])
    assert abs(sol.value("force", ())) > 1.0
    assert abs(sol.value("force", ()) - F) <= 1e-9 * abs(F)
    right = _check(sc, "force", f"{abs(F):.4g} N")
    assert right.ok and right.key == "force" and right.unit == "N"
    signed = _check(sc, "force", f"{F:+.4g} N")  # a sign given: compared signed
    assert signed.ok and signed.signed
    reversed_ = _check(sc, "force", f"{-F:+.4g} N")
    assert not reversed_.ok and reversed_.mistake == "sense"
    slips = {
        "normal_for_driver": abs(float(want[("N", X)])),
        "pin_force_for_driver": _size(
            next(v for k, v in want.items() if len(k) == 3 and k[0] == X)
        ),
        "inertia_left_out": abs(float(still[("F", X)])),
    }
    for code, value in slips.items():
        assert abs(value - abs(F)) > 0.02 * abs(F), code  # a slip the check can tell
        v = _check(sc, "force", f"{value:.4g} N")
        assert not v.ok and v.mistake == code, (code, v.mistake, v.diagnosis)


def test_the_second_inputs_force_and_the_cranks_torque_beside_it(digits):
    sc, sol, want, still = _reference(
        SECOND,
        [("O", "OA", FRAME), ("C", "CB", "block C"), ("B", "CB", "block B")],
        [
            ("C", "block C", "OA", ("O", "A"), True),
            ("B", "block B", FRAME, (mpf(1), mpf(0)), False),
        ],
        "OA",
    )
    F, T = float(want[("F", "C")]), float(want[("T",)])
    assert abs(sol.value("force2", ()) - F) <= 1e-9 * abs(F)
    assert abs(sol.value("torque", ()) - T) <= 1e-9 * abs(T)
    assert _check(sc, "force2", f"{abs(F):.4g} N").ok
    sense = "ccw" if T > 0 else "cw"
    assert _check(sc, "torque", f"{abs(T):.4g} N m {sense}").ok
    v = _check(sc, "force2", f"{abs(float(want[('N', 'C')])):.4g} N")
    assert not v.ok and v.mistake == "normal_for_driver"
    v = _check(sc, "torque", f"{abs(float(still[('T',)])):.4g} N m {sense}")
    assert not v.ok and v.mistake == "inertia_left_out"
    with pytest.raises(SceneError, match="its answer key is force2"):
        sol.value("torque2", ())


def test_a_drivers_force_from_the_loads_power_balance():
    """Without masses a driving block's force is the loads' power balance: F vs + sum F.v
    = 0 (the velocities of the load's point from the 50-digit reference)."""
    from polygon_method.scene import load_scene

    sc = load_scene(ROOT / "tests" / "textbook" / "block_collar_on_rod.toml")
    sol = solve(sc)
    ref = reference_solution(sc, sol.P)
    vE = ref["velocities"]["E"]
    vs = sc.input.omega  # the block's velocity along its guide (signed)
    F = -float(vE[1] * -200) / vs
    assert abs(sol.value("force", ()) - F) <= 1e-9 * abs(F)
    assert check_answers(
        sol, parse_scene(_with_answers(sc, f'[answers]\nforce = "{abs(F):.4g} N"\n')).answers
    )[0].ok


@pytest.mark.parametrize(
    "scene, key, why",
    [
        ("fourbar_forces.toml", "force", "drives this mechanism with a torque"),
        ("five_bar_two_inputs.toml", "torque2", "needs the force analysis"),
    ],
)
def test_the_keys_refused_where_they_name_nothing(tmp_path, capsys, scene, key, why):
    """One line naming the key, exit code 2: a crank's effort is no force; without the
    force analysis one power balance does not give a second input's effort."""
    from polygon_method.cli import main

    base = (ROOT / "worked_problems" / scene).read_text().split("[answers]")[0]
    path = tmp_path / "s.toml"
    path.write_text(f'{base}\n[answers]\n{key} = "10"\n')
    assert main(["check", str(path)]) == 2
    err = capsys.readouterr().err
    assert why in err and key in err and len(err.strip().splitlines()) == 1


def test_a_power_given_in_kw_is_shown_in_kw_too(tmp_path, capsys):
    """The correct value in SI and in the answer's own unit (as a speed in in/s is): the
    mean power of T = 1100 + 320 sin 2 theta - 480 cos 2 theta at 280 rpm is 1100 w."""
    from polygon_method.cli import main

    base = (ROOT / "tests" / "textbook" / "flywheel" / "law_rim_section.toml").read_text()
    base = base.split("[answers]")[0]
    P = 1100 * 280 * 2 * math.pi / 60
    for given, own in (
        ("30.1 kW", f"{P / 1e3:.4g} kW"),
        ("43 hp", f"{P / 745.69987158227:.4g} hp"),
    ):
        path = tmp_path / "p.toml"
        path.write_text(f'{base}[answers]\npower = "{given}"\n')
        assert main(["check", str(path)]) == 1
        out = capsys.readouterr().out
        assert f"W ({own})" in out, out
        assert main(["check", "--json", str(path)]) == 1
        (v,) = json.loads(capsys.readouterr().out)["answers"]
        assert abs(v["correct"] - P) <= 1e-9 * P and v["unit"] == "W"
