"""The textbook corpus's reports as a student reads them (tests/textbook/*.toml): values
that are exactly zero at the textbook's special positions written 0, not 1e-16 (solve,
steps, centres, linkage, sweep summary, the page, check, the variants' key); the words of
notes, refusals and step tables; the labels of image points. Each test names the fault it
was written for.
"""

import math
import re

import pytest

from polygon_method import load_scene, solve
from polygon_method.common.errors import SingularStepError
from polygon_method.solver.centres import locate
from polygon_method.text.centres import centres_text
from polygon_method.text.report import solution_text
from polygon_method.text.steptable import steps_text
from textbook_corpus import CRANKED, FILES, HERE, NOISE, at_angle, solved, turned, turned_cases


def test_steps_write_no_rounding_noise_at_mid_stroke():
    """Crank and slotted lever at 270 deg: the block does not slide and the ram's rod
    translates at this instant. The step table said "vs_A = 1.603e-16 m/s along O1-P",
    "P-R turns ccw (opposite senses)" and a Coriolis component of 1.1e-15."""
    _, sol, ref = solved(HERE / "slotted_lever_270.toml")
    # (zero but for the float crank angle 3 pi / 2)
    assert abs(ref["omega"]["P-R"]) < 1e-12 and abs(ref["sliders"]["A"]["vs"]) < 1e-12
    text = steps_text(sol)
    assert not NOISE.search(text), NOISE.search(text).group(0)
    assert "vs_A = 0 m/s: A does not slide along O1-P" in text
    assert "P-R does not turn: rub = omega_O1-P r = 3.491 x 0.01" in text
    assert "P-R ccw" not in text and "P-R cw" not in text
    assert "2 x 3.491 x 0 = 0" in text


NOISE_CASES = [pytest.param(f, None, id=f.stem) for f in FILES] + [
    pytest.param(f, a, id=f"{f.stem}-{a}") for f, a in turned_cases()[0]
]


@pytest.mark.parametrize("path,angle", NOISE_CASES)
def test_reports_write_no_noise(path, angle):
    """No -0.0000 for a coordinate on an axis, no 1e-15 where a value is zero."""
    sol = solved(path)[1] if angle is None else turned(path, angle)
    assert "-0.0000" not in solution_text(sol)
    assert not NOISE.search(solution_text(sol)), NOISE.search(solution_text(sol)).group(0)
    steps = steps_text(sol)
    assert not NOISE.search(steps), NOISE.search(steps).group(0)
    if sol.scene.input.second is not None:  # two inputs: Kennedy's theorem refuses, saying why
        with pytest.raises(SingularStepError, match="two inputs"):
            locate(sol)
        return
    text = centres_text(locate(sol))
    assert not NOISE.search(text), NOISE.search(text).group(0)


def test_default_slotted_end_note_reads_as_english():
    _, sol, _ = solved(HERE / "oscillating_cylinder.toml")
    assert "C: of its two positions the one on the side of the block was taken" in " ".join(
        sol.notes
    )


def test_sweep_summary_writes_a_true_zero_as_zero():
    """The rocker's end C stands still at the ends of its swing: the summary's minimum of
    v_C is 0 (it printed 1.18743e-13)."""
    from polygon_method.linkage.summary import summarize

    scene = load_scene(HERE / "block_on_coupler.toml")
    text = summarize(scene, [math.radians(5.0 * k) for k in range(72)]).text()
    row = next(ln for ln in text.splitlines() if ln.startswith("v_C "))
    assert row.split()[4] == "0", row
    assert not NOISE.search(text), NOISE.search(text).group(0)


def test_engine_formulas_write_a_true_zero_as_zero():
    """At 90 deg from i.d.c. the rod does not turn: exact and formula are 0 (the exact
    printed 6.57668e-15, the formula 2.13741e-15)."""
    from polygon_method.linkage import analyse

    text = analyse(load_scene(HERE / "engine_inline_270.toml")).text()
    row = next(ln for ln in text.splitlines() if "rod CP: |omega|" in ln)
    assert row.split()[3:6] == ["0", "0", "0"], row


