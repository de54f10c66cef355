"""Angles as books give them: "30 deg above the horizontal", "60 deg right of the
vertical", "45 deg from the line of stroke, ccw", "30 deg past the inner dead centre".

Every form comes down to a reference direction ``ref`` and a size ``phi`` measured from it
in a sense ``s`` (+1 counter-clockwise, -1 clockwise): ``theta = ref + s phi``, returned
in (-180, 180] deg, counter-clockwise from +x like a plain angle (so that 30 deg below the
horizontal is -30, drawn as a book draws it, 30 deg clockwise). The references:

==============================  ===============================================  =======
form                            reference and sense                              example
==============================  ===============================================  =======
``above the horizontal``        +x, ccw (``, left``: -x, cw)                     30 -> 30
``below the horizontal``        +x, cw (``, left``: -x, ccw)                     30 -> -30
``right of the vertical``       +y (upward), cw (``downward vertical``: -y, ccw) 60 -> 30
``left of the vertical``        +y (upward), ccw (``downward vertical``: -y, cw) 60 -> 150
``from the vertical, cw``       +y (upward) or -y (``downward``), the sense given 60 -> 30
``from the horizontal, ccw``    +x, the sense given                              30 -> 30
``from the line of stroke, cw`` the slider's path direction (``of D``: slider D) as given
``past the inner dead centre``  the crank at its inner (outer) dead centre, in the crank's
                                sense of rotation (``before``: against it); ``IDC``, ``ODC``
==============================  ===============================================  =======

"60 deg from the vertical" does not say on which side: it is refused, with the two
unambiguous forms. So is "30 deg from the horizontal" and, without a sense, "from the line
of stroke". A size of zero needs no side.

The slider crank's dead centres a book's angle may be measured from: :mod:`.dead_centres`.

>>> round(math.degrees(read_angle("30 deg below the horizontal", "path").value), 12)
-30.0
>>> read_angle("60 deg right of the vertical", "path").value == math.radians(30)
True
>>> read_angle("30 deg", "path") is None   # a plain angle: read as before
True
>>> read_angle("vertically downwards", "direction").value == -math.pi / 2
True
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from ..common.errors import SceneError
from ..common.tolerances import ROUNDING
from ..common.units import UNITS
from .angle_turns import _deg, _half_turn
from .dead_centres import candidates, dead_centres, side_along

__all__ = [
    "BookAngle",
    "Slip",
    "read_angle",
    "is_book_form",
    "dead_centres",
    "side_along",
    "candidates",
    "EXAMPLES",
]

_NUMBER = r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?"
_UNIT = r"deg|degrees|degree|°|rad"
_HEAD = re.compile(rf"^\s*({_NUMBER})\s*({_UNIT})?(?:\s+|(?<=°)|$)(.*)$")
_SENSE = {"cw": -1, "clockwise": -1, "ccw": 1, "acw": 1, "anticlockwise": 1, "counterclockwise": 1}
_SENSE.update({"c.w.": -1, "a.c.w.": 1, "c.c.w.": 1})  # older books' abbreviations
_SENSE_RE = "|".join(re.escape(s) for s in sorted(_SENSE, key=len, reverse=True))
#: words that make an angle a book's form (without them the plain reader reads it)
_BOOK_WORDS = re.compile(
    r"horizontal|vertical|dead|\b[iotb]dc\b|[iotb]\.d\.c|stroke|"
    r"\bfrom\b|\babove\b|\bbelow\b|\bleft\b|\bright\b|\bpast\b|\bbefore\b|"
    r"\bafter\b|\bbeyond\b|x\s*axis|\+x|\bup(wards?)?\b|\bdown(wards?)?\b|"
    r"line of cent(?:re|er)s?|fixed link|\bangle\s+[a-z]\w*\s*=|^\s*(?:at\s|θ|theta)|"
    r"^\s*(?:perpendicular|normal|at right angles|along|parallel)\b",
    re.IGNORECASE,
)
#: a way in words, without a size: "down" (vertically downwards, straight down, to the left)
_WAY = re.compile(r"(?:vertically |straight |horizontally )?(up|down|left|right)(?:wards?)?")
_WAY_DEG = {"right": 0.0, "up": 90.0, "left": 180.0, "down": -90.0}

#: good forms, for messages (by where the angle is)
EXAMPLES = {
    "angle": '"30 deg" (ccw from +x), "30 deg below the horizontal", "60 deg right of '
    'the vertical", "60 deg from the vertical, cw" or "30 deg past the inner '
    'dead centre"',
    "path": '"30 deg" (ccw from +x), "30 deg above the horizontal", "60 deg left of the '
    'vertical" or "60 deg from the vertical, ccw"',
    "direction": '"30 deg" (ccw from +x), "30 deg below the horizontal", "60 deg right of '
    'the vertical" or "0 deg from the line of stroke"',
}


@dataclass(frozen=True)
class Slip:
    """A classic misreading of a book's angle: the angle it gives (rad), a code and words."""

    value: float
    code: str
    text: str


