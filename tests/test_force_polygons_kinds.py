"""Force polygons of every kind of group the force analysis solves: a triad (a class-III
group: the plate's polygon and each loaded link's; a plate of three links, its sides' too), gears and planets, racks, the driving
wheel, a wheel's centre on a line, the Scotch yoke, a peg in two slots, the slotted lever, a
driving block and a hydraulic cylinder, as well as the dyads, sliders and cranks the sheet
drew before.

Each polygon is held to an independent reference: the matrix method (every moving body's
Newton-Euler equations, D'Alembert's inertia at G, as one linear system in all the unknown
pin, guide, contact and driver forces, solved at 30 digits with mpmath; the bodies, their
pins and the lines of the guides and the teeth written here by hand for each mechanism,
never read from the tool). Every side of every polygon is the force the reference gives
(a pin's, a guide's, a contact's, a driver's; a part along or across a line sums with its
partner to the whole force and is square to it; the inertia forces, weights and loads
from the scene and the kinematics), each polygon sums to zero to 1e-9 of its largest side,
the unknowns' direction lines run along their sides, and the written sheet (SVG) draws
each side at the sheet's force scale to 1e-5 of the paper, on A4.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from polygon_method import load_scene, solve
from polygon_method.scene import parse_scene
from polygon_method.draw import render_pages
from polygon_method.draw.forces import NEGLIGIBLE, polygon_tag
from polygon_method.forces import FRAME, side_label
from test_draw import CM, Svg, vector_length_cm
from test_forces import with_forces
from test_forces_rolling import DEG20, Matrix, _driving_wheel, _gear_contact, _teeth, _with
from test_paper import _centre, _check_page, _said

ROOT = Path(__file__).resolve().parent.parent


class Ref(Matrix):
    """The matrix method, each unknown named by what the polygon calls it: a pin force by
    (point, on, by), a force of unknown size along a line by (what, point, on, by)."""

    def __init__(self, sol, bodies, load_body):
        super().__init__(sol, bodies, load_body)
        self.keys = []  # (column name, what, point, on, by, line or None)

    def pin(self, name, at, on, by, point=None):
        super().pin(name, at, on, by)
        self.keys.append((name, "pin", point or name, on, by, None))

    def along(self, name, at, d, on, by, what=None, point=None):
        super().along(name, at, d, on, by)
        what = what or ("contact" if name.startswith("tooth") else "guide")
        self.keys.append((name, what, point or name, on, by, d))

    def forces(self, x):
        """[(what, point, on, by, vector on `on`)] from the solution ``x``."""
        out = []
        for name, what, point, on, by, d in self.keys:
            if d is None:
                out.append((what, point, on, by, (x[name + ".x"], x[name + ".y"])))
            else:
                out.append((what, point, on, by, (x[name] * d[0], x[name] * d[1])))
        return out


def _unit(a, b):
    d = math.dist(a, b)
    return ((b[0] - a[0]) / d, (b[1] - a[1]) / d)


def _n(a, b):
    u = _unit(a, b)
    return (-u[1], u[0])


# ----- the mechanisms, each with its reference written by hand


def gear_pair():
    sol = solve(load_scene(ROOT / "worked_problems" / "gear_pair_forces.toml"))
    P = sol.P
    keys = {}

    def build():
        mat = Ref(sol, ["O1-A", "O2-B", "BC", "block C"], {"C": "block C", "B": "BC"})
        mat.pin("O1", P["O1"], "O1-A", FRAME)
        mat.pin("O2", P["O2"], "O2-B", FRAME)
        mat.pin("B", P["B"], "BC", "O2-B")
        mat.pin("C", P["C"], "BC", "block C")
        mat.along("N_C", P["C"], (0.0, 1.0), "block C", FRAME, point="C")
        mat.couple("T", "O1-A")
        keys["mat"] = mat
        return mat

    x = _teeth(build, [_gear_contact(sol, "O2", "O1", 0.050, DEG20, "O2-B", "O1-A")])
    return sol, keys["mat"].forces(x)


def planet_on_a_sun():
    sc = _with(
        ROOT / "worked_problems" / "rolling_epicyclic.toml",
        {
            "OA": {"mass": 1, "along": 50},
            "AP": {"mass": 2, "along": 10, "gyration": 30},
            "PQ": {"mass": 1.5, "along": 75, "gyration": 40},
            "Q": {"mass": 3},
        },
        {"Q": {"force": [-200, 50]}, "AP": {"torque": "3 N m cw"}},
    )
    sol = solve(sc)
    P = sol.P
    keys = {}

    def build():
        mat = Ref(sol, ["OA", "AP", "PQ", "block Q"], {"Q": "block Q", "P": "PQ"})
        mat.pin("O", P["O"], "OA", FRAME)
        mat.pin("A", P["A"], "AP", "OA")
        mat.pin("P", P["P"], "PQ", "AP")
        mat.pin("Q", P["Q"], "PQ", "block Q")
        mat.along("N_Q", P["Q"], (0.0, 1.0), "block Q", FRAME, point="Q")
        mat.couple("T", "OA")
        keys["mat"] = mat
        return mat

    x = _teeth(build, [_gear_contact(sol, "A", "O", 0.060, DEG20, "AP", FRAME)])
    return sol, keys["mat"].forces(x)


def two_racks():
    sc = _with(
        ROOT / "tests" / "textbook" / "rolling_pinion_two_racks.toml",
        {
            "OA": {"mass": 1, "along": 0, "gyration": 30},
            "R1": {"mass": 2},
            "R2": {"mass": 3},
            "R1-Q": {"mass": 1, "along": 60, "gyration": 40},
            "DQ": {"mass": 0.5, "along": 40},
        },
        {"R1": {"force": [100, -30]}, "DQ": {"torque": "2 N m ccw"}},
        rolling={"R2": {"pressure_angle": 25}},
    )
    sol = solve(sc)
    P = sol.P
    O = P["O"]
    keys = {}

    def rack(name, phi):
        y = P[name][1]
        m = (0.0, 1.0 if y > O[1] else -1.0)
        return (f"tooth {name}", (O[0], y), (-m[1], m[0]), m, f"block {name}", "OA", phi)

    def build():
        mat = Ref(sol, ["OA", "block R1", "block R2", "R1-Q", "DQ"], {"R1": "block R1"})
        mat.pin("O", O, "OA", FRAME)
        mat.pin("R1", P["R1"], "R1-Q", "block R1")
        mat.pin("Q", P["Q"], "R1-Q", "DQ")
        mat.pin("D", P["D"], "DQ", FRAME)
        for r in ("R1", "R2"):
            mat.along("N_" + r, P[r], (0.0, 1.0), "block " + r, FRAME, point=r)
            mat.couple("C_" + r, "block " + r)
        mat.couple("T", "OA")
        keys["mat"] = mat
        return mat

    x = _teeth(build, [rack("R1", DEG20), rack("R2", math.radians(25))])
    return sol, keys["mat"].forces(x)


def driving_wheel():
    sol = solve(_driving_wheel())
    P = sol.P
    C = P["C"]
    Ip = (C[0], 0.0)
    mat = Ref(sol, ["CA", "AB", "block B"], {"B": "block B", "A": "CA"})
    mat.along("grip", Ip, (1.0, 0.0), "CA", FRAME, what="contact")
    mat.along("push", Ip, (0.0, 1.0), "CA", FRAME, what="contact")
    mat.pin("A", P["A"], "AB", "CA")
    mat.along("N_B", P["B"], (0.0, 1.0), "block B", FRAME, point="B")
    mat.pin("B", P["B"], "AB", "block B")
    mat.couple("tau", "CA")
    return sol, _contact_whole(mat.forces(mat.solve()))


def _contact_whole(forces):
    """The ground's grip and push on a wheel, also as one contact force."""
    parts = [f for f in forces if f[0] == "contact"]
    if len(parts) == 2:
        (_, _, on, by, a), (_, _, _, _, b) = parts
        forces = [f for f in forces if f[0] != "contact"]
        forces.append(("contact", "I", on, by, (a[0] + b[0], a[1] + b[1])))
    return forces


