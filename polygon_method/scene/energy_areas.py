"""The ``[turning_moment] areas`` of a turning-moment diagram's scene (a part of
:mod:`polygon_method.scene.energy`'s reader): the areas between the diagram and the mean
line, in order, in mm^2 with the diagram's scales or as energies."""

from __future__ import annotations

import math
import re

from ..common.tolerances import ROUNDING
from ..common.units import UNITS
from .energy_records import Diagram

#: the most areas a turning-moment diagram may give: each is drawn as a lobe with its
#: value, lettered at its crossings and a row of the table (100000 took minutes to draw)
MAX_AREAS = 100
#: an energy of a diagram's area or stroke beyond it is a slip of the scales (J)
ABSURD_ENERGY = 1e12
ABSURD_ENERGY_WORDS = f"an energy beyond {ABSURD_ENERGY:g} J is absurd; check the scales"
_SCALE = re.compile(r"^\s*([0-9.]+)\s*(mm|cm)\s*=\s*(.+?)\s*$")


class _AreasReader:
    """The reader's methods for the areas (mixed into the cycle reader)."""

    def _areas(self, spec, t) -> Diagram:
        xs = spec["areas"]
        if isinstance(xs, list) and len(xs) > MAX_AREAS:  # each is a lobe, a letter, a row
            raise self.err(
                f"{len(xs)} areas: at most {MAX_AREAS} (a book's diagram has a dozen; a "
                "diagram read at many angles is angle = [...] and torque = [...])",
                t,
                "areas",
            )
        if (
            not isinstance(xs, list)
            or len(xs) < 2
            or not all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in xs)
            or not all(math.isfinite(v) and v != 0 for v in xs)
        ):
            raise self.err(
                "areas = [+52, -124, ...]: at least two areas, in order, above the mean line "
                "positive, none zero",
                t,
                "areas",
            )
        unit = spec.get("area_unit", "mm^2")
        words = []
        if unit in ("mm^2", "mm2", "mm²", "cm^2", "cm2", "cm²"):
            per = self._per_area(spec, t, unit)
            words.append(
                f"1 {unit} of the diagram = {per:.6g} J (the torque scale times the angle "
                "scale in rad)"
            )
            mm2 = tuple(float(v) for v in xs)
        elif isinstance(unit, str) and unit in UNITS["energy"]:
            for k in ("torque_scale", "angle_scale"):
                if k in spec:
                    raise self.err(f"{k}: not with areas in {unit} (energies)", t, k)
            per, mm2 = UNITS["energy"][unit], ()
            words.append(f"the areas given as energies in {unit}")
        else:
            raise self.err(
                f'area_unit = {unit!r}: "mm^2" (with torque_scale and angle_scale) or an '
                "energy unit (" + ", ".join(UNITS["energy"]) + ")",
                t,
                "area_unit",
            )
        areas = tuple(float(v) * per for v in xs)
        scale = max(abs(a) for a in areas)
        if scale > ABSURD_ENERGY:
            raise self.err(ABSURD_ENERGY_WORDS, t, "areas")
        net = math.fsum(xs) * per  # the numbers as the book gives them, summed exactly
        if abs(net) <= ROUNDING * scale:
            net = 0.0  # (the rounding of their energies, not the book's)
        if abs(net) > 0.02 * scale:
            raise self.err(
                f"the areas add up to {net:.4g} J, not nought: over a cycle the energy the "
                "engine gives above the mean equals what it takes below (check the signs)",
                t,
                "areas",
            )
        if net != 0:
            words.append(f"the areas add up to {net:.4g} J (the book's rounding), not nought")
        cycle, w = self._cycle(spec, t, 2 * math.pi)
        words.append(w)
        return Diagram(
            "areas", cycle, areas=areas, mm2=mm2, per_mm2=per if mm2 else None, words=tuple(words)
        )

    def _per_area(self, spec, t, unit) -> float:
        side = 1e-3 if unit.startswith("mm") else 1e-2  # the paper's unit, m
        vals = []
        for key, kind in (("torque_scale", "torque"), ("angle_scale", "angle")):
            raw = spec.get(key)
            m = _SCALE.match(raw) if isinstance(raw, str) else None
            if m is None:
                example = "1 mm = 70 N m" if kind == "torque" else "1 mm = 4.5 deg"
                raise self.err(
                    f'{key} = "{example}": the diagram\'s scale, with areas in {unit}', t, key
                )
            paper = float(m.group(1)) * (1e-3 if m.group(2) == "mm" else 1e-2)
            if not paper > 0:
                raise self.err(f"{key}: the paper's length must be positive", t, key)
            q = self.ld.qty(m.group(3), kind, t, key).value
            if not q > 0:
                raise self.err(f"{key}: the scale must be positive", t, key)
            vals.append(q / (paper / side))
        return vals[0] * vals[1]
