"""An estimated bound on the rounding error of every quantity of a motion, from the
conditions of the steps it depends on (see ``docs/errors.md``, "How far an answer may be
off").

Every quantity is computed in double precision (unit roundoff ``EPS`` = 2^-53, about
1.1e-16). A step that intersects two direction lines (a dyad, a slider, a slotted link)
divides by its condition ``c`` (the sine of the angle between the lines, or the block's
distance from the pivot over the links that place them), so it multiplies the errors it is given,
and the rounding it makes itself, by ``g = 1/c``. Positions, velocities and accelerations
are carried step by step along the plan, each relative to the size of its kind in the
mechanism at that instant (``scales``, the same sizes the accuracy chart measures against):

Each kind's rule lives with the kind, in its step's ``error_bound`` (the steps package):
two direction lines by default (:mod:`polygon_method.steps.rounding`, ``eV ~ eps/c^2``,
``eA ~ eps/c^2`` to ``eps/c^3``); a dyad component by component (only the part of a
point's error along the link to it reaches the point it finds); a slotted link from the
lever's turn and the block's motion relative to the pivot; a crank relative to its tip's
own motion; a carried point from the two points it is carried by. ``K`` is the kind's
``rounding`` constant.

Every ``K eps`` is multiplied by ``max(1, largest |coordinate| / longest link)``: a
mechanism far from the origin is rounded to the digits of its coordinates. A step's own
rounding of velocities and accelerations is of its own numbers (``_Walk.own``): ``K eps``
times its own speeds and accelerations over the sizes of their kinds, and its positions'
error turns into its velocities' as its own links turn (``_Walk.couple``).
``eX_in`` is the largest error of that kind among the points (and link omegas) the step
reads. A link's omega and alpha get its step's ``eV`` and ``eA`` (a dyad's links and a
slider's rod at least those of the side that turns them, divided by its length); a slider's sliding
velocity ``eV``, its sliding acceleration and Coriolis component ``eA`` (a block on a
slotted link, its own). ``K`` was fitted on thousands of random mechanisms near every singular family against the 50-digit reference
and then given a margin (``benchmarks/error_bounds.py``). The same formulas take floats
(one instant) or numpy arrays (a sweep).
"""

from __future__ import annotations

from ..common.tolerances import SAME
from .compiler import compile_plan
from .kinematics import hypot
from ..steps.rounding import CAP, C_FLOOR, EPS, USELESS, largest, vmax, vmin

__all__ = [
    "EPS",
    "C_FLOOR",
    "ErrorBounds",
    "error_bounds",
    "scales",
    "bounds_dict",
    "shown_bounds",
    "SHOWN",
    "USELESS",
    "NO_BOUND",
]

#: the text report shows a bound only above this (the promise of agreement everywhere else)
SHOWN = SAME
#: the reason given, in words and in the JSON, where a bound is no useful bound
NO_BOUND = (
    "no useful bound: the rounding carried along the steps a quantity depends on "
    "may reach its size (a long chain of steps, or ill-conditioned ones)"
)


def _cap(x):
    """``x`` saturated at :data:`CAP` (an undefined one too): floats or arrays, or a tuple
    of them (a step's bound for each of its links, kept a tuple)."""
    if isinstance(x, float):
        return x if x < CAP else CAP
    if isinstance(x, tuple):
        return tuple(_cap(e) for e in x)
    import numpy as np

    return np.fmin(x, CAP)


#: each kind's rounding constant is the ``rounding`` of its step class (fitted against the
#: 50-digit reference, with a margin); its rule, the step's ``error_bound``


