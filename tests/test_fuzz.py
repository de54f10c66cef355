"""Fuzzing: whatever the scene, the tool answers with finite numbers or one clear error.

Three generators feed the same checks:

* scene-shaped TOML text with random tables, keys and values (wrong types, NaN, inf,
  unit typos, unknown names...);
* valid scene files mutated character by character (syntax errors, cut files, odd bytes);
* random but well-formed mechanisms (four-bar, slider-crank, crank and slotted lever) with
  random link lengths and angles, many of which cannot be assembled or sit at a toggle.

For each: ``parse_scene`` then ``solve`` either succeed or raise a
:class:`~polygon_method.common.errors.PolygonMethodError` (never anything else); a solution holds
no NaN or inf anywhere (JSON, text report, answer values, a sweep of the plan) and its
positions close every loop (each link keeps its length, each slider stays on its path);
the command line returns 0 or 2, prints one line on stderr for 2, and its ``--json`` is
strict JSON.

The number of examples is small in CI. A longer run::

    FUZZ_EXAMPLES=5000 python -m pytest tests/test_fuzz.py

(with ``FUZZ_EXAMPLES`` set the examples are random; without it they are derandomized so
that CI is reproducible).
"""

from __future__ import annotations

import atexit
import contextlib
import io
import json
import math
import os
import re
import shutil
import tempfile
from pathlib import Path

import numpy as np
from hypothesis import HealthCheck, Phase, given, settings
from hypothesis import strategies as st

from polygon_method.check.engine import ENGINE_KEYS
from polygon_method.check.engine import engine_value
from polygon_method.cli import main
from polygon_method.common.errors import TOL, PolygonMethodError
from polygon_method.solver.compiler import compile_plan
from polygon_method.solver.plan import Context
from polygon_method.scene import FixedPath, parse_scene
from polygon_method.motion.solution import solve

_LONG = "FUZZ_EXAMPLES" in os.environ
EXAMPLES = int(os.environ.get("FUZZ_EXAMPLES", "40"))
FUZZ = settings(
    max_examples=EXAMPLES,
    deadline=None,
    derandomize=not _LONG,
    phases=[Phase.explicit, Phase.reuse, Phase.generate, Phase.shrink],
    database=None if not _LONG else settings.default.database,
    suppress_health_check=[HealthCheck.too_slow],
)

ROOT = Path(__file__).resolve().parent.parent
_WORK = Path(tempfile.mkdtemp(prefix="pm-fuzz-"))
atexit.register(shutil.rmtree, _WORK, ignore_errors=True)

# --------------------------------------------------------------------------- checks


def _finite_tree(obj, where="") -> None:
    if isinstance(obj, bool) or obj is None or isinstance(obj, str):
        return
    if isinstance(obj, (int, float, np.floating, np.integer)):
        assert math.isfinite(float(obj)), f"{where} = {obj}"
        return
    if isinstance(obj, dict):
        for k, v in obj.items():
            _finite_tree(v, f"{where}.{k}")
        return
    if isinstance(obj, (list, tuple)):
        for i, v in enumerate(obj):
            _finite_tree(v, f"{where}[{i}]")
        return
    raise AssertionError(f"{where}: unexpected {type(obj).__name__} in the output")


_NONFINITE = re.compile(r"(?<![A-Za-z])(nan|inf|infinity)(?![A-Za-z])", re.I)


def _check_error(exc: PolygonMethodError) -> None:
    line = exc.one_line()
    assert line and line.isprintable(), repr(line)  # one line, no control characters
    assert "Traceback" not in line


