"""A sheet's heading (the scene's title) on the sheets drawn as one matplotlib figure (a
turning-moment diagram's, an engine's cycle): wrapped to the sheet's width as the force
panels' words are, measured as drawn (:func:`~polygon_method.draw.sketch._text_size`) and
broken after a comma or a semicolon where one is near enough, else at a space; smaller
type where it would need more lines than the room above the plots holds. A long title ran
off both edges of the A4 sheet."""

from __future__ import annotations

import re

from .paper import MARGIN
from .sketch import _text_size
from .style import PT_PER_CM

__all__ = ["heading", "wrap_words"]

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
