"""The engine chapter's equivalent dynamical system half done: a link replaced by two masses
at its pins (``m_A = m GB / l``, ``m_B = m GA / l``, statically equivalent) without the
correction couple, so that its moment of inertia about G is taken as ``m GA GB`` (G on the
line between the pins, ``GA = lam l``, ``GB = (1 - lam) l``) instead of ``m k^2``.

>>> from types import SimpleNamespace as S
>>> sc = S(link=lambda key: S(length=0.6))
>>> rod = S(body="AB", block=False, mu=0.0, lam=1 / 3, mass=40.0, inertia=1.6)
>>> round(two_masses(sc, [rod])["AB"], 12)  # 40 x 0.2 x 0.4
3.2
"""

from __future__ import annotations

from ..common.tolerances import SAME

#: the slip's words, for the diagnosis
WORDS = (
    "the rod replaced by two masses at its pins (m GB / l and m GA / l) without the "
    "correction couple: I taken as m GA GB, not m k^2"
)


def two_masses(sc, turning) -> dict:
    """body -> the moment of inertia the two masses give, for each massive link of
    ``turning`` whose G lies between its pins and whose own I differs from it."""
    two = {}
    for m in turning:
        if not m.block and m.mu == 0.0 and 0.0 < m.lam < 1.0:
            L = sc.link(m.body).length
            i2 = m.mass * m.lam * (1 - m.lam) * L * L
            if abs(m.inertia - i2) > SAME * m.inertia:
                two[m.body] = i2
    return two
