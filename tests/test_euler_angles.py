"""euler_angles checked against independent computations.

(a) Eq. 11.8 (and the yaw-pitch-roll rates) against omega read off the rotation
    matrix, R^T dR/dt (body) and dR/dt R^T (fixed frame), by finite differences
    along R(t) = Rz(phi(t)) Rx(theta(t)) Rz(psi(t)) (or Rz Ry Rx);
(b) the inverse put back through the finite-difference omega;
(c) T and H against the particles themselves: v = omega x d for each mass
    (Eq. 11.1), T = (1/2) sum m v.v and H = sum m d x v, nothing from the kind;
    T = (1/2) omega . H and |H| the same in both frames;
(d) particles against bodies of known inertia (a cube's corners about its
    centre and about a corner, a ring), and the symmetric top against Eq. 11.10;
(e) the problem files and bad input (exit 2, one line).
"""

from __future__ import annotations

import json
import math
import re
from fractions import Fraction

import numpy as np
import pytest
from conftest import examples
from hypothesis import example, given, settings
from hypothesis import strategies as st
from rotations import rx, rz

from gyro_cli.physics import euler_kinematics as ek

RPM = 2 * math.pi / 60


def ry(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0, s], [0, 1.0, 0], [-s, 0, c]])


def vee(W: np.ndarray) -> np.ndarray:
    return np.array([W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1]]) / 2


def fd_omegas(R_of, t=0.0, h=1e-6):
    """(body omega from R^T dR/dt, fixed omega from dR/dt R^T), central differences."""
    dR = (R_of(t + h) - R_of(t - h)) / (2 * h)
    R = R_of(t)
    return vee(R.T @ dR), vee(dR @ R.T)


ZXZ_CASES = [  # angles (deg) and rates (rad/s)
    ((30, 60, 45), (2.0, 1.0, 10.0)),
    ((-50, 120, 200), (-0.7, 3.0, -4.0)),
    ((10, 5, -80), (5.0, -2.0, 0.5)),
    ((170, 150, 33), (0.0, 0.0, 7.0)),
    ((0, 90, 0), (1.0, 1.0, 1.0)),
]


@pytest.mark.parametrize("angles, rates", ZXZ_CASES)
def test_eq_11_8_against_the_rotation_matrix(angles, rates):
    phi, theta, psi = map(math.radians, angles)
    r1, r2, r3 = rates

    def R_of(t):
        return rz(phi + r1 * t) @ rx(theta + r2 * t) @ rz(psi + r3 * t)

    body, fixed = fd_omegas(R_of)
    assert np.allclose(ek.body_rates_zxz(theta, psi, *rates), body, atol=1e-7)
    R = np.array(ek.attitude("zxz", phi, theta, psi))
    assert np.allclose(R, R_of(0.0), atol=1e-14)
    assert np.allclose(R @ np.array(ek.body_rates_zxz(theta, psi, *rates)), fixed, atol=1e-7)


@pytest.mark.parametrize("angles, rates", [((20, 30, 40), (0.3, -0.2, 1.5)),
                                           ((-100, -75, 160), (2.0, 0.4, -3.0)),
                                           ((0, 0, 90), (0.1745, 0, 0))])
def test_yaw_pitch_roll_rates_against_the_rotation_matrix(angles, rates):
    yaw, pitch, roll = map(math.radians, angles)
    r1, r2, r3 = rates

    def R_of(t):
        return rz(yaw + r1 * t) @ ry(pitch + r2 * t) @ rx(roll + r3 * t)

    body, _ = fd_omegas(R_of)
    assert np.allclose(ek.body_rates_zyx(pitch, roll, *rates), body, atol=1e-7)
    assert np.allclose(np.array(ek.attitude("zyx", yaw, pitch, roll)), R_of(0.0), atol=1e-14)


@pytest.mark.parametrize("theta, psi, omega", [(40, 25, (3.0, 4.0, 5.0)),
                                               (150, -60, (-1.0, 0.5, 2.0)),
                                               (91, 270, (0.0, 0.0, -3.0))])
