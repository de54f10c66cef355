"""The diagrams, measured from the SVG files themselves.

Lengths are read from the SVG's own coordinates (user units are points, 72 to the inch,
and the root's width/height are in pt): a vector drawn at ``1 cm = 0.1 m/s`` must be
|v| / 0.1 cm long on the page, the scale bar n cm. Labels are the ink boxes of their glyphs
(the glyph outlines the SVG defines, moved and scaled as the SVG says), checked with
shapely against each other and against every line, arrow and outline drawn.
"""

import glob
import math
import os
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from shapely.geometry import LineString, Polygon, box

from polygon_method import parse_scene, solve
from polygon_method.cli import main
from polygon_method.polygons.constructions import acceleration_constructions, velocity_constructions
from polygon_method.draw import choose_scales, drawn_vectors, make_figure, render, svg_string
from polygon_method.polygons.scales import parse_scale
from reference import reference_solution
from scenes import seed

ROOT = Path(__file__).resolve().parents[1]
WORKED = sorted(glob.glob(str(ROOT / "worked_problems" / "*.toml")))
SVGNS = "{http://www.w3.org/2000/svg}"
XLINK = "{http://www.w3.org/1999/xlink}href"
CM = 72 / 2.54  # pt per cm

FOURBAR = seed(
    middle='[points]\nE = { on = "BC", along = 40 }\n'
    'F = { on = "BC", distances = { B = 45, C = 30 }, turn = "cw" }\n'
    'G = { on = "CD", distances = { C = 24, D = 44 }, turn = "cw" }\n'
    '[assembly]\nC = "above"\n',
    drive='angle = 60\nspeed = "10.5 rad/s cw"\nacceleration = "40 rad/s^2 ccw"',
    after="[pins]\nB = { radius = 10 }\n",
)

SLOTTED = """
[ground]
O = [0, 0]
C = [0, -300]
[links]
OA = 150
CP = 600
[sliders]
A = { along = "CP" }
[assembly]
P = "above"
[input]
crank = "OA"
angle = 30
speed = "20 rad/s ccw"
"""


@pytest.fixture(scope="module")
def fourbar():
    return solve(parse_scene(FOURBAR))


# --------------------------------------------------------------------------- SVG reading

_NUM = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def _points(d):
    nums = [float(x) for x in _NUM.findall(d or "")]
    return list(zip(nums[0::2], nums[1::2]))


def _transform(text):
    """(a, b, c, d, e, f) of an SVG transform made of translate/scale (x' = a x + e ...)."""
    m = [1.0, 0.0, 0.0, 1.0, 0.0, 0.0]
    for op, args in re.findall(r"(\w+)\(([^)]*)\)", text or ""):
        v = [float(x) for x in _NUM.findall(args)]
        if op == "translate":
            t = [1, 0, 0, 1, v[0], v[1] if len(v) > 1 else 0.0]
        elif op == "scale":
            t = [v[0], 0, 0, v[1] if len(v) > 1 else v[0], 0, 0]
        else:
            raise AssertionError(f"unexpected transform {op}")
        a, b, c, d, e, f = m
        m = [
            a * t[0] + c * t[1],
            b * t[0] + d * t[1],
            a * t[2] + c * t[3],
            b * t[2] + d * t[3],
            a * t[4] + c * t[5] + e,
            b * t[4] + d * t[5] + f,
        ]
    return m


def _apply(m, p):
    return (m[0] * p[0] + m[2] * p[1] + m[4], m[1] * p[0] + m[3] * p[1] + m[5])


