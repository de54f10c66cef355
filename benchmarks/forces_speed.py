"""Speed of the force analysis, side by side with the kinematic solve it rests on.

    python benchmarks/forces_speed.py            # a few seconds
    python benchmarks/forces_speed.py --quick    # fewer rounds
    python benchmarks/forces_speed.py --json     # the numbers as JSON too
    python benchmarks/forces_speed.py --smoke    # one round, 360 angles (the test's run)

Measured interleaved, in small batches, each figure the least over the rounds (on a shared
machine the others' load comes and goes; a figure measured a minute after its peer is
compared with another machine), on the worked problems with forces
(``worked_problems/fourbar_forces.toml``, ``engine_forces.toml``, ``shaper_forces.toml``):

* ``kinematic``: the warm solve of the scene (``solve(scene)``, its plan cached);
* ``forces``: the warm force solve of that solution (``analyse(sol)``: the driver's torque
  with inertia, the shaking force and moment, every pin force and guide force as numbers);
* ``forces, records``: the same with its pin-force records read (``analyse(sol).pins``);
* ``forces, words``: the same with the step records read (``.steps``: the long road that
  writes each group's working in words, which only ``steps``, ``solve`` and the drawings ask
  for);
* ``floor`` (the four-bar): plain Python float code for the same four-bar's forces from
  the same kinematic numbers (:func:`floor_fourbar_forces`, straight-line arithmetic, no
  call), giving the same numbers (checked to 1e-12);

and over 3600 crank angles of each: the sweep with its forces in vectorised calls
(``sweep`` then ``analyse`` on the arrays; the forces alone) against a Python loop of the
one-instant solve and force solve at each angle (checked equal at every angle to 1e-12).

A benchmark, not a test: nothing here fails on time.
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))  # this tree's package, not an installed one
PROBLEMS = ROOT / "worked_problems"
NAMES = ("fourbar_forces", "engine_forces", "shaper_forces")


def solve_at(scene, theta):
    """The one-instant solve of ``scene`` at the crank angle ``theta`` (rad) on its
    plan's branch: what ``solve`` does at the scene's own angle."""
    from polygon_method.motion.solution import Solution
    from polygon_method.solver.compiler import compile_plan
    from polygon_method.steps.base import Instant

    plan = compile_plan(scene)
    inp = scene.input
    sol = object.__new__(Solution)
    ctx = object.__new__(Instant)
    ctx.theta, ctx.omega, ctx.alpha, ctx.cond = theta, inp.omega, inp.alpha, {}
    plan.instant(ctx, sol)
    sol.scene, sol.plan, sol.theta, sol.bad, sol._cache = scene, plan, theta, None, {}
    return sol


def floor_fourbar_forces(scene):
    """The floor: ``worked_problems/fourbar_forces.toml``'s forces in plain Python float
    code, from the kinematic numbers (a flat tuple: :func:`floor_input`) to the pin forces
    at O2, A, B, O4 (on the crank, the coupler, the coupler, the rocker), the driver's
    torque and the shaking force and moment: the masses' centres from their links' ends,
    D'Alembert's forces and couples, the weights, the load and the couple, the dyad's 2x2
    moments, the crank's moments. Returns the function."""
    ms = {m.body: m for m in scene.masses}
    crank, coupler, rocker = ms["O2-A"], ms["A-B"], ms["B-O4"]
    g = scene.gravity
    gx, gy = g.g * g.direction[0], g.g * g.direction[1]
    load = next(ld for ld in scene.loads if ld.force is not None)
    cpl = next(ld for ld in scene.loads if ld.force is None).torque
    lx, ly = load.force
    lam2, mu2, m2, i2 = crank.lam, crank.mu, crank.mass, crank.inertia
    lam3, mu3, m3, i3 = coupler.lam, coupler.mu, coupler.mass, coupler.inertia
    lam4, mu4, m4, i4 = rocker.lam, rocker.mu, rocker.mass, rocker.inertia
    (ox, oy), (qx, qy) = scene.ground["O2"], scene.ground["O4"]

    def floor(k):
        ax, ay, bx, by, ex, ey, aax, aay, abx, aby, al2, al3, al4 = k
        # centres and their accelerations: p + lam (q - p) + mu perp(q - p)
        dx, dy = ax - ox, ay - oy
        g2x, g2y = ox + lam2 * dx - mu2 * dy, oy + lam2 * dy + mu2 * dx
        a2x, a2y = lam2 * aax - mu2 * aay, lam2 * aay + mu2 * aax
        dx, dy = bx - ax, by - ay
        g3x, g3y = ax + lam3 * dx - mu3 * dy, ay + lam3 * dy + mu3 * dx
        dx, dy = abx - aax, aby - aay
        a3x, a3y = aax + lam3 * dx - mu3 * dy, aay + lam3 * dy + mu3 * dx
        dx, dy = qx - bx, qy - by
        g4x, g4y = bx + lam4 * dx - mu4 * dy, by + lam4 * dy + mu4 * dx
        a4x, a4y = abx - lam4 * abx + mu4 * aby, aby - lam4 * aby - mu4 * abx
        # each link's known resultant (Fx, Fy, M about the origin)
        f2x, f2y = m2 * (gx - a2x), m2 * (gy - a2y)
        M2 = g2x * f2y - g2y * f2x - i2 * al2
        f3x, f3y = m3 * (gx - a3x), m3 * (gy - a3y)
        M3 = g3x * f3y - g3y * f3x - i3 * al3 + ex * ly - ey * lx
        f3x += lx
        f3y += ly
        f4x, f4y = m4 * (gx - a4x), m4 * (gy - a4y)
        M4 = g4x * f4y - g4y * f4x - i4 * al4 + cpl
        # the dyad: P on the coupler at B by the rocker
        m1b = M3 - (ax * f3y - ay * f3x)
        m2d = M4 - (qx * f4y - qy * f4x)
        r1x, r1y, r2x, r2y = bx - ax, by - ay, bx - qx, by - qy
        det = r1x * r2y - r1y * r2x
        px = (-m1b * r2x - r1x * m2d) / det
        py = (-r1y * m2d - m1b * r2y) / det
        fax, fay = -(f3x + px), -(f3y + py)  # on the coupler at A by the crank
        fdx, fdy = -(f4x - px), -(f4y - py)  # on the rocker at O4 by the frame
        # the crank: its known forces and the coupler's push at A
        kx, ky = f2x - fax, f2y - fay
        km = M2 - (ax * fay - ay * fax)
        torque = -(km - (ox * ky - oy * kx))
        shx, shy = kx - fdx, ky - fdy  # the frame's share, felt back
        shm = (ox * ky - oy * kx) + (qx * -fdy - qy * -fdx) - torque
        return ((-kx, -ky), (fax, fay), (px, py), (fdx, fdy), torque, (shx, shy), shm)

    return floor