def test_inverse_reproduces_omega_through_the_rotation_matrix(theta, psi, omega):
    theta, psi = math.radians(theta), math.radians(psi)
    r1, r2, r3 = ek.euler_rates_zxz(theta, psi, *omega)
    body, _ = fd_omegas(lambda t: rz(0.3 + r1 * t) @ rx(theta + r2 * t) @ rz(psi + r3 * t))
    assert np.allclose(body, omega, atol=1e-6)
    y1, y2, y3 = ek.euler_rates_zyx(theta - 1.0, psi, *omega)
    body, _ = fd_omegas(lambda t: rz(0.2 + y1 * t) @ ry(theta - 1.0 + y2 * t) @ rx(psi + y3 * t))
    assert np.allclose(body, omega, atol=1e-6)


def test_inverse_is_refused_at_the_singular_attitudes():
    for theta in (0.0, math.pi, 2 * math.pi):
        with pytest.raises(ek.SingularAngles):
            ek.euler_rates_zxz(theta, 0.3, 1.0, 2.0, 3.0)
    for pitch in (math.pi / 2, -math.pi / 2):
        with pytest.raises(ek.SingularAngles):
            ek.euler_rates_zyx(pitch, 0.3, 1.0, 2.0, 3.0)


# ---- inertia, T and H from the particles themselves ---------------------------

def particle_sums(particles, omega):
    """T = (1/2) sum m |omega x d|^2 and H = sum m d x (omega x d), Eq. 11.1 directly."""
    T, H = 0.0, np.zeros(3)
    for m, x, y, z in particles:
        d = np.array([x, y, z])
        v = np.cross(omega, d)
        T += 0.5 * m * v @ v
        H += m * np.cross(d, v)
    return T, H


RNG = np.random.default_rng(11)
LUMPY = [(float(RNG.uniform(0.1, 2)), *map(float, RNG.uniform(-0.5, 0.5, 3))) for _ in range(9)]


@pytest.mark.parametrize("omega", [(1.0, 2.0, 3.0), (-4.0, 0.5, 0.0), (0.0, 0.0, 9.0)])
def test_T_and_H_with_products_against_the_particles(omega):
    matrix = ek.inertia_matrix(*ek.inertia_from_particles(LUMPY))
    T_ref, H_ref = particle_sums(LUMPY, np.array(omega))
    assert ek.kinetic_energy(matrix, omega) == pytest.approx(T_ref, rel=1e-12)
    assert np.allclose(ek.angular_momentum(matrix, omega), H_ref, rtol=1e-12, atol=1e-14)
    # and the chapter's expansion of Eq. 11.2 (first line), with its -2 z y w_y w_z terms
    Ix, Iy, Iz, Ixy, Iyz, Izx = ek.inertia_from_particles(LUMPY)
    wx, wy, wz = omega
    T_chapter = 0.5 * (Ix * wx ** 2 + Iy * wy ** 2 + Iz * wz ** 2
                       - 2 * Iyz * wy * wz - 2 * Izx * wz * wx - 2 * Ixy * wx * wy)
    assert T_chapter == pytest.approx(T_ref, rel=1e-12)


def cube(side, mass, corner_at_origin):
    s = side if corner_at_origin else side / 2
    lo = 0.0 if corner_at_origin else -s
    return [(mass, x, y, z) for x in (lo, s) for y in (lo, s) for z in (lo, s)]


def test_cube_corners_about_the_centre_and_about_a_corner():
    m, a = 0.5, 0.2
    Ix, Iy, Iz, Ixy, Iyz, Izx = ek.inertia_from_particles(cube(a, m, False))
    # about the centre: each mass at distance^2 (a/2)^2 + (a/2)^2 from each axis
    assert (Ix, Iy, Iz) == pytest.approx((8 * m * a * a / 2,) * 3)
    assert (Ixy, Iyz, Izx) == pytest.approx((0, 0, 0), abs=1e-15)
    moments = ek.principal_moments(ek.inertia_matrix(*ek.inertia_from_particles(cube(a, m, True))))
    # about a corner: the diagonal passes through the centre, where every axis has
    # 8 m (a^2 / 2) = 4 m a^2; across the diagonal, parallel axes moved by the centre's
    # distance sqrt(3) a / 2: 4 m a^2 + 8 m (3 a^2 / 4) = 10 m a^2
    assert moments == pytest.approx([4 * m * a * a, 10 * m * a * a, 10 * m * a * a])


