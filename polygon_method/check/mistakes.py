"""The mistakes behind wrong answers: each known mistake computed from the solver's numbers
or a re-solved scene, and matched against the answer given (the alternatives:
``alternatives.py``; rubbing and torque: ``power.py``; slips of the pen: ``slips.py``)."""

from __future__ import annotations

import math

from ..common.tolerances import SAME
from ..scene import GuideSlider
from ..motion.solution import Solution
from ..steps import under_label
from ..common.numbers import textbook as _g
from . import confusions, force_slips, power, slips
from .alternatives import _DECIMAL, _FACTOR_MISTAKES, _Alternatives, _Candidate, _speed_mistakes
from .alternatives import offset_slips
from .slips import _SLIP_RANK, _slip
from .link_slips import link_slips
from .slots import coriolis_left_out
from .verdicts import FORCE_KINDS


_OPPOSITE = {"above": "below", "below": "above", "left": "right", "right": "left"}
_PHASE = {"v": "velocity", "a": "acceleration"}
_UNIT_FAMILY = {
    "v": "v",
    "vs": "v",
    "rub": "v",
    "vu": "v",
    "vI": "v",
    "a": "a",
    "as": "a",
    "ac": "a",
    "au": "a",
    "aI": "a",
    "omega": "omega",
    "alpha": "alpha",
}
#: the kind whose unit slips an answer shares (the guide's point under a block: a point's)
_AS_KIND = {"vu": "v", "au": "a", "vmin": "v", "ar": "a", "at": "a"}


