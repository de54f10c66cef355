"""An adversarial user of every command, a third pass: what once crashed (exit 3), held
gigabytes, printed a number of 300 digits or NaN, named no file, or refused a valid scene,
each kept as a test; and generated mutations of every worked problem and corpus scene
through ``solve --json``, holding the promise (exit 0 with strict, finite JSON, or exit 2
with one line naming the file).

Expected values come from the inputs (a count of angles worked out here, a gear's size by
hand), never from the code under test."""

from __future__ import annotations

import copy
import json
import math
import random
import re
import tomllib
import warnings
from pathlib import Path

import pytest

from polygon_method.cli import main

ROOT = Path(__file__).resolve().parent.parent
SEED = str(ROOT / "worked_problems/fourbar_image_points.toml")
TRAMMEL = str(ROOT / "worked_problems/ellipse_trammel.toml")
FLYWHEEL = (ROOT / "worked_problems/engine_flywheel.toml").read_text()


def _one_line(capsys, *names):
    out, err = capsys.readouterr()
    lines = [x for x in err.splitlines() if not x.startswith("warning:")]
    assert len(lines) == 1 and not out.strip(), err
    for name in names:
        assert str(name) in lines[0], lines[0]
    assert "Traceback" not in err and "internal error" not in err
    return lines[0]


def _refuse(x):
    raise ValueError(f"{x} in the JSON")


# ----------------------------------------------------------------- sweep ranges


@pytest.mark.parametrize("scene", [SEED, TRAMMEL], ids=["crank", "block"])
@pytest.mark.parametrize(
    "start, stop, step",
    [
        (-1e6, 1e6, 1e-310),  # (b - a) / s past the largest float: was an OverflowError
        (0, 10, 1e-300),  # 1e301 angles: its count was printed in 302 digits
        (-1e308, 1e308, 1e300),  # b - a past the largest float
        (1e308, -1e308, -1e-300),
    ],
)
def test_a_sweep_range_of_countless_values_is_one_short_line(capsys, scene, start, stop, step):
    assert main(["sweep", scene, "--from", str(start), "--to", str(stop), "--step", str(step)]) == 2
    line = _one_line(capsys)
    assert len(line) < 250 and not re.search(r"\d{20}", line), line
    assert not re.search(r"(?<![A-Za-z])(inf|nan)(?![A-Za-z])", line, re.I), line


def test_a_range_of_a_few_values_is_counted_with_both_ends(tmp_path, capsys):
    out = tmp_path / "s.csv"
    assert (
        main(["sweep", SEED, "--from", "0", "--to", "10", "--step", "2.5", "--csv", str(out)]) == 0
    )
    assert len(out.read_text().splitlines()) == 1 + 5  # 0, 2.5, 5, 7.5, 10


def test_a_driving_blocks_places_far_beyond_any_scene_are_named_as_places(capsys):
    """A block's sweep past 1e4 m was refused as "crank angles ... within +-1e6 rad"."""
    assert main(["sweep", TRAMMEL, "--from", "1e300", "--to", "1e300", "--step", "1"]) == 2
    line = _one_line(capsys)
    assert "the places of block" in line and "mm" in line and "crank" not in line


# ----------------------------------------------------------------- naming the scene


def _chain(n):
    links = "".join(
        f'"{a}-P{i}" = 66\n"{b}-P{i}" = 56\n'
        for i, (a, b) in enumerate(
            zip(["B", "C"] + [f"P{k}" for k in range(n)], ["C"] + [f"P{k}" for k in range(n)])
        )
    )
    return (
        "[ground]\nA = [0, 0]\nD = [100, 0]\n[links]\nAB = 50\nBC = 66\nCD = 56\n"
        + links
        + '[input]\ncrank = "AB"\nangle = 60\nspeed = "10 rad/s cw"\n'
    )


def test_too_many_centres_to_list_names_the_scene(tmp_path, capsys):
    """Each dyad adds two links: 20 dyads, 2 + 2 * 20 + 2 = 44 bodies, past 30."""
    path = tmp_path / "chain.toml"
    path.write_text(_chain(20))
    assert main(["centres", str(path)]) == 2
    assert "instantaneous centres" in _one_line(capsys, path)


def test_a_diagram_too_large_for_its_paper_names_the_scene(tmp_path, capsys):
    out = tmp_path / "d.svg"
    assert main(["draw", SEED, "-o", str(out), "--scale", "1 cm = 1 mm"]) == 2
    assert "--scale" in _one_line(capsys, SEED) and not out.exists()


GEARS = """[ground]
O1 = [0, 0]
O2 = [300, 0]
[links]
"O1-A" = 40
"O2-B" = 60
[rolling]
"O2-B" = { on = "O1-A", angle = 90 }
[input]
crank = "O1-A"
angle = 20
speed = "100 rpm ccw"
"""


def test_a_large_gear_is_drawn_on_a4_at_a_scale_that_holds_its_pitch_circle(tmp_path, capsys):
    """O2-B (pitch radius 60) meshes with the gear about O1 300 away: its pitch radius is
    240, and the circles span x = -240 to 360 mm, 600 mm. The joints alone set 1 cm =
    25 mm: 28.8 cm, refused on A4. 600 mm in 18 cm: the round scale 1 cm = 50 mm."""
    path = tmp_path / "gears.toml"
    path.write_text(GEARS)
    assert main(["draw", str(path), "-o", str(tmp_path / "g.svg")]) == 0
    assert "configuration 1 cm = 50 mm" in capsys.readouterr().out


