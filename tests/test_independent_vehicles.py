"""Independent check of the vehicle kinds: ship, aeroplane, two_wheeler, four_wheeler.

Everything gyro answers is re-derived here from first principles, without the
implementation:

* ship / aeroplane.  A rotor of axial inertia J spinning at omega about the
  fore-and-aft axis has H = J omega s (s = +-x).  The vehicle turns at omega_p,
  so H (fixed in the vehicle) is carried round: dH/dt = omega_p x H, and that
  is the couple the bearings must put ON the rotor.  The rotor pushes back on
  the vehicle with the reactive couple -(omega_p x H).
  - The size J omega omega_p is checked against central differences of
    H(t) = R(t) J omega s, with R(t) the vehicle's attitude written as a
    rotation matrix (yaw for steering, simple-harmonic pitch, roll).
  - The effect (words) is found by integrating Euler's equations of a
    gyrostat (vehicle + fore-and-aft rotor of constant relative spin) with
    solve_ivp: a rudder (or pitching) torque starts the turn (or the pitch)
    from rest, and we watch where the bow goes during the first instants.
    Nothing but Euler's equations and the right-hand rule enter.
  - The spin vector comes from the words alone: "clockwise seen by an
    observer" means the top of the rotor moves to that observer's right.
* two_wheeler.  Free body of the heeled machine in steady turn: weight, road
  normal force and friction written as vectors; sum F = m a_G and the moments
  about G equal dH/dt (finite differences of the tilted wheels' H(t)).  The
  heel is the root of that moment balance (brentq), compared with gyro.
* four_wheeler.  Free body of the car: four vertical reactions, friction,
  weight; vertical equilibrium and moments about G = dH/dt solved as a linear
  system for the left / right wheel reactions.  Limiting speed: brentq on the
  inner reaction from that free body.

Units as textbooks give them (rpm, km/h, knots, mph, tonne, lb, ft, slug ft^2)
are converted here by hand with exact definitions.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

# ---- exact unit definitions, written out by hand --------------------------
RPM = 2 * math.pi / 60          # rad/s per rev/min
KMH = 1000 / 3600               # m/s per km/h
KNOT = 1852 / 3600              # m/s per international knot
MPH = 1609.344 / 3600           # m/s per mile/h
FT = 0.3048                     # m
INCH = 0.0254                   # m
LB = 0.45359237                 # kg (pound mass)
LBF = LB * 9.80665              # N (pound force)
SLUG = LBF / FT                 # kg (lbf s^2 / ft)
DEG = math.pi / 180

X = np.array([1.0, 0.0, 0.0])   # forward (bow / nose)
Y = np.array([0.0, 1.0, 0.0])   # left (port)
Z = np.array([0.0, 0.0, 1.0])   # up

REL = 1e-6


# ---- running gyro ----------------------------------------------------------
def solve(run, write, text):
    """Solve a problem in-process; return (answers as SI lists, warnings)."""
    path = write(text)
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    answers = {k: v["si_values"] for k, v in data["answers"].items()}
    return answers, data["warnings"]


def close(a, b, rel=REL, abs_=1e-9):
    return abs(a - b) <= rel * abs(b) + abs_


# ---- rotations --------------------------------------------------------------
def rot(axis, angle):
    """Rodrigues: rotation by `angle` about unit vector `axis` (right hand)."""
    a = np.asarray(axis, float)
    a = a / np.linalg.norm(a)
    K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


def skew(w):
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


# ---- the spin vector from the words ----------------------------------------
def spin_unit(sense: str) -> np.ndarray:
    """Unit spin vector from e.g. 'clockwise_from_stern'.

    The observer at the stern (rear) looks forward (+x); at the bow (front) he
    looks aft (-x).  His 'right' is look x up.  Clockwise for him: the top of
    the rotor (position +z from the axis) moves to his right.  The spin w
    (along +-x) must satisfy w x z = right; try both and keep the one that
    does.  Counter-clockwise: the top moves to his left.
    """
    rotation, _, where = sense.split("_", 2)
    look = X if where in ("stern", "rear") else -X
    right = np.cross(look, Z)
    wanted = right if rotation == "clockwise" else -right
    for cand in (X, -X):
        if np.allclose(np.cross(cand, Z), wanted):
            return cand
    raise AssertionError(sense)


def test_spin_words_by_construction():
    # clockwise seen by someone = vector pointing away from him (right-hand rule)
    assert np.allclose(spin_unit("clockwise_from_stern"), X)
    assert np.allclose(spin_unit("clockwise_from_bow"), -X)
    assert np.allclose(spin_unit("counterclockwise_from_bow"), X)
    assert np.allclose(spin_unit("counterclockwise_from_rear"), -X)
    assert np.allclose(spin_unit("clockwise_from_front"), -X)


# ---- gyrostat: where does the bow go? ---------------------------------------
def bow_response(h_body, torque_world, t_end=0.3):
    """Integrate Euler's equations of a vehicle carrying a rotor.

    I dw/dt + w x (I w + h) = M   (body axes; h = rotor's relative momentum,
    fixed in the body), dR/dt = R [w]x.  Start at rest, aligned with the world.
    The torque `torque_world` (rudder or pitching) starts the commanded motion.
    Returns the bow direction R x at t_end.  Its component perpendicular to
    the commanded motion is the gyroscopic effect: -w x h is exactly the
    reactive couple -(omega_p x H) on the vehicle.
    """
    I = np.diag([2.0, 5.0, 6.0])
    Iinv = np.linalg.inv(I)

    def f(t, y):
        R = y[:9].reshape(3, 3)
        w = y[9:]
        M = R.T @ torque_world
        dw = Iinv @ (M - np.cross(w, I @ w + h_body))
        dR = R @ skew(w)
        return np.concatenate([dR.ravel(), dw])

    y0 = np.concatenate([np.eye(3).ravel(), np.zeros(3)])
    sol = solve_ivp(f, (0, t_end), y0, rtol=1e-11, atol=1e-14, method="DOP853")
    return sol.y[:9, -1].reshape(3, 3) @ X


def words_ship(bow):
    """Effect words for a ship from the bow's displacement (docs' table)."""
    if abs(bow[2]) > 1e-9 and abs(bow[2]) > abs(bow[1]):
        return ("raises the bow and lowers the stern" if bow[2] > 0
                else "lowers the bow and raises the stern")
    if abs(bow[1]) > 1e-9:
        return "turns the ship to port" if bow[1] > 0 else "turns the ship to starboard"
    return "none"


def words_plane(bow):
    if abs(bow[2]) > 1e-9 and abs(bow[2]) > abs(bow[1]):
        return ("raises the nose and dips the tail" if bow[2] > 0
                else "dips the nose and raises the tail")
    if abs(bow[1]) > 1e-9:
        return "turns the nose to the left" if bow[1] > 0 else "turns the nose to the right"
    return "none"


def steering_effect(sense, turn, words):
    """Rudder torque about +z (left) or -z (right); read the pitch of the bow."""
    s = spin_unit(sense)
    yaw = Z if turn == "left" else -Z
    bow = bow_response(1.0 * s, 0.5 * yaw)
    # the commanded yaw is in bow[1]; the gyroscopic response is the pitch:
    return words(np.array([0.0, 0.0, bow[2]]))


def pitching_effect(sense, bow_motion):
    """Pitching torque: bow rising = rotation carrying x to z = about -y."""
    s = spin_unit(sense)
    axis = -Y if bow_motion == "rising" else Y
    bow = bow_response(1.0 * s, 0.5 * axis)
    return words_ship(np.array([0.0, bow[1], 0.0]))  # the yaw is the effect


def test_gyrostat_bow_rises_for_khurmi_case():
    # sanity of the integrator: Khurmi's statement (rotor clockwise from the
    # stern, steering left -> bow rises) comes out of Euler's equations.
    assert steering_effect("clockwise_from_stern", "left", words_ship) == \
        "raises the bow and lowers the stern"


# ---- dH/dt by central differences ------------------------------------------
def dH_dt(H_of_t, t, dt=1e-4):
    return (H_of_t(t + dt) - H_of_t(t - dt)) / (2 * dt)


# =============================================================================
# ship
# =============================================================================
SENSES_SHIP = ["clockwise_from_stern", "counterclockwise_from_stern",
               "clockwise_from_bow", "counterclockwise_from_bow"]


def test_ship_steering_khurmi_8_tonne(run, write):
    # Khurmi: rotor 8 t, k = 0.6 m, 1800 rpm clockwise from the stern; ship at
    # 100 km/h steering left on a 75 m curve.
    a, _ = solve(run, write, """
        id: s1
        kind: ship
        given:
          mass: 8 tonne
          k_axial: 0.6 m
          spin: 1800 rpm
          rotor_sense: clockwise_from_stern
          speed: 100 km/h
          turn_radius: 75 m
          turn: left
        find:
          couple: kN*m
          precession: rad/s
          effect: null
        """)
    J = 8000 * 0.6 ** 2                 # = 2880 kg m^2
    omega = 1800 * RPM                  # = 188.50 rad/s
    wp = 100 * KMH / 75                 # = 0.37037 rad/s
    C = J * omega * wp                  # = 201.06 kN m
    assert close(a["couple"][0], C)
    assert close(a["precession"][0], wp)
    # finite differences: H(t) = Rz(wp t) J omega x (left turn: about +z)
    H = lambda t: rot(Z, wp * t) @ (J * omega * spin_unit("clockwise_from_stern"))
    on_rotor = dH_dt(H, 0.0)
    assert close(np.linalg.norm(on_rotor), C)
    assert close(on_rotor[1], C)            # omega_p x H along +y on the rotor
    # reactive couple on the ship is -y: rotation about -y lifts the bow
    assert a["effect"][0] == "raises the bow and lowers the stern"
    assert a["effect"][0] == steering_effect("clockwise_from_stern", "left", words_ship)


def test_ship_steering_imperial_weight(run, write):
    # An older British text: rotor weighing 20 000 lb, k = 2 ft, 3000 rpm
    # anticlockwise seen from the stern; 15 knots, turning to starboard on a
    # 1500 ft radius; couple in lbf ft.
    a, _ = solve(run, write, """
        id: s2
        kind: ship
        given:
          weight: 20000 lb
          g: 32.2 ft/s^2
          k_axial: 2 ft
          spin: 3000 rpm
          rotor_sense: counterclockwise_from_stern
          speed: 15 knot
          turn_radius: 1500 ft
          turn: right
        find:
          couple: lbf*ft
          effect: null
        """)
    m = 20000 * LBF / (32.2 * FT)       # mass from the weight with the stated g
    J = m * (2 * FT) ** 2
    wp = 15 * KNOT / (1500 * FT)
    C = J * 3000 * RPM * wp
    # in imperial: (20000/32.2) slug * 4 ft^2 * 314.16 * 0.016879... lbf ft
    C_lbfft = (20000 / 32.2) * 4 * 3000 * RPM * (15 * 6076.1154856 / 3600 / 1500)
    assert close(C / (LBF * FT), C_lbfft, rel=1e-6)
    assert close(a["couple"][0], C)
    # spin -x, omega_p -z: omega_p x H = (-z) x (-x) J w wp = +y on the rotor...
    # z x x = y, so (-z) x (-x) = +y; reactive -y: the bow rises.
    assert a["effect"][0] == "raises the bow and lowers the stern"
    assert a["effect"][0] == steering_effect("counterclockwise_from_stern", "right", words_ship)


@pytest.mark.parametrize("sense", SENSES_SHIP)
@pytest.mark.parametrize("turn", ["left", "right"])
def test_ship_steering_every_sense(run, write, sense, turn):
    a, _ = solve(run, write, f"""
        id: s3
        kind: ship
        given:
          J: 1500 kg*m^2
          spin: 2000 rpm
          rotor_sense: {sense}
          speed: 20 knot
          turn_radius: 400 m
          turn: {turn}
        find:
          couple: N*m
          effect: null
        """)
    J, omega, wp = 1500, 2000 * RPM, 20 * KNOT / 400
    s = spin_unit(sense)
    wz = Z if turn == "left" else -Z
    H = lambda t: rot(wz, wp * t) @ (J * omega * s)
    on_rotor = dH_dt(H, 0.3)
    assert close(a["couple"][0], np.linalg.norm(on_rotor))
    assert close(a["couple"][0], J * omega * wp)
    reactive = -on_rotor
    # reactive couple along -y lifts the bow; along +y dips it
    by_vector = ("raises the bow and lowers the stern" if reactive[1] < 0
                 else "lowers the bow and raises the stern")
    by_dynamics = steering_effect(sense, turn, words_ship)
    assert by_vector == by_dynamics
    assert a["effect"][0] == by_dynamics


@pytest.mark.parametrize("sense", SENSES_SHIP)
@pytest.mark.parametrize("bow", ["rising", "falling"])
def test_ship_pitching_shm_every_sense(run, write, sense, bow):
    # Rattan-style: rotor 6 t, k = 0.5 m, 2200 rpm; the ship pitches 6 deg
    # above and 6 deg below the mean (amplitude 6 deg) with a period of 20 s.
    a, _ = solve(run, write, f"""
        id: s4
        kind: ship
        given:
          mass: 6 tonne
          k_axial: 500 mm
          spin: 2200 rpm
          rotor_sense: {sense}
          motion: pitching
          amplitude: 6 deg
          period: 20 s
          bow: {bow}
        find:
          couple: N*m
          precession: rad/s
          max_precession: rad/s
          max_angular_acceleration: rad/s^2
          effect: null
        """)
    J, omega = 6000 * 0.5 ** 2, 2200 * RPM
    phi, T = 6 * DEG, 20.0
    w1 = 2 * math.pi / T
    # theta(t) = phi sin(w1 t): rate phi w1 cos, acceleration -phi w1^2 sin
    wp_max = phi * w1
    alpha_max = phi * w1 ** 2
    assert close(a["max_precession"][0], wp_max)
    assert close(a["precession"][0], wp_max)
    assert close(a["max_angular_acceleration"][0], alpha_max)
    assert close(a["couple"][0], J * omega * wp_max)

    # numerically: sample theta over a period, the largest rate by central
    # differences, the largest acceleration by second differences
    theta = lambda t: phi * math.sin(w1 * t)
    ts = np.linspace(0, T, 4001)
    dt = 1e-3
    rates = [(theta(t + dt) - theta(t - dt)) / (2 * dt) for t in ts]
    accs = [(theta(t + dt) - 2 * theta(t) + theta(t - dt)) / dt ** 2 for t in ts]
    assert close(max(np.abs(rates)), wp_max, rel=1e-6)
    assert close(max(np.abs(accs)), alpha_max, rel=1e-6)

    # the couple from dH/dt with the ship pitching: bow rising is a rotation
    # about -y, so H(t) = R(-y, theta(t)) J omega s when the bow rises at t = 0
    s = spin_unit(sense)
    sign = 1 if bow == "rising" else -1
    H = lambda t: rot(-Y, sign * theta(t)) @ (J * omega * s)
    couples = [np.linalg.norm(dH_dt(H, t, dt=1e-3)) for t in ts]
    assert close(max(couples), J * omega * wp_max, rel=1e-6)
    assert np.linalg.norm(dH_dt(H, T / 4, dt=1e-3)) < 1e-6 * J * omega * wp_max  # zero at the extremes
    reactive = -dH_dt(H, 0.0)
    by_vector = "turns the ship to port" if reactive[2] > 0 else "turns the ship to starboard"
    by_dynamics = pitching_effect(sense, bow)
    assert by_vector == by_dynamics
    assert a["effect"][0] == by_dynamics


def test_ship_pitching_rate_known_statement(run, write):
    # Khurmi: rotor clockwise from the stern, bow rising -> the ship turns to
    # starboard.  2.2 tonne, k = 320 mm, 200 rpm, pitching at 0.7 rad/s.
    a, _ = solve(run, write, """
        id: s5
        kind: ship
        given:
          mass: 2.2 tonne
          k_axial: 320 mm
          spin: 200 rpm
          rotor_sense: clockwise_from_stern
          motion: pitching
          pitch_rate: 0.7 rad/s
          bow: rising
        find:
          couple: N*m
          effect: null
        """)
    J = 2200 * 0.32 ** 2
    assert close(a["couple"][0], J * 200 * RPM * 0.7)      # 3302.8 N m
    # omega_p = -0.7 y, H = +x: omega_p x H = 0.7 J w (-y x x) = +z on the rotor,
    # -z on the ship: clockwise seen from above, to starboard.
    assert a["effect"][0] == "turns the ship to starboard"
    assert pitching_effect("clockwise_from_stern", "rising") == "turns the ship to starboard"


def test_ship_rolling_no_effect(run, write):
    a, _ = solve(run, write, """
        id: s6
        kind: ship
        given:
          mass: 6000 kg
          k_axial: 0.45 m
          spin: 2400 rpm
          rotor_sense: clockwise_from_bow
          motion: rolling
          roll_rate: 0.04 rad/s
        find:
          couple: N*m
          effect: null
        """)
    s = spin_unit("clockwise_from_bow")
    H = lambda t: rot(X, 0.04 * t) @ (6000 * 0.45 ** 2 * 2400 * RPM * s)
    assert np.linalg.norm(dH_dt(H, 0.0)) < 1e-6         # omega_p parallel to H
    bow = bow_response(s, 0.5 * X)                       # roll torque
    assert np.linalg.norm(bow - X) < 1e-9                # the bow does not move
    assert abs(a["couple"][0]) < 1e-9
    assert a["effect"][0] == "none"


def test_ship_zero_spin(run, write):
    # limiting case: no spin, no angular momentum, no couple, no effect
    a, _ = solve(run, write, """
        id: s7
        kind: ship
        given:
          J: 100 kg*m^2
          spin: 0 rpm
          rotor_sense: clockwise_from_stern
          speed: 10 knot
          turn_radius: 100 m
        find:
          couple: N*m
          effect: null
        """)
    assert abs(a["couple"][0]) < 1e-12
    assert a["effect"][0] == "none"


def test_ship_large_amplitude_formulas_hold(run, write):
    # 45 deg amplitude: still theta = phi sin(w1 t), so phi w1 and phi w1^2
    # (nothing in the derivation is small-angle).
    a, _ = solve(run, write, """
        id: s8
        kind: ship
        given:
          J: 10 kg*m^2
          spin: 100 rad/s
          rotor_sense: clockwise_from_stern
          motion: pitching
          amplitude: 45 deg
          period: 4 s
        find:
          couple: N*m
          max_precession: rad/s
          max_angular_acceleration: rad/s^2
        """)
    w1 = 2 * math.pi / 4
    assert close(a["max_precession"][0], math.pi / 4 * w1)
    assert close(a["max_angular_acceleration"][0], math.pi / 4 * w1 ** 2)
    assert close(a["couple"][0], 10 * 100 * math.pi / 4 * w1)


def test_ship_pitch_90_deg_refused(run, write):
    # 90 deg would stand the ship on its bow; gyro refuses it (exit 2).
    path = write("""
        id: s9
        kind: ship
        given:
          J: 10 kg*m^2
          spin: 100 rad/s
          rotor_sense: clockwise_from_stern
          motion: pitching
          amplitude: 90 deg
          period: 4 s
        find:
          couple: N*m
        """)
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 2
    assert "90" in result.output


# =============================================================================
# aeroplane
# =============================================================================
def test_aeroplane_rattan_left_turn(run, write):
    # engine + propeller 400 kg, k = 0.3 m, 2400 rpm clockwise seen from the
    # rear (pilot's view), 200 km/h, left turn of 50 m radius.
    a, _ = solve(run, write, """
        id: a1
        kind: aeroplane
        given:
          mass: 400 kg
          k_axial: 0.3 m
          spin: 2400 rpm
          rotor_sense: clockwise_from_rear
          speed: 200 km/h
          turn_radius: 50 m
          turn: left
        find:
          couple: N*m
          precession: rad/s
          effect: null
        """)
    J = 400 * 0.09                        # 36 kg m^2
    wp = 200 * KMH / 50                   # 1.111 rad/s
    C = J * 2400 * RPM * wp               # 10053 N m
    assert close(a["couple"][0], C)
    assert close(a["precession"][0], wp)
    # spin +x (clockwise seen by the pilot), omega_p +z: z x x = +y on the
    # rotor, -y on the aeroplane: rotation about -y lifts the nose.
    assert a["effect"][0] == "raises the nose and dips the tail"
    assert a["effect"][0] == steering_effect("clockwise_from_rear", "left", words_plane)


def test_aeroplane_imperial(run, write):
    # J given in slug ft^2, speed in mph, radius in ft.
    a, _ = solve(run, write, """
        id: a2
        kind: aeroplane
        given:
          J: 12 slug*ft^2
          spin: 1800 rpm
          rotor_sense: counterclockwise_from_front
          speed: 150 mph
          turn_radius: 1200 ft
          turn: right
        find:
          couple: lbf*ft
          effect: null
        """)
    J = 12 * SLUG * FT ** 2
    wp = 150 * MPH / (1200 * FT)
    C = J * 1800 * RPM * wp
    # all-imperial hand figure: 12 * 188.50 * (220 ft/s / 1200 ft) lbf ft
    assert close(C / (LBF * FT), 12 * 1800 * RPM * (150 * 5280 / 3600 / 1200))
    assert close(a["couple"][0], C)
    # ccw from the front = cw from the rear: spin +x; right turn omega_p = -z:
    # (-z) x x = -y on the rotor, +y on the plane: the nose dips.
    assert a["effect"][0] == "dips the nose and raises the tail"
    assert a["effect"][0] == steering_effect("counterclockwise_from_front", "right", words_plane)


@pytest.mark.parametrize("sense", ["clockwise_from_rear", "counterclockwise_from_rear",
                                   "clockwise_from_front", "counterclockwise_from_front"])
@pytest.mark.parametrize("turn", ["left", "right"])
def test_aeroplane_every_sense(run, write, sense, turn):
    a, _ = solve(run, write, f"""
        id: a3
        kind: aeroplane
        given:
          J: 5 kg*m^2
          spin: 3000 rpm
          rotor_sense: {sense}
          speed: 300 km/h
          turn_radius: 800 m
          turn: {turn}
        find:
          couple: N*m
          effect: null
        """)
    J, omega, wp = 5, 3000 * RPM, 300 * KMH / 800
    s = spin_unit(sense)
    wz = Z if turn == "left" else -Z
    on_rotor = dH_dt(lambda t: rot(wz, wp * t) @ (J * omega * s), 0.0)
    assert close(a["couple"][0], np.linalg.norm(on_rotor))
    expected = steering_effect(sense, turn, words_plane)
    assert expected == ("raises the nose and dips the tail" if -on_rotor[1] < 0
                        else "dips the nose and raises the tail")
    assert a["effect"][0] == expected


# =============================================================================
# two_wheeler
# =============================================================================
def two_wheeler_free_body(m, h, I_eq, r_w, v, R, g, turn="left"):
    """Heel from the free body of the machine (heading frame x fwd, y left, z up).

    Left turn: centre of the curve on +y, omega_p = +z v/R.  The machine leans
    toward the centre by theta: G sits at (0, s h sin(theta), h cos(theta))
    from the contact P, s = +1 for a left turn.  Forces at P: N z (normal) and
    F (friction toward the centre).  G moves on a circle: a_G = v^2/R toward
    the centre, so sum F = m a_G gives N = m g, F = m v^2 / R.
    Wheels (and engine with I_eq = 2 I_w +- G I_E) spin about the axle,
    perpendicular to the tilted wheel plane: axle unit a = (0, cos, -s sin);
    rolling forward spins them about +y (w x r z = v x for w = v/r y), so
    H = I_eq (v/r_w) a.  It is carried round at omega_p: dH/dt by finite
    differences of H(t) = Rz(omega_p t) H.  Moments about G must equal dH/dt.
    Returns theta (signed: + toward the centre) solving the x-moment balance,
    and a function giving the residual vector of both laws.
    """
    side = 1.0 if turn == "left" else -1.0
    wp = side * v / R
    centre = side * Y

    def residual(theta):
        rG = np.array([0.0, side * h * math.sin(theta), h * math.cos(theta)])
        N = m * g * Z
        F = m * v ** 2 / R * centre
        W = -m * g * Z
        force_res = (N + F + W) - m * (v ** 2 / R) * centre
        a = np.array([0.0, math.cos(theta), -side * math.sin(theta)])
        H0 = I_eq * v / r_w * a
        dH = dH_dt(lambda t: rot(Z, wp * t) @ H0, 0.0, dt=1e-5)
        moment_G = np.cross(-rG, N + F)                # contact force about G
        return force_res, moment_G - dH

    theta = brentq(lambda th: residual(th)[1][0], -math.pi / 2 + 1e-9,
                   math.pi / 2 - 1e-9, xtol=1e-14)
    return theta, residual


def test_two_wheeler_250kg(run, write):
    a, w = solve(run, write, """
        id: t1
        kind: two_wheeler
        given:
          mass: 250 kg
          cg_height: 0.6 m
          wheel_inertia: 1 kg*m^2
          wheel_radius: 300 mm
          engine_inertia: 0.3 kg*m^2
          gear_ratio: 5
          engine_sense: same
          speed: 90 km/h
          turn_radius: 50 m
        find:
          heel_angle: deg
          gyroscopic_couple: N*m
          centrifugal_couple: N*m
        """)
    m, h, v, R, r = 250, 0.6, 25.0, 50.0, 0.3
    I_eq = 2 * 1 + 5 * 0.3                       # 3.5 kg m^2
    Cg = I_eq * (v / r) * (v / R)                 # 3.5 * 83.33 * 0.5 = 145.83
    Cc = m * v ** 2 / R * h                       # 1875
    theta = math.atan((Cg + Cc) / (m * 9.81 * h))  # 53.94 deg
    assert close(a["gyroscopic_couple"][0], Cg)
    assert close(a["centrifugal_couple"][0], Cc)
    assert close(a["heel_angle"][0], theta)
    th_fb, res = two_wheeler_free_body(m, h, I_eq, r, v, R, 9.81)
    assert close(a["heel_angle"][0], th_fb, rel=1e-7)
    f_res, m_res = res(th_fb)
    assert np.allclose(f_res, 0) and np.allclose(m_res, 0, atol=1e-5)
    assert w == []


def test_two_wheeler_racing_khurmi(run, write):
    # Khurmi ex. 18: 150 kg, h 0.7 m, wheels 0.6 m dia, 1.5 kg m^2 each, engine
    # 0.25 kg m^2 at 5x in the same sense, 140 km/h on a 120 m curve -> 55.57 deg.
    a, _ = solve(run, write, """
        id: t2
        kind: two_wheeler
        given:
          mass: 150 kg
          cg_height: 0.7 m
          wheel_inertia: 1.5 kg*m^2
          wheel_radius: 0.3 m
          engine_inertia: 0.25 kg*m^2
          gear_ratio: 5
          speed: 140 km/h
          turn_radius: 120 m
          turn: right
        find:
          heel_angle: deg
        """)
    v = 140 * KMH
    I_eq = 2 * 1.5 + 5 * 0.25
    th_fb, _ = two_wheeler_free_body(150, 0.7, I_eq, 0.3, v, 120, 9.81, turn="right")
    assert close(a["heel_angle"][0], th_fb, rel=1e-7)
    # the book prints 55.57 deg from rounded intermediate figures; we get 55.555
    assert abs(math.degrees(th_fb) - 55.57) < 0.02


def test_two_wheeler_opposite_engine_imperial(run, write):
    # US units: machine + rider 500 lb, G 2 ft up, wheels 12 in radius with
    # 15 lb ft^2 each, engine 2 lb ft^2 at 6x running against the wheels,
    # 45 mph on a 200 ft curve, g = 32.2 ft/s^2.
    a, _ = solve(run, write, """
        id: t3
        kind: two_wheeler
        given:
          mass: 500 lb
          g: 32.2 ft/s^2
          cg_height: 2 ft
          wheel_inertia: 15 lb*ft^2
          wheel_radius: 12 in
          engine_inertia: 2 lb*ft^2
          gear_ratio: 6
          engine_sense: opposite
          speed: 45 mph
          turn_radius: 200 ft
        find:
          heel_angle: deg
          gyroscopic_couple: lbf*ft
          centrifugal_couple: lbf*ft
        """)
    m, h, r, g = 500 * LB, 2 * FT, 12 * INCH, 32.2 * FT
    I_w, I_E = 15 * LB * FT ** 2, 2 * LB * FT ** 2
    v, R = 45 * MPH, 200 * FT
    I_eq = 2 * I_w - 6 * I_E                   # engine against the wheels
    Cg = I_eq * v ** 2 / (R * r)
    Cc = m * v ** 2 * h / R
    assert close(a["gyroscopic_couple"][0], Cg)
    assert close(a["centrifugal_couple"][0], Cc)
    th_fb, _ = two_wheeler_free_body(m, h, I_eq, r, v, R, g)
    assert close(a["heel_angle"][0], th_fb, rel=1e-7)
    assert close(a["heel_angle"][0], math.atan((Cg + Cc) / (m * g * h)))


def test_two_wheeler_leans_outward_when_engine_dominates(run, write):
    # light, low machine with a big reversed engine: C_g + C_c < 0
    a, w = solve(run, write, """
        id: t4
        kind: two_wheeler
        given:
          mass: 100 kg
          cg_height: 0.1 m
          wheel_inertia: 0.1 kg*m^2
          wheel_radius: 0.3 m
          engine_inertia: 2 kg*m^2
          gear_ratio: 10
          engine_sense: opposite
          speed: 20 m/s
          turn_radius: 50 m
          turn: left
        find:
          heel_angle: deg
          gyroscopic_couple: N*m
        """)
    I_eq = 0.2 - 20.0                                 # -19.8 kg m^2
    assert close(a["gyroscopic_couple"][0], I_eq * 400 / (50 * 0.3))   # -528 N m
    th_fb, _ = two_wheeler_free_body(100, 0.1, I_eq, 0.3, 20, 50, 9.81)
    assert th_fb < 0                                  # away from the centre
    assert close(a["heel_angle"][0], th_fb, rel=1e-7)
    assert any("outward" in x for x in w)


def test_two_wheeler_no_gyro_is_banking_angle(run, write):
    # limiting case: massless wheels, no engine -> tan(theta) = v^2 / (g R)
    a, _ = solve(run, write, """
        id: t5
        kind: two_wheeler
        given:
          mass: 180 kg
          cg_height: 0.65 m
          wheel_inertia: 0 kg*m^2
          wheel_radius: 0.3 m
          speed: 72 km/h
          turn_radius: 40 m
        find:
          heel_angle: rad
          gyroscopic_couple: N*m
        """)
    assert abs(a["gyroscopic_couple"][0]) < 1e-12
    assert close(a["heel_angle"][0], math.atan(20.0 ** 2 / (9.81 * 40)))


# =============================================================================
# four_wheeler
# =============================================================================
def four_wheeler_free_body(m, h, x, I_eq, r_w, v, R, g, turn="left"):
    """Per-wheel reactions [outer, inner] from the free body.

    Heading frame x fwd, y left, z up, G at the origin, road at z = -h.
    Wheels at (+-b, +-x/2, -h); left wheels carry P_L each, right P_R each.
    Friction: total m v^2/R toward the centre, shared between the wheels
    (its moment about G only depends on the total because all act at z = -h).
    Unknowns P_L, P_R from
      vertical: 2 P_L + 2 P_R - m g = 0 (G does not accelerate vertically)
      moment about G, x-component = (dH/dt)_x, with H = I_eq (v/r_w) y
      (every rotor's axis across the car; I_eq = sum I_w +- G sum I_E)
      carried round at omega_p = +-v/R z (finite differences).
    The y and z moment equations are balanced by the symmetric fore/aft split.
    """
    side = 1.0 if turn == "left" else -1.0
    wp = side * v / R
    centre = side * Y
    b = 1.3  # half wheelbase; drops out
    H0 = I_eq * v / r_w * Y
    dH = dH_dt(lambda t: rot(Z, wp * t) @ H0, 0.0, dt=1e-5)
    fric = m * v ** 2 / R * centre / 4                # each wheel, any split works

    def moment_x(PL, PR):
        M = np.zeros(3)
        for sx in (b, -b):
            for sy, P in ((x / 2, PL), (-x / 2, PR)):
                r = np.array([sx, sy, -h])
                M += np.cross(r, P * Z + fric)
        return M

    # linear in PL, PR: build the 2x2 system numerically
    base = moment_x(0, 0)
    col_L = moment_x(1, 0) - base
    col_R = moment_x(0, 1) - base
    A = np.array([[2.0, 2.0], [col_L[0], col_R[0]]])
    rhs = np.array([m * g, dH[0] - base[0]])
    PL, PR = np.linalg.solve(A, rhs)
    # check the remaining moment components are balanced (symmetry)
    Mfull = moment_x(PL, PR)
    assert np.allclose(Mfull[1:], dH[1:], atol=1e-6)
    # outer wheels are on the far side from the centre
    return (PR, PL) if turn == "left" else (PL, PR)


def test_four_wheeler_trolley_khurmi(run, write):
    # Khurmi: trolley 2500 kg, rails 1.5 m apart, 30 m curve at 24 km/h;
    # wheels 0.75 m dia; each axle (with gear, wheels) 18 kg m^2; each of two
    # motors 12 kg m^2 at 5x the wheel speed, running opposite; G 0.9 m up.
    a, w = solve(run, write, """
        id: f1
        kind: four_wheeler
        given:
          mass: 2.5 tonne
          cg_height: 0.9 m
          track: 1.5 m
          wheel_radius: 0.375 m
          axle_inertia: 18 kg*m^2
          engine_inertia: 12 kg*m^2
          engines: 2
          gear_ratio: 5
          engine_sense: opposite
          speed: 24 km/h
          turn_radius: 30 m
        find:
          wheel_reactions: N
          gyroscopic_couple: N*m
          centrifugal_couple: N*m
          limiting_speed: km/h
        """)
    m, h, x, r, R, g = 2500, 0.9, 1.5, 0.375, 30.0, 9.81
    v = 24 * KMH
    I_eq = 2 * 18 - 5 * (2 * 12)            # -84 kg m^2
    Cg = I_eq * v ** 2 / (R * r)            # -331.85 N m
    Cc = m * v ** 2 * h / R                 # 3333.3 N m
    outer = m * g / 4 + Cg / (2 * x) + Cc / (2 * x)    # 7131.7 N
    inner = m * g / 4 - Cg / (2 * x) - Cc / (2 * x)    # 5130.8 N
    assert close(a["gyroscopic_couple"][0], Cg)
    assert close(a["centrifugal_couple"][0], Cc)
    assert close(a["wheel_reactions"][0], outer)
    assert close(a["wheel_reactions"][1], inner)
    fb = four_wheeler_free_body(m, h, x, I_eq, r, v, R, g)
    assert close(a["wheel_reactions"][0], fb[0], rel=1e-7)
    assert close(a["wheel_reactions"][1], fb[1], rel=1e-7)
    # limiting speed: inner reaction of the free body = 0
    v_lim = brentq(lambda vv: four_wheeler_free_body(m, h, x, I_eq, r, vv, R, g)[1],
                   1.0, 200.0, xtol=1e-12)
    assert close(a["limiting_speed"][0], v_lim, rel=1e-7)
    assert close(v_lim ** 2, m * g * x * R / (2 * (I_eq / r + m * h)), rel=1e-7)
    assert w == []


def test_four_wheeler_car_right_turn_wheels_each(run, write):
    # Car 2000 kg, track 1.5 m, G 0.5 m up, wheels 0.8 m dia with 0.8 kg m^2
    # each; transverse engine 0.75 kg m^2 at 4x the wheel speed, same sense;
    # right turn of 60 m radius at 60 km/h.
    a, _ = solve(run, write, """
        id: f2
        kind: four_wheeler
        given:
          mass: 2000 kg
          cg_height: 500 mm
          track: 1.5 m
          wheel_radius: 0.4 m
          wheel_inertia: 0.8 kg*m^2
          engine_inertia: 0.75 kg*m^2
          gear_ratio: 4
          engine_sense: same
          speed: 60 km/h
          turn_radius: 60 m
          turn: right
        find:
          wheel_reactions: N
          gyroscopic_couple: N*m
          limiting_speed: m/s
        """)
    m, h, x, r, R, g = 2000, 0.5, 1.5, 0.4, 60.0, 9.81
    v = 60 * KMH
    I_eq = 4 * 0.8 + 4 * 0.75               # 6.2 kg m^2
    Cg = I_eq * v ** 2 / (R * r)
    assert close(a["gyroscopic_couple"][0], Cg)
    fb = four_wheeler_free_body(m, h, x, I_eq, r, v, R, g, turn="right")
    assert close(a["wheel_reactions"][0], fb[0], rel=1e-7)
    assert close(a["wheel_reactions"][1], fb[1], rel=1e-7)
    assert fb[0] > fb[1]
    v_lim = brentq(lambda vv: four_wheeler_free_body(m, h, x, I_eq, r, vv, R, g, "right")[1],
                   1.0, 300.0, xtol=1e-12)
    assert close(a["limiting_speed"][0], v_lim, rel=1e-7)


def test_four_wheeler_railcar_limit(run, write):
    # Khurmi rail car: 4 t, axles 30 kg m^2 each, 1.5 m gauge, 375 mm wheels,
    # two motors 15 kg m^2 at 3x, opposite; G 1.05 m; 240 m curve -> 149 km/h.
    a, _ = solve(run, write, """
        id: f3
        kind: four_wheeler
        given:
          mass: 4 tonne
          cg_height: 1.05 m
          track: 1.5 m
          wheel_radius: 375 mm
          axle_inertia: 30 kg*m^2
          engine_inertia: 15 kg*m^2
          engines: 2
          gear_ratio: 3
          engine_sense: opposite
          turn_radius: 240 m
        find:
          limiting_speed: km/h
        """)
    m, h, x, r, R, g = 4000, 1.05, 1.5, 0.375, 240.0, 9.81
    I_eq = 2 * 30 - 3 * 2 * 15              # -30 kg m^2
    v_lim = brentq(lambda vv: four_wheeler_free_body(m, h, x, I_eq, r, vv, R, g)[1],
                   1.0, 200.0, xtol=1e-12)
    assert close(a["limiting_speed"][0], v_lim, rel=1e-7)
    assert abs(v_lim / KMH - 149.0) < 0.1               # 149.06 km/h


def test_four_wheeler_above_limit_inner_wheels_lift(run, write):
    # imperial trolley: 6000 lb, 4 ft 8.5 in gauge, G 4 ft up, 15 in wheels
    # with 40 lb ft^2 each, no engine, 60 mph on a 300 ft curve
    a, w = solve(run, write, """
        id: f4
        kind: four_wheeler
        given:
          mass: 6000 lb
          cg_height: 4 ft
          track: 56.5 in
          wheel_radius: 15 in
          wheel_inertia: 40 lb*ft^2
          speed: 60 mph
          turn_radius: 300 ft
        find:
          wheel_reactions: N
          limiting_speed: mph
        """)
    m, h, x, r = 6000 * LB, 4 * FT, 56.5 * INCH, 15 * INCH
    I_eq = 4 * 40 * LB * FT ** 2
    v, R = 60 * MPH, 300 * FT
    fb = four_wheeler_free_body(m, h, x, I_eq, r, v, R, 9.81)
    assert fb[1] < 0                          # the free body needs a pull: lifts
    assert close(a["wheel_reactions"][0], fb[0], rel=1e-7)
    assert close(a["wheel_reactions"][1], fb[1], rel=1e-7)
    v_lim = brentq(lambda vv: four_wheeler_free_body(m, h, x, I_eq, r, vv, R, 9.81)[1],
                   0.5, v, xtol=1e-12)
    assert close(a["limiting_speed"][0], v_lim, rel=1e-7)
    assert w, "a negative reaction should be warned about"


def test_four_wheeler_zero_speed_weight_only(run, write):
    a, _ = solve(run, write, """
        id: f5
        kind: four_wheeler
        given:
          mass: 1200 kg
          cg_height: 0.55 m
          track: 1.4 m
          wheel_radius: 0.3 m
          wheel_inertia: 1 kg*m^2
          speed: 0 km/h
          turn_radius: 50 m
        find:
          wheel_reactions: N
        """)
    assert close(a["wheel_reactions"][0], 1200 * 9.81 / 4)
    assert close(a["wheel_reactions"][1], 1200 * 9.81 / 4)


def test_four_wheeler_never_lifts_exit_2(run, write):
    # I_eq / r_w + m h < 0: the reversed gyroscopic couple always presses the
    # inner wheels down more than centrifugal action lifts them; the inner
    # reaction from the free body grows with speed, it never reaches zero.
    m, h, x, r, R = 100, 0.1, 1.0, 0.3, 50.0
    I_eq = 4 * 0.1 - 10 * 2
    inner = [four_wheeler_free_body(m, h, x, I_eq, r, vv, R, 9.81)[1] for vv in (1, 10, 100)]
    assert inner[0] < inner[1] < inner[2]
    path = write("""
        id: f6
        kind: four_wheeler
        given:
          mass: 100 kg
          cg_height: 0.1 m
          track: 1 m
          wheel_radius: 0.3 m
          wheel_inertia: 0.1 kg*m^2
          engine_inertia: 2 kg*m^2
          gear_ratio: 10
          engine_sense: opposite
          turn_radius: 50 m
        find:
          limiting_speed: m/s
        """)
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 2
