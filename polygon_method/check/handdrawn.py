"""A careful hand drawing of the construction, and how far it may be off: the default
tolerance of an answer.

A student draws the configuration at the scale the step table states, then each polygon at
its own (the step table's scales fit each diagram on an A4 sheet: 15 cm for the
configuration, 12 cm for a polygon), with a pencil, a ruler and a set square. Every length
set out or read is off by the pencil's ``PENCIL_CM`` (where the line ends) and by the
ruler's reading: a length is read to the ruler's smallest division, ``DIVISION_CM`` (1 mm),
so it is up to half a division off, evenly spread (a standard deviation of
``DIVISION_CM / sqrt(12)``); the two together are ``LENGTH_CM``, 0.38 mm. Every direction
is off by about ``PENCIL_DEG`` (standard deviations). The errors are followed through the construction as it is drawn:

* the configuration: each link's length, each fixed point's place and the crank angle as
  drawn move every direction line the polygons are built from. Many drawn mechanisms are
  evaluated at once (the plan's dimensions as arrays, a fixed seed: the same scene always
  gets the same tolerances);
* the polygons, step by step from their construction records: a vector set out from a
  known image carries that image's error, plus the pencil's on its length and direction;
  a direction line through a point is off at the found image by that point's error and
  its direction error over the distance; two lines crossing at gamma put the image
  ``sqrt(e1^2 + e2^2) / sin gamma`` off (a later step inherits the earlier ones);
* the value read off: its own pencil error;
* a quantity built from read-offs follows its construction: a rubbing velocity
  ``|w1 -/+ w2| r`` with the drawn omegas (the crank's is given), the input torque
  ``-sum(F . v + T w) / omega`` with the drawn velocities and omegas, a sliding velocity or
  acceleration read off between the two images it joins (c1 to c; o to x on a fixed
  path), the Coriolis component ``2 omega vs`` with both factors as drawn. The drawn
  configurations give each its spread too.

The tolerance of an answer is the 95th percentile of its relative error over the drawings:
the configuration's spread combined with 1.96 times the polygon's, never below 0.5 %.
"""

from __future__ import annotations

import dataclasses
import math

from ..common.tolerances import SAME
from ..polygons.constructions import acceleration_constructions, velocity_constructions
from ..motion.link_points import link_rates, segment_least
from ..solver.derived import input_torque, largest, rubbing_at
from ..solver.kinematics import evaluate
from ..polygons.scales import diagram_scales

__all__ = [
    "BUILT",
    "DIVISION_CM",
    "HandDrawing",
    "HOW",
    "LENGTH_CM",
    "PENCIL_CM",
    "PENCIL_DEG",
    "SAMPLES",
]

#: a pencil's error on paper, lengths (cm) and directions (deg): standard deviations
PENCIL_CM = 0.025
PENCIL_DEG = 0.25
#: the smallest division of the ruler a length is read on (cm): 1 mm
DIVISION_CM = 0.1
#: a length set out or read on the paper: the pencil's error and the reading's, half a
#: division either way evenly spread (standard deviation ``DIVISION_CM / sqrt(12)``)
LENGTH_CM = math.hypot(PENCIL_CM, DIVISION_CM / math.sqrt(12.0))
#: configurations drawn per scene
SAMPLES = 300
Z95 = 1.96
#: how a quantity built from read-offs is drawn, as the check's rule says it (after BUILT)
BUILT = "; built as: "
HOW = {
    "rub": "rub = |w1 -/+ w2| r with the drawn omegas",
    "torque": "T = -sum(F . v) / omega with the drawn velocities",
    "vs": "read off between the two images the sliding joins",
    "as": "read off between the two images the sliding joins",
    "ac": "2 omega vs with the drawn omega and vs",
    "vmin": "op, p the foot of the perpendicular from o to the drawn xy",
    "ar": "v_XY^2 / XY with the drawn v_XY",
    "at": "read off across XY between the two images",
}


