"""The heavy symmetric top in closed form: nutation limits, period and precession.

Chapter 11, Eqs. 11.14-11.26 (with the errata: Eq. 11.24 has gamma^2/a). With
u = cos(theta) the energy integral is u'^2 = f(u) (Eq. 11.19),

    f(u) = (1 - u^2)(alpha - a u) - (beta - gamma u)^2 = a (u - u1)(u - u2)(u - u3),

and the axis nutates between u1 <= u2 (in [-1, 1]); u3 >= 1. With
u = u1 + (u2 - u1) sin^2(s) the period and the precession over one period are
complete elliptic integrals of the first and third kinds (Carlson forms):

    T = 4 K(m) / sqrt(a (u3 - u1)),                 m = (u2 - u1) / (u3 - u1)
    phidot = (beta - gamma u) / (1 - u^2)
           = 1/2 [(beta - gamma) / (1 - u) + (beta + gamma) / (1 + u)]
    mean phidot = [(beta - gamma) Pi(n1, m) / (1 - u1) + (beta + gamma) Pi(-n2, m) / (1 + u1)]
                  / (2 K(m)),      n1 = (u2 - u1) / (1 - u1),  n2 = (u2 - u1) / (1 + u1)

Everything is computed relative to the starting point, d = u - u0, where f has
coefficients free of cancellation (f(u0) = sin^2(theta0) thetadot0^2 exactly), so
double roots (steady precession) and release from rest (u0 a root) stay exact.

Pure floats; the elliptic integrals are elliptic.py's (no scipy).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TypedDict

from ..core.generic import V, pi_like, sin

STEADY_AMPLITUDE = 1e-9    # rad: a theta range below this is no nutation ("steady")
CUSP_TOLERANCE = 1e-10     # |phidot| at a limit, relative to the larger one: a cusp


@dataclass(frozen=True)
class Top:
    """The body: transverse inertia I about the fixed point, axial J, and m g l (SI)."""

    I: float    # kg m^2 (> 0)
    J: float    # kg m^2 (> 0)
    mgl: float  # N m (> 0: centre of mass above the pivot when theta < 90 deg)


@dataclass(frozen=True)
class Start:
    """The state at t = 0: theta0 (rad), spin psidot (rad/s), phidot and thetadot (rad/s)."""

    theta0: float
    spin: float
    precession0: float = 0.0
    theta_rate0: float = 0.0


@dataclass(frozen=True)
class Nutation:
    """The closed-form motion of a heavy top (Eqs. 11.14-11.19); SI, angles in rad."""

    a: float
    alpha: float
    beta: float
    gamma: float
    P1: float
    P2: float
    energy: float
    u_roots: tuple[float, float, float]
    theta_min: float
    theta_max: float
    nutation_period: float
    mean_precession: float
    max_precession: float
    min_precession: float
    motion: str
    # relative to the start (for the exact motion): roots d_i = u_i - u0, 1 -/+ u0 exactly
    d_roots: tuple[float, float, float] = (0.0, 0.0, 0.0)
    one_minus_u0: float = 0.0
    one_plus_u0: float = 0.0
    rising: bool = False       # u increasing at t = 0 (theta decreasing)
    stable: bool = True        # sleeping top: J^2 omega_z^2 > 4 I m g l cos(theta0)
    limit_precession: tuple[float, float] = (math.nan, math.nan)   # phidot at u1, at u2
    K: float = math.nan        # K(m) of the period, m = (u2 - u1) / (u3 - u1) (not sleeping)


# ---- constants of the motion ---------------------------------------------------

def constants(top: Top, start: Start) -> dict[str, float]:
    """P1, P2, h (Eqs. 11.14, 11.17) and a, alpha, beta, gamma (Eq. 11.18) at t = 0."""
    _check_top(top)
    c0, s0 = _cos_sin(start.theta0)
    omega_z = start.spin + start.precession0 * c0                     # Eq. 11.8
    P2 = top.J * omega_z                                              # Eq. 11.14
    P1 = top.I * start.precession0 * s0 * s0 + P2 * c0                # Eq. 11.14
    kinetic = 0.5 * (top.I * (start.theta_rate0 ** 2 + (start.precession0 * s0) ** 2)
                     + top.J * omega_z ** 2)                          # Eq. 11.10
    h = kinetic + top.mgl * c0                                        # Eq. 11.17
    a = 2 * top.mgl / top.I                                           # Eq. 11.18
    # alpha = 2 h / I - P2^2 / (I J), written without the cancellation of P2^2 terms
    alpha = start.theta_rate0 ** 2 + (start.precession0 * s0) ** 2 + a * c0
    return {"P1": P1, "P2": P2, "energy": h, "a": a, "alpha": alpha, "beta": P1 / top.I,
            "gamma": P2 / top.I, "omega_z": omega_z}


def f_of_u(nut: Nutation, u):
    """f(u) = (1 - u^2)(alpha - a u) - (beta - gamma u)^2 (Eq. 11.19); vectorised."""
    return (1 - u * u) * (nut.alpha - nut.a * u) - (nut.beta - nut.gamma * u) ** 2


def phidot(nut: Nutation, u):
    """Precession rate (beta - gamma u) / (1 - u^2) at u = cos(theta) (Eqs. 11.16, 11.26);
    vectorised. On the vertical (u = +-1) it is undefined: inf or nan, no exception."""
    import numpy as np

    u = np.asarray(u, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        rate = (nut.beta - nut.gamma * u) / (1 - u * u)
    return float(rate) if rate.ndim == 0 else rate


# ---- the cubic, relative to the start -------------------------------------------

def _shifted_cubic(k: dict[str, float], start: Start) -> tuple[float, float, float, float]:
    """shifted_cubic from the constants of the motion already worked out (``constants``)."""
    c0_, s0 = _cos_sin(start.theta0)
    s2 = s0 * s0
    p, r = start.precession0, start.theta_rate0
    A = r * r + p * p * s2
    gamma, a = k["gamma"], k["a"]
    return (s2 * r * r, s2 * (2 * p * gamma - a - 2 * c0_ * p * p) - 2 * c0_ * r * r,
            2 * a * c0_ - A - gamma * gamma, a)


def _cubic(c: tuple[float, float, float, float], d):
    return ((c[3] * d + c[2]) * d + c[1]) * d + c[0]


def _bracketed_root(c, lo: float, hi: float) -> float:
    """The root of the cubic in [lo, hi] (f(lo) <= 0 <= f(hi) or the reverse):
    Newton steps kept inside a shrinking bracket, to the last bit."""
    flo, fhi = _cubic(c, lo), _cubic(c, hi)
    if flo == 0:
        return lo
    if fhi == 0:
        return hi
    if flo > 0 and fhi > 0 or flo < 0 and fhi < 0:
        # rounding at a (near) double root: the end nearer a zero
        return lo if abs(flo) < abs(fhi) else hi
    x = 0.5 * (lo + hi)
    for _ in range(200):
        fx = _cubic(c, x)
        if fx == 0:
            return x
        if (fx < 0) == (flo < 0):
            lo, flo = x, fx
        else:
            hi, fhi = x, fx
        slope = (3 * c[3] * x + 2 * c[2]) * x + c[1]
        step = x - fx / slope if slope else x
        x_new = step if lo < step < hi else 0.5 * (lo + hi)
        if x_new == x or hi - lo <= 4 * math.ulp(max(abs(lo), abs(hi))):
            return x_new
        x = x_new
    return x


def _quadratic_roots(a: float, b: float, c: float) -> tuple[float, float]:
    """Both roots of a x^2 + b x + c (a != 0), without cancellation; a negative
    discriminant from rounding is taken as zero (Eq. 11.19 has real roots)."""
    disc = max(b * b - 4 * a * c, 0.0)
    q = -0.5 * (b + math.copysign(math.sqrt(disc), b))
    if q == 0:
        return 0.0, 0.0
    low, high = sorted((q / a, c / q))
    return low, high


def _d_roots(c: tuple[float, float, float, float], one_minus: float,
             one_plus: float) -> tuple[float, float, float]:
    """d_roots of the shifted cubic ``c``, with 1 -+ u0 of the start."""
    if c[0] == 0:                     # u0 is a root: divide it out, Eq. 11.23
        r1, r2, r3 = sorted((0.0,) + _quadratic_roots(c[3], c[2], c[1]))
        return r1, r2, r3
    # f(-1) <= 0 < f(u0) and f(1) <= 0: one root on each side of u0, the third above 1
    d1 = _bracketed_root(c, -one_plus, 0.0)
    d2 = _bracketed_root(c, 0.0, one_minus)
    d3 = -c[2] / c[3] - d1 - d2       # sum of the roots
    return d1, d2, d3


# ---- the motion ------------------------------------------------------------------

class _Common(TypedDict):
    """The fields of a Nutation that every motion fills alike."""

    a: float
    alpha: float
    beta: float
    gamma: float
    P1: float
    P2: float
    energy: float
    one_minus_u0: float
    one_plus_u0: float
    rising: bool


def analyse(top: Top, start: Start) -> Nutation:
    """Everything about the motion from the initial state (Eqs. 11.14-11.26), exact."""
    k = constants(top, start)
    one_minus0, one_plus0 = _one_minus_plus(start.theta0)
    c0_, s0 = _cos_sin(start.theta0)
    vertical = s0 == 0.0
    if vertical and start.theta_rate0 == 0.0 and k["omega_z"] == 0.0:
        raise ValueError("a top standing or hanging on the vertical without spin does not move")
    d1, d2, d3 = _d_roots(_shifted_cubic(k, start), one_minus0, one_plus0)
    u0 = c0_
    roots = (u0 + d1, u0 + d2, u0 + d3)
    theta_of = _theta_of
    theta_max = theta_of(one_minus0 - d1, one_plus0 + d1)
    theta_min = theta_of(one_minus0 - d2, one_plus0 + d2)
    common = _Common(a=k["a"], alpha=k["alpha"], beta=k["beta"], gamma=k["gamma"], P1=k["P1"],
                     P2=k["P2"], energy=k["energy"], one_minus_u0=one_minus0,
                     one_plus_u0=one_plus0, rising=-s0 * start.theta_rate0 > 0 or
                     (start.theta_rate0 == 0 and d1 == 0.0 and d2 > 0))

    if vertical and start.theta_rate0 == 0.0:
        return _sleeping(top, start, k, roots, common)

    # the roots as the motion sees them; (u3 - u1) from the d's keeps full precision
    span, width = d3 - d1, d2 - d1
    a = k["a"]
    K = complete_K(d1, d2, d3)
    period = 4 * K / math.sqrt(a * span)
    B = start.precession0 * s0 * s0          # beta - gamma u0, exactly
    rates = [_phidot_at(k, B, d, one_minus0, one_plus0) for d in (d1, d2)]
    if theta_max - theta_min < STEADY_AMPLITUDE:
        # u1 = u2: no nutation; the period is that of small oscillations (m -> 0)
        mean = rates[0] if width == 0 else 0.5 * (rates[0] + rates[1])
        return Nutation(u_roots=roots, theta_min=theta_min, theta_max=theta_max,
                        nutation_period=period, mean_precession=mean,
                        max_precession=max(rates, key=abs), min_precession=min(rates, key=abs),
                        motion="steady", d_roots=(d1, d2, d3),
                        limit_precession=(rates[0], rates[1]), K=K, **common)
    mean = _mean_precession(k, B, d1, d2, d3, one_minus0, one_plus0, K)
    big = max(range(2), key=lambda i: abs(rates[i]))
    return Nutation(u_roots=roots, theta_min=theta_min, theta_max=theta_max,
                    nutation_period=period, mean_precession=mean,
                    max_precession=rates[big], min_precession=rates[1 - big],
                    motion=classify(*rates), d_roots=(d1, d2, d3),
                    limit_precession=(rates[0], rates[1]), K=K, **common)


def classify(phidot_at_u1: float, phidot_at_u2: float) -> str:
    """cusps if phidot vanishes at a limit, loops if it changes sign, waves otherwise.

    The numerator of phidot (beta - gamma u) is linear in u, so its signs over a
    nutation are its signs at the two limits (Figs. 11-9, 11-10).
    """
    scale = max(abs(phidot_at_u1), abs(phidot_at_u2))
    if scale == 0 or min(abs(phidot_at_u1), abs(phidot_at_u2)) <= CUSP_TOLERANCE * scale:
        return "cusps"
    return "loops" if (phidot_at_u1 < 0) != (phidot_at_u2 < 0) else "waves"


def _phidot_at(k: dict, B: float, d: float, one_minus0: float, one_plus0: float) -> float:
    """phidot at u = u0 + d: (B - gamma d) / ((1 - u)(1 + u)). A limit on the pole itself
    (u = +-1 is a root only when beta = +-gamma: the axis passes through the vertical) is
    beta / (1 + u) = gamma / 2 at u = 1 and -gamma / (1 - u) = -gamma / 2 at u = -1."""
    one_minus, one_plus = one_minus0 - d, one_plus0 + d
    if one_minus <= 0:
        return k["gamma"] / 2
    if one_plus <= 0:
        return -k["gamma"] / 2
    return (B - k["gamma"] * d) / (one_minus * one_plus)


def limit_precession_terms(nut: Nutation, start: Start) -> tuple[tuple[float, float, float],
                                                                  ...]:
    """For u1 and u2: (beta - gamma u, 1 - u, 1 + u) without cancellation, from the roots'
    offsets d = u - u0: beta - gamma u = B - gamma d with B = phidot0 sin^2(theta0), and
    1 -+ u = (1 -+ u0) -+ d. phidot there is the first over the product of the other two
    (Eq. 11.16), as `analyse` computes it; on a pole (1 - u or 1 + u is 0) see _phidot_at."""
    _, s0 = _cos_sin(start.theta0)
    B = start.precession0 * s0 * s0
    return tuple((B - nut.gamma * d, nut.one_minus_u0 - d, nut.one_plus_u0 + d)
                 for d in nut.d_roots[:2])


def _mean_precession(k: dict, B: float, d1: float, d2: float, d3: float, one_minus0: float,
                     one_plus0: float, K: float) -> float:
    """(phi advance over a period) / period, third-kind integrals in Carlson form:
    Pi(n, m) = R_F(0, 1 - m, 1) + n/3 R_J(0, 1 - m, 1, 1 - n); K = K(m) of the period."""
    from .elliptic import carlson_rj

    width, span = d2 - d1, d3 - d1
    y = (d3 - d2) / span                                           # 1 - m, exactly
    gamma = k["gamma"]
    one_minus1, one_plus1 = one_minus0 - d1, one_plus0 + d1       # 1 - u1, 1 + u1
    # beta -+ gamma = B - gamma (u0 -+ 1) with B = beta - gamma u0: no cancellation
    minus = 0.0 if k["beta"] == gamma else B - gamma * one_minus0
    plus = 0.0 if k["beta"] == -gamma else B + gamma * one_plus0
    total = 0.0
    if minus:       # n1 = (u2 - u1)/(1 - u1), 1 - n1 = (1 - u2)/(1 - u1)
        n, p = width / one_minus1, (one_minus0 - d2) / one_minus1
        total += minus * (K + n / 3 * carlson_rj(0.0, y, 1.0, p)) / one_minus1
    if plus:        # -n2 = -(u2 - u1)/(1 + u1), 1 + n2 = (1 + u2)/(1 + u1)
        n, p = -width / one_plus1, (one_plus0 + d2) / one_plus1
        total += plus * (K + n / 3 * carlson_rj(0.0, y, 1.0, p)) / one_plus1
    return total / (2 * K)


def complete_K(d1: float, d2: float, d3: float) -> float:
    """K(m), m = (u2 - u1)/(u3 - u1), from 1 - m = (u3 - u2)/(u3 - u1) (elliptic.py)."""
    from .elliptic import complete_K as K_of

    return K_of((d3 - d2) / (d3 - d1))


def _sleeping(top: Top, start: Start, k: dict, roots, common: _Common) -> Nutation:
    """Axis on the vertical (theta0 = 0 or 180 deg, thetadot0 = 0): the sleeping top.

    Upright it is stable when J^2 omega_z^2 > 4 I m g l (Eq. 11.21 with theta0 = 0), i.e.
    gamma^2 > 2 a; hanging it always is. A slight disturbance then nutates with the
    small-oscillation period 2 pi / sqrt(a (u3 - u1)) = 2 pi / sqrt(gamma^2 -+ 2 a).
    phi is undefined on the vertical: the precession answers are NaN.
    """
    upright = math.cos(start.theta0) > 0
    a, gamma = k["a"], k["gamma"]
    beat = gamma * gamma - 2 * a if upright else gamma * gamma + 2 * a
    stable = beat > 0
    period = 2 * math.pi / math.sqrt(beat) if stable else math.nan
    theta = 0.0 if upright else math.pi
    u = 1.0 if upright else -1.0
    # f = (1 - u)^2 (a (1 + u) - gamma^2) upright; -(1 + u)^2 (a (1 - u) + gamma^2) hanging
    other = gamma * gamma / a - 1 if upright else 1 + gamma * gamma / a
    roots = tuple(sorted((u, u, other)))
    d = tuple(r - u for r in roots)
    return Nutation(u_roots=roots, theta_min=theta, theta_max=theta, nutation_period=period,
                    mean_precession=math.nan, max_precession=math.nan,
                    min_precession=math.nan, motion="sleeping", d_roots=d, stable=stable,
                    **common)


# ---- the fast top (gamma^2 >> a) ------------------------------------------------

def fast_nutation_period(I: V, J: V, omega_z: V) -> V:
    """2 pi I / (J omega_z): 2 pi over gamma = J omega_z / I, which is sqrt(a (u3 - u1))
    with u3 ~ gamma^2 / a for a fast top."""
    return 2 * pi_like(I, J, omega_z) * I / (J * omega_z)


def fast_mean_precession(mgl: V, J: V, omega_z: V) -> V:
    """m g l / (J omega_z) = a / (2 gamma): the slow root of Eq. 11.20 for gamma^2 >> a."""
    return mgl / (J * omega_z)


def fast_nutation_amplitude(I: V, mgl: V, theta0: V, J: V, omega_z: V) -> V:
    """theta_max - theta_min ~ 2 I m g l sin(theta0) / (J omega_z)^2, released from rest.

    From Eq. 11.23, a (1 - u^2) = gamma^2 (u2 - u) at u = u1; for gamma^2 >> a,
    u2 - u1 ~ a sin^2(theta0) / gamma^2 and dtheta ~ du / sin(theta0).
    """
    return 2 * I * mgl * sin(theta0) / (J * omega_z) ** 2


# ---- helpers ---------------------------------------------------------------------

def _check_top(top: Top) -> None:
    if not (top.I > 0 and top.J > 0 and top.mgl > 0):
        raise ValueError("I, J and m g l must be positive")
    if not all(map(math.isfinite, (top.I, top.J, top.mgl))):
        raise ValueError("I, J and m g l must be finite")


def _cos_sin(theta: float) -> tuple[float, float]:
    """cos and sin, exact 0 and +-1 on the axes (sin(pi) is 1.2e-16 in floating point)."""
    c, s = math.cos(theta), math.sin(theta)
    if abs(s) < 1e-15:
        return (1.0 if c > 0 else -1.0), 0.0
    if abs(c) < 1e-15:
        return 0.0, s
    return c, s


def _one_minus_plus(theta: float) -> tuple[float, float]:
    """(1 - cos theta, 1 + cos theta) = (2 sin^2(theta/2), 2 cos^2(theta/2)), no cancellation."""
    c, s = _cos_sin(theta)
    if s == 0:
        return (0.0, 2.0) if c > 0 else (2.0, 0.0)
    return 2 * math.sin(theta / 2) ** 2, 2 * math.cos(theta / 2) ** 2


def _theta_of(one_minus: float, one_plus: float) -> float:
    """_theta_from_one_minus_plus for one pair of floats, in plain floats (math.asin, no
    numpy: `gyro check` does not import it): the same clip and choice, the same angle
    within an ulp or two (numpy's arcsin and math's may round differently)."""
    one_minus = min(max(one_minus, 0.0), 2.0)   # as np.clip, NaN and -0.0 included
    one_plus = min(max(one_plus, 0.0), 2.0)
    if one_minus <= one_plus:
        return 2 * math.asin(math.sqrt(0.5 * one_minus))
    return math.pi - 2 * math.asin(math.sqrt(0.5 * one_plus))


def _theta_from_one_minus_plus(one_minus, one_plus):
    """theta from 1 - u and 1 + u: 2 asin(sqrt((1 - u)/2)) near the top, pi - 2 asin(
    sqrt((1 + u)/2)) near the bottom (both well conditioned there); vectorised."""
    import numpy as np

    one_minus = np.clip(one_minus, 0.0, 2.0)
    one_plus = np.clip(one_plus, 0.0, 2.0)
    theta = np.where(one_minus <= one_plus, 2 * np.arcsin(np.sqrt(0.5 * one_minus)),
                     np.pi - 2 * np.arcsin(np.sqrt(0.5 * one_plus)))
    return float(theta) if np.ndim(theta) == 0 else theta
