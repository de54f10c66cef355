"""Core solver against independent references.

* closed-form slider-crank kinematics;
* finite differences in time of the solved positions (Richardson-extrapolated), for every
  step kind: crank, RRR, RRP on fixed and moving guides, RPR (slotted lever, swivel);
* loop closure: every link keeps its length, every slider stays on its guide;
* image points: triangle bcf similar to BCF, read the same way round;
* rubbing |w1 - w2| r; input torque by virtual work (finite differences of positions).
"""

import json
import math

import pytest

from polygon_method import parse_scene, solve
from polygon_method.cli import main
from polygon_method.solver.compiler import compile_plan
from polygon_method.solver.plan import Context
from scenes import TRANSLATING_COUPLER, seed

FOURBAR = seed(
    middle='[points]\nE = { on = "BC", along = 40 }\n'
    'F = { on = "BC", distances = { B = 45, C = 30 }, turn = "cw" }\n'
    'G = { on = "CD", distances = { C = 24, D = 44 }, turn = "cw" }\n'
    '[assembly]\nC = "above"\n',
    drive='angle = 60\nspeed = "10.5 rad/s cw"\nacceleration = "40 rad/s^2 ccw"',
    after="[pins]\nA = { radius = 30 }\nB = { radius = 40 }\n"
    "C = { radius = 25 }\nD = { diameter = 70 }\n",
)

OFFSET_SLIDER = """
[ground]
O = [0, 0]
[links]
OA = 50
AB = 200
[points]
E = { on = "AB", distances = { A = 80, B = 150 }, turn = "ccw" }
[sliders]
B = { path = "horizontal", through = [0, 20] }
[input]
crank = "OA"
angle = 30
speed = "300 rpm ccw"
acceleration = "20 rad/s^2 ccw"
[loads]
B = { force = "1.5 kN", direction = 180 }
"""

SLOTTED_LEVER = """
units = "mm"
[ground]
O2 = [0, 300]
O4 = [0, 0]
[links]
"O2-A" = 100
"O4-P" = 500
"P-Q" = 150
[sliders]
A = { along = "O4-P" }
Q = { path = "horizontal", through = [0, 520] }
[assembly]
Q = "right"
[input]
crank = "O2-A"
angle = 20
speed = "60 rpm cw"
acceleration = "5 rad/s^2 cw"
[pins]
A = { diameter = 20 }
P = { diameter = 20 }
[loads]
Q = { force = [-800, 0] }
"""

WHITWORTH = """
[ground]
O2 = [0, 0]
O4 = [0, -60]
[links]
"O2-A" = 120
"O4-P" = 90
"P-Q" = 250
[sliders]
A = { along = "O4-P" }
Q = { path = "horizontal", through = [0, -60] }
[assembly]
P = "below"
Q = "left"
[input]
crank = "O2-A"
angle = 130
speed = "120 rpm ccw"
"""

SWIVEL = """
[ground]
A = [0, 0]
O = [150, 0]
[links]
AB = 50
BC = 250
[sliders]
O = { along = "BC" }
[input]
crank = "AB"
angle = 75
speed = "200 rpm ccw"
acceleration = "30 rad/s^2 cw"
"""

MOVING_GUIDE = seed(
    ground="H = [60, 130]\n",
    links="HX = 80\n",
    middle='[sliders]\nX = { along = "BC" }\n[assembly]\nC = "above"\nX = [70, 55]\n',
    drive='angle = 60\nspeed = "10.5 rad/s cw"\nacceleration = "12 rad/s^2 cw"',
)

SIX_LINK = """
[ground]
O2 = [0, 0]
O4 = [300, 0]
[links]
"O2-A" = 100
AB = 280
"O4-B" = 200
"E-F" = 260
[points]
E = { on = "AB", distances = { A = 150, B = 180 }, turn = "ccw" }
[sliders]
F = { path = "vertical", through = [250, 0] }
[assembly]
B = "above"
F = "above"
[input]
crank = "O2-A"
angle = 70
speed = "150 rpm ccw"
"""

