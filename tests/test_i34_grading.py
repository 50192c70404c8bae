"""Issue 34, grading by assignment: variant ids, one question under two ids, the stored
key, handout's validation of an assignment, and grading inside an autograder (--student).

The right answers are worked by hand from each student's variant file (test_course.by_hand:
the quadratic of Eq. 11.13 and the least spin of Eq. 11.21), not taken from the solver.
"""

from __future__ import annotations

import csv
import json
from pathlib import Path

import yaml
from test_check import put
from test_course import TOP, assignment_rows, by_hand, make_set


def _answers(out: Path, student: str, problem_dir: str = "11_3") -> tuple[list[float], float]:
    return by_hand(yaml.safe_load((out / problem_dir / f"{student}.yaml").read_text()))


def _roots(roots: list[float]) -> str:
    return f"{roots[0]:.4g} rpm; {roots[1]:.4g} rpm"


def _json(result) -> dict:
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


# ---- item 2: a variant id equal to another problem's id ------------------------------------

def _p1_set(run, tmp_path: Path) -> Path:
    """Problems P1 and P1-2 (the 11/3 top under two ids), students 1, 2 and 2-1 (whose P1
    would be P1-2-1, as would student 1's P1-2)."""
    text = TOP.read_text()
    put(tmp_path, "p1.yaml", text.replace('id: "11/3"', 'id: "P1"'))
    put(tmp_path, "p1_2.yaml", text.replace('id: "11/3"', 'id: "P1-2"'))
    put(tmp_path, "r.csv", "student\n1\n2\n2-1\n")
    out = tmp_path / "hw"
    result = run("vary", tmp_path / "p1.yaml", tmp_path / "p1_2.yaml", "--roster",
                 tmp_path / "r.csv", "-o", out)
    assert result.exit_code == 0, result.output
    return out


def test_item02_variant_ids_never_equal_a_problem_id(run, tmp_path):
    out = _p1_set(run, tmp_path)
    rows = assignment_rows(out)
    variants = {(r["student"], r["problem"]): r["variant"] for r in rows}
    assert not set(variants.values()) & {"P1", "P1-2"}
    assert len(set(variants.values())) == len(rows) == 6
    assert variants[("1", "P1")] == "P1-1"  # the plain id where nothing collides
    for r in rows:  # each file holds the id its row names
        assert yaml.safe_load((out / r["file"]).read_text())["id"] == r["variant"]
    # student 2 answers P1 under their own variant id and P1-2 under the problem's id
    p1_roots, p1_least = _answers(out, "2", "p1")
    q_roots, q_least = _answers(out, "2", "p1_2")
    mine = variants[("2", "P1")]
    sheet = put(tmp_path, "s.csv", f"2,{mine},precession,{_roots(p1_roots)}\n"
                                   f"2,{mine},min_spin,{p1_least:.4g} rpm\n"
                                   f"2,P1-2,precession,{_roots(q_roots)}\n"
                                   f"2,P1-2,min_spin,{q_least:.4g} rpm\n")
    data = _json(run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
                     "--format", "json"))
    assert data["scores"]["2"] == {"points": 4.0, "max_points": 4.0}