class Svg:
    def __init__(self, text):
        self.root = ET.fromstring(text)
        ids = [g.get("id") for g in self.root.iter(SVGNS + "g") if g.get("id")]
        assert len(ids) == len(set(ids)), "duplicate ids"
        self.groups = {g.get("id"): g for g in self.root.iter(SVGNS + "g") if g.get("id")}
        self.glyphs = {}
        for p in self.root.iter(SVGNS + "path"):
            if p.get("id"):
                m = _transform(p.get("transform"))
                self.glyphs[p.get("id")] = [_apply(m, q) for q in _points(p.get("d"))]

    def size_cm(self):
        w, h = self.root.get("width"), self.root.get("height")
        assert w.endswith("pt") and h.endswith("pt")
        return float(w[:-2]) / CM, float(h[:-2]) / CM

    def path(self, gid):
        """The vertices (pt) of the first path of group ``gid``."""
        return _points(self.groups[gid].find(f".//{SVGNS}path").get("d"))

    def text_box(self, gid):
        """The ink box (pt) of a text group: its glyph outlines, placed."""
        g = self.groups[gid]
        pts = []
        for inner in g.findall(SVGNS + "g"):
            m = _transform(inner.get("transform"))
            for use in inner.iter(SVGNS + "use"):
                u = _transform(use.get("transform"))
                for q in self.glyphs.get(use.get(XLINK)[1:], []):
                    pts.append(_apply(m, _apply(u, q)))
        if not pts:  # a blank
            return None
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        return box(min(xs), min(ys), max(xs), max(ys))

    def texts(self):
        return [k for k in self.groups if k.startswith(("label-", "note-"))]

    def geometry(self):
        """Every line, outline and arrowhead drawn (as shapely geometries, pt)."""
        out = []
        for gid, g in self.groups.items():
            if gid.startswith(("label-", "note-", "panel-", "figure_", "axes_", "patch_")):
                continue
            for p in g.iter(SVGNS + "path"):
                pts = _points(p.get("d"))
                if len(pts) < 2:
                    continue
                style = p.get("style") or ""
                width = re.search(r"stroke-width: ([\d.]+)", style)
                half = float(width.group(1)) / 2 if width else 0.5
                geom = LineString(pts).buffer(half)
                filled = (
                    "fill: none" not in style
                    and gid.endswith(("-head",))
                    or gid.startswith(("velocity-point", "acceleration-point"))
                )
                if filled and len(pts) >= 3:
                    geom = geom.union(Polygon(pts).buffer(0))
                out.append((gid, geom))
        return out


def vector_length_cm(svg, gid):
    start = svg.path(f"{gid}-shaft")[0]
    tip = svg.path(f"{gid}-head")[0]
    return math.dist(start, tip) / CM, ((tip[0] - start[0]) / CM, -(tip[1] - start[1]) / CM)


# --------------------------------------------------------------------------- scale and size


def test_svg_parses_and_is_printed_true_to_scale(fourbar):
    text = svg_string(fourbar, "velocity", {"velocity": parse_scale("1 cm = 0.1 m/s")})
    svg = Svg(text)
    w, h = svg.size_cm()
    vb = [float(x) for x in svg.root.get("viewBox").split()]
    # user units are points: the viewBox has the same numbers as width/height in pt
    assert vb[2] / CM == pytest.approx(w, abs=1e-6) and vb[3] / CM == pytest.approx(h, abs=1e-6)
    bar = svg.path("velocity-scale-bar")
    n = round(math.dist(bar[0], bar[-1]) / CM)
    assert n >= 1 and math.dist(bar[0], bar[-1]) / CM == pytest.approx(n, abs=1e-5)
    # the crank's vector: omega x AB = 10.5 x 0.05 = 0.525 m/s -> 5.25 cm at 1 cm = 0.1 m/s
    ob = next(
        i
        for i, v in enumerate(drawn_vectors(fourbar, "velocity"))
        if v.kind == "absolute" and v.label == "ob"
    )
    length, _ = vector_length_cm(svg, f"velocity-vector-{ob}")
    assert length == pytest.approx(5.25, abs=1e-5)


@pytest.mark.parametrize(
    "phase,scale",
    [
        ("velocity", "1 cm = 0.05 m/s"),
        ("acceleration", "1 cm = 0.5 m/s^2"),
        ("velocity", None),
        ("acceleration", None),
    ],
)
def test_every_vector_is_drawn_at_its_magnitude(fourbar, phase, scale):
    given = {phase: parse_scale(scale)} if scale else None
    text, used, _ = render(fourbar, "svg", phase, given)
    per_cm = used[phase].per_cm
    svg = Svg(text)
    vectors = drawn_vectors(fourbar, phase)
    assert len(vectors) >= 5
    for n, v in enumerate(vectors):
        length, (dx, dy) = vector_length_cm(svg, f"{phase}-vector-{n}")
        assert length == pytest.approx(v.magnitude / per_cm, abs=2e-5), v
        ex, ey = v.end[0] - v.start[0], v.end[1] - v.start[1]
        assert dx * ey - dy * ex == pytest.approx(0, abs=1e-4 * length)  # same direction
        assert dx * ex + dy * ey > 0


