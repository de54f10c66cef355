"""Property tests (hypothesis) over the other mechanisms the scene format can state: six-link
chains through a plate, a swivel (a block at a fixed point sliding along a moving link), a
block pinned to a rocker sliding along a moving coupler (Coriolis on a moving guide), and a
dyad built on the side of a plate.

Each mechanism is built from its positions, with every step's condition above the
warning's by construction (no generated case is filtered out or skipped): the tool solves
it without a warning, agrees with the 50-digit reference (Newton on the loop-closure
equations) within 1e-9 of the size of each kind of quantity, and every step's condition
measure equals the one computed from the reference's own positions.
"""

import math

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from polygon_method.common.errors import TOL
from methods import Kinematics, compare
from polygon_method.solver.plan import Dyad, SliderDyad, SlottedLink
from polygon_method.scene import parse_scene
from polygon_method.motion.solution import solve
from reference import reference_solution

SETTINGS = settings(
    max_examples=40,
    deadline=None,
    derandomize=True,
    database=None,
    suppress_health_check=[HealthCheck.too_slow],
)

# Every mechanism is built from its positions at the instant, every step's condition at
# least sin 6 deg (above the warning's sin 5 deg) by construction, its lengths and
# assembly read off them: each generated case applies, none is filtered out.
length = st.floats(min_value=20.0, max_value=200.0)
coord = st.floats(min_value=-150.0, max_value=150.0)
angle = st.floats(min_value=0.0, max_value=359.0)
speed = st.floats(min_value=0.5, max_value=50.0)
sense = st.sampled_from(["cw", "ccw"])
accel = st.floats(min_value=0.0, max_value=100.0)
direction = st.floats(min_value=-math.pi, max_value=math.pi)
#: an angle between two direction lines whose sine is at least sin 6 deg, either side
apart = st.floats(min_value=math.radians(6.5), max_value=math.radians(173.5)).flatmap(
    lambda x: st.sampled_from([x, -x])
)


def _at(p, r, ang):
    return (p[0] + r * math.cos(ang), p[1] + r * math.sin(ang))


def _dist(p, q):
    return math.hypot(p[0] - q[0], p[1] - q[1])


def _dir(p, q):
    return math.atan2(q[1] - p[1], q[0] - p[0])


def _turn(p, q, x):
    """How the triangle p, q, x reads."""
    return "ccw" if (q[0] - p[0]) * (x[1] - p[1]) - (q[1] - p[1]) * (x[0] - p[0]) > 0 else "cw"


def _xy(p):
    return f"[{p[0]!r}, {p[1]!r}]"


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
        others = [
            lk.length for lk in scene.links if lk.key != step.guide and (lk.p in pts or lk.q in pts)
        ]
        rho = max(others) if others else step.length
        return min(1.0, math.hypot(*_sub(P[step.point], P[step.known])) / rho)
    return 1.0


def verdict(text):
    """Solve a scene; compare with the reference wherever the tool answers."""
    scene = parse_scene(text)
    sol = solve(scene)  # built to assemble, every condition above the warning's
    r = reference_solution(scene, sol.P)
    ref = Kinematics(
        "reference",
        r["positions"],
        r["velocities"],
        r["accelerations"],
        r["omega"],
        r["alpha"],
        {k: (v["vs"], v["as"]) for k, v in r["sliders"].items()},
    )
    for st_ in sol.plan.steps:
        assert sol.conditions[st_.index] == pytest.approx(
            expected_condition(st_, ref.P, scene), rel=1e-7, abs=1e-12
        )
    worst = min(sol.conditions.values())
    assert worst >= TOL.warn and not sol.warnings
    kin = Kinematics(
        "solve", sol.P, sol.V, sol.A, sol.W, sol.Al, {k: (v[0], v[1]) for k, v in sol.S.items()}
    )
    err = compare(kin, ref, scene)
    assert err["all"] < 1e-9, err


def _motion(w, s, al):
    return f'speed = "{w!r} rad/s {s}"\n' + (f'acceleration = "{al!r} rad/s^2 {s}"\n' if al else "")


def _four_bar(a, th, e, delta, mu, frac):
    """A at the origin, B on the crank AB at ``th`` deg, D at ``e`` from B (direction
    ``delta``), C with the angle BCD of ``mu`` (its sine at least sin 6 deg) and the angle
    BDC ``frac`` of what is left of the triangle: (B, C, D, BC, CD) by the law of sines."""
    B = _at((0.0, 0.0), a, math.radians(th))
    D = _at(B, e, delta)
    at_d = frac * (math.pi - abs(mu))
    at_b = math.pi - abs(mu) - at_d
    b = e * math.sin(at_d) / math.sin(abs(mu))
    C = _at(B, b, delta + math.copysign(at_b, mu))
    return B, C, D, b, _dist(C, D)


triangle = st.floats(min_value=0.05, max_value=0.95)


