"""The motion given on another quantity than the crank's speed (a part of the scene reader):
``[input] omega_BC``, ``vs_B`` (a slider's, or a cylinder's rate of extension), ``v_C``, with
their rates, read into a :class:`GivenRate`."""

from __future__ import annotations

import re

from ..common.errors import printable
from .block_input import _SENSE as _COLLAR
from .piston_words import towards_the_crank
from .rate_words import RATED as _RATED
from .crank_speed import second_crank_angle
from .records import GIVEN_KINDS, INPUT_KEYS, GivenRate, Input, split_name

_WAYS = r"(extending|retracting|lengthening|shortening|outwards?|inwards?)"


def _extending(raw):
    """A cylinder's rate with a word: ``"0.2 m/s extending"`` (``"0.2 m/s, extending"``,
    ``"extending at 0.2 m/s"``) -> 0.2 m/s, ``retracting`` -> its negative (a signed
    number: + extending)."""
    if isinstance(raw, str):
        m = re.match(rf"^\s*(.*?\S)\s*,?\s+{_WAYS}\s*$", raw, re.IGNORECASE)
        m = m or re.match(rf"^\s*(){_WAYS}\s+(?:at\s+)?(.*?\S)\s*$", raw, re.IGNORECASE)
        if m:
            text = (m.group(1) or m.group(3)).strip()
            if m.group(2).lower() in ("retracting", "shortening", "inward", "inwards"):
                text = text[1:] if text.startswith("-") else "-" + text.lstrip("+")
            return text
    return raw


def _given_key(key):
    """(prefix, names) of an [input] key naming a given motion or its rate (``vs_B`` ->
    ("vs", ("B",))), or None."""
    prefix, _, rest = key.partition("_")
    if prefix not in ("omega", "vs", "v", "alpha", "as", "a") or not rest:
        return None
    names = split_name(rest)
    if (
        not names
        or len(names) > 2
        or (prefix in ("omega", "alpha") and len(names) != 2)
        or (prefix in ("v", "a") and len(names) != 1)
    ):
        return None  # vs_OR, as_OR: a cylinder's rate of extension
    return prefix, names


