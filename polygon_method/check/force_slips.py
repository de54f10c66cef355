"""The force chapter's classic slips, each answer solved again as the slip would have it
(read by the diagnoser ``mistakes._Diagnoser`` as ``d``: its solution, scene and comparison)."""

from __future__ import annotations

from dataclasses import replace

from ..common.errors import PolygonMethodError
from ..forces import analyse, force_value
from ..motion.solution import solve
from ..scene import Gravity
from ..scene.force_records import rolling_body
from . import rod_slip
from .alternatives import _Candidate

__all__ = ["force_slips"]


def force_slips(d, kind, names, signed):
    """The force chapter's classic slips, each solved again as the slip would have it:
    the power balance without inertia, the piston's inertia left out, the weights added
    where the problem leaves them out, the inertia couple left out, the offset h on the
    wrong side of G (the couple's sense reversed); a tooth load given as its part along
    the tangent (the pressure angle left out)."""
    sol, sc = d.sol, d.sc
    out = []

    def pick(f):
        return (
            f.input_torque
            if kind == "torque"
            else force_value(f, kind, rolling_body(sc, names) if kind == "Fc" else names[0])
        )

    def again(words, code, **changes):
        try:
            value = pick(analyse(solve(replace(sc, **changes))))
        except PolygonMethodError:
            return
        out.append(_Candidate(d.cmp(value, signed), code, words))

    if kind == "torque" and sol.input_torque is not None:
        out.append(
            _Candidate(
                d.cmp(sol.input_torque, signed),
                "no_inertia",
                "the power balance without the inertia forces (T = -sum F . v "
                "/ omega leaves out -m a_G . v_G and -I alpha omega)",
            )
        )
    if kind == "Fc":  # the tooth load's part along the tangent given for the whole
        body = rolling_body(sc, names)
        c = next((c for c in sol.forces.contacts if c.wheel == body), None)
        if c is not None and c.teeth is not None and c.teeth > 0:
            out.append(
                _Candidate(
                    d.cmp(abs(c.tangential), signed),
                    "pressure_angle_left_out",
                    "the tooth load's part along the common tangent given "
                    "for the whole load: the pressure angle left out (the "
                    "load acts along the line of action, |T| / cos phi)",
                )
            )
    blocks = [m.body for m in sc.masses if m.block]
    if blocks:
        again(
            f"the inertia of the reciprocating parts at {', '.join(blocks)} left out",
            "piston_inertia_left_out",
            masses=tuple(m for m in sc.masses if not m.block),
        )
    if sc.gravity is None and sc.masses:
        again(
            "the weights added: the problem leaves gravity out (a horizontal engine's "
            "weights are neglected)",
            "weight_added",
            gravity=Gravity(9.81, (0.0, -1.0), "g = 9.81 m/s^2 downwards"),
        )
    turning = [m for m in sc.masses if m.inertia and sol.Al.get(m.body, 0.0)]
    if turning:
        again(
            "the inertia couple -I alpha left out (the inertia force taken through G)",
            "inertia_couple_left_out",
            masses=tuple(replace(m, inertia=0.0) for m in sc.masses),
        )
        again(
            "the inertia force's offset h = I alpha / (m a_G) on the wrong side of G",
            "offset_wrong_side",
            masses=tuple(replace(m, inertia=-m.inertia) for m in sc.masses),
        )
    two = rod_slip.two_masses(sc, turning)  # the equivalent system, no correction couple
    if two:
        masses = tuple(replace(m, inertia=two.get(m.body, m.inertia)) for m in sc.masses)
        again(rod_slip.WORDS, "correction_couple_left_out", masses=masses)
    return out
