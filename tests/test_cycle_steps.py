"""``steps`` works the asked ``time_ratio``, ``stroke_X``, ``theta_XY`` and ``angle_XYZ`` as a
book does (text/cycle_steps.py): the dead positions and the crank angles they occur at, the
crank's turn on each stroke, the slider's extreme places, atan2 of the coordinates. Its
numbers against closed forms written here from the geometry (a crank and slotted lever's
extreme positions, the crank perpendicular to the lever; an offset slider crank's dead
centres, crank and rod in line), and its worked sums against what they state."""

from __future__ import annotations

import json
import math
import re

from polygon_method import parse_scene, solve
from polygon_method.cli import main
from polygon_method.linkage.cycle_values import quick_return, stroke_ends
from polygon_method.text.cycle_steps import cycle_items

REL = 1e-9
NUM = r"(-?[\d.]+)"


def _turn(a: float) -> float:
    """An angle (deg) in [0, 360)."""
    return a % 360.0


def _slotted(d, r, L, h):
    """A crank and slotted lever shaper: lever pivot P, crank centre O at d above it, crank
    r, slotted bar PB = L, its end B in a vertical slot of the ram Y on the line h above P."""
    return f"""
units = "mm"
[ground]
P = [0, 0]
O = [0, {d}]
[links]
OA = {r}
PB = {L}
[sliders]
A = {{ along = "PB" }}
Y = {{ path = "horizontal", through = [0, {h}] }}
B = {{ along = "block Y", direction = "vertical" }}
[input]
crank = "OA"
angle = 30
speed = "60 rpm cw"
[answers]
time_ratio = "?"
stroke_Y = "?"
"""


def _offset(r, l, e):
    """An offset slider crank: crank OA = r about O, rod AB = l, B on the line y = e."""
    return f"""
units = "mm"
[ground]
O = [0, 0]
[links]
OA = {r}
AB = {l}
[sliders]
B = {{ path = "horizontal", through = [0, {e}] }}
[input]
crank = "OA"
angle = 30
speed = "100 rpm ccw"
[answers]
time_ratio = "?"
stroke_B = "?"
theta_AB = "?"
angle_OAB = "?"
"""


def _check_sums(item: str) -> None:
    """The time ratio's working states beta + alpha = 360 and beta / alpha = the ratio."""
    beta = float(re.search(rf"beta = {NUM} deg", item)[1])
    alpha = float(re.search(rf"alpha = {NUM} deg", item)[1])
    total = float(re.search(rf"beta \+ alpha = {NUM} deg", item)[1])
    ratio = float(re.search(rf"= beta / alpha = {NUM} / {NUM} = {NUM}", item)[3])
    assert abs(beta + alpha - total) <= 2e-4 and abs(total - 360) <= 1e-4
    assert beta >= alpha
    assert abs(beta / alpha - ratio) <= 1e-5 * ratio


def test_slotted_lever_working_against_its_closed_form():
    """Dead positions: the lever tangent to the crank circle, the crank perpendicular to it,
    so cos(angle POA) = r / d: the crank at -90 deg +- acos(r/d); the return stroke turns
    the crank alpha = 2 acos(r/d) (the short arc below O), the cutting beta = 360 - alpha.
    The lever leans asin(r/d) from PO at each end: its end B, in the ram's vertical slot, and
    so the ram at x = +-L sin(asin(r/d)) = +-L r / d."""
    d, r, L, h = 240.0, 95.0, 500.0, 450.0
    sol = solve(parse_scene(_slotted(d, r, L, h)))
    out, stats, arc1, arc2, ratio = quick_return(sol.scene)
    half = math.degrees(math.acos(r / d))
    got = sorted(_turn(s.deg) for s in stats)
    want = sorted(_turn(-90 + sgn * half) for sgn in (1, -1))
    assert all(abs(a - b) <= REL * 360 for a, b in zip(got, want))
    alpha = 2 * math.acos(r / d)
    assert abs(min(arc1, arc2) - alpha) <= REL * alpha
    assert abs(max(arc1, arc2) - (2 * math.pi - alpha)) <= REL * alpha
    assert abs(ratio - (2 * math.pi - alpha) / alpha) <= REL * ratio
    omin, omax, _ = stroke_ends(sol.scene, "Y", "stroke_Y")
    x = L * 1e-3 * r / d  # B, the bar's end, at L sin(asin(r/d)) from the line PO
    assert abs(omin + x) <= REL * x and abs(omax - x) <= REL * x
    items = cycle_items(sol)
    assert len(items) == 2 and items[0].startswith("time_ratio:")
    _check_sums(items[0])
    for deg in want:  # the crank angles of the dead positions, as written
        shown = [float(v) for v in re.findall(rf"at crank angle {NUM} deg", items[0])]
        assert any(abs(_turn(s) - deg) <= 1e-4 for s in shown)
    hi, lo, dist = re.search(
        rf"= their distance = {NUM} - \(?{NUM}\)? = {NUM} mm", items[1]
    ).groups()
    assert abs(float(hi) - float(lo) - float(dist)) <= 1e-3
    assert abs(float(dist) - 2 * x * 1e3) <= 1e-3


