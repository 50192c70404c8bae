"""A platform's download regraded fairly (an adversarial pass): Canvas's highest attempt
whatever the rows' order, a blank attempt graded 0 (not left out of the grades), each
student's Canvas id and name in the gradebook file, no student silently replaced by
another; Moodle's numbers read as Moodle reads them (`965,4`, `9.654x10^2`), attempts
not finished left ungraded, and two students of one name never merged."""

from __future__ import annotations

import csv
import json
import xml.etree.ElementTree as ET
import zipfile
from pathlib import Path

import pytest
from test_i38_ecf_more import PROBLEM_11_3
from test_i38_regrade import HEADER, blanks, canvas_analysis, qti_questions


@pytest.fixture
def canvas(run, tmp_path: Path) -> tuple[Path, list[str], list[str]]:
    """11/3 exported as QTI: the problem, its questions' texts and the right typed values."""
    problem = tmp_path / "p11_3.yaml"
    problem.write_text(PROBLEM_11_3)
    package = tmp_path / "bank.zip"
    assert run("export", "--to", "qti", problem, "-o", package).exit_code == 0
    with zipfile.ZipFile(package) as z:
        name = next(n for n in z.namelist() if n.endswith(".xml") and "manifest" not in n)
        root = ET.fromstring(z.read(name))
    right = [f"{float(el.text):.5g}" for el in root.iter() if el.tag.endswith("varequal")]
    texts = qti_questions(package)
    assert len(right) == len(texts) == 3
    return problem, texts, right


def _scores(run, path: Path, problem: Path, platform: str = "canvas",
            *options: str) -> dict[str, float]:
    """Each student's points in a regrade of a platform's download."""
    done = run("check", "--answers", path, "--responses", platform, problem, *options,
               "--format", "json")
    assert done.exit_code == 0, done.output
    return {s: v["points"] for s, v in json.loads(done.stdout)["scores"].items()}


def test_canvas_the_highest_attempt_counts_in_any_row_order(run, tmp_path, canvas):
    problem, texts, right = canvas
    wrong = ["1", "1", "1"]
    rows = [["Ann Lee", "101", "S1", "2", *right], ["Ann Lee", "101", "S1", "1", *wrong]]
    assert _scores(run, canvas_analysis(tmp_path, texts, rows), problem) == {"S1": 2.0}
    rows.reverse()  # the same attempts in the other order
    assert _scores(run, canvas_analysis(tmp_path, texts, rows), problem) == {"S1": 2.0}


def test_canvas_a_blank_attempt_is_graded_zero_not_left_out(run, tmp_path, canvas):
    problem, texts, right = canvas
    rows = [["Ann Lee", "101", "S1", "1", *right], ["Bob Roe", "102", "S2", "1", "", "", ""]]
    assert _scores(run, canvas_analysis(tmp_path, texts, rows), problem) == {"S1": 2.0, "S2": 0.0}


def test_canvas_ids_and_names_go_to_their_gradebook_columns(run, tmp_path, canvas):
    problem, texts, right = canvas
    rows = [["Ann Lee", "101", "S1", "1", *right], ["Bob Roe", "102", "", "1", *right]]
    out = tmp_path / "quiz.csv"
    done = run("check", "--answers", canvas_analysis(tmp_path, texts, rows), "--responses",
               "canvas", problem, "--out", out, "--out-format", "canvas")
    assert done.exit_code == 0, done.output
    with open(out, newline="") as handle:
        table = list(csv.DictReader(handle))[1:]  # after "Points Possible"
    got = [(r["Student"], r["ID"], r["SIS User ID"], r["Section"], r["quiz"]) for r in table]
    # bob has no SIS id: his Canvas id goes in ID, not in SIS User ID
    assert sorted(got) == [("Ann Lee", "101", "S1", "Dynamics", "2"),
                   ("Bob Roe", "102", "", "Dynamics", "2")]


