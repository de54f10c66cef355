"""The answer keys of two points of one link (``vmin_XY``, ``ar_XY``, ``at_XY``) in every
view: their error bounds in ``solve --json`` (and ``solve``'s lines of estimated errors),
an answer file asking them (``solve``, ``steps``, ``page --answers``), the sweep's columns
and summary, and the page's mark of p.

Each against something independent: the 50-digit loop-closure reference
(tests/reference.py: its velocities, omegas and alphas, the slowest point of XY worked from
them in mpmath), the rod's instantaneous centre (|omega| times its distance from the rod),
omega^2 r and alpha r of the reference, central finite differences over the crank angle.
"""

import json
import math
from pathlib import Path

import mpmath
import pytest
from mpmath import mpf

from polygon_method import parse_scene, solve
from polygon_method.motion.link_points import least_speed, pair_bounds
from reference import reference_solution
from edge_families import EDGE_FAMILIES  # (benchmarks/, on the tests' path)

HERE = Path(__file__).resolve().parent
BOOK = HERE / "textbook" / "rattan_slider_crank_least_speed.toml"


def _slider_crank(angle, answers=""):
    return f"""
units = "mm"
[ground]
O = [0, 0]
[links]
OA = 480
AB = 1600
[points]
E = {{ on = "AB", along = -450 }}
[sliders]
B = {{ path = "horizontal", through = "O" }}
[assembly]
B = "right"
[input]
crank = "OA"
angle = {angle}
speed = "20 rad/s ccw"
acceleration = "30 rad/s^2 cw"
[answers]
{answers}
"""


#: a non-Grashof four-bar whose coupler and rocker come into line at 112.0243 deg (a toggle: the dyad's
#: condition small, every bound of the points it finds large)
FOURBAR = """
units = "mm"
[ground]
O2 = [0, 0]
O4 = [300, 0]
[links]
"O2-A" = 100
AB = 250
"O4-B" = 100
[points]
C = {{ on = "AB", distances = {{ A = 150, B = 150 }}, turn = "ccw" }}
[input]
crank = "O2-A"
angle = {angle}
speed = "12 rad/s cw"
acceleration = "40 rad/s^2 ccw"
[assembly]
B = "above"
[answers]
{answers}
"""


def _exact(sol, kind, x, y):
    """The record's numbers from the 50-digit reference: v_X, v_Y, and the slowest point
    of XY worked from them (the foot t = -v_X . v_YX / |v_YX|^2 and op = |v_X x v_Y| /
    |v_YX|), omega^2 XY and |alpha| XY with the reference's omega and alpha."""
    ref = reference_solution(sol.scene, sol.P)
    P, V = ref["positions"], ref["velocities"]
    (px, py), (qx, qy) = P[x], P[y]
    r = mpmath.hypot(qx - px, qy - py)
    if kind != "vmin":
        key = _link(sol, x, y)
        w, al = ref["omega"][key], ref["alpha"][key]
        return {
            "r": r,
            "omega": w,
            "alpha": al,
            "radial": w * w * r,
            "tangential": abs(al) * r,
            "value": w * w * r if kind == "ar" else abs(al) * r,
        }
    b, c = V[x], V[y]
    d = (c[0] - b[0], c[1] - b[1])
    dd = d[0] ** 2 + d[1] ** 2
    t = -(b[0] * d[0] + b[1] * d[1]) / dd
    at = min(max(t, mpf(0)), mpf(1))
    speed = mpmath.hypot(b[0] + at * d[0], b[1] + at * d[1])
    return {
        "value": speed,
        "speed": speed,
        "foot_speed": abs(b[0] * c[1] - b[1] * c[0]) / mpmath.sqrt(dd),
        "foot_fraction": t,
        "fraction": at,
        "distance": at * r,
        "position": (px + at * (qx - px), py + at * (qy - py)),
    }


def _link(sol, x, y):
    for lk in sol.scene.links:
        on = {lk.p, lk.q} | {c.name for c in sol.scene.points if c.link == lk.key}
        if {x, y} <= on:
            return lk.key
    raise AssertionError((x, y))


#: the size each number's bound is relative to (``error_bounds.relative_to``; 1: absolute)
_SIZE = {
    "value": None,
    "speed": "velocity",
    "foot_speed": "velocity",
    "foot_fraction": 1,
    "fraction": 1,
    "distance": "position",
    "position": "position",
    "r": "position",
    "omega": "omega",
    "alpha": "alpha",
    "radial": "acceleration",
    "tangential": "acceleration",
}

