"""The loop equations of a class-III group (a triad): a plate with three vertices V1, V2,
V3, each joined by a binary link to a known point K1, K2, K3. No vertex can be found alone
(each has one link to a known point): the three are found at once.

Position: the plate's pose ``q = (x, y, th)``, V1 = (x, y), ``Vi = V1 + R(th) ui`` with
ui the vertex's place on the plate relative to V1 (u1 = 0), from the loop equations
``Fi = |Vi - Ki|^2 - li^2 = 0`` by Newton's method, ``M dq = -F / 2`` with the rows of
``M``::

    (rix, riy, (Vi - V1) x ri),   ri = Vi - Ki

Several assemblies exist (up to six); the one the scene states is followed from the
scene's instant by continuation (each new position from the nearest one already solved,
in small steps where the inputs move far, never across a change of sign of det M).

Velocity: ``vVi = v1 + w perp(Vi - V1)`` and ``ri . (vVi - vKi) = 0``, one 3x3 solve
``M (v1x, v1y, w) = (ri . vKi)``. Acceleration: ``aVi = a1 + al perp(Vi - V1) - w^2 (Vi -
V1)`` and ``ri . (aVi - aKi) + |vVi - vKi|^2 = 0``, the same matrix with the right side
``ri . (aKi + w^2 (Vi - V1)) - |vVi - vKi|^2``. A link's omega is ``ri x (vVi - vKi) /
|ri|^2`` (alpha the same with accelerations).

Condition: ``|det N| / prod |Ni|`` with the rows ``Ni = (uix, uiy, (Vi - G) x ui / rho)``,
ui the unit vector along link i, G the plate's centroid and rho the RMS distance of its
vertices from G: 1 when the three links pull along orthogonal directions, 0 when their
lines meet in one point (or are parallel), where the plate can turn about that point
without any link moving (the triad's singular position).

>>> solve3((1.0, 0.0, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 4.0), (1.0, 1.0, 1.0))
(1.0, 0.5, 0.25)
"""

from __future__ import annotations

from ...common.tolerances import CONVERGED, LEAST_STEP, ONE_ASSEMBLY
import math

from ..construction import add
from ..relations import rigid_acceleration, rigid_velocity

__all__ = [
    "solve3",
    "det3",
    "vertices",
    "matrix",
    "velocity",
    "acceleration",
    "condition",
    "newton_step",
    "assemblies",
    "follow",
    "solve_scalar",
    "solve_array",
    "Memo",
    "flat",
    "scale",
    "sign",
    "det_sign",
    "kp",
]

#: Newton's residual (|Fi| / 2 li, relative to the largest length) taken as converged
_CONVERGED = CONVERGED
#: the most plate positions continuation keeps per step (for starting new solves)
_KEEP = 1024
#: solved positions passed sequentially in array mode (the rest start from them)
_SUBSAMPLE = 256


# --------------------------------------------------------------------------- formulas


def solve3(m, h):
    """z with M z = h for a 3x3 matrix ``m`` (9 entries, rows first) by Cramer's rule;
    floats or arrays. Returns the three entries of z."""
    a, b, c, d, e, f, g, k, l_ = m
    h1, h2, h3 = h
    c1 = e * l_ - f * k
    c2 = f * g - d * l_
    c3 = d * k - e * g
    det = a * c1 + b * c2 + c * c3
    z1 = (h1 * c1 + b * (f * h3 - h2 * l_) + c * (h2 * k - e * h3)) / det
    z2 = (a * (h2 * l_ - f * h3) + h1 * c2 + c * (d * h3 - h2 * g)) / det
    z3 = (a * (e * h3 - h2 * k) + b * (h2 * g - d * h3) + h1 * c3) / det
    return z1, z2, z3


def det3(m):
    """The determinant of a 3x3 matrix given row by row as nine numbers."""
    a, b, c, d, e, f, g, k, l_ = m
    return a * (e * l_ - f * k) + b * (f * g - d * l_) + c * (d * k - e * g)


