"""The variants' records (a part of the variants' generator, :mod:`.`): one student's
variant, the set made of a base scene, and the one line saying fewer were found than asked."""

from __future__ import annotations

from dataclasses import dataclass

from ..scene import Scene


@dataclass(frozen=True)
class Variant:
    """One student's problem: its id, file name, the values chosen (as the scene writes
    them, by ``[variants]`` key), its scene text, the scene read back and its solution."""

    id: str
    name: str
    values: dict
    shown: dict
    text: str
    scene: Scene
    solution: object
    least_condition: float
    linkage: str


def shortfall_line(found, kept: str, widen: str) -> str | None:
    """One line when ``found`` (a set of variants: ``variants``, ``requested``, ``space``,
    ``tried``, ``exhaustive``, ``rejected``) holds fewer than asked, else None: how many
    of how many combinations made a good variant (``kept``: what a good one is), why the
    others were turned down, and what to do (``widen``: the ranges, or more)."""
    n = len(found.variants)
    if n >= found.requested:
        return None
    why = ", ".join(f"{k}: {v}" for k, v in sorted(found.rejected.items(), key=lambda kv: -kv[1]))
    where = (
        f"only {n} of the {found.space} combinations of [variants] make a good variant"
        if found.exhaustive
        else f"only {n} good variants found in {found.tried} of the {found.space} "
        "combinations of [variants]"
    )
    return (
        f"{where} ({kept}), not {found.requested}"
        + (f"; turned down: {why}" if why else "")
        + (f": widen the ranges or ask for --count {n}" if n else f": {widen}")
    )


@dataclass(frozen=True)
class VariantSet:
    """The variants made of a base scene: each variant, how many were asked for, the seed, the
    combinations the ranges allow and how many were screened."""

    base: Scene
    variants: tuple
    requested: int
    seed: int
    space: int  # combinations the ranges allow
    tried: int  # candidates screened
    exhaustive: bool  # every combination was screened
    rejected: dict  # why candidates were turned down -> how many
    linkage: str
    questions: tuple  # (key, kind, names, unit, signed, the unit asked or None)

    def shortfall(self) -> str | None:
        """One line when fewer variants than asked were found, else None."""
        return shortfall_line(
            self,
            f"assembled on the stated branch, every step's condition at least "
            f"{self.base.variation.min_text}, the class kept: {self.linkage}",
            "widen the ranges or lower min_condition",
        )
