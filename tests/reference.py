"""An independent high-precision reference for the solver (mpmath, 50 significant digits).

It shares no kinematics with ``polygon_method``: only the scene loader's data are used.
The mechanism is written as a square system of holonomic constraints ``f(q, t) = 0`` in
the coordinates ``q`` (x, y of every non-ground point):

* a link PQ (not the crank, not both ends on ground):  ``|P - Q|^2 - L^2 = 0``
* the crank tip T about pivot O:  ``T - O - r (cos th, sin th) = 0``,
  ``th(t) = th0 + omega t + alpha t^2 / 2``
* a carried point X on link PQ:  ``X - (P + lam (Q - P) + mu perp(Q - P)) = 0``, lam and mu
  from the numbers the scene gives it (its triangle solved here, not the loader's)
* a slider X on a fixed path:  ``cross(X - through, u) = 0``, u from the path's angle as
  read
* a block X sliding along moving link G1 G2:  ``cross(X - G1, G2 - G1) = 0``
* a wheel CX of radius r rolling without slip ([rolling]): ``X - C - l (cos phi, sin phi) = 0``
  with, on a fixed line (T a point of it, m its normal towards the wheel, t = perp(m)),
  ``phi = phi0 + ((C - T).t - s0) / r`` and the centre ``(C - T).m - r = 0``; on a circle
  or a gear (centred at O, fixed or moving), ``phi = phi0 + kd (psi - psi0) + kb (beta -
  beta0)``: no slip at the pitch point relative to the line of centres, psi the direction
  O -> C and beta the gear's (its centre to its link's other point), both read from the
  points, ``kd = 1 + e R/r``, ``kb = -e R/r`` (e = +1 outside, -1 inside; R from the centre
  distance: |d| + e r, or r - |d| where the wheel is a ring about the gear, e = -1: no slip
  at I = O - R d/|d| relative to the line of centres gives the same kd, kb). Evaluated at the scene's own angle, where phi = phi0 (s0 is C's place there);
  it has no explicit time, and its gamma is its second derivative along q' (mpmath.diff).
* a rack R on a fixed path (T, u) meshing with a pinion about O:  ``(R - T).u - k K (th - th0)
  = 0`` with k = -(T - O).perp(u) (the pinion's point at the pitch point moves as the rack)
  and K the pinion's turns per turn of the crank (with the path's equation above); a
  pinion that is no wheel of [rolling] and not the crank (keyed to a rocker: it turns as
  a linkage makes it) ``(R - T).u - k (beta - beta0) = 0``, beta its direction O -> Q
  (Q its link's other point) read from the points, beta0 at the scene's own angle (no
  explicit time; its gamma the second derivative along q', mpmath.diff).
* a driving block X on its fixed path (T, u) ([input] block): ``(X - T).u - s = 0`` (with the
  path's equation above), ``s(t) = s0 + vs t + as t^2 / 2``: the "crank angle" th is s,
  ``f_t = -vs``, ``gamma = -as``
* a driving wheel CX rolling on a fixed line ([input] wheel): its centre C is the driving
  block above, its place s along the [rolling] line (T its through point, u its direction:
  ``(C - T).u - s = 0``), on the line at the radius by the wheel's own equation
* a collar X driven along its rod K-N of length L, K on the ground ([input] block, X sliding
  along a moving link): ``(X - K).(N - K) - L s = 0`` (with the guide's equation and the
  rod's length), ``s(t) = s0 + vs t + as t^2 / 2``: ``f_t = -L vs``, ``gamma = 2 (vX -
  vK).(vN - vK) - L as``
* a collar X sliding along the crank K-N as the second input ([input.second] block): the
  same, with its own s(t), vs, as
* a pin X in the slot of a translating yoke Y (a block on a fixed path), the slot along
  the fixed unit d:  ``cross(X - Y, d) = 0`` (linear: ``gamma = 0``)
* a peg in two slots: one of the two above for each slot (two equations for its point);
  its sliding quantities are keyed by slot (``P_OA``, ``P_ground``)

Positions: Newton-Raphson from the solver's float positions.  Every constraint is at most
quadratic in ``q``, so along a motion ``f'' = J q'' + gamma`` with a closed-form ``gamma``:

* link:      ``gamma = 2 |vP - vQ|^2``
* crank:     ``gamma = -(alpha perp(r) - omega^2 r)``, ``r = T - O``; ``f_t = -omega perp(r)``
* carried, fixed path:  ``gamma = 0`` (linear in q)
* guide:     ``gamma = 2 cross(vX - vG1, vG2 - vG1)``

so ``J q' = -f_t`` and ``J q'' = -gamma``.

Angular velocity of a link from its two ends (``r = Q - P``, rigid: ``v_rel = omega perp(r)``,
``a_rel = alpha perp(r) - omega^2 r``; ``cross(r, perp(r)) = |r|^2``, ``cross(r, r) = 0``):
``omega = cross(r, v_rel) / |r|^2``, ``alpha = cross(r, a_rel) / |r|^2``.

A block X on moving guide G1 -> G2 (``u`` unit G1 -> G2, ``X = G1 + s u``, ``u' = omega perp(u)``):
``vX = vG1 + omega perp(X - G1) + s' u`` and
``aX = aG1 - omega^2 (X - G1) + alpha perp(X - G1) + 2 omega s' perp(u) + s'' u``.
"""

