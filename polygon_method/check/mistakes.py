"""The mistakes behind wrong answers: each known mistake computed from the solver's numbers
or a re-solved scene, and matched against the answer given."""

from __future__ import annotations

import itertools
import math
import re
from dataclasses import dataclass, replace

from ..errors import PolygonMethodError
from ..plan import Context
from ..forces import analyse, force_value
from ..scene import GuideSlider, Gravity, Scene
from ..solution import Solution, solve
from ..steps import under_label
from ..numbers import textbook as _g
from ..numbers import working as _num
from .slots import coriolis_left_out
from .tolerance import _terms



@dataclass(frozen=True)
class _Candidate:
    value: float
    code: str
    text: str
    window: float | None = None  # narrower matching window (absolute), for wide families


class _Alternatives:
    """Solutions of the same scene with one mistake made (asked of the solver, cached)."""

    def __init__(self, sol: Solution):
        self.sol = sol
        self.cache = {}

    def solve(self, key, scene):
        if key not in self.cache:
            try:
                self.cache[key] = solve(scene)
            except (PolygonMethodError, ValueError, ZeroDivisionError, OverflowError):
                self.cache[key] = None
        return self.cache[key]

    def speed(self, factor):
        sc = self.sol.scene
        return self.solve(("speed", factor),
                          replace(sc, input=replace(sc.input, omega=sc.input.omega * factor,
                                                    given=None)))  # that speed, as given

    def angle_as_radians(self):
        sc = self.sol.scene
        deg = math.degrees(sc.input.angle)
        return self.solve(("radians",),
                          replace(sc, input=replace(sc.input, angle=deg)))

    def angle_slips(self):
        """(slip, solution or None) for each classic misreading of the crank angle's words
        (the other dead centre, against the rotation, above for below, from the horizontal
        for from the vertical): the scene's reader lists them with the words."""
        sc = self.sol.scene
        return [(slip, self.solve(("slip", slip.code, slip.value),
                                  replace(sc, input=replace(sc.input, angle=slip.value))))
                for slip in sc.input.angle_slips]

    def branches(self):
        """(point, words, solution) for the other branch of every two-way step."""
        out = self.cache.get("branches")
        if out is not None:
            return out
        sol = self.sol
        sc = sol.scene
        out = []
        ctx = Context(sc.input.angle, sc.input.omega, sc.input.alpha)
        for st in sol.plan.steps:
            if not st.other_assembly_mistake:
                continue
            try:
                base, off, *_ = st.candidates(dict(sol.P), ctx)
            except PolygonMethodError:
                continue
            X = st.point
            other = (base[0] - st.sigma * off[0], base[1] - st.sigma * off[1])
            here = sol.P[X]
            if math.dist(other, here) <= 1e-9 * max(math.hypot(*off), 1e-9) or \
                    math.dist(other, here) == 0:
                continue
            alt = self.solve(("branch", X),
                             replace(sc, assembly={**sc.assembly, X: other}))
            if alt is None:
                continue
            dx, dy = other[0] - here[0], other[1] - here[1]
            side = ("below" if dy < 0 else "above") if abs(dy) >= abs(dx) else \
                ("left" if dx < 0 else "right")
            out.append((X, side, alt))
        self.cache["branches"] = out
        return out


def _speed_mistakes(scene: Scene):
    """(factor on the crank's omega, code, words) for the speed confusions that the way the
    scene states the speed makes possible."""
    g = scene.input.given
    if g is not None:  # the crank's speed was found from a given motion
        return _given_mistakes(scene, g)
    unit = re.sub(r"^[-+0-9.eE\s]+", "", scene.input.speed_text).split()
    unit = unit[0].lower() if unit else "rad/s"
    k = 60 / (2 * math.pi)
    if unit in ("rpm", "r.p.m.", "r.p.m", "rev/min"):
        return ((k, "rpm_as_rad_s", "rpm used as rad/s (omega = N instead of 2 pi N / 60)"),
                (60.0, "rps_rpm", "rpm taken as rps (omega = 2 pi N, the / 60 left out)"))
    if unit in ("rps", "r.p.s.", "r.p.s", "rev/s"):
        return ((1 / (2 * math.pi), "rps_as_rad_s", "rps used as rad/s (omega = n instead "
                 "of 2 pi n)"),
                (1 / 60, "rps_rpm", "rps taken as rpm (omega = 2 pi n / 60)"))
    return ((1 / k, "rad_s_as_rpm", "rad/s taken as rpm (converted again by 2 pi / 60)"),
            (2 * math.pi, "rad_s_as_rps", "rad/s taken as rps (multiplied by 2 pi)"))


