"""The force step of a triad (a class-III group): a plate with vertices V_1, V_2, V_3, each
joined by a binary link l_i to a known point K_i. The group is the plate and the three
links: statically determinate, but not link by link: the plate's three equations hold the
three links' forces along themselves together (the textbook's 3x3 solve).

Unknown: ``P_i``, the force on link i at V_i by the plate (the plate feels ``-P_i``),
written along the link and across it: ``P_i = a_i e_i + b_i n_i``, ``e_i = (V_i - K_i) /
L_i``, ``n_i = perp(e_i)``. Each link's moments about K_i, where its other pin force has
no arm, give its part across (``cross(V_i - K_i, P_i) = L_i b_i``)::

    b_i = -M_i / L_i

and the plate's balance (forces, and moments about its first vertex V_1, scaled by the
plate's size S) the parts along, one 3x3 system::

    sum a_i e_i = R - sum b_i n_i
    sum a_i (V_i - V_1) x e_i = M_1 - sum b_i (V_i - V_1) x n_i

(R, M_1: the known forces on the plate and their moment about V_1). Its determinant
vanishes when the three links' lines meet in one point (or are parallel): the triad's
own singularity, where the kinematics fails too; the condition is its determinant over
the product of its columns' sizes. Then each link's balance gives its force at K_i,
``-(F_i + P_i)``.

Three links along x, y and x again, the plate's vertices at (1, 0), (0, 1), (1, 1) from
K_1 = (0, 0), K_2 = (0, 0), K_3 = (0, 1): 1 N pushing the plate to the right at V_1,
along link 1's line, is held by link 1 alone:

>>> a = solve3x3(((1.0, 0.0), (0.0, 1.0), (1.0, 0.0)), ((0.0, 0.0), (-1.0, 1.0), (0.0, 1.0)),
...              (1.0, 0.0, 0.0))
>>> [round(v, 12) + 0.0 for v in a[:3]]
[1.0, 0.0, 0.0]
"""

from __future__ import annotations

from ..steps.rounding import largest, vhypot
from .bodies import Singular, any_zero, cross, least, outer_pin, unit
from ..common.numbers import fmt
from .records import ForcePolygon, ForceStep, PinForce, Side


def solve3x3(e, r, rhs):
    """(a_1, a_2, a_3, the condition) of ``sum a_i (e_i, r_i x e_i) = rhs`` (Cramer's rule;
    ``r_i`` the vertices from the moments' point, already over the plate's size)."""
    cols = [(ex, ey, cross(rx, ry, ex, ey)) for (ex, ey), (rx, ry) in zip(e, r)]

    def det(c1, c2, c3):
        return (
            c1[0] * (c2[1] * c3[2] - c2[2] * c3[1])
            - c2[0] * (c1[1] * c3[2] - c1[2] * c3[1])
            + c3[0] * (c1[1] * c2[2] - c1[2] * c2[1])
        )

    d = det(*cols)
    size = 1.0
    for c in cols:
        size = size * (c[0] * c[0] + c[1] * c[1] + c[2] * c[2]) ** 0.5
    cond = abs(d) / size
    if any_zero(d):
        return None, None, None, 0.0
    return (
        det(rhs, cols[1], cols[2]) / d,
        det(cols[0], rhs, cols[2]) / d,
        det(cols[0], cols[1], rhs) / d,
        cond,
    )


def covers(st) -> bool:
    """A plate that is one body, or one made of three links (:func:`_sides`)."""
    return True


def owns(st) -> dict:
    """The plate's vertices act, for loads and later pins, on the plate; a plate of three
    links' V_1 and V_2 on its first side (V_1 V_2), V_3 on the second (V_2 V_3)."""
    if st.sides:
        return dict(zip(st.points, (st.plate, st.plate, st.sides[0][0])))
    return {p: st.plate for p in st.points}


def _size(P, st):
    (x1, y1) = P[st.points[0]]
    return largest([vhypot(P[p][0] - x1, P[p][1] - y1) for p in st.points[1:]])


def divisor(st, rec, P, L):
    """The 3x3 solve divides by its condition, each link's part across by its length."""
    short = _size(P, st)
    for v, k in zip(st.points, st.knowns):
        short = least(short, vhypot(P[v][0] - P[k][0], P[v][1] - P[k][1]))
    return rec.condition * short


