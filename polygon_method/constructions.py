"""What each plan step draws on the velocity and acceleration polygons.

These records are read by the step tables and the drawings; they hold the numbers the
solver computed and never redo the kinematics. In the polygon plane a point's image is its
velocity (or acceleration) vector from the pole ``o`` (``o'``); the image of point B is
``b`` (``b'``), every fixed point is at the pole.

>>> from polygon_method import parse_scene, solve
>>> sol = solve(parse_scene('''
... [ground]
... A = [0, 0]
... D = [100, 0]
... [links]
... AB = 50
... BC = 66
... CD = 56
... [input]
... crank = "AB"
... angle = 60
... speed = "10.5 rad/s cw"
... '''))
>>> c = velocity_constructions(sol)[1]
>>> c.text
'through b draw a line perpendicular to BC; through d (at o), one perpendicular to DC; they meet at c'
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .plan import Carried, Crank, Dyad, SliderDyad, SlottedLink
from .solution import Solution

__all__ = ["Vector", "DirectionLine", "Construction", "velocity_constructions",
           "acceleration_constructions", "image_label"]


@dataclass(frozen=True)
class Vector:
    """A segment of a polygon, from ``start`` to ``end`` (polygon coordinates, SI).

    ``kind``: ``absolute`` (from the pole), ``relative`` (between two images),
    ``centripetal``, ``tangential``, ``coriolis``, ``sliding``.
    """

    start: tuple
    end: tuple
    label: str  # e.g. "bc"
    kind: str
    name: str  # e.g. "v_CB" or "centripetal of CB"
    text: str  # how it is found: "omega_BC^2 x BC, parallel to BC, towards B"

    @property
    def magnitude(self) -> float:
        return math.hypot(self.end[0] - self.start[0], self.end[1] - self.start[1])


@dataclass(frozen=True)
class DirectionLine:
    """An infinite line of known direction through a known polygon point."""

    point: tuple
    direction: tuple  # unit vector
    through: str  # label of the point it is drawn through, e.g. "b"
    relation: str  # "perpendicular to BC", "parallel to the path", ...


@dataclass(frozen=True)
class Construction:
    """One plan step on one polygon."""

    step: int
    title: str
    phase: str  # "velocity" or "acceleration"
    finds: str  # the image label found, e.g. "c"
    point: tuple  # where it is
    given: tuple  # Vectors known before the step (drawn first)
    lines: tuple  # the two DirectionLines, or () for a direct step
    found: tuple  # Vectors the step determines
    text: str
    condition: float


def image_label(sol: Solution, point: str, phase: str = "velocity") -> str:
    """``b`` for B on the velocity polygon, ``b'`` on the acceleration polygon; fixed
    points are the pole ``o``/``o'``."""
    prime = "'" if phase == "acceleration" else ""
    if point in sol.scene.ground:
        return "o" + prime
    return point.lower() + prime


def _pole(sol, point, phase):
    """Label for text: ``d (at o)`` for a fixed point that is not named O."""
    lab = image_label(sol, point, phase)
    own = point.lower() + ("'" if phase == "acceleration" else "")
    if lab != own:
        return f"{own} (at {lab})"
    return lab


def _unit(x, y):
    n = math.hypot(x, y)
    return (x / n, y / n) if n else (0.0, 0.0)


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def _add(a, b):
    return (a[0] + b[0], a[1] + b[1])


def _perp(v):
    return (-v[1], v[0])


def _rel(sol, X, Y, D, phase, kind="relative"):
    """Vector from image of Y to image of X (v_XY)."""
    lx, ly = image_label(sol, X, phase), image_label(sol, Y, phase)
    sym = "v" if phase == "velocity" else "a"
    return Vector(D[Y], D[X], f"{ly}{lx}", kind, f"{sym}_{X}{Y}", "")


def _abs(sol, X, D, phase):
    o = "o" if phase == "velocity" else "o'"
    sym = "v" if phase == "velocity" else "a"
    return Vector((0.0, 0.0), D[X], f"{o}{image_label(sol, X, phase)}", "absolute",
                  f"{sym}_{X}", "")


def velocity_constructions(sol: Solution) -> tuple:
    """The velocity polygon, step by step (one :class:`Construction` per plan step)."""
    cache = sol._cache.get("vcons")
    if cache is not None:
        return cache
    out = tuple(_velocity(sol, st) for st in sol.plan.steps)
    sol._cache["vcons"] = out
    return out


def acceleration_constructions(sol: Solution) -> tuple:
    """The acceleration polygon, step by step."""
    cache = sol._cache.get("acons")
    if cache is not None:
        return cache
    out = tuple(_acceleration(sol, st) for st in sol.plan.steps)
    sol._cache["acons"] = out
    return out


