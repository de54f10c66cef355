"""Gears given by their teeth ([rolling] teeth, on_teeth, module or diametral_pitch, or the
centre distance alone): the speed ratios are the teeth's (z1/z2 exactly, to 1e-12), held
to the closed forms of the gear-train chapters (omega3 = -omega2 z2/z3 for fixed centres,
the train value of a compound train, Willis' formula for an epicyclic), and a scene by its
teeth moves as the same scene with its radii stated by hand. Bad teeth: one line, exit 2."""

import math
import subprocess
import sys
from pathlib import Path

import pytest

from polygon_method import parse_scene, solve

W1 = -1000 * 2 * math.pi / 60  # the driver, 1000 rpm cw

PAIR = """
units = "mm"
[ground]
O2 = [0, 0]
O3 = [{d}, 0]
[links]
"O2-A" = {r2}
"O3-B" = {r3}
[rolling]
{table}
"O3-B" = {{ on = "O2-A"{keys} }}
[input]
crank = "O2-A"
angle = 25
speed = "1000 rpm cw"
"""


def _pair(z2, z3, m=4.0, keys=None, table=None, d=None, r2=None, r3=None):
    r2 = m * z2 / 2 if r2 is None else r2
    r3 = m * z3 / 2 if r3 is None else r3
    keys = f", teeth = {z3}, on_teeth = {z2}" if keys is None else keys
    table = f'module = "{m} mm"' if table is None else table
    d = r2 + r3 if d is None else d
    return PAIR.format(d=d, r2=r2, r3=r3, keys=keys, table=table)


@pytest.mark.parametrize("z2,z3", [(20, 60), (17, 43), (31, 19), (12, 100)])
def test_external_pair_turns_by_the_teeth_ratio(z2, z3):
    """omega3 = -omega2 z2 / z3 (fixed centres, external mesh), and the scene by its teeth
    moves as the one with its radii by hand (radius m z / 2)."""
    sol = solve(parse_scene(_pair(z2, z3)))
    assert sol.W["O3-B"] / sol.W["O2-A"] == pytest.approx(-z2 / z3, rel=1e-12)
    assert sol.W["O3-B"] == pytest.approx(-W1 * z2 / z3, rel=1e-12)
    by_hand = solve(parse_scene(_pair(z2, z3, keys="", table="")))
    for p in ("A", "B"):
        assert math.dist(sol.V[p], by_hand.V[p]) <= 1e-12 * math.hypot(*by_hand.V[p])
        assert math.dist(sol.A[p], by_hand.A[p]) <= 1e-12 * math.hypot(*by_hand.A[p])


def test_module_in_the_entry_and_diametral_pitch():
    """The module in the entry; a US book's diametral pitch P (radius z / (2 P) inches)."""
    sol = solve(
        parse_scene(_pair(20, 50, keys=", teeth = 50, on_teeth = 20, module = 4", table=""))
    )
    assert sol.W["O3-B"] == pytest.approx(-W1 * 20 / 50, rel=1e-12)
    text = _pair(20, 50, m=0.1, keys=", teeth = 50, on_teeth = 20", table="diametral_pitch = 10")
    sol = solve(parse_scene(text.replace('units = "mm"', 'units = "in"')))
    assert sol.scene.rolling[0].radius == pytest.approx(50 / 20 * 0.0254, rel=1e-12)
    assert sol.W["O3-B"] == pytest.approx(-W1 * 20 / 50, rel=1e-12)


def test_without_a_module_the_centre_distance_gives_the_radii():
    """No module: r = d z / (z2 + z3), said as a default taken; the ratio the teeth's."""
    sol = solve(parse_scene(_pair(20, 60, m=2.4, keys=", teeth = 60, on_teeth = 20", table="")))
    assert sol.scene.rolling[0].radius == pytest.approx(0.072, rel=1e-12)
    assert sol.W["O3-B"] == pytest.approx(-W1 / 3, rel=1e-12)
    note = next(n for n in sol.notes if "module not given" in n)
    assert "96 mm" in note and "72 mm and 24 mm" in note, note


RING = """
units = "mm"
[ground]
O1 = [{e}, 0]
O = [0, 0]
[links]
"O1-A" = {rp}
"O-Q" = {rr}
[rolling]
"O-Q" = {{ on = "O1-A", ring = true, teeth = {zr}, on_teeth = {zp}{module} }}
[input]
crank = "O1-A"
angle = 0
speed = "1000 rpm cw"
"""


