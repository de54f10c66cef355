"""Refusals and crashes at the edges: a long chain whose error bounds would overflow, an
answer file nested a thousand levels deep, a correct but huge answer, assembly hints of a
scene in metres, a title the plot font cannot draw, and JSON that never holds NaN or inf.
Expected values come from closed forms, the 50-digit reference (tests/reference.py) or the
same scene in other units, never from the tool's own output."""

from __future__ import annotations

import json
import math
import re

import pytest

from reference import reference_solution
from polygon_method import parse_scene, solve
from polygon_method.cli import main


def _strict(text):
    """JSON as the standard reads it: NaN and Infinity refused."""

    def refuse(name):
        raise ValueError(f"{name} in the JSON")

    return json.loads(text, parse_constant=refuse)


def _chain(n, angle=45.0):
    """A crank and ``n`` blocks, each on a horizontal path 100 mm above the last, joined by
    rods at ``angle`` to the paths: each step divides its bound by sin(angle)."""
    L = 100 / math.tan(math.radians(angle))
    rod = math.hypot(100, L)
    links = ['"O-X0" = 50'] + [f'"X{k - 1}-X{k}" = {rod!r}' for k in range(1, n + 1)]
    sl = [f'X{k} = {{ path = "horizontal", through = [0, {100 * k}] }}' for k in range(1, n + 1)]
    asm = [f"X{k} = [{50 + L * k!r}, {100 * k}]" for k in range(1, n + 1)]
    return (
        'title = "long chain"\nunits = "mm"\n[ground]\nO = [0, 0]\n[links]\n'
        + "\n".join(links)
        + "\n[sliders]\n"
        + "\n".join(sl)
        + "\n[assembly]\n"
        + "\n".join(asm)
        + '\n[input]\ncrank = "O-X0"\nangle = 0\nspeed = "10 rad/s ccw"\n'
    ), L