BOUND_CASES = [
    (_slider_crank(60), "vmin", "A", "B"),
    (_slider_crank(160), "vmin", "A", "B"),  # the foot beyond b
    (_slider_crank("90.0001"), "vmin", "A", "B"),  # the rod barely turns: t far off
    (_slider_crank("89.99999"), "vmin", "E", "B"),
    (_slider_crank(60), "ar", "B", "A"),
    (_slider_crank("90.0001"), "ar", "B", "A"),
    (_slider_crank(160), "at", "E", "A"),
    (FOURBAR.format(angle="112.024", answers=""), "vmin", "A", "B"),  # near the toggle
    (FOURBAR.format(angle="112.024", answers=""), "vmin", "C", "B"),
    (FOURBAR.format(angle="112.024", answers=""), "ar", "B", "A"),
    (FOURBAR.format(angle="112.024", answers=""), "at", "C", "A"),
    (FOURBAR.format(angle=-40, answers=""), "vmin", "A", "C"),
]


@pytest.mark.parametrize(
    "text,kind,x,y", BOUND_CASES, ids=[f"{c[1]}{c[2]}{c[3]}-{i}" for i, c in enumerate(BOUND_CASES)]
)
def test_every_number_of_a_record_is_within_its_bound_of_the_reference(text, kind, x, y):
    sol = solve(parse_scene(text))
    got = sol.to_dict()  # (nothing asked: the record's numbers as link_points gives them)
    from polygon_method.motion.link_points import components

    rec = (least_speed(sol, x, y) if kind == "vmin" else components(sol, x, y)).as_dict()
    rec["value"] = sol.value(kind, (x, y))
    bounds = pair_bounds(sol, kind, x, y)
    sizes = got["error_bounds"]["relative_to"]
    exact = _exact(sol, kind, x, y)
    for part, bound in bounds.items():
        size = _SIZE[part] or ("velocity" if kind == "vmin" else "acceleration")
        size = 1.0 if size == 1 else sizes[size]
        want, have = exact[part], rec[part]
        if part == "position":
            err = max(abs(float(w) - h) for w, h in zip(want, have))
        elif part in ("omega", "alpha"):  # (a size: the record's are signed)
            err = abs(abs(float(want)) - abs(have))
        else:
            err = abs(float(want) - have)
        assert err <= bound * size, (part, err, bound * size)


def test_the_bounds_say_where_the_answer_is_uncertain():
    """Away from trouble every bound is below the promise of 1e-9; where the rod barely
    turns the foot's place is uncertain (its bound large, the error there real), the
    speeds not; near the toggle the speeds' bounds grow too."""
    calm = solve(parse_scene(_slider_crank(60)))
    assert all(b < 1e-9 for b in pair_bounds(calm, "vmin", "A", "B").values())
    flat = solve(parse_scene(_slider_crank("90.0001")))
    b = pair_bounds(flat, "vmin", "A", "B")
    assert b["foot_fraction"] > 1e-7 and b["speed"] < 1e-13
    exact = _exact(flat, "vmin", "A", "B")
    err = abs(float(exact["foot_fraction"]) - least_speed(flat, "A", "B").fraction)
    assert err > 1e-4 * b["foot_fraction"]  # (the bound within 1e4 of a real error)
    toggle = solve(parse_scene(FOURBAR.format(angle="112.024", answers="")))
    assert (
        pair_bounds(toggle, "vmin", "A", "B")["speed"]
        > 1e3 * pair_bounds(calm, "vmin", "A", "B")["speed"]
    )


def test_solve_json_gives_each_asked_keys_bounds_and_solve_lists_the_large_ones():
    text = _slider_crank("90.0001", 'vmin_AB = "9.6 m/s"\nar_BA = "1 m/s^2"')
    sol = solve(parse_scene(text))
    d = json.loads(json.dumps(sol.to_dict()))
    lp = d["error_bounds"]["link_points"]
    assert set(lp) == {"vmin_AB", "ar_BA"}
    assert set(lp["vmin_AB"]) == {
        "value",
        "speed",
        "foot_speed",
        "foot_fraction",
        "fraction",
        "distance",
        "position",
    }
    assert lp["ar_BA"]["value"] == lp["ar_BA"]["radial"]
    from polygon_method.text.report import solution_text

    report = solution_text(sol)
    tail = report[report.index("estimated error above") :]
    assert "vmin_AB: where along:" in tail
    assert "link_points" not in solve(parse_scene(_slider_crank(60))).to_dict()["error_bounds"]