def scales(motion) -> dict:
    """The size of each kind of quantity in the mechanism at each instant, the denominators
    of the relative bounds: position the longest link; velocity the largest point speed (at
    least omega r of the crank); acceleration the largest point acceleration (at least
    (omega^2 + |alpha|) r); omega the largest |omega| (at least the crank's); alpha the
    largest |alpha| (at least omega^2 + |alpha| of the crank)."""
    sc = motion.scene
    plan = getattr(motion, "plan", None) or compile_plan(sc)
    v0, a0, w, w2 = plan.steps[0].input_scales(sc)  # the driver's (crank or block)
    return {
        "position": max(lk.length for lk in sc.links),
        "velocity": vmax(v0, largest([hypot(*v) for v in motion.V.values()])),
        "acceleration": vmax(a0, largest([hypot(*a) for a in motion.A.values()])),
        "omega": vmax(w, largest([abs(x) for x in motion.W.values()])),
        "alpha": vmax(w2, largest([abs(x) for x in motion.Al.values()])),
    }


class ErrorBounds:
    """Relative error bounds of a motion's quantities (floats, or arrays over a sweep).

    ``P, V, A``: point -> bound of its position, velocity, acceleration (the error of the
    vector over the size of its kind); ``W, Al``: link key -> omega, alpha; ``S``: slider
    point -> (sliding velocity, sliding acceleration, Coriolis); ``scales``: the sizes the
    bounds are relative to (:func:`scales`). ``worst``: the largest bound of all.
    """

    __slots__ = ("P", "V", "A", "W", "Al", "S", "scales")

    def __init__(self, P, V, A, W, Al, S, sizes):
        self.P, self.V, self.A, self.W, self.Al, self.S = P, V, A, W, Al, S
        self.scales = sizes

    @property
    def worst(self):
        """The largest relative bound of any answer."""
        vals = [
            *self.P.values(),
            *self.V.values(),
            *self.A.values(),
            *self.W.values(),
            *self.Al.values(),
            *(b for t in self.S.values() for b in t),
        ]
        return largest(vals) if vals else EPS

    def rubbing(self, pin) -> object:
        """Bound of a pin's rubbing velocity, relative to omega_scale times its radius:
        the largest, over the pairs of links it joins, of the sum of their omegas' bounds
        (the rubbing is the difference of the two omegas; ``pin``: an entry of
        plan.pins)."""
        b = []
        for pair in pin[5]:
            terms = [self.W.get(lk, 0.0) for lk in pair if lk is not None]
            if terms:
                b.append(terms[0] + terms[1] if len(terms) == 2 else terms[0])
        return largest(b) if b else 0.0

    def torque(self, scene) -> object:
        """Bound of the input torque, relative to the sum over the loads of |F| times the
        velocity scale (|T| times the omega scale) divided by the crank's |omega|."""
        b = []
        for load in scene.loads:
            if load.force is not None:
                b.append(self.V.get(load.target, 0.0) + self._turned(scene, load))
            else:
                b.append(self.W.get(scene.link(load.target).key, 0.0))
        return largest(b) if b else 0.0

    def _turned(self, scene, load) -> object:
        """A force stated against a link: its direction's error (rad), from its two
        points' positions' errors over their distance (0 for any other force)."""
        if load.across is None:
            return 0.0
        a, b = load.across[:2]
        if a in scene.ground and b in scene.ground:
            return 0.0  # (a line of the frame: given)
        n = scene.link(f"{a}-{b}").length
        return (self.P.get(a, 0.0) + self.P.get(b, 0.0)) * (self.scales["position"] / n)


class _Boxes(dict):
    """(phase, point) -> (error along x, error along y); a point a dyad did not find has
    its scalar bound in both."""

    def __init__(self, eP, eV, eA):
        super().__init__()
        self.tables = (eP, eV, eA)

    def of(self, phase, point):
        b = self.get((phase, point))
        if b is None:
            e = self.tables[phase].get(point, 0.0)
            return e, e
        return b


