"""A class's variants of an engine problem whose answers are the engine chapter's (the
inertia force, the piston effort, the crank effort): each variant's key against the closed
forms of the in-line slider crank at that variant's speed."""

import math
from pathlib import Path

import pytest

from polygon_method.scene import parse_scene
from polygon_method.variants import generate
from polygon_method.variants.papers import answer

ROOT = Path(__file__).resolve().parents[1]

TEXT = (ROOT / "worked_problems" / "engine_forces.toml").read_text().split("[answers]")[0] + (
    '[answers]\nFi_B = "1 kN"\npiston_effort = "1 kN"\ncrank_effort = "1 kN"\n'
    'rod_thrust = "1 kN"\n\n[variants]\nspeed = ["150 rpm", "250 rpm", "400 rpm"]\n'
)


def _closed_forms(rpm):
    """(inertia force, piston effort, crank effort, rod thrust) in N: r 0.3 m, l 1.2 m,
    60 deg, 250 kg at the piston, 0.35 N/mm^2 on a 500 mm bore towards the crank."""
    r, l, th, m = 0.3, 1.2, math.radians(60), 250.0
    w = rpm * math.pi / 30
    n = l / r
    s = math.sin(th)
    root = math.sqrt(n * n - s * s)
    # the piston's acceleration towards O, exactly (not the two-term approximation)
    xdd = w * w * r * (math.cos(th) + (n * n * math.cos(2 * th) + s**4) / root**3)
    gas = 0.35e6 * math.pi / 4 * 0.5**2
    F_P = gas - m * xdd  # towards the crank: the gas less the inertia of the parts
    phi = math.asin(s / n)
    F_Q = F_P / math.cos(phi)
    F_T = F_Q * math.sin(th + phi)
    return m * abs(xdd), abs(F_P), abs(F_T), abs(F_Q)


def test_each_variants_engine_key_is_the_closed_form_at_its_speed():
    vs = generate(parse_scene(TEXT, "engine.toml"), count=2, seed=5)
    keys = [q[0] for q in vs.questions]
    assert keys == ["Fi_B", "piston_effort", "crank_effort", "rod_thrust"]
    speeds = set()
    for v in vs.variants:
        rpm = v.scene.input.omega * 30 / math.pi
        speeds.add(round(abs(rpm)))
        want = _closed_forms(abs(rpm))
        got = [answer(v.solution, q) for q in vs.questions]
        assert got == pytest.approx(want, rel=1e-9)
    assert speeds == {150, 400}  # (the base's own speed is not a variant)
