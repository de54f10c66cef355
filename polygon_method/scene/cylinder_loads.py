"""A force given in a passive cylinder (a strut, a ram under pressure, a damper): ``[loads]``
naming the cylinder by its key (a part of the scene reader).

```toml
[cylinders]
"O-R" = {}
[loads]
"O-R" = { push = "2 kN" }                          # or pull = "2 kN"
"O-R" = { pressure = "5 N/mm^2", bore = 50 }       # on the whole bore: pushes its ends apart
"O-R" = { pressure = "5 N/mm^2", bore = 50, rod = 20 }   # on the annulus: pulls them together
"O-R" = { damping = "400 N s/m" }                  # a damper: F = -c (rate of extension)
"O-R" = { stiffness = "2 N/mm", free_length = 250 } # a spring: F = k (L0 - L)
```

The cylinder is a two-force member: its force ``F`` (+ pushing its ends apart) acts along its
line on the bodies at its two ends. ``pressure`` with ``bore`` acts on the whole bore (the cap
side, the barrel's closed end), pushing the rod out; with ``rod`` and no ``back`` on the
annulus (the rod side), pulling it in; with both, ``pressure`` on the cap side against
``back`` on the annulus. ``damping`` c adds ``-c vs`` (vs the rate of extension: a damper
resists its motion), alone or with a push, a pull or a pressure; ``stiffness`` k with
``free_length`` L0 a spring's ``k (L0 - L)`` (L the cylinder's length at the instant:
compressed it pushes its ends apart, stretched it pulls them together), alone or with the
others. The force analysis applies
it (:mod:`polygon_method.forces.cylinder`); a cylinder on which the motion is given drives
and its force is found, so a force given in it is refused.

>>> c = LoadedCylinder("O-R", "O", "R", None, 2000.0, 50.0, "a push of 2 kN")
>>> c.force_at(0.4), c.force_at(0.4, at_rest=True)
(1980.0, 2000.0)
>>> s = LoadedCylinder("O-R", "O", "R", None, 0.0, 0.0, "a spring", None, 2000.0, 0.5)
>>> s.force_at(0.4, length=0.25), s.force_at(0.0, at_rest=True, length=0.75)
(500.0, -500.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..common.numbers import article
from .records import Cylinder, split_name

__all__ = ["LoadedCylinder", "length_of", "stated", "_CylinderLoads"]

_KEYS = ("push", "pull", "pressure", "bore", "rod", "back", "damping", "stiffness", "free_length")


@dataclass(frozen=True)
class LoadedCylinder(Cylinder):
    """A cylinder with a force given in it: ``push`` (N, + pushing its ends apart; a push,
    minus a pull, or a pressure times its area), ``damping`` (N s/m, the damper's
    coefficient, 0 without), ``words`` how the scene gave it."""

    push: float = 0.0
    damping: float = 0.0
    words: str = ""
    #: a pressure on the annulus (Pa) and the bore's whole area (m^2), or None: the slip
    #: of the rod's area not taken off is asked of it (``check``)
    annulus: tuple | None = None
    #: a spring's stiffness k (N/m, 0 without) and its free length L0 (m, None without)
    stiffness: float = 0.0
    free_length: float | None = None

    def force_at(self, rate, at_rest=False, length=None):
        """The force (N, + pushing apart) at the rate of extension ``rate`` (m/s) and the
        length ``length`` (m; floats or arrays): ``push - c rate + k (L0 - L)``; at rest
        nothing moves, so the damper pushes nothing (the spring still does)."""
        f = self.push if at_rest or not self.damping else self.push - self.damping * rate
        return f + self.spring_at(length) if self.stiffness else f

    def spring_at(self, length):
        """The spring's part ``k (L0 - L)`` (N, + pushing apart: compressed) at ``length``."""
        if not self.stiffness:
            return 0.0
        return self.stiffness * (self.free_length - length)


def length_of(c, P):
    """The cylinder ``c``'s length |R - K| (m; floats or arrays) in the positions ``P``."""
    (kx, ky), (rx, ry) = P[c.barrel], P[c.rod]
    dx, dy = rx - kx, ry - ky
    return (dx * dx + dy * dy) ** 0.5


