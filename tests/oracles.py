"""Float formulas the kinds write as trees, written here independently as oracles for the
tests (the kinds' steps are evaluated from their trees; these compute the same on floats)."""

from __future__ import annotations

import math


def gyroscopic_moment(J: float, I: float, spin: float, precession: float, theta: float) -> float:
    """Moment on the rotor along n = K x k / sin(theta): Omega sin th (J omega_z - I Omega cos th)
    (Meriam Eq. 11.13 with thetaddot = 0)."""
    cos = math.cos(theta)
    return precession * math.sin(theta) * (J * (spin + precession * cos) - I * precession * cos)


def tilt_rate_uniform(drop: float, speed: float, drop_length: float, spacing: float) -> float:
    """Tilt rate of an axle when one wheel drops ``drop`` evenly over ``drop_length`` of track
    at ``speed``: the drop takes t = s / v, the axle turns through drop / L in it."""
    return drop * speed / (drop_length * spacing)


def tilt_rate_harmonic(drop: float, drop_time: float, spacing: float) -> float:
    """Greatest tilt rate when one wheel falls ``drop`` and rises again in ``drop_time`` with
    simple harmonic motion: y = (drop / 2)(1 - cos(2 pi t / T)), so y' peaks at pi drop / T."""
    return math.pi * drop / (drop_time * spacing)


def counterweight_offset(moment: float, counterweight: float, g: float) -> float:
    """How far the block moves from the balance point so its weight gives the moment: M / (m_c g)."""
    return abs(moment) / (counterweight * g)


# ---- the precession of the equinoxes (kinds/earth_precession.py) ----------------------

def tidal_from_period(period: float, mass_ratio: float) -> float:
    """G M_b / a^3 from the orbital period and q = M_b / M: n^2 q / (1 + q) (Kepler III)."""
    n = 2 * math.pi / period
    return n * n * mass_ratio / (1 + mass_ratio)


def node_factor(inclination: float) -> float:
    """(1 - (3/2) sin^2 i): the torque of an orbit at i, averaged over its turning node."""
    return 1 - 1.5 * math.sin(inclination) ** 2


def eccentricity_factor(e: float) -> float:
    """(1 - e^2)^(-3/2): <a^3 / r^3> over a Kepler orbit (time average)."""
    return (1 - e * e) ** -1.5


def precession_rate(tidal: float, e: float, H: float, obliquity: float, omega: float,
                    inclination: float = 0.0) -> float:
    """Rate at which the spin axis turns about the orbit normal, rad/s (retrograde positive):
    (3/2) (G M_b / a^3) (1 - e^2)^(-3/2) H cos(eps) (1 - (3/2) sin^2 i) / omega."""
    return (1.5 * tidal * eccentricity_factor(e) * H * math.cos(obliquity)
            * node_factor(inclination) / omega)


# ---- Euler angles (kinds/euler_angles.py) ----------------------------------------------

def fixed_accel_zxz(phi: float, theta: float, rates: tuple[float, float, float],
                    accels: tuple[float, float, float]) -> tuple[float, float, float]:
    """(alpha_X, alpha_Y, alpha_Z): the fixed components of omega differentiated,
    omega_X = thetadot c(ph) + psidot s(th) s(ph), omega_Y = thetadot s(ph) - psidot s(th) c(ph),
    omega_Z = phidot + psidot c(th)."""
    p1, p2, p3 = rates
    a1, a2, a3 = accels
    st, ct, sf, cf = math.sin(theta), math.cos(theta), math.sin(phi), math.cos(phi)
    return (a2 * cf - p2 * p1 * sf + a3 * st * sf + p3 * p2 * ct * sf + p3 * p1 * st * cf,
            a2 * sf + p2 * p1 * cf - a3 * st * cf - p3 * p2 * ct * cf + p3 * p1 * st * sf,
            a1 + a3 * ct - p3 * p2 * st)


# ---- the released top (kinds/released_top.py) ------------------------------------------

def released_u1(I: float, J: float, mgl: float, theta0: float, omega_z: float) -> float:
    """u1 = gamma^2/(2a) - sqrt(gamma^4/(4a^2) - gamma^2/a cos(theta0) + 1) (Eq. 11.25), as
    printed but for the root: written without cancellation, u1 = c / q of the quadratic
    a u^2 - gamma^2 u + gamma^2 u0 - a = 0 (Eq. 11.24 corrected)."""
    a = 2 * mgl / I
    g2 = (J * omega_z / I) ** 2
    b, c = -g2, g2 * math.cos(theta0) - a
    q = -0.5 * (b + math.copysign(math.sqrt(max(b * b - 4 * a * c, 0.0)), b))
    return min(q / a, c / q)
