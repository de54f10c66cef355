"""The ``[variants]`` table of a turning-moment diagram's scene (a part of
:mod:`polygon_method.scene.energy`'s reader): what a teacher lets vary from student to
student. Each key names one of the scene's tables (``turning_moment``, ``press``,
``flywheel``) and holds, for keys that table states, a list of values as the scene would
write them or a range ``{ from, to, step }`` (optional ``unit``):

.. code-block:: toml

    [variants]
    flywheel = { speed = ["250 rpm", "300 rpm"], plus_minus = ["1%", "1.5%"] }
    turning_moment = { torque_scale = ["1 mm = 60 N m", "1 mm = 70 N m"] }
    press = { holes_per_minute = { from = 10, to = 15, step = 1 } }

Every value is checked as the scene's own would be (the scene read again with it in place):
one that would not read is one line naming ``[variants] TABLE`` and its line.
"""

from __future__ import annotations

import copy
from dataclasses import dataclass

from ..common.errors import PolygonMethodError, SceneError
from ..common.units import did_you_mean

__all__ = ["CycleVaried", "read_cycle_variation", "VARIED_TABLES"]

#: the tables whose keys may vary
VARIED_TABLES = ("turning_moment", "press", "flywheel")


@dataclass(frozen=True)
class CycleVaried:
    """One varied key: ``table`` and ``key`` (where its value goes), the distinct
    ``values`` as the scene writes them, and each ``shown`` as text."""

    table: str
    key: str
    values: tuple
    shown: tuple

    @property
    def name(self) -> str:
        """``flywheel.speed``: the key as the answer key's columns name it."""
        return f"{self.table}.{self.key}"

    def __len__(self):
        return len(self.values)


def _shown(v) -> str:
    if isinstance(v, list):
        return "[" + ", ".join(_shown(x) for x in v) + "]"
    return v if isinstance(v, str) else f"{v:g}"


def read_cycle_variation(ld, parse) -> tuple:
    """The :class:`CycleVaried` keys of a diagram's scene (``ld``: the reader's loader,
    ``parse``: reads a scene's raw table, raising a :class:`SceneError` where it would not
    read); ``()`` where the scene has no ``[variants]``."""
    raw = ld.raw
    if "variants" not in raw:
        return ()
    spec = raw["variants"]
    if not isinstance(spec, dict) or not spec:
        raise SceneError(
            "[variants] names the tables whose keys vary: flywheel = { speed = "
            '["250 rpm", "300 rpm"] }',
            file=ld.file,
            key="[variants]",
            line=ld.line_of("variants"),
        )
    out = []
    for table, keys in spec.items():
        if table not in VARIED_TABLES:
            raise ld.error(
                f"unknown table '{table}'{did_you_mean(table, list(VARIED_TABLES))}; a "
                "turning-moment diagram's variants vary the keys of " + ", ".join(VARIED_TABLES),
                "variants",
                table,
            )
        stated = raw.get(table)
        if not isinstance(stated, dict):
            raise ld.error(f"the scene has no [{table}] to vary", "variants", table)
        if not isinstance(keys, dict) or not keys:
            raise ld.error(
                f"{table} = {{ KEY = [values] }}: the keys of [{table}] that vary, e.g. "
                'speed = ["250 rpm", "300 rpm"]',
                "variants",
                table,
            )
        for key, values in keys.items():
            out.append(_varied(ld, parse, table, key, values, stated))
    return tuple(out)


def _varied(ld, parse, table, key, values, stated) -> CycleVaried:
    where = f"{table}.{key}"
    if key not in stated:
        raise ld.error(
            f"{where}: the scene's [{table}] does not give {key}{did_you_mean(key, list(stated))}; "
            "vary what it states",
            "variants",
            table,
        )
    if isinstance(values, dict):
        base = stated[key]
        unit = "" if isinstance(base, (int, float)) and not isinstance(base, bool) else None
        values = ld._range(where, values, unit, table)
    if not isinstance(values, list) or not values:
        raise ld.error(
            f"{where}: a list of values as the scene writes them, or a range "
            "{ from = 10, to = 15, step = 1 } (optional unit)",
            "variants",
            table,
        )
    from .variation import MAX_VALUES

    if len(values) > MAX_VALUES:
        raise ld.error(f"{where}: more than {MAX_VALUES} values", "variants", table)
    kept, seen = [], set()
    for v in values:
        trial = copy.deepcopy({k: x for k, x in ld.raw.items() if k != "variants"})
        trial[table][key] = v
        try:
            parse(trial)
        except PolygonMethodError as exc:
            raise ld.error(f"{where} = {_shown(v)}: {exc.message}", "variants", table) from None
        mark = repr(v)
        if mark not in seen:
            seen.add(mark)
            kept.append(v)
    return CycleVaried(table, key, tuple(kept), tuple(_shown(v) for v in kept))
