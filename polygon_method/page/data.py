"""The page's data: the frames as plain lists, rounded to six significant figures (a
thousandth of a per cent, far below what a drawing or the page's four-figure values show),
with what the script needs to draw them: names, links, plates, sliders, the step table's
scales, and the drawings' colours and dashes.

>>> import polygon_method as pm
>>> from polygon_method.page.frames import frames
>>> d = page_data(frames(pm.load_scene("worked_problems/fourbar_image_points.toml"), 12))
>>> d["points"], [s["text"] for s in d["scales"]]
(['B', 'C', 'E', 'F', 'G'], ['1 cm = 10 mm', '1 cm = 0.05 m/s', '1 cm = 1 m/s²'])
"""

from __future__ import annotations

import numpy as np

from ..draw.style import (
    BODY_EDGE,
    BODY_FACE,
    FORCE_STYLE,
    HEAD_HALF,
    HEAD_LEN,
    IMAGE_FACE,
    LEAST_STYLE,
    LINE_STYLE,
    PITCH_STYLE,
    STYLE,
)
from ..solver.errorbound import USELESS
from ..common.errors import TOL
from ..common.tolerances import PAGE
from ..common.numbers import quiet, sense
from ..draw.plots import MARKS, SERIES_COLORS
from ..polygons.scales import DIAGRAMS, display_unit
from ..scene import Link
from ..steps import image_name, slot_labels, under_label
from ..steps.relations import rigid_acceleration
from ..motion.link_points import asked_pairs, feet_over, pair_quantities
from ..text.link_points import foot_name
from .force_layer import FORCES_CM, force_layers, offset_points
from .frames import Frames, round_sig

__all__ = ["page_data", "diagram_box", "page_style", "offset_points"]

#: the largest polygon a diagram's box holds, in times the median polygon of the cycle
REACH = 1.5
#: the longest force's arrow over the cycle on the page's configuration (cm)
INERTIA_CM = FORCES_CM


def _flat(xy) -> list:
    """(x array, y array) -> [x0, y0, x1, y1, ...] rounded."""
    x, y = (np.asarray(c, dtype=float) for c in xy)
    return round_sig(np.column_stack([np.broadcast_to(x, y.shape), y]))


def res_length(res, cyl) -> float:
    """A cylinder's longest pin-to-pin length over the frames (a size for the noise)."""
    (bx, by), (rx, ry) = res.P[cyl.barrel], res.P[cyl.rod]
    return float(np.max(np.hypot(np.asarray(rx) - bx, np.asarray(ry) - by)))


def _noise_scales(res, moving, links, n) -> dict:
    """Per frame, the largest of each kind (as :attr:`Solution.scales`, and the mechanism's
    size for positions): what rounding noise is measured against."""

    def b(x):
        return np.broadcast_to(np.asarray(x, dtype=float), (n,))

    def most(arrays):
        return np.max(np.array(arrays), axis=0) if arrays else np.zeros(n)

    w = most([np.abs(b(res.W[lk.key])) for lk in links])
    size = np.maximum(
        most([np.hypot(b(res.P[p][0]), b(res.P[p][1])) for p in moving]),
        max([lk.length for lk in links] + [0.0]),
    )
    return {
        "P": size,
        "V": most([np.hypot(b(res.V[p][0]), b(res.V[p][1])) for p in moving]),
        "A": most([np.hypot(b(res.A[p][0]), b(res.A[p][1])) for p in moving]),
        "W": w,
        "Al": most([np.abs(b(res.Al[lk.key])) for lk in links]) + w * w,
    }


def _torque_scale(sc, k):
    """Per frame, the size of the input torque's terms: sum |F| v + |T| omega, over the
    crank's omega (what the torque's rounding noise is measured against)."""
    forces = sum(float(np.hypot(*ld.force)) for ld in sc.loads if ld.force is not None)
    torques = sum(abs(ld.torque) for ld in sc.loads if ld.torque is not None)
    return (forces * k["V"] + torques * k["W"]) / abs(sc.input.omega)


