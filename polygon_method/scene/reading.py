"""Reading a scene: TOML text (or a file) checked table by table into a :class:`Scene`,
every failure one :class:`SceneError` naming the file, key and line."""

from __future__ import annotations

import functools
import math
import os
import re
import stat
import tomllib
from dataclasses import replace
from pathlib import Path

from ..common.errors import PolygonMethodError, SceneError, printable
from ..common.tolerances import SAME
from ..common.typography import long_integer_text
from ..common.units import LENGTH_UNITS, UNITS, parse_quantity
from .rolling import read_rolling
from .source import (
    LineIndex,
    deepest_key,
    has_long_run,
    key_line,  # noqa: F401
    line_of,  # noqa: F401
    long_integer,
    printable_text,
    syntax_error,
    toml_lines,
    toml_table,
)
from .source import has_long_run as _has_long_run  # noqa: F401  (its old name)
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
from .tables import _suggest, _Tables
from .variation import _Variants
from .connected import _Connected
from .cylinder_loads import _CylinderLoads

_TOP_KEYS = frozenset(TOP_KEYS)
#: the most a scene file may hold: a scene is a page of text (``/dev/zero`` is not read on)
MAX_SCENE_BYTES = 1 << 20
#: the most points a scene may have (a textbook's mechanism has a few dozen; a long chain
#: of dyads for studying how rounding grows has thousands: the chain of 10,001 links that
#: measures planning time has 10,002)
MAX_POINTS = 20000


def load_scene(path, *, variants: bool = True, answers: bool = True) -> Scene:
    """Read and check a scene file. Raises :class:`SceneError` naming file, key and line.
    With ``variants=False`` the ``[variants]`` table is left unread (``scene.variation``
    is None): for a command that makes no variants, which need not pay for reading it.
    With ``answers=False`` the ``[answers]`` table is left unread (``scene.answers`` is
    empty, ``scene.tolerance`` None): for a command that checks no answers. A file that
    states a turning-moment diagram with no mechanism (``[turning_moment]`` or ``[press]``)
    is refused in one line naming :func:`polygon_method.load_cycle`, its reader."""
    path, text = scene_text(path)
    try:
        return parse_scene(text, file=str(path), variants=variants, answers=answers)
    except PolygonMethodError as exc:
        raise exc.located(str(path))


def scene_text(path) -> tuple:
    """``(path, text)`` of a scene file: its bytes read (at most ``MAX_SCENE_BYTES``; a
    named pipe without waiting for ever), refused in one line where they are not UTF-8
    text. Shared by :func:`load_scene` and :func:`polygon_method.scene.energy.load_cycle`."""
    path = _path_of(path, "scene")
    try:
        data = _read_start(path)
    except FileNotFoundError:
        raise SceneError("no such file", file=str(path)) from None
    except IsADirectoryError:
        raise SceneError("is a directory, not a scene file", file=str(path)) from None
    except OSError as exc:
        raise SceneError(f"cannot read: {exc.strerror}", file=str(path)) from None
    if len(data) > MAX_SCENE_BYTES:
        raise SceneError(
            f"larger than {MAX_SCENE_BYTES >> 20} MiB: not a scene file (a "
            "scene is a page of TOML text)",
            file=str(path),
        )
    if b"\x00" in data:
        raise SceneError(
            "not a text file (it holds binary data); a scene is TOML text", file=str(path)
        )
    try:
        text = data.decode("utf-8-sig")  # a byte-order mark (some Windows editors) is fine
    except UnicodeDecodeError as exc:
        raise SceneError(
            f"not UTF-8 text (byte {exc.start}); save the scene as UTF-8", file=str(path)
        ) from None
    return path, text


def _read_start(path) -> bytes:
    """The first ``MAX_SCENE_BYTES + 1`` bytes of ``path``. A named pipe is opened without
    waiting for a writer (a plain open would wait for ever where none comes): what a writer
    has put in is read, and a pipe that nobody writes into reads as empty."""
    flags = os.O_RDONLY | getattr(os, "O_NONBLOCK", 0) | getattr(os, "O_BINARY", 0)
    fd = os.open(path, flags)
    try:
        if hasattr(os, "set_blocking"):
            os.set_blocking(fd, True)  # then read as any file: to the end, or the limit
        fh = os.fdopen(fd, "rb")
    except BaseException:
        os.close(fd)
        raise
    with fh:
        data = fh.read(MAX_SCENE_BYTES + 1)
        if not data and stat.S_ISFIFO(os.fstat(fh.fileno()).st_mode):
            raise SceneError(
                "a named pipe that nothing is writing into: nothing to read "
                "(start its writer first, or give the file itself)",
                file=str(path),
            )
        return data


