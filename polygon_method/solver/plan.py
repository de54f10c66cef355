"""The construction plan: the scene's constraint graph compiled into an ordered tuple of
steps, each one a hand construction (see :mod:`polygon_method.steps`), with the assembly
branch of each step chosen.

The plan is topology plus branch choices. Dimensions (lengths, fixed paths, the positions
of carried points on their bodies, ground points, the crank's angle, speed and
acceleration) are inputs: :meth:`Plan.dimensions` reads them from any scene of the same
shape, as floats or numpy arrays, and :meth:`Plan.run` evaluates the steps with them, so
that one call evaluates many crank angles or many mechanisms. Each step records, as
defaults, the dimensions of the scene the plan was compiled from.

:mod:`polygon_method.solver.compiler` makes a plan from a scene. One instant (floats) runs each
step's three phases in a row (``bind_instant``); arrays run all positions, then all
velocities, then all accelerations (``bind``). Both call the same formulas.

>>> from polygon_method.scene import parse_scene
>>> from polygon_method.solver.compiler import compile_plan
>>> print(compile_plan(parse_scene('''
... [ground]
... A = [0, 0]
... D = [100, 0]
... [links]
... AB = 50
... BC = 66
... CD = 56
... [input]
... crank = "AB"
... angle = 60
... speed = "10.5 rad/s cw"
... ''')))
plan: 2 steps
  1. crank AB: finds B
  2. dyad BC, CD at C: finds C
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from ..common.errors import TOL, PolygonMethodError
from ..scene import FixedPath, GuideSlider, Scene
from ..steps import Carried, Context, Crank, Dyad, SliderDyad, SlottedLink, State
from .collector import held_off

__all__ = [
    "Plan",
    "Dims",
    "Bodies",
    "Crank",
    "Dyad",
    "SliderDyad",
    "SlottedLink",
    "Carried",
    "Context",
    "State",
]


_new = object.__new__

# --------------------------------------------------------------------------- bodies


class Bodies:
    """The rigid bodies of a scene in their own frames: link ``key`` has its first point at
    (0, 0), its second at (L, 0) and each carried point at (lam L, mu L). A link with
    carried points is one rigid body (a plate)."""

    def __init__(self, scene: Scene):
        self.scene = scene
        self._carried = carried = {}
        for cp in scene.points:
            carried.setdefault(cp.link, []).append(cp)
        # each link's own key; the frame of a link with no carried point made here, in the
        # same pass (:meth:`frame` makes the others, and the frames asked by other names)
        self._links = links = {}
        self._frames = frames = {}
        for lk in scene.links:
            key = lk.key
            links[key] = lk
            if key not in carried:
                frames[key] = {lk.p: (0.0, 0.0), lk.q: (lk.length, 0.0)}

    def link(self, key):
        """The scene's link ``key`` (its own key, or its two points in either order)."""
        return self._links.get(key) or self.scene.link(key)

    def frame(self, key) -> dict:
        """The points of link ``key`` in the link's own frame (its first point at the origin, its
        second on the x axis), carried points included."""
        b = self._frames.get(key)
        if b is None:
            lk = self._links.get(key) or self.scene.link(key)
            b = {lk.p: (0.0, 0.0), lk.q: (lk.length, 0.0)}
            for cp in self._carried.get(lk.key, ()):
                b[cp.name] = (cp.lam * lk.length, cp.mu * lk.length)
            self._frames[key] = b
        return b

    def distance(self, key, a, b) -> float:
        """|AB| on body ``key``."""
        f = self.frame(key)
        (ax, ay), (bx, by) = f[a], f[b]
        return math.hypot(bx - ax, by - ay)

    def coefficients(self, key, r1, r2, x):
        """(lam, mu) with X = R1 + lam (R2 - R1) + mu perp(R2 - R1) on body ``key``."""
        b = self.frame(key)
        (x1, y1), (x2, y2), (px, py) = b[r1], b[r2], b[x]
        dx, dy = x2 - x1, y2 - y1
        n2 = dx * dx + dy * dy
        return (((px - x1) * dx + (py - y1) * dy) / n2, (dx * (py - y1) - dy * (px - x1)) / n2)