def _velocity(sol, st) -> Construction:
    P, V, ph = sol.P, sol.V, "velocity"
    cond = sol.conditions.get(st.index, 1.0)
    lab = lambda p: image_label(sol, p, ph)  # noqa: E731
    if isinstance(st, Crank):
        w = sol.W[st.link]
        v = _abs(sol, st.tip, V, ph)
        text = (f"from {_pole(sol, st.pivot, ph)} draw {lab(st.pivot)}{lab(st.tip)} "
                f"perpendicular to {st.pivot}{st.tip}, = omega x {st.pivot}{st.tip} = "
                f"{abs(w):.4g} x {st.length:.4g} = {v.magnitude:.4g} m/s")
        return Construction(st.index, st.title, ph, lab(st.tip), V[st.tip], (), (), (v,),
                            text, cond)
    if isinstance(st, Dyad):
        X, B, D = st.point, st.b, st.d
        d1 = _unit(*_perp(_sub(P[X], P[B])))
        d2 = _unit(*_perp(_sub(P[X], P[D])))
        lines = (DirectionLine(V[B], d1, lab(B), f"perpendicular to {B}{X}"),
                 DirectionLine(V[D], d2, lab(D), f"perpendicular to {D}{X}"))
        text = (f"through {_pole(sol, B, ph)} draw a line perpendicular to {B}{X}; through "
                f"{_pole(sol, D, ph)}, one perpendicular to {D}{X}; they meet at {lab(X)}")
        found = (_rel(sol, X, B, V, ph), _rel(sol, X, D, V, ph), _abs(sol, X, V, ph))
        return Construction(st.index, st.title, ph, lab(X), V[X], (), lines, found, text, cond)
    if isinstance(st, SliderDyad):
        X, B = st.point, st.b
        d1 = _unit(*_perp(_sub(P[X], P[B])))
        given = ()
        if st.path is not None:
            u, through, tl = st.path.u, (0.0, 0.0), "o"
            rel = f"parallel to the path ({st.path.label})"
        else:
            g1, g2 = P[st.g1], P[st.g2]
            u = _unit(*_sub(g2, g1))
            wg = sol.W[st.guide]
            r = _sub(P[X], g1)
            through = _add(V[st.g1], (-wg * r[1], wg * r[0]))
            tl = f"{lab(X)}1"
            rel = f"parallel to {st.guide}"
            given = (Vector(V[st.g1], through, f"{lab(st.g1)}{tl}", "relative",
                            f"v of the point of {st.guide} under {X}",
                            f"omega_{st.guide} x {st.g1}{X}"),)
        lines = (DirectionLine(V[B], d1, lab(B), f"perpendicular to {B}{X}"),
                 DirectionLine(through, u, tl, rel))
        text = (f"through {_pole(sol, B, ph)} draw a line perpendicular to {B}{X}; through "
                f"{tl}, one {rel}; they meet at {lab(X)}")
        found = (_rel(sol, X, B, V, ph), _abs(sol, X, V, ph),
                 Vector(through, V[X], f"{tl}{lab(X)}", "sliding", f"vs_{X}",
                        "sliding velocity"))
        return Construction(st.index, st.title, ph, lab(X), V[X], given, lines, found, text,
                            cond)
    if isinstance(st, SlottedLink):
        A, K, N = st.point, st.known, st.new
        kA = _sub(P[A], P[K])
        wg = sol.W[st.guide]
        coincident = _add(V[K], (-wg * kA[1], wg * kA[0]))
        u = _unit(*_sub(P[st.second], P[st.first]))
        c = f"{lab(A)}1"
        lines = (DirectionLine(V[K], _unit(*_perp(kA)), lab(K),
                               f"perpendicular to {K}{A}"),
                 DirectionLine(V[A], u, lab(A), f"parallel to {st.guide}"))
        text = (f"through {_pole(sol, K, ph)} draw a line perpendicular to {K}{A} (the point "
                f"of {st.guide} under the block); through {lab(A)}, one parallel to "
                f"{st.guide} (the sliding); they meet at {c}; then {lab(K)}{lab(N)} / "
                f"{lab(K)}{c} = {K}{N} / {K}{A} gives {lab(N)}")
        found = (Vector(V[K], coincident, f"{lab(K)}{c}", "relative",
                        f"v of the point of {st.guide} under {A}", ""),
                 Vector(coincident, V[A], f"{c}{lab(A)}", "sliding", f"vs_{A}",
                        "sliding velocity of the block"),
                 _abs(sol, N, V, ph))
        return Construction(st.index, st.title, ph, lab(N), V[N], (), lines, found, text,
                            cond)
    if isinstance(st, Carried):
        return _carried(sol, st, V, ph, cond)
    raise TypeError(st)


