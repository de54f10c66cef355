"""The force step of a dyad (RRR): links 1 (B-C) and 2 (D-C) pinned together at C, B and D
on bodies already solved for their motion.

Unknown: ``P``, the force on link 1 at C by link 2 (link 2 feels ``-P``). The moments of
each link about its other end, where the unknown pin forces at B and D have no arm::

    cross(C - B, P) + M1_B = 0          (link 1 about B)
    cross(C - D, -P) + M2_D = 0         (link 2 about D)

with ``M1_B``, ``M2_D`` the moments of the known forces on each link about that end. A 2x2
system whose determinant is ``cross(C - B, C - D)``: zero when B, C, D are in a line (the
dyad's dead point, where the kinematics is singular too). Then each link's force balance
gives its end's pin force: on link 1 at B ``-(F1 + P)``, on link 2 at D ``-(F2 - P)``.

A weight of 1 N at C = (1, 1) on link 1 from B = (0, 0); link 2 stands upright on
D = (1, 0) and takes it all (the joint's triangle of forces: link 1 carries none):

>>> P, FB, FD, c = solve(0.0, 0.0, (0.0, -1.0, -1.0), 1.0, 0.0, (0.0, 0.0, 0.0), 1.0, 1.0)
>>> [round(v, 12) + 0.0 for v in P + FB + FD]
[0.0, 1.0, 0.0, 0.0, 0.0, 1.0]
"""

from __future__ import annotations

from ..steps.rounding import vhypot
from .bodies import THREE_PINS, Singular, any_zero, cross, least, outer_pin, unit
from ..common.numbers import fmt
from .records import ForceStep, PinForce, Side


def solve(bx, by, known1, dx, dy, known2, cx, cy, condition=True):
    """(P on link 1 at C by link 2, the force on link 1 at B, the force on link 2 at D,
    the condition ``|cross(C - B, C - D)| / (|C - B| |C - D|)``, None unless
    ``condition``); floats, or arrays over a sweep.

    ``known1``, ``known2``: ``(Fx, Fy, M)`` of the known forces on each link, M about the
    origin. (Each ``cross`` written out: this is the short road's hot path too.)"""
    f1x, f1y, m1 = known1
    f2x, f2y, m2 = known2
    m1b = m1 - (bx * f1y - by * f1x)  # about B: M - cross(B, F)
    m2d = m2 - (dx * f2y - dy * f2x)  # about D
    r1x, r1y = cx - bx, cy - by
    r2x, r2y = cx - dx, cy - dy
    det = r1x * r2y - r1y * r2x  # cross(C - B, C - D)
    cond = None
    if condition:
        size = ((r1x * r1x + r1y * r1y) * (r2x * r2x + r2y * r2y)) ** 0.5  # never 0
        cond = abs(det) / size
    if det == 0 if det.__class__ is float else any_zero(det):  # (no call for a float)
        return None, None, None, 0.0
    # -r1y Px + r1x Py = -M1_B ;  -r2y Px + r2x Py = M2_D
    px = (-m1b * r2x - r1x * m2d) / det
    py = (-r1y * m2d - m1b * r2y) / det
    return (px, py), (-(f1x + px), -(f1y + py)), (-(f2x - px), -(f2y - py)), cond


def bodies(st) -> tuple:
    """The bodies the step moves: its two links."""
    return (st.link1, st.link2)


def owns(st) -> dict:
    """The point the step finds acts, for loads and later pins, on its first link."""
    return {st.point: st.link1}


def bind(st, own, ix):
    l1, l2, b, d, c = st.link1, st.link2, st.b, st.d, st.point
    ob, od = own[b], own[d]
    i1, i2, ib, id_ = ix(l1), ix(l2), ix(ob), ix(od)
    why = f"{b}, {c} and {d} are in a line"
    head = (THREE_PINS, c, l1, l2, b, ob, d, od)  # what its raw pin entry always holds

    def run(P, S, pins, guides):
        # solve(...) written out, the same operations in the same order (no call, no
        # tuple between them): the forces to the last bit of the long road's
        (bx, by), (dx, dy), (cx, cy) = P[b], P[d], P[c]
        sx, sy, sm = S
        f1x, f1y, f2x, f2y = sx[i1], sy[i1], sx[i2], sy[i2]
        m1b = sm[i1] - (bx * f1y - by * f1x)  # about B
        m2d = sm[i2] - (dx * f2y - dy * f2x)  # about D
        r1x, r1y = cx - bx, cy - by
        r2x, r2y = cx - dx, cy - dy
        det = r1x * r2y - r1y * r2x
        if det == 0 if det.__class__ is float else any_zero(det):
            raise Singular(why)
        px = (-m1b * r2x - r1x * m2d) / det
        py = (-r1y * m2d - m1b * r2y) / det
        # -F_B and -F_D, the reactions on the bodies at B and D (a negation is exact:
        # -(-x) is x to the bit)
        ex, ey, gx, gy = f1x + px, f1y + py, f2x - px, f2y - py
        # its three pins, (c, l1, l2, (px, py)), (b, l1, ob, (-ex, -ey)) and (d, l2, od,
        # (-gx, -gy)), in one tuple: made into records only when they are read
        pins.append((head, px, py, ex, ey, gx, gy))
        sx[ib] = sx[ib] + ex  # sums_add(S, ib, ex, ey, bx, by), written out
        sy[ib] = sy[ib] + ey
        sm[ib] = sm[ib] + (bx * ey - by * ex)
        sx[id_] = sx[id_] + gx  # sums_add(S, id_, gx, gy, dx, dy)
        sy[id_] = sy[id_] + gy
        sm[id_] = sm[id_] + (dx * gy - dy * gx)

    return run


