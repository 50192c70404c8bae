"""A student's answer is graded within the tolerance measured from the solver's value,
the truth, and never within less than the figures gyro prints (an adversarial pass found
the band measured from the student's own number: 919.1 rpm against 928.3 rpm was wrong at
-0.991% and 937.65 rpm right at +1.007%; and a 0.02% tolerance marking the printed answer,
copied digit for digit, wrong)."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest
from conftest import PROBLEMS

HEAD = "student,problem,answer,value\n"


def _truth(run, path: Path) -> float:
    """11/3's min_spin as solved, in rpm (the band's centre; the physics is tested elsewhere)."""
    done = run("solve", path, "--format", "json")
    assert done.exit_code == 0, done.output
    answer = json.loads(done.stdout)["answers"]["min_spin"]
    assert answer["unit"] == "rpm"
    return answer["values"][0]


def _problem(tmp_path: Path, tolerance: str) -> Path:
    text = (PROBLEMS / "11_3.yaml").read_text()
    path = tmp_path / "top.yaml"
    path.write_text(re.sub(r"(?m)^tolerance: .*$", f"tolerance: {tolerance}", text))
    return path


def _result(run, tmp_path: Path, problem: Path, value: str) -> str:
    sheet = tmp_path / "sheet.csv"
    sheet.write_text(HEAD + f"ann,11/3,min_spin,{value}\n")
    done = run("check", "--answers", sheet, problem, "--format", "json")
    assert done.exit_code == 0, done.output
    (row,) = json.loads(done.stdout)["rows"]
    return row["result"]


def test_one_percent_is_one_percent_of_the_solvers_value(run, tmp_path):
    problem = _problem(tmp_path, "1%")
    truth = _truth(run, problem)   # 965.4 rpm: the band is 955.7 to 975.1 rpm
    inside_low, inside_high = truth * (1 - 0.0099), truth * (1 + 0.0099)
    outside_low, outside_high = truth * (1 - 0.0101), truth * (1 + 0.0101)
    # measured from the student's number these two were wrong (s >= t / 1.01 fails at -0.995%)
    assert _result(run, tmp_path, problem, f"{truth * (1 - 0.00995):.6f} rpm") == "correct"
    assert _result(run, tmp_path, problem, f"{inside_low:.6f} rpm") == "correct"
    assert _result(run, tmp_path, problem, f"{inside_high:.6f} rpm") == "correct"
    # ... and this one right (s <= t / 0.99 passes at +1.005%)
    assert _result(run, tmp_path, problem, f"{truth * (1 + 0.00995 + 0.0001):.6f} rpm") \
        == "wrong"
    assert _result(run, tmp_path, problem, f"{outside_low:.6f} rpm") == "wrong"
    assert _result(run, tmp_path, problem, f"{outside_high:.6f} rpm") == "wrong"


def test_the_printed_answer_copied_is_right_under_a_tight_tolerance(run, tmp_path):
    problem = _problem(tmp_path, "0.0001%")
    truth = _truth(run, problem)
    printed = f"{truth:.4g} rpm"   # what gyro prints: four significant figures
    assert abs(float(printed.split()[0]) - truth) / truth > 1e-6  # outside 0.0001%
    assert _result(run, tmp_path, problem, printed) == "correct"
    # there the student tolerance (1%, as a bank's blank) applies, and no more
    assert _result(run, tmp_path, problem, f"{truth * 1.009:.6f} rpm") == "correct"
    assert _result(run, tmp_path, problem, f"{truth * 1.011:.6f} rpm") == "wrong"


def test_a_tolerance_looser_than_the_printed_figures_is_the_problems(run, tmp_path):
    problem = _problem(tmp_path, "5%")
    truth = _truth(run, problem)
    assert _result(run, tmp_path, problem, f"{truth * 1.049:.6f} rpm") == "correct"
    assert _result(run, tmp_path, problem, f"{truth * 1.051:.6f} rpm") == "wrong"


@pytest.mark.parametrize(("value", "half", "expected"), [
    (991.9231, 0.0099, 9.919231),   # 0.001%: tighter than 0.05 rpm, the 4th figure's half
    (991.9231, 9.919231, 9.919231),  # 1%: looser, kept
    (0.0012345, 1e-9, 1.2345e-5),   # 1% of the value
    (123456.0, 0.01, 1234.56),
])
def test_student_width_by_hand(value, half, expected):
    from gyro_cli.checking.tolerance import parse_tolerance, rounding, student_width

    one = parse_tolerance("1%", None)
    tight = parse_tolerance("0.001%", None)
    got, _ = student_width(tight, one, value, half, 4)
    assert got == pytest.approx(expected, rel=1e-12)
    # never less than the rounding to four figures: half a unit of the fourth
    assert rounding(991.9231, 4) == pytest.approx(0.05)
    assert rounding(0.0012345, 4) == pytest.approx(5e-7)
