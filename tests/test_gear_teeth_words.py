"""Gears given by their teeth said as a book says them, in every view that describes a
wheel: the sun "of 40 teeth" (not "the fixed circle about O"), its pitch radius, the
planet and the ring "of 24 (88) teeth": solve's plan, the step table's drawing and polygon
steps, the problem's words (the page and the problem sheet), the JSON's steps and teeth,
the page's pitch circles in a real browser. A wheel with no teeth keeps its words."""

import json
import re
from pathlib import Path

import pytest

from polygon_method import load_scene, parse_scene, solve
from polygon_method.cli import main
from polygon_method.text.steptable import steps_text
from polygon_method.text.words import given

BOOK = Path(__file__).resolve().parent / "textbook" / "rattan_epicyclic_by_teeth.toml"
PLANET = "planet AP of 24 teeth meshing with the sun of 40 teeth about O"
RING = "ring O-Q of 88 teeth meshing with the planet AP of 24 teeth inside it"


def _flat(text):
    return " ".join(text.split())


def test_solve_plan_names_the_gears_by_their_teeth(capsys):
    assert main(["solve", str(BOOK)]) == 0
    out = capsys.readouterr().out
    assert f"2. {PLANET}: finds P" in out and f"3. {RING}: finds Q" in out, out
    assert "fixed circle" not in out


def test_steps_say_the_teeth_and_pitch_radii():
    """The sun's pitch radius 5 x 40 / 2 = 100 mm, the planet's 60 mm (the module 5 mm)."""
    out = _flat(steps_text(solve(load_scene(str(BOOK)))))
    assert (
        "P: the planet AP (24 teeth, pitch radius m z / 2 = 5 x 24 / 2 = 60 mm (1.20 cm)) "
        "meshes with the sun of 40 teeth about O (pitch radius 100 mm (2.00 cm))" in out
    ), out
    assert (
        "Q: the ring O-Q (88 teeth, pitch radius m z / 2 = 5 x 88 / 2 = 220 mm (4.40 cm)) "
        "meshes with the planet AP of 24 teeth inside it (pitch radius 60 mm (1.20 cm))" in out
    ), out
    assert (
        f"Step 2 ({PLANET}): no slip: the planet's point at the pitch point I with the sun of 40 teeth about O is at rest"
        in out
    )
    assert f"Step 3 ({RING}): equal velocities" in out
    assert "fixed circle" not in out and "wheel AP" not in out


def test_problem_words_say_the_teeth():
    """The planet's, the sun's and the annulus's teeth, their pitch radii and the module."""
    lines = given(load_scene(str(BOOK)))
    assert "The module is 5 mm." in lines, lines
    assert (
        "The planet AP of 24 teeth (centre A, pitch radius 60 mm) meshes with the sun of 40 "
        "teeth about O (pitch radius 100 mm); P is its point in contact at the instant shown."
    ) in lines, lines
    assert (
        "The ring gear O-Q of 88 teeth (centre O, pitch radius 220 mm) meshes internally with "
        "the planet AP of 24 teeth inside it (pitch radius 60 mm); Q is its point in contact "
        "at the instant shown."
    ) in lines, lines


PAIR = """
units = "mm"
[ground]
O2 = [0, 0]
O3 = [{d}, 0]
[links]
"O2-A" = 30
"O3-B" = 100
[rolling]
module = "4 mm"
"O3-B" = {{ on = "O2-A", teeth = 50{more} }}
[input]
crank = "O2-A"
angle = 25
speed = "1000 rpm cw"
"""


@pytest.mark.parametrize("more", [", on_teeth = 20", ""])
def test_a_pair_by_its_teeth_in_every_view(more, capsys, tmp_path):
    """Gear 3 of 50 teeth driven by gear 2 of 20 (stated, or 140 - 100 = 40 mm of module 4:
    20 teeth): the words, the step title, the JSON."""
    text = PAIR.format(d=140, more=more)
    sol = solve(parse_scene(text))
    assert (
        "The gear O3-B of 50 teeth (centre O3, pitch radius 100 mm) meshes with the gear O2-A "
        "of 20 teeth (pitch radius 40 mm)" in " ".join(given(sol.scene))
    )
    out = _flat(steps_text(sol))
    assert "gear O3-B of 50 teeth meshing with the gear O2-A of 20 teeth" in out
    assert "meshes with the gear O2-A of 20 teeth (pitch radius 40 mm (" in out
    f = tmp_path / "pair.toml"
    f.write_text(text, encoding="utf-8")
    assert main(["solve", "--json", str(f)]) == 0
    doc = json.loads(capsys.readouterr().out)
    assert doc["rolling"]["O3-B"]["teeth"] == {"teeth": 50, "on_teeth": 20, "module": 0.004}
    assert (
        doc["steps"][1]["title"] == "gear O3-B of 50 teeth meshing with the gear O2-A of 20 teeth"
    )