def _carried(sol, st, D, ph, cond):
    lab = lambda p: image_label(sol, p, ph)  # noqa: E731
    X, p, q = st.point, st.p, st.q
    if st.mu == 0:
        text = (f"{lab(p)}{lab(X)} / {lab(p)}{lab(q)} = {p}{X} / {p}{q} = {st.lam:.4g}: "
                f"{lab(X)} on {lab(p)}{lab(q)}" + (" produced" if not 0 <= st.lam <= 1 else ""))
    else:
        text = (f"triangle {lab(p)}{lab(q)}{lab(X)} similar to {p}{q}{X}, read the same way "
                f"round ({'ccw' if st.mu > 0 else 'cw'}): {lab(X)} is the image of {X}")
    found = (_abs(sol, X, D, ph), _rel(sol, X, p, D, ph))
    return Construction(st.index, st.title, ph, lab(X), D[X], (), (), found, text, cond)


def _centripetal(sol, X, B, link, A, ph):
    """Centripetal component of a_XB: w^2 |XB| along XB, towards B, drawn from b'."""
    w = sol.W[link]
    r = _sub(sol.P[X], sol.P[B])
    vec = (-w * w * r[0], -w * w * r[1])
    start = A[B]
    end = _add(start, vec)
    L = math.hypot(*r)
    return Vector(start, end, f"{image_label(sol, B, ph)}{X.lower()}c", "centripetal",
                  f"centripetal of {X}{B}",
                  f"v_{X}{B}^2 / {X}{B} = {w * w * L:.4g} m/s^2, parallel to {X}{B}, "
                  f"towards {B}")