def _quiet(x, scale, n):
    """``x`` (one value per frame) with rounding noise, at most ``TOL.negligible`` of its
    frame's ``scale``, set to 0: the page writes 0, not 1.6e-15 rad/s ccw."""
    return quiet(np.broadcast_to(np.asarray(x, dtype=float), (n,)), scale)


def _lim(e, size, n):
    """Per frame, the absolute bound of a quantity: its relative bound ``e`` times the
    ``size`` it is relative to; 0 where it is no useful bound (then nothing is hidden)."""
    e = np.broadcast_to(np.asarray(e, dtype=float), (n,))
    size = np.broadcast_to(np.asarray(size, dtype=float), (n,))
    return np.where(e < USELESS, e * size, 0.0)


def _own(x, e, size, n):
    """``x`` (one value per frame) set to 0 where it is within its own error bound: the
    page writes 0, not 1.6e-15 rad/s ccw, and never hides a value above its bound."""
    x = np.broadcast_to(np.asarray(x, dtype=float), (n,))
    return np.where(np.abs(x) <= _lim(e, size, n), 0.0, x)


def _own_vec(xy, e, size, n):
    """A vector per frame, each component 0 where it is within the vector's own bound
    (both where its size is)."""
    lim = _lim(e, size, n)
    comps = (np.broadcast_to(np.asarray(c, dtype=float), (n,)) for c in xy)
    return [np.where(np.abs(c) <= lim, 0.0, c) for c in comps]


def _sliding(s, e, sizes, n):
    """A block's sliding velocity, acceleration and Coriolis (x, y), each within its own
    bound 0."""
    ev, ea, ec = e if e is not None else (0.0, 0.0, 0.0)
    cx, cy = _own_vec(s[2:4], ec, sizes["acceleration"], n)
    return [
        round_sig(v)
        for v in (
            _own(s[0], ev, sizes["velocity"], n),
            _own(s[1], ea, sizes["acceleration"], n),
            cx,
            cy,
        )
    ]


def _xy(fr: Frames, phase):
    res = fr.res
    return {"configuration": res.P, "velocity": res.V, "acceleration": res.A}[phase]


def diagram_box(fr: Frames, phase: str, scale) -> list:
    """[x0, y0, x1, y1] (cm of paper, y up) that the diagram needs over the frames: every
    point of every frame (and the pole); where the crank cannot turn fully, except on
    frames where a polygon is more than ``REACH`` times its median size (near a limit
    position, where the polygons grow without bound: what reaches beyond the box is cut
    off there)."""
    n = len(fr)
    table = _xy(fr, phase)
    names = fr.sol.scene.point_names if phase == "configuration" else fr.moving
    x = np.array([np.broadcast_to(table[p][0], (n,)) for p in names]) / scale.per_cm
    y = np.array([np.broadcast_to(table[p][1], (n,)) for p in names]) / scale.per_cm
    if phase != "configuration":  # the pole, where every fixed point's image is
        x, y = np.vstack([x, np.zeros((1, n))]), np.vstack([y, np.zeros((1, n))])
    if phase != "configuration" and not fr.full_turn:
        size = np.hypot(x, y).max(axis=0)
        keep = size <= REACH * np.median(size)
        keep[fr.start] = True
        x, y = x[:, keep], y[:, keep]
    return [
        round(float(x.min()), 3),
        round(float(y.min()), 3),
        round(float(x.max()), 3),
        round(float(y.max()), 3),
    ]


def _unders(sol) -> dict:
    """Each block on a moving guide (by its slider key): the image letter of the guide's
    point under it (a1; a peg in two slots: p1 and p2)."""
    out = {}
    for s in sol.scene.sliders:
        if hasattr(s, "guide"):
            out[s.key] = slot_labels(sol, s.point)[s.key] if s.slot else under_label(sol, s.point)
    return out


