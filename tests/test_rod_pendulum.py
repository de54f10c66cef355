"""A connecting rod's moment of inertia from its swing as a compound pendulum ([masses]
``oscillations = "21 in 40 s"`` or ``period``, with ``about`` an end or ``pivot_distance``):
``k_G^2 = g h T^2 / (4 pi^2) - h^2`` worked here at 40 digits; the engine's inertia torque
with it to the books' equivalent dynamical system (two masses at the pins and the
correction couple, ``test_textbook_forces._equivalent_system``); Khurmi's rod hung from a
point off its pins; every view; the impossible swing and the bad keys in one line."""

from __future__ import annotations

from pathlib import Path

import mpmath
import pytest
from mpmath import mpf

import test_textbook_forces as corpus
from polygon_method import load_scene, parse_scene, solve
from polygon_method.cli import main

HERE = Path(__file__).resolve().parent / "textbook"
ENGINE = HERE / "force_engine_rod_swung_as_pendulum.toml"
NAME = ENGINE.stem


def _k(h, T, g="9.81"):
    mpmath.mp.dps = 40
    h, T, g = mpf(h), mpf(T), mpf(g)
    return mpmath.sqrt(g * h * T**2 / (4 * mpmath.pi**2) - h**2)


def test_the_rods_gyration_from_its_swing():
    k = _k("0.6", mpf(40) / 21)
    sc = load_scene(ENGINE)
    rod = next(m for m in sc.masses if m.body == "AB")
    assert rod.inertia == pytest.approx(float(60 * k**2), rel=1e-12)
    assert float(k) == pytest.approx(0.4254, abs=5e-5)  # the file's hand figure
    assert "from its swing" in rod.how
    assert any("swinging about B" in n and "I_G = I_pivot - m h^2" in n for n in sc.reading_notes)


def test_the_inertia_torque_by_the_equivalent_dynamical_system(monkeypatch):
    """The rod (60 kg, G 400 mm from A, k from the swing) as 24 kg at B and 36 kg at A with
    the correction couple; the piston 80 kg; 300 rpm cw, 40 deg past the i.d.c."""
    k = _k("0.6", mpf(40) / 21)
    entry = (250, 1000, 300, -1, 40, 60, 400, k * 1000, 80, 0, 0)
    monkeypatch.setitem(corpus.HEAVY_RODS, NAME, entry)
    turning, _, sg = corpus._equivalent_system(NAME)
    sol = solve(load_scene(ENGINE))
    want = -sg * turning
    assert sol.forces.input_torque == pytest.approx(float(want), rel=1e-9)
    answer = next(a for a in sol.scene.answers if a.key == "torque")
    assert float(answer.value) == pytest.approx(float(want), rel=1e-3)


KHURMI = """units = "mm"
[ground]
O = [0, 0]
[links]
OA = 200
AB = 850
[sliders]
B = {{ path = "horizontal", through = "O" }}
[input]
crank = "OA"
angle = 30
speed = "200 rpm ccw"
[masses]
AB = {{ mass = "37.5 kg", along = 625, from = "B", {swing} }}
"""


@pytest.mark.parametrize(
    "swing, h, T",
    [
        ('period = "1.87 s", pivot_distance = 650', "0.65", "1.87"),
        ('oscillations = "20 in 37.4 s", pivot_distance = 650', "0.65", "1.87"),
        ('period = 1.6, about = "A"', "0.225", "1.6"),
    ],
)
def test_khurmis_rod_hung_from_a_point_off_its_pins(swing, h, T):
    """Khurmi's rod of 37.5 kg hung 650 mm above its G (25 mm above the small end's
    centre), its period 1.87 s: k_G = 0.377 m, the book's; or swung about its big end."""
    sc = parse_scene(KHURMI.format(swing=swing))
    rod = next(m for m in sc.masses if m.body == "AB")
    k = _k(h, T)
    assert rod.inertia == pytest.approx(float(mpf("37.5") * k**2), rel=1e-12)
    if h == "0.65":
        assert float(k) == pytest.approx(0.377, abs=5e-4)  # the book: 0.377 m


def test_every_view(capsys, tmp_path):
    for args in (
        ["solve", ENGINE],
        ["solve", ENGINE, "--json"],
        ["steps", ENGINE],
        ["check", ENGINE],
        ["sweep", ENGINE, "--summary"],
        ["draw", ENGINE, "--forces", "-o", tmp_path / "f.svg"],
    ):
        assert main([str(a) for a in args]) == 0, args
    out = capsys.readouterr().out
    assert "swinging about B (|BG| = 0.6 m) as a compound pendulum" in out