PLATE = """
# four-bar A-B-E-G whose coupler is a plate B, C, E named by its side BC: E is found first
[ground]
A = [0, 0]
G = [120, 0]
[links]
AB = 40
BC = 100
EG = 90
[points]
E = { on = "BC", distances = { B = 70, C = 50 }, turn = "cw" }
[assembly]
E = "above"
[input]
crank = "AB"
angle = 80
speed = "10 rad/s ccw"
acceleration = "3 rad/s^2 ccw"
"""

ALL = {
    "plate": PLATE,
    "fourbar": FOURBAR,
    "offset_slider": OFFSET_SLIDER,
    "slotted_lever": SLOTTED_LEVER,
    "whitworth": WHITWORTH,
    "swivel": SWIVEL,
    "moving_guide": MOVING_GUIDE,
    "six_link": SIX_LINK,
}


def positions_at(scene, theta):
    plan = compile_plan(scene)
    ctx = Context(theta, scene.input.omega, scene.input.alpha)
    return plan.evaluate(ctx, velocities=False, accelerations=False)[0]


def derivatives(scene, point, h=2e-3):
    """dX/dtheta and d2X/dtheta2 by Richardson-extrapolated central differences."""
    th = scene.input.angle

    def d1(step):
        p, m = positions_at(scene, th + step)[point], positions_at(scene, th - step)[point]
        return [(a - b) / (2 * step) for a, b in zip(p, m)]

    def d2(step):
        p, m = positions_at(scene, th + step)[point], positions_at(scene, th - step)[point]
        c = positions_at(scene, th)[point]
        return [(a - 2 * z + b) / step**2 for a, z, b in zip(p, c, m)]

    r1 = [(4 * a - b) / 3 for a, b in zip(d1(h / 2), d1(h))]
    r2 = [(4 * a - b) / 3 for a, b in zip(d2(h / 2), d2(h))]
    return r1, r2


def fd_motion(scene, point):
    """v = X' w, a = X'' w^2 + X' alpha (theta = theta0 + w t + alpha t^2 / 2)."""
    w, al = scene.input.omega, scene.input.alpha
    d1, d2 = derivatives(scene, point)
    v = [x * w for x in d1]
    a = [x * w * w + y * al for x, y in zip(d2, d1)]
    return v, a


def close(a, b, scale, rel):
    return all(abs(x - y) <= rel * scale for x, y in zip(a, b))


@pytest.mark.parametrize("name", sorted(ALL))
def test_velocities_and_accelerations_match_finite_differences(name):
    scene = parse_scene(ALL[name])
    sol = solve(scene)
    vscale = max(sol.speed(p) for p in sol.P)
    ascale = max(sol.acceleration_magnitude(p) for p in sol.P)
    for p in scene.point_names:
        v, a = fd_motion(scene, p)
        assert close(sol.V[p], v, vscale, 1e-8), (p, sol.V[p], v)
        assert close(sol.A[p], a, ascale, 1e-6), (p, sol.A[p], a)


@pytest.mark.parametrize("name", sorted(ALL))
def test_link_omega_alpha_match_finite_differences(name):
    scene = parse_scene(ALL[name])
    sol = solve(scene)
    th, w, al = scene.input.angle, scene.input.omega, scene.input.alpha

    def angle(lk, t):
        P = positions_at(scene, t)
        (x1, y1), (x2, y2) = P[lk.p], P[lk.q]
        return math.atan2(y2 - y1, x2 - x1)

    def unwrap(d):
        return (d + math.pi) % (2 * math.pi) - math.pi

    for lk in scene.links:

        def d1(h):
            return unwrap(angle(lk, th + h) - angle(lk, th - h)) / (2 * h)

        def d2(h):
            return (
                unwrap(angle(lk, th + h) - angle(lk, th))
                - unwrap(angle(lk, th) - angle(lk, th - h))
            ) / h**2

        h = 2e-3
        d1 = (4 * d1(h / 2) - d1(h)) / 3
        d2 = (4 * d2(h / 2) - d2(h)) / 3
        wl = d1 * w
        al_l = d2 * w * w + d1 * al
        wscale = max(abs(x) for x in sol.W.values())
        assert abs(sol.W[lk.key] - wl) <= 1e-8 * wscale, (lk.key, sol.W[lk.key], wl)
        ascale = max(abs(x) for x in sol.Al.values()) + wscale**2
        assert abs(sol.Al[lk.key] - al_l) <= 1e-6 * ascale, (lk.key, sol.Al[lk.key], al_l)


