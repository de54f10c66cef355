"""Two points of one link, as the books ask of them: the point of the segment between them
with the least absolute velocity (``vmin_BC``), and the radial and tangential components
of one's acceleration relative to the other (``ar_CB``, ``at_CB``). Written once here; the
answer keys, ``check``, ``solve``, ``--json`` and ``steps`` read these records, with each
number's error bound (:func:`pair_bounds`); ``sweep`` (its columns, summary and plot) and
the page the same over many crank angles (:func:`pair_quantities`, :func:`feet_over`).

The least speed, by hand (Rattan, Sadhu Singh, Khurmi): on the velocity polygon draw op
perpendicular to bc from the pole; p is the image of the point of BC (produced if need be)
moving slowest, ``BP = BC x bp / bc`` and ``v_P = op``. As a formula, the points of the line
move as ``v(t) = v_B + t (v_C - v_B)``; the foot is ``t = -v_B . v_CB / |v_CB|^2`` and
``op = |v_B x v_C| / |v_CB|``. Where the foot falls outside bc the least on the link itself
is at the nearer end; where the link does not turn (omega within its error bound of 0)
every point of it moves alike, and the least is that common speed, at no point in
particular. A link with more than two points (a plate) is named by two of its points: the
least on the segment between them (the least of the whole plane of the plate is its
instantaneous centre's, 0).

The components, as the acceleration polygon sets them out: ``omega^2 CB`` directed from C
to B (radial, centripetal) and ``alpha CB`` perpendicular to CB (tangential), omega and
alpha the link's.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from ..common.errors import SceneError

__all__ = [
    "PAIR_KINDS",
    "LeastSpeed",
    "Components",
    "common_link",
    "least_speed",
    "components",
    "pair_value",
    "segment_least",
    "segment_slowest",
    "pair_quantities",
    "pair_columns",
    "Feet",
    "feet_over",
    "link_rates",
    "asked_pairs",
    "asked_dict",
    "pair_bounds",
    "pair_worst",
    "bounds_dict",
]

#: the answer kinds of two points of one link -> (the kind of their error bound, words)
PAIR_KINDS = {
    "vmin": ("v", "the least speed of a point of {0}{1}"),
    "ar": ("a", "the radial component of the acceleration of {0} relative to {1}"),
    "at": ("a", "the tangential component of the acceleration of {0} relative to {1}"),
}


#: a line of a scene's text that may ask one (its key first on the line)
_ASKED = re.compile(r"^[ \t]*[\"']?(?:vmin|ar|at)_", re.M)


@dataclass(frozen=True)
class LeastSpeed:
    """The point of segment XY of one link moving slowest.

    ``fraction`` is bp/bc of the foot p of the perpendicular from o to bc (None where the
    link does not turn: no foot), ``at`` the fraction along XY of the slowest point of the
    segment (the foot, or the nearer end where the foot falls outside; 0 where the link
    does not turn), ``speed`` its speed (m/s), ``foot_speed`` op (the least of the line
    XY produced), ``length`` XY (m), ``position`` the slowest point's (m), ``where``
    "between", "beyond X" (the foot beyond x: the least at X), or "translating"."""

    link: str
    x: str
    y: str
    fraction: float | None
    at: float
    speed: float
    foot_speed: float
    length: float
    position: tuple
    where: str

    @property
    def offset(self) -> float | None:
        """XP (m): the foot's distance from X along XY (negative behind X), None without one."""
        return None if self.fraction is None else self.fraction * self.length

    def as_dict(self) -> dict:
        """The JSON entry (SI)."""
        return {
            "link": self.link,
            "from": self.x,
            "to": self.y,
            "speed": self.speed,
            "fraction": self.at,
            "distance": self.at * self.length,
            "position": list(self.position),
            "foot_fraction": self.fraction,
            "foot_speed": self.foot_speed,
            "where": self.where,
        }


@dataclass(frozen=True)
class Components:
    """X relative to Y on one link: ``radial`` = omega^2 r (directed X to Y), ``tangential``
    = |alpha| r, at ``r`` = XY (m), omega and alpha the link's."""

    link: str
    x: str
    y: str
    r: float
    omega: float
    alpha: float
    radial: float
    tangential: float

    def as_dict(self) -> dict:
        """The JSON entry (SI)."""
        return {
            "link": self.link,
            "of": self.x,
            "relative_to": self.y,
            "r": self.r,
            "omega": self.omega,
            "alpha": self.alpha,
            "radial": self.radial,
            "tangential": self.tangential,
        }