# ----------------------------------------------------------------------------- --answers


def _rod_least(angle):
    """The closed form of the rod AB's slowest point of the line AB (Rattan's slider crank
    of the textbook scene, 480 / 1600 mm, 20 rad/s): |omega_AB| times the distance of the
    rod's instantaneous centre I (OA produced meets the normal to the stroke at B) from AB."""
    from reference import reference_slider_crank

    r, l, th = mpf("0.48"), mpf("1.6"), mpmath.radians(angle)
    ref = reference_slider_crank(r, l, 0, th, 20, 0)
    A, B = (r * mpmath.cos(th), r * mpmath.sin(th)), (ref["x"], mpf(0))
    t = B[0] / mpmath.cos(th)
    ic = (t * mpmath.cos(th), t * mpmath.sin(th))
    d = (B[0] - A[0], B[1] - A[1])
    dist = abs(d[0] * (ic[1] - A[1]) - d[1] * (ic[0] - A[0])) / mpmath.hypot(*d)
    return float(abs(ref["omega_rod"]) * dist)


def _book_without_answers(tmp_path):
    """The textbook scene with its [answers] left out, and a student's answer file asking
    vmin_EB (E on the rod produced beyond A: the foot falls between E and B) and at_AB."""
    text = BOOK.read_text()
    scene = tmp_path / "scene.toml"
    scene.write_text(text[: text.index("[answers]")])
    answers = tmp_path / "answers.toml"
    answers.write_text(
        'student = "A. Student"\n[answers]\nvmin_EB = "9.3 m/s"\nat_AB = "168 m/s^2"\n'
    )
    return scene, answers


def _run(*args):
    from polygon_method.cli import main

    return main([str(a) for a in args])


def test_solve_and_steps_show_what_an_answer_file_asks(tmp_path, capsys):
    scene, answers = _book_without_answers(tmp_path)
    assert _run("solve", scene) == 0
    assert "asked of two points" not in capsys.readouterr().out  # the scene asks none
    assert _run("solve", scene, "--answers", answers) == 0
    out = capsys.readouterr().out
    assert "vmin_EB = 9.275 m/s at P on EB" in out and "at_AB = alpha_AB x AB" in out
    assert _run("solve", scene, "--answers", answers, "--json") == 0
    d = json.loads(capsys.readouterr().out)
    want = _rod_least(60)  # the foot between E and B: the line's least is the segment's
    assert abs(d["link_points"]["vmin_EB"]["value"] - want) <= 1e-9 * want
    assert d["link_points"]["vmin_EB"]["where"] == "between"
    assert set(d["error_bounds"]["link_points"]) == {"vmin_EB", "at_AB"}
    assert _run("steps", scene, "--answers", answers) == 0
    steps = " ".join(capsys.readouterr().out.split())
    assert "from o draw op perpendicular to eb, meeting eb at p" in steps


def test_the_answer_files_keys_replace_the_scenes(tmp_path, capsys):
    """As check and page read one: the file's [answers] in place of the scene's."""
    answers = tmp_path / "answers.toml"
    answers.write_text('[answers]\nar_EA = "1 m/s^2"\n')
    assert _run("solve", BOOK, "--json") == 0
    assert set(json.loads(capsys.readouterr().out)["link_points"]) == {"vmin_AB", "ar_BA", "at_BA"}
    assert _run("solve", BOOK, "--json", "--answers", answers) == 0
    assert set(json.loads(capsys.readouterr().out)["link_points"]) == {"ar_EA"}


def test_draw_marks_op_where_an_answer_file_asks_vmin(tmp_path, capsys):
    scene, answers = _book_without_answers(tmp_path)
    out = tmp_path / "v.svg"
    assert _run("draw", scene, "--diagram", "velocity", "-o", out) == 0
    assert "velocity-least" not in out.read_text()
    assert _run("draw", scene, "--diagram", "velocity", "--answers", answers, "-o", out) == 0
    assert 'id="velocity-least-E-B-0"' in out.read_text()


