"""An estimated bound on the rounding error of every quantity of a motion, from the
conditions of the steps it depends on (see ``docs/errors.md``, "How far an answer may be
off").

Every quantity is computed in double precision (unit roundoff ``EPS`` = 2^-53, about
1.1e-16). A step that intersects two direction lines (a dyad, a slider, a slotted link)
divides by its condition ``c`` (the sine of the angle between the lines, or the block's
distance from the pivot over the lever's length), so it multiplies the errors it is given,
and the rounding it makes itself, by ``g = 1/c``. Positions, velocities and accelerations
are carried step by step along the plan, each relative to the size of its kind in the
mechanism at that instant (``scales``, the same sizes the accuracy chart measures against):

* a dyad or a slider (RRR, RRP)::

      eP = g (K eps + eP_in)
      eV = g (K eps + eV_in + eP)                        -> about eps / c^2
      eA = g (K eps + eA_in + eP + R eV)                 -> eps / c^2 to eps / c^3

  where ``R = omega_scale^2 / alpha_scale``: where the velocities themselves grow like
  1/c (a toggle reached with the crank turning, a slider's dead centre) the accelerations
  grow faster still and the error relative to them is one power of c smaller (R ~ c); at a
  change point, where the motion stays finite, R ~ 1 and the acceleration's error grows
  like eps/c^3;
  a dyad carries its errors component by component (:func:`_dyad`): only the part of a
  point's error along the link to it reaches the point it finds;
* a slotted link (RPR): the lever's direction ``d = A - K`` over ``|d| = c L`` turns by
  ``turn = eP_in L_scale / |d| + K eps`` (only what the step is given is divided by c);
  omega ``= (vA - vK) x u / |d|``, the sliding velocity, alpha and the sliding
  acceleration follow from that turn and from the block's motion relative to the pivot
  (its size read from the motion), each as its own relative error (:func:`_slotted`):
  eps/c where the block slides slowly, an eps/c^2 part where it slides fast;
* a crank: ``K eps (|O| + r) / position_scale`` for its tip's position; its velocity and
  acceleration are computed from the tip's coordinates minus the pivot's, so
  ``K eps (|O| + |T|) / r`` of the tip's own velocity (omega r) and acceleration
  ((omega^2 + |alpha|) r);
* a carried point: the errors of the two points it is carried by, times
  ``1 + (|XN1| + |XN2|) / |N1N2|`` (how far out of its base it reaches), plus ``K eps``.

Every ``K eps`` is multiplied by ``max(1, largest |coordinate| / longest link)``: a
mechanism far from the origin is rounded to the digits of its coordinates.
``eX_in`` is the largest error of that kind among the points (and link omegas) the step
reads. A link's omega and alpha get its step's ``eV`` and ``eA``; a slider's sliding
velocity ``eV``, its sliding acceleration and Coriolis component ``eA`` (a block on a
slotted link, its own). ``K`` was fitted on
thousands of random mechanisms near every singular family against the 50-digit reference
and then given a margin (``benchmarks/error_bounds.py``). The same formulas take floats
(one instant) or numpy arrays (a sweep).
"""

from __future__ import annotations

from .kinematics import hypot

__all__ = ["EPS", "K", "ErrorBounds", "error_bounds", "scales", "bounds_dict",
           "shown_bounds", "SHOWN"]

#: the text report shows a bound only above this (the promise of agreement everywhere else)
SHOWN = 1e-9

#: unit roundoff of IEEE double precision
EPS = 2.0 ** -53
#: the constant of each kind of step (fitted against the 50-digit reference, with a margin)
K = {"crank": 8.0, "carried": 8.0, "dyad": 48.0, "slider": 48.0, "slotted": 16.0}
#: a step of a kind not listed here is bounded as a dyad (two direction lines)
K_OTHER = 48.0
#: the conditions are at least the refusal band's edge; never divide by less than this
C_FLOOR = 1e-12


def _max(a, b):
    if isinstance(a, float) and isinstance(b, float):
        return a if a >= b else b
    import numpy as np
    return np.maximum(a, b)