def common_link(scene, x: str, y: str):
    """The link both ``x`` and ``y`` are points of (its ends or its carried points), else a
    :class:`SceneError` naming them."""
    for lk in scene.links:
        on = {lk.p, lk.q} | {c.name for c in scene.points if c.link == lk.key}
        if x in on and y in on:
            return lk
    raise SceneError(
        f"{x} and {y} are not two points of one link (the ends of a link of [links], or "
        "points of [points] carried on it)"
    )


def segment_least(vx, vy):
    """The least speed of the points of a segment whose ends move at ``vx`` and ``vy``
    (floats, or arrays of many drawn mechanisms): ``|v_X + t v_YX|`` at the foot t
    clipped to [0, 1]; ``|v_X|`` where the ends move alike."""
    return segment_slowest(vx, vy)[1]


def segment_slowest(vx, vy) -> tuple:
    """(t, speed): the fraction along XY of the slowest point of the segment (the foot
    clipped to [0, 1]; 0 where the ends move alike) and its speed (:func:`segment_least`)."""
    import numpy as np

    (bx, by), (cx, cy) = vx, vy
    dx, dy = np.subtract(cx, bx), np.subtract(cy, by)
    dd = dx * dx + dy * dy
    with np.errstate(all="ignore"):
        t = np.where(dd > 0, -(bx * dx + by * dy) / np.where(dd > 0, dd, 1.0), 0.0)
    t = np.clip(t, 0.0, 1.0)
    return t, np.hypot(bx + t * dx, by + t * dy)


#: the words of each kind in sweep --summary's table
_SUMMARY_WORDS = {
    "vmin": "least speed of a point of {0}{1}",
    "ar": "radial comp. of {0} rel. {1}, omega^2 r",
    "at": "tangential comp. of {0} rel. {1}, alpha r",
}


def pair_quantities(scene, m):
    """(key, unit, array, words) of each asked key over the crank angles of the motion
    ``m`` (a sweep's, or its chunk's): what ``sweep --summary`` takes the extremes of."""
    import numpy as np

    for key, kind, (x, y) in asked_pairs(scene):
        if kind == "vmin":
            value, unit = segment_least(m.V[x], m.V[y]), "m/s"
        else:
            value, unit = link_rates(scene, m.W, m.Al, m.P, x, y)[kind == "at"], "m/s^2"
        value = np.broadcast_to(np.asarray(value, dtype=float), (m.n,))  # (two fixed points: 0)
        yield key, unit, value, _SUMMARY_WORDS[kind].format(x, y)


def pair_columns(res) -> list:
    """``sweep --csv``'s columns (name, unit, array) of each asked key: its value; for
    ``vmin_XY`` also ``vmin_XY_from_X``, the slowest point's distance from X along XY (m),
    an empty cell where the link does not turn (its omega within its own error bound:
    every point alike, at no point in particular)."""
    import numpy as np

    cols, feet = [], {f.key: f for f in feet_over(res)}
    for key, unit, value, _ in pair_quantities(res.scene, res):
        cols.append((key, unit, value))
        f = feet.get(key)
        if f is not None:
            cols.append((f"{key}_from_{f.x}", "m", np.ma.masked_array(f.distance, mask=f.still)))
    return cols


@dataclass(frozen=True)
class Feet:
    """A ``vmin_XY`` asked, over the crank angles of a sweep (arrays): ``t`` the foot p of
    the perpendicular from o to xy as a fraction of XY from X (unclipped: beyond an end where
    outside [0, 1]), ``foot`` its image (v_X + t v_YX: (x, y), m/s), ``speed`` the least speed
    of the segment, ``distance`` the slowest point's distance from X (m), ``still`` where the
    link does not turn (its omega within its own error bound: no foot, every point alike),
    ``noise`` the speed's absolute error bound (:func:`pair_bounds`' ``speed``; 0 where it is
    no useful bound)."""

    key: str
    x: str
    y: str
    t: object
    foot: tuple
    speed: object
    distance: object
    still: object
    noise: object


