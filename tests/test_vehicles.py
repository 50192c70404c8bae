"""ship, aeroplane, two_wheeler and four_wheeler checked against independent computations.

(a) ship and aeroplane: the rotor's H(t) = R(t) J omega s built here from rotation
    matrices (the vehicle turning, pitching or rolling), dH/dt by central
    differences, the reactive couple -dH/dt applied to the vehicle as a small
    rotation, and the effect read off how the bow (nose) point moves. The spin
    vector s comes from the words alone: "clockwise seen from X" means the top of
    the rotor moves to the observer's right. Every sense and turn is covered.
(b) two_wheeler and four_wheeler: the free body of the vehicle with every force
    (weight, road normal forces, friction) written out as vectors; their moments
    about G against dH/dt by finite differences of the rotors' H(t).
(c) the bundled problems by hand, the limiting speed by root finding on the free
    body, `gyro vary`, and bad input (exit 2, one line).
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from rotations import rx, rz

RPM = 2 * math.pi / 60
G = 9.81
UP = np.array([0.0, 0.0, 1.0])
BOW = np.array([1.0, 0.0, 0.0])


def ry(a: float) -> np.ndarray:
    c, s = math.cos(a), math.sin(a)
    return np.array([[c, 0, s], [0, 1.0, 0], [-s, 0, c]])


def solve_json(run, write, text):
    path = write(text)
    result = run("solve", "--format", "json", path)
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)["answers"]


def spin_unit(sense: str) -> np.ndarray:
    """Unit spin vector from the words: clockwise seen by an observer = top moves to their right."""
    turn, end = sense.split("_from_")
    look = BOW if end in ("stern", "rear") else -BOW       # the observer's line of sight
    right = np.cross(look, UP)                               # the observer's right hand
    for s in (look, -look):
        top_velocity = np.cross(s, UP)
        if (np.dot(top_velocity, right) > 0) == (turn == "clockwise"):
            return s
    raise AssertionError


def dH_dt(R_of, H_body, h=1e-5):
    return (R_of(h) @ H_body - R_of(-h) @ H_body) / (2 * h)


def words_from_motion(torque: np.ndarray, vehicle: str) -> str:
    """Apply the couple as a small rotation and see where the front end goes."""
    if np.linalg.norm(torque) < 1e-9:
        return "none"
    rotation = 1e-3 * torque / np.linalg.norm(torque)
    front = np.cross(rotation, BOW)                 # displacement of the bow / nose point
    out = []
    if abs(front[2]) > 1e-9:
        if vehicle == "ship":
            out.append("raises the bow and lowers the stern" if front[2] > 0 else
                       "lowers the bow and raises the stern")
        else:
            out.append("raises the nose and dips the tail" if front[2] > 0 else
                       "dips the nose and raises the tail")
    if abs(front[1]) > 1e-9:
        if vehicle == "ship":
            out.append("turns the ship to port" if front[1] > 0 else "turns the ship to starboard")
        else:
            out.append("turns the nose to the left" if front[1] > 0 else
                       "turns the nose to the right")
    return "; ".join(out)


SHIP_SENSES = ["clockwise_from_stern", "counterclockwise_from_stern", "clockwise_from_bow",
               "counterclockwise_from_bow"]
PLANE_SENSES = ["clockwise_from_rear", "counterclockwise_from_rear", "clockwise_from_front",
                "counterclockwise_from_front"]


def test_spin_unit_reads_the_words_as_textbooks_do():
    # Khurmi: clockwise seen from the stern, the spin vector points to the bow
    assert np.allclose(spin_unit("clockwise_from_stern"), BOW)
    assert np.allclose(spin_unit("counterclockwise_from_bow"), BOW)
    assert np.allclose(spin_unit("clockwise_from_front"), -BOW)


# ---- (a) ship and aeroplane: dH/dt of R(t) J omega s ------------------------------

@pytest.mark.parametrize("sense", SHIP_SENSES)
@pytest.mark.parametrize("turn", ["left", "right"])
def test_ship_steering_against_finite_differences(run, write, sense, turn):
    m, k, rpm, v, R = 8000.0, 0.6, 1800.0, 100 / 3.6, 75.0
    J, w, Om = m * k * k, rpm * RPM, v / R
    yaw = Om if turn == "left" else -Om          # a left turn is counter-clockwise from above
    H = J * w * spin_unit(sense)
    torque_on_ship = -dH_dt(lambda t: rz(yaw * t), H)
    got = solve_json(run, write, f"""
        id: t
        kind: ship
        given: {{mass: {m} kg, k_axial: {k} m, spin: {rpm} rpm, rotor_sense: {sense},
                 speed: 100 km/h, turn_radius: {R} m, turn: {turn}}}
        find: {{couple: N*m, effect: null}}
        """)
    assert got["couple"]["values"][0] == pytest.approx(np.linalg.norm(torque_on_ship), rel=1e-7)
    assert got["effect"]["values"][0] == words_from_motion(torque_on_ship, "ship")


@pytest.mark.parametrize("sense", SHIP_SENSES)
@pytest.mark.parametrize("bow", ["rising", "falling"])
def test_ship_pitching_against_finite_differences(run, write, sense, bow):
    m, k, rpm, phi, T = 6000.0, 0.45, 2400.0, math.radians(7.5), 18.0
    J, w, w1 = m * k * k, rpm * RPM, 2 * math.pi / T
    sign = 1.0 if bow == "rising" else -1.0
    theta = lambda t: sign * phi * math.sin(w1 * t)  # noqa: E731  bow-up angle, mean at t = 0
    R_of = lambda t: ry(-theta(t))  # noqa: E731     ry(-a) lifts the bow point by a
    assert (R_of(0.1) @ BOW)[2] * sign > 0           # the construction does what it says
    H = J * w * spin_unit(sense)
    torque_on_ship = -dH_dt(R_of, H)
    quarter = T / 4                                   # the extreme: largest angular acceleration
    h = 1e-3
    alpha = abs(theta(quarter + h) - 2 * theta(quarter) + theta(quarter - h)) / h ** 2
    got = solve_json(run, write, f"""
        id: t
        kind: ship
        given: {{mass: {m} kg, k_axial: {k} m, spin: {rpm} rpm, rotor_sense: {sense},
                 motion: pitching, amplitude: 7.5 deg, period: {T} s, bow: {bow}}}
        find: {{couple: N*m, effect: null, max_precession: rad/s,
                max_angular_acceleration: rad/s^2}}
        """)
    assert got["couple"]["values"][0] == pytest.approx(np.linalg.norm(torque_on_ship), rel=1e-7)
    assert got["effect"]["values"][0] == words_from_motion(torque_on_ship, "ship")
    assert got["max_precession"]["values"][0] == pytest.approx(
        (theta(1e-6) - theta(-1e-6)) / 2e-6 * sign, rel=1e-8)
    assert got["max_angular_acceleration"]["values"][0] == pytest.approx(alpha, rel=1e-5)


@pytest.mark.parametrize("sense", SHIP_SENSES[:2])
def test_ship_rolling_has_no_couple(run, write, sense):
    H = 1215 * 2400 * RPM * spin_unit(sense)
    assert np.allclose(dH_dt(lambda t: rx(0.035 * t), H), 0, atol=1e-6)
    got = solve_json(run, write, f"""
        id: t
        kind: ship
        given: {{mass: 6000 kg, k_axial: 450 mm, spin: 2400 rpm, rotor_sense: {sense},
                 motion: rolling, roll_rate: 0.035 rad/s}}
        find: {{couple: N*m, effect: null}}
        """)
    assert got["couple"]["values"] == [0.0]
    assert got["effect"]["values"] == ["none"]


@pytest.mark.parametrize("sense", PLANE_SENSES)
@pytest.mark.parametrize("turn", ["left", "right"])
def test_aeroplane_against_finite_differences(run, write, sense, turn):
    m, k, rpm, v, R = 400.0, 0.3, 2400.0, 200 / 3.6, 50.0
    yaw = v / R if turn == "left" else -v / R
    H = m * k * k * rpm * RPM * spin_unit(sense)
    torque = -dH_dt(lambda t: rz(yaw * t), H)
    got = solve_json(run, write, f"""
        id: t
        kind: aeroplane
        given: {{mass: {m} kg, k_axial: {k} m, spin: {rpm} rpm, rotor_sense: {sense},
                 speed: 200 km/h, turn_radius: {R} m, turn: {turn}}}
        find: {{couple: N*m, effect: null}}
        """)
    assert got["couple"]["values"][0] == pytest.approx(np.linalg.norm(torque), rel=1e-7)
    assert got["effect"]["values"][0] == words_from_motion(torque, "aeroplane")


def test_the_textbook_rules_hold():
    """Khurmi's statements, as the independent vector rule above reproduces them."""
    H = spin_unit("clockwise_from_stern")
    left = -dH_dt(lambda t: rz(0.1 * t), H)
    assert words_from_motion(left, "ship") == "raises the bow and lowers the stern"
    rising = -dH_dt(lambda t: ry(-0.1 * t), H)
    assert words_from_motion(rising, "ship") == "turns the ship to starboard"
    H = spin_unit("clockwise_from_rear")
    assert words_from_motion(-dH_dt(lambda t: rz(0.1 * t), H), "aeroplane") == \
        "raises the nose and dips the tail"


