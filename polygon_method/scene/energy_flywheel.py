"""The ``[flywheel]`` and ``[answers]`` tables of a turning-moment diagram's scene (a part of
:mod:`polygon_method.scene.energy`'s reader): the speed and its fluctuation (a coefficient,
a range either side of the mean, the greatest and least speeds, or the flywheel itself
given), the rim (its radius, or found from a rim speed or a hoop stress; its density, its
share of the flywheel's effect, its section), and the answers to check."""

from __future__ import annotations

import math
import re

from ..common.errors import SceneError
from ..common.units import TINY, did_you_mean, question, question_unit
from ..common.tolerances import LEAST_FLUCTUATION
from .energy_records import Rim
from .answers import FILE_KEYS
from .records import Answer

_POWER = {"W": 1.0, "kW": 1e3, "MW": 1e6, "hp": 745.69987158227}
_DENSITY = {"kg/m^3": 1.0, "kg/m³": 1.0, "kg/m3": 1.0, "g/cm^3": 1e3, "g/cm³": 1e3}
_NUM = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.*?)\s*$")
#: cast iron, the books' flywheel (kg/m^3), where the scene gives no density
DEFAULT_DENSITY = 7200.0
#: the least coefficient of fluctuation of speed a scene may ask for (as the engine's)
_LEAST = LEAST_FLUCTUATION


