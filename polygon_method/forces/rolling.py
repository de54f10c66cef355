"""The force step of a rolling wheel's own point (the plan's "rolling" step): none of its
own. On a fixed line the wheel's forces, with the ground's contact, are solved with the
link that finds its centre (:mod:`.wheel`); the wheel's point acts, for loads and later
pins, on the wheel.

On a circle or a gear the wheel's centre is held by a link (an arm, a frame): the contact's
normal force and the centre's pin force then share one direction the statics cannot split
(a preload, or the teeth's pressure angle, decides it). That is refused in one line, no
guess."""

from __future__ import annotations


def covers(st) -> bool:
    """A wheel on a fixed line (its centre's step solves its forces)."""
    return st.on == "line"


def check(st, plan):
    """Why the plan cannot be solved for forces with this step, or None: a wheel on a line
    whose centre no link finds (no group holds its contact)."""
    held = any(s is not st and st.centre in s.finds and getattr(s, "wheel", None) == st.wheel
               for s in plan.steps)
    return None if held else f"wheel {st.wheel} rolls on a line with its centre found by no link"


def owns(st) -> dict:
    return {st.rim: st.wheel}


def step(st, P, led, own):
    return (), (), None, None
