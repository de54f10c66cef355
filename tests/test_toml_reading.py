"""The scene reader's speed-ups read exactly what the slow path reads.

* ``toml_table`` (a compiled TOML reader first, tomllib where it refuses) gives the table
  tomllib gives for every TOML file in the repository and for every one-line deletion and
  duplication of them; where tomllib refuses a text, the scene reader's message is the one
  it gives with tomllib alone.
* ``LineIndex`` (every key's line in one pass) finds the line a regular expression per key
  finds (the reader's earlier way, kept here as the reference), for every table and key of
  every file, and for keys that are not there.
* The same for texts changed a character at a time (a character of TOML's syntax put in
  or in place of another, at random places drawn from a fixed seed), read by each compiled
  reader (``toml_rs`` for a text of few brackets, ``rtoml`` for one of many), and a text
  nested deeper than ``toml_rs``'s stack holds is refused in words, never a crash.
* A command that makes no variants does not read ``[variants]``.
"""

import random
import re
import subprocess
import sys
import tomllib
from pathlib import Path

import pytest

from polygon_method.cli import main
from polygon_method.common.errors import SceneError
from polygon_method.scene import parse_scene
from polygon_method.scene import source
from polygon_method.scene.reading import LineIndex, toml_lines, toml_table

ROOT = Path(__file__).resolve().parents[1]


def _texts():
    for f in sorted(ROOT.glob("worked_problems/*.toml")) + sorted(ROOT.glob("tests/**/*.toml")):
        try:
            yield f.name, f.read_text(encoding="utf-8")
        except UnicodeDecodeError:  # the corpus of bad files holds some on purpose
            continue


TEXTS = list(_texts())


def _variants(text):
    lines = text.split("\n")
    yield text
    for i in range(len(lines)):
        yield "\n".join(lines[:i] + lines[i + 1 :])
        yield "\n".join(lines[: i + 1] + lines[i:])


def test_the_corpus_is_there():
    assert len(TEXTS) > 40


@pytest.mark.parametrize("name,text", TEXTS, ids=[n for n, _ in TEXTS])
def test_the_fast_reader_reads_what_tomllib_reads(name, text, monkeypatch):
    compared = refused = 0
    for t in _variants(text):
        try:
            want = tomllib.loads(t)
        except (tomllib.TOMLDecodeError, RecursionError):
            with pytest.raises(SceneError) as fast:
                parse_scene(t, file="x.toml")
            with monkeypatch.context() as m:
                m.setattr(source, "_fast_toml", None)
                with pytest.raises(SceneError) as slow:
                    parse_scene(t, file="x.toml")
            assert str(fast.value) == str(slow.value)
            refused += 1
            continue
        assert repr(toml_table(t)) == repr(want)  # (nan is not nan: compared as text)
        compared += 1
    assert compared >= 1


#: what a mutation puts in: TOML's syntax, and what tomllib refuses and a reader might not
_SYNTAX = list("[]{},.=\"'#\\\n\r\t -+_:") + ["\ufeff", "\\e", "\\x41", "e", "x", "0", "T", "nan"]


def _mutations(text, rng, count):
    for _ in range(count):
        i = rng.randrange(len(text) + 1)
        cut = rng.choice((0, 0, 1))  # put in, or in place of the character there
        yield text[:i] + rng.choice(_SYNTAX) + text[i + cut :]


