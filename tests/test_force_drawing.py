"""The forces sheet (free-body diagrams and force polygons) measured in the written SVG: each
polygon side as long as its force at the sheet's force scale, the force taken from where it
comes from (the scene's loads and masses, the kinematics' a_G, the solved pin forces and
their components along and square to the link measured from the drawn positions); each
polygon closed; the unknowns' direction lines through the point where it closes; each free
body's arrows along their forces, through their points, the inertia force at h from G;
the sheets on their paper; `steps` giving the same sides in cm."""

from __future__ import annotations

import math
import re
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from polygon_method import load_scene, solve
from polygon_method.draw import render_pages
from polygon_method.draw.forces import NEGLIGIBLE
from polygon_method.forces import side_label
from polygon_method.forces.records import block
from polygon_method.scene import FixedPath
from polygon_method.polygons.scales import (
    choose_scale,
    extent,
    finer,
    force_scale,
    parse_scale,
    polygon_corners,
)
from polygon_method.text.steptable import steps_text
from test_draw import CM, Svg, vector_length_cm
from test_forces import CASES, with_forces
from test_paper import _centre, _check_page, _said

ROOT = Path(__file__).resolve().parents[1]
WORKED = [
    ROOT / "worked_problems" / "engine_forces.toml",
    ROOT / "worked_problems" / "fourbar_forces.toml",
]