# ---- (b) wheelers: free body with every force ----------------------------------------

def wheel_spin_unit() -> np.ndarray:
    """Rolling forward (+x) without slip: omega x (contact - centre) = -v x gives omega along +y."""
    w = np.array([0.0, 1.0, 0.0])
    contact = np.array([0.0, 0.0, -1.0])
    assert np.allclose(np.cross(w, contact), -BOW)
    return w


@pytest.mark.parametrize("sense", ["same", "opposite"])
@pytest.mark.parametrize("turn", ["left", "right"])
@pytest.mark.parametrize("speed_kmh", [40.0, 90.0])
def test_two_wheeler_free_body(run, write, sense, turn, speed_kmh):
    m, h, Iw, rw, IE, Gr, R = 250.0, 0.6, 1.0, 0.3, 0.3, 5.0, 50.0
    v = speed_kmh / 3.6
    got = solve_json(run, write, f"""
        id: t
        kind: two_wheeler
        given: {{mass: {m} kg, cg_height: {h} m, wheel_inertia: {Iw} kg*m^2,
                 wheel_radius: {rw} m, engine_inertia: {IE} kg*m^2, gear_ratio: {Gr},
                 engine_sense: {sense}, speed: {speed_kmh} km/h, turn_radius: {R} m,
                 turn: {turn}}}
        find: {{heel_angle: rad, gyroscopic_couple: N*m, centrifugal_couple: N*m}}
        """)
    theta = got["heel_angle"]["values"][0]
    inward = 1.0 if turn == "left" else -1.0       # the centre lies to the left on a left turn
    Om = inward * v / R
    ww = v / rw
    H_spin = (2 * Iw * ww + (1 if sense == "same" else -1) * IE * Gr * ww) * wheel_spin_unit()
    lean = rx(-inward * theta)                       # leaning toward the centre by theta
    H_of = lambda t: rz(Om * t) @ lean  # noqa: E731
    dH = dH_dt(H_of, H_spin)
    G_pos = lean @ np.array([0.0, 0.0, h])           # centre of mass from the contact point
    assert G_pos[1] * inward >= 0 or theta < 0
    forces = {"normal": np.array([0.0, 0.0, m * G]),
              "friction": np.array([0.0, inward * m * v * v / R, 0.0])}
    weight = np.array([0.0, 0.0, -m * G])
    # forces: the net force is m a_G (centripetal, toward the centre)
    assert np.allclose(sum(forces.values()) + weight, [0, inward * m * v * v / R, 0])
    moment = sum(np.cross(-G_pos, f) for f in forces.values())   # about G; weight acts at G
    assert np.allclose(moment, dH, atol=1e-6 * m * G * h), (moment, dH)
    # upright couples by hand
    assert got["centrifugal_couple"]["values"][0] == pytest.approx(m * v * v * h / R)
    assert got["gyroscopic_couple"]["values"][0] == pytest.approx(
        np.dot(H_spin, [0, 1, 0]) * v / R)


