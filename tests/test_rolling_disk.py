"""rolling_disk checked against independent computations.

axle_pivot (11/6): along the prescribed motion (rotation matrices, nothing from
the kind) the velocity of the material contact point is zero with the computed
spin, and the moments about the pin of gravity and the computed normal force
equal dH_O/dt from finite differences of H_O = R I_O R^T omega.

free: the Newton-Euler equations of a rolling rigid disk (contact force solved
from the rolling constraint at every step, written out here) integrated from
the computed steady state keep the tilt, the centre's circle and the contact
point's circle; the large-circle limits tan(beta) = 3 v^2 / (2 g rho) (disk) and
2 v^2 / (g rho) (hoop); the three ways of asking agree with each other.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from rotations import K, cross3, omega_of, rx, rz
from scipy.integrate import solve_ivp

from gyro_cli.kinds.rolling_disk import (
    axle_pivot_normal_force,
    axle_pivot_spin,
    free_from_speed_and_path,
    free_from_speed_and_tilt,
    free_from_tilt_and_path,
)

RPM = 2 * math.pi / 60


@pytest.mark.parametrize("m, r, R, Omega", [(3.0, 0.3048, 0.6096, 48 * RPM),
                                            (2.0, 0.1, 0.35, -7.0), (5.0, 0.2, 0.21, 3.0)])
def test_axle_pivot_rolls_and_balances_moments_about_the_pin(m, r, R, Omega):
    g = 9.81
    J, I_G = m * r * r / 2, m * r * r / 4
    spin = axle_pivot_spin(Omega, R, r)
    N = axle_pivot_normal_force(m, g, J, Omega, r)
    # The disk: axle along x of the turning frame, spinning about it.
    R_of = lambda t: rz(Omega * t) @ rx(spin * t)  # noqa: E731
    centre = lambda t: R * R_of(t)[:, 0]  # noqa: E731
    t0, h = 0.3, 1e-5
    contact = centre(t0) - r * K
    body_point = R_of(t0).T @ (contact - centre(t0))
    material = lambda t: centre(t) + R_of(t) @ body_point  # noqa: E731
    v_contact = (material(t0 + h) - material(t0 - h)) / (2 * h)
    assert np.linalg.norm(v_contact) < 1e-6 * abs(Omega) * R
    I_O = np.diag([J, I_G + m * R * R, I_G + m * R * R])
    H = lambda t: R_of(t) @ I_O @ R_of(t).T @ omega_of(R_of, t)  # noqa: E731
    dH = (H(t0 + 1e-4) - H(t0 - 1e-4)) / 2e-4
    moments = np.cross(centre(t0), -m * g * K) + np.cross(contact, N * K)
    assert np.allclose(moments, dH, atol=1e-6 * m * g * R)


def test_problem_11_6_by_hand(run, problems_dir):
    # 96.6 lb: m = 3 slug; J = m r^2 / 2 = 1.5 slug ft^2; Omega = 48 rpm = 5.0265 rad/s.
    # N = W + J Omega^2 / r = 96.6 + 1.5 * 25.266 / 1 = 134.50 lb.
    # Spin: the centre moves at Omega R = 10.05 ft/s, so |psidot| = Omega R / r = 96 rpm.
    # Moment of gravity and N about the pin: (N - W) R = 37.90 * 2 = 75.80 lb ft.
    result = run("solve", "--format", "json", problems_dir / "11_6.yaml")
    assert result.exit_code == 0, result.output
    answers = json.loads(result.stdout)["answers"]
    Omega = 48 * RPM
    assert answers["normal_force"]["values"][0] == pytest.approx(96.6 + 1.5 * Omega ** 2,
                                                                 rel=1e-9)
    assert answers["normal_force"]["values"][0] == pytest.approx(134.50, abs=0.01)
    assert answers["spin"]["values"][0] == pytest.approx(-96.0)
    assert answers["moment"]["values"][0] == pytest.approx(1.5 * Omega ** 2 * 2, rel=1e-9)


def rolling_disk_rhs(m, g, r, J, I):
    """Newton-Euler for a rigid disk rolling without slipping; state G, v_G, k, omega.

    With rho from G to the contact point, the contact force F and a = dv_G/dt:
        m a = F - m g K,   I_w wdot + w x I_w w = rho x F,   a = rho x wdot - w x rhodot
    (the contact point at rest), so F = m a + m g K eliminates F and a:
        (I_w - m [rho]x^2) wdot = -w x I_w w - m rho x (w x rhodot) + m g rho x K,
    a 3x3 system solved by Cramer's rule in plain floats (the integrations call this
    tens of thousands of times; numpy's cost per small array was most of their time)."""
    def rhs(t, y):
        v, (k0, k1, k2), w = y[3:6], y[6:9], tuple(y[9:12])
        n = math.sqrt(k0 * k0 + k1 * k1 + k2 * k2)
        k = (k0 / n, k1 / n, k2 / n)
        u = (-k[2] * k[0], -k[2] * k[1], 1.0 - k[2] * k[2])   # K - (K.k) k
        un = math.sqrt(u[0] ** 2 + u[1] ** 2 + u[2] ** 2)
        uh = (u[0] / un, u[1] / un, u[2] / un)
        rho = (-r * uh[0], -r * uh[1], -r * uh[2])
        kdot = cross3(w, k)
        udot = tuple(-kdot[2] * k[i] - k[2] * kdot[i] for i in range(3))
        uu = sum(uh[i] * udot[i] for i in range(3))
        rhodot = tuple(-r * (udot[i] - uu * uh[i]) / un for i in range(3))
        kw = sum(k[i] * w[i] for i in range(3))
        Iw_w = tuple(I * w[i] + (J - I) * kw * k[i] for i in range(3))
        # I_w - m [rho]x^2 = I 1 + (J - I) k k^T + m (|rho|^2 1 - rho rho^T)
        rr = rho[0] ** 2 + rho[1] ** 2 + rho[2] ** 2
        A = [[(I + m * rr if i == j else 0.0) + (J - I) * k[i] * k[j] - m * rho[i] * rho[j]
              for j in range(3)] for i in range(3)]
        t1, t2, t3 = cross3(w, Iw_w), cross3(rho, cross3(w, rhodot)), cross3(rho, (0.0, 0.0, 1.0))
        b = [-t1[i] - m * t2[i] + m * g * t3[i] for i in range(3)]
        c00 = A[1][1] * A[2][2] - A[1][2] * A[2][1]
        c01 = A[1][2] * A[2][0] - A[1][0] * A[2][2]
        c02 = A[1][0] * A[2][1] - A[1][1] * A[2][0]
        det = A[0][0] * c00 + A[0][1] * c01 + A[0][2] * c02
        wd = [(c00 * b[0] + (A[0][2] * A[2][1] - A[0][1] * A[2][2]) * b[1]
               + (A[0][1] * A[1][2] - A[0][2] * A[1][1]) * b[2]) / det,
              (c01 * b[0] + (A[0][0] * A[2][2] - A[0][2] * A[2][0]) * b[1]
               + (A[0][2] * A[1][0] - A[0][0] * A[1][2]) * b[2]) / det,
              (c02 * b[0] + (A[0][1] * A[2][0] - A[0][0] * A[2][1]) * b[1]
               + (A[0][0] * A[1][1] - A[0][1] * A[1][0]) * b[2]) / det]
        a = [p - q for p, q in zip(cross3(rho, wd), cross3(w, rhodot))]
        return [v[0], v[1], v[2], a[0], a[1], a[2], kdot[0], kdot[1], kdot[2],
                wd[0], wd[1], wd[2]]
    return rhs