def wheel_centre():
    sol = solve(
        with_forces(load_scene(ROOT / "worked_problems" / "rolling_wheel_rod_slider.toml"), 3)
    )
    P = sol.P
    C = P["C"]
    Ip = (C[0], P["G"][1])  # the wheel touches the ground line through G under its centre
    mat = Ref(sol, ["OA", "AC", "CP", "PQ", "block Q"], {"Q": "block Q", "A": "OA", "P": "CP"})
    mat.pin("O", P["O"], "OA", FRAME)
    mat.pin("A", P["A"], "AC", "OA")
    mat.pin("C", C, "AC", "CP")
    mat.pin("P", P["P"], "PQ", "CP")
    mat.pin("Q", P["Q"], "PQ", "block Q")
    mat.along("N_Q", P["Q"], (0.0, 1.0), "block Q", FRAME, point="Q")
    mat.along("grip", Ip, (1.0, 0.0), "CP", FRAME, what="contact")
    mat.along("push", Ip, (0.0, 1.0), "CP", FRAME, what="contact")
    mat.couple("T", "OA")
    return sol, _contact_whole(mat.forces(mat.solve()))


def scotch_yoke():
    sol = solve(with_forces(load_scene(ROOT / "worked_problems" / "scotch_yoke.toml"), 3))
    P = sol.P
    mat = Ref(sol, ["OP", "block Y", "block P"], {"P": "OP", "Y": "block Y"})  # P: the crank's tip
    mat.pin("O", P["O"], "OP", FRAME)
    mat.pin("P", P["P"], "block P", "OP")
    mat.along("N_Y", P["Y"], (0.0, 1.0), "block Y", FRAME, point="Y")  # the path's
    mat.along("N_P", P["P"], (1.0, 0.0), "block P", "block Y", point="P")  # the slot's
    mat.couple("C_Y", "block Y")
    mat.couple("T", "OP")
    return sol, mat.forces(mat.solve())


