"""Forces on rolling wheels, gears, racks and the driving wheel, against independent
references.

- the matrix method: every moving body's Newton-Euler equations (D'Alembert: the forces and
  their moments about the origin, with the inertia force -m a_G and couple -I alpha) as one
  linear system in all the unknowns at once (the pin forces, the guides' normal forces and
  couples, the driver's torque, and each gear's tooth load as one unknown along its line of
  action), solved together at 30 digits with mpmath. The bodies, which body is pinned to
  which and the lines of action are written here by hand for each mechanism, not read from
  the tool. The tooth load's line leans so that the teeth push apart, which depends on the
  sense of the load: each sense is solved and the one that agrees with itself kept.
- the virtual-power balance with inertia (every rolling scene given masses, in
  ``tests/test_forces.py``, which now covers these kinds), and here on the worked problem.

G's acceleration is computed from the links' end points (a point fixed on a rigid link),
as in ``tests/test_forces.py``.
"""

from __future__ import annotations

import json
import math
import re
from pathlib import Path

import mpmath
import pytest

from polygon_method.common.errors import PolygonMethodError, SceneError
from polygon_method.forces import FRAME

from newton_euler import NewtonEuler
from polygon_method.motion.solution import solve
from polygon_method.scene import load_scene, parse_scene, scene_from_table, scene_table

ROOT = Path(__file__).resolve().parent.parent
WORKED = ROOT / "worked_problems" / "gear_pair_forces.toml"
DEG20 = math.radians(20.0)


@pytest.fixture(autouse=True)
def _precision():
    dps = mpmath.mp.dps
    yield
    mpmath.mp.dps = dps


def _kin(sol, m):
    """(G, a_G, alpha) of a mass's body from its link's ends (or its block)."""
    if m.block:
        return sol.P[m.body], sol.A[m.body], 0.0
    lk = sol.scene.link(m.body)

    def at(T):
        (px, py), (qx, qy) = T[lk.p], T[lk.q]
        dx, dy = qx - px, qy - py
        return (px + m.lam * dx - m.mu * dy, py + m.lam * dy + m.mu * dx)

    return at(sol.P), at(sol.A), sol.Al[lk.key]


def _unit(v):
    n = math.hypot(*v)
    return (v[0] / n, v[1] / n)


class Matrix(NewtonEuler):
    """The matrix method (``newton_euler.NewtonEuler``) on a solved scene: its bodies, the
    unknowns added one by one; then the inertia, the weights and the loads read from the
    scene's masses and loads (``load_body``: point -> the body a load there acts on), and
    every moving body's three equations solved at once at 30 digits. A block's moments are
    taken about its own point (all its pins' forces pass through it)."""

    def __init__(self, sol, bodies, load_body):
        about = {b: sol.P[b[6:]] for b in bodies if b.startswith("block ")}
        super().__init__(bodies, about=about, mp=True)
        self.sol, self.load_body = sol, load_body

    def couple(self, name, on, by=FRAME):
        """A couple of unknown size on ``on``, its opposite on ``by`` (the frame)."""
        super().couple(name, on, by)

    def add_known(self):
        """The inertia, the weights and the loads on the known side."""
        sol, sc = self.sol, self.sol.scene
        g = sc.gravity
        for m in sc.masses:
            G, a, al = _kin(sol, m)
            body = f"block {m.body}" if m.block else m.body
            F = (-m.mass * a[0], -m.mass * a[1])
            if g is not None:
                F = (F[0] + m.mass * g.g * g.direction[0], F[1] + m.mass * g.g * g.direction[1])
            self.known(body, F, G, -m.inertia * al)
        for ld in sc.loads:
            if ld.force is not None:
                self.known(self.load_body[ld.target], ld.force, sol.P[ld.target])
            else:
                self.known(ld.target, c=ld.torque)

    def solve(self):
        """name -> value (30 digits, as floats)."""
        mpmath.mp.dps = 30
        self.add_known()
        return {k: float(v) for k, v in super().solve().items()}


def _teeth(build, contacts):
    """Solve the matrix method with each tooth load's line leaning each way (``contacts``:
    (name, point, t, m) per tooth contact, the load ``T (t + s tan phi m)`` on the driven
    body), keeping the choice whose loads agree with their lean; name -> value, with each
    contact's force vector under ``name + ".F"``."""
    import itertools

    for signs in itertools.product((1, -1), repeat=len(contacts)):
        mat = build()
        dirs = {}
        for (name, at, t, m, on, by, phi), s in zip(contacts, signs):
            d = (t[0] + s * math.tan(phi) * m[0], t[1] + s * math.tan(phi) * m[1])
            mat.along(name, at, d, on, by)
            dirs[name] = (d, s)
        x = mat.solve()
        if all(x[n] * s > 0 for n, (d, s) in dirs.items()):
            for n, (d, s) in dirs.items():
                x[n + ".F"] = (x[n] * d[0], x[n] * d[1])
            return x
    raise AssertionError("no lean of the tooth loads agrees with itself")