def step(st, P, led, own):
    """Solve the step's pin forces from the ledger; enter the reactions on the bodies at B
    and D. Returns (pin forces, guide forces, :class:`ForceStep`, driving torque or None)."""
    l1, l2 = st.link1, st.link2
    k1, k2 = led.of(l1), led.of(l2)
    (bx, by), (dx, dy), (cx, cy) = P[st.b], P[st.d], P[st.point]
    p, fb, fd, cond = solve(bx, by, k1, dx, dy, k2, cx, cy)
    if p is None:
        raise Singular(f"{st.b}, {st.point} and {st.d} are in a line")
    ob, od = own[st.b], own[st.d]
    pins = (PinForce(st.point, l1, l2, p), PinForce(st.b, l1, ob, fb), PinForce(st.d, l2, od, fd))
    known1, known2 = led.known(l1), led.known(l2)
    led.add(ob, -fb[0], -fb[1], bx, by, side=Side("pin", ob, l1, st.b, (-fb[0], -fb[1]), (bx, by)))
    led.add(od, -fd[0], -fd[1], dx, dy, side=Side("pin", od, l2, st.d, (-fd[0], -fd[1]), (dx, dy)))
    eq = ()
    drawing = None
    if isinstance(cond, float):  # one instant: the working in words, the force polygon

        def drawn():
            B, C, D = (bx, by), (cx, cy), (dx, dy)
            whole_b = Side("pin", l1, ob, st.b, fb, B)
            whole_d = Side("pin", l2, od, st.d, fd, D)
            bn, bt = outer_pin(whole_b, B, C)
            dn, dt = outer_pin(whole_d, D, C)
            # the pole, F_B along BC (found last), F_B square to BC, link 1's known forces,
            # link 2's, F_D square to DC, F_D along DC (found last): closed
            polygon = (bn, bt) + known1 + known2 + (dt, dn)
            k = len(polygon)
            return (
                polygon,
                ((0, unit(B, C)), (k - 1, unit(D, C))),
                (
                    (whole_b, 0, 2),
                    (Side("pin", l1, l2, st.point, p, C), 2 + len(known1), 0),
                    (whole_d, k - 2, k),
                ),
            )

        drawing = drawn
        X, B, D = st.point, st.b, st.d
        m1b = k1[2] - cross(bx, by, k1[0], k1[1])
        m2d = k2[2] - cross(dx, dy, k2[0], k2[1])
        eq = (
            f"moments of {l1} about {B}: ({X} - {B}) x F_{X} + M_{B} = 0, with M_{B} = "
            f"{fmt(m1b)} N m the known forces' moment",
            f"moments of {l2} about {D}: ({X} - {D}) x (-F_{X}) + M_{D} = 0, with M_{D} = "
            f"{fmt(m2d)} N m",
            f"the two together: F_{X} = ({fmt(p[0])}, {fmt(p[1])}) N, the force on {l1} by {l2}",
            f"forces on {l1}: F_{B} = -(the known forces + F_{X}) = ({fmt(fb[0])}, {fmt(fb[1])}) N",
            f"forces on {l2}: F_{D} = -(the known forces - F_{X}) = ({fmt(fd[0])}, {fmt(fd[1])}) N",
        )
    rec = ForceStep(
        st.index,
        "dyad",
        st.title,
        (l1, l2),
        (k1, k2),
        (
            (f"F_{st.point} on {l1} by {l2}", p),
            (f"F_{st.b} on {l1} by {ob}", fb),
            (f"F_{st.d} on {l2} by {od}", fd),
        ),
        cond,
        f"sine of the angle at {st.point} between {st.point}{st.b} and {st.point}{st.d}",
        eq,
        drawing,
    )
    return pins, (), rec, None


def divisor(st, rec, P, L):
    """The length the step's equations divide by: ``min(|CB|, |CD|) c / 2`` (its
    determinant over the larger arm, Cramer's rule: see :mod:`.bounds`)."""
    (bx, by), (dx, dy), (cx, cy) = P[st.b], P[st.d], P[st.point]
    return 0.5 * rec.condition * least(vhypot(cx - bx, cy - by), vhypot(cx - dx, cy - dy))
