"""The scene reader's last check of the links: every point takes part (a part of the
scene reader)."""

from __future__ import annotations

from ..common.errors import SceneError
from .records import FixedPath, GuideSlider, split_name


class _Connected:
    """The check that every point takes part (mixed into the reader)."""

    def connected(self, links, points, sliders, ground, inp, cylinders=(), rolling=()):
        """Every point must take part: a dangling point is almost always a typo."""
        uses = {}
        for cyl in cylinders:
            for p in (cyl.barrel, cyl.rod):
                uses[p] = uses.get(p, 0) + 1
        for lk in links:
            uses[lk.p] = uses.get(lk.p, 0) + 1
            uses[lk.q] = uses.get(lk.q, 0) + 1
        # a ground point joined to nothing (unless a path runs through it, or it is a pivot)
        lonely = [name for name in ground if name not in uses and name != inp.pivot]
        if lonely:
            through = {s.through for s in sliders if isinstance(s, FixedPath)}
            through |= {r.through for r in rolling if r.through is not None}  # a ground line's
            blocks = {s.point for s in sliders}
            lonely = [n for n in lonely if ground[n] not in through and n not in blocks]
        # a point of one link alone, and no other role (ground points have theirs)
        if not any(
            (uses[lk.p] == 1 and lk.p not in ground) or (uses[lk.q] == 1 and lk.q not in ground)
            for lk in links
        ):
            links = ()  # (the usual scene: every joint of two links or more, or on the ground)
        else:
            roles = self.roles(points, sliders, ground, links, rolling)
        for lk in links:
            for p in lk.points:
                if uses[p] == 1 and p not in roles:  # (a cylinder's end is used twice)
                    other = lk.other(p)
                    guess = [
                        f"{other}{g}" if len(other) == len(g) == 1 else f"{other}-{g}"
                        for g in lonely
                    ]
                    hint = (
                        (
                            f" (did you mean {guess[0]}? ground point {lonely[0]} is joined to "
                            "nothing)"
                        )
                        if guess
                        else ""
                    )
                    raise self.error(
                        f"point {p} appears only in link {lk.key} and nowhere "
                        f"else: nothing holds it (a typo?){hint}",
                        "links",
                        lk.key,
                    )
        if lonely:
            name = lonely[0]
            raise SceneError(
                f"ground point {name} is not joined to any link: add its link or remove it",
                file=self.file,
                key=f"[ground] {name}",
                line=self.line_of("ground", name),
            )

    def roles(self, points, sliders, ground, links, rolling) -> set:
        """The points that take part otherwise than as a joint of two links: ground points,
        carried points, blocks, a guide's ends, a wheel's points, the ends of a plate."""
        roles = set(ground) | {p.name for p in points} | {s.point for s in sliders}
        roles |= {p for s in sliders if isinstance(s, GuideSlider) for p in (s.first, s.second)}
        roles |= {p for r in rolling for p in (r.centre, r.rim)}  # a wheel's points roll
        roles |= {
            p for r in rolling if r.base for p in self.index[frozenset(split_name(r.base))].points
        }  # and so does the gear a wheel meshes with
        plates = {p.link for p in points}  # a link carrying points is a plate: its ends belong
        roles |= {q for lk in links if lk.key in plates for q in lk.points}
        return roles
