"""The tolerance of an answer: what a careful drawing at the chosen scales allows (see
the package's rule)."""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..common.errors import PolygonMethodError
from ..polygons.scales import DRAWING_PRECISION_CM, diagram_scales
from .handdrawn import BUILT, HOW, HandDrawing
from ..scene import GuideSlider
from ..motion.solution import Solution
from .verdicts import FORCE_KINDS, ROUNDING, UNIT_OF

_SIN30 = 0.5


@dataclass(frozen=True)
class Stated:
    """A tolerance stated instead of the default: ``relative`` (0.05 for 5 %) for every
    answer, and ``absolute`` ((SI unit of the answers, SI value, as written), ...) for the
    answers in that unit (``0.01 m/s`` for velocities); ``source`` says where it was
    stated (a verdict's rule ends with it)."""

    relative: float | None = None
    absolute: tuple = ()
    source: str = "the answers' tolerance"

    def text(self) -> str:
        """The stated tolerance in words: "5 %, 0.01 m/s"."""
        parts = ([f"{100 * self.relative:g} %"] if self.relative is not None else []) + [
            t for _, _, t in self.absolute
        ]
        return ", ".join(parts)

    def absolute_for(self, unit):
        """The absolute tolerance stated for ``unit`` and its words, ``(value, text)``, or None."""
        return next(((x, t) for u, x, t in self.absolute if u == unit), None)


#: where the tolerance of an answer file came from
SOURCES = {
    "command line": "--tolerance on the command line",
    "answer file": "the answer file's own tolerance",
    "scene": "the scene's [answers] tolerance, the book's, for its own answers",
    "default": "the default: what a careful hand drawing at the step table's scales allows",
}


def choose_tolerance(
    command_line: Stated | None, own: float | None, book: float | None, scenes_own: bool
) -> tuple:
    """(the tolerance to check with: a :class:`Stated` or None for the default, where it
    comes from: a key of ``SOURCES``, and why, in words) for one set of answers.

    The command line first, then the answer file's own ``tolerance``; the scene's (the
    book's) only for the scene's own answers: a student's file is never checked at the
    book's tolerance without saying so.

    >>> choose_tolerance(None, None, 0.03, scenes_own=False)[1:]
    ('default', "the default: what a careful hand drawing at the step table's scales allows (not the scene's 3 %: that is the book's, for the scene's own answers)")
    >>> choose_tolerance(Stated(0.05, source="--tolerance"), 0.02, 0.03, False)[1]
    'command line'
    """
    if command_line is not None:
        why = f"{command_line.text()}, from {SOURCES['command line']}"
        if own is not None:
            why += f" (over the answer file's own {100 * own:g} %)"
        return command_line, "command line", why
    if own is not None:
        return Stated(own), "answer file", f"{100 * own:g} %, {SOURCES['answer file']}"
    if book is not None and scenes_own:
        return Stated(book), "scene", f"{100 * book:g} %, {SOURCES['scene']}"
    why = SOURCES["default"]
    if book is not None:
        why += (
            f" (not the scene's {100 * book:g} %: that is the book's, for the scene's own answers)"
        )
    return None, "default", why


def _terms(terms) -> str:
    """``a - b + c`` from (sign, text) pairs."""
    out = ("" if terms[0][0] > 0 else "-") + terms[0][1]
    for sg, t in terms[1:]:
        out += f" {'+' if sg > 0 else '-'} {t}"
    return out


