"""Independent checks of the kinds torque_free, euler_angles and gyro_drift.

Every expected value here is derived in this file from first principles
(Euler's equations, H = sum m r x (omega x r), rotation matrices, Lagrange's
equations for a rotor in gimbals), written out step by step, and wherever
possible confirmed by integrating the equations of motion with
scipy.integrate.solve_ivp or by finite differences of rotation matrices.
Nothing is taken from gyro's own formulas: only the key and answer names and
the sign conventions stated in docs/torque_free.md and docs/euler_and_drift.md.

The problems are stated as different books would state them: slug ft^2, rpm,
rev/s, deg/h, g cm^2, dyn cm, mm and grams, radii of gyration.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from rotations import rows_times_skew
from scipy.integrate import solve_ivp

# ---------------------------------------------------------------- units
SLUG_FT2 = 14.59390293720636 * 0.3048**2   # 1 slug ft^2 in kg m^2
G_CM2 = 1e-3 * 1e-4                          # 1 g cm^2 in kg m^2
DYN_CM = 1e-5 * 1e-2                         # 1 dyn cm in N m
RPM = 2 * math.pi / 60                       # 1 rev/min in rad/s
DEG = math.pi / 180
HOUR = 3600.0
YEAR = 365.25 * 86400.0                      # the Julian year

RTOL = 1e-6          # closed forms
RTOL_INT = 1e-6      # tight integrations of exact (linear-in-time) motions


# ---------------------------------------------------------------- helpers
def solve(run, write, text, name="p.yaml"):
    """Solve a problem in-process; return {answer: si value (or list)}."""
    path = write(text, name)
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    out = {}
    for key, ans in data["answers"].items():
        vals = ans["si_values"]
        out[key] = vals[0] if len(vals) == 1 else vals
    out["_warnings"] = data.get("warnings", [])
    out["_values"] = {k: a["values"] for k, a in data["answers"].items()}
    return out


def refused(run, write, text, key):
    """Exit 2, with the one-line reason naming the offending given key."""
    path = write(text, "bad.yaml")
    result = run("solve", "--format", "json", path)
    return result.exit_code == 2 and f"given.{key}" in result.output


def close(a, b, rtol=RTOL, atol=0.0):
    return math.isclose(a, b, rel_tol=rtol, abs_tol=atol)


def vee(W):
    """Axial vector of a (nearly) skew matrix."""
    return np.array([W[2, 1] - W[1, 2], W[0, 2] - W[2, 0], W[1, 0] - W[0, 1]]) / 2


def Rx(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def Ry(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def Rz(a):
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def R_zxz(phi, theta, psi):
    return Rz(phi) @ Rx(theta) @ Rz(psi)


def R_zyx(yaw, pitch, roll):
    return Rz(yaw) @ Ry(pitch) @ Rx(roll)


def omega_fd(Rfun, angles, rates):
    """omega from R(t) = Rfun(angles + rates t) by a 5-point difference at t = 0.

    Returns (omega in body axes from R^T dR/dt, omega in the fixed frame
    from dR/dt R^T)."""
    angles = np.asarray(angles, float)
    rates = np.asarray(rates, float)
    h = 1e-3 / max(1.0, float(np.max(np.abs(rates))))
    R = lambda t: Rfun(*(angles + rates * t))
    dR = (-R(2 * h) + 8 * R(h) - 8 * R(-h) + R(-2 * h)) / (12 * h)
    R0 = R(0.0)
    return vee(R0.T @ dR), vee(dR @ R0.T)


def unwrap_slope(t, ang):
    """Mean rate of an angle sampled at t (least squares on the unwrapped angle)."""
    return np.polyfit(t, np.unwrap(ang), 1)[0]


# =========================================================================
# torque_free
# =========================================================================
#
# Hand derivation.  Body axes x, y across the symmetry axis k = z, transverse
# inertia I, axial J.  Write omega = w_t e + w_z k with e across k.  Then
#     H = I w_t e + J w_z k                       (fixed in space, no moment)
#     |H| = sqrt((I w_t)^2 + (J w_z)^2)
#     theta (H to k):  tan(theta) = I w_t / (J w_z)
#     beta (omega to k): tan(beta) = w_t / w_z
# Since e, k and H are coplanar, omega = (H / I) h_hat + (1 - J/I) w_z k
# (check: along k  H cos(theta)/I + w_z - J w_z / I = w_z; across  H sin/I = w_t).
# A vector omega = a h_hat + b k turns k about h_hat at rate a:  k' = omega x k
# = a h_hat x k.  So the precession is phidot = H / I and, in the z-x-z
# angles with Z along H, omega = phidot K + psidot k gives psidot = (I - J)/I w_z.
# Everything follows from (w_z, w_t); for each pair of givens we solve for them.

TF_ANSWERS = """
  precession: rad/s
  spin: rpm
  axial_rate: rad/s
  omega: rpm
  nutation_angle: deg
  omega_angle: deg
  angular_momentum: kg*m^2/s
  precession_period: s
  body_wobble_period: min
  body_cone_angle: deg
  space_cone_angle: deg
  motion: null
