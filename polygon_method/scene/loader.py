"""The scene reader (:class:`_Loader`): every table of a scene checked and turned into its
records, table by table, each failure one :class:`SceneError` naming the file, key and line;
where a key is in the text, a quantity and a length in the scene's unit. The tables' own
readers are mixed in (:mod:`.tables`, :mod:`.inputs`, :mod:`.answers`, ...)."""

from __future__ import annotations

import functools
import math
import re
from dataclasses import replace

from ..common.errors import SceneError
from ..common.tolerances import SAME
from ..common.typography import long_integer_text, odd_in_name
from ..common.units import LENGTH_UNITS, UNITS, parse_quantity
from .rolling import read_rolling
from .teeth_links import links_from_teeth
from .source import (
    LineIndex,
    has_long_run,
    long_integer,
    printable_text,
    toml_lines,
)
from .records import (
    _ABSURD_LONG,
    _ABSURD_SHORT,
    _POINT_ONLY,
    _UNIT_ORDER,
    TOP_KEYS,
    FixedPath,
    Link,
    Scene,
    split_name,
)
from .inputs import _Input
from .engine import _Engine
from .masses import _Masses
from .answers import _Answers
from .table_help import _suggest
from .tables import _Tables
from .variation import _Variants
from .connected import _Connected
from .cylinder_loads import _CylinderLoads

_TOP_KEYS = frozenset(TOP_KEYS)
#: the most points a scene may have (a textbook's mechanism has a few dozen; a long chain
#: of dyads for studying how rounding grows has thousands: the chain of 10,001 links that
#: measures planning time has 10,002)
MAX_POINTS = 20000