def test_page_data_writes_rounding_noise_as_zero():
    """The page's values at the scene's angle (slotted lever at 270 deg): omega of the ram's
    rod and the block's sliding velocity are 0, not 1.6e-15 rad/s ccw, written out by the
    page as 0.0000000000000016."""
    from polygon_method.page.data import page_data
    from polygon_method.page.frames import frames

    d = page_data(frames(load_scene(HERE / "slotted_lever_270.toml"), 12))
    k = d["start"]
    assert d["theta"][k] == 270.0
    assert d["W"]["P-R"][k] == 0.0 and d["S"]["A"][0][k] == 0.0
    assert d["S"]["A"][2][k] == 0.0 and d["S"]["A"][3][k] == 0.0
    assert d["P"]["A"][2 * k] == 0.0  # A on the y axis
    assert d["W"]["P-R"][k + 1] != 0.0  # only the noise: the next frame's omega is kept


def test_centres_drawing_with_two_centres_at_one_pin():
    """The centres' diagram of the slotted lever at mid-stroke: a Kennedy line through two
    centres at one place (I23 = I24 at A) has no direction of its own; the drawing failed
    with "OverflowError: cannot convert float infinity to integer"."""
    from polygon_method.draw import render

    sol = solve(load_scene(HERE / "slotted_lever_270.toml"))
    data, _, _ = render(sol, "svg", "centres", None, "I")
    svg = data.decode() if isinstance(data, bytes) else data
    assert "I25" in svg and "nan" not in svg.lower()


def test_a_load_that_takes_no_power_gives_no_torque():
    """The coupling rod translates horizontally, its weight acts straight down: the input
    torque is 0 (solve printed "6.51e-14 N m ccw", the step table "F . v = -1.154e-12 W"
    and "5.511e-14 N m cw", the force "direction = 270" had an x component of -1.8e-13 N)."""
    scene, sol, ref = solved(HERE / "coupling_rod_90.toml")
    assert scene.loads[0].force == (0.0, -1000.0)
    assert "input torque on AB: 0 N m " in solution_text(sol)
    text = steps_text(sol)
    assert "cos 90 deg = 0 W" in text and "= 0 N m" in text
    assert not NOISE.search(text)
    from polygon_method.page.data import page_data
    from polygon_method.page.frames import frames

    d = page_data(frames(scene, 12))
    assert d["torque"][d["start"]] == 0.0 and d["torque"][d["start"] + 1] != 0.0


def test_path_and_force_directions_are_exact_at_right_angles():
    from polygon_method import parse_scene

    sc = parse_scene("""
[ground]
O = [0, 0]
[links]
OA = 40
AB = 150
[sliders]
B = { path = "180 deg" }
[input]
crank = "OA"
angle = 30
speed = "10 rad/s ccw"
[loads]
A = { force = "1 kN", direction = -90 }
B = { force = "2 kN", direction = "180 deg" }
""")
    assert sc.sliders[0].u == (-1.0, 0.0)
    assert [ld.force for ld in sc.loads] == [(0.0, -1000.0), (-2000.0, 0.0)]


def test_assembly_refusal_names_positions_without_noise():
    """The Whitworth scene's rough position for P does not fit the crank at 90 deg (the
    lever is vertical): the refusal printed P's positions as [5.08699e-15, 120]."""
    from polygon_method import parse_scene
    from polygon_method.common.errors import AssemblyError

    with pytest.raises(AssemblyError) as exc:
        solve(parse_scene(at_angle(HERE / "whitworth_180.toml", 90)))
    assert "[0, 120]" in str(exc.value) and "[0, -120]" in str(exc.value)
    assert not NOISE.search(str(exc.value))


def test_variants_answer_key_writes_a_true_zero_as_zero():
    """A variant at mid-stroke (crank at 270 deg): the key gave omega_P-R as "3.68e-15
    rad/s ccw" and vs_A as "2.664e-16 m/s"."""
    from polygon_method import parse_scene
    from polygon_method.variants import generate
    from polygon_method.variants.papers import answer_key_csv, answer_key_markdown

    text = (
        (HERE / "slotted_lever_270.toml").read_text(encoding="utf-8")
        + """
[variants]
angle = [270]
"O2-A" = { from = 90, to = 120, step = 10 }
"""
    )
    vs = generate(parse_scene(text), 3, 1)
    md, csv = answer_key_markdown(vs), answer_key_csv(vs)
    assert not NOISE.search(md) and not NOISE.search(csv), (md, csv)
    assert all(v.solution.omega("P-R") == 0.0 for v in vs.variants)


