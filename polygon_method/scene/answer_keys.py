"""The ``[answers]`` table's keys (a part of the answers' reader, :mod:`.answers`): the
answer kinds each key prefix names, the engine chapter's and the drivers' keys, the names
of a moving guide's point under a block."""

from __future__ import annotations

from .records import ANSWER_KINDS

__all__ = [
    "DRIVER_ANSWERS",
    "ENGINE_ANSWERS",
    "ENGINE_PER_PISTON",
    "PAIR_ANSWER_KINDS",
    "under_block_names",
]

#: the engine chapter's answer keys -> their unit kind (checked in check/engine.py)
ENGINE_ANSWERS = {
    "piston_effort": "force",
    "crank_effort": "force",
    "turning_moment": "torque",
    "T_mean": "torque",
    "dE_max": "energy",
    "I_flywheel": "moment_of_inertia",
    "m_flywheel": "mass",
    "rod_thrust": "force",
    "side_thrust": "force",
    "shaking_force": "force",
    "shaking_moment": "torque",
    # the connecting rod's equivalent dynamical system (linkage/rod_system.py)
    "m_small_end": "mass",
    "m_L": "mass",
    "l_GL": "length",
    "correction_couple": "torque",
    "correction_torque": "torque",
}


#: the keys each cylinder of several on one crank has, its piston after them
#: (``piston_effort_B``, as the sweep's columns name them)
ENGINE_PER_PISTON = (
    "piston_effort",
    "crank_effort",
    "turning_moment",
    "rod_thrust",
    "side_thrust",
    "m_small_end",
    "m_L",
    "l_GL",
    "correction_couple",
    "correction_torque",
)


def under_block_names(point_names, ground, sliders) -> dict:
    """Answer name -> slider key, for the point of a moving guide that lies under a block:
    ``A1`` for the block at A (its image is a1 on the velocity polygon, a1' on the
    acceleration polygon), ``A2`` where the scene has a point A1 of its own; for a peg in
    two moving slots, ``P1`` and ``P2`` in the order of its slots (a fixed slot has none:
    its point is the pole). The names follow the polygons' letters.

    >>> from types import SimpleNamespace as S
    >>> under_block_names(["O2", "A", "O4", "P"], {"O2": 0, "O4": 0},
    ...                   [S(point="A", key="A", guide="O4-P")])
    {'A1': 'A'}
    """
    lower = {p.lower() for p in point_names}
    taken = set(lower)
    if "O" in point_names and "O" not in ground:  # a moving O's image is o1 (or o2 ...)
        k = 1
        while f"o{k}" in lower:
            k += 1
        taken.add(f"o{k}")
    out, used = {}, set()
    for s in sliders:
        if not getattr(s, "guide", None):
            continue
        k = 1
        while f"{s.point.lower()}{k}" in taken | used:
            k += 1
        used.add(f"{s.point.lower()}{k}")
        out[f"{s.point}{k}"] = s.key
    return out


#: the answer kinds of two points of one link, as ``ANSWER_KINDS``: the least speed of a
#: point between them (``vmin_BC``), the radial and tangential components of one's
#: acceleration relative to the other (``ar_CB``, ``at_CB``; ``motion/link_points.py``)
PAIR_ANSWER_KINDS = {
    "vmin": ("velocity", "pair", False),
    "ar": ("acceleration", "pair", False),
    "at": ("acceleration", "pair", False),
}
_KINDS = {**ANSWER_KINDS, **PAIR_ANSWER_KINDS}

#: the drivers' efforts other than the crank's torque: a driving block's, collar's or
#: cylinder's force along its guide (``force``), a second input's torque or force
DRIVER_ANSWERS = {"force": "force", "torque2": "torque", "force2": "force"}