@pytest.mark.parametrize("sense", ["same", "opposite"])
@pytest.mark.parametrize("turn", ["left", "right"])
def test_four_wheeler_free_body(run, write, sense, turn):
    m, h, x, rw, Ia, IE, n, Gr, R, kmh = 2500.0, 0.9, 1.5, 0.375, 18.0, 12.0, 2, 5.0, 30.0, 24.0
    v = kmh / 3.6
    got = solve_json(run, write, f"""
        id: t
        kind: four_wheeler
        given: {{mass: {m} kg, cg_height: {h} m, track: {x} m, wheel_radius: {rw} m,
                 axle_inertia: {Ia} kg*m^2, engine_inertia: {IE} kg*m^2, engines: {n},
                 gear_ratio: {Gr}, engine_sense: {sense}, speed: {kmh} km/h,
                 turn_radius: {R} m, turn: {turn}}}
        find: {{wheel_reactions: N, gyroscopic_couple: N*m, centrifugal_couple: N*m}}
        """)
    outer, inner = got["wheel_reactions"]["values"]
    inward = 1.0 if turn == "left" else -1.0
    ww = v / rw
    H = (2 * Ia + (1 if sense == "same" else -1) * n * IE * Gr) * ww * wheel_spin_unit()
    dH = dH_dt(lambda t: rz(inward * v / R * t), H)
    a = 1.2                                             # half the wheelbase: any value
    wheels = []                                         # (position from G, force on the car)
    for fore in (a, -a):
        for side, N in ((inward * x / 2, inner), (-inward * x / 2, outer)):
            friction = inward * m * v * v / R / 4
            wheels.append((np.array([fore, side, -h]), np.array([0.0, friction, N])))
    total = sum(f for _, f in wheels) + np.array([0.0, 0.0, -m * G])
    assert np.allclose(total, [0, inward * m * v * v / R, 0], atol=1e-6 * m * G)
    moment = sum(np.cross(r, f) for r, f in wheels)
    assert np.allclose(moment, dH, atol=1e-6 * m * G), (moment, dH)