def test_item02_a_sheet_id_that_is_a_problem_and_a_variant_is_refused(run, tmp_path):
    # an assignment made before variant ids avoided problem ids: student 2's P1 is P1-2
    out = _p1_set(run, tmp_path)
    path = out / "assignment.csv"
    rows = assignment_rows(out)
    for r in rows:
        if (r["student"], r["problem"]) == ("2", "P1"):
            variant_file = out / r["file"]
            data = yaml.safe_load(variant_file.read_text())
            data["id"] = r["variant"] = "P1-2"
            variant_file.write_text(yaml.safe_dump(data, sort_keys=False))
    with open(path, "w", newline="") as handle:
        writer = csv.DictWriter(handle, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    roots, _ = _answers(out, "2", "p1")
    sheet = put(tmp_path, "s.csv", f"1,P1,min_spin,900 rpm\n2,P1-2,precession,{_roots(roots)}\n")
    result = run("check", "--answers", sheet, "--assignment", path)
    assert result.exit_code == 2, result.output
    message = result.stderr.strip()
    assert len(message.splitlines()) == 1
    assert "line 2" in message and "problem P1-2" in message
    assert "student 2's variant of problem P1" in message


# ---- item 3: the same answer under both ids ------------------------------------------------

def test_item03_one_question_under_two_ids_counts_once(run, tmp_path):
    out = make_set(run, tmp_path, 2, TOP)
    roots, least = _answers(out, "s000")
    sheet = put(tmp_path, "s.csv", f"s000,11/3,precession,{_roots(roots)}\n"
                                   f"s000,11/3-s000,precession,{_roots(roots)}\n"
                                   f"s000,11/3-s000,min_spin,{least:.4g} rpm\n"
                                   f"s000,11/3,min_spin, {least:.4g}  rpm\n")
    data = _json(run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
                     "--format", "json"))
    mine = {r["answer"]: r for r in data["rows"] if r["student"] == "s000"}
    assert mine["precession"]["result"] == "correct" and mine["precession"]["points"] == 1
    assert data["scores"]["s000"] == {"points": 2.0, "max_points": 2.0}


def test_item03_differing_answers_under_two_ids_are_refused(run, tmp_path):
    out = make_set(run, tmp_path, 2, TOP)
    roots, _ = _answers(out, "s000")
    sheet = put(tmp_path, "s.csv", f"s001,11/3,min_spin,900 rpm\n"
                                   f"s000,11/3,precession,{_roots(roots)}\n"
                                   f"s000,11/3-s000,precession,{roots[0]:.4g} rpm\n")
    result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv")
    assert result.exit_code == 2, result.output
    message = result.stderr.strip()
    assert len(message.splitlines()) == 1
    assert "lines 2 and 3" in message and "'11/3'" in message and "'11/3-s000'" in message


# ---- items 4 and 5: the stored key is used only when it verifies ---------------------------

def _key_case(run, tmp_path):
    out = make_set(run, tmp_path, 2, TOP)
    roots, least = _answers(out, "s000")
    key_path = out / "key.json"
    return out, key_path, json.loads(key_path.read_text()), roots, least


def _grade(run, out: Path, sheet: Path):
    return run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
               "--format", "json")


def test_item04_an_edited_key_answer_is_not_trusted(run, tmp_path):
    out, key_path, key, roots, least = _key_case(run, tmp_path)
    answer = key["variants"]["11/3-s000"]["answers"]["min_spin"]
    answer["values"] = [500.0]
    answer["si_values"] = [500.0 * 2 * 3.141592653589793 / 60]
    key_path.write_text(json.dumps(key))
    sheet = put(tmp_path, "s.csv", "s000,11/3,min_spin,500 rpm\n")
    result = _grade(run, out, sheet)
    data = _json(result)
    row = next(r for r in data["rows"] if r["student"] == "s000" and r["answer"] == "min_spin")
    assert row["result"] == "wrong" and "500" not in row["correct"]
    assert "key.json does not verify" in result.stderr
    right = put(tmp_path, "r.csv", f"s000,11/3,min_spin,{least:.4g} rpm\n")
    data = _json(_grade(run, out, right))
    assert data["scores"]["s000"]["points"] == 1.0


