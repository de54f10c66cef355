"""Friction with a coefficient of its own at each guide and each pin (``[friction] guides =
{ Q = 0.08, A = 0.2 }``, ``pins = { O = 0.05, ... }``): textbook problems whose slide, slot
and pins are each given their own, held to the matrix Newton-Euler method at 40 digits
(written here: nothing of the tool's solve), repeated until the friction settles, each pin's
and guide's friction with its own coefficient; the views a student reads; the bad tables
refused in one line."""

from __future__ import annotations

from pathlib import Path

import mpmath
import pytest
from mpmath import mpf

from newton_euler import NewtonEuler
from polygon_method import load_scene, solve
from polygon_method.cli import main
from polygon_method.common.errors import SceneError

HERE = Path(__file__).resolve().parent / "textbook"
REL = 1e-9
CRANK = HERE / "friction_each_slider_crank_pins.toml"
SHAPER = HERE / "friction_each_shaper_slot_and_ram.toml"


def _settled(build, names):
    """Solve ``build(previous)`` again with the friction of the forces found before (none
    at first) until the driver's torque settles to 1e-30."""
    x = last = None
    for _ in range(200):
        x = build(x)
        if last is not None and abs(last - x["T"]) < mpf(10) ** -30:
            return x
        last = x["T"]
    raise AssertionError("the friction did not settle")


def _size(x, name):
    return mpmath.hypot(x[name + ".x"], x[name + ".y"])


def _pin(sol, point):
    return next(p for p in sol.forces.pins if p.point == point).magnitude


def _crank_reference():
    """The slider crank: O (r 25 mm, mu 0.05), A (20 mm, 0.08), B (12.5 mm, 0.12), the
    guide 0.15; the crank 20 rad/s cw at 120 deg, 1.5 kN against the slider."""
    mpmath.mp.dps = 40
    r, l, th, w2 = mpf("0.08"), mpf("0.32"), mpmath.radians(120), mpf(-20)
    A = (r * mpmath.cos(th), r * mpmath.sin(th))
    B = (A[0] + mpmath.sqrt(l**2 - A[1] ** 2), mpf(0))
    vA = (-w2 * A[1], w2 * A[0])
    w3 = -vA[1] / (B[0] - A[0])  # B moves along the line of stroke
    vs = vA[0] - w3 * (B[1] - A[1])
    om = {"OA": w2, "AB": w3, "block": 0, "frame": 0}
    pins = [
        ("O", (0, 0), "OA", "frame", mpf("0.025"), mpf("0.05")),
        ("A", A, "AB", "OA", mpf("0.02"), mpf("0.08")),
        ("B", B, "AB", "block", mpf("0.0125"), mpf("0.12")),
    ]

    def build(x):
        ne = NewtonEuler(["OA", "AB", "block"], about={"block": B}, mp=True)
        for name, at, on, by, rad, mu in pins:
            ne.pin(name, at, on, by)
            if x is not None:
                c = -mu * rad * _size(x, name) * mpmath.sign(om[on] - om[by])
                ne.known(on, c=c)
                ne.known(by if by != "block" else "frame", c=-c)  # a block passes it on
        ne.along("N", B, (0, 1), "block", "frame")
        if x is not None:
            ne.known("block", (-mpf("0.15") * abs(x["N"]) * mpmath.sign(vs), 0), B)
        ne.known("block", (mpf(-1500), 0), B)
        ne.couple("T", "OA", "frame")
        return ne.solve()

    return _settled(build, ())


def _shaper_reference():
    """The shaper: the ram's guide 0.08, the slot 0.2 (the crank 1 rad/s ccw at 30 deg)."""
    mpmath.mp.dps = 40
    O1, O2, th = (mpf(0), mpf(0)), (mpf(0), mpf("-0.3")), mpmath.radians(30)
    A = (mpf("0.12") * mpmath.cos(th), mpf("0.12") * mpmath.sin(th))
    L = mpmath.hypot(A[0] - O2[0], A[1] - O2[1])
    u = ((A[0] - O2[0]) / L, (A[1] - O2[1]) / L)
    n = (-u[1], u[0])
    P = (O2[0] + mpf("0.6") * u[0], O2[1] + mpf("0.6") * u[1])
    Q = (P[0] + mpmath.sqrt(mpf("0.2") ** 2 - (mpf("0.32") - P[1]) ** 2), mpf("0.32"))
    vA = (-A[1], A[0])
    vs = vA[0] * u[0] + vA[1] * u[1]  # the block along the slot, outward +
    wl = (vA[0] * n[0] + vA[1] * n[1]) / L
    vP = (-wl * (P[1] - O2[1]), wl * (P[0] - O2[0]))
    vQ = vP[0] + vP[1] / (Q[0] - P[0]) * (Q[1] - P[1])  # the ram along its guide

    def build(x):
        ne = NewtonEuler(
            ["crank", "block", "lever", "PQ", "ram"], about={"block": A, "ram": Q}, mp=True
        )
        ne.pin("O1", O1, "crank", "frame")
        ne.pin("A", A, "block", "crank")
        ne.along("NA", A, n, "block", "lever")
        ne.pin("O2", O2, "lever", "frame")
        ne.pin("P", P, "PQ", "lever")
        ne.pin("Q", Q, "PQ", "ram")
        ne.along("NQ", Q, (0, 1), "ram", "frame")
        ne.known("ram", (mpf(3000), 0), Q)
        if x is not None:
            ne.known("ram", (-mpf("0.08") * abs(x["NQ"]) * mpmath.sign(vQ), 0), Q)
            g = -mpf("0.2") * abs(x["NA"]) * mpmath.sign(vs)
            ne.known("block", (g * u[0], g * u[1]), A)
            ne.known("lever", (-g * u[0], -g * u[1]), A)
        ne.couple("T", "crank", "frame")
        return ne.solve()

    return _settled(build, ())


