"""What a scene may say: its names and keys (a part of the scene's records).

Names: a point is a capital letter with optional digits (``B``, ``O2``); a link is named
by its two points (``BC``, ``"O2-A"``), in either order. The tables a scene has, the keys of
[input], the kinds of answer a key names, and a fixed path's words.
"""

from __future__ import annotations

import re

POINT_NAME = re.compile(r"[A-Z][0-9]*")
_POINT_ONLY = re.compile(r"^[A-Z][0-9]*\Z")  # \Z: "A\n" is no point name
_LINK_NAME = re.compile(r"^(?:[A-Z][0-9]*-?)+\Z")

_UNIT_ORDER = ("mm", "cm", "m", "in", "ft")

TOP_KEYS = (
    "title",
    "source",
    "notes",
    "units",
    "ground",
    "links",
    "points",
    "sliders",
    "cylinders",
    "rolling",
    "assembly",
    "input",
    "pins",
    "loads",
    "answers",
    "variants",
    "variant",
    "masses",
    "gravity",
    "indicator",
    "flywheel",
    "friction",
)
INPUT_KEYS = ("crank", "angle", "speed", "acceleration")
#: the kinds of quantity on which [input] may give the motion instead of the crank's speed
#: (named as answer keys: ``omega_BC``, ``vs_B``, ``v_B``), with their rate's prefix
GIVEN_KINDS = {"omega": "alpha", "vs": "as", "v": "a"}

#: answer key prefix -> (unit kind, what it names, sense allowed)
ANSWER_KINDS = {
    "v": ("velocity", "point", False),
    "a": ("acceleration", "point", False),
    "omega": ("angular_velocity", "link", True),
    "alpha": ("angular_acceleration", "link", True),
    "vs": ("velocity", "slider", True),
    "as": ("acceleration", "slider", True),
    "ac": ("acceleration", "slider", False),
    "rub": ("velocity", "pin", False),
    "vI": ("velocity", "wheel", False),
    "aI": ("acceleration", "wheel", False),
    # the force analysis (a scene with [masses] or [gravity]): the size of the force at a
    # pin joining two bodies, of a guide's normal force on its block
    "F": ("force", "pin_force", False),
    "N": ("force", "guide", False),
    # a body's inertia (link L, or the block at X): the size of its force -m a_G, its
    # couple -I alpha (ccw positive, or a sense), the offset h of the book's single force
    "Fi": ("force", "body", False),
    "Ci": ("torque", "body", True),
    "h": ("length", "body", False),
    "Fc": ("force", "contact", False),  # rolling wheel L's contact force (a rack: its point)
    "Tmax": ("torque", "drive", False),  # a friction drive's largest torque on L, mu N r
    "Pmax": ("power", "drive", False),  # and the largest power through its grip, mu N v
    # the torque the frame holds a fixed circle (an epicyclic's fixed sun or annulus) with,
    # about its centre O (Thold_O: ccw positive, or a sense)
    "Thold": ("torque", "held", True),
}
#: the answer kinds of the guide's point under a block (``v_A1``, ``a_A1``: its image a1)
UNDER_BLOCK_KINDS = {"v": "vu", "a": "au"}


def guide_words(label: str, noun: str = "path", of: str | None = None) -> str:
    """A fixed path's (or slot's) words from its label, as a teacher writes them:
    "horizontal path", "vertical slot", "path at 30 deg" (never "the at 30 deg path");
    with ``of``, whose: "horizontal path of D", "slot of yoke Y (at 70 deg)".

    >>> guide_words("horizontal"), guide_words("at 30 deg"), guide_words("at 70 deg", "slot")
    ('horizontal path', 'path at 30 deg', 'slot at 70 deg')
    >>> guide_words("at 30 deg", of="D"), guide_words("vertical", "slot", "yoke Y")
    ('path of D (at 30 deg)', 'vertical slot of yoke Y')
    """
    if of is None:
        return f"{noun} {label}" if label.startswith("at ") else f"{label} {noun}"
    return f"{noun} of {of} ({label})" if label.startswith("at ") else f"{label} {noun} of {of}"


def split_name(name: str) -> tuple[str, ...]:
    """Point names in a link or relative name: ``"BC"`` -> (B, C), ``"O2-A"`` -> (O2, A).

    >>> split_name("BC"), split_name("O2-A"), split_name("O2A"), split_name("Bc")
    (('B', 'C'), ('O2', 'A'), ('O2', 'A'), ())
    """
    if (
        isinstance(name, str)
        and len(name) == 2
        and name.isascii()
        and name.isalpha()
        and name.isupper()
    ):  # the usual name, two capitals: read at once
        return (name[0], name[1])
    if not isinstance(name, str) or not _LINK_NAME.match(name) or name.endswith("-"):
        return ()
    return tuple(POINT_NAME.findall(name))
