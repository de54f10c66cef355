"""``[turning_moment] cylinders``: a multi-cylinder engine whose book gives one cylinder's
turning moment (in readings, or by its strokes) and the number of cylinders firing at equal
intervals ("a three-cylinder engine, its cranks at 120 deg; the diagram of each cylinder a
triangle of 60 N m at 60 deg after its dead centre, the return stroke's torque
negligible"). The engine's diagram is the sum of the cylinder's, shifted by the cycle over
the number of cylinders: straight segments between the union of every copy's readings,
exact (a sum of straight segments is straight between their corners; a jump where any copy
jumps).

>>> from .energy_records import Table
>>> one = Table((0.0, 1.0, 3.0, 6.0), (0.0, 60.0, 0.0, 0.0))
>>> s = summed(one, 3, 6.0)
>>> [round(a, 9) for a in s.angles], [round(t, 9) for t in s.torques]
([0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0], [30.0, 60.0, 30.0, 60.0, 30.0, 60.0, 30.0])
"""

from __future__ import annotations

import math

from ..common.tolerances import ROUNDING
from .energy_records import Diagram, Table

__all__ = ["summed", "MAX_CYLINDERS"]

#: the most cylinders an engine's diagram may sum (a book's has up to a dozen)
MAX_CYLINDERS = 24


def _left(table, u) -> float:
    """The torque just before ``u`` (within the table's span; at its start, the value at
    its end: the cycle before)."""
    a, t = table.angles, table.torques
    if u <= a[0]:
        return t[-1]
    for i in range(len(a) - 1):
        if a[i] < u <= a[i + 1] and a[i + 1] > a[i]:
            return t[i] + (t[i + 1] - t[i]) * (u - a[i]) / (a[i + 1] - a[i])
    return t[-1]


def _right(table, u, cycle) -> float:
    """The torque just after ``u`` (at the cycle's end, the value at its start)."""
    if u >= cycle:
        u = 0.0
    return table.value(u)


def summed(table, n: int, cycle: float) -> Table:
    """The sum of ``n`` copies of ``table`` (its readings over [0, cycle]), copy k shifted
    by ``k cycle / n``: readings at the union of the copies' corners, two at a jump."""
    shift = cycle / n
    tol = ROUNDING * cycle
    xs = sorted({(a + k * shift) % cycle for a in table.angles for k in range(n)} | {0.0, cycle})
    pts = []
    for x in xs:  # (corners a rounding apart are one)
        if not pts or x - pts[-1] > tol:
            pts.append(x)
    pts[-1] = cycle
    angles, torques = [], []
    for x in pts:
        us = [(x - k * shift) % cycle for k in range(n)]
        us = [0.0 if u > cycle - tol or u < tol else u for u in us]
        left = math.fsum(_left(table, u) for u in us)
        right = math.fsum(_right(table, u, cycle) for u in us)
        if x > 0.0 and (x >= cycle or abs(left - right) > ROUNDING * (abs(left) + abs(right))):
            angles.append(x)
            torques.append(left)
        if x < cycle:
            angles.append(x)
            torques.append(right)
    return Table(tuple(angles), tuple(torques), f"{n} cylinders summed")


class _CylindersReader:
    """The reader's method for ``cylinders`` (mixed into the cycle reader)."""

    def _cylinders(self, spec, t, d) -> Diagram:
        """The diagram ``d`` of one cylinder summed over ``spec["cylinders"]``."""
        if "cylinders" not in spec:
            return d
        n = spec["cylinders"]
        if isinstance(n, bool) or not isinstance(n, int) or not 2 <= n <= MAX_CYLINDERS:
            raise self.err(
                f"cylinders = {n!r}: a whole number of cylinders, 2 to {MAX_CYLINDERS}, firing "
                "at equal intervals",
                t,
                "cylinders",
            )
        if not isinstance(d.driving, Table):
            raise self.err(
                "cylinders: one cylinder's readings (angle = [...]) or strokes are summed; a "
                "law sums its cylinders as a list of laws, and areas are the engine's own",
                t,
                "cylinders",
            )
        words = d.words[:-1] + (
            f"{n} cylinders, each this turning moment, firing {math.degrees(d.cycle) / n:g} "
            f"deg apart (the cycle over {n}), summed",
            d.words[-1],
        )
        return Diagram(
            d.form,
            d.cycle,
            driving=summed(d.driving, n, d.cycle),
            resisting=d.resisting,
            at=d.at,
            words=words,
        )
