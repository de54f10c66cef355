"""Instantaneous centres: the textbook's second method (Kennedy's theorem).

The bodies are numbered as a textbook does: the ground 1, the crank 2, then the bodies in
the order the construction sets them moving (a block counts as a body). Of the
``N = n (n - 1) / 2`` centres, the **primary** ones come from the joints: a pin is the
centre of the bodies it joins; a block sliding on a straight fixed path has its centre with
the ground at infinity perpendicular to the path, and a block sliding on a moving link has
its centre with that link at infinity perpendicular to the link; a wheel rolling without
slip has its centre with what it rolls on at the contact point. The others are found by
**Kennedy's theorem**: the three centres of any three bodies lie on one line, so ``I_ij``
is where the line through ``I_ik, I_kj`` crosses the line through ``I_il, I_lj``.

A centre at infinity is a direction, never a huge coordinate. Two lines that cross at a
small angle give a far, ill-conditioned centre: the sine of the angle is the centre's
condition, with the polygon steps' policy (a warning below ``TOL.warn``, an error below
``TOL.singular``, except exactly parallel lines: a centre at infinity).

Velocities follow from the centres alone: a body j turning about ``I_1j`` moves a point X
with ``v = omega_j x (X - I_1j)``; the angular-velocity-ratio theorem gives omega_j from a
body i already known, ``omega_j (I_ij - I_1j) = omega_i (I_ij - I_1i)`` (I_ij is a point of
both bodies, with one velocity). A test compares every value with the polygon solution.

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
>>> ic = locate(sol)
>>> ic.bodies, len(ic.centres)
(('ground', 'AB', 'BC', 'CD'), 6)
>>> [ic.centres[k].label for k in ic.order if not ic.centres[k].primary]
['I13', 'I24']
>>> round(ic.omega(3), 9) == round(sol.W["BC"], 9)
True
"""

from __future__ import annotations

import dataclasses
import math
from dataclasses import dataclass

from ..common.errors import TOL, SceneError, SingularStepError
from ..common.tolerances import PARALLEL, SAME, crossing_angle
from ..scene import FixedPath, GuideSlider, YokeSlot, guide_words

__all__ = ["Centre", "Centres", "locate", "centres_dict", "MAX_BODIES", "JSON_BODIES"]

#: more bodies than this have too many centres to list (n = 30: 435 centres)
MAX_BODIES = 30
#: ``solve --json`` lists the centres of mechanisms of at most this many bodies (66 centres)
JSON_BODIES = 12
#: what a student can do where a centre is too far to locate
_POLYGONS_STAND = (
    "; the velocity and acceleration polygons are not affected "
    "(polygon-method steps), or set the crank a few degrees away"
)


@dataclass(frozen=True)
class Centre:
    """The instantaneous centre of bodies ``i < j`` (textbook numbers).

    ``point``: its position (m), or None when it is at infinity, in ``direction`` (a unit
    vector; the bodies' relative motion is then a translation perpendicular to it).
    ``how``: in words; ``lines``: for a centre found by Kennedy's theorem, the two pairs of
    centres whose lines cross here; ``condition``: the sine of their crossing angle.
    """

    i: int
    j: int
    point: tuple | None
    direction: tuple | None
    how: str
    lines: tuple = ()
    condition: float = 1.0
    prefix: str = "I"  # "I13" or, as some courses write it, "13"

    @property
    def label(self) -> str:
        """The centre's name as a book writes it: I13 (I1,12 past nine bodies)."""
        pair = f"{self.i}{self.j}" if max(self.i, self.j) < 10 else f"{self.i},{self.j}"
        return self.prefix + pair

    @property
    def primary(self) -> bool:
        """Found by inspection (a pin, a slider's path, a rolling contact), not by Kennedy's
        theorem."""
        return not self.lines

    @property
    def at_infinity(self) -> bool:
        """The centre is at infinity (its two lines are parallel: the bodies translate relative to
        each other)."""
        return self.point is None