@pytest.mark.parametrize("n", [3, 4, 7, 24])
def test_ring_of_particles(n):
    m, r = 0.25, 0.3
    ring = [(m, r * math.cos(2 * math.pi * k / n + 0.1), r * math.sin(2 * math.pi * k / n + 0.1),
             0.0) for k in range(n)]
    Ix, Iy, Iz, Ixy, Iyz, Izx = ek.inertia_from_particles(ring)
    M = n * m
    assert Iz == pytest.approx(M * r * r)          # a hoop about its axis
    assert Ix == pytest.approx(M * r * r / 2)      # about a diameter, for any n >= 3
    assert Iy == pytest.approx(M * r * r / 2)
    assert abs(Ixy) < 1e-15 and Iyz == 0 and Izx == 0


def test_products_sign_convention_from_a_single_mass():
    # one mass at (1, 1, 0): I_xy = sum m x y = +m, and H for omega along x has H_y = -m w
    (Ix, Iy, Iz, Ixy, _, _) = ek.inertia_from_particles([(2.0, 1.0, 1.0, 0.0)])
    assert Ixy == 2.0
    H = ek.angular_momentum(ek.inertia_matrix(Ix, Iy, Iz, Ixy), (3.0, 0.0, 0.0))
    _, H_ref = particle_sums([(2.0, 1.0, 1.0, 0.0)], np.array([3.0, 0.0, 0.0]))
    assert np.allclose(H, H_ref) and H[1] == -6.0


# ---- the command line -------------------------------------------------------

def solve_json(run, path):
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 0, result.output
    return {k: v["si_values"] for k, v in json.loads(result.stdout)["answers"].items()}


PARTICLE_FILE = """
    id: p
    kind: euler_angles
    given:
      phi: 35 deg
      theta: 70 deg
      psi: -20 deg
      phi_rate: 1.5 rad/s
      theta_rate: -0.5 rad/s
      psi_rate: 4 rad/s
      particles:
        - {mass: 1 kg, x: 0.1 m, y: 0.2 m, z: -0.1 m}
        - {mass: 2 kg, x: -0.3 m, y: 0.05 m, z: 0.2 m}
        - {mass: 0.5 kg, x: 0 m, y: -0.4 m, z: 0.3 m}
        - {mass: 1.5 kg, x: 0.25 m, y: 0.1 m, z: 0.1 m}
    find: [omega_x, omega_y, omega_z, omega_X, omega_Y, omega_Z, kinetic_energy, H_x, H_y, H_z,
           H_X, H_Y, H_Z, angular_momentum, omega_H_angle, I_xy, principal_moments]
    """


def test_particle_problem_end_to_end(run, write):
    a = solve_json(run, write(PARTICLE_FILE))
    particles = [(1, .1, .2, -.1), (2, -.3, .05, .2), (.5, 0, -.4, .3), (1.5, .25, .1, .1)]
    phi, theta, psi = map(math.radians, (35, 70, -20))

    def R_of(t):
        return rz(phi + 1.5 * t) @ rx(theta - 0.5 * t) @ rz(psi + 4 * t)

    body, fixed = fd_omegas(R_of)
    omega = np.array([a["omega_x"][0], a["omega_y"][0], a["omega_z"][0]])
    assert np.allclose(omega, body, atol=1e-7)
    assert np.allclose([a["omega_X"][0], a["omega_Y"][0], a["omega_Z"][0]], fixed, atol=1e-7)
    T_ref, H_ref = particle_sums(particles, body)
    H = np.array([a["H_x"][0], a["H_y"][0], a["H_z"][0]])
    assert a["kinetic_energy"][0] == pytest.approx(T_ref, rel=1e-7)
    assert np.allclose(H, H_ref, rtol=1e-7)
    assert a["kinetic_energy"][0] == pytest.approx(0.5 * omega @ H, rel=1e-12)  # T = w.H / 2
    H_fixed = np.array([a["H_X"][0], a["H_Y"][0], a["H_Z"][0]])
    assert np.linalg.norm(H_fixed) == pytest.approx(np.linalg.norm(H), rel=1e-12)
    assert np.allclose(H_fixed, R_of(0.0) @ H_ref, rtol=1e-7)
    assert a["angular_momentum"][0] == pytest.approx(np.linalg.norm(H_ref), rel=1e-7)
    cos = omega @ H / np.linalg.norm(omega) / np.linalg.norm(H)
    assert a["omega_H_angle"][0] == pytest.approx(math.acos(cos), rel=1e-6)
    assert a["I_xy"][0] == pytest.approx(sum(m * x * y for m, x, y, _ in particles))
    inertia = sum(m * (np.dot(d, d) * np.eye(3) - np.outer(d, d))
                  for m, *d in [(p[0], *p[1:]) for p in particles] for d in [np.array(d)])
    assert a["principal_moments"] == pytest.approx(sorted(np.linalg.eigvalsh(inertia)))


