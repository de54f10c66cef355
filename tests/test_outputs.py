"""A user's files are never destroyed or half-written, and every refusal is one line with
exit code 2: links are written through, special files written into, several outputs are
checked before anything is computed and written all or none, the scene is never written
over, and what is read or asked for is bounded."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from polygon_method.cli import main

ROOT = Path(__file__).resolve().parent.parent
SCENE = ROOT / "worked_problems" / "fourbar_crank_acceleration.toml"


def run(argv, capsys):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def one_line_refusal(code, err):
    assert code == 2, err
    lines = err.strip().splitlines()
    assert len(lines) == 1 and "internal error" not in err and "Traceback" not in err, err
    return lines[0]


def test_a_link_is_written_through(tmp_path, capsys):
    target = tmp_path / "target.csv"
    target.write_text("old\n")
    link = tmp_path / "link.csv"
    link.symlink_to(target.name)
    code, _, err = run(["sweep", SCENE, "--steps", "8", "--csv", link], capsys)
    assert code == 0, err
    assert link.is_symlink() and os.readlink(link) == target.name
    assert target.read_text().startswith("theta [deg]")


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full here")
def test_a_full_device_is_one_line_and_stays_a_device(capsys):
    code, _, err = run(["sweep", SCENE, "--steps", "8", "--csv", "/dev/full"], capsys)
    line = one_line_refusal(code, err)
    assert "/dev/full" in line and "No space left" in line
    assert Path("/dev/full").is_char_device()


def test_a_directory_is_refused(tmp_path, capsys):
    d = tmp_path / "out.svg"
    d.mkdir()
    line = one_line_refusal(*run(["draw", SCENE, "-o", d], capsys)[::2])
    assert "is a directory" in line
    assert d.is_dir() and not any(d.iterdir())


def test_several_outputs_are_written_all_or_none(tmp_path, capsys):
    csv = tmp_path / "a.csv"
    csv.write_text("keep\n")
    line = one_line_refusal(
        *run(
            [
                "sweep",
                SCENE,
                "--steps",
                "8",
                "--csv",
                csv,
                "--plot",
                tmp_path / "missing" / "p.svg",
            ],
            capsys,
        )[::2]
    )
    assert "--plot" in line and "no directory" in line
    assert csv.read_text() == "keep\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.csv"]  # no temporary left


def test_the_scene_is_never_written_over(tmp_path, capsys):
    scene = tmp_path / "s.toml"
    shutil.copy(SCENE, scene)
    before = scene.read_bytes()
    for argv in (["sweep", scene, "--csv", scene], ["draw", scene, "-o", tmp_path / "s.toml"]):
        line = one_line_refusal(*run(argv, capsys)[::2])
        assert "scene file itself" in line or "must end in" in line
    link = tmp_path / "s.svg"
    link.symlink_to(scene.name)
    line = one_line_refusal(*run(["draw", scene, "-o", link], capsys)[::2])
    assert "scene file itself" in line
    assert scene.read_bytes() == before


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="no /dev/zero here")
def test_reading_is_bounded(capsys):
    line = one_line_refusal(*run(["solve", "/dev/zero"], capsys)[::2])
    assert "larger than 1 MiB" in line


def test_control_characters_in_a_path_are_shown_escaped(tmp_path, capsys):
    line = one_line_refusal(*run(["solve", tmp_path / "no\nsuch\tfile.toml"], capsys)[::2])
    assert "no\\nsuch\\tfile.toml" in line


def test_points_without_a_plot_and_absurd_ranges_are_refused(capsys):
    line = one_line_refusal(*run(["sweep", SCENE, "--points", "C"], capsys)[::2])
    assert "--plot" in line
    line = one_line_refusal(
        *run(["sweep", SCENE, "--from", "1e300", "--to", "1e301", "--step", "1"], capsys)[::2]
    )
    assert "within" in line


def test_a_csv_too_large_is_refused_up_front_with_its_memory(tmp_path, capsys):
    out = tmp_path / "big.csv"
    line = one_line_refusal(
        *run(["sweep", SCENE, "--steps", "10000000", "--csv", out], capsys)[::2]
    )
    assert "GiB" in line and "--summary" in line
    assert not out.exists()


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full here")
def test_a_full_standard_output_is_one_line():
    with open("/dev/full", "w") as full:
        p = subprocess.run(
            [sys.executable, "-m", "polygon_method", "solve", str(SCENE)],
            stdout=full,
            stderr=subprocess.PIPE,
            text=True,
            cwd=ROOT,
        )
    line = one_line_refusal(p.returncode, p.stderr)
    assert "No space left" in line


#: the kinds of output path tried (/dev/full only where the system has it)
KINDS = ["new", "existing", "link", "directory", "missing_dir", "scene"] + (
    ["dev_full"] if Path("/dev/full").exists() else []
)


def _in_process(argv):
    """``main(argv)`` with its standard output and error caught: (exit code, stderr)."""
    import contextlib
    import io

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main([str(a) for a in argv])
    return code, err.getvalue()


def _make(kind, tmp, name, scene):
    if kind == "new":
        return tmp / f"{name}"
    if kind == "existing":
        p = tmp / f"{name}"
        p.write_text("keep\n")
        return p
    if kind == "link":
        target = tmp / f"target-{name}"
        target.write_text("keep\n")
        p = tmp / f"{name}"
        p.symlink_to(target.name)
        return p
    if kind == "directory":
        p = tmp / f"{name}"
        p.mkdir()
        return p
    if kind == "missing_dir":
        return tmp / "nowhere" / f"{name}"
    if kind == "scene":
        return scene
    return Path("/dev/full")


def _pairs():
    """The pairs of output kinds tried: each for the CSV alone; each for the plot after a
    CSV that can be written (new, or over a file that must keep its text if the plot is
    refused); each for the CSV before a new plot. (Every pair of the seven kinds is 56
    sweeps, most of them drawing a plot: a minute of the suite for no new case.)"""
    pairs = [(k, None) for k in KINDS]
    pairs += [(c, k) for c in ("new", "existing") for k in KINDS]
    pairs += [(k, "new") for k in KINDS if k not in ("new", "existing")]
    return pairs


@pytest.mark.parametrize("csv_kind,plot_kind", _pairs())
def test_fuzz_output_paths(tmp_path, csv_kind, plot_kind):
    """Any mix of output paths: exit 0 with every output written, or exit 2 with one line
    and nothing of the user's destroyed or half-written: regular files keep their text,
    links stay links, directories stay directories, no temporary file is left. Run in
    process (``main``); the real entry point is run as a process by the tests above."""
    tmp = tmp_path / "out"
    tmp.mkdir()
    scene = tmp / "scene.toml"
    shutil.copy(SCENE, scene)
    before = scene.read_bytes()
    csv_path = _make(csv_kind, tmp, "a.csv", scene)
    argv = ["sweep", str(scene), "--steps", "12", "--csv", str(csv_path)]
    plot_path = None
    if plot_kind is not None:
        plot_path = _make(plot_kind, tmp, "p.svg", scene)
        if plot_kind == "scene":
            plot_path = scene
        argv += ["--plot", str(plot_path)]
    snapshot = {
        p: (p.is_symlink(), p.is_dir(), p.read_text() if p.is_file() else None)
        for p in tmp.rglob("*")
    }
    code, err = _in_process(argv)
    assert code in (0, 2), err
    assert scene.read_bytes() == before
    leftovers = [p for p in tmp.rglob(".*.tmp")]
    assert not leftovers, leftovers
    if code == 2:
        line = one_line_refusal(code, err)
        assert line
        for p, (link, is_dir, text) in snapshot.items():  # nothing changed
            assert p.is_symlink() == link and p.is_dir() == is_dir
            if text is not None and not link:
                assert p.read_text() == text, p
        return
    for p, kind in ((csv_path, csv_kind), (plot_path, plot_kind)):
        if p is None or kind == "dev_full":
            continue
        if kind == "link":
            assert p.is_symlink()
        assert p.is_file() and p.stat().st_size > 0


def test_a_reader_that_goes_away_is_no_error():
    """``polygon-method sweep ... | head``: the reader closes the pipe after a line; the
    command stops quietly, exit 0, nothing on stderr."""
    p = subprocess.Popen(
        [sys.executable, "-m", "polygon_method", "sweep", str(SCENE), "--steps", "300000"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        cwd=ROOT,
    )
    p.stdout.readline()
    p.stdout.close()
    err = p.stderr.read()
    assert p.wait(timeout=60) == 0
    assert err == b""


@pytest.mark.parametrize(
    "args",
    [
        ["sweep", str(SCENE), "--csv", ""],
        ["sweep", str(SCENE), "--plot", " "],
        ["draw", str(SCENE), "-o", ""],
        ["check", str(SCENE), "--gradebook", ""],
        ["variants", str(ROOT / "worked_problems" / "fourbar_image_points.toml"), "-o", ""],
        ["solve", ""],
    ],
)
def test_an_empty_name_is_refused_never_taken_as_not_given(args, capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main(args) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "empty" in err
    assert list(tmp_path.iterdir()) == []  # nothing written (not even here)


def test_variants_into_a_dangling_link_is_one_clear_line(tmp_path, capsys):
    link = tmp_path / "out"
    link.symlink_to(tmp_path / "nowhere" / "dir")
    code = main(
        [
            "variants",
            str(ROOT / "worked_problems" / "fourbar_image_points.toml"),
            "--count",
            "2",
            "-o",
            str(link),
        ]
    )
    err = capsys.readouterr().err
    assert code == 2 and "does not exist" in err and err.count("\n") == 1
    assert not (tmp_path / "nowhere").exists()
