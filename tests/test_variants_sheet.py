"""Variants: never the base problem itself; the problem sheet shows each student's figure,
true to a stated scale, with their own dimensions and no answers."""

import math

import pytest

from polygon_method import parse_scene
from polygon_method.cli import main
from polygon_method.common.numbers import textbook
from polygon_method.variants import generate

BASE = """
title = "Four-bar for variants"
[ground]
A = [0, 0]
D = [100, 0]
[links]
AB = 50
BC = 66
CD = 56
[assembly]
C = "above"
[input]
crank = "AB"
angle = 60
speed = "10.5 rad/s cw"
[answers]
v_C = "0.4 m/s"
omega_CD = "7.15 rad/s cw"
[variants]
"""


def test_a_variant_is_never_the_base_problem():
    """Of BC in [66, 67] (the base has 66) only BC = 67 is a variant; "6.6 cm" is the
    base's 66 mm (and 420 deg its 60 deg, listed once), so of 2 x 2 combinations 3 are
    variants."""
    scene = parse_scene(BASE + "BC = [66, 67]\n")
    one = generate(scene, 1, seed=3)
    assert [v.values["BC"] for v in one.variants] == [67]
    two = generate(scene, 2, seed=3)
    assert len(two.variants) == 1 and two.rejected.get("the base problem itself") == 1
    assert "only 1 of the 2 combinations" in two.shortfall()
    scene = parse_scene(BASE + 'angle = [60, 420, 70]\nBC = ["6.6 cm", 67]\n')
    got = generate(scene, 6, seed=1)
    pairs = {(v.values["angle"], v.values["BC"]) for v in got.variants}
    assert (60, "6.6 cm") not in pairs and (420, "6.6 cm") not in pairs
    assert len(pairs) == 3 and got.rejected.get("the base problem itself") == 1


@pytest.fixture(scope="module")
def variants():
    return generate(parse_scene(BASE + "BC = [60, 63, 70]\nCD = [52, 58]\n"), 2, seed=5)


def test_the_problem_sheet_shows_the_students_figure_true_to_scale(variants):
    """Each variant's figure: B and C are drawn BC apart at the stated scale (the
    student's own BC, not the base's), the axes are as large on the paper as the drawing
    says (1 cm of drawing is 1 cm of A4), and no answer is written on the page."""
    from polygon_method.draw import draw_configuration
    from polygon_method.polygons.scales import parse_scale
    from polygon_method.variants.papers import PAGE_CM, sheet_pages

    figs = list(sheet_pages(variants, figure=draw_configuration))
    drawn = [f for f in figs if f.axes]
    assert len(drawn) == len(variants.variants)
    for v, fig in zip(variants.variants, drawn):
        ax = fig.axes[0]
        words = [t.get_text() for t in fig.texts]
        said = next(t for t in words if t.startswith("Figure: the configuration"))
        scale = parse_scale(said.split("drawn at ")[1], "length")
        joints = {
            a.get_gid(): a.center for a in ax.patches if (a.get_gid() or "").startswith("joint-")
        }
        cm = math.dist(joints["joint-B"], joints["joint-C"])
        assert cm * scale.per_cm == pytest.approx(v.values["BC"] * 1e-3, rel=1e-9)
        box = ax.get_position()
        (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()
        assert box.width * PAGE_CM[0] == pytest.approx(x1 - x0, rel=1e-9)
        assert box.height * PAGE_CM[1] == pytest.approx(y1 - y0, rel=1e-9)
        assert 0 <= box.x0 and box.x1 <= 1 and 0 <= box.y0 and box.y1 <= 1
        text = " ".join(words + [t.get_text() for t in ax.texts])
        for q in variants.questions:  # v_C's and omega_CD's values: nowhere on the page
            value = abs(v.solution.value(q[1], q[2]))
            assert textbook(value) not in text, (q[0], textbook(value))


def test_variants_pdf_writes_the_sheet_with_figures(tmp_path, capsys):
    scene = tmp_path / "base.toml"
    scene.write_text(BASE + "BC = [60, 63, 70]\n")
    out = tmp_path / "class"
    assert (
        main(["variants", str(scene), "--count", "2", "--seed", "1", "-o", str(out), "--pdf"]) == 0
    )
    pdf = (out / "problem-sheet.pdf").read_bytes()
    assert (
        pdf.startswith(b"%PDF")
        and pdf.count(b"/Type /Page\n") + pdf.count(b"/Type /Page ") + pdf.count(b"/Type/Page") >= 2
    )
