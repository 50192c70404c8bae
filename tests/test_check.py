"""`gyro check`: passing, failing (with the slip), bad files, tolerances, root matching,
JSON, exit codes, through click's CliRunner and the installed `gyro` command.

Independent references: the expected answers are hand calculations written out
here (the gyroscope limit phidot = m g l / (J psidot) at theta = 90 deg, and the
quadratic of the theta equation solved with the textbook root formula); the
slips are built by applying the slip (x10, sign, 2 pi, ...) to those values;
tolerances are worked by hand (3 sig of 45.1 rpm is +-0.05 rpm).
"""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from gyro_cli.checking import check, expected, matching, tolerance
from gyro_cli.core import units

G = 9.81
RPM = 2 * math.pi / 60

# Gyroscope at theta = 90 deg: m = 2 kg, l = 0.1 m, J = 0.01 kg m^2, psidot = 100 rad/s.
# With the axis horizontal, dH/dt = J psidot phidot must equal m g l (no phidot^2 term):
GYRO_PRECESSION = 2 * G * 0.1 / (0.01 * 100)  # = 1.962 rad/s
GYRO_MOMENT = 2 * G * 0.1  # m g l sin(90 deg) = 1.962 N m


def _two_roots() -> tuple[float, float]:
    """Top: m = 1 kg, l = 0.05 m, J = 0.002, I = 0.01 kg m^2, theta = 60 deg, psidot = 300 rad/s.

    The theta equation of the Lagrangian with thetaddot = 0 (divided by sin theta):
    I phidot^2 cos(th) - J (psidot + phidot cos(th)) phidot + m g l = 0, i.e.
    a p^2 + b p + c = 0 with a = (I - J) cos th, b = -J psidot, c = m g l.
    """
    a, b, c = (0.01 - 0.002) * 0.5, -0.002 * 300, 1 * G * 0.05
    root = math.sqrt(b * b - 4 * a * c)
    return (-b - root) / (2 * a), (-b + root) / (2 * a)


SLOW, FAST = _two_roots()  # about 0.8220 and 149.18 rad/s


def gyro_file(expected: str = "", tolerance: str = "", extra_find: str = "") -> str:
    text = """\
        id: gyro-90
        title: Horizontal gyroscope
        kind: steady_precession
        given:
          mass: 2 kg
          J: 0.01 kg m^2
          I_pivot: 0.05 kg m^2
          cg_distance: 0.1 m
          spin: 100 rad/s
          theta: 90 deg
        find:
          precession: rad/s
        """
    text = textwrap.dedent(text).replace("precession: rad/s\n", f"precession: rad/s{extra_find}\n")
    if expected:
        text += "expected:\n" + textwrap.indent(textwrap.dedent(expected), "  ")
    if tolerance:
        text += f"tolerance: {tolerance}\n"
    return text


def top_file(expected: str, tolerance: str = "") -> str:
    text = textwrap.dedent("""\
        id: top-60
        kind: steady_precession
        given:
          mass: 1 kg
          J: 0.002 kg m^2
          I_pivot: 0.01 kg m^2
          cg_distance: 0.05 m
          spin: 300 rad/s
          theta: 60 deg
        find:
          precession: rad/s
        """)
    text += "expected:\n" + textwrap.indent(textwrap.dedent(expected), "  ")
    if tolerance:
        text += f"tolerance: {tolerance}\n"
    return text


def put(directory: Path, name: str, text: str) -> Path:
    path = directory / name
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


@pytest.fixture
def passing(tmp_path: Path) -> Path:
    d = tmp_path / "set"
    put(d, "gyro.yaml", gyro_file(f"precession: {GYRO_PRECESSION:.6g} rad/s\n"
                                  f"moment: {GYRO_MOMENT:.6g} N m\n"))
    # roots in the other order, and in rpm: matched as a set, units converted
    put(d, "sub/top.yml", top_file(f"precession: [{FAST / RPM:.6g} rpm, {SLOW:.6g} rad/s]\n"))
    return d


