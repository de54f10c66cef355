"""Check answers (a student's or a book's) against the solution, and name the mistake.

For every answer: the value given, the correct value, the error in %, the verdict; for a
wrong one, the known mistake that explains it where one does (rpm used as rad/s, a
relative velocity given for an absolute one, the other assembly branch, the sum of angular
velocities where the difference applies, ...). The alternatives are computed by the solver
(a re-solved scene with the mistaken speed, angle or branch) or from its numbers; no
kinematics is redone here.

Tolerance rule (when the answers do not state ``tolerance``): what a careful drawing at the
chosen scales allows. A length on a diagram is drawn and read to half a millimetre
(0.05 cm); at the velocity scale ``s_v`` (m/s per cm) that is ``0.05 s_v``; a value derived
from a read-off inherits its error (omega = v / l: ``0.05 s_v / l``; rubbing
|w1 - w2| r: the sum of both; torque = sum(F . v) / omega: ``sum |F| 0.05 s_v / omega``).
Where the two direction lines of a construction cross at less than 30 deg the read-off
error grows as ``1 / (2 sin gamma)``. Never tighter than 0.5 % (three significant figures);
values computed rather than drawn (the crank's) get 0.5 %. For speeds, accelerations,
omegas, alphas, rubbing velocities, the input torque and the sliding quantities (sliding
velocity and acceleration, Coriolis) a simulated careful hand drawing (:mod:`.handdrawn`)
decides where it allows more.

>>> from polygon_method import parse_scene, solve
>>> sol = solve(parse_scene('''
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
... speed = "300 rpm ccw"
... [answers]
... v_A = "45 m/s"
... '''))
>>> v = check_answers(sol)[0]
>>> v.ok, v.mistake                    # 300 x 0.15: N used as omega
(False, 'rpm_as_rad_s')
"""

from __future__ import annotations

import math
from dataclasses import replace

from ..common.errors import SceneError
from ..motion.link_points import PAIR_KINDS
from ..motion.solution import Solution
from ..motion.tidy import tidied
from .centres import centre_verdict
from .cycle import CYCLE_KEYS, cycle_verdict
from .engine import ENGINE_KEYS, engine_verdict
from .mistakes import _Diagnoser
from .tolerance import SOURCES, Stated, _Tolerances, answer_tolerance, choose_tolerance
from .verdicts import (
    _NOISE_KIND,
    ROUNDING,
    UNIT_OF,
    Verdict,
    asked_line,
    asked_text,
    verdicts_dict,
    verdicts_text,
)

#: answers that are magnitudes (a negative one is a mistake of its own)
_MAGNITUDES = {
    "v": "a speed",
    "a": "an acceleration's size",
    "ac": "a Coriolis component's size",
    "rub": "a rubbing velocity",
    "F": "a pin force's size",
    "N": "a guide's normal force's size",
    "Fc": "a contact force's size",
    "Tmax": "a largest torque",
    "Pmax": "a largest power",
    "vu": "a speed",
    "au": "an acceleration's size",
    "Fi": "an inertia force's size",
    "h": "an offset",
    "vmin": "a speed",
    "ar": "a component's size",
    "at": "a component's size",
}


def _noise_of(sol: Solution, kind, names) -> tuple:
    """(kind, name) of :meth:`Solution.noise` for an answer: its own error bound."""
    if kind in ("omega", "alpha"):  # a link's, or a cylinder's
        return kind, sol._key("-".join(names))
    if kind in ("vs", "as", "ac"):
        return kind, names[0]
    if kind in ("vu", "au"):  # the guide's point under a block: from the guide's end and
        sl = sol.scene.slider(names[0])  # the block's point, the sum of their bounds
        return kind[0], (sol.scene.link(sl.guide).p, sl.point)
    if kind in PAIR_KINDS:  # two points of one link: the sum of their bounds
        return PAIR_KINDS[kind][0], tuple(names)
    if kind in ("vI", "aI"):  # the rolling step's points
        key = sol.scene.link("-".join(names)).key
        pts = [p for st in sol.plan.steps if key in st.links for p in (*st.needs, *st.finds)]
        return kind[0], tuple(dict.fromkeys(pts)) or None
    return kind, tuple(names)


def tolerances(sol: Solution):
    """The tolerances of one solution, to share among many answer files."""
    return _Tolerances(sol)


