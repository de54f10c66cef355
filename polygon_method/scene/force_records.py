"""The force chapter's records of a scene: a body's mass (:class:`Mass`), gravity
(:class:`Gravity`), an engine's indicator diagram (:class:`Indicator`), the flywheel asked
for (:class:`Flywheel`) and friction (:class:`Friction`); the rolling body an answer names
(:func:`rolling_body`). The scene's other records are in :mod:`.records`."""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["Mass", "Gravity", "Indicator", "Flywheel", "Friction", "rolling_body"]


@dataclass(frozen=True)
class Mass:
    """A body's mass (kg) for the force analysis: a link's (``body`` its key) or a slider
    block's, a piston's (``body`` its point, ``block`` True). The centre of mass
    ``G = P + lam (Q - P) + mu perp(Q - P)`` on the link (``P``, ``Q`` its joint points, as a
    carried point's); a block's is its point. ``inertia``: the moment of inertia about G
    (kg m^2; ``m k^2`` when the radius of gyration ``k`` was given). ``how``: the words of
    the centre and of the inertia, for the step table."""

    body: str
    mass: float
    lam: float = 0.0
    mu: float = 0.0
    inertia: float = 0.0
    block: bool = False
    centre: str | None = None  # the point the scene named as the centre, or None
    how: str = ""


@dataclass(frozen=True)
class Gravity:
    """Gravity, when the scene states it (off otherwise): ``g`` (m/s^2) along unit
    ``direction`` (straight down, (0, -1), unless the scene turns it: a vertical engine
    drawn lying down)."""

    g: float
    direction: tuple
    text: str = ""


@dataclass(frozen=True)
class Indicator:
    """An indicator diagram: the gas pressure on the piston ``piston`` over a whole cycle
    (``cycle`` rad of the crank: 2 pi for a two-stroke engine or a steam engine, 4 pi for a
    four-stroke one), pushing it towards the crank on ``area`` (m^2, the bore's circle less
    the rod's where given). ``against`` is "angle" (``x``: crank angles from the inner dead
    centre in the crank's sense, rad; ``p``: the pressure at each, Pa; linear between them,
    round the cycle) or "stroke" (``x``: the piston's place as a fraction of the stroke from
    the inner dead centre, 0 to 1; ``p``: one row of pressures per stroke, in the cycle's
    order from the inner dead centre). ``words``: how the scene gave it. ``lag``: for a
    cylinder after the first of several on one crank, the crank angle (rad, in the sense of
    rotation) from the first cylinder's inner dead centre to where this one's cycle begins
    (its own inner dead centre, some turns on); None for the first, or where the scene
    leaves it to the geometry (the least such angle)."""

    piston: str
    area: float
    cycle: float
    against: str
    x: tuple
    p: tuple
    words: str = ""
    lag: float | None = None


@dataclass(frozen=True)
class Flywheel:
    """The flywheel asked for: the coefficient of fluctuation of speed ``coefficient``
    (``Cs = (w_max - w_min) / w_mean``, the whole range), the mean speed ``speed`` (rad/s;
    None: the crank's), the rim's mean radius ``radius`` (m) or the radius of gyration
    ``gyration`` (m) for its mass, or None; ``words``: how the scene gave Cs."""

    coefficient: float
    speed: float | None = None
    radius: float | None = None
    gyration: float | None = None
    words: str = ""


