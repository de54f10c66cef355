"""The ``[press]`` table of a turning-moment diagram's scene (a part of
:mod:`polygon_method.scene.energy`'s reader): a punching or riveting press, the energy of one
hole (given, or from the greatest force and the plate's thickness, or from the hole's size and
the plate's ultimate shear strength), the holes a minute and how long the punching takes."""

from __future__ import annotations

import math
import re

from .energy_records import Press
from ..common.units import UNITS

_PRESS_KEYS = (
    "energy",
    "force",
    "thickness",
    "diameter",
    "shear_strength",
    "energy_per_area",
    "holes_per_minute",
    "time",
    "punching_time",
    "punching_angle",
    "punching_fraction",
    "stroke",
    "losses",
)


_PER_AREA = re.compile(
    r"^\s*((?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(J|N m|N-m|Nm)\s*/\s*(mm\^2|mm2|mm²|cm\^2|cm2|cm²|m\^2|m2|m²)\s*$"
)
#: an area's unit factors (m^2), from the length's
_MM2, _CM2 = UNITS["length"]["mm"] ** 2, UNITS["length"]["cm"] ** 2
_AREA = {
    "mm^2": _MM2,
    "mm2": _MM2,
    "mm²": _MM2,
    "cm^2": _CM2,
    "cm2": _CM2,
    "cm²": _CM2,
    "m^2": 1.0,
    "m2": 1.0,
    "m²": 1.0,
}