def _check_solution(sol) -> None:
    d = sol.to_dict()
    json.dumps(d, allow_nan=False)
    _finite_tree(d, "json")
    text = sol.report()
    if sol.scene.title:  # the scene's own words may spell "inf" (a mutated title did)
        text = text.replace(sol.scene.title, "")
    assert not _NONFINITE.search(text), text
    for ans in sol.scene.answers:
        if ans.kind in ENGINE_KEYS:  # the engine chapter's keys: check's own (the cycle)
            try:
                value = engine_value(sol, ans.kind)
            except PolygonMethodError:
                continue  # (refused in one line by check, as its own tests hold)
            assert value is None or math.isfinite(value), ans.key
            continue
        value = sol.value(ans.kind, ans.names)
        assert value is not None and math.isfinite(value), ans.key
    # loop closure, independent of how the steps found the points
    P, V = sol.P, sol.V
    scale = max(
        [lk.length for lk in sol.scene.links]
        + [abs(c) for xy in sol.scene.ground.values() for c in xy]
    )
    vmax = max(math.hypot(*v) for v in V.values())
    cond = min([c for c in sol.conditions.values()] + [1.0])
    for lk in sol.scene.links:
        (x1, y1), (x2, y2) = P[lk.p], P[lk.q]
        assert abs(math.hypot(x2 - x1, y2 - y1) - lk.length) <= 1e-7 * scale, lk.key
        # a rigid link: the relative velocity is perpendicular to the link
        (u1, w1), (u2, w2) = V[lk.p], V[lk.q]
        dot = (u2 - u1) * (x2 - x1) + (w2 - w1) * (y2 - y1)
        assert abs(dot) <= (1e-7 / max(cond, 1e-9)) * vmax * lk.length + 1e-300, lk.key
    for sl in sol.scene.sliders:
        if isinstance(sl, FixedPath):
            (x, y), (qx, qy), (ux, uy) = P[sl.point], sl.through, sl.u
            assert abs((x - qx) * uy - (y - qy) * ux) <= 1e-7 * scale, sl.point


def _check_sweep(scene) -> None:
    """The plan over a whole turn: where no step failed, every value is finite."""
    try:
        plan = compile_plan(scene)
    except PolygonMethodError as exc:
        _check_error(exc)
        return
    theta = scene.input.angle + np.linspace(0.0, 2 * np.pi, 25)
    ctx = Context(theta, scene.input.omega, scene.input.alpha, array=True)
    with np.errstate(all="ignore"):
        out = plan.evaluate(ctx)
    ok = np.ones_like(theta, dtype=bool)
    if ctx.bad is not None:
        ok &= ~np.asarray(ctx.bad, dtype=bool)
    for c in ctx.cond.values():
        ok &= np.broadcast_to(np.asarray(c, dtype=float), theta.shape) >= TOL.singular
    for table in out:
        for name, value in table.items():
            for part in value if isinstance(value, (tuple, list)) else (value,):
                if part is None:
                    continue
                for comp in part if isinstance(part, tuple) else (part,):
                    arr = np.broadcast_to(np.asarray(comp, dtype=float), theta.shape)
                    assert np.isfinite(arr[ok]).all(), (name, arr[ok])


def _api(text: str):
    """Parse and solve through the Python API; only PolygonMethodError may escape.

    Returns the scene, or the error that refused it.
    """
    try:
        scene = parse_scene(text, file="fuzz.toml")
    except PolygonMethodError as exc:
        _check_error(exc)
        assert exc.file == "fuzz.toml"
        return exc
    try:
        sol = solve(scene)
    except PolygonMethodError as exc:
        _check_error(exc)
        assert exc.file == "fuzz.toml"
        return scene
    _check_solution(sol)
    return scene


def _cli(data: bytes) -> int:
    path = _WORK / "scene.toml"
    path.write_bytes(data)
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(["solve", "--json", str(path)])
    assert code in (0, 2), err.getvalue()
    if code == 2:
        assert out.getvalue() == ""
        assert err.getvalue().count("\n") == 1, err.getvalue()
        assert err.getvalue()[:-1].isprintable(), repr(err.getvalue())
        assert str(path) in err.getvalue()
    else:
        _finite_tree(json.loads(out.getvalue()), "stdout")
    return code


def _both(text: str):
    scene = _api(text)
    code = _cli(text.encode("utf-8", errors="surrogatepass"))
    return scene, code


# --------------------------------------------------------------------------- TOML writer


def _toml_value(v) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        if math.isnan(v):
            return "nan"
        if math.isinf(v):
            return "inf" if v > 0 else "-inf"
        return repr(v)
    if isinstance(v, str):
        return json.dumps(v)  # a TOML basic string
    if isinstance(v, list):
        return "[" + ", ".join(_toml_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{json.dumps(k)} = {_toml_value(x)}" for k, x in v.items()) + " }"
    raise TypeError(v)