from __future__ import annotations

import mpmath
from mpmath import mp, mpf

mp.dps = 50

__all__ = [
    "reference_solution",
    "reference_positions",
    "constraint_residuals",
    "constraint_jacobian",
    "reference_slider_crank",
    "reference_fourbar_algebraic",
    "theta_at",
]

NEWTON_TOL = mpf("1e-40")
ZERO2 = (mpf(0), mpf(0))


def _v(xy):
    return (mpf(xy[0]), mpf(xy[1]))


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def _dot(a, b):
    return a[0] * b[0] + a[1] * b[1]


def _cross(a, b):
    return a[0] * b[1] - a[1] * b[0]


def _perp(a):
    return (-a[1], a[0])


def _unit(a):
    n = mpmath.sqrt(_dot(a, a))
    return (a[0] / n, a[1] / n)


def theta_at(scene, t):
    """Crank angle at time t (t = 0: the scene's angle)."""
    inp = scene.input
    t = mpf(t)
    return mpf(inp.angle) + mpf(inp.omega) * t + mpf(inp.alpha) * t * t / 2


# --------------------------------------------------------------------------- constraints
#
# Each equation is (kind, data).  _eval gives its value and its gradient as a list of
# (point, d/dx, d/dy) terms (ground points are dropped later).


def _equations(scene):
    ground = scene.ground
    inp = scene.input
    eqs = []
    wheels = {pr.wheel for pr in getattr(scene, "rolling", ())}  # their rim equations below
    for lk in scene.links:
        if lk.key == inp.crank or (lk.p in ground and lk.q in ground) or lk.key in wheels:
            continue
        two = getattr(inp, "second", None)
        if two is not None and two.crank is not None and lk.key == scene.link(two.crank).key:
            continue
        eqs.append(("link", (lk.p, lk.q, mpf(lk.length))))
    wheel = getattr(inp, "wheel", None)
    if wheel is not None:  # a driving wheel: its centre's place along its ground line (T,
        pr = next(p for p in scene.rolling if p.wheel == wheel)  # u: the [rolling] line's)
        eqs.append(("block", (inp.block, _v(pr.through), _unit(_v(pr.u)))))
    elif getattr(inp, "block", None) is not None and hasattr(scene.slider(inp.block), "guide"):
        sl = scene.slider(inp.block)  # a collar driven along its rod K-N (K on the ground)
        rod = scene.link(sl.guide)
        k = rod.p if rod.p in ground else rod.q
        eqs.append(("collar", (inp.block, k, rod.other(k), mpf(rod.length))))
    elif getattr(inp, "block", None) is not None:  # a block driven along its fixed path
        sl = scene.slider(inp.block)
        eqs.append(("block", (inp.block, _v(sl.through), _unit(_v(sl.u)))))
    else:
        crank = scene.link(inp.crank)
        eqs.append(("crank", (inp.pivot, inp.tip, mpf(crank.length), 0)))
        eqs.append(("crank", (inp.pivot, inp.tip, mpf(crank.length), 1)))
    two = getattr(inp, "second", None)
    if two is not None and two.block is not None:  # a collar sliding along the crank K-N
        rod = scene.link(scene.slider(two.block).guide)
        k = rod.p if rod.p in ground else rod.q
        eqs.append(
            (
                "collar2",
                (
                    two.block,
                    k,
                    rod.other(k),
                    mpf(rod.length),
                    mpf(two.angle),
                    mpf(two.omega),
                    mpf(two.alpha),
                ),
            )
        )
    elif two is not None:  # a second driven crank, at its own angle, speed and acceleration
        r2 = mpf(scene.link(two.crank).length)
        for c in (0, 1):
            eqs.append(
                (
                    "crank2",
                    (two.pivot, two.tip, r2, c, mpf(two.angle), mpf(two.omega), mpf(two.alpha)),
                )
            )
    exact = _carried_coefficients(scene)
    for cp in scene.points:
        lk = scene.link(cp.link)
        lam, mu = exact[cp.name]
        for comp in (0, 1):
            eqs.append(("carried", (cp.name, lk.p, lk.q, lam, mu, comp)))
    for sl in scene.sliders:
        if getattr(sl, "wheel", ""):  # a driving wheel's centre: on its line by "wheelline"
            continue
        if hasattr(sl, "guide"):  # (an offset slot: its line e to the left of first -> second)
            eqs.append(("guide", (sl.point, sl.first, sl.second, mpf(getattr(sl, "offset", 0)))))
        elif hasattr(sl, "yoke"):  # the slot of a translating yoke: a line of fixed direction
            e = mpf(getattr(sl, "offset", 0))  # (its line e to the left of Y's along d)
            eqs.append(("yoke", (sl.point, sl.yoke, _unit(_v(sl.direction)), e)))
        else:
            eqs.append(("path", (sl.point, _v(sl.through), _path_unit(sl))))
    rates = {inp.crank: mpf(1)}
    for pr in getattr(scene, "rolling", ()):
        if pr.on == "rack":
            sl = scene.slider(pr.rim)
            T, u = _v(sl.through), _unit(_v(sl.u))
            O = _v(scene.ground[pr.base_centre])
            k = -_dot(_sub(T, O), _perp(u))
            if pr.base != scene.link(inp.crank).key and pr.base not in wheels:
                bl = scene.link(pr.base)
                eqs.append(
                    ("rackfree", (pr.rim, T, u, k, pr.base_centre, bl.other(pr.base_centre)))
                )
                continue
            eqs.append(("rack", (pr.rim, T, u, k, pr.base, rates, mpf(inp.angle))))
            continue
        ell = mpf(scene.link(pr.wheel).length)
        r = mpf(pr.radius)
        if pr.on == "line":
            T, m = _v(pr.through), _v(pr.m)
            eqs.append(("wheelline", (pr.centre, T, m, r)))
            for c in (0, 1):
                eqs.append(("rim", (pr.rim, pr.centre, ell, pr.angle, ("line", T, m, r), c)))
            continue
        e = -1 if pr.inside else 1
        base = None
        if pr.base is not None:  # the gear's centre, then its other point: its angle
            bl = scene.link(pr.base)
            base = (pr.base_centre, bl.q if bl.p == pr.base_centre else bl.p)
        for c in (0, 1):
            eqs.append(
                (
                    "rim",
                    (
                        pr.rim,
                        pr.centre,
                        ell,
                        pr.angle,
                        ("circle", pr.base_centre, e, r, pr, base),
                        c,
                    ),
                )
            )
    return eqs