def test_totals_match_an_independent_reference(fourbar):
    """o->c, o'->c' etc. against the 50-digit loop-closure reference (not the solver)."""
    ref = reference_solution(fourbar.scene, fourbar.P)
    for phase, key, unit in (
        ("velocity", "velocities", "1 cm = 0.05 m/s"),
        ("acceleration", "accelerations", "1 cm = 0.5 m/s^2"),
    ):
        scale = parse_scale(unit)
        svg = Svg(svg_string(fourbar, phase, {phase: scale}))
        checked = 0
        for n, v in enumerate(drawn_vectors(fourbar, phase)):
            if v.kind != "absolute":
                continue
            point = v.name.split("_")[1]
            rx, ry = (float(c) for c in ref[key][point])
            length, _ = vector_length_cm(svg, f"{phase}-vector-{n}")
            assert length * scale.per_cm == pytest.approx(math.hypot(rx, ry), rel=1e-6)
            checked += 1
        assert checked >= 5  # b, c, e, f, g


def test_physical_size_is_the_content_not_a_tight_bbox(fourbar):
    fig, used, _ = make_figure(fourbar, "all")
    for ax in fig.axes:
        # one data unit = one centimetre on the page
        (x0, y0), (x1, y1) = ax.transData.transform([(0, 0), (1, 1)])
        assert (x1 - x0) / fig.dpi * 2.54 == pytest.approx(1.0, rel=1e-9)
        assert (y1 - y0) / fig.dpi * 2.54 == pytest.approx(1.0, rel=1e-9)
    w, h = fig.get_size_inches() * 2.54
    assert w <= 29.7  # the panels flow in rows no wider than A4 landscape


def test_scales_are_textbook_round_and_fit_a4(fourbar):
    for diagram, sheet in (
        ("all", (29.7, math.inf)),
        ("velocity", (21.0, 29.7)),
        ("configuration", (21.0, 29.7)),
    ):
        text, used, _ = render(fourbar, "svg", diagram)
        for s in used.values():
            mant = float(s.value) / 10 ** math.floor(math.log10(float(s.value)))
            assert any(math.isclose(mant, m) for m in (1, 2, 2.5, 5)), s
        w, h = Svg(text).size_cm()
        assert w <= sheet[0] and h <= sheet[1]
    assert {k: str(v) for k, v in choose_scales(fourbar, "velocity").items()} == {
        "velocity": "1 cm = 0.05 m/s"
    }  # 0.63 m/s across: the largest that fits


# --------------------------------------------------------------------------- labels


def _check_labels(text):
    svg = Svg(text)
    boxes = {}
    for gid in svg.texts():
        b = svg.text_box(gid)
        if b is not None:
            boxes[gid] = b
    assert any(k.startswith("label-") for k in boxes)
    names = sorted(boxes)
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            assert not boxes[a].intersects(boxes[b]), f"labels {a} and {b} overlap"
    geometry = svg.geometry()
    assert len(geometry) > 10
    for gid, b in boxes.items():
        for other, geom in geometry:
            assert not b.intersects(geom), f"{gid} sits on {other}"
    return svg


def test_labels_clear_of_each_other_and_of_lines(fourbar):
    svg = _check_labels(svg_string(fourbar, "all"))
    for gid in (
        "label-o",
        "label-b",
        "label-c",
        "label-op",
        "label-bp",
        "label-cp",
        "label-B",
        "label-C",
        "label-crank-angle",
    ):
        assert gid in svg.groups, gid