def test_four_wheeler_limiting_speed_is_where_the_free_body_lifts_the_inner_wheels(run, write):
    from scipy.optimize import brentq

    m, h, x, rw, Ia, IE, Gr, R = 4000.0, 1.05, 1.5, 0.375, 30.0, 15.0, 3.0, 240.0

    def inner_reaction(v):
        # moments about G along x (left turn, inner wheels at y = +x/2, outer at -x/2,
        # friction m v^2 / R at depth h): 2 N_in (x/2) - 2 N_out (x/2) + h m v^2 / R = dH_x
        dHx = dH_dt(lambda t: rz(v / R * t),
                    (2 * Ia - 2 * IE * Gr) * v / rw * wheel_spin_unit())[0]
        diff = (dHx - h * m * v * v / R) / x            # N_in - N_out
        return (m * G / 2 + diff) / 2                   # with 2 N_in + 2 N_out = m g

    v_lim = brentq(inner_reaction, 1.0, 200.0, xtol=1e-12)
    got = solve_json(run, write, f"""
        id: t
        kind: four_wheeler
        given: {{mass: {m} kg, cg_height: {h} m, track: {x} m, wheel_radius: {rw} m,
                 axle_inertia: {Ia} kg*m^2, engine_inertia: {IE} kg*m^2, engines: 2,
                 gear_ratio: {Gr}, engine_sense: opposite, turn_radius: {R} m}}
        find: {{limiting_speed: m/s}}
        """)
    assert got["limiting_speed"]["values"][0] == pytest.approx(v_lim, rel=1e-6)


# ---- (c) by hand, problems, vary, bad input -------------------------------------

