"""The page in a real browser: headless Chromium (the system's ``chromium``) driven by
Playwright. The page loads from file:// with no console error and no network request; the
slider moves the drawings and the values to what an independent solve at that crank angle
gives, to the page's own precision; play runs and pause stops.

Where Playwright or the browser is missing these tests skip and say which (``.ci/run``
installs both where it can)."""

import dataclasses
import json
import math
from pathlib import Path

import pytest

import polygon_method as pm
from polygon_method.cli import main
from polygon_method.common.numbers import fmt

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT / "worked_problems" / "fourbar_image_points.toml"
SLOTTED = ROOT / "worked_problems" / "crank_slotted_lever.toml"
STEEP = ROOT / "worked_problems" / "fourbar_acceleration.toml"  # ill-conditioned at its ends
# a cylinder whose rate of extension is given: each frame holds it (the crank's speed follows)
TIPPER = ROOT / "worked_problems" / "tipper_cylinder.toml"
PISTON = ROOT / "worked_problems" / "piston_driven_slider_crank.toml"


@pytest.fixture(scope="module")
def pages(tmp_path_factory):
    d = tmp_path_factory.mktemp("pages")
    out = {}
    for name, scene in (
        ("seed", SEED),
        ("slotted", SLOTTED),
        ("steep", STEEP),
        ("tipper", TIPPER),
        ("piston", PISTON),
    ):
        path = d / f"{name}.html"
        assert main(["page", str(scene), "-o", str(path)]) == 0
        out[name] = path
    return out


class Opened:
    """A page opened in the browser, with every request and console message recorded."""

    def __init__(self, browser, path):
        self.page = browser.new_page(viewport={"width": 1280, "height": 1000})
        self.requests, self.console, self.errors = [], [], []
        self.page.route("**/*", self._route)
        self.page.on("console", lambda m: self.console.append((m.type, m.text)))
        self.page.on("pageerror", lambda e: self.errors.append(str(e)))
        self.url = path.as_uri()
        self.page.goto(self.url)
        self.data = json.loads(self.page.evaluate("document.getElementById('frames').textContent"))

    def _route(self, route):
        self.requests.append(route.request.url)
        if route.request.url == self.url or route.request.url.startswith("data:"):
            route.continue_()
        else:
            route.abort()

    def slide(self, k):
        self.page.evaluate(
            "(k) => { const s = document.getElementById('angle'); s.value = k; "
            "s.dispatchEvent(new Event('input')); }",
            k,
        )

    def shown_scale(self, phase) -> float:
        """The scale stated beside a diagram ("1 cm = 0.5 m/s"), in SI per cm, after checking
        that it is round (1, 2 or 5 x 10^k) and is the one the diagram is drawn at."""
        words = self.text(f"#scale-{phase}").split()
        assert words[:3] == ["1", "cm", "="] and len(words) == 5, words
        value, unit = float(words[3]), words[4]
        mantissa = value / 10 ** math.floor(math.log10(value) + 1e-12)
        assert min(abs(mantissa - m) for m in (1, 2, 5)) < 1e-9, words
        si = value * (self.data["unit"] if phase == "configuration" else 1.0)
        assert (
            unit
            == {"configuration": self.data["units"], "velocity": "m/s", "acceleration": "m/s²"}[
                phase
            ]
        )
        drawn = float(self.page.get_attribute(f"#{phase}", "data-per-cm"))
        assert abs(drawn - si) <= 1e-9 * si, (drawn, si)
        return si

    def text(self, sel):
        return self.page.text_content(sel).strip()

    def attrs(self, sel, names):
        return [float(self.page.get_attribute(sel, n)) for n in names]


@pytest.fixture
def opened(browser, pages):
    made = []

    def open_(name):
        o = Opened(browser, pages[name])
        made.append(o)
        return o

    yield open_
    for o in made:
        o.page.close()


def solve_at(scene_path, degrees):
    scene = pm.load_scene(str(scene_path))
    return pm.solve(
        dataclasses.replace(
            scene, input=dataclasses.replace(scene.input, angle=math.radians(degrees))
        )
    )


def near_cm(drawn: float, cm: float) -> bool:
    """A coordinate drawn (cm, to 0.001) from data rounded to six figures."""
    return abs(drawn - cm) <= 1.5e-3 + 6e-6 * abs(cm)


def agrees(shown: str, exact: float, digits=4) -> bool:
    """``shown`` (four significant figures) is ``exact`` rounded, allowing for the page's
    data being rounded to six figures first."""
    x = float(shown)
    if exact == 0:
        return x == 0
    ulp = 10.0 ** (math.floor(math.log10(abs(exact))) - digits + 1)
    return abs(x - exact) <= 0.5 * ulp * 1.001 + 1e-6 * abs(exact)


def test_page_loads_with_no_error_and_no_request(opened):
    for name in ("seed", "slotted"):
        o = opened(name)
        o.page.wait_for_timeout(200)
        assert o.errors == [], o.errors
        assert [m for m in o.console if m[0] in ("error", "warning")] == []
        assert o.requests == [o.url], o.requests  # the file itself, nothing else
        assert o.text("#angle-now").startswith("θ = ")
        n = len(o.data["theta"])
        assert n == 180 and o.page.get_attribute("#angle", "max") == str(n - 1)


