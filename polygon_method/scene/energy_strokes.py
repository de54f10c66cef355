"""The ``[turning_moment] strokes`` of a turning-moment diagram's scene (a part of
:mod:`polygon_method.scene.energy`'s reader): the books' engine whose diagram is stated by
the work of each stroke, "the work done by the gases during the expansion stroke is three
times the work done on them during the compression stroke, the suction and exhaust strokes
negligible; the turning moment during each stroke a triangle".

Each stroke is half a turn of the crank, in the cycle's order from its start (a four-stroke
engine's suction, compression, expansion, exhaust). ``strokes`` gives each one's work, as
energies (``["0 J", "-4 kJ", "12 kJ", "0 J"]``) or in proportion (``[0, -1, 3, 0]``) with the
net work of a cycle (``work``) or the engine's ``power`` at the mean speed of
``[flywheel]`` (``W = P Theta / w``, Theta the cycle's angle: 4 pi for a four-stroke engine).
Each stroke's turning moment is a triangle on its half turn, its peak ``2 W_k / pi`` at
mid-stroke (its area W_k): the diagram is then straight segments, solved as any table.

>>> [round(x, 6) for x in _peaks([0.0, -4000.0, 12000.0, 0.0])[1]]
[0.0, 0.0, 0.0, -2546.479089, 0.0, 7639.437268, 0.0, 0.0, 0.0]
"""

from __future__ import annotations

import math
import re

from ..common.tolerances import ROUNDING
from ..common.units import did_you_mean
from .energy_areas import ABSURD_ENERGY, ABSURD_ENERGY_WORDS
from .energy_records import Diagram, Table

#: the most strokes a cycle may have (a four-stroke engine has 4; 16 covers any book's)
MAX_STROKES = 16
_SHAPES = ("triangle",)
_AREA_SCALE = re.compile(
    r"^\s*((?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(mm\^2|mm2|mm²|cm\^2|cm2|cm²|m\^2|m2|m²)"
    r"\s*=\s*(.+?)\s*$"
)
_AREAS = {
    "mm^2": "mm^2",
    "mm2": "mm^2",
    "mm²": "mm^2",
    "cm^2": "cm^2",
    "cm2": "cm^2",
    "cm²": "cm^2",
    "m^2": "m^2",
    "m2": "m^2",
    "m²": "m^2",
}


def _peaks(works) -> tuple:
    """(angles rad, torques N m) of the triangles, one a half turn, of the strokes' works
    (J): 0 at each stroke's ends, ``2 W / pi`` at its middle."""
    angles, torques = [0.0], [0.0]
    for k, w in enumerate(works):
        angles += [(k + 0.5) * math.pi, (k + 1) * math.pi]
        torques += [2.0 * w / math.pi, 0.0]
    return tuple(angles), tuple(torques)


