"""Problems as other books state them, round three (issue 23).

Each test writes the book's data as printed and checks gyro's answer against a
derivation by hand written out here (or an independent method: bisection on a
residual, a balance of moments), never against gyro's own formula.
"""

from __future__ import annotations

import math

import pytest

from gyro_cli.solving.solve import solve_file

RPM = 2 * math.pi / 60


def _unstated(path) -> str:
    """A bundled problem's text without its statement (placed last in the file), whose
    {key}s would name keys the test takes out of `given`."""
    return path.read_text().split("\nstatement:")[0] + "\n"


def si(path, name):
    return solve_file(str(path)).answers[name].si_values


def _bisect(f, lo, hi, n=200):
    """A root of f in [lo, hi] by bisection (f changes sign there)."""
    for _ in range(n):
        mid = (lo + hi) / 2
        if (f(lo) < 0) == (f(mid) < 0):
            lo = mid
        else:
            hi = mid
    return (lo + hi) / 2


# ---- item 1: steady_precession without theta ------------------------------

def test_giancoli_toy_gyroscope_without_an_angle(problems_dir):
    # Giancoli 11-41: 170 g disk, r = 5.5 cm, centre 21/2 cm from the stand, 45 rev/s.
    m, r, l, g = 0.170, 0.055, 0.105, 9.80
    J = m * r * r / 2                            # 2.571e-4 kg m^2, a uniform disk
    omega = 45 * 2 * math.pi                     # 282.7 rad/s
    torque = m * g * l                           # 0.1749 N m, the axle horizontal
    L_horizontal = J * omega                     # 0.07270 kg m^2/s
    Omega = torque / L_horizontal                # dL/dt = torque: 2.406 rad/s
    T = 2 * math.pi / Omega
    assert T == pytest.approx(2.611, abs=1e-3)   # the book: 2.6 s
    result = solve_file(str(problems_dir / "toy_gyroscope_no_angle.yaml"))
    assert result.answers["precession_approx"].si_values == [pytest.approx(Omega, rel=1e-9)]
    assert result.answers["precession_period"].si_values == [pytest.approx(T, rel=1e-9)]
    assert result.answers["precession_period"].labels == ["approximation"]
    warning = " ".join(result.solution.warnings)
    assert "no theta given" in warning and "need theta" in warning


def test_without_theta_the_warning_says_how_far_the_exact_root_moves(problems_dir):
    # The exact slow root at 30 deg, found by bisection on the moment balance
    # dH/dt = phidot sin(th) (J omega_z - I phidot cos(th)) = m g l sin(th),
    # omega_z = psidot + phidot cos(th), I about the stand by parallel axes.
    m, r, l, g = 0.170, 0.055, 0.105, 9.80
    J, I = m * r * r / 2, m * r * r / 4 + m * l * l
    psidot, th = 45 * 2 * math.pi, math.radians(30)

    def residual(phidot):
        omega_z = psidot + phidot * math.cos(th)
        return phidot * math.sin(th) * (J * omega_z - I * phidot * math.cos(th)) \
            - m * g * l * math.sin(th)

    slow30 = _bisect(residual, 0.0, 10.0)
    at90 = m * g * l / (J * psidot)              # exact at 90 deg
    assert slow30 == pytest.approx(2.540, abs=1e-3)
    warning = " ".join(solve_file(str(problems_dir / "toy_gyroscope_no_angle.yaml"))
                       .solution.warnings)
    assert f"{slow30:.3f} rad/s at 30 deg" in warning
    assert f"{abs(slow30 - at90) / at90 * 100:.2g}% apart" in warning


def test_without_theta_a_spin_for_a_precession_and_no_inertia(write):
    # Young and Freedman's toy gyroscope turned round: one turn in 2.20 s, what spin?
    # m g l = J omega Omega -> omega = m g l / (J Omega).
    m, g, l, J = 0.165, 9.80, 0.0400, 1.20e-4
    Omega = 2 * math.pi / 2.20
    omega = m * g * l / (J * Omega)
    assert omega / RPM == pytest.approx(1802.5, abs=0.5)
    path = write("""\
        id: x
        kind: steady_precession
        given: {mass: 165 g, J: 1.20e-4 kg m^2, cg_distance: 4.00 cm, g: 9.80 m/s^2,
                precession: 0.4545 rev/s}
        find: {spin: rpm}
        """)
    result = solve_file(str(path))
    assert result.answers["spin"].si_values == [pytest.approx(omega, rel=1e-3)]
    assert result.answers["spin"].labels == ["approximation"]
    assert any("transverse inertia I" in w for w in result.solution.warnings)


@pytest.mark.parametrize("find", ["cg_speed", "pivot_force", "min_spin", "precession_slow",
                                  "moment", "axial_rate"])
def test_without_theta_answers_that_need_it_are_refused_in_one_line(run, write, find):
    path = write(f"""\
        id: x
        kind: steady_precession
        given: {{mass: 170 g, shape: disk, radius: 5.5 cm, cg_distance: 10.5 cm,
                spin: 45 rev/s}}
        find: {{precession: rad/s, {find}: null}}
        """)
    out = run("solve", path)
    assert out.exit_code == 2, out.stdout
    assert out.stderr.count("\n") == 1 and "given.theta" in out.stderr
    assert "Traceback" not in out.stderr


# ---- item 11: gyroscopic_torque without a mass; spin from speed; tilt from a drop ----

def test_irodov_turbine_rail_force_without_a_mass(problems_dir):
    # Irodov 1.299: F = 2 pi n I v / (l R), the couple I omega Omega shared by two rails l apart.
    I, n, v, R, l = 240.0, 1500 / 60, 50 / 3.6, 250.0, 1.5
    F = 2 * math.pi * n * I * v / (l * R)
    assert F == pytest.approx(1396, abs=1)       # the book: 1.4 kN
    result = solve_file(str(problems_dir / "irodov_turbine_locomotive.yaml"))
    assert result.answers["bearing_forces"].si_values == [pytest.approx(F, rel=1e-9),
                                                          pytest.approx(-F, rel=1e-9)]
    assert result.answers["bearing_forces"].labels == ["A", "B"]
    assert any("couple's share alone" in w for w in result.solution.warnings)


