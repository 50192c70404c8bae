"""The linearised Whipple bicycle: Meijaard, Papadopoulos, Ruina & Schwab (2007).

J. P. Meijaard, J. M. Papadopoulos, A. Ruina and A. L. Schwab, "Linearized dynamics
equations for the balance and steer of a bicycle: a benchmark and review",
Proc. R. Soc. A 463 (2007) 1955-1982, doi:10.1098/rspa.2007.1857. Section and
equation numbers below are the paper's.

Four rigid bodies (rear wheel R, rear frame B with the rider, front frame H,
front wheel F) on a flat road; axes x forward, y to the right, z down, origin at
the rear contact point. Lean phi and steer delta obey, for small motions about
upright straight running at speed v (Eq. 5.3, torques zero),

    M q'' + v C1 q' + (g K0 + v^2 K2) q = 0,    q = (phi, delta).

The entries of M, C1, K0, K2 are built in Appendix A from totals: the whole
bicycle T (Eqs. A 1-A 5), the front assembly A = H + F (A 6-A 10), its inertia
about the steer axis (A 11-A 14), the trail ratio mu (A 15) and the wheels' spin
angular momentum coefficients S_R = I_Ryy / r_R, S_F = I_Fyy / r_F (A 16-A 18).

Gyroscopic share: the wheels' spin angular momentum (I_Ryy v / r_R and I_Fyy v / r_F)
enters only through S_R, S_F and S_T = S_R + S_F; I_Ryy and I_Fyy appear nowhere
else (the lean and steer inertias use I_xx and I_zz = I_xx of the axisymmetric
wheels). ``gyroscopic=False`` sets S_R = S_F = 0: in C1 the terms mu S_T + S_F cos(lambda)
of C1_phidelta and C1_deltaphi, in K2 the S_T of K2_phidelta and the S_F sin(lambda) of
K2_deltadelta.

Pure Python (math, cmath; no numpy, so solving a bicycle costs no numpy import). The
eigenvalues at a speed are the roots of the quartic characteristic polynomial
det(M s^2 + v C1 s + g K0 + v^2 K2) = det(M) det(s I - A) of the 4x4 state matrix A;
the speeds where the stability changes are the roots of polynomials in v^2 (the
characteristic polynomial's constant term and its Hurwitz determinant). One root finder
serves both: Aberth-Ehrlich iteration in complex arithmetic, then Newton steps on the
polynomial itself; a real polynomial's roots come out as exact reals or exact conjugate
pairs. Whether a speed between those is self-stable needs no roots: the Routh-Hurwitz
conditions on the coefficients there decide it (``routh_hurwitz``), and the eigenvalues
only where rounding could. Polynomials are lists of coefficients, lowest power first.
"""

from __future__ import annotations

import cmath
import functools
import math
import sys
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import SupportsIndex, overload

# Table 1 of the paper, SI (lambda = pi/10 rad). g is the paper's 9.81 m/s^2.
BENCHMARK: dict[str, float] = {
    "w": 1.02, "c": 0.08, "lambda": math.pi / 10, "g": 9.81,
    "rR": 0.3, "mR": 2.0, "IRxx": 0.0603, "IRyy": 0.12,
    "xB": 0.3, "zB": -0.9, "mB": 85.0, "IBxx": 9.2, "IByy": 11.0, "IBzz": 2.8, "IBxz": 2.4,
    "xH": 0.9, "zH": -0.7, "mH": 4.0, "IHxx": 0.05892, "IHyy": 0.06, "IHzz": 0.00708,
    "IHxz": -0.00756,
    "rF": 0.35, "mF": 3.0, "IFxx": 0.1405, "IFyy": 0.28,
}
KEYS = tuple(BENCHMARK)


@dataclass(frozen=True)
class Totals:
    """Appendix A: the whole bicycle (T), the front assembly (A), trail ratio, spin terms."""

    mT: float
    xT: float
    zT: float
    ITxx: float
    ITxz: float
    ITzz: float
    mA: float
    xA: float
    zA: float
    IAxx: float
    IAxz: float
    IAzz: float
    uA: float
    IAll: float
    IAlx: float
    IAlz: float
    mu: float
    SR: float
    SF: float
    ST: float
    SA: float


