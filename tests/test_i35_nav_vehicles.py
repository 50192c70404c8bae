"""Issue 35, round four: navigation gyros on the rotating Earth (item 3), four-wheelers
as the books draw them (item 4), and `gyro new` statements that read as sentences
(item 9).

Every number is worked by hand here from the books' own formulas, or checked by an
independent law (the wheel loads add up to the weight, their moments balance the
couples), never by calling gyro's formula again.
"""

from __future__ import annotations

import math
import re

import numpy as np
import pytest
import yaml
from scipy.optimize import brentq

from gyro_cli import kinds
from gyro_cli.commands import authoring
from gyro_cli.solving.problem import build, load
from gyro_cli.solving.solve import solve, solve_file

# ---- item 9: every template's statement reads as a sentence -------------------------

PLACEHOLDER = re.compile(r"\{([A-Za-z_][A-Za-z0-9_]*)\}")


def _fill(statement: str, given: dict) -> str:
    """The statement with each {key} replaced by the given value as written (our own
    filling, not gyro's)."""
    return PLACEHOLDER.sub(lambda m: " ".join(str(given[m.group(1)]).split())
                           if m.group(1) in given else m.group(0), statement)


def sentence_faults(text: str) -> list[str]:
    """What keeps ``text`` from reading as sentences: each fault found, in words."""
    faults = []
    if "{" in text or "}" in text:
        faults.append("an unfilled brace")
    if not re.match(r"[A-Z]", text):
        faults.append("does not start with a capital letter")
    if not re.search(r"[.?]$", text):
        faults.append("does not end with a full stop")
    op = r"[/*^=+<>-]"
    if re.search(rf"(^|\s){op}\s*([,.;:)]|$)", text):
        faults.append("an operator dangling before punctuation or the end")
    if re.search(rf"[(,;:]\s*{op}(\s|$)", text):
        faults.append("an operator dangling after punctuation")
    if re.search(rf"(^|\s){op}\s+{op}(\s|$)", text) or re.search(r"\^\d*\s*/", text):
        faults.append("two operators in a row")
    if re.search(r"\s[/*^]\s", text):  # a unit is written m/s, a formula H / I
        faults.append("a formula in the prose")
    if re.search(r"\b(sin|cos|tan|sqrt)\b(?!\()", text):
        faults.append("a function without its argument")
    if text.count("(") != text.count(")") or "()" in text:
        faults.append("unbalanced or empty brackets")
    if re.search(r"\s[,.;:]|[,;:]{2}|\.\.|\s{2}", text):
        faults.append("stray punctuation or spacing")
    if re.search(r"\b[A-Za-z]+_[A-Za-z0-9_]*\b", text):
        faults.append("a key name (snake_case) in the prose")
    if re.search(r"\b(\w+) \1\b", text, re.I):
        faults.append("a doubled word")
    for piece in re.split(r"(?<=[.?])\s+", text):
        if piece and not re.match(r"[A-Z]", piece):
            faults.append(f"a sentence that starts in lower case: {piece[:30]!r}")
    return faults


def test_item09_sentence_check_catches_the_old_garbled_statements():
    """The check itself: the statements gyro new printed before the fix are faulted."""
    old_four = ("Given: total mass of the vehicle 2500 kg. Find [outer, inner]: vertical "
                "reaction on each outer and each inner wheel,  v^2 /, positive overturning "
                "outward, m v^2 h / R.")
    old_drift = "Given: rotor spin 24000 rpm. Find drift rate of the spin axis, H / sqrt, c /)."
    assert sentence_faults(old_four) and sentence_faults(old_drift)
    assert sentence_faults("Given the mass {mass}. Find the couple.")
    assert sentence_faults("Find the rotor_sense.")
    assert sentence_faults("Find the moment along n = K x k / sin, [A, B]: forces.")
    assert sentence_faults("Find the precession about H, H / I, magnitude of omega.")
    assert not sentence_faults("A top spins at 1800 rpm with its axis at 30 deg. Find the "
                               "rate of steady precession (slow root).")


