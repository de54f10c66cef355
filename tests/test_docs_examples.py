"""The documentation's examples, run: every fenced block of README.md and docs/*.md.

A reader trusts what the docs show, so each example is held to it. The doc's own text is
the expected value, never the tool's output frozen here:

- every ``polygon-method ...`` command runs in process (``polygon_method.cli.main``) in a
  scratch folder that sees ``worked_problems/``, with its ``[optional]`` parts left out,
  and exits 0, or 2 where the doc shows an error line; the lines it shows follow in the
  output, in order (``...`` and left-out rows skipped), numbers within half a unit of the
  doc's last digit, whitespace as it falls; a synopsis (``SCENE``, ``FILE``, ``a|b``) is
  not run, but every option it names is one its command takes;
- every TOML snippet parses with ``polygon_method.parse_scene``; a fragment (a table or two
  of a scene, as the doc presents it) is completed with the worked problem named in
  ``FRAGMENTS`` below, the snippet's entries merged into the problem's (the tables it
  names replaced whole); an answer file against its scene, a turning-moment diagram on
  its own with ``parse_cycle``;
- the commands written in the prose take the options they show, and those on a worked
  problem run;
- the Python blocks run, a value shown in a comment (``expr  # ['A4 portrait']``) is the
  expression's value; the JSON shown is what ``solve --json`` has; the commands of the
  benchmark scripts name files and options that exist; the README's two commands for a
  fresh machine fit pyproject.toml and the CI; a few of the README's and variants.md's
  sentences about what the tool does are run as they say; every file the docs name is
  there.

Every block is claimed by one of these (``test_every_block_is_held``): a new example
is run, or named here with the reason it is not.
"""

from __future__ import annotations

import ast
import contextlib
import io
import json
import re
import shlex
import tokenize
import tomllib
from pathlib import Path

import pytest
import rtoml

import polygon_method as pm
from polygon_method.cli import main
from polygon_method.scene.answer_files import parse_answers

ROOT = Path(__file__).resolve().parent.parent
WORKED = ROOT / "worked_problems"
# architecture.md, the map of the code, has no example to run (its new step kind is made up)
DOC_FILES = ["README.md"] + sorted(
    f"docs/{p.name}" for p in (ROOT / "docs").glob("*.md") if p.name != "architecture.md"
)
_FENCE = re.compile(r"^```(\w*)[ \t]*\n(.*?)^```[ \t]*$", re.S | re.M)
_COMMAND = ("polygon-method ", "python -m polygon_method ")


def _blocks():
    out = []
    for name in DOC_FILES:
        text = (ROOT / name).read_text(encoding="utf-8")
        for m in _FENCE.finditer(text):
            line = text.count("\n", 0, m.start()) + 1
            out.append((name, line, m.group(1), m.group(2)))
    return out


BLOCKS = _blocks()


def _key(name, text):
    """A block's name that survives edits around it: its file and its first line that is
    not a table's header, a comment or blank (without its comment)."""
    for ln in text.splitlines():
        bare = " ".join(ln.split("#")[0].split()) if "=" in ln else " ".join(ln.split())
        if bare and not bare.startswith("#") and (not bare.startswith("[") or "--" in bare):
            return f"{name}: {bare[:90]}"
    return f"{name}: {' '.join(text.split())[:60]}"


def _keyed():
    """{key: (file, line, lang, text)}; a key a block of the same file already has gets
    " #2", " #3" after it."""
    out = {}
    for block in BLOCKS:
        key, n = _key(block[0], block[3]), 1
        while (key if n == 1 else f"{key} #{n}") in out:
            n += 1
        out[key if n == 1 else f"{key} #{n}"] = block
    return out


KEYED = _keyed()


# --- commands ----------------------------------------------------------------------------


def _commands(text):
    """[(command, expected output lines)] of a block: ``$ `` transcripts, or command lines
    each followed by the lines it prints; a synopsis' indented ``[...]`` lines continue it."""
    items = []
    transcript = any(ln.startswith("$ ") for ln in text.splitlines())
    for ln in text.splitlines():
        bare = ln[2:] if ln.startswith("$ ") else ln
        if bare.startswith(_COMMAND) and (ln.startswith("$ ") or not transcript):
            items.append([bare, []])
        elif items and not items[-1][1] and ln.startswith(" ") and ln.strip().startswith("["):
            items[-1][0] += " " + ln.strip()
        elif items:
            items[-1][1].append(ln)
    return [(cmd, out) for cmd, out in items]


