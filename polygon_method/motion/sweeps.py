"""Sweeps: every quantity of ``solve`` as arrays over many crank angles, in chunks.

>>> from polygon_method.scene import parse_scene
>>> sc = parse_scene('''
... [ground]
... O = [0, 0]
... [links]
... OA = 150
... AB = 600
... [sliders]
... B = { path = "horizontal" }
... [input]
... crank = "OA"
... angle = 0
... speed = "10 rad/s ccw"
... ''')
>>> res = sweep(sc, np.radians([30.0, 90.0, 150.0]))
>>> [round(float(v), 4) for v in res.sliding_velocity("B")]   # dx/dt, x = r cos t + ...
[-0.9137, -1.5, -0.5863]
"""

from __future__ import annotations

import io

import numpy as np

from ..solver.derived import input_torque, largest, pin_rubbing
from ..solver.errorbound import error_bounds
from ..common.errors import TOL, SceneError
from ..solver.kinematics import Motion
from ..solver.compiler import compile_plan
from ..solver.two_given import held_over
from ..scene import Scene, direction_columns
from ..solver.tracking import CHUNK, Domain, Sweeper, array_motion, run_arrays, valid_mask
from ..common.units import ABSURD
from . import sweep_forces
from .link_points import pair_columns, pair_worst

__all__ = [
    "sweep",
    "SweepResult",
    "evaluate_all",
    "angles_ok",
    "sweep_angles",
    "stroke_places",
    "CHUNK",
]


# --------------------------------------------------------------------------- the result


