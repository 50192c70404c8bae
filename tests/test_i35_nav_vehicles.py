"""Issue 35, round four: navigation gyros on the rotating Earth (item 3), four-wheelers
as the books draw them (item 4), and `gyro new` statements that read as sentences
(item 9).

Every number is worked by hand here from the books' own formulas, or checked by an
independent law (the wheel loads add up to the weight, their moments balance the
couples), never by calling gyro's formula again.
"""

from __future__ import annotations

import re

import pytest
import yaml

from gyro_cli import kinds
from gyro_cli.commands import authoring
from gyro_cli.solving.problem import load


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
    example = dict(kinds.get(name).extra.get("example") or {})
    example.pop("statement", None)
    monkeypatch.setitem(kinds.get(name).extra, "example", example)
    text = authoring.template(name)
    data = yaml.safe_load(text)
    filled = _fill(" ".join(data["statement"].split()), data["given"])
    assert sentence_faults(filled) == [], filled


# ---- item 3: navigation gyros on the rotating Earth ---------------------------------

import math  # noqa: E402

import numpy as np  # noqa: E402

from gyro_cli.solving.solve import solve_file  # noqa: E402

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
