"""The alternatives a mistake is matched against: a candidate value with its words, the
scene re-solved with one mistake made (the speed, the crank angle, the other branch), and
the slips of units and factors each kind of answer invites."""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace

from ..common.tolerances import DISTINCT, LEAST_REACH, SAME
from ..common.errors import PolygonMethodError
from ..solver.plan import Context
from ..scene import Scene
from ..motion.solution import Solution, solve


@dataclass(frozen=True)
class _Candidate:
    value: float
    code: str
    text: str
    window: float | None = None  # narrower matching window (absolute), for wide families


class _Alternatives:
    """Solutions of the same scene with one mistake made (asked of the solver, cached)."""

    def __init__(self, sol: Solution):
        self.sol = sol
        self.cache = {}

    def solve(self, key, scene):
        if key not in self.cache:
            try:
                self.cache[key] = solve(scene)
            except (PolygonMethodError, ValueError, ZeroDivisionError, OverflowError):
                self.cache[key] = None
        return self.cache[key]

    def speed(self, factor):
        sc = self.sol.scene
        return self.solve(
            ("speed", factor),
            replace(sc, input=replace(sc.input, omega=sc.input.omega * factor, given=None)),
        )  # that speed, as given

    def angle_as_radians(self):
        sc = self.sol.scene
        deg = math.degrees(sc.input.angle)
        return self.solve(("radians",), replace(sc, input=replace(sc.input, angle=deg)))

    def angle_slips(self):
        """(slip, solution or None) for each classic misreading of the crank angle's words
        (the other dead centre, against the rotation, above for below, from the horizontal
        for from the vertical): the scene's reader lists them with the words."""
        sc = self.sol.scene
        return [
            (
                slip,
                self.solve(
                    ("slip", slip.code, slip.value),
                    replace(sc, input=replace(sc.input, angle=slip.value)),
                ),
            )
            for slip in sc.input.angle_slips
        ]

    def branches(self):
        """(point, words, solution) for the other branch of every two-way step."""
        out = self.cache.get("branches")
        if out is not None:
            return out
        sol = self.sol
        sc = sol.scene
        out = []
        ctx = Context(sc.input.angle, sc.input.omega, sc.input.alpha)
        for st in sol.plan.steps:
            if not st.other_assembly_mistake:
                continue
            try:
                base, off, *_ = st.candidates(dict(sol.P), ctx)
            except PolygonMethodError:
                continue
            X = st.point
            other = (base[0] - st.sigma * off[0], base[1] - st.sigma * off[1])
            here = sol.P[X]
            if (
                math.dist(other, here) <= SAME * max(math.hypot(*off), LEAST_REACH)
                or math.dist(other, here) == 0
            ):
                continue
            alt = self.solve(("branch", X), replace(sc, assembly={**sc.assembly, X: other}))
            if alt is None:
                continue
            dx, dy = other[0] - here[0], other[1] - here[1]
            side = (
                ("below" if dy < 0 else "above")
                if abs(dy) >= abs(dx)
                else ("left" if dx < 0 else "right")
            )
            out.append((X, side, alt))
        self.cache["branches"] = out
        return out


def offset_slips(alts):
    """(slider, code, solution or None) for each offset slot drawn otherwise: through the
    lever's own line (the offset left out) and on the other side of it."""
    sc, out = alts.sol.scene, []
    for i, sl in enumerate(sc.sliders):
        if not getattr(sl, "offset", 0.0):
            continue
        for code, e in (("offset_left_out", 0.0), ("offset_other_side", -sl.offset)):
            sliders = sc.sliders[:i] + (replace(sl, offset=e),) + sc.sliders[i + 1 :]
            out.append((sl, code, alts.solve((code, sl.key), replace(sc, sliders=sliders))))
    return out


