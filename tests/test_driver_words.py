"""The views name the driver as the driver names itself: a sweep of a collar-driven scene
speaks of the collar's places (not of "block C"), and a scene whose motion is given as a
cylinder's rate of extension states the effort by power balance as the force in that
cylinder (not a torque on the crank the cylinder turns)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from polygon_method import load_scene, solve, sweep
from polygon_method.cli import main

WORKED = Path(__file__).resolve().parent.parent / "worked_problems"
COLLAR = WORKED / "collar_on_turning_rod.toml"
BOOM = WORKED / "boom_cylinder_load.toml"


def test_a_collar_driven_sweep_counts_the_collars_places(capsys, tmp_path):
    """Places beyond the collar's travel (150 to 450 mm on OA) are left out, and the count
    names what was asked for: places of the collar on its rod."""
    code = main(
        ["sweep", str(COLLAR), "--from", "200", "--to", "2000", "--step", "100"]
        + ["--csv", str(tmp_path / "s.csv")]
    )
    out = capsys.readouterr().out
    assert code == 0
    assert "3 of 19 places of collar C on OA (mm) evaluated" in out  # 200, 300, 400 mm
    assert "block" not in out


def test_a_collar_driven_sweep_out_of_reach_names_the_collar(capsys, tmp_path):
    code = main(
        ["sweep", str(COLLAR), "--from", "1500", "--to", "2000", "--step", "100"]
        + ["--csv", str(tmp_path / "s.csv")]
    )
    err = capsys.readouterr().err
    assert code == 2 and len(err.strip().splitlines()) == 1
    assert "none of the requested places of collar C on OA (mm)" in err
    assert "block" not in err


@pytest.mark.parametrize(
    "args, says",
    [
        (["--from", "200", "--to", "400"], "--from, --to and --step go together (the places of "),
        (["--from", "0", "--to", "1e9", "--step", "1"], "--from and --to are the places of "),
    ],
)
def test_a_collar_driven_sweeps_bad_range_names_the_collar(args, says, capsys):
    assert main(["sweep", str(COLLAR), *args, "--csv", "-"]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and says in err
    assert "collar C on OA" in err and "block" not in err


def test_a_collar_driven_sweeps_plot_is_labelled_by_the_collar():
    pytest.importorskip("matplotlib")
    from polygon_method.draw.plots import plot_figure

    scene = load_scene(COLLAR)
    res = sweep(scene, [0.2, 0.3, 0.4])
    fig = plot_figure(res)
    labels = [ax.get_xlabel() for ax in fig.axes if ax.get_xlabel()]
    assert labels and all(lab == "place of collar C on OA, s_C (mm)" for lab in labels)
    assert "input: the place of collar C on OA" in fig._suptitle.get_text()


def _number(pattern, text):
    found = re.search(pattern, text)
    assert found, (pattern, text)
    return float(found.group(1))


def test_a_cylinder_driven_scene_states_the_force_in_its_cylinder(capsys):
    """The boom: the cylinder C-R extends at 0.3 m/s and 4905 N hangs down at B. The power
    the cylinder puts in, F vs, balances the load's, so F = 4905 N x (B's upward velocity)
    / 0.3 m/s, worked here from B's velocity alone (no torque on the crank enters)."""
    sol = solve(load_scene(BOOM))
    by_hand = 4905.0 * sol.V["B"][1] / 0.3
    assert by_hand > 0  # the load is lifted: the cylinder pushes
    assert main(["solve", str(BOOM)]) == 0
    out = capsys.readouterr().out
    assert "input torque on OB" not in out
    f = _number(r"input force in cylinder C-R: (\S+) N pushing its ends apart \(power", out)
    assert f == pytest.approx(by_hand, rel=5e-4)  # printed to 4 significant figures
    key, exact = sol.cylinder_force
    assert key == "C-R" and exact == pytest.approx(by_hand, rel=1e-12)
    assert main(["steps", str(BOOM)]) == 0
    steps = " ".join(capsys.readouterr().out.split())  # (its lines wrapped)
    f = _number(r"the cylinder C-R drives: F vs_C-R = T omega_OB, F = .* = (\S+) N pushing", steps)
    assert f == pytest.approx(by_hand, rel=5e-4)


def test_a_crank_driven_scene_keeps_its_torque():
    """The force is asked only where a cylinder's motion is given: a crank driven at its
    speed with a load has its torque and no cylinder force."""
    sol = solve(load_scene(WORKED / "fourbar_forces.toml"))
    assert sol.input_torque is not None and sol.cylinder_force is None