class _Walk:
    """What a step's ``error_bound`` reads: the motion and its points (``P, V, A``), the
    sizes the bounds are relative to (``sizes``, ``ratio``), each point's error along x
    and y (``box``) and the blocks' sliding bounds a step finds (``slide``)."""

    def __init__(self, motion, sizes, box):
        self.motion, self.sizes, self.box = motion, sizes, box
        self.P, self.V, self.A = motion.P, motion.V, motion.A
        self.ratio = sizes["omega"] ** 2 / sizes["alpha"]
        self.slide = {}
        self._local = {}
        #: carried point -> how far its place on its body may be off (m), where not 0
        self.spread = {
            cp.name: cp.spread for cp in motion.scene.points if getattr(cp, "spread", 0.0)
        }

    def condition(self, step):
        return self.motion.cond.get(step.index, 1.0)

    def local(self, step):
        """The step's own magnitudes, each over the size of its kind (at most 1): ``fv``
        its largest point speed plus its links' |omega| times its span; ``fa`` its largest
        point acceleration plus its links' (omega^2 + |alpha|) times its span plus a
        Coriolis component (2 |omega| times its speeds); ``wv`` its
        links' largest |omega| times the size of positions over the size of velocities
        (how a position error turns into a velocity error through a direction line),
        ``wa`` likewise (omega^2 + |alpha|) into accelerations, ``wr`` twice that |omega|
        times the size of velocities over the size of accelerations (how a velocity error
        turns into an acceleration error: ``2 omega dv``). A step's own rounding is
        ``eps`` times the numbers it combines, not times the largest in the mechanism."""
        got = self._local.get(step.index)
        if got is not None:
            return got
        m, sz = self.motion, self.sizes
        pts = [x for x in (*step.needs, *step.finds) if x in self.P and x in self.V]
        links = [lk for lk in (*step.links, *step.needs_links) if lk in m.W]
        span = 0.0
        for i, x in enumerate(pts):
            for y in pts[i + 1 :]:
                span = vmax(span, hypot(self.P[x][0] - self.P[y][0], self.P[x][1] - self.P[y][1]))
        w = largest([abs(m.W[lk]) for lk in links])
        w2 = largest([m.W[lk] * m.W[lk] + abs(m.Al[lk]) for lk in links if lk in m.Al])
        tiny = 1e-300
        vs, as_ = vmax(sz["velocity"], tiny), vmax(sz["acceleration"], tiny)
        speed = largest([hypot(*self.V[x]) for x in pts])
        fv = (speed + w * span) / vs
        fa = (
            largest([hypot(*self.A[x]) for x in pts if x in self.A])
            + w2 * span
            + 2 * w * (speed + w * span)
        ) / as_
        ls = sz["position"]
        got = (vmin(fv, 1.0), vmin(fa, 1.0), w * ls / vs, w2 * ls / as_, 2 * w * vs / as_)
        self._local[step.index] = got
        return got

    def own(self, step, k):
        """(kp, kv, ka): the step's own rounding ``k`` (relative to the size of positions)
        for its positions, and for its velocities and accelerations scaled by the step's
        own speeds and accelerations (:meth:`local`)."""
        fv, fa = self.local(step)[:2]
        return k, k * fv, k * fa

    def couple(self, step):
        """(cv, ca, cr) for :func:`..steps.rounding.two_lines`: how a position error turns
        into a velocity and an acceleration error, and a velocity error into an
        acceleration error, through the step's own links (:meth:`local`), at most what
        the sizes of the mechanism give (1, 1 and ``ratio``)."""
        wv, wa, wr = self.local(step)[2:]
        return vmin(wv, 1.0), vmin(wa, 1.0), vmin(wr, self.ratio)