__all__ = [
    "tolerances",
    "Verdict",
    "check_answers",
    "asked_verdict",
    "asked_verdicts",
    "asked_line",
    "asked_text",
    "answer_tolerance",
    "verdicts_text",
    "verdicts_dict",
    "ROUNDING",
    "Stated",
    "choose_tolerance",
    "SOURCES",
]


def check_answers(sol: Solution, answers=None, tolerance: float | None = None, _tols=None) -> tuple:
    """Check ``answers`` (default: the scene's ``[answers]``) against ``sol``.

    Parameters
    ----------
    answers : iterable of :class:`~polygon_method.scene.Answer`, optional
    tolerance : float or :class:`Stated`, optional
        Relative tolerance (0.03 for 3 %), or a stated one (relative, or absolute per
        unit); default the scene's ``tolerance`` for the scene's own answers, else the
        drawing rule (module docstring).

    Returns
    -------
    tuple of :class:`Verdict`, in the answers' order.
    """
    if answers is None:
        answers = sol.scene.answers
        if tolerance is None:
            tolerance = sol.scene.tolerance
    answers = tuple(answers)
    tols = _tols or _Tolerances(sol)  # (one for a whole class: the same drawings)
    diag = _Diagnoser(sol, [a for a in answers if not a.asked])
    out = []
    centres = []
    clean = []  # the solution without rounding noise, made when an answer needs it
    for ans in answers:
        kind = ans.kind
        if ans.asked:  # a question without its answer: the value, not graded
            out.append(asked_verdict(sol, ans, clean, centres))
        elif kind == "centre":
            out.append(centre_verdict(sol, ans, tolerance, centres))
        elif kind in ENGINE_KEYS:  # the engine chapter's: its efforts, the cycle, the flywheel
            out.append(engine_verdict(sol, ans, tolerance))
        elif kind in CYCLE_KEYS:  # a quick return's times, a stroke, a link's angle
            out.append(cycle_verdict(sol, ans, tolerance))
        else:
            out.append(_verdict(sol, ans, tolerance, tols, diag, clean))
    return _graded_once(sol, answers, out)


#: the answer kinds whose two names, in either order, are one quantity: a link's omega
#: and alpha (omega_BC is omega_CB), a relative velocity's or acceleration's size (v_BC,
#: v_CB), a wheel's contact point, a contact force
_EITHER_ORDER = ("omega", "alpha", "v", "a", "vI", "aI", "Fc", "centre", "vmin", "ar", "at")


#: the answer kinds that are sizes (a question's value is shown as one): the rest are
#: signed (a sense, ccw positive, or a sign along a guide)
_SIZES = ("v", "a", "ac", "rub", "F", "N", "Fc", "vu", "au", "Fi", "h", "Tmax", "Pmax", "vI", "aI")


def asked_verdict(sol: Solution, ans, clean=None, centres=None) -> Verdict:
    """The tool's value of a question asked without its answer (``v_C = "?"``): the value
    a given answer is checked against (the same functions: :func:`_exact`, the engine's
    and the centres' verdicts), a :class:`Verdict` marked ``asked``, not graded."""
    clean = [] if clean is None else clean
    if ans.kind == "centre":
        return centre_verdict(sol, ans, None, [] if centres is None else centres)
    if ans.kind in ENGINE_KEYS:
        return engine_verdict(sol, ans, None)
    if ans.kind in CYCLE_KEYS:
        return cycle_verdict(sol, ans, None)
    exact = _exact(sol, ans, clean)
    slider = sol.scene.slider(ans.names[0]) if ans.kind in ("vs", "as") else None
    if slider is not None:  # along the guide: its size and which way, in words
        from ..text.polygon_steps import sliding_words

        along = sliding_words(slider, exact)
        return Verdict.asked_of(ans, exact, UNIT_OF[ans.kind], False, extra={"along": along})
    # (a cylinder's extension and its rate: signed, as solve's cylinder table gives them)
    signed = ans.kind not in _SIZES and ans.kind not in PAIR_KINDS
    return Verdict.asked_of(ans, exact if signed else abs(exact), UNIT_OF[ans.kind], signed)


def asked_verdicts(sol: Solution, answers) -> tuple:
    """:func:`asked_verdict` of each question among ``answers`` asked without its answer,
    in their order (``solve`` and ``steps`` end with them)."""
    clean, centres = [], []
    return tuple(asked_verdict(sol, a, clean, centres) for a in answers if a.asked)


def _quantity(ans):
    """What an answer names, the same for its names in either order."""
    if ans.kind in _EITHER_ORDER:
        return ans.kind, frozenset(ans.names)
    return ans.kind, tuple(ans.names)