def vertices(x, y, th, prm, cos, sin):
    """The plate's vertices V1, V2, V3 at pose (x, y, th); ``prm`` = (l1, l2, l3, u2x, u2y,
    u3x, u3y)."""
    c, s = cos(th), sin(th)
    u2x, u2y, u3x, u3y = prm[3], prm[4], prm[5], prm[6]
    return (
        (x, y),
        (x + c * u2x - s * u2y, y + s * u2x + c * u2y),
        (x + c * u3x - s * u3y, y + s * u3x + c * u3y),
    )


def matrix(V, K):
    """The rows (rix, riy, (Vi - V1) x ri) of the loop equations' Jacobian (halved)."""
    (x1, y1) = V[0]
    out = []
    for (vx, vy), (kx, ky) in zip(V, K):
        rx, ry = vx - kx, vy - ky
        out += [rx, ry, (vx - x1) * ry - (vy - y1) * rx]
    return tuple(out)


def newton_step(q, K, prm, cos, sin):
    """One Newton step from pose ``q``: (new pose, residual max |Fi| / 2 li, det M at q)."""
    x, y, th = q
    V = vertices(x, y, th, prm, cos, sin)
    m = matrix(V, K)
    F = []
    res = None
    for i in range(3):
        rx, ry = V[i][0] - K[i][0], V[i][1] - K[i][1]
        f = 0.5 * (rx * rx + ry * ry - prm[i] * prm[i])
        F.append(-f)
        r = abs(f) / prm[i]
        res = r if res is None else _vmax(r, res)
    dx, dy, dth = solve3(m, F)
    return (x + dx, y + dy, th + dth), res, det3(m)


def _vmax(a, b):
    if isinstance(a, float) and isinstance(b, float):
        return a if a >= b else b
    import numpy as np

    return np.maximum(a, b)


def condition(V, K):
    """|det N| / prod |Ni| (see the module): 1 at best, 0 where the three links' lines
    meet in one point."""
    gx = (V[0][0] + V[1][0] + V[2][0]) / 3.0
    gy = (V[0][1] + V[1][1] + V[2][1]) / 3.0
    rho2 = sum((vx - gx) ** 2 + (vy - gy) ** 2 for vx, vy in V) / 3.0
    rho = rho2**0.5
    rows, norm = [], 1.0
    for (vx, vy), (kx, ky) in zip(V, K):
        rx, ry = vx - kx, vy - ky
        n = (rx * rx + ry * ry) ** 0.5
        ux, uy = rx / n, ry / n
        t = ((vx - gx) * uy - (vy - gy) * ux) / rho
        rows += [ux, uy, t]
        norm = norm * (1.0 + t * t) ** 0.5
    return abs(det3(rows)) / norm


def velocity(V, K, VK):
    """(v1, w, (vV1, vV2, vV3), (w1, w2, w3)): the plate's and the links' angular velocities
    and the vertices' velocities, from the known points' velocities ``VK``."""
    m = matrix(V, K)
    h = tuple((V[i][0] - K[i][0]) * VK[i][0] + (V[i][1] - K[i][1]) * VK[i][1] for i in range(3))
    vx, vy, w = solve3(m, h)
    x1, y1 = V[0]
    vv, wl = [], []
    for i in range(3):
        dx, dy = V[i][0] - x1, V[i][1] - y1
        ex, ey = add((vx, vy), rigid_velocity(dx, dy, w))
        vv.append((ex, ey))
        rx, ry = V[i][0] - K[i][0], V[i][1] - K[i][1]
        wl.append((rx * (ey - VK[i][1]) - ry * (ex - VK[i][0])) / (rx * rx + ry * ry))
    return w, tuple(vv), tuple(wl)


