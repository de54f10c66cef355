"""``sweep --csv``'s ``correction_couple`` and ``correction_torque`` columns (and their
extremes in ``--summary``): the connecting rod's correction couple ``m alpha (l1 l3 -
k_G^2)`` and its torque on the crank shaft ``T' omega_rod / omega``, row by row against the
closed form worked here, the rod's angle differentiated in time with mpmath at 40 digits."""

from __future__ import annotations

import csv
import io

import mpmath
import pytest

from polygon_method.cli import main

R, L = 0.08, 0.3  # crank, rod (m)
M, L1, K = 3.0, 0.11, 0.095  # the rod's mass, G from the small end B, k_G
RPM = 1500.0
REL = 1e-9


def _text(offset):
    return f"""units = "mm"
[ground]
O = [0, 0]
[links]
OA = {R * 1000}
AB = {L * 1000}
[sliders]
B = {{ path = "horizontal", through = [0, {offset * 1000}] }}
[masses]
AB = {{ mass = "{M} kg", from = "B", along = {L1 * 1000}, gyration = {K * 1000} }}
B = {{ mass = "2 kg" }}
[input]
crank = "OA"
angle = "35 deg"
speed = "{RPM} rpm anticlockwise"
"""


def _beta(offset):
    """The direction of BA as a function of the crank angle (mpmath, 40 digits)."""
    r, l, e = mpmath.mpf(R), mpmath.mpf(L), mpmath.mpf(offset)

    def beta(t):
        ax, ay = r * mpmath.cos(t), r * mpmath.sin(t)
        bx = ax + mpmath.sqrt(l**2 - (ay - e) ** 2)
        return mpmath.atan2(ay - e, ax - bx)

    return beta


def _closed(offset, angle_deg):
    """(T', T' omega_rod / omega) at the crank angle: omega_rod = w beta', alpha = w^2
    beta'' at uniform w."""
    mpmath.mp.dps = 40
    w = mpmath.mpf(RPM) * 2 * mpmath.pi / 60
    beta, t = _beta(offset), mpmath.radians(angle_deg)
    wr, al = w * mpmath.diff(beta, t), w**2 * mpmath.diff(beta, t, 2)
    m, l, l1, k = mpmath.mpf(M), mpmath.mpf(L), mpmath.mpf(L1), mpmath.mpf(K)
    c = m * al * (l1 * (l - l1) - k**2)
    return float(c), float(c * wr / w)


def _rows(tmp_path, capsys, offset, steps=24):
    scene = tmp_path / "rod.toml"
    scene.write_text(_text(offset))
    assert main(["sweep", str(scene), "--csv", "-", "--steps", str(steps)]) == 0
    rows = list(csv.reader(io.StringIO(capsys.readouterr().out)))
    head = [h.split(" [")[0] for h in rows[0]]
    assert "correction_couple [N m]" in rows[0] and "correction_torque [N m]" in rows[0]
    return [dict(zip(head, map(float, r))) for r in rows[1:] if r]


@pytest.mark.parametrize("offset", [0.0, 0.02])
def test_each_row_is_the_closed_form(tmp_path, capsys, offset):
    rows = _rows(tmp_path, capsys, offset)
    assert len(rows) == 24
    checked = 0
    for row in rows:
        if round(row["theta"]) not in (15, 75, 150, 210, 300):
            continue
        c, t = _closed(offset, row["theta"])
        scale = abs(M * (L1 * (L - L1) - K**2)) * (RPM * 2 * mpmath.pi / 60) ** 2 * R / L
        assert row["correction_couple"] == pytest.approx(c, rel=REL, abs=REL * float(scale))
        assert row["correction_torque"] == pytest.approx(t, rel=REL, abs=REL * float(scale))
        checked += 1
    assert checked == 5


def test_the_summary_gives_the_couples_extremes(tmp_path, capsys):
    """The in-line engine's largest correction couple where alpha is largest (found here by
    mpmath: beta''' = 0) and its largest torque on the crank shaft (d/dt (T' beta') = 0)."""
    scene = tmp_path / "rod.toml"
    scene.write_text(_text(0.0))
    assert main(["sweep", str(scene), "--summary", "--steps", "360"]) == 0
    lines = {ln.split()[0]: ln.split() for ln in capsys.readouterr().out.splitlines() if ln}
    mpmath.mp.dps = 40
    beta = _beta(0.0)
    w = mpmath.mpf(RPM) * 2 * mpmath.pi / 60
    c0 = mpmath.mpf(M) * (mpmath.mpf(L1) * (mpmath.mpf(L) - mpmath.mpf(L1)) - mpmath.mpf(K) ** 2)
    for key, f in (
        ("correction_couple", lambda t: c0 * w**2 * mpmath.diff(beta, t, 2)),
        ("correction_torque", lambda t: c0 * w**2 * mpmath.diff(beta, t, 2) * mpmath.diff(beta, t)),
    ):
        got = lines[key]
        assert got[1:3] == ["N", "m"]
        at = float(got[4])
        t = mpmath.findroot(lambda t: mpmath.diff(f, t), mpmath.radians(at))
        assert float(got[3]) == pytest.approx(float(f(t)), rel=1e-5)  # (6 digits shown)
        assert at == pytest.approx(float(mpmath.degrees(t)), abs=2e-3)
