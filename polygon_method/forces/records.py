"""The force analysis' records (SI, counter-clockwise positive).

Sign rule: a pin force is the force *on* one body *by* the other at the pin; the other body
feels its opposite. A body is a link (its key), a slider block (``block B``) or the frame
(``frame``). Moments are taken about the frame's origin unless a record says otherwise.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

from ..common.numbers import fmt, sense_word
from .grip import words as grip_words


FRAME = "frame"


def block(point: str) -> str:
    """The body name of the slider block at ``point``: ``block B``."""
    return f"block {point}"


@dataclass(frozen=True)
class Inertia:
    """D'Alembert's inertia of one body: the force ``-m a_G`` at G and the couple
    ``-I alpha``; or, as a book draws it, the force alone along a line offset from G by
    ``h = I alpha / (m |a_G|)``: its point ``G + offset perp(F/|F|)`` (``offset`` signed,
    ``perp`` turning 90 deg ccw), whose moment about G is the couple
    (``cross(offset perp(F/|F|), F) = -offset |F| = -I alpha``). ``offset`` is None where
    ``a_G = 0`` (the couple alone, no single force)."""

    body: str
    mass: float
    inertia: float
    G: tuple
    a_G: tuple
    alpha: float
    force: tuple
    couple: float
    offset: float | None
    how: str = ""

    @property
    def offset_point(self):
        """The point of the single resultant's line nearest G, or None."""
        if self.offset is None:
            return None
        fx, fy = self.force
        f = (fx * fx + fy * fy) ** 0.5
        return (self.G[0] - self.offset * fy / f, self.G[1] + self.offset * fx / f)


@dataclass(frozen=True)
class PinForce:
    """The force (N) on body ``on`` by body ``by`` at pin ``point``."""

    point: str
    on: str
    by: str
    force: tuple

    @property
    def magnitude(self) -> float:
        """The force's size, ``|F|`` (N)."""
        return (self.force[0] ** 2 + self.force[1] ** 2) ** 0.5


@dataclass(frozen=True)
class GuideForce:
    """The guide's normal force on the block at ``point``: ``normal`` (N) along the unit
    ``n`` (the path's direction turned 90 deg ccw), acting through the block's pin (a
    frictionless guide; the block's loads all pass through its pin, so the guide adds no
    couple, except a yoke's, see ``couple``). ``by``: the body the guide is, the frame for a fixed path, the link for a
    block sliding on a moving link (which feels the opposite, at the block's pin)."""

    point: str
    normal: float
    n: tuple
    by: str = FRAME
    #: the guide's couple on the block (N m, ccw): a translating yoke's path keeps it from
    #: turning; 0 for a block whose loads all pass through its pin
    couple: float = 0.0
    #: the slot's name where a point slides in two (a peg: ``P_OA``); else the point
    name: str = ""

    @property
    def key(self) -> str:
        """The name the guide's force goes by in the output: the slider's key, or its point."""
        return self.name or self.point

    @property
    def force(self) -> tuple:
        """The normal force as a vector, ``normal n`` (N)."""
        return (self.normal * self.n[0], self.normal * self.n[1])


