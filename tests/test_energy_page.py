"""The page of a turning-moment diagram stated on its own (``page`` on a [turning_moment] or
[press] scene), in headless Chromium (the system's ``chromium``, driven by Playwright) at a
desktop's 1280 px and a phone's 390 px: no page error or console message, nothing fetched,
no sideways scroll; and every value it shows (at the cursor as the slider moves, the
answers, the book's table) equals the closed form worked here by hand (the sinusoid's
crossings and energies, the areas' running sums, the press's straight lines) or mpmath's
quadrature, to the four figures shown. Without Playwright or Chromium the browser tests
skip and say which is missing."""

import math
import re
from pathlib import Path

import mpmath
import pytest

from polygon_method.cli import main

ROOT = Path(__file__).resolve().parents[1]
AREAS = ROOT / "worked_problems" / "flywheel" / "engine_areas_rim.toml"
PRESS = ROOT / "worked_problems" / "flywheel" / "punching_press.toml"
LAW = """title = "A sinusoid about its mean"
[turning_moment]
torque = "1000 + 300 sin 2theta - 500 cos 2theta"
[flywheel]
speed = "300 rpm"
plus_minus = "1%"
radius = "0.5 m"
[answers]
dE_max = "583.1 J"
I_flywheel = "29.5 kg m^2"
"""
SEGMENTS = """title = "Straight segments with a jump"
[turning_moment]
angle = [0, 30, 90, 90, 180, 360]
torque = [0, 900, 900, 200, 0, 0]
"""
N = 90  # frames of the law's page: 4 deg apart
NUM = re.compile(r"[-+−]?\d+(?:\.\d+)?(?:e[-+]\d+)?")


def _number(text: str) -> float:
    return float(NUM.search(text).group(0).replace("−", "-"))


def _agrees(shown: str, exact: float, scale: float) -> bool:
    """``shown`` (four significant figures) is ``exact`` rounded, or within the arithmetic's
    noise of a quantity of size ``scale`` (a value near nought)."""
    got = _number(shown)
    if exact == 0 or abs(exact) < 1e-9 * scale:
        return abs(got) <= 1e-9 * scale
    ulp4 = 10 ** (math.floor(math.log10(abs(exact))) - 3)
    return abs(got - exact) <= 0.5 * ulp4 * (1 + 1e-9) + 1e-9 * scale


# -- the law's closed forms (worked by hand): T - 1000 = 300 sin 2t - 500 cos 2t


A = math.hypot(300, 500)
W = 300 * math.pi / 30
CS = 0.02
INERTIA = A / (W * W * CS)


def _energy(t):
    """int_0^t (T - T_mean) = 150 (1 - cos 2t) - 250 sin 2t (J)."""
    return 150 * (1 - math.cos(2 * t)) - 250 * math.sin(2 * t)


A_ANGLE = math.atan2(500, 300) / 2  # the first crossing: tan 2t = 5/3
E_MIN = 150 - A / 2 - _energy(A_ANGLE)  # E above E at a is least where 150 - (A/2) cos(..)


def _speed(e):
    """I (w^2 - w_min^2) / 2 = E - E_min, w_min = w (1 - Cs / 2)."""
    return math.sqrt((W * (1 - CS / 2)) ** 2 + 2 * (e - E_MIN) / INERTIA)


def test_the_closed_forms_agree_with_mpmath():
    """The hand-worked energy and speed, against mpmath's quadrature of the law at 30
    digits (so the browser test's reference is itself held)."""
    mpmath.mp.dps = 30
    for t in (0.3, 1.7, 4.0):
        e = mpmath.quad(lambda x: 300 * mpmath.sin(2 * x) - 500 * mpmath.cos(2 * x), [0, t])
        assert abs(float(e) - _energy(t)) <= 1e-12 * A
    e_rel_min = min(_energy(A_ANGLE + k * math.pi / 2) for k in range(4)) - _energy(A_ANGLE)
    assert abs(e_rel_min - E_MIN) <= 1e-12 * A
    top = max(_energy(A_ANGLE + k * math.pi / 2) for k in range(4)) - _energy(A_ANGLE)
    assert abs(_speed(top) - W * (1 + CS / 2)) <= 1e-12 * W


# -- without a browser


@pytest.fixture(scope="module")
def written(tmp_path_factory):
    d = tmp_path_factory.mktemp("energy_pages")
    law = d / "law.toml"
    law.write_text(LAW, encoding="utf-8")
    seg = d / "segments.toml"
    seg.write_text(SEGMENTS, encoding="utf-8")
    out = {}
    for name, scene, extra in (
        ("law", law, ["--frames", str(N)]),
        ("areas", AREAS, []),
        ("press", PRESS, ["--frames", "50"]),
        ("segments", seg, []),
    ):
        path = d / f"{name}.html"
        assert main(["page", str(scene), "-o", str(path)] + extra) == 0
        out[name] = path
    return out