def _path_unit(sl):
    """A fixed path's direction: from its angle as the scene gives it (not the loader's
    unit vector), else its unit vector."""
    ang = getattr(sl, "angle", None)
    if ang is None:
        return _unit(_v(sl.u))
    return (mpmath.cos(mpf(ang)), mpmath.sin(mpf(ang)))


def _carried_coefficients(scene):
    """name -> (lam, mu) of each carried point, from the numbers the scene gives it
    (``source``: along a link, or by its distances from two points of the link, the
    triangle solved here at full precision; a nearly flat one is flattened only where
    it does not close), else the loader's lam and mu."""
    out, frames = {}, {}
    for cp in scene.points:
        lk = scene.link(cp.link)
        L = mpf(lk.length)
        frame = frames.setdefault(lk.key, {lk.p: (mpf(0), mpf(0)), lk.q: (L, mpf(0))})
        src = getattr(cp, "source", ())
        if not src:
            xy = (mpf(cp.lam) * L, mpf(cp.mu) * L)
        elif src[0] == "along":
            _, start, d = src
            (sx, sy), (ox, oy) = frame[start], frame[lk.other(start)]
            t = mpf(d) / L
            xy = (sx + t * (ox - sx), sy + t * (oy - sy))
        else:
            _, r1, d1, r2, d2, turn = src
            d1, d2 = mpf(d1), mpf(d2)
            (x1, y1), (x2, y2) = frame[r1], frame[r2]
            e = mpmath.sqrt((x2 - x1) ** 2 + (y2 - y1) ** 2)
            along = (d1 * d1 - d2 * d2 + e * e) / (2 * e)
            h = mpmath.sqrt(max(d1 * d1 - along * along, mpf(0)))
            ex, ey = (x2 - x1) / e, (y2 - y1) / e
            xy = (x1 + along * ex - turn * h * ey, y1 + along * ey + turn * h * ex)
        frame[cp.name] = xy
        out[cp.name] = (xy[0] / L, xy[1] / L)
    return out


