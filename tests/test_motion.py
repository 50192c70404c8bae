"""Exact theta(t), phi(t), psi(t) (gyro_cli.physics.motion) against Lagrange's equations 11.13
integrated in the test (tests/lagrange_top.py), against the energy integral by finite
differences, and across the start (either direction, any point of the band)."""

from __future__ import annotations

import functools
import math

import numpy as np
import pytest
from lagrange_top import integrate
from test_nutation import CASES, RPM, TOP

from gyro_cli.physics import motion
from gyro_cli.physics.nutation import Start, analyse


@functools.cache  # theta and phi, psi are checked against one integration
def _reference(top, start, periods: float, n: int = 2001):
    nut = analyse(top, start)
    t = np.linspace(0.0, periods * nut.nutation_period, n)
    ref = integrate(top.I, top.J, top.mgl, start.theta0, start.spin, start.precession0,
                    start.theta_rate0, t_end=t[-1], t_eval=t)
    return nut, t, ref.sol.y


def test_theta_of_t_matches_integration_over_5_periods():
    """Every seeded random top: exact theta(t) within 1e-8 rad of the integration."""
    for top, start in CASES:
        _, t, y = _reference(top, start, 5.0)
        theta = motion.theta_of_t(top, start, t)
        assert np.max(np.abs(theta - y[0])) < 1e-8, start
        assert theta[0] == pytest.approx(start.theta0, abs=1e-12)


def test_phi_and_psi_match_integration():
    """phi(t) and psi(t) (third-kind integrals) against the integrated angles, 5 periods."""
    for top, start in CASES:
        _, t, y = _reference(top, start, 5.0)
        theta, phi, psi = motion.angles_of_t(top, start, t)
        scale_phi = 1 + np.max(np.abs(y[1]))
        scale_psi = 1 + np.max(np.abs(y[2]))
        assert np.max(np.abs(phi - y[1])) < 1e-8 * scale_phi, start
        assert np.max(np.abs(psi - y[2])) < 1e-8 * scale_psi, start


@pytest.mark.parametrize("theta_rate0", [2.0, -2.0, 0.0])
def test_start_anywhere_in_the_band_moving_either_way(theta_rate0):
    """From the same theta0, thrown up, thrown down or at rest: theta(t) follows the
    integration, and the first thetadot has the sign given."""
    start = Start(math.radians(70), 1500 * RPM, 3.0, theta_rate0)
    _, t, y = _reference(TOP, start, 3.0, 1501)
    theta = motion.theta_of_t(TOP, start, t)
    assert np.max(np.abs(theta - y[0])) < 1e-8
    if theta_rate0:
        assert np.sign(theta[1] - theta[0]) == np.sign(theta_rate0)


def test_energy_integral_by_finite_differences():
    """(sin th thetadot)^2 = f(cos th) (Eq. 11.19) along the exact theta(t), thetadot by
    central differences."""
    start = Start(math.radians(50), 900 * RPM, -2.0, 1.0)
    nut = analyse(TOP, start)
    h = nut.nutation_period * 1e-5
    t = np.linspace(0.1, 2.0, 97)
    th = motion.theta_of_t(TOP, start, t)
    thd = (motion.theta_of_t(TOP, start, t + h) - motion.theta_of_t(TOP, start, t - h)) / (2 * h)
    u = np.cos(th)
    f = (1 - u * u) * (nut.alpha - nut.a * u) - (nut.beta - nut.gamma * u) ** 2
    scale = nut.a + abs(nut.alpha) + nut.gamma ** 2
    assert np.max(np.abs((np.sin(th) * thd) ** 2 - f)) < 1e-6 * scale


def test_negative_times_run_the_motion_backwards():
    start = Start(math.radians(40), 1200 * RPM, 1.0, 0.5)
    nut = analyse(TOP, start)
    t = np.linspace(0, 2.5 * nut.nutation_period, 801)
    back = integrate(TOP.I, TOP.J, TOP.mgl, start.theta0, start.spin, start.precession0,
                     start.theta_rate0, t_end=-t[-1], t_eval=-t).sol.y
    theta, phi, psi = motion.angles_of_t(TOP, start, -t)
    assert np.max(np.abs(theta - back[0])) < 1e-8
    assert np.max(np.abs(phi - back[1])) < 1e-8 * (1 + np.max(np.abs(back[1])))


