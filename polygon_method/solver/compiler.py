"""Compiling a scene: its constraint graph walked into a :class:`~polygon_method.solver.plan.Plan`.

The crank is the first step; then, for each point not yet found (in the scene's order),
each recogniser of :data:`polygon_method.steps.TIERS` is tried in turn. A point is looked
at again only when one of its neighbours has just been found, so compiling is linear in
the size of the scene. Each branching step chooses its assembly at the scene's crank
angle. Plans are kept in a small cache keyed by the scene's content (never inside the
scene): a changed scene gets its own plan.

>>> from polygon_method.scene import parse_scene
>>> sc = parse_scene('''
... [ground]
... O = [0, 0]
... [links]
... OA = 150
... AB = 600
... [sliders]
... B = { path = "horizontal" }
... [input]
... crank = "OA"
... angle = 90
... speed = "10 rad/s ccw"
... ''')
>>> [st.kind for st in compile_plan(sc).steps], gruebler(sc)
(['crank', 'slider'], 1)
"""

from __future__ import annotations

import functools
import heapq
import math
import weakref
from dataclasses import replace

from ..common.errors import AssemblyError, PolygonMethodError, SceneError
from ..common.numbers import in_units, quiet
from ..common.tolerances import SAME, TOL
from .completion import gas_towards_crank, given_completed, loads_along_links, place
from .two_given import complete_two, needs_two, trial_speeds
from .mobility import gruebler, leftover
from .plan import Bodies, Dims, Plan, _pin_entries, first_tier
from .reach import reach_words
from ..scene import GuideSlider, Scene, key_line
from ..steps import NEEDS, TIERS, Context, Crank, collar, cylinder
from ..steps.block import BlockDriver
from ..steps.rolling_driver import WheelDriver
from ..steps.second_collar import second_collar
from ..steps.second_crank import SecondCrank

__all__ = ["compile_plan", "gruebler"]

#: crank angles tried per turn for saying where a scene that cannot assemble could
_REACH_GRID = 720
#: an [assembly] hint in words: (the axis compared, +1 for the larger coordinate)
_SIDES = {"above": (1, 1), "below": (1, -1), "right": (0, 1), "left": (0, -1)}


# --------------------------------------------------------------------------- compiling

_BY_ID: dict = {}  # id(scene) -> [weak reference to the scene, plan, kept] (bounded)
_BY_CONTENT: dict = {}  # content key -> plan (bounded)
_KEEP = 256
PLANS_BY_ID = _BY_ID  # the same dict, for solve's first look (without compile_plan's call)
_NOT_KEPT = (None, None)  # an entry's (input, context) before solve keeps its own


def compile_plan(scene: Scene) -> Plan:
    """Compile the scene's constraint graph into a plan and choose each assembly branch.

    Raises :class:`MobilityError` when the scene is not a one-degree-of-freedom mechanism
    that these steps can build, :class:`AssemblyError` when it cannot be put together at the
    given crank angle.
    """
    hit = _BY_ID.get(id(scene))
    if hit is not None and hit[0]() is scene:
        return hit[1]
    key = getattr(scene, "_key", None)  # the scene's content (made with the scene)
    plan = _BY_CONTENT.get(key) if key is not None else None
    if plan is None:
        if not isinstance(scene, Scene):
            raise SceneError(
                f"a Scene is needed (load_scene(path) or parse_scene(text)), "
                f"not {type(scene).__name__} {str(scene)[:60]!r}"
            )
        try:
            notes = ()
            if scene.input.placed is not None and not scene.input.placed.found:
                notes = place(
                    scene, lambda trial: _Compiler(trial_speeds(trial)).run()
                )  # the crank's angle that gives the stated position
            if needs_two(scene.input):  # two inputs, a speed given on another link
                notes = notes + complete_two(scene, lambda trial: _Compiler(trial).run())
            plan = _Compiler(scene).run()
            if notes:
                plan = replace(plan, notes=notes + plan.notes)
        except PolygonMethodError as exc:  # name the scene file and line in the message
            if exc.line is None and exc.key:
                exc.line = key_line(scene, exc.key)
            raise exc.located(scene.file)
        if scene.input.given is not None:
            plan = given_completed(plan)
        if key is not None:
            while _BY_CONTENT and len(_BY_CONTENT) >= _KEEP:
                _BY_CONTENT.pop(next(iter(_BY_CONTENT)))
            _BY_CONTENT[key] = plan
    if (
        scene.input.omega is None
        or needs_two(scene.input)
        or (scene.input.placed is not None and not scene.input.placed.found)
    ):
        object.__setattr__(scene, "input", plan.scene.input)  # completed when compiled
    if plan.scene is not scene:  # a scene of the same content: its own loads, masses, ...
        plan = _for_scene(plan, scene)
    if scene.loads and any(ld.toward is not None and ld.force is None for ld in scene.loads):
        gas_towards_crank(plan, scene)  # a gas force's direction (loads are not in the key)
    if scene.loads and any(ld.across is not None for ld in scene.loads):
        loads_along_links(plan, scene)  # a force against a link: its vector at the instant
    try:
        ident = id(scene)
        # (the scene, its plan, and solve's kept (input, one-instant context), none yet)
        entry = [weakref.ref(scene, functools.partial(_forget, ident)), plan, _NOT_KEPT]
        while len(_BY_ID) >= _KEEP:  # the plan holds its scene: bounded, or none would go
            _BY_ID.pop(next(iter(_BY_ID)))
        _BY_ID[ident] = entry
    except TypeError:
        pass
    return plan


