"""The force tests' matrix method: the Newton-Euler equations of planar rigid bodies as one
linear system in every unknown force and couple at once, solved in floats (numpy) or at
mpmath's precision. It is the second method beside the tool's walk group by group in the
plan's reverse order, so it imports nothing of ``polygon_method``: each test says which
forces act on which body, where and along what, and puts the inertia, the weights and the
loads (D'Alembert) on the known side.

Three equations per moving body: the sums of the x forces, of the y forces, and of the
moments about the origin (or about a point of the body's own, ``about``: a block whose
every force passes through its pin has no moment equation, and the row is left out). A body
not in the list (the frame) takes no equations: what acts on it is its own business.

>>> ne = NewtonEuler(["bar"])  # a bar hinged at the origin, held level by a force at x = 2
>>> ne.pin("O", (0.0, 0.0), "bar", "frame")
>>> ne.along("F", (2.0, 0.0), (0.0, 1.0), "bar", "frame")
>>> ne.known("bar", (0.0, -10.0), (1.0, 0.0))  # its weight at its middle
>>> x = ne.solve()
>>> [round(float(x[k]), 12) for k in ("O.x", "O.y", "F")]
[0.0, 5.0, 5.0]
"""

from __future__ import annotations

import mpmath
import numpy as np

__all__ = ["NewtonEuler"]


class NewtonEuler:
    """The equations of ``bodies``, an unknown at a time (each a column by name); ``mp``:
    solve with mpmath at its current precision (the coefficients taken as ``mpf``)."""

    def __init__(self, bodies, about=None, mp=False):
        self.bodies = list(bodies)
        self.about = dict(about or {})  # body -> the point its moments are taken about
        self.mp = mp
        self.cols = []  # (name, [(body, fx, fy, moment about the origin)])
        self.rhs = {b: [0, 0, 0] for b in self.bodies}

    def pin(self, name, at, on, by):
        """A force of two unknown components (``name.x``, ``name.y``) at ``at`` on ``on``,
        its opposite on ``by``."""
        x, y = at
        self.cols.append((name + ".x", [(on, 1, 0, -y), (by, -1, 0, y)]))
        self.cols.append((name + ".y", [(on, 0, 1, x), (by, 0, -1, -x)]))

    def along(self, name, at, d, on, by):
        """A force of unknown size ``name`` along ``d`` at ``at`` on ``on``, its opposite on
        ``by``."""
        x, y = at
        m = x * d[1] - y * d[0]
        self.cols.append((name, [(on, d[0], d[1], m), (by, -d[0], -d[1], -m)]))

    def couple(self, name, on, by=None):
        """A couple of unknown size ``name`` (ccw positive) on ``on``, its opposite on
        ``by``."""
        self.cols.append((name, [(on, 0, 0, 1)] + ([(by, 0, 0, -1)] if by is not None else [])))

    def known(self, body, F=(0, 0), at=(0, 0), c=0):
        """A known force ``F`` at ``at`` and a known couple ``c`` on ``body`` (an inertia
        force and couple, a weight, a load): moved to the right-hand side."""
        if body in self.rhs:
            e = self.rhs[body]
            e[0] -= F[0]
            e[1] -= F[1]
            e[2] -= at[0] * F[1] - at[1] * F[0] + c

    def vector(self, x, name):
        """The force ``name`` added by :meth:`pin`, from the solution ``x``, as (x, y)."""
        return (x[name + ".x"], x[name + ".y"])

    def solve(self):
        """{unknown's name: value}: floats (numpy), or mpmath numbers (``mp``)."""
        num = mpmath.mpf if self.mp else float
        n = len(self.cols)
        rows = {b: [[num(0)] * n for _ in range(3)] for b in self.bodies}
        ref = {b: self.about.get(b, (0, 0)) for b in self.bodies}
        for j, (_, acts) in enumerate(self.cols):
            for body, fx, fy, m in acts:
                if body in rows:
                    rx, ry = ref[body]
                    for k, v in enumerate((fx, fy, m - (rx * fy - ry * fx))):
                        rows[body][k][j] += num(v)
        A, b = [], []
        for body in self.bodies:
            rx, ry = ref[body]
            kx, ky, km = self.rhs[body]
            for k, v in enumerate((kx, ky, km - (rx * ky - ry * kx))):
                if k == 2 and body in self.about and all(abs(e) < 1e-15 for e in rows[body][k]):
                    continue  # every force on it passes through its point: no moment row
                A.append(rows[body][k])
                b.append(num(v))
        assert len(A) == n, f"{len(A)} equations for {n} unknowns: not statically determinate"
        if self.mp:
            x = mpmath.lu_solve(mpmath.matrix(A), mpmath.matrix(b))
        else:
            x = np.linalg.solve(np.array(A, dtype=float), np.array(b, dtype=float))
        return {name: x[j] for j, (name, _) in enumerate(self.cols)}