@pytest.mark.parametrize(
    "body,words",
    [
        ('[answers]\nvmin_OB = "1 m/s"\n', "[answers] vmin_OB (line 2): O and B are not two"),
        ('[answers]\nvmin_Eb = "1 m/s"\n', "did you mean"),
        ('variant = "07"\n[answers]\nvmin_AB = "1 m/s"\n', "names variant '07'"),
    ],
)
def test_a_bad_answer_file_is_one_line_naming_it(tmp_path, capsys, body, words):
    scene, _ = _book_without_answers(tmp_path)
    bad = tmp_path / "bad.toml"
    bad.write_text(body)
    for command in ("solve", "steps"):
        assert _run(command, scene, "--answers", bad) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and str(bad) in err and words in err, err
    assert _run("draw", scene, "--answers", bad, "-o", tmp_path / "x.svg") == 2
    assert not (tmp_path / "x.svg").exists()
    capsys.readouterr()
    assert _run("draw", scene, "--animate", "--answers", bad, "-o", tmp_path / "x.gif") == 2
    assert "--answers" in capsys.readouterr().err


# ----------------------------------------------------------------------------- sweep


def _csv(path):
    import csv

    with open(path) as f:
        rows = list(csv.reader(f))
    head = [h.split(" [")[0] for h in rows[0]]
    return [dict(zip(head, r)) for r in rows[1:]]


def test_the_sweeps_columns_against_the_closed_form_at_every_angle(tmp_path, capsys):
    """vmin_AB by a golden-section search over the rod's points, their velocities from the
    closed form's v_A (omega r) and v_B (its x differentiated), at every 15 deg; where
    along, and ar_BA, at_BA as omega_rod^2 l and |alpha_rod| l of the closed form."""
    from reference import reference_slider_crank
    from test_least_speed_and_components import _brute_least

    out = tmp_path / "s.csv"
    assert _run("sweep", BOOK, "--steps", 24, "--csv", out) == 0
    rows = _csv(out)
    assert len(rows) == 24 and {"vmin_AB", "vmin_AB_from_A", "ar_BA", "at_BA"} <= set(rows[0])
    r, l, w = mpf("0.48"), mpf("1.6"), 20
    for row in rows:
        th = mpmath.radians(mpf(row["theta"]))
        ref = reference_slider_crank(r, l, 0, th, w, 0)
        va = (-w * r * mpmath.sin(th), w * r * mpmath.cos(th))
        vb = (ref["v"], mpf(0))
        s, v = _brute_least(None, None, va, vb)
        assert abs(float(row["vmin_AB"]) - float(v)) <= 1e-9 * 9.6, row["theta"]
        assert abs(float(row["ar_BA"]) - float(ref["omega_rod"] ** 2 * l)) <= 1e-9 * 57.6
        assert abs(float(row["at_BA"]) - float(abs(ref["alpha_rod"]) * l)) <= 1e-9 * 210
        if abs(ref["omega_rod"]) < 1e-9:  # 90 and 270 deg: the rod does not turn
            assert row["vmin_AB_from_A"] == "", row
        else:
            assert abs(float(row["vmin_AB_from_A"]) - float(s * l)) < 1e-6
    assert any(row["vmin_AB_from_A"] == "" for row in rows)  # (the cases cover it)
    assert any(0.1 < float(row["vmin_AB_from_A"] or 0) < 1.5 for row in rows)  # between


def test_the_summarys_extremes_against_the_closed_form():
    """omega_rod^2 l is greatest at the dead centres, (r omega)^2 / l; |alpha_rod| l at 90
    deg, l r omega^2 / sqrt(l^2 - r^2); the least speed of the rod is 0 at the inner dead
    centre (the piston at rest) and at most v_A = r omega."""
    from polygon_method import load_scene
    from polygon_method.linkage.summary import summarize

    got = {e.name: e for e in summarize(load_scene(BOOK, answers=False)).extremes}
    r, l, w = 0.48, 1.6, 20.0
    assert abs(got["ar_BA"].maximum - (r * w) ** 2 / l) <= 1e-9 * 57.6
    assert got["ar_BA"].at_max % 180 == pytest.approx(0, abs=1e-6)
    want = l * r * w * w / math.sqrt(l * l - r * r)
    assert abs(got["at_BA"].maximum - want) <= 1e-9 * want
    assert got["at_BA"].at_max % 180 == pytest.approx(90, abs=1e-6)
    assert got["vmin_AB"].minimum == 0 and got["vmin_AB"].at_min == pytest.approx(0, abs=1e-6)
    assert abs(got["vmin_AB"].maximum - r * w) <= 1e-9 * r * w
    assert "least speed of a point of AB" in got["vmin_AB"].what