def _wheel_rate(scene, pr, rates, P):
    """K: the wheel's turning per radian of the crank, from the gear ratio."""
    O = _v(scene.ground[pr.base_centre])
    e = -1 if pr.inside else 1
    d = _sub(P[pr.centre], O)
    r = mpf(pr.radius)
    R = mpmath.sqrt(_dot(d, d)) - e * r
    k_arm = 0 if pr.centre in scene.ground else 1
    k_base = 0 if pr.base is None else rates[pr.base]
    K = (1 + e * R / r) * k_arm - e * (R / r) * k_base
    rates[pr.wheel] = K
    return K, R


def _eval(kind, d, P, th, moving=False):
    """Value and gradient terms of one equation at positions P and crank angle th
    (``moving``: the gradient along a motion, a wheel's angle following its arm and gear;
    else at the instant, where it is phi0)."""
    if kind == "link":
        p, q, L = d
        r = _sub(P[p], P[q])
        return _dot(r, r) - L * L, [(p, 2 * r[0], 2 * r[1]), (q, -2 * r[0], -2 * r[1])]
    if kind in ("crank", "crank2"):
        o, tip, r, c = d[:4]
        if kind == "crank2":
            th = d[4]
        trig = mpmath.cos(th) if c == 0 else mpmath.sin(th)
        val = P[tip][c] - P[o][c] - r * trig
        g = (1, 0) if c == 0 else (0, 1)
        return val, [(tip, mpf(g[0]), mpf(g[1])), (o, -mpf(g[0]), -mpf(g[1]))]
    if kind == "carried":
        x, p, q, lam, mu, c = d
        (px, py), (qx, qy) = P[p], P[q]
        dx, dy = qx - px, qy - py
        if c == 0:
            val = P[x][0] - (px + lam * dx - mu * dy)
            return val, [(x, mpf(1), mpf(0)), (p, -(1 - lam), -mu), (q, -lam, mu)]
        val = P[x][1] - (py + lam * dy + mu * dx)
        return val, [(x, mpf(0), mpf(1)), (p, mu, -(1 - lam)), (q, -mu, -lam)]
    if kind == "path":
        x, through, u = d
        a = _sub(P[x], through)
        return _cross(a, u), [(x, u[1], -u[0])]
    if kind == "block":  # the driving block's place along its path: th is s
        x, through, u = d
        return _dot(_sub(P[x], through), u) - th, [(x, u[0], u[1])]
    if kind in ("collar", "collar2"):  # the collar's place on its rod: (X - K).(N - K) / L = s
        x, k, n, L = d[:4]
        if kind == "collar2":  # a second input: its own place at the instant
            th = d[4]
        a, b = _sub(P[x], P[k]), _sub(P[n], P[k])
        return _dot(a, b) - L * th, [
            (x, b[0], b[1]),
            (n, a[0], a[1]),
            (k, -a[0] - b[0], -a[1] - b[1]),
        ]
    if kind == "yoke":
        x, y, u, e = d  # (X - Y) x u + e = 0: X is e to the left of the line Y + t u
        a = _sub(P[x], P[y])
        return _cross(a, u) + e, [(x, u[1], -u[0]), (y, -u[1], u[0])]
    if kind == "guide":  # (X - G1) x (G2 - G1) + e |G2 - G1| = 0: X is e left of G1 -> G2
        x, g1, g2, e = d
        a, b = _sub(P[x], P[g1]), _sub(P[g2], P[g1])
        nb = mpmath.sqrt(_dot(b, b))
        hx, hy = e * b[0] / nb, e * b[1] / nb  # the gradient of e |b| in G2
        return _cross(a, b) + e * nb, [
            (x, b[1], -b[0]),
            (g2, -a[1] + hx, a[0] + hy),
            (g1, a[1] - b[1] - hx, b[0] - a[0] - hy),
        ]
    if kind == "rack":
        x, T, u, k, base, rates, th0 = d
        K = rates.get(base, 0)  # (at the scene's own angle th = th0 the term is zero)
        return _dot(_sub(P[x], T), u) - k * K * (th - th0), [(x, u[0], u[1])]
    if kind == "rackfree":  # at the scene's own angle the pinion's turn is zero
        x, T, u, k, O, Q = d
        out = [(x, u[0], u[1])]
        if moving:  # - k d(beta), beta the direction O -> Q
            hx, hy = _angle_gradient(P, O, Q)
            out += [(Q, -k * hx, -k * hy), (O, k * hx, k * hy)]
        return _dot(_sub(P[x], T), u), out
    if kind == "wheelline":
        x, T, m, r = d
        return _dot(_sub(P[x], T), m) - r, [(x, m[0], m[1])]
    if kind == "rim":
        x, cen, ell, phi0, how, c = d
        phi, dphi = _rim_angle(P, cen, phi0, how)
        e = (mpmath.cos(phi), mpmath.sin(phi))
        val = P[x][c] - P[cen][c] - ell * e[c]
        pe = _perp(e)[c]  # d e_c / d phi
        g = (mpf(1), mpf(0)) if c == 0 else (mpf(0), mpf(1))
        out = [(x, g[0], g[1]), (cen, -g[0] - ell * pe * dphi[0], -g[1] - ell * pe * dphi[1])]
        if moving and how[0] == "circle":  # phi = phi0 + kd (psi - psi0) + kb (beta - beta0)
            for name, gx, gy in _rim_turning(P, cen, how):
                out.append((name, -ell * pe * gx, -ell * pe * gy))
        return val, out
    raise ValueError(kind)


