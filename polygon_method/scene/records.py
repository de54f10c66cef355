"""The scene's records: a mechanism problem as a textbook states it, in SI, checked.

Names: a point is a capital letter with optional digits (``B``, ``O2``); a link is named
by its two points (``BC``, ``"O2-A"``), in either order.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field

from ..common.errors import SceneError
from ..common.tolerances import LEAST_BLOCK_SPEED
from ..common.units import ABSURD, TINY, UNITS
from .force_records import Flywheel, Friction, Gravity, Indicator, Mass  # noqa: F401  (re-exported)
from .content import ContentKey

POINT_NAME = re.compile(r"[A-Z][0-9]*")
_POINT_ONLY = re.compile(r"^[A-Z][0-9]*\Z")  # \Z: "A\n" is no point name
_LINK_NAME = re.compile(r"^(?:[A-Z][0-9]*-?)+\Z")

_UNIT_ORDER = ("mm", "cm", "m", "in", "ft")

#: the largest and smallest lengths a scene may state, in metres
_ABSURD_LONG = 1e4
_ABSURD_SHORT = UNITS["length"]["mm"] / 10_000  # a tenth of a micrometre

TOP_KEYS = (
    "title",
    "source",
    "notes",
    "units",
    "ground",
    "links",
    "points",
    "sliders",
    "cylinders",
    "rolling",
    "assembly",
    "input",
    "pins",
    "loads",
    "answers",
    "variants",
    "variant",
    "masses",
    "gravity",
    "indicator",
    "flywheel",
    "friction",
)
INPUT_KEYS = ("crank", "angle", "speed", "acceleration")
#: the kinds of quantity on which [input] may give the motion instead of the crank's speed
#: (named as answer keys: ``omega_BC``, ``vs_B``, ``v_B``), with their rate's prefix
GIVEN_KINDS = {"omega": "alpha", "vs": "as", "v": "a"}

#: answer key prefix -> (unit kind, what it names, sense allowed)
ANSWER_KINDS = {
    "v": ("velocity", "point", False),
    "a": ("acceleration", "point", False),
    "omega": ("angular_velocity", "link", True),
    "alpha": ("angular_acceleration", "link", True),
    "vs": ("velocity", "slider", True),
    "as": ("acceleration", "slider", True),
    "ac": ("acceleration", "slider", False),
    "rub": ("velocity", "pin", False),
    "vI": ("velocity", "wheel", False),
    "aI": ("acceleration", "wheel", False),
    # the force analysis (a scene with [masses] or [gravity]): the size of the force at a
    # pin joining two bodies, of a guide's normal force on its block
    "F": ("force", "pin_force", False),
    "N": ("force", "guide", False),
    # a body's inertia (link L, or the block at X): the size of its force -m a_G, its
    # couple -I alpha (ccw positive, or a sense), the offset h of the book's single force
    "Fi": ("force", "body", False),
    "Ci": ("torque", "body", True),
    "h": ("length", "body", False),
    "Fc": ("force", "contact", False),  # rolling wheel L's contact force (a rack: its point)
    "Tmax": ("torque", "drive", False),  # a friction drive's largest torque on L, mu N r
    "Pmax": ("power", "drive", False),  # and the largest power through its grip, mu N v
}
#: the answer kinds of the guide's point under a block (``v_A1``, ``a_A1``: its image a1)
UNDER_BLOCK_KINDS = {"v": "vu", "a": "au"}


def guide_words(label: str, noun: str = "path", of: str | None = None) -> str:
    """A fixed path's (or slot's) words from its label, as a teacher writes them:
    "horizontal path", "vertical slot", "path at 30 deg" (never "the at 30 deg path");
    with ``of``, whose: "horizontal path of D", "slot of yoke Y (at 70 deg)".

    >>> guide_words("horizontal"), guide_words("at 30 deg"), guide_words("at 70 deg", "slot")
    ('horizontal path', 'path at 30 deg', 'slot at 70 deg')
    >>> guide_words("at 30 deg", of="D"), guide_words("vertical", "slot", "yoke Y")
    ('path of D (at 30 deg)', 'vertical slot of yoke Y')
    """
    if of is None:
        return f"{noun} {label}" if label.startswith("at ") else f"{label} {noun}"
    return f"{noun} of {of} ({label})" if label.startswith("at ") else f"{label} {noun} of {of}"


def split_name(name: str) -> tuple[str, ...]:
    """Point names in a link or relative name: ``"BC"`` -> (B, C), ``"O2-A"`` -> (O2, A).

    >>> split_name("BC"), split_name("O2-A"), split_name("O2A"), split_name("Bc")
    (('B', 'C'), ('O2', 'A'), ('O2', 'A'), ())
    """
    if (
        isinstance(name, str)
        and len(name) == 2
        and name.isascii()
        and name.isalpha()
        and name.isupper()
    ):  # the usual name, two capitals: read at once
        return (name[0], name[1])
    if not isinstance(name, str) or not _LINK_NAME.match(name) or name.endswith("-"):
        return ()
    return tuple(POINT_NAME.findall(name))


@dataclass(frozen=True)
class Link:
    """A rigid binary link between two joint points, named as in the scene."""

    key: str
    p: str
    q: str
    length: float

    @property
    def points(self) -> tuple[str, str]:
        """The link's two end points, in the scene's order."""
        return (self.p, self.q)

    def other(self, point: str) -> str:
        """The link's end that is not ``point``."""
        return self.q if point == self.p else self.p


