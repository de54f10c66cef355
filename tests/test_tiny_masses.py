"""A mass, a moment of inertia or a weight far below any link's (1e-300 kg) is a slip:
refused in one line naming the key and its line, as a force, a torque or a pressure below
its least size is (``common/unit_tables.py`` ``TINY``: one rule). A signed length as tiny
(a centre 1e-300 mm along its link) is no slip: it is accepted, and the answers stay exact
(the torque's change from a centre 50 mm out is the crank's weight's moment, to 1e-9)."""

from __future__ import annotations

import math
import subprocess
import sys
from pathlib import Path

import pytest

from polygon_method import parse_scene, solve
from polygon_method.common.errors import SceneError

ROOT = Path(__file__).resolve().parent.parent
FOURBAR = (ROOT / "worked_problems" / "fourbar_forces.toml").read_text()
CRANK = '"O2-A" = { mass = "2 kg", along = 50, inertia = "0.005 kg m^2" }'
assert CRANK in FOURBAR


def _with(entry):
    return FOURBAR.replace(CRANK, f'"O2-A" = {{ {entry} }}')


@pytest.mark.parametrize(
    "entry",
    [
        'mass = "1e-300 kg", along = 50',
        "mass = 1e-300, along = 50",
        'mass = "1e-330 kg", along = 50',  # reads as 0.0, yet is no zero
        'mass = "1e-300 N", along = 50',  # a weight
        'mass = "1e-300 kg/m"',  # per length
        'mass = "2 kg", along = 50, inertia = "1e-300 kg m^2"',
        'mass = "2 kg", along = 50, inertia = 1e-20',
    ],
)
def test_a_mass_or_inertia_far_below_any_links_is_refused_at_its_line(entry):
    text = _with(entry)
    with pytest.raises(SceneError) as exc:
        parse_scene(text, file="s.toml")
    err = exc.value
    assert "absurdly small" in err.message and "\n" not in err.message
    assert err.key == "[masses] O2-A"
    assert err.line == text.splitlines().index(f'"O2-A" = {{ {entry} }}') + 1


def test_the_least_sizes_are_accepted():
    """A milligram and 1e-12 kg m^2 are no slip (1000 times the least sizes)."""
    sc = parse_scene(_with('mass = "0.001 g", along = 50, inertia = "1e-12 kg m^2"'))
    (m,) = [m for m in sc.masses if m.body == "O2-A"]
    assert m.mass == pytest.approx(1e-6, rel=1e-12)


def test_a_tiny_signed_length_is_accepted_and_exact():
    """The crank at constant speed: its inertia force is radial (through O2) and its
    I alpha zero, so moving its centre from 50 mm to 1e-300 mm out changes the driving
    torque by its weight's moment only, m g r cos(theta) (2 kg, 50 mm, 60 deg)."""
    far = solve(parse_scene(FOURBAR))
    near = solve(parse_scene(_with('mass = "2 kg", along = 1e-300, inertia = "0.005 kg m^2"')))
    g = 9.81
    want = 2.0 * g * 0.05 * math.cos(math.radians(60))
    t_far, t_near = far.forces.input_torque, near.forces.input_torque
    assert t_far - t_near == pytest.approx(want, rel=1e-9)
    for p in near.forces.pins:
        assert all(math.isfinite(c) and (c == 0 or abs(c) > 1e-200) for c in p.force)


def test_the_command_line_says_it_in_one_line(tmp_path):
    path = tmp_path / "s.toml"
    path.write_text(_with('mass = "1e-300 kg", along = 50'))
    out = subprocess.run(
        [sys.executable, "-m", "polygon_method", "solve", str(path)],
        capture_output=True,
        text=True,
    )
    assert out.returncode == 2 and "Traceback" not in out.stderr
    assert out.stderr.count("\n") == 1 and "[masses] O2-A (line" in out.stderr
