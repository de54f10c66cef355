"""Adversarial inputs at the seams of the features merged together (a force in a passive
cylinder, several cylinders' indicator diagrams, a friction drive held by a preload, the
scene's new readings), found by a scripted sweep of every command over mutated worked
problems. Each test compares with something independent of the code under test: a closed
form computed here, or the numbers the user wrote."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from polygon_method.cli import main

ROOT = Path(__file__).resolve().parent.parent
CYLINDER = ROOT / "worked_problems" / "cylinder_pull_on_rocker.toml"


def _v_R() -> float:
    """The speed of R (120 mm up the rocker QB) in the cylinder problem, in closed form:
    the four-bar's rocker angle by circle intersection, its rate by a central difference
    in the crank angle (60 rpm: omega = 2 pi rad/s)."""

    def rocker(theta: float) -> float:
        ax, ay = 100 * math.cos(theta), 100 * math.sin(theta)
        dx, dy = 300 - ax, -ay  # from A to Q
        d = math.hypot(dx, dy)
        a = (300**2 - 200**2 + d**2) / (2 * d)  # from A along AQ to the chord
        h = math.sqrt(300**2 - a**2)
        mx, my = ax + a * dx / d, ay + a * dy / d
        bx, by = mx - h * dy / d, my + h * dx / d  # the branch above OQ
        if by < 0:
            bx, by = mx + h * dy / d, my - h * dx / d
        return math.atan2(by, bx - 300)

    theta, step = math.radians(60), 1e-6
    rate = (rocker(theta + step) - rocker(theta - step)) / (2 * step)
    return abs(rate * 2 * math.pi) * 0.120


def test_a_cylinders_sliding_velocity_given_as_its_rods_speed_is_diagnosed(tmp_path, capsys):
    """``vs_CR`` wrong in a scene whose C-R is a cylinder (no slider named C-R): the
    mistake finder looked the key up as a slider and check stopped with an internal error
    (exit 3). A student who gives the rod end's absolute speed for the rod's sliding
    velocity is now told so."""
    v_R = _v_R()
    text = CYLINDER.read_text(encoding="utf-8").replace(
        'vs_CR = "0.1526 m/s"', f'vs_CR = "{v_R:.4f} m/s"'
    )
    path = tmp_path / "cyl.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["check", "--json", str(path)]) == 1
    record = json.loads(capsys.readouterr().out)["answers"][0]
    assert record["key"] == "vs_CR" and record["verdict"] == "wrong"
    assert record["mistake"] == "absolute_for_relative", record
    assert "of R" in record["diagnosis"]


def test_a_cylinders_sliding_velocity_wrong_by_anything_is_one_verdict(tmp_path, capsys):
    """Any wrong ``vs_CR`` (here the rod pinned at Q, so the cylinder does not move: the
    given 0.1526 m/s is wrong), in the text table and the page's check alike."""
    text = CYLINDER.read_text(encoding="utf-8").replace(
        'R = { on = "QB", along = 120 }', 'R = { on = "QB", along = 0 }'
    )
    path = tmp_path / "cyl.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["check", str(path)]) == 1
    row = next(line for line in capsys.readouterr().out.splitlines() if line.startswith("vs_CR"))
    assert "WRONG" in row and " 0 m/s" in row, row
    assert main(["page", str(path), "-o", str(tmp_path / "p.html"), "--frames", "4"]) == 0


VTWIN = ROOT / "worked_problems" / "vtwin_flywheel.toml"


def test_a_flywheel_of_an_engine_at_rest_is_refused_in_one_line(tmp_path, capsys):
    """``speed = "0 rpm"`` with a [flywheel]: the motion is solved per rad/s of the crank
    (the virtual velocities), and the flywheel came out for a mean speed of 1 rad/s, I =
    38990 kg m^2; with [flywheel] speed = "3000 rpm" it came out 0.3950 kg m^2 against the
    scene's 0.3972 (computed independently in its comment), the parts' inertia taken at 1
    rad/s. A flywheel needs the running speed: one line naming [flywheel] and its line."""
    text = VTWIN.read_text(encoding="utf-8").replace('speed = "3000 rpm ccw"', 'speed = "0 rpm"')
    for extra in ("", 'speed = "3000 rpm"\n'):
        body = text.replace("radius = 150 ", extra + "radius = 150 ")
        path = tmp_path / "vt.toml"
        path.write_text(body, encoding="utf-8")
        line_no = 1 + body.splitlines().index(
            next(s for s in body.splitlines() if s.startswith("[flywheel]"))
        )
        for argv in (["solve", str(path)], ["check", str(path)]):
            assert main(argv) == 2
            err = capsys.readouterr().err.strip().splitlines()
            assert len(err) == 1 and "[flywheel]" in err[0], err
            assert f"line {line_no}" in err[0] and str(path) in err[0], err