def feet_over(res) -> list:
    """The :class:`Feet` of each ``vmin_XY`` asked of the sweep ``res`` (``sweep --csv``'s
    columns, the page's mark of p)."""
    import numpy as np

    from ..solver.errorbound import USELESS

    asked = [(key, x, y) for key, kind, (x, y) in asked_pairs(res.scene) if kind == "vmin"]
    if not asked:
        return []
    eb, n, out = res.error_bounds, np.shape(res.theta), []
    for key, x, y in asked:
        link = common_link(res.scene, x, y).key
        e = np.broadcast_to(np.asarray(eb.W.get(link, 0.0), dtype=float), n)
        still = np.abs(res.W[link]) <= np.where(e < USELESS, e * eb.scales["omega"], 0.0)
        vel = (*res.V[x], *res.V[y])
        bx, by, cx, cy = (np.broadcast_to(np.asarray(c, dtype=float), n) for c in vel)
        dx, dy = cx - bx, cy - by
        dd = np.where(still, 1.0, dx * dx + dy * dy)
        with np.errstate(all="ignore"):
            t = np.where(still | (dd == 0), 0.0, -(bx * dx + by * dy) / dd)
        at, speed = segment_slowest((bx, by), (cx, cy))
        (px, py), (qx, qy) = res.P[x], res.P[y]
        length = np.hypot(np.subtract(qx, px), np.subtract(qy, py))
        far = np.broadcast_to(np.where(still, 0.0, at) * length, n)
        foot = (bx + t * dx, by + t * dy)
        ev = np.maximum(
            *(np.broadcast_to(np.asarray(eb.V.get(p, 0.0), dtype=float), n) for p in (x, y))
        )
        noise = np.where(ev < USELESS, ev * eb.scales["velocity"], 0.0)
        out.append(Feet(key, x, y, t, foot, np.broadcast_to(speed, n), far, still, noise))
    return out


def link_rates(scene, W, Al, P, x: str, y: str) -> tuple:
    """(omega^2 r, |alpha| r) of ``x`` about ``y`` on their link, from the motion's
    omegas, alphas and places (floats, or arrays of many drawn mechanisms)."""
    import numpy as np

    key = common_link(scene, x, y).key
    (px, py), (qx, qy) = P[x], P[y]
    r = np.hypot(np.subtract(px, qx), np.subtract(py, qy))
    return W[key] * W[key] * r, np.abs(Al[key]) * r


def least_speed(sol, x: str, y: str) -> LeastSpeed:
    """The slowest point of segment ``x``-``y`` of one link (see the module docstring)."""
    lk = common_link(sol.scene, x, y)
    (bx, by), (cx, cy) = _still(sol, x), _still(sol, y)
    (px, py), (qx, qy) = sol.P[x], sol.P[y]
    length = math.hypot(qx - px, qy - py)
    dx, dy = cx - bx, cy - by
    turns = sol.shown(sol.W[lk.key], "omega", lk.key) != 0 and (dx, dy) != (0.0, 0.0)
    if not turns or length == 0:  # every point alike (v_X and v_Y both within their bounds)
        s = math.hypot(bx, by)
        return LeastSpeed(lk.key, x, y, None, 0.0, s, s, length, (px, py), "translating")
    t = -(bx * dx + by * dy) / (dx * dx + dy * dy)
    foot = abs(bx * cy - by * cx) / math.hypot(dx, dy)  # op = |v_X x v_Y| / |v_YX|
    where = f"beyond {x}" if t < 0 else f"beyond {y}" if t > 1 else "between"
    at, speed = min(max(t, 0.0), 1.0), float(segment_least((bx, by), (cx, cy)))
    pos = (px + at * (qx - px), py + at * (qy - py))
    return LeastSpeed(lk.key, x, y, t, at, speed, foot, length, pos, where)


def _still(sol, x: str) -> tuple:
    """``x``'s velocity, 0 where it is within its error bound (a dead centre's piston)."""
    v = sol.V[x]
    return (0.0, 0.0) if math.hypot(*v) <= sol.noise("v", x) else v


def components(sol, x: str, y: str) -> Components:
    """The radial and tangential components of ``x``'s acceleration relative to ``y`` (the
    link's omega and alpha within their error bounds of 0 are 0, as every report shows them)."""
    key = common_link(sol.scene, x, y).key
    w = sol.shown(sol.W[key], "omega", key)  # rounding noise about 0 is 0
    al = sol.shown(sol.Al[key], "alpha", key)
    radial, tangential = link_rates(sol.scene, {key: w}, {key: al}, sol.P, x, y)
    r = math.dist(sol.P[x], sol.P[y])
    return Components(key, x, y, r, w, al, float(radial), float(tangential))


