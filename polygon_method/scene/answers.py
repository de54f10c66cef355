"""The ``[answers]`` table (and a student's answer file, read the same way): each key
named as a book names the quantity (``v_C``, ``omega_BC``, ``a_C``, ``R_B``, ``torque``,
``I13``, the engine's and the forces' keys), its value and unit checked, its sense read;
an unknown key gets a "did you mean" hint. A decimal comma is read as a point."""

from __future__ import annotations

import math
import re

from ..common.errors import printable
from ..common.units import UNITS, decimal_comma, question
from .records import ANSWER_KINDS, UNDER_BLOCK_KINDS, Answer, split_name
from .cycle_answers import CYCLE_ANSWERS, _CycleAnswers, bare as _bare
from .questions import _Questions, unit_kind
from .table_help import _suggest, _which_point

__all__ = [
    "decimal_comma",
    "DRIVER_ANSWERS",
    "ENGINE_ANSWERS",
    "ENGINE_PER_PISTON",
    "under_block_names",
    "CYCLE_ANSWERS",
    "unit_kind",
]

#: a centre answered as at infinity, optionally with the direction of its lines
_INFINITY = re.compile(r"^\s*(?:at\s+)?infinity\s*(?:[,;]\s*(?:along\s+)?(.*?))?\s*$", re.I)

#: the engine chapter's answer keys -> their unit kind (checked in check/engine.py)
ENGINE_ANSWERS = {
    "piston_effort": "force",
    "crank_effort": "force",
    "turning_moment": "torque",
    "T_mean": "torque",
    "dE_max": "energy",
    "I_flywheel": "moment_of_inertia",
    "m_flywheel": "mass",
    "rod_thrust": "force",
    "side_thrust": "force",
    "shaking_force": "force",
    "shaking_moment": "torque",
}


#: the keys each cylinder of several on one crank has, its piston after them
#: (``piston_effort_B``, as the sweep's columns name them)
ENGINE_PER_PISTON = ("piston_effort", "crank_effort", "turning_moment", "rod_thrust", "side_thrust")


def under_block_names(point_names, ground, sliders) -> dict:
    """Answer name -> slider key, for the point of a moving guide that lies under a block:
    ``A1`` for the block at A (its image is a1 on the velocity polygon, a1' on the
    acceleration polygon), ``A2`` where the scene has a point A1 of its own; for a peg in
    two moving slots, ``P1`` and ``P2`` in the order of its slots (a fixed slot has none:
    its point is the pole). The names follow the polygons' letters.

    >>> from types import SimpleNamespace as S
    >>> under_block_names(["O2", "A", "O4", "P"], {"O2": 0, "O4": 0},
    ...                   [S(point="A", key="A", guide="O4-P")])
    {'A1': 'A'}
    """
    lower = {p.lower() for p in point_names}
    taken = set(lower)
    if "O" in point_names and "O" not in ground:  # a moving O's image is o1 (or o2 ...)
        k = 1
        while f"o{k}" in lower:
            k += 1
        taken.add(f"o{k}")
    out, used = {}, set()
    for s in sliders:
        if not getattr(s, "guide", None):
            continue
        k = 1
        while f"{s.point.lower()}{k}" in taken | used:
            k += 1
        used.add(f"{s.point.lower()}{k}")
        out[f"{s.point}{k}"] = s.key
    return out


#: the answer kinds of two points of one link, as ``ANSWER_KINDS``: the least speed of a
#: point between them (``vmin_BC``), the radial and tangential components of one's
#: acceleration relative to the other (``ar_CB``, ``at_CB``; ``motion/link_points.py``)
PAIR_ANSWER_KINDS = {
    "vmin": ("velocity", "pair", False),
    "ar": ("acceleration", "pair", False),
    "at": ("acceleration", "pair", False),
}
_KINDS = {**ANSWER_KINDS, **PAIR_ANSWER_KINDS}

#: the drivers' efforts other than the crank's torque: a driving block's, collar's or
#: cylinder's force along its guide (``force``), a second input's torque or force
DRIVER_ANSWERS = {"force": "force", "torque2": "torque", "force2": "force"}


