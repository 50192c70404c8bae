"""gyroscopic_torque checked against independent computations.

(a) the moment against the rate of change of H = R I R^T omega computed by
    finite differences along the prescribed motion (rotation matrices built from
    z-x-z Euler angles, omega taken from dR/dt R^T, nothing from the kind);
(b) bearing forces put back into a free body written out here: the sum of the
    force vectors against m a_G (a_G by finite differences of G's path) and the
    sum of their moments about G against dH/dt (finite differences);
(c) the two published values and problems 11/4, 11/5, 11/7 by hand;
(d) the command line on each problem file, and bad input (exit 2).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from oracles import gyroscopic_moment
from rotations import K, omega_of, rx, rz

from gyro_cli.kinds.gyroscopic_torque import bearing_forces

RPM = 2 * math.pi / 60


def attitude(t, precession, theta, spin):
    """z-x-z: frame turns at precession about K, spin axis at theta, rotor spins relative."""
    return rz(precession * t) @ rx(theta) @ rz(spin * t)


def angular_momentum(R_of, t, inertia_body):
    R = R_of(t)
    return R @ inertia_body @ R.T @ omega_of(R_of, t)


def dH_dt(R_of, t, inertia_body, h=1e-4):
    return (angular_momentum(R_of, t + h, inertia_body)
            - angular_momentum(R_of, t - h, inertia_body)) / (2 * h)


CASES = [  # J, I (about G), spin, precession, theta
    (0.02, 0.015, 150.0, 2.0, math.pi / 2),
    (0.02, 0.015, -150.0, 2.0, math.pi / 2),
    (0.02, 0.015, 150.0, -3.0, math.radians(60)),
    (0.05, 0.08, 40.0, 6.0, math.radians(125)),
    (0.01, 0.006, -20.0, -9.0, math.radians(30)),
]


@pytest.mark.parametrize("J, I, spin, precession, theta", CASES)
def test_moment_is_finite_difference_of_H(J, I, spin, precession, theta):
    inertia = np.diag([I, I, J])
    R_of = lambda t: attitude(t, precession, theta, spin)  # noqa: E731
    for t in (0.0, 0.37, 1.1):
        rate = dH_dt(R_of, t, inertia)
        k = R_of(t)[:, 2]
        n = np.cross(K, k) / math.sin(theta)
        M = gyroscopic_moment(J, I, spin, precession, theta)
        assert np.allclose(rate, M * n, rtol=1e-5, atol=1e-6 * max(1.0, abs(M))), (rate, M * n)


def test_eq_11_29_at_90_deg_is_J_spin_precession():
    # Limiting case theta = 90 deg: Q_theta = J phidot psidot, whatever I is.
    for I in (0.0, 0.3, 7.0):
        assert gyroscopic_moment(0.2, I, 100.0, 0.5, math.pi / 2) == pytest.approx(10.0)


def free_body_residuals(m, g, J, I, spin, precession, theta, L, a, R, offset, forces, t=0.4):
    """Rebuild the force vectors and test Newton and Euler about G numerically."""
    R_of = lambda s: attitude(s, precession, theta, spin)  # noqa: E731
    k = R_of(t)[:, 2]
    up = (K - math.cos(theta) * k) / math.sin(theta)

    def centre(s):
        ks = R_of(s)[:, 2]
        ns = np.cross(K, ks) / math.sin(theta)
        hs = (ks - math.cos(theta) * K) / math.sin(theta)  # horizontal, the way k points
        return R * (ns if offset == "across" else hs)

    h = 1e-4
    a_G = (centre(t + h) - 2 * centre(t) + centre(t - h)) / h ** 2
    toward_axis = -centre(t) / np.linalg.norm(centre(t)) if R else np.zeros(3)
    F_A = forces.up[0] * up + forces.side[0] * toward_axis
    F_B = forces.up[1] * up + forces.side[1] * toward_axis
    thrust = forces.thrust * k
    weight = -m * g * K
    newton = F_A + F_B + thrust + weight - m * a_G
    r_A, r_B = -a * k, (L - a) * k
    euler = np.cross(r_A, F_A) + np.cross(r_B, F_B) - dH_dt(R_of, t, np.diag([I, I, J]))
    return newton, euler


@pytest.mark.parametrize("offset", ["across", "along"])
@pytest.mark.parametrize("theta, a", [(math.pi / 2, 0.12), (math.radians(70), 0.05),
                                      (math.radians(115), 0.3), (math.pi / 2, -0.1)])
def test_bearing_forces_satisfy_the_free_body(offset, theta, a):
    m, g, J, I, spin, precession, L, R = 4.0, 9.81, 0.03, 0.02, 120.0, 2.5, 0.25, 0.6
    M = gyroscopic_moment(J, I, spin, precession, theta)
    forces = bearing_forces(m, g, M, L, a, precession, theta, R, offset)
    newton, euler = free_body_residuals(m, g, J, I, spin, precession, theta, L, a, R, offset,
                                        forces)
    assert np.max(np.abs(newton)) < 1e-5 * m * g
    assert np.max(np.abs(euler)) < 1e-5 * max(abs(M), 1.0)


def test_bearing_forces_by_hand_simple_case():
    # Rotor 10 kg midway between bearings 0.5 m apart, J p Omega = 0.1 * 200 * 1.5 = 30 N m.
    # Up: each bearing carries 10 * 9.81 / 2 = 49.05 N; the couple adds 30 / 0.5 = 60 N at A
    # and takes 60 N from B (moment about G along n: a F_A - b F_B = M).
    forces = bearing_forces(10.0, 9.81, 30.0, 0.5, 0.25, 1.5, math.pi / 2)
    assert forces.up == pytest.approx((109.05, -10.95))
    assert forces.side == (0.0, 0.0) and forces.thrust == pytest.approx(0.0, abs=1e-12)


def solve_json(run, path):
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)["answers"]


def test_published_ship_turbine_couple(run, write):
    # 3500 kg, k = 0.45 m, 3000 rpm, ship turning on 100 m at 10 m/s:
    # J = 3500 * 0.45^2 = 708.75 kg m^2, Omega = 10 / 100 = 0.1 rad/s,
    # M = J p Omega = 708.75 * 314.159 * 0.1 = 22 266 N m = 22.27 kN m.
    path = write("""
        id: ship
        kind: gyroscopic_torque
        given:
          mass: 3500 kg
          k_axial: 0.45 m
          spin: 3000 rpm
          speed: 10 m/s
          turn_radius: 100 m
        find:
          moment: kN*m
          precession: rad/s
        """)
    answers = solve_json(run, path)
    assert round(answers["moment"]["values"][0], 2) == 22.27
    assert answers["precession"]["values"][0] == pytest.approx(0.1)
    assert 708.75 * 3000 * RPM * 0.1 / 1000 == pytest.approx(answers["moment"]["values"][0])


def test_published_disk_on_arm_precesses_at_16_65(run, write):
    # "A 300 mm, 5 kg disk spinning at 300 rpm at the end of a horizontal 600 mm arm":
    # gravity's moment m g l = 5 * 9.81 * 0.6 = 29.43 N m; Omega = m g l / (J p).
    # Read 300 mm as the DIAMETER: J = 5 * 0.15^2 / 2 = 0.05625, Omega = 29.43 / (0.05625 *
    # 31.416) = 16.65 rad/s (the published value). Read as the radius: J = 0.225 and Omega =
    # 4.163 rad/s, which is not it. So 300 mm is the diameter.
    assert 29.43 / (0.05625 * 300 * RPM) == pytest.approx(16.65, abs=0.005)
    assert 29.43 / (0.225 * 300 * RPM) == pytest.approx(4.163, abs=0.001)
    torque = write("""
        id: arm
        kind: gyroscopic_torque
        given:
          mass: 5 kg
          shape: disk
          diameter: 300 mm
          spin: 300 rpm
          moment: 29.43 N*m
        find:
          precession: rad/s
        """, "torque.yaml")
    assert round(solve_json(run, torque)["precession"]["values"][0], 2) == 16.65
    top = write("""
        id: arm-top
        kind: steady_precession
        given:
          mass: 5 kg
          shape: disk
          diameter: 300 mm
          cg_distance: 600 mm
          theta: 90 deg
          spin: 300 rpm
        find:
          precession: rad/s
        """, "top.yaml")
    assert round(solve_json(run, top)["precession"]["values"][0], 2) == 16.65


def test_problem_11_4_by_hand(run, problems_dir):
    # J = 2.2 * 0.06^2 = 7.92e-3 kg m^2; p = 1725 rpm = 180.64 rad/s; M = J p Omega = 0.28614 N m.
    # The 0.5 kg block moved by db gives 0.5 * 9.81 * db = M: db = 58.33 mm, b = 180 -+ 58.33 mm.
    J, p = 2.2 * 0.06 ** 2, 1725 * RPM
    M = J * p * 0.2
    db = M / (0.5 * 9.81)
    answers = solve_json(run, problems_dir / "11_4.yaml")
    assert answers["counterweight_position"]["values"] == pytest.approx(
        [180 - db * 1000, 180 + db * 1000], rel=1e-9)
    assert answers["counterweight_position"]["values"] == pytest.approx([121.67, 238.33],
                                                                          abs=0.01)
    assert answers["moment"]["values"][0] == pytest.approx(M)


def test_problem_11_5_by_hand(run, problems_dir):
    # Rotor J = 2.5 * 0.035^2 = 3.0625e-3 kg m^2, spin -1725 rpm (ccw seen from A toward B),
    # turntable 48 rpm = 5.0265 rad/s: M = J p Omega = -2.7807 N m.
    # Free body of the 10 kg motor, supports 0.2 m apart, centre midway:
    #   F_A + F_B = 10 * 9.81 = 98.1 N;  0.1 F_A - 0.1 F_B = M  ->  F_A = 49.05 - 13.90 N.
    M = 2.5 * 0.035 ** 2 * (-1725 * RPM) * (48 * RPM)
    F_A, F_B = 98.1 / 2 + M / 0.2, 98.1 / 2 - M / 0.2
    answers = solve_json(run, problems_dir / "11_5.yaml")
    assert answers["bearing_forces"]["values"] == pytest.approx([F_A, F_B], rel=1e-12)
    assert answers["bearing_forces"]["values"] == pytest.approx([35.15, 62.95], abs=0.01)
    assert answers["bearing_forces"]["labels"] == ["A", "B"]


def test_problem_11_7_by_hand(run, problems_dir):
    # 64.4 lb cylinder: m = 2 slug; J = m r^2 / 2 = 2 * 0.5^2 / 2 = 0.25 slug ft^2;
    # M = J p Omega = 0.25 * 50 * 30 = 375 lb ft.
    answers = solve_json(run, problems_dir / "11_7.yaml")
    assert answers["moment"]["values"][0] == pytest.approx(375.0, rel=1e-9)


@pytest.mark.parametrize("name", ["11_4.yaml", "11_5.yaml", "11_7.yaml"])
def test_cli_solves_and_checks_each_problem_file(run, problems_dir, name):
    solved = run("solve", problems_dir / name)
    assert solved.exit_code == 0, solved.output
    assert "line of nodes" in solved.stdout
    checked = run("check", problems_dir / name)
    assert checked.exit_code == 0, checked.output


def test_worked_answer_shows_each_share_and_sense(run, write):
    path = write("""
        id: shares
        kind: gyroscopic_torque
        given:
          mass: 20 kg
          J: 0.4 kg*m^2
          spin: 3000 rpm
          speed: 15 m/s
          turn_radius: 50 m
          bearing_spacing: 0.8 m
          cg_position: 0.3 m
        find:
          bearing_forces: N
          bearing_side_forces: N
        """)
    out = run("solve", path)
    assert out.exit_code == 0, out.output
    for line in ("F_A,weight", "F_B,weight", "F_A,couple", "F_B,couple", "F_A,side",
                 "Sense: the moment the bearings exert on the rotor points along +n"):
        assert line in out.stdout


BAD = [
    ("""
        id: bad
        kind: gyroscopic_torque
        given: {mass: 2 kg, J: 0.01 kg*m^2, spin: 100 rad/s, precession: 1 rad/s,
                bearing_spacing: 0 mm}
        find: {bearing_forces: N}
        """, "bearing_spacing"),
    ("""
        id: bad
        kind: gyroscopic_torque
        given: {mass: 2 kg, J: 0.01 kg*m^2, spin: 100 rad/s, precession: 1 rad/s,
                bearing_spacing: 200 mm, cg_position: 250 mm}
        find: {bearing_forces: N}
        """, "outside the bearings"),
    ("""
        id: bad
        kind: gyroscopic_torque
        given: {mass: 2 kg, J: 0.01 kg*m^2, spin: 100 rad/s, precession: 1 rad/s, theta: 0 deg,
                bearing_spacing: 200 mm}
        find: {moment: N*m}
        """, "theta = 0 deg"),
    ("""
        id: bad
        kind: gyroscopic_torque
        given: {mass: 2 kg, J: 0.01 kg*m^2, spin: 100 rad/s, precession: 1 rad/s,
                speed: 3 m/s, turn_radius: 10 m}
        find: {moment: N*m}
        """, "not precession and speed"),
    ("""
        id: bad
        kind: gyroscopic_torque
        given: {mass: 2 kg, J: 0.01 kg*m^2, spin: 100 rad/s, precession: 1 rad/s,
                cg_radius: 1 m}
        find: {moment: N*m}
        """, "need bearing_spacing"),
]


@pytest.mark.parametrize("text, reason", BAD)
def test_bad_input_exits_2_with_the_reason(run, write, text, reason):
    result = run("solve", write(text))
    assert result.exit_code == 2
    assert reason in result.stderr and "Traceback" not in result.output
    assert len(result.stderr.strip().splitlines()) == 1


def test_overhung_rotor_is_allowed_when_declared(run, write):
    # Overhung: centre 0.1 m beyond B (a = 0.3 m, L = 0.2 m). Static: F_A + F_B = 19.62 N,
    # moments about G: 0.3 F_A - (-0.1) F_B = 0 -> F_A = -9.81 N (A holds the shaft down),
    # F_B = 29.43 N.
    path = write("""
        id: overhung
        kind: gyroscopic_torque
        given: {mass: 2 kg, J: 0.01 kg*m^2, spin: 0 rad/s, precession: 1 rad/s,
                bearing_spacing: 200 mm, cg_position: 300 mm, arrangement: overhung}
        find: {bearing_forces: N}
        """)
    assert solve_json(run, path)["bearing_forces"]["values"] == pytest.approx([-9.81, 29.43])


@pytest.mark.parametrize("theta", [math.radians(50), math.pi / 2, math.radians(130)])
def test_precession_for_a_given_moment_reproduces_it_by_finite_differences(theta):
    from gyro_cli.kinds.gyroscopic_torque import precession_for_moment

    J, I, spin, M = 0.02, 0.03, 80.0, 1.7
    roots = precession_for_moment(J, I, spin, theta, M)
    assert roots
    for precession in roots:
        R_of = lambda t: attitude(t, precession, theta, spin)  # noqa: E731, B023 (called in this iteration)
        h = 1e-2 / max(abs(precession), abs(spin))  # the fast root turns at ~250 rad/s
        rate = dH_dt(R_of, 0.2, np.diag([I, I, J]), h=h)
        n = np.cross(K, R_of(0.2)[:, 2]) / math.sin(theta)
        assert np.allclose(rate, M * n, atol=1e-4 * M)