def test_pin_between_links_turning_alike_rubs_at_zero():
    """Crank along the line of centres (180 deg): |O4A| is stationary, so the transmission
    angle is too and the coupler and the rocker turn alike: pin B does not rub. solve
    printed 1.421e-17 m/s, the steps "|6.818 - 6.818| x 0.008 = 1.421e-17 m/s"."""
    from polygon_method import parse_scene

    sol = solve(parse_scene(at_angle(HERE / "fourbar_crank_rocker_crossed.toml", 180)))
    assert sol.omega("A-B") == pytest.approx(sol.omega("O4-B"), rel=1e-12)
    assert re.search(r"(?m)^B +8 +0$", solution_text(sol))
    text = steps_text(sol)
    assert "|6.818 - 6.818| x 0.008 = 0 m/s" in text and not NOISE.search(text)


def test_centres_distance_of_a_point_at_its_centre_is_zero():
    """The piston at the outer dead centre is its rod's centre with the ground: the table
    gave its distance as 4.2863e-17 m."""
    from polygon_method import parse_scene

    sol = solve(parse_scene(at_angle(HERE / "engine_inline_270.toml", 180)))
    text = centres_text(locate(sol))
    assert "x 0 m = 0 m/s" in text and not NOISE.search(text)


@pytest.mark.parametrize("path", CRANKED, ids=[f.stem for f in CRANKED])  # (a block's
def test_linkage_text_has_no_double_blank_line(path):  # travel is no crank's turn)
    """The oscillating cylinder has no transmission angle: its output's range followed two
    blank lines."""
    from polygon_method.linkage import analyse

    text = analyse(load_scene(path)).text()
    assert "\n\n\n" not in text


def test_carried_points_are_described_with_their_unit():
    """The step table said "E: on BC, 280 from B" (no unit) and "E: on AB, -30 from A" for
    a point on the crank produced backwards."""
    words = {f.stem: steps_text(solved(f)[1]) for f in FILES}
    assert "  - E: on BC, 280 mm from B" in words["oscillating_cylinder"]
    assert "  - E: on AB produced beyond A, 30 mm from A" in words["crank_point_beyond"]
    assert "  - D: on AB produced beyond B, 220 mm from A" in words["inclined_slider"]
    assert "F: on BC, EF = 50 mm, CF = 70 mm, ECF read ccw" in words["coupler_plate_four_points"]


def test_check_takes_a_zero_torque_as_zero():
    """The coupling rod's weight takes no power: an answer of 0 N m is right, and the table
    shows 0 (it showed "1.2021e-13 N m, error 100.00 %, tolerance 8e+15 %")."""
    from polygon_method.check import check_answers, verdicts_text
    from polygon_method.scene import parse_scene

    text = (
        (HERE / "coupling_rod_90.toml").read_text(encoding="utf-8")
        + """
[answers]
torque = "0 N m"
rub_B = "0.6283 m/s"
"""
    )
    verdicts = check_answers(solve(parse_scene(text)))
    assert [v.ok for v in verdicts] == [True, True]
    assert verdicts[0].correct == 0.0
    assert "e+" not in verdicts_text(verdicts) and not NOISE.search(verdicts_text(verdicts))


def test_point_under_the_block_is_not_labelled_as_a_point_of_the_scene():
    """A slotted lever carrying a point named A1: the lever's point under the block A was
    labelled a1 too (two a1 on the velocity polygon, two a1' on the acceleration one)."""
    from polygon_method import parse_scene
    from polygon_method.polygons.constructions import (
        acceleration_constructions,
        velocity_constructions,
    )

    text = (
        (HERE / "slotted_lever_270.toml")
        .read_text(encoding="utf-8")
        .replace("[sliders]", '[points]\nA1 = { on = "O1-P", along = 450 }\n\n[sliders]')
    )
    sol = solve(parse_scene(text))
    for cons, a1 in ((velocity_constructions(sol), "a1"), (acceleration_constructions(sol), "a1'")):
        labels = [c.finds for c in cons] + [lab for c in cons for lab, _ in c.named]
        assert labels.count(a1) == 1, labels
        assert ("a2'" if a1.endswith("'") else "a2") in labels
    assert "meet at a2; then op / oa2 = O1P / O1A" in steps_text(sol)


