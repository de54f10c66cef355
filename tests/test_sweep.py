"""Full-cycle sweeps against independent references.

* the same quantities from single solves (the scalar path) at sample angles;
* finite differences of the swept positions in the crank angle (velocities and
  accelerations, with a crank acceleration);
* the slider crank's closed form;
* the limit positions of a non-Grashof linkage from the law of cosines;
* a parallelogram through its change points (its velocity ratio is exactly 1).
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from polygon_method import parse_scene, solve
from polygon_method.cli import main
from polygon_method.linkage.summary import summarize, summary_of
from polygon_method.motion.sweeps import sweep
from polygon_method.solver.tracking import Sweeper
from scenes import NON_GRASHOF, SLOTTED_LEVER as SLOTTED

FOURBAR = """
[ground]
A = [0, 0]
D = [100, 0]
[links]
AB = 40
BC = 120
CD = 80
[points]
E = { on = "BC", distances = { B = 70, C = 80 }, turn = "ccw" }
[assembly]
C = "above"
[input]
crank = "AB"
angle = 120
speed = "20 rad/s ccw"
acceleration = "150 rad/s^2 ccw"
[pins]
B = { diameter = 20 }
"""

ENGINE = """
[ground]
O = [0, 0]
[links]
OA = 150
AB = 600
[sliders]
B = { path = "horizontal", through = "O" }
[assembly]
B = "right"
[input]
crank = "OA"
angle = 60
speed = "450 rpm ccw"
[loads]
B = { force = "1 kN", direction = 180 }
"""

PARALLELOGRAM = """
[ground]
A = [0, 0]
D = [100, 0]
[links]
AB = 40
BC = 100
CD = 40
[assembly]
C = "above"
[input]
crank = "AB"
angle = 60
speed = "10 rad/s ccw"
"""


def at_angle(scene, theta):
    """The same scene (and plan: the same branches) with the crank at ``theta``."""
    return dataclasses.replace(scene, input=dataclasses.replace(scene.input, angle=theta))


@pytest.mark.parametrize("text", [FOURBAR, ENGINE, SLOTTED], ids=["fourbar", "engine", "slotted"])
def test_sweep_equals_single_solves(text):
    sc = parse_scene(text)
    degs = np.array([0.0, 37.0, 90.0, 151.5, 222.0, 300.0, 359.0])
    res = sweep(sc, np.radians(degs))
    assert len(res) == len(degs) and res.left_out == 0
    for k, th in enumerate(np.radians(degs)):
        sol = solve(at_angle(sc, float(th)))
        scale_v = abs(sc.input.omega) * 1.0
        for p in sc.point_names:
            for i in (0, 1):
                assert res.P[p][i][k] == pytest.approx(sol.P[p][i], abs=1e-12)
                assert res.V[p][i][k] == pytest.approx(sol.V[p][i], rel=1e-11, abs=1e-12 * scale_v)
                assert res.A[p][i][k] == pytest.approx(
                    sol.A[p][i], rel=1e-10, abs=1e-11 * scale_v**2
                )
        for key in res.W:
            assert res.W[key][k] == pytest.approx(sol.W[key], rel=1e-11, abs=1e-12)
            assert res.Al[key][k] == pytest.approx(sol.Al[key], rel=1e-10, abs=1e-10)
        for s in sc.sliders:
            assert res.S[s.point][0][k] == pytest.approx(sol.S[s.point][0], rel=1e-11, abs=1e-12)
            assert res.S[s.point][1][k] == pytest.approx(sol.S[s.point][1], rel=1e-10, abs=1e-10)
        for pin, r in res.rubbing.items():
            assert r[k] == pytest.approx(sol.rubbing[pin].rubbing_velocity, rel=1e-11)
        if res.input_torque is not None:
            assert res.input_torque[k] == pytest.approx(sol.input_torque, rel=1e-10)


def five_point(f, h):
    """First and second derivatives at the middle of f(-2h), f(-h), f(0), f(h), f(2h)."""
    d1 = (f[0] - 8 * f[1] + 8 * f[3] - f[4]) / (12 * h)
    d2 = (-f[0] + 16 * f[1] - 30 * f[2] + 16 * f[3] - f[4]) / (12 * h * h)
    return d1, d2


@pytest.mark.parametrize("text", [FOURBAR, ENGINE, SLOTTED], ids=["fourbar", "engine", "slotted"])
def test_sweep_matches_finite_differences_of_positions(text):
    """v = w dP/dt, a = w^2 d2P/dt2 + alpha dP/dt (t the crank angle); the same for the
    links' angles, from the swept positions alone."""
    sc = parse_scene(text)
    w, al = sc.input.omega, sc.input.alpha
    h = 1e-3
    centres = np.radians([10.0, 75.0, 140.0, 205.0, 290.0])
    th = (centres[:, None] + h * np.arange(-2, 3)[None, :]).ravel()
    res = sweep(sc, th)
    assert len(res) == len(th)
    scale = max(lk.length for lk in sc.links)
    for p in sc.point_names:
        for i in (0, 1):
            x = res.P[p][i].reshape(-1, 5)
            v = res.V[p][i].reshape(-1, 5)[:, 2]
            a = res.A[p][i].reshape(-1, 5)[:, 2]
            d1, d2 = five_point(x.T, h)
            np.testing.assert_allclose(v, w * d1, atol=1e-8 * abs(w) * scale)
            np.testing.assert_allclose(a, w * w * d2 + al * d1, atol=1e-5 * w * w * scale)
    for lk in sc.links:
        if lk.p in sc.ground and lk.q in sc.ground:
            continue
        (x1, y1), (x2, y2) = res.P[lk.p], res.P[lk.q]
        ang = np.unwrap(np.arctan2(y2 - y1, x2 - x1).reshape(-1, 5), axis=1)
        d1, d2 = five_point(ang.T, h)
        np.testing.assert_allclose(res.W[lk.key].reshape(-1, 5)[:, 2], w * d1, atol=1e-8 * abs(w))
        np.testing.assert_allclose(
            res.Al[lk.key].reshape(-1, 5)[:, 2], w * w * d2 + al * d1, atol=1e-5 * w * w
        )


