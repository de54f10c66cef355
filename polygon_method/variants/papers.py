"""The papers of a class's variants: the answer key (Markdown, CSV), the problem sheet
(Markdown, PDF: matplotlib imported only when a PDF is asked for) and the summary line per
variant. Text only: the command line writes them."""

from __future__ import annotations

import csv
import io

from ..numbers import fmt, sense
from ..scene import Scene, scene_table


def answer(sol, q) -> float:
    """The exact value of a question ``(key, kind, names, unit, signed)`` in ``sol``."""
    return float(sol.value(q[1], q[2]))


def _signed(x, unit, signed):
    if not signed:
        return f"{fmt(abs(x))} {unit}"
    s = sense(x) if unit in ("rad/s", "rad/s^2", "N m") else ""
    if s:
        return f"{fmt(abs(x))} {unit} {s}"
    return f"{fmt(x)} {unit}"


def answer_key_csv(vs) -> str:
    """One row per variant: its id, file, the values chosen, then each answer in SI
    (angular quantities and torques signed, counter-clockwise positive)."""
    keys = [v.key for v in vs.base.variation.varied]
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["variant", "file"] + keys + [f"{q[0]} ({q[3]})" for q in vs.questions])
    for v in vs.variants:
        w.writerow([v.id, v.name] + [v.shown[k] for k in keys]
                   + [f"{answer(v.solution, q):.10g}" for q in vs.questions])
    return buf.getvalue()


def _cell(x):
    return str(x).replace("|", "\\|")


def answer_key_markdown(vs) -> str:
    base = vs.base
    keys = [v.key for v in base.variation.varied]
    out = [f"# Answer key: {base.title or base.file}", "",
           f"{len(vs.variants)} variants, seed {vs.seed}; each assembled as the base scene, "
           f"every construction step's condition at least {base.variation.min_text}, "
           f"the linkage's class kept ({vs.linkage}). Values to four significant "
           "figures (the CSV has ten); grade with `polygon-method check BASE ANSWERS "
           "--variants DIR`.", ""]
    head = ["variant"] + keys + [q[0] for q in vs.questions]
    out.append("| " + " | ".join(_cell(h) for h in head) + " |")
    out.append("|" + "---|" * len(head))
    for v in vs.variants:
        cells = [v.id] + [v.shown[k] for k in keys] + \
            [_signed(answer(v.solution, q), q[3], q[4]) for q in vs.questions]
        out.append("| " + " | ".join(_cell(c) for c in cells) + " |")
    return "\n".join(out) + "\n"


_QUESTION_WORDS = {"v": "the velocity of {0}", "a": "the acceleration of {0}",
                   "omega": "the angular velocity of link {0}",
                   "alpha": "the angular acceleration of link {0}",
                   "vs": "the sliding velocity at {0}", "as": "the sliding acceleration at {0}",
                   "ac": "the Coriolis component at {0}", "rub": "the rubbing velocity at pin {0}",
                   "torque": "the input torque on the crank"}


def _question(q) -> str:
    key, kind, names = q[0], q[1], q[2]
    if kind in ("v", "a") and len(names) == 2:
        what = ("the velocity of {0} relative to {1}" if kind == "v"
                else "the acceleration of {0} relative to {1}").format(*names)
    else:
        what = _QUESTION_WORDS[kind].format("".join(names) if kind in ("omega", "alpha")
                                            and all(len(n) == 1 for n in names)
                                            else "-".join(names))
    return f"{what} (`{key}`)"


