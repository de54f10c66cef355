"""The page (``polygon-method page``) and the animations (``draw --animate``), without a
browser: the frames against independent solves at their angles, the page's data against
its frames, the size and self-containment of the page, the GIF's frames, and the command
line on every worked problem and on bad input. The page's script is tested in a browser in
``test_page_browser.py``."""

import dataclasses
import glob
import io
import json
import math
import re
from pathlib import Path

import numpy as np
import pytest

from polygon_method.scene import load_scene

import polygon_method as pm
from polygon_method.cli import main
from polygon_method.page import frames, page_html
from polygon_method.page.animate import animation
from polygon_method.page.data import page_data
from polygon_method.polygons.scales import diagram_scales

ROOT = Path(__file__).resolve().parents[1]
WORKED = sorted(glob.glob(str(ROOT / "worked_problems" / "*.toml")))
SEED = str(ROOT / "worked_problems" / "fourbar_image_points.toml")
# scenes whose assembly words pick the sweep's branch at every angle (the Whitworth's
# "left" does not: solved afresh at another angle it may take the other assembly)
SAME_BRANCH = [
    "fourbar_image_points",
    "crank_slotted_lever",
    "toggle_mechanism",
    "six_link_second_slider",
    "two_slider_mechanism",
    "offset_slider_crank",
]


def at_angle(scene, theta):
    """The scene with its crank at ``theta`` (rad), solved afresh: an independent solve."""
    return pm.solve(
        dataclasses.replace(scene, input=dataclasses.replace(scene.input, angle=float(theta)))
    )


def _json_of(html: str) -> dict:
    m = re.search(r'<script type="application/json" id="frames">(.*?)</script>', html, re.S)
    return json.loads(m.group(1).replace("<\\/", "</"))


@pytest.mark.parametrize("name", SAME_BRANCH)
def test_frames_match_solve_at_their_angles(name):
    scene = pm.load_scene(str(ROOT / "worked_problems" / f"{name}.toml"))
    fr = frames(scene, 24)
    res = fr.res
    assert len(fr) == 24
    for k in sorted({0, fr.start, 5, 11, len(fr) - 1}):
        sol = at_angle(scene, res.theta[k])
        size = {
            "P": max(math.hypot(*xy) for xy in sol.P.values()),
            "V": max(math.hypot(*xy) for xy in sol.V.values()),
            "A": max(math.hypot(*xy) for xy in sol.A.values()),
        }
        for table in ("P", "V", "A"):
            for p in scene.point_names:
                got = [float(np.broadcast_to(c, (len(fr),))[k]) for c in getattr(res, table)[p]]
                want = getattr(sol, table)[p]
                assert math.dist(got, want) <= 1e-9 * size[table], (name, k, table, p)
        wmax = max(abs(w) for w in sol.W.values()) + 1e-300
        amax = max(abs(a) for a in sol.Al.values()) + wmax * wmax
        for lk in scene.links:
            assert (
                abs(float(np.broadcast_to(res.W[lk.key], (len(fr),))[k]) - sol.W[lk.key])
                <= 1e-9 * wmax
            )
            assert (
                abs(float(np.broadcast_to(res.Al[lk.key], (len(fr),))[k]) - sol.Al[lk.key])
                <= 1e-9 * amax
            )


def test_frames_start_at_the_stated_instant_and_keep_the_step_tables_scales():
    scene = pm.load_scene(SEED)
    fr = frames(scene, 180)
    assert math.isclose(fr.res.theta[fr.start], scene.input.angle, abs_tol=1e-15)
    assert [s.text for s in fr.scales] == [s.text for s in diagram_scales(pm.solve(scene))]
    steps = pm.solve(scene)
    from polygon_method.text.steptable import steps_text

    text = steps_text(steps)
    for s in fr.scales:  # the scales the page states are the ones the step table states
        assert s.text in text


def test_frames_stay_between_the_limit_positions():
    scene = pm.load_scene(SEED)  # a crank that cannot turn fully
    fr = frames(scene, 90)
    dom = fr.res.domain
    assert not fr.full_turn and len(dom.limits) == 2
    th = fr.res.theta
    assert np.all(np.diff(th) > 0)
    assert dom.lo < th[0] and th[-1] < dom.hi
    full = frames(pm.load_scene(str(ROOT / "worked_problems" / "crank_slotted_lever.toml")), 90)
    step = np.diff(full.res.theta)
    assert (
        full.full_turn
        and np.allclose(step, step[0])
        and math.isclose(abs(step[0]) * 90, 2 * math.pi)
    )
    assert step[0] < 0  # the crank turns clockwise: the frames follow it


