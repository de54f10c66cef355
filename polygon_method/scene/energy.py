"""Reading a scene that states a turning-moment diagram and no mechanism (the flywheel
chapter): ``[turning_moment]`` (areas with the diagram's scales, a law of the crank angle, or
straight segments), ``[press]`` (a punching press), ``[flywheel]`` (the speed's fluctuation
and the rim) and ``[answers]``. Every failure one :class:`SceneError` naming file, key and
line, as the mechanism's reader does (its location helpers are reused).

A law is read from the book's words, ``"1000 + 300 sin 2theta - 500 cos 2theta"``:

>>> parse_law("1000 + 300 sin 2theta - 500 cos(2 theta - 30 deg)")[1]
('sin', 300.0, 2.0, 0.0)
>>> [round(x, 6) for x in parse_law("-500 cos(2 theta - 30 deg)")[0][1:]]
[-500.0, 2.0, -0.523599]
"""

from __future__ import annotations

import math
import re
import tomllib

from ..common.errors import SceneError
from ..common.units import UNITS, did_you_mean
from .energy_areas import _AreasReader
from .energy_cylinders import _CylindersReader
from .energy_flywheel import CYCLE_ANSWERS, _RimReader
from .energy_strokes import _StrokesReader
from .energy_press import _PressReader
from .energy_records import CycleScene, Diagram, Law, Table
from .source import syntax_error, toml_table
from ..common.tolerances import ROUNDING

__all__ = [
    "CYCLE_TABLES",
    "CYCLE_ANSWERS",
    "is_cycle",
    "cycle_from_text",
    "load_cycle",
    "parse_cycle",
    "cycle_from_table",
    "cycle_variation",
    "answer_file_from_text",
    "answers_from_text",
    "parse_law",
]

#: the tables that make a scene a turning-moment diagram's (no mechanism)
CYCLE_TABLES = ("turning_moment", "press")
_TOP = (
    "title",
    "source",
    "notes",
    "units",
    "turning_moment",
    "press",
    "flywheel",
    "answers",
    "variants",
    "variant",
)

_MECHANISM = ("ground", "links", "input", "sliders", "points", "indicator", "masses")
_TM_KEYS = (
    "areas",
    "area_unit",
    "torque_scale",
    "angle_scale",
    "torque",
    "resisting",
    "unit",
    "angle",
    "cycle",
    "at",
    "strokes",
    "power",
    "work",
    "shape",
    "area_scale",
    "dE_max",
    "cylinders",
)
_TOKEN = re.compile(
    r"\s*(?:(?P<num>(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)|(?P<word>sin|cos|theta|θ|deg|°|rad)"
    r"|(?P<op>[-+*/()]))"
)


def is_cycle(raw: dict) -> bool:
    """Whether a scene's table states a turning-moment diagram or a press."""
    return any(k in raw for k in CYCLE_TABLES)


def cycle_from_text(text: str, file: str | None = None) -> CycleScene | None:
    """The :class:`CycleScene` of a scene's TOML text (see the module's words); None where
    the text states no turning-moment diagram (a mechanism's scene)."""
    from .loader import _Loader

    try:
        raw = toml_table(text)
    except tomllib.TOMLDecodeError as exc:
        raise syntax_error(str(exc), text, file) from None
    if not is_cycle(raw):
        return None
    return _CycleReader(_Loader(raw, text, file)).scene()


def cycle_from_table(raw: dict, file: str | None = None) -> CycleScene:
    """The :class:`CycleScene` of a TOML table already parsed (checked as a file's would
    be; the messages name no line): a variant's, made from its base scene's table."""
    from .loader import _Loader

    return _CycleReader(_Loader(raw, "", file)).scene()


def cycle_variation(text: str, file: str | None = None) -> tuple:
    """The ``[variants]`` of a diagram's scene text: its
    :class:`~polygon_method.scene.energy_variation.CycleVaried` keys, each value checked
    as the scene's own would be; ``()`` where it has none."""
    from .energy_variation import read_cycle_variation
    from .loader import _Loader

    try:
        raw = toml_table(text)
    except tomllib.TOMLDecodeError as exc:
        raise syntax_error(str(exc), text, file) from None
    return read_cycle_variation(_Loader(raw, text, file), cycle_from_table)