@dataclass(frozen=True)
class BookAngle:
    """An angle read from a book's words: ``value`` (rad, ccw from +x, in (-pi, pi]), the
    scene's ``words`` as written (tidied), the ``note`` saying how they were read, and the
    ``slips`` a student reading them might make."""

    value: float
    words: str
    note: str
    slips: tuple = ()


def is_book_form(raw) -> bool:
    """Whether ``raw`` is an angle in a book's words (else the plain reader reads it)."""
    return isinstance(raw, str) and _BOOK_WORDS.search(raw) is not None


def _tidy(raw: str) -> str:
    text = raw.strip().lower()
    text = re.sub(r"cent(er|re)s?\b", "centre", text)
    text = re.sub(r"\b([iotb])\.\s*d\.\s*c\.?", r"\1dc", text)
    text = re.sub(
        r"\banti[-\s]\s*clockwise|\bcounter[-\s]\s*clockwise",
        lambda m: m.group(0).replace("-", "").replace(" ", ""),
        text,
    )
    text = re.sub(r"[,;()]", " ", text)
    # "angle BAD = 60 deg, ccw": a four-bar's angle at the crank's pivot A, from the frame's
    # AD (read_angle finds which end is the frame's)
    text = re.sub(
        rf"^angle\s+((?:[a-z][0-9]*){{3}})\s*=\s*({_NUMBER}\s*(?:{_UNIT})?)(.*)$",
        r"\2 from angle \1 \3",
        text,
    )
    # "theta2 = 30 deg", "θ = 30°" (a US book's crank angle): the plain angle that follows
    text = re.sub(r"^(?:θ|theta)\s*_?[0-9]*\s*=\s*", "", text)
    # "the crank makes 45 deg with ...", "crank OA is inclined at 30 deg to ...": the
    # crank is the subject of the book's sentence
    text = re.sub(
        r"^(?:the\s+)?(?:driving\s+)?crank(?:\s+[a-z][0-9]*-?[a-z][0-9]*)?\s+"
        r"(?=(?:makes|making|is|inclined|at)\b)",
        "",
        text,
    )
    # "makes an angle of 60 deg with the vertical", "inclined at 30 deg to the line of
    # stroke": the angle from that reference
    text = re.sub(r"^(?:(?:makes|making|is|inclined|at|an|angle|of)\s+)+", "", text)
    text = re.sub(
        r"\b(?:with|to)\s+(?=(?:the\s+)?(?:upward |downward )?"
        r"(?:vertical|horizontal|line of stroke|line of centres?))",
        "from ",
        text,
    )
    text = re.sub(r"\b(the|measured|to|on|is|at)\b", "", text)
    text = text.replace("x-axis", "x axis")
    return re.sub(r"\s+", " ", text).strip()