@pytest.mark.parametrize("zp,zr,module", [(20, 80, ', module = "2 mm"'), (15, 61, "")])
def test_a_pinion_drives_a_ring_by_the_teeth_ratio(zp, zr, module):
    """A pinion on a fixed centre inside a ring: the ring turns the pinion's way at zp/zr."""
    rp, rr = zp, zr  # module 2 mm: m z / 2 = z mm (without one, the centre distance)
    sol = solve(parse_scene(RING.format(e=rr - rp, rp=rp, rr=rr, zr=zr, zp=zp, module=module)))
    assert sol.W["O-Q"] / sol.W["O1-A"] == pytest.approx(zp / zr, rel=1e-12)


COMPOUND = """
units = "mm"
[ground]
O1 = [0, 0]
O2 = [{d1}, 0]
O4 = [{d1}, {d2}]
[links]
"O1-A" = {r1}
"O2-B" = {r2}
"O4-C" = {r4}
[rolling]
module = "{m} mm"
"O2-B" = {{ on = "O1-A"{k1} }}
"O4-C" = {{ on = "O2-B"{k2} }}
[input]
crank = "O1-A"
angle = 0
speed = "1000 rpm cw"
"""


@pytest.mark.parametrize("z1,z2,z3,z4,m", [(20, 50, 15, 45, 4), (18, 54, 20, 60, 3)])
def test_compound_train_value_is_the_teeth_product(z1, z2, z3, z4, m):
    """Two gears keyed to one shaft: omega4 = omega1 (z1/z2)(z3/z4), two external meshes;
    and the scene by the teeth moves as the scene by the radii (on_radius by hand)."""
    r = [m * z / 2 for z in (z1, z2, z3, z4)]
    geo = dict(d1=r[0] + r[1], d2=r[2] + r[3], r1=r[0], r2=r[1], r4=r[3], m=m)
    teeth = COMPOUND.format(
        **geo, k1=f", teeth = {z2}, on_teeth = {z1}", k2=f", teeth = {z4}, on_teeth = {z3}"
    )
    sol = solve(parse_scene(teeth))
    assert sol.W["O4-C"] / sol.W["O1-A"] == pytest.approx(z1 * z3 / (z2 * z4), rel=1e-12)
    hand = solve(parse_scene(COMPOUND.format(**geo, k1="", k2=f", on_radius = {r[2]}")))
    for p in ("A", "B", "C"):
        assert math.dist(sol.V[p], hand.V[p]) <= 1e-12 * math.hypot(*hand.V[p])


EPICYCLIC = """
units = "mm"
[ground]
O = [0, 0]
[links]
OA = {arm}
AP = {rp}
"O-Q" = {rr}
[rolling]
{module}
AP = {{ on = "O", teeth = {zp}, on_teeth = {zs} }}
"O-Q" = {{ on = "AP", ring = true, teeth = {zr} }}
[input]
crank = "OA"
angle = 30
speed = "200 rpm ccw"
"""


@pytest.mark.parametrize("zs,zp,module", [(40, 24, 'module = "5 mm"'), (30, 21, "")])
def test_epicyclic_by_willis(zs, zp, module):
    """The sun fixed, the arm driven: Willis' formula, (omega - omega_arm) / (omega_sun -
    omega_arm) = -zs/z for the planet and -zs/zr for the annulus (zr = zs + 2 zp)."""
    zr = zs + 2 * zp
    m = 5.0
    text = EPICYCLIC.format(
        arm=m * (zs + zp) / 2, rp=m * zp / 2, rr=m * zr / 2, module=module, zp=zp, zs=zs, zr=zr
    )
    sol = solve(parse_scene(text))
    w_arm, w_sun = sol.W["OA"], 0.0
    assert (sol.W["AP"] - w_arm) / (w_sun - w_arm) == pytest.approx(-zs / zp, rel=1e-12)
    assert (sol.W["O-Q"] - w_arm) / (w_sun - w_arm) == pytest.approx(-zs / zr, rel=1e-12)


def _run(text, tmp_path):
    f = tmp_path / "g.toml"
    f.write_text(text, encoding="utf-8")
    return subprocess.run(
        [sys.executable, "-m", "polygon_method", "solve", str(f)],
        capture_output=True,
        text=True,
        timeout=120,
    )