class _Tolerances:
    """Drawing tolerances of one solution (see the module docstring)."""

    def __init__(self, sol: Solution):
        self.sol = sol
        _, self.sv, self.sa = diagram_scales(sol)
        self.d = DRAWING_PRECISION_CM
        steps = sol.plan.steps
        self.factor = {}
        worst = 1.0
        for st in steps:
            worst = min(worst, sol.conditions.get(st.index, 1.0))
            f = max(1.0, _SIN30 / max(worst, ROUNDING))
            for p in st.finds:
                self.factor[p] = f
            for lk in st.links:
                self.factor[lk] = f
        self.crank = steps[0]  # the driver: a crank, or a block driven along its guide
        self.input_links = steps[0].links  # the crank's link (a block's: none)
        self.input_point = steps[0].finds[0]  # the crank's tip, the block's point

    def hand(self, kind, names, correct):
        """The simulated hand drawing's relative tolerance, or None where it says nothing."""
        if not hasattr(self, "_hand"):
            try:
                self._hand = HandDrawing(self.sol)
            except PolygonMethodError:  # no simulation here: the drawing rule applies
                self._hand = None
        if self._hand is None:
            return None
        return self._hand.tolerance(kind, names, correct)

    def f(self, what) -> float:
        return self.factor.get(what, 1.0)

    def link_factor(self, key) -> float:
        return self.factor.get(key, 1.0)

    def omega_abs(self, key) -> float:
        """Drawing error of omega of link ``key``: 0.05 s_v / l (zero for the crank)."""
        sc = self.sol.scene
        if key in self.input_links or key in self.sol.plan.fixed_links:
            return 0.0
        lk = sc.link(key)
        return self.d * self.sv.per_cm * self.link_factor(lk.key) / lk.length

    def body_omega_abs(self, body) -> float:
        sc = self.sol.scene
        if body == "ground":
            return 0.0
        if body.startswith("block "):
            sl = sc.slider(body[6:])
            return self.omega_abs(sc.link(sl.guide).key) if isinstance(sl, GuideSlider) else 0.0
        return self.omega_abs(body)

    def drawing(self, kind, names) -> tuple[float, str]:
        """(absolute drawing tolerance, what it is read from) of an answer."""
        sol, d = self.sol, self.d
        sv, sa = self.sv.per_cm, self.sa.per_cm
        vt, at = f"velocity diagram at {self.sv.text}", f"acceleration diagram at {self.sa.text}"
        if kind in FORCE_KINDS or (kind == "torque" and sol.scene.has_forces):
            return 0.0, "computed (the force analysis)"
        if kind in ("v", "a"):
            if len(names) == 1 and names[0] == self.input_point and sol.scene.input.given is None:
                return 0.0, "computed (crank)"
            f = max(self.f(n) for n in names)
            return (d * sv * f, vt) if kind == "v" else (d * sa * f, at)
        if kind in ("omega", "alpha"):
            s = sv if kind == "omega" else sa
            cyl = sol.scene.cylinder("-".join(names))
            if cyl is not None:  # read off the polygon over the cylinder's length now
                return d * s / sol.cylinder_length(cyl.key), (vt if kind == "omega" else at)
            lk = sol.scene.link("-".join(names))
            given = sol.scene.input.given is not None  # the crank's speed read off too
            if lk.key in self.input_links and not given:
                return 0.0, "computed (crank)"
            f = self.link_factor(lk.key)
            return d * s * f / lk.length, (vt if kind == "omega" else at)
        if kind in ("vu", "au"):  # read off at a1 (a1'), found with the block's step
            f = self.f(sol.scene.slider(names[0]).point)
            return (d * sv * f, vt) if kind == "vu" else (d * sa * f, at)
        if kind in ("vI", "aI"):  # read off at the contact's image, like the wheel's point
            f = max(self.f(n) for n in names)
            return (d * sv * f, vt) if kind == "vI" else (d * sa * f, at)
        if kind in ("vmin", "ar", "at"):  # two points of one link
            f = max(self.f(n) for n in names)
            if kind == "at":  # the tangential component, read off the acceleration diagram
                return d * sa * f, at
            if kind == "vmin":  # op, read off the velocity diagram
                return d * sv * f, vt
            r = math.dist(sol.P[names[0]], sol.P[names[1]])  # v^2 / r with v as read
            return 2 * d * sv * f * sol.speed(*names) / r if r else 0.0, vt
        if kind in ("vs", "as"):
            if names[0] == self.input_point and not self.crank.periodic:
                return 0.0, "given (the driving block)"
            f = self.f(names[0])
            return (d * sv * f, vt) if kind == "vs" else (d * sa * f, at)
        if kind == "ac":
            sl = sol.scene.slider(names[0])
            if not isinstance(sl, GuideSlider):
                return d * sa, at
            g = sol.scene.link(sl.guide)
            w, vs = abs(sol.W[g.key]), abs(sol.S[names[0]][0])
            return 2 * d * sv * self.f(names[0]) * (w + vs / g.length), vt
        if kind == "rub":
            r = sol.rubbing[names[0]]
            if not r.pairs:
                return d * sv, vt
            pair = max(r.pairs, key=r.pairs.get)
            a, b = pair.split("|")
            return r.radius * (self.body_omega_abs(a) + self.body_omega_abs(b)), vt
        if kind == "torque":
            sc = sol.scene
            tot = 0.0
            for load in sc.loads:
                if load.force is not None:
                    tot += math.hypot(*load.force) * d * sv * self.f(load.target)
                else:
                    tot += abs(load.torque) * self.omega_abs(load.target)
            return tot / abs(sc.input.omega), vt
        raise KeyError(kind)


def answer_tolerance(
    sol: Solution,
    kind: str,
    names: tuple,
    correct: float,
    relative: float | None = None,
    _tols=None,
) -> tuple[float, str]:
    """(absolute tolerance, rule) for one answer.

    ``relative`` (the answers' ``tolerance``) gives ``relative |correct|``; without it the
    drawing rule of the module docstring applies. Never tighter than 0.5 % of |correct|.
    """
    tols = _tols or _Tolerances(sol)
    draw, where = tols.drawing(kind, names)
    source = "the answers' tolerance"
    if isinstance(relative, Stated):
        source = relative.source
        given = relative.absolute_for(UNIT_OF[kind])
        if given is not None:  # 0.01 m/s for the velocities
            return given[0], f"{given[1]} ({source})"
        relative = relative.relative
    if relative is not None:
        tol = relative * abs(correct)
        if tol == 0:
            tol = draw or ROUNDING
        return tol, f"{100 * relative:g} % ({source})"
    hand = None if where.startswith("computed") else tols.hand(kind, names, correct)
    if hand is not None and hand * abs(correct) > max(ROUNDING * abs(correct), draw):
        how = f"{BUILT}{HOW[kind]}" if kind in HOW else ""
        return hand * abs(correct), (
            "a careful hand drawing at the step table's scales (pencil 0.25 mm and 0.25 deg, "
            "lengths read to the ruler's 1 mm division), "
            f"simulated: 95 % of drawings are this close{how}"
        )
    tol = max(ROUNDING * abs(correct), draw)
    if tol == 0:
        tol = tols.d * (tols.sv.per_cm if UNIT_OF[kind] in ("m/s", "rad/s") else tols.sa.per_cm)
    if draw <= ROUNDING * abs(correct):
        return tol, "0.5 % (three significant figures)" if where.startswith(
            "computed"
        ) else f"0.5 % (three significant figures; 0.05 cm on the {where} is finer)"
    return tol, f"0.05 cm on the {where}"
