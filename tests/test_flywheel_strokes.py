"""A turning-moment diagram stated by its strokes' works (``[turning_moment] strokes``): the
books' "the work done by the gases during the expansion stroke is three times the work done
on them during compression, the suction and exhaust negligible; each stroke's diagram a
triangle". Held to the closed forms worked here at 40 digits: the net work of a cycle from
the power and the speed, the strokes' works in proportion, the mean torque, and dE_max =
W_k (1 - T_mean / h)^2 for the one lobe above the mean (h = 2 W_k / pi the triangle's peak:
the part above the mean line is a similar triangle); every view; the bad tables in one
line."""

from __future__ import annotations

from pathlib import Path

import mpmath
import pytest
from mpmath import mpf

from polygon_method.cli import main
from polygon_method.forces.flywheel_cycle import solve_cycle
from polygon_method.scene.energy import cycle_from_text

HERE = Path(__file__).resolve().parent / "textbook" / "flywheel"
GAS = HERE / "strokes_expansion_three_times_compression.toml"
REL = 1e-9


def _solve(text):
    return solve_cycle(cycle_from_text(text, "t.toml"))


def _run(capsys, *args):
    code = main([str(a) for a in args])
    out = capsys.readouterr()
    return code, out.out, out.err


def test_khurmis_gas_engine_by_the_closed_form():
    """20 kW at 300 rpm, four-stroke, W_e = 3 W_c: W = 8000 J, W_e = 12000 J, dE_max =
    12000 (11/12)^2 = 10083.3 J; Cs = 0.04: I = dE_max / (w^2 Cs)."""
    mpmath.mp.dps = 40
    w = 300 * 2 * mpmath.pi / 60
    W = 20000 * 4 * mpmath.pi / w  # the power over the time of two turns
    We = 3 * W / 2  # 3 W_c - W_c = W
    mean, peak = W / (4 * mpmath.pi), 2 * We / mpmath.pi
    dE = We * (1 - mean / peak) ** 2
    c = solve_cycle(cycle_from_text(GAS.read_text(encoding="utf-8"), str(GAS)))
    assert c.form == "strokes"
    assert c.T_mean == pytest.approx(float(mean), rel=REL)
    assert c.dE_max == pytest.approx(float(dE), rel=REL)
    assert float(dE) == pytest.approx(12000 * 121 / 144, rel=1e-30)
    assert c.inertia == pytest.approx(float(dE / (w**2 * mpf("0.04"))), rel=REL)
    # the energy least where the expansion's triangle rises through the mean, greatest where
    # it falls through it: 360 + 90 mean / peak and 540 - 90 mean / peak deg
    at = {x.letter: x.angle for x in c.crossings[:-1]}  # (the last is a, a cycle on)
    assert mpmath.degrees(at["a"]) == pytest.approx(float(360 + 90 * mean / peak), rel=REL)
    assert mpmath.degrees(at["b"]) == pytest.approx(float(540 - 90 * mean / peak), rel=REL)


AREAS = HERE / "strokes_four_triangles_areas.toml"


def test_khurmis_four_triangles_of_given_areas_by_the_closed_form():
    """The areas -0.45, -1.7, 6.8, -0.65 (1e-3 m^2) at 3 MJ per m^2: W_e = 20400 J, the net
    12000 J; one lobe above the mean: dE_max = W_e (1 - T_mean / h)^2; 200 rpm, Cs 0.02,
    the rim at 1.2 m: the book's 1386 kg."""
    mpmath.mp.dps = 40
    We, W = mpf(20400), mpf(-1350 - 5100 + 20400 - 1950)
    mean, peak = W / (4 * mpmath.pi), 2 * We / mpmath.pi
    dE = We * (1 - mean / peak) ** 2
    w = 200 * 2 * mpmath.pi / 60
    I = dE / (w**2 * mpf("0.02"))
    c = solve_cycle(cycle_from_text(AREAS.read_text(encoding="utf-8"), str(AREAS)))
    assert c.T_mean == pytest.approx(float(mean), rel=REL)
    assert c.dE_max == pytest.approx(float(dE), rel=REL)
    assert c.inertia == pytest.approx(float(I), rel=REL)
    assert c.mass == pytest.approx(float(I / mpf("1.44")), rel=REL)
    assert float(I / mpf("1.44")) == pytest.approx(1386, rel=1e-3)  # the book's


