"""Whether a steady motion lasts: the linearised equations about it (floats, SI).

Both steady motions treated here belong to a family of steady motions (the heavy
top's steady precessions, the disk's steady rolling circles) and their linearised
equations have the same shape: with x the small change of the tilt angle,

    x'' + k x = 0,

plus neutral directions (zero eigenvalues) along the family itself. A perturbation
that changes the integrals of the motion (the top's p_phi, p_psi and energy; the
disk's rates) moves the body to a neighbouring steady motion with a slightly
different precession rate, about which the same x'' + k x = 0 holds: the angles
then drift apart linearly in time (the zero eigenvalues), but the tilt stays within
O(perturbation) of its steady value. So k decides:

    k > 0  stable: the tilt oscillates at sqrt(k) rad/s (small nutation / wobble);
    k < 0  unstable: the tilt leaves the steady value as exp(s t), s = sqrt(-k) 1/s;
    k = 0  neutral to first order (only for degenerate data).

**Heavy symmetric top about a fixed point** (Chapter 11, Eqs. 11.13-11.14). With the
integrals P1 = p_phi = I phidot sin^2 th + J omega_z cos th and P2 = p_psi = J omega_z
fixed, Eq. 11.13's first line reads I thetaddot = F(theta) with
phidot(theta) = (P1 - P2 cos th) / (I sin^2 th) (Eq. 11.16):

    F = I phidot^2 sin th cos th - P2 phidot sin th + m g l sin th.

Using d phidot / d theta = P2 / (I sin th) - 2 phidot cos th / sin th and the
steady-precession condition m g l = P2 phidot - I phidot^2 cos th (Eq. 11.13 with
thetaddot = 0), F'(theta0) simplifies to

    -I k = F' = -(P2 - 2 I phidot cos th)^2 / I - I phidot^2 sin^2 th,

    k = ((J omega_z - 2 I phidot cos th) / I)^2 + phidot^2 sin^2 th  >= 0,

which is U_eff''(theta0) / I for the effective potential
U_eff = (P1 - P2 cos th)^2 / (2 I sin^2 th) + m g l cos th (Goldstein, Classical
Mechanics, Sec. 5.7). m g l does not appear: every steady precession of a heavy
symmetric top about a fixed point is a minimum of U_eff and stable, whichever root,
theta above or below the horizontal; k = 0 needs phidot = 0 and omega_z = 0, a body
at rest (possible only with no moment). For a fast top k -> (J omega_z / I)^2, the
square of the chapter's nutation frequency.

**Disk rolling without slipping** on a horizontal plane (rolling_disk, free). Radius
r, mass m, I_G (= A) about a diameter and J (= C) about the axis, both at the centre
G; tilt beta of the disk's plane from the vertical, heading phi, spin psidot
relative to the frame turning with phi and beta; omega = phidot K - betadot e_t +
psidot k (e_t the horizontal tangent, k the axis). Rolling, v_G = omega x r u (u from
the contact point to G), in Newton's law m a_G = F - m g K and the moment equation
dH_G/dt = (-r u) x F (Euler's equations about G), with F eliminated, give

    (A + m r^2) beta''   = (C - A + m r^2) phidot^2 sin b cos b
                           + (C + m r^2) phidot psidot cos b + m g r sin b,
    phidot'  = betadot (2 A phidot sin b - C omega_z) / (A cos b),
    omega_z' = -betadot m r^2 phidot cos b / (C + m r^2),

omega_z = psidot + phidot sin b the axial rate. Steady rolling is betadot = 0 with
the first right-hand side zero (it is the rolling_disk kind's moment equation with
psidot = -Omega R / r). Write the first as beta'' = f(beta, phidot, psidot); the last
two are betadot times functions of the state, so at a steady state, to first order,
phidot' = g1 betadot and psidot' = g2 betadot with g1, g2 constants. Differentiating
the first once more, betadot'' = (f_beta + f_phidot g1 + f_psidot g2) betadot = -k
betadot, and, written with omega_z = psidot + phidot sin b,

    A (A + m r^2) k = C (C + m r^2) omega_z^2 - A (3 C + m r^2) phidot omega_z sin b
                      + A^2 phidot^2 (1 + 2 sin^2 b) + A m r^2 phidot^2 cos^2 b
                      - A m g r cos b.

Upright rolling in a straight line (phidot = 0, b = 0) gives the classic condition
omega_z^2 > m g r A / (C (C + m r^2)) (Routh, Advanced Rigid Dynamics, Sec. 244;
for a thin uniform disk v^2 > g r / 3, for a hoop v^2 > g r / 4). The elimination
and the derivatives were done with a computer algebra system; the formula is tested
against Newton-Euler integrations of the rolling disk (axis, angular velocity and
centre in world axes, contact force solved from the rolling constraint each step) in
tests/test_stability.py, which match the growth rate to a few parts in a million.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from ..core.generic import V, sqrt

STABLE, UNSTABLE, NEUTRAL = "stable", "unstable", "neutral"
NEUTRAL_TOLERANCE = 1e-12   # |k| below this fraction of its largest term counts as zero


@dataclass(frozen=True)
class Stability:
    """The verdict from x'' + k x = 0: the word, k (1/s^2), the growth rate of the
    unstable mode (1/s, 0 when stable) and the small-oscillation frequency (rad/s, 0
    when unstable)."""

    word: str
    k: float
    growth_rate: float
    frequency: float


def verdict(k: float, scale: float) -> Stability:
    """Classify k; ``scale`` is the size of its largest term (for the neutral band).

    OverflowError when k or the scale is not a finite number (extreme data)."""
    if not (math.isfinite(k) and math.isfinite(scale)):
        raise OverflowError("k of the linearised equations is not a finite number")
    if abs(k) <= NEUTRAL_TOLERANCE * abs(scale):
        return Stability(NEUTRAL, k, 0.0, 0.0)
    if k > 0:
        return Stability(STABLE, k, 0.0, math.sqrt(k))
    return Stability(UNSTABLE, k, math.sqrt(-k), 0.0)


def top_terms(I: float, J: float, theta: float, precession: float,
              axial_rate: float) -> tuple[float, float]:
    """The two squares of the top's k: ((J w_z - 2 I phidot cos th) / I)^2, phidot^2 sin^2 th."""
    first = (J * axial_rate - 2 * I * precession * math.cos(theta)) / I
    second = precession * math.sin(theta)
    return first * first, second * second