def test_a_sweep_without_the_keys_asked_has_no_such_column(tmp_path, capsys):
    scene, answers = _book_without_answers(tmp_path)
    out = tmp_path / "s.csv"
    assert _run("sweep", scene, "--steps", 4, "--csv", out) == 0
    assert "vmin" not in out.read_text().splitlines()[0]
    assert _run("sweep", scene, "--steps", 4, "--csv", out, "--answers", answers) == 0
    head = out.read_text().splitlines()[0]
    assert "vmin_EB [m/s],vmin_EB_from_E [m]" in head and "at_AB [m/s^2]" in head
    assert _run("sweep", scene, "--summary", "--answers", answers) == 0
    assert "least speed of a point of EB" in capsys.readouterr().out


# ----------------------------------------------------------------------------- the page


def _page_of(tmp_path, name, *args):
    out = tmp_path / f"{name}.html"
    assert _run("page", *args, "--frames", 36, "-o", out) == 0
    return out


def _opened(browser, path, width):
    page = browser.new_page(viewport={"width": width, "height": 900})
    errors = []
    page.on("pageerror", lambda e: errors.append(str(e)))
    page.on("console", lambda m: m.type in ("error", "warning") and errors.append(m.text))
    page.goto(path.as_uri())
    return page, errors


def _slide(page, k):
    page.evaluate(
        "(k) => { const s = document.getElementById('angle'); s.value = k; "
        "s.dispatchEvent(new Event('input')); }",
        k,
    )


def _closed_form_foot(degrees):
    """The rod's velocities by the closed form (v_A = omega r across OA, v_B = omega dx/dth),
    and from them the foot t of the perpendicular from o to ab, p's image and the least
    speed of the rod by a golden-section search over its points (s, speed)."""
    from reference import reference_slider_crank
    from test_least_speed_and_components import _brute_least

    r, l, w = mpf("0.48"), mpf("1.6"), 20
    th = mpmath.radians(mpf(degrees))
    ref = reference_slider_crank(r, l, 0, th, w, 0)
    va, vb = (-w * r * mpmath.sin(th), w * r * mpmath.cos(th)), (ref["v"], mpf(0))
    d = (vb[0] - va[0], vb[1] - va[1])
    t = -(va[0] * d[0] + va[1] * d[1]) / (d[0] ** 2 + d[1] ** 2)
    s, v = _brute_least(None, None, va, vb)
    foot = (float(va[0] + t * d[0]), float(va[1] + t * d[1]))
    return float(t), foot, float(s * l), float(v), float(ref["omega_rod"])


