"""Sheets of paper: the diagrams' panels (each at its own true scale) laid out on A4, A3 or
US letter, portrait or landscape, on as few pages as hold them; never shrunk, never cut off.

A panel is a rectangle of so many centimetres (a diagram with its header, at its scale).
The panels of a sheet keep their order (configuration, velocity, acceleration) and are
arranged side by side, stacked, or one beside the other two stacked (every arrangement
that cuts the sheet straight across, in order). Where the three do not fit one page in any
arrangement either way round, they go on two pages (the first two together, or the last
two), else one a page.

>>> [p.text for p in paginate([(9.0, 10.0), (9.0, 11.0), (8.0, 13.5)], "A4")]
['A4 landscape']
>>> [p.text for p in paginate([(18.0, 15.0), (12.0, 14.0), (8.0, 13.5)], "A4")]
['A4 portrait', 'A4 landscape']
>>> paginate([(30.0, 10.0)], "A4")
Traceback (most recent call last):
...
polygon_method.common.errors.PolygonMethodError: --paper: panel 1 is 30 x 10 cm: more than A4 holds inside its margins (19.8 x 28 cm, either way round)
"""

from __future__ import annotations

from bisect import bisect_right
from dataclasses import dataclass
from itertools import permutations

from ..common.tolerances import ON_PAPER
from ..common.errors import PolygonMethodError

__all__ = [
    "PAPERS",
    "PAPER_NAMES",
    "FOOTER",
    "Page",
    "paper_size",
    "paper_name",
    "paginate",
    "fill",
    "room",
    "fits",
    "page_files",
]

#: paper sizes (cm, portrait): ISO A4 and A3, US letter (8.5 x 11 in)
PAPERS = {"A4": (21.0, 29.7), "A3": (29.7, 42.0), "letter": (21.59, 27.94)}
PAPER_NAMES = tuple(PAPERS)
#: the strip at the foot of each page (cm) for the line that names the paper
FOOTER = 0.5
#: the paper's margin all round and the gap between two panels (cm); each panel has 2 mm
#: of its own round its drawing (:data:`~polygon_method.draw.sheet.PANEL_PAD`), so a
#: drawing is 8 mm from the paper's edge at least (printers leave 4 to 6 mm blank) and 7 mm
#: from the next (they were 9 mm and 1 cm: 13 more of the 237 worked and textbook sheets
#: now fit one A4 page)
MARGIN, GAP = 0.6, 0.3


def paper_size(name: str) -> tuple:
    """(width, height) in cm of the paper ``name`` (portrait), case as a user writes it
    (``a4``, ``Letter``)."""
    for key, size in PAPERS.items():
        if str(name).strip().lower() == key.lower():
            return size
    raise PolygonMethodError(f"unknown paper {name!r}; use A4, A3 or letter", key="--paper")


def paper_name(name: str) -> str:
    """The paper's name as this module writes it (``a4`` -> ``A4``, ``LETTER`` ->
    ``letter``)."""
    paper_size(name)
    return next(k for k in PAPERS if k.lower() == str(name).strip().lower())


def room(paper: str, orientation: str) -> tuple:
    """(width, height) in cm a page leaves for panels: the paper less a margin all round
    and the footer."""
    w, h = paper_size(paper)
    if orientation == "landscape":
        w, h = h, w
    return w - 2 * MARGIN, h - 2 * MARGIN - FOOTER


@dataclass(frozen=True)
class Page:
    """One page of a sheet.

    Attributes
    ----------
    paper, orientation : str
        ``A4``, ``A3`` or ``letter``; ``portrait`` or ``landscape``.
    size : tuple
        (width, height) of the page in cm, as it is printed.
    placed : tuple
        ``(panel index, x, y)``: the panel's top-left corner in cm from the page's
        top-left corner.
    number, count : int
        This page's number and how many pages the sheet has.
    panels : tuple
        The names of the panels on it (``configuration``, ...), where the caller gave them.
    """

    paper: str
    orientation: str
    size: tuple
    placed: tuple
    number: int = 1
    count: int = 1
    panels: tuple = ()

    @property
    def text(self) -> str:
        """The paper in words: "A4 portrait"."""
        return f"{self.paper} {self.orientation}"

    def footer(self) -> str:
        """The line each page carries: the paper it was drawn for and how to print it."""
        w, h = self.size
        page = f"; page {self.number} of {self.count}" if self.count > 1 else ""
        return (
            f"{self.text} ({w:g} x {h:g} cm): print at 100 % (actual size, not fit to page){page}"
        )