def totals(p: dict[str, float], gyroscopic: bool = True) -> Totals:
    """Eqs. A 1-A 19 of the paper, on SI floats keyed by the paper's names.

    Whole bicycle about the rear contact point (parallel axes; the wheels'
    centres are at (0, -rR) and (w, -rF), and I_zz = I_xx for each wheel):
      m_T = m_R + m_B + m_H + m_F                                     (A 1)
      x_T = (x_B m_B + x_H m_H + w m_F) / m_T                         (A 2)
      z_T = (-r_R m_R + z_B m_B + z_H m_H - r_F m_F) / m_T
      I_Txx = sum I_xx + m_R r_R^2 + m_B z_B^2 + m_H z_H^2 + m_F r_F^2 (A 3)
      I_Txz = I_Bxz + I_Hxz - m_B x_B z_B - m_H x_H z_H + m_F w r_F    (A 4)
      I_Tzz = I_Rxx + I_Bzz + I_Hzz + I_Fxx + m_B x_B^2 + m_H x_H^2 + m_F w^2  (A 5)
    Front assembly A = H + F about its own centre of mass (A 6-A 10), the
    perpendicular distance u_A of its centre from the steer axis (A 11) and its
    inertias about the steer axis (A 12-A 14):
      u_A = (x_A - w - c) cos(lambda) - z_A sin(lambda)
      I_All = m_A u_A^2 + I_Axx sin^2 + 2 I_Axz sin cos + I_Azz cos^2
      I_Alx = -m_A u_A z_A + I_Axx sin + I_Axz cos
      I_Alz =  m_A u_A x_A + I_Axz sin + I_Azz cos
    mu = c cos(lambda) / w (A 15); S_R = I_Ryy / r_R, S_F = I_Fyy / r_F,
    S_T = S_R + S_F (A 16); S_A = m_A u_A + mu m_T x_T (A 17).
    """
    w, c, lam = p["w"], p["c"], p["lambda"]
    rR, mR, rF, mF = p["rR"], p["mR"], p["rF"], p["mF"]
    xB, zB, mB, xH, zH, mH = p["xB"], p["zB"], p["mB"], p["xH"], p["zH"], p["mH"]
    mT = mR + mB + mH + mF
    xT = (xB * mB + xH * mH + w * mF) / mT
    zT = (-rR * mR + zB * mB + zH * mH - rF * mF) / mT
    ITxx = (p["IRxx"] + p["IBxx"] + p["IHxx"] + p["IFxx"] + mR * rR ** 2 + mB * zB ** 2
            + mH * zH ** 2 + mF * rF ** 2)
    ITxz = p["IBxz"] + p["IHxz"] - mB * xB * zB - mH * xH * zH + mF * w * rF
    ITzz = (p["IRxx"] + p["IBzz"] + p["IHzz"] + p["IFxx"] + mB * xB ** 2 + mH * xH ** 2
            + mF * w ** 2)
    mA = mH + mF
    xA = (xH * mH + w * mF) / mA
    zA = (zH * mH - rF * mF) / mA
    IAxx = p["IHxx"] + p["IFxx"] + mH * (zH - zA) ** 2 + mF * (rF + zA) ** 2
    IAxz = p["IHxz"] - mH * (xH - xA) * (zH - zA) + mF * (w - xA) * (rF + zA)
    IAzz = p["IHzz"] + p["IFxx"] + mH * (xH - xA) ** 2 + mF * (w - xA) ** 2
    s, co = math.sin(lam), math.cos(lam)
    uA = (xA - w - c) * co - zA * s
    IAll = mA * uA ** 2 + IAxx * s * s + 2 * IAxz * s * co + IAzz * co * co
    IAlx = -mA * uA * zA + IAxx * s + IAxz * co
    IAlz = mA * uA * xA + IAxz * s + IAzz * co
    mu = c / w * co
    SR = p["IRyy"] / rR if gyroscopic else 0.0
    SF = p["IFyy"] / rF if gyroscopic else 0.0
    SA = mA * uA + mu * mT * xT
    return Totals(mT, xT, zT, ITxx, ITxz, ITzz, mA, xA, zA, IAxx, IAxz, IAzz, uA, IAll, IAlx,
                  IAlz, mu, SR, SF, SR + SF, SA)


class Matrix2(tuple):
    """A 2x2 matrix of floats: a tuple of its two rows, read as a[i, j] or a[i][j]."""

    __slots__ = ()

    def __new__(cls, rows) -> Matrix2:
        return super().__new__(cls, tuple(tuple(float(x) for x in row) for row in rows))

    def __getitem__(self, key):
        if isinstance(key, tuple):
            i, j = key
            return tuple.__getitem__(self, i)[j]
        return tuple.__getitem__(self, key)

    def ravel(self) -> list[float]:
        """The entries row by row: 11, 12, 21, 22."""
        return [x for row in self for x in row]


class Spectrum(tuple[complex, ...]):
    """Eigenvalues (complex), with .real and .imag: tuples of their real and imaginary parts."""

    __slots__ = ()

    @property
    def real(self) -> tuple[float, ...]:
        return tuple(e.real for e in self)

    @property
    def imag(self) -> tuple[float, ...]:
        return tuple(e.imag for e in self)

    # scaled: every eigenvalue times factor (SupportsIndex, the tuple's repeat count, is
    # accepted for the signature of tuple.__mul__ and gets NotImplemented unless a number)
    def __mul__(self, factor: complex | SupportsIndex) -> Spectrum:
        if isinstance(factor, (int, float, complex)) and not isinstance(factor, bool):
            return Spectrum(e * factor for e in self)
        return NotImplemented

    __rmul__ = __mul__

    def __truediv__(self, divisor: float) -> Spectrum:
        return Spectrum(e / divisor for e in self)


@dataclass(frozen=True)
class Matrices:
    """M (kg m^2), C1 (kg m), K0 (kg m), K2 (kg): 2x2 matrices, rows/columns (phi, delta)."""

    M: Matrix2
    C1: Matrix2
    K0: Matrix2
    K2: Matrix2


