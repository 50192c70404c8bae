"""Bad input: one line on stderr naming file and key, exit code 2, no traceback."""

from __future__ import annotations

import subprocess
import sys
import time

import pytest

GOOD_GIVEN = """weight: 3 oz
  k_axial: 0.84 in
  k_pivot: 1.80 in
  cg_distance: 1.5 in
  spin: 1800 rpm
  theta: 30 deg"""


def problem(given: str = GOOD_GIVEN, find: str = "precession: rpm",
            kind: str = "steady_precession", extra: str = "") -> str:
    return f"id: x\nkind: {kind}\ngiven:\n  {given}\nfind:\n  {find}\n{extra}"


def one_line_error(out, *fragments: str) -> str:
    assert out.exit_code == 2, out.output
    assert out.stdout == ""
    err = out.stderr
    assert "Traceback" not in err
    assert err.count("\n") == 1 and err.startswith("gyro: "), err
    for fragment in fragments:
        assert fragment in err, (fragment, err)
    return err


CASES = {
    "empty file": ("", ["is empty"]),
    "yaml syntax": ("id: x\nkind: [steady\n", ["YAML error", "line"]),
    "not a mapping": ("- 1\n- 2\n", ["expected a mapping", "list"]),
    "missing kind": ("id: x\ngiven: {}\nfind: {precession: rpm}\n", ["kind", "missing"]),
    "unknown kind": (problem(kind="top_spin"), ["unknown kind 'top_spin'", "steady_precession"]),
    "unknown top key": (problem(extra="tolerence: 1%\n"), ["tolerence", "did you mean 'tolerance'"]),
    "unknown given key": (problem(given=GOOD_GIVEN.replace("spin:", "spinn:")),
                          ["given.spinn (line 8)", "did you mean 'spin'"]),
    "wrong dimension": (problem(given=GOOD_GIVEN.replace("1800 rpm", "30 deg")),
                        ["given.spin", "angular rate", "30 deg"]),
    "unknown unit": (problem(given=GOOD_GIVEN.replace("1800 rpm", "1800 rpmm")),
                     ["given.spin", "unknown unit", "rpmm"]),
    "bare angle": (problem(given=GOOD_GIVEN.replace("30 deg", "30")),
                   ["given.theta", "deg or rad"]),
    "negative mass": (problem(given=GOOD_GIVEN.replace("weight: 3 oz", "mass: -2 kg")),
                      ["given.mass", "expected mass > 0 kg"]),
    "zero mass": (problem(given=GOOD_GIVEN.replace("weight: 3 oz", "mass: 0 kg")),
                  ["given.mass", "expected mass > 0 kg"]),
    "negative length": (problem(given=GOOD_GIVEN.replace("0.84 in", "-0.84 in")),
                        ["given.k_axial", "expected k_axial > 0 m"]),
    "zero length": (problem(given=GOOD_GIVEN.replace("1.80 in", "0 in")),
                    ["given.k_pivot", "expected k_pivot > 0 m"]),
    "spin below threshold": (problem(given=GOOD_GIVEN.replace("1800 rpm", "500 rpm")),
                             ["given.spin", "too low", "965.4 rpm", "Eq. 11.21"]),
    "power tower": (problem(given=GOOD_GIVEN.replace("1800 rpm", '"9**9**9**9 rpm"')),
                    ["given.spin"]),
    "python tag": ("id: !!python/object/apply:os.system ['echo hi']\nkind: steady_precession\n",
                   ["tag not allowed"]),
    "unknown answer": (problem(find="precesion: rpm"), ["find.precesion", "did you mean"]),
    "answer in wrong unit": (problem(find="precession: m"), ["find.precession", "angular rate"]),
    "vertical axis": (problem(given=GOOD_GIVEN.replace("30 deg", "0 deg")),
                      ["given.theta", "undefined"]),
    "given not a mapping": ("id: x\nkind: steady_precession\ngiven: 3\nfind: {spin: rpm}\n",
                            ["given", "mapping"]),
}