def test_a_four_stroke_engine_is_animated_over_its_720_degree_cycle(tmp_path, capsys):
    # the indicator table of the worked engine runs 0 to 720 deg (cycle = "4-stroke"): its
    # gas force at 30 deg (the suction stroke, -0.1 bar) and at 390 deg (the expansion
    # stroke, 32 bar) differ, so one turn of frames would show half the cycle
    path = ROOT / "worked_problems" / "engine_flywheel.toml"
    scene = pm.load_scene(str(path))
    assert math.isclose(math.degrees(scene.indicator.x[-1]), 720)
    fr = frames(scene, 8)
    step = np.diff(fr.res.theta)
    assert fr.full_turn and np.allclose(step, math.radians(90)) and fr.start == 0
    assert sorted(np.round(fr.degrees % 720, 9)) == [30 + 90 * k for k in range(8)]
    assert page_data(fr)["cycle"] == 720
    assert main(["page", str(path), "--frames", "8", "-o", str(tmp_path / "e.html")]) == 0
    html = (tmp_path / "e.html").read_text()
    assert "2 turns of the crank (720°)" in html
    assert re.search(r"stated instant is θ =\s*390°", html)  # 390 deg, not 30
    assert "(720 deg)" in capsys.readouterr().out
    svg = animation(fr, "svg")  # the angles shown run round the cycle, not a turn
    assert "crank angles (deg): 390.0;480.0;570.0;660.0;30.0;120.0;210.0;300.0" in svg


def test_page_data_is_the_frames_rounded_to_six_figures():
    scene = pm.load_scene(SEED)
    fr = frames(scene, 60)
    d = _json_of(page_html(fr))
    assert d == json.loads(json.dumps(page_data(fr)))
    n = len(fr)
    for key, table in (("P", fr.res.P), ("V", fr.res.V), ("A", fr.res.A)):
        # rounding noise (1e-10 of the largest of its kind) is written as 0
        noise = 1e-10 * max(
            float(np.max(np.hypot(*(np.broadcast_to(c, (n,)) for c in xy))))
            for xy in table.values()
        )
        for p in fr.moving:
            exact = np.column_stack([np.broadcast_to(c, (n,)) for c in table[p]]).ravel()
            got = np.array(d[key][p])
            assert np.all(np.abs(got - exact) <= 5.0001e-6 * np.abs(exact) + noise)
    for lk in scene.links:
        if lk.key in d["W"]:
            exact = np.broadcast_to(fr.res.W[lk.key], (n,))
            assert np.all(np.abs(np.array(d["W"][lk.key]) - exact) <= 5.0001e-6 * np.abs(exact))
    assert np.allclose(d["theta"], fr.degrees, atol=5e-7, rtol=0)


