"""A sweep through a position where a group's force equations are exactly singular: a
parallel crank's dead point (the crank along the frame, the coupler and the rocker in one
line with it: the moments about the pins cannot hold the force between them). The force
columns are present; the singular row's force cells are empty (never a NaN or an infinity)
and ``condition_forces`` is 0 there; every other row's forces are those of the sweep
without the dead point's angle, and its driving torque balances the virtual power with
inertia (G's motion from the links' ends, here) to 1e-9.
"""

from __future__ import annotations

import csv
import io
from types import SimpleNamespace

import numpy as np
import pytest

from polygon_method.cli import main
from polygon_method.motion.sweeps import sweep
from polygon_method.scene import parse_scene

PARALLEL = """
title = "parallel crank four-bar with masses"
units = "mm"
[ground]
O = [0, 0]
C = [300, 0]
[links]
OA = 100
AB = 300
CB = 100
[assembly]
B = [390, 40]
[input]
crank = "OA"
angle = 20
speed = "10 rad/s ccw"
acceleration = "4 rad/s^2 cw"
[masses]
OA = { mass = 1, along = 50 }
AB = { mass = 2, distances = { A = 160, B = 160 }, turn = "ccw", gyration = 90 }
CB = { mass = 1.5, along = 60, gyration = 40 }
[gravity]
direction = 260
[loads]
B = { force = [20, -50] }
CB = { torque = "3 N m ccw" }
"""

#: every 7.5 deg from 0: the dead point at 0 exactly (and 180, where the rounding of the
#: positions leaves the equations a hair from singular: its condition says so)
DEGREES = np.arange(0.0, 360.0, 7.5)


def _table(text):
    rows = list(csv.reader(io.StringIO(text)))
    head = [h.split(" [")[0] for h in rows[0]]
    return head, rows[1:]


@pytest.fixture(scope="module")
def swept():
    sc = parse_scene(PARALLEL)
    res = sweep(sc, np.radians(DEGREES))
    assert len(res) == len(DEGREES)
    return sc, res


def _virtual_power(sol, T):
    """``T w + sum F.v + sum C w + sum m g.v_G - sum m a_G.v_G - sum I alpha w`` and the
    size of its terms (``T`` the driver's torque with inertia)."""
    sc = sol.scene
    terms = [T * sol.W[sc.input.crank]]
    for ld in sc.loads:
        if ld.force is not None:
            v = sol.V[ld.target]
            terms.append(ld.force[0] * v[0] + ld.force[1] * v[1])
        else:
            terms.append(ld.torque * sol.W[ld.target])
    g = sc.gravity
    for m in sc.masses:
        lk = sc.link(m.body)

        def at(T, lk=lk, m=m):
            (px, py), (qx, qy) = T[lk.p], T[lk.q]
            dx, dy = qx - px, qy - py
            return (px + m.lam * dx - m.mu * dy, py + m.lam * dy + m.mu * dx)

        v, a = at(sol.V), at(sol.A)
        terms.append(m.mass * g.g * (g.direction[0] * v[0] + g.direction[1] * v[1]))
        terms.append(-m.mass * (a[0] * v[0] + a[1] * v[1]))
        terms.append(-m.inertia * sol.Al[lk.key] * sol.W[lk.key])
    return sum(terms), sum(abs(t) for t in terms)


def test_the_force_columns_are_there_and_empty_only_at_the_dead_point(swept):
    sc, res = swept
    text = res.to_csv(error_bound=True)
    assert "nan" not in text.lower() and "inf" not in text.lower()
    head, rows = _table(text)
    forces = [h for h in head if h.startswith(("F_", "shake", "torque_inertia", "err_forces"))]
    assert "torque_inertia" in forces and "err_forces" in forces and len(forces) >= 8
    cond = head.index("condition_forces")
    for deg, row in zip(DEGREES, rows):
        cells = [row[head.index(h)] for h in forces]
        if deg == 0.0:
            assert cells == [""] * len(cells) and float(row[cond]) == 0.0
        else:
            assert all(c != "" for c in cells), deg
            assert 0.0 < float(row[cond]) <= 1.0
    # the rest of the row is there: the kinematics at the dead point
    zero = rows[0]
    assert all(zero[head.index(h)] != "" for h in head if h.startswith(("x_", "omega_")))


def _row(res, i):
    """The sweep's motion at its row ``i``, as floats."""

    def at(d):
        return {
            k: tuple(float(np.broadcast_to(c, res.theta.shape)[i]) for c in v) for k, v in d.items()
        }

    def one(d):
        return {k: float(np.broadcast_to(v, res.theta.shape)[i]) for k, v in d.items()}

    return SimpleNamespace(scene=res.scene, V=at(res.V), A=at(res.A), W=one(res.W), Al=one(res.Al))


def test_every_other_row_balances_the_power_and_is_the_sweep_without_the_dead_point(swept):
    """The torque at every determined row balances the virtual power with the sweep's own
    kinematics (past 180 deg the parallel crank may cross to its other branch: the sweep's,
    not the scene's); each force column is the sweep's without the dead point's angle."""
    sc, res = swept
    head, rows = _table(res.to_csv())
    at_180 = float(rows[list(DEGREES).index(180.0)][head.index("condition_forces")])
    assert at_180 < 1e-12  # a hair from singular: said by the condition
    clear = sweep(sc, np.radians(DEGREES[1:]))
    head2, rows2 = _table(clear.to_csv())
    assert np.allclose(np.radians(clear.degrees), np.radians(DEGREES[1:]))
    checked = 0
    for i, (deg, row) in enumerate(zip(DEGREES, rows)):
        if deg == 0.0:
            continue
        for h in head2:  # the same columns, the same numbers
            assert float(row[head.index(h)]) == pytest.approx(
                float(rows2[i - 1][head2.index(h)]), rel=1e-12, abs=1e-12
            ), (deg, h)
        if deg == 180.0:  # (a hair from singular: the balance loses its digits there)
            continue
        T = float(row[head.index("torque_inertia")])
        total, size = _virtual_power(_row(res, i), T)
        assert abs(total) <= 1e-9 * size, deg
        checked += 1
    assert checked == len(DEGREES) - 2


def test_the_sweep_command_writes_the_columns(tmp_path, capsys):
    scene = tmp_path / "parallel.toml"
    scene.write_text(PARALLEL)
    out = tmp_path / "p.csv"
    assert main(["sweep", str(scene), "--steps", "8", "--csv", str(out)]) == 0
    capsys.readouterr()
    head, rows = _table(out.read_text())
    assert "torque_inertia" in head and "condition_forces" in head
    assert rows[0][head.index("torque_inertia")] == ""
    assert rows[1][head.index("torque_inertia")] != ""


def test_a_sweep_clear_of_the_dead_point_has_no_condition_column(swept):
    sc, _ = swept
    res = sweep(sc, np.radians(DEGREES[1:12]))
    head, rows = _table(res.to_csv())
    assert "condition_forces" not in head and "torque_inertia" in head
    assert all(all(c != "" for c in r) for r in rows)