def test_khurmi_wheel_drop_harmonic(problems_dir):
    # The wheel falls 6 mm and rises in 0.1 s, y = 3 mm (1 - cos(2 pi t / 0.1 s)):
    # its greatest speed 3 mm x 62.83 rad/s = 0.1885 m/s tilts the 1.5 m axle at 0.1257 rad/s.
    J, v, r_w, L = 180.0, 95 / 3.6, 0.9, 1.5
    spin = v / r_w                               # 29.32 rad/s, rolling without slip
    tilt = 0.003 * (2 * math.pi / 0.1) / L
    C = J * spin * tilt                          # the couple that turns H = J spin at tilt
    assert C == pytest.approx(663.3, abs=0.2)    # the book: 663 N m
    result = solve_file(str(problems_dir / "khurmi_wheel_drop.yaml"))
    assert result.answers["moment"].si_values == [pytest.approx(C, rel=1e-9)]
    assert result.answers["precession"].si_values == [pytest.approx(tilt, rel=1e-9)]
    assert result.answers["couple_forces"].si_values == [pytest.approx(C / L, rel=1e-9),
                                                         pytest.approx(-C / L, rel=1e-9)]


def test_a_wheel_drops_the_couple_is_about_the_vertical_and_its_forces_along_the_track(write):
    # Axes: x along the track, y the axle (A to B), z up. The drop tilts the axle about x at
    # Omega, so dH/dt = Omega x_hat x (J spin y_hat) = J spin Omega z_hat: a couple about the
    # vertical, whose forces at the wheels (L apart along y) lie along x, the track. The
    # weight (along -z) is across them: with the mass given they are still +-M / L, and
    # nothing says the couple loads or relieves a rail.
    import numpy as np

    from gyro_cli.render import report

    J, spin, Omega, L, m = 180.0, 95 / 3.6 / 0.9, 0.003 * (2 * math.pi / 0.1) / 1.5, 1.5, 2000.0
    dH = np.cross([Omega, 0, 0], [0, J * spin, 0])
    assert dH[0] == dH[1] == 0 and dH[2] == pytest.approx(663.23, abs=0.01)
    force = dH[2] / L                            # each wheel's, along the track
    path = write(f"""\
        id: x
        kind: gyroscopic_torque
        given: {{J: 180 kg m^2, speed: 95 km/h, wheel_radius: 0.9 m, drop: 6 mm,
                drop_time: 0.1 s, bearing_spacing: 1.5 m, supported_mass: {m} kg}}
        find: {{moment: N m, couple_forces: N, bearing_forces: N}}
        """)
    result = solve_file(path)
    for key in ("couple_forces", "bearing_forces"):   # 10,250 N had been printed: + weight
        assert result.answers[key].si_values == [pytest.approx(force, rel=1e-9),
                                                 pytest.approx(-force, rel=1e-9)]
    text = report.text(result)
    assert "(down)" not in text and "couple about the vertical" in text
    assert "relieved" not in text and "one side is pushed forward and the other back" in text
    assert "the weight (vertical) not among them" in text


def test_a_wheel_drop_refuses_loads_that_need_a_vertical_precession_axis(run, write):
    path = write("""\
        id: x
        kind: gyroscopic_torque
        given: {J: 180 kg m^2, spin: 30 rad/s, drop: 6 mm, drop_time: 0.1 s,
                bearing_spacing: 1.5 m, mass: 2000 kg}
        find: {bearing_loads: N}
        """)
    out = run("solve", path)
    assert out.exit_code == 2 and out.stderr.count("\n") == 1, out.stderr
    assert "find.bearing_loads" in out.stderr and "ask couple_forces" in out.stderr


def test_wheel_drop_over_a_length_at_a_speed(write):
    # Rail wheels (J = 2 kg m^2 each pair), r_w = 0.5 m at 72 km/h; one wheel drops 10 mm
    # over 2 m of track, gauge 1.5 m. The drop lasts 2 / 20 = 0.1 s, the axle turns through
    # 0.010 / 1.5 rad in it: Omega = 0.06667 rad/s; spin = 20 / 0.5 = 40 rad/s;
    # M = 2 x 40 x 0.06667 = 5.333 N m.
    path = write("""\
        id: x
        kind: gyroscopic_torque
        given: {J: 2 kg m^2, speed: 72 km/h, wheel_radius: 0.5 m, drop: 10 mm,
                drop_length: 2 m, bearing_spacing: 1.5 m}
        find: {moment: N m, precession: rad/s}
        """)
    assert si(path, "precession") == [pytest.approx(0.010 / 1.5 / 0.1, rel=1e-9)]
    assert si(path, "moment") == [pytest.approx(2 * 40 * 0.010 / 1.5 / 0.1, rel=1e-9)]


@pytest.mark.parametrize("given, key", [
    ("mass: 0 kg, J: 240 kg m^2, spin: 1500 rpm, precession: 0.05 rad/s", "given.mass"),
    ("J: 240 kg m^2, spin: 1500 rpm, precession: 0.05 rad/s, bearing_spacing: 1.5 m",
     "given.mass"),
    ("J: 180 kg m^2, spin: 30 rad/s, drop: 6 mm, bearing_spacing: 1.5 m", "given.drop_length"),
    ("J: 180 kg m^2, wheel_radius: 0.9 m, precession: 0.1 rad/s", "given.speed"),
    ("J: 180 kg m^2, spin: 30 rad/s, speed: 10 m/s", "given.turn_radius"),
])
def test_gyroscopic_torque_least_data_refusals_are_one_line(run, write, given, key):
    find = "bearing_loads: N" if "bearing_spacing: 1.5 m}" in given or "0.05 rad/s, b" in \
        given else "moment: N m"
    path = write(f"id: x\nkind: gyroscopic_torque\ngiven: {{{given}}}\nfind: {{{find}}}\n")
    out = run("solve", path)
    assert out.exit_code == 2, out.stdout
    assert out.stderr.count("\n") == 1 and key in out.stderr, out.stderr
    if key == "given.mass" and "mass: 0" in given:
        assert "leave mass out" in out.stderr


# ---- item 5: the books' own words; a suggestion never flips a meaning ------------

SHIP = """\
id: x
kind: ship
given: {mass: 2.2 t, k_axial: 320 mm, spin: 1800 rpm, rotor_sense: %s,
        speed: 25 km/h, turn_radius: 250 m, turn: %s}
find: {couple: N*m, effect: null}
"""


def _cross(a, b):
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def _steering_effect(H_forward: bool, turn_left: bool) -> str:
    """By hand: ship axes x forward, y to port, z up; the ship feels -(omega_p x H).
    About +y the couple carries x (the bow) toward -z: it lowers the bow."""
    H = (1.0 if H_forward else -1.0, 0.0, 0.0)
    wp = (0.0, 0.0, 1.0 if turn_left else -1.0)
    on_ship = [-c for c in _cross(wp, H)]
    return "lowers the bow" if on_ship[1] > 0 else "raises the bow"