@pytest.mark.parametrize("name", ["fourbar_image_points", "crank_slotted_lever", "whitworth"])
def test_the_pages_component_ends_close_the_polygons(name):
    """The page draws each centripetal component to its ``knees`` point and each block's
    guide point from ``guidePoints``: the tangential component alpha perp(q - p) from the
    knee reaches a_q, and the guide's point under a block moves with the guide link
    (v = v_G + omega perp(X - G), a = a_G - omega^2 (X - G) + alpha perp(X - G)), its
    sliding and Coriolis components reaching a_X: closures against the frames' own
    relations, written here afresh."""
    scene = pm.load_scene(str(ROOT / "worked_problems" / f"{name}.toml"))
    fr = frames(scene, 24)
    d, res, n = page_data(fr), fr.res, len(fr)

    def b(x):
        return np.broadcast_to(np.asarray(x, dtype=float), (n,))

    def xy(flat):
        a = np.array(flat).reshape(n, 2)
        return a[:, 0], a[:, 1]

    amax = max(float(np.max(np.hypot(b(a[0]), b(a[1])))) for a in res.A.values())
    vmax = max(float(np.max(np.hypot(b(v[0]), b(v[1])))) for v in res.V.values())
    checked = 0
    for p, q, key in d["links"]:
        kx, ky = xy(d["knees"][key])
        rx, ry = b(res.P[q][0]) - b(res.P[p][0]), b(res.P[q][1]) - b(res.P[p][1])
        al = b(res.Al[key])
        assert np.allclose(kx - al * ry, b(res.A[q][0]), rtol=0, atol=1e-5 * amax)
        assert np.allclose(ky + al * rx, b(res.A[q][1]), rtol=0, atol=1e-5 * amax)
        checked += 1
    for s in d["sliders"]:
        if "guide" not in s:
            continue
        g, link, x = s["guide"][0], s["link"], s["point"]
        w, al = b(res.W[link]), b(res.Al[link])
        rx, ry = b(res.P[x][0]) - b(res.P[g][0]), b(res.P[x][1]) - b(res.P[g][1])
        vg = (b(res.V[g][0]), b(res.V[g][1])) if g in res.V else (0.0, 0.0)
        ag = (b(res.A[g][0]), b(res.A[g][1])) if g in res.A else (0.0, 0.0)
        v1, a1, back = (xy(f) for f in d["guidePoints"][s["key"]])
        assert np.allclose(v1[0], vg[0] - w * ry, rtol=0, atol=1e-5 * vmax)
        assert np.allclose(v1[1], vg[1] + w * rx, rtol=0, atol=1e-5 * vmax)
        assert np.allclose(a1[0], ag[0] - w * w * rx - al * ry, rtol=0, atol=1e-5 * amax)
        assert np.allclose(a1[1], ag[1] - w * w * ry + al * rx, rtol=0, atol=1e-5 * amax)
        vs = b(res.S[s["key"]][0])  # the Coriolis component 2 omega vs, across the guide
        assert np.allclose(
            np.hypot(b(res.A[x][0]) - back[0], b(res.A[x][1]) - back[1]),
            2 * np.abs(w * vs),
            rtol=0,
            atol=1e-5 * amax,
        )
        checked += 1
    assert checked >= len(d["links"]) + (name != "fourbar_image_points")


def test_page_is_small_and_self_contained(tmp_path):
    out = tmp_path / "page.html"
    assert main(["page", SEED, "-o", str(out)]) == 0
    html = out.read_text(encoding="utf-8")
    assert len(html.encode()) < 2_000_000  # the bound for 180 frames
    assert len(_json_of(html)["theta"]) == 180
    assert not re.search(r"""(src|href)\s*=\s*["']?\s*(https?:)?//""", html, re.I)
    assert not re.search(r"<script[^>]*\ssrc=", html, re.I)
    assert not re.search(r"<link\b|@import|url\(\s*['\"]?(https?:)?//", html, re.I)
    assert "<svg" in html and 'id="angle"' in html and 'id="play"' in html
    # the step table and the check table (the scene has answers; one is wrong)
    assert "Step by step" in html and "v_CB" in html and "WRONG" in html


def test_page_checks_an_answer_file(tmp_path):
    ans = tmp_path / "student.toml"
    ans.write_text('[answers]\nv_C = "0.40 m/s"\nomega_BC = "9 rad/s"\n')
    out = tmp_path / "page.html"
    assert main(["page", SEED, "-o", str(out), "--answers", str(ans), "--frames", "12"]) == 0
    html = out.read_text(encoding="utf-8")
    table = html[html.index('id="check"') :]
    table = table[: table.index("</table>")]
    assert table.count("<tr>") == 3 and table.count("WRONG") == 1


@pytest.mark.parametrize(
    "argv, words",
    [
        (["page", "missing.toml", "-o", "{d}/p.html"], "missing.toml"),
        (["page", SEED, "-o", "{d}/p.htm"], None),
        (["page", SEED, "-o", "{d}/p.pdf"], ".html"),
        (["page", SEED, "-o", "{d}/p.html", "--frames", "1"], "--frames"),
        (["page", SEED, "-o", "{d}/nodir/p.html"], "no directory"),
        (["page", SEED, "-o", "{d}/p.html", "--answers", "{d}/none.toml"], "none.toml"),
        (["draw", SEED, "--animate", "-o", "{d}/c.png"], ".gif"),
        (["draw", SEED, "--animate", "-o", "{d}/c.gif", "--frames", "0"], "--frames"),
        (["draw", SEED, "--animate", "--diagram", "velocity", "-o", "{d}/c.gif"], "--animate"),
    ],
)
def test_bad_input_is_one_line_and_exit_2(tmp_path, capsys, argv, words):
    argv = [a.replace("{d}", str(tmp_path)) for a in argv]
    code = main(argv)
    err = capsys.readouterr().err
    if words is None:  # .htm is an HTML page too
        assert code == 0
        return
    assert code == 2, err
    assert len(err.strip().splitlines()) == 1 and words in err and "Traceback" not in err
    assert not [p for p in tmp_path.iterdir() if p.suffix in (".html", ".gif")]