@pytest.mark.parametrize("path", WORKED + ["slotted"], ids=lambda p: Path(p).stem)
def test_worked_problem_sheets(path):
    scene = parse_scene(SLOTTED) if path == "slotted" else None
    if scene is None:
        from polygon_method import load_scene

        scene = load_scene(path)
    sol = solve(scene)
    text, used, warnings = render(sol, "svg", "all")
    assert warnings == []
    _check_labels(text)
    w, h = Svg(text).size_cm()
    assert w <= 29.7  # rows no wider than A4 landscape
    # one diagram, one scale: the sheet states the scales the step table states
    from polygon_method.polygons.scales import diagram_scales
    from polygon_method.text.steptable import steps_text

    stated = [s.text for s in diagram_scales(sol)]
    assert [used[n].text for n in ("configuration", "velocity", "acceleration")] == stated
    table = steps_text(sol)
    for t in stated:
        assert t in table


# --------------------------------------------------------------------------- image points


def _signed_area(p):
    return sum(p[i][0] * p[(i + 1) % 3][1] - p[(i + 1) % 3][0] * p[i][1] for i in range(3)) / 2


@pytest.mark.parametrize("phase", ["velocity", "acceleration"])
def test_image_triangle_is_similar_to_the_link_triangle(fourbar, phase):
    svg = Svg(svg_string(fourbar, phase))
    b, c, f = svg.path(f"{phase}-image-F")[:3]
    bc = math.dist(b, c)
    # the scene's own numbers: BF = 45, CF = 30, BC = 66 mm, B, C, F read clockwise
    assert math.dist(b, f) / bc == pytest.approx(45 / 66, rel=1e-6)
    assert math.dist(c, f) / bc == pytest.approx(30 / 66, rel=1e-6)
    # clockwise with y up is counter-clockwise in the SVG's y-down coordinates
    assert _signed_area([b, c, f]) > 0
    c2, d, g = svg.path(f"{phase}-image-G")[:3]
    assert math.dist(c2, g) / math.dist(c2, d) == pytest.approx(24 / 56, rel=1e-6)
    assert math.dist(d, g) / math.dist(c2, d) == pytest.approx(44 / 56, rel=1e-6)


def test_acceleration_components_have_their_own_styles():
    sol = solve(parse_scene(SLOTTED))
    text = svg_string(sol, "acceleration")
    svg = Svg(text)
    styles = {}
    for n, v in enumerate(drawn_vectors(sol, "acceleration")):
        style = svg.groups[f"acceleration-vector-{n}-shaft"].find(f"{SVGNS}path").get("style")
        styles.setdefault(v.kind, set()).add(re.search(r"stroke: (#\w+)", style).group(1))
    assert {"centripetal", "tangential", "coriolis", "absolute"} <= set(styles)
    colours = [next(iter(s)) for s in styles.values()]
    assert all(len(s) == 1 for s in styles.values()) and len(set(colours)) == len(colours) - (
        "relative" in styles and "absolute" in styles
    )
    # the Coriolis vector is 2 omega vs, as the records say
    cor = next(v for c in acceleration_constructions(sol) for v in c.given if v.kind == "coriolis")
    vs, w = sol.sliding_velocity("A"), sol.omega("CP")
    assert cor.magnitude == pytest.approx(2 * abs(w * vs), rel=1e-12)


# --------------------------------------------------------------------------- output


def test_deterministic_svg(fourbar):
    a = svg_string(fourbar, "all")
    b = svg_string(solve(parse_scene(FOURBAR)), "all")
    assert a == b
    assert "<dc:date>" not in a
    assert fourbar._repr_svg_() == a


def test_cli_formats_and_clean_failures(tmp_path, capsys):
    scene = tmp_path / "fb.toml"
    scene.write_text(FOURBAR)
    for ext, magic in ((".svg", b"<?xml"), (".png", b"\x89PNG"), (".pdf", b"%PDF")):
        out = tmp_path / f"fb{ext}"
        assert (
            main(
                [
                    "draw",
                    str(scene),
                    "-o",
                    str(out),
                    "--diagram",
                    "velocity",
                    "--scale",
                    "1 cm = 0.1 m/s",
                ]
            )
            == 0
        )
        assert out.read_bytes().startswith(magic)
    assert "velocity 1 cm = 0.1 m/s" in capsys.readouterr().out
    # a scene that cannot be assembled: one line, exit 2, nothing written
    bad = tmp_path / "bad.toml"
    bad.write_text(FOURBAR.replace("CD = 56", "CD = 10"))
    for args in (
        ["draw", str(bad), "-o", str(tmp_path / "bad.svg")],
        ["draw", str(scene), "-o", str(tmp_path / "x.jpg")],
        ["draw", str(scene), "-o", str(tmp_path / "y.svg"), "--scale", "1 cm = fast"],
        [
            "draw",
            str(scene),
            "-o",
            str(tmp_path / "z.svg"),
            "--scale",
            "1 cm = 0.1 m/s",
            "--scale",
            "1 cm = 0.2 m/s",
        ],
    ):
        assert main(args) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "Traceback" not in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == [
        "bad.toml",
        "fb.pdf",
        "fb.png",
        "fb.svg",
        "fb.toml",
    ]


