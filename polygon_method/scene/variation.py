"""The ``[variants]`` table: what a teacher lets vary from student to student, and how
(a part of the scene reader), and the ``[variant]`` table that names a generated variant.

Every key names something the scene states as a number: a link (``BC``), the crank's
``angle``, ``speed`` or ``acceleration``, or a point with a sub-key (a ground point's or a
fixed path's ``x``/``y``, a carried point's ``along`` or ``distances``, a pin's
``diameter``/``radius``, a load's ``force``). Each takes a range ``{ from, to, step }``
(optional ``unit``) or a list of values as the scene would write them. The values are
checked here as the scene's own value would be; which combinations make a good variant is
decided by :mod:`polygon_method.variants`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..common.errors import SceneError
from ..common.tolerances import ROUNDING, SAME
from .offset_variation import offset_sizes
from .records import split_name

__all__ = ["Varied", "Variation", "VariantOf", "DEFAULT_MIN_CONDITION", "MAX_VALUES"]

#: the default least condition of every step of a variant: sin 15 deg
DEFAULT_MIN_CONDITION = math.sin(math.radians(15.0))
#: the most values one key's range may hold
MAX_VALUES = 10_000

_RANGE_KEYS = ("from", "to", "step", "unit")
_INPUT_VARIED = ("angle", "speed", "acceleration")
_SETTINGS = ("min_condition",)


@dataclass(frozen=True)
class Varied:
    """One varied quantity: where its value goes in the scene's table (``path``), the
    distinct ``values`` as the scene writes them, each ``shown`` with its unit, and in SI."""

    key: str  # as written in [variants], with the sub-key: "BC", "angle", "D.x", "F.distances.B"
    label: str  # in words: "link BC", "crank angle", "x of ground point D"
    path: tuple
    values: tuple
    shown: tuple
    si: tuple
    setup: tuple = ()  # (path, value) set first (a pin's table, a path's through)

    def __len__(self):
        return len(self.values)


@dataclass(frozen=True)
class Variation:
    """A scene's ``[variants]``: the varied quantities and the least condition allowed."""

    varied: tuple
    min_condition: float = DEFAULT_MIN_CONDITION
    min_text: str = "sin 15 deg"

    @property
    def size(self) -> int:
        """How many combinations the ranges allow."""
        return math.prod(len(v) for v in self.varied)


@dataclass(frozen=True)
class VariantOf:
    """A generated variant's ``[variant]`` table: its id, the base scene's title, the seed."""

    id: str
    of: str = ""
    seed: int | None = None


def _g(x: float) -> int | float:
    """A range's value as a short TOML number (no 60.00000000001)."""
    r = float(f"{x:.12g}")
    return int(r) if r.is_integer() and abs(r) < 1e15 else r