@pytest.mark.parametrize("name", sorted(ALL))
def test_loop_closure(name):
    scene = parse_scene(ALL[name])
    sol = solve(scene)
    for lk in scene.links:
        assert math.dist(sol.P[lk.p], sol.P[lk.q]) == pytest.approx(lk.length, rel=1e-13)
    for s in scene.sliders:
        X = sol.P[s.point]
        if hasattr(s, "u"):
            (qx, qy), (ux, uy) = s.through, s.u
            assert abs((X[0] - qx) * uy - (X[1] - qy) * ux) < 1e-14
        else:
            (x1, y1), (x2, y2) = sol.P[s.first], sol.P[s.second]
            cross = (X[0] - x1) * (y2 - y1) - (X[1] - y1) * (x2 - x1)
            assert abs(cross) < 1e-14


def test_offset_slider_crank_closed_form():
    """x = r cos t + sqrt(l^2 - (r sin t - e)^2), differentiated by hand."""
    scene = parse_scene(OFFSET_SLIDER)
    sol = solve(scene)
    r, l, e = 0.05, 0.2, 0.02
    t, w, al = scene.input.angle, scene.input.omega, scene.input.alpha
    s = r * math.sin(t) - e
    q = math.sqrt(l * l - s * s)
    x = r * math.cos(t) + q
    dx = -r * math.sin(t) - s * r * math.cos(t) / q  # dx/dt(theta)
    ds = r * math.cos(t)
    dds = -r * math.sin(t)
    dq = -s * ds / q
    ddq = -(ds * ds + s * dds) / q + s * ds * dq / q**2
    ddx = -r * math.cos(t) + ddq
    assert sol.P["B"] == pytest.approx((x, e), abs=1e-15)
    assert sol.V["B"][0] == pytest.approx(dx * w, rel=1e-12)
    assert sol.A["B"][0] == pytest.approx(ddx * w * w + dx * al, rel=1e-12)
    assert sol.V["B"][1] == 0 and sol.A["B"][1] == 0
    # the rod's angular velocity: sin(phi) = (r sin t - e)/l  ->  phi' = r cos t w / (l cos phi)
    phi_dot = r * math.cos(t) * w / q
    assert abs(sol.omega("AB")) == pytest.approx(abs(phi_dot), rel=1e-12)
    assert sol.sliding_velocity("B") == pytest.approx(dx * w, rel=1e-12)


def test_engine_piston_at_90_degrees_equals_crank_pin_speed():
    scene = parse_scene(
        OFFSET_SLIDER.replace("through = [0, 20]", "through = [0, 0]").replace(
            "angle = 30", "angle = 90"
        )
    )
    sol = solve(scene)
    assert sol.speed("B") == pytest.approx(0.05 * 10 * math.pi, rel=1e-14)


@pytest.mark.parametrize("name", ["fourbar", "six_link", "offset_slider", "plate"])
def test_image_points_similar_and_same_way_round(name):
    scene = parse_scene(ALL[name])
    sol = solve(scene)
    for cp in scene.points:
        lk = scene.link(cp.link)
        z = lambda D, p: complex(*D[p])  # noqa: E731
        space = (z(sol.P, cp.name) - z(sol.P, lk.p)) / (z(sol.P, lk.q) - z(sol.P, lk.p))
        for D in (sol.V, sol.A):
            image = (z(D, cp.name) - z(D, lk.p)) / (z(D, lk.q) - z(D, lk.p))
            assert image == pytest.approx(space, rel=1e-12)


