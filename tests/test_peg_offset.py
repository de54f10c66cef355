"""A peg in an offset slot (``P = { along = "OA", offset = "40 mm left", path = ... }``, or
``along = ["AB", "CD"], offset = ["15 mm left", "10 mm right"]``): a pin in a slot whose
centre line is parallel to its link's and off it (tests/textbook/hunt7_peg_*.toml).

Set out by hand with nothing of the solver: each slot the line ``G + e perp(u) + s u`` of
its link (u from its first point to its second, e to the left), the peg where the two lines
cross, as closed forms of time at 40 digits (the crank's angle theta(t) = theta_0 + omega t
+ alpha t^2 / 2; the four-bar's rocker by the circles' intersection), differentiated in
time by mpmath; each slot's sliding the rate of ``(P - G).u`` and its Coriolis component 2
omega vs perp(u) from those. Then the loop closure of the solved points (the peg at each
slot's offset from its link's line), the Newton reference within the error bounds, the
refusals in one line and every view's words.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import mpmath
import pytest
from mpmath import mpf

from polygon_method import load_scene, parse_scene, solve
from polygon_method.check import check_answers
from polygon_method.common.errors import PolygonMethodError

HERE = Path(__file__).resolve().parent / "textbook"
ONE = HERE / "hunt7_peg_offset_slot_fixed_slot.toml"
TWO = HERE / "hunt7_peg_two_offset_slots.toml"
YOKE = HERE / "hunt7_scotch_yoke_offset_slot.toml"
REL = 1e-9


@pytest.fixture(autouse=True)
def _digits():
    old = mpmath.mp.dps
    mpmath.mp.dps = 40
    yield
    mpmath.mp.dps = old


def _cross_lines(g1, u1, e1, g2, u2, e2):
    """Where G1 + e1 perp(u1) + s u1 and G2 + e2 perp(u2) + t u2 cross (mpf)."""
    p1 = (g1[0] - e1 * u1[1], g1[1] + e1 * u1[0])
    p2 = (g2[0] - e2 * u2[1], g2[1] + e2 * u2[0])
    cr = u1[0] * u2[1] - u1[1] * u2[0]
    wx, wy = p2[0] - p1[0], p2[1] - p1[1]
    s = (wx * u2[1] - wy * u2[0]) / cr
    return (p1[0] + s * u1[0], p1[1] + s * u1[1])


def _unit(a, b):
    dx, dy = b[0] - a[0], b[1] - a[1]
    n = mpmath.sqrt(dx * dx + dy * dy)
    return (dx / n, dy / n)


def _rates(f):
    """(value, d/dt, d2/dt2) at t = 0 of each component of f(t)."""
    out = []
    for c in range(len(f(mpf(0)))):
        g = lambda t, c=c: f(t)[c]  # noqa: E731
        out.append((g(mpf(0)), mpmath.diff(g, 0, 1), mpmath.diff(g, 0, 2)))
    return out


def _close(got, want, size):
    assert abs(got - float(want)) <= REL * size, (got, float(want))


def _one_by_hand(deg=30, w=5, al=10, e="0.04", c="0.2"):
    """The bar OA (O at the origin) turning at theta(t); its slot e to the left of O -> A;
    the fixed slot x = c. Returns the peg's rates and the slot's sliding."""
    th0, w, al, e, c = mpmath.radians(deg), mpf(w), mpf(al), mpf(e), mpf(c)

    def th(t):
        return th0 + w * t + al * t * t / 2

    def peg(t):
        u = (mpmath.cos(th(t)), mpmath.sin(th(t)))
        return _cross_lines((0, 0), u, e, (c, 0), (0, 1), 0)

    def along(t):  # the peg's distance along the bar's slot, and along the fixed slot
        x, y = peg(t)
        return (x * mpmath.cos(th(t)) + y * mpmath.sin(th(t)), y)

    return _rates(peg), _rates(along), th0


def test_pin_in_an_offset_slot_of_a_bar_and_a_fixed_slot_by_hand():
    sol = solve(load_scene(ONE))
    (x, y), (s_bar, s_fixed), th0 = _one_by_hand()
    for i, D, size in ((0, sol.P, 0.3), (1, sol.V, 1.5), (2, sol.A, 15.0)):
        _close(D["P"][0], x[i], size)
        _close(D["P"][1], y[i], size)
    _close(sol.S["P_OA"][0], s_bar[1], 1.5)
    _close(sol.S["P_OA"][1], s_bar[2], 15.0)
    _close(sol.S["P_ground"][0], s_fixed[1], 1.5)
    _close(sol.S["P_ground"][1], s_fixed[2], 15.0)
    cor = 2 * 5 * s_bar[1]  # 2 omega vs, across the bar (perp(u) = (-sin, cos))
    want = (-cor * mpmath.sin(th0), cor * mpmath.cos(th0))
    for got, w in zip(sol.coriolis("P_OA"), want):
        _close(got, w, 15.0)


def _two_by_hand(deg=60, w=-10.5, al=20, e1="0.015", e2="-0.01"):
    """The four-bar A (0, 0), D (0.1, 0), AB 50, BC 66, CD 56 mm, C above BD's line; the
    peg where AB's slot (e1 to the left of A -> B) and CD's (e2 to the left of C -> D)
    cross."""
    th0, w, al, e1, e2 = mpmath.radians(deg), mpf(w), mpf(al), mpf(e1), mpf(e2)
    a, b, c, dx = mpf("0.05"), mpf("0.066"), mpf("0.056"), mpf("0.1")

    def th(t):
        return th0 + w * t + al * t * t / 2

    def points(t):
        B = (a * mpmath.cos(th(t)), a * mpmath.sin(th(t)))
        ux, uy = dx - B[0], -B[1]  # B -> D
        d = mpmath.sqrt(ux * ux + uy * uy)
        k = (b * b - c * c + d * d) / (2 * d)
        h = mpmath.sqrt(b * b - k * k)
        ex, ey = ux / d, uy / d
        C = (B[0] + k * ex - h * ey, B[1] + k * ey + h * ex)  # to the left of B -> D
        if C[1] < B[1] + k * ey - h * ex:  # the other one (keep the upper, as assembled)
            C = (B[0] + k * ex + h * ey, B[1] + k * ey - h * ex)
        return B, C

    def peg(t):
        B, C = points(t)
        return _cross_lines((0, 0), _unit((0, 0), B), e1, C, _unit(C, (dx, 0)), e2)

    def along(t):  # along AB's slot from A, along CD's from C
        B, C = points(t)
        P = peg(t)
        u1, u2 = _unit((0, 0), B), _unit(C, (dx, 0))
        return (
            P[0] * u1[0] + P[1] * u1[1],
            (P[0] - C[0]) * u2[0] + (P[1] - C[1]) * u2[1],
            mpmath.atan2(C[1], C[0] - dx),
        )

    return _rates(peg), _rates(along)


def test_a_peg_in_two_offset_slots_of_a_four_bar_by_hand():
    sol = solve(load_scene(TWO))
    (x, y), (s1, s2, phi) = _two_by_hand()
    for i, D, size in ((0, sol.P, 0.15), (1, sol.V, 2.0), (2, sol.A, 50.0)):
        _close(D["P"][0], x[i], size)
        _close(D["P"][1], y[i], size)
    _close(sol.W["CD"], phi[1], 10.0)
    for key, s in (("P_AB", s1), ("P_CD", s2)):
        _close(sol.S[key][0], s[1], 2.0)
        _close(sol.S[key][1], s[2], 50.0)
    cd = 2 * float(phi[1]) * float(s2[1])  # 2 omega_CD vs, its size
    _close(math.hypot(*sol.coriolis("P_CD")), abs(cd), 50.0)
    _close(math.hypot(*sol.coriolis("P_AB")), abs(2 * 10.5 * float(s1[1])), 50.0)


@pytest.mark.parametrize("angle", [-90, -45, 0, 35, 60, 80, 100])
def test_the_solved_peg_sits_at_each_slots_offset(angle):
    """Loop closure: the solved peg is e_i to the left of each link's line G_i -> H_i (its
    signed distance (H - G) x (P - G) / |H - G|) and its velocity and acceleration satisfy
    the slot's relation differentiated: (vP - vC_i) and (aP - aC_i - Coriolis) along u_i."""
    text = TWO.read_text(encoding="utf-8").replace("angle = 60", f"angle = {angle}")
    sol = solve(parse_scene(text))
    P, V, A, W, Al = sol.P, sol.V, sol.A, sol.W, sol.Al
    for key, g, h, link, e in (("P_AB", "A", "B", "AB", 0.015), ("P_CD", "C", "D", "CD", -0.01)):
        (gx, gy), (hx, hy), (px, py) = P[g], P[h], P["P"]
        n = math.hypot(hx - gx, hy - gy)
        ux, uy = (hx - gx) / n, (hy - gy) / n
        rx, ry = px - gx, py - gy
        assert abs(ux * ry - uy * rx - e) < 1e-15
        w, al = W[link], Al[link]
        vc = (V[g][0] - w * ry, V[g][1] + w * rx)
        rel = (V["P"][0] - vc[0], V["P"][1] - vc[1])
        assert abs(-uy * rel[0] + ux * rel[1]) < 1e-13 * 2.0  # no velocity across the slot
        ac = (A[g][0] - w * w * rx - al * ry, A[g][1] - w * w * ry + al * rx)
        vs = ux * rel[0] + uy * rel[1]
        rel = (A["P"][0] - ac[0] + 2 * w * vs * uy, A["P"][1] - ac[1] - 2 * w * vs * ux)
        assert abs(-uy * rel[0] + ux * rel[1]) < 1e-12 * 50.0


