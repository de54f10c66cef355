"""The [input] table (a part of the scene reader): the driving crank, its angle (or the
position it gives, stated otherwise: ``length_OR``, ``s_B``, ``angle_DC``), its speed (or
the motion given on another quantity: ``vs_B``, ``omega_BC``, ``v_C``), a second driven
crank (``[input.second]``), and the slider crank's dead centres for angles in a book's
words. A driving block or collar is read in :mod:`.block_input`, a motion given on another
quantity in :mod:`.given_motion`, a rate or a speed in words in :mod:`.input_rates`."""

from __future__ import annotations

import math
import re

from ..common.errors import SceneError, printable
from .angles import candidates, is_book_form
from .block_input import _BlockInput
from .crank_speed import crank_speed, link_angle, second_crank_angle
from .given_motion import _given_key, _GivenMotion
from .input_rates import _Rates
from .records import GIVEN_KINDS, INPUT_KEYS, FixedPath, Input, PositionGiven, split_name
from .table_help import _suggest
from .wheel_input import wheel_input


class _Input(_BlockInput, _GivenMotion, _Rates):
    """The [input] table's methods of the scene reader."""

    def dead_centres(self, link, pivot, tip, ground):
        """The candidate dead centres of the slider crank that ``link`` drives, for
        :func:`.angles.read_angle`: ``[(inner, outer, keeps)]``."""
        rods = [
            (lk, s)
            for lk in self.index.values()
            if tip in lk.points and lk is not link
            for s in self.fixed
            if s.point == lk.other(tip)
        ]
        if len(rods) != 1:
            raise SceneError(
                "a dead centre is where the crank and the rod of a slider crank are in line; "
                + (
                    f"crank {link.key} drives no rod whose other end slides on a fixed path "
                    "in [sliders]: give the angle from +x, the horizontal or the vertical"
                    if not rods
                    else f"crank {link.key} drives {len(rods)} slider rods "
                    f"({', '.join(lk.key for lk, _ in rods)}): give the angle from +x"
                )
            )
        ((rod, slider),) = rods
        through = ground[pivot] if slider.through[1] is None else slider.through
        hint = self.raw.get("assembly")
        hint = hint.get(slider.point) if isinstance(hint, dict) else None
        if isinstance(hint, list) and len(hint) == 2:
            try:
                hint = tuple(self.length(c, "assembly", slider.point, positive=False) for c in hint)
            except SceneError:
                hint = None  # refused when [assembly] is read, by its own key
        return candidates(
            ground[pivot],
            link.length,
            rod.length,
            through,
            slider.u,
            hint,
            (self.unit, self.scale()),
        )

    def input(self, index, ground):
        """[input]: what drives the mechanism (a crank; a block on its guide, a collar along
        its rod or a wheel on a line, each read by its own method), where it stands, its
        speed (or the motion given on another quantity) and its acceleration."""
        if "input" not in self.raw:
            raise SceneError(
                "missing [input] table: which link is the crank, its angle and speed",
                file=self.file,
                key="[input]",
            )
        spec = self.table("input")
        if "block" in spec:  # a block on a fixed guide drives the mechanism: no crank
            return self.block_input(spec, ground)
        if "wheel" in spec:  # a wheel rolling on a ground line drives it: no crank
            return wheel_input(self, spec, ground)
        second = None
        if "second" in spec:  # a second driving crank: two degrees of freedom
            second = self.second_input(spec["second"], ground)
            spec = {k: v for k, v in spec.items() if k != "second"}
        spec, placed = self._position_otherwise(spec)
        given_keys, rate_keys = self._motion_keys(spec, placed)
        link, pivot = self._crank(spec, ground)
        tip = link.other(pivot)
        if placed is not None:  # a provisional angle: the one that gives it is found later
            spec = dict(spec, angle=math.degrees(placed.near) if placed.near is not None else 0)
        angle, speed, said = self._angle_and_speed(spec, given_keys, link, pivot, ground)
        alpha = self._crank_acceleration(spec, given_keys, speed)
        self.two_inputs = second is not None
        self.two_given_checks(given_keys, second)
        if given_keys:  # (the crank as stated, for "the piston moves towards the crank")
            self.crank_now = None if placed is not None else (pivot, tip, angle, link)
            given = self._given_motion(given_keys[0], rate_keys, spec, index)
            return Input(
                link.key,
                pivot,
                tip,
                angle,
                None,
                alpha,
                given.text,
                given,
                said=said,
                placed=placed,
                second=second,
            )
        if rate_keys:
            raise self.error(
                f"{rate_keys[0]} is the rate of a given motion, but [input] gives "
                "the crank's speed: give the crank's acceleration instead",
                "input",
                rate_keys[0],
            )
        if speed.value == 0:  # at rest: the weights and loads alone, per rad/s of the crank
            speed, alpha = self.at_rest_speed(alpha, speed.sense, second is not None), 0.0
        self.two_inputs = second is not None
        if second is not None and second.crank == link.key:
            raise self.error(
                f"the second input is the crank {link.key} again: name another "
                "link pivoted on the ground",
                "input.second",
                "crank",
            )
        return Input(
            link.key,
            pivot,
            tip,
            angle,
            speed.value,
            alpha,
            str(spec["speed"]),
            said=said,
            second=second,
            placed=placed,
        )

    def _given_motion(self, key, rate_keys, spec, index):
        """The motion given on another quantity (:meth:`given_rate`), its rate not beside
        the crank's acceleration."""
        given = self.given_rate(key, rate_keys, spec, index)
        if given.rate is not None and "acceleration" in spec:
            raise self.error(
                f"[input] gives both the crank's acceleration and {given.rate_key}: one only",
                "input",
                given.rate_key,
            )
        return given

    def _position_otherwise(self, spec):
        """(spec, placed): the position given otherwise than by the crank's angle (``s_B``,
        ``length_OR``, ``angle_CD``, with ``near``), read and taken out of the table, or
        None."""
        placed = None
        at = [
            k
            for k in spec
            if k.partition("_")[0] in ("length", "s", "angle") and k.partition("_")[2]
        ]
        if at:  # the position given otherwise than by the crank's angle
            if "angle" in spec or len(at) > 1:
                raise self.error(
                    f"[input] gives the position twice ({', '.join(['angle'] * ('angle' in spec) + at)}): "
                    "one only (the crank's angle is then found)",
                    "input",
                    at[-1],
                )
            placed = self.placed_at(at[0], spec[at[0]], spec.get("near"))
            spec = {k: v for k, v in spec.items() if k not in (at[0], "near")}
        elif "near" in spec:
            raise self.error(
                "near is a rough crank angle choosing among those that give a "
                "position stated otherwise (length_OR, s_B, angle_CD): there is "
                "none",
                "input",
                "near",
            )
        return spec, placed

    def _motion_keys(self, spec, placed):
        """(given, rates): the [input] keys of a motion given on another quantity and of its
        rate, checked (one motion only, not beside the crank's speed); the keys the crank
        needs besides them (crank, angle and speed) present."""
        rates = {k: _given_key(k) for k in spec if k not in INPUT_KEYS}
        for k, parsed in rates.items():
            if parsed is None:
                raise self.error(
                    f"unknown key{_suggest(k, INPUT_KEYS)}; [input] takes crank, "
                    "angle, speed, acceleration, or the given motion named as an "
                    "answer key (omega_BC, vs_B, v_B and alpha_BC, as_B, a_B)",
                    "input",
                    k,
                )
        given_keys = [k for k, p in rates.items() if p[0] in GIVEN_KINDS]
        rate_keys = [k for k, p in rates.items() if p[0] not in GIVEN_KINDS]
        if len(given_keys) > 1:
            raise self.error(
                f"[input] gives the motion twice ({', '.join(given_keys)}): a "
                "mechanism of one degree of freedom takes one input",
                "input",
                given_keys[1],
            )
        if given_keys and "speed" in spec:
            raise self.error(
                f"[input] gives both the crank's speed and {given_keys[0]}: one "
                "input only (remove speed to find the crank's from "
                f"{given_keys[0]})",
                "input",
                given_keys[0],
            )
        for k in ("crank",) + (() if placed else ("angle",)) + (() if given_keys else ("speed",)):
            if k not in spec:
                example = {
                    "crank": 'crank = "AB"',
                    "angle": "angle = 60",
                    "speed": 'speed = "10 rad/s ccw"',
                }[k]
                raise self.error(f"[input] has no {k}: add e.g. {example}", "input")
        return given_keys, rate_keys

    def _crank(self, spec, ground):
        """(link, pivot): the crank [input] names, pinned to the ground at one end (a rolling
        wheel, a link off the ground or fixed at both ends refused)."""
        link, pts = self.find_link(spec["crank"], "input", "crank")
        on_ground = [p for p in pts if p in ground]
        rolling = self.raw.get("rolling")
        if (
            not on_ground
            and isinstance(rolling, dict)
            and any(set(split_name(k)) == set(pts) for k in rolling)
        ):
            raise self.error(
                f"{link.key} is a rolling wheel, not a crank: on a line it drives "
                f'alone as wheel = "{link.key}" with omega_{link.key} (no '
                "crank); with a crank in the chain, give the wheel's motion as "
                f"omega_{link.key} (the crank's speed is then found)",
                "input",
                "crank",
            )
        if not on_ground:
            raise self.error(
                f"crank {link.key} is not pinned to the ground: neither "
                f"{pts[0]} nor {pts[1]} is in [ground]",
                "input",
                "crank",
            )
        if len(on_ground) == 2:
            raise self.error(
                f"crank {link.key} has both ends in [ground]; it cannot turn", "input", "crank"
            )
        return link, on_ground[0]

    def _angle_and_speed(self, spec, given_keys, link, pivot, ground):
        """(angle, speed, said): the crank's angle (rad), from +x or in a book's words (a
        dead centre passed in the crank's sense), its speed (None where the motion is given
        on another quantity) and what the book's words said (or ())."""
        tip = link.other(pivot)
        said = ()
        if not is_book_form(spec["angle"]):
            angle = self.qty(spec["angle"], "angle", "input", "angle", default_unit="deg").value
        speed = (
            None
            if given_keys
            else self.rest_speed(spec["speed"])  # at rest: a bare nought needs no unit
            or crank_speed(self, spec["speed"], link)
        )
        if is_book_form(spec["angle"]):  # a dead centre is passed in the crank's sense
            if given_keys and re.search(
                r"\b(past|before|after|beyond)\b", str(spec["angle"]), re.IGNORECASE
            ):
                raise self.error(
                    f"{spec['angle']!r}: past or before a dead centre follows the "
                    "crank's sense, which a given motion leaves to be found; give "
                    "the angle from +x, the horizontal or the vertical",
                    "input",
                    "angle",
                )
            book = self.book_angle(
                spec["angle"],
                "angle",
                "input",
                "angle",
                "crank angle",
                dead=lambda: self.dead_centres(link, pivot, tip, ground),
                sense=None if speed is None else speed.value,
                centres=(pivot, ground),
            )
            angle = book.value
            said = (book.words, angle, book.slips, f"crank angle: {book.note}")
        return angle, speed, said

    def _crank_acceleration(self, spec, given_keys, speed):
        """The crank's angular acceleration: 0 by default, None where a given motion leaves
        it to be found; in a book's words (slowing down) against the crank's speed."""
        acc = spec.get("acceleration", 0 if not given_keys else None)
        if acc is None:
            return None
        if isinstance(acc, (int, float)) and not isinstance(acc, bool) and acc == 0:
            return 0.0
        alpha = self.rated(
            acc,
            "angular_acceleration",
            "input",
            "acceleration",
            None if speed is None else speed.value,
        )
        if alpha is None:
            alpha = self.qty(
                acc, "angular_acceleration", "input", "acceleration", need_sense=True
            ).value
        return alpha

    def placed_at(self, key, raw, near):
        """``length_OR = 850`` (two points' distance, a cylinder's length), ``s_B = 300`` (a
        slider's place on its path from its through point), ``angle_CD = 30`` (the direction
        C -> D): the position as a book gives it; ``near``: a rough crank angle."""
        kind, _, rest = key.partition("_")
        names = split_name(rest)
        if kind == "s":
            sl = self.slider_points.get(names[0]) if len(names) == 1 else None
            if not isinstance(sl, FixedPath):
                raise self.error(
                    f"s_{rest}: no slider {rest} on a fixed path in [sliders] (s_B "
                    "is B's place along its path, from its through point)",
                    "input",
                    key,
                )
            value = self.length(raw, "input", key, positive=False)
        elif kind == "length":
            if len(names) != 2 or any(n not in self.known for n in names):
                raise self.error(
                    f"length_{rest}: two points of the scene, e.g. length_OR (the "
                    "distance O to R, a cylinder's length)",
                    "input",
                    key,
                )
            value = self.length(raw, "input", key)
        else:
            if len(names) != 2 or any(n not in self.known for n in names):
                raise self.error(
                    f"angle_{rest}: two points of the scene, e.g. angle_CD (the direction C -> D)",
                    "input",
                    key,
                )
            value = link_angle(self, raw, key, names, self.ground)
        near_v = (
            None
            if near is None
            else self.qty(near, "angle", "input", "near", default_unit="deg").value
        )
        text = printable(str(raw))
        if isinstance(raw, (int, float)) and not isinstance(raw, bool):
            text += " deg" if kind == "angle" else f" {self.unit}"
        return PositionGiven(key, kind, tuple(names), value, near_v, text)

    def second_input(self, spec, ground):
        """``[input.second]``: a second driving crank, with its crank, angle, speed and
        (optional) acceleration, read as the first's."""
        if not isinstance(spec, dict):
            raise self.error(
                "the second input is a table: [input.second] with crank, angle, speed",
                "input",
                "second",
            )
        if "block" in spec:  # a collar sliding along the turning crank
            sl = self.slider_points.get(spec["block"]) if isinstance(spec["block"], str) else None
            if sl is None or not hasattr(sl, "guide") or sl.slot:
                raise self.error(
                    f"{spec['block']!r}: the second input's block is a collar "
                    'sliding along a turning rod, C = { along = "O-A" } in '
                    "[sliders] (a block on a fixed guide as a second input is "
                    "not solved)",
                    "input.second",
                    "block",
                )
            return self.collar_input(spec, sl, ground, table="input.second")
        given = self.second_given(spec)
        for k in spec:
            if k not in INPUT_KEYS and (given is None or k not in (given.key, given.rate_key)):
                why = (
                    " (a block driven along a turning link, the collar on a rotating rod, "
                    "is not solved yet; a block on a fixed guide drives alone as [input] "
                    "block)"
                    if k == "block" or k.startswith(("vs_", "as_", "s_"))
                    else ""
                )
                raise self.error(
                    f"unknown key{_suggest(k, INPUT_KEYS)}; the second input "
                    f"takes crank, angle, speed (or one given elsewhere: omega_XY, v_X, vs_X), "
                    f"acceleration{why}",
                    "input.second",
                    k,
                )
        for k in ("crank", "angle") + (() if given is not None else ("speed",)):
            if k not in spec:
                raise self.error(f"[input.second] has no {k}", "input.second")
        link, pts = self.find_link(spec["crank"], "input.second", "crank")
        on_ground = [p for p in pts if p in ground]
        if len(on_ground) != 1:
            raise self.error(
                f"the second crank {link.key} must turn about one ground point",
                "input.second",
                "crank",
            )
        pivot = on_ground[0]
        if given is not None:
            return self.second_given_input(spec, given, link, pivot, ground)
        speed = crank_speed(self, spec["speed"], link, "input.second")
        angle = second_crank_angle(self, spec["angle"], link, pivot, ground, speed.value)
        if speed.value == 0:
            raise self.error(
                "the second crank's speed is zero: give it, or make it part of the frame",
                "input.second",
                "speed",
            )
        acc = spec.get("acceleration", 0)
        alpha = (
            0.0
            if (isinstance(acc, (int, float)) and not isinstance(acc, bool) and acc == 0)
            else self.rated(
                acc, "angular_acceleration", "input.second", "acceleration", speed.value
            )
        )
        if alpha is None:
            alpha = self.qty(
                acc, "angular_acceleration", "input.second", "acceleration", need_sense=True
            ).value
        return Input(
            link.key, pivot, link.other(pivot), angle, speed.value, alpha, str(spec["speed"])
        )
