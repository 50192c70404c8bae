"""The gyroscope as a detector of motion (Eq. 11.29): single-gimbal rate gyros.

A rotor of angular momentum H = J spin is carried in a gimbal whose axis (the
output axis) is perpendicular to the spin axis; the case turns at Omega about
the input axis, perpendicular to both. Eq. 11.29 says the gimbal bearings must
supply the moment Q = J psidot phidot = H Omega about the output axis to keep
the spin axis from turning. Let a torsion spring k and a damper c about the
output axis supply it instead, the gimbal (with rotor) having inertia I_g
about that axis; for small gimbal angles theta

    I_g thetaddot + c thetadot + k theta = H Omega

(the full gyroscopic moment is H Omega cos(theta): the tilted spin axis sees
only the component of the input rate across it). Hence

- spring-restrained rate gyro: steady theta = H Omega / k (small angles),
  sensitivity theta / Omega = H / k, natural frequency sqrt(k / I_g),
  damping ratio c / (2 sqrt(k I_g));
- rate-integrating gyro (damper only): steady thetadot = H Omega / c, so
  theta = (H / c) * integral of Omega dt, the angle turned; time constant I_g / c;
- rigid restraint (neither): the bearings' moment H Omega (Eq. 11.29).

(Thomson, *Introduction to Space Dynamics*, ch. 5; Cannon, *Dynamics of
Physical Systems*, the rate gyro.)

The formulas are written once for floats and formula trees (core/generic.py):
the kind calls them with its symbols to write its steps.
"""

from __future__ import annotations

import math

from ..core.generic import V, sqrt


def steady_deflection(H: V, rate: V, k: V) -> V:
    """theta = H Omega / k (small angles)."""
    return H * rate / k


def gimbal_rate(H: V, rate: V, c: V) -> V:
    """thetadot = H Omega / c (rate-integrating, steady)."""
    return H * rate / c


def rate_from_moment(H: V, moment: V) -> V:
    """Omega = M / H (Eq. 11.29 solved for the input rate)."""
    return moment / H


def natural_frequency(k: V, I_g: V) -> V:
    """omega_n = sqrt(k / I_g)."""
    return sqrt(k / I_g)


def damping_ratio(c: V, k: V, I_g: V) -> V:
    """zeta = c / (2 sqrt(k I_g))."""
    return c / (2 * sqrt(k * I_g))


def large_angle_deflection(H: float, rate: float, k: float) -> float:
    """The root of k theta = H Omega cos(theta) in (-pi/2, pi/2) (bisection; exact steady state)."""
    lo, hi = -math.pi / 2, math.pi / 2
    f = lambda t: k * t - H * rate * math.cos(t)  # noqa: E731 - increasing on the interval
    for _ in range(200):
        mid = (lo + hi) / 2
        if f(mid) > 0:
            hi = mid
        else:
            lo = mid
        if hi - lo < 1e-15:
            break
    return (lo + hi) / 2