def gyro_exe() -> str:
    exe = Path(sys.executable).with_name("gyro")
    if not exe.exists():
        pytest.fail("the gyro command is not installed next to the test interpreter")
    return str(exe)


# ---- passing, failing, bad ---------------------------------------------------

def test_passing_set_exits_0_with_a_line_per_answer(run, passing):
    result = run("check", passing)
    assert result.exit_code == 0, result.output
    lines = [line for line in result.stdout.splitlines() if line.strip().startswith("PASS")]
    assert len(lines) == 4  # gyro: precession, moment; top: two roots
    assert result.stdout.splitlines()[-1].startswith("OK: 4 answers in 2 problems: 4 passed")


def test_installed_command_exit_codes(passing, tmp_path):
    exe = gyro_exe()
    ok = subprocess.run([exe, "check", str(passing)], capture_output=True, text=True)
    assert ok.returncode == 0, ok.stderr
    bad_answer = put(tmp_path, "wrong.yaml", gyro_file(f"precession: {GYRO_PRECESSION * 10:.6g} "
                                                       "rad/s\n"))
    failed = subprocess.run([exe, "check", str(bad_answer)], capture_output=True, text=True)
    assert failed.returncode == 1
    assert "power of ten" in failed.stdout
    bad_file = put(tmp_path, "bad.yaml", gyro_file("precession: 3 m\n"))
    errored = subprocess.run([exe, "check", str(passing), str(bad_file)], capture_output=True,
                             text=True)
    assert errored.returncode == 2
    assert "Traceback" not in errored.stderr
    assert errored.stdout.count("PASS") == 4  # the good files are still reported


@pytest.mark.parametrize("factor, slip", [
    (10.0, "power of ten"),
    (0.001, "power of ten"),
    (-1.0, "the sign"),
    (2 * math.pi, "2 pi"),
    (1 / (2 * math.pi), "2 pi"),
    (60 / (2 * math.pi), "rpm against rad/s"),
    (-10.0, "power of ten and the sign"),
])
def test_failing_answer_names_the_slip(run, tmp_path, factor, slip):
    wrong = GYRO_PRECESSION * factor
    path = put(tmp_path, "p.yaml", gyro_file(f"precession: {wrong:.6g} rad/s\n"))
    result = run("check", path)
    assert result.exit_code == 1
    line = next(x for x in result.stdout.splitlines() if x.strip().startswith("FAIL"))
    assert slip in line
    assert "likely slip" in line
    # how far off, worked by hand: (got - expected) / expected
    off = (GYRO_PRECESSION - wrong) / abs(wrong)
    assert f"{off * 100:+.2f}%" in line


def test_mass_against_weight_is_a_factor_of_g(run, tmp_path):
    # The moment m g l written as m l (the mass where the weight belongs).
    path = put(tmp_path, "p.yaml", gyro_file(f"moment: {2 * 0.1:.6g} N m\n"))
    result = run("check", path)
    assert result.exit_code == 1
    assert "mass against weight" in result.stdout


def test_other_root_is_diagnosed(run, tmp_path):
    # Both expected values are the slow root: the second is left the fast root.
    path = put(tmp_path, "p.yaml", top_file(f"precession: [{SLOW:.6g} rad/s, {SLOW:.6g} rad/s]\n"))
    result = run("check", path)
    assert result.exit_code == 1
    assert "the other root" in result.stdout


def test_mixed_set_with_bad_files_exits_2_and_reports_the_rest(run, passing, tmp_path):
    bad_dim = put(tmp_path, "bad_dim.yaml", gyro_file("precession: 1.962 m\n"))
    bad_yaml = put(tmp_path, "bad_yaml.yaml", "id: [unclosed\n")
    result = run("check", passing, bad_dim, bad_yaml)
    assert result.exit_code == 2
    assert result.stdout.count("PASS") == 4
    err = result.stderr.strip().splitlines()
    assert len(err) == 2
    assert "expected.precession" in err[0] and "bad_dim.yaml" in err[0]
    assert "an angular rate" in err[0]  # a wrong dimension is a file error, not a failed answer
    assert "bad_yaml.yaml" in err[1]
    assert "FAIL" not in result.stdout