def read_angle(
    raw,
    where: str,
    *,
    dead=None,
    sense: float | None = None,
    strokes: dict | None = None,
    centres=None,
):
    """Read a book's angle; None where ``raw`` is a plain angle (``"30 deg"``, ``30``).

    ``where`` is "angle" (the crank's), "path" (a slider's) or "direction" (a load's).
    ``dead`` is a function giving the candidate dead centres, ``(inner, outer, keeps)``
    crank angles (rad) with None or a test of the final crank angle (whether the slider's
    [assembly] point keeps the side they were found for), or raising :class:`SceneError`
    with the reason there are none; ``sense`` the crank's sense of
    rotation (+1 ccw, -1 cw); ``strokes`` the fixed paths' directions (rad) by slider name;
    ``centres`` the crank's pivot and the ground points (name -> (x, y)), for an angle from
    the line of centres (a four-bar's "angle BAD = 60 deg": "60 deg from AD, ccw").
    Raises :class:`SceneError` (no key: the caller adds it) for an ambiguous or unreadable
    form, with examples of good ones.
    """
    if not is_book_form(raw):
        return None
    shown = raw.strip()
    good = f"write it as e.g. {EXAMPLES[where]}"
    text = _tidy(raw)
    _refuse_across(text, shown, good)
    way = _WAY.fullmatch(text)
    if way:  # "down", "to the left": a way, the plain angle of its axis
        theta = math.radians(_WAY_DEG[way.group(1)])
        return BookAngle(theta, shown, f"'{shown}' = {_deg(theta)} deg from +x")
    a, rest = _measured(raw, text, shown, good)
    hv = re.fullmatch(r"(above|below) horizontal(?: (left|right))?", rest)
    if hv:
        return _horizontal_side(a, hv)
    vv = re.fullmatch(r"(left|right) of (upward |downward )?vertical", rest)
    if vv:
        return _vertical_side(a, vv)
    fm = re.fullmatch(
        rf"(?:({_SENSE_RE}) )?(from|past|after|beyond|before) (.+?)"
        rf"(?: ({_SENSE_RE}))?",
        rest,
    )
    if not fm:
        raise SceneError(f"cannot read '{shown}' as an angle: {good}")
    s1, word, target, s2 = fm.groups()
    if s1 and s2:
        raise SceneError(f"'{shown}' gives two senses: give one, cw or ccw")
    given = _SENSE.get(s1 or s2 or "")
    target = target.strip()
    dc = re.fullmatch(
        r"(inner|outer|top|bottom|head[- ]?end|crank[- ]?end) dead centre|"
        r"(idc|odc|tdc|bdc)",
        target,
    )
    if word != "from" and not dc:
        raise SceneError(
            f"'{shown}': past/before go with a dead centre (\"30 deg past the "
            f'inner dead centre"); {good}'
        )
    if dc:
        if where != "angle":
            raise SceneError(
                f"'{shown}': a dead centre is a position of the crank; only "
                f"[input] angle may be measured from it; {good}"
            )
        return _from_dead_centre(a, dc, word, given, sense, dead)
    return _from_line(a, target, where, given, strokes, centres, good)


def _refuse_across(text, shown, good):
    """A direction across or along a link ("perpendicular to CD") turns with the link: it
    is refused, with what to give instead."""
    across = re.match(r"(perpendicular|normal|right angles|along|parallel)\b\s*(\S*)", text)
    if across:  # "perpendicular to CD": the link's direction is known once it is solved
        how = {"along": "along", "right angles": "at right angles to"}.get(across.group(1))
        link = across.group(2).upper() or "the link"
        raise SceneError(
            f"'{shown}': a direction {how or across.group(1) + ' to'} {link} turns with the "
            f"link and is not read; give its angle at this instant ({link}'s direction from "
            f"the solved positions, plus or minus 90 deg across it); {good}"
        )