def _scenes():
    """The two worked force problems, and four covered problems of the corpus given masses,
    gravity in a slanting direction, a load and a couple."""
    out = [pytest.param(load_scene(p), id=p.stem) for p in WORKED]
    for c in CASES[:: max(1, len(CASES) // 4)][:4]:
        out.append(
            pytest.param(
                with_forces(load_scene(c.values[0]), 3), id=f"{Path(c.values[0]).stem}+masses"
            )
        )
    return out


SCENES = _scenes()
_SHEETS = {}


def _sheet(scene, paper="A4"):
    key = (scene.file, scene.title, id(scene), paper)
    if key not in _SHEETS:
        sol = solve(scene)
        datas, used, warnings, pages = render_pages(sol, "svg", "forces", paper=paper)
        _SHEETS[key] = sol, [Svg(d) for d in datas], used, pages
    return _SHEETS[key]


def _find(svgs, gid):
    return next((s for s in svgs if gid in s.groups), None)


def _magnitude(sol, side):
    """The size of a side's force from its source, not from the polygon's record."""
    sc, f = sol.scene, sol.forces
    if side.what in ("load", "gas"):
        ld = next(ld for ld in sc.loads if ld.target == side.point)
        return math.hypot(*ld.force)
    if side.what == "weight":
        m = next(m for m in sc.masses if (f"block {m.body}" if m.block else m.body) == side.on)
        return m.mass * sc.gravity.g
    if side.what == "inertia":
        m = next(m for m in sc.masses if (f"block {m.body}" if m.block else m.body) == side.on)
        if m.block:
            a = sol.A[m.body]
        else:
            lk = sc.link(m.body)
            (px, py), (qx, qy) = sol.A[lk.p], sol.A[lk.q]
            dx, dy = qx - px, qy - py
            a = (px + m.lam * dx - m.mu * dy, py + m.lam * dy + m.mu * dx)
        return m.mass * math.hypot(*a)
    if side.what == "guide":  # (a peg's two slots: two guides at its point, by their links)
        at = [g for g in f.guides if g.point == side.point]
        mine = [g for g in at if {g.by, block(g.point)} == {side.on, side.by}]
        return abs((mine or at)[0].normal)
    if side.what == "driver" and f.driver == "block":  # the driving force along its guide
        return abs(f.input_torque)
    if side.what == "contact":  # a rolling contact's force (the teeth's load), either body
        c = next(c for c in f.contacts if {c.wheel, c.by} == {side.on, side.by})
        # its parts: normal to the contact (n), along it (t)
        return {"": c.load, "n": abs(c.normal), "t": abs(c.tangential)}[side.part]
    F = f.pin(side.point, side.on, side.by)  # the solved pin force, by the sign rule
    if not side.part:
        return math.hypot(*F)
    # its parts along and square to the link that carries the pin on body `on` (a block's
    # guide, for a block)
    ex, ey = _line(sol, side)
    L = math.hypot(ex, ey)
    along = (F[0] * ex + F[1] * ey) / L
    return abs(along) if side.part == "n" else abs(F[0] * ey - F[1] * ex) / L


def _line(sol, side):
    """The direction of the link that carries the pin on body ``side.on`` (from the pin to
    the link's other end), or of the block's guide for a block."""
    sc = sol.scene
    if side.on.startswith("block "):
        s = sc.slider(side.on.split()[1])
        if isinstance(s, FixedPath):
            return s.u
        (ax, ay), (bx, by) = sol.P[s.first], sol.P[s.second]
        return (bx - ax, by - ay)
    lk = sc.link(side.on)
    other = lk.q if lk.p == side.point else lk.p
    (ax, ay), (bx, by) = sol.P[side.point], sol.P[other]
    return (bx - ax, by - ay)


@pytest.mark.parametrize("scene", SCENES)
def test_each_polygon_side_measures_its_force_and_each_polygon_closes(scene):
    sol, svgs, used, pages = _sheet(scene)
    f = sol.forces
    fs = used["force polygons"]
    assert fs.text == force_scale(f).text
    sheet = max(max(p.size) for p in pages)
    tol = 1e-5 * sheet
    big = max(math.hypot(*s.vector) for st in f.steps for s in st.polygon)
    drawn_polygons = 0
    for st in f.steps:
        tag = f"force-polygon-{st.index + 1}"
        svg = _find(svgs, f"{tag}-pole")
        nonzero = [math.hypot(*s.vector) > NEGLIGIBLE * big for s in st.polygon]
        if svg is None:
            assert sum(nonzero) < 3  # a polygon of two opposite forces is not drawn
            continue
        drawn_polygons += 1
        assert _said(svg, f"note-{tag}-scale") == fs.text.replace(" ", "")
        total = [0.0, 0.0]
        for k, side in enumerate(st.polygon):
            if not nonzero[k]:
                assert f"{tag}-side-{k}-shaft" not in svg.groups
                continue
            length, (dx, dy) = vector_length_cm(svg, f"{tag}-side-{k}")
            assert length == pytest.approx(_magnitude(sol, side) / fs.per_cm, abs=tol), side_label(
                side, f.numbers
            )
            # the drawn side points the force's way
            assert dx * fs.per_cm == pytest.approx(side.vector[0], abs=tol * fs.per_cm)
            assert dy * fs.per_cm == pytest.approx(side.vector[1], abs=tol * fs.per_cm)
            total[0] += dx
            total[1] += dy
        assert math.hypot(*total) < tol * len(st.polygon)  # closed
        # the whole pin forces read across it
        for n in range(len(st.chords)):
            gid = f"{tag}-chord-{n}"
            if f"{gid}-shaft" in svg.groups:
                length, _ = vector_length_cm(svg, gid)
                assert any(
                    length == pytest.approx(_magnitude(sol, c) / fs.per_cm, abs=tol)
                    for c, _, _ in st.chords
                )
        # the unknowns' direction lines run through both ends of their sides: the first's
        # and the last's through the pole, where the polygon closes (a driving wheel's two
        # contact parts, the last two sides, meet at the corner between them)
        pole = _centre(svg, f"{tag}-pole")
        corners = [pole]
        for k, side in enumerate(st.polygon):
            dx, dy = (side.vector[0] / fs.per_cm * CM, -side.vector[1] / fs.per_cm * CM)
            corners.append((corners[-1][0] + dx, corners[-1][1] + dy))
        for k, _ in st.unknown:
            (x1, y1), (x2, y2) = svg.path(f"{tag}-line-{k}")[:2]
            for px, py in corners[k : k + 2]:
                d = abs((x2 - x1) * (py - y1) - (y2 - y1) * (px - x1)) / math.hypot(
                    x2 - x1, y2 - y1
                )
                assert d / CM < tol * 10
    assert drawn_polygons >= 1


def test_the_force_scale_is_the_round_scale_the_rule_chooses():
    for p in SCENES:
        sol = solve(p.values[0])
        f = sol.forces
        size = max(extent(polygon_corners(pg)) for st in f.steps for pg in st.polygons)
        s = force_scale(f)
        assert size / s.per_cm <= 12.0 + 1e-9
        assert size / finer(s).per_cm > 12.0
        assert s.unit == ("kN" if s.per_cm >= 1e3 else "N")
    assert choose_scale(4800.0, 12.0, unit="N").text == "1 cm = 500 N"


@pytest.mark.parametrize("scene", SCENES)
def test_each_free_body_draws_its_forces_along_their_lines(scene):
    sol, svgs, used, pages = _sheet(scene)
    sc, f = sol.scene, sol.forces
    space = used["free bodies"]
    tol = 1e-5 * max(max(p.size) for p in pages)
    for fb in f.free:
        tag = f"free-body-{fb.number}"
        svg = _find(svgs, f"{tag}-body")
        assert svg is not None, tag
        assert _said(svg, f"note-{tag}-scale") == space.text.replace(" ", "")
        if not fb.body.startswith("block "):  # the link to the configuration's scale
            cyl = sc.cylinder(fb.body)  # a cylinder: its length at this instant
            p, q = (cyl.barrel, cyl.rod) if cyl else (sc.link(fb.body).p, sc.link(fb.body).q)
            length = math.dist(sol.P[p], sol.P[q]) if cyl else sc.link(fb.body).length
            got = math.dist(_centre(svg, f"{tag}-joint-{p}"), _centre(svg, f"{tag}-joint-{q}")) / CM
            assert got * space.per_cm == pytest.approx(length, rel=1e-5)
        for k, side in enumerate(fb.sides):
            gid = f"{tag}-force-{k}"
            if f"{gid}-shaft" not in svg.groups:
                assert math.hypot(*side.vector) <= NEGLIGIBLE * 1e6
                continue
            _, (dx, dy) = vector_length_cm(svg, gid)
            n = math.hypot(dx, dy)
            v = side.vector
            assert (dx * v[1] - dy * v[0]) / (n * math.hypot(*v)) == pytest.approx(0, abs=1e-5)
            assert dx * v[0] + dy * v[1] > 0
            # one end of the arrow is the point of application
            tail = svg.path(f"{gid}-shaft")[0]
            tip = svg.path(f"{gid}-head")[0]
            at = (side.at[0] / space.per_cm, side.at[1] / space.per_cm)
            ends = [
                (
                    (x - svg_origin(svg, tag, space, sol)[0]) / CM,
                    -(y - svg_origin(svg, tag, space, sol)[1]) / CM,
                )
                for x, y in (tail, tip)
            ]
            assert min(math.dist(e, at) for e in ends) < tol * 10
            if side.what == "inertia":  # its line at h = I alpha / (m a_G) from G
                m = next(
                    m for m in sc.masses if (f"block {m.body}" if m.block else m.body) == side.on
                )
                if m.block:
                    continue
                lk = sc.link(m.body)
                h = m.inertia * abs(sol.Al[lk.key]) / _magnitude(sol, side)
                G = (
                    f.inertia_of(side.on).G[0] / space.per_cm,
                    f.inertia_of(side.on).G[1] / space.per_cm,
                )
                d = abs(dx * (G[1] - ends[0][1]) - dy * (G[0] - ends[0][0])) / n
                assert d * space.per_cm == pytest.approx(h, abs=tol * space.per_cm * 10)


def svg_origin(svg, tag, space, sol):
    """Where the point (0, 0) of the scene is on the page (pt), from a drawn joint."""
    fb = next(fb for fb in sol.forces.free if f"free-body-{fb.number}" == tag)
    cyl = sol.scene.cylinder(fb.body)
    name = (
        fb.body[6:]
        if fb.body.startswith("block ")
        else cyl.barrel
        if cyl is not None
        else sol.scene.link(fb.body).p
    )
    x, y = _centre(svg, f"{tag}-joint-{name}")
    px, py = sol.P[name]
    return (x - px / space.per_cm * CM, y + py / space.per_cm * CM)


@pytest.mark.parametrize("path", WORKED, ids=[p.stem for p in WORKED])
@pytest.mark.parametrize("paper", ["A4", "letter"])
def test_forces_sheets_are_on_their_paper(path, paper):
    sol, svgs, used, pages = _sheet(load_scene(path), paper)
    assert len(svgs) == len(pages) >= 1
    for svg, page in zip(svgs, pages):
        _check_page(svg, page, paper)


def test_steps_gives_the_force_scale_and_each_side_in_cm():
    """The worked four-bar's whole pin forces, from its answers (the matrix method),
    at the stated scale, as steps writes them."""
    path = WORKED[1]
    sol = solve(load_scene(path))
    text = steps_text(sol)
    assert "Force scale: 1 cm = 100 N" in text
    flat = " ".join(text.split())
    across = re.findall(r"read across it \(whole pin forces\): ([^\n]*?)(?: - |$)", flat)
    assert across
    said = dict(re.findall(r"(F_\d\d) (\d+\.\d\d) cm", " ".join(across)))
    for name, answer in (("F_32", 558.7), ("F_34", 471.6), ("F_41", 451.9)):
        assert float(said[name]) == pytest.approx(answer / 100, abs=0.006)
    sides = re.search(
        r"force polygon at 1 cm = 100 N, from its pole, head to tail: (.*?); "
        r"it closes",
        flat,
    ).group(1)
    assert "F_32^n" in sides and "P at E 5.00 cm" in sides  # the 500 N load: 5 cm


def _run(*args):
    return subprocess.run(
        [sys.executable, "-m", "polygon_method", *args],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=300,
    )


def test_draw_forces_on_the_command_line(tmp_path):
    out = tmp_path / "engine.svg"
    r = _run("draw", str(WORKED[0]), "--forces", "-o", str(out))
    assert r.returncode == 0, r.stderr
    assert "force polygons 1 cm = 10 kN" in r.stdout and "A4" in r.stdout
    assert out.read_text().startswith("<?xml")
    # the same sheet by its --diagram name, at a force scale given
    r = _run(
        "draw",
        str(WORKED[0]),
        "--diagram",
        "forces",
        "--scale",
        "1 cm = 5 kN",
        "-o",
        str(tmp_path / "b.svg"),
    )
    assert r.returncode == 0 and "force polygons 1 cm = 5 kN" in r.stdout, r.stderr
    # a scene without masses: one line, exit 2, nothing written
    bad = tmp_path / "none.svg"
    r = _run("draw", "worked_problems/fourbar_image_points.toml", "--forces", "-o", str(bad))
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1
    assert "[masses]" in r.stderr and not bad.exists()
    r = _run("draw", str(WORKED[0]), "--forces", "--diagram", "velocity", "-o", str(bad))
    assert r.returncode == 2 and "--forces" in r.stderr and not bad.exists()


def test_the_page_draws_each_inertia_force_on_its_offset_line_over_the_cycle():
    """The page's inertia forces, frame by frame, against m a_G from the sweep's link ends
    (G placed on the link by the test), at one round scale that holds the largest force
    drawn (the layer of pin forces too); each
    drawn through H, the point of its line nearest G, where the force's moment about G is
    the inertia couple -I alpha (alpha from the sweep)."""
    from polygon_method.page.data import INERTIA_CM, page_data
    from polygon_method.page.frames import frames
    from polygon_method.page.html import page_html

    offsets = 0
    for path in WORKED:
        sc = load_scene(path)
        fr = frames(sc, 24)
        data = page_data(fr)
        d = data["inertia"]
        res = fr.res
        n = len(res.theta)
        largest = 0.0
        for b in d["bodies"]:
            m = next(
                m for m in sc.masses if (f"block {m.body}" if m.block else m.body) == b["body"]
            )
            for k in range(n):
                if m.block:
                    a = (res.A[m.body][0][k], res.A[m.body][1][k])
                    G = (res.P[m.body][0][k], res.P[m.body][1][k])
                else:
                    lk = sc.link(m.body)

                    def at(T):
                        (px, py), (qx, qy) = T[lk.p], T[lk.q]
                        px, py, qx, qy = (
                            float(x[k]) if hasattr(x, "__len__") else float(x)
                            for x in (px, py, qx, qy)
                        )
                        dx, dy = qx - px, qy - py
                        return (px + m.lam * dx - m.mu * dy, py + m.lam * dy + m.mu * dx)

                    a, G = at(res.A), at(res.P)
                F = (b["F"][2 * k], b["F"][2 * k + 1])
                assert F[0] == pytest.approx(-m.mass * a[0], rel=1e-5, abs=1e-6 * m.mass)
                assert F[1] == pytest.approx(-m.mass * a[1], rel=1e-5, abs=1e-6 * m.mass)
                assert b["G"][2 * k] == pytest.approx(G[0], rel=1e-5, abs=1e-9)
                largest = max(largest, math.hypot(*F))
                h = (b["H"][2 * k] - G[0], b["H"][2 * k + 1] - G[1])
                couple = (
                    0.0 if m.block else -m.inertia * float(np.broadcast_to(res.Al[m.body], (n,))[k])
                )
                lk_len = max(lk.length for lk in sc.links)
                if (
                    abs(couple) > 1e-9 * math.hypot(*F) * lk_len
                    and abs(couple) < 0.999 * math.hypot(*F) * lk_len
                ):  # the line within reach
                    offsets += 1
                    assert h[0] * F[1] - h[1] * F[0] == pytest.approx(couple, rel=1e-4)
                    assert h[0] * F[0] + h[1] * F[1] == pytest.approx(
                        0.0, abs=1e-4 * math.hypot(*h) * math.hypot(*F)
                    )  # nearest G
                elif abs(couple) < 1e-12:  # through G (to the page's rounding)
                    assert math.hypot(*h) < 1e-5 * lk_len
        # one scale for every force on the page: the inertia forces and the layer of the
        # joints' forces, loads and weights (each of those from the solve's own records)
        assert data["forces"]["perCm"] == d["perCm"]
        for a in data["forces"]["arrows"]:
            largest = max(largest, max(map(math.hypot, a["F"][0::2], a["F"][1::2])))
        assert largest / d["perCm"] <= INERTIA_CM + 1e-9
        stated = parse_scale(d["text"])
        assert stated.per_cm == pytest.approx(d["perCm"])
        assert largest / finer(stated).per_cm > INERTIA_CM  # the finest that holds it
        assert (
            f'inertia forces (each on its line h from G): <b id="scale-inertia">{d["text"]}</b>'
        ) in page_html(fr)
    assert offsets > 0  # some body's force is off G in some frame
    # no masses: no inertia forces on the page
    plain = frames(load_scene(ROOT / "worked_problems" / "fourbar_image_points.toml"), 12)
    assert page_data(plain)["inertia"] is None


def test_a_plan_the_forces_do_not_cover_is_refused_by_the_sheet_in_one_line(monkeypatch):
    from polygon_method.common.errors import PolygonMethodError
    from polygon_method.scene import scene_from_table, scene_table
    from test_forces import _not_covered

    _not_covered(monkeypatch)  # (every kind is covered now: one made uncovered again)

    raw = scene_table(load_scene(ROOT / "tests" / "textbook" / "class3_triangle_plate.toml"))
    raw["gravity"] = {}
    sol = solve(scene_from_table(raw))
    with pytest.raises(PolygonMethodError, match=r"not solved for forces yet \(step 2"):
        render_pages(sol, "svg", "forces")


def test_the_couples_are_drawn_with_their_values():
    """The worked four-bar: the driver's torque on the crank, its answer (the matrix
    method), and the rocker's resisting couple, the scene's 20 N m cw, each a curved arrow
    on its body with its value."""
    sol, svgs, used, pages = _sheet(load_scene(WORKED[1]))
    f = sol.forces
    said = {}
    for fb in f.free:
        for k, c in enumerate(fb.couples):
            tag = f"free-body-{fb.number}"
            svg = _find(svgs, f"{tag}-couple-{k}-arc")
            assert svg is not None and f"{tag}-couple-{k}-head" in svg.groups
            said[c.what] = _said(svg, f"label-{tag}-couple-{k}")
    assert said["torque"] == "T2=49.84Nmccw"
    assert said["load"] == "C4=20Nmcw"
