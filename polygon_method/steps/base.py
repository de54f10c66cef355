"""What every construction step shares: the evaluation context, the state a plan fills in,
the step base class (and, from :mod:`.construction`, the records a step gives to step tables
and drawings, imported here by every kind).

A step kind is one module of :mod:`polygon_method.steps`; this module holds nothing of any
one kind.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from types import MappingProxyType

from ..common.tolerances import LEAST_REACH
from ..common.errors import TOL, AssemblyError, SingularStepError
from .construction import (  # the records, here as before
    Construction,
    DirectionLine,
    Vector,
    absolute,
    add,
    centripetal,
    image_label,
    image_name,
    numbered,
    perp,
    pole_text,
    relative,
    sub,
    tangential,
    unit,
)
from .rounding import two_lines

__all__ = [
    "REQUIRED",
    "OPTIONAL",
    "Context",
    "State",
    "Step",
    "Vector",
    "DirectionLine",
    "Construction",
    "image_name",
    "image_label",
    "numbered",
    "pole_text",
    "unit",
    "sub",
    "add",
    "perp",
    "relative",
    "absolute",
    "centripetal",
    "tangential",
]


class Context:
    """What an evaluation needs besides the state: the input motion and the maths for
    floats or arrays. In scalar mode a failing step raises; in array mode it is masked
    (``bad``, ``failures``) and the evaluation goes on. ``theta, omega, alpha``: the
    crank's angle, speed and acceleration; for a driving block, its place s along its
    guide, its velocity vs and acceleration as."""

    __slots__ = ("theta", "omega", "alpha", "array", "cond", "bad", "failures", "np", "cos", "sin")

    def __init__(self, theta, omega, alpha, *, array=False):
        self.theta, self.omega, self.alpha = theta, omega, alpha
        self.array = array
        self.cond = {}
        self.bad = None  # array mode: positions where a step failed
        self.failures = {}  # array mode: step index -> mask
        if array:
            import numpy as np

            self.np = np
            self.cos, self.sin = np.cos, np.sin
        else:
            self.np = None
            self.cos, self.sin = math.cos, math.sin

    def root(self, disc, scale2, step, why):
        """sqrt(disc), where disc < 0 means the step cannot assemble (``why()`` says why)."""
        if self.array:
            np = self.np
            miss = disc < -TOL.closure * scale2
            if miss is True or (miss is not False and miss.any()):  # a bool where a
                # step's points are all fixed; .any() of an array is cheaper than np.any
                self.fail(step, miss)
            return np.sqrt(np.maximum(disc, 0.0))
        if disc < -TOL.closure * scale2:
            raise AssemblyError(why(), step=step.label)
        return disc**0.5 if disc > 0 else 0.0

    def fail(self, step, mask):
        """Mark the positions in ``mask`` where ``step`` fails (array mode): they are left out of
        the motion."""
        prev = self.failures.get(step.index)
        self.failures[step.index] = mask if prev is None else (prev | mask)
        self.bad = mask if self.bad is None else (self.bad | mask)

    def safe(self, den, step):
        """A denominator that is never exactly zero (array mode: singular entries masked)."""
        if self.array:
            zero = den == 0
            if zero is True or (zero is not False and zero.any()):  # (as in root)
                self.fail(step, zero)
                return self.np.where(zero, 1.0, den)
        return den

    def minimum(self, a, b):
        """The smaller of ``a`` and ``b``, element by element for arrays."""
        return self.np.minimum(a, b) if self.array else min(a, b)


class Instant(Context):
    """The context of one instant (floats), made with one call and four fields set
    (:meth:`Context.instant`): what every scalar context shares is the class's."""

    __slots__ = ()
    array = False
    bad = None
    failures = MappingProxyType({})  # scalar mode raises: nothing is ever masked
    np = None
    cos = math.cos
    sin = math.sin

    def __reduce__(self):  # its own four fields (the rest are the class's; a kept
        # context's read-only conditions, none written there, come back empty)
        cond = self.cond
        return _instant, (self.theta, self.omega, self.alpha, cond if type(cond) is dict else None)


def _instant(theta, omega, alpha, cond=None, new=object.__new__, cls=Instant) -> Context:
    c = new(cls)
    c.theta = theta
    c.omega = omega
    c.alpha = alpha
    c.cond = {} if cond is None else cond
    return c