def _fitting(w, h, paper):
    """The first orientation (portrait before landscape) whose room holds ``w`` x ``h``
    cm, or None."""
    for orientation in ("portrait", "landscape"):
        rw, rh = room(paper, orientation)
        if w <= rw + ON_PAPER and h <= rh + ON_PAPER:
            return orientation
    return None


def _front(items, paper):
    """The arrangements of the panels ``items`` ([(index, (w, h))], in order) that cut
    straight across and may be the first that fits: (width, height, rank, [(index, x,
    y)]), by rank.

    Every such arrangement is one panel, or two arrangements of a cut of the panels, side
    by side (tops aligned) before stacked (left edges aligned), cut after the first panel
    before after the second, ...: its rank is (0 or 1, the cut, the first part's rank, the
    second part's), the order they are tried in. An arrangement is dropped where it fits
    neither way round (none made of it would fit: a part is never larger than the whole),
    or where one of lower rank is no wider and no taller (whatever is made of it would fit
    where the same made of the other fits, and comes later). So the first that fits is
    the first of every arrangement that fits, found in time polynomial in the number of
    panels (there are millions of arrangements of ten panels)."""
    n = len(items)
    fronts = {}
    for i, (k, (w, h)) in enumerate(items):
        fronts[i, i + 1] = [(w, h, (), [(k, 0.0, 0.0)])]
    for length in range(2, n + 1):
        for i in range(n - length + 1):
            j = i + length
            made = []
            for across in (0, 1):
                for cut in range(i + 1, j):
                    for a in fronts[i, cut]:
                        for b in fronts[cut, j]:
                            if across == 0:  # side by side, tops aligned
                                w, h = a[0] + GAP + b[0], max(a[1], b[1])
                            else:  # stacked, left edges aligned
                                w, h = max(a[0], b[0]), a[1] + GAP + b[1]
                            if _fitting(w, h, paper) is not None:
                                made.append((w, h, (across, cut - i, a[2], b[2]), a, b))
            made.sort(key=lambda m: m[2])
            kept, ws, hs = [], [], []  # (ws, hs): the staircase of the kept, w up, h down
            for m in made:
                at = bisect_right(ws, m[0])  # the kept no wider: the lowest of them
                if at and hs[at - 1] <= m[1]:
                    continue
                kept.append(m)
                end = at
                while end < len(ws) and hs[end] >= m[1]:  # those it now beats
                    end += 1
                ws[at:end], hs[at:end] = [m[0]], [m[1]]
            fronts[i, j] = [(w, h, rank, _placed(a, b, rank[0])) for w, h, rank, a, b in kept]
    return fronts[0, n]


def _placed(a, b, across):
    """The panels' places in the arrangement of ``a`` and ``b`` side by side (``across``
    0) or stacked (1)."""
    if across == 0:
        return a[3] + [(k, x + a[0] + GAP, y) for k, x, y in b[3]]
    return a[3] + [(k, x, y + a[1] + GAP) for k, x, y in b[3]]


def _one_page(items, paper):
    """The page holding ``items``, or None: the first arrangement that fits, portrait
    before landscape for each; the arrangement centred across the page, at its top."""
    for w, h, _, pos in _front(items, paper):
        orientation = _fitting(w, h, paper)
        if orientation is not None:
            rw, _ = room(paper, orientation)
            pw, ph = paper_size(paper)
            size = (pw, ph) if orientation == "portrait" else (ph, pw)
            left = MARGIN + (rw - w) / 2
            return Page(
                paper, orientation, size, tuple((k, left + x, MARGIN + y) for k, x, y in pos)
            )
    return None


def fits(size, paper: str) -> bool:
    """Whether one page of ``paper`` (either way round) holds a panel of ``size`` (cm)."""
    return _one_page([(0, tuple(size))], paper_name(paper)) is not None


def _fewest_runs(sizes, paper):
    """The pages of panels ``sizes`` as runs of consecutive panels: as few as hold them,
    and of those the one whose first page holds fewest, then the second, ... (each panel
    alone fits). A run that does not fit on one page does not fit with one more panel, so
    each panel starts a run of at most so many."""
    n = len(sizes)
    pages = {}

    def page(i, j):
        if (i, j) not in pages:
            pages[i, j] = _one_page([(k, sizes[k]) for k in range(i, j)], paper)
        return pages[i, j]

    longest = []
    for i in range(n):
        j = i + 1
        while j < n and page(i, j + 1) is not None:
            j += 1
        longest.append(j)
    fewest = [0] * (n + 1)  # fewest pages from panel i to the end
    for i in range(n - 1, -1, -1):
        fewest[i] = 1 + min(fewest[j] for j in range(i + 1, longest[i] + 1))
    runs, i = [], 0
    while i < n:
        j = next(j for j in range(i + 1, longest[i] + 1) if fewest[j] == fewest[i] - 1)
        runs.append(page(i, j))
        i = j
    return runs


