"""A crank's speed as a book gives it: an angular velocity (``"180 rpm cw"``), or the linear
speed of its pin with the crank's sense (``"3 m/s cw"``: "the crank pin moves at 3 m/s"),
``omega = v / r`` with r the crank's length; a second crank's angle and a link's (the
position given by a rocker's angle) in a book's words."""

from __future__ import annotations

from ..common.errors import SceneError
from ..common.units import Quantity, parse_quantity
from .angles import is_book_form

__all__ = ["crank_speed", "second_crank_angle", "link_angle"]


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


def second_crank_angle(reader, raw, link, pivot, ground, omega) -> float:
    """[input.second]'s crank angle (rad): a plain angle, or a book's words read as the first
    crank's ("makes 30 deg with the vertical, ccw", "angle EDA = 60 deg, cw"), noted."""
    if not is_book_form(raw):
        return reader.qty(raw, "angle", "input.second", "angle", default_unit="deg").value
    book = reader.book_angle(
        *(raw, "angle", "input.second", "angle", "second crank angle"),
        dead=lambda: reader.dead_centres(link, pivot, link.other(pivot), ground),
        **dict(sense=omega or None, centres=(pivot, ground)),
    )
    reader.read_notes.append(f"second crank angle: {book.note}")
    return book.value


def link_angle(reader, raw, key, names, ground) -> float:
    """``angle_DC`` (rad), the direction D -> C that sets the position: a plain angle, or a
    book's words ("120 deg from DA, cw", "makes 30 deg with the vertical, cw"), from the
    frame's line where D is a ground point; noted."""
    if not is_book_form(raw):
        return reader.qty(raw, "angle", "input", key, default_unit="deg").value

    def no_dead_centre():
        raise SceneError("a dead centre is a position of the crank; give the link's angle from +x")

    pivot = names[0] if names[0] in ground else None
    book = reader.book_angle(
        *(raw, "angle", "input", key, key),
        dead=no_dead_centre,
        centres=None if pivot is None else (pivot, ground),
    )
    reader.read_notes.append(f"{key}: {book.note}")
    return book.value


def _speed_unit(raw) -> bool:
    """Whether ``raw`` is written in a unit of linear speed (``"-3 m/s cw"``, ``"3 ft/s"``):
    then its faults are a pin speed's, not an angular velocity's.

    >>> _speed_unit("-3 m/s cw"), _speed_unit("3 rad/s"), _speed_unit(3)
    (True, False, False)
    """
    from ..common.units import UNITS

    words = str(raw).split() if isinstance(raw, str) else []
    return any(w in UNITS["velocity"] for w in words[1:])