def test_canvas_a_row_without_an_attempt_number_is_refused(run, tmp_path, canvas):
    problem, texts, right = canvas
    for attempt in ("", "x", "2.0"):
        rows = [["Bob Roe", "102", "S2", attempt, *right], ["Bob Roe", "102", "S2", "1",
                                                            "1", "1", "1"]]
        done = run("check", "--answers", canvas_analysis(tmp_path, texts, rows), "--responses",
                   "canvas", problem)
        assert done.exit_code == 2, done.output
        (line,) = done.stderr.splitlines()
        assert "line 2" in line and "not an attempt number" in line, line


def test_canvas_one_sis_id_equal_to_anothers_canvas_id_is_refused(run, tmp_path, canvas):
    problem, texts, right = canvas
    rows = [["Ann Lee", "101", "102", "1", *right], ["Bob Roe", "102", "", "1", "", "", ""]]
    done = run("check", "--answers", canvas_analysis(tmp_path, texts, rows), "--responses",
               "canvas", problem)
    assert done.exit_code == 2, done.output
    (line,) = done.stderr.splitlines()
    assert "two students would be graded as '102'" in line and "101 and 102" in line, line


@pytest.mark.parametrize(("typed", "english", "comma"), [
    ("965,4", "9654", "965.4"), ("1,005", "1005", "1.005"),
    ("1,005.5", "1005.5", "1005.5"), ("2,456,789", "2456789", "2456789"),
    ("2,5e-3", "25e-3", "2.5e-3"), ("1 005", "1005", "1005"),
    ("9.654x10^2", "9.654e2", "9.654e2"), ("9.654 × 10^2 rpm", "9.654e2 rpm", "9.654e2 rpm"),
    ("9.654E2", "9.654e2", "9.654e2"), ("9.654*10**-2", "9.654e-2", "9.654e-2"),
    ("965.", "965.", "965."), ("965. rpm", "965. rpm", "965. rpm"),
    ("965.4 rpm", "965.4 rpm", "965.4 rpm"), ("\u2212965,4", "-9654", "-965.4"),
    ("1.2.3", "1.2.3", "1.2.3"), ("cusps", "cusps", "cusps"),
])
def test_moodle_numbers_by_hand(typed, english, comma):
    # Moodle's apply_units (question/type/numerical/question.php): spaces dropped, x10^
    # a power of ten; a '.' or several ',' make ',' a thousands separator; else the site's
    # thousands separator is dropped (',' on an English site) and a ',' left is the point
    from gyro_cli.commands.responses import moodle_number

    assert moodle_number(typed) == english
    assert moodle_number(typed, decimal_comma=True) == comma


def _moodle(tmp_path: Path, rows: list[list[str]], header: list[str] = HEADER) -> Path:
    path = tmp_path / "quiz-responses.csv"
    with path.open("w", newline="", encoding="utf-8-sig") as out:
        writer = csv.writer(out)
        writer.writerow(header)
        writer.writerows(rows)
    return path


@pytest.fixture
def moodle(run, tmp_path: Path) -> tuple[Path, list[str]]:
    problem = tmp_path / "p11_3.yaml"
    problem.write_text(PROBLEM_11_3)
    bank = tmp_path / "bank.xml"
    assert run("export", "--to", "moodle", problem, "-o", bank).exit_code == 0
    return problem, [f"{float(v):.5g}" for v in blanks(bank)]


def _cell(values: list[str]) -> str:
    return "; ".join(f"part {k}: {v}" for k, v in enumerate(values, 1))


def test_moodle_a_decimal_comma_is_read_as_the_site_reads_it(run, tmp_path, moodle):
    problem, right = moodle
    comma = [v.replace(".", ",") for v in right]
    assert any("," in v for v in comma)
    powers = [f"{float(v) / 100:.7g}x10^2 " for v in right]
    # "534." with its point: 533.5 rpm to the units, inside 11/3's 1%
    trailing = [f"{float(v):.0f}." if float(v) > 500 else v for v in right]
    assert any(v.endswith(".") for v in trailing)
    rows = [["Lee", "Ann", "ann@x.edu", "Finished", "", "", "", "3", _cell(comma)],
            ["Roe", "Bob", "bob@x.edu", "Finished", "", "", "", "3", _cell(powers)],
            ["Poe", "Cat", "cat@x.edu", "Finished", "", "", "", "3", _cell(trailing)]]
    path = _moodle(tmp_path, rows)
    # a site whose language writes a decimal comma: 45,13 is 45.13
    assert _scores(run, path, problem, "moodle", "--decimal-comma") == \
        {"ann@x.edu": 2.0, "bob@x.edu": 2.0, "cat@x.edu": 2.0}
    # an English site (the default): 45,13 is 4513, as Moodle marked it
    english = _scores(run, path, problem, "moodle")
    assert english["ann@x.edu"] < 2.0 and english["bob@x.edu"] == 2.0
    assert run("check", "--answers", path, "--responses", "canvas", problem,
               "--decimal-comma").exit_code == 2
    del trailing