@pytest.mark.parametrize("path", [ONE, TWO, YOKE])
def test_peg_offset_slots_within_their_error_bounds(path):
    """Every quantity within its own error bound of the 40-digit Newton reference (each
    slot's offset in its guide equation)."""
    from error_bounds import compare_case, load_reference

    for kind, what, err, bound in compare_case(solve(load_scene(path)), load_reference(40)):
        assert err <= bound, (kind, what, err, bound)


_PEG = """
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 400
[sliders]
SPEC
[input]
crank = "OA"
angle = 30
speed = "5 rad/s ccw"
"""


@pytest.mark.parametrize(
    "spec, words",
    [
        (
            'P = { along = "OA", offset = ["40 left", 10], path = "vertical", through = [200, 0] }',
            'has one offset, its slot\'s in the link: offset = "30 mm left"',
        ),
        (
            'P = { along = "OA", offset = 0, path = "vertical", through = [200, 0] }',
            "offset = 0: the slot is on the link's own line",
        ),
        (
            'Y = { path = "horizontal", through = [0, 0] }\n'
            'P = { along = "block Y", direction = "vertical", offset = "20 mm up" }',
            "the slot's side is left or right (looking along the slot (vertical)), not 'up'",
        ),
        (
            'P = { path = "vertical", through = [200, 0], offset = 20 }',
            "a fixed path takes no offset",
        ),
    ],
)
def test_a_peg_offset_misstated_is_one_line(spec, words):
    with pytest.raises(PolygonMethodError) as exc:
        parse_scene(_PEG.replace("SPEC", spec))
    assert words in str(exc.value) and "\n" not in str(exc.value), str(exc.value)


