"""Stability of steady motions (gyro_cli/physics/stability.py) against integration.

Each verdict is checked by integrating a perturbed motion from the full equations of
motion written here (nothing from gyro_cli moves the body):

- the heavy top: H' = l k x (-m g K) (moment of gravity about the fixed point),
  k' = omega x k, omega = H / I + (1/J - 1/I) (H . k) k (world axes, no Euler angle);
- the rolling disk: Newton-Euler with the contact force solved from the rolling
  constraint at every step (tests/test_rolling_disk.py's rolling_disk_rhs).

The top's steady precessions all come out stable; the unstable case is the rolling
disk below its critical speed (a coin rolling slowly, nearly upright).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from test_rolling_disk import rolling_disk_rhs

from gyro_cli.kinds.rolling_disk import free_from_speed_and_path
from gyro_cli.kinds.steady_precession import precession_from_spin
from gyro_cli.physics.stability import (
    NEUTRAL,
    STABLE,
    UNSTABLE,
    disk_critical_axial_rate,
    disk_rolling,
    top_steady_precession,
    verdict,
)

K = np.array([0.0, 0.0, 1.0])
RPM = 2 * math.pi / 60

# problem 11/3's top, SI (3 ozf, k_axial 0.84 in, k_pivot 1.80 in, l = 1.5 in, g = 32.2 ft/s^2)
W = 3 * 0.27801385
M = W / (32.2 * 0.3048)
TOP = {"I": M * (1.80 * 0.0254) ** 2, "J": M * (0.84 * 0.0254) ** 2, "mgl": W * 1.5 * 0.0254}


# ---- the heavy top ------------------------------------------------------------------

def top_rhs(I, J, mgl):
    """k' = omega x k, H' = m g l k x (-K), omega = H / I + (1/J - 1/I)(H.k) k, in plain
    floats (numpy's cost per 3-vector was most of an integration's time)."""
    def rhs(_, y):
        k0, k1, k2, h0, h1, h2 = y.tolist()
        n = math.sqrt(k0 * k0 + k1 * k1 + k2 * k2)
        k0, k1, k2 = k0 / n, k1 / n, k2 / n
        c = (1 / J - 1 / I) * (h0 * k0 + h1 * k1 + h2 * k2)
        w0, w1, w2 = h0 / I + c * k0, h1 / I + c * k1, h2 / I + c * k2
        return [w1 * k2 - w2 * k1, w2 * k0 - w0 * k2, w0 * k1 - w1 * k0,
                -mgl * k1, mgl * k0, 0.0]
    return rhs


def top_start(I, J, theta, spin, precession, theta_rate=0.0):
    """Axis in the x-z plane at theta from K; omega = phidot K + psidot k + thetadot n,
    n = K x k / |K x k| the line of nodes (Eqs. 11.5-11.8 in vector form)."""
    k = np.array([math.sin(theta), 0.0, math.cos(theta)])
    n = np.cross(K, k) / math.sin(theta)
    omega = precession * K + spin * k + theta_rate * n
    H = I * omega + (J - I) * (omega @ k) * k
    return np.concatenate([k, H])


def theta_series(I, J, mgl, y0, t_end, n):
    sol = solve_ivp(top_rhs(I, J, mgl), (0, t_end), y0, method="DOP853", rtol=1e-11,
                    atol=1e-13, dense_output=True)
    assert sol.success
    t = np.linspace(0, t_end, n)
    Y = sol.sol(t)
    k = Y[:3] / np.linalg.norm(Y[:3], axis=0)
    return t, np.arccos(np.clip(k[2], -1, 1))


def mean_period(t, x):
    """Mean spacing of the upward zero crossings of x (linear interpolation)."""
    i = np.nonzero((x[:-1] < 0) & (x[1:] >= 0))[0]
    crossings = t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])
    return (crossings[-1] - crossings[0]) / (len(crossings) - 1)


def top_cases():
    """(theta, spin, phidot): both roots of problem 11/3's top at 30 deg, a hanging top at
    120 deg (one root of each sign), and a spin just above the least one (the two roots
    nearly equal, where the first square of k vanishes)."""
    I, J, mgl = TOP["I"], TOP["J"], TOP["mgl"]
    cases = []
    for theta_deg, spin in ((30, 1800 * RPM), (120, 1800 * RPM)):
        theta = math.radians(theta_deg)
        cases += [(theta, spin, p) for p in precession_from_spin(I, J, theta, spin, mgl)]
    theta = math.radians(30)
    least = 2 * math.sqrt((I - J) * mgl * math.cos(theta)) / J
    cases += [(theta, 1.0001 * least, p)
              for p in precession_from_spin(I, J, theta, 1.0001 * least, mgl)]
    return cases


@pytest.mark.parametrize("theta, spin, phidot", top_cases())
def test_top_steady_precession_is_stable_and_nutates_at_sqrt_k(theta, spin, phidot):
    """A thetadot kick leaves p_phi = H . K and p_psi = H . k unchanged (it is along the line
    of nodes), so theta oscillates about the same steady value, with amplitude
    thetadot0 / sqrt(k) and period 2 pi / sqrt(k)."""
    I, J, mgl = TOP["I"], TOP["J"], TOP["mgl"]
    axial = spin + phidot * math.cos(theta)
    v = top_steady_precession(I, J, theta, phidot, axial)
    assert v.word == STABLE and v.growth_rate == 0.0
    # unperturbed: theta stays put (the root is a steady precession of these equations)
    t, th = theta_series(I, J, mgl, top_start(I, J, theta, spin, phidot), 10 / v.frequency,
                         200)
    assert np.max(np.abs(th - theta)) < 1e-8
    kick = 1e-5 * v.frequency
    periods = 20
    t, th = theta_series(I, J, mgl, top_start(I, J, theta, spin, phidot, kick),
                         periods * 2 * math.pi / v.frequency, periods * 400)
    assert np.max(np.abs(th - theta)) == pytest.approx(kick / v.frequency, rel=1e-3)
    assert mean_period(t, th - theta) == pytest.approx(2 * math.pi / v.frequency, rel=1e-4)


def test_top_perturbation_that_changes_the_integrals_stays_near():
    """A kick in phidot changes p_phi (and the energy): the top goes to a neighbouring
    steady precession and nutates about it; theta stays within a few times the kick's
    size in radians, for 50 small-nutation periods."""
    I, J, mgl = TOP["I"], TOP["J"], TOP["mgl"]
    theta, spin = math.radians(30), 1800 * RPM
    for phidot in precession_from_spin(I, J, theta, spin, mgl):
        v = top_steady_precession(I, J, theta, phidot, spin + phidot * math.cos(theta))
        kick = 1e-4 * abs(phidot)
        t, th = theta_series(I, J, mgl, top_start(I, J, theta, spin, phidot + kick),
                             50 * 2 * math.pi / v.frequency, 20000)
        # the kick is a transverse rate kick sin(theta) (as a thetadot kick would be), so
        # theta moves by about kick sin(theta) / sqrt(k); measured: 0.5 and 0.33 of that
        # scale for the slow and the fast root; the bound allows 4 times it
        bound = 4 * kick * math.sin(theta) / v.frequency
        assert 0 < np.max(np.abs(th - theta)) < bound


def test_top_k_is_the_curvature_of_the_effective_potential():
    """k = U_eff''(theta0) / I by central differences of U_eff = (P1 - P2 cos th)^2 /
    (2 I sin^2 th) + m g l cos th, P1 and P2 from the root (Eq. 11.14)."""
    I, J, mgl = TOP["I"], TOP["J"], TOP["mgl"]
    theta, spin = math.radians(50), 2400 * RPM
    for phidot in precession_from_spin(I, J, theta, spin, mgl):
        axial = spin + phidot * math.cos(theta)
        P2 = J * axial
        P1 = I * phidot * math.sin(theta) ** 2 + P2 * math.cos(theta)

        def U(th):
            return ((P1 - P2 * math.cos(th)) ** 2 / (2 * I * math.sin(th) ** 2)  # noqa: B023 (called in this iteration)
                    + mgl * math.cos(th))
        h = 1e-4
        assert (U(theta + h) - U(theta - h)) / (2 * h) == pytest.approx(0, abs=1e-6 * mgl)
        curvature = (U(theta + h) - 2 * U(theta) + U(theta - h)) / h ** 2
        assert top_steady_precession(I, J, theta, phidot, axial).k == \
            pytest.approx(curvature / I, rel=1e-5)


def test_verdict_words():
    assert verdict(4.0, 4.0).word == STABLE and verdict(4.0, 4.0).frequency == 2.0
    assert verdict(-9.0, 9.0).word == UNSTABLE and verdict(-9.0, 9.0).growth_rate == 3.0
    assert verdict(1e-20, 1.0).word == NEUTRAL


# ---- the rolling disk --------------------------------------------------------------

COIN = {"m": 5.670e-3, "r": 24.26e-3 / 2}     # a US quarter dollar: 5.670 g, 24.26 mm


def disk_inertias(m, r, shape="disk"):
    """(J about the axis, I_G about a diameter) of a thin disk or hoop."""
    return (m * r * r / 2, m * r * r / 4) if shape == "disk" else (m * r * r, m * r * r / 2)


def disk_start(s, r, tilt_rate=0.0):
    """State (G, v_G, k, omega) of the steady state s, heading along y, with a tilt kick;
    omega = Omega K - betadot e_t + psidot k (betadot > 0 tilts further in)."""
    e_r, e_t = np.array([1.0, 0, 0]), np.array([0, 1.0, 0])
    k = math.cos(s.tilt) * e_r + math.sin(s.tilt) * K
    u = -math.sin(s.tilt) * e_r + math.cos(s.tilt) * K          # contact point -> G
    G = s.centre_radius * e_r + r * u
    w = s.precession * K + s.spin * k - tilt_rate * e_t
    v = np.cross(w, r * u)                                       # rolling
    return np.concatenate([G, v, k, w])


def tilt_rate_series(m, g, r, J, I, y0, t_end, n):
    sol = solve_ivp(rolling_disk_rhs(m, g, r, J, I), (0, t_end), y0, method="DOP853",
                    rtol=1e-11, atol=1e-14, dense_output=True)
    assert sol.success
    t = np.linspace(0, t_end, n)
    Y = sol.sol(t)
    k = Y[6:9] / np.linalg.norm(Y[6:9], axis=0)
    kdot = np.cross(Y[9:12].T, k.T).T
    tilt = np.arcsin(k[2])
    return t, tilt, kdot[2] / np.cos(tilt)                       # betadot = (k')_z / cos b


@pytest.mark.parametrize("shape, speed, path", [("disk", 0.10, 1.0), ("disk", 0.15, 0.3),
                                                 ("hoop", 0.12, 2.0)])
def test_slow_rolling_is_unstable_at_the_computed_growth_rate(shape, speed, path):
    """Below the critical speed the tilt rate grows as exp(s t): the slope of log|betadot|,
    once the decaying mode has died out, is the growth rate sqrt(-k)."""
    m, g, r = COIN["m"], 9.81, COIN["r"]
    J, I = disk_inertias(m, r, shape)
    (s,) = free_from_speed_and_path(m, g, r, J, I, speed, path)
    v = disk_rolling(m, g, r, I, J, s.tilt, s.precession, s.axial_rate)
    assert v.word == UNSTABLE
    kick = 1e-9
    t_end = math.log(1e-3 / kick * 2 * v.growth_rate) / v.growth_rate   # |betadot| ~ 1e-3
    t, tilt, rate = tilt_rate_series(m, g, r, J, I, disk_start(s, r, kick), t_end, 2000)
    late = (t > 6 / v.growth_rate)
    slope = np.polyfit(t[late], np.log(np.abs(rate[late])), 1)[0]
    assert slope == pytest.approx(v.growth_rate, rel=1e-4)    # measured: 4e-7 to 3e-6
    assert abs(tilt[-1] - s.tilt) > 1e3 * kick / v.growth_rate     # it has left the state


@pytest.mark.parametrize("shape, speed, path", [("disk", 0.5, 1.0), ("disk", 0.3, 0.05),
                                                 ("hoop", 0.4, 2.0)])
def test_fast_rolling_is_stable_and_wobbles_at_sqrt_k(shape, speed, path):
    """Above the critical speed (or on a tight circle) a tilt kick gives a bounded wobble
    of the tilt rate at sqrt(k)."""
    m, g, r = COIN["m"], 9.81, COIN["r"]
    J, I = disk_inertias(m, r, shape)
    states = free_from_speed_and_path(m, g, r, J, I, speed, path)
    assert states
    for s in states:
        v = disk_rolling(m, g, r, I, J, s.tilt, s.precession, s.axial_rate)
        assert v.word == STABLE
        kick = 1e-6 * v.frequency
        periods = 20
        t, tilt, rate = tilt_rate_series(m, g, r, J, I, disk_start(s, r, kick),
                                         periods * 2 * math.pi / v.frequency, periods * 200)
        assert np.max(np.abs(rate)) == pytest.approx(kick, rel=1e-3)
        assert mean_period(t, rate) == pytest.approx(2 * math.pi / v.frequency, rel=1e-4)
        assert np.max(np.abs(tilt - s.tilt)) < 3 * kick / v.frequency


def test_upright_critical_speed_is_routh_s():
    """Upright straight rolling: stable iff v^2 > g r / 3 (thin disk), g r / 4 (hoop)."""
    m, g, r = COIN["m"], 9.81, COIN["r"]
    for shape, fraction in (("disk", 3), ("hoop", 4)):
        J, I = disk_inertias(m, r, shape)
        critical = disk_critical_axial_rate(m, g, r, I, J)
        assert critical * r == pytest.approx(math.sqrt(g * r / fraction), rel=1e-12)
        for factor, word in ((0.99, UNSTABLE), (1.01, STABLE)):
            w = factor * critical
            assert disk_rolling(m, g, r, I, J, 0.0, 0.0, -w).word == word


# ---- through the command line ------------------------------------------------------

def coin_file(write, speed, path):
    return write(f"""
        id: coin
        kind: rolling_disk
        given:
          arrangement: free
          mass: 5.670 g
          shape: disk
          radius: 12.13 mm
          speed: {speed}
          path_radius: {path}
        find:
          tilt: deg
          stability: null
          growth_rate: s^-1
        """)


def test_cli_unstable_coin_warns(run, write):
    result = run("solve", "--format", "json", coin_file(write, "0.10 m/s", "1 m"))
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    answers = report["answers"]
    assert answers["stability"]["values"] == ["unstable"]
    m, g, r = COIN["m"], 9.81, COIN["r"]
    J, I = disk_inertias(m, r)
    (s,) = free_from_speed_and_path(m, g, r, J, I, 0.10, 1.0)
    assert answers["growth_rate"]["values"][0] == pytest.approx(
        disk_rolling(m, g, r, I, J, s.tilt, s.precession, s.axial_rate).growth_rate, rel=1e-9)
    assert any("unstable" in w for w in report["warnings"])


def test_cli_stable_coin_no_warning(run, write):
    result = run("solve", "--format", "json", coin_file(write, "0.5 m/s", "1 m"))
    assert result.exit_code == 0, result.output
    report = json.loads(result.stdout)
    assert report["answers"]["stability"]["values"] == ["stable"]
    assert report["answers"]["growth_rate"]["values"] == [0.0]
    assert not any("unstable" in w for w in report["warnings"])


def test_cli_top_roots_stable(run, write):
    path = write("""
        id: top
        kind: steady_precession
        given: {weight: 3 oz, k_axial: 0.84 in, k_pivot: 1.80 in, cg_distance: 1.5 in,
                spin: 1800 rpm, theta: 30 deg}
        find: {precession: rpm, stability: null, growth_rate: s^-1}
        """)
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 0, result.output
    answers = json.loads(result.stdout)["answers"]
    assert answers["stability"]["values"] == ["stable", "stable"]
    assert answers["growth_rate"]["values"] == [0.0, 0.0]


@pytest.mark.parametrize("text, key", [
    ("""
        id: t
        kind: steady_precession
        given: {J: 1e-4 kg m^2, I_pivot: 2e-4 kg m^2, mass: 1 kg, moment: 0.1 N m,
                spin: 1800 rpm, theta: 30 deg}
        find: {stability: null}
        """, "find.stability"),
    ("""
        id: t
        kind: rolling_disk
        given: {arrangement: axle_pivot, weight: 96.6 lb, shape: disk, radius: 1 ft,
                path_radius: 2 ft, precession: 48 rpm}
        find: {stability: null}
        """, "find.stability"),
])
def test_stability_not_defined_is_one_line(run, write, text, key):
    result = run("solve", write(text))
    assert result.exit_code == 2
    assert len(result.stderr.strip().splitlines()) == 1 and key in result.stderr


def test_bundled_problems_by_hand(run, problems_dir):
    """The three bundled stability problems against their hand working (in their notes)."""
    def answers(name):
        result = run("solve", "--format", "json", problems_dir / name)
        assert result.exit_code == 0, result.output
        return json.loads(result.stdout)["answers"]

    coin = answers("rolling_coin_upright.yaml")
    assert coin["upright_speed"]["values"][0] == pytest.approx(math.sqrt(9.81 * 0.01213 / 3),
                                                               rel=1e-9)
    assert coin["stability"]["values"] == ["unstable"]
    hoop = answers("rolling_hoop_stable.yaml")
    assert hoop["upright_speed"]["values"][0] == pytest.approx(math.sqrt(9.81 * 0.35 / 4),
                                                               rel=1e-9)
    assert hoop["stability"]["values"] == ["stable"]
    # 11/3, slow root, by hand: I, J, omega_z as in the file's notes
    I, J = TOP["I"], TOP["J"]
    phidot = 45.13 * RPM
    omega_z = 1800 * RPM + phidot * math.cos(math.radians(30))
    k = ((J * omega_z - 2 * I * phidot * math.cos(math.radians(30))) / I) ** 2 + \
        (phidot * 0.5) ** 2
    assert k == pytest.approx(1146, rel=2e-3)
    assert 2 * math.pi / math.sqrt(k) == pytest.approx(0.186, abs=5e-4)
    top = answers("11_3_stability.yaml")
    assert top["stability"]["values"] == ["stable", "stable"]
