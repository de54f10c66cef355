"""``sweep --csv -`` writes the CSV on standard output (the words on stderr), as the shell's
convention has it, and never a file named '-'; the rows are those of ``--csv FILE``, and
each row's crank speed is the scene's (an independent figure: 10.5 rad/s)."""

from pathlib import Path

from polygon_method.cli import main

SEED = str(Path(__file__).resolve().parents[1] / "worked_problems" / "fourbar_image_points.toml")


def test_a_sweeps_csv_on_standard_output(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["sweep", SEED, "--csv", "-", "--steps", "12"]) == 0
    out, err = capsys.readouterr()
    assert not (tmp_path / "-").exists()
    assert "crank angles evaluated" in err and "crank angles" not in out
    assert main(["sweep", SEED, "--csv", str(tmp_path / "s.csv"), "--steps", "12"]) == 0
    capsys.readouterr()
    assert out == (tmp_path / "s.csv").read_text()
    rows = [r.split(",") for r in out.splitlines()]
    col = rows[0].index("omega_AB [rad/s]")
    assert len(rows) > 5 and all(abs(abs(float(r[col])) - 10.5) < 1e-12 for r in rows[1:])


def test_the_summary_goes_to_stderr_beside_a_csv_on_stdout(tmp_path, capsys, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(["sweep", SEED, "--csv", "-", "--steps", "12", "--summary"]) == 0
    out, err = capsys.readouterr()
    assert out.startswith("theta [deg],") and "omega_BC" in err and not (tmp_path / "-").exists()
