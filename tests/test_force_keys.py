"""The force chapter's answer keys by name (``Fi_L``, ``Ci_L``, ``h_L``, ``shaking_force``,
``shaking_moment``, ``rod_thrust``, ``side_thrust``), each against a closed form the test
works out from the kinematics alone: D'Alembert's ``-m a_G`` and ``-I alpha`` with G set out
on its link by the test; the shaking force and moment from Newton's laws for all the moving
bodies at once (the frame's reaction is what the applied and inertia forces leave: no pin
force enters); the engine's thrust in the rod ``F_P / cos(phi)`` and on the walls
``F_P tan(phi)`` from the rod's obliquity phi. Then ``check`` marks the true values right and
a slipped one wrong."""

import math
from dataclasses import replace
from pathlib import Path

import pytest

from polygon_method import load_scene, solve
from polygon_method.check import check_answers
from polygon_method.check.engine import engine_value
from polygon_method.common.errors import SceneError
from polygon_method.scene import parse_scene

ROOT = Path(__file__).resolve().parent.parent
FOURBAR = ROOT / "worked_problems" / "fourbar_forces.toml"
ENGINE = ROOT / "worked_problems" / "engine_forces.toml"


def _at(sol, m, T):
    """(x, y) of body m's centre G in T (positions, or accelerations) by the test."""
    if m.block:
        return T[m.body]
    lk = sol.scene.link(m.body)
    (px, py), (qx, qy) = T[lk.p], T[lk.q]
    dx, dy = qx - px, qy - py
    return (px + m.lam * dx - m.mu * dy, py + m.lam * dy + m.mu * dx)


def _newton(sol):
    """The shaking force and moment (about the origin) from the applied and inertia forces
    of every moving body: Newton's laws for them all, the frame's share what is left."""
    sc = sol.scene
    g = sc.gravity
    fx = fy = mz = 0.0

    def put(F, at, couple=0.0):
        nonlocal fx, fy, mz
        fx += F[0]
        fy += F[1]
        mz += at[0] * F[1] - at[1] * F[0] + couple

    for m in sc.masses:
        G, a = _at(sol, m, sol.P), _at(sol, m, sol.A)
        put((-m.mass * a[0], -m.mass * a[1]), G)
        if not m.block:
            put((0.0, 0.0), G, -m.inertia * sol.Al[sc.link(m.body).key])
        if g is not None:
            put((m.mass * g.g * g.direction[0], m.mass * g.g * g.direction[1]), G)
    for ld in sc.loads:
        if ld.torque is not None:
            put((0.0, 0.0), (0.0, 0.0), ld.torque)
        elif ld.gas is None:
            put(ld.force, sol.P[ld.target])
    return math.hypot(fx, fy), mz


def test_inertia_keys_are_dalemberts_force_couple_and_offset():
    sol = solve(load_scene(FOURBAR))
    for m in sol.scene.masses:
        a = _at(sol, m, sol.A)
        F = m.mass * math.hypot(*a)
        C = -m.inertia * sol.Al[m.body]
        assert sol.value("Fi", (m.body,)) == pytest.approx(F, rel=1e-12)
        assert sol.value("Ci", (m.body,)) == pytest.approx(C, rel=1e-12, abs=1e-15)
        assert sol.value("h", (m.body,)) == pytest.approx(abs(C) / F, rel=1e-12)


def test_shaking_force_and_moment_by_newton_for_all_bodies():
    for path in (FOURBAR,):
        sol = solve(load_scene(path))
        F, M = _newton(sol)
        assert engine_value(sol, "shaking_force") == pytest.approx(F, rel=1e-9)
        assert engine_value(sol, "shaking_moment") == pytest.approx(M, rel=1e-9, abs=1e-9 * F)


def test_engine_thrusts_from_the_rods_obliquity():
    sol = solve(load_scene(ENGINE))
    piston = next(m.body for m in sol.scene.masses if m.block)
    rod = next(lk for lk in sol.scene.links if piston in lk.points)
    crank_pin = rod.other(piston)
    (bx, by), (ax, ay) = sol.P[piston], sol.P[crank_pin]
    path = next(s for s in sol.scene.sliders if s.point == piston)
    ux, uy = path.u
    L = math.hypot(ax - bx, ay - by)
    cos_phi = abs((ax - bx) * ux + (ay - by) * uy) / L
    F_P = engine_value(sol, "piston_effort")
    assert F_P > 0
    assert engine_value(sol, "rod_thrust") == pytest.approx(F_P / cos_phi, rel=1e-9)
    assert engine_value(sol, "side_thrust") == pytest.approx(
        F_P * math.sqrt(1 - cos_phi**2) / cos_phi, rel=1e-9
    )


def _checked(path, answers):
    text = (
        path.read_text().split("[answers]")[0]
        + "[answers]\n"
        + "".join(f'{k} = "{v}"\n' for k, v in answers.items())
    )
    sol = solve(parse_scene(text, str(path)))
    return {v.key: v for v in check_answers(sol)}


def test_check_marks_the_true_values_right_and_a_slip_wrong():
    sol = solve(load_scene(FOURBAR))
    F, M = _newton(sol)
    u = sol.scene.length_unit
    right = {
        "Fi_A-B": f"{sol.value('Fi', ('A-B',)):.6g} N",
        "Ci_A-B": f"{sol.value('Ci', ('A-B',)):.6g} N m",
        "h_A-B": f"{sol.value('h', ('A-B',)) / u:.6g}",  # in the scene's mm
        "shaking_force": f"{F:.6g} N",
        "shaking_moment": f"{abs(M):.6g} N m",
    }
    got = _checked(FOURBAR, right)
    assert all(v.ok for v in got.values()), [v for v in got.values() if not v.ok]
    wrong = dict(right, **{"Fi_A-B": f"{1.2 * sol.value('Fi', ('A-B',)):.6g} N"})
    assert not _checked(FOURBAR, wrong)["Fi_A-B"].ok
    # the piston's inertia force by the block's name, the thrusts of the engine
    es = solve(load_scene(ENGINE))
    piston = next(m.body for m in es.scene.masses if m.block)
    m = next(m for m in es.scene.masses if m.block)
    fi = m.mass * math.hypot(*es.A[piston])
    got = _checked(
        ENGINE,
        {
            f"Fi_{piston}": f"{fi:.6g} N",
            "rod_thrust": f"{engine_value(es, 'rod_thrust'):.6g} N",
            "side_thrust": f"{engine_value(es, 'side_thrust'):.6g} N",
        },
    )
    assert all(v.ok for v in got.values()), got


def test_keys_that_name_nothing_are_refused_in_one_line():
    text = FOURBAR.read_text().split("[answers]")[0]
    with pytest.raises(SceneError, match="Fi_X names a link"):
        parse_scene(text + '[answers]\nFi_QZ = "3 N"\n', "s.toml")
    plain = (ROOT / "worked_problems" / "fourbar_image_points.toml").read_text()
    with pytest.raises(SceneError, match="needs the force analysis"):
        parse_scene(plain.split("[answers]")[0] + '[answers]\nFi_BC = "3 N"\n', "s.toml")
    massless = solve(load_scene(FOURBAR))
    sc = replace(massless.scene, masses=massless.scene.masses[:1])
    with pytest.raises(SceneError, match="no mass"):
        solve(sc).value("Fi", ("A-B",))