def test_wrong_answer_and_bad_file_exit_2(run, tmp_path):
    wrong = put(tmp_path, "w.yaml", gyro_file("precession: 5 rad/s\n"))
    missing = tmp_path / "nope.yaml"
    result = run("check", wrong, missing)
    assert result.exit_code == 2
    assert "FAIL" in result.stdout
    assert "no such file" in result.stderr


@pytest.mark.parametrize("expected, message", [
    ("precession: []\n", "empty list"),
    ("precession: {a: 1}\n", "mapping"),
    ("precesion: 1 rad/s\n", "did you mean 'precession'"),
    ("precession: 1.9\n", "an angular rate"),  # a bare number is not a rate
])
def test_malformed_expected_is_a_file_error(run, tmp_path, expected, message):
    path = put(tmp_path, "p.yaml", gyro_file(expected))
    result = run("check", path)
    assert result.exit_code == 2
    assert message in result.stderr
    assert "expected." in result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


# ---- tolerances ---------------------------------------------------------------

@pytest.mark.parametrize("value, tolerance, passes", [
    ("1.962 rad/s", "", True),             # default 1%
    ("1.98 rad/s", "", True),              # 0.92% off
    ("1.99 rad/s", "", False),             # 1.4% off
    ("1.99 rad/s", "2%", True),
    ("1.965 rad/s", "0.1%", False),        # 0.15% off
    ("1.96 rad/s", "3 sig", True),         # +-0.005 around 1.96
    ("1.960 rad/s", "4 sig", False),       # +-0.0005 around 1.960; off by 0.002
    ("1.9620 rad/s", "5 sig", True),
    ("1.955 rad/s", "0.01 rad/s", True),   # absolute
    ("1.955 rad/s", "0.001 rad/s", False),
    ("18.7 rpm", "1 rpm", True),           # 1.962 rad/s = 18.736 rpm
    ("18.7 rpm", "0.01 rpm", False),
])
def test_tolerance_forms(run, tmp_path, value, tolerance, passes):
    path = put(tmp_path, "p.yaml", gyro_file(f"precession: {value}\n", tolerance))
    result = run("check", path)
    assert result.exit_code == (0 if passes else 1), result.output


def test_tolerance_per_answer_with_default(run, tmp_path):
    expected = f"precession: 1.99 rad/s\nmoment: {GYRO_MOMENT * 1.015:.6g} N m\n"
    path = put(tmp_path, "p.yaml", gyro_file(expected, "{precession: 2%, default: 0.1%}"))
    result = run("check", path, "--format", "json")
    doc = json.loads(result.stdout)
    verdict = {a["name"]: a["passed"] for a in doc["problems"][0]["answers"]}
    assert verdict == {"precession": True, "moment": False}
    path = put(tmp_path, "q.yaml", gyro_file(expected, "{precession: 2%, moment: 0.05 N m}"))
    assert run("check", path).exit_code == 0


@pytest.mark.parametrize("tolerance, message", [
    ("0.01", "ambiguous"),
    ("5 m", "an angular rate"),            # absolute tolerance in the wrong dimension
    ("{precesion: 1%}", "did you mean 'precession'"),
    ("150%", "between 0% and 100%"),
    ("0 sig", "from 1 to 15"),
])
def test_bad_tolerance_is_a_file_error(run, tmp_path, tolerance, message):
    path = put(tmp_path, "p.yaml", gyro_file("precession: 1.962 rad/s\n", tolerance))
    result = run("check", path)
    assert result.exit_code == 2
    assert message in result.stderr
    assert "tolerance" in result.stderr


