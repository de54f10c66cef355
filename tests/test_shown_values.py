"""Values shown as 0 are zeros within their own error bound, never real values that are small
beside an unrelated huge one (near a toggle the largest acceleration is 1e12 m/s^2 while a
point near the crank's pivot, a block's sliding acceleration and its Coriolis component are
tens of m/s^2). Each value is compared with the 50-digit reference (tests/reference.py)
and, for the carried point, with the closed form omega^2 r."""

from __future__ import annotations

import math

import pytest

from reference import reference_solution
from polygon_method import parse_scene, solve
from polygon_method.check import check_answers
from polygon_method.text.report import solution_text
from polygon_method.motion.tidy import tidied
from polygon_method.text.steptable import steps_text

SCENE = """
units = "mm"
[ground]
O2 = [0, 0]
O4 = [200, 0]
O5 = [0, {pivot}]
[links]
"O2-A" = 150
"A-B" = 450
"B-O4" = 300
"O5-Q" = 600
[points]
C = {{ on = "O2-A", from = "O2", along = {r} }}
[sliders]
C = {{ along = "O5-Q" }}
[assembly]
B = "above"
[input]
crank = "O2-A"
angle = {angle!r}
speed = "{w} rad/s ccw"
"""

#: the crank angle where A-B and B-O4 fold into one line (O4A = AB - BO4)
LIMIT = math.degrees(math.acos(2 / 3))

#: (degrees past the limit, the carried point's radius in mm, crank speed, the lever's
#: pivot): each with the carried point's acceleration below 1e-10 of the largest
CASES = [
    (2.2e-4, 1.0, 200.0, -5.0),
    (2.2e-4, 0.3, 50.0, 4.0),
    (2.2e-4, 0.05, 1000.0, -12.0),
    (4e-4, 0.3, 3.0, -5.0),
    (4e-4, 0.05, 200.0, 7.0),
    (1e-3, 0.05, 20.0, -3.0),
]


def _case(d, r, w, pivot):
    sc = parse_scene(SCENE.format(angle=LIMIT + d, r=r, w=w, pivot=pivot))
    sol = solve(sc)
    return sc, sol, reference_solution(sc, dict(sol.P))


@pytest.mark.parametrize("d, r, w, pivot", CASES)
def test_nothing_above_its_bound_is_zeroed(d, r, w, pivot):
    sc, sol, ref = _case(d, r, w, pivot)
    big = max(math.hypot(*a) for a in sol.A.values())
    small = w * w * r / 1000  # a_C = omega^2 r (a constant crank speed)
    assert small < 1e-10 * big  # the family applies: the old rule hid it
    clean = tidied(sol)
    checked = 0
    for p in sc.point_names:
        for mine, table, kind in (
            (clean.V[p], ref["velocities"], "v"),
            (clean.A[p], ref["accelerations"], "a"),
        ):
            true = float(math.hypot(*table[p]))
            if mine == (0.0, 0.0):
                assert true <= sol.noise(kind, p) * (1 + 1e-9) or true == 0
            elif true > 2 * sol.noise(kind, p):  # shown: right to its bound (a component
                # within the bound may be 0)
                assert abs(math.hypot(*mine) - true) <= sol.noise(kind, p) + 1e-9 * true
                checked += 1
    for lk in sc.links:
        for mine, table, kind in (
            (clean.W[lk.key], ref["omega"], "omega"),
            (clean.Al[lk.key], ref["alpha"], "alpha"),
        ):
            true = float(table[lk.key])
            if mine == 0.0:
                assert abs(true) <= sol.noise(kind, lk.key) * (1 + 1e-9)
            else:
                checked += 1
    s = ref["sliders"]["C"]
    vs, a_s, cx, cy = clean.S["C"]
    assert a_s == pytest.approx(float(s["as"]), rel=1e-6) and a_s != 0
    cor = float(math.hypot(*s["coriolis"]))
    assert cor > 2 * sol.noise("ac", "C")
    assert abs(math.hypot(cx, cy) - cor) <= sol.noise("ac", "C") + 1e-9 * cor
    assert math.hypot(*clean.A["C"]) == pytest.approx(small, rel=1e-9)
    assert checked >= 10


@pytest.mark.parametrize("d, r, w, pivot", CASES[::2])
def test_reports_show_the_small_values(d, r, w, pivot):
    sc, sol, ref = _case(d, r, w, pivot)
    small = w * w * r / 1000
    shown = f"{small:.4g} at"
    text = solution_text(sol)
    row = next(line for line in text.splitlines() if line.startswith("C "))
    assert shown in row
    slider = next(line for line in text.splitlines() if line.startswith("C ") and "O5-Q" in line)
    a_s = float(ref["sliders"]["C"]["as"])
    assert f"{a_s:<20.5g}".strip() in slider.split()
    steps = steps_text(sol)
    assert any(
        line.strip().startswith("a_C ") and line.rstrip().endswith(f"{small:.4g} m/s^2")
        for line in steps.splitlines()
    )


@pytest.mark.parametrize("d, r, w, pivot", CASES[1::3])
def test_check_does_not_pass_a_wrong_answer_for_a_small_value(d, r, w, pivot):
    sc, sol, _ = _case(d, r, w, pivot)
    small = w * w * r / 1000
    ans = parse_scene(
        SCENE.format(angle=LIMIT + d, r=r, w=w, pivot=pivot)
        + f'[answers]\ntolerance = "1%"\na_C = "{12345 + small} m/s^2"\n'
        f'as_C = "{12345} m/s^2"\n'
    )
    got = check_answers(solve(ans))
    assert [v.ok for v in got] == [False, False]
    assert got[0].correct == pytest.approx(small, rel=1e-9)


# ----- sweep summaries: each extreme is zeroed only within its own bound

TINY_CRANK = """
units = "m"
[ground]
A = [0, 0]
D = [10000, 0]
[links]
AB = {r!r}
BC = 10000
CD = 10000
[assembly]
C = "above"
[input]
crank = "AB"
angle = {angle!r}
speed = "10 rad/s ccw"
"""


@pytest.mark.parametrize("r", [1e-6, 4e-6])
def test_a_summary_shows_what_is_small_beside_the_input_sizes(r):
    """A crank of r (micrometres) driving links 10 km long: every speed is below 1e-9 of
    omega times the longest link, the size the summary once called zero below. The
    crank pin's speed and acceleration are omega r and omega^2 r (closed form), and the
    rocker's largest omega is the 50-digit reference's at the angle the summary gives."""
    from polygon_method.linkage.summary import summarize

    s = summarize(parse_scene(TINY_CRANK.format(r=r, angle=30.0)))
    vb, ab = s.extreme("v_B"), s.extreme("a_B")
    assert vb.constant and math.isclose(vb.maximum, 10 * r, rel_tol=1e-9), vb
    assert ab.constant and math.isclose(ab.maximum, 100 * r, rel_tol=1e-9), ab
    w = s.extreme("omega_CD")
    assert w.maximum > 0 > w.minimum, w
    sc = parse_scene(TINY_CRANK.format(r=r, angle=float(w.at_max)))
    ref = reference_solution(sc, solve(sc).P)
    assert math.isclose(w.maximum, float(ref["omega"]["CD"]), rel_tol=1e-9), (w, ref["omega"])
    assert "(constant)" in s.text() and f"{10 * r:.6g}" in s.text()
