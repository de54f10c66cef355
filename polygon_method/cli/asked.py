"""``--answers FILE`` for the views that show an answer, not grade it (``solve``, ``steps``,
``draw``, ``page``): the keys an answer file asks, read as ``check`` and ``page`` read one,
in place of the scene's own ``[answers]``. Only what is asked changes what is shown (the
least speed of a link, ``vmin_XY``, and the components ``ar_XY``, ``at_XY``: the other
answers are shown whether asked or not); the values given are ``check``'s to grade."""

from __future__ import annotations

import re
from dataclasses import replace

__all__ = [
    "asked_scene",
    "asked_verdicts",
    "asked_lines",
    "steps_answers",
    "no_answers",
    "ANSWERS_HELP",
    "ASKED_HELP",
]

#: the option's help where the command checks the answers (``page``)
ANSWERS_HELP = "a TOML file with an [answers] table to check"
#: its help where the command shows what they ask (``solve``, ``steps``, ``draw``)
ASKED_HELP = (
    "a TOML file with an [answers] table (a student's or a book's): what it asks is "
    "shown in place of the scene's own (vmin_XY, ar_XY, at_XY); check grades it"
)


def asked_scene(args, scene):
    """``scene`` asking what ``--answers FILE`` asks (its ``[answers]`` in place of the
    scene's); ``scene`` itself without the option. A file that names a variant is read only
    with that variant's own scene (as ``check`` and ``page`` refuse it), and a fault in it is
    one line naming the file, its key and line."""
    path = getattr(args, "answers", None)
    if not path:
        return scene
    from ..common.errors import SceneError
    from ..motion.link_points import PAIR_KINDS, common_link
    from ..scene import load_answers
    from .commands import _own_variant

    _, answers, named = load_answers(path, scene, with_variant=True)
    _own_variant(named, scene, path)
    for a in answers:  # two points of one link: said now, naming the key and its line
        if a.kind in PAIR_KINDS:
            try:
                common_link(scene, *a.names)
            except SceneError as exc:
                raise SceneError(exc.message, file=path, key=f"[answers] {a.key}", line=a.line)
    return replace(scene, answers=tuple(answers))


def no_answers(args, what: str) -> None:
    """``--answers`` refused, in one line, where the view marks no answer (``what``: what it
    draws instead): never silently ignored."""
    if getattr(args, "answers", None):
        from ..common.errors import PolygonMethodError

        raise PolygonMethodError(
            f"{what}, no answer marked: leave out --answers (the page marks them: page "
            "SCENE --answers FILE)",
            key="--answers",
        )


def asked_verdicts(sol, file) -> tuple:
    """The tool's answers to the questions asked without their answers (``v_C = "?"``) of
    the scene's ``[answers]``, or of ``--answers FILE`` in its place (check's verdicts,
    marked asked: one definition of each value); () where none is asked (a scene without
    one pays a search of its text). A fault is one line naming ``file``, the key, its line."""
    from ..common.errors import PolygonMethodError
    from ..scene import asked_questions

    try:
        questions = asked_questions(sol.scene)
        if not questions:
            return ()
        from ..check import asked_verdicts as verdicts

        return verdicts(sol, questions)
    except PolygonMethodError as exc:
        raise exc.located(file)


def asked_lines(verdicts) -> list:
    """``solve``'s last lines: the answers to the questions asked, in the book's form
    (``Answers asked: v_C = 0.3828 m/s; omega_CD = 4.785 rad/s cw``); [] where none is
    asked."""
    if not verdicts:
        return []
    from ..check.verdicts import asked_line

    return ["", asked_line(verdicts)]


def asked_json(verdicts) -> dict:
    """``solve --json``'s ``answers_asked`` (each question's key, value in SI, unit, text
    as a book gives it, the question as written, its line); {} where none is asked."""
    if not verdicts:
        return {}
    from ..check.verdicts import asked_dict

    return {"answers_asked": [asked_dict(v) for v in verdicts]}


_SECTION = re.compile(r"^(?:## )?(\d+)\. ", re.M)


def steps_answers(text: str, verdicts, fmt: str = "text") -> str:
    """``steps``' text ``text`` with a last section, "N. Answers", the answers to the
    questions asked (a line each, in the unit asked for), N the number after its last
    section's; ``text`` itself where none is asked."""
    if not verdicts:
        return text
    from ..check.verdicts import asked_text

    numbers = [int(m.group(1)) for m in _SECTION.finditer(text)]
    head = f"{max(numbers, default=0) + 1}. Answers"
    if fmt == "markdown":
        lines = [f"## {head}", ""] + [f"- {v.key} = {asked_text(v)}" for v in verdicts]
    else:
        lines = [head, "=" * len(head), ""] + [f"  - {v.key} = {asked_text(v)}" for v in verdicts]
    return text.rstrip("\n") + "\n\n" + "\n".join(lines)
