"""A scene's text: its TOML read (a compiled reader where it reads it, ``tomllib`` where it
does not), tomllib's messages in this tool's words, and where each key stands (its line),
found in one pass; the integers too long for the scene's numbers found without reading them."""

from __future__ import annotations

import re
import tomllib

from ..common.errors import SceneError
from ..common.typography import character_words

try:  # a compiled TOML reader held to TOML 1.0, as tomllib is: a scene in a fortieth of its time
    from toml_rs import loads as _toml_rs
except ImportError:  # pragma: no cover - rtoml, or the pure-Python reader, does it all
    _toml_rs = None
try:  # a compiled reader with a nesting limit of its own: for the texts of many brackets
    from rtoml import loads as _rtoml
except ImportError:  # pragma: no cover
    _rtoml = None

#: the most brackets (``[`` and ``{``) a text that ``toml_rs`` reads may hold: it goes one
#: level deeper on its stack for each level of nesting and has no limit of its own (a text
#: nested some thousands deep ends the process), so a text that could be nested deeper
#: (a scene of hundreds of points) is read by ``rtoml``, which stops at a depth of its own
NESTING_SAFE = 512


def _compiled(text: str) -> dict:
    """The table of ``text`` read by a compiled reader, or an exception where it refuses
    it (or none is installed)."""
    if _toml_rs is not None and _scanned(text).count(b"[") <= NESTING_SAFE:
        return _toml_rs(text, toml_version="1.0.0")
    if _rtoml is not None:
        return _rtoml(text)
    raise ImportError("no compiled TOML reader")


#: the compiled readers, None where tomllib is to read every text (as a test has it)
_fast_toml = _compiled if _toml_rs is not None or _rtoml is not None else None


__all__ = [
    "toml_table",
    "toml_lines",
    "LineIndex",
    "line_of",
    "key_line",
    "syntax_error",
    "duplicate_key",
    "deepest_key",
    "printable_text",
    "has_long_run",
    "long_integer",
]


def toml_table(text: str) -> dict:
    """The TOML table of ``text``: read by a compiled reader where it reads it, else by
    ``tomllib``, whose errors (:class:`tomllib.TOMLDecodeError`, ``RecursionError``) are
    the ones this module words. The compiled reader (``toml_rs``, held to TOML 1.0; for a
    text of more than :data:`NESTING_SAFE` brackets ``rtoml``) is tried first for speed
    only: where it refuses a text (too deep, a float past the largest, bad syntax, a
    byte-order mark, which tomllib refuses too) tomllib reads the text again, so every text
    tomllib reads gives the same table, and every text it refuses is refused in the same
    words; ``rtoml``, for a text of many brackets, also reads what TOML 1.1 added (a
    newline or a trailing comma in an inline table, ``\\e`` and ``\\xHH`` escapes, times
    without seconds) and gives a date's time zone as a class of its own.

    >>> toml_table("a = 1\\n[b]\\nc = 'x'")
    {'a': 1, 'b': {'c': 'x'}}
    >>> toml_table('a = 9223372036854775808')   # past 64 bits: read (refused later)
    {'a': 9223372036854775808}
    """
    if _fast_toml is not None and text[:1] != "\ufeff":  # (a mark: tomllib refuses it)
        try:
            return _fast_toml(text)
        except Exception:  # noqa: BLE001 - any refusal: tomllib reads it, or words why not
            pass
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError:
        raise
    except ValueError:  # int() refuses an integer of thousands of digits: where is it?
        raise tomllib.TOMLDecodeError(_too_many_digits(text)) from None


_LONG_DIGITS = re.compile(r"\d[\d_]{4000,}")


def _too_many_digits(text: str) -> str:
    """A decode error's words for an integer too long for ``int`` to read (thousands of
    digits), at its line and column as tomllib gives them.

    >>> _too_many_digits("a = 1\\nb = " + "1" * 5000)
    'An integer of 5000 digits: absurd for a mechanism; check the value and its unit (at line 2, column 5)'
    """
    m = _LONG_DIGITS.search(text)
    if m is None:
        return "Invalid value"
    line = text.count("\n", 0, m.start()) + 1
    column = m.start() - text.rfind("\n", 0, m.start())
    digits = sum(c.isdigit() for c in m.group(0))
    return (
        f"An integer of {digits} digits: absurd for a mechanism; check the value and its "
        f"unit (at line {line}, column {column})"
    )


def toml_lines(text: str) -> list:
    """The lines of a TOML text as TOML counts them: split at line feeds only (not at the
    form feeds, U+2028 and other breaks that ``str.splitlines`` also splits at, which a
    string or a comment may hold)."""
    lines = text.split("\n")
    if "\r" not in text:  # (the usual file: nothing to take off)
        return lines
    return [line[:-1] if line.endswith("\r") else line for line in lines]