def test_slider_crank_closed_form():
    """x = r cos t + sqrt(l^2 - r^2 sin^2 t), differentiated by hand."""
    sc = parse_scene(ENGINE)
    r, l, w = 0.15, 0.6, 450 * 2 * math.pi / 60
    t = np.radians(np.arange(0.0, 360.0, 0.5))
    res = sweep(sc, t)
    s, c = np.sin(t), np.cos(t)
    q = np.sqrt(l * l - r * r * s * s)
    x = r * c + q
    dx = -r * s - r * r * s * c / q
    d2x = -r * c - r * r * (c * c - s * s) / q - r**4 * s * s * c * c / q**3
    np.testing.assert_allclose(res.P["B"][0], x, rtol=0, atol=1e-13)
    np.testing.assert_allclose(res.S["B"][0], w * dx, rtol=0, atol=1e-11)
    np.testing.assert_allclose(res.A["B"][0], w * w * d2x, rtol=0, atol=1e-9)
    # the rod: sin(phi) = -r sin t / l (phi of A -> B), omega = dphi/dt
    phi_dot = -r * c / (l * np.cos(np.arcsin(r * s / l)))
    np.testing.assert_allclose(res.W["AB"], w * phi_dot, rtol=0, atol=1e-11)
    # the power balance: T w = -F . v with F = 1 kN towards -x
    np.testing.assert_allclose(res.input_torque, -(-1000.0 * w * dx) / w, rtol=1e-12, atol=1e-9)


def test_non_grashof_stops_at_limit_positions():
    """O2A 150, AB 450, BO4 300, O2O4 200: B assembles while O4A >= AB - BO4 = 150 mm,
    150^2 + 200^2 - 2 (150)(200) cos t >= 150^2, cos t <= 2/3 (the discriminant vanishes
    at cos t = 2/3)."""
    sc = parse_scene(NON_GRASHOF)
    lim = math.acos(2.0 / 3.0)
    dom = Sweeper(sc).domain
    assert not dom.full_turn
    assert dom.lo == pytest.approx(lim, abs=1e-10)
    assert dom.hi == pytest.approx(2 * math.pi - lim, abs=1e-10)
    assert len(dom.limits) == 2
    t = np.radians(np.arange(0.0, 360.0, 1.0))
    res = sweep(sc, t)
    inside = (t > lim) & (t < 2 * math.pi - lim)
    assert len(res) == int(inside.sum()) and res.left_out == int((~inside).sum())
    np.testing.assert_array_equal(res.theta, t[inside])
    for arr in list(res.W.values()) + [v for xy in res.V.values() for v in xy]:
        assert np.isfinite(arr).all()
    # the branch stays the scene's: B on the same side of the line A -> O4 throughout
    (ax, ay), (bx, by) = res.P["A"], res.P["B"]
    side = (0.2 - ax) * (by - ay) - (0.0 - ay) * (bx - ax)
    assert (side < 0).all() or (side > 0).all()
    s = summarize(sc, t)
    assert s.requested == 360 and s.evaluated == len(res)
    assert "cannot turn fully" in s.text()


