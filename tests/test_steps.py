"""Step tables: the numbers printed are the solution's numbers; scales are textbook-round.

The printed values are parsed back out of the Markdown and compared with the solution (to
the printed precision) and, for the input link, with the hand arithmetic
(omega = 2 pi N / 60, v = omega r). Scale choice is checked against a brute-force search.
"""

import math
import re
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from polygon_method import load_scene, parse_scene, solve
from polygon_method.cli import main
from polygon_method.polygons.scales import choose_scale, diagram_scales, extent, parse_scale
from polygon_method.text.steptable import read_off, steps_text
from scenes import seed

ROOT = Path(__file__).resolve().parent.parent
WORKED = sorted((ROOT / "worked_problems").glob("*.toml"))
TOGGLE = ROOT / "worked_problems" / "toggle_mechanism.toml"

FOURBAR = seed(
    top='title = "four-bar"\n',
    middle='[points]\nE = { on = "BC", along = 40 }\n[assembly]\nC = "above"\n',
    drive='angle = 60\nspeed = "10.5 rad/s cw"\nacceleration = "40 rad/s^2 ccw"',
    after="[pins]\nB = { diameter = 80 }\nC = { radius = 25 }\n",
)

SLOTTED = """
[ground]
O4 = [0, 0]
O2 = [0, 300]
[links]
"O2-A" = 120
"O4-P" = 600
[sliders]
A = { along = "O4-P" }
[assembly]
P = "above"
[input]
crank = "O2-A"
angle = 45
speed = "60 rpm cw"
"""


def close(printed: str, exact: float, digits: int = 4) -> bool:
    """``printed`` is ``exact`` to the printed number of significant figures."""
    x = float(printed)
    return (
        abs(x - exact) <= 0.51 * 10 ** (math.floor(math.log10(abs(exact))) - digits + 1)
        if exact
        else x == 0
    )


def tables(md: str):
    """Every Markdown table as (header, rows)."""
    out = []
    for block in md.split("\n\n"):
        lines = [ln for ln in block.splitlines() if ln.startswith("|")]
        if len(lines) >= 2:
            cells = [[c.strip() for c in re.split(r"(?<!\\)\|", ln)[1:-1]] for ln in lines]
            out.append((cells[0], cells[2:]))
    return out


def table(md, first):
    return [t for t in tables(md) if t[0][0] == first]


def exact_of(sol, name):
    m = re.match(r"^(v|a|vs|as)_([A-Z0-9-]+)$", name)
    if not m:
        return None
    kind, names = m.group(1), re.findall(r"[A-Z][0-9]*", m.group(2))
    if kind == "vs":
        return abs(sol.sliding_velocity(names[0]))
    if kind == "as":
        return abs(sol.sliding_acceleration(names[0]))
    return (sol.speed if kind == "v" else sol.acceleration_magnitude)(*names)


@pytest.mark.parametrize("source", ["toggle", "fourbar", "slotted"])
def test_read_offs_are_the_solution(source):
    sc = (
        load_scene(TOGGLE)
        if source == "toggle"
        else parse_scene(FOURBAR if source == "fourbar" else SLOTTED)
    )
    sol = solve(sc)
    md = steps_text(sol, fmt="markdown")
    _, vs, acc = diagram_scales(sol)
    checked = 0
    for (header, rows), scale in zip(table(md, "vector"), (vs, acc)):
        assert header == ["vector", "on the diagram", "length (cm)", "read", "exact"]
        for name, _, cm, read, ex in rows:
            value = float(ex.split()[0])
            truth = exact_of(sol, name)
            if truth is not None:
                assert close(ex.split()[0], truth), (name, ex, truth)
                checked += 1
            # the length is the drawn one, to 0.05 cm; 'read' is that length at the scale
            assert abs(float(cm) - value / scale.per_cm) <= 0.025 + 0.006
            assert float(read.split()[0]) == pytest.approx(
                float(cm) * scale.per_cm, rel=6e-3, abs=1e-12
            )
    assert checked >= 4


