"""Steady precession: the approximation and the motion of the centre of mass (floats, SI).

Chapter 11, Gyroscopic Motion, Eq. 11.13 with thetaddot = 0 gives the exact
rates; the quantities here follow from a rate once it is known.
"""

from __future__ import annotations

import math

from ..core.generic import V


def precession_approx(D: V, J: V, axial: V) -> V:
    """The gyroscopic approximation Omega = D / (J omega) = m g l / (J omega).

    Eq. 11.13 with thetaddot = 0 divided by J omega_z phidot reads
    1 - I phidot cos(theta) / (J omega_z) = D / (J omega_z phidot): dropping the
    I term (a fast spin, or theta = 90 deg where it is exact) leaves this.
    """
    return D / (J * axial)


def cg_radius(l: float, theta: float) -> float:
    """Radius of the centre of mass's horizontal circle: l sin(theta)."""
    return l * math.sin(theta)


def cg_speed(l: float, theta: float, precession: float) -> float:
    """Speed of the centre of mass on its circle: l sin(theta) |phidot|."""
    return cg_radius(l, theta) * abs(precession)


def cg_acceleration(l: float, theta: float, precession: float) -> float:
    """Centripetal acceleration of the centre of mass: l sin(theta) phidot^2, toward the axis."""
    return cg_radius(l, theta) * precession * precession


def pivot_force(m: float, g: float, l: float, theta: float,
                precession: float) -> tuple[float, float, float]:
    """The support's force on the body: (vertical up, horizontal toward the axis, magnitude).

    Newton's second law for the centre of mass, F + m g (down) = m a_G, with a_G
    the centripetal l sin(theta) phidot^2 toward the precession axis (theta and
    phidot constant): F_vertical = m g, F_horizontal = m l sin(theta) phidot^2.
    """
    vertical = m * g
    horizontal = m * cg_acceleration(l, theta, precession)
    return vertical, horizontal, math.hypot(vertical, horizontal)


def precession_period(precession: float) -> float:
    """Time for one turn of the precession: 2 pi / |phidot|."""
    return 2 * math.pi / abs(precession)