@dataclass(frozen=True)
class CarriedPoint:
    """A point fixed on a link: ``X = P + lam (Q - P) + mu perp(Q - P)``.

    ``P``, ``Q`` are the link's two joint points (``link.p``, ``link.q``) and ``perp`` turns a
    vector 90 deg counter-clockwise. The image point on a polygon follows the same formula.
    """

    name: str
    link: str
    lam: float
    mu: float
    how: str  # the scene's own words, for step tables
    #: how far (m) its place on the link may be from the one its numbers say: the rounding
    #: of the distances it is given, carried through the triangle (large only where the
    #: triangle is nearly flat: its height is then ill-conditioned), plus the spread of the
    #: points it is set out from
    spread: float = 0.0
    #: the numbers it was given, in metres, for an independent check: ``("along", start,
    #: d)`` or ``("distances", r1, d1, r2, d2, turn)`` (turn +1 ccw, -1 cw)
    source: tuple = ()


@dataclass(frozen=True)
class FixedPath:
    """A slider moving on a fixed straight line through ``through`` along unit ``u``."""

    point: str
    u: tuple[float, float]
    through: tuple[float, float]
    label: str
    #: for a peg in two slots (see :class:`GuideSlider`): "ground"; else ""
    slot: str = ""
    #: the path's angle as read (rad, ccw from +x; ``u`` is exact only at whole right
    #: angles), None where the path was not given by an angle
    angle: float | None = None
    #: the path of the centre of a driving wheel rolling on a line (``[input] wheel``): the
    #: wheel's link (no block is there: the wheel's centre moves along it); "" otherwise
    wheel: str = ""

    @property
    def key(self) -> str:
        """The slider's name in the solution and in answer keys: its point (``D``), or for
        a peg in two slots the point and the slot (``P_ground``)."""
        return f"{self.point}_{self.slot}" if self.slot else self.point


@dataclass(frozen=True)
class GuideSlider:
    """A block pinned at ``point`` that slides along moving link ``guide`` (first -> second)."""

    point: str
    guide: str
    first: str
    second: str
    #: for a peg in two slots (``P = { along = ["OA", "QB"] }``, or one link and a fixed
    #: path): the guide's key, so that the two slots of one point have names of their own
    #: (``P_OA``, ``P_QB``); "" for a block on one guide
    slot: str = ""

    @property
    def key(self) -> str:
        """The slider's name in the solution and in answer keys: its point (``A``), or for
        a peg in two slots the point and the slot (``P_OA``)."""
        return f"{self.point}_{self.slot}" if self.slot else self.point


@dataclass(frozen=True)
class YokeSlot:
    """A block pinned at ``point`` that slides in the slot of a translating yoke: the yoke
    is the block at ``yoke`` on a fixed path, its slot the line through it along unit
    ``direction`` (fixed: the yoke does not turn). The Scotch yoke's crank pin."""

    point: str
    yoke: str
    direction: tuple[float, float]
    label: str  # "vertical", "at 60 deg"
    slot: str = ""

    @property
    def key(self) -> str:
        """The slider's name in the solution and in answer keys: its point."""
        return self.point