@pytest.mark.parametrize("route", ["toml_rs", "rtoml"])
def test_a_changed_character_is_read_as_tomllib_reads_it(route, monkeypatch):
    if route == "rtoml":  # every text one of many brackets: the other compiled reader
        monkeypatch.setattr(source, "NESTING_SAFE", -1)
    rng = random.Random(20261126)
    compared = refused = beyond = 0
    for name, text in TEXTS[::3]:
        for t in _mutations(text, rng, 40):
            try:
                want = tomllib.loads(t)
            except (tomllib.TOMLDecodeError, RecursionError):
                try:
                    if t[:1] == "\ufeff":  # toml_table never hands the compiled reader a
                        raise ValueError  # byte-order mark (toml_rs reads one past it)
                    source._fast_toml(t)
                except Exception:  # noqa: BLE001 - refused by the compiled reader too
                    pass
                else:  # read: only rtoml, and only what TOML 1.1 added (its docstring)
                    assert route == "rtoml", t
                    beyond += 1
                    continue
                with pytest.raises(SceneError) as fast:
                    parse_scene(t, file="x.toml")
                with monkeypatch.context() as m:
                    m.setattr(source, "_fast_toml", None)
                    with pytest.raises(SceneError) as slow:
                        parse_scene(t, file="x.toml")
                assert str(fast.value) == str(slow.value), t
                refused += 1
                continue
            assert repr(toml_table(t)) == repr(want), t
            compared += 1
    assert compared > 100 and refused > 100 and beyond < refused / 10


def test_a_text_nested_past_the_compiled_readers_stack_is_refused_in_words():
    code = (
        "from polygon_method.scene import parse_scene\n"
        "from polygon_method.common.errors import SceneError\n"
        "for depth in (400, 20000):\n"
        "    try:\n"
        "        parse_scene('title = ' + '[' * depth + ']' * depth)\n"
        "    except SceneError as exc:\n"
        "        print(exc)\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code], capture_output=True, text=True, cwd=ROOT, timeout=120
    )
    assert out.returncode == 0, out.stderr[-500:]
    lines = out.stdout.strip().splitlines()
    assert len(lines) == 2 and "title must be a string" in lines[0], lines
    assert "nested too deeply" in lines[1], lines


_HEADER = re.compile(r"^\s*\[\s*([A-Za-z0-9_.\-\"]+)\s*\]\s*(#.*)?$")


def line_by_regex(lines, table, key=None):
    """The line of ``[table] key`` found one key at a time by regular expressions."""
    current = None
    for i, line in enumerate(lines, 1):
        m = _HEADER.match(line)
        if m:
            current = m.group(1).strip('"')
            if key is None and current == table:
                return i
            continue
        if key is not None and current == table:
            if re.match(rf"^\s*\"?{re.escape(key)}\"?\s*=", line):
                return i
    if key is not None and table:  # a dotted key: links.BC = 66, or input.angle = 30
        dotted = re.compile(
            rf"^\s*\"?{re.escape(table)}\"?\s*\.\s*\"?{re.escape(key)}"
            rf"\"?\s*="
        )
        for i, line in enumerate(lines, 1):
            if dotted.match(line):
                return i
    return None


@pytest.mark.parametrize("name,text", TEXTS, ids=[n for n, _ in TEXTS])
def test_the_line_index_finds_what_a_regex_per_key_finds(name, text):
    try:
        raw = tomllib.loads(text)
    except (tomllib.TOMLDecodeError, RecursionError):
        raw = {}
    lines = toml_lines(text)
    index = LineIndex(lines)
    asked = [(None, k) for k in raw] + [(t, None) for t in raw]
    asked += [(t, k) for t, v in raw.items() if isinstance(v, dict) for k in v]
    asked += [(t, f"{k}x") for t, k in asked if k] + [("nowhere", None), ("links", "ZZ")]
    for table, key in asked:
        assert index(table, key) == line_by_regex(lines, table, key), (table, key)


def test_a_command_that_makes_no_variants_does_not_read_them(tmp_path, capsys):
    seed = (ROOT / "worked_problems" / "fourbar_image_points.toml").read_text()
    broken = seed.replace("BC = { from = 60, to = 72, step = 1 }", "BC = { from = 60 }")
    assert broken != seed
    f = tmp_path / "s.toml"
    f.write_text(broken)
    assert main(["solve", str(f)]) == 0
    assert main(["variants", str(f), "--count", "2", "-o", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "[variants] BC" in err[0] and "no to" in err[0]