def first_tier(scene: Scene, tier: tuple, needs: dict) -> tuple:
    """The recognisers of ``tier`` that can find a point in ``scene``: those that need no
    table, and those whose table (``needs``, ``steps.NEEDS``) the scene has. Kept by the
    tier, the needs (their identity and number) and which of those tables the scene lacks."""
    key = (id(tier), id(needs), not scene.points, not scene.sliders, not scene.rolling)
    hit = _TIERS_KEPT.get(key)
    if hit is not None and hit[0] is tier and hit[1] is needs and hit[2] == len(needs):
        return hit[3]
    out = tuple([r for r in tier if (t := needs.get(r)) is None or getattr(scene, t)])
    if set(needs.values()) <= {"points", "sliders", "rolling"}:  # (the tables of the key)
        _TIERS_KEPT[key] = (tier, needs, len(needs), out)
    return out


#: ``first_tier``'s answers: (tier, needs, their number, the recognisers) by its key
_TIERS_KEPT: dict = {}


# --------------------------------------------------------------------------- dimensions


@dataclass(frozen=True)
class Dims:
    """A plan's inputs: ``ground`` point -> (x, y); ``steps`` the dimensions of each step
    (its ``params``); the crank's ``theta, omega, alpha``; ``radii`` pin -> radius. Any
    value may be a numpy array (many mechanisms, or many crank angles, at once)."""

    ground: dict
    steps: tuple
    theta: object
    omega: object
    alpha: object
    radii: dict = field(default_factory=dict)


# --------------------------------------------------------------------------- the plan