class _Loader(_Tables, _Answers, _Input, _Variants, _Masses, _Engine, _Connected, _CylinderLoads):
    def __init__(self, raw: dict, text: str, file):
        self.raw = raw
        self.text = text
        self.long_run = has_long_run(text)
        self.file = file
        self.unit = "mm"
        self.strokes, self.fixed = {}, []  # the fixed paths: directions (rad), records
        self.read_notes = []  # how angles in a book's words were read

    # -- locations
    @functools.cached_property
    def lines(self) -> list:
        """The text's lines (as TOML counts them), split when a line is first asked for."""
        return toml_lines(self.text)

    def line_of(self, table: str | None, key: str | None = None):
        """Line number of ``[table] key`` (or of the table header) in the file, if found
        (all of them found in one pass, the first time one is asked for)."""
        index = self.__dict__.get("_line_index")
        if index is None:
            index = self._line_index = LineIndex(self.lines)
        return index(table, key)

    def error(self, message, table=None, key=None, cls=SceneError):
        label = f"[{table}] {key}" if table and key else (f"[{table}]" if table else key)
        return cls(
            printable_text(message),
            file=self.file,
            key=printable_text(label),
            line=self.line_of(table, key),
        )

    def top_line(self, key):
        for i, line in enumerate(self.lines, 1):
            if re.match(r"^\s*\[", line):
                return None
            if re.match(rf"^\s*{re.escape(key)}\s*=", line):
                return i
        return None

    def qty(self, raw, kind, table, key, **kw):
        try:
            return parse_quantity(raw, kind, where="", **kw)
        except SceneError as exc:
            raise self.error(exc.message, table, key) from None

    def length(self, raw, table, key, *, positive=True):
        kind = type(raw)
        if kind is int or kind is float:  # a bare number in the scene's unit: at once
            try:
                q = float(raw) * UNITS["length"][self.unit]  # what parse_quantity gives
            except OverflowError:  # an integer of hundreds of digits: worded below
                q = math.nan
            if (_ABSURD_SHORT if positive else -_ABSURD_LONG) <= q <= _ABSURD_LONG:
                return q  # (else, NaN and infinities too: refused in the words below)
        q = self.qty(raw, "length", table, key, default_unit=self.unit).value
        if positive and q <= 0:
            raise self.error(f"length must be positive, got {raw!r}", table, key)
        if abs(q) > _ABSURD_LONG or (positive and q < _ABSURD_SHORT):
            raise self.error(
                f"length {raw!r} ({q:g} m) is absurd for a mechanism; "
                f'check the units (units = "{self.unit}")',
                table,
                key,
            )
        return q

    def coords(self, raw, table, key):
        if not (isinstance(raw, list) and len(raw) == 2):
            raise self.error("expected coordinates [x, y]", table, key)
        return (
            self.length(raw[0], table, key, positive=False),
            self.length(raw[1], table, key, positive=False),
        )

    def table(self, name, required=False) -> dict:
        value = self.raw.get(name)
        if value is None:
            if required:
                raise SceneError(f"missing [{name}] table", file=self.file, key=f"[{name}]")
            return {}
        if not isinstance(value, dict):
            raise SceneError(
                f"'{name}' must be a table [{name}]",
                file=self.file,
                key=name,
                line=self.top_line(name),
            )
        return value

    def point_name(self, name, table, key=None):
        one = type(name) is str and len(name) == 1 and "A" <= name <= "Z"  # (the usual)
        if not one and not _POINT_ONLY.match(str(name)):
            raise self.error(
                f"'{name}' is not a point name (a capital letter, optionally "
                f"followed by digits: A, O2, B1){odd_in_name(name)}",
                table,
                key or name,
            )
        return name

    def check_integers(self):
        """Refuse an integer beyond TOML's 64-bit range (``BC = 10**400`` written out):
        named by its key, never an overflow further on."""
        hit = long_integer(self.raw) if self.long_run else None
        if hit is None:
            return
        path, value = hit
        shown = long_integer_text(value)
        message = (
            f"the integer {shown} is beyond TOML's 64-bit integers, and absurd for a "
            "mechanism; check the value and its unit"
        )
        if len(path) >= 2:
            raise self.error(message, path[0], path[1])
        raise SceneError(
            message,
            file=self.file,
            key=path[0] if path else None,
            line=self.top_line(path[0]) if path else None,
        )

    # -- the scene
    def scene(self) -> Scene:
        """The scene, its tables read and checked each after those it needs."""
        self.check_integers()
        self._top_keys()
        units, title, source = self._header()
        ground = self._ground()
        links, index = self._links(ground)
        self.index = index
        self.ground = ground
        points, sliders, rolling, known, cylinders, inp = self._mechanism(links, index, ground)
        assembly = self.assembly(known)
        hint = getattr(self, "collar_hint", None)  # a driving collar placed by [x, y]
        if hint is not None:
            assembly.setdefault(*hint)
        pins = self.pins(known)
        loads = self.loads(known)
        cylinders = self.cylinder_loads(cylinders, inp)  # a force given in a passive one
        masses, gravity = self.masses(points, sliders), self.gravity()
        friction = self.friction(pins, sliders, known)
        indicators = self.indicators(sliders)
        indicator = indicators[0] if len(indicators) == 1 else None
        flywheel = self.flywheel()
        tolerance, answers = (
            self.answers(known, sliders, pins, loads)
            if getattr(self, "read_answers", True)
            else (None, ())
        )
        self.connected(links, points, sliders, ground, inp, cylinders, rolling)
        if len(known) > MAX_POINTS:
            raise SceneError(
                f"the scene has {len(known)} points: at most {MAX_POINTS} (a "
                "mechanism of a textbook has a few dozen)",
                file=self.file,
            )
        variation = (
            self.variation(inp, ground, sliders, loads)
            if getattr(self, "read_variants", True)
            else None
        )
        variant = self.variant_of()
        return Scene(
            title=title,
            units=units,
            ground=ground,
            links=tuple(links),
            points=tuple(points),
            sliders=tuple(sliders),
            assembly=assembly,
            input=inp,
            pins=tuple(pins),
            loads=tuple(loads),
            answers=tuple(answers),
            tolerance=tolerance,
            file=self.file,
            cylinders=tuple(cylinders),
            source=source if isinstance(source, str) else None,
            variation=variation,
            variant=variant,
            reading_notes=tuple(self.read_notes),
            _link_index=index,
            rolling=tuple(rolling),
            masses=tuple(masses),
            statics="masses" in self.raw,
            at_rest=getattr(self, "at_rest", False),
            start_alpha=getattr(self, "start_alpha", 0.0),
            gravity=gravity,
            indicator=indicator,
            indicators=indicators,
            flywheel=flywheel,
            friction=friction,
            _text=self.text,
        )

    def _top_keys(self):
        """Every top-level key is one a scene has (a turning-moment diagram's tables are
        refused, naming their reader)."""
        raw = self.raw
        for key in raw:
            if key not in _TOP_KEYS:
                if key in ("turning_moment", "press") and isinstance(raw[key], dict):
                    raise SceneError(
                        f"a turning-moment diagram with no mechanism ([{key}]) is not a "
                        "mechanism's scene: read it with polygon_method.load_cycle (or "
                        "parse_cycle) and solve it with polygon_method.solve_cycle",
                        file=self.file,
                        key=f"[{key}]",
                        line=self.line_of(key),
                    )
                kind = "table" if isinstance(raw[key], dict) else "key"
                where = f"[{key}]" if kind == "table" else key
                raise SceneError(
                    f"unknown {kind}{_suggest(key, TOP_KEYS)}; a scene has " + ", ".join(TOP_KEYS),
                    file=self.file,
                    key=printable_text(where),
                    line=self.line_of(key) if kind == "table" else self.top_line(key),
                )

    def _header(self):
        """(units, title, source): the scene's length unit and its free text, checked."""
        raw = self.raw
        units = raw.get("units", "mm")
        if not isinstance(units, str):
            raise SceneError(
                'units is a string: units = "mm" (or "cm", "m", "in", "ft")',
                file=self.file,
                key="units",
                line=self.top_line("units") or self.line_of("units"),
            )
        if units not in LENGTH_UNITS:
            raise SceneError(
                f"unknown length unit {units!r}{_suggest(units, _UNIT_ORDER)}; "
                "use mm, cm, m, in or ft",
                file=self.file,
                key="units",
                line=self.top_line("units"),
            )
        self.unit = units
        title = raw.get("title", "")
        if not isinstance(title, str):
            raise SceneError(
                'title must be a string: title = "Four-bar chain ABCD"',
                file=self.file,
                key="title",
                line=self.top_line("title") or self.line_of("title"),
            )
        source = raw.get("source")
        for key in ("source", "notes"):  # free text: a number or a table is a slip
            if key in raw and not isinstance(raw[key], str):
                raise SceneError(
                    f'{key} is free text, a string: {key} = "..."',
                    file=self.file,
                    key=key,
                    line=self.top_line(key) or self.line_of(key),
                )
        return units, title, source

    def _ground(self) -> dict:
        """[ground]: the fixed points, at least one."""
        raw = self.raw
        ground = {}
        for name, value in self.table("ground").items():
            self.point_name(name, "ground")
            ground[name] = self.coords(value, "ground", name)
        if not ground:  # (a wheel rolling on the floor has no pivot, but its floor a point)
            raise SceneError(
                f"{'[ground] is empty' if 'ground' in raw else 'missing [ground] table'}; give "
                "at least the crank's fixed pivot (where no link turns about the frame, as a "
                "wheel rolling on the floor or a driving block, a point of its line: O = [0, 0], "
                'with through = "O")',
                file=self.file,
                key="[ground]",
                line=self.line_of("ground"),
            )
        return ground

    def _links(self, ground):
        """(links, index): [links], each a length between two points (one between two
        ground points as far apart as they are); the index by the pair of points."""
        links, index = [], {}
        stated = self.table("links", required="rolling" not in self.raw)
        for key, value in stated.items():
            pts = split_name(key)
            if len(pts) != 2:
                raise self.error(
                    f"{key!r} is not a link name: a link is named by its two "
                    f'joint points, e.g. BC or "O2-A"{odd_in_name(key)}',
                    "links",
                    key,
                )
            if pts[0] == pts[1]:
                raise self.error("a link joins two different points", "links", key)
            if isinstance(value, dict):
                raise self.error("a link's value is its length, e.g. BC = 66", "links", key)
            length = self.length(value, "links", key)
            pair = frozenset(pts)
            if pair in index:
                raise self.error(
                    f"duplicate link: {index[pair].key} and {key} join the same points",
                    "links",
                    key,
                )
            link = Link(key, pts[0], pts[1], length)
            index[pair] = link
            links.append(link)
            if pts[0] in ground and pts[1] in ground:
                gx = math.dist(ground[pts[0]], ground[pts[1]])
                if abs(gx - length) > SAME * max(gx, length):
                    raise self.error(
                        f"both ends are ground points {gx / self.scale():g} "
                        f"{self.unit} apart, but the link is {value}",
                        "links",
                        key,
                    )
        for key, p, q, length in links_from_teeth(self, index, ground):  # a book's gears
            index[frozenset((p, q))] = link = Link(key, p, q, length)
            links.append(link)
        if not links:
            raise SceneError(
                "[links] is empty", file=self.file, key="[links]", line=self.line_of("links")
            )
        return links, index

    def _mechanism(self, links, index, ground):
        """(points, sliders, rolling, known, cylinders, input): the tables that make the
        mechanism, each after those it names (a slider on a carried point, the input on a
        slider); a fixed path with no through point goes through the crank's pivot."""
        points = self.carried_points(index, ground)
        carried = {p.name for p in points}
        sliders = self.sliders(index, ground, carried)
        rolling = read_rolling(self, ground, sliders, carried)
        self.rolling_pairs = rolling
        known = set(ground).union([lk.p for lk in links], [lk.q for lk in links], carried)
        known |= {s.point for s in sliders}  # a peg in two slots, a collar on no link; a yoke
        known |= {s.yoke for s in sliders if hasattr(s, "yoke")}
        self.known = known
        self.slider_points = {s.point: s for s in sliders}
        self.cylinder_list = cylinders = self.cylinders(known)
        inp = self.input(index, ground)
        if inp.wheel is not None:  # the driving wheel's centre moves on its own path
            sliders = list(sliders) + [self.slider_points[inp.block]]
        origin = ground[inp.pivot] if inp.pivot is not None else next(iter(ground.values()))
        sliders = [
            replace(s, through=origin) if isinstance(s, FixedPath) and s.through[1] is None else s
            for s in sliders
        ]
        return points, sliders, rolling, known, cylinders, inp

    def scale(self):
        return UNITS["length"][self.unit]

    def find_link(self, name, table, key):
        pts = split_name(name) if isinstance(name, str) else ()
        if len(pts) != 2:
            raise self.error(f"'{name}' is not a link name (two points, e.g. BC)", table, key)
        link = self.index.get(frozenset(pts))
        if link is None:
            wheel = (
                f" (a wheel is a link too: {name} = its radius, or its teeth and a module)"
                if table == "rolling"
                else ""
            )
            raise self.error(
                f"no link {name} in [links]"
                f"{_suggest(name, [lk.key for lk in self.index.values()]) or wheel}",
                table,
                key,
            )
        return link, pts
