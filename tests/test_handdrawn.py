"""The default tolerance of rubbing velocities, the input torque and the sliding quantities
(sliding velocity and acceleration, Coriolis) from the simulated careful hand drawing.

Each is checked against how the quantity is built by hand, not against the tool's own
numbers: a drawing a student could make (the mechanism drawn with its crank angle a
quarter of a degree off, solved, the value rounded to three figures) passes; the spread of
a value built from others is bounded by theirs (rub = |w1 -/+ w2| r, T = F v / omega,
Coriolis = 2 omega vs); each known mistake, made in the arithmetic here, is still caught;
a stated tolerance still overrides.
"""

import math
from pathlib import Path

import pytest

from polygon_method import load_scene, parse_scene, solve
from polygon_method.check import check_answers
from polygon_method.scene import parse_answers

ROOT = Path(__file__).resolve().parent.parent / "worked_problems"
TOGGLE = ROOT / "toggle_mechanism.toml"
LEVER = ROOT / "crank_slotted_lever.toml"
WHITWORTH = ROOT / "whitworth.toml"


def verdicts(scene, text, tolerance=None):
    _, answers = parse_answers("[answers]\n" + text, scene)
    return {v.key: v for v in check_answers(solve(scene), answers, tolerance)}


def drawn(path, angle_off):
    """The scene with its crank angle as a pencil sets it out, ``angle_off`` deg off."""
    text = path.read_text()
    old = next(ln for ln in text.splitlines() if ln.startswith("angle = "))
    value = float(old.split("=")[1].split("#")[0])
    return parse_scene(text.replace(old, f"angle = {value + angle_off}"))


KEYS = {
    TOGGLE: ("rub_A", "rub_D", "torque", "vs_D"),
    LEVER: ("vs_A", "as_A", "ac_A"),
    WHITWORTH: ("vs_A", "as_A", "ac_A"),
}
UNITS = {"rub": "m/s", "vs": "m/s", "as": "m/s^2", "ac": "m/s^2", "torque": "N m"}


@pytest.mark.parametrize("path", list(KEYS), ids=lambda p: p.stem)
def test_a_plausible_hand_drawing_passes(path):
    """The answers of a drawing whose crank angle is 0.25 deg off, to three figures, are
    right under the default tolerance, which says it is the hand drawing's."""
    scene = load_scene(path)
    for off in (0.25, -0.25):
        hand = solve(drawn(path, off))
        text = ""
        for key in KEYS[path]:
            kind, _, name = key.partition("_")
            value = hand.value(kind, (name,) if name else ())
            text += f'{key} = "{abs(value):.3g} {UNITS[kind]}"\n'
        got = verdicts(scene, text)
        for key in KEYS[path]:
            v = got[key]
            assert v.ok, (key, off, v.error, v.tolerance)
            assert "hand drawing" in v.rule, v.rule


def tolerance_of(scene, key, value, unit):
    v = verdicts(scene, f'{key} = "{value!r} {unit}"\n')[key]
    return v.tolerance


def test_the_spread_of_a_built_quantity_is_bounded_by_its_factors():
    """rub = |w1 - w2| r from the drawn omegas; T = F v_D / omega with one force along the
    path (so its relative spread is that of v_D); Coriolis = 2 omega vs (within the sum of
    the relative spreads of its factors)."""
    sc = load_scene(TOGGLE)
    sol = solve(sc)
    tol = lambda key, x, unit: tolerance_of(sc, key, x, unit)  # noqa: E731
    # pin A joins the crank OA (its omega is given, exact) and AB
    r_a = 0.015
    w_ab = abs(sol.W["AB"])
    rub_a = abs(sol.W["OA"] - sol.W["AB"]) * r_a
    t_rub = tol("rub_A", rub_a, "m/s") * rub_a
    t_w = tol("omega_AB", w_ab, "rad/s") * w_ab
    assert t_rub <= 1.1 * r_a * t_w
    # one force along the slider's path: T = F v_D / omega
    v_d = sol.speed("D")
    torque = 2000 * v_d / abs(sol.W["OA"])
    assert abs(sol.input_torque) == pytest.approx(torque, rel=1e-9)
    assert tol("torque", torque, "N m") == pytest.approx(tol("vs_D", v_d, "m/s"), rel=0.25)
    # Coriolis on the slotted lever: 2 omega vs
    sc = load_scene(LEVER)
    sol = solve(sc)
    w = abs(sol.W[sc.link("O4-P").key])
    vs = abs(sol.sliding_velocity("A"))
    ac = 2 * w * vs
    assert math.hypot(*sol.coriolis("A")) == pytest.approx(ac, rel=1e-9)
    t_ac = tolerance_of(sc, "ac_A", ac, "m/s^2")
    t_sum = tolerance_of(sc, "omega_O4-P", w, "rad/s") + tolerance_of(sc, "vs_A", vs, "m/s")
    assert t_ac <= 1.1 * t_sum
    assert t_ac > 0.005