def test_a_wheel_without_teeth_keeps_its_words():
    """A friction wheel on a fixed circle (no teeth): "the wheel AP (radius 60 mm) rolls
    without slipping on the fixed circle about O", as before, the circle's radius the
    centre distance's, 160 - 60 = 100 mm."""
    text = BOOK.read_text(encoding="utf-8")
    text = text.split("[rolling]")[0] + (
        '[links]\nOA = 160\nAP = 60\n[rolling]\nAP = { on = "O" }\n[input]\ncrank = "OA"\n'
        'angle = 30\nspeed = "200 rpm ccw"\n'
    )
    sol = solve(parse_scene(text))
    out = _flat(steps_text(sol))
    assert (
        "the wheel AP (radius 60 mm (" in out
        and "rolls without slipping on the fixed circle about O (radius 100 mm (" in out
    )
    assert "of 40 teeth" not in out and "planet AP" not in out
    assert any(
        "rolls without slipping outside the fixed circle about O;" in s for s in given(sol.scene)
    )


def test_page_says_the_teeth_in_a_browser(browser, tmp_path):
    """The page: the problem's words and the step labels say the teeth; each pitch circle's
    tooltip (its SVG title) says whose it is."""
    path = tmp_path / "book.html"
    assert main(["page", str(BOOK), "-o", str(path)]) == 0
    page = browser.new_page()
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    try:
        page.goto(path.as_uri())
        body = _flat(page.inner_text("body"))
        assert "meshes with the sun of 40 teeth about O (pitch radius 100 mm)" in body, body[:2000]
        titles = page.evaluate(
            "Array.from(document.querySelectorAll('circle > title')).map(t => t.textContent)"
        )
        assert "pitch circle of the sun of 40 teeth about O" in titles, titles
        assert "pitch circle of the planet AP of 24 teeth" in titles, titles
        assert "pitch circle of the ring O-Q of 88 teeth" in titles, titles
        assert not any(re.match(r"pitch circle about", t) for t in titles), titles
        assert not errors, errors
    finally:
        page.close()


def test_a_us_book_says_the_diametral_pitch(capsys, tmp_path):
    """Diametral pitch 10 per inch, gears of 50 and 20 teeth: the pitch radius z / (2 P) =
    50 / 20 = 2.5 in (not "m z / 2 = 2.54 x 50 / 2 = 2.5 in", millimetres and inches
    mixed), in the notes and the step table; the problem's words and the JSON say P."""
    text = PAIR.format(d=3.5, more=", on_teeth = 20").replace('units = "mm"', 'units = "in"')
    text = text.replace('module = "4 mm"', "diametral_pitch = 10").replace("30\n", "1\n", 1)
    text = text.replace('"O3-B" = 100', '"O3-B" = 2.5')
    sol = solve(parse_scene(text))
    out = _flat(steps_text(sol))
    assert "50 teeth, pitch radius z / (2 P) = 50 / (2 x 10) = 2.5 in (" in out, out
    assert "2.54 x" not in out
    assert any(
        "pitch radius z / (2 P) = 50 / (2 x 10) = 2.5 in and 20 / (2 x 10) = 1 in" in n
        for n in sol.notes
    ), sol.notes
    assert "The diametral pitch is 10 per inch." in given(sol.scene)
    f = tmp_path / "us.toml"
    f.write_text(text, encoding="utf-8")
    assert main(["solve", "--json", str(f)]) == 0
    rec = json.loads(capsys.readouterr().out)["rolling"]["O3-B"]["teeth"]
    assert rec["diametral_pitch"] == 10 and rec["module"] == pytest.approx(0.0254 / 10, rel=1e-15)


def test_centres_name_the_pitch_point(capsys):
    """The instantaneous centre of the planet and the sun is the pitch point of gears that
    mesh (a wheel with no teeth keeps 'the contact of ...')."""
    assert main(["centres", str(BOOK)]) == 0
    out = capsys.readouterr().out
    assert "the pitch point of AP meshing with the sun of 40 teeth about O (no slip)" in out, out
    assert "the contact of AP" not in out


def test_the_force_drawing_names_the_gears_by_their_teeth(tmp_path):
    """The force sheet's heading of the planet's step and the contact's words (its text
    is kept beside each drawn line of the SVG)."""
    text = BOOK.read_text(encoding="utf-8").split("[answers]")[0]
    assert '"O-Q" = { torque = "100 N m cw" }' in text  # the book's resisting torque
    scene = tmp_path / "held.toml"
    scene.write_text(text, "utf-8")
    svg = tmp_path / "f.svg"
    assert main(["draw", "--diagram", "forces", str(scene), "-o", str(svg)]) == 0
    out = svg.read_text(encoding="utf-8")
    assert "planet AP of 24 teeth meshing with the sun of" in out
    assert "fixed circle" not in out