def _gear_contact(sol, wheel_centre, base_centre, R, phi, on, by, inside=False):
    """(name, I, t, m, on, by, phi) of a tooth contact: m from the pitch point towards the
    wheel's centre, t = perp(m)."""
    C, O = sol.P[wheel_centre], sol.P[base_centre]
    u = _unit((C[0] - O[0], C[1] - O[1]))
    I = (O[0] + R * u[0], O[1] + R * u[1])
    m = (-u[0], -u[1]) if inside else u
    return ("tooth " + on, I, (-m[1], m[0]), m, on, by, phi)


def _close(got, want, scale):
    assert math.hypot(got[0] - want[0], got[1] - want[1]) <= 1e-9 * scale, (got, want)


# ----- a gear pair driving a slider (the worked problem)


def _gear_pair_matrix(sol):
    sc = sol.scene
    P = sol.P
    phi = sc.rolling[0].pressure_angle
    phi = DEG20 if phi is None else phi

    def build():
        mat = Matrix(sol, ["O1-A", "O2-B", "BC", "block C"], {"C": "block C", "B": "BC"})
        mat.pin("O1", P["O1"], "O1-A", FRAME)
        mat.pin("O2", P["O2"], "O2-B", FRAME)
        mat.pin("B", P["B"], "BC", "O2-B")
        mat.pin("C", P["C"], "BC", "block C")
        mat.along("N_C", P["C"], (0.0, 1.0), "block C", FRAME)
        mat.couple("T", "O1-A")
        return mat

    return _teeth(build, [_gear_contact(sol, "O2", "O1", 0.050, phi, "O2-B", "O1-A")])


def test_the_gear_pair_against_the_matrix_method():
    sol = solve(load_scene(WORKED))
    f = sol.forces
    x = _gear_pair_matrix(sol)
    scale = max(math.hypot(x[k + ".x"], x[k + ".y"]) for k in ("O1", "O2", "B", "C"))
    for k, on, by in (
        ("O1", "O1-A", FRAME),
        ("O2", "O2-B", FRAME),
        ("B", "BC", "O2-B"),
        ("C", "BC", "block C"),
    ):
        _close(f.pin(k, on, by), (x[k + ".x"], x[k + ".y"]), scale)
    (c,) = f.contacts
    assert c.wheel == "O2-B" and c.by == "O1-A" and c.stated
    _close(c.force, x["tooth O2-B.F"], scale)
    assert abs(c.load - abs(x["tooth O2-B"]) * math.hypot(1, math.tan(DEG20))) <= 1e-9 * scale
    assert abs(f.input_torque - x["T"]) <= 1e-9 * scale * 0.125
    (g,) = f.guides
    assert abs(g.normal - x["N_C"]) <= 1e-9 * scale


def test_the_worked_gear_pair_and_its_written_answers():
    """The numbers the worked problem writes (comments and [answers]) against the matrix
    method, to their four figures; and `check` holds its answers."""
    from polygon_method.check import check_answers

    sol = solve(load_scene(WORKED))
    x = _gear_pair_matrix(sol)
    text = WORKED.read_text()
    want = {
        "F_O2": math.hypot(x["O2.x"], x["O2.y"]),
        "F_B": math.hypot(x["B.x"], x["B.y"]),
        "F_C": math.hypot(x["C.x"], x["C.y"]),
        "N_C": abs(x["N_C"]),
        "Fc": math.hypot(*x["tooth O2-B.F"]),
        "T": abs(x["T"]),
    }
    for key, v in want.items():
        written = re.search(rf"#.*\b{key} = ([\d.]+)", text)
        assert float(written.group(1)) == pytest.approx(v, rel=6e-4), key
    assert re.search(r"#.*\bT = [\d.]+ \((c?cw)\)", text).group(1) == (
        "ccw" if x["T"] > 0 else "cw"
    )
    verdicts = check_answers(sol)
    assert verdicts and all(v.ok for v in verdicts), [(v.key, v.ok) for v in verdicts]
    assert {v.key for v in verdicts} >= {"Fc_O2-B", "F_B", "N_C", "torque"}


# ----- a planet on a fixed sun (the teeth's angle stated), Watt's sun and planet (a gear
# fixed to a moving link), a pinion between two racks


def _with(path, masses, loads=None, gravity=True, rolling=None, answers=None):
    raw = scene_table(load_scene(path))
    raw.pop("answers", None)
    raw["masses"] = masses
    if gravity:
        raw["gravity"] = {"direction": 250}
    if loads:
        raw["loads"] = loads
    for key, extra in (rolling or {}).items():
        raw["rolling"][key] = {**raw["rolling"][key], **extra}
    if answers:
        raw["answers"] = answers
    return scene_from_table(raw)


