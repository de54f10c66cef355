"""The force chapter's tables: ``[masses]`` (a link's mass, its centre of mass and moment of
inertia; a slider block's or piston's mass) and ``[gravity]`` (a part of the scene reader).

A scene without them is solved for its motion alone, as before.
"""

from __future__ import annotations

import math
import re

from ..common.errors import SceneError
from ..common.tolerances import ROUNDING
from ..common.units import UNITS, Quantity, did_you_mean
from .records import Friction, Gravity, Mass, split_name
from .pendulum import PENDULUM_KEYS, TWO_SWING_KEYS, swing_inertia, two_swings
from .table_help import _unit_at

#: the g of a book (m/s^2), when [gravity] does not give its own
STANDARD_G = 9.81
#: a uniform link's mass or weight per length: "20 N/m", "5 kg/m", "2 lbf/ft"
_PER_LENGTH = re.compile(
    r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(kg|g|t|lb|N|kN|kgf|lbf)\s*/\s*"
    r"(m|mm|cm|ft|in)\s*$"
)

_LINK_KEYS = (
    (
        "mass",
        "centre",
        "along",
        "from",
        "distances",
        "turn",
        "inertia",
        "gyration",
        "about",
    )
    + PENDULUM_KEYS
    + TWO_SWING_KEYS
)