def matrices(p: dict[str, float], gyroscopic: bool = True) -> Matrices:
    """Eqs. A 20-A 23 of the paper.

      M_pp = I_Txx,  M_pd = M_dp = I_Alx + mu I_Txz,  M_dd = I_All + 2 mu I_Alz + mu^2 I_Tzz
      K0_pp = m_T z_T,  K0_pd = K0_dp = -S_A,  K0_dd = -S_A sin(lambda)
      K2_pp = K2_dp = 0,  K2_pd = (S_T - m_T z_T) cos(lambda) / w,
      K2_dd = (S_A + S_F sin(lambda)) cos(lambda) / w
      C1_pp = 0,  C1_pd = mu S_T + S_F cos(lambda) + I_Txz cos(lambda) / w - mu m_T z_T,
      C1_dp = -(mu S_T + S_F cos(lambda)),
      C1_dd = I_Alz cos(lambda) / w + mu (S_A + I_Tzz cos(lambda) / w)
    """
    return matrices_of(totals(p, gyroscopic), p["w"], p["lambda"])


def matrices_of(t: Totals, w: float, lam: float) -> Matrices:
    """``matrices`` from the totals of Appendix A (a worked answer's steps, a student's
    value among them), the wheel base ``w`` and the steer axis tilt ``lam``."""
    s, co = math.sin(lam), math.cos(lam)
    M = Matrix2([[t.ITxx, t.IAlx + t.mu * t.ITxz],
                 [t.IAlx + t.mu * t.ITxz, t.IAll + 2 * t.mu * t.IAlz + t.mu ** 2 * t.ITzz]])
    K0 = Matrix2([[t.mT * t.zT, -t.SA], [-t.SA, -t.SA * s]])
    K2 = Matrix2([[0.0, (t.ST - t.mT * t.zT) * co / w],
                  [0.0, (t.SA + t.SF * s) * co / w]])
    gyro = t.mu * t.ST + t.SF * co
    C1 = Matrix2([[0.0, gyro + t.ITxz * co / w - t.mu * t.mT * t.zT],
                  [-gyro, t.IAlz * co / w + t.mu * (t.SA + t.ITzz * co / w)]])
    return Matrices(M, C1, K0, K2)




def eigenvalues(m: Matrices, v: float, g: float) -> Spectrum:
    """The four eigenvalues at speed v (complex), ascending real part, then imaginary part.

    The roots of the characteristic quartic sum a_k(v) s^k; a complex pair comes out as
    exact conjugates (bit-equal real parts), a real eigenvalue with imaginary part 0.0,
    so the order is exact.
    """
    return _spectrum([polyval(v, c) for c in _characteristic(m, g)])


def _spectrum(a: list[float]) -> Spectrum:
    """The roots of sum a[k] s^k, ascending real part, then imaginary part."""
    return Spectrum(sorted(roots(a), key=lambda e: (e.real, e.imag)))


# ---- polynomials: lists of float coefficients, lowest power first ----------------

def _trim(c: list[float]) -> list[float]:
    """Without trailing (highest-power) zeros; [0.0] if every coefficient is 0."""
    c = list(c)
    while len(c) > 1 and c[-1] == 0:
        c.pop()
    return c or [0.0]


def polyadd(a: list[float], b: list[float]) -> list[float]:
    n = max(len(a), len(b))
    return _trim([(a[k] if k < len(a) else 0.0) + (b[k] if k < len(b) else 0.0)
                  for k in range(n)])


def polysub(a: list[float], b: list[float]) -> list[float]:
    n = max(len(a), len(b))
    return _trim([(a[k] if k < len(a) else 0.0) - (b[k] if k < len(b) else 0.0)
                  for k in range(n)])


def polymul(a: list[float], b: list[float]) -> list[float]:
    out = [0.0] * (len(a) + len(b) - 1)
    for i, x in enumerate(a):
        for j, y in enumerate(b):
            out[i + j] += x * y
    return _trim(out)


def polyval(x, c: Sequence[float]):
    """c[0] + c[1] x + ... by Horner's rule (x real or complex)."""
    value = c[-1] + x * 0
    for coefficient in reversed(c[:-1]):
        value = coefficient + value * x
    return value


def polyder(c: list[float]) -> list[float]:
    return [k * c[k] for k in range(1, len(c))] or [0.0]


_EPS = 2.220446049250313e-16
_SWEEPS = 500       # Aberth sweeps at most
_WATCH = 16         # the sweep from which ``roots`` looks for z going round a cycle