def test_the_page_fetches_nothing(written):
    for path in written.values():
        html = path.read_text(encoding="utf-8")
        assert html.startswith("<!DOCTYPE html>")
        assert "http://" not in html and "https://" not in html and "<link" not in html
        assert "@import" not in html and "src=" not in html
        assert len(html.encode()) < 400_000


def test_bad_input_is_one_line_and_leaves_the_file(tmp_path, capsys):
    out = tmp_path / "p.html"
    out.write_text("keep", encoding="utf-8")
    for argv in (
        ["page", str(PRESS), "-o", str(tmp_path / "p.svg")],
        ["page", str(PRESS), "-o", str(out), "--frames", "1"],
        ["page", str(PRESS), "-o", str(out), "--answers", str(tmp_path / "none.toml")],
    ):
        capsys.readouterr()
        assert main(argv) == 2
        err = capsys.readouterr().err.strip()
        assert err and "\n" not in err and "Traceback" not in err
    assert out.read_text(encoding="utf-8") == "keep"


# -- in the browser


class Opened:
    def __init__(self, browser, path, width):
        self.page = browser.new_page(viewport={"width": width, "height": 900})
        self.problems, self.requests = [], []
        self.url = path.as_uri()
        self.page.route("**/*", self._route)
        self.page.on("console", lambda m: self.problems.append(f"{m.type}: {m.text}"))
        self.page.on("pageerror", lambda e: self.problems.append(str(e)))
        self.page.goto(self.url)

    def _route(self, route):
        self.requests.append(route.request.url)
        (route.continue_ if route.request.url == self.url else route.abort)()

    def slide(self, k):
        self.page.evaluate(
            "(k) => { const s = document.getElementById('angle'); s.value = k; "
            "s.dispatchEvent(new Event('input')); }",
            k,
        )

    def values(self) -> dict:
        return dict(
            self.page.evaluate(
                "Array.from(document.querySelectorAll('#values tr')).map(r => "
                "[r.cells[0].textContent, r.cells[1].textContent])"
            )
        )

    def table(self, sel) -> list:
        return self.page.evaluate(
            f"Array.from(document.querySelectorAll('{sel} tbody tr')).map(r => "
            "Array.from(r.cells).map(c => c.textContent))"
        )

    def fits(self) -> bool:
        return self.page.evaluate(
            "document.documentElement.scrollWidth <= window.innerWidth && "
            "document.body.scrollWidth <= window.innerWidth"
        )

    def close(self):
        assert self.problems == [], self.problems
        assert self.requests == [self.url], self.requests
        self.page.close()


@pytest.mark.parametrize("width", [1280, 390])
def test_the_laws_page_shows_the_closed_forms(browser, written, width, tmp_path):
    o = Opened(browser, written["law"], width)
    assert o.fits()
    for k in (0, 7, 23, 45, 61, 89):
        o.slide(k)
        t = 2 * math.pi * k / N
        v = o.values()
        torque = 1000 + 300 * math.sin(2 * t) - 500 * math.cos(2 * t)
        e = _energy(t) - _energy(A_ANGLE)
        assert _agrees(v["crank angle θ"], math.degrees(t), 360), v
        assert _agrees(v["turning moment T"], torque, 1000), (k, v)
        assert _agrees(v["mean torque"], 1000, 1000)
        assert _agrees(v["T − R"], torque - 1000, 1000), (k, v)
        assert _agrees(v["energy above E at a"], e, A), (k, v)
        assert _agrees(v["speed ω"], _speed(e), W), (k, v)
        assert _agrees(v["angular acceleration (T − R) / I"], (torque - 1000) / INERTIA, 20)
        # the cursor's line is where the crank angle is, on every plot
        xs = o.page.evaluate(
            "Array.from(document.querySelectorAll('line.cursor')).map(l => +l.getAttribute('x1'))"
        )
        assert len(xs) == 3 and max(xs) - min(xs) < 1e-9
        assert o.fits()
    answers = o.page.evaluate("document.getElementById('answers').textContent")
    m = re.search(r"dE_max = ([0-9.]+) J", answers)
    assert _agrees(m.group(1), A, A)
    m = re.search(r"moment of inertia I = ([0-9.]+) kg m\^2", answers)
    assert _agrees(m.group(1), INERTIA, INERTIA)
    rows = o.table("#book")
    assert len(rows) == 4  # the crossings a, b, c, d, and a again
    for i, r in enumerate(rows):
        ang = (2 * A_ANGLE + i * math.pi) / 2
        assert abs(_number(r[0].split("(")[1]) - math.degrees(ang)) <= 5e-5
        sign = -1 if i % 2 else 1  # T - 1000 = A sin(2t - phi): above its mean after a
        assert _agrees(r[2], sign * A, A), r
    assert [r[5] for r in o.table("#check")] == ["right", "right"]
    # the crossings sit on the mean line (drawn dashed), the energy's at their energies
    marks = o.page.evaluate(
        "Array.from(document.querySelectorAll('#plot-torque circle.crossing')).map(c => "
        "+c.getAttribute('cy'))"
    )
    mean = o.page.evaluate(
        "document.querySelector('#plot-torque path[stroke-dasharray]').getAttribute('d')"
    )
    y_mean = float(mean.split(",")[1].split()[0])
    assert len(marks) == 4 and all(abs(y - y_mean) < 0.02 for y in marks), (marks, y_mean)
    o.page.screenshot(path=str(tmp_path / f"law-{width}.png"), full_page=True)
    o.close()