def test_a_failing_page_leaves_the_old_file(tmp_path):
    out = tmp_path / "page.html"
    out.write_text("old")
    bad = tmp_path / "bad.toml"
    bad.write_text("[links]\nAB = -1\n")
    assert main(["page", str(bad), "-o", str(out)]) == 2
    assert out.read_text() == "old"


def test_gif_has_the_frames_asked_for(tmp_path):
    from PIL import Image

    out = tmp_path / "cycle.gif"
    assert main(["draw", SEED, "--animate", "-o", str(out), "--frames", "5"]) == 0
    with Image.open(out) as im:
        assert im.format == "GIF" and im.n_frames == 5
        first = im.convert("RGB").tobytes()
        im.seek(3)
        assert im.convert("RGB").tobytes() != first  # the mechanism moved


def test_svg_and_html_animations(tmp_path):
    fr = frames(pm.load_scene(SEED), 6)
    svg = animation(fr, "svg")
    import xml.etree.ElementTree as ET

    root = ET.fromstring(svg)
    anims = [e for e in root.iter() if e.tag.endswith("animate")]
    assert anims and all(len(a.get("values").split(";")) == 6 for a in anims)
    # the velocity vector of C, drawn from the pole: its end is v_C / scale at each frame
    vscale = fr.scales[1].per_cm
    ends = [float(v) for a in anims for v in a.get("values").split(";")]
    for k in range(6):
        x = float(np.broadcast_to(fr.res.V["C"][0], (6,))[k]) / vscale
        assert min(abs(e - x) for e in ends) < 6e-4
    out = tmp_path / "cycle.html"
    assert main(["draw", SEED, "--animate", "-o", str(out), "--frames", "4"]) == 0
    assert "<script" in out.read_text(encoding="utf-8")


@pytest.mark.parametrize("path", WORKED, ids=lambda p: Path(p).stem)
def test_page_and_animation_of_every_worked_problem(tmp_path, path):
    out = tmp_path / "page.html"
    assert main(["page", path, "-o", str(out), "--frames", "24"]) == 0
    d = _json_of(out.read_text(encoding="utf-8"))
    given = load_scene(path).input.given is not None
    n = len(d["theta"])
    # a motion given on a piston leaves out the frames at its dead centres (the crank's
    # speed unbounded there): 0 and 180 deg of a full turn in 15 deg steps
    assert n == 24 or (given and n == 22), n
    assert 0 <= d["start"] < n
    for values in list(d["P"].values()) + list(d["V"].values()) + list(d["A"].values()):
        assert len(values) == 2 * n and all(math.isfinite(v) for v in values)
    assert main(["draw", path, "--animate", "-o", str(tmp_path / "c.svg"), "--frames", "8"]) == 0
    assert main(["draw", path, "--animate", "-o", str(tmp_path / "c.gif"), "--frames", "2"]) == 0
    from PIL import Image

    with Image.open(tmp_path / "c.gif") as im:
        assert im.n_frames == 2


def test_the_scene_is_never_written_over_by_a_page(tmp_path, capsys):
    scene = tmp_path / "s.toml"
    scene.write_bytes(Path(SEED).read_bytes())
    link = tmp_path / "s.html"
    link.symlink_to(scene.name)
    for argv in (
        ["page", str(scene), "-o", str(link)],
        ["draw", str(scene), "--animate", "-o", str(tmp_path / "s.svg")],
    ):
        if argv[0] == "draw":
            (tmp_path / "s.svg").symlink_to(scene.name)
        code = main(argv)
        err = capsys.readouterr().err
        assert code == 2 and "scene file itself" in err and len(err.strip().splitlines()) == 1
    assert scene.read_bytes() == Path(SEED).read_bytes()


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full here")
def test_a_page_to_a_device_is_one_line(capsys):
    code = main(["page", SEED, "-o", "/dev/full", "--frames", "4"])  # not an .html name
    err = capsys.readouterr().err
    assert code == 2 and ".html" in err and len(err.strip().splitlines()) == 1