def test_symmetric_top_against_eq_11_10(run, write):
    # Eq. 11.10: T = (1/2)[I (thetadot^2 + phidot^2 sin^2 th) + J (psidot + phidot cos th)^2]
    I, J, th, pd, td, sd = 0.012, 0.004, math.radians(35), 3.0, -1.2, 60.0
    a = solve_json(run, write(f"""
        id: top
        kind: euler_angles
        given: {{theta: 35 deg, psi: 123 deg, phi_rate: {pd} rad/s, theta_rate: {td} rad/s,
                psi_rate: {sd} rad/s, I: {I} kg m^2, J: {J} kg m^2}}
        find: [kinetic_energy, omega_z]
        """))
    T = 0.5 * (I * (td ** 2 + pd ** 2 * math.sin(th) ** 2) + J * (sd + pd * math.cos(th)) ** 2)
    assert a["kinetic_energy"][0] == pytest.approx(T, rel=1e-12)
    assert a["omega_z"][0] == pytest.approx(sd + pd * math.cos(th), rel=1e-12)


def test_principal_axis_rotation_has_omega_along_H(run, write):
    # a cube of masses about its centre turning about any axis: H parallel to omega
    a = solve_json(run, write("""
        id: c
        kind: euler_angles
        given:
          theta: 50 deg
          psi: 10 deg
          phi_rate: 2 rad/s
          psi_rate: -3 rad/s
          I_x: 0.3 kg m^2
          I_y: 0.3 kg m^2
          I_z: 0.3 kg m^2
        find: [omega_H_angle]
        """))
    assert a["omega_H_angle"][0] == pytest.approx(0.0, abs=1e-12)


def test_bundled_problems_by_hand(run, problems_dir):
    a = solve_json(run, problems_dir / "euler_aircraft_zyx.yaml")
    # banked 90 deg: the 10 deg/s yaw rate is felt entirely as pitch rate q (published)
    assert a["omega_y"][0] == pytest.approx(math.radians(10))
    assert a["omega_x"][0] == 0 and a["omega_z"][0] == 0
    a = solve_json(run, problems_dir / "euler_inverse.yaml")
    th, ps = math.radians(40), math.radians(25)
    back = (a["phi_rate"][0] * math.sin(th) * math.sin(ps) + a["theta_rate"][0] * math.cos(ps),
            a["phi_rate"][0] * math.sin(th) * math.cos(ps) - a["theta_rate"][0] * math.sin(ps),
            a["phi_rate"][0] * math.cos(th) + a["psi_rate"][0])
    assert back == pytest.approx((3.0, 4.0, 5.0))
    a = solve_json(run, problems_dir / "euler_cube_corners.yaml")
    m, s, w = 0.5, 0.2, 10.0  # H = (-2, -2, 8) m a^2 w; angle atan(sqrt(8) / 8)
    assert a["angular_momentum"][0] == pytest.approx(math.sqrt(72) * m * s * s * w)
    assert a["omega_H_angle"][0] == pytest.approx(math.atan(math.sqrt(8) / 8))
    assert run("check", problems_dir / "euler_top_11_3.yaml").exit_code == 0


# ---- bad input --------------------------------------------------------------

def one_line(result, *fragments):
    assert result.exit_code == 2, result.output
    err = result.stderr
    assert err.count("\n") == 1 and "Traceback" not in err, err
    for f in fragments:
        assert f in err, (f, err)
    return err


BASE = """id: b
kind: euler_angles
given:
  theta: 30 deg
  psi: 0 deg
{extra}
find: [{find}]
"""