def acceleration(V, K, VV, VK, AK, w):
    """(al, (aV1, aV2, aV3), (al1, al2, al3)) from the known points' accelerations ``AK``,
    the vertices' and known points' velocities and the plate's omega ``w``."""
    m = matrix(V, K)
    x1, y1 = V[0]
    w2 = w * w
    h = []
    for i in range(3):
        rx, ry = V[i][0] - K[i][0], V[i][1] - K[i][1]
        sx, sy = VV[i][0] - VK[i][0], VV[i][1] - VK[i][1]
        h.append(
            rx * (AK[i][0] + w2 * (V[i][0] - x1))
            + ry * (AK[i][1] + w2 * (V[i][1] - y1))
            - (sx * sx + sy * sy)
        )
    ax, ay, al = solve3(m, h)
    aa, all_ = [], []
    for i in range(3):
        dx, dy = V[i][0] - x1, V[i][1] - y1
        ex, ey = add((ax, ay), rigid_acceleration(dx, dy, w, al))
        aa.append((ex, ey))
        rx, ry = V[i][0] - K[i][0], V[i][1] - K[i][1]
        all_.append((rx * (ey - AK[i][1]) - ry * (ex - AK[i][0])) / (rx * rx + ry * ry))
    return al, tuple(aa), tuple(all_)


# --------------------------------------------------------------------------- positions


def scale(prm):
    """The triad's size: its largest dimension (the scale of its tolerances)."""
    return max(
        abs(prm[0]),
        abs(prm[1]),
        abs(prm[2]),
        math.hypot(prm[3], prm[4]),
        math.hypot(prm[5], prm[6]),
        1e-300,
    )


def _newton(q, K, prm, size, iters=40):
    """Newton to machine precision from pose q (floats): (pose, det M) or None."""
    cos, sin = math.cos, math.sin
    tol = _CONVERGED * max(size, *(abs(c) for xy in K for c in xy), abs(q[0]), abs(q[1]))
    polished = False
    for _ in range(iters):
        new, res, det = newton_step(q, K, prm, cos, sin)
        if not all(math.isfinite(v) for v in new):
            return None
        dx, dy, dth = new[0] - q[0], new[1] - q[1], new[2] - q[2]
        if math.hypot(dx, dy) > size or abs(dth) > 1.0:  # a wild step: not near a solution
            return None
        q = new
        if polished:
            return q, det
        polished = res <= tol
    return None


def flat(K, prm):
    """The known points ``K`` and the dimensions ``prm`` as one flat tuple (the memo's key)."""
    return tuple(c for xy in K for c in xy) + tuple(prm)


def follow(q, a, b, size, det_sign):
    """Continuation (floats) of pose ``q``, solved at inputs ``a`` (K and dimensions
    flattened), to inputs ``b``: straight along the inputs, in steps halved where Newton
    fails, jumps or changes the sign of det M (another assembly). The pose at ``b`` or
    None (the assembly ends on the way: a limit position)."""
    t, h = 0.0, 1.0
    dist = max(abs(u - v) for u, v in zip(a, b)) / size
    if dist > 0.05:
        h = 0.05 / dist
    while t < 1.0:
        s = min(1.0, t + h)
        inp = tuple(u + s * (v - u) for u, v in zip(a, b))
        K, prm = ((inp[0], inp[1]), (inp[2], inp[3]), (inp[4], inp[5])), inp[6:]
        got = _newton(q, K, prm, size, iters=12 if s < 1.0 else 40)
        ok = got is not None and (det_sign == 0 or got[1] * det_sign > 0)
        if ok:
            moved = math.hypot(got[0][0] - q[0], got[0][1] - q[1])
            step = max(abs(u - v) for u, v in zip(a, b)) * (s - t)
            ok = moved <= 4.0 * step + 0.1 * size and abs(got[0][2] - q[2]) < 0.5
        if ok:
            q, t = got[0], s
            h = min(2.0 * h, 1.0)
        else:
            h *= 0.5
            if h < LEAST_STEP:
                return None
    return q


