"""The ``forces`` entry of ``solve --json`` (:func:`forces_dict`): the force analysis'
records as plain numbers (SI, ccw positive), the sign rule stated in the entry."""

from __future__ import annotations

import math

from .grip import json as grip_json
from .records import Contact, Forces

__all__ = ["forces_dict"]


def _vec(v):
    return [v[0] + 0.0, v[1] + 0.0]  # + 0.0: no -0.0 in the JSON


def _contact_dict(c: Contact) -> dict:
    """One contact's JSON entry: the force on the wheel by ``by`` at the contact point; for
    teeth the pressure angle (deg, and whether the scene states it) and the tooth load, for
    a friction grip the least friction coefficient."""
    d = {
        "point": _vec(c.point),
        "by": c.by,
        "normal_force": c.normal + 0.0,
        "tangential_force": c.tangential + 0.0,
        "normal": _vec(c.m),
        "force": _vec(c.force),
    }
    if c.teeth is None:
        d["required_friction"] = c.required_friction
        d.update(grip_json(c))
    else:
        d.update(
            pressure_angle=math.degrees(c.teeth),
            pressure_angle_stated=c.stated,
            tooth_load=c.load + 0.0,
        )
    if c.holding is not None:  # a fixed circle: the torque the frame holds it with
        d["holding_torque"] = c.holding + 0.0
    return d


def _second(f: Forces) -> dict:  # a second crank's torque, a second collar's force
    if f.second_crank.startswith("block "):
        return {"block": f.second_crank, "collar": True, "input_force": f.second_torque + 0.0}
    return {"crank": f.second_crank, "input_torque": f.second_torque + 0.0}


def forces_dict(f: Forces) -> dict:
    """The ``forces`` entry of ``solve --json`` (SI, ccw positive; the sign rule in
    ``convention``)."""
    pins = {}
    for p in f.pins:
        pins.setdefault(p.point, []).append(
            {"on": p.on, "by": p.by, "force": _vec(p.force), "magnitude": p.magnitude}
        )
    return {
        "convention": "SI, counter-clockwise positive; a pin's force is the force on body "
        "'on' by body 'by' (body 'by' feels its opposite); moments about the "
        "frame's origin",
        "bodies": {
            i.body: {
                "mass": i.mass,
                "moment_of_inertia": i.inertia,
                "centre_of_mass": _vec(i.G),
                "acceleration_of_centre": _vec(i.a_G),
                "inertia_force": _vec(i.force),
                "inertia_couple": i.couple + 0.0,
                "offset": i.offset,
                "offset_point": None if i.offset is None else _vec(i.offset_point),
            }
            for i in f.inertia
        },
        "pins": pins,
        "guides": {
            g.key: {
                "normal_force": g.normal + 0.0,
                "normal": _vec(g.n),
                "force": _vec(g.force),
                "by": g.by,
                **(
                    {"couple": g.couple + 0.0}
                    if g.couple is not None and isinstance(g.couple, float) and g.couple
                    else {}
                ),
            }
            for g in f.guides
        },
        ("input_torque" if f.driver in ("crank", "wheel") else "input_force"): f.input_torque + 0.0,
        **({} if f.centre_force is None else {"centre_force": _vec(f.centre_force)}),
        f.driver: f.crank,
        **({} if f.second_crank is None else {"second": _second(f)}),
        **({"contacts": {c.wheel: _contact_dict(c) for c in f.contacts}} if f.contacts else {}),
        **(
            {
                "friction": {
                    "power": f.friction_power + 0.0,
                    "guides": [
                        {"on": it[0], "what": it[1], "force": _vec(it[2]), "at": _vec(it[3])}
                        for it in f.friction
                        if len(it) == 4
                    ],
                    "pins": [
                        {"on": it[0], "what": it[1], "couple": it[2] + 0.0}
                        for it in f.friction
                        if len(it) == 3
                    ],
                }
            }
            if f.friction
            else {}
        ),
        "shaking_force": _vec(f.shaking_force),
        "shaking_moment": f.shaking_moment + 0.0,
        "steps": [
            {"step": s.index + 1, "kind": s.kind, "title": s.title, "condition": s.condition}
            for s in f.steps
        ],
    }
