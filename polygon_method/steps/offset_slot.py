"""An offset slot: the slot of a lever K-N whose centre line is parallel to the link's and e
to the left of K -> N (a slot cut in a bracket of the lever, missing its pivot). The block at
A is then ``A - K = t w + e perp(w)``, w the link's unit direction, so

    t = sigma sqrt(|KA|^2 - e^2),   w = (t d - e perp(d)) / |d|^2   (d = A - K)

and the slotted link's relations hold as written (``d.u = +-t``). Its condition is
min(1, |t| / rho): nought where the slot's line stands square to KA (the block at the foot
of the perpendicular from K, |KA| = |e|: a limit position, where both tangents from A meet).
Here: the position, and the words the slotted link says of such a slot.

>>> x, y, c = place_offset(0.0, 0.0, 0.3, 0.4, 1.0, 1.0, 0.3, 1.0)
>>> round(x, 12), round(y, 12), round(c, 12)   # t = 0.4: A - K = 0.4 w + 0.3 perp(w)
(0.96, 0.28, 0.4)
"""

from __future__ import annotations

from ..common.numbers import in_units

__all__ = ["place_offset", "slot_words", "out_of_reach", "image_words", "why"]


def place_offset(kx, ky, ax, ay, length, rho, e, sigma, ctx=None, step=None):
    """The free end N of a link whose slot, e to the left of its line K -> N, holds the block
    at A: ``N = K + L (t d - e perp(d)) / |d|^2``. Returns x, y and the condition."""
    dx, dy = ax - kx, ay - ky
    m2 = dx * dx + dy * dy
    disc = m2 - e * e
    if ctx is None:
        root = max(disc, 0.0) ** 0.5
    else:
        root = ctx.root(disc, e * e, step, lambda: out_of_reach(step, m2**0.5, e))
        m2 = ctx.safe(m2, step)
    t = sigma * root
    f = length / m2
    c = root / rho
    return (
        kx + f * (t * dx + e * dy),
        ky + f * (t * dy - e * dx),
        (ctx.minimum(c, 1.0) if ctx is not None else min(c, 1.0)),
    )


def _side(st) -> str:
    return "left" if st.offset > 0 else "right"


def slot_words(st) -> str:
    """The slot in words ("the slot of QB, 30 mm to the left of its line Q -> B")."""
    return (
        f"the slot of {st.guide}, {in_units(abs(st.offset), st.unit)} {st.uname} to the "
        f"{_side(st)} of its line {st.known} -> {st.new}"
    )


def out_of_reach(st, dist, e) -> str:
    """Why the slot cannot hold the block: it is nearer the pivot than the slot ever comes."""
    u, n = st.unit, st.uname
    return (
        f"cannot assemble {st.new}: block {st.point} is {in_units(dist, u)} {n} from "
        f"{st.known}, less than the slot's offset of {in_units(abs(e), u)} {n} (the slot of "
        f"{st.guide}, to the {_side(st)} of its line {st.known} -> {st.new}, never comes "
        f"nearer {st.known})"
    )


def image_words(st, k, n, c) -> str:
    """How the lever's far end n follows from k and c on a polygon: by its image triangle."""
    return (
        f"{n} completes the triangle {k}{c}{n} similar to {st.known}{st.point}{st.new} (the "
        f"lever's image: the slot, and so the lever's point under {st.point}, lie off the "
        f"line {st.known}{st.new})"
    )


def why(st, what, c=0.0, L=None) -> str:
    """The slotted link's words for an offset slot: ``what`` one of "singular", "warning",
    "limit", "column", "position" (``L`` the length writer)."""
    K, A, s = st.known, st.point, slot_words(st)
    if what == "singular":
        return (
            f"{s}, stands square to {K}{A} (condition {c:.2g}): the block is at the foot of "
            f"the perpendicular from {K}, a limit position where the lever's point under it "
            "moves along the slot"
        )
    if what == "warning":
        return f"{st.label}: {s}, is nearly square to {K}{A} (condition {c:.3g}): near a limit position"
    if what == "limit":
        return f"block {A} comes within the slot's offset of {K}: {s}, stands square to {K}{A}"
    if what == "column":
        return f"{A}'s distance along the slot from {K}'s foot / {st.ref or st.guide} (at most 1)"
    e = L(abs(st.offset))
    return (
        f"{st.new}: {s}, passes through the block at {A}: draw the circle of radius {e} about "
        f"{K} and from {A} the tangent to it (the slot's line); {K}{st.new} is parallel to "
        f"it, {e} to its {'right' if st.offset > 0 else 'left'}: mark {K}{st.new} = "
        f"{L(st.length)} on that line"
    )