def _min(a, b):
    if isinstance(a, float) and isinstance(b, float):
        return a if a <= b else b
    import numpy as np
    return np.minimum(a, b)


def _sub(a, b):
    return (a[0] - b[0], a[1] - b[1])


def _abs(x):
    return abs(x)


def largest(values):
    """The largest of floats and arrays, entry by entry (0.0 for none)."""
    if not values:
        return 0.0
    if all(isinstance(v, float) for v in values):
        return max(values)
    import numpy as np
    best = np.zeros(np.broadcast_shapes(*(np.shape(v) for v in values)))
    for v in values:
        np.maximum(best, v, out=best)
    return best


def scales(motion) -> dict:
    """The size of each kind of quantity in the mechanism at each instant, the denominators
    of the relative bounds: position the longest link; velocity the largest point speed (at
    least omega r of the crank); acceleration the largest point acceleration (at least
    (omega^2 + |alpha|) r); omega the largest |omega| (at least the crank's); alpha the
    largest |alpha| (at least omega^2 + |alpha| of the crank)."""
    sc = motion.scene
    inp = sc.input
    r = sc.link(inp.crank).length
    w = abs(inp.omega)
    w2 = inp.omega ** 2 + abs(inp.alpha)
    return {
        "position": max(lk.length for lk in sc.links),
        "velocity": _max(w * r, largest([hypot(*v) for v in motion.V.values()])),
        "acceleration": _max(w2 * r, largest([hypot(*a) for a in motion.A.values()])),
        "omega": _max(w, largest([_abs(x) for x in motion.W.values()])),
        "alpha": _max(w2, largest([_abs(x) for x in motion.Al.values()])),
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
        vals = [*self.P.values(), *self.V.values(), *self.A.values(), *self.W.values(),
                *self.Al.values(), *(b for t in self.S.values() for b in t)]
        return largest(vals) if vals else EPS

    def rubbing(self, pin) -> object:
        """Bound of a pin's rubbing velocity, relative to omega_scale times its radius:
        the largest omega bound of the links it joins (``pin``: an entry of plan.pins)."""
        b = [self.W.get(lk, 0.0) for pair in pin[5] for lk in pair if lk is not None]
        return largest(b) if b else 0.0

    def torque(self, scene) -> object:
        """Bound of the input torque, relative to the sum over the loads of |F| times the
        velocity scale (|T| times the omega scale) divided by the crank's |omega|."""
        b = []
        for load in scene.loads:
            if load.force is not None:
                b.append(self.V.get(load.target, 0.0))
            else:
                b.append(self.W.get(scene.link(load.target).key, 0.0))
        return largest(b) if b else 0.0


def _carried_gain(P, x, a, b):
    """1 + (|XA| + |XB|) / |AB|: how far out of its base a carried point reaches."""
    (px, py), (ax, ay), (bx, by) = P[x], P[a], P[b]
    base = hypot(bx - ax, by - ay)
    return 1.0 + (hypot(px - ax, py - ay) + hypot(px - bx, py - by)) / base


def _slotted(motion, sizes, st, k, p_in, v_in, a_in):
    """(eP, eV, eA of the lever's end, eW, eAl of the lever, the block's sliding (e_vs,
    e_as, e_coriolis)) of a slotted link: the lever's direction is d = A - K over |d|, so
    the error of d (its points' error) turns it by that over |d| = c L; the block's motion
    relative to the pivot (e, e_a), turned so, errs by e times that angle; omega = e x u /
    |d| and alpha = e_a x u / |d| divide once more."""
    K_, A_ = st.needs[0], st.needs[1]
    P, V, A = motion.P, motion.V, motion.A
    Ls, Vs, As = sizes["position"], sizes["velocity"], sizes["acceleration"]
    Om, Als = sizes["omega"], sizes["alpha"]
    m = _max(hypot(*_sub(P[A_], P[K_])), C_FLOOR * Ls)
    n = st.finds[0]
    L = hypot(*_sub(P[n], P[K_]))
    vs = _abs(motion.S[A_][0]) if A_ in motion.S else Vs
    w = _abs(motion.W.get(st.links[0], 0.0)) if st.links else Om
    al = _abs(motion.Al.get(st.links[0], 0.0)) if st.links else Als
    e = hypot(*_sub(V[A_], V[K_]))
    ea = hypot(*_sub(A[A_], A[K_])) + w * w * m + 2 * w * vs
    turn = p_in * Ls / m + k                            # the lever's direction, rad
    d_w = (v_in * Vs + e * turn) / m + k * w           # omega, rad/s
    d_vs = v_in * Vs + e * turn + k * Vs               # sliding velocity, m/s
    d_al = (a_in * As + ea * turn + 2 * d_w * vs + 2 * w * d_vs) / m + k * al
    d_as = a_in * As + ea * turn + 2 * w * d_w * m + k * As
    d_cor = 2 * (d_w * vs + w * d_vs) + k * As
    p = k + p_in + turn * L / Ls
    v = k + (v_in * Vs + L * d_w + w * L * turn) / Vs
    a = k + (a_in * As + L * d_al + 2 * w * d_w * L + (w * w + al) * L * turn) / As
    return p, v, a, d_w / Om + k, d_al / Als + k, (d_vs / Vs, d_as / As, d_cor / As)


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


def _dyad(P, st, g, k, ratio, box):
    """A dyad's bounds, component by component. Linearised, ``r1 . dX = r1 . dB`` and
    ``r2 . dX = r2 . dD`` (the same two rows for positions, velocities and
    accelerations), so ``dX = (-(u1 . dB) perp(u2) + (u2 . dD) perp(u1)) / c``: only the
    component of B's error along XB, and of D's along XD, is carried, and it is carried
    across the other link. A chain of dyads then carries its errors without multiplying
    them by 1/c at every step where the geometry does not."""
    B, D = st.needs[0], st.needs[1]
    X = st.finds[0]
    (x, y), (bx, by), (dx, dy) = P[X], P[B], P[D]
    r1x, r1y, r2x, r2y = x - bx, y - by, x - dx, y - dy
    n1 = _max(hypot(r1x, r1y), 1e-300)
    n2 = _max(hypot(r2x, r2y), 1e-300)
    u1x, u1y, u2x, u2y = _abs(r1x / n1), _abs(r1y / n1), _abs(r2x / n2), _abs(r2y / n2)

    def carry(phase, own):
        """(bound of |dX|, (bound along x, bound along y)); ``own``: what the step adds
        in any direction."""
        table = box.tables[phase]
        ebx, eby = box.of(phase, B)
        edx, edy = box.of(phase, D)
        s1 = _min(u1x * ebx + u1y * eby, table.get(B, 0.0))  # |u . dB| <= |dB| too
        s2 = _min(u2x * edx + u2y * edy, table.get(D, 0.0))
        ex = g * (s1 * u2y + s2 * u1y + own)
        ey = g * (s1 * u2x + s2 * u1x + own)
        return g * (s1 + s2 + own), (ex, ey)

    p, bp = carry(0, k)
    v, bv = carry(1, k + p)
    a, ba = carry(2, k + p + ratio * v)
    return p, v, a, {(0, X): bp, (1, X): bv, (2, X): ba}


def error_bounds(motion) -> ErrorBounds:
    """The :class:`ErrorBounds` of ``motion`` (a solution or a sweep, with accelerations):
    rounding carried along the plan's steps, each step multiplying by 1/condition."""
    plan, cond, P = motion.plan, motion.cond, motion.P
    sizes = scales(motion)
    ratio = sizes["omega"] ** 2 / sizes["alpha"]
    eP, eV, eA, eW, eAl, eS = {}, {}, {}, {}, {}, {}
    slide = {}  # a block on a slotted link: its sliding, from its step
    box = _Boxes(eP, eV, eA)  # a dyad's errors by component (x, y)

    def worst(table, names, other=None, links=()):
        vals = [table[n] for n in names if n in table]
        if other is not None:
            vals += [other[lk] for lk in links if lk in other]
        return largest(vals) if vals else 0.0

    # coordinates far from the origin, compared with the links, are rounded to the digits
    # of the coordinates: every rounding is that much larger, relative to the links
    far = largest([hypot(*xy) for xy in P.values()]) / sizes["position"]
    far = _max(far, 1.0)
    for st in plan.steps:
        kind = st.kind
        k = K.get(kind, K_OTHER) * EPS * far
        needs, nlinks = st.needs, st.needs_links
        p_in = worst(eP, needs)
        v_in = worst(eV, needs, eW, nlinks)
        a_in = worst(eA, needs, eAl, nlinks)
        if kind == "crank":  # T = O + r (cos, sin), v = omega perp(T - O)
            (ox, oy), (tx, ty) = P[needs[0]], P[st.finds[0]]
            r = hypot(tx - ox, ty - oy)
            p = K.get(kind, K_OTHER) * EPS * (hypot(ox, oy) + r) / sizes["position"]
            gain = K.get(kind, K_OTHER) * EPS * _max((hypot(ox, oy) + hypot(tx, ty)) / r, 1.0)
            inp = motion.scene.input  # relative to the crank tip's own motion
            v = gain * _abs(inp.omega) * r / sizes["velocity"]
            a = gain * (inp.omega ** 2 + _abs(inp.alpha)) * r / sizes["acceleration"]
        elif kind == "carried":
            pair = [n for n in needs if n in P][:2]
            x = st.finds[0]
            gain = _carried_gain(P, x, *pair) if len(pair) == 2 and x in P else 1.0
            p, v, a = gain * p_in + k, gain * v_in + k, gain * a_in + k
        else:
            c = cond.get(st.index, 1.0)
            g = 1.0 / _max(c, C_FLOOR)
            if kind == "slotted":
                p, v, a, w, al, slide[needs[1]] = _slotted(motion, sizes, st, k, p_in,
                                                           v_in, a_in)
            elif kind == "dyad":
                p, v, a, boxes = _dyad(P, st, g, k, ratio, box)
                w, al = v, a
                box.update(boxes)
            else:
                p = g * (k + p_in)
                v = g * (k + v_in + p)
                a = g * (k + a_in + p + ratio * v)
                w, al = v, a
        if kind in ("crank", "carried"):
            w, al = v, a
        for x in st.finds:
            eP[x], eV[x], eA[x] = p, v, a
        for lk in st.links:
            eW[lk], eAl[lk] = w, al
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
        if x in slide:
            eS[x] = slide[x]
            continue
        v, a = eV[x], eA[x]
        guide = getattr(s, "guide", None)
        if guide is not None:
            key = scene.link(guide).key
            v, a = _max(v, eW.get(key, 0.0)), _max(a, eAl.get(key, 0.0))
        eS[x] = (v, a, a)
    return ErrorBounds(eP, eV, eA, eW, eAl, eS, sizes)


def bounds_dict(sol, b=None) -> dict:
    """The ``error_bounds`` object of ``solve --json``: each quantity's bound, keyed as the
    quantities themselves, and the sizes they are relative to (``b``: the bounds, if
    already computed)."""
    b = error_bounds(sol) if b is None else b
    sc = sol.scene
    d = {"relative_to": {k: float(v) for k, v in b.scales.items()},
         "points": {p: {"position": b.P[p], "velocity": b.V[p], "acceleration": b.A[p]}
                    for p in sc.point_names},
         "links": {lk.key: {"omega": b.W.get(lk.key, EPS), "alpha": b.Al.get(lk.key, EPS)}
                   for lk in sc.links}}
    if sc.sliders:
        d["sliders"] = {s.point: dict(zip(("sliding_velocity", "sliding_acceleration",
                                           "coriolis"), b.S.get(s.point, (EPS,) * 3)))
                        for s in sc.sliders}
    if sc.pins:
        d["pins"] = {pin[0]: {"rubbing_velocity": b.rubbing(pin)} for pin in sol.plan.pins}
    if sc.loads:
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
    if sol.scene.loads and b.torque(sol.scene) > SHOWN:
        out.append(("input torque", b.torque(sol.scene)))
    return sorted(out, key=lambda t: -t[1])
