"""The papers of a class's variants: the answer key (Markdown, CSV), the problem sheet
(Markdown, PDF: matplotlib imported only when a PDF is asked for) and the summary line per
variant. Text only: the command line writes them."""

from __future__ import annotations

import csv
import io

from ..common.errors import SceneError
from ..common.numbers import fmt, sense
from ..common.units import UNITS, question_unit
from ..linkage.cycle_values import CYCLE_KEYS, cycle_value, words as cycle_words
from ..linkage.engine_values import ENGINE_KEYS, engine_value
from ..scene.questions import unit_kind
from ..text.words import given


def _turning_unit(unit) -> bool:
    """A unit of a quantity with a sense (cw, ccw): rpm, deg/s^2, kN m, ..."""
    return any(unit in UNITS[k] for k in ("angular_velocity", "angular_acceleration", "torque"))


def answer(sol, q) -> float:
    """The exact value of a question ``(key, kind, names, unit, signed)`` in ``sol`` (an
    engine's key from the engine chapter's values: a variant that cannot give it is
    refused in one line naming the key)."""
    if q[1] in ENGINE_KEYS:
        v = engine_value(sol, q[0])
        if v is None:
            raise SceneError(
                f"{q[0]}: a variant of this scene does not give it (no forces, or no "
                "flywheel); leave it out of the base scene's [answers]",
                key=f"[answers] {q[0]}",
            )
        return float(v)
    if q[1] in CYCLE_KEYS:  # a quick return's times, a stroke, a link's angle (rad)
        return float(cycle_value(sol, q[1], q[2], q[0]))
    return float(sol.value(q[1], q[2]))


def _in_unit_asked(x, q) -> tuple:
    """(value, unit) of a question's answer ``x`` (SI) in the unit it asks (``"? rpm"``),
    else as it is."""
    if len(q) < 6 or not q[5]:
        return x, q[3]
    return x / question_unit(q[5], unit_kind(q[1])), q[5]


def _signed(x, unit, signed):
    if not signed:
        return f"{fmt(abs(x))} {unit}"
    s = sense(x) if unit in ("rad/s", "rad/s^2", "N m") or _turning_unit(unit) else ""
    if s:
        return f"{fmt(abs(x))} {unit} {s}"
    return f"{fmt(x)} {unit}"


def answer_key_csv(vs) -> str:
    """One row per variant: its id, file, the values chosen, then each answer in SI
    (angular quantities and torques signed, counter-clockwise positive), written in full
    (the shortest text that reads back as the same double)."""
    keys = [v.key for v in vs.base.variation.varied]
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["variant", "file"] + keys + [f"{q[0]} ({q[3]})" for q in vs.questions])
    for v in vs.variants:
        w.writerow(
            [v.id, v.name]
            + [v.shown[k] for k in keys]
            + [repr(float(answer(v.solution, q))) for q in vs.questions]
        )
    return buf.getvalue()


def _cell(x):
    return str(x).replace("|", "\\|")


def answer_key_markdown(vs) -> str:
    """The teacher's answer key as Markdown: one row per variant, its varied dimensions and its
    answers."""
    base = vs.base
    keys = [v.key for v in base.variation.varied]
    out = [
        f"# Answer key: {base.title or base.file}",
        "",
        f"{len(vs.variants)} variants, seed {vs.seed}; each assembled as the base scene, "
        f"every construction step's condition at least {base.variation.min_text}, "
        f"the linkage's class kept ({vs.linkage}). Values to four significant "
        "figures (the CSV has ten); grade with `polygon-method check BASE ANSWERS "
        "--variants DIR`.",
        "",
    ]
    head = ["variant"] + keys + [q[0] for q in vs.questions]
    out.append("| " + " | ".join(_cell(h) for h in head) + " |")
    out.append("|" + "---|" * len(head))
    for v in vs.variants:
        cells = (
            [v.id]
            + [v.shown[k] for k in keys]
            + [_signed(*_in_unit_asked(answer(v.solution, q), q), q[4]) for q in vs.questions]
        )
        out.append("| " + " | ".join(_cell(c) for c in cells) + " |")
    return "\n".join(out) + "\n"


