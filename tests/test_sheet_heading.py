"""A long scene title on the sheets drawn as one figure (a turning-moment diagram stated on
its own, ``draw``; an engine's cycle, ``draw --diagram cycle``): it ran off both edges of
the A4 sheet. Wrapped as the force panels' words are, its box, measured by matplotlib's
Agg renderer on the drawn figure (not the wrapping's own measure), lies inside the sheet
and above the plots and their titles; a short title stays one line where it was."""

from __future__ import annotations

import re
from pathlib import Path

import pytest

from polygon_method.cli import main

ROOT = Path(__file__).resolve().parents[1]
LONG = (
    "A four-stroke single-cylinder petrol engine of a small motor car, its indicator "
    "diagram read from the laboratory test bench, with the turning-moment diagram, the "
    "fluctuation of energy and the flywheel it needs"
)
SHEETS = {  # the module drawing it, the scene, the command's extra words
    "cycle": (
        "engine_cycle",
        ROOT / "worked_problems" / "engine_flywheel.toml",
        ["--diagram", "cycle"],
    ),
    "diagram": ("energy", ROOT / "worked_problems" / "flywheel" / "engine_areas_rim.toml", []),
}


def _drawn(monkeypatch, tmp_path, sheet, title):
    """The figure the sheet was drawn as (caught on its way to the file)."""
    import importlib

    module_name, scene, extra = SHEETS[sheet]
    module = importlib.import_module(f"polygon_method.draw.{module_name}")
    caught, real = [], module.figure_data
    monkeypatch.setattr(
        module, "figure_data", lambda fig, fmt, **kw: caught.append(fig) or real(fig, fmt, **kw)
    )
    text = re.sub(r'(?m)^title = ".*"$', f'title = "{title}"', scene.read_text(encoding="utf-8"))
    path = tmp_path / "long.toml"
    path.write_text(text, encoding="utf-8")
    assert main(["draw", str(path), *extra, "-o", str(tmp_path / "sheet.pdf")]) == 0
    (fig,) = caught
    return fig


@pytest.mark.parametrize("title", [LONG, LONG + "; " + LONG, "A short title"])
@pytest.mark.parametrize("sheet", sorted(SHEETS))
def test_the_heading_lies_within_the_sheet_and_above_the_plots(monkeypatch, tmp_path, sheet, title):
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    fig = _drawn(monkeypatch, tmp_path, sheet, title)
    w, h = (x * 2.54 for x in fig.get_size_inches())
    assert (round(w, 6), round(h, 6)) == (21.0, 29.7)  # A4, portrait
    canvas = FigureCanvasAgg(fig)
    canvas.draw()
    renderer = canvas.get_renderer()
    (head,) = [t for t in fig.texts if " ".join(t.get_text().split()) == title]
    box = head.get_window_extent(renderer)
    sheet_box = fig.bbox
    assert box.x0 >= sheet_box.x0 and box.x1 <= sheet_box.x1, (box, sheet_box)
    assert box.y1 <= sheet_box.y1 and box.y0 >= sheet_box.y0, (box, sheet_box)
    highest = max(ax.get_tightbbox(renderer).y1 for ax in fig.axes)
    assert box.y0 > highest, (box.y0, highest)  # clear of the plots and their titles
    if title == "A short title":
        assert "\n" not in head.get_text() and head.get_position() == (0.5, 0.95)
    else:
        assert head.get_text().count("\n") >= 2