class SweepResult(Motion):
    """Every quantity of ``solve`` as an array over the crank angles the linkage reaches:
    the :class:`~polygon_method.solver.kinematics.Motion` of a sweep.

    ``theta`` holds the requested crank angles (rad, in the order asked) that the crank
    reaches on the scene's branch; the others are counted in ``left_out`` and explained by
    ``limits`` / ``change_points``. ``P, V, A``: point -> (x, y) arrays (m, m/s, m/s^2);
    ``W, Al``: link -> omega, alpha (rad/s, rad/s^2, ccw positive); ``S``: slider ->
    (vs, as, coriolis x, coriolis y); ``conditions``: step index -> condition measure;
    ``rubbing``: pin -> rubbing velocity (m/s); ``input_torque``: N m or None.
    """

    __slots__ = ("rubbing", "input_torque", "requested", "left_out", "domain", "notes")

    def __init__(
        self,
        scene,
        plan,
        theta,
        P,
        V,
        A,
        W,
        Al,
        S,
        conditions,
        rubbing,
        input_torque,
        requested,
        left_out,
        domain: Domain,
        notes=(),
    ):
        Motion.__init__(self, scene, plan, theta, P, V, A, W, Al, S, conditions, None)
        self.rubbing, self.input_torque = rubbing, input_torque
        self.requested, self.left_out, self.domain, self.notes = (
            requested,
            left_out,
            domain,
            tuple(notes),
        )

    @property
    def limits(self) -> tuple:
        """The limit positions of the sweep's domain (where a step stops assembling)."""
        return self.domain.limits

    @property
    def change_points(self) -> tuple:
        """The change points the sweep passed through (two assemblies meeting)."""
        return self.domain.change_points

    @property
    def degrees(self) -> np.ndarray:
        """The crank angles in degrees."""
        return np.degrees(self.theta)

    def __len__(self):
        return len(self.theta)

    @property
    def error_bounds(self):
        """The estimated error bound of every quantity at every angle (arrays; see
        :class:`~polygon_method.solver.errorbound.ErrorBounds`), computed on each call."""
        return error_bounds(self)

    def columns(self, error_bound=False):
        """(name, unit, array) of every quantity, the CSV's columns in order; with
        ``error_bound``, last, ``err_max``: the largest estimated relative error of any
        quantity at that angle (:mod:`polygon_method.solver.errorbound`)."""
        sc = self.scene
        driver = self.plan.steps[0]  # what the parameter is: asked of the driver
        cols = (
            [("theta", "deg", self.degrees)]
            if driver.periodic
            else [(driver.parameter(sc)[1], "m", self.theta)]
        )  # a block driver's place
        for p in sc.point_names:
            (x, y), (vx, vy), (ax, ay) = self.P[p], self.V[p], self.A[p]
            cols += [
                (f"x_{p}", "m", x),
                (f"y_{p}", "m", y),
                (f"vx_{p}", "m/s", vx),
                (f"vy_{p}", "m/s", vy),
                (f"ax_{p}", "m/s^2", ax),
                (f"ay_{p}", "m/s^2", ay),
            ]
        for lk in sc.links:
            cols += [
                (f"omega_{lk.key}", "rad/s", self.W[lk.key]),
                (f"alpha_{lk.key}", "rad/s^2", self.Al[lk.key]),
            ]
        cols += pair_columns(self)  # vmin_BC, ar_CB, at_CB: where the answers ask them
        for s in sc.sliders:
            vs, a_s, cx, cy = self.S[s.key]
            cols += [
                (f"vs_{s.key}", "m/s", vs),
                (f"as_{s.key}", "m/s^2", a_s),
                (f"acx_{s.key}", "m/s^2", cx),
                (f"acy_{s.key}", "m/s^2", cy),
            ]
        for c in sc.cylinders:  # its length, rate of extension and its acceleration
            (bx, by), (rx, ry) = self.P[c.barrel], self.P[c.rod]
            vs, a_s, _, _ = self.S[c.key]
            cols += [
                (f"length_{c.key}", "m", np.hypot(rx - bx, ry - by)),
                (f"vs_{c.key}", "m/s", vs),
                (f"as_{c.key}", "m/s^2", a_s),
                (f"omega_{c.key}", "rad/s", self.W[c.key]),
                (f"alpha_{c.key}", "rad/s^2", self.Al[c.key]),
            ]
        for pin, r in self.rubbing.items():
            cols.append((f"rub_{pin}", "m/s", r))
        if self.input_torque is not None:
            cols.append(("torque", "N m", self.input_torque))
        cols += direction_columns(sc.loads, self.P)  # a load turning with its link
        cols += self.force_columns()
        for st in compile_plan(sc).steps:
            if st.branching:
                cols.append((f"condition_step{st.index + 1}", "1", self.conditions[st.index]))
        if error_bound:
            worst = np.fmax(self.error_bounds.worst, pair_worst(self))  # (vmin_BC ... asked)
            cols.append(("err_max", "1", np.broadcast_to(worst, np.shape(self.theta))))
            got = self._force_rows()
            if got is not None:  # the largest bound of any force (relative to the largest)
                from ..forces.bounds import force_bounds  # lazy, as in `_forces`

                f, rows, _ = got
                at = self if rows is None else sweep_forces.take(self, rows)
                worst = [
                    ("err_forces", "1", np.broadcast_to(force_bounds(at, f).worst, at.theta.shape))
                ]
                cols += worst if rows is None else sweep_forces.spread(worst, rows, len(self))
        return cols

    def _forces(self):
        """The force analysis over the sweep, or None (no masses or gravity; a plan, or a
        position, the analysis does not cover)."""
        got = self._force_rows()
        return None if got is None or got[1] is not None else got[0]

    def _force_rows(self):
        """``(forces, rows, why)`` over the sweep (:func:`.sweep_forces.by_rows`: ``rows``
        None, or the angles where a group's equations are not singular), or None."""
        if not self.scene.has_forces or not len(self.theta):
            return None
        from ..forces import analyse  # lazy: a scene without masses never loads forces/

        return sweep_forces.by_rows(self, analyse)

    def force_columns(self) -> list:
        """The force analysis over the sweep, for a scene with masses or gravity (none for a
        plan the analysis does not cover): the driver's torque with inertia (the negative
        of an engine's turning moment), the shaking force and moment, each guide's normal
        force and the size of each pin force (named ``F_<pin>_<on>_<by>``); for an engine
        (a gas force or an indicator diagram on a slider crank's piston) the piston effort
        (towards the crank), the crank effort and the turning moment (both in the crank's
        sense of rotation). Where a group's equations are exactly singular at some angles
        (:mod:`.sweep_forces`) the cells there are empty, and ``condition_forces`` (0 there,
        else the least condition of the groups' equations) says so row by row."""
        got = self._force_rows()
        if got is None:
            return []
        f, rows, _ = got
        at = self if rows is None else sweep_forces.take(self, rows)
        n = np.shape(at.theta)
        cols = [
            ("torque_inertia", "N m", np.broadcast_to(f.input_torque, n))
            if f.driver in ("crank", "wheel")  # (a driving wheel's: the torque on it)
            else ("force_inertia", "N", np.broadcast_to(f.input_torque, n))
        ]
        if f.second_crank is not None:  # a second crank's torque, a second collar's force
            two = ("force2_inertia", "N") if f.second_crank.startswith("block ") else None
            cols.append((*(two or ("torque2_inertia", "N m")), np.broadcast_to(f.second_torque, n)))
        cols += [
            ("shake_x", "N", np.broadcast_to(f.shaking_force[0], n)),
            ("shake_y", "N", np.broadcast_to(f.shaking_force[1], n)),
            ("shake_moment", "N m", np.broadcast_to(f.shaking_moment, n)),
        ]
        cols += [(f"N_{g.point}", "N", np.broadcast_to(g.normal, n)) for g in f.guides]
        from ..forces import holding_columns  # lazy, as below: a fixed gear's holding
        from ..forces.grip import margins  # lazy, as below: a friction drive's grip

        cols += [(k, u, np.broadcast_to(v, n)) for k, u, v, _ in margins(f) + holding_columns(f)]
        cols += [
            (
                f"F_{p.point}_{p.on}_{p.by}".replace(" ", ""),
                "N",
                np.broadcast_to(np.hypot(*p.force), n),
            )
            for p in f.pins
        ]
        from ..forces.engine import cylinder_efforts, efforts  # lazy, as in `_forces`
        from ..forces.cylinder import given_forces

        cols += [(f"F_{k}", "N", np.broadcast_to(v, n)) for k, v in given_forces(f)]

        e = efforts(self.scene, self.plan, at.P, f)
        if e is not None:  # an engine: the turning-moment diagram and its efforts
            cols += [
                ("piston_effort", "N", np.broadcast_to(e.F_P, n)),
                ("crank_effort", "N", np.broadcast_to(e.F_T, n)),
                ("turning_moment", "N m", np.broadcast_to(e.T, n)),
            ]
        es = cylinder_efforts(self.scene, self.plan, at.P, f) if e is None else ()
        for c in es:  # several cylinders on one crank: each one's, then their sum
            cols += [
                (f"piston_effort_{c.piston}", "N", np.broadcast_to(c.F_P, n)),
                (f"crank_effort_{c.piston}", "N", np.broadcast_to(c.F_T, n)),
            ]
        if es:
            cols.append(("turning_moment", "N m", np.broadcast_to(sum(c.T for c in es), n)))
        cols += rod_columns(self.scene, self.plan, at, n)
        if rows is None:
            return cols
        whole = len(self)
        return sweep_forces.spread(cols, rows, whole) + [
            ("condition_forces", "1", sweep_forces.conditions(f, rows, whole))
        ]

    def to_csv(self, error_bound=False) -> str:
        """One row per crank angle; the header names each quantity with its unit."""
        cols = self.columns(error_bound)
        buf = io.StringIO()
        buf.write(",".join(f"{n} [{u}]" for n, u, _ in cols) + "\n")
        if len(self.theta):
            if any(np.ma.is_masked(a) for _, _, a in cols):  # forces not determined: empty
                buf.write(sweep_forces.csv_rows([a for _, _, a in cols]))
                return buf.getvalue()
            data = np.column_stack([np.asarray(a, dtype=float) for _, _, a in cols])
            np.savetxt(buf, data, delimiter=",", fmt="%.17g")  # full precision
        return buf.getvalue()