def _strip_optional(cmd):
    """The command without its ``[...]`` parts (nested ones too) and its ``# comment``."""
    cmd = re.sub(r"\s+#.*$", "", cmd)
    while True:
        shorter = re.sub(r"\s*\[[^\[\]]*\]", "", cmd)
        if shorter == cmd:
            return cmd.strip()
        cmd = shorter


def _argv(cmd):
    words = shlex.split(cmd)
    return words[3:] if words[0] == "python" else words[1:]


def _is_synopsis(argv):
    return any(re.fullmatch(r"[A-Z][A-Z_]*(\.[a-z]+)?/?", w) or "|" in w for w in argv)


_NUMBER = re.compile(r"-?\d+(?:\.\d+)?(?:[eE][-+]?\d+)?")


def _same(doc, out):
    """A printed line as the doc shows it: the words alike (whitespace collapsed), integers
    equal, a number with decimals within half a unit of the doc's last digit."""
    doc, out = " ".join(doc.split()), " ".join(out.split())
    if _NUMBER.sub("#", doc) != _NUMBER.sub("#", out):
        return False
    for a, b in zip(_NUMBER.findall(doc), _NUMBER.findall(out)):
        mantissa = a.lower().split("e")[0]
        if "." not in mantissa:
            if a != b:
                return False
            continue
        exp = int(a.lower().split("e")[1]) if "e" in a.lower() else 0
        half = 0.5 * 10.0 ** (exp - len(mantissa.split(".")[1]))
        if abs(float(a) - float(b)) > half * (1 + 1e-9):
            return False
    return True


def _follows(expected, printed):
    """Each of the doc's lines found in the output, in order; returns the first not found."""
    lines = printed.splitlines()
    pos = 0
    for want in expected:
        if not want.strip() or want.strip() == "...":
            continue
        hit = next((i for i in range(pos, len(lines)) if _same(want, lines[i])), None)
        if hit is None:
            return want
        pos = hit + 1
    return None


@pytest.fixture
def scratch(tmp_path, monkeypatch):
    """A scratch folder as the working directory, ``worked_problems/`` seen from it."""
    (tmp_path / "worked_problems").symlink_to(WORKED, target_is_directory=True)
    monkeypatch.chdir(tmp_path)
    monkeypatch.setenv("MPLBACKEND", "Agg")
    return tmp_path


def _run(argv, streams=False):
    """The command's exit code and what it printed (``streams``: stdout and stderr apart)."""
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        try:
            code = main(argv)
        except SystemExit as exc:  # --help
            code = exc.code
    if streams:
        return code, out.getvalue(), err.getvalue()
    return code, out.getvalue() + err.getvalue()


_RUNS = []
_SYNOPSES = []
for _name, _line, _lang, _text in BLOCKS:
    if _lang not in ("", "sh"):
        continue
    for _cmd, _out in _commands(_text):
        _SYNOPSES.append(pytest.param(_cmd, id=f"{_name}:{_line}:{_argv(_cmd)[0]}"))
        if not _is_synopsis(_argv(_strip_optional(_cmd))):
            _RUNS.append(pytest.param(_strip_optional(_cmd), _out, id=f"{_name}:{_line}"))


_SUBCOMMANDS = "solve plan steps check variants draw page sweep linkage centres".split()


def _inline_commands():
    """(file, line, command) of each command written in the prose, `polygon-method ...`
    (a table's escaped ``\\|`` read as ``|``)."""
    for name in DOC_FILES:
        for number, text in enumerate((ROOT / name).read_text(encoding="utf-8").splitlines()):
            for cmd in re.findall(r"`((?:polygon-method|python -m polygon_method) [^`]+)`", text):
                yield name, number + 1, cmd.replace("\\|", "|")
            for cmd in re.findall(rf"`((?:{'|'.join(_SUBCOMMANDS)}) --?[a-z][^`]*)`", text):
                yield name, number + 1, "polygon-method " + cmd  # `draw --forces`