@pytest.mark.parametrize(
    "swing, words",
    [
        ('period = "1 s", about = "B"', "quicker than a point mass's at G"),
        ('period = "1.9 s"', "the point it swings about"),
        ('period = "1.9 s", about = "C"', "about = 'C': an end of AB"),
        ('period = "1.9 s", about = "B", gyration = 200', "gyration: not with the swing"),
        ('oscillations = "twenty", about = "B"', "oscillations = 'twenty'"),
        ('period = "1.9 s", oscillations = "20 in 38 s", about = "B"', "one of them"),
        ('period = "-2 s", about = "B"', "period = '-2 s': a time"),
    ],
)
def test_a_bad_swing_is_one_line(tmp_path, capsys, swing, words):
    text = ENGINE.read_text(encoding="utf-8").replace(
        'oscillations = "21 in 40 s", about = "B"', swing
    )
    bad = tmp_path / "bad.toml"
    bad.write_text(text, encoding="utf-8")
    assert main(["solve", str(bad)]) == 2
    err = capsys.readouterr().err
    assert words in err and len(err.strip().splitlines()) == 1, err


BOTH = HERE / "force_engine_rod_swung_about_both_ends.toml"


def test_the_rod_swung_about_both_ends_places_its_centre(monkeypatch):
    """Khurmi's oil-engine rod: both swings give k^2 = c h - h^2 with the knife-edges 37.5 and
    60 mm beyond the centres; h1 = S (c2 - S) / (c1 + c2 - 2 S) solved here at 40 digits: G
    706.0 mm from the small end, I = 6.850 kg m^2; the engine's torque by the equivalent
    dynamical system."""
    mpmath.mp.dps = 40
    g = mpf("9.81")
    c1, c2 = (g * T**2 / (4 * mpmath.pi**2) for T in (mpf("1.9"), mpf("1.65")))
    S = 1 + mpf("0.0375") + mpf("0.06")
    # the two equations solved by mpmath's root finder, not the closed form
    h1 = mpmath.findroot(lambda h: (c1 * h - h**2) - (c2 * (S - h) - (S - h) ** 2), 0.7)
    x = h1 - mpf("0.0375")  # G from the small end's centre B
    k2 = c1 * h1 - h1**2
    sc = load_scene(BOTH)
    rod = next(m for m in sc.masses if m.body == "AB")
    assert rod.inertia == pytest.approx(float(60 * k2), rel=1e-12)
    assert 1 - rod.lam == pytest.approx(float(x), rel=1e-12)  # lam from A
    assert float(x) == pytest.approx(0.706, abs=5e-4) and float(60 * k2) == pytest.approx(
        6.85, abs=5e-3
    )
    entry = (250, 1000, 300, -1, 40, 60, (1 - x) * 1000, mpmath.sqrt(k2) * 1000, 80, 0, 0)
    monkeypatch.setitem(corpus.HEAVY_RODS, BOTH.stem, entry)
    turning, _, sg = corpus._equivalent_system(BOTH.stem)
    sol = solve(sc)
    assert sol.forces.input_torque == pytest.approx(float(-sg * turning), rel=1e-9)
    assert main(["check", str(BOTH)]) == 0


@pytest.mark.parametrize(
    "swings, words",
    [
        ('swings = { B = "100 in 190 s" }', "the swing about each end of AB, both"),
        ('swings = { B = "100 in 100 s", A = "100 in 165 s" }', "put no centre of mass"),
        ('swings = { B = "1.9 s", A = "1.65 s" }, along = 300', "along: not with swings"),
        ("knife_edge = { B = 37.5 }", "knife_edge goes with swings"),
    ],
)
def test_bad_swings_are_one_line(tmp_path, capsys, swings, words):
    text = BOTH.read_text(encoding="utf-8").replace(
        'swings = { B = "100 in 190 s", A = "100 in 165 s" }, knife_edge = { B = 37.5, A = 60 }',
        swings,
    )
    bad = tmp_path / "bad.toml"
    bad.write_text(text, encoding="utf-8")
    assert main(["solve", str(bad)]) == 2
    err = capsys.readouterr().err
    assert words in err and len(err.strip().splitlines()) == 1, err
