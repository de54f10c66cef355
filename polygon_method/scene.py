"""Scene files: a mechanism problem as a textbook states it (see ``docs/scene-format.md``).

The loader is the only part of the tool that reads files. It checks every table and key,
turns quantities into SI and resolves names, so that everything after it works on a
:class:`Scene` that is known to be well formed (whether the links can be assembled is the
plan's business).

>>> s = parse_scene('''
... [ground]
... A = [0, 0]
... D = [100, 0]
... [links]
... AB = 50
... BC = 66
... CD = 56
... [input]
... crank = "AB"
... angle = 60
... speed = "10.5 rad/s cw"
... ''')
>>> s.link("CB").length
0.066
>>> s.input.omega
-10.5
"""

from __future__ import annotations

import math
import re
import tomllib
from dataclasses import dataclass, field, replace
from pathlib import Path

from .errors import PolygonMethodError, SceneError
from .units import LENGTH_UNITS, UNITS, did_you_mean, parse_quantity

__all__ = [
    "Scene", "Link", "CarriedPoint", "FixedPath", "GuideSlider", "Input", "Pin", "Load",
    "Answer", "load_scene", "parse_scene", "split_name", "ANSWER_KINDS", "parse_answers",
    "load_answers",
]

POINT_NAME = re.compile(r"[A-Z][0-9]*")
_POINT_ONLY = re.compile(r"^[A-Z][0-9]*$")
_LINK_NAME = re.compile(r"^(?:[A-Z][0-9]*-?)+$")

_UNIT_ORDER = ("mm", "cm", "m", "in")

#: the largest and smallest lengths a scene may state, in metres
_ABSURD_LONG = 1e4
_ABSURD_SHORT = 1e-7

TOP_KEYS = ("title", "source", "notes", "units", "ground", "links", "points", "sliders",
            "assembly", "input", "pins", "loads", "answers")
INPUT_KEYS = ("crank", "angle", "speed", "acceleration")

#: answer key prefix -> (unit kind, what it names, sense allowed)
ANSWER_KINDS = {
    "v": ("velocity", "point", False),
    "a": ("acceleration", "point", False),
    "omega": ("angular_velocity", "link", True),
    "alpha": ("angular_acceleration", "link", True),
    "vs": ("velocity", "slider", True),
    "as": ("acceleration", "slider", True),
    "ac": ("acceleration", "slider", False),
    "rub": ("velocity", "pin", False),
}


def split_name(name: str) -> tuple[str, ...]:
    """Point names in a link or relative name: ``"BC"`` -> (B, C), ``"O2-A"`` -> (O2, A)."""
    if not isinstance(name, str) or not _LINK_NAME.match(name) or name.endswith("-"):
        return ()
    return tuple(POINT_NAME.findall(name))


@dataclass(frozen=True)
class Link:
    """A rigid binary link between two joint points, named as in the scene."""

    key: str
    p: str
    q: str
    length: float

    @property
    def points(self) -> tuple[str, str]:
        return (self.p, self.q)

    def other(self, point: str) -> str:
        return self.q if point == self.p else self.p


@dataclass(frozen=True)
class CarriedPoint:
    """A point fixed on a link: ``X = P + lam (Q - P) + mu perp(Q - P)``.

    ``P``, ``Q`` are the link's two joint points (``link.p``, ``link.q``) and ``perp`` turns a
    vector 90 deg counter-clockwise. The image point on a polygon follows the same formula.
    """

    name: str
    link: str
    lam: float
    mu: float
    how: str  # the scene's own words, for step tables


@dataclass(frozen=True)
class FixedPath:
    """A slider moving on a fixed straight line through ``through`` along unit ``u``."""

    point: str
    u: tuple[float, float]
    through: tuple[float, float]
    label: str


@dataclass(frozen=True)
class GuideSlider:
    """A block pinned at ``point`` that slides along moving link ``guide`` (first -> second)."""

    point: str
    guide: str
    first: str
    second: str


@dataclass(frozen=True)
class Input:
    """The driving crank: link ``crank`` turning about ground point ``pivot``."""

    crank: str
    pivot: str
    tip: str
    angle: float  # rad, direction of pivot -> tip
    omega: float  # rad/s, ccw positive
    alpha: float  # rad/s^2, ccw positive
    speed_text: str


@dataclass(frozen=True)
class Pin:
    point: str
    radius: float
    given: str  # "diameter" or "radius", as the scene gave it


@dataclass(frozen=True)
class Load:
    """A force on a point (N), or a torque on a link (N m, ccw positive)."""

    target: str
    force: tuple[float, float] | None = None
    torque: float | None = None


