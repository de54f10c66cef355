"""What an ``[answers]`` key names, checked against the scene (a part of the answers'
reader, :mod:`.answers`): its points, link, slider, wheel or pin there; the keys the scene
can check and a did-you-mean among them; the one line an unknown key gets."""

from __future__ import annotations

from .answer_keys import DRIVER_ANSWERS, ENGINE_ANSWERS, under_block_names
from .records import split_name
from .table_help import _suggest, _which_point


class _AnswerNames:
    """The loader's methods checking the names an answer key gives (mixed into
    :class:`.answers._Answers`)."""

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
            "m_small_end, m_L, l_GL, correction_couple, correction_torque (the rod's "
            "equivalent dynamical system), "
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