@dataclass(frozen=True)
class Contact:
    """The contact force on a rolling body at its contact point ``point`` (x, y), by ``by``:
    ``normal`` (N) along ``m`` (the unit normal at the contact towards the body: from the
    ground line, the circle or the other gear towards the wheel's centre; for a rack, away
    from its pinion), ``tangential`` (N) along ``t = perp(m)``. ``wheel``: the body (a
    wheel's link, a rack's ``block R``).

    A wheel on a fixed line grips by friction (``teeth`` None): both parts follow from the
    statics; no slip needs ``|T| / N`` of friction (``required_friction``, None where ``N
    <= 0``: the wheel would lift off). Gear teeth (a gear, a planet on a circle, a rack:
    ``teeth`` the pressure angle phi, rad) push along the line of action through the pitch
    point, at phi to the common tangent, the teeth pushing apart: ``N = |T| tan phi``, the
    tooth load ``|T| / cos phi`` (``load``). No slip at the pitch point: neither works."""

    wheel: str
    point: tuple
    normal: float
    tangential: float
    m: tuple
    #: the body that pushes: the frame (a ground line, a fixed circle), a gear, a pinion
    by: str = FRAME
    #: the teeth's pressure angle (rad), or None (a friction grip on a ground line)
    teeth: float | None = None
    #: whether the scene states the pressure angle (False: the default, 20 deg)
    stated: bool = True
    #: a friction drive's (mu or None, N pressing, r, R or None, v or None): :mod:`.grip`
    grip: tuple | None = None
    #: a gear given by its teeth: (the body in words, what it meshes with), as the step
    #: table says them ("planet AP of 24 teeth", "the sun of 40 teeth about O"), or None
    words: tuple | None = None
    #: on a fixed circle: the torque (N m, ccw positive) the frame holds it with (the
    #: circle's own balance against the wheel's push at the contact), else None
    holding: float | None = None
    #: on a fixed circle: its centre (the point the ``Thold_O`` answer key names), else None
    about: str | None = None

    couple = 0.0

    @property
    def key(self) -> str:
        """The contact's name in the output: "contact of W"."""
        return f"contact of {self.wheel}"

    @property
    def force(self) -> tuple:
        """The contact force on the wheel as a vector: its normal and tangential parts along ``m``
        and across it (N)."""
        mx, my = self.m
        return (self.normal * mx - self.tangential * my, self.normal * my + self.tangential * mx)

    @property
    def load(self):
        """The contact force's size (N): the tooth load along the line of action."""
        n, t = self.normal, self.tangential
        return (n * n + t * t) ** 0.5

    @property
    def required_friction(self):
        """The least friction coefficient that keeps the wheel from slipping, |T| / N; None (inf
        over a sweep) where the wheel would lift off, and for gear teeth."""
        if self.teeth is not None:
            return None
        n, t = self.normal if self.grip is None else self.grip[1], self.tangential
        if not isinstance(t, float):  # a sweep: where it lifts off, no number
            import numpy as np

            return np.where(n > 0, np.abs(t) / np.where(n > 0, n, 1.0), np.inf)
        return abs(t) / n if n > 0 else None

    def angle_words(self) -> str:
        """The pressure angle in words, saying where it is the default."""
        deg = math.degrees(self.teeth)
        return f"{deg:.4g} deg" + (
            "" if self.stated else " (the default; pressure_angle in [rolling] gives it)"
        )

    def holding_words(self) -> str:
        """``; the frame holds the sun of 40 teeth about O with 45.45 N m cw`` on a fixed
        circle (the torque a book asks to hold the sun), else nothing."""
        if self.holding is None or not isinstance(self.holding, float):
            return ""
        what = self.words[1] if self.words else "the fixed circle"
        h = self.holding
        return f"; the frame holds {what} with {fmt(abs(h))} N m {sense_word(h)}".rstrip()

    def grip_words(self) -> str:
        """The friction rolling needs here, in words (or why the wheel lifts off); for
        teeth, the tooth load along the line of action."""
        if self.teeth is not None:
            return (
                f"the tooth load along the line of action, at the pressure angle "
                f"{self.angle_words()} to the common tangent: {self.load:.4g} N (its "
                f"part along the tangent {abs(self.tangential):.4g} N, pushing the teeth "
                f"apart {self.normal:.4g} N)" + self.holding_words()
            )
        if self.grip is not None:  # a friction drive (or a stated mu): holds or slips
            return grip_words(self)
        mu = self.required_friction
        if mu is None:
            return (
                f"the ground would have to pull wheel {self.wheel} down (N = "
                f"{self.normal:.4g} N): it lifts off the line, and rolling without "
                "slip does not hold"
            )
        return (
            f"no slip needs a friction coefficient of at least |T| / N = {mu:.3g} at the "
            f"contact of {self.wheel}"
        )


@dataclass(frozen=True)
class Side:
    """One force as a force polygon and a free-body diagram draw it: ``vector`` (N) on body
    ``on`` (by body ``by`` for a pin or a guide), acting along a line through ``at`` (m):
    the pin or the loaded point, G for a weight; for an inertia force, G in a polygon's
    side and, in a :class:`FreeBody`, the offset point of the book's single force (G where
    there is none). ``what``: ``inertia``, ``weight``, ``load``, ``gas``, ``pin``, ``guide``,
    ``contact`` (the ground's, the teeth's) or ``driver`` (a driving block's); ``point``: the point it acts at (a pin, a loaded
    point; "" for an inertia force or a weight); ``part``: "" the whole force, ``t`` its
    component square to the link (a block's guide) from ``point``, ``n`` its component
    along it (at a contact: ``n`` normal to it, ``t`` along it)."""

    what: str
    on: str
    by: str
    point: str
    vector: tuple
    at: tuple
    part: str = ""


@dataclass(frozen=True)
class Couple:
    """A couple (N m, ccw positive) on body ``on``: ``what`` ``inertia`` (``-I alpha``,
    drawn only where no single inertia force carries it: ``a_G = 0``), ``load`` (a
    ``[loads]`` couple), ``friction`` (a pin's friction circle's), ``guide`` (a guide's,
    holding a rack or a yoke from turning) or
    ``torque`` (the driver's, on the crank or a driving wheel); ``point``: a friction
    couple's pin (a body with friction at two pins has two)."""

    what: str
    on: str
    value: float
    point: str = ""