def test_moodle_an_attempt_not_finished_is_not_graded(run, tmp_path, moodle):
    problem, right = moodle
    rows = [["Lee", "Ann", "ann@x.edu", "Finished", "", "", "", "3", _cell(right)],
            ["Lee", "Ann", "ann@x.edu", "In progress", "", "", "", "-", _cell(["", "", ""])],
            ["Roe", "Bob", "bob@x.edu", "In progress", "", "", "", "-", _cell(right)]]
    path = _moodle(tmp_path, rows)
    assert _scores(run, path, problem, "moodle") == {"ann@x.edu": 2.0}
    # the teacher is told (bob, in progress, had been left out without a word)
    done = run("check", "--answers", path, "--responses", "moodle", problem)
    assert "2 attempt(s) not finished (State) are not graded" in done.stderr, done.stderr


def test_moodle_two_rows_of_one_name_without_identity_fields_are_refused(run, tmp_path,
                                                                       moodle):
    problem, right = moodle
    header = [h for h in HEADER if h != "Email address"]
    rows = [["Lee", "Ann", "Finished", "", "", "", "3", _cell(right)],
            ["Lee", "Ann", "Finished", "", "", "", "0", _cell(["1", "1", "1"])]]
    done = run("check", "--answers", _moodle(tmp_path, rows, header), "--responses", "moodle",
               problem)
    assert done.exit_code == 2, done.output
    (line,) = done.stderr.splitlines()
    assert "rows 2 and 3 both name 'Lee Ann'" in line and "identity field" in line, line


def test_canvas_best_attempt_keeps_the_attempt_with_the_most_points(run, tmp_path, canvas):
    """A quiz that keeps the highest grade: --attempts best regrades every attempt and
    keeps the best (the latest alone could give less than the platform gave)."""
    problem, texts, right = canvas
    rows = [["Ann Lee", "101", "S1", "1", *right], ["Ann Lee", "101", "S1", "2", "1", "1", "1"],
            ["Bob Roe", "102", "S2", "1", "1", "1", "1"]]
    path = canvas_analysis(tmp_path, texts, rows)
    assert _scores(run, path, problem) == {"S1": 0.0, "S2": 0.0}
    done = run("check", "--answers", path, "--responses", "canvas", problem, "--attempts",
               "best", "--format", "json")
    assert done.exit_code == 0, done.output
    data = json.loads(done.stdout)
    assert {s: v["points"] for s, v in data["scores"].items()} == {"S1": 2.0, "S2": 0.0}
    assert {r["student"] for r in data["rows"]} == {"S1", "S2"}
    assert len(data["rows"]) == 4  # each student's two questions, once
    assert "1 student(s) made several attempts" in done.stderr
    out = tmp_path / "quiz.csv"
    assert run("check", "--answers", path, "--responses", "canvas", problem, "--attempts",
               "best", "--out", out, "--out-format", "canvas").exit_code == 0
    with open(out, newline="") as handle:
        table = list(csv.DictReader(handle))[1:]
    assert sorted((r["Student"], r["SIS User ID"], r["quiz"]) for r in table) == \
        [("Ann Lee", "S1", "2"), ("Bob Roe", "S2", "0")]