for _name, _line, _cmd in _inline_commands():
    _SYNOPSES.append(pytest.param(_cmd, id=f"{_name}:{_line}:{_argv(_cmd)[0]}"))
    _bare = _argv(_strip_optional(_cmd))
    # a command on a worked problem, as written (not "scene.toml answers.toml")
    if not _is_synopsis(_bare) and any(w.startswith("worked_problems/") for w in _bare):
        _RUNS.append(pytest.param(_strip_optional(_cmd), [], id=f"{_name}:{_line}"))


@pytest.mark.parametrize("cmd, shown", _RUNS)
def test_a_documented_command_prints_what_the_doc_shows(scratch, cmd, shown):
    argv = _argv(cmd)
    code, out, err = _run(argv, streams=True)
    printed = out + err
    error = any(ln.startswith(f"polygon-method {argv[0]}: ") for ln in shown)
    assert code == (2 if error else 0), printed
    if error:  # "one line on stderr ...; nothing is written" (errors.md)
        assert not out and len(err.splitlines()) == 1, printed
        assert [p.name for p in scratch.iterdir()] == ["worked_problems"]
    missing = _follows(shown, printed)
    assert missing is None, f"not printed: {missing!r}\n--- printed:\n{printed}"


@pytest.mark.parametrize("cmd", _SYNOPSES)
def test_every_option_a_command_shows_is_taken(cmd):
    argv = _argv(cmd)
    code, helptext = _run([argv[0], "--help"])
    assert code == 0
    for option in re.findall(r"(?<![\w-])(--?[a-z][\w-]*)", cmd):
        assert re.search(rf"(?<![\w-]){re.escape(option)}(?![\w-])", helptext), option
    words = set(re.findall(r"[\w.]+", helptext))
    for option, choices in re.findall(r"(--[\w-]+)[ =]([\w.]+(?:\|[\w.]+)+)", cmd):
        assert set(choices.split("|")) <= words, (option, choices)


# Output shown without its command beside it: the command the prose around it names, and
# the exit code it implies (check: 1 where an answer is WRONG).
EXCERPTS = {
    "README.md: point position (mm) velocity (m/s) acceleration (m/s^2)": (
        ["solve", "worked_problems/fourbar_image_points.toml"],
        0,
    ),
    "docs/steps-and-check.md: rub_A 0.207 m/s 0.244 m/s 15.16 % 7 % WRONG": (
        ["check", "worked_problems/toggle_mechanism.toml"],
        1,
    ),
}


def _excerpt_params():
    for key, (name, line, _lang, text) in KEYED.items():
        if key in EXCERPTS:
            yield pytest.param(*EXCERPTS[key], text, id=f"{name}:{line}")


@pytest.mark.parametrize("argv, code, shown", list(_excerpt_params()))
def test_an_excerpt_is_what_its_command_prints(scratch, argv, code, shown):
    got, printed = _run(argv)
    assert got == code, printed
    missing = _follows(shown.splitlines(), printed)
    assert missing is None, f"not printed: {missing!r}\n--- printed:\n{printed}"


# errors.md's three lines are about a four-bar "fourbar.toml": this one, with BC on line 9
# and the speed on line 14 as the lines say, and each fault made in turn.
_FOURBAR = """\
title = "Four-bar chain ABCD"
units = "mm"
[ground]
A = [0, 0]
D = [100, 0]

[links]
AB = 50
BC = 66
CD = 56

[input]
crank = "AB"
speed = "10.5 rad/s cw"
angle = 60
"""
_FAULTS = {
    "[links] BC": ("BC = 66", "BC = -66"),
    "[input] speed": ("rad/s cw", "rmp cw"),
    "cannot assemble C": ("D = [100, 0]\n", "D = [80, 0]\n", "angle = 60", "angle = 180"),
}


def _error_lines():
    (text,) = [t for n, _, lang, t in BLOCKS if n == "docs/errors.md" and lang == "text"]
    return text.splitlines()


@pytest.mark.parametrize("shown", _error_lines(), ids=list(_FAULTS))
def test_the_error_lines_errors_md_shows(scratch, shown):
    (fault,) = [f for f in _FAULTS if f in shown]
    edits, scene = _FAULTS[fault], _FOURBAR
    for old, new in zip(edits[::2], edits[1::2]):
        scene = scene.replace(old, new)
    Path("fourbar.toml").write_text(scene)
    code, out, printed = _run(["solve", "fourbar.toml"], streams=True)
    assert not out and len(printed.splitlines()) == 1
    assert code == 2
    assert _same(shown, printed.strip()), printed


