"""The flywheel chapter's problems that give the energy and no diagram
(``[turning_moment] dE_max``): "the maximum fluctuation of energy per revolution is 15 % of
the energy developed per revolution" (with the power, or the work of a cycle) and "the
fluctuation of energy is 56 kN m". Held to the book's arithmetic in exact fractions (pi kept
apart as mpmath's at 40 digits); every view (the drawings refused in one line: no diagram);
the bad tables in one line."""

from __future__ import annotations

from fractions import Fraction as Q
from pathlib import Path

import mpmath
import pytest

from polygon_method.cli import main
from polygon_method.forces.flywheel_cycle import solve_cycle
from polygon_method.scene.energy import cycle_from_text

HERE = Path(__file__).resolve().parent / "textbook" / "flywheel"
STEAM = HERE / "energy_fluctuation_part_of_the_work.toml"
GIVEN = HERE / "energy_fluctuation_given_speeds.toml"
REL = 1e-12


def _solve(path, text=None):
    return solve_cycle(cycle_from_text(text or path.read_text(encoding="utf-8"), str(path)))


def _run(capsys, *args):
    code = main([str(a) for a in args])
    out = capsys.readouterr()
    return code, out.out, out.err


def test_khurmis_steam_engine_by_the_books_arithmetic():
    """185 kW at 100 rpm: W = 185000 x 60 / 100 J a revolution (exactly: P 2 pi / w);
    dE_max = 15 % of it; Cs = 0.02; I = dE_max / (w^2 Cs); the rim at 1.2 m, 7200 kg/m^3,
    its width twice its thickness."""
    mpmath.mp.dps = 40
    W = Q(185000 * 60, 100)
    dE = Q(15, 100) * W
    assert (W, dE) == (111000, 16650)
    w = 100 * 2 * mpmath.pi / 60
    I = dE / (w**2 * mpmath.mpf("0.02"))
    m = I / mpmath.mpf("1.44")
    area = m / (2 * mpmath.pi * mpmath.mpf("1.2") * 7200)
    t = mpmath.sqrt(area / 2)
    c = _solve(STEAM)
    assert c.form == "energy" and c.dE_max == pytest.approx(float(dE), rel=REL)
    assert c.work == pytest.approx(float(W), rel=REL)
    assert c.T_mean == pytest.approx(float(W / (2 * mpmath.pi)), rel=REL)
    assert c.inertia == pytest.approx(float(I), rel=1e-11)
    assert c.mass == pytest.approx(float(m), rel=1e-11)
    assert c.rim_thickness == pytest.approx(float(t), rel=1e-11)
    assert c.rim_width == pytest.approx(float(2 * t), rel=1e-11)
    assert float(m) == pytest.approx(5272, rel=1e-3)  # the book's 5270 kg


def test_the_work_given_instead_of_the_power_is_the_same():
    text = STEAM.read_text(encoding="utf-8").replace('power = "185 kW"', 'work = "111 kJ"')
    assert _solve(STEAM, text).dE_max == pytest.approx(_solve(STEAM).dE_max, rel=REL)


def test_khurmis_flywheel_given_its_speeds_found():
    """I = 6500 x 1.8^2; Cs = 56000 / (I w^2); the speeds w (1 +- Cs / 2)."""
    mpmath.mp.dps = 40
    I = Q(6500) * Q(18, 10) ** 2
    w = 120 * 2 * mpmath.pi / 60
    cs = 56000 / (I * w**2)
    c = _solve(GIVEN)
    assert c.Cs == pytest.approx(float(cs), rel=REL)
    assert c.speed_max == pytest.approx(float(w * (1 + cs / 2)), rel=REL)
    assert c.speed_min == pytest.approx(float(w * (1 - cs / 2)), rel=REL)
    assert c.T_mean is None  # no power, no work: no mean torque


@pytest.mark.parametrize("scene", [STEAM, GIVEN])
def test_every_view(capsys, tmp_path, scene):
    code, out, _ = _run(capsys, "solve", scene)
    assert code == 0 and "the maximum fluctuation of energy given (no diagram)" in out
    assert "the energy greatest at" not in out  # (no angles: the energy alone)
    code, out, _ = _run(capsys, "steps", scene)
    assert code == 0 and "as the book states it" in out
    code, out, _ = _run(capsys, "solve", scene, "--json")
    assert code == 0 and '"form": "energy"' in out
    assert _run(capsys, "check", scene)[0] == 0
    assert _run(capsys, "sweep", scene, "--summary")[0] == 0
    for args in (
        ["draw", scene, "-o", tmp_path / "d.svg"],
        ["page", scene, "-o", tmp_path / "p.html"],
        ["sweep", scene, "--plot", tmp_path / "p.svg"],
        ["sweep", scene, "--csv", tmp_path / "c.csv"],
    ):
        code, _, err = _run(capsys, *args)
        assert code == 2 and len(err.strip().splitlines()) == 1, err
        assert "fluctuation of energy" in err
    assert not (tmp_path / "d.svg").exists() and not (tmp_path / "p.html").exists()


