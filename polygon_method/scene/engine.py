"""The engine chapter's tables: ``[indicator]`` (the gas pressure on the piston over a whole
cycle, a table against the crank angle or the stroke) and ``[flywheel]`` (the coefficient of
fluctuation of speed the flywheel must keep, its rim). A part of the scene reader.

An indicator pressure pushes the piston towards the crank (negative: away, as in a suction
stroke below the atmosphere); the crank angle of its table counts from the inner dead centre
in the crank's sense of rotation, over 360 deg (a two-stroke engine, a steam engine) or
720 deg (a four-stroke engine).
"""

from __future__ import annotations

import math

from ..common.units import ABSURD, UNITS, did_you_mean
from .records import FixedPath, Flywheel, Indicator

_INDICATOR_KEYS = ("piston", "bore", "rod", "cycle", "unit", "angle", "stroke", "pressure")
_FLYWHEEL_KEYS = ("coefficient", "plus_minus", "speed", "radius", "gyration")
#: the least coefficient of fluctuation of speed (or +- range) a scene may ask for
_LEAST_FLUCTUATION = 1e-6
_CYCLES = {
    "2-stroke": 2 * math.pi,
    "two-stroke": 2 * math.pi,
    "steam": 2 * math.pi,
    "4-stroke": 4 * math.pi,
    "four-stroke": 4 * math.pi,
}