class _GivenMotion:
    """The reader's methods for a motion given on another quantity in [input]."""

    def given_rate(self, key, rate_keys, spec, index, table="input") -> GivenRate:
        """``omega_BC = "3 rad/s cw"``, ``vs_B = "1.5 m/s up"``, ``v_B = "3 m/s down"`` in
        [input], with its rate (``alpha_BC``, ``as_B``, ``a_B``) if given."""
        kind, names = _given_key(key)
        rate_kind = GIVEN_KINDS[kind]
        for r in rate_keys:
            rk, rnames = _given_key(r)
            if rk != rate_kind or rnames != names:
                raise self.error(
                    f"{r} does not go with {key}: the given motion's rate is "
                    f"{rate_kind}_{'-'.join(names) if len(names) > 1 and any(len(n) > 1 for n in names) else ''.join(names)}",
                    table,
                    r,
                )
        rate_key = rate_keys[0] if rate_keys else None
        raw, raw_rate = spec[key], spec.get(rate_key) if rate_key else None
        text = printable(str(raw))
        rate_text = None if raw_rate is None else printable(str(raw_rate))
        direction = None
        if kind == "omega":
            if len(names) != 2 or frozenset(names) not in index:
                raise self.error(f"no link {''.join(names)} in [links]", table, key)
            value = self.qty(raw, "angular_velocity", table, key, need_sense=True).value
            rate = (
                None
                if raw_rate is None
                else (
                    0.0
                    if raw_rate == 0
                    else self.rated(raw_rate, "angular_acceleration", table, rate_key, value)
                )
            )
            if rate is None and raw_rate is not None:
                rate = self.qty(
                    raw_rate, "angular_acceleration", table, rate_key, need_sense=True
                ).value
            names = index[frozenset(names)].points
        else:
            point = names[0] if len(names) == 1 else None
            if kind == "vs" and point is None:  # a cylinder's rate of extension
                cyl = self.find_cylinder(names)
                if cyl is None:
                    raise self.error(f"no cylinder {'-'.join(names)} in [cylinders]", table, key)
                names, u = (cyl.key,), (1.0, 0.0)  # signed: + extending
                raw = _extending(raw)
                if raw_rate is not None and not (
                    isinstance(raw_rate, str) and any(r.match(raw_rate.strip()) for r in _RATED)
                ):  # slowing: kept
                    raw_rate = _extending(raw_rate)
            elif kind == "vs":
                sl = self.slider_points.get(point)
                if sl is None:
                    raise self.error(f"no slider {''.join(names)} in [sliders]", table, key)
                u = getattr(sl, "u", None)
                raw, raw_rate = towards_the_crank(self, sl, (raw, key), (raw_rate, rate_key))
            else:
                if point is None or point not in self.known:
                    raise self.error(f"no point {''.join(names)} in the scene", table, key)
                u = None
            self._along_turning(kind, u, _COLLAR.match(str(raw)), (raw, key, table))
            value, direction = self.directed(raw, "velocity", key, u, kind == "v", table)
            self._along_turning(kind, u, direction, (raw, key, table))
            rate = None
            if raw_rate is not None:  # a point's speed: its rate is of the speed (+1)
                rate = self.rated(
                    raw_rate, "acceleration", table, rate_key, value if kind == "vs" else 1.0
                )
            if raw_rate is not None and rate is None:
                rate, way = self.directed(
                    raw_rate, "acceleration", rate_key, u if kind == "vs" else None, False, table
                )
                self._along_turning(kind, u, way, (raw_rate, rate_key, table))
        if value == 0:
            raise self.error(
                f"{key} is zero: it does not set the crank's speed (give the "
                "crank's speed instead)",
                table,
                key,
            )
        return GivenRate(key, kind, tuple(names), value, rate, direction, text, rate_key, rate_text)

    def _along_turning(self, kind, u, way, given):
        """A way in the plane ("at 30 deg", "up") given to the sliding ``vs_X`` (``kind``
        "vs") of a block along a turning link (no fixed guide ``u``): refused, the link's
        direction changes with the motion, so the words would be read as nothing (its
        sliding is signed along the link)."""
        if kind != "vs" or u is not None or way is None:
            return
        raw, key, table = given
        sl = self.slider_points[key.split("_", 1)[1]]
        raise self.error(
            f"{raw!r}: block {sl.point} slides along the turning link {sl.guide}, whose "
            "direction the mechanism sets: give its sliding signed along the link, positive "
            f'from {sl.first} towards {sl.second} (e.g. "1.5 m/s" or "-1.5 m/s")',
            table,
            key,
        )

    def find_cylinder(self, names):
        return next((c for c in self.cylinder_list if {c.barrel, c.rod} == set(names)), None)

    def two_given_checks(self, given_keys, second):
        """With two inputs, a speed given elsewhere (a link's ``omega_XY``, a point's
        ``v_X``, a slider's ``vs_X``) stands beside a second crank (not a collar)."""
        if not (given_keys and second is not None):
            return
        if second.block is not None:
            raise self.error(
                f"{given_keys[0]} with two inputs: a speed given elsewhere (omega_XY, v_X, "
                "vs_X) stands beside a second crank, not a collar: give the crank's own",
                "input",
                given_keys[0],
            )

    def second_given(self, spec):
        """The speed of the second input given elsewhere (a link's ``omega_XY``, a point's
        ``v_X``, a slider's ``vs_X``, with its rate) in ``[input.second]``, read as the
        first input's; None where it gives its crank's own speed."""
        keys = [k for k in spec if k not in INPUT_KEYS and _given_key(k) is not None]
        given = [k for k in keys if _given_key(k)[0] in GIVEN_KINDS]
        if not given:
            return None
        if len(given) > 1 or "speed" in spec:
            raise self.error(
                f"{given[-1]}: the second input's speed is its crank's (speed) or one given "
                "elsewhere (omega_XY, v_X or vs_X, with its rate), one only",
                "input.second",
                given[-1],
            )
        rates = [k for k in keys if k not in given]
        g = self.given_rate(given[0], rates, spec, self.index, "input.second")
        if g.rate is not None and "acceleration" in spec:
            raise self.error(
                f"[input.second] gives both the crank's acceleration and {g.rate_key}: one only",
                "input.second",
                g.rate_key,
            )
        return g

    def second_given_input(self, spec, given, link, pivot, ground):
        """The second crank whose speed is found from ``given`` when the scene is compiled
        (its omega None until then; its alpha None unless its own is stated)."""
        angle = second_crank_angle(self, spec["angle"], link, pivot, ground, None)
        acc = spec.get("acceleration")
        alpha = None
        if isinstance(acc, (int, float)) and not isinstance(acc, bool) and acc == 0:
            alpha = 0.0
        elif acc is not None:
            alpha = self.qty(
                acc, "angular_acceleration", "input.second", "acceleration", need_sense=True
            ).value
        return Input(link.key, pivot, link.other(pivot), angle, None, alpha, given.text, given)
