"""The PyPI packages ``mechanism`` and ``pylinkage`` on the same four-bars, when installed.

Both are optional (``pip install polygon-method[peers]``); each function raises
``ImportError`` when its package is absent, so that the benchmark skips it. Each returns a
:class:`polygon_method.methods.Kinematics` of the crank tip and the coupler-rocker joint
(positions, velocities, accelerations) and the coupler's and rocker's omega, alpha.

* ``mechanism`` writes the loop ``a(theta2) + b(theta3) - c(theta4) - d = 0`` and solves
  it, and its first and second time derivatives, with scipy's ``fsolve`` from a guess.
* ``pylinkage`` intersects circles (RRR dyad), keeping the intersection nearest the
  previous position, and computes velocities and accelerations from the positions.
"""

from __future__ import annotations

import math
import warnings

from methods import Kinematics, is_fourbar


def _frame(scene):
    fb = is_fourbar(scene)
    if fb is None:
        raise ValueError("not a four-bar")
    cr, dy = fb
    tip = cr.tip
    pivot2 = dy.d if dy.b == tip else dy.b
    o2, o4 = scene.ground[cr.pivot], scene.ground[pivot2]
    b = dy.l1 if dy.b == tip else dy.l2
    c = dy.l2 if dy.b == tip else dy.l1
    coupler = dy.link1 if dy.b == tip else dy.link2
    rocker = dy.link2 if dy.b == tip else dy.link1
    gx, gy = o4[0] - o2[0], o4[1] - o2[1]
    return dict(
        cr=cr,
        dy=dy,
        o2=o2,
        o4=o4,
        a=cr.length,
        b=b,
        c=c,
        d=math.hypot(gx, gy),
        phi0=math.atan2(gy, gx),
        coupler=coupler,
        rocker=rocker,
        pivot2=pivot2,
    )


def _assemble(scene, f, th3, th4, w3, w4, al3, al4, method, info):
    """Global Kinematics from the lecture-frame angles and rates."""
    inp = scene.input
    p0 = f["phi0"]
    th2 = inp.angle
    o2, o4 = f["o2"], f["o4"]
    ra = (f["a"] * math.cos(th2), f["a"] * math.sin(th2))
    t4 = th4 + p0
    rc = (f["c"] * math.cos(t4), f["c"] * math.sin(t4))
    A = (o2[0] + ra[0], o2[1] + ra[1])
    B = (o4[0] + rc[0], o4[1] + rc[1])

    def vel(w, r):
        return (-w * r[1], w * r[0])

    def acc(w, al, r):
        return (-w * w * r[0] - al * r[1], -w * w * r[1] + al * r[0])

    w2, al2 = inp.omega, inp.alpha
    P = {f["cr"].pivot: o2, f["pivot2"]: o4, f["cr"].tip: A, f["dy"].point: B}
    V = {f["cr"].tip: vel(w2, ra), f["dy"].point: vel(w4, rc)}
    Acc = {f["cr"].tip: acc(w2, al2, ra), f["dy"].point: acc(w4, al4, rc)}
    W = {f["cr"].link: w2, f["coupler"]: w3, f["rocker"]: w4}
    Al = {f["cr"].link: al2, f["coupler"]: al3, f["rocker"]: al4}
    return Kinematics(method, P, V, Acc, W, Al, {}, info)