class _StrokesReader:
    """The reader's methods for ``strokes`` (mixed into the cycle reader)."""

    def _strokes(self, spec, t, at) -> Diagram:
        raw = spec["strokes"]
        numbers = isinstance(raw, list) and all(
            isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
            for v in raw
        )
        energies = isinstance(raw, list) and all(isinstance(v, str) for v in raw)
        if not (numbers or energies) or not 2 <= len(raw) <= MAX_STROKES:
            raise self.err(
                f"strokes = [0, -1, 3, 0]: each stroke's work in proportion (2 to "
                f'{MAX_STROKES} strokes, with work or power), or ["0 J", "-4 kJ", "12 kJ", '
                '"0 J"]: each stroke\'s work',
                t,
                "strokes",
            )
        for k in ("torque", "resisting", "angle", "unit", "areas"):
            if k in spec:
                raise self.err(f"{k}: not with strokes (the strokes' works are the diagram)", t, k)
        n = len(raw)
        cycle, cw = self._cycle(spec, t, n * math.pi)
        if abs(cycle - n * math.pi) > ROUNDING * cycle:
            raise self.err(
                f"{n} strokes of half a turn each make {180 * n} deg, not "
                f"{math.degrees(cycle):g} (a four-stroke engine's cycle has 4)",
                t,
                "cycle",
            )
        shape = spec.get("shape", "triangle")
        if shape not in _SHAPES:
            raise self.err(
                f"shape = {shape!r}{did_you_mean(str(shape), list(_SHAPES))}: each stroke's "
                'turning moment "triangle" (the books\' assumption)',
                t,
                "shape",
            )
        words = []
        if energies:
            for k in ("power", "work"):
                if k in spec:
                    raise self.err(f"{k}: not with the strokes' works given as energies", t, k)
            works = [self.ld.qty(v, "energy", t, "strokes").value for v in raw]
            words.append("each stroke's work given: " + ", ".join(f"{w:.6g} J" for w in works))
        elif any(k in spec for k in ("area_scale", "area_unit", "torque_scale", "angle_scale")):
            works = self._stroke_areas(spec, t, raw, words)
        else:
            works = self._proportions(spec, t, raw, cycle, words)
        if not max(abs(w) for w in works) <= ABSURD_ENERGY:  # (also an overflow to inf)
            raise self.err(ABSURD_ENERGY_WORDS, t, "strokes")
        if not math.fsum(works) > 0:
            raise self.err(
                "the strokes' works add up to no net work: an engine's cycle does work "
                "(the expansion more than the compression; a stroke done on the gases is "
                "negative)",
                t,
                "strokes",
            )
        angles, torques = _peaks(works)
        words.append(
            "each stroke a triangle on its half turn, its peak 2 W / pi at mid-stroke: "
            + ", ".join(f"{x:.6g}" for x in torques[1::2])
            + f" N m; {cw}"
        )
        words.append("the resisting torque constant, the mean (default)")
        table = Table(angles, torques, f"{n} strokes, each a triangle")
        return Diagram("strokes", cycle, driving=table, resisting=None, at=at, words=tuple(words))

    def _proportions(self, spec, t, raw, cycle, words) -> list:
        """The strokes' works (J) from their proportions and the net work of a cycle: given
        (``work``), or the power at the flywheel's mean speed over the cycle's time."""
        ways = [k for k in ("work", "power") if k in spec]
        if len(ways) != 1:
            raise self.err(
                'strokes in proportion need the net work of a cycle (work = "8 kJ") or the '
                'engine\'s power (power = "20 kW", at [flywheel] speed): one of them',
                t,
                ways[1] if ways else "power",
            )
        total = math.fsum(raw)
        if not total > 0:
            raise self.err(
                f"the strokes' proportions add up to {total:g}: an engine's cycle does net "
                "work (the expansion more than the compression, which is negative)",
                t,
                "strokes",
            )
        W = self._cycle_work(spec, t, ways[0], cycle, words)
        n = spec.get("cylinders")
        if isinstance(n, int) and not isinstance(n, bool) and n >= 2:  # the engine's
            W /= n
            words.append(f"the engine's {n} cylinders share it: {W:.6g} J a cylinder")
        works = [r * W / total for r in raw]
        words.append(
            "the strokes' works in proportion "
            + " : ".join(f"{r:g}" for r in raw)
            + f" (net {total:g}): "
            + ", ".join(f"{x:.6g} J" for x in works)
        )
        return works

    def _stroke_areas(self, spec, t, raw, words) -> list:
        """The strokes' works (J) from their triangles' areas on the diagram (above the line
        of zero turning moment positive): ``area_scale = "1 m^2 = 3 MN m"`` (the energy an
        area stands for), or ``area_unit`` "mm^2" / "cm^2" with the diagram's
        ``torque_scale`` and ``angle_scale``, as for the areas of a diagram."""
        for k in ("power", "work"):
            if k in spec:
                raise self.err(f"{k}: not with the strokes' areas (they give the works)", t, k)
        if "area_scale" in spec:
            for k in ("area_unit", "torque_scale", "angle_scale"):
                if k in spec:
                    raise self.err(f"{k}: not with area_scale (it gives the areas' energy)", t, k)
            per, unit = self._area_scale(spec["area_scale"], t)
        else:
            unit = spec.get("area_unit", "mm^2")
            if unit not in ("mm^2", "mm2", "mm²", "cm^2", "cm2", "cm²"):
                raise self.err(
                    f'area_unit = {unit!r}: "mm^2" or "cm^2" with torque_scale and '
                    'angle_scale (or area_scale = "1 m^2 = 3 MN m")',
                    t,
                    "area_unit",
                )
            per = self._per_area(spec, t, unit)
        works = [float(v) * per for v in raw]
        words.append(
            f"1 {unit} of the diagram = {per:.6g} J: the strokes' works "
            + ", ".join(f"{w:.6g} J" for w in works)
        )
        return works

    def _area_scale(self, raw, t) -> tuple:
        """(J per unit area, the area's unit) of ``"1 m^2 = 3 MN m"``."""
        m = _AREA_SCALE.match(raw) if isinstance(raw, str) else None
        if m is None or m.group(2) not in _AREAS:
            raise self.err(
                f'area_scale = {raw!r}: the energy an area of the diagram stands for, "1 m^2 = '
                '3 MN m" (or per mm^2, cm^2)',
                t,
                "area_scale",
            )
        e = self.ld.qty(m.group(3), "energy", t, "area_scale").value
        a = float(m.group(1))
        if not (a > 0 and e > 0):
            raise self.err("area_scale: both sides must be positive", t, "area_scale")
        return e / a, _AREAS[m.group(2)]

    def _fluctuation(self, spec, t, at) -> Diagram:
        """The book's energy alone, no diagram: "the maximum fluctuation of energy is 15 %
        of the work done per revolution" (``dE_max = "15%"`` with ``work`` or ``power``) or
        "the fluctuation of energy is 56 kN m" (``dE_max = "56 kN m"``; ``work`` or
        ``power`` then give the mean torque)."""
        for k in ("resisting", "angle", "unit", "area_unit", "area_scale", "shape"):
            if k in spec:
                raise self.err(f"{k}: not with dE_max (no diagram is given)", t, k)
        if at is not None:
            raise self.err("at: the acceleration at an angle needs the diagram", t, "at")
        raw = spec["dE_max"]
        cycle, cw = self._cycle(spec, t, 2 * math.pi)
        words = []
        ways = [k for k in ("work", "power") if k in spec]
        if len(ways) > 1:
            raise self.err("give the work of a cycle or the power: one of them", t, "power")
        W = None
        if ways:
            W = self._cycle_work(spec, t, ways[0], cycle, words)
        share = isinstance(raw, str) and raw.strip().endswith("%")
        if share:
            if W is None:
                raise self.err(
                    f"dE_max = {raw!r}: a part of the work of a cycle, which needs work = "
                    '"111 kJ" or power = "185 kW" (at [flywheel] speed)',
                    t,
                    "dE_max",
                )
            ce = self.ld.qty(raw, "percent", t, "dE_max").value
            if not 0 < ce < 10:
                raise self.err(  # (1e300% was refused as not "above 0")
                    f"dE_max = {raw!r}: a part of the work, above 0 and below 1000%",
                    t,
                    "dE_max",
                )
            dE = ce * W
            words.append(
                f"the maximum fluctuation of energy {ce:.6g} of the work of a cycle (the "
                f"coefficient of fluctuation of energy): dE_max = {ce:.6g} x {W:.6g} = {dE:.6g} J"
            )
        else:
            dE = self.ld.qty(raw, "energy", t, "dE_max").value
            words.append(f"the maximum fluctuation of energy given: dE_max = {dE:.6g} J")
        if not dE > 0:
            raise self.err(f"dE_max = {raw!r}: the fluctuation must be positive", t, "dE_max")
        words.append(f"no diagram: the energy's fluctuation is the book's statement; {cw}")
        return Diagram("energy", cycle, words=tuple(words), fluctuation=dE, work=W)

    def _cycle_work(self, spec, t, way, cycle, words) -> float:
        """The net work of a cycle (J): ``work``, or ``power`` over a cycle's time at the
        flywheel's mean speed."""
        if way == "work":
            W = self.ld.qty(spec["work"], "energy", t, "work").value
            words.append(f"the net work of a cycle W = {W:.6g} J (given)")
        else:
            P = self.ld.qty(spec["power"], "power", t, "power").value
            w = self._strokes_speed(t)
            W = P * cycle / w
            words.append(
                f"the net work of a cycle W = P Theta / w = {P:.6g} x {cycle:.6g} / {w:.6g} = "
                f"{W:.6g} J (the power over the time of one cycle at the mean speed)"
            )
        if not W > 0:
            raise self.err("the net work of a cycle must be positive", t, way)
        return W

    def _strokes_speed(self, t) -> float:
        """The mean speed (rad/s) that turns a power into a cycle's work: [flywheel]'s
        ``speed``, or the mean of its ``max_speed`` and ``min_speed``."""
        fly = self.raw.get("flywheel")
        fly = fly if isinstance(fly, dict) else {}
        if "speed" in fly:
            return self._speed(fly, "flywheel", "speed")
        if "max_speed" in fly and "min_speed" in fly:
            hi, lo = (self._speed(fly, "flywheel", k) for k in ("max_speed", "min_speed"))
            return (hi + lo) / 2
        raise self.err(
            'power needs the mean speed to give the work of a cycle: [flywheel] speed = "300 '
            'rpm" (or give work = the net work of a cycle)',
            t,
            "power",
        )