def test_check_of_a_centre_on_an_axis_shows_no_noise():
    """I25 of the slotted lever at mid-stroke is on the y axis: the check table showed the
    correct position as [4.4904e-14, -116.67] mm."""
    from polygon_method.check import check_answers, verdicts_text
    from polygon_method.scene import parse_scene

    text = (
        (HERE / "slotted_lever_270.toml").read_text(encoding="utf-8")
        + """
[answers]
I_25 = [0, -116.7]
"""
    )
    verdicts = check_answers(solve(parse_scene(text)))
    assert verdicts[0].ok
    text = verdicts_text(verdicts)
    assert "[0, -116.67] mm" in text and not NOISE.search(text)


def test_elliptic_trammel_with_both_sliders_is_refused_as_redundant():
    """A trammel bar BC driven at its middle A by a crank OA = BC / 2, with both ends on
    sliders, is over-constrained (Gruebler 0; the second slider's path holds anyway). The
    refusal said "slider C cannot slide (already fixed)", while C does slide; the scene
    with B's slider alone solves, and C stays on the y axis by itself."""
    from polygon_method import parse_scene
    from polygon_method.common.errors import MobilityError

    text = """
[ground]
O = [0, 0]
[links]
OA = 50
BC = 100
[points]
A = { on = "BC", along = 50 }
{C}
[sliders]
B = { path = "horizontal", through = "O" }
{slider}
[input]
crank = "OA"
angle = 30
speed = "10 rad/s ccw"
"""
    with pytest.raises(MobilityError) as exc:
        solve(
            parse_scene(
                text.replace("{C}", "").replace(
                    "{slider}", 'C = { path = "vertical", through = "O" }'
                )
            )
        )
    assert "slider C is redundant (C is already placed" in str(exc.value)
    assert "cannot slide" not in str(exc.value)
    sol = solve(parse_scene(text.replace("{C}", "").replace("{slider}", "")))
    assert abs(sol.P["C"][0]) < 1e-15 and abs(sol.V["C"][0]) < 1e-15


def test_check_shows_the_correct_value_in_the_answers_own_unit():
    """A problem set in inches is answered in in/s and lbf in: the table showed the correct
    values in SI only ("3.192 m/s" beside "125.7 in/s")."""
    from polygon_method.check import check_answers, verdicts_text
    from polygon_method.scene import parse_scene

    scene, sol, _ = solved(HERE / "fourbar_inches.toml")
    text = (
        (HERE / "fourbar_inches.toml").read_text(encoding="utf-8")
        + """
[answers]
v_A = "125.7 in/s"
omega_A-B = "100 rpm"
v_B = "3 m/s"
"""
    )
    table = verdicts_text(check_answers(solve(parse_scene(text))))
    v_a = math.hypot(*sol.V["A"])
    assert f"{v_a:.4g} m/s ({v_a / 0.0254:.4g} in/s)" in table, table
    w = abs(sol.omega("A-B"))
    assert f"({w * 60 / (2 * math.pi):.4g} rpm)" in table
    row = next(ln for ln in table.splitlines() if ln.startswith("v_B "))
    assert "(" not in row  # given in SI: SI only
    from polygon_method.page.html import check_html  # the page's table says the same

    html = check_html(check_answers(solve(parse_scene(text))), "")
    assert f"{v_a:.4g} m/s ({v_a / 0.0254:.4g} in/s)" in html


def test_sweep_summary_transmission_angle_at_a_change_point_is_zero():
    """A parallelogram's four pivots come into line at crank 0 and 180 deg: its transmission
    angle (equal to the crank angle between 0 and 90 deg) is 0 there. The summary gave
    0.0572958 deg, the refusal threshold's value carried by the samples next to it (and
    the linkage command says 0.00)."""
    from polygon_method.linkage.summary import summarize

    scene = load_scene(HERE / "coupling_rod_90.toml")

    def mu_row(degrees):
        text = summarize(scene, [math.radians(d) for d in degrees]).text()
        return next(ln for ln in text.splitlines() if ln.startswith("mu at C ")).split()

    row = mu_row(range(0, 360, 5))
    assert row[6:8] == ["0", "0.000"] or row[6:8] == ["0", "180.000"], row
    row = mu_row(range(3, 360, 7))  # not sampled at the change points: still found
    assert row[6] == "0" and row[7] in ("0.000", "180.000"), row
    row = mu_row(range(3, 171, 7))  # no change point in the range: the sampled minimum
    assert row[6:8] == ["3", "3.000"], row