@dataclass(frozen=True)
class Cylinder:
    """A hydraulic or pneumatic cylinder: its barrel pivoted at ``barrel``, its rod pinned
    at ``rod``; ``key`` as the scene names it (barrel first: ``"O-R"``); ``stroke`` its
    shortest and longest pin-to-pin length (m), or None."""

    key: str
    barrel: str
    rod: str
    stroke: tuple | None = None


@dataclass(frozen=True)
class GivenRate:
    """The input's motion given on another quantity than the crank's speed, as a book
    gives it ("the piston moves at 5 m/s", "the coupler turns at 3 rad/s cw"): ``kind`` an
    answer key's prefix (``omega`` a link's angular velocity, ``vs`` a slider's sliding
    velocity along its guide, ``v`` a point's speed in ``direction``), ``names`` the link's
    points or the point, ``value`` SI (signed: ccw for omega, along the guide for vs, along
    ``direction`` for v), ``rate`` its rate of change (alpha; the sliding acceleration; the
    rate of change of the point's speed, positive speeding up) or None, ``text`` and
    ``rate_text`` as the scene wrote them.

    The crank's omega follows from ``value = omega * Y1``, with ``Y1`` the quantity when
    the crank turns at 1 rad/s; its alpha from ``rate = alpha * Y1 + omega^2 * H``, with
    ``H`` the rate when the crank turns uniformly at 1 rad/s (velocities are linear in the
    crank's speed; accelerations linear in its alpha and in omega^2)."""

    key: str
    kind: str
    names: tuple
    value: float
    rate: float | None
    direction: tuple | None
    text: str
    rate_key: str | None = None
    rate_text: str | None = None


@dataclass(frozen=True)
class RollingPair:
    """A wheel or gear rolling without slip: link ``wheel`` from its centre ``centre`` to
    the point ``rim`` on it, rolling (pitch) radius ``radius`` (m), on a fixed line (``on =
    "line"``) through ``through`` along unit ``u``, the wheel on the side of unit normal
    ``m`` (from the line towards the centre); a fixed circle (``on = "circle"``) about
    ground point ``base_centre``; a gear (``on = "gear"``): link ``base`` turning about its
    ground end ``base_centre``; a rack (``on = "rack"``): the block ``rim`` on a fixed path
    (its pitch line), meshing with the gear ``base`` (``wheel`` the block's point, ``centre``
    None). ``inside``: the wheel rolls inside the circle (a ring, an internal gear). ``ring``:
    the wheel is itself a ring (an internal gear) about its centre, the gear it meshes with
    inside it (``inside`` is then true as well: the pair meshes internally). ``base_radius``:
    the circle's radius as the problem states it (None: from the centre distance).
    ``angle``: the direction centre -> rim (rad) at the scene's crank angle (None: towards
    the contact point). ``label``: the line or circle in words. ``pressure_angle``: the
    teeth's pressure angle (rad) a gear, circle or rack states (None: the default, 20 deg).
    ``grip``: a friction drive's (preload N or None, friction coefficient or None), or None.
    """

    wheel: str
    centre: str
    rim: str
    radius: float
    on: str
    label: str
    u: tuple | None = None
    through: tuple | None = None
    m: tuple | None = None
    base: str | None = None
    base_centre: str | None = None
    inside: bool = False
    base_radius: float | None = None
    angle: float | None = None
    ring: bool = False
    pressure_angle: float | None = None
    grip: tuple | None = None


@dataclass(frozen=True)
class PositionGiven:
    """The position given otherwise than by the crank's angle, as a book gives it ("when
    the cylinder is 850 mm long", "when the piston is 300 mm from O", "when the rocker
    makes 30 deg"): ``kind`` ``length`` (the distance of two points, ``names``), ``s`` (a
    slider's place along its fixed path from its ``through`` point) or ``angle`` (the
    direction of ``names[0] -> names[1]``); ``value`` SI; ``near`` a rough crank angle
    (rad) choosing among the angles that give it, or None; ``text`` as written. The crank's
    angle is found when the scene is compiled (``Input.angle`` is then that angle)."""

    key: str
    kind: str
    names: tuple
    value: float
    near: float | None
    text: str
    found: bool = False


