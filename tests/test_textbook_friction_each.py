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
from polygon_method import load_scene, parse_scene, solve
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


def _crank_reference(circles=None, mu_guide="0.15"):
    """The slider crank: O (r 25 mm, mu 0.05), A (20 mm, 0.08), B (12.5 mm, 0.12), the
    guide 0.15; the crank 20 rad/s cw at 120 deg, 1.5 kN against the slider. ``circles``:
    the friction circles' radii (m) at O, A, B instead (each pin's couple rho |F|)."""
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
    if circles is not None:
        pins = [(n, at, on, by, mpf(rho), 1) for (n, at, on, by, _, _), rho in zip(pins, circles)]

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
            ne.known("block", (-mpf(mu_guide) * abs(x["N"]) * mpmath.sign(vs), 0), B)
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
        ("pins = { Q = 0.1 }", "pins: 'Q' is not a joint of the mechanism (a pin)"),
        ("pins = { O = 0.1, A = 0.1, B = 0.1, Q = '2 mm' }", "'Q' is not a joint"),
        ('pins = "-2 mm"', "length must be positive"),
        ("guides = { B = 1.5 }", "guides.B = 1.5: a coefficient of friction"),
        ('guides = { B = "0.1" }', "guides.B = '0.1': a coefficient of friction"),
        ("guides = {}", "guides = {} names none"),
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


PEG = HERE / "peg_two_slotted_links.toml"


def _peg_scene(tmp_path, table):
    text = PEG.read_text(encoding="utf-8").split("[answers]")[0]
    text += (
        '[masses]\n[loads]\nP = { force = "100 N", direction = 200 }\n'
        f"[friction]\nguides = {table}\n"
    )
    f = tmp_path / "peg.toml"
    f.write_text(text, encoding="utf-8")
    return f


def _peg_reference(C_tool, mu1, mu2):
    """The four-bar A (0, 0), D (100, 0), AB 50, BC 66, CD 56 at 60 deg, the crank 10.5
    rad/s cw; the peg P where the slots (the lines AB and CD) cross; 100 N at 200 deg on it.
    Five bodies' unknowns: the pins A, B, C, D, each slot's normal force and the torque;
    each slot's friction mu |N| against the peg's sliding along it, repeated to settle."""
    mpmath.mp.dps = 40
    w2 = mpf("-10.5")

    def place(th, branch):
        B = (mpf("0.05") * mpmath.cos(th), mpf("0.05") * mpmath.sin(th))
        D = (mpf("0.1"), mpf(0))
        dx, dy = D[0] - B[0], D[1] - B[1]
        L = mpmath.hypot(dx, dy)
        x = (mpf("0.066") ** 2 - mpf("0.056") ** 2 + L**2) / (2 * L)
        h = branch * mpmath.sqrt(mpf("0.066") ** 2 - x**2)
        C = (B[0] + (x * dx - h * dy) / L, B[1] + (x * dy + h * dx) / L)
        # P on the line A-B and the line D-C
        u1 = (B[0] / mpf("0.05"), B[1] / mpf("0.05"))
        u2 = ((C[0] - D[0]) / mpf("0.056"), (C[1] - D[1]) / mpf("0.056"))
        det = u1[0] * (-u2[1]) - u1[1] * (-u2[0])
        s = (D[0] * (-u2[1]) - D[1] * (-u2[0])) / det
        return B, C, D, (s * u1[0], s * u1[1]), u1, u2

    th = mpmath.radians(60)
    branch = min((1, -1), key=lambda b: abs(place(th, b)[1][0] - C_tool[0]))
    B, C, D, P, u1, u2 = place(th, branch)

    def ang(k):
        def f(t):
            pts = place(t, branch)
            v = (pts[1][0] - pts[k][0], pts[1][1] - pts[k][1])
            return mpmath.atan2(v[1], v[0])

        return f

    w3 = mpmath.diff(ang(0), th) * w2  # BC's direction B->C
    w4 = mpmath.diff(ang(2), th) * w2  # CD's from D
    vP = [mpmath.diff(lambda t, i=i: place(t, branch)[3][i], th) * w2 for i in (0, 1)]
    vs1 = (vP[0] + w2 * P[1]) * u1[0] + (vP[1] - w2 * P[0]) * u1[1]  # relative to AB
    vs2 = (vP[0] + w4 * P[1]) * u2[0] + (vP[1] - w4 * (P[0] - D[0])) * u2[1]
    assert w3 != 0
    n1, n2 = (-u1[1], u1[0]), (-u2[1], u2[0])
    F = (100 * mpmath.cos(mpmath.radians(200)), 100 * mpmath.sin(mpmath.radians(200)))

    def build(x):
        ne = NewtonEuler(["AB", "BC", "CD", "peg"], about={"peg": P}, mp=True)
        ne.pin("A", (0, 0), "AB", "frame")
        ne.pin("B", B, "BC", "AB")
        ne.pin("C", C, "BC", "CD")
        ne.pin("D", D, "CD", "frame")
        ne.along("N1", P, n1, "peg", "AB")
        ne.along("N2", P, n2, "peg", "CD")
        ne.known("peg", F, P)
        if x is not None:
            for name, mu, u, vs, by in (("N1", mu1, u1, vs1, "AB"), ("N2", mu2, u2, vs2, "CD")):
                f = -mu * abs(x[name]) * mpmath.sign(vs)
                ne.known("peg", (f * u[0], f * u[1]), P)
                ne.known(by, (-f * u[0], -f * u[1]), P)
        ne.couple("T", "AB", "frame")
        return ne.solve()

    return _settled(build, ())