def _per_frame(xs, n) -> list:
    """Each of ``xs`` (a number or one per frame) as an array of ``n`` frames."""
    return [np.broadcast_to(np.asarray(x, dtype=float), (n,)) for x in xs]


def _knees(res, links, n) -> dict:
    """Per link (q about p), per frame: where its centripetal component ends and its
    tangential one starts in the acceleration polygon, a_p - omega^2 (q - p) (SI)."""
    out = {}
    for lk in links:
        px, py, qx, qy, w, ax, ay = _per_frame(
            (*res.P[lk.p], *res.P[lk.q], res.W[lk.key], *res.A[lk.p]), n
        )
        cx, cy = rigid_acceleration(qx - px, qy - py, w, 0.0)
        out[lk.key] = _flat([ax + cx, ay + cy])
    return out


def _guide_points(res, sliders, n) -> dict:
    """Per block on a moving guide, per frame: the image of the guide's point under it,
    v_X1 = v_X - vs u (velocities), and a_X1 = a_X - as u - coriolis with the Coriolis
    component's start a_X - coriolis (accelerations), u along the guide (SI): the
    decomposition the step table states, for the script to draw."""
    out = {}
    for s in sliders:
        if "guide" not in s:
            continue
        (g, h) = s["guide"]
        gx, gy, hx, hy, vs, a_s, cx, cy = _per_frame((*res.P[g], *res.P[h], *res.S[s["key"]]), n)
        vx, vy, ax, ay = _per_frame((*res.V[s["point"]], *res.A[s["point"]]), n)
        d = np.hypot(hx - gx, hy - gy)
        d = np.where(d > 0, d, 1.0)
        ux, uy = (hx - gx) / d, (hy - gy) / d
        bx, by = ax - cx, ay - cy
        out[s["key"]] = [
            _flat([vx - vs * ux, vy - vs * uy]),
            _flat([bx - a_s * ux, by - a_s * uy]),
            _flat([bx, by]),
        ]
    return out


def _least(sol, res) -> list:
    """Each ``vmin_XY`` the answers ask, per frame (:func:`..motion.link_points.feet_over`):
    ``t`` the foot p as a fraction of XY from X (beyond an end outside [0, 1]; None where the
    link does not turn: no foot), ``foot`` p's image (SI), ``speed`` the least speed of the
    segment, ``from`` the slowest point's distance from X (m; None where it does not turn),
    and ``p``, ``P`` the names the steps give the foot and the slowest point."""
    out = []
    for f in feet_over(res):
        none = lambda a: [None if s else v for v, s in zip(round_sig(a), f.still)]  # noqa: E731
        out.append(
            {
                "key": f.key,
                "x": f.x,
                "y": f.y,
                "P": foot_name(sol, f.key),
                "p": foot_name(sol, f.key).lower(),
                "t": none(f.t),
                "foot": _flat(f.foot),
                "speed": round_sig(np.where(f.speed <= f.noise, 0.0, f.speed)),  # (noise: 0)
                "from": none(f.distance),
            }
        )
    return out


def _components(sc, res) -> list:
    """Each ``ar_XY``, ``at_XY`` the answers ask, per frame: its key, kind and points, and its
    values (omega^2 XY, |alpha| XY: :func:`..motion.link_points.pair_quantities`, m/s^2)."""
    kinds = {key: (kind, names) for key, kind, names in asked_pairs(sc)}
    return [
        {
            "key": key,
            "kind": kinds[key][0],
            "x": kinds[key][1][0],
            "y": kinds[key][1][1],
            "values": round_sig(np.broadcast_to(value, np.shape(res.theta))),
        }
        for key, unit, value, _ in pair_quantities(sc, res)
        if kinds[key][0] != "vmin"
    ]