def step(st, P, led, own):
    """Solve the three links' and the plate's forces; enter the reactions at the known
    points. Returns as :func:`.dyad.step`."""
    plate = st.plate
    kp = led.of(plate)
    each = (kp,) + tuple(led.of(key) for key, _, _ in st.sides)  # (each side's known)
    for k in each[1:]:  # a plate of three links: the triangle as one body first
        kp = tuple(a + b for a, b in zip(kp, k))
    (x1, y1) = P[st.points[0]]
    S = _size(P, st)
    e, n, b, r, kls = [], [], [], [], []
    for lk, K, V in zip(st.links_, st.knowns, st.points):
        (kx, ky), (vx, vy) = P[K], P[V]
        L = vhypot(vx - kx, vy - ky)
        ex, ey = (vx - kx) / L, (vy - ky) / L
        kl = led.of(lk)
        kls.append(kl)
        mk = kl[2] - cross(kx, ky, kl[0], kl[1])
        e.append((ex, ey))
        n.append((-ey, ex))
        b.append(-mk / L)
        r.append(((vx - x1) / S, (vy - y1) / S))
    m1 = kp[2] - cross(x1, y1, kp[0], kp[1])
    rhs = (
        kp[0] - sum(bi * ni[0] for bi, ni in zip(b, n)),
        kp[1] - sum(bi * ni[1] for bi, ni in zip(b, n)),
        m1 / S - sum(bi * cross(ri[0], ri[1], ni[0], ni[1]) for bi, ri, ni in zip(b, r, n)),
    )
    a1, a2, a3, cond = solve3x3(e, r, rhs)
    if a1 is None:
        raise Singular(f"the lines of {', '.join(st.links_)} meet in one point")
    # the known forces one by one, for the polygons (before the reactions are entered)
    knowns = (led.known(plate),) + tuple(led.known(lk) for lk in st.links_)
    pins, found, eq = [], [], []
    vown = owns(st)
    for ai, bi, ei, ni, kl, lk, K, V in zip(
        (a1, a2, a3), b, e, n, kls, st.links_, st.knowns, st.points
    ):
        p = (ai * ei[0] + bi * ni[0], ai * ei[1] + bi * ni[1])
        fk = (-(kl[0] + p[0]), -(kl[1] + p[1]))
        ok = own[K]
        (kx, ky) = P[K]
        led.add(ok, -fk[0], -fk[1], kx, ky, side=Side("pin", ok, lk, K, (-fk[0], -fk[1]), (kx, ky)))
        pins += [PinForce(V, lk, vown[V], p), PinForce(K, lk, ok, fk)]
        found += [(f"F_{V} on {lk} by {vown[V]}", p), (f"F_{K} on {lk} by {ok}", fk)]
        if isinstance(ai, float):
            eq.append(
                f"{lk}: across it b = -M_{K} / {lk} = {fmt(bi)} N (its moments about "
                f"{K}); along it a = {fmt(ai)} N (the plate's 3x3 solve)"
            )
    drawing = None
    if st.sides:  # the triangle's own pins, from its sides' moments
        knowns = knowns[:1] + tuple(led.known(k) for k, _, _ in st.sides) + knowns[1:]
        cond = least(cond, _sides(st, P, led, pins, found, eq))
    if isinstance(a1, float):
        parts = tuple(zip((a1, a2, a3), b, e, n))
        at_k = [p.force for p in pins[1:6:2]]
        mid = tuple(p.force for p in pins[6:])  # (a plate of three links: V2's, V1's, V3's)

        def drawing():
            return polygons(st, P, own, parts, knowns, at_k, mid)

    rec = ForceStep(
        st.index,
        "triad",
        st.title,
        (plate,) + tuple(k for k, _, _ in st.sides) + tuple(st.links_),
        each + tuple(kls),
        tuple(found),
        cond,
        "the plate's 3x3 system's divisor (Cramer's rule) over its columns' sizes (zero where the "
        "three links' lines meet in one point)",
        tuple(eq),
        drawing,
    )
    return tuple(pins), (), rec, None


def _sides(st, P, led, pins, found, eq):
    """A plate of three links (sides S_1 = V_1 V_2, the plate's key; S_2 = V_2 V_3; S_3 = V_3
    V_1): each hanging link's force back on the side that owns its vertex, then the pins
    between the sides as a dyad's at V_2, S_1 about V_1 and S_2 about V_3 (where the other
    pins have no arm): the force on S_1 at V_2 by S_2, and from the two sides' balances the
    force on S_1 at V_1 by S_3 and on S_2 at V_3 by S_3 (S_3's balance then holds, the
    triangle's as a whole having been solved). Returns that dyad's condition (the sine of
    the triangle's angle at V_2)."""
    from .dyad import solve as dyad

    vown = owns(st)
    (s2, _, _), (s3, _, _) = st.sides
    known = {st.plate: led.of(st.plate), s2: led.of(s2)}  # (the ledger keeps its own)
    for pin in pins[0::2]:  # (on each hanging link at its vertex, by the side there)
        (vx, vy), (fx, fy) = P[pin.point], pin.force
        kx, ky, km = known[vown[pin.point]]
        known[vown[pin.point]] = (kx - fx, ky - fy, km - (vx * fy - vy * fx))
    V1, V2, V3 = st.points
    (x1, y1), (x2, y2), (x3, y3) = P[V1], P[V2], P[V3]
    p, f1, f3, cond = dyad(x1, y1, known[st.plate], x3, y3, known[s2], x2, y2)
    if p is None:
        raise Singular(f"{V1}, {V2} and {V3} are in a line")
    pins += [PinForce(V2, st.plate, s2, p), PinForce(V1, st.plate, s3, f1)]
    pins.append(PinForce(V3, s2, s3, f3))
    found += [
        (f"F_{V2} on {st.plate} by {s2}", p),
        (f"F_{V1} on {st.plate} by {s3}", f1),
        (f"F_{V3} on {s2} by {s3}", f3),
    ]
    if isinstance(cond, float):
        eq.append(
            f"the plate's sides: {st.plate}'s moments about {V1} and {s2}'s about {V3} give the "
            f"force at {V2}; their balances the forces at {V1} and {V3} by {s3}"
        )
    return cond