def error_bounds(motion) -> ErrorBounds:
    """The :class:`ErrorBounds` of ``motion`` (a solution or a sweep, with accelerations):
    rounding carried along the plan's steps, each step multiplying by 1/condition."""
    plan, P = motion.plan, motion.P
    sizes = scales(motion)
    eP, eV, eA, eW, eAl, eS = {}, {}, {}, {}, {}, {}
    walk = _Walk(motion, sizes, _Boxes(eP, eV, eA))

    def worst(table, names, other=None, links=()):
        vals = [table[n] for n in names if n in table]
        if other is not None:
            vals += [other[lk] for lk in links if lk in other]
        return largest(vals) if vals else 0.0

    # coordinates far from the origin, compared with the links, are rounded to the digits
    # of the coordinates: every rounding is that much larger, relative to the links
    far = largest([hypot(*xy) for xy in P.values()]) / sizes["position"]
    far = vmax(far, 1.0)
    for st in plan.steps:  # each kind's rule is its step's error_bound
        needs, nlinks = st.needs, st.needs_links
        p, v, a, w, al = st.error_bound(
            walk,
            st.rounding * EPS * far,
            worst(eP, needs),
            worst(eV, needs, eW, nlinks),
            worst(eA, needs, eAl, nlinks),
        )
        p, v, a, w, al = _cap(p), _cap(v), _cap(a), _cap(w), _cap(al)
        for x in st.finds:
            eP[x], eV[x], eA[x] = p, v, a
        if isinstance(w, tuple):  # one bound for each of its links
            for lk, wi, ali in zip(st.links, w, al):
                eW[lk], eAl[lk] = wi, ali
        else:
            for lk in st.links:
                eW[lk], eAl[lk] = w, al
    slide = walk.slide
    for lk in motion.W:  # the crank's omega and alpha are given; fixed links do not turn
        eW.setdefault(lk, EPS)
        eAl.setdefault(lk, EPS)
    for g in motion.scene.ground:
        eP.setdefault(g, 0.0)
        eV.setdefault(g, 0.0)
        eA.setdefault(g, 0.0)
    scene = motion.scene
    for s in scene.sliders:  # the block's point, and the guide's turning when it moves
        x = s.point
        if x not in eV:
            continue
        if s.key in slide:
            eS[s.key] = slide[s.key]
            continue
        v, a = eV[x], eA[x]
        guide = getattr(s, "guide", None)
        if guide is not None:
            key = scene.link(guide).key
            v, a = vmax(v, eW.get(key, 0.0)), vmax(a, eAl.get(key, 0.0))
        eS[s.key] = (v, a, a)
    for cyl in scene.cylinders:  # its rate of extension, as a slider's sliding velocity
        if cyl.key in slide:
            eS[cyl.key] = slide[cyl.key]
    res = getattr(plan, "given", None)
    if res is not None:
        _given_spread(motion, res, sizes, eV, eA, eW, eAl, eS)
        for t in (eV, eA, eW, eAl):
            for k in t:
                t[k] = _cap(t[k])
        eS.update((k, tuple(_cap(x) for x in t)) for k, t in eS.items())
    return ErrorBounds(eP, eV, eA, eW, eAl, eS, sizes)


def _given_spread(motion, res, sizes, eV, eA, eW, eAl, eS):
    """The crank's speed found from a given motion (``omega = Y / Y1``) errs as ``Y1``
    does, relative to ``Y``: every velocity and omega (proportional to omega) by that
    much relative to itself; every acceleration and alpha twice that, plus the error of the given quantity's
    rate carried through ``alpha = (Y' - omega^2 H) / Y1``."""
    g = motion.scene.input.given
    if g.kind == "omega":
        key = motion.scene.link("-".join(g.names)).key
        ev, ea, kv, ka = eW.get(key, EPS), eAl.get(key, EPS), "omega", "alpha"
        y = abs(motion.W[key])
    elif g.kind == "vs":
        ev, ea, _ = eS.get(g.names[0], (EPS,) * 3)
        kv, ka = "velocity", "acceleration"
        y = abs(motion.S[g.names[0]][0])
    else:
        ev, ea, kv, ka = eV[g.names[0]], eA[g.names[0]], "velocity", "acceleration"
        y = hypot(*motion.V[g.names[0]])
    y = vmax(y, sizes[kv] * 1e-300)
    rw = ev * sizes[kv] / y + 2 * EPS
    time = vmax(sizes["velocity"] / sizes["acceleration"], sizes["omega"] / sizes["alpha"])
    ra = ea * sizes[ka] / y * time + 2 * rw
    # every velocity and omega is omega times what it is per unit omega: each errs by rw
    # relative to itself, that is rw times its own size over the size of its kind
    vs, ws = vmax(sizes["velocity"], 1e-300), vmax(sizes["omega"], 1e-300)
    for k in eV:
        eV[k] = eV[k] + rw * vmin(hypot(*motion.V[k]) / vs, 1.0) if k in motion.V else eV[k] + rw
    for k in eW:
        eW[k] = eW[k] + rw * vmin(abs(motion.W[k]) / ws, 1.0) if k in motion.W else eW[k] + rw
    for t in (eA, eAl):
        for k in t:
            t[k] = t[k] + ra
    for k, (v, a, c) in eS.items():
        own = vmin(abs(motion.S[k][0]) / vs, 1.0) if k in motion.S else 1.0
        eS[k] = (v + rw * own, a + ra, c + ra)