def test_animation_html_is_self_contained(tmp_path):
    """No network reference at all: no URL (http, https or protocol-relative), no <link>,
    no src but the frames' own data, so that its buttons work offline."""
    out = tmp_path / "cycle.html"
    assert main(["draw", SEED, "--animate", "-o", str(out), "--frames", "5"]) == 0
    html = out.read_text(encoding="utf-8")
    assert "http://" not in html and "https://" not in html and "//cdn" not in html
    assert "<link" not in html and "@import" not in html and "url(" not in html
    assert re.findall(r'src="(?!data:)', html) == []
    assert html.count("data:image/png;base64,") == 5
    for button in ('id="play"', 'id="back"', 'id="next"'):  # labelled in text, not icons
        assert re.search(button + r"[^>]*>[^<]+</button>", html), button


def _polygon_extents(table, names, n):
    """Per frame, the extent (SI) of a polygon's images and its pole, from the sweep."""
    xy = [np.zeros((n, 2))] + [
        np.column_stack([np.broadcast_to(table[p][0], (n,)), np.broadcast_to(table[p][1], (n,))])
        for p in names
    ]
    xy = np.stack(xy)
    return np.max(xy.max(axis=0) - xy.min(axis=0), axis=1)


@pytest.mark.parametrize(
    "name", ["fourbar_image_points", "crank_slotted_lever", "whitworth", "rolling_epicyclic"]
)
def test_animation_pictures_state_round_scales_that_fit_their_panels(name):
    """Each picture is at least 800 px wide; each polygon's stated scale is round (1, 2 or
    5 x 10^k per cm) and at it the polygon (its images and pole, from the sweep) fits its
    panel and spans at least a quarter of it, wherever it is not near rest."""
    from polygon_method.page.raster import PANEL, PX_PER_CM, Pictures

    fr = frames(pm.load_scene(f"worked_problems/{name}.toml"), 48)
    pics = Pictures(fr)
    assert pics.size[0] >= 800
    n = len(fr)
    for phase, table in (("velocity", fr.res.V), ("acceleration", fr.res.A)):
        size = _polygon_extents(table, fr.moving, n)
        rest = 0.05 * np.median(size)
        looked = 0
        for k in range(n):
            words = pics.scale_text(phase, k).split()
            per = float(words[3])
            m = per / 10 ** math.floor(math.log10(per) + 1e-12)
            assert min(abs(m - r) for r in (1, 2, 5)) < 1e-9, words
            px = size[k] / per * PX_PER_CM
            assert px <= PANEL, (phase, k, px)
            if size[k] > rest:
                assert px >= PANEL / 4, (phase, k, px)
                looked += 1
        assert looked > n // 2
    first = pics.picture(0)
    assert first.size == pics.size and first.mode == "P"


def test_gif_frames_are_written_as_they_are_drawn(monkeypatch):
    """Never more than one picture alive at a time: each frame goes into the GIF as soon as
    it is drawn (bounded memory, whatever the count of frames)."""
    import gc
    import weakref
    from PIL import Image
    from polygon_method.page import raster

    alive, most = [], [0]
    draw = raster.Pictures.picture

    def counted(self, k):
        gc.collect()
        live = [r for r in alive if r() is not None]
        most[0] = max(most[0], len(live))
        im = draw(self, k)
        alive.append(weakref.ref(im))
        return im

    monkeypatch.setattr(raster.Pictures, "picture", counted)
    fr = frames(pm.load_scene(SEED), 12)
    gif = animation(fr, "gif")
    assert len(alive) == 12 and most[0] <= 1
    with Image.open(io.BytesIO(gif)) as im:
        assert im.n_frames == 12 and im.size[0] >= 800


@pytest.mark.parametrize(
    "name,words", [("tipper_cylinder", "crank angle"), ("ellipse_trammel", "place of block A")]
)
def test_the_slider_is_labelled_with_what_the_frames_step_through(name, words):
    """The page's slider says what it moves: the crank angle, or a driving block's place."""
    fr = frames(load_scene(ROOT / "worked_problems" / f"{name}.toml"), 12)
    label = re.search(r'<label for="angle">(.*?)</label>', page_html(fr)).group(1)
    assert label == words
