"""A sheet's heading (the scene's title) on the sheets drawn as one matplotlib figure (a
turning-moment diagram's, an engine's cycle): wrapped to the sheet's width as the force
panels' words are, measured as drawn (:func:`~polygon_method.draw.sketch._text_size`) and
broken after a comma or a semicolon where one is near enough, else at a space; smaller
type where it would need more lines than the room above the plots holds. A long title ran
off both edges of the A4 sheet."""

from __future__ import annotations

import re

from ..text.energy import book_number as _g
from .paper import FOOTER, MARGIN
from .sketch import _text_size
from .style import PT_PER_CM, SMALL_PT

__all__ = ["heading", "wrap_words", "flywheel_line", "foot"]

#: the least size (pt) a heading is set in to fit the room above the plots
LEAST_PT = 8.0
#: a line's height as a multiple of its type's size (matplotlib's line spacing, 1.2)
LEADING = 1.2


def wrap_words(text: str, size: float, room: float) -> list:
    """``text`` in lines no wider than ``room`` cm at ``size`` pt: whole clauses (after a
    comma or a semicolon) where they fit, else word by word; a word wider than the room
    alone on its line.

    >>> wrap_words("a short title", 11, 19.0)
    ['a short title']
    """
    out, cur = [], ""
    for part in re.split(r"(?<=[,;]) ", text.strip()):
        for word in [part] if _text_size(part, size)[0] <= room else part.split(" "):
            more = f"{cur} {word}" if cur else word
            if cur and _text_size(more, size)[0] > room:
                out.append(cur)
                cur = word
            else:
                cur = more
    return out + ([cur] if cur else [])


def heading(fig, text: str, sheet: tuple, size: float, top: float, base: float = 0.95):
    """The heading ``text`` on ``fig`` (a sheet of ``sheet`` = (width, height) cm),
    centred: one line at ``base`` (a fraction of the height) as ever; more, wrapped within
    the sheet's margins, hung from its top margin above ``top`` (the plots' top, a
    fraction of the height), in smaller type down to :data:`LEAST_PT` if they need it."""
    w, h = sheet
    lines = wrap_words(text, size, w - 2 * MARGIN)
    if len(lines) == 1:
        return fig.text(0.5, base, text, ha="center", fontsize=size, parse_math=False)
    room = (1.0 - top) * h - 2 * MARGIN  # cm between the top margin and the plots (less a gap)
    while size > LEAST_PT and len(lines) * size * LEADING / PT_PER_CM > room:
        size -= 0.5
        lines = wrap_words(text, size, w - 2 * MARGIN)
    return fig.text(
        0.5,
        1.0 - MARGIN / h,
        "\n".join(lines),
        ha="center",
        va="top",
        fontsize=size,
        linespacing=LEADING,
        parse_math=False,
    )


def flywheel_line(dE_max, inertia=None, cs=None, omega=None, mass=None) -> str:
    """The answers under a turning-moment diagram's plots as a book prints them, whatever
    ``solve`` spells in ASCII (``dE_max``, ``kg m^2``, ``Cs``, ``w``).

    >>> flywheel_line(1125.0, 0.5702, 0.02, 314.2, 25.34)
    'ΔEₘₐₓ = 1125 J;  I = 0.5702 kg m² (Cₛ = 0.02, ω = 314.2 rad/s);  m = 25.34 kg'
    """
    out = f"ΔEₘₐₓ = {_g(dE_max)} J"
    if inertia is not None:
        out += f";  I = {_g(inertia)} kg m² (Cₛ = {_g(cs)}, ω = {_g(omega)} rad/s)"
    if mass is not None:
        out += f";  m = {_g(mass)} kg"
    return out


def foot(fig, sheet: tuple, paper: str, answers: str) -> None:
    """The foot of a sheet of ``sheet`` = (width, height) cm drawn as one figure: the
    ``answers`` centred above the line naming the ``paper`` (as every sheet of ``draw``
    names it, at the same place: its plots are not to a scale, its page is the paper's)."""
    w, h = sheet
    base = MARGIN + FOOTER + 0.1  # cm: the answers' baseline, over the paper's line
    fig.text(0.5, base / h, answers, ha="center", fontsize=10, parse_math=False)
    fig.text(
        MARGIN / w,
        (MARGIN + FOOTER / 2) / h,
        f"{paper} portrait ({w:g} x {h:g} cm)",
        fontsize=SMALL_PT,
        ha="left",
        va="center",
        parse_math=False,
    )
