"""A load stated against a link in every view: ``solve --json``'s ``loads`` gives its
force and direction at the instant (with the link's two points, the offset and the words),
``sweep`` a ``load_dir_M`` column of its direction at every row; both against the closed
form's positions (``test_link_loads._positions``: C where two circles cross)."""

from __future__ import annotations

import csv
import io
import json
import math

import numpy as np
import pytest

from polygon_method import solve
from polygon_method.cli import main
from polygon_method.motion.sweeps import sweep
from test_link_loads import SCENE, _positions, _scene, _unit

#: each direction's words -> (its link's points, by their index in _positions, the turn)
WAYS = {
    '"perpendicular to BC, ccw"': (1, 2, 90.0),
    '"along CD"': (2, 3, 0.0),
    '"30 deg cw from DC"': (3, 2, -30.0),
    '"at 45 deg to BC, anticlockwise"': (1, 2, 45.0),
}


def _deg(v):
    return math.degrees(math.atan2(v[1], v[0])) % 360


@pytest.mark.parametrize("words", list(WAYS))
def test_the_json_gives_the_loads_force_and_direction_at_the_instant(words):
    p, q, turn = WAYS[words]
    d = solve(_scene(words, "270")).to_dict()
    pos = _positions(math.radians(60))
    want = 500 * _unit(pos[p], pos[q], turn)
    m = d["loads"]["M"]
    assert m["force"] == pytest.approx(list(want), rel=1e-9, abs=1e-9 * 500)
    assert m["direction"] == pytest.approx(_deg(want), abs=1e-9)
    assert m["against"] == [["A", "B", "C", "D"][p], ["A", "B", "C", "D"][q]]
    assert m["offset"] == pytest.approx(turn, abs=1e-12)
    assert m["stated"] == words.strip('"')
    e = d["loads"]["E"]  # a plain angle: its force and direction, nothing against a link
    assert e["force"] == [0.0, -200.0] and e["direction"] == 270.0 and "against" not in e


def test_a_torque_load_is_listed_too_and_a_scene_without_loads_has_no_key():
    text = SCENE.format(m='"along CD"', e="0", angle=60) + 'CD = { torque = "20 N m cw" }\n'
    from polygon_method import parse_scene

    d = solve(parse_scene(text)).to_dict()
    assert d["loads"]["CD"] == {"torque": -20.0}
    no = SCENE.format(m="0", e="0", angle=60).split("[masses]")[0]
    assert "loads" not in solve(parse_scene(no)).to_dict()


@pytest.mark.parametrize("words", list(WAYS))
def test_the_sweep_has_the_direction_at_every_row(words):
    p, q, turn = WAYS[words]
    degs = [0, 45, 100, 170, 230, 300]
    res = sweep(_scene(words, "270"), np.radians(degs))
    cols = {(k, u): v for k, u, v in res.columns()}
    assert ("load_dir_E", "deg") not in cols  # a plain angle stays put: no column
    got = cols[("load_dir_M", "deg")]
    for i, d in enumerate(degs):
        pos = _positions(math.radians(d))
        want = _deg(_unit(pos[p], pos[q], turn))
        err = (got[i] - want + 180) % 360 - 180
        assert abs(err) <= 1e-9


def test_the_csv_and_the_json_agree_at_the_scenes_instant(tmp_path, capsys):
    path = tmp_path / "s.toml"
    path.write_text(
        SCENE.format(m='"perpendicular to BC, ccw"', e='"30 deg ccw from CD"', angle=60)
    )
    assert main(["solve", "--json", str(path)]) == 0
    loads = json.loads(capsys.readouterr().out)["loads"]
    assert (
        main(["sweep", str(path), "--from", "60", "--to", "60", "--step", "1", "--csv", "-"]) == 0
    )
    rows = list(csv.DictReader(io.StringIO(capsys.readouterr().out)))
    assert float(rows[0]["load_dir_M [deg]"]) == pytest.approx(loads["M"]["direction"], abs=1e-9)
    assert float(rows[0]["load_dir_E [deg]"]) == pytest.approx(loads["E"]["direction"], abs=1e-9)
