"""Recognising a class-III group: which points of the scene form a triad's plate, its three
vertices each hung on one link from a known point (a plate with carried points, or three
links joined in a triangle), and where its vertices sit on the plate.

>>> triangle_offsets(3.0, 5.0, 4.0, 1.0)  # a right angle at V1
(3.0, 0.0, 0.0, 4.0)
"""

from __future__ import annotations

__all__ = ["plate_of", "triangle_offsets"]


def plate_of(g, name):
    """A plate (a link with carried points: a body of three or more points, none known)
    with ``name`` among three of its points that each have exactly one unused link to a
    known point, or three links joined in a triangle about ``name`` (:func:`_triangle`):
    the triad's fields (``points``, ``plate``, ``knowns``, ``links_``, ``lengths``,
    ``offsets`` and a triangle's ``sides``), or None."""
    for key in g.bodies_of(name):
        if key in g.used_links:
            continue
        b = g.body(key)
        if len(b) < 3 or any(p in g.P for p in b):
            continue
        verts = []
        for p in b:
            free = [f for f in g.free(p) if f[0] != key]
            if len(free) == 1:
                verts.append((p, free[0]))
        if name not in [v[0] for v in verts] or len(verts) < 3:
            continue
        verts = verts[:3]
        if len({f[0] for _, f in verts}) < 3:
            continue  # one link to two vertices: no triad
        f = b
        (p1, (k1, K1, l1)), (p2, (k2, K2, l2)), (p3, (k3, K3, l3)) = verts
        return dict(
            points=(p1, p2, p3),
            plate=key,
            knowns=(K1, K2, K3),
            links_=(k1, k2, k3),
            lengths=(l1, l2, l3),
            offsets=(
                f[p2][0] - f[p1][0],
                f[p2][1] - f[p1][1],
                f[p3][0] - f[p1][0],
                f[p3][1] - f[p1][1],
            ),
        )
    return _triangle(g, name)


def _one_free(g, p, exclude):
    """The one link of ``p`` to a known point, not among ``exclude``; None if not one."""
    free = [f for f in g.free(p) if f[0] not in exclude]
    return free[0] if len(free) == 1 else None


def _triangle(g, name):
    """Three links joined in a triangle (a rigid plate made of links: name-X, X-Y, Y-name),
    none of their points known, each point with one other link to a known point."""
    ends = {}
    for key in g.bodies_of(name):
        b = g.body(key)
        if key in g.used_links or len(b) != 2:
            continue
        other = next(p for p in b if p != name)
        if other not in g.P:
            ends.setdefault(other, key)
    names = list(ends)
    for i, X in enumerate(names):
        for Y in names[i + 1 :]:
            side = next(
                (k for k in g.bodies_of(X) if k not in g.used_links and set(g.body(k)) == {X, Y}),
                None,
            )
            if side is None:
                continue
            tri = {ends[X], side, ends[Y]}
            free = [(p, _one_free(g, p, tri)) for p in (name, X, Y)]
            if any(f is None for _, f in free) or len({f[0] for _, f in free}) < 3:
                continue
            (p1, (k1, K1, l1)), (p2, (k2, K2, l2)), (p3, (k3, K3, l3)) = free
            a = g.bodies.distance(ends[X], name, X)
            b = g.bodies.distance(side, X, Y)
            c = g.bodies.distance(ends[Y], Y, name)
            return dict(
                points=(p1, p2, p3),
                plate=ends[X],
                knowns=(K1, K2, K3),
                links_=(k1, k2, k3),
                lengths=(l1, l2, l3),
                offsets=triangle_offsets(a, b, c, 1.0),
                sides=((side, X, Y), (ends[Y], Y, name)),
            )
    return None


def triangle_offsets(a, b, c, hand):
    """V2 - V1 and V3 - V1 of a triangle with V1V2 = a, V2V3 = b, V3V1 = c, V3 on the
    side ``hand`` (+1: left of V1 -> V2)."""
    x3 = (a * a + c * c - b * b) / (2.0 * a)
    return (a, 0.0, x3, hand * max(c * c - x3 * x3, 0.0) ** 0.5)