def test_item05_a_damaged_key_is_ignored_and_the_variants_solved(run, tmp_path):
    out, key_path, key, roots, least = _key_case(run, tmp_path)
    sheet = put(tmp_path, "s.csv", f"s000,11/3,precession,{_roots(roots)}\n"
                                   f"s000,11/3,min_spin,{least:.4g} rpm\n")
    original = key_path.read_text()
    deleted = json.loads(original)
    del deleted["variants"]["11/3-s000"]["answers"]["min_spin"]
    no_answers = json.loads(original)
    no_answers["variants"]["11/3-s000"]["answers"] = 5
    listed = json.loads(original)
    listed["variants"] = [listed["variants"]]
    bad_problem = json.loads(original)
    bad_problem["problems"]["11/3"]["questions"] = "precession"
    unhashable = json.loads(original)
    unhashable["variants"]["11/3-s000"]["problem"] = ["11/3"]
    assert '"values": [' in original
    damaged = [json.dumps(deleted), original[: len(original) // 2], json.dumps(no_answers),
               json.dumps(listed), json.dumps(bad_problem), json.dumps(unhashable), "[]",
               "null", original.replace('"values": [', '"values": [NaN, ', 1)]
    for text in damaged:
        key_path.write_text(text)
        result = _grade(run, out, sheet)
        assert result.exit_code == 0, (text[:80], result.output)
        assert json.loads(result.stdout)["scores"]["s000"]["points"] == 2.0
        assert result.stderr.count("key.json does not verify") == 1, result.stderr
    other_code = json.loads(original)
    other_code["code"] = "0" * 64  # a key of another gyro version: solved again, said so
    key_path.write_text(json.dumps(other_code))
    result = _grade(run, out, sheet)
    assert json.loads(result.stdout)["scores"]["s000"]["points"] == 2.0
    assert "key.json was written by other gyro code" in result.stderr
    key_path.write_text(original)  # the key as written: used, without a note
    result = _grade(run, out, sheet)
    assert result.exit_code == 0 and "key.json" not in result.stderr


# ---- item 6: one validation of an assignment row for check and handout ---------------------

def test_item06_handout_refuses_a_row_check_refuses(run, tmp_path):
    out = make_set(run, tmp_path, 2, TOP)
    path = out / "assignment.csv"
    text = path.read_text()
    # s000's row now points at s001's file: s000 would be handed s001's numbers
    path.write_text(text.replace("11/3-s000,11_3/s000.yaml", "11/3-s000,11_3/s001.yaml"))
    sheet = put(tmp_path, "s.csv", "s000,11/3,min_spin,900 rpm\n")
    checked = run("check", "--answers", sheet, "--assignment", path)
    handed = run("handout", "--assignment", path, "-o", tmp_path / "sheets" / "hw.html")
    assert checked.exit_code == 2 and handed.exit_code == 2, handed.output
    assert handed.stderr == checked.stderr
    assert "line 2" in handed.stderr and "'11/3-s001'" in handed.stderr
    assert not (tmp_path / "sheets").exists()


# ---- item 17: --student, the submitter inside an autograder --------------------------------

def test_item17_a_sheet_naming_another_student_is_refused(run, tmp_path):
    out = make_set(run, tmp_path, 2, TOP)
    roots, least = _answers(out, "s001")
    sheet = put(tmp_path, "s.csv", f"s001,11/3,precession,{_roots(roots)}\n"
                                   f"s001,11/3,min_spin,{least:.4g} rpm\n")
    result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
                 "--student", "s000", "--out", tmp_path / "results.json",
                 "--out-format", "gradescope")
    assert result.exit_code == 2, result.output
    assert len(result.stderr.strip().splitlines()) == 1
    assert "line 1" in result.stderr and "'s001'" in result.stderr and "'s000'" in result.stderr
    assert not (tmp_path / "results.json").exists()
    stranger = run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
                   "--student", "zed")
    assert stranger.exit_code == 2 and "'zed'" in stranger.stderr


