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

import dataclasses

from ..common.numbers import article
from ..common.tolerances import LEAST_FLUCTUATION, SAME
from ..common.units import ABSURD, UNITS, did_you_mean
from .records import FixedPath, Flywheel, Indicator

_INDICATOR_KEYS = ("piston", "bore", "rod", "cycle", "unit", "angle", "stroke", "pressure")
#: a sub-table's form of table ("angle" or "stroke") drops the shared table's other form
_OTHER = {"angle": ("stroke",), "stroke": ("angle",)}
_FLYWHEEL_KEYS = ("coefficient", "plus_minus", "speed", "radius", "gyration")
#: the least coefficient of fluctuation of speed (or +- range) a scene may ask for
_LEAST_FLUCTUATION = LEAST_FLUCTUATION
_CYCLES = {
    "2-stroke": 2 * math.pi,
    "two-stroke": 2 * math.pi,
    "steam": 2 * math.pi,
    "4-stroke": 4 * math.pi,
    "four-stroke": 4 * math.pi,
}

#: the atmosphere's pressure (Pa): a gauge pressure is never below its negative
ATMOSPHERE = 101_325.0


def _form(sub) -> str | None:
    """The form of table a sub-table gives: "angle", "stroke" or None (the shared one)."""
    return "angle" if "angle" in sub else ("stroke" if "stroke" in sub else None)


