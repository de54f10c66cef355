"""A crank's speed as a book gives it: an angular velocity (``"180 rpm cw"``), or the linear
speed of its pin with the crank's sense (``"3 m/s cw"``: "the crank pin moves at 3 m/s"),
``omega = v / r`` with r the crank's length."""

from __future__ import annotations

from ..common.errors import SceneError
from ..common.units import Quantity, parse_quantity

__all__ = ["crank_speed"]


def crank_speed(reader, raw, link, table: str = "input") -> Quantity:
    """The crank ``link``'s angular velocity from ``raw`` (SI, signed, with its sense).

    >>> from polygon_method.scene.records import Link
    >>> class R:
    ...     def qty(self, raw, kind, *a, **k): return parse_quantity(raw, kind, **k)
    >>> crank_speed(R(), "3 m/s cw", Link("OA", "O", "A", 0.1))
    Quantity(value=-30.0, sense='cw')
    >>> crank_speed(R(), "60 rpm ccw", Link("OA", "O", "A", 0.1)).value == 2 * 3.141592653589793
    True
    """
    try:
        return reader.qty(raw, "angular_velocity", table, "speed", need_sense=True)
    except SceneError as exc:
        try:
            parse_quantity(raw, "velocity", allow_sense=True)  # the crank pin's speed
        except SceneError:  # in a unit of neither: the angular velocity's words;
            if not _speed_unit(raw):  # a pin's speed ("-3 m/s cw"): its own
                raise exc from None
    v = reader.qty(raw, "velocity", table, "speed", need_sense=True)
    return Quantity(v.value / link.length, v.sense)


def _speed_unit(raw) -> bool:
    """Whether ``raw`` is written in a unit of linear speed (``"-3 m/s cw"``, ``"3 ft/s"``):
    then its faults are a pin speed's, not an angular velocity's.

    >>> _speed_unit("-3 m/s cw"), _speed_unit("3 rad/s"), _speed_unit(3)
    (True, False, False)
    """
    from ..common.units import UNITS

    words = str(raw).split() if isinstance(raw, str) else []
    return any(w in UNITS["velocity"] for w in words[1:])
