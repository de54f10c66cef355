"""The force chapter's classic slips, each answer solved again as the slip would have it
(read by the diagnoser ``mistakes._Diagnoser`` as ``d``: its solution, scene and comparison)."""

from __future__ import annotations

from dataclasses import replace

from ..common.errors import PolygonMethodError
from ..forces import analyse, force_value
from ..motion.solution import solve
from ..scene import Gravity
from ..scene.cylinder_loads import stated
from ..scene.force_records import Friction, rolling_body
from . import rod_slip
from .alternatives import _Candidate

__all__ = ["force_slips"]


def force_slips(d, kind, names, signed):
    """The force chapter's classic slips, each solved again as the slip would have it:
    the friction or the piston's inertia left out, the weights added where the problem
    leaves them out, the inertia couple left out, the offset h on the wrong side of G;
    a tooth load's part along the tangent given for it; a fixed gear's holding torque by
    the ratio of teeth turned over; a driver's effort by the power
    balance without inertia, or as at rest, or given as another force at its block."""
    sol, sc, out = d.sol, d.sc, []

    def pick(f):
        if kind in ("torque", "force"):
            return f.input_torque
        if kind in ("torque2", "force2"):
            return f.second_torque
        if kind in ("Tmax", "Pmax"):
            return force_value(f, kind, sc.link("-".join(names)).key)
        return force_value(f, kind, rolling_body(sc, names) if kind == "Fc" else names[0])

    def again(words, code, **changes):
        """The slip's candidate: the scene solved again with ``changes``, or None."""
        try:
            value = pick(analyse(solve(replace(sc, **changes))))
        except PolygonMethodError:
            return None
        return _Candidate(d.cmp(value, signed), code, words)

    def redo(words, code, **changes):
        out.extend(c for c in (again(words, code, **changes),) if c is not None)

    _friction_left_out(sc, redo)
    if kind in ("torque", "force", "torque2", "force2"):
        out += _effort_slips(d, kind, signed, again)
    out += _gear_slips(d, kind, names, signed)
    blocks = [m.body for m in sc.masses if m.block]
    if blocks:
        redo(
            f"the inertia of the reciprocating parts at {', '.join(blocks)} left out",
            "piston_inertia_left_out",
            masses=tuple(m for m in sc.masses if not m.block),
        )
    if sc.gravity is None and sc.masses:
        redo(
            "the weights added: the problem leaves gravity out (a horizontal engine's "
            "weights are neglected)",
            "weight_added",
            gravity=Gravity(9.81, (0.0, -1.0), "g = 9.81 m/s^2 downwards"),
        )
    turning = [m for m in sc.masses if m.inertia and sol.Al.get(m.body, 0.0)]
    if turning:
        redo(
            "the inertia couple -I alpha left out (the inertia force taken through G)",
            "inertia_couple_left_out",
            masses=tuple(replace(m, inertia=0.0) for m in sc.masses),
        )
        redo(
            "the inertia force's offset h = I alpha / (m a_G) on the wrong side of G",
            "offset_wrong_side",
            masses=tuple(replace(m, inertia=-m.inertia) for m in sc.masses),
        )
    for c in stated(sc):  # a passive cylinder's given force
        for words, code, slip in _cylinder_slips(c):
            redo(words, code, cylinders=tuple(slip if x is c else x for x in sc.cylinders))
    two = rod_slip.two_masses(sc, turning)  # the equivalent system, no correction couple
    if two:
        masses = tuple(replace(m, inertia=two.get(m.body, m.inertia)) for m in sc.masses)
        redo(rod_slip.WORDS, "correction_couple_left_out", masses=masses)
    return out


def _gear_slips(d, kind, names, signed) -> list:
    """A gear's slips: a tooth load's part along the tangent given for it, a fixed gear's
    holding torque by the ratio of teeth turned over."""
    sol, sc, out = d.sol, d.sc, []
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
    if kind == "Thold":  # the ratio of teeth turned over; another shaft's torque
        out += _ratio_inverted(d, names[0], signed)
        out += _shaft_torques(d, signed)
    return out


def _shaft_torques(d, signed) -> list:
    """A fixed gear's holding torque given as another shaft's: the driver's, or a torque
    load's on a shaft of the train (the output machine's): the three sum to nought, so
    the fixed gear holds what the other two leave."""
    out = []
    driver = d.sol.forces.input_torque if d.sol.forces is not None else None
    shafts = [("the driving torque", driver)] if driver else []
    shafts += [(f"the torque on {ld.target}", ld.torque) for ld in d.sc.loads if ld.torque]
    for words, t in shafts:
        out.append(
            _Candidate(
                d.cmp(t, signed),
                "shaft_torque_for_holding",
                f"{words} given for the holding torque: the torques on the train sum to "
                "nought, so the fixed gear holds what the driving and the driven shafts "
                "leave, not either one",
            )
        )
    return out


def _ratio_inverted(d, centre, signed) -> list:
    """The holding torque of the fixed circle about ``centre`` by the ratio of teeth turned
    over: a planet's two tooth loads are equal, so the fixed gear takes the other gear's
    torque times z_fixed / z_other; the slip takes z_other / z_fixed, the right value
    times (r_other / r_fixed)^2 (the pitch radii, in proportion to the teeth)."""
    sc, out = d.sc, []
    for r in sc.rolling:
        if r.on != "circle" or r.base_centre != centre:
            continue
        others = [q for q in sc.rolling if q.base == r.wheel and q.on == "gear"]
        if len(others) != 1 or not r.base_radius:  # (a compound planet: no one ratio)
            continue
        q, held = others[0], d.sol.value("Thold", (centre,))
        k = (q.radius / r.base_radius) ** 2
        ratio = (
            f"{q.teeth[0]}/{r.teeth[1]}"
            if r.teeth and q.teeth and q.teeth[0] and r.teeth[1]
            else "r_other / r_fixed"
        )
        out.append(
            _Candidate(
                d.cmp(held * k, signed),
                "teeth_ratio_inverted",
                f"the ratio of teeth turned over ({ratio} taken for its inverse): the "
                "planet's tooth loads are equal, so the fixed gear takes the other gear's "
                "torque times z_fixed / z_other (each torque the load times its own pitch "
                "radius)",
            )
        )
    return out