def test_item17_only_the_submitter_is_graded_and_no_solver_value_shown(run, tmp_path):
    out = make_set(run, tmp_path, 3, TOP)
    roots, least = _answers(out, "s000")
    sheet = put(tmp_path, "s.csv", f"s000,11/3,precession,{roots[0]:.4g} rpm\n"
                                   f"s000,11/3,min_spin,{least * 1.2:.4g} rpm\n")
    assignment = out / "assignment.csv"
    result = run("check", "--answers", sheet, "--assignment", assignment, "--student", "s000")
    assert result.exit_code == 0, result.output
    solver_values = []
    for student in ("s000", "s001", "s002"):
        other_roots, other_least = _answers(out, student)
        solver_values += [f"{v:.4g}" for v in other_roots + [other_least]]
        variant = yaml.safe_load((out / "11_3" / f"{student}.yaml").read_text())
        solver_values += [str(v).split()[0] for k, v in variant["expected"].items()
                          for v in (v if isinstance(v, list) else [v])]
    shown = result.stdout.replace(f"{roots[0]:.4g} rpm", "")  # what s000 submitted
    assert "s001" not in shown and "s002" not in shown and "solver" not in shown
    for value in solver_values:
        assert value not in shown, value
    assert "s000" in shown and "score 0.5 / 2" in shown
    assert "a root is missing" in shown and "off by" not in shown  # off by 20%: the answer
    # s000 hands in s001's numbers: their page does not say (or confirm) whose they are
    _, copied_least = _answers(out, "s001")
    copied = put(tmp_path, "c.csv", f"s000,11/3,min_spin,{copied_least:.4g} rpm\n")
    result = run("check", "--answers", copied, "--assignment", assignment)
    assert "student s001's variant" in result.stdout  # the teacher's report says so
    result = run("check", "--answers", copied, "--assignment", assignment, "--student", "s000")
    assert result.exit_code == 0 and "s001" not in result.stdout, result.output
    data = _json(run("check", "--answers", sheet, "--assignment", assignment, "--student",
                     "s000", "--format", "json"))
    assert list(data["scores"]) == ["s000"] and {r["student"] for r in data["rows"]} == {"s000"}
    assert all(r["correct"] == "" and r["relative_error"] is None for r in data["rows"])
    target = tmp_path / "results.json"
    empty = put(tmp_path, "empty.csv", "")  # a submission with nothing in it is still graded
    for fmt in ("gradescope", "prairielearn"):
        for answers in (sheet, empty):
            result = run("check", "--answers", answers, "--assignment", assignment, "--student",
                         "s000", "--out", target, "--out-format", fmt, "--force")
            assert result.exit_code == 0, result.output
            written = target.read_text()
            for value in solver_values:
                assert value not in written.replace(f"{roots[0]:.4g} rpm", ""), (fmt, value)
            assert "s001" not in written and "s002" not in written
    assert json.loads(written)["score"] == 0


def test_item17_reveal_shows_the_submitters_own_answers_only(run, tmp_path):
    """After the due date (--reveal) the submitter sees their own variant's answers (worked
    by hand here), still nobody else's."""
    out = make_set(run, tmp_path, 3, TOP)
    roots, least = _answers(out, "s000")
    sheet = put(tmp_path, "s.csv", f"s000,11/3,min_spin,{least * 1.2:.4g} rpm\n")
    data = _json(run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
                     "--student", "s000", "--reveal", "--out", tmp_path / "r.json",
                     "--out-format", "gradescope", "--format", "json"))
    row = next(r for r in data["rows"] if r["answer"] == "min_spin")
    assert abs(float(row["correct"].split()[0]) / least - 1) < 1e-3
    assert abs(row["relative_error"] - 0.2) < 1e-3
    written = (tmp_path / "r.json").read_text()
    assert f"{least:.4g}" in written
    for student in ("s001", "s002"):
        other_roots, other_least = _answers(out, student)
        for value in other_roots + [other_least]:
            assert f"{value:.4g}" not in written and f"{value:.4g}" not in json.dumps(data)


def test_item17_the_submitter_is_matched_by_nfc(run, tmp_path):
    """--student typed in NFD names the roster's NFC student, not a stranger."""
    import unicodedata

    put(tmp_path, "r.csv", "student\ncafé\n")
    out = tmp_path / "hw"
    assert run("vary", TOP, "--roster", tmp_path / "r.csv", "-o", out).exit_code == 0
    rows = assignment_rows(out)
    least = by_hand(yaml.safe_load((out / rows[0]["file"]).read_text()))[1]
    sheet = put(tmp_path, "s.csv", f"café,11/3,min_spin,{least:.4g} rpm\n")
    data = _json(run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
                     "--student", unicodedata.normalize("NFD", "café"), "--format", "json"))
    assert list(data["scores"]) == ["café"]
    assert data["scores"]["café"]["points"] == 1