@pytest.mark.parametrize("width", [1280, 390])
def test_the_page_marks_p_where_vmin_is_asked(browser, tmp_path, width):
    """In headless Chromium: at 60 deg p between a and b, at 160 deg beyond b (ab produced
    to it), at 90 deg none (the rod does not turn); op drawn to p's image as the closed form
    puts it, at the panel's scale; the values row and the tooltip say the least speed and
    where; nothing sideways on a phone."""
    from reference import reference_slider_crank

    path = _page_of(tmp_path, "book", BOOK)
    page, errors = _opened(browser, path, width)
    data = json.loads(page.evaluate("document.getElementById('frames').textContent"))
    assert data["theta"][0] == 60 and len(data["least"]) == 1
    for k, where in ((0, "between"), (10, "beyond"), (3, "still")):
        _slide(page, k)
        deg = data["theta"][k]
        t, foot, dist, least, w_rod = _closed_form_foot(deg)
        row = page.text_content("#val-least-vmin_AB")
        op = page.query_selector("#v-least-op-vmin_AB")
        ext = page.query_selector("#v-least-ext-vmin_AB")
        speed = float(row.split()[0])
        assert abs(speed - least) <= 5e-4 * least, (deg, row)  # (four figures)
        ref = reference_slider_crank(mpf("0.48"), mpf("1.6"), 0, mpmath.radians(mpf(deg)), 20, 0)
        for key, want in (("ar_BA", ref["omega_rod"] ** 2), ("at_BA", abs(ref["alpha_rod"]))):
            shown = page.text_content(f"#val-asked-{key}").split()[0]
            assert abs(float(shown) - float(want) * 1.6) <= 5e-4 * float(want) * 1.6 + 1e-12
        if where == "still":
            assert abs(w_rod) < 1e-12 and not op.is_visible() and "does not turn" in row
            continue
        per = float(page.get_attribute("#velocity", "data-per-cm")) / 10  # SI per mm
        x2, y2 = (float(op.get_attribute(a)) for a in ("x2", "y2"))
        assert op.is_visible() and abs(x2 - foot[0] / per) < 2e-3 and abs(y2 + foot[1] / per) < 2e-3
        assert ext.is_visible() == (where == "beyond") and (t > 1) == (where == "beyond")
        if where == "between":  # AP in the scene's mm, four figures
            assert abs(float(row.split("AP = ")[1].split()[0]) - dist * 1000) < 0.05, row
        else:
            assert "at the end B (p falls beyond b)" in row
        tip = page.evaluate("document.querySelector('#v-least-dot-vmin_AB title').textContent")
        assert tip.startswith("vmin_AB = ") and "op = " in tip
        label = page.query_selector("#v-least-lab-vmin_AB")
        assert label.is_visible() and label.text_content().endswith("p")
    plotted = page.evaluate(
        "[...document.querySelectorAll('#plot-v .series title, #plot-a .series title')]"
        ".map((t) => t.textContent)"
    )
    assert "min,AB" in plotted and "BA" in plotted  # v_min,AB; ar_BA and at_BA
    if width == 390:  # a phone: the page does not scroll sideways
        assert page.evaluate("document.documentElement.scrollWidth") <= 390
    page.query_selector("#velocity").screenshot(path=str(tmp_path / f"velocity-{width}.png"))
    assert errors == []
    page.close()


def test_the_page_marks_what_an_answer_file_asks_and_nothing_unasked(browser, tmp_path):
    scene, answers = _book_without_answers(tmp_path)
    bare = _page_of(tmp_path, "bare", scene)
    page, errors = _opened(browser, bare, 1280)
    assert page.query_selector("[id^=v-least]") is None
    assert "op square to xy" not in page.text_content(".legend")
    page.close()
    asked = _page_of(tmp_path, "asked", scene, "--answers", answers)
    page, errors = _opened(browser, asked, 1280)
    t, foot, dist, least, _ = _closed_form_foot(60)
    e = page.query_selector("#v-least-op-vmin_EB")
    assert e.is_visible()
    row = page.text_content("#val-least-vmin_EB")
    assert abs(float(row.split()[0]) - least) <= 5e-4 * least  # the foot lies between E and B
    assert "EP = " in row and "op square to xy" in page.text_content(".legend")
    steps = " ".join(page.text_content("body").split())
    assert "from o draw op perpendicular to eb" in steps
    assert errors == []
    page.close()


def test_sweep_plot_draws_them_beside_the_speeds_and_accelerations():
    """sweep --plot: v_min,AB among the speeds, a^r_BA and a^t_BA among the accelerations,
    each curve the closed form's at its angles."""
    import numpy as np

    from polygon_method import load_scene
    from polygon_method.draw.plots import plot_figure
    from polygon_method.motion.sweeps import sweep

    res = sweep(load_scene(BOOK, answers=False), np.radians(np.arange(0.0, 360.0, 30.0)))
    fig = plot_figure(res)
    lines = {ln.get_label(): ln for ax in fig.axes for ln in ax.get_lines()}
    vmin, ar = lines["$v_{\\mathrm{min,AB}}$"], lines["$a^{r}_{\\mathrm{BA}}$"]
    assert "$a^{t}_{\\mathrm{BA}}$" in lines
    for deg, v, a in zip(vmin.get_xdata(), vmin.get_ydata(), ar.get_ydata()):
        _, _, _, least, w_rod = _closed_form_foot(deg)
        assert abs(v - least) <= 1e-9 * 9.6, deg
        assert abs(a - w_rod**2 * 1.6) <= 1e-9 * 57.6, deg
    assert len(vmin.get_xdata()) == 12


GROUND_LINK = """
units = "mm"
[ground]
O2 = [0, 0]
O4 = [300, 0]
[links]
"O2-A" = 100
AB = 250
"O4-B" = 200
"O2-O4" = 300
[input]
crank = "O2-A"
angle = 30
speed = "10 rad/s ccw"
[assembly]
B = "above"
[answers]
vmin_O2-O4 = "0 m/s"
ar_O4-O2 = "0 m/s^2"
vmin_O4-B = "1 m/s"
"""