def polygons(st, P, own, parts, knowns, at_k, mid=()):
    """The triad's force polygons, as a book draws a class-III group's: the plate's (its
    known forces, then each link's force on it at its vertex, the part across the link
    from the link's moments about K_i and the part along it from the 3x3 solve, whose
    direction lines are drawn; it closes on the pole), then each link's that carries
    forces of its own or a couple (the plate's force on it across and along it, its known
    forces, the force at K_i closing it; a link carrying nothing is a two-force member, its
    force along it, and has none). A plate of three links: the first polygon is the
    triangle's as one plate (its three sides' known forces), and after the links' come its
    sides' (:func:`_side_polygons`). ``parts``: (a_i, b_i, e_i, n_i) per link; ``knowns``:
    the plate's (then each other side's) and each link's known forces (:class:`Side` s);
    ``at_k``: the force on each link at K_i; ``mid``: a plate of three links' pin forces
    between its sides (on S_1 at V_2 by S_2, on S_1 at V_1 by S_3, on S_2 at V_3 by S_3).
    Returns (polygon, unknown, chords, every :class:`ForcePolygon`)."""
    plate = st.plate
    vown = owns(st)
    nplate = 1 + len(st.sides)
    sides, unknown, chords = [s for k in knowns[:nplate] for s in k], [], []
    links, hung = [], []
    for (a, b, (ex, ey), (nx, ny)), lk, K, V, known, fk in zip(
        parts, st.links_, st.knowns, st.points, knowns[nplate:], at_k
    ):
        at, on = P[V], vown[V]
        across, along = (b * nx, b * ny), (a * ex, a * ey)
        whole = (across[0] + along[0], across[1] + along[1])
        k = len(sides)  # on the plate: the link's force back, across and along the link
        sides += [
            Side("pin", on, lk, V, (-across[0], -across[1]), at, "t"),
            Side("pin", on, lk, V, (-along[0], -along[1]), at, "n"),
        ]
        unknown.append((k + 1, (ex, ey)))
        hung.append(Side("pin", on, lk, V, (-whole[0], -whole[1]), at))
        chords.append((hung[-1], k, k + 2))
        if known or b != 0:
            poly = (
                Side("pin", lk, on, V, across, at, "t"),
                Side("pin", lk, on, V, along, at, "n"),
                *known,
                Side("pin", lk, own[K], K, fk, P[K]),
            )
            read = ((Side("pin", lk, on, V, whole, at), 0, 2),) if known else ()
            links.append(ForcePolygon((lk,), poly, (), read))  # (no known: F_K the whole)
    bodies = (plate,) + tuple(k for k, _, _ in st.sides)
    main = ForcePolygon(bodies, tuple(sides), tuple(unknown), tuple(chords))
    more = _side_polygons(st, P, dict(zip(bodies, knowns)), hung, mid) if st.sides else ()
    return main.polygon, main.unknown, main.chords, (main, *links, *more)


def _side_polygons(st, P, known, hung, mid):
    """A plate of three links' own polygons, drawn as the dyad S_1, S_2 about V_2 is (its
    solve): the two sides' known forces and the hanging links' forces on them (found
    before, now known), S_3's forces on them at V_1 and V_3, each split along its side
    (V_1 V_2, V_3 V_2: their direction lines meet where it closes) and square to it (from
    the side's moments about V_2), the force at V_2 between them read across; then S_3's
    (its known forces and the other two sides' on it: two alone, equal and opposite
    along it, where it carries none)."""
    V1, V2, V3 = st.points
    s1 = st.plate
    (s2, _, _), (s3, _, _) = st.sides
    X1, X2, X3 = P[V1], P[V2], P[V3]
    p, f1, f3 = mid
    k1 = known[s1] + tuple(h for h in hung if h.on == s1)
    k2 = known[s2] + tuple(h for h in hung if h.on == s2)
    whole1, whole3 = Side("pin", s1, s3, V1, f1, X1), Side("pin", s2, s3, V3, f3, X3)
    n1, t1 = outer_pin(whole1, X1, X2)
    n3, t3 = outer_pin(whole3, X3, X2)
    poly = (n1, t1) + k1 + k2 + (t3, n3)
    k = len(poly)
    middle = (Side("pin", s1, s2, V2, p, X2), 2 + len(k1), 0)
    pair = ForcePolygon(
        (s1, s2),
        poly,
        ((0, unit(X1, X2)), (k - 1, unit(X3, X2))),
        ((whole1, 0, 2), middle, (whole3, k - 2, k)),
    )
    back = (
        Side("pin", s3, s1, V1, (-f1[0], -f1[1]), X1),
        Side("pin", s3, s2, V3, (-f3[0], -f3[1]), X3),
    )
    return pair, ForcePolygon((s3,), known[s3] + back)
