"""A scene's content as a key for what is cached outside the scene (its plan)."""

from __future__ import annotations

__all__ = ["ContentKey"]


class ContentKey:
    """A scene's content as a key for what is cached outside it (its plan): the tuple of
    its records, hashed once when the scene is made (a dict looks a key up by its hash:
    the records' own hashes are then not walked again at each look-up), equal to another
    key of the same content.

    >>> ContentKey((1, "a")) == ContentKey((1, "a")), ContentKey((1,)) == ContentKey((2,))
    (True, False)
    """

    __slots__ = ("parts", "_hash")

    def __init__(self, parts: tuple):
        self.parts = parts
        self._hash = hash(parts)  # a TypeError for anything unhashable

    def __hash__(self):
        return self._hash

    def __eq__(self, other):
        return self is other or (
            type(other) is ContentKey and self._hash == other._hash and self.parts == other.parts
        )