def roots(c: list[float]) -> list[complex]:
    """The roots of the real polynomial c[0] + c[1] x + ... + c[n] x^n (complex).

    Aberth-Ehrlich simultaneous iteration from points on a circle that encloses every
    root, then Newton steps on the polynomial. A root whose imaginary part is at the
    rounding level is real (imaginary part 0.0, polished in real arithmetic); the others
    come in exact conjugate pairs. Roots at 0 (zero low coefficients) are exact zeros.
    """
    c = _trim([float(x) for x in c])
    zeros = 0
    while len(c) > 1 and c[0] == 0:
        c.pop(0)
        zeros += 1
    n = len(c) - 1
    out = [0j] * zeros
    if n < 1:
        return out
    if n == 1:
        return out + [complex(-c[0] / c[1])]
    lead = c[-1]
    monic = [x / lead for x in c]
    if not all(math.isfinite(x) for x in monic):
        return out + [complex(math.nan, 0.0)] * n
    radius = 2 * max(abs(monic[k]) ** (1.0 / (n - k)) for k in range(n))
    circle, others_of = _start(n)
    z = [radius * point for point in circle]
    dmonic = polyder(monic)
    # polyval and sum written out in the loop (the same operations in the same order, so
    # the same floats): the iteration is most of a bicycle's check
    top, rest = monic[-1], monic[-2::-1]
    dtop, drest = dmonic[-1], dmonic[-2::-1]
    tol, isfinite = 4 * _EPS, cmath.isfinite
    # A sweep is a function of z alone: once z is back (bit for bit) where it stood at the
    # start of an earlier sweep, the sweeps go round that cycle to the last one, and z is
    # where the cycle stands after _SWEEPS sweeps, without the sweeps in between. (Near a
    # pair +-sigma or a double root the steps can circle in the last bits and never meet
    # the tolerance.) Watched from sweep _WATCH on: most polynomials have converged by then.
    history: list[tuple[complex, ...]] = []     # z at the start of sweeps _WATCH, ...
    start: dict[tuple[complex, ...], int] = {}
    for sweep in range(_SWEEPS):
        if sweep >= _WATCH:
            state = tuple(z)
            first = start.setdefault(state, sweep)
            # equal as numbers is not enough: 0.0 and -0.0 (repr tells them apart, exactly)
            if first != sweep and repr(state) == repr(history[first - _WATCH]):
                z = list(history[first - _WATCH + (_SWEEPS - first) % (sweep - first)])
                break
            history.append(state)
        moved = False
        for i, js in others_of:
            zi = z[i]
            value = top + zi * 0
            for coefficient in rest:
                value = coefficient + value * zi
            if value == 0:
                continue
            slope = dtop + zi * 0
            for coefficient in drest:
                slope = coefficient + slope * zi
            others = 0
            for j in js:
                zj = z[j]
                if zi != zj:
                    others = others + 1.0 / (zi - zj)
            ratio = value / slope if slope != 0 else complex(math.inf)
            denominator = 1.0 - ratio * others
            step = ratio if denominator == 0 else ratio / denominator
            if not isfinite(step):
                continue
            z[i] = zi = zi - step
            if not moved and abs(step) > tol * abs(zi):
                moved = True
        if not moved:
            break
    d = polyder(c)
    polished = []
    for zi in z:
        polished.append(complex(_newton(zi, c, d)))
    # real roots: imaginary part at the rounding level
    real, upper, lower = [], [], []
    for zi in polished:
        if abs(zi.imag) <= 1e-10 * max(1.0, abs(zi)):
            real.append(zi.real)
        elif zi.imag > 0:
            upper.append(zi)
        else:
            lower.append(zi)
    while len(upper) != len(lower):          # no partner: the one nearest the axis is real
        side = upper if len(upper) > len(lower) else lower
        nearest = min(side, key=lambda e: abs(e.imag))
        side.remove(nearest)
        real.append(nearest.real)
    for x in real:
        out.append(complex(_newton_real(x, c, d), 0.0))
    for zu in upper:
        partner = min(lower, key=lambda e: abs(e - zu.conjugate()))
        lower.remove(partner)
        zp = complex(_newton(0.5 * (zu + partner.conjugate()), c, d))
        zp = complex(zp.real, abs(zp.imag))
        out.extend([zp, zp.conjugate()])
    return out


@functools.lru_cache(maxsize=16)
def _start(n: int) -> tuple[tuple[complex, ...], tuple[tuple[int, tuple[int, ...]], ...]]:
    """What ``roots`` starts from for degree n, the same for every polynomial: the n
    points on the unit circle (times the radius, the start of the sweeps) and each index
    with the others."""
    return (tuple(cmath.exp(1j * (2 * math.pi * k / n + 0.4)) for k in range(n)),
            tuple((i, tuple(j for j in range(n) if j != i)) for i in range(n)))


@overload
def _newton(x: float, c: list[float], d: list[float], steps: int = 4) -> float: ...
@overload
def _newton(x: complex, c: list[float], d: list[float], steps: int = 4) -> complex: ...
def _newton(x: complex | float, c: list[float], d: list[float],
            steps: int = 4) -> complex | float:
    """Newton steps on c from x (complex or real; d = polyder(c)), kept while the residual
    does not grow.

    polyval written out (the same operations in the same order, so the same floats): the
    polishing is a third of ``roots``. A step that leaves x as it is, bit for bit, ends the
    steps: the residual there is the same, so every step after it would leave x as it is
    too. (Equal numbers are equal bits but for the sign of a zero: where x has a zero
    part, repr tells 0.0 from -0.0.)
    """
    ctop, crest = c[-1], c[-2::-1]
    dtop, drest = d[-1], d[-2::-1]
    value = ctop + x * 0
    for coefficient in crest:
        value = coefficient + value * x
    for _ in range(steps):
        if value == 0:
            break
        slope = dtop + x * 0
        for coefficient in drest:
            slope = coefficient + slope * x
        if slope == 0:
            break
        trial = x - value / slope
        if trial == x and (x.real != 0 and (x.imag != 0 or x.__class__ is float)
                           or repr(trial) == repr(x)):
            break
        new = ctop + trial * 0
        for coefficient in crest:
            new = coefficient + new * trial
        if not abs(new) <= abs(value):
            break
        x, value = trial, new
    return x