def _column(sol: Solution, ans) -> str | None:
    """The one name of an answer's quantity where it has two (``omega_CB``: ``omega_BC``, as
    the scene names the link; ``v_CB``: its points in the scene's order), else None."""
    if ans.kind not in _EITHER_ORDER or ans.kind == "centre" or len(ans.names) != 2:
        return None
    sc = sol.scene
    if ans.kind in ("v", "a"):
        order = {p: i for i, p in enumerate(sc.point_names)}
        a, b = sorted(ans.names, key=lambda p: order.get(p, len(order)))
        name = f"{ans.kind}_{a}{b}" if len(a) == len(b) == 1 else f"{ans.kind}_{a}-{b}"
    elif sc.has_link("-".join(ans.names)):
        name = f"{ans.kind}_{sc.link('-'.join(ans.names)).key}"
    else:
        return None
    return None if name == ans.key else name


def _graded_once(sol: Solution, answers, verdicts) -> tuple:
    """The verdicts with the same quantity given under several names (``omega_BC`` and
    ``omega_CB``) graded once, in the first name's row, the others named in it: right
    only where every value given for it is."""
    first: dict = {}
    out: list = []
    for ans, v in zip(answers, verdicts):
        q = _quantity(ans)
        if v.asked:  # a question, not graded: its own row
            out.append(v)
            continue
        if q not in first:
            first[q] = len(out)
            out.append(replace(v, column=_column(sol, ans)))
            continue
        k = first[q]
        also = (*out[k].also, (v.key, v.raw, v.line, v.ok, v.given))
        out[k] = replace(out[k], also=also, ok=out[k].ok and v.ok)
        if out[k].mistake is None and not v.ok:  # the wrong one's mistake, the first right
            why = v.diagnosis or "none of the known ones explains it"
            out[k] = replace(out[k], mistake=v.mistake, diagnosis=f"{v.key}: {why}")
    return tuple(out)


def _exact(sol: Solution, ans, clean: list) -> float:
    """The right value of ``ans``: rounding noise within its bound a zero (a translating
    coupler's omega; a load that takes no power, two omegas alike: from the tidied solution,
    made once into ``clean``)."""
    kind = ans.kind
    try:
        exact = sol.value(kind, ans.names)
    except SceneError as exc:  # (a key the mechanism has no value for: name it, and its line)
        if exc.key is not None:
            raise
        raise SceneError(exc.message, key=f"[answers] {ans.key}", line=ans.line) from None
    if exact is None or not math.isfinite(exact):
        raise SceneError(
            f"{ans.key}: no value to check against", key=f"[answers] {ans.key}", line=ans.line
        )
    if kind in ("torque", "rub"):  # (a load that takes no power, two omegas alike)
        if not clean:
            clean.append(tidied(sol))
        return clean[0].value(kind, ans.names)
    if kind in _NOISE_KIND:  # noise within its bound is a zero (a translating coupler's omega)
        return sol.shown(exact, *_noise_of(sol, kind, ans.names))
    return exact


def _verdict(sol: Solution, ans, tolerance, tols, diag, clean: list) -> Verdict:
    """The verdict on one answer of a kinematic quantity (:func:`check_answers`)."""
    kind = ans.kind
    exact = _exact(sol, ans, clean)
    signed = ans.sense is not None or ans.value < 0
    if kind in ("v", "a", "ac", "rub", "F", "N", "Fc", "vu", "au", "Fi", "h", "Tmax", "Pmax"):
        signed = False
    if kind in PAIR_KINDS:
        signed = False
    given = ans.value if signed else abs(ans.value)
    correct = exact if signed else abs(exact)
    tol, rule = answer_tolerance(sol, kind, ans.names, correct, tolerance, _tols=tols)
    err = abs(given - correct)
    ok = err <= tol * (1 + ROUNDING)
    mistake = diagnosis = None
    if kind in _MAGNITUDES and ans.value < 0 and correct != 0:
        ok, mistake = False, "negative_magnitude"
        diagnosis = (
            f"{_MAGNITUDES[kind]} is a magnitude, never negative: give its size "
            f"({abs(ans.value):g}), and its direction in words where asked"
        )
    elif not ok:
        mistake, diagnosis = diag.diagnose(ans, given, correct, tol, signed)
    return Verdict.judged(
        ans, given, correct, UNIT_OF[kind], tol, rule, ok, signed, mistake, diagnosis
    )