def answer_file_from_text(text: str, file: str | None = None) -> tuple:
    """``(tolerance, answers, variant, student)`` of a student's answer file for a
    diagram's scene: its ``[answers]`` (read as the scene's are), the variant it names
    (``variant = "07"``, or None) and the student's name (``student`` or ``name``, or
    None)."""
    from .loader import _Loader

    try:
        raw = toml_table(text)
    except tomllib.TOMLDecodeError as exc:
        raise syntax_error(str(exc), text, file) from None
    if not isinstance(raw.get("answers"), dict):
        raise SceneError("no [answers] table", file=file, key="[answers]")
    ld = _Loader(raw, text, file)
    named = raw.get("variant")
    if isinstance(named, int) and not isinstance(named, bool):
        named = f"{named:02d}"
    if named is not None and not (isinstance(named, str) and named.strip()):
        raise SceneError('variant = "07": the variant\'s id', file=file, key="variant")
    student = raw.get("student", raw.get("name"))
    if student is not None and not isinstance(student, str):
        raise SceneError('student = "A. Student": a name, a string', file=file, key="student")
    tolerance, answers = _CycleReader(ld).answers()
    return tolerance, answers, named.strip() if named else None, student


def parse_cycle(text: str, file: str | None = None) -> CycleScene:
    """The :class:`CycleScene` of a turning-moment diagram's TOML text; a
    :class:`SceneError` (one line) where the text states none (a mechanism's scene is read
    by :func:`polygon_method.parse_scene`).

    >>> s = parse_cycle('[turning_moment]\\ntorque = "1000 + 300 sin 2theta"')
    >>> s.diagram.form, round(s.diagram.cycle, 6)
    ('law', 6.283185)
    """
    if not isinstance(text, str):
        raise SceneError("the scene's text (TOML) is needed as a str", file=file)
    scene = cycle_from_text(text, file)
    if scene is None:
        raise SceneError(
            "states no turning-moment diagram ([turning_moment] or [press]): a mechanism's "
            "scene is read by polygon_method.load_scene (or parse_scene)",
            file=file,
        )
    return scene


def load_cycle(path) -> CycleScene:
    """Read a scene file that states a turning-moment diagram (or a punching press) and no
    mechanism: its :class:`CycleScene`, which
    :func:`polygon_method.forces.flywheel_cycle.solve_cycle` solves. Every failure one
    :class:`SceneError` naming file, key and line, as :func:`polygon_method.load_scene`."""
    from ..common.errors import PolygonMethodError
    from .file_text import scene_text

    path, text = scene_text(path)
    try:
        return parse_cycle(text, str(path))
    except PolygonMethodError as exc:
        raise exc.located(str(path))


def answers_from_text(text: str, file: str | None = None) -> tuple:
    """``(tolerance, answers)`` of a student's answer file for a diagram's scene (its
    ``[answers]`` table, read as the scene's is)."""
    from .loader import _Loader

    try:
        raw = toml_table(text)
    except tomllib.TOMLDecodeError as exc:
        raise syntax_error(str(exc), text, file) from None
    if not isinstance(raw.get("answers"), dict):
        raise SceneError("no [answers] table", file=file, key="[answers]")
    return _CycleReader(_Loader(raw, text, file)).answers()


# -- a torque law in the book's words


def parse_law(text: str) -> tuple:
    """The terms ``(f, c, k, phi)`` of a law such as ``"1000 + 300 sin 2theta"``; a
    ValueError with the reason for words it cannot read."""
    s = str(text).strip()
    s = re.sub(r"^\s*T\s*(\(\s*(theta|θ)\s*\))?\s*=", "", s)
    toks, pos = [], 0
    while pos < len(s):
        if s[pos:].strip() == "":
            break
        m = _TOKEN.match(s, pos)
        if m is None:
            raise ValueError(f"cannot read {s[pos:].strip()[:20]!r}")
        toks.append(next((k, v) for k, v in m.groupdict().items() if v is not None))
        pos = m.end()
    terms, i = [], 0
    if not toks:
        raise ValueError("an empty law")
    while i < len(toks):
        sign = 1.0
        while i < len(toks) and toks[i][0] == "op" and toks[i][1] in "+-":
            sign = -sign if toks[i][1] == "-" else sign
            i += 1
        coef, had = 1.0, False
        if i < len(toks) and toks[i][0] == "num":
            coef, had, i = float(toks[i][1]), True, i + 1
            if i < len(toks) and toks[i] == ("op", "*"):
                i += 1
        if i < len(toks) and toks[i][1] in ("sin", "cos"):
            f = toks[i][1]
            k, phi, i = _argument(toks, i + 1)
            terms.append((f, sign * coef, k, phi))
        elif had:
            terms.append(("const", sign * coef, 0.0, 0.0))
        else:
            raise ValueError("each term is a number, or a number times sin or cos of k theta")
        if i < len(toks) and not (toks[i][0] == "op" and toks[i][1] in "+-"):
            raise ValueError(f"unexpected {toks[i][1]!r}")
    return tuple(terms)