def _given_mistakes(scene, g):
    """The slips of a speed given on another quantity: the given speed taken as the crank
    pin's (omega = v / r), or the given link's omega taken as the crank's."""
    w = abs(scene.input.omega)
    if g.kind == "omega":
        wrong = abs(g.value)
        words = (f"the given omega_{''.join(g.names)} taken as the crank's (the polygon not "
                 "scaled to it)")
    else:
        wrong = abs(g.value) / scene.link(scene.input.crank).length
        words = (f"the given speed of {g.names[0]} ({g.text}) taken as the crank pin's "
                 f"(omega_{scene.input.crank} = v / r, the polygon not scaled to it)")
    if abs(wrong - w) <= 1e-6 * w:
        return ()
    return ((wrong / w, "given_as_crank", words),)


_FACTOR_MISTAKES = {
    "v": ((1e3, "mm_m", "mm/s given as m/s"), (1e-3, "mm_m", "m/s given as mm/s")),
    "vs": ((1e3, "mm_m", "mm/s given as m/s"), (1e-3, "mm_m", "m/s given as mm/s")),
    "rub": ((1e3, "mm_m", "mm/s given as m/s"), (1e-3, "mm_m", "m/s given as mm/s")),
    "a": ((1e3, "mm_m", "mm/s^2 given as m/s^2"), (1e-3, "mm_m", "m/s^2 given as mm/s^2")),
    "as": ((1e3, "mm_m", "mm/s^2 given as m/s^2"), (1e-3, "mm_m", "m/s^2 given as mm/s^2")),
    "ac": ((1e3, "mm_m", "mm/s^2 given as m/s^2"), (1e-3, "mm_m", "m/s^2 given as mm/s^2"),
           (0.5, "coriolis_factor", "the factor 2 of the Coriolis component 2 omega v left "
            "out")),
    "omega": ((180 / math.pi, "deg_rad", "degrees per second given as rad/s"),
              (math.pi / 180, "deg_rad", "radians taken as degrees (rad/s x pi / 180)"),
              (60 / (2 * math.pi), "rpm_as_rad_s", "the answer is in rpm, not rad/s"),
              (1e-3, "mm_m", "a length in mm used in omega = v / l (l must be in m)"),
              (1e3, "mm_m", "a velocity in mm/s used in omega = v / l")),
    "alpha": ((180 / math.pi, "deg_rad", "degrees per second squared given as rad/s^2"),
              (math.pi / 180, "deg_rad", "radians taken as degrees"),
              (1e-3, "mm_m", "a length in mm used in alpha = a_t / l (l must be in m)")),
    "torque": ((1e3, "mm_m", "N mm given as N m"), (1e-3, "mm_m", "N m given as N mm")),
}
_DECIMAL = ((10.0, "decimal_point", "the decimal point misplaced (10 times too large)"),
            (0.1, "decimal_point", "the decimal point misplaced (10 times too small)"),
            (100.0, "decimal_point", "the decimal point misplaced, or cm for m (100 times)"),
            (0.01, "decimal_point", "the decimal point misplaced, or m for cm (1/100)"))