class _Measured:
    """A book's angle whose size is read: ``phi`` (rad; ``size`` as written, in degrees
    where ``in_deg``), the words as written (``shown``) and the match of its size (``m``),
    turned from a reference in a sense into a :class:`BookAngle`."""

    __slots__ = ("shown", "m", "size", "in_deg", "phi")

    def __init__(self, shown, m, size, in_deg, phi):
        self.shown, self.m, self.size, self.in_deg, self.phi = shown, m, size, in_deg, phi

    def turned(self, ref, s):
        """``ref + s phi`` in (-pi, pi]; a reference in degrees (a float from the tables
        here) is turned in degrees where the size is, so that "60 deg right of the
        vertical" is exactly the plain 30 deg; a dead centre or a stroke is in rad."""
        if isinstance(ref, float) and self.in_deg:
            return _half_turn(ref + s * self.size, 180.0) * UNITS["angle"]["deg"]
        base = math.radians(ref) if isinstance(ref, float) else ref.rad
        return _half_turn(base + s * self.phi, math.pi)

    def done(self, ref, s, ref_words, slips=()):
        """The :class:`BookAngle` ``ref + s phi``, its note naming the reference's place
        (``ref_words``), with the slips ``(ref, s, code, words)`` a reader might make."""
        theta = self.turned(ref, s)
        shown = self.shown
        note = f"'{shown}' = {_deg(theta)} deg from +x" + (f" ({ref_words})" if ref_words else "")
        return BookAngle(
            theta,
            shown,
            note,
            tuple(Slip(self.turned(r2, s2), code, words) for r2, s2, code, words in slips),
        )


def _measured(raw, text, shown, good):
    """(the angle's size read, the words after it): a size not negative, at most a full
    turn; a plain "at 30 deg" (or with a sense only) measured from +x."""
    m = _HEAD.match(text)
    plain = m is not None and not m.group(3) and text != raw.strip().lower()
    if not m or not (m.group(3) or plain):
        raise SceneError(f"cannot read '{shown}' as an angle: {good}")
    size, unit, rest = float(m.group(1)), m.group(2) or "deg", (m.group(3) or "").strip()
    if plain or rest in _SENSE:  # "at 30 deg", "theta2 = 30 deg": from +x, ccw (or as said)
        rest = f"from +x {rest}"
    if not math.isfinite(size) or size < 0:
        raise SceneError(
            f"'{shown}': give the size of the angle (not negative) and the side "
            f"it is measured to; {good}"
        )
    in_deg = unit != "rad"
    phi = size * UNITS["angle"]["deg" if in_deg else "rad"]
    if phi > 2 * math.pi * (1 + ROUNDING):
        raise SceneError(f"'{shown}' is more than a full turn from its reference; {good}")
    return _Measured(shown, m, size, in_deg, phi), rest


def _horizontal_side(a, hv):
    """ "30 deg above (below) the horizontal" (", left": from -x)."""
    up = hv.group(1) == "above"
    left = hv.group(2) == "left"
    ref, s = (180.0, -1 if up else 1) if left else (0.0, 1 if up else -1)
    return a.done(
        ref,
        s,
        "",
        [
            (
                ref,
                -s,
                "above_below",
                "the angle taken "
                f"{'below' if up else 'above'} the horizontal instead of "
                f"{'above' if up else 'below'}",
            )
        ],
    )


def _vertical_side(a, vv):
    """ "60 deg right (left) of the vertical" (the upward one, or the downward)."""
    down = (vv.group(2) or "").strip() == "downward"
    right = vv.group(1) == "right"
    ref = 270.0 if down else 90.0
    s = (1 if right else -1) if down else (-1 if right else 1)
    h_ref, h_s = (0.0, 1 if not down else -1) if right else (180.0, -1 if not down else 1)
    return a.done(
        ref,
        s,
        "",
        [
            (
                h_ref,
                h_s,
                "from_horizontal",
                "the angle measured from the horizontal instead of the vertical",
            )
        ],
    )


