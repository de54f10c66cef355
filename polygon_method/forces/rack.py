"""The force step of a rack on its pinion (the plan's "rack" step): the rack is a block R
on a fixed guide (unit ``u`` along its pitch line, ``n = perp(u)``), meshing with a gear
turning about the fixed centre O at the pitch point I (the foot of the perpendicular from
O on the pitch line).

The pinion's teeth push the rack along the line of action through I, at the pressure
angle phi to the pitch line (20 deg unless the scene says), pushing it away from the
pinion: with ``m = (I - O) / |I - O|`` the contact force on the rack is ``F = T u + N m``,
``N = |T| tan phi``. The guide holds the rack with ``G n`` and a couple ``C`` (a rack is a
long bar: its guide keeps it from turning). With ``R`` the resultant of the known forces on
the rack and ``M_R`` their moment about its point R::

    T = -R . u,   G = -(R . n + N m . n),   C = -(M_R + (I - R) x F)

The pinion feels ``-F`` at I. Nothing is divided: never singular.

A rack along +x above its pinion (m = +y), pushed back by 100 N along -x: the teeth push
it 100 N along +x and 100 tan 20 deg = 36.4 N up, the guide pulls it down as hard:

>>> T, N, G = solve((-100.0, 0.0), (1.0, 0.0), (0.0, 1.0), 0.3490658503988659)
>>> [round(v, 9) + 0.0 for v in (T, N, G)]
[100.0, 36.397023427, -36.397023427]
"""

from __future__ import annotations

from ..common.numbers import fmt
from .bodies import cross, direction
from .records import FRAME, Contact, ForceStep, GuideForce, Side, block
from .rolling import pressure_angle


def solve(known, u, m, phi):
    """(T along u, N along m, the guide's G along n = perp(u)) holding the rack against the
    known resultant ``known`` (Fx, Fy)."""
    import math

    rx, ry = known[0], known[1]
    ux, uy = u
    mx, my = m
    t = -(rx * ux + ry * uy)
    n = abs(t) * math.tan(phi)
    g = -((-rx * uy + ry * ux) + n * (-mx * uy + my * ux))
    return t, n, g


def owns(st) -> dict:
    """The rack's point acts, for loads and later pins, on the rack."""
    return {st.point: block(st.point)}


def blocks(st) -> tuple:
    return (st.point,)


def bodies(st) -> tuple:
    return (block(st.point),)


def step(st, P, led, own):
    """The tooth load on the rack, the guide's normal force and couple; the pinion feels
    the tooth load back at the pitch point. Returns as :func:`.dyad.step`, the contact
    and the guide among the guides."""
    X, bl = st.point, block(st.point)
    kb = led.of(bl)
    ux, uy = st.dims[2], st.dims[3]
    ix, iy = st.contact(P)  # fixed: the foot of O on the pitch line
    d = -st.dims[4]
    s = 1.0 if d > 0 else -1.0
    mx, my = -s * uy, s * ux  # (I - O) / |I - O|
    phi, stated = pressure_angle(st)
    t, n, g = solve(kb, (ux, uy), (mx, my), phi)
    fx, fy = t * ux + n * mx, t * uy + n * my
    xx, xy = P[X]
    mr = kb[2] - cross(xx, xy, kb[0], kb[1])
    c = -(mr + cross(ix - xx, iy - xy, fx, fy))
    contact = Contact(bl, (ix, iy), n, -t * s, (mx, my), st.base, phi, stated)
    guide = GuideForce(X, g, (-uy, ux), FRAME, c)
    known = led.known(bl)
    led.add(st.base, -fx, -fy, ix, iy, side=Side("contact", st.base, bl, "I", (-fx, -fy), (ix, iy)))
    led.add(FRAME, g * uy, -g * ux, xx, xy)
    led.couple(FRAME, -c)
    eq, drawing = (), None
    if isinstance(t, float):

        def drawing():
            # the pole, the rack's known forces, the tooth load along the line of action
            # and the guide's normal force: their lines meet where it closes
            import math

            tooth = Side("contact", bl, st.base, "I", (fx, fy), (ix, iy))
            lean = math.tan(phi)
            line = direction((fx, fy), (ux + lean * mx, uy + lean * my))
            held = Side("guide", bl, FRAME, X, guide.force, (xx, xy))
            k = len(known)
            return known + (tooth, held), ((k, line), (k + 1, guide.n)), ()

        eq = (
            f"the tooth load on rack {X} by the pinion {st.base} acts at the pitch point I "
            f"along the line of action, at the pressure angle {contact.angle_words()} to "
            "the pitch line, pushing the rack away from the pinion",
            f"the rack along its guide: T + R . u = 0, R = ({fmt(kb[0])}, {fmt(kb[1])}) N "
            f"the known forces on {bl}: T = {fmt(t)} N (along the guide's direction)",
            f"N = |T| tan phi = {fmt(n)} N; the tooth load |T| / cos phi = {fmt(contact.load)} N",
            f"across the guide: G = -(R . n + N m . n) = {fmt(g)} N; the guide's couple "
            f"C = -(M_{X} + (I - {X}) x F) = {fmt(c)} N m (it keeps the rack from turning)",
        )
    rec = ForceStep(
        st.index,
        "rack",
        st.title,
        (bl,),
        (kb,),
        (
            (f"F_I on {bl} by {st.base} (the tooth load along the line of action)", (fx, fy)),
            (f"N_{X} on {bl} by the guide", g),
            (f"C on {bl} by the guide", c),
        ),
        1.0,
        "",
        eq,
        drawing,
    )
    return (), (contact, guide), rec, None
