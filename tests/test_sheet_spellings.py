"""Right answers as students write them on a sheet: a unit written once after several
numbers (``45.13; 533.5 rpm``, the way books print roots) and a leading ≈ or ~ before a
rounded value. Both had been graded ``invalid``, 0 points (found and left open by the
fifth session's adversarial passes). The right values are worked out by hand
(test_i38_ecf.hand_11_3: 11/3's roots 45.13 and 533.5 rpm, its least spin 965.4 rpm)."""

from __future__ import annotations

import pytest
from test_i38_ecf import by_answer, hand_11_3, sheet

from gyro_cli.checking import grades
from gyro_cli.checking.grades import written_values

RIGHT = hand_11_3()
SLOW, FAST, LEAST = (f"{RIGHT[k]:.4g}" for k in ("slow", "fast", "min_spin"))
RAD = 60 / (2 * 3.141592653589793)  # rpm per rad/s


def test_hand_values_are_the_books():
    assert (SLOW, FAST, LEAST) == ("45.13", "533.5", "965.4")


@pytest.mark.parametrize("written", [
    f"{SLOW}; {FAST} rpm", f"{SLOW} rpm; {FAST} rpm", f"{FAST}; {SLOW} rpm",
    f"{float(SLOW) / RAD:.4g}; {float(FAST) / RAD:.4g} rad/s",
    f"≈{SLOW} rpm; ~{FAST} rpm", f"≈ {SLOW}; {FAST} rpm",
])
def test_both_roots_right_however_the_unit_is_written(tmp_path, written):
    graded = grades.grade(str(sheet(tmp_path, [("ann", "precession", written)])),
                          [str(_problem())])
    row = by_answer(graded, "ann")["precession"]
    assert row.result == "correct" and row.points == 1, row


@pytest.mark.parametrize("written", [f"≈{LEAST} rpm", f"~{LEAST} rpm", f"≃ {LEAST} rpm"])
def test_about_sign_before_a_right_value(tmp_path, written):
    graded = grades.grade(str(sheet(tmp_path, [("ann", "min_spin", written)])), [str(_problem())])
    assert by_answer(graded, "ann")["min_spin"].result == "correct"


@pytest.mark.parametrize(("written", "result"), [
    # a unit after the first number only: which unit the second has is not written
    (f"{SLOW} rpm; {FAST}", "invalid"),
    # a wrong root stays wrong with the unit written once
    (f"{SLOW}; {float(FAST) * 1.05:.4g} rpm", "partial"),
    # a number with no unit anywhere is no angular rate
    (f"{SLOW}; {FAST}", "invalid"),
])
def test_what_stays_refused(tmp_path, written, result):
    graded = grades.grade(str(sheet(tmp_path, [("ann", "precession", written)])), [str(_problem())])
    assert by_answer(graded, "ann")["precession"].result == result


def test_written_values_keep_yaml_numbers_and_words():
    assert written_values(["1", "2 rpm"]) == ["1 rpm", "2 rpm"]
    assert written_values([3.0, "2 rpm"]) == ["3.0 rpm", "2 rpm"]
    assert written_values(["2 rpm", 3]) == ["2 rpm", 3]
    assert written_values(["stable", " ", "unstable"]) == ["stable", "unstable"]
    assert written_values(["0.5", "2"]) == ["0.5", "2"]
    assert written_values(["1e-3", "2E+02 N m"]) == ["1e-3 N m", "2E+02 N m"]


def test_a_yaml_sheet_reads_the_unit_once_too(tmp_path):
    path = tmp_path / "s.yaml"
    path.write_text(f'ann:\n  "11/3":\n    precession: [{SLOW}, {FAST} rpm]\n')
    graded = grades.grade(str(path), [str(_problem())])
    assert by_answer(graded, "ann")["precession"].result == "correct"


def _problem():
    from conftest import PROBLEMS

    return PROBLEMS / "11_3.yaml"


# ---- word answers: each side a set of words --------------------------------------------

def _words(truth: list[str], written: str) -> grades.GradeRow:
    from types import SimpleNamespace

    row = grades.GradeRow("ann", "p", "motion", written, "", None, "missing", 0.0)
    return grades._grade_words(row, written.split(";"), SimpleNamespace(si_values=truth))


@pytest.mark.parametrize(("truth", "written", "points", "result"), [
    # the solver's word repeated (both roots stable): one wrong word is half the point
    (["stable", "stable"], "unstable; stable", 0.5, "partial"),
    (["stable", "stable"], "stable; cusps", 0.5, "partial"),
    (["stable", "stable"], "stable", 1.0, "correct"),
    (["stable", "stable"], "Stable; stable.", 1.0, "correct"),
    (["stable", "unstable"], "stable", 0.5, "partial"),
    (["stable", "unstable"], "unstable; stable", 1.0, "correct"),
    (["cusps"], "cusp; cusps", 1.0, "correct"),
    (["cusps"], "loops", 0.0, "wrong"),
])
def test_words_are_sets_on_both_sides(truth, written, points, result):
    row = _words(truth, written)
    assert (row.points, row.result) == (points, result), row


def test_a_wrong_stability_word_is_not_full_marks(tmp_path):
    """11/3-stability: both roots stable. `unstable; stable` had been given 1 of 1 point
    (the solver's two `stable` each matched by the student's one); an adversarial pass."""
    from conftest import PROBLEMS

    path = tmp_path / "w.csv"
    path.write_text("student,problem,answer,value\nann,11/3-stability,stability,unstable; stable\n")
    graded = grades.grade(str(path), [str(PROBLEMS / "11_3_stability.yaml")])
    row = by_answer(graded, "ann")["stability"]
    assert row.points == 0.5 and row.result == "partial", row