def _toml(doc: dict) -> str:
    lines = [
        f"{json.dumps(k)} = {_toml_value(v)}" for k, v in doc.items() if not isinstance(v, dict)
    ]
    for k, v in doc.items():
        if isinstance(v, dict):
            lines.append(f"[{json.dumps(k) if not re.match(r'^[a-z]+$', k) else k}]")
            lines += [f"{json.dumps(kk)} = {_toml_value(vv)}" for kk, vv in v.items()]
    return "\n".join(lines) + "\n"


# --------------------------------------------------------------------------- strategies

POINTS = ["A", "B", "C", "D", "E", "F", "O", "O2", "O4", "P", "Q"]
point = st.sampled_from(POINTS) | st.sampled_from(
    ["a", "AB", "1", "", "A-", "Z9", "é", "A\nB", "B\x1b[2J", "C\u2028"]
)


def _join(a, b):
    return a + b if len(a) == len(b) == 1 else f"{a}-{b}"


link_key = st.builds(_join, st.sampled_from(POINTS), st.sampled_from(POINTS)) | point
number = st.one_of(
    st.integers(-10, 400),
    st.integers(-(2**70), 2**70),
    st.floats(allow_nan=True, allow_infinity=True),
    st.floats(0.01, 500.0),
)
length = (
    number
    | st.sampled_from(
        [
            "50 mm",
            "5 cm",
            "0.05 m",
            "2 in",
            "50 mn",
            "-3 mm",
            "nan mm",
            "1e999 mm",
            "50",
            "",
            "mm",
            "50 mm cw",
            "1e-30 m",
            "3 rad/s",
        ]
    )
    | st.booleans()
)
text = st.text(st.characters(exclude_categories=("Cs",)), max_size=8)  # TOML-encodable
scalar = number | text | st.booleans()
anything = st.recursive(
    scalar, lambda c: st.lists(c, max_size=3) | st.dictionaries(text, c, max_size=3), max_leaves=6
)
coords = st.lists(length, min_size=2, max_size=2) | anything
angle = number | st.sampled_from(
    ["60 deg", "1 rad", "60 dge", "400 deg", "1e308 deg", "-90", "90 deg cw"]
)
speed = (
    st.builds(
        lambda v, u, s: f"{v} {u} {s}".strip(),
        number,
        st.sampled_from(["rad/s", "rpm", "rps", "rmp", "", "m/s"]),
        st.sampled_from(["cw", "ccw", "", "acw"]),
    )
    | number
)
acceleration = (
    st.builds(
        lambda v, u, s: f"{v} {u} {s}".strip(),
        number,
        st.sampled_from(["rad/s^2", "rad/s", ""]),
        st.sampled_from(["cw", "ccw", ""]),
    )
    | number
)
force = (
    number
    | st.sampled_from(["2 kN", "1e308 MN", "-5 N", "5 kn"])
    | st.lists(number, min_size=1, max_size=3)
)
answer_key = st.builds(
    lambda p, n: f"{p}_{n}",
    st.sampled_from(["v", "a", "omega", "alpha", "vs", "as", "ac", "rub", "vel", "w"]),
    link_key,
) | st.sampled_from(["torque", "tolerance"])
answer_value = number | st.sampled_from(
    ["0.39 m/s", "5 rad/s ccw", "3 %", "1 m/s^2", "2 N m cw", "0 m/s", "1e308 m/s"]
)

scene_doc = st.fixed_dictionaries(
    {},
    optional={
        "title": scalar,
        "units": st.sampled_from(["mm", "cm", "m", "in", "mmm", "ft"]) | scalar,
        "ground": st.dictionaries(point, coords, max_size=4) | anything,
        "links": st.dictionaries(link_key, length, max_size=6),
        "points": st.dictionaries(
            point,
            st.fixed_dictionaries(
                {"on": link_key},
                optional={
                    "along": length,
                    "from": point,
                    "distances": st.dictionaries(point, length, max_size=3),
                    "turn": st.sampled_from(["cw", "ccw", "up"]),
                },
            ),
            max_size=2,
        ),
        "sliders": st.dictionaries(
            point,
            st.fixed_dictionaries(
                {},
                optional={
                    "path": st.sampled_from(["horizontal", "vertical", "30 deg", "diagonal"])
                    | angle,
                    "through": coords | point,
                    "along": link_key,
                },
            ),
            max_size=2,
        ),
        "assembly": st.dictionaries(
            point, st.sampled_from(["above", "below", "left", "right", "up"]) | coords, max_size=2
        ),
        "input": st.fixed_dictionaries(
            {},
            optional={
                "crank": link_key,
                "angle": angle,
                "speed": speed,
                "acceleration": acceleration,
            },
        ),
        "pins": st.dictionaries(
            point,
            st.dictionaries(st.sampled_from(["diameter", "radius", "dia"]), length, max_size=2),
            max_size=2,
        ),
        "loads": st.dictionaries(
            link_key,
            st.fixed_dictionaries(
                {}, optional={"force": force, "direction": angle, "torque": force}
            ),
            max_size=2,
        ),
        "answers": st.dictionaries(answer_key, answer_value, max_size=3),
        "extra": anything,
    },
)

