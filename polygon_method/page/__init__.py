"""The page a student opens in a browser (``polygon-method page``) and the animation of
``draw --animate``: the three diagrams moving with the crank, from one vectorised sweep.

:mod:`.frames` computes the frames, :mod:`.data` turns them into the page's data,
:mod:`.html` writes the page (its script and style are the package files ``page.js`` and
``page.css``), :mod:`.animate` makes GIF, HTML or SVG animations with matplotlib.
"""

from .frames import (
    DEFAULT_FRAMES,
    MAX_FOLLOW_FRAMES,
    MAX_FRAMES,
    MAX_PICTURE_FRAMES,
    Frames,
    check_frames,
    frames,
    max_frames,
)

__all__ = [
    "frames",
    "Frames",
    "DEFAULT_FRAMES",
    "MAX_FRAMES",
    "MAX_PICTURE_FRAMES",
    "MAX_FOLLOW_FRAMES",
    "max_frames",
    "check_frames",
    "page_html",
    "animation",
]


def page_html(*args, **kw):
    """The animated page as HTML (see :func:`polygon_method.page.html.page_html`)."""
    from .html import page_html as make

    return make(*args, **kw)


def animation(*args, **kw):
    """An animation of the cycle: GIF, HTML or SVG (see
    :func:`polygon_method.page.animate.animation`)."""
    from .animate import animation as make

    return make(*args, **kw)