def test_the_frames_own_link_asked_is_at_rest_in_every_view(tmp_path, capsys):
    """Two fixed points (the frame written as a link): 0 at every angle, in one array per
    view (a constant would break the summary's arrays); O4-B turns about the fixed O4: its
    slowest point is the pivot, at 0 m/s, 0 m from O4."""
    scene = tmp_path / "g.toml"
    scene.write_text(GROUND_LINK)
    assert _run("sweep", scene, "--summary") == 0
    out = capsys.readouterr().out
    assert "vmin_O2-O4  m/s                0 (constant)" in out
    csv = tmp_path / "g.csv"
    assert _run("sweep", scene, "--steps", 8, "--csv", csv) == 0
    rows = _csv(csv)
    assert all(float(r["vmin_O2-O4"]) == 0 and r["vmin_O2-O4_from_O2"] == "" for r in rows)
    assert all(float(r["vmin_O4-B"]) == 0 and float(r["vmin_O4-B_from_O4"]) == 0 for r in rows)
    assert all(float(r["ar_O4-O2"]) == 0 for r in rows)
    assert _run("page", scene, "--frames", 8, "-o", tmp_path / "g.html") == 0
    capsys.readouterr()
    assert _run("solve", scene, "--json") == 0
    d = json.loads(capsys.readouterr().out)
    assert d["link_points"]["vmin_O2-O4"]["where"] == "translating"


# ----------------------------------------------------------------------------- edges


def _pairs_of(sol):
    """Every two points of one moving link (its ends and its carried points), each once."""
    sc = sol.scene
    out = []
    for lk in sc.links:
        if lk.p in sc.ground and lk.q in sc.ground:
            continue
        on = [lk.p, lk.q] + [c.name for c in sc.points if c.link == lk.key]
        out += [(x, y) for i, x in enumerate(on) for y in on[i + 1 :]]
    return out


@pytest.mark.parametrize("fam", list(EDGE_FAMILIES))
def test_every_records_bound_holds_on_mechanisms_near_their_edges(fam):
    """Random mechanisms of the error bound's edge families (benchmarks/edge_families.py:
    a flat triangle, a plate on a short side, a motion given near a dead centre, a path a
    hair off round or through a far point, a block then a toggle, pegs, cylinders, rolling,
    triads, yokes), every two points of every moving link: each number of the vmin, ar and
    at records within its bound of the 40-digit reference of the scene's own decimals (the
    largest error was 0.16 of its bound when this was written)."""
    import random

    from edge_families import make, reference_scene
    from error_bounds import load_reference

    from polygon_method.common.errors import PolygonMethodError
    from polygon_method.motion.link_points import components

    ref_mod = load_reference(40)
    rng = random.Random(f"keys-{fam}")
    done = tries = 0
    while done < 3:
        tries += 1
        assert tries <= 12, f"{fam}: most cases refused"
        text = make(fam, rng, 10.0 ** rng.uniform(-3, 0))
        try:
            sol = solve(parse_scene(text))
        except PolygonMethodError:
            continue
        done += 1
        with ref_mod.mpmath.workdps(ref_mod.DIGITS):
            r = ref_mod.reference_solution(reference_scene(sol, text, ref_mod), sol.P)
        k = sol.error_bounds.scales
        checked = 0
        for x, y in _pairs_of(sol):
            for kind in ("vmin", "ar", "at"):
                rec = (
                    least_speed(sol, x, y) if kind == "vmin" else components(sol, x, y)
                ).as_dict()
                if kind == "vmin" and rec["where"] == "translating":
                    continue
                want = _exact_of(r, sol, kind, x, y)
                for part, bound in pair_bounds(sol, kind, x, y).items():
                    if part == "value" or part in ("omega", "alpha"):
                        continue
                    size = _SIZE[part]
                    size = 1.0 if size == 1 else k[size]
                    if part == "position":
                        err = max(abs(float(w) - h) for w, h in zip(want[part], rec[part]))
                    else:
                        err = abs(float(want[part]) - rec[part])
                    assert err <= bound * size, (fam, kind, x, y, part, err, bound * size, text)
                    checked += 1
        assert checked