@SETTINGS
@given(
    a=length,
    e=length,
    delta=direction,
    th=angle,
    mu=apart,
    frac=triangle,
    psi=apart,
    e1=length,
    f=length,
    chi=direction,
    nu=apart,
    g=length,
    w=speed,
    s=sense,
    al=accel,
)
def test_six_link_through_a_plate(a, e, delta, th, mu, frac, psi, e1, f, chi, nu, g, w, s, al):
    B, C, D, b, c = _four_bar(a, th, e, delta, mu, frac)
    E = _at(C, e1, _dir(C, D) + psi)  # the plate CDE: E off the line CD
    F = _at(E, f, chi)
    G = _at(F, g, chi + math.pi + nu)  # the angle at F between FE and FG: nu
    verdict(f"""
[ground]
A = [0, 0]
D = {_xy(D)}
G = {_xy(G)}
[links]
AB = {a!r}
BC = {b!r}
CD = {c!r}
EF = {f!r}
FG = {g!r}
[points]
E = {{ on = "CD", distances = {{ C = {e1!r}, D = {_dist(E, D)!r} }}, turn = "{_turn(C, D, E)}" }}
[assembly]
C = {_xy(C)}
F = {_xy(F)}
[input]
crank = "AB"
angle = {th!r}
{_motion(w, s, al)}""")


@SETTINGS
@given(
    a=length,
    L=st.floats(min_value=200.0, max_value=500.0),
    ro=st.floats(min_value=1.1, max_value=2.5),
    beta=direction,
    along=st.floats(min_value=-100.0, max_value=300.0),
    th=angle,
    w=speed,
    s=sense,
    al=accel,
)
def test_swivel_block_at_a_fixed_point(a, L, ro, beta, along, th, w, s, al):
    """O at least 1.1 times the crank's length from A: the block at O at least 0.1 of the
    crank from B (the slotted step's condition above sin 6 deg)."""
    ox, oy = _at((0.0, 0.0), ro * a, beta)
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
@given(
    a=length,
    e=length,
    delta=direction,
    th=angle,
    mu=apart,
    frac=triangle,
    t=st.floats(min_value=-0.5, max_value=1.5),
    h=length,
    psi=st.floats(min_value=0.0, max_value=math.radians(83.5)),
    other=st.booleans(),
    w=speed,
    s=sense,
    al=accel,
    first=st.booleans(),
)
def test_block_sliding_along_a_moving_coupler(
    a, e, delta, th, mu, frac, t, h, psi, other, w, s, al, first
):
    """X on the line BC, the rod HX at ``psi`` (at most 83.5 deg) from it: the slider
    step's condition |cos psi| above sin 6 deg."""
    B, C, D, b, c = _four_bar(a, th, e, delta, mu, frac)
    X = (B[0] + t * (C[0] - B[0]), B[1] + t * (C[1] - B[1]))
    H = _at(X, h, _dir(B, C) + (math.pi if other else 0.0) + psi)
    verdict(f"""
[ground]
A = [0, 0]
D = {_xy(D)}
H = {_xy(H)}
[links]
AB = {a!r}
BC = {b!r}
CD = {c!r}
HX = {h!r}
[sliders]
X = {{ along = "{"BC" if first else "CB"}" }}
[assembly]
C = {_xy(C)}
X = {_xy(X)}
[input]
crank = "AB"
angle = {th!r}
{_motion(w, s, al)}""")


@SETTINGS
@given(
    a=length,
    th=angle,
    bg=st.floats(min_value=40.0, max_value=200.0),
    beta=direction,
    eps_=apart,
    frac=st.floats(min_value=0.1, max_value=0.9),
    r=length,
    gamma=apart,
    w=speed,
    s=sense,
    al=accel,
)
def test_dyad_on_the_side_of_a_plate(a, th, bg, beta, eps_, frac, r, gamma, w, s, al):
    """E found by the dyad on the plate's side BE and the link EG, at an angle ``eps_``
    at E (sine at least sin 6 deg); C on the plate at ``gamma`` from BE at B."""
    B = _at((0.0, 0.0), a, math.radians(th))
    G = _at(B, bg, beta)
    p = frac * bg  # BE shorter than BG: the far root of the law of cosines is positive
    g = p * math.cos(eps_) + math.sqrt(bg * bg - (p * math.sin(eps_)) ** 2)
    # E: |BE| = p, |GE| = g, the angle BEG = |eps_|, on the side eps_ says
    at_b = math.acos(max(-1.0, min(1.0, (p * p + bg * bg - g * g) / (2 * p * bg))))
    E = _at(B, p, beta + math.copysign(at_b, eps_))
    C = _at(B, r, _dir(B, E) + gamma)
    verdict(f"""
[ground]
A = [0, 0]
G = {_xy(G)}
[links]
AB = {a!r}
BC = {r!r}
EG = {g!r}
[points]
E = {{ on = "BC", distances = {{ B = {p!r}, C = {_dist(E, C)!r} }}, turn = "{_turn(B, C, E)}" }}
[assembly]
E = {_xy(E)}
[input]
crank = "AB"
angle = {th!r}
{_motion(w, s, al)}""")
