"""Linkage properties against the lecture's closed forms.

Grashof's classes on textbook linkages; toggle positions from the law of cosines;
transmission angle extremes from the law of cosines; dead centres, stroke and time ratio
of the offset slider crank from right triangles; the slotted lever's return angle
2 acos(r / d); the slider crank's approximate formulas evaluated here by hand.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from scenes import NON_GRASHOF, SLOTTED_LEVER

from polygon_method import parse_scene
from polygon_method.cli import main
from polygon_method.linkage import analyse, grashof


def fourbar(crank, coupler, output, ground, angle=60.0, side="above"):
    return parse_scene(f"""
[ground]
A = [0, 0]
D = [{ground}, 0]
[links]
AB = {crank}
BC = {coupler}
CD = {output}
[assembly]
C = "{side}"
[input]
crank = "AB"
angle = {angle}
speed = "10 rad/s ccw"
""")


@pytest.mark.parametrize(
    "lengths, kind, turns_in, turns_out",
    [
        ((30, 90, 70, 100), "crank-rocker", True, False),  # s = crank: 130 < 160
        ((60, 80, 70, 30), "double crank", True, True),  # s = ground: 110 < 130
        ((70, 80, 30, 60), "rocker-crank", False, True),  # s = output
        ((70, 30, 60, 80), "double rocker", False, False),  # s = coupler
        ((50, 66, 56, 100), "non-Grashof triple rocker", False, False),  # 150 > 122
        ((150, 450, 300, 200), "non-Grashof triple rocker", False, False),
        ((40, 100, 40, 100), "parallelogram", True, True),  # 140 = 140, opposite equal
        ((100, 40, 40, 100), "deltoid", False, True),  # adjacent equal; BC, CD shortest
        ((40, 40, 100, 100), "deltoid", True, False),  # AB, BC shortest
        ((50, 50, 50, 50), "rhombus", True, True),
        ((20, 60, 50, 30), "special Grashof crank-rocker", True, False),  # 20 + 60 = 50 + 30
    ],
)
def test_grashof_classes(lengths, kind, turns_in, turns_out):
    g = grashof(*(x / 1000 for x in lengths))
    assert g.kind == kind
    assert (g.input_turns, g.output_turns) == (turns_in, turns_out)


def test_anti_parallelogram_from_the_scene():
    sc = fourbar(40, 100, 40, 100, angle=60, side="below")  # crossed: C below
    assert analyse(sc).grashof.kind == "anti-parallelogram"
    assert analyse(fourbar(40, 100, 40, 100, angle=60)).grashof.kind == "parallelogram"


def test_crank_rocker_toggles_swing_and_time_ratio():
    """a = 30, b = 90, c = 70, d = 100 (mm). Driven from the output the linkage locks where
    the crank and coupler are in line: |AC| = b + a = 120 (extended) or b - a = 60
    (folded); angle at A: cos = (d^2 + AC^2 - c^2) / (2 d AC)."""
    a, b, c, d = 30.0, 90.0, 70.0, 100.0
    lk = analyse(fourbar(a, b, c, d))
    assert lk.grashof.kind == "crank-rocker" and lk.turns_fully
    ext = math.degrees(math.acos((d * d + (a + b) ** 2 - c * c) / (2 * d * (a + b))))
    fold = 180 + math.degrees(math.acos((d * d + (b - a) ** 2 - c * c) / (2 * d * (b - a))))
    got = sorted(s.deg for s in lk.stationary)
    assert got == pytest.approx(sorted([ext, fold]), abs=1e-7)
    # the rocker's extreme angles, at D, between DA (180 deg) and DC
    psi = [
        180 - math.degrees(math.acos((d * d + c * c - L * L) / (2 * d * c))) for L in (a + b, b - a)
    ]
    assert math.degrees(lk.output_min) == pytest.approx(min(psi), abs=1e-7)
    assert math.degrees(lk.output_max) == pytest.approx(max(psi), abs=1e-7)
    arc = fold - ext  # the crank turns ccw from extended to folded
    assert lk.time_ratio == pytest.approx(max(arc, 360 - arc) / min(arc, 360 - arc), rel=1e-9)
    assert "extended" in lk.text() and "folded" in lk.text()


def test_transmission_angle_extremes_by_the_law_of_cosines():
    """cos mu = (b^2 + c^2 - AD'^2) / 2bc with |AD'| = d - a (crank at 0) and d + a (at 180);
    here mu runs from 49.99 to 108.03 deg, so the acute angle's maximum is 90 deg, reached
    where a^2 + d^2 - 2ad cos t = b^2 + c^2."""
    a, b, c, d = 30.0, 90.0, 70.0, 100.0
    lk = analyse(fourbar(a, b, c, d))
    (t,) = lk.transmission
    mu0 = math.degrees(math.acos((b * b + c * c - (d - a) ** 2) / (2 * b * c)))
    mu180 = math.degrees(math.acos((b * b + c * c - (d + a) ** 2) / (2 * b * c)))
    assert t.minimum == pytest.approx(min(mu0, 180 - mu180), abs=1e-7)
    assert t.at_min == pytest.approx(0.0, abs=1e-5)
    assert t.maximum == pytest.approx(90.0, abs=1e-7)
    t90 = math.degrees(math.acos((a * a + d * d - b * b - c * c) / (2 * a * d)))
    assert t.at_max == pytest.approx(t90, abs=1e-5) or t.at_max == pytest.approx(
        360 - t90, abs=1e-5
    )
    # now, at 60 deg: |BD|^2 = a^2 + d^2 - 2ad cos 60
    bd2 = a * a + d * d - 2 * a * d * 0.5
    mu = math.degrees(math.acos((b * b + c * c - bd2) / (2 * b * c)))
    assert t.now == pytest.approx(min(mu, 180 - mu), abs=1e-9)
    assert not t.warn and "WARNING" not in lk.text()


def test_transmission_warning_below_40_deg():
    """a = 40, b = 120, c = 80, d = 100: mu at crank 0 is acos((120^2 + 80^2 - 60^2) /
    (2 120 80)) = 26.4 deg < 40; it is below 40 while |AD'|^2 = a^2 + d^2 - 2ad cos t is
    below b^2 + c^2 - 2bc cos 40."""
    a, b, c, d = 40.0, 120.0, 80.0, 100.0
    lk = analyse(fourbar(a, b, c, d, angle=120))
    (t,) = lk.transmission
    assert t.minimum == pytest.approx(
        math.degrees(math.acos((b * b + c * c - (d - a) ** 2) / (2 * b * c))), abs=1e-7
    )
    assert t.warn and "WARNING" in lk.text()
    e2 = b * b + c * c - 2 * b * c * math.cos(math.radians(40))
    edge = math.degrees(math.acos((a * a + d * d - e2) / (2 * a * d)))
    ((lo, hi),) = t.below
    assert lo == pytest.approx(360 - edge, abs=1e-6)
    assert hi == pytest.approx(edge, abs=1e-6)


def test_non_grashof_toggles_driven_from_the_input():
    """O2A 150, AB 450, BO4 300, O2O4 200: the input's toggles where AB and BO4 are in line,
    O4A = 450 - 300: cos t = (150^2 + 200^2 - 150^2) / (2 150 200) = 2/3."""
    sc = parse_scene(NON_GRASHOF)
    lk = analyse(sc)
    assert lk.grashof.kind == "non-Grashof triple rocker" and not lk.turns_fully
    lim = math.degrees(math.acos(2 / 3))
    assert lk.range_deg == pytest.approx((lim, 360 - lim), abs=1e-8)
    text = lk.text()
    assert f"{lim:.4f}" in text and f"{360 - lim:.4f}" in text
    assert "quick return: not applicable" in text


def offset_slider_crank(r=100, l=400, e=40):
    return parse_scene(f"""
[ground]
O = [0, 0]
[links]
OA = {r}
AB = {l}
[sliders]
B = {{ path = "horizontal", through = [0, {-e}] }}
[assembly]
B = "right"
[input]
crank = "OA"
angle = 60
speed = "300 rpm cw"
""")


def test_offset_slider_crank_dead_centres_stroke_and_time_ratio():
    """Dead centres where crank and rod are in line: B at x = sqrt((l +- r)^2 - e^2) on the
    line y = -e; stroke their difference; the crank angles between them give the time
    ratio."""
    r, l, e = 100.0, 400.0, 40.0
    lk = analyse(offset_slider_crank(r, l, e))
    x1, x2 = math.sqrt((l + r) ** 2 - e * e), math.sqrt((l - r) ** 2 - e * e)
    t_ext = math.degrees(math.atan2(-e, x1)) % 360
    t_fold = math.degrees(math.atan2(e, -x2)) % 360
    assert sorted(s.deg for s in lk.stationary) == pytest.approx(sorted([t_ext, t_fold]), abs=1e-7)
    assert (lk.output_max - lk.output_min) * 1000 == pytest.approx(x1 - x2, rel=1e-10)
    arc = (t_ext - t_fold) % 360
    assert lk.time_ratio == pytest.approx(max(arc, 360 - arc) / min(arc, 360 - arc), rel=1e-9)
    assert "in-line slider crank only" in lk.text()


def test_slotted_lever_time_ratio():
    """The lever's extreme positions are where the crank is perpendicular to it: the
    return takes 2 acos(r / d) of the crank (r = 120, d = 300)."""
    sc = parse_scene(SLOTTED_LEVER)
    lk = analyse(sc)
    ret = 2 * math.degrees(math.acos(120 / 300))
    assert lk.time_ratio == pytest.approx((360 - ret) / ret, rel=1e-9)
    assert lk.kind == "crank and slotted lever"


def test_slider_crank_formulas_beside_the_exact_values():
    """The notes' engine: r = 150, l = 600 mm, 450 rpm, 60 deg from i.d.c.; the formulas
    v = r w (sin t + sin 2t / 2n), a = r w^2 (cos t + cos 2t / n) evaluated here, the exact
    values from x = r cos t + sqrt(l^2 - r^2 sin^2 t)."""
    sc = parse_scene("""
[ground]
O = [0, 0]
[links]
OA = 150
AB = 600
[sliders]
B = { path = "horizontal", through = "O" }
[assembly]
B = "right"
[input]
crank = "OA"
angle = 60
speed = "450 rpm ccw"
""")
    lk = analyse(sc)
    r, l, n, w, t = 0.15, 0.6, 4.0, 450 * math.pi / 30, math.radians(60)
    v_ap = r * w * (math.sin(t) + math.sin(2 * t) / (2 * n))
    a_ap = r * w * w * (math.cos(t) + math.cos(2 * t) / n)
    q = math.sqrt(l * l - r * r * math.sin(t) ** 2)
    v_ex = r * w * (math.sin(t) + r * math.sin(t) * math.cos(t) / q)
    text = "\n".join(lk.formulas)
    assert f"{v_ap:.6g}" in text and f"{a_ap:.6g}" in text and f"{v_ex:.6g}" in text
    err = 100 * (v_ap - v_ex) / v_ex
    assert f"{err:+.3f} %" in text
    assert lk.stationary[0].deg == pytest.approx(0.0, abs=1e-6)
    assert lk.time_ratio == pytest.approx(1.0, abs=1e-9)


def test_parallelogram_change_points_reported():
    lk = analyse(fourbar(40, 100, 40, 100))
    assert len(lk.change_points) == 2
    assert all("change point" in c for c in lk.change_points)
    (t,) = lk.transmission
    assert t.minimum == 0.0


def test_linkage_command(tmp_path, capsys):
    p = tmp_path / "cr.toml"
    p.write_text("""
[ground]
A = [0, 0]
D = [100, 0]
[links]
AB = 30
BC = 90
CD = 70
[input]
crank = "AB"
angle = 60
speed = "10 rad/s ccw"
""")
    assert main(["linkage", str(p)]) == 0
    out = capsys.readouterr().out
    assert "crank-rocker" in out and "transmission angle" in out
    assert main(["linkage", str(tmp_path / "missing.toml")]) == 2
    assert len(capsys.readouterr().err.strip().splitlines()) == 1


def test_degenerate_slider_crank_at_a_singular_instant_prints_no_nan(capsys):
    """r = l: the slider can dwell at the crank pivot, and at 90 deg the rod is square to the
    path (a dead centre for the slider step): the report must say so, never print nan/inf,
    and must not list the dwell as hundreds of toggle positions."""
    import tempfile
    from pathlib import Path

    from polygon_method.cli import main

    text = """
    [ground]
    O = [0, 0]
    [links]
    OA = 1
    AB = 1
    [sliders]
    B = { path = "horizontal", through = [0, 0] }
    [input]
    crank = "OA"
    angle = 90
    speed = "1 rad/s cw"
    """
    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "degenerate.toml"
        path.write_text(text)
        assert main(["linkage", str(path)]) == 0
    out = capsys.readouterr().out
    assert "nan" not in out and "inf " not in out
    assert "not compared at the scene's instant" in out
    assert out.count("crank at") < 20


@pytest.mark.parametrize(
    "text",
    [
        # a four-bar micrometres from locked: BC + CD just reach across
        *[
            f"""
[ground]
A = [0, 0]
D = [100, 0]
[links]
AB = 50
BC = 25
CD = {cd}
[input]
crank = "AB"
angle = 0
speed = "10 rad/s ccw"
"""
            for cd in ("25.001", "25.00001", "25.000001", "25.0000001")
        ],
        # a slider's path nearly tangent to the circle the rod's end can reach
        *[
            f"""
[ground]
O = [0, 0]
[links]
OA = 100
AB = 50
[sliders]
B = {{ path = "horizontal", through = [0, {y}] }}
[input]
crank = "OA"
angle = 90
speed = "10 rad/s ccw"
"""
            for y in ("149.999", "149.99999", "149.9999999")
        ],
    ],
)
def test_nearly_locked_linkages_give_a_result_or_one_line(text, tmp_path, capsys):
    from polygon_method.cli import main

    path = tmp_path / "locked.toml"
    path.write_text(text)
    code = main(["linkage", str(path)])
    out, err = capsys.readouterr()
    assert code in (0, 2), err
    assert "internal error" not in err and "Traceback" not in err
    if code == 2:
        assert len(err.strip().splitlines()) == 1
    else:
        assert "nan" not in out.lower() and "inf " not in out.lower()


def test_an_oscillating_cylinder_has_its_swing_and_quick_return():
    """Crank r about O, the link through a swivel at C, |OC| = c: the link swings
    +-asin(r/c) and returns quickly: the crank turns 360 - 2 acos(r/c) deg one way."""
    from polygon_method import parse_scene
    from polygon_method.linkage import analyse

    r, c = 50.0, 150.0
    sc = parse_scene(f"""
    [ground]
    O = [0, 0]
    C = [{c}, 0]
    [links]
    OA = {r}
    AB = 250
    [sliders]
    C = {{ along = "AB" }}
    [input]
    crank = "OA"
    angle = 60
    speed = "10 rad/s ccw"
    """)
    text = analyse(sc).text()
    swing = 2 * math.degrees(math.asin(r / c))
    forward = 360 - 2 * math.degrees(math.acos(r / c))
    assert f"swing {swing:.4f} deg" in text
    assert f"time ratio {forward / (360 - forward):.6f}" in text


def test_no_negative_zero_in_the_text():
    import re
    from pathlib import Path
    from polygon_method import load_scene
    from polygon_method.linkage import analyse

    for path in sorted((Path(__file__).parent.parent / "worked_problems").glob("*.toml")):
        scene = load_scene(path)
        if scene.input.block is not None:  # no crank's turn to analyse (refused)
            continue
        text = analyse(scene).text()
        assert not re.search(r"(?<![\d.])-0\.0+(?!\d)", text), path.name


def test_a_slider_that_stands_still_has_no_stroke_and_no_formula_errors():
    """An isosceles slider crank on the branch where the slider stays at the crank centre
    (rod as long as the crank, the path through the centre): rounding about a standstill is
    no stroke, and the engine formulas, which assume a moving piston, are not compared (no
    'inf %', no error of 1e11 %)."""
    import re as _re

    from polygon_method import parse_scene
    from polygon_method.linkage import analyse

    sc = parse_scene("""
[ground]
O = [0, 0]
[links]
OA = 1.0
AB = 1.0
[sliders]
B = { path = "1.0 deg", through = [0, 2.225073858507e-311] }
[assembly]
B = "left"
[input]
crank = "OA"
angle = 0.0
speed = "1.0 rad/s cw"
""")
    text = str(analyse(sc))
    assert "no stroke" in text and "moves between" not in text
    assert "do not apply" in text
    assert not _re.search(r"(?<![A-Za-z])(nan|inf)(?![A-Za-z])", text, _re.I)
    assert not _re.search(r"e\+0[5-9]|e\+[1-9]\d", text)  # no absurd percentages


TOGGLE_PRESS = Path(__file__).parent / "textbook" / "toggle_press.toml"


def test_an_output_standing_on_a_pivot_dwells_at_once(tmp_path, capsys, monkeypatch):
    """The toggle press without ``D = "below"`` takes D on the pivot C (BD = CB: D stays at
    C whatever the crank does, warned): the slider stands still over the whole cycle. Its
    rounding's hundreds of sign changes were each refined (13,000 evaluations of the cycle,
    seconds) and then thrown away; now none is, and the place is C's: 0 along the path."""
    from polygon_method.linkage import cycle

    calls = []
    real = cycle._Cycle.evaluate
    monkeypatch.setattr(
        cycle._Cycle, "evaluate", lambda self, *a, **k: calls.append(1) or real(self, *a, **k)
    )
    scene = tmp_path / "press.toml"
    scene.write_text(TOGGLE_PRESS.read_text().replace('D = "below"\n', ""))
    assert main(["linkage", str(scene)]) == 0
    out = capsys.readouterr().out
    assert "slider D: stands still at 0 mm along the path: no stroke" in out
    assert "stands still at all 3600 of the sampled crank angles" in out
    assert "dwells over the whole cycle" in out and "the output stands still" not in out
    assert len(calls) < 100, len(calls)


def test_a_rocker_standing_on_its_circle_lists_no_toggles(tmp_path, capsys):
    """A rocker ED whose circle about E passes through the pivot C, with BD = CB: D stays at
    C, the rocker at atan2(C - E) = atan2(-160, -120) = -126.8699 deg (closed form). Its
    rate is all rounding, whose sign changes were listed as 300-odd toggle positions."""
    scene = tmp_path / "rocker.toml"
    text = (
        TOGGLE_PRESS.read_text()
        .split("[sliders]")[0]
        .replace("C = [0, 400]", "C = [0, 400]\nE = [120, 560]")
    )
    text = text.replace("BD = 150", "BD = 150\nED = 200")
    scene.write_text(
        text + '[assembly]\nB = "below"\n[input]\ncrank = "OA"\nangle = 0\nspeed = "60 rpm cw"\n'
    )
    assert main(["linkage", str(scene)]) == 0
    out = capsys.readouterr().out
    deg = math.degrees(math.atan2(-160, -120))
    assert f"swings between {deg:.4f} and {deg:.4f} deg: swing 0.0000 deg" in out, out
    assert "the output stands still" not in out and "dwells over the whole cycle" in out