@pytest.mark.parametrize("width", [1280, 390])
def test_the_areas_page_steps_over_the_crossings(browser, written, width):
    """The running sums of the areas worked by hand in the file: E, E+52, E-72, E+20,
    E-120, E-35, E-107, E (mm^2 of 70 N m x 4.5 deg)."""
    o = Opened(browser, written["areas"], width)
    per = 70 * 4.5 * math.pi / 180
    sums = [0, 52, -72, 20, -120, -35, -107, 0]
    w = 600 * math.pi / 30
    inertia = 172 * per / (w * w * 0.03)
    for k, s in enumerate(sums):
        o.slide(k)
        v = o.values()
        assert v["crossing"] == "abcdefga"[k]
        assert _agrees(v["energy above E at a"], s * per, 172 * per), (k, v)
        speed = math.sqrt((w * 0.985) ** 2 + 2 * (s + 120) * per / inertia)
        assert _agrees(v["speed ω"], speed, w), (k, v)
        assert o.fits()
    rows = o.table("#check")
    assert rows[0][0] == "dE_max" and rows[0][5] == "WRONG" and "largest" in rows[0][6]
    o.close()


@pytest.mark.parametrize("width", [1280, 390])
def test_the_press_page_follows_the_flywheels_energy(browser, written, width):
    """E = F t / 2, F = tau pi d t; 5 s a cycle, an eighth of it punching: the energy falls
    by E (1 - 1/8) in 0.625 s and the motor's E / 5 s brings it back."""
    o = Opened(browser, written["press"], width)
    E = 400e6 * math.pi * 0.025 * 0.018**2 / 2
    dE = E * 7 / 8
    for k in (0, 3, 6, 7, 20, 49):
        o.slide(k)
        t = 5.0 * k / 50
        e = -dE * t / 0.625 if t <= 0.625 else -dE + E / 5 * (t - 0.625)
        v = o.values()
        assert _agrees(v["time in the cycle"], t, 5), v
        assert _agrees(v["the flywheel's energy above its start"], e, dE), (k, v)
        assert _agrees(v["the motor's power"], E / 5, E)
        assert o.fits()
    # the book's table: a to b while the hole is punched, b back to a while the motor refills
    book = o.page.evaluate(
        "[...document.querySelectorAll('#book tbody tr')].map(r => [...r.cells].map(c => c.textContent))"
    )
    assert [r[:2] for r in book] == [["a", "b"], ["b", "a"]], book
    assert _agrees(book[0][2], -dE, dE) and _agrees(book[1][2], dE, dE)
    o.close()


def test_the_segments_page_loads_on_a_phone(browser, written):
    """Straight segments with a jump: the mean 1/(2 pi) x the trapezoids (by hand: 13.5 +
    54 + 31.5 ... in N m rad), the page loads and fits."""
    o = Opened(browser, written["segments"], 390)
    work = (0.5 * 900 * 30 + 900 * 60 + 0.5 * 200 * 90) * math.pi / 180
    answers = o.page.evaluate("document.getElementById('answers').textContent")
    m = re.search(r"T_mean = ([0-9.]+) N m", answers)
    assert _agrees(m.group(1), work / (2 * math.pi), 1000)
    o.slide(20)
    assert o.fits()
    o.close()


def test_an_answer_file_of_another_variant_is_refused(tmp_path, capsys):
    """As ``check`` does: an answer file that names a variant is checked on that variant's
    own page only."""
    scene = tmp_path / "law.toml"
    scene.write_text(LAW, encoding="utf-8")
    ans = tmp_path / "ann.toml"
    ans.write_text('variant = "03"\n[answers]\ndE_max = "583.1 J"\n', encoding="utf-8")
    assert main(["page", str(scene), "-o", str(tmp_path / "p.html"), "--answers", str(ans)]) == 2
    err = capsys.readouterr().err
    assert "variant '03'" in err and err.count("\n") == 1
    assert not (tmp_path / "p.html").exists()
