"""A machine's torque given in readings (straight segments) beside a motor's steady torque,
``torque = "constant"`` with ``resisting = [...]`` at ``angle = [...]`` (the books' "the
torque of the machine varies ...; the driving torque is constant"): against the areas by
hand (tests/textbook/flywheel/segments_machine_torque_three_turns.toml), the speed
greatest where the machine begins to take more than the motor gives (it had to be stated
the other way round, the machine's torque as the engine's, which put the speed's extremes
the wrong way); a jump in the machine's torque drawn upright; the CSV one row an angle."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from polygon_method.cli import main
from polygon_method.forces.flywheel_cycle import curves, solve_cycle
from polygon_method.scene.energy import cycle_from_text

FILE = (
    Path(__file__).resolve().parent
    / "textbook"
    / "flywheel"
    / "segments_machine_torque_three_turns.toml"
)


def _cycle(text):
    scene = cycle_from_text(text)
    return scene, solve_cycle(scene)


def test_the_machines_torque_in_readings_against_the_areas_by_hand():
    scene, c = _cycle(FILE.read_text(encoding="utf-8"))
    # the mean: the trapezoids 1875 pi + 6000 pi + 1875 pi + 1500 pi over 6 pi rad
    assert c.T_mean == pytest.approx(11250 * math.pi / (6 * math.pi), rel=1e-12)
    # above the mean 90 to 630 deg: two triangles 1/2 x 1125 x pi/2 and 1125 x 2 pi
    want = 2 * (0.5 * 1125 * math.pi / 2) + 1125 * 2 * math.pi
    assert c.dE_max == pytest.approx(want, rel=1e-12)
    # the motor gives more than the machine takes up to 90 deg: the speed greatest there
    hi, lo = c.crossings[c.i_max], c.crossings[c.i_min]
    assert math.degrees(hi.angle) == pytest.approx(90, abs=1e-9)
    assert math.degrees(lo.angle) == pytest.approx(630, abs=1e-9)
    assert c.Cs == pytest.approx(want / (180 * (250 * math.pi / 30) ** 2), rel=1e-12)


def test_the_book_states_it_with_the_machine_as_the_engine_gets_the_extremes_swapped():
    """The same numbers as the engine's torque (the only way before): dE_max alike, the
    speed's extremes the other way round -- what the resisting readings put right."""
    text = FILE.read_text(encoding="utf-8")
    swapped = text.replace(
        'resisting = [750, 3000, 3000, 750, 750]\ntorque = "constant"',
        "torque = [750, 3000, 3000, 750, 750]",
    )
    _, c = _cycle(swapped)
    _, m = _cycle(text)
    assert c.dE_max == pytest.approx(m.dE_max, rel=1e-12)
    assert c.crossings[c.i_max].angle == pytest.approx(m.crossings[m.i_min].angle)


def test_a_jump_in_the_machines_torque_is_drawn_upright_and_tabulated_once(tmp_path, capsys):
    text = (
        "[turning_moment]\nangle = [0, 180, 180, 360]\nresisting = [500, 500, 1500, 1500]\n"
        'torque = "constant"\n[flywheel]\nspeed = "300 rpm"\nplus_minus = "1%"\n'
    )
    scene, c = _cycle(text)
    assert c.T_mean == pytest.approx(1000)
    assert c.dE_max == pytest.approx(500 * math.pi, rel=1e-12)  # 500 N m over half a turn
    th, tq, rs, _ = curves(scene, c, 9)
    at = [i for i in range(len(th)) if th[i] == math.pi]  # the jump: before it, then after
    assert len(at) >= 2 and rs[at[0]] == 500.0 and rs[at[-1]] == 1500.0
    assert all(t == pytest.approx(1000) for t in tq)
    path = tmp_path / "s.toml"
    path.write_text(text, encoding="utf-8")
    out = tmp_path / "s.csv"
    assert main(["sweep", str(path), "--csv", str(out), "--steps", "4"]) == 0
    rows = out.read_text().splitlines()[1:]
    assert len(rows) == len(set(rows))  # no row twice
    assert [r.split(",")[0] for r in rows] == ["0", "90", "180", "180", "270", "360"]
    assert f"{len(rows)} crank angles" in capsys.readouterr().err


def test_a_list_of_resisting_torques_needs_the_angles_and_a_steady_motor(tmp_path):
    bad = '[turning_moment]\nangle = [0, 180, 360]\nresisting = [1, 2]\ntorque = "constant"\n'
    path = tmp_path / "b.toml"
    path.write_text(bad, encoding="utf-8")
    assert main(["solve", str(path)]) == 2
