"""The unit tables: each kind's spellings and their factors to SI, the sizes that make sense
for a mechanism, and the unit an answer of each kind is written in (read by
:mod:`.units`, which re-exports them).

>>> UNITS["length"]["mm"], ANSWER_UNITS["omega"]
(0.001, 'rad/s')
"""

from __future__ import annotations

import math

_PI = math.pi

#: unit spellings by kind: factor to SI
UNITS: dict[str, dict[str, float]] = {
    "length": {
        "mm": 1e-3,
        "cm": 1e-2,
        "m": 1.0,
        "in": 0.0254,
        "inch": 0.0254,
        "inches": 0.0254,
        "ft": 0.3048,
        "feet": 0.3048,
        "foot": 0.3048,
    },
    "angle": {
        "deg": _PI / 180,
        "°": _PI / 180,
        "degree": _PI / 180,
        "degrees": _PI / 180,
        "rad": 1.0,
    },
    "angular_velocity": {
        "rad/s": 1.0,
        "rpm": 2 * _PI / 60,
        "r.p.m.": 2 * _PI / 60,
        "r.p.m": 2 * _PI / 60,
        "rev/min": 2 * _PI / 60,
        "rps": 2 * _PI,
        "r.p.s.": 2 * _PI,
        "r.p.s": 2 * _PI,
        "rev/s": 2 * _PI,
        "deg/s": _PI / 180,
        "rad/sec": 1.0,
        "rev/sec": 2 * _PI,
        "deg/sec": _PI / 180,
    },
    "angular_acceleration": {
        "rad/s^2": 1.0,
        "rad/s²": 1.0,
        "rad/s2": 1.0,
        "rad/s/s": 1.0,
        "rad/sec^2": 1.0,
        "rad/sec²": 1.0,
        "rad/sec2": 1.0,
    },
    "force": {"N": 1.0, "kN": 1e3, "MN": 1e6, "lbf": 4.4482216152605, "kgf": 9.80665},
    "power": {"W": 1.0, "kW": 1e3, "MW": 1e6, "hp": 745.69987158227},
    "velocity": {
        "m/s": 1.0,
        "mm/s": 1e-3,
        "cm/s": 1e-2,
        "km/h": 1 / 3.6,
        "in/s": 0.0254,
        "ft/s": 0.3048,
        "m/sec": 1.0,
        "mm/sec": 1e-3,
        "cm/sec": 1e-2,
        "in/sec": 0.0254,
        "ft/sec": 0.3048,
        "km/hr": 1 / 3.6,
    },
    "acceleration": {
        "m/s^2": 1.0,
        "m/s²": 1.0,
        "m/s2": 1.0,
        "mm/s^2": 1e-3,
        "mm/s²": 1e-3,
        "mm/s2": 1e-3,
        "cm/s^2": 1e-2,
        "cm/s²": 1e-2,
        "cm/s2": 1e-2,
        "in/s^2": 0.0254,
        "in/s²": 0.0254,
        "ft/s^2": 0.3048,
        "ft/s²": 0.3048,
        "in/s2": 0.0254,
        "ft/s2": 0.3048,
        "m/sec^2": 1.0,
        "m/sec²": 1.0,
        "m/sec2": 1.0,
        "mm/sec^2": 1e-3,
        "cm/sec^2": 1e-2,
        "in/sec^2": 0.0254,
        "ft/sec^2": 0.3048,
        "ft/sec²": 0.3048,
    },
    "torque": {
        "N m": 1.0,
        "N·m": 1.0,
        "Nm": 1.0,
        "N.m": 1.0,
        "N-m": 1.0,
        "kN m": 1e3,
        "kN·m": 1e3,
        "kNm": 1e3,
        "kN.m": 1e3,
        "N mm": 1e-3,
        "N cm": 1e-2,
        "Nmm": 1e-3,
        "N·mm": 1e-3,
        "lbf in": 4.4482216152605 * 0.0254,
        "lbf ft": 4.4482216152605 * 0.3048,
    },
    "percent": {"%": 0.01},
    # the force chapter: a link's mass, its moment of inertia, a gas pressure
    "mass": {"kg": 1.0, "g": 1e-3, "t": 1e3, "lb": 0.45359237},
    "moment_of_inertia": {
        "kg m^2": 1.0,
        "kg m²": 1.0,
        "kg·m^2": 1.0,
        "kg·m²": 1.0,
        "kg m2": 1.0,
        "kg mm^2": 1e-6,
        "kg mm²": 1e-6,
        "kg cm^2": 1e-4,
        "kg cm²": 1e-4,
        "g mm^2": 1e-9,
        "g cm^2": 1e-7,
        "lb ft^2": 0.45359237 * 0.3048**2,
        "lb in^2": 0.45359237 * 0.0254**2,
    },
    "energy": {
        "J": 1.0,
        "kJ": 1e3,
        "MJ": 1e6,
        "N m": 1.0,
        "N·m": 1.0,
        "kN m": 1e3,
        "kN·m": 1e3,
        "MN m": 1e6,
        "MN·m": 1e6,
    },
    "pressure": {
        "Pa": 1.0,
        "N/m^2": 1.0,
        "N/m²": 1.0,
        "kPa": 1e3,
        "kN/m^2": 1e3,
        "kN/m²": 1e3,
        "MPa": 1e6,
        "N/mm^2": 1e6,
        "N/mm²": 1e6,
        "bar": 1e5,
        "psi": 4.4482216152605 / 0.0254**2,
        "kgf/cm^2": 9.80665e4,
        "kgf/cm²": 9.80665e4,
    },
    # a damper's coefficient: its force per unit rate of extension
    "damping": {
        "N s/m": 1.0,
        "N·s/m": 1.0,
        "Ns/m": 1.0,
        "N/(m/s)": 1.0,
        "kN s/m": 1e3,
        "kN·s/m": 1e3,
        "N s/mm": 1e3,
        "N·s/mm": 1e3,
        "lbf s/in": 4.4482216152605 / 0.0254,
        "lbf s/ft": 4.4482216152605 / 0.3048,
    },
    # a spring's stiffness: its force per unit change of length
    "stiffness": {
        "N/m": 1.0,
        "N/mm": 1e3,
        "N/cm": 1e2,
        "kN/m": 1e3,
        "kN/mm": 1e6,
        "MN/m": 1e6,
        "lbf/in": 4.4482216152605 / 0.0254,
        "lbf/ft": 4.4482216152605 / 0.3048,
    },
}

