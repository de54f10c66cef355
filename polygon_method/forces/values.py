"""The size of what a force answer key names (``F_B``, ``N_B``, ``Fc_L``, ``Fi_L``, ``Ci_L``,
``h_L``, ``Tmax_L``, ``Pmax_L``, ``Thold_O``), and a driver's effort but the crank's torque (``force``,
``torque2``, ``force2``), read from a :class:`~.records.Forces`."""

from __future__ import annotations

from ..common.errors import SceneError
from .grip import value as drive_value
from .records import Forces


def force_value(f: Forces, kind: str, name: str) -> float:
    """The size of what an answer key names: ``F`` the force at pin ``name`` (a pin joining
    two bodies), ``N`` the guide's normal force on the block at ``name``; ``Fc`` the size of
    the contact force on the rolling body ``name`` (a wheel's link, a rack's ``block R``): a
    gear's tooth load; of body ``name``
    (a link's key, or ``block X``): ``Fi`` its inertia force's size ``m |a_G|``, ``Ci`` its
    inertia couple ``-I alpha`` (signed, ccw positive), ``h`` the offset ``|I alpha| / (m
    |a_G|)`` of the book's single force from G (0 where the body has no couple);
    ``Thold`` the torque (ccw positive) the frame holds the fixed circle about ``name``
    with, the sum over the gears rolling on it (an epicyclic's fixed sun or annulus)."""
    if kind in ("Tmax", "Pmax"):  # a friction drive's largest torque, power
        return drive_value(f.contacts, kind, name)
    if kind == "Thold":  # the frame's torque on the fixed circle about ``name``
        held = [c.holding for c in f.contacts if c.about == name and c.holding is not None]
        if not held:
            raise SceneError(f"Thold_{name}: no gear rolls on a fixed circle about {name}")
        return sum(held)
    if kind == "Fc":
        c = next((c for c in f.contacts if c.wheel == name), None)
        if c is None:
            raise SceneError(f"Fc: {name} has no rolling contact")
        return c.load
    if kind in ("Fi", "Ci", "h"):
        i = f.inertia_of(name)
        if i is None:
            raise SceneError(
                f"{kind}_{name.removeprefix('block ')}: {name} has no mass in "
                "[masses]: no inertia force"
            )
        if kind == "Fi":
            return (i.force[0] ** 2 + i.force[1] ** 2) ** 0.5
        if kind == "Ci":
            return i.couple
        if i.offset is None and i.couple != 0:
            raise SceneError(
                f"h_{name.removeprefix('block ')}: a_G = 0: the inertia is a "
                "couple alone, with no single force to offset"
            )
        return abs(i.offset or 0.0)
    if kind == "N":
        g = next((g for g in f.guides if g.key == name), None)
        if g is None:
            raise SceneError(f"N_{name}: the block at {name} slides on no guide")
        return abs(g.normal)
    found = [p for p in f.pins if p.point == name]
    if len(found) != 1:
        raise SceneError(
            f"F_{name}: "
            + (
                f"no pin joins two bodies at {name}"
                if not found
                else f"the pin at {name} joins more than two bodies ("
                + ", ".join(sorted({b for p in found for b in (p.on, p.by)}))
                + "): its forces are in solve's table"
            )
        )
    return found[0].magnitude


def holding_columns(f: Forces) -> list:
    """(name, unit, torque, words) of each fixed circle a gear rolls on, for the sweep's
    columns and its summary: ``Thold_O`` the torque (N m, ccw positive) the frame holds
    the circle about O with, the sum over the gears on it (as :func:`force_value`)."""
    about = dict.fromkeys(c.about for c in f.contacts if c.about is not None)
    return [
        (
            f"Thold_{o}",
            "N m",
            force_value(f, "Thold", o),
            f"torque holding the fixed circle about {o}, ccw +",
        )
        for o in about
    ]


def effort_value(f: Forces | None, kind: str) -> float:
    """A driver's effort other than the crank's torque (signed): ``force`` a driving
    block's, collar's or cylinder's force along its guide (:attr:`Forces.input_torque`),
    ``torque2`` a second crank's torque, ``force2`` a second collar's force along the
    crank (:attr:`Forces.second_torque`). Refused in one line where the mechanism has no
    such effort."""
    if f is None:
        raise SceneError(f"{kind}: a crank drives this mechanism: its effort is a torque")
    if kind == "force":
        if f.driver not in ("block", "collar", "cylinder"):
            raise SceneError(
                f"force: {f.crank} drives this mechanism with a torque, not a force "
                "(its answer key is torque)"
            )
        return f.input_torque
    if f.second_torque is None:
        raise SceneError(f"{kind}: the mechanism has one input: no second effort")
    torque = not (f.second_crank or "").startswith("block ")
    if torque != (kind == "torque2"):
        raise SceneError(
            f"{kind}: the second input's effort is "
            + (
                "a torque (its answer key is torque2)"
                if torque
                else "a force (its answer key is force2)"
            )
        )
    return f.second_torque
