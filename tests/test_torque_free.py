"""torque_free checked against independent computations.

(a) Euler's equations with no moment, I w_x' = (I - J) w_y w_z, I w_y' = (J - I) w_z w_x,
    J w_z' = 0, integrated with the attitude R' = R [w]x (solve_ivp) from the state the
    kind reports (omega and beta only); along the motion the test measures the angle of
    the axis from H, the rate of the axis about H, the Euler spin psi (node line to body
    x axis), the turn of omega about k in the body, both cone angles and |H|. Each must
    match every answer the kind gives and the two quantities the file gave;
(b) the five problem files worked by hand in the textbooks' own formulas;
(c) limiting cases: a nearly spherical body, Feynman's plate;
(d) bad input: one line, exit 2; `gyro vary` on the kind's example.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from rotations import rows_times_skew
from scipy.integrate import solve_ivp
from test_bad_input import one_line_error

RPM = 2 * math.pi / 60
SIDEREAL_DAY = 86164.0905  # s


def integrate(J, I, omega, beta, periods):
    """Body rates and attitude from omega at beta to k (in the body x-z plane), R(0) = 1."""
    def rhs(t, y):
        w0, w1, w2, *R = y.tolist()
        dw = [(I - J) * w1 * w2 / I, (J - I) * w2 * w0 / I, 0.0]
        return dw + rows_times_skew(R, [w0, w1, w2])

    w0 = [omega * math.sin(beta), 0.0, omega * math.cos(beta)]
    y0 = np.concatenate([w0, np.eye(3).ravel()])
    t = np.linspace(0.0, periods, 4001)
    sol = solve_ivp(rhs, (0.0, periods), y0, t_eval=t, rtol=1e-11, atol=1e-12,
                    method="DOP853")
    assert sol.success
    return sol.t, sol.y[:3].T, sol.y[3:].T.reshape(-1, 3, 3)


def slope(t, angle):
    return np.polyfit(t, np.unwrap(angle), 1)[0]


def measure(J, I, omega, beta, span):
    """Everything the kind answers, measured on the integrated motion."""
    t, w, R = integrate(J, I, omega, beta, span)
    H = R[0] @ np.diag([I, I, J]) @ w[0]
    h = H / np.linalg.norm(H)
    k = R[:, :, 2]
    x = R[:, :, 0]
    e1 = np.cross(h, [1.0, 0.0, 0.0] if abs(h[0]) < 0.9 else [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(h, e1)
    theta = np.arccos(np.clip(k @ h, -1, 1))
    phi = np.arctan2(k @ e2, k @ e1)              # the axis about H, in space
    node = np.cross(h, k)
    node /= np.linalg.norm(node, axis=1)[:, None]
    psi = np.arctan2(np.einsum("ij,ij->i", np.cross(node, x), k), np.einsum("ij,ij->i", node, x))
    w_space = np.einsum("nij,nj->ni", R, w)
    wnorm = np.linalg.norm(w, axis=1)
    # H at every instant, to see it stays put
    H_t = np.einsum("nij,nj->ni", R, w * [I, I, J])
    assert np.allclose(H_t, H, atol=1e-8 * np.linalg.norm(H))
    return {
        "nutation_angle": theta,
        "precession": slope(t, phi),
        "spin": slope(t, psi),
        "axial_rate": w[:, 2],
        "omega": wnorm,
        "omega_angle": np.arccos(w[:, 2] / wnorm),
        "body_wobble_period": 2 * math.pi / abs(slope(t, np.arctan2(w[:, 1], w[:, 0]))),
        "body_cone_angle": np.arccos(w[:, 2] / wnorm),
        "space_cone_angle": np.arccos(np.clip(w_space @ h / wnorm, -1, 1)),
        "angular_momentum": np.linalg.norm(H),
    }


PROLATE = (0.02, 0.05)
OBLATE = (0.08, 0.05)
CASES = [  # (J, I), given motion (two keys)
    (PROLATE, {"omega": "10 rad/s", "omega_angle": "20 deg"}),
    (PROLATE, {"omega": "10 rad/s", "nutation_angle": "40 deg"}),
    (PROLATE, {"omega": "10 rad/s", "axial_rate": "8 rad/s"}),
    (PROLATE, {"omega": "10 rad/s", "precession": "6 rad/s"}),
    (PROLATE, {"omega": "10 rad/s", "spin": "3 rad/s"}),
    (PROLATE, {"omega_angle": "15 deg", "axial_rate": "7 rad/s"}),
    (PROLATE, {"omega_angle": "15 deg", "precession": "5 rad/s"}),
    (PROLATE, {"omega_angle": "15 deg", "spin": "2 rad/s"}),
    (PROLATE, {"nutation_angle": "50 deg", "axial_rate": "70 rpm"}),
    (PROLATE, {"nutation_angle": "50 deg", "precession": "5 rad/s"}),
    (PROLATE, {"nutation_angle": "50 deg", "spin": "2 rad/s"}),
    (PROLATE, {"axial_rate": "7 rad/s", "precession": "4 rad/s"}),
    (PROLATE, {"precession": "4 rad/s", "spin": "2 rad/s"}),
    (OBLATE, {"omega": "10 rad/s", "omega_angle": "35 deg"}),
    (OBLATE, {"omega": "10 rad/s", "spin": "-3 rad/s"}),
    (OBLATE, {"omega": "10 rad/s", "precession": "12 rad/s"}),
    (OBLATE, {"axial_rate": "5 rad/s", "precession": "9 rad/s"}),
    (OBLATE, {"nutation_angle": "30 deg", "spin": "-2 rad/s"}),
    (OBLATE, {"omega_angle": "60 deg", "precession": "10 rad/s"}),
    (OBLATE, {"precession": "12 rad/s", "spin": "-3 rad/s"}),
    (OBLATE, {"nutation_angle": "80 deg", "omega": "3 rad/s"}),
]

ANSWERS = ["precession", "spin", "axial_rate", "omega", "nutation_angle", "omega_angle",
           "angular_momentum", "precession_period", "body_wobble_period", "body_cone_angle",
           "space_cone_angle", "motion"]


def solve_json(run, write, J, I, motion):
    given = "\n".join(f"  {k}: {v}" for k, v in motion.items())
    find = "\n".join(f"  {a}: null" for a in ANSWERS)
    path = write(f"id: t\nkind: torque_free\ngiven:\n  J: {J} kg m^2\n  I_cg: {I} kg m^2\n"
                 f"{given}\nfind:\n{find}\n")
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 0, result.output
    return {k: v["si_values"][0] for k, v in json.loads(result.stdout)["answers"].items()}


def si(text):
    from gyro_cli.core.units import parse

    dim = "angle" if text.endswith("deg") else "rate"
    return parse(text, dim, "x")[0]


@pytest.mark.parametrize("inertia, motion", CASES)
def test_answers_match_integrated_euler_equations(run, write, inertia, motion):
    J, I = inertia
    ans = solve_json(run, write, J, I, motion)
    span = 3 * max(ans["precession_period"], ans["body_wobble_period"])
    got = measure(J, I, ans["omega"], ans["omega_angle"], span)
    for name, measured in got.items():
        values = np.atleast_1d(measured)
        # constant along the motion, and equal to the kind's answer
        assert np.allclose(values, ans[name], rtol=2e-6, atol=1e-8), (name, values[:3], ans[name])
    assert ans["precession_period"] == pytest.approx(2 * math.pi / got["precession"], rel=2e-6)
    # the two quantities the file gave come back out of the integration
    for key, text in motion.items():
        measured = np.atleast_1d(got[key])
        assert np.allclose(measured, si(text), rtol=2e-6, atol=1e-9), (key, text)
    # direct: psi and phi turn the same way, the axis lies farther from H than omega does
    measured_sense = "direct" if got["spin"] * got["precession"] > 0 else "retrograde"
    assert ans["motion"] == measured_sense
    theta, beta = got["nutation_angle"][0], got["omega_angle"][0]
    assert (theta > beta) == (measured_sense == "direct")
    assert got["precession"] > 0 and got["axial_rate"][0] > 0


# ---- the problem files by hand -------------------------------------------------

def answers_of(run, path):
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 0, result.output
    return {k: v["si_values"] for k, v in json.loads(result.stdout)["answers"].items()}


def test_curtis_shell_by_hand(run, problems_dir):
    # Curtis, Ex. 10.2: C = m r^2 = 100, A = m r^2 / 2 + m l^2 / 12 = 50 + 75 = 125 kg m^2.
    # omega_p = C / (A - C) omega_s / cos(theta) = 4 (2 pi rad/min) / cos 20 = 26.746 rad/min;
    # 180 deg takes pi / omega_p = 0.117463 min = 7.048 s.
    a = answers_of(run, problems_dir / "torque_free_shell.yaml")
    C, A = 100 * 1.0 ** 2, 100 * 1.0 ** 2 / 2 + 100 * 3.0 ** 2 / 12
    omega_p = C / (A - C) * 6.2832 / math.cos(math.radians(20))  # rad/min
    assert omega_p == pytest.approx(26.746, abs=1e-3)
    assert a["precession"][0] * 60 == pytest.approx(omega_p, rel=1e-9)
    assert a["precession_period"][0] / 2 == pytest.approx(7.048, abs=1e-3)
    assert a["motion"] == ["direct"]


def test_hibbeler_football_by_hand(run, problems_dir):
    # H vertical, axis 30 deg above the horizontal: theta = 60 deg; I_z / I = 1/3.
    # psidot = (I - I_z) / I_z phidot cos(theta) = 2 (3) (0.5) = 3 rad/s.
    # omega_x = phidot sin(theta) = 2.598, omega_z = psidot + phidot cos(theta) = 4.5;
    # omega = sqrt(2.598^2 + 4.5^2) = 5.196 rad/s (book: 5.20 rad/s).
    a = answers_of(run, problems_dir / "torque_free_football.yaml")
    assert a["spin"][0] == pytest.approx(3.0, rel=1e-9)
    assert a["omega"][0] == pytest.approx(math.hypot(3 * math.sin(math.pi / 3), 4.5), rel=1e-9)
    assert a["omega"][0] == pytest.approx(5.20, abs=0.005)
    assert a["omega_angle"][0] == pytest.approx(math.atan(2.598076 / 4.5), rel=1e-6)


def test_hibbeler_21_72_football_by_hand(run, problems_dir):
    # I_z = m k_z^2 = 0.25 (0.042)^2 = 4.41e-4, I = m k_y^2 = 0.25 (0.13)^2 = 4.225e-3 kg m^2.
    # H_G = I_z omega_z / cos(theta) = 4.41e-4 (15) / 0.766044 = 8.6353e-3 kg m^2/s;
    # phidot = H_G / I = 2.0439 rad/s; psidot = omega_z - phidot cos(theta) = 13.434 rad/s.
    a = answers_of(run, problems_dir / "torque_free_football_21_72.yaml")
    Iz, I = 0.25 * 0.042 ** 2, 0.25 * 0.13 ** 2
    H = Iz * 15 / math.cos(math.radians(40))
    assert a["angular_momentum"][0] == pytest.approx(H, rel=1e-12)
    assert a["precession"][0] == pytest.approx(H / I, rel=1e-12)
    assert a["precession"][0] == pytest.approx(2.044, abs=5e-4)
    assert a["spin"][0] == pytest.approx(15 - H / I * math.cos(math.radians(40)), rel=1e-12)


def test_rigid_earth_euler_period_by_hand(run, problems_dir):
    # Euler: the figure sees the rotation axis go round in (A / (C - A)) sidereal days
    # = 1 / 0.00328 = 304.88 sidereal days = 304.05 days of 86400 s, retrograde (oblate).
    a = answers_of(run, problems_dir / "torque_free_earth.yaml")
    euler_days = SIDEREAL_DAY / 0.00328 / 86400
    assert euler_days == pytest.approx(304.05, abs=0.01)
    # omega_z in the file is 7.292115e-5 rad/s, 1 turn per 86164.1 s to 7 figures
    assert a["body_wobble_period"][0] / 86400 == pytest.approx(euler_days, rel=2e-6)
    assert a["motion"] == ["retrograde"]
    # the space cone is small: beta - theta = beta (C - A) / C to first order
    beta = math.radians(0.25 / 3600)
    assert a["space_cone_angle"][0] == pytest.approx(beta * 0.00328 / 1.00328, rel=1e-4)


def test_oblate_satellite_by_hand(run, problems_dir):
    # J / I = 1.6, phidot = pi rad/s, psidot = -0.1 rad/s (retrograde):
    # omega_z = I psidot / (I - J) = -0.1 / -0.6 = 0.16667 rad/s;
    # cos(theta) = J omega_z / (I phidot) = 1.6 (0.16667) / pi = 0.084883, theta = 85.131 deg;
    # omega_perp = pi sin(theta) = 3.13026; omega = sqrt(0.16667^2 + 3.13026^2) = 3.13469 rad/s.
    a = answers_of(run, problems_dir / "torque_free_satellite.yaml")
    assert a["axial_rate"][0] == pytest.approx(1 / 6, rel=1e-9)
    cos = 1.6 * (1 / 6) / math.pi
    assert math.degrees(a["nutation_angle"][0]) == pytest.approx(85.131, abs=1e-3)
    assert a["omega"][0] == pytest.approx(math.hypot(1 / 6, math.pi * math.sqrt(1 - cos * cos)),
                                          rel=1e-9)
    assert a["omega"][0] == pytest.approx(3.13469, abs=1e-5)


def test_feynman_plate_wobbles_at_twice_its_spin(run, problems_dir):
    # Thin disk: J = 2 I, so psidot = -omega_z and phidot = 2 omega_z / cos(theta).
    a = answers_of(run, problems_dir / "torque_free_plate.yaml")
    wz = 3 * 2 * math.pi
    assert a["spin"][0] == pytest.approx(-wz, rel=1e-12)
    assert a["precession"][0] / wz == pytest.approx(2 / math.cos(math.radians(1)), rel=1e-12)


def test_nearly_spherical_body_turns_about_H(run, write):
    # J -> I: omega lines up with H, the axis precesses at omega and the wobble stops.
    ans = solve_json(run, write, 0.1, 0.1 * (1 + 1e-7), {"omega": "5 rad/s",
                                                         "omega_angle": "40 deg"})
    assert ans["precession"] == pytest.approx(5.0, rel=1e-6)
    assert ans["space_cone_angle"] < 1e-6
    assert ans["body_wobble_period"] > 1e6


def test_worked_answer_states_conventions_and_checks(run, problems_dir):
    result = run("solve", problems_dir / "torque_free_satellite.yaml")
    assert result.exit_code == 0, result.output
    out = result.stdout
    assert "taken on the side of H" in out and "retrograde precession" in out
    assert "acos(J omega_z / (I phidot))" in out and "Check" in out
    assert "9.81 m/s^2" not in out  # no weight acts: g is not listed among the data


# ---- bad input -----------------------------------------------------------------

def tf(motion: str, body: str = "J: 0.02 kg m^2\n  I_cg: 0.05 kg m^2") -> str:
    return f"id: x\nkind: torque_free\ngiven:\n  {body}\n  {motion}\nfind:\n  precession: rpm\n"


BAD = {
    "one motion key": (tf("omega: 10 rad/s"), ["given.omega", "exactly two", "got omega"]),
    "three motion keys": (tf("omega: 10 rad/s\n  spin: 2 rad/s\n  precession: 5 rad/s"),
                          ["given.spin", "exactly two"]),
    "angles tied": (tf("omega_angle: 10 deg\n  nutation_angle: 20 deg"),
                    ["given.nutation_angle", "tied", "fix no rate"]),
    "rates tied": (tf("axial_rate: 10 rad/s\n  spin: 6 rad/s"), ["given.spin", "tied"]),
    "theta 90": (tf("nutation_angle: 90 deg\n  omega: 1 rad/s"),
                 ["given.nutation_angle", "expected 0 deg <= nutation_angle < 90 deg", "got '90 deg'"]),
    "theta over 90": (tf("nutation_angle: 120 deg\n  omega: 1 rad/s"),
                      ["given.nutation_angle", "180 deg minus"]),
    "beta 0": (tf("omega_angle: 0 deg\n  omega: 1 rad/s"),
               ["given.omega_angle", "spins steadily about its axis"]),
    "negative omega": (tf("omega: -3 rad/s\n  omega_angle: 10 deg"),
                       ["given.omega", "expected omega > 0 rad/s"]),
    "zero precession": (tf("precession: 0 rpm\n  omega_angle: 10 deg"),
                        ["given.precession", "expected precession > 0 rad/s"]),
    "spin sign oblate": (tf("spin: 3 rad/s\n  omega: 10 rad/s",
                            "J: 0.08 kg m^2\n  I_cg: 0.05 kg m^2"),
                         ["given.spin", "negative for this oblate", "retrograde"]),
    "spin sign prolate": (tf("spin: -3 rad/s\n  omega: 10 rad/s"),
                          ["given.spin", "positive for this prolate"]),
    "spin zero": (tf("spin: 0 rad/s\n  omega: 10 rad/s"), ["given.spin", "expected spin != 0 rad/s"]),
    "omega below axial": (tf("omega: 5 rad/s\n  axial_rate: 6 rad/s"),
                          ["given.omega", "must exceed the axial rate"]),
    "omega equals axial": (tf("omega: 5 rad/s\n  axial_rate: 5 rad/s"), ["given.omega"]),
    "omega below spin's axial": (tf("omega: 4 rad/s\n  spin: 3 rad/s"),
                                 ["given.omega", "from spin"]),
    "precession out of range": (tf("omega: 10 rad/s\n  precession: 12 rad/s"),
                                ["given.precession", "between J omega / I and omega",
                                 "4 and 10 rad/s"]),
    "precession too slow": (tf("axial_rate: 10 rad/s\n  precession: 3 rad/s"),
                            ["given.precession", "must exceed J omega_z / I = 4 rad/s"]),
    "J equals I": (tf("omega: 1 rad/s\n  omega_angle: 10 deg",
                      "J: 0.05 kg m^2\n  I_cg: 0.05 kg m^2"), ["given.J", "J = I"]),
    "negative inertia": (tf("omega: 1 rad/s\n  omega_angle: 10 deg",
                            "J: 0.02 kg m^2\n  I_cg: -0.05 kg m^2"),
                         ["given.I_cg", "expected I_cg > 0 kg m^2"]),
    "missing I": (tf("omega: 1 rad/s\n  omega_angle: 10 deg", "J: 0.02 kg m^2"),
                  ["given.I_cg", "I_cg, k_cg or a shape"]),
    "I about a pivot": (tf("omega: 1 rad/s\n  omega_angle: 10 deg",
                           "J: 0.02 kg m^2\n  I_pivot: 0.05 kg m^2"),
                        ["given.I_pivot", "centre of mass"]),
    "H without mass": (tf("omega: 1 rad/s\n  omega_angle: 10 deg",
                          "k_axial: 0.1 m\n  k_cg: 0.2 m").replace(
        "find:\n", "find:\n  angular_momentum: kg m^2/s\n"), ["given.mass", "depends on the mass"]),
    "overflow": (tf("precession: 1e308 rad/s\n  spin: 1e308 rad/s"),
                 ["given.precession", "overflow or underflow"]),
    "underflow": (tf("omega: 1e-310 rad/s\n  omega_angle: 30 deg"),
                  ["given.omega", "overflow or underflow"]),
    "rate as angle": (tf("omega: 10 deg\n  omega_angle: 10 deg"), ["given.omega", "rate"]),
}


@pytest.mark.parametrize("name", BAD)
def test_bad_input_is_one_line(run, write, name):
    text, fragments = BAD[name]
    one_line_error(run("solve", write(text)), *fragments)


def test_vary_on_the_example(run, tmp_path):
    new = tmp_path / "tf.yaml"
    assert run("new", "torque_free", "-o", new).exit_code == 0
    out = tmp_path / "variants"
    result = run("vary", new, "--count", "5", "--seed", "3", "-o", out)
    assert result.exit_code == 0, result.output
    result = run("check", out)
    assert result.exit_code == 0, result.output


@pytest.mark.parametrize("J, warned", [("0.1004", False), ("0.2", True)])
def test_j_over_two_i_is_solved_with_a_warning(run, write, J, warned):
    # textbook data no rigid body could have: solved as given, the inconsistency named
    # (within the body check's 1% slack for rounded data, silently)
    path = write(tf("omega: 1 rad/s\n  omega_angle: 10 deg", f"J: {J} kg m^2\n  I_cg: 0.05 kg m^2"))
    result = run("solve", path)
    assert result.exit_code == 0, result.output
    assert ("exceeds twice the transverse moment I_G" in result.stdout and "no rigid body" in result.stdout) is warned


def test_radii_of_gyration_without_mass_give_the_rates(run, write):
    # J/I = (k_z/k_G)^2 = 1/4: tan(theta) = 4 tan(10 deg); H / I per kilogram cancels
    path = write(tf("omega: 1 rad/s\n  omega_angle: 10 deg", "k_axial: 0.1 m\n  k_cg: 0.2 m")
                 .replace("precession: rpm", "precession: rad/s"))
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 0, result.output
    import json

    wz, we = math.cos(math.radians(10)), math.sin(math.radians(10))
    H_per_kg = math.hypot(0.01 * wz, 0.04 * we)
    value = json.loads(result.stdout)["answers"]["precession"]["values"][0]
    assert value == pytest.approx(H_per_kg / 0.04, rel=1e-12)


def test_latex_of_tiny_angles_has_one_superscript(run, problems_dir):
    # 6.9e-5 deg must not become 6.9\times10^{-5}^{\circ}, which TeX rejects
    for fmt in ("latex", "markdown"):
        result = run("solve", "--format", fmt, problems_dir / "torque_free_earth.yaml")
        assert result.exit_code == 0, result.output
        assert "}^{\\circ}" in result.stdout
        assert "10^{-5}^" not in result.stdout and "10^{-7}^" not in result.stdout


def test_free_cone_uses_i_about_its_centre_of_mass(run, write):
    # solid cone, m = 1 kg, r = 0.1 m, h = 0.3 m: J = 3 m r^2 / 10 = 0.003,
    # I_G = m (3 r^2 / 20 + 3 h^2 / 80) = 0.0015 + 0.003375 = 0.004875 kg m^2 (not about the apex).
    # omega = 10 rad/s at beta = 10 deg: omega_z = 9.8481, omega_e = 1.7365 rad/s,
    # H = sqrt((0.003 omega_z)^2 + (0.004875 omega_e)^2), phidot = H / I_G.
    path = write("id: x\nkind: torque_free\ngiven:\n  mass: 1 kg\n  shape: cone\n  radius: 0.1 m\n"
                 "  height: 0.3 m\n  omega: 10 rad/s\n  omega_angle: 10 deg\n"
                 "find:\n  precession: rad/s\n")
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 0, result.output
    got = json.loads(result.stdout)["answers"]["precession"]["si_values"][0]
    wz, we = 10 * math.cos(math.radians(10)), 10 * math.sin(math.radians(10))
    assert got == pytest.approx(math.hypot(0.003 * wz, 0.004875 * we) / 0.004875, rel=1e-12)