class _Variants:
    """The reader's method for ``[variants]`` (mixed into the scene reader with the other
    tables)."""

    def variation(self, inp, ground, sliders, loads) -> Variation | None:
        if "variants" not in self.raw:
            return None
        spec = self.table("variants")
        varied, min_condition, min_text = [], DEFAULT_MIN_CONDITION, "sin 15 deg"
        for key, value in spec.items():
            if key == "min_condition":
                min_condition, min_text = self._min_condition(value)
                continue
            varied.extend(self._varied(key, value, inp, ground, sliders, loads))
        if not varied:
            raise self.error(
                "[variants] varies nothing: give a range or a list, e.g. "
                "BC = { from = 60, to = 75, step = 1 }",
                "variants",
            )
        self._one_key_each(varied)
        return Variation(tuple(varied), min_condition, min_text)

    def _one_key_each(self, varied):
        """Two keys that set one quantity (BC and CB; a pin's radius and its diameter)
        would write one value and show the other on the problem sheet: refused."""
        seen = {}
        for v in varied:
            what = v.path[:2] if v.path[0] == "pins" else v.path
            if what in seen:
                raise self.error(
                    f"{seen[what]} and {v.key} both vary {v.label.split(' of ')[-1]}"
                    ": vary it by one key",
                    "variants",
                    v.key.split(".")[0],
                )
            seen[what] = v.key

    def _min_condition(self, value):
        if isinstance(value, (int, float)) and not isinstance(value, bool):
            if not 0 < value < 1:
                raise self.error(
                    f"min_condition = {value!r}: a sine between 0 and 1 (0.2588 "
                    'for 15 deg), or an angle such as "15 deg"',
                    "variants",
                    "min_condition",
                )
            return float(value), f"{value:g}"
        ang = self.qty(value, "angle", "variants", "min_condition", default_unit="deg").value
        if not 0 < ang < math.pi / 2:
            raise self.error(
                f"min_condition = {value!r}: an angle between 0 and 90 deg",
                "variants",
                "min_condition",
            )
        return math.sin(ang), f"sin {math.degrees(ang):g} deg"

    # ----- one key
    def _varied(self, key, value, inp, ground, sliders, loads):
        raw = self.raw
        if key in _INPUT_VARIED:
            return [self._input(key, value, inp)]
        pts = split_name(key)
        if len(pts) == 2:
            link = self.index.get(frozenset(pts))
            if link is None:
                raise self.error(
                    f"no link {key} in [links] to vary{self._choices(key)}", "variants", key
                )
            unit = self.unit
            return [
                self._values(
                    key,
                    value,
                    "length",
                    unit,
                    ("links", link.key),
                    f"link {link.key}",
                    positive=True,
                )
            ]
        if len(pts) != 1:
            raise self.error(
                f"unknown key{self._choices(key)}: [variants] names a link "
                "(BC), angle, speed, acceleration, a point with what varies "
                "(D = { x = ... }), or min_condition",
                "variants",
                key,
            )
        if not isinstance(value, dict) or not value:
            raise self.error(
                f"a point's variation says what varies: {key} = {{ x = {{ from "
                "= 95, to = 105, step = 1 } } (x, y, along, distances, "
                "diameter, radius, force)",
                "variants",
                key,
            )
        out = []
        for sub, v in value.items():
            out.extend(self._point(key, sub, v, ground, sliders, inp, raw))
        return out

    def _choices(self, key) -> str:
        from .table_help import _suggest

        names = (
            [lk.key for lk in self.index.values()]
            + list(_INPUT_VARIED)
            + list(_SETTINGS)
            + sorted(self.known)
        )
        return _suggest(key, names)

    def _input(self, key, value, inp):
        if inp.block is not None:  # no crank: its place and rates are s_A, vs_A, as_A
            raise self.error(
                f"{key}: the scene is driven by block {inp.block}, which has no "
                f"crank {'angle' if key == 'angle' else key} to vary (vary the "
                "links, points and paths)",
                "variants",
                key,
            )
        if key == "angle":
            return self._values(key, value, "angle", "deg", ("input", "angle"), "crank angle")
        kind = "angular_velocity" if key == "speed" else "angular_acceleration"
        base = inp.omega if key == "speed" else inp.alpha
        if base is None:  # the motion is given on another quantity: the crank's is found
            raise self.error(
                f"{key}: the scene gives the motion on {inp.given.key}, and the "
                f"crank's {'speed' if key == 'speed' else 'acceleration'} is "
                "found from it: there is no crank speed to vary",
                "variants",
                key,
            )
        sense = "ccw" if base > 0 else ("cw" if base < 0 else None)
        return self._values(
            key,
            value,
            kind,
            None,
            ("input", key),
            f"crank {'speed' if key == 'speed' else 'acceleration'}",
            sense=sense,
            nonzero=key == "speed",
        )

    def _point(self, name, sub, value, ground, sliders, inp, raw):
        """The keys varied of point ``name``'s ``sub`` (x, y; along, distances; a pin's
        diameter or radius; a load's force)."""
        key = f"{name}.{sub}"
        if sub in ("x", "y"):
            return self._coordinate(key, name, sub, value, ground, sliders, inp, raw)
        spec = raw.get("points", {}).get(name)
        if sub == "along":
            if not isinstance(spec, dict) or "along" not in spec:
                raise self.error(f"{name} is not a point carried with along", "variants", name)
            return [
                self._values(
                    key,
                    value,
                    "length",
                    self.unit,
                    ("points", name, "along"),
                    f"{name} along {spec['on']}",
                    positive=False,
                    table_key=name,
                )
            ]
        if sub == "distances":
            return self._distances(key, name, value, spec)
        if sub in ("diameter", "radius"):
            if name not in raw.get("pins", {}):
                raise self.error(f"no pin {name} in [pins] to vary", "variants", name)
            return [
                self._values(
                    key,
                    value,
                    "length",
                    self.unit,
                    ("pins", name, sub),
                    f"{sub} of pin {name}",
                    setup=((("pins", name), {}),),
                    table_key=name,
                )
            ]
        if sub == "force":
            return self._force_size(key, name, value, raw)
        if sub == "offset":
            return offset_sizes(self, key, name, value, sliders, raw)
        from .table_help import _suggest

        subs = ("x", "y", "along", "distances", "diameter", "radius", "force", "offset")
        raise self.error(
            f"unknown key '{sub}'{_suggest(sub, subs)}: a point varies by " + ", ".join(subs),
            "variants",
            name,
        )

    def _coordinate(self, key, name, sub, value, ground, sliders, inp, raw):
        """``x`` or ``y`` of a ground point, or of the path of a slider on a fixed path (its
        through point; across the path only: along it nothing moves)."""
        at = [s for s in sliders if s.point == name]  # a peg in two slots: its fixed one
        slider = next((s for s in at if hasattr(s, "u")), at[0] if at else None)
        i = 0 if sub == "x" else 1
        if name in ground:
            return [
                self._values(
                    key,
                    value,
                    "length",
                    self.unit,
                    ("ground", name, i),
                    f"{sub} of ground point {name}",
                    positive=False,
                    table_key=name,
                )
            ]
        if slider is not None and hasattr(slider, "u"):
            if abs(slider.u[1 - i]) < ROUNDING:  # along the path itself: nothing moves
                raise self.error(
                    f"the path of {name} runs along {sub}: moving it along "
                    f"{sub} changes nothing (vary its "
                    f"{'y' if sub == 'x' else 'x'})",
                    "variants",
                    name,
                )
            through = raw["sliders"][name].get("through")
            if isinstance(through, str):
                raise self.error(
                    f"the path of {name} passes through ground point "
                    f"{through}: vary {through} = {{ {sub} = ... }}",
                    "variants",
                    name,
                )
            setup = ()
            if through is None:  # through the crank's pivot (a block driver: the first
                # ground point), as written in [ground]
                origin = inp.pivot if inp.pivot is not None else next(iter(raw["ground"]))
                setup = ((("sliders", name, "through"), list(raw["ground"][origin])),)
            return [
                self._values(
                    key,
                    value,
                    "length",
                    self.unit,
                    ("sliders", name, "through", i),
                    f"{sub} of the path of slider {name}",
                    setup=setup,
                    positive=False,
                    table_key=name,
                )
            ]
        raise self.error(
            f"{name} is not a ground point or a slider on a fixed path: its {sub} is not stated",
            "variants",
            name,
        )

    def _distances(self, key, name, value, spec):
        """The distances of a point carried with ``distances`` that vary, each its own key."""
        if not isinstance(spec, dict) or not isinstance(spec.get("distances"), dict):
            raise self.error(f"{name} is not a point carried with distances", "variants", name)
        if not isinstance(value, dict) or not value:
            raise self.error(
                f"{name}.distances names the distances that vary, e.g. "
                "distances = { B = [40, 45] }",
                "variants",
                name,
            )
        out = []
        for r, v in value.items():
            if r not in spec["distances"]:
                raise self.error(
                    f"{name} is not given a distance from {r} (its distances "
                    f"are from {', '.join(spec['distances'])})",
                    "variants",
                    name,
                )
            out.append(
                self._values(
                    f"{key}.{r}",
                    v,
                    "length",
                    self.unit,
                    ("points", name, "distances", r),
                    f"{r}{name}",
                    table_key=name,
                )
            )
        return out

    def _force_size(self, key, name, value, raw):
        """The size of a force of [loads] given by its size (not as [Fx, Fy])."""
        spec = raw.get("loads", {}).get(name)
        if not isinstance(spec, dict) or isinstance(spec.get("force"), list) or "force" not in spec:
            raise self.error(
                f"no force of a given size at {name} in [loads] to vary "
                "(a force [Fx, Fy] cannot vary by its size)",
                "variants",
                name,
            )
        return [
            self._values(
                key,
                value,
                "force",
                "N",
                ("loads", name, "force"),
                f"force at {name}",
                table_key=name,
            )
        ]

    # ----- the values of one key
    def _values(
        self,
        key,
        value,
        kind,
        unit,
        path,
        label,
        *,
        positive=True,
        sense=None,
        nonzero=False,
        setup=(),
        table_key=None,
    ):
        where = table_key or key
        if isinstance(value, dict):
            items = self._range(key, value, unit, where)
        elif isinstance(value, list):
            if not value:
                raise self.error(f"{key}: the list of values is empty", "variants", where)
            if len(value) > MAX_VALUES:
                raise self.error(
                    f"{key}: the list holds {len(value)} values, more than {MAX_VALUES}",
                    "variants",
                    where,
                )
            items = list(value)
        else:
            raise self.error(
                f"{key} = {value!r}: give a range {{ from = 60, to = 75, step = "
                "1 } or a list [60, 65, 70]",
                "variants",
                where,
            )
        values, shown, si, seen = [], [], [], set()
        for item in items:
            if isinstance(item, bool) or not isinstance(item, (int, float, str)):
                raise self.error(
                    f'{key}: {item!r} is not a value (a number or a string such as "60 mm")',
                    "variants",
                    where,
                )
            if (
                sense is not None
                and isinstance(item, str)
                and item.split()[-1:]
                and item.split()[-1].lower()
                not in ("cw", "ccw", "clockwise", "anticlockwise", "acw", "counterclockwise")
            ):
                item = f"{item} {sense}"  # the base scene's sense
            q = self.qty(
                item,
                kind,
                "variants",
                where,
                default_unit=unit,
                need_sense=kind.startswith("angular"),
            )
            if positive and kind == "length" and q.value <= 0:
                raise self.error(f"{key}: {item!r} must be positive", "variants", where)
            if nonzero and q.value == 0:
                raise self.error(
                    f"{key}: a crank speed of {item!r} moves nothing", "variants", where
                )
            if kind == "length":
                self.length(item, "variants", where, positive=positive)
            same = q.value
            if kind == "angle":  # 0 and 360 deg are one position: one problem
                same = round(math.degrees(q.value) % 360.0, 9) % 360.0
            if same in seen:  # the same value written twice (60 and "6 cm"): once
                continue
            seen.add(same)
            values.append(item)
            si.append(q.value)
            if isinstance(item, str):
                shown.append(item)
            else:
                shown.append(f"{item:g} {unit}" if unit else f"{item:g}")
        return Varied(key, label, path, tuple(values), tuple(shown), tuple(si), setup)

    def _range(self, key, spec, unit, where):
        for k in spec:
            if k not in _RANGE_KEYS:
                from .table_help import _suggest

                raise self.error(
                    f"{key}: unknown key '{k}'{_suggest(k, _RANGE_KEYS)}; a range "
                    "is { from = 60, to = 75, step = 1 } (optional unit)",
                    "variants",
                    where,
                )
        for k in ("from", "to", "step"):
            v = spec.get(k)
            if v is None:
                raise self.error(
                    f"{key}: the range has no {k} (a range is {{ from = 60, to = 75, step = 1 }})",
                    "variants",
                    where,
                )
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not math.isfinite(v):
                raise self.error(
                    f'{key}: {k} = {v!r} must be a number (give the unit as unit = "...")',
                    "variants",
                    where,
                )
        a, b, s = spec["from"], spec["to"], spec["step"]
        u = spec.get("unit", unit)
        if "unit" in spec and not isinstance(u, str):
            raise self.error(
                f'{key}: unit = {u!r} must be a string such as "mm" or "rpm"', "variants", where
            )
        if u is None:
            raise self.error(
                f'{key}: the range needs its unit, e.g. unit = "rpm"', "variants", where
            )
        if s <= 0:
            raise self.error(f"{key}: step = {s!r} must be positive", "variants", where)
        if b < a:
            raise self.error(
                f"{key}: the range is empty (from {a!r} is above to {b!r})", "variants", where
            )
        span = (b - a) / s
        n = int(math.floor(span + SAME)) + 1 if span < 10 * MAX_VALUES else MAX_VALUES + 1
        if n > MAX_VALUES:
            raise self.error(
                f"{key}: the range holds more than {MAX_VALUES} values; take a larger step",
                "variants",
                where,
            )
        vals = [_g(a + i * s) for i in range(n)]
        if u == unit:
            return vals
        return [f"{v:g} {u}" for v in vals]

    # ----- a generated variant's own table
    def variant_of(self) -> VariantOf | None:
        spec = self.raw.get("variant")
        if spec is None:
            return None
        if not isinstance(spec, dict):
            raise SceneError(
                'a scene\'s variant is a table: [variant] id = "07"',
                file=self.file,
                key="variant",
                line=self.top_line("variant"),
            )
        for k in spec:
            if k not in ("id", "of", "seed"):
                raise self.error(f"unknown key '{k}': [variant] has id, of and seed", "variant", k)
        vid = spec.get("id")
        if isinstance(vid, int) and not isinstance(vid, bool):
            vid = f"{vid:02d}"
        if not isinstance(vid, str) or not vid.strip():
            raise self.error('[variant] needs its id, e.g. id = "07"', "variant", "id")
        of = spec.get("of", "")
        if not isinstance(of, str):
            raise self.error("of is the base scene's title (a string)", "variant", "of")
        seed = spec.get("seed")
        if seed is not None and (isinstance(seed, bool) or not isinstance(seed, int)):
            raise self.error("seed is a whole number", "variant", "seed")
        return VariantOf(vid.strip(), of, seed)
