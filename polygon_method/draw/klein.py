"""Klein's construction drawn on the configuration diagram (a slider crank at uniform crank
speed): the rod produced to M, the perpendicular O M, the circle about the crank pin through
M and the circle on the rod as diameter, their common chord through Q to N, and N O, the
piston's acceleration over omega^2, drawn bold. See :mod:`polygon_method.linkage.klein`."""

from __future__ import annotations

import math

from ..linkage.klein import klein_of
from .style import DOT_R, LABEL_PT

#: the construction's lines: grey and dashed, thin, under the mechanism
KLEIN_COLOR = "#6a3d9a"
_DASH = (3.0, 2.0)


def klein_line(sol) -> str | None:
    """The configuration diagram's line saying what the construction gives, or None."""
    k, names = klein_of(sol)
    if k is None:
        return None
    O, C, P = names
    return (
        f"Klein's construction (dashed, purple): {O}M = v_{P}/ω, {C}M = v_{P}{C}/ω; "
        f"N{O} = a_{P}/ω² (bold)"
    )


def draw_klein(sk, sol, scale, P):
    """Add Klein's construction to the sketch ``sk`` (points ``P`` in cm)."""
    k, names = klein_of(sol)
    if k is None:
        return
    s = scale.per_cm
    cm = lambda p: (p[0] / s, p[1] / s)  # noqa: E731
    taken = set(sol.scene.point_names)

    def name(n):  # a scene's own point of that name keeps it: the construction's is primed
        return n + "'" if n in taken else n

    O, C, Pn, M, Q, N = (cm(k.O), cm(k.C), cm(k.P), cm(k.M), cm(k.Q), cm(k.N))
    line = dict(color=KLEIN_COLOR, lw=0.5, dashes=_DASH, z=1, hint=False)
    sk.line([C, M], gid="klein-rod-produced", **line)
    sk.line([O, M], gid="klein-OM", **line)
    rc = math.dist(C, M)
    for gid, centre, r in (
        ("klein-circle-M", C, rc),
        ("klein-circle-rod", ((C[0] + Pn[0]) / 2, (C[1] + Pn[1]) / 2), math.dist(C, Pn) / 2),
    ):
        pts = [
            (
                centre[0] + r * math.cos(2 * math.pi * i / 144),
                centre[1] + r * math.sin(2 * math.pi * i / 144),
            )
            for i in range(145)
        ]
        sk.line(pts, gid=gid, **line)
    on = [Q, N] + ([cm(k.K), cm(k.L)] if k.K is not None else [])  # the chord's line
    dx, dy = N[0] - Q[0], N[1] - Q[1]
    if k.K is not None:
        dx, dy = on[2][0] - on[3][0], on[2][1] - on[3][1]
    ordered = sorted(on, key=lambda p: (p[0] - Q[0]) * dx + (p[1] - Q[1]) * dy)
    sk.line([ordered[0], ordered[-1]], gid="klein-chord", **line)
    sk.line([N, O], gid="klein-NO", color=KLEIN_COLOR, lw=1.6, z=2, hint=False)
    marks = [("M", M), ("Q", Q), ("N", N)]
    if k.K is not None:
        marks += [("K", cm(k.K)), ("L", cm(k.L))]
    for label, xy in marks:
        sk.circle(
            xy,
            DOT_R * 0.8,
            gid=f"klein-{label}",
            face=KLEIN_COLOR,
            edge=KLEIN_COLOR,
            lw=0.3,
            z=6,
            obstacle=None,
        )
        sk.label(
            name(label), [xy], LABEL_PT, gid=f"label-klein-{label}", color=KLEIN_COLOR, point=True
        )