def stated(scene) -> tuple:
    """The scene's cylinders with a force given in them (:class:`LoadedCylinder`)."""
    return tuple(c for c in scene.cylinders if isinstance(c, LoadedCylinder))


class _CylinderLoads:
    """The scene reader's methods for a force given in a cylinder (mixed into the reader)."""

    def _cylinder_named(self, name):
        """The cylinder ``[loads]`` names (by its two points, either way), or None."""
        pts = split_name(name) if isinstance(name, str) else ()
        if len(pts) != 2:
            return None
        return next(
            (c for c in getattr(self, "cylinder_list", ()) if {c.barrel, c.rod} == set(pts)),
            None,
        )

    def point_loads(self):
        """The ``[loads]`` entries that are not a cylinder's (the points' and the links')."""
        out = []
        for name, spec in self.table("loads").items():
            if self._cylinder_named(name) is not None:
                continue
            if isinstance(spec, dict) and {"push", "pull", "damping"} & set(spec):
                raise self.error(
                    f"no cylinder {name} in [cylinders]: a push, a pull or a damping acts "
                    f'in a cylinder (add [cylinders] "{name}" = {{}}, its barrel\'s pivot '
                    "first)",
                    "loads",
                    name,
                )
            out.append((name, spec))
        return out

    def cylinder_loads(self, cylinders, inp) -> list:
        """``cylinders`` with each one ``[loads]`` names made a :class:`LoadedCylinder`."""
        given = {}
        for name, spec in self.table("loads").items():
            cyl = self._cylinder_named(name)
            if cyl is None:
                continue
            if cyl.key in given:
                raise self.error(f"the cylinder {cyl.key} is loaded twice", "loads", name)
            g = inp.given
            if g is not None and g.kind == "vs" and g.names == (cyl.key,):
                raise self.error(
                    f"the cylinder {cyl.key} drives (its rate of extension {g.key} is given in "
                    "[input]): its force is found, not given; drop one of them",
                    "loads",
                    name,
                )
            if not ("masses" in self.raw or "gravity" in self.raw):
                raise self.error(
                    f"a force in the cylinder {cyl.key} is applied by the force analysis: "
                    "give [masses] (empty for the loads alone) or [gravity]",
                    "loads",
                    name,
                )
            given[cyl.key] = self._cylinder_load(cyl, name, spec)
        return [given.get(c.key, c) for c in cylinders]

    def _cylinder_load(self, cyl, name, spec) -> LoadedCylinder:
        example = (
            f'a force in the cylinder {cyl.key} is {{ push = "2 kN" }} or {{ pull = "2 kN" }}, '
            '{ pressure = "5 N/mm^2", bore = 50 } (and rod = 20: on the annulus), and/or '
            '{ damping = "400 N s/m" }, and/or { stiffness = "2 N/mm", free_length = 250 }'
        )
        if not isinstance(spec, dict) or not spec:
            raise self.error(example, "loads", name)
        for k in spec:
            if k not in _KEYS:
                why = (
                    "a cylinder's force acts along its line: give push or pull, not a force "
                    "and direction"
                    if k in ("force", "direction")
                    else f"unknown key '{k}'"
                )
                raise self.error(f"{why}; {example}", "loads", name)
        ways = [k for k in ("push", "pull", "pressure") if k in spec]
        if len(ways) > 1:
            raise self.error(f"give one of push, pull and pressure, not {ways}", "loads", name)
        push, words, annulus = 0.0, [], None
        if ways and ways[0] != "pressure":
            f = self.qty(spec[ways[0]], "force", "loads", name, default_unit="N").value
            if f < 0:
                other = "pull" if ways[0] == "push" else "push"
                raise self.error(
                    f"a {ways[0]} of {spec[ways[0]]!r} is negative: say {other} instead",
                    "loads",
                    name,
                )
            push = f if ways[0] == "push" else -f
            words.append(f"a {ways[0]} of {spec[ways[0]]}")
        elif ways or any(k in spec for k in ("bore", "rod", "back")):
            push, said = self._oil(cyl, name, spec)
            if "rod" in spec and "back" not in spec:  # (the annulus side alone)
                bore = self.length(spec["bore"], "loads", name)
                p = self._gauge(spec, "pressure", name)
                annulus = (p, math.pi / 4 * bore * bore)
            words.append(said)
        c = 0.0
        if "damping" in spec:
            c = self.qty(spec["damping"], "damping", "loads", name, default_unit="N s/m").value
            if c < 0:
                raise self.error(
                    f"damping = {spec['damping']!r} is negative: a damper resists its motion "
                    "(F = -c times the rate of extension, c > 0)",
                    "loads",
                    name,
                )
            words.append(
                f"a damper of {spec['damping']}" + (" N s/m" if _bare(spec["damping"]) else "")
            )
        k, free = self._spring(cyl, name, spec, words)
        return LoadedCylinder(
            cyl.key, cyl.barrel, cyl.rod, cyl.stroke, push, c, ", ".join(words), annulus, k, free
        )

    def _spring(self, cyl, name, spec, words):
        """(k N/m, L0 m) of a spring in the cylinder (0, None without); its words appended."""
        if "stiffness" not in spec and "free_length" not in spec:
            return 0.0, None
        for k in ("stiffness", "free_length"):
            if k not in spec:
                raise self.error(
                    f"a spring in the cylinder {cyl.key} needs its stiffness and its free "
                    f'length (stiffness = "2 N/mm", free_length = 250): no {k}',
                    "loads",
                    name,
                )
        k = self.qty(spec["stiffness"], "stiffness", "loads", name, default_unit="N/m").value
        if not k > 0:
            raise self.error(
                f"stiffness = {spec['stiffness']!r} is not positive: a spring's stiffness k > 0 "
                "(F = k (L0 - L), compressed it pushes its ends apart)",
                "loads",
                name,
            )
        free = self.length(spec["free_length"], "loads", name, positive=False)
        if not free > 0:
            raise self.error(
                f"free_length = {spec['free_length']!r} is not positive: a spring's free "
                "length is its length unloaded, L0 > 0",
                "loads",
                name,
            )
        unit = " N/m" if _bare(spec["stiffness"]) else ""
        words.append(f"a spring of {spec['stiffness']}{unit}, free length {self._words(free)}")
        return k, free

    def _gauge(self, spec, key, name) -> float:
        """A cylinder's gauge pressure ``spec[key]`` (Pa): the reader's :meth:`gauge`, a
        pull said as a cylinder gives it."""
        return self.gauge(
            spec, key, name, ": a pull is a pressure on the annulus (rod = ...) or pull = ..."
        )

    def _oil(self, cyl, name, spec):
        """(the force, + pushing apart; its words) of a pressure on the cylinder's piston."""
        for k in ("pressure", "bore"):
            if k not in spec:
                raise self.error(
                    f"a pressure in the cylinder {cyl.key} needs pressure and bore (and rod "
                    "for the annulus side): no " + k,
                    "loads",
                    name,
                )
        p = self._gauge(spec, "pressure", name)
        bore = self.length(spec["bore"], "loads", name)
        area = math.pi / 4 * bore * bore
        words = f"{spec['pressure']} on {article(self._words(bore))} bore"
        if "back" in spec and "rod" not in spec:
            raise self.error(
                "back is the pressure on the annulus (the rod side): give the rod's diameter "
                "(rod = 20)",
                "loads",
                name,
            )
        if "rod" not in spec:
            return p * area, words + " on the cap side, " + (
                "pushing the rod out"
                if p > 0
                else "no force"
                if p == 0
                else "below the atmosphere: pulling the rod in"
            )
        rod = self.length(spec["rod"], "loads", name)
        if rod >= bore:
            raise self.error(
                f"the piston rod ({self._words(rod)}) must be thinner than the bore "
                f"({self._words(bore)})",
                "loads",
                name,
            )
        annulus = area - math.pi / 4 * rod * rod
        if "back" not in spec:
            return (
                -p * annulus,
                f"{spec['pressure']} on the annulus of {article(self._words(bore))} bore less a "
                f"{self._words(rod)} rod, "
                + (
                    "pulling the rod in"
                    if p > 0
                    else "no force"
                    if p == 0
                    else "below the atmosphere: pushing the rod out"
                ),
            )
        back = self._gauge(spec, "back", name)
        return p * area - back * annulus, (
            words + f" on the cap side against {spec['back']} on the annulus, less a "
            f"{self._words(rod)} rod"
        )


def _bare(raw) -> bool:
    return type(raw) in (int, float)