_OPPOSITE = {"above": "below", "below": "above", "left": "right", "right": "left"}


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
        sol, sc = self.sol, self.sc
        kind, names = ans.kind, ans.names
        correct = sol.value(kind, names)
        out = []
        val = lambda s: self.cmp(s.value(kind, names), signed)  # noqa: E731
        if signed:
            word = "cw" if correct > 0 else "ccw"
            if kind in ("vs", "as"):
                out.append(_Candidate(-correct, "sense", "the direction along the guide is "
                                      "reversed"))
            else:
                out.append(_Candidate(-correct, "sense", f"the sense is wrong ({word} given; "
                                      f"it turns {'ccw' if correct > 0 else 'cw'})"))
        if kind != "torque":
            for factor, code, words in _speed_mistakes(sc):
                alt = self.alts.speed(factor)
                if alt is not None:
                    out.append(_Candidate(val(alt), code, words))
        elif not sc.has_forces:
            out += self.torque(signed)
        if kind in ("F", "N") or (kind == "torque" and sc.has_forces):
            out += self.force_slips(kind, names, signed)
        for factor, code, words in _FACTOR_MISTAKES.get(kind, ()):
            out.append(_Candidate(self.cmp(correct, signed) * factor, code, words))
        if kind in ("v", "a"):
            out += self.relative(ans, signed)
        if kind in ("omega", "alpha"):
            out += self.per_length(ans)
        if kind in ("a", "aI"):
            out += self.contact_at_rest(ans)
        if kind in ("a", "as"):
            out += self.coriolis_left_out(kind, names[0])
        if kind == "vs":
            X = sc.slider(names[0]).point  # a peg's slot: vs_P_OA is of the peg P
            out.append(_Candidate(sol.speed(X), "absolute_for_relative",
                                  f"the absolute velocity of {X} given for its "
                                  "sliding velocity"))
        if kind == "rub":
            out += self.rubbing(names[0])
        for X, side, alt in self.alts.branches():
            try:
                out.append(_Candidate(val(alt), "other_branch",
                                      f"the other assembly branch ({X} {side} instead of "
                                      f"{_OPPOSITE[side]})"))
            except (KeyError, TypeError):
                pass
        for slip, alt in self.alts.angle_slips():
            if alt is not None and kind != "torque":
                out.append(_Candidate(val(alt), slip.code, f"{slip.text} (crank at "
                                      f"{_g(math.degrees(slip.value))} deg from +x instead of "
                                      f"{_g(math.degrees(sc.input.angle) % 360)})"))
        alt = self.alts.angle_as_radians()
        if alt is not None and kind != "torque":
            out.append(_Candidate(val(alt), "angle_in_radians", "the crank angle in degrees used as "
                                  "radians (calculator in RAD mode)"))
        for factor, code, words in _DECIMAL:
            out.append(_Candidate(self.cmp(correct, signed) * factor, code, words))
        return out

    def relative(self, ans, signed):
        sol = self.sol
        kind, names = ans.kind, ans.names
        sym = kind
        mag = sol.speed if kind == "v" else sol.acceleration_magnitude
        out = []
        if len(names) == 1:
            X = names[0]
            for Y in self.body_points(X):
                out.append(_Candidate(mag(X, Y), "relative_for_absolute",
                                      f"the relative {sym}_{X}{Y} given for the absolute "
                                      f"{sym}_{X}"))
            sl = self.sc.slider(X)
            if kind in ("v", "a") and isinstance(sl, GuideSlider):
                if kind == "v":
                    out.append(_Candidate(abs(sol.sliding_velocity(X)), "relative_for_absolute",
                                          f"the sliding velocity of {X} on its guide given for "
                                          f"its absolute velocity"))
                # the classic slotted-lever slip: the guide's point under the block for the
                # block itself (a1 for a: they differ by the sliding velocity)
                under = self.point_under_block(X, sl, kind)
                phase = "acceleration" if kind == "a" else "velocity"
                if under is not None:
                    out.append(_Candidate(math.hypot(*under), "coincident_for_block",
                                          f"{sym} of the point of {sl.guide} under the block "
                                          f"({under_label(self.sol, X, phase)}) "
                                          f"given for the block {X}'s own: they differ by "
                                          "the sliding" + (" and Coriolis components" if
                                                           kind == "a" else " velocity")))
            if kind == "a":
                for lk in self.sc.links:
                    if X in lk.points and lk.other(X) in self.sc.ground:
                        out += self.components(X, lk.other(X), lk, f"a_{X}")
        else:
            X, Y = names
            for Z in (X, Y):
                if Z not in self.sc.ground:
                    out.append(_Candidate(mag(Z), "absolute_for_relative",
                                          f"the absolute {sym}_{Z} given for the relative "
                                          f"{sym}_{X}{Y}"))
            lk = self.link_at(X, Y)
            if kind == "a" and lk is not None:
                out += self.components(X, Y, lk, f"a_{X}{Y}")
        return out

    def point_under_block(self, X, sl, kind):
        """Velocity (kind "v") or acceleration ("a") of the guide link's point that lies
        under the block at X, from the guide's known point, omega and alpha."""
        sol = self.sol
        g = self.sc.link(sl.guide)
        K = next((p for p in g.points if p in self.sc.ground), g.points[0])
        (kx, ky), (x, y) = sol.P[K], sol.P[X]
        rx, ry = x - kx, y - ky
        w = sol.W[g.key]
        if kind == "v":
            vx, vy = sol.V[K]
            return (vx - w * ry, vy + w * rx)
        al = sol.Al[g.key]
        ax, ay = sol.A[K]
        return (ax - w * w * rx - al * ry, ay - w * w * ry + al * rx)

    def components(self, X, Y, lk, name):
        sol = self.sol
        r = math.dist(sol.P[X], sol.P[Y])
        w, al = sol.W[lk.key], sol.Al[lk.key]
        return [_Candidate(w * w * r, "component_only",
                           f"only the centripetal component (omega^2 r = {_g(w * w * r)} "
                           f"m/s^2) of {name}; add the tangential one"),
                _Candidate(abs(al) * r, "component_only",
                           f"only the tangential component (alpha r = {_g(abs(al) * r)} "
                           f"m/s^2) of {name}; add the centripetal one")]

    def per_length(self, ans):
        sol = self.sol
        lk = self.sc.link("-".join(ans.names))
        P, Q, L = lk.p, lk.q, lk.length
        out = []
        if ans.kind == "omega":
            for Z in (P, Q):
                if Z not in self.sc.ground:
                    out.append(_Candidate(sol.speed(Z) / L, "absolute_over_length",
                                          f"the absolute v_{Z} divided by {lk.key}; "
                                          f"omega_{lk.key} = v_{Q}{P} / {lk.key}"))
            out.append(_Candidate(sol.speed(Q, P), "not_divided_by_length",
                                  f"v_{Q}{P} not divided by the length {lk.key}"))
            for key in (f"v_{P}{Q}", f"v_{Q}{P}"):
                a = self.given.get(key)
                if a is not None:
                    out.append(_Candidate(abs(a.value) / L, "carried_error",
                                          f"carried from your {key} = {a.raw}: "
                                          f"{_g(abs(a.value))} / {_g(L)} (the method is "
                                          "right)"))
        else:
            w = sol.W[lk.key]
            out.append(_Candidate(sol.acceleration_magnitude(Q, P) / L, "total_for_tangential",
                                  f"the whole a_{Q}{P} divided by {lk.key}; alpha uses its "
                                  "tangential component only"))
            out.append(_Candidate(w * w, "total_for_tangential",
                                  "the centripetal component divided by the length (that "
                                  "is omega^2); alpha uses the tangential component"))
            for Z in (P, Q):
                if Z not in self.sc.ground:
                    out.append(_Candidate(sol.acceleration_magnitude(Z) / L,
                                          "absolute_over_length",
                                          f"the absolute a_{Z} divided by {lk.key}"))
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
        return [_Candidate(v, code, text) for v, code, text in
                coriolis_left_out(self.sol, kind, name)]

    def rubbing(self, X):
        sol, sc = self.sol, self.sc
        rub = sol.rubbing[X]
        r = rub.radius
        pin = next(p for p in sc.pins if p.point == X)
        out = []
        correct = rub.rubbing_velocity
        if pin.given == "diameter":
            out.append(_Candidate(2 * correct, "diameter_as_radius",
                                  f"the diameter {_g(2 * r * 1e3)} mm used as the radius "
                                  f"(r = {_g(r * 1e3)} mm)"))
        else:
            out.append(_Candidate(2 * correct, "diameter_as_radius",
                                  f"twice the radius (a diameter, {_g(2 * r * 1e3)} mm) used "
                                  f"as the radius {_g(r * 1e3)} mm"))
        out.append(_Candidate(correct / 2, "radius_as_diameter",
                              f"the radius {_g(r * 1e3)} mm halved (taken as a diameter)"))
        if len(rub.pairs) > 1:
            for pair, v in rub.pairs.items():
                out.append(_Candidate(v, "one_pair",
                                      f"the rubbing between {pair.replace('|', ' and ')} "
                                      f"only; the largest at {X} is {_g(correct)} m/s"))
        if not rub.pairs:
            return out
        pair = max(rub.pairs, key=rub.pairs.get)
        a, b = pair.split("|")
        wa, wb = rub.bodies[a], rub.bodies[b]
        why = ""
        if wa != 0 and wb != 0 and (wa > 0) != (wb > 0):  # in magnitudes, as written by hand
            how, why = f"(|w_{a}| + |w_{b}|) r", " (the sum: they turn in opposite senses)"
        elif wa != 0 and wb != 0:
            how, why = f"| |w_{a}| - |w_{b}| | r", " (the difference: they turn alike)"
        else:
            how = f"|w_{a} - w_{b}| r"
        rule = (f"pin {X} joins {' and '.join(rub.bodies)}: rub_{X} = {how} = "
                f"{_g(correct)} m/s{why}")
        if wa != 0 and wb != 0:
            if (wa > 0) == (wb > 0):
                out.append(_Candidate((abs(wa) + abs(wb)) * r, "sum_for_difference",
                                      f"the sum of the angular velocities of {a} and {b} "
                                      f"where the difference applies (both turn "
                                      f"{'ccw' if wa > 0 else 'cw'}); {rule}"))
            else:
                out.append(_Candidate(abs(abs(wa) - abs(wb)) * r, "difference_for_sum",
                                      f"the difference of the angular velocities of {a} and "
                                      f"{b} where the sum applies ({a} turns "
                                      f"{'ccw' if wa > 0 else 'cw'}, {b} "
                                      f"{'ccw' if wb > 0 else 'cw'}); {rule}"))
            for body, w in ((a, wa), (b, wb)):
                out.append(_Candidate(abs(w) * r, "one_link_only",
                                      f"the angular velocity of {body} alone; {rule}"))
        at_pin = set(rub.bodies)
        moving = [lk.key for lk in sc.links if lk.key not in sol.plan.fixed_links]
        for omegas, yours in self.omega_sets():
            for n in (1, 2, 3):
                for combo in itertools.combinations(moving, n):
                    if all(c in at_pin for c in combo):
                        continue
                    for signs in itertools.product((1, -1), repeat=n - 1):
                        terms = [(1, combo[0])] + list(zip(signs, combo[1:]))
                        s = sum(sg * omegas[c] for sg, c in terms)
                        if s < 0:
                            terms = [(-sg, c) for sg, c in terms]
                        terms.sort(key=lambda t: -t[0])  # a positive term first
                        expr = _terms([(sg, f"omega_{c}") for sg, c in terms])
                        nums = _terms([(sg, _num(omegas[c])) for sg, c in terms])
                        away = [c for c in combo if c not in at_pin]
                        mine = [c for c in combo if c in yours]
                        out.append(_Candidate(
                            abs(s) * r, "links_not_at_pin",
                            f"angular velocities of links that do not meet at {X} "
                            f"({', '.join(away)}): ({expr}) r = ({nums}) x {_num(r)}"
                            + (f" (your {', '.join('omega_' + c for c in mine)})"
                               if mine else "") + f"; {rule}", window=0.02))
        return out

    def torque(self, signed):
        sol, sc = self.sol, self.sc
        w = sc.input.omega
        crank = sc.input.crank
        out = []
        exact_terms = sol.power_terms
        powers = [(sum(p for _, p in exact_terms), "")]
        # the student's own velocities at the loaded points
        theirs, used = 0.0, []
        for (target, p), load in zip(exact_terms, sc.loads):
            a = self.given.get(f"v_{target}")
            if load.force is not None and a is not None and sol.speed(target) > 0:
                theirs += p * abs(a.value) / sol.speed(target)
                used.append(f"v_{target} = {a.raw}")
            else:
                theirs += p
        if used:
            powers.insert(0, (theirs, f" with your {', '.join(used)}"))
        sign = (lambda t: t) if signed else abs
        exact_power = powers[-1][0]
        for power, label in powers:
            # with the student's own velocities the right method gives another torque than
            # the correct one: say so, so that the two numbers do not read as a contradiction
            then = "" if not label else (
                f" (with the exact velocities: {_g(abs(exact_power))} / {_g(abs(w))} = "
                f"{_g(abs(exact_power / w))} N m)")
            if label:
                out.append(_Candidate(sign(-power / w), "carried_error",
                                      f"carried from your velocities: T = {_g(abs(power))} / "
                                      f"{_g(abs(w))}{label} (the method is right)"))
            for omegas, yours in self.omega_sets():
                for lk in sc.links:
                    if lk.key == crank or lk.key in sol.plan.fixed_links or omegas[lk.key] == 0:
                        continue
                    wl = omegas[lk.key]
                    out.append(_Candidate(
                        sign(-power / (w / abs(w) * wl)), "wrong_omega_in_power_balance",
                        f"the power {_num(abs(power))} W{label} divided by omega_{lk.key} = "
                        f"{_num(wl)} rad/s{' (yours)' if lk.key in yours else ''} instead of "
                        f"the crank's omega_{crank} = {_g(abs(w))} rad/s: T = P / omega_{crank}"
                        f" = {_g(abs(power))} / {_g(abs(w))} = {_g(abs(power / w))} N m"
                        f"{then}"))
            for factor, code, words in _speed_mistakes(sc):
                out.append(_Candidate(sign(-power / (w * factor)), code,
                                      f"{words}, in T = P / omega"))
        # |F| |v| without the angle between them
        full = 0.0
        for load in sc.loads:
            if load.force is not None:
                full += math.hypot(*load.force) * sol.speed(load.target)
            else:
                full += abs(load.torque * sol.W[load.target])
        power = sum(p for _, p in exact_terms)
        if abs(full - abs(power)) > 1e-9 * full:
            out.append(_Candidate(sign(math.copysign(full, -power / w)), "force_times_speed",
                                  "F x v without the angle between force and velocity "
                                  "(the power is F . v = F v cos theta)"))
        return out

    def force_slips(self, kind, names, signed):
        """The force chapter's classic slips, each solved again as the slip would have it:
        the power balance without inertia, the piston's inertia left out, the weights added
        where the problem leaves them out, the inertia couple left out, the offset h on the
        wrong side of G (the couple's sense reversed)."""
        sol, sc = self.sol, self.sc
        out = []

        def pick(f):
            return f.input_torque if kind == "torque" else force_value(f, kind, names[0])

        def again(words, code, **changes):
            try:
                value = pick(analyse(solve(replace(sc, **changes))))
            except PolygonMethodError:
                return
            out.append(_Candidate(self.cmp(value, signed), code, words))

        if kind == "torque" and sol.input_torque is not None:
            out.append(_Candidate(self.cmp(sol.input_torque, signed), "no_inertia",
                                  "the power balance without the inertia forces (T = -sum F . v "
                                  "/ omega leaves out -m a_G . v_G and -I alpha omega)"))
        blocks = [m.body for m in sc.masses if m.block]
        if blocks:
            again(f"the inertia of the reciprocating parts at {', '.join(blocks)} left out",
                  "piston_inertia_left_out",
                  masses=tuple(m for m in sc.masses if not m.block))
        if sc.gravity is None and sc.masses:
            again("the weights added: the problem leaves gravity out (a horizontal engine's "
                  "weights are neglected)", "weight_added",
                  gravity=Gravity(9.81, (0.0, -1.0), "g = 9.81 m/s^2 downwards"))
        turning = [m for m in sc.masses if m.inertia and sol.Al.get(m.body, 0.0)]
        if turning:
            again("the inertia couple -I alpha left out (the inertia force taken through G)",
                  "inertia_couple_left_out",
                  masses=tuple(replace(m, inertia=0.0) for m in sc.masses))
            again("the inertia force's offset h = I alpha / (m a_G) on the wrong side of G",
                  "offset_wrong_side",
                  masses=tuple(replace(m, inertia=-m.inertia) for m in sc.masses))
        return out

    def contact_at_rest(self, ans):
        """Rolling's classic slip: the contact point's acceleration taken as zero (for the
        contact, and for a point of the wheel found from it)."""
        sol, X = self.sol, ans.names[0]
        c = ("contact_acceleration_zero", "the contact point's acceleration taken as zero: "
             "no slip makes its velocity zero, not its acceleration (omega^2 r towards the "
             "centre)")
        if ans.kind == "aI":
            return [_Candidate(0.0, *c)]
        out = []
        for st in sol.plan.steps if len(ans.names) == 1 else ():
            got = st.contact_motion(sol)
            on = {p for w in st.links for p in sol.scene.link(w).points}
            if got is not None and X in on | {q.name for q in sol.scene.points
                                              if q.link in st.links}:
                (ax, ay), (bx, by) = sol.A[X], got[2]
                out.append(_Candidate(math.hypot(ax - bx, ay - by), *c))
        return out

    def own_slip(self, ans):
        """A copying slip: the answer is the student's own value for the same quantity
        (v_BD and v_DB have one magnitude) with its leading digits lost: 36 for 2.36."""
        m = _NUM.search(str(ans.raw))
        mine = _digits(m.group()) if m else None
        if mine is None or len(mine[0]) < 2:
            return None
        for other in self.given.values():
            if other.key == ans.key or other.kind != ans.kind or \
                    set(other.names) != set(ans.names):
                continue
            mo = _NUM.search(str(other.raw))
            theirs = _digits(mo.group()) if mo else None
            if theirs and len(theirs[0]) > len(mine[0]) and theirs[0].endswith(mine[0]):
                return _Candidate(ans.value, "transcription_slip",
                                  f"a slip of the pen: {m.group()} is your own {other.key} = "
                                  f"{mo.group()} with its leading digits lost")
        return None

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
                matches.append((rel if rel > 1e-9 else 0.0, order, c))
        slip = _slip(ans.raw, given, correct, signed) or self.own_slip(ans)
        if slip is not None:
            matches.append((math.inf, 0, slip))
        if not matches:
            return None, None
        matches.sort(key=lambda m: m[:2])
        matches = [(d, c) for d, _, c in matches]
        best = matches[0][1]
        text = best.text
        others = [c for d, c in matches[1:] if c.code != best.code and d <= 0.005
                  and matches[0][0] <= 0.005]
        if others:
            text += "; or " + others[0].text
        return best.code, text