@pytest.mark.parametrize("name", kinds.names())
def test_item09_every_gyro_new_statement_reads_as_a_sentence(run, tmp_path, name):
    out = tmp_path / f"{name}.yaml"
    assert run("new", name, "-o", out).exit_code == 0
    data = yaml.safe_load(out.read_text())
    filled = _fill(" ".join(data["statement"].split()), data["given"])
    assert sentence_faults(filled) == [], filled
    assert load(str(out)).statement_text() == filled  # gyro fills it the same way
    # the statement states the data: every given quantity (a value with a number)
    written = set(PLACEHOLDER.findall(data["statement"]))
    quantities = {k for k, v in data["given"].items() if re.match(r"\s*[-+]?[\d.]", str(v))}
    assert quantities <= written, (name, quantities - written)


@pytest.mark.parametrize("name", kinds.names())
def test_item09_a_kind_without_its_own_statement_still_gets_sentences(monkeypatch, name):
    """A new kind whose example carries no statement: the template's sentence is made
    from the keys' descriptions and still reads as one."""
    example = dict(kinds.get(name).example or {})
    example.pop("statement", None)
    monkeypatch.setattr(kinds.get(name), "example", example)
    text = authoring.template(name)
    data = yaml.safe_load(text)
    filled = _fill(" ".join(data["statement"].split()), data["given"])
    assert sentence_faults(filled) == [], filled


# ---- item 3: navigation gyros on the rotating Earth ---------------------------------

DEG_H = math.pi / 180 / 3600
SIDEREAL = 7.292115e-5  # rad/s
KT = 1852 / 3600
NM_EARTH = 1852 * 60 * 180 / math.pi  # the sphere whose arc minute is a nautical mile


def answers(path):
    return solve_file(str(path)).answers


def si(path, name):
    return answers(path)[name].si_values


def dg_file(write, given: str, find: str = "{drift_rate: deg/h, drift_sense: null}") -> object:
    return write(f"id: dg\nkind: directional_gyro\ngiven:\n{given}\nfind: {find}\n")


def azimuth_drift(latitude: float, east_speed: float, t: float) -> float:
    """The azimuth of a spin axis fixed in inertial space, measured clockwise from the
    local north seen from above, after time t: built from the vectors of the rotating
    Earth and the moving craft, not from any drift formula."""
    lon_rate = SIDEREAL + east_speed / (NM_EARTH * math.cos(latitude))

    def frame(time):
        th = lon_rate * time
        up = np.array([math.cos(latitude) * math.cos(th), math.cos(latitude) * math.sin(th),
                       math.sin(latitude)])
        east = np.array([-math.sin(th), math.cos(th), 0.0])
        return east, np.cross(up, east)

    spin = frame(0.0)[1]  # aligned with north at the start
    east, north = frame(t)
    return math.atan2(spin @ east, spin @ north)


@pytest.mark.parametrize("lat_text, lat", [("30 S", -30), ("45 deg N", 45), ("S 60", -60),
                                           ("75°N", 75), ("0 deg", 0)])
@pytest.mark.parametrize("speed_kt, direction", [(0, "east"), (400, "east"), (250, "west")])
def test_item03_drift_agrees_with_the_rotating_frames(write, lat_text, lat, speed_kt,
                                                      direction):
    """The drift rate against the azimuth of an axis held fixed in space, found from the
    frames at one minute (where the rate is constant to 1e-7)."""
    path = dg_file(write, f"  latitude: {lat_text}\n  ground_speed: {speed_kt} kt\n"
                          f"  direction: {direction}")
    v_east = speed_kt * KT * (1 if direction == "east" else -1)
    t = 1.0
    expected = azimuth_drift(math.radians(lat), v_east, t) / t
    got = si(path, "drift_rate")[0]
    assert got == pytest.approx(expected, rel=1e-6, abs=1e-12)
    sense = answers(path)["drift_sense"].si_values[0]
    assert sense == ("right" if expected > 1e-12 else "left" if expected < -1e-12 else "none")