def test_a_peg_with_each_slot_its_own_coefficient_against_the_matrix_method(tmp_path, capsys):
    """The peg's two slots, 0.1 in the crank's and 0.2 in the rocker's (guides = { P_AB =
    0.1, P_CD = 0.2 }): the torque, the slots' normal forces and the pins to the 40-digit
    matrix method; solve names each slot's friction (both: before, the second was not
    said, the two sharing one name)."""
    sol = solve(load_scene(_peg_scene(tmp_path, "{ P_AB = 0.1, P_CD = 0.2 }")))
    x = _peg_reference(sol.P["C"], mpf("0.1"), mpf("0.2"))
    f = sol.forces
    assert f.input_torque == pytest.approx(float(x["T"]), rel=REL)
    normals = {g.key: abs(g.normal) for g in f.guides}
    assert normals["P_AB"] == pytest.approx(float(abs(x["N1"])), rel=REL)
    assert normals["P_CD"] == pytest.approx(float(abs(x["N2"])), rel=REL)
    for name in ("A", "B", "C", "D"):
        assert _pin(sol, name) == pytest.approx(float(_size(x, name)), rel=REL)
    code, out, _ = _run(capsys, "solve", _peg_scene(tmp_path, "{ P_AB = 0.1, P_CD = 0.2 }"))
    assert code == 0
    assert "friction in the slot of AB at P" in out and "friction in the slot of CD at P" in out
    assert "guide at P_AB" in out and "guide at P_CD" in out
    # one coefficient for both slots, by the point
    same = solve(load_scene(_peg_scene(tmp_path, "{ P = 0.15 }")))
    y = _peg_reference(sol.P["C"], mpf("0.15"), mpf("0.15"))
    assert same.forces.input_torque == pytest.approx(float(y["T"]), rel=REL)


CIRCLE = HERE / "friction_circle_slider_crank.toml"


def test_friction_circles_given_by_their_radius_against_the_matrix_method():
    """Ballaney's "the radius of the friction circle is 2 mm at each pin, mu 0.1 at the
    guide": no pin sizes; each pin's couple 2 mm x |F| against the relative turning."""
    x = _crank_reference(circles=("0.002", "0.002", "0.002"), mu_guide="0.1")
    sol = solve(load_scene(CIRCLE))
    assert sol.forces.input_torque == pytest.approx(float(x["T"]), rel=REL)
    for name in ("O", "A", "B"):
        assert _pin(sol, name) == pytest.approx(float(_size(x, name)), rel=REL)
    assert sol.forces.guides[0].normal == pytest.approx(float(x["N"]), rel=REL)
    keys = {a.key: a for a in sol.scene.answers}
    assert float(keys["torque"].value) == pytest.approx(float(x["T"]), rel=1e-3)


def test_each_pins_circle_is_its_coefficient_times_its_radius():
    """The per-pin file's coefficients and sizes stated instead as the circles mu r: the
    same forces to the last bits' rounding."""
    text = CRANK.read_text(encoding="utf-8").replace(
        "pins = { O = 0.05, A = 0.08, B = 0.12 }",
        'pins = { O = "1.25 mm", A = "1.6 mm", B = "1.5 mm" }',
    )
    text = text.split("[pins]")[0] + "[answers]" + text.split("[answers]")[1]
    a, b = solve(load_scene(CRANK)), solve(parse_scene(text))
    assert b.forces.input_torque == pytest.approx(a.forces.input_torque, rel=1e-12)


def test_friction_circles_at_rest_about_to_start():
    """At rest about to turn cw, the static friction limiting against the motion about to
    start: with no masses the same forces as moving cw (the matrix method's)."""
    x = _crank_reference(circles=("0.002", "0.002", "0.002"), mu_guide="0.1")
    text = CIRCLE.read_text(encoding="utf-8").replace(
        'speed = "20 rad/s clockwise"', 'speed = "0 rad/s cw"'
    )
    sol = solve(parse_scene(text))
    assert sol.scene.at_rest
    assert sol.forces.input_torque == pytest.approx(float(x["T"]), rel=REL)