@pytest.mark.parametrize("phi", [None, 14.5])
def test_a_planet_on_a_fixed_sun_against_the_matrix_method(phi):
    sc = _with(
        ROOT / "worked_problems" / "rolling_epicyclic.toml",
        {
            "OA": {"mass": 1, "along": 50},
            "AP": {"mass": 2, "along": 10, "gyration": 30},
            "PQ": {"mass": 1.5, "along": 75, "gyration": 40},
            "Q": {"mass": 3},
        },
        {"Q": {"force": [-200, 50]}, "AP": {"torque": "3 N m cw"}},
        rolling=None if phi is None else {"AP": {"pressure_angle": phi}},
    )
    sol = solve(sc)
    f = sol.forces
    P = sol.P
    angle = DEG20 if phi is None else math.radians(phi)

    def build():
        mat = Matrix(sol, ["OA", "AP", "PQ", "block Q"], {"Q": "block Q", "P": "PQ"})
        mat.pin("O", P["O"], "OA", FRAME)
        mat.pin("A", P["A"], "AP", "OA")
        mat.pin("P", P["P"], "PQ", "AP")
        mat.pin("Q", P["Q"], "PQ", "block Q")
        mat.along("N_Q", P["Q"], (0.0, 1.0), "block Q", FRAME)
        mat.couple("T", "OA")
        return mat

    x = _teeth(build, [_gear_contact(sol, "A", "O", 0.060, angle, "AP", FRAME)])
    scale = max(math.hypot(x[k + ".x"], x[k + ".y"]) for k in ("O", "A", "P", "Q"))
    for k, on, by in (
        ("O", "OA", FRAME),
        ("A", "AP", "OA"),
        ("P", "PQ", "AP"),
        ("Q", "PQ", "block Q"),
    ):
        _close(f.pin(k, on, by), (x[k + ".x"], x[k + ".y"]), scale)
    (c,) = f.contacts
    assert c.by == FRAME and c.stated == (phi is not None)
    _close(c.force, x["tooth AP.F"], scale)
    assert abs(f.input_torque - x["T"]) <= 1e-9 * scale * 0.1
    # the load's line: at the pressure angle to the common tangent, the teeth pushing apart
    assert c.normal >= 0 and abs(math.atan2(c.normal, abs(c.tangential)) - angle) <= 1e-12


def test_watts_sun_and_planet_against_the_matrix_method():
    """The planet fixed to the rod CB drives the sun OS about O: the sun's tooth load acts
    on the rod, which a dyad (the rod and the beam) carries on to the crank OC."""
    sc = _with(
        ROOT / "worked_problems" / "sun_and_planet_watt.toml",
        {
            "OC": {"mass": 5, "along": 300},
            "CB": {"mass": 40, "along": 1200, "gyration": 700},
            "BD": {"mass": 30, "along": 1000, "gyration": 600},
            "OS": {"mass": 20, "along": 0, "gyration": 250},
        },
        {"OS": {"torque": "400 N m cw"}},
    )
    sol = solve(sc)
    f = sol.forces
    P = sol.P

    def build():
        mat = Matrix(sol, ["OC", "CB", "BD", "OS"], {})
        mat.pin("O", P["O"], "OC", FRAME)
        mat.pin("C", P["C"], "CB", "OC")
        mat.pin("B", P["B"], "BD", "CB")
        mat.pin("D", P["D"], "BD", FRAME)
        mat.pin("OS", P["O"], "OS", FRAME)
        mat.couple("T", "OC")
        return mat

    x = _teeth(build, [_gear_contact(sol, "O", "C", 0.300, DEG20, "OS", "CB")])
    scale = max(math.hypot(x[k + ".x"], x[k + ".y"]) for k in ("O", "C", "B", "D", "OS"))
    _close(f.pin("O", "OC", FRAME), (x["O.x"], x["O.y"]), scale)
    _close(f.pin("C", "CB", "OC"), (x["C.x"], x["C.y"]), scale)
    _close(f.pin("B", "BD", "CB"), (x["B.x"], x["B.y"]), scale)
    _close(f.pin("D", "BD", FRAME), (x["D.x"], x["D.y"]), scale)
    _close(f.pin("O", "OS", FRAME), (x["OS.x"], x["OS.y"]), scale)
    (c,) = f.contacts
    assert (c.wheel, c.by) == ("OS", "CB")
    _close(c.force, x["tooth OS.F"], scale)
    assert abs(f.input_torque - x["T"]) <= 1e-9 * scale * 0.6


def test_a_pinion_between_two_racks_against_the_matrix_method():
    """Each rack is held by its guide (a normal force and a couple: the tooth load acts off
    the rack's point) and pushed by the pinion's teeth at its pitch point."""
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
    f = sol.forces
    P = sol.P
    O = P["O"]

    def rack(name, point, phi):
        y = point[1]
        m = (0.0, 1.0 if y > O[1] else -1.0)  # from the pinion's centre out to the rack
        return (f"tooth {name}", (O[0], y), (-m[1], m[0]), m, f"block {name}", "OA", phi)

    def build():
        mat = Matrix(sol, ["OA", "block R1", "block R2", "R1-Q", "DQ"], {"R1": "block R1"})
        mat.pin("O", O, "OA", FRAME)
        mat.pin("R1", P["R1"], "R1-Q", "block R1")
        mat.pin("Q", P["Q"], "R1-Q", "DQ")
        mat.pin("D", P["D"], "DQ", FRAME)
        for r in ("R1", "R2"):
            mat.along("N_" + r, P[r], (0.0, 1.0), "block " + r, FRAME)
            mat.couple("C_" + r, "block " + r)
        mat.couple("T", "OA")
        return mat

    x = _teeth(build, [rack("R1", P["R1"], DEG20), rack("R2", P["R2"], math.radians(25))])
    scale = max(math.hypot(x[k + ".x"], x[k + ".y"]) for k in ("O", "R1", "Q", "D"))
    _close(f.pin("O", "OA", FRAME), (x["O.x"], x["O.y"]), scale)
    _close(f.pin("R1", "R1-Q", "block R1"), (x["R1.x"], x["R1.y"]), scale)
    _close(f.pin("Q", "R1-Q", "DQ"), (x["Q.x"], x["Q.y"]), scale)
    _close(f.pin("D", "DQ", FRAME), (x["D.x"], x["D.y"]), scale)
    guides = {g.point: g for g in f.guides}
    contacts = {c.wheel: c for c in f.contacts}
    for r in ("R1", "R2"):
        assert abs(guides[r].normal - x["N_" + r]) <= 1e-9 * scale
        assert abs(guides[r].couple - x["C_" + r]) <= 1e-9 * scale * 0.1
        _close(contacts["block " + r].force, x[f"tooth {r}.F"], scale)
        assert contacts["block " + r].by == "OA"
    assert abs(f.input_torque - x["T"]) <= 1e-9 * scale * 0.1