@pytest.mark.parametrize("shape, factors", [("disk", (0.5, 0.25)), ("hoop", (1.0, 0.5))])
@pytest.mark.parametrize("speed, tilt", [(2.0, math.radians(20)), (1.2, math.radians(45)),
                                         (3.0, math.radians(14))])
def test_free_rolling_integrated_keeps_the_steady_motion(shape, factors, speed, tilt):
    m, g, r = 1.3, 9.81, 0.12
    J, I = factors[0] * m * r * r, factors[1] * m * r * r
    s = free_from_speed_and_tilt(m, g, r, J, I, tilt, speed)
    e_r, e_t = np.array([1.0, 0, 0]), np.array([0, 1.0, 0])
    k = math.cos(tilt) * e_r + math.sin(tilt) * K
    G = s.centre_radius * e_r + r * math.cos(tilt) * K
    w = s.precession * K + s.spin * k
    v = s.precession * s.centre_radius * e_t
    contact = G + r * (math.sin(tilt) * e_r - math.cos(tilt) * K)
    assert np.linalg.norm(v + np.cross(w, contact - G)) < 1e-12 * speed  # rolls at the start
    assert math.hypot(*contact[:2]) == pytest.approx(s.path_radius)
    T = 2 * math.pi / s.precession
    sol = solve_ivp(rolling_disk_rhs(m, g, r, J, I), (0, T), np.concatenate([G, v, k, w]),
                    method="DOP853", rtol=1e-11, atol=1e-12, dense_output=True)
    assert sol.success
    ts = np.linspace(0, T, 200)
    Y = sol.sol(ts)
    ks = Y[6:9] / np.linalg.norm(Y[6:9], axis=0)
    tilts = np.arcsin(ks[2])
    assert np.max(np.abs(tilts - tilt)) < 1e-6
    assert np.max(np.abs(np.hypot(Y[0], Y[1]) - s.centre_radius)) < 1e-6 * s.centre_radius
    assert np.max(np.abs(Y[2] - G[2])) < 1e-8
    assert np.linalg.norm(Y[0:3, -1] - G) < 1e-5 * s.centre_radius  # back after one turn


