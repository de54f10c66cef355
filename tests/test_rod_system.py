"""The connecting rod's equivalent dynamical system (``m_small_end``, ``m_L``, ``l_GL``,
``correction_couple``, ``correction_torque``) against first principles worked here: the
three conditions of dynamical equivalence, the two pin masses' moment of inertia summed
mass by mass, the rod's angular acceleration from its angle differentiated at 40 digits,
the couple's torque on the crank shaft by statics (a pure couple on the rod, the block
held by its guide's normal force alone); Khurmi's worked example within its rounding; the
classic slips named; a scene with no rod, or a rod with no mass, refused in one line."""

from __future__ import annotations

import math

import mpmath
import pytest

from polygon_method import load_scene, parse_scene, solve
from polygon_method.check import check_answers
from polygon_method.common.errors import SceneError
from polygon_method.scene import parse_answers
from polygon_method.text.steptable import steps_text
from textbook_corpus import HERE

R, L, E = 0.08, 0.3, 0.0  # crank, rod, offset (m)
M, L1, K = 3.0, 0.11, 0.095  # the rod's mass, G from the small end B, k_G


def _text(offset=0.0, angle=35.0, rpm=1500.0, answers=""):
    e = offset * 1000
    return f"""units = "mm"
[ground]
O = [0, 0]
[links]
OA = {R * 1000}
AB = {L * 1000}
[sliders]
B = {{ path = "horizontal", through = [0, {e}] }}
[masses]
AB = {{ mass = "{M} kg", from = "B", along = {L1 * 1000}, gyration = {K * 1000} }}
B = {{ mass = "2 kg" }}
[input]
crank = "OA"
angle = "{angle} deg"
speed = "{rpm} rpm anticlockwise"
{answers}"""


def _scene(offset=0.0, angle=35.0, rpm=1500.0, answers=""):
    return parse_scene(_text(offset, angle, rpm, answers))


def _rod_motion(offset, angle, rpm):
    """(omega_rod, alpha_rod) of the rod BA at 40 digits: A = r (cos t, sin t), B on
    y = e to the right, beta the direction of BA, differentiated in time at uniform w."""
    mpmath.mp.dps = 40
    w = mpmath.mpf(rpm) * 2 * mpmath.pi / 60
    r, l, e = mpmath.mpf(R), mpmath.mpf(L), mpmath.mpf(offset)

    def beta(t):
        ax, ay = r * mpmath.cos(t), r * mpmath.sin(t)
        bx = ax + mpmath.sqrt(l**2 - (ay - e) ** 2)
        return mpmath.atan2(ay - e, ax - bx)

    t = mpmath.radians(angle)
    return float(w * mpmath.diff(beta, t)), float(w**2 * mpmath.diff(beta, t, 2)), float(w)


def _by_statics(offset, angle, couple):
    """The torque on the crank of a pure couple on the rod (ccw), the block massless and
    held by its guide's normal force: the rod's end forces F_A = -F_B, F_B = s n along the
    guide's normal n; moments about A: couple + (B - A) x F_B = 0; the rod pushes the crank
    at A with -F_A = F_B, its moment about O the torque on the crank."""
    t = math.radians(angle)
    ax, ay = R * math.cos(t), R * math.sin(t)
    bx, by = ax + math.sqrt(L**2 - (ay - offset) ** 2), offset
    nx, ny = 0.0, 1.0
    s = -couple / ((bx - ax) * ny - (by - ay) * nx)
    fx, fy = s * nx, s * ny
    return ax * fy - ay * fx


def _verdicts(sc, text):
    _, ans = parse_answers("[answers]\n" + text, sc)
    return {v.key: v for v in check_answers(solve(sc), ans)}


def _values(sc, keys):
    got = _verdicts(sc, "".join(f'{k} = "?"\n' for k in keys))
    return {k: got[k].correct for k in keys}


KEYS = ("m_small_end", "m_L", "l_GL", "correction_couple", "correction_torque")


