"""A stray quote in a roster or an answer sheet is refused, naming its line (an adversarial
pass found it folding the rows after it into one cell, silently: classmates graded
missing, their answers shown in one student's feedback; a roster's students dropped)."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from conftest import PROBLEMS

from gyro_cli.core.csvsafe import CellRunsOn, one_line_rows

ROSTER = "student,name\nann,Ann\nbob,Bob\ncat,Cat\n"


def _one_line(result, line: int) -> str:
    assert result.exit_code == 2, result.output
    lines = result.stderr.splitlines()
    assert len(lines) == 1 and f"line {line}: a cell runs over a line break" in lines[0], lines
    return lines[0]


@pytest.fixture
def homework(run, tmp_path: Path) -> Path:
    (tmp_path / "roster.csv").write_text(ROSTER)
    done = run("vary", PROBLEMS / "11_3.yaml", "--roster", tmp_path / "roster.csv",
               "--seed", "7", "-o", tmp_path / "hw")
    assert done.exit_code == 0, done.output
    return tmp_path / "hw" / "assignment.csv"


@pytest.mark.parametrize(("sheet", "line"), [
    ('ann,11/3,min_spin,"991.9 rpm\nbob,11/3,min_spin,941.8 rpm\ncat,11/3,min_spin,945.1 rpm\n', 2),
    ('ann,11/3,min_spin,991.9 rpm\nbob,11/3,"min_spin\n",941.8 rpm\n', 3),
    ('ann,11/3,min_spin,"991.9 rpm"\nbob,11/3,min_spin,"941.8\r\nrpm"\n', 3),
])
def test_a_sheet_cell_over_a_line_break_is_refused_and_nothing_written(run, tmp_path, homework,
                                                                         sheet, line):
    path = tmp_path / "sheet.csv"
    path.write_text("student,problem,answer,value\n" + sheet, newline="")
    out, feedback = tmp_path / "grades.csv", tmp_path / "fb"
    result = run("check", "--answers", path, "--assignment", homework, "--out", out,
                 "--feedback", feedback)
    assert str(path) in _one_line(result, line)
    assert not out.exists() and not feedback.exists()


def test_the_same_sheet_with_its_quote_closed_grades_every_student(run, tmp_path, homework):
    path = tmp_path / "sheet.csv"
    path.write_text("student,problem,answer,value\nann,11/3,min_spin,\"991.9 rpm\"\n"
                    "bob,11/3,min_spin,941.8 rpm\n")
    result = run("check", "--answers", path, "--assignment", homework)
    # each answered min_spin (right for seed 7) and no precession: one of two points each
    assert re.search(r"ann\s+score 1 / 2", result.stdout), result.stdout
    assert re.search(r"bob\s+score 1 / 2", result.stdout), result.stdout


@pytest.mark.parametrize(("roster", "line"), [
    ('student,name,section\nann,Ann,"A\nbob,Bob,B\ncat,Cat,C\n', 2),
    ('student,name,section\nann,Ann,A\nbob,Bob,"B\n"\n', 3),
])
def test_a_roster_cell_over_a_line_break_is_refused_and_nothing_written(run, tmp_path, roster,
                                                                          line):
    path = tmp_path / "roster.csv"
    path.write_text(roster)
    result = run("vary", PROBLEMS / "11_3.yaml", "--roster", path, "-o", tmp_path / "hw")
    assert str(path) in _one_line(result, line)
    assert not (tmp_path / "hw").exists()


def test_rows_keep_the_line_they_start_on():
    assert one_line_rows('a,b\n\n"x,y",z\r\nq,r\n') == [(1, ["a", "b"]), (2, []),
                                                       (3, ["x,y", "z"]), (4, ["q", "r"])]
    with pytest.raises(CellRunsOn) as err:
        one_line_rows('a,b\nc,"d\ne"\nf,g\n')
    assert err.value.line == 2