# --- TOML snippets -----------------------------------------------------------------------

# A fragment, keyed as _key names it: the worked problem it completes, the tables (or
# "table.key" entries) of the problem the snippet takes the place of (the rest merged
# entry by entry), and what the doc says the rest of the scene holds.
FRAGMENTS = {
    'docs/forces.md: AB = { mass = "30 kg", along = 400, from = "A", gyration = 250 }': (
        "engine_analytical.toml",
        (),
        "",
    ),
    'docs/forces.md: "C-R" = { pressure = "5 N/mm^2", bore = 50, rod = 20 }': (
        "cylinder_pull_on_rocker.toml",
        ("loads",),
        "",
    ),
    'docs/scene-format.md: E = { force = "100 N", direction = 150 }': (
        "fourbar_image_points.toml",
        (),
        "",
    ),
    'docs/scene-format.md: M = { on = "CD", along = 200 }': (
        "static_fourbar_pin_forces.toml",
        ("loads",),
        "",
    ),
    # "G a point of AB ([points])"
    'docs/scene-format.md: OA = { mass = "10 kg", along = 50, inertia = "0.1 kg m^2" }': (
        "two_slider_mechanism.toml",
        (),
        '[points]\nG = { on = "AB", along = 100 }',
    ),
    "docs/scene-format.md: guides = 0.1": ("engine_forces.toml", (), ""),
    'docs/scene-format.md: piston = "B"': ("engine_flywheel.toml", ("indicator", "flywheel"), ""),
    'docs/scene-format.md: crank = "OA"': ("offset_slider_crank.toml", ("input",), ""),
    # "instead of angle, [input] may state that position"
    'docs/scene-format.md: crank = "QR"': ("tipper_cylinder.toml", ("input.angle",), ""),
    'docs/scene-format.md: A = { path = "horizontal", through = "O" }': (
        "ellipse_trammel.toml",
        ("input", "sliders"),
        "",
    ),
    'docs/scene-format.md: C = { along = "O-A" }': ("collar_forces.toml", ("input", "sliders"), ""),
    'docs/scene-format.md: crank = "ED"': ("five_bar_two_inputs.toml", ("input.second",), ""),
    'docs/scene-format.md: C = { along = "O-A" } #2': (
        "collar_on_turning_crank.toml",
        ("input",),
        "",
    ),
    'docs/scene-format.md: "O-R" = { stroke = [1000, 1900] }': (
        "tipper_cylinder.toml",
        ("input", "cylinders"),
        "",
    ),
    # "the mechanism driven by its crank ...", "applied by the force analysis, so the scene
    # gives [masses]"
    'docs/scene-format.md: "O-R" = { push = "2 kN" }': (
        "tipper_cylinder.toml",
        ("input.vs_OR",),
        '[masses]\n[input]\nspeed = "0.1 rad/s cw"',
    ),
}
# an answer file, read against the scene the doc's example is about
ANSWER_FILES = {
    'docs/steps-and-check.md: student = "A. Student"': "fourbar_image_points.toml",
    'docs/variants.md: student = "Ann Smith"': "fourbar_image_points.toml",
}
# a turning-moment diagram on its own (parse_cycle), completed with this problem
CYCLES = {
    "docs/scene-format.md: areas = [52, -124, 92, -140, 85, -72, 107]": None,
    'docs/variants.md: flywheel = { speed = { from = 250, to = 350, step = 25, unit = "rpm" }, '
    'plus_minus = ["1%"': "flywheel/engine_areas_rim.toml",
}
# variants.md's catalogue of what may vary: each line on a scene that has that key's
# kind (a slider's fixed path, a load), the rest on the four-bar of the seed notes
CATALOGUE = "docs/variants.md: BC = { from = 60, to = 75, step = 1 }"
CATALOGUE_SCENES = {
    "B": "offset_slider_crank.toml",
    "P": "../tests/textbook/engine_inline_270.toml",
    "A": "../tests/textbook/hunt5_offset_slot_lever.toml",
}


