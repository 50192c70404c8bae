"""The minus sign U+2212, which gyro's HTML pages and handouts print and a student copies
from them, reads as '-' (an adversarial pass found `−928.3 rpm` graded `invalid`, 0 points,
where '-928.3 rpm' was graded)."""

from __future__ import annotations

import json
import re

import pytest
from conftest import PROBLEMS

from gyro_cli.core import units

MINUS = "\u2212"


@pytest.mark.parametrize(("text", "number"), [
    (f"{MINUS}965.4 rpm", -965.4), (f"9.654e{MINUS}2 rpm", 9.654e-2),
    (f"{MINUS}1.5E{MINUS}3 m", -1.5e-3), ("-965.4 rpm", -965.4),
])
def test_the_minus_sign_is_a_minus(text, number):
    got, _ = units._split(text, "x")
    assert got == number


def test_en_dash_and_other_dashes_are_still_refused():
    for dash in ("\u2013", "\u2014", "\u2010"):
        with pytest.raises(units.InputError):
            units._split(f"{dash}5 rpm", "x")


def _graded(run, tmp_path, value: str) -> dict:
    sheet = tmp_path / "sheet.csv"
    sheet.write_text(f"student,problem,answer,value\nann,11/3,min_spin,{value}\n",
                     encoding="utf-8")
    done = run("check", "--answers", sheet, PROBLEMS / "11_3.yaml", "--format", "json")
    assert done.exit_code == 0, done.output
    (row,) = json.loads(done.stdout)["rows"]
    return row


def test_a_student_value_with_the_minus_sign_is_graded_as_with_a_hyphen(run, tmp_path):
    hyphen = _graded(run, tmp_path, "-965.4 rpm")
    minus = _graded(run, tmp_path, f"{MINUS}965.4 rpm")
    assert hyphen["result"] == minus["result"] == "wrong"  # the sign slip, not `invalid`
    assert minus["relative_error"] == hyphen["relative_error"]
    assert "the sign" in minus["note"] and "the sign" in hyphen["note"]


def test_a_problem_file_with_the_minus_sign_solves_as_with_a_hyphen(run, tmp_path):
    text = (PROBLEMS / "11_3.yaml").read_text(encoding="utf-8")
    outputs = []
    for sign in ("-", MINUS):
        path = tmp_path / f"top{len(outputs)}.yaml"
        # the spin with a negative exponent: 18000e-1 rpm is the 1800 rpm of the book
        path.write_text(re.sub(r"(?m)^  spin: 1800 rpm", f"  spin: 18000e{sign}1 rpm", text),
                        encoding="utf-8")
        done = run("solve", path, "--format", "json")
        outputs.append((done.exit_code, json.loads(done.stdout)["answers"]
                        if done.exit_code == 0 else done.stderr))
    assert outputs[0][0] == 0 and outputs[0] == outputs[1]
    assert "533.5" in f"{outputs[0][1]['precession']['values'][1]:.4g}"  # the book's 533.5 rpm