DRIVE = ROOT / "worked_problems" / "friction_drive.toml"


def test_a_friction_drive_at_rest_passes_no_power(tmp_path, capsys):
    """``speed = "0 rpm"``: the largest power mu N v came out 15 W "at the contact's speed
    v = 0.1 m/s", the virtual speed of 1 rad/s (mu N r1 x 1 rad/s = 0.3 x 500 x 0.1); at
    rest the contact does not move and no power passes: 0 W. The largest torque, mu N r,
    is the speed's no matter (22.5 N m, the scene's closed form)."""
    text = DRIVE.read_text(encoding="utf-8").replace('speed = "300 rpm ccw"', 'speed = "0 rpm"')
    text = text.replace('Pmax_O2B = "471.2 W"', 'Pmax_O2B = "0 W"')
    path = tmp_path / "drive.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["check", "--json", str(path)]) == 0
    records = {r["key"]: r for r in json.loads(capsys.readouterr().out)["answers"]}
    assert records["Pmax_O2B"]["correct"] == 0 and records["Pmax_O2B"]["verdict"] == "right"
    assert math.isclose(records["Tmax_O2B"]["correct"], 0.3 * 500 * 0.150, rel_tol=1e-12)
    assert main(["solve", str(path)]) == 0
    line = next(s for s in capsys.readouterr().out.splitlines() if "largest power" in s)
    assert "= 0 W" in line and "at rest" in line, line


AMBEKAR = ROOT / "tests" / "textbook" / "ambekar_fourbar_angle_bad_midpoint.toml"


