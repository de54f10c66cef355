"""The summary of a scene with masses: the force analysis's extremes over the turn (the
driving torque with inertia, the shaking force and moment, every pin force, an engine's
efforts), each held to the sweep's own columns: its value at the summary's angle is the
extreme it states, and no angle of a dense sweep (7,200 angles) goes beyond it. A scene the
force analysis cannot cover at some angle says so and summarises no force."""

import math
from pathlib import Path

import numpy as np
import pytest

from polygon_method import load_scene
from polygon_method.linkage.summary import summarize
from polygon_method.motion.sweeps import sweep

ROOT = Path(__file__).resolve().parent.parent
SCENES = [
    ROOT / "worked_problems" / "fourbar_forces.toml",
    ROOT / "worked_problems" / "engine_forces.toml",
]


def _columns(res):
    """name -> array of the sweep's force columns; a pin force's or the shaking force's
    size from the CSV's components where the summary gives a size."""
    cols = {name: np.asarray(arr, dtype=float) for name, _, arr in res.force_columns()}
    cols["shake"] = np.hypot(cols.pop("shake_x"), cols.pop("shake_y"))
    return cols


@pytest.mark.parametrize("path", SCENES, ids=lambda p: p.stem)
def test_force_extremes_are_the_sweeps_own(path):
    scene = load_scene(path)
    summary = summarize(scene)
    rows = {e.name: e for e in summary.extremes}
    dense = _columns(sweep(scene, np.radians(np.arange(0.0, 360.0, 0.05))))
    forces = [n for n in dense if n in rows]
    assert "shake" in forces and any(n.startswith("F_") for n in forces)
    assert "torque_inertia" in forces
    F = max(max(abs(rows[n].maximum), abs(rows[n].minimum)) for n in forces if rows[n].unit == "N")
    L = max(lk.length for lk in scene.links)
    for name in forces:  # (to a 1e-9 part of the largest force, of it times the longest link)
        e = rows[name]
        size = max(abs(e.maximum), abs(e.minimum), F * (L if e.unit == "N m" else 1.0))
        assert dense[name].max() <= e.maximum + 1e-9 * size, name
        assert dense[name].min() >= e.minimum - 1e-9 * size, name
        for value, at in ((e.maximum, e.at_max), (e.minimum, e.at_min)):
            if at is None:
                continue
            there = _columns(sweep(scene, [math.radians(at)]))[name][0]
            assert there == pytest.approx(value, rel=1e-6, abs=1e-9 * size), (name, at)


def test_the_engine_summarises_its_efforts():
    rows = {e.name for e in summarize(load_scene(SCENES[1])).extremes}
    assert {"piston_effort", "crank_effort", "turning_moment"} <= rows


def test_no_forces_summarised_where_the_analysis_fails(monkeypatch):
    from polygon_method.common.errors import PolygonMethodError
    import polygon_method.forces as forces

    def refuse(motion):
        raise PolygonMethodError("forces: refused here")

    monkeypatch.setattr(forces, "analyse", refuse)
    summary = summarize(load_scene(SCENES[0]))
    names = {e.name for e in summary.extremes}
    assert not any(n.startswith("F_") or n.startswith("shake") for n in names)
    assert any("forces are not summarised: forces: refused here" in n for n in summary.notes)