@dataclass(frozen=True)
class Answer:
    key: str
    kind: str  # prefix of ANSWER_KINDS or "torque"
    names: tuple[str, ...]
    value: float  # SI; signed when a sense was given
    sense: str | None
    raw: str
    line: int | None = None


@dataclass(frozen=True)
class Scene:
    """A loaded, checked scene. Lengths in metres, angles in radians, SI throughout."""

    title: str
    units: str
    ground: dict
    links: tuple
    points: tuple
    sliders: tuple
    assembly: dict
    input: Input
    pins: tuple = ()
    loads: tuple = ()
    answers: tuple = ()
    tolerance: float | None = None
    file: str | None = None
    _link_index: dict = field(default_factory=dict, repr=False, compare=False)
    _cache: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    # ----- lookups
    def link(self, name: str) -> Link:
        """The link joining the two points of ``name``, in either order."""
        pts = split_name(name)
        found = self._link_index.get(frozenset(pts)) if len(pts) == 2 else None
        if found is None:
            raise SceneError(f"no link {name} in [links]", file=self.file)
        return found

    def has_link(self, name: str) -> bool:
        pts = split_name(name)
        return len(pts) == 2 and frozenset(pts) in self._link_index

    @property
    def point_names(self) -> tuple[str, ...]:
        """Every point of the scene: ground, joints, carried points (in file order)."""
        seen = dict.fromkeys(self.ground)
        for link in self.links:
            seen.update(dict.fromkeys(link.points))
        for cp in self.points:
            seen[cp.name] = None
        return tuple(seen)

    def carried(self, name: str) -> CarriedPoint | None:
        return next((c for c in self.points if c.name == name), None)

    def slider(self, name: str):
        return next((s for s in self.sliders if s.point == name), None)

    @property
    def length_unit(self) -> float:
        return UNITS["length"][self.units]


# --------------------------------------------------------------------------- loading


def load_scene(path) -> Scene:
    """Read and check a scene file. Raises :class:`SceneError` naming file, key and line."""
    path = Path(path)
    try:
        data = path.read_bytes()
    except FileNotFoundError:
        raise SceneError("no such file", file=str(path)) from None
    except IsADirectoryError:
        raise SceneError("is a directory, not a scene file", file=str(path)) from None
    except OSError as exc:
        raise SceneError(f"cannot read: {exc.strerror}", file=str(path)) from None
    if b"\x00" in data:
        raise SceneError("not a text file (it holds binary data); a scene is TOML text",
                         file=str(path))
    try:
        text = data.decode("utf-8-sig")  # a byte-order mark (some Windows editors) is fine
    except UnicodeDecodeError as exc:
        raise SceneError(f"not UTF-8 text (byte {exc.start}); save the scene as UTF-8",
                         file=str(path)) from None
    try:
        return parse_scene(text, file=str(path))
    except PolygonMethodError as exc:
        raise exc.located(str(path))


def parse_scene(text: str, file: str | None = None) -> Scene:
    """Parse scene text (TOML). See :func:`load_scene`."""
    if not text.strip():
        raise SceneError("the file is empty; a scene needs [ground], [links] and [input]",
                         file=file)
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise _syntax_error(str(exc), text, file) from None
    except RecursionError:
        raise SceneError("TOML nested too deeply (brackets or braces inside each other "
                         "hundreds of times); a scene needs at most [x, y] pairs and small "
                         "tables", file=file, key=_deepest_key(text)) from None
    if not raw:
        raise SceneError("the file has no tables or keys (only comments); a scene needs "
                         "[ground], [links] and [input]", file=file)
    return _Loader(raw, text, file).scene()


#: tomllib's messages, in the words of this tool
_TOML_WORDS = [
    (r"^Unclosed array$", "unclosed array: a ']' is missing"),
    (r"^Unclosed inline table$", "unclosed inline table: a '}' is missing"),
    (r"^Illegal character '\\n'$", "a string is not closed before the end of the line "
     "(a '\"' is missing)"),
    (r"^Expected '\]' at the end of a table declaration$",
     "expected ']' at the end of a table header such as [links]"),
    (r"^Cannot declare \((.*?),?\) twice$", None),
    (r"^Expected newline or end of document after a statement$",
     "expected the end of the line after a value (a missing quote, comma or '=', or two "
     "values on one line?)"),
    (r"^Invalid value$", "invalid value (strings need quotes: \"50 mm\", \"AB\")"),
]