@pytest.mark.parametrize(
    "along, words",
    [
        ('"1/0 of BC"', "over nought"),  # was an internal error (ZeroDivisionError)
        ('"midpoint of CD"', "E is on BC"),  # was read as the midpoint of BC, silently
        ('"the middle of AB"', "E is on BC"),
        ('"1/3 of CD"', "E is on BC"),  # was "unknown unit '/3 of CD'"
    ],
)
def test_a_part_of_a_link_names_its_own_link_and_no_nought(tmp_path, capsys, along, words):
    """``along = "1/3 of BC"`` and ``"midpoint"``, the book's words for a point on a link:
    a part over nought stopped with an internal error, and a midpoint of another link was
    taken for the midpoint of the point's own. One line naming the point and its line."""
    text = AMBEKAR.read_text(encoding="utf-8")
    body = text.replace('along = "midpoint"', f"along = {along}")
    path = tmp_path / "am.toml"
    path.write_text(body, encoding="utf-8")
    line_no = 1 + next(i for i, s in enumerate(body.splitlines()) if s.startswith("E = {"))
    assert main(["solve", str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and words in err[0], err
    assert f"[points] E (line {line_no})" in err[0], err


def test_a_third_of_a_link_from_its_far_end_is_two_thirds_from_the_near(tmp_path, capsys):
    """``"1/3 of BC", from = "C"`` and ``"2/3 of BC"`` (from B) are the one point: an
    identity of the inputs, and the midpoint the mean of B and C."""
    text = AMBEKAR.read_text(encoding="utf-8").split("[answers]")[0]
    got = {}
    for key, along in (
        ("c", '"1/3 of BC", from = "C"'),
        ("b", '"2/3 of BC"'),
        ("m", '"midpoint of CB"'),
    ):
        path = tmp_path / f"{key}.toml"
        path.write_text(text.replace('along = "midpoint"', f"along = {along}"), encoding="utf-8")
        assert main(["solve", "--json", str(path)]) == 0
        got[key] = json.loads(capsys.readouterr().out)
    pos = lambda doc, p: doc["points"][p]["position"]  # noqa: E731
    assert pos(got["c"], "E") == pytest.approx(pos(got["b"], "E"), abs=1e-12)
    mid = [(b + c) / 2 for b, c in zip(pos(got["m"], "B"), pos(got["m"], "C"))]
    assert pos(got["m"], "E") == pytest.approx(mid, abs=1e-12)


DUMP = ROOT / "tests" / "textbook" / "mabie_dump_body_cylinder.toml"


@pytest.mark.parametrize("length", [1.0, 2.2])
def test_a_cylinder_placed_at_its_strokes_end_is_found(tmp_path, capsys, length):
    """``length_OR`` at the cylinder's stroke end (``stroke = [1.0, 2.2]``): the turn was
    searched for a sign change only, and none brackets a stroke's end (past it the
    mechanism does not assemble): "no angle of the crank QR gives it; over the turn it
    runs from 1.00253 to 2.19916 m", a sampled range. The closed form: R = 1.5 (cos t,
    sin t) from Q, O at (1.2, -0.4): |OR|^2 = 3.85 - 3 (1.2 cos t - 0.4 sin t); the first
    root from 0 deg; omega = vs / (dL/dt), the cylinder moving away from the end it is at
    (towards it, it is refused: below)."""
    text = DUMP.read_text(encoding="utf-8").split("[answers]")[0]
    path = tmp_path / "dump.toml"
    vs = 0.1 if length == 1.0 else -0.1
    if vs < 0:
        text = text.replace("0.1 m/s extending", "0.1 m/s retracting")
    path.write_text(text.replace("length_OR = 1.6", f"length_OR = {length}"), encoding="utf-8")
    assert main(["solve", "--json", str(path)]) == 0
    got = json.loads(capsys.readouterr().out)["input"]
    c = (3.85 - length**2) / 3 / math.hypot(1.2, 0.4)  # cos(t + phi)
    phi = math.atan2(0.4, 1.2)
    roots = sorted((s * math.acos(c) - phi) % (2 * math.pi) for s in (1, -1))
    theta = roots[0]
    dL = 3 * (1.2 * math.sin(theta) + 0.4 * math.cos(theta)) / (2 * length)
    assert got["angle"] % (2 * math.pi) == pytest.approx(theta, rel=1e-9)
    assert got["omega"] == pytest.approx(vs / dL, rel=1e-8)


@pytest.mark.parametrize("length, way", [(2.2, "extending"), (1.0, "retracting")])
def test_a_cylinder_at_its_strokes_end_cannot_go_on(tmp_path, capsys, length, way):
    """Fully extended (2.2 m, the stroke's most) it cannot extend, fully closed (1 m) it
    cannot retract: one line naming the given motion, as any impossible statement."""
    text = DUMP.read_text(encoding="utf-8").split("[answers]")[0]
    text = text.replace("length_OR = 1.6", f"length_OR = {length}")
    path = tmp_path / "dump.toml"
    path.write_text(text.replace("0.1 m/s extending", f"0.1 m/s {way}"), encoding="utf-8")
    for command in (["solve"], ["solve", "--json"], ["steps"], ["check"]):
        assert main([*command, str(path)]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and "[input] vs_OR" in err[0], err
        assert f"cannot {way.removesuffix('ing')}" in err[0], err


def test_a_length_past_the_stroke_names_the_strokes_ends(tmp_path, capsys):
    """Past the stroke, the range named is the stroke's, 1 to 2.2 m, not a sampled one."""
    text = DUMP.read_text(encoding="utf-8").split("[answers]")[0]
    path = tmp_path / "dump.toml"
    path.write_text(text.replace("length_OR = 1.6", "length_OR = 0.5"), encoding="utf-8")
    assert main(["solve", str(path)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "runs from 1 to 2.2 m" in err[0], err


@pytest.mark.parametrize(
    "pressures, ok",
    [
        ("[-5, -5, -5, -5, -5, -5, -5, -5, -5, -5, -5, -5, -5, -5]", False),
        ("[-0.1, -0.1, 0.8, 3.0, 6.0, 12.0, 40.0, 32.0, 18.0, 10.0, 6.0, 3.0, 0.2, -1.1]", False),
        ("[-1.0, -0.1, 0.8, 3.0, 6.0, 12.0, 40.0, 32.0, 18.0, 10.0, 6.0, 3.0, 0.2, -1.0]", True),
    ],
)
def test_an_indicator_pressure_below_a_vacuum_is_refused(tmp_path, capsys, pressures, ok):
    """An indicator diagram of -5 bar (gauge) was read and its cycle worked out: no gas
    pressure is below a vacuum, -1.01325 bar gauge (the standard atmosphere, 101325 Pa;
    absolute pressures are never negative); -1 bar, a near vacuum, is a pressure."""
    text = VTWIN.read_text(encoding="utf-8")
    old = next(s for s in text.splitlines() if s.startswith("pressure = ["))
    body = text.replace(old, f"pressure = {pressures}")
    path = tmp_path / "vt.toml"
    path.write_text(body, encoding="utf-8")
    line_no = 1 + body.splitlines().index(f"pressure = {pressures}")
    code = main(["solve", str(path)])
    err = capsys.readouterr().err.strip().splitlines()
    if ok:
        assert code == 0 and not err, err
        return
    assert code == 2 and len(err) == 1, err
    assert f"[indicator] pressure (line {line_no})" in err[0] and "vacuum" in err[0], err


def test_an_engines_cycle_at_rest_has_no_power_and_the_same_mean(tmp_path, capsys):
    """An engine's scene at rest (``speed = "0 rpm"``, no ``[flywheel]``) printed "at 9.5493
    rpm, power ..." for its turning-moment diagram: the virtual 1 rad/s taken for a speed.
    At rest no power passes; the mean torque is the running engine's (the inertia forces do
    no net work over a cycle), so the two means agree."""
    import re

    text = (ROOT / "worked_problems" / "engine_flywheel.toml").read_text(encoding="utf-8")
    text = text.split("[answers]")[0]
    text = re.sub(r"(?ms)^\[flywheel\].*?(?=^\[|\Z)", "", text)
    running = tmp_path / "running.toml"
    running.write_text(text, encoding="utf-8")
    rest = tmp_path / "rest.toml"
    rest.write_text(re.sub(r"(?m)^speed = .*$", 'speed = "0 rpm"', text), encoding="utf-8")
    means = []
    for scene in (running, rest):
        assert main(["solve", str(scene)]) == 0
        line = next(x for x in capsys.readouterr().out.splitlines() if "T_mean =" in x)
        means.append(float(line.split("T_mean =")[1].split()[0]))
        if scene is rest:
            assert "at rest: no power" in line and "rpm" not in line, line
        else:
            assert "rpm, power" in line, line
    assert math.isclose(means[0], means[1], rel_tol=1e-5), means


def _gas_alone(deg):
    """The engine_flywheel problem's turning moment of its gas force alone (N m) at ``deg``
    from the inner dead centre, in closed form: the indicator's pressure read linearly
    between its readings, on the 100 mm bore, T = F r sin(t + phi) / cos(phi) with
    sin(phi) = sin(t) / n (r = 60 mm, n = 4)."""
    ang = [0, 180, 240, 300, 330, 360, 375, 390, 420, 450, 480, 540, 560, 720]
    bar = [-0.1, -0.1, 0.8, 3.0, 6.0, 12.0, 40.0, 32.0, 18.0, 10.0, 6.0, 3.0, 0.2, -0.1]
    force = float(np.interp(deg, ang, bar)) * 1e5 * math.pi / 4 * 0.1**2
    t = math.radians(deg % 360)
    phi = math.asin(math.sin(t) / 4)
    return force * 0.06 * math.sin(t + phi) / math.cos(phi)


def test_an_engines_cycle_at_rest_is_the_gas_force_alone_in_every_view(tmp_path, capsys):
    """At rest nothing moves: the cycle's turning moment is the gas force's alone (its
    greatest and least on the 0.25 deg grid are the closed form's, to the last bits), as
    the instant's forces say ("at rest: no inertia"). It was said to be "with the inertia
    of the moving parts at the virtual 1 rad/s" and the --json had inertia_included true:
    neither was so. Every view says the same; none speaks of a speed as if real."""
    import re

    text = (ROOT / "worked_problems" / "engine_flywheel.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?ms)^\[flywheel\].*?(?=^\[|\Z)", "", text.split("[answers]")[0])
    rest = tmp_path / "rest.toml"
    rest.write_text(re.sub(r"(?m)^speed = .*$", 'speed = "0 rpm"', text), encoding="utf-8")
    grid = np.arange(0.0, 720.0, 0.25)
    T = [_gas_alone(x) for x in grid]
    assert main(["solve", "--json", str(rest)]) == 0
    tm = json.loads(capsys.readouterr().out)["turning_moment"]
    assert tm["inertia_included"] is False
    assert tm["T_max"] == pytest.approx(max(T), rel=1e-12)
    assert tm["at_T_max_deg"] == grid[int(np.argmax(T))]
    assert tm["T_min"] == pytest.approx(min(T), rel=1e-12)
    assert tm["at_T_min_deg"] == grid[int(np.argmin(T))]
    for command in (["solve"], ["steps"], ["sweep", "--summary"]):
        assert main([*command, str(rest)]) == 0
        out = " ".join(capsys.readouterr().out.split())
        assert "at rest: the gas force alone, no inertia (nothing moves)" in out, command
        assert "virtual 1 rad/s: the crank" not in out and "rpm, power" not in out, command
        assert "the speed would be greatest at" in out and "turning slowly" in out, command
        if command == ["solve"]:  # the instant's efforts: the weight, no inertia
            assert "reciprocating parts' weight (at rest: no inertia)" in out, command
            assert "reciprocating parts' inertia" not in out, command
    # sweep --summary's driving torque at rest holds the crank against the gas alone: its
    # words said "with inertia"; its extremes are the closed form's, refined (6 figures)
    assert main(["sweep", "--summary", str(rest)]) == 0
    (row,) = [x for x in capsys.readouterr().out.splitlines() if x.startswith("torque_inertia")]
    assert "at rest: the loads alone, no inertia" in row and "with inertia" not in row, row
    fine = np.arange(300.0, 420.0, 0.001)
    held = [-_gas_alone(x) for x in fine]
    mx, at_mx, mn, at_mn = (float(v) for v in row.split()[3:7])  # (its unit N m: two words)
    assert mx == float(f"{max(held):.6g}") and mn == float(f"{min(held):.6g}"), row
    assert abs(at_mx - fine[int(np.argmax(held))]) < 2e-3, row
    assert abs(at_mn - fine[int(np.argmin(held))]) < 2e-3, row
    page = tmp_path / "rest.html"
    assert main(["page", str(rest), "-o", str(page)]) == 0
    html = " ".join(page.read_text(encoding="utf-8").split())
    assert "at rest: the gas force alone, no inertia (nothing moves)" in html
    assert "virtual 1 rad/s: the crank" not in html


def test_an_engines_cycle_starting_from_rest_says_what_it_counts(tmp_path, capsys):
    """Starting from rest (an acceleration at speed 0) the cycle counts the start's inertia
    at every angle, no velocity: its inertia is included (--json), its words say so and
    that it is no running engine's cycle, and no speed is said to be greatest or least."""
    import re

    text = (ROOT / "worked_problems" / "engine_flywheel.toml").read_text(encoding="utf-8")
    text = re.sub(r"(?ms)^\[flywheel\].*?(?=^\[|\Z)", "", text.split("[answers]")[0])
    start = 'speed = "0 rpm"\nacceleration = "2000 rad/s^2 ccw"'
    scene = tmp_path / "start.toml"
    scene.write_text(re.sub(r"(?m)^speed = .*$", start, text), encoding="utf-8")
    assert main(["solve", "--json", str(scene)]) == 0
    assert json.loads(capsys.readouterr().out)["turning_moment"]["inertia_included"] is True
    assert main(["solve", str(scene)]) == 0
    out = capsys.readouterr().out
    assert "starting from rest at every angle, alpha_OA = 2000 rad/s^2 ccw" in out
    assert "not a running engine's cycle" in out and "no speed yet to be greatest" in out
    assert "the speed greatest at" not in out and "would be greatest" not in out