def test_png_carries_its_physical_size(tmp_path):
    sol = solve(parse_scene(FOURBAR))
    data, _, _ = render(sol, "png", "velocity")
    svg = Svg(svg_string(sol, "velocity"))
    # pHYs chunk: pixels per metre
    i = data.index(b"pHYs")
    ppm = int.from_bytes(data[i + 4 : i + 8], "big")
    width_px = int.from_bytes(data[16:20], "big")
    assert width_px / ppm * 100 == pytest.approx(svg.size_cm()[0], rel=2e-3)


def test_importing_and_solving_do_not_load_matplotlib_or_shapely():
    code = (
        "import sys, polygon_method as pm, polygon_method.draw\n"
        f"pm.solve(pm.parse_scene({FOURBAR!r}))\n"
        "bad = [m for m in ('matplotlib', 'shapely') if m in sys.modules]\n"
        "assert not bad, bad\n"
    )
    subprocess.run([sys.executable, "-c", code], check=True, env=dict(os.environ))


def test_drawing_functions_take_an_axes_and_return_their_artists(fourbar):
    from matplotlib.figure import Figure

    from polygon_method.draw import draw_acceleration, draw_configuration, draw_velocity

    for draw, scale in (
        (draw_configuration, "1 cm = 20 mm"),
        (draw_velocity, None),
        (draw_acceleration, "1 cm = 1 m/s^2"),
    ):
        ax = Figure().add_subplot()
        artists = draw(ax, fourbar, scale)
        assert artists and all(a.axes is ax for a in artists)
        assert len({a.get_gid() for a in artists}) == len(artists)
    # one data unit is one centimetre: o->b is omega x AB = 0.525 m/s, 5.25 units at 0.1
    ax = Figure().add_subplot()
    artists = {a.get_gid(): a for a in draw_velocity(ax, fourbar, "1 cm = 0.1 m/s")}
    n = next(i for i, v in enumerate(drawn_vectors(fourbar, "velocity")) if v.label == "ob")
    shaft = artists[f"velocity-vector-{n}-shaft"].get_xydata()[0]
    tip = artists[f"velocity-vector-{n}-head"].get_xy()[0]
    assert math.dist(shaft, tip) == pytest.approx(5.25, rel=1e-12)


@pytest.mark.parametrize(
    "path",
    sorted(Path(__file__).parent.parent.glob("worked_problems/*.toml")),
    ids=lambda p: p.stem,
)
def test_single_diagram_uses_the_scale_the_steps_state(path):
    """A student drawing from `steps` and comparing with `draw --diagram X` sees one scale."""
    from polygon_method.draw import DIAGRAMS, layout
    from polygon_method.polygons.scales import diagram_scales
    from polygon_method import load_scene
    from polygon_method.text.steptable import steps_text

    sol = solve(load_scene(path))
    text = steps_text(sol)
    for name, stated in zip(DIAGRAMS, diagram_scales(sol)):
        ((drawn_name, scale, _),) = layout(sol, name)
        assert drawn_name == name
        assert scale.text == stated.text
        assert stated.text in text