@dataclass(frozen=True)
class Centres:
    """Every instantaneous centre of a solved mechanism, and the velocities they give.

    ``bodies``: body names, ``bodies[k - 1]`` is body k; ``centres``: (i, j) -> Centre;
    ``order``: the keys in the order found (primary first); ``omegas``: body -> omega by the
    angular-velocity-ratio theorem, with ``ratio_from`` body -> the body it came from;
    ``warnings``: ill-conditioned centres.
    """

    bodies: tuple
    centres: dict
    order: tuple
    omegas: dict
    ratio_from: dict
    warnings: tuple
    sol: object

    @property
    def n(self) -> int:
        """The number of bodies, the frame included."""
        return len(self.bodies)

    def centre(self, i, j) -> Centre:
        """The centre of bodies ``i`` and ``j`` (either order)."""
        return self.centres[(min(i, j), max(i, j))]

    def omega(self, body) -> float:
        """The angular velocity of ``body`` (its number, or a link's name), from the centres."""
        return self.omegas[self._number(body)]

    def _number(self, body) -> int:
        if isinstance(body, int):
            return body
        names = [b.lower() for b in self.bodies]
        key = (
            self.sol.scene.link(body).key.lower()
            if self.sol.scene.has_link(body)
            else str(body).lower()
        )
        return names.index(key) + 1

    def velocity(self, point, body=None):
        """The velocity of ``point`` (on ``body``, by default the first body it is on) from
        the centres: omega_j x (X - I_1j), or the translation of a body whose I_1j is at
        infinity."""
        j = self._number(body) if body is not None else self.body_of(point)
        return self._field(j, self.sol.P[point])

    def body_of(self, point) -> int:
        """The number of the moving body ``point`` belongs to (1, the frame, for a fixed point)."""
        for name, _ in self.sol.plan.bodies_at(point):
            k = self._index.get(name)
            if k is not None and k != 1:
                return k
        return 1

    @property
    def _index(self):
        return {b: k + 1 for k, b in enumerate(self.bodies)}

    def _field(self, j, x):
        if j == 1:
            return (0.0, 0.0)
        c = self.centre(1, j)
        w = self.omegas[j]
        if c.point is not None:
            return (-w * (x[1] - c.point[1]), w * (x[0] - c.point[0]))
        i = self.ratio_from[j]  # a translating body: the velocity of its centre with i
        return self._field(i, self.centre(i, j).point)


def _body_names(sol):
    """Ground, then the bodies in the order the steps set them moving."""
    names = ["ground"]
    for st in sol.plan.steps:
        for b in st.bodies():
            if b not in names:
                names.append(b)
    return tuple(names)


def _number_of(sol, names):
    fixed = set(sol.plan.fixed_links)
    index = {b: k + 1 for k, b in enumerate(names)}
    return lambda name: 1 if name in fixed else index.get(name)


def _unit(x, y):
    n = math.hypot(x, y)
    return (x / n, y / n)


def _primary(sol, names):
    sc = sol.scene
    num = _number_of(sol, names)
    found = {}
    for p in sc.point_names:
        joined = sorted({num(name) for name, _ in sol.plan.bodies_at(p)} - {None})
        for a in range(len(joined)):
            for b in range(a + 1, len(joined)):
                key = (joined[a], joined[b])
                if key not in found:
                    found[key] = Centre(*key, tuple(sol.P[p]), None, f"the pin at {p}")
    for s in sc.blocks:  # (not a driving wheel's centre path: the rolling step's contact)
        blk = num(f"block {s.key}")  # a peg in two slots: a block in each
        if isinstance(s, FixedPath):
            d = _unit(-s.u[1], s.u[0])
            key = (1, blk)
            how = (
                f"block {s.key} slides on the {guide_words(s.label)}: at infinity, "
                "perpendicular to the path"
            )
        elif isinstance(s, GuideSlider):
            (x1, y1), (x2, y2) = sol.P[s.first], sol.P[s.second]
            ux, uy = _unit(x2 - x1, y2 - y1)
            d = (-uy, ux)
            g = num(sc.link(s.guide).key)
            key = (min(g, blk), max(g, blk))
            how = f"block {s.key} slides along {s.guide}: at infinity, perpendicular to {s.guide}"
        elif isinstance(s, YokeSlot):  # a block in the slot of a translating yoke
            d = _unit(-s.direction[1], s.direction[0])
            g = num(f"block {s.yoke}")
            key = (min(g, blk), max(g, blk))
            how = (
                f"block {s.point} slides in the {guide_words(s.label, 'slot', f'yoke {s.yoke}')}: at "
                "infinity, perpendicular to the slot"
            )
        else:  # pragma: no cover
            continue
        found[key] = Centre(*key, None, d, how)
    for c in sc.cylinders:  # the rod slides in the barrel: at infinity, across the cylinder
        (x1, y1), (x2, y2) = sol.P[c.barrel], sol.P[c.rod]
        ux, uy = _unit(x2 - x1, y2 - y1)
        a, b = num(f"barrel {c.key}"), num(f"rod {c.key}")
        if a is None or b is None:
            continue
        key = (min(a, b), max(a, b))
        found[key] = Centre(
            *key,
            None,
            (-uy, ux),
            f"the rod of {c.key} slides in its barrel: at infinity, perpendicular to the cylinder",
        )
    for st in sol.plan.steps:  # rolling without slip: the contact point
        for a, b, xy, how in st.contacts(sol.P):
            key = tuple(sorted((num(a), num(b))))
            found[key] = Centre(*key, tuple(xy), None, how)
    return found