def page_style() -> dict:
    """The drawings' colours, widths (pt) and dashes (in line widths), as ``draw`` and
    ``sweep --plot`` have them (:mod:`polygon_method.draw.style`), for the page's script."""
    lines = {k: [c, w, list(d) if d else None] for k, (c, w, d) in STYLE.items()}
    lines["line"] = [LINE_STYLE[0], LINE_STYLE[1], list(LINE_STYLE[2])]
    lines["pitch"] = [PITCH_STYLE[0], PITCH_STYLE[1], list(PITCH_STYLE[2])]
    lines["least"] = [LEAST_STYLE[0], LEAST_STYLE[1], list(LEAST_STYLE[2])]
    for kind, (c, w, _) in FORCE_STYLE.items():  # the forces' arrows, as the sheet's
        lines[kind] = [c, w, None]
    return {
        "lines": lines,
        "head": [HEAD_LEN, HEAD_HALF],
        "body": [BODY_FACE, BODY_EDGE],
        "image": IMAGE_FACE,
        "series": list(SERIES_COLORS),
        "marks": {k: [c, w, list(d) if d else None] for k, (c, w, d) in MARKS.items()},
    }


def page_data(fr: Frames) -> dict:
    """Everything the page's script reads (SI, counter-clockwise positive)."""
    sol, res = fr.sol, fr.res
    sc = sol.scene
    moving = list(fr.moving)
    links = _links(sc, res)
    sliders = _sliders(sc)
    wheels, lines = _rolling_shapes(sol)
    n = len(fr)
    d = {
        "title": sc.title or sc.file or "mechanism",
        "units": sc.units,
        "unit": sc.length_unit,
        # the step table's scales (the page draws each polygon at its own per frame)
        "scales": [
            {"diagram": name, "text": display_unit(s.text), "perCm": s.per_cm}
            for name, s in zip(DIAGRAMS, fr.scales)
        ],
        "theta": [round(float(t), 6) for t in fr.degrees],
        "start": fr.start,
        "fullTurn": fr.full_turn,
        "limits": fr.limits_text,
        "cycle": fr.cycle_degrees,  # the angles shown modulo it (720: a four-stroke)
        "tol": PAGE,  # the script's tolerances, by name (common/tolerances.py)
        "crank": sc.input.crank,
        "pivot": sc.input.pivot,
        **({} if sol.plan.steps[0].periodic else {"param": list(fr.parameter)}),
        "ground": {p: [float(c) for c in xy] for p, xy in sc.ground.items()},
        "points": moving,
        "images": {p: image_name(sc, p) for p in sc.point_names},  # b for B (o1: a moving O)
        "under": _unders(sol),  # the guide's point under a block: a1 (or a2)
        "links": [[lk.p, lk.q, lk.key] for lk in links],
        "plates": [[sc.link(cp.link).p, sc.link(cp.link).q, cp.name] for cp in sc.points],
        "sliders": sliders,
        "knees": _knees(res, links, n),  # where each centripetal component ends
        "guidePoints": _guide_points(res, sliders, n),  # the guide's point under a block
        "least": _least(sol, res),  # vmin_XY asked: the foot p of op square to xy
        "asked": _components(sc, res),  # ar_XY, at_XY asked: their values per frame
        "wheels": wheels,
        "rollLines": lines,
        **_motion(sc, res, moving, links, n),
        "sense": sense(sc.input.omega),
        "warnBelow": TOL.warn,
        "style": page_style(),
    }
    d["inertia"], d["forces"] = force_layers(res, n)
    d.update(_conditions(res, n))
    return d


def _links(sc, res) -> list:
    """The moving links, and each cylinder as a link between its barrel's pivot and its
    rod's end (drawn and tabled so: it turns as one, at its omega; its length changes)."""
    links = [lk for lk in sc.links if not (lk.p in sc.ground and lk.q in sc.ground)]
    links += [Link(c.key, c.barrel, c.rod, res_length(res, c)) for c in sc.cylinders]
    return links