_QUESTION_WORDS = {
    "v": "the velocity of {0}",
    "a": "the acceleration of {0}",
    "omega": "the angular velocity of link {0}",
    "alpha": "the angular acceleration of link {0}",
    "vs": "the sliding velocity at {0}",
    "as": "the sliding acceleration at {0}",
    "ac": "the Coriolis component at {0}",
    "rub": "the rubbing velocity at pin {0}",
    "torque": "the input torque on the crank",
    "vI": "the velocity of the point of wheel {0} in contact",
    "aI": "the acceleration of the point of wheel {0} in contact",
    "F": "the force at pin {0}",
    "N": "the guide's normal force on block {0}",
    "vu": "the velocity of the point of the guide under the block {0}",
    "au": "the acceleration of the point of the guide under the block {0}",
    "Fc": "the contact force between {0}",
    "Tmax": "the largest torque the friction drive passes to {0}",
    "Pmax": "the largest power through the grip of {0}",
    "Fi": "the inertia force of {0}",
    "Ci": "the inertia couple of {0}",
    "Thold": "the torque holding the fixed gear about {0}",
    "h": "the offset of {0}'s inertia force from its centre of mass",
    "force": "the driver's force along its guide",
    "force2": "the second input's force along its guide",
    "torque2": "the second input's torque",
}
#: two points of one link (X, Y): the least speed between them, X's components about Y
_PAIR_WORDS = {
    "vmin": "the least velocity of a point of {0}{1} (and where it is)",
    "ar": "the radial component of the acceleration of {0} relative to {1}",
    "at": "the tangential component of the acceleration of {0} relative to {1}",
}


def _question(q) -> str:
    key, kind, names = q[0], q[1], q[2]
    if kind in ("v", "a") and len(names) == 2:
        what = (
            "the velocity of {0} relative to {1}"
            if kind == "v"
            else "the acceleration of {0} relative to {1}"
        ).format(*names)
    elif kind in _PAIR_WORDS:
        what = _PAIR_WORDS[kind].format(*names)
    elif kind in ENGINE_KEYS:
        what = ENGINE_KEYS[kind][2] + (f" of the cylinder {names[0]}" if names else "")
    elif kind in CYCLE_KEYS:
        what = cycle_words(kind, names)
    else:
        what = _QUESTION_WORDS[kind].format(
            "".join(names)
            if kind in ("omega", "alpha", "vI", "aI") and all(len(n) == 1 for n in names)
            else "-".join(names)
        )
    unit = f", in {q[5]}" if len(q) > 5 and q[5] else ""  # "? rpm": the unit asked
    return f"{what} (`{key}`{unit})"


def sheet_sections(vs) -> list:
    """(heading, lines) for each variant's problem."""
    out = []
    for v in vs.variants:
        lines = ["Given:"] + [f"- {x}" for x in given(v.scene)]
        sc = v.scene
        how = (
            "the force polygons (a static force analysis)"
            if sc.statics and not (sc.masses or sc.gravity)
            else "the velocity and acceleration polygons"
            + (" and the force polygons" if sc.has_forces else "")
        )
        lines += ["", f"Find, by {how}:"]
        lines += [f"- {_question(q)}" for q in vs.questions]
        lines += [
            "",
            f'Write your answers in a file with `variant = "{v.id}"` and an '
            '`[answers]` table (e.g. `v_C = "0.4 m/s"`).',
        ]
        out.append((f"Variant {v.id}", lines))
    return out


def sheet_markdown(vs) -> str:
    """The problem sheet: each student's problem with their own numbers."""
    base = vs.base
    out = [f"# {base.title or base.file}: a problem per student", ""]
    for head, lines in sheet_sections(vs):
        out += [f"## {head}", ""] + lines + [""]
    return "\n".join(out)


