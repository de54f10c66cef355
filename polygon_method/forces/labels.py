"""The book's names of the forces and couples on the sheet, the polygons and in words:
``F32`` the force on link 3 by link 2 (the frame is link 1), ``Fi3`` link 3's inertia
force, ``T2`` the driver's torque; with subscripts or written out."""

from __future__ import annotations

from .records import Couple, Side

__all__ = ["number_sub", "side_label", "couple_label"]

_SUB = str.maketrans("0123456789", "\u2080\u2081\u2082\u2083\u2084\u2085\u2086\u2087\u2088\u2089")


def _sub(numbers, *bodies, unicode=True):
    nums = [str(numbers.get(b, "?")) for b in bodies]
    text = ("," if any(len(n) > 1 for n in nums) else "").join(nums)
    return text.translate(_SUB) if unicode else "_" + text


def number_sub(numbers: dict, body: str, unicode: bool = True) -> str:
    """A body's number as a subscript (``G\u2083`` is link 3's centre of mass)."""
    return _sub(numbers, body, unicode=unicode)


def side_label(side: Side, numbers: dict, unicode: bool = True) -> str:
    """The book's name of a force: ``F32`` the force on link 3 by link 2 (the frame is
    link 1), ``F34t``/``F34n`` its components square to and along link 3, ``Fi3`` link 3's
    inertia force, ``W3`` its weight, ``P at E`` a load, ``gas force``; with subscripts
    (``F\u2083\u2082``) or, ``unicode=False``, written out (``F_32^t``).

    >>> side_label(Side("pin", "AB", "BC", "B", (1.0, 0.0), (0.0, 0.0), "t"),
    ...            {"frame": 1, "AB": 3, "BC": 4}, unicode=False)
    'F_34^t'
    """
    sup = {"t": "\u1d57", "n": "\u207f"} if unicode else {"t": "^t", "n": "^n"}
    if side.what in ("pin", "guide", "contact"):
        return "F" + _sub(numbers, side.on, side.by, unicode=unicode) + sup.get(side.part, "")
    if side.what == "inertia":
        return ("F\u1d62" if unicode else "Fi") + _sub(numbers, side.on, unicode=unicode)
    if side.what == "weight":
        return "W" + _sub(numbers, side.on, unicode=unicode)
    if side.what in ("driver", "gas"):  # a driving block's driver, along its guide
        return "gas force" if side.what == "gas" else "Fd" + _sub(numbers, side.on, unicode=unicode)
    if side.what == "friction":
        head = "\u03bcN" if unicode else "muN"  # on ``on`` by the body it rubs on
        return head + (
            _sub(numbers, side.on, side.by, unicode=unicode) if side.by else f" at {side.point}"
        )
    return f"{'Fd' if side.what == 'driver' else 'P'} at {side.point}"  # (Fd: a collar's driver)


def couple_label(c: Couple, numbers: dict, unicode: bool = True) -> str:
    """``T2`` the driver's torque on link 2, ``C4`` a couple on link 4, ``Ci3`` the inertia
    couple of link 3, ``C\u03bc3 at A`` the friction circle's couple on link 3 at pin A."""
    head = {
        "torque": "T",
        "load": "C",
        "guide": "C",
        "friction": "C\u03bc" if unicode else "Cmu",
        "inertia": "C\u1d62" if unicode else "Ci",
    }[c.what]
    at = f" at {c.point}" if c.what == "friction" and c.point else ""  # each pin's own
    return head + _sub(numbers, c.on, unicode=unicode) + at
