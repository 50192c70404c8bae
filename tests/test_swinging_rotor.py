"""swinging_rotor (problem 11/8) checked against a numerical integration of the swing.

The swing is integrated from the moment of gravity about the shaft; along that
trajectory the disk's attitude is R(t) = Rx(theta(t)) Rz(p t), and the forces
in A and B are solved here from the free body: sum of forces = m a_G (a_G by
finite differences of G's path) and sum of moments about O = dH_O/dt (finite
differences of H_O = R I_O R^T omega). Nothing comes from the kind's formulas.
Problem 11/8 is also worked by hand, and bad input exits 2.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from gyro_cli.kinds.swinging_rotor import swing_forces

G_VEC = np.array([0.0, 0.0, -9.81])


def rx(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[1.0, 0, 0], [0, c, -s], [0, s, c]])


def rz(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1.0]])


def integrated_forces(m, J, I_G, p, L, d, a, theta0, theta_end):
    """Integrate the swing, then solve the free body at theta_end. Returns (F_A, F_B, thetadot,
    arm unit, normal unit)."""
    g = 9.81
    I_O = I_G + m * L * L

    def rhs(t, y):
        # moment of gravity about the shaft (x): G = L (0, -sin th, cos th), W = -m g z
        return [y[1], m * g * L * math.sin(y[0]) / I_O]

    def reached(t, y):
        return y[0] - theta_end
    reached.terminal, reached.direction = True, 1
    start = max(theta0, 1e-7)
    sol = solve_ivp(rhs, (0, 60), [start, 0.0], method="DOP853", rtol=1e-12, atol=1e-14,
                    events=reached, dense_output=True)
    t_end = sol.t_events[0][0]

    def state(t):
        th, thd = sol.sol(t)
        R = rx(th) @ rz(p * t)
        k = R[:, 2]
        omega = np.array([thd, 0, 0]) + p * k
        return R, k, omega

    def H(t):
        R, _, omega = state(t)
        return R @ np.diag([I_O, I_O, J]) @ R.T @ omega

    def centre(t):
        return L * state(t)[1]

    h = 1e-4
    t = t_end - 2 * h  # stay inside the integrated interval
    dH = (H(t + h) - H(t - h)) / (2 * h)
    a_G = (centre(t + h) - 2 * centre(t) + centre(t - h)) / h ** 2
    b = d - a
    # Unknowns Ay, Az, By, Bz (no axial force): forces y, z and moments y, z about O.
    A = np.array([[1, 0, 1, 0], [0, 1, 0, 1], [0, a, 0, -b], [-a, 0, b, 0]], dtype=float)
    need = m * a_G - m * G_VEC
    rhs_vec = np.array([need[1], need[2], dH[1], dH[2]])
    Ay, Az, By, Bz = np.linalg.solve(A, rhs_vec)
    # The x moment is not the bearings': gravity alone must give it.
    assert np.cross(centre(t), m * G_VEC)[0] == pytest.approx(dH[0], rel=1e-5)
    th = sol.sol(t)[0]
    arm = np.array([0, -math.sin(th), math.cos(th)])
    normal = np.array([0, math.cos(th), math.sin(th)])
    return (np.array([0, Ay, Az]), np.array([0, By, Bz]), sol.sol(t)[1], arm, normal, th)


CASES = [  # m, J, I_G, p, L, d, a, theta0, theta
    (2.0, 0.01, 0.005, 300.0, 0.25, 0.2, 0.1, 0.0, math.pi / 2),  # problem 11/8
    (2.0, 0.01, 0.005, -300.0, 0.25, 0.2, 0.1, 0.0, math.pi / 2),
    (1.5, 0.012, 0.006, 180.0, 0.3, 0.25, 0.05, math.radians(30), math.radians(140)),
    (3.0, 0.03, 0.015, -90.0, 0.2, 0.15, 0.12, math.radians(10), math.radians(60)),
]


@pytest.mark.parametrize("m, J, I_G, p, L, d, a, theta0, theta", CASES)
def test_forces_match_the_integrated_swing(m, J, I_G, p, L, d, a, theta0, theta):
    F_A, F_B, thetadot, arm, normal, th = integrated_forces(m, J, I_G, p, L, d, a, theta0,
                                                            theta)
    f = swing_forces(m, 9.81, J, I_G, p, L, d, a, theta0, th)
    assert f.thetadot == pytest.approx(thetadot, rel=1e-8)
    scale = max(abs(f.couple), m * 9.81)
    assert F_A @ arm == pytest.approx(f.arm[0], abs=1e-5 * scale)
    assert F_B @ arm == pytest.approx(f.arm[1], abs=1e-5 * scale)
    assert F_A @ normal == pytest.approx(f.normal[0], abs=1e-5 * scale)
    assert F_B @ normal == pytest.approx(f.normal[1], abs=1e-5 * scale)


def test_problem_11_8_by_hand(run, problems_dir):
    # m = 2 kg, r = 0.1 m: J = m r^2/2 = 0.01, I_G = m r^2/4 = 0.005; L = 0.25 m, d = 0.2 m.
    # I_O = 0.005 + 2 (0.25)^2 = 0.13 kg m^2.
    # Energy, top to horizontal: 0.13 thetadot^2 / 2 = 2 * 9.81 * 0.25  ->  thetadot^2 = 75.46,
    # thetadot = 8.687 rad/s. Moments about AB: thetaddot = 2 * 9.81 * 0.25 / 0.13 = 37.73.
    # Along the arm: F_A + F_B = -m L thetadot^2 = -37.73 N (toward the shaft; gravity is
    # across the horizontal arm), split equally; couple J p thetadot / d = 0.01 * 300 * 8.687 /
    # 0.2 = 130.3 N, + at B, - at A: F_A = -18.87 - 130.3 = -149.2 N, F_B = 111.4 N.
    # Vertical: F_A + F_B = m (g - L thetaddot) = 2 (9.81 - 9.433) = 0.7546 N -> 0.3773 N each.
    thetadot = math.sqrt(2 * 2 * 9.81 * 0.25 / 0.13)
    couple = 0.01 * 300 * thetadot / 0.2
    arm_A = -2 * 0.25 * thetadot ** 2 / 2 - couple
    arm_B = -2 * 0.25 * thetadot ** 2 / 2 + couple
    vertical = 2 * (9.81 - 0.25 * 2 * 9.81 * 0.25 / 0.13) / 2
    result = run("solve", "--format", "json", problems_dir / "11_8.yaml")
    assert result.exit_code == 0, result.output
    answers = json.loads(result.stdout)["answers"]
    assert answers["angular_rate"]["values"][0] == pytest.approx(thetadot, rel=1e-12)
    assert answers["bearing_forces_arm"]["values"] == pytest.approx([arm_A, arm_B], rel=1e-12)
    assert answers["bearing_forces_normal"]["values"] == pytest.approx([vertical, vertical])
    assert answers["bearing_forces"]["values"] == pytest.approx(
        [math.hypot(arm_A, vertical), math.hypot(arm_B, vertical)])
    assert answers["bearing_forces"]["values"] == pytest.approx([149.2, 111.4], abs=0.05)
    assert answers["bearing_forces"]["labels"] == ["A", "B"]


def test_worked_answer_gives_formulas_in_m_r_p_g(run, problems_dir):
    out = run("solve", problems_dir / "11_8.yaml").stdout
    assert "F_A,arm = (b / d) m g (cos(theta) - 2 L^2 (cos(theta0) - cos(theta)) / " \
           "(r^2 / 4 + L^2)) - m (r^2 / 2) p sqrt(2 g L (cos(theta0) - cos(theta)) / " \
           "(r^2 / 4 + L^2)) / d = 0.5000 (-37.73 N) - 130.3 N = -149.2 N" in out
    assert "F_B,normal = (a / d) (m g sin(theta) (r^2 / 4) / (r^2 / 4 + L^2))" in out
    assert "thetaddot = m g L sin(theta) / I_O = g L sin(theta) / (r^2 / 4 + L^2) = " \
           "9.810 m/s^2 (0.2500 m) sin(90.00 deg) / (0.06500 m^2) = 37.73 rad/s^2" in out


def test_cli_checks_problem_11_8(run, problems_dir):
    assert run("check", problems_dir / "11_8.yaml").exit_code == 0


BASE = """
    id: bad
    kind: swinging_rotor
    given:
      mass: 2 kg
      shape: disk
      radius: 100 mm
      spin: 300 rad/s
      arm_length: 250 mm
      {extra}
    find: {{bearing_forces: N}}
    """


@pytest.mark.parametrize("extra, reason", [
    ("bearing_spacing: 0 mm\n      theta: 90 deg", "bearing_spacing must be positive"),
    ("bearing_spacing: 200 mm\n      theta: 20 deg\n      theta0: 30 deg", "never reaches"),
    ("bearing_spacing: 200 mm\n      theta: 90 deg\n      arm_position: 300 mm",
     "outside the bearings"),
])
def test_bad_input_exits_2_with_the_reason(run, write, extra, reason):
    result = run("solve", write(BASE.format(extra=extra)))
    assert result.exit_code == 2, result.output
    assert reason in result.stderr and "Traceback" not in result.output