@pytest.mark.parametrize("shape, coefficient, factors", [("disk", 1.5, (0.5, 0.25)),
                                                        ("hoop", 2.0, (1.0, 0.5))])
def test_large_circle_limit(shape, coefficient, factors):
    # Far from the axis the I_G term and r sin(beta) vanish: tan(beta) = c v^2 / (g rho) with
    # c = (m r^2 + J) / (m r^2): 3/2 for a disk, 2 for a hoop.
    m, g, r, speed = 1.0, 9.81, 0.1, 3.0
    J, I = factors[0] * m * r * r, factors[1] * m * r * r
    s = free_from_speed_and_tilt(m, g, r, J, I, math.radians(0.5), speed)
    assert math.tan(s.tilt) == pytest.approx(coefficient * speed ** 2 / (g * s.centre_radius),
                                             rel=1e-3)


def test_three_ways_of_asking_agree():
    m, g, r = 2.0, 9.81, 0.15
    J, I = m * r * r / 2, m * r * r / 4
    s = free_from_speed_and_tilt(m, g, r, J, I, math.radians(25), 1.7)
    back = free_from_tilt_and_path(m, g, r, J, I, math.radians(25), s.path_radius)
    assert back.speed == pytest.approx(1.7, rel=1e-12)
    tilts = [x.tilt for x in free_from_speed_and_path(m, g, r, J, I, 1.7, s.path_radius)]
    assert any(abs(t - math.radians(25)) < 1e-9 for t in tilts)


def test_free_through_the_cli(run, write):
    path = write("""
        id: coin
        kind: rolling_disk
        given:
          arrangement: free
          mass: 1 kg
          shape: disk
          radius: 0.1 m
          speed: 2 m/s
          tilt: 20 deg
        find:
          path_radius: m
          precession: rad/s
        """)
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 0, result.output
    answers = json.loads(result.stdout)["answers"]
    R = answers["path_radius"]["values"][0]
    # Hand check with the large-circle form, corrected: tan(20 deg) = 0.3640, so
    # rho ~ 1.5 v^2 / (g tan beta) = 1.680 m; the exact root is a little larger (I_G term).
    assert 1.68 < R - 0.1 * math.sin(math.radians(20)) < 1.70


