"""Class-III group (a triad): a plate with three vertices, each joined by a binary link to
a known point, its three vertices found at once. This module is the step (recognition,
assembly, the three phases, the words; the polygons with Goodman's auxiliary point are in
:mod:`.goodman`); its
loop equations, their Newton solution, the continuation of the scene's assembly and the
search of every assembly are in :mod:`.loop` (see its docstring for the formulas).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ...common.tolerances import SAME
from ...common.errors import AssemblyError
from ...common.numbers import in_units
from ..base import Step, sub, unit
from ..rounding import two_lines
from . import goodman
from .recognition import plate_of, triangle_offsets
from .loop import (
    Memo,
    acceleration,
    assemblies,
    condition,
    det3,
    flat,
    matrix,
    newton_step,
    scale,
    sign,
    solve3,
    solve_array,
    solve_scalar,
    velocity,
    vertices,
)

__all__ = [
    "Triad",
    "recognise",
    "solve3",
    "vertices",
    "velocity",
    "acceleration",
    "condition",
    "newton_step",
    "assemblies",
]


# --------------------------------------------------------------------------- recognition


def recognise(g, name):
    """The triad finding ``name`` (:func:`.recognition.plate_of`: a plate, or three links
    in a triangle, whose three vertices each hang on one link from a known point), or None;
    no other kind can find any point when this is tried."""
    found = plate_of(g, name)
    return None if found is None else Triad(g.next_index, unit=g.unit, uname=g.uname, **found)


def _any_assembly(K, prm, np):
    """(x, y, th, bad): an assembly of each element, if any (a step whose assembly is not
    chosen yet: where can the crank be set so that it assembles at all)."""
    cols = [np.asarray(c, dtype=float) for xy in K for c in xy] + [
        np.asarray(p, dtype=float) for p in prm
    ]
    n = max([c.size for c in cols] + [1])
    cols = [np.broadcast_to(c, (n,)) if c.ndim else np.full(n, float(c)) for c in cols]
    out = np.zeros((3, n))
    bad = np.ones(n, dtype=bool)
    for i in range(n):
        v = [float(c[i]) for c in cols]
        found = assemblies(((v[0], v[1]), (v[2], v[3]), (v[4], v[5])), tuple(v[6:]))
        if found:
            out[:, i] = found[0]
            bad[i] = False
    return out[0], out[1], out[2], bad


# --------------------------------------------------------------------------- the step


@dataclass(frozen=True)
class Triad(Step):
    """A class-III group: plate ``plate`` with vertices ``points`` joined by ``links`` of
    ``lengths`` to the known points ``knowns`` (see the module). ``offsets``: V2 - V1 and
    V3 - V1 on the plate (its own frame). ``start``: the scene's assembly (inputs, pose,
    sign of det M), chosen when compiling; ``count``: how many assemblies there are."""

    points: tuple
    plate: str
    knowns: tuple
    links_: tuple
    lengths: tuple
    offsets: tuple
    sigma: float = 1.0  # one assembly is followed by continuation, never flipped
    unit: float = 1e-3
    uname: str = "mm"
    start: tuple = ()
    count: int = 0
    #: a plate made of three links: the other two sides, (key, from, to) each, and the
    #: side of V1 -> V2 its third vertex is on (chosen when compiling: two assemblies each)
    sides: tuple = ()
    hand: float = 1.0
    memo: object = field(default=None, compare=False, repr=False)

    kind = "triad"
    branching = True
    other_assembly_mistake = True

    def __post_init__(self):
        if self.start and self.memo is None:
            object.__setattr__(self, "memo", Memo(self.start))

    # ----- what it is
    @property
    def finds(self):
        """Its three vertices, found at once."""
        return self.points

    @property
    def links(self):
        """The plate (and a plate of three links' other sides) and the three links that hang it from
        the known points."""
        return (self.plate,) + tuple(k for k, _, _ in self.sides) + self.links_

    @property
    def needs(self):
        """The known points the three links hang from."""
        return tuple(dict.fromkeys(self.knowns))

    @property
    def needs_links(self):
        """None: it reads no other link's omega."""
        return ()

    @property
    def title(self):
        """``triad: plate BC (B, C, E) on AB, CD, FE``."""
        return f"triad: {self._plate_words} ({', '.join(self.points)}) on {', '.join(self.links_)}"

    @property
    def _plate_words(self):
        """``plate BC``, or ``plate BC, CD, DB`` for a plate of three links."""
        return "plate " + ", ".join((self.plate,) + tuple(k for k, _, _ in self.sides))

    @property
    def params(self):
        """The three links' lengths, then the vertices' offsets on the plate (V2 - V1, V3 - V1)."""
        return tuple(self.lengths) + tuple(self.offsets)

    def dimensions(self, scene, bodies):
        """The same read from another scene of the same shape: the links' lengths and the plate's
        offsets (a triangle of links': from its three sides)."""
        own = tuple(
            bodies.distance(k, K, V) for k, K, V in zip(self.links_, self.knowns, self.points)
        )
        if self.sides:
            p1, p2, _ = self.points
            (k2, a2, b2), (k3, a3, b3) = self.sides
            return own + triangle_offsets(
                bodies.distance(self.plate, p1, p2),
                bodies.distance(k2, a2, b2),
                bodies.distance(k3, a3, b3),
                self.hand,
            )
        f = bodies.frame(self.plate)
        (x1, y1), (x2, y2), (x3, y3) = (f[p] for p in self.points)
        return own + (x2 - x1, y2 - y1, x3 - x1, y3 - y1)

    def drawn(self, prm, pencil, P):
        """The dimensions as a hand drawing sets them out, each with the pencil's error."""
        return tuple(v + pencil() for v in prm)

    def reach(self):
        """The triad's size (the largest of its lengths and offsets): a scale for its tolerances."""
        return scale(self.params)

    # ----- compiling: the assembly the scene states
    def assemble(self, g):
        """(the step with its assembly, {vertex: position}) at the compiler's instant: every
        assembly is found; the [assembly] hints of the vertices choose one (a rough position
        [x, y]: the nearest; above/below/left/right: the extreme one), else the one with the
        first vertex highest (stated in the notes)."""
        K = tuple(g.P[k] for k in self.knowns)
        prm = self.params
        found = assemblies(K, prm)
        hands = [self.hand] * len(found)
        if self.sides:  # a triangle of links: its mirror image assembles too
            mirror = prm[:6] + (-prm[6],)
            more = assemblies(K, mirror)
            found += more
            hands += [-self.hand] * len(more)
        if not found:
            raise AssemblyError(self.why(), step=self.label)
        prms = [prm if h == self.hand else prm[:6] + (-prm[6],) for h in hands]
        places = [
            dict(zip(self.points, vertices(*q, pr, math.cos, math.sin)))
            for q, pr in zip(found, prms)
        ]
        hints = {p: g.scene.assembly[p] for p in self.points if p in g.scene.assembly}
        size = self.reach()
        coords = {p: h for p, h in hints.items() if isinstance(h, tuple)}
        if coords:
            d = [sum(math.dist(pl[p], h) ** 2 for p, h in coords.items()) ** 0.5 for pl in places]
            order = sorted(range(len(found)), key=d.__getitem__)
            best = order[0]
            key = f"[assembly] {', '.join(coords)}"
            if d[best] > size:
                raise AssemblyError(
                    f"assembly {', '.join(coords)} matches no assembly of the triad "
                    f"({self._listed(places, coords)}); give rough positions near the one "
                    "the figure shows",
                    key=key,
                    file=g.scene.file,
                )
            if len(order) > 1:
                sep = max(math.dist(places[best][p], places[order[1]][p]) for p in coords)
                if d[order[1]] - d[best] <= 0.1 * sep:
                    raise AssemblyError(
                        f"assembly {', '.join(coords)} is as near one assembly of the triad "
                        f"as another ({self._listed(places, coords)}): give rough positions "
                        "nearer the one the figure shows",
                        key=key,
                        file=g.scene.file,
                    )
        elif hints:
            p, h = next(iter(hints.items()))
            axis, want = {"above": (1, 1), "below": (1, -1), "right": (0, 1), "left": (0, -1)}[h]
            best = max(range(len(found)), key=lambda i: places[i][p][axis] * want)
        else:
            p = self.points[0]
            best = max(range(len(found)), key=lambda i: (places[i][p][1], places[i][p][0]))
            if len(found) > 1:
                g.notes.append(
                    f"{', '.join(self.points)}: of the triad's {len(found)} assemblies the one "
                    f"with {p} highest was taken (default; set [assembly] {p} = [x, y] to a "
                    "rough position to choose)"
                )
        q, prm = found[best], prms[best]
        det = newton_step(q, K, prm, math.cos, math.sin)[2]
        chosen = Triad(
            self.index,
            self.points,
            self.plate,
            self.knowns,
            self.links_,
            self.lengths,
            prm[3:],
            self.sigma,
            self.unit,
            self.uname,
            (flat(K, prm), q, sign(det)),
            len(found),
            sides=self.sides,
            hand=hands[best],
        )
        return chosen, places[best]

    def _listed(self, places, coords):
        u, n = self.unit, self.uname
        return "; ".join(
            ", ".join(f"{p} [{in_units(pl[p][0], u)}, {in_units(pl[p][1], u)}]" for p in coords)
            + f" {n}"
            for pl in places
        )

    # ----- evaluation
    def place(self, P, prm, ctx, sigma=None):
        """The three vertices at the compiler's instant, continued from the scene's assembly (the
        loop equations solved by Newton's method)."""
        K = tuple(P[k] for k in self.knowns)
        q = solve_scalar(self.memo, K, prm)
        if q is None:
            raise AssemblyError(self.why(), step=self.label)
        V = vertices(*q, prm, math.cos, math.sin)
        return V[0][0], V[0][1], condition(V, K)

    def positions(self, P, ctx):
        """Place the triad's three points into ``P`` for one instant (the assembly followed from the
        memo of poses already solved); refused when none exists."""
        K = tuple(P[k] for k in self.knowns)
        q = solve_scalar(self.memo, K, self.params)
        if q is None:
            raise AssemblyError(self.why(), step=self.label)
        V = vertices(*q, self.params, math.cos, math.sin)
        for p, xy in zip(self.points, V):
            P[p] = xy
        ctx.cond[self.index] = condition(V, K)

    @property
    def point(self):
        """The first vertex: where the checker's other-assembly mistake is hinted."""
        return self.points[0]

    def candidates(self, P, ctx):
        """(midpoint, half the vector from the other to this) of the first vertex, between
        this assembly and the nearest other one of the triad at ``P`` (no other: a zero
        half-vector)."""
        K = tuple(P[k] for k in self.knowns)
        here = tuple(P[p] for p in self.points)
        best = None
        for h in (1.0, -1.0) if self.sides else (1.0,):
            prm = self.params[:6] + (h * self.params[6],)
            for q in assemblies(K, prm):
                V = vertices(*q, prm, math.cos, math.sin)
                d = sum(math.dist(a, b) for a, b in zip(V, here))
                if d > SAME * self.reach() and (best is None or d < best[0]):
                    best = (d, V[0])
        x, y = here[0]
        if best is None:
            return (x, y), (0.0, 0.0)
        ox, oy = best[1]
        return ((x + ox) / 2, (y + oy) / 2), ((x - ox) / 2, (y - oy) / 2)

    def bind(self, prm):
        """The three phases: positions by continuation of the assembly (one instant) or by solving
        each element (arrays), then the 3 x 3 loop equations for the velocities and the
        accelerations."""
        pts, kn, i, step = self.points, self.knowns, self.index, self
        plate, lk = self.plate, self.links_
        sides = tuple(k for k, _, _ in self.sides)

        def position(m):
            K = tuple(m.P[k] for k in kn)
            if m.array:
                np = m.ctx.np
                if step.memo is None:  # no assembly chosen (the compiler's search of
                    x, y, th, bad = _any_assembly(K, prm, np)  # where it assembles)
                else:
                    x, y, th, bad = solve_array(step.memo, K, prm, np)
                if bad.any():
                    m.ctx.fail(step, bad)
                V = vertices(x, y, th, prm, np.cos, np.sin)
                with np.errstate(all="ignore"):
                    c = condition(V, K)
                c = np.where(np.isfinite(c), c, 0.0)
            else:
                q = solve_scalar(step.memo, K, prm)
                if q is None:
                    raise AssemblyError(step.why(), step=step.label)
                V = vertices(*q, prm, math.cos, math.sin)
                c = condition(V, K)
            for p, xy in zip(pts, V):
                m.P[p] = xy
            m.cond[i] = c

        def parts(m):
            V = tuple(m.P[p] for p in pts)
            K = tuple(m.P[k] for k in kn)
            if m.array:  # a singular entry (masked) must not divide by zero
                np = m.ctx.np
                d = det3(matrix(V, K))
                zero = d == 0
                if np.any(zero):
                    m.ctx.fail(step, zero)
                    V = tuple(
                        (np.where(zero, vx + 1e-3 * (j + 1), vx), vy)
                        for j, (vx, vy) in enumerate(V)
                    )
            return V, K

        def velocity_(m):
            V, K = parts(m)
            w, vv, wl = velocity(V, K, tuple(m.V[k] for k in kn))
            for p, v in zip(pts, vv):
                m.V[p] = v
            m.W[plate] = w
            for k in sides:
                m.W[k] = w
            for k, wk in zip(lk, wl):
                m.W[k] = wk

        def acceleration_(m):
            V, K = parts(m)
            al, aa, all_ = acceleration(
                V,
                K,
                tuple(m.V[p] for p in pts),
                tuple(m.V[k] for k in kn),
                tuple(m.A[k] for k in kn),
                m.W[plate],
            )
            for p, a in zip(pts, aa):
                m.A[p] = a
            m.Al[plate] = al
            for k in sides:
                m.Al[k] = al
            for k, ak in zip(lk, all_):
                m.Al[k] = ak

        return position, velocity_, acceleration_

    def bind_instant(self, prm):
        """The default one-instant road: its three phases in a row."""
        return Step.bind_instant(self, prm)

    rounding = 96.0

    def error_bound(self, walk, k, p_in, v_in, a_in):
        """The rule of two direction lines with the triad's condition: Newton's positions
        are exact to rounding, and one 3x3 solve at condition c multiplies the errors it
        is given by about 1/c."""
        return two_lines(walk.condition(self), walk.ratio, k, p_in, v_in, a_in)

    # ----- words
    def _lines(self):
        return ", ".join(f"{K}{V}" for K, V in zip(self.knowns, self.points))

    def why(self, e=None):
        """Why the triad cannot assemble at this crank angle: no pose reaches its links, or its
        assembly ended at a limit."""
        if not self.start:  # no assembly chosen yet: none exists here
            return (
                f"cannot assemble the triad {', '.join(self.points)}: no position of the "
                f"{self._plate_words} reaches the links {', '.join(self.links_)} from "
                f"{', '.join(self.knowns)} at this crank angle"
            )
        return (
            f"cannot assemble the triad {', '.join(self.points)}: its assembly ends before "
            f"this crank angle (a limit of the triad, where the lines of "
            f"{self._lines()} meet in one point)"
        )

    def singular_why(self, c) -> str:
        """Why it is singular: the three links' lines meet in one point (a limit of the triad)."""
        return (
            f"the lines of {self._lines()} meet in one point (or are parallel; condition "
            f"{c:.2g}): the {self._plate_words} could turn about that point while the "
            "links stand still, so its velocity is indeterminate (a limit position of "
            "the triad, where two of its assemblies meet)"
        )

    def warning(self, c) -> str:
        """The warning near a limit: the auxiliary-point construction is ill-conditioned."""
        return (
            f"{self.label}: the lines of {self._lines()} nearly meet in one point "
            f"(condition {c:.3g}): near a limit of the triad the auxiliary point "
            "construction is ill-conditioned"
        )

    def limit_why(self) -> str:
        """Why its motion ends: the three links' lines meet in one point."""
        return (
            f"the lines of {self._lines()} meet in one point (the triad "
            f"{', '.join(self.points)} cannot be assembled beyond it on its branch)"
        )

    def transmission(self):
        """None: a triad has no single transmission angle."""
        return None

    def condition_column(self):
        """The sweep's column of its condition (0 where the three links' lines meet in a point)."""
        return (
            f"cond {''.join(self.points)}",
            "",
            "triad condition (0: the three links' lines meet in a point)",
        )

    def bodies(self):
        """The bodies it moves: its links and its plate."""
        return (
            (self.links_[0], self.plate)
            + tuple(k for k, _, _ in self.sides)
            + (self.links_[1], self.links_[2])
        )

    def orient(self):
        """How the views draw each of its bodies: the plate from V1 to V2, each link from its vertex
        to its known point."""
        out = {self.plate: (self.points[1], self.points[0])}
        for k, a, b in self.sides:
            out[k] = (b, a)
        for k, K, V in zip(self.links_, self.knowns, self.points):
            out[k] = (V, K)
        return out

    def output(self, ground):
        """None: a triad is no output of the linkage's analysis."""
        return None

    def produced(self):
        """None: it draws no link produced."""
        return None

    def default_hint(self, P):
        """``above``: the hint where the scene gives none (the triad chooses its own assembly)."""
        return "above"

    def position_words(self, L, which, angle_deg):
        """The step table's words for its position: each vertex on the arc of its link about its
        known point, the plate's shape, and the assembly taken."""
        arcs = "; ".join(
            f"{V} on the arc of radius {k} = {L(l)} about {K}"
            for V, k, K, l in zip(self.points, self.links_, self.knowns, self.lengths)
        )
        return (
            f"{', '.join(self.points)} together (no one of them can be found alone): "
            f"{arcs}; the {self._plate_words} is fitted to the three arcs by trial (or "
            f"by the loop equations), the assembly of the figure"
            + (f" (one of {self.count})" if self.count > 1 else "")
        )

    # ----- the polygons (the auxiliary point construction)
    def _aux(self, P):
        """(i, j, m, S): the two links whose lines cross at the largest angle, where they
        cross (S, a point of the plate), and the third link."""
        V = [P[p] for p in self.points]
        K = [P[k] for k in self.knowns]
        best = None
        for i, j, m in ((0, 1, 2), (0, 2, 1), (1, 2, 0)):
            a, b = unit(*sub(V[i], K[i])), unit(*sub(V[j], K[j]))
            s = abs(a[0] * b[1] - a[1] * b[0])
            if best is None or s > best[0]:
                best = (s, i, j, m)
        _, i, j, m = best
        (ax, ay), (bx, by) = sub(V[i], K[i]), sub(V[j], K[j])
        den = ax * by - ay * bx
        wx, wy = K[j][0] - K[i][0], K[j][1] - K[i][1]
        t = (wx * by - wy * bx) / den if den else 0.0
        return i, j, m, (K[i][0] + t * ax, K[i][1] + t * ay)

    def auxiliary(self, P):
        """S, where the two links' lines that cross best meet, drawn from their fixed or
        known ends (the links produced)."""
        i, j, _, S = self._aux(P)
        return ((self._aux_name(P).upper(), S, (self.knowns[i], self.knowns[j])),)

    def _aux_name(self, names):
        taken = {p.lower() for p in names}
        if "s" not in taken:
            return "s"
        k = 1
        while f"s{k}" in taken:
            k += 1
        return f"s{k}"

    def _aux_label(self, sol):
        taken = {p.lower() for p in sol.scene.point_names}
        if "s" not in taken:
            return "s"
        k = 1
        while f"s{k}" in taken:
            k += 1
        return f"s{k}"

    def construction(self, sol, ph):
        """Goodman's auxiliary-point construction on the ``ph`` polygon (:mod:`.goodman`)."""
        return goodman.construction(self, sol, ph)
