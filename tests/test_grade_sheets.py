"""Answer sheets a class really hands in: word answers, malformed values, huge values,
and YAML sheets with the problem files' nesting and alias limits."""

from __future__ import annotations

import csv
import time

import pytest
from conftest import PROBLEMS

from gyro_cli.checking.grades import WORD_SYNONYMS, normal_word

TOPS = [PROBLEMS / name for name in ("11_2_released_top.yaml", "11_2_released_top_loops.yaml",
                                     "11_2_released_top_waves.yaml", "11_3.yaml")]


def rows_of(path):
    with open(path, newline="") as handle:
        return {(r["student"], r["problem"], r["answer"]): r for r in csv.DictReader(handle)
                if r["result"] != "score"}


def test_word_answers_are_graded_as_words(run, tmp_path):
    # The solver's words for these three tops (cusps, loops, waves), written as students do.
    sheet = tmp_path / "sheet.csv"
    sheet.write_text("alice,11.2-released,motion,cusps\n"
                     "alice,11.2-loops,motion,  Looping.\n"
                     "alice,11.2-waves,motion,WAVY\n"
                     "bob,11.2-released,motion,loops\n"
                     "bob,11.2-loops,motion,loop; cusps\n"
                     "bob,11.2-waves,motion,42\n")
    out = tmp_path / "grades.csv"
    result = run("check", "--answers", sheet, *TOPS, "--out", out)
    assert result.exit_code == 0, result.output
    rows = rows_of(out)
    for pid in ("11.2-released", "11.2-loops", "11.2-waves"):
        assert rows[("alice", pid, "motion")]["result"] == "correct"
        assert rows[("alice", pid, "motion")]["points"] == "1"
    assert rows[("bob", "11.2-released", "motion")]["result"] == "wrong"
    assert "expected cusps" in rows[("bob", "11.2-released", "motion")]["note"]
    assert rows[("bob", "11.2-loops", "motion")]["result"] == "partial"  # loop and a wrong word
    assert rows[("bob", "11.2-waves", "motion")]["result"] == "wrong"


def test_synonyms_are_words_of_their_own_answer_only():
    for word, synonyms in WORD_SYNONYMS.items():
        assert word in synonyms
        for other, theirs in WORD_SYNONYMS.items():
            if other != word:
                assert not set(synonyms) & set(theirs)
    assert normal_word("  Steady   Precession. ") == "steady precession"


@pytest.mark.parametrize("value, reason", [
    ("965.4 rpm*", "965.4 rpm*"),
    ("1e308 s", None),            # huge but finite: a wrong answer, graded, no overflow
    ("1e999 rpm", "finite"),
    ("12 parsecs", "parsecs"),
    ("fast", None),
    ("3 m", "expected an angular rate"),
    ("(rpm", "(rpm"),
])
def test_a_malformed_value_grades_that_row_and_the_rest_goes_on(run, tmp_path, value, reason):
    sheet = tmp_path / "sheet.csv"
    sheet.write_text(f"student,problem,answer,value\n"
                     f"ann,11/3,precession,{value}\n"
                     f"ben,11/3,precession,45.1 rpm\n")
    out = tmp_path / "grades.csv"
    result = run("check", "--answers", sheet, PROBLEMS / "11_3.yaml", "--out", out)
    assert result.exit_code == 0, result.output
    assert "Traceback" not in result.output
    rows = rows_of(out)
    ann = rows[("ann", "11/3", "precession")]
    assert ann["result"] in ("invalid", "wrong")
    if reason:
        assert ann["result"] == "invalid" and reason in ann["note"], ann
    assert "inf" not in ann["relative_error"] and "inf" not in ann["note"]
    assert rows[("ben", "11/3", "precession")]["result"] in ("correct", "wrong", "partial")
    json_result = run("check", "--answers", sheet, PROBLEMS / "11_3.yaml", "--format", "json")
    assert json_result.exit_code == 0, json_result.output


def test_a_yaml_sheet_with_an_alias_bomb_is_refused_at_once(run, tmp_path):
    sheet = tmp_path / "sheet.yaml"
    sheet.write_text("a0: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]\n" + "".join(
        f"a{i}: &a{i} [{', '.join([f'*a{i - 1}'] * 9)}]\n" for i in range(1, 10)))
    began = time.monotonic()
    result = run("check", "--answers", sheet, PROBLEMS / "11_3.yaml")
    assert time.monotonic() - began < 10
    assert result.exit_code == 2
    assert result.stderr.count("\n") == 1 and "expand to more than" in result.stderr


def test_a_yaml_sheet_nested_too_deep_is_refused(run, tmp_path):
    sheet = tmp_path / "sheet.yaml"
    sheet.write_text("ann: " + "{a: " * 500 + "1" + "}" * 500 + "\n")
    result = run("check", "--answers", sheet, PROBLEMS / "11_3.yaml")
    assert result.exit_code == 2 and "nested deeper than" in result.stderr
    assert result.stderr.count("\n") == 1


def test_a_yaml_sheet_with_odd_values(run, tmp_path):
    sheet = tmp_path / "sheet.yaml"
    sheet.write_text("ann:\n  '11/3':\n    precession: [.nan, {a: 1}]\n"
                     "2024-02-31:\n  '11/3':\n    precession: 45.1 rpm\n"
                     "cy:\n  '11/3':\n    precession: !!bool yes\n")
    out = tmp_path / "grades.csv"
    result = run("check", "--answers", sheet, PROBLEMS / "11_3.yaml", "--out", out)
    assert result.exit_code == 0, result.output
    rows = rows_of(out)
    assert rows[("ann", "11/3", "precession")]["result"] == "invalid"
    assert rows[("2024-02-31", "11/3", "precession")]["result"] != "invalid"
    assert rows[("cy", "11/3", "precession")]["result"] == "invalid"
