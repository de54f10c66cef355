"""The short roads of reading a scene and compiling it, held to the long ones they stand for.

* A bare number in its default unit is read at once (``parse_quantity``, the reader's
  lengths); the same number written as text takes the whole way (the regular expression,
  the unit's table): both give the same value to the last bit, and refuse the same values.
* The compiler leaves out a recogniser whose table the scene lacks (``steps.NEEDS``): every
  scene of the corpus and every worked problem compiles to the same plan with every
  recogniser tried, and a recogniser left out never finds a point where it is tried.
* A plan is cached by the scene's content (``ContentKey``, hashed once): a scene whose text
  has changed is never served the plan of the old one.
"""

import math
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from polygon_method import parse_scene, solve
from polygon_method.common.errors import PolygonMethodError, SceneError
from polygon_method.common.units import UNITS, parse_quantity
from polygon_method.scene import load_scene
from polygon_method.scene.content import ContentKey
from polygon_method.solver import compiler as plan_module
from polygon_method.steps import NEEDS, TIERS
from scenes import seed
from textbook_corpus import FILES

WORKED = sorted((Path(__file__).resolve().parent.parent / "worked_problems").glob("*.toml"))

KINDS = [("length", "mm"), ("length", "in"), ("angle", "deg"), ("force", "N"), ("mass", "kg")]


def _read(raw, kind, unit):
    try:
        return parse_quantity(raw, kind, default_unit=unit).value
    except SceneError:
        return "refused"


@settings(max_examples=400, deadline=None)
@given(
    st.one_of(
        st.floats(allow_nan=False, allow_infinity=False),
        st.integers(min_value=-(10**30), max_value=10**30),
        st.floats(min_value=-1e-6, max_value=1e-6),
    ),
    st.sampled_from(KINDS),
)
def test_a_bare_number_reads_as_the_same_number_written_as_text(x, kind_unit):
    """The text's number is read by the regular expression and ``float``: the same
    correctly rounded value as the number itself (an integer's text too)."""
    kind, unit = kind_unit
    text = repr(float(x)) if isinstance(x, float) else str(x)
    assert _read(x, kind, unit) == _read(text, kind, unit)


NUMBERS = st.one_of(
    st.floats(allow_nan=False).map(repr),
    st.integers(-(10**20), 10**20).map(str),
    st.sampled_from(
        [
            "1.",
            ".5",
            "+.5e-3",
            "1e999",
            "-0",
            "0",
            "1_0",
            "1e",
            "e5",
            "--1",
            "1.2.3",
            "inf",
            "nan",
            "\u0661",
            "0x10",
            "5-",
            ".",
            "+",
            "1E+5",
            "00012.50",
        ]
    ),
)
UNITS_WRITTEN = st.sampled_from(
    [
        "mm",
        "m",
        "in",
        "ft",
        "deg",
        "rad",
        "rad/s",
        "rpm",
        "RPM",
        "N",
        "kN",
        "N m",
        "m/s",
        "kg",
        "rad/s^2",
        "foo",
        "",
        "cw",
        "6 in",
    ]
)
SENSES = st.sampled_from(["", "cw", "ccw", "CW", "anticlockwise", "Clockwise", "up", "cw ccw"])
SPACES = st.sampled_from([" ", "  ", "\t", "\u2003", ""])
ALL_KINDS = [
    "length",
    "angle",
    "angular_velocity",
    "angular_acceleration",
    "force",
    "torque",
    "velocity",
    "acceleration",
    "mass",
]


def _outcome(fn, *args):
    try:
        q = fn(*args)
    except SceneError as exc:
        return ("refused", exc.message)
    return (q.value, q.sense)


@settings(max_examples=600, deadline=None)
@given(
    NUMBERS,
    UNITS_WRITTEN,
    SENSES,
    SPACES,
    SPACES,
    st.sampled_from(ALL_KINDS),
    st.sampled_from([None, "mm", "deg", "N"]),
    st.booleans(),
    st.booleans(),
    st.booleans(),
)
def test_a_quantity_read_at_once_is_the_quantity_read_the_whole_way(
    number, unit, sense, gap, end, kind, default, need, allow, absurd
):
    """The short road (split at spaces, the unit looked up in its table, ``float``) gives
    what the regular expression's road gives, value and sense to the last bit, and leaves
    to it every text it would refuse (the refusal's words are the whole way's)."""
    from polygon_method.common.units import UNITS as TABLES, _whole_way

    if default is not None and default not in TABLES[kind]:
        default = None
    raw = f"{gap}{number} {unit}{gap}{sense}{end}"
    args = (raw, kind)
    flags = dict(default_unit=default, need_sense=need, allow_sense=allow, refuse_absurd=absurd)
    whole = _outcome(lambda: _whole_way(raw, kind, "", default, need, allow, absurd))
    assert _outcome(lambda: parse_quantity(*args, **flags)) == whole
    for bare in (number, float(len(number)), -len(number)):  # and a bare number
        whole = _outcome(lambda: _whole_way(bare, kind, "", default, need, allow, absurd))
        assert _outcome(lambda: parse_quantity(bare, kind, **flags)) == whole