# seeds for the text mutations: the worked problems and three small scenes
_SEEDS = [
    """[ground]\nA = [0, 0]\nD = [100, 0]\n[links]\nAB = 50\nBC = 66\nCD = 56\n[points]
E = { on = "BC", along = 40 }\nF = { on = "BC", distances = { B = 45, C = 30 }, turn = "cw" }
[assembly]\nC = "above"\n[input]\ncrank = "AB"\nangle = 60\nspeed = "10.5 rad/s cw"
acceleration = "5 rad/s^2 ccw"\n[pins]\nB = { diameter = 30 }\n[loads]
C = { force = "2 kN", direction = 30 }\n[answers]\nv_C = "0.39 m/s"\ntorque = "20 N m"
""",
    """[ground]\nO = [0, 0]\n[links]\nOA = 150\nAB = 600\n[sliders]
B = { path = "horizontal", through = [0, 20] }\n[input]\ncrank = "OA"\nangle = 30
speed = "180 rpm ccw"\n[answers]\nvs_B = "1 m/s"\n""",
    """[ground]\nO2 = [0, 300]\nO4 = [0, 0]\n[links]\n"O2-A" = 100\n"O4-P" = 500
"P-Q" = 150\n[sliders]\nA = { along = "O4-P" }\nQ = { path = "horizontal", through = [0, 520] }
[assembly]\nQ = "right"\n[input]\ncrank = "O2-A"\nangle = 20\nspeed = "60 rpm cw"
[loads]\nQ = { force = [-800, 0] }\n""",
] + [p.read_text(encoding="utf-8") for p in sorted((ROOT / "worked_problems").glob("*.toml"))]

_PIECES = [
    "[",
    "]",
    "{",
    "}",
    "=",
    '"',
    "'",
    ",",
    "\n",
    "#",
    " ",
    "-",
    ".",
    "e",
    "0",
    "nan",
    "inf",
    "1e400",
    "[links]",
    "[[x]]",
    "A",
    "\\",
    "\x00",
    "\ufeff",
    "é",
    '"""',
    "[" * 40,
    "AB = 5\n",
    "\r\n",
    "\t",
]


@st.composite
def mutated(draw):
    text = draw(st.sampled_from(_SEEDS))
    for _ in range(draw(st.integers(1, 4))):
        i = draw(st.integers(0, len(text)))
        op = draw(st.sampled_from(["insert", "delete", "number", "cut", "swap"]))
        if op == "insert":
            piece = draw(st.sampled_from(_PIECES) | st.text(max_size=4))  # surrogates too
            text = text[:i] + piece + text[i:]
        elif op == "delete":
            text = text[:i] + text[i + draw(st.integers(1, 8)) :]
        elif op == "number":
            nums = list(re.finditer(r"\d+(\.\d+)?", text))
            if nums:
                m = nums[draw(st.integers(0, len(nums) - 1))]
                new = draw(
                    st.sampled_from(
                        [
                            "0",
                            "-1",
                            "1e-9",
                            "1e9",
                            "0.0001",
                            "99999",
                            "nan",
                            "inf",
                            "1e400",
                            "150",
                            "600",
                        ]
                    )
                )
                text = text[: m.start()] + new + text[m.end() :]
        elif op == "cut":
            text = text[:i]
        else:
            lines = text.split("\n")
            a = draw(st.integers(0, len(lines) - 1))
            b = draw(st.integers(0, len(lines) - 1))
            lines[a], lines[b] = lines[b], lines[a]
            text = "\n".join(lines)
    return text