def _speed_mistakes(scene: Scene):
    """(factor on the crank's omega, code, words) for the speed confusions that the way the
    scene states the speed makes possible."""
    g = scene.input.given
    if g is not None:  # the crank's speed was found from a given motion
        return _given_mistakes(scene, g)
    unit = re.sub(r"^[-+0-9.eE\s]+", "", scene.input.speed_text).split()
    unit = unit[0].lower() if unit else "rad/s"
    k = 60 / (2 * math.pi)
    if unit in ("rpm", "r.p.m.", "r.p.m", "rev/min"):
        return (
            (k, "rpm_as_rad_s", "rpm used as rad/s (omega = N instead of 2 pi N / 60)"),
            (60.0, "rps_rpm", "rpm taken as rps (omega = 2 pi N, the / 60 left out)"),
        )
    if unit in ("rps", "r.p.s.", "r.p.s", "rev/s"):
        return (
            (1 / (2 * math.pi), "rps_as_rad_s", "rps used as rad/s (omega = n instead of 2 pi n)"),
            (1 / 60, "rps_rpm", "rps taken as rpm (omega = 2 pi n / 60)"),
        )
    return (
        (1 / k, "rad_s_as_rpm", "rad/s taken as rpm (converted again by 2 pi / 60)"),
        (2 * math.pi, "rad_s_as_rps", "rad/s taken as rps (multiplied by 2 pi)"),
    )


def _given_mistakes(scene, g):
    """The slips of a speed given on another quantity: the given speed taken as the crank
    pin's (omega = v / r), or the given link's omega taken as the crank's."""
    w = abs(scene.input.omega)
    if g.kind == "omega":
        wrong = abs(g.value)
        words = (
            f"the given omega_{''.join(g.names)} taken as the crank's (the polygon not "
            "scaled to it)"
        )
    else:
        wrong = abs(g.value) / scene.link(scene.input.crank).length
        words = (
            f"the given speed of {g.names[0]} ({g.text}) taken as the crank pin's "
            f"(omega_{scene.input.crank} = v / r, the polygon not scaled to it)"
        )
    if abs(wrong - w) <= DISTINCT * w:
        return ()
    return ((wrong / w, "given_as_crank", words),)


_FACTOR_MISTAKES = {
    "v": ((1e3, "mm_m", "mm/s given as m/s"), (1e-3, "mm_m", "m/s given as mm/s")),
    "vs": ((1e3, "mm_m", "mm/s given as m/s"), (1e-3, "mm_m", "m/s given as mm/s")),
    "rub": ((1e3, "mm_m", "mm/s given as m/s"), (1e-3, "mm_m", "m/s given as mm/s")),
    "a": ((1e3, "mm_m", "mm/s^2 given as m/s^2"), (1e-3, "mm_m", "m/s^2 given as mm/s^2")),
    "as": ((1e3, "mm_m", "mm/s^2 given as m/s^2"), (1e-3, "mm_m", "m/s^2 given as mm/s^2")),
    "ac": (
        (1e3, "mm_m", "mm/s^2 given as m/s^2"),
        (1e-3, "mm_m", "m/s^2 given as mm/s^2"),
        (0.5, "coriolis_factor", "the factor 2 of the Coriolis component 2 omega v left out"),
    ),
    "omega": (
        (180 / math.pi, "deg_rad", "degrees per second given as rad/s"),
        (math.pi / 180, "deg_rad", "radians taken as degrees (rad/s x pi / 180)"),
        (60 / (2 * math.pi), "rpm_as_rad_s", "the answer is in rpm, not rad/s"),
        (1e-3, "mm_m", "a length in mm used in omega = v / l (l must be in m)"),
        (1e3, "mm_m", "a velocity in mm/s used in omega = v / l"),
    ),
    "alpha": (
        (180 / math.pi, "deg_rad", "degrees per second squared given as rad/s^2"),
        (math.pi / 180, "deg_rad", "radians taken as degrees"),
        (1e-3, "mm_m", "a length in mm used in alpha = a_t / l (l must be in m)"),
    ),
    "torque": ((1e3, "mm_m", "N mm given as N m"), (1e-3, "mm_m", "N m given as N mm")),
    "h": (  # the offset of the inertia force from G: I alpha / (m a_G) is in m
        (1e3, "mm_m", 'the offset in mm given as m (a bare h is in m; write "16 mm")'),
        (1e-3, "mm_m", "the offset in m given as mm"),
    ),
}
_DECIMAL = (
    (10.0, "decimal_point", "the decimal point misplaced (10 times too large)"),
    (0.1, "decimal_point", "the decimal point misplaced (10 times too small)"),
    (100.0, "decimal_point", "the decimal point misplaced, or cm for m (100 times)"),
    (0.01, "decimal_point", "the decimal point misplaced, or m for cm (1/100)"),
)