def test_sig_figs_count_on_the_value_as_written():
    tol = tolerance.parse_tolerance("3 sig", "rate")
    # 45.1 rpm to 3 significant figures: half a unit in the last place is 0.05 rpm.
    assert tol.half_width(45.1 * RPM, 45.1) == pytest.approx(0.05 * RPM)
    assert tol.half_width(0.00451 * RPM, 0.00451) == pytest.approx(0.000005 * RPM)
    assert tolerance.parse_tolerance("1%", "rate").half_width(-10.0, -10.0) == pytest.approx(0.1)
    absolute = tolerance.parse_tolerance("6 rpm", "rate")
    assert absolute.half_width(1000.0, 1.0) == pytest.approx(6 * RPM)


# ---- matching roots as sets --------------------------------------------------

def test_match_roots_pairs_nearest_and_uses_none_twice():
    assert matching.match_roots([533.5, 45.13], [45.13, 533.5]) == [(0, 1), (1, 0)]
    # two expected near the same root: the nearer takes it, the other gets the rest
    assert matching.match_roots([45.0, 45.2], [45.13, 533.5]) == [(0, 1), (1, 0)] or \
        matching.match_roots([45.0, 45.2], [45.13, 533.5]) == [(0, 0), (1, 1)]
    pairs = matching.match_roots([45.0, 45.2], [45.13, 533.5])
    assert sorted(j for _, j in pairs) == [0, 1]
    assert dict(pairs)[1] == 0  # 45.2 is nearer 45.13 than 45.0 is (log distance)
    assert matching.match_roots([1.0], [1.0, 2.0]) == [(0, 0), (None, 1)]
    assert matching.match_roots([1.0, 2.0], [2.0]) == [(0, None), (1, 0)]
    # a slip (x10) still pairs with the root it spoils, not with a larger one
    assert matching.match_roots([4.513, 533.5], [45.13, 533.5]) == [(0, 0), (1, 1)]


def test_roots_in_any_order_pass_and_a_missing_root_fails(run, tmp_path):
    both = put(tmp_path, "both.yaml", top_file(f"precession: [{FAST:.6g} rad/s, "
                                               f"{SLOW:.6g} rad/s]\n"))
    assert run("check", both).exit_code == 0
    one = put(tmp_path, "one.yaml", top_file(f"precession: {SLOW:.6g} rad/s\n"))
    result = run("check", one)  # one keyed root passes, the other is "not keyed"
    assert result.exit_code == 0, result.stdout
    assert "not keyed" in result.stdout and "1 passed, 0 failed" in result.stdout
    result = run("check", "--strict", one)  # --strict keeps the rule that every root is keyed
    assert result.exit_code == 1
    assert "has no expected value" in result.stdout
    three = put(tmp_path, "three.yaml", top_file(f"precession: [{SLOW:.6g} rad/s, {FAST:.6g} "
                                                 "rad/s, 3 rad/s]\n"))
    result = run("check", three)
    assert result.exit_code == 1
    assert "got no root" in result.stdout


def test_an_answer_equal_for_both_roots_needs_one_expected_value(run, tmp_path):
    # The moment is m g l sin(theta) for either precession rate.
    moment = 1 * G * 0.05 * math.sin(math.radians(60))
    path = put(tmp_path, "p.yaml", top_file(f"precession: [{SLOW:.6g} rad/s, {FAST:.6g} rad/s]\n"
                                            f"moment: {moment:.6g} N m\n"))
    assert run("check", path).exit_code == 0


def test_diagnose_pure():
    assert matching.diagnose(10.0, -10.0, 0.1) .startswith("the sign")
    assert "power of ten" in matching.diagnose(10.0, 1000.0, 0.1)
    assert "2 pi" in matching.diagnose(1.0, 2 * math.pi, 0.01)
    assert "60" in matching.diagnose(1.0, 60.0, 0.01)
    assert "degrees against radians" in matching.diagnose(1.0, math.degrees(1.0), 0.01)
    assert "mass against weight" in matching.diagnose(2.0, 2.0 * 9.81, 0.02)
    assert matching.diagnose(10.0, 13.0, 0.1) is None  # 30% off: no known slip
    assert "other root" in matching.diagnose(5.0, 50.0, 0.05, [5.01])