def _merged(base, snippet, replaced, extra):
    """The worked problem ``base`` with the snippet's tables in it (as TOML text)."""
    scene = tomllib.loads((WORKED / base).read_text(encoding="utf-8"))
    for dotted in replaced:
        *path, last = dotted.split(".")
        table = scene
        for part in path:
            table = table[part]
        table.pop(last, None)

    def merge(into, more):
        for k, v in more.items():
            if isinstance(v, dict) and isinstance(into.get(k), dict):
                merge(into[k], v)
            else:
                into[k] = v

    merge(scene, tomllib.loads(snippet))
    merge(scene, tomllib.loads(extra))
    return rtoml.dumps(scene)


def _toml_params():
    for key, (name, line, lang, text) in KEYED.items():
        if lang == "toml" and key != CATALOGUE:
            yield pytest.param(key, text, id=f"{name}:{line}")


@pytest.mark.parametrize("key, text", list(_toml_params()))
def test_a_toml_snippet_parses(key, text):
    if key in FRAGMENTS:
        pm.parse_scene(_merged(*((FRAGMENTS[key][0], text) + FRAGMENTS[key][1:])), "x.toml")
    elif key in ANSWER_FILES:
        scene = pm.load_scene(WORKED / ANSWER_FILES[key])
        tolerance, answers, variant, student = parse_answers(
            text, scene, "answers.toml", with_variant=True, with_student=True
        )
        assert answers and student
    elif key in CYCLES:
        base = CYCLES[key]
        pm.parse_cycle(text if base is None else _merged(base, text, ("variants",), ""))
    else:  # a whole scene
        pm.parse_scene(text, "scene.toml")


def _catalogue_lines():
    (text,) = [t for k, (_, _, _, t) in KEYED.items() if k == CATALOGUE]
    lines = [ln for ln in text.splitlines() if "=" in ln and not ln.startswith(("[", "#"))]
    last = [ln for ln in lines if ln.startswith("min_condition")]
    assert last, "the catalogue ends with its min_condition"
    return [
        pytest.param(ln, last[0], id=ln.split("=")[0].strip()) for ln in lines if ln not in last
    ]


@pytest.mark.parametrize("line, condition", _catalogue_lines())
def test_each_kind_of_variant_parses_on_a_scene_that_has_it(line, condition):
    base = CATALOGUE_SCENES.get(line.split("=")[0].strip(), "fourbar_image_points.toml")
    text = _merged(base, f"[variants]\n{line}\n{condition}\n", ("variants",), "")
    pm.parse_scene(text, "x.toml")


# --- Python, JSON, scripts, the README's two commands ------------------------------------


def _python_params():
    for key, (name, line, lang, text) in KEYED.items():
        if lang == "python":
            yield pytest.param(name, text, id=f"{name}:{line}")


def _shown_values_asserted(text):
    """The block with each bare expression whose comment is a Python value (``x  # ['A4
    portrait']``) turned into an assertion that it is that value."""
    comments = {
        tok.start[0]: tok.string[1:].strip()
        for tok in tokenize.generate_tokens(io.StringIO(text).readline)
        if tok.type == tokenize.COMMENT
    }
    tree = ast.parse(text)
    for i, node in enumerate(tree.body):
        comment = comments.get(node.end_lineno, "")
        try:
            ast.literal_eval(comment)
        except (ValueError, SyntaxError):
            continue
        if isinstance(node, ast.Expr):
            shown = ast.parse(comment, mode="eval").body
            test = ast.Compare(node.value, [ast.Eq()], [shown])
            tree.body[i] = ast.copy_location(ast.Assert(test), node)
    return ast.fix_missing_locations(tree)


@pytest.mark.parametrize("name, text", list(_python_params()))
def test_a_python_block_runs(scratch, name, text, capsys):
    # errors.md's block reads "fourbar.toml": the four-bar of its lines, that cannot assemble
    scene = _FOURBAR.replace("D = [100, 0]", "D = [80, 0]").replace("angle = 60", "angle = 180")
    Path("fourbar.toml").write_text(scene)
    exec(compile(_shown_values_asserted(text), name, "exec"), {"__name__": "__doc_example__"})
    if "AssemblyError" in text:
        assert capsys.readouterr().out.startswith("step 2 (dyad BC, CD at C) cannot assemble C")


def _json_of(argv):
    code, printed = _run(argv)
    assert code == 0, printed
    return json.loads(printed)