@pytest.mark.parametrize("case", sorted(CASES))
def test_bad_file(case, run, write):
    text, fragments = CASES[case]
    path = write(text)
    err = one_line_error(run("solve", path), *fragments)
    assert str(path) in err


def test_missing_file(run, tmp_path):
    one_line_error(run("solve", tmp_path / "nope.yaml"), "no such file")


def test_directory(run, tmp_path):
    one_line_error(run("solve", tmp_path), "directory")


@pytest.mark.parametrize("size,message", [(1_000_000, "larger than"),
                                          (500_000, "at most 100")])
def test_megabyte_string_is_refused_fast(run, write, size, message):
    path = write(problem(given=GOOD_GIVEN.replace("1800 rpm", "1" * size + " rpm")))
    start = time.perf_counter()
    one_line_error(run("solve", path), message)
    assert time.perf_counter() - start < 1.0


@pytest.mark.parametrize("text", ["9**9**9**9 rpm", "1 rpm**9**9**9", "1 m^9^9 rpm",
                                  "(1e308)**999 rpm", "1 " + "(" * 50 + "rpm" + ")" * 50])
def test_pathological_quantities_rejected_within_a_second(text):
    from gyro_cli.core import units
    from gyro_cli.core.errors import InputError

    start = time.perf_counter()
    with pytest.raises(InputError):
        units.parse(text, "rate", "given.spin")
    assert time.perf_counter() - start < 1.0


def test_other_files_still_solved(run, write, problems_dir):
    bad = write("", "bad.yaml")
    out = run("solve", problems_dir / "11_3.yaml", bad)
    assert out.exit_code == 2
    assert "45.13 rpm" in out.stdout
    assert "bad.yaml" in out.stderr and "Traceback" not in out.stderr


def test_installed_command_exits_2(write):
    path = write(problem(given=GOOD_GIVEN.replace("1800 rpm", "30 deg")))
    proc = subprocess.run([sys.executable, "-m", "gyro_cli", "solve", str(path)],
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 2
    assert proc.stderr.count("\n") == 1 and "Traceback" not in proc.stderr


def test_key_written_twice(run, write):
    """YAML keeps the last of two equal keys silently; gyro refuses it."""
    path = write(problem(given=GOOD_GIVEN + "\n  spin: 900 rpm"))
    one_line_error(run("solve", path), "given.spin", "written twice", "lines 8 and 10")


def test_axial_inertia_beyond_the_transverse_ones_through_the_pivot(run, write):
    """J > 2 (I_pivot - m l^2) is solved as given with a warning (textbook data do this):
    here J = m (1 m)^2 against I_G = m (0.99 in^2)."""
    path = write(problem(given=GOOD_GIVEN.replace("0.84 in", "1 m")))
    out = run("solve", path)
    assert out.exit_code == 0, out.output
    assert "k_axial: J = " in out.stdout and "no rigid body" in out.stdout


@pytest.mark.parametrize("given", [
    # a radius of gyration of 1e9 m: the released top degenerates in floating point
    GOOD_GIVEN.replace("1.80 in", "1e9 m").replace("spin: 1800 rpm", "spin: 1800 rpm\n  "
                                                   "theta0: 30 deg").replace("\n  theta: 30 deg",
                                                                             ""),
])
def test_extreme_magnitudes_say_so(run, write, given):
    path = write(problem(given=given, kind="released_top", find="theta_max: deg"))
    one_line_error(run("solve", path), "double precision")


def test_overflowing_answer_is_refused(run, write):
    path = write(problem(given="mass: 1e300 kg\n  shape: disk\n  radius: 1e9 m\n  spin: 300 rad/s"
                         "\n  arm_length: 250 mm\n  bearing_spacing: 200 mm\n  theta: 90 deg",
                         kind="swinging_rotor", find="bearing_forces: N"))
    one_line_error(run("solve", path), "not a finite number")
