"""The in-line engine the force and engine tests share: its scene (a slider crank with its
reciprocating mass at the piston) and the chapter's closed forms at 50 digits, derived here
from the geometry (the piston's place ``x = r cos t + sqrt(l^2 - r^2 sin^2 t)``
differentiated by mpmath), never read from the tool.
"""

import mpmath
import pytest

from polygon_method.scene import parse_scene

ENGINE = """
title = "engine"
units = "mm"
[ground]
O = [0, 0]
[links]
OA = {r}
AB = {l}
[sliders]
B = {{ path = "horizontal", through = "O" }}
[assembly]
B = "{side}"
[input]
crank = "OA"
angle = {theta}
speed = "{rpm} rpm {sense}"
[masses]
B = {{ mass = "{m} kg" }}
"""


def engine(theta, *, r=150, l=600, rpm=1800, m=2.5, side="right", sense="ccw", extra=""):
    """The engine's scene at crank angle ``theta`` (deg), with the tables ``extra``."""
    return parse_scene(
        ENGINE.format(r=r, l=l, theta=theta, rpm=rpm, m=m, side=side, sense=sense) + extra
    )


def closed_forms(theta_idc, theta, r, l, rpm, m, F_gas, sg=1) -> dict:
    """The engine chapter's forces of an in-line engine at ``theta`` (deg from +x), its
    inner dead centre at ``theta_idc``, turning in the sense ``sg``, under the gas force
    ``F_gas`` (N, towards the crank), as 50-digit numbers: ``F_P`` the piston effort
    (towards the crank), ``F_Q`` the thrust in the rod, ``F_N`` the side thrust, ``F_T``
    the crank effort, ``T`` the turning moment in the sense of rotation (r, l in mm)."""
    mpmath.mp.dps = 50
    R, L = mpmath.mpf(r) / 1000, mpmath.mpf(l) / 1000
    w = 2 * mpmath.pi * rpm / 60
    t = sg * mpmath.radians(mpmath.mpf(theta) - theta_idc)  # from i.d.c., with the rotation

    def x(tt):  # the piston's distance from O
        return R * mpmath.cos(tt) + mpmath.sqrt(L**2 - (R * mpmath.sin(tt)) ** 2)

    a_toward = -(w**2) * mpmath.diff(x, t, 2)  # the piston's acceleration towards O
    F_P = mpmath.mpf(F_gas) - m * a_toward
    n = L / R
    phi = mpmath.asin(mpmath.sin(t) / n)
    F_Q = F_P / mpmath.cos(phi)
    T = F_P * R * (mpmath.sin(t) + mpmath.sin(2 * t) / (2 * mpmath.sqrt(n**2 - mpmath.sin(t) ** 2)))
    return {
        "F_P": F_P,
        "F_Q": F_Q,
        "F_N": F_P * mpmath.tan(phi),
        "F_T": F_Q * mpmath.sin(t + phi),
        "T": T,
    }


@pytest.fixture(autouse=True)
def _precision():
    """mpmath's working precision as it was before each test (others rely on theirs);
    autouse in every module that imports it."""
    dps = mpmath.mp.dps
    yield
    mpmath.mp.dps = dps