def _rim_angle(P, cen, phi0, how):
    """The wheel's angle at the scene's own angle and its gradient in C (see the module)."""
    if how[0] == "line":
        _, T, m, r = how
        t = _perp(m)
        phi = phi0 if phi0 is not None else mpmath.atan2(-m[1], -m[0])
        return mpf(phi), (t[0] / r, t[1] / r)
    _, O, e, r, pr, base = how
    if phi0 is None:  # towards the contact (a ring's is beyond the gear inside it)
        d = _sub(P[cen], P[O])
        g = 1 if getattr(pr, "ring", False) else e
        phi0 = mpmath.atan2(-g * d[1], -g * d[0])
    return mpf(phi0), (mpf(0), mpf(0))


def _rim_ratios(P, cen, how):
    """(kd, kb) of a wheel on a circle or gear: its turning per turn of the line of centres
    and per turn of the gear, from no slip at the pitch point relative to the line of
    centres, ``(omega - omega_d) r = -e (omega_B - omega_d) R``; R from the centre
    distance."""
    _, O, e, r, pr, base = how
    d = _sub(P[cen], P[O])
    R = mpmath.sqrt(_dot(d, d)) - e * r
    if getattr(pr, "ring", False):  # the wheel a ring about the gear: |d| = r - R
        R = r - mpmath.sqrt(_dot(d, d))
    return 1 + e * R / r, -e * R / r


def _angle_gradient(P, a, b):
    """d atan2(b - a) / d b (and minus it for a): perp(b - a) / |b - a|^2."""
    d = _sub(P[b], P[a])
    n2 = _dot(d, d)
    return (-d[1] / n2, d[0] / n2)


def _rim_turning(P, cen, how):
    """Gradient terms of the wheel's angle along a motion: kd d(psi) + kb d(beta), psi the
    direction O -> C, beta the gear's (its centre to its other point)."""
    _, O, e, r, pr, base = how
    kd, kb = _rim_ratios(P, cen, how)
    gx, gy = _angle_gradient(P, O, cen)
    out = [(cen, kd * gx, kd * gy), (O, -kd * gx, -kd * gy)]
    if base is not None:
        hx, hy = _angle_gradient(P, base[0], base[1])
        out += [(base[1], kb * hx, kb * hy), (base[0], -kb * hx, -kb * hy)]
    return out


def _rim_value_along(P, V, d, s):
    """The rim equation's value at positions P + s V, the wheel's angle following the
    line of centres and the gear from their directions in P (the motion's second
    derivative of this at s = 0 is the equation's gamma)."""
    x, cen, ell, phi0, how, c = d
    _, O, e, r, pr, base = how
    Q = {n: (P[n][0] + s * V[n][0], P[n][1] + s * V[n][1]) for n in P}
    kd, kb = _rim_ratios(P, cen, how)

    def turn(a, b):  # the turn of direction a -> b from its direction in P
        d0, d1 = _sub(P[b], P[a]), _sub(Q[b], Q[a])
        return mpmath.atan2(_cross(d0, d1), _dot(d0, d1))

    phi, _ = _rim_angle(P, cen, phi0, how)
    phi = phi + kd * turn(O, cen) + (kb * turn(*base) if base is not None else 0)
    ec = mpmath.cos(phi) if c == 0 else mpmath.sin(phi)
    return Q[x][c] - Q[cen][c] - ell * ec


def _add_s(p, v, s):
    """p + s v."""
    return (p[0] + s * v[0], p[1] + s * v[1])


