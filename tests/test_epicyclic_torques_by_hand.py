"""Epicyclic trains of the gear-train chapter asked for torques: Khurmi's train driven by its
sun with the annulus held (its teeth and the carrier's arm given, no module: the pitch radii
from the centre distance), and Rattan's compound planet. Held to Willis' formula and the
train's torques summing to nought, by hand in exact fractions, and to the tooth loads by
each gear's moments (the planet's moments about its centre)."""

from __future__ import annotations

from fractions import Fraction as Q
from pathlib import Path

import pytest

from polygon_method import load_scene, solve
from polygon_method.cli import main

HERE = Path(__file__).resolve().parent / "textbook"
SUN = HERE / "khurmi_epicyclic_sun_driven_annulus_held.toml"
COMPOUND = HERE / "rattan_compound_planet_holding.toml"
RPM = 3.141592653589793 / 30
REL = 1e-12


def test_sun_driven_annulus_held_by_willis_and_the_torques():
    zs, zp, ze = 16, 24, 64
    ws = Q(1000)  # rpm ccw
    wc = ws / (1 + Q(ze, zs))  # Willis, the annulus at rest
    wp = wc * (1 - Q(ze, zp))  # (omega_P - omega_C) / (0 - omega_C) = z_E / z_P
    tc = -Q(100) * ws / wc  # the power balance: the carrier's machine
    held = -(Q(100) + tc)  # the three torques sum to nought
    assert (wc, wp, tc, held) == (200, Q(-1000, 3), -500, 400)
    sol = solve(load_scene(SUN))
    assert sol.W["OA"] == pytest.approx(float(wc) * RPM, rel=REL)
    assert sol.W["AP"] == pytest.approx(float(wp) * RPM, rel=REL)
    assert sol.value("torque", ()) == pytest.approx(float(tc), rel=1e-9)
    assert sol.value("Thold", ("O",)) == pytest.approx(float(held), rel=1e-9)
    # the pitch radii from the arm (100 mm) and the teeth: d z / (z_E - z_P), d z / (z + z_P)
    d = Q(1, 10)
    assert {lk.key: lk.length for lk in sol.scene.links}["AP"] == pytest.approx(
        float(d * zp / (ze - zp)), rel=REL
    )
    assert {lk.key: lk.length for lk in sol.scene.links}["O-S"] == pytest.approx(
        float(d * zs / (zs + zp)), rel=REL
    )


def test_compound_planet_by_willis_and_the_planets_moments():
    za, zb, zc, zd, m = 40, 20, 30, 30, Q(4, 1000)
    assert za + zb == zc + zd  # coaxial
    wa = Q(700)
    wd = wa * (1 - Q(za, zb) * Q(zc, zd))  # Willis, A at rest
    t_arm = -Q(100) * wd / wa  # 100 N m ccw on D
    # by the teeth: D's tangential load at C, the planet's moments, A's torque
    f_d = Q(100) / (m * zd / 2)
    f_a = f_d * (m * zc / 2) / (m * zb / 2)
    held = -f_a * (m * za / 2)
    assert held == -(t_arm + 100) == -200
    sol = solve(load_scene(COMPOUND))
    assert sol.W["O-S"] == pytest.approx(float(wd) * RPM, rel=REL)
    assert sol.value("torque", ()) == pytest.approx(float(t_arm), rel=1e-9)
    assert sol.value("Thold", ("O",)) == pytest.approx(float(held), rel=1e-9)


@pytest.mark.parametrize("scene", [SUN, COMPOUND])
def test_every_view(scene, capsys, tmp_path):
    for args in (
        ["solve", scene],
        ["solve", scene, "--json"],
        ["steps", scene],
        ["check", scene],
        ["sweep", scene, "--summary"],
        ["draw", scene, "-o", tmp_path / "d.svg"],
        ["draw", scene, "--forces", "-o", tmp_path / "f.svg"],
    ):
        assert main([str(a) for a in args]) == 0, args
    out = capsys.readouterr().out
    assert "holds the" in out


def test_no_module_and_no_arm_is_still_one_line(tmp_path, capsys):
    text = SUN.read_text(encoding="utf-8").replace("[links]\nOA = 100\n", "")
    bad = tmp_path / "bad.toml"
    bad.write_text(text, encoding="utf-8")
    assert main(["solve", str(bad)]) == 2
    err = capsys.readouterr().err
    assert "module" in err and len(err.strip().splitlines()) == 1


