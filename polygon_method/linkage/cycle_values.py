"""The answers a book asks of the mechanism's cycle and its configuration, exactly: a quick
return's ratio of the time of the cutting (working) stroke to the return stroke
(``time_ratio``), a slider's length of stroke (``stroke_X``), and at the instant a link's
direction (``theta_XY``: from X to Y, ccw from +x) and the angle at a joint
(``angle_XYZ``: between YX and YZ). The cycle's two are ``linkage``'s own values
(:func:`.analysis.motion_over_cycle`: one definition), worked out only where asked; read by
``check`` (each answer against it, and the questions asked without their answers)."""

from __future__ import annotations

import math

from ..common.errors import SceneError
from ..common.tolerances import SAME
from ..scene import Scene
from .analysis import motion_over_cycle
from .cycle import _Cycle
from .output_motion import stroke_turns
from .shapes import _Output, _output_of, four_bar_of, slider_crank_of, slotted_of

__all__ = [
    "CYCLE_KEYS",
    "CYCLE_SI",
    "cycle_value",
    "direction",
    "joint_angle",
    "quick_return",
    "stroke_ends",
    "words",
]

#: answer kind -> (unit kind, the unit ``check`` shows it in, what it is: :func:`words`)
CYCLE_KEYS = {
    "time_ratio": (
        "ratio",
        "",
        "the ratio of the time of the cutting stroke to the time of the return stroke",
    ),
    "stroke": ("length", "m", "the length of stroke of the slider {0}"),
    "theta": ("angle", "deg", "a link's direction from +x"),
    "angle": ("angle", "deg", "the angle at a joint"),
}


def words(kind: str, names: tuple) -> str:
    """What an answer of ``kind`` of ``names`` is, as a book asks it.

    >>> words("theta", ("C", "D")), words("angle", ("O4", "P", "Q"))
    ('the angle CD makes with +x (from C to D, ccw)', 'the angle O4-P-Q')
    """
    if kind == "time_ratio":
        return CYCLE_KEYS[kind][2]
    if kind == "stroke":
        return CYCLE_KEYS[kind][2].format(names[0])
    sep = "-" if any(len(n) > 1 for n in names) else ""
    if kind == "theta":
        return f"the angle {sep.join(names)} makes with +x (from {names[0]} to {names[1]}, ccw)"
    return f"the angle {sep.join(names)}"


#: answer kind -> the SI unit :func:`cycle_value` gives it in (a class's answer key)
CYCLE_SI = {"time_ratio": "", "stroke": "m", "theta": "rad", "angle": "rad"}

#: the last scene's cycle (a scene asked both its time ratio and a stroke works it out once)
_LAST: dict = {}


def _refuse(key, why):
    raise SceneError(f"{key}: {why}")


def _cycle(scene: Scene, key: str):
    """The scene's :class:`_Cycle` (the crank's turn, sampled), or ``key`` refused where
    no crank turns."""
    hit = _LAST.get("scene")
    if hit is not None and hit[0] is scene:
        return hit[1]
    from ..solver.compiler import compile_plan

    plan = compile_plan(scene)
    if not plan.steps[0].periodic:
        _refuse(key, f"no crank turns (the mechanism is driven by {plan.steps[0].title})")
    cyc = _Cycle(scene)
    _LAST["scene"] = (scene, cyc, {})  # and each output's motion, as it is asked
    return cyc


def _motion(scene, cyc, out):
    """:func:`motion_over_cycle`'s (stationary, lines, min, max, time ratio, lines), once
    per output of the scene (its time ratio and its stroke asked both: one search)."""
    done = _LAST["scene"][2]
    if (out.kind, out.name) not in done:
        done[out.kind, out.name] = motion_over_cycle(
            cyc, out, scene, four_bar_of(scene), slider_crank_of(scene), slotted_of(scene)
        )[1]
    return done[out.kind, out.name]


def time_ratio(scene: Scene, key: str = "time_ratio") -> float:
    """The quick return's ratio of the crank's turn during the slower stroke (the cutting
    stroke) to the quicker (the return), the output's as ``linkage`` gives it."""
    return quick_return(scene, key)[4]


def quick_return(scene: Scene, key: str = "time_ratio") -> tuple:
    """(output, its two standstills, the crank's turn from the first to the second and on
    round, rad, the time ratio): :func:`time_ratio`'s working (``steps`` writes it)."""
    cyc = _cycle(scene, key)
    if not cyc.dom.full_turn:
        _refuse(
            key, f"the crank {scene.input.crank} does not turn fully: no cutting and return strokes"
        )
    out = _output_of(scene, cyc.plan)
    if out is None:
        _refuse(key, "the mechanism has no output link or slider whose strokes to time")
    motion = _motion(scene, cyc, out)
    ratio = motion[4]
    if ratio is None:
        _refuse(
            key,
            f"{out.label} does not stand still twice in the crank's turn: no forward and "
            "return strokes (no quick return)",
        )
    return (out, motion[0], *stroke_turns(cyc, motion[0]), ratio)


def stroke(scene: Scene, point: str, key: str) -> float:
    """Slider ``point``'s length of stroke (m) over the crank's cycle, as ``linkage`` gives
    the output's: its farthest places along its fixed path apart."""
    omin, omax, _ = stroke_ends(scene, point, key)
    return omax - omin


def stroke_ends(scene: Scene, point: str, key: str) -> tuple:
    """(least, largest place along its path, m; the slider's path): :func:`stroke`'s
    working (``steps`` writes it)."""
    sl = scene.slider(point)
    if sl is None or not hasattr(sl, "through"):
        _refuse(
            key,
            f"{point} slides along a moving link, not a fixed path: its stroke is no "
            "length on the frame (ask its sliding velocity, vs_X)",
        )
    cyc = _cycle(scene, key)
    out = _Output(
        "slider",
        sl.point,  # (named as linkage names its output: one search for both keys)
        f"slider {point}",
        point=sl.point,
        path=sl,
    )
    _, _, omin, omax, _, _ = _motion(scene, cyc, out)
    if omin is None or omax - omin == 0.0:
        _refuse(key, f"{point} stands still over the crank's cycle: no stroke")
    return omin, omax, sl


def direction(P, x: str, y: str) -> float:
    """The direction from point x to point y at the instant, ccw from +x, in [0, 2 pi)."""
    (ax, ay), (bx, by) = P[x], P[y]
    return math.atan2(by - ay, bx - ax) % (2 * math.pi)


def joint_angle(P, x: str, y: str, z: str) -> float:
    """The angle at y between yx and yz, in [0, pi]."""
    a, b = direction(P, y, x), direction(P, y, z)
    d = abs(a - b) % (2 * math.pi)
    return min(d, 2 * math.pi - d)


def cycle_value(sol, kind: str, names: tuple, key: str | None = None) -> float:
    """The exact value of the answer ``kind`` of ``names`` (SI: a ratio, m, rad)."""
    key = key or kind
    if kind == "time_ratio":
        return time_ratio(sol.scene, key)
    if kind == "stroke":
        return stroke(sol.scene, names[0], key)
    if kind not in ("theta", "angle"):
        raise KeyError(kind)
    at = names[1] if kind == "angle" else names[0]
    size = max((lk.length for lk in sol.scene.links), default=1.0)
    for other in names:
        if other != at and math.dist(sol.P[at], sol.P[other]) <= SAME * size:
            _refuse(
                key,
                f"{at} and {other} coincide at the instant: the line {at}{other} has no direction",
            )
    return direction(sol.P, *names) if kind == "theta" else joint_angle(sol.P, *names)