@dataclass(frozen=True)
class FreeBody:
    """One body alone with every force on it (``sides``, whole forces at their points)
    and every couple (``couples``): what its free-body diagram draws. ``number`` is the
    body's number on the sheet (the frame 1)."""

    body: str
    number: int
    sides: tuple
    couples: tuple


@dataclass(frozen=True)
class ForcePolygon:
    """One force polygon of a step: the balance of ``bodies`` drawn head to tail from the
    pole (``polygon``: the :class:`Side` s in the order drawn, closing on the pole),
    ``unknown`` (index, unit direction) the sides whose direction alone the book knows
    before it closes the polygon (their lines drawn through its corners), ``chords``
    (:class:`Side`, i, j) the whole forces read across it. A group of more than two bodies
    may draw one for each body that carries forces of its own (a triad's plate and its
    loaded links; a driving collar, its rod and the link it is pinned to)."""

    bodies: tuple
    polygon: tuple
    unknown: tuple = ()
    chords: tuple = ()


@dataclass(frozen=True)
class ForceStep:
    """One step of the force solution, in the order solved (the kinematic plan's, reversed):
    ``kind`` (crank, dyad, slider), ``title``, ``bodies`` and, for each body, the resultant
    ``(Fx, Fy, M)`` of what was known on it before the step (inertia, weight, loads, the
    forces of the bodies solved before; M about the frame's origin), the unknowns found
    (name -> value), the ``condition`` of its equations (1 best, 0 singular) and ``why``
    (what the condition measures); ``equations`` its working in words.

    A sweep's records hold arrays and no words."""

    index: int
    kind: str
    title: str
    bodies: tuple
    known: tuple
    found: tuple
    condition: float
    why: str = ""
    #: the step's equations with their numbers, in the book's words (SI)
    equations: tuple = ()
    #: a function giving (polygon, unknown, chords), made when first asked for (one
    #: instant; None over a sweep); or (polygon, unknown, chords, polygons), ``polygons``
    #: every :class:`ForcePolygon` of the step, the first that one
    drawing: object = field(default=None, repr=False, compare=False)
    #: the pin forces (:class:`PinForce`) and guide forces (:class:`GuideForce`) it found
    pins: tuple = ()
    guides: tuple = ()

    @cached_property
    def _drawn(self):
        return self.drawing() if self.drawing is not None else ((), (), ())

    @property
    def polygon(self) -> tuple:
        """Its force polygon: the :class:`Side` s in the order drawn, head to tail from the
        pole, closing on it (the group's known forces, then the unknowns: each outer pin's
        force as its components square to its link, from the link's moments, and along
        it, found where the direction lines meet)."""
        return self._drawn[0]

    @property
    def unknown(self) -> tuple:
        """The sides (index, unit direction) whose direction alone was known: their lines
        are drawn through the polygon's known corners and meet where it closes."""
        return self._drawn[1]

    @property
    def chords(self) -> tuple:
        """Whole forces read across the polygon: (:class:`Side`, i, j), the vector from
        corner i to corner j (corner 0 the pole, corner k the end of side k - 1)."""
        return self._drawn[2]

    @property
    def polygons(self) -> tuple:
        """Every force polygon of the step (:class:`ForcePolygon`), the first its
        :attr:`polygon`: one for most groups; a triad's plate and each of its links that
        carries forces of its own, a driving collar, its rod and its link, each their own."""
        d = self._drawn
        if len(d) > 3:
            return d[3]
        return (ForcePolygon(self.bodies, *d),) if d[0] else ()