@pytest.mark.parametrize("sense, forward", [
    ("anticlockwise_from_stern", False), ("anticlockwise from stern", False),
    ("counter-clockwise from the stern", False), ("counterclockwise seen from aft", False),
    ("Anti-clockwise when viewed from the rear", False), ("clockwise from aft", True),
    ("clockwise when viewed from the aft", True), ("clockwise from the bow", False),
    ("anticlockwise from the bow", True), ("anticlockwise from the front", True),
    ("clockwise_from_stern", True),
])
@pytest.mark.parametrize("turn, left", [("port", True), ("starboard", False), ("left", True),
                                        ("to starboard", False)])
def test_ship_words_as_books_print_them(write, sense, forward, turn, left):
    # Seen from the stern the observer looks forward: clockwise points forward
    # (right-hand rule); seen from the bow, clockwise points aft.
    result = solve_file(str(write(SHIP % (sense, turn))))
    assert _steering_effect(forward, left) in result.answers["effect"].si_values[0]


def test_bundled_6000kg_problem_in_its_own_words(problems_dir):
    text = _unstated(problems_dir / "ship_pitching_6000kg.yaml")
    assert "bow: descending" in text and "anticlockwise viewed from the bow" in text
    # anticlockwise from the bow = clockwise from the stern: H forward (+x); the bow falling
    # is a rotation about +y; omega_p x H = y x x = -z on the rotor, +z on the ship: to port.
    H, wp = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)
    assert [-c for c in _cross(wp, H)][2] > 0
    assert si(problems_dir / "ship_pitching_6000kg.yaml", "effect") == ["turns the ship to port"]


@pytest.mark.parametrize("bow, word", [("descending", "falling"), ("ascending", "rising"),
                                       ("rising", "rising"), ("falling", "falling")])
def test_ship_bow_words(write, bow, word):
    text = (SHIP % ("clockwise_from_stern", "left")).replace(
        "speed: 25 km/h, turn_radius: 250 m, turn: left", f"motion: pitching, "
        f"pitch_rate: 0.8 rad/s, bow: {bow}")
    result = solve_file(str(write(text)))
    # bow rising: rotation about -y; omega_p x H = (-y) x (+x) = +z on the rotor, -z on the
    # ship: starboard. Falling: port.
    assert result.answers["effect"].si_values == [
        "turns the ship to starboard" if word == "rising" else "turns the ship to port"]


@pytest.mark.parametrize("text, refused", [
    ("anticlockwize_from_stern", "clockwise_from_stern'"), ("clockwise", "from_"),
    ("anticlockwise", "'clockwise"), ("counterclockwise_from_stirn", "'clockwise"),
])
def test_a_suggestion_never_flips_a_meaning(run, write, text, refused):
    out = run("solve", write(SHIP % (text, "left")))
    assert out.exit_code == 2 and out.stderr.count("\n") == 1
    assert f"did you mean {refused}" not in out.stderr and "Traceback" not in out.stderr
    if "did you mean" in out.stderr:
        assert "counterclockwise" in out.stderr.split("did you mean")[1]


def test_no_suggestion_of_any_word_key_flips_a_choice():
    """Every word key of every kind: a one-letter slip in a choice, or the choice with its
    opposite's prefix swapped in, is never answered with the opposite choice."""
    from gyro_cli.core.params import flips, read_word, safe_choices

    opposite = {"clockwise": "anticlockwise", "left": "right", "rising": "falling",
                "stern": "bow", "rear": "front", "same": "opposite"}
    from gyro_cli.core.body import BODY_PARAMS
    from gyro_cli.kinds import get, names

    for name in names():
        for param in get(name).params + BODY_PARAMS:
            for choice in param.choices:
                assert read_word(param, choice) == choice
                for i in range(1, len(choice) - 1):
                    slip = choice[:i] + choice[i + 1:]
                    assert all(not flips(choice, c) for c in safe_choices(slip, param.choices))
                for word, other in opposite.items():
                    if word in choice.split("_") and other not in choice:
                        swapped = choice.replace(word, other)
                        assert choice not in safe_choices(swapped, param.choices), swapped


def test_the_docs_list_every_spelling_a_kind_accepts():
    """Every other spelling a kind's word key accepts is listed in docs/real_problems.md,
    and each one the page lists is read as the page says."""
    import re
    from pathlib import Path

    from gyro_cli.core.body import BODY_PARAMS
    from gyro_cli.core.params import normal_word, read_word
    from gyro_cli.kinds import get, names

    doc = (Path(__file__).resolve().parent.parent / "docs" / "real_problems.md").read_text()
    section = doc.split("## Words as the books print them")[1].split("\n## ")[0]
    rows = re.findall(r"^\| `(\w+)` \| (.+?) \| `(.+?)` \|$", section, re.M)
    assert rows
    listed = set()
    params = {p.name: p for p in BODY_PARAMS}
    for name in ("aeroplane", "directional_gyro", "four_wheeler", "ship", "torque_free"):
        params.update({p.name: p for p in get(name).params})
    for key, written, reading in rows:
        for word in re.findall(r"`([^`]+)`", written):
            for turn in ("clockwise", "counterclockwise"):
                text, want = word.replace("...", turn), reading.replace("...", turn)
                assert read_word(params[key], text) == want, (key, text, want)
                listed.add(normal_word(text))
    for name in names():
        for param in get(name).params + BODY_PARAMS:
            for spelling, _ in param.words:
                assert spelling in listed, (name, param.name, spelling)


# ---- item 6: pitching as the books give it -----------------------------------

def test_khurmi_pitching_between_the_extremes(problems_dir):
    # 12 deg between the extremes is an amplitude of 6 deg from the mean position.
    J, omega = 3500 * 0.45 ** 2, 3000 * RPM                 # 708.75 kg m^2, 314.16 rad/s
    phi, w1 = math.radians(12) / 2, 2 * math.pi / 40
    # theta = phi sin(w1 t): its rate phi w1 cos(w1 t) is greatest at the mean position
    rate = phi * w1
    C = J * omega * rate
    assert C == pytest.approx(3663, abs=1)                 # the book: 3.66 kN m
    path = problems_dir / "ship_pitching_3500kg_extremes.yaml"
    assert si(path, "couple") == [pytest.approx(C, rel=1e-9)]
    assert si(path, "max_precession") == [pytest.approx(rate, rel=1e-9)]


SHIP_PITCH = """\
id: x
kind: ship
given: {mass: 3500 kg, k_axial: 0.45 m, spin: 3000 rpm, rotor_sense: clockwise_from_stern,
        motion: pitching, bow: falling, %s}
find: {couple: N*m}
"""


