"""The tolerance policy of the whole tool, in one place: each tolerance named, with what it
protects. A literal tolerance elsewhere in the code is a bug waiting; name it here.

:class:`Tolerances` (``TOL``) holds the policy a user meets: when a step is singular or
ill-conditioned, when a circle touches, which transmission angle is poor, what is rounding
noise in a report. The constants below are the slack of the tool's own arithmetic.

>>> crossing_angle(0.5), crossing_angle(1.0000000000000002)
(30.000000000000004, 90.0)
>>> same(1.0, 1.0 + 1e-12), same(1.0, 1.0 + 1e-6)
(True, False)
"""

from __future__ import annotations

import math

__all__ = [
    "Tolerances",
    "TOL",
    "SAME",
    "ROUNDING",
    "FLOOR",
    "LEAST_REACH",
    "ULP",
    "DISTINCT",
    "ON_PAPER",
    "PLOTTED_ZERO",
    "EXTREME_RESOLVED",
    "ZERO_RESOLVED",
    "REFINED",
    "AT_LIMIT",
    "SMOOTH",
    "CONVERGED",
    "LEAST_STEP",
    "ONE_ASSEMBLY",
    "PAGE",
    "same",
    "crossing_angle",
]

#: the tool's promise: every answer agrees with an independent reference to this fraction of
#: its size, so two lengths, places or directions that agree to it are the same (a point on
#: a line, a centre distance that is the sum of the radii, a drawn label on its spot): a
#: finer difference is not one the answers can resolve
SAME = 1e-9
#: a few units in the last place gathered by a handful of operations: the slack with which a
#: computed value is held to a limit it may reach exactly (a stroke's ends, a crank that just
#: turns fully, a full turn of 2 pi, a scale that is exactly round)
ROUNDING = 1e-12
#: a cycle's mean (a turning moment's over its cycle: its work over the cycle's angle) at most
#: this fraction of the diagram's largest value is rounding about a true nought (the
#: quadrature's many products; a steady gas pressure does no net work over a cycle): it is
#: written 0, not -9e-15 N m
MEAN_NOUGHT = ROUNDING
#: a floor for a divisor or a norm that may be exactly zero, far below any real size: the
#: quotient comes out large and finite, never a ZeroDivisionError, an inf or a NaN
FLOOR = 1e-300
#: a step's least reach (m): the size its tolerances scale with never drops to zero, even
#: for a link of no length (refused elsewhere, but the scale must not divide by zero first)
LEAST_REACH = 1e-9

# ----------------------------------------------------------------- near nothing, on the page
#: a few units in the last place of a number of size one (a unit vector's component): below
#: it the component is zero, and a line along it is parallel to that axis
ULP = 1e-15
#: a difference that must be plain to count: a slip whose value is the right one to this
#: fraction is no slip, a plotted curve that varies less is drawn flat, a parallelogram whose
#: links are parallel to it is not crossed, a point this far (cm) off a drawn line is off it
DISTINCT = 1e-6
#: a length on a drawing (cm on the sketch, pixels on a picture) or an angle drawn (rad)
#: below which it is nothing, and the slack with which a drawn place is held to a limit (a
#: tick at the end of an axis, a sheet that just fits the paper): a million times finer
#: than a pen's 0.01 cm, far above the drawing's rounding
ON_PAPER = 1e-9
#: a plotted quantity whose every value is below this fraction of its unit's size is nought
#: (drawn as a flat line about 0, not as magnified rounding noise)
PLOTTED_ZERO = 1e-8

# ----------------------------------------------------------------- refining over a cycle
#: the bracket (rad of the crank) at which an extreme's refinement stops: the angle is then
#: known to its last few digits
EXTREME_RESOLVED = 1e-13
#: the bracket (rad of the crank) at which a zero crossing's refinement stops
ZERO_RESOLVED = 1e-14
#: a sweep's extremes are refined to about this (rad of the crank, or of the parameter's
#: radian): the zooming passes are as many as that takes from the sample spacing
REFINED = 1e-11
#: the offset (rad, or of the parameter's radian) inside a limit position at which a
#: quantity is compared with its value at the limit (at one and at two offsets)
AT_LIMIT = 1e-9
#: a quantity whose values :data:`AT_LIMIT` inside a limit position agree with its value
#: at the limit to this fraction of its kind is finite and smooth there (it is then taken as
#: an extreme at the limit; one that does not may grow without bound)
SMOOTH = 1e-7

