"""The heavy top's motion in time, exactly: theta(t), phi(t), psi(t).

With f(u) = a (u - u1)(u - u2)(u - u3) (Eq. 11.19) the substitution
u = u1 + (u2 - u1) sin^2(s) turns u'^2 = f(u) into

    s' = omega sqrt(1 - m sin^2 s),   omega = sqrt(a (u3 - u1)) / 2,  m = (u2 - u1)/(u3 - u1),

so s = am(omega t + c) and u(t) = u1 + (u2 - u1) sn^2(omega t + c | m): theta is
largest (u = u1) at omega t + c = 0 and smallest (u = u2) at K(m). The phase c
puts u(0) = u0 on the right branch: sn^2(c) = (u0 - u1)/(u2 - u1), c in [0, K]
when u rises at t = 0 (theta falling), in [K, 2K] when it falls.

phi and psi follow from Eq. 11.16 with the partial fractions
phidot = 1/2 [(beta - gamma)/(1 - u) + (beta + gamma)/(1 + u)] and
psidot = P2/J - gamma - 1/2 [(beta - gamma)/(1 - u) - (beta + gamma)/(1 + u)]:
with 1 - u = (1 - u1)(1 - n1 sin^2 s), 1 + u = (1 + u1)(1 + n2 sin^2 s) each term
integrates to an incomplete elliptic integral of the third kind,
Pi(n; s | m) = sin s R_F(cos^2 s, 1 - m sin^2 s, 1)
               + n/3 sin^3 s R_J(cos^2 s, 1 - m sin^2 s, 1, 1 - n sin^2 s),
and over each half period 2 Pi(n | m) (so phi(t + T) = phi(t) + mean phidot T).

Vectorised over t with numpy and scipy.special (imported inside the functions).
"""

from __future__ import annotations

import math

import numpy as np

from .nutation import Nutation, Start, Top, _cos_sin, _theta_from_one_minus_plus, analyse


def phase(nut: Nutation) -> tuple[float, float, float, float]:
    """(omega, m, K, c): u(t) = u1 + (u2 - u1) sn^2(omega t + c | m)."""
    from scipy.special import elliprf

    d1, d2, d3 = nut.d_roots
    width, span = d2 - d1, d3 - d1
    omega = 0.5 * math.sqrt(nut.a * span)
    m = width / span
    y = (d3 - d2) / span                         # 1 - m, exactly
    K = float(elliprf(0.0, y, 1.0))
    x = -d1 / width                              # sn^2(c) = (u0 - u1)/(u2 - u1)
    # F(asin sqrt x | m) = sqrt(x) R_F(1 - x, 1 - m x, 1), 1 - x = d2/width, 1 - m x = d3/span
    F = math.sqrt(x) * float(elliprf(d2 / width, d3 / span, 1.0)) if x > 0 else 0.0
    c = F if nut.rising else 2 * K - F
    return omega, m, K, c


def _nutates(nut: Nutation) -> bool:
    d1, d2, _ = nut.d_roots
    return nut.motion not in ("sleeping", "steady") and d2 > d1


def _grid(t) -> np.ndarray:
    return np.asarray(t, dtype=float)


def theta_of_t(top: Top, start: Start, t, nut: Nutation | None = None) -> np.ndarray:
    """theta(t) from u(t) = u1 + (u2 - u1) sn^2(omega t + c | m); exact, vectorised."""
    from scipy.special import ellipj

    nut = nut or analyse(top, start)
    t = _grid(t)
    if not _nutates(nut):
        theta = start.theta0 if nut.motion == "steady" else nut.theta_min
        return np.full(t.shape, float(theta))
    omega, m, K, c = phase(nut)
    tau = np.mod(omega * t + c, 2 * K)           # sn^2 has period 2K
    sn, cn, _, _ = ellipj(tau, m)
    d1, d2, _ = nut.d_roots
    width = d2 - d1
    # 1 -/+ u from u1 when sn^2 is small, from u2 (via cn^2 = 1 - sn^2) when it is not
    s2, c2 = sn * sn, cn * cn
    low = s2 <= 0.5
    one_minus = np.where(low, (nut.one_minus_u0 - d1) - width * s2, (nut.one_minus_u0 - d2)
                         + width * c2)
    one_plus = np.where(low, (nut.one_plus_u0 + d1) + width * s2, (nut.one_plus_u0 + d2)
                        - width * c2)
    return _theta_from_one_minus_plus(one_minus, one_plus)