# ----------------------------------------------------------------- the engine's cycle


@pytest.mark.parametrize(
    "old, new, key, words",
    [
        ("40.0, 32.0", "1e303, 32.0", "[indicator] pressure", "absurd"),  # 7 GB, then nan
        ("40.0, 32.0", "1e6, 32.0", "[indicator] pressure", "absurd"),  # 1e11 Pa
        ('plus_minus = "1%"', "coefficient = 1e-300", "[flywheel] coefficient", "steady"),
    ],
)
@pytest.mark.parametrize("command", [["solve"], ["sweep", "--steps", "8", "--summary"]])
def test_an_engine_cycle_of_absurd_numbers_is_refused(
    tmp_path, capsys, old, new, key, words, command
):
    path = tmp_path / "engine.toml"
    path.write_text(FLYWHEEL.replace(old, new))
    assert main([command[0], str(path), *command[1:]]) == 2
    assert words in _one_line(capsys, path, key)


def test_a_flywheel_on_no_engine_names_its_table_once(tmp_path, capsys):
    path = tmp_path / "s.toml"
    path.write_text(
        Path(SEED)
        .read_text()
        .replace("[answers]", '[flywheel]\nplus_minus = "1%"\nradius = 150\n[answers]', 1)
    )
    assert main(["solve", str(path)]) == 2
    line = _one_line(capsys, path)
    assert line.count("[flywheel]") == 1 and "engine" in line


def test_warnings_pass_as_they_come_and_are_never_held(monkeypatch):
    """The command line once recorded every warning until the command ended (a numpy
    warning at each of millions of points held gigabytes)."""
    from polygon_method.cli import _glyphs

    seen = []
    monkeypatch.setattr(warnings, "showwarning", lambda *a, **k: seen.append(str(a[0])))
    with _glyphs("solve"):
        with warnings.catch_warnings():
            warnings.simplefilter("always")
            warnings.warn("first", RuntimeWarning)
            assert seen == ["first"]  # shown at once, not at the end
            warnings.warn(
                "Glyph 26725 (\\N{CJK UNIFIED IDEOGRAPH-6A5F}) missing from font(s) DejaVu Sans.",
                UserWarning,
            )
            assert seen == ["first"]


# ----------------------------------------------------------------- generated mutations

_FILES = sorted((ROOT / "worked_problems").glob("*.toml")) + sorted(
    (ROOT / "tests/textbook").glob("*.toml")
)
_NUMBER = [
    0,
    -1,
    1e-300,
    1e300,
    float("nan"),
    float("inf"),
    True,
    "5 furlong",
    [],
    {},
    "",
    "1e400",
    "0 rpm",
    "\uff15\uff10",
]
_TEXT = ["", "nan", "inf", "1e400 mm", "5 furlong", 0, True, [], "0 rpm cw", "\u03a9"]
_LIST = [[], [1], ["a", "b"], [float("nan"), 0], [1e300, 0], 5]


def _value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float) and not math.isfinite(v):
        return "nan" if v != v else ("inf" if v > 0 else "-inf")
    if isinstance(v, (int, float)):
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    return "{ " + ", ".join(f"{json.dumps(k)} = {_value(x)}" for k, x in v.items()) + " }"


def _toml(doc) -> str:
    lines = [f"{json.dumps(k)} = {_value(v)}" for k, v in doc.items() if not isinstance(v, dict)]
    for k, v in doc.items():
        if isinstance(v, dict):
            lines += [f"[{json.dumps(k)}]"] + [
                f"{json.dumps(a)} = {_value(b)}" for a, b in v.items()
            ]
    return "\n".join(lines) + "\n"


def _leaves(d, path=()):
    for k, v in d.items():
        if isinstance(v, dict):
            yield from _leaves(v, path + (k,))
        else:
            yield path + (k,), v


def _mutations(per_file=4):
    """Each scene's values, a few at a time, replaced by a wrong type, NaN, infinity, zero,
    an absurd size or an unknown unit (chosen by a seeded draw: the same cases each run)."""
    out = []
    for f in _FILES:
        doc = tomllib.loads(f.read_text(encoding="utf-8"))
        leaves = [(p, v) for p, v in _leaves(doc) if p[0] not in ("title", "source", "notes")]
        rnd = random.Random(f.name)
        for path, v in rnd.sample(leaves, min(per_file, len(leaves))):
            pool = _LIST if isinstance(v, list) else _TEXT if isinstance(v, str) else _NUMBER
            bad = rnd.choice(pool)
            out.append(
                pytest.param(
                    str(f.relative_to(ROOT)),
                    path,
                    bad,
                    id=f"{f.parent.name}-{f.stem}-{'.'.join(path)}",
                )
            )
    return out


@pytest.mark.parametrize("name, path, bad", _mutations())
def test_a_mutated_scene_is_solved_finitely_or_refused_in_one_line(
    tmp_path, capsys, name, path, bad
):
    doc = tomllib.loads((ROOT / name).read_text(encoding="utf-8"))
    target = doc
    for k in path[:-1]:
        target = target[k]
    target[path[-1]] = copy.deepcopy(bad)
    scene = tmp_path / "scene.toml"
    scene.write_text(_toml(doc), encoding="utf-8")
    code = main(["solve", "--json", str(scene)])
    if code == 0:
        json.loads(capsys.readouterr().out, parse_constant=_refuse)
    else:
        assert code == 2
        _one_line(capsys, scene)