def test_parallelogram_keeps_its_branch_through_the_change_points():
    """A parallelogram's output turns with the crank (omega_CD = omega_AB, omega_BC = 0) on
    both sides of its change points (0 and 180 deg), sampled on them too."""
    sc = parse_scene(PARALLELOGRAM)
    t = np.radians(np.arange(0.0, 360.0, 0.5))
    res = sweep(sc, t)
    assert len(res) == len(t)
    cps = res.change_points
    # located to about sqrt(eps): at a tangency the circles' intersection is that sharp
    at = sorted((math.degrees(c.theta) + 90) % 360 - 90 for c in cps)
    assert at == pytest.approx([0.0, 180.0], abs=1e-5)
    assert all(c.followed for c in cps)
    np.testing.assert_allclose(res.W["CD"], 10.0, rtol=0, atol=1e-8)
    np.testing.assert_allclose(res.W["BC"], 0.0, rtol=0, atol=1e-8)
    np.testing.assert_allclose(res.Al["CD"], 0.0, rtol=0, atol=1e-5)
    # C = B + (AD): the coupler translates
    np.testing.assert_allclose(res.P["C"][0], res.P["B"][0] + 0.1, atol=1e-12)
    np.testing.assert_allclose(res.P["C"][1], res.P["B"][1], atol=1e-12)


def test_summary_extremes_of_the_engine():
    """The largest piston speed of an in-line slider crank, n = 4, by closed form: the
    root of d/dt [sin t + r sin t cos t / sqrt(l^2 - r^2 sin^2 t) ...] found by a dense
    grid and golden section here."""
    sc = parse_scene(ENGINE)
    r, l, w = 0.15, 0.6, 450 * 2 * math.pi / 60

    def v(t):
        s, c = math.sin(t), math.cos(t)
        return r * w * (s + r * s * c / math.sqrt(l * l - r * r * s * s))

    a, b = math.radians(60), math.radians(90)
    g = (math.sqrt(5) - 1) / 2
    for _ in range(200):
        c1, c2 = b - g * (b - a), a + g * (b - a)
        if v(c1) > v(c2):
            b = c2
        else:
            a = c1
    tmax = (a + b) / 2
    s = summarize(sc, np.radians(np.arange(0.0, 360.0, 1.0)))
    e = s.extreme("vs_B")
    assert -e.minimum == pytest.approx(v(tmax), rel=1e-12)
    assert e.at_min == pytest.approx(math.degrees(tmax), abs=1e-5)
    assert e.maximum == pytest.approx(v(tmax), rel=1e-12)
    assert e.at_max == pytest.approx(360 - math.degrees(tmax), abs=1e-5)
    stroke = s.extreme("s_B")
    assert stroke.maximum - stroke.minimum == pytest.approx(2 * r, rel=1e-12)
    text = s.text()
    assert "maximum piston velocity" in text
    # the notes' formula: cos t = (-n + sqrt(n^2 + 8)) / 4 with n = 4
    t_ap = math.acos((-4 + math.sqrt(24)) / 4)
    v_ap = r * w * (math.sin(t_ap) + math.sin(2 * t_ap) / 8)
    assert f"{v_ap:.6g}" in text and f"{math.degrees(t_ap):.4f}" in text


def test_summary_reduces_like_the_stored_sweep():
    sc = parse_scene(FOURBAR)
    t = np.radians(np.arange(0.0, 360.0, 0.25))
    a = summarize(sc, t, chunk=97, refine=False)
    b = summary_of(sweep(sc, t), refine=False)
    for ea, eb in zip(a.extremes, b.extremes):
        assert ea.name == eb.name
        assert ea.maximum == pytest.approx(eb.maximum, rel=1e-13, abs=1e-15)
        assert ea.minimum == pytest.approx(eb.minimum, rel=1e-13, abs=1e-15)