def _given(sc: Scene, raw: dict) -> list:
    u = sc.units
    out = []
    g = raw.get("ground", {})
    out.append("fixed pivots: " + ", ".join(f"{p} at ({_n(x)}, {_n(y)}) {u}"
                                           for p, (x, y) in g.items()))
    out.append("links: " + ", ".join(f"{k} = {_q(v, u)}" for k, v in raw["links"].items()))
    for cp in sc.points:
        out.append(f"point {cp.name}: {cp.how}")
    for name, s in raw.get("sliders", {}).items():
        if "along" in s:
            out.append(f"block {name} slides along {s['along']}")
        else:
            thr = s.get("through")
            where = (f" through ({_n(thr[0])}, {_n(thr[1])}) {u}" if isinstance(thr, list)
                     else f" through {thr}" if thr else "")
            out.append(f"slider {name} moves on a {s['path']} path{where}"
                       if s["path"] in ("horizontal", "vertical")
                       else f"slider {name} moves on a path at {s['path']}{where}")
    for p, h in raw.get("assembly", {}).items():
        out.append(f"{p} assembled {h} (of its two positions)" if isinstance(h, str)
                   else f"{p} assembled near ({_n(h[0])}, {_n(h[1])}) {u} (of its two "
                   "positions)")
    inp = raw["input"]
    line = (f"crank {inp['crank']} at {_q(inp['angle'], 'deg')} from +x (ccw), turning at "
            f"{inp['speed']}")
    if inp.get("acceleration") not in (None, 0):
        line += f", angular acceleration {inp['acceleration']}"
    out.append(line)
    for p, spec in raw.get("pins", {}).items():
        (k, v), = spec.items()
        out.append(f"pin {p}: {k} {_q(v, u)}")
    for p, spec in raw.get("loads", {}).items():
        if "torque" in spec:
            out.append(f"torque on {p}: {spec['torque']}")
        elif isinstance(spec.get("force"), list):
            out.append(f"force at {p}: ({spec['force'][0]}, {spec['force'][1]}) N")
        else:
            out.append(f"force at {p}: {_q(spec['force'], 'N')} at {_q(spec['direction'], 'deg')}")
    return out


def _n(x):
    return f"{x:g}" if isinstance(x, (int, float)) else str(x)


def _q(v, unit):
    return v if isinstance(v, str) else f"{v:g} {unit}"


def sheet_sections(vs) -> list:
    """(heading, lines) for each variant's problem."""
    out = []
    for v in vs.variants:
        raw = scene_table(v.scene)
        lines = ["Given:"] + [f"- {x}" for x in _given(v.scene, raw)]
        lines += ["", "Find, by the velocity and acceleration polygons:"]
        lines += [f"- {_question(q)}" for q in vs.questions]
        lines += ["", f"Write your answers in a file with `variant = \"{v.id}\"` and an "
                  "`[answers]` table (e.g. `v_C = \"0.4 m/s\"`)."]
        out.append((f"Variant {v.id}", lines))
    return out


def sheet_markdown(vs) -> str:
    """The problem sheet: each student's problem with their own numbers."""
    base = vs.base
    out = [f"# {base.title or base.file}: a problem per student", ""]
    for head, lines in sheet_sections(vs):
        out += [f"## {head}", ""] + lines + [""]
    return "\n".join(out)


def sheet_pages(vs):
    """The problem sheet's pages, one matplotlib figure (A4, plain text) per variant."""
    import textwrap

    from matplotlib.figure import Figure

    base = vs.base

    def page(head):
        fig = Figure(figsize=(8.27, 11.69))
        fig.text(0.08, 0.95, f"{base.title or base.file}".replace("$", r"\$"), fontsize=11,
                 va="top")
        fig.text(0.08, 0.92, head, fontsize=15, weight="bold", va="top")
        return fig

    for head, lines in sheet_sections(vs):
        fig, y = page(head), 0.88
        for line in lines:
            for part in textwrap.wrap(line.replace("`", "").replace("$", r"\$"), 90) or [""]:
                if y < BOTTOM:  # the page is full: the problem goes on over the page
                    yield fig
                    fig, y = page(f"{head} (continued)"), 0.88
                fig.text(0.08, y, part, fontsize=10, va="top")
                y -= 0.022
        yield fig


#: the lowest line of a problem sheet's page (fraction of its height from the bottom)
BOTTOM = 0.05


def sheet_pdf(vs) -> bytes:
    """The problem sheet as a PDF, a page per variant."""
    from matplotlib.backends.backend_pdf import PdfPages

    buf = io.BytesIO()
    base = vs.base
    with PdfPages(buf, metadata={"Title": f"{base.title or base.file}: problem sheet",
                                 "CreationDate": None}) as pdf:
        for fig in sheet_pages(vs):
            pdf.savefig(fig)
    return buf.getvalue()


def summary_text(vs) -> str:
    base = vs.base
    lines = [f"{base.title or base.file}: {len(vs.variants)} variants (seed {vs.seed}) of "
             f"{vs.space} combinations, {vs.tried} screened; class kept: {vs.linkage}; "
             f"every step's condition at least {base.variation.min_text}"]
    for v in vs.variants:
        lines.append(f"  {v.name}: " + ", ".join(f"{k} {v.shown[k]}" for k in v.shown)
                     + f"; least condition {v.least_condition:.3f}")
    return "\n".join(lines)