@dataclass(frozen=True)
class Plan:
    """An ordered tuple of construction steps for one shape of mechanism, branches chosen.

    ``print(plan)`` lists the steps as a hand solution would take them.
    """

    steps: tuple
    ground: dict
    scene: Scene = field(repr=False, compare=False)
    notes: tuple = ()
    fixed_links: dict = field(default_factory=dict)
    #: per sized pin: (point, body names, their links or None, "a|b" keys, (i, j) pairs,
    #: the pairs' links)
    pins: tuple = ()
    dims: Dims | None = field(default=None, repr=False, compare=False)
    #: how the crank's speed was found where the scene gives the motion on another
    #: quantity (a :class:`polygon_method.solver.given.Resolution`), else None
    given: object = field(default=None, repr=False, compare=False)

    #: the force analysis's plan for this plan's scene, kept here by ``forces`` when first
    #: made (not a field: never compared, copied by ``replace`` or pickled)
    force_plan = None
    #: what is made when first needed and then kept in the plan (none of it a field, so
    #: ``replace`` starts from these again): the bound phases (``_bind_own``), the
    #: one-instant functions (``bind_own_instant``; a plan that solves one instant binds
    #: only these) and the branching steps checked after the positions (``checked``); and
    #: the sized pins' table where there are none (``__post_init__``)
    _phases = None
    instant_steps = None
    start_cond = None  # each steady step's condition, 1 (made by __post_init__)
    _checked = None
    pin_table = ()
    pin_rows = None  # two_body_rows of pin_table, made when first asked (two_body_rows())

    def __hash__(self):
        return id(self)

    def __eq__(self, other):
        return self is other

    def bodies_at(self, point) -> tuple:
        """The bodies a pin at ``point`` joins: (name, link whose omega it has, or None for
        a body that does not turn: the ground, a block on a fixed path)."""
        return _bodies_at(self.scene, point)

    def __str__(self):
        lines = [f"plan: {len(self.steps)} steps"]
        for st in self.steps:
            lines.append(
                f"  {st.index + 1}. {st.title}: finds "
                f"{', '.join(st.finds) or 'its length and rates (no new point)'}"
            )
        return "\n".join(lines)

    # ----- only what is asked
    def restricted(self, points=(), links=()) -> "Plan":
        """The plan cut down to the steps that the given points (position, velocity,
        acceleration) and links (omega, alpha) depend on, in the same order. A slider on a
        moving link needs the step that turns that link; a carried point, the two points it
        is carried by. The steps keep their indices.

        >>> from polygon_method.scene import parse_scene
        >>> sc = parse_scene('''
        ... [ground]
        ... O = [0, 0]
        ... [links]
        ... OA = 150
        ... AB = 600
        ... [points]
        ... M = { on = "AB", along = 300 }
        ... [sliders]
        ... B = { path = "horizontal" }
        ... [input]
        ... crank = "OA"
        ... angle = 90
        ... speed = "10 rad/s ccw"
        ... ''')
        >>> from polygon_method.solver.compiler import compile_plan
        >>> plan = compile_plan(sc)
        >>> [st.title for st in plan.restricted(points=["A"]).steps]
        ['crank OA']
        >>> [st.title for st in plan.restricted(points=["M"]).steps]
        ['crank OA', 'link AB, slider B on the horizontal path', 'point M on AB']
        """
        finder = {}
        for st in self.steps:
            for p in st.finds:
                finder[p] = st
            for lk in st.links:
                finder[("link", lk)] = st
        want = [finder[p] for p in points if p in finder]
        want += [finder[("link", lk)] for lk in links if ("link", lk) in finder]
        keep = set()
        while want:
            st = want.pop()
            if st.index in keep:
                continue
            keep.add(st.index)
            want += [finder[p] for p in st.needs if p in finder]
            want += [finder[("link", lk)] for lk in st.needs_links if ("link", lk) in finder]
        pos = [i for i, st in enumerate(self.steps) if st.index in keep]
        steps = tuple(self.steps[i] for i in pos)
        dims = replace(self.dims, steps=tuple(self.dims.steps[i] for i in pos))
        return replace(self, steps=steps, dims=dims)

    # ----- inputs
    def dimensions(self, scene: Scene) -> Dims:
        """The dimensions of ``scene``, a mechanism of this plan's shape."""
        bodies = Bodies(scene)
        inp = scene.input
        if any(getattr(st, "instant_dimensions", False) for st in self.steps):
            steps = self._instant_dimensions(scene, bodies)
        else:
            steps = tuple(st.dimensions(scene, bodies) for st in self.steps)
        return Dims(
            dict(scene.ground),
            steps,
            inp.angle,
            inp.omega,
            inp.alpha,
            {p.point: p.radius for p in scene.pins},
        )

    def _instant_dimensions(self, scene: Scene, bodies) -> tuple:
        """Each step's dimensions, a step that needs the positions at the scene's instant
        (a kind with ``instant_dimensions`` true, its ``dimensions(scene, bodies, P=...)``
        reading them: a wheel's place along its line, its arm's angle) given
        them from the steps before it, placed at ``scene``'s own dimensions and crank
        angle. Where those cannot be placed (a candidate variant that does not assemble
        there), the plan's own dimensions stand in for the step's: the evaluation of the
        candidate fails at the step before it all the same."""
        inp = scene.input
        ctx = Context(inp.angle, inp.omega, inp.alpha)
        m = State(
            dict(scene.ground), {}, {}, dict(self.fixed_links), dict(self.fixed_links), {}, ctx
        )
        out, placed, broken = [], 0, False
        for k, st in enumerate(self.steps):
            if not getattr(st, "instant_dimensions", False):
                out.append(st.dimensions(scene, bodies))
                continue
            try:
                while not broken and placed < k:
                    self.steps[placed].bind(out[placed])[0](m)
                    placed += 1
                out.append(st.params if broken else st.dimensions(scene, bodies, P=m.P))
            except (PolygonMethodError, ArithmeticError, ValueError):
                broken = True
                out.append(st.params)
        return tuple(out)

    # ----- evaluation
    def run(self, ctx: Context, dims: Dims | None = None, upto: int = 2) -> State:
        """Evaluate the steps: positions, then (``upto >= 1``) the velocity polygon, then
        (``upto >= 2``) the acceleration polygon. Returns the filled :class:`State`.

        With ``Context(..., array=True)`` every value may be an array. In scalar mode a step
        that cannot assemble, or whose condition is below ``TOL.singular``, raises.
        """
        if dims is None:
            ground = self.ground
            if upto >= 2 and not ctx.array:  # one instant: each step's phases in a row
                return self.instant(ctx)
            phases = self._phases or self._bind_own()
        else:
            ground, phases = dims.ground, self.bind(dims)
        zero = self.zero_motion
        m = State(
            dict(ground),
            dict(zero),
            dict(zero),
            dict(self.fixed_links),
            dict(self.fixed_links),
            {},
            ctx,
        )
        try:
            for f in phases[0]:
                f(m)
            if not ctx.array:
                cond = m.cond
                for i, st in self._checked or self.checked():
                    if cond[i] < TOL.singular:
                        raise st.singular(cond[i])
            if upto >= 1:
                for f in phases[1]:
                    f(m)
            if upto >= 2:
                for f in phases[2]:
                    f(m)
        except PolygonMethodError as exc:  # name the scene file in the one-line message
            raise exc.located(self.scene.file)
        return m

    def instant(self, ctx: Context, m=None) -> State:
        """``run(ctx)`` for one instant (floats, ``ctx.array`` false): all three phases at
        the plan's own dimensions, each step's position, check, velocity and acceleration in
        a row (``bind_instant``), the same formulas with fewer calls. A step that cannot
        assemble, or is singular, raises before any later step is placed. ``m``: the record
        to fill (a State's slots; a new State when None). ``solve`` writes this out for
        its one instant: a change here is made there too."""
        zero = self.zero_motion
        fixed = self.fixed_links
        if m is None:
            m = _new(State)  # State(...) filled in here: one Python call fewer per solve
        m.P = self.ground.copy()
        m.V = zero.copy()
        m.A = zero.copy()
        m.W = fixed.copy()
        m.Al = fixed.copy()
        m.S = {}
        steps = self.instant_steps or self.bind_own_instant()
        m.cond = ctx.cond
        m.cond.update(self.start_cond)  # (the steady steps' 1: not written by them)
        m.ctx = ctx
        m.array = ctx.array  # false: one instant
        try:
            for f in steps:
                f(m)
        except PolygonMethodError as exc:  # name the scene file in the one-line message
            raise exc.located(self.scene.file)
        return m

    def _runs(self) -> list:
        """(i, j): the steps ``i`` to ``j - 1`` of each run that a kind binds together
        (``group_key``; a step of no group is a run of one)."""
        steps, out, i, n = self.steps, [], 0, len(self.steps)
        while i < n:
            st, j = steps[i], i + 1
            key = st.group_key
            if key is not None:  # neighbours the kind can do in one go (points on one body)
                while j < n and type(steps[j]) is type(st) and steps[j].group_key == key:
                    j += 1
            out.append((i, j))
            i = j
        return out

    def _groups(self, dims: Dims):
        """The steps in runs that a kind binds together (:meth:`_runs`), with their
        dimensions."""
        steps, prms = self.steps, dims.steps
        for i, j in self._runs():
            yield steps[i:j], prms[i:j]

    def bind(self, dims: Dims) -> tuple:
        """(positions, velocities, accelerations): each the steps' phase functions, in
        order, for ``dims``."""
        bound = [
            type(g[0]).bind_group(g, p) if len(g) > 1 else g[0].bind(p[0])
            for g, p in self._groups(dims)
        ]
        return tuple(tuple(b[k] for b in bound) for k in range(3))

    def bind_instant(self, dims: Dims) -> tuple:
        """One function per step (or group of steps) doing its three phases in a row, for
        one instant at ``dims`` (floats); a step of no group (the usual one) bound without
        a slice."""
        steps, prms, out = self.steps, dims.steps, []
        for i, j in self._runs():
            if j == i + 1:
                out.append(steps[i].bind_instant(prms[i]))
            else:
                out.append(type(steps[i]).bind_group_instant(steps[i:j], prms[i:j]))
        return tuple(out)

    def _bind_own(self):
        object.__setattr__(self, "_phases", self.bind(self.dims))
        return self._phases

    def bind_own_instant(self):
        """The plan's own one-instant functions (``instant_steps``), bound once to its
        dimensions and kept: ``solve`` runs them in turn on a solution (a large plan's in
        one function, the cyclic collector held off: :mod:`.collector`)."""
        object.__setattr__(self, "instant_steps", held_off(self.bind_instant(self.dims)))
        return self.instant_steps

    def __getstate__(self):  # the bound phases are made again, not pickled
        return {
            k: v
            for k, v in self.__dict__.items()
            if k
            not in (
                "zero_motion",
                "_phases",
                "instant_steps",
                "start_cond",
                "_checked",
                "pin_table",
                "pin_rows",
                "force_plan",
            )
        }

    def __setstate__(self, state):
        for k, v in state.items():
            object.__setattr__(self, k, v)
        self.__post_init__()

    def __post_init__(self):
        # what every evaluation at the plan's own dimensions starts from (made anew by
        # dataclasses.replace, so a plan with other steps never runs stale functions; the
        # rest is made when first needed: the class's attributes above)
        object.__setattr__(self, "zero_motion", dict.fromkeys(self.ground, (0.0, 0.0)))
        # the conditions a one-instant solve starts from: each steady step's 1, which its
        # one-instant function does not write
        object.__setattr__(self, "start_cond", {st.index: 1.0 for st in self.steps if st.steady})
        if self.pins:  # each sized pin with its radius at the plan's own dimensions, its
            # pairs' links and its one pair's (None where it joins more than two bodies),
            # what derived.rubbing_records reads, one instant at a time
            radii = self.dims.radii if self.dims is not None else {}
            object.__setattr__(
                self,
                "pin_table",
                tuple([pin_entry(pin, radii.get(pin[0])) for pin in self.pins]),
            )

    def two_body_rows(self):
        """:func:`two_body_rows` of the sized pins, made once and kept as ``pin_rows``."""
        rows = two_body_rows(self.pin_table)
        object.__setattr__(self, "pin_rows", rows)
        return rows

    def checked(self) -> tuple:
        """(index, step) of each branching step: checked for a singular condition after
        the positions (``run``); made once and kept."""
        out = tuple([(st.index, st) for st in self.steps if st.branching])
        object.__setattr__(self, "_checked", out)
        return out

    def evaluate(self, ctx, *, velocities=True, accelerations=True):
        """Run the plan at the compiled scene's dimensions: dicts ``P, V, A`` (point ->
        (x, y)), ``W, Al`` (link -> omega, alpha) and ``S`` (slider -> [vs, as,
        (coriolis x, y)]); the phases not asked for come back empty."""
        upto = 2 if (velocities and accelerations) else (1 if velocities else 0)
        m = self.run(ctx, upto=upto)
        if upto == 0:
            return m.P, {}, {}, {}, {}, {}
        S = {k: [s[0], s[1], (s[2], s[3])] for k, s in m.S.items()}
        if upto == 1:
            return m.P, m.V, {}, m.W, {}, S
        return m.P, m.V, m.A, m.W, m.Al, S