def _newton_real(x: float, c: list[float], d: list[float], steps: int = 4) -> float:
    """``_newton`` in real arithmetic: a real root polished."""
    return float(_newton(x, c, d, steps))


# ---- the characteristic polynomial as polynomials in v ------------------------

def characteristic(m: Matrices, g: float) -> list[list[float]]:
    """[a0, a1, a2, a3, a4]: det(M s^2 + v C1 s + g K0 + v^2 K2) = sum a_k(v) s^k.

    Worked once per bicycle (every speed's eigenvalues and stability ask for it): a copy
    of the remembered coefficients.
    """
    return [list(a) for a in _characteristic(m, g)]


@functools.lru_cache(maxsize=64)
def _characteristic(m: Matrices, g: float) -> tuple[tuple[float, ...], ...]:
    """The coefficients of ``characteristic``: ``_characteristic_computed``, each that
    double precision cannot tell from 0 set to 0 (``_resolved``)."""
    return _resolved(_characteristic_computed(m, g), _characteristic_by_polynomials(
        _absolute(m), abs(g), permanent=True))


def _characteristic_computed(m: Matrices, g: float) -> tuple[tuple[float, ...], ...]:
    """``_characteristic_by_polynomials`` with its products written out
    (``_characteristic_written_out``) wherever that one is finite."""
    coeffs = _characteristic_written_out(m, g)
    if all(math.isfinite(x) for a in coeffs for x in a):
        return coeffs
    return _characteristic_by_polynomials(m, g)


#: a coefficient within this many rounding units of the sum of its terms' sizes is 0: each
#: is a sum of at most eight products, each rounded once, the sums rounded again
_UNRESOLVED = 16 * sys.float_info.epsilon


def _resolved(coeffs: tuple[tuple[float, ...], ...], sizes: tuple[tuple[float, ...], ...]
              ) -> tuple[tuple[float, ...], ...]:
    """The coefficients with each that is no larger than the rounding of the sum that
    made it set to 0: ``sizes`` are the sums of the terms' sizes (the characteristic of
    the matrices' absolute values, every difference a sum). Without a spinning wheel, a0's
    v^2 coefficient is g (K0_pp K2_dd - K2_pd K0_dp) = 0 exactly, but came out as +-4.5e-13
    (5607.6 + 4.5e-13 v^2 printed), and a -4.5e-13 made a capsize speed of 1e8 m/s."""
    out = []
    for a, size in zip(coeffs, sizes):
        size = (*size, *[0.0] * (len(a) - len(size)))
        out.append(_trim([0.0 if math.isfinite(s) and abs(c) <= _UNRESOLVED * s else c
                          for c, s in zip(a, size)]))
    return tuple(tuple(a) for a in out)


def _absolute(m: Matrices) -> Matrices:
    """The matrices with each entry's absolute value."""
    return Matrices(*(Matrix2([[abs(x) for x in row] for row in a])
                      for a in (m.M, m.C1, m.K0, m.K2)))


def _characteristic_written_out(m: Matrices, g: float) -> tuple[tuple[float, ...], ...]:
    """``_characteristic_by_polynomials`` with the polynomial products written out: the
    same products added in the same order, so the same floats wherever these are finite.

    A = M, B = v C1, C = g K0 + v^2 K2 have the coefficients [M_ij], [0, C1_ij] and
    [g K0_ij, 0, K2_ij]. ``polymul`` sums each coefficient's products from 0.0, lowest
    power of the first factor first; a product with one of those zero coefficients is
    +-0 (its factors finite), and a sum that starts at 0.0 is never -0.0, so it neither
    changes a sum nor its sign and is left out; for the same reason the zeros ``_trim``
    drops and the 0.0 that ``polyadd`` pads with are the same. (An infinite coefficient
    is where those products are not +-0: that case is left to the polynomials.)
    """
    (a00, a01), (a10, a11) = m.M
    (b00, b01), (b10, b11) = m.C1
    (k00, k01), (k10, k11) = ((g * x for x in row) for row in m.K0)
    (q00, q01), (q10, q11) = m.K2
    a4 = [(0.0 + a00 * a11) - (0.0 + a01 * a10)]
    a3 = [0.0, ((0.0 + a00 * b11) + (0.0 + b00 * a11))
          - ((0.0 + a01 * b10) + (0.0 + b01 * a10))]
    a2 = [((0.0 + a00 * k11) + (0.0 + k00 * a11)) - ((0.0 + a01 * k10) + (0.0 + k01 * a10)),
          0.0,
          (((0.0 + a00 * q11) + (0.0 + q00 * a11)) - ((0.0 + a01 * q10) + (0.0 + q01 * a10)))
          + ((0.0 + b00 * b11) - (0.0 + b01 * b10))]
    a1 = [0.0,
          ((0.0 + b00 * k11) + (0.0 + k00 * b11)) - ((0.0 + b01 * k10) + (0.0 + k01 * b10)),
          0.0,
          ((0.0 + b00 * q11) + (0.0 + q00 * b11)) - ((0.0 + b01 * q10) + (0.0 + q01 * b10))]
    a0 = [(0.0 + k00 * k11) - (0.0 + k01 * k10),
          0.0,
          ((0.0 + k00 * q11) + q00 * k11) - ((0.0 + k01 * q10) + q01 * k10),
          0.0,
          (0.0 + q00 * q11) - (0.0 + q01 * q10)]
    return tuple(tuple(_trim(a)) for a in (a0, a1, a2, a3, a4))


