"""What follows from a motion: rubbing velocities at pins, the input torque by power
balance, the transmission angles. One set of formulas for one instant (floats) and for a
sweep (arrays).

* rubbing at a pin joining bodies 1 and 2: ``|w1 - w2| r`` (signed omegas: the sum of the
  magnitudes when they turn in opposite senses, the difference when alike);
* input torque T on the crank (ccw positive): ``T w + sum(F . v) + sum(T_load w_link) = 0``;
* transmission angle at a dyad or slider: the acute angle whose sine is its condition.
"""

from __future__ import annotations

from collections import defaultdict

from ..common.tolerances import crossing_angle
from ..scene.cylinder_loads import length_of, stated
from ..scene.link_loads import load_force

from ..steps.rounding import largest
from .plan import pin_entry

__all__ = [
    "PinRubbing",
    "rubbing_at",
    "pin_rubbing",
    "pin_records",
    "rubbing_records",
    "plan_records",
    "largest",
    "power_terms",
    "input_torque",
    "transmission_angle",
]


def rubbing_at(pin, W, radius) -> tuple:
    """``|w_i - w_j| r`` for each pair of bodies a pin joins (``pin``: an entry of
    ``plan.pins``; a body without a link, the ground or a block on a fixed path, does not
    turn)."""
    w = W.get  # a body without a link (None) is not in W: it does not turn
    pairs = pin[5]
    if len(pairs) == 1:  # a pin of two bodies (the usual one)
        ((a, b),) = pairs
        return (abs(w(a, 0.0) - w(b, 0.0)) * radius,)
    return tuple([abs(w(a, 0.0) - w(b, 0.0)) * radius for a, b in pairs])


def pin_rubbing(plan, W, radii) -> dict:
    """pin -> :func:`rubbing_at` for every sized pin (the pair keys are ``plan.pins``'
    "a|b" names)."""
    return {pin[0]: rubbing_at(pin, W, radii[pin[0]]) for pin in plan.pins}


def pin_records(pins, W, radii) -> dict:
    """pin -> :class:`PinRubbing` for every sized pin at one instant (floats): the values of
    :func:`rubbing_at`, in one pass (:func:`rubbing_records` with the radii ``radii``)."""
    return rubbing_records(tuple(pin_entry(pin, radii[pin[0]]) for pin in pins), W)


def rubbing_records(table, W) -> dict:
    """pin -> :class:`PinRubbing` for every pin of ``table`` (``plan.pin_table``: each
    sized pin's :func:`pin_entry`, made once per plan) at one instant: the values of
    :func:`rubbing_at`, in one pass, a link not in ``W`` turning at 0 (as
    :func:`rubbing_at` has it: ``W`` read through a :class:`~collections.defaultdict`)."""
    w = defaultdict(float, W)
    out = {}
    for k in table:
        p, r, _, pairs, a, b = k
        if pairs is None:  # a pin of two bodies (the usual one)
            rec = PinRubbing()
            rec.rubbing_velocity = (
                abs((0.0 if a is None else w[a]) - (0.0 if b is None else w[b])) * r
            )
        else:
            rec = _Many()
            vs = tuple(
                [
                    abs((0.0 if x is None else w[x]) - (0.0 if y is None else w[y])) * r
                    for x, y in pairs
                ]
            )
            rec._values = vs
            rec.rubbing_velocity = max(vs) if vs else 0.0
        rec._k = k  # the pin, its radius (constant: one field for the three)
        rec._W = W
        out[p] = rec
    return out


def plan_records(plan, W) -> dict:
    """The records of :func:`rubbing_records` at a ``plan``'s sized pins: where every pin
    joins two bodies, one at least turning (``plan.pin_rows``, :func:`~.plan.two_body_rows`,
    made when first asked), in one pass with no test of a body's link per pin; else, or
    where a link is not in ``W`` (turning at 0), by :func:`rubbing_records`."""
    rows = plan.pin_rows
    if rows is None:  # not yet made
        rows = plan.two_body_rows()
    if rows is False:
        return rubbing_records(plan.pin_table, W)
    out = {}
    Rec = PinRubbing
    try:
        for p, r, k, a, b in rows:
            out[p] = rec = Rec()
            rec.rubbing_velocity = abs(W[a] - W[b]) * r if b is not None else abs(W[a]) * r
            rec._k = k
            rec._W = W
    except KeyError:
        return rubbing_records(plan.pin_table, W)
    return out