def mechanism_fourbar(scene, guess):
    """PyPI ``mechanism``: fsolve on the vector loop. ``guess``: a Kinematics near the
    answer (its link angles start fsolve; velocities and accelerations start at zero)."""
    import numpy as np
    from mechanism import Mechanism, Vector, get_joints

    f = _frame(scene)
    inp = scene.input
    p0 = f["phi0"]
    gp = guess.P
    tip, pt = f["cr"].tip, f["dy"].point
    th3g = math.atan2(gp[pt][1] - gp[tip][1], gp[pt][0] - gp[tip][0]) - p0
    th4g = math.atan2(gp[pt][1] - f["o4"][1], gp[pt][0] - f["o4"][0]) - p0
    O2, A, B, O4 = get_joints("O2 A B O4")
    a = Vector((O2, A), r=f["a"])
    b = Vector((A, B), r=f["b"])
    c = Vector((O4, B), r=f["c"])
    d = Vector((O2, O4), r=f["d"], theta=0, style="ground")

    def loops(x, i):
        temp = np.zeros((1, 2))
        temp[0] = a(i) + b(x[0]) - c(x[1]) - d()
        return temp.flatten()

    m = Mechanism(
        vectors=(a, b, c, d),
        origin=O2,
        loops=loops,
        pos=inp.angle - p0,
        vel=inp.omega,
        acc=inp.alpha,
        guess=(np.array([th3g, th4g]), np.zeros(2), np.zeros(2)),
    )
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        m.calculate()
    th3, th4 = float(b.pos.theta), float(c.pos.theta)
    w3, w4 = float(b.vel.omega), float(c.vel.omega)
    al3, al4 = float(b.acc.alpha), float(c.acc.alpha)
    t2 = inp.angle - p0  # does the loop close? (the library does not say)
    res = math.hypot(
        f["a"] * math.cos(t2) + f["b"] * math.cos(th3) - f["c"] * math.cos(th4) - f["d"],
        f["a"] * math.sin(t2) + f["b"] * math.sin(th3) - f["c"] * math.sin(th4),
    )
    return _assemble(
        scene,
        f,
        th3,
        th4,
        w3,
        w4,
        al3,
        al4,
        "mechanism (PyPI)",
        {"loop residual": res, "warnings": [str(w.message) for w in caught]},
    )


def pylinkage_fourbar(scene, guess):
    """PyPI ``pylinkage``: an RRR dyad, the intersection nearest ``guess``'s position."""
    from pylinkage.actuators import Crank
    from pylinkage.components import Ground
    from pylinkage.dyads import RRRDyad
    from pylinkage.simulation import Linkage

    f = _frame(scene)
    inp = scene.input
    p0 = f["phi0"]
    cp, sp = math.cos(p0), math.sin(p0)
    gb = guess.P[f["dy"].point]
    rx, ry = gb[0] - f["o2"][0], gb[1] - f["o2"][1]
    hint = (cp * rx + sp * ry, -sp * rx + cp * ry)  # into the frame O2 = 0, O4 on +x
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        g1, g2 = Ground(0.0, 0.0, name="O2"), Ground(f["d"], 0.0, name="O4")
        crank = Crank(anchor=g1, radius=f["a"], angular_velocity=0.0, initial_angle=inp.angle - p0)
        dyad = RRRDyad(
            anchor1=crank.output,
            anchor2=g2,
            distance1=f["b"],
            distance2=f["c"],
            x=hint[0],
            y=hint[1],
        )
        lk = Linkage([g1, g2, crank, dyad], name="four-bar")
        lk.set_input_velocity(crank, omega=inp.omega, alpha=inp.alpha)
        pos, vel, acc = next(iter(lk.step_with_derivatives(iterations=1, dt=0)))
    if None in (pos[3], vel[3], acc[3]) or None in pos[3]:
        raise ArithmeticError("pylinkage gives no position, velocity or acceleration here")
    ax, ay = pos[2]
    bx, by = pos[3]
    (vax, vay), (vbx, vby) = vel[2], vel[3]
    (aax, aay), (abx, aby) = acc[2], acc[3]
    r3 = (bx - ax, by - ay)
    r4 = (bx - f["d"], by)
    v3 = (vbx - vax, vby - vay)
    a3 = (abx - aax, aby - aay)

    def rate(r, v):
        return (r[0] * v[1] - r[1] * v[0]) / (r[0] ** 2 + r[1] ** 2)

    th3, th4 = math.atan2(r3[1], r3[0]), math.atan2(r4[1], r4[0])
    return _assemble(
        scene,
        f,
        th3,
        th4,
        rate(r3, v3),
        rate(r4, (vbx, vby)),
        rate(r3, a3),
        rate(r4, (abx, aby)),
        "pylinkage (PyPI)",
        {},
    )


PEERS = {"mechanism (PyPI)": mechanism_fourbar, "pylinkage (PyPI)": pylinkage_fourbar}