class _Masses:
    """The scene reader's methods for [masses] and [gravity] (mixed into the reader)."""

    @staticmethod
    def rest_speed(raw):
        """A crank's speed of a bare nought (at rest: it needs no unit), else None."""
        return Quantity(0.0) if type(raw) in (int, float) and raw == 0 else None

    def at_rest_speed(self, alpha, sense=None, two=False) -> Quantity:
        """A crank's speed of nought: at rest, where the scene asks for the force analysis
        (its weights and loads alone, no inertia); the motion is then solved per rad/s of
        the crank (ccw), the virtual velocities of the power balance. Refused without the
        force analysis. ``sense`` (``"0 rad/s cw"``): the way the motion is about to start,
        against which a limiting friction acts (ccw unless cw). With an acceleration
        ``alpha`` (rad/s^2): starting from rest, its inertia the tangential terms alone
        (``start_alpha``), the motion per rad/s in alpha's sense (a stated sense must agree;
        one crank: ``two`` inputs refused). The caller solves the motion without alpha."""
        if not ("masses" in self.raw or "gravity" in self.raw):
            raise self.error(
                "the crank speed is zero: nothing moves"
                + (
                    " (starting from rest with an acceleration: give [masses] for the "
                    "inertia of the start, or the speed at the instant)"
                    if alpha
                    else " (at rest, the weights held: give [masses] and [gravity]; the "
                    'loads alone: give any speed, e.g. "1 rad/s ccw", without masses nothing '
                    "depends on it, and an empty [masses] for the pin forces too)"
                ),
                "input",
                "speed",
            )
        self.at_rest = True  # (to turn in the sense stated: a limiting friction's sense)
        if alpha:
            way = "ccw" if alpha > 0 else "cw"
            if sense is not None and sense != way:
                raise self.error(
                    f"the crank starts from rest {sense}, but its acceleration is {way}: "
                    "from rest it turns the way it accelerates (drop the speed's sense, or "
                    "give the acceleration's)",
                    "input",
                    "speed",
                )
            if two:
                raise self.error(
                    "starting from rest with an acceleration is solved for one crank: "
                    "with two inputs give each crank's speed at the instant",
                    "input",
                    "speed",
                )
            self.start_alpha = alpha
            sense = way
        return Quantity(-1.0, "cw") if sense == "cw" else Quantity(1.0, "ccw")

    def at_rest_driver(self, speed, acc, key) -> float:
        """A driving block's or wheel's speed of nought (``key``: ``vs_A``, ``omega_W``):
        at rest as a crank's (:meth:`at_rest_speed`), the motion solved per 1 m/s (1
        rad/s) the way the zero's sign says (``"0 m/s left"``; a bare 0 along the guide's
        direction, or a wheel's ccw), or starting from rest the way ``acc`` says, its
        inertia ``start_alpha = acc``. Refused without the force analysis."""
        if not ("masses" in self.raw or "gravity" in self.raw):
            raise self.error(
                f"{key} is zero: nothing moves (at rest, the weights held: give [masses] "
                "and [gravity]; starting from rest with an acceleration: [masses])",
                "input",
                key,
            )
        self.at_rest = True
        if acc:
            self.start_alpha = acc
            return 1.0 if acc > 0 else -1.0
        return math.copysign(1.0, speed)

    def masses(self, carried, sliders):
        """[masses]: one :class:`Mass` per link or block named."""
        out = []
        for name, spec in self.table("masses").items():
            if not isinstance(spec, dict) or "mass" not in spec:
                raise self.error(
                    'a mass is { mass = "2 kg" } for a slider block, or for a '
                    'link { mass = "2 kg", centre = "G" (or along = 40, '
                    'from = "B"), inertia = "0.02 kg m^2" (or gyration = 50) }',
                    "masses",
                    name,
                )
            per = _PER_LENGTH.match(spec["mass"]) if isinstance(spec["mass"], str) else None
            m = self._mass(per.group(1) + " " + per.group(2) if per else spec["mass"], name)
            if not m > 0:
                hint = (
                    "; a balanced crank (its G at its pivot) has its real mass with "
                    "centre = its pivot: it then takes no power (only its weight acts, at the pivot)"
                    if m == 0 and "inertia" in spec
                    else ""
                )
                raise self.error(
                    f"a mass must be positive, got {spec['mass']!r}{hint}", "masses", name
                )
            pts = split_name(name)
            if per is not None and len(pts) == 1:
                raise self.error(
                    f"mass = {spec['mass']!r}: a mass (or weight) per length is a uniform "
                    "link's; a block's is its mass", "masses", name,
                )  # fmt: skip
            if len(pts) == 1 and name in self.slider_points:
                extra = [k for k in spec if k != "mass"]
                if extra:
                    raise self.error(
                        f"a block's mass is at its point {name} and it does not "
                        f"turn: give only mass (not '{extra[0]}')",
                        "masses",
                        name,
                    )
                out.append(Mass(name, m, block=True, centre=name, how=f"at {name}"))
                continue
            if len(pts) == 1:
                raise self.error(
                    f"{name} is no slider: a link's mass goes under the link's "
                    "name (e.g. AB), a block's under its point",
                    "masses",
                    name,
                )
            for k in spec:
                if k not in _LINK_KEYS:
                    raise self.error(f"unknown key '{k}'{_did_you_mean(k)}", "masses", name)
            link, pts = self.find_link(name, "masses", name)
            if any(o.body == link.key for o in out):
                raise self.error(f"link {link.key} has a mass already", "masses", name)
            lam, mu, where, centre, inertia, said, m = self._link_mass(
                spec, per, m, (link, pts, carried), name
            )
            out.append(
                Mass(
                    link.key,
                    m,
                    lam,
                    mu,
                    inertia,
                    centre=centre,
                    how=f"centre of mass {where}; {said}",
                )
            )
        return out

    def _link_mass(self, spec, per, m, placed, name) -> tuple:
        """(lam, mu, words of G, its named point, I_G, words of I, the mass) of a link's
        entry: G placed and I given (or from a swing), or both from two swings."""
        link, pts, carried = placed
        if ("knife_edge" in spec and "swings" not in spec) or ("swings" in spec and per):
            raise self.error(
                "knife_edge goes with swings, and swings with the link's whole mass",
                "masses",
                name,
            )
        if "swings" in spec:  # its G and I_G from two swings
            g = (self.gravity() or Gravity(STANDARD_G, None, "")).g
            lam, where, inertia, said = two_swings(self, spec, link, m, name, g)
            return lam, 0.0, where, None, inertia, said, m
        lam, mu, where, centre = self._centre(spec, link, pts, carried, name)
        inertia, said, m = self._link_inertia(spec, per, m, link, (lam, mu), name)
        return lam, mu, where, centre, inertia, said, m

    def _link_inertia(self, spec, per, m, link, at, name) -> tuple:
        """(I_G, words, the mass) of a link: a uniform bar's from its mass per length, the
        given inertia or gyration (about G, or about an end: the parallel axes), or its swing
        as a compound pendulum (:mod:`.pendulum`)."""
        lam, mu = at
        swing = any(k in spec for k in PENDULUM_KEYS)
        if per is not None:  # "the links weigh 20 N/m": a uniform bar, m = w L
            m, said = self._uniform(spec, per, m, link, name)
            inertia = m * link.length**2 / 12.0
            if "inertia" in spec or "gyration" in spec:
                inertia, said = self._inertia(spec, m, name)
        if swing:  # "it makes 21 complete oscillations in 40 seconds"
            g = (self.gravity() or Gravity(STANDARD_G, None, "")).g
            return (*swing_inertia(self, spec, link, m, lam, mu, name, g), m)
        if per is None:
            inertia, said = self._inertia(spec, m, name)
        if "about" in spec:  # "I about the crank shaft's axis O": the parallel axes
            inertia, said = self._about(spec, link, m, lam, mu, inertia, said, name)
        return inertia, said, m

    def _centre(self, spec, link, pts, carried, name):
        """(lam, mu, words, named point or None) of a link's centre of mass."""
        L = link.length
        named = spec.get("centre")
        placed = "along" in spec or "distances" in spec
        if named is not None:
            if placed:
                raise self.error(
                    'give the centre as a point (centre = "G") or as a place '
                    "(along, distances), not both",
                    "masses",
                    name,
                )
            if named in link.points:
                lam = 0.0 if named == link.p else 1.0
                return lam, 0.0, f"at {named}", named
            cp = next((c for c in carried if c.name == named), None)
            if cp is None or cp.link != link.key:
                on = f" (it is on {cp.link})" if cp is not None else ""
                raise self.error(
                    f"centre = {named!r} is not a point of link {link.key}{on}: "
                    "name one of its joints or of its carried points in [points], "
                    "or give along/distances",
                    "masses",
                    name,
                )
            return cp.lam, cp.mu, f"at {named}", named
        if not placed:
            if "from" in spec or "turn" in spec:
                raise self.error("'from' and 'turn' go with along and distances", "masses", name)
            return 0.5, 0.0, f"at the middle of {link.key} (no centre given)", None
        frame = {link.p: (0.0, 0.0), link.q: (L, 0.0)}
        for c in carried:
            if c.link == link.key:
                frame[c.name] = (c.lam * L, c.mu * L)
        xy, how, _, _ = self.on_link(spec, link, pts, frame, "masses", name)
        return xy[0] / L, xy[1] / L, how, None

    def _about(self, spec, link, m, lam, mu, inertia, said, name):
        """(I about G, words) from a moment of inertia (or a radius of gyration) a book gives
        about an end of the link ("about the crank shaft's axis O"): I_G = I_O - m |OG|^2
        (the parallel axes), |OG| from G's place on the link."""
        end = spec["about"]
        if end not in link.points or not ("inertia" in spec or "gyration" in spec):
            raise self.error(
                f"about = {end!r}: the end of {link.key} the moment of inertia (or the "
                "radius of gyration) is given about, with inertia or gyration",
                "masses",
                name,
            )
        d = link.length * math.hypot(lam - (0.0 if end == link.p else 1.0), mu)
        i_g = inertia - m * d * d
        if i_g < -ROUNDING * inertia:  # (nought within rounding: all the mass at G)
            raise self.error(
                f"I about {end} = {inertia:.6g} kg m^2 is less than m |{end}G|^2 = "
                f"{m * d * d:.6g} kg m^2: no body has it (check the centre and the value)",
                "masses",
                name,
            )
        i_g = max(i_g, 0.0)
        return (
            i_g,
            f"{said.replace('_G', '_' + end)} about {end}; I_G = I_{end} - m |{end}G|^2 = {i_g:.6g} kg m^2",
        )

    def _inertia(self, spec, m, name):
        """(I about G, words): given, from the radius of gyration (I = m k^2), or 0."""
        if "inertia" in spec and "gyration" in spec:
            raise self.error(
                "give the moment of inertia or the radius of gyration, not both", "masses", name
            )
        if "inertia" in spec:
            inertia = self.qty(
                spec["inertia"], "moment_of_inertia", "masses", name, default_unit="kg m^2"
            ).value
            if inertia < 0:
                raise self.error(
                    f"a moment of inertia cannot be negative, got {spec['inertia']!r}",
                    "masses",
                    name,
                )
            return inertia, f"I_G = {inertia:.6g} kg m^2"
        if "gyration" in spec:
            k = self.length(spec["gyration"], "masses", name)
            return m * k * k, f"k_G = {self._words(k)}, I_G = m k^2 = {m * k * k:.6g} kg m^2"
        return 0.0, "I_G = 0 (no inertia given: a point mass)"

    def _uniform(self, spec, per, m, link, name) -> tuple:
        """(the link's mass, words) from its mass ``m`` per ``per``'s length unit: times its
        length; a uniform bar's I_G = m L^2 / 12 unless the entry gives its own."""
        unit = UNITS["length"][per.group(3)]
        total = m * link.length / unit
        length = f"{spec['mass']} x {link.length / unit:.6g} {per.group(3)}"
        weight = self.read_notes and self.read_notes[-1].startswith(f"mass of {name}: the weight")
        if weight:  # (the note of the weight per length read as a mass: said once, here)
            self.read_notes.pop()
            w = float(per.group(1)) * link.length / unit
            length += f" = {w:.6g} {per.group(2)}, read as W / g"
        self.read_notes.append(f"mass of {name}: {length} = {total:.6g} kg (a uniform link)")
        said = f"I_G = m L^2 / 12 = {total * link.length**2 / 12.0:.6g} kg m^2 (a uniform bar)"
        return total, said

    def _mass(self, raw, name) -> float:
        """A [masses] entry's mass (kg); a book's weight ("the reciprocating parts weigh 300
        N": ``mass = "300 N"``, also kN, kgf, lbf) is read as the mass W / g (the g of
        [gravity], else 9.81 m/s^2), said in the notes."""
        try:
            return self.qty(raw, "mass", "masses", name, default_unit="kg").value
        except SceneError as not_a_mass:
            try:
                w = self.qty(raw, "force", "masses", name).value if isinstance(raw, str) else None
            except SceneError as not_a_weight:  # a weight's own refusal ("1e-300 N": too
                words = raw.split()  # small) where its unit is a force's
                if len(words) == 2 and words[1] in UNITS["force"]:
                    raise not_a_weight from None
                w = None
            if w is None:
                raise not_a_mass from None
        g = (self.gravity() or Gravity(STANDARD_G, None, "")).g
        self.read_notes.append(f"mass of {name}: the weight {raw} read as W / g = {w / g:.6g} kg")
        return w / g

    def gravity(self):
        """[gravity]: None without the table (gravity off)."""
        if "gravity" not in self.raw:
            return None
        spec = self.table("gravity")
        for k in spec:
            if k not in ("g", "direction"):
                raise self.error(
                    f"unknown key '{k}'{_did_you_mean(k, ('g', 'direction'))}", "gravity", k
                )
        g = STANDARD_G
        if "g" in spec:
            g = self.qty(spec["g"], "acceleration", "gravity", "g", default_unit="m/s^2").value
            if not g > 0:
                raise self.error(f"g must be positive, got {spec['g']!r}", "gravity", "g")
        ang = -math.pi / 2
        if "direction" in spec:
            ang = self.qty(
                spec["direction"], "angle", "gravity", "direction", default_unit="deg"
            ).value
        u = _unit_at(ang)
        text = f"g = {g:g} m/s^2 " + (
            "downwards" if u == (0.0, -1.0) else f"at {math.degrees(ang):g} deg"
        )
        return Gravity(g, u, text)

    def friction(self, pins, sliders=(), known=()):
        """[friction]: None without the table (frictionless, as the books start). Each of
        ``guides`` and ``pins`` a coefficient for all, or a table of each guide's (by its
        block's point) or each pin's own."""
        if "friction" not in self.raw:
            return None
        spec = self.table("friction")
        out = {}
        sized = {p.point for p in pins}
        blocks = {s.point for s in sliders} | {s.key for s in sliders}
        joints = set(known)  # (a friction circle stated at a point: any joint)
        for k, v in spec.items():
            if k not in ("guides", "pins"):
                raise self.error(
                    f"unknown key '{k}'{_did_you_mean(k, ('guides', 'pins'))}: "
                    "[friction] takes guides and pins (coefficients)",
                    "friction",
                    k,
                )
            if isinstance(v, dict):
                each = self._each_friction(k, v, blocks if k == "guides" else sized | joints)
                out["at_" + k] = tuple(e for e in each if not isinstance(e[1], tuple))
                if k == "pins":  # (a friction circle stated: its radius, no pin size)
                    out["at_circles"] = tuple((q, r[0]) for q, r in each if isinstance(r, tuple))
                    self._sized(out["at_pins"], sized)
                continue
            if k == "pins" and isinstance(v, str):
                out["circle"] = self._circle(v, k)
                continue
            out[k] = self._coefficient(k, v)
        if out.get("pins") and not pins:
            raise self.error(
                "friction at the pins needs their sizes: give [pins] (each pin's "
                "diameter or radius: the friction circle's radius is mu r)",
                "friction",
                "pins",
            )
        self._circles_inside(out, pins)
        return Friction(**out)

    def _circles_inside(self, out, pins) -> None:
        """A friction circle stated where [pins] gives the pin's size lies inside the pin:
        its radius is mu r, mu below 1 (a 30 mm circle on a 25 mm pin was read)."""
        size = {p.point: p.radius for p in pins}
        every = [(q, out["circle"]) for q in size] if "circle" in out else []
        for q, rc in [*out.get("at_circles", ()), *every]:
            if q in size and not rc < size[q]:
                raise self.error(
                    f"pins: the friction circle at {q}, {self._words(rc)}, is not smaller "
                    f"than the pin itself (radius {self._words(size[q])} in [pins]): its "
                    "radius is mu r, mu below 1 (check the value, or give the pin's "
                    f"coefficient: pins = {{ {q} = 0.1 }})",
                    "friction",
                    "pins",
                )

    def _circle(self, v, key, name="") -> float:
        """A friction circle's radius stated ("5 mm"), with its unit: a number in quotes
        ("0.1") reads as a coefficient as well as a length (it was read as 0.1 mm)."""
        if re.fullmatch(r"\s*[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?\s*", v):
            raise self.error(
                f"{name or key} = {v!r}: a friction circle's radius takes its unit "
                f'("{v.strip()} {self.unit}"); a coefficient of friction is a bare number '
                f"({name or key} = {v.strip()})",
                "friction",
                key,
            )
        return self.length(v, "friction", key)  # (refused unless positive)

    def _sized(self, each, sized) -> None:
        """A pin given a coefficient needs its size in [pins] (its friction circle mu r)."""
        for q, _ in each:
            if q not in sized:
                raise self.error(
                    f"pins.{q}: a coefficient needs the pin's size in [pins] (its friction "
                    f"circle mu r), or give the circle's radius itself (pins = {{ {q} = "
                    '"5 mm" })',
                    "friction",
                    "pins",
                )

    def _coefficient(self, k, v, name=""):
        if isinstance(v, bool) or not isinstance(v, (int, float)) or not 0 <= v < 1:
            raise self.error(
                f"{name or k} = {v!r}: a coefficient of friction, a number from 0 up to (not) 1",
                "friction",
                k,
            )
        return float(v)

    def _each_friction(self, k, table, names) -> tuple:
        """``guides = { B = 0.1, A = 0.15 }``: each guide's coefficient by its block's point
        (each pin's by its name in [pins]); a name that is none of them is refused."""
        if not table:
            raise self.error(
                f"{k} = {{}} names none: give each one's coefficient ({k} = {{ B = 0.1 }}), "
                f"or one for all ({k} = 0.1)",
                "friction",
                k,
            )
        out = []
        for name, v in table.items():
            if name not in names:
                what = (
                    "a sliding block's point (the guide of the block there)"
                    if k == "guides"
                    else "a joint of the mechanism (a pin)"
                )
                have = ", ".join(sorted(names)) or "none"
                raise self.error(
                    f"{k}: '{name}' is not {what}; the scene has {have}", "friction", k
                )
            if k == "pins" and isinstance(v, str):  # the friction circle's radius
                out.append((name, (self._circle(v, k, f"{k}.{name}"),)))
                continue
            out.append((name, self._coefficient(k, v, f"{k}.{name}")))
        return tuple(out)


def _did_you_mean(word, choices=_LINK_KEYS) -> str:
    return did_you_mean(word, list(choices))