def top_steady_precession(I: float, J: float, theta: float, precession: float,
                          axial_rate: float) -> Stability:
    """A heavy symmetric top's steady precession (theta, phidot, omega_z): k = U_eff'' / I."""
    a, b = top_terms(I, J, theta, precession, axial_rate)
    return verdict(a + b, a + b)


def disk_terms(m: float, g: float, r: float, A: float, C: float, tilt: float,
               precession: float, axial_rate: float) -> list[float]:
    """The five terms of A (A + m r^2) k for the rolling disk, in the order written above."""
    s, c = math.sin(tilt), math.cos(tilt)
    mr2 = m * r * r
    return [C * (C + mr2) * axial_rate ** 2,
            -A * (3 * C + mr2) * precession * axial_rate * s,
            A * A * precession ** 2 * (1 + 2 * s * s),
            A * mr2 * precession ** 2 * c * c,
            -A * m * g * r * c]


def disk_rolling(m: float, g: float, r: float, A: float, C: float, tilt: float,
                 precession: float, axial_rate: float) -> Stability:
    """A disk's steady rolling at tilt beta, precession phidot and axial rate omega_z."""
    terms = disk_terms(m, g, r, A, C, tilt, precession, axial_rate)
    denominator = A * (A + m * r * r)
    return verdict(sum(terms) / denominator, max(map(abs, terms)) / denominator)


def disk_critical_axial_rate(m: V, g: V, r: V, A: V, C: V) -> V:
    """Upright straight rolling is stable above |omega_z| = sqrt(m g r A / (C (C + m r^2)))."""
    return sqrt(m * g * r * A / (C * (C + m * r ** 2)))