class _Diagnoser:
    def __init__(self, sol: Solution, answers):
        self.sol = sol
        self.sc = sol.scene
        self.alts = _Alternatives(sol)
        self.given = {a.key: a for a in answers}
        # the student's own angular velocities, where given (magnitudes)
        self.their_w = {}
        for a in answers:
            if a.kind == "omega" and self.sc.has_link("-".join(a.names)):
                self.their_w[self.sc.link("-".join(a.names)).key] = abs(a.value)

    # -- helpers
    def unit_slips(self, kind) -> tuple:
        """The slips of the scene's own length unit where it is not mm or m (a problem in
        inches): a velocity in in/s given as m/s, a length in inches in omega = v / l."""
        u, f = self.sc.units, self.sc.length_unit
        if u in ("mm", "m"):
            return ()
        family = _UNIT_FAMILY.get(_AS_KIND.get(kind, kind))
        if family in ("v", "a"):
            per = "/s" if family == "v" else "/s^2"
            return ((1 / f, "length_unit", f"{u}{per} given as m{per}"),)
        if family in ("omega", "alpha"):
            return (
                (
                    f,
                    "length_unit",
                    f"a length in {u} used in "
                    f"{'omega = v' if family == 'omega' else 'alpha = a_t'} / l (l must be "
                    "in m)",
                ),
            )
        return ()

    def cmp(self, x, signed):
        return x if signed else abs(x)

    def body_points(self, X):
        """Points on the same rigid body as X (link ends, carried points), not ground."""
        sc = self.sc
        bodies = {lk.key for lk in sc.links if X in lk.points}
        cp = sc.carried(X)
        if cp is not None:
            bodies.add(cp.link)
        pts = []
        for key in bodies:
            lk = sc.link(key)
            pts += [lk.p, lk.q] + [c.name for c in sc.points if c.link == key]
        return [p for p in dict.fromkeys(pts) if p != X and p not in sc.ground]

    def link_at(self, X, Y):
        sc = self.sc
        for lk in sc.links:
            on = {lk.p, lk.q} | {c.name for c in sc.points if c.link == lk.key}
            if X in on and Y in on:
                return lk
        return None

    # -- candidates
    def candidates(self, ans, signed):
        """Every known mistake's value for the answer ``ans`` (``signed``: compared with its
        sign), in the order they are matched: the sense, the speed and the factors, the
        kind's own slips, the mechanism set up otherwise, a decimal slip, then another
        quantity of the problem."""
        sol, sc = self.sol, self.sc
        kind, names = ans.kind, ans.names
        correct = sol.value(kind, names)
        out = self._sense(kind, correct) if signed else []
        if kind != "torque":
            for factor, code, words in _speed_mistakes(sc):
                alt = self.alts.speed(factor)
                if alt is not None:
                    out.append(_Candidate(self.cmp(alt.value(kind, names), signed), code, words))
        elif not sc.has_forces:
            out += self.torque(signed)
        if kind in FORCE_KINDS or (kind == "torque" and sc.has_forces):
            out += self.force_slips(kind, names, signed)
        for factor, code, words in _FACTOR_MISTAKES.get(
            _AS_KIND.get(kind, kind), ()
        ) + self.unit_slips(kind):
            out.append(_Candidate(self.cmp(correct, signed) * factor, code, words))
        out += self._of_the_kind(ans, signed)
        out += self._set_up_otherwise(ans, signed)
        for factor, code, words in _DECIMAL:
            out.append(_Candidate(self.cmp(correct, signed) * factor, code, words))
        # last: another quantity of the problem (a named mistake of the same value first)
        out += confusions.other_quantities(self, ans, signed)
        return out

    @staticmethod
    def _sense(kind, correct) -> list:
        """The sense reversed (a direction along the guide, or cw for ccw)."""
        if kind in ("vs", "as"):
            return [_Candidate(-correct, "sense", "the direction along the guide is reversed")]
        if kind in ("force", "force2"):
            return [
                _Candidate(
                    -correct,
                    "sense",
                    "the driver's force's direction along its guide is reversed (+ along the "
                    "guide's direction; a collar's + outward, from the rod's pivot)",
                )
            ]
        word = "cw" if correct > 0 else "ccw"
        if kind == "Thold":
            return [
                _Candidate(
                    -correct,
                    "sense",
                    f"the sense is wrong ({word} given; the frame holds the fixed gear "
                    f"{'ccw' if correct > 0 else 'cw'}: against the planet's push on its "
                    "teeth, the torques on the train summing to nought)",
                )
            ]
        return [
            _Candidate(
                -correct,
                "sense",
                f"the sense is wrong ({word} given; it turns {'ccw' if correct > 0 else 'cw'})",
            )
        ]

    def _of_the_kind(self, ans, signed) -> list:
        """The slips of the answer's own kind: a relative velocity for an absolute one, a
        per-length slip, a gear ratio, a contact point taken at rest, a Coriolis component
        left out, an absolute velocity for a sliding one, a rubbing slip."""
        kind, names = ans.kind, ans.names
        out = []
        if kind in ("vu", "au"):
            out += confusions.under_block(self, ans)
        if kind in ("v", "a"):
            out += self.relative(ans, signed)
        if kind in ("omega", "alpha"):
            out += self.per_length(ans)
        if kind == "omega":
            out += self.gear_ratio(ans, signed)
        if kind in ("a", "aI"):
            out += self.contact_at_rest(ans)
        if kind in ("a", "as"):
            out += self.coriolis_left_out(kind, names[0])
        if kind in ("a", "alpha"):
            out += self.step_coriolis_left_out(kind, names, signed)
        X = self._sliding_point(names[0]) if kind == "vs" else None
        if X is not None:
            out.append(
                _Candidate(
                    self.sol.speed(X),
                    "absolute_for_relative",
                    f"the absolute velocity of {X} given for its sliding velocity",
                )
            )
        if kind == "rub":
            out += self.rubbing(names[0])
        if kind in ("vmin", "ar", "at"):  # two points of one link
            out += link_slips(self.sol, ans)
        return out

    def _sliding_point(self, name: str) -> str | None:
        """The point whose absolute velocity a student may give for the sliding velocity
        ``vs_<name>``: a block's point (a peg's slot: vs_P_OA is of the peg P), a
        cylinder's rod end (vs_CR: the rod slides in its barrel)."""
        slider = self.sc.slider(name)
        if slider is not None:
            return slider.point
        cylinder = self.sc.cylinder(name)
        return cylinder.rod if cylinder is not None else None

    def _set_up_otherwise(self, ans, signed) -> list:
        """The mechanism set up otherwise: the other assembly branch, the crank's angle
        read otherwise, the angle in degrees taken as radians."""
        sc, kind, names = self.sc, ans.kind, ans.names
        val = lambda s: self.cmp(s.value(kind, names), signed)  # noqa: E731
        out = []
        for X, side, alt in self.alts.branches():
            try:
                out.append(
                    _Candidate(
                        val(alt),
                        "other_branch",
                        f"the other assembly branch ({X} {side} instead of {_OPPOSITE[side]})",
                    )
                )
            except (KeyError, TypeError):
                pass
        for sl, code, alt in offset_slips(self.alts):
            if alt is not None:
                e = f"{_g(abs(sl.offset) / sc.length_unit)} {sc.units}"
                side = "left" if sl.offset > 0 else "right"
                yoke = getattr(sl, "yoke", None)  # a yoke's slot: off the line through Y
                what = f"yoke {yoke}" if yoke else sl.guide
                line = (
                    (f"the line through {yoke}", f"the line through {yoke} along it")
                    if yoke
                    else (f"its line {sl.first}{sl.second}", f"its line {sl.first} -> {sl.second}")
                )
                out.append(
                    _Candidate(
                        val(alt),
                        code,
                        f"the slot of {what} drawn through {line[0]} (its offset of {e} left out)"
                        if code == "offset_left_out"
                        else f"the slot of {what} taken {e} to the "
                        f"{'right' if side == 'left' else 'left'} of {line[1]}, not the {side}",
                    )
                )
        if kind == "torque":
            return out
        for slip, alt in self.alts.angle_slips():
            if alt is not None:
                out.append(
                    _Candidate(
                        val(alt),
                        slip.code,
                        f"{slip.text} (crank at "
                        f"{_g(math.degrees(slip.value))} deg from +x instead of "
                        f"{_g(math.degrees(sc.input.angle) % 360)})",
                    )
                )
        alt = self.alts.angle_as_radians()
        if alt is not None:
            out.append(
                _Candidate(
                    val(alt),
                    "angle_in_radians",
                    "the crank angle in degrees used as radians (calculator in RAD mode)",
                )
            )
        return out

    def relative(self, ans, signed):
        sol = self.sol
        kind, names = ans.kind, ans.names
        sym = kind
        unit = "m/s" if kind == "v" else "m/s^2"
        mag = sol.speed if kind == "v" else sol.acceleration_magnitude
        out = []
        if len(names) == 1:
            X = names[0]
            for Y in self.body_points(X):
                out.append(
                    _Candidate(
                        mag(X, Y),
                        "relative_for_absolute",
                        f"you gave {sym}_{X}{Y} ({_g(mag(X, Y))} {unit}), the "
                        f"relative {_PHASE[kind]} of {X} to {Y}, for the "
                        f"absolute {sym}_{X}",
                    )
                )
            sl = self.sc.slider(X)
            if kind in ("v", "a") and isinstance(sl, GuideSlider):
                if kind == "v":
                    out.append(
                        _Candidate(
                            abs(sol.sliding_velocity(sl.key)),  # (a peg's: its first slot's)
                            "relative_for_absolute",
                            f"the sliding velocity of {X} on its guide given for "
                            f"its absolute velocity",
                        )
                    )
                # the classic slotted-lever slip: the guide's point under the block for the
                # block itself (a1 for a: they differ by the sliding velocity)
                phase = "acceleration" if kind == "a" else "velocity"
                under = sol.under_block(sl.key, phase)
                if under is not None:
                    key = next(
                        (
                            f"{sym}_{n}"
                            for n, k in confusions.under_names(self.sc).items()
                            if k == sl.key
                        ),
                        None,
                    )
                    out.append(
                        _Candidate(
                            math.hypot(*under),
                            "coincident_for_block",
                            "you gave "
                            + (f"{key}, " if key else "")
                            + f"the {_PHASE[kind]} of the point of {sl.guide} "
                            f"under the block ({under_label(self.sol, X, phase)}"
                            f"), for the block {X}'s own {sym}_{X}: they differ "
                            "by the sliding"
                            + (" and Coriolis components" if kind == "a" else " velocity"),
                        )
                    )
            if kind == "a":
                for lk in self.sc.links:
                    if X in lk.points and lk.other(X) in self.sc.ground:
                        out += self.components(X, lk.other(X), lk, f"a_{X}")
        else:
            X, Y = names
            for Z in (X, Y):
                if Z not in self.sc.ground:
                    out.append(
                        _Candidate(
                            mag(Z),
                            "absolute_for_relative",
                            f"you gave {sym}_{Z} ({_g(mag(Z))} {unit}), the "
                            f"absolute {_PHASE[kind]} of {Z}, for the relative "
                            f"{sym}_{X}{Y}",
                        )
                    )
            lk = self.link_at(X, Y)
            if kind == "a" and lk is not None:
                out += self.components(X, Y, lk, f"a_{X}{Y}")
        return out

    def components(self, X, Y, lk, name):
        """The slips of one component for the relative acceleration ``name`` of X about Y
        on link ``lk``."""
        sol = self.sol
        r = math.dist(sol.P[X], sol.P[Y])
        return confusions.component_only(sol.W[lk.key], sol.Al[lk.key], r, name)

    def per_length(self, ans):
        sol = self.sol
        lk = self.sc.link("-".join(ans.names))
        P, Q, L = lk.p, lk.q, lk.length
        out = []
        if ans.kind == "omega":
            for Z in (P, Q):
                if Z not in self.sc.ground:
                    out.append(
                        _Candidate(
                            sol.speed(Z) / L,
                            "absolute_over_length",
                            f"the absolute v_{Z} divided by {lk.key}; "
                            f"omega_{lk.key} = v_{Q}{P} / {lk.key}",
                        )
                    )
            out.append(
                _Candidate(
                    sol.speed(Q, P),
                    "not_divided_by_length",
                    f"v_{Q}{P} not divided by the length {lk.key}",
                )
            )
            for key in (f"v_{P}{Q}", f"v_{Q}{P}"):
                a = self.given.get(key)
                if a is not None:
                    out.append(
                        _Candidate(
                            abs(a.value) / L,
                            "carried_error",
                            f"carried from your {key} = {a.raw}: "
                            f"{_g(abs(a.value))} / {_g(L)} (the method is "
                            "right)",
                        )
                    )
        else:
            w = sol.W[lk.key]
            out.append(
                _Candidate(
                    sol.acceleration_magnitude(Q, P) / L,
                    "total_for_tangential",
                    f"the whole a_{Q}{P} divided by {lk.key}; alpha uses its "
                    "tangential component only",
                )
            )
            out.append(
                _Candidate(
                    w * w,
                    "total_for_tangential",
                    "the centripetal component divided by the length (that "
                    "is omega^2); alpha uses the tangential component",
                )
            )
            for Z in (P, Q):
                if Z not in self.sc.ground:
                    out.append(
                        _Candidate(
                            sol.acceleration_magnitude(Z) / L,
                            "absolute_over_length",
                            f"the absolute a_{Z} divided by {lk.key}",
                        )
                    )
        return out

    def omega_sets(self):
        """(|omega| by link, the links whose value is the student's): the student's own
        angular velocities where given, and the exact ones."""
        exact = {k: abs(v) for k, v in self.sol.W.items()}
        sets = [(exact, frozenset())]
        if self.their_w:
            theirs = dict(exact)
            theirs.update(self.their_w)
            sets.insert(0, (theirs, frozenset(self.their_w)))
        return sets

    def coriolis_left_out(self, kind, name):
        """A peg in two slots drawn without the Coriolis component of a moving slot."""
        return [
            _Candidate(v, code, text) for v, code, text in coriolis_left_out(self.sol, kind, name)
        ]

    def step_coriolis_left_out(self, kind, names, signed):
        """A step's Coriolis component left out of the acceleration polygon (a collar driven
        along its turning rod): what each step says the polygon then gives."""
        sol, out = self.sol, []
        key = (
            kind,
            next((lk.key for lk in self.sc.links if set(lk.points) == set(names)), None)
            if kind == "alpha"
            else names[0],
        )
        for st in sol.plan.steps:
            wrong = getattr(st, "coriolis_left_out", lambda sol: {})(sol).get(key)
            right = sol.value(kind, names)
            if wrong is not None and abs(abs(wrong) - abs(right)) > SAME * abs(right):
                out.append(
                    _Candidate(
                        self.cmp(wrong, signed) if kind == "alpha" else wrong,
                        "coriolis_omitted",
                        "the Coriolis component 2 omega v "
                        f"of {st.title} left out of the acceleration polygon",
                    )
                )
        return out

    def rubbing(self, X):
        return power.rubbing(self, X)

    def torque(self, signed):
        return power.torque(self, signed)

    def force_slips(self, kind, names, signed):
        return force_slips.force_slips(self, kind, names, signed)

    def gear_ratio(self, ans, signed):
        """A planet's omega by the tabular method, its classic slips (the step says them)."""
        key = self.sc.link("-".join(ans.names)).key
        out = []
        for st in self.sol.plan.steps:
            slips_of = getattr(st, "ratio_slips", None)
            if slips_of is not None and key in st.links:
                out += [
                    _Candidate(self.cmp(v, signed), code, words)
                    for v, code, words in slips_of(self.sol)
                ]
        return out

    def contact_at_rest(self, ans):
        """Rolling's classic slip: the contact point's acceleration taken as zero (for the
        contact, and for a point of the wheel found from it)."""
        sol, X = self.sol, ans.names[0]
        c = (
            "contact_acceleration_zero",
            "the contact point's acceleration taken as zero: "
            "no slip makes its velocity zero, not its acceleration (omega^2 r towards the "
            "centre)",
        )
        if ans.kind == "aI":
            wheel = sol.scene.link("-".join(ans.names)).key
            st = next((s for s in sol.plan.steps if wheel in s.links), None)
            got = st.contact_motion(sol) if st is not None else None
            if got is not None and math.hypot(*got[1]) > 0.0:  # a moving gear: v_I not zero
                c = (
                    c[0],
                    "the contact point's acceleration taken as zero: no slip makes "
                    "the two gears' velocities equal at the pitch point, not their "
                    "accelerations (each has its own centripetal component)",
                )
            return [_Candidate(0.0, *c)]
        out = []
        for st in sol.plan.steps if len(ans.names) == 1 else ():
            got = st.contact_motion(sol)
            on = {p for w in st.links for p in sol.scene.link(w).points}
            if got is not None and X in on | {
                q.name for q in sol.scene.points if q.link in st.links
            }:
                (ax, ay), (bx, by) = sol.A[X], got[2]
                out.append(_Candidate(math.hypot(ax - bx, ay - by), *c))
        return out

    def own_slip(self, ans):
        return slips.own_slip(self, ans)

    # -- the verdict
    def diagnose(self, ans, given, correct, tol, signed):
        matches = []
        for order, c in enumerate(self.candidates(ans, signed)):
            if not math.isfinite(c.value) or abs(c.value - correct) <= tol:
                continue
            # the answer's relative tolerance, applied to the mistaken value
            window = tol * abs(c.value) / abs(correct) if correct and c.value else tol
            if c.window is not None:
                window = min(window, c.window * abs(c.value))
            dev = abs(given - c.value)
            if dev <= window:
                rel = dev / max(abs(c.value), 1e-300)
                # equal to rounding: the simpler mistake (earlier in the list) first
                matches.append((rel if rel > SAME else 0.0, order, c))
        slip = _slip(ans.raw, given, correct, signed) or self.own_slip(ans)
        if slip is not None:  # its digits match exactly: before a mistake that only comes
            matches.append((_SLIP_RANK, 0, slip))  # near (more than rounding off)
        if not matches:
            return None, None
        matches.sort(key=lambda m: m[:2])
        matches = [(d, c) for d, _, c in matches]
        best = matches[0][1]
        text = best.text
        others = [
            c
            for d, c in matches[1:]
            if c.code != best.code
            and d <= 0.005
            and matches[0][0] <= 0.005
            and not (  # the same value, named twice
                c.code == "another_quantity" and abs(c.value - best.value) <= SAME * abs(best.value)
            )
        ]
        if others:
            text += "; or " + others[0].text
        return best.code, text