class _Engine:
    """The scene reader's methods for [indicator] and [flywheel] (mixed into the reader)."""

    def indicator(self, sliders):
        """[indicator]: an :class:`Indicator`, or None without the table."""
        if "indicator" not in self.raw:
            return None
        spec = self.table("indicator")
        t = "indicator"
        for k in spec:
            if k not in _INDICATOR_KEYS:
                raise self.error(f"unknown key '{k}'{did_you_mean(k, list(_INDICATOR_KEYS))}", t, k)
        fixed = [s.point for s in sliders if isinstance(s, FixedPath) and not s.slot]
        piston = spec.get("piston")
        if piston is None:
            if len(fixed) != 1:
                raise self.error(
                    'name the piston: piston = "B" (a slider on a fixed path)', t, "piston"
                )
            piston = fixed[0]
        if piston not in fixed:
            raise self.error(
                f"piston = {piston!r}: no slider on a fixed path of that name", t, "piston"
            )
        if "bore" not in spec:
            raise self.error(
                "the indicator's pressure acts on the piston's area: give bore "
                "(and rod, the piston rod's diameter, on a crank side)",
                t,
                "bore",
            )
        bore = self.length(spec["bore"], t, "bore")
        area = math.pi / 4 * bore * bore
        words = f"on a {self._words(bore)} bore"
        if "rod" in spec:
            rod = self.length(spec["rod"], t, "rod")
            if rod >= bore:
                raise self.error(
                    f"the piston rod ({self._words(rod)}) must be thinner than "
                    f"the bore ({self._words(bore)})",
                    t,
                    "rod",
                )
            area -= math.pi / 4 * rod * rod
            words += f" less a {self._words(rod)} rod"
        cyc = str(spec.get("cycle", "2-stroke")).strip().lower()
        if cyc not in _CYCLES:
            raise self.error(
                f'cycle = {spec.get("cycle")!r}: "2-stroke" (one turn, also a '
                'steam engine) or "4-stroke" (two turns)',
                t,
                "cycle",
            )
        cycle = _CYCLES[cyc]
        unit = spec.get("unit")
        if not isinstance(unit, str) or unit.strip() not in UNITS["pressure"]:
            raise self.error(
                f"unit = {unit!r}: the pressures' unit, one of " + ", ".join(UNITS["pressure"]),
                t,
                "unit",
            )
        k = UNITS["pressure"][unit.strip()]
        has_angle, has_stroke = "angle" in spec, "stroke" in spec
        if has_angle == has_stroke:
            raise self.error(
                "give the pressure against the crank angle (angle = [0, 30, "
                "...], deg from the inner dead centre) or against the stroke "
                "(stroke = [0, 0.25, ...], fractions from the inner dead centre, "
                "with one row of pressures per stroke): one of them",
                t,
                "angle" if has_angle else "stroke",
            )
        if "pressure" not in spec:
            raise self.error("no pressure: the indicator's pressures, in unit", t, "pressure")
        if has_angle:
            xs = self._numbers(spec["angle"], t, "angle")
            if xs[0] < 0 or xs[-1] > math.degrees(cycle) + 1e-9:
                raise self.error(
                    f"the angles run from 0 to {math.degrees(cycle):g} deg (the "
                    f"{cyc} cycle from the inner dead centre)",
                    t,
                    "angle",
                )
            ps = self._numbers(spec["pressure"], t, "pressure", increasing=False)
            if len(ps) != len(xs):
                raise self.error(f"{len(ps)} pressures for {len(xs)} angles", t, "pressure")
            self._pressures(ps, k, unit, t)
            return Indicator(
                piston,
                area,
                cycle,
                "angle",
                tuple(math.radians(x) for x in xs),
                tuple(p * k for p in ps),
                f"{cyc} indicator diagram, {len(xs)} crank angles, {words}",
            )
        xs = self._numbers(spec["stroke"], t, "stroke")
        if xs[0] < 0 or xs[-1] > 1:
            raise self.error(
                "the stroke's places are fractions from 0 (inner dead centre) to 1 (outer)",
                t,
                "stroke",
            )
        rows = spec["pressure"]
        n = round(cycle / math.pi)
        if (
            not isinstance(rows, list)
            or len(rows) != n
            or not all(isinstance(r, list) for r in rows)
        ):
            raise self.error(
                f"pressure = one row per stroke ({n} for a {cyc} cycle), each a "
                "pressure at every place of stroke",
                t,
                "pressure",
            )
        ps = []
        for r in rows:
            row = self._numbers(r, t, "pressure", increasing=False)
            if len(row) != len(xs):
                raise self.error(
                    f"a row of {len(row)} pressures for {len(xs)} places of stroke", t, "pressure"
                )
            self._pressures(row, k, unit, t)
            ps.append(tuple(p * k for p in row))
        return Indicator(
            piston,
            area,
            cycle,
            "stroke",
            tuple(xs),
            tuple(ps),
            f"{cyc} indicator diagram, {n} strokes of {len(xs)} places, {words}",
        )

    def _pressures(self, ps, k, unit, table):
        """Refuse a pressure beyond what a mechanism meets (a units slip; the cycle's
        torque and energy of such a pressure overflow)."""
        worst = max(abs(p) for p in ps)
        if not worst * k <= ABSURD["pressure"]:
            raise self.error(
                f"a pressure of {worst:g} {unit.strip()} is absurd for an engine "
                f"(more than {ABSURD['pressure']:g} Pa); check the values and "
                "their unit",
                table,
                "pressure",
            )

    def _numbers(self, raw, table, key, increasing=True):
        """A list of plain numbers (at least two; strictly increasing where asked)."""
        if (
            not isinstance(raw, list)
            or len(raw) < 2
            or not all(
                isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
                for v in raw
            )
        ):
            raise self.error(f"{key} = a list of at least two numbers", table, key)
        xs = [float(v) for v in raw]
        if increasing and any(b <= a for a, b in zip(xs, xs[1:])):
            raise self.error(f"{key}: the values must increase", table, key)
        return xs

    def flywheel(self):
        """[flywheel]: a :class:`Flywheel`, or None without the table."""
        if "flywheel" not in self.raw:
            return None
        spec = self.table("flywheel")
        t = "flywheel"
        for k in spec:
            if k not in _FLYWHEEL_KEYS:
                raise self.error(f"unknown key '{k}'{did_you_mean(k, list(_FLYWHEEL_KEYS))}", t, k)
        if ("coefficient" in spec) == ("plus_minus" in spec):
            raise self.error(
                "give the coefficient of fluctuation of speed, coefficient = "
                "0.02 ((w_max - w_min) / w_mean, the whole range), or the speed's "
                'range either side of the mean, plus_minus = "1%": one of them',
                t,
                "coefficient",
            )
        key = "coefficient" if "coefficient" in spec else "plus_minus"
        raw = spec[key]
        if isinstance(raw, str) and raw.strip().endswith("%"):
            c = self.qty(raw, "percent", t, key).value
        elif isinstance(raw, (int, float)) and not isinstance(raw, bool):
            c = float(raw)
        else:
            raise self.error(f'{key} = {raw!r}: a number (0.02) or a percentage ("2%")', t, key)
        if not 0 < c < 1:
            raise self.error(
                f"{key} = {raw!r}: between 0 and 1 (a fraction of the mean speed)", t, key
            )
        if c < _LEAST_FLUCTUATION:  # I = dE / (w^2 Cs): a units slip, and it overflows
            raise self.error(
                f"{key} = {raw!r}: no flywheel keeps the speed that steady (at "
                f"least {_LEAST_FLUCTUATION:g} of the mean speed; books give "
                "0.002 to 0.2 for the whole range)",
                t,
                key,
            )
        if key == "plus_minus":
            words = f"the speed within +-{raw} of the mean: Cs = 2 x {c:g} = {2 * c:g}"
            c *= 2
        else:
            words = f"Cs = {c:g}"
        speed = None
        if "speed" in spec:
            speed = abs(self.qty(spec["speed"], "angular_velocity", t, "speed").value)
            if not speed > 0:
                raise self.error("the mean speed must not be zero", t, "speed")
        if "radius" in spec and "gyration" in spec:
            raise self.error(
                "give the rim's radius or the radius of gyration, not both", t, "gyration"
            )
        radius = self.length(spec["radius"], t, "radius") if "radius" in spec else None
        gyr = self.length(spec["gyration"], t, "gyration") if "gyration" in spec else None
        return Flywheel(c, speed, radius, gyr, words)