@pytest.mark.parametrize(
    "offset, words",
    [
        ('"15 left"', 'one offset a slot, in their order: offset = ["30 mm left", 0]'),
        ('["15 left"]', 'one offset a slot, in their order: offset = ["30 mm left", 0]'),
        ("[0, 0]", "offset = [0, 0]: both slots are on their links' lines; leave offset out"),
        ('["15 mm up", 0]', "the slot's side is left or right (looking from A to B), not 'up'"),
    ],
)
def test_two_slots_offsets_misstated_are_one_line(offset, words):
    text = TWO.read_text(encoding="utf-8").replace(
        'offset = ["15 mm left", "10 mm right"]', f"offset = {offset}"
    )
    with pytest.raises(PolygonMethodError) as exc:
        parse_scene(text)
    assert words in str(exc.value) and "\n" not in str(exc.value), str(exc.value)


def test_one_slot_offset_and_the_other_on_its_line():
    """offset = [0, "10 mm right"]: AB's slot on its line, CD's off it: the same peg as the
    hand's with e1 = 0."""
    text = TWO.read_text(encoding="utf-8").replace(
        'offset = ["15 mm left", "10 mm right"]', 'offset = [0, "10 mm right"]'
    )
    sol = solve(parse_scene(text))
    (x, y), _ = _two_by_hand(e1=0)
    for i, D, size in ((0, sol.P, 0.15), (1, sol.V, 2.0), (2, sol.A, 50.0)):
        _close(D["P"][0], x[i], size)
        _close(D["P"][1], y[i], size)
    assert "offset" not in sol.to_dict()["sliders"]["P_AB"]


