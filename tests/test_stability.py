"""Stability near singular positions: the condition measure is shown, warned about, and at
or too near a singularity the tool refuses with a clear error -- never NaN, inf, a wrong
number or a silent jump to the other branch.

Every check is against something independent: the transmission angle measured from the
positions, or the 50-digit loop-closure reference (tests/reference.py) on the branch the
scene asks for.
"""

import json
import math

import pytest

from polygon_method.cli import main
from polygon_method.common.errors import TOL, SingularStepError
from methods import Kinematics, compare
from polygon_method.scene import parse_scene
from polygon_method.motion.solution import solve
from reference import reference_solution

FOURBAR = """
[ground]
A = [0, 0]
D = [{d}, 0]
[links]
AB = {a}
BC = {b}
CD = {c}
[assembly]
C = {asm}
[input]
crank = "AB"
angle = "{angle!r} rad"
speed = "10 rad/s ccw"
acceleration = "5 rad/s^2 cw"
"""

SLIDER_LIMIT = """
[ground]
O = [0, 0]
[links]
OA = 50
AB = 80
[sliders]
B = {{ path = "horizontal", through = [0, -30] }}
[assembly]
B = "right"
[input]
crank = "OA"
angle = "{angle!r} rad"
speed = "10 rad/s ccw"
"""

BLOCK_AT_PIVOT = """
[ground]
O2 = [0, 0]
O4 = [0, 50]
[links]
"O2-A" = 50
"O4-P" = 300
[sliders]
A = { along = "O4-P" }
[input]
crank = "O2-A"
angle = 90
speed = "10 rad/s ccw"
"""


def toggle(angle):
    """A triple rocker: BC and CD fall in line (toggle) at crank angle 180 deg."""
    return FOURBAR.format(a=20, b=70, c=50, d=100, angle=angle, asm='"above"')


def toggle_guess(angle):
    """C above the line BD (the branch asked for), by the two circles; a tiny offset
    keeps the reference's Newton off the exactly singular straight line."""
    bx, by = 0.02 * math.cos(angle), 0.02 * math.sin(angle)
    ex, ey = 0.1 - bx, -by
    e = math.hypot(ex, ey)
    along = (0.07**2 - 0.05**2 + e * e) / (2 * e)
    h = max(math.sqrt(max(0.07**2 - along * along, 0.0)), 1e-9)
    ux, uy = ex / e, ey / e
    cx, cy = bx + along * ux - h * uy, by + along * uy + h * ux
    if cy < by + (cx - bx) * ey / ex:  # keep it above BD
        cx, cy = bx + along * ux + h * uy, by + along * uy - h * ux
    return {"B": (bx, by), "C": (cx, cy)}


def parallelogram(angle):
    """AB = CD = 40, BC = AD = 100: a change point at 0 and 180 deg; the parallelogram
    branch (C = B + AD) is asked for by a rough position."""
    bx, by = 0.04 * math.cos(angle), 0.04 * math.sin(angle)
    asm = f"[{(bx + 0.1) * 1e3!r}, {by * 1e3!r}]"
    return FOURBAR.format(a=40, b=100, c=40, d=100, angle=angle, asm=asm)


def parallelogram_guess(angle):
    bx, by = 0.04 * math.cos(angle), 0.04 * math.sin(angle)
    return {"B": (bx, by), "C": (bx + 0.1, by)}


def slider(angle):
    """Offset slider-crank whose rod AB reaches the path only just at 90 deg: the rod is
    perpendicular to the guide there (the step's dead centre)."""
    return SLIDER_LIMIT.format(angle=angle)


def slider_guess(angle):
    ax, ay = 0.05 * math.cos(angle), 0.05 * math.sin(angle)
    return {"A": (ax, ay), "B": (ax + math.sqrt(max(0.08**2 - (ay + 0.03) ** 2, 0.0)), -0.03)}


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


def sin_transmission(P, b, c, d):
    """sin of the angle at c between c->b and c->d, from positions (independent)."""
    u = (float(P[b][0] - P[c][0]), float(P[b][1] - P[c][1]))
    v = (float(P[d][0] - P[c][0]), float(P[d][1] - P[c][1]))
    return abs(u[0] * v[1] - u[1] * v[0]) / (math.hypot(*u) * math.hypot(*v))


def finite(x):
    if isinstance(x, dict):
        return all(finite(v) for v in x.values())
    if isinstance(x, (list, tuple)):
        return all(finite(v) for v in x)
    if isinstance(x, float):
        return math.isfinite(x)
    return True


@pytest.fixture
def write(tmp_path):
    def _write(text, name="scene.toml"):
        p = tmp_path / name
        p.write_text(text)
        return str(p)

    return _write


# --------------------------------------------------------------------------- shown