def _from_dead_centre(a, dc, word, given, sense, dead):
    """ "30 deg past (before) the inner (outer) dead centre": from the crank at that dead
    centre, in the crank's sense of rotation (against it: before) unless a sense is said."""
    said = dc.group(1) or dc.group(2)[0]
    if said[0] in "hc" and said.endswith("end"):  # US books: the cylinder head's end
        said = "inner" if said[0] == "h" else "outer"  # is the inner, the crank's the outer
    inner = said in ("inner", "i", "top", "t")
    name = {"i": "inner", "o": "outer", "t": "top", "b": "bottom"}.get(said, said)
    turning = 1 if sense is None or sense > 0 else -1
    s = given if given is not None else turning
    if word == "before":
        s = -s
    found = []
    for idc, odc, keeps in dead():  # one candidate, or one per side of an [assembly] point
        ref, other = (idc, odc) if inner else (odc, idc)
        if keeps is None or keeps(a.turned(_Rad(ref), s)):
            found.append((ref, other))
    if len(found) != 1:
        raise SceneError(
            f"'{a.shown}': the slider's [assembly] position does not settle "
            "on which side of the crank pin the slider is at the dead centre; "
            "give it as left/right (above/below) instead of a point"
        )
    ((ref, other),) = found
    ref_words = (
        f"the {name} dead centre is at {_deg(ref)} deg, the crank turning "
        f"{'ccw' if turning > 0 else 'cw'}"
    )
    slips = [
        (
            _Rad(other),
            s,
            "other_dead_centre",
            f"the angle measured from the other dead centre instead of the {name}",
        )
    ]
    if a.size != 0:
        slips.append(
            (
                _Rad(ref),
                -s,
                "against_rotation",
                "the angle measured from the "
                "dead centre against the crank's rotation instead of with it",
            )
        )
    return a.done(_Rad(ref), s, ref_words, slips)


def _from_line(a, target, where, given, strokes, centres, good):
    """ "... from the line of stroke", "from the line of centres" (or "angle BAD"), "from the
    horizontal (vertical), cw": from that line, in the sense said (a size not nought
    needs one)."""
    shown, m = a.shown, a.m
    vertex = re.fullmatch(r"angle ([a-z][0-9]*)([a-z][0-9]*)([a-z][0-9]*)", target)
    if vertex:  # "angle BAD = 60 deg": from the frame's line AD through the crank's pivot A
        target = _frame_side(vertex.groups(), centres, shown, good)
    stroke = re.fullmatch(r"line of stroke(?: of ([a-z][0-9]*))?", target)
    if stroke:
        if where == "path":
            raise SceneError(
                f"'{shown}': a slider's path is a line of stroke; give its "
                f"direction as {EXAMPLES['path']}"
            )
        ref, named = _stroke(strokes or {}, (stroke.group(1) or "").upper(), shown)
        if given is None and a.size != 0:
            raise SceneError(
                f"'{shown}' does not say to which side: add the sense, e.g. "
                f'"{_size(m)} from the line of stroke, ccw" (or cw)'
            )
        return a.done(_Rad(ref), given or 1, f"the line of stroke{named} is at {_deg(ref)} deg")
    if centres is not None and (target in _FRAME_WORDS or re.fullmatch(_PAIR, target)):
        ref, words = _centres_line(centres, target, shown)
        if given is None and a.size != 0:
            raise SceneError(
                f"'{shown}' does not say to which side: add the sense, e.g. "
                f'"{_size(m)} from {_line_words(target)}, ccw" (or cw)'
            )
        return a.done(_Rad(ref), given or 1, words)
    if target not in _AXES:
        raise SceneError(f"cannot read '{shown}' as an angle (measured from what?): {good}")
    ref = _AXES[target]
    if given is None and a.size != 0:
        if "vertical" in target:
            which = "" if target == "vertical" else target.split()[0] + " "
            raise SceneError(
                f"'{shown}' does not say to which side of the vertical: write \"{_size(m)} "
                f'right of the {which}vertical" or "{_size(m)} left of the {which}vertical" '
                f'(or "{_size(m)} from the {which}vertical, cw")'
            )
        if target == "horizontal":
            raise SceneError(
                f"'{shown}' does not say to which side of the horizontal: write "
                f'"{_size(m)} above the horizontal" or "{_size(m)} below the '
                'horizontal" (add ", left" for the left-hand side)'
            )
    return a.done(ref, given or 1, "")