def test_every_view_says_the_pegs_offset_slot(capsys, tmp_path):
    """steps sets the slot out (parallel to its link, so far to its side) and finds the peg
    where the two cross; solve's table, the JSON, the problem's words, the plan's title,
    check against the book's answers, draw and sweep --summary."""
    from polygon_method.cli import main

    path = str(TWO)
    assert main(["steps", path]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "peg P in the slot of AB parallel to its line A -> B, 15 mm to the left of it" in out
    assert (
        "P: the slot of AB (drawn parallel to AB, 15 mm (0.75 cm) to the left of its line A "
        "-> B) and the slot of CD (drawn parallel to CD, 10 mm (0.50 cm) to the right of its "
        "line C -> D) cross at P"
    ) in out
    assert "peg P in the offset slot of AB and the offset slot of CD" in out
    assert main(["solve", path]) == 0
    out = capsys.readouterr().out
    assert "AB slot 15 left" in out and "CD slot 10 right" in out
    assert main(["solve", "--json", path]) == 0
    sliders = json.loads(capsys.readouterr().out)["sliders"]
    assert sliders["P_AB"]["offset"] == 0.015 and sliders["P_CD"]["offset"] == -0.01
    assert main(["check", path]) == 0
    assert "right" in capsys.readouterr().out
    assert main(["draw", path, "-o", str(tmp_path / "peg.svg")]) == 0
    assert (tmp_path / "peg.svg").stat().st_size > 1000
    assert main(["sweep", "--summary", path]) == 0
    assert "vs_P_AB" in capsys.readouterr().out
    from polygon_method.text.words import given

    words = " ".join(" ".join(given(load_scene(path))).split())
    assert "15 mm to the left" in words, words


@pytest.mark.parametrize("path", [ONE, TWO, YOKE])
def test_book_answers(path):
    verdicts = [v for v in check_answers(solve(load_scene(path))) if v.given]
    assert len(verdicts) >= 4 and all(v.ok for v in verdicts), [
        (v.key, v.given, v.correct) for v in verdicts if not v.ok
    ]


def test_a_sweep_of_the_offset_slots_is_the_solves():
    """The array road (a sweep, the page's frames) places the peg on the same offset lines
    as one instant's solve, with the same sliding."""
    from polygon_method.motion.sweeps import sweep
    from polygon_method.solver.kinematics import evaluate

    scene = load_scene(TWO)
    res = sweep(scene, [-1.5, -0.4, 0.3, 1.0, 1.7])
    for i, th in enumerate(res.theta):
        one = evaluate(res.plan, theta=float(th))
        for D, d in ((res.P, one.P), (res.V, one.V), (res.A, one.A)):
            for c in (0, 1):
                assert D["P"][c][i] == pytest.approx(d["P"][c], rel=1e-12, abs=1e-12)
        for k in ("P_AB", "P_CD"):
            assert res.S[k][1][i] == pytest.approx(one.S[k][1], rel=1e-12, abs=1e-12)


@pytest.mark.parametrize("deg", [0, 40, 90, 200, 300])
def test_a_yoke_whose_slot_is_off_its_point_by_hand(deg):
    """The Scotch yoke's slot 20 mm to the left of the line through Y (looking up the slot):
    Y = r cos theta + 20 mm, its velocity and acceleration r cos theta's rates (the offset
    a constant); the pin slides by r sin theta's."""
    text = YOKE.read_text(encoding="utf-8").replace("angle = 40", f"angle = {deg}")
    sol = solve(parse_scene(text))
    th0, w, r, e = mpmath.radians(deg), 2 * mpmath.pi * 300 / 60, mpf("0.08"), mpf("0.02")

    def th(t):
        return th0 + w * t + 25 * t * t

    (yx,) = _rates(lambda t: (r * mpmath.cos(th(t)) + e,))
    (sp,) = _rates(lambda t: (r * mpmath.sin(th(t)),))
    for i, D, size in ((0, sol.P, 0.1), (1, sol.V, 2.5), (2, sol.A, 80.0)):
        _close(D["Y"][0], yx[i], size)
        assert D["Y"][1] == 0.0
    for i, size in ((1, 2.5), (2, 80.0)):
        _close(sol.S["Y"][i - 1], yx[i], size)
        _close(sol.S["P"][i - 1], sp[i], size)
    assert abs(sol.P["P"][0] - (sol.P["Y"][0] - 0.02)) < 1e-16  # the slot's line through P


def test_every_view_says_the_yokes_offset_slot(capsys):
    from polygon_method.cli import main

    path = str(YOKE)
    assert main(["steps", path]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert (
        "block P slides in the vertical slot of yoke Y, its centre line 20 mm to the left of "
        "the yoke's line through Y"
    ) in out
    assert "the line along the yoke's slot (vertical) 20 mm (2.00 cm) to the right of P" in out
    assert main(["solve", path]) == 0
    assert "vertical slot 20 left" in capsys.readouterr().out
    assert main(["solve", "--json", path]) == 0
    assert json.loads(capsys.readouterr().out)["sliders"]["P"]["offset"] == 0.02
    from polygon_method.text.words import given

    words = " ".join(" ".join(given(load_scene(path))).split())
    assert "its centre line 20 mm to the left of the yoke's line through Y" in words, words


def test_variants_vary_a_pegs_offset_on_its_side(tmp_path):
    """[variants] P = { offset = ... }: each variant's peg in AB's slot that far to the
    left (the scene's side), its motion the hand's with that offset."""
    from polygon_method.cli import main

    text = TWO.read_text(encoding="utf-8").replace(
        'offset = ["15 mm left", "10 mm right"]', 'offset = ["15 mm left", 0]'
    )
    text = text[: text.index("[answers]")] + (
        '[answers]\nv_P = "?"\n\n[variants]\nP = { offset = { from = 10, to = 20, step = 1 } }\n'
    )
    base = tmp_path / "base.toml"
    base.write_text(text, encoding="utf-8")
    assert main(["variants", str(base), "--count", "3", "-o", str(tmp_path / "v")]) == 0
    seen = 0
    for f in sorted((tmp_path / "v").glob("variant-*.toml")):
        sc = load_scene(f)
        (s,) = [s for s in sc.sliders if s.key == "P_AB"]
        assert 0.010 - 1e-12 <= s.offset <= 0.020 + 1e-12  # to the left, as the scene's
        sol = solve(sc)
        (x, y), _ = _two_by_hand(e1=mpmath.mpf(s.offset), e2=0)
        _close(sol.V["P"][0], x[1], 2.0)
        _close(sol.V["P"][1], y[1], 2.0)
        seen += 1
    assert seen == 3


@pytest.mark.parametrize(
    "path, old, new, key",
    [
        (YOKE, "", "", "P"),
        (HERE / "hunt5_offset_slot_lever.toml", '"30 mm left"', '"30 mm right"', "A"),
    ],
)
def test_variants_vary_a_yokes_or_a_blocks_offset(path, old, new, key):
    """A yoke's offset slot, and a block's on its right: the values' side is the scene's
    (the SI value signed to the left)."""
    text = path.read_text(encoding="utf-8").replace(old, new) if old else path.read_text()
    text += f"\n[variants]\n{key} = {{ offset = [20, 25, 35] }}\n"
    (v,) = parse_scene(text).variation.varied
    side = -1 if "right" in new else 1
    assert v.si == tuple(side * x for x in (0.02, 0.025, 0.035))
    assert v.shown[0] == f"20 mm {'right' if side < 0 else 'left'}"


@pytest.mark.parametrize(
    "offsets, words",
    [
        ("", "the slot of P has no offset to vary"),
        ('offset = ["15 mm left", "10 mm right"]', "P sits in two offset slots: name the"),
    ],
)
def test_variants_of_an_offset_refused_in_one_line(offsets, words):
    text = TWO.read_text(encoding="utf-8").replace(
        ', offset = ["15 mm left", "10 mm right"]', f", {offsets}" if offsets else ""
    )
    text += "\n[variants]\nP = { offset = [20, 25] }\n"
    with pytest.raises(PolygonMethodError) as exc:
        parse_scene(text)
    assert words in str(exc.value) and "\n" not in str(exc.value), str(exc.value)


def test_a_pegs_offset_slot_force_analysis_by_virtual_power():
    """The force walk pushes the peg across each slot at P, off the bar's line: the driving
    torque is the virtual power's, T omega + sum(F.v) + sum(m g.v - m a.v - I alpha omega)
    = 0, from the motion (held to the hand's above)."""
    text = ONE.read_text(encoding="utf-8")
    text = text[: text.index("[answers]")] + (
        "[masses]\n"
        'OA = { mass = "4 kg", along = 200, inertia = "0.06 kg m^2" }\n'
        'P = { mass = "2 kg" }\n'
        "[gravity]\n"
        '[loads]\nP = { force = "300 N", direction = 270 }\n'
    )
    sol = solve(parse_scene(text))
    V, A, W, Al = sol.V, sol.A, sol.W, sol.Al

    def dot(a, b):
        return a[0] * b[0] + a[1] * b[1]

    g = (0.0, -9.81)
    power = dot((0.0, -300.0), V["P"])
    vg = (V["A"][0] / 2, V["A"][1] / 2)
    ag = (A["A"][0] / 2, A["A"][1] / 2)
    power += 4 * dot(g, vg) - 4 * dot(ag, vg) - 0.06 * Al["OA"] * W["OA"]
    power += 2 * dot(g, V["P"]) - 2 * dot(A["P"], V["P"])
    want = -power / W["OA"]
    got = sol.forces.input_torque
    assert abs(got - want) < 1e-9 * max(abs(want), 300 * 0.4)


@pytest.mark.parametrize(
    "e1, code, words",
    [
        ("0", "offset_left_out", "the slot of AB drawn through its line AB (its offset of 15 mm"),
        ("-0.015", "offset_other_side", "the slot of AB taken 15 mm to the right of its line"),
    ],
)
def test_a_pegs_offset_slot_drawn_otherwise_is_named(e1, code, words):
    """A student who draws AB's slot through AB's line (or on its other side): the peg's
    velocity by the hand's lines with that offset, given as the answer, is named by check."""
    (x, y), _ = _two_by_hand(e1=mpf(e1))
    v = float(mpmath.hypot(x[1], y[1]))
    text = TWO.read_text(encoding="utf-8")
    text = text[: text.index("[answers]")] + f'[answers]\nv_P = "{v:.4g} m/s"\n'
    (verdict,) = check_answers(solve(parse_scene(text)))
    assert not verdict.ok and verdict.mistake == code and words in verdict.diagnosis, verdict


@pytest.mark.parametrize(
    "path, answer",
    [
        (YOKE, 'a_Y = "70 m/s^2"'),  # a yoke's offset slot among the slips tried
        (HERE / "peg_two_slotted_links.toml", 'v_P = "1.5 m/s"'),  # a peg's v_P: its slots'
    ],
)
def test_a_wrong_answer_on_a_yoke_or_a_peg_gets_a_verdict(path, answer):
    """A wrong answer is judged, not refused: the slips tried of a yoke's offset slot and a
    peg's sliding (keyed by its slot, P_AB) were once an error."""
    text = path.read_text(encoding="utf-8")
    text = text[: text.index("[answers]")] if "[answers]" in text else text
    (verdict,) = check_answers(solve(parse_scene(text + f"\n[answers]\n{answer}\n")))
    assert not verdict.ok


def test_variants_vary_each_of_a_pegs_two_offsets_by_its_link():
    """P = { offset = { AB = [...], CD = [...] } }: each slot's offset its own key, written
    into its place in the scene's list on its own side; a link that is no offset slot of the
    peg is refused naming those that are."""
    text = TWO.read_text(encoding="utf-8") + (
        "\n[variants]\nP = { offset = { AB = [10, 20], CD = { from = 5, to = 8, step = 1 } } }\n"
    )
    ab, cd = parse_scene(text).variation.varied
    assert (ab.key, ab.path, ab.values, ab.si) == (
        "P.offset.AB",
        ("sliders", "P", "offset", 0),
        ("10 left", "20 left"),
        (0.01, 0.02),
    )
    assert cd.path == ("sliders", "P", "offset", 1) and cd.values[0] == "5 right"
    assert cd.si == pytest.approx((-0.005, -0.006, -0.007, -0.008), rel=1e-15)
    with pytest.raises(PolygonMethodError) as exc:
        parse_scene(text.replace("CD = {", "BC = {"))
    assert "BC is not a slot of P with an offset (its offset slots: AB, CD)" in str(exc.value)
