"""Two inputs ([input.second]): a five-bar with two driven cranks, against the 50-digit
reference (a second crank constraint at its own angle, speed and acceleration), and the
superposition the step table shows against the combined solve (velocities are linear in
the two speeds)."""

import json
import math

import pytest

from polygon_method import solve
from polygon_method.cli import main
from polygon_method.scene import parse_scene
from reference import reference_solution

REL = 1e-9

FIVE_BAR = """
units = "mm"
[ground]
A = [0, 0]
E = [120, 0]
[links]
AB = 60
BC = 140
CD = 140
DE = 60
[points]
P = {{ on = "BC", along = 70 }}
[assembly]
C = "above"
[input]
crank = "AB"
angle = {a1}
speed = "10 rad/s ccw"
acceleration = {al1}
[input.second]
crank = "ED"
angle = {a2}
speed = "{w2}"
{acc2}
"""


CASES = [
    (60, 120, "5 rad/s cw", "", 0),
    (30, 150, "8 rad/s ccw", 'acceleration = "40 rad/s^2 cw"', '"20 rad/s^2 ccw"'),
    (100, 80, "2 rad/s cw", "", 0),
]


@pytest.mark.parametrize("a1, a2, w2, acc2, al1", CASES)
def test_five_bar_against_reference(a1, a2, w2, acc2, al1):
    sc = parse_scene(FIVE_BAR.format(a1=a1, a2=a2, w2=w2, acc2=acc2, al1=al1 or 0))
    sol = solve(sc)
    ref = reference_solution(sc, dict(sol.P))
    vs = max(math.hypot(*v) for v in sol.V.values())
    acc = max(math.hypot(*a) for a in sol.A.values())
    for p in sc.point_names:
        for got, want, size in (
            (sol.P[p], ref["positions"][p], 0.14),
            (sol.V[p], ref["velocities"][p], vs),
            (sol.A[p], ref["accelerations"][p], acc),
        ):
            assert float(math.hypot(got[0] - want[0], got[1] - want[1])) <= REL * size, p
    w = max(abs(x) for x in sol.W.values())
    for lk in sc.links:
        assert abs(sol.W[lk.key] - ref["omega"][lk.key]) <= REL * w
        assert abs(sol.Al[lk.key] - ref["alpha"][lk.key]) <= REL * (w * w + 40)


def test_superposition_adds_up(tmp_path, capsys):
    """The step table's v' (first crank alone) + v'' (second alone) = the solved v."""
    from polygon_method.text.steptable import steps_text as step_table

    sc = parse_scene(FIVE_BAR.format(a1=60, a2=120, w2="5 rad/s cw", acc2="", al1=0))
    sol = solve(sc)
    text = step_table(sol)
    assert "v = v' + v''" in text and "(AB alone)" in text
    # independent: each crank alone against the reference with the other held
    import dataclasses

    one = dataclasses.replace(
        sc,
        input=dataclasses.replace(
            sc.input, second=dataclasses.replace(sc.input.second, omega=1e-300, alpha=0.0)
        ),
    )
    r1 = reference_solution(one, dict(sol.P))
    ref = reference_solution(sc, dict(sol.P))
    # the second alone = the whole minus the first alone
    for p in ("B", "C", "D", "P"):
        v2 = (
            ref["velocities"][p][0] - r1["velocities"][p][0],
            ref["velocities"][p][1] - r1["velocities"][p][1],
        )
        m = float(math.hypot(*v2))
        if m > 1e-6:
            shown = f"{m:.4g}"
            assert shown[:4] in text, (p, shown)


def test_views_and_refusals(tmp_path, capsys):
    f = tmp_path / "five.toml"
    f.write_text(
        FIVE_BAR.format(a1=60, a2=120, w2="5 rad/s cw", acc2="", al1=0)
        + '[loads]\nP = { force = "100 N", direction = 270 }\n'
    )
    assert main(["solve", "--json", str(f)]) == 0
    d = json.loads(capsys.readouterr().out)
    assert "input_torque" not in d and d["input"]["second"]["crank"] == "DE"
    assert main(["centres", str(f)]) == 2  # Kennedy cannot reach every centre: it says why
    assert "two degrees of freedom" in capsys.readouterr().err
    for argv in (
        ["steps"],
        ["linkage"],
        ["plan"],
        ["draw", "-o", str(tmp_path / "d.svg")],
        ["sweep", "--steps", "36", "--summary"],
        ["page", "-o", str(tmp_path / "p.html")],
    ):
        assert main([argv[0], str(f), *argv[1:]]) in (0,), argv
    out = capsys.readouterr().out
    assert "second input" in out
    bad = f.read_text().replace(
        'speed = "5 rad/s cw"', 'speed = "5 rad/s cw"\nomega_BC = "1 rad/s cw"'
    )
    f.write_text(bad)
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "second" in err


def test_two_inputs_on_one_freedom_and_one_on_two(tmp_path, capsys):
    """A four-bar given two inputs is over-determined; a five-bar given one is not
    determined: each one line naming what to do."""
    f = tmp_path / "od.toml"
    f.write_text(
        "[ground]\nA = [0, 0]\nD = [100, 0]\n[links]\nAB = 50\nBC = 66\nCD = 56\n"
        '[input]\ncrank = "AB"\nangle = 60\nspeed = "10 rad/s cw"\n'
        '[input.second]\ncrank = "DC"\nangle = 100\nspeed = "1 rad/s cw"\n'
    )
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "over-determine" in err and "mobility 1" in err
    f.write_text(
        FIVE_BAR.format(a1=60, a2=120, w2="5 rad/s cw", acc2="", al1=0).split("[input.second]")[0]
    )
    assert main(["solve", str(f)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "mobility 2" in err and "[input.second]" in err
