"""The mistake of a peg in two slots: a moving slot's Coriolis component left out.

A peg at P sits in slots i and j (unit directions u_i, u_j); its acceleration is ``aP =
aC_i + cor_i + as_i u_i = aC_j + cor_j + as_j u_j``. Drawn without ``cor_i`` (the line
parallel to slot i through the end of the point under the peg, not through the end of
the Coriolis component), the two lines meet elsewhere: with ``x u_i - y u_j = cor_i`` (a
2x2 solve) the peg's acceleration moves by ``y u_j`` and the sliding accelerations by ``x``
(slot i) and ``y`` (slot j).
"""

from __future__ import annotations

import math

from ..scene import GuideSlider

__all__ = ["coriolis_left_out"]


def _direction(sol, s):
    """The unit direction of a slider's guide: its fixed path, or its link first to second."""
    if not isinstance(s, GuideSlider):
        return s.u
    (x1, y1), (x2, y2) = sol.P[s.first], sol.P[s.second]
    n = math.hypot(x2 - x1, y2 - y1)
    return ((x2 - x1) / n, (y2 - y1) / n)


def coriolis_left_out(sol, kind, name) -> list:
    """(value, code, words) of an answer ``a_P`` or ``as_P_AB`` (``kind``, ``name`` as in
    ``[answers]``) where P is a peg in two slots drawn without one moving slot's Coriolis
    component; none for other answers."""
    sc = sol.scene
    sl = sc.slider(name)
    if sl is None or not sl.slot:
        return []
    X = sl.point
    slots = sc.slots(X)
    out = []
    for i, si in enumerate(slots):
        if not isinstance(si, GuideSlider):
            continue
        sj = slots[1 - i]
        ui, uj = _direction(sol, si), _direction(sol, sj)
        cx, cy = sol.coriolis(si.key)
        cross = ui[0] * uj[1] - ui[1] * uj[0]
        if (cx == 0 and cy == 0) or cross == 0:
            continue
        x = (cx * uj[1] - cy * uj[0]) / cross
        y = (cx * ui[1] - cy * ui[0]) / cross
        if kind == "a":
            ax, ay = sol.A[X]
            value = math.hypot(ax + y * uj[0], ay + y * uj[1])
        elif name == si.key:
            value = sol.S[si.key][1] + x
        else:
            value = sol.S[sj.key][1] + y
        out.append(
            (
                value,
                "coriolis_omitted",
                f"the Coriolis component in the slot of {si.guide} (2 omega_{si.guide} "
                f"vs_{si.key}) left out of the acceleration polygon of the peg {X}",
            )
        )
    return out