#: ``Context(theta, omega, alpha)`` for one instant, faster (a solve makes one per call)
Context.instant = staticmethod(_instant)


class State:
    """The values a plan fills in, step by step: ``P, V, A`` point -> (x, y); ``W, Al``
    link -> omega, alpha; ``S`` slider point -> [vs, as, coriolis x, coriolis y];
    ``cond`` step index -> condition. Floats, or arrays over many positions."""

    __slots__ = ("P", "V", "A", "W", "Al", "S", "cond", "ctx", "array")

    def __init__(self, P, V, A, W, Al, S, ctx):
        self.P, self.V, self.A, self.W, self.Al, self.S = P, V, A, W, Al, S
        self.cond = ctx.cond
        self.ctx = ctx
        self.array = ctx.array  # arrays: singular entries are masked, not raised


#: what every kind of step must give itself (the step contract): a kind that leaves one to
#: the base class fails when its module is imported, never silently in a view.
#:
#: ``kind``           its name in the JSON ``steps``
#: ``finds``          the points it finds (a cylinder finds none, a triad three)
#: ``links``          the links whose omega and alpha it determines
#: ``needs``          the points it reads
#: ``title``          its words in the plan ("dyad BC, CD at C")
#: ``params``         its dimensions, as the compiled scene gives them
#: ``dimensions``     the same, read from another scene of the same shape
#: ``place``          its position formula (either branch) with its condition
#: ``bind``           its three phases (position, velocity, acceleration) for dimensions
#: ``reach``          its largest length: the scale of its tolerances
#: ``bodies``         the bodies it sets moving, in the textbook's numbering order
#: ``orient``         each link it finds: which point relative to which (the step table)
#: ``position_words`` its line of the configuration diagram's construction
#: ``construction``   what it draws on either polygon, and the sentence
#: ``singular_why``   why it fails at a small condition
#: ``warning``        the line for a condition below ``TOL.warn``
#: ``limit_why``      why the linkage cannot be assembled beyond its limit position
#: ``condition_column`` its condition's column in a sweep summary (or None)
#: ``transmission``   the transmission angle its condition measures, in words (or None)
REQUIRED = (
    "kind",
    "finds",
    "links",
    "needs",
    "title",
    "params",
    "dimensions",
    "place",
    "bind",
    "reach",
    "bodies",
    "orient",
    "position_words",
    "construction",
    "singular_why",
    "warning",
    "limit_why",
    "condition_column",
    "transmission",
)

#: what a kind may leave to the base class, each default right for most kinds: ``branching``
#: (False: one assembly), ``steady`` (False: its condition written at each instant), ``image_by_similar_triangle``, ``draws_relative``,
#: ``other_assembly_mistake``, ``needs_links`` (none), ``bind_instant`` (its three phases
#: in a row), ``group_key``/``bind_group``/``bind_group_instant`` (not bound in groups),
#: ``rounding``/``error_bound`` (the rule of two direction lines), ``contacts``,
#: ``contact_motion``, ``shapes`` (no rolling contact, nothing drawn besides links),
#: ``produced``, ``drawn`` (draws nothing of its own), ``output``, ``default_hint``,
#: ``assemble`` (placed by ``place`` and its branch), ``auxiliary`` (no auxiliary point);
#: the driver protocol, asked of the plan's first step: ``periodic`` (True: the motion's
#: parameter is a crank's angle and repeats every turn; a block driver's is its place
#: along its guide), ``parameter_words`` (that parameter in words), ``input_scales`` (the
#: least sizes of velocity, acceleration, omega, alpha the input sets), ``input_words``
#: and ``effort_words`` (a driver's own line of the printed solution and of its input
#: effort; None: a crank's, which the views write), ``parameter`` (its name, symbol and
#: unit as an axis or a column heads it), ``parameter_scale`` (how much of the parameter
#: plays the part of a crank's radian: the sweep's offsets near a change point are
#: multiples of it), ``effort_key`` (the JSON key of the input effort), ``input_record``
#: (a driver's own JSON ``input``; None: a crank's, which the solution writes),
#: ``drive_caption`` (a driver's own line under the drawings; None: a crank's), ``travel``
#: (what a driver's sweep runs over, in words: "the block's travel"), ``body_omega`` (a
#: driver that does not turn about the frame but about an instantaneous centre: its omega;
#: None), ``input_items`` (the step table's heading and lines for the input; None: the
#: views'), ``driver_name`` (body 2 of the centres' numbering: "the driving block A")
OPTIONAL = (
    "steady",
    "periodic",
    "parameter_words",
    "input_scales",
    "input_words",
    "effort_words",
    "parameter",
    "parameter_scale",
    "effort_key",
    "input_record",
    "drive_caption",
    "travel",
    "body_omega",
    "input_items",
    "driver_name",
    "assemble",
    "auxiliary",
    "branching",
    "image_by_similar_triangle",
    "draws_relative",
    "other_assembly_mistake",
    "needs_links",
    "bind_instant",
    "group_key",
    "bind_group",
    "bind_group_instant",
    "rounding",
    "error_bound",
    "contacts",
    "contact_motion",
    "shapes",
    "produced",
    "drawn",
    "output",
    "default_hint",
)


