"""The mistakes of rubbing velocities and the input torque: a diameter for a radius, the sum
of two angular velocities for their difference (or the reverse), links that do not meet at
the pin, the wrong omega in the power balance, F v without the angle between them. ``d``
is the diagnoser (its solution, scene, the student's answers and omegas)."""

from __future__ import annotations

import itertools
import math

from ..common.tolerances import SAME
from ..common.numbers import textbook as _g
from ..common.numbers import working as _num
from .alternatives import _Candidate, _speed_mistakes
from .tolerance import _terms


def _length(sc, x) -> str:
    """A length in the scene's own unit: ``19.05 mm`` in a scene in mm, ``0.75 in`` in one
    in inches."""
    return f"{_g(x / sc.length_unit)} {sc.units}"


def rubbing(d, X):
    """The known slips in a rubbing velocity at pin ``X``: the diameter taken for the radius, the
    omegas added where they should be subtracted (or the reverse), and the like; ``(value,
    mistake)`` pairs for the diagnoser ``d``."""
    sol, sc = d.sol, d.sc
    rub = sol.rubbing[X]
    out = _radius_slips(sc, rub, X)
    if not rub.pairs:
        return out
    rule, slips = _sense_slips(rub, X)
    return out + slips + _links_not_at_pin(d, rub, X, rule)


def _radius_slips(sc, rub, X) -> list:
    """The radius taken for a diameter or the reverse, and one pair of bodies at a pin that
    joins more."""
    r = rub.radius
    pin = next(p for p in sc.pins if p.point == X)
    correct = rub.rubbing_velocity
    out = []
    if pin.given == "diameter":
        out.append(
            _Candidate(
                2 * correct,
                "diameter_as_radius",
                f"the diameter {_length(sc, 2 * r)} used as the radius (r = {_length(sc, r)})",
            )
        )
    else:
        out.append(
            _Candidate(
                2 * correct,
                "diameter_as_radius",
                f"twice the radius (a diameter, {_length(sc, 2 * r)}) used "
                f"as the radius {_length(sc, r)}",
            )
        )
    out.append(
        _Candidate(
            correct / 2,
            "radius_as_diameter",
            f"the radius {_length(sc, r)} halved (taken as a diameter)",
        )
    )
    if len(rub.pairs) > 1:
        for pair, v in rub.pairs.items():
            out.append(
                _Candidate(
                    v,
                    "one_pair",
                    f"the rubbing between {pair.replace('|', ' and ')} "
                    f"only; the largest at {X} is {_g(correct)} m/s",
                )
            )
    return out


def _sense_slips(rub, X) -> tuple:
    """(the rule in words, the slips): the sum of the omegas for their difference or the
    reverse, and one link's omega alone, at the pair of bodies that rub the most."""
    r, correct = rub.radius, rub.rubbing_velocity
    out = []
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
    rule = f"pin {X} joins {' and '.join(rub.bodies)}: rub_{X} = {how} = {_g(correct)} m/s{why}"
    if wa != 0 and wb != 0:
        if (wa > 0) == (wb > 0):
            out.append(
                _Candidate(
                    (abs(wa) + abs(wb)) * r,
                    "sum_for_difference",
                    f"the sum of the angular velocities of {a} and {b} "
                    f"where the difference applies (both turn "
                    f"{'ccw' if wa > 0 else 'cw'}); {rule}",
                )
            )
        else:
            out.append(
                _Candidate(
                    abs(abs(wa) - abs(wb)) * r,
                    "difference_for_sum",
                    f"the difference of the angular velocities of {a} and "
                    f"{b} where the sum applies ({a} turns "
                    f"{'ccw' if wa > 0 else 'cw'}, {b} "
                    f"{'ccw' if wb > 0 else 'cw'}); {rule}",
                )
            )
        for body, w in ((a, wa), (b, wb)):
            out.append(
                _Candidate(
                    abs(w) * r, "one_link_only", f"the angular velocity of {body} alone; {rule}"
                )
            )
    return rule, out


