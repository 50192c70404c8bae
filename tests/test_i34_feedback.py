"""Issue 34, items 7-9: naming another student's variant only when chance cannot explain
it, student-facing outputs that name no other student, and feedback that does not give
the answer away before the due date.

The class: 300 students with their own variants of problems 11/3 and 11/5 (`gyro vary
--roster`). Each student's own numbers are the answers printed in their variant file;
every student but the copiers slips by 1-10% (a seeded random): every value on its own,
every value of a problem by one factor, or one of their given values misread and the
problem worked again from it (so their answers are those of a variant that nobody may
have been given: the hardest case for a coincidence). Some also make a named slip (2 pi,
a power of ten, the sign), leave out a root, or give a value in a wrong unit. Ten
students copy another student's whole homework as printed in that student's file.
"""

from __future__ import annotations

import csv
import json
import math
import random
import re
from pathlib import Path

import pytest
from click.testing import CliRunner
from conftest import read_yaml

from gyro_cli import api
from gyro_cli.checking import copies, matching
from gyro_cli.cli import main

ROOT = Path(__file__).resolve().parent.parent
PROBLEMS = [ROOT / "problems" / "11_3.yaml", ROOT / "problems" / "11_5.yaml"]
N = 300
VARIED = {"11/3": ("spin", "theta"), "11/5": ("spin", "precession")}
COPIERS = {f"s{k:03d}": f"s{(k + 150) % N:03d}" for k in range(3, N, 30)}  # copier: source
STUDENT_ID = re.compile(r"\bs\d{3}\b")
NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def gyro(*args: object) -> object:
    result = CliRunner().invoke(main, [str(a) for a in args])
    assert result.exit_code == 0, result.output
    return result


def _printed(data: dict) -> dict[str, list[str]]:
    """A variant's answers as its file (``data``, read) prints them (what a copier copies)."""
    return {q: [str(v) for v in (vs if isinstance(vs, list) else [vs])]
            for q, vs in data["expected"].items()}


def _slip(rng: random.Random) -> float:
    return 1 + rng.choice((-1, 1)) * rng.uniform(0.01, 0.10)


def _written(number: float, unit: str) -> str:
    return f"{number:.4g} {unit}"


def _own_answers(rng: random.Random, pid: str, variant: Path) -> dict[str, list[str]]:
    """One student's answers to their own variant, slipped by 1-10%."""
    data = read_yaml(variant.read_text())  # libyaml's loader: the pure-Python one took
    printed = _printed(data)  # most of the class's set-up
    mode = rng.choice(("each", "same", "given"))
    if mode == "given":  # a given value misread: the problem worked again from it
        key = rng.choice(VARIED[pid])
        number, unit = str(data["given"][key]).split(maxsplit=1)
        worked = api.solve_file(str(variant), **{key: _written(float(number) * _slip(rng),
                                                               unit)})
        return {q: [_written(v, worked.answers[q].unit) for v in worked.answers[q].values]
                for q in printed}
    factor = _slip(rng)
    out = {}
    for q, values in printed.items():
        out[q] = []
        for text in values:
            number, unit = text.split(maxsplit=1)
            out[q].append(_written(float(number) * (factor if mode == "same" else _slip(rng)),
                                   unit))
    return out


def _more_slips(rng: random.Random, answers: dict[str, list[str]]) -> None:
    """Now and then a named slip, a root left out, or a wrong unit, on top."""
    question = rng.choice(sorted(answers))
    values = answers[question]
    number, unit = values[0].split(maxsplit=1)
    what = rng.choice(("2pi", "ten", "sign", "root", "unit", "none", "none"))
    if what == "2pi":
        values[0] = _written(float(number) * 2 * math.pi, unit)
    elif what == "ten":
        values[0] = _written(float(number) * 10, unit)
    elif what == "sign":
        values[0] = _written(-float(number), unit)
    elif what == "root" and len(values) > 1:
        del values[rng.randrange(len(values))]
    elif what == "unit":
        values[0] = f"{number} kg"


