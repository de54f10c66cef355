"""A gear whose teeth the scene does not state, beside a module: its pitch radius from what
the scene fixes (the centre distance, less or plus the other gear's; an ``on_radius``; a
wheel's link) must be a whole number of teeth, 2 r / m. Where it is, the teeth are said in
a note (a default taken) and the train runs by them; where it is not (OA = 163 mm with a
24-tooth planet of module 5 mm makes a sun of (163 - 60) x 2 / 5 = 41.2 teeth), refused in
one line naming the entry and its line, exit 2. Every figure here is hand arithmetic."""

import math
import subprocess
import sys

import pytest

from polygon_method import parse_scene, solve

PLANET = """
units = "mm"
[ground]
O = [0, 0]
[links]
OA = {arm}
[rolling]
module = "5 mm"
AP = {{ on = "O", teeth = 24{more} }}
[input]
crank = "OA"
angle = 30
speed = "200 rpm ccw"
"""

PAIR = """
units = "{units}"
[ground]
O2 = [0, 0]
O3 = [{d}, 0]
[rolling]
{module}
"O3-B" = {{ on = "O2-A", teeth = 50, on_teeth = 20{more} }}
[input]
crank = "O3-B"
angle = 25
speed = "1000 rpm cw"
"""


def _run(text, tmp_path):
    f = tmp_path / "g.toml"
    f.write_text(text, encoding="utf-8")
    return subprocess.run(
        [sys.executable, "-m", "polygon_method", "solve", str(f)],
        capture_output=True,
        text=True,
        timeout=120,
    )


def _one_line(out):
    lines = out.stderr.strip().splitlines()
    assert out.returncode == 2 and len(lines) == 1, out.stderr + out.stdout
    return lines[0]


def test_the_sun_from_the_arm_not_whole_is_refused(tmp_path):
    """OA = 163 mm, the planet 5 x 24 / 2 = 60 mm: the sun 103 mm, 2 x 103 / 5 = 41.2 teeth.
    Refused naming the entry and its line; 41 teeth need OA = 102.5 + 60 = 162.5 mm, 42
    teeth 105 + 60 = 165 mm."""
    line = _one_line(_run(PLANET.format(arm=163, more=""), tmp_path))
    assert "[rolling] AP (line 9)" in line, line
    assert "41.2 teeth of module 5 mm" in line and "not a whole number" in line, line
    assert "on_teeth" in line and "162.5 mm (41 teeth) or 165 mm (42 teeth)" in line, line


@pytest.mark.parametrize("inside,arm,zs", [(False, 160, 40), (True, 160, 88), (False, 185, 50)])
def test_the_sun_from_the_arm_whole_is_said_and_obeys_willis(inside, arm, zs):
    """OA = 160 mm: the sun 160 - 60 = 100 mm, 40 teeth (outside); inside an annulus 160 +
    60 = 220 mm, 88 teeth; OA = 185 mm: 125 mm, 50 teeth. The note says it; the planet
    turns by Willis' formula with those teeth, omega_p = omega_arm (1 + e zs / 24)."""
    more = ", inside = true" if inside else ""
    sol = solve(parse_scene(PLANET.format(arm=arm, more=more)))
    e = -1 if inside else 1
    assert sol.W["AP"] == pytest.approx(sol.W["OA"] * (1 + e * zs / 24), rel=1e-12)
    R = (arm + e * -60) if not inside else arm + 60
    note = next(n for n in sol.notes if "no on_teeth or on_radius" in n)
    assert f"= {R:g} mm: {zs} teeth" in note, note
    assert ("plus" if inside else "less") + " AP's 60 mm" in note, note
    assert sol.to_dict()["rolling"]["AP"]["teeth"]["on_teeth"] == zs
    assert sol.scene.rolling[0].base_radius == pytest.approx(5e-3 * zs / 2, rel=1e-15)


@pytest.mark.parametrize(
    "more,said,teeth",
    [
        (", on_radius = 103", "on_radius 103 mm", "41.2"),  # 2 x 103 / 5
        (", on_radius = 100", None, None),  # 40 teeth: taken
    ],
)
def test_on_radius_with_a_module_is_whole_teeth(tmp_path, more, said, teeth):
    """A sun's on_radius beside a module: 2 R / m teeth, whole or refused."""
    text = PLANET.format(arm=160 if said is None else 163, more=more)
    if said is None:
        sol = solve(parse_scene(text))
        assert sol.scene.rolling[0].teeth == (24, 40, pytest.approx(5e-3, rel=1e-15), None)
        return
    line = _one_line(_run(text, tmp_path))
    assert "[rolling] AP" in line and said in line and f"{teeth} teeth" in line, line


