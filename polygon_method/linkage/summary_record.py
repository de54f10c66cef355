"""A sweep summary's records (:class:`Summary`, one :class:`Extreme` per quantity) and their
text, as ``sweep --summary`` prints it; :mod:`.summary` reduces a sweep into them."""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..common.numbers import quiet
from ..scene import Scene
from ..solver.compiler import compile_plan
from ..solver.tracking import fmt_deg

__all__ = ["Summary", "Extreme"]

# --------------------------------------------------------------------------- summaries


@dataclass(frozen=True)
class Extreme:
    """The largest and smallest value of one quantity over the sweep, with the crank angles
    (deg) where they occur. ``at_max``/``at_min`` are None for a constant quantity."""

    name: str
    unit: str
    maximum: float
    at_max: float | None
    minimum: float
    at_min: float | None
    what: str = ""
    refined: bool = False
    max_unbounded: bool = False  # grows without bound towards the limit position at_max
    min_unbounded: bool = False
    #: where the maximum (minimum) grows without bound towards an angle that is not a limit
    #: position: why (a group's force equations singular there), else ""
    max_where: str = ""
    min_where: str = ""

    @property
    def constant(self) -> bool:
        """The quantity does not change over the sweep (it has no maximum of its own)."""
        return self.at_max is None


@dataclass(frozen=True)
class Summary:
    """Extremes of every quantity, the reachable range and the notes of a sweep.

    Crank angles are in degrees, within one turn: in [0, 360) (a reachable range that
    passes 0 runs from its start to its end "through 0").
    """

    scene: Scene
    requested: int
    evaluated: int
    extremes: tuple
    limits: tuple
    change_points: tuple
    notes: tuple = ()
    formulas: tuple = ()  # lines comparing a textbook's approximate formula with the exact
    range_deg: tuple | None = None  # (lo, hi) where the crank cannot turn fully
    deg: object = field(default=math.degrees, repr=False, compare=False)  # rad -> shown deg

    def extreme(self, name) -> Extreme:
        """The entry of one quantity (``v_C``, ``omega_BC``, ``vs_B``, ``mu at C``...)."""
        for e in self.extremes:
            if e.name == name:
                return e
        raise KeyError(name)

    def text(self) -> str:
        """The summary as ``sweep --summary`` prints it."""
        sc = self.scene
        if not compile_plan(sc).steps[0].periodic:  # asked of the driver: a block's travel
            return self._block_text()
        inp = sc.input
        if inp.given is not None:
            g = inp.given
            held = (
                f"{g.key} held at {g.text}"
                + (
                    f", {g.rate_key} at {g.rate_text}"
                    if g.rate is not None
                    else " (steady)"
                    if compile_plan(sc).given.rate is not None
                    else ", the crank's alpha constant"
                )
                + " at every angle (the crank's speed follows); "
            )
        elif sc.at_rest:  # the motion per rad/s: the virtual velocities
            held = (
                f"crank {inp.crank} at rest, the motion per 1 rad/s "
                f"{'ccw' if inp.omega > 0 else 'cw'} (virtual); the forces "
                + (
                    f"of a start from rest with alpha = {sc.start_alpha:+.6g} rad/s^2"
                    if sc.start_alpha
                    else "that hold it"
                )
                + " at every angle; "
            )
        else:
            held = (
                f"crank {inp.crank} at {abs(inp.omega):.6g} rad/s "
                f"{'ccw' if inp.omega > 0 else 'cw'}"
                + (f", {inp.alpha:+.6g} rad/s^2" if inp.alpha else "")
                + " at every angle"
                + (
                    f" (the two cranks' speeds found from {', '.join(f'{g.key} = {g.text}' for g in inp.found_from)}, held by the train's fixed ratios)"
                    if inp.found_from
                    else ""
                )
                + "; "
            )
        if inp.given is not None and self.evaluated < self.requested:
            held = (
                f"{held.rstrip('; ')}; where {inp.given.key} hardly moves whatever the "
                "crank's speed (its condition below 1e-3, a dead centre for this input) "
                "the crank's speed is unbounded: those angles are left out and the "
                "extremes beside them grow without bound; "
            )
        out = [
            f"sweep of {sc.title or sc.file or 'the mechanism'}",
            held + f"{self.evaluated} of {self.requested} crank angles evaluated",
        ]
        deg = self.deg
        if self.limits and self.range_deg is not None:
            lo, hi = self.range_deg
            out.append(
                f"the crank cannot turn fully: it reaches {lo:.4f} to {hi:.4f} deg "
                + ("(through 0) " if hi < lo else "")
                + "on the scene's branch"
            )
            for lp in self.limits:
                out.append(f"  limit position at {fmt_deg(deg(lp.theta))} deg: {lp.step}: {lp.why}")
        if self.evaluated < self.requested:
            out.append(
                f"  {self.requested - self.evaluated} requested angle(s) are left out "
                "(beyond the limit positions, or singular)"
            )
        for cp in self.change_points:
            out.append(f"change point at crank angle {fmt_deg(deg(cp.theta))} deg: {cp.why}")
        out.extend(self.notes)
        out.append("")
        self._table(out, "deg")
        return "\n".join(out)

    def _block_text(self) -> str:
        """The text of a sweep over a driving block's stroke: places in the scene's units."""
        sc = self.scene
        inp, uname = sc.input, sc.units
        driver = compile_plan(sc).steps[0]
        block = driver.finds[0]
        deg = self.deg
        per = (
            f"1 rad/s of the wheel, its centre {driver.sense(inp.omega)}"
            if inp.wheel is not None
            else f"1 m/s {driver.sense(inp.omega)}"
        )
        moving = (
            f"{driver.title} at rest, the motion per {per} (virtual); the forces "
            + (
                f"of a start from rest with {abs(sc.start_alpha):.6g} m/s^2 "
                f"{driver.sense(sc.start_alpha)}"
                + (" of its centre" if inp.wheel is not None else "")
                if sc.start_alpha
                else "that hold it"
            )
            if sc.at_rest
            else f"{driver.title} at {abs(inp.omega):.6g} m/s {driver.sense(inp.omega)}"
            + (f", {abs(inp.alpha):.6g} m/s^2 {driver.sense(inp.alpha)}" if inp.alpha else "")
        )
        out = [
            f"sweep of {sc.title or sc.file or 'the mechanism'}",
            f"{moving} at every place; {self.evaluated} of {self.requested} places "
            f"s_{block} along its guide evaluated",
        ]
        if self.range_deg is not None:
            lo, hi = self.range_deg
            mover = driver.parameter(sc)[0].removeprefix("place of ")  # block A, ...
            out.append(
                f"the {mover} travels from s_{block} = {lo:.6g} to "
                f"{hi:.6g} {uname} on the scene's branch"
                + (
                    " (its stated stroke)"
                    if inp.stroke is not None and all(lp.step == driver.label for lp in self.limits)
                    else ""
                )
            )
            for lp in self.limits:
                out.append(f"  end at s_{block} = {deg(lp.theta):.6g} {uname}: {lp.step}: {lp.why}")
        if self.evaluated < self.requested:
            out.append(
                f"  {self.requested - self.evaluated} requested place(s) are left out "
                "(beyond the ends of its travel, or singular)"
            )
        for cp in self.change_points:
            out.append(f"change point at s_{block} = {deg(cp.theta):.6g} {uname}: {cp.why}")
        out.extend(self.notes)
        out.append("")
        self._table(out, uname)
        return "\n".join(out)

    def _table(self, out, unit):
        """The table of extremes, each at its parameter (crank angle in deg, or a block's
        place in ``unit``)."""
        at = f"at ({unit})"
        if self.extremes:
            w = max(len(e.name) for e in self.extremes)
            out.append(
                f"{'quantity':<{w}}  {'unit':<7} {'maximum':>12} {at:>10} {'minimum':>12} {at:>10}"
            )
            # at rest nothing moves: a driver's effort holds it against the loads alone (its
            # column's words say "with inertia", as they are where the mechanism moves)
            still = self.scene.at_rest and not self.scene.start_alpha
            sc = self.scene  # a static analysis (no body massive): the loads (and friction)
            fr = sc.friction is not None and sc.friction.active
            massless = not sc.masses and sc.gravity is None
            for e in self.extremes:
                what = e.what.replace("with inertia", "at rest: the loads alone, no inertia")
                what = what if still else e.what
                if massless and not still:
                    loads = "of the loads and friction" if fr else "of the loads"
                    what = what.replace("with inertia", f"{loads} (no body massive)")
                if e.constant:
                    out.append(f"{e.name:<{w}}  {e.unit:<7} {e.maximum:>12.6g} {'(constant)':>10}")
                    continue
                # rounding noise about a true zero (a speed at a dead centre) is 0 already
                # (each value within its own error bound: _Reducer._noise); an extreme
                # refined to a zero of the quantity is found to about TOL.negligible of the
                # quantity's range, the accuracy of its place: written 0 too
                big = max(abs(e.maximum), abs(e.minimum))
                mx = "+unbounded" if e.max_unbounded else f"{quiet(e.maximum, big):.6g}"
                mn = "-unbounded" if e.min_unbounded else f"{quiet(e.minimum, big):.6g}"
                out.append(
                    f"{e.name:<{w}}  {e.unit:<7} {mx:>12} "
                    f"{fmt_deg(e.at_max, 3):>10} {mn:>12} "
                    f"{fmt_deg(e.at_min, 3):>10}" + (f"  {what}" if what else "")
                )
                for flag, at, word, why in (
                    (e.max_unbounded, e.at_max, "grows", e.max_where),
                    (e.min_unbounded, e.at_min, "falls", e.min_where),
                ):
                    if flag and why:
                        out.append(
                            f"{'':<{w}}  ({word} without bound towards {fmt_deg(at, 3)} {unit})"
                        )
                    elif flag:
                        out.append(
                            f"{'':<{w}}  ({word} without bound towards the limit "
                            f"position at {fmt_deg(at, 3)} {unit})"
                        )
        if self.formulas:
            out.append("")
            out.extend(self.formulas)
