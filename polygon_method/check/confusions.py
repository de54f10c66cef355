"""A wrong answer that is another quantity of the same problem: "you gave v_CB for v_C",
"you gave omega_BC for omega_CD", "the block A's own velocity for the point of the lever
under it". ``d`` is the diagnoser (its solution and scene)."""

from __future__ import annotations

import math

from ..common.numbers import textbook as _g
from ..steps import under_label
from .alternatives import _Candidate

__all__ = ["other_quantities", "under_block", "component_only"]

#: an answer's kind -> the family of kinds it may be confused with (one unit)
_FAMILY = {
    "v": "velocity",
    "vs": "velocity",
    "vu": "velocity",
    "vI": "velocity",
    "a": "acceleration",
    "as": "acceleration",
    "ac": "acceleration",
    "au": "acceleration",
    "aI": "acceleration",
    "omega": "omega",
    "alpha": "alpha",
    "vmin": "velocity",
    "ar": "acceleration",
    "at": "acceleration",
}
_UNIT = {"velocity": "m/s", "acceleration": "m/s^2", "omega": "rad/s", "alpha": "rad/s^2"}


def _quantities(d, family):
    """(key, kind, names) of every quantity of ``family`` the problem has: each moving
    point's, each pair on one link (relative), each slider's, each point under a block;
    each moving link's omega or alpha."""
    sol, sc = d.sol, d.sc
    out = []
    if family in ("omega", "alpha"):
        for lk in sc.links:
            if lk.key not in sol.plan.fixed_links:
                out.append((f"{family}_{lk.key}", family, (lk.p, lk.q)))
        return out
    v = family == "velocity"
    moving = [p for p in sc.point_names if p not in sc.ground]
    out += [(f"{'v' if v else 'a'}_{p}", "v" if v else "a", (p,)) for p in moving]
    for lk in sc.links:
        pts = [q for q in (lk.p, lk.q) + tuple(c.name for c in sc.points if c.link == lk.key)]
        for i, X in enumerate(pts):
            for Y in pts[i + 1 :]:
                out.append((f"{'v' if v else 'a'}_{X}{Y}", "v" if v else "a", (X, Y)))
    for s in sc.sliders:
        out.append((f"{'vs' if v else 'as'}_{s.key}", "vs" if v else "as", (s.key,)))
        if not v and getattr(s, "guide", None):
            out.append((f"ac_{s.key}", "ac", (s.key,)))
    for name, key in under_names(sc).items():
        out.append((f"{'v' if v else 'a'}_{name}", "vu" if v else "au", (key,)))
    return out


def under_names(sc) -> dict:
    """``A1`` -> slider key of the guide's point under each block (see the scene's
    ``under_block_names``)."""
    from ..scene.answers import under_block_names

    return under_block_names(sc.point_names, sc.ground, sc.sliders)


def _same(kind, names, kind2, names2) -> bool:
    """One quantity under two spellings (v_CB and v_BC; omega_BC and omega_CB)."""
    if kind != kind2:
        return False
    if kind in ("v", "a", "omega", "alpha"):
        return set(names) == set(names2)
    return tuple(names) == tuple(names2)


def _sense(kind, x) -> str:
    if kind in ("omega", "alpha"):
        return f"{'ccw' if x > 0 else 'cw'} itself"
    return "the other way along the guide"


def other_quantities(d, ans, signed) -> list:
    """A candidate for every other quantity of the answer's unit in this problem."""
    family = _FAMILY.get(ans.kind)
    if family is None:
        return []
    sol = d.sol
    out = []
    seen = set()
    for key, kind, names in _quantities(d, family):
        if _same(ans.kind, ans.names, kind, names):
            continue
        ident = (kind, frozenset(names) if kind in ("v", "a", "omega", "alpha") else names)
        if ident in seen:
            continue
        seen.add(ident)
        try:
            x = sol.value(kind, names)
        except (KeyError, TypeError, AttributeError):
            continue
        if x is None or not math.isfinite(x) or x == 0:
            continue
        x = d.cmp(x, signed)
        out.append(
            _Candidate(
                x,
                "another_quantity",
                f"you gave {key} ({_g(abs(x))} {_UNIT[family]}) for {ans.key}",
            )
        )
        if signed:  # its size, with the other sense
            out.append(
                _Candidate(
                    -x,
                    "another_quantity",
                    f"you gave {key}'s size ({_g(abs(x))} {_UNIT[family]}, "
                    f"{_sense(kind, x)}) for {ans.key}",
                )
            )
    return out


def under_block(d, ans) -> list:
    """v_A1 / a_A1 asked: the block's own value given for the guide's point under it, or
    (for a_A1 on a guide turning about a fixed pivot) one component of it only."""
    sol, sc = d.sol, d.sc
    sl = sc.slider(ans.names[0])
    X = sl.point
    v = ans.kind == "vu"
    phase = "velocity" if v else "acceleration"
    img = under_label(sol, X, phase)
    own = sol.speed(X) if v else sol.acceleration_magnitude(X)
    block = f"o{X.lower()}" if v else f"o'{X.lower()}'"
    out = [
        _Candidate(
            own,
            "block_for_coincident",
            f"the block {X}'s own {phase} ({block}) given for that of the point of "
            f"{sl.guide} under it ({img}): they differ by the "
            + ("sliding velocity" if v else "sliding and Coriolis components"),
        )
    ]
    if v:
        out.append(
            _Candidate(
                abs(sol.sliding_velocity(sl.key)),
                "relative_for_absolute",
                f"the sliding velocity of {X} on {sl.guide} given for the "
                f"velocity of the point under the block ({img})",
            )
        )
        return out
    g = sc.link(sl.guide)
    K = next((p for p in (g.p, g.q) if p in sc.ground), None)
    if K is None:
        return out
    r = math.dist(sol.P[K], sol.P[X])
    out += component_only(sol.W[g.key], sol.Al[g.key], r, img, f"{K}{X}")
    return out


def component_only(w, al, r, of, r_words="r") -> list:
    """The two slips of one component for the whole relative acceleration ``of`` (a point
    of a link turning at ``w``, ``al``, at ``r`` from its other point, named ``r_words``):
    the centripetal component alone (omega^2 r) and the tangential one alone (alpha r)."""
    return [
        _Candidate(
            w * w * r,
            "component_only",
            f"only the centripetal component (omega^2 {r_words} = {_g(w * w * r)} "
            f"m/s^2) of {of}; add the tangential one",
        ),
        _Candidate(
            abs(al) * r,
            "component_only",
            f"only the tangential component (alpha {r_words} = {_g(abs(al) * r)} "
            f"m/s^2) of {of}; add the centripetal one",
        ),
    ]
