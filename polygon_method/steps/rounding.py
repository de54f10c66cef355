"""How rounding passes through a construction step: the helpers each kind's
``error_bound`` uses (for floats or numpy arrays alike, and shared with the layers above:
``vhypot`` is :func:`polygon_method.solver.kinematics.hypot`, ``largest`` the one of
:mod:`polygon_method.solver.derived` and :mod:`polygon_method.solver.errorbound`) and the rule of two
direction lines that most kinds share. The walk along the plan, the sizes the bounds are relative to and
the output records are in :mod:`polygon_method.solver.errorbound`.

A step that intersects two direction lines divides by its condition ``c`` (the sine of the
angle between them), so it multiplies the errors it is given, and the rounding ``k`` it
makes itself, by ``g = 1/c``::

    eP = g (k + eP_in)
    eV = g (k + eV_in + eP)
    eA = g (k + eA_in + eP + R eV)

with ``R = omega_scale^2 / alpha_scale`` (where velocities themselves grow like 1/c the
accelerations grow faster still, and the error relative to them is one power of c smaller).
A step given its own rounding for each kind (``k_P, k_V, k_A``: ``k`` times its own speeds
and accelerations over the sizes of their kinds) and its own links' coupling (``c_V eP``,
``c_A eP``, ``c_R eV`` in place of ``eP``, ``eP``, ``R eV``) has them in their places.

>>> p, v, a, w, al = two_lines(0.5, 1.0, 1.0, 0.0, 0.0, 0.0)   # c = 1/2, own rounding 1
>>> p, v, a
(2.0, 6.0, 18.0)
"""

from __future__ import annotations

import math

from ..common.tolerances import LEAST_CONDITION

__all__ = [
    "EPS",
    "C_FLOOR",
    "vmax",
    "vmin",
    "vhypot",
    "largest",
    "two_lines",
    "plus",
    "turning",
    "line_rounding",
]

#: unit roundoff of IEEE double precision
EPS = 2.0**-53
#: the conditions are at least the refusal band's edge; never divide by less than this (nor
#: by a lever shorter than this fraction of the mechanism's size)
C_FLOOR = LEAST_CONDITION
#: a relative bound at or above this says nothing (the error may be the size of the largest
#: value of its kind): "no useful bound", null in the JSON
USELESS = 1.0
#: bounds saturate here, never overflow to inf (a long chain of steps that each multiply
#: the bound): far above :data:`USELESS`, far below the largest float
CAP = 1e100


def vmax(a, b):
    """The larger of two floats, or entry by entry of arrays."""
    if isinstance(a, float) and isinstance(b, float):
        return a if a >= b else b
    import numpy as np

    return np.maximum(a, b)


def vmin(a, b):
    """The smaller of two floats, or entry by entry of arrays."""
    if isinstance(a, float) and isinstance(b, float):
        return a if a <= b else b
    import numpy as np

    return np.minimum(a, b)


def vhypot(x, y):
    """|(x, y)| for floats or arrays."""
    if isinstance(x, float) and isinstance(y, float):
        return math.hypot(x, y)
    import numpy as np

    return np.hypot(x, y)


def largest(values):
    """The largest of floats, or entry by entry of arrays and floats (0.0 for none)."""
    if not values:
        return 0.0
    if all(isinstance(v, float) for v in values):
        return max(values)
    import numpy as np

    best = np.full(np.broadcast_shapes(*(np.shape(v) for v in values)), -np.inf)
    for v in values:
        np.maximum(best, v, out=best)
    return best


def two_lines(c, ratio, k, p_in, v_in, a_in, couple=None):
    """(eP, eV, eA, eW, eAl) of a step that intersects two direction lines at condition
    ``c`` (see the module): its omegas and alphas err as its velocities and accelerations.
    ``k``: its own rounding, or (for positions, velocities, accelerations) each relative
    to the step's own magnitudes (``walk.own``); ``couple``: how much a position error
    turns into a velocity and an acceleration error, and a velocity error into an
    acceleration error, from the step's own links (``walk.couple``), at most ``1, 1, R``."""
    kp, kv, ka = k if isinstance(k, tuple) else (k, k, k)
    cv, ca, cr = (1.0, 1.0, ratio) if couple is None else couple
    g = 1.0 / vmax(c, C_FLOOR)
    p = g * (kp + p_in)
    v = g * (kv + v_in + cv * p)
    a = g * (ka + a_in + ca * p + cr * v)
    return p, v, a, v, a


def plus(k, extra):
    """An own rounding ``k`` (one value, or one for each of positions, velocities and
    accelerations) with ``extra`` added to each."""
    if isinstance(k, tuple):
        return tuple(x + extra for x in k)
    return k + extra


def turning(walk, rx, ry, dv, da, p, v, a, k):
    """(eW, eAl) of a link found from two of its points ``r = (rx, ry)`` apart (m), whose
    relative velocity ``dv`` and acceleration ``da`` (m/s, m/s^2) are known, the two
    points' position, velocity and acceleration errors summing to ``p, v, a`` (relative
    to the sizes of their kinds): ``omega = r x dv / |r|^2`` errs by ``|d dv| / |r| +
    3 |dv| |dr| / |r|^2`` (and alpha likewise), so a short side of a large plate divides
    the errors of its ends by its own length, not by the plate's (``k``: own rounding)."""
    sz = walk.sizes
    n = vmax(vhypot(rx, ry), C_FLOOR * sz["position"])
    dr = p * sz["position"] / n  # the side's turn (rad) from its ends' position errors
    w = (v * sz["velocity"] + 3 * dv * dr) / n / sz["omega"]
    al = (a * sz["acceleration"] + 3 * da * dr) / n / sz["alpha"]
    return w + k, al + k


def line_rounding(K, qx, qy, x, y, position, angle=None):
    """The own rounding (relative to ``position``, the size of positions) of a step that
    places ``(x, y)`` on a fixed line through ``(qx, qy)``: ``X = Q + s u`` is rounded to
    the digits of ``|Q|`` and ``|XQ|`` (a line through a point far from the mechanism),
    and the line's direction, read from ``angle`` (rad; None: given as a unit vector), is
    off by its rounding ``du``, which moves the line by ``du |XQ|`` and turns the
    velocity and acceleration lines along it by ``du``."""
    du = 2 * EPS if angle is None else 4 * EPS * vmax(1.0, abs(angle))
    xq = vhypot(x - qx, y - qy)
    return (K * EPS * (vhypot(qx, qy) + xq) + du * xq) / position + du