def test_moving_guide_sliding_and_coriolis_from_finite_differences():
    """s = (X - B).u along BC; vs = ds/dt, as = d2s/dt2 (relative to the turning link),
    and a_X = a_X' + 2 w vs perp(u) + as u with X' the point of BC under X."""
    scene = parse_scene(MOVING_GUIDE)
    sol = solve(scene)
    th, w, al = scene.input.angle, scene.input.omega, scene.input.alpha

    def s_at(t):
        P = positions_at(scene, t)
        (bx, by), (cx, cy), (x, y) = P["B"], P["C"], P["X"]
        L = math.hypot(cx - bx, cy - by)
        return ((x - bx) * (cx - bx) + (y - by) * (cy - by)) / L

    h = 1e-3
    d1 = [(s_at(th + k) - s_at(th - k)) / (2 * k) for k in (h, h / 2)]
    d2 = [(s_at(th + k) - 2 * s_at(th) + s_at(th - k)) / k**2 for k in (h, h / 2)]
    ds = (4 * d1[1] - d1[0]) / 3
    dds = (4 * d2[1] - d2[0]) / 3
    assert sol.sliding_velocity("X") == pytest.approx(ds * w, rel=1e-8)
    assert sol.sliding_acceleration("X") == pytest.approx(dds * w * w + ds * al, rel=1e-6)
    wg = sol.omega("BC")
    (bx, by), (cx, cy) = sol.P["B"], sol.P["C"]
    L = math.hypot(cx - bx, cy - by)
    u = ((cx - bx) / L, (cy - by) / L)
    cor = sol.coriolis("X")
    vs = sol.sliding_velocity("X")
    assert cor == pytest.approx((-2 * wg * vs * u[1], 2 * wg * vs * u[0]), rel=1e-12)
    assert math.hypot(*cor) == pytest.approx(2 * abs(wg * vs), rel=1e-12)


@pytest.mark.parametrize("name", ["slotted_lever", "whitworth", "swivel"])
def test_slotted_link_sliding_velocity_from_finite_differences(name):
    """The block's distance from the guide's first point changes at the sliding velocity."""
    scene = parse_scene(ALL[name])
    sol = solve(scene)
    sl = next(s for s in scene.sliders if hasattr(s, "guide"))
    th, w = scene.input.angle, scene.input.omega

    def s_at(t):
        P = positions_at(scene, t)
        (x1, y1), (x2, y2), (x, y) = P[sl.first], P[sl.second], P[sl.point]
        L = math.hypot(x2 - x1, y2 - y1)
        return ((x - x1) * (x2 - x1) + (y - y1) * (y2 - y1)) / L

    h = 1e-3
    d = [(s_at(th + k) - s_at(th - k)) / (2 * k) for k in (h, h / 2)]
    assert sol.sliding_velocity(sl.point) == pytest.approx((4 * d[1] - d[0]) / 3 * w, rel=1e-8)
    vs, wg = sol.sliding_velocity(sl.point), sol.omega(sl.guide)
    assert math.hypot(*sol.coriolis(sl.point)) == pytest.approx(2 * abs(wg * vs), rel=1e-12)


def test_rubbing_is_difference_of_signed_omegas_times_radius():
    scene = parse_scene(FOURBAR)
    sol = solve(scene)
    wab, wbc, wcd = sol.omega("AB"), sol.omega("BC"), sol.omega("CD")
    assert wab < 0 < wbc  # opposite senses: the magnitudes add
    assert sol.rubbing["B"].rubbing_velocity == pytest.approx((abs(wab) + abs(wbc)) * 0.040)
    assert sol.rubbing["A"].rubbing_velocity == pytest.approx(abs(wab) * 0.030)
    assert sol.rubbing["C"].rubbing_velocity == pytest.approx(abs(wbc - wcd) * 0.025)
    assert sol.rubbing["D"].rubbing_velocity == pytest.approx(abs(wcd) * 0.035)


