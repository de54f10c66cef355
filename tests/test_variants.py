"""A variant per student (``variants``) and each student graded against their own
(``check --variants``). Every property is checked against something computed here by
hand: the four-bar's position by intersecting two circles, its transmission angle from
those positions, Grashof's inequality, the velocity loop solved as a 2x2 system, a
slider crank's r + e <= l."""

from __future__ import annotations

import csv
import math
import re
import tomllib

import numpy as np
import pytest

from polygon_method import parse_scene, solve
from polygon_method.cli import main
from polygon_method.common.errors import SceneError
from polygon_method.solver.compiler import compile_plan
from polygon_method.scene import scene_from_table, scene_table
from polygon_method.variants import generate, screen

FOURBAR = """
title = "Four-bar ABCD for a class"
units = "mm"

[ground]
A = [0, 0]
D = [100, 0]

[links]
AB = 30
BC = 90
CD = 70

[points]
E = { on = "BC", along = 40 }

[assembly]
C = "above"

[input]
crank = "AB"
angle = 60
speed = "120 rpm cw"

[answers]
v_C = "0.3 m/s"
omega_BC = "3 rad/s"
alpha_CD = "50 rad/s^2"

[variants]
BC = { from = 40, to = 110, step = 1 }
angle = { from = 0, to = 355, step = 5 }
speed = ["100 rpm", "120 rpm", "150 rpm ccw"]
D = { x = [96, 100, 104] }
E = { along = [30, 40, 50] }
min_condition = "30 deg"
"""

MIN = math.sin(math.radians(30))


def _write(tmp_path, text, name="base.toml"):
    p = tmp_path / name
    p.write_text(text)
    return p


@pytest.fixture(scope="module")
def made():
    sc = parse_scene(FOURBAR, file="base.toml")
    return sc, generate(sc, 40, 7)


def _dims(text):
    """(AB, BC, CD, D, angle, omega) read from a variant's own TOML, by hand."""
    raw = tomllib.loads(text)
    om = raw["input"]["speed"].split()
    w = float(om[0]) * 2 * math.pi / 60 * (1 if om[2] == "ccw" else -1)
    return (
        raw["links"]["AB"],
        raw["links"]["BC"],
        raw["links"]["CD"],
        tuple(raw["ground"]["D"]),
        math.radians(raw["input"]["angle"]),
        w,
        raw["points"]["E"]["along"],
    )


def _fourbar_by_hand(ab, bc, cd, d, theta, w):
    """C above (of the two circle intersections, the one with larger y), omegas of BC and
    CD from the velocity loop, all in mm and rad/s."""
    bx, by = ab * math.cos(theta), ab * math.sin(theta)
    dx, dy = d
    ex, ey = dx - bx, dy - by
    e = math.hypot(ex, ey)
    a = (bc * bc - cd * cd + e * e) / (2 * e)
    h = math.sqrt(bc * bc - a * a)
    mx, my = bx + a * ex / e, by + a * ey / e
    c1 = (mx - h * ey / e, my + h * ex / e)
    c2 = (mx + h * ey / e, my - h * ex / e)
    cx, cy = max(c1, c2, key=lambda c: c[1])
    # transmission angle at C between CB and CD
    u = (bx - cx, by - cy)
    v = (dx - cx, dy - cy)
    sin_mu = abs(u[0] * v[1] - u[1] * v[0]) / (bc * cd)
    # v_B + w3 x BC = w4 x DC
    vbx, vby = -w * by, w * bx
    # w3 (-(cy-by), cx-bx) - w4 (-(cy-dy), cx-dx) = -v_B
    m = np.array([[-(cy - by), (cy - dy)], [cx - bx, -(cx - dx)]])
    w3, w4 = np.linalg.solve(m, [-vbx, -vby])
    vc = abs(w4) * cd * 1e-3
    return (cx, cy), sin_mu, w3, w4, vc