def peg_in_two_slots():
    sc = with_forces(load_scene(ROOT / "tests" / "textbook" / "peg_two_slotted_links.toml"), 3)
    sol = solve(sc)
    P = sol.P
    mat = Ref(sol, ["AB", "BC", "CD", "block P"], {"P": "block P", "B": "AB", "C": "BC"})
    mat.pin("A", P["A"], "AB", FRAME)
    mat.pin("B", P["B"], "BC", "AB")
    mat.pin("C", P["C"], "BC", "CD")
    mat.pin("D", P["D"], "CD", FRAME)
    mat.along("N_AB", P["P"], _n(P["A"], P["B"]), "block P", "AB", point="P")
    mat.along("N_CD", P["P"], _n(P["C"], P["D"]), "block P", "CD", point="P")
    mat.couple("T", "AB")
    return sol, mat.forces(mat.solve())


def slotted_lever():
    sc = with_forces(load_scene(ROOT / "worked_problems" / "crank_slotted_lever.toml"), 3)
    sol = solve(sc)
    P = sol.P
    mat = Ref(
        sol,
        ["O2-A", "block A", "O4-P", "P-Q", "block Q"],
        {"A": "O2-A", "P": "O4-P", "Q": "block Q"},
    )
    mat.pin("O2", P["O2"], "O2-A", FRAME)
    mat.pin("A", P["A"], "block A", "O2-A")
    mat.along("N_A", P["A"], _n(P["O4"], P["P"]), "block A", "O4-P", point="A")
    mat.pin("O4", P["O4"], "O4-P", FRAME)
    mat.pin("P", P["P"], "P-Q", "O4-P")
    mat.pin("Q", P["Q"], "P-Q", "block Q")
    mat.along("N_Q", P["Q"], (0.0, 1.0), "block Q", FRAME, point="Q")
    mat.couple("T", "O2-A")
    return sol, mat.forces(mat.solve())


