"""``[turning_moment] cylinders``: one cylinder's turning moment (readings, or strokes)
summed over n cylinders firing at equal intervals. Held to the copies summed here in
mpmath at 30 digits (each cylinder's segments evaluated at its own phase) at many angles,
with a jump; to Khurmi's three-cylinder engine worked by hand (the sum a triangle wave
between 30 and 60 N m: T_mean 45 N m, dE_max = pi / 3 x 15 / 2 J, alpha at 60 deg 15 / I);
every view; the bad tables in one line."""

from __future__ import annotations

from pathlib import Path

import mpmath
import pytest

from polygon_method.cli import main
from polygon_method.forces.flywheel_cycle import solve_cycle
from polygon_method.scene.energy import cycle_from_text

HERE = Path(__file__).resolve().parent / "textbook" / "flywheel"
THREE = HERE / "segments_three_cylinders_summed.toml"
REL = 1e-12


def _one(angles, torques):
    """One cylinder's torque at u (deg, within its cycle), mpmath: at a jump, after it."""
    A = [mpmath.mpf(a) for a in angles]

    def T(u):
        for i in range(len(A) - 1):
            if A[i] <= u < A[i + 1]:
                return torques[i] + (torques[i + 1] - torques[i]) * (u - A[i]) / (A[i + 1] - A[i])
        return mpmath.mpf(torques[-1])

    return T


@pytest.mark.parametrize(
    "angles, torques, n, cycle",
    [
        ([0, 60, 180, 360], [0, 60, 0, 0], 3, 360),
        (
            [0, 90, 180, 270, 360, 450, 540, 540, 630, 720],
            [0, -800, 0, -2600, 0, 18000, 0, 300, -900, 0],
            4,
            720,
        ),
        ([0, 45, 180, 180, 300, 360], [100, 500, 20, -50, 0, 100], 5, 360),
    ],
)
def test_the_sum_of_the_shifted_copies_against_mpmath(angles, torques, n, cycle):
    text = (
        f"[turning_moment]\nangle = {angles}\ntorque = {torques}\ncylinders = {n}\n"
        f'cycle = "{cycle} deg"\n'
    )
    sc = cycle_from_text(text, "t.toml")
    T = _one(angles, torques)
    table = sc.diagram.driving
    with mpmath.workdps(30):
        for j in range(1, 997):
            x = mpmath.mpf(cycle) * j / 997  # (off every corner)
            want = sum(T((x - k * mpmath.mpf(cycle) / n) % cycle) for k in range(n))
            got = table.value(float(mpmath.radians(x)))
            assert got == pytest.approx(float(want), rel=1e-9, abs=1e-9 * max(map(abs, torques)))
    c = solve_cycle(sc)
    one = cycle_from_text(
        f"[turning_moment]\nangle = {angles}\ntorque = {torques}\n", "t.toml"
    ).diagram.driving
    work = one.integral(one.angles[-1])
    assert c.work == pytest.approx(n * work, rel=1e-9)  # n cylinders, n times one's work


def test_khurmis_three_cylinders_by_hand():
    mpmath.mp.dps = 30
    c = solve_cycle(cycle_from_text(THREE.read_text(encoding="utf-8"), str(THREE)))
    w = 600 * 2 * mpmath.pi / 60
    I = 3 * mpmath.mpf("0.065") ** 2
    dE = mpmath.pi / 3 * 15 / 2
    assert c.T_mean == pytest.approx(45, rel=REL)
    assert c.power == pytest.approx(float(45 * w), rel=REL)
    assert c.dE_max == pytest.approx(float(dE), rel=1e-9)
    assert c.Cs == pytest.approx(float(dE / (I * w**2)), rel=1e-9)
    assert c.alpha_at == pytest.approx(float(15 / I), rel=1e-9)
    # the first of the three equal lobes, as the book reads them
    assert c.crossings[c.i_max].letter == "b"
    assert mpmath.degrees(c.crossings[c.i_max].angle) == pytest.approx(90, rel=1e-9)


def test_every_view(capsys, tmp_path):
    for args in (
        ["solve", THREE],
        ["steps", THREE],
        ["check", THREE],
        ["sweep", THREE, "--summary"],
        ["solve", THREE, "--json"],
        ["draw", THREE, "-o", tmp_path / "d.svg"],
        ["page", THREE, "-o", tmp_path / "p.html"],
        ["sweep", THREE, "--csv", tmp_path / "c.csv"],
    ):
        assert main([str(a) for a in args]) == 0, args
    out = capsys.readouterr().out
    assert "3 cylinders, each this turning moment, firing 120 deg apart" in out


@pytest.mark.parametrize(
    "body, words",
    [
        ('torque = "100 + 30 sin 3theta"\ncylinders = 3', "a law sums its cylinders"),
        ('areas = [10, -10]\narea_unit = "J"\ncylinders = 2', "cylinders: one cylinder"),
        ("angle = [0, 180, 360]\ntorque = [0, 50, 0]\ncylinders = 1", "cylinders = 1: a whole"),
        ("angle = [0, 180, 360]\ntorque = [0, 50, 0]\ncylinders = 2.5", "cylinders = 2.5"),
    ],
)
def test_a_bad_cylinders_is_one_line(tmp_path, capsys, body, words):
    f = tmp_path / "t.toml"
    f.write_text(f"[turning_moment]\n{body}\n", encoding="utf-8")
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err
    assert words in err and len(err.strip().splitlines()) == 1, err


def test_the_power_with_cylinders_is_the_engines():
    """'A four-cylinder engine develops 20 kW': the strokes' works are a cylinder's share,
    the mean torque the engine's own (20 kW at 300 rpm), not four times it."""
    text = (HERE / "strokes_expansion_three_times_compression.toml").read_text(encoding="utf-8")
    text = text.replace('power = "20 kW"\n', 'power = "20 kW"\ncylinders = 4\n', 1)
    c = solve_cycle(cycle_from_text(text.split("[answers]")[0], "t.toml"))
    assert c.power == pytest.approx(20000, rel=REL)
    assert c.T_mean == pytest.approx(20000 / (300 * float(mpmath.pi) / 30), rel=REL)
