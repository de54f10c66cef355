"""Weights at rest: ``[masses]`` and ``[gravity]`` with the crank's speed nought give the
weights (and the loads) alone, no inertia; held to statics solved by hand in the test:

- a four-bar lifting linkage (three uniform heavy links and a load on the coupler produced,
  worked_problems/lifting_linkage_at_rest.toml stated with masses instead of loads): the
  positions by the two circles' intersection and each link's three equations of
  equilibrium as one 9 x 9 system at 50 digits (every pin force and the holding torque);
  the book's 169.8 N m cw;
- a vertical slider crank holding its piston's weight and its crank's: the rod is a
  two-force member, so the piston's balance gives the rod's force and the guide's, the
  crank's moments the holding torque, in closed form; over the turn the holding torque is
  the potential energy's derivative dU/dtheta (the sweep at rest).
"""

from __future__ import annotations

import json
import math

import mpmath
import numpy as np
import pytest
from mpmath import mpf

from polygon_method.check import check_answers
from polygon_method.motion.solution import solve
from polygon_method.motion.sweeps import sweep
from polygon_method.forces import FRAME, analyse
from polygon_method.scene import parse_scene
from polygon_method.common.errors import SceneError

LIFTING = """
title = "lifting linkage at rest, the links' weights from their masses"
units = "m"
[ground]
A = [0, 0]
D = [1.2, 0]
[links]
AB = 0.5
BC = 1.0
CD = 0.8
[points]
E = { on = "BC", along = 1.4 }
[assembly]
C = "above"
[input]
crank = "AB"
angle = 100
speed = 0
[masses]
AB = { mass = "10 kg" }
BC = { mass = "20 kg", gyration = 0.3 }
CD = { mass = "15 kg" }
[gravity]
[loads]
E = { force = "500 N", direction = "down" }
[answers]
tolerance = "1%"
torque = "169.8 N m cw"
"""

VERTICAL = """
title = "vertical slider crank at rest: the piston's and the crank's weights held"
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 150
AB = 600
[sliders]
B = { path = "vertical", through = "O" }
[assembly]
B = "above"
[input]
crank = "OA"
angle = 30
speed = "0 rpm"
[masses]
OA = { mass = "4 kg" }
B = { mass = "12 kg" }
[gravity]
g = "9.81 m/s^2"
"""


@pytest.fixture
def digits():
    saved = mpmath.mp.dps
    mpmath.mp.dps = 50
    yield
    mpmath.mp.dps = saved


def _lifting_by_hand():
    """The four-bar's statics at 50 digits: positions from the two circles about B and D,
    then per link (AB, BC, CD) its forces and moments about the origin in the unknowns
    F_A (on AB by the frame), F_B (on BC by AB), F_C (on BC by CD), F_D (on CD by the
    frame) and T (on AB by its driver)."""
    g = mpf("9.81")
    th = mpmath.radians(100)
    A, D = (mpf(0), mpf(0)), (mpf("1.2"), mpf(0))
    B = (mpf("0.5") * mpmath.cos(th), mpf("0.5") * mpmath.sin(th))
    dx, dy = D[0] - B[0], D[1] - B[1]
    d = mpmath.sqrt(dx * dx + dy * dy)
    a = (1 + d * d - mpf("0.64")) / (2 * d)  # from B along BD, BC = 1, CD = 0.8
    h = mpmath.sqrt(1 - a * a)
    C = (B[0] + a * dx / d - h * dy / d, B[1] + a * dy / d + h * dx / d)  # above BD
    E = (B[0] + mpf("1.4") * (C[0] - B[0]), B[1] + mpf("1.4") * (C[1] - B[1]))
    mid = lambda P, Q: ((P[0] + Q[0]) / 2, (P[1] + Q[1]) / 2)  # noqa: E731
    loads = {  # body -> [(force, point)]
        "AB": [((0, -10 * g), mid(A, B))],
        "BC": [((0, -20 * g), mid(B, C)), ((0, mpf(-500)), E)],
        "CD": [((0, -15 * g), mid(C, D))],
    }
    cols = {"FAx": 0, "FAy": 1, "FBx": 2, "FBy": 3, "FCx": 4, "FCy": 5, "FDx": 6, "FDy": 7, "T": 8}
    M, rhs = mpmath.zeros(9, 9), mpmath.zeros(9, 1)
    acts = {  # body -> [(unknown pair, point, sign)]
        "AB": [("FA", A, 1), ("FB", B, -1)],
        "BC": [("FB", B, 1), ("FC", C, 1)],
        "CD": [("FC", C, -1), ("FD", D, 1)],
    }
    for i, body in enumerate(("AB", "BC", "CD")):
        r = 3 * i
        for name, P, sign in acts[body]:
            M[r, cols[name + "x"]] += sign
            M[r + 1, cols[name + "y"]] += sign
            M[r + 2, cols[name + "x"]] += -sign * P[1]
            M[r + 2, cols[name + "y"]] += sign * P[0]
        for (fx, fy), P in loads[body]:
            rhs[r] -= fx
            rhs[r + 1] -= fy
            rhs[r + 2] -= P[0] * fy - P[1] * fx
    M[2, cols["T"]] = 1
    x = mpmath.lu_solve(M, rhs)
    return {k: x[j] for k, j in cols.items()}


