"""A turning-moment diagram's solution in words: ``solve`` (the answers, the defaults
named) and ``steps`` (the book's table: the areas between the crossings, the energy at
each crossing, the greatest and the least, then the flywheel and its rim)."""

from __future__ import annotations

import math

from ..common.numbers import textbook


def book_number(x: float) -> str:
    """Four significant figures, as a book writes them; a whole number from 10,000 to ten
    million written out (17963 J, not 1.7963e+04 J)."""
    return f"{x:.0f}" if 1e4 <= abs(x) < 1e7 else textbook(x)


_g = book_number


__all__ = ["cycle_text", "cycle_steps", "book_number", "answer_lines", "FORMS"]

_FORMS = {
    "areas": "the turning-moment diagram given as its areas above and below the mean line",
    "law": "the turning moment given as a law of the crank angle",
    "table": "the turning moment given as straight segments",
    "strokes": "the turning moment given by each stroke's work, a triangle on its half turn",
    "energy": "the maximum fluctuation of energy given (no diagram)",
    "press": "a punching press",
}


#: what each form of the diagram is, in words
FORMS = _FORMS


def _rpm(w: float) -> str:
    return f"{_g(w)} rad/s ({_g(w * 30 / math.pi)} rpm)"


def _where(c) -> str:
    return c.letter if c.angle is None else f"{c.letter} ({math.degrees(c.angle):.4f} deg)"


def _summary(c) -> list:
    out = []
    if c.form == "press":
        out.append(f"energy of one hole E = {_g(c.E_stroke)} J")
        out.append(f"power of the motor E / t_cycle = {_g(c.power)} W ({_g(c.power / 1e3)} kW)")
    elif c.T_mean is not None:
        out.append(
            f"mean torque T_mean = {_g(c.T_mean)} N m (work per cycle {_g(c.work)} J over "
            f"{math.degrees(c.cycle):g} deg)"
        )
        if c.power is not None:
            out.append(
                f"power at the mean speed T_mean w = {_g(c.power)} W ({_g(c.power / 1e3)} kW)"
            )
    out.append(f"maximum fluctuation of energy dE_max = {_g(c.dE_max)} J")
    if c.Ce is not None:
        out.append(
            f"coefficient of fluctuation of energy Ce = dE_max / (work per cycle) = {_g(c.Ce)}"
        )
    return out


def _flywheel(c) -> list:
    out = []
    if c.inertia is None and c.mass is not None:  # the rim's speed alone, no shaft's speed
        return [
            f"coefficient of fluctuation of speed Cs = {_g(c.Cs)}",
            f"rim's mass m = dE_max / (v^2 Cs) = {_g(c.mass)} kg (its speed {_g(c.rim_speed)} "
            "m/s; I and R need the shaft's speed)",
        ]
    if c.inertia is None:
        return out
    out.append(f"mean speed w = {_rpm(c.speed)}")
    out.append(f"coefficient of fluctuation of speed Cs = {_g(c.Cs)}")
    out.append(f"flywheel's moment of inertia I = {_g(c.inertia)} kg m^2")
    out.append(f"greatest speed {_rpm(c.speed_max)}, least {_rpm(c.speed_min)}")
    if c.alpha_at is not None:
        out.append(
            f"angular acceleration at the crank angle asked (T - R) / I = {_g(c.alpha_at)} rad/s^2"
        )
    if c.mass is not None:
        out.append(f"flywheel's mass m = {_g(c.mass)} kg")
    if c.rim_radius is not None:
        out.append(f"rim: mean radius {_g(c.rim_radius)} m, rim speed {_g(c.rim_speed)} m/s")
        out.append(f"rim's section A = m / (2 pi R rho) = {_g(c.rim_area * 1e6)} mm^2")
    if c.rim_width is not None:
        out.append(
            f"rim's width {_g(c.rim_width * 1e3)} mm, thickness {_g(c.rim_thickness * 1e3)} mm"
        )
    return out


def answer_lines(c) -> list:
    """The answers of ``solve``'s words, a line each (the page lists them)."""
    lines = _summary(c)
    e_max, e_min = c.crossings[c.i_max], c.crossings[c.i_min]
    if c.form not in ("press", "energy"):  # (the energy alone gives no angles)
        lines.append(
            f"  the energy greatest at {_where(e_max)}, least at {_where(e_min)} (the speed "
            "greatest and least there)"
        )
    return lines + _flywheel(c)


def cycle_text(scene, c) -> str:
    """``solve``'s words for a :class:`~polygon_method.forces.flywheel_cycle.CycleEnergy`."""
    lines = [scene.title or "Turning-moment diagram", _FORMS[c.form]]
    lines += ["  " + w for w in c.words]
    lines.append("")
    lines += answer_lines(c)
    return "\n".join(lines)


