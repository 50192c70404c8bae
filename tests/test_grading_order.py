"""An answer whose values have places (11/5's forces at A and B) given in the other order:
the feedback says the order, not "too high; too low" (an adversarial pass found the
order slip `matching.compare` finds thrown away), and names no solver value."""

from __future__ import annotations

import json

from conftest import PROBLEMS

from gyro_cli.solving.problem import load


def _rows(run, tmp_path, lines: str) -> dict[str, dict]:
    sheet = tmp_path / "sheet.csv"
    sheet.write_text("student,problem,answer,value\n" + lines)
    done = run("check", "--answers", sheet, PROBLEMS / "11_5.yaml", "--format", "json")
    assert done.exit_code == 0, done.output
    return {r["student"]: r for r in json.loads(done.stdout)["rows"]}


def test_forces_given_b_first_are_said_to_be_out_of_order(run, tmp_path):
    # 11/5 by hand (docs: the book's answers): A 35.15 N, B 62.95 N
    rows = _rows(run, tmp_path, "ann,11/5,bearing_forces,62.95 N; 35.15 N\n"
                                "cat,11/5,bearing_forces,35.15 N; 62.95 N\n")
    assert rows["cat"]["result"] == "correct"
    ann = rows["ann"]
    assert ann["result"] == "wrong" and ann["points"] == 0
    assert ann["feedback"].count("not in its place") == 2, ann["feedback"]
    assert "the answer lists A, B in that order" in ann["feedback"]
    assert "too high" not in ann["feedback"] and "too low" not in ann["feedback"]
    assert "is the computed B" in ann["note"]  # the teacher's note says which
    # the student's words hold no value but their own
    for number in ("35.15", "62.95"):
        assert ann["feedback"].count(number) == 1


def test_the_statement_says_which_force_is_first_and_which_way_is_positive():
    statement = load(str(PROBLEMS / "11_5.yaml")).statement
    assert "A first" in statement and "upward positive" in statement
    assert "from A to B" in statement  # what the spin's sign means
