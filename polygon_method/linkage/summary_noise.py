"""The rounding noise of a summary's extremes: each quantity's own error bound at the samples
where an extreme is reached (below it a value is noise about a true zero, and is shown as 0).

A sample beside a followed change point is not the plan's value there (the construction is
indeterminate: both assemblies meet) but the sweep's Richardson extrapolation from six angles
either side (:meth:`~polygon_method.solver.tracking.Sweeper.richardson`), so its bound is
theirs, times the sum of the sizes of its weights, (15 + 6 + 1) / 10 = 2.2: the plan's own
bound at the change point, where its condition is nought, would call any value there noise
(a lever's Coriolis component at its greatest, read as "0 (constant)").
"""

from __future__ import annotations

import numpy as np

from ..scene import FixedPath
from ..solver.kinematics import Motion

__all__ = ["noise"]

#: the sum of the sizes of the Richardson weights of a sample beside a change point
_WEIGHTS = 2.2


def noise(scene, plan, sw, best, theta) -> dict:
    """name -> f(i): the absolute error bound of each quantity at sample ``i`` of ``theta``
    (``best``: the summary's extremes, ``[max, imax, min, imin, ...]`` by name); 0 where
    the bound is no useful bound (hide nothing)."""
    idx = sorted(
        {
            int(i)
            for mx, imx, mn, imn, *_ in best.values()
            for i in (imx, imn)
            if i is not None and i >= 0
        }
    )
    if not idx or len(theta) == 0:
        return {}
    th = np.asarray(theta, dtype=float)[idx]
    table = _absolute(scene, plan, sw.evaluate(th), th)
    for ids, h in sw.near_change_points(th):
        beside = [
            _absolute(scene, plan, sw.evaluate(th[ids] + s * h), th[ids])
            for s in (-3, -2, -1, 1, 2, 3)
        ]
        for name, arr in table.items():
            arr[ids] = _WEIGHTS * np.max([b[name] for b in beside], axis=0)
    where = {k: j for j, k in enumerate(idx)}
    return {name: (lambda i, a=arr: float(a[where[int(i)]])) for name, arr in table.items()}


def _absolute(scene, plan, fr, th) -> dict:
    """name -> the absolute error bound of each quantity of frame ``fr`` at angles ``th``."""
    from ..solver.errorbound import USELESS, error_bounds

    with np.errstate(all="ignore"):
        eb = error_bounds(
            Motion(scene, plan, th, fr.P, fr.V, fr.A, fr.W, fr.Al, fr.S, fr.cond, fr.bad)
        )
    size = {k: np.broadcast_to(np.asarray(v, dtype=float), th.shape) for k, v in eb.scales.items()}

    def of(rel, kind):
        rel = np.broadcast_to(np.asarray(rel, dtype=float), th.shape)
        return np.where(rel < USELESS, rel * size[kind], 0.0)

    out = {}
    for p in eb.V:
        out[f"v_{p}"] = of(eb.V[p], "velocity")
        out[f"a_{p}"] = of(eb.A[p], "acceleration")
    for lk in eb.W:
        out[f"omega_{lk}"] = of(eb.W[lk], "omega")
        out[f"alpha_{lk}"] = of(eb.Al[lk], "alpha")
    for s in scene.sliders:
        if s.key in eb.S:
            ev, ea, ec = eb.S[s.key]
            out[f"vs_{s.key}"] = of(ev, "velocity")
            out[f"as_{s.key}"] = of(ea, "acceleration")
            out[f"ac_{s.key}"] = of(ec, "acceleration")
        if isinstance(s, FixedPath) and s.point in eb.P:
            out[f"s_{s.key}"] = of(eb.P[s.point], "position")
    return out
