"""A friction drive: two wheels pressed together by a stated preload, gripping by friction
(``[rolling]`` ``preload``, ``friction``), and a wheel on a line with its friction stated.

References, each independent of the tool:

- the closed form of the book: the largest torque the grip passes to a wheel of radius r is
  ``T_max = mu P r``, the largest power ``mu P v`` (v the pitch line's speed, omega R for
  the driving gear of radius R turning at omega);
- a hand-worked pair: a couple of 12 N m on the driven wheel of radius 150 mm needs
  12 / 0.15 = 80 N at the contact; mu P = 0.3 x 500 = 150 N: it holds with 70 N to spare;
  30 N m needs 200 N: it slips, 50 N short;
- the matrix method at 30 digits (every moving body's Newton-Euler equations as one linear
  system, written here by hand: the preload a known pair of forces along the line of
  centres, the grip's tangential force one unknown along the common tangent) on a wheel
  that drives a slider through a rod, at several angles, at the sweep's worst angle and on
  either side of it;
- on a line, the same matrix method's ground force split along and across the line; a ring
  pressed by its planet (pushed outwards) the same; a planet on a fixed sun passes no power
  (its contact does not move).
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import pytest

from polygon_method.cli import main
from polygon_method.common.errors import SceneError
from polygon_method.forces import FRAME, force_value
from polygon_method.linkage.summary import summarize
from polygon_method.motion.solution import solve
from polygon_method.scene import parse_scene

from test_forces_rolling import Matrix, _driving_wheel, _wheel_matrix

ROOT = Path(__file__).resolve().parent.parent

PAIR = """
title = "Two friction wheels pressed together"
units = "mm"
[ground]
O1 = [0, 0]
O2 = [{d}, 0]
[links]
"O1-A" = {R}
"O2-B" = {r}
[rolling]
"O2-B" = {{ on = "O1-A", preload = "{P} N", friction = {mu} }}
[input]
crank = "O1-A"
angle = 0
speed = "{rpm} rpm ccw"
[loads]
"O2-B" = {{ torque = "{M} N m cw" }}
"""


def _pair(P=500, mu=0.3, R=100, r=150, rpm=300, M=12):
    return PAIR.format(d=R + r, R=R, r=r, P=P, mu=mu, rpm=rpm, M=M)


@pytest.mark.parametrize(
    "P, mu, R, r, rpm",
    [(500, 0.3, 100, 150, 300), (2000, 0.25, 60, 240, 1450), (80, 0.6, 90, 30, 50)],
)
def test_the_largest_torque_and_power_are_the_books_closed_form(P, mu, R, r, rpm):
    """T_max = mu P r on the wheel, mu P R on the gear; P_max = mu P omega R."""
    sol = solve(parse_scene(_pair(P, mu, R, r, rpm, M=0.001)))
    f = sol.forces
    omega = rpm * 2 * math.pi / 60
    want = {
        ("Tmax", "O2-B"): mu * P * r / 1000,
        ("Tmax", "O1-A"): mu * P * R / 1000,
        ("Pmax", "O2-B"): mu * P * omega * R / 1000,
    }
    for (kind, body), v in want.items():
        assert force_value(f, kind, body) == pytest.approx(v, rel=1e-12), (kind, body)
    (c,) = sol.to_dict()["forces"]["contacts"].values()
    assert c["max_torque"] == pytest.approx(want[("Tmax", "O2-B")], rel=1e-12)
    assert c["max_torque_on_base"] == pytest.approx(want[("Tmax", "O1-A")], rel=1e-12)
    assert c["max_power"] == pytest.approx(want[("Pmax", "O2-B")], rel=1e-12)
    assert c["preload"] == P and c["friction"] == mu and c["normal_force"] == P


@pytest.mark.parametrize(
    "M, T, margin, words",
    [
        (12, 80.0, 70.0, "holds with a margin of 70 N"),
        (30, 200.0, -50.0, "slips (it needs 50 N more"),
    ],
)
def test_the_hand_worked_pair_holds_or_slips_in_every_view(tmp_path, capsys, M, T, margin, words):
    scene = tmp_path / "pair.toml"
    scene.write_text(_pair(M=M) + '[answers]\nTmax_O2B = "22.5 N m"\nPmax_O2B = "471 W"\n')
    sol = solve(parse_scene(scene.read_text()))
    (c,) = sol.forces.contacts
    assert abs(c.tangential) == pytest.approx(T, rel=1e-12)
    assert main(["solve", str(scene)]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert words in out and "mu N = 0.3 x 500 N = 150 N" in out
    assert main(["solve", str(scene), "--json"]) == 0
    got = json.loads(capsys.readouterr().out)["forces"]["contacts"]["O2-B"]
    assert got["margin"] == pytest.approx(margin, rel=1e-12)
    assert got["slips"] is (margin < 0)
    assert got["required_friction"] == pytest.approx(T / 500, rel=1e-12)
    assert got["largest_tangential_force"] == pytest.approx(150.0, rel=1e-12)
    assert main(["steps", str(scene)]) == 0
    steps = " ".join(capsys.readouterr().out.split())
    assert words in steps and "pressed together with the preload" in steps
    assert main(["check", str(scene)]) == 0
    out = capsys.readouterr().out
    assert "2 of 2 right" in out, out


# ----- a wheel driving a slider through a rod, against the matrix method

DRIVE = """
title = "A friction wheel drives a slider"
units = "mm"
[ground]
O1 = [0, 0]
O2 = [250, 0]
[links]
"O1-A" = 100
"O2-B" = 150
BC = 450
[sliders]
C = { path = "horizontal", through = [250, 0] }
[rolling]
"O2-B" = { on = "O1-A", preload = "PRELOAD N", friction = 0.3, angle = WHEEL }
[input]
crank = "O1-A"
angle = ANGLE
speed = "300 rpm ccw"
[masses]
"O2-B" = { mass = 3, along = 40, gyration = 90 }
C = { mass = 2 }
BC = { mass = 1.5, along = 225 }
[gravity]
direction = 250
[loads]
C = { force = [-60, 0] }
"""


def _drive(angle, preload=500):
    """The drive at crank angle ``angle`` (deg), the wheel where the crank's turn from 0 puts
    it: 60 deg at 0, turning back R / r = 2/3 as far (its angle repeats every 3 turns)."""
    wheel = (60.0 - 2.0 * angle / 3.0) % 360.0
    text = DRIVE.replace("ANGLE", repr(angle % 360.0)).replace("WHEEL", repr(wheel))
    return parse_scene(text.replace("PRELOAD", str(preload)))


def _matrix(sol, preload):
    """The gear, the wheel, the rod and the block; the preload a known pair along the line of
    centres at the contact I, the grip's tangential force T along t = perp(m) one unknown."""
    P = sol.P
    m = (1.0, 0.0)  # from the gear towards the wheel's centre, O1 -> O2
    t = (-m[1], m[0])
    I = (0.1, 0.0)
    mat = Matrix(sol, ["O1-A", "O2-B", "BC", "block C"], {"C": "block C"})
    mat.pin("O1", P["O1"], "O1-A", FRAME)
    mat.pin("O2", P["O2"], "O2-B", FRAME)
    mat.pin("B", P["B"], "BC", "O2-B")
    mat.pin("C", P["C"], "BC", "block C")
    mat.along("N_C", P["C"], (0.0, 1.0), "block C", FRAME)
    mat.along("T", I, t, "O2-B", "O1-A")
    mat.couple("tau", "O1-A")
    mat.known("O2-B", (preload * m[0], preload * m[1]), I)
    mat.known("O1-A", (-preload * m[0], -preload * m[1]), I)
    return mat.solve()