def _argument(toks, i):
    """(k, phi, next index) of ``k theta [/ n] [+- phase [deg|rad]]``, in brackets or not."""
    bracket = i < len(toks) and toks[i] == ("op", "(")
    i += bracket
    k = 1.0
    if i < len(toks) and toks[i][0] == "num":
        k, i = float(toks[i][1]), i + 1
        if i < len(toks) and toks[i] == ("op", "*"):
            i += 1
    if i >= len(toks) or toks[i][1] not in ("theta", "θ"):
        raise ValueError("sin and cos take k theta (the crank angle), e.g. sin 2theta")
    i += 1
    if i + 1 < len(toks) and toks[i] == ("op", "/") and toks[i + 1][0] == "num":
        k, i = k / float(toks[i + 1][1]), i + 2
    phi = 0.0
    if bracket:
        if i < len(toks) and toks[i][0] == "op" and toks[i][1] in "+-":
            sgn = -1.0 if toks[i][1] == "-" else 1.0
            if i + 1 >= len(toks) or toks[i + 1][0] != "num":
                raise ValueError("a phase is a number of degrees: sin(theta - 120 deg)")
            phi, i = sgn * float(toks[i + 1][1]), i + 2
            unit = "deg"
            if i < len(toks) and toks[i][1] in ("deg", "°", "rad"):
                unit, i = toks[i][1], i + 1
            phi = phi if unit == "rad" else math.radians(phi)
        if i >= len(toks) or toks[i] != ("op", ")"):
            raise ValueError("a bracket is not closed")
        i += 1
    if not k > 0:
        raise ValueError("the multiple of theta must be positive")
    return k, phi, i