@pytest.fixture(scope="module")
def course(tmp_path_factory: pytest.TempPathFactory) -> dict:
    """The class of 300, its sheet, and the teacher's and the students' outputs."""
    base = tmp_path_factory.mktemp("course")
    roster = base / "roster.csv"
    roster.write_text("student\n" + "".join(f"s{k:03d}\n" for k in range(N)))
    hw = base / "hw"
    gyro("vary", *PROBLEMS, "--roster", roster, "--seed", 34, "-o", hw)
    with open(hw / "assignment.csv", newline="") as handle:
        files = {(r["student"], r["problem"]): hw / r["file"] for r in csv.DictReader(handle)}
    rng = random.Random(3407)
    lines = ["student,problem,answer,value"]
    given: dict[str, list[str]] = {}
    for k in range(N):
        student = f"s{k:03d}"
        for pid in VARIED:
            if student in COPIERS:
                answers = _printed(read_yaml(files[(COPIERS[student], pid)].read_text()))
            else:
                answers = _own_answers(rng, pid, files[(student, pid)])
                if rng.random() < 0.3:
                    _more_slips(rng, answers)
            for question, values in answers.items():
                lines.append(f"{student},{pid},{question},{'; '.join(values)}")
                given.setdefault(student, []).extend(values)
    sheet = base / "answers.csv"
    sheet.write_text("\n".join(lines) + "\n")
    assignment = hw / "assignment.csv"
    gyro("check", "--answers", sheet, "--assignment", assignment, "--out", base / "grades.csv",
         "--feedback", base / "feedback")
    # Gradescope's and PrairieLearn's results of the same grading, written as `gyro check
    # --out-format FMT` writes them, without grading the class twice more (the command
    # line's --out-format: tests/test_i34_grading.py, tests/test_course.py)
    from gyro_cli.checking import grades
    from gyro_cli.render import grades_report

    graded = grades.grade(str(sheet), (), assignment=str(assignment))
    for fmt in ("gradescope", "prairielearn"):
        grades_report.write_out(graded, str(base / fmt), fmt, False, [str(sheet)])
    with open(base / "grades.csv", newline="") as handle:
        grades = list(csv.DictReader(handle))
    key = json.loads((hw / "key.json").read_text())
    return {"base": base, "sheet": sheet, "assignment": assignment, "grades": grades,
            "given": given, "key": key, "files": files}


def _student_outputs(base: Path, student: str) -> dict[str, str]:
    """Every text a student receives: their feedback page and the texts of their
    Gradescope and PrairieLearn results."""
    out = {"feedback": (base / "feedback" / f"{student}.md").read_text()}
    for fmt in ("gradescope", "prairielearn"):
        data = json.loads((base / fmt / f"{student}.json").read_text())
        texts = [data.get("output", ""), data.get("message", "")]
        for test in data["tests"]:
            texts += [test.get("output", ""), test.get("message", ""), test.get("name", ""),
                      test.get("description", "")]
        out[fmt] = "\n".join(texts)
    return out


def test_item07_no_false_copying_accusation(course):
    """A class of 300 students each slipping 1-10% on their own numbers: no one is told
    they used another's numbers; 10 exact copies: all 10 in the teacher's CSV."""
    named: dict[str, set[str]] = {}
    for row in course["grades"]:
        found = re.search(r"the answers to student (s\d{3})'s variant", row["note"])
        if found:
            named.setdefault(row["student"], set()).add(found.group(1))
    assert named == {copier: {source} for copier, source in COPIERS.items()}
    for copier in COPIERS:  # every wrong row of theirs says so
        rows = [r for r in course["grades"] if r["student"] == copier and r["result"] == "wrong"]
        assert rows and all("the answers to student" in r["note"] for r in rows)


def test_item07_a_match_is_to_the_digits_the_student_wrote():
    """Half a unit of the last digit written, relative; never looser than 0.1%."""
    assert copies.written_precision("45.13 rpm") == pytest.approx(0.005 / 45.13)
    assert copies.written_precision("1.2345e3 N") == pytest.approx(0.05 / 1234.5)
    assert copies.written_precision("1.5e3 N") == copies.EPS_MAX  # 3% would be chance
    assert copies.written_precision("2 N") == copies.EPS_MAX
    assert copies.written_precision(12.345) == pytest.approx(0.0005 / 12.345)


def test_item07_alone_one_problem_of_a_dense_class_names_no_one(course):
    """Students whose wrong answers to 11/5 equal another variant's to the digits they
    wrote (slips onto the curve all variants of 11/5 lie on) are in the class, and no
    one of them is named."""
    from gyro_cli.checking import grades

    landed = []
    original = grades.whose

    def spy(index, student, wrong, size):  # the coincidences the bound must absorb
        for pid, (own, given) in wrong.items():
            answered = index.answered(own, given)
            if answered is not None and index.matching(pid, own.variant, answered):
                landed.append((student, pid))
        return original(index, student, wrong, size)

    grades.whose = spy
    try:
        graded = grades.grade(str(course["sheet"]), [], assignment=str(course["assignment"]))
    finally:
        grades.whose = original
    chance = [s for s, pid in landed if s not in COPIERS]
    assert chance, "the class should hold slips that land on another variant by chance"
    named = {r.student for r in graded.rows if "the answers to student" in r.note}
    assert named == set(COPIERS)