def _characteristic_by_polynomials(m: Matrices, g: float, permanent: bool = False
                                   ) -> tuple[tuple[float, ...], ...]:
    """The coefficients of ``characteristic``, by polynomial arithmetic; ``permanent``:
    every difference a sum (of the matrices' absolute values: the size of each sum).

    Each a_k is a list of coefficients in v (lowest power first).
    For 2x2 A s^2 + B s + C: a4 = det A, a0 = det C,
      a3 = A11 B22 + B11 A22 - A12 B21 - B12 A21,
      a2 = A11 C22 + B11 B22 + C11 A22 - A12 C21 - B12 B21 - C12 A21,
      a1 = B11 C22 + C11 B22 - B12 C21 - C12 B21.
    """
    A = [[[m.M[i][j]] for j in range(2)] for i in range(2)]
    B = [[[0.0, m.C1[i][j]] for j in range(2)] for i in range(2)]
    C = [[[g * m.K0[i][j], 0.0, m.K2[i][j]] for j in range(2)] for i in range(2)]

    minus = polyadd if permanent else polysub

    def cross(X, Y):
        """X11 Y22 + Y11 X22 - X12 Y21 - Y12 X21: the mixed term of det(X + Y)."""
        return minus(polyadd(polymul(X[0][0], Y[1][1]), polymul(Y[0][0], X[1][1])),
                     polyadd(polymul(X[0][1], Y[1][0]), polymul(Y[0][1], X[1][0])))

    def det(X):
        return minus(polymul(X[0][0], X[1][1]), polymul(X[0][1], X[1][0]))

    a4 = det(A)
    a3 = cross(A, B)
    a2 = polyadd(cross(A, C), det(B))
    a1 = cross(B, C)
    a0 = det(C)
    return tuple(tuple(_trim(a)) for a in (a0, a1, a2, a3, a4))


def hurwitz(coeffs: list[list[float]]) -> list[float]:
    """H3 = a1 a2 a3 - a0 a3^2 - a1^2 a4 as a polynomial in v.

    With a4 > 0, all four roots have negative real parts iff every a_k > 0 and
    H3 > 0 (Routh-Hurwitz for a quartic). A pair of roots +-i omega on the
    imaginary axis makes H3 = 0; a root s = 0 makes a0 = 0. So stability can
    change only at roots of a0(v) (a real eigenvalue through 0: capsize-type)
    and of H3(v) (a complex pair through the axis: weave-type).
    """
    a0, a1, a2, a3, a4 = coeffs
    return polysub(polymul(polymul(a1, a2), a3),
                   polyadd(polymul(a0, polymul(a3, a3)), polymul(polymul(a1, a1), a4)))


def hurwitz_of(m: Matrices, g: float) -> list[float]:
    """``hurwitz(characteristic(m, g))``: H3(v), worked once per bicycle (``stability`` and
    the worked answer both ask for it)."""
    return list(_hurwitz_of(m, g))


@functools.lru_cache(maxsize=64)
def _hurwitz_of(m: Matrices, g: float) -> tuple[float, ...]:
    coeffs = _characteristic(m, g)
    if all(math.isfinite(x) for a in coeffs for x in a):
        h3 = _hurwitz_written_out(coeffs)
        if all(math.isfinite(x) for x in h3):
            return h3
    return tuple(hurwitz(characteristic(m, g)))


def _hurwitz_written_out(coeffs: tuple[tuple[float, ...], ...]) -> tuple[float, ...]:
    """``hurwitz`` of Eq. 5.3's (finite) a_k(v), its products written out: the same products
    added in the same order, so the same floats wherever these are finite.

    a1 and a3 hold odd powers of v only, a0, a2 and a4 even ones (B = v C1 is odd in v,
    A and C even): the other coefficients are 0.0, as are the products with them, left
    out for the reasons ``_characteristic_written_out`` gives (a sum that starts at 0.0
    is never -0.0), and so are the zeros ``_trim`` drops and ``polyadd`` pads with.
    """
    a0, a1, a2, a3, a4 = ((*a, 0.0, 0.0, 0.0, 0.0)[:5] for a in coeffs)
    t0, t2, t4 = a0[0], a0[2], a0[4]
    p1, p3 = a1[1], a1[3]
    r0, r2 = a2[0], a2[2]
    s1, u0 = a3[1], a4[0]
    x1, x3, x5 = 0.0 + p1 * r0, (0.0 + p1 * r2) + p3 * r0, 0.0 + p3 * r2    # a1 a2
    y2 = 0.0 + s1 * s1                                                    # a3^2
    z2, z4, z6 = 0.0 + p1 * p1, (0.0 + p1 * p3) + p3 * p1, 0.0 + p3 * p3    # a1^2
    # a1 a2 a3 - (a0 a3^2 + a1^2 a4), powers v^2, v^4, v^6
    h2 = (0.0 + x1 * s1) - ((0.0 + t0 * y2) + (0.0 + z2 * u0))
    h4 = (0.0 + x3 * s1) - ((0.0 + t2 * y2) + (0.0 + z4 * u0))
    h6 = (0.0 + x5 * s1) - ((0.0 + t4 * y2) + (0.0 + z6 * u0))
    return tuple(_trim([0.0, 0.0, h2, 0.0, h4, 0.0, h6]))


