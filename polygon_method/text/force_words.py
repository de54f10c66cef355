"""The force chapter's words of what acts on a mechanism: inertia, weights, loads, friction
(a static force analysis has the loads alone; a mechanism at rest its weights and loads,
no inertia), for the ``steps`` document's sections 6 to 8."""

from __future__ import annotations

from ..common.numbers import fmt

__all__ = ["acting", "known_words", "rest_blocks", "symbol_words", "holding", "start_words"]


def holding(sc) -> bool:
    """At rest with no acceleration: the weights and loads held, no inertia (starting from
    rest with one has the inertia of the start)."""
    return bool(sc.at_rest) and not getattr(sc, "start_alpha", 0.0)


def start_words(sc) -> str:
    """Starting from rest, in words: the crank's alpha and what it gives (or "")."""
    a = getattr(sc, "start_alpha", 0.0)
    if not (sc.at_rest and a):
        return ""
    b = None if sc.input.crank is not None else sc.input.tip  # (a driving block, a wheel's centre)
    rod = next((s.guide for s in sc.sliders if s.point == b and hasattr(s, "guide")), None)
    way = (
        f"{'outward along' if a > 0 else 'inward along'} its rod {rod}"  # a driving collar
        if rod is not None
        else f"{'along' if a > 0 else 'against'} its path"
    )
    given, per = (
        (f"as_{b} = {fmt(abs(a))} m/s^2 {way}", f"m/s of {b}")
        if b is not None
        else (
            f"alpha_{sc.input.crank} = {fmt(abs(a))} rad/s^2 {'ccw' if a > 0 else 'cw'}",
            "rad/s of the crank",
        )
    )
    return (
        f"starting from rest with {given}: no velocity yet, so every acceleration has its "
        "tangential terms alone (no centripetal, no Coriolis component), the start's "
        f"acceleration times the motion per {per} (a_G = {given.split(' =')[0]} x v_G per "
        f"{per.split(' of')[0]})"
    )


def rest_blocks(sc, f, F, vec) -> list:
    """Section 6 at rest: no inertia (nothing moves), each body's weight at G."""
    g = sc.gravity
    said = (
        f"Gravity: {g.text}, each weight m g at G (the centre of mass, a point of the body)."
        if g is not None
        else "No gravity (the scene gives no [gravity]): the masses weigh nothing here."
    )
    blocks = [
        (
            "p",
            "At rest: nothing moves, so no body has an inertia force or couple (a_G = 0, "
            f"alpha = 0); the weights and the loads alone act. {said}",
        )
    ]
    if g is None:
        return blocks
    rows = []
    u = sc.length_unit
    for i in f.inertia:
        w = (i.mass * g.g * g.direction[0], i.mass * g.g * g.direction[1])
        at = f"({fmt(i.G[0] / u)}, {fmt(i.G[1] / u)})"
        rows.append(
            (
                i.body,
                fmt(i.mass),
                i.how.split("; I_G")[0],
                at,
                f"{fmt(i.mass)} x {fmt(g.g)}",
                vec(w, F),
            )
        )
    header = ("body", "m (kg)", "G", f"G ({sc.units})", "m g", "weight W")
    return blocks + [("table", header, rows)]


def acting(sc) -> str:
    """What acts on the mechanism, in words: "inertia, weights and loads", "the weights and
    loads" at rest, "the loads alone" in a static force analysis (no mass).

    >>> from types import SimpleNamespace as S
    >>> acting(S(masses=(1,), at_rest=False, gravity=1, loads=(1,), indicator=None,
    ...          friction=None))
    'inertia, weights and loads'
    >>> acting(S(masses=(), at_rest=False, gravity=None, loads=(1,), indicator=None,
    ...          friction=None))
    'the loads alone'
    """
    kinds = []
    if sc.masses and not holding(sc):
        kinds.append("inertia")
    if sc.masses and sc.gravity is not None:
        kinds.append("weights")
    if sc.loads or getattr(sc, "indicators", ()):
        kinds.append("loads")
    if sc.friction is not None:
        kinds.append("friction")
    if not kinds:
        return "no load: nothing to hold"
    if len(kinds) == 1:
        return f"the {kinds[0]} alone" if kinds[0] != "inertia" else "inertia alone"
    words = ", ".join(kinds[:-1]) + " and " + kinds[-1]
    return words if kinds[0] == "inertia" else "the " + words


def known_words(sc) -> str:
    """What a body's known resultant holds (section 7): its inertia force and couple (not
    at rest, nor without masses), its weight (with gravity), the loads, the friction."""
    if sc is None:
        return "the inertia force and couple, the weight, the loads"
    parts = []
    if sc.masses and not holding(sc):
        parts.append("the inertia force and couple")
    if sc.masses and sc.gravity is not None:
        parts.append("the weight")
    parts.append("the loads")
    fr = sc.friction
    if fr is not None and fr.active:  # (their sizes from the forces found)
        parts.append(
            "the friction (mu |N| at the guides, the couples mu r |F| at the pins, from the "
            "forces found, the walk repeated until they settle)"
        )
    return ", ".join(parts) + (
        " (no inertia: at rest)"
        if holding(sc)
        else " (the inertia of the start from rest)"
        if sc.at_rest
        else ""
    )


def symbol_words(sc) -> str:
    """The symbols of the known forces named on the polygons: Fi_3, W_3, where they act."""
    inertia = sc is None or (sc.masses and not holding(sc))
    weight = sc is None or (sc.masses and sc.gravity is not None)
    words = (["Fi_3 the inertia force of 3"] if inertia else []) + (
        ["W_3 its weight" if inertia else "W_3 the weight of 3"] if weight else []
    )
    return "".join(f", {w}" for w in words)


def outside_words(sc) -> str:
    """After the shaking force and moment: where loads act from off the frame (a machine
    resisting the output, a cutting force), their reactions are on what applies them, not
    on this frame, so the shaking sums are theirs with the inertia's ("" where none does: a
    gas force's reaction is on the cylinder's cover, the frame, and is counted)."""
    if not any(getattr(ld, "gas", None) is None for ld in sc.loads):
        return ""
    return (
        " (the loads act from off the frame: their reactions are on what applies them, so "
        "the shaking sums are the loads' with the weights' and the inertia's)"
    )