@pytest.mark.parametrize("extra, find, fragments", [
    ("  phi_rate: 1 rad/s\n  I_x: -0.1 kg m^2\n  I_y: 0.1 kg m^2\n  I_z: 0.1 kg m^2",
     "kinetic_energy", ["given.I_x", "expected I_x > 0 kg m^2"]),
    ("  phi_rate: 1 rad/s\n  I_x: 0.1 kg m^2\n  I_y: 0.1 kg m^2\n  I_z: 0.5 kg m^2",
     "kinetic_energy", ["given.I_z", "no rigid body"]),
    ("  phi_rate: 1 rad/s\n  I: 0.1 kg m^2\n  J: -0.1 kg m^2", "kinetic_energy",
     ["given.J", "expected J > 0 kg m^2"]),
    ("  phi_rate: 1 rad/s\n  particles:\n    - {mass: 1 kg, x: 0 m, y: 1 m, z: 0 m}\n"
     "    - {mass: 1 kg, x: 1 m, y: 0 m, z: 0 m}\n    - {x: 1 m, y: 1 m, z: 0 m}",
     "kinetic_energy", ["given.particles[2].mass", "needs its mass", "(line 10)"]),
    ("  phi_rate: 1 rad/s\n  particles:\n    - {mass: -1 kg, x: 0 m, y: 1 m, z: 0 m}",
     "kinetic_energy", ["given.particles[0].mass", "positive"]),
    ("  phi_rate: 1 rad/s\n  particles:\n    - {mass: 1 kg, x: 0 m, y: 1 m, z: 0 m, w: 1 m}",
     "kinetic_energy", ["given.particles[0].w", "unknown key"]),
    ("  phi_rate: 1 rad/s\n  particles: 3 kg", "kinetic_energy",
     ["given.particles", "list of particles"]),
    ("  omega_x: 1 rad/s\n  omega_y: 2 rad/s\n  omega_z: 3 rad/s", "phi_rate",
     None),  # theta = 30 deg: fine (control)
    ("  phi_rate: 1 rad/s", "omega_X", ["given.phi", "give phi"]),
    ("  phi_rate: 1 rad/s", "kinetic_energy", ["needs the body's inertia"]),
    ("  phi_rate: 1 rad/s\n  omega_x: 1 rad/s", "omega_z", ["not both"]),
    ("  yaw_rate: 1 rad/s", "omega_z", ["given.yaw_rate", "sequence: zyx"]),
])
def test_bad_input(run, tmp_path, extra, find, fragments):
    path = tmp_path / "b.yaml"
    path.write_text(BASE.format(extra=extra, find=find))
    result = run("solve", path)
    if fragments is None:
        assert result.exit_code == 0, result.output
        return
    one_line(result, str(path), *fragments)


@pytest.mark.parametrize("theta", ["0 deg", "180 deg", "360 deg"])
def test_theta_zero_in_the_inverse_is_one_clear_line(run, tmp_path, theta):
    path = tmp_path / "s.yaml"
    path.write_text(BASE.replace("30 deg", theta).format(
        extra="  omega_x: 1 rad/s\n  omega_y: 2 rad/s\n  omega_z: 3 rad/s", find="phi_rate"))
    one_line(run("solve", path), "given.theta", "singular", "same axis")


def test_pitch_90_in_the_zyx_inverse(run, tmp_path):
    path = tmp_path / "s.yaml"
    path.write_text("id: s\nkind: euler_angles\ngiven:\n  sequence: zyx\n  pitch: 90 deg\n"
                    "  roll: 10 deg\n  omega_x: 1 rad/s\n  omega_y: 0 rad/s\n  omega_z: 0 rad/s\n"
                    "find: [yaw_rate]\n")
    one_line(run("solve", path), "given.pitch", "gimbal lock")


def test_near_singular_inverse_warns(run, tmp_path):
    path = tmp_path / "s.yaml"
    path.write_text(BASE.replace("30 deg", "0.5 deg").format(
        extra="  omega_x: 1 rad/s\n  omega_y: 0 rad/s\n  omega_z: 0 rad/s", find="phi_rate"))
    out = json.loads(run("solve", "--format", "json", path).stdout)
    assert any("singular" in w for w in out["warnings"])
    assert math.isfinite(out["answers"]["phi_rate"]["values"][0])


def test_vary_refuses_particles_and_schema_describes_them(run, tmp_path):
    path = tmp_path / "v.yaml"
    path.write_text(BASE.format(extra="  phi_rate: 1 rad/s\n  particles:\n"
                                      "    - {mass: 1 kg, x: 0 m, y: 1 m, z: 0 m}",
                                find="omega_z") + "vary: {particles: [0.9, 1.1]}\n")
    one_line(run("vary", path, "--count", "2", "-o", tmp_path / "o"), "not a numeric given key")
    schema = json.loads(run("schema").stdout)
    rule = next(r for r in schema["allOf"] if r["if"]["properties"]["kind"]["const"] ==
                "euler_angles")
    particles = rule["then"]["properties"]["given"]["properties"]["particles"]
    assert particles["type"] == "array"
    assert particles["items"]["required"] == ["mass", "x", "y", "z"]