def test_item03_30S_is_7_5_deg_per_hour_to_the_left(problems_dir):
    """ATPL question: 15 x sin 30 = 7.5 deg/h to the left, the reading increases."""
    path = problems_dir / "dg_apparent_drift_30S.yaml"
    assert si(path, "drift_rate")[0] / DEG_H == pytest.approx(-15 * 0.5)
    assert answers(path)["drift_sense"].si_values == ["left"]
    assert answers(path)["reading"].si_values == ["increases"]


def test_item03_45N_with_the_sidereal_rate(problems_dir):
    """15.041 deg/h x sin 45 = 10.636 deg/h to the right (the exam's 11)."""
    rate = si(problems_dir / "dg_apparent_drift_45N.yaml", "drift_rate")[0] / DEG_H
    sidereal_deg_h = 360 / (23 + 56 / 60 + 4.0905 / 3600)  # 15.0411 deg/h
    assert rate == pytest.approx(sidereal_deg_h * math.sqrt(0.5), rel=1e-5)
    assert round(rate) == 11


def test_item03_latitude_nut_set_south_adds_in_the_north(problems_dir):
    """Nut at 30 S, standing at 60 N: 15 x 0.8660 + 15 x 0.5 = 20.49 deg/h right."""
    path = problems_dir / "dg_latitude_nut_30S_at_60N.yaml"
    assert si(path, "earth_rate_drift")[0] / DEG_H == pytest.approx(12.990381, rel=1e-6)
    assert si(path, "nut_correction")[0] / DEG_H == pytest.approx(7.5)
    assert si(path, "drift_rate")[0] / DEG_H == pytest.approx(20.490381, rel=1e-6)
    assert math.degrees(si(path, "reading_change")[0]) == pytest.approx(-20.490381, rel=1e-6)


def test_item03_nut_cancels_at_its_own_latitude_and_its_moment(write):
    """Limiting case: standing still at the nut's latitude there is no drift; and the nut's
    moment, divided by H, is the Earth's vertical rate there (Eq. 11.29)."""
    path = dg_file(write, "  latitude: 52 N\n  latitude_nut: 52 N\n  J: 2e-4 kg m^2\n"
                          "  spin: 20000 rpm", "{drift_rate: deg/h, nut_moment: N m, "
                          "drift_sense: null}")
    assert abs(si(path, "drift_rate")[0]) < 1e-18
    assert answers(path)["drift_sense"].si_values == ["none"]
    H = 2e-4 * 20000 * 2 * math.pi / 60
    M = si(path, "nut_moment")[0]
    assert M / H == pytest.approx(SIDEREAL * math.sin(math.radians(52)), rel=1e-12)


def test_item03_flying_west_with_the_sun_cancels_the_earth(write):
    """A craft flying west at the Earth's surface speed holds its place under the Sun: the
    frame stops turning in space and the drift vanishes (limiting case)."""
    lat = math.radians(40)
    speed = SIDEREAL * NM_EARTH * math.cos(lat)  # m/s
    path = dg_file(write, f"  latitude: 40 N\n  ground_speed: {speed!r} m/s\n"
                          "  direction: west")
    assert abs(si(path, "drift_rate")[0]) < 1e-9 * SIDEREAL


def test_item03_transport_wander_400_kt_east_at_45N(problems_dir):
    """JAR notes: 400 x tan 45 / 60 = 6.667 deg/h, east in the north: reading decreases."""
    path = problems_dir / "dg_transport_wander_400kt_45N.yaml"
    assert si(path, "transport_wander")[0] / DEG_H == pytest.approx(400 / 60, rel=1e-9)
    total = si(path, "drift_rate")[0] / DEG_H
    assert total == pytest.approx(400 / 60 + 15.041068 * math.sqrt(0.5), rel=1e-5)