def test_two_fixed_centres_no_module_no_links():
    """Gears of 20 and 50 teeth on fixed centres 140 mm apart, neither in [links] nor a
    module: r = d z / (z + z_o), 40 and 100 mm; omega3 = -omega2 20/50."""
    from polygon_method import parse_scene

    sol = solve(
        parse_scene(
            """units = "mm"
[ground]
O2 = [0, 0]
O3 = [140, 0]
[links]
"O2-A" = 40
[rolling]
"O3-B" = { on = "O2-A", teeth = 50, on_teeth = 20 }
[input]
crank = "O2-A"
angle = 0
speed = "100 rpm cw"
"""
        )
    )
    lengths = {lk.key: lk.length for lk in sol.scene.links}
    assert lengths["O3-B"] == pytest.approx(0.14 * 50 / 70, rel=REL)
    assert sol.W["O3-B"] == pytest.approx(100 * RPM * 20 / 50, rel=REL)
    assert any(
        n.startswith("[links] O3-B not given: its length the pitch radius") for n in sol.notes
    )


DRIVE = HERE / "wilson_sadler_geared_drive_accelerating.toml"


def test_geared_drive_by_the_reflected_inertias():
    """T = (I1 + I23 n2^2 + I4 n4^2) alpha + T_drum n4, n the speed ratios to the motor
    (exact fractions); and each mesh's tangential tooth load from the gears beyond it."""
    n2, n4 = Q(20, 50), Q(20, 50) * Q(15, 45)
    i1, i23, i4, alpha = Q(1, 100), Q(6, 100), Q(9, 100), Q(100)
    torque = (i1 + i23 * n2**2 + i4 * n4**2) * alpha + 20 * n4
    assert torque == Q(359, 75)  # 4.7867 N m
    sol = solve(load_scene(DRIVE))
    assert sol.value("torque", ()) == pytest.approx(float(torque), rel=1e-9)
    # the drum's gear: its tooth load along the tangent (i4 alpha4 + 20) / r4, r4 = 90 mm
    t4 = (i4 * alpha * n4 + 20) / Q(9, 100)
    drum = next(c for c in sol.forces.contacts if c.wheel == "O4-C")
    assert abs(drum.tangential) == pytest.approx(float(t4), rel=1e-9)


SERIES = HERE / "ghosh_mallik_train_two_planets_in_series.toml"


def test_two_planets_in_series_by_the_tabular_method():
    """S (25) fixed, P1 (25) and P2 (15) on the arm, R (65): the train value with the arm
    fixed e = (-25/25)(-25/15)(15/65); each speed by Willis; the torques by the power balance
    and their sum; R's 50 N m through the teeth (the planets' moments) to S."""
    wa = Q(100)
    e_r, e_1, e_2 = Q(25, 65), Q(-25, 25), Q(25, 15)  # (omega - omega_a) / (0 - omega_a)
    wr, w1, w2 = (wa * (1 - e) for e in (e_r, e_1, e_2))
    t_arm = Q(50) * wr / wa
    held = -(t_arm - 50)
    assert (wr, w1, w2) == (Q(4000, 65), 200, Q(-200, 3))
    sol = solve(load_scene(SERIES))
    for key, w in (("O-R", wr), ("AP", w1), ("BQ", w2)):
        assert sol.W[key] == pytest.approx(float(w) * RPM, rel=REL)
    assert sol.value("torque", ()) == pytest.approx(float(t_arm), rel=1e-9)
    assert sol.value("Thold", ("O",)) == pytest.approx(float(held), rel=1e-9)
    # by the teeth: R's tangential load 50 / 0.13 passes P2 unchanged (its moments), then
    # P1 unchanged, and S takes it at 0.05 m: 50 x 0.05 / 0.13 = 19.23 N m
    assert float(held) == pytest.approx(50 * 0.05 / 0.13, rel=1e-12)


IDLER = HERE / "shigley_idler_gear_shaft_force.toml"


@pytest.mark.parametrize("phi", [20, 14.5])
def test_the_idlers_shaft_force_by_hand(phi, tmp_path):
    """W_t = 20 / 0.0375 at both meshes, W_r = W_t tan phi; on the idler from the pinion at
    its left (W_r, -W_t), from gear 4 above it (W_t, -W_r): the shaft takes their sum back.
    The pressure angle stated once for the table (``[rolling] pressure_angle``)."""
    import math

    text = IDLER.read_text(encoding="utf-8").replace(
        "pressure_angle = 20 ", f"pressure_angle = {phi} "
    )
    f = tmp_path / "idler.toml"
    f.write_text(text.split("[answers]")[0], encoding="utf-8")
    sol = solve(load_scene(f))
    wt = 20 / 0.0375
    wr = wt * math.tan(math.radians(phi))
    shaft = -(wr + wt), wt + wr  # the frame's force on the idler at O3
    o3 = next(p for p in sol.forces.pins if p.point == "O3")
    assert o3.force[0] == pytest.approx(shaft[0], rel=1e-12)
    assert o3.force[1] == pytest.approx(shaft[1], rel=1e-12)
    for c in sol.forces.contacts:
        assert c.load == pytest.approx(wt / math.cos(math.radians(phi)), rel=1e-12)
        assert c.stated  # the table's pressure angle is stated, not the default
    assert sol.value("torque", ()) == pytest.approx(-wt * 0.025, rel=1e-12)