def test_rubbing_pairs_at_a_pin_joining_three_bodies():
    toggle = """
    [ground]
    O = [0, 0]
    C = [-105, -360]
    [links]
    OA = 180
    AB = 360
    CB = 240
    BD = 540
    [sliders]
    D = { path = "horizontal", through = "C" }
    [assembly]
    B = [98, -232]
    D = "right"
    [input]
    crank = "OA"
    angle = 45
    speed = "180 rpm ccw"
    [pins]
    B = { diameter = 30 }
    D = { diameter = 30 }
    """
    sol = solve(parse_scene(toggle))
    r = sol.rubbing["B"]
    assert set(r.pairs) == {"AB|CB", "AB|BD", "CB|BD"}
    w = {k: sol.omega(k) for k in ("AB", "CB", "BD")}
    assert r.pairs["AB|BD"] == pytest.approx(abs(w["AB"] - w["BD"]) * 0.015)
    assert r.rubbing_velocity == max(r.pairs.values())
    assert sol.rubbing["D"].rubbing_velocity == pytest.approx(abs(w["BD"]) * 0.015)
    out = sol.to_dict()
    assert "pairs" in out["pins"]["B"] and "pairs" not in out["pins"]["D"]


@pytest.mark.parametrize("name", ["offset_slider", "slotted_lever"])
def test_input_torque_by_virtual_work(name):
    """T = -sum F . dX/dtheta, with dX/dtheta from finite differences of positions."""
    scene = parse_scene(ALL[name])
    sol = solve(scene)
    total = 0.0
    for load in scene.loads:
        d1, _ = derivatives(scene, load.target)
        total += load.force[0] * d1[0] + load.force[1] * d1[1]
    assert sol.input_torque == pytest.approx(-total, rel=1e-8)


def test_torque_sign_crank_must_drive_against_a_resisting_force():
    scene = parse_scene(OFFSET_SLIDER)
    sol = solve(scene)
    # the piston moves towards -x at 30 deg (ccw crank), the force acts along -x: it helps
    assert sol.V["B"][0] < 0
    assert sol.input_torque < 0


def test_plan_is_independent_of_file_order():
    text = FOURBAR.replace("AB = 50\nBC = 66\nCD = 56", "CD = 56\nBC = 66\nAB = 50")
    a, b = solve(parse_scene(FOURBAR)), solve(parse_scene(text))
    for p in a.P:
        assert a.P[p] == pytest.approx(b.P[p], abs=1e-15)
        assert a.A[p] == pytest.approx(b.A[p], abs=1e-12)


def test_assembly_hints_choose_the_branch():
    up = solve(parse_scene(FOURBAR))
    down = solve(parse_scene(FOURBAR.replace('C = "above"', 'C = "below"')))
    near = solve(parse_scene(FOURBAR.replace('C = "above"', "C = [80, -30]")))
    assert up.P["C"][1] > 0 > down.P["C"][1]
    assert near.P["C"] == down.P["C"]
    # the mirror image of C in the line BD is the other branch
    (bx, by), (dx, dy) = up.P["B"], up.P["D"]
    ux, uy = (
        (dx - bx) / math.dist(up.P["B"], up.P["D"]),
        (dy - by) / math.dist(up.P["B"], up.P["D"]),
    )
    cx, cy = up.P["C"][0] - bx, up.P["C"][1] - by
    along = cx * ux + cy * uy
    mirror = (bx + 2 * along * ux - cx, by + 2 * along * uy - cy)
    assert down.P["C"] == pytest.approx(mirror, abs=1e-15)