def _line(a: Centre, b: Centre):
    """(point, unit direction) of the line through two centres, or None (the line at
    infinity, or two centres at one place)."""
    if a.point is not None and b.point is not None:
        dx, dy = b.point[0] - a.point[0], b.point[1] - a.point[1]
        if math.hypot(dx, dy) == 0.0:
            return None
        return a.point, _unit(dx, dy)
    if a.point is not None:
        return a.point, b.direction
    if b.point is not None:
        return b.point, a.direction
    return None


def _cross(l1, l2, scale):
    """Where two lines meet: ('point', xy, sine), ('infinity', direction, 0.0) for parallel
    lines, or None for one line twice."""
    (p1, d1), (p2, d2) = l1, l2
    s = d1[0] * d2[1] - d1[1] * d2[0]
    wx, wy = p2[0] - p1[0], p2[1] - p1[1]
    if abs(s) <= PARALLEL:
        if abs(wx * d1[1] - wy * d1[0]) <= SAME * scale:
            return None  # the same line: no crossing
        return ("infinity", d1, 0.0)  # parallel lines meet at infinity along them
    t = (wx * d2[1] - wy * d2[0]) / s
    return ("point", (p1[0] + t * d1[0], p1[1] + t * d1[1]), abs(s))


def locate(sol, prefix: str = "I") -> "Centres":
    """Every instantaneous centre of the solved mechanism ``sol``, by Kennedy's theorem, and
    the angular velocities by the angular-velocity-ratio theorem. ``prefix``: the centres
    are labelled ``I13`` (the default) or, with ``prefix=""``, ``13``."""
    names = _body_names(sol)
    n = len(names)
    if n > MAX_BODIES:
        raise SceneError(
            f"{n} bodies have {n * (n - 1) // 2} instantaneous centres: more "
            f"than this tool lists (at most {MAX_BODIES} bodies)",
            file=sol.scene.file,
        )
    scale = max((math.hypot(*p) for p in sol.P.values()), default=1.0) or 1.0
    found = _primary(sol, names)
    order = sorted(found)
    warnings = []
    missing = [(i, j) for i in range(1, n + 1) for j in range(i + 1, n + 1) if (i, j) not in found]
    while True:
        while missing:
            # as a textbook goes: the next centre is the first that two lines locate well;
            # one that only nearly parallel lines locate waits until better lines are known
            pick, fallback = None, None
            for key in missing:
                c = _kennedy(key, found, n, scale)
                if c is None:
                    continue
                if c.point is None or c.condition >= TOL.warn:
                    pick = c
                    break
                if fallback is None or c.condition > fallback.condition:
                    fallback = c
            c = pick or fallback
            if c is None:
                break
            if c.point is not None and c.condition < TOL.singular:
                raise SingularStepError(
                    f"{c.label} is where {_words(c.lines[0])} and {_words(c.lines[1])} cross, "
                    f"at {crossing_angle(c.condition):.2g} deg (condition "
                    f"{c.condition:.2g}): the lines are nearly parallel, the centre far and "
                    f"ill-determined{_POLYGONS_STAND}",
                    step=f"centre {c.label}",
                )
            if c.point is not None and c.condition < TOL.warn:
                warnings.append(
                    f"centre {c.label}: its lines cross at "
                    f"{crossing_angle(c.condition):.3g} deg (condition "
                    f"{c.condition:.3g}): far and ill-conditioned"
                )
            key = (c.i, c.j)
            found[key] = c
            order.append(key)
            missing.remove(key)
        # every line through known centres coincides: one centre where the velocities
        # agree on that line, then Kennedy's theorem again
        if not missing or not _by_velocities(sol, names, found, order, missing, warnings):
            break
    if missing:
        raise SingularStepError(
            "Kennedy's theorem cannot locate "
            + ", ".join(f"I{i}{j}" for i, j in missing)
            + (
                " (two inputs: with two degrees of freedom a centre of two bodies depends on "
                "the ratio of the input speeds, and Kennedy's theorem does not reach it from "
                "the pins alone; the polygons give every velocity)"
                if sol.scene.input.second is not None
                else " (every pair of lines through known centres is the same line or lies at "
                "infinity)"
            ),
            step="centres",
        )
    omegas, ratio_from = _omegas(sol, names, found)
    if prefix != "I":
        found = _relabelled(found, order, prefix)
    return Centres(names, found, tuple(order), omegas, ratio_from, tuple(warnings), sol)