@pytest.mark.parametrize(
    "name, scene, frames",
    [
        ("seed", SEED, (141, 20, 170, 0)),
        ("slotted", SLOTTED, (0, 47, 123)),
        ("steep", STEEP, (0, 90, 179)),
        ("tipper", TIPPER, (0, 60, 179)),
        ("piston", PISTON, (3, 50, 100, 170)),
    ],
)
def test_slider_moves_drawings_and_values_to_the_solve_at_that_angle(opened, name, scene, frames):
    o = opened(name)
    d = o.data
    seen = set()
    for k in frames:
        o.slide(k)
        # each diagram's scale at this frame, as the page states it (mm of the panel: 10 a
        # centimetre)
        space, vscale, ascale = (
            o.shown_scale(ph) / 10 for ph in ("configuration", "velocity", "acceleration")
        )
        theta = d["theta"][k]
        sol = solve_at(scene, theta)
        assert o.text("#angle-now") == f"θ = {theta % 360:.1f}°"
        assert o.text("#val-theta") == f"{theta % 360:.1f}°"
        for p in d["points"]:
            shown = o.text(f"#val-v-{p}")
            assert agrees(shown.split()[0], sol.speed(p)), (k, p, shown)
            assert agrees(o.text(f"#val-a-{p}").split()[0], sol.acceleration_magnitude(p))
            # the vector drawn from the pole ends at the image point, to scale (mm; y down)
            x2, y2 = o.attrs(f"#v-abs-{p}", ("x2", "y2"))
            vx, vy = sol.V[p]
            assert near_cm(x2, vx / vscale) and near_cm(y2, -vy / vscale)
            x2, y2 = o.attrs(f"#a-abs-{p}", ("x2", "y2"))
            ax, ay = sol.A[p]
            assert near_cm(x2, ax / ascale) and near_cm(y2, -ay / ascale)
            seen.add((p, round(x2, 3), round(y2, 3)))
        for p, q, key in d["links"]:
            w = o.text(f"#val-w-{key}").split()
            assert agrees(w[0], abs(sol.W[key]))
            if sol.W[key] != 0 and abs(sol.W[key]) > 1e-9:
                assert w[-1] == ("ccw" if sol.W[key] > 0 else "cw")
            x1, y1, x2, y2 = o.attrs(f"#c-link-{key}", ("x1", "y1", "x2", "y2"))
            assert near_cm(x1, sol.P[p][0] / space) and near_cm(y2, -sol.P[q][1] / space)
        for s in d["S"]:
            assert agrees(o.text(f"#val-vs-{s}").split()[0], sol.sliding_velocity(s))
        # the condition: a warning exactly where solve warns (near a singular position)
        cond = o.text("#val-condition")
        assert ("below sin 5°" in cond) == bool(sol.warnings), (k, cond, sol.warnings)
        assert agrees(cond.split()[0], min(sol.conditions.values()), 3)
        # the plots' marker stands at the angle
        assert o.page.get_attribute("#plot-v-marker", "x1") is not None
    assert len(seen) > len(d["points"])  # the polygons moved


def test_play_runs_and_pause_stops(opened):
    o = opened("slotted")
    before = o.text("#angle-now")
    o.page.click("#play")
    o.page.wait_for_timeout(600)
    running = o.text("#angle-now")
    assert running != before
    o.page.click("#play")
    stopped = o.text("#angle-now")
    o.page.wait_for_timeout(400)
    assert o.text("#angle-now") == stopped
    assert o.page.text_content("#play").strip().endswith("play")


def test_play_turns_back_at_the_limit_positions(opened):
    o = opened("seed")  # the crank cannot turn fully
    n = len(o.data["theta"])
    o.slide(n - 2)
    o.page.click("#play")
    o.page.wait_for_timeout(500)
    o.page.click("#play")
    k = int(o.page.input_value("#angle"))
    assert 0 <= k < n - 2


def test_tooltip_names_a_vector_with_its_value(opened):
    o = opened("seed")
    o.slide(o.data["start"])
    o.page.click("#v-lab-C")  # a click or a tap; a hover shows the same as its <title>
    tip = o.text("#tooltip")
    assert o.page.text_content("#v-lab-C title") == tip
    sol = pm.solve(pm.load_scene(str(SEED)))
    assert tip.startswith("v_C = oc = ") and f"{fmt(sol.speed('C'))} m/s" in tip


def test_screenshots_at_two_angles(opened, tmp_path):
    o = opened("seed")
    shots = []
    for k in (o.data["start"], 20):
        o.slide(k)
        path = tmp_path / f"page-{k}.png"
        o.page.screenshot(path=str(path))
        shots.append(path.read_bytes())
    assert all(s[:8] == b"\x89PNG\r\n\x1a\n" and len(s) > 20_000 for s in shots)
    assert shots[0] != shots[1]