def test_angular_velocities_and_accelerations_lines():
    sol = solve(parse_scene(FOURBAR))
    text = steps_text(sol)
    flat = " ".join(text.split())
    for key in ("BC", "CD"):
        m = re.search(
            rf"omega_{key} = v_\w+ / {key} = ([\d.]+) / ([\d.]+) = ([\d.]+) rad/s "
            r"(cw|ccw)",
            flat,
        )
        assert m, key
        a, b, w, sense = float(m[1]), float(m[2]), m[3], m[4]
        assert close(w, abs(sol.omega(key)))
        assert sense == ("ccw" if sol.omega(key) > 0 else "cw")
        assert a / b == pytest.approx(float(w), rel=1e-3)
        assert b == pytest.approx(sol.scene.link(key).length)
        m = re.search(
            rf"alpha_{key} = tangential of a_\w+ / {key} = ([\d.]+) / ([\d.]+) = "
            r"([\d.]+) rad/s\^2 (cw|ccw)",
            flat,
        )
        assert m, key
        assert close(m[3], abs(sol.alpha(key)))
        assert m[4] == ("ccw" if sol.alpha(key) > 0 else "cw")
    assert "alpha_AB = 40 rad/s^2 ccw (given)" in flat


def test_input_link_arithmetic_is_the_hand_arithmetic():
    sol = solve(load_scene(TOGGLE))
    flat = " ".join(steps_text(sol).split())
    w = 2 * math.pi * 180 / 60
    m = re.search(
        r"N = 180 rpm; omega_OA = 2 pi N / 60 = 2 pi x 180 / 60 = ([\d.]+) rad/s ccw", flat
    )
    assert m and close(m[1], w)
    m = re.search(
        r"v_A = omega_OA x OA = ([\d.]+) x ([\d.]+) = ([\d.]+) m/s, perpendicular "
        "to OA",
        flat,
    )
    assert m and float(m[2]) == 0.18 and close(m[3], w * 0.18)


def test_rubbing_and_torque_lines():
    sol = solve(load_scene(TOGGLE))
    flat = " ".join(steps_text(sol).split())
    m = re.search(
        r"pin A \(r = 15 mm\), OA and AB: OA and AB both turn ccw: rub = "
        r"\|omega_OA - omega_AB\| r = \|([\d.]+) - ([\d.]+)\| x 0.015 = ([\d.]+) m/s",
        flat,
    )
    assert m
    assert close(m[3], sol.rubbing["A"].rubbing_velocity)
    assert (float(m[1]) - float(m[2])) * 0.015 == pytest.approx(float(m[3]), rel=2e-3)
    m = re.search(
        r"T = -\(sum F \. v\) / omega_OA = ([-\d.]+) / ([-\d.]+) = ([\d.]+) N m "
        r"(cw|ccw)",
        flat,
    )
    assert m and close(m[3], abs(sol.input_torque))
    assert m[4] == ("ccw" if sol.input_torque > 0 else "cw")
    # pin B of the four-bar: AB cw, BC ccw: the sum of the magnitudes
    sol = solve(parse_scene(FOURBAR))
    flat = " ".join(steps_text(sol).split())
    assert "AB turns cw, BC ccw (opposite senses): rub = (omega_AB + omega_BC) r" in flat


def test_acceleration_table_centripetal_and_coriolis():
    sol = solve(parse_scene(SLOTTED))
    md = steps_text(sol, fmt="markdown")
    ((header, rows),) = [t for t in table(md, "link") if t[0][1] == "length (m)"]
    assert header[-1] == "Coriolis (m/s^2)"
    by = {r[0]: r for r in rows}
    for key, row in by.items():
        lk = sol.scene.link(key)
        v, L = re.match(r"([\d.]+)\^2 / ([\d.]+) = ([\d.]+)", row[3]).groups()[:2]
        cen = float(re.search(r"= ([\d.]+)$", row[3])[1])
        assert float(L) == pytest.approx(lk.length)
        assert close(f"{cen}", float(v) ** 2 / float(L), digits=3)
    cor = float(re.search(r"= ([\d.]+) \(block A", by["O4-P"][6])[1])
    assert close(f"{cor}", math.hypot(*sol.coriolis("A")))
    assert by["O2-A"][6] == "-"