def test_condition_is_the_transmission_angle_and_is_shown(write, capsys):
    angle = math.pi - 0.02  # transmission angle about 1.7 deg: ill-conditioned
    scene = parse_scene(toggle(angle))
    ref = reference(scene, toggle_guess(angle))
    expected = sin_transmission(ref.P, "B", "C", "D")
    assert TOL.singular < expected < TOL.warn

    path = write(toggle(angle))
    assert main(["solve", "--json", path]) == 0
    d = json.loads(capsys.readouterr().out)
    step = next(s for s in d["steps"] if "C" in s["finds"])
    assert step["condition"] == pytest.approx(expected, rel=1e-9)
    assert [s["condition"] for s in d["steps"] if s is not step] == [1.0]
    (warning,) = d["warnings"]
    assert f"step {step['step']}" in warning and "BC" in warning and "CD" in warning
    assert f"{expected:.3g}" in warning

    assert main(["solve", path]) == 0
    text = capsys.readouterr().out
    assert f"condition {expected:.3g}" in text
    assert "warning: step 2" in text


def test_well_conditioned_has_no_warning(write, capsys):
    angle = math.radians(60)
    text = FOURBAR.format(a=50, b=66, c=56, d=100, angle=angle, asm='"above"')
    ref = reference(parse_scene(text), {"B": (0.025, 0.0433), "C": (0.09, 0.055)})
    assert main(["solve", "--json", write(text)]) == 0
    d = json.loads(capsys.readouterr().out)
    assert d["warnings"] == []
    assert d["steps"][1]["condition"] == pytest.approx(
        sin_transmission(ref.P, "B", "C", "D"), rel=1e-12
    )
    assert d["steps"][1]["condition"] > TOL.warn


def test_steps_shows_the_condition(write, capsys):
    pytest.importorskip("polygon_method.steps")
    angle = math.pi - 0.02
    scene = parse_scene(toggle(angle))
    expected = sin_transmission(reference(scene, toggle_guess(angle)).P, "B", "C", "D")
    assert main(["steps", write(toggle(angle))]) == 0
    out = capsys.readouterr().out
    assert "condition" in out
    assert f"{expected:.3g}" in out


# --------------------------------------------------------------------------- refused


@pytest.mark.parametrize(
    "text, step, words",
    [
        (toggle(math.pi), "step 2", ("BC", "CD", "toggle")),
        (parallelogram(0.0), "step 2", ("BC", "CD", "in line")),
        (parallelogram(math.pi), "step 2", ("BC", "CD", "in line")),
        (slider(math.pi / 2), "step 2", ("AB", "guide", "dead centre")),
        (BLOCK_AT_PIVOT, "step 2", ("block A", "O4", "pivot")),
    ],
    ids=["toggle", "change-point-0", "change-point-180", "slider-dead-centre", "block-at-pivot"],
)
@pytest.mark.parametrize("json_flag", [[], ["--json"]], ids=["text", "json"])
def test_true_singularity_is_a_clear_error(write, capsys, text, step, words, json_flag):
    with pytest.raises(SingularStepError):
        solve(parse_scene(text))
    assert main(["solve", *json_flag, write(text)]) == 2
    out, err = capsys.readouterr()
    assert out == ""
    assert err.count("\n") == 1 and "Traceback" not in err
    assert step in err
    for w in words:
        assert w in err


# --------------------------------------------------------------------------- near


NEAR = [(f"toggle-{k}", toggle, toggle_guess, math.pi - 10.0**-k) for k in range(1, 13)]
NEAR += [(f"change-point+{k}", parallelogram, parallelogram_guess, 10.0**-k) for k in range(1, 13)]
NEAR += [
    (f"change-point-{k}", parallelogram, parallelogram_guess, -(10.0**-k)) for k in (2, 4, 6, 8)
]
NEAR += [(f"slider-{k}", slider, slider_guess, math.pi / 2 - 10.0**-k) for k in range(1, 13)]


@pytest.mark.parametrize("name, make, guess, angle", NEAR, ids=[n[0] for n in NEAR])
def test_near_a_singularity_right_or_refused(name, make, guess, angle):
    """Approaching a toggle, a change point or a slider's dead centre: every answer the
    tool gives is within 1e-6 of the size of its quantity on the branch asked for (and
    within 1e-9 where no warning is given), or it refuses with SingularStepError. Never a
    wrong number or the other branch with only a warning."""
    text = make(angle)
    scene = parse_scene(text)
    try:
        sol = solve(scene)
    except SingularStepError as exc:
        assert exc.step and "step" in exc.step
        return
    assert finite(sol.to_dict())
    ref = reference(scene, guess(angle))
    err = compare(
        Kinematics(
            "solve", sol.P, sol.V, sol.A, sol.W, sol.Al, {k: (v[0], v[1]) for k, v in sol.S.items()}
        ),
        ref,
        scene,
    )
    cond = min(sol.conditions.values())
    if cond >= TOL.warn:
        assert not sol.warnings
        assert err["all"] < 1e-9, err
    else:
        assert sol.warnings
        assert err["all"] < 1e-6, (cond, err)