def _links_not_at_pin(d, rub, X, rule) -> list:
    """Omegas of links that do not meet at the pin, one to three, added or subtracted (the
    student's own omegas too, from the diagnoser ``d``)."""
    sol, sc, r = d.sol, d.sc, rub.radius
    out = []
    at_pin = set(rub.bodies)
    moving = [lk.key for lk in sc.links if lk.key not in sol.plan.fixed_links]
    for omegas, yours in d.omega_sets():
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
                    out.append(
                        _Candidate(
                            abs(s) * r,
                            "links_not_at_pin",
                            f"angular velocities of links that do not meet at {X} "
                            f"({', '.join(away)}): ({expr}) r = ({nums}) x {_num(r)}"
                            + (f" (your {', '.join('omega_' + c for c in mine)})" if mine else "")
                            + f"; {rule}",
                            window=0.02,
                        )
                    )
    return out


def torque(d, signed):
    """The known slips in the input torque by power balance: a load's power left out or its sign
    turned, the student's own velocities used; ``(value, mistake)`` pairs (``signed``: the answer
    gave a sense)."""
    sol, sc = d.sol, d.sc
    w = sc.input.omega
    crank = sc.input.crank
    out = []
    exact_terms = sol.power_terms
    powers = [(sum(p for _, p in exact_terms), "")]
    # the student's own velocities at the loaded points
    theirs, used = 0.0, []
    for (target, p), load in zip(exact_terms, sc.loads):
        a = d.given.get(f"v_{target}")
        if load.force is not None and a is not None and sol.speed(target) > 0:
            theirs += p * abs(a.value) / sol.speed(target)
            used.append(f"v_{target} = {a.raw}")
        else:
            theirs += p
    theirs += sum(p for _, p in exact_terms[len(sc.loads) :])  # a passive cylinder's F vs
    if used:
        powers.insert(0, (theirs, f" with your {', '.join(used)}"))
    sign = (lambda t: t) if signed else abs
    exact_power = powers[-1][0]
    for power, label in powers:
        # with the student's own velocities the right method gives another torque than
        # the correct one: say so, so that the two numbers do not read as a contradiction
        then = (
            ""
            if not label
            else (
                f" (with the exact velocities: {_g(abs(exact_power))} / {_g(abs(w))} = "
                f"{_g(abs(exact_power / w))} N m)"
            )
        )
        if label:
            out.append(
                _Candidate(
                    sign(-power / w),
                    "carried_error",
                    f"carried from your velocities: T = {_g(abs(power))} / "
                    f"{_g(abs(w))}{label} (the method is right)",
                )
            )
        for omegas, yours in d.omega_sets():
            for lk in sc.links:
                if lk.key == crank or lk.key in sol.plan.fixed_links or omegas[lk.key] == 0:
                    continue
                wl = omegas[lk.key]
                out.append(
                    _Candidate(
                        sign(-power / (w / abs(w) * wl)),
                        "wrong_omega_in_power_balance",
                        f"the power {_num(abs(power))} W{label} divided by omega_{lk.key} = "
                        f"{_num(wl)} rad/s{' (yours)' if lk.key in yours else ''} instead of "
                        f"the crank's omega_{crank} = {_g(abs(w))} rad/s: T = P / omega_{crank}"
                        f" = {_g(abs(power))} / {_g(abs(w))} = {_g(abs(power / w))} N m"
                        f"{then}",
                    )
                )
        for factor, code, words in _speed_mistakes(sc):
            out.append(_Candidate(sign(-power / (w * factor)), code, f"{words}, in T = P / omega"))
    # |F| |v| without the angle between them
    full = 0.0
    for load in sc.loads:
        if load.force is not None:
            full += math.hypot(*load.force) * sol.speed(load.target)
        else:
            full += abs(load.torque * sol.W[load.target])
    power = sum(p for _, p in exact_terms)
    if abs(full - abs(power)) > SAME * full:
        out.append(
            _Candidate(
                sign(math.copysign(full, -power / w)),
                "force_times_speed",
                "F x v without the angle between force and velocity "
                "(the power is F . v = F v cos theta)",
            )
        )
    return out
