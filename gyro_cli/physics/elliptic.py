"""Complete elliptic integrals of the first and third kinds, on floats, without scipy.

The released top's period and mean precession (Eqs. 11.22-11.26, see nutation.py)
need K(m) and Pi(n, m) in Carlson's symmetric forms,

    K(m) = R_F(0, 1 - m, 1),    Pi(n, m) - K(m) = n/3 R_J(0, 1 - m, 1, 1 - n),

for one scalar each per problem. scipy.special has them, but importing it costs
a third of a second, more than all the rest of solving a problem file; these
are a dozen lines each and as accurate (tests/test_elliptic.py holds them to
scipy's and to limiting cases at 1e-13).

- K by the arithmetic-geometric mean (DLMF 19.8.5): K = pi / (2 M(1, sqrt(1 - m))),
  quadratically convergent, exact to a few ulps; the one ``ellipk`` of the formulas
  (core/expr.py) uses.
- R_J by Carlson's duplication (B. C. Carlson, "Numerical computation of real or
  complex elliptic integrals", Numer. Algorithms 10 (1995) 13-26, Algorithm 3;
  DLMF 19.36(i)), for p > 0, with R_C(1, 1 + e) in closed form. Unlike the AGM
  series for Pi (DLMF 19.8.6), which loses half the digits as n -> 1, it keeps
  full precision there: the top whose axis nearly reaches the vertical.
"""

from __future__ import annotations

import math

_EPS = 2.0 ** -53
_RJ_SCALE = (_EPS / 4) ** (-1 / 6)  # Carlson's Q = (r/4)^(-1/6) max|A0 - x|: error < r


def complete_K(y: float) -> float:
    """K(m) with y = 1 - m given (0 <= y; y = 0 is the logarithmic pole, inf): the
    arithmetic-geometric mean the formulas' ``ellipk`` uses (core.expr.agm_K)."""
    from ..core.expr import agm_K

    return math.inf if y == 0.0 else agm_K(y)


def carlson_rj(x: float, y: float, z: float, p: float) -> float:
    """R_J(x, y, z, p) for x, y, z >= 0 (at most one 0) and p > 0 (Carlson 1995)."""
    x0, y0, z0 = x, y, z
    A0 = A = (x + y + z + 2 * p) / 5
    delta = (p - x) * (p - y) * (p - z)
    Q = _RJ_SCALE * max(abs(A0 - x), abs(A0 - y), abs(A0 - z), abs(A0 - p))
    scale, total = 1.0, 0.0  # scale = 4^-m
    while scale * Q >= abs(A):
        sx, sy, sz, sp = math.sqrt(x), math.sqrt(y), math.sqrt(z), math.sqrt(p)
        lam = sx * sy + sx * sz + sy * sz
        d = (sp + sx) * (sp + sy) * (sp + sz)
        total += scale * _rc_one(delta * scale ** 3 / (d * d)) / d
        A, x, y, z, p = (A + lam) / 4, (x + lam) / 4, (y + lam) / 4, (z + lam) / 4, \
            (p + lam) / 4
        scale /= 4
    X, Y, Z = (A0 - x0) * scale / A, (A0 - y0) * scale / A, (A0 - z0) * scale / A
    P = (-X - Y - Z) / 2
    E2 = X * Y + X * Z + Y * Z - 3 * P * P
    E3 = X * Y * Z + 2 * E2 * P + 4 * P ** 3
    E4 = (2 * X * Y * Z + E2 * P + 3 * P ** 3) * P
    E5 = X * Y * Z * P * P
    series = 1 - 3 * E2 / 14 + E3 / 6 + 9 * E2 * E2 / 88 - 3 * E4 / 22 \
        - 9 * E2 * E3 / 52 + 3 * E5 / 26
    return scale * A ** -1.5 * series + 6 * total


def _rc_one(e: float) -> float:
    """R_C(1, 1 + e) for e > -1: atan(sqrt e)/sqrt e, atanh(sqrt -e)/sqrt -e, or its
    series near 0 (where both lose digits)."""
    if abs(e) < 1e-3:  # the next term, e^7/15, is below 1e-21
        return 1 - e / 3 + e * e / 5 - e ** 3 / 7 + e ** 4 / 9 - e ** 5 / 11 + e ** 6 / 13
    if e > 0:
        root = math.sqrt(e)
        return math.atan(root) / root
    root = math.sqrt(-e)
    return math.atanh(root) / root