class _Answers(_Questions, _CycleAnswers):
    """The loader's ``[answers]`` methods (mixed into the loader with the other tables)."""

    def _engine_value(self, value, kind, key) -> float:
        """An engine answer's value (SI) of ``kind``, in its kind's first unit when bare: an
        effort, a turning moment, the cycle's energy or the flywheel's (one cylinder's, or
        one piston's of several)."""
        return self.qty(
            value,
            kind,
            "answers",
            key,
            default_unit=next(iter(UNITS[kind])),
            allow_sense=False,
            refuse_absurd=False,
        ).value

    def driver_answer(self, key, value, raw_text, line, loads, forces):
        """``force`` (a driving block's, collar's or cylinder's force along its guide, N:
        a size, or signed along the guide, + outward for a collar), ``torque2`` and
        ``force2`` (a second input's effort: a second crank's torque, a second collar's
        force; the force analysis gives them)."""
        if key == "force" and not (loads or forces):
            raise self.error(
                "a driver's force answer needs [loads] to balance, or [masses]", "answers", key
            )
        if key != "force" and not forces:
            raise self.error(
                f"{key}: a second input's effort needs the force analysis (the power "
                "balance gives only the two efforts' weighted sum): give [masses] (empty "
                "for the loads alone) or [gravity]",
                "answers",
                key,
            )
        q = self.qty(
            value,
            DRIVER_ANSWERS[key],
            "answers",
            key,
            default_unit=next(iter(UNITS[DRIVER_ANSWERS[key]])),
            allow_sense=key == "torque2",
            refuse_absurd=False,
        )
        sense = q.sense or ("+" if str(value).lstrip().startswith("+") else None)
        return Answer(key, key, (), q.value, sense, raw_text, line)  # (+: signed, as -)

    def answers(self, known, sliders, pins, loads):
        spec = self.table("answers")
        tolerance = None
        out = []
        slider_names = {s.key: s for s in sliders}
        pin_names = {p.point for p in pins}
        for key, value in spec.items():
            if key == "tolerance":
                if question(value) is not None:
                    raise self.error(
                        'tolerance is the answers\' allowance, a per cent ("3%"): not a question',
                        "answers",
                        key,
                    )
                q = self.qty(value, "percent", "answers", key, default_unit="%").value
                if not 0 < q < 1:
                    raise self.error(
                        f"tolerance {value!r} must be between 0 and 100 %", "answers", key
                    )
                tolerance = q
                continue
            out.append(self.answer(key, value, known, slider_names, pin_names, loads))
        return tolerance, out

    def centre_answer(self, key, rest, value, line):
        """``I_13 = [x, y]``: the instantaneous centre of links 1 and 3 (textbook numbers:
        ground 1, crank 2), in the scene's units; ``I_1_12`` past link 9."""
        parts = rest.split("_") if "_" in rest else list(rest)
        named = len(parts) == 2 and not any(p.isdigit() for p in parts)
        if named:  # the scene's names: I_ground_BC, I_AB_CD
            for part in parts:
                if part.lower() != "ground":
                    self.find_link(part, "answers", key)
        elif (
            len(parts) != 2
            or not all(p.isdigit() and int(p) > 0 for p in parts)
            or int(parts[0]) == int(parts[1])
        ):
            raise self.error(
                "an instantaneous centre is I_ij with two different link "
                "numbers (ground 1, crank 2), e.g. I_13, or I_1_12 past 9, or "
                "two link names, e.g. I_ground_BC",
                "answers",
                key,
            )
        pair = tuple(parts) if named else tuple(sorted(int(p) for p in parts))
        if isinstance(value, str):  # "at infinity", or with the direction of its lines
            return Answer(
                key, "centre", pair, self.centre_at_infinity(key, value), None, value, line
            )
        if not (
            isinstance(value, list)
            and len(value) == 2
            and all(
                isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
                for v in value
            )
        ):
            raise self.error(
                f"a centre's answer is its position [x, y] in {self.unit}, or \"at "
                f'infinity" ("at infinity, 90 deg": the direction of its lines), got {value!r}',
                "answers",
                key,
            )
        for v in value:  # [1e300, 0]: a units slip, never an error of 1e299 per cent
            self.length(v, "answers", key, positive=False)
        u = self.scale()
        return Answer(
            key,
            "centre",
            pair,
            (value[0] * u, value[1] * u),
            None,
            f"[{value[0]:g}, {value[1]:g}] {self.unit}",
            line,
        )

    def centre_at_infinity(self, key, value) -> tuple:
        """``("infinity", direction)`` of a centre answered as at infinity: ``"at infinity"``
        (the direction not stated: None) or ``"at infinity, 90 deg"``, ``"..., vertical"``
        (the direction of the parallel lines it is the meeting point of, rad, mod pi)."""
        m = _INFINITY.match(value)
        if m is None:
            raise self.error(
                f'{value!r}: a centre is [x, y] in {self.unit}, or "at infinity" (with the '
                'direction of its lines: "at infinity, 90 deg", "at infinity, vertical")',
                "answers",
                key,
            )
        d = (m.group(1) or "").strip().lower()
        if not d:
            return ("infinity", None)
        if d in ("horizontal", "vertical"):
            return ("infinity", 0.0 if d == "horizontal" else math.pi / 2)
        q = self.qty(d, "angle", "answers", key, default_unit="deg")
        return ("infinity", q.value % math.pi)

    def answer_keys(self, known, slider_names, pin_names, loads) -> list:
        """Every answer key this scene can check (for a did-you-mean)."""
        moving = [p for p in sorted(known) if p not in getattr(self, "ground", {})]
        keys = [f"{k}_{p}" for k in ("v", "a") for p in moving]
        for lk in self.index.values():
            keys += [
                f"omega_{lk.key}",
                f"alpha_{lk.key}",
                f"v_{lk.p}{lk.q}",
                f"v_{lk.q}{lk.p}",
                f"a_{lk.p}{lk.q}",
                f"a_{lk.q}{lk.p}",
            ]
            keys += [f"{k}_{lk.p}{lk.q}" for k in ("vmin", "ar", "at")]
        keys += [f"{k}_{s}" for k in ("vs", "as", "ac", "stroke") for s in slider_names]
        keys += [f"theta_{lk.p}{lk.q}" for lk in self.index.values()] + ["time_ratio"]
        keys += [f"rub_{p}" for p in sorted(pin_names)]
        keys += [f"{k}_{n}" for k in ("v", "a") for n in self.under_names(known, slider_names)]
        return keys + (["torque"] if loads else []) + list(DRIVER_ANSWERS) + list(ENGINE_ANSWERS)

    def under_names(self, known, slider_names) -> dict:
        """``A1`` -> the block at A's slider key: the guide's point under the block."""
        return under_block_names(sorted(known), getattr(self, "ground", {}), slider_names.values())

    def key_hint(self, key, known, slider_names, pin_names, loads) -> str:
        """`` (did you mean 'v_C'?)``: the key in another case (names are case-sensitive:
        ``v_c``, ``omega_bc``), or a key one or two typos away; else empty."""
        keys = self.answer_keys(known, slider_names, pin_names, loads)
        written = key
        head, _, rest = key.partition("_")
        if head.lower() in ("w", "\u03c9"):  # w_BC, \u03c9_BC: omega_BC
            key = f"omega_{rest}"
        folded = {k.lower(): k for k in keys}
        best = folded.get(key.lower())
        if best is None:
            for k in keys:  # omega_o2a for omega_O2-A
                if k.lower().replace("-", "") == key.lower().replace("-", ""):
                    best = k
                    break
        if best is None:
            from ..common.units import suggest

            best = suggest(key, keys)
        return f" (did you mean '{best}'?)" if best is not None and best != written else ""

    def _drive(self, key, prefix, rest, names):
        """``Tmax_L``, ``Pmax_L``: L a wheel of ``[rolling]`` whose grip states ``friction``
        (``Tmax``: or the gear it grips; ``Pmax``: not on a line, whose contact does not move)."""
        lk = self.index.get(frozenset(names)) if len(names) == 2 else None
        pairs = [r for r in getattr(self, "rolling_pairs", ()) or () if r.grip and r.grip[1]]
        if prefix == "Pmax":
            pairs = [r for r in pairs if r.on != "line"]
        if lk is None or not any(
            lk.key in (r.wheel, r.base if prefix == "Tmax" else None) for r in pairs
        ):
            raise self.error(
                f"{key}: {rest} is no wheel of a friction drive (a wheel of [rolling] with "
                "friction = mu"
                + (
                    ", not on a line: its contact does not move)"
                    if prefix == "Pmax"
                    else ", or the gear it grips)"
                ),
                "answers",
                key,
            )

    def answer(self, key, value, known, slider_names, pin_names, loads):
        """One key of [answers] (or of a student's file) and its value: an :class:`Answer`,
        the key checked against the scene (what it names is there, the force analysis
        asked for where it is a force) and the value read in the key's kind; or a question
        asked without its answer (``"?"``, ``"? rpm"``: :meth:`question`)."""
        unit = question(value)
        if unit is not None:
            return self.question(key, unit, known, slider_names, pin_names, loads)
        return self._answer(key, value, known, slider_names, pin_names, loads)

    def _answer(self, key, value, known, slider_names, pin_names, loads):
        """:meth:`answer` of a value (not a question)."""
        line = self.line_of("answers", key)
        forces = getattr(self, "scene_forces", None)  # an answer file: its scene's
        if forces is None:
            forces = "masses" in self.raw or "gravity" in self.raw or "indicator" in self.raw
            forces = forces or any(r.grip for r in getattr(self, "rolling_pairs", ()) or ())
        hint = lambda: self.key_hint(key, known, slider_names, pin_names, loads)  # noqa: E731
        read = decimal_comma(value)
        if read is None:
            raise self.error(
                f"'{printable(str(value))}': the comma reads two ways (a decimal "
                "comma, or thousands?): write the number with a decimal point, "
                'e.g. "1.25 m/s" or "1250 mm/s"',
                "answers",
                key,
            )
        raw_text, value = printable(str(value)), read
        if key == "torque":
            return self._torque_answer(key, value, raw_text, line, loads, forces)
        if key in DRIVER_ANSWERS:
            return self.driver_answer(key, value, raw_text, line, loads, forces)
        engine = self._engine_answer(key, value, raw_text, line, slider_names)
        if engine is not None:
            return engine
        cycle = self._cycle_answer(key, value, raw_text, line, known, slider_names, hint)
        if cycle is not None:
            return cycle
        prefix, _, rest = key.partition("_")
        if prefix == "I" and rest:
            return self.centre_answer(key, rest, value, line)
        if prefix not in _KINDS or not rest:
            raise self._unknown_key(key, hint)
        kind, what, sense_ok = _KINDS[prefix]
        if what in ("pin_force", "guide", "body", "contact", "drive", "held") and not forces:
            raise self.error(
                f"{key}: a force answer needs the force analysis: give [masses] or [gravity]",
                "answers",
                key,
            )
        if prefix in UNDER_BLOCK_KINDS and rest not in known:
            under = self.under_names(known, slider_names).get(rest)
            if under is not None:  # v_A1: the guide's point under the block at A
                q = self.qty(value, kind, "answers", key, default_unit=next(iter(UNITS[kind])))
                return Answer(
                    key, UNDER_BLOCK_KINDS[prefix], (under,), q.value, None, raw_text, line
                )
        names = (rest,) if what == "slider" and rest in slider_names else split_name(rest)
        if not names:
            raise self.error(f"'{rest}' is not a point or link name{hint()}", "answers", key)
        if what in ("pin_force", "guide", "body", "contact", "drive", "held"):
            names = self._force_names(key, prefix, rest, names, what, known, slider_names)
        else:
            names = self._motion_names(
                key, prefix, rest, names, what, known, slider_names, pin_names, hint
            )
        if prefix == "h":  # (a body's: the offset of its single inertia force)
            q = self.qty(
                value, "length", "answers", key, default_unit=self.unit, refuse_absurd=False
            )
            if _bare(value):  # a bare length is in the scene's unit: say so
                raw_text = f"{raw_text} {self.unit}"
            return Answer(key, prefix, names, q.value, None, raw_text, line)
        q = self.qty(
            value,
            kind,
            "answers",
            key,
            default_unit=next(iter(UNITS[kind])),
            allow_sense=sense_ok,
            refuse_absurd=False,
        )  # warned of when checked
        return Answer(key, prefix, names, q.value, q.sense, raw_text, line)

    def _engine_answer(self, key, value, raw_text, line, slider_names):
        """An engine chapter's answer (efforts, the cycle, the flywheel; ``piston_effort_B``
        one cylinder's of several), or None for a key of another kind."""
        if key in ENGINE_ANSWERS:  # the engine chapter's: efforts, the cycle, the flywheel
            value = self._engine_value(value, ENGINE_ANSWERS[key], key)
            return Answer(key, key, (), value, None, raw_text, line)
        base, _, piston = key.rpartition("_")
        if base in ENGINE_PER_PISTON and piston:  # piston_effort_B: one cylinder's of several
            if piston not in slider_names:
                raise self.error(
                    f"{key}: {piston} is no slider of the scene (name a cylinder's piston)",
                    "answers",
                    key,
                )
            value = self._engine_value(value, ENGINE_ANSWERS[base], key)
            return Answer(key, base, (piston,), value, None, raw_text, line)
        return None

    def _torque_answer(self, key, value, raw_text, line, loads, forces):
        """``torque``: the crank's driving torque, where a power balance (or the force
        analysis) gives it (not a driving block's: its effort is a force)."""
        if not loads and not forces:
            raise self.error(
                "a torque answer needs [loads] to balance, or [masses]", "answers", key
            )
        if getattr(self, "two_inputs", False) and not forces:
            raise self.error(
                "with two inputs one power balance does not give the two "
                "driving torques: no torque answer (the force analysis gives each: "
                "give [masses], empty for the loads alone; torque2 the second's)",
                "answers",
                key,
            )
        if getattr(self, "driving_block", None) and not (
            forces and getattr(self, "driving_wheel", None)
        ):
            raise self.error(
                f"the block {self.driving_block} drives the mechanism: its "
                "driving effort is a force along its guide, not a torque "
                "(solve prints it; its answer key is force)",
                "answers",
                key,
            )
        q = self.qty(
            value,
            "torque",
            "answers",
            key,
            default_unit="N m",
            allow_sense=True,
            refuse_absurd=False,
        )
        return Answer(key, "torque", (), q.value, q.sense, raw_text, line)

    def _unknown_key(self, key, hint):
        """The error for a key of no answer kind, with the keys there are."""
        examples = [
            "v_C",
            "a_C",
            "v_CB",
            "omega_BC",
            "alpha_BC",
            "vs_D",
            "as_D",
            "ac_A",
            "rub_B",
            "torque",
        ]
        return self.error(
            f"unknown answer key{hint() or _suggest(key, examples)}; keys are v_X, "
            "a_X, v_XY, a_XY, omega_L, alpha_L, vs_X, as_X, ac_X, rub_X, "
            "torque, force, torque2, force2 (the drivers' efforts), I_ij (a centre), "
            "vI_L, aI_L (a wheel's contact point), vmin_XY (the least speed between "
            "two points of a link), ar_XY, at_XY (X's radial and tangential "
            "acceleration relative to Y), "
            "F_X, N_X, Fi_L, Ci_L, h_L, Fc_L (forces), Thold_O (the torque holding a "
            "fixed gear about O), Tmax_L, Pmax_L (a friction "
            "drive's largest torque and power), piston_effort, crank_effort, "
            "turning_moment, rod_thrust, side_thrust (each with _B: piston B's of several "
            "cylinders), shaking_force, shaking_moment, "
            "T_mean, dE_max, I_flywheel, m_flywheel (the force and engine chapters), "
            "time_ratio, stroke_X (a quick return's times, a slider's stroke), theta_XY, "
            "angle_XYZ (a link's direction from +x, the angle at a joint)",
            "answers",
            key,
        )

    def _motion_names(self, key, prefix, rest, names, what, known, slider_names, pin_names, hint):
        """The names a motion's answer key gives (points, a link or a cylinder, a slider, a
        rolling wheel, a pin of [pins]), each checked to be in the scene."""
        if what == "point":
            if len(names) > 2:
                raise self.error(f"v_X or v_XY: one or two points{hint()}", "answers", key)
            for n in names:
                if n not in known:
                    raise self.error(
                        f"no point {n} in the scene{hint() or _which_point(n, known)}",
                        "answers",
                        key,
                    )
        elif what == "pair":  # two points of one link: vmin_BC, ar_CB, at_CB
            if len(names) != 2 or names[0] == names[1] or not set(names) <= set(known):
                raise self.error(
                    f"{prefix}_XY names two points of one link (e.g. {prefix}_CB){hint()}",
                    "answers",
                    key,
                )
        elif what == "link" and len(names) == 2 and self.find_cylinder(names):
            names = tuple(split_name(self.find_cylinder(names).key))
        elif (
            what == "slider"
            and len(names) == 2
            and self.find_cylinder(names)
            and prefix in ("vs", "as")
        ):
            names = (self.find_cylinder(names).key,)
        elif what == "link":
            if len(names) != 2 or frozenset(names) not in self.index:
                raise self.error(
                    f"no link {rest} in [links]"
                    f"{hint() or _suggest(rest, [lk.key for lk in self.index.values()])}",
                    "answers",
                    key,
                )
        elif what == "slider":
            if len(names) != 1 or names[0] not in slider_names:
                slots = [k for k, s in slider_names.items() if s.point == rest]
                if slots:  # a peg in two slots: which one?
                    raise self.error(
                        f"{rest} sits in two slots: name the slot, "
                        + " or ".join(f"{prefix}_{k}" for k in slots),
                        "answers",
                        key,
                    )
                raise self.error(f"no slider {rest} in [sliders]{hint()}", "answers", key)
        elif what == "wheel":  # the wheel's point at its rolling contact
            wheels = {r.wheel for r in getattr(self, "rolling_pairs", ())}
            lk = self.index.get(frozenset(names)) if len(names) == 2 else None
            if lk is None or lk.key not in wheels:
                raise self.error(
                    f"{prefix}_{rest}: {rest} is no wheel of [rolling] (the key "
                    "names a rolling wheel's link, e.g. aI_CP)",
                    "answers",
                    key,
                )
        elif what == "pin":
            if len(names) != 1 or names[0] not in pin_names:
                raise self.error(
                    f"rubbing at {rest} needs its size in [pins]{hint()}", "answers", key
                )
        return names

    def _force_names(self, key, prefix, rest, names, what, known, slider_names):
        """The names a force answer key gives (a pin, a rolling contact, a friction drive, a
        body, a guide's block), each checked to be in the scene."""
        if what == "pin_force":
            if len(names) != 1 or names[0] not in known:
                raise self.error(
                    f"F_X names a pin: no point {rest} in the scene{_which_point(rest, known)}",
                    "answers",
                    key,
                )
        elif what == "contact":  # a rolling contact's force: the wheel's link, a rack's point
            pairs = getattr(self, "rolling_pairs", ()) or ()
            lk = self.index.get(frozenset(names)) if len(names) == 2 else None
            if not (
                (lk is not None and lk.key in {r.wheel for r in pairs})
                or (len(names) == 1 and names[0] in {r.rim for r in pairs if r.on == "rack"})
            ):
                raise self.error(
                    f"Fc_{rest}: {rest} is no wheel of [rolling] and no rack (the "
                    "key names a rolling wheel's link, e.g. Fc_AP, or a rack's "
                    "point)",
                    "answers",
                    key,
                )
        elif what == "held":  # a fixed circle's centre (an epicyclic's fixed sun or annulus)
            fixed = {
                r.base_centre for r in getattr(self, "rolling_pairs", ()) or () if r.on == "circle"
            }
            if len(names) != 1 or names[0] not in fixed:
                raise self.error(
                    f"Thold_{rest}: no gear of [rolling] rolls on a fixed circle about "
                    f"{rest} (the key names the fixed circle's centre"
                    + (f", e.g. Thold_{sorted(fixed)[0]})" if fixed else ")"),
                    "answers",
                    key,
                )
        elif what == "drive":  # a friction drive's wheel (or the gear it grips), mu stated
            self._drive(key, prefix, rest, names)
        elif what == "body":  # a link, or the block at a slider's point
            if rest in slider_names or (len(names) == 1 and names[0] in slider_names):
                names = (f"block {slider_names[rest].point if rest in slider_names else rest}",)
            elif len(names) != 2 or frozenset(names) not in self.index:
                raise self.error(
                    f"{prefix}_X names a link (Fi_AB) or a slider's block (Fi_B): "
                    f"no link or block {rest}",
                    "answers",
                    key,
                )
            else:
                names = (self.index[frozenset(names)].key,)
        elif what == "guide":
            if len(names) != 1 or names[0] not in slider_names:
                raise self.error(
                    f"N_X names a slider's block: no slider {rest} in [sliders]", "answers", key
                )
        return names