@dataclass(frozen=True)
class Forces:
    """The force analysis at one instant.

    ``inertia`` (:class:`Inertia` per massive body), ``pins`` (:class:`PinForce`, one per
    pair of bodies at a pin, in the order solved), ``guides`` (:class:`GuideForce`),
    ``input_torque`` (N m, on the crank by its driver, ccw positive, inertia included; for a
    driving block, ``driver == "block"``, the force on it by its driver, N, signed along
    its guide's direction; a driving collar's, ``"collar"``, along its rod, + outward; for
    a driving wheel, ``"wheel"``, the torque on the wheel by its driver), ``shaking_force``
    (the resultant force the mechanism exerts on the frame, through its pins and guides,
    and a gas force's push on the cylinder's cover: the gas acts between the piston and
    the frame) and ``shaking_moment`` (its moment about the frame's origin, with the
    driver's reaction ``-input_torque`` on the frame), ``steps`` (:class:`ForceStep`).
    ``applied``: body -> the loads and weights on it, (what, (Fx, Fy), point) and (what,
    couple) entries.

    The numbers are held; the records are made when first read (``compute only what is
    asked for``), from ``source``: a tuple whose first item ``R`` makes them,
    ``R.parts(source)`` (``inertia``, ``pins``, ``guides``), ``R.story(source)``
    (``steps``, ``applied``, ``contacts``, what the drawings read) and
    ``R.resultant(source, body)`` (:meth:`resultant`)."""

    input_torque: float
    shaking_force: tuple
    shaking_moment: float
    crank: str
    #: "crank" (a driving torque), "block" (a driving force along the block's guide),
    #: "cylinder" (the force in the cylinder ``crank`` names, + pushing its ends apart) or
    #: "wheel" (a torque on the driving wheel ``crank`` names)
    driver: str = "crank"
    #: a second input's effort and body: a crank's torque (N m, ccw +), a collar's force (N)
    second_torque: float | None = None
    second_crank: str | None = None
    #: what makes the records when first read (see above)
    source: tuple = field(default=(), repr=False, compare=False)
    #: a driving wheel's effort as a force at its centre along the ground instead of the
    #: torque (N, a vector): ``(input_torque / r) t``, t = perp(m) along the ground; else None
    centre_force: tuple | None = None
    #: the friction (``[friction]``) the forces were found with: (body, what, force, point)
    #: at the guides and (body, what, couple) at the pins, reactions included
    #: (:func:`.friction.loads`), and its power (W, never positive)
    friction: tuple = ()
    friction_power: float = 0.0
    #: with friction, how the passes settled (:func:`.friction.settling`): (the
    #: contraction q, the last change of the forces, N, of the effort, of a second effort)
    settling: tuple = ()

    def resultant(self, body: str) -> tuple:
        """``(Fx, Fy, M about the origin)`` of every force on ``body`` but those of its own
        group's unknowns: its inertia, weight and loads, and the reactions of the groups
        solved before its own (what its force polygon starts from; for a slider's block,
        the piston's known forces). No group solved after a body's own acts on it: it
        finds no point of it."""
        return self.source[0].resultant(self.source, body)

    @cached_property
    def _parts(self) -> tuple:
        return self.source[0].parts(self.source)

    @cached_property
    def _story(self) -> tuple:
        return self.source[0].story(self.source)

    @property
    def inertia(self) -> tuple:
        """:class:`Inertia` per massive body, in the scene's order."""
        return self._parts[0]

    @property
    def pins(self) -> tuple:
        """:class:`PinForce` s, one per pair of bodies at a pin, in the order solved."""
        return self._parts[1]

    @property
    def guides(self) -> tuple:
        """:class:`GuideForce` s, in the order solved."""
        return self._parts[2]

    @property
    def steps(self) -> tuple:
        """:class:`ForceStep` s, in the order solved (their words and drawings)."""
        return self._story[0]

    @property
    def applied(self) -> dict:
        """body -> the loads and weights on it (see the class)."""
        return self._story[1]

    @property
    def contacts(self) -> tuple:
        """The contact force on each rolling body (:class:`Contact`): a wheel on a line, a
        gear, a planet, a rack."""
        return self._story[2]

    @property
    def drawing(self) -> tuple:
        """What :attr:`numbers` and :attr:`free` are read from: (a function making body ->
        number, a function making the free bodies from it)."""
        return self._story[3]

    @cached_property
    def numbers(self) -> dict:
        """body -> its number on the sheet, as the books number links: the frame 1, then
        the bodies in the order the plan finds them (the crank 2)."""
        return self.drawing[0]() if self.drawing else {}

    @cached_property
    def free(self) -> tuple:
        """:class:`FreeBody` of each moving body, in the order of :attr:`numbers` (one
        instant, or arrays over a sweep)."""
        return self.drawing[1](self.numbers) if self.drawing else ()

    def pin(self, point: str, on: str, by: str | None = None):
        """The force on body ``on`` at ``point`` (by ``by``, when the pin joins more than two
        bodies); the opposite of the stored record where the pair is stored the other way."""
        for p in self.pins:
            if p.point != point:
                continue
            if p.on == on and (by is None or p.by == by):
                return p.force
            if p.by == on and (by is None or p.on == by):
                return (-p.force[0], -p.force[1])
        raise KeyError((point, on, by))

    def inertia_of(self, body: str):
        """The inertia record of ``body``, or None when it has no mass."""
        return next((i for i in self.inertia if i.body == body), None)