def pair_value(sol, kind: str, names) -> float:
    """The value behind ``vmin_XY``, ``ar_XY``, ``at_XY``."""
    x, y = names
    if kind == "vmin":
        return least_speed(sol, x, y).speed
    c = components(sol, x, y)
    return c.radial if kind == "ar" else c.tangential


def asked_pairs(scene, answers=None) -> tuple:
    """(key, kind, (X, Y)) of every ``vmin``, ``ar``, ``at`` key the scene's ``[answers]``
    asks (``answers``: another set's, an answer file's, answers or (key, kind, names)), each
    quantity once, in the order asked. A scene read without its answers (``solve``, ``steps``) is asked from its
    text: only the keys' names are read there (their values are ``check``'s)."""
    if answers is None:
        answers = scene.answers or _keys_of_text(scene)
    out, seen = [], set()
    for a in answers:
        key, kind, names = (a.key, a.kind, tuple(a.names)) if hasattr(a, "kind") else a
        if kind not in PAIR_KINDS or len(names) != 2:
            continue
        ident = (kind, frozenset(names))
        if ident in seen:
            continue
        seen.add(ident)
        out.append((key, kind, names))
    return tuple(out)


def asked_dict(sol) -> dict:
    """``solve --json``'s ``link_points``: each asked key's value and its record (SI);
    empty where none is asked."""
    out = {}
    for key, kind, (x, y) in asked_pairs(sol.scene):
        rec = least_speed(sol, x, y) if kind == "vmin" else components(sol, x, y)
        out[key] = {"value": pair_value(sol, kind, (x, y)), **rec.as_dict()}
    return {"link_points": out} if out else {}


#: the rounding of the few operations from the points' numbers to an answer, in EPS
_OWN = 8.0
_EPS = _OWN * 2.0**-53


def pair_bounds(sol, kind: str, x: str, y: str) -> dict:
    """The estimated error bound of each number of an asked key's record
    (:meth:`LeastSpeed.as_dict`, :meth:`Components.as_dict`), each relative to the size of
    its kind that ``solve --json``'s ``error_bounds.relative_to`` gives (a speed to the
    velocities', a component to the accelerations', a distance or a place to the
    positions', omega and alpha to theirs; a fraction of XY is absolute), from the bounds
    of the points' and the link's own (:attr:`Solution.error_bounds`).

    The velocity of each point of XY is a weighted mean of v_X's and v_Y's, so no point's
    is off by more than the larger of their two bounds, ``e``: the least speed of the
    segment neither (a least of numbers each within ``e``); op, at the foot t of XY
    produced, by ``(|t| + |1 - t|) e``. The foot's place ``t = -v_X . v_YX / |v_YX|^2``
    moves by at most ``e / |v_YX| + 6 e |v_X| / |v_YX|^2`` (to first order): large where
    the link barely turns (v_YX = omega XY small). ``omega^2 r``: ``(2 |omega| dw + dw^2) r
    + omega^2 dr``; ``|alpha| r``: ``r da + |alpha| dr`` (dw, da, dr the bounds of omega,
    alpha and XY)."""
    b = sol.error_bounds
    if kind != "vmin":
        c = components(sol, x, y)
        radial, tangential, dr = _component_bounds(b, c.link, c.omega, c.alpha, c.r, x, y)
        return {
            "value": radial if kind == "ar" else tangential,
            "r": dr + _EPS,
            "omega": b.W.get(c.link, 0.0),
            "alpha": b.Al.get(c.link, 0.0),
            "radial": radial,
            "tangential": tangential,
        }
    ls = least_speed(sol, x, y)
    e = max(b.V.get(x, 0.0), b.V.get(y, 0.0))
    out = {"value": e + _EPS, "speed": e + _EPS}
    if ls.fraction is None:  # every point alike: no foot, no place (at no point in particular)
        out["foot_speed"] = out["speed"]
        return out
    op, dt, distance, position = _foot_bounds(
        b, x, y, _still(sol, x), _still(sol, y), ls.fraction, ls.at, ls.length
    )
    out.update(foot_speed=op, foot_fraction=dt, fraction=dt, distance=distance, position=position)
    return out  # (the foot clipped to the segment, "fraction", is no farther off than the foot)