@pytest.mark.parametrize("name", ["crank_slotted_lever", "whitworth"])
def test_the_point_under_the_block_is_marked_on_both_polygons(name):
    """a1 and a1', which the step table names, are drawn and labelled where the lever's
    point under the block moves: v = w perp(KA), a = -w^2 KA + al perp(KA)."""
    from polygon_method import load_scene

    sol = solve(load_scene(Path(__file__).parent.parent / "worked_problems" / f"{name}.toml"))
    st = next(s for s in sol.plan.steps if s.kind == "slotted")
    (kx, ky), (ax, ay) = sol.P[st.known], sol.P[st.point]
    rx, ry = ax - kx, ay - ky
    w, al = sol.W[st.guide], sol.Al[st.guide]
    want = {
        "velocity": (-w * ry, w * rx),
        "acceleration": (-w * w * rx - al * ry, -w * w * ry + al * rx),
    }
    for phase, prime in (("velocity", ""), ("acceleration", "'")):
        cons = (velocity_constructions if phase == "velocity" else acceleration_constructions)(sol)
        ((label, xy),) = cons[st.index].named
        assert label == st.point.lower() + "1" + prime
        assert xy == pytest.approx(want[phase], rel=1e-12, abs=1e-12)
        text, _, _ = render(sol, "svg", phase)
        assert f'id="label-{label.replace(chr(39), "p")}"' in text


def test_a_point_on_a_link_produced_has_its_image_line_produced():
    """T on BC produced: bc (b'c') is drawn produced to t (t'), on the line of b and c."""
    sol = solve(
        parse_scene("""
    [ground]
    A = [0, 0]
    D = [100, 0]
    [links]
    AB = 50
    BC = 66
    CD = 56
    [points]
    T = { on = "BC", along = 100 }
    [input]
    crank = "AB"
    angle = 60
    speed = "10.5 rad/s cw"
    """)
    )
    from polygon_method.draw.diagrams import _polygon
    from polygon_method.polygons.scales import diagram_scales

    _, vs, as_ = diagram_scales(sol)
    for phase, scale, D in (("velocity", vs, sol.V), ("acceleration", as_, sol.A)):
        sk = _polygon(sol, scale, phase)
        ((a, b),) = [
            pts
            for kind, pts, kw in sk.items
            if kind == "line" and kw["gid"] == f"{phase}-produced-T"
        ]
        s = scale.per_cm
        bx, by = D["B"][0] / s, D["B"][1] / s
        tx, ty = D["T"][0] / s, D["T"][1] / s
        assert a == pytest.approx((bx, by), abs=1e-9) and b == pytest.approx((tx, ty), abs=1e-9)
        cx, cy = D["C"][0] / s, D["C"][1] / s
        assert abs((cx - bx) * (ty - by) - (cy - by) * (tx - bx)) < 1e-9 * (1 + tx * tx + ty * ty)


SWIVEL = """
[ground]
O = [0, 0]
C = [150, 0]
[links]
OA = 50
AB = 250
[sliders]
C = { along = "AB" }
[input]
crank = "OA"
angle = 60
speed = "10 rad/s ccw"
"""


def test_a_swivel_block_is_drawn_as_textbooks_draw_it():
    """A block at a fixed swivel: its pivot symbol, the lever's point under it named c1
    (c1'), and the lever's image line a c1 produced to b drawn on both polygons."""
    from polygon_method.text.steptable import steps_text

    sol = solve(parse_scene(SWIVEL))
    text, _, _ = render(sol, "svg", "all")
    assert 'id="ground-C"' in text
    assert 'id="label-c1"' in text and 'id="label-c1p"' in text
    table = steps_text(sol)
    assert "c1" in table and "o1" not in table
    assert "under C, relative to A" in table
    for phase, D in (("velocity", sol.V), ("acceleration", sol.A)):
        cons = (velocity_constructions if phase == "velocity" else acceleration_constructions)(sol)
        st = next(s for s in sol.plan.steps if s.kind == "slotted")
        line = [v for v in cons[st.index].found if v.kind == "relative" and v.name.endswith("BA")]
        assert line and line[0].start == D["A"] and line[0].end == D["B"]
        ((_, c1),) = cons[st.index].named  # a, c1 and b are in line
        (ax, ay), (bx, by) = D["A"], D["B"]
        cross = (bx - ax) * (c1[1] - ay) - (by - ay) * (c1[0] - ax)
        assert abs(cross) <= 1e-9 * ((bx - ax) ** 2 + (by - ay) ** 2)