def _friction_left_out(sc, redo) -> None:
    """With friction: the answer solved again without it (``redo`` adds the candidate)."""
    if sc.friction is not None and sc.friction.active:
        redo(
            "the friction left out (mu |N| at the slides, the friction circles' couples mu r "
            "|F| at the pins: against the sliding and the turning, the driver overcomes them)",
            "friction_left_out",
            friction=Friction(0.0, 0.0),
        )


def _cylinder_slips(c) -> list:
    """(words, code, the cylinder as the slip has it) of a passive cylinder's given force:
    left out, a pressure on the annulus taken on the whole bore, a damper's sense turned, a
    spring's sense turned or its free length left out."""
    out = [
        (
            f"the force in the cylinder {c.key} left out",
            "cylinder_force_left_out",
            replace(c, push=0.0, damping=0.0, stiffness=0.0),
        )
    ]
    if c.annulus is not None:
        p, bore = c.annulus
        out.append(
            (
                f"the pressure in {c.key} taken on the whole bore: on the annulus side the "
                "rod's area comes off (p pi/4 (D^2 - d^2))",
                "rod_area_not_taken_off",
                replace(c, push=-p * bore),
            )
        )
    if c.damping:
        out.append(
            (
                f"the damper in {c.key} taken as helping its motion (+c vs): a damper "
                "resists it, F = -c vs",
                "damper_sense_turned",
                replace(c, damping=-c.damping),
            )
        )
    if c.stiffness:
        out += [
            (
                f"the spring in {c.key} taken as k (L - L0): a spring stretched pulls its ends "
                "together, compressed pushes them apart, F = k (L0 - L)",
                "spring_sense_turned",
                replace(c, stiffness=-c.stiffness),
            ),
            (
                f"the spring in {c.key} taken as k L, its free length left out: it pushes "
                "only as far as it is compressed below its free length, F = k (L0 - L)",
                "free_length_left_out",
                replace(c, free_length=0.0),
            ),
        ]
    return out


def _effort_slips(d, kind, signed, again) -> list:
    """A driver's effort: the power balance without inertia (for the first input), the
    inertia left out with the weights kept (as at rest: ``again`` solves the scene again
    so; where the problem has weights, or for a second input, which no power balance
    gives), and a force along a guide given as another force at its block."""
    sol, sc, out = d.sol, d.sc, []
    frictionless = sc.friction is None or not sc.friction.active
    massless = not sc.masses and sc.gravity is None  # (the loads' balance: friction left out)
    if (
        kind in ("torque", "force")
        and sol.input_torque is not None
        and (frictionless or not massless)
    ):
        out.append(
            _Candidate(
                d.cmp(sol.input_torque, signed),
                "no_inertia",
                "the power balance without the inertia forces (T = -sum F . v "
                "/ omega leaves out -m a_G . v_G and -I alpha omega"
                + ("" if frictionless else ", and the friction")
                + ")"
                if kind == "torque"
                else "the power balance of the loads alone (F = -sum P / v_s leaves out "
                "the weights' m g . v_G, -m a_G . v_G and -I alpha omega)",
            )
        )
    starting = sc.start_alpha != 0.0  # (from rest: the holding effort is the slip)
    if (
        sc.masses
        and (starting or not sc.at_rest)
        and (sc.gravity is not None or kind.endswith("2") or starting)
    ):
        slip = again(
            "the inertia left out: the driver's effort of the weights and loads alone, as "
            "if the mechanism were at rest (D'Alembert's -m a_G and -I alpha belong among "
            "the forces it holds)",
            "inertia_left_out",
            at_rest=True,
            start_alpha=0.0,
        )
        out += [slip] if slip is not None else []
    if kind in ("force", "force2"):
        out += _driver_slips(d, kind, signed)
    return out


def _driver_slips(d, kind, signed) -> list:
    """A driver's force along its guide (a driving block's, a collar's): the guide's
    normal force on its block given for it, and the whole force on the block from the
    link pinned to it (its part along the guide is the driver's)."""
    sol, out = d.sol, []
    f = sol.forces
    if f is None:
        return out
    body = f.crank if kind == "force" else f.second_crank
    if not body or not body.startswith("block "):
        return out
    X = body.removeprefix("block ")
    g = next((g for g in f.guides if g.point == X), None)
    if g is not None:
        out.append(
            _Candidate(
                d.cmp(abs(g.normal), signed),
                "normal_for_driver",
                f"the guide's normal force on the block at {X} (N_{X}, across the guide) "
                "given for the driver's force along it",
            )
        )
    for p in f.pins:
        if p.point == X and body in (p.on, p.by):
            out.append(
                _Candidate(
                    d.cmp(p.magnitude, signed),
                    "pin_force_for_driver",
                    f"the whole force at the pin {X} (F_{X}, of {p.by if p.on == body else p.on} "
                    "on the block) given for the driver's force: only its part along the "
                    "guide is the driver's, with the block's own loads and inertia",
                )
            )
    return out