def rod_columns(scene, plan, at, n) -> list:
    """A connecting rod's correction couple and its torque on the crank shaft over the
    sweep (``forces.rod``: the equivalent dynamical system's; none without such a rod)."""
    from ..forces.rod import correction_arrays  # lazy, as the other force columns

    got = correction_arrays(scene, plan, at.W, at.Al, n[0])
    if got is None:
        return []
    cols = [("correction_couple", "N m", got[0])]
    return cols if got[1] is None else cols + [("correction_torque", "N m", got[1])]


def rubbing_arrays(plan, W, n):
    """The rubbing velocity at every pin over a sweep of ``n`` positions (the largest over the pairs
    of bodies each pin joins), from the omegas ``W``."""
    radii = plan.dims.radii
    return {
        point: np.broadcast_to(largest(values), (n,)) if values else np.zeros(n)
        for point, values in pin_rubbing(plan, W, radii).items()
    }


def torque_array(scene, V, W, omega, n, S=None, P=None):
    """The input torque over a sweep (``omega`` the crank's; where the motion is given
    on another quantity and held, the crank's speed at each angle, ``W`` of the crank;
    ``S`` the sliding rates, for a passive cylinder's given force)."""
    if scene.input.given is not None:
        omega = W[scene.link(scene.input.crank).key]
    t = input_torque(scene, V, W, omega, S, P)
    return None if t is None else np.broadcast_to(t, (n,)) + 0.0


