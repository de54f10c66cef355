"""The kinematic relations every step builds on, each written once, as plain functions on
floats or numpy arrays (the steps' one-instant and array roads both call them):

* two points of one rigid body: ``v_T - v_O = omega perp(r)`` and
  ``a_T - a_O = -omega^2 r + alpha perp(r)``, with ``r = T - O``;
* a point sliding along a guide that turns at ``omega``: the Coriolis component
  ``2 omega vs perp(u)`` of its acceleration (``u`` the unit vector of the guide).

``perp(x, y) = (-y, x)``, the vector turned a quarter turn counter-clockwise.

>>> rigid_velocity(0.05, 0.0, 10.0)          # r along +x, 10 rad/s ccw: 0.5 m/s up
(-0.0, 0.5)
>>> rigid_acceleration(0.05, 0.0, 10.0, 0.0)  # towards O: omega^2 r = 5 m/s^2
(-5.0, 0.0)
>>> coriolis(2.0, 0.5, 1.0, 0.0)             # 2 x 2 rad/s x 0.5 m/s = 2 m/s^2, across u
(-0.0, 2.0)
"""

__all__ = ["rigid_velocity", "rigid_acceleration", "coriolis"]


def rigid_velocity(rx, ry, omega):
    """v_T - v_O = omega perp(r), r = T - O."""
    return -omega * ry, omega * rx


def rigid_acceleration(rx, ry, omega, alpha):
    """a_T - a_O = -omega^2 r + alpha perp(r)."""
    k = omega * omega
    return -k * rx - alpha * ry, -k * ry + alpha * rx


def coriolis(w, vs, ux, uy):
    """2 omega_guide vs perp(u): the Coriolis component of a point sliding at ``vs`` along
    a guide of unit direction ``u`` that turns at ``w``."""
    return -2 * w * vs * uy, 2 * w * vs * ux