def _path_of(path, what) -> Path:
    """``path`` as a :class:`Path`, or a :class:`SceneError` for what names no file (None,
    a number, an empty name, a NUL byte)."""
    if isinstance(path, bytes):
        path = os.fsdecode(path)
    if not isinstance(path, (str, os.PathLike)):
        raise SceneError(
            f"a {what} file's path is needed (a str or a Path), not {type(path).__name__}"
        )
    if not str(path).strip():
        raise SceneError(f"an empty file name: name the {what} file")
    if "\x00" in str(path):
        raise SceneError(f"a file name cannot hold a NUL byte: {printable(str(path))}")
    return Path(path)


def parse_scene(
    text: str, file: str | None = None, *, variants: bool = True, answers: bool = True
) -> Scene:
    """Parse scene text (TOML). See :func:`load_scene`."""
    if isinstance(text, (bytes, bytearray)):
        raise SceneError(
            "the scene's text is needed as a str: decode the bytes (UTF-8), or "
            "give the file to load_scene",
            file=file,
        )
    if not isinstance(text, str):
        raise SceneError(
            f"the scene's text (TOML) is needed as a str, not "
            f"{type(text).__name__}; load_scene reads a file",
            file=file,
        )
    if not text.strip():
        raise SceneError(
            "the file is empty; a scene needs [ground], [links] and [input]", file=file
        )
    try:
        raw = toml_table(text)
    except tomllib.TOMLDecodeError as exc:
        raise syntax_error(str(exc), text, file) from None
    except RecursionError:
        raise SceneError(
            "TOML nested too deeply (brackets or braces inside each other "
            "hundreds of times); a scene needs at most [x, y] pairs and small "
            "tables",
            file=file,
            key=deepest_key(text),
        ) from None
    if not raw:
        raise SceneError(
            "the file has no tables or keys (only comments); a scene needs "
            "[ground], [links] and [input]",
            file=file,
        )
    loader = _Loader(raw, text, file)
    loader.read_variants = variants
    loader.read_answers = answers
    return loader.scene()


def scene_table(scene: Scene) -> dict:
    """The TOML table a scene was read from (its text parsed again), for making variants
    of it; empty for a scene not read from text."""
    return toml_table("\n".join(toml_lines(scene._text))) if scene._text else {}


