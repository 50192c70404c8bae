"""`gyro check --out F --feedback DIR` writes its files as one set: a refusal of either
(a feedback page that exists, an input in the way) comes before anything is written (an
adversarial pass found the grades file written, then --feedback refused with exit 2)."""

from __future__ import annotations

from pathlib import Path

import pytest
from conftest import class_set


@pytest.fixture
def homework(run, tmp_path: Path) -> Path:
    assignment = class_set(run, tmp_path, ["ann", "bob"])
    sheet = tmp_path / "sheet.csv"
    sheet.write_text("student,problem,answer,value\nann,11/3,min_spin,991.9 rpm\n"
                     "bob,11/3,min_spin,941.8 rpm\n")
    return assignment


def _refused(result, name: str) -> None:
    assert result.exit_code == 2, result.output
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and name in lines[0] and "exists" in lines[0], lines


@pytest.mark.parametrize("fmt", ["grades", "canvas", "gradescope", "prairielearn"])
def test_a_refused_feedback_page_leaves_no_out_behind(run, tmp_path, homework, fmt):
    feedback = tmp_path / "fb"
    feedback.mkdir()
    (feedback / "bob.md").write_text("last week's page\n")
    out = tmp_path / ("grades.csv" if fmt in ("grades", "canvas") else fmt)
    result = run("check", "--answers", tmp_path / "sheet.csv", "--assignment", homework,
                 "--out", out, "--out-format", fmt, "--feedback", feedback)
    _refused(result, "bob.md")
    assert not out.exists()
    assert sorted(p.name for p in feedback.iterdir()) == ["bob.md"]
    assert (feedback / "bob.md").read_text() == "last week's page\n"


def test_a_refused_out_leaves_no_feedback_behind(run, tmp_path, homework):
    out = tmp_path / "grades.csv"
    out.write_text("last week's grades\n")
    feedback = tmp_path / "fb"
    result = run("check", "--answers", tmp_path / "sheet.csv", "--assignment", homework,
                 "--out", out, "--feedback", feedback)
    _refused(result, "grades.csv")
    assert out.read_text() == "last week's grades\n" and not feedback.exists()


def test_with_force_both_are_written(run, tmp_path, homework):
    feedback = tmp_path / "fb"
    feedback.mkdir()
    (feedback / "bob.md").write_text("last week's page\n")
    out = tmp_path / "grades.csv"
    result = run("check", "--answers", tmp_path / "sheet.csv", "--assignment", homework,
                 "--out", out, "--feedback", feedback, "--force")
    assert result.exit_code == 0, result.output
    assert out.read_text().startswith("student,")
    assert sorted(p.name for p in feedback.iterdir()) == ["ann.md", "bob.md"]
    assert "# Feedback for bob" in (feedback / "bob.md").read_text()


def test_out_and_feedback_naming_one_file_is_refused(run, tmp_path, homework):
    feedback = tmp_path / "fb"
    result = run("check", "--answers", tmp_path / "sheet.csv", "--assignment", homework,
                 "--out", feedback / "ann.md", "--feedback", feedback)
    assert result.exit_code == 2, result.output
    assert "would both write" in result.stderr and not feedback.exists()


def test_a_submitter_cannot_tell_a_classmates_variant_id_from_an_unknown_one(run, tmp_path,
                                                                           homework):
    """Inside an autograder (--student) another student's variant id had been graded ("on
    your own variant") and an unknown one refused: trying ids told who is enrolled (an
    adversarial pass). Now both are refused in the same words; the teacher's own run
    still grades the classmate's id (on the student's own variant)."""
    import csv

    with open(homework, newline="") as handle:
        variant = {row["student"]: row["variant"] for row in csv.DictReader(handle)}
    told = []
    for pid in (variant["bob"], "11/3-nobody"):
        sheet = tmp_path / "mine.csv"
        sheet.write_text(f"student,problem,answer,value\nann,{pid},min_spin,991.9 rpm\n")
        result = run("check", "--answers", sheet, "--assignment", homework, "--student", "ann")
        assert result.exit_code == 2, result.output
        (line,) = result.stderr.splitlines()
        told.append(line.replace(repr(pid), "ID"))
    assert told[0] == told[1] and "one of their own variants" in told[0], told
    sheet = tmp_path / "teacher.csv"
    sheet.write_text(f"student,problem,answer,value\nann,{variant['bob']},min_spin,991.9 rpm\n")
    result = run("check", "--answers", sheet, "--assignment", homework)
    assert result.exit_code == 0 and "ann          score 1 / 2" in result.stdout, result.output


@pytest.mark.parametrize("damage", ["missing", "broken"])
def test_a_classmates_broken_variant_neither_stops_nor_is_named_to_a_submitter(
        run, tmp_path, homework, damage):
    """--student grades the submitter's own variants alone: a classmate's variant file,
    deleted or not YAML, had stopped the submitter's grading (exit 2) with a line naming
    the classmate's file (a second adversarial pass)."""
    bob = homework.parent / "11_3" / "bob.yaml"
    if damage == "missing":
        bob.unlink()
    else:
        bob.write_text("given: [unclosed\n")
    sheet = tmp_path / "mine.csv"
    sheet.write_text("student,problem,answer,value\nann,11/3,min_spin,991.9 rpm\n")
    result = run("check", "--answers", sheet, "--assignment", homework, "--student", "ann")
    assert result.exit_code == 0, result.output
    assert "bob" not in result.output and "ann" in result.stdout
    assert "score 1 / 2" in result.stdout
    # the teacher's own run is stopped by it, naming the file
    result = run("check", "--answers", sheet, "--assignment", homework)
    assert result.exit_code == 2 and "bob.yaml" in result.stderr