# ----------------------------------------------------------------- the triad's loop solve
#: Newton's residual (|Fi| / 2 li, relative to the largest length) taken as converged
CONVERGED = 1e-13
#: continuation halves its step along the crank's angle (a fraction of the whole step) and
#: gives up below this: the assembly cannot be followed there
LEAST_STEP = 1e-7
#: two assemblies of a triad whose vertices are closer than this fraction of its size, and
#: whose plate angles closer than this (rad), are one
ONE_ASSEMBLY = 1e-7


def same(a: float, b: float, rel: float = SAME) -> bool:
    """Whether ``a`` and ``b`` agree to ``rel`` of the larger (:data:`SAME`: the promise)."""
    return abs(a - b) <= rel * max(abs(a), abs(b), FLOOR)


def crossing_angle(condition: float) -> float:
    """The angle (deg, acute) at which two direction lines cross, from a step's condition
    measure (the sine of that angle): at a dyad or a slider, its transmission angle. A
    condition a hair above 1 by rounding is 90 deg. Floats or arrays (a sweep's)."""
    if isinstance(condition, (float, int)):
        return math.degrees(math.asin(min(max(condition, -1.0), 1.0)))
    import numpy as np  # a sweep's conditions

    return np.degrees(np.arcsin(np.clip(condition, -1.0, 1.0)))


class Tolerances:
    """The single tolerance policy of the tool.

    Attributes
    ----------
    singular : float
        A step whose condition measure (the sine of the angle between its two direction
        lines) is below this is singular: an error, never a number. 1e-3 is about 0.06 deg
        from a toggle, change point or dead centre: closer than that, rounding alone (which
        moves a circle intersection by about eps L / c, and the acceleration polygon by
        that over c^2 more) would put errors above 1e-6 of their size into the answers.
    warn : float
        Below this (sin 5 deg) the step is ill-conditioned: the answer is printed with a
        warning naming the step. A drawing error of 0.25 deg then moves the intersection
        by more than 3 %.
    closure : float
        Relative slack (of the lengths involved) within which a circle that just touches
        another circle or line counts as touching rather than missing.
    transmission_warn_deg : float
        The lecture's advice: keep the transmission angle above 40 deg.
    negligible : float
        A value smaller than this fraction of the largest of its kind in the same solution
        (a coupler that translates: omega 3e-13 beside 10 rad/s) is rounding noise: reports
        and step tables show it as 0 with no sense; the JSON keeps the raw number.
    """

    singular = 1e-3
    warn = 0.08715574274765817  # sin(5 deg)
    closure = 1e-12
    transmission_warn_deg = 40.0
    negligible = 1e-10


TOL = Tolerances()


#: the names the browser page's script takes its tolerances by (sent in the page's data, so
#: that the script holds no literal of its own)
PAGE = {"same": SAME, "rounding": ROUNDING, "floor": FLOOR}


# ----------------------------------------------------------------- a scene's least sizes
#: the least coefficient of fluctuation of speed (or +- range about the mean) a scene may ask
#: of a flywheel: a greatest and a least speed closer than this fraction are no plain
#: difference (:data:`DISTINCT`), and the flywheel that would hold them, the energy over
#: ``Cs w^2``, grows without a size a book would print
LEAST_FLUCTUATION = DISTINCT
#: a driving block's least speed (m/s) other than nought (a crank's is ``TINY``'s): below it
#: the block's driving force, its power over its speed, overflows; nought is a block at rest
LEAST_BLOCK_SPEED = 1e-12

__all__ += ["LEAST_FLUCTUATION", "LEAST_BLOCK_SPEED"]