def test_json_contract(capsys):
    import tempfile
    from pathlib import Path

    with tempfile.TemporaryDirectory() as d:
        path = Path(d) / "s.toml"
        path.write_text(SLOTTED_LEVER)
        assert main(["solve", str(path), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    scene = parse_scene(SLOTTED_LEVER)
    assert set(data["points"]) == set(scene.point_names)
    assert set(data["links"]) == {lk.key for lk in scene.links}
    for entry in data["points"].values():
        assert set(entry) >= {"position", "velocity", "acceleration"}
    assert set(data["sliders"]) == {"A", "Q"}
    for s in data["sliders"].values():
        assert set(s) >= {"sliding_velocity", "sliding_acceleration", "coriolis"}
    assert set(data["pins"]) == {"A", "P"}
    assert isinstance(data["input_torque"], float)
    assert data["sliders"]["Q"]["coriolis"] == [0.0, 0.0]


def test_crank_with_ground_point_second_in_its_name():
    a = solve(parse_scene(FOURBAR))
    b = solve(
        parse_scene(FOURBAR.replace("AB = 50", "BA = 50").replace('crank = "AB"', 'crank = "BA"'))
    )
    assert a.P["C"] == b.P["C"]
    assert b.omega("BA") == a.omega("AB")


@pytest.mark.parametrize(
    "word, sign",
    [
        ("clockwise", -1),
        ("anticlockwise", 1),
        ("acw", 1),
        ("counter-clockwise", 1),
        ("cw", -1),
        ("CCW", 1),
    ],
)
def test_sense_words_as_textbooks_write_them(word, sign):
    scene = parse_scene(FOURBAR.replace('"10.5 rad/s cw"', f'"100 rpm {word}"'))
    assert scene.input.omega == pytest.approx(sign * 100 * 2 * math.pi / 60)


def test_parallelogram_coupler_translates_and_reports_say_zero():
    """AB = CD, BC = AD: the coupler translates (omega_BC = 0, closed form) and the rocker
    turns with the crank. Rounding leaves ~1e-13 rad/s in omega_BC: reports show 0 with no
    sense; the JSON keeps the raw number."""
    from polygon_method.text.steptable import steps_text

    scene = parse_scene(TRANSLATING_COUPLER)
    sol = solve(scene)
    assert abs(sol.omega("BC")) < 1e-12 and sol.omega("CD") == pytest.approx(10, rel=1e-12)
    assert abs(sol.alpha("CD")) < 1e-8
    row = next(line for line in sol.report().splitlines() if line.startswith("BC "))
    assert "0 rad/s " in row and "cw" not in row and "ccw" not in row
    assert "omega_BC = v_CB / BC = 0 / 0.1 = 0 rad/s\n" in steps_text(sol) + "\n"


def test_rubbing_records_are_the_rubbing_formula_at_every_pin():
    """The records a solve makes (each pin of two bodies read straight from W) hold what
    :func:`rubbing_at` gives (|w1 - w2| r, a body that does not turn at 0), on every worked
    problem with sized pins; a link missing from W is read as 0, as that formula reads it,
    and a pin of three bodies gives each pair."""
    from pathlib import Path

    from polygon_method import load_scene
    from polygon_method.solver.derived import pin_records, rubbing_at

    checked = 0
    for path in sorted((Path(__file__).parent.parent / "worked_problems").glob("*.toml")):
        sol = solve(load_scene(path))
        plan, radii = sol.plan, sol.plan.dims.radii
        for pin in plan.pins:
            want = rubbing_at(pin, sol.W, radii[pin[0]])
            assert sol.rubbing[pin[0]].values == want, (path.stem, pin[0])
            assert sol.rubbing[pin[0]].rubbing_velocity == max(want)
            links = [lk for pair in pin[5] for lk in pair if lk is not None]
            W = {k: v for k, v in sol.W.items() if k != links[0]}  # one link missing
            assert pin_records((pin,), W, radii)[pin[0]].values == rubbing_at(pin, W, radii[pin[0]])
            checked += 1
    assert checked >= 8
    three = (
        "P",
        ("a", "b", "ground"),
        ("AB", "BC", None),
        ("a|b", "a|ground", "b|ground"),
        (),
        (("AB", "BC"), ("AB", None), ("BC", None)),
    )
    rec = pin_records((three,), {"AB": 2.0, "BC": -3.0}, {"P": 0.5})["P"]
    assert rec.values == (2.5, 1.0, 1.5) and rec.rubbing_velocity == 2.5
