"""Every drawing, plot, sheet and page the tool writes is the same byte for byte run to run:
each writer is run twice through the command line (in one process, so that a random SVG id
or a clock stamp would differ) and its files compared; none carries a date."""

from pathlib import Path

import pytest

from polygon_method.cli import main

ROOT = Path(__file__).resolve().parent.parent
WORKED = ROOT / "worked_problems"
FOURBAR = WORKED / "fourbar_image_points.toml"
ENGINE = WORKED / "engine_forces.toml"
GEARS = WORKED / "gear_pair_forces.toml"
TRIAD = WORKED / "class3_six_bar_forces.toml"
VTWIN = WORKED / "vtwin_flywheel.toml"

#: (name, the command's arguments with OUT for the output, the scene)
WRITERS = [
    ("draw.svg", ["draw", "{scene}", "-o", "{out}.svg", "--diagram", "velocity"], FOURBAR),
    ("draw.png", ["draw", "{scene}", "-o", "{out}.png", "--diagram", "velocity"], FOURBAR),
    ("draw.pdf", ["draw", "{scene}", "-o", "{out}.pdf"], FOURBAR),
    ("forces.svg", ["draw", "{scene}", "--forces", "-o", "{out}.svg"], ENGINE),
    ("forces.pdf", ["draw", "{scene}", "--forces", "-o", "{out}.pdf"], ENGINE),
    ("gear-forces.svg", ["draw", "{scene}", "--forces", "-o", "{out}.svg"], GEARS),
    ("triad-forces.svg", ["draw", "{scene}", "--forces", "-o", "{out}.svg"], TRIAD),
    ("forces-page.html", ["page", "{scene}", "--frames", "4", "-o", "{out}.html"], GEARS),
    ("centres.svg", ["draw", "{scene}", "--diagram", "centres", "-o", "{out}.svg"], FOURBAR),
    ("centres.pdf", ["draw", "{scene}", "--diagram", "centres", "-o", "{out}.pdf"], FOURBAR),
    ("sweep.svg", ["sweep", "{scene}", "--steps", "24", "--plot", "{out}.svg"], FOURBAR),
    ("sweep.png", ["sweep", "{scene}", "--steps", "24", "--plot", "{out}.png"], FOURBAR),
    ("sweep.pdf", ["sweep", "{scene}", "--steps", "24", "--plot", "{out}.pdf"], FOURBAR),
    ("engine-sweep.svg", ["sweep", "{scene}", "--steps", "24", "--plot", "{out}.svg"], ENGINE),
    ("engine-cycle.svg", ["draw", "{scene}", "--diagram", "cycle", "-o", "{out}.svg"], VTWIN),
    ("animate.svg", ["draw", "{scene}", "--animate", "--frames", "4", "-o", "{out}.svg"], FOURBAR),
    ("animate.gif", ["draw", "{scene}", "--animate", "--frames", "4", "-o", "{out}.gif"], FOURBAR),
    ("page.html", ["page", "{scene}", "--frames", "4", "-o", "{out}.html"], FOURBAR),
    ("variants", ["variants", "{scene}", "--count", "2", "--pdf", "-o", "{out}"], FOURBAR),
]


def _run(tmp_path, run, args, scene):
    d = tmp_path / f"run{run}"
    d.mkdir()
    argv = [a.format(scene=scene, out=d / "x") for a in args]
    assert main(argv) == 0, argv
    return {p.relative_to(d): p.read_bytes() for p in sorted(d.rglob("*")) if p.is_file()}


@pytest.mark.parametrize("name,args,scene", WRITERS, ids=[w[0] for w in WRITERS])
def test_every_file_written_is_the_same_byte_for_byte_run_to_run(
    tmp_path, monkeypatch, capsys, name, args, scene
):
    monkeypatch.delenv("SOURCE_DATE_EPOCH", raising=False)  # matplotlib's fixed clock
    first, second = (_run(tmp_path, k, args, scene) for k in (1, 2))
    capsys.readouterr()
    assert first and sorted(first) == sorted(second)
    for path, data in first.items():
        assert data == second[path], f"{name}: {path} differs between two runs"
        if path.suffix == ".svg":
            assert b"<dc:date>" not in data
        elif path.suffix == ".pdf":
            assert b"/CreationDate" not in data and b"/ModDate" not in data
        elif path.suffix == ".png":
            assert b"tIME" not in data and b"Software" not in data