def _by_velocities(sol, names, found, order, missing, warnings):
    """The centres Kennedy's theorem leaves on one line (every line through known centres
    is the same line: a slotted lever at mid-stroke, its rod translating), located on it
    by the angular-velocity-ratio theorem read the other way: I_ij is the point whose
    velocity is the same as a point of i and of j, ``omega_i x (X - I_1i) = omega_j x
    (X - I_1j)``, with the omegas the ratio theorem gives from the centres already found.
    Moves the first it locates from ``missing`` into ``found`` and ``order``: True, or
    False where none can be."""
    try:
        w, frm = _omegas(sol, names, found)
    except (KeyError, SingularStepError):
        return False  # some omega cannot be had either: the caller says which are left

    def field(i, x):
        return _velocity_field(found, w, frm, i, x)

    big = max(abs(x) for x in w.values()) or 1.0

    def lines_of(key):
        i, j = key
        out = []
        for k in range(1, len(names) + 1):
            a, b = found.get((min(i, k), max(i, k))), found.get((min(k, j), max(k, j)))
            if k not in key and a is not None and b is not None and _line(a, b) is not None:
                out.append((a, b))
        return out

    # first the centres with the most lines (all the same line), in the textbook's order
    for key in sorted(missing, key=lambda kk: -len(lines_of(kk))):
        i, j = key
        lines = lines_of(key)
        if not lines:
            continue
        dw = w[i] - w[j]
        p0 = next(x.point for x in lines[0] if x.point is not None)  # a point of the line
        vi, vj = field(i, p0), field(j, p0)
        dx, dy = vj[0] - vi[0], vj[1] - vi[1]
        how = (
            "Kennedy's lines coincide: on that line where the two bodies' velocities "
            "are equal (angular-velocity ratio)"
        )
        cond = min(1.0, abs(dw) / big)
        if cond <= PARALLEL:
            continue  # the same omega (a relative translation): left to the refusal
        if cond < TOL.singular:
            raise SingularStepError(
                f"I{i}{j}: Kennedy's lines coincide and the two bodies' omegas differ by "
                f"{cond:.2g} of the largest: the centre is far and ill-determined"
                f"{_POLYGONS_STAND}",
                step=f"centre I{i}{j}",
            )
        if cond < TOL.warn:
            warnings.append(
                f"centre I{i}{j}: the two bodies' omegas differ by {cond:.3g} "
                "of the largest: far and ill-conditioned"
            )
        # v_i(p0) + omega_i k x (X - p0) = v_j(p0) + omega_j k x (X - p0):
        # k x (X - p0) = (dx, dy) / dw
        c = Centre(i, j, (p0[0] + dy / dw, p0[1] - dx / dw), None, how, (lines[0], lines[-1]), cond)
        found[key] = c
        order.append(key)
        missing.remove(key)
        return True
    return False


def _velocity_field(found, w, frm, i, x):
    """The velocity of the point x as a point of body i (from the centres and omegas)."""
    if i == 1:
        return (0.0, 0.0)
    c = found[(1, i)]
    if c.point is not None:
        return (-w[i] * (x[1] - c.point[1]), w[i] * (x[0] - c.point[0]))
    k = frm[i]  # a translating body: the velocity of its centre with k
    if isinstance(k, tuple):  # the driving block: its given velocity
        return k
    return _velocity_field(found, w, frm, k, found[(min(k, i), max(k, i))].point)


def _relabelled(found, order, prefix):
    """The centres labelled with another prefix (their lines and words too)."""
    out = {}
    for key in order:
        c = found[key]
        lines = tuple((out[(a.i, a.j)], out[(b.i, b.j)]) for a, b in c.lines)
        how = c.how
        if lines:
            how = (
                f"Kennedy: on the line {lines[0][0].label}-{lines[0][1].label} and the "
                f"line {lines[1][0].label}-{lines[1][1].label}"
            ) + (" (parallel: at infinity)" if c.point is None else "")
        out[key] = dataclasses.replace(c, lines=lines, how=how, prefix=prefix)
    return out


