"""The directional gyro on the rotating Earth: apparent drift, latitude nut, transport wander.

Chapter 11, section 11.3 (Fig. 11-13): a gyroscope in gimbals that feels no moment
"remains fixed in orientation relative to an inertial reference frame". A
directional gyro (DG, DI) holds its spin axis horizontal; with no moment about the
vertical gimbal axis its azimuth is fixed in inertial space. North is not: the local
level frame (east, north, up) turns about the local vertical U at the vertical
component of its own angular velocity.

- The Earth turns at Omega_E (the sidereal rate, 15.041 deg/h) about the polar axis,
  Omega_E (cos(lambda) N + sin(lambda) U) at latitude lambda: north turns about U at
  Omega_E sin(lambda), anticlockwise seen from above in the northern hemisphere
  (lambda > 0), clockwise in the southern.
- A craft moving east at v_E along its parallel (radius R cos(lambda)) changes its
  longitude at l' = v_E / (R cos(lambda)), a rotation about the polar axis too, whose
  vertical part is l' sin(lambda) = v_E tan(lambda) / R (northward motion turns the
  frame about the east axis, which has no vertical part). On a sphere whose arc
  minute is one nautical mile (R = 6366.7 km) this is the pilots' (GS / 60) tan(lat)
  deg/h with GS in knots, and over a change of longitude dl it is dl sin(lat).

Relative to north the spin axis therefore turns the other way: **drift to the right**
(clockwise seen from above) at (Omega_E + l') sin(lambda) in the northern hemisphere,
to the left in the southern. The heading the instrument reads is measured from the
spin axis, so it *decreases* while the axis drifts right.

The latitude nut: a small weight on the inner gimbal gives a moment M about the
horizontal gimbal axis; by Eq. 11.29 (Q_theta = J phidot psidot, read for phidot) the
spin axis precesses about the vertical at M / H. Set for latitude lambda_n it is sized
M = H Omega_E sin(lambda_n), and it turns the axis left (anticlockwise from above) at
Omega_E sin(lambda_n), cancelling the Earth's drift at that latitude.

Signs here: a drift is positive to the right (clockwise seen from above); latitudes
north positive; an eastward speed positive. The formulas are written once for floats and
formula trees (core/generic.py): the kind calls them with its symbols to write its steps.
"""

from __future__ import annotations

import math

from ..core.generic import V, cos, sin

#: the Earth's sidereal rate, rad/s (360 deg in 23 h 56 min 4.1 s: 15.041 deg/h)
EARTH_RATE = 7.292115e-5
#: the radius of a sphere whose arc minute is one nautical mile, m (1852 m * 60 * 180 / pi)
NAUTICAL_EARTH_RADIUS = 1852.0 * 60 * 180 / math.pi


def earth_rate_drift(earth_rate: V, latitude: V) -> V:
    """Apparent drift from the Earth's rotation, Omega_E sin(lambda), right positive."""
    return earth_rate * sin(latitude)


def longitude_rate(east_speed: V, radius: V, latitude: V) -> V:
    """The craft's rate of change of longitude, v_E / (R cos(lambda)), east positive."""
    return east_speed / (radius * cos(latitude))


def transport_wander(longitude_change: V, latitude: V) -> V:
    """Drift from moving east, l' sin(lambda) = v_E tan(lambda) / R, right positive: a rate
    from the rate of change of longitude l', an angle from a whole change of longitude."""
    return longitude_change * sin(latitude)


def nut_correction(earth_rate: V, nut_latitude: V) -> V:
    """The latitude nut's precession, -Omega_E sin(lambda_n) (left for a northern setting)."""
    return -earth_rate * sin(nut_latitude)


def nut_moment(H: V, earth_rate: V, nut_latitude: V) -> V:
    """The moment the nut must apply, H Omega_E sin(lambda_n) (Eq. 11.29: rate = M / H)."""
    return H * earth_rate * sin(nut_latitude)


def heading_after(initial: float, heading_change: float, drift_angle: float) -> float:
    """The reading after the axis drifted ``drift_angle`` (right positive) while the craft's
    true heading changed by ``heading_change``, in [0, 2 pi)."""
    return (initial + heading_change - drift_angle) % (2 * math.pi)