def test_hand_calculations_of_the_bundled_problems(run, problems_dir):
    def answers(name):
        result = run("solve", "--format", "json", problems_dir / name)
        assert result.exit_code == 0, result.output
        return {k: v["si_values"] for k, v in json.loads(result.stdout)["answers"].items()}

    # ship, 8 t: I = 8000 x 0.36 = 2880; omega = 1800 x 2 pi / 60 = 188.50; v/R = 27.78/75
    assert answers("ship_steering_8t.yaml")["couple"][0] == pytest.approx(
        2880 * 188.4956 * (100 / 3.6 / 75), rel=1e-5)
    # ship 6000 kg pitching: 1215 x 251.33 x (0.13090 x 0.34907)
    got = answers("ship_pitching_6000kg.yaml")
    assert got["couple"][0] == pytest.approx(1215 * 251.327 * 0.130900 * 0.349066, rel=1e-5)
    assert got["max_angular_acceleration"][0] == pytest.approx(0.130900 * 0.349066 ** 2,
                                                                rel=1e-5)
    # aeroplane 4200 N: m = 4200 / 9.81 = 428.13; J = 428.13 x 1^2; 335.10 x 152.78 / 100
    assert answers("aeroplane_4200N_right.yaml")["couple"][0] == pytest.approx(
        428.135 * 335.103 * 1.527778, rel=1e-5)
    # motorcycle: tan(theta) = (3.5 x 625 / 15 + 250 x 625 x 0.6 / 50) / (250 x 9.81 x 0.6)
    assert answers("two_wheeler_250kg.yaml")["heel_angle"][0] == pytest.approx(
        math.atan((3.5 * 625 / 15 + 1875) / 1471.5), rel=1e-9)
    # trolley 2500 kg: 6131.25 + (-84 x 44.444 / 11.25) / 3 + (2500 x 44.444 x 0.9 / 30) / 3
    outer, inner = answers("four_wheeler_trolley_2500kg.yaml")["wheel_reactions"]
    vv = (24 / 3.6) ** 2
    Cg, Cc = -84 * vv / (30 * 0.375), 2500 * vv * 0.9 / 30
    assert outer == pytest.approx(6131.25 + Cg / 3 + Cc / 3)
    assert inner == pytest.approx(6131.25 - Cg / 3 - Cc / 3)
    # rail car: v^2 = 4000 x 9.81 x 1.5 x 240 / (2 (-30 / 0.375 + 4200))
    assert answers("four_wheeler_railcar_limit.yaml")["limiting_speed"][0] == pytest.approx(
        math.sqrt(4000 * 9.81 * 1.5 * 240 / (2 * 4120)), rel=1e-9)


def test_every_vehicle_problem_checks(run, problems_dir):
    for prefix in ("ship_", "aeroplane_", "two_wheeler_", "four_wheeler_"):
        files = sorted(problems_dir.glob(prefix + "*.yaml"))
        assert len(files) >= 2
        for path in files:
            result = run("check", path)
            assert result.exit_code == 0, result.output


@pytest.mark.parametrize("name", ["ship_pitching_6000kg.yaml", "aeroplane_400kg_left.yaml",
                                  "two_wheeler_250kg.yaml", "four_wheeler_trolley_2500kg.yaml"])
def test_vary_on_vehicle_problems(run, problems_dir, tmp_path, name):
    out = tmp_path / "out"
    result = run("vary", problems_dir / name, "--count", "4", "--seed", "3", "-o", out)
    assert result.exit_code == 0, result.output
    checked = run("check", out)
    assert checked.exit_code == 0, checked.output
    assert "4 problems" in checked.stdout.splitlines()[-1]


SHIP = """
id: t
kind: ship
given:
  mass: 8000 kg
  k_axial: 0.6 m
  spin: 1800 rpm
  rotor_sense: clockwise_from_stern
{extra}
find: {{couple: N*m, effect: null}}
"""