@pytest.mark.parametrize(
    "keys,table,words",
    [
        (", teeth = 50.5, on_teeth = 20", None, "whole number"),
        (", teeth = 0, on_teeth = 20", None, "whole number"),
        (', teeth = "50", on_teeth = 20', None, "whole number"),
        (", teeth = 50, on_teeth = 20, radius = 90", None, "radius is 90 mm"),
        (", teeth = 50, on_teeth = 20", 'module = "5 mm"', "the link O3-B is 100 mm"),
        (", teeth = 50, on_teeth = 20, on_radius = 30", None, "on_radius is 30 mm"),
        (", teeth = 50", "", "module not given"),
        (', teeth = 50, on_teeth = 20, module = "4 mm", diametral_pitch = 6', "", "keep one"),
        (", teeth = 50, on_teeth = 20, module = -4", "", "above 0"),
    ],
)
def test_bad_teeth_are_one_line(tmp_path, keys, table, words):
    """Teeth not a whole number above 0, a radius that disagrees, no module and no second
    gear's teeth: one line naming the key, exit 2."""
    text = _pair(20, 50, keys=keys, table=table)
    out = _run(text, tmp_path)
    lines = out.stderr.strip().splitlines()
    assert out.returncode == 2 and len(lines) == 1, out.stderr + out.stdout
    assert "[rolling] O3-B" in lines[0]
    if words:
        assert words in lines[0], lines[0]


def test_module_bare_number_is_mm_in_any_unit():
    """A bare module is in mm (as a module always is), whatever the scene's unit."""
    text = _pair(20, 50, keys=", teeth = 50, on_teeth = 20", table="module = 4")
    text = text.replace('units = "mm"', 'units = "m"')
    for x in ("140", "40", "100"):
        text = text.replace(f"= {x}.0\n", f"= {float(x) / 1000}\n").replace(
            f"[{x}.0, 0]", f"[{float(x) / 1000}, 0]"
        )
    sol = solve(parse_scene(text))
    assert sol.scene.rolling[0].radius == pytest.approx(0.1, rel=1e-12)
    assert any("module 4 mm" in n for n in sol.notes)


def test_every_view_says_the_teeth():
    """solve's note, the step table's drawing of the wheel, the JSON's rolling record."""
    from polygon_method.text.steptable import steps_text

    sol = solve(parse_scene(_pair(20, 50)))
    assert any("pitch radius m z / 2 = 4 x 50 / 2 = 100 mm" in n for n in sol.notes)
    assert "50 teeth, pitch radius m z / 2 = 4 x 50 / 2 = 100 mm" in steps_text(sol)
    rec = sol.to_dict()["rolling"]["O3-B"]["teeth"]
    assert rec == {"teeth": 50, "on_teeth": 20, "module": pytest.approx(0.004, rel=1e-15)}


BY_HAND = """
units = "mm"
[ground]
O = [0, 0]
[links]
OA = {arm}
AP = {rp}
"O-Q" = {rr}
[rolling]
AP = {{ on = "O", on_radius = {rs} }}
"O-Q" = {{ on = "AP", ring = true }}
[input]
crank = "OA"
angle = 30
speed = "200 rpm ccw"
"""


@pytest.mark.parametrize("left_out", [("OA", "AP", "O-Q"), ("AP", "O-Q"), ("OA",)])
@pytest.mark.parametrize("zs,zp,m", [(40, 24, 5.0), (30, 21, 2.5)])
def test_lengths_left_out_are_the_teeth(zs, zp, m, left_out):
    """The gears' links and the arm left out of [links]: their lengths the pitch radii (m z
    / 2) and the centre distance (r_sun + r_planet), the motion the same as the scene with
    every length and radius by hand (no teeth), to 1e-12; Willis' formula holds."""
    zr = zs + 2 * zp
    geo = dict(arm=m * (zs + zp) / 2, rp=m * zp / 2, rr=m * zr / 2)
    text = EPICYCLIC.format(**geo, module=f'module = "{m} mm"', zp=zp, zs=zs, zr=zr)
    for key, name, length in (("OA", "OA", "arm"), ("AP", "AP", "rp"), ("O-Q", '"O-Q"', "rr")):
        if key in left_out:
            line = f"\n{name} = {geo[length]}\n"
            assert line in text
            text = text.replace(line, "\n", 1)
    sol = solve(parse_scene(text))
    hand = solve(parse_scene(BY_HAND.format(**geo, rs=m * zs / 2)))
    for p in ("A", "P", "Q"):
        assert math.dist(sol.P[p], hand.P[p]) <= 1e-12 * math.hypot(*hand.P[p])
        assert math.dist(sol.V[p], hand.V[p]) <= 1e-12 * math.hypot(*hand.V[p])
        assert math.dist(sol.A[p], hand.A[p]) <= 1e-12 * math.hypot(*hand.A[p])
    w_arm = sol.W["OA"]
    assert (sol.W["AP"] - w_arm) / -w_arm == pytest.approx(-zs / zp, rel=1e-12)
    assert (sol.W["O-Q"] - w_arm) / -w_arm == pytest.approx(-zs / zr, rel=1e-12)
    for key in left_out:
        assert any(n.startswith(f"[links] {key} not given") for n in sol.notes), sol.notes