class PinRubbing:
    """Rubbing velocity at a pin: ``|w1 - w2| r`` for each pair of bodies the pin joins.

    Attributes: ``point``, ``radius``, ``values`` (one per pair), ``pairs`` ({"AB|BC": v}),
    ``bodies`` ({body: omega}) and ``rubbing_velocity`` (the largest pair). Made by
    :func:`pin_records` and :func:`rubbing_records`; a pin of more than two bodies is a
    :class:`_Many` (its values kept apart).
    """

    # _k: the pin's table entry; a pin of two bodies has one value, rubbing_velocity (no
    # tuple made until read)
    __slots__ = ("rubbing_velocity", "_k", "_W")

    @property
    def values(self) -> tuple:
        """The rubbing velocity of each pair of bodies the pin joins, in ``pairs``' order
        (a pin of two bodies: its one pair's)."""
        return (self.rubbing_velocity,)

    @values.setter
    def values(self, vs):
        """Set the values (a tidied solution writes its noise as exact zeros): a pin of two
        bodies its one value, as its rubbing velocity."""
        (self.rubbing_velocity,) = vs

    @property
    def point(self) -> str:
        """The pin's point."""
        return self._k[0]

    @property
    def radius(self) -> float:
        """The pin's radius (m)."""
        return self._k[1]

    @property
    def _pin(self) -> tuple:  # the pin as ``plan.pins`` gives it
        return self._k[2]

    @property
    def pairs(self) -> dict:
        """Each pair of bodies the pin joins and its rubbing velocity |w1 - w2| r."""
        return dict(zip(self._pin[3], self.values))

    @property
    def bodies(self) -> dict:
        """Each body the pin joins and its omega."""
        W = self._W
        return {name: W.get(lk, 0.0) for name, lk in zip(self._pin[1], self._pin[2])}

    def __repr__(self):
        return f"PinRubbing({self.point!r}, radius={self.radius!r}, pairs={self.pairs!r})"


class _Many(PinRubbing):
    """A :class:`PinRubbing` at a pin of more than two bodies: a value for each pair."""

    __slots__ = ("_values",)

    @property
    def values(self) -> tuple:
        """The rubbing velocity of each pair of bodies the pin joins, in ``pairs``' order."""
        return self._values

    @values.setter
    def values(self, vs):
        """Set the values (a tidied solution writes its noise as exact zeros)."""
        self._values = tuple(vs)


def power_terms(scene, V, W, S=None, P=None) -> list:
    """(what, power in W) of each load: F . v for forces, T w for torques on links; with the
    sliding rates ``S``, then ``F vs`` of each passive cylinder's given force (vs its rate
    of extension; at rest a damper pushes nothing; with the positions ``P`` a spring's
    ``k (L0 - L)``), named ``cylinder C-R``."""
    out = []
    for load in scene.loads:
        if load.force is not None:
            fx, fy = load.force if P is None else load_force(load, P)  # (turning with a link)
            vx, vy = V[load.target]
            out.append((load.target, fx * vx + fy * vy))
        else:
            out.append((load.target, load.torque * W[scene.link(load.target).key]))
    for c in stated(scene) if S is not None else ():  # (after the loads: zipped with them)
        vs = S[c.key][0]
        n = length_of(c, P) if c.stiffness else None  # (a spring: its length)
        out.append((f"cylinder {c.key}", c.force_at(vs, scene.at_rest, n) * vs))
    return out


def input_torque(scene, V, W, omega, S=None, P=None):
    """T on the crank, ccw positive, from the power balance; None without loads (``S``: a
    passive cylinder's given force is a load, :func:`power_terms`)."""
    if not (scene.loads or S is not None and stated(scene)) or scene.input.second is not None:
        return None  # two inputs: one power balance does not give two driving torques
    terms = power_terms(scene, V, W, S, P)
    total = terms[0][1]
    for _, p in terms[1:]:
        total = total + p
    return -total / omega


def transmission_angle(condition):
    """The transmission angle (deg, acute) from a step's condition (its sine)."""
    return crossing_angle(condition)