@dataclass(frozen=True)
class Step:
    """One hand construction: finds one point (``finds``; a class-III group finds three
    at once) from points already known.

    A kind fills in: ``finds``, ``links`` (the links whose omega and alpha it determines),
    ``needs`` (the points it reads), ``params`` (its dimensions, as the plan's scene gives
    them) and ``dimensions(scene, bodies)`` (the same read from another scene), ``place``
    (its position formula, either branch), ``bind`` (its three phases), the words below and
    ``construction`` (what it draws on either polygon).
    """

    index: int

    def __init_subclass__(cls, **kw):
        """The step contract (:data:`REQUIRED`), checked when a kind is defined: a kind
        that leaves a member to this base class is refused at import."""
        super().__init_subclass__(**kw)
        missing = [
            name
            for name in REQUIRED
            if not any(name in vars(k) for k in cls.__mro__[:-1] if k is not Step)
        ]
        if missing:
            raise TypeError(
                f"step kind {cls.__name__} does not give {', '.join(missing)} "
                "(the step contract: polygon_method.steps.base.REQUIRED)"
            )

    #: the name of the kind ("crank", "dyad", ...), as in the JSON ``steps``
    kind = "step"
    #: whether the step has two assemblies (a branch ``sigma`` to choose)
    branching = False
    #: whether its condition is 1 at every instant (nothing intersected: a crank, a carried
    #: point): a plan starts each one-instant solve's conditions with its 1
    #: (``Plan.start_cond``), and its one-instant function does not write it
    steady = False
    #: whether the step's image is found by a similar triangle off the line of two images
    image_by_similar_triangle = False
    #: whether a polygon shows the relative vectors this step finds (a carried point's
    #: image triangle shows them instead)
    draws_relative = True
    #: whether a student drawing the other of the step's two assemblies is a mistake to
    #: look for when checking answers
    other_assembly_mistake = False
    #: the driver protocol (the plan's first step): True where the motion's parameter is
    #: a crank's angle, repeating every turn; False for a block driven along its guide,
    #: whose parameter is its place s (a length) and whose sweep runs over its stroke
    periodic = True

    def parameter_words(self) -> str:
        """The motion's parameter in words, asked of the plan's first step (the driver)."""
        return "the crank angle"

    #: the driver as body 2 of the centres' numbering (ground 1, the crank 2)
    driver_name = "the crank"

    def body_omega(self, sol):
        """The angular velocity of the driver's own body where it turns about no fixed
        pivot (a wheel rolling on the ground: about its contact point), asked of the plan's
        first step; None for a crank (the input's omega) or a block (it translates)."""
        return None

    def input_items(self, scene, fmt):
        """(heading, lines) of the step table's input section, asked of the plan's first
        step (``fmt`` writes a number); None where the views write a crank's or a block's."""
        return None

    def input_words(self, scene):
        """The printed solution's line for the input, asked of the plan's first step: None
        for a crank (the views write its angle and speed)."""
        return None

    def effort_words(self, effort):
        """The printed line of the driving effort the power balance gives (``effort``, SI),
        for a driver whose :meth:`input_words` is not None."""
        return None

    #: the JSON key of the driving effort the power balance gives (a crank's torque)
    effort_key = "input_torque"

    def parameter(self, scene) -> tuple:
        """(name, symbol, unit) of the motion's parameter, as an axis or a column heads it,
        asked of the plan's first step (the driver): a crank's angle in degrees."""
        return ("crank angle", "θ", "°")

    def parameter_scale(self, scene) -> float:
        """How much of the motion's parameter (in SI) plays the part of a crank's radian,
        asked of the driver: the offsets a sweep takes near a change point (to compare the
        branches' velocities, to extrapolate from both sides) are multiples of it. 1 for a
        crank, whose parameter is its angle in radians."""
        return 1.0

    def input_record(self, scene):
        """The JSON ``input`` of a solve, asked of the driver: None for a crank (the
        solution writes its angle and speed)."""
        return None

    def drive_caption(self, scene):
        """The line under the drawings saying what drives the mechanism, asked of the
        driver: None for a crank (the drawing writes its angle and speed)."""
        return None

    #: what a driver's sweep runs over, in words (None: a crank's turn, between its limits)
    travel = None

    def input_scales(self, scene):
        """(v, a, omega, alpha): the least sizes of each kind that the input sets, asked of
        the plan's first step (the driver; the error bounds are relative to them)."""
        raise NotImplementedError(f"{self.kind} does not drive a mechanism")

    @property
    def label(self) -> str:
        """The step as errors and warnings name it: "step 3 (dyad C from B and D)"."""
        return f"step {self.index + 1} ({self.title})"

    # ----- evaluation
    def bind(self, prm):
        """(position, velocity, acceleration): the step's three phases for the dimensions
        ``prm``, each a function of a :class:`State` that fills in what the step finds. They
        call the kind's module-level formulas, which take floats or arrays alike."""
        raise NotImplementedError

    def bind_instant(self, prm):
        """One function of a :class:`State` for one instant (floats): the step's position,
        the check of its condition (a branching step below ``TOL.singular`` raises), its
        velocity and its acceleration, in a row. By default the three phases of
        :meth:`bind`; a kind may give one that passes its intermediates from phase to phase,
        calling the same module-level formulas (the numbers are the same to the last bit)."""
        position, velocity, acceleration = self.bind(prm)
        if not self.branching:

            def instant(m):
                position(m)
                velocity(m)
                acceleration(m)

            return instant
        i, step = self.index, self

        def instant(m):
            position(m)
            c = m.cond[i]
            if c < TOL.singular:
                raise step.singular(c)
            velocity(m)
            acceleration(m)

        return instant

    @classmethod
    def bind_group_instant(cls, steps, prms):
        """:meth:`bind_instant` for steps bound together (``group_key``): by default the
        three phases of ``bind_group`` in a row."""
        position, velocity, acceleration = cls.bind_group(steps, prms)
        checked = tuple(st for st in steps if st.branching)

        def instant(m):
            position(m)
            for st in checked:
                if m.cond[st.index] < TOL.singular:
                    raise st.singular(m.cond[st.index])
            velocity(m)
            acceleration(m)

        return instant

    def singular(self, c):
        """The error of this step at a condition ``c`` below ``TOL.singular``."""
        return SingularStepError(self.singular_why(c), step=self.label)

    def positions(self, P, ctx):
        """Place this step's point into the dict ``P`` (one step alone, at the plan's own
        dimensions; a step finding several points places them all)."""
        x, y, c = self.place(P, self.params, ctx)
        P[self.finds[0]] = (x, y)
        ctx.cond[self.index] = c

    def candidates(self, P, ctx):
        """The two assemblies as (midpoint, half the vector from one to the other)."""
        prm = self.params
        (x1, y1, _), (x2, y2, _) = self.place(P, prm, ctx, 1.0), self.place(P, prm, ctx, -1.0)
        return ((x1 + x2) / 2, (y1 + y2) / 2), ((x1 - x2) / 2, (y1 - y2) / 2)

    #: the rounding constant of the kind in its error bound (fitted against the 50-digit
    #: reference, with a margin: ``benchmarks/error_bounds.py``)
    rounding = 48.0

    def error_bound(self, walk, k, p_in, v_in, a_in):
        """(eP, eV, eA, eW, eAl): the relative error bounds of what this step finds (its
        points' positions, velocities, accelerations; its links' omegas and alphas), from
        the largest bounds of what it reads (``p_in, v_in, a_in``) and its own rounding
        ``k``. ``walk`` (:mod:`polygon_method.solver.errorbound`) holds the motion, the sizes the
        bounds are relative to (``walk.sizes``, ``walk.ratio``) and the step's condition
        (``walk.condition(step)``). By default: two direction lines (:mod:`.rounding`)."""
        return two_lines(
            walk.condition(self), walk.ratio, walk.own(self, k), p_in, v_in, a_in, walk.couple(self)
        )

    #: steps of one kind next to each other with the same key may be bound together
    #: (``bind_group``): the same formulas, fewer calls
    group_key = None

    @property
    def needs_links(self) -> tuple:
        """Links (other than its own) whose omega and alpha the step reads."""
        return ()

    def reach(self) -> float:
        """The largest length of the step (a scale for its tolerances)."""
        return LEAST_REACH

    # ----- words
    def singular_why(self, c) -> str:
        """Why the step fails at condition ``c`` (below ``TOL.singular``)."""
        return f"the step is singular (condition {c:.2g})"

    def warning(self, c) -> str:
        """The warning line for a condition ``c`` below ``TOL.warn``."""
        return f"{self.label}: condition {c:.3g}"

    def limit_why(self) -> str:
        """Why the linkage cannot be assembled beyond a limit position of this step."""
        return "the linkage cannot be assembled beyond it"

    def stop_words(self, P, key, rate) -> str | None:
        """Why its link ``key`` cannot move at the stated ``rate`` (signed as the scene reads
        it) from the positions ``P``: against a stop (a cylinder at the end of its stroke);
        None where it can."""
        return None

    def condition_column(self):
        """(name, unit, words) of this step's condition in a sweep summary: the
        transmission angle for the steps whose condition is its sine."""
        return (f"mu at {self.finds[0]}", "deg", "transmission angle (acute)")

    def transmission(self):
        """Words for the transmission angle this step's condition measures
        (``"between BC and CD"``), or None if its condition is no transmission angle."""
        return None

    def bodies(self) -> tuple:
        """The bodies this step sets moving (links, blocks), in the order a textbook numbers
        them (ground 1, crank 2, ...)."""
        return ()

    def contacts(self, P):
        """The rolling contacts this step makes, ((body, body, point, words), ...): each
        contact point is the instantaneous centre of its two bodies (no slip), a primary
        centre for Kennedy's theorem. By default none."""
        return ()

    def contact_motion(self, sol):
        """(I, v_I, a_I) of a rolling contact the step makes: the contact point and the
        velocity and acceleration of the rolling body's point there; None by default."""
        return None

    def shapes(self, P):
        """What a configuration diagram draws for this step besides its links, in metres:
        ``("circle", centre point's name, radius)`` (a pitch circle, chain-dotted), ``("ground line",
        point, direction, normal)`` (a fixed line, hatched on the side away from
        ``normal``), ``("contact", point)`` (a rolling contact), ``("guide clear of", slider
        point, position)`` (its guide's wall on the side away from that position: a rack's
        pinion). By default none."""
        return ()

    def produced(self):
        """(A, X) where the step's point X lies on a line AB produced beyond B (the image
        line is drawn produced, from a to x), else None."""
        return None

    def drawn(self, prm, pencil, P):
        """The step's dimensions as a hand drawing makes them: ``pencil(scale)`` gives a
        pencil's error in length (over ``scale``); ``P`` the positions. By default a step
        draws nothing of its own."""
        return prm

    def output(self, ground):
        """What this step drives that a linkage analysis may call the output: ("rocker",
        link, pivot, point), ("slider", point), ("lever", link, pivot, free end), or None."""
        return None

    def orient(self) -> dict:
        """link -> (X, Y): the relative motion of each link the step finds, X relative to Y,
        as the step table's acceleration table names it."""
        return {}

    def default_hint(self, P):
        """Which of the two positions the step takes when the scene does not say."""
        return "above"

    def auxiliary(self, P) -> tuple:
        """Points a construction adds to the configuration diagram: (label, (x, y), the
        points it is drawn from (each a line from that point to it)), as Goodman's
        auxiliary point where two links produced meet. None by default."""
        return ()

    def assemble(self, g):
        """(the step with its assembly chosen, {point: (x, y)}) for a step that chooses
        its own assembly when compiled (``g``: the compiler, its ``P``, ``scene``,
        ``notes``), or None: the compiler chooses between the two positions of
        :meth:`place` (``sigma`` = +1 or -1) by the scene's [assembly] hint."""
        return None