def _sliders(sc) -> list:
    """Each block the page draws: on a moving guide (its guide's two points and link), in
    a yoke's slot (the slot's direction, moving with the pin), or on a fixed path (its
    direction and a point it passes through). A driving wheel's centre path: none."""
    sliders = []
    for s in sc.blocks:  # (a driving wheel's centre path: no block, no guide)
        if hasattr(s, "guide"):
            guided = {"point": s.point, "key": s.key, "guide": [s.first, s.second], "link": s.guide}
            if s.offset:  # an offset slot: cut in a bracket of the link (the link a plate)
                guided["offset"] = float(s.offset)
            sliders.append(guided)
        elif hasattr(s, "yoke"):  # a yoke's slot: a line through the pin, moving with it
            sliders.append({"point": s.point, "key": s.key, "u": [float(c) for c in s.direction]})
        else:
            sliders.append(
                {
                    "point": s.point,
                    "key": s.key,
                    "u": [float(c) for c in s.u],
                    "through": [float(c) for c in s.through],
                }
            )
    return sliders


def _rolling_shapes(sol):
    """``(wheels, lines)``: the pitch circles ([centre, radius], a gear's [centre, radius,
    words]: "pitch circle of the sun of 40 teeth about O") and the fixed lines
    wheels roll on ([point, point]), as the steps' shapes give them at the stated instant."""
    shapes = [sh for st in sol.plan.steps for sh in st.shapes(sol.P)]
    wheels = [  # pitch circles (a gear's with its words: its tooltip)
        [sh[1], float(sh[2]), *sh[3:]] for sh in shapes if sh[0] == "circle"
    ]
    lines = [
        [[float(c) for c in sh[1]], [float(c) for c in sh[2]]]
        for sh in shapes
        if sh[0] == "ground line"
    ]  # the fixed lines wheels roll on
    return wheels, lines


def _motion(sc, res, moving, links, n) -> dict:
    """The motion per frame: positions, velocities, accelerations, each link's omega and
    alpha, each block's sliding and the input torque, each with its rounding noise (within
    its own error bound, or below its kind's size) written 0."""
    k = _noise_scales(res, moving, links, n)
    eb = res.error_bounds  # each quantity's own bound, per frame: below it, noise
    return {
        "P": {p: _flat([_quiet(c, k["P"], n) for c in res.P[p]]) for p in moving},
        "V": {
            p: _flat(_own_vec(res.V[p], eb.V.get(p, 0.0), eb.scales["velocity"], n)) for p in moving
        },
        "A": {
            p: _flat(_own_vec(res.A[p], eb.A.get(p, 0.0), eb.scales["acceleration"], n))
            for p in moving
        },
        "W": {
            lk.key: round_sig(_own(res.W[lk.key], eb.W.get(lk.key, 0.0), eb.scales["omega"], n))
            for lk in links
        },
        "Al": {
            lk.key: round_sig(_own(res.Al[lk.key], eb.Al.get(lk.key, 0.0), eb.scales["alpha"], n))
            for lk in links
        },
        "S": {s.key: _sliding(res.S[s.key], eb.S.get(s.key), eb.scales, n) for s in sc.sliders},
        "torque": None
        if res.input_torque is None
        else round_sig(_quiet(res.input_torque, _torque_scale(sc, k), n)),
    }


def _conditions(res, n) -> dict:
    """Each frame's worst-conditioned step: its condition (six figures: shown to three,
    rounded once) and which step it is, with the steps' labels; none where no step has a
    condition."""
    conds = [
        (st.label, np.broadcast_to(res.cond[st.index], (n,)))
        for st in res.plan.steps
        if st.index in res.cond
    ]
    if not conds:
        return {}
    table = np.array([c for _, c in conds])
    worst = table.argmin(axis=0)
    return {
        "condition": round_sig(table.min(axis=0)),
        "conditionStep": [int(i) for i in worst],
        "stepLabels": [label for label, _ in conds],
    }
