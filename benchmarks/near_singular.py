"""Random mechanisms near each singular family, at a chosen condition of the step that
goes singular (for validating the error bound against the 50-digit reference).

Each maker takes a ``random.Random`` and the condition ``c`` wanted (1e-3 is the edge of
the refusal band) and returns the scene's TOML text. Lengths in mm, angles exact floats.

* ``toggle``: a four-bar whose coupler and follower are nearly in line (extended or
  folded), with a point carried on the coupler;
* ``change_point``: a parallelogram four-bar near its change point (all four pivots in line),
  on the parallelogram branch, with a point carried on the coupler;
* ``dead_centre``: an offset slider-crank on a guide at any angle, the rod nearly
  perpendicular to the guide (the step's dead centre);
* ``block_at_pivot``: a crank and slotted lever, the block near the lever's pivot;
* ``chain``: a toggle four-bar driving a second dyad from its coupler point (errors carried
  through two steps);
* ``toggle and slider``: a toggle four-bar whose extended follower drives a slider.

:func:`make` adds a pin size at every moving joint and a force and a torque as loads.
"""

from __future__ import annotations

import math

__all__ = ["FAMILIES", "make"]


def _r(x):
    return repr(float(x))


def _circle(bx, by, dx, dy, l1, l2, sigma):
    ex, ey = dx - bx, dy - by
    e2 = ex * ex + ey * ey
    a = (l1 * l1 - l2 * l2 + e2) / (2 * e2)
    h = math.sqrt(max(l1 * l1 - a * a * e2, 0.0) / e2)
    return bx + a * ex - sigma * h * ey, by + a * ey + sigma * h * ex


INPUT = """[input]
crank = "{crank}"
angle = "{angle} rad"
speed = "{speed} rad/s {sense}"
acceleration = "{acc} rad/s^2 {asense}"
"""


def _input(rng, crank, angle):
    return INPUT.format(
        crank=crank,
        angle=_r(angle),
        speed=_r(rng.uniform(1, 50)),
        sense=rng.choice(["cw", "ccw"]),
        acc=_r(rng.uniform(0, 100)),
        asense=rng.choice(["cw", "ccw"]),
    )


def _coupler_lengths(rng, e, c):
    """b, cl with the angle at C between CB and CD of sine c, for |BD| = e."""
    if c > 0.3 or rng.random() < 0.5:  # extended: B, C, D nearly in line with C between
        phi = math.pi - math.asin(c)
        b = e * rng.uniform(0.25, 0.75)
        cl = b * math.cos(phi) + math.sqrt(e * e - (b * math.sin(phi)) ** 2)
    else:  # folded: C beyond, BC and CD nearly overlapping
        phi = math.asin(c)
        b = e * rng.uniform(1.3, 2.5)
        cl = b * math.cos(phi) - math.sqrt(e * e - (b * math.sin(phi)) ** 2)
    return b, cl


def _toggle_four_bar(rng, c):
    """A four-bar A(0, 0), D(100, 0) with a random crank and its coupler and rocker made so
    that the dyad at C has condition c: (d, a, theta, B, b, cl, C) flattened."""
    d = 100.0
    a = rng.uniform(15, 60)
    th = rng.uniform(-math.pi, math.pi)
    bx, by = a * math.cos(th), a * math.sin(th)
    e = math.hypot(d - bx, by)
    b, cl = _coupler_lengths(rng, e, c)
    cx, cy = _circle(bx, by, d, 0.0, b, cl, rng.choice([1.0, -1.0]))
    return d, a, th, bx, by, b, cl, cx, cy


def toggle(rng, c, carried=True):
    d, a, th, bx, by, b, cl, cx, cy = _toggle_four_bar(rng, c)
    text = f"""[ground]
A = [0, 0]
D = [{_r(d)}, 0]
[links]
AB = {_r(a)}
BC = {_r(b)}
CD = {_r(cl)}
"""
    if carried:
        text += f"""[points]
E = {{ on = "BC", along = {_r(rng.uniform(-0.5, 1.5) * b)} }}
"""
    return (
        text
        + f"""[assembly]
C = [{_r(cx)}, {_r(cy)}]
"""
        + _input(rng, "AB", th)
    )


def change_point(rng, c):
    a = rng.uniform(20, 80)
    d = rng.uniform(80, 200)
    delta = math.asin(c) * rng.choice([1.0, -1.0]) + rng.choice([0.0, math.pi])
    bx, by = a * math.cos(delta), a * math.sin(delta)
    return f"""[ground]
A = [0, 0]
D = [{_r(d)}, 0]
[links]
AB = {_r(a)}
BC = {_r(d)}
CD = {_r(a)}
[points]
E = {{ on = "BC", along = {_r(rng.uniform(-0.5, 1.5) * d)} }}
[assembly]
C = [{_r(bx + d)}, {_r(by)}]
""" + _input(rng, "AB", delta)


def dead_centre(rng, c):
    r = rng.uniform(20, 80)
    ell = r * rng.uniform(1.5, 4.0)
    beta = rng.uniform(0, 180)
    ux, uy = math.cos(math.radians(beta)), math.sin(math.radians(beta))
    th = rng.uniform(-math.pi, math.pi)
    ax, ay = r * math.cos(th), r * math.sin(th)
    g = math.acos(c) * rng.choice([1.0, -1.0]) + rng.choice([0.0, math.pi])
    rx, ry = ux * math.cos(g) - uy * math.sin(g), ux * math.sin(g) + uy * math.cos(g)
    bx, by = ax + ell * rx, ay + ell * ry
    s = rng.uniform(-50, 50)
    return f"""[ground]
O = [0, 0]
[links]
OA = {_r(r)}
AB = {_r(ell)}
[sliders]
B = {{ path = "{_r(beta)} deg", through = [{_r(bx + s * ux)}, {_r(by + s * uy)}] }}
[assembly]
B = [{_r(bx)}, {_r(by)}]
""" + _input(rng, "OA", th)