def test_every_variant_reads_solves_and_keeps_away_from_singular_positions(made):
    sc, vs = made
    assert len(vs.variants) == 40
    for v in vs.variants:
        again = parse_scene(v.text, file=v.name)  # the file as written reads back
        assert again.variation is None and again.variant.id == v.id
        assert again.variant.of == sc.title
        sol = solve(again)
        ab, bc, cd, d, theta, w, _ = _dims(v.text)
        (cx, cy), sin_mu, w3, w4, vc = _fourbar_by_hand(ab, bc, cd, d, theta, w)
        assert sol.P["C"] == pytest.approx((cx * 1e-3, cy * 1e-3), rel=1e-12)
        assert sin_mu >= MIN  # well away from the toggle
        assert min(sol.conditions.values()) == pytest.approx(sin_mu, rel=1e-9)
        assert sol.omega("BC") == pytest.approx(w3, rel=1e-9)
        assert sol.omega("CD") == pytest.approx(w4, rel=1e-9)
        assert sol.speed("C") == pytest.approx(vc, rel=1e-9)


def test_the_class_is_kept_by_grashofs_inequality(made):
    _, vs = made
    for v in vs.variants:
        ab, bc, cd, d, *_ = _dims(v.text)
        ad = math.hypot(*d)
        s, *pq, l = sorted([ab, bc, cd, ad])
        assert s + l < sum(pq) and s == ab  # Grashof, the crank shortest: crank-rocker


def test_ranges_are_respected_and_no_two_variants_are_the_same(made):
    _, vs = made
    seen = set()
    for v in vs.variants:
        ab, bc, cd, d, theta, w, along = _dims(v.text)
        assert 40 <= bc <= 110 and bc == int(bc)
        deg = math.degrees(theta)
        assert 0 <= deg <= 355 and abs(deg / 5 - round(deg / 5)) < 1e-9
        assert d[0] in (96, 100, 104) and d[1] == 0
        assert along in (30, 40, 50)
        assert round(abs(w) * 60 / (2 * math.pi), 9) in (100, 120, 150)
        assert (w > 0) == (round(abs(w) * 60 / (2 * math.pi)) == 150)  # base sense kept
        assert (ab, cd) == (30, 70)  # what does not vary stays
        key = (bc, round(deg, 9), round(w, 9), d, along)
        assert key not in seen
        seen.add(key)


def test_the_same_seed_gives_the_same_variants_another_seed_others(made):
    sc, vs = made
    again = generate(parse_scene(FOURBAR, file="base.toml"), 40, 7)
    assert [v.text for v in again.variants] == [v.text for v in vs.variants]
    other = generate(sc, 40, 8)
    assert [v.text for v in other.variants] != [v.text for v in vs.variants]
    assert {v.text for v in other.variants} != {v.text for v in vs.variants}
    first = generate(sc, 5, 7)  # a smaller class gets the first of the same variants
    assert [v.text for v in first.variants] == [v.text for v in vs.variants[:5]]


def test_the_vectorised_screen_agrees_with_solving_each_candidate_alone():
    sc = parse_scene(FOURBAR, file="base.toml")
    plan = compile_plan(sc)
    raw = scene_table(sc)
    raw.pop("variants")
    scenes = []
    rng = np.random.default_rng(3)
    for _ in range(120):  # many fail: BC 40..110 at any crank angle
        r = tomllib.loads(FOURBAR)
        r.pop("variants")
        r["links"]["BC"] = int(rng.integers(40, 111))
        r["input"]["angle"] = int(rng.integers(0, 72)) * 5
        r["ground"]["D"] = [int(rng.choice([96, 100, 104])), 0]
        scenes.append(scene_from_table(r))
    ok, least = screen(plan, scenes, MIN)
    assert 10 < ok.sum() < 110  # both kinds are there
    for k, s in enumerate(scenes):
        ab, bc, cd = (lk.length * 1e3 for lk in s.links)
        d = (s.ground["D"][0] * 1e3, 0.0)
        bx, by = ab * math.cos(s.input.angle), ab * math.sin(s.input.angle)
        e = math.hypot(d[0] - bx, d[1] - by)
        assembles = abs(bc - cd) < e < bc + cd
        if not assembles:
            assert not ok[k]
            continue
        _, sin_mu, *_ = _fourbar_by_hand(ab, bc, cd, d, s.input.angle, -12.566)
        assert bool(ok[k]) == (sin_mu >= MIN)
        if sin_mu > 1e-3:  # a plain solve gives the same least condition
            assert least[k] == pytest.approx(min(solve(s).conditions.values()), rel=1e-12)
            assert least[k] == pytest.approx(sin_mu, rel=1e-9)