def test_item03_gyro_heading_after_P_to_Q_is_328(problems_dir):
    """Op Proc question: 15 sin 61 x 1.5 + 20 sin 61 = 37.17 deg right; 000 + 5 - 37.17 is
    327.8 on the dial, answer (D) 328."""
    path = problems_dir / "dg_gyro_heading_P_to_Q.yaml"
    s61 = math.sin(math.radians(61))
    drift = 15 * s61 * 1.5 + 20 * s61
    assert math.degrees(si(path, "drift_angle")[0]) == pytest.approx(drift, rel=1e-9)
    assert math.degrees(si(path, "indicated_heading")[0]) == pytest.approx(360 + 5 - drift)
    assert round(math.degrees(si(path, "indicated_heading")[0])) == 328


def test_item03_a_track_gives_its_east_component(write):
    """Track 060 at 300 kt is 300 sin 60 kt east: the same as flying east at that speed."""
    by_track = dg_file(write, "  latitude: 50 N\n  ground_speed: 300 kt\n  track: 60 deg")
    east = 300 * math.sin(math.radians(60))
    by_east = dg_file(write, f"  latitude: 50 N\n  ground_speed: {east!r} kt\n"
                             "  direction: east", "{drift_rate: deg/h}")
    assert si(by_track, "drift_rate")[0] == pytest.approx(si(by_east, "drift_rate")[0])
    north = dg_file(write, "  latitude: 50 N\n  ground_speed: 300 kt\n  direction: north")
    assert si(north, "drift_rate")[0] / DEG_H == pytest.approx(
        15.041068 * math.sin(math.radians(50)), rel=1e-5)


@pytest.mark.parametrize("written, degrees", [("30 S", -30), ("30 deg S", -30), ("30°S", -30),
                                              ("S 30", -30), ("30 south", -30), ("45 N", 45),
                                              ("N45.5 deg", 45.5), ("-12 deg", -12)])
def test_item03_hemisphere_words_are_read(write, written, degrees):
    path = dg_file(write, f"  latitude: {written}\n  earth_rate: 15 deg/h")
    assert si(path, "drift_rate")[0] / DEG_H == pytest.approx(15 * math.sin(math.radians(degrees)))
    word = dg_file(write, f"  latitude: {abs(degrees)} deg\n  hemisphere: "
                          f"{'S' if degrees < 0 else 'northern'}\n  earth_rate: 15 deg/h",
                   "{drift_rate: deg/h}")
    assert si(word, "drift_rate")[0] == pytest.approx(si(path, "drift_rate")[0])


def test_item03_gyrocompass_reads_a_southern_latitude(write):
    base = ("id: gc\nkind: gyrocompass\ngiven:\n  J: 0.01 kg m^2\n  spin: 12000 rpm\n"
            "  I_vertical: 0.02 kg m^2\n  latitude: {}\nfind: {{period: s}}\n")
    south = write(base.format("35 S"), "s.yaml")
    signed = write(base.format("-35 deg"), "n.yaml")
    assert si(south, "period") == si(signed, "period")


@pytest.mark.parametrize("given, key, words", [
    ("  latitude: 95 N", "given.latitude", "90 deg"),
    ("  latitude: 30 E", "given.latitude", "write N or S"),
    ("  latitude: -30 S", "given.latitude", "not both"),
    ("  latitude: 30 deg\n  hemisphere: east", "given.hemisphere", "north, south"),
    ("  latitude: 30 S\n  hemisphere: S", "given.hemisphere", "once"),
    ("  latitude: -30 deg\n  hemisphere: S", "given.hemisphere", "negative latitude"),
    ("  latitude: 30 N\n  ground_speed: 300 kt", "given.direction", "direction"),
    ("  latitude: 30 N\n  direction: east", "given.ground_speed", "ground_speed"),
    ("  latitude: 90 N\n  ground_speed: 300 kt\n  direction: east", "given.latitude", "pole"),
    ("  latitude: 30 N\n  latitude_nut: 100 S", "given.latitude_nut", "90 deg"),
])
def test_item03_bad_input_is_one_line_naming_the_key(run, write, given, key, words):
    path = dg_file(write, given)
    result = run("solve", path)
    assert result.exit_code == 2, result.output
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and key in lines[0] and words in lines[0], lines