def bounds_dict(sol, b=None) -> dict:
    """The ``error_bounds`` object of ``solve --json``: each quantity's bound, keyed as the
    quantities themselves, and the sizes they are relative to (``b``: the bounds, if
    already computed)."""
    b = error_bounds(sol) if b is None else b
    sc = sol.scene
    d = {
        "relative_to": {k: float(v) for k, v in b.scales.items()},
        "points": {
            p: {"position": b.P[p], "velocity": b.V[p], "acceleration": b.A[p]}
            for p in sc.point_names
        },
        "links": {
            lk.key: {"omega": b.W.get(lk.key, EPS), "alpha": b.Al.get(lk.key, EPS)}
            for lk in sc.links
        },
    }
    if sc.blocks:
        d["sliders"] = {
            s.key: dict(
                zip(
                    ("sliding_velocity", "sliding_acceleration", "coriolis"),
                    b.S.get(s.key, (EPS,) * 3),
                )
            )
            for s in sc.blocks
        }
    if sc.wheel_paths:  # a driving wheel's centre along its line, keyed as in `rolling`
        d["rolling"] = {
            s.wheel: dict(
                zip(("centre_velocity", "centre_acceleration"), b.S.get(s.key, (EPS,) * 2))
            )
            for s in sc.wheel_paths
        }
    if sc.pins:
        d["pins"] = {pin[0]: {"rubbing_velocity": b.rubbing(pin)} for pin in sol.plan.pins}
    if sc.loads and sc.input.second is None:
        d["input_torque"] = b.torque(sc)
    d["worst"] = b.worst
    return d


def shown_bounds(sol, b=None) -> list:
    """(quantity, bound) of every quantity whose bound exceeds :data:`SHOWN`, largest
    first, for the text report (``b``: the bounds, if already computed)."""
    b = error_bounds(sol) if b is None else b
    out = []
    for p in sol.scene.point_names:
        for what, t in (("position", b.P), ("velocity", b.V), ("acceleration", b.A)):
            if t.get(p, 0.0) > SHOWN:
                out.append((f"{what} of {p}", t[p]))
    for lk in sol.scene.links:
        for what, t in (("omega", b.W), ("alpha", b.Al)):
            if t.get(lk.key, 0.0) > SHOWN:
                out.append((f"{what} of {lk.key}", t[lk.key]))
    for x, t in b.S.items():
        for what, v in zip(("sliding velocity", "sliding acceleration", "Coriolis"), t):
            if v > SHOWN:
                out.append((f"{what} of {x}", v))
    if sol.scene.pins:
        for pin in sol.plan.pins:
            if b.rubbing(pin) > SHOWN:
                out.append((f"rubbing at {pin[0]}", b.rubbing(pin)))
    if sol.scene.loads and sol.scene.input.second is None and b.torque(sol.scene) > SHOWN:
        out.append(("input torque", b.torque(sol.scene)))
    return sorted(out, key=lambda t: -t[1])