def test_solve_json_has_the_keys_scene_format_lists(scratch):
    """ "At least these keys, all in SI": a mechanism with a slider, pins and a load."""
    (text,) = [t for k, (_, _, lang, t) in KEYED.items() if k == "docs/scene-format.md: {"]
    shown = json.loads(re.sub(r"\[x, y\]|\[vx, vy\]|\[ax, ay\]", "[0, 0]", text))
    got = _json_of(["solve", "--json", "worked_problems/toggle_mechanism.toml"])
    for table, entries in shown.items():
        if not isinstance(entries, dict):
            assert isinstance(got[table], float), table
            continue
        (example,) = entries.values()
        assert got[table], table
        for entry in got[table].values():
            assert set(example) <= set(entry), (table, entry)


def test_the_error_bounds_scene_format_shows(scratch):
    """The engine's error_bounds: the same keys; the sizes they are relative to, rounded
    to two digits as the doc says (r w, r w^2, ...)."""
    (text,) = [t for k, (_, _, _, t) in KEYED.items() if '"error_bounds": {' in k]
    shown = json.loads("{" + text + "}")["error_bounds"]
    got = _json_of(["solve", "--json", "worked_problems/engine_analytical.toml"])["error_bounds"]

    def keys(d):
        return {k: keys(v) for k, v in d.items()} if isinstance(d, dict) else None

    assert keys(got) == keys(shown)
    for what, size in shown["relative_to"].items():
        assert abs(got["relative_to"][what] - size) <= 0.05 * size, what


# the commands that run a script of the project rather than the tool
SCRIPTS = (
    "docs/accuracy.md: python benchmarks/accuracy_speed.py",
    "docs/errors.md: python benchmarks/error_bounds.py",
    "docs/errors.md: FUZZ_EXAMPLES=5000 python -m pytest tests/test_fuzz.py",
)


@pytest.mark.parametrize("key", SCRIPTS)
def test_a_script_the_docs_run_is_there_with_its_options(key):
    (text,) = [t for k, (_, _, _, t) in KEYED.items() if k.startswith(key)]
    for line in text.splitlines():
        words = shlex.split(line, comments=True)
        script = next(w for w in words if w.endswith(".py"))
        source = (ROOT / script).read_text(encoding="utf-8")
        for word in words:
            name = word.split("=")[0] if "=" in word else word
            if word.startswith("--") or "=" in word:
                assert name in source, (script, name)


def _install_commands():
    return [t for k, (_, _, lang, t) in KEYED.items() if k.startswith("README.md: python3 -m venv")]


def test_the_readmes_two_commands_fit_this_tree():
    """The fresh machine's commands: the Python the README names is the one pyproject
    requires; the install's extras exist; the command installed is the one run on a worked
    problem that exists; the test command is the one the CI runs, with the test tools."""
    project = tomllib.loads((ROOT / "pyproject.toml").read_text())
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    minimum = re.search(r"Python (\d+\.\d+) or newer", readme).group(1)
    assert project["project"]["requires-python"] == f">={minimum}"
    solve, tests = [t.strip() for t in _install_commands()]
    steps = [shlex.split(step) for step in solve.split("&&")]
    assert steps[2] == ["python", "-m", "pip", "install", "."]
    assert steps[3][0] in project["project"]["scripts"]
    assert steps[3][1] == "solve" and (ROOT / steps[3][2]).is_file()
    steps = [shlex.split(step) for step in tests.split("&&")]
    (extra,) = re.fullmatch(r"\.\[(\w+)\]", steps[2][-1]).groups()
    assert steps[2][:-1] == ["python", "-m", "pip", "install", "-e"]
    extras = project["project"]["optional-dependencies"][extra]
    assert {"pytest", "pytest-xdist", "hypothesis", "mpmath"} <= {
        re.split(r"[<>=!~\[ ]", e)[0] for e in extras
    }
    ci = (ROOT / ".ci" / "run").read_text()
    assert f"pip install --quiet -e '.[{extra}]'" in ci
    assert steps[3] == ["python", "-m", "pytest"] and "\npython -m pytest\n" in ci