def assemblies(K, prm, n=2048):
    """Every assembly of the triad at known points ``K`` (floats): a list of poses, found
    by turning link 1 about K1 (angle phi), placing the plate about V1 so that V2 is on its
    circle about K2 (two ways), and taking the sign changes of |V3 - K3|^2 - l3^2, each
    polished by Newton."""
    import numpy as np

    l1, l2, l3, u2x, u2y, u3x, u3y = prm
    size = scale(prm)
    phi = np.linspace(0.0, 2.0 * math.pi, n + 1)
    x1 = K[0][0] + l1 * np.cos(phi)
    y1 = K[0][1] + l1 * np.sin(phi)
    dx, dy = K[1][0] - x1, K[1][1] - y1
    dn = np.hypot(dx, dy)
    un = math.hypot(u2x, u2y)
    c = (un * un + dn * dn - l2 * l2) / 2.0
    with np.errstate(all="ignore"):
        arg = c / (dn * un)
    ok = np.abs(arg) <= 1.0
    base = np.arctan2(dy, dx) - math.atan2(u2y, u2x)
    found = []
    for sign in (1.0, -1.0):
        th = base + sign * np.arccos(np.clip(arg, -1.0, 1.0))
        x3 = x1 + np.cos(th) * u3x - np.sin(th) * u3y
        y3 = y1 + np.sin(th) * u3x + np.cos(th) * u3y
        g = (x3 - K[2][0]) ** 2 + (y3 - K[2][1]) ** 2 - l3 * l3
        seeds = []
        for i in np.nonzero(ok[:-1] & ok[1:] & (np.sign(g[:-1]) != np.sign(g[1:])))[0]:
            w = g[i] / (g[i] - g[i + 1]) if g[i] != g[i + 1] else 0.5
            seeds.append(
                (
                    x1[i] + w * (x1[i + 1] - x1[i]),
                    y1[i] + w * (y1[i + 1] - y1[i]),
                    th[i] + w * (th[i + 1] - th[i]),
                )
            )
        # two roots closer than the grid (near a limit) make no sign change: the small
        # local minima of |g| are tried too
        a = np.abs(g)
        near = (
            ok[1:-1]
            & ok[:-2]
            & ok[2:]
            & (a[1:-1] <= a[:-2])
            & (a[1:-1] <= a[2:])
            & (a[1:-1] < 0.05 * l3 * size)
        )
        seeds += [(x1[i], y1[i], th[i]) for i in np.nonzero(near)[0] + 1]
        for q0 in seeds:
            got = _newton(tuple(float(v) for v in q0), K, prm, size)
            if got is None:
                continue
            q = got[0]
            if all(
                math.hypot(q[0] - p[0], q[1] - p[1]) > ONE_ASSEMBLY * size
                or abs(math.remainder(q[2] - p[2], 2 * math.pi)) > ONE_ASSEMBLY
                for p in found
            ):
                found.append((q[0], q[1], math.remainder(q[2], 2 * math.pi)))
    return found


