"""Issue 38 item 4 (more platforms): a Moodle quiz Responses report of a bank gyro
exported, regraded by `gyro check --answers DOWNLOAD --responses moodle PATHS` with errors
carried forward (Moodle's cloze grader marks each blank alone)."""

from __future__ import annotations

import csv
import json
import re
from pathlib import Path

from test_i38_ecf_more import PROBLEM_11_3, carl_and_dana

#: Moodle's Responses report downloaded as CSV (identity fields: the site's email address)
HEADER = ["Surname", "First name", "Email address", "State", "Started on", "Completed",
          "Time taken", "Grade/4.00", "Response 1"]


def blanks(bank: Path) -> list[str]:
    """Each cloze question's blanks in the export, in its order: its NUMERICAL answers."""
    questions = re.findall(r'<question type="cloze">.*?</question>', bank.read_text(), re.S)
    return [re.findall(r"\{1:NUMERICAL:=([^:]+):", q) for q in questions][0]


def report(tmp_path: Path, answers: dict[str, list[str]], count: int) -> Path:
    """A Responses report: per student one attempt, the cloze response as Moodle sums it
    up ("part 1: x; part 2: y", an empty part as "part 3: "), then the average row."""
    path = tmp_path / "quiz-responses.csv"
    with path.open("w", newline="", encoding="utf-8-sig") as out:
        writer = csv.writer(out)
        writer.writerow(HEADER)
        for user, typed in answers.items():
            assert len(typed) == count
            cell = "; ".join(f"part {k}: {v}" for k, v in enumerate(typed, 1))
            writer.writerow([user.title(), "A", f"{user}@example.edu", "Finished",
                             "27 November 2026  9:00 AM", "27 November 2026  9:40 AM",
                             "40 mins", "0.00", cell])
        writer.writerow(["Overall average", "", "", "", "", "", "", "0.00", ""])
    return path


def test_item04_moodle_responses_regraded_with_errors_carried_forward(tmp_path, run):
    """11/3 with `steps: [I]` exported to Moodle (one cloze question, 4 blanks); a student
    whose I is 10% high and whose precession roots and least spin are right for it:
    Moodle gives 0 for each; regraded from the report with --credit ecf=1, 2 of 3."""
    problem = tmp_path / "p11_3.yaml"
    problem.write_text(PROBLEM_11_3.replace("tolerance: 1%\n", "tolerance: 1%\nsteps: [I]\n"))
    bank = tmp_path / "bank.xml"
    made = run("export", "--to", "moodle", problem, "-o", bank)
    assert made.exit_code == 0, made.output
    assert "--responses moodle" in made.stderr
    count = len(blanks(bank))
    assert count == 4
    path = report(tmp_path, carl_and_dana(), count)
    graded = run("check", "--answers", path, "--responses", "moodle", problem,
                 "--credit", "ecf=1", "--format", "json")
    assert graded.exit_code == 0, graded.output
    rows = {(r["student"], r["answer"]): r for r in json.loads(graded.stdout)["rows"]}
    carl = "carl@example.edu"
    assert rows[carl, "I"]["points"] == 0
    for name in ("precession", "min_spin"):
        assert rows[carl, name]["result"] == "carried", rows[carl, name]
        assert "consistent with your I = " in rows[carl, name]["note"]
    assert sum(r["points"] for (who, _), r in rows.items() if who == carl) == 2
    dana = "dana@example.edu"
    assert rows[dana, "I"]["points"] == 1 and rows[dana, "min_spin"]["points"] == 1
    assert rows[dana, "precession"]["points"] < 1  # the fast root left blank
    plain = run("check", "--answers", path, "--responses", "moodle", problem,
                "--format", "json")
    assert plain.exit_code == 0, plain.output
    marks = [r["points"] for r in json.loads(plain.stdout)["rows"] if r["student"] == carl]
    assert len(marks) == 3 and sum(marks) == 0  # without ECF: as Moodle marked it