@pytest.mark.parametrize(
    "raw", [math.nan, math.inf, -math.inf, 10**400, True, 1e300, -1e305, 0, -0.0]
)
def test_the_numbers_the_short_road_leaves_are_refused_or_read_as_before(raw):
    """NaN, infinities, an integer past any float, a bool: the whole way words them."""
    for kind, unit in KINDS:
        value = _read(raw, kind, unit)
        if isinstance(raw, bool) or not (isinstance(raw, int) or math.isfinite(raw)):
            assert value == "refused"
        elif isinstance(raw, int) and abs(raw) > 1e300:
            assert value == "refused"
        elif value != "refused":
            assert value == float(raw) * UNITS[kind][unit]


@pytest.mark.parametrize("bad", ["nan", "inf", "-inf", "0", "1e-9", "2e10", "10" * 30, "true"])
def test_a_length_the_short_road_leaves_is_refused_with_its_key_and_line(bad):
    text = seed(links=f"EF = {bad}\nCE = 30\nEA = 40\n".replace("EA", "EB"))
    with pytest.raises(PolygonMethodError) as err:
        parse_scene(text, file="s.toml")
    assert err.value.key == "[links] EF" and err.value.line == 9


def _plan_kinds(scene):
    plan_module._BY_ID.clear()
    plan_module._BY_CONTENT.clear()
    plan = plan_module.compile_plan(scene)
    return [(st.kind, st.finds, st.params, getattr(st, "sigma", None)) for st in plan.steps]


@pytest.mark.parametrize("path", FILES + WORKED, ids=lambda p: p.stem)
def test_leaving_out_recognisers_without_their_table_changes_no_plan(path, monkeypatch):
    scene = load_scene(path)
    short = _plan_kinds(scene)
    tried = []

    def watched(recognise):
        def watch(g, name):
            step = recognise(g, name)
            if step is not None and not getattr(scene, NEEDS[recognise]):
                tried.append((recognise.__module__, name))
            return step

        return watch

    every = (tuple(watched(r) if r in NEEDS else r for r in TIERS[0]),) + TIERS[1:]
    monkeypatch.setattr(plan_module, "TIERS", every)
    monkeypatch.setattr(plan_module, "NEEDS", {})
    assert _plan_kinds(load_scene(path)) == short
    assert tried == []  # a recogniser left out would have found nothing


def test_a_changed_scene_is_never_served_the_old_plan():
    plan_module._BY_ID.clear()
    plan_module._BY_CONTENT.clear()
    before = solve(parse_scene(seed()))
    again = parse_scene(seed())  # the same content: the same plan, from the cache
    assert again._key == before.scene._key and hash(again._key) == hash(before.scene._key)
    assert plan_module.compile_plan(again).steps is before.plan.steps
    changed = parse_scene(seed().replace("BC = 66", "BC = 70"))
    assert changed._key != before.scene._key
    got = solve(changed)
    # C of the changed four-bar, from the closed form (A at 0, D at 100, AB 50 at 60 deg)
    bx, by = 50 * math.cos(math.radians(60)), 50 * math.sin(math.radians(60))
    e = math.hypot(100 - bx, -by)
    a = (70**2 - 56**2 + e * e) / (2 * e)
    h = math.sqrt(70**2 - a * a)
    ux, uy = (100 - bx) / e, -by / e
    want = [(bx + a * ux - s * h * uy, by + a * uy + s * h * ux) for s in (1, -1)]
    c = (got.P["C"][0] * 1e3, got.P["C"][1] * 1e3)
    assert min(math.dist(c, w) for w in want) < 1e-9
    assert math.dist(c, (before.P["C"][0] * 1e3, before.P["C"][1] * 1e3)) > 1
    assert ContentKey((1, "a")) == ContentKey((1, "a")) != ContentKey((1, "b"))


def test_scenes_solved_in_a_long_process_are_let_go():
    """A class's worth of scenes solved one after another (variants, grading) does not keep
    every scene alive: the cache by identity is bounded, and a scene no longer held
    elsewhere is collected (its weak reference dies)."""
    import gc
    import weakref

    plan_module._BY_ID.clear()
    plan_module._BY_CONTENT.clear()
    refs = []
    for k in range(plan_module._KEEP + 40):
        sc = parse_scene(seed().replace("BC = 66", f"BC = {60 + k / 100:g}"))
        solve(sc)
        refs.append(weakref.ref(sc))
        del sc
    gc.collect()
    assert len(plan_module._BY_ID) <= plan_module._KEEP
    gone = sum(r() is None for r in refs)
    assert gone >= 40, f"only {gone} of {len(refs)} scenes were let go"
