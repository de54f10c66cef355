"""Drawing scales chosen as a textbook chooses them: 1, 2, 2.5 or 5 x 10^k per cm.

>>> choose_scale(3.393, unit="m/s").text     # 6.79 cm of drawing for the crank pin
'1 cm = 0.5 m/s'
>>> choose_scale(0.7, fit_cm=15, unit="mm").text   # 700 mm of mechanism on 14 cm
'1 cm = 50 mm'
>>> s = parse_scale("1 cm = 0.1 m/s")
>>> s.per_cm, s.kind, s.cm(0.392)
(0.1, 'velocity', 3.92)

A scale maps a quantity in SI (m, m/s, m/s^2) to centimetres of drawing: ``cm = q / per_cm``.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from decimal import Decimal

from .constructions import acceleration_constructions, drawn_vectors, velocity_constructions
from ..common.errors import PolygonMethodError, SceneError
from ..common.units import UNITS
from ..common.tolerances import ROUNDING, SAME

__all__ = [
    "Scale",
    "choose_scale",
    "parse_scale",
    "diagram_scales",
    "choose_scales",
    "parse_scales",
    "coarser",
    "finer",
    "MANTISSAS",
    "FIT_CM",
    "SPACE_FIT_CM",
    "DRAWING_PRECISION_CM",
    "extent",
    "DIAGRAMS",
    "KIND_OF_DIAGRAM",
    "force_scale",
    "polygon_corners",
    "newton_scale",
]

#: the round numbers a textbook scale is made of (times a power of ten)
MANTISSAS = ("1", "2", "2.5", "5")
#: the largest extent of a velocity or acceleration diagram on the page (cm)
FIT_CM = 12.0
#: the largest extent of the configuration diagram (across an A4 page, cm)
SPACE_FIT_CM = 15.0
#: how closely a careful drawing is drawn and read: half a millimetre
DRAWING_PRECISION_CM = 0.05

#: the SI a centimetre of drawing may stand for, by kind: beyond, a scale is a slip (its
#: diagram would be kilometres across, or a speck) and its text hundreds of digits long
_SANE_PER_CM = {
    "length": (1e-9, 1e4),
    "velocity": (1e-12, 1e6),
    "acceleration": (1e-12, 1e12),
    "force": (1e-9, 1e12),
}
_SI = {"length": "m", "velocity": "m/s", "acceleration": "m/s^2", "force": "N"}

_KIND_OF_UNIT = {u: k for k in ("length", "velocity", "acceleration", "force") for u in UNITS[k]}


@dataclass(frozen=True)
class Scale:
    """``1 cm = value unit``: one centimetre of drawing stands for ``per_cm`` (SI).

    Attributes
    ----------
    value : str
        The round number as written (``"0.5"``, ``"25"``), in ``unit``.
    unit : str
        The unit it is written in (``"m/s"``, ``"mm"``).
    kind : str
        ``length``, ``velocity`` or ``acceleration``.
    per_cm : float
        SI quantity per centimetre of drawing (``0.5`` for 1 cm = 0.5 m/s; ``0.02`` for
        1 cm = 20 mm).
    """

    value: str
    unit: str
    kind: str
    per_cm: float

    @property
    def text(self) -> str:
        """The scale as a book writes it: "1 cm = 0.1 m/s"."""
        return f"1 cm = {self.value} {self.unit}"

    def __str__(self) -> str:
        return self.text

    def cm(self, quantity: float) -> float:
        """Length on the drawing (cm) of a quantity (SI): ``quantity / per_cm``."""
        return quantity / self.per_cm

    def quantity(self, cm: float) -> float:
        """The quantity (SI) that ``cm`` centimetres of drawing stand for."""
        return cm * self.per_cm


def _unit_kind(unit: str) -> str:
    kind = _KIND_OF_UNIT.get(unit)
    if kind is None:
        raise SceneError(
            f"unknown unit {unit!r} for a scale; use a length (mm, cm, m), a "
            "velocity (m/s, mm/s), an acceleration (m/s^2) or a force (N, kN)",
            key="scale",
        )
    return kind


def _text(d: Decimal) -> str:
    s = format(d.normalize(), "f")
    return s


def choose_scale(max_magnitude: float, fit_cm: float = FIT_CM, unit: str = "m/s") -> Scale:
    """The smallest round scale (1, 2, 2.5, 5 x 10^k ``unit`` per cm) at which
    ``max_magnitude`` (SI) takes at most ``fit_cm`` centimetres of drawing.

    A zero or non-finite magnitude gets ``1 cm = 1 unit``.
    """
    kind = _unit_kind(unit)
    factor = UNITS[kind][unit]
    if not (fit_cm > 0):
        raise SceneError(f"fit_cm must be positive, got {fit_cm!r}", key="scale")
    need = max_magnitude / factor / fit_cm  # unit per cm, at least
    if not (math.isfinite(need) and need > 0):
        return Scale("1", unit, kind, factor)
    k = math.floor(math.log10(need)) - 1
    while True:
        for m in MANTISSAS:
            d = Decimal(m).scaleb(k)
            if float(d) >= need * (1 - ROUNDING):
                return Scale(_text(d), unit, kind, float(d) * factor)
        k += 1


_SCALE = re.compile(r"^\s*([0-9.]+)\s*(cm|mm)\s*=\s*([-+0-9.eE]+)\s*(.+?)\s*$")


def parse_scale(text: str, kind: str | None = None) -> Scale:
    """Read ``"1 cm = 0.1 m/s"`` (also ``"2 cm = 1 m/s"``, ``"1 cm = 20 mm"``).

    ``kind`` (``length``, ``velocity``, ``acceleration``), when given, must match the unit.
    Raises :class:`SceneError` on anything else.
    """
    m = _SCALE.match(str(text))
    if not m:
        raise SceneError(f'cannot read scale {text!r}; write it as "1 cm = 0.1 m/s"', key="scale")
    try:
        paper = Decimal(m.group(1))
        value = Decimal(m.group(3))
    except ArithmeticError:
        raise SceneError(
            f'cannot read scale {text!r}; write it as "1 cm = 0.1 m/s"', key="scale"
        ) from None
    if m.group(2) == "mm":
        paper = paper / 10
    unit = m.group(4)
    got = _unit_kind(unit)
    if kind is not None and got != kind:
        raise SceneError(f"scale {text!r} is a {got} scale, not a {kind} one", key="scale")
    if not (paper > 0 and value > 0 and value.is_finite()):
        raise SceneError(f"scale {text!r}: both sides must be positive", key="scale")
    per = value / paper
    si = float(per) * UNITS[got][unit]
    low, high = _SANE_PER_CM[got]
    if not low <= si <= high:
        raise SceneError(
            f"scale {text!r} is absurd for a mechanism's diagram (1 cm for "
            f"{si:g} {_SI[got]}; between {low:g} and {high:g}); leave --scale "
            "out and the tool chooses one",
            key="scale",
        )
    return Scale(_text(per), unit, got, si)


def extent(points) -> float:
    """The size of a diagram: the largest distance between two of its points (two corners
    of their convex hull: a thousand points are not a million pairs)."""
    pts = _hull(points)
    return max((math.dist(p, q) for i, p in enumerate(pts) for q in pts[i + 1 :]), default=0.0)


def _hull(points) -> list:
    """The corners of the convex hull of ``points`` (Andrew's monotone chain; collinear
    points dropped, as no farthest pair needs them)."""
    pts = sorted(set((float(x), float(y)) for x, y in points))
    if len(pts) <= 3:
        return pts

    def half(seq):
        out = []
        for p in seq:
            while (
                len(out) >= 2
                and (
                    (out[-1][0] - out[-2][0]) * (p[1] - out[-2][1])
                    - (out[-1][1] - out[-2][1]) * (p[0] - out[-2][0])
                )
                <= 0
            ):
                out.pop()
            out.append(p)
        return out

    lower, upper = half(pts), half(reversed(pts))
    return lower[:-1] + upper[:-1]


def diagram_scales(sol, fit_cm: float = FIT_CM, space_fit_cm: float = SPACE_FIT_CM):
    """(space, velocity, acceleration) scales for a solution's three diagrams.

    Each is the smallest round scale at which the diagram's size (the largest distance
    between two of its points: joints for the configuration, with its pitch circles and a
    yoke's slot, the pole and every image
    point for a polygon, and the ends of the components its construction draws) is at most ``space_fit_cm`` (configuration, in the scene's length
    unit) or ``fit_cm`` (each polygon).
    """

    def drawn(records):  # every end of every vector the construction draws
        return [p for c in records for v in c.given + c.found for p in (v.start, v.end)]

    sc = sol.scene
    pole = [(0.0, 0.0)]
    vel = pole + list(sol.V.values()) + drawn(velocity_constructions(sol))
    acc = pole + list(sol.A.values()) + drawn(acceleration_constructions(sol))
    return (
        choose_scale(
            extent(list(sol.P.values()) + _drawn_beside(sol)), space_fit_cm, unit=sc.units
        ),
        choose_scale(extent(vel), fit_cm, unit="m/s"),
        choose_scale(extent(acc), fit_cm, unit="m/s^2"),
    )


def _drawn_beside(sol) -> list:
    """Points (m) of what a configuration diagram draws beyond the joints, so that its scale
    holds them too: eight points on each pitch circle (a ring, a sun, a gear) and, for a
    translating yoke, its slot's far end (the bar reaches as far past the yoke's point as
    the pin is on the near side)."""
    out = []
    for st in sol.plan.steps:
        for shape in st.shapes(sol.P):
            if shape[0] == "circle":
                c = sol.P[shape[1]] if isinstance(shape[1], str) else shape[1]
                out += [
                    (
                        c[0] + shape[2] * math.cos(k * math.pi / 4),
                        c[1] + shape[2] * math.sin(k * math.pi / 4),
                    )
                    for k in range(8)
                ]
    for sl in sol.scene.sliders:
        if hasattr(sl, "yoke"):
            (yx, yy), (px, py) = sol.P[sl.yoke], sol.P[sl.point]
            out.append((2 * yx - px, 2 * yy - py))
    return out


def polygon_corners(step) -> list:
    """The corners (N) of a force step's polygon (or of one of its polygons, a
    ``ForcePolygon``): the pole, then the end of each side in turn (the last is the pole
    again, to rounding)."""
    out = [(0.0, 0.0)]
    for side in step.polygon:
        x, y = out[-1]
        out.append((x + side.vector[0], y + side.vector[1]))
    return out


def force_scale(forces, fit_cm: float = FIT_CM) -> Scale:
    """The one force scale of a sheet of force polygons: the smallest round scale (1, 2,
    2.5, 5 x 10^k N or kN per cm) at which the largest polygon is at most ``fit_cm`` across
    (the rule of the velocity and acceleration polygons); in kN from 1 cm = 1 kN (a
    polygon 4 800 N across: 1 cm = 500 N; 68 700 N across: 1 cm = 10 kN)."""
    size = max(
        (extent(polygon_corners(pg)) for st in forces.steps for pg in st.polygons), default=0.0
    )
    return newton_scale(size, fit_cm)


def newton_scale(size: float, fit_cm: float) -> Scale:
    """The smallest round force scale at which ``size`` (N) takes at most ``fit_cm``: in N,
    or in kN from 1 cm = 1 kN."""
    s = choose_scale(size, fit_cm, unit="N")
    return choose_scale(size, fit_cm, unit="kN") if s.per_cm >= 1e3 else s


# --------------------------------------------------------------------------- the sheets


def display_unit(text: str) -> str:
    """``m/s^2`` as printed on a drawing: ``m/s\u00b2``."""
    return text.replace("^2", "\u00b2")


DIAGRAMS = ("configuration", "velocity", "acceleration")
KIND_OF_DIAGRAM = {
    "configuration": "length",
    "velocity": "velocity",
    "acceleration": "acceleration",
    "forces": "force",
}
#: A4 portrait for one diagram, A4 landscape for the three side by side (cm)
SHEET_ONE = (21.0, 29.7)
SHEET_ALL = (29.7, 21.0)
MARGIN = 0.8  # sheet margin (cm)
GAP = 0.8  # between panels (cm)


def _scale_unit(kind: str, sol) -> str:
    return {"length": sol.scene.units, "velocity": "m/s", "acceleration": "m/s^2"}[kind]


def _extents_si(sol, diagram):
    """Width and height (SI) of what a diagram must show: the mechanism's points, or the
    pole and every point and vector end of a polygon."""
    if diagram == "configuration":
        pts = list(sol.P.values())
    else:
        pts = [(0.0, 0.0)] + [p for v in drawn_vectors(sol, diagram) for p in (v.start, v.end)]
        pts += list((sol.V if diagram == "velocity" else sol.A).values())
    xs = [p[0] for p in pts]
    ys = [p[1] for p in pts]
    return max(xs) - min(xs), max(ys) - min(ys)


def _room(diagram: str, n: int):
    """(width, height) in cm left for the geometry of one panel on its sheet: the sheet
    less its margins, the gaps, a header and room for labels around the figure."""
    sw, sh = SHEET_ALL if n > 1 else SHEET_ONE
    w = (sw - 2 * MARGIN - (n - 1) * GAP) / min(n, 2)  # (the sheet is shared out later)
    h = sh - 2 * MARGIN
    header = 4.2 if diagram == "acceleration" else 3.0
    return w - 1.6, h - header - 1.6


def _fit_scale(sol, diagram, room) -> Scale:
    """The smallest textbook-round scale at which the diagram fits ``room`` (cm)."""
    ex, ey = _extents_si(sol, diagram)
    need = max(ex / room[0], ey / room[1])
    unit = _scale_unit(KIND_OF_DIAGRAM[diagram], sol)
    return choose_scale(need, 1.0, unit=unit)


def coarser(scale: Scale) -> Scale:
    """The next round scale after ``scale`` (the drawing gets smaller)."""
    return choose_scale(scale.per_cm * (1 + SAME), 1.0, unit=scale.unit)


def finer(scale: Scale) -> Scale:
    """The round scale before ``scale`` (the drawing gets larger)."""
    s = choose_scale(scale.per_cm / 2.6, 1.0, unit=scale.unit)
    while True:
        n = coarser(s)
        if n.per_cm >= scale.per_cm * (1 - SAME):
            return s
        s = n


def choose_scales(sol, diagram: str = "all", given=None) -> dict:
    """First choice of each diagram's scale: ``given`` ones (by diagram name or kind) are
    kept, the others are the smallest textbook-round scales at which the diagram's points
    fit the room a panel can have on an A4 page (portrait for one diagram, landscape for
    three side by side). The drawing's layout then coarsens them until the labelled sheet
    fits."""
    names = DIAGRAMS if diagram == "all" else (diagram,)
    given = dict(given or {})
    out = {}
    for name in names:
        s = given.get(name) or given.get(KIND_OF_DIAGRAM[name])
        if s is None and len(names) == 1:  # one diagram: the scale `steps` states
            s = dict(zip(DIAGRAMS, diagram_scales(sol)))[name]
        out[name] = s if s is not None else _fit_scale(sol, name, _room(name, len(names)))
    return out


def parse_scales(texts) -> dict:
    """``--scale`` arguments (possibly repeated) -> {kind: Scale}; a kind given twice is an
    error."""
    out = {}
    for text in texts or ():
        try:
            s = parse_scale(text)
        except PolygonMethodError as exc:
            raise PolygonMethodError(exc.message, key="--scale") from None
        if s.kind in out:
            raise PolygonMethodError(
                f"two {s.kind} scales given ({out[s.kind]} and {s})", key="--scale"
            )
        out[s.kind] = s
    return out
