"""The precession of the equinoxes: an oblate planet as a top torqued by the Sun and Moon.

Derivation (MacCullagh's formula; e.g. Danby, *Fundamentals of Celestial
Mechanics*, ch. 13; Murray & Dermott, *Solar System Dynamics*, sec. 5.14).
A planet with polar moment C and equatorial moments A = B, spin axis s, feels
from a point mass M_b at distance r in direction u the potential

    V = -G M_b M / r + (3 G M_b (C - A) / (2 r^3)) (u . s)^2 + const,

so the torque on it is  T = -s x dV/ds = (3 G M_b (C - A) / r^3) (u . s) (u x s).

Averaged over an orbit (time average on a Kepler ellipse: <1/r^3> =
1 / (a^3 (1 - e^2)^(3/2)), and <u u^T / r^3> is isotropic in the orbit plane,
(I - n n^T) / (2 a^3 (1 - e^2)^(3/2)), with n the orbit normal),

    <T> = -(3/2) (G M_b / (a^3 (1 - e^2)^(3/2))) (C - A) cos(eps) (n x s),

eps the obliquity (angle between s and n). The chapter's steady precession
(dH/dt = T with H = C omega s) then turns s about -n at the rate

    Omega_p = (3/2) (G M_b / (a^3 (1 - e^2)^(3/2))) ((C - A) / C) cos(eps) / omega.

An orbit inclined by i to the reference plane (the Moon's, 5.145 deg to the
ecliptic) whose node turns round in a time short against the precession (18.6
years against 26,000) is averaged over the node too: the orbit normal m spends
equal times on a cone of half-angle i about n, <m m^T> = cos^2 i n n^T +
(sin^2 i / 2)(I - n n^T), which multiplies the torque by (1 - (3/2) sin^2 i).

By Kepler's third law, n_b^2 a^3 = G (M + M_b), so G M_b / a^3 = n_b^2 q / (1 + q)
with q = M_b / M the mass ratio: the orbital period and the mass ratio suffice.
"""

from __future__ import annotations

import math

G = 6.67430e-11                  # m^3 kg^-1 s^-2, CODATA 2018
ARCSEC = math.pi / (180 * 3600)  # rad
JULIAN_YEAR = 365.25 * 86400.0   # s