def test_item03_answers_that_need_more_data_say_which_key(run, write):
    for find, key in [("{nut_correction: deg/h}", "given.latitude_nut"),
                      ("{drift_angle: deg}", "given.duration"),
                      ("{transport_wander: deg/h}", "given.ground_speed")]:
        result = run("solve", dg_file(write, "  latitude: 30 N", find))
        assert result.exit_code == 2 and key in result.stderr, (find, result.stderr)


# ---- item 4: four-wheelers as the books draw them -----------------------------------

RPM = 2 * math.pi / 60


def free_body_loads(m, g, h, x, L, a_f, bank, v, R, turn, H_across, H_along):
    """The four wheel loads (front outer, front inner, rear outer, rear inner) from the
    car's free body, written with vectors: Newton's law for the centre of mass, the
    moments about G of the track's forces equal to dH/dt of the rotors (by central
    differences of H turning about the vertical), and the books' rule that each axle
    takes the same share of the roll moment. H_across is along the car's left in the
    track's plane (the wheels' sense), H_along along the car's forward axis."""
    c = 1.0 if turn == "left" else -1.0  # the centre of the curve at +Y (left) or -Y
    X, Y, Z = np.eye(3)
    n = np.array([0.0, c * math.sin(bank), math.cos(bank)])   # normal to the track
    y_in = np.array([0.0, c * math.cos(bank), -math.sin(bank)])  # across it, toward the centre
    left = c * y_in
    wp = c * v / R  # about +Z
    H0 = H_across * left + H_along * X

    def H(t):
        a = wp * t
        rot = np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0],
                        [0, 0, 1]])
        return rot @ H0

    dt = 1e-3
    dH = (H(dt) - H(-dt)) / (2 * dt)
    # force balance: sum N n + F y_in - m g Z = m (v^2 / R) (toward the centre, c Y)
    A = np.array([[n @ Y, y_in @ Y], [n @ Z, y_in @ Z]])
    N_total, F = np.linalg.solve(A, [m * v * v / R * c, m * g])
    wheels = [(a_f, -1), (a_f, +1), (a_f - L, -1), (a_f - L, +1)]  # outer: away from the centre
    rows, rhs = [[1.0] * 4], [N_total]
    roll, pitch = [], []
    for ahead, side in wheels:
        r = ahead * X + side * x / 2 * y_in - h * n
        moment = np.cross(r, n)
        roll.append(moment @ X)
        pitch.append(moment @ y_in)
    friction_moment = np.cross(-h * n, F * y_in)
    rows += [roll, pitch, [1.0, -1.0, -1.0, 1.0]]
    rhs += [dH @ X - friction_moment @ X, dH @ y_in - friction_moment @ y_in, 0.0]
    return np.linalg.solve(np.array(rows), np.array(rhs))


CAR = """\
id: car
kind: four_wheeler
given:
  mass: 1600 kg
  track: 1.5 m
  cg_height: 0.55 m
  wheel_radius: 0.3 m
  wheel_inertia: 2.5 kg m^2
  turn_radius: 80 m
  speed: 72 km/h
{extra}find:
  wheel_loads: N
  axle_loads: N
  limiting_speed: m/s
"""


@pytest.mark.parametrize("bank", [0.0, 6.0])
@pytest.mark.parametrize("cg", [None, 1.1, 1.7])
@pytest.mark.parametrize("engine", ["none", "across same", "across opposite",
                                    "along clockwise_from_front left",
                                    "along clockwise_from_front right",
                                    "along counterclockwise_from_rear right",
                                    "along clockwise_from_rear left at speed"])