# ----- the driving wheel


def _driving_wheel(extra=""):
    text = (ROOT / "worked_problems" / "rolling_wheel_driver.toml").read_text()
    text = (
        text.split("[answers]")[0]
        + """
[masses]
CA = { mass = "20 kg", distances = { C = 60, A = 280 }, turn = "ccw", gyration = 212 }
AB = { mass = "5 kg", along = 600, gyration = 350 }
B = { mass = "10 kg" }
[gravity]
direction = 260
[loads]
B = { force = [-300, 40] }
A = { force = [0, -50] }
"""
        + extra
    )
    return parse_scene(text)


def _wheel_matrix(sol, effort):
    """The wheel, the rod and the block; the ground's contact as two unknowns; the driver's
    effort a torque on the wheel, or (``effort == "force"``) a force at its centre along the
    ground."""
    P = sol.P
    C = P["C"]
    I = (C[0], 0.0)
    mat = Matrix(sol, ["CA", "AB", "block B"], {"B": "block B", "A": "CA"})  # (as the docs)
    mat.pin("I", I, "CA", FRAME)
    mat.pin("A", P["A"], "AB", "CA")
    mat.along("N_B", P["B"], (0.0, 1.0), "block B", FRAME)
    mat.pin("B", P["B"], "AB", "block B")
    if effort == "torque":
        mat.couple("tau", "CA")
    else:
        mat.along("F", C, (1.0, 0.0), "CA", FRAME)
    return mat.solve()


def test_the_driving_wheel_against_the_matrix_method():
    """The torque on the driving wheel, the ground's grip and push and the pin forces; the
    same effort as a force at its centre (a second matrix solve with that force instead of
    the torque) is tau / r, the pin forces unchanged."""
    sol = solve(_driving_wheel())
    f = sol.forces
    x = _wheel_matrix(sol, "torque")
    scale = max(math.hypot(x[k + ".x"], x[k + ".y"]) for k in ("I", "A", "B"))
    assert f.driver == "wheel" and f.crank == "CA"
    assert abs(f.input_torque - x["tau"]) <= 1e-9 * scale * 0.3
    (c,) = f.contacts
    _close(c.force, (x["I.x"], x["I.y"]), scale)
    _close(f.pin("A", "AB", "CA"), (x["A.x"], x["A.y"]), scale)
    _close(f.pin("B", "AB", "block B"), (x["B.x"], x["B.y"]), scale)
    y = _wheel_matrix(sol, "force")
    _close(f.centre_force, (y["F"], 0.0), scale)
    _close(f.pin("A", "AB", "CA"), (y["A.x"], y["A.y"]), scale)
    # the power balance with inertia, written out: the torque's power tau omega
    sc = sol.scene
    terms = [f.input_torque * sol.W["CA"]]
    for ld in sc.loads:
        terms.append(ld.force[0] * sol.V[ld.target][0] + ld.force[1] * sol.V[ld.target][1])
    for m in sc.masses:
        lk = None if m.block else sc.link(m.body)

        def at(T, m=m, lk=lk):
            if lk is None:
                return T[m.body]
            (px, py), (qx, qy) = T[lk.p], T[lk.q]
            return (
                px + m.lam * (qx - px) - m.mu * (qy - py),
                py + m.lam * (qy - py) + m.mu * (qx - px),
            )

        v, a = at(sol.V), at(sol.A)
        g = sc.gravity
        terms.append(m.mass * g.g * (g.direction[0] * v[0] + g.direction[1] * v[1]))
        terms.append(-m.mass * (a[0] * v[0] + a[1] * v[1]))
        if lk is not None:
            terms.append(-m.inertia * sol.Al[lk.key] * sol.W[lk.key])
    assert abs(sum(terms)) <= 1e-9 * sum(abs(t) for t in terms)


# ----- near a toggle the forces grow without bound

TOGGLE = """
units = "mm"
[ground]
O1 = [0, 0]
O2 = [100, 0]
D = [300, 0]
[links]
"O1-A" = 40
"O2-B" = 50
BC = 150
CD = 100
[rolling]
"O2-B" = {{ on = "O1-A", radius = 60, angle = {angle} }}
[assembly]
C = "above"
[input]
crank = "O1-A"
angle = 0
speed = "100 rpm ccw"
[masses]
BC = {{ mass = "1 kg", along = 75 }}
CD = {{ mass = "1 kg", along = 50 }}
[loads]
C = {{ force = [0, -100] }}
"""