class HandDrawing:
    """How far a careful hand drawing of one solution may be off, quantity by quantity."""

    def __init__(self, sol, samples: int = SAMPLES, seed: int = 7):
        import numpy as np

        self.np, self.sol = np, sol
        space, self.sv, self.sa = diagram_scales(sol)
        self.space = space
        rng = np.random.default_rng(seed)
        n, plan = samples, sol.plan
        dims = plan.dims
        d_len = LENGTH_CM * space.per_cm

        def pencil(scale=1.0):
            return rng.normal(0.0, d_len, n) / scale

        ground = {p: (x + pencil(), y + pencil()) for p, (x, y) in dims.ground.items()}
        steps = tuple(st.drawn(prm, pencil, sol.P) for st, prm in zip(plan.steps, dims.steps))
        theta = dims.theta + rng.normal(0.0, math.radians(PENCIL_DEG), n)
        drawn = dataclasses.replace(dims, ground=ground, steps=steps, theta=theta)
        with np.errstate(all="ignore"):
            self.m = evaluate(plan, dims=drawn, array=True)
        ok = np.ones(n, dtype=bool) if self.m.bad is None else ~self.m.bad
        for x, y in self.m.P.values():
            ok &= np.isfinite(x) & np.isfinite(y)
        self.ok, self.n = ok, n
        self.sliding = {}  # "vs_A" / "as_A" -> sigma of the sliding vector as drawn
        self.image_sigma = {}  # phase -> the sigma of an image point at (x, y), or None
        self.sigma = {
            "velocity": self._polygon(velocity_constructions(sol), sol.V, self.sv, "velocity"),
            "acceleration": self._polygon(
                acceleration_constructions(sol), sol.A, self.sa, "acceleration"
            ),
        }

    # ----- the polygons, as drawn
    def _polygon(self, cons, D, scale, phase):
        """point -> the standard deviation (SI) of its image as drawn, step by step."""
        p = LENGTH_CM * scale.per_cm
        th = math.radians(PENCIL_DEG)
        known = [((0.0, 0.0), 0.0)]  # (image, its sigma): the pole

        def sigma_at(xy):
            best = min(known, key=lambda k: math.dist(k[0], xy))
            return best[1] if math.dist(best[0], xy) <= SAME * (1 + math.hypot(*xy)) else None

        def set_out(vec):  # a vector drawn from a known image: its end's sigma
            s0 = sigma_at(vec.start)
            s0 = 0.0 if s0 is None else s0
            return math.sqrt(s0**2 + p**2 + (th * vec.magnitude) ** 2)

        out = {}
        for c in cons:
            for g in c.given:
                known.append((g.end, set_out(g)))
            x = c.point
            if c.lines:
                offs = []
                for ln in c.lines:
                    s0 = sigma_at(ln.point)
                    s0 = p if s0 is None else s0
                    offs.append(math.hypot(s0, th * math.dist(ln.point, x)))
                s = math.hypot(*offs) / max(c.condition, 1e-3)
            else:  # set out directly (a crank, an image by similar triangles)
                ends = [
                    set_out(v)
                    for v in c.found
                    if math.dist(v.end, x) <= SAME * (1 + math.hypot(*x))
                ]
                s = min(ends) if ends else p
            known.append((x, s))
            for v in c.found:
                if sigma_at(v.end) is None:
                    known.append((v.end, math.hypot(s, p)))
        for name, xy in D.items():
            s = sigma_at(xy)
            out[name] = 0.0 if s is None else s
        self.image_sigma[phase] = sigma_at
        # a sliding component is read between the two images it joins (c1 to c)
        for c in cons:
            for v in c.found:
                if v.kind == "sliding":
                    ends = [sigma_at(v.start), sigma_at(v.end)]
                    self.sliding[v.name] = math.hypot(*(e or 0.0 for e in ends))
        return out

    # ----- the answers
    def _spread(self, kind, names):
        """(values over the drawn configurations, sigma of the polygon drawing and reading
        for this quantity, SI)."""
        np, m, sol = self.np, self.m, self.sol
        sv = self.sigma["velocity"]
        sa = self.sigma["acceleration"]
        rv, ra = LENGTH_CM * self.sv.per_cm, LENGTH_CM * self.sa.per_cm
        if kind in ("v", "a"):
            s = sv if kind == "v" else sa
            r = rv if kind == "v" else ra
            poly = math.sqrt(sum(s.get(x, 0.0) ** 2 for x in names) + r**2)
            vals = m.speed(*names) if kind == "v" else m.acceleration_magnitude(*names)
            return vals, poly
        if kind in ("vu", "au"):  # the guide's point under a block: its image a1 (a1')
            phase = "velocity" if kind == "vu" else "acceleration"
            s, r = (sv, rv) if kind == "vu" else (sa, ra)
            img = self.image_sigma[phase](sol.under_block(names[0], phase))
            if img is None:
                img = s.get(sol.scene.slider(names[0]).point, 0.0)
            vals = np.hypot(*m.under_block(names[0], phase))
            return vals, math.hypot(img, r)
        if kind in ("omega", "alpha"):
            s = sv if kind == "omega" else sa
            r = rv if kind == "omega" else ra
            cyl = sol.scene.cylinder("-".join(names))
            if cyl is not None:  # a cylinder: over its length now, as drawn
                key, p, q, length = cyl.key, cyl.barrel, cyl.rod, sol.cylinder_length(cyl.key)
            else:
                lk = sol.scene.link("-".join(names))
                key, p, q, length = lk.key, lk.p, lk.q, lk.length
            poly = math.sqrt(s.get(p, 0.0) ** 2 + s.get(q, 0.0) ** 2 + r**2) / length
            vals = np.abs(m.omega(key) if kind == "omega" else m.alpha(key))
            return vals, poly
        if kind in ("vs", "as"):  # read off between the images the sliding joins
            X = names[0]
            s, r = (sv, rv) if kind == "vs" else (sa, ra)
            drawn = self.sliding.get(f"{kind}_{X}", s.get(X, 0.0))  # on a path: o to x
            vals = m.sliding_velocity(X) if kind == "vs" else m.sliding_acceleration(X)
            return np.abs(vals), math.hypot(drawn, r)
        if kind == "ac":  # 2 omega vs, both factors as drawn
            X = names[0]
            guide = getattr(sol.scene.slider(X), "guide", None)
            if guide is None:
                return None, None
            w, vs = abs(sol.W[sol.scene.link(guide).key]), abs(sol.sliding_velocity(X))
            s_vs = math.hypot(self.sliding.get(f"vs_{X}", sv.get(X, 0.0)), rv)
            poly = 2 * math.hypot(self.omega_sigma(guide) * vs, w * s_vs)
            return np.hypot(*m.coriolis(X)), poly
        if kind in ("vmin", "ar", "at"):  # two points of one link
            return self._pair(kind, *names)
        if kind == "rub":  # |w1 -/+ w2| r with the drawn omegas (the largest pair)
            pin = next(p for p in sol.plan.pins if p[0] == names[0])
            r = sol.plan.dims.radii[names[0]]
            vals = np.asarray(largest(rubbing_at(pin, m.W, r)), dtype=float)
            rub = sol.rubbing[names[0]]
            if not rub.pairs:
                return None, None
            i = max(range(len(rub.values)), key=rub.values.__getitem__)
            a, b = pin[5][i]
            return vals, r * math.hypot(self.omega_sigma(a), self.omega_sigma(b))
        if kind == "torque":  # T = -sum(F . v + T_l w_l) / omega with the drawn v, omega
            sc, w = sol.scene, sol.plan.dims.omega
            vals = input_torque(sc, m.V, m.W, w, m.S, m.P)  # (S: a passive cylinder's F vs)
            if vals is None:
                return None, None
            var = 0.0
            for load in sc.loads:
                if load.force is not None:
                    var += math.hypot(*load.force) ** 2 * (sv.get(load.target, 0.0) ** 2 + rv**2)
                else:
                    var += (load.torque * self.omega_sigma(load.target)) ** 2
            return np.abs(vals), math.sqrt(var) / abs(w)
        return None, None

    def _pair(self, kind, x, y):
        """(values, sigma) of ``vmin_XY`` (op from the drawn x and y), ``ar_XY`` (the drawn
        v_XY squared over XY), ``at_XY`` (read off between the images x' and y')."""
        m, sol = self.m, self.sol
        phase = "acceleration" if kind == "at" else "velocity"
        scale = self.sa if kind == "at" else self.sv
        s = self.sigma[phase]
        poly = math.sqrt(s.get(x, 0.0) ** 2 + s.get(y, 0.0) ** 2 + (LENGTH_CM * scale.per_cm) ** 2)
        if kind == "vmin":
            return segment_least(m.V[x], m.V[y]), poly
        radial, tangential = link_rates(sol.scene, m.W, m.Al, m.P, x, y)
        if kind == "at":
            return tangential, poly
        r = math.dist(sol.P[x], sol.P[y])
        return radial, (2 * sol.speed(x, y) * poly / r if r else 0.0)

    def omega_sigma(self, link) -> float:
        """The standard deviation of omega of ``link`` as read off the velocity polygon
        (zero for the crank, whose omega is given, and for a body that does not turn)."""
        sol = self.sol
        if link is None or link in sol.plan.fixed_links:
            return 0.0
        lk = sol.scene.link(link)
        if lk.key in sol.plan.steps[0].links:  # the crank's (a driving block turns none)
            return 0.0
        s = self.sigma["velocity"]
        r = LENGTH_CM * self.sv.per_cm
        return math.sqrt(s.get(lk.p, 0.0) ** 2 + s.get(lk.q, 0.0) ** 2 + r**2) / lk.length

    def tolerance(self, kind, names, correct):
        """The 95th percentile of the relative error, or None where this model does not
        cover the quantity (the drawing rule applies there)."""
        np = self.np
        if correct == 0 or not self.ok.any():
            return None
        vals, poly = self._spread(kind, names)
        if vals is None:
            return None
        x = np.broadcast_to(np.asarray(vals, dtype=float), (self.n,))[self.ok]
        config = np.abs(np.abs(x) - abs(correct))
        total = np.sqrt(config**2 + (Z95 * poly) ** 2) / abs(correct)
        total = total[np.isfinite(total)]
        return float(np.percentile(total, 95.0)) if len(total) else None
