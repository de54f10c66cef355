"""Scenes shared by several test modules (each used as it stands in more than one)."""


def seed(
    *, top="", ground="", links="", middle="", drive='angle = 60\nspeed = "10.5 rad/s cw"', after=""
) -> str:
    """The seed four-bar as scene text (pivots A and D 100 apart, AB 50, BC 66, CD 56, the
    crank AB), with what a test adds: ``top`` lines before ``[ground]`` (title, units),
    more ``ground`` pivots, more ``links``, ``middle`` tables between ``[links]`` and ``[input]``
    (``[points]``, ``[assembly]``, ``[cylinders]``), the ``drive`` lines of ``[input]`` after
    the crank (its angle and motion), and tables ``after`` it (``[pins]``). A test that
    fills the text in with ``str.format`` passes its fields through and doubles its braces.

    >>> print(seed(drive="angle = 30"), end="")
    <BLANKLINE>
    [ground]
    A = [0, 0]
    D = [100, 0]
    [links]
    AB = 50
    BC = 66
    CD = 56
    [input]
    crank = "AB"
    angle = 30
    """
    return (
        f"\n{top}[ground]\nA = [0, 0]\nD = [100, 0]\n{ground}[links]\nAB = 50\nBC = 66\n"
        f'CD = 56\n{links}{middle}[input]\ncrank = "AB"\n{drive}\n{after}'
    )


#: the seed four-bar, no more than its links, pivots and crank
FOURBAR = seed()[1:]

SLOTTED_LEVER = """
[ground]
O4 = [0, 0]
O2 = [0, 300]
[links]
"O2-A" = 120
"O4-P" = 600
"P-Q" = 200
[sliders]
A = { along = "O4-P" }
Q = { path = "horizontal", through = [0, 620] }
[assembly]
Q = "right"
[input]
crank = "O2-A"
angle = 45
speed = "60 rpm cw"
"""

NON_GRASHOF = """
[ground]
O2 = [0, 0]
O4 = [200, 0]
[links]
"O2-A" = 150
"A-B" = 450
"B-O4" = 300
[assembly]
B = "above"
[input]
crank = "O2-A"
angle = 150
speed = "200 rad/s ccw"
"""

# AB = CD, BC = AD: the coupler translates
TRANSLATING_COUPLER = """
[ground]
A = [0, 0]
D = [100, 0]
[links]
AB = 40
BC = 100
CD = 40
[assembly]
C = "above"
[input]
crank = "AB"
angle = 30
speed = "10 rad/s ccw"
"""