def test_near_a_toggle_the_forces_grow_as_one_over_the_condition():
    """The gear driven by the pinion carries a dyad whose links come into line as the gear's
    pin B turns to 180 deg (|BD| = BC + CD there): the dyad's condition (the sine at C)
    falls as the distance to the toggle, its pin forces grow as 1/condition (their product
    stays the 100 N load's size over the geometry's), `solve` warns with the condition, and
    at the toggle itself the kinematics refuses in one line."""
    from polygon_method.text.report import solution_text

    seen = []
    for d in (10.0, 1.0, 0.1):
        sol = solve(parse_scene(TOGGLE.format(angle=180 - d)))
        f = sol.forces
        (dyad,) = [s for s in f.steps if s.kind == "dyad"]
        F = max(p.magnitude for p in f.pins)
        seen.append((dyad.condition, F))
    for (c0, F0), (c1, F1) in zip(seen, seen[1:]):
        assert 9.0 < c0 / c1 < 11.0 and 9.0 < F1 / F0 < 11.0
        assert F1 * c1 == pytest.approx(F0 * c0, rel=0.01)
    text = solution_text(sol)
    assert re.search(
        r"warning: forces, step 3 \(dyad BC, CD at C\): condition 0\.00143 "
        r"\(sine of the angle at C between CB and CD\): the pin forces grow as "
        r"1/condition",
        text,
    )
    assert "estimated error of the forces above" in text
    with pytest.raises(PolygonMethodError, match="BC and CD are in line"):
        solve(parse_scene(TOGGLE.format(angle=180 - 1e-3)))


# ----- every view


def test_solve_json_steps_and_the_sheet_show_the_tooth_load():
    from polygon_method.draw import render_pages
    from polygon_method.text.report import solution_text
    from polygon_method.text.steptable import steps_text

    sol = solve(load_scene(WORKED))
    f = sol.forces
    text = solution_text(sol)
    assert (
        "contact of wheel O2-B with the gear O1-A: normal 99.45 N, tangential 273.2 N "
        "(290.8 N at 70.0 deg); the tooth load along the line of action, at the pressure "
        "angle 20 deg to the common tangent: 290.8 N"
    ) in text
    d = json.loads(json.dumps(sol.to_dict(), allow_nan=False))["forces"]
    c = d["contacts"]["O2-B"]
    assert c["by"] == "O1-A" and c["pressure_angle"] == pytest.approx(20.0)
    assert c["pressure_angle_stated"] is True and "required_friction" not in c
    assert c["tooth_load"] == pytest.approx(f.contacts[0].load, rel=1e-15)
    assert c["force"] == pytest.approx(list(f.contacts[0].force), rel=1e-15)
    steps = " ".join(steps_text(sol).split())
    assert "the tooth load along the line of action" in steps
    assert re.search(
        r"Step 2, wheel O2-B rolling on the gear O1-A: the tooth load along the "
        r"line of action",
        steps,
    )
    # the free bodies: the gear feels the pinion's teeth, the pinion the gear's, opposite
    sides = {fb.body: [s for s in fb.sides if s.what == "contact"] for fb in f.free}
    (on_gear,), (on_pinion,) = sides["O2-B"], sides["O1-A"]
    assert on_gear.vector == pytest.approx(tuple(-v for v in on_pinion.vector), rel=1e-15)
    assert on_gear.at == f.contacts[0].point and on_gear.by == "O1-A"
    datas = render_pages(sol, "svg", "forces")[0]
    num = f.numbers["O2-B"]
    k = next(
        i
        for i, s in enumerate(next(fb for fb in f.free if fb.body == "O2-B").sides)
        if s.what == "contact"
    )
    assert any(f'id="free-body-{num}-force-{k}-shaft"' in svg for svg in datas)


def test_the_default_pressure_angle_is_said_to_be_the_default():
    from polygon_method.text.report import solution_text

    sc = _with(
        ROOT / "worked_problems" / "rolling_epicyclic.toml",
        {"AP": {"mass": 2, "gyration": 30}},
        gravity=True,
    )
    text = solution_text(solve(sc))
    assert (
        "at the pressure angle 20 deg (the default; pressure_angle in [rolling] gives "
        "it) to the common tangent"
    ) in text
    d = solve(sc).to_dict()["forces"]["contacts"]["AP"]
    assert d["pressure_angle_stated"] is False and d["by"] == "frame"


def test_the_driving_wheel_in_solve_and_json():
    from polygon_method.text.report import solution_text

    sol = solve(_driving_wheel())
    f = sol.forces
    text = solution_text(sol)
    assert re.search(
        r"input torque on the wheel CA \(inertia, weights and loads\): [\d.]+ N m "
        r"c?cw \(its driver's torque on it, the effort taken as a torque; as a "
        r"force at its centre along the ground instead: [\d.]+ N at [\d.]+ "
        r"deg\)",
        text,
    )
    d = json.loads(json.dumps(sol.to_dict(), allow_nan=False))["forces"]
    assert d["wheel"] == "CA" and d["input_torque"] == f.input_torque
    assert d["centre_force"] == pytest.approx(
        [-f.input_torque / 0.3 * u for u in (1.0, 0.0)], abs=1e-12
    )
    assert d["contacts"]["CA"]["by"] == "frame" and "required_friction" in d["contacts"]["CA"]
    # steps: the ground's grip is a force along the line, the driver's a torque
    from polygon_method.text.steptable import steps_text

    words = " ".join(steps_text(sol).split())
    assert re.search(r"T at the contact of CA = -?[\d.]+ N \(along the line", words)
    assert re.search(r"T on CA by its driver = [\d.]+ N m c?cw", words)


