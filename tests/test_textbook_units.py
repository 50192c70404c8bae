"""Units as textbooks write them (issue 8 item 1) and the unit tokenizer.

Every conversion factor below is written out by hand from the definitions
(1 mile = 1609.344 m, 1 lbf = 4.4482216152605 N, 1 ft = 0.3048 m,
1 in = 0.0254 m, 1 oz = 1/16 lb, 1 knot = 1852 m/h), not taken from pint.
"""

from __future__ import annotations

import math
import time

import pytest

from gyro_cli.core import units
from gyro_cli.core.errors import InputError

LBF = 4.4482216152605          # N, 0.45359237 kg x 9.80665 m/s^2
FT, IN = 0.3048, 0.0254
REV = 2 * math.pi


@pytest.mark.parametrize("text, dimension, si", [
    # rates
    ("60 rev/min", "rate", REV), ("60 r/min", "rate", REV), ("60 RPM", "rate", REV),
    ("60 rpm", "rate", REV), ("1 rev/s", "rate", REV), ("1 rps", "rate", REV),
    ("1 rev", "angle", REV), ("5 1/s", "rate", 5.0),
    # speeds: kilometres per hour, never kilo-miles per hour
    ("360 kmph", "speed", 100.0), ("360 kph", "speed", 100.0), ("360 km/h", "speed", 100.0),
    ("360 km/hr", "speed", 100.0), ("10 knot", "speed", 18520 / 3600),
    ("10 kn", "speed", 18520 / 3600), ("60 mph", "speed", 60 * 1609.344 / 3600),
    # masses and forces
    ("1.5 t", "mass", 1500.0), ("2 tonne", "mass", 2000.0), ("1 kgf", "force", 9.80665),
    ("20 lb", "force", 20 * LBF), ("3 oz", "force", 3 * LBF / 16),
    # moments: lb and oz with a length read as pound-force and ounce-force
    ("50 lb ft", "moment", 50 * LBF * FT), ("50 lb-ft", "moment", 50 * LBF * FT),
    ("50 lb*ft", "moment", 50 * LBF * FT), ("50 ft lb", "moment", 50 * LBF * FT),
    ("12 lb in", "moment", 12 * LBF * IN), ("8 oz in", "moment", 8 * LBF / 16 * IN),
    ("2 N m", "moment", 2.0), ("2 N-m", "moment", 2.0), ("2 N.m", "moment", 2.0),
    ("2 Nm", "moment", 2.0), ("2 N*m", "moment", 2.0), ("1.2 kN m", "moment", 1200.0),
])
def test_textbook_units(text, dimension, si):
    value, _ = units.parse(text, dimension, "given.x")
    assert value == pytest.approx(si, rel=1e-9)


def test_kmph_is_kilometres_per_hour():
    # 360 km in one hour is 360000 m / 3600 s = 100 m/s (not 360 x 1609.344 km / 3600 s)
    assert units.parse("360 kmph", "speed", "given.speed")[0] == pytest.approx(100.0)


def test_lb_stays_a_mass_where_a_mass_is_meant():
    assert units.parse("2 lb", "mass", "given.mass")[0] == pytest.approx(2 * 0.45359237)
    # a force written with lb as a mass (lb ft/s^2, a poundal) keeps its meaning
    assert units.parse("1 lb ft/s^2", "force", "k")[0] == pytest.approx(0.45359237 * FT)


@pytest.mark.parametrize("unit, dimension, shown, per_si", [
    ("N*m", "moment", "N m", 1.0), ("N-m", "moment", "N m", 1.0),
    ("lb-ft", "moment", "lbf ft", 1 / (LBF * FT)), ("lb", "force", "lbf", 1 / LBF),
    ("kmph", "speed", "km/h", 3.6), ("kg*m^2", "inertia", "kg m^2", 1.0),
    ("rev/min", "rate", "rev/min", 60 / REV),
])
def test_answer_units_print_as_steps_print_them(unit, dimension, shown, per_si):
    text = units.check_unit(unit, dimension, "find.x")
    assert text == shown
    assert units.convert(1.0, dimension, text) == pytest.approx(per_si)


@pytest.mark.parametrize("text, fragments", [
    ("1 rmp", ["unknown unit 'rmp'", "did you mean 'rpm'"]),
    ("1800 rpm relative to the precessing frame psidot, see notes",
     ["unknown unit 'relative'", "a comment needs '#'"]),
    ("1 mrpm", ["'mrpm'", "milli"]),
    ("1 rpm*", ["ends with an operator"]),
    ("1 ()", ["empty brackets"]),
    ("1 (rpm", ["unbalanced brackets"]),
    ("1 rpm)", ["unbalanced brackets"]),
    ("1 rad//s", ["'/'", "no unit before it"]),
    ("1 m^2^3", ["chained powers"]),
    ("9**9**9**9 rpm", ["power"]),
    ("1 rpm, fast", ["unknown unit 'fast'", "a comment needs '#'"]),
    ("1 rpm;", ["unexpected ';'"]),
])
def test_bad_units_give_one_clear_line(text, fragments):
    with pytest.raises(InputError) as err:
        units.parse(text, "rate", "given.spin")
    message = str(err.value)
    assert "\n" not in message and "given.spin" in message
    for fragment in fragments:
        assert fragment in message, message


@pytest.mark.parametrize("unit", [
    "m " * 5000, "a" * 9999 + "*", "(" * 5000, "m/" * 5000 + "s", "m^2 " * 2500,
    "(m)" * 3333 + ")",
])
def test_tokenizer_is_linear_on_10000_characters(unit):
    # CPU time, so that a loaded machine does not fail it; measured about 4 ms
    start = time.process_time()
    try:
        tokens = units.tokenize(unit, key="given.x")
    except InputError:
        tokens = None
    assert time.process_time() - start < 0.5
    if unit == "m " * 5000:
        assert len(tokens) == 2 * 5000 - 1  # names and the products between them


def test_long_quantity_text_is_refused_fast():
    start = time.process_time()
    with pytest.raises(InputError, match="at most 100"):
        units.parse("1 " + "m " * 5000, "length", "given.radius")
    # the old regular expression backtracked exponentially on this kind of text
    with pytest.raises(InputError):
        units.parse("1 " + "a" * 60 + "!", "length", "given.radius")
    assert time.process_time() - start < 0.5


def test_cli_unknown_unit_is_one_line(run, write):
    path = write("""\
        id: x
        kind: steady_precession
        given: {weight: 3 oz, k_axial: 0.84 in, k_pivot: 1.80 in, cg_distance: 1.5 in,
                spin: 1800 rmp, theta: 30 deg}
        find: {precession: rpm}
        """)
    out = run("solve", path)
    assert out.exit_code == 2
    assert out.stderr.count("\n") == 1 and "did you mean 'rpm'" in out.stderr
    assert "Traceback" not in out.stderr and "(" not in out.stderr.split("did you mean")[0][-20:]


def test_time_per_angle_needs_an_angle_in_its_unit():
    # pint counts angles as plain numbers, so `yr` would pass as years per radian
    with pytest.raises(InputError, match="angle in its unit"):
        units.check_unit("yr", "time_per_angle", "find.years_per_degree")
    per_degree = units.convert(3600.0 * 180 / math.pi, "time_per_angle", "h/deg")
    assert per_degree == pytest.approx(1.0, rel=1e-12)   # 1 h per degree, from s/rad
