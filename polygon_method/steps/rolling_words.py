"""A rolling wheel's words in the step table (a part of :mod:`.rolling`): its title, how it
is placed, how its omega follows from no slip. A gear given by its teeth is said as a book
says it: "the planet AP (24 teeth, pitch radius m z / 2 = 5 x 24 / 2 = 60 mm) meshes with
the sun of 40 teeth about O (pitch radius 100 mm)"; a wheel with none as "the wheel AP
(radius 60 mm) rolls without slipping on the fixed circle about O"."""

from __future__ import annotations

import math

from ..common.numbers import sense_word
from ..scene.teeth import pitch_words

__all__ = ["noun", "title", "position_words", "omega_words", "circle_words"]


def noun(st):
    """What the wheel is called: ``ring``, ``planet`` (a gear on a fixed sun or annulus),
    ``gear`` (given by its teeth), else ``wheel``."""
    if st.ring:
        return "ring"
    if not st.teeth:
        return "wheel"
    return "planet" if st.on == "circle" else "gear"


def _of_teeth(st):
    """`` of 24 teeth`` where the wheel is given by its teeth, else nothing."""
    return f" of {st.teeth[0]} teeth" if st.teeth and st.teeth[0] else ""


def title(st):
    """``wheel CA rolling on the line ...``; a gear by its teeth ``planet AP of 24 teeth
    meshing with the sun of 40 teeth about O``; a ring ``ring O-Q ... meshing with ...
    inside it``."""
    if st.ring:
        return f"ring {st.wheel}{_of_teeth(st)} meshing with {st.where} inside it"
    if st.teeth:
        return f"{noun(st)} {st.wheel}{_of_teeth(st)} meshing with {st.where}"
    return f"wheel {st.wheel} rolling on {st.where}"


def position_words(st, L):
    """The step table's words for its position: how far the wheel has turned and why (one
    over r per unit of the centre's travel, the gear ratio, or the arm's and the gear's
    turns)."""
    dims = st.dims
    r, ell = dims[1], dims[0]
    phi = math.degrees(dims[6] if st.on == "line" else dims[5])
    phi = round(phi, 9) + 0.0  # -7e-15 deg is 0 (rounding), as the table prints it
    if st.on == "line":
        how = "the wheel turns 1/r rad for each unit its centre moves along the line"
    elif st.theta_rate is not None:
        k = dims[7]  # (a gear turning against the crank: the other way, not "-11 times")
        way = " the other way" if k < 0 else ""
        how = f"the {noun(st)} turns {abs(k):.4g} times the crank's angle{way}, by the gear ratio"
    else:
        kd, kb = dims[3], dims[4]
        how = (
            f"no slip relative to the arm: the {noun(st)} turns "
            + (f"{kd:.4g} times the line of centres {st.base_centre}{st.centre}" if kd else "")
            + (" and " if kd and kb and st.base else "")
            + (f"{kb:.4g} times the gear {st.base}" if kb and st.base else "")
        )
    rad = pitch_words(st.teeth, r, L)  # "radius m z / 2 = ..." for a gear by its teeth
    if st.teeth:  # the gear it meshes with, its pitch radius (from its teeth or the scene)
        what = (
            f"the {noun(st)} {st.wheel} ({rad}) meshes with {st.where}"
            f"{' inside it' if st.ring else ''} (pitch radius {L(dims[2])})"
        )
    elif st.ring:
        what = (
            f"the ring {st.wheel} (pitch {rad}) meshes with {st.where} inside it (pitch "
            f"radius {L(dims[2])})"
        )
    else:  # what it rolls on, its radius (stated, or the centre distance's)
        on = (
            ""
            if st.on == "line"
            else f" ({'pitch ' if st.on == 'gear' else ''}radius {L(dims[2])})"
        )
        what = f"the wheel {st.wheel} ({rad}) rolls without slipping on {st.where}{on}"
    return (
        f"{st.rim}: {what}; from {st.centre} draw {st.centre}{st.rim} = {L(ell)} at "
        f"{phi:.4g} deg ({how})"
    )


def omega_words(st, sol, w, vI):
    """How omega follows from no slip at the contact I, in the book's words."""
    C, W, r, it = st.centre, st.wheel, st.dims[1], noun(st)
    sense = f"{abs(w):.4g} rad/s {sense_word(w)}".rstrip()  # (nought: no sense)
    if st.on != "gear":
        at = "the pitch point" if st.teeth else "the contact"
        return (
            f"no slip: the {it}'s point at {at} I with {st.where} is at rest, "
            f"so I is the {it}'s instantaneous centre and omega_{W} = v_{C} / {C}I = "
            f"{math.hypot(*sol.V[C]):.4g} / {r:.4g} = {sense}"
        )
    O = st.base_centre
    moving = math.hypot(*sol.V[O]) > 0.0
    return (
        f"equal velocities at the pitch point (no slip): the {it}'s point at I moves as "
        "the gear's, v_I = "
        + (f"v_{O} + " if moving else "")
        + f"omega_{st.base} x {O}I = {math.hypot(*vI):.4g} m/s; "
        f"omega_{W} = (v_I - v_{C}) / {C}I, perpendicular to {C}I, = {sense}"
    )


def circle_words(st):
    """``((own,), (base,))``: the wheel's pitch circle and its gear's in words where it is
    a gear given by its teeth (``pitch circle of the planet AP of 24 teeth``, ``pitch circle
    of the sun of 40 teeth about O``), else ``((), ())``."""
    if not st.teeth or st.on == "line":
        return (), ()
    own = f"pitch circle of the {noun(st)} {st.wheel}{_of_teeth(st)}"
    return (own,), (f"pitch circle of {st.where}",)