@pytest.mark.parametrize("z2,z3", [(20, 50), (17, 43)])
def test_fixed_centres_gears_left_out(z2, z3):
    """Two gears about fixed centres with [links] left out (the driver named by on and
    on_teeth): the radii m z / 2, omega3 = -omega2 z2/z3, the motion of the scene with its
    links by hand, to 1e-12."""
    hand_text = _pair(z2, z3, keys="", table="")
    text = _pair(z2, z3).replace(f'"O2-A" = {2.0 * z2}\n"O3-B" = {2.0 * z3}\n', "")
    assert '"O2-A" = ' not in text.split("[rolling]")[0]
    sol, hand = solve(parse_scene(text)), solve(parse_scene(hand_text))
    assert sol.W["O3-B"] == pytest.approx(-W1 * z2 / z3, rel=1e-12)
    for p in ("A", "B"):
        assert math.dist(sol.V[p], hand.V[p]) <= 1e-12 * math.hypot(*hand.V[p])
        assert math.dist(sol.A[p], hand.A[p]) <= 1e-12 * math.hypot(*hand.A[p])


@pytest.mark.parametrize(
    "keys,table,words",
    [
        ("", "", "no link O3-B in [links]"),  # neither a length nor teeth
        # its teeth alone: the mate's teeth unknown, so not even the centre distance (the
        # fixed centres 140 mm apart) fixes its radius (with on_teeth = 20 too it does: d z
        # / (z + z_o), tests/test_epicyclic_torques_by_hand.py)
        (", teeth = 50", "", "no module to make its length"),
    ],
)
def test_gear_without_a_length_is_one_line(tmp_path, keys, table, words):
    """A gear left out of [links] with neither teeth and a module: one line naming the
    link, exit 2."""
    text = _pair(20, 50, keys=keys, table=table).replace('"O3-B" = 100.0\n', "", 1)
    out = _run(text, tmp_path)
    lines = out.stderr.strip().splitlines()
    assert out.returncode == 2 and len(lines) == 1, out.stderr + out.stdout
    assert "[rolling] O3-B" in lines[0] and words in lines[0], lines[0]


RING_FIXED = """
units = "mm"
[ground]
O = [0, 0]
[rolling]
module = "{m} mm"
AP = {{ on = "O", inside = true, teeth = {zp}, on_teeth = {zr} }}
[input]
crank = "OA"
angle = 30
speed = "200 rpm ccw"
"""


@pytest.mark.parametrize("zp,zr,m", [(24, 88, 5.0), (17, 61, 3.0)])
def test_arm_inside_a_fixed_ring_is_r_ring_less_r_planet(zp, zr, m):
    """A planet inside a fixed annulus, [links] left out: the arm r_ring - r_planet = m (zr
    - zp) / 2, and Willis' formula omega = omega_arm (1 - zr / zp)."""
    sol = solve(parse_scene(RING_FIXED.format(m=m, zp=zp, zr=zr)))
    arm = next(lk for lk in sol.scene.links if lk.key == "OA")
    assert arm.length * 1e3 == pytest.approx(m * (zr - zp) / 2, rel=1e-12)
    assert sol.W["AP"] == pytest.approx(sol.W["OA"] * (1 - zr / zp), rel=1e-12)
    assert any("220 - 60 = 160 mm" in n for n in sol.notes) or zp != 24