def test_moodle_the_latest_attempt_is_the_one_started_last(run, tmp_path, moodle):
    """A report listing the newest attempt first (sorted by Started on) had its older
    attempt regraded as the latest (a third adversarial pass)."""
    problem, right = moodle
    wrong = _cell(["1", "1", "1"])
    newest_first = [
        ["Lee", "Ann", "ann@x.edu", "Finished", "2 January 2027, 9:00 AM", "", "", "3",
         _cell(right)],
        ["Lee", "Ann", "ann@x.edu", "Finished", "1 January 2027, 9:00 AM", "", "", "0", wrong]]
    assert _scores(run, _moodle(tmp_path, newest_first), problem, "moodle") == \
        {"ann@x.edu": 2.0}
    assert _scores(run, _moodle(tmp_path, newest_first[::-1]), problem, "moodle") == \
        {"ann@x.edu": 2.0}
    undated = [row[:4] + [""] + row[5:] for row in newest_first]
    done = run("check", "--answers", _moodle(tmp_path, undated), "--responses", "moodle",
               problem)
    assert done.exit_code == 2 and "which is the latest is unknown" in done.stderr
    assert _scores(run, _moodle(tmp_path, undated), problem, "moodle", "--attempts",
                   "best") == {"ann@x.edu": 2.0}


def test_attempts_are_one_student_whatever_their_rows_write(run, tmp_path, canvas, moodle):
    """An SIS id added between attempts, or an id in another Unicode form, had split one
    student in two under --attempts best (and lost their name from the gradebook)."""
    problem, texts, right = canvas
    rows = [["Ann Lee", "101", "", "1", *right], ["Ann Lee", "101", "S1", "2", "1", "1", "1"]]
    path = canvas_analysis(tmp_path, texts, rows)
    assert _scores(run, path, problem, "canvas", "--attempts", "best") == {"S1": 2.0}
    assert _scores(run, path, problem) == {"S1": 0.0}
    # attempts 9 and 10, equal points: the later is kept (not "10" < "9" as text)
    later = [f"{float(v) * 1.001:.5g}" for v in right]  # as right, written otherwise
    rows = [["Ann Lee", "101", "S1", "9", *right], ["Ann Lee", "101", "S1", "10", *later]]
    done = run("check", "--answers", canvas_analysis(tmp_path, texts, rows), "--responses",
               "canvas", problem, "--attempts", "best", "--format", "json")
    assert done.exit_code == 0, done.output
    kept = json.loads(done.stdout)["rows"]
    assert all(r["points"] == 1 for r in kept)
    assert {r["submitted"].split()[0] for r in kept} <= {*later}, kept
    moodle_problem, moodle_right = moodle
    nfd, nfc = "jose\u0301@x.edu", "jos\u00e9@x.edu"
    rows = [["Ramírez", "José", nfd, "Finished", "1 January 2027, 9:00 AM", "", "", "3",
             _cell(moodle_right)],
            ["Ramírez", "José", nfd, "Finished", "2 January 2027, 9:00 AM", "", "", "0",
             _cell(["1", "1", "1"])]]
    path = _moodle(tmp_path, rows)
    assert _scores(run, path, moodle_problem, "moodle", "--attempts", "best") == {nfc: 2.0}
    out = tmp_path / "q.csv"
    assert run("check", "--answers", path, "--responses", "moodle", moodle_problem,
               "--out", out, "--out-format", "canvas").exit_code == 0
    with open(out, newline="", encoding="utf-8") as handle:
        (row,) = list(csv.DictReader(handle))[1:]
    assert row["Student"] == "José Ramírez"


def test_canvas_an_attempt_listed_twice_is_refused(run, tmp_path, canvas):
    problem, texts, right = canvas
    rows = [["Ann Lee", "101", "S1", "1", "1", "1", "1"], ["Ann Lee", "101", "S1", "1", *right]]
    done = run("check", "--answers", canvas_analysis(tmp_path, texts, rows), "--responses",
               "canvas", problem)
    assert done.exit_code == 2 and "attempt 1 is listed twice" in done.stderr