def floor_input(sol) -> tuple:
    """The floor's input: the kinematic numbers it reads, as plain floats."""
    P, A, Al = sol.P, sol.A, sol.Al
    return (*P["A"], *P["B"], *P["E"], *A["A"], *A["B"], Al["O2-A"], Al["A-B"], Al["B-O4"])


def _floor_agrees(sol, f, out):
    """The floor gives the force solve's numbers, to 1e-12 of the largest force."""
    size = max(math.hypot(*p.force) for p in f.pins)
    theirs = (f.pin("O2", "O2-A"), f.pin("A", "A-B"), f.pin("B", "A-B"), f.pin("O4", "B-O4"))
    for mine, want in zip(out[:4], theirs):
        assert math.dist(mine, want) <= 1e-12 * size, (mine, want)
    assert abs(out[4] - f.input_torque) <= 1e-12 * size * 0.35
    assert math.dist(out[5], f.shaking_force) <= 1e-12 * size
    assert abs(out[6] - f.shaking_moment) <= 1e-12 * size * 0.35


def side_by_side(rounds):
    """name -> {figure: least seconds per call over ``rounds`` interleaved rounds}."""
    from polygon_method import load_scene, solve
    from polygon_method.forces import analyse

    out = {}
    for name in NAMES:
        scene = load_scene(PROBLEMS / f"{name}.toml")
        sol = solve(scene)
        f = analyse(sol)
        batches = {
            "kinematic": (lambda: solve(scene), 200),
            "forces": (lambda: analyse(sol), 200),
            "forces, records": (lambda: analyse(sol).pins, 200),
            "forces, words": (lambda: analyse(sol).steps, 20),
        }
        if name == "fourbar_forces":
            floor, k = floor_fourbar_forces(scene), floor_input(sol)
            _floor_agrees(sol, f, floor(k))
            batches["floor"] = (lambda: floor(k), 200)
        out[name] = _interleaved(batches, rounds)
    return out


