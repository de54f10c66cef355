"""A large plan's one instant run with Python's cyclic garbage collector held off.

Each one-instant step function stores a few new tuples of floats in the solution's dicts.
Up to some 2,000 of them per solve come from the interpreter's free list of small tuples,
which the collector does not count; past that every new tuple counts towards its next
young collection (one per 700), and every tenth young collection sets off a middle one,
every tenth of those, when enough has piled up, a full one, which walks every live object
(the plan's own bound functions and the scene's records, in proportion to the chain's
length). A chain of 10,001 links set off some 16 young, 1.4 middle and 0.13 full
collections per solve, one of 1,001 links none: its cost per link grew by a tenth in time,
7 % in instructions (``benchmarks/instructions.py chain1001 chain10001``).

Holding the collector off while the steps run is safe: the collector exists for reference
cycles, and the steps make none (floats and tuples of floats stored in dicts the solution
owns; their temporaries freed by reference counting as each step returns). It loses
nothing, it only waits: the objects counted meanwhile are still counted, and the first
allocation after it is enabled again runs the young collection they are due (over what the
caller keeps; a cycle made meanwhile, say an exception's traceback, is collected then).
Memory grows meanwhile by no more than the solve's own motion. It is enabled again in a
``finally`` (an assembly that fails or a singular step included), and only where it was
enabled before: a program that runs with the collector off keeps it off. The one case it
does not cover is another thread disabling the collector during the solve itself (its
setting is then enabled again at the solve's end).
"""

from __future__ import annotations

from gc import disable, enable, isenabled

#: a plan of more one-instant functions than this runs them with the collector held off
#: (a textbook mechanism has a few dozen steps: held off, it would pay the two calls for
#: nothing, and its solve makes fewer new tuples than the free list keeps)
HELD_OFF_ABOVE = 200


def held_off(fns: tuple) -> tuple:
    """``fns`` as they are, or for a plan of more than :data:`HELD_OFF_ABOVE` of them,
    one function running them all in turn with the collector held off."""
    if len(fns) <= HELD_OFF_ABOVE:
        return fns

    def instant(m):
        if not isenabled():  # off already (the caller's choice): left off
            for f in fns:
                f(m)
            return
        disable()
        try:
            for f in fns:
                f(m)
        finally:
            enable()

    return (instant,)