def test_moodle_best_attempt_and_a_blank_attempt(run, tmp_path, moodle):
    problem, right = moodle
    rows = [["Lee", "Ann", "ann@x.edu", "Finished", "1 Jan 2027 9:00 AM", "", "", "3",
             _cell(right)],
            ["Lee", "Ann", "ann@x.edu", "Finished", "2 Jan 2027 9:00 AM", "", "", "0",
             _cell(["1", "1", "1"])],
            ["Roe", "Bob", "bob@x.edu", "Finished", "", "", "", "0", _cell(["", "", ""])]]
    path = _moodle(tmp_path, rows)
    # the latest attempt; bob's blank one is graded 0, not left out
    assert _scores(run, path, problem, "moodle") == {"ann@x.edu": 0.0, "bob@x.edu": 0.0}
    assert _scores(run, path, problem, "moodle", "--attempts", "best") == \
        {"ann@x.edu": 2.0, "bob@x.edu": 0.0}
    refused = run("check", "--answers", path, "--responses", "moodle", problem, "--attempts",
                  "best", "--student", "ann@x.edu")
    assert refused.exit_code == 2


@pytest.mark.parametrize(("keep", "ann"), [("latest", 0.0), ("best", 2.0), ("first", 2.0),
                                           ("average", 1.0)])
def test_canvas_attempts_kept_as_the_quiz_keeps_them(run, tmp_path, canvas, keep, ann):
    """Ann's first attempt right (2 points), her second wrong (0): the quiz keeps the
    latest (0), the highest (2), the first (2) or the average (1). A quiz that keeps the
    first or the average had no regrade mode (left open two sessions)."""
    problem, texts, right = canvas
    rows = [["Ann Lee", "101", "S1", "1", *right], ["Ann Lee", "101", "S1", "2", "1", "1", "1"],
            ["Bob Roe", "102", "S2", "1", *right]]
    path = canvas_analysis(tmp_path, texts, rows)
    assert _scores(run, path, problem, "canvas", "--attempts", keep) == {"S1": ann, "S2": 2.0}
    done = run("check", "--answers", path, "--responses", "canvas", problem, "--attempts", keep,
               "--format", "json")
    data = json.loads(done.stdout)
    assert len(data["rows"]) == 4  # each student's two questions, once
    if keep == "average":
        assert "the mean of their attempts' points" in done.stderr
        # the rows shown are the latest attempt's
        assert {r["result"] for r in data["rows"] if r["student"] == "S1"} == {"wrong"}


@pytest.mark.parametrize(("keep", "ann"), [("latest", 2.0), ("best", 2.0), ("first", 0.0),
                                           ("average", 1.0)])
def test_moodle_attempts_kept_as_the_quiz_keeps_them(run, tmp_path, moodle, keep, ann):
    """Moodle's grading methods (highest, average, first, last): Ann started a wrong
    attempt on 1 January and a right one on 2 January, the report listing the newest
    first; the first is the one started first, whatever the rows' order."""
    problem, right = moodle
    rows = [["Lee", "Ann", "ann@x.edu", "Finished", "2 January 2027, 9:00 AM", "", "", "3",
             _cell(right)],
            ["Lee", "Ann", "ann@x.edu", "Finished", "1 January 2027, 9:00 AM", "", "", "0",
             _cell(["1", "1", "1"])]]
    assert _scores(run, _moodle(tmp_path, rows), problem, "moodle", "--attempts", keep) == \
        {"ann@x.edu": ann}


def test_moodle_regrade_feedback_without_hints(run, tmp_path, moodle):
    # --no-hints reaches a platform's regrade too: ann's 9.654 (a power of ten low) is told
    # "not right" on her page, the teacher's grades CSV still names the slip.
    problem, right = moodle
    low = [f"{float(v) / 10:.5g}" for v in right]
    path = _moodle(tmp_path, [["Lee", "Ann", "ann@x.edu", "Finished", "", "", "", "3",
                               _cell(low)]])
    out = run("check", "--answers", path, "--responses", "moodle", problem, "--no-hints",
              "--feedback", tmp_path / "pages", "--out", tmp_path / "grades.csv")
    assert out.exit_code == 0, out.output
    [page] = (tmp_path / "pages").iterdir()
    text = page.read_text()
    assert "not right" in text and "too" not in text and "slip" not in text, text
    assert "a power of ten" in (tmp_path / "grades.csv").read_text()