def test_the_wheel_by_its_link_with_the_sun_by_its_teeth(tmp_path):
    """on_teeth = 40 with no teeth: the planet's link AP is its pitch radius, 2 x 61 / 5 =
    24.4 teeth refused naming teeth; AP = 60 mm makes 24 teeth."""
    text = PLANET.replace("OA = {arm}", "OA = {arm}\nAP = {ap}").replace(
        "teeth = 24", "on_teeth = 40"
    )
    line = _one_line(_run(text.format(arm=161, ap=61, more=""), tmp_path))
    assert "AP's radius 61 mm (the link AP): 24.4 teeth" in line and "give teeth" in line, line
    sol = solve(parse_scene(text.format(arm=160, ap=60, more="")))
    assert sol.scene.rolling[0].teeth[:2] == (24, 40)
    assert sol.W["AP"] == pytest.approx(sol.W["OA"] * (1 + 40 / 24), rel=1e-12)


@pytest.mark.parametrize("d,z2", [(140, 20), (143, None), (150, 25)])
def test_fixed_centres_the_driver_from_the_centre_distance(tmp_path, d, z2):
    """Gear 3 of 50 teeth, module 4 mm (100 mm), its driver named only by on: the driver
    O2O3 - 100 mm, 2 (d - 100) / 4 teeth: 140 mm gives 20, 150 mm 25, 143 mm 21.5
    (refused: 142 mm gives 21, 144 mm 22). omega3 = -omega2 z2 / 50."""
    text = PAIR.format(units="mm", d=d, module='module = "4 mm"', more="")
    text = text.replace(", on_teeth = 20", "").replace('crank = "O3-B"', 'crank = "O2-A"')
    text = text.replace("[rolling]", '[links]\n"O2-A" = 30\n"O3-B" = 100\n[rolling]')
    if z2 is None:
        line = _one_line(_run(text, tmp_path))
        assert "[rolling] O3-B" in line and "21.5 teeth" in line, line
        assert "142 mm (21 teeth) or 144 mm (22 teeth)" in line, line
        return
    sol = solve(parse_scene(text))
    assert sol.W["O3-B"] == pytest.approx(-sol.W["O2-A"] * z2 / 50, rel=1e-12)
    assert any(f"{z2} teeth" in n and "O2O3" in n for n in sol.notes), sol.notes


@pytest.mark.parametrize("d,ok", [(3.5, True), (3.52, False)])
def test_diametral_pitch_the_same_rule(tmp_path, d, ok):
    """A US book: P = 10 per inch, gear 3 of 50 teeth (2.5 in); a second gear meshing with
    it about O4, 30 teeth (1.5 in), its centre 4 in above O3 makes 2.5 + 1.5: the
    driver O2-A from O2O3 = 3.5 in less 2.5 in = 1 in is 2 x 1 x 10 = 20 teeth; 3.52 in
    makes 20.4 (refused)."""
    text = PAIR.format(units="in", d=d, module="diametral_pitch = 10", more="")
    text = text.replace(", on_teeth = 20", "").replace('crank = "O3-B"', 'crank = "O2-A"')
    text = text.replace("[rolling]", '[links]\n"O2-A" = 0.9\n"O3-B" = 2.5\n[rolling]')
    if not ok:
        line = _one_line(_run(text, tmp_path))
        assert "20.4 teeth of diametral pitch 10 per inch" in line, line
        return
    sol = solve(parse_scene(text))
    assert sol.scene.rolling[0].teeth[:2] == (50, 20)
    assert sol.W["O3-B"] == pytest.approx(-sol.W["O2-A"] * 20 / 50, rel=1e-12)


PLACED = """
units = "mm"
[ground]
A = [0, 0]
E = [200, 0]
O = [{ox!r}, {oy!r}]
[links]
AB = 50
BC = 130
CE = 110
OS = 60
[rolling]
module = "5 mm"
OS = {{ on = "C-B", teeth = 24 }}
[assembly]
C = "above"
[input]
crank = "AB"
angle = 60
speed = "10 rad/s ccw"
"""


