"""Property tests (hypothesis) over the other mechanisms the scene format can state: six-link
chains through a plate, a swivel (a block at a fixed point sliding along a moving link), a
block pinned to a rocker sliding along a moving coupler (Coriolis on a moving guide), and a
dyad built on the side of a plate.

Wherever the tool gives an answer without a warning, it agrees with the 50-digit reference
(Newton on the loop-closure equations) within 1e-9 of the size of each kind of quantity;
every step's condition measure equals the one computed from the reference's own positions;
a refusal is an AssemblyError or a SingularStepError, never a number.
"""

import math

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from polygon_method.errors import TOL, AssemblyError, SingularStepError
from methods import Kinematics, compare
from polygon_method.plan import Dyad, SliderDyad, SlottedLink
from polygon_method.scene import parse_scene
from polygon_method.solution import solve
from reference import reference_solution

SETTINGS = settings(max_examples=40, deadline=None, derandomize=True, database=None,
                    suppress_health_check=[HealthCheck.too_slow, HealthCheck.filter_too_much])

length = st.floats(min_value=20.0, max_value=200.0)
coord = st.floats(min_value=-150.0, max_value=150.0)
angle = st.floats(min_value=0.0, max_value=359.0)
speed = st.floats(min_value=0.5, max_value=50.0)
sense = st.sampled_from(["cw", "ccw"])
accel = st.floats(min_value=0.0, max_value=100.0)


def _sub(a, b):
    return (float(a[0]) - float(b[0]), float(a[1]) - float(b[1]))


def _sine(u, v):
    return abs(u[0] * v[1] - u[1] * v[0]) / (math.hypot(*u) * math.hypot(*v))


def expected_condition(step, P, scene):
    """The condition of a step from positions alone (here: the reference's)."""
    if isinstance(step, Dyad):
        return _sine(_sub(P[step.point], P[step.b]), _sub(P[step.point], P[step.d]))
    if isinstance(step, SliderDyad):
        r = _sub(P[step.point], P[step.b])
        u = step.path.u if step.path is not None else _sub(P[step.g2], P[step.g1])
        return abs(r[0] * u[0] + r[1] * u[1]) / (math.hypot(*r) * math.hypot(*u))
    if isinstance(step, SlottedLink):
        # over the longest other link at the block or the pivot (the guide's own length
        # where none): the size of what places them
        pts = (step.point, step.known)
        others = [lk.length for lk in scene.links
                  if lk.key != step.guide and (lk.p in pts or lk.q in pts)]
        rho = max(others) if others else step.length
        return min(1.0, math.hypot(*_sub(P[step.point], P[step.known])) / rho)
    return 1.0


def verdict(text):
    """Solve a scene; compare with the reference wherever the tool answers."""
    scene = parse_scene(text)
    try:
        sol = solve(scene)
    except (AssemblyError, SingularStepError):
        assume(False)
    r = reference_solution(scene, sol.P)
    ref = Kinematics("reference", r["positions"], r["velocities"], r["accelerations"],
                     r["omega"], r["alpha"],
                     {k: (v["vs"], v["as"]) for k, v in r["sliders"].items()})
    for st_ in sol.plan.steps:
        assert sol.conditions[st_.index] == pytest.approx(
            expected_condition(st_, ref.P, scene), rel=1e-7, abs=1e-12)
    worst = min(sol.conditions.values())
    assert (len(sol.warnings) > 0) == (worst < TOL.warn)
    assume(worst >= TOL.warn)
    kin = Kinematics("solve", sol.P, sol.V, sol.A, sol.W, sol.Al,
                     {k: (v[0], v[1]) for k, v in sol.S.items()})
    err = compare(kin, ref, scene)
    assert err["all"] < 1e-9, err


def _motion(w, s, al):
    return (f'speed = "{w!r} rad/s {s}"\n'
            + (f'acceleration = "{al!r} rad/s^2 {s}"\n' if al else ""))


@SETTINGS
@given(a=length, b=length, c=length, d=length, e1=length, e2=length, f=length, g=length,
       gx=coord, gy=coord, th=angle, w=speed, s=sense, al=accel,
       up=st.booleans(), turn=sense)
def test_six_link_through_a_plate(a, b, c, d, e1, e2, f, g, gx, gy, th, w, s, al, up, turn):
    assume(abs(e1 - e2) < c < e1 + e2)
    verdict(f"""
[ground]
A = [0, 0]
D = [{d!r}, 0]
G = [{gx!r}, {gy!r}]
[links]
AB = {a!r}
BC = {b!r}
CD = {c!r}
EF = {f!r}
FG = {g!r}
[points]
E = {{ on = "CD", distances = {{ C = {e1!r}, D = {e2!r} }}, turn = "{turn}" }}
[assembly]
C = "{'above' if up else 'below'}"
F = "{'below' if up else 'above'}"
[input]
crank = "AB"
angle = {th!r}
{_motion(w, s, al)}""")


@SETTINGS
@given(a=length, L=st.floats(min_value=200.0, max_value=500.0), ox=coord, oy=coord,
       along=st.floats(min_value=-100.0, max_value=300.0), th=angle, w=speed, s=sense,
       al=accel)
def test_swivel_block_at_a_fixed_point(a, L, ox, oy, along, th, w, s, al):
    assume(math.hypot(ox, oy) > a + 5)
    verdict(f"""
[ground]
A = [0, 0]
O = [{ox!r}, {oy!r}]
[links]
AB = {a!r}
BC = {L!r}
[points]
E = {{ on = "BC", along = {along!r} }}
[sliders]
O = {{ along = "BC" }}
[input]
crank = "AB"
angle = {th!r}
{_motion(w, s, al)}""")


@SETTINGS
@given(a=length, b=length, c=length, d=length, hx=coord, hy=coord, h=length, th=angle,
       w=speed, s=sense, al=accel, first=st.booleans())
def test_block_sliding_along_a_moving_coupler(a, b, c, d, hx, hy, h, th, w, s, al, first):
    verdict(f"""
[ground]
A = [0, 0]
D = [{d!r}, 0]
H = [{hx!r}, {hy!r}]
[links]
AB = {a!r}
BC = {b!r}
CD = {c!r}
HX = {h!r}
[sliders]
X = {{ along = "{'BC' if first else 'CB'}" }}
[assembly]
C = "above"
[input]
crank = "AB"
angle = {th!r}
{_motion(w, s, al)}""")


@SETTINGS
@given(a=length, p=length, q=length, r=length, g=length, gx=st.floats(60.0, 200.0),
       th=angle, w=speed, s=sense, al=accel, turn=sense)
def test_dyad_on_the_side_of_a_plate(a, p, q, r, g, gx, th, w, s, al, turn):
    assume(abs(p - q) < r < p + q)
    verdict(f"""
[ground]
A = [0, 0]
G = [{gx!r}, 0]
[links]
AB = {a!r}
BC = {r!r}
EG = {g!r}
[points]
E = {{ on = "BC", distances = {{ B = {p!r}, C = {q!r} }}, turn = "{turn}" }}
[input]
crank = "AB"
angle = {th!r}
{_motion(w, s, al)}""")
