"""The tables after [ground] and [links], one method each (a part of the scene reader):
[cylinders], [assembly] hints, [pins] and an angle in a book's words here; [points],
[sliders] and [loads] in :mod:`.carried`, :mod:`.sliders` and :mod:`.loads`, mixed in."""

from __future__ import annotations

from ..common.errors import SceneError
from .angles import read_angle
from .carried import _CarriedPoints
from .loads import _Loads
from .records import Cylinder, Pin, split_name
from .sliders import _Sliders
from .table_help import _which_point


class _Tables(_CarriedPoints, _Sliders, _Loads):
    """The scene reader's methods for one table each (mixed into the reader)."""

    def _words(self, metres: float) -> str:
        """A length (m) in the scene's unit, as the step tables write it: ``280 mm``."""
        return f"{metres / self.scale():.6g} {self.unit}"

    def cylinders(self, known):
        """``[cylinders] "O-R" = {}``: a cylinder, barrel pivoted at O, rod pinned at R;
        optionally ``{ stroke = [closed, extended] }`` (pin-to-pin lengths)."""
        out = []
        for key, spec in self.table("cylinders").items():
            pts = split_name(key)
            if len(pts) != 2 or pts[0] == pts[1]:
                raise self.error(
                    f"{key!r} is not a cylinder's name: its barrel's pivot, then "
                    'its rod\'s end, e.g. "O-R" or OR',
                    "cylinders",
                    key,
                )
            for p in pts:
                if p not in known:
                    raise self.error(
                        f"no point {p} in the scene{_which_point(p, known)}: a "
                        "cylinder joins two points of the mechanism (a ground "
                        "point or a link's joint)",
                        "cylinders",
                        key,
                    )
            if frozenset(pts) in self.index:
                raise self.error(
                    f"{key} is also a rigid link in [links]: a cylinder changes "
                    "its length; remove one of them",
                    "cylinders",
                    key,
                )
            if not isinstance(spec, dict) or set(spec) - {"stroke"}:
                raise self.error(
                    "a cylinder is {} or { stroke = [closed, extended] }", "cylinders", key
                )
            stroke = spec.get("stroke")
            if stroke is not None:
                if not (isinstance(stroke, list) and len(stroke) == 2):
                    raise self.error(
                        "stroke = [closed, extended]: its shortest and longest pin-to-pin lengths",
                        "cylinders",
                        key,
                    )
                lo, hi = (self.length(v, "cylinders", key) for v in stroke)
                if not lo < hi:
                    raise self.error(
                        f"stroke {stroke}: the closed length must be shorter than the extended one",
                        "cylinders",
                        key,
                    )
                stroke = (lo, hi)
            if any({c.barrel, c.rod} == set(pts) for c in out):
                raise self.error("the same two points have a cylinder already", "cylinders", key)
            out.append(Cylinder(key, pts[0], pts[1], stroke))
        return out

    def book_angle(self, raw, where, table, key, what, **kw):
        """An angle in a book's words (:mod:`.angles`), its reading noted (the crank's is
        noted with the crank: a copy of the scene at another angle has no such note); None
        for a plain angle."""
        try:
            book = read_angle(raw, where, strokes=self.strokes, **kw)
        except SceneError as exc:
            raise self.error(exc.message, table, key) from None
        if book is not None and where != "angle":
            self.read_notes.append(f"{what}: {book.note}")
        return book

    def assembly(self, known):
        out = {}
        for name, hint in self.table("assembly").items():
            if name not in known:
                raise self.error(
                    f"no point {name} in the scene{_which_point(name, known)}", "assembly", name
                )
            if isinstance(hint, str):
                if hint not in ("above", "below", "left", "right"):
                    raise self.error(
                        f"{hint!r}: use above, below, left, right or a rough position [x, y]",
                        "assembly",
                        name,
                    )
                out[name] = hint
            else:
                out[name] = self.coords(hint, "assembly", name)
        return out

    def pins(self, known):
        out = []
        for name, spec in self.table("pins").items():
            if name not in known:
                raise self.error(
                    f"no point {name} in the scene{_which_point(name, known)}", "pins", name
                )
            if (
                not isinstance(spec, dict)
                or len(spec) != 1
                or next(iter(spec)) not in ("diameter", "radius")
            ):
                raise self.error("a pin is { diameter = 30 } or { radius = 15 }", "pins", name)
            ((k, v),) = spec.items()
            size = self.length(v, "pins", name)
            out.append(Pin(name, size / 2 if k == "diameter" else size, k))
        return out