def test_slider_crank_with_a_coefficient_at_each_pin_against_the_matrix_method():
    x = _crank_reference()
    sol = solve(load_scene(CRANK))
    f = sol.forces
    assert f.input_torque == pytest.approx(float(x["T"]), rel=REL)
    for name in ("O", "A", "B"):
        assert _pin(sol, name) == pytest.approx(float(_size(x, name)), rel=REL)
    assert f.guides[0].normal == pytest.approx(float(x["N"]), rel=REL)
    # each pin's own coefficient: the couples mu r |F| differ pin by pin
    couples = {it[1]: abs(it[2]) for it in f.friction if len(it) == 3}
    for name, r, mu in (("O", 0.025, 0.05), ("A", 0.02, 0.08), ("B", 0.0125, 0.12)):
        want = mu * r * float(_size(x, name))
        assert couples[f"friction at pin {name}"] == pytest.approx(want, rel=REL)


def test_shaper_with_its_slot_rougher_than_the_rams_guide_against_the_matrix_method():
    x = _shaper_reference()
    sol = solve(load_scene(SHAPER))
    f = sol.forces
    assert f.input_torque == pytest.approx(float(x["T"]), rel=REL)
    normals = {g.point: abs(g.normal) for g in f.guides}
    assert normals["Q"] == pytest.approx(float(abs(x["NQ"])), rel=REL)
    assert normals["A"] == pytest.approx(float(abs(x["NA"])), rel=REL)
    for name in ("O1", "O2", "P", "Q"):
        assert _pin(sol, name) == pytest.approx(float(_size(x, name)), rel=REL)
    forces = {it[1]: it[2] for it in f.friction if len(it) == 4 and it[0].startswith("block")}
    slot = forces["friction at the guide of A"]
    assert mpmath.hypot(*slot) == pytest.approx(0.2 * float(abs(x["NA"])), rel=REL)


def _run(capsys, *args):
    code = main([str(a) for a in args])
    out = capsys.readouterr()
    return code, out.out, out.err


@pytest.mark.parametrize("scene", [CRANK, SHAPER])
def test_each_coefficient_in_every_view(capsys, tmp_path, scene):
    code, out, _ = _run(capsys, "solve", scene)
    assert code == 0 and "(inertia, weights, loads and friction)" in out
    said = {CRANK: "0.05 at pin O, 0.08 at pin A, 0.12 at pin B", SHAPER: "0.08 at the guide of Q"}
    assert said[scene] in out
    code, out, _ = _run(capsys, "solve", scene, "--json")
    assert code == 0
    code, out, _ = _run(capsys, "steps", scene)
    assert code == 0 and "friction power" in out
    assert _run(capsys, "draw", scene, "--forces", "-o", tmp_path / "f.svg")[0] == 0
    code, out, _ = _run(capsys, "sweep", scene, "--summary")
    assert code == 0 and "of the loads and friction (no body massive)" in out
    code, out, _ = _run(capsys, "check", scene)
    assert code == 0, out


def test_the_books_answers_are_the_matrix_methods():
    """The [answers] written in each file are the matrix method's numbers."""
    x = _crank_reference()
    sc = load_scene(CRANK)
    keys = {a.key: a for a in sc.answers}
    assert float(keys["torque"].value) == pytest.approx(float(x["T"]), rel=1e-3)
    assert float(keys["F_O"].value) == pytest.approx(float(_size(x, "O")), rel=1e-3)
    x = _shaper_reference()
    keys = {a.key: a for a in load_scene(SHAPER).answers}
    assert float(keys["torque"].value) == pytest.approx(float(x["T"]), rel=1e-3)
    assert float(keys["N_A"].value) == pytest.approx(float(abs(x["NA"])), rel=1e-3)


@pytest.mark.parametrize(
    "table, words",
    [
        ("guides = { Z = 0.1 }", "guides: 'Z' is not a sliding block's point"),
        ("pins = { Q = 0.1 }", "pins: 'Q' is not a pin with a size in [pins]"),
        ("guides = { B = 1.5 }", "guides.B = 1.5: a coefficient of friction"),
        ('guides = { B = "0.1" }', "guides.B = '0.1': a coefficient of friction"),
    ],
)
def test_a_bad_coefficient_table_is_one_line(tmp_path, capsys, table, words):
    text = CRANK.read_text(encoding="utf-8")
    text = text.replace("guides = 0.15\npins = { O = 0.05, A = 0.08, B = 0.12 }", table)
    bad = tmp_path / "bad.toml"
    bad.write_text(text, encoding="utf-8")
    with pytest.raises(SceneError, match="friction"):
        load_scene(bad)
    code, out, err = _run(capsys, "solve", bad)
    assert code == 2 and words in err and len(err.strip().splitlines()) == 1