def angles_ok(sw: Sweeper, theta):
    """Mask of the requested angles the crank reaches on the scene's branch."""
    if sw.domain.full_turn and not sw.domain.limits:
        return None
    _, ok = sw.domain.map(theta)
    return ok


def evaluate_all(sw: Sweeper, theta, chunk):
    """Evaluate ``theta`` (all reachable) in chunks; yields (slice, Frame)."""
    n = len(theta)
    for s in range(0, n, chunk):
        th = theta[s : s + chunk]
        fr = sw.evaluate(th)
        for idx, h in sw.near_change_points(th):
            _patch(fr, sw.richardson(th[idx], h), idx)
        if sw.plan.scene.input.found_from:  # two inputs' speeds found elsewhere: held?
            held_over(sw.plan.scene, fr)
        yield slice(s, min(s + chunk, n)), fr


def _patch(fr: Motion, fix: Motion, idx):
    def put(arr, new):
        if arr.flags.writeable:  # read-only: a constant (ground point, fixed link)
            arr[idx] = new

    for k in fr.P:
        for j in (0, 1):
            put(fr.P[k][j], fix.P[k][j])
    for k in fr.V:
        for j in (0, 1):
            put(fr.V[k][j], fix.V[k][j])
            put(fr.A[k][j], fix.A[k][j])
    for k in fr.W:
        put(fr.W[k], fix.W[k])
        put(fr.Al[k], fix.Al[k])
    for k, v in fr.S.items():
        for j in range(len(v)):
            put(v[j], fix.S[k][j])
    fr.bad[idx] = False
    for i in fr.cond:  # the construction is indeterminate here; the values come from both sides
        if fr.cond[i].flags.writeable:
            fr.cond[i][idx] = np.maximum(fr.cond[i][idx], TOL.singular)


def stroke_places(scene: Scene, n: int = 361):
    """``n`` places of a driving block (m, along its guide), evenly from one end of its
    travel to the other: its stated stroke, both ends included; or, where the mechanism
    stops assembling (a singular end: :class:`~polygon_method.solver.tracking.Sweeper`), the
    middles of ``n`` equal parts of its travel."""
    sw = Sweeper(scene)
    dom = sw.domain
    if all(lp.step == sw.driver.label for lp in dom.limits):  # the stated stroke's ends
        return np.linspace(dom.lo, dom.hi, n) if n > 1 else np.array([dom.lo])
    # an end where the mechanism stops assembling is singular: the middles of n parts
    return dom.lo + (dom.hi - dom.lo) * (np.arange(n) + 0.5) / n