def test_the_strokes_areas_in_mm2_with_the_diagrams_scales():
    """The same diagram drawn at 1 mm = 100 N m and 1 mm = 3 deg: 1 mm^2 = 5.236 J."""
    text = AREAS.read_text(encoding="utf-8")
    per = 100 * 3 * float(mpmath.pi) / 180
    mm2 = [x / per for x in (-1350, -5100, 20400, -1950)]
    other = text.replace(
        "strokes = [-0.45e-3, -1.7e-3, 6.8e-3, -0.65e-3]   # m^2, above the zero line positive",
        f"strokes = [{', '.join(repr(x) for x in mm2)}]",
    ).replace(
        'area_scale = "1 m^2 = 3 MN m"',
        'area_unit = "mm^2"\ntorque_scale = "1 mm = 100 N m"\nangle_scale = "1 mm = 3 deg"',
    )
    a, b = _solve(text), _solve(other)
    assert b.dE_max == pytest.approx(a.dE_max, rel=1e-12)


STEAM = """title = "Double-acting steam engine, each stroke a triangle"
[turning_moment]
strokes = [1, 1]
{given}
[flywheel]
speed = "120 rpm"
coefficient = 0.02
"""


@pytest.mark.parametrize("given", ['work = "6 kJ"', 'power = "12 kW"'])
def test_a_double_acting_steam_engine_by_the_closed_form(given):
    """Two equal triangles a turn: T_mean = W_k / pi, h = 2 W_k / pi, so the part above the
    mean is a quarter of each: dE_max = W_k / 4 (12 kW at 120 rpm is 6 kJ a turn)."""
    mpmath.mp.dps = 40
    c = _solve(STEAM.format(given=given))
    Wk = mpf(3000)
    assert c.T_mean == pytest.approx(float(Wk / mpmath.pi), rel=REL)
    assert c.dE_max == pytest.approx(float(Wk / 4), rel=REL)
    w = 120 * 2 * mpmath.pi / 60
    assert c.inertia == pytest.approx(float(Wk / 4 / (w**2 * mpf("0.02"))), rel=REL)


def test_the_strokes_works_given_as_energies_are_the_same_diagram():
    text = GAS.read_text(encoding="utf-8")
    given = text.replace("strokes = [0, -1, 3, 0]", 'strokes = ["0 J", "-4 kJ", "12 kJ", "0 J"]')
    given = given.replace('power = "20 kW"\n', "")
    a, b = _solve(text), _solve(given)
    assert b.dE_max == pytest.approx(a.dE_max, rel=1e-12)
    assert b.T_mean == pytest.approx(a.T_mean, rel=1e-12)


def test_every_view_reads_it(capsys, tmp_path):
    code, out, _ = _run(capsys, "solve", GAS)
    assert code == 0
    assert "the strokes' works in proportion 0 : -1 : 3 : 0 (net 2): 0 J, -4000 J, 12000 J" in out
    assert "W = P Theta / w = 20000 x 12.5664 / 31.4159 = 8000 J" in out
    code, out, _ = _run(capsys, "steps", GAS)
    assert code == 0 and "each stroke's work, a triangle on its half turn" in out
    code, out, _ = _run(capsys, "solve", GAS, "--json")
    assert code == 0 and '"form": "strokes"' in out
    assert _run(capsys, "sweep", GAS, "--summary")[0] == 0
    assert _run(capsys, "sweep", GAS, "--csv", tmp_path / "s.csv", "--steps", "8")[0] == 0
    rows = (tmp_path / "s.csv").read_text().splitlines()
    # the expansion's peak at mid-stroke, 2 x 12000 / pi N m, at 450 deg
    assert float(rows[6].split(",")[1]) == pytest.approx(24000 / float(mpmath.pi), rel=REL)
    assert _run(capsys, "draw", GAS, "-o", tmp_path / "d.svg")[0] == 0
    assert _run(capsys, "page", GAS, "-o", tmp_path / "p.html")[0] == 0
    answers = tmp_path / "a.toml"
    answers.write_text('[answers]\nI_flywheel = "510.8 kg m^2"\n', encoding="utf-8")
    code, out, _ = _run(capsys, "check", GAS, answers)
    assert code == 1 and "mistake" in out  # the range either side taken for Cs: twice