@pytest.mark.parametrize("angle", [0.0, 130.0, 250.0])
def test_the_grip_against_the_matrix_method(angle):
    sol = solve(_drive(angle))
    f = sol.forces
    x = _matrix(sol, 500.0)
    scale = 500.0
    (c,) = f.contacts
    assert c.normal == 500.0
    assert c.tangential == pytest.approx(x["T"], abs=1e-9 * scale)
    assert f.input_torque == pytest.approx(x["tau"], abs=1e-9 * scale * 0.1)
    for name, on, by in (("O2", "O2-B", FRAME), ("B", "BC", "O2-B"), ("C", "BC", "block C")):
        got = f.pin(name, on, by)
        assert got[0] == pytest.approx(x[name + ".x"], abs=1e-9 * scale), name
        assert got[1] == pytest.approx(x[name + ".y"], abs=1e-9 * scale), name
    d = sol.to_dict()["forces"]["contacts"]["O2-B"]
    assert d["margin"] == pytest.approx(0.3 * 500.0 - abs(x["T"]), abs=1e-9 * scale)


@pytest.mark.parametrize("preload, holds", [(600, True), (500, False)])
def test_the_sweep_summary_names_the_worst_angle(preload, holds):
    """The summary's least margin and its angle: the matrix method's margin there agrees to
    1e-9, and is no larger than a tenth of a degree on either side (the worst angle)."""
    sc = _drive(0.0, preload)
    s = summarize(sc)
    (e,) = [e for e in s.extremes if e.name == "grip_O2-B"]
    note = next(n for n in s.notes if n.startswith("the grip of O2-B"))
    assert ("holds over the range" in note) is holds and ("slips" in note) is (not holds)
    assert (e.minimum >= 0) is holds

    def margin(deg):
        sol = solve(_drive(deg, preload))
        return 0.3 * preload - abs(_matrix(sol, float(preload))["T"])

    worst = margin(e.at_min)
    assert e.minimum == pytest.approx(worst, abs=1e-9 * preload)
    assert margin(e.at_min - 0.1) >= worst and margin(e.at_min + 0.1) >= worst