BAD = [
    ("""
        id: bad
        kind: rolling_disk
        given: {arrangement: free, mass: 1 kg, shape: disk, radius: 100 mm,
                path_radius: 50 mm, tilt: 60 deg}
        find: {speed: m/s}
        """, "no steady rolling"),
    ("""
        id: bad
        kind: rolling_disk
        given: {arrangement: free, mass: 1 kg, shape: disk, radius: 100 mm,
                path_radius: 20 mm, speed: 5 m/s}
        find: {tilt: deg}
        """, "no tilt"),
    ("""
        id: bad
        kind: rolling_disk
        given: {arrangement: axle_pivot, mass: 1 kg, shape: disk, radius: 100 mm,
                path_radius: 0 m, precession: 10 rpm}
        find: {normal_force: N}
        """, "expected path_radius > 0 m"),
    ("""
        id: bad
        kind: rolling_disk
        given: {arrangement: free, mass: 1 kg, shape: disk, radius: 100 mm, speed: 1 m/s}
        find: {tilt: deg}
        """, "exactly two"),
]


@pytest.mark.parametrize("text, reason", BAD)
def test_bad_input_exits_2_with_the_reason(run, write, text, reason):
    result = run("solve", write(text))
    assert result.exit_code == 2, result.output
    assert reason in result.stderr and "Traceback" not in result.output


def test_cli_checks_problem_11_6(run, problems_dir):
    assert run("check", problems_dir / "11_6.yaml").exit_code == 0


@pytest.mark.parametrize("top", [math.pi / 2, math.asin(0.35 / 0.4), math.asin(1e-3)])
def test_the_scan_grid_is_the_tilts_point_by_point_and_kept_unchanged(top):
    """The scan's grid, made once per largest tilt and kept, is the list the scan built point
    by point (top / n 10^(-k/8) below the first step, then top i / n), float for float, and
    it cannot be written into."""
    from gyro_cli.kinds.rolling_disk import _scan_grid

    n = 4000
    points = [top / n * 10 ** (-k / 8) for k in range(96, 0, -1)]
    points += [top * i / n for i in range(1, n)]
    grid = _scan_grid(top)
    assert list(grid) == points and isinstance(grid, tuple)
    assert _scan_grid(top) is grid


@pytest.mark.parametrize("path", [1e9, 1e12, 1e15, 1e16, 1e100, 1e300])
def test_a_disk_on_a_huge_circle_tilts_as_the_large_circle_limit_says(path):
    """On a circle of radius R >> r the moment balance m g r sin(b) rho^2 = v^2 cos(b)
    [rho (m r + J / r) + I sin(b)] becomes b = v^2 (m r + J / r) / (m g r R), to within b
    itself. The tilt is found to 1e-9 of itself however small: below a microradian the
    bisection goes on past 1e-15 rad (it stopped there, and printed 7.887e-11 deg for
    7.885e-11 at R = 1e12 m), and below the scan's finest point (about 4e-16 rad, beyond
    R = 1e16 m at 3 m/s) the tilt is still found, not reported as missing."""
    from gyro_cli.kinds.rolling_disk import free_from_speed_and_path

    m, r, v, g = 1.0, 0.05, 3.0, 9.81
    J, I = m * r * r / 2, m * r * r / 4  # a thin disk
    states = free_from_speed_and_path(m, g, r, J, I, v, path)
    assert len(states) == 1
    limit = v * v * (m * r + J / r) / (m * g * r * path)
    assert states[0].tilt == pytest.approx(limit, rel=1e-8)


def test_the_tilt_on_a_huge_circle_is_printed_right(run, write):
    result = run("solve", write("""\
        id: far
        kind: rolling_disk
        given: {arrangement: free, mass: 1 kg, shape: disk, radius: 50 mm, speed: 3 m/s,
                path_radius: 1e12 m}
        find: {tilt: deg}
        """))
    assert result.exit_code == 0, result.output
    # 3 v^2 / (2 g R) rad = 27 / (2 9.81 1e12) rad = 1.3761e-12 rad = 7.885e-11 deg
    assert "beta = 7.885e-11 deg" in result.output
