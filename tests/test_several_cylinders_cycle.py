"""Several cylinders on one crank under their indicator diagrams: each cylinder's gas force
in its own phase ([indicator] with a sub-table per piston: a shared table with a lag, or the
piston's own), the turning-moment diagram the sum over the cylinders, its mean, the
fluctuation of energy and the flywheel.

The references are independent of the tool:

- at an instant, a V-twin and a radial with every body massive and gravity: the matrix
  Newton-Euler method at 30 digits of ``test_several_cylinders`` (closed-form positions,
  mpmath's differentiation), each cylinder's pressure interpolated here from its table at
  its own phase;
- over the cycle, the pistons alone massive (the books' reciprocating parts) and the crank
  steady: the virtual power in closed form at 30 digits, ``T = sum_k (-p_k A - m w^2 s_k'')
  s_k'`` (``s_k`` the piston's distance from the crank centre along its line, its
  derivatives written out and held to mpmath's differentiation), the mean and the energies
  by mpmath's quadrature between the corners of every cylinder's table, the crossings by
  mpmath's root finder, to 1e-9.
"""

from __future__ import annotations

import math

import mpmath
import numpy as np
import pytest

from polygon_method.cli import main
from polygon_method.forces.engine import cylinder_efforts
from polygon_method.linkage.flywheel import turning_moment
from polygon_method.motion.solution import solve
from polygon_method.scene import parse_scene

from test_several_cylinders import R, L, VTWIN, RADIAL, reference, scene_text

#: a four-stroke table (bar) against the crank angle from the inner dead centre
ANGLES = [0, 180, 240, 300, 330, 360, 375, 390, 420, 450, 480, 540, 560, 720]
BAR = [-0.1, -0.1, 0.8, 3.0, 6.0, 12.0, 40.0, 32.0, 18.0, 10.0, 6.0, 3.0, 0.2, -0.1]
#: a two-stroke table (N/mm^2) for the radial's own tables
ANGLES2 = [0, 20, 60, 120, 180, 240, 300, 345, 360]
MPA2 = [3.5, 2.8, 1.2, 0.5, 0.1, 0.15, 0.6, 2.0, 3.5]
MPA2_C = [2.0, 2.4, 1.0, 0.3, 0.05, 0.1, 0.4, 1.2, 2.0]
#: a four-stroke table against the stroke (fractions from the inner dead centre; bar, one
#: row a stroke: suction, compression, expansion, exhaust)
PLACES = [0, 0.1, 0.25, 0.5, 0.75, 1]
ROWS = [
    [-0.1, -0.15, -0.15, -0.1, -0.1, 0.0],
    [0.0, 0.8, 1.5, 3.0, 6.0, 12.0],
    [40.0, 30.0, 18.0, 9.0, 5.0, 3.0],
    [0.2, 0.15, 0.1, 0.1, 0.0, -0.1],
]


def _indicator_tables(kind):
    """The [indicator] text and {piston: (its table's angles deg, pressures Pa, lag deg)}."""
    if kind == "v-twin":  # one shared four-stroke table, C's cycle 450 deg after B's
        text = (
            '[indicator]\nbore = 80\ncycle = "4-stroke"\nunit = "bar"\n'
            f"angle = {ANGLES}\npressure = {BAR}\n[indicator.B]\n[indicator.C]\nlag = 450\n"
        )
        return text, {
            "B": (ANGLES, [p * 1e5 for p in BAR], 0),
            "C": (ANGLES, [p * 1e5 for p in BAR], 450),
        }
    if kind == "stroke":  # a V-twin on one four-stroke table against the stroke, C's lag
        # left to the geometry (90 deg: its inner dead centre on the first turn)
        text = (
            '[indicator]\nbore = 80\ncycle = "4-stroke"\nunit = "bar"\n'
            f"stroke = {PLACES}\npressure = {ROWS}\n[indicator.B]\n[indicator.C]\n"
        )
        rows = [[p * 1e5 for p in row] for row in ROWS]
        return text, {"B": (PLACES, rows, 0, "stroke"), "C": (PLACES, rows, 90, "stroke")}
    # the radial: two-stroke, B and D the shared table, C its own; the lags left to the
    # geometry (C's inner dead centre 120 deg after B's, D's 240 deg)
    text = (
        '[indicator]\nbore = 80\nunit = "N/mm^2"\n'
        f"angle = {ANGLES2}\npressure = {MPA2}\n[indicator.B]\n"
        f"[indicator.C]\nangle = {ANGLES2}\npressure = {MPA2_C}\n[indicator.D]\n"
    )
    mpa = [p * 1e6 for p in MPA2]
    return text, {
        "B": (ANGLES2, mpa, 0),
        "C": (ANGLES2, [p * 1e6 for p in MPA2_C], 120),
        "D": (ANGLES2, mpa, 240),
    }


