"""The scene's records: a mechanism problem as a textbook states it, in SI, checked.

:class:`Scene` here; the records of its parts in :mod:`.part_records`, its names and keys
in :mod:`.names` (all of them named here too, as they always were).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..common.errors import SceneError
from ..common.tolerances import LEAST_BLOCK_SPEED
from ..common.units import ABSURD, TINY, UNITS
from .force_records import Flywheel, Friction, Gravity, Indicator, Mass  # noqa: F401  (re-exported)
from .content import ContentKey
from .names import (  # noqa: F401  (re-exported: the scene's names and keys)
    _LINK_NAME,
    _POINT_ONLY,
    _UNIT_ORDER,
    ANSWER_KINDS,
    GIVEN_KINDS,
    INPUT_KEYS,
    POINT_NAME,
    TOP_KEYS,
    UNDER_BLOCK_KINDS,
    guide_words,
    split_name,
)
from .part_records import (  # noqa: F401  (re-exported: the records of its parts)
    Answer,
    CarriedPoint,
    Cylinder,
    FixedPath,
    GivenRate,
    GuideSlider,
    Input,
    Link,
    Load,
    Pin,
    PositionGiven,
    RollingPair,
    YokeSlot,
)

#: the largest and smallest lengths a scene may state, in metres
_ABSURD_LONG = 1e4
_ABSURD_SHORT = UNITS["length"]["mm"] / 10_000  # a tenth of a micrometre


@dataclass(frozen=True)
class Scene:
    """A loaded, checked scene. Lengths in metres, angles in radians, SI throughout."""

    title: str
    units: str
    ground: dict
    links: tuple
    points: tuple
    sliders: tuple
    assembly: dict
    input: Input
    pins: tuple = ()
    loads: tuple = ()
    answers: tuple = ()
    tolerance: float | None = None
    file: str | None = None
    #: hydraulic or pneumatic cylinders (:class:`Cylinder`)
    cylinders: tuple = ()
    #: wheels and gears rolling without slip (the scene's [rolling])
    rolling: tuple = ()
    #: the force analysis: masses (:class:`Mass`), gravity, ``statics`` (an empty [masses])
    masses: tuple = ()
    gravity: Gravity | None = None
    statics: bool = False
    #: at rest (``[input] speed = 0``, force analysis): no inertia, the motion per rad/s of
    #: the crank (virtual); ``start_alpha`` (rad/s^2, ccw +) starting so: its inertia
    at_rest: bool = False
    start_alpha: float = 0.0
    #: the engine chapter: the indicator diagrams (:class:`Indicator`; ``indicator`` a single
    #: cylinder's, else None) and the flywheel asked for (:class:`Flywheel`), or None
    indicator: Indicator | None = None
    indicators: tuple = ()
    flywheel: Flywheel | None = None
    #: Coulomb friction at the guides and the pins (:class:`Friction`), or None
    friction: Friction | None = None
    #: where the problem comes from (the scene's ``source``), for headings
    source: str | None = field(default=None, compare=False)
    #: the scene's [variants] (what may vary per student), and [variant] (which one it is)
    variation: object = field(default=None, compare=False)
    variant: object = field(default=None, compare=False)
    #: how the reader read what a book's words gave ("crank angle: '30 deg past the inner
    #: dead centre' = 210 deg from +x (...)"), notes of every solution
    reading_notes: tuple = field(default=(), compare=False)
    _link_index: dict = field(default_factory=dict, repr=False, compare=False)
    _text: str = field(default="", repr=False, compare=False)  # the file's text

    def __post_init__(self):
        # made once per scene (and anew by dataclasses.replace, checked as a file is): the
        # points in file order, and the scene's content as a key for the plans cached outside
        self._check_numbers()
        seen = dict.fromkeys(self.ground)
        for link in self.links:
            seen[link.p] = seen[link.q] = None
        for cp in self.points:
            seen[cp.name] = None
        for r in self.rolling:  # a rack's point, on no link
            seen[r.rim] = None
        for sl in self.sliders:  # a peg in two slots, a yoke, a collar driven along its rod
            seen[sl.yoke if isinstance(sl, YokeSlot) else sl.point] = None  # need be no joint
        object.__setattr__(self, "_names", tuple(seen))
        try:
            key = (
                self.units,
                tuple(self.ground.items()),
                self.links,
                self.points,
                self.sliders,
                tuple(self.assembly.items()),
                self.input,
                self.pins,
                self.file,
                self.cylinders,
                self.rolling,
            )
            key = ContentKey(key)
        except (TypeError, AttributeError):  # something unhashable: not cached by content
            key = None
        object.__setattr__(self, "_key", key)

    def _check_numbers(self) -> None:
        """Finite numbers, positive lengths (a scene made through the API, too)."""
        inp = self.input
        rows = (
            (
                ("angle", inp.angle, "angle"),
                ("speed", inp.omega, "angular_velocity"),
                ("acceleration", inp.alpha, "angular_acceleration"),
            )
            if inp.block is None
            else (
                ("place", inp.angle, "velocity"),
                ("speed", inp.omega, "velocity"),
                ("acceleration", inp.alpha, "acceleration"),
            )
        )  # a block's s, vs, as
        for name, v, kind in rows:
            if v is None and inp.given is not None and name != "angle":
                continue  # found from the given motion when the scene is compiled
            if not isinstance(v, (int, float)) or not math.isfinite(v):
                raise SceneError(
                    f"the {'crank' if inp.block is None else 'block'}'s {name} "
                    f"must be a finite number, got {v!r}",
                    key=f"[input] {name}",
                    file=self.file,
                )
            # the bounds a file's values meet, for a scene made through the API too: beyond
            # them the squares of the solution overflow, or the input torque divides by 0
            if not abs(v) <= ABSURD[kind] or (
                name == "speed" and not abs(v) >= TINY.get(kind, LEAST_BLOCK_SPEED)
            ):
                raise SceneError(
                    f"the {'crank' if inp.block is None else 'block'}'s {name} "
                    f"{v!r} (SI) is "
                    + (
                        "zero: nothing moves"
                        if name == "speed" and v == 0
                        else "absurd for a mechanism"
                    ),
                    key=f"[input] {name}",
                    file=self.file,
                )
        for p, xy in self.ground.items():
            if not all(isinstance(c, (int, float)) and abs(c) <= _ABSURD_LONG for c in xy):
                raise SceneError(
                    f"ground point {p} must have finite coordinates within "
                    f"{_ABSURD_LONG:g} m, got {xy!r}",
                    key=f"[ground] {p}",
                    file=self.file,
                )
        for lk in self.links:
            if (
                not isinstance(lk.length, (int, float))
                or not _ABSURD_SHORT <= lk.length <= _ABSURD_LONG
            ):
                raise SceneError(
                    f"link {lk.key} must have a length between "
                    f"{_ABSURD_SHORT:g} and {_ABSURD_LONG:g} m, got "
                    f"{lk.length!r}",
                    key=f"[links] {lk.key}",
                    file=self.file,
                )

    # ----- lookups
    def link(self, name: str) -> Link:
        """The link joining the two points of ``name``, in either order."""
        pts = split_name(name)
        found = self._link_index.get(frozenset(pts)) if len(pts) == 2 else None
        if found is None:
            raise SceneError(f"no link {name} in [links]", file=self.file)
        return found

    def has_link(self, name: str) -> bool:
        """Whether ``name`` (e.g. "BC" or "CB") is a link of the scene."""
        pts = split_name(name)
        return len(pts) == 2 and frozenset(pts) in self._link_index

    @property
    def point_names(self) -> tuple[str, ...]:
        """Every point of the scene: ground, joints, carried points (in file order)."""
        return self._names

    def carried(self, name: str) -> CarriedPoint | None:
        """The carried point named ``name``, or None."""
        return next((c for c in self.points if c.name == name), None)

    def cylinder(self, name: str):
        """The cylinder of [cylinders] named ``name`` (either order of its points), or None."""
        pts = split_name(name)
        return next(
            (c for c in self.cylinders if len(pts) == 2 and {c.barrel, c.rod} == set(pts)), None
        )

    def slider(self, name: str):
        """The slider named ``name``: a block's point (``D``), or one slot of a peg in two
        slots (``P_OA``; the point alone gives its first slot)."""
        return next((s for s in self.sliders if s.point == name or s.key == name), None)

    @property
    def blocks(self) -> tuple:
        """The sliders that are blocks: every slider record but a driving wheel's centre
        path (``[input] wheel``: no block is there, the wheel's centre moves along it)."""
        paths = self.wheel_paths
        return tuple(s for s in self.sliders if s not in paths)

    @property
    def wheel_paths(self) -> tuple:
        """The slider records that are no block: a driving wheel's centre path (keyed by
        the centre; its ``wheel`` names the wheel's link)."""
        return tuple(s for s in self.sliders if getattr(s, "wheel", ""))

    @property
    def cycle(self) -> float:
        """The crank's angle (rad) the motion and forces repeat over: 4 pi for a four-stroke."""
        return self.indicators[0].cycle if self.indicators else 2 * math.pi

    def slots(self, point: str) -> tuple:
        """Every slider record at ``point``: one for a block, two for a peg in two slots."""
        return tuple(s for s in self.sliders if s.point == point)

    def mass_of(self, body: str):
        """The :class:`Mass` of a link (its key) or of a block (its point), or None."""
        return next((m for m in self.masses if m.body == body), None)

    @property
    def has_forces(self) -> bool:
        """Whether the scene asks for the force analysis: masses, gravity, friction, a grip."""
        asked = (self.gravity, self.indicators or None, self.friction)  # statics: [masses] = {}
        grip = any(r.grip for r in self.rolling)  # a friction drive's grip: its statics
        return bool(self.masses) or self.statics or grip or any(x is not None for x in asked)

    def rolling_of(self, point: str):
        """The rolling pair whose wheel has ``point`` as its rim point, or None."""
        return next((r for r in self.rolling if r.rim == point), None)

    @property
    def length_unit(self) -> float:
        """The scene's length unit in metres (0.001 for mm)."""
        return UNITS["length"][self.units]