@dataclass(frozen=True)
class Friction:
    """Coulomb friction for the force analysis (``[friction]``): ``guides``, the
    coefficient at every sliding guide (the friction ``mu |N|`` opposing the block's
    sliding), ``pins``, the coefficient at every pin with a size in ``[pins]`` (the friction
    circle of radius ``mu r``: a couple ``mu r |F|`` opposing the relative turning).

    A book that gives each guide or pin its own coefficient ("0.1 at the slide, 0.15 in the
    slot of the lever") gives a table (``guides = { B = 0.1, A = 0.15 }``): ``at_guides``
    and ``at_pins`` are its (point, mu) pairs, and a guide or pin the table does not name has
    none (``guides``/``pins`` are then 0).

    >>> f = Friction(pins=0.05, at_guides=(("B", 0.1), ("A", 0.15)))
    >>> f.guide("A"), f.guide("Q"), f.pin("O"), f.active
    (0.15, 0.0, 0.05, True)
    >>> f.words()
    "mu = 0.1 at the guide of B, 0.15 at the guide of A (no other guide's), 0.05 at the pins with a size in [pins]"
    >>> Friction(0.1, 0.05).words()
    'mu = 0.1 at the guides, 0.05 at the pins with a size in [pins]'
    >>> Friction(0.1).words()
    'mu = 0.1 at the guides, none at the pins'

    A book may give the friction circle's radius itself ("the radius of the friction circle
    is 5 mm at each pin"): ``circle`` (m) at every pin, or ``at_circles`` each pin's, with no
    pin sizes needed.

    >>> f = Friction(circle=0.005)
    >>> f.radius("A", None), f.radius("A", 0.02), f.words()
    (0.005, 0.005, 'mu = none at the guides, a friction circle of 5 mm at every pin')
    >>> round(Friction(at_pins=(("O", 0.05),), at_circles=(("A", 0.0016),)).radius("O", 0.025), 12)
    0.00125
    """

    guides: float = 0.0
    pins: float = 0.0
    at_guides: tuple = ()
    at_pins: tuple = ()
    circle: float = 0.0
    at_circles: tuple = ()

    def guide(self, point: str, key: str | None = None) -> float:
        """The coefficient at the guide of the block at ``point`` (a peg's slot by its
        ``key`` first, ``P_OA``, then by its point)."""
        each = dict(self.at_guides)
        return each.get(key, each.get(point, self.guides))

    def pin(self, point: str) -> float:
        """The coefficient at the pin ``point`` (with a size in ``[pins]``)."""
        return dict(self.at_pins).get(point, self.pins)

    def radius(self, point: str, r: float | None) -> float | None:
        """The friction circle's radius (m) at the pin ``point`` of radius ``r`` (None: no
        size given): stated, or ``mu r``; None where the pin has no friction."""
        each = dict(self.at_circles)
        if point in each:
            return each[point]
        if self.circle and point not in dict(self.at_pins):
            return self.circle
        mu = self.pin(point)
        return mu * r if mu and r is not None else None

    @property
    def any_guides(self) -> bool:
        """Whether any guide has friction."""
        return bool(self.guides or any(mu for _, mu in self.at_guides))

    @property
    def any_pins(self) -> bool:
        """Whether any pin has friction."""
        return bool(
            self.pins
            or self.circle
            or any(mu for _, mu in self.at_pins)
            or any(r for _, r in self.at_circles)
        )

    @property
    def active(self) -> bool:
        """Whether any guide or pin has friction (not all coefficients nought)."""
        return self.any_guides or self.any_pins

    def words(self) -> str:
        """The coefficients as stated: "mu = 0.1 at the guides, 0.05 at the pins with a
        size in [pins]", or each named guide's and pin's."""
        g = (
            ", ".join(f"{mu:g} at the guide of {p}" for p, mu in self.at_guides)
            + " (no other guide's)"
            if self.at_guides
            else f"{self.guides:g} at the guides"
            if self.guides
            else "none at the guides"
        )
        named = [f"{mu:g} at pin {q}" for q, mu in self.at_pins] + [
            f"a friction circle of {r * 1e3:g} mm at pin {q}" for q, r in self.at_circles
        ]
        p = (
            ", ".join(named) + " (no other pin's)"
            if named
            else f"a friction circle of {self.circle * 1e3:g} mm at every pin"
            if self.circle
            else f"{self.pins:g} at the pins with a size in [pins]"
            if self.pins
            else "none at the pins"
        )
        return f"mu = {g}, {p}"


def rolling_body(scene, names) -> str:
    """The rolling body an answer's names give (``Fc_AP``): the wheel's link key, or a
    rack's ``block R``."""
    if len(names) == 1:
        return f"block {names[0]}"
    return scene.link("-".join(names)).key
