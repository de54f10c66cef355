"""The frames of an animation: one vectorised sweep of the scene over its crank's cycle (the
full turn, or between its limit positions), at the scales of ``steps`` and ``draw``.

The frames are the sweep's own arrays (SI, counter-clockwise positive): nothing is solved
here. Over a full turn they start at the scene's instant and follow the crank's sense of
rotation; where the crank cannot turn fully they run between the limit positions (a little
inside them, where the velocities stay finite), with the scene's instant among them.

>>> import polygon_method as pm
>>> fr = frames(pm.load_scene("worked_problems/crank_slotted_lever.toml"), 180)
>>> len(fr), fr.start, fr.full_turn, [round(float(d), 6) for d in fr.degrees[:3]]
(180, 0, True, [45.0, 43.0, 41.0])
>>> [s.text for s in fr.scales]       # the scales of ``steps``
['1 cm = 50 mm', '1 cm = 0.1 m/s', '1 cm = 0.5 m/s^2']
>>> fr = frames(pm.load_scene("worked_problems/fourbar_image_points.toml"), 180)
>>> fr.full_turn, fr.limits_text, round(float(fr.degrees[fr.start]), 6)
(False, '256.21 deg and 103.79 deg', 60.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..common.tolerances import ROUNDING
from ..common.errors import SceneError
from ..polygons.scales import diagram_scales
from ..motion.solution import solve
from ..motion.sweeps import sweep
from ..solver.tracking import Sweeper

__all__ = [
    "Frames",
    "frames",
    "frame_angles",
    "DEFAULT_FRAMES",
    "MAX_FRAMES",
    "MAX_PICTURE_FRAMES",
    "max_frames",
    "check_frames",
    "need_frames",
    "round_sig",
    "MAX_FRAME_POINTS",
    "MAX_FOLLOW_FRAMES",
    "frames_to_follow",
]

#: frames of a cycle when none are asked for (2 deg apart over a full turn)
DEFAULT_FRAMES = 180
#: the most frames a page or an SVG animation may have
MAX_FRAMES = 3600
#: the most frames of an animation made of pictures (GIF, HTML player): each frame is a
#: picture held in memory until the file is whole (about 0.35 MB in a GIF, 30 KB in the
#: HTML player), and drawing one takes about 0.06 s
MAX_PICTURE_FRAMES = 360


def max_frames(fmt: str | None = None) -> int:
    """The most frames of a page (``fmt`` None), or of an animation to ``fmt``."""
    return MAX_PICTURE_FRAMES if fmt in ("gif", "html") else MAX_FRAMES


def check_frames(n, fmt: str | None = None) -> int:
    """``n`` as a count of frames (a whole number from 2 to :func:`max_frames`), or a
    :class:`SceneError` naming ``--frames``."""
    top = max_frames(fmt)
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or not 2 <= n <= top:
        what = f"a {fmt.upper()} animation" if fmt in ("gif", "html") else "a page or an SVG"
        raise SceneError(
            f"--frames {n!r}: give a whole number of frames from 2 to {top} (for {what})",
            key="--frames",
        )
    return int(n)


#: frames times points a page or animation holds at most (about 60 bytes each on a page:
#: some 60 MB, which a browser still opens)
MAX_FRAME_POINTS = 1_000_000

#: the most frames a page or an SVG animation takes of itself to follow a wheel or a second
#: crank turning fast (a differential's planet, 15 times its arm over the arm's 10 turns):
#: three times what ``--frames`` may ask, a page of a few MB
MAX_FOLLOW_FRAMES = 3 * MAX_FRAMES

#: how far inside a limit position the frames stop, as a fraction of the range
INSIDE = 0.004


@dataclass(frozen=True)
class Frames:
    """A scene's motion over its cycle, frame by frame.

    ``followed`` says, where the count of frames was raised above the one asked to follow a
    wheel turning fast (:func:`frames_to_follow`), by how much and why; "" elsewhere.

    ``res`` is the :class:`~polygon_method.motion.sweeps.SweepResult` (its ``theta`` in frame
    order), ``sol`` the solution at the scene's instant (frame ``start``), ``scales`` the
    (space, velocity, acceleration) scales of the step table, ``full_turn`` whether the crank
    turns fully, ``cycle`` the crank's angle (rad) the frames go over when it does: the
    scene's cycle (``Scene.cycle``: two turns for a four-stroke engine).
    """

    res: object
    sol: object
    scales: tuple
    start: int
    full_turn: bool
    cycle: float = 2 * math.pi
    followed: str = ""

    @property
    def cycle_degrees(self) -> float:
        """The cycle in degrees (360, or 720 for a four-stroke engine): the angles shown
        are taken modulo it, so that 390 deg stays 30 deg into a four-stroke's second turn."""
        return math.degrees(self.cycle)

    def __len__(self):
        return len(self.res)

    @property
    def said(self) -> str:
        """ ", not 180: ..." where the count was raised to follow a wheel (``followed``)."""
        return f", {self.followed}" if self.followed else ""

    def aliased(self, what) -> tuple:
        """The note that ``what`` (the curves, the pictures) may be aliased, where the
        frames cannot follow a wheel turning fast; () where they can."""
        from ..linkage.cycle import sweep_aliased

        return sweep_aliased(self.res, what)

    @property
    def degrees(self) -> np.ndarray:
        """The crank angle of each frame (deg, continuous from frame to frame); for a block
        driver, the block's place along its guide (in the scene's units)."""
        dom = self.res.domain
        if not dom.periodic:
            return np.asarray(self.res.theta) / dom.unit
        return np.degrees(self.res.theta)

    @property
    def parameter(self) -> tuple:
        """(name, symbol, unit) of what the frames step through: the crank angle (deg), or
        a driving block's place (the scene's length unit)."""
        return self.sol.plan.steps[0].parameter(self.sol.scene)  # asked of the driver

    @property
    def moving(self) -> tuple:
        """The points that move (not ground), in the scene's order."""
        sc = self.sol.scene
        return tuple(p for p in sc.point_names if p not in sc.ground)

    @property
    def limits_text(self) -> str:
        """The limit positions in words: crank angles, or a block's places along its guide."""
        dom = self.res.domain
        lim = dom.limits
        if not dom.periodic:  # a block driver: the ends of its travel
            return " and ".join(
                f"s = {lp.theta / dom.unit:.6g} {self.sol.scene.units}" for lp in lim
            )
        return " and ".join(f"{lp.degrees:.2f} deg" for lp in lim)