def test_markdown_and_text_carry_the_same_numbers():
    sol = solve(load_scene(TOGGLE))
    num = re.compile(r"-?\d+\.\d+")
    md = steps_text(sol, fmt="markdown")
    tx = steps_text(sol, fmt="text")
    assert sorted(num.findall(md)) == sorted(num.findall(tx))
    assert md.startswith("# ") and "## 3. Velocity diagram" in md
    for ln in md.splitlines():
        if ln.startswith("|"):
            assert ln.endswith("|")


@pytest.mark.parametrize("path", WORKED, ids=lambda p: p.stem)
def test_cli_steps_every_worked_problem(path, capsys):
    for fmt in ("text", "markdown"):
        assert main(["steps", str(path), "--format", fmt]) == 0
        out = capsys.readouterr().out
        assert "Velocity scale: 1 cm = " in out and "nan" not in out.lower()


def test_cli_steps_bad_scene(tmp_path, capsys):
    p = tmp_path / "s.toml"
    p.write_text("[ground]\nA = [0, 0]\n")
    assert main(["steps", str(p)]) == 2
    err = capsys.readouterr().err
    assert "Traceback" not in err and len(err.strip().splitlines()) == 1


# --------------------------------------------------------------------------- scales


def brute_scale(magnitude, fit):
    cands = sorted(m * 10.0**k for m in (1, 2, 2.5, 5) for k in range(-12, 12))
    return next(c for c in cands if magnitude / c <= fit * (1 + 1e-12))


@settings(max_examples=200, deadline=None)
@given(st.floats(1e-6, 1e6), st.floats(2, 30))
def test_choose_scale_is_the_smallest_round_scale_that_fits(magnitude, fit):
    s = choose_scale(magnitude, fit, unit="m/s")
    assert s.per_cm == pytest.approx(brute_scale(magnitude, fit), rel=1e-9)
    digits = s.value.replace(".", "").strip("0")
    assert digits in ("1", "2", "25", "5"), s.value
    assert parse_scale(s.text).per_cm == pytest.approx(s.per_cm, rel=1e-12)


def test_scales_of_a_solution_fit_the_page():
    sol = solve(load_scene(TOGGLE))
    space, vs, acc = diagram_scales(sol)
    assert space.text == "1 cm = 50 mm" and space.per_cm == pytest.approx(0.05)
    assert vs.text == "1 cm = 0.5 m/s"  # the crank's 3.393 m/s is 6.79 cm
    pts = [(0.0, 0.0)] + list(sol.A.values())
    size = max(math.dist(p, q) for p in pts for q in pts)
    assert extent(pts) == pytest.approx(size)
    assert size / acc.per_cm <= 12
    assert acc.per_cm == pytest.approx(brute_scale(size, 12))


def test_read_off_rounds_to_half_a_millimetre():
    s = parse_scale("1 cm = 0.05 m/s")
    assert read_off(0.4005, s) == (8.0, pytest.approx(0.4))
    assert read_off(0.3399, s)[0] == 6.8
    assert read_off(0.3412, s)[0] == 6.8  # 6.824 cm
    assert read_off(0.3413, s)[0] == 6.85  # 6.826 cm


def test_space_scale_in_scene_units():
    sol = solve(parse_scene(FOURBAR))
    space, _, _ = diagram_scales(sol)
    assert space.unit == "mm" and space.text == "1 cm = 10 mm"