def test_a_slider_crank_keeps_its_crank_turning_fully():
    text = """
title = "Offset engine"
[ground]
O = [0, 0]
[links]
OA = 50
AB = 120
[sliders]
B = { path = "horizontal", through = [0, 20] }
[input]
crank = "OA"
angle = 30
speed = "300 rpm ccw"
[variants]
OA = { from = 40, to = 110, step = 2 }
B = { y = { from = -40, to = 40, step = 5 } }
angle = { from = 10, to = 170, step = 10 }
"""
    vs = generate(parse_scene(text), 25, 1)
    assert len(vs.variants) == 25
    for v in vs.variants:
        raw = tomllib.loads(v.text)
        r, ell, e = raw["links"]["OA"], raw["links"]["AB"], raw["sliders"]["B"]["through"][1]
        assert r + abs(e) <= ell  # the crank still turns fully
        sol = solve(v.scene)
        assert min(sol.conditions.values()) >= math.sin(math.radians(15))


def test_cli_writes_scenes_key_and_sheet_and_check_pairs_each_student(tmp_path):
    base = _write(tmp_path, FOURBAR)
    out = tmp_path / "class"
    assert (
        main(["variants", str(base), "--count", "8", "--seed", "7", "-o", str(out), "--pdf"]) == 0
    )
    names = sorted(p.name for p in out.iterdir())
    assert names == ["answer-key.csv", "answer-key.md", "problem-sheet.md", "problem-sheet.pdf"] + [
        f"variant-{k:02d}.toml" for k in range(1, 9)
    ]
    pdf = (out / "problem-sheet.pdf").read_bytes()
    assert pdf.startswith(b"%PDF") and len(re.findall(rb"/Type /Page\b", pdf)) == 8
    rows = list(csv.DictReader((out / "answer-key.csv").open()))
    assert [r["variant"] for r in rows] == [f"{k:02d}" for k in range(1, 9)]
    for r in rows:  # the key against the loop equations solved by hand (written in full:
        text = (out / r["file"]).read_text()  # 10 figures would be off by up to 5e-11)
        *_, w3, w4, vc = _fourbar_by_hand(*_dims(text)[:6])
        assert float(r["v_C (m/s)"]) == pytest.approx(vc, rel=1e-12)
        assert float(r["omega_BC (rad/s)"]) == pytest.approx(w3, rel=1e-12)
    sheet = (out / "problem-sheet.md").read_text()
    assert sheet.count("## Variant ") == 8 and 'variant = "07"' in sheet
    # a student's correct answers to variant 07
    key = {r["variant"]: r for r in rows}
    answers = tmp_path / "answers"
    answers.mkdir()
    right7 = (
        f'[answers]\nv_C = "{float(key["07"]["v_C (m/s)"]):.4f} m/s"\n'
        f'omega_BC = "{abs(float(key["07"]["omega_BC (rad/s)"])):.4f} rad/s"\n'
    )
    (answers / "ann.toml").write_text('variant = "07"\n' + right7)
    (answers / "bob.toml").write_text('variant = "variant-03.toml"\n' + right7)
    (answers / "eve.toml").write_text('variant = "Variant 7"\n' + right7)
    (answers / "cy.toml").write_text(right7)  # names no variant
    (answers / "dee.toml").write_text('variant = "77"\n' + right7)
    book = tmp_path / "book.csv"
    assert (
        main(["check", str(base), str(answers), "--variants", str(out), "--gradebook", str(book)])
        == 0
    )
    graded = {r["student"]: r for r in csv.DictReader(book.open())}
    assert graded["ann"]["variant"] == "07" and graded["ann"]["right"] == "2"
    assert graded["bob"]["variant"] == "03" and graded["bob"]["v_C"].startswith("WRONG")
    assert graded["cy"]["error"] and "names no variant" in graded["cy"]["error"]
    assert graded["dee"]["variant"] == "77" and "not in" in graded["dee"]["error"]
    assert graded["eve"]["variant"] == "07" and graded["eve"]["right"] == "2"
    # one file: 0 against its own variant, 1 against another
    assert main(["check", str(base), str(answers / "ann.toml"), "--variants", str(out)]) == 0
    assert main(["check", str(out / "variant-07.toml"), str(answers / "ann.toml")]) == 0
    assert main(["check", str(base), str(answers / "bob.toml"), "--variants", str(out)]) == 1
    # named but graded without its variant: one clear line
    assert main(["check", str(base), str(answers / "ann.toml")]) == 2


