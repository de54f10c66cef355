"""``--answers FILE`` for the views that show an answer, not grade it (``solve``, ``steps``,
``draw``, ``page``): the keys an answer file asks, read as ``check`` and ``page`` read one,
in place of the scene's own ``[answers]``. Only what is asked changes what is shown (the
least speed of a link, ``vmin_XY``, and the components ``ar_XY``, ``at_XY``: the other
answers are shown whether asked or not); the values given are ``check``'s to grade."""

from __future__ import annotations

from dataclasses import replace

__all__ = ["asked_scene", "no_answers", "ANSWERS_HELP", "ASKED_HELP"]

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