def _component_bounds(b, key, w, al, r, x, y) -> tuple:
    """(radial, tangential, dr): the bounds of ``omega^2 r`` and ``|alpha| r`` relative to
    the accelerations' size, and of r = XY relative to the positions' (``b`` the bounds,
    ``w``, ``al`` the link's omega and alpha, floats or arrays)."""
    import numpy as np

    k = b.scales
    acc, ps = k["acceleration"], k["position"]
    dr = b.P.get(x, 0.0) + b.P.get(y, 0.0)
    dw, da = b.W.get(key, 0.0) * k["omega"], b.Al.get(key, 0.0) * k["alpha"]
    w, al = np.abs(w), np.abs(al)
    radial = ((2 * w * dw + dw * dw) * r + w * w * dr * ps) / acc + _EPS * w * w * r / acc
    tangential = (da * r + al * dr * ps) / acc + _EPS * al * r / acc
    return radial, tangential, dr


def _foot_bounds(b, x, y, vx, vy, t, at, length) -> tuple:
    """(op, foot, distance, position): the bounds of op (relative to the velocities' size),
    of the foot's fraction t of XY (absolute), of the slowest point's distance from X and of
    its place (relative to the positions' size); ``vx``, ``vy`` the ends' velocities, ``at``
    the foot clipped to the segment (floats or arrays; the link turns: v_YX is not 0)."""
    import numpy as np

    k = b.scales
    e = np.maximum(b.V.get(x, 0.0), b.V.get(y, 0.0))
    (bx, by), (cx, cy) = vx, vy
    d = np.hypot(np.subtract(cx, bx), np.subtract(cy, by))  # |v_YX|
    err = e * k["velocity"]
    dt = err / d + 6 * err * np.hypot(bx, by) / (d * d) + _EPS * (1 + np.abs(t))
    op = (np.abs(t) + np.abs(1 - t)) * (e + _EPS)
    where = dt * length / k["position"]
    dr = b.P.get(x, 0.0) + b.P.get(y, 0.0)
    px, py = b.P.get(x, 0.0), b.P.get(y, 0.0)
    return op, dt, where + at * dr + _EPS, where + (1 - at) * px + at * py + _EPS


def pair_worst(res):
    """The largest bound (relative) of the asked keys' columns of ``sweep --csv`` at each
    angle (their values; a slowest point's distance from X where the link turns), for its
    ``err_max``; 0 where none is asked."""
    import numpy as np

    b, n, out = res.error_bounds, np.shape(res.theta), np.zeros(np.shape(res.theta))
    feet = {f.key: f for f in feet_over(res)}
    for key, kind, (x, y) in asked_pairs(res.scene):
        if kind == "vmin":
            f = feet[key]
            e = np.maximum(b.V.get(x, 0.0), b.V.get(y, 0.0)) + _EPS
            (px, py), (qx, qy) = res.P[x], res.P[y]
            length = np.hypot(np.subtract(qx, px), np.subtract(qy, py))
            at = np.clip(f.t, 0.0, 1.0)
            with np.errstate(all="ignore"):  # (where the link does not turn: no foot, no bound)
                _, _, far, _ = _foot_bounds(b, x, y, res.V[x], res.V[y], f.t, at, length)
            out = np.fmax(out, np.fmax(e, np.where(f.still, 0.0, far)))
            continue
        link = common_link(res.scene, x, y).key
        (px, py), (qx, qy) = res.P[x], res.P[y]
        r = np.hypot(np.subtract(qx, px), np.subtract(qy, py))
        radial, tangential, _ = _component_bounds(b, link, res.W[link], res.Al[link], r, x, y)
        out = np.fmax(out, np.broadcast_to(radial if kind == "ar" else tangential, n))
    return out


def bounds_dict(sol) -> dict:
    """``solve --json``'s ``error_bounds.link_points``: each asked key's bounds
    (:func:`pair_bounds`); empty where none is asked."""
    out = {key: pair_bounds(sol, kind, x, y) for key, kind, (x, y) in asked_pairs(sol.scene)}
    return {"link_points": out} if out else {}


def _keys_of_text(scene) -> tuple:
    """(key, kind, names) of the pair keys of the scene's ``[answers]`` read from its text (a
    scene loaded without its answers), those naming two points of one link."""
    text = getattr(scene, "_text", None) or ""
    if not _ASKED.search(text):
        return ()
    from ..scene import split_name
    from ..scene.reading import scene_table

    table = scene_table(scene).get("answers")
    out = []
    for key in table if isinstance(table, dict) else ():
        kind, _, rest = key.partition("_")
        names = split_name(rest)
        if kind in PAIR_KINDS and len(names) == 2 and names[0] != names[1]:
            try:
                common_link(scene, *names)
            except SceneError:  # (check names it, with its line)
                continue
            out.append((key, kind, names))
    return tuple(out)
