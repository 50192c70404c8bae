"""One rule for "the same answer" in an answer sheet: values read as the answer's
quantity. An adversarial pass found `991.9 rpm` and `991.9rpm` under a problem's id and its
variant's id refused as different answers, and the same two in two rows of one id graded as
two roots; the old text comparison, which ignored case, also took `mrad/s` for `Mrad/s`."""

from __future__ import annotations

import csv
import re
from pathlib import Path

import pytest
from conftest import PROBLEMS, class_set

HEAD = "student,problem,answer,value\n"


@pytest.fixture
def homework(run, tmp_path: Path) -> Path:
    return class_set(run, tmp_path, ["ann"])


def _variant(assignment: Path) -> str:
    with open(assignment, newline="") as handle:
        (row,) = list(csv.DictReader(handle))
    return row["variant"]


def _check(run, tmp_path, assignment, rows: str):
    sheet = tmp_path / "sheet.csv"
    sheet.write_text(HEAD + rows)
    return run("check", "--answers", sheet, "--assignment", assignment)


def _ann_scores(result) -> str:
    assert result.exit_code == 0, result.output
    found = re.search(r"ann\s+score (\S+ / \S+)", result.stdout)
    assert found, result.stdout
    return found.group(1)


def test_the_right_answer_alone_scores_its_point(run, tmp_path, homework):
    # the reference for the tests below: 991.9 rpm is ann's min_spin (seed 7)
    assert _ann_scores(_check(run, tmp_path, homework, "ann,11/3,min_spin,991.9 rpm\n")) \
        == "1 / 2"


@pytest.mark.parametrize("again", ["991.9rpm", "991.9 RPM", " 991.9   rpm ", "99.19e1 rpm"])
def test_one_quantity_under_both_ids_counts_once(run, tmp_path, homework, again):
    rows = f"ann,11/3,min_spin,991.9 rpm\nann,{_variant(homework)},min_spin,{again}\n"
    assert _ann_scores(_check(run, tmp_path, homework, rows)) == "1 / 2"


@pytest.mark.parametrize(("first", "again"), [("103871.5 mrad/s", "103871.5 Mrad/s"),
                                              ("991.9 rpm", "991.8 rpm")])
def test_different_quantities_under_both_ids_are_refused(run, tmp_path, homework, first,
                                                         again):
    rows = f"ann,11/3,min_spin,{first}\nann,{_variant(homework)},min_spin,{again}\n"
    result = _check(run, tmp_path, homework, rows)
    assert result.exit_code == 2, result.output
    (line,) = result.stderr.splitlines()
    assert "twice" in line and "lines 2 and 3" in line and "different values" in line, line


@pytest.mark.parametrize("again", ["991.9rpm", "991.9 RPM", "99.19e1 rpm"])
def test_one_quantity_in_two_rows_of_one_id_is_refused_as_a_repeat(run, tmp_path, homework,
                                                                   again):
    result = _check(run, tmp_path, homework,
                    f"ann,11/3,min_spin,991.9 rpm\nann,11/3,min_spin,{again}\n")
    assert result.exit_code == 2, result.output
    (line,) = result.stderr.splitlines()
    assert "sheet.csv" in line and "line 3" in line and "values of line 2 again" in line, line


def test_two_different_values_in_two_rows_are_still_two_roots(run, tmp_path, homework):
    # one right root and one more: not a repeat, graded as the roots given (not full marks)
    result = _check(run, tmp_path, homework,
                    "ann,11/3,min_spin,991.9 rpm\nann,11/3,min_spin,500 rpm\n")
    assert _ann_scores(result) != "1 / 2"


def test_without_an_assignment_a_repeat_is_refused_too(run, tmp_path):
    sheet = tmp_path / "sheet.csv"
    sheet.write_text(HEAD + "ann,11/3,min_spin,991.9 rpm\nann,11/3,min_spin,991.9rpm\n")
    result = run("check", "--answers", sheet, PROBLEMS / "11_3.yaml")
    assert result.exit_code == 2, result.output
    assert "values of line 2 again" in result.stderr and "line 3" in result.stderr


@pytest.fixture
def motor(run, tmp_path: Path) -> tuple[Path, str, str]:
    """11/5 for one student: the assignment and ann's forces at A and B as solved."""
    import json

    assignment = class_set(run, tmp_path, ["ann"], PROBLEMS / "11_5.yaml", name="hw5")
    key = json.loads((assignment.parent / "key.json").read_text())
    (entry,) = key["variants"].values()
    a, b = entry["answers"]["bearing_forces"]["values"]
    assert entry["answers"]["bearing_forces"]["labels"] == ["A", "B"]
    return assignment, f"{a:.4g} N", f"{b:.4g} N"


def test_an_ordered_answer_in_two_orders_under_both_ids_is_two_answers(run, tmp_path, motor):
    """A then B, and B then A, are different answers to 11/5 (a second adversarial pass
    found them taken as one, so the row that came first decided the grade)."""
    assignment, a, b = motor
    variant = _variant(assignment)
    for first, second in (((a, b), (b, a)), ((b, a), (a, b))):
        rows = (f"ann,11/5,bearing_forces,{first[0]}; {first[1]}\n"
                f"ann,{variant},bearing_forces,{second[0]}; {second[1]}\n")
        result = _check(run, tmp_path, assignment, rows)
        assert result.exit_code == 2, result.output
        assert "different values" in result.stderr
    same = f"ann,11/5,bearing_forces,{a}; {b}\nann,{variant},bearing_forces,{a}; {b}\n"
    assert _ann_scores(_check(run, tmp_path, assignment, same)) == "1 / 1"


def test_an_ordered_answer_in_two_orders_in_two_rows_is_no_repeat(run, tmp_path, motor):
    assignment, a, b = motor
    result = _check(run, tmp_path, assignment, f"ann,11/5,bearing_forces,{a}; {b}\n"
                                               f"ann,11/5,bearing_forces,{b}; {a}\n")
    assert result.exit_code == 0 and "again" not in result.stderr, result.output


def test_a_step_asked_is_compared_as_a_quantity(run, tmp_path):
    """`steps: [I]`: 1.776e-4 kg m^2 and 1.776e-04 kg*m^2 are one value (they had been
    compared as text and merged as two roots, halving the point)."""
    path = tmp_path / "t3.yaml"
    path.write_text((PROBLEMS / "11_3.yaml").read_text()
                    .replace("tolerance: 1%\n", "tolerance: 1%\nsteps: [I]\n"))
    sheet = tmp_path / "sheet.csv"
    sheet.write_text(HEAD + "ann,11/3,I,1.776e-4 kg m^2\nann,11/3,I,1.776e-04 kg*m^2\n")
    result = run("check", "--answers", sheet, path)
    assert result.exit_code == 2, result.output
    assert "values of line 2 again" in result.stderr and "line 3" in result.stderr
    sheet.write_text(HEAD + "ann,11/3,I,1.776e-4 kg m^2\nann,11/3,I,1.776e-4 kg\n")
    result = run("check", "--answers", sheet, path)  # another dimension: not a repeat
    assert result.exit_code == 0, result.output