def test_arm_two_pairs_disagree_is_one_line(tmp_path):
    """The annulus's teeth not the sun's and two planets' (90, not 40 + 2 x 24): the arm
    from the two pairs disagrees, refused in one line naming it, exit 2."""
    text = EPICYCLIC.format(arm=160, rp=60, rr=225, module='module = "5 mm"', zp=24, zs=40, zr=90)
    text = text.replace("OA = 160\n", "").replace("AP = 60\n", "").replace('"O-Q" = 225\n', "")
    assert "[links]\n[rolling]" in text
    out = _run(text, tmp_path)
    lines = out.stderr.strip().splitlines()
    assert out.returncode == 2 and len(lines) == 1, out.stderr + out.stdout
    assert "[rolling] O-Q" in lines[0] and "the arm OA" in lines[0], lines[0]


def _left_out(radius_words="", module='module = "5 mm"'):
    """The book's epicyclic (sun 40, planet 24, annulus 88 teeth) with [links] left out, the
    annulus's entry given ``radius_words`` beside its teeth."""
    text = EPICYCLIC.format(arm=160, rp=60, rr=220, module=module, zp=24, zs=40, zr=88)
    text = text.replace("OA = 160\n", "").replace("AP = 60\n", "").replace('"O-Q" = 220\n', "")
    return text.replace("ring = true, teeth = 88", "ring = true, teeth = 88" + radius_words)


def test_a_radius_beside_teeth_that_disagrees_is_named_before_any_arm(tmp_path):
    """An annulus's radius of 200 mm beside 88 teeth of module 5 (220 mm): the radius is what
    is wrong, so the line names it (it had named an arm of 140 mm made from it)."""
    out = _run(_left_out(", radius = 200"), tmp_path)
    lines = out.stderr.strip().splitlines()
    assert out.returncode == 2 and len(lines) == 1, out.stderr + out.stdout
    assert "[rolling] O-Q" in lines[0] and "radius is 200 mm" in lines[0], lines[0]
    assert "220 mm" in lines[0] and "arm" not in lines[0], lines[0]


def test_a_radius_beside_teeth_that_agrees_makes_the_link_left_out():
    """The same radius stated as the teeth make it (220 mm), the annulus left out of
    [links]: its link that radius, and the train obeys Willis' formula to 1e-12."""
    sol = solve(parse_scene(_left_out(", radius = 220")))
    ring = next(lk for lk in sol.scene.links if lk.key == "O-Q")
    assert ring.length == pytest.approx(0.220, rel=1e-12)
    w_arm = sol.W["OA"]
    assert (sol.W["O-Q"] - w_arm) / -w_arm == pytest.approx(-40 / 88, rel=1e-12)


@pytest.mark.parametrize(
    "module", ['module = "1e-300 mm"', 'module = "1e9 mm"', "diametral_pitch = 1e300"]
)
def test_an_absurd_module_is_one_line(tmp_path, module):
    """A module (or a diametral pitch) that would make teeth below a tenth of a micrometre
    or kilometres long is refused in one line naming the module (it had passed to a length
    of 3e-302 m, refused as an [links] entry the scene never wrote)."""
    out = _run(_left_out(module=module), tmp_path)
    lines = out.stderr.strip().splitlines()
    assert out.returncode == 2 and len(lines) == 1, out.stderr + out.stdout
    said = module.split(" =")[0]  # the key the scene wrote (module or diametral_pitch)
    assert f"[rolling] {said} (line" in lines[0] and "absurd" in lines[0], lines[0]


def test_a_wheel_that_does_not_speed_up_has_no_sense_in_the_step_table(capsys):
    """The arm turning uniformly, Willis' formula makes every wheel's alpha nought (omega a
    fixed multiple of the arm's): the step table writes it with no sense (it wrote
    "alpha_AP = 0 rad/s^2 ccw"), as every nought angular quantity is written."""
    from polygon_method.cli import main

    path = Path(__file__).resolve().parents[1] / "tests" / "textbook"
    assert main(["steps", str(path / "rattan_epicyclic_by_teeth.toml")]) == 0
    out = " ".join(capsys.readouterr().out.split())
    assert "alpha_AP = 0 rad/s^2 from the no-" in out  # (the line may break at its hyphen)
    assert "alpha_O-Q = 0 rad/s^2 from the no-" in out
    assert "0 rad/s^2 ccw" not in out and "0 rad/s^2 cw" not in out