def test_check_keys_for_the_tooth_load_and_the_wheels_torque(tmp_path, capsys):
    """Fc_L: the contact force's size at wheel L (a rack's point); the driving wheel's
    torque is a torque answer where masses are given; a key naming no wheel is one line."""
    from polygon_method.check import check_answers
    from polygon_method.cli import main

    sol = solve(load_scene(WORKED))
    c = sol.forces.contacts[0]
    base = WORKED.read_text().split("[answers]")[0]
    wrong = parse_scene(base + f'[answers]\n"Fc_O2-B" = "{abs(c.tangential):.4g} N"\n')
    (v,) = check_answers(solve(wrong))
    assert not v.ok and v.key == "Fc_O2-B" and v.mistake == "pressure_angle_left_out"
    tau = solve(_driving_wheel()).forces.input_torque
    wheel = _driving_wheel(
        f'[answers]\ntorque = "{abs(tau):.4g} N m {"ccw" if tau > 0 else "cw"}"\n'
    )
    (v,) = check_answers(solve(wheel))
    assert v.ok
    racks = _with(
        ROOT / "tests" / "textbook" / "rolling_pinion_two_racks.toml",
        {"R1": {"mass": 2}},
        gravity=True,
    )
    want = next(c.load for c in solve(racks).forces.contacts if c.wheel == "block R1")
    racks = _with(
        ROOT / "tests" / "textbook" / "rolling_pinion_two_racks.toml",
        {"R1": {"mass": 2}},
        gravity=True,
        answers={"Fc_R1": f"{want:.4g} N"},
    )
    (v,) = check_answers(solve(racks))
    assert v.ok
    bad = tmp_path / "bad.toml"
    bad.write_text(base + '[answers]\nFc_BC = "100 N"\n')
    assert main(["check", str(bad)]) == 2
    err = capsys.readouterr().err.strip()
    assert "\n" not in err and "Fc_BC: BC is no wheel of [rolling] and no rack" in err


@pytest.mark.parametrize(
    "extra, words",
    [
        (
            '{ on = "horizontal", through = [0, 0], pressure_angle = 20 }',
            "a wheel on a line grips by friction",
        ),
        ('{ on = "O1-A", radius = 75, pressure_angle = 60 }', "from 0 to 45 deg"),
    ],
)
def test_bad_pressure_angles_are_one_located_line(extra, words):
    text = WORKED.read_text()
    text = re.sub(r'"O2-B" = \{ on = "O1-A".*\}', lambda _: f'"O2-B" = {extra}', text)
    with pytest.raises(SceneError, match=words) as e:
        parse_scene(text)
    assert "\n" not in str(e.value) and "[rolling] O2-B" in str(e.value)


# ----- friction at the guides and the pins


def _friction_scene(path, guides, pins):
    """A worked problem given masses on every moving link (G off the link's line) and
    block, gravity, a load at a moving point, every pin a size, and [friction]."""
    sc = load_scene(path)
    raw = scene_table(sc)
    raw.pop("answers", None)
    raw.pop("variants", None)
    unit = sc.length_unit
    masses = dict(raw.get("masses", {}))
    moving = [lk for lk in sc.links if not (lk.p in sc.ground and lk.q in sc.ground)]
    for k, lk in enumerate(moving):
        if lk.key not in masses:
            L = lk.length / unit
            masses[lk.key] = {
                "mass": 1.0 + k,
                "distances": {lk.p: 0.6 * L, lk.q: 0.6 * L},
                "turn": "ccw",
                "gyration": 0.3 * L,
            }
    for sl in sc.blocks:
        if sl.point not in masses:
            masses[sl.point] = {"mass": 2.0}
    raw["masses"] = masses
    raw.setdefault("gravity", {"direction": 250})
    loads = dict(raw.get("loads", {}))
    if not loads:
        pt = next(p for lk in moving for p in lk.points if p not in sc.ground)
        loads[pt] = {"force": [-300, 120]}
    raw["loads"] = loads
    names = sorted({p for lk in sc.links for p in lk.points})
    raw["pins"] = {p: {"diameter": 20 + 3 * k} for k, p in enumerate(names)}
    raw["friction"] = {"guides": guides, "pins": pins}
    return scene_from_table(raw)


def _omega_of(sol, body):
    sc = sol.scene
    if body == FRAME:
        return 0.0
    if body.startswith("block "):
        g = getattr(sc.slider(body[6:]), "guide", None)
        return sol.W[sc.link(g).key] if g else 0.0
    return sol.W[body]