def pin_entry(pin, radius) -> tuple:
    """A pin's entry in ``plan.pin_table``: (point, radius, the pin as ``plan.pins`` gives
    it, its pairs' links or None for a pin of two bodies, that one pair's two links (None
    for a body that does not turn; both None for a pin of more bodies))."""
    pairs = pin[5]
    if len(pairs) == 1:
        return (pin[0], radius, pin, None, *pairs[0])
    return (pin[0], radius, pin, pairs, None, None)


def two_body_rows(table):
    """The rows of :func:`~.derived.plan_records` for ``table`` (a plan's ``pin_table``):
    (point, radius, entry, a turning link, the other body's link or None where it does not
    turn) per pin, in the table's order; False where a pin joins more than two bodies or two
    that do not turn (:func:`~.derived.rubbing_records` takes those)."""
    rows = []
    for k in table:
        p, r, _, pairs, a, b = k
        if pairs is not None or a is None and b is None:
            return False
        rows.append((p, r, k, a, b) if a is not None else (p, r, k, b, None))
    return tuple(rows)


def _bodies_at(sc, point) -> tuple:
    out = [("ground", None)] if point in sc.ground else []
    for lk in sc.links:
        if lk.p == point or lk.q == point:
            out.append((lk.key, lk.key))
    for cp in sc.points:  # (sc.carried(point))
        if cp.name == point:
            out.append((cp.link, cp.link))
            break
    if not sc.cylinders and not sc.sliders:  # (the usual scene: pins of links alone)
        return tuple(out)
    for cyl in sc.cylinders:  # barrel and rod turn together (the cylinder's omega)
        if point == cyl.barrel:
            out.append((f"barrel {cyl.key}", cyl.key))
        elif point == cyl.rod:
            out.append((f"rod {cyl.key}", cyl.key))
    blocks = sc.blocks  # (a driving wheel's centre path: no block there)
    for sl in sc.slots(point):  # a block; a peg in two slots has a block in each
        if sl not in blocks:
            continue
        if isinstance(sl, FixedPath):
            out.append((f"block {sl.key}", None))
        elif isinstance(sl, GuideSlider):
            out.append((f"block {sl.key}", sc.link(sl.guide).key))
        else:  # in the slot of a translating yoke: the block does not turn
            out.append((f"block {sl.key}", None))
    return tuple(out)