#: the axes an angle may be measured from, by name, and their direction (deg)
_AXES = {
    "horizontal": 0.0,
    "+x": 0.0,
    "x axis": 0.0,
    "positive x axis": 0.0,
    "vertical": 90.0,
    "upward vertical": 90.0,
    "downward vertical": 270.0,
}


def _size(m) -> str:
    """The size as the scene wrote it: ``60 deg``."""
    return f"{m.group(1)} {m.group(2) or 'deg'}"


@dataclass(frozen=True)
class _Rad:
    """A reference direction in radians (a dead centre, a line of stroke)."""

    rad: float


#: the frame's line in words, and a line named by two ground points ("AD", "O2O4", "O2-O4")
_FRAME_WORDS = ("line of centres", "line of centre", "fixed link", "frame")
_PAIR = r"(?:line )?([a-z][0-9]*)-?([a-z][0-9]*)"


def _line_words(target: str) -> str:
    """The line of centres as the scene names it: "the line of centres", "AD"."""
    if target in _FRAME_WORDS:
        return "the line of centres" if target.startswith("line") else f"the {target}"
    return target.upper()


def _frame_side(names3, centres, shown: str, good: str) -> str:
    """The frame's line ("ad") of a book's "angle BAD": its vertex the crank's pivot, one of
    its two other letters a ground point (the other is the crank's pin)."""
    if centres is None:
        raise SceneError(
            f"'{shown}': an angle at the crank's pivot is read for [input] only; {good}"
        )
    pivot, ground = centres
    names = {g.lower(): g for g in ground}
    first, vertex, last = names3
    if names.get(vertex) != pivot:
        raise SceneError(
            f"'{shown}': the angle's vertex {vertex.upper()} (its middle letter) is not the "
            f"crank's pivot {pivot}"
        )
    ends = [e for e in (first, last) if names.get(e) not in (None, pivot)]
    if len(ends) != 1:
        raise SceneError(
            f"'{shown}': one of {first.upper()} and {last.upper()} must be a ground point "
            f"(the frame's line from the crank's pivot {pivot}), the other the crank's pin"
        )
    return vertex + ends[0]


def _centres_line(centres, target: str, shown: str):
    """(direction rad, words) of the line of centres from the crank's pivot: to the frame's
    other point (of two), or along the named pair of ground points through the pivot."""
    pivot, ground = centres
    others = [g for g in ground if g != pivot]
    if target in _FRAME_WORDS:
        if len(others) != 1:
            raise SceneError(
                f"'{shown}': the frame has {len(ground)} points: name the line from the "
                f'crank\'s pivot, e.g. "... from {pivot}{others[0] if others else "D"}, ccw"'
            )
        (other,) = others
    else:
        pair = re.fullmatch(_PAIR, target)
        names = {g.lower(): g for g in ground}
        a, b = names.get(pair.group(1)), names.get(pair.group(2))
        if a is None or b is None or a == b or pivot not in (a, b):
            raise SceneError(
                f"'{shown}': {_line_words(target)} is no line of two ground points through the "
                f"crank's pivot {pivot}"
            )
        other = b if a == pivot else a
    (x0, y0), (x1, y1) = ground[pivot], ground[other]
    ref = math.atan2(y1 - y0, x1 - x0)
    return ref, f"the line of centres {pivot}{other} is at {_deg(ref)} deg"


def _stroke(strokes: dict, name: str, shown: str):
    """(direction rad, words) of the line of stroke: the only fixed path, or slider
    ``name``'s."""
    if name:
        if name not in strokes:
            raise SceneError(f"'{shown}': no slider {name} on a fixed path in [sliders]")
        return strokes[name], f" of {name}"
    if not strokes:
        raise SceneError(f"'{shown}': no line of stroke: the scene has no slider on a fixed path")
    if len(strokes) > 1:
        first = next(iter(strokes))
        raise SceneError(
            f"'{shown}': the scene has {len(strokes)} sliders on fixed paths; "
            f'name one: "... from the line of stroke of {first}, ccw"'
        )
    ((name, ang),) = strokes.items()
    return ang, ""
