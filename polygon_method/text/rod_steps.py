"""The connecting rod's equivalent dynamical system worked as a book works it (``steps``'
items, only where the scene's ``[answers]`` asks ``m_small_end``, ``m_L``, ``l_GL``,
``correction_couple`` or ``correction_torque``, with a value or "?"): the rod's numbers,
l1 l2 = k_G^2, the two masses, the correction couple with the second mass at the crank pin
and its torque on the crank shaft. The numbers are
:mod:`polygon_method.linkage.rod_system`'s (the keys' one definition), not worked again."""

from __future__ import annotations

from ..common.errors import PolygonMethodError
from ..linkage.engine_values import split_key
from ..linkage.rod_system import ROD_KEYS, rod_system
from ..scene.reading import scene_table

__all__ = ["rod_items"]


def _g(x) -> str:
    return f"{x:.6g}"


def _asked(scene) -> list:
    """The pistons (None: the scene's one rod) whose rod keys ``[answers]`` asks, in order."""
    if scene.answers:
        keys = [a.key for a in scene.answers]
    else:  # read without its answers (steps): the table's keys
        table = scene_table(scene).get("answers")
        keys = list(table) if isinstance(table, dict) else []
    out = []
    for key in keys:
        base, piston = split_key(key)
        if base in ROD_KEYS and piston not in out:
            out.append(piston)
    return out


def _system_words(s, u, unit) -> list:
    m, l, l1, k2 = s.m, s.l, s.l1, s.k2
    l3 = l - l1
    m_b, m_l, l2 = (s.value(k) for k in ("m_small_end", "m_L", "l_GL"))
    return [
        f"The rod {s.rod}: m = {_g(m)} kg, l = {_g(l / u)} {unit} between the centres; G "
        f"l1 = {_g(l1 / u)} {unit} from the small end {s.small} (the gudgeon pin), "
        f"l3 = l - l1 = {_g(l3 / u)} {unit} from the big end {s.big} (the crank pin); "
        f"k_G = {_g(k2**0.5 / u)} {unit} about G ({s.how or 'as given'}).",
        f"Two masses equivalent to it, one at {s.small}, one at L beyond G, l2 = GL from G: "
        f"m_{s.small} + m_L = m, m_{s.small} l1 = m_L l2 (the same centre), m_{s.small} "
        "l1^2 + m_L l2^2 = m k_G^2 (the same inertia), so l1 l2 = k_G^2: "
        f"l_GL = l2 = k_G^2 / l1 = {_g(k2)} / "
        f"{_g(l1)} = {_g(l2)} m ({_g(l2 / u)} {unit}; L {_g((l1 + l2) / u)} {unit} from "
        f"{s.small}).",
        f"m_small_end = m l2 / (l1 + l2) = {_g(m)} x {_g(l2)} / {_g(l1 + l2)} = "
        f"{_g(m_b)} kg at {s.small}; m_L = m l1 / (l1 + l2) = {_g(m)} x {_g(l1)} / "
        f"{_g(l1 + l2)} = {_g(m_l)} kg at L.",
    ]


def _couple_words(s) -> list:
    m, l, l1, k2 = s.m, s.l, s.l1, s.k2
    l3 = l - l1
    c = s.value("correction_couple")
    out = [
        f"With the second mass at the crank pin {s.big} instead of at L ({_g(m * l3 / l)} kg "
        f"at {s.small}, {_g(m * l1 / l)} kg at {s.big}: m l3 / l and m l1 / l), the two "
        f"masses' moment of inertia about G is m l1 l3 = {_g(m * l1 * l3)} kg m^2, the "
        f"rod's m k_G^2 = {_g(m * k2)} kg m^2: with the rod's angular acceleration "
        f"alpha = {_g(abs(s.alpha))} rad/s^2, the correction couple correction_couple = "
        f"m alpha (l1 l3 - k_G^2) = {_g(m)} x {_g(abs(s.alpha))} x ({_g(l1 * l3)} - "
        f"{_g(k2)}) = {_g(abs(c))} N m (added to the two masses' inertia couple: in the "
        f"sense of alpha where l1 l3 > k_G^2).",
    ]
    if s.ratio is None:
        out.append("correction_torque: the crank is at rest (its speed not given): no ratio.")
    else:
        out.append(
            f"Its torque on the crank shaft (virtual power: the couple works at the rod's "
            f"omega): correction_torque = T' omega_rod / omega = {_g(abs(c))} x "
            f"{_g(abs(s.ratio))} = {_g(abs(c * s.ratio))} N m (for an in-line engine "
            "omega_rod / omega = cos t / sqrt(n^2 - sin^2 t))."
        )
    return out


def rod_items(sol) -> list[str]:
    """``steps``' items for the asked rod keys (none when none are asked); a rod the scene
    cannot answer says why in its one line."""
    sc = sol.scene
    items = []
    for piston in _asked(sc):
        try:
            s = rod_system(sol, piston)
        except PolygonMethodError as exc:
            items.append(f"the equivalent dynamical system: not answered: {exc.message}")
            continue
        items += _system_words(s, sc.length_unit, sc.units) + _couple_words(s)
    return items