def test_every_answer_and_key_is_documented(run):
    from pathlib import Path

    from gyro_cli import kinds

    doc = (Path(__file__).resolve().parent.parent / "docs" / "euler_and_drift.md").read_text()
    listing = run("kinds").stdout
    for name in ("euler_angles", "gyro_drift"):
        kind = kinds.get(name)
        for item in [a.name for a in kind.answers] + [p.name for p in kind.params]:
            assert f"`{item}`" in doc, (name, item)
            assert re.search(rf"^    {item}(\s|angular|rate|inertia|angle)", listing,
                             re.M), (name, item)


def test_no_gravity_line_where_gravity_plays_no_part(run, write):
    out = json.loads(run("solve", "--format", "json", write("""
        id: g
        kind: euler_angles
        given: {theta: 30 deg, psi: 0 deg, psi_rate: 1 rad/s, I: 1 kg m^2, J: 1 kg m^2}
        find: [kinetic_energy]
        """)).stdout)
    assert "g" not in [line["key"] for line in out["given"]]


def test_a_body_described_by_shape_and_cg_distance(run, write):
    # a 2 kg disk of radius 0.1 m whose centre is 0.2 m from the fixed point along k:
    # J = m r^2 / 2 = 0.01, I = m r^2 / 4 + m l^2 = 0.085 (parallel axes); Eq. 11.10 for T
    a = solve_json(run, write("""
        id: disk
        kind: euler_angles
        given: {mass: 2 kg, shape: disk, radius: 0.1 m, cg_distance: 0.2 m,
                theta: 60 deg, psi: 30 deg, phi_rate: 2 rad/s, theta_rate: 0.5 rad/s,
                psi_rate: 40 rad/s}
        find: [kinetic_energy, principal_moments]
        """))
    th = math.radians(60)
    T = 0.5 * (0.085 * (0.25 + 4 * math.sin(th) ** 2) + 0.01 * (40 + 2 * math.cos(th)) ** 2)
    assert a["kinetic_energy"][0] == pytest.approx(T, rel=1e-12)
    assert a["principal_moments"] == pytest.approx([0.01, 0.085, 0.085])


def test_omega_H_angle_at_rest_is_refused_plainly(run, write):
    result = run("solve", write("""
        id: r
        kind: euler_angles
        given: {theta: 30 deg, psi: 0 deg, psi_rate: 0 rad/s, I: 1 kg m^2, J: 1 kg m^2}
        find: [omega_H_angle]
        """))
    one_line(result, "find.omega_H_angle", "undefined")


def eigvalsh(matrix) -> list[float]:
    return [float(v) for v in np.linalg.eigvalsh(np.array(matrix, dtype=float))]


def close_to_eigvalsh(values, matrix, rel=1e-13) -> bool:
    """Each eigenvalue within rel * max|eigenvalue| of numpy's."""
    expected = eigvalsh(matrix)
    scale = max(abs(v) for v in expected)
    return all(abs(v - e) <= rel * scale for v, e in zip(values, expected))


def test_principal_moments_are_lapacks_on_principal_axes_and_close_elsewhere():
    """On principal axes principal_moments sorts the moments: the same floats as numpy's
    eigvalsh for every diagonal matrix inside DIAGONAL_RANGE (equal moments, zeros, widely
    spread ones); outside it, or as soon as one product is not exactly 0, the Jacobi
    rotations answer, within a few ulps of the norm of eigvalsh's answer."""
    import random

    rng = random.Random(11)
    cases = [(0.0, 2.0, 2.0), (1.0, 1.0, 1.0), (3.0, 1.0, 2.0), (1e-100, 1e100, 1.0)]
    for _ in range(3000):
        d = [10 ** rng.uniform(-100, 100) if rng.random() < 0.5 else rng.uniform(0.001, 10)
             for _ in range(3)]
        if rng.random() < 0.2:
            d[1] = d[0]
        if rng.random() < 0.1:
            d[2] = 0.0
        cases.append(tuple(d))
    for d in cases:
        matrix = ek.inertia_matrix(*d)
        assert ek.principal_moments(matrix) == eigvalsh(matrix), d
    # outside the range a diagonal matrix is still its sorted diagonal (no rotation)
    for d in [(1e-120, 1.0, 2.0), (1e150, 1.0, 2.0), (2.0, -0.0, 1e-150)]:
        assert ek.principal_moments(ek.inertia_matrix(*d)) == sorted(d), d
    for d, products in [((1e-120, 1.0, 2.0), (0.0, 0.0, 0.0)), ((1e150, 1.0, 2.0), (0.0,) * 3),
                        ((1.0, 2.0, 2.5), (1e-30, 0.0, 0.0)), ((1.0, 2.0, 2.5), (0.0, 0.3, 0.1))]:
        matrix = ek.inertia_matrix(*d, *products)
        assert close_to_eigvalsh(ek.principal_moments(matrix), matrix), (d, products)