class _PressReader:
    """The reader's methods for [press] (mixed into the cycle reader)."""

    def press(self) -> Press:
        """[press]: a :class:`Press`."""
        t = "press"
        spec = self.ld.table(t)
        self._keys(spec, t, _PRESS_KEYS)
        words = []
        energy = self._hole(spec, t, words)
        if not energy > 0:
            raise self.err("the energy of one hole must be positive", t, "energy")
        if "losses" in spec:  # "the frictional losses are 1/6 of the work of punching"
            f = self._losses(spec["losses"], t)
            energy *= 1.0 + f
            words.append(
                f"with the losses, {f:.6g} of it: E = {1 + f:.6g} x the punching's work = "
                f"{energy:.6g} J a hole (the motor supplies it all)"
            )
        period, f = self._timing(spec, t, words)
        return Press(energy, period, float(f), tuple(words))

    def _losses(self, raw, t) -> float:
        """The losses as a part of the punching's work: "1/6", "20%" or 0.2."""
        m = re.match(r"^\s*(\d+)\s*/\s*(\d+)\s*$", raw) if isinstance(raw, str) else None
        if m and int(m.group(2)) > 0:
            f = int(m.group(1)) / int(m.group(2))
        elif isinstance(raw, str) and raw.strip().endswith("%"):
            f = self.ld.qty(raw, "percent", t, "losses").value
        elif isinstance(raw, (int, float)) and not isinstance(raw, bool):
            f = float(raw)
        else:
            f = math.nan
        if not 0 <= f < 10:
            raise self.err(
                f'losses = {raw!r}: a part of the punching\'s work, "1/6", "20%" or 0.2 '
                "(from 0 to below 1000%)",
                t,
                "losses",
            )
        return f

    def _hole(self, spec, t, words) -> float:
        """The energy of one hole (J): given, or half the greatest force times the
        plate's thickness."""
        if "energy" in spec:
            for k in ("force", "diameter", "shear_strength"):
                if k in spec:
                    raise self.err(f"{k}: not with energy (the energy of one hole is given)", t, k)
            energy = self.ld.qty(spec["energy"], "energy", t, "energy").value
            words.append(f"the energy of one hole {energy:.6g} J")
        else:
            if "thickness" not in spec:
                raise self.err(
                    'give the energy of one hole (energy = "6 kJ"), or the greatest force '
                    "and the plate's thickness (force, thickness), or the hole's diameter, "
                    "the thickness and the plate's ultimate shear strength",
                    t,
                    "energy",
                )
            th = self.ld.length(spec["thickness"], t, "thickness")
            if "energy_per_area" in spec:
                return self._sheared(spec, t, th, words)
            if "force" in spec:
                for k in ("diameter", "shear_strength"):
                    if k in spec:
                        raise self.err(f"{k}: not with force (the force is given)", t, k)
                force = self.ld.qty(spec["force"], "force", t, "force").value
            else:
                if "diameter" not in spec or "shear_strength" not in spec:
                    raise self.err(
                        "the greatest force: give force, or the hole's diameter and the "
                        "plate's ultimate shear strength (shear_strength)",
                        t,
                        "force",
                    )
                d = self.ld.length(spec["diameter"], t, "diameter")
                tau = self.ld.qty(spec["shear_strength"], "pressure", t, "shear_strength").value
                force = tau * math.pi * d * th
                words.append(f"the greatest force F = tau pi d t = {force:.6g} N")
            if not force > 0:
                raise self.err("the force must be positive", t, "force")
            energy = 0.5 * force * th
            words.append(
                f"the energy of one hole E = F t / 2 = {energy:.6g} J (the force falling "
                "evenly from its greatest to nought through the plate: the book's triangle)"
            )
        return energy

    def _sheared(self, spec, t, th, words) -> float:
        """The energy of one hole from the energy per mm^2 of sheared area (pi d t)."""
        for k in ("force", "shear_strength"):
            if k in spec:
                raise self.err(f"{k}: not with energy_per_area", t, k)
        if "diameter" not in spec:
            raise self.err("energy_per_area needs the hole's diameter", t, "diameter")
        d = self.ld.length(spec["diameter"], t, "diameter")
        raw = spec["energy_per_area"]
        m = _PER_AREA.match(raw) if isinstance(raw, str) else None
        if m is None or not float(m.group(1)) > 0:
            raise self.err(
                f'energy_per_area = {raw!r}: "6 J/mm^2" (J or N m per mm^2, cm^2 or m^2)',
                t,
                "energy_per_area",
            )
        e = float(m.group(1)) / _AREA[m.group(3)]
        energy = e * math.pi * d * th
        words.append(f"the energy of one hole E = e pi d t = {energy:.6g} J (the sheared area)")
        return energy

    def _timing(self, spec, t, words) -> tuple:
        """(the cycle's time, s; the part of it the punching takes)."""
        if ("holes_per_minute" in spec) == ("time" in spec):
            raise self.err(
                'give the rate, holes_per_minute = 6, or the time of one cycle, time = "10 s": '
                "one of them",
                t,
                "holes_per_minute",
            )
        if "time" in spec:
            period = self._seconds(spec["time"], t, "time")
        else:
            n = spec["holes_per_minute"]
            if isinstance(n, bool) or not isinstance(n, (int, float)) or not 0 < n < 1e6:
                raise self.err("holes_per_minute = a positive number", t, "holes_per_minute")
            period = 60.0 / n
        words.append(f"one cycle {period:.6g} s")
        keys = ("punching_time", "punching_angle", "punching_fraction", "stroke")
        given = [k for k in keys if k in spec]
        if len(given) != 1:
            raise self.err(
                "how long the punching takes: punching_time (s), punching_angle (of the "
                "crank's turn), punching_fraction (of the cycle) or the punch's stroke (with "
                "the plate's thickness): one of them",
                t,
                given[1] if given else "punching_time",
            )
        key = given[0]
        if key == "stroke":  # the books' t / (2 s): down its stroke in half a turn
            if "thickness" not in spec:
                raise self.err("the punch's stroke needs the plate's thickness", t, key)
            th = self.ld.length(spec["thickness"], t, "thickness")
            stroke = self.ld.length(spec[key], t, key)
            f = th / (2.0 * stroke)
            words.append(
                f"the punching t / (2 s) = {th * 1e3:.6g} mm / (2 x {stroke * 1e3:.6g} mm) "
                "of the cycle (the "
                "punch goes down its stroke in half a turn, through the plate's thickness "
                "of it at a uniform rate: the books' assumption)"
            )
        elif key == "punching_time":
            f = self._seconds(spec[key], t, key) / period
        elif key == "punching_angle":
            f = self.ld.qty(spec[key], "angle", t, key, default_unit="deg").value / (2 * math.pi)
        else:
            f = spec[key]
            if isinstance(f, str) and "/" in f:
                a, _, b = f.partition("/")
                try:
                    f = float(a) / float(b)
                except (ValueError, ZeroDivisionError):
                    raise self.err(f'{key} = {spec[key]!r}: a fraction, 0.1 or "1/10"', t, key)
            if isinstance(f, bool) or not isinstance(f, (int, float)):
                raise self.err(f'{key} = {spec[key]!r}: a fraction, 0.1 or "1/10"', t, key)
        if not 0 < f < 1:
            raise self.err(
                f"{key}: the punching takes part of the cycle (0 to 1), not {f:g}", t, key
            )
        words.append(f"the punching {f:.6g} of the cycle")
        return period, f

    def _seconds(self, raw, t, key) -> float:
        m = re.match(r"^\s*([0-9.eE+-]+)\s*(s|sec|seconds?|min|minutes?)?\s*$", str(raw))
        try:
            v = float(m.group(1)) if m else math.nan
        except ValueError:
            v = math.nan
        if isinstance(raw, bool) or not (v > 0 and math.isfinite(v)):
            raise self.err(f'{key} = {raw!r}: a time, "10 s" or 10 (seconds)', t, key)
        return v * (60.0 if m.group(2) and m.group(2).startswith("min") else 1.0)