def _words(pair):
    (a, b) = pair
    return f"the line {a.label}-{b.label}"


def _kennedy(key, found, n, scale):
    i, j = key
    lines = []
    far = None  # two centres at infinity in two directions: the line at infinity
    for k in range(1, n + 1):
        if k in key:
            continue
        a, b = found.get((min(i, k), max(i, k))), found.get((min(k, j), max(k, j)))
        if a is None or b is None:
            continue
        ln = _line(a, b)
        if ln is not None:
            lines.append((ln, (a, b)))
        elif (
            a.point is None
            and b.point is None
            and abs(a.direction[0] * b.direction[1] - a.direction[1] * b.direction[0]) > PARALLEL
        ):
            far = (a, b)
    best = None
    for p in range(len(lines)):
        for q in range(p + 1, len(lines)):
            hit = _cross(lines[p][0], lines[q][0], scale)
            if hit is None:
                continue
            kind, where, cond = hit
            pairs = (lines[p][1], lines[q][1])
            how = (
                f"Kennedy: on the line {pairs[0][0].label}-{pairs[0][1].label} and the "
                f"line {pairs[1][0].label}-{pairs[1][1].label}"
            )
            if kind == "infinity":
                return Centre(i, j, None, where, how + " (parallel: at infinity)", pairs, 0.0)
            c = Centre(i, j, where, None, how, pairs, cond)
            if best is None or cond > best.condition:
                best = c
    if best is None and far is not None and lines:  # a line and the line at infinity (a
        (_, d), pair = lines[0]  # body that translates: the Scotch yoke)
        how = (
            f"Kennedy: on the line {pair[0].label}-{pair[1].label} and the line at "
            f"infinity through {far[0].label} and {far[1].label}: at infinity along the "
            "first"
        )
        return Centre(i, j, None, d, how, (pair, far), 0.0)
    return best


def _omegas(sol, names, found):
    """omega of every body, from the crank's by the angular-velocity-ratio theorem."""
    n = len(names)
    driver = sol.plan.steps[0]
    turning = driver.body_omega(sol)
    if turning is not None:  # a driving wheel: body 2 turns about its contact point
        w, frm = {1: 0.0, 2: turning}, {}
    elif driver.periodic:  # a crank: body 2 turns at the input's omega
        w, frm = {1: 0.0, 2: sol.scene.input.omega}, {}
    else:  # a block driven along its guide: body 2 translates at its given velocity
        w, frm = {1: 0.0, 2: 0.0}, {2: tuple(sol.V[driver.finds[0]])}

    def get(i, j):
        return found[(min(i, j), max(i, j))]

    def field(i, x):
        return _velocity_field(found, w, frm, i, x)

    pending = list(range(3, n + 1))
    while pending:
        done = False
        for j in list(pending):
            c1j = get(1, j)
            best = None
            for i in list(w):
                if i == j or (min(i, j), max(i, j)) not in found:
                    continue  # (not yet located: the omegas from the others)
                cij = get(i, j)
                if cij.point is None:
                    if c1j.point is not None and get(1, i).point is not None:
                        best = (float("inf"), i, w[i])  # the same omega (parallel motion)
                    continue
                if c1j.point is None:  # j translates
                    best = best or (float("inf"), i, 0.0)
                    continue
                rx, ry = cij.point[0] - c1j.point[0], cij.point[1] - c1j.point[1]
                r2 = rx * rx + ry * ry
                if r2 == 0.0:
                    continue
                vx, vy = field(i, cij.point)
                cand = (r2, i, (rx * vy - ry * vx) / r2)
                if best is None or cand[0] > best[0]:
                    best = cand
            if best is not None:
                _, i, wj = best
                w[j], frm[j] = wj, i
                pending.remove(j)
                done = True
        if not done:
            raise SingularStepError(
                "the angular velocities cannot be had from the centres "
                "(every body's centres with the known ones coincide)",
                step="centres",
            )
    return w, frm


def centres_dict(ic: Centres) -> dict:
    """The centres for the JSON contract: label -> bodies, position (m) or direction."""
    out = {}
    for key in ic.order:
        c = ic.centres[key]
        d = {"bodies": [ic.bodies[c.i - 1], ic.bodies[c.j - 1]], "how": c.how}
        if c.point is None:
            d["direction"] = list(c.direction)
        else:
            d["position"] = list(c.point)
        if not c.primary:
            d["condition"] = c.condition
        out[c.label] = d
    return out
