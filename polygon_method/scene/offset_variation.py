"""``[variants]`` of an offset slot's distance (a part of the ``[variants]`` reader,
:mod:`.variation`): ``A = { offset = [20, 25, 30] }`` for a block's, a yoke's or a peg's one
offset slot, ``P = { offset = { AB = [10, 15], CD = [5, 8] } }`` for each of a peg's slots
by its link. Sizes only, in the scene's units; the side is the scene's (each value written
with it, ``"25 left"``; its SI value signed to the left).
"""

from __future__ import annotations

__all__ = ["offset_sizes"]

_RANGE_KEYS = ("from", "to", "step", "unit")


def offset_sizes(reader, key, name, value, sliders, raw) -> list:
    """The varied offsets of point ``name``'s slot(s): one ``Varied`` each (``reader``: the
    scene reader, its ``_values`` and ``error``)."""
    at = [s for s in sliders if s.point == name and hasattr(s, "offset")]
    offs = [s for s in at if s.offset]
    by_link = isinstance(value, dict) and value and not set(value) <= set(_RANGE_KEYS)
    if not by_link:
        if len(offs) != 1:
            raise reader.error(
                f"the slot of {name} has no offset to vary (state it in [sliders]: offset = "
                '"30 mm left")'
                if not offs
                else f"{name} sits in two offset slots: name the slot's link, {name} = "
                f"{{ offset = {{ {offs[0].guide} = [10, 15] }} }}",
                "variants",
                name,
            )
        return [_one(reader, key, name, value, offs[0], raw, at.index(offs[0]))]
    out = []
    for link, v in value.items():
        s = next((s for s in at if link in (getattr(s, "guide", 0), getattr(s, "along", 0))), None)
        if s is None or not s.offset:
            raise reader.error(
                f"{key}: {link} is not a slot of {name} with an offset"
                + (
                    f" (its offset slots: {', '.join(t.guide for t in offs)})"
                    if offs and hasattr(offs[0], "guide")
                    else ""
                ),
                "variants",
                name,
            )
        out.append(_one(reader, f"{key}.{link}", name, v, s, raw, at.index(s)))
    return out


def _one(reader, key, name, value, s, raw, index):
    """One slot's varied offset: its place in the scene's table (a peg's list: ``index``,
    its slot's place in ``along``), the values with the scene's side."""
    from .variation import Varied

    written = raw["sliders"][name]["offset"]
    path = ("sliders", name, "offset")
    if isinstance(written, list):  # a peg's: its slot's place in the list
        path += (index,)
    side = "left" if s.offset > 0 else "right"
    what = f"yoke {s.yoke}" if hasattr(s, "yoke") else s.guide
    v = reader._values(
        key, value, "length", reader.unit, path, f"offset of the slot of {what}", table_key=name
    )
    return Varied(
        v.key,
        v.label,
        v.path,
        tuple(f"{x:g} {side}" if not isinstance(x, str) else f"{x} {side}" for x in v.values),
        tuple(f"{x} {side}" for x in v.shown),
        tuple(x if s.offset > 0 else -x for x in v.si),
        v.setup,
    )