def test_phi_advances_by_mean_precession_each_period():
    """phi(t + T) - phi(t) = mean precession x T, with phi from the integration."""
    start = Start(math.radians(35), 2000 * RPM, -1.0)
    nut = analyse(TOP, start)
    T = nut.nutation_period
    t = np.array([0.0, 0.3 * T, 0.71 * T])
    ref = integrate(TOP.I, TOP.J, TOP.mgl, start.theta0, start.spin, start.precession0,
                    start.theta_rate0, t_end=4 * T, t_eval=np.concatenate([t, t + 3 * T]))
    phi = ref.sol.y[1]
    assert np.allclose(phi[3:] - phi[:3], 3 * T * nut.mean_precession, rtol=1e-8)


def test_steady_and_sleeping_motion_is_constant_theta():
    start = Start(0.0, 1800 * RPM)
    t = np.linspace(0, 1, 5)
    theta, phi, psi = motion.angles_of_t(TOP, start, t)
    assert np.all(theta == 0) and np.all(phi == 0)
    assert psi == pytest.approx(1800 * RPM * t)
    # steady precession: phi = phidot t, theta = theta0 (Eq. 11.20 root from the quadratic)
    theta0 = math.radians(30)
    A, B, C = (TOP.J - TOP.I) * math.cos(theta0), TOP.J * 1800 * RPM, -TOP.mgl
    rate = (-B + math.sqrt(B * B - 4 * A * C)) / (2 * A)
    steady = Start(theta0, 1800 * RPM, rate)
    theta, phi, _ = motion.angles_of_t(TOP, steady, t)
    assert np.allclose(theta, theta0, atol=1e-9) and np.allclose(phi, rate * t, rtol=1e-9)


def test_a_million_points_vectorised():
    """10^6 times in one call: finite, inside the band (timing is in benchmarks/)."""
    start = Start(math.radians(30), 1800 * RPM)
    nut = analyse(TOP, start)
    theta = motion.theta_of_t(TOP, start, np.linspace(0, 1000 * nut.nutation_period, 10 ** 6))
    assert theta.shape == (10 ** 6,)
    assert np.all(theta >= nut.theta_min - 1e-12) and np.all(theta <= nut.theta_max + 1e-12)


@pytest.mark.parametrize("theta0, precession0", [(0.0, 0.0), (0.0, 2.0), (math.pi, 0.0)])
def test_axis_through_the_vertical(theta0, precession0):
    """Thrown from the vertical (P1 = +-P2): Euler angles are singular there, so the reference
    is the quaternion integration of gyro_cli.physics.simulate (no Euler-angle equation). theta(t)
    and the period agree; the azimuth jumps by +-pi at each passage, so the simulated mean
    precession is the analytic one (the continuous advance) plus or minus pi / T."""
    from gyro_cli.physics.simulate import Params, simulate

    start = Start(theta0, 1800 * RPM if theta0 == 0 else 50.0, precession0, 1.0)
    nut = analyse(TOP, start)
    assert nut.motion == "waves"
    assert (nut.theta_min == 0.0) if theta0 == 0 else (nut.theta_max == math.pi)
    p = Params(TOP.I, TOP.J, TOP.mgl, start.theta0, start.spin, start.precession0,
               start.theta_rate0)
    sim = simulate(p, p, t_end=3 * nut.nutation_period, samples=601)
    assert np.max(np.abs(motion.theta_of_t(TOP, start, sim.t) - sim.theta)) < 1e-9
    assert nut.nutation_period == pytest.approx(sim.nutation_period, rel=1e-8)
    if theta0 != 0:
        return      # simulate's azimuth through the lowest point is not a stable measure
    jump = math.pi / nut.nutation_period
    assert min(abs(nut.mean_precession + s * jump - sim.mean_precession) for s in (1, -1)) \
        < 1e-6 * jump
