"""Issue 35, round four: the chapter's classic applications (item 10: the edge-runner mill,
a ship's stabiliser gyro, an aeroplane in a loop, the turbine rotor of a pitching ship)
and signed pairs written as books print them (item 7).

Every number is worked by hand here from the books' data, and the directions and the
mill's pressure are found independently: the rotor's angular momentum is built as a
vector H(t) from rotation matrices, dH/dt is taken by central differences, and the forces
come from moments about the hinge written as vectors; never by calling gyro's formula.
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from gyro_cli.checking import check
from gyro_cli.cli import main
from gyro_cli.solving.solve import solve_file

RPM = 2 * math.pi / 60
G_US = 32.2 * 0.3048
LBF = 4.4482216152605
FT = 0.3048


def answers(path: Path) -> dict:
    return solve_file(str(path)).answers


def si(path: Path, name: str) -> list:
    return answers(path)[name].si_values


def rot(axis: np.ndarray, angle: float) -> np.ndarray:
    """Rodrigues' rotation matrix about the unit ``axis``."""
    a = axis / np.linalg.norm(axis)
    K = np.array([[0, -a[2], a[1]], [a[2], 0, -a[0]], [-a[1], a[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


def ddt(f, t: float = 0.0, h: float = 1e-5) -> np.ndarray:
    return (f(t + h) - f(t - h)) / (2 * h)


X, Y, Z = np.eye(3)


# ---- item 10: the edge-runner mill -------------------------------------------------

def mill_pan_force(m: float, J: float, I_O: float, r: float, R: float, Omega: float,
                   g: float = 9.81) -> float:
    """The pan's force on one roller from moments about the hinge O, as vectors.

    The roller's body frame turns at Omega about z, and the roller spins about its axle
    e_r at the rate that keeps the contact point at rest (found here from the velocity of
    the contact point, not from the book's formula). H about O = J w_s e_r + I_O Omega z;
    dH/dt by central differences; the moment of the weight and of N z at the contact point
    about O must equal it along e_t (the pin gives no moment about e_t)."""
    # rolling: v_contact = Omega z x (R e_r - r z) + w_s e_r x (-r z) = 0 along e_t
    e_r0 = X
    v_from_shaft = np.cross(Omega * Z, R * e_r0 - r * Z)
    v_per_spin = np.cross(e_r0, -r * Z)
    w_s = -float(v_from_shaft @ Y) / float(v_per_spin @ Y)

    def H(t: float) -> np.ndarray:
        e_r = rot(Z, Omega * t) @ e_r0
        return J * w_s * e_r + I_O * Omega * Z

    dH = ddt(H)
    e_t = Y
    contact = R * e_r0 - r * Z
    # moment of the weight at R e_r and of N z at the contact point, along e_t:
    weight_moment = float(np.cross(R * e_r0, -m * g * Z) @ e_t)
    per_N = float(np.cross(contact, Z) @ e_t)
    return (float(dH @ e_t) - weight_moment) / per_N


def test_item10_edge_runner_two_rollers_by_hand(problems_dir):
    # Khurmi-style: 2 t rollers, 1.2 m diameter, k = 0.5 m, path 0.75 m, shaft 40 rpm
    J, r, R, Omega = 2000 * 0.5 ** 2, 0.6, 0.75, 40 * RPM
    omega = Omega * R / r                      # rolling: rim speed = centre speed
    C = J * omega * Omega
    P = C / R                                  # moments about the hinge
    assert omega == pytest.approx(5.236, abs=1e-3)
    assert C == pytest.approx(10966, abs=1)
    assert P == pytest.approx(14622, abs=1)
    total = 2 * (2000 * 9.81 + P)
    path = problems_dir / "edge_runner_two_rollers.yaml"
    assert si(path, "roller_spin")[0] == pytest.approx(omega, rel=1e-12)
    assert si(path, "couple")[0] == pytest.approx(C, rel=1e-12)
    assert si(path, "extra_pressure")[0] == pytest.approx(P, rel=1e-12)
    assert si(path, "total_pan_force")[0] == pytest.approx(total, rel=1e-12)


@pytest.mark.parametrize("Omega", [40 * RPM, -40 * RPM, 3.0])
def test_item10_edge_runner_pan_force_from_the_vectors(write, Omega):
    """The pan force from dH/dt about the hinge (numerical), either way round: the couple
    always presses the roller down."""
    m, k, r, R = 2000.0, 0.5, 0.6, 0.75
    J = m * k * k
    N = mill_pan_force(m, J, I_O=J / 2 + m * R * R, r=r, R=R, Omega=Omega)
    assert N > m * 9.81
    path = write(f"""\
        id: mill
        kind: edge_runner
        given: {{mass: {m} kg, k_axial: {k} m, radius: {r} m, path_radius: {R} m,
                 shaft_speed: {abs(Omega)!r} rad/s}}
        find: {{pan_force: N}}
        """)
    assert si(path, "pan_force")[0] == pytest.approx(N, rel=1e-6)


def test_item10_edge_runner_limits(write):
    """A roller with no inertia presses with its weight alone; the extra pressure does not
    depend on the path radius (J Omega^2 / r: BGU's disk)."""
    def pan(R: float, J: str = "") -> list:
        body = f"J: {J}, mass: 2 kg, radius: 0.1 m" if J else "mass: 2 kg, shape: disk, radius: 0.1 m"
        return si(write(f"""\
            id: d
            kind: edge_runner
            given: {{{body}, path_radius: {R} m, shaft_speed: 5 rad/s}}
            find: {{extra_pressure: N, pan_force: N}}
            """), "extra_pressure") + si(write(f"""\
            id: d
            kind: edge_runner
            given: {{{body}, path_radius: {R} m, shaft_speed: 5 rad/s}}
            find: {{pan_force: N}}
            """, "q.yaml"), "pan_force")
    assert pan(0.3, J="1e-12 kg*m^2") == pytest.approx([0.0, 2 * 9.81], abs=1e-9)
    # the uniform disk: M b Omega^2 / 2 at any path radius
    for R in (0.3, 1.0, 5.0):
        assert pan(R) == pytest.approx([2 * 0.1 * 25 / 2, 2 * 9.81 + 2.5], rel=1e-12)


def test_item10_edge_runner_us_data(problems_dir):
    m = 1000 * LBF / G_US
    J = m * (1.5 * FT) ** 2
    Omega = 20 * RPM
    P = J * Omega ** 2 / (2 * FT)
    path = problems_dir / "edge_runner_us_muller.yaml"
    assert si(path, "extra_pressure")[0] == pytest.approx(P, rel=1e-9)
    assert P / LBF == pytest.approx(153.3, abs=0.1)


@pytest.mark.parametrize("given, key", [
    ("{mass: 2 kg, shape: disk, radius: 0.1 m, shaft_speed: 5 rad/s}", "path_radius"),
    ("{mass: 2 kg, k_axial: 0.1 m, path_radius: 1 m, shaft_speed: 5 rad/s}", "radius"),
    ("{mass: 2 kg, shape: disk, radius: 0.1 m, path_radius: -1 m, shaft_speed: 5 rad/s}",
     "path_radius"),
    ("{mass: 2 kg, shape: disk, radius: 0.1 m, path_radius: 1 m, shaft_speed: 5 rad/s, "
     "rollers: 1.5}", "rollers"),
])
def test_item10_edge_runner_bad_input_is_one_line(run, write, given, key):
    path = write(f"""\
        id: bad
        kind: edge_runner
        given: {given}
        find: {{extra_pressure: N}}
        """)
    result = run("solve", path)
    assert result.exit_code == 2, result.output
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and key in lines[0], result.stderr


# ---- item 10: the aeroplane in a loop -------------------------------------------------

def effect_of_reactive(reactive: np.ndarray) -> str:
    """The books' words, read from where a small rotation by the reactive couple takes
    the nose (x) and the left wingtip (y)."""
    nose = rot(reactive, 1e-3) @ X if np.linalg.norm(reactive) else X
    if abs(nose[1]) > abs(nose[2]):
        return "turns the nose to the left" if nose[1] > 0 else "turns the nose to the right"
    return "raises the nose and dips the tail" if nose[2] > 0 else \
        "dips the nose and raises the tail"


def spin_from_words(sense: str) -> np.ndarray:
    """'clockwise seen from the rear' moves the top of the disc to the observer's right;
    the observer at the rear looks forward (+x), his right is -y."""
    clockwise = not sense.startswith(("anti", "counter"))
    from_rear = "rear" in sense
    look = X if from_rear else -X
    right = np.cross(look, Z)            # the observer's right, looking along `look`
    top_velocity = right if clockwise else -right
    # omega x (r z) = top_velocity  ->  omega along z x top_velocity / r
    return np.cross(Z, top_velocity)


@pytest.mark.parametrize("name, expected_C", [
    ("aeroplane_loop_hang_glider.yaml", (50 * LBF / G_US) * (1.5 * FT) ** 2 * 1000 * RPM
     * (40 * 0.44704) / (100 * FT)),
    ("aeroplane_pull_out_of_dive.yaml", 80 * 0.25 * 2000 * RPM * 100 / 400),
    ("aeroplane_outside_loop.yaml", 400 * 0.09 * 2400 * RPM * (250 / 3.6) / 150),
])
def test_item10_loops_by_hand_and_by_vectors(problems_dir, name, expected_C):
    import yaml

    path = problems_dir / name
    data = yaml.safe_load(path.read_text())
    got = answers(path)
    assert got["couple"].si_values[0] == pytest.approx(expected_C, rel=1e-9)
    # the direction: H(t) carried round the loop by pitching about the lateral axis
    s = spin_from_words(data["given"]["rotor_sense"])
    J_omega = 1.0
    rising = "outside" not in data["given"].get("nose", "")
    q = 0.3 if rising else -0.3           # nose up: x toward z, a rotation about -y

    def H(t: float) -> np.ndarray:
        return rot(-Y, q * t) @ (J_omega * s)

    reactive = -ddt(H)
    assert got["effect"].si_values[0] == effect_of_reactive(reactive) == data["expected"]["effect"]


def test_item10_loop_and_turn_keys_do_not_mix(run, write):
    path = write("""\
        id: bad
        kind: aeroplane
        given: {mass: 80 kg, k_axial: 0.5 m, spin: 2000 rpm, speed: 100 m/s,
                motion: loop, turn_radius: 400 m}
        find: {couple: N*m}
        """)
    result = run("solve", path)
    assert result.exit_code == 2
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and "turn_radius" in lines[0]


# ---- item 10: a ship's stabiliser gyro -------------------------------------------------

def vertical_spin(sense: str) -> np.ndarray:
    """'clockwise seen from above': the observer looks down (-z) with the bow at the top of
    his view; his right is look x up = -y (starboard). Clockwise, the rotor's front edge
    (at +x) moves to his right, and omega follows from v = omega x r at that edge."""
    clockwise = not sense.startswith(("anti", "counter"))
    look = -Z if ("above" in sense or "top" in sense) else Z
    right = np.cross(look, X)
    velocity = right if clockwise else -right
    return np.cross(X, velocity)


def test_vertical_spin_from_words_is_the_right_hand_rule():
    # clockwise seen from above points down (away from the observer); from below, up
    assert vertical_spin("clockwise from above") @ Z < 0
    assert vertical_spin("anticlockwise from above") @ Z > 0
    assert vertical_spin("clockwise from below") @ Z > 0


@pytest.mark.parametrize("name, sense, top", [
    ("ship_stabiliser_hospital_ship.yaml", "clockwise from above", "forward"),
    ("ship_stabiliser_axle_aft.yaml", "clockwise from below", "aft"),
    ("ship_stabiliser_rolling_couple.yaml", "anticlockwise from above", "forward"),
])
def test_item10_stabilisers_by_vectors(problems_dir, name, sense, top):
    """H(t): the vertical spin vector tipped about the athwartship axis y (the top moving
    forward is a rotation about +y); the hull feels -dH/dt; a roll to port is undone by a
    couple about +x (lifting the port side)."""
    s = vertical_spin(sense)
    q = 0.1 if top == "forward" else -0.1

    def H(t: float) -> np.ndarray:
        return rot(Y, q * t) @ s

    reactive = -ddt(H)
    lifts = "port" if reactive @ X > 0 else "starboard"
    got = answers(problems_dir / name)
    if "effect" in got:
        other = "starboard" if lifts == "port" else "port"
        assert got["effect"].si_values[0] == f"lifts the {lifts} side and dips the {other}"
    if "axle_top" in got:
        import yaml

        roll = yaml.safe_load((problems_dir / name).read_text())["given"]["roll"]
        assert got["axle_top"].si_values[0] == top
        assert roll.endswith(lifts)        # the couple lifts the side the ship rolls to


def test_item10_hospital_ship_by_hand(problems_dir):
    J, omega, q = 80000 * 1.45 ** 2, 960 * RPM, 0.320
    assert J * omega * q == pytest.approx(5.411e6, rel=1e-3)
    assert si(problems_dir / "ship_stabiliser_hospital_ship.yaml", "couple")[0] == \
        pytest.approx(J * omega * q, rel=1e-12)
    J2, w2 = 20000 * 1.0, 1200 * RPM
    assert si(problems_dir / "ship_stabiliser_rolling_couple.yaml", "precession")[0] == \
        pytest.approx(5e5 / (J2 * w2), rel=1e-12)


@pytest.mark.parametrize("extra, key", [
    ("rotor_sense: clockwise from the stern, precession: 0.3 rad/s", "rotor_sense"),
    ("gyro_sense: clockwise from above", "precession"),
    ("gyro_sense: clockwise from above, precession: 0.3 rad/s, rolling_couple: 1 kN*m",
     "rolling_couple"),
])
def test_item10_stabiliser_bad_input_is_one_line(run, write, extra, key):
    path = write(f"""\
        id: bad
        kind: ship
        given: {{mass: 80 Mg, k_axial: 1.45 m, spin: 960 rpm, motion: stabilising, {extra}}}
        find: {{couple: N*m}}
        """)
    result = run("solve", path)
    assert result.exit_code == 2, result.output
    lines = [line for line in result.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and key in lines[0], result.stderr


def test_item10_stabiliser_key_outside_its_motion_is_refused(run, write):
    path = write("""\
        id: bad
        kind: ship
        given: {mass: 8 t, k_axial: 0.6 m, spin: 1800 rpm, speed: 10 m/s, turn_radius: 75 m,
                gyro_sense: clockwise from above}
        find: {couple: N*m}
        """)
    result = run("solve", path)
    assert result.exit_code == 2 and "gyro_sense" in result.stderr


# ---- item 10: the turbine rotor in a pitching ship (already stateable) -------------------

def test_item10_turbine_rotor_pitching_8t_by_hand(problems_dir):
    # Khurmi's 8 t rotor: 12 deg in all is an amplitude of 6 deg; period 20 s
    J, omega = 8000 * 0.6 ** 2, 1800 * RPM
    wp_max = math.radians(12) / 2 * 2 * math.pi / 20
    C = J * omega * wp_max
    assert C == pytest.approx(17860, abs=5)
    path = problems_dir / "ship_pitching_8t_total_12deg.yaml"
    assert si(path, "couple")[0] == pytest.approx(C, rel=1e-12)
    # bow rising, clockwise from the stern (H forward): H(t) = R(-y, q t) H0
    def H(t: float) -> np.ndarray:
        return rot(-Y, 0.03 * t) @ X

    reactive = -ddt(H)
    assert reactive @ Z < 0  # about -z: turns the ship to starboard
    assert answers(path)["effect"].si_values[0] == "turns the ship to starboard"


# ---- item 7: signed pairs as books print them, sizes with words -------------------------

# Irodov 1.299's turbine: J = 240 kg m^2 at 1500 rpm, a 250 m curve at 50 km/h, rails 1.5 m
# apart: M = J omega v / R, shared by the rails as +M / L and -M / L
IRODOV_RAIL = 240 * 1500 * RPM * (50 / 3.6) / 250 / 1.5     # about 1396 N


def rails(tmp_path: Path, expected: str) -> Path:
    path = tmp_path / "rails.yaml"
    path.write_text(textwrap.dedent("""\
        id: rails
        kind: gyroscopic_torque
        given: {J: 240 kg*m^2, spin: 1500 rpm, speed: 50 km/h, turn_radius: 250 m,
                bearing_spacing: 1.5 m}
        find: {couple_forces: kN}
        tolerance: 1%
        """) + f"expected:\n  couple_forces: {expected}\n")
    return path


def test_item07_sizes_with_words_pass_in_any_order(tmp_path):
    assert IRODOV_RAIL == pytest.approx(1396.3, abs=0.1)
    size = f"{IRODOV_RAIL / 1000:.4g} kN"
    for expected in (f"[{size} up at A, {size} down at B]",
                     f"[{size} down at B, {size} up at A]",       # the book's order
                     f"[{size} pressed at A, {size} relieved at B]",
                     f"['{size}, A, upwards', 'B: {size} downwards']"):
        result = check.check_file(str(rails(tmp_path, expected)))
        assert result.status == "pass", (expected, [a.message for a in result.answers])


def test_item07_words_against_gyro_name_the_convention_not_the_order(tmp_path):
    size = f"{IRODOV_RAIL / 1000:.4g} kN"
    result = check.check_file(str(rails(tmp_path, f"[{size} down at A, {size} up at B]")))
    assert result.status == "fail"
    for answer in result.answers:
        assert answer.slip is not None and "the order" not in answer.slip
        assert "sign convention for couple_forces" in answer.slip
        assert "upward on the rotor positive" in answer.slip
    assert "gyro finds it up" in result.answers[0].slip


def test_item07_a_plain_size_pair_offers_the_words(tmp_path):
    size = f"{IRODOV_RAIL / 1000:.4g} kN"
    result = check.check_file(str(rails(tmp_path, f"[{size}, {size}]")))
    first, second = result.answers
    assert first.passed and not second.passed
    assert "the order" not in second.slip
    assert "sign convention for couple_forces" in second.slip
    assert f"`{size} down at B`" in second.slip


def test_item07_khurmi_reactions_upwards_and_downwards(problems_dir):
    # Khurmi Example 14.2, by hand: I = m r^2 / 2, C = I omega omega_p, shares C / x and m g / 2
    I = 5 * 0.075 ** 2 / 2
    C = I * 1000 * RPM * 60 * RPM
    up_A, down_B = C / 0.1 + 5 * 9.81 / 2, C / 0.1 - 5 * 9.81 / 2
    assert (up_A, down_B) == pytest.approx((117.05, 68.00), abs=0.01)
    path = problems_dir / "khurmi_disc_bearings_in_words.yaml"
    assert si(path, "bearing_forces") == pytest.approx([up_A, -down_B], rel=1e-9)
    result = check.check_file(str(path))
    assert result.status == "pass"
    assert [a.expected_si for a in result.answers[:2]] == pytest.approx([116.5, -67.5])


def test_item07_wheels_named_by_words_in_any_order(tmp_path, problems_dir):
    import yaml

    source = problems_dir / "four_wheeler_trolley_2700kg.yaml"
    data = yaml.safe_load(source.read_text())
    outer, inner = data["expected"]["wheel_reactions"]
    data["expected"]["wheel_reactions"] = [f"{inner} inner", f"{outer} outer"]
    path = tmp_path / "w.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    assert check.check_file(str(path)).status == "pass"
    data["expected"]["wheel_reactions"] = [f"{inner} outer", f"{outer} inner"]
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    result = check.check_file(str(path))
    assert result.status == "fail"
    assert result.answers[0].slip.startswith("the place: ")


@pytest.mark.parametrize("expected, words", [
    ("[1.4 kN up down at A, 1.4 kN at B]", "both signs"),
    ("[-1.4 kN down at A, 1.4 kN up at B]", "not both"),
    ("[1.4 kN up at A, 1.4 kN down at A]", "both at A"),
    ("[1.4 kN up at A, 1.4 kN down]", "of every value"),
    ("[1.4 kN, outer rail pressed]", "words this answer reads"),
    ("[1.4 kN sideways at A, 1.4 kN at B]", "words this answer reads"),
])
def test_item07_bad_words_are_one_line_exit_2(tmp_path, expected, words):
    out = CliRunner().invoke(main, ["check", str(rails(tmp_path, expected))])
    assert out.exit_code == 2, out.output
    lines = [line for line in out.stderr.splitlines() if line.strip()]
    assert len(lines) == 1 and words in lines[0] and "expected.couple_forces" in lines[0], \
        out.stderr


def test_item07_a_place_named_in_part_is_refused(tmp_path, problems_dir):
    import yaml

    data = yaml.safe_load((problems_dir / "four_wheeler_racing_car_flywheel.yaml").read_text())
    data["expected"] = {"wheel_loads": ["6310.7 N outer", "3340.2 N inner",
                                        "6659.8 N outer", "3689.3 N inner"]}
    path = tmp_path / "car.yaml"
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    out = CliRunner().invoke(main, ["check", str(path)])
    assert out.exit_code == 2
    assert "front outer or rear outer" in out.stderr
    data["expected"] = {"wheel_loads": ["6310.7 N front outer", "3340.2 N front inner",
                                        "3689.3 N rear inner", "6659.8 N rear outer"]}
    path.write_text(yaml.safe_dump(data, sort_keys=False))
    assert check.check_file(str(path)).status == "pass"