def _interp(xs, ps, x):
    """The table's value at ``x`` (deg, within it), linear between readings."""
    for a, b, pa, pb in zip(xs, xs[1:], ps, ps[1:]):
        if a <= x <= b:
            return pa + (pb - pa) * (x - a) / (b - a)
    raise AssertionError(x)


def _massive_scene(cyl, kind, angle):
    """``test_several_cylinders``' scene (every body massive, gravity) with the indicator
    in place of the steady pressures."""
    text = scene_text(cyl, angle)
    text = text[: text.index("[loads]")]
    return text + _indicator_tables(kind)[0]


@pytest.mark.parametrize(
    "cyl, kind, angle",
    [
        (VTWIN, "v-twin", 400.0),
        (VTWIN, "v-twin", 100.0),
        (VTWIN, "v-twin", 650.0),
        (RADIAL, "radial", 30.0),
        (RADIAL, "radial", 250.0),
    ],
)
def test_each_cylinder_in_its_phase_against_the_matrix_method(cyl, kind, angle):
    _, tables = _indicator_tables(kind)
    first = next(iter(cyl))
    cycle = 720 if kind == "v-twin" else 360
    pressures = {}
    for p, (deg, _) in cyl.items():
        xs, ps, lag = tables[p]
        phase = (angle - cyl[first][0] - lag) % cycle  # the crank angle from its own i.d.c.
        pressures[p] = (deg, _interp(xs, ps, phase) / 1e6)  # N/mm^2, as the reference takes
    ref = reference(pressures, angle)
    sol = solve(parse_scene(_massive_scene(cyl, kind, angle)))
    size = max(abs(v) for v in ref.values())
    es = cylinder_efforts(sol.scene, sol.plan, sol.P, sol.forces)
    assert [e.piston for e in es] == list(cyl)
    for e in es:
        assert e.F_T == pytest.approx(ref["F_T" + e.piston], abs=1e-9 * size)
        assert e.F_P == pytest.approx(ref["F_P" + e.piston], abs=1e-9 * size)
    total = sum(ref["F_T" + p] for p in cyl) * R
    assert sum(e.T for e in es) == pytest.approx(total, abs=1e-9 * size * R)
    assert sol.forces.input_torque == pytest.approx(ref["T"], abs=1e-9 * size * R)


# -- over the cycle: the pistons alone massive, the virtual power in closed form ----------

M_PISTON, W = 1.2, 3000 * math.pi / 30
AREA = math.pi / 4 * 0.08**2


def _cycle_scene(cyl, kind, flywheel=True):
    links = "\n".join(f"A{p} = 240" for p in cyl)
    sliders = "\n".join(f'{p} = {{ path = {a}, through = "O" }}' for p, (a, _) in cyl.items())
    masses = "\n".join(f'{p} = {{ mass = "{M_PISTON} kg" }}' for p in cyl)
    assembly = "\n".join(f'{p} = "{"above" if a < 180 else "below"}"' for p, (a, _) in cyl.items())
    fw = '[flywheel]\nplus_minus = "1%"\nradius = 150\n' if flywheel else ""
    return f"""
title = "cylinders on one crank over the cycle"
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 60
{links}
[sliders]
{sliders}
[assembly]
{assembly}
[input]
crank = "OA"
angle = 45
speed = "3000 rpm ccw"
[masses]
{masses}
{_indicator_tables(kind)[0]}
{fw}"""