#: tomllib's messages, in the words of this tool
_TOML_WORDS = [
    (r"^Unclosed array$", "unclosed array: a ']' is missing"),
    (r"^Unclosed inline table$", "unclosed inline table: a '}' is missing"),
    (
        r"^Illegal character '\\n'$",
        "a string is not closed before the end of the line (a '\"' is missing)",
    ),
    (
        r"^Expected '\]' at the end of a table declaration$",
        "expected ']' at the end of a table header such as [links]",
    ),
    (r"^Cannot declare \((.*?),?\) twice$", None),
    (
        r"^Expected newline or end of document after a statement$",
        "expected the end of the line after a value (a missing quote, comma or '=', or two "
        "values on one line?)",
    ),
    (r"^Invalid value$", 'invalid value (strings need quotes: "50 mm", "AB")'),
]


_HEADER = re.compile(r"^\s*\[\s*([A-Za-z0-9_.\-\"]+)\s*\]\s*(#.*)?$")


def _unquoted(name):
    """A key as written before its ``=``, without the spaces after it and one quote on each
    side."""
    name = name.rstrip()
    if name.startswith('"'):
        name = name[1:]
    return name[:-1] if name.endswith('"') else name


class LineIndex:
    """Every ``[table] key``'s line in one pass over the lines (the first key line of the
    table's section, else the first dotted ``table.key =`` line; a header's own line for
    ``key=None``), for a reader that asks for many: the lines of a scene's answers.

    >>> ix = LineIndex(['a = 1', '[t]', 'k = 2', '"O-R" = {x = 1}', 'u.w = 3', '[t.v]', 'k = 4'])
    >>> ix('t', 'k'), ix('t', 'O-R'), ix('t', None), ix(None, 'a'), ix('u', 'w'), ix('t', 'z')
    (3, 4, 2, 1, 5, None)
    >>> ix('t.u', 'w'), ix('t.v', 'k'), ix('t.v', None)
    (5, 7, 6)
    """

    def __init__(self, lines):
        self.keys, self.headers, self.dotted = {}, {}, {}
        current = None
        for i, line in enumerate(lines, 1):
            head = line.lstrip()
            if head.startswith("["):
                m = _HEADER.match(line)
                if m:
                    current = m.group(1).strip('"')
                    self.headers.setdefault(current, i)
                    continue
            cut = head.find("=")
            if cut < 0:
                continue
            name = _unquoted(head[:cut])
            self.keys.setdefault((current, name), i)
            table, dot, rest = name.partition(".")
            if dot:
                table = _unquoted(table)
                if table and not any(c in table for c in '"= \t'):
                    key = _unquoted(rest.lstrip())
                    self.dotted.setdefault((table, key), i)
                    if current:  # ``C.lag = 1`` under [indicator]: [indicator.C] lag
                        self.dotted.setdefault((f"{current}.{table}", key), i)

    def __call__(self, table: str | None, key: str | None = None):
        if key is None:
            return self.headers.get(table)
        found = self.keys.get((table, key))
        if found is None and table:
            found = self.dotted.get((table, key))
        return found


def line_of(lines, table: str | None, key: str | None = None):
    """Line number of ``[table] key`` (or of the table header) in ``lines``, if found: the
    first key line of the table's section, else the first dotted ``table.key =`` line."""
    return LineIndex(lines)(table, key)


def key_line(scene, key: str | None):
    """The line of a located key such as ``[assembly] C``, ``[links] BC, CD`` (its first
    name), ``[loads] "C-R"`` or ``[indicator.C] lag`` (a dotted table's, as its header
    ``[indicator.C]`` names it, or a dotted key ``C.lag`` under ``[indicator]``) in the file
    the scene was read from, or None.

    >>> from types import SimpleNamespace as NS
    >>> text = '[indicator]\\nbore = 100\\n[indicator.B]\\n[indicator.C]\\nlag = 450\\n'
    >>> sc = NS(_text=text)
    >>> key_line(sc, "[indicator.C] lag"), key_line(sc, "[indicator.B]")
    (5, 3)
    >>> key_line(sc, "[indicator] bore"), key_line(sc, "[indicator.D] lag")
    (2, None)
    """
    m = re.match(r"^\[\s*([A-Za-z0-9_.\-\"]+)\s*\]\s*([^,\s]+)?", key or "")
    if not m or not scene._text:
        return None
    name = None if m.group(2) is None else _unquoted(m.group(2))
    return line_of(toml_lines(scene._text), m.group(1).strip('"'), name)


def parsed_table(text: str, file, needs: str) -> dict:
    """``text``'s TOML table (:func:`toml_table`), or one located :class:`SceneError`: the
    reader's syntax error at its line, or a nesting too deep for it, with ``needs`` (what the
    file needs instead, in words) and the deepest key."""
    try:
        return toml_table(text)
    except tomllib.TOMLDecodeError as exc:
        raise syntax_error(str(exc), text, file) from None
    except RecursionError:
        raise SceneError(
            "TOML nested too deeply (brackets or braces inside each other hundreds of "
            f"times); {needs}",
            file=file,
            key=deepest_key(text),
        ) from None