def _syntax_error(msg, text, file) -> SceneError:
    """A TOML decode error as a :class:`SceneError` at its line and column."""
    m = re.search(r"\(at line (\d+), column (\d+)\)", msg)
    core = re.sub(r"\s*\(at (line|end).*?\)", "", msg).strip()
    where = f"line {m.group(1)}, column {m.group(2)}" if m else None
    if core.startswith("Cannot overwrite a value"):
        dup = _duplicate_key(text)
        if dup is not None:
            table, key, first, again = dup
            label = f"[{table}] {key}" if table else key
            return SceneError(f"duplicate key {key} (first given on line {first}); give each "
                              "key once", file=file, key=label, line=again)
    for pattern, words in _TOML_WORDS:
        hit = re.match(pattern, core)
        if hit:
            if words is None:  # a table declared twice
                name = ".".join(part.strip(" '\"") for part in hit.group(1).split(","))
                words = f"[{name}] is declared twice; put all its keys under one header"
            core = words
            break
    else:
        core = core[:1].lower() + core[1:]
    return SceneError(f"TOML syntax error: {core}", file=file, key=where)


def _duplicate_key(text):
    """(table, key, first line, second line) of a key given twice in one table, or None."""
    table, seen = "", {}
    for i, line in enumerate(text.splitlines(), 1):
        head = re.match(r"^\s*\[\s*([^\[\]]+?)\s*\]\s*(#.*)?$", line)
        if head:
            table = head.group(1).strip('"')
            continue
        m = re.match(r"^\s*(\"[^\"]*\"|[A-Za-z0-9_\-]+)\s*=", line)
        if m:
            key = m.group(1).strip('"')
            if (table, key) in seen:
                return table, key, seen[(table, key)], i
            seen[(table, key)] = i
    return None


def _deepest_key(text):
    """The key whose value opens the most brackets on one line (for nesting errors)."""
    best, where = 0, None
    for i, line in enumerate(text.splitlines(), 1):
        m = re.match(r"^\s*([^=\s]+)\s*=", line)
        depth = line.count("[") + line.count("{")
        if m and depth > best:
            best, where = depth, f"{m.group(1).strip(chr(34))} (line {i})"
    return where


def _suggest(word, choices) -> str:
    return did_you_mean(word, list(choices))


def _printable(text):
    """``text`` with line breaks and control characters escaped, so that a message built
    from the file's own names stays one clean line on a terminal.

    >>> print(_printable('A\\nB'), _printable('BC'))
    A\\nB BC
    """
    if text is None or str(text).isprintable():
        return text
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in str(text))


def _which_point(name, known) -> str:
    """A did-you-mean, or else the scene's points, for a message about an unknown point."""
    names = sorted(known, key=lambda p: (p[0], len(p), p))
    hint = _suggest(name, names)
    if hint or not names:
        return hint
    listed = ", ".join(names[:12]) + (", ..." if len(names) > 12 else "")
    return f" (its points are {listed})"


