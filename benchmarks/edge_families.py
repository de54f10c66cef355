"""Random mechanisms at the edges where an error bound is hardest to keep: each step kind
near each of its singular positions, with the numbers given as a user would give them
(for validating the error bound against the 50-digit reference, ``error_bounds.py``).

Each maker takes a ``random.Random`` and a closeness ``c`` (log-uniform in [1e-3, 1]: the
condition of the step made singular, or for a flat triangle how nearly it closes) and
returns the scene's TOML text. Besides the families of ``near_singular.py``:

* ``flat triangle``: a point carried on a coupler by its distances from the two ends,
  the two adding up to the coupler's length within 1e-16 to 1e-6 of it (or short of it by
  less than the loader's tolerance: the triangle is flattened);
* ``short side``: a plate turned by a dyad acting on a side 10 to 5000 times shorter than
  the plate (a point carried far out on a short coupler), the dyad near a toggle;
* ``hair off round``: a slider crank near its step's dead centre on a path given a hair
  (1e-14 to 1e-8 deg) off a whole number of right angles, in degrees;
* ``far path``: a slider crank near dead centre whose path is given through a point 10 to
  1e5 times the crank's length away along the path;
* ``block then toggle``: a block near its lever's pivot, the lever driving a dyad near a
  toggle (two ill-conditioned steps in a row);
* ``given motion``: a slider crank driven by its piston's speed (and its rate, or the
  crank's acceleration) ~c rad from a dead centre, where the crank's speed found from it
  grows as 1/c;
* ``peg``, ``cylinder``, ``rolling``, ``triad``, ``yoke``: a scene of the kind (from the
  corpus of textbook exercises) with its lengths varied and its crank turned to where the
  kind's steps come nearest to singular, and towards the refusal until their condition is
  near ``c`` (a triad's and a yoke's condition hardly change over a turn: they stay at
  their corpus shapes' values).

:func:`reference_scene` gives the scene as the reference must read it: the decimals of the
text at full precision (lengths, a carried point's distances, a path's angle), and a
given motion's crank speed found by the reference itself.
"""

from __future__ import annotations

import math
import tomllib
from decimal import Decimal
from pathlib import Path

from near_singular import FAMILIES as NEAR, _input, _r, loaded

__all__ = ["FAMILIES", "make", "EDGE_FAMILIES"]

ROOT = Path(__file__).resolve().parent.parent


def flat_triangle(rng, c):
    """A four-bar A(0, 0), D(100, 0) away from its toggles, F on BC by distances, written
    as a user writes them (decimals in mm, rounded when held in metres)."""
    b = Decimal("80.00000000000001") if rng.random() < 0.5 else Decimal(80)
    th = rng.uniform(-math.pi, math.pi)
    d1 = Decimal(f"{rng.uniform(0.05, 0.95) * 80:.12f}")
    # closes within delta of BC: 1e-16 .. 1e-6 of it (c maps 1e-3..1 onto that), or short
    # by less than the loader's tolerance (flattened)
    delta = Decimal(f"{10.0 ** (-16 + 10 * (math.log10(c) + 3) / 3):.3e}")
    if rng.random() < 0.2:
        delta = -delta * Decimal("1e-6")
    d2 = b - d1 + b * delta
    turn = rng.choice(["cw", "ccw"])
    return f"""[ground]
A = [0, 0]
D = [100, 0]
[links]
AB = 30
BC = {b}
CD = 70
[points]
F = {{ on = "BC", distances = {{ B = {d1}, C = {d2} }}, turn = "{turn}" }}
[assembly]
C = "above"
""" + _input(rng, "AB", th)