@pytest.mark.parametrize("keys", [
    "amplitude: 6 deg, period: 40 s", "pitch_amplitude: 6 deg, period: 40 s",
    "pitch_total: 12 deg, period: 40 s", "between_extremes: 12 deg, frequency: 0.025 Hz",
    "amplitude: 6 deg, frequency: 0.15708 rad/s",
])
def test_pitching_amplitude_swing_period_or_frequency(write, keys):
    C = 3500 * 0.45 ** 2 * 3000 * RPM * math.radians(6) * 2 * math.pi / 40
    assert si(write(SHIP_PITCH % keys), "couple") == [pytest.approx(C, rel=1e-4)]


@pytest.mark.parametrize("keys, key", [
    ("amplitude: 6 deg, pitch_total: 12 deg, period: 40 s", "given.pitch_total"),
    ("period: 40 s, frequency: 0.025 Hz, amplitude: 6 deg", "given.frequency"),
    ("period: 40 s", "given.amplitude"),
])
def test_pitching_keys_refused_in_one_line(run, write, keys, key):
    out = run("solve", write(SHIP_PITCH % keys))
    assert out.exit_code == 2 and out.stderr.count("\n") == 1 and key in out.stderr


# ---- item 7: a ship's turning rate; a vehicle's weight; wheels by mass and k -----

@pytest.mark.parametrize("rate, turn", [("0.1 rad/s", "left"), ("5.7296 deg/s", "port"),
                                        ("0.1 rad/s", "starboard")])
def test_ship_steering_from_a_turning_rate(write, rate, turn):
    # Khurmi's 3500 kg rotor (k = 0.45 m, 3000 rpm clockwise from the stern) at 36 km/h on a
    # 100 m curve turns at 10 / 100 = 0.1 rad/s: C = 708.75 x 314.16 x 0.1 = 22.27 kN m;
    # left: raises the bow (H forward, omega_p up: z x x = +y on the rotor, -y on the ship).
    path = write(f"""\
        id: x
        kind: ship
        given: {{mass: 3500 kg, k_axial: 0.45 m, spin: 3000 rpm,
                rotor_sense: clockwise_from_stern, turn_rate: {rate}, turn: {turn}}}
        find: {{couple: N*m, effect: null}}
        """)
    result = solve_file(str(path))
    assert result.answers["couple"].si_values == [pytest.approx(708.75 * 3000 * RPM * 0.1,
                                                                rel=1e-4)]
    left = turn in ("left", "port")
    assert _steering_effect(True, left) in result.answers["effect"].si_values[0]


def test_ship_turn_rate_with_speed_is_refused(run, write):
    path = write("""\
        id: x
        kind: ship
        given: {J: 700 kg m^2, spin: 3000 rpm, turn_rate: 0.1 rad/s, speed: 10 m/s}
        find: {couple: N*m}
        """)
    out = run("solve", path)
    assert out.exit_code == 2 and "given.speed" in out.stderr and out.stderr.count("\n") == 1


def test_two_wheeler_by_its_weight_and_wheels_by_mass_and_k(problems_dir, write):
    # The bundled 250 kg machine, stated as "weighs 2452.5 N" with each wheel 10 kg at
    # k = 0.31623 m (I_w = 10 x 0.1 = 1 kg m^2). By hand: omega_w = 25 / 0.3 = 83.33 rad/s,
    # omega_p = 25 / 50 = 0.5 rad/s; C_g = (2 x 1 + 5 x 0.3)(83.33)(0.5) = 145.8 N m;
    # C_c = 250 x 25^2 x 0.6 / 50 = 1875 N m; tan(theta) = 2020.8 / (250 x 9.81 x 0.6).
    text = _unstated(problems_dir / "two_wheeler_250kg.yaml")
    text = text.replace("  mass: 250 kg\n", "  weight: 2452.5 N\n").replace(
        "  wheel_inertia: 1 kg*m^2\n", "  wheel_mass: 10 kg\n  wheel_k: 0.316228 m\n")
    path = write(text)
    C_g = (2 * 1 + 5 * 0.3) * (25 / 0.3) * (25 / 50)
    C_c = 250 * 25 ** 2 * 0.6 / 50
    theta = math.atan((C_g + C_c) / (250 * 9.81 * 0.6))
    assert si(path, "gyroscopic_couple") == [pytest.approx(C_g, rel=1e-5)]
    assert si(path, "centrifugal_couple") == [pytest.approx(C_c, rel=1e-9)]
    assert si(path, "heel_angle") == [pytest.approx(theta, rel=1e-5)]
    assert math.degrees(theta) == pytest.approx(53.94, abs=0.01)


def test_four_wheeler_by_weight_and_axles_by_mass_and_k(problems_dir, write):
    # Khurmi's trolley: each axle with its wheels 200 kg at k = 0.3 m: I = 200 x 0.09 = 18.
    text = _unstated(problems_dir / "four_wheeler_trolley_2500kg.yaml")
    text = text.replace("  mass: 2500 kg\n", "  weight: 24.525 kN\n").replace(
        "  axle_inertia: 18 kg*m^2\n", "  axle_mass: 200 kg\n  axle_k: 0.3 m\n")
    result = solve_file(str(write(text)))
    # outer and inner wheels, re-derived in the bundled file's notes: 7132 N and 5131 N
    assert result.answers["wheel_reactions"].si_values == [pytest.approx(7132, abs=1),
                                                           pytest.approx(5131, abs=1)]


@pytest.mark.parametrize("extra, key", [
    ("  weight: 2452.5 N\n", "given.weight"),                      # with mass too
    ("  wheel_mass: 10 kg\n", "given.wheel_k"),                    # k missing
    ("  wheel_k: 0.3 m\n", "given.wheel_mass"),
])
def test_vehicle_data_refusals(problems_dir, run, write, extra, key):
    text = _unstated(problems_dir / "two_wheeler_250kg.yaml")
    if "wheel" in extra:
        text = text.replace("  wheel_inertia: 1 kg*m^2\n", "")
    path = write(text.replace("  cg_height: 0.6 m\n", "  cg_height: 0.6 m\n" + extra))
    out = run("solve", path)
    assert out.exit_code == 2 and key in out.stderr and out.stderr.count("\n") == 1, out.stderr


# ---- item 8: shapes -----------------------------------------------------------

