"""The gyrocompass: a rotor with its spin axis held horizontal, free to turn about the vertical.

Derivation (angular momentum about the local vertical U, which turns with the
Earth at Omega_E = Omega (cos(lat) N + sin(lat) U); E, N, U east, north, up).
The axis points at azimuth alpha east of north, s = cos(alpha) N + sin(alpha) E,
and the rotor's spin angular momentum is H s, H = J spin. In inertial space

    d/dt (H_total . U) = M_U + H_total . (Omega_E x U),   Omega_E x U = Omega cos(lat) E,

and H_total . U = I_v (Omega sin(lat) - alphadot) (turning east of north is a
turn about -U). With no moment about the vertical (M_U = 0, frictionless),

    I_v alphaddot = -H Omega cos(lat) sin(alpha)

up to terms of order I Omega^2 (Omega^2 = 5e-9 s^-2). This is a pendulum:
alpha = 0 (the spin vector pointing north) is stable, the moment about the
vertical that turns the axis back toward north is H Omega cos(lat) sin(alpha),
and small swings about north have the period

    T = 2 pi sqrt(I_v / (H Omega cos(lat))).

(Kibble & Berkshire, *Classical Mechanics*, 5th ed., problem 9.15; Cannon,
*Dynamics of Physical Systems*, the Foucault gyrocompass.) At the poles
cos(lat) = 0: the Earth's rate has no horizontal component and there is no
north-seeking moment at all.

The functions are written once for floats and formula trees (core/generic.py):
the kind calls them with its symbols to write its steps.
"""

from __future__ import annotations

from ..core.generic import V, cos, pi_like, sin, sqrt

EARTH_RATE = 7.292115e-5  # rad/s, IERS Conventions (2010), nominal mean angular velocity


def directive_stiffness(H: V, earth_rate: V, latitude: V) -> V:
    """D = H Omega cos(lat): north-seeking moment per radian of small deviation, N m/rad."""
    return H * earth_rate * cos(latitude)


def north_seeking_moment(stiffness: V, deviation: V) -> V:
    """D sin(alpha): moment about the vertical turning the axis back to north."""
    return stiffness * sin(deviation)


def period(I_v: V, stiffness: V) -> V:
    """2 pi sqrt(I_v / D): period of small swings about north."""
    return 2 * pi_like(I_v, stiffness) * sqrt(I_v / stiffness)