def _interleaved(batches, rounds):
    best = dict.fromkeys(batches, float("inf"))
    clock = time.perf_counter
    for _ in range(rounds):
        for key, (fn, n) in batches.items():
            t = clock()
            for _ in range(n):
                fn()
            best[key] = min(best[key], (clock() - t) / n)
    return best


def _columns(f):
    """The forces a sweep's CSV gives, by name: the effort, the shaking force and moment,
    each guide's normal force, each pin force's components."""
    out = {
        "effort": f.input_torque,
        "shake_x": f.shaking_force[0],
        "shake_y": f.shaking_force[1],
        "shake_m": f.shaking_moment,
    }
    out.update({f"N_{g.key}": g.normal for g in f.guides})
    for p in f.pins:
        out[f"F_{p.point}_{p.on}_{p.by}_x"] = p.force[0]
        out[f"F_{p.point}_{p.on}_{p.by}_y"] = p.force[1]
    return out


def sweeps(rounds, n=3600):
    """name -> {figure: least seconds over ``rounds``} for ``n`` crank angles: the sweep
    with its forces vectorised, its forces alone, and a loop of one-instant solves and
    force solves (and the force solves alone); checked equal at every angle to 1e-12 of the
    largest force there."""
    from polygon_method import load_scene
    from polygon_method.forces import analyse
    from polygon_method.motion.sweeps import sweep

    out = {}
    th = np.radians(np.arange(n) * (360.0 / n))
    for name in NAMES:
        scene = load_scene(PROBLEMS / f"{name}.toml")
        res = sweep(scene, th)
        assert len(res) == n, name
        cols = _columns(analyse(res))
        sols = [solve_at(scene, t) for t in th]
        for i in range(0, n, 7):  # the vectorised forces are the one-instant ones
            one = _columns(analyse(sols[i]))
            size = max(abs(v) for v in one.values())
            for key, v in one.items():
                assert abs(np.broadcast_to(cols[key], (n,))[i] - v) <= 1e-12 * size, (name, key)
        batches = {
            "sweep + forces": (lambda: analyse(sweep(scene, th)).pins, 1),
            "sweep": (lambda: sweep(scene, th), 1),
            "forces of a sweep": (lambda: analyse(res).pins, 1),
            "loop: solve + forces": (lambda: [analyse(solve_at(scene, t)).pins for t in th], 1),
            "loop: forces": (lambda: [analyse(s).pins for s in sols], 1),
        }
        out[name] = _interleaved(batches, rounds)
    return out


def fmt(t):
    return f"{t * 1e6:9.2f} us" if t < 1e-3 else f"{t * 1e3:9.3f} ms"


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="fewer rounds")
    ap.add_argument("--json", action="store_true", help="print the numbers as JSON too")
    ap.add_argument(
        "--smoke",
        action="store_true",
        help="one round and 360 angles: that it runs and its checks hold",
    )
    args = ap.parse_args(argv)
    rounds = 1 if args.smoke else 3 if args.quick else 15
    n = 360 if args.smoke else 3600
    one = side_by_side(rounds)
    many = sweeps(max(1, rounds // 3), n)
    print("one instant, warm (least of interleaved batches):")
    for name, r in one.items():
        k = r["kinematic"]
        print(f"  {name}")
        for key, t in r.items():
            tail = "" if key == "kinematic" else f"   {t / k:5.2f} of the kinematic solve"
            if key == "forces" and "floor" in r:
                tail += f", {t / r['floor']:4.2f} of the floor"
            print(f"    {key:<18}{fmt(t)}{tail}")
    print(f"{n} crank angles:")
    for name, r in many.items():
        print(f"  {name}")
        for key, t in r.items():
            print(f"    {key:<22}{fmt(t)}")
        print(
            f"    the forces vectorised are {r['loop: forces'] / r['forces of a sweep']:.0f} "
            f"times as fast as the loop; the sweep with forces "
            f"{r['sweep + forces'] / r['sweep']:.2f} of the sweep alone"
        )
    if args.json:
        print(json.dumps({"one": one, "sweep": many, "angles": n}, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