@pytest.mark.parametrize("offset,angle", [(0.0, 35.0), (0.0, 150.0), (0.025, 250.0)])
def test_the_two_masses_and_the_couple_from_first_principles(offset, angle):
    got = _values(_scene(offset, angle), KEYS)
    m1, m2, l2 = got["m_small_end"], got["m_L"], got["l_GL"]
    # the three conditions of dynamical equivalence, each by itself
    assert m1 + m2 == pytest.approx(M, rel=1e-12)
    assert m1 * L1 == pytest.approx(m2 * l2, rel=1e-12)  # G the same
    assert m1 * L1**2 + m2 * l2**2 == pytest.approx(M * K**2, rel=1e-12)  # I_G the same
    # the closed forms: l1 l2 = k^2, m1 = m l2 / (l1 + l2), m2 = m l1 / (l1 + l2)
    assert l2 == pytest.approx(K**2 / L1, rel=1e-12)
    assert m1 == pytest.approx(M * (K**2 / L1) / (L1 + K**2 / L1), rel=1e-12)
    # the masses at the two pins: statically equivalent, their I about G summed mass by mass
    l3 = L - L1
    at_b, at_a = M * l3 / L, M * L1 / L
    assert at_b * L1 == pytest.approx(at_a * l3, rel=1e-12)
    i_two = at_b * L1**2 + at_a * l3**2
    w_rod, a_rod, w = _rod_motion(offset, angle, 1500.0)
    couple = (i_two - M * K**2) * a_rod  # what the two masses' inertia couple lacks
    assert got["correction_couple"] == pytest.approx(abs(couple), rel=1e-9)
    assert got["correction_couple"] == pytest.approx(M * abs(a_rod) * L1 * (L - L1 - l2), rel=1e-9)
    torque = _by_statics(offset, angle, couple)
    assert got["correction_torque"] == pytest.approx(abs(torque), rel=1e-9)
    if offset == 0.0:  # the book's T' cos t / sqrt(n^2 - sin^2 t)
        t, n = math.radians(angle), L / R
        book = abs(couple * math.cos(t)) / math.sqrt(n * n - math.sin(t) ** 2)
        assert got["correction_torque"] == pytest.approx(book, rel=1e-9)


def test_khurmi_worked_example_within_its_rounding():
    path = HERE / "khurmi_rod_equivalent_dynamical_system.toml"
    sc = load_scene(path)
    sol = solve(sc)
    vs = check_answers(sol)
    assert all(v.ok for v in vs if not v.asked) and sum(not v.asked for v in vs) == 3
    couple = next(v for v in vs if v.key == "correction_couple").correct
    # T' = 133.4 N m at the book's alpha of 23 000 rad/s^2: T' / alpha is the scene's
    alpha = abs(float(sol.Al["AB"]))
    assert couple / alpha == pytest.approx(133.4 / 23000, rel=5e-4)


def test_the_classic_slips_are_named():
    sc = _scene()
    l2 = K**2 / L1
    m1, m2 = M * l2 / (L1 + l2), M * L1 / (L1 + l2)
    k2_end = K**2 + L1**2  # k about the small end (the parallel axes)
    l2e = k2_end / L1
    got = _verdicts(
        sc,
        f'm_small_end = "{m2:.6g} kg"\nm_L = "{M * L1 / (L1 + l2e):.6g} kg"\n'
        f'l_GL = "{(L1 + l2) * 1000:.6g} mm"\n',
    )
    assert got["m_small_end"].mistake == "masses_swapped"
    assert got["m_L"].mistake == "k_about_end"
    assert got["l_GL"].mistake == "from_small_end"
    w_rod, a_rod, w = _rod_motion(0.0, 35.0, 1500.0)
    couple = M * abs(a_rod) * (L1 * (L - L1) - K**2)
    got = _verdicts(sc, f'correction_torque = "{couple:.6g} N m"\nm_small_end = "{m1:.6g}"\n')
    assert got["correction_torque"].mistake == "couple_not_reduced"
    assert got["m_small_end"].ok


def test_steps_work_the_system_in_the_books_order():
    sc = _scene(answers='[answers]\nm_L = "?"\ncorrection_torque = "?"\n')
    text = steps_text(solve(sc))
    part = text[text.index("equivalent dynamical system") :]
    l2 = K**2 / L1
    order = ["l1 l2 = k_G^2", "m_small_end = m l2 / (l1 + l2)", "m l1 l3", "correction_torque"]
    assert [part.index(w) for w in order] == sorted(part.index(w) for w in order)
    assert f"{l2:.6g} m" in part and f"{M * L1 / (L1 + l2):.6g} kg at L" in part