@pytest.mark.parametrize("kind_text, reason", [
    (SHIP.format(extra="  speed: 10 m/s\n  turn_radius: 0 m"), "expected turn_radius > 0 m"),
    (SHIP.format(extra="  speed: 10 m/s"), "steering needs speed and turn_radius"),
    (SHIP.format(extra="  motion: pitching\n  amplitude: 5 deg\n  period: 10 s"),
     "bow: rising or falling"),
    (SHIP.format(extra="  motion: pitching\n  amplitude: 95 deg\n  period: 10 s\n  bow: rising"),
     "cannot pitch through 90 deg"),
    (SHIP.format(extra="  motion: rolling\n  speed: 10 m/s"), "belongs to `motion: steering`"),
    (SHIP.format(extra="  motion: sideways"), "expected one of steering, pitching, rolling"),
    (SHIP.replace("clockwise_from_stern", "clockwise_from_port").format(
        extra="  speed: 1 m/s\n  turn_radius: 5 m"), "expected one of clockwise_from_stern"),
    (SHIP.replace("  rotor_sense: clockwise_from_stern\n", "").format(
        extra="  speed: 1 m/s\n  turn_radius: 5 m"), "rotor_sense"),
    ("""
id: t
kind: aeroplane
given: {mass: 400 kg, k_axial: 0.3 m, spin: -2400 rpm, rotor_sense: clockwise_from_rear,
        speed: 200 km/h, turn_radius: 50 m}
find: {couple: N*m}
""", "positive rate"),
    ("""
id: t
kind: two_wheeler
given: {mass: 250 kg, cg_height: 0 m, wheel_inertia: 1 kg*m^2, wheel_radius: 0.3 m,
        speed: 20 m/s, turn_radius: 50 m}
find: {heel_angle: deg}
""", "expected cg_height > 0 m"),
    ("""
id: t
kind: two_wheeler
given: {mass: 250 kg, cg_height: 0.6 m, wheel_radius: 0.3 m, speed: 20 m/s, turn_radius: 50 m}
find: {heel_angle: deg}
""", "given.wheel_inertia"),
    ("""
id: t
kind: four_wheeler
given: {mass: 2500 kg, cg_height: 0.9 m, track: 1.5 m, wheel_radius: 0.375 m,
        wheel_inertia: 9 kg*m^2, axle_inertia: 18 kg*m^2, speed: 24 km/h, turn_radius: 30 m}
find: {wheel_reactions: N}
""", "one of them"),
    ("""
id: t
kind: four_wheeler
given: {mass: 2500 kg, cg_height: 0.9 m, track: 1.5 m, wheel_radius: 0.375 m,
        axle_inertia: 18 kg*m^2, engines: 1.5, speed: 24 km/h, turn_radius: 30 m}
find: {wheel_reactions: N}
""", "engines is a count"),
    ("""
id: t
kind: four_wheeler
given: {mass: 100 kg, cg_height: 0.1 m, track: 1.5 m, wheel_radius: 0.1 m,
        axle_inertia: 1 kg*m^2, engine_inertia: 10 kg*m^2, gear_ratio: 5,
        engine_sense: opposite, turn_radius: 30 m}
find: {limiting_speed: m/s}
""", "never leave the road"),
])
def test_bad_input_exits_2_with_one_line(run, write, kind_text, reason):
    result = run("solve", write(kind_text))
    assert result.exit_code == 2, result.output
    assert reason in result.stderr, result.stderr
    assert "Traceback" not in result.output
    assert len(result.stderr.strip().splitlines()) == 1


def test_inner_wheels_lifting_is_warned(run, write):
    result = run("solve", write("""
        id: t
        kind: four_wheeler
        given: {mass: 2500 kg, cg_height: 0.9 m, track: 1.5 m, wheel_radius: 0.375 m,
                wheel_inertia: 9 kg*m^2, speed: 120 km/h, turn_radius: 30 m}
        find: {wheel_reactions: N}
        """))
    assert result.exit_code == 0
    assert "inner wheels leave the road" in result.output


def test_extreme_magnitudes_keep_the_words_or_exit_2(run, write):
    tiny = run("solve", "--format", "json", write("""
        id: t
        kind: ship
        given: {mass: 1e-50 kg, k_axial: 1e-5 m, spin: 2400 rpm,
                rotor_sense: clockwise_from_stern, speed: 200 km/h, turn_radius: 50 m}
        find: {effect: null}
        """))
    assert tiny.exit_code == 0
    assert json.loads(tiny.stdout)["answers"]["effect"]["values"] == [
        "raises the bow and lowers the stern"]
    # below 1e-60 SI a given value is refused (issue 22 item 7): its products underflow
    underflow = run("solve", write("""
        id: t
        kind: ship
        given: {mass: 1e-300 kg, k_axial: 1e-10 m, spin: 2400 rpm,
                rotor_sense: clockwise_from_stern, speed: 200 km/h, turn_radius: 50 m}
        find: {effect: null}
        """))
    assert underflow.exit_code == 2
    assert "given.mass" in underflow.stderr and "underflow" in underflow.stderr
    assert len(underflow.stderr.strip().splitlines()) == 1
    for kind_text in ("""
        id: t
        kind: aeroplane
        given: {mass: 1e300 kg, k_axial: 1e10 m, spin: 2400 rpm,
                rotor_sense: clockwise_from_rear, speed: 200 km/h, turn_radius: 50 m}
        find: {effect: null}
        """, """
        id: t
        kind: two_wheeler
        given: {mass: 1e300 kg, cg_height: 1e10 m, wheel_inertia: 1 kg*m^2,
                wheel_radius: 0.3 m, speed: 20 m/s, turn_radius: 50 m}
        find: {heel_angle: deg}
        """):
        result = run("solve", write(kind_text))
        assert result.exit_code == 2, result.output
        assert "double precision" in result.stderr and "inf" not in result.output
        assert len(result.stderr.strip().splitlines()) == 1