class _RimReader:
    """The reader's methods for [flywheel] and [answers] (mixed into the cycle reader)."""

    def _fraction(self, raw, t, key):
        if isinstance(raw, str) and raw.strip().endswith("%"):
            return self.ld.qty(raw, "percent", t, key).value
        if isinstance(raw, (int, float)) and not isinstance(raw, bool):
            return float(raw)
        raise self.err(f'{key} = {raw!r}: a number (0.02) or a percentage ("2%")', t, key)

    def _speed(self, spec, t, key):
        w = abs(self.ld.qty(spec[key], "angular_velocity", t, key).value)
        if not w > TINY["angular_velocity"]:
            raise self.err(f"{key}: the speed must not be nought", t, key)
        return w

    def _coefficient(self, spec, t, words):
        """(Cs or None, mean speed, the given inertia or None)."""
        ways = [
            k for k in ("coefficient", "plus_minus", "max_speed", "inertia", "mass") if k in spec
        ]
        if len(ways) != 1 or ("min_speed" in spec) != ("max_speed" in spec):
            raise self.err(
                "give the speed's fluctuation (coefficient = 0.02, the whole range over the "
                'mean; plus_minus = "1%"; or max_speed and min_speed), or the flywheel '
                "(inertia, or mass with gyration): one of them",
                t,
                ways[1] if len(ways) > 1 else "coefficient",
            )
        way = ways[0]
        if way == "max_speed":
            hi, lo = self._speed(spec, t, "max_speed"), self._speed(spec, t, "min_speed")
            if not hi > lo:
                raise self.err("max_speed must be greater than min_speed", t, "max_speed")
            if "speed" in spec:
                raise self.err("speed: not with max_speed and min_speed (their mean)", t, "speed")
            w = (hi + lo) / 2
            words.append(
                f"the mean speed ({_rpm(hi)} + {_rpm(lo)}) / 2 = {_rpm(w)}: Cs = "
                f"(w_max - w_min) / w_mean = {(hi - lo) / w:.6g}"
            )
            return (hi - lo) / w, w, None
        rim_alone = way in ("coefficient", "plus_minus") and (
            "rim_speed" in spec or "stress" in spec
        )
        if "speed" not in spec and not rim_alone:
            raise self.err('give the mean speed: speed = "300 rpm"', t, "speed")
        w = None
        if "speed" in spec:
            w = self._speed(spec, t, "speed")
            words.append(f"the mean speed {_rpm(w)} = {w:.6g} rad/s")
        else:  # the books' "the mean speed of the flywheel is 25 m/s": the rim's alone
            words.append(
                "the shaft's mean speed not given: the rim's speed v stands for it, m = dE_max "
                "/ (v^2 Cs) (I = m R^2, w = v / R: R cancels; I and R need the shaft's speed)"
            )
        if way in ("coefficient", "plus_minus"):
            c = self._fraction(spec[way], t, way)
            if not 0 < c < 1:
                raise self.err(f"{way}: between 0 and 1 (a fraction of the mean speed)", t, way)
            if c < _LEAST:
                raise self.err(
                    f"{way}: no flywheel keeps the speed that steady (at least {_LEAST:g})", t, way
                )
            if way == "plus_minus":
                words.append(f"the speed within +-{c:.6g} of the mean: Cs = 2 x {c:.6g}")
                c *= 2
            else:
                words.append(f"Cs = {c:.6g}, the whole range over the mean")
            return c, w, None
        if way == "inertia":
            i = self.ld.qty(spec["inertia"], "moment_of_inertia", t, "inertia").value
        else:
            m = self.ld.qty(spec["mass"], "mass", t, "mass").value
            k = "gyration" if "gyration" in spec else "radius" if "radius" in spec else None
            if k is None:
                raise self.err("the flywheel's mass needs its gyration (or radius)", t, "mass")
            r = self.ld.length(spec[k], t, k)
            i = m * r * r
            words.append(f"I = m k^2 = {m:.6g} x {r:.6g}^2")
        if not i > 0:
            raise self.err("the flywheel's inertia must be positive", t, way)
        words.append(f"the flywheel given: I = {i:.6g} kg m^2 (the speed's fluctuation found)")
        return None, w, i

    def flywheel(self, press) -> Rim:
        """[flywheel]: a :class:`Rim`."""
        t = "flywheel"
        spec = self.ld.table(t)
        for k in spec:
            if k not in _FLY_KEYS:
                raise self.err(f"unknown key '{k}'{did_you_mean(k, list(_FLY_KEYS))}", t, k)
        words = []
        c, w, inertia = self._coefficient(spec, t, words)
        ld = self.ld
        density = DEFAULT_DENSITY
        if "density" in spec:
            density = self._density(spec["density"], t)
            words.append(f"the rim's density {density:.6g} kg/m^3")
        radius, rim_speed, stress = self._radius(spec, t, w, density, words)
        gyr = (
            ld.length(spec["gyration"], t, "gyration")
            if "gyration" in spec and "mass" not in spec
            else None
        )
        share = 1.0
        if "rim_share" in spec:
            share = self._fraction(spec["rim_share"], t, "rim_share")
            if not 0 < share <= 1:
                raise self.err(
                    "rim_share: the rim's part of the flywheel's effect, 0 to 1", t, "rim_share"
                )
            words.append(f"the rim gives {share:.6g} of the flywheel's effect")
        ratio, width, thickness = self._section(spec, t, radius, words)
        if radius is not None and "density" not in spec and stress is None:
            words.append(f"the rim's density {density:g} kg/m^3 (cast iron, the default)")
        return Rim(
            c,
            w,
            inertia,
            radius,
            gyr,
            rim_speed,
            stress,
            density,
            share,
            ratio,
            width,
            thickness,
            tuple(words),
        )

    def _radius(self, spec, t, w, density, words) -> tuple:
        """(the rim's mean radius, its speed, the hoop stress), None where not given."""
        ld = self.ld
        sizes = [k for k in ("radius", "diameter", "rim_speed", "stress") if k in spec]
        if len(sizes) > 1:
            raise self.err(f"{sizes[1]}: the rim's radius is given once ({sizes[0]})", t, sizes[1])
        if "gyration" in spec and sizes and "mass" not in spec:
            raise self.err(
                "give the rim's radius or the radius of gyration, not both", t, "gyration"
            )
        radius = rim_speed = stress = None
        if sizes == ["radius"]:
            radius = ld.length(spec["radius"], t, "radius")
        elif sizes == ["diameter"]:
            radius = ld.length(spec["diameter"], t, "diameter") / 2
        elif sizes == ["rim_speed"]:
            rim_speed = abs(ld.qty(spec["rim_speed"], "velocity", t, "rim_speed").value)
            if not rim_speed > 0:
                raise self.err("rim_speed must be positive", t, "rim_speed")
            if w is not None:
                radius = rim_speed / w
                words.append(f"the rim's mean radius R = v / w = {radius:.6g} m")
        elif sizes == ["stress"]:
            stress = ld.qty(spec["stress"], "pressure", t, "stress").value
            if not stress > 0:
                raise self.err("stress must be positive", t, "stress")
            if "density" not in spec:
                words.append(f"the rim's density {density:g} kg/m^3 (cast iron, the default)")
            rim_speed = math.sqrt(stress / density)
            radius = None if w is None else rim_speed / w
            words.append(
                f"the hoop stress sigma = rho v^2: v = {rim_speed:.6g} m/s"
                + ("" if w is None else f", R = v / w = {radius:.6g} m")
            )
        return radius, rim_speed, stress

    def _section(self, spec, t, radius, words) -> tuple:
        """(width / thickness, the width, the thickness) the rim's section is set by."""
        ld = self.ld
        ratio = width = thickness = None
        sec = [k for k in ("width_to_thickness", "width", "thickness") if k in spec]
        if len(sec) > 1:
            raise self.err(
                f"{sec[1]}: the rim's section is set by one of width_to_thickness, "
                "width and thickness",
                t,
                sec[1],
            )
        if sec and radius is None:
            raise self.err(
                f"{sec[0]}: the rim's section needs its radius (radius, diameter, "
                "rim_speed or stress)",
                t,
                sec[0],
            )
        if sec == ["width_to_thickness"]:
            ratio = self._fraction(spec["width_to_thickness"], t, "width_to_thickness")
            if not ratio > 0:
                raise self.err("width_to_thickness must be positive", t, "width_to_thickness")
        elif sec == ["width"]:
            width = ld.length(spec["width"], t, "width")
        elif sec == ["thickness"]:
            thickness = ld.length(spec["thickness"], t, "thickness")
        return ratio, width, thickness

    def _density(self, raw, t):
        m = _NUM.match(raw) if isinstance(raw, str) else None
        if isinstance(raw, (int, float)) and not isinstance(raw, bool):
            v, f = float(raw), 1.0
        elif m and m.group(2) in _DENSITY:
            v, f = float(m.group(1)), _DENSITY[m.group(2)]
        else:
            raise self.err(
                f'density = {raw!r}: "7200 kg/m^3" (or a number in kg/m^3)', t, "density"
            )
        if not 100 <= v * f <= 30000:
            raise self.err(f"density = {raw!r}: not a metal's (100 to 30,000 kg/m^3)", t, "density")
        return v * f

    # -- [answers]
    def answers(self):
        t = "answers"
        spec = self.ld.table(t) if "answers" in self.raw else {}
        tolerance, out = None, []
        for key, value in spec.items():
            if key == "tolerance":
                q = self.ld.qty(value, "percent", t, key, default_unit="%").value
                if not 0 < q < 1:
                    raise self.err(f"tolerance {value!r} must be between 0 and 100 %", t, key)
                tolerance = q
                continue
            if isinstance(value, dict):  # [answers.extra]: at its line, as a mechanism's
                raise self.ld._sub_table(key, value)
            if key in FILE_KEYS:  # student inside [answers]: where it belongs
                self.ld.answer_file = "turning_moment" not in self.raw and "press" not in self.raw
                raise self.ld._misplaced(key)
            out.append(self.answer(key, value))
        return tolerance, out

    def answer(self, key, value):
        t = "answers"
        if key not in CYCLE_ANSWERS:
            raise self.err(
                f"unknown answer key{did_you_mean(key, list(CYCLE_ANSWERS))}; a turning-moment "
                "diagram's answers are " + ", ".join(CYCLE_ANSWERS),
                t,
                key,
            )
        kind = CYCLE_ANSWERS[key]
        unit = question(value)
        if unit is not None:  # a question without its answer ("?", "? kW")
            return self._question(key, kind, unit)
        raw = value.replace(",", ".") if isinstance(value, str) and "." not in value else value
        if kind == "power":
            m = _NUM.match(raw) if isinstance(raw, str) else None
            if not m or m.group(2) not in _POWER:
                raise self.err(f'{key} = {value!r}: a power, "5.5 kW" (W, kW, MW, hp)', t, key)
            v = float(m.group(1)) * _POWER[m.group(2)]
        elif kind == "percent":
            v = self._fraction(raw, t, key)
        else:
            v = self.ld.qty(raw, kind, t, key, refuse_absurd=False).value
        if not math.isfinite(v):
            raise self.err(f"{key} = {value!r}: not a finite number", t, key)
        return Answer(key, key, (), v, None, str(value), self.ld.line_of(t, key))

    def _question(self, key, kind, unit):
        """``dE_max = "?"`` (or ``"? kJ"``: the unit its answer is to be given in): an
        :class:`Answer` whose value is None (``asked``), the unit one of the key's kind."""
        t = "answers"
        if unit:
            if kind == "power" and unit not in _POWER:
                raise self.err(f'{key} = "? {unit}": a power\'s unit: W, kW, MW or hp', t, key)
            if kind == "percent" and unit != "%":
                raise self.err(f'{key} = "? {unit}": a fraction, "?" or "? %"', t, key)
            if kind not in ("power", "percent"):
                try:
                    question_unit(unit, kind, "")
                except SceneError as exc:
                    raise self.err(exc.message, t, key) from None
        raw = f"? {unit}".rstrip()
        return Answer(key, key, (), None, None, raw, self.ld.line_of(t, key), unit or None)


def _rpm(w):
    return f"{w * 30 / math.pi:.6g} rpm"


_FLY_KEYS = (
    "coefficient",
    "plus_minus",
    "speed",
    "max_speed",
    "min_speed",
    "inertia",
    "mass",
    "radius",
    "diameter",
    "gyration",
    "rim_speed",
    "stress",
    "density",
    "rim_share",
    "width_to_thickness",
    "width",
    "thickness",
)
#: answer key -> unit kind (checked in check/energy.py)
CYCLE_ANSWERS = {
    "T_mean": "torque",
    "power": "power",
    "dE_max": "energy",
    "E_stroke": "energy",
    "I_flywheel": "moment_of_inertia",
    "m_flywheel": "mass",
    "Cs": "percent",
    "Ce": "percent",
    "speed_max": "angular_velocity",
    "speed_min": "angular_velocity",
    "alpha_at": "angular_acceleration",
    "rim_radius": "length",
    "rim_width": "length",
    "rim_thickness": "length",
}