def driving_block():
    sol = solve(with_forces(load_scene(ROOT / "worked_problems" / "ellipse_trammel.toml"), 3))
    P = sol.P
    mat = Ref(sol, ["block A", "AB", "block B"], {"A": "block A", "B": "block B", "C": "AB"})
    mat.pin("A", P["A"], "AB", "block A")
    mat.pin("B", P["B"], "AB", "block B")
    mat.along("N_A", P["A"], (0.0, 1.0), "block A", FRAME, point="A")
    mat.along("N_B", P["B"], (-1.0, 0.0), "block B", FRAME, point="B")
    mat.along("F_A", P["A"], (1.0, 0.0), "block A", FRAME, what="driver", point="A")
    return sol, mat.forces(mat.solve())


def cylinder():
    """The tipper raised by its cylinder: the cylinder pushes the body at R along O -> R,
    the frame at O back; the crank QR is not driven."""
    sol = solve(with_forces(load_scene(ROOT / "worked_problems" / "tipper_cylinder.toml"), 3))
    P = sol.P
    u = _unit(P["O"], P["R"])
    mat = Ref(sol, ["QR"], {"R": "QR", "G": "QR"})
    mat.pin("Q", P["Q"], "QR", FRAME)
    mat.along("F", P["R"], u, "QR", "O-R", what="pin", point="R")
    x = mat.solve()
    out = mat.forces(x)
    out.append(("pin", "O", "O-R", FRAME, (x["F"] * u[0], x["F"] * u[1])))  # its other end
    return sol, out


TRIAD = """
title = "Class-III six-bar (plate BCD on AB, EC, FD), with masses"
units = "mm"
[ground]
O = [0, 0]
E = [70, 213]
F = [235, -17]
[links]
OA = 20
AB = 110
BC = 78
EC = 122
FD = 101
[points]
D = { on = "BC", distances = { B = 73, C = 71 }, turn = "cw" }
[assembly]
B = [80, 60]
[input]
crank = "OA"
angle = 150
speed = "240 rpm ccw"
[gravity]
direction = 250
"""


def _triad(sc):
    sol = solve(sc)
    P = sol.P
    mat = Ref(sol, ["OA", "AB", "BC", "EC", "FD"], {"A": "OA", "B": "BC", "C": "BC", "D": "BC"})
    mat.pin("O", P["O"], "OA", FRAME)
    mat.pin("A", P["A"], "AB", "OA")
    mat.pin("B", P["B"], "AB", "BC")
    mat.pin("C", P["C"], "EC", "BC")
    mat.pin("D", P["D"], "FD", "BC")
    mat.pin("E", P["E"], "EC", FRAME)
    mat.pin("F", P["F"], "FD", FRAME)
    mat.couple("T", "OA")
    return sol, mat.forces(mat.solve())


def triad():
    """A class-III group (worked_problems/class3_six_bar_forces.toml): the plate and AB, EC
    massive (their centres off the links), FD carrying a couple only, a load at the
    plate's corner D."""
    return _triad(load_scene(ROOT / "worked_problems" / "class3_six_bar_forces.toml"))


def triad_two_force_links():
    """EC and FD carrying nothing (two-force members: their forces along their lines, no
    polygon of their own), the plate and AB massive, a load and a couple on the plate."""
    return _triad(
        parse_scene(
            TRIAD + "[masses]\n"
            'BC = { mass = 4, distances = { B = 30, C = 55 }, turn = "ccw", gyration = 35 }\n'
            "AB = { mass = 1, along = 55 }\n"
            '[loads]\nC = { force = [40, -90] }\nBC = { torque = "1.5 N m ccw" }\n'
        )
    )


def _three_links(text):
    from test_triad_three_links import PINS

    sol = solve(parse_scene(text))
    P = sol.P
    mat = Ref(sol, ["OA", "AB", "BC", "CD", "DB", "EC", "FD"], {"C": "BC", "D": "CD"})
    for point, on, by in PINS:  # (two pins at each corner: one per pair of bodies)
        mat.pin(f"{point} {on} {by}", P[point], on, by, point=point)
    mat.couple("T", "OA")
    return sol, mat.forces(mat.solve())