def test_a_students_flywheel_with_cs_either_side_is_named(capsys, tmp_path):
    answers = tmp_path / "a.toml"
    answers.write_text('[answers]\nI_flywheel = "15182 kg m^2"\n', encoding="utf-8")
    code, out, _ = _run(capsys, "check", STEAM, answers)
    assert code == 1 and "mistake" in out


@pytest.mark.parametrize(
    "old, new, words",
    [
        ('power = "185 kW"\n', "", "a part of the work of a cycle, which needs"),
        ('dE_max = "15%"', 'dE_max = "-5 kJ"', "the fluctuation must be positive"),
        ('dE_max = "15%"', 'dE_max = "15 kg"', "dE_max"),
        ('power = "185 kW"', 'power = "185 kW"\nwork = "111 kJ"', "one of them"),
        ('power = "185 kW"', 'power = "185 kW"\nresisting = "100"', "resisting: not with dE_max"),
        ('power = "185 kW"', 'power = "185 kW"\nareas = [1, -1]', "one of them"),
    ],
)
def test_a_bad_table_is_one_line(tmp_path, capsys, old, new, words):
    bad = tmp_path / "bad.toml"
    bad.write_text(STEAM.read_text(encoding="utf-8").replace(old, new), encoding="utf-8")
    code, _, err = _run(capsys, "solve", bad)
    assert code == 2 and words in err and len(err.strip().splitlines()) == 1, err


LOSSES = HERE / "press_frictional_losses.toml"


def test_khurmis_press_with_its_frictional_losses():
    """6 J a mm^2 of pi d t, 7/6 of it with the losses; 10 holes a minute, 1.5 s of
    punching in 6: dE_max = E (1 - 1/4); the power E / 6 s; Cs = 20 / 190."""
    mpmath.mp.dps = 40
    E = 6 * mpmath.pi * 25 * 20 * mpmath.mpf(7) / 6
    dE = E * (1 - mpmath.mpf(1.5) / 6)
    w = 190 * 2 * mpmath.pi / 60
    I = dE / (w**2 * mpmath.mpf(20) / 190)
    c = _solve(LOSSES)
    assert c.power == pytest.approx(float(E / 6), rel=REL)
    assert c.dE_max == pytest.approx(float(dE), rel=REL)
    assert c.inertia == pytest.approx(float(I), rel=1e-11)
    assert c.mass == pytest.approx(float(I / mpmath.mpf("0.25")), rel=1e-11)
    same = LOSSES.read_text(encoding="utf-8").replace(
        'losses = "1/6"', "losses = 0.1666666666666666667"
    )
    assert _solve(LOSSES, same).dE_max == pytest.approx(c.dE_max, rel=1e-12)


@pytest.mark.parametrize("value", ['"a sixth"', '"-10%"', "true", '"1/0"'])
def test_bad_losses_are_one_line(tmp_path, capsys, value):
    bad = tmp_path / "bad.toml"
    bad.write_text(
        LOSSES.read_text(encoding="utf-8").replace('losses = "1/6"', f"losses = {value}"),
        encoding="utf-8",
    )
    code, _, err = _run(capsys, "solve", bad)
    assert code == 2 and "losses" in err and len(err.strip().splitlines()) == 1, err


def test_the_coefficient_of_fluctuation_of_energy(tmp_path, capsys):
    """Ce = dE_max / the work of a cycle: Khurmi's steam engine's stated 15 % back; the gas
    engine of strokes 12000 (11/12)^2 / 8000; none for areas alone (no work known)."""
    assert _solve(STEAM).Ce == pytest.approx(0.15, rel=REL)
    gas = HERE / "strokes_expansion_three_times_compression.toml"
    assert _solve(gas).Ce == pytest.approx(12000 * 121 / 144 / 8000, rel=REL)
    assert _solve(HERE / "areas_multicylinder.toml").Ce is None
    answers = tmp_path / "a.toml"
    answers.write_text('[answers]\nCe = "15%"\n', encoding="utf-8")
    code, out, _ = _run(capsys, "check", STEAM, answers)
    assert code == 0 and "right" in out
    code, out, _ = _run(capsys, "solve", STEAM)
    assert "coefficient of fluctuation of energy Ce = dE_max / (work per cycle) = 0.15" in out