def test_item08_student_outputs_name_no_other_student(course):
    base = course["base"]
    for k in range(N):
        student = f"s{k:03d}"
        for where, text in _student_outputs(base, student).items():
            others = set(STUDENT_ID.findall(text)) - {student}
            assert not others, (student, where, others, text)
            assert "answers to student" not in text, (student, text)
    # the teacher's CSV has the match (test_item07); a copier's page only their result
    page = (base / "feedback" / f"{next(iter(COPIERS))}.md").read_text()
    assert "off" in page


def test_item08_answering_another_variant_id_is_not_told_whose(tmp_path):
    roster = tmp_path / "roster.csv"
    roster.write_text("student\nann\nbob\n")
    hw = tmp_path / "hw"
    gyro("vary", PROBLEMS[0], "--roster", roster, "-o", hw)
    sheet = tmp_path / "s.csv"
    sheet.write_text("ann,11/3-bob,min_spin,900 rpm\n")
    gyro("check", "--answers", sheet, "--assignment", hw / "assignment.csv", "--out",
         tmp_path / "g.csv", "--feedback", tmp_path / "fb")
    page = (tmp_path / "fb" / "ann.md").read_text()
    assert "bob" not in page and "graded on your own variant 11/3-ann" in page
    assert "student bob's numbers" in (tmp_path / "g.csv").read_text()  # the teacher's


def _allowed_numbers(course: dict, student: str) -> list[float]:
    """The numbers a student's page may hold: their own, their points and score, the
    constants the named slips are written with, and the unit reader's examples."""
    allowed = []
    for text in course["given"][student] + [student]:
        allowed += [float(n) for n in NUMBER.findall(text)]
    for row in course["grades"]:
        if row["student"] == student:
            allowed += [float(row["points"]), float(row["max_points"])]
            if row["result"] == "score":
                allowed.append(float(row["note"].rstrip("%")))
            if row["result"] == "invalid":  # the unit reader's examples ('1800 rpm')
                allowed += [float(n) for n in NUMBER.findall(row["note"])]
    for _, words in matching.SLIPS:
        allowed += [float(n) for n in NUMBER.findall(words)]
    allowed += [11, 3, 5, 10, 1, 2, -1, -2, -3, 10 ** 1, 100]  # ids 11/3, 11/5; 10^k, 1/10
    return allowed


def _numbers(text: str, student: str) -> list[float]:
    text = STUDENT_ID.sub("", text.replace(f"Feedback for {student}", ""))
    return [float(n) for n in NUMBER.findall(text)]


def test_item09_feedback_gives_no_number_from_the_solver(course):
    base = course["base"]
    wrong_pages = 0
    for k in range(N):
        student = f"s{k:03d}"
        allowed = _allowed_numbers(course, student)
        outputs = _student_outputs(base, student)
        if "To look at again" in outputs["feedback"]:
            wrong_pages += 1
        for where, text in outputs.items():
            for number in _numbers(text, student):
                assert any(math.isclose(number, a, rel_tol=1e-9, abs_tol=1e-9)
                           for a in allowed), (student, where, number, text)
            without_score = re.sub(r"points \(\d+\.\d%\)", "", text)
            assert "off by" not in text and "%" not in without_score, (student, where, text)
    assert wrong_pages > N // 2  # the check ran on many pages with wrong answers


def test_item09_feedback_words_too_high_too_low_missing_root_slip(course):
    pages = [(course["base"] / "feedback" / f"s{k:03d}.md").read_text() for k in range(N)]
    everything = "\n".join(pages)
    for words in ("too high", "too low", "a root is missing", "likely slip: a factor of 2 pi",
                  "likely slip: a power of ten", "the wrong sign", "not readable"):
        assert words in everything, words


def test_item09_reveal_shows_the_worked_answer(course, tmp_path):
    gyro("check", "--answers", course["sheet"], "--assignment", course["assignment"],
         "--feedback", tmp_path / "fb", "--reveal")
    shown = 0
    for row in course["grades"]:
        if row["result"] not in ("wrong", "partial"):
            continue
        page = (tmp_path / "fb" / f"{row['student']}.md").read_text()
        assert "the answer: " in page
        numbers = [float(n) for n in NUMBER.findall(page)]
        variant = course["key"]["variants"][row["variant"]]["answers"][row["answer"]]
        for value in variant["values"]:
            assert any(math.isclose(n, value, rel_tol=1e-3) for n in numbers), (value, page)
        shown += 1
    assert shown > 100
    # --reveal alone (no student-facing output) is refused
    result = CliRunner().invoke(main, ["check", "--answers", str(course["sheet"]),
                                       "--assignment", str(course["assignment"]), "--reveal"])
    assert result.exit_code == 2 and "--reveal goes with" in result.output