def test_item04_wheel_loads_balance_the_free_body(write, bank, cg, engine):
    m, x, h, rw, Iw, R, v = 1600, 1.5, 0.55, 0.3, 2.5, 80.0, 20.0
    L = 2.6
    extra = f"  wheelbase: {L} m\n" + (f"  cg_to_front: {cg} m\n" if cg else "")
    if bank:
        extra += f"  bank_angle: {bank} deg\n"
    I_E, G, turn = 0.9, 3.5, "left"
    H_across = 4 * Iw * v / rw
    H_along = 0.0
    if engine.startswith("across"):
        sense = engine.split()[1]
        extra += f"  engine_inertia: {I_E} kg m^2\n  gear_ratio: {G}\n  engine_sense: {sense}\n"
        H_across += (1 if sense == "same" else -1) * I_E * G * v / rw
    elif engine.startswith("along"):
        _, rotation, turn, *at_speed = engine.split()
        spin = I_E * (1500 * RPM if at_speed else G * v / rw)
        extra += (f"  engine_axis: fore_and_aft\n  engine_inertia: {I_E} kg m^2\n"
                  f"  engine_rotation: {rotation}\n  turn: {turn}\n")
        extra += "  engine_speed: 1500 rpm\n" if at_speed else f"  gear_ratio: {G}\n"
        # clockwise seen from the front: the vector points away from that observer, aft
        forward = ("counterclockwise" in rotation) == rotation.endswith("front")
        H_along = spin * (1 if forward else -1)
    path = write(CAR.format(extra=extra))
    got = si(path, "wheel_loads")
    a_f = cg if cg else L / 2
    expected = free_body_loads(m, 9.81, h, x, L, a_f, math.radians(bank), v, R, turn,
                               H_across, H_along)
    assert got == pytest.approx(list(expected), rel=1e-6)
    front, rear = si(path, "axle_loads")
    assert front + rear == pytest.approx(sum(expected), rel=1e-12)


def test_item04_racing_car_with_its_flywheel_along(problems_dir):
    """Worked in the file's notes: 6310.7, 3340.2, 6659.8, 3689.3 N."""
    loads = si(problems_dir / "four_wheeler_racing_car_flywheel.yaml", "wheel_loads")
    m, v, R, x = 20000 / 9.81, 30 / 3.6, 15.0, 1.0
    wheels = 4 * 3 * (v / 0.4) * (v / R) / (2 * x)
    centrifugal = m * v * v * 0.3 / R / (2 * x)
    flywheel = 4 * 3000 * RPM * (v / R) / 2 / 2   # per wheel: C_p / L / 2, front less
    hand = [5000 + wheels + centrifugal - flywheel, 5000 - wheels - centrifugal - flywheel,
            5000 + wheels + centrifugal + flywheel, 5000 - wheels - centrifugal + flywheel]
    assert loads == pytest.approx(hand, rel=1e-9)
    assert sum(loads) == pytest.approx(20000)


def test_item04_ncert_car_at_rest(problems_dir):
    """Moments about the rear axle: F_front 1.8 = 17640 (0.75)."""
    path = problems_dir / "four_wheeler_car_at_rest_cg_behind_front.yaml"
    assert si(path, "wheel_loads") == pytest.approx([3675, 3675, 5145, 5145])


def test_item04_banked_trolley(problems_dir):
    path = problems_dir / "four_wheeler_banked_trolley.yaml"
    b = math.radians(8)
    N = 2000 * (9.81 * math.cos(b) + 7.5 * math.sin(b))
    Cc = 2000 * 1 * (7.5 * math.cos(b) - 9.81 * math.sin(b))
    Cg = 36 * (15 / 0.35) * 0.5 * math.cos(b)
    outer, inner = N / 4 + (Cc + Cg) / 3.2, N / 4 - (Cc + Cg) / 3.2
    assert si(path, "wheel_reactions") == pytest.approx([outer, inner], rel=1e-9)
    # a limiting case: banked for the speed (tan b = v^2 / (g R)) no friction is needed
    # across the track and the centrifugal couple vanishes
    v_design = math.sqrt(9.81 * 30 * math.tan(b))
    data = yaml.safe_load((problems_dir / "four_wheeler_banked_trolley.yaml").read_text())
    data["given"]["speed"] = f"{v_design!r} m/s"
    data["find"] = {"centrifugal_couple": "N m"}
    data.pop("expected"), data.pop("statement")
    result = solve(build("<banked>", data, {}))
    assert abs(result.answers["centrifugal_couple"].si_values[0]) < 1e-9