def sheet_pages(vs, figure=None):
    """The problem sheet's pages, matplotlib figures (A4) per variant: its problem in words
    and, with ``figure`` (``figure(ax, solution, scale)`` paints a configuration diagram in
    centimetres of paper, as ``draw.draw_configuration`` does), the student's own figure
    true to a stated round scale under it (over the page where it does not fit)."""
    import textwrap

    from matplotlib.figure import Figure

    base = vs.base

    def page(head):
        fig = Figure(figsize=(PAGE_CM[0] / 2.54, PAGE_CM[1] / 2.54))
        fig.text(
            0.08, 0.95, f"{base.title or base.file}".replace("$", r"\$"), fontsize=11, va="top"
        )
        fig.text(0.08, 0.92, head, fontsize=15, weight="bold", va="top")
        return fig

    for v, (head, lines) in zip(vs.variants, sheet_sections(vs)):
        fig, y = page(head), 0.88
        for line in lines:
            for part in textwrap.wrap(line.replace("`", "").replace("$", r"\$"), 90) or [""]:
                if y < BOTTOM:  # the page is full: the problem goes on over the page
                    yield fig
                    fig, y = page(f"{head} (continued)"), 0.88
                fig.text(0.08, y, part, fontsize=10, va="top")
                y -= 0.022
        if figure is not None:
            if not _put_figure(fig, y, v.solution, figure):
                yield fig
                fig = page(f"{head}: the figure")
                _put_figure(fig, 0.88, v.solution, figure)
        yield fig


#: the lowest line of a problem sheet's page (fraction of its height from the bottom)
BOTTOM = 0.05
#: the problem sheet's page: A4 portrait (cm), and its side margins
PAGE_CM = (21.0, 29.7)
_SIDE_CM = 0.08 * PAGE_CM[0]


def _put_figure(fig, top, sol, figure) -> bool:
    """Paint ``sol``'s configuration on ``fig`` below ``top`` (a fraction of the page's
    height), true to scale: at the step table's scale, or the next round scales where it
    does not fit the room left; False (nothing painted) where the room left is too small
    for it at half the step table's size."""
    from ..polygons.scales import coarser, diagram_scales

    scale = diagram_scales(sol)[0]
    first = scale.per_cm
    room_w = PAGE_CM[0] - 2 * _SIDE_CM
    room_h = (top - BOTTOM) * PAGE_CM[1] - 1.0  # a line for the scale's words above it
    while True:
        ax = fig.add_axes((0.0, 0.0, 0.1, 0.1))
        figure(ax, sol, scale)
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        w, h = x1 - x0, y1 - y0
        if w <= room_w and h <= room_h:
            break
        fig.delaxes(ax)
        if scale.per_cm > 2.01 * first:
            return False
        scale = coarser(scale)
    left = (PAGE_CM[0] - w) / 2
    bottom = top * PAGE_CM[1] - 1.0 - h
    ax.set_position((left / PAGE_CM[0], bottom / PAGE_CM[1], w / PAGE_CM[0], h / PAGE_CM[1]))
    fig.text(0.08, top, f"Figure: the configuration, drawn at {scale.text}", fontsize=10, va="top")
    return True


def sheet_pdf(vs, figure=None) -> bytes:
    """The problem sheet as a PDF, a page per variant (with its figure: see
    :func:`sheet_pages`)."""
    from matplotlib.backends.backend_pdf import PdfPages

    buf = io.BytesIO()
    base = vs.base
    with PdfPages(
        buf, metadata={"Title": f"{base.title or base.file}: problem sheet", "CreationDate": None}
    ) as pdf:
        for fig in sheet_pages(vs, figure):
            pdf.savefig(fig)
    return buf.getvalue()


def summary_text(vs) -> str:
    """One line per variant and what varied, as ``variants`` prints it."""
    base = vs.base
    lines = [
        f"{base.title or base.file}: {len(vs.variants)} variants (seed {vs.seed}) of "
        f"{vs.space} combinations, {vs.tried} screened; class kept: {vs.linkage}; "
        f"every step's condition at least {base.variation.min_text}"
    ]
    for v in vs.variants:
        lines.append(
            f"  {v.name}: "
            + ", ".join(f"{k} {v.shown[k]}" for k in v.shown)
            + f"; least condition {v.least_condition:.3f}"
        )
    return "\n".join(lines)