def test_chunks_do_not_change_the_values():
    sc = parse_scene(SLOTTED)
    t = np.radians(np.arange(0.0, 360.0, 0.7))
    a, b = sweep(sc, t, chunk=50), sweep(sc, t)
    for k in a.W:
        np.testing.assert_array_equal(a.W[k], b.W[k])
        np.testing.assert_array_equal(a.Al[k], b.Al[k])


def test_csv_and_plot_from_the_command_line(tmp_path, capsys):
    scene = tmp_path / "fb.toml"
    scene.write_text(FOURBAR)
    csv, svg = tmp_path / "out.csv", tmp_path / "out.svg"
    assert (
        main(
            [
                "sweep",
                str(scene),
                "--from",
                "0",
                "--to",
                "90",
                "--step",
                "10",
                "--csv",
                str(csv),
                "--plot",
                str(svg),
                "--points",
                "C,E",
            ]
        )
        == 0
    )
    rows = csv.read_text().splitlines()
    assert len(rows) == 1 + 10
    header = rows[0].split(",")
    assert header[0] == "theta [deg]" and "omega_BC [rad/s]" in header
    data = np.array([[float(x) for x in r.split(",")] for r in rows[1:]])
    np.testing.assert_allclose(data[:, 0], np.arange(0, 91, 10))
    sol = solve(at_angle(parse_scene(FOURBAR), math.radians(30)))
    j = header.index("omega_BC [rad/s]")
    assert data[3, j] == pytest.approx(sol.W["BC"], rel=1e-9)
    assert svg.read_text().lstrip().startswith("<?xml")


@pytest.mark.parametrize(
    "argv, says",
    [
        (["--steps", "0"], "--steps"),
        (["--from", "0", "--to", "90"], "--step"),
        (["--from", "0", "--to", "90", "--step", "-5"], "--step"),
        (["--steps", "10", "--from", "0", "--to", "90", "--step", "5"], "either"),
        (["--plot", "out.txt"], "--plot"),
        (["--plot", "out.svg", "--points", "Z"], "no point Z"),
    ],
)
def test_bad_sweep_arguments_one_line_exit_2(tmp_path, capsys, argv, says):
    scene = tmp_path / "fb.toml"
    scene.write_text(FOURBAR)
    argv = [a if not a.startswith("out.") else str(tmp_path / a) for a in argv]
    assert main(["sweep", str(scene), *argv]) == 2
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and says in err
    assert not list(tmp_path.glob("out.*"))


def test_unreachable_request_is_an_error(tmp_path, capsys):
    scene = tmp_path / "ng.toml"
    scene.write_text(NON_GRASHOF)
    assert (
        main(
            [
                "sweep",
                str(scene),
                "--from",
                "0",
                "--to",
                "40",
                "--step",
                "1",
                "--csv",
                str(tmp_path / "out.csv"),
            ]
        )
        == 2
    )
    assert "none of the requested crank angles" in capsys.readouterr().err
    assert not (tmp_path / "out.csv").exists()


def test_package_level_sweep_is_the_function():
    import polygon_method as pm

    sc = parse_scene(ENGINE)
    res = pm.sweep(sc, [math.radians(90.0)])
    # at 90 deg the rod's angle is stationary: the piston moves with the crank pin
    assert res.sliding_velocity("B")[0] == pytest.approx(-0.15 * 450 * math.pi / 30, rel=1e-12)


def test_the_plot_title_stays_inside_the_figure():
    """A long scene title is wrapped, never clipped at the figure's edges."""
    from pathlib import Path

    from polygon_method import load_scene
    from polygon_method.draw.plots import plot_figure

    sc = load_scene(
        Path(__file__).resolve().parent.parent / "worked_problems" / "fourbar_image_points.toml"
    )
    fig = plot_figure(sweep(sc))
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    box = fig._suptitle.get_window_extent(canvas.get_renderer())
    assert box.x0 >= 0 and box.x1 <= fig.bbox.x1 and box.y1 <= fig.bbox.y1