def test_item04_engine_along_and_centre_of_mass_forward(problems_dir):
    path = problems_dir / "four_wheeler_car_engine_along_cg_forward.yaml"
    v = 60 / 3.6
    wp, ww = v / 60, v / 0.4
    weight_f, weight_r = 19620 * 1.5 / 2.5 / 2, 19620 * 1.0 / 2.5 / 2
    side = (4 * 0.8 * ww * wp + 2000 * v * v * 0.5 / 60) / (2 * 1.5)
    pitch = 0.75 * 4 * ww * wp / 2.5 / 2
    assert si(path, "wheel_loads") == pytest.approx(
        [weight_f + side - pitch, weight_f - side - pitch, weight_r + side + pitch,
         weight_r - side + pitch], rel=1e-9)


@pytest.mark.parametrize("extra", ["  wheelbase: 2.6 m\n  cg_to_front: 1.0 m\n  bank_angle: 5 deg\n",
                                   "  wheelbase: 2.6 m\n  cg_to_rear: 0.9 m\n"
                                   "  engine_axis: fore_and_aft\n  engine_inertia: 1.2 kg m^2\n"
                                   "  gear_ratio: 4\n  engine_rotation: clockwise seen from the rear"
                                   "\n  turn: right\n"])
def test_item04_limiting_speed_where_the_free_body_lifts_a_wheel(write, extra):
    path = write(CAR.format(extra=extra))
    v_lim = si(path, "limiting_speed")[0]
    cg = 1.0 if "cg_to_front" in extra else 2.6 - 0.9
    bank = math.radians(5) if "bank" in extra else 0.0
    turn = "right" if "right" in extra else "left"

    def least(v):
        H_across = 4 * 2.5 * v / 0.3
        H_along = 1.2 * 4 * v / 0.3 if "fore_and_aft" in extra else 0.0  # clockwise from the rear: forward
        return min(free_body_loads(1600, 9.81, 0.55, 1.5, 2.6, cg, bank, v, 80.0, turn,
                                   H_across, H_along))

    assert v_lim == pytest.approx(brentq(least, 1.0, 200.0, xtol=1e-12), rel=1e-7)


def test_item04_level_midway_car_is_the_old_model(write):
    """With the wheelbase given and the centre of mass midway, the general car gives the
    outer and inner reactions and limiting speed of the plain one."""
    plain = write(CAR.format(extra="").replace("  axle_loads: N\n", "").replace(
        "wheel_loads", "wheel_reactions"), "plain.yaml")
    book = write(CAR.format(extra="  wheelbase: 2.6 m\n").replace("  axle_loads: N\n", "")
                 .replace("wheel_loads", "wheel_reactions"), "book.yaml")
    assert si(book, "wheel_reactions") == pytest.approx(si(plain, "wheel_reactions"), rel=1e-12)
    assert si(book, "limiting_speed") == pytest.approx(si(plain, "limiting_speed"), rel=1e-9)


