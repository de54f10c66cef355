"""The mechanism at rest where it stands: what the force analysis sees of a scene at rest
(``[input] speed = 0``: its weights and loads, no inertia), of one starting from rest with
an acceleration (the inertia of the start), and of a scene whose inertia a slip leaves out
(the check's "the inertia left out").

Starting from rest (``speed = 0`` with the crank's ``acceleration`` alpha): every velocity is
nought, so each acceleration has its tangential terms alone (no centripetal, no Coriolis
component): a point's is ``alpha dP/dtheta``, a link's angular acceleration ``alpha
dphi/dtheta``, a block's sliding one ``alpha ds/dtheta``: alpha over the virtual omega times
the motion per rad/s of the crank (the acceleration polygon is the velocity polygon per rad/s
scaled by alpha).

At rest every acceleration is nought, so each body's inertia force ``-m a_G`` and couple
``-I alpha`` vanish and only its weight ``m g`` and the loads remain. The velocities are
kept as the motion that is about to start (per rad/s of the crank, in the sense the scene
states): with ``[friction]`` each friction force is then limiting, ``mu |N|`` against the
impending sliding (and the friction circle's couple against the impending turning), as a
textbook finds the effort to start a motion with the coefficient of static friction
(:mod:`.friction`). The positions are the motion's own.
"""

from __future__ import annotations

__all__ = ["Still", "still"]


class Still:
    """A motion's positions and velocities with every acceleration nought (the attributes
    the force analysis reads of a :class:`~polygon_method.solver.kinematics.Motion`)."""

    __slots__ = ("scene", "plan", "theta", "P", "V", "A", "W", "Al", "S", "cond", "bad")

    def __init__(self, motion, zero, k=0.0):
        self.scene, self.plan, self.theta = motion.scene, motion.plan, motion.theta
        self.P, self.cond, self.bad = motion.P, motion.cond, motion.bad
        self.V, self.W = motion.V, motion.W  # the motion about to start (friction's sense)
        if k:  # starting from rest: alpha / omega times the motion per rad/s
            self.A = {p: (k * v[0] + zero, k * v[1] + zero) for p, v in motion.V.items()}
            self.Al = {lk: k * w + zero for lk, w in motion.W.items()}
            self.S = {p: (v[0], k * v[0] + zero, zero, zero) for p, v in motion.S.items()}
            return
        self.A = {k: (zero, zero) for k in motion.A}
        self.Al = {k: zero for k in motion.Al}
        self.S = {k: (v[0], zero, zero, zero) for k, v in motion.S.items()}


def still(motion) -> Still:
    """``motion`` at rest where it stands, about to move as its velocities say (floats, or
    arrays of noughts over a sweep).

    >>> from types import SimpleNamespace as S
    >>> m = S(scene=None, plan=None, theta=0.5, P={"A": (1.0, 2.0)}, V={"A": (3.0, 0.0)},
    ...       A={"A": (0.0, 9.0)}, W={"AB": 2.0}, Al={"AB": -1.0}, S={}, cond={}, bad=None)
    >>> r = still(m)
    >>> r.P["A"], r.V["A"], r.A["A"], r.W["AB"], r.Al["AB"]
    ((1.0, 2.0), (3.0, 0.0), (0.0, 0.0), 2.0, 0.0)
    """
    theta = motion.theta
    sc = motion.scene
    k = 0.0 if sc is None else sc.start_alpha / sc.input.omega  # (starting from rest)
    if isinstance(theta, float):
        return Still(motion, 0.0, k)
    import numpy as np

    return Still(motion, np.zeros(np.shape(theta)), k)