def angles_of_t(top: Top, start: Start, t,
                nut: Nutation | None = None) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(theta, phi, psi) at times t, with phi(0) = psi(0) = 0 (Eqs. 11.16, 11.19), exact.

    On the vertical (sleeping top) phi is undefined: phi = 0 and psi = omega_z t.
    """
    from scipy.special import ellipj, elliprf, elliprj

    nut = nut or analyse(top, start)
    t = _grid(t)
    theta = theta_of_t(top, start, t, nut)
    if nut.motion == "sleeping":
        return theta, np.zeros(t.shape), nut.P2 / top.J * t
    if not _nutates(nut):
        rate = nut.mean_precession
        spin = nut.P2 / top.J - rate * math.cos(start.theta0)
        return theta, rate * t, spin * t

    omega, m, K, c = phase(nut)
    d1, d2, d3 = nut.d_roots
    width, y = d2 - d1, (d3 - d2) / (d3 - d1)
    one_minus1, one_plus1 = nut.one_minus_u0 - d1, nut.one_plus_u0 + d1
    B = _B(start)
    minus = 0.0 if nut.beta == nut.gamma else B - nut.gamma * nut.one_minus_u0   # beta - gamma
    plus = 0.0 if nut.beta == -nut.gamma else B + nut.gamma * nut.one_plus_u0    # beta + gamma
    terms = []     # (coefficient / (2 (1 -+ u1) omega), n, 1 - n)
    if minus:
        terms.append((minus / (2 * one_minus1 * omega), width / one_minus1,
                      (nut.one_minus_u0 - d2) / one_minus1))
    if plus:
        terms.append((plus / (2 * one_plus1 * omega), -width / one_plus1,
                      (nut.one_plus_u0 + d2) / one_plus1))
    K_c = K

    def integrals(tau: np.ndarray) -> list[np.ndarray]:
        """int_0^tau of 1/(1 - n sn^2) d tau' for each term, any tau >= 0 (periodicity)."""
        turns, r = np.divmod(tau, 2 * K_c)
        sn, cn, dn, _ = ellipj(r, m)
        sn = np.abs(sn)
        x, yy = cn * cn, dn * dn
        rf = elliprf(x, yy, 1.0)
        out = []
        for _, n, p in terms:
            complete = K_c + n / 3 * float(elliprj(0.0, y, 1.0, p))   # Pi(n | m)
            part = sn * rf + n / 3 * sn ** 3 * elliprj(x, yy, 1.0, 1 - n * sn * sn)
            part = np.where(r <= K_c, part, 2 * complete - part)        # am(r) past pi/2
            out.append(2 * complete * turns + part)
        return out

    tau = omega * t + c
    sign = np.sign(tau)
    now = integrals(np.abs(tau))
    at0 = integrals(np.array([c]))
    phi = np.zeros(t.shape)
    psi = (nut.P2 / top.J - nut.gamma) * t
    for (coeff, _, _), value, zero in zip(terms, now, at0):
        swept = sign * value - zero[0]
        phi += coeff * swept
    # psi: the (1 - u) term with the opposite sign, the (1 + u) term with the same
    for (coeff, n, _), value, zero in zip(terms, now, at0):
        swept = sign * value - zero[0]
        psi += (-coeff if n > 0 else coeff) * swept
    return theta, phi, psi


def _B(start: Start) -> float:
    """beta - gamma u0 = phidot0 sin^2(theta0) (Eq. 11.14)."""
    return start.precession0 * _cos_sin(start.theta0)[1] ** 2
