"""The force drawing's friction labels: a peg in two slots has a friction force in each,
named like the guide's force on the same pair (``\u03bcN\u2085\u2082`` beside ``F\u2085\u2082``, the force on
the peg, block 5, by link 2), so that every force label in a free body or a force polygon
is its own; read from the SVG the drawing writes."""

from __future__ import annotations

import re
from collections import Counter
from pathlib import Path

import pytest

from polygon_method.cli import main

HERE = Path(__file__).resolve().parent / "textbook"
LABEL = re.compile(
    r'<g id="label-((?:free-body|force-polygon)-\d+)-(?:force|side)-\d+">\s*<!-- (.*?) -->', re.S
)
SUB = str.maketrans("\u2080\u2081\u2082\u2083\u2084\u2085\u2086\u2087\u2088\u2089", "0123456789")

PEG_FRICTION = """
[masses]
AB = { mass = "2 kg", centre = "B" }
CD = { mass = "3 kg", centre = "C" }
P = { mass = "1 kg" }
[loads]
P = { force = "100 N", direction = 30 }
[friction]
guides = { P = 0.1 }
"""


def _labels(tmp_path, text):
    scene = tmp_path / "scene.toml"
    scene.write_text(text)
    out = tmp_path / "sheet.svg"
    assert main(["draw", str(scene), "--forces", "-o", str(out)]) == 0
    groups = {}
    for svg in sorted(tmp_path.glob("sheet*.svg")):
        for group, label in LABEL.findall(svg.read_text()):
            groups.setdefault(group, []).append(label)
    assert groups, "no force labels read from the drawing"
    return groups


def _friction(groups):
    return {g: [x for x in v if x.startswith("\u03bcN")] for g, v in groups.items()}


def test_a_peg_in_two_slots_names_each_slots_friction(tmp_path):
    text = (HERE / "peg_two_slotted_links.toml").read_text() + PEG_FRICTION
    groups = _labels(tmp_path, text)
    for group, labels in groups.items():
        twice = [x for x, n in Counter(labels).items() if n > 1]
        assert not twice, f"{group}: {twice} twice among {labels}"
    fr = _friction(groups)
    # the peg (block 5) rubs in the slot of AB (link 2) and of CD (link 4)
    assert sorted(fr["free-body-5"]) == ["\u03bcN\u2085\u2082", "\u03bcN\u2085\u2084"]
    assert fr["free-body-2"] == ["\u03bcN\u2082\u2085"]
    assert fr["free-body-4"] == ["\u03bcN\u2084\u2085"]
    # each friction's pair is the pair of a guide force on the same free body
    for group, labels in groups.items():
        pairs = {x[1:].translate(SUB) for x in labels if re.fullmatch(r"F[\u2080-\u2089]+", x)}
        for x in fr[group]:
            assert x[2:].translate(SUB) in pairs, f"{group}: {x} has no F of its pair in {labels}"
    # the force polygons carry the same names: the peg's step both, each link's its own
    polys = [sorted(v) for g, v in fr.items() if g.startswith("force-polygon") and v]
    assert ["\u03bcN\u2085\u2082", "\u03bcN\u2085\u2084"] in polys
    assert ["\u03bcN\u2082\u2085"] in polys and ["\u03bcN\u2084\u2085"] in polys


@pytest.mark.parametrize("name", ["friction_each_shaper_slot_and_ram.toml"])
def test_a_single_guides_friction_is_named_by_its_pair_too(tmp_path, name):
    groups = _labels(tmp_path, (HERE / name).read_text())
    fr = [x for v in _friction(groups).values() for x in v]
    assert fr and all(re.fullmatch(r"\u03bcN[\u2080-\u2089]{2,}", x) for x in fr), fr
    for group, labels in groups.items():
        twice = [x for x, n in Counter(labels).items() if n > 1]
        assert not twice, f"{group}: {twice} twice among {labels}"


def test_each_pins_friction_couple_names_its_pin(tmp_path):
    """The slider crank with friction at O, A and B: the rod has a friction couple at A and
    at B, the crank at O and at A; each named by its pin, none twice on one free body."""
    scene = tmp_path / "scene.toml"
    scene.write_text((HERE / "friction_each_slider_crank_pins.toml").read_text())
    out = tmp_path / "sheet.svg"
    assert main(["draw", str(scene), "--forces", "-o", str(out)]) == 0
    couples = {}
    for svg in sorted(tmp_path.glob("sheet*.svg")):
        found = re.findall(
            r'<g id="label-(free-body-\d+)-couple-\d+">\s*<!-- (.*?) = ', svg.read_text()
        )
        for body, label in found:
            couples.setdefault(body, []).append(label)
    friction = {b: sorted(x for x in v if x.startswith("C\u03bc")) for b, v in couples.items()}
    assert friction["free-body-2"] == ["C\u03bc\u2082 at A", "C\u03bc\u2082 at O"]
    assert friction["free-body-3"] == ["C\u03bc\u2083 at A", "C\u03bc\u2083 at B"]
    for body, labels in couples.items():
        assert len(set(labels)) == len(labels), f"{body}: {labels}"