def block_at_pivot(rng, c):
    L = rng.uniform(100, 500)
    phi = rng.uniform(-math.pi, math.pi)
    ax, ay = c * L * math.cos(phi), c * L * math.sin(phi)
    r = rng.uniform(20, 100)
    th = rng.uniform(-math.pi, math.pi)
    return f"""[ground]
O2 = [{_r(ax - r * math.cos(th))}, {_r(ay - r * math.sin(th))}]
O4 = [0, 0]
[links]
"O2-A" = {_r(r)}
"O4-P" = {_r(L)}
[sliders]
A = {{ along = "O4-P" }}
""" + _input(rng, "O2-A", th)


def chain(rng, c):
    """A toggle four-bar (condition c at C) whose coupler point E drives a dyad EF, FG to
    a further ground point G (a well-conditioned second step that carries the errors)."""
    d, a, th, bx, by, b, cl, cx, cy = _toggle_four_bar(rng, c)
    along = rng.uniform(-0.5, 1.5) * b
    ex, ey = bx + along * (cx - bx) / b, by + along * (cy - by) / b
    ef, fg = rng.uniform(100, 250), rng.uniform(80, 200)
    phi = rng.uniform(-math.pi, math.pi)
    fx, fy = ex + ef * math.cos(phi), ey + ef * math.sin(phi)
    psi = phi + math.pi + rng.uniform(0.5, 2.6) * rng.choice([1.0, -1.0])  # F's angle 30..150
    gx, gy = fx + fg * math.cos(psi), fy + fg * math.sin(psi)
    return f"""[ground]
A = [0, 0]
D = [{_r(d)}, 0]
G = [{_r(gx)}, {_r(gy)}]
[links]
AB = {_r(a)}
BC = {_r(b)}
CD = {_r(cl)}
EF = {_r(ef)}
FG = {_r(fg)}
[points]
E = {{ on = "BC", along = {_r(along)} }}
[assembly]
C = [{_r(cx)}, {_r(cy)}]
F = [{_r(fx)}, {_r(fy)}]
""" + _input(rng, "AB", th)


def toggle_slider(rng, c):
    """A toggle four-bar (condition c at C) whose follower, extended to E, drives a slider F
    on an inclined fixed path (a dyad's errors carried through a slider step)."""
    d, a, th, bx, by, b, cl, cx, cy = _toggle_four_bar(rng, c)
    along = cl * rng.uniform(1.1, 1.6)  # E on CD's extension beyond C, from D
    ex, ey = d + along * (cx - d) / cl, along * cy / cl
    ell = rng.uniform(100, 250)
    beta = rng.uniform(0, 180)
    ux, uy = math.cos(math.radians(beta)), math.sin(math.radians(beta))
    gam = rng.uniform(0.3, 1.2) * rng.choice([1.0, -1.0])  # rod 17..69 deg from the guide
    fx = ex + ell * (ux * math.cos(gam) - uy * math.sin(gam))
    fy = ey + ell * (ux * math.sin(gam) + uy * math.cos(gam))
    return f"""[ground]
A = [0, 0]
D = [{_r(d)}, 0]
[links]
AB = {_r(a)}
BC = {_r(b)}
DC = {_r(cl)}
EF = {_r(ell)}
[points]
E = {{ on = "DC", along = {_r(along)} }}
[sliders]
F = {{ path = "{_r(beta)} deg", through = [{_r(fx + 20 * ux)}, {_r(fy + 20 * uy)}] }}
[assembly]
C = [{_r(cx)}, {_r(cy)}]
F = [{_r(fx)}, {_r(fy)}]
""" + _input(rng, "AB", th)


def loaded(text, rng):
    """The scene with a pin size at every moving joint of two links and a force on the last
    point and a torque on the last link (for the rubbing and torque bounds)."""
    import tomllib

    t = tomllib.loads(text)
    links = list(t["links"])
    ground = set(t["ground"])
    joints = {}
    for k in links:
        ends = k.split("-") if "-" in k else [k[0], k[1:]]
        for p in ends:
            joints[p] = joints.get(p, 0) + 1
    sliders = list(t.get("sliders", {}))
    points = [p for p, n in joints.items() if (n >= 2 or p in sliders) and p not in ground]
    pins = "".join(f'"{p}" = {{ radius = {_r(rng.uniform(5, 20))} }}\n' for p in points)
    target = sliders or points
    fx, fy = rng.uniform(-500, 500), rng.uniform(-500, 500)
    loads = (
        f'"{target[-1]}" = {{ force = [{_r(fx)}, {_r(fy)}] }}\n'
        f'"{links[-1]}" = {{ torque = "{_r(rng.uniform(1, 50))} N m ccw" }}\n'
    )
    head, inp = text.split("[input]")
    return head + "[pins]\n" + pins + "[loads]\n" + loads + "[input]" + inp


FAMILIES = {
    "toggle": toggle,
    "change point": change_point,
    "dead centre": dead_centre,
    "block at pivot": block_at_pivot,
    "chain": chain,
    "toggle and slider": toggle_slider,
}


def make(family, rng, c, loads=True):
    """The scene text of ``family`` at condition ``c``, with pins and loads unless not."""
    text = FAMILIES[family](rng, c)
    return loaded(text, rng) if loads else text