def _friction_power(sol, f):
    """The friction's power, from the forces found and the motion, written here: at each
    pin -mu r |F| |omega_on - omega_by|, at each guide -mu |N| |v_rel| (v_rel the block's
    velocity less the guide's point's under it)."""
    sc = sol.scene
    fr = sc.friction
    radius = {p.point: p.radius for p in sc.pins}
    total = 0.0
    for p in f.pins:
        if p.point in radius:
            total -= (
                fr.pins
                * radius[p.point]
                * p.magnitude
                * abs(_omega_of(sol, p.on) - _omega_of(sol, p.by))
            )
    for g in f.guides:
        X = g.point
        v = sol.V[X]
        if g.by == FRAME:
            w = (0.0, 0.0)
        else:
            lk = sc.link(g.by)
            (px, py), (vx, vy), om = sol.P[lk.p], sol.V[lk.p], sol.W[lk.key]
            w = (vx - om * (sol.P[X][1] - py), vy + om * (sol.P[X][0] - px))
        total -= fr.guides * abs(g.normal) * math.hypot(v[0] - w[0], v[1] - w[1])
    return total


FRICTION_CASES = [
    "offset_slider_crank",
    "fourbar_forces",
    "crank_slotted_lever",
    "whitworth",
    "gear_pair_forces",
]


@pytest.mark.parametrize("name", FRICTION_CASES)
def test_friction_the_power_balance_includes_its_loss(name):
    """The driver's power balances the loads', the inertia's and the friction's, the last
    written here from the forces found (every pin a size, mu 0.15 at the guides and 0.1 at
    the pins); every body in equilibrium with its friction; the torque differs from the
    frictionless one."""
    import sys

    sys.path.insert(0, str(ROOT / "tests"))
    from test_forces import _driver_power, _kin, _newton_euler

    path = ROOT / "worked_problems" / f"{name}.toml"
    sc = _friction_scene(path, 0.15, 0.1)
    sol = solve(sc)
    f = sol.forces
    loss = _friction_power(sol, f)
    assert loss < 0 and abs(f.friction_power - loss) <= 1e-12 * abs(loss)
    terms = _driver_power(sc, sol, f) + [loss]
    for ld in sc.loads:
        if ld.force is not None:
            v = sol.V[ld.target]
            terms.append(ld.force[0] * v[0] + ld.force[1] * v[1])
        else:
            terms.append(ld.torque * sol.W[ld.target])
    g = sc.gravity
    for m in sc.masses:
        G, v, a, al, w = _kin(sol, m)
        if g is not None:
            terms.append(m.mass * g.g * (g.direction[0] * v[0] + g.direction[1] * v[1]))
        terms.append(-m.mass * (a[0] * v[0] + a[1] * v[1]))
        terms.append(-m.inertia * al * w)
    assert abs(sum(terms)) <= 1e-9 * sum(abs(t) for t in terms)
    for body, (rf, rm, fs, ms) in _newton_euler(sol, f).items():
        assert body == FRAME or (rf <= 1e-9 * fs and rm <= 1e-9 * ms), body
    # the shaking force and moment: the loads', weights' and inertia's, friction internal
    fx = fy = mo = scale = 0.0
    for ld in sc.loads:
        if ld.force is not None and not ld.gas:
            x, y = sol.P[ld.target]
            fx, fy = fx + ld.force[0], fy + ld.force[1]
            mo += x * ld.force[1] - y * ld.force[0]
            scale += math.hypot(*ld.force) * (1 + math.hypot(x, y))
        elif ld.force is None:
            mo += ld.torque
            scale += abs(ld.torque)
    for m in sc.masses:
        G, v, a, al, w = _kin(sol, m)
        F = (m.mass * (g.g * g.direction[0] - a[0]), m.mass * (g.g * g.direction[1] - a[1]))
        fx, fy = fx + F[0], fy + F[1]
        mo += G[0] * F[1] - G[1] * F[0] - m.inertia * al
        scale += math.hypot(*F) * (1 + math.hypot(*G)) + abs(m.inertia * al)
    assert math.hypot(f.shaking_force[0] - fx, f.shaking_force[1] - fy) <= 1e-9 * scale
    assert abs(f.shaking_moment - mo) <= 1e-9 * (scale + abs(f.input_torque))
    plain = solve(replace_friction(sc, None)).forces
    assert abs(plain.input_torque - f.input_torque) > 1e-3 * abs(plain.input_torque)


def replace_friction(sc, fr):
    import dataclasses

    return dataclasses.replace(sc, friction=fr)


def test_no_friction_is_as_before_and_the_words_say_it():
    from polygon_method.scene.records import Friction
    from polygon_method.text.report import solution_text

    sc = load_scene(WORKED)
    f0 = solve(sc).forces
    f1 = solve(replace_friction(sc, Friction(0.0, 0.0))).forces
    assert f1.input_torque == f0.input_torque and f1.friction_power == 0.0
    raw = scene_table(sc)
    raw["pins"] = {
        "O1": {"diameter": 20},
        "O2": {"diameter": 20},
        "B": {"diameter": 16},
        "C": {"diameter": 16},
    }
    raw["friction"] = {"guides": 0.1, "pins": 0.05}
    raw.pop("answers")
    sol = solve(scene_from_table(raw))
    text = solution_text(sol)
    assert "friction at the guide of C:" in text and "friction at pin O2: couple" in text
    assert re.search(r"friction power: -[\d.]+ W", text)
    assert "input torque on O1-A (inertia, weights, loads and friction):" in text
    d = json.loads(json.dumps(sol.to_dict(), allow_nan=False))["forces"]["friction"]
    assert d["power"] == sol.forces.friction_power < 0
    assert {p["what"] for p in d["pins"]} >= {"friction at pin O2", "friction at pin B"}


