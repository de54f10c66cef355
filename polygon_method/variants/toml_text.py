"""A scene's table written back as TOML text (the variants' scene files): the few types a
scene holds, strings with JSON's escapes (which are TOML's), a header as comments.

>>> print(dump_toml({"title": "a", "links": {"AB": "50 mm", "B C": [1, 2.5]}}, "one"), end="")
# one
title = "a"
<BLANKLINE>
[links]
AB = "50 mm"
"B C" = [1, 2.5]
"""

from __future__ import annotations

import json
import re

from ..common.errors import printable

__all__ = ["dump_toml"]

_BARE = re.compile(r"^[A-Za-z0-9_-]+$")


def _string(text: str) -> str:
    """``text`` as a TOML basic string: JSON's escapes are TOML's, save that TOML also
    wants DEL escaped."""
    return json.dumps(text, ensure_ascii=False).replace("\x7f", "\\u007f")


def _key(k) -> str:
    return k if _BARE.fullmatch(k) else _string(k)


def _value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return repr(v)
    if isinstance(v, str):
        return _string(v)
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + " }"
    raise TypeError(f"cannot write {type(v).__name__} as TOML")


def dump_toml(raw: dict, header: str = "") -> str:
    """A scene's table as TOML text: top-level keys first, then one ``[table]`` each."""
    # a comment holds no control character (a title may: it is shown escaped here)
    out = [f"# {printable(line)}" if line else "#" for line in header.split("\n")]
    for k, v in raw.items():
        if not isinstance(v, dict):
            out.append(f"{_key(k)} = {_value(v)}")
    for k, v in raw.items():
        if isinstance(v, dict):
            out.append("")
            out.append(f"[{_key(k)}]")
            out.extend(f"{_key(kk)} = {_value(vv)}" for kk, vv in v.items())
    return "\n".join(out) + "\n"