def test_a_four_bar_at_rest_holds_its_weights_as_statics_by_hand(digits):
    sc = parse_scene(LIFTING)
    assert sc.at_rest
    sol = solve(sc)
    f = sol.forces
    want = _lifting_by_hand()
    big = max(abs(float(v)) for v in want.values())
    assert abs(f.input_torque - float(want["T"])) <= 1e-9 * abs(float(want["T"]))
    for pin, key, on, by in (
        ("A", "FA", "AB", FRAME),
        ("B", "FB", "BC", "AB"),
        ("C", "FC", "BC", "CD"),
        ("D", "FD", "CD", FRAME),
    ):
        got = f.pin(pin, on, by)
        assert (
            math.hypot(got[0] - float(want[key + "x"]), got[1] - float(want[key + "y"]))
            <= 1e-9 * big
        ), pin
    for i in f.inertia:  # no inertia at rest, the gyration given notwithstanding
        assert i.force == (0.0, 0.0) and i.couple == 0.0
    assert abs(-f.input_torque - 169.8) <= 0.01 * 169.8  # the book's, clockwise
    (v,) = check_answers(sol)
    assert v.ok, v
    d = json.loads(json.dumps(sol.to_dict()))
    assert d["at_rest"] is True and d["forces"]["input_torque"] == f.input_torque


def _vertical_by_hand(theta):
    """The vertical slider crank's statics in closed form (floats): the rod AB massless
    is a two-force member; the piston's balance along the vertical gives the rod's force,
    across it the guide's; the crank's moments about O the holding torque. Returns (T, the
    rod's force's size, the guide's normal force's size)."""
    r, l, g = 0.15, 0.6, 9.81
    A = (r * math.cos(theta), r * math.sin(theta))
    B = (0.0, A[1] + math.sqrt(l * l - A[0] ** 2))
    e = ((B[0] - A[0]) / l, (B[1] - A[1]) / l)  # A -> B
    f = 12 * g / e[1]  # the rod pushes the piston along e: f e_y = m g
    N = -f * e[0]
    on_crank = (-f * e[0], -f * e[1])  # the rod pushes the crank back at A
    moment = A[0] * on_crank[1] - A[1] * on_crank[0] + (A[0] / 2) * (-4 * g)
    return -moment, abs(f), abs(N)


def test_a_vertical_slider_crank_at_rest_in_closed_form():
    sc = parse_scene(VERTICAL)
    sol = solve(sc)
    f = sol.forces
    T, rod, N = _vertical_by_hand(math.radians(30))
    assert abs(f.input_torque - T) <= 1e-9 * abs(T)
    assert abs(sol.value("F", ("B",)) - rod) <= 1e-9 * rod
    assert abs(sol.value("N", ("B",)) - N) <= 1e-9 * rod


def test_the_holding_torque_over_the_turn_is_the_potential_energys_derivative():
    """At rest at every crank angle (the sweep): T = dU/dtheta, U = m_c g (r/2) sin theta +
    m_p g y_B(theta), y_B = r sin theta + sqrt(l^2 - r^2 cos^2 theta)."""
    sc = parse_scene(VERTICAL)
    th = np.radians(np.arange(1.0, 360.0, 7.0))
    f = analyse(sweep(sc, th))
    r, l, g = 0.15, 0.6, 9.81
    c, s = np.cos(th), np.sin(th)
    dyB = r * c + r * r * c * s / np.sqrt(l * l - (r * c) ** 2)
    dU = 4 * g * (r / 2) * c + 12 * g * dyB
    assert np.all(np.abs(f.input_torque - dU) <= 1e-9 * np.abs(dU).max())


def test_the_words_say_at_rest(capsys, tmp_path):
    from polygon_method.cli import main

    path = tmp_path / "rest.toml"
    path.write_text(LIFTING)
    assert main(["solve", str(path)]) == 0
    out = capsys.readouterr().out
    assert "at rest, about to turn ccw (the velocities and accelerations below are per 1" in out
    assert "at rest: no inertia (nothing moves); the weights m g at G" in out
    assert "(at rest: the weights and loads, no inertia): 169.8 N m cw" in out
    assert main(["steps", str(path)]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert (
        "at rest (omega_AB = 0, about to turn ccw): the polygons are drawn for omega_AB = 1" in out
    )
    assert "6. Weights at rest (no inertia)" in out and "Inertia forces" not in out
    assert "(the weights and loads, no inertia; its power balances theirs)" in out


@pytest.mark.parametrize(
    "change, why",
    [
        ("[gravity]\n", "give [masses] and [gravity]"),  # no force analysis asked
        (
            'speed = 0\nacceleration = "2 rad/s^2 ccw"',
            "starting from rest with an acceleration: give [masses]",
        ),  # (with [masses] it is solved: tests/test_start_from_rest.py)
    ],
)
def test_a_zero_speed_refused_where_nothing_is_held(change, why):
    text = LIFTING.split("[masses]")[0]
    if change != "[gravity]\n":
        text = text.replace("speed = 0", change)
    with pytest.raises(SceneError, match=why.replace("[", r"\[").replace("]", r"\]")):
        parse_scene(text)


def test_a_slider_crank_at_rest_has_no_klein_construction():
    """Klein's construction draws the piston's motion: at rest there is none to draw."""
    from polygon_method.linkage.klein import klein_of

    sol = solve(parse_scene(VERTICAL))
    k, why = klein_of(sol)
    assert k is None and why.startswith("at rest")
    moving = solve(parse_scene(VERTICAL.replace('speed = "0 rpm"', 'speed = "60 rpm ccw"')))
    assert klein_of(moving)[0] is not None