fin = dict(allow_nan=False, allow_infinity=False)
sense = st.sampled_from(["cw", "ccw"])
# finite magnitudes from the tiny to the absurd, written as a number a TOML string holds
magnitude = st.floats(1e-300, 1e300, **fin) | st.sampled_from([1e-9, 1e6, 1e9, 1e12])


def sometimes_extreme(usual):
    """``usual`` four times in five, else a magnitude from the tiny to the absurd."""
    return st.integers(0, 4).flatmap(lambda k: magnitude if k == 4 else usual)


def _ext(draw, lo, hi):
    return draw(sometimes_extreme(st.floats(lo, hi, **fin)))


@st.composite
def fourbar(draw):
    d = draw(st.floats(1, 500, **fin) | st.integers(1, 200).map(float))
    ab, bc, cd = (
        draw(st.floats(0.5, 500, **fin) | st.integers(1, 200).map(float)) for _ in range(3)
    )
    doc = {
        "ground": {"A": [0, 0], "D": [d, draw(st.sampled_from([0, 0, 30, -40]))]},
        "links": {"AB": ab, "BC": bc, "CD": cd},
        "points": {},
        "input": {
            "crank": "AB",
            "angle": draw(st.floats(-720, 720, **fin) | st.sampled_from([0, 90, 180, 270])),
            "speed": f"{_ext(draw, 0.01, 3000)} rpm {draw(sense)}",
        },
    }
    alpha = _ext(draw, -1e4, 1e4)
    if alpha:
        doc["input"]["acceleration"] = f"{abs(alpha)} rad/s^2 {'ccw' if alpha > 0 else 'cw'}"
    hint = draw(st.sampled_from([None, "above", "below", "left", "right", "near"]))
    if hint == "near":
        doc["assembly"] = {
            "C": [draw(st.floats(-600, 600, **fin)), draw(st.floats(-600, 600, **fin))]
        }
    elif hint:
        doc["assembly"] = {"C": hint}
    if draw(st.booleans()):
        doc["points"]["E"] = {"on": "BC", "along": draw(st.floats(-300, 300, **fin))}
    if draw(st.booleans()):
        doc["points"]["F"] = {
            "on": "CD",
            "distances": {"C": draw(st.floats(1, 300, **fin)), "D": draw(st.floats(1, 300, **fin))},
            "turn": draw(sense),
        }
    if draw(st.booleans()):
        doc["pins"] = {"B": {"diameter": draw(st.floats(1, 60, **fin))}}
        doc["loads"] = {
            "C": {"force": f"{_ext(draw, 0, 1e5)} kN", "direction": draw(st.floats(0, 360, **fin))}
        }
        doc["answers"] = {
            "v_C": "0.4 m/s",
            "omega_BC": "5 rad/s",
            "rub_B": "0.1 m/s",
            "torque": "20 N m",
        }
    if not doc["points"]:
        del doc["points"]
    return doc


@st.composite
def slider_crank(draw):
    r = draw(st.floats(1, 300, **fin) | st.integers(1, 200).map(float))
    rod = draw(st.floats(1, 900, **fin) | st.integers(1, 200).map(float))
    doc = {
        "ground": {"O": [0, 0]},
        "links": {"OA": r, "AB": rod},
        "sliders": {
            "B": {
                "path": draw(
                    st.sampled_from(["horizontal", "vertical"])
                    | st.floats(-180, 180, **fin).map(lambda a: f"{a} deg")
                ),
                "through": [
                    0,
                    draw(st.floats(-400, 400, **fin) | st.integers(-100, 100).map(float)),
                ],
            }
        },
        "input": {
            "crank": "OA",
            "angle": draw(st.floats(-360, 360, **fin) | st.sampled_from([0, 90, 180, 270])),
            "speed": f"{draw(st.floats(0.1, 500, **fin))} rad/s {draw(sense)}",
        },
    }
    if draw(st.booleans()):
        doc["assembly"] = {"B": draw(st.sampled_from(["left", "right", "above", "below"]))}
    if draw(st.booleans()):
        doc["loads"] = {
            "B": {"force": [_ext(draw, -1e4, 1e4), 0.0]},
            "AB": {"torque": f"{_ext(draw, 0, 1e3)} N m {draw(sense)}"},
        }
        doc["answers"] = {"vs_B": "1 m/s", "as_B": "2 m/s^2"}
    return doc