def test_known_mistakes_on_these_quantities_are_still_caught():
    """Made here in the arithmetic, each is WRONG under the default tolerance and named."""
    sc = load_scene(TOGGLE)
    sol = solve(sc)
    w_oa, w_ab, w_bd = sol.W["OA"], sol.W["AB"], sol.W["BD"]
    r = 0.015
    if (w_oa > 0) == (w_ab > 0):  # alike: the difference applies; the sum is the slip
        rub_wrong, code = (abs(w_oa) + abs(w_ab)) * r, "sum_for_difference"
    else:
        rub_wrong, code = abs(abs(w_oa) - abs(w_ab)) * r, "difference_for_sum"
    v_d = sol.speed("D")
    power = 2000 * v_d
    cases = [
        ("rub_A", rub_wrong, "m/s", code),
        ("rub_A", abs(w_oa - w_ab) * 2 * r, "m/s", "diameter_as_radius"),
        ("rub_D", abs(w_bd) * 2 * r, "m/s", "diameter_as_radius"),
        ("torque", power / abs(w_ab), "N m", "wrong_omega_in_power_balance"),
        ("torque", power / (abs(w_oa) * 60 / (2 * math.pi)), "N m", "rpm_as_rad_s"),
    ]
    for key, value, unit, code in cases:
        v = verdicts(sc, f'{key} = "{value:.4g} {unit}"\n')[key]
        assert not v.ok and v.mistake == code, (key, code, v.mistake, v.tolerance)
    sc = load_scene(LEVER)
    sol = solve(sc)
    w = abs(sol.W[sc.link("O4-P").key])
    vs = abs(sol.sliding_velocity("A"))
    cases = [
        ("ac_A", w * vs, "m/s^2", "coriolis_factor"),
        ("vs_A", sol.speed("A"), "m/s", "absolute_for_relative"),
    ]
    for key, value, unit, code in cases:
        v = verdicts(sc, f'{key} = "{value:.4g} {unit}"\n')[key]
        assert not v.ok and v.mistake == code, (key, code, v.mistake, v.tolerance)


def test_a_stated_tolerance_overrides_the_hand_drawing():
    sc = load_scene(TOGGLE)
    sol = solve(sc)
    torque = abs(sol.input_torque)
    text = f'torque = "{torque * 1.02:.5g} N m"\nvs_D = "{sol.speed("D") * 1.02:.5g} m/s"\n'
    free = verdicts(sc, text)
    assert all(v.ok and "hand drawing" in v.rule for v in free.values())
    strict = verdicts(sc, text, tolerance=0.01)
    assert all(not v.ok and "answers' tolerance" in v.rule for v in strict.values())


# The answers in the worked problems that their books or notes read off a drawn diagram,
# and, apart, those the files document as slips or method errors (each must still be
# caught, and named where the mistake is a known one).
DRAWN = (
    "fourbar_velocity_khurmi",
    "slider_crank_midpoint",
    "fourbar_image_points",
    "toggle_mechanism",
    "two_slider_mechanism",
)
DOCUMENTED_MISTAKES = {
    ("fourbar_image_points", "v_CB"): "transcription_slip",
    ("toggle_mechanism", "v_BD"): "transcription_slip",
    ("toggle_mechanism", "rub_A"): "links_not_at_pin",
    ("toggle_mechanism", "torque"): "wrong_omega_in_power_balance",
    ("two_slider_mechanism", "v_D"): None,
}  # (the lost figure's BC)


def test_nine_in_ten_published_drawn_answers_pass_by_default():
    """The default tolerance (the pencil and the ruler's 1 mm division) lets at least 9 in
    10 of the published drawn answers through (the books' own values, not this tool's),
    while every mistake the problem files document is still WRONG and named."""
    passed = total = 0
    for stem in DRAWN:
        scene = load_scene(ROOT / f"{stem}.toml")
        for v in check_answers(solve(scene), scene.answers, None):
            if (stem, v.key) in DOCUMENTED_MISTAKES:
                code = DOCUMENTED_MISTAKES[stem, v.key]
                assert not v.ok and v.mistake == code, (stem, v.key, v.mistake)
                continue
            total += 1
            passed += v.ok
    assert total >= 25
    assert passed >= 0.9 * total, (passed, total)