def random_symmetric(rng: np.random.Generator, case: int) -> np.ndarray:
    """A symmetric 3x3 matrix of one of five sorts (case % 5): plain, nearly equal
    eigenvalues, a zero eigenvalue, a common scale 1e-100..1e100, and entries 1e8 apart."""
    sort = case % 5
    if sort in (1, 2):
        if sort == 1:
            eigenvalues = 1.0 + np.array([0.0, rng.choice([0.0, 1e-15, 1e-12, 1e-8]),
                                          rng.choice([0.0, 2e-16, 1e-10])])
        else:
            eigenvalues = np.array([0.0, rng.uniform(0.1, 5), rng.uniform(0.1, 5)])
        Q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        A = Q @ np.diag(eigenvalues) @ Q.T
    else:
        A = rng.uniform(-1, 1, size=(3, 3))
        if sort == 4:
            A *= 10.0 ** rng.uniform(-8, 0, size=(3, 3))
        if sort >= 3:
            A *= 10.0 ** rng.uniform(-100, 100)
    return (A + A.T) / 2


def as_matrix(A: np.ndarray) -> ek.Matrix:
    return tuple(tuple(float(x) for x in row) for row in A)  # type: ignore[return-value]


def test_symmetric_eigenvalues_against_eigvalsh():
    """5000 matrices: every eigenvalue within 1e-13 max|eigenvalue| of eigvalsh's (the worst
    measured, 2e-15: a few ulps)."""
    rng = np.random.default_rng(20)
    for case in range(5000):
        matrix = as_matrix(random_symmetric(rng, case))
        values = ek.symmetric_eigenvalues(matrix)
        assert values == sorted(values)
        assert close_to_eigvalsh(values, matrix), matrix


def test_symmetric_eigenvalues_by_hand():
    # eight masses m at the corners of a cube of side a, about a corner: m a^2 times this
    # matrix, with 4 about the body diagonal and 10 about every axis across it
    cube = ((8.0, -2.0, -2.0), (-2.0, 8.0, -2.0), (-2.0, -2.0, 8.0))
    assert ek.symmetric_eigenvalues(cube) == pytest.approx([4.0, 10.0, 10.0], rel=1e-15)
    m, a = 0.5, 0.2
    scaled = tuple(tuple(m * a * a * x for x in row) for row in cube)
    assert ek.symmetric_eigenvalues(scaled) == pytest.approx([0.08, 0.2, 0.2], rel=1e-15)
    # the 2x2 block [[2, 1], [1, 2]] (eigenvalues 1 and 3) beside 5
    block = ((2.0, 1.0, 0.0), (1.0, 2.0, 0.0), (0.0, 0.0, 5.0))
    assert ek.symmetric_eigenvalues(block) == pytest.approx([1.0, 3.0, 5.0], rel=1e-15)
    # diag(1, 2, 3) turned by the rotation R = (1/3) [[2, -1, 2], [2, 2, -1], [-1, 2, 2]]:
    # R diag(1, 2, 3) R^T = (1/9) [[18, -6, 6], [-6, 15, 0], [6, 0, 21]]
    R = ((2 / 3, -1 / 3, 2 / 3), (2 / 3, 2 / 3, -1 / 3), (-1 / 3, 2 / 3, 2 / 3))
    turned = ((2.0, -2 / 3, 2 / 3), (-2 / 3, 5 / 3, 0.0), (2 / 3, 0.0, 7 / 3))
    assert np.allclose(np.array(R) @ np.diag([1.0, 2.0, 3.0]) @ np.array(R).T, turned,
                       rtol=0, atol=1e-15)
    assert ek.symmetric_eigenvalues(turned) == pytest.approx([1.0, 2.0, 3.0], rel=1e-15)
    assert ek.principal_moments(turned) == pytest.approx([1.0, 2.0, 3.0], rel=1e-15)
    # already diagonal: sorted, not rotated
    assert ek.symmetric_eigenvalues(((3.0, 0.0, 0.0), (0.0, -1.0, 0.0), (0.0, 0.0, 0.0))) == \
        [-1.0, 0.0, 3.0]