def paginate(sizes, paper: str = "A4", names=None, advice: str = "", panels=None) -> list:
    """The pages of a sheet whose panels are ``sizes`` ((width, height) in cm, in order):
    all on one page where an arrangement fits either way round, else on as few pages as
    hold them, each panel whole. Raises :class:`PolygonMethodError` (key ``--paper``) when
    one panel alone is larger than the paper holds (``names``: what each panel is, for that
    line; ``advice``: what to do, after it; ``panels``: their short names, kept on each
    page)."""
    paper = paper_name(paper)
    for k, (w, h) in enumerate(sizes):
        if _one_page([(k, (w, h))], paper) is None:
            rw, rh = room(paper, "portrait")
            raise PolygonMethodError(
                f"{names[k] if names else f'panel {k + 1}'} is {w:.3g} x {h:.3g} cm: more "
                f"than {paper} holds inside its margins ({rw:.3g} x {rh:.3g} cm, either way "
                f"round){advice}",
                key="--paper",
            )
    pages = _fewest_runs(sizes, paper)
    n = len(pages)
    return [
        Page(
            p.paper,
            p.orientation,
            p.size,
            p.placed,
            i + 1,
            n,
            tuple(panels[k] for k, _, _ in p.placed) if panels else (),
        )
        for i, p in enumerate(pages)
    ]


#: the most panels a page tries in every order where their own order does not fit (4: 24
#: orders of 40 arrangements each; 5 would be 120 of 224)
REORDER = 4


def _one_page_any(items, paper):
    """The page holding ``items`` in their order, or else in another order (up to
    :data:`REORDER` panels), or None."""
    page = _one_page(items, paper)
    if page is not None or len(items) > REORDER:
        return page
    for order in permutations(items):
        page = _one_page(list(order), paper)
        if page is not None:
            return page
    return None


def fill(sizes, paper: str = "A4", panels=None) -> list:
    """The pages of a sheet whose panels are ``sizes`` ((width, height) in cm), each page
    filled before another is started: the panels taken in order, each onto the page being
    filled where the page still holds them all (in their order, or in another), else onto
    a new page. For a sheet of many panels of a kind (the forces sheet's free bodies and
    polygons, group by group), whose order across the pages is kept; the panels of one page
    are laid out as :func:`paginate` lays them out. Each panel must fit a page alone
    (:func:`paginate` refuses one that does not, in one line).

    >>> [[k for k, _, _ in p.placed] for p in fill([(10, 7), (9, 10), (14, 13), (9, 7.5)])]
    [[0, 1, 2], [3]]
    """
    paper = paper_name(paper)
    groups = []
    for k, size in enumerate(sizes):
        tried = None if not groups else _one_page_any(groups[-1][1] + [(k, size)], paper)
        if tried is None:
            tried = _one_page_any([(k, size)], paper)
            if tried is None:
                return paginate(sizes, paper, panels=panels)  # (its one line)
            groups.append((tried, [(k, size)]))
        else:
            groups[-1] = (tried, groups[-1][1] + [(k, size)])
    n = len(groups)
    return [
        Page(
            page.paper,
            page.orientation,
            page.size,
            page.placed,
            i + 1,
            n,
            tuple(panels[k] for k, _, _ in page.placed) if panels else (),
        )
        for i, (page, _) in enumerate(groups)
    ]


def page_files(path, count: int) -> list:
    """The files a sheet of ``count`` pages is written to as SVG or PNG: the name given for
    one page; ``NAME-1.svg``, ``NAME-2.svg``, ... for more.

    >>> [str(p) for p in page_files("out/sheet.svg", 3)]
    ['out/sheet-1.svg', 'out/sheet-2.svg', 'out/sheet-3.svg']
    """
    from pathlib import Path

    path = Path(path)
    if count == 1:
        return [path]
    return [path.with_name(f"{path.stem}-{k}{path.suffix}") for k in range(1, count + 1)]