def _positive_roots(poly: Sequence[float]) -> list[float]:
    """Real roots v > 0 of a polynomial in v that is even in v: solved in w = v^2.

    Roots of the polynomial in w, kept where real and positive, then polished by
    Newton steps on the polynomial in v.
    """
    poly = [float(x) for x in poly]
    if not any(poly):
        return []
    even = poly[::2]                         # coefficients of w^0, w^1, ...
    # B = v C1 and C = g K0 + v^2 K2 have exact zero coefficients, so the factors of
    # w (roots at v = 0) come out as exact zeros, not as rounding noise.
    while even and even[0] == 0:             # factors of w (v = 0 roots)
        even = even[1:]
    while even and even[-1] == 0:
        even = even[:-1]
    if len(even) < 2:
        return []
    out = []
    d = polyder(poly)
    for r in roots(even):
        if abs(r.imag) > 1e-9 * max(1.0, abs(r)) or r.real <= 0:
            continue
        v = math.sqrt(r.real)
        for _ in range(8):
            slope = polyval(v, d)
            if slope == 0:
                break
            step = polyval(v, poly) / slope
            v -= step
            if abs(step) <= 1e-16 * abs(v):
                break
        if v > 0:
            out.append(float(v))
    return sorted(set(out))


@dataclass(frozen=True)
class Stability:
    """The speeds (v > 0) where the self-stability changes, and the stable intervals."""

    weave: list[float]            # a complex pair crosses the imaginary axis (H3 = 0)
    capsize: list[float]          # a real eigenvalue crosses zero (a0 = 0)
    stable: list[tuple[float, float]]   # (low, high); high may be inf
    other: list[float]            # roots where the stability does not change (a real pair +-sigma)
    # the eigenvalues at each of those speeds, as worked out on the way (eigenvalues(m, v, g))
    spectra: dict = field(default_factory=dict, compare=False, repr=False)


# A Hurwitz quantity within this fraction of the sum of its terms' magnitudes is
# rounding's to decide: far above the few ulps of rounding in a_k(v) and H3, far below
# any margin a root finder's backward error could cross.
HURWITZ_TOL = 1e-9


def routh_hurwitz(a: list[float], terms: list[float]) -> bool | None:
    """Whether every root of a0 + a1 s + a2 s^2 + a3 s^3 + a4 s^4 has Re(s) < 0, from its
    coefficients alone; None where rounding could decide it (then find the roots).

    Routh-Hurwitz for the quartic of Eq. 5.3 (in the Lienard-Chipart form, as ``hurwitz``):
    with a4 > 0, all four roots have Re(s) < 0 iff a0, a1, a2, a3 > 0 and
    H3 = a1 a2 a3 - a0 a3^2 - a1^2 a4 > 0; a coefficient < 0 alone means a root with
    Re(s) > 0. ``terms[k]`` is the sum of the magnitudes of the terms that made a[k]
    (for a_k(v) = sum c_j v^j, sum |c_j| v^j): a coefficient, or H3, no larger than
    HURWITZ_TOL times its terms' magnitudes is undecided (None), and so is a lead
    a4 <= 0 or a non-finite value.
    """
    a0, a1, a2, a3, a4 = a
    if not a4 > 0 or not all(math.isfinite(x) for x in a):
        return None
    for ak, scale in zip(a, terms):
        if not abs(ak) > HURWITZ_TOL * scale:
            return None
    if a0 < 0 or a1 < 0 or a2 < 0 or a3 < 0:
        return False
    t1, t2, t3 = a1 * a2 * a3, a0 * a3 * a3, a1 * a1 * a4
    h3 = t1 - t2 - t3
    if not abs(h3) > HURWITZ_TOL * (abs(t1) + abs(t2) + abs(t3)):
        return None
    return h3 > 0


def _stable_at(m: Matrices, v: float, g: float) -> bool:
    """Whether every eigenvalue at speed v has Re(s) < 0 (spectral_abscissa < 0): by
    routh_hurwitz on a_k(v) (Eq. 5.3's characteristic quartic), and by the eigenvalues
    only where rounding could decide it."""
    a = [polyval(v, c) for c in _characteristic(m, g)]
    x = abs(v)
    decided = routh_hurwitz(a, [polyval(x, c) for c in _magnitudes(m, g)])
    if decided is None:
        return max(_spectrum(a).real) < 0
    return decided