def syntax_error(msg, text, file) -> SceneError:
    """A TOML decode error as a :class:`SceneError` at its line and column."""
    m = re.search(r"\(at line (\d+), column (\d+)\)", msg)
    core = re.sub(r"\s*\(at (line|end).*?\)", "", msg).strip()
    where = f"line {m.group(1)}, column {m.group(2)}" if m else None
    if core.startswith("Cannot overwrite a value"):
        dup = duplicate_key(text)
        if dup is not None:
            table, key, first, again = dup
            label = f"[{table}] {key}" if table else key
            return SceneError(
                f"duplicate key {key} (first given on line {first}); give each key once",
                file=file,
                key=label,
                line=again,
            )
    if core.startswith("An integer of"):  # (no syntax error: a value past reading)
        return SceneError(core[:1].lower() + core[1:], file=file, key=where)
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
    if m:
        core += _odd_character(text, int(m.group(1)), int(m.group(2)))
    if re.search(r"\r(?!\n)", text):  # an old Mac's line ends: TOML sees one long line
        core += (
            "; the file ends its lines with a lone carriage return (CR): save it with "
            "LF or CRLF line endings"
        )
    return SceneError(f"TOML syntax error: {core}", file=file, key=where)


def _odd_character(text, line, column) -> str:
    """Words naming the character outside ASCII where TOML stopped (``line``, ``column``
    from 1), which the eye may not tell from the one meant (a Greek capital Eta for H, a
    no-break space, a full-width digit); '' where it stopped at an ASCII one."""
    lines = toml_lines(text)
    row = lines[line - 1] if 0 < line <= len(lines) else ""
    ch = row[column - 1] if 0 < column <= len(row) else ""
    if not ch or ch.isascii():
        return ""
    return (
        f": the character {character_words(ch)} there; keys and values outside quotes are "
        'plain ASCII (a point A, O2; a link AB, "O2-A")'
    )


def duplicate_key(text):
    """(table, key, first line, second line) of a key given twice in one table, or None."""
    table, seen = "", {}
    for i, line in enumerate(toml_lines(text), 1):
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


def deepest_key(text):
    """The key whose value opens the most brackets on one line (for nesting errors)."""
    best, where = 0, None
    for i, line in enumerate(toml_lines(text), 1):
        m = re.match(r"^\s*([^=\s]+)\s*=", line)
        depth = line.count("[") + line.count("{")
        if m and depth > best:
            best, where = depth, f"{m.group(1).strip(chr(34))} (line {i})"
    return where


def printable_text(text):
    """``text`` with line breaks and control characters escaped, so that a message built
    from the file's own names stays one clean line on a terminal.

    >>> print(printable_text('A\\nB'), printable_text('BC'))
    A\\nB BC
    """
    if text is None or str(text).isprintable():
        return text
    return "".join(c if c.isprintable() else repr(c)[1:-1] for c in str(text))


#: TOML's integers are 64-bit ("an integer that cannot be represented losslessly must be
#: an error"); tomllib reads longer ones, which no float can hold
_INT64 = 1 << 63
#: what any integer beyond 64 bits is written with: 16 or more digits in a row (decimal
#: 19, hex 16, octal 21, binary 64, underscores between them); a text without such a run
#: has none, and its values need not be walked. Looked for in the text's UTF-8 bytes, each
#: digit byte made "x" and every other byte " " (one C pass, where a regular expression
#: tries every position): a digit is one ASCII byte, and no other character's bytes are
#: digits, so the runs are the same
_LONG_RUN = b"x" * 16
#: the same pass counts the brackets (``[`` and ``{``, made ``[``) for :data:`NESTING_SAFE`
_DIGITS = bytes(
    ord("x") if chr(c) in "0123456789ABCDEFabcdef_" else ord("[") if chr(c) in "[{" else ord(" ")
    for c in range(256)
)
#: the last text scanned and its scan (reading a scene asks twice: the brackets before the
#: TOML is read, the runs of digits after), kept as one pair: a text held is never another
_LAST = [("", b"")]


def _scanned(text: str) -> bytes:
    """``text``'s UTF-8 bytes with each digit (of any base, and ``_``) made ``x``, each
    ``[`` and ``{`` made ``[``, every other byte a space (one C pass)."""
    last = _LAST[0]
    if last[0] is text:
        return last[1]
    out = text.encode("utf-8", "replace").translate(_DIGITS)
    _LAST[0] = (text, out)
    return out


def has_long_run(text: str) -> bool:
    """Whether ``text`` has 16 or more of ``[0-9A-Fa-f_]`` in a row.

    >>> has_long_run("BC = 1234567890123456"), has_long_run("BC = 123456789012345 # é")
    (True, False)
    """
    return _LONG_RUN in _scanned(text)


def long_integer(raw):
    """The keys leading to the first integer of ``raw`` outside TOML's 64-bit range, and
    the integer, or None."""
    todo = [((), raw)]
    while todo:
        path, value = todo.pop()
        if isinstance(value, dict):
            todo.extend((path + (k,), v) for k, v in reversed(value.items()))
        elif isinstance(value, list):
            todo.extend((path, v) for v in reversed(value))
        elif isinstance(value, int) and not -_INT64 <= value < _INT64:
            return path, value
    return None