def triad_three_links():
    """A class-III group whose plate is three links (BC, CD, DB pinned in a triangle, hung
    from AB, EC, FD): every body massive, gravity, loads at C and D, a couple on CD
    (tests/test_triad_three_links.py's scene at 110 deg). Its polygons: the triangle's as
    one plate, each hanging link's, the sides BC and CD as a dyad about C, and DB's."""
    from test_triad_three_links import scene_text

    return _three_links(scene_text(110.0))


def triad_three_links_bare_side():
    """The same with the third side DB carrying nothing (a two-force member between B and
    D: its two forces equal and opposite along it, no polygon of its own), nor the rockers."""
    from test_triad_three_links import ROOT as TOP

    text = (TOP / "tests" / "textbook" / "class3_triangle_plate.toml").read_text()
    return _three_links(
        text.replace("angle = 30", "angle = 250") + "[masses]\n"
        "AB = { mass = 1.1, along = 55, gyration = 35 }\n"
        'BC = { mass = 0.8, distances = { B = 45, C = 45 }, turn = "ccw", gyration = 25 }\n'
        "CD = { mass = 0.7, along = 35, gyration = 22 }\n"
        "[loads]\nC = { force = [15, -40] }\nD = { force = [-10, 5] }\n"
    )


CASES = [
    triad,
    triad_two_force_links,
    triad_three_links,
    triad_three_links_bare_side,
    gear_pair,
    planet_on_a_sun,
    two_racks,
    driving_wheel,
    wheel_centre,
    scotch_yoke,
    peg_in_two_slots,
    slotted_lever,
    driving_block,
    cylinder,
]
_SOLVED = {}


def _case(fn):
    if fn not in _SOLVED:
        _SOLVED[fn] = fn()
    return _SOLVED[fn]


def _reference(forces, side):
    """The reference's force on ``side.on`` by ``side.by`` of the side's kind (at its point
    where two bodies meet at more than one), or None."""
    for what, point, on, by, v in forces:
        if what != side.what or (what != "contact" and point != side.point):
            continue
        if (on, by) == (side.on, side.by):
            return v
        if (on, by) == (side.by, side.on):
            return (-v[0], -v[1])
    return None


def _known(sol, side):
    """An inertia force, a weight or a load from the scene and the kinematics."""
    sc = sol.scene
    if side.what in ("load", "gas"):
        return next(ld.force for ld in sc.loads if ld.target == side.point)
    m = next(m for m in sc.masses if (f"block {m.body}" if m.block else m.body) == side.on)
    if side.what == "weight":
        g = sc.gravity
        return (m.mass * g.g * g.direction[0], m.mass * g.g * g.direction[1])
    if m.block:
        a = sol.A[m.body]
    else:
        lk = sc.link(m.body)
        (px, py), (qx, qy) = sol.A[lk.p], sol.A[lk.q]
        a = (px + m.lam * (qx - px) - m.mu * (qy - py), py + m.lam * (qy - py) + m.mu * (qx - px))
    return (-m.mass * a[0], -m.mass * a[1])


