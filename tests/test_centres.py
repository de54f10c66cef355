"""The instantaneous-centre method against the polygon solution (a second method): every
centre is where the two bodies' velocity fields of the polygon solution agree, the three
centres of any three bodies are in line (Kennedy), and the velocities the centres give equal
the polygon's to 1e-9, on every worked problem and on random mechanisms of every kind."""

from __future__ import annotations

import dataclasses
import glob
import json
import math
import re
from pathlib import Path

import pytest
from hypothesis import HealthCheck, assume, given, settings
from hypothesis import strategies as st

from polygon_method import PolygonMethodError, load_scene, solve
from polygon_method.solver.centres import locate
from polygon_method.cli import main

ROOT = Path(__file__).resolve().parent.parent
WORKED = sorted(glob.glob(str(ROOT / "worked_problems" / "*.toml")))


def _field(sol, name):
    """(point on the body, its velocity, omega) from the polygon solution."""
    if name == "ground" or name in sol.plan.fixed_links:
        return (0.0, 0.0), (0.0, 0.0), 0.0
    if name.startswith("block "):
        sl = sol.scene.slider(name.split()[1])  # by its key: a peg has two blocks
        p = sl.point
        if not hasattr(sl, "guide"):  # on a fixed path, or in a translating yoke's slot
            return sol.P[p], sol.V[p], 0.0
        return sol.P[p], sol.V[p], sol.W[sol.scene.link(sl.guide).key]
    if name.startswith(("barrel ", "rod ")):  # a cylinder's barrel (at its pivot), its rod
        part, key = name.split(" ", 1)
        cyl = sol.scene.cylinder(key)
        p = cyl.barrel if part == "barrel" else cyl.rod
        return sol.P[p], sol.V[p], sol.W[cyl.key]
    lk = sol.scene.link(name)
    return sol.P[lk.p], sol.V[lk.p], sol.W[lk.key]


def _v(field, x):
    (kx, ky), (vx, vy), w = field
    return vx - w * (x[1] - ky), vy + w * (x[0] - kx)


def agree(sol, tol=1e-9):
    ic = locate(sol)
    vmax = max(math.hypot(*v) for v in sol.V.values())
    wmax = max(abs(w) for w in sol.W.values())
    L = max(math.hypot(*p) for p in sol.P.values())
    # each centre: the two bodies' velocities agree there (at infinity: the same omega,
    # and a relative translation perpendicular to the centre's direction)
    for (i, j), c in ic.centres.items():
        fi, fj = _field(sol, ic.bodies[i - 1]), _field(sol, ic.bodies[j - 1])
        if c.point is not None:
            a, b = _v(fi, c.point), _v(fj, c.point)
            assert math.hypot(a[0] - b[0], a[1] - b[1]) <= tol * vmax * max(
                1.0, math.hypot(*c.point) / L
            ), (c.label, a, b)
        else:
            assert abs(fi[2] - fj[2]) <= tol * wmax, c.label
            a, b = _v(fi, (0.0, 0.0)), _v(fj, (0.0, 0.0))
            rel = (a[0] - b[0], a[1] - b[1])
            assert abs(rel[0] * c.direction[0] + rel[1] * c.direction[1]) <= tol * vmax
    # Kennedy: any three centres of three bodies are in line
    n = ic.n
    for i in range(1, n + 1):
        for j in range(i + 1, n + 1):
            for k in range(j + 1, n + 1):
                cs = [ic.centre(i, j), ic.centre(j, k), ic.centre(i, k)]
                fin = [c.point for c in cs if c.point is not None]
                if len(fin) == 3:
                    (x1, y1), (x2, y2), (x3, y3) = fin
                    area = (x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)
                    assert (
                        abs(area)
                        <= 1e-7 * L * L * max(1.0, max(math.hypot(*p) for p in fin) / L) ** 2
                    )
    # the velocities the centres give
    for k, name in enumerate(ic.bodies, 1):
        assert abs(ic.omega(k) - _field(sol, name)[2]) <= tol * wmax, name
    for p in sol.scene.point_names:
        v = ic.velocity(p)
        assert math.hypot(v[0] - sol.V[p][0], v[1] - sol.V[p][1]) <= tol * vmax, p
    return ic


# a mechanism of two degrees of freedom has centres Kennedy's theorem does not reach (they
# depend on the ratio of the input speeds): not generated here (tests/test_two_inputs.py)
ONE_INPUT = [p for p in WORKED if "[input.second]" not in Path(p).read_text(encoding="utf-8")]