def short_side(rng, c):
    """A crank AB, a short coupler BC (1 to 10 mm) carrying E far out (10 to 5000 times
    BC), and a rocker CD to D about 100 mm from B, at a transmission angle of sine ~c."""
    a = rng.uniform(20, 50)
    th = rng.uniform(-math.pi, math.pi)
    bx, by = a * math.cos(th), a * math.sin(th)
    s = rng.uniform(1, 10)
    d = 100.0
    ang = math.atan2(by, bx - d)  # direction D -> B, roughly C -> ... from D
    mu = math.asin(c) * rng.choice([1.0, -1.0]) + rng.choice([0.0, math.pi])
    cx, cy = bx + s * math.cos(ang + mu), by + s * math.sin(ang + mu)
    cl = math.hypot(cx - d, cy)
    ratio = 10.0 ** rng.uniform(1, math.log10(5000))
    if rng.random() < 0.5:
        point = f'E = {{ on = "BC", along = {_r(ratio * s)} }}'
    else:
        point = (
            f'E = {{ on = "BC", distances = {{ B = {_r(ratio * s)}, C = '
            f'{_r(ratio * s + s * rng.uniform(-0.9, 0.9))} }}, turn = "ccw" }}'
        )
    return f"""[ground]
A = [0, 0]
D = [{_r(d)}, 0]
[links]
AB = {_r(a)}
BC = {_r(s)}
CD = {_r(cl)}
[points]
{point}
[assembly]
C = [{_r(cx)}, {_r(cy)}]
""" + _input(rng, "AB", th)


def _slider_crank(rng, c, beta_deg, through_shift):
    """An offset slider crank O(0, 0), crank OA, rod AB, B on a path at ``beta_deg``
    through a point ``through_shift`` along the path from B, the rod at sine ~c from
    perpendicular to the path (the step's dead centre)."""
    r = rng.uniform(20, 80)
    ell = r * rng.uniform(1.5, 4.0)
    beta = math.radians(beta_deg)
    ux, uy = math.cos(beta), math.sin(beta)
    th = rng.uniform(-math.pi, math.pi)
    ax, ay = r * math.cos(th), r * math.sin(th)
    g = math.acos(c) * rng.choice([1.0, -1.0]) + rng.choice([0.0, math.pi])
    rx, ry = ux * math.cos(g) - uy * math.sin(g), ux * math.sin(g) + uy * math.cos(g)
    bx, by = ax + ell * rx, ay + ell * ry
    return r, ell, th, (bx, by), (bx + through_shift * ux, by + through_shift * uy)


def hair_off_round(rng, c):
    k = rng.choice([0, 90, 180, 270, -90, 360])
    hair = Decimal(f"{10.0 ** rng.uniform(-14, -8) * rng.choice([1.0, -1.0]):.3e}")
    text_angle = str(Decimal(k) + hair)  # exact decimals: "89.999999999999679"
    r, ell, th, (bx, by), (tx, ty) = _slider_crank(rng, c, float(text_angle), rng.uniform(-50, 50))
    return f"""[ground]
O = [0, 0]
[links]
OA = {_r(r)}
AB = {_r(ell)}
[sliders]
B = {{ path = "{text_angle} deg", through = [{_r(tx)}, {_r(ty)}] }}
[assembly]
B = [{_r(bx)}, {_r(by)}]
""" + _input(rng, "OA", th)


def far_path(rng, c):
    beta = rng.uniform(0, 180)
    r0 = rng.uniform(20, 80)
    shift = r0 * 10.0 ** rng.uniform(1, 5) * rng.choice([1.0, -1.0])
    r, ell, th, (bx, by), (tx, ty) = _slider_crank(rng, c, beta, shift)
    return f"""[ground]
O = [0, 0]
[links]
OA = {_r(r)}
AB = {_r(ell)}
[sliders]
B = {{ path = "{_r(beta)} deg", through = [{_r(tx)}, {_r(ty)}] }}
[assembly]
B = [{_r(bx)}, {_r(by)}]
""" + _input(rng, "OA", th)