def _unknowns(scene):
    return [n for n in scene.point_names if n not in scene.ground]


def _system(scene, P, th, moving=False):
    """Residual vector and Jacobian (mpmath) at positions P (dict name -> mpf pair);
    ``moving``: the Jacobian of the motion (see :func:`_eval`)."""
    names = _unknowns(scene)
    col = {n: i for i, n in enumerate(names)}
    eqs = _equations(scene)
    if len(eqs) != 2 * len(names):
        raise ValueError(f"{len(eqs)} constraint equations for {2 * len(names)} unknowns")
    F = mpmath.matrix(len(eqs), 1)
    J = mpmath.matrix(len(eqs), 2 * len(names))
    for i, (kind, d) in enumerate(eqs):
        val, grad = _eval(kind, d, P, th, moving)
        F[i] = val
        for name, gx, gy in grad:
            if name in col:
                J[i, 2 * col[name]] += gx
                J[i, 2 * col[name] + 1] += gy
    return F, J, eqs, names


def _full(scene, P):
    out = {n: _v(xy) for n, xy in scene.ground.items()}
    out.update({n: _v(xy) for n, xy in P.items() if n not in scene.ground})
    return out


def constraint_residuals(scene, positions, theta=None):
    """Max |f| over the constraint equations at ``positions`` (theta: crank angle)."""
    th = mpf(scene.input.angle) if theta is None else mpf(theta)
    F, *_ = _system(scene, _full(scene, positions), th)
    return max(abs(F[i]) for i in range(F.rows))


def constraint_jacobian(scene, positions, theta=None):
    """(J, unknown names): the analytic Jacobian, columns x, y of each unknown in turn."""
    th = mpf(scene.input.angle) if theta is None else mpf(theta)
    _, J, _, names = _system(scene, _full(scene, positions), th)
    return J, names


def reference_positions(scene, guess_positions, theta=None, *, max_iter=60):
    """Newton-Raphson on the loop-closure equations from ``guess_positions``."""
    th = mpf(scene.input.angle) if theta is None else mpf(theta)
    P = _full(scene, guess_positions)
    polished = False
    for _ in range(max_iter):
        F, J, _, names = _system(scene, P, th)
        res = max(abs(F[i]) for i in range(F.rows))
        if res < NEWTON_TOL and polished:
            return P, res
        dq = mpmath.lu_solve(J, -F)
        for i, n in enumerate(names):
            P[n] = (P[n][0] + dq[2 * i], P[n][1] + dq[2 * i + 1])
        polished = res < NEWTON_TOL  # one more step after convergence: full precision
    raise ArithmeticError(f"Newton did not converge (residual {mpmath.nstr(res, 3)})")


# --------------------------------------------------------------------------- solution