class _Loader:
    def __init__(self, raw: dict, text: str, file):
        self.raw = raw
        self.lines = text.splitlines()
        self.file = file
        self.unit = "mm"

    # -- locations
    def line_of(self, table: str | None, key: str | None = None):
        """Line number of ``[table] key`` (or of the table header) in the file, if found."""
        current = None
        header = re.compile(r"^\s*\[\s*([A-Za-z0-9_.\-\"]+)\s*\]\s*(#.*)?$")
        for i, line in enumerate(self.lines, 1):
            m = header.match(line)
            if m:
                current = m.group(1).strip('"')
                if key is None and current == table:
                    return i
                continue
            if key is not None and current == table:
                if re.match(rf"^\s*\"?{re.escape(key)}\"?\s*=", line):
                    return i
        return None

    def error(self, message, table=None, key=None, cls=SceneError):
        label = f"[{table}] {key}" if table and key else (f"[{table}]" if table else key)
        return cls(_printable(message), file=self.file, key=_printable(label),
                   line=self.line_of(table, key))

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
        q = self.qty(raw, "length", table, key, default_unit=self.unit).value
        if positive and q <= 0:
            raise self.error(f"length must be positive, got {raw!r}", table, key)
        if abs(q) > _ABSURD_LONG or (positive and q < _ABSURD_SHORT):
            raise self.error(f"length {raw!r} ({q:g} m) is absurd for a mechanism; "
                             f"check the units (units = \"{self.unit}\")", table, key)
        return q

    def coords(self, raw, table, key):
        if not (isinstance(raw, list) and len(raw) == 2):
            raise self.error("expected coordinates [x, y]", table, key)
        return tuple(self.length(v, table, key, positive=False) for v in raw)

    def table(self, name, required=False) -> dict:
        value = self.raw.get(name)
        if value is None:
            if required:
                raise SceneError(f"missing [{name}] table", file=self.file, key=f"[{name}]")
            return {}
        if not isinstance(value, dict):
            raise SceneError(f"'{name}' must be a table [{name}]", file=self.file, key=name,
                             line=self.top_line(name))
        return value

    def point_name(self, name, table, key=None):
        if not _POINT_ONLY.match(str(name)):
            raise self.error(f"'{name}' is not a point name (a capital letter, optionally "
                             "followed by digits: A, O2, B1)", table, key or name)
        return name

    # -- the scene
    def scene(self) -> Scene:
        raw = self.raw
        for key in raw:
            if key not in TOP_KEYS:
                kind = "table" if isinstance(raw[key], dict) else "key"
                where = f"[{key}]" if kind == "table" else key
                raise SceneError(f"unknown {kind}{_suggest(key, TOP_KEYS)}; a scene has "
                                 + ", ".join(TOP_KEYS), file=self.file, key=_printable(where),
                                 line=self.line_of(key) if kind == "table" else self.top_line(key))
        units = raw.get("units", "mm")
        if not isinstance(units, str):
            raise SceneError("units is a string: units = \"mm\" (or \"cm\", \"m\", \"in\")",
                             file=self.file, key="units",
                             line=self.top_line("units") or self.line_of("units"))
        if units not in LENGTH_UNITS:
            raise SceneError(f"unknown length unit {units!r}{_suggest(units, _UNIT_ORDER)}; "
                             "use mm, cm, m or in", file=self.file, key="units",
                             line=self.top_line("units"))
        self.unit = units
        title = raw.get("title", "")
        if not isinstance(title, str):
            raise SceneError("title must be a string", file=self.file, key="title")

        ground = {}
        for name, value in self.table("ground", required=True).items():
            self.point_name(name, "ground")
            ground[name] = self.coords(value, "ground", name)
        if not ground:
            raise SceneError("[ground] is empty; give at least the crank's fixed pivot",
                             file=self.file, key="[ground]", line=self.line_of("ground"))

        links, index = [], {}
        for key, value in self.table("links", required=True).items():
            pts = split_name(key)
            if len(pts) != 2:
                raise self.error(f"{key!r} is not a link name: a link is named by its two "
                                 "joint points, e.g. BC or \"O2-A\"", "links", key)
            if pts[0] == pts[1]:
                raise self.error("a link joins two different points", "links", key)
            if isinstance(value, dict):
                raise self.error("a link's value is its length, e.g. BC = 66", "links", key)
            length = self.length(value, "links", key)
            pair = frozenset(pts)
            if pair in index:
                raise self.error(f"duplicate link: {index[pair].key} and {key} join the same "
                                 "points", "links", key)
            link = Link(key, pts[0], pts[1], length)
            index[pair] = link
            links.append(link)
            if pts[0] in ground and pts[1] in ground:
                gx = math.dist(ground[pts[0]], ground[pts[1]])
                if abs(gx - length) > 1e-9 * max(gx, length):
                    raise self.error(f"both ends are ground points {gx / self.scale():g} "
                                     f"{self.unit} apart, but the link is {value}", "links", key)
        if not links:
            raise SceneError("[links] is empty", file=self.file, key="[links]",
                             line=self.line_of("links"))
        self.index = index
        self.ground = ground

        points = self.carried_points(index, ground)
        sliders = self.sliders(index, ground, {p.name for p in points})
        known = set(ground) | {p for lk in links for p in lk.points} | {p.name for p in points}
        self.known = known
        inp = self.input(index, ground)
        sliders = [replace(s, through=ground[inp.pivot])
                   if isinstance(s, FixedPath) and s.through[1] is None else s
                   for s in sliders]
        assembly = self.assembly(known)
        pins = self.pins(known)
        loads = self.loads(known)
        tolerance, answers = self.answers(known, sliders, pins, loads)
        self.connected(links, points, sliders, ground, inp)
        return Scene(title=title, units=units, ground=ground, links=tuple(links),
                     points=tuple(points), sliders=tuple(sliders), assembly=assembly,
                     input=inp, pins=tuple(pins), loads=tuple(loads), answers=tuple(answers),
                     tolerance=tolerance, file=self.file, _link_index=index)

    def scale(self):
        return UNITS["length"][self.unit]

    def find_link(self, name, table, key):
        pts = split_name(name) if isinstance(name, str) else ()
        if len(pts) != 2:
            raise self.error(f"'{name}' is not a link name (two points, e.g. BC)", table, key)
        link = self.index.get(frozenset(pts))
        if link is None:
            raise self.error(f"no link {name} in [links]"
                             f"{_suggest(name, [lk.key for lk in self.index.values()])}",
                             table, key)
        return link, pts

    def carried_points(self, index, ground):
        table = self.table("points")
        local = {}  # link key -> {point: (x, y) in the link frame, P at 0, Q at (L, 0)}
        out = []
        for name, spec in table.items():
            self.point_name(name, "points")
            if name in ground:
                raise self.error(f"{name} is a ground point and a carried point; a point has "
                                 "one role", "points", name)
            if not isinstance(spec, dict) or "on" not in spec:
                raise self.error("a carried point is a table such as { on = \"BC\", along = "
                                 "40 } or { on = \"BC\", distances = { B = 45, C = 30 }, turn "
                                 "= \"cw\" }", "points", name)
            allowed = ("on", "along", "from", "distances", "turn")
            for k in spec:
                if k not in allowed:
                    raise self.error(f"unknown key '{k}'{_suggest(k, allowed)}", "points", name)
            link, pts = self.find_link(spec["on"], "points", name)
            if name in link.points:
                raise self.error(f"{name} is a joint of link {link.key}; it cannot also be "
                                 "carried on it", "points", name)
            frame = local.setdefault(link.key, {link.p: (0.0, 0.0), link.q: (link.length, 0.0)})
            has_along, has_dist = "along" in spec, "distances" in spec
            if has_along == has_dist:
                raise self.error("give either along (with an optional from) or distances "
                                 "with turn", "points", name)
            if has_along:
                start = spec.get("from", pts[0])
                if start not in link.points:
                    raise self.error(f"from = {start!r} is not an end of {link.key}",
                                     "points", name)
                if "turn" in spec:
                    raise self.error("turn goes with distances, not with along", "points", name)
                d = self.length(spec["along"], "points", name, positive=False)
                sx, sy = frame[start]
                ox, oy = frame[link.other(start)]
                t = d / link.length
                xy = (sx + t * (ox - sx), sy + t * (oy - sy))
                how = f"on {spec['on']}, {spec['along']} from {start}"
            else:
                dist = spec["distances"]
                if not isinstance(dist, dict) or len(dist) != 2:
                    raise self.error("distances names two points of the link, e.g. "
                                     "{ B = 45, C = 30 }", "points", name)
                turn = spec.get("turn")
                if turn not in ("cw", "ccw"):
                    raise self.error("turn = \"cw\" or \"ccw\": how the triangle (the two "
                                     "points of distances, then this point) reads", "points",
                                     name)
                (r1, d1), (r2, d2) = dist.items()
                for r in (r1, r2):
                    if r not in frame:
                        raise self.error(f"{r} is not a point of link {link.key}", "points",
                                         name)
                d1 = self.length(d1, "points", name)
                d2 = self.length(d2, "points", name)
                (x1, y1), (x2, y2) = frame[r1], frame[r2]
                e = math.hypot(x2 - x1, y2 - y1)
                u = self.scale()
                if d1 + d2 < e * (1 - 1e-12) or abs(d1 - d2) > e * (1 + 1e-12):
                    if d1 + d2 < e:
                        why = (f"{r1}{name} + {r2}{name} = {(d1 + d2) / u:g} < {r1}{r2} = "
                               f"{e / u:g} {self.unit}")
                    else:
                        why = (f"|{r1}{name} - {r2}{name}| = {abs(d1 - d2) / u:g} > {r1}{r2} = "
                               f"{e / u:g} {self.unit}")
                    raise self.error(f"the triangle {r1}{r2}{name} cannot close: {why}",
                                     "points", name)
                along = (d1 * d1 - d2 * d2 + e * e) / (2 * e)
                h = math.sqrt(max(d1 * d1 - along * along, 0.0))
                ex, ey = (x2 - x1) / e, (y2 - y1) / e
                sign = 1.0 if turn == "ccw" else -1.0
                xy = (x1 + along * ex - sign * h * ey, y1 + along * ey + sign * h * ex)
                how = (f"on {spec['on']}, {r1}{name} = {spec['distances'][r1]}, {r2}{name} = "
                       f"{spec['distances'][r2]}, {r1}{r2}{name} read {turn}")
            frame[name] = xy
            L = link.length
            out.append(CarriedPoint(name, link.key, xy[0] / L, xy[1] / L, how))
        return out

    def sliders(self, index, ground, carried):
        out = []
        for name, spec in self.table("sliders").items():
            self.point_name(name, "sliders")
            if not isinstance(spec, dict):
                raise self.error("a slider is a table: { path = \"horizontal\", through = "
                                 "[x, y] } or { along = \"CP\" }", "sliders", name)
            allowed = ("path", "through", "along")
            for k in spec:
                if k not in allowed:
                    raise self.error(f"unknown key '{k}'{_suggest(k, allowed)}", "sliders", name)
            if "along" in spec:
                if "path" in spec or "through" in spec:
                    raise self.error("a block slides either on a fixed path or along a link, "
                                     "not both", "sliders", name)
                guide = spec["along"]
                if len(split_name(guide)) == 2 and not self.index.get(frozenset(
                        split_name(guide))) and any(p in self.ground
                                                    for p in split_name(guide)):
                    raise self.error(
                        f"the guide {guide} is not in [links]: add it with its length, e.g. "
                        f"\"{guide}\" = 500 (if the problem does not give the lever's length, "
                        "any length will do: it only places the end of the lever)", "sliders", name)
                link, pts = self.find_link(guide, "sliders", name)
                if name in link.points:
                    raise self.error(f"{name} is an end of {link.key}; a block slides along a "
                                     "link between its ends", "sliders", name)
                if all(p in ground for p in pts):
                    raise self.error(f"{link.key} is fixed (both ends are ground points): "
                                     "use path/through for a fixed guide", "sliders", name)
                out.append(GuideSlider(name, link.key, pts[0], pts[1]))
                continue
            if name in ground:
                raise self.error(f"{name} is a ground point; it cannot slide on a fixed path",
                                 "sliders", name)
            if name in carried:
                raise self.error(f"{name} is carried on a link and also slides on a fixed "
                                 "path: one constraint too many", "sliders", name)
            if "path" not in spec:
                raise self.error("the slider's path has no direction: add path = "
                                 "\"horizontal\", \"vertical\" or an angle such as \"30 deg\"",
                                 "sliders", name)
            path = spec["path"]
            if isinstance(path, str) and not re.match(r"^\s*[-+.\d]", path) \
                    and path not in ("horizontal", "vertical"):
                raise self.error(f"path = {path!r}: use \"horizontal\", \"vertical\" or an "
                                 "angle such as \"30 deg\"" + _suggest(path, ("horizontal",
                                                                            "vertical")),
                                 "sliders", name)
            if path == "horizontal":
                ang, label = 0.0, "horizontal"
            elif path == "vertical":
                ang, label = math.pi / 2, "vertical"
            else:
                ang = self.qty(path, "angle", "sliders", name, default_unit="deg").value
                label = f"at {math.degrees(ang):g} deg"
            through = spec.get("through")
            if through is None:
                through = ("input pivot", None)
            elif isinstance(through, str):
                if through not in ground:
                    raise self.error(f"through = {through!r} is not a ground point"
                                     f"{_suggest(through, ground)}", "sliders", name)
                through = ground[through]
            else:
                through = self.coords(through, "sliders", name)
            u = {0.0: (1.0, 0.0), math.pi / 2: (0.0, 1.0)}.get(ang, (math.cos(ang), math.sin(ang)))
            out.append(FixedPath(name, u, through, label))
        return out

    def input(self, index, ground):
        if "input" not in self.raw:
            raise SceneError("missing [input] table: which link is the crank, its angle and "
                             "speed", file=self.file, key="[input]")
        spec = self.table("input")
        for k in spec:
            if k not in INPUT_KEYS:
                raise self.error(f"unknown key{_suggest(k, INPUT_KEYS)}", "input", k)
        for k in ("crank", "angle", "speed"):
            if k not in spec:
                example = {"crank": "crank = \"AB\"", "angle": "angle = 60",
                           "speed": "speed = \"10 rad/s ccw\""}[k]
                raise self.error(f"[input] has no {k}: add e.g. {example}", "input")
        link, pts = self.find_link(spec["crank"], "input", "crank")
        on_ground = [p for p in pts if p in ground]
        if not on_ground:
            raise self.error(f"crank {link.key} is not pinned to the ground: neither "
                             f"{pts[0]} nor {pts[1]} is in [ground]", "input", "crank")
        if len(on_ground) == 2:
            raise self.error(f"crank {link.key} has both ends in [ground]; it cannot turn",
                             "input", "crank")
        pivot = on_ground[0]
        tip = link.other(pivot)
        angle = self.qty(spec["angle"], "angle", "input", "angle", default_unit="deg").value
        speed = self.qty(spec["speed"], "angular_velocity", "input", "speed", need_sense=True)
        acc = spec.get("acceleration", 0)
        if isinstance(acc, (int, float)) and not isinstance(acc, bool) and acc == 0:
            alpha = 0.0
        else:
            alpha = self.qty(acc, "angular_acceleration", "input", "acceleration",
                             need_sense=True).value
        if speed.value == 0:
            raise self.error("the crank speed is zero: nothing moves", "input", "speed")
        return Input(link.key, pivot, tip, angle, speed.value, alpha, str(spec["speed"]))

    def assembly(self, known):
        out = {}
        for name, hint in self.table("assembly").items():
            if name not in known:
                raise self.error(f"no point {name} in the scene{_which_point(name, known)}",
                                 "assembly", name)
            if isinstance(hint, str):
                if hint not in ("above", "below", "left", "right"):
                    raise self.error(f"{hint!r}: use above, below, left, right or a rough "
                                     "position [x, y]", "assembly", name)
                out[name] = hint
            else:
                out[name] = self.coords(hint, "assembly", name)
        return out

    def pins(self, known):
        out = []
        for name, spec in self.table("pins").items():
            if name not in known:
                raise self.error(f"no point {name} in the scene{_which_point(name, known)}",
                                 "pins", name)
            if not isinstance(spec, dict) or len(spec) != 1 or \
                    next(iter(spec)) not in ("diameter", "radius"):
                raise self.error("a pin is { diameter = 30 } or { radius = 15 }", "pins", name)
            (k, v), = spec.items()
            size = self.length(v, "pins", name)
            out.append(Pin(name, size / 2 if k == "diameter" else size, k))
        return out

    def loads(self, known):
        out = []
        for name, spec in self.table("loads").items():
            if not isinstance(spec, dict):
                raise self.error("a load is { force = \"2 kN\", direction = 0 }, { force = "
                                 "[Fx, Fy] } or, on a link, { torque = \"20 N m cw\" }",
                                 "loads", name)
            allowed = ("force", "direction", "torque")
            for k in spec:
                if k not in allowed:
                    raise self.error(f"unknown key '{k}'{_suggest(k, allowed)}", "loads", name)
            if "torque" in spec:
                if not self.index.get(frozenset(split_name(name))):
                    raise self.error(f"a torque acts on a link; no link {name} in [links]",
                                     "loads", name)
                t = self.qty(spec["torque"], "torque", "loads", name, need_sense=True).value
                out.append(Load(self.index[frozenset(split_name(name))].key, torque=t))
                continue
            if name not in known:
                raise self.error(f"load on unknown point {name}{_which_point(name, known)}",
                                 "loads", name)
            f = spec.get("force")
            if f is None:
                raise self.error("a load needs force", "loads", name)
            if isinstance(f, list):
                if len(f) != 2 or "direction" in spec:
                    raise self.error("force = [Fx, Fy] in N (no direction with a vector)",
                                     "loads", name)
                fx, fy = (self.qty(c, "force", "loads", name, default_unit="N").value
                          for c in f)
            else:
                mag = self.qty(f, "force", "loads", name, default_unit="N").value
                if "direction" not in spec:
                    raise self.error("a force needs a direction (deg, ccw from +x)",
                                     "loads", name)
                ang = self.qty(spec["direction"], "angle", "loads", name,
                               default_unit="deg").value
                fx, fy = mag * math.cos(ang), mag * math.sin(ang)
            out.append(Load(name, force=(fx, fy)))
        return out

    def answers(self, known, sliders, pins, loads):
        spec = self.table("answers")
        tolerance = None
        out = []
        slider_names = {s.point for s in sliders}
        pin_names = {p.point for p in pins}
        for key, value in spec.items():
            if key == "tolerance":
                q = self.qty(value, "percent", "answers", key, default_unit="%").value
                if not 0 < q < 1:
                    raise self.error(f"tolerance {value!r} must be between 0 and 100 %",
                                     "answers", key)
                tolerance = q
                continue
            out.append(self.answer(key, value, known, slider_names, pin_names, loads))
        return tolerance, out

    def answer(self, key, value, known, slider_names, pin_names, loads):
        line = self.line_of("answers", key)
        if key == "torque":
            if not loads:
                raise self.error("a torque answer needs [loads] to balance", "answers", key)
            q = self.qty(value, "torque", "answers", key, default_unit="N m", allow_sense=True)
            return Answer(key, "torque", (), q.value, q.sense, str(value), line)
        prefix, _, rest = key.partition("_")
        if prefix not in ANSWER_KINDS or not rest:
            examples = ["v_C", "a_C", "v_CB", "omega_BC", "alpha_BC", "vs_D", "as_D", "ac_A",
                        "rub_B", "torque"]
            raise self.error(f"unknown answer key{_suggest(key, examples)}; keys are v_X, "
                             "a_X, v_XY, a_XY, omega_L, alpha_L, vs_X, as_X, ac_X, rub_X, "
                             "torque", "answers", key)
        kind, what, sense_ok = ANSWER_KINDS[prefix]
        names = split_name(rest)
        if not names:
            raise self.error(f"'{rest}' is not a point or link name", "answers", key)
        if what == "point":
            if len(names) > 2:
                raise self.error("v_X or v_XY: one or two points", "answers", key)
            for n in names:
                if n not in known:
                    raise self.error(f"no point {n} in the scene{_which_point(n, known)}",
                                     "answers", key)
        elif what == "link":
            if len(names) != 2 or frozenset(names) not in self.index:
                raise self.error(f"no link {rest} in [links]"
                                 f"{_suggest(rest, [lk.key for lk in self.index.values()])}",
                                 "answers", key)
        elif what == "slider":
            if len(names) != 1 or names[0] not in slider_names:
                raise self.error(f"no slider {rest} in [sliders]", "answers", key)
        elif what == "pin":
            if len(names) != 1 or names[0] not in pin_names:
                raise self.error(f"rubbing at {rest} needs its size in [pins]", "answers", key)
        q = self.qty(value, kind, "answers", key, default_unit=next(iter(UNITS[kind])),
                     allow_sense=sense_ok)
        return Answer(key, prefix, names, q.value, q.sense, str(value), line)

    def connected(self, links, points, sliders, ground, inp):
        """Every point must take part: a dangling point is almost always a typo."""
        uses = {}
        for lk in links:
            for p in lk.points:
                uses[p] = uses.get(p, 0) + 1
        roles = set(ground) | {p.name for p in points} | {s.point for s in sliders}
        roles |= {p for s in sliders if isinstance(s, GuideSlider) for p in (s.first, s.second)}
        plates = {p.link for p in points}  # a link carrying points is a plate: its ends belong
        roles |= {q for lk in links if lk.key in plates for q in lk.points}
        through = {s.through for s in sliders if isinstance(s, FixedPath)}
        lonely = [name for name, xy in ground.items()
                  if name not in uses and xy not in through and name != inp.pivot
                  and name not in {s.point for s in sliders}]
        for lk in links:
            for p in lk.points:
                if uses[p] == 1 and p not in roles:
                    other = lk.other(p)
                    guess = [f"{other}{g}" if len(other) == len(g) == 1 else f"{other}-{g}"
                             for g in lonely]
                    hint = (f" (did you mean {guess[0]}? ground point {lonely[0]} is joined to "
                            "nothing)") if guess else ""
                    raise self.error(f"point {p} appears only in link {lk.key} and nowhere "
                                     f"else: nothing holds it (a typo?){hint}", "links", lk.key)
        if lonely:
            name = lonely[0]
            raise SceneError(f"ground point {name} is not joined to any link: add its link "
                             "or remove it", file=self.file, key=f"[ground] {name}",
                             line=self.line_of("ground", name))


