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

Dead centres of a slider crank (crank O A = r, rod A B = l, B on a straight path through
Q along unit u; B on the side ``s`` of A along u, +1 unless [assembly] says otherwise):
O, A and B are in line. At the inner dead centre the crank pin points at the piston and
the piston is farthest from the crank shaft, ``|OB| = l + r`` (A between O and B: the
books' "x = (l + r) - (l cos phi + r cos theta) from the i.d.c.", the project's
``worked_problems/engine_analytical.toml``; also "top dead centre", TDC); at the outer
dead centre it is nearest, ``|OB| = l - r`` (O between A and B; "bottom dead centre",
BDC). With F the foot of O on the path and ``e = |OF|`` (the offset),
``B = F + s sqrt(|OB|^2 - e^2) u``; the crank points along O->B at the inner dead centre
and the other way at the outer one: for a horizontal path below O (``e`` below) and the
piston on the right, ``theta_IDC = -asin(e / (l + r))`` and
``theta_ODC = 180 deg - asin(e / (l - r))``.

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
from ..common.tolerances import ROUNDING, SAME, TOL
from ..common.units import UNITS

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
    across = re.match(r"(perpendicular|normal|right angles|along|parallel)\b\s*(\S*)", text)
    if across:  # "perpendicular to CD": the link's direction is known once it is solved
        how = {"along": "along", "right angles": "at right angles to"}.get(across.group(1))
        link = across.group(2).upper() or "the link"
        raise SceneError(
            f"'{shown}': a direction {how or across.group(1) + ' to'} {link} turns with the "
            f"link and is not read; give its angle at this instant ({link}'s direction from "
            f"the solved positions, plus or minus 90 deg across it); {good}"
        )
    way = _WAY.fullmatch(text)
    if way:  # "down", "to the left": a way, the plain angle of its axis
        theta = math.radians(_WAY_DEG[way.group(1)])
        return BookAngle(theta, shown, f"'{shown}' = {_deg(theta)} deg from +x")
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

    def turned(ref, s):
        """``ref + s phi`` in (-pi, pi]; a reference in degrees (a float from the tables
        here) is turned in degrees where the size is, so that "60 deg right of the
        vertical" is exactly the plain 30 deg; a dead centre or a stroke is in rad."""
        if isinstance(ref, float) and in_deg:
            return _half_turn(ref + s * size, 180.0) * UNITS["angle"]["deg"]
        base = math.radians(ref) if isinstance(ref, float) else ref.rad
        return _half_turn(base + s * phi, math.pi)

    def done(ref, s, ref_words, slips=()):
        theta = turned(ref, s)
        note = f"'{shown}' = {_deg(theta)} deg from +x" + (f" ({ref_words})" if ref_words else "")
        return BookAngle(
            theta,
            shown,
            note,
            tuple(Slip(turned(r2, s2), code, words) for r2, s2, code, words in slips),
        )

    hv = re.fullmatch(r"(above|below) horizontal(?: (left|right))?", rest)
    if hv:
        up = hv.group(1) == "above"
        left = hv.group(2) == "left"
        ref, s = (180.0, -1 if up else 1) if left else (0.0, 1 if up else -1)
        return done(
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
    vv = re.fullmatch(r"(left|right) of (upward |downward )?vertical", rest)
    if vv:
        down = (vv.group(2) or "").strip() == "downward"
        right = vv.group(1) == "right"
        ref = 270.0 if down else 90.0
        s = (1 if right else -1) if down else (-1 if right else 1)
        h_ref, h_s = (0.0, 1 if not down else -1) if right else (180.0, -1 if not down else 1)
        return done(
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
            if keeps is None or keeps(turned(_Rad(ref), s)):
                found.append((ref, other))
        if len(found) != 1:
            raise SceneError(
                f"'{shown}': the slider's [assembly] position does not settle "
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
        if size != 0:
            slips.append(
                (
                    _Rad(ref),
                    -s,
                    "against_rotation",
                    "the angle measured from the "
                    "dead centre against the crank's rotation instead of with it",
                )
            )
        return done(_Rad(ref), s, ref_words, slips)
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
        if given is None and size != 0:
            raise SceneError(
                f"'{shown}' does not say to which side: add the sense, e.g. "
                f'"{_size(m)} from the line of stroke, ccw" (or cw)'
            )
        return done(_Rad(ref), given or 1, f"the line of stroke{named} is at {_deg(ref)} deg")
    if centres is not None and (target in _FRAME_WORDS or re.fullmatch(_PAIR, target)):
        ref, words = _centres_line(centres, target, shown)
        if given is None and size != 0:
            raise SceneError(
                f"'{shown}' does not say to which side: add the sense, e.g. "
                f'"{_size(m)} from {_line_words(target)}, ccw" (or cw)'
            )
        return done(_Rad(ref), given or 1, words)
    refs = {
        "horizontal": 0.0,
        "+x": 0.0,
        "x axis": 0.0,
        "positive x axis": 0.0,
        "vertical": 90.0,
        "upward vertical": 90.0,
        "downward vertical": 270.0,
    }
    if target not in refs:
        raise SceneError(f"cannot read '{shown}' as an angle (measured from what?): {good}")
    ref = refs[target]
    if given is None and size != 0:
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
    return done(ref, given or 1, "")


def _size(m) -> str:
    """The size as the scene wrote it: ``60 deg``."""
    return f"{m.group(1)} {m.group(2) or 'deg'}"


@dataclass(frozen=True)
class _Rad:
    """A reference direction in radians (a dead centre, a line of stroke)."""

    rad: float


def _half_turn(a, half):
    """``a`` turned by whole turns into (-half, half] (``half`` = 180 or pi).

    >>> _half_turn(330.0, 180.0), _half_turn(-180.0, 180.0), _half_turn(0.0, 180.0)
    (-30.0, 180.0, 0.0)
    """
    if -half < a <= half:
        return a + 0.0  # as it is, to the last bit (and never -0.0)
    d = (a + half) % (2 * half) - half
    return half if d == -half else d


def _deg(theta) -> str:
    """An angle (rad) in degrees for the notes, in (-180, 180]."""
    return f"{_half_turn(round(math.degrees(theta), 9), 180.0):g}"


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


def side_along(hint, u) -> int:
    """Which of the two slider positions (+1: the one farther along ``u``) an [assembly]
    hint word takes, as the compiler picks: the default (None) the one farther along the
    path; above/below/right/left the one on that side (+1 where the path has no such
    component: the compiler refuses the hint in its own words)."""
    if not isinstance(hint, str):
        return 1
    axis, want = {"above": (1, 1), "below": (1, -1), "right": (0, 1), "left": (0, -1)}.get(
        hint, (0, 0)
    )
    return -1 if u[axis] * want < -SAME else 1


def dead_centres(pivot, r, l, through, u, side, unit=("m", 1.0)) -> tuple:
    """(inner, outer) dead-centre crank angles (rad) of a slider crank: pivot O, crank r,
    rod l, path through ``through`` along unit ``u``, slider on ``side`` (+1 / -1) of the
    crank pin along u (lengths in m; ``unit`` (name, metres) for the messages). Raises
    :class:`SceneError` where the rod cannot reach.

    >>> i, o = dead_centres((0, 0), 1, 4, (0, 0), (1, 0), 1)   # in-line, path +x
    >>> round(math.degrees(i), 9), round(math.degrees(o), 9)
    (0.0, 180.0)
    """
    ox, oy = pivot
    qx, qy = through
    ux, uy = u
    t0 = (ox - qx) * ux + (oy - qy) * uy
    fx, fy = qx + t0 * ux, qy + t0 * uy  # the foot of O on the path
    e = math.hypot(ox - fx, oy - fy)
    name, k = unit
    out = []
    for reach, words in ((l + r, "inner"), (l - r, "outer")):
        if reach <= 0:
            raise SceneError(
                f"no {words} dead centre: the rod ({l / k:g} {name}) is not "
                f"longer than the crank ({r / k:g} {name})"
            )
        if reach < e * (1 + TOL.closure):
            raise SceneError(
                f"no {words} dead centre: the rod and crank in line reach "
                f"{reach / k:g} {name}, less than the line of stroke's offset "
                f"{e / k:g} {name} from the crank's pivot (the crank cannot turn "
                "a full turn)"
            )
        t = side * math.sqrt(reach * reach - e * e)
        bx, by = fx + t * ux - ox, fy + t * uy - oy
        ang = math.atan2(by, bx)
        out.append(ang + math.pi if words == "outer" else ang)
    return tuple(_half_turn(a, math.pi) for a in out)


def candidates(pivot, r, l, through, u, hint, unit=("m", 1.0)) -> list:
    """The dead centres of a slider crank as :func:`read_angle` takes them,
    ``[(inner, outer, keeps)]``: one candidate for the piston's side that an [assembly]
    word (or none) sets; for a rough position ``hint = (x, y)``, one per side, each with a
    test of the final crank angle: whether the position is nearer the piston on that side
    there (as the compiler picks it)."""
    if not isinstance(hint, tuple):
        return [(*dead_centres(pivot, r, l, through, u, side_along(hint, u), unit), None)]
    (ox, oy), (qx, qy), (ux, uy) = pivot, through, u

    def keeps(side):
        def test(theta):
            ax, ay = ox + r * math.cos(theta), oy + r * math.sin(theta)
            t = (ax - qx) * ux + (ay - qy) * uy
            fx, fy = qx + t * ux, qy + t * uy  # the foot of the crank pin on the path
            h2 = l * l - (ax - fx) ** 2 - (ay - fy) ** 2
            if h2 <= 0:
                return False
            h = math.sqrt(h2)
            ahead = math.dist((fx + h * ux, fy + h * uy), hint)
            behind = math.dist((fx - h * ux, fy - h * uy), hint)
            return (ahead < behind) == (side > 0)

        return test

    return [(*dead_centres(pivot, r, l, through, u, side, unit), keeps(side)) for side in (1, -1)]