def reference_solution(scene, guess_positions):
    """Positions, velocities, accelerations, link omega/alpha and slider quantities (mpf)."""
    inp = scene.input
    th, w, al = mpf(inp.angle), mpf(inp.omega), mpf(inp.alpha)
    P, res = reference_positions(scene, guess_positions, th)
    _, J, eqs, names = _system(scene, P, th, moving=True)
    n = len(eqs)

    rates = {inp.crank: mpf(1)}  # a rack's pinion: a gear at a fixed ratio of the crank
    for pr in getattr(scene, "rolling", ()):  # in the scene's order: a gear before its mate
        if pr.on not in ("line", "rack"):
            try:
                _wheel_rate(scene, pr, rates, P)
            except KeyError:  # its gear turns as a linkage makes it: no rack on it
                pass
    ft = mpmath.matrix(n, 1)
    for i, (kind, d) in enumerate(eqs):
        if kind == "crank":
            o, tip, _, c = d
            ft[i] = -w * _perp(_sub(P[tip], P[o]))[c]
        elif kind == "crank2":
            o, tip, _, c, _, w2, _ = d
            ft[i] = -w2 * _perp(_sub(P[tip], P[o]))[c]
        elif kind == "block":
            ft[i] = -w
        elif kind == "collar":
            ft[i] = -d[3] * w
        elif kind == "collar2":
            ft[i] = -d[3] * d[5]
        elif kind == "rack":
            ft[i] = -d[3] * rates[d[4]] * w
    qd = mpmath.lu_solve(J, -ft)
    V = {g: ZERO2 for g in scene.ground}
    V.update({nm: (qd[2 * i], qd[2 * i + 1]) for i, nm in enumerate(names)})

    gamma = mpmath.matrix(n, 1)
    for i, (kind, d) in enumerate(eqs):
        if kind == "link":
            rv = _sub(V[d[0]], V[d[1]])
            gamma[i] = 2 * _dot(rv, rv)
        elif kind == "crank":
            o, tip, _, c = d
            r = _sub(P[tip], P[o])
            gamma[i] = -(al * _perp(r)[c] - w * w * r[c])
        elif kind == "crank2":
            o, tip, _, c, _, w2, al2 = d
            r = _sub(P[tip], P[o])
            gamma[i] = -(al2 * _perp(r)[c] - w2 * w2 * r[c])
        elif (
            kind == "guide"
        ):  # and e |b|'' less its part in J q'': e (b'.b' - (b.b')^2 / b.b) / |b|
            x, g1, g2, e = d
            bv, b = _sub(V[g2], V[g1]), _sub(P[g2], P[g1])
            bb = _dot(b, b)
            gamma[i] = 2 * _cross(_sub(V[x], V[g1]), bv) + e * (
                _dot(bv, bv) - _dot(b, bv) ** 2 / bb
            ) / mpmath.sqrt(bb)
        elif kind == "block":
            gamma[i] = -al
        elif kind in ("collar", "collar2"):  # (X - K).(N - K) - L s: f'' minus J q''
            x, k, n, L = d[:4]
            gamma[i] = 2 * _dot(_sub(V[x], V[k]), _sub(V[n], V[k])) - L * (
                al if kind == "collar" else d[6]
            )
        elif kind == "rack":
            gamma[i] = -d[3] * rates[d[4]] * al
        elif kind == "rackfree":  # -k beta along the motion: its second derivative
            x, T, u, k, O, Q = d
            d0 = _sub(P[Q], P[O])
            gamma[i] = -k * mpmath.diff(
                lambda s: mpmath.atan2(
                    _cross(d0, _sub(_add_s(P[Q], V[Q], s), _add_s(P[O], V[O], s))),
                    _dot(d0, _sub(_add_s(P[Q], V[Q], s), _add_s(P[O], V[O], s))),
                ),
                0,
                2,
            )
        elif kind == "rim":  # X - C - l e(phi): gamma = l phi'^2 e - l perp(e) phi_tt
            x, cen, ell, _, how, c = d
            e = _unit(_sub(P[x], P[cen]))
            if how[0] == "line":
                t = _perp(how[2])
                dphi, phitt = _dot(V[cen], t) / how[3], 0
                gamma[i] = ell * dphi * dphi * e[c] - ell * _perp(e)[c] * phitt
            else:  # no explicit time: the second derivative along the motion
                gamma[i] = mpmath.diff(lambda s, d=d: _rim_value_along(P, V, d, s), 0, 2)
    qdd = mpmath.lu_solve(J, -gamma)
    A = {g: ZERO2 for g in scene.ground}
    A.update({nm: (qdd[2 * i], qdd[2 * i + 1]) for i, nm in enumerate(names)})

    omega, alpha = {}, {}
    for lk in scene.links:
        r = _sub(P[lk.q], P[lk.p])
        r2 = _dot(r, r)
        omega[lk.key] = _cross(r, _sub(V[lk.q], V[lk.p])) / r2
        alpha[lk.key] = _cross(r, _sub(A[lk.q], A[lk.p])) / r2

    sliders = {}
    for sl in scene.sliders:
        x = sl.point
        if hasattr(sl, "guide"):
            g1, g2 = sl.first, sl.second
            u = _unit(_sub(P[g2], P[g1]))
            wg, ag = omega[scene.link(sl.guide).key], alpha[scene.link(sl.guide).key]
            rel = _sub(P[x], P[g1])
            vx_ = (V[g1][0] + wg * _perp(rel)[0], V[g1][1] + wg * _perp(rel)[1])
            vs = _dot(_sub(V[x], vx_), u)
            cor = (2 * wg * vs * _perp(u)[0], 2 * wg * vs * _perp(u)[1])
            ax_ = (
                A[g1][0] - wg * wg * rel[0] + ag * _perp(rel)[0],
                A[g1][1] - wg * wg * rel[1] + ag * _perp(rel)[1],
            )
            acc = _dot(_sub(_sub(A[x], ax_), cor), u)
        elif hasattr(sl, "yoke"):  # relative to the yoke, which translates: no Coriolis
            u = _unit(_v(sl.direction))
            vs, acc = _dot(_sub(V[x], V[sl.yoke]), u), _dot(_sub(A[x], A[sl.yoke]), u)
            cor = ZERO2
        else:
            u = _path_unit(sl)
            vs, acc, cor = _dot(V[x], u), _dot(A[x], u), ZERO2
        sliders[getattr(sl, "key", x)] = {"vs": vs, "as": acc, "coriolis": cor}

    return {
        "positions": P,
        "velocities": V,
        "accelerations": A,
        "omega": omega,
        "alpha": alpha,
        "sliders": sliders,
        "residual": res,
    }