def test_too_few_variants_is_one_line_and_writes_nothing(tmp_path, capsys):
    text = (
        FOURBAR.replace("BC = { from = 40, to = 110, step = 1 }", "BC = [88, 90]")
        .replace("angle = { from = 0, to = 355, step = 5 }", "angle = [60]")
        .replace("D = { x = [96, 100, 104] }\n", "")
        .replace("E = { along = [30, 40, 50] }\n", "")
    )
    base = _write(tmp_path, text)
    out = tmp_path / "out"
    # 6 combinations, one of them the base problem itself (no variant): 5
    assert main(["variants", str(base), "--count", "6", "-o", str(out)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "only 5 of the 6 combinations" in err and "--count 5" in err
    assert "the base problem itself: 1" in err
    assert not out.exists()
    assert main(["variants", str(base), "--count", "5", "-o", str(out)]) == 0
    assert len(list(out.glob("variant-*.toml"))) == 5


@pytest.mark.parametrize(
    "line, words",
    [
        ("BX = [60, 62]", "no link BX in [links] to vary (did you mean 'BC'?)"),
        ("BC = { from = 75, to = 60, step = 1 }", "the range is empty"),
        ("BC = { from = 60, to = 75, step = 0 }", "step = 0 must be positive"),
        ("BC = []", "the list of values is empty"),
        ('speed = ["100 rmp"]', "unknown unit 'rmp'"),
        ('BC = ["60 rpm"]', "'rpm' is a unit of angular velocity, not of length"),
        ("E = { alng = [1] }", "unknown key 'alng' (did you mean 'along'?)"),
        ("min_condition = 1.5", "a sine between 0 and 1"),
        ("A = { z = [1] }", "unknown key 'z'"),
        ("BC = { from = 60, to = 75 }", "the range has no step"),
        ("BC = { from = 60, to = 75, step = 5e-324 }", "holds more than 10000 values"),
    ],
)
def test_a_bad_variants_table_is_one_located_line(tmp_path, capsys, line, words):
    text = FOURBAR.split("[variants]")[0] + "[variants]\n" + line + "\n"
    n = text.splitlines().index(line) + 1
    base = _write(tmp_path, text)
    assert main(["variants", str(base), "-o", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1
    assert f"base.toml: [variants] {line.split()[0]} (line {n}): " in err
    assert words in err


def test_a_scene_without_variants_is_one_clear_line(tmp_path, capsys):
    base = _write(tmp_path, FOURBAR.split("[variants]")[0])
    assert main(["variants", str(base), "-o", str(tmp_path / "out")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "no [variants] table" in err
    with pytest.raises(SceneError):
        generate(parse_scene(FOURBAR.split("[variants]")[0]), 3, 0)


def test_the_worked_problems_variants_table_changes_no_solution(capsys):
    """The seed four-bar states [variants]: its solve --json is that of the scene without
    the table, and 40 variants of it exist (it stays a triple rocker)."""
    from pathlib import Path

    path = Path(__file__).parent.parent / "worked_problems" / "fourbar_image_points.toml"
    text = path.read_text()
    assert "[variants]" in text
    with_table = solve(parse_scene(text)).to_dict()
    without = solve(parse_scene(text.split("[variants]")[0])).to_dict()
    assert with_table == without
    vs = generate(parse_scene(text), 40, 7)
    assert len(vs.variants) == 40 and vs.linkage == "four-bar: non-Grashof triple rocker"
    for v in vs.variants:
        raw = tomllib.loads(v.text)
        s, *pq, l = sorted([raw["links"]["AB"], raw["links"]["BC"], raw["links"]["CD"], 100])
        assert s + l > sum(pq)


def test_a_rough_position_hint_follows_each_variants_own_figure():
    """Whitworth's lever end P is placed by a rough position read off the base figure; in
    each variant it is that variant's own P, on the base scene's branch."""
    from pathlib import Path

    text = (Path(__file__).parent.parent / "worked_problems" / "whitworth.toml").read_text()
    text += "\n[variants]\nangle = { from = 0, to = 355, step = 5 }\n"
    base = parse_scene(text)
    assert isinstance(base.assembly["P"], tuple)
    sigma = [getattr(st, "sigma", None) for st in compile_plan(base).steps]
    vs = generate(base, 12, 3)
    for v in vs.variants:
        hint = tomllib.loads(v.text)["assembly"]["P"]
        sol = solve(v.scene)
        assert [c * 1e3 for c in sol.P["P"]] == pytest.approx(hint, abs=0.051)
        assert [getattr(st, "sigma", None) for st in compile_plan(v.scene).steps] == sigma
        # the slotted lever passes through the block: O4, A and P in line
        (ox, oy), (ax, ay), (px, py) = sol.P["O4"], sol.P["A"], sol.P["P"]
        assert abs((ax - ox) * (py - oy) - (ay - oy) * (px - ox)) < 1e-12


from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402

_leaf = st.one_of(
    st.integers(-(10**6), 10**6),
    st.floats(allow_nan=True, allow_infinity=True),
    st.booleans(),
    st.sampled_from(["60 mm", "100 rpm", "15 deg", "x", "", "3 rad/s ccw", "-5 cm", "1e9 m"]),
)
_value = st.recursive(
    _leaf,
    lambda inner: st.one_of(
        st.lists(inner, max_size=4),
        st.dictionaries(
            st.sampled_from(
                [
                    "from",
                    "to",
                    "step",
                    "unit",
                    "x",
                    "y",
                    "along",
                    "distances",
                    "B",
                    "C",
                    "diameter",
                    "force",
                    "z",
                ]
            ),
            inner,
            max_size=4,
        ),
    ),
    max_leaves=8,
)
_keys = st.sampled_from(
    [
        "BC",
        "CD",
        "AB",
        "angle",
        "speed",
        "acceleration",
        "min_condition",
        "A",
        "D",
        "E",
        "B",
        "C",
        "Q",
        "BX",
        "O2-A",
        "id",
    ]
)


@settings(max_examples=150, deadline=None)
@given(
    table=st.dictionaries(_keys, _value, max_size=4),
    variant=st.one_of(
        st.none(), st.dictionaries(st.sampled_from(["id", "of", "seed", "q"]), _leaf, max_size=3)
    ),
)
def test_any_variants_table_reads_or_is_one_scene_error(table, variant):
    """Whatever [variants] and [variant] hold: a scene, or a SceneError naming the table;
    never another exception."""
    raw = tomllib.loads(FOURBAR.split("[variants]")[0])
    raw["pins"] = {"B": {"diameter": 20}}
    raw["variants"] = table
    if variant is not None:
        raw["variant"] = variant
    try:
        sc = scene_from_table(raw)
    except SceneError as exc:
        assert exc.key and ("variant" in exc.key or "[variants]" in exc.key)
        return
    if sc.variation is not None:
        assert sc.variation.varied and 0 < sc.variation.min_condition < 1
        for v in sc.variation.varied:
            assert len(v.values) == len(v.si) == len(set(v.si)) >= 1
            assert all(math.isfinite(x) for x in v.si)


def test_variants_output_directory_rules(tmp_path, capsys):
    base = _write(tmp_path, FOURBAR)
    afile = tmp_path / "a.txt"
    afile.write_text("keep")
    assert main(["variants", str(base), "--count", "3", "-o", str(afile)]) == 2
    assert "not a directory" in capsys.readouterr().err and afile.read_text() == "keep"
    assert main(["variants", str(base), "--count", "3", "-o", str(tmp_path / "no" / "such")]) == 2
    assert "no directory" in capsys.readouterr().err
    out = tmp_path / "class"
    assert main(["variants", str(base), "--count", "4", "--seed", "1", "-o", str(out)]) == 0
    first = (out / "variant-01.toml").read_text()
    capsys.readouterr()
    # a smaller class into the same directory would leave variant-04 of the earlier run
    assert main(["variants", str(base), "--count", "3", "--seed", "2", "-o", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "variant-04.toml" in err
    assert (out / "variant-01.toml").read_text() == first  # nothing was replaced
    assert main(["variants", str(base), "--count", "4", "--seed", "2", "-o", str(out)]) == 0
    assert (out / "variant-01.toml").read_text() != first
    assert main(["variants", str(base), "--count", "0", "-o", str(out)]) == 2