def test_a_wheel_on_a_line_with_its_friction_stated():
    """The driving wheel on level ground, friction = 0.3: the ground's push N and grip T from
    the matrix method (the contact's two unknowns), the margin mu N - |T|, the words."""
    sol = solve(_driving_wheel_with("friction = 0.3"))
    (c,) = sol.forces.contacts
    x = _wheel_matrix(sol, "torque")
    N, T = x["I.y"], x["I.x"]
    scale = math.hypot(N, T)
    d = sol.to_dict()["forces"]["contacts"]["CA"]
    assert d["margin"] == pytest.approx(0.3 * N - abs(T), abs=1e-9 * scale)
    assert d["normal_pressing"] == pytest.approx(N, abs=1e-9 * scale)
    assert d["max_torque"] == pytest.approx(0.3 * N * 0.3, abs=1e-9 * scale)  # r = 300 mm
    assert d["max_power"] is None and "preload" not in d
    words = c.grip_words()
    assert ("holds with a margin" in words) is (0.3 * N >= abs(T))


def _driving_wheel_with(extra):
    text = _driving_wheel()._text
    assert 'CA = { on = "horizontal", through = [0, 0], angle = 135 }' in text
    text = text.replace(
        'CA = { on = "horizontal", through = [0, 0], angle = 135 }',
        f'CA = {{ on = "horizontal", through = [0, 0], angle = 135, {extra} }}',
    )
    return parse_scene(text)


# ----- bad input: one line naming the file and the key, exit 2