@pytest.mark.parametrize(
    "old, new, words",
    [
        ("strokes = [0, -1, 3, 0]", "strokes = [0, -1, 3]", "3 strokes of half a turn"),
        ("strokes = [0, -1, 3, 0]", "strokes = [0, -3, 1, 0]", "add up to -2"),
        ('power = "20 kW"', "", "need the net work of a cycle"),
        ('power = "20 kW"', 'power = "20 kW"\nwork = "8 kJ"', "one of them"),
        ("strokes = [0, -1, 3, 0]", 'strokes = [0, "-1", 3, 0]', "strokes = [0, -1, 3, 0]"),
        ('cycle = "4-stroke"', 'cycle = "4-stroke"\nshape = "sine"', "shape = 'sine'"),
        ('speed = "300 rpm"', 'inertia = "40 kg m^2"', "power needs the mean speed"),
        ("strokes = [0, -1, 3, 0]", "strokes = [0, -1, 3, 0]\nareas = [1, -1]", "one of them"),
        ('power = "20 kW"', 'area_scale = "1 m^2 = 3 MN"', "'MN' is a unit of force"),
        ('power = "20 kW"', 'area_scale = "3 MN m"', "area_scale = '3 MN m'"),
        ('cycle = "4-stroke"', 'cycle = "4-stroke"\narea_scale = "1 m^2 = 3 MJ"', "power: not"),
        ('power = "20 kW"', 'area_unit = "J"', "area_unit = 'J'"),
    ],
)
def test_a_bad_strokes_table_is_one_line(tmp_path, capsys, old, new, words):
    text = GAS.read_text(encoding="utf-8").replace(old, new)
    if 'inertia = "40' in text:
        text = text.replace('plus_minus = "2%"\n', "")
    bad = tmp_path / "bad.toml"
    bad.write_text(text, encoding="utf-8")
    code, out, err = _run(capsys, "solve", bad)
    assert code == 2 and words in err, err
    assert len(err.strip().splitlines()) == 1


def test_readings_that_stop_before_the_cycle_are_refused(tmp_path, capsys):
    """Readings to 180 deg in a cycle of 360: beyond the last one the segments' torque was
    extended along the last segment (-90 N m at 360 deg in the CSV and the drawing) while
    the energies took it as nought; now one line asks for the readings to the cycle's end."""
    f = tmp_path / "t.toml"
    f.write_text(
        '[turning_moment]\nangle = [0, 60, 180]\ntorque = [0, 60, 0]\ncycle = "360 deg"\n'
        '[flywheel]\nspeed = "600 rpm"\ncoefficient = 0.02\n',
        encoding="utf-8",
    )
    code, _, err = _run(capsys, "solve", f)
    assert code == 2 and "the readings end at 180 deg, before the cycle's 360 deg" in err
    assert len(err.strip().splitlines()) == 1
    f.write_text(
        f.read_text()
        .replace("[0, 60, 180]", "[0, 60, 180, 360]")
        .replace("[0, 60, 0]", "[0, 60, 0, 0]"),
        encoding="utf-8",
    )
    c = solve_cycle(cycle_from_text(f.read_text(), str(f)))
    assert c.T_mean == pytest.approx(0.5 * 60 * float(mpmath.pi) / (2 * float(mpmath.pi)), rel=REL)