class Memo:
    """The poses this step has solved (its inputs flattened, the pose, sign of det M):
    the scene's own first, then what continuation passed (at most ``_KEEP``)."""

    def __init__(self, anchor):
        self.items = [anchor]
        self._array = None

    def array(self):
        """The memo's inputs as one array (for the nearest-neighbour search)."""
        if self._array is None or len(self._array) != len(self.items):
            import numpy as np

            self._array = np.array([it[0] for it in self.items])
        return self._array

    def nearest(self, inp, size):
        """The memo's item whose inputs are nearest to ``inp`` and its distance relative to
        ``size``."""
        first = self.items[0]
        if first[0] == inp:
            return first, 0.0
        if len(self.items) < 16:
            best, bd = None, None
            for it in self.items:
                d = max(abs(u - v) for u, v in zip(it[0], inp)) / size
                if bd is None or d < bd:
                    best, bd = it, d
            return best, bd
        import numpy as np

        d = np.abs(self.array() - np.asarray(inp)).max(axis=1)
        k = int(np.argmin(d))
        return self.items[k], float(d[k]) / size

    def add(self, inp, q, sign):
        """Remember the pose ``q`` solved at inputs ``inp`` with its determinant's sign (the oldest
        forgotten past the memo's size)."""
        if len(self.items) >= _KEEP:
            del self.items[1 : _KEEP // 2]
        self.items.append((inp, q, sign))


def solve_scalar(memo, K, prm):
    """The pose at inputs (K, prm) on the scene's assembly (floats), or None."""
    size = scale(prm)
    inp = flat(K, prm)
    it, d = memo.nearest(inp, size)
    if d == 0.0:
        got = _newton(it[1], K, prm, size)
        if got is not None and got[1] * it[2] > 0:
            return got[0]
        return None
    q = follow(it[1], it[0], inp, size, it[2])
    if q is not None:
        memo.add(inp, q, sign(newton_step(q, K, prm, math.cos, math.sin)[2]))
    return q


def kp(inp):
    """Flat inputs back into the known points and the dimensions."""
    return ((inp[0], inp[1]), (inp[2], inp[3]), (inp[4], inp[5])), inp[6:]


def det_sign(q, inp):
    """The sign of the loop equations' Jacobian at pose ``q`` (the assembly's side)."""
    return sign(newton_step(q, *kp(inp), math.cos, math.sin)[2])


def solve_array(memo, K, prm, np):
    """Poses for arrays of inputs: continuation in the arrays' order (a crank's turn) from
    the element nearest to a pose already solved, over a subsample (at most
    ``_SUBSAMPLE`` points); the rest by Newton from the straight line between their two
    solved neighbours, in one vectorised pass; an element where that fails (near a limit)
    by continuation from its neighbour. Returns (x, y, th, bad mask)."""
    data, size = _stacked(K, prm, np)
    n = len(data)
    sub_idx = _subsample(data, size, np)
    inp_of = lambda i: tuple(float(v) for v in data[i])  # noqa: E731
    a, qs, signs = _walk(memo, data, sub_idx, size, inp_of, np)
    if not qs:
        return np.zeros(n), np.zeros(n), np.zeros(n), np.ones(n, dtype=bool)
    x, y, th, good, inside = _between(data, size, qs, signs, np)
    # what Newton missed between two solved neighbours: continuation from the neighbour
    idx = np.arange(n)
    for side in (idx[(idx > a) & inside & ~good], idx[(idx < a) & inside & ~good][::-1]):
        for i in side:
            prev = i - 1 if i > a else i + 1
            if not good[prev]:
                continue
            p = (float(x[prev]), float(y[prev]), float(th[prev]))
            got = follow(p, inp_of(prev), inp_of(i), size, det_sign(p, inp_of(prev)))
            if got is not None:
                x[i], y[i], th[i] = got
                good[i] = True
    return x, y, th, ~good


def _stacked(K, prm, np):
    """The inputs as an n x 13 array (the known points' x, y, then the dimensions) and the
    size of the largest dimension."""
    cols = [np.asarray(c, dtype=float) for xy in K for c in xy] + [
        np.asarray(p, dtype=float) for p in prm
    ]
    n = max([c.size for c in cols] + [1])
    cols = [np.broadcast_to(c, (n,)) if c.ndim else np.full(n, float(c)) for c in cols]
    data = np.stack(cols, axis=1)  # n x 13
    return data, float(max(scale(tuple(np.max(np.abs(data[:, 6:]), axis=0))), 1e-300))


def _subsample(data, size, np):
    """The elements continuation walks through: every 2 % of the largest length the
    inputs move (at most ``_SUBSAMPLE``), the first and the last."""
    n = len(data)
    moved = np.concatenate([[0.0], np.cumsum(np.abs(np.diff(data, axis=0)).max(axis=1))])
    marks = np.searchsorted(moved, np.arange(0.0, moved[-1], 0.02 * size))
    if len(marks) > _SUBSAMPLE:
        marks = range(0, n, max(1, -(-n // _SUBSAMPLE)))
    return sorted(set(int(i) for i in marks) | {0, n - 1})


def _walk(memo, data, sub_idx, size, inp_of, np):
    """Continuation over the subsample, both ways from the element nearest a pose already
    solved (``memo``), stopping each way at a limit: (that element, poses, signs) by
    element index."""
    ref = memo.array()
    probe = sub_idx[:: max(1, len(sub_idx) // 16)]  # where the walk starts: near a solved one
    dist = np.abs(data[probe][:, None, :] - ref[None, :, :]).max(axis=2).min(axis=1)
    a = probe[int(np.argmin(dist))]
    qs, signs = {}, {}
    qa = solve_scalar(memo, *kp(inp_of(a)))
    if qa is None:
        return a, qs, signs
    qs[a] = qa
    signs[a] = det_sign(qa, inp_of(a))
    pos = sub_idx.index(a)
    for order in (sub_idx[pos + 1 :], sub_idx[:pos][::-1]):
        prev = a
        for i in order:
            q = follow(qs[prev], inp_of(prev), inp_of(i), size, signs[prev])
            if q is None:  # a limit before i: each element up to it in turn
                d = 1 if i > prev else -1
                for e in range(prev + d, i, d):
                    q = follow(qs[prev], inp_of(prev), inp_of(e), size, signs[prev])
                    if q is None:
                        break
                    qs[e] = q
                    signs[e] = det_sign(q, inp_of(e))
                    prev = e
                break
            qs[i] = q
            signs[i] = det_sign(q, inp_of(i))
            memo.add(inp_of(i), q, signs[i])
            prev = i
    return a, qs, signs


def _between(data, size, qs, signs, np):
    """Every element between the solved ones by Newton from the straight line between its
    two solved neighbours, in one vectorised pass, kept where it converged on the same
    assembly: (x, y, th, good mask, inside the solved range mask)."""
    n = len(data)
    known = np.array(sorted(qs), dtype=np.intp)
    kq = np.array([qs[int(i)] for i in known])
    ks = np.array([signs[int(i)] for i in known])
    idx = np.arange(n)
    inside = (idx >= known[0]) & (idx <= known[-1])
    if len(known) == 1:
        lo = hi = np.zeros(n, dtype=np.intp)
        w = np.zeros(n)
    else:
        hi = np.clip(np.searchsorted(known, idx), 1, len(known) - 1)
        lo = hi - 1
        w = np.clip((idx - known[lo]) / (known[hi] - known[lo]), 0.0, 1.0)
    q = [kq[lo, c] + w * (kq[hi, c] - kq[lo, c]) for c in range(3)]
    Kx = tuple((data[:, 2 * i], data[:, 2 * i + 1]) for i in range(3))
    pr = tuple(data[:, 6 + c] for c in range(7))
    with np.errstate(all="ignore"):
        for _ in range(8):
            q, res, det = newton_step(tuple(q), Kx, pr, np.cos, np.sin)
        q, res, det = newton_step(tuple(q), Kx, pr, np.cos, np.sin)
        big = np.maximum(size, np.abs(data[:, :6]).max(axis=1))
        good = (
            inside
            & np.isfinite(res)
            & (res <= 1e3 * _CONVERGED * big)
            & (np.sign(det) == ks[lo])
            & (np.sign(det) == ks[hi])
        )
    x, y, th = (np.where(good, c, 0.0) for c in q)
    for k in known:
        x[k], y[k], th[k] = qs[int(k)]
        good[k] = True
    return x, y, th, good, inside


def sign(d):
    """+1.0 for a positive ``d``, else -1.0."""
    return 1.0 if d > 0 else -1.0
