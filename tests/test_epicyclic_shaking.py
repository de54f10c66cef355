"""The loaded epicyclic train's shaking force and moment (Rattan's train of
``tests/textbook/rattan_epicyclic_by_teeth.toml``: the sun of 40 teeth fixed, the arm
driven, the annulus of 88 teeth resisting with 100 N m) against a Newton-Euler solve by hand
at 40 digits: each moving body's three equations (the arm, the planet, the annulus), each
tooth load one unknown along its line of action, the driver's torque; then the forces the
train puts on the frame (its two bearings at O, the planet's push on the fixed sun, the
driver's reaction) summed by hand. Static, the shaking moment is the 100 N m cw of the
annulus's resisting machine (its reaction is on that machine, not on this frame: the
driver's 145.5 N m cw less the sun's 45.45 N m ccw); with the bodies massive, the arm
speeding up and gravity, every force and both shaking sums to 1e-9."""

from __future__ import annotations

from pathlib import Path

import mpmath
import pytest
from mpmath import mpf

from newton_euler import NewtonEuler
from polygon_method import load_scene, parse_scene, solve

HERE = Path(__file__).resolve().parent / "textbook"
TRAIN = HERE / "rattan_epicyclic_by_teeth.toml"
REL = 1e-9

MASSES = """[masses]
OA = { mass = "3 kg", along = 80, gyration = 60 }
AP = { mass = "1.5 kg", centre = "A", gyration = 40 }
"O-Q" = { mass = "6 kg", centre = "O", gyration = 200 }
[gravity]
"""


def _reference(massive, alpha_arm):
    """The train at 30 deg, the arm at 200 rpm ccw speeding up at ``alpha_arm`` (rad/s^2):
    the 40-digit Newton-Euler solve, the two leans of each tooth load tried and the one
    that pushes the teeth apart kept. Returns the solution and the shaking (Fx, Fy, M)."""
    mpmath.mp.dps = 40
    rs, rp, rr = mpf("0.1"), mpf("0.06"), mpf("0.22")  # m z / 2, the module 5 mm
    R = rs + rp
    th = mpmath.radians(30)
    e = (mpmath.cos(th), mpmath.sin(th))
    t = (-e[1], e[0])
    w, al = 200 * mpmath.pi / 30, mpf(alpha_arm)
    A, P, Q = ((R * e[0], R * e[1]), (rs * e[0], rs * e[1]), (rr * e[0], rr * e[1]))
    # rolling: the planet's pitch point on the sun at rest, the annulus's moving with it
    al_p, al_r = al * R / rp, 2 * al * R / rr
    g = mpf("9.81")

    def acc(d):  # a point of the arm at distance d along it
        return (-(w**2) * d * e[0] + al * d * t[0], -(w**2) * d * e[1] + al * d * t[1])

    tan = mpmath.tan(mpmath.radians(20))
    for s1 in (1, -1):
        for s2 in (1, -1):
            ne = NewtonEuler(["arm", "planet", "ring"], mp=True)
            ne.pin("O1", (0, 0), "arm", "frame")
            ne.pin("A", A, "planet", "arm")
            # on the planet by the sun: along t, pushed apart along +e (towards its centre)
            ne.along("Ts", P, (t[0] + s1 * tan * e[0], t[1] + s1 * tan * e[1]), "planet", "frame")
            # on the planet by the annulus: pushed towards its own centre, along -e
            ne.along("Tr", Q, (t[0] - s2 * tan * e[0], t[1] - s2 * tan * e[1]), "planet", "ring")
            ne.pin("O2", (0, 0), "ring", "frame")
            ne.couple("T", "arm", "frame")
            ne.known("ring", c=mpf(-100))
            if massive:
                for body, m, k, G, a, alpha in (
                    (
                        "arm",
                        3,
                        mpf("0.06"),
                        (mpf("0.08") * e[0], mpf("0.08") * e[1]),
                        acc(mpf("0.08")),
                        al,
                    ),
                    ("planet", mpf("1.5"), mpf("0.04"), A, acc(R), al_p),
                    ("ring", 6, mpf("0.2"), (0, 0), (0, 0), al_r),
                ):
                    ne.known(body, (-m * a[0], -m * a[1] - m * g), G, -m * k**2 * alpha)
            x = ne.solve()
            if s1 * x["Ts"] >= 0 and s2 * x["Tr"] >= 0:
                Fs = (x["Ts"] * (t[0] + s1 * tan * e[0]), x["Ts"] * (t[1] + s1 * tan * e[1]))
                fx = -x["O1.x"] - x["O2.x"] - Fs[0]
                fy = -x["O1.y"] - x["O2.y"] - Fs[1]
                # the frame feels the bearings at O (no arm about O), the push on the sun at
                # P and the driver's reaction -T
                m_ = -(P[0] * Fs[1] - P[1] * Fs[0]) - x["T"]
                return x, (fx, fy, m_), Fs
    raise AssertionError("no lean pushes both pairs of teeth apart")


def _scene(massive, alpha):
    text = TRAIN.read_text(encoding="utf-8")
    if massive:
        text = text.replace("[masses]\n", MASSES)
    if alpha:
        text = text.replace(
            'speed = "200 rpm ccw"', f'speed = "200 rpm ccw"\nacceleration = "{alpha} rad/s^2 ccw"'
        )
    return parse_scene(text)


@pytest.mark.parametrize("massive, alpha", [(False, 0), (True, 0), (True, 40)])
def test_the_trains_forces_and_shaking_against_newton_euler(massive, alpha):
    x, (fx, fy, m), Fs = _reference(massive, alpha)
    sol = solve(_scene(massive, alpha))
    f = sol.forces
    assert f.input_torque == pytest.approx(float(x["T"]), rel=REL)
    big = float(max(abs(x["O1.x"]), abs(x["O1.y"]), abs(x["Ts"])))
    assert f.shaking_force[0] == pytest.approx(float(fx), abs=REL * big)
    assert f.shaking_force[1] == pytest.approx(float(fy), abs=REL * big)
    assert f.shaking_moment == pytest.approx(float(m), rel=REL, abs=REL * big * 0.22)
    # the planet pushes the sun with -Fs at P; the frame holds it with the opposite, P x Fs
    P = (0.1 * mpmath.cos(mpmath.radians(30)), 0.1 * mpmath.sin(mpmath.radians(30)))
    assert sol.value("Thold", ("O",)) == pytest.approx(float(P[0] * Fs[1] - P[1] * Fs[0]), rel=REL)


def test_static_the_shaking_moment_is_the_resisting_machines_torque():
    """Static: the frame feels the driver's reaction, 145.45 N m cw, and the sun's push,
    45.45 N m ccw: 100 N m cw, the torque of the machine the annulus drives (the reaction
    of the load is on that machine, not on this frame), and no shaking force."""
    x, (fx, fy, m), _ = _reference(False, 0)
    assert float(x["T"]) == pytest.approx(100 * (1 + 40 / 88), rel=REL)
    assert float(m) == pytest.approx(-100.0, rel=REL)
    assert abs(float(fx)) < 1e-30 and abs(float(fy)) < 1e-30
    sol = solve(load_scene(TRAIN))
    assert sol.forces.shaking_moment == pytest.approx(-100.0, rel=REL)