@st.composite
def slotted_lever(draw):
    h = draw(st.floats(1, 500, **fin) | st.integers(1, 300).map(float))
    r = draw(st.floats(1, 400, **fin) | st.integers(1, 300).map(float))
    lever = draw(st.floats(1, 900, **fin))
    rod = draw(st.floats(1, 400, **fin))
    doc = {
        "ground": {"O4": [0, 0], "O2": [0, h]},
        "links": {"O2-A": r, "O4-P": lever, "P-Q": rod},
        "sliders": {
            "A": {"along": "O4-P"},
            "Q": {"path": "horizontal", "through": [0, draw(st.floats(-900, 900, **fin))]},
        },
        "input": {
            "crank": "O2-A",
            "angle": draw(st.floats(-360, 360, **fin) | st.sampled_from([90, 270, -90])),
            "speed": f"{draw(st.floats(1, 300, **fin))} rpm {draw(sense)}",
            "acceleration": f"{_ext(draw, 0, 100)} rad/s^2 {draw(sense)}",
        },
    }
    if draw(st.booleans()):
        doc["assembly"] = {"Q": draw(st.sampled_from(["left", "right"]))}
    if draw(st.booleans()):
        doc["answers"] = {"ac_A": "1 m/s^2", "omega_O4-P": "1 rad/s"}
    return doc


MECHANISM = st.one_of(fourbar(), slider_crank(), slotted_lever())
TABLES = ["answers", "loads", "pins", "input", "assembly", "sliders", "points", "links", "ground"]
wild = st.one_of(
    length,
    angle,
    speed,
    acceleration,
    force,
    answer_value,
    point,
    link_key,
    coords,
    anything,
    st.sampled_from(["above", "left", "horizontal", "cw", "AB", "BC", "O4-P", "O2-A"]),
)
some_key = st.one_of(
    point,
    link_key,
    answer_key,
    st.sampled_from(
        [
            "crank",
            "angle",
            "speed",
            "acceleration",
            "on",
            "along",
            "from",
            "distances",
            "turn",
            "path",
            "through",
            "force",
            "direction",
            "torque",
            "diameter",
            "radius",
            "units",
            "title",
            "tolerance",
        ]
    ),
)


def _plausible(draw, doc) -> None:
    """Add or change one entry with a value of the right kind, using the scene's names."""
    if any(
        not isinstance(doc.get(t, {}), dict)
        for t in ("links", "ground", "points", "sliders", "assembly", "input", "pins", "loads")
    ):
        return  # an earlier fault made a table something else: broken enough already
    pts = sorted(
        {p for key in doc.get("links", {}) for p in re.findall(r"[A-Z][0-9]*", key)}
        | set(doc.get("ground", {}))
    )
    links = list(doc.get("links", {})) or ["AB"]
    pts = pts or ["A", "B"]
    size = st.floats(0.5, 600, allow_nan=False) | st.integers(1, 300)
    what = draw(
        st.sampled_from(
            [
                "link",
                "ground",
                "crank",
                "carried",
                "slider",
                "guide",
                "assembly",
                "length",
                "pin",
                "load",
            ]
        )
    )
    new_point = st.sampled_from(pts + ["G", "H"])
    if what == "link":
        a, b = draw(new_point), draw(new_point)
        doc.setdefault("links", {})[_join(a, b)] = draw(size)
    elif what == "ground":
        doc.setdefault("ground", {})[draw(new_point)] = [draw(size), draw(size)]
    elif what == "crank":
        doc.setdefault("input", {})["crank"] = draw(st.sampled_from(links))
    elif what == "carried":
        doc.setdefault("points", {})[draw(new_point)] = {
            "on": draw(st.sampled_from(links)),
            "along": draw(size),
        }
    elif what == "slider":
        doc.setdefault("sliders", {})[draw(new_point)] = {
            "path": draw(st.sampled_from(["horizontal", "vertical", "60 deg"]))
        }
    elif what == "guide":
        doc.setdefault("sliders", {})[draw(new_point)] = {"along": draw(st.sampled_from(links))}
    elif what == "assembly":
        doc.setdefault("assembly", {})[draw(new_point)] = draw(
            st.sampled_from(["above", "below", "left", "right"])
            | st.lists(size, min_size=2, max_size=2)
        )
    elif what == "length":
        doc.setdefault("links", {})[draw(st.sampled_from(links))] = draw(size)
    elif what == "pin":
        doc.setdefault("pins", {})[draw(new_point)] = {"radius": draw(size)}
    else:
        doc.setdefault("loads", {})[draw(new_point)] = {"force": [draw(size), draw(size)]}