@pytest.mark.parametrize(
    "table, words",
    [
        ("[friction]\nguides = 1.5", "a coefficient of friction, a number from 0 up to"),
        ("[friction]\npins = 0.1", "friction at the pins needs their sizes"),
        ("[friction]\nguide = 0.1", "unknown key 'guide'"),
    ],
)
def test_bad_friction_is_one_located_line(table, words):
    text = WORKED.read_text().split("[answers]")[0] + table + "\n"
    with pytest.raises(SceneError, match=words) as e:
        parse_scene(text)
    assert "\n" not in str(e.value) and "[friction]" in str(e.value)


def test_a_ring_driven_by_a_planet_against_the_matrix_method():
    """The ring (an internal gear) about O driven by the planet inside it: on the planet,
    the pinion of the internal pair, the teeth's push points to its own centre (the pair
    pushed apart), so the ring feels it outwards; the planet rolls on the fixed sun too."""
    sc = _with(
        ROOT / "worked_problems" / "ring_gear_output.toml",
        {
            "OA": {"mass": 1, "along": 30},
            "AP": {"mass": 0.5, "along": 0, "gyration": 14},
            "O-Q": {"mass": 3, "along": 0, "gyration": 70},
            "Q-B": {"mass": 1, "along": 75, "gyration": 45},
            "B": {"mass": 2},
        },
        {"B": {"force": [-150, 20]}},
    )
    sol = solve(sc)
    f = sol.forces
    P = sol.P
    O, A = P["O"], P["A"]
    u = _unit((A[0] - O[0], A[1] - O[1]))
    sun = (
        "tooth sun",
        (O[0] + 0.040 * u[0], O[1] + 0.040 * u[1]),
        (-u[1], u[0]),
        u,
        "AP",
        FRAME,
        DEG20,
    )
    m = (-u[0], -u[1])  # from the ring's pitch point towards the planet's centre
    ring = (
        "tooth ring",
        (A[0] + 0.020 * u[0], A[1] + 0.020 * u[1]),
        (-m[1], m[0]),
        m,
        "AP",
        "O-Q",
        DEG20,
    )

    def build():
        mat = Matrix(sol, ["OA", "AP", "O-Q", "Q-B", "block B"], {"B": "block B"})
        mat.pin("O", O, "OA", FRAME)
        mat.pin("OQ", O, "O-Q", FRAME)
        mat.pin("A", A, "AP", "OA")
        mat.pin("Q", P["Q"], "Q-B", "O-Q")
        mat.pin("B", P["B"], "Q-B", "block B")
        mat.along("N_B", P["B"], (0.0, 1.0), "block B", FRAME)
        mat.couple("T", "OA")
        return mat

    x = _teeth(build, [sun, ring])
    scale = max(math.hypot(x[k + ".x"], x[k + ".y"]) for k in ("O", "OQ", "A", "Q", "B"))
    _close(f.pin("A", "AP", "OA"), (x["A.x"], x["A.y"]), scale)
    _close(f.pin("O", "O-Q", FRAME), (x["OQ.x"], x["OQ.y"]), scale)
    _close(f.pin("Q", "Q-B", "O-Q"), (x["Q.x"], x["Q.y"]), scale)
    contacts = {c.wheel: c for c in f.contacts}
    _close(contacts["AP"].force, x["tooth sun.F"], scale)
    on_ring = contacts["O-Q"]
    assert on_ring.by == "AP" and on_ring.normal < 0  # pushed outwards, away from O
    _close(on_ring.force, tuple(-v for v in x["tooth ring.F"]), scale)
    assert abs(f.input_torque - x["T"]) <= 1e-9 * scale * 0.1


def test_friction_over_a_sweep_balances_power_at_every_angle():
    """The same passes on arrays (a sweep of the crank and slotted lever with friction,
    every 5 deg): the power balance with the friction's loss at every angle, to 1e-9."""
    import sys

    import numpy as np

    from polygon_method.forces import analyse
    from polygon_method.motion.sweeps import sweep

    sys.path.insert(0, str(ROOT / "tests"))
    from test_forces import _driver_power, _kin

    sc = _friction_scene(ROOT / "worked_problems" / "crank_slotted_lever.toml", 0.15, 0.1)
    res = sweep(sc, np.radians(np.arange(3.0, 360.0, 5.0)))
    f = analyse(res)
    terms = _driver_power(sc, res, f) + [f.friction_power]
    for ld in sc.loads:
        if ld.force is not None:
            v = res.V[ld.target]
            terms.append(ld.force[0] * v[0] + ld.force[1] * v[1])
        else:
            terms.append(ld.torque * res.W[ld.target])
    g = sc.gravity
    for m in sc.masses:
        G, v, a, al, w = _kin(res, m)
        terms.append(m.mass * g.g * (g.direction[0] * v[0] + g.direction[1] * v[1]))
        terms.append(-m.mass * (a[0] * v[0] + a[1] * v[1]))
        terms.append(-m.inertia * al * w)
    total = sum(terms)
    scale = sum(np.abs(t) for t in terms)
    assert len(res) >= 60 and np.all(np.asarray(f.friction_power) <= 0)
    assert np.all(np.abs(total) <= 1e-9 * scale)