def test_every_block_is_held():
    """Each fenced block is run or checked by one of the tests above; the names in the
    tables above are blocks' names (a renamed example is not silently left out)."""
    named = set(EXCERPTS) | set(FRAGMENTS) | set(ANSWER_FILES) | set(CYCLES) | {CATALOGUE}
    assert named <= set(KEYED), named - set(KEYED)
    for key, (name, line, lang, text) in KEYED.items():
        held = (
            lang in ("toml", "python")
            or key in EXCERPTS
            or (lang in ("", "sh") and _commands(text))
            or key.startswith(SCRIPTS)
            or text in _install_commands()
            or (name == "docs/errors.md" and lang == "text")
            or key == "docs/scene-format.md: {"
            or key.startswith('docs/scene-format.md: "error_bounds": {')
        )
        assert held, f"{name}:{line}: an example no test runs"


def test_the_readmes_drawing_is_two_a4_pages_at_the_step_tables_scales(scratch):
    """README: `draw ... -o fourbar.pdf` "(two A4 pages at the step table's scales; one
    page with `--paper A3`)"."""
    readme = " ".join((ROOT / "README.md").read_text(encoding="utf-8").split())
    cmd = "polygon-method draw worked_problems/fourbar_image_points.toml -o fourbar.pdf"
    assert f"`{cmd}` (two A4 pages at the step table's scales; one page with `--paper A3`)" in (
        readme
    )
    code, steps = _run(["steps", "worked_problems/fourbar_image_points.toml"])
    assert code == 0
    scales = re.findall(
        r"^(?:Space|Velocity|Acceleration) scale: (1 cm = [^ ]+ [^ (]+)", steps, re.M
    )
    assert len(scales) == 3
    code, a4 = _run(_argv(cmd))
    assert code == 0 and a4.splitlines()[0].startswith("fourbar.pdf: 2 pages on A4")
    code, a3 = _run(_argv(cmd) + ["--paper", "A3"])
    assert code == 0 and a3.startswith("fourbar.pdf: A3 ") and len(a3.splitlines()) == 1
    for printed in (a4.splitlines()[0], a3):
        shown = re.findall(r"(?:configuration|velocity|acceleration) (1 cm = [^;]+)", printed)
        assert [s.strip().replace("²", "^2") for s in shown] == scales


def test_the_readmes_scene_is_its_worked_problem_shortened():
    """README: "(`worked_problems/fourbar_image_points.toml`, shortened, with a question
    `a_C = "?"` added)": every entry it shows is the worked problem's (its title cut
    short), but the question it says it adds."""
    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    said = re.search(
        r"\(`(worked_problems/[\w/]+\.toml)`, shortened, with a question `(\w+) = ", readme
    )
    (text,) = [t for k, (n, _, lang, t) in KEYED.items() if n == "README.md" and lang == "toml"]
    shown, worked = tomllib.loads(text), tomllib.loads((ROOT / said.group(1)).read_text())
    assert worked["title"].startswith(shown.pop("title"))
    assert shown["answers"].pop(said.group(2)) == "?" and said.group(2) not in worked["answers"]

    def within(part, whole, where):
        for key, value in part.items():
            if isinstance(value, dict):
                within(value, whole[key], f"{where}{key}.")
            else:
                assert whole.get(key) == value, where + key

    within(shown, worked, "")


def test_the_readmes_check_finds_the_notes_slip(scratch):
    """README: "`polygon-method check` finds the notes' slip (`v_CB = 0.84` written for
    0.34 m/s)"."""
    readme = " ".join((ROOT / "README.md").read_text(encoding="utf-8").split())
    said = re.search(
        r"finds the notes' slip \(`(\w+) = ([\d.]+)` written for ([\d.]+) m/s\)", readme
    )
    key, written, meant = said.groups()
    code, printed = _run(["check", "worked_problems/fourbar_image_points.toml"])
    assert code == 1
    (row,) = [ln for ln in printed.splitlines() if ln.startswith(f"{key} ")]
    assert row.split()[1] == written and row.split()[-1] == "WRONG"
    after = printed.split(row, 1)[1].splitlines()[1]
    assert "slip of the pen" in after and f"{written} written for {meant}" in after


