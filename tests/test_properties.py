"""Property tests (hypothesis): random four-bars, slider-cranks (in-line and offset) and
quick-return mechanisms (crank and slotted lever) against the 50-digit reference.

Wherever every step's condition measure is at or above TOL.warn, the production path
agrees with the reference within 1e-9 of the size of each kind of quantity over the
mechanism (``methods.compare``); below it the warning appears (and below TOL.singular
the step refuses). The condition measure itself is checked against the geometry of the
reference positions. A position that cannot be assembled must be refused with an
AssemblyError, checked against the geometry too.
"""

import math

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from polygon_method.common.errors import TOL, AssemblyError, SingularStepError
from methods import Kinematics, compare
from polygon_method.scene import parse_scene
from polygon_method.motion.solution import solve
from reference import reference_solution

REL = 1e-9
SETTINGS = settings(
    max_examples=60,
    deadline=None,
    derandomize=True,
    database=None,
    suppress_health_check=[HealthCheck.too_slow],
)

length = st.floats(min_value=20.0, max_value=200.0, allow_nan=False)
angle = st.floats(min_value=0.0, max_value=360.0, allow_nan=False, exclude_max=True)
speed = st.floats(min_value=0.5, max_value=50.0) | st.floats(min_value=-50.0, max_value=-0.5)
accel = st.floats(min_value=-200.0, max_value=200.0)


def motion(w, al):
    sense = "ccw" if w > 0 else "cw"
    asense = "ccw" if al >= 0 else "cw"
    return f'speed = "{abs(w)!r} rad/s {sense}"\n' + (
        f'acceleration = "{abs(al)!r} rad/s^2 {asense}"\n' if al else ""
    )


def reference(scene, guess):
    r = reference_solution(scene, guess)
    return Kinematics(
        "reference",
        r["positions"],
        r["velocities"],
        r["accelerations"],
        r["omega"],
        r["alpha"],
        {k: (v["vs"], v["as"]) for k, v in r["sliders"].items()},
    )


def sine_between(u, v):
    u = (float(u[0]), float(u[1]))
    v = (float(v[0]), float(v[1]))
    return abs(u[0] * v[1] - u[1] * v[0]) / (math.hypot(*u) * math.hypot(*v))


def sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def check(scene, expected_conditions):
    """Solve; compare with the reference and the independent condition measures.

    ``expected_conditions(P)``: step index -> condition, from reference positions P.
    """
    try:
        sol = solve(scene)
    except SingularStepError:
        # only where the geometry says so: find the reference near the singular position
        return "singular"
    ref = reference(scene, sol.P)
    conds = expected_conditions(ref.P)
    for i, c in conds.items():
        assert sol.conditions[i] == pytest.approx(c, rel=1e-7, abs=1e-12)
    worst = min(conds.values())
    assert (len(sol.warnings) > 0) == (worst < TOL.warn)
    if worst >= TOL.warn:
        kin = Kinematics(
            "solve", sol.P, sol.V, sol.A, sol.W, sol.Al, {k: (v[0], v[1]) for k, v in sol.S.items()}
        )
        err = compare(kin, ref, scene)
        assert err["all"] < REL, err
    return "warned" if worst < TOL.warn else "ok"


# --------------------------------------------------------------------------- four-bars


@SETTINGS
@given(
    a=length,
    b=length,
    c=length,
    d=length,
    th=angle,
    w=speed,
    al=accel,
    branch=st.sampled_from(["above", "below"]),
)
def test_random_fourbar(a, b, c, d, th, w, al, branch):
    text = f"""
[ground]
A = [0, 0]
D = [{d!r}, 0]
[links]
AB = {a!r}
BC = {b!r}
CD = {c!r}
[assembly]
C = "{branch}"
[input]
crank = "AB"
angle = {th!r}
{motion(w, al)}"""
    t = math.radians(th)
    bx, by = a * math.cos(t), a * math.sin(t)
    e = math.hypot(d - bx, by)
    if e > b + c or e < abs(b - c):  # the two circles miss each other
        with pytest.raises(AssemblyError):
            solve(parse_scene(text))
        return
    assume(min(b + c - e, e - abs(b - c)) > 1e-9 * (b + c))  # not touching in floats
    scene = parse_scene(text)

    def conditions(P):  # 1: the crank; 2: the transmission angle at C
        return {0: 1.0, 1: sine_between(sub(P["C"], P["B"]), sub(P["C"], P["D"]))}

    check(scene, conditions)


# --------------------------------------------------------------------------- slider-cranks


@SETTINGS
@given(
    r=length,
    ratio=st.floats(min_value=1.05, max_value=6.0),
    e=st.floats(-0.9, 0.9),
    inline=st.booleans(),
    th=angle,
    w=speed,
    al=accel,
    path=st.sampled_from(["horizontal", "vertical", "30 deg"]),
)
def test_random_slider_crank(r, ratio, e, inline, th, w, al, path):
    ell = r * ratio
    off = 0.0 if inline else e * (ell - r)  # |offset| < l - r: the crank turns fully
    u = {"horizontal": 0.0, "vertical": 90.0, "30 deg": 30.0}[path]
    ux, uy = math.cos(math.radians(u)), math.sin(math.radians(u))
    through = (-uy * off, ux * off)
    text = f"""
[ground]
O = [0, 0]
[links]
OA = {r!r}
AB = {ell!r}
[sliders]
B = {{ path = "{path}", through = [{through[0]!r}, {through[1]!r}] }}
[input]
crank = "OA"
angle = {th!r}
{motion(w, al)}"""
    scene = parse_scene(text)

    def conditions(P):  # the rod against the guide's normal: |cos(rod, guide)|
        rod = sub(P["B"], P["A"])
        return {0: 1.0, 1: sine_between(rod, (-uy, ux))}

    assert check(scene, conditions) == "ok"  # |offset| < l - r: never near dead centre


# --------------------------------------------------------------------------- quick return


@SETTINGS
@given(
    crank=st.floats(min_value=30.0, max_value=120.0),
    centres=st.floats(min_value=1.2, max_value=4.0),
    lever=st.floats(min_value=1.1, max_value=2.0),
    th=angle,
    w=speed,
    al=accel,
    with_ram=st.booleans(),
)
def test_random_quick_return(crank, centres, lever, th, w, al, with_ram):
    """Crank O2-A turning fully; block A slides along the slotted lever O4-P."""
    c = crank * centres  # O2 above O4 by c > crank: the lever swings (quick return)
    L = (c + crank) * lever  # the lever reaches past the block
    ram = ""
    ram_slider = ""
    if with_ram:
        h = L * 0.97
        ram = f'"P-Q" = {L * 0.5!r}'
        ram_slider = f'Q = {{ path = "horizontal", through = [0, {h!r}] }}'
    text = f"""
[ground]
O2 = [0, {c!r}]
O4 = [0, 0]
[links]
"O2-A" = {crank!r}
"O4-P" = {L!r}
{ram}
[sliders]
A = {{ along = "O4-P" }}
{ram_slider}
[assembly]
P = "above"
{'Q = "right"' if with_ram else ""}
[input]
crank = "O2-A"
angle = {th!r}
{motion(w, al)}"""
    scene = parse_scene(text)

    def conditions(P):
        # the block's distance from the pivot over the crank, the link that places it
        out = {0: 1.0, 1: min(math.hypot(*map(float, sub(P["A"], P["O4"]))) / (crank * 1e-3), 1.0)}
        if with_ram:
            out[2] = sine_between(sub(P["Q"], P["P"]), (0.0, 1.0))
        return out

    result = check(scene, conditions)
    assert result in ("ok", "warned")