# --------------------------------------------------------------------------- answer files

_ANSWER_FILE_KEYS = ("answers", "title", "student", "name", "notes", "source")


def parse_answers(text: str, scene: Scene, file: str | None = None):
    """Read an answer file (an ``[answers]`` table, e.g. a student's) against ``scene``.

    Keys and values follow the scene's ``[answers]`` rules. Returns
    ``(tolerance or None, tuple of Answer)``; raises :class:`SceneError` naming the key.
    """
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        m = re.search(r"\(at line (\d+), column (\d+)\)", str(exc))
        core = re.sub(r"\s*\(at line.*?\)", "", str(exc)).strip()
        raise SceneError(f"TOML syntax error: {core}", file=file,
                         key=f"line {m.group(1)}, column {m.group(2)}" if m else None) from None
    for key in raw:
        if key not in _ANSWER_FILE_KEYS:
            raise SceneError("an answer file holds an [answers] table (and optionally title, "
                             f"student){_suggest(key, _ANSWER_FILE_KEYS)}", file=file, key=key)
    if not isinstance(raw.get("answers"), dict) or not raw["answers"]:
        raise SceneError("no [answers] table (or it is empty)", file=file, key="[answers]")
    loader = _Loader(raw, text, file)
    loader.unit = scene.units
    loader.index = scene._link_index
    tolerance, answers = loader.answers(set(scene.point_names), scene.sliders, scene.pins,
                                        scene.loads)
    return tolerance, tuple(answers)


def load_answers(path, scene: Scene):
    """Read an answer file from ``path``; see :func:`parse_answers`."""
    path = Path(path)
    try:
        data = path.read_bytes()
        text = data.decode("utf-8")
    except FileNotFoundError:
        raise SceneError("no such file", file=str(path)) from None
    except IsADirectoryError:
        raise SceneError("is a directory, not an answer file", file=str(path)) from None
    except UnicodeDecodeError as exc:
        raise SceneError(f"not UTF-8 text (byte {exc.start})", file=str(path)) from None
    except OSError as exc:
        raise SceneError(f"cannot read: {exc.strerror}", file=str(path)) from None
    if "\x00" in text:
        raise SceneError("not a text file (it holds binary data)", file=str(path))
    try:
        return parse_answers(text, scene, file=str(path))
    except PolygonMethodError as exc:
        raise exc.located(str(path))