def block_then_toggle(rng, c):
    """A crank O2-A, a block A on the lever O4-P (A at ~c of the crank's length from O4),
    P driving a dyad PQ, QR (R on the ground) at a transmission angle of sine ~c too."""
    r = rng.uniform(20, 100)
    L = r * 10.0 ** rng.uniform(-2, 2)  # a lever 0.01 to 100 times the crank
    phi = rng.uniform(-math.pi, math.pi)
    ax, ay = c * r * math.cos(phi), c * r * math.sin(phi)
    th = rng.uniform(-math.pi, math.pi)
    o2 = (ax - r * math.cos(th), ay - r * math.sin(th))
    # the lever's direction O4 -> A
    lx, ly = math.cos(phi), math.sin(phi)
    if rng.random() < 0.5:
        lx, ly = -lx, -ly  # P on the other side of O4 than A
    px, py = L * lx, L * ly
    # the dyad P, Q, R near a toggle: Q nearly on the line P R
    pq = L * rng.uniform(0.3, 2)
    qr = L * rng.uniform(0.3, 2)
    psi = rng.uniform(-math.pi, math.pi)
    qx, qy = px + pq * math.cos(psi), py + pq * math.sin(psi)
    c2 = c * rng.uniform(1.0, 3.0) if rng.random() < 0.5 else 10.0 ** rng.uniform(-3, 0)
    mu = math.asin(min(1.0, c2)) * rng.choice([1.0, -1.0])
    out = psi + mu  # Q -> R nearly along P -> Q (extended)
    rx, ry = qx + qr * math.cos(out), qy + qr * math.sin(out)
    return f"""[ground]
O2 = [{_r(o2[0])}, {_r(o2[1])}]
O4 = [0, 0]
R = [{_r(rx)}, {_r(ry)}]
[links]
"O2-A" = {_r(r)}
"O4-P" = {_r(L)}
"P-Q" = {_r(pq)}
"Q-R" = {_r(qr)}
[sliders]
A = {{ along = "O4-P" }}
[assembly]
P = [{_r(px)}, {_r(py)}]
Q = [{_r(qx)}, {_r(qy)}]
""" + _input(rng, "O2-A", th)


def given_motion(rng, c):
    """An offset slider crank whose motion is given by the piston's speed (and its rate,
    or the crank's acceleration), the crank ~c rad from a dead centre, where the piston's
    speed per unit crank speed vanishes and the crank's speed found from it grows as 1/c."""
    r = rng.uniform(20, 80)
    ell = r * rng.uniform(2.0, 5.0)
    e = rng.uniform(-0.3, 0.3) * r
    # the dead centres: O, A, B in line, B on y = e at |OB| = l + r or l - r
    dead = [math.asin(e / (ell + r)), math.pi - math.asin(e / (ell - r))]
    th = rng.choice(dead) + c * rng.uniform(1, 3) * rng.choice([1.0, -1.0])
    how = rng.choice(["rate", "crank", "steady"])
    vs = rng.uniform(0.5, 5) * rng.choice([1.0, -1.0])
    given = f'vs_B = "{_r(vs)} m/s"\n'
    if how == "rate":
        given += f'as_B = "{_r(rng.uniform(-50, 50))} m/s^2"\n'
    elif how == "crank":
        given += f'acceleration = "{_r(rng.uniform(0, 100))} rad/s^2 ccw"\n'
    return (
        f"""[ground]
O = [0, 0]
[links]
OA = {_r(r)}
AB = {_r(ell)}
[sliders]
B = {{ path = "horizontal", through = [0, {_r(e)}] }}
[assembly]
B = "right"
[input]
crank = "OA"
angle = "{_r(th)} rad"
"""
        + given
    )


# ------------------------------------------------------------------ kinds from the corpus

#: scene files of each newer kind (varied and turned towards a refusal)
KIND_FILES = {
    "peg": [
        "tests/textbook/peg_two_slotted_links.toml",
        "tests/textbook/peg_drives_a_rod.toml",
        "tests/textbook/peg_shaper_lever_slot.toml",
    ],
    "cylinder": ["worked_problems/tipper_cylinder.toml"],
    "rolling": [
        "tests/textbook/rolling_planet_fixed_sun.toml",
        "tests/textbook/rolling_wheel_on_ground.toml",
        "tests/textbook/rolling_gear_train.toml",
        "worked_problems/rolling_wheel_rod_slider.toml",
    ],
    "triad": ["tests/textbook/class3_six_bar.toml", "tests/textbook/class3_triangle_plate.toml"],
    "yoke": ["tests/textbook/scotch_yoke_inclined.toml", "worked_problems/scotch_yoke.toml"],
}


def _strip(text):
    """The scene without its answers (they are not what is measured) and its pins and
    loads (``loaded`` adds its own)."""
    out, skip = [], False
    for line in text.splitlines():
        s = line.strip()
        if s.startswith("["):
            skip = s in ("[answers]", "[pins]", "[loads]", "[variants]")
        if not skip:
            out.append(line)
    return "\n".join(out) + "\n"


def _set_angle(text, deg):
    lines = text.splitlines()
    inside = False
    for i, line in enumerate(lines):
        s = line.strip()
        if s.startswith("["):
            inside = s == "[input]"
        elif inside and s.startswith("angle"):
            lines[i] = f'angle = "{_r(deg)} deg"'
    return "\n".join(lines) + "\n"


