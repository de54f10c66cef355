"""The records of a scene's parts, in SI (a part of the scene's records): links, carried
points, sliders (a block on a fixed path, along a link, in a yoke's slot), cylinders, rolling
pairs, the input (and a motion or a position given otherwise), pins, loads and answers."""

from __future__ import annotations

from dataclasses import dataclass, field


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
    #: an offset slot: its centre line parallel to the link's, this far (m) to the left of
    #: it looking from ``first`` to ``second`` (negative: to the right); 0 on the link's line
    offset: float = 0.0

    @property
    def key(self) -> str:
        """The slider's name in the solution and in answer keys: its point (``A``), or for
        a peg in two slots the point and the slot (``P_OA``)."""
        return f"{self.point}_{self.slot}" if self.slot else self.point

    @property
    def along(self) -> str:
        """The guide named from its first point to its second, as the scene wrote it (``DC``
        for the link CD written ``along = "DC"``; ``P-O1``): the way the sliding is signed."""
        one = len(self.first) == 1 and len(self.second) == 1
        return f"{self.first}{self.second}" if one else f"{self.first}-{self.second}"


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
    #: an offset slot: its centre line this far (m) to the left of the line through the
    #: yoke's point Y along ``direction`` (negative: to the right); 0 through Y
    offset: float = 0.0

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
    ``teeth``: where the scene gives the gears by their teeth (:mod:`.teeth`).
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
    #: a gear given by its teeth: (its teeth or None, its gear's or None, the module m or
    #: None where the centre distance gave the radii), or None
    teeth: tuple | None = None


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
    #: with two inputs, the speeds given on other links (:class:`GivenRate`) that the
    #: cranks' speeds were found from when the scene was compiled (then ``given`` is None
    #: and ``omega``, ``alpha`` of both cranks are those found); empty otherwise
    found_from: tuple = field(default=(), compare=False)
    #: an angle the scene gave in a book's words: (words, the angle they gave (rad), the
    #: slips a reader of them might make (:class:`~.angles.Slip`), the note saying how
    #: they were read); empty for a plain angle
    said: tuple = field(default=(), compare=False)

    def found_record(self) -> dict:
        """The JSON input's ``found_from``: the speeds given elsewhere (SI, ccw +) that
        two cranks' speeds were found from, a point's with the ``direction`` its velocity
        component is taken along (a unit vector); {} where there are none."""
        if not self.found_from:
            return {}
        keys = ("key", "value", "rate_key", "rate")
        return {
            "found_from": [
                {k: getattr(g, k) for k in keys}
                | ({"direction": list(g.direction)} if g.kind == "v" else {})
                for g in self.found_from
            ]
        }

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
    crank centre (``force`` is None until then).

    A force whose direction is stated against a link ("perpendicular to CD, ccw") has
    ``across`` = (first point, second point, offset in rad or None, the words, size in N):
    it turns with the link; ``force`` is its vector at the scene's instant, completed when
    compiled (:func:`~polygon_method.scene.link_loads.load_force` gives it anywhere)."""

    target: str
    force: tuple[float, float] | None = None
    torque: float | None = None
    gas: tuple | None = None
    toward: float | None = None
    across: tuple | None = None


@dataclass(frozen=True)
class Answer:
    """One answer of ``[answers]`` (or of a student's file): its key, what it names, its value in SI
    and its sense as given; or a question asked without its answer (``v_C = "?"``, ``"? rpm"``):
    ``value`` None, ``unit`` the unit its answer is to be given in (None: the SI unit)."""

    key: str
    kind: str  # prefix of ANSWER_KINDS, "torque", "centre", or "vu"/"au" (the guide's point
    # under a block: names is the slider's key)
    names: tuple  # points or a link's points; (i, j) link numbers for a centre
    value: float | tuple | None  # SI; signed when a sense was given; (x, y) in m for a
    # centre; None for a question asked without its answer
    sense: str | None
    raw: str
    line: int | None = None
    unit: str | None = None  # a question's unit ("? rpm": "rpm"), as written

    @property
    def asked(self) -> bool:
        """A question asked without its answer (``"?"``): not graded, its value shown."""
        return self.value is None