def test_item04_a_moodle_report_of_another_quiz_is_refused(tmp_path, run):
    """Not a Responses report, or one with more questions than the files: one line, exit 2."""
    problem = tmp_path / "p11_3.yaml"
    problem.write_text(PROBLEM_11_3)
    sheet = tmp_path / "sheet.csv"
    sheet.write_text("student,problem,answer,value\ncarl,11/3,I,1\n")
    two = tmp_path / "two.csv"
    two.write_text(",".join(HEADER + ["Response 2"]) + "\n"
                   + "C,A,c@x.edu,Finished,,,,0,part 1: 45,part 1: 4\n")
    parts = tmp_path / "parts.csv"
    parts.write_text(",".join(HEADER) + "\nC,A,c@x.edu,Finished,,,,0,part 9: 45\n")
    for path, words in ((sheet, "line 1"), (two, "expected 1 to 1"), (parts, "line 2")):
        refused = run("check", "--answers", path, "--responses", "moodle", problem)
        assert refused.exit_code == 2, refused.output
        assert path.name in refused.output and words in refused.output, refused.output
        assert "Traceback" not in refused.output
        assert len(refused.output.strip().splitlines()) == 1, refused.output


# ---- Canvas: the quiz's Student Analysis of a QTI 1.2 bank ----

CANVAS_HEADER = ["name", "id", "sis_id", "section", "section_id", "section_sis_id",
                 "submitted", "attempt"]


def qti_questions(package: Path) -> list[str]:
    """Each item's question text in the QTI export, its order kept, as Canvas shows it in
    a column name: the tags stripped without a space."""
    import xml.etree.ElementTree as ET
    import zipfile

    with zipfile.ZipFile(package) as z:
        names = [n for n in z.namelist() if n.endswith(".xml") and "manifest" not in n]
        root = ET.fromstring(z.read(names[0]))
    items = [el for el in root.iter() if el.tag.endswith("}item") or el.tag == "item"]
    texts = []
    for item in items:
        presentation = [el for el in item.iter() if el.tag.endswith("presentation")][0]
        mattext = [el for el in presentation.iter() if el.tag.endswith("mattext")][0]
        texts.append(re.sub(r"<[^>]+>", "", mattext.text or ""))
    return texts


def canvas_analysis(tmp_path: Path, texts: list[str], rows: list[list[str]]) -> Path:
    """A Student Analysis: per question "ID: text" and its points column, then the totals;
    a row per attempt, ``rows`` as [name, Canvas id, SIS id, attempt, typed...]."""
    path = tmp_path / "student_analysis.csv"
    with path.open("w", newline="", encoding="utf-8") as out:
        writer = csv.writer(out)
        header = list(CANVAS_HEADER)
        for k, text in enumerate(texts):
            header += [f"{5000 + k}: {text}", "1.0"]
        writer.writerow(header + ["n correct", "n incorrect", "score"])
        for name, canvas_id, sis_id, attempt, *typed in rows:
            cells = [c for value in typed for c in (value, "0.0")]
            writer.writerow([name, canvas_id, sis_id, "Dynamics", "7", "", "2026-11-27",
                             attempt] + cells + ["0", str(len(texts)), "0"])
    return path


def analysis(tmp_path: Path, texts: list[str], answers: dict[str, list[str]]) -> Path:
    """`canvas_analysis` with one row per student (the first student's attempt 1, all 1s,
    replaced by their attempt 2)."""
    rows = []
    for n, (user, typed) in enumerate(answers.items()):
        who = [user.title(), str(100 + n), f"S{n}"]
        if n == 0:
            rows.append(who + ["1"] + ["1"] * len(texts))
        rows.append(who + ["2"] + list(typed))
    return canvas_analysis(tmp_path, texts, rows)