def test_the_test_tools_the_readme_installs_are_all_the_tests_import():
    """``pip install -e '.[test]'`` then ``python -m pytest``: every package the tests, the
    doctests' modules and the benchmark modules the tests load import is installed by the
    project's dependencies or its test extra (or comes with one of them: Pillow with
    matplotlib)."""
    import importlib.metadata as md
    import sys

    def name(requirement):
        return re.sub(r"[-_.]+", "-", re.split(r"[<>=!~\[ ;(]", requirement)[0]).lower()

    project = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    (extra,) = re.findall(r"\.\[(\w+)\]", _install_commands()[1])
    todo = [name(r) for r in project["dependencies"] + project["optional-dependencies"][extra]]
    installed = set()
    while todo:
        dist = todo.pop()
        if dist not in installed:
            installed.add(dist)
            with contextlib.suppress(md.PackageNotFoundError):
                todo += [name(r) for r in md.requires(dist) or [] if "extra ==" not in r]
    local = {p.stem for p in (ROOT / "tests").glob("*.py")}
    local |= {p.stem for p in (ROOT / "benchmarks").glob("*.py")} | {"polygon_method"}
    sources = [*(ROOT / "tests").glob("*.py"), *(ROOT / "polygon_method").rglob("*.py")]
    sources += [
        ROOT / "benchmarks" / f"{m}.py" for m in ("methods", "error_bounds", "edge_families")
    ]
    imported = set()
    for path in sources:
        for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
            if isinstance(node, ast.Import):
                imported |= {a.name.split(".")[0] for a in node.names}
            elif isinstance(node, ast.ImportFrom) and node.level == 0:
                imported.add(node.module.split(".")[0])
    distributions = md.packages_distributions()
    for module in sorted(imported - set(sys.stdlib_module_names) - local):
        dists = {name(d) for d in distributions.get(module, [module])}
        assert dists & installed, f"{module} is imported but not installed by .[{extra}]"


def test_the_variants_workflow_variants_md_shows(scratch):
    """variants.md's two commands on the seed four-bar (its [variants] table): the files its
    table lists, and no other; a student's answer file as the doc writes it graded against
    its variant, the class's gradebook written, exit 0 for a whole class (README)."""
    (name, _, _, text) = KEYED[
        "docs/variants.md: polygon-method variants SCENE --count 40 --seed 7 -o class/ [--pdf]"
    ]
    scene = "worked_problems/fourbar_image_points.toml"
    make, grade = [_argv(_strip_optional(c).replace("SCENE", scene)) for c, _ in _commands(text)]
    code, printed = _run(make)
    assert code == 0, printed
    table = (ROOT / name).read_text(encoding="utf-8").split("| file | what it is |")[1]
    rows = re.findall(r"^\| (`.*?) \|", table, re.M)
    listed = set()
    for row in rows:
        spans = re.findall(r"`([^`]+)`", row)
        if "..." in row:  # `variant-01.toml` ... `variant-40.toml`
            digits = [re.search(r"\d+", s).group() for s in spans[:2]]
            first, last, width = int(digits[0]), int(digits[1]), len(digits[0])
            count = int(make[make.index("--count") + 1])
            assert (first, last) == (1, count)
            listed |= {f"variant-{i:0{width}d}.toml" for i in range(first, last + 1)}
        else:
            listed |= {s for s in spans if "." in s and not s.endswith(".pdf")}  # --pdf left out
    folder = make[make.index("-o") + 1].rstrip("/")
    assert {p.name for p in Path(folder).iterdir()} == listed
    Path("answers").mkdir()
    answer = KEYED['docs/variants.md: student = "Ann Smith"'][3]
    Path("answers/ann.toml").write_text(answer)
    code, printed = _run(grade)
    assert code == 0, printed
    book = Path(grade[grade.index("--gradebook") + 1]).read_text()
    assert "Ann Smith" in book and re.search(r"^Ann Smith\s+07\s", printed, re.M), printed


def test_every_file_the_docs_name_is_there():
    """A path of this repository a doc names (``worked_problems/...``, ``tests/...``,
    ``benchmarks/...``, an image) is there; a ``*`` pattern matches a file."""
    named = set()
    for name in DOC_FILES:
        text = (ROOT / name).read_text(encoding="utf-8")
        found = re.findall(r"(?:worked_problems|tests|benchmarks|docs)/[\w./*-]+", text)
        named |= {(name, p.rstrip(".,")) for p in found}
    assert len(named) > 50
    for name, path in sorted(named):
        assert next(ROOT.glob(path), None) if "*" in path else (ROOT / path).exists(), (name, path)