"""


def tf_hand(I, J, wz, wt):
    """All answers from the body components of omega."""
    H = math.hypot(I * wt, J * wz)
    theta = math.atan2(I * wt, J * wz)
    beta = math.atan2(wt, wz)
    phidot = H / I
    psidot = (I - J) / I * wz
    return {
        "precession": phidot,
        "spin": psidot,
        "axial_rate": wz,
        "omega": math.hypot(wz, wt),
        "nutation_angle": theta,
        "omega_angle": beta,
        "angular_momentum": H,
        "precession_period": 2 * math.pi / phidot,
        "body_wobble_period": 2 * math.pi / abs(psidot),
        "body_cone_angle": beta,
        "space_cone_angle": abs(theta - beta),
        "motion": "direct" if psidot > 0 else "retrograde",
    }


def tf_pair(I, J, given):
    """(w_z, w_t) from two givens (SI), each pair worked by hand."""
    g = given
    keys = frozenset(g)
    if keys == {"omega", "omega_angle"}:
        # omega resolved along and across k
        return g["omega"] * math.cos(g["omega_angle"]), g["omega"] * math.sin(g["omega_angle"])
    if keys == {"nutation_angle", "axial_rate"}:
        # tan(theta) = I w_t / (J w_z)
        wz = g["axial_rate"]
        return wz, J * wz * math.tan(g["nutation_angle"]) / I
    if keys == {"nutation_angle", "spin"}:
        # psidot = (I - J)/I w_z
        wz = I * g["spin"] / (I - J)
        return wz, J * wz * math.tan(g["nutation_angle"]) / I
    if keys == {"nutation_angle", "precession"}:
        # H = I phidot; H along k is J w_z, across is I w_t
        H = I * g["precession"]
        th = g["nutation_angle"]
        return H * math.cos(th) / J, H * math.sin(th) / I
    if keys == {"omega_angle", "precession"}:
        # H^2 = omega^2 (J^2 cos^2 b + I^2 sin^2 b) = (I phidot)^2
        b = g["omega_angle"]
        w = I * g["precession"] / math.hypot(J * math.cos(b), I * math.sin(b))
        return w * math.cos(b), w * math.sin(b)
    if keys == {"omega_angle", "axial_rate"}:
        wz = g["axial_rate"]
        return wz, wz * math.tan(g["omega_angle"])
    if keys == {"omega_angle", "spin"}:
        wz = I * g["spin"] / (I - J)
        return wz, wz * math.tan(g["omega_angle"])
    if keys == {"omega", "axial_rate"}:
        wz = g["axial_rate"]
        return wz, math.sqrt(g["omega"] ** 2 - wz**2)
    if keys == {"omega", "spin"}:
        wz = I * g["spin"] / (I - J)
        return wz, math.sqrt(g["omega"] ** 2 - wz**2)
    if keys == {"omega", "precession"}:
        # w_z^2 + w_t^2 = w^2 and J^2 w_z^2 + I^2 w_t^2 = I^2 phidot^2:
        # subtract I^2 x the first:  (J^2 - I^2) w_z^2 = I^2 (phidot^2 - w^2)
        w, p = g["omega"], g["precession"]
        wz = math.sqrt(I**2 * (p**2 - w**2) / (J**2 - I**2))
        return wz, math.sqrt(w**2 - wz**2)
    if keys == {"precession", "axial_rate"}:
        wz = g["axial_rate"]
        return wz, math.sqrt((I * g["precession"]) ** 2 - (J * wz) ** 2) / I
    if keys == {"precession", "spin"}:
        wz = I * g["spin"] / (I - J)
        return wz, math.sqrt((I * g["precession"]) ** 2 - (J * wz) ** 2) / I
    raise AssertionError(keys)


def tf_integrate(I, J, wz, wt):
    """Euler's equations with no moment and R' = R [omega]x, from omega = (w_t, 0, w_z).

    Returns the motion measured on the integrated solution."""
    hand = tf_hand(I, J, wz, wt)
    t_end = 2.5 * max(hand["precession_period"], hand["body_wobble_period"])
    t = np.linspace(0.0, t_end, 6001)

    def f(_t, y):
        w0, w1, w2, *R = y.tolist()
        dw = [(I - J) / I * w1 * w2,          # I w_x' = (I_y - I_z) w_y w_z
              (J - I) / I * w2 * w0,          # I w_y' = (I_z - I_x) w_z w_x
              0.0]                            # J w_z' = 0
        return dw + rows_times_skew(R, [w0, w1, w2])

    y0 = np.concatenate([[wt, 0.0, wz], np.eye(3).ravel()])
    sol = solve_ivp(f, (0, t_end), y0, method="DOP853", t_eval=t, rtol=1e-12, atol=1e-13)
    assert sol.success
    w_b = sol.y[:3].T
    R = sol.y[3:].T.reshape(-1, 3, 3)
    Ib = np.array([I, I, J])
    H_s = np.einsum("nij,nj->ni", R, w_b * Ib)          # H in space
    H0 = H_s[0]
    assert np.max(np.abs(H_s - H0)) < 1e-9 * np.linalg.norm(H0)   # H is conserved
    h = H0 / np.linalg.norm(H0)
    e1 = np.cross(h, [0.0, 1.0, 0.0])
    e1 /= np.linalg.norm(e1)
    e2 = np.cross(h, e1)
    k = R[:, :, 2]
    xb = R[:, :, 0]
    w_s = np.einsum("nij,nj->ni", R, w_b)
    theta = np.arccos(np.clip(k @ h, -1, 1))
    # precession: the angle of k about H
    phidot = unwrap_slope(t, np.arctan2(k @ e2, k @ e1))
    # Euler spin psi: from the node line (H x k) to the body's x axis, about k
    node = np.cross(h, k)
    node /= np.linalg.norm(node, axis=1)[:, None]
    psi = np.arctan2(np.einsum("ni,ni->n", np.cross(node, xb), k), np.einsum("ni,ni->n", node, xb))
    psidot = unwrap_slope(t, psi)
    # omega seen from the body turns about k
    body_turn = unwrap_slope(t, np.arctan2(w_b[:, 1], w_b[:, 0]))
    beta = np.arccos(w_b[:, 2] / np.linalg.norm(w_b, axis=1))
    space_cone = np.arccos(np.clip(w_s @ h / np.linalg.norm(w_s, axis=1), -1, 1))
    return {
        "precession": phidot,
        "spin": psidot,
        "body_turn": body_turn,
        "axial_rate": float(np.mean(w_b[:, 2])),
        "omega": float(np.mean(np.linalg.norm(w_b, axis=1))),
        "nutation_angle": float(np.mean(theta)), "theta_spread": float(np.ptp(theta)),
        "omega_angle": float(np.mean(beta)), "beta_spread": float(np.ptp(beta)),
        "space_cone_angle": float(np.mean(space_cone)),
        "angular_momentum": float(np.linalg.norm(H0)),
    }


def tf_yaml(body, given_text):
    return f"""
    id: tf
    kind: torque_free
    given:
{body}
{given_text}
    find:{TF_ANSWERS.replace(chr(10) + '  ', chr(10) + '      ')}
    """


def _given_lines(pairs):
    return "\n".join(f"      {k}: {v}" for k, v in pairs)


# Prolate capsule in US units: J = 600 slug ft^2, I = 900 slug ft^2 (I > J)
PROLATE = ("      J: 600 slug*ft^2\n      I_cg: 900 slug*ft^2", 900 * SLUG_FT2, 600 * SLUG_FT2)
# Oblate satellite from its mass and radii of gyration: 1200 kg, k_axial 0.9 m,
# k_cg 0.7 m: J = 972, I = 588 kg m^2 (J > I)
OBLATE = ("      mass: 1200 kg\n      k_axial: 900 mm\n      k_cg: 0.7 m", 1200 * 0.7**2, 1200 * 0.9**2)

# (given as text, given in SI)
PROLATE_PAIRS = [
    ([("omega", "30 rpm"), ("omega_angle", "25 deg")], {"omega": 30 * RPM, "omega_angle": 25 * DEG}),
    ([("nutation_angle", "15 deg"), ("axial_rate", "2 rad/s")], {"nutation_angle": 15 * DEG, "axial_rate": 2.0}),
    ([("nutation_angle", "40 deg"), ("spin", "0.5 rad/s")], {"nutation_angle": 40 * DEG, "spin": 0.5}),
    ([("nutation_angle", "60 deg"), ("precession", "12 rpm")], {"nutation_angle": 60 * DEG, "precession": 12 * RPM}),
    ([("omega", "3 rad/s"), ("axial_rate", "2.5 rad/s")], {"omega": 3.0, "axial_rate": 2.5}),
    ([("omega", "3 rad/s"), ("spin", "0.8 rad/s")], {"omega": 3.0, "spin": 0.8}),
    # phidot must lie between J w / I = 2 and w = 3 rad/s for this prolate body
    ([("omega", "3 rad/s"), ("precession", "2.6 rad/s")], {"omega": 3.0, "precession": 2.6}),
    ([("precession", "2 rad/s"), ("axial_rate", "1 rad/s")], {"precession": 2.0, "axial_rate": 1.0}),
    ([("precession", "0.3 revolution/s"), ("spin", "0.4 rad/s")], {"precession": 0.3 * 2 * math.pi, "spin": 0.4}),
    ([("omega_angle", "35 deg"), ("precession", "1.5 rad/s")], {"omega_angle": 35 * DEG, "precession": 1.5}),
    ([("omega_angle", "20 deg"), ("spin", "60 deg/s")], {"omega_angle": 20 * DEG, "spin": 60 * DEG}),
]
OBLATE_PAIRS = [
    ([("omega", "45 rpm"), ("omega_angle", "10 deg")], {"omega": 45 * RPM, "omega_angle": 10 * DEG}),
    ([("nutation_angle", "5 deg"), ("axial_rate", "0.2 revolution/s")], {"nutation_angle": 5 * DEG, "axial_rate": 0.2 * 2 * math.pi}),
    ([("nutation_angle", "70 deg"), ("spin", "-0.3 rad/s")], {"nutation_angle": 70 * DEG, "spin": -0.3}),
    ([("nutation_angle", "30 deg"), ("precession", "8 rpm")], {"nutation_angle": 30 * DEG, "precession": 8 * RPM}),
    ([("omega", "2 rad/s"), ("axial_rate", "1.2 rad/s")], {"omega": 2.0, "axial_rate": 1.2}),
    ([("omega", "2 rad/s"), ("spin", "-0.5 rad/s")], {"omega": 2.0, "spin": -0.5}),
    # oblate: phidot between w = 2 and J w / I = 3.306 rad/s
    ([("omega", "2 rad/s"), ("precession", "2.8 rad/s")], {"omega": 2.0, "precession": 2.8}),
    ([("precession", "3 rad/s"), ("axial_rate", "1 rad/s")], {"precession": 3.0, "axial_rate": 1.0}),
    ([("omega_angle", "50 deg"), ("precession", "1 rad/s")], {"omega_angle": 50 * DEG, "precession": 1.0}),
    ([("omega_angle", "60 deg"), ("axial_rate", "0.5 rad/s")], {"omega_angle": 60 * DEG, "axial_rate": 0.5}),
    ([("precession", "20 rpm"), ("spin", "-0.4 rad/s")], {"precession": 20 * RPM, "spin": -0.4}),
]

CASES = [(PROLATE, p) for p in PROLATE_PAIRS] + [(OBLATE, p) for p in OBLATE_PAIRS]


@pytest.mark.parametrize("body,pair", CASES, ids=[
    ("prolate-" if b is PROLATE else "oblate-") + "+".join(k for k, _ in p[0]) for b, p in CASES])
def test_torque_free_pairs_against_hand_and_integration(run, write, body, pair):
    body_text, I, J = body
    text_pairs, si_pairs = pair
    got = solve(run, write, tf_yaml(body_text, _given_lines(text_pairs)))
    wz, wt = tf_pair(I, J, si_pairs)
    hand = tf_hand(I, J, wz, wt)
    # my own solution reproduces the two givens
    for k, v in si_pairs.items():
        assert close(hand[k], v, 1e-12), k
    # gyro against the hand solution
    for k, v in hand.items():
        if k == "motion":
            assert got[k] == v
        else:
            assert close(got[k], v), (k, got[k], v)
    # the integrated motion from my (w_z, w_t)
    sim = tf_integrate(I, J, wz, wt)
    assert sim["theta_spread"] < 1e-8 and sim["beta_spread"] < 1e-8      # cones are cones
    for k in ("precession", "spin", "axial_rate", "omega", "nutation_angle",
              "omega_angle", "space_cone_angle", "angular_momentum"):
        assert close(got[k], sim[k], RTOL_INT), (k, got[k], sim[k])
    # omega turns about k in the body at -psidot: one turn per body_wobble_period
    assert close(sim["body_turn"], -got["spin"], RTOL_INT)
    assert close(2 * math.pi / abs(sim["body_turn"]), got["body_wobble_period"], RTOL_INT)
    assert close(got["body_cone_angle"], sim["omega_angle"], RTOL_INT)
    # direct: spin with the precession; retrograde: against it
    assert got["motion"] == ("direct" if sim["spin"] * sim["precession"] > 0 else "retrograde")
    # prolate: theta > beta; oblate: beta > theta
    if I > J:
        assert got["nutation_angle"] > got["omega_angle"] and got["motion"] == "direct"
    else:
        assert got["omega_angle"] > got["nutation_angle"] and got["motion"] == "retrograde"


def test_torque_free_football_from_mass_and_radii(run, write):
    """A football, 0.41 kg, k_axial 30 mm, k_cg 45 mm, thrown spinning so that
    omega = 300 rpm at 25 deg from its axis (prolate: direct).

    Hand: I = 0.41 (0.045)^2 = 8.3025e-4, J = 0.41 (0.03)^2 = 3.69e-4 kg m^2;
    w = 31.416 rad/s, w_z = w cos 25 = 28.472, w_t = w sin 25 = 13.277;
    H = sqrt((I w_t)^2 + (J w_z)^2) = sqrt(0.011023^2 + 0.010506^2) = 0.015228;
    phidot = H / I = 18.342 rad/s; psidot = (I - J)/I w_z = 15.818 rad/s;
    tan(theta) = I w_t / (J w_z) = 1.0492, theta = 46.37 deg."""
    I, J = 0.41 * 0.045**2, 0.41 * 0.03**2
    got = solve(run, write, tf_yaml("      mass: 410 g\n      k_axial: 30 mm\n      k_cg: 45 mm",
                                    "      omega: 300 rpm\n      omega_angle: 25 deg"))
    w = 300 * RPM
    wz, wt = w * math.cos(25 * DEG), w * math.sin(25 * DEG)
    H = math.sqrt((I * wt) ** 2 + (J * wz) ** 2)
    assert close(got["angular_momentum"], H)
    assert close(got["precession"], H / I)
    assert close(got["spin"], (I - J) / I * wz)
    assert close(got["nutation_angle"], math.atan(I * wt / (J * wz)))
    assert close(got["space_cone_angle"], math.atan(I * wt / (J * wz)) - 25 * DEG)
    assert abs(got["precession"] - 18.342) < 1e-3 and abs(got["spin"] - 15.818) < 1e-3
    assert got["motion"] == "direct"


def test_torque_free_thin_disk_limit_wobbles_twice_as_fast(run, write):
    """Feynman's plate: a thin disk (J = 2 I, the accepted limit) thrown with a
    small wobble.  psidot = (I - J)/I w_z = -w_z; phidot = H/I -> 2 w_z as the
    wobble vanishes: the wobble is twice the spin (retrograde)."""
    got = solve(run, write, tf_yaml("      shape: disk\n      mass: 0.2 kg\n      radius: 110 mm",
                                    "      axial_rate: 5 revolution/s\n      nutation_angle: 0.5 deg"))
    m, r = 0.2, 0.11
    J, I = m * r**2 / 2, m * r**2 / 4       # thin disk: J = m r^2/2, I = m r^2/4 (perp. axes)
    wz = 5 * 2 * math.pi
    wt = J * wz * math.tan(0.5 * DEG) / I
    hand = tf_hand(I, J, wz, wt)
    for k in ("precession", "spin", "omega", "omega_angle", "angular_momentum", "space_cone_angle"):
        assert close(got[k], hand[k]), k
    assert close(got["spin"], -wz)
    assert abs(got["precession"] / wz - 2) < 1e-4           # 2 w_z / cos(theta)
    assert got["motion"] == "retrograde"
    sim = tf_integrate(I, J, wz, wt)
    assert close(sim["precession"], got["precession"], RTOL_INT)
    assert close(sim["spin"], got["spin"], RTOL_INT)


def test_torque_free_earth_euler_period(run, write):
    """The rigid Earth: (C - A)/A = 0.00327 (the dynamical ellipticity), one
    turn a sidereal day, a free wobble of 0.2 arcsec.  psidot = (A - C)/A w_z,
    so the body wobble period is A/(C - A) sidereal days = 305.8 days."""
    A = 8.0e37
    C = A * 1.00327
    got = solve(run, write, tf_yaml(f"      J: {C!r} kg*m^2\n      I_cg: {A!r} kg*m^2",
                                    "      axial_rate: 7.292115e-5 rad/s\n      nutation_angle: 0.2 arcsec"))
    wz = 7.292115e-5                     # 2 pi / 86164.1 s
    hand = tf_hand(A, C, wz, C * wz * math.tan(0.2 / 3600 * DEG) / A)
    assert close(got["body_wobble_period"], 2 * math.pi / 7.292115e-5 / 0.00327)
    assert abs(got["body_wobble_period"] / 86400 - 304.975) < 0.001
    for k in ("precession", "spin", "omega", "omega_angle", "angular_momentum", "precession_period"):
        assert close(got[k], hand[k]), k
    assert got["motion"] == "retrograde"


def test_torque_free_nearly_spherical_body(run, write):
    """J -> I: omega stays (almost) along H, precession -> omega, no space cone,
    and the body wobble becomes infinitely slow."""
    I, J = 10.0, 10.0 * (1 - 1e-6)
    got = solve(run, write, tf_yaml("      J: 9.99999 kg*m^2\n      I_cg: 10 kg*m^2",
                                    "      omega: 2 rad/s\n      omega_angle: 40 deg"))
    hand = tf_hand(I, J, 2 * math.cos(40 * DEG), 2 * math.sin(40 * DEG))
    for k in ("precession", "spin", "nutation_angle", "space_cone_angle", "body_wobble_period"):
        assert close(got[k], hand[k], 1e-5), (k, got[k], hand[k])
    assert close(got["precession"], 2.0, 1e-5)
    assert got["space_cone_angle"] < 1e-5
    assert got["body_wobble_period"] > 1e6


@pytest.mark.parametrize("given,key", [
    ("      omega_angle: 20 deg\n      nutation_angle: 30 deg", "nutation_angle"),  # tied by the inertias
    ("      axial_rate: 2 rad/s\n      spin: 0.5 rad/s", "spin"),  # tied, no angle
    ("      nutation_angle: 30 deg\n      spin: -0.5 rad/s", "spin"),  # wrong sign for prolate
    ("      nutation_angle: 90 deg\n      axial_rate: 1 rad/s", "nutation_angle"),  # no wobble at 90 deg
    ("      nutation_angle: 0 deg\n      axial_rate: 1 rad/s", "nutation_angle"),  # nor at 0
    ("      nutation_angle: 120 deg\n      axial_rate: 1 rad/s", "nutation_angle"),  # k must be on the side of H
    ("      omega: 3 rad/s\n      precession: 3.5 rad/s", "precession"),  # phidot outside (2, 3)
    ("      omega: 3 rad/s\n      precession: 1.9 rad/s", "precession"),
    ("      omega: 3 rad/s\n      axial_rate: 3.5 rad/s", "omega"),  # w_z > w
])
def test_torque_free_refusals_prolate(run, write, given, key):
    assert refused(run, write, tf_yaml(PROLATE[0], given), key)


@pytest.mark.parametrize("body", [
    "      J: 5 kg*m^2\n      I_cg: 5 kg*m^2",        # sphere: nothing wobbles
])
def test_torque_free_refused_bodies(run, write, body):
    assert refused(run, write, tf_yaml(body, "      omega: 3 rad/s\n      omega_angle: 20 deg"), "J")


def test_torque_free_body_no_rigid_body_could_have_is_solved_with_a_warning(run, write):
    # J > 2 I: textbook data no rigid body could have; Euler's equations do not care,
    # so the answer is worked as given (H = sqrt((J w cos b)^2 + (I w sin b)^2), phidot = H / I)
    text = tf_yaml("      J: 11 kg*m^2\n      I_cg: 5 kg*m^2",
                   "      omega: 3 rad/s\n      omega_angle: 20 deg")
    result = run("solve", "--format", "json", write(text))
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert any("no rigid body" in w for w in data["warnings"])
    b = math.radians(20)
    H = math.hypot(11 * 3 * math.cos(b), 5 * 3 * math.sin(b))
    assert data["answers"]["precession"]["si_values"][0] == pytest.approx(H / 5, rel=1e-9)


def test_torque_free_oblate_positive_spin_refused(run, write):
    assert refused(run, write, tf_yaml(OBLATE[0], "      nutation_angle: 30 deg\n      spin: 0.3 rad/s"), "spin")


# =========================================================================
# euler_angles
# =========================================================================
#
# Derivation: the body's axes in the fixed frame are the columns of
# R(t) = Rz(phi) Rx(theta) Rz(psi).  For any rotation R(t), R^T R = 1 gives
# R^T dR/dt skew; its axial vector is omega in body axes, and that of
# dR/dt R^T is omega in the fixed frame.  Both are taken here by finite
# differences along R(t) = R(angles + rates t), so Eq. 11.8 itself is never
# used.  For a rigid body of particles at body positions r_i (from the fixed
# point), v_i = omega x r_i, so T = 1/2 sum m |omega x r|^2 and
# H = sum m r x (omega x r), computed directly; the inertia matrix is the
# linear map omega -> H, read off column by column.

EA_FIND_ALL = """
      omega_x: rad/s
      omega_y: rad/s
      omega_z: rad/s
      omega: rad/s
      kinetic_energy: J
      H_x: kg*m^2/s
      H_y: kg*m^2/s
      H_z: kg*m^2/s
      angular_momentum: kg*m^2/s
      omega_H_angle: deg"""
EA_FIND_FIXED = """
      omega_X: rad/s
      omega_Y: rad/s
      omega_Z: rad/s
      H_X: kg*m^2/s
      H_Y: kg*m^2/s
      H_Z: kg*m^2/s"""


def ea_yaml(given, find):
    return f"""
    id: ea
    kind: euler_angles
    given:
{given}
    find:{find}
    """


def particles_T_H(masses, positions, w):
    """T and H by direct sums over the particles (v = omega x r)."""
    T = 0.0
    H = np.zeros(3)
    for m, r in zip(masses, positions):
        v = np.cross(w, r)
        T += 0.5 * m * v @ v
        H += m * np.cross(r, v)
    return T, H


def inertia_from_H(masses, positions):
    """Inertia matrix as the map omega -> H, one column per unit omega."""
    return np.column_stack([particles_T_H(masses, positions, e)[1] for e in np.eye(3)])


def check_T_H(got, w_b, Imat, R=None):
    H = Imat @ w_b
    T = 0.5 * w_b @ H
    assert close(got["kinetic_energy"], T)
    for i, c in enumerate("xyz"):
        assert close(got["omega_" + c], w_b[i], atol=1e-12 * np.linalg.norm(w_b)), c
        assert close(got["H_" + c], H[i], atol=1e-9 * np.linalg.norm(H)), c
    assert close(got["omega"], np.linalg.norm(w_b))
    assert close(got["angular_momentum"], np.linalg.norm(H))
    ang = math.acos(np.clip(w_b @ H / np.linalg.norm(w_b) / np.linalg.norm(H), -1, 1))
    assert close(got["omega_H_angle"], ang, atol=1e-7)
    if R is not None:
        w_s, H_s = R @ w_b, R @ H
        for i, c in enumerate("XYZ"):
            assert close(got["omega_" + c], w_s[i], atol=1e-9 * np.linalg.norm(w_b)), c
            assert close(got["H_" + c], H_s[i], atol=1e-9 * np.linalg.norm(H)), c


@pytest.mark.parametrize("angles,rates", [
    # (phi, theta, psi) in deg, (phidot, thetadot, psidot) as text and in rad/s
    ((30, 60, 45), (("2 rad/s", 2.0), ("1 rad/s", 1.0), ("10 rad/s", 10.0))),
    ((-110, 135, 200), (("-30 rpm", -30 * RPM), ("45 deg/s", 45 * DEG), ("600 rpm", 600 * RPM))),
    ((0, 90, 0), (("0 rad/s", 0.0), ("0 rad/s", 0.0), ("-5 revolution/s", -10 * math.pi))),
    ((75, 12, -40), (("1.5 revolution/s", 3 * math.pi), ("-0.2 rad/s", -0.2), ("0 rad/s", 0.0))),
])
def test_euler_zxz_symmetric_top(run, write, angles, rates):
    """A symmetric top: I = 0.02, J = 0.03 kg m^2 about the fixed point.
    omega from R^T dR/dt, T = 1/2 omega . I omega, H in both frames."""
    phi, theta, psi = (a * DEG for a in angles)
    given = (f"      phi: {angles[0]} deg\n      theta: {angles[1]} deg\n      psi: {angles[2]} deg\n"
             f"      phi_rate: {rates[0][0]}\n      theta_rate: {rates[1][0]}\n      psi_rate: {rates[2][0]}\n"
             "      I: 2e5 g*cm^2\n      J: 0.03 kg*m^2")
    got = solve(run, write, ea_yaml(given, EA_FIND_ALL + EA_FIND_FIXED))
    rate_si = [r[1] for r in rates]
    w_b, w_s = omega_fd(R_zxz, (phi, theta, psi), rate_si)
    R = R_zxz(phi, theta, psi)
    assert np.allclose(R @ w_b, w_s, atol=1e-9 * (1 + np.linalg.norm(w_s)))
    Imat = np.diag([0.02, 0.02, 0.03])
    check_T_H(got, w_b, Imat, R)
    # Eq. 11.10 for the symmetric top, as a second hand check:
    # T = 1/2 I (phidot^2 sin^2 theta + thetadot^2) + 1/2 J (phidot cos theta + psidot)^2
    pd, td, sd = rate_si
    T10 = 0.5 * 0.02 * (pd**2 * math.sin(theta) ** 2 + td**2) + 0.5 * 0.03 * (pd * math.cos(theta) + sd) ** 2
    assert close(got["kinetic_energy"], T10)


def test_euler_particles_with_products(run, write):
    """Five small masses (grams, positions in mm) fixed to a light frame that
    turns about the origin: no symmetry, all three products non-zero."""
    masses = [0.120, 0.250, 0.080, 0.300, 0.150]          # kg
    pos = np.array([[60, -20, 35], [-45, 70, 10], [15, 25, -90], [0, -55, -30], [80, 40, 50]]) / 1000.0
    lines = "\n".join(f"        - {{mass: {m * 1000:g} g, x: {p[0] * 1000:g} mm, y: {p[1] * 1000:g} mm, z: {p[2] * 1000:g} mm}}"
                      for m, p in zip(masses, pos))
    given = ("      phi: 20 deg\n      theta: 50 deg\n      psi: -35 deg\n"
             "      phi_rate: 120 rpm\n      theta_rate: -3 rad/s\n      psi_rate: 15 rad/s\n"
             "      particles:\n" + lines)
    find = EA_FIND_ALL + EA_FIND_FIXED + """
      I_x: kg*m^2
      I_y: kg*m^2
      I_z: kg*m^2
      I_xy: kg*m^2
      I_yz: kg*m^2
      I_zx: kg*m^2
      principal_moments: kg*m^2"""
    got = solve(run, write, ea_yaml(given, find))
    m = np.array(masses)
    x, y, z = pos.T
    # Eq. 11.3 by direct sums; products as the chapter writes them (no minus sign)
    assert close(got["I_x"], float(np.sum(m * (y**2 + z**2))))
    assert close(got["I_y"], float(np.sum(m * (z**2 + x**2))))
    assert close(got["I_z"], float(np.sum(m * (x**2 + y**2))))
    assert close(got["I_xy"], float(np.sum(m * x * y)))
    assert close(got["I_yz"], float(np.sum(m * y * z)))
    assert close(got["I_zx"], float(np.sum(m * z * x)))
    Imat = inertia_from_H(masses, pos)                      # omega -> H from the particles
    # the off-diagonal entries of that map are minus the chapter's products
    assert close(Imat[0, 1], -got["I_xy"]) and close(Imat[1, 2], -got["I_yz"]) and close(Imat[2, 0], -got["I_zx"])
    assert np.allclose(sorted(got["principal_moments"]), np.linalg.eigvalsh(Imat), rtol=1e-6)
    ang = (20 * DEG, 50 * DEG, -35 * DEG)
    w_b, _ = omega_fd(R_zxz, ang, (120 * RPM, -3.0, 15.0))
    T, H = particles_T_H(masses, pos, w_b)
    assert close(got["kinetic_energy"], T)
    for i, c in enumerate("xyz"):
        assert close(got["H_" + c], H[i])
    check_T_H(got, w_b, Imat, R_zxz(*ang))
    assert got["omega_H_angle"] > 1 * DEG            # axes not principal: H leaves omega


def test_euler_cube_corner_about_edge(run, write):
    """Eight equal masses at a cube's corners, fixed point at one corner,
    turning about an edge (z): H is not along omega.  By hand with m = 1 lb
    (pound-mass) and a = 6 in: I_z = 8 m a^2 (four masses at a^2, two at
    2 a^2), I_xy = ... = 2 m a^2 (two corners with x = y = a); the matrix
    m a^2 [[8,-2,-2],[-2,8,-2],[-2,-2,8]] has 8 - 2*2 = 4 along the diagonal
    (1,1,1) and 8 + 2 = 10 across it; H = omega (-2, -2, 8) m a^2, at
    atan(sqrt 8 / 8) = 19.47 deg from omega."""
    a = 6 * 0.0254
    mlb = 0.45359237
    corners = [(i, j, k) for i in (0, 1) for j in (0, 1) for k in (0, 1)]
    lines = "\n".join(f"        - {{mass: 1 lb, x: {6 * i} in, y: {6 * j} in, z: {6 * k} in}}" for i, j, k in corners)
    given = "      theta: 90 deg\n      psi: 0 deg\n      psi_rate: 100 rpm\n      particles:\n" + lines
    got = solve(run, write, ea_yaml(given, EA_FIND_ALL + "\n      I_z: kg*m^2\n      I_xy: kg*m^2\n      principal_moments: kg*m^2"))
    w = 100 * RPM
    ma2 = mlb * a**2
    assert close(got["I_z"], 8 * ma2) and close(got["I_xy"], 2 * ma2)
    assert np.allclose(sorted(got["principal_moments"]), [4 * ma2, 10 * ma2, 10 * ma2], rtol=1e-6)
    assert close(got["H_x"], -2 * ma2 * w) and close(got["H_z"], 8 * ma2 * w)
    assert close(got["omega_H_angle"], math.atan(math.sqrt(8) / 8))
    assert close(got["kinetic_energy"], 0.5 * 8 * ma2 * w**2)
    pos = np.array(corners, float) * a
    check_T_H(got, np.array([0, 0, w]), inertia_from_H([mlb] * 8, pos))


def test_euler_body_keys_parallel_axes(run, write):
    """A body given by mass and radii of gyration about its centre of mass,
    held at a point 80 mm down its axis: I about the fixed point = m (k_cg^2 + l^2)."""
    m, kc, ka, l = 1.5, 0.05, 0.04, 0.08
    given = ("      theta: 30 deg\n      psi: 10 deg\n      phi_rate: 3 rad/s\n      psi_rate: 200 rad/s\n"
             "      mass: 1.5 kg\n      k_cg: 50 mm\n      k_axial: 40 mm\n      cg_distance: 80 mm")
    got = solve(run, write, ea_yaml(given, EA_FIND_ALL + "\n      I_x: kg*m^2\n      I_z: kg*m^2"))
    I, J = m * (kc**2 + l**2), m * ka**2
    assert close(got["I_x"], I) and close(got["I_z"], J)
    w_b, _ = omega_fd(R_zxz, (0.0, 30 * DEG, 10 * DEG), (3.0, 0.0, 200.0))
    check_T_H(got, w_b, np.diag([I, I, J]))


@pytest.mark.parametrize("theta,psi,w", [
    (60, 45, (1.932, 0.5176, 11.0)),
    (120, -70, (-4.0, 2.5, -30.0)),
    (0.8, 200, (0.3, -0.1, 50.0)),          # within 1 deg of theta = 0: a warning only
])
def test_euler_zxz_inverse(run, write, theta, psi, w):
    """Given body omega and theta, psi: the rates.  omega is linear in the
    rates; its matrix is built column by column from finite differences of R,
    and solved.  The rates gyro returns are put back through R(t)."""
    given = (f"      theta: {theta} deg\n      psi: {psi} deg\n"
             f"      omega_x: {w[0]} rad/s\n      omega_y: {w[1]} rad/s\n      omega_z: {w[2]} rad/s\n"
             "      I: 0.02 kg*m^2\n      J: 0.03 kg*m^2")
    got = solve(run, write, ea_yaml(given, "\n      phi_rate: rad/s\n      theta_rate: rad/s\n      psi_rate: rad/s"))
    ang = (0.0, theta * DEG, psi * DEG)
    A = np.column_stack([omega_fd(R_zxz, ang, e)[0] for e in np.eye(3)])
    rates = np.linalg.solve(A, np.array(w))
    for name, r in zip(("phi_rate", "theta_rate", "psi_rate"), rates):
        assert close(got[name], r, atol=1e-9 * np.linalg.norm(w)), (name, got[name], r)
    back, _ = omega_fd(R_zxz, ang, (got["phi_rate"], got["theta_rate"], got["psi_rate"]))
    assert np.allclose(back, w, rtol=1e-8, atol=1e-8)
    if theta < 1:
        assert got["_warnings"]


@pytest.mark.parametrize("angles,rates", [
    ((40, 15, -25), ((10, "10 deg/s"), (-5, "-5 deg/s"), (60, "60 deg/s"))),
    ((-150, -70, 170), ((0.5 / DEG, "0.5 rad/s"), (0.2 / DEG, "0.2 rad/s"), (-3 / DEG, "-3 rad/s"))),
    ((0, 0, 0), ((30 * 6, "30 rpm"), (0, "0 rpm"), (0, "0 rpm"))),      # pure yaw: r = yawdot
])
def test_euler_zyx_aircraft(run, write, angles, rates):
    """An aircraft in yaw, pitch, roll: I_x = 1.8e4, I_y = 2.6e4, I_z = 4.2e4
    slug ft^2 (roughly), I_zx = 1.2e3 slug ft^2.  p, q, r from R^T dR/dt with
    R = Rz(yaw) Ry(pitch) Rx(roll)."""
    yaw, pitch, roll = (a * DEG for a in angles)
    given = (f"      sequence: zyx\n      yaw: {angles[0]} deg\n      pitch: {angles[1]} deg\n      roll: {angles[2]} deg\n"
             f"      yaw_rate: {rates[0][1]}\n      pitch_rate: {rates[1][1]}\n      roll_rate: {rates[2][1]}\n"
             "      I_x: 1.8e4 slug*ft^2\n      I_y: 2.6e4 slug*ft^2\n      I_z: 4.2e4 slug*ft^2\n"
             "      I_zx: 1.2e3 slug*ft^2")
    got = solve(run, write, ea_yaml(given, EA_FIND_ALL + EA_FIND_FIXED))
    rate_si = [r[0] * DEG for r in rates]
    w_b, w_s = omega_fd(R_zyx, (yaw, pitch, roll), rate_si)
    S = SLUG_FT2
    Imat = np.array([[1.8e4 * S, 0, -1.2e3 * S], [0, 2.6e4 * S, 0], [-1.2e3 * S, 0, 4.2e4 * S]])
    # that matrix is the omega -> H map of any mass distribution with sum m z x = I_zx:
    # check the sign on two particles in the x-z plane
    pts = np.array([[1.0, 0, 1.0], [-1.0, 0, -1.0]])
    Ip = inertia_from_H([1.0, 1.0], pts)
    assert close(Ip[0, 2], -float(np.sum(pts[:, 2] * pts[:, 0])))
    check_T_H(got, w_b, Imat, R_zyx(yaw, pitch, roll))


@pytest.mark.parametrize("pitch,roll,pqr", [
    (20, 35, (0.3, -0.2, 0.1)),
    (-60, -120, (-1.0, 0.5, 2.0)),
])
def test_euler_zyx_inverse(run, write, pitch, roll, pqr):
    given = (f"      sequence: zyx\n      pitch: {pitch} deg\n      roll: {roll} deg\n"
             f"      omega_x: {pqr[0]} rad/s\n      omega_y: {pqr[1]} rad/s\n      omega_z: {pqr[2]} rad/s\n"
             "      I_x: 1 kg*m^2\n      I_y: 2 kg*m^2\n      I_z: 2.5 kg*m^2")
    got = solve(run, write, ea_yaml(given, "\n      yaw_rate: rad/s\n      pitch_rate: rad/s\n      roll_rate: rad/s"))
    ang = (0.0, pitch * DEG, roll * DEG)
    A = np.column_stack([omega_fd(R_zyx, ang, e)[0] for e in np.eye(3)])
    rates = np.linalg.solve(A, np.array(pqr))
    for name, r in zip(("yaw_rate", "pitch_rate", "roll_rate"), rates):
        assert close(got[name], r, atol=1e-9), (name, got[name], r)


def test_euler_inverse_singular_refused(run, write):
    zxz = ("      theta: 0 deg\n      psi: 10 deg\n      omega_x: 1 rad/s\n      omega_y: 0 rad/s\n"
           "      omega_z: 2 rad/s\n      I: 1 kg*m^2\n      J: 1.5 kg*m^2")
    zyx = ("      sequence: zyx\n      pitch: 90 deg\n      roll: 10 deg\n      omega_x: 1 rad/s\n"
           "      omega_y: 0 rad/s\n      omega_z: 2 rad/s\n      I_x: 1 kg*m^2\n      I_y: 1 kg*m^2\n      I_z: 1.5 kg*m^2")
    assert refused(run, write, ea_yaml(zxz, "\n      phi_rate: rad/s"), "theta")
    assert refused(run, write, ea_yaml(zyx, "\n      yaw_rate: rad/s"), "pitch")


@pytest.mark.parametrize("given,key", [
    # z-x-z keys with the z-y-x sequence
    ("      sequence: zyx\n      theta: 30 deg\n      psi: 0 deg\n      psi_rate: 1 rad/s\n      I: 1 kg*m^2\n      J: 1 kg*m^2", "theta"),
    # an inertia no rigid body has: I_z > I_x + I_y
    ("      theta: 30 deg\n      psi: 0 deg\n      psi_rate: 1 rad/s\n      I_x: 1 kg*m^2\n      I_y: 1 kg*m^2\n      I_z: 2.5 kg*m^2", "I_z"),
    # not positive definite
    ("      theta: 30 deg\n      psi: 0 deg\n      psi_rate: 1 rad/s\n      I_x: 1 kg*m^2\n      I_y: 1 kg*m^2\n      I_z: 1 kg*m^2\n      I_xy: 1.2 kg*m^2", "I_xy"),
])
def test_euler_refusals(run, write, given, key):
    assert refused(run, write, ea_yaml(given, "\n      kinetic_energy: J"), key)


# =========================================================================
# gyro_drift
# =========================================================================
#
# Derivation (Lagrange).  Outer gimbal turns by a about the fixed X (its
# inertia A about X); the inner gimbal by b about the outer gimbal's y; the
# rotor (spin J, transverse I_r, inner gimbal lumped in) spins by s about the
# inner gimbal's z.  The frame of the inner gimbal is Rx(a) Ry(b); its angular
# velocity in its own axes is (a' cos b, b', a' sin b), so
#     T = 1/2 A a'^2 + 1/2 I_r (a'^2 cos^2 b + b'^2) + 1/2 J (a' sin b + s')^2.
# s is cyclic: H = J (a' sin b + s') stays constant.  With a moment M about X:
#     d/dt[(A + I_r cos^2 b) a' + H sin b] = M
#     I_r b'' + I_r a'^2 sin b cos b - H a' cos b = 0
# Linearised (I_x = A + I_r, I_y = I_r):  I_x a'' + H b' = M,  I_y b'' - H a' = 0.
# From rest, b' = M/H on average (the drift, about y), and the nutation has
# w_n^2 = H^2 / (I_x I_y).  Both the linear and the nonlinear equations are
# integrated below and measured; a free rotor (no gimbals) under a moment
# fixed in space is integrated too, with full Euler equations and attitude.

GD_FIND = """
      angular_momentum: kg*m^2/s
      drift_rate: deg/h
      drift_angle: deg
      moment: N*m
      nutation_frequency: rad/s
      nutation_period: s
      nutation_amplitude: rad
      nutation_amplitude_drift: rad
      max_deflection: rad"""


def gd_yaml(given, find=GD_FIND):
    return f"""
    id: gd
    kind: gyro_drift
    given:
{given}
    find:{find}
    """


def measure_nutation(t, a, b):
    """Drift rate, nutation frequency and amplitudes measured on a(t), b(t)."""
    from scipy.signal import find_peaks  # here: scipy.signal costs every test process a second

    sign = 1.0 if abs(np.max(a)) >= abs(np.min(a)) else -1.0
    peaks, _ = find_peaks(sign * a)
    tp = []
    for p in peaks[1:-1] if len(peaks) > 2 else peaks:      # refine each peak by a parabola
        y0, y1, y2 = sign * a[p - 1], sign * a[p], sign * a[p + 1]
        dt = t[p + 1] - t[p]
        tp.append(t[p] + 0.5 * dt * (y0 - y2) / (y0 - 2 * y1 + y2))
    tp = np.array(tp)
    period = (tp[-1] - tp[0]) / (len(tp) - 1)
    # a from rest is at its trough at t = 0 and at every whole period: the mean
    # drift is measured between whole cycles
    n = int(t[-1] / period)
    T_whole = n * period
    b_end = np.interp(T_whole, t, b)
    drift = (b_end - b[0]) / T_whole
    amp_x = (np.max(a) - np.min(a)) / 2
    ripple = b - drift * t
    amp_y = (np.max(ripple) - np.min(ripple)) / 2
    return {"drift": drift, "w_n": 2 * math.pi / period, "amp_x": amp_x,
            "mean_x": (np.max(a) + np.min(a)) / 2, "amp_y": amp_y,
            "max_x": float(np.max(np.abs(a)))}


def linear_gimbals(H, M, Ix, Iy, cycles=12, per=400):
    w_n = H / math.sqrt(Ix * Iy)
    t = np.linspace(0, cycles * 2 * math.pi / w_n, cycles * per + 1)
    # scale: time by 1/w_n, angles by M Iy / H^2 (the equations are linear)
    sa = M * Iy / H**2

    def f(_t, y):
        a, ad, b, bd = y
        return [ad, (M - H * bd) / Ix, bd, H * ad / Iy]

    y0 = [0.0, 0.0, 0.0, 0.0]
    sol = solve_ivp(f, (0, t[-1]), y0, method="DOP853", t_eval=t, rtol=1e-12,
                    atol=1e-12 * abs(sa) * np.array([1, w_n, 1, w_n]))
    assert sol.success
    return t, sol.y[0], sol.y[2]


def nonlinear_gimbals(H, M, Ix, Iy, cycles=12, per=400):
    A, Ir = Ix - Iy, Iy
    w_n = H / math.sqrt(Ix * Iy)
    t = np.linspace(0, cycles * 2 * math.pi / w_n, cycles * per + 1)

    def f(_t, y):
        a, ad, b, bd = y
        cb, sb = math.cos(b), math.sin(b)
        # d/dt[(A + Ir cb^2) a' + H sb] = M
        add = (M + 2 * Ir * cb * sb * bd * ad - H * cb * bd) / (A + Ir * cb**2)
        bdd = (H * ad * cb - Ir * ad**2 * sb * cb) / Ir
        return [ad, add, bd, bdd]

    sa = abs(M) * Iy / H**2
    sol = solve_ivp(f, (0, t[-1]), [0.0, 0.0, 0.0, 0.0], method="DOP853", t_eval=t,
                    rtol=1e-12, atol=1e-13 * sa * np.array([1, w_n, 1, w_n]))
    assert sol.success
    return t, sol.y[0], sol.y[2]


def free_rotor(J, I, spin, M, cycles=12, per=400):
    """A free symmetric rotor (no gimbals), spin axis along Z, at rest but for
    its spin when a constant moment M about the fixed X is switched on.
    Euler's equations in body axes with the moment R^T (M X), and R' = R [w]x.
    a: rotation of the axis about X, b: about Y (k ~ Z + b X - a Y)."""
    H = J * spin
    w_n = H / I
    t = np.linspace(0, cycles * 2 * math.pi / w_n, cycles * per + 1)

    def f(_t, y):
        w0, w1, w2, *R = y.tolist()
        m0, m1, m2 = M * R[0], M * R[1], M * R[2]     # R^T (M, 0, 0): M times R's first row
        dw = [((I - J) * w1 * w2 + m0) / I,
              ((J - I) * w2 * w0 + m1) / I,
              m2 / J]
        return dw + rows_times_skew(R, [w0, w1, w2])

    y0 = np.concatenate([[0.0, 0.0, spin], np.eye(3).ravel()])
    sol = solve_ivp(f, (0, t[-1]), y0, method="DOP853", t_eval=t, rtol=1e-13, atol=1e-14)
    assert sol.success
    R = sol.y[3:].T.reshape(-1, 3, 3)
    k = R[:, :, 2]
    a = np.arctan2(-k[:, 1], k[:, 2])
    b = np.arctan2(k[:, 0], np.hypot(k[:, 1], k[:, 2]))
    return t, a, b


def check_drift(got, H, M, Ix, Iy, duration=None):
    w_n = H / math.sqrt(Ix * Iy)
    assert close(got["angular_momentum"], H)
    assert close(got["moment"], M)
    assert close(got["drift_rate"], M / H)
    if duration is not None:
        assert close(got["drift_angle"], M / H * duration)
    assert close(got["nutation_frequency"], w_n)
    assert close(got["nutation_period"], 2 * math.pi / w_n)
    assert close(got["nutation_amplitude"], abs(M) * Iy / H**2)
    assert close(got["nutation_amplitude_drift"], abs(M) * math.sqrt(Ix * Iy) / H**2)
    assert close(got["max_deflection"], 2 * abs(M) * Iy / H**2)


def check_against_motion(got, meas, rtol):
    assert close(meas["drift"], got["drift_rate"], rtol)
    assert close(meas["w_n"], got["nutation_frequency"], rtol)
    assert close(meas["amp_x"], got["nutation_amplitude"], rtol)
    assert close(abs(meas["mean_x"]), got["nutation_amplitude"], rtol)    # centre of the swing: same size
    assert close(meas["max_x"], got["max_deflection"], rtol)
    assert close(meas["amp_y"], got["nutation_amplitude_drift"], rtol)


def test_gyro_drift_navigation_gyro_cgs(run, write):
    """A navigation gyro in cgs units: rotor J = 150 g cm^2 at 24,000 rpm,
    bearing friction 0.5 dyn cm about the inner gimbal axis; rotor with inner
    gimbal 90 g cm^2, outer gimbal adds 60 g cm^2 about the moment's axis.
    By hand: H = 1.5e-5 kg m^2 x 2513.27 rad/s = 0.037699 kg m^2/s;
    drift = 5e-8 / 0.037699 = 1.3263e-6 rad/s = 0.27357 deg/h; 6 h: 1.6414 deg."""
    J, spin, M, Ix, Iy = 150 * G_CM2, 24000 * RPM, 0.5 * DYN_CM, 150 * G_CM2, 90 * G_CM2
    got = solve(run, write, gd_yaml(
        "      J: 150 g*cm^2\n      spin: 24000 rpm\n      moment: 0.5 dyn*cm\n"
        "      I_x: 150 g*cm^2\n      I_y: 90 g*cm^2\n      duration: 6 h"))
    H = J * spin
    check_drift(got, H, M, Ix, Iy, 6 * HOUR)
    assert abs(got["drift_rate"] / (DEG / HOUR) - 0.27357) < 1e-4
    # the values in the units asked for: deg/h as navigation books quote it
    assert close(got["_values"]["drift_rate"][0], M / H / (DEG / HOUR))
    assert close(got["_values"]["drift_angle"][0], M / H * 6 * HOUR / DEG)
    # Hz on a rate: cycles per second, w_n / (2 pi)
    hz = solve(run, write, gd_yaml(
        "      J: 150 g*cm^2\n      spin: 24000 rpm\n      moment: 0.5 dyn*cm\n"
        "      I_x: 150 g*cm^2\n      I_y: 90 g*cm^2", "\n      nutation_frequency: Hz"), "hz.yaml")
    assert close(hz["_values"]["nutation_frequency"][0], H / math.sqrt(Ix * Iy) / (2 * math.pi))
    meas = measure_nutation(*linear_gimbals(H, M, Ix, Iy))
    check_against_motion(got, meas, 1e-6)


@pytest.mark.parametrize("M_text,M", [("1e-3 N*m", 1e-3), ("-1e-3 N*m", -1e-3)])
def test_gyro_drift_toy_rotor_unequal_gimbals_nonlinear(run, write, M_text, M):
    """A toy rotor J = 1e-4 kg m^2 at 3000 rpm, pushed with 1 mN m about the
    outer gimbal axis: I_x = 8e-5 (rotor 6e-5 + outer gimbal 2e-5), I_y = 6e-5.
    Both signs of M: the drift changes sign, the amplitudes are sizes."""
    J, spin, Ix, Iy = 1e-4, 3000 * RPM, 8e-5, 6e-5
    got = solve(run, write, gd_yaml(
        f"      J: 1e-4 kg*m^2\n      spin: 3000 rpm\n      moment: {M_text}\n"
        "      I_x: 8e-5 kg*m^2\n      I_y: 6e-5 kg*m^2\n      duration: 2 s"))
    H = J * spin
    check_drift(got, H, M, Ix, Iy, 2.0)
    assert (got["drift_rate"] > 0) == (M > 0)
    lin = measure_nutation(*linear_gimbals(H, M, Ix, Iy))
    check_against_motion(got, lin, 1e-6)
    # the nonlinear gimbals: angles of order 1e-4 to 1e-2 rad over the run;
    # they agree with the linear answers to about 1e-5
    non = measure_nutation(*nonlinear_gimbals(H, M, Ix, Iy))
    check_against_motion(got, non, 1e-4)


def test_gyro_drift_free_rotor_equal_inertias(run, write):
    """A disk rotor of 0.4 kg, radius 50 mm, spinning at 6000 rpm in light
    gimbals (neglected): I is the disk's own m r^2/4, J = m r^2/2.
    A moment of 0.02 N m fixed in space across the spin axis.  The full
    rigid-body motion (Euler's equations and attitude) is integrated."""
    m, r, spin, M = 0.4, 0.05, 6000 * RPM, 0.02
    J, I = m * r**2 / 2, m * r**2 / 4
    got = solve(run, write, gd_yaml(
        "      shape: disk\n      mass: 400 g\n      radius: 50 mm\n      spin: 6000 rpm\n"
        "      moment: 0.02 N*m\n      duration: 30 s"))
    H = J * spin
    check_drift(got, H, M, I, I, 30.0)
    assert close(got["nutation_frequency"], 2 * spin)         # H / I = 2 psidot for a thin disk
    meas = measure_nutation(*free_rotor(J, I, spin, M))
    check_against_motion(got, meas, 1e-4)      # nonlinear: agrees to about 1e-5


def test_gyro_drift_budget_and_angular_momentum(run, write):
    """A drift budget of 0.01 deg/h for a gyro of H = 2e5 g cm^2/s: the largest
    moment M = H x rate = 2e-2 kg m^2/s x 4.8481e-8 rad/s = 9.696e-10 N m."""
    H = 2e5 * G_CM2
    rate = 0.01 * DEG / HOUR
    got = solve(run, write, gd_yaml(
        "      angular_momentum: 2e5 g*cm^2/s\n      drift_rate: 0.01 deg/h\n      I: 50 g*cm^2\n"
        "      duration: 1 day"))
    check_drift(got, H, H * rate, 50 * G_CM2, 50 * G_CM2, 86400.0)
    assert close(got["drift_angle"], 0.24 * DEG)
    assert close(got["moment"], 9.6963e-10, 1e-4)


def test_gyro_drift_period_earth(run, write):
    """The Earth as a gyroscope: C = 8.04e37 kg m^2 turning once a sidereal day,
    its axis drifting once in 25,800 years: M = H 2 pi / T."""
    C, w = 8.04e37, 2 * math.pi / 86164.1
    H = C * w
    got = solve(run, write, gd_yaml(
        "      angular_momentum: 5.8627e33 kg*m^2/s\n      drift_period: 25800 year\n"
        "      I: 8.01e37 kg*m^2", "\n      moment: N*m\n      drift_rate: rad/s"))
    H = 5.8627e33
    assert abs(H / (C * w) - 1) < 1e-4
    assert close(got["drift_rate"], 2 * math.pi / (25800 * YEAR))
    assert close(got["moment"], H * 2 * math.pi / (25800 * YEAR))


@pytest.mark.parametrize("given,key", [
    ("      J: 1e-4 kg*m^2\n      spin: 0 rpm\n      moment: 1e-3 N*m\n      I: 6e-5 kg*m^2", "spin"),  # no spin: no gyroscope
    ("      J: 1e-4 kg*m^2\n      spin: 3000 rpm\n      I: 6e-5 kg*m^2", "moment"),                    # neither moment nor budget
])
def test_gyro_drift_refusals(run, write, given, key):
    assert refused(run, write, gd_yaml(given, "\n      drift_rate: deg/h"), key)
