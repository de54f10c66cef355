"""The ``[loads]`` table (a part of the scene reader): a force at a point, a torque on a link,
a gas force on a piston (a cylinder's force: :mod:`.cylinder_loads`)."""

from __future__ import annotations

import math

from ..common.errors import SceneError
from ..common.numbers import article
from .engine import ATMOSPHERE
from .link_loads import read_across
from .records import Load, split_name
from .table_help import _suggest, _unit_at, _which_point


class _Loads:
    """The reader's methods for [loads] (mixed into the reader)."""

    def gauge(self, spec, key, name, advice="") -> float:
        """The gauge pressure ``spec[key]`` (Pa) of ``[loads] name``, refused below a vacuum
        (a slip of sign or unit: it would pull a piston silently; ``advice``: what to write
        instead), as the indicator's readings are: a piston's gas force and a cylinder's."""
        p = self.qty(spec[key], "pressure", "loads", name).value
        if p < -ATMOSPHERE:
            raise self.error(
                f"{key} = {spec[key]!r} is below a vacuum (gauge pressures reach "
                f"-{ATMOSPHERE / 1e5:g} bar at the least){advice}",
                "loads",
                name,
            )
        return p

    def loads(self, known):
        out = []
        for name, spec in self.point_loads():  # (a cylinder's: scene/cylinder_loads.py)
            if not isinstance(spec, dict):
                raise self.error(
                    'a load is { force = "2 kN", direction = 0 }, { force = '
                    '[Fx, Fy] } or, on a link, { torque = "20 N m cw" }',
                    "loads",
                    name,
                )
            if "couple" in spec and "torque" not in spec:  # a book's "a couple of 50 N m"
                spec = {("torque" if k == "couple" else k): v for k, v in spec.items()}
            allowed = ("force", "direction", "torque", "pressure", "bore", "rod", "back")
            for k in spec:
                if k not in allowed:
                    raise self.error(f"unknown key '{k}'{_suggest(k, allowed)}", "loads", name)
            if "pressure" in spec or "bore" in spec or "rod" in spec or "back" in spec:
                out.append(self.gas_load(name, spec))
                continue
            if "torque" in spec:
                if "force" in spec or "direction" in spec:
                    raise self.error(
                        "a torque acts on a link, a force at a point: give the "
                        "force under the name of the point it acts at",
                        "loads",
                        name,
                    )
                if not self.index.get(frozenset(split_name(name))):
                    raise self.error(
                        f"a torque acts on a link; no link {name} in [links]", "loads", name
                    )
                t = self.qty(spec["torque"], "torque", "loads", name, need_sense=True).value
                out.append(Load(self.index[frozenset(split_name(name))].key, torque=t))
                continue
            if name not in known:
                raise self.error(
                    f"load on unknown point {name}{_which_point(name, known)}", "loads", name
                )
            f = spec.get("force")
            if f is None:
                raise self.error("a load needs force", "loads", name)
            if isinstance(f, list):
                if len(f) != 2 or "direction" in spec:
                    raise self.error(
                        "force = [Fx, Fy] in N (no direction with a vector)", "loads", name
                    )
                fx, fy = (self.qty(c, "force", "loads", name, default_unit="N").value for c in f)
            else:
                mag = self.qty(f, "force", "loads", name, default_unit="N").value
                if "direction" not in spec:
                    raise self.error("a force needs a direction (deg, ccw from +x)", "loads", name)
                across = self.link_direction(spec["direction"], name)
                if across is not None:  # turns with the link: completed when compiled
                    out.append(Load(name, across=(*across, mag)))
                    continue
                book = self.book_angle(
                    spec["direction"],
                    "direction",
                    "loads",
                    name,
                    f"direction of the force at {name}",
                )
                ang = (
                    book.value
                    if book is not None
                    else self.qty(
                        spec["direction"], "angle", "loads", name, default_unit="deg"
                    ).value
                )
                ux, uy = _unit_at(ang)
                fx, fy = mag * ux, mag * uy
            out.append(Load(name, force=(fx, fy)))
        return out

    def link_direction(self, raw, name):
        """(first point, second point, offset, words) of a direction stated against a link
        of the scene ("perpendicular to CD, ccw"), or None (:mod:`.link_loads`)."""
        try:
            got = read_across(raw, split_name)
        except SceneError as exc:
            raise self.error(exc.message, "loads", name) from None
        fixed = got is not None and got[0] != got[1] and all(p in self.ground for p in got[:2])
        if got is not None and not fixed and not self.index.get(frozenset(got[:2])):
            raise self.error(
                f"'{raw.strip()}': no link {got[0]}{got[1]} in [links] (nor two ground "
                "points) to take the direction from",
                "loads",
                name,
            )
        return got

    def gas_load(self, name, spec):
        """A gas force on a piston: pressure times the piston's area (the bore's circle, less
        the piston rod's on the crank side of a double-acting cylinder), along
        ``direction``; without a direction, towards the crank (worked out when the scene is
        compiled). ``back``: a double-acting cylinder's crank-side pressure, on the bore's
        circle less the rod's, pushing the other way (``pressure`` then acts on the whole
        bore, the cover side)."""
        if name not in self.slider_points:
            raise self.error(f"a gas pressure acts on a piston: {name} is no slider", "loads", name)
        for k in ("pressure", "bore"):
            if k not in spec:
                raise self.error(
                    f"a gas force needs pressure and bore (and direction, the "
                    f"way the gas pushes the piston, deg ccw from +x, when not "
                    f"towards the crank): no {k}",
                    "loads",
                    name,
                )
        if "force" in spec or "torque" in spec:
            raise self.error(
                "give the gas force by pressure and bore, or a force, not both", "loads", name
            )
        p = self.gauge(spec, "pressure", name)
        bore = self.length(spec["bore"], "loads", name)
        area = math.pi / 4 * bore * bore
        rod_area = 0.0
        words = f"{spec['pressure']} on {article(self._words(bore))} bore"
        if "rod" in spec:
            rod = self.length(spec["rod"], "loads", name)
            if rod >= bore:
                raise self.error(
                    f"the piston rod ({self._words(rod)}) must be thinner than "
                    f"the bore ({self._words(bore)})",
                    "loads",
                    name,
                )
            rod_area = math.pi / 4 * rod * rod
            if "back" not in spec:
                area -= rod_area
                words += f" less a {self._words(rod)} rod"
        f = p * area
        if "back" in spec:  # double-acting: the cover side's pressure less the crank side's
            back = self.gauge(spec, "back", name)
            f -= back * (area - rod_area)
            words += f" (the cover side) against {spec['back']} on the crank side" + (
                f" less a {self._words(math.sqrt(rod_area * 4 / math.pi))} rod" if rod_area else ""
            )
            p, area = f / area, area  # the net pressure on the whole bore
        if "direction" not in spec:
            return Load(name, force=None, gas=(p, area, words), toward=f)
        book = self.book_angle(
            spec["direction"], "direction", "loads", name, f"direction of the gas force at {name}"
        )
        ang = (
            book.value
            if book is not None
            else self.qty(spec["direction"], "angle", "loads", name, default_unit="deg").value
        )
        ux, uy = _unit_at(ang)
        return Load(name, force=(f * ux, f * uy), gas=(p, area, words))
