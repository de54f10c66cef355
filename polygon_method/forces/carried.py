"""A point carried on a link needs no force step: its loads and the pins of the links
found from it act on the link that carries it."""

from __future__ import annotations


def bodies(st) -> tuple:
    """A carried point moves no body of its own: its link's."""
    return (st.link,)


def owns(st) -> dict:
    """A carried point belongs to its link: the forces at it act on that link."""
    return {st.point: st.link}


def bind(st, own, ix):
    return None  # nothing to solve: no call on the short road


def step(st, P, led, own):
    """A carried point adds no unknown force: nothing to solve, nothing to record."""
    return (), (), None, None