# ---- reports, paths, exit codes -----------------------------------------------

def test_json_report_parsed_back(run, passing, tmp_path):
    wrong = put(tmp_path, "w.yaml", gyro_file("precession: 2.2 rad/s\n"))
    result = run("check", passing, wrong, "--format", "json")
    assert result.exit_code == 1
    doc = json.loads(result.stdout)
    summary = doc["summary"]
    assert (summary["answers"], summary["passed"], summary["failed"]) == (5, 4, 1)
    assert summary["exit_code"] == 1
    failed = [a for p in doc["problems"] for a in p["answers"] if not a["passed"]]
    assert len(failed) == 1
    answer = failed[0]
    assert answer["expected_value"] == 2.2 and answer["unit"] == "rad/s"
    assert answer["got_value"] == pytest.approx(GYRO_PRECESSION, rel=1e-12)
    assert answer["relative_error"] == pytest.approx((GYRO_PRECESSION - 2.2) / 2.2, rel=1e-9)
    assert answer["tolerance_value"] == pytest.approx(0.022)
    statuses = sorted(p["status"] for p in doc["problems"])
    assert statuses == ["fail", "pass", "pass"]


def test_no_expected_answers_is_reported_not_passed(run, tmp_path, passing):
    plain = put(tmp_path, "plain.yaml", gyro_file())
    alone = run("check", plain)
    assert alone.exit_code == 1  # nothing was compared
    assert "no expected answers" in alone.stdout
    assert "nothing was compared" in alone.stdout
    mixed = run("check", passing, plain)
    assert mixed.exit_code == 0
    assert "1 without expected answers" in mixed.stdout
    assert run("check", passing, plain, "--strict").exit_code == 1


def test_directories_recurse_globs_expand_hidden_skipped(run, tmp_path, passing):
    put(passing, ".hidden/junk.yaml", "not: a problem\n")
    result = run("check", passing, "--format", "json")
    files = sorted(Path(p["file"]).name for p in json.loads(result.stdout)["problems"])
    assert files == ["gyro.yaml", "top.yml"]
    pattern = str(passing / "**" / "*.yml")
    result = run("check", pattern, "--format", "json")
    assert [Path(p["file"]).name for p in json.loads(result.stdout)["problems"]] == ["top.yml"]
    nothing = run("check", str(tmp_path / "*.nothing"))
    assert nothing.exit_code == 2 and "no files match" in nothing.stderr
    empty = tmp_path / "empty"
    empty.mkdir()
    assert run("check", empty).exit_code == 2


def test_unit_registry_is_created_once_for_a_directory(tmp_path, monkeypatch, passing):
    import pint

    made = []
    real = pint.UnitRegistry

    def counting(*args, **kwargs):
        made.append(1)
        return real(*args, **kwargs)

    monkeypatch.setattr(units, "_registry", None)
    monkeypatch.setattr(pint, "UnitRegistry", counting)
    for i in range(5):
        put(passing, f"more/g{i}.yaml", gyro_file(f"precession: {GYRO_PRECESSION:.6g} rad/s\n"))
    result = check.run([str(passing)])
    assert result.exit_code == 0 and result.counts()["checked"] == 7
    assert len(made) <= 1  # none at all when every unit was met before (unit cache)


def test_junit_option_writes_the_file(run, passing, tmp_path):
    out = tmp_path / "report.xml"
    result = run("check", passing, "--junit", out)
    assert result.exit_code == 0
    assert out.read_text().startswith("<?xml")
    # re-running replaces it (CI reruns), without leaving temporary files behind
    assert run("check", passing, "--junit", out).exit_code == 0
    assert sorted(os.listdir(tmp_path)) == ["report.xml", "set"]


