"""``check --tolerance 1 mm`` and ``--tolerance 1 deg``: a teacher grading a drawing gives
an absolute tolerance for the answers that are lengths (a centre's position, a stroke, an
inertia force's offset) or angles (a link's direction, the angle at a joint), beside a per
cent or a velocity's; each verdict's rule and the report's "tolerance used" say it.

The expected values are closed forms written here: the four-bar's C from two circles, the
centre of the coupler as the crossing of lines AB and DC, the direction of CD, the slider
crank's stroke 2 r."""

from __future__ import annotations

import json
import math

import pytest

from polygon_method.cli import main
from scenes import seed

FOURBAR = seed(middle='[assembly]\nC = "above"\n')  # A (0, 0), D (100, 0); AB 50, BC 66, CD 56


def _fourbar():
    """B, C (mm) at 60 deg, C above AD."""
    bx, by = 50 * math.cos(math.radians(60)), 50 * math.sin(math.radians(60))
    ex, ey = 100 - bx, -by
    e = math.hypot(ex, ey)
    along = (66**2 - 56**2 + e * e) / (2 * e)
    h = math.sqrt(66**2 - along * along)
    ux, uy = ex / e, ey / e
    cands = [(bx + along * ux - s * h * uy, by + along * uy + s * h * ux) for s in (1, -1)]
    return (bx, by), max(cands, key=lambda p: p[1])


def _centre_of_the_coupler():
    """I_ground_BC: where line AB (through A, B) meets line DC (through D, C), in mm."""
    (bx, by), (cx, cy) = _fourbar()
    # A + t (B - A) = D + u (C - D)
    dx, dy = cx - 100.0, cy
    det = bx * (-dy) - by * (-dx)
    t = (100.0 * (-dy)) / det
    return t * bx, t * by


def _theta_dc():
    (_, _), (cx, cy) = _fourbar()
    return math.degrees(math.atan2(cy, cx - 100.0)) % 360  # D -> C


def _run(capsys, *argv):
    code = main(list(map(str, argv)))
    out = capsys.readouterr()
    return code, out.out, out.err


def _files(tmp_path, answers):
    scene = tmp_path / "s.toml"
    scene.write_text(FOURBAR)
    ans = tmp_path / "ann.toml"
    ans.write_text("[answers]\n" + answers)
    return scene, ans


def test_a_centre_within_one_millimetre(tmp_path, capsys):
    ix, iy = _centre_of_the_coupler()
    scene, ans = _files(tmp_path, f"I_ground_BC = [{ix + 0.6:.4f}, {iy - 0.6:.4f}]\n")  # 0.85 mm
    code, out, _ = _run(capsys, "check", scene, ans, "--tolerance", "1 mm", "--json")
    data = json.loads(out)
    (v,) = data["answers"]
    assert code == 0 and v["verdict"] == "right" and "1 mm" in v["rule"]
    assert "1 mm" in data["tolerance_used"]["why"]
    code, out, _ = _run(capsys, "check", scene, ans, "--tolerance", "0.5 mm")
    assert code == 1 and "WRONG" in out and "0.5 mm" in out


def test_a_links_direction_within_one_degree(tmp_path, capsys):
    want = _theta_dc()
    scene, ans = _files(tmp_path, f'theta_DC = "{want + 0.8:.4f} deg"\n')
    code, out, _ = _run(capsys, "check", scene, ans, "--tolerance", "1 deg")
    assert code == 0 and "tolerance used: 1 deg, from --tolerance on the command line" in out
    code, out, _ = _run(capsys, "check", scene, ans, "--tolerance", "0.5 deg", "--json")
    (v,) = json.loads(out)["answers"]
    assert code == 1 and v["verdict"] == "wrong" and "0.5 deg" in v["rule"]
    assert v["tolerance_percent"] / 100 * v["correct"] == pytest.approx(math.radians(0.5))
    assert v["correct"] == pytest.approx(math.radians(_theta_dc()), rel=1e-12)


def test_lengths_and_angles_beside_a_per_cent(tmp_path, capsys):
    """1 mm for the centre, 1 deg for the direction, 5 % for the rest (omega_BC 4 % off)."""
    ix, iy = _centre_of_the_coupler()
    from test_check import fourbar_closed_form

    w3, _ = fourbar_closed_form()
    scene, ans = _files(
        tmp_path,
        f"I_ground_BC = [{ix + 0.9:.4f}, {iy:.4f}]\n"
        f'theta_DC = "{_theta_dc() - 0.9:.4f} deg"\n'
        f'omega_BC = "{abs(w3) * 1.04:.5f} rad/s"\n',
    )
    argv = ["check", scene, ans, "--tolerance", "1 mm", "--tolerance", "1 deg"]
    code, out, _ = _run(capsys, *argv, "--tolerance", "5%", "--json")
    data = json.loads(out)
    got = {a["key"]: a for a in data["answers"]}
    assert code == 0 and all(a["verdict"] == "right" for a in got.values())
    assert "5 %" in got["omega_BC"]["rule"] and "1 deg" in got["theta_DC"]["rule"]
    assert data["tolerance_used"]["why"].startswith("5 %, 1 mm, 1 deg")


def test_a_stroke_within_one_millimetre(tmp_path, capsys):
    scene = tmp_path / "s.toml"
    scene.write_text(
        'units = "mm"\n[ground]\nO = [0, 0]\n[links]\nOA = 60\nAB = 240\n'
        '[sliders]\nB = { path = "horizontal" }\n[input]\ncrank = "OA"\nangle = 30\n'
        'speed = "10 rad/s ccw"\n'
    )
    ans = tmp_path / "a.toml"
    ans.write_text('[answers]\nstroke_B = "120.9 mm"\n')  # 2 r = 120 mm
    code, out, _ = _run(capsys, "check", scene, ans, "--tolerance", "1 mm")
    assert code == 0 and "1 mm" in out
    ans.write_text('[answers]\nstroke_B = "121.2 mm"\n')
    code, out, _ = _run(capsys, "check", scene, ans, "--tolerance", "1 mm")
    assert code == 1


@pytest.mark.parametrize("bad", ["0 mm", "-1 deg", "1 deg ccw"])
def test_a_bad_length_or_angle_tolerance_is_one_line(tmp_path, capsys, bad):
    scene, ans = _files(tmp_path, 'v_C = "0.4 m/s"\n')
    code, _, err = _run(capsys, "check", scene, ans, "--tolerance", bad)
    assert code == 2 and "--tolerance" in err and len(err.strip().splitlines()) == 1