@pytest.mark.property
@settings(max_examples=examples(300), deadline=None)
@given(st.lists(st.floats(-1e3, 1e3), min_size=6, max_size=6), st.integers(-60, 60))
@example([0.0, 2.267842938665626e-277, 0.0, 0.0, 2.267842938665626e-277,
          2.267842938665626e-277], -37)  # subnormal entries: found by a `make test`
def test_symmetric_eigenvalues_keep_trace_and_determinant(entries, power):
    """The sum of the eigenvalues is the trace and their product the determinant (computed
    exactly in fractions), to a few ulps of the norm (its cube for the determinant). Among
    subnormal numbers (below 2.2e-308) an eigenvalue is a multiple of the least, 5e-324,
    whatever its size: a few of those are allowed too."""
    a, b, c, d, e, f = (x * 10.0 ** power for x in entries)
    matrix = ((a, d, e), (d, b, f), (e, f, c))
    l1, l2, l3 = ek.symmetric_eigenvalues(matrix)
    scale = max(abs(l1), abs(l3))
    assert abs((l1 + l2 + l3) - (a + b + c)) <= 1e-14 * scale + 4 * math.ulp(0.0)
    F = [[Fraction(x) for x in row] for row in matrix]
    det = (F[0][0] * (F[1][1] * F[2][2] - F[1][2] * F[2][1])
           - F[0][1] * (F[1][0] * F[2][2] - F[1][2] * F[2][0])
           + F[0][2] * (F[1][0] * F[2][1] - F[1][1] * F[2][0]))
    assert abs(l1 * l2 * l3 - float(det)) <= 1e-13 * scale ** 3


def test_symmetric_eigenvalues_refuse_what_is_not_finite():
    for bad in (math.inf, -math.inf, math.nan):
        with pytest.raises(ValueError, match="not finite"):
            ek.symmetric_eigenvalues(ek.inertia_matrix(1.0, 2.0, 2.5, bad))
    # scaled by a power of two, neither huge nor tiny entries overflow or underflow
    for size in (1e307, 1e-300):
        matrix = ek.inertia_matrix(size, size, size, size)
        assert ek.symmetric_eigenvalues(matrix) == pytest.approx([0.0, size, 2 * size],
                                                                 rel=1e-15, abs=1e-15 * size)


def test_principal_moments_do_not_import_numpy():
    """gyro check must not import numpy for a matrix with products of inertia."""
    import subprocess
    import sys

    code = ("import sys\n"
            "class NoNumpy:\n"
            "    def find_spec(self, name, path=None, target=None):\n"
            "        if name.split('.')[0] == 'numpy':\n"
            "            raise ImportError('numpy is blocked')\n"
            "sys.meta_path.insert(0, NoNumpy())\n"
            "from gyro_cli.physics import euler_kinematics as ek\n"
            "print(ek.principal_moments(ek.inertia_matrix(8.0, 8.0, 8.0, 2.0, 2.0, 2.0)))\n"
            "print('numpy' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         check=True)
    values, numpy_loaded = out.stdout.split("\n")[:2]
    assert [float(v) for v in values.strip("[]").split(",")] == pytest.approx([4, 10, 10])
    assert numpy_loaded == "False"


@pytest.mark.parametrize("extra, fragments", [
    ("  I_x: 1 kg m^2\n  I_y: 2 kg m^2\n  I_z: 2.5 kg m^2\n  I_xy: 1e300 kg m^2",
     ["given.I_xy", "not positive definite"]),
    ("  particles:\n    - {mass: 1 kg, x: 1e200 m, y: 1 m, z: 0 m}\n"
     "    - {mass: 1 kg, x: 1 m, y: 1e200 m, z: 1 m}",
     ["given", "outside what euler_angles can compute", "not finite"]),
])
def test_huge_inertia_is_one_clear_line(run, tmp_path, extra, fragments):
    path = tmp_path / "h.yaml"
    path.write_text(BASE.format(extra="  phi_rate: 1 rad/s\n" + extra,
                                find="principal_moments, kinetic_energy"))
    one_line(run("solve", path), str(path), *fragments)