@pytest.mark.parametrize("n, angle", [(2300, 45.0), (1200, 30.0)])
def test_long_chain_has_no_useful_bound_never_inf(tmp_path, capsys, n, angle):
    text, L = _chain(n, angle)
    f = tmp_path / "chain.toml"
    f.write_text(text)
    assert main(["solve", "--json", str(f)]) == 0
    d = _strict(capsys.readouterr().out)
    # the positions are exact: X_k = (50 + L k, 100 k) mm, every block moving with the crank
    # pin's horizontal speed (the crank at 0 deg: 0.05 x 10 m/s, all the rods translate)
    for k in (1, n // 2, n):
        x, y = d["points"][f"X{k}"]["position"]
        assert x == pytest.approx((50 + L * k) / 1000, rel=1e-9)
        assert y == pytest.approx(k / 10, rel=1e-9)
    eb = d["error_bounds"]
    assert eb["worst"] is None
    assert "no useful bound" in eb["no_useful_bound"]["reason"]
    assert eb["points"][f"X{n}"]["acceleration"] is None
    assert eb["points"]["X1"]["position"] is not None  # the first steps keep theirs
    assert main(["solve", str(f)]) == 0
    out = capsys.readouterr().out
    assert "no useful bound" in out
    assert not re.search(r"\b(inf|nan)\b", out, re.IGNORECASE)


def _deep(depth=1000):
    return "[answers]\nv_A = " + "[" * depth + "]" * depth + "\n"


SCENE = """
title = "four-bar"
units = "mm"
[ground]
O2 = [0, 0]
O4 = [200, 0]
[links]
"O2-A" = 150
"A-B" = 450
"B-O4" = 300
[assembly]
B = "above"
[input]
crank = "O2-A"
angle = {angle!r}
speed = "{w} rad/s ccw"
"""


@pytest.mark.parametrize("depth", [1000, 5000])
def test_deeply_nested_answer_file_is_one_row(tmp_path, capsys, depth):
    scene = tmp_path / "s.toml"
    scene.write_text(SCENE.format(angle=150.0, w=200))
    deep = tmp_path / "class" / "a-deep.toml"
    deep.parent.mkdir()
    deep.write_text(_deep(depth))
    good = tmp_path / "class" / "b-good.toml"
    good.write_text('[answers]\nv_A = "30 m/s"\n')  # omega r = 200 x 0.15
    assert main(["check", str(scene), str(deep)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "nested too deeply" in err[0] and "a-deep.toml" in err[0]
    assert main(["check", str(scene), str(deep.parent)]) == 0
    out = capsys.readouterr().out
    assert "nested too deeply" in out and "1 of 1 answers right" in out
    assert main(["page", str(scene), "--answers", str(deep), "-o", str(tmp_path / "p.html")]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "nested too deeply" in err[0]
    assert not (tmp_path / "p.html").exists()


@pytest.mark.parametrize("d, w", [(2.2e-4, 50.0), (2.2e-4, 200.0), (5e-4, 120.0)])
def test_huge_correct_answer_is_checked_and_warned_of(tmp_path, capsys, d, w):
    # near the toggle of a non-Grashof four-bar alpha runs to 1e10 rad/s^2 and more
    angle = math.degrees(math.acos(2 / 3)) + d
    sc = parse_scene(SCENE.format(angle=angle, w=w))
    ref = reference_solution(sc, dict(solve(sc).P))
    al = float(ref["alpha"]["B-O4"])
    assert abs(al) > 1e9  # the family applies: beyond the plausibility limit
    f = tmp_path / "s.toml"
    f.write_text(SCENE.format(angle=angle, w=w))
    ans = tmp_path / "a.toml"
    ans.write_text(
        f'[answers]\ntolerance = "0.1%"\nalpha_B-O4 = "{abs(al):.6e} rad/s^2 '
        f'{"ccw" if al > 0 else "cw"}"\n'
    )
    assert main(["check", "--json", str(f), str(ans)]) == 0
    got = _strict(capsys.readouterr().out)
    (v,) = got["answers"]
    assert v["verdict"] == "right" and "far beyond" in v["warning"]
    assert main(["check", str(f), str(ans)]) == 0
    out = capsys.readouterr().out
    assert sum("warning: alpha_B-O4" in line for line in out.splitlines()) == 1


VARIED = """
title = "small four-bar"
units = "{u}"
[ground]
A = [0, 0]
D = [{d}, 0]
[links]
AB = {ab}
BC = {bc}
CD = {cd}
[assembly]
C = [{cx}, {cy}]
[input]
crank = "AB"
angle = 60
speed = "10.5 rad/s cw"
[answers]
v_C = "0.5 m/s"
[variants]
BC = [{bc1}, {bc}, {bc2}]
CD = [{cd1}, {cd}, {cd2}]
angle = [50, 60, 70]
"""


@pytest.mark.parametrize("size", [(40, 20, 30, 25, 30, 20), (60, 25, 50, 45, 50, 30)])
def test_variants_do_not_depend_on_the_unit(tmp_path, capsys, size):
    d, ab, bc, cd, cx, cy = size
    counts = []
    for u, k in (("mm", 1.0), ("m", 1e-3), ("cm", 0.1)):
        f = tmp_path / f"s-{u}.toml"
        f.write_text(
            VARIED.format(
                u=u,
                d=d * k,
                ab=ab * k,
                bc=bc * k,
                cd=cd * k,
                cx=cx * k,
                cy=cy * k,
                bc1=(bc - 1) * k,
                bc2=(bc + 1) * k,
                cd1=(cd - 1) * k,
                cd2=(cd + 1) * k,
            )
        )
        # 27 combinations, less the base problem's own (a variant is never the base)
        code = main(["variants", str(f), "--count", "26", "-o", str(tmp_path / u)])
        out = capsys.readouterr()
        assert code == 0, out.err
        counts.append(len(list((tmp_path / u).glob("variant-*.toml"))))
        # each variant's hint chooses the branch it was made on: it solves as written
        for v in sorted((tmp_path / u).glob("variant-*.toml"))[:5]:
            assert main(["solve", str(v)]) == 0
            capsys.readouterr()
    assert counts == [26, 26, 26]


@pytest.mark.parametrize("title", ["Vier-Gelenk 機構", "Четырёхзвенник ꙮ 𝔐 㐀"])
def test_title_the_font_lacks_is_said_once(tmp_path, capsys, recwarn, title):
    f = tmp_path / "s.toml"
    f.write_text(SCENE.format(angle=150.0, w=10).replace('"four-bar"', f'"{title}"'))
    assert main(["sweep", str(f), "--steps", "36", "--plot", str(tmp_path / "p.png")]) == 0
    err = capsys.readouterr().err
    assert err.count("no glyph") == 1 and "Glyph" not in err
    assert main(["draw", str(f), "--animate", "--frames", "4", "-o", str(tmp_path / "a.gif")]) == 0
    err = capsys.readouterr().err
    assert err.count("no glyph") == 1
    v = tmp_path / "v.toml"
    v.write_text(
        VARIED.format(
            u="mm", d=40, ab=20, bc=30, cd=25, cx=30, cy=20, bc1=29, bc2=31, cd1=24, cd2=26
        ).replace("small four-bar", title)
    )
    assert main(["variants", str(v), "--count", "2", "--pdf", "-o", str(tmp_path / "class")]) == 0
    err = capsys.readouterr().err
    assert err.count("no glyph") == 1 and "Glyph" not in err
    assert not [w for w in recwarn if "Glyph" in str(w.message)]


@pytest.mark.parametrize(
    "text",
    [
        _chain(2200)[0],
        SCENE.format(angle=math.degrees(math.acos(2 / 3)) + 2.2e-4, w=1e5),
        SCENE.format(angle=150.0, w=1e-6),
    ],
)
def test_json_never_holds_nan_or_inf(tmp_path, capsys, text):
    f = tmp_path / "s.toml"
    f.write_text(text)
    code = main(["solve", "--json", str(f)])
    out = capsys.readouterr()
    assert code in (0, 2), out.err
    if code == 0:
        _strict(out.out)