def sweep_angles(angles, turns=1):
    """The crank angles of a sweep (radians) as an array: every degree of ``turns`` turns (the
    motion's period) when None; anything that is not numbers is refused in one line."""
    if angles is None:
        return np.radians(np.arange(360.0 * turns))
    try:
        th = np.atleast_1d(np.asarray(angles, dtype=float))
    except (TypeError, ValueError):
        raise SceneError(
            f"the crank angles must be numbers (radians), got {str(angles)[:60]!r}"
        ) from None
    if th.ndim != 1:
        raise SceneError("the crank angles must be a 1-D sequence")
    if not np.isfinite(th).all():
        raise SceneError("the crank angles must be finite numbers")
    if len(th) and np.abs(th).max() > ABSURD["angle"]:  # cos(1e300) is rounding, not a turn
        raise SceneError(
            f"the crank angles must be within +-{ABSURD['angle']:g} rad, got {np.abs(th).max():g}"
        )
    return th


def sweep(scene: Scene, angles=None, *, chunk: int = CHUNK) -> SweepResult:
    """Every quantity of ``solve`` at each crank angle in ``angles`` (rad; default every
    degree of a turn, or of the turns after which the motion repeats), in one pass per
    chunk of angles.

    Angles the crank cannot reach on the scene's branch (beyond a limit position) are left
    out and reported (``left_out``, ``limits``), never filled with NaN or another branch.
    """
    if angles is None and not compile_plan(scene).steps[0].periodic:
        angles = stroke_places(scene)  # a driving block: its travel
    if isinstance(chunk, bool) or not isinstance(chunk, (int, np.integer)) or chunk < 1:
        raise SceneError(f"chunk = {chunk!r}: a whole number of crank angles, 1 or more")
    sw = Sweeper(scene)
    th_req = sweep_angles(angles, sw.domain.turns)
    sw.stated_branch()
    plan = sw.plan
    ok = angles_ok(sw, th_req)
    th = th_req if ok is None else th_req[ok]
    n = len(th)
    fr = None
    store = None
    for sl, part in evaluate_all(sw, th, chunk):
        if sl.start == 0 and sl.stop == n:
            fr = part
        else:  # copy chunk by chunk into one block, so that the chunks' memory is reused
            if store is None:
                store = _Store(th, part)
            store.put(sl, part)
    if store is not None:
        fr = store.frame()
    elif fr is None:
        fr = run_arrays(plan, th, sw.omega, sw.alpha)
    bad = valid_mask(fr, plan)
    notes = list(sw.domain.notes)
    if bad.any():
        notes.append(
            f"{int(bad.sum())} crank angle(s) at a singular position (a toggle "
            "where the velocity is indeterminate) were left out"
        )
    # each step places its point at its links' lengths; only where values were taken from
    # both sides of a change point (or a step was masked) could a row fail to close
    open_ = unclosed(scene, fr) & ~bad if sw.domain.change_points else bad & False
    if open_.any():
        notes.append(
            f"{int(open_.sum())} crank angle(s) where the links would not keep their "
            "lengths (an indeterminate position) were left out"
        )
        bad |= open_
    if bad.any():
        fr = select(fr, ~bad)
        th = th[~bad]
    n = len(th)
    rub = rubbing_arrays(plan, fr.W, n)
    torque = torque_array(scene, fr.V, fr.W, sw.omega, n, fr.S, fr.P)
    return SweepResult(
        scene,
        plan,
        th,
        fr.P,
        fr.V,
        fr.A,
        fr.W,
        fr.Al,
        fr.S,
        fr.cond,
        rub,
        torque,
        len(th_req),
        len(th_req) - n,
        sw.domain,
        tuple(notes),
    )