@st.composite
def broken_mechanism(draw):
    """A valid mechanism with one to three faults put into its tables."""
    doc = draw(MECHANISM)
    for _ in range(draw(st.integers(1, 3))):
        table = draw(st.sampled_from(TABLES + [None]))
        target = doc if table is None else doc.setdefault(table, {})
        if not isinstance(target, dict):
            continue
        op = draw(st.sampled_from(["plausible", "set", "delete", "rename", "nest"]))
        keys = list(target)
        if op == "plausible":  # a change a student could make: the scene stays well formed
            _plausible(draw, doc)
        elif op == "set" or not keys:
            key = draw(st.sampled_from(keys) | some_key) if keys else draw(some_key)
            target[key] = draw(wild)
        elif op == "delete":
            del target[draw(st.sampled_from(keys))]
        elif op == "rename":
            old = draw(st.sampled_from(keys))
            target[draw(some_key)] = target.pop(old)
        else:  # change one entry of an inline table (a carried point, a slider, a load)
            key = draw(st.sampled_from(keys))
            if isinstance(target[key], dict):
                target[key][draw(some_key)] = draw(wild)
            else:
                target[key] = {draw(some_key): draw(wild)}
    return doc


# --------------------------------------------------------------------------- tests


@FUZZ
@given(scene_doc)
def test_generated_toml_never_escapes_the_error_family(doc):
    _both(_toml(doc))


@FUZZ
@given(broken_mechanism())
def test_mechanisms_with_faults_never_escape_the_error_family(doc):
    _both(_toml(doc))


@FUZZ
@given(mutated())
def test_mutated_scene_text(text):
    _both(text)


@FUZZ
@given(
    st.binary(max_size=200)
    | st.text(max_size=200).map(lambda t: t.encode("utf-8", errors="surrogatepass"))
)
def test_arbitrary_bytes_through_the_cli(data):
    assert _cli(data) == 2 or data.strip()


@FUZZ
@given(MECHANISM)
def test_random_mechanisms_give_finite_answers_or_one_error(doc):
    scene, code = _both(_toml(doc))
    if isinstance(scene, PolygonMethodError):  # an open triangle or an absurd magnitude
        assert "cannot close" in scene.message or "absurd" in scene.message, scene.one_line()
        return
    _check_sweep(scene)


@settings(FUZZ, max_examples=max(EXAMPLES // 2, 1))
@given(MECHANISM, st.booleans())
def test_every_command_on_random_mechanisms(doc, draw):
    """steps, check, linkage, sweep and draw: exit 0, 1 or 2, never an internal error."""
    path = _WORK / "any.toml"
    path.write_text(_toml(doc), encoding="utf-8")
    commands = [["steps"], ["check"], ["linkage"], ["sweep", "--steps", "24", "--summary"]]
    if draw:  # the slowest command: half of the examples
        commands.append(["draw", "-o", str(_WORK / "any.svg"), "--diagram", "velocity"])
    for cmd in commands:
        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main([cmd[0], str(path)] + cmd[1:])
        assert code in (0, 1, 2), (cmd, err.getvalue())
        if code == 2:
            assert out.getvalue() == "" and err.getvalue().count("\n") == 1, cmd
        assert not _NONFINITE.search(out.getvalue()), (cmd, out.getvalue())


def test_the_generators_reach_solutions():
    """The mechanism generators are not all impossible: some solve, some fail."""
    results = []

    @settings(
        max_examples=100, deadline=None, derandomize=True, database=None, phases=[Phase.generate]
    )
    @given(MECHANISM)
    def run(doc):
        results.append(_cli(_toml(doc).encode()))

    run()
    assert results.count(0) >= 10 and results.count(2) >= 10, results