@pytest.mark.parametrize(
    "scene,words",
    [
        ("rodless", "has no mass"),
        ("fourbar", "no connecting rod"),
    ],
)
def test_refused_in_one_line_saying_why(scene, words):
    if scene == "rodless":
        sc = parse_scene(
            'units = "mm"\n[ground]\nO = [0, 0]\n[links]\nOA = 80\nAB = 300\n[sliders]\n'
            'B = { path = "horizontal" }\n[masses]\nB = { mass = "2 kg" }\n[input]\n'
            'crank = "OA"\nangle = "35 deg"\nspeed = "100 rpm ccw"\n'
        )
    else:
        sc = parse_scene(
            'units = "mm"\n[ground]\nO = [0, 0]\nD = [300, 0]\n[links]\nOA = 80\nAB = 300\n'
            'BD = 200\n[masses]\nAB = { mass = "2 kg" }\n[input]\ncrank = "OA"\n'
            'angle = "35 deg"\nspeed = "100 rpm ccw"\n'
        )
    with pytest.raises(SceneError) as exc:
        _verdicts(sc, 'm_L = "1 kg"\n')
    assert words in exc.value.message and "\n" not in str(exc.value)


def test_each_variants_key_is_the_first_principles_value_at_its_speed():
    from polygon_method.variants import generate
    from polygon_method.variants.papers import answer

    text = parse_scene(
        _text(answers='[answers]\nm_L = "1 kg"\ncorrection_torque = "1 N m"\n')
        + '\n[variants]\nspeed = ["600 rpm", "900 rpm", "2000 rpm"]\n',
        "rod.toml",
    )
    vs = generate(text, count=2, seed=5)
    assert [q[0] for q in vs.questions] == ["m_L", "correction_torque"]
    l2 = K**2 / L1
    for v in vs.variants:
        rpm = abs(v.scene.input.omega) * 30 / math.pi
        _, a_rod, _ = _rod_motion(0.0, 35.0, rpm)
        couple = M * a_rod * (L1 * (L - L1) - K**2)
        want = [M * L1 / (L1 + l2), abs(_by_statics(0.0, 35.0, couple))]
        assert [answer(v.solution, q) for q in vs.questions] == pytest.approx(want, rel=1e-9)


def test_several_rods_on_one_crank_each_by_its_piston():
    base = (
        'units = "mm"\n[ground]\nO = [0, 0]\n[links]\nOA = 60\nAB = 240\nAC = 240\n'
        '[sliders]\nB = { path = "horizontal" }\nC = { path = "vertical" }\n[masses]\n'
        'AB = { mass = "2 kg", from = "B", along = 90, gyration = 80 }\n'
        'AC = { mass = "3 kg", from = "C", along = 60, gyration = 80 }\n[input]\n'
        'crank = "OA"\nangle = "30 deg"\nspeed = "2000 rpm ccw"\n'
    )
    sc = parse_scene(base)
    got = _values(sc, ("m_L_B", "m_L_C", "l_GL_C"))
    assert got["m_L_B"] == pytest.approx(2 * 0.09 / (0.09 + 0.08**2 / 0.09), rel=1e-12)
    assert got["m_L_C"] == pytest.approx(3 * 0.06 / (0.06 + 0.08**2 / 0.06), rel=1e-12)
    assert got["l_GL_C"] == pytest.approx(0.08**2 / 0.06, rel=1e-12)
    with pytest.raises(SceneError) as exc:
        _verdicts(sc, 'm_L = "1 kg"\n')
    assert "name the piston after the key (_B or _C)" in exc.value.message


def test_a_bare_l_gl_is_in_the_scenes_unit():
    got = _verdicts(_scene(), f"l_GL = {K**2 / L1 * 1000:.6g}\n")["l_GL"]
    assert got.ok and got.raw.endswith(" mm")


def test_k_about_the_big_end_named_for_the_couple():
    _, a_rod, _ = _rod_motion(0.0, 35.0, 1500.0)
    l3 = L - L1
    slip = M * abs(a_rod) * (L1 * l3 - (K**2 + l3**2))  # k^2 = k_G^2 + l3^2
    got = _verdicts(_scene(), f'correction_couple = "{abs(slip):.6g} N m"\n')
    assert got["correction_couple"].mistake == "k_about_end"
    assert "big end A" in got["correction_couple"].diagnosis


def test_steps_say_why_a_rod_cannot_be_answered():
    sc = parse_scene(
        'units = "mm"\n[ground]\nO = [0, 0]\n[links]\nOA = 80\nAB = 300\n[sliders]\n'
        'B = { path = "horizontal" }\n[masses]\nB = { mass = "2 kg" }\n[input]\n'
        'crank = "OA"\nangle = "35 deg"\nspeed = "100 rpm ccw"\n[answers]\nm_L = "?"\n'
    )
    text = steps_text(solve(sc))
    assert "not answered: the rod AB has no mass" in " ".join(text.split())