class _Reference:
    """The summed turning moment against the diagram's phase (rad from the first
    cylinder's inner dead centre) in closed form at 30 digits."""

    def __init__(self, cyl, kind):
        self.cyl, self.tables = cyl, _indicator_tables(kind)[1]
        self.cycle = 360 if kind == "radial" else 720
        self.first = cyl[next(iter(cyl))][0]

    @staticmethod
    def s_derivatives(psi):
        """s', s'' (d/dtheta) of the piston's distance s = r cos psi + sqrt(l^2 - r^2
        sin^2 psi), psi the crank's angle from the piston's line."""
        r, l = mpmath.mpf(R), mpmath.mpf(L)
        sn, cs = mpmath.sin(psi), mpmath.cos(psi)
        q = mpmath.sqrt(l * l - r * r * sn * sn)
        d1 = -r * sn - r * r * sn * cs / q
        d2 = -r * cs - r * r * (cs * cs - sn * sn) / q - r**4 * sn * sn * cs * cs / q**3
        return d1, d2

    def __call__(self, phase):
        theta_deg = self.first + mpmath.degrees(phase)
        total = mpmath.mpf(0)
        for p, (deg, _) in self.cyl.items():
            xs, ps, lag = self.tables[p][:3]
            own = (mpmath.degrees(phase) - lag) % self.cycle
            psi = mpmath.radians(theta_deg - deg)
            if len(self.tables[p]) == 4:  # against the stroke: the row of its stroke
                s = R * mpmath.cos(psi) + mpmath.sqrt(L**2 - R**2 * mpmath.sin(psi) ** 2)
                x = min(max((L + R - s) / (2 * R), 0), 1)
                pr = _interp(xs, ps[min(int(own // 180), 3)], x)
            else:
                pr = _interp(xs, ps, own)
            d1, d2 = self.s_derivatives(psi)
            total += (-pr * AREA - M_PISTON * W**2 * d2) * d1
        return total

    def corners(self):
        """The phases (rad) where a cylinder's pressure has a corner: its table's angles
        shifted by its lag."""
        out = {mpmath.mpf(0), mpmath.mpf(self.cycle)}
        for table in self.tables.values():
            xs, _, lag = table[:3]
            if len(table) == 4:  # the dead centres and the places of stroke, each stroke
                out |= {mpmath.mpf((k * 180 + lag) % self.cycle) for k in range(4)}
                for k in range(4):
                    for x in xs:  # cos psi where the piston is at x: the cosine rule
                        s = L + R - 2 * R * mpmath.mpf(x)
                        c = min(max((s * s + R * R - L * L) / (2 * R * s), -1), 1)
                        a = mpmath.degrees(mpmath.acos(c))
                        own = k * 180 + (a if k % 2 == 0 else 180 - a)
                        out.add((own + lag) % self.cycle)
            else:
                out |= {mpmath.mpf((x + lag) % self.cycle) for x in xs}
        return [mpmath.radians(x) for x in sorted(out)]

    def integral(self, a, b):
        """int_a^b T dphase (a < b within the cycle) between the corners."""
        cuts = [a] + [c for c in self.corners() if a < c < b] + [b]
        return mpmath.quad(self, cuts)


def test_the_written_out_derivatives_are_mpmaths():
    with mpmath.workdps(30):
        for psi in (0.3, 1.9, 4.4):
            d1, d2 = _Reference.s_derivatives(mpmath.mpf(psi))

            def s(t):
                return R * mpmath.cos(t) + mpmath.sqrt(L**2 - R**2 * mpmath.sin(t) ** 2)

            assert abs(d1 - mpmath.diff(s, psi)) < 1e-15
            assert abs(d2 - mpmath.diff(s, psi, 2)) < 1e-12


@pytest.mark.parametrize(
    "cyl, kind",
    [(VTWIN, "v-twin"), (RADIAL, "radial"), (VTWIN, "stroke")],
    ids=["v-twin", "radial", "against-the-stroke"],
)
def test_the_cycle_of_the_summed_diagram_against_the_quadrature(cyl, kind):
    sc = parse_scene(_cycle_scene(cyl, kind))
    tm = turning_moment(sc)
    ref = _Reference(cyl, kind)
    if kind == "stroke":  # the default lag is said
        assert "C's cycle 90 deg after B's (the least: its first inner dead centre)" in tm.words
    with mpmath.workdps(30):
        cycle = mpmath.radians(ref.cycle)
        work = ref.integral(mpmath.mpf(0), cycle)
        mean = work / cycle
        size = float(max(abs(ref(mpmath.radians(x))) for x in range(0, ref.cycle, 2)))
        assert tm.mean == pytest.approx(float(mean), abs=1e-9 * size)
        # the crossings: every sign change of T - mean on a 0.1 deg grid, refined here
        grid = [mpmath.radians(x / 10) for x in range(0, 10 * ref.cycle + 1)]
        vals = [ref(x) - mean for x in grid]
        roots = []
        for a, b, fa, fb in zip(grid, grid[1:], vals, vals[1:]):
            if fa * fb < 0:
                roots.append(mpmath.findroot(lambda x: ref(x) - mean, (a, b), solver="anderson"))
        assert len(tm.crossings) == len(roots) >= 2
        for got, want in zip(tm.crossings, roots):
            assert got == pytest.approx(float(mpmath.degrees(want)), abs=1e-9 * ref.cycle)
        # the energy at each crossing, from the first, by quadrature of T - mean
        E = [mpmath.mpf(0)]
        for a, b in zip(roots, roots[1:]):
            E.append(E[-1] + ref.integral(a, b) - mean * (b - a))
        dE = max(E) - min(E)
        assert tm.dE_max == pytest.approx(float(dE), rel=1e-9)
        areas = [b - a for a, b in zip(E, E[1:])] + [E[0] - E[-1]]
        assert [lb.energy for lb in tm.lobes] == pytest.approx(
            [float(x) for x in areas], abs=1e-9 * float(dE)
        )
        cs, w, inertia, mass = tm.flywheel
        assert (cs, w) == (0.02, pytest.approx(W, rel=1e-15))
        assert inertia == pytest.approx(float(dE / (W**2 * 0.02)), rel=1e-9)
        assert mass == pytest.approx(float(dE / (W**2 * 0.02) / mpmath.mpf("0.15") ** 2), rel=1e-9)


def test_a_shared_table_gives_each_cylinder_the_work_of_one():
    """Two cylinders on one table do twice one cylinder's work per cycle (the inertia does
    none): the mean torque is twice the single cylinder's."""
    sc = parse_scene(_cycle_scene(VTWIN, "v-twin", flywheel=False))
    tm = turning_moment(sc)
    with mpmath.workdps(30):  # one cylinder's work: its turning moment over the cycle
        ref = _Reference({"B": VTWIN["B"]}, "v-twin")
        one = ref.integral(mpmath.mpf(0), mpmath.radians(720))
    assert tm.mean == pytest.approx(2 * float(one) / (4 * math.pi), rel=1e-9)


def _views(tmp_path, text, *args):
    path = tmp_path / "e.toml"
    path.write_text(text)
    return main([*args, str(path)])


def test_solve_json_and_the_summary_give_the_cycle(tmp_path, capsys):
    text = _cycle_scene(VTWIN, "v-twin")
    tm = turning_moment(parse_scene(text))
    assert _views(tmp_path, text, "solve") == 0
    out = capsys.readouterr().out
    assert "the cylinders B, C on one crank, their turning moments summed" in out
    assert "C's cycle 450 deg after B's (given)" in out
    assert "dE_max = E_max - E_min" in out and f"{tm.dE_max:.6g} J" in out
    assert _views(tmp_path, text, "solve", "--json") == 0
    import json

    d = json.loads(capsys.readouterr().out)["turning_moment"]
    assert d["dE_max"] == pytest.approx(tm.dE_max, rel=1e-12)
    assert d["flywheel"]["I"] == pytest.approx(tm.flywheel[2], rel=1e-12)


@pytest.mark.parametrize(
    "old, new, words",
    [
        ("lag = 450", "lag = 400", "lag = 90, 450 (deg)"),
        ("[indicator.B]\n", "[indicator.B]\nlag = 30\n", "[indicator.B] lag"),
        (
            'cycle = "4-stroke"\n',
            'cycle = "4-stroke"\npiston = "B"\n',
            "the sub-tables name the pistons",
        ),
        (
            "lag = 450",
            'lag = 450\ncycle = "2-stroke"\nangle = [0, 360]\npressure = [1, 1]',
            "share their cycle",
        ),
        ("lag = 450", "lag = 450\nbores = 80", "[indicator.C] bores"),
        ("lag = 450", "lag = 900", "[indicator.C] lag"),
        ("[indicator.C]", "[indicator.E]", "[indicator.E] piston"),
    ],
)
def test_a_bad_indicator_of_several_cylinders_is_one_line(tmp_path, capsys, old, new, words):
    text = _cycle_scene(VTWIN, "v-twin")
    assert old in text
    path = tmp_path / "bad.toml"
    path.write_text(text.replace(old, new, 1))
    assert main(["solve", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err, err


@pytest.mark.parametrize("command", ["solve", "steps", "sweep", "check"])
@pytest.mark.parametrize("dotted", [False, True])
def test_a_lag_that_misses_its_dead_centre_names_its_line(tmp_path, capsys, command, dotted):
    """The lag found wrong by the force analysis (not when the file is read) names the line
    it is on, under the dotted header ``[indicator.C]`` or as ``C.lag`` under
    ``[indicator]``: the line counted here from the text, by hand."""
    text = _cycle_scene(VTWIN, "v-twin").replace("lag = 450", "lag = 400", 1)
    if dotted:
        text = text.replace("[indicator.C]\nlag = 400\n", "").replace(
            "[indicator.B]\n", "B = {}\nC.lag = 400\n", 1
        )
    if command == "check":  # an answer that needs the cycle: the lag's fault, not its
        text += '\n[answers]\nT_mean = "100 N m"\n'
    line = [i for i, s in enumerate(text.split("\n"), 1) if "lag = 400" in s]
    assert len(line) == 1
    path = tmp_path / "lag.toml"
    path.write_text(text)
    assert main([command, str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "lag = 90, 450 (deg)" in err, err
    assert f"[indicator.C] lag (line {line[0]})" in err, err


def test_a_lag_on_the_first_cylinder_names_its_line(tmp_path, capsys):
    """Refused as the file is read: ``C.lag`` under [indicator] before B's sub-table makes
    C the first cylinder (no lag there); its line named all the same."""
    text = _cycle_scene(VTWIN, "v-twin").replace("[indicator.C]\nlag = 450\n", "")
    text = text.replace("[indicator.B]\n", "C.lag = 450\n[indicator.B]\n", 1)
    line = [i for i, s in enumerate(text.split("\n"), 1) if s.startswith("C.lag = 450")]
    path = tmp_path / "first.toml"
    path.write_text(text)
    assert main(["solve", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert "C's is the first cylinder" in err, err
    assert len(line) == 1 and f"[indicator.C] lag (line {line[0]})" in err, err


# -- check: each cylinder's keys --------------------------------------------------------


def _check(tmp_path, capsys, text, answers):
    path = tmp_path / "a.toml"
    path.write_text(text + "[answers]\n" + answers)
    code = main(["check", str(path), "--json"])
    import json

    return code, json.loads(capsys.readouterr().out)


def _given(v):
    return f"{v:.10g}"


@pytest.mark.parametrize("cyl, kind, angle", [(VTWIN, "v-twin", 400.0), (RADIAL, "radial", 250.0)])
def test_each_pistons_keys_against_the_matrix_method(tmp_path, capsys, cyl, kind, angle):
    ref = reference(_pressures(cyl, kind, angle), angle)
    lines = []
    for p in cyl:
        lines += [
            f'piston_effort_{p} = "{_given(abs(ref["F_P" + p]))} N"',
            f'crank_effort_{p} = "{_given(abs(ref["F_T" + p]))} N"',
            f'turning_moment_{p} = "{_given(abs(ref["F_T" + p] * R))} N m"',
            f'rod_thrust_{p} = "{_given(math.hypot(ref[f"P{p}.x"], ref[f"P{p}.y"]))} N"',
            f'side_thrust_{p} = "{_given(abs(ref["N" + p]))} N"',
        ]
    code, out = _check(tmp_path, capsys, _massive_scene(cyl, kind, angle), "\n".join(lines) + "\n")
    verdicts = out["answers"]
    assert code == 0 and len(verdicts) == 5 * len(cyl)
    for v in verdicts:  # the tool's own value, to the matrix method's
        assert v["verdict"] == "right" and v["correct"] == pytest.approx(v["given"], rel=1e-9)


def _pressures(cyl, kind, angle):
    """{piston: (its line's angle, its pressure N/mm^2 at ``angle``)} from its table."""
    _, tables = _indicator_tables(kind)
    first = next(iter(cyl))
    cycle = 720 if kind == "v-twin" else 360
    out = {}
    for p, (deg, _) in cyl.items():
        xs, ps, lag = tables[p]
        out[p] = (deg, _interp(xs, ps, (angle - cyl[first][0] - lag) % cycle) / 1e6)
    return out


def test_a_pistons_inertia_left_out_is_named_for_that_piston(tmp_path, capsys, monkeypatch):
    """The piston effort and crank effort of C given as if its piston had no mass: the
    matrix method with C's piston massless (and weightless) gives the slip's values."""
    import test_several_cylinders as ts

    angle = 400.0
    pr = _pressures(VTWIN, "v-twin", angle)
    right = reference(pr, angle)
    text = _massive_scene(VTWIN, "v-twin", angle)
    monkeypatch.setattr(ts, "M_PISTON", 0.0)
    slip = reference(pr, angle)
    assert abs(slip["F_PC"] - right["F_PC"]) > 0.05 * abs(right["F_PC"])  # (a slip to tell)
    answers = (
        f'piston_effort_C = "{_given(abs(slip["F_PC"]))} N"\n'
        f'crank_effort_C = "{_given(abs(slip["F_TC"]))} N"\n'
    )
    code, out = _check(tmp_path, capsys, text, answers)
    assert code == 1
    for v in out["answers"]:
        assert v["verdict"] == "wrong" and v["mistake"] == "piston_inertia_left_out", v


@pytest.mark.parametrize(
    "key, words",
    [
        ("piston_effort", "name the piston, piston_effort_B"),
        ("side_thrust", "name the piston, side_thrust_B"),
        ("piston_effort_Z", "Z is no slider of the scene"),
        ("crank_effort_A", "A is no slider of the scene"),
    ],
)
def test_a_key_of_no_cylinder_is_one_line(tmp_path, capsys, key, words):
    path = tmp_path / "a.toml"
    path.write_text(_cycle_scene(VTWIN, "v-twin") + f'[answers]\n{key} = "100 N"\n')
    assert main(["check", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and words in err and f"[answers] {key}" in err, err


def test_the_cycles_keys_and_their_slips(tmp_path, capsys):
    text = _cycle_scene(VTWIN, "v-twin")
    tm = turning_moment(parse_scene(text))
    inertia = tm.flywheel[2]
    answers = (
        f'T_mean = "{_given(2 * tm.mean)} N m"\ndE_max = "{_given(tm.dE_max)} J"\n'
        f'I_flywheel = "{_given(2 * inertia)} kg m^2"\nm_flywheel = "{_given(tm.flywheel[3])} kg"\n'
    )
    code, out = _check(tmp_path, capsys, text, answers)
    verdicts = out["answers"]
    assert [v["verdict"] for v in verdicts] == ["wrong", "right", "wrong", "right"]
    assert verdicts[0]["mistake"] == "one_turn_cycle"  # a four-stroke's work over one turn
    assert verdicts[2]["mistake"] == "cs_half_range"


# -- the sweep's views ----------------------------------------------------------------


def test_the_sweep_csv_summary_and_plot_of_the_summed_diagram(tmp_path, capsys):
    import csv

    text = _cycle_scene(VTWIN, "v-twin")
    path = tmp_path / "e.toml"
    path.write_text(text)
    out = tmp_path / "e.csv"
    assert main(["sweep", str(path), "--csv", str(out), "--steps", "36"]) == 0
    rows = list(csv.DictReader(out.open()))
    assert len(rows) == 72 and float(rows[-1]["theta [deg]"]) > 360  # the 720 deg cycle
    ref = _Reference(VTWIN, "v-twin")
    with mpmath.workdps(30):
        for row in rows[::5]:  # each row's crank angle, as the diagram's phase from B's
            phase = mpmath.radians(float(row["theta [deg]"]) - VTWIN["B"][0])
            want = float(ref(phase % (4 * mpmath.pi)))
            assert float(row["turning_moment [N m]"]) == pytest.approx(want, abs=1e-9 * 1e3)
    capsys.readouterr()
    assert main(["sweep", str(path), "--summary"]) == 0
    summary = capsys.readouterr().out
    tm = turning_moment(parse_scene(text))
    assert "the cylinders B, C on one crank, their turning moments summed" in summary
    assert f"dE_max = E_max - E_min = {tm.E_max:.6g} - ({tm.E_min:.6g})" in summary
    from polygon_method.draw.plots import plot_figure
    from polygon_method.motion.sweeps import sweep

    sc = parse_scene(text)
    fig = plot_figure(sweep(sc, np.radians(np.arange(0.0, 720.0, 10.0))))
    panel = fig.axes[-1]
    labels = [ln.get_label() for ln in panel.lines]
    assert {"cylinder B", "cylinder C", "turning moment T (the sum)"} <= set(labels)
    assert "inner dead centre of B" in panel.get_xlabel()
    lines = {ln.get_label(): ln for ln in panel.lines}
    x = lines["turning moment T (the sum)"].get_xdata()
    total = lines["turning moment T (the sum)"].get_ydata()
    parts = lines["cylinder B"].get_ydata() + lines["cylinder C"].get_ydata()
    assert np.allclose(total, parts, rtol=0, atol=1e-9 * np.abs(total).max())
    with mpmath.workdps(30):
        for k in (0, 200, 777, 1300):  # the plotted sum at its phase, to the closed form
            assert total[k] == pytest.approx(float(ref(mpmath.radians(x[k]))), abs=1e-9 * 1e3)


def test_the_worked_v_twin_against_the_closed_form(capsys):
    """``worked_problems/vtwin_flywheel.toml`` (this file's V-twin, its instant 390 deg after
    B's inner dead centre): each stated answer to the virtual power in closed form to its
    four figures, the tool's to 1e-9, and ``check`` holds them all."""
    from pathlib import Path

    from polygon_method.scene import load_scene

    path = Path(__file__).resolve().parent.parent / "worked_problems" / "vtwin_flywheel.toml"
    sc = load_scene(path)
    ref = _Reference(VTWIN, "v-twin")
    want = {}
    with mpmath.workdps(30):
        total = mpmath.mpf(0)
        for p, (deg, _) in VTWIN.items():
            xs, ps, lag = ref.tables[p]
            pr = _interp(xs, ps, (435 - VTWIN["B"][0] - lag) % 720)
            d1, d2 = ref.s_derivatives(mpmath.radians(435 - deg))
            F_P = pr * AREA + M_PISTON * W**2 * d2  # towards the crank
            want[f"piston_effort_{p}"] = F_P
            want[f"crank_effort_{p}"] = -F_P * d1 / R
            want[f"turning_moment_{p}"] = -F_P * d1
            total += -F_P * d1
        want["turning_moment"] = total
        cycle = 4 * mpmath.pi
        mean = ref.integral(mpmath.mpf(0), cycle) / cycle
        want["T_mean"] = mean
        tm = turning_moment(sc)
        roots = [
            mpmath.findroot(lambda x: ref(x) - mean, mpmath.radians(c), tol=1e-25)
            for c in tm.crossings
        ]
        E = [mpmath.mpf(0)]
        for a, b in zip(roots, roots[1:]):
            E.append(E[-1] + ref.integral(a, b) - mean * (b - a))
        dE = max(E) - min(E)
        want["dE_max"] = dE
        want["I_flywheel"] = dE / (W**2 * mpmath.mpf("0.02"))
        want["m_flywheel"] = want["I_flywheel"] / mpmath.mpf("0.15") ** 2
    assert tm.mean == pytest.approx(float(mean), rel=1e-9)
    assert tm.dE_max == pytest.approx(float(dE), rel=1e-9)
    stated = {a.key: a.value for a in sc.answers}
    assert set(stated) == set(want) - {"piston_effort_C", "crank_effort_C"}
    for key, v in stated.items():  # to the four figures stated
        assert v == pytest.approx(abs(float(want[key])), rel=6e-4), key
    assert main(["check", str(path)]) == 0
    assert "9 of 9 right" in capsys.readouterr().out


@pytest.mark.parametrize("command", [["solve"], ["steps"], ["sweep", "--summary"], ["check"]])
def test_a_lag_off_the_inner_dead_centre_is_refused_by_every_view(tmp_path, capsys, command):
    text = _cycle_scene(VTWIN, "v-twin").replace("lag = 450", "lag = 400")
    path = tmp_path / "bad.toml"
    path.write_text(text + '[answers]\nT_mean = "100 N m"\n')
    assert main([*command, str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "lag = 90, 450 (deg)" in err, err


def test_steps_gives_the_books_table_of_the_areas(tmp_path, capsys):
    text = _cycle_scene(VTWIN, "v-twin")
    tm = turning_moment(parse_scene(text))
    assert _views(tmp_path, text, "steps") == 0
    out = capsys.readouterr().out
    assert "The turning-moment diagram" in out and "running sum (J)" in out
    table = out[out.index("running sum (J)") :].split("\n\n")[0].splitlines()[2:]
    rows = [[float(x) for x in line.split()] for line in table]
    assert len(rows) == len(tm.lobes)
    run = 0.0
    for k, (row, lb) in enumerate(zip(rows, tm.lobes)):  # each area, its running sum
        run += lb.energy
        assert row[:4] == [k + 1, round(lb.start, 3), round(lb.end, 3), float(f"{lb.energy:.6g}")]
        assert row[4] == pytest.approx(run, abs=1e-5 * tm.dE_max)
    assert rows[-1][4] == 0.0  # the cycle closes on itself
    assert f"dE_max = E_max - E_min = {tm.E_max:.6g}" in out
    assert _views(tmp_path, text, "steps", "--format", "markdown") == 0
    assert "| area | from (deg) |" in capsys.readouterr().out


def test_the_drawn_energy_curve_is_the_quadrature_of_the_summed_diagram(tmp_path, capsys):
    """``draw --diagram cycle``: its energy curve, E above E at the first crossing, at every
    10 deg to the closed form's quadrature at 30 digits; the sheet is written for the
    engine and refused in one line for a mechanism that is no engine."""
    from polygon_method.linkage.flywheel import energy_curve

    sc = parse_scene(_cycle_scene(VTWIN, "v-twin"))
    tm = turning_moment(sc)
    x, T, E, parts = energy_curve(sc, tm, n=73)
    assert [p for p, _ in parts] == ["B", "C"]
    ref = _Reference(VTWIN, "v-twin")
    with mpmath.workdps(30):
        cycle = 4 * mpmath.pi
        mean = ref.integral(mpmath.mpf(0), cycle) / cycle
        a = mpmath.findroot(lambda t: ref(t) - mean, mpmath.radians(tm.crossings[0]), tol=1e-25)
        E_a = ref.integral(mpmath.mpf(0), a) - mean * a  # E at the first crossing, from 0
        for k in range(0, 73, 6):
            phase = mpmath.radians(x[k])
            E_ref = (ref.integral(mpmath.mpf(0), phase) - mean * phase if k else 0) - E_a
            assert E[k] == pytest.approx(float(E_ref), abs=1e-9 * tm.dE_max), x[k]
            assert T[k] == pytest.approx(float(ref(phase)), abs=1e-9 * 1e3)
    assert float(E.max() - E.min()) <= tm.dE_max * (1 + 1e-12)  # (the extremes at crossings)
    path = tmp_path / "e.toml"
    path.write_text(_cycle_scene(VTWIN, "v-twin"))
    out = tmp_path / "cycle.svg"
    assert main(["draw", str(path), "--diagram", "cycle", "-o", str(out)]) == 0
    svg = out.read_text()
    assert "cylinder B" in svg and "ΔEₘₐₓ" in svg
    plain = tmp_path / "plain.toml"
    plain.write_text(
        '[ground]\nO = [0, 0]\nQ = [4, 0]\n[links]\nOA = 1\nAB = 4\nBQ = 2\n[input]\ncrank = "OA"\n'
        'angle = 30\nspeed = "10 rad/s ccw"\n'
    )
    capsys.readouterr()
    assert main(["draw", str(plain), "--diagram", "cycle", "-o", str(tmp_path / "p.svg")]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "an engine's turning-moment diagram" in err, err


def test_solve_json_has_each_cylinders_efforts(tmp_path, capsys):
    """``solve --json``'s ``forces.engine``: each cylinder's efforts and their turning
    moment, to the 30-digit matrix method."""
    import json

    angle = 650.0
    ref = reference(_pressures(VTWIN, "v-twin", angle), angle)
    size = max(abs(v) for v in ref.values())
    assert _views(tmp_path, _massive_scene(VTWIN, "v-twin", angle), "solve", "--json") == 0
    eng = json.loads(capsys.readouterr().out)["forces"]["engine"]
    assert [c["piston"] for c in eng["cylinders"]] == ["B", "C"]
    for c in eng["cylinders"]:
        p = c["piston"]
        assert c["piston_effort"] == pytest.approx(ref["F_P" + p], abs=1e-9 * size)
        assert c["crank_effort"] == pytest.approx(ref["F_T" + p], abs=1e-9 * size)
        assert c["turning_moment"] == pytest.approx(ref["F_T" + p] * R, abs=1e-9 * size * R)
        assert c["rod_thrust"] == pytest.approx(
            math.hypot(ref[f"P{p}.x"], ref[f"P{p}.y"]), abs=1e-9 * size
        )
        assert c["side_thrust"] == pytest.approx(abs(ref["N" + p]), abs=1e-9 * size)
    total = (ref["F_TB"] + ref["F_TC"]) * R
    assert eng["turning_moment"] == pytest.approx(total, abs=1e-9 * size * R)


def test_the_summary_places_a_four_stroke_extreme_in_its_turn(tmp_path, capsys):
    """The summary's turning moment's greatest and least are at crank angles within the
    four-stroke cycle's two turns: the closed form there is the value it gives (a turn
    earlier the other cylinder's stroke differs)."""
    text = _cycle_scene(VTWIN, "v-twin")
    assert _views(tmp_path, text, "sweep", "--summary") == 0
    row = next(ln for ln in capsys.readouterr().out.splitlines() if ln.startswith("turning_moment"))
    top, at_top, low, at_low = (float(x) for x in row.split()[3:7])
    ref = _Reference(VTWIN, "v-twin")
    with mpmath.workdps(30):
        for value, at in ((top, at_top), (low, at_low)):
            assert value == pytest.approx(float(ref(mpmath.radians(at - 45))), rel=1e-5)
            other = float(ref(mpmath.radians(at - 45 + 360)))  # the same angle a turn on
            assert abs(other - value) > 0.05 * abs(value)


def test_one_indicator_beside_another_cylinders_steady_gas_force(tmp_path, capsys):
    """A V-twin whose B has the one [indicator] (piston named) and C a steady [loads]
    pressure: an engine of two cylinders (before, C's rod was left out of the turning
    moment); each to the matrix method."""
    angle = 400.0
    text = scene_text(VTWIN, angle)
    text = text.replace('B = { pressure = "2.0 N/mm^2", bore = 80 }\n', "")
    text += (
        '[indicator]\npiston = "B"\nbore = 80\ncycle = "4-stroke"\nunit = "bar"\n'
        f"angle = {ANGLES}\npressure = {BAR}\n"
    )
    assert "B = { pressure" not in text
    pr = {"B": (45, _interp(ANGLES, BAR, (angle - 45) % 720) / 10), "C": VTWIN["C"]}
    ref = reference(pr, angle)
    size = max(abs(v) for v in ref.values())
    sol = solve(parse_scene(text))
    es = cylinder_efforts(sol.scene, sol.plan, sol.P, sol.forces)
    assert [e.piston for e in es] == ["B", "C"]
    for e in es:
        assert e.F_T == pytest.approx(ref["F_T" + e.piston], abs=1e-9 * size)
    assert _views(tmp_path, text, "solve") == 0
    assert "engine, cylinder C:" in capsys.readouterr().out