def _pin_entries(sc) -> tuple:
    """Each sized pin's entry in the plan (:func:`_pin_entry`), in the order of
    ``sc.pins``; the bodies at the pins of a scene of links and carried points alone found
    in one pass over them (as :func:`_bodies_at` finds them pin by pin, in its order)."""
    if sc.cylinders or sc.sliders:
        return tuple([_pin_entry(sc, pin.point) for pin in sc.pins])
    ground = sc.ground
    at = {pin.point: [("ground", None)] if pin.point in ground else [] for pin in sc.pins}
    for lk in sc.links:
        p, q, key = lk.p, lk.q, lk.key
        if p in at:
            at[p].append((key, key))
        if q in at and q != p:
            at[q].append((key, key))
    carried = set()
    for cp in sc.points:  # the first carried point of each name (as sc.carried finds it)
        name = cp.name
        if name in at and name not in carried:
            carried.add(name)
            at[name].append((cp.link, cp.link))
    return tuple([_pin_entry(sc, pin.point, tuple(at[pin.point])) for pin in sc.pins])


def _pin_entry(sc, point, joined=None) -> tuple:
    """A pin's entry in the plan: (point, the bodies it joins, their links or None, each
    pair's "a|b" key, the pairs' (i, j), the pairs' links). ``joined``: the bodies at the
    pin, where they are known (:func:`_bodies_at`)."""
    if joined is None:
        joined = _bodies_at(sc, point)
    if len(joined) == 2:  # (the usual pin: two bodies, one pair)
        (a, la), (b, lb) = joined
        return (point, (a, b), (la, lb), (f"{a}|{b}",), ((0, 1),), ((la, lb),))
    bodies = tuple([b for b, _ in joined])
    links = tuple([lk for _, lk in joined])
    keys, pairs, linked = [], [], []
    n = len(joined)
    for i in range(n):
        for j in range(i + 1, n):
            keys.append(f"{bodies[i]}|{bodies[j]}")
            pairs.append((i, j))
            linked.append((links[i], links[j]))
    return (point, bodies, links, tuple(keys), tuple(pairs), tuple(linked))