# --------------------------------------------------------------------------- closed forms


def reference_slider_crank(r, l, e, theta, omega, alpha):
    """Offset slider-crank: crank pivot at the origin, slider on y = e (piston right of pin).

    ``x = r cos th + D``, ``D = sqrt(l^2 - s^2)``, ``s = r sin th - e``; with
    ``x_th = -r sin th - s c / D`` and ``x_thth = -c - (c^2 - s yB) / D - s^2 c^2 / D^3``
    (``c = r cos th``, ``yB = r sin th``): ``v = omega x_th``, ``a = alpha x_th + omega^2 x_thth``.
    Rod B -> piston at angle phi = -asin(s / l): ``omega_rod = -c omega / D``,
    ``alpha_rod = (yB omega^2 - c alpha) / D - s c^2 omega^2 / D^3``.
    """
    r, l, e, th, w, al = (mpf(v) for v in (r, l, e, theta, omega, alpha))
    c, yb = r * mpmath.cos(th), r * mpmath.sin(th)
    s = yb - e
    D = mpmath.sqrt(l * l - s * s)
    x = c + D
    x1 = -yb - s * c / D
    x2 = -c - (c * c - s * yb) / D - s * s * c * c / D**3
    return {
        "x": x,
        "v": w * x1,
        "a": al * x1 + w * w * x2,
        "omega_rod": -c * w / D,
        "alpha_rod": (yb * w * w - c * al) / D - s * c * c * w * w / D**3,
    }


def reference_fourbar_algebraic(a, b, c, d, theta2, omega2, alpha2, branch):
    """Four-bar by the algebraic method (ME220 lecture 6): O2 at the origin, O4 at (d, 0),
    crank O2A = a, coupler AB = b, rocker O4B = c; ``branch`` = +1 / -1 is the sign of the
    root in ``B_y = (-Q +- sqrt(Q^2 - 4 P R)) / 2P``.

    Velocities and accelerations: mpmath.diff of the closed form in time, with
    ``theta2(t) = theta2 + omega2 t + alpha2 t^2 / 2``.
    """
    a, b, c, d, th0, w, al = (mpf(v) for v in (a, b, c, d, theta2, omega2, alpha2))
    sgn = 1 if branch > 0 else -1

    def pos(t):
        th = th0 + w * t + al * t * t / 2
        ax, ay = a * mpmath.cos(th), a * mpmath.sin(th)
        S = (a * a - b * b + c * c - d * d) / (2 * (ax - d))
        Pc = ay * ay / (ax - d) ** 2 + 1
        Qc = 2 * ay * (d - S) / (ax - d)
        Rc = (d - S) ** 2 - c * c
        by = (-Qc + sgn * mpmath.sqrt(Qc * Qc - 4 * Pc * Rc)) / (2 * Pc)
        bx = S - ay * by / (ax - d)
        return ax, ay, bx, by

    ax, ay, bx, by = pos(0)
    th3 = mpmath.atan2(by - ay, bx - ax)
    th4 = mpmath.atan2(by, bx - d)

    def angle(t, which):  # continuous near t = 0: the turn from the t = 0 direction
        ax_, ay_, bx_, by_ = pos(t)
        r0 = (bx - ax, by - ay) if which == 3 else (bx - d, by)
        r = (bx_ - ax_, by_ - ay_) if which == 3 else (bx_ - d, by_)
        return mpmath.atan2(_cross(r0, r), _dot(r0, r))

    def deriv(f, n):
        return mpmath.diff(f, 0, n)

    comp = [lambda t, k=k: pos(t)[k] for k in range(4)]
    vA = (deriv(comp[0], 1), deriv(comp[1], 1))
    vB = (deriv(comp[2], 1), deriv(comp[3], 1))
    aA = (deriv(comp[0], 2), deriv(comp[1], 2))
    aB = (deriv(comp[2], 2), deriv(comp[3], 2))
    return {
        "A": (ax, ay),
        "B": (bx, by),
        "theta3": th3,
        "theta4": th4,
        "vA": vA,
        "vB": vB,
        "aA": aA,
        "aB": aB,
        "omega3": deriv(lambda t: angle(t, 3), 1),
        "omega4": deriv(lambda t: angle(t, 4), 1),
        "alpha3": deriv(lambda t: angle(t, 3), 2),
        "alpha4": deriv(lambda t: angle(t, 4), 2),
    }