def _inertias_by_integration(shape: str, m: float, r: float = 0.0, r_i: float = 0.0,
                             w: float = 0.0, L: float = 0.0, n: int = 400):
    """J and I_G of a uniform body by midpoint sums over its volume (or surface), written
    from the definitions J = sum dm (x^2 + y^2), I_G = sum dm (y^2 + z^2), z the axis."""
    import numpy as np

    u = (np.arange(n) + 0.5) / n
    if shape == "shell":        # mass on the surface rho = r, z in [-L/2, L/2], phi uniform
        z = (u - 0.5) * L
        phi = 2 * np.pi * u
        Z, P = np.meshgrid(z, phi)
        x, y = r * np.cos(P), r * np.sin(P)
        return m * np.mean(x ** 2 + y ** 2), m * np.mean(y ** 2 + Z ** 2)
    if shape == "hollow_sphere":  # uniform on the sphere: cos(polar) uniform in [-1, 1]
        c = 2 * u - 1
        phi = 2 * np.pi * u
        C, P = np.meshgrid(c, phi)
        s = np.sqrt(1 - C ** 2)
        x, y, z = r * s * np.cos(P), r * s * np.sin(P), r * C
        return m * np.mean(x ** 2 + y ** 2), m * np.mean(y ** 2 + z ** 2)
    if shape == "box":          # x, y in [-w/2, w/2], z in [-L/2, L/2]
        a = (u - 0.5)
        X, Y, Z = np.meshgrid(a * w, a * w, a[:: max(1, n // 100)] * L, sparse=True)
        J = m * np.mean(X ** 2 + Y ** 2 + 0 * Z)
        return J, m * np.mean(Y ** 2 + Z ** 2 + 0 * X)
    if shape == "annulus":      # area element rho drho dphi dz, rho in [r_i, r]
        rho = r_i + (r - r_i) * u
        z = (u - 0.5) * L
        R, Z = np.meshgrid(rho, z)
        weight = R / R.mean()
        J = m * np.mean(weight * R ** 2)
        I = m * np.mean(weight * (R ** 2 / 2 + Z ** 2))   # <y^2> over phi is rho^2 / 2
        return J, I
    raise ValueError(shape)


@pytest.mark.parametrize("shape, dims, keys", [
    ("shell", dict(r=1.0, L=3.0), "radius: 1 m, length: 3 m"),
    ("hollow_sphere", dict(r=0.2), "radius: 0.2 m"),
    ("box", dict(w=0.3, L=0.5), "width: 0.3 m, length: 0.5 m"),
    ("annulus", dict(r=0.3, r_i=0.1, L=0.2), "radius: 0.3 m, inner_radius: 0.1 m, length: 0.2 m"),
])
def test_new_shapes_against_integration(write, shape, dims, keys):
    J, I_G = _inertias_by_integration(shape, 100.0, **dims)
    path = write(f"""\
        id: x
        kind: steady_precession
        given: {{mass: 100 kg, shape: {shape}, {keys}, cg_distance: 0.5 m, theta: 60 deg,
                spin: 3000 rpm}}
        find: {{precession: rad/s}}
        """)
    text = " ".join(s.as_text() for sec in solve_file(str(path)).solution.sections
                    for s in sec.steps)
    from gyro_cli.core.work import num
    assert "J = " in text
    assert num(J) in text and num(I_G) in text, (J, I_G, text[:400])


def test_curtis_shell_is_prolate_as_a_shell(problems_dir):
    # Curtis 10.2: thin shell r = 1 m, L = 3 m, 100 kg: J = m r^2 = 100, I = m r^2/2 + m L^2/12
    # = 125 kg m^2 > J: prolate, direct precession; omega_p = J psidot / ((I - J) cos(theta)).
    J, I, theta, psidot = 100.0, 125.0, math.radians(20), 2 * math.pi / 60
    precession = J * psidot / ((I - J) * math.cos(theta))
    assert precession * 60 == pytest.approx(26.746, abs=1e-3)     # the book: 26.75 rad/min
    assert si(problems_dir / "torque_free_shell.yaml", "precession") == \
        [pytest.approx(precession, rel=1e-4)]


@pytest.mark.parametrize("shape, keys, key, words", [
    ("ring", "radius: 1 m, length: 3 m", "given.length", "shell"),
    ("disk", "radius: 1 m, length: 3 m", "given.length", "cylinder"),
    ("sphere", "radius: 1 m, inner_radius: 0.5 m", "given.inner_radius", "radius or diameter"),
    ("box", "width: 1 m", "given.length", "width, length"),
    ("annulus", "radius: 1 m", "given.inner_radius", "inner_radius"),
    ("annulus", "radius: 1 m, inner_radius: 1.5 m", "given.inner_radius", "less than"),
])
def test_a_shape_refuses_a_key_it_does_not_use(run, write, shape, keys, key, words):
    path = write(f"""\
        id: x
        kind: torque_free
        given: {{mass: 100 kg, shape: {shape}, {keys}, nutation_angle: 20 deg,
                spin: 1 rad/s}}
        find: {{precession: rad/s}}
        """)
    out = run("solve", path)
    assert out.exit_code == 2 and out.stderr.count("\n") == 1
    assert key in out.stderr and words in out.stderr, out.stderr


# ---- item 9: ordered answers are compared in order -----------------------------

def test_swapped_wheel_reactions_fail_with_the_order_named(problems_dir, run, tmp_path):
    # outer 6131 - 110.6 + 1111 = 7132 N, inner 6131 + 110.6 - 1111 = 5131 N (the file's
    # notes): the key [inner, outer] is the swap a set comparison let pass.
    text = _unstated(problems_dir / "four_wheeler_trolley_2500kg.yaml")
    swapped = tmp_path / "swap.yaml"
    swapped.write_text(text.replace("[7132 N, 5131 N]", "[5131 N, 7132 N]"))
    out = run("check", swapped)
    assert out.exit_code == 1
    assert "the order: 5131 N is the computed inner" in out.stdout
    assert run("check", problems_dir / "four_wheeler_trolley_2500kg.yaml").exit_code == 0


def test_roots_are_still_matched_as_a_set(problems_dir, run, tmp_path):
    # 11/3's two precession rates, keyed fast first: roots have no order.
    text = _unstated(problems_dir / "11_3.yaml")
    import re
    found = re.search(r"precession: \[([^,\]]+), ([^\]]+)\]", text)
    assert found, "11_3.yaml keys both roots"
    swapped = tmp_path / "roots.yaml"
    swapped.write_text(text.replace(found.group(0),
                                    f"precession: [{found.group(2)}, {found.group(1)}]"))
    assert run("check", swapped).exit_code == 0


def test_ordered_and_root_labels():
    from gyro_cli.checking.matching import match_in_order, ordered

    assert ordered(["A", "B"]) and ordered(["outer", "inner"])
    assert ordered(["vertical", "horizontal (slow)", "magnitude (slow)"])
    assert not ordered(["slow", "fast"]) and not ordered([]) and not ordered(["approximation"])
    assert match_in_order(2, 3) == [(0, 0), (1, 1), (None, 2)]
    assert match_in_order(3, 2) == [(0, 0), (1, 1), (2, None)]


# ---- item 12: torque_free in the books' convention; Meriam's ratio n ---------------

def test_oblate_satellite_with_the_books_positive_spin(problems_dir):
    # J / I = 1.6, one precession every 2 s, spin 0.1 rad/s quoted positive (retrograde).
    # Along k: J omega_z = H cos(theta); across: I phidot sin(theta) = H sin(theta), so
    # H = I phidot. The spin relative to the precessing frame has magnitude
    # (J - I) / I omega_z for J > I: omega_z = I p / (J - I) = 0.1 / 0.6 = 0.16667 rad/s.
    J, I, phidot, p = 1.6, 1.0, math.pi, 0.1
    omega_z = I * p / (J - I)
    cos_theta = J * omega_z / (I * phidot)
    assert math.degrees(math.acos(cos_theta)) == pytest.approx(85.131, abs=1e-3)
    path = problems_dir / "torque_free_satellite.yaml"
    assert si(path, "axial_rate") == [pytest.approx(omega_z, rel=1e-9)]
    assert si(path, "spin_ratio") == [pytest.approx(p / phidot, rel=1e-9)]


def test_spin_ratio_signed_without_the_words(write):
    # A disk (J = 2 I), axis 1 deg from H: psidot = (I - J) / I omega_z = -omega_z and
    # phidot = J omega_z / (I cos(theta)) = 2 omega_z / cos(theta): n = -cos(theta) / 2.
    path = write("""\
        id: x
        kind: torque_free
        given: {J: 2 kg m^2, I_cg: 1 kg m^2, axial_rate: 3 rad/s, nutation_angle: 1 deg}
        find: {spin_ratio: null}
        """)
    assert si(path, "spin_ratio") == [pytest.approx(-math.cos(math.radians(1)) / 2, rel=1e-9)]


@pytest.mark.parametrize("given, key, words", [
    ("J: 1.6 kg m^2, I_cg: 1 kg m^2, precession: 0.5 rev/s, spin: 0.1 rad/s",
     "given.spin", "precession_sense: retrograde"),
    ("J: 1.6 kg m^2, I_cg: 1 kg m^2, precession: 0.5 rev/s, spin: 0.1 rad/s, "
     "precession_sense: direct", "given.precession_sense", "oblate"),
])
def test_torque_free_sense_refusals(run, write, given, key, words):
    path = write(f"id: x\nkind: torque_free\ngiven: {{{given}}}\nfind: {{omega: rad/s}}\n")
    out = run("solve", path)
    assert out.exit_code == 2 and out.stderr.count("\n") == 1
    assert key in out.stderr and words in out.stderr, out.stderr


# ---- item 2: rolling_disk, how long for one lap ---------------------------------

def test_coin_rolling_on_a_circle_one_lap(write):
    # A coin (thin disk, J = m r^2 / 2, I_G = m r^2 / 4), r = 1.2 cm, rolling at 0.5 m/s with
    # its centre on... given the contact circle R = 0.4 m and the tilt from the moment
    # balance. Independently: with the tilt gyro finds, rho = R - r sin(beta) and the lap
    # takes the distance round the centre's circle over the speed, 2 pi rho / v.
    path = write("""\
        id: x
        kind: rolling_disk
        given: {arrangement: free, shape: disk, radius: 1.2 cm, path_radius: 0.4 m,
                speed: 0.5 m/s}
        find: {tilt: deg, precession_period: s}
        """)
    result = solve_file(str(path))
    beta = result.answers["tilt"].si_values[0]
    r, R, v, g = 0.012, 0.4, 0.5, 9.81
    rho = R - r * math.sin(beta)
    # the moment balance per kilogram, m g r sin(b) = Omega^2 cos(b) [rho (m r + J/r) + I_G sin b]
    Omega = v / rho
    lhs = g * r * math.sin(beta)
    rhs = Omega ** 2 * math.cos(beta) * (rho * (r + r / 2) + r * r / 4 * math.sin(beta))
    assert lhs == pytest.approx(rhs, rel=1e-6)
    assert result.answers["precession_period"].si_values == \
        [pytest.approx(2 * math.pi * rho / v, rel=1e-9)]


def test_disk_on_a_pinned_axle_one_lap(problems_dir, write):
    # problem 11/6's shaft turns at 48 rpm: one lap of the circle takes 60 / 48 = 1.25 s.
    text = _unstated(problems_dir / "11_6.yaml")
    assert "precession: 48 rpm" in text
    path = write(text.replace("\nfind:\n", "\nfind:\n  precession_period: s\n", 1))
    assert si(path, "precession_period") == [pytest.approx(1.25, rel=1e-9)]


# ---- item 3: euler_angles asks for the angles only when an answer needs them -------

def test_inertia_of_particles_needs_no_angles(problems_dir, write):
    # The bundled cube of eight 0.5 kg masses (a = 0.2 m), written without angles or rates:
    # I_z = sum m (x^2 + y^2): four corners at 0, a^2 (two), 2 a^2 -> 2 x 4 masses... by hand:
    m, a = 0.5, 0.2
    corners = [(x, y, z) for x in (0, a) for y in (0, a) for z in (0, a)]
    I_z = sum(m * (x * x + y * y) for x, y, z in corners)        # 8 m a^2 = 0.16
    I_xy = sum(m * x * y for x, y, z in corners)                 # 2 m a^2 = 0.04
    assert (I_z, I_xy) == (pytest.approx(0.16), pytest.approx(0.04))
    text = _unstated(problems_dir / "euler_cube_corners.yaml")
    body = text.split("find:")[0]
    for line in ("  theta: 90 deg\n", "  psi: 0 deg\n", "  psi_rate: 10 rad/s\n"):
        body = body.replace(line, "")
    path = write(body + "find:\n  I_z: kg*m^2\n  I_xy: kg*m^2\n  principal_moments: kg*m^2\n")
    result = solve_file(str(path))
    assert result.answers["I_z"].si_values == [pytest.approx(I_z)]
    assert result.answers["I_xy"].si_values == [pytest.approx(I_xy)]
    # eigenvalues of [[8, -2, -2], [-2, 8, -2], [-2, -2, 8]] m a^2: 4 (along the diagonal), 10, 10
    assert result.answers["principal_moments"].si_values == [
        pytest.approx(4 * m * a * a), pytest.approx(10 * m * a * a), pytest.approx(10 * m * a * a)]


def test_euler_answers_that_need_the_angles_still_ask(run, write):
    path = write("""\
        id: x
        kind: euler_angles
        given:
          particles: [{mass: 1 kg, x: 1 m, y: 0 m, z: 0 m}]
        find: {I_x: kg*m^2, omega: rad/s}
        """)
    out = run("solve", path)
    assert out.exit_code == 2 and out.stderr.count("\n") == 1 and "given.theta" in out.stderr


# ---- item 10: the docs' stated readings agree with the code ------------------------

def test_every_reading_the_docs_state_is_the_codes():
    """Every "`360 kmph` = 100 m/s" in README.md and docs/*.md: both sides read by gyro's
    own unit reader in the first dimension they share, and equal (to the digits printed)."""
    import re
    from pathlib import Path

    from gyro_cli.core import units
    from gyro_cli.core.errors import InputError

    root = Path(__file__).resolve().parent.parent
    pattern = re.compile(r"`([-0-9.e+]+ [^`]+)` = ([-0-9.e+]+ [A-Za-z/^0-9]+)")
    found = []
    for page in [root / "README.md", *sorted((root / "docs").glob("*.md"))]:
        for left, right in pattern.findall(page.read_text()):
            found.append((page.name, left, right))
    assert any("kmph" in left for _, left, _ in found)
    for page, left, right in found:
        for dimension in ("speed", "rate", "mass", "force", "length", "moment", "time", "angle"):
            try:
                a = units.parse(left, dimension, "doc")[0]
                b = units.parse(right, dimension, "doc")[0]
            except InputError:
                continue
            assert a == pytest.approx(b, rel=5e-3), (page, left, right)
            break
        else:
            pytest.fail(f"{page}: {left} = {right} is read in no dimension")


def test_vehicles_page_no_longer_warns_against_kmph():
    from pathlib import Path

    text = (Path(__file__).resolve().parent.parent / "docs" / "vehicles.md").read_text()
    assert "Avoid `kmph`" not in text and "`kmph` is\nkilometres per hour" in text


# ---- a newcomer's polish -------------------------------------------------------

def test_an_angular_frequency_asked_in_hz_is_printed_as_f(write):
    # omega_n = sqrt(k / I_g) = sqrt(0.8 / 1e-4) = 89.44 rad/s; f_n = omega_n / (2 pi) = 14.24 Hz
    path = write("""\
        id: x
        kind: rate_gyro
        given: {J: 2e-4 kg m^2, spin: 24000 rpm, stiffness: 0.8 N m/rad,
                gimbal_inertia: 1e-4 kg m^2, rate: 5 deg/s}
        find: {natural_frequency: Hz}
        """)
    answer = solve_file(str(path)).answers["natural_frequency"]
    assert answer.values == [pytest.approx(math.sqrt(0.8 / 1e-4) / (2 * math.pi), rel=1e-9)]
    assert answer.symbol == "f_n"
    in_rad = solve_file(str(write(path.read_text().replace("Hz", "rad/s"), "q.yaml")))
    assert in_rad.answers["natural_frequency"].symbol == "omega_n"


def test_no_default_g_for_a_rate_gyro_and_whole_numbers_as_written(problems_dir, run):
    out = run("solve", problems_dir / "rate_gyro_reading.yaml")
    assert out.exit_code == 0 and "(default)" not in out.stdout.split("\n\n")[1 if "Source" in
                                                                           out.stdout else 0]
    out = run("solve", problems_dir / "two_wheeler_250kg.yaml")
    assert "5.00000" not in out.stdout and "\n  G            5 " in out.stdout


def test_torque_free_has_no_empty_body_heading_and_one_beta(run, problems_dir):
    out = run("solve", problems_dir / "torque_free_satellite.yaml").stdout
    assert "\nBody\n\n" not in out and "\nBody\n" not in out
    assert sum(1 for line in out.splitlines() if line.strip().startswith("beta =")) == 1


def test_new_templates_carry_their_own_notes_and_keys(run):
    rate = run("new", "rate_gyro").stdout
    assert "precessing frame" not in rate and "I_pivot" not in rate and "  # g:" not in rate
    top = run("new", "steady_precession").stdout
    assert "precessing frame" in top and "I_pivot" in top
    listing = run("new")
    assert listing.exit_code == 0 and "steady_precession" in listing.stdout
    assert "rate_gyro" in listing.stdout


def test_grading_table_has_a_header_row(run, problems_dir, tmp_path):
    sheet = tmp_path / "sheet.csv"
    sheet.write_text("alice,11/3,precession,45.13 rpm; 533.5 rpm\n")
    out = run("check", "--answers", sheet, problems_dir / "11_3.yaml")
    first = out.stdout.splitlines()[0].split()
    assert first[:5] == ["student", "problem", "answer", "result", "points"], out.stdout


def test_readme_shows_latex_with_standalone():
    from pathlib import Path

    readme = (Path(__file__).resolve().parent.parent / "README.md").read_text()
    quick = next(block for block in readme.split("```")[1::2] if "gyro solve" in block)
    assert "--format latex --standalone" in quick
    assert "or latex" not in quick and "latex FILE" not in quick


# ---- acceptance: a folder of published problems in the books' own words -------------

BOOKS_WORDS = ["toy_gyroscope_no_angle.yaml", "irodov_turbine_locomotive.yaml",
               "khurmi_wheel_drop.yaml", "ship_steering_2200kg_aft.yaml",
               "ship_pitching_6000kg.yaml", "ship_pitching_3500kg_extremes.yaml",
               "torque_free_shell.yaml", "torque_free_satellite.yaml"]


def test_gyro_check_passes_on_the_books_folder(run, problems_dir, tmp_path):
    folder = tmp_path / "books"
    folder.mkdir()
    for name in BOOKS_WORDS:
        text = (problems_dir / name).read_text()
        assert "source:" in text and "expected:" in text, name
        (folder / name).write_text(text)
    out = run("check", folder)
    assert out.exit_code == 0, out.stdout + out.stderr
    assert f"in {len(BOOKS_WORDS)} problems" in out.stdout and "0 failed" in out.stdout


@pytest.mark.parametrize("name, axis", [
    ("ship_pitching_6000kg.yaml", "athwartships as it pitches"),
    ("ship_stabiliser_hospital_ship.yaml", "stabiliser's frame is turned, athwartships"),
    ("aeroplane_outside_loop.yaml", "about its lateral axis in a loop"),
])
def test_a_pitch_or_a_loop_is_not_called_a_turn_about_the_vertical(problems_dir, name, axis):
    # Pitching turns the spin axis about the athwartship axis and a loop about the lateral
    # one (the worked answer's own omega_p = v / R step says so): the conventions had called
    # omega_p "the turn's angular velocity, about the vertical" for every vehicle.
    from gyro_cli.render import report

    text = report.text(solve_file(str(problems_dir / name)))
    assert "the turn's angular velocity, about the vertical" not in text
    assert axis in text


def test_without_an_angle_the_dropped_term_is_the_one_that_gives_the_approximation(
        problems_dir):
    # The toy gyroscope's spin is psidot (45 rev/s). Eq. 11.13 with omega_z = psidot +
    # phidot cos(theta) reads m g l = phidot (J psidot + (J - I) phidot cos(theta)): dropping
    # (J - I) phidot cos(theta) gives m g l / (J psidot); dropping I phidot cos(theta) alone
    # would leave m g l / (J omega_z), another number at any tilt.
    from gyro_cli.render import report

    m, r, l, g, spin = 0.170, 0.055, 0.105, 9.80, 45 * 2 * math.pi
    J = m * r ** 2 / 2
    result = solve_file(str(problems_dir / "toy_gyroscope_no_angle.yaml"))
    assert result.answers["precession_approx"].si_values == \
        [pytest.approx(m * g * l / (J * spin), rel=1e-9)]
    text = report.text(result)
    assert "once the (J - I) phidot cos(theta) term of Eq. 11.13 is dropped" in text


def test_a_rate_gyros_time_constant_is_called_one(problems_dir):
    # I_g theta'' + c theta' = H omega: theta' = (H omega / c)(1 - exp(-t c / I_g)), which
    # reaches 63% of its value at tau = I_g / c, not all of it.
    from gyro_cli.render import report

    text = report.text(solve_file(str(problems_dir / "rate_integrating_gyro.yaml")))
    assert "about two thirds of its value" in text
    assert round(1 - math.exp(-1), 2) == 0.63 and round(1 - math.exp(-3), 2) == 0.95


@pytest.mark.parametrize("extra, key", [
    ("theta: 60 deg, I_cg: 100 kg m^2", "given.theta"),   # M/L would be M/(L sin theta)
    ("theta: 0 deg", "given.theta"),
    ("counterweight: 50 kg, balance_position: 0.3 m", "given.counterweight"),
])
def test_a_wheel_drop_refuses_what_its_geometry_cannot_carry(run, write, extra, key):
    # The couple of a wheel's drop is about the vertical: a weight cannot balance it, and the
    # axle is across the track (theta 90 deg), so a tilted axle is no wheel set.
    path = write(f"""\
        id: x
        kind: gyroscopic_torque
        given: {{J: 180 kg m^2, spin: 30 rad/s, drop: 6 mm, drop_time: 0.1 s,
                bearing_spacing: 1.5 m, {extra}}}
        find: {{moment: N m, couple_forces: N}}
        """)
    out = run("solve", path)
    assert out.exit_code == 2 and out.stderr.count("\n") == 1 and key in out.stderr, out.stderr


@pytest.mark.parametrize("name", ["irodov_turbine_locomotive.yaml", "two_wheeler_250kg.yaml"])
def test_a_turn_the_data_do_not_give_is_said_to_be_taken(problems_dir, tmp_path, name):
    # Irodov gives no sense of the curve: the left turn the senses are printed for is gyro's
    # choice, and the worked answer says so (it had been printed as if given).
    from gyro_cli.render import report

    text = report.text(solve_file(str(problems_dir / name)))
    assert "no turn is given: taken left; only the senses depend on it" in text
    stated = tmp_path / name
    stated.write_text((problems_dir / name).read_text().replace("given:\n",
                                                                "given:\n  turn: left\n"))
    assert "no turn is given" not in report.text(solve_file(str(stated)))


@pytest.mark.parametrize("name, said", [
    ("torque_free_shell.yaml", "(Meriam's n); positive: the precession direct"),
    ("torque_free_earth.yaml", "(Meriam's n); negative: the precession retrograde"),
])
def test_the_spin_ratio_says_its_own_sign(problems_dir, name, said):
    # n = psidot / phidot = (I - J) cos(theta) / J: positive for a prolate body (the shell,
    # I > J: direct), negative for an oblate one (the Earth, J > I: retrograde). The shell's
    # positive n had been followed by "negative: retrograde".
    from gyro_cli.render import report

    assert said in report.text(solve_file(str(problems_dir / name)))


@pytest.mark.parametrize("name, said", [
    # 1e-7 N m / 0.1 kg m^2/s = 1e-6 rad/s x (180 / pi) x 3600 = 0.2063 deg/h
    ("drift_navigation_gyro.yaml", "= 1.000e-06 rad/s    = 0.2063 deg/h"),
    # 2 pi / 8.142e11 s = 7.717e-12 rad/s = 1.592e-6 deg/h (the Earth's 25,800 years)
    ("drift_earth_precession.yaml", "= 7.717e-12 rad/s    = 1.592e-06 deg/h"),
])
def test_a_drift_rates_note_in_deg_per_hour_is_its_own_value(problems_dir, name, said):
    # The note beside Omega_d had converted a value already in deg/h again: 4.255e+04 deg/h
    # printed beside 1e-6 rad/s, whose answer line said 0.2063 deg/h.
    from gyro_cli.render import report

    assert 1e-6 * 180 / math.pi * 3600 == pytest.approx(0.2063, abs=1e-4)
    assert said in report.text(solve_file(str(problems_dir / name)))


def test_the_chapters_earth_figures_are_said_for_the_earth_only(problems_dir):
    # "The chapter's 26,000 years; its '80 years' ... is a misprint" is the chapter's Earth:
    # Mars's 171,000 years had been followed by it.
    from gyro_cli.render import report

    assert "26,000" in report.text(solve_file(str(problems_dir / "11_3_equinoxes.yaml")))
    assert "26,000" not in report.text(solve_file(str(problems_dir / "mars_precession.yaml")))


def test_a_directional_gyro_keeps_its_azimuth_without_a_horizontal_gimbal_moment(problems_dir):
    # H along north, dH/dt = M: a moment about the vertical U moves H's tip along U (the axis
    # tilts, its azimuth kept); one about the horizontal inner gimbal axis E moves it along E
    # (the azimuth turns). The sentence had named the vertical axis.
    from gyro_cli.render import report

    text = report.text(solve_file(str(problems_dir / "dg_apparent_drift_45N.yaml")))
    assert "no moment about the horizontal (inner) gimbal axis the spin axis keeps its " \
        "azimuth" in text


def test_at_90_deg_the_spin_is_worked_without_the_inertia_the_book_leaves_out(problems_dir):
    # With the axis horizontal, m g l = J psidot phidot (cos(theta) = 0): the transverse
    # inertia, not given, had been substituted as "0 kg m^2" in the (J - I) term.
    from gyro_cli.render import report

    result = solve_file(str(problems_dir / "toy_gyroscope_pivot.yaml"))
    text = report.text(result)
    assert "0 kg m^2)" not in text.replace("0.0001200 kg m^2)", "")
    assert "psidot = m g l / (J phidot) =" in text
