"""The textbook corpus (tests/textbook/*.toml) and what its tests share: the scenes, their
solutions and 50-digit references (cached), the comparison with the reference, the scenes
turned to other crank angles, the other assembly of a point."""

import math
import re
from pathlib import Path

from mpmath import mpf

from polygon_method import load_scene, parse_scene, solve
from polygon_method.common.errors import PolygonMethodError
from polygon_method.scene import FixedPath, GuideSlider
from reference import reference_solution

__all__ = [
    "HERE",
    "FILES",
    "CRANKED",
    "BLOCK_DRIVEN",
    "REL",
    "NOISE",
    "solved",
    "worst_error",
    "at_angle",
    "turned",
    "parameters",
    "other_position",
    "guide_direction",
]

HERE = Path(__file__).resolve().parent / "textbook"
FILES = sorted(HERE.glob("*.toml"))
#: the corpus's scenes driven by a block along its guide ([input] block: the motion's
#: parameter is the block's place s, not a crank's angle), and those driven by a crank
BLOCK_DRIVEN = [f for f in FILES if load_scene(f).input.block is not None]
CRANKED = [f for f in FILES if f not in BLOCK_DRIVEN]
REL = 1e-9
NOISE = re.compile(r"\d(\.\d+)?e-(1[0-9]|[2-9][0-9])")  # a number below 1e-10: noise


def _norm(v):
    return math.hypot(float(v[0]), float(v[1])) if isinstance(v, tuple) else abs(float(v))


def _err(got, want, scale):
    if isinstance(want, tuple):
        d = math.hypot(float(mpf(got[0]) - want[0]), float(mpf(got[1]) - want[1]))
    else:
        d = abs(float(mpf(got) - want))
    return d / max(_norm(want), scale, 1e-300)


_CACHE = {}


def solved(path):
    """(scene, solution, reference). Where the motion is given on another quantity (``vs_B``,
    ``omega_BC``, a cylinder's ``vs_OR``), the scene is the solution's, with the crank's
    speed found: the reference is solved at that speed, and test_textbook checks that the
    reference then moves the given quantity as stated (which makes the found speed right)."""
    if path not in _CACHE:
        scene = load_scene(path)
        sol = solve(scene)
        if scene.input.given is not None:
            scene = sol.scene
        _CACHE[path] = scene, sol, reference_solution(scene, sol.P)
    return _CACHE[path]


def worst_error(scene, sol, ref):
    """(relative error, what) of the worst quantity against the reference."""
    errs = []
    for tab, got in (("positions", sol.P), ("velocities", sol.V), ("accelerations", sol.A)):
        scale = max(_norm(v) for v in ref[tab].values())
        errs += [(_err(tuple(got[n]), ref[tab][n], scale), f"{tab} {n}") for n in scene.point_names]
    w = max(_norm(v) for v in ref["omega"].values())
    for tab, got, scale in (
        ("omega", sol.W, w),  # alpha's size: omega^2 as well (a
        (
            "alpha",
            sol.Al,  # parallelogram has every alpha 0)
            max(_norm(v) for v in ref["alpha"].values()) + w * w,
        ),
    ):
        errs += [
            (_err(got[lk.key], ref[tab][lk.key], scale), f"{tab} {lk.key}") for lk in scene.links
        ]
    vs = max(_norm(v) for v in ref["velocities"].values())
    as_ = max(_norm(v) for v in ref["accelerations"].values())
    for sl in scene.sliders:  # by the slider's key: a peg in two slots has one per slot
        want, got = ref["sliders"][sl.key], sol.S[sl.key]
        errs += [
            (_err(got[0], want["vs"], vs), f"sliding velocity {sl.key}"),
            (_err(got[1], want["as"], as_), f"sliding acceleration {sl.key}"),
            (_err(tuple(sol.coriolis(sl.key)), want["coriolis"], as_), f"Coriolis {sl.key}"),
        ]
    return max(errs)


def _mirror(x, a, b):
    """x reflected in the line through a and b."""
    ux, uy = b[0] - a[0], b[1] - a[1]
    n = math.hypot(ux, uy)
    ux, uy = ux / n, uy / n
    dx, dy = x[0] - a[0], x[1] - a[1]
    t = dx * ux + dy * uy
    fx, fy = a[0] + t * ux, a[1] + t * uy
    return (2 * fx - x[0], 2 * fy - x[1])


def guide_direction(scene, P, X):
    """The unit direction of the path or guide of a slider at X (a moving guide from its
    first point to its second), or None."""
    s = next((s for s in scene.sliders if s.point == X), None)
    if s is None:
        return None
    if isinstance(s, FixedPath):
        return s.u
    if hasattr(s, "yoke"):  # the slot of a translating yoke
        return s.direction
    (x1, y1), (x2, y2) = P[s.first], P[s.second]
    n = math.hypot(x2 - x1, y2 - y1)
    return ((x2 - x1) / n, (y2 - y1) / n)