@pytest.mark.parametrize(
    "spec, words",
    [
        ('{ on = "O1-A", preload = "500 N", friction = 1.5 }', "friction = 1.5: the coefficient"),
        ('{ on = "O1-A", preload = "500 N", friction = 0 }', "above 0 and below 1"),
        ('{ on = "O1-A", preload = "500 N", friction = "a lot" }', "friction = 'a lot'"),
        ('{ on = "O1-A", preload = "-5 N", friction = 0.3 }', "the force pressing the wheels"),
        ('{ on = "O1-A", preload = "5 m", friction = 0.3 }', "not of force"),
        ('{ on = "O1-A", friction = 0.3 }', "give the force pressing them"),
        ('{ on = "O1-A", preload = "500 N", pressure_angle = 20 }', "remove pressure_angle"),
        ('{ on = "O1-A", preload = "500 N", frction = 0.3 }', "unknown key 'frction'"),
    ],
)
def test_bad_grips_are_one_located_line(tmp_path, capsys, spec, words):
    text = re.sub(r'"O2-B" = \{ on = "O1-A".*\}', lambda _: f'"O2-B" = {spec}', _pair())
    scene = tmp_path / "bad.toml"
    scene.write_text(text)
    assert main(["solve", str(scene)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "bad.toml" in err and "[rolling] O2-B" in err, err
    assert words in err, err


def test_a_preload_on_a_line_and_bad_drive_keys_are_refused(tmp_path, capsys):
    with pytest.raises(SceneError, match="a wheel on a line is pressed on it") as e:
        _driving_wheel_with('preload = "100 N"')
    assert "\n" not in str(e.value)
    for key, words in (
        ('Pmax_CA = "1 W"', "not on a line"),
        ('Tmax_AB = "1 N m"', "AB is no wheel of a friction drive"),
    ):
        text = _driving_wheel_with("friction = 0.3")._text + f"\n[answers]\n{key}\n"
        scene = tmp_path / "bad.toml"
        scene.write_text(text)
        assert main(["check", str(scene)]) == 2
        err = capsys.readouterr().err.strip()
        assert "\n" not in err and words in err and "bad.toml" in err, err


def test_a_ring_pressed_by_its_planet_against_the_matrix_method():
    """The ring (an internal gear) about O gripped by the planet inside it with a preload of
    300 N, the planet toothed on the fixed sun: the preload pushes the planet towards its own
    centre and the ring outwards; the ring's grip T one unknown along the tangent."""
    from test_forces_rolling import DEG20, _teeth, _unit, _with

    sc = _with(
        ROOT / "worked_problems" / "ring_gear_output.toml",
        {
            "OA": {"mass": 1, "along": 30},
            "AP": {"mass": 0.5, "along": 0, "gyration": 14},
            "O-Q": {"mass": 3, "along": 0, "gyration": 70},
            "Q-B": {"mass": 1, "along": 75, "gyration": 45},
            "B": {"mass": 2},
        },
        {"B": {"force": [-150, 20]}},
        rolling={"O-Q": {"preload": "300 N", "friction": 0.35}},
    )
    sol = solve(sc)
    f = sol.forces
    P = sol.P
    O, A = P["O"], P["A"]
    u = _unit((A[0] - O[0], A[1] - O[1]))
    sun = ("tooth sun", (O[0] + 0.040 * u[0], O[1] + 0.040 * u[1]), (-u[1], u[0]), u, "AP")
    m = (-u[0], -u[1])  # from the ring's pitch point towards the planet's centre
    I = (A[0] + 0.020 * u[0], A[1] + 0.020 * u[1])

    def build():
        mat = Matrix(sol, ["OA", "AP", "O-Q", "Q-B", "block B"], {"B": "block B"})
        mat.pin("O", O, "OA", FRAME)
        mat.pin("OQ", O, "O-Q", FRAME)
        mat.pin("A", A, "AP", "OA")
        mat.pin("Q", P["Q"], "Q-B", "O-Q")
        mat.pin("B", P["B"], "Q-B", "block B")
        mat.along("N_B", P["B"], (0.0, 1.0), "block B", FRAME)
        mat.along("T ring", I, (-m[1], m[0]), "AP", "O-Q")
        mat.known("AP", (300.0 * m[0], 300.0 * m[1]), I)
        mat.known("O-Q", (-300.0 * m[0], -300.0 * m[1]), I)
        mat.couple("T", "OA")
        return mat

    x = _teeth(build, [(*sun, FRAME, DEG20)])
    scale = max(math.hypot(x[k + ".x"], x[k + ".y"]) for k in ("O", "OQ", "A", "Q", "B"))
    on_ring = {c.wheel: c for c in f.contacts}["O-Q"]
    Tr = x["T ring"]
    want = (-(300.0 * m[0] - Tr * m[1]), -(300.0 * m[1] + Tr * m[0]))  # on the ring
    assert math.dist(on_ring.force, want) <= 1e-9 * scale
    assert math.dist(f.pin("O", "O-Q", FRAME), (x["OQ.x"], x["OQ.y"])) <= 1e-9 * scale
    assert abs(f.input_torque - x["T"]) <= 1e-9 * scale * 0.1
    d = sol.to_dict()["forces"]["contacts"]["O-Q"]
    assert d["normal_pressing"] == 300.0 and d["normal_force"] == -300.0  # pushed outwards
    assert d["margin"] == pytest.approx(0.35 * 300.0 - abs(Tr), abs=1e-9 * scale)


def test_a_planet_on_a_fixed_circle_passes_no_power(tmp_path, capsys):
    text = (ROOT / "worked_problems" / "rolling_epicyclic.toml").read_text().split("[answers]")[0]
    text = text.replace(
        'AP = { on = "O", on_radius = 60, angle = 30 }',
        'AP = { on = "O", on_radius = 60, angle = 30, preload = "200 N", friction = 0.4 }',
    )
    assert "preload" in text
    scene = tmp_path / "planet.toml"
    scene.write_text(text + '[answers]\nPmax_AP = "0 W"\nTmax_AP = "3.2 N m"\n')
    sol = solve(parse_scene(scene.read_text()))
    assert force_value(sol.forces, "Pmax", "AP") == 0.0
    r = 0.040  # AP = 40 mm, the planet's radius
    assert force_value(sol.forces, "Tmax", "AP") == pytest.approx(0.4 * 200 * r, rel=1e-12)
    assert main(["check", str(scene)]) == 0
    assert "2 of 2 right" in capsys.readouterr().out
    assert main(["solve", str(scene)]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "with the fixed circle" in out and "no power passes" in out


def test_the_worked_friction_drive():
    """worked_problems/friction_drive.toml: its closed-form answers right; the margin it
    quotes at the instant and at the sweep's worst angle, each the matrix method's there."""
    path = ROOT / "worked_problems" / "friction_drive.toml"
    text = path.read_text()
    assert main(["check", str(path)]) == 0

    def posed(deg):
        wheel = (60.0 - 2.0 * deg / 3.0) % 360.0
        t = text.replace(
            'preload = "500 N", friction = 0.3, angle = 60',
            (f'preload = "500 N", friction = 0.3, angle = {wheel!r}'),
        )
        return solve(parse_scene(t.replace("angle = 0\n", f"angle = {deg % 360.0!r}\n")))

    def margin(sol):
        return 150.0 - abs(_matrix(sol, 500.0)["T"])

    sol = posed(0.0)
    assert margin(sol) == pytest.approx(138.3, abs=0.05)  # as the file says
    (c,) = sol.forces.contacts
    assert 150.0 - abs(c.tangential) == pytest.approx(margin(sol), abs=1e-9 * 500)
    (e,) = [e for e in summarize(parse_scene(text)).extremes if e.name == "grip_O2-B"]
    assert e.at_min == pytest.approx(792.06, abs=0.01) and e.minimum == pytest.approx(
        0.72, abs=0.005
    )
    assert e.minimum == pytest.approx(margin(posed(e.at_min)), abs=1e-9 * 500)