@functools.lru_cache(maxsize=64)
def _magnitudes(m: Matrices, g: float) -> tuple[tuple[float, ...], ...]:
    """The magnitudes of a_k(v)'s coefficients, |c_j| (``routh_hurwitz``'s scale of a_k(v)
    is sum |c_j| |v|^j): the same at every probe speed of a bicycle, found once."""
    return tuple(tuple(abs(cj) for cj in c) for c in _characteristic(m, g))


def stability(m: Matrices, g: float) -> Stability:
    """Weave and capsize speeds and the self-stable speed range(s), v > 0.

    Candidates are the positive roots of a0(v) and H3(v); between consecutive
    candidates the eigenvalues' signs cannot change, so one speed inside each
    interval decides it (``_stable_at``: Routh-Hurwitz on a_k(v), the eigenvalues
    where rounding could decide). The eigenvalues are found at the candidates only,
    to tell a capsize or weave speed from a root where the stability does not change.

    Worked once per bicycle, as its characteristic coefficients are (problems of one
    bicycle at several speeds share it); each call gets lists of its own.
    """
    weave, capsize, stable, other, spectra = _stability(m, g)
    return Stability(list(weave), list(capsize), list(stable), list(other), dict(spectra))


@functools.lru_cache(maxsize=64)
def _stability(m: Matrices, g: float) -> tuple[tuple, ...]:
    """``stability``'s speeds, intervals and spectra, as tuples."""
    a0_roots, h3_roots = _candidates(m, g)
    capsize, weave, other = [], [], []
    spectra: dict[float, Spectrum] = {}
    for v in a0_roots:
        ev = spectra[v] = eigenvalues(m, v, g)
        if min(abs(e) for e in ev) <= 1e-6 * max(1.0, max(abs(e) for e in ev)):
            capsize.append(v)                # a real eigenvalue at 0
        else:
            other.append(v)                  # rounding: no eigenvalue there after all
    for v in h3_roots:
        ev = spectra[v] = eigenvalues(m, v, g)
        scale = max(1.0, max(abs(e) for e in ev))
        near = min(ev, key=lambda e: abs(e.real))
        if abs(near.real) <= 1e-6 * scale and abs(near.imag) > 1e-6 * scale:
            weave.append(v)                  # a pair +-i omega on the imaginary axis
        else:
            other.append(v)                  # a real pair +-sigma: no change of stability
    stable = _stable_between(m, g, sorted(set(capsize + weave + other)))
    return tuple(weave), tuple(capsize), tuple(stable), tuple(other), tuple(spectra.items())


def stable_speeds(m: Matrices, g: float) -> list[tuple[float, float]]:
    """``stability(m, g).stable``, the same intervals, without the eigenvalues at the
    candidates: every candidate is an edge whether it is a capsize speed, a weave speed
    or neither (the probes between the edges decide), so telling them apart, which is
    what the eigenvalues are found for, is not needed for the stable range alone.
    Worked once per bicycle, as ``stability`` is."""
    return list(_stable_speeds(m, g))


@functools.lru_cache(maxsize=64)
def _stable_speeds(m: Matrices, g: float) -> tuple[tuple[float, float], ...]:
    a0_roots, h3_roots = _candidates(m, g)
    return tuple(_stable_between(m, g, sorted(set(a0_roots + h3_roots))))


def _candidates(m: Matrices, g: float) -> tuple[list[float], list[float]]:
    """The speeds v > 0 where the stability can change: the roots of a0(v) (a real
    eigenvalue through 0) and of H3(v) (a pair through the imaginary axis)."""
    return _positive_roots(_characteristic(m, g)[0]), _positive_roots(_hurwitz_of(m, g))


def _stable_between(m: Matrices, g: float, edges: list[float]) -> list[tuple[float, float]]:
    """The stable intervals of v > 0 cut at ``edges`` (ascending): each decided at one
    probe speed inside it, neighbours that are both stable joined."""
    points = [0.0] + edges + [math.inf]
    stable: list[tuple[float, float]] = []
    for lo, hi in zip(points, points[1:]):
        probe = 0.5 * (lo + hi) if math.isfinite(hi) else (2 * lo if lo > 0 else 1.0)
        if _stable_at(m, probe, g):
            if stable and stable[-1][1] == lo:
                stable[-1] = (stable[-1][0], hi)
            else:
                stable.append((lo, hi))
    return stable


def motion(ev: Spectrum, tol: float = 1e-12) -> str:
    """stable, or which mode grows: capsize (a real eigenvalue > 0: the bicycle falls
    over without oscillating), weave (a complex pair with positive real part: an
    oscillation of lean and steer that grows), or 'capsize and weave'."""
    scale = max(1.0, max(abs(e) for e in ev))
    growing = [e for e in ev if e.real > tol * scale]
    real = any(abs(e.imag) <= tol * scale for e in growing)
    pair = any(abs(e.imag) > tol * scale for e in growing)
    if real and pair:
        return "capsize and weave"
    if pair:
        return "weave"
    if real:
        return "capsize"
    return "stable"
