"""gyro_cli.physics.nutation against independent references: Lagrange's equations 11.13 integrated
numerically (tests/lagrange_top.py), Eq. 11.25 and Eq. 11.20 written out here, limiting
cases (fast top, sleeping top, steady precession) and the cubic itself."""

from __future__ import annotations

import math

import numpy as np
import pytest
from lagrange_top import integrate

from gyro_cli.physics.nutation import (
    Start,
    Top,
    analyse,
    fast_mean_precession,
    fast_nutation_amplitude,
    fast_nutation_period,
    phidot,
)

# problem 11/3's top: 3 ozf, k_z = 0.84 in, k_O = 1.80 in, l = 1.5 in, g = 32.2 ft/s^2
G = 32.2 * 0.3048
M = 3 * 0.45359237 * 9.80665 / 16 / G
TOP = Top(I=M * (1.80 * 0.0254) ** 2, J=M * (0.84 * 0.0254) ** 2, mgl=M * G * 1.5 * 0.0254)
RPM = math.pi / 30


def random_cases(n: int = 22, seed: int = 2026) -> list[tuple[Top, Start]]:
    """Seeded tops: slow and fast spin, upright and hanging, released, pushed and thrown
    (thetadot0 of either sign). Axes that come within 3 deg of the vertical are redrawn."""
    rng = np.random.default_rng(seed)
    out = []
    while len(out) < n:
        I = 10 ** rng.uniform(-5, -1)
        top = Top(I=I, J=I * rng.uniform(0.1, 1.9), mgl=I * rng.uniform(2, 80))
        a = 2 * top.mgl / top.I
        theta0 = math.radians(rng.uniform(10, 170))
        gamma = math.sqrt(a) * rng.uniform(0.5, 5.0)
        # released, pushed either way, or pushed near the slow steady rate a / (2 gamma)
        precession0 = [0.0, rng.uniform(-1.5, 1.5) * math.sqrt(a),
                       rng.uniform(0.3, 1.7) * a / (2 * gamma)][len(out) % 3]
        theta_rate0 = [0.0, rng.choice([-1, 1]) * rng.uniform(0.1, 0.8) * math.sqrt(a)][
            (len(out) // 3) % 2]
        spin = gamma * top.I / top.J - precession0 * math.cos(theta0)
        start = Start(theta0, spin, precession0, theta_rate0)
        nut = analyse(top, start)
        if nut.theta_min > math.radians(3) and nut.theta_max < math.radians(177) and \
                nut.theta_max - nut.theta_min > 1e-3:
            out.append((top, start))
    return out


CASES = random_cases()


@pytest.fixture(scope="module")
def measured():
    out = []
    for top, start in CASES:
        nut = analyse(top, start)
        ref = integrate(top.I, top.J, top.mgl, start.theta0, start.spin, start.precession0,
                        start.theta_rate0, t_end=4.3 * nut.nutation_period)
        out.append((top, start, nut, ref))
    return out


def test_random_tops_against_lagrange_integration(measured):
    """>= 20 tops: theta limits, period and mean precession to 1e-7 relative."""
    assert len(measured) >= 20
    motions = set()
    for _top, start, nut, ref in measured:
        assert len(ref.t_max) >= 3, start
        assert nut.theta_min == pytest.approx(ref.theta_min, rel=1e-7), start
        assert nut.theta_max == pytest.approx(ref.theta_max, rel=1e-7), start
        assert nut.nutation_period == pytest.approx(ref.nutation_period, rel=1e-7), start
        scale = max(abs(nut.max_precession), abs(nut.min_precession))
        assert nut.mean_precession == pytest.approx(ref.mean_precession, rel=1e-7,
                                                    abs=1e-9 * scale), start
        motions.add(nut.motion)
    assert {"cusps", "loops", "waves"} <= motions


def test_motion_word_against_integrated_phidot(measured):
    """loops: the integrated phidot changes sign; waves: it keeps one; cusps: it touches 0."""
    for _top, start, nut, ref in measured:
        t = np.linspace(0, ref.t_max[-1], 4001)
        phd = ref.sol.sol(t)[4]
        scale = np.max(np.abs(phd))
        if nut.motion == "loops":
            assert phd.min() < -1e-4 * scale and phd.max() > 1e-4 * scale, start
        elif nut.motion == "waves":
            assert np.all(phd > 0) or np.all(phd < 0), start
        else:
            assert nut.motion == "cusps"
            assert np.min(np.abs(phd)) < 1e-6 * scale, start
        # max/min precession: the integrated phidot at theta's turning points
        assert np.max(np.abs(phd)) <= abs(nut.max_precession) * (1 + 1e-6), start


def test_u_roots_are_the_zeros_of_eq_11_19(measured):
    """f(u) of Eq. 11.19 (written here from P1, P2, h) vanishes at the roots; f(u0) >= 0."""
    for top, start, nut, _ in measured:
        c, s = math.cos(start.theta0), math.sin(start.theta0)
        wz = start.spin + start.precession0 * c
        P2 = top.J * wz
        P1 = top.I * start.precession0 * s * s + P2 * c
        h = 0.5 * (top.I * (start.theta_rate0 ** 2 + (start.precession0 * s) ** 2)
                   + top.J * wz * wz) + top.mgl * c
        a, alpha = 2 * top.mgl / top.I, 2 * h / top.I - P2 * P2 / (top.I * top.J)
        beta, gamma = P1 / top.I, P2 / top.I
        assert (nut.a, nut.beta, nut.gamma) == pytest.approx((a, beta, gamma), rel=1e-12)
        assert nut.alpha == pytest.approx(alpha, rel=1e-9, abs=1e-9 * (a + gamma ** 2))
        assert nut.energy == pytest.approx(h, rel=1e-12)

        def f(u):
            return (1 - u * u) * (alpha - a * u) - (beta - gamma * u) ** 2  # noqa: B023 (called in this iteration)
        scale = a + alpha + beta ** 2 + gamma ** 2
        u1, u2, u3 = nut.u_roots
        assert u1 <= math.cos(start.theta0) <= u2 <= 1 <= u3
        for u in nut.u_roots:
            assert abs(f(u)) < 1e-11 * scale
        # and the cubic is a (u - u1)(u - u2)(u - u3): compare at a point away from the roots
        assert f(-2.0) == pytest.approx(a * (-2 - u1) * (-2 - u2) * (-2 - u3), rel=1e-9)


def test_phidot_is_eq_11_16():
    """phidot(nut, u) against (P1 - P2 cos th) / (I sin^2 th), P1 and P2 from Eq. 11.14."""
    start = Start(math.radians(50), 150.0, -4.0, 1.0)
    nut = analyse(TOP, start)
    c, s = math.cos(start.theta0), math.sin(start.theta0)
    P2 = TOP.J * (start.spin + start.precession0 * c)
    P1 = TOP.I * start.precession0 * s * s + P2 * c
    th = np.linspace(0.3, 2.5, 7)
    assert np.allclose(phidot(nut, np.cos(th)), (P1 - P2 * np.cos(th)) / (TOP.I * np.sin(th) ** 2),
                       rtol=1e-12)
    assert phidot(nut, c) == pytest.approx(start.precession0, rel=1e-12)


@pytest.mark.parametrize("theta0_deg, spin_rpm", [(30, 1800), (60, 1000), (120, 600), (10, 5000)])
def test_release_from_rest_is_eq_11_25_with_cusps(theta0_deg, spin_rpm):
    """phidot0 = thetadot0 = 0: cusps, theta_min = theta0 and theta_max from Eq. 11.25 (as
    corrected in the errata: gamma^2/a under the root), here by hand."""
    theta0 = math.radians(theta0_deg)
    nut = analyse(TOP, Start(theta0, spin_rpm * RPM))
    a = 2 * TOP.mgl / TOP.I
    gamma = TOP.J * spin_rpm * RPM / TOP.I
    u1 = gamma ** 2 / (2 * a) - math.sqrt(gamma ** 4 / (4 * a * a) - gamma ** 2 / a
                                          * math.cos(theta0) + 1)
    assert nut.motion == "cusps"
    assert nut.theta_min == pytest.approx(theta0, rel=1e-14)
    assert nut.theta_max == pytest.approx(math.acos(u1), rel=1e-9)
    assert nut.min_precession == 0.0
    # phidot at theta_max from Eq. 11.26, gamma (u2 - u1) / (1 - u1^2)
    assert nut.max_precession == pytest.approx(gamma * (math.cos(theta0) - u1) / (1 - u1 * u1),
                                               rel=1e-9)


def test_fast_top_approximations_converge():
    """As the spin grows the exact period, mean precession and amplitude approach the fast-top
    forms, the relative error falling like a / gamma^2 (x100 spin: error / ~10^4)."""
    theta0 = math.radians(40)
    errors = []
    for spin in (2000 * RPM, 20000 * RPM, 200000 * RPM):
        nut = analyse(TOP, Start(theta0, spin))
        errors.append([abs(fast_nutation_period(TOP.I, TOP.J, spin) / nut.nutation_period - 1),
                       abs(fast_mean_precession(TOP.mgl, TOP.J, spin) / nut.mean_precession - 1),
                       abs(fast_nutation_amplitude(TOP.I, TOP.mgl, theta0, TOP.J, spin)
                           / (nut.theta_max - nut.theta_min) - 1)])
    errors = np.array(errors)
    assert np.all(errors[1] < errors[0] / 50) and np.all(errors[2] < errors[1] / 50)
    assert np.all(errors[2] < 1e-4)


def test_fast_top_mean_precession_is_half_the_largest():
    """A fast top released from rest: phidot runs from 0 to ~2x its mean (cycloid-like cusps)."""
    nut = analyse(TOP, Start(math.radians(40), 50000 * RPM))
    assert nut.max_precession == pytest.approx(2 * nut.mean_precession, rel=1e-3)


def steady_rates(theta0: float, spin: float) -> list[float]:
    """Eq. 11.13 with thetaddot = 0, written with psidot: (J - I) cos th phidot^2 + J psidot
    phidot - m g l = 0."""
    A = (TOP.J - TOP.I) * math.cos(theta0)
    B, C = TOP.J * spin, -TOP.mgl
    root = math.sqrt(B * B - 4 * A * C)
    return [(-B + root) / (2 * A), (-B - root) / (2 * A)]


@pytest.mark.parametrize("which", [0, 1])
def test_steady_precession_has_no_nutation(which):
    """Started at a steady rate (Eq. 11.20): steady, theta constant, phidot = the rate, and the
    period that of small oscillations: integrate a slightly disturbed start to measure it."""
    theta0, spin = math.radians(30), 1800 * RPM
    rate = steady_rates(theta0, spin)[which]
    nut = analyse(TOP, Start(theta0, spin, rate))
    assert nut.motion == "steady"
    assert nut.theta_max - nut.theta_min < 1e-9
    assert nut.mean_precession == pytest.approx(rate, rel=1e-9)
    assert nut.theta_min == pytest.approx(theta0, abs=1e-9)
    ref = integrate(TOP.I, TOP.J, TOP.mgl, theta0, spin, rate, 1e-6,
                    t_end=5.5 * nut.nutation_period)
    assert nut.nutation_period == pytest.approx(ref.nutation_period, rel=1e-5)


def test_near_steady_start_resolves_a_tiny_nutation():
    """A near-double root: a thetadot0 of 1e-7 rad/s on top of steady precession. The band
    (about 1e-9 rad wide) and its period against the integration."""
    theta0, spin = math.radians(30), 1800 * RPM
    rate = steady_rates(theta0, spin)[0]
    start = Start(theta0, spin, rate, 1e-7)
    nut = analyse(TOP, start)
    ref = integrate(TOP.I, TOP.J, TOP.mgl, *start.__dict__.values(), t_end=4.5 * 0.2)
    assert nut.theta_max - nut.theta_min == pytest.approx(ref.theta_max - ref.theta_min,
                                                          rel=1e-3)
    # thetadot ~ 1e-7 rad/s against atol 1e-13: the integration's turning times carry ~1e-7
    assert nut.nutation_period == pytest.approx(ref.nutation_period, rel=1e-6)


def test_sleeping_top_stability_and_period():
    """theta0 = 0: sleeping; stable iff J^2 omega_z^2 > 4 I m g l, checked by integrating a
    start tilted by 1e-5 rad: stable stays within 1e-4 rad, unstable falls. The stable
    period is the limit of the tilted top's nutation period."""
    least = 2 * math.sqrt(TOP.I * TOP.mgl) / TOP.J
    for factor, stable in ((1.5, True), (0.8, False)):
        nut = analyse(TOP, Start(0.0, factor * least))
        assert nut.motion == "sleeping" and nut.stable is stable
        assert nut.theta_min == nut.theta_max == 0.0
        assert math.isnan(nut.mean_precession)
        a, gamma = 2 * TOP.mgl / TOP.I, TOP.J * factor * least / TOP.I
        t_end = 30 / math.sqrt(abs(gamma ** 2 - 2 * a))      # 5 periods, or e^15 growth
        ref = integrate(TOP.I, TOP.J, TOP.mgl, 1e-5, factor * least, t_end=t_end)
        grew = np.max(ref.sol.y[0])
        assert bool(grew < 1e-4) == stable
        if stable:
            assert nut.nutation_period == pytest.approx(ref.nutation_period, rel=1e-6)


def test_hanging_sleeping_top_is_stable():
    nut = analyse(TOP, Start(math.pi, 100.0))
    assert nut.motion == "sleeping" and nut.stable and nut.theta_min == math.pi
    ref = integrate(TOP.I, TOP.J, TOP.mgl, math.pi - 1e-5, 100.0, t_end=1.0)
    assert nut.nutation_period == pytest.approx(ref.nutation_period, rel=1e-6)
    assert np.min(ref.sol.y[0]) > math.pi - 1e-4


def test_thrown_through_the_start_either_way():
    """thetadot0 of either sign from the same point: same band, same period (time reversal
    of theta), and both against the integration."""
    base = dict(theta0=math.radians(50), spin=1200 * RPM, precession0=2.0)
    a = analyse(TOP, Start(**base, theta_rate0=1.5))
    b = analyse(TOP, Start(**base, theta_rate0=-1.5))
    assert (a.theta_min, a.theta_max, a.nutation_period) == pytest.approx(
        (b.theta_min, b.theta_max, b.nutation_period), rel=1e-13)
    assert a.theta_min < base["theta0"] < a.theta_max
    ref = integrate(TOP.I, TOP.J, TOP.mgl, base["theta0"], base["spin"], 2.0, -1.5,
                    t_end=4.5 * a.nutation_period)
    assert a.theta_min == pytest.approx(ref.theta_min, rel=1e-7)
    assert a.theta_max == pytest.approx(ref.theta_max, rel=1e-7)


def test_bad_tops_are_refused():
    for top in (Top(0.0, 1.0, 1.0), Top(1.0, -1.0, 1.0), Top(1.0, 1.0, 0.0)):
        with pytest.raises(ValueError):
            analyse(top, Start(0.5, 10.0))
    with pytest.raises(ValueError):
        analyse(TOP, Start(0.0, 0.0))


def test_limit_angles_from_one_minus_plus_are_acos_and_the_vectorised_within_an_ulp_or_two():
    """analyse's theta of a limit in plain floats (_theta_of, math.asin: no numpy) is the
    vectorised _theta_from_one_minus_plus's (numpy's arcsin) within two ulps, with the same
    clipping, -0.0 and NaN, and both are acos(u) within a few ulps where acos itself is well
    conditioned."""
    from gyro_cli.physics.nutation import _theta_from_one_minus_plus, _theta_of

    rng = np.random.default_rng(7)
    u = np.concatenate([rng.uniform(-1, 1, 4000), 1 - 10.0 ** rng.uniform(-16, 0, 500),
                        -1 + 10.0 ** rng.uniform(-16, 0, 500)])
    one_minus, one_plus = 1 - u, 1 + u
    edges = [(0.0, 2.0), (2.0, 0.0), (-0.0, 2.0), (-1e-18, 2.0), (2.0 + 1e-15, -1e-18),
             (1.0, 1.0), (math.nan, 1.0), (1.0, math.nan)]
    pairs = list(zip(one_minus.tolist(), one_plus.tolist())) + edges
    vectorised = _theta_from_one_minus_plus(np.array([p[0] for p in pairs]),
                                            np.array([p[1] for p in pairs]))
    for (a, b), expected in zip(pairs, vectorised.tolist()):
        got = _theta_of(a, b)
        if math.isnan(expected):
            assert math.isnan(got), (a, b)
            continue
        assert abs(got - expected) <= 2 * math.ulp(expected), (a, b)
        assert math.copysign(1, got) == math.copysign(1, expected), (a, b)
    for x in u[:4000].tolist():   # away from the poles acos(u) is accurate itself
        assert _theta_of(1 - x, 1 + x) == pytest.approx(math.acos(x), rel=1e-14, abs=1e-15)
    assert (_theta_of(0.0, 2.0), _theta_of(2.0, 0.0)) == (0.0, math.pi)  # upright, hanging
    assert abs(_theta_of(1.0, 1.0) - math.pi / 2) <= 2 * math.ulp(math.pi / 2)  # horizontal


def test_K_of_the_period_is_the_first_kind_integral_by_quadrature():
    """Nutation.K (the K(m) analyse worked the period from, and the worked answer shows)
    against K(m) = int_0^(pi/2) ds / sqrt(1 - m sin^2 s) by the trapezium rule, which
    converges geometrically for this periodic integrand, and T = 4 K / sqrt(a (u3 - u1))."""
    for top, start in CASES[:8]:
        nut = analyse(top, start)
        u1, u2, u3 = nut.u_roots
        m = (u2 - u1) / (u3 - u1)
        s = np.linspace(0.0, math.pi / 2, 2001)
        f = 1 / np.sqrt(1 - m * np.sin(s) ** 2)
        K = float((f.sum() - 0.5 * (f[0] + f[-1])) * (s[1] - s[0]))
        assert nut.K == pytest.approx(K, rel=1e-12)
        assert nut.nutation_period == pytest.approx(4 * K / math.sqrt(nut.a * (u3 - u1)),
                                                    rel=1e-12)