def _exact_of(r, sol, kind, x, y):
    """The record's numbers worked in mpmath from the reference's solution ``r``."""
    P, V = r["positions"], r["velocities"]
    (px, py), (qx, qy) = P[x], P[y]
    length = mpmath.hypot(qx - px, qy - py)
    if kind != "vmin":
        key = _link(sol, x, y)
        w, al = r["omega"][key], r["alpha"][key]
        return {"r": length, "radial": w * w * length, "tangential": abs(al) * length}
    b, c = V[x], V[y]
    d = (c[0] - b[0], c[1] - b[1])
    dd = d[0] ** 2 + d[1] ** 2
    t = -(b[0] * d[0] + b[1] * d[1]) / dd
    at = min(max(t, mpf(0)), mpf(1))
    return {
        "speed": mpmath.hypot(b[0] + at * d[0], b[1] + at * d[1]),
        "foot_speed": abs(b[0] * c[1] - b[1] * c[0]) / mpmath.sqrt(dd),
        "foot_fraction": t,
        "fraction": at,
        "distance": at * length,
        "position": (px + at * (qx - px), py + at * (qy - py)),
    }


def test_the_sweeps_err_max_covers_the_asked_columns():
    """sweep --csv --error-bound: err_max at each angle is at least each asked column's own
    bound (the value's; the slowest point's distance where the rod turns), the bound
    solve --json gives at that angle, and every such column is within it of the closed
    form (the rod near 90 deg, where where-along grows uncertain, included)."""
    import dataclasses

    import numpy as np

    from polygon_method import load_scene
    from polygon_method.motion.sweeps import sweep

    scene = load_scene(BOOK, answers=False)
    degrees = [0.0, 30.0, 60.0, 89.9999999, 90.0, 160.0, 270.00001]
    res = sweep(scene, np.radians(degrees))
    cols = {name: np.asarray(a) for name, _, a in res.columns(error_bound=True)}
    sizes = res.error_bounds.scales
    for i, deg in enumerate(degrees):
        sol = solve(
            dataclasses.replace(scene, input=dataclasses.replace(scene.input, angle=res.theta[i]))
        )
        worst = cols["err_max"][i]
        for key, kind, names in (
            ("vmin_AB", "vmin", "AB"),
            ("ar_BA", "ar", "BA"),
            ("at_BA", "at", "BA"),
        ):
            b = pair_bounds(sol, kind, *names)
            assert worst >= b["value"] * (1 - 1e-9), (deg, key)
            if "distance" in b:
                assert worst >= b["distance"] * (1 - 1e-9), (deg, key)
        _, _, dist, least, w_rod = _closed_form_foot(deg)
        vs = np.broadcast_to(sizes["velocity"], res.theta.shape)[i]
        assert abs(cols["vmin_AB"][i] - least) <= worst * vs
        if abs(w_rod) > 1e-6:
            ps = np.broadcast_to(sizes["position"], res.theta.shape)[i]
            assert abs(cols["vmin_AB_from_A"][i] - dist) <= max(worst * ps, 1e-7)


def test_two_least_speeds_asked_have_feet_of_their_own_names(tmp_path, capsys):
    """vmin_AB and vmin_C-B on one polygon: p and f (the next letter the scene leaves free),
    in the solution's words, the steps, and the page's marks; each value the brute-force
    least of the reference's velocities."""
    from test_least_speed_and_components import _brute_least

    text = FOURBAR.format(angle=40, answers='vmin_AB = "1 m/s"\nvmin_C-B = "1 m/s"')
    scene = tmp_path / "fb.toml"
    scene.write_text(text)
    assert _run("solve", scene) == 0
    out = capsys.readouterr().out
    assert "the foot p of the perpendicular from o to ab" in out
    assert "at F on CB: the foot f of the perpendicular from o to cb" in out
    sol = solve(parse_scene(text))
    V = reference_solution(sol.scene, sol.P)["velocities"]
    for key, (x, y) in (("vmin_AB", "AB"), ("vmin_C-B", "CB")):
        _, want = _brute_least(None, None, V[x], V[y])
        got = json.loads(json.dumps(sol.to_dict()))["link_points"][key]["value"]
        assert abs(got - float(want)) <= 1e-9 * float(want), key
    from polygon_method.page.data import page_data
    from polygon_method.page.frames import frames

    least = page_data(frames(sol.scene, 6))["least"]
    assert [(d["key"], d["p"], d["P"]) for d in least] == [
        ("vmin_AB", "p", "P"),
        ("vmin_C-B", "f", "F"),
    ]
