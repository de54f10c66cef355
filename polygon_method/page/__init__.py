"""The page a student opens in a browser (``polygon-method page``) and the animation of
``draw --animate``: the three diagrams moving with the crank, from one vectorised sweep.

:mod:`.frames` computes the frames, :mod:`.data` turns them into the page's data,
:mod:`.html` writes the page (its script and style are the package files ``page.js`` and
``page.css``), :mod:`.animate` makes GIF, HTML or SVG animations with matplotlib.
"""

from .frames import (DEFAULT_FRAMES, MAX_FRAMES, MAX_PICTURE_FRAMES, Frames, check_frames,
                     frames, max_frames)

__all__ = ["frames", "Frames", "DEFAULT_FRAMES", "MAX_FRAMES", "MAX_PICTURE_FRAMES",
           "max_frames", "check_frames", "page_html", "animation"]


def page_html(*args, **kw):
    from .html import page_html as make
    return make(*args, **kw)


def animation(*args, **kw):
    from .animate import animation as make
    return make(*args, **kw)