def cycle_steps(scene, c) -> str:
    """``steps``: the hand solution, in the book's order."""
    out = [f"Step table: {scene.title or 'turning-moment diagram'}", ""]
    k = 1
    if c.form == "press":
        out.append(f"{k}. The energy of one hole E = {_g(c.E_stroke)} J.")
        for w in c.words:
            out.append(f"   {w}")
        k += 1
        out.append(
            f"{k}. The motor gives E over the whole cycle evenly; the flywheel gives what it "
            f"does not while the hole is punched: dE_max = {_g(c.dE_max)} J; the motor's "
            f"power E / t = {_g(c.power)} W."
        )
        k += 1
    elif c.form == "energy":
        out.append(f"{k}. The maximum fluctuation of energy, as the book states it:")
        out += [f"   {w}" for w in c.words]
        k += 1
        if c.T_mean is not None:
            out.append(
                f"{k}. The mean torque T_mean = W / {math.degrees(c.cycle):g} deg = "
                f"{_g(c.work)} J / {c.cycle:.6g} rad = {_g(c.T_mean)} N m."
            )
            k += 1
    else:
        out.append(f"{k}. {_FORMS[c.form][0].upper() + _FORMS[c.form][1:]}:")
        for w in c.words:
            out.append(f"   {w}")
        k += 1
        if c.T_mean is not None:
            out.append(
                f"{k}. The mean torque T_mean = (1 / {math.degrees(c.cycle):g} deg) int T "
                f"dtheta = {_g(c.work)} J / {c.cycle:.6g} rad = {_g(c.T_mean)} N m."
            )
            k += 1
        out.append(f"{k}. The crossings of the mean line and the energy at each (E at a = E):")
        out.append("")
        out += _table(c)
        out.append("")
        k += 1
        e_max, e_min = c.crossings[c.i_max], c.crossings[c.i_min]
        out.append(
            f"{k}. The greatest energy at {e_max.letter}, {_e(e_max.energy)}; the least "
            f"at {e_min.letter}, {_e(e_min.energy)}: dE_max = {_g(e_max.energy)} - "
            f"({_g(e_min.energy)}) = {_g(c.dE_max)} J."
        )
        k += 1
    out += _flywheel_steps(scene, c, k)
    return "\n".join(out)


def _flywheel_steps(scene, c, k) -> list:
    """The flywheel's steps, numbered from ``k``: I (or Cs) from dE_max, the speeds, the
    acceleration asked, the mass and the rim; or the rim's mass from its speed alone."""
    out = []
    if c.inertia is None and c.mass is not None:
        out.append(
            f"{k}. dE_max = I w^2 Cs = m v^2 Cs (I = m R^2, v = w R): m = {_g(c.dE_max)} / "
            f"({_g(c.rim_speed)}^2 x {_g(c.Cs)}) = {_g(c.mass)} kg"
            + (
                "."
                if scene.flywheel.share == 1
                else f", times its share {_g(scene.flywheel.share)}."
            )
        )
    if c.inertia is not None:
        w = c.speed
        if scene.flywheel.inertia is None:
            out.append(
                f"{k}. dE_max = I w^2 Cs: I = {_g(c.dE_max)} / ({_g(w)}^2 x {_g(c.Cs)}) = "
                f"{_g(c.inertia)} kg m^2 (w in rad/s, Cs the whole range)."
            )
        else:
            out.append(
                f"{k}. dE_max = I w^2 Cs: Cs = {_g(c.dE_max)} / ({_g(c.inertia)} x {_g(w)}^2) "
                f"= {_g(c.Cs)}."
            )
        k += 1
        out.append(
            f"{k}. The speed between w (1 - Cs / 2) = {_rpm(c.speed_min)} and w (1 + Cs / 2) "
            f"= {_rpm(c.speed_max)}."
        )
        k += 1
        if c.alpha_at is not None:
            out.append(
                f"{k}. At the crank angle asked, alpha = (T - R) / I = {_g(c.alpha_at)} rad/s^2."
            )
            k += 1
        if c.mass is not None and c.rim_radius is None:
            out.append(f"{k}. The flywheel's mass m = I / k^2 = {_g(c.mass)} kg.")
        elif c.mass is not None:
            out.append(
                f"{k}. The rim at R = {_g(c.rim_radius)} m (rim speed v = w R = "
                f"{_g(c.rim_speed)} m/s): m = {_g(c.mass)} kg; its section A = m / (2 pi R "
                f"rho) = {_g(c.rim_area * 1e6)} mm^2"
                + (
                    f", width {_g(c.rim_width * 1e3)} mm x thickness "
                    f"{_g(c.rim_thickness * 1e3)} mm."
                    if c.rim_width is not None
                    else "."
                )
            )
    return out


def _e(x: float) -> str:
    """An energy from E at a: ``E + 285.9``, ``E - 395.8``, ``E``."""
    return "E" if x == 0 else f"E {'+' if x > 0 else '-'} {_g(abs(x))}"


def _table(c) -> list:
    rows = [("from", "to", "area (J)", "energy at the end")]
    n = len(c.crossings) - 1
    for i in range(n):
        a, b = c.crossings[i], c.crossings[i + 1]
        area = c.areas[i] if i < len(c.areas) else b.energy - a.energy
        end = _e(b.energy)
        rows.append((_where(a), _where(b), f"{area:+.6g}", end))
    widths = [max(len(r[j]) for r in rows) for j in range(4)]
    out = ["   " + "  ".join(x.ljust(w) for x, w in zip(r, widths)).rstrip() for r in rows]
    out.insert(1, "   " + "  ".join("-" * w for w in widths))
    return out