def _scale_links(text, rng):
    lines = text.splitlines()
    inside = False
    for i, line in enumerate(lines):
        s = line.strip()
        if s.startswith("["):
            inside = s == "[links]"
        elif inside and "=" in s and not s.startswith("#"):
            key, val = s.split("=", 1)
            try:
                v = float(val.split("#")[0])
            except ValueError:
                continue
            lines[i] = f"{key.strip()} = {_r(v * rng.uniform(0.97, 1.03))}"
    return "\n".join(lines) + "\n"


def _worst(text, kind):
    """The smallest condition among the steps of ``kind`` (or of every step) at the
    scene's own angle; None where it does not solve."""
    from polygon_method.common.errors import PolygonMethodError
    from polygon_method.scene import parse_scene
    from polygon_method.motion.solution import solve

    try:
        sol = solve(parse_scene(text))
    except PolygonMethodError:
        return None
    own = [sol.conditions.get(st.index, 1.0) for st in sol.plan.steps if st.kind == kind]
    return min(own or sol.conditions.values())


def kind_near(files, kind, steps=72):
    """A maker: a scene of ``files`` (lengths varied by 3 %), its crank turned to where the
    steps of ``kind`` come nearest to singular over the turn, and from there
    bisected towards the refusal until their condition is between ``c`` and ``2 c`` (or
    the lowest the turn reaches, where that is above ``c``); ``steps`` angles a turn."""
    pitch = 360.0 / steps

    def maker(rng, c):
        path = ROOT / rng.choice(files)
        base = _strip(path.read_text())
        text = _scale_links(base, rng) if rng.random() < 0.7 else base
        start = rng.uniform(0, pitch)
        grid = [start + pitch * i for i in range(steps)]
        conds = [_worst(_set_angle(text, th), kind) for th in grid]
        ok = [i for i, w in enumerate(conds) if w is not None]
        if not ok:
            return base
        best = min(ok, key=lambda i: conds[i])
        if conds[best] >= c:
            return _set_angle(text, grid[best])
        # a solvable angle above c next to it, then bisect between the two
        up = next((i for i in ok if conds[i] >= c), None)
        if up is None:
            return _set_angle(text, grid[best])
        near = min(
            (i for i in ok if conds[i] >= c),
            key=lambda i: min(abs(i - best), steps - abs(i - best)),
        )
        lo, hi = grid[near], grid[best]
        if abs(lo - hi) > 180:
            hi += 360 if hi < lo else -360
        for _ in range(60):
            mid = (lo + hi) / 2
            w = _worst(_set_angle(text, mid), kind)
            if w is None or w < c:
                hi = mid
            else:
                lo = mid
                if w < 2 * c:
                    break
        return _set_angle(text, lo)

    return maker


EDGE_FAMILIES = {
    "flat triangle": flat_triangle,
    "short side": short_side,
    "given motion": given_motion,
    "hair off round": hair_off_round,
    "far path": far_path,
    "block then toggle": block_then_toggle,
}
# (a triad's solve is slower, and its condition is nearly flat over the turn: 24 angles)
EDGE_FAMILIES.update(
    {k: kind_near(v, k, 24 if k == "triad" else 72) for k, v in KIND_FILES.items()}
)

FAMILIES = dict(NEAR)
FAMILIES.update(EDGE_FAMILIES)

#: families whose own numbers are not reproduced by the loads that ``loaded`` adds
_NO_LOADS = set(KIND_FILES)