@pytest.mark.parametrize("case", CASES, ids=[c.__name__ for c in CASES])
def test_each_polygon_side_is_the_reference_force_and_each_polygon_closes(case):
    sol, forces = _case(case)
    f = sol.forces
    kinds = set()
    for st, pg in ((st, pg) for st in f.steps for pg in st.polygons):
        sides = pg.polygon
        assert sides, (st.kind, st.title)  # every group has its polygon now
        kinds.add(st.kind)
        big = max(math.hypot(*s.vector) for s in sides)
        sx = sum(s.vector[0] for s in sides)
        sy = sum(s.vector[1] for s in sides)
        assert math.hypot(sx, sy) <= 1e-9 * big, st.title  # closed
        scale = max(big, max(math.hypot(*v[4]) for v in forces))
        for k, s in enumerate(sides):
            name = side_label(s, f.numbers, unicode=False)
            if s.what in ("inertia", "weight", "load", "gas"):
                want = _known(sol, s)
            else:
                want = _reference(forces, s)
                assert want is not None, (st.title, name)
                if s.part:  # a part: with its partner, the whole force; square to it
                    other = next(
                        o
                        for o in sides
                        if o is not s
                        and (o.what, o.on, o.by, o.point) == (s.what, s.on, s.by, s.point)
                    )
                    assert {s.part, other.part} == {"n", "t"}
                    dot = s.vector[0] * other.vector[0] + s.vector[1] * other.vector[1]
                    assert abs(dot) <= 1e-9 * scale * scale
                    want = (want[0] - other.vector[0], want[1] - other.vector[1])
            assert math.dist(s.vector, want) <= 1e-9 * scale, (st.title, name, s.vector, want)
        # the unknowns' direction lines run along their sides
        for k, u in pg.unknown:
            v = sides[k].vector
            assert abs(u[0] * v[1] - u[1] * v[0]) <= 1e-9 * scale, (st.title, k)
        # the whole forces read across it
        corners = [(0.0, 0.0)]
        for s in sides:
            corners.append((corners[-1][0] + s.vector[0], corners[-1][1] + s.vector[1]))
        for c, i, j in pg.chords:
            vec = (corners[j][0] - corners[i][0], corners[j][1] - corners[i][1])
            assert math.dist(vec, c.vector) <= 1e-9 * scale
            want = _reference(forces, c)
            if want is not None:
                assert math.dist(c.vector, want) <= 1e-9 * scale, (st.title, c)
    assert kinds


_SHEETS = {}


def _sheet(case):
    if case not in _SHEETS:
        sol, _ = _case(case)
        datas, used, _, pages = render_pages(sol, "svg", "forces", paper="A4")
        _SHEETS[case] = sol, [Svg(d) for d in datas], used, pages
    return _SHEETS[case]


@pytest.mark.parametrize("case", CASES, ids=[c.__name__ for c in CASES])
def test_the_sheet_draws_each_polygon_at_its_scale_on_a4(case):
    sol, svgs, used, pages = _sheet(case)
    f = sol.forces
    fs = used["force polygons"]
    tol = 1e-5 * max(max(p.size) for p in pages)
    polys = [(polygon_tag(st, n), pg) for st in f.steps for n, pg in enumerate(st.polygons)]
    big = max(math.hypot(*s.vector) for _, pg in polys for s in pg.polygon)
    drawn = 0
    for tag, st in polys:  # (each polygon of each step, read as the step's first was)
        svg = next((s for s in svgs if f"{tag}-pole" in s.groups), None)
        nonzero = [math.hypot(*s.vector) > NEGLIGIBLE * big for s in st.polygon]
        if svg is None:  # two opposite forces (a massless crank, a cylinder): no polygon
            assert sum(nonzero) < 3
            continue
        drawn += 1
        assert _said(svg, f"note-{tag}-scale") == fs.text.replace(" ", "")
        total = [0.0, 0.0]
        for k, side in enumerate(st.polygon):
            if not nonzero[k]:
                continue
            _, (dx, dy) = vector_length_cm(svg, f"{tag}-side-{k}")
            assert dx * fs.per_cm == pytest.approx(side.vector[0], abs=tol * fs.per_cm)
            assert dy * fs.per_cm == pytest.approx(side.vector[1], abs=tol * fs.per_cm)
            total[0] += dx
            total[1] += dy
        assert math.hypot(*total) < tol * len(st.polygon)
        # each direction line passes through both ends of its side
        for k, _ in st.unknown:
            if not nonzero[k]:
                continue
            (x1, y1), (x2, y2) = svg.path(f"{tag}-line-{k}")[:2]
            tail = svg.path(f"{tag}-side-{k}-shaft")[0]
            tip = svg.path(f"{tag}-side-{k}-head")[0]
            for px, py in (tail, tip):
                d = abs((x2 - x1) * (py - y1) - (y2 - y1) * (px - x1)) / math.hypot(
                    x2 - x1, y2 - y1
                )
                assert d / CM < tol * 10 + 0.02  # (the head's tip, drawn to the corner)
        assert _centre(svg, f"{tag}-pole") is not None
    assert drawn >= 1
    for svg, page in zip(svgs, pages):
        _check_page(svg, page, "A4")