_NUM = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def _digits(number: str):
    """(significant digits, exponent of the last digit) of a written number."""
    s = number.lstrip("+-")
    if "e" in s.lower():
        return None
    if "." in s:
        whole, frac = s.split(".")
    else:
        whole, frac = s, ""
    digits = (whole + frac).lstrip("0")
    return digits, -len(frac)


def _slip(raw: str, given: float, correct: float, signed: bool):
    """A slip of the pen: one digit differs, two are swapped, or leading digits dropped."""
    m = _NUM.search(str(raw))
    if not m or float(m.group()) == 0 or correct == 0:
        return None
    written = m.group()
    factor = given / float(written)  # SI per written unit, with the sign of a sense
    target = correct / factor
    if not signed:
        target = abs(target)
    d = _digits(written)
    if d is None:
        return None
    digits, last = d
    if len(digits) < 2 or target <= 0:
        return None
    q = round(target / 10.0 ** last)
    right = str(q)
    if len(right) == len(digits):
        diff = [i for i in range(len(digits)) if digits[i] != right[i]]
        if len(diff) == 1 and diff[0] < len(digits) - 1:  # a last digit off is no slip
            return _Candidate(given, "transcription_slip",
                              f"a slip of the pen: one digit differs ({written} written for "
                              f"{_written(q, last)})")
        if len(diff) == 2 and diff[1] == diff[0] + 1 and \
                digits[diff[0]] == right[diff[1]] and digits[diff[1]] == right[diff[0]]:
            return _Candidate(given, "transcription_slip",
                              f"a slip of the pen: two digits swapped ({written} written for "
                              f"{_written(q, last)})")
    if len(right) > len(digits) and right.endswith(digits) and len(digits) >= 2:
        return _Candidate(given, "transcription_slip",
                          f"a slip of the pen: leading digits dropped ({written} written for "
                          f"{_written(q, last)})")
    return None


def _written(q: int, last: int) -> str:
    if last >= 0:
        return str(q * 10 ** last)
    s = str(q).rjust(-last + 1, "0")
    return f"{s[:last]}.{s[last:]}"