def test_offset_slider_crank_dead_centres_and_the_instant():
    """Dead centres of an offset slider crank (B on y = e): extended, B at
    x1 = sqrt((l + r)^2 - e^2), the crank at atan2(e, x1); folded, B at
    x2 = sqrt((l - r)^2 - e^2), the crank at atan2(-e, -x2). The stroke is x1 - x2, the
    ratio the crank's larger turn between them over the smaller. At the instant (crank
    30 deg): A = r (cos 30, sin 30), B = (xA + sqrt(l^2 - (e - yA)^2), e); theta_AB by
    atan2, angle OAB by the cosine rule."""
    r, l, e = 100.0, 380.0, 60.0
    sol = solve(parse_scene(_offset(r, l, e)))
    x1, x2 = math.sqrt((l + r) ** 2 - e**2), math.sqrt((l - r) ** 2 - e**2)
    t1, t2 = math.atan2(e, x1), math.atan2(-e, -x2)
    ccw = (t2 - t1) % (2 * math.pi)  # the crank ccw from extended to folded
    want = sorted(_turn(math.degrees(t)) for t in (t1, t2))
    _, stats, arc1, arc2, ratio = quick_return(sol.scene)
    got = sorted(_turn(s.deg) for s in stats)
    assert all(abs(a - b) <= REL * 360 for a, b in zip(got, want))
    big, small = max(ccw, 2 * math.pi - ccw), min(ccw, 2 * math.pi - ccw)
    assert abs(max(arc1, arc2) - big) <= REL * big and abs(min(arc1, arc2) - small) <= REL * big
    assert abs(ratio - big / small) <= REL * ratio
    omin, omax, _ = stroke_ends(sol.scene, "B", "stroke_B")
    assert abs((omax - omin) - (x1 - x2) * 1e-3) <= REL * x1 * 1e-3
    items = cycle_items(sol)
    assert [i.split(":")[0] for i in items] == ["time_ratio", "stroke_B", "theta_AB", "angle_OAB"]
    _check_sums(items[0])
    hi, lo, dist = re.search(rf"distance = {NUM} - \(?{NUM}\)? = {NUM} mm", items[1]).groups()
    assert abs(float(hi) - float(lo) - float(dist)) <= 1e-3
    assert abs(float(dist) - (x1 - x2)) <= 1e-3 and abs(float(lo) - x2) <= 1e-3
    xa, ya = r * math.cos(math.radians(30)), r * math.sin(math.radians(30))
    xb = xa + math.sqrt(l**2 - (e - ya) ** 2)
    theta = math.degrees(math.atan2(e - ya, xb - xa)) % 360
    ob = math.hypot(xb, e)
    cos_a = (r**2 + l**2 - ob**2) / (2 * r * l)
    angle = math.degrees(math.acos(cos_a))
    th = float(
        re.search(rf"theta_AB = atan2\(dy, dx\) = atan2\({NUM}, {NUM}\) = {NUM} deg", items[2])[3]
    )
    assert abs(th - theta) <= 1e-4
    dx, dy = (float(v) for v in re.search(rf"dx = {NUM} mm, dy = {NUM} mm", items[2]).groups())
    assert abs(math.degrees(math.atan2(dy, dx)) % 360 - th) <= 1e-3
    an = float(re.search(rf"angle_OAB = {NUM} deg", items[3])[1])
    assert abs(an - angle) <= 1e-4


def test_steps_command_shows_the_working_where_asked(tmp_path, capsys):
    path = tmp_path / "offset.toml"
    path.write_text(_offset(100, 380, 60))
    assert main(["steps", str(path)]) == 0
    text = capsys.readouterr().out
    assert "Asked of the cycle and the configuration" in text
    assert "beta + alpha = 360.0000 deg" in text
    plain = tmp_path / "plain.toml"
    plain.write_text(_offset(100, 380, 60).split("[answers]")[0])
    assert main(["steps", str(plain)]) == 0
    assert "Asked of the cycle" not in capsys.readouterr().out


def test_a_key_that_cannot_be_worked_says_why_in_its_line():
    """A crank that does not turn fully (r + e > l) has no cutting and return strokes."""
    sol = solve(parse_scene(_offset(100, 130, 60)))
    items = cycle_items(sol)
    assert items[0].startswith("time_ratio: not answered: the crank OA does not turn fully")


def test_check_json_gives_a_graded_angle_in_si(tmp_path, capsys):
    """``check --json``: a graded theta_XY or angle_XYZ in rad (unit "rad"), as every other
    number; the table's row in degrees. Against the cosine rule and atan2 of the closed-form
    positions (crank 30 deg)."""
    r, l, e = 100.0, 380.0, 60.0
    xa, ya = r * math.cos(math.radians(30)), r * math.sin(math.radians(30))
    xb = xa + math.sqrt(l**2 - (e - ya) ** 2)
    angle = math.acos((r**2 + l**2 - (xb**2 + e**2)) / (2 * r * l))
    theta = math.atan2(e - ya, xb - xa)  # small and positive: -358.5 deg is written as it
    path = tmp_path / "graded.toml"
    text = _offset(r, l, e).split("[answers]")[0]
    path.write_text(text + '[answers]\nangle_OAB = "151.5 deg"\ntheta_AB = -358.5\n')
    assert main(["check", "--json", str(path)]) == 0
    got = {a["key"]: a for a in json.loads(capsys.readouterr().out)["answers"]}
    a, t = got["angle_OAB"], got["theta_AB"]
    assert a["unit"] == t["unit"] == "rad" and a["verdict"] == t["verdict"] == "right"
    assert abs(a["correct"] - angle) <= REL * angle
    assert abs(a["given"] - math.radians(151.5)) <= REL
    assert abs(t["correct"] - (theta - 2 * math.pi)) <= REL * 2 * math.pi  # as given: -360 + x
    assert abs(t["given"] - math.radians(-358.5)) <= REL
    assert main(["check", str(path)]) == 0
    row = next(x for x in capsys.readouterr().out.splitlines() if x.startswith("angle_OAB"))
    assert f"{math.degrees(angle):.4g} deg" in row