def _c_by_hand():
    """C of the four-bar by hand: the circles about B (130 mm) and E (110 mm) cut, above."""
    bx, by = 50 * math.cos(math.radians(60)), 50 * math.sin(math.radians(60))
    ex, ey = 200.0, 0.0
    dd = math.hypot(ex - bx, ey - by)
    a = (130**2 - 110**2 + dd**2) / (2 * dd)
    h = math.sqrt(130**2 - a**2)
    mx, my = bx + a * (ex - bx) / dd, by + a * (ey - by) / dd
    c1 = (mx - h * (ey - by) / dd, my + h * (ex - bx) / dd)
    c2 = (mx + h * (ey - by) / dd, my - h * (ex - bx) / dd)
    return max(c1, c2, key=lambda c: c[1])


def test_the_centre_distance_known_only_once_placed(tmp_path):
    """A gear about O meshing with a gear on the coupler at C (no link fixes |OC|): its
    teeth from |OC| at the stated instant, by hand from the four-bar's C. O 160 mm above C:
    the gear 160 - 60 = 100 mm, 40 teeth (a note of the plan); O at (100, 250): |OC| - 60
    is no whole number of teeth, refused naming [rolling] OS."""
    cx, cy = _c_by_hand()
    sol = solve(parse_scene(PLACED.format(ox=cx, oy=cy + 160)))
    note = next(n for n in sol.notes if "at the stated instant" in n)
    assert "CO = 160 mm" in note and "100 mm: 40 teeth" in note, note
    assert sol.plan.steps[-1].title == "gear OS of 24 teeth meshing with the gear BC of 40 teeth"
    zf = 2 * (math.hypot(100 - cx, 250 - cy) - 60) / 5
    line = _one_line(_run(PLACED.format(ox=100.0, oy=250.0), tmp_path))
    assert "[rolling] OS" in line and f"{zf:.6g} teeth" in line, line
    assert abs(zf - round(zf)) > 0.1


def test_no_arm_and_no_sun_is_one_line_naming_the_planet(tmp_path):
    """The planet of 24 teeth on a fixed circle about O, neither the sun's teeth nor the
    arm OA stated: nothing fixes the centre distance; the line names the planet's entry and
    what to give (it named '[input] crank: no link OA')."""
    text = PLANET.format(arm=160, more="").replace("[links]\nOA = 160\n", "")
    line = _one_line(_run(text, tmp_path))
    assert "[rolling] AP (line" in line and "the arm OA is not in [links]" in line, line
    assert "give on_teeth" in line, line


def test_the_sun_from_the_annulus_and_the_planet():
    """No arm and no sun's teeth, the annulus of 88 (or 90) teeth on the planet of 24: the
    arm is r_ring - r_planet = 5 (88 - 24) / 2 = 160 mm (165 mm), the sun 160 - 60 = 100
    mm, 40 teeth (42: z_r - 2 z_p), and the annulus turns by Willis' formula with them."""
    for zr in (88, 90):
        text = PLANET.format(arm=0, more="").replace("[links]\nOA = 0\n", "")
        text = text.replace(
            "[input]", f'"O-Q" = {{ on = "AP", ring = true, teeth = {zr} }}\n[input]'
        )
        sol = solve(parse_scene(text))
        zs = zr - 48
        assert sol.scene.rolling[0].teeth[1] == zs
        w_arm = sol.W["OA"]
        assert (sol.W["O-Q"] - w_arm) / -w_arm == pytest.approx(-zs / zr, rel=1e-12)


@pytest.mark.parametrize("ring,teeth", [(220, 88), (221, None)])
def test_an_annulus_on_a_toothed_planet_is_toothed_too(tmp_path, ring, teeth):
    """The table's module, the annulus's entry naming no teeth, on the planet of 24 teeth:
    the annulus is a gear all the same, 2 x 220 / 5 = 88 teeth (said; Willis' formula with
    them), and a link of 221 mm (88.4 teeth) is refused naming the annulus's entry."""
    text = (
        PLANET.format(arm=160, more=", on_teeth = 40")
        .replace("[input]", '"O-Q" = { on = "AP", ring = true }\n[input]')
        .replace("OA = 160\n", f'OA = 160\n"O-Q" = {ring}\n')
    )
    if teeth is None:
        line = _one_line(_run(text, tmp_path))
        assert "[rolling] O-Q" in line and "88.4 teeth" in line, line
        return
    sol = solve(parse_scene(text))
    assert any("O-Q's radius 220 mm (the link O-Q): 88 teeth" in n for n in sol.notes)
    w_arm = sol.W["OA"]
    assert (sol.W["O-Q"] - w_arm) / -w_arm == pytest.approx(-40 / 88, rel=1e-12)
    assert "ring O-Q of 88 teeth meshing with the planet AP of 24 teeth inside it" in [
        st.title for st in sol.plan.steps
    ]