@dataclass(frozen=True)
class Input:
    """The driving crank: link ``crank`` turning about ground point ``pivot``; its angle
    sets the position. Its speed is ``omega`` (and ``alpha``), or is found from ``given``
    (a :class:`GivenRate`) when the scene is compiled: until then ``omega`` is None (and
    ``alpha`` None unless the scene gives the crank's own)."""

    crank: str
    pivot: str
    tip: str
    angle: float  # rad, direction of pivot -> tip
    omega: float | None  # rad/s, ccw positive
    alpha: float | None  # rad/s^2, ccw positive
    speed_text: str
    given: GivenRate | None = None
    #: a second driving crank (two degrees of freedom): an Input of its own, or None
    second: "Input | None" = None
    #: the position given otherwise than by the crank's angle (:class:`PositionGiven`)
    placed: PositionGiven | None = None
    #: a block on a fixed straight guide driving the mechanism (``[input] block = "A"``):
    #: its point, or None for a crank. Then ``crank`` and ``pivot`` are None, ``tip`` is the
    #: block's point, and the motion's parameter is the block's place along its guide:
    #: ``angle`` holds its displacement s (m, from the guide's through point, along the
    #: guide's direction), ``omega`` its velocity vs (m/s) and ``alpha`` its acceleration
    #: as (m/s^2), each signed along the guide
    block: str | None = None
    #: a block driver's stated stroke (s from, s to; m), or None: the sweep then runs from
    #: the first to the last position where the mechanism assembles
    stroke: tuple | None = None
    #: a wheel rolling on a fixed line driving the mechanism (``[input] wheel = "CP"``): its
    #: link, or None. Then ``block`` is its centre, moving on the line parallel to the ground
    #: at the wheel's radius (its path in the scene's sliders), ``angle``, ``omega``,
    #: ``alpha`` the centre's place, velocity and acceleration along it (as for a block),
    #: ``speed_text`` the wheel's angular velocity as the scene gave it
    wheel: str | None = None
    #: a driving wheel's motion given on its centre (``vs_C``, ``as_C``) instead of its own
    #: omega and alpha: the keys so given (the step table says which were given)
    wheel_given: tuple = ()
    #: an angle the scene gave in a book's words: (words, the angle they gave (rad), the
    #: slips a reader of them might make (:class:`~.angles.Slip`), the note saying how
    #: they were read); empty for a plain angle
    said: tuple = field(default=(), compare=False)

    @property
    def angle_words(self) -> str | None:
        """The scene's own words for the crank angle ("30 deg past the inner dead centre"),
        while the angle is the one they gave (a copy turned to another angle has none)."""
        return self.said[0] if self.said and self.said[1] == self.angle else None

    @property
    def angle_note(self) -> str | None:
        """How the reader read the words of :attr:`angle_words` (None without them)."""
        return self.said[3] if self.angle_words is not None else None

    @property
    def angle_slips(self) -> tuple:
        """The classic misreadings of the scene's words for the angle (see ``said``)."""
        return self.said[2] if self.angle_words is not None else ()


@dataclass(frozen=True)
class Pin:
    """A pin of a stated size at ``point`` (radius in m), for its rubbing velocity."""

    point: str
    radius: float
    given: str  # "diameter" or "radius", as the scene gave it


@dataclass(frozen=True)
class Load:
    """A force on a point (N), or a torque on a link (N m, ccw positive). A gas force on a
    piston is a force whose ``gas`` says how it was given: (pressure in Pa, area in m^2,
    the words "0.5 N/mm^2 on a 100 mm bore"); the force is pressure times area.

    A gas force given without its direction pushes the piston towards the crank, as books
    mean it: ``toward`` is then its size (N; negative: away from the crank), and its
    direction is worked out when the scene is compiled, from the piston's place beside the
    crank centre (``force`` is None until then)."""

    target: str
    force: tuple[float, float] | None = None
    torque: float | None = None
    gas: tuple | None = None
    toward: float | None = None


@dataclass(frozen=True)
class Answer:
    """One answer of ``[answers]`` (or of a student's file): its key, what it names, its value in SI
    and its sense as given."""

    key: str
    kind: str  # prefix of ANSWER_KINDS, "torque", "centre", or "vu"/"au" (the guide's point
    # under a block: names is the slider's key)
    names: tuple  # points or a link's points; (i, j) link numbers for a centre
    value: float  # SI; signed when a sense was given; (x, y) in m for a centre
    sense: str | None
    raw: str
    line: int | None = None


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