def test_item04_canvas_student_analysis_regraded_with_errors_carried_forward(tmp_path, run):
    """11/3 with `steps: [I]` exported as QTI (one item per number) and taken in Canvas:
    its Student Analysis regraded with --credit ecf=1 gives carl 2 of 3, without 0."""
    problem = tmp_path / "p11_3.yaml"
    problem.write_text(PROBLEM_11_3.replace("tolerance: 1%\n", "tolerance: 1%\nsteps: [I]\n"))
    package = tmp_path / "bank.zip"
    made = run("export", "--to", "qti", problem, "-o", package)
    assert made.exit_code == 0, made.output
    assert "--responses canvas" in made.stderr
    texts = qti_questions(package)
    assert len(texts) == 4
    path = analysis(tmp_path, texts, carl_and_dana())
    graded = run("check", "--answers", path, "--responses", "canvas", problem,
                 "--credit", "ecf=1", "--format", "json")
    assert graded.exit_code == 0, graded.output
    rows = {(r["student"], r["answer"]): r for r in json.loads(graded.stdout)["rows"]}
    assert rows["S0", "I"]["points"] == 0
    for name in ("precession", "min_spin"):
        assert rows["S0", name]["result"] == "carried", rows["S0", name]
    assert sum(r["points"] for (who, _), r in rows.items() if who == "S0") == 2
    assert rows["S1", "I"]["points"] == 1 and rows["S1", "precession"]["points"] < 1
    plain = run("check", "--answers", path, "--responses", "canvas", problem,
                "--format", "json")
    marks = [r["points"] for r in json.loads(plain.stdout)["rows"] if r["student"] == "S0"]
    assert len(marks) == 3 and sum(marks) == 0
    other = tmp_path / "other.csv"
    other.write_text(",".join(CANVAS_HEADER + ["77: What is 2 + 2?", "1.0"]) + "\n")
    refused = run("check", "--answers", other, "--responses", "canvas", problem)
    assert refused.exit_code == 2 and "other.csv" in refused.output, refused.output
    assert len(refused.output.strip().splitlines()) == 1, refused.output


ROOT = Path(__file__).resolve().parent.parent


def test_item04_moodle_numerical_typed_with_its_unit_and_a_second_slot(tmp_path, run):
    """Two problems, two slots: 11/3's cloze in Response 1, 11/1's numerical question
    (typed with its unit, as Moodle asks) in Response 2; both regraded right."""
    import xml.etree.ElementTree as ET

    top = tmp_path / "a.yaml"
    top.write_text(PROBLEM_11_3)
    spin = tmp_path / "b.yaml"
    spin.write_text((ROOT / "problems" / "11_1.yaml").read_text())
    bank = tmp_path / "bank.xml"
    assert run("export", "--to", "moodle", top, spin, "-o", bank).exit_code == 0
    asked = [q for q in ET.parse(bank).getroot().findall("question")
             if q.get("type") != "category"]
    assert [q.get("type") for q in asked] == ["cloze", "numerical"]
    cloze = re.findall(r"\{1:NUMERICAL:=([^:]+):", asked[0].findtext("questiontext/text"))
    number = next(a.findtext("text") for a in asked[1].findall("answer")
                  if a.get("fraction") == "100")
    path = tmp_path / "responses.csv"
    with path.open("w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(HEADER + ["Response 2"])
        writer.writerow(["Lee", "Ann", "ann@x.edu", "Finished", "", "", "", "0", "; ".join(
            f"part {k}: {float(v):.5g}" for k, v in enumerate(cloze, 1)),
            f"{float(number):.5g} rpm"])
    graded = run("check", "--answers", path, "--responses", "moodle", top, spin,
                 "--format", "json")
    assert graded.exit_code == 0, graded.output
    rows = json.loads(graded.stdout)["rows"]
    assert len(rows) == 3 and all(r["points"] == 1 for r in rows), rows


def test_item04_canvas_word_answer_columns_are_left_to_canvas(tmp_path, run):
    """A problem with a word answer: its multiple-choice column in the Student Analysis
    is not refused; the numbers beside it are regraded."""
    import xml.etree.ElementTree as ET
    import zipfile

    problem = tmp_path / "top.yaml"
    problem.write_text((ROOT / "problems" / "11_2_released_top.yaml").read_text())
    package = tmp_path / "bank.zip"
    assert run("export", "--to", "qti", problem, "-o", package).exit_code == 0
    texts = qti_questions(package)
    with zipfile.ZipFile(package) as z:
        name = next(n for n in z.namelist() if n.endswith(".xml") and "manifest" not in n)
        root = ET.fromstring(z.read(name))
    typed = []
    for item in (el for el in root.iter() if el.tag.endswith("}item")):
        right = [el.text for el in item.iter() if el.tag.endswith("varequal")][0]
        typed.append(f"{float(right):.5g}" if any(el.tag.endswith("render_fib")
                                                   for el in item.iter()) else "cusps")
    assert "cusps" in typed and len(typed) > 1
    path = analysis(tmp_path, texts, {"ann": typed})
    graded = run("check", "--answers", path, "--responses", "canvas", problem,
                 "--format", "json")
    assert graded.exit_code == 0, graded.output
    rows = json.loads(graded.stdout)["rows"]
    assert rows and all(r["points"] == 1 for r in rows), rows