class _CycleReader(_RimReader, _PressReader, _AreasReader, _StrokesReader, _CylindersReader):
    """Reads a :class:`CycleScene` with a mechanism reader's location helpers ``ld``."""

    def __init__(self, ld):
        self.ld = ld
        self.raw = ld.raw

    def err(self, message, table=None, key=None):
        return self.ld.error(message, table, key)

    def scene(self) -> CycleScene:
        raw, ld = self.raw, self.ld
        for key in raw:
            if key in _MECHANISM:
                raise self.err(
                    "a turning-moment diagram stated as [turning_moment] or [press] "
                    "stands alone (no mechanism); an engine's diagram comes from its "
                    "[indicator]",
                    key,
                )
            if key not in _TOP:
                raise self.err(
                    f"unknown table or key{did_you_mean(key, list(_TOP))}; a turning-moment "
                    "diagram's scene has " + ", ".join(_TOP),
                    key,
                )
        if ("turning_moment" in raw) == ("press" in raw):
            raise self.err(
                "give the turning moment ([turning_moment]) or a punching press ([press]): "
                "one of them",
                "press",
            )
        units = raw.get("units", "mm")
        if not isinstance(units, str) or units not in UNITS["length"]:
            raise self.err('units = "mm" (or "cm", "m", "in", "ft")', None, "units")
        ld.unit = units
        for key in ("title", "source", "notes"):
            if key in raw and not isinstance(raw[key], str):
                raise self.err(f'{key} is free text, a string: {key} = "..."', None, key)
        diagram = self.turning_moment() if "turning_moment" in raw else None
        press = self.press() if "press" in raw else None
        fly = self.flywheel(press) if "flywheel" in raw else None
        if diagram is not None and diagram.at is not None and (fly is None):
            raise self.err(
                "the angular acceleration at a crank angle needs the flywheel: give "
                "[flywheel] (its inertia, or the speed's fluctuation)",
                "turning_moment",
                "at",
            )
        tolerance, answers = self.answers()
        return CycleScene(
            raw.get("title", ""),
            ld.file,
            diagram,
            press,
            fly,
            tuple(answers),
            tolerance,
            raw.get("source"),
            units,
            ld.variant_of(),
        )

    # -- [turning_moment]
    def _keys(self, spec, table, keys):
        for k in spec:
            if k not in keys:
                raise self.err(f"unknown key '{k}'{did_you_mean(k, list(keys))}", table, k)

    def _cycle(self, spec, t, default):
        if "cycle" not in spec:
            return default, f"the cycle {math.degrees(default):g} deg (default)"
        raw = spec["cycle"]
        if isinstance(raw, str) and raw.strip().lower() in ("4-stroke", "four-stroke"):
            return 4 * math.pi, "the cycle 720 deg (four-stroke)"
        if isinstance(raw, str) and raw.strip().lower() in ("2-stroke", "two-stroke", "steam"):
            return 2 * math.pi, "the cycle 360 deg"
        c = self.ld.qty(raw, "angle", t, "cycle", default_unit="deg").value
        if not 0 < c <= 8 * math.pi + ROUNDING:
            raise self.err(f"cycle = {raw!r}: between 0 and 1440 deg", t, "cycle")
        return c, f"the cycle {math.degrees(c):g} deg"

    def turning_moment(self) -> Diagram:
        t = "turning_moment"
        spec = self.ld.table(t)
        self._keys(spec, t, _TM_KEYS)
        has = [k for k in ("areas", "torque", "strokes", "dE_max") if k in spec]
        if len(has) != 1:
            raise self.err(
                "give the areas between the diagram and the mean line (areas = [...]), "
                'the turning moment (torque = "1000 + 300 sin 2theta", or a table with '
                "angle = [...]), each stroke's work (strokes = [0, -1, 3, 0]) or the "
                'fluctuation of energy alone (dE_max = "15%" of the work of a cycle): one of '
                "them",
                t,
                has[1] if has else "torque",
            )
        at = None
        if "at" in spec:
            at = self.ld.qty(spec["at"], "angle", t, "at", default_unit="deg").value
        if "strokes" in spec:
            return self._cylinders(spec, t, self._strokes(spec, t, at))
        if "dE_max" in spec:
            return self._fluctuation(spec, t, at)
        if "cylinders" in spec and "angle" not in spec:
            raise self.err(
                "cylinders: one cylinder's readings (angle = [...]) or strokes are summed; a "
                "law sums its cylinders as a list of laws, and areas are the engine's own",
                t,
                "cylinders",
            )
        for k in ("power", "work", "shape", "area_scale"):
            if k in spec:
                raise self.err(
                    f"{k}: only with strokes = [...] (each stroke's work) or dE_max", t, k
                )
        if "areas" in spec:
            for k in ("torque", "resisting", "angle", "unit", "at"):
                if k in spec:
                    raise self.err(f"{k}: not with areas (the areas are the diagram)", t, k)
            return self._areas(spec, t)
        unit = spec.get("unit", "N m")
        if not isinstance(unit, str) or unit.strip() not in UNITS["torque"]:
            raise self.err(
                f"unit = {unit!r}: the torques' unit, one of " + ", ".join(UNITS["torque"]),
                t,
                "unit",
            )
        k = UNITS["torque"][unit.strip()]
        words = []
        if "angle" in spec:
            return self._cylinders(spec, t, self._readings(spec, t, k, unit.strip(), at))
        else:
            driving = self._law(spec["torque"], t, "torque", k)
            cycle, w = self._cycle(spec, t, 2 * math.pi)
            words.append(f"T = {driving.text} {unit.strip()}, {w}")
        resisting = None
        r = spec.get("resisting", "constant")
        if isinstance(r, str) and r.strip().lower() == "constant":
            if isinstance(driving, Law) and not driving.terms:
                raise self.err(
                    'torque = "constant" needs a resisting torque that varies (resisting = '
                    '"800 + 350 sin theta")',
                    t,
                    "resisting" if "resisting" in spec else "torque",
                )
            words.append("the resisting torque constant, the mean (default)")
        else:
            resisting = self._law(r, t, "resisting", k)
            if not resisting.terms:
                raise self.err("only one of torque and resisting may be constant", t, "resisting")
            words.append(f"the resisting torque {resisting.text} {unit.strip()}")
        return Diagram(
            "law" if isinstance(driving, Law) else "table",
            cycle,
            driving=driving,
            resisting=resisting,
            at=at,
            words=tuple(words),
        )

    def _readings(self, spec, t, k, unit, at) -> Diagram:
        """A diagram of straight segments at ``angle``: the engine's turning moment
        (``torque``) and the machine's (``resisting``), each a list of readings at those
        angles; one of them may be ``"constant"`` (a motor's steady torque; the resisting
        torque's default), the resisting torque a law."""
        tq, r = spec["torque"], spec.get("resisting", "constant")
        steady = [isinstance(x, str) and x.strip().lower() == "constant" for x in (tq, r)]
        if steady[0] and not isinstance(r, list):
            raise self.err(
                'torque = "constant" with angle = [...] needs the resisting torque\'s '
                "readings at those angles (resisting = [...])",
                t,
                "resisting" if "resisting" in spec else "torque",
            )
        driving = Law((), "constant") if steady[0] else self._table(spec, "torque", t, k)
        if steady[1]:
            resisting = None
        elif isinstance(r, list) and all(isinstance(v, (int, float)) for v in r):
            resisting = self._table(spec, "resisting", t, k)  # readings at the same angles
        else:
            resisting = self._law(r, t, "resisting", k)
        cycle, w = self._cycle(spec, t, math.radians(spec["angle"][-1]))
        if math.radians(spec["angle"][-1]) > cycle + ROUNDING:
            raise self.err("the table's angles run past the cycle", t, "angle")
        if math.radians(spec["angle"][-1]) < cycle - ROUNDING * cycle:
            raise self.err(
                f"the readings end at {spec['angle'][-1]:g} deg, before the cycle's "
                f"{math.degrees(cycle):g} deg: give the torque to the cycle's end (angle = "
                f"[..., {math.degrees(cycle):g}], torque = [..., 0] where it is nought)",
                t,
                "angle",
            )
        n = len(spec["angle"])
        if steady[0]:
            words = [f"the driving torque constant (a motor's), the mean, {w}"]
        else:
            words = [f"the turning moment in {n} readings, {w}"]
        if resisting is None:
            words.append("the resisting torque constant, the mean (default)")
        elif isinstance(resisting, Table):
            words.append(f"the resisting torque in {n} readings at the same angles")
        else:
            words.append(f"the resisting torque {resisting.text} {unit}")
        return Diagram(
            "table", cycle, driving=driving, resisting=resisting, at=at, words=tuple(words)
        )

    def _law(self, raw, t, key, k):
        """A :class:`Law` from a string (or a list of them, summed: a multi-cylinder
        engine's cylinders), its numbers in the torque unit ``k`` (N m each)."""
        items = raw if isinstance(raw, list) else [raw]
        if not items or not all(isinstance(s, (str, int, float)) for s in items):
            raise self.err(
                f'{key} = a law such as "1000 + 300 sin 2theta" (or a list of them)', t, key
            )
        if len(items) == 1 and isinstance(items[0], str) and items[0].strip() == "constant":
            return Law((), "constant")
        terms = []
        for s in items:
            if isinstance(s, (int, float)) and not isinstance(s, bool):
                terms.append(("const", float(s), 0.0, 0.0))
                continue
            try:
                terms += parse_law(s)
            except ValueError as exc:
                raise self.err(
                    f"{key} = {s!r}: {exc} (write it as the book does, e.g. "
                    '"1000 + 300 sin 2theta - 500 cos(2theta - 30 deg)")',
                    t,
                    key,
                ) from None
        terms = tuple((f, c * k, kk, phi) for f, c, kk, phi in terms)
        if any(not math.isfinite(c) or abs(c) > 1e9 for _, c, _, _ in terms):
            raise self.err(f"{key}: a torque beyond 1e9 N m is absurd; check the unit", t, key)
        text = " + ".join(str(s) for s in items)
        return Law(terms, text)

    def _table(self, spec, key, t, k) -> Table:
        ang, tq = spec["angle"], spec[key]
        ok = (
            isinstance(ang, list)
            and isinstance(tq, list)
            and len(ang) >= 2
            and all(isinstance(v, (int, float)) and not isinstance(v, bool) for v in ang + tq)
        )
        if not ok:
            raise self.err(
                f"angle = [...] (deg) and {key} = [...] (in unit): two lists of numbers", t, "angle"
            )
        if len(ang) != len(tq):
            raise self.err(f"{len(tq)} torques for {len(ang)} angles", t, key)
        if ang[0] != 0 or any(b < a for a, b in zip(ang, ang[1:])) or ang[-1] <= 0:
            raise self.err(
                "the angles start at 0 and do not decrease (a jump: one angle twice)", t, "angle"
            )
        if any(a == b == c for a, b, c in zip(ang, ang[1:], ang[2:])):
            raise self.err("an angle given three times: a jump needs it twice", t, "angle")
        if any(not math.isfinite(v) or abs(v * k) > 1e9 for v in tq):
            raise self.err("a torque beyond 1e9 N m is absurd; check the unit", t, key)
        return Table(
            tuple(math.radians(a) for a in ang),
            tuple(v * k for v in tq),
            f"{len(ang)} readings",
        )

    # -- [press]