@pytest.mark.parametrize("path", ONE_INPUT, ids=[Path(p).stem for p in ONE_INPUT])
def test_worked_problems_agree_with_the_polygon(path):
    agree(solve(load_scene(path)))


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(
    which=st.sampled_from(WORKED),
    angle=st.floats(0.0, 360.0),
    scale=st.lists(st.floats(0.85, 1.15), min_size=12, max_size=12),
)
def test_random_mechanisms_of_every_kind_agree(which, angle, scale):
    sc = load_scene(which)
    links = tuple(
        dataclasses.replace(lk, length=lk.length * scale[k % 12])
        if not (lk.p in sc.ground and lk.q in sc.ground)
        else lk
        for k, lk in enumerate(sc.links)
    )
    sc = dataclasses.replace(
        sc, links=links, assembly={}, input=dataclasses.replace(sc.input, angle=math.radians(angle))
    )
    try:
        sol = solve(sc)
        agree(sol)
    except PolygonMethodError:
        assume(False)


def test_a_slider_s_centre_is_at_infinity_perpendicular_to_its_path():
    sol = solve(load_scene(ROOT / "worked_problems" / "offset_slider_crank.toml"))
    ic = locate(sol)
    c = ic.centre(1, 4)
    assert c.at_infinity and c.primary
    sl = sol.scene.sliders[0]
    assert abs(c.direction[0] * sl.u[0] + c.direction[1] * sl.u[1]) < 1e-15


def test_a_translating_coupler_has_its_centre_at_infinity():
    """A parallelogram's coupler translates: I13 is at infinity (parallel lines), given as a
    direction, and omega_3 is exactly 0."""
    from polygon_method import parse_scene

    sol = solve(
        parse_scene("""
    [ground]
    A = [0, 0]
    D = [100, 0]
    [links]
    AB = 40
    BC = 100
    CD = 40
    [assembly]
    C = "above"
    [input]
    crank = "AB"
    angle = 70
    speed = "10 rad/s ccw"
    """)
    )
    ic = agree(sol)
    c = ic.centre(1, 3)
    assert c.at_infinity and not c.primary
    assert ic.omega(3) == 0.0


def test_the_command_and_the_json(capsys):
    path = ROOT / "worked_problems" / "six_link_second_slider.toml"
    assert main(["centres", str(path)]) == 0
    out = capsys.readouterr().out
    assert "N = n (n - 1) / 2 = 6 x 5 / 2 = 15" in out and "Kennedy" in out
    assert main(["solve", str(path), "--json"]) == 0
    d = json.loads(capsys.readouterr().out)
    assert len(d["centres"]) == 15
    for c in d["centres"].values():
        assert ("position" in c) != ("direction" in c)


@pytest.mark.parametrize(
    "name", ["fourbar_image_points", "ellipse_trammel", "rolling_wheel_driver"]
)
def test_the_table_names_body_2_as_the_scene_drives_it(name, capsys, tmp_path):
    """Body 2 is what the scene's [input] drives (read here from the file itself): the crank,
    a driving block, a driving wheel; never "the crank" for a block or a wheel."""
    import tomllib

    path = ROOT / "worked_problems" / f"{name}.toml"
    inp = tomllib.loads(path.read_text())["input"]
    want = (
        "the crank"
        if "crank" in inp
        else f"the driving block {inp['block']}"
        if "block" in inp
        else f"the driving wheel {inp['wheel']}"
    )
    assert main(["centres", str(path)]) == 0
    out = capsys.readouterr().out.splitlines()
    assert f"Links (the ground is 1, {want} 2):" in out
    body2 = out[out.index(f"Links (the ground is 1, {want} 2):") + 2].split(maxsplit=1)
    assert body2 == [
        "2",
        inp["crank"]
        if "crank" in inp
        else f"block {inp['block']}"
        if "block" in inp
        else inp["wheel"],
    ]
    answers = tmp_path / "a.toml"  # a centre past the bodies: the same numbering named
    answers.write_text("[answers]\nI_19 = [0, 0]\n")
    assert main(["check", str(path), str(answers)]) == 2
    assert f"(ground 1, {want} 2)" in capsys.readouterr().err


