"""Sweeps never jump branch and never keep an impossible row: a scene whose own instant is
at a change point is refused with solve's message; samples exactly at a change point keep
every link's length."""

from __future__ import annotations

import math
import re

import numpy as np
import pytest

from polygon_method import SingularStepError, parse_scene, solve
from polygon_method.linkage.summary import summarize
from polygon_method.motion.sweeps import sweep

PARALLELOGRAM = """
[ground]
A = [0, 0]
D = [100, 0]
[links]
AB = 40
BC = 100
CD = 40
[assembly]
C = "above"
[input]
crank = "AB"
angle = {angle}
speed = "10 rad/s ccw"
"""

ISOSCELES_ENGINE = """
[ground]
O = [0, 0]
[links]
OA = 100
AB = 100
[sliders]
B = {{ path = "horizontal" }}
[input]
crank = "OA"
angle = {angle}
speed = "10 rad/s ccw"
"""


def _message(fn):
    with pytest.raises(SingularStepError) as err:
        fn()
    return err.value.one_line()


@pytest.mark.parametrize(
    "text, angle", [(PARALLELOGRAM, 180.02), (PARALLELOGRAM, -0.03), (ISOSCELES_ENGINE, 90.01)]
)
def test_a_scene_at_a_change_point_is_refused_as_solve_refuses_it(text, angle):
    sc = parse_scene(text.format(angle=angle))
    said = _message(lambda: solve(sc))
    assert _message(lambda: sweep(sc, np.radians([angle - 1.0, angle + 1.0]))) == said
    assert _message(lambda: summarize(sc, np.radians([angle - 1.0, angle + 1.0]))) == said


@pytest.mark.parametrize(
    "lengths, angle", [((100, 100, 100), 90), ((100, 60, 60), 30)], ids=["rhombus", "deltoid"]
)
def test_samples_at_a_change_point_keep_every_link_length(lengths, angle):
    ab, bc, cd = lengths
    text = f"""
    [ground]
    A = [0, 0]
    D = [100, 0]
    [links]
    AB = {ab}
    BC = {bc}
    CD = {cd}
    [input]
    crank = "AB"
    angle = {angle}
    speed = "10 rad/s ccw"
    """
    sc = parse_scene(text)
    res = sweep(sc, np.radians(np.arange(0.0, 360.0, 0.5)))
    assert len(res) > 0
    for lk in sc.links:
        (px, py), (qx, qy) = res.P[lk.p], res.P[lk.q]
        off = np.abs(np.hypot(qx - px, qy - py) - lk.length)
        assert off.max() <= 1e-9 * lk.length, (lk.key, float(off.max()))
    assert np.isfinite(res.W["CD"]).all() and np.isfinite(res.Al["CD"]).all()


def test_the_stated_branch_is_followed_on_both_sides():
    """Just clear of the change point the parallelogram stays a parallelogram: the
    follower turns with the crank (omega_CD = omega_AB) on both sides of the scene."""
    sc = parse_scene(PARALLELOGRAM.format(angle=175.0))
    res = sweep(sc, np.radians(np.arange(170.0, 180.0, 0.5)))
    assert np.allclose(res.W["CD"], 10.0, rtol=1e-9)
    assert math.isclose(solve(sc).W["CD"], 10.0, rel_tol=1e-9)


def test_an_extreme_at_a_limit_position_is_said_to_grow_without_bound():
    """Towards a toggle of the driven side omega_CD grows as 1 / sqrt(d) and alpha_CD as
    1 / d^1.5: the summary says so, at the limit position, whatever the sampling."""
    from pathlib import Path
    from polygon_method import load_scene

    sc = load_scene(
        Path(__file__).resolve().parent.parent / "worked_problems" / "fourbar_image_points.toml"
    )
    for n in (360, 36000):
        s = summarize(sc, np.radians(np.linspace(0.0, 360.0, n, endpoint=False)))
        lims = sorted(s.deg(lp.theta) for lp in s.limits)
        w = s.extreme("omega_CD")
        assert w.max_unbounded and w.min_unbounded
        assert {round(w.at_max, 6), round(w.at_min, 6)} == {round(x, 6) for x in lims}
        assert s.extreme("a_C").max_unbounded and not s.extreme("a_C").min_unbounded
        assert s.extreme("v_B").constant and not s.extreme("v_B").max_unbounded
        assert "grows without bound towards the limit position" in s.text()


def test_a_crank_that_turns_fully_has_no_unbounded_extreme():
    from pathlib import Path
    from polygon_method import load_scene

    sc = load_scene(
        Path(__file__).resolve().parent.parent
        / "worked_problems"
        / "fourbar_crank_acceleration.toml"
    )
    s = summarize(sc)
    assert not any(e.max_unbounded or e.min_unbounded for e in s.extremes)


from hypothesis import HealthCheck, event, given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

from polygon_method import PolygonMethodError  # noqa: E402


@settings(max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    shape=st.sampled_from(["parallelogram", "rhombus", "deltoid", "isosceles"]),
    angle=st.one_of(
        st.sampled_from([0.0, 180.0, 90.0, -0.001, 179.999, 90.01]), st.floats(-360.0, 360.0)
    ),
    lo=st.floats(-400.0, 400.0),
    span=st.floats(0.0, 400.0),
    n=st.integers(1, 400),
)
def test_fuzz_sweeps_near_change_points(shape, angle, lo, span, n):
    """Linkages with change points, swept from any stated angle over any range: a sweep
    either refuses in one error of the family, or every row it keeps is a possible
    position (every link at its length) with finite values."""
    if shape == "isosceles":
        text = ISOSCELES_ENGINE.format(angle=angle)
    else:
        ab, bc, cd = {
            "parallelogram": (40, 100, 40),
            "rhombus": (100, 100, 100),
            "deltoid": (100, 60, 60),
        }[shape]
        text = f"""
        [ground]
        A = [0, 0]
        D = [100, 0]
        [links]
        AB = {ab}
        BC = {bc}
        CD = {cd}
        [input]
        crank = "AB"
        angle = {angle}
        speed = "10 rad/s ccw"
        """
    try:
        sc = parse_scene(text)
        res = sweep(sc, np.radians(np.linspace(lo, lo + span, n)))
    except PolygonMethodError as exc:  # a refusal: one line, naming what it refuses
        line = exc.one_line()
        assert line.strip() and "\n" not in line, line
        assert not re.search(r"\b(nan|inf)\b", line.lower()), line
        event("refused")
        return
    event("swept")
    for lk in sc.links:
        (px, py), (qx, qy) = res.P[lk.p], res.P[lk.q]
        off = np.abs(np.hypot(qx - px, qy - py) - lk.length)
        assert (off <= 1e-9 * lk.length).all(), (lk.key, float(off.max()))
    for arrays in (res.W, res.Al):
        for v in arrays.values():
            assert np.isfinite(v).all()