def scene_from_table(raw: dict, file: str | None = None) -> Scene:
    """A scene from a TOML table already parsed (checked exactly as a file's would be; the
    messages name no line)."""
    return _Loader(raw, "", file).scene()


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
                "followed by digits: A, O2, B1)",
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
        raw = self.raw
        self.check_integers()
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

        links, index = [], {}
        for key, value in self.table("links", required=True).items():
            pts = split_name(key)
            if len(pts) != 2:
                raise self.error(
                    f"{key!r} is not a link name: a link is named by its two "
                    'joint points, e.g. BC or "O2-A"',
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
        if not links:
            raise SceneError(
                "[links] is empty", file=self.file, key="[links]", line=self.line_of("links")
            )
        self.index = index
        self.ground = ground

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
        assembly = self.assembly(known)
        hint = getattr(self, "collar_hint", None)  # a driving collar placed by [x, y]
        if hint is not None:
            assembly.setdefault(*hint)
        pins = self.pins(known)
        loads = self.loads(known)
        cylinders = self.cylinder_loads(cylinders, inp)  # a force given in a passive one
        masses, gravity = self.masses(points, sliders), self.gravity()
        friction = self.friction(pins)
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

    def scale(self):
        return UNITS["length"][self.unit]

    def find_link(self, name, table, key):
        pts = split_name(name) if isinstance(name, str) else ()
        if len(pts) != 2:
            raise self.error(f"'{name}' is not a link name (two points, e.g. BC)", table, key)
        link = self.index.get(frozenset(pts))
        if link is None:
            wheel = f" (a wheel is a link too: {name} = its radius)" if table == "rolling" else ""
            raise self.error(
                f"no link {name} in [links]"
                f"{_suggest(name, [lk.key for lk in self.index.values()]) or wheel}",
                table,
                key,
            )
        return link, pts


# --------------------------------------------------------------------------- answer files

_ANSWER_FILE_KEYS = ("answers", "title", "student", "name", "notes", "source", "variant")


def parse_answers(
    text: str,
    scene: Scene,
    file: str | None = None,
    *,
    with_variant: bool = False,
    with_student: bool = False,
):
    """Read an answer file (an ``[answers]`` table, e.g. a student's) against ``scene``.

    Keys and values follow the scene's ``[answers]`` rules. Returns
    ``(tolerance or None, tuple of Answer)``, and with ``with_variant`` the variant the
    file names (``variant = "07"``, a number, or a variant's file name; None if it names
    none) as a third item, and with ``with_student`` the student's name the file gives
    (``student = "A. Student"``, or ``name``; None if it gives none) after it; raises
    :class:`SceneError` naming the key.
    """
    if not isinstance(text, str):
        raise SceneError(
            f"the answer file's text (TOML) is needed as a str, not {type(text).__name__}",
            file=file,
        )
    if not isinstance(scene, Scene):
        raise SceneError(
            f"a Scene is needed to read answers against, not {type(scene).__name__}", file=file
        )
    try:
        raw = toml_table(text)
    except tomllib.TOMLDecodeError as exc:
        raise syntax_error(str(exc), text, file) from None
    except RecursionError:
        raise SceneError(
            "TOML nested too deeply (brackets or braces inside each other "
            'hundreds of times); an answer file needs only key = "value" '
            "lines",
            file=file,
            key=deepest_key(text),
        ) from None
    scene_tables = [k for k in ("ground", "links", "input") if isinstance(raw.get(k), dict)]
    if scene_tables:  # the scene itself, or another, given as the answers
        raise SceneError(
            f"this is a scene (it has [{scene_tables[0]}]), not an answer file: an answer "
            "file holds an [answers] table (and optionally title, student)",
            file=file,
            key=f"[{scene_tables[0]}]",
        )
    for key in raw:
        if key not in _ANSWER_FILE_KEYS:
            raise SceneError(
                "an answer file holds an [answers] table (and optionally title, "
                f"student){_suggest(key, _ANSWER_FILE_KEYS)}",
                file=file,
                key=key,
            )
    if not isinstance(raw.get("answers"), dict) or not raw["answers"]:
        raise SceneError("no [answers] table (or it is empty)", file=file, key="[answers]")
    loader = _Loader(raw, text, file)
    loader.check_integers()
    loader.unit = scene.units
    loader.index = scene._link_index
    loader.cylinder_list = scene.cylinders
    loader.two_inputs = scene.input.second is not None
    loader.scene_forces = scene.has_forces
    loader.driving_block = scene.input.block
    loader.driving_wheel = scene.input.wheel
    loader.rolling_pairs = scene.rolling
    loader.ground = scene.ground
    tolerance, answers = loader.answers(
        set(scene.point_names), scene.sliders, scene.pins, scene.loads
    )
    student = None
    for key in ("student", "name"):
        if key in raw and student is None:
            if not isinstance(raw[key], str) or not raw[key].strip():
                raise SceneError(
                    f'{key} is the student\'s name, a string: {key} = "A. Student"',
                    file=file,
                    key=key,
                    line=loader.top_line(key),
                )
            student = " ".join(raw[key].split())
    if not with_variant:
        return (tolerance, tuple(answers)) + ((student,) if with_student else ())
    variant = raw.get("variant")
    if isinstance(variant, int) and not isinstance(variant, bool):
        variant = f"{variant:02d}"
    if variant is not None and (not isinstance(variant, str) or not variant.strip()):
        raise SceneError(
            'variant names the student\'s variant: variant = "07" (or its '
            'file name, "variant-07.toml")',
            file=file,
            key="variant",
            line=loader.top_line("variant"),
        )
    return (tolerance, tuple(answers), (variant.strip() if variant else None)) + (
        (student,) if with_student else ()
    )


def load_answers(path, scene: Scene, *, with_variant: bool = False, with_student: bool = False):
    """Read an answer file from ``path``; see :func:`parse_answers`."""
    path = _path_of(path, "answer")
    try:
        data = _read_start(path)
        if len(data) > MAX_SCENE_BYTES:
            raise SceneError(
                f"larger than {MAX_SCENE_BYTES >> 20} MiB: not an answer file", file=str(path)
            )
        text = data.decode("utf-8-sig")  # a byte-order mark is fine, as in a scene
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
        return parse_answers(
            text, scene, file=str(path), with_variant=with_variant, with_student=with_student
        )
    except PolygonMethodError as exc:
        raise exc.located(str(path))