@pytest.mark.parametrize(
    "name", ["fourbar_image_points", "crank_slotted_lever", "six_link_second_slider"]
)
def test_the_centres_drawing_marks_every_centre(name):
    from polygon_method.draw import render

    sol = solve(load_scene(ROOT / "worked_problems" / f"{name}.toml"))
    svg, used, _ = render(sol, "svg", "centres")
    assert svg == render(sol, "svg", "centres")[0]  # byte-stable
    ic = locate(sol)
    for c in ic.centres.values():
        assert f'id="centre-{c.label}' in svg, c.label
        assert f'id="chord-{c.label}"' in svg, c.label
    assert set(used) == {"centres"}


def _check(text_answers):
    from polygon_method.check import check_answers
    from polygon_method.scene import parse_answers

    sc = load_scene(ROOT / "worked_problems" / "fourbar_image_points.toml")
    sol = solve(sc)
    tol, answers = parse_answers(text_answers, sc)
    return sol, check_answers(sol, answers, tol)


def test_centre_answers_are_checked_against_the_centres():
    sol, vs = _check("[answers]\nI_13 = [76.0, 131.5]\nI_24 = [-213.6, 0]\n")
    assert [v.ok for v in vs] == [True, True]
    ic = locate(sol)
    x, y = ic.centre(2, 4).point
    sol, vs = _check(f"[answers]\nI_13 = [{x * 1e3:.3f}, {y * 1e3:.3f}]\n")
    assert not vs[0].ok and vs[0].mistake == "another_centre" and "I24" in vs[0].diagnosis
    sol, vs = _check("[answers]\nI_ground_BC = [76.0, 131.5]\nI_AB_CD = [-213.6, 0]\n")
    assert [v.ok for v in vs] == [True, True]
    sol, vs = _check('[answers]\ntolerance = "40 %"\nI_13 = [100, 150]\n')
    assert vs[0].ok and "stated" in vs[0].rule


@pytest.mark.parametrize(
    "line, words",
    [
        ("I_11 = [0, 0]", "two different link numbers"),
        ("I_1x = [0, 0]", "two different link numbers"),
        ("I_13 = 5", "position [x, y]"),
        ('I_13 = [1, "a"]', "position [x, y]"),
    ],
)
def test_bad_centre_answers_are_one_clear_error(line, words):
    from polygon_method import SceneError

    with pytest.raises(SceneError, match=re.escape(words)):
        _check(f"[answers]\n{line}\n")


def test_a_centre_of_a_link_that_is_not_there(capsys, tmp_path):
    answers = tmp_path / "a.toml"
    answers.write_text("[answers]\nI_15 = [0, 0]\n")
    code = main(
        ["check", str(ROOT / "worked_problems" / "fourbar_image_points.toml"), str(answers)]
    )
    err = capsys.readouterr().err
    assert code == 2 and "there are 4 links" in err and len(err.strip().splitlines()) == 1


def test_centres_labelled_as_the_course_writes_them(capsys, tmp_path):
    sol = solve(load_scene(ROOT / "worked_problems" / "fourbar_image_points.toml"))
    plain = locate(sol, prefix="")
    assert [plain.centres[k].label for k in plain.order] == ["12", "14", "23", "34", "13", "24"]
    assert "on the line 12-23" in plain.centre(1, 3).how
    path = ROOT / "worked_problems" / "fourbar_image_points.toml"
    assert main(["centres", str(path), "--centre-labels", "13"]) == 0
    out = capsys.readouterr().out
    assert "  13   (" in out and "I13" not in out
    svg = tmp_path / "c.svg"
    assert (
        main(["draw", str(path), "--diagram", "centres", "--centre-labels", "13", "-o", str(svg)])
        == 0
    )
    text = svg.read_text()
    assert 'id="centre-13"' in text and 'id="centre-I13"' not in text


def test_a_centre_too_far_to_locate_is_one_line_that_says_what_still_works(tmp_path, capsys):
    """The Watt six-bar at 95 deg: I46's lines cross at 0.018 deg. The refusal names the
    centre and its lines, and says the polygons still solve the position, which they do."""
    from polygon_method.cli import main

    text = (Path(__file__).parent / "textbook" / "watt_six_bar.toml").read_text()
    scene = tmp_path / "w.toml"
    scene.write_text(re.sub(r"(?m)^angle = .*$", "angle = 95", text))
    assert main(["centres", str(scene)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "centre I46" in err and "polygons are not affected" in err
    assert main(["steps", str(scene)]) == 0