def frame_angles(scene, n: int, domain) -> tuple[np.ndarray, int]:
    """``n`` crank angles (rad) over the cycle and the index of the scene's own angle: over
    a full turn, the scene's whole cycle (two turns for a four-stroke engine, whose gas
    force repeats only after them) from its own angle in the crank's sense."""
    t0 = scene.input.angle
    if domain.full_turn:
        sense = -1.0 if scene.input.omega < 0 else 1.0
        return t0 + sense * (cycle_of(scene, domain) / n) * np.arange(n), 0
    lo, hi = domain.lo, domain.hi
    pad = INSIDE * (hi - lo)
    th = np.linspace(lo + pad, hi - pad, max(n - 1, 1))
    k = int(np.searchsorted(th, t0))
    near = [j for j in (k - 1, k) if 0 <= j < len(th) and abs(th[j] - t0) <= ROUNDING * (hi - lo)]
    if near:  # the instant is a frame already (0 in a range symmetric about it): n frames
        th = np.linspace(lo + pad, hi - pad, n)  # of which the nearest is the instant,
        k = int(np.argmin(np.abs(th - t0)))  # none twice
        th[k] = t0
        return th, k
    return np.insert(th, k, t0), k


def frames_to_follow(scene, n: int = DEFAULT_FRAMES, most: int = MAX_FOLLOW_FRAMES):
    """(count, words): ``n`` frames, or as many more as keep the wheel or second crank
    turning fastest at a fixed ratio of the crank within ``linkage``'s
    :data:`~polygon_method.linkage.cycle.MOST_PER_SAMPLE` (10 deg) between two frames, so
    that the picture shows its own turning, not a wheel jumping a third of a turn (or
    seeming to turn back) from frame to frame; the words say so where the count was raised,
    else "". Where more than ``most`` (or than a page holds, :data:`MAX_FRAME_POINTS`)
    would be needed, ``n``: more that still cannot follow it show nothing truer, and the
    page says its frames may be aliased."""
    from ..linkage.cycle import samples_to_follow

    n = check_frames(n)
    sw = Sweeper(scene)
    dom, plan = sw.domain, sw.plan
    span = cycle_of(scene, dom) if dom.full_turn else dom.hi - dom.lo
    points = max(len(getattr(scene, "point_names", ())), 1)
    need = samples_to_follow(plan, span, n)
    if need > n and not dom.full_turn:  # n frames between the limits: n - 1 gaps
        need += 1
    if need <= n or need > min(most, MAX_FRAME_POINTS // points):
        return n, ""
    rate, st = max(
        (abs(r), s) for s in plan.steps if (r := getattr(s, "theta_rate", None)) is not None
    )
    turn = math.degrees(rate * span / (need if dom.full_turn else need - 1))
    words = (
        f"not {n}: {st.title} turns {rate:.3g} times as fast as the crank {scene.input.crank}, "
        f"at most {turn:.3g} deg between two frames (the picture follows it)"
    )
    return need, words


def asked(scene, n, fmt=None) -> Frames:
    """The frames ``--frames n`` asks (2 to the most ``fmt`` holds: a page's, None, or an
    animation's); without it (``n`` None), 180 or as many more as follow a wheel turning
    fast, up to what ``fmt`` holds (:func:`frames_to_follow`), the frames saying so."""
    if n is None:
        return frames(
            scene, DEFAULT_FRAMES, follow=MAX_FOLLOW_FRAMES if fmt is None else max_frames(fmt)
        )
    check_frames(n, fmt)
    return frames(scene, n)


def frames(scene, n: int = DEFAULT_FRAMES, *, follow: int = 0) -> Frames:
    """The scene's motion at ``n`` crank angles over its cycle, in one vectorised sweep
    (``n`` from 2 to :data:`MAX_FRAMES`); with ``follow`` (a count of frames), at least
    ``n`` and at most ``follow``: as many as :func:`frames_to_follow` takes to follow a
    wheel turning fast."""
    n = check_frames(n)
    followed = ""
    if follow:
        n, followed = frames_to_follow(scene, n, follow)
    points = len(getattr(scene, "point_names", ()))
    if n * points > MAX_FRAME_POINTS:  # the page holds every point at every frame
        raise SceneError(
            f"--frames {n} of {points} points would make a page of about "
            f"{n * points * 60 / 1e6:.0f} MB: give at most "
            f"{max(2, MAX_FRAME_POINTS // max(points, 1))} frames for this scene",
            key="--frames",
        )
    sol = solve(scene)  # the stated instant: the scales, and its errors first
    scales = diagram_scales(sol)
    domain = Sweeper(scene).domain  # the cycle on the scene's branch (found once a scene)
    th, start = frame_angles(scene, n, domain)
    res = sweep(scene, th)
    kept = res.theta
    if len(kept) != len(th):  # angles at a singular position were left out
        start = int(np.argmin(np.abs(kept - scene.input.angle)))
    full = bool(domain.full_turn)
    return Frames(res, sol, scales, start, full, cycle_of(scene, domain), followed)


def cycle_of(scene, domain) -> float:
    """The crank's angle (rad) the frames of a full turn go over: the motion's period where
    it repeats only after several turns (a gear train: ``domain.period``), else the scene's
    cycle (two turns for a four-stroke engine)."""
    return domain.period if domain.turns > 1 else scene.cycle


def need_frames(fr) -> Frames:
    """``fr`` if it is the frames of a scene, else a :class:`SceneError` saying how to make
    them (an API misuse is an error of the family, never an AttributeError)."""
    if not isinstance(fr, Frames):
        raise SceneError(
            "the frames of a scene are needed (polygon_method.page.frames(scene, "
            f"n)), not {type(fr).__name__}"
        )
    return fr


def round_sig(a, digits: int = 6) -> list:
    """Values rounded to ``digits`` significant figures (for the page's data): a list.

    >>> round_sig([0.392034567, -12345678.0, 0.0])
    [0.392035, -12345700.0, 0.0]
    """
    return [float(f"{x:.{digits}g}") for x in np.asarray(a, dtype=float).ravel().tolist()]