def test_each_construction_states_where_its_lines_cross():
    """The angle printed for a dyad is the angle between its two links at the joint,
    measured here from the positions (the transmission angle, acute)."""
    import re
    from pathlib import Path

    from polygon_method import load_scene

    path = Path(__file__).parent.parent / "worked_problems" / "toggle_mechanism.toml"
    sol = solve(load_scene(path))
    text = steps_text(sol)
    (ax, ay), (bx, by), (cx, cy) = sol.P["A"], sol.P["B"], sol.P["C"]
    ang = math.degrees(
        abs(
            math.atan2(
                (ax - bx) * (cy - by) - (ay - by) * (cx - bx),
                (ax - bx) * (cx - bx) + (ay - by) * (cy - by),
            )
        )
    )
    acute = min(ang, 180 - ang)
    m = re.search(r"Step 2 \(dyad AB, CB at B\).*?the lines cross at ([0-9.]+) deg", text, re.S)
    assert m and float(m.group(1)) == pytest.approx(acute, abs=0.05)


TEXTBOOK = sorted((ROOT / "tests" / "textbook").glob("*.toml"))


def _gears_only(path):
    """A train of gears (or a planet on an arm) driven by cranks only: each gear's velocity
    follows from no slip at its pitch point (omega by the ratio, v = omega x radius), so no
    direction line is drawn; nor for a point carried on the arm (a second planet's centre:
    found by its image). A wheel on a line is found from a link pinned to it: lines."""
    from polygon_method.solver.compiler import compile_plan

    return all(
        st.kind in ("crank", "second crank", "carried")
        or (st.kind == "rolling" and st.on in ("gear", "circle"))
        for st in compile_plan(load_scene(path)).steps
    )


GEARS_ONLY = [p for p in WORKED + TEXTBOOK if _gears_only(p)]


@pytest.mark.parametrize("path", GEARS_ONLY, ids=lambda p: p.stem)
def test_a_train_of_gears_draws_no_direction_line(path):
    from polygon_method.polygons.constructions import (
        acceleration_constructions,
        velocity_constructions,
    )

    sol = solve(load_scene(path))
    assert not [
        ln
        for cons in (velocity_constructions(sol), acceleration_constructions(sol))
        for c in cons
        for ln in c.lines
    ]


@pytest.mark.parametrize(
    "path", [p for p in WORKED + TEXTBOOK if p not in GEARS_ONLY], ids=lambda p: p.stem
)
def test_every_construction_line_carries_its_mark_and_runs_as_it_says(path):
    """Each direction line of every construction states the mark the drawing writes beside
    it (a structured field: the drawing reads no sentence). Where the mark names a link of
    two points ("\u22a5 BC", "\u2225 BC"), the line's direction is checked against the
    configuration: perpendicular or parallel to B->C, to 1e-12."""
    from polygon_method.polygons.constructions import (
        acceleration_constructions,
        velocity_constructions,
    )

    sol = solve(load_scene(path))
    n = checked = 0
    for cons in (velocity_constructions(sol), acceleration_constructions(sol)):
        for c in cons:
            for ln in c.lines:
                n += 1
                assert ln.mark, (c.title, ln.relation)
                assert ln.mark[0] in "\u22a5\u2225" or ln.mark.startswith("along"), ln.mark
                m = re.fullmatch("([\u22a5\u2225]) ([A-Z][0-9]*)-?([A-Z][0-9]*)", ln.mark)
                if m and m.group(2) in sol.P and m.group(3) in sol.P:
                    (x1, y1), (x2, y2) = sol.P[m.group(2)], sol.P[m.group(3)]
                    L = math.hypot(x2 - x1, y2 - y1)
                    ux, uy = (x2 - x1) / L, (y2 - y1) / L
                    dx, dy = ln.direction
                    off = ux * dx + uy * dy if m.group(1) == "\u22a5" else ux * dy - uy * dx
                    assert abs(off) <= 1e-12, (ln.mark, off)
                    checked += 1
    assert n > 0
    assert checked > 0 or "yoke" in path.stem  # a yoke's lines are its path and its slot
