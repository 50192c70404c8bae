"""Issue 35 (problems as other books state them, round four): torque_free and euler_angles.

Item 1: torque_free given the angular momentum H (Hibbeler 21-76's football).
Item 2: torque_free's kinetic energy, and the body that dissipates energy (Curtis 10.18,
        the major-axis rule).
Item 5: euler_angles both ways: the angular acceleration from the Euler angles' rates and
        accelerations (Hibbeler ch. 20's antenna), the moment a motion needs by Euler's
        equations, and T and H from body-axis omega with no angle at all.

Each answer is held against a hand calculation written out here, or against something
the kind does not compute: the torque-free motion integrated (solve_ivp), an energy-sink
integration that keeps |H| and loses energy, finite differences of omega and H along the
Euler angles' own motion, sums over particles.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from rotations import cross3, rx, rz
from scipy.integrate import solve_ivp
from test_bad_input import one_line_error
from test_torque_free import measure

RPM = 2 * math.pi / 60


def answers(run, path) -> dict:
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 0, result.output
    return {k: v["si_values"] for k, v in json.loads(result.stdout)["answers"].items()}


def one(run, path) -> dict:
    return {k: v[0] for k, v in answers(run, path).items()}


def tf_file(write, body: str, motion: dict, find: list[str], name: str = "p.yaml"):
    given = "\n".join(f"  {k}: {v}" for k, v in motion.items())
    wanted = "\n".join(f"  {a}: null" for a in find)
    return write(f"id: t\nkind: torque_free\ngiven:\n  {body}\n{given}\nfind:\n{wanted}\n", name)


PROLATE, OBLATE = "J: 0.02 kg m^2\n  I_cg: 0.05 kg m^2", "J: 0.08 kg m^2\n  I_cg: 0.05 kg m^2"
INERTIA = {PROLATE: (0.02, 0.05), OBLATE: (0.08, 0.05)}
MOTION_ANSWERS = ["precession", "spin", "axial_rate", "omega", "nutation_angle", "omega_angle",
                  "angular_momentum", "precession_period", "body_wobble_period"]


# ---- item 1: H given -------------------------------------------------------------------

def test_item01_hibbeler_21_76_football_given_H_by_hand(run, problems_dir):
    # Hibbeler 21-76: m = 450 g, k_z = 30 mm, k = 50 mm, H_G = 0.02 kg m^2/s, theta = 45 deg.
    # I_z = 0.45 (0.03)^2 = 4.05e-4, I = 0.45 (0.05)^2 = 1.125e-3 kg m^2.
    # phidot = H_G / I = 0.02 / 1.125e-3 = 17.78 rad/s;
    # omega_z = H_G cos(theta) / I_z = 0.014142 / 4.05e-4 = 34.92 rad/s;
    # psidot = omega_z - phidot cos(theta) = 34.92 - 12.57 = 22.35 rad/s;
    # tan(beta) = (I_z / I) tan(theta) = 0.36: beta = 19.80 deg.
    a = one(run, problems_dir / "torque_free_football_H_21_76.yaml")
    Iz, I = 0.45 * 0.03 ** 2, 0.45 * 0.05 ** 2
    H, c = 0.02, math.cos(math.radians(45))
    assert a["precession"] == pytest.approx(H / I, rel=1e-12)
    assert a["precession"] == pytest.approx(17.78, abs=5e-3)
    wz = H * c / Iz
    assert a["axial_rate"] == pytest.approx(wz, rel=1e-12)
    assert a["spin"] == pytest.approx(wz - H / I * c, rel=1e-12)
    assert a["spin"] == pytest.approx(22.35, abs=5e-3)
    assert math.degrees(a["omega_angle"]) == pytest.approx(math.degrees(math.atan(0.36)),
                                                            rel=1e-12)
    assert math.degrees(a["omega_angle"]) == pytest.approx(19.80, abs=5e-3)


def test_item01_space_station_H_and_axial_rate_by_hand(run, problems_dir):
    # cos(theta) = I_z omega_z / H_G = 1200 (0.4) / 600 = 0.8: theta = 36.87 deg;
    # phidot = 600 / 2000 = 0.3 rad/s; psidot = (800 / 2000) 0.4 = 0.16 rad/s;
    # omega_e = H sin(theta) / I = 600 (0.6) / 2000 = 0.18: omega = sqrt(0.16 + 0.0324).
    a = one(run, problems_dir / "torque_free_H_and_axial_rate.yaml")
    assert a["nutation_angle"] == pytest.approx(math.acos(0.8), rel=1e-12)
    assert a["precession"] == pytest.approx(0.3, rel=1e-12)
    assert a["spin"] == pytest.approx(0.16, rel=1e-12)
    assert a["omega"] == pytest.approx(math.sqrt(0.16 + 0.0324), rel=1e-12)


H_CASES = [  # body, the two data (H and one more)
    (PROLATE, {"angular_momentum": "0.4 kg m^2/s", "nutation_angle": "40 deg"}),
    (PROLATE, {"angular_momentum": "0.4 kg m^2/s", "omega_angle": "15 deg"}),
    (PROLATE, {"angular_momentum": "0.4 kg m^2/s", "axial_rate": "12 rad/s"}),
    (PROLATE, {"angular_momentum": "0.4 kg m^2/s", "spin": "5 rad/s"}),
    (PROLATE, {"angular_momentum": "0.4 kg m^2/s", "omega": "10 rad/s"}),
    (OBLATE, {"angular_momentum": "0.6 kg m^2/s", "nutation_angle": "30 deg"}),
    (OBLATE, {"angular_momentum": "0.6 kg m^2/s", "axial_rate": "6 rad/s"}),
    (OBLATE, {"angular_momentum": "0.6 kg m^2/s", "spin": "-2 rad/s"}),
    (OBLATE, {"angular_momentum": "0.6 kg m^2/s", "omega": "9 rad/s"}),
]


def _si(text: str) -> float:
    from gyro_cli.core.units import parse

    dim = ("angle" if text.endswith("deg") else "angular_momentum" if "kg" in text
           else "rate")
    return parse(text, dim, "x")[0]


@pytest.mark.parametrize("body, motion", H_CASES)
def test_item01_H_with_each_partner_matches_the_integrated_motion(run, write, body, motion):
    """Euler's equations with no moment, integrated from the omega and beta the kind reports:
    |H| along the motion is the H the file gave, the other datum comes back, and every
    other answer is what the integrated motion shows."""
    J, I = INERTIA[body]
    ans = one(run, tf_file(write, body, motion, MOTION_ANSWERS))
    span = 3 * max(ans["precession_period"], ans["body_wobble_period"])
    got = measure(J, I, ans["omega"], ans["omega_angle"], span)
    for key, text in motion.items():
        assert np.allclose(np.atleast_1d(got[key]), _si(text), rtol=2e-6, atol=1e-9), key
    for name in ("precession", "spin", "axial_rate", "nutation_angle", "omega_angle"):
        assert np.allclose(np.atleast_1d(got[name]), ans[name], rtol=2e-6, atol=1e-8), name


BAD_H = {
    "H tied to precession": (
        {"angular_momentum": "0.4 kg m^2/s", "precession": "8 rad/s"},
        ["given.precession", "tied by phidot = H / I", "fix no angle"]),
    "H below J omega_z": (
        {"angular_momentum": "0.2 kg m^2/s", "axial_rate": "12 rad/s"},
        ["given.angular_momentum", "must exceed J omega_z = 0.24 kg m^2/s", "from axial_rate"]),
    "H inconsistent with spin": (  # omega_z = I psidot / (I - J) = 0.05 (6) / 0.03 = 10
        {"angular_momentum": "0.15 kg m^2/s", "spin": "6 rad/s"},
        ["given.angular_momentum", "must exceed J omega_z = 0.2 kg m^2/s", "from spin"]),
    "H beyond I omega": (
        {"angular_momentum": "0.6 kg m^2/s", "omega": "10 rad/s"},
        ["given.angular_momentum", "strictly between J omega and I omega", "0.2 and 0.5"]),
    "H negative": ({"angular_momentum": "-0.4 kg m^2/s", "omega": "10 rad/s"},
                   ["given.angular_momentum", "expected angular_momentum > 0"]),
    "H at 90 deg": ({"angular_momentum": "0.4 kg m^2/s", "nutation_angle": "90 deg"},
                    ["given.nutation_angle", "90 deg"]),
    "H with two more": ({"angular_momentum": "0.4 kg m^2/s", "nutation_angle": "40 deg",
                         "spin": "5 rad/s"}, ["exactly two", "angular_momentum"]),
}


@pytest.mark.parametrize("name", BAD_H)
def test_item01_bad_H_is_one_line_naming_the_key_and_limit(run, write, name):
    motion, fragments = BAD_H[name]
    one_line_error(run("solve", tf_file(write, PROLATE, motion, ["precession"])), *fragments)


# ---- item 2: energy and its dissipation --------------------------------------------------

def test_item02_curtis_10_18_by_hand(run, problems_dir):
    # A = B = 30, C = 60 kg m^2, omega_z = 2 rad/s, theta = 15 deg.
    # H = C omega_z / cos(theta) = 120 / 0.965926 = 124.233 kg m^2/s, kept;
    # C > A: ends spinning about z at H / C = 2.07055 rad/s.
    # omega_e = H sin(theta) / A = 1.07180 rad/s; T_0 = (1/2)(60 (4) + 30 (1.14875)) = 137.231 J;
    # T_f = H^2 / (2 C) = 128.616 J; lost 8.6156 J.
    a = one(run, problems_dir / "torque_free_curtis_10_18.yaml")
    H = 60 * 2 / math.cos(math.radians(15))
    we = H * math.sin(math.radians(15)) / 30
    T0 = 0.5 * (60 * 4 + 30 * we ** 2)
    assert a["final_rate"] == pytest.approx(H / 60, rel=1e-12)
    assert a["final_rate"] == pytest.approx(2.0706, abs=1e-4)
    assert a["kinetic_energy"] == pytest.approx(T0, rel=1e-12)
    assert a["final_kinetic_energy"] == pytest.approx(H * H / 120, rel=1e-12)
    assert a["energy_lost"] == pytest.approx(T0 - H * H / 120, rel=1e-9)
    assert a["energy_lost"] == pytest.approx(8.616, abs=1e-3)
    assert a["spin_stability"] == "stable"


def test_item02_minor_axis_spinner_by_hand(run, problems_dir):
    # J = 1200 < I = 2000 kg m^2, 2 rpm about the axis, no wobble: H = J omega = 251.33,
    # unstable; ends about a transverse axis at H / I = 1.2 rpm;
    # lost (1/2) J omega^2 - H^2 / (2 I) = 26.319 - 15.791 = 10.528 J.
    a = one(run, problems_dir / "torque_free_minor_axis_flat_spin.yaml")
    w = 2 * RPM
    assert a["spin_stability"] == "unstable"
    assert a["angular_momentum"] == pytest.approx(1200 * w, rel=1e-12)
    assert a["final_rate"] == pytest.approx(1.2 * RPM, rel=1e-12)
    assert a["energy_lost"] == pytest.approx(0.5 * 1200 * w * w - (1200 * w) ** 2 / 4000,
                                             rel=1e-9)


def test_item02_kinetic_energy_by_hand_and_half_omega_dot_H(run, write):
    # prolate J = 0.02, I = 0.05, omega = 10 rad/s at beta = 20 deg:
    # omega_z = 9.3969, omega_e = 3.4202 rad/s; T = (1/2)(0.02 (88.302) + 0.05 (11.698)) J.
    a = one(run, tf_file(write, PROLATE, {"omega": "10 rad/s", "omega_angle": "20 deg"},
                         ["kinetic_energy", "angular_momentum", "nutation_angle"]))
    wz, we = 10 * math.cos(math.radians(20)), 10 * math.sin(math.radians(20))
    T = 0.5 * (0.02 * wz ** 2 + 0.05 * we ** 2)
    assert a["kinetic_energy"] == pytest.approx(T, rel=1e-12)
    # T = (1/2) omega . H: H at theta from k, omega at beta from k, so omega . H = omega H cos
    assert a["kinetic_energy"] == pytest.approx(
        0.5 * 10 * a["angular_momentum"] * math.cos(a["nutation_angle"] - math.radians(20)),
        rel=1e-12)


def _dissipate(J: float, I: float, w0: np.ndarray, rate: float = 2.0, span: float = 60.0):
    """Body-frame H_b' = H_b x omega + (rate / |H|^2) H_b x (H_b x omega): the first term is
    torque-free motion seen in the body, the second is perpendicular to H_b (|H| kept) and
    has omega . (H x (H x omega)) = (omega . H)^2 - |omega|^2 |H|^2 <= 0 (energy lost)."""
    inertia = np.array([I, I, J])

    def rhs(t, H):
        H = H.tolist()  # floats: a numpy array's items cost more than the arithmetic
        turning = cross3(H, [H[0] / I, H[1] / I, H[2] / J])            # H x omega
        k = rate / (H[0] * H[0] + H[1] * H[1] + H[2] * H[2])
        return [a + k * b for a, b in zip(turning, cross3(H, turning))]

    sol = solve_ivp(rhs, (0.0, span), inertia * w0, rtol=1e-11, atol=1e-13, method="DOP853")
    assert sol.success
    H = sol.y[:, -1]
    w = H / inertia
    return np.linalg.norm(inertia * w0), H, w, 0.5 * w @ (inertia * w)


@pytest.mark.parametrize("body, motion", [
    (OBLATE, {"axial_rate": "3 rad/s", "nutation_angle": "25 deg"}),
    (PROLATE, {"omega": "4 rad/s", "omega_angle": "10 deg"}),
    (PROLATE, {"axial_rate": "4 rad/s", "omega_angle": "0 deg"}),
])
def test_item02_dissipation_against_an_energy_sink_integration(run, write, body, motion):
    """|H| kept, energy lost until the state stops changing: the body ends turning about its
    axis of largest moment, at final_rate, with final_kinetic_energy."""
    J, I = INERTIA[body]
    find = ["omega", "omega_angle", "kinetic_energy", "final_rate", "final_kinetic_energy",
            "energy_lost", "spin_stability", "angular_momentum"]
    a = one(run, tf_file(write, body, motion, find))
    beta = a["omega_angle"] or 1e-6  # a steady spin: a wobble of a microradian to start it
    w0 = a["omega"] * np.array([math.sin(beta), 0.0, math.cos(beta)])
    H0, H, w, T = _dissipate(J, I, w0, span=80.0)
    T0 = 0.5 * w0 @ (np.array([I, I, J]) * w0)
    assert np.linalg.norm(H) == pytest.approx(H0, rel=1e-8)
    assert a["angular_momentum"] == pytest.approx(H0, rel=1e-6)
    assert a["kinetic_energy"] == pytest.approx(T0, rel=1e-6)
    assert np.linalg.norm(w) == pytest.approx(a["final_rate"], rel=1e-6)
    assert T == pytest.approx(a["final_kinetic_energy"], rel=1e-6)
    assert T0 - T == pytest.approx(a["energy_lost"], rel=1e-5)
    along_axis = abs(w[2]) / np.linalg.norm(w)
    if a["spin_stability"] == "stable":
        assert J > I and along_axis == pytest.approx(1.0, abs=1e-6)
    else:
        assert I > J and along_axis == pytest.approx(0.0, abs=1e-5)


BAD_STEADY = {
    "precession of a steady spin": (
        {"axial_rate": "4 rad/s", "omega_angle": "0 deg"}, ["precession"],
        ["given.omega_angle", "precession is not defined", "spins steadily about its axis"]),
    "spin given with no wobble": (
        {"spin": "4 rad/s", "nutation_angle": "0 deg"}, ["kinetic_energy"],
        ["given.spin", "nutation_angle = 0", "axial_rate or omega"]),
}


@pytest.mark.parametrize("name", BAD_STEADY)
def test_item02_a_steady_spin_refuses_what_needs_a_wobble(run, write, name):
    motion, find, fragments = BAD_STEADY[name]
    one_line_error(run("solve", tf_file(write, PROLATE, motion, find)), *fragments)


# ---- item 5: euler_angles both ways -------------------------------------------------------

def test_item05_H_and_T_from_body_omega_without_angles(run, problems_dir):
    # omega = (0.1, 0.2, 3) rad/s, I = (400, 300, 500) kg m^2, alpha = (0.05, 0, 0) rad/s^2.
    # H = (40, 60, 1500); T = (1/2)(4 + 12 + 4500) = 2258 J.
    # Euler: M_x = 400 (0.05) - (300 - 500)(0.2)(3) = 140; M_y = -(500 - 400)(3)(0.1) = -30;
    # M_z = -(400 - 300)(0.1)(0.2) = -2 N m.
    a = one(run, problems_dir / "euler_satellite_moment.yaml")
    assert (a["H_x"], a["H_y"], a["H_z"]) == pytest.approx((40.0, 60.0, 1500.0), rel=1e-12)
    assert a["kinetic_energy"] == pytest.approx(2258.0, rel=1e-12)
    assert (a["M_x"], a["M_y"], a["M_z"]) == pytest.approx((140.0, -30.0, -2.0), rel=1e-12)


def test_item05_body_omega_with_particles_needs_no_angle(run, write):
    # H = sum m d x (omega x d), T = (1/2) sum m |omega x d|^2 over the particles themselves
    parts = [(0.5, 0.2, 0.1, 0.0), (0.3, -0.1, 0.3, 0.2), (0.7, 0.0, -0.2, 0.25)]
    omega = np.array([1.5, -2.0, 4.0])
    text = "\n".join(f"    - {{mass: {m} kg, x: {x} m, y: {y} m, z: {z} m}}"
                     for m, x, y, z in parts)
    path = write(f"id: p\nkind: euler_angles\ngiven:\n  omega_x: 1.5 rad/s\n  omega_y: -2 rad/s\n"
                 f"  omega_z: 4 rad/s\n  particles:\n{text}\n"
                 "find:\n  H_x: null\n  H_y: null\n  H_z: null\n  kinetic_energy: null\n"
                 "  omega_H_angle: null\n")
    a = one(run, path)
    H = sum(m * np.cross(d, np.cross(omega, d)) for m, *xyz in parts for d in [np.array(xyz)])
    T = sum(0.5 * m * np.sum(np.cross(omega, np.array(xyz)) ** 2) for m, *xyz in parts)
    assert (a["H_x"], a["H_y"], a["H_z"]) == pytest.approx(tuple(H), rel=1e-12)
    assert a["kinetic_energy"] == pytest.approx(T, rel=1e-12)
    cos = H @ omega / np.linalg.norm(H) / np.linalg.norm(omega)
    assert a["omega_H_angle"] == pytest.approx(math.acos(cos), rel=1e-9)


BAD_EULER = {
    "rates need angles": (
        "omega_x: 1 rad/s\n  omega_y: 2 rad/s\n  omega_z: 3 rad/s\n  I: 1 kg m^2\n  J: 1.5 kg m^2",
        "phi_rate: null\n  H_x: null", ["given.theta", "phi_rate needs the angles theta and psi"]),
    "fixed frame needs angles": (
        "omega_x: 1 rad/s\n  omega_z: 3 rad/s\n  I: 1 kg m^2\n  J: 1.5 kg m^2",
        "H_X: null", ["given.theta", "H_X needs the angles"]),
    "body alpha with Euler rates": (
        "theta: 30 deg\n  psi: 0 deg\n  phi_rate: 2 rad/s\n  alpha_x: 1 rad/s^2\n  I: 1 kg m^2\n"
        "  J: 1.5 kg m^2", "M_x: null", ["given.alpha_x", "phi_acceleration"]),
    "Euler acceleration with body omega": (
        "theta: 30 deg\n  psi: 0 deg\n  omega_x: 2 rad/s\n  phi_acceleration: 1 rad/s^2\n"
        "  I: 1 kg m^2\n  J: 1.5 kg m^2", "M_x: null",
        ["given.phi_acceleration", "alpha_x, alpha_y, alpha_z"]),
    "fixed alpha needs phi": (
        "theta: 30 deg\n  psi: 0 deg\n  phi_rate: 2 rad/s\n  theta_acceleration: 1 rad/s^2",
        "alpha_X: null", ["given.phi", "alpha_X"]),
    "moment needs inertia": (
        "omega_x: 1 rad/s\n  omega_z: 3 rad/s", "moment: null", ["given.I_x", "moment needs"]),
    "yaw acceleration in zxz": (
        "theta: 30 deg\n  psi: 0 deg\n  phi_rate: 2 rad/s\n  yaw_acceleration: 1 rad/s^2",
        "alpha_x: null", ["given.yaw_acceleration", "sequence: zyx"]),
}


@pytest.mark.parametrize("name", BAD_EULER)
def test_item05_bad_input_is_one_line(run, write, name):
    given, find, fragments = BAD_EULER[name]
    path = write(f"id: e\nkind: euler_angles\ngiven:\n  {given}\nfind:\n  {find}\n")
    one_line_error(run("solve", path), *fragments)


def test_item05_hibbeler_antenna_by_hand(run, problems_dir):
    # omega = omega_1 K + omega_2 i' with i' = I at this instant: 1.5 I + 3 K;
    # alpha = omega_1' K + omega_2' i' + omega_1 K x omega_2 i' = 2 K + 4 I + 4.5 J rad/s^2.
    a = one(run, problems_dir / "euler_antenna_hibbeler.yaml")
    assert (a["alpha_X"], a["alpha_Y"], a["alpha_Z"]) == pytest.approx((4.0, 4.5, 2.0),
                                                                       rel=1e-12)
    assert a["angular_acceleration"] == pytest.approx(math.sqrt(16 + 20.25 + 4), rel=1e-12)
    assert (a["omega_X"], a["omega_Z"]) == pytest.approx((1.5, 3.0), rel=1e-12)


def test_item05_rotor_moment_is_J_psidot_phidot(run, problems_dir):
    # theta = 90 deg, rates constant: M = Omega x H = phidot K x J psidot k, k = -J at phi = 0:
    # 2 (0.02)(300) = 12 N m along I (the line of nodes), nothing else.
    a = one(run, problems_dir / "euler_rotor_gyroscopic_moment.yaml")
    assert a["M_x"] == pytest.approx(0.02 * 2 * 300, rel=1e-12)
    assert a["M_X"] == pytest.approx(12.0, rel=1e-12)
    assert abs(a["M_y"]) < 1e-12 and abs(a["M_z"]) < 1e-12
    assert a["moment"] == pytest.approx(12.0, rel=1e-12)


def ry(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0, s], [0, 1.0, 0], [-s, 0, c]])


def vee(W: np.ndarray) -> np.ndarray:
    return np.array([W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1]]) / 2


def _motion(sequence: str, angles, rates, accels):
    """R(t) with each angle a + adot t + addot t^2 / 2, and omega (body, fixed) from R."""
    first, second, third = ((rz, rx, rz) if sequence == "zxz" else (rz, ry, rx))

    def R_of(t):
        a = [x + v * t + 0.5 * c * t * t for x, v, c in zip(angles, rates, accels)]
        return first(a[0]) @ second(a[1]) @ third(a[2])

    def omegas(t, h=1e-5):
        dR = (R_of(t + h) - R_of(t - h)) / (2 * h)
        R = R_of(t)
        return vee(R.T @ dR), vee(dR @ R.T)

    return R_of, omegas


ACCEL_CASES = [  # sequence, angles (deg), rates (rad/s), accelerations (rad/s^2), inertia keys
    ("zxz", (30, 60, 45), (2.0, 1.0, 10.0), (0.5, -1.5, 3.0),
     "I_x: 0.3 kg m^2\n  I_y: 0.4 kg m^2\n  I_z: 0.5 kg m^2"),
    ("zxz", (-50, 120, 200), (-0.7, 3.0, -4.0), (2.0, 0.0, -1.0),
     "I_x: 0.3 kg m^2\n  I_y: 0.4 kg m^2\n  I_z: 0.5 kg m^2\n  I_xy: 0.05 kg m^2\n"
     "  I_zx: -0.03 kg m^2"),
    ("zyx", (20, 30, 40), (0.3, -0.2, 1.5), (1.0, 0.7, -2.0),
     "I_x: 2 kg m^2\n  I_y: 3 kg m^2\n  I_z: 4 kg m^2"),
    ("zyx", (-100, -75, 160), (2.0, 0.4, -3.0), (-0.3, 0.2, 0.9),
     "I_x: 2 kg m^2\n  I_y: 3 kg m^2\n  I_z: 4 kg m^2\n  I_yz: 0.4 kg m^2"),
]


@pytest.mark.parametrize("sequence, angles, rates, accels, inertia", ACCEL_CASES)
def test_item05_alpha_and_moment_against_finite_differences(run, write, sequence, angles,
                                                            rates, accels, inertia):
    """alpha: omega (read off dR/dt along the angles' own motion) differentiated in time, in
    body and fixed axes; M: the fixed-frame H = R I R^T omega differentiated in time."""
    names = ("phi", "theta", "psi") if sequence == "zxz" else ("yaw", "pitch", "roll")
    given = "\n  ".join([f"sequence: {sequence}"]
                        + [f"{n}: {a} deg" for n, a in zip(names, angles)]
                        + [f"{n}_rate: {r} rad/s" for n, r in zip(names, rates)]
                        + [f"{n}_acceleration: {c} rad/s^2" for n, c in zip(names, accels)]
                        + [inertia])
    find = ["alpha_x", "alpha_y", "alpha_z", "alpha_X", "alpha_Y", "alpha_Z", "M_x", "M_y",
            "M_z", "M_X", "M_Y", "M_Z"]
    path = write(f"id: a\nkind: euler_angles\ngiven:\n  {given}\nfind:\n"
                 + "".join(f"  {f}: null\n" for f in find))
    a = one(run, path)
    R_of, omegas = _motion(sequence, [math.radians(x) for x in angles], rates, accels)
    h = 1e-4
    body = (omegas(h)[0] - omegas(-h)[0]) / (2 * h)
    fixed = (omegas(h)[1] - omegas(-h)[1]) / (2 * h)
    assert [a[f"alpha_{n}"] for n in "xyz"] == pytest.approx(list(body), abs=1e-5)
    assert [a[f"alpha_{n}"] for n in "XYZ"] == pytest.approx(list(fixed), abs=1e-5)
    values = dict(line.split(": ") for line in inertia.split("\n  "))
    kg = {k: float(v.split()[0]) for k, v in values.items()}
    Ib = np.array([[kg["I_x"], -kg.get("I_xy", 0), -kg.get("I_zx", 0)],
                   [-kg.get("I_xy", 0), kg["I_y"], -kg.get("I_yz", 0)],
                   [-kg.get("I_zx", 0), -kg.get("I_yz", 0), kg["I_z"]]])

    def H_fixed(t):
        R = R_of(t)
        return R @ Ib @ R.T @ omegas(t)[1]

    M = (H_fixed(h) - H_fixed(-h)) / (2 * h)
    assert [a[f"M_{n}"] for n in "XYZ"] == pytest.approx(list(M), abs=1e-5)
    assert [a[f"M_{n}"] for n in "xyz"] == pytest.approx(list(R_of(0.0).T @ M), abs=1e-5)


def test_item05_constant_euler_rates_still_accelerate():
    """A limiting case by hand: steady precession (rates constant) of a top at theta = 90 deg,
    psi = 0: alpha = phidot K x psidot k, with k = -J at phi = 0: phidot psidot I."""
    import oracles

    from gyro_cli.physics import euler_kinematics as ek

    body = ek.body_accel_zxz(math.pi / 2, 0.0, (2.0, 0.0, 300.0), (0.0, 0.0, 0.0))
    fixed = oracles.fixed_accel_zxz(0.0, math.pi / 2, (2.0, 0.0, 300.0), (0.0, 0.0, 0.0))
    assert body == pytest.approx((600.0, 0.0, 0.0))
    assert fixed == pytest.approx((600.0, 0.0, 0.0))


def test_item05_schema_and_docs_name_the_new_keys(run):
    from pathlib import Path

    schema = json.loads(run("schema").stdout)
    text = json.dumps(schema)
    for key in ("phi_acceleration", "alpha_x", "angular_momentum"):
        assert f'"{key}"' in text
    root = Path(__file__).resolve().parent.parent
    doc = (root / "docs" / "torque_free.md").read_text()
    for name in ("angular_momentum", "kinetic_energy", "final_rate", "energy_lost",
                 "spin_stability", "final_kinetic_energy"):
        assert f"`{name}`" in doc, name
    real = (root / "docs" / "real_problems.md").read_text()
    for file in ("torque_free_football_H_21_76.yaml", "torque_free_curtis_10_18.yaml",
                 "euler_antenna_hibbeler.yaml", "euler_satellite_moment.yaml"):
        assert file in real, file


def test_issue35_problems_check(run, problems_dir):
    files = ["torque_free_football_H_21_76.yaml", "torque_free_curtis_10_18.yaml",
             "torque_free_minor_axis_flat_spin.yaml", "torque_free_H_and_axial_rate.yaml",
             "euler_antenna_hibbeler.yaml", "euler_satellite_moment.yaml",
             "euler_rotor_gyroscopic_moment.yaml"]
    result = run("check", *(problems_dir / f for f in files))
    assert result.exit_code == 0, result.output
    assert "0 failed" in result.output