def test_word_answers_compare_as_words():
    from gyro_cli.solving.solve import Reported

    motion = Reported("motion", "motion", ["cusps"], None, ["cusps"], None, [])
    exact = tolerance.parse_tolerance("1%", None)
    good = matching.compare("motion", expected.parse_expected("Cusps", None, "expected.motion"), exact,
                         motion)
    bad = matching.compare("motion", expected.parse_expected(["loops"], None, "expected.motion"),
                        exact, motion)
    assert [a.passed for a in good] == [True]
    assert [a.passed for a in bad] == [False] and "got cusps" in bad[0].message


def test_dimensionless_expected_may_be_a_bare_number():
    from gyro_cli.solving.solve import Reported

    ratio = Reported("u", "u", [0.5], "", [0.5], "", [])
    values = expected.parse_expected([0.501], "dimensionless", "expected.u")
    assert values[0].si == 0.501
    assert [a.passed for a in matching.compare("u", values, tolerance.parse_tolerance("1%", "x"),
                                            ratio)] == [True]


def test_unused_tolerance_entries_and_unsolvable_files_are_file_errors(run, tmp_path):
    unused = put(tmp_path, "u.yaml", gyro_file("precession: 1.962 rad/s\n",
                                               "{precession: 1%, moment: 3 kg}"))
    result = run("check", unused)
    assert result.exit_code == 2 and "tolerance.moment" in result.stderr
    # no expected answers, but no steady precession either (spin far below the least spin)
    hopeless = put(tmp_path, "h.yaml", gyro_file().replace("theta: 90 deg", "theta: 30 deg")
                   .replace("spin: 100 rad/s", "spin: 0.01 rad/s"))
    result = run("check", hopeless)
    assert result.exit_code == 2 and "too low for steady precession" in result.stderr


def test_unit_factor_cache_keeps_every_check():
    """The SI factor cached for a unit (for speed) gives pint's value and keeps the checks."""
    first, _ = units.parse("1800 rpm", "rate", "k")
    again, quantity = units.parse("900 rpm", "rate", "k")
    assert first == pytest.approx(1800 * 2 * math.pi / 60, rel=1e-15)
    pint_value = units.registry().Quantity(900, "rpm").to("rad/s").magnitude
    assert again == pytest.approx(pint_value, rel=1e-15)
    assert quantity.magnitude == 900 and not quantity.us_customary
    units.parse("3 in", "length", "k")
    with pytest.raises(units.InputError, match="an angular rate"):
        units.parse("3 in", "rate", "k")  # cached for length, still refused as a rate
    with pytest.raises(units.InputError, match="out of range"):
        units.parse("1e308 km", "length", "k")  # finite number, infinite in metres
    assert units.parse("3 oz", "force", "k", weight=True)[0] == pytest.approx(3 * 0.27801385,
                                                                              rel=1e-8)
    assert units.convert(first, "rate", "rpm") == pytest.approx(1800, rel=1e-15)


def test_a_magnitude_check_shows_the_computed_value_as_signed(run):
    # Irodov's locomotive: the turbine's couple M = J psidot Omega loads the rails +M / L
    # and -M / L; the key gives [1.4 kN, -1.4 kN] and compares sizes (`magnitude`). B's
    # computed value is negative: shown "-1.396 kN (B)" beside "-1.4 kN", not as "1.396"
    problems = Path(__file__).resolve().parent.parent / "problems"
    result = run("check", problems / "irodov_turbine_locomotive.yaml")
    assert result.exit_code == 0, result.output
    rows = [line.split() for line in result.output.splitlines() if "bearing_forces[" in line]
    assert [(r[2], r[4], r[6]) for r in rows] == [("1.4", "1.396", "(A)"),
                                                   ("-1.4", "-1.396", "(B)")], rows
    assert all("magnitude" in line for line in result.output.splitlines()
               if "bearing_forces[" in line)