def other_position(scene, P, X):
    """The other assembly of X: the mirror image in the line of the two centres of its
    dyad; for a slider, in the normal to its path through the link's other end; for the
    free end of a slotted link, through the link's pivot. None for the crank's tip."""
    two = scene.input.second
    if X == scene.input.tip or X == scene.input.block or (two is not None and X == two.tip):
        return None  # the crank's tip, a driving block, a second input: one position
    if len(scene.slots(X)) == 2:
        return None  # a peg in two slots: where they cross, one position
    if any(r.rim == X for r in scene.rolling):
        return None  # a rolling wheel's point, a rack: one position (the no-slip relation)
    tri = _triad_other(scene, P, X)
    if tri is not False:
        return tri
    from polygon_method.solver.compiler import compile_plan

    slotted = {st.finds[0] for st in compile_plan(scene).steps if st.kind == "slotted"}
    for s in scene.sliders:  # the free end of a slotted link: on the other side of its pivot
        if isinstance(s, GuideSlider) and X in slotted and X in (s.first, s.second):
            k = P[s.second if X == s.first else s.first]
            if s.offset:  # an offset slot: the other tangent from the block to its circle
                return _other_tangent(k, P[s.point], P[X], s.offset if X == s.second else -s.offset)
            return (2 * k[0] - P[X][0], 2 * k[1] - P[X][1])
    ends = [lk.q if lk.p == X else lk.p for lk in scene.links if X in (lk.p, lk.q)]
    u = guide_direction(scene, P, X)
    if u is not None and len(ends) == 1:  # a link and a slider: the arc cuts the guide twice
        b = P[ends[0]]
        return _mirror(P[X], b, (b[0] - u[1], b[1] + u[0]))
    if len(ends) >= 2:  # the first two links at X in the file: the dyad that finds X
        return _mirror(P[X], P[ends[0]], P[ends[1]])
    return None


def _other_tangent(k, a, n, e):
    """The lever's end n reflected to the other tangent from the block at a to the circle of
    radius |e| about the pivot k (the slot e to the left of k -> n): a - k = t w + e perp(w)
    with t the other way, w = (t d - e perp(d)) / |d|^2."""
    dx, dy = a[0] - k[0], a[1] - k[1]
    m2 = dx * dx + dy * dy
    L = math.dist(k, n)
    t = -((n[0] - k[0]) * dx + (n[1] - k[1]) * dy) / L  # the tangent's t, turned over
    return (k[0] + L * (t * dx + e * dy) / m2, k[1] + L * (t * dy - e * dx) / m2)


def _triad_other(scene, P, X):
    """For a point of a class-III group: its place in the nearest other assembly of the
    group (all of them searched, test_triad checks the search against a brute-force one),
    None if there is none; False for a point no triad finds."""
    from polygon_method.solver.compiler import compile_plan
    from polygon_method.steps import triad

    st = next((s for s in compile_plan(scene).steps if s.kind == "triad" and X in s.finds), None)
    if st is None:
        return False
    K = tuple(P[k] for k in st.knowns)
    here = {p: P[p] for p in st.finds}
    best = None
    for h in (1.0, -1.0) if st.sides else (1.0,):
        prm = st.params[:6] + (h * st.params[6],)
        for q in triad.assemblies(K, prm):
            V = dict(zip(st.finds, triad.vertices(*q, prm, math.cos, math.sin)))
            d = sum(math.dist(V[p], here[p]) for p in st.finds)
            if d > 1e-9 and (best is None or d < best[0]):
                best = (d, V[X])
    return None if best is None else best[1]


_TURNED = {}


def turned(path, angle):
    """The scene with its crank at ``angle``, or None where it is not assembled there (or
    its hints do not fit); cached."""
    if (path, angle) not in _TURNED:
        try:
            _TURNED[path, angle] = solve(parse_scene(at_angle(path, angle)))
        except PolygonMethodError:
            _TURNED[path, angle] = None
    return _TURNED[path, angle]


def parameters(path):
    """The other values of a scene's parameter its tests take: a crank at 0, 90, 180 and
    270 deg; a driving block at its guide's through point (0), half its place, a quarter
    beyond it and its place mirrored (-s), in the scene's units."""
    if load_scene(path).input.block is None:
        return (0, 90, 180, 270)
    s = float(_PLACE.search(Path(path).read_text(encoding="utf-8")).group(2))
    return (0, s / 2, 1.25 * s, -s)


def turned_cases():
    """(path, parameter) at each of :func:`parameters`: those that assemble (on the
    scene's hints), and those refused there, each with its refusal."""
    good, refused = [], []
    for f in FILES:
        for a in parameters(f):
            try:
                solve(parse_scene(at_angle(f, a)))
                good.append((f, a))
            except PolygonMethodError as exc:
                refused.append((f, a, exc))
    return good, refused


#: a driving block's place in a scene's [input]: s_B = 380
_PLACE = re.compile(r"(?m)^(s_\w+) = (-?[0-9.]+)")


def at_angle(path, angle):
    """The scene's text with its crank at ``angle`` (deg); for a scene driven by a block,
    with the block at the place ``angle`` along its guide (the scene's units): the
    motion's parameter, whichever the driver."""
    text = Path(path).read_text(encoding="utf-8")
    if load_scene(path).input.block is not None:
        return _PLACE.sub(lambda m: f"{m.group(1)} = {angle!r}", text, count=1)
    return re.sub(r"(?m)^angle = .*$", f"angle = {angle}", text)