def unclosed(scene, fr: Motion):
    """Mask of the rows where some link does not keep its length (beyond rounding: the
    squared length within 2e-9 of its own): every row a sweep keeps is a possible position
    of the mechanism."""
    bad = np.zeros(len(fr.theta), dtype=bool)
    with np.errstate(invalid="ignore", over="ignore"):
        for lk in scene.links:
            if lk.p in scene.ground and lk.q in scene.ground:
                continue
            (px, py), (qx, qy) = fr.P[lk.p], fr.P[lk.q]
            dx, dy = qx - px, qy - py
            L2 = lk.length * lk.length
            bad |= ~(np.abs(dx * dx + dy * dy - L2) <= 2e-9 * L2)
    return bad


def _constant(v) -> bool:
    """A column that is one number for every angle (a zero-stride view)."""
    return v.strides == (0,)


def _const(v, n):
    return np.broadcast_to(v[0] if len(v) else np.float64(0.0), (n,))


class _Store:
    """One block of rows (one allocation) that chunk frames are copied into; constant
    columns (ground points, fixed links, the crank's speed) get no row: they stay one
    number, as a zero-stride view."""

    def __init__(self, theta, first: Motion):
        self.theta, self.first = theta, first
        keys = []
        for k in first.P:
            keys += [("P", k, 0), ("P", k, 1)]
        for k in first.V:
            keys += [("V", k, 0), ("V", k, 1), ("A", k, 0), ("A", k, 1)]
        keys += [("W", k, None) for k in first.W] + [("Al", k, None) for k in first.Al]
        for k, v in first.S.items():
            keys += [("S", k, j) for j in range(len(v))]
        keys += [("cond", i, None) for i in first.cond]
        n = len(theta)
        self.constants = {}
        self.keys = []
        for key in keys:
            v = self._get(first, key)
            if _constant(v):
                self.constants[key] = _const(v, n)
            else:
                self.keys.append(key)
        self.block = np.empty((len(self.keys), n))
        self.bad = np.zeros(n, dtype=bool)

    @staticmethod
    def _get(fr, key):
        kind, k, j = key
        v = getattr(fr, kind)[k]
        return v if j is None else v[j]

    def put(self, sl, fr: Motion):
        for r, key in enumerate(self.keys):
            self.block[r, sl] = self._get(fr, key)
        self.bad[sl] = fr.bad

    def frame(self) -> Motion:
        rows = dict(zip(self.keys, self.block))
        rows.update(self.constants)
        f = self.first
        P = {k: (rows[("P", k, 0)], rows[("P", k, 1)]) for k in f.P}
        V = {k: (rows[("V", k, 0)], rows[("V", k, 1)]) for k in f.V}
        A = {k: (rows[("A", k, 0)], rows[("A", k, 1)]) for k in f.A}
        W = {k: rows[("W", k, None)] for k in f.W}
        Al = {k: rows[("Al", k, None)] for k in f.Al}
        S = {k: tuple(rows[("S", k, j)] for j in range(len(v))) for k, v in f.S.items()}
        cond = {i: rows[("cond", i, None)] for i in f.cond}
        return array_motion(self.theta, P, V, A, W, Al, S, cond, self.bad)


def select(fr: Motion, keep) -> Motion:
    """The motion at the angles ``keep`` (a mask); constant columns stay constants."""
    m = int(np.count_nonzero(keep))

    def take(v):
        return _const(v, m) if _constant(v) else v[keep]

    two = lambda d: {k: (take(v[0]), take(v[1])) for k, v in d.items()}  # noqa: E731
    return array_motion(
        fr.theta[keep],
        two(fr.P),
        two(fr.V),
        two(fr.A),
        {k: take(v) for k, v in fr.W.items()},
        {k: take(v) for k, v in fr.Al.items()},
        {k: tuple(take(a) for a in v) for k, v in fr.S.items()},
        {i: take(c) for i, c in fr.cond.items()},
        fr.bad[keep],
    )