def _acceleration(sol, st) -> Construction:
    P, A, ph = sol.P, sol.A, "acceleration"
    cond = sol.conditions.get(st.index, 1.0)
    lab = lambda p: image_label(sol, p, ph)  # noqa: E731
    if isinstance(st, Crank):
        O, T = st.pivot, st.tip
        cen = _centripetal(sol, T, O, st.link, A, ph)
        al = sol.Al[st.link]
        r = _sub(P[T], P[O])
        tan = Vector(cen.end, A[T], f"{lab(T)}t", "tangential", f"tangential of {T}{O}",
                     f"alpha x {O}{T} = {abs(al) * math.hypot(*r):.4g} m/s^2, "
                     f"perpendicular to {O}{T}")
        text = (f"from {_pole(sol, O, ph)} draw the centripetal component {cen.text}"
                + (f"; add the tangential component {tan.text}" if al else
                   " (no tangential component: the crank turns uniformly)")
                + f"; its end is {lab(T)}")
        found = (cen, tan, _abs(sol, T, A, ph)) if al else (cen, _abs(sol, T, A, ph))
        return Construction(st.index, st.title, ph, lab(T), A[T], (cen,), (), found, text,
                            cond)
    if isinstance(st, Dyad):
        X, B, D = st.point, st.b, st.d
        c1 = _centripetal(sol, X, B, st.link1, A, ph)
        c2 = _centripetal(sol, X, D, st.link2, A, ph)
        d1 = _unit(*_perp(_sub(P[X], P[B])))
        d2 = _unit(*_perp(_sub(P[X], P[D])))
        lines = (DirectionLine(c1.end, d1, f"the end of the centripetal of {X}{B}",
                               f"perpendicular to {B}{X}"),
                 DirectionLine(c2.end, d2, f"the end of the centripetal of {X}{D}",
                               f"perpendicular to {D}{X}"))
        text = (f"from {_pole(sol, B, ph)} draw the centripetal of {X}{B} ({c1.text}), and "
                f"through its end a line perpendicular to {B}{X}; from {_pole(sol, D, ph)} "
                f"draw the centripetal of {X}{D} ({c2.text}), and through its end a line "
                f"perpendicular to {D}{X}; they meet at {lab(X)}")
        found = (Vector(c1.end, A[X], f"t{X}{B}", "tangential", f"tangential of {X}{B}",
                        f"alpha_{st.link1} x {B}{X}"),
                 Vector(c2.end, A[X], f"t{X}{D}", "tangential", f"tangential of {X}{D}",
                        f"alpha_{st.link2} x {D}{X}"),
                 _rel(sol, X, B, A, ph), _rel(sol, X, D, A, ph), _abs(sol, X, A, ph))
        return Construction(st.index, st.title, ph, lab(X), A[X], (c1, c2), lines, found,
                            text, cond)
    if isinstance(st, SliderDyad):
        X, B = st.point, st.b
        c1 = _centripetal(sol, X, B, st.link, A, ph)
        d1 = _unit(*_perp(_sub(P[X], P[B])))
        given = [c1]
        if st.path is not None:
            u, through, tl = st.path.u, (0.0, 0.0), "o'"
            rel = f"parallel to the path ({st.path.label})"
        else:
            g1 = P[st.g1]
            u = _unit(*_sub(P[st.g2], g1))
            wg, ag = sol.W[st.guide], sol.Al[st.guide]
            r = _sub(P[X], g1)
            under = _add(A[st.g1], (-wg * wg * r[0] - ag * r[1], -wg * wg * r[1] + ag * r[0]))
            cor = sol.S[X][2]
            through = _add(under, cor)
            tl = "the end of the Coriolis component"
            rel = f"parallel to {st.guide}"
            given += [Vector(A[st.g1], under, f"{lab(X)}1", "relative",
                             f"a of the point of {st.guide} under {X}", ""),
                      Vector(under, through, "cor", "coriolis", f"Coriolis at {X}",
                             f"2 omega_{st.guide} vs = {math.hypot(*cor):.4g} m/s^2")]
        lines = (DirectionLine(c1.end, d1, f"the end of the centripetal of {X}{B}",
                               f"perpendicular to {B}{X}"),
                 DirectionLine(through, u, tl, rel))
        text = (f"from {_pole(sol, B, ph)} draw the centripetal of {X}{B} ({c1.text}) and "
                f"through its end a line perpendicular to {B}{X}; through {tl}, one {rel}; "
                f"they meet at {lab(X)}")
        found = (Vector(c1.end, A[X], f"t{X}{B}", "tangential", f"tangential of {X}{B}",
                        f"alpha_{st.link} x {B}{X}"),
                 Vector(through, A[X], "s", "sliding", f"as_{X}", "sliding acceleration"),
                 _rel(sol, X, B, A, ph), _abs(sol, X, A, ph))
        return Construction(st.index, st.title, ph, lab(X), A[X], tuple(given), lines, found,
                            text, cond)
    if isinstance(st, SlottedLink):
        Ab, K, N = st.point, st.known, st.new
        kA = _sub(P[Ab], P[K])
        w, al = sol.W[st.guide], sol.Al[st.guide]
        cen_end = _add(A[K], (-w * w * kA[0], -w * w * kA[1]))
        under = _add(cen_end, (-al * kA[1], al * kA[0]))
        cor = sol.S[Ab][2]
        u = _unit(*_sub(P[st.second], P[st.first]))
        back = _sub(A[Ab], cor)
        c = f"{lab(Ab)[:-1]}1'"
        cen = Vector(A[K], cen_end, "cen", "centripetal", f"centripetal of {Ab}{K} on "
                     f"{st.guide}", f"omega^2 x {K}{Ab} = {w * w * math.hypot(*kA):.4g} m/s^2, "
                     f"towards {K}")
        corv = Vector(back, A[Ab], "cor", "coriolis", f"Coriolis at {Ab}",
                      f"2 omega_{st.guide} vs = {math.hypot(*cor):.4g} m/s^2, perpendicular "
                      f"to {st.guide}")
        lines = (DirectionLine(cen_end, _unit(*_perp(kA)), "the end of the centripetal",
                               f"perpendicular to {K}{Ab}"),
                 DirectionLine(back, u, "the start of the Coriolis component",
                               f"parallel to {st.guide}"))
        text = (f"from {_pole(sol, K, ph)} draw the centripetal of the point of {st.guide} "
                f"under the block ({cen.text}) and through its end a line perpendicular to "
                f"{K}{Ab}; from {lab(Ab)} draw the Coriolis component backwards ({corv.text}) "
                f"and through its start a line parallel to {st.guide}; they meet at {c}; "
                f"{lab(N)} follows by {lab(K)}{lab(N)} / {lab(K)}{c} = {K}{N} / {K}{Ab}")
        found = (Vector(cen_end, under, "t", "tangential", f"tangential of {Ab}{K}",
                        f"alpha_{st.guide} x {K}{Ab}"),
                 Vector(under, back, "s", "sliding", f"as_{Ab}", "sliding acceleration"),
                 _abs(sol, N, A, ph))
        return Construction(st.index, st.title, ph, lab(N), A[N], (cen, corv), lines, found,
                            text, cond)
    if isinstance(st, Carried):
        return _carried(sol, st, A, ph, cond)
    raise TypeError(st)