def exact_scene(scene, text):
    """``scene`` with the numbers the reference reads replaced by the decimals of
    ``text`` at full precision (mpmath): every link's length, every carried point's
    distances and every fixed path's angle given in degrees, so that the rounding of these
    inputs is part of the error measured (lengths in the scene's unit times its scale)."""
    import dataclasses
    import re

    import mpmath

    t = tomllib.loads(text, parse_float=Decimal)
    exact = {
        "mm": "0.001",
        "cm": "0.01",
        "m": "1",
        "in": "0.0254",
        "inch": "0.0254",
        "inches": "0.0254",
        "ft": "0.3048",
        "feet": "0.3048",
        "foot": "0.3048",
    }
    scale = mpmath.mpf(exact[t.get("units", "mm")])

    def metres(v):
        return mpmath.mpf(str(v)) * scale

    links = tuple(
        dataclasses.replace(lk, length=metres(t["links"][lk.key]))
        if isinstance(t["links"].get(lk.key), (int, Decimal))
        else lk
        for lk in scene.links
    )
    points = []
    for cp in scene.points:
        spec = t.get("points", {}).get(cp.name, {})
        if cp.source and cp.source[0] == "distances":
            _, r1, _, r2, _, turn = cp.source
            d = spec["distances"]
            cp = dataclasses.replace(
                cp, source=("distances", r1, metres(d[r1]), r2, metres(d[r2]), turn)
            )
        points.append(cp)
    sliders = []
    for sl in scene.sliders:
        spec = t.get("sliders", {}).get(getattr(sl, "point", ""), {})
        m = re.fullmatch(r"\s*([-+.\d]+)\s*deg", str(spec.get("path", "")))
        if m and getattr(sl, "angle", None) is not None:
            sl = dataclasses.replace(sl, angle=mpmath.mpf(m.group(1)) * mpmath.pi / 180)
        sliders.append(sl)
    return _Exact(scene, links, tuple(points), tuple(sliders))


def reference_scene(sol, text, ref_mod):
    """The scene the reference solves for ``sol`` made from ``text``: :func:`exact_scene`,
    and where the motion is given on another quantity, the crank's omega and alpha found
    from it by the reference itself (the quantity per unit crank speed, ``Y1``, and its rate
    at a uniform unit speed, ``H``: ``omega = value / Y1``, ``alpha = (rate - omega^2 H) /
    Y1``, or the crank's own alpha where the scene gives it), never the solver's."""
    from polygon_method.scene import parse_scene

    exact = exact_scene(sol.scene, text)
    g = sol.scene.input.given
    if g is None:
        return exact
    own_alpha = parse_scene(text).input.alpha
    mpf = ref_mod.mpf
    with ref_mod.mpmath.workdps(ref_mod.DIGITS):
        unit = _Exact(
            exact, exact.links, exact.points, exact.sliders, _Input(sol.scene.input, mpf(1), mpf(0))
        )
        r1 = ref_mod.reference_solution(unit, sol.P)
        if g.kind == "omega":
            key = sol.scene.link("-".join(g.names)).key
            y1, h = r1["omega"][key], r1["alpha"][key]
        elif g.kind == "vs" and g.names[0] in r1["sliders"]:
            y1, h = r1["sliders"][g.names[0]]["vs"], r1["sliders"][g.names[0]]["as"]
        elif g.kind == "vs":  # a cylinder's rate of extension
            from error_bounds import cylinder_rates

            cyl = sol.scene.cylinder(g.names[0])
            q = cylinder_rates(r1, cyl.barrel, cyl.rod)
            y1, h = q["vs"], q["as"]
        else:
            (vx, vy), (ax, ay), (dx, dy) = (
                r1["velocities"][g.names[0]],
                r1["accelerations"][g.names[0]],
                g.direction,
            )
            y1, h = vx * dx + vy * dy, ax * dx + ay * dy
        w = mpf(g.value) / y1
        al = mpf(own_alpha) if own_alpha is not None else (mpf(g.rate or 0) - w * w * h) / y1
    return _Exact(exact, exact.links, exact.points, exact.sliders, _Input(sol.scene.input, w, al))


class _Input:
    """The crank's input with its omega and alpha at full precision."""

    def __init__(self, inp, omega, alpha):
        self._inp, self.omega, self.alpha = inp, omega, alpha

    def __getattr__(self, name):
        return getattr(self._inp, name)


class _Exact:
    """A scene as the reference reads it, with some of its numbers at full precision
    (the scene's records check their numbers are floats: this stands in front of it)."""

    def __init__(self, scene, links, points, sliders, inp=None):
        self._scene, self.links, self.points, self.sliders = scene, links, points, sliders
        self.input = scene.input if inp is None else inp
        self._by_key = {lk.key: lk for lk in links}

    def __getattr__(self, name):
        return getattr(self._scene, name)

    def link(self, name):
        return self._by_key[self._scene.link(name).key]


def make(family, rng, c, loads=True):
    """The scene text of ``family`` at closeness ``c``, with pins and loads unless not."""
    text = FAMILIES[family](rng, c)
    if loads and family not in _NO_LOADS:
        return loaded(text, rng)
    return text