class _Engine:
    """The scene reader's methods for [indicator] and [flywheel] (mixed into the reader)."""

    def indicators(self, sliders) -> tuple:
        """[indicator]: its :class:`Indicator` records, () without the table. One piston's
        table as the keys of [indicator]; several cylinders' as a sub-table per piston
        (``[indicator.B]``, ``[indicator.C]``), each with the keys of [indicator] itself
        (the shared table) or its own, and ``lag``: the crank angle its cycle begins after
        the first's."""
        if "indicator" not in self.raw:
            return ()
        spec = self.table("indicator")
        subs = {k: v for k, v in spec.items() if isinstance(v, dict)}
        if not subs:
            return (self._indicator(spec, lambda k: "indicator", sliders),)
        shared = {k: v for k, v in spec.items() if not isinstance(v, dict)}
        if "piston" in shared:
            raise self.error(
                "with a sub-table per piston ([indicator.B], [indicator.C]) the sub-tables "
                "name the pistons: no piston here",
                "indicator",
                "piston",
            )
        out = []
        for n, (name, sub) in enumerate(subs.items()):
            t = f"indicator.{name}"
            for k in sub:
                if k not in _INDICATOR_KEYS[1:] + ("lag",):
                    keys = list(_INDICATOR_KEYS[1:]) + ["lag"]
                    raise self.error(f"unknown key '{k}'{did_you_mean(k, keys)}", t, k)
            merged = {k: v for k, v in shared.items() if k not in _OTHER.get(_form(sub), ())}
            merged.update({k: v for k, v in sub.items() if k != "lag"})
            merged["piston"] = name
            lag = None
            if "lag" in sub:
                lag = self.qty(sub["lag"], "angle", t, "lag", default_unit="deg").value
                if n == 0 and lag != 0:
                    raise self.error(
                        f"{name}'s is the first cylinder: the diagram's cycle begins at its "
                        "inner dead centre (no lag; give the others' after it)",
                        t,
                        "lag",
                    )
                if n and not 0 <= lag < out[0].cycle:
                    raise self.error(
                        f"lag = {sub['lag']!r}: from 0 to the cycle's "
                        f"{math.degrees(out[0].cycle):g} deg after the first cylinder's",
                        t,
                        "lag",
                    )

            def where(k, sub=sub, t=t):
                return t if k in sub or k == "piston" else "indicator"

            ind = self._indicator(merged, where, sliders)
            if out and ind.cycle != out[0].cycle:
                raise self.error(
                    f"{name}'s cycle is not {out[0].piston}'s: the cylinders on one crank "
                    "share their cycle (every one 2-stroke or every one 4-stroke)",
                    where("cycle"),
                    "cycle",
                )
            out.append(dataclasses.replace(ind, lag=lag) if n else ind)
        return tuple(out)

    def _indicator(self, spec, where, sliders):
        """One piston's :class:`Indicator` from the keys ``spec`` (``where(key)``: the
        table a key was given in, for the error's label)."""
        for k in spec:
            if k not in _INDICATOR_KEYS:
                keys = list(_INDICATOR_KEYS)
                raise self.error(f"unknown key '{k}'{did_you_mean(k, keys)}", where(k), k)
        piston, area, words = self._piston_area(spec, where, sliders)
        cyc = str(spec.get("cycle", "2-stroke")).strip().lower()
        if cyc not in _CYCLES:
            raise self.error(
                f'cycle = {spec.get("cycle")!r}: "2-stroke" (one turn, also a '
                'steam engine) or "4-stroke" (two turns)',
                where("cycle"),
                "cycle",
            )
        cycle = _CYCLES[cyc]
        unit = spec.get("unit")
        if not isinstance(unit, str) or unit.strip() not in UNITS["pressure"]:
            raise self.error(
                f"unit = {unit!r}: the pressures' unit, one of " + ", ".join(UNITS["pressure"]),
                where("unit"),
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
                where("angle" if has_angle else "stroke"),
                "angle" if has_angle else "stroke",
            )
        if "pressure" not in spec:
            raise self.error(
                "no pressure: the indicator's pressures, in unit", where("pressure"), "pressure"
            )
        if has_angle:
            xs = self._numbers(spec["angle"], where("angle"), "angle")
            # the cycle's end (deg), held to SAME of a degree: its rounding in degrees
            if xs[0] < 0 or xs[-1] > math.degrees(cycle) + SAME:
                raise self.error(
                    f"the angles run from 0 to {math.degrees(cycle):g} deg (the "
                    f"{cyc} cycle from the inner dead centre)",
                    where("angle"),
                    "angle",
                )
            ps = self._numbers(spec["pressure"], where("pressure"), "pressure", increasing=False)
            if len(ps) != len(xs):
                raise self.error(
                    f"{len(ps)} pressures for {len(xs)} angles", where("pressure"), "pressure"
                )
            self._pressures(ps, k, unit, where("pressure"))
            return Indicator(
                piston,
                area,
                cycle,
                "angle",
                tuple(math.radians(x) for x in xs),
                tuple(p * k for p in ps),
                f"{cyc} indicator diagram, {len(xs)} crank angles, {words}",
            )
        return self._stroke_table(spec, where, piston, area, (cycle, cyc), (k, unit), words)

    def _piston_area(self, spec, where, sliders):
        """(the piston, the area the pressure acts on, m^2, its words) of an indicator."""
        fixed = [s.point for s in sliders if isinstance(s, FixedPath) and not s.slot]
        piston = spec.get("piston")
        if piston is None:
            if len(fixed) != 1:
                raise self.error(
                    'name the piston: piston = "B" (a slider on a fixed path)',
                    where("piston"),
                    "piston",
                )
            piston = fixed[0]
        if piston not in fixed:
            raise self.error(
                f"piston = {piston!r}: no slider on a fixed path of that name",
                where("piston"),
                "piston",
            )
        if "bore" not in spec:
            raise self.error(
                "the indicator's pressure acts on the piston's area: give bore "
                "(and rod, the piston rod's diameter, on a crank side)",
                where("bore"),
                "bore",
            )
        bore = self.length(spec["bore"], where("bore"), "bore")
        area = math.pi / 4 * bore * bore
        words = f"on {article(self._words(bore))} bore"
        if "rod" in spec:
            rod = self.length(spec["rod"], where("rod"), "rod")
            if rod >= bore:
                raise self.error(
                    f"the piston rod ({self._words(rod)}) must be thinner than "
                    f"the bore ({self._words(bore)})",
                    where("rod"),
                    "rod",
                )
            area -= math.pi / 4 * rod * rod
            words += f" less a {self._words(rod)} rod"
        return piston, area, words

    def _stroke_table(self, spec, where, piston, area, cycles, units, words):
        """The :class:`Indicator` of a table against the stroke: one row of pressures per
        stroke (``cycles``: the cycle in rad and its name; ``units``: the factor to Pa and
        the unit's name)."""
        (cycle, cyc), (k, unit) = cycles, units
        xs = self._numbers(spec["stroke"], where("stroke"), "stroke")
        if xs[0] < 0 or xs[-1] > 1:
            raise self.error(
                "the stroke's places are fractions from 0 (inner dead centre) to 1 (outer)",
                where("stroke"),
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
                where("pressure"),
                "pressure",
            )
        ps = []
        for r in rows:
            row = self._numbers(r, where("pressure"), "pressure", increasing=False)
            if len(row) != len(xs):
                raise self.error(
                    f"a row of {len(row)} pressures for {len(xs)} places of stroke",
                    where("pressure"),
                    "pressure",
                )
            self._pressures(row, k, unit, where("pressure"))
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
        least = min(ps)
        if worst * k <= ABSURD["pressure"] and least * k < -ATMOSPHERE:
            raise self.error(
                f"a pressure of {least:g} {unit.strip()} is below a vacuum (gauge "
                f"pressures reach -{ATMOSPHERE / 1e5:g} bar at the least, absolute ones "
                "0); check the values and their unit",
                table,
                "pressure",
            )
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
        if getattr(self, "at_rest", False):  # the motion per rad/s: no inertia, no speed
            raise self.error(
                "the crank is at rest (its speed 0): a flywheel keeps a running engine's "
                "speed, its turning moment with the inertia of the parts at that speed; "
                'give the crank\'s speed in [input] (speed = "3000 rpm")',
                t,
            )
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
