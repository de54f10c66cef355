"""Sizes, fonts and line styles of the drawings (cm on paper, pt for text and lines)."""

from __future__ import annotations


CM_PER_INCH = 2.54
PT_PER_CM = 72.0 / 2.54
FORMATS = ("svg", "png", "pdf")
FONT = "DejaVu Sans"
PNG_DPI = 200

#: the largest figure any scale may make (cm): beyond A0 it is a mistake in the scale
MAX_FIGURE_CM = 120.0

# sizes on paper (cm) and in points (text, line widths)
BAR = 0.28  # width of a link drawn as a bar
JOINT_R = 0.08  # a pin joint's circle
DOT_R = 0.045  # an image point
POLE_R = 0.06
HEAD_LEN, HEAD_HALF = 0.26, 0.075  # arrowheads
OVERSHOOT = 0.6  # how far a direction line runs past the points it joins
LABEL_PT, MARK_PT, NOTE_PT, TITLE_PT, SMALL_PT = 10.0, 7.5, 8.5, 10.5, 7.0
CLEAR = 0.05  # clearance of a label from any line (cm)
MARK_APART = 0.25  # a line's mark ("perp EF") from the points' labels, where there is room
PIN_ZONE = 0.3  # around a fixed pin, where its bracket and the links' rounded ends meet (cm)
BLOCK_MIN, BLOCK_CLEAR = 0.35, 0.04  # a block's least length; its clearance of other pins

#: line styles of the vectors by kind (colour, width in pt, dashes or None)
STYLE = {
    "absolute": ("#000000", 1.5, None),
    "relative": ("#000000", 0.9, None),
    "sliding": ("#7b3294", 1.1, (5.0, 1.5, 1.0, 1.5)),
    "centripetal": ("#1f5fbf", 1.2, None),
    "tangential": ("#d95f02", 1.2, (4.0, 1.5)),
    "coriolis": ("#1a9641", 2.2, None),
}
LINE_STYLE = ("#777777", 0.6, (4.0, 2.5))  # construction (direction) lines
#: op drawn from the pole square to xy where vmin_XY is asked, and xy produced to its foot p
LEAST_STYLE = ("#000000", 0.6, (2.0, 1.5))
LEGEND_NAMES = {
    "absolute": "total (from the pole)",
    "relative": "relative (between images)",
    "centripetal": "centripetal component",
    "tangential": "tangential component",
    "coriolis": "Coriolis component",
    "sliding": "sliding component",
}
#: line styles of the forces by kind (colour, width in pt, dashes or None): free bodies,
#: force polygons, the page's inertia forces
FORCE_STYLE = {
    "pin": ("#000000", 1.4, None),
    "guide": ("#7b3294", 1.4, None),
    "inertia": ("#d95f02", 1.4, None),
    "weight": ("#555555", 1.2, None),
    "load": ("#1f5fbf", 1.4, None),
    "gas": ("#1f5fbf", 1.4, None),
    "contact": ("#1b7837", 1.4, None),
    "friction": ("#b2182b", 1.2, None),
    "driver": (
        "#01665e",
        1.4,
        None,
    ),  # a driver's force: a driving block's, a collar's along its rod
}
BODY_FACE, BODY_EDGE = "#dde6f2", "#23395d"
IMAGE_FACE = "#f4d35e"
PITCH_STYLE = ("#333333", 0.7, (6.0, 2.0, 1.0, 2.0))  # pitch circles
