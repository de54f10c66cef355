"""Warm cost of the newer step kinds against a dyad's, of a solve whose motion is given on
another quantity against the same solve given the crank's speed, and of a chain driven by a
block on a fixed guide (a block and a slider) against one driven by a crank (a crank and a
slider).

Each figure is the median of many warm ``solve`` calls (the plan compiled once, as for a
student's repeated solve); a step's own cost is the difference between a scene with it and
the same scene without it. Run: ``python benchmarks/new_kinds.py``.
"""

from __future__ import annotations

import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent.parent))

from polygon_method import parse_scene, solve  # noqa: E402

SLIDER = """
[ground]
O = [0, 0]
{extra_ground}
[links]
OA = 150
AB = 600
{extra_links}
[sliders]
B = {{ path = "horizontal" }}
{extra}
[input]
crank = "OA"
angle = 40
{speed}
"""

FOURBAR = """
[ground]
A = [0, 0]
D = [100, 0]
[links]
AB = 50
BC = 66
CD = 56
{extra_links}
[input]
crank = "AB"
angle = 60
speed = "10 rad/s cw"
"""

CASES = {
    "slider crank, crank's speed given": SLIDER.format(
        extra_links="", extra="", extra_ground="", speed='speed = "10 rad/s ccw"'
    ),
    "slider crank, piston's speed given (vs_B)": SLIDER.format(
        extra_links="", extra="", extra_ground="", speed='vs_B = "5 m/s left"\nas_B = "-20 m/s^2"'
    ),
    "slider crank + a cylinder Q-A": SLIDER.format(
        extra_links="",
        extra='[cylinders]\n"Q-A" = {}',
        extra_ground="Q = [-700, -300]",
        speed='speed = "10 rad/s ccw"',
    ),
    "ellipse trammel driven by block A (a block, a slider)": """
[ground]
O = [0, 0]
[links]
AB = 600
[sliders]
A = { path = "horizontal", through = "O" }
B = { path = "vertical", through = "O" }
[input]
block = "A"
s_A = 150
vs_A = "5 m/s left"
as_A = "-20 m/s^2"
""",
    "four-bar": FOURBAR.format(extra_links=""),
    "four-bar + a dyad": FOURBAR.format(extra_links="CE = 60\nDE = 70\n"),
    "five-bar (a crank, a second crank, a dyad)": """
[ground]
A = [0, 0]
E = [120, 0]
[links]
AB = 60
BC = 140
CD = 140
DE = 60
[input]
crank = "AB"
angle = 60
speed = "10 rad/s ccw"
[input.second]
crank = "ED"
angle = 120
speed = "5 rad/s cw"
""",
}


def warm(text, n=4000, repeat=7):
    scene = parse_scene(text)
    solve(scene)
    runs = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        for _ in range(n):
            solve(scene)
        runs.append((time.perf_counter() - t0) / n)
    return statistics.median(runs)


def step_costs(repeat=7, number=2000):
    """The warm one-instant cost of each rolling step against a dyad's, each step's bound
    closure timed alone (best of ``repeat``): the seed four-bar's dyad, the planet on a fixed
    sun and the wheel on the ground of the textbook corpus, a planet on a rocker and Watt's
    sun and planet (the wheel's angle followed from its arm and its gear)."""
    import timeit
    from pathlib import Path
    from polygon_method import load_scene
    from polygon_method.solver.compiler import compile_plan
    from polygon_method.solver.plan import Context

    here = Path(__file__).resolve().parents[1] / "tests" / "textbook"

    def cost(scene, kind):
        plan = compile_plan(scene)
        inp = scene.input
        m = plan.instant(Context(inp.angle, inp.omega, inp.alpha))
        st = next(s for s in plan.steps if s.kind == kind)
        f = st.bind_instant(st.params)
        return min(timeit.repeat(lambda: f(m), number=number, repeat=repeat)) / number

    d = cost(parse_scene(CASES["four-bar"]), "dyad")
    planet = load_scene(here / "rolling_planet_fixed_sun.toml")
    wheel = load_scene(here / "rolling_wheel_on_ground.toml")
    rocker = load_scene(here / "rolling_planet_on_rocker.toml")
    watt = load_scene(here / "rolling_sun_and_planet.toml")
    collar = load_scene(here / "collar_on_turning_rod.toml")
    second = load_scene(here / "collar_second_input.toml")
    return {
        "dyad": d,
        "planet's rolling step": cost(planet, "rolling"),
        "collar driven along its rod (the driver, two points)": cost(collar, "collar"),
        "collar sliding along the crank (second input)": cost(second, "second collar"),
        "wheel's rolling step": cost(wheel, "rolling"),
        "wheel's centre on the ground": cost(wheel, "wheel centre"),
        "planet on a rocker (its arm's angle followed)": cost(rocker, "rolling"),
        "sun driven by a planet on the rod (Watt)": cost(watt, "rolling"),
    }


def main():
    steps = step_costs()
    for name, v in steps.items():
        print(f"{name:<52} {v * 1e6:7.2f} us ({v / steps['dyad']:.2f} of a dyad)")
    t = {name: warm(text) for name, text in CASES.items()}
    for name, v in t.items():
        print(f"{name:<52} {v * 1e6:7.2f} us")
    dyad = t["four-bar + a dyad"] - t["four-bar"]
    cyl = t["slider crank + a cylinder Q-A"] - t["slider crank, crank's speed given"]
    five = t["five-bar (a crank, a second crank, a dyad)"] - t["four-bar"]
    print(f"a dyad's warm cost:              {dyad * 1e6:6.2f} us")
    print(f"a cylinder step's warm cost:     {cyl * 1e6:6.2f} us ({cyl / dyad:.2f} of a dyad)")
    print(f"a second crank's warm cost:      {five * 1e6:6.2f} us ({five / dyad:.2f} of a dyad)")
    block = (
        t["ellipse trammel driven by block A (a block, a slider)"]
        / t["slider crank, crank's speed given"]
    )
    print(f"a solve driven by a block / the same chain driven by a crank: {block:.2f}")
    given = t["slider crank, piston's speed given (vs_B)"] / t["slider crank, crank's speed given"]
    print(f"a solve with the piston's speed given / with the crank's: {given:.2f}")


if __name__ == "__main__":
    main()