#: the largest magnitude (SI) that makes sense for a mechanism, by kind: beyond it a value
#: is a units slip, and the squares and products of the solution would overflow
ABSURD: dict[str, float] = {
    "angle": 1e6,  # rad
    "angular_velocity": 1e6,  # rad/s (nearly 10 million rpm)
    "angular_acceleration": 1e9,  # rad/s^2
    "force": 1e9,  # N
    "torque": 1e9,  # N m
    "velocity": 1e6,  # m/s
    "acceleration": 1e12,  # m/s^2
    "mass": 1e7,  # kg
    "moment_of_inertia": 1e7,  # kg m^2
    "pressure": 1e10,  # Pa
    "damping": 1e9,  # N s/m
    "stiffness": 1e12,  # N/m (a steel bar's, a million times over)
}

#: the smallest magnitude (SI) other than zero that makes sense, by kind: below it a value
#: is a units slip, and products such as F v underflow to zero
TINY: dict[str, float] = {
    "angular_velocity": 1e-9,  # rad/s (one turn in 200 years)
    "force": 1e-9,  # N
    "torque": 1e-12,  # N m
}
#: a stiffness below the smallest force per millimetre (a nanonewton per mm) is a slip
TINY["stiffness"] = TINY["force"] / UNITS["length"]["mm"]
#: and so are a damping below a nanonewton per mm/s and a pressure below a nanonewton per
#: square millimetre (1 mPa, a hundred-millionth of the atmosphere: no gauge reads it, and a
#: value far below it, 1e-300 Pa, makes forces and powers of subnormal junk)
TINY["damping"] = TINY["force"] / UNITS["length"]["mm"]
TINY["pressure"] = TINY["force"] / UNITS["length"]["mm"] ** 2
#: a mass below the one a nanonewton accelerates at 1 m/s^2 (a microgram) and a moment of
#: inertia below that mass at a millimetre are slips too: far below any link's or block's
#: (1e-300 kg, lighter than an electron, makes inertia forces of subnormal junk beside the
#: mechanism's other sizes); a signed length (a coordinate, an offset along a link) is not
#: bounded below: added to the mechanism's sizes it changes nothing past their rounding
TINY["mass"] = TINY["force"] / UNITS["acceleration"]["m/s^2"]
TINY["moment_of_inertia"] = TINY["mass"] * UNITS["length"]["mm"] ** 2

#: an answer's kind (the prefix of its key: ``v_C``, ``omega_BC``, ``F_B``, ``torque``) -> the SI
#: unit its value is written in: the answer keys, the verdicts and the variants' papers
ANSWER_UNITS = {
    "v": "m/s",
    "a": "m/s^2",
    "omega": "rad/s",
    "alpha": "rad/s^2",
    "vs": "m/s",
    "as": "m/s^2",
    "ac": "m/s^2",
    "rub": "m/s",
    "torque": "N m",
    "vI": "m/s",
    "aI": "m/s^2",
    "F": "N",
    "N": "N",
    "Fc": "N",
    "Tmax": "N m",
    "Pmax": "W",
    "vu": "m/s",
    "au": "m/s^2",
    "Fi": "N",
    "Ci": "N m",
    "Thold": "N m",
    "h": "m",
    "force": "N",
    "force2": "N",
    "torque2": "N m",
    "vmin": "m/s",
    "ar": "m/s^2",
    "at": "m/s^2",
}

#: the lengths a scene may be written in (``units = ...``)
LENGTH_UNITS = {"mm", "cm", "m", "in", "ft"}

#: the SI unit each kind is given in, as words write it
SI_NAME = {
    "angle": "rad",
    "angular_velocity": "rad/s",
    "angular_acceleration": "rad/s^2",
    "force": "N",
    "torque": "N m",
    "velocity": "m/s",
    "acceleration": "m/s^2",
    "mass": "kg",
    "moment_of_inertia": "kg m^2",
    "pressure": "Pa",
    "energy": "J",
    "damping": "N s/m",
    "stiffness": "N/m",
}