def _for_scene(plan, scene):
    """The cached plan of a scene of the same content, for ``scene``: the content key holds
    what the plan is made of (its points, links, input, pins), not what it leaves to the
    scene (its loads, masses, gravity, answers, title), so the plan carries the scene it is
    asked for, never another's. Its steps and the phases already bound at its dimensions
    (which the key fixes) are shared."""
    out = replace(plan, scene=scene)
    object.__setattr__(out, "_phases", plan._phases)
    object.__setattr__(out, "instant_steps", plan.instant_steps)
    return out


def _forget(ident, ref, by_id=_BY_ID):
    """A scene has gone: drop its entry (unless its id already names a newer scene). The
    weak reference's callback, ``ident`` bound first (a partial bound by keyword costs
    twice as much to make, once per scene compiled)."""
    hit = by_id.get(ident)
    if hit is not None and hit[0] is ref:
        del by_id[ident]


class _Compiler:
    """The constraint graph as the recognisers see it (``g`` in the steps' ``recognise``):
    the points found so far (``P``), the links and sliders already used, the bodies."""

    def __init__(self, scene: Scene):
        self.scene = scene
        self.names = scene.point_names
        self.unit = scene.length_unit
        self.uname = scene.units
        inp = scene.input
        self.ctx = Context.instant(
            inp.angle, 1.0 if inp.omega is None else inp.omega, inp.alpha or 0.0
        )  # only positions are placed here
        self.P = dict(scene.ground)
        self.steps = []
        ground = scene.ground  # the links of two ground points: used, and not turning
        self._fixed = [lk.key for lk in scene.links if lk.p in ground and lk.q in ground]
        self.used_links = set(self._fixed)
        self.used_sliders = set()
        self.notes = []
        self.bodies = bodies = Bodies(scene)
        self._carried = {cp.name: cp for cp in scene.points} if scene.points else {}
        sliders = scene.sliders
        self._sliders = {s.point: s for s in sliders if not s.slot} if sliders else {}
        self._slots = {}  # a peg's point -> its two slots
        self._guided = {}  # link key -> slider points that slide on it (or a wheel's rim
        # point meshing with it: found once the gear is, whatever [links]' order)
        self._yokes = {}  # a pin -> the yoke whose slot it slides in
        self.first_tier = first_tier(scene, TIERS[0], NEEDS)  # (TIERS as it is now)
        self._bodies_of = of = {}
        frame = bodies.frame
        for lk in scene.links:
            key = lk.key
            for p in frame(key):
                if p in of:
                    of[p].append(key)
                else:
                    of[p] = [key]
        for pr in scene.rolling or ():
            if pr.on == "gear" and pr.rim:
                self._guided.setdefault(scene.link(pr.base).key, []).append(pr.rim)
        if not sliders:
            return
        for s in sliders:
            if s.slot:
                self._slots.setdefault(s.point, []).append(s)
        for s in sliders:
            if isinstance(s, GuideSlider):
                self._guided.setdefault(scene.link(s.guide).key, []).append(s.point)
            elif hasattr(s, "yoke"):
                self._yokes.setdefault(s.point, []).append(s.yoke)

    # ----- what the recognisers ask
    @property
    def next_index(self) -> int:
        return len(self.steps)

    def carried(self, name):
        return self._carried.get(name)

    def slider(self, name):
        """The block at ``name`` (none for a peg in two slots: see :meth:`slots`)."""
        return self._sliders.get(name)

    def slots(self, name):
        """The two slots of a peg at ``name`` (empty where it is none)."""
        return tuple(self._slots.get(name, ()))

    def body(self, key) -> dict:
        return self.bodies.frame(key)

    def bodies_of(self, name):
        return self._bodies_of.get(name, ())

    def known_link(self, link):
        return link.p in self.P and link.q in self.P

    def free(self, name):
        """(body key, its known point K, |KX|) for each unused body of ``name`` that has
        exactly one known point (none if a body has two: that is a carried point)."""
        out, frame, P = [], self.bodies.frame, self.P
        for key in self._bodies_of.get(name, ()):
            b = frame(key)
            known = [p for p in b if p in P]
            if len(known) == 1 and key not in self.used_links:
                k = known[0]
                (kx, ky), (x, y) = b[k], b[name]
                out.append((key, k, math.hypot(x - kx, y - ky)))
        return out

    # ----- compiling
    def add(self, step):
        try:
            own = step.assemble(self)  # a step that chooses its own assembly
            if own is not None:
                step, placed = own
            elif step.branching:
                step, xy = self.choose_branch(step)
                placed = {step.finds[0]: xy}
            else:
                placed = {step.finds[0]: step.place(self.P, step.params, self.ctx)[:2]}
        except AssemblyError as exc:
            if exc.key is None:  # not an [assembly] hint: the links cannot meet here
                exc.message = f"{exc.message}; {self.reach(step)}"
            raise
        self.P.update(placed)
        self.steps.append(step)
        self.used_links.update(step.links)

    def reach(self, failing, n=_REACH_GRID) -> str:
        """Where the crank (or the driving block) can be set so that the steps so far and
        ``failing`` assemble: what to do when the stated angle cannot."""
        return reach_words(self, failing, n)

    def neighbours(self, name):
        out = set()
        frame, guided = self.bodies.frame, self._guided
        for key in self._bodies_of.get(name, ()):
            out.update(frame(key))
            if guided:
                out.update(guided.get(key, ()))
        if self._yokes:
            out.update(self._yokes.get(name, ()))
        return out

    def run(self) -> Plan:
        """The plan: the driver first, a second input next, then each point found by the
        first recogniser that takes it, the cylinders last; what is left over refused."""
        self._driver()
        self._second_input()
        self._walk()
        for st in cylinder.recognise_all(self):  # both ends known: last, they find no point
            self.steps.append(st)
        self.finish()
        return self._plan()

    def _driver(self):
        """The first step: a wheel rolling on a ground line, a collar driven along its rod,
        a block on a fixed guide, or the crank."""
        sc = self.scene
        inp = sc.input
        if inp.wheel is not None:  # a wheel rolling on a ground line drives: its centre
            path = sc.slider(inp.block)  # the centre's place on its path is the input
            pr = next(p for p in sc.rolling if p.wheel == inp.wheel)
            along = -pr.m[1] * path.u[0] + pr.m[0] * path.u[1]
            self.used_sliders.add(path.key)
            self.add(
                WheelDriver(
                    0,
                    inp.block,
                    path,
                    self.fmt(pr.through),
                    self.unit,
                    self.uname,
                    wheel=inp.wheel,
                    radius=pr.radius,
                    ground_words=pr.label,
                    along=along,
                )
            )
        elif inp.block is not None and collar.is_collar(sc):  # a collar driven along its rod
            self.used_sliders.add(inp.block)
            self.add(collar.driver(self, sc, gruebler))
        elif inp.block is not None:  # a block on a fixed guide drives: its place is the input
            path = sc.slider(inp.block)
            named = [p for p, xy in sc.ground.items() if xy == path.through]
            self.used_sliders.add(path.key)
            self.add(
                BlockDriver(
                    0,
                    inp.block,
                    path,
                    named[0] if named else self.fmt(path.through),
                    self.unit,
                    self.uname,
                )
            )
        else:
            crank = self.bodies.link(inp.crank)
            self.add(Crank(0, crank.key, inp.pivot, inp.tip, crank.length))

    def _second_input(self):
        """The second input's step, where the scene has two degrees of freedom: a collar
        sliding along the crank, or a second driven crank."""
        sc = self.scene
        inp = sc.input
        two = inp.second
        if two is not None and two.block is not None:  # a collar sliding along the crank
            self.add(second_collar(self, two))
        elif two is not None:  # two degrees of freedom: the second crank is the next step
            link = sc.link(two.crank)
            self.add(
                SecondCrank(
                    1,
                    link.key,
                    two.pivot,
                    two.tip,
                    link.length,
                    two.angle,
                    two.omega,
                    two.alpha,
                    inp.angle,
                    inp.omega,
                )
            )

    def _walk(self):
        """Each point not yet found, in the scene's order, tried with the first tier's
        recognisers (looked at again only when a neighbour has just been found), then with
        the later tiers', until none finds one."""
        names = self.names
        order = {p: i for i, p in enumerate(names)}
        heap = list(range(len(names)))  # sorted: a heap
        waiting = set(heap)  # each point in the heap once (a plate of many carried points
        while True:  # would push its every point again for each found: quadratic)
            found = None
            while heap and found is None:
                i = heapq.heappop(heap)
                waiting.discard(i)
                name = names[i]
                if name in self.P:
                    continue
                found = self._first(self.first_tier, name)
            for tier in TIERS[1:]:
                if found is not None:
                    break
                for name in names:
                    if name not in self.P:
                        found = self._first(tier, name)
                        if found is not None:
                            break
            if found is None:
                break
            self.add(found)
            if len(self.P) >= len(names) and order.keys() <= self.P.keys():
                continue  # every point found: no neighbour is left to look at again
            for x in found.finds:
                for p in self.neighbours(x):
                    i = order.get(p)
                    if i is not None and p not in self.P and i not in waiting:
                        heapq.heappush(heap, i)
                        waiting.add(i)

    def _plan(self) -> Plan:
        """The plan of the steps found, with the scene's dimensions."""
        sc = self.scene
        inp = sc.input
        fixed = dict.fromkeys(self._fixed, 0.0)
        pins = _pin_entries(sc) if sc.pins else ()
        steps = tuple(self.steps)
        ground = dict(sc.ground)
        dims = Dims(
            ground,
            tuple([st.params for st in steps]),
            inp.angle,
            inp.omega,
            inp.alpha,
            {p.point: p.radius for p in sc.pins} if sc.pins else {},
        )
        return Plan(steps, ground, sc, tuple(self.notes), fixed, pins, dims)

    def _first(self, kinds, name):
        for recognise in kinds:
            step = recognise(self, name)
            if step is not None:
                return step
        return None

    # ----- branches
    def choose_branch(self, step):
        sc = self.scene
        name = step.finds[0]
        prm = step.params
        P, ctx = self.P, self.ctx
        plus = step.place(P, prm, ctx, 1.0)[:2]
        minus = step.place(P, prm, ctx, -1.0)[:2]
        hint = sc.assembly.get(name)
        if hint is None:
            default = step.default_hint(P)
            reach = step.reach()
            sigma = self.pick(name, default, plus, minus, step, default=True, scale=reach)
            if math.dist(plus, minus) > SAME * reach:
                side = (
                    "on the side of the block"
                    if default == "block side"
                    else default
                    if isinstance(default, str)
                    else "farther along the guide"
                )
                self.notes.append(
                    f"{name}: of its two positions the one {side} was taken "
                    f"(default; set [assembly] {name} to choose)"
                )
        else:
            sigma = self.pick(name, hint, plus, minus, step)
        chosen = step if sigma == step.sigma else replace(step, sigma=sigma)
        return chosen, (plus if sigma > 0 else minus)

    def pick(self, name, hint, plus, minus, step, default=False, scale=None):
        sep = math.dist(plus, minus)
        if scale is None:
            scale = step.reach()
        if sep <= TOL.closure * scale:  # the circles touch: one position
            return 1.0
        if hint == "block side":
            return 1.0
        if isinstance(hint, tuple) and default:
            ux, uy = hint
            d = (plus[0] - minus[0]) * ux + (plus[1] - minus[1]) * uy
            return 1.0 if d >= 0 else -1.0
        if isinstance(hint, str):
            axis, want = _SIDES[hint]
            d = (plus[axis] - minus[axis]) * want
            if abs(d) <= SAME * scale:
                if default:  # level: take the right-hand one
                    return 1.0 if plus[0] >= minus[0] else -1.0
                other = "left/right" if axis == 1 else "above/below"
                raise AssemblyError(
                    f'assembly {name} = "{hint}" matches neither position: both are at the '
                    f"same {'height' if axis == 1 else 'x'} ({self.fmt(plus)} and "
                    f"{self.fmt(minus)}); use {other} or a rough position [x, y]",
                    key=f"[assembly] {name}",
                    file=self.scene.file,
                )
            return 1.0 if d > 0 else -1.0
        d1, d2 = math.dist(hint, plus), math.dist(hint, minus)
        # a rough position must be decisively nearer one of them (not in the middle tenth)
        if min(d1, d2) > step.reach() or abs(d1 - d2) <= 0.1 * sep:
            raise AssemblyError(
                f"assembly {name} = {self.fmt(hint)} matches neither position of {name} "
                f"({self.fmt(plus)} or {self.fmt(minus)}); give a rough position near the "
                "one the figure shows",
                key=f"[assembly] {name}",
                file=self.scene.file,
            )
        return 1.0 if d1 < d2 else -1.0

    def fmt(self, xy):
        """A position in the scene's units; rounding noise about an axis written 0."""
        size = max([lk.length for lk in self.scene.links] + [abs(c) for c in xy])
        x, y = (quiet(c, size) for c in xy)
        return f"[{in_units(x, self.unit)}, {in_units(y, self.unit)}]"

    # ----- what is left over
    def finish(self):
        """Refuse what the steps leave over (:func:`~polygon_method.solver.mobility.leftover`)."""
        leftover(self)