@pytest.mark.parametrize("extra, find, key, words", [
    ("  wheelbase: 2.6 m\n  cg_to_front: 1.0 m\n", "wheel_reactions", "find.wheel_reactions",
     "wheel_loads"),
    ("  wheelbase: 2.6 m\n  engine_axis: fore_and_aft\n  engine_inertia: 1 kg m^2\n"
     "  engine_sense: same\n  engine_rotation: clockwise seen from the front\n  turn: left\n",
     "wheel_loads", "given.engine_sense", "engine_rotation"),
    ("  wheelbase: 2.6 m\n  engine_axis: fore_and_aft\n  engine_inertia: 1 kg m^2\n  turn: left\n",
     "wheel_loads", "given.engine_rotation", "seen from"),
    ("  wheelbase: 2.6 m\n  engine_axis: fore_and_aft\n  engine_inertia: 1 kg m^2\n"
     "  engine_rotation: clockwise seen from the front\n", "wheel_loads", "given.turn", "turn"),
    ("  engine_axis: fore_and_aft\n  engine_inertia: 1 kg m^2\n  turn: left\n"
     "  engine_rotation: clockwise seen from the front\n", "wheel_loads", "given.wheelbase",
     "wheelbase"),
    ("  engine_rotation: clockwise seen from the front\n", "wheel_loads",
     "given.engine_rotation", "fore_and_aft"),
    ("  wheelbase: 2.6 m\n  cg_to_front: 3 m\n", "wheel_loads", "given.cg_to_front",
     "between the axles"),
    ("  cg_to_front: 1 m\n", "wheel_loads", "given.wheelbase", "wheelbase"),
    ("  bank_angle: 95 deg\n", "wheel_loads", "given.bank_angle", "90 deg"),
    ("  cant: 2 m\n", "wheel_loads", "given.cant", "track"),
    ("  cant: 0.1 m\n  bank_angle: 4 deg\n", "wheel_loads", "given.cant", "not both"),
    ("  engine_speed: 3000 rpm\n  gear_ratio: 3\n  engine_inertia: 1 kg m^2\n", "wheel_loads",
     "given.engine_speed", "not both"),
    ("  engine_axis: sideways\n", "wheel_loads", "given.engine_axis", "across"),
    ("  cant: 1.3 m\n", "limiting_speed", "given.cant", "no load even at rest"),
])
def test_item04_what_the_model_cannot_represent_is_refused(run, write, extra, find, key, words):
    text = CAR.format(extra=extra).replace("  wheel_loads: N\n  axle_loads: N\n"
                                           "  limiting_speed: m/s\n",
                                           f"  {find}: {'m/s' if 'speed' in find else 'N'}\n")
    result = run("solve", write(text))
    assert result.exit_code == 2, result.output
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and key in lines[0] and words in lines[0], lines


def test_item04_cant_is_the_bank_of_its_sine(write):
    by_cant = write(CAR.format(extra="  cant: 0.12 m\n"), "c.yaml")
    by_angle = write(CAR.format(extra=f"  bank_angle: {math.degrees(math.asin(0.12 / 1.5))!r} deg\n"),
                     "a.yaml")
    assert si(by_cant, "wheel_loads") == pytest.approx(si(by_angle, "wheel_loads"), rel=1e-12)


def test_item03_the_worked_steps_agree_with_a_hand_calculation(write):
    """The kind's steps (written by physics/directional_gyro.py's functions) against the
    rates worked by hand: the Earth's vertical component, the craft's longitude rate on the
    nautical-mile sphere, the nut's rate and moment."""
    path = dg_file(write, "  latitude: 35 S\n  latitude_nut: 48 N\n  ground_speed: 320 kt\n"
                          "  direction: west\n  angular_momentum: 0.5 kg m^2/s",
                   "{drift_rate: deg/h, earth_rate_drift: deg/h, transport_wander: deg/h, "
                   "nut_correction: deg/h, nut_moment: N m}")
    lat, nut = math.radians(-35), math.radians(48)
    radius = 1852 * 60 / math.radians(1)  # one arc minute is one nautical mile
    assert si(path, "earth_rate_drift")[0] == pytest.approx(SIDEREAL * math.sin(lat))
    # west at 320 kt: l' = -v / (R cos(lat)); its vertical part l' sin(lat) = -v tan(lat) / R
    assert si(path, "transport_wander")[0] == pytest.approx(-320 * KT * math.tan(lat) / radius)
    assert si(path, "nut_correction")[0] == pytest.approx(-SIDEREAL * math.sin(nut))
    assert si(path, "nut_moment")[0] == pytest.approx(0.5 * SIDEREAL * math.sin(nut))
    # westward in the south: with the Earth's sense reversed there, the transport wander is
    # to the right (clockwise), opposite to the Earth's apparent drift to the left
    assert si(path, "transport_wander")[0] > 0 > si(path, "earth_rate_drift")[0]
