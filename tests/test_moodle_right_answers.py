"""A Moodle Responses report downloaded with its "Right answer" columns: each slot's right
answer must be the exported problem's, else the report is refused (one line, exit 2). A
quiz whose questions are in another order than the files, or one built from a bank
exported with --variants, would otherwise be regraded against the wrong numbers, unnoticed
(Moodle's report names no question)."""

from __future__ import annotations

import csv
import re
import xml.etree.ElementTree as ET
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
HEADER = ["Surname", "First name", "Email address", "State", "Started on", "Completed",
          "Time taken", "Grade/2.00"]


def _exported(bank: Path) -> list[str]:
    """Each question's right answer as Moodle's report sums it up: a cloze's "part 1: x;
    part 2: y" (its stored answers, as written), a numerical question's number."""
    out = []
    for question in ET.parse(bank).getroot().findall("question"):
        if question.get("type") == "cloze":
            values = re.findall(r"\{1:NUMERICAL:=([^:]+):", question.findtext("questiontext/text"))
            out.append("; ".join(f"part {k}: {v}" for k, v in enumerate(values, 1)))
        elif question.get("type") == "numerical":
            out.append(next(a.findtext("text") for a in question.findall("answer")
                            if a.get("fraction") == "100"))
    return out


def _report(path: Path, right: list[str], responses: list[str]) -> Path:
    with path.open("w", newline="", encoding="utf-8-sig") as out:
        writer = csv.writer(out)
        slots = range(1, len(right) + 1)
        writer.writerow(HEADER + [c for n in slots for c in (f"Response {n}", f"Right answer {n}")])
        writer.writerow(["Lee", "Ann", "ann@x.edu", "Finished", "", "", "", "0"]
                        + [c for pair in zip(responses, right) for c in pair])
    return path


def _two_problems(tmp_path: Path, run) -> tuple[Path, Path, list[str]]:  # type: ignore[no-untyped-def]
    top, spin = tmp_path / "a.yaml", tmp_path / "b.yaml"
    top.write_text((ROOT / "problems" / "11_3.yaml").read_text())
    spin.write_text((ROOT / "problems" / "11_1.yaml").read_text())
    bank = tmp_path / "bank.xml"
    assert run("export", "--to", "moodle", top, spin, "-o", bank).exit_code == 0
    return top, spin, _exported(bank)


def test_right_answers_of_the_exported_problems_are_regraded(tmp_path, run):
    """11/3's cloze (45.13 and 533.5 rpm, least spin 965.4 rpm: the chapter's answers) and
    11/1's numerical question, in the files' order: graded, every answer right."""
    top, spin, right = _two_problems(tmp_path, run)
    assert re.fullmatch(r"part 1: 45\.13\d*; part 2: 533\.5\d*; part 3: 965\.4\d*", right[0])
    typed = ["part 1: 45.13; part 2: 533.5; part 3: 965.4", f"{float(right[1]):.4g} rpm"]
    path = _report(tmp_path / "r.csv", right, typed)
    graded = run("check", "--answers", path, "--responses", "moodle", top, spin)
    assert graded.exit_code == 0, graded.output
    assert "invalid" not in graded.stdout and "wrong" not in graded.stdout, graded.stdout
    assert graded.stderr == "", graded.stderr  # checked: nothing to say


def test_a_report_without_right_answers_is_graded_with_a_note(tmp_path, run):
    """Without the Right answer columns the report is graded as before, and a note on
    stderr says what could not be checked and how to download it."""
    top, spin, right = _two_problems(tmp_path, run)
    path = tmp_path / "r.csv"
    with path.open("w", newline="") as out:
        writer = csv.writer(out)
        writer.writerow(HEADER + ["Response 1", "Response 2"])
        writer.writerow(["Lee", "Ann", "ann@x.edu", "Finished", "", "", "", "0",
                         "part 1: 45.13; part 2: 533.5; part 3: 965.4", right[1]])
    graded = run("check", "--answers", path, "--responses", "moodle", top, spin)
    assert graded.exit_code == 0, graded.output
    assert graded.stderr.count("gyro: note: the report has no Right answer columns") == 1
    assert "Right answer ticked" in graded.stderr


def test_a_quiz_in_another_order_is_refused(tmp_path, run):
    """The quiz's question 1 is 11/1, the files give 11/3 first: Response 1 would have
    been graded as 11/3's precession. Refused, naming the slot and the remedy."""
    top, spin, right = _two_problems(tmp_path, run)
    path = _report(tmp_path / "r.csv", right, ["", ""])
    swapped = run("check", "--answers", path, "--responses", "moodle", spin, top)
    assert swapped.exit_code == 2, swapped.output
    line = swapped.output.strip()
    assert len(line.splitlines()) == 1 and "r.csv: line 2:" in line, line
    assert "Right answer 1 is not 11/1's" in line and "another order" in line, line


def test_a_drawn_variant_is_refused(tmp_path, run):
    """A bank of 3 drawn variants of 11/3: a student's quiz drew the second. Regraded
    against 11/3 as written it would be wrong; refused, naming --variants."""
    top = tmp_path / "a.yaml"
    top.write_text((ROOT / "problems" / "11_3.yaml").read_text())
    bank = tmp_path / "bank.xml"
    assert run("export", "--to", "moodle", top, "--variants", "3", "--seed", "5",
               "-o", bank).exit_code == 0
    drawn = _exported(bank)
    assert len(set(drawn)) == 3
    as_written = tmp_path / "one.xml"
    assert run("export", "--to", "moodle", top, "-o", as_written).exit_code == 0
    other = next(r for r in drawn if r != _exported(as_written)[0])
    path = _report(tmp_path / "r.csv", [other], [other])
    refused = run("check", "--answers", path, "--responses", "moodle", top)
    assert refused.exit_code == 2, refused.output
    assert "--variants" in refused.output and "Right answer 1" in refused.output


def test_right_answers_on_a_decimal_comma_site_and_rounded_to_seven_digits(tmp_path, run):
    """Written with a decimal comma (`--decimal-comma`) or rounded to 7 significant digits,
    the right answer is still the exported one."""
    top, spin, right = _two_problems(tmp_path, run)
    values = [float(v) for v in re.findall(r"part \d+: (\S+?)(?:;|$)", right[0])]
    comma = "; ".join(f"part {k}: {v:.7g}".replace(".", ",") for k, v in enumerate(values, 1))
    path = _report(tmp_path / "r.csv", [comma, f"{float(right[1]):.7g}"], ["", ""])
    graded = run("check", "--answers", path, "--responses", "moodle", "--decimal-comma",
                 top, spin)
    assert graded.exit_code == 0, graded.output
