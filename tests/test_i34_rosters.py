"""Issue 34, items 10-16: rosters, student ids, safe file names, CSV round trips, and no
output of a course command replacing one of its inputs.

Each student's correct answers are worked by hand from their own variant file
(test_course.by_hand: the 11/3 top's quadratic), never taken from the solver.
"""

from __future__ import annotations

import csv
import json
import re
import unicodedata
from pathlib import Path

import pytest
import yaml
from hypothesis import given, settings
from hypothesis import strategies as st
from test_check import put
from test_course import TOP, assignment_rows, by_hand

# Each sheet answers min_spin right and leaves the two precession rates out.
ONE_OF_TWO = {"points": 1.0, "max_points": 2.0}


def _own_answers(out: Path) -> dict[str, float]:
    """Each student's least spin (rpm), worked by hand from their own variant file."""
    from gyro_cli.checking.assignment import read_assignment

    return {r.student: by_hand(yaml.safe_load(Path(r.file).read_text()))[1]
            for r in read_assignment(str(out / "assignment.csv")).rows}


def _sheet(tmp_path: Path, answers: dict[str, float], name: str = "answers.csv") -> Path:
    rows = [["student", "problem", "answer", "value"]]
    rows += [[s, "11/3", "min_spin", f"{v:.5g} rpm"] for s, v in answers.items()]
    path = tmp_path / name
    path.parent.mkdir(parents=True, exist_ok=True)
    with open(path, "w", newline="", encoding="utf-8") as handle:
        csv.writer(handle, lineterminator="\n").writerows(rows)
    return path


def _grades(run, sheet: Path, out: Path) -> dict:
    result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
                 "--format", "json")
    assert result.exit_code == 0, result.output
    return json.loads(result.stdout)


def _one_line(result, *words: str) -> None:
    assert result.exit_code == 2, result.output
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1 and "Traceback" not in result.output, result.stderr
    for word in words:
        assert word in lines[0], (word, lines[0])


def _roster(tmp_path: Path, ids: list[str], name: str = "roster.csv") -> Path:
    path = tmp_path / name
    with open(path, "w", newline="", encoding="utf-8") as handle:
        writer = csv.writer(handle, lineterminator="\n")
        writer.writerow(["student"])
        writer.writerows([i] for i in ids)
    return path


# ---- item 10 -----------------------------------------------------------------------------

def test_item10_safe_names_are_unique_across_the_roster(run, tmp_path):
    from gyro_cli.checking.assignment import file_names

    hashed = file_names(["x y"])["x y"]  # what a lone `x y` is called
    for order in ([hashed, "x y"], ["x y", hashed]):
        names = file_names(order)
        assert len({n.lower() for n in names.values()}) == 2, names
        assert names[hashed] == hashed  # a plain id keeps its own name
    names = file_names(["Ann", "ann", "ANN", "key", "Assignment", "ann-x", "ann x"])
    lowered = [n.lower() for n in names.values()]
    assert len(set(lowered)) == len(lowered), names  # a case-folding file system too
    assert "key" not in lowered and "assignment" not in lowered  # gyro's own names
    assert names["Ann"] == "Ann" and names["ann-x"] == "ann-x"
    # end to end: each student their own file, graded on it
    r = _roster(tmp_path, [hashed, "x y"])
    out = tmp_path / "hw"
    result = run("vary", TOP, "--roster", r, "-o", out)
    assert result.exit_code == 0, result.output
    rows = assignment_rows(out)
    assert len({row["file"].lower() for row in rows}) == 2
    for row in rows:
        assert yaml.safe_load((out / row["file"]).read_text())["id"] == row["variant"]
    graded = _grades(run, _sheet(tmp_path, _own_answers(out)), out)
    assert graded["scores"] == {hashed: ONE_OF_TWO,
                                "x y": ONE_OF_TWO}


# ---- item 11 -----------------------------------------------------------------------------

def test_item11_handout_key_never_replaces_the_roster(run, tmp_path):
    r = put(tmp_path, "class-key.csv", "student,name\nann,Ann Lee\nbob,Bob Roy\n")
    before = r.read_bytes()
    for force in ((), ("--force",)):
        result = run("handout", TOP, "--roster", r, "-o", tmp_path / "class.html", *force)
        _one_line(result, "class-key.csv", "input")
        assert r.read_bytes() == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["class-key.csv"]  # nothing written


def test_item11_grades_out_never_replace_the_assignment_key_or_sheet(run, tmp_path):
    r = _roster(tmp_path, ["ann", "key"])
    out = tmp_path / "hw"
    assert run("vary", TOP, "--roster", r, "-o", out).exit_code == 0
    answers = _own_answers(out)
    inputs = {p: p.read_bytes() for p in (out / "assignment.csv", out / "key.json")}
    both = _sheet(tmp_path, answers)
    one = _sheet(tmp_path, {"ann": answers["ann"]}, "one.csv")
    for sheet, target, fmt in ((both, out / "assignment.csv", "canvas"),
                               (both, out / "assignment.csv", "grades"),
                               (one, out / "key.json", "gradescope"),
                               (one, out / "key.json", "prairielearn")):
        result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
                     "--out", target, "--out-format", fmt, "--force")
        _one_line(result, target.name, "input")
    # the case: --out DIR holding key.json, a student whose id is `key`
    result = run("check", "--answers", both, "--assignment", out / "assignment.csv",
                 "--out", out, "--out-format", "gradescope", "--force")
    assert result.exit_code in (0, 2), result.output
    assert {p: p.read_bytes() for p in inputs} == inputs
    if result.exit_code == 0:  # then the student `key` got a file of their own
        written = sorted(p.name for p in out.glob("*.json") if p.name != "key.json")
        assert len(written) == 2 and "ann.json" in written
    # feedback pages over the sheet itself (a CSV sheet named ann.md)
    sheet = _sheet(tmp_path / "fb", answers, "ann.md")
    before = sheet.read_bytes()
    result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
                 "--feedback", tmp_path / "fb", "--force")
    _one_line(result, "ann.md", "input")
    assert sheet.read_bytes() == before


def test_ids_windows_keeps_for_devices_get_hashed_file_names(run, tmp_path):
    """`con.md` or `11_3/nul.yaml` is a device on Windows, not a file (found by reading
    the code in an adversarial pass): such an id gets a hashed name, as `key` does."""
    from gyro_cli.checking.assignment import file_names

    devices = ["con", "NUL", "Aux", "prn", "com1", "LPT9", "con.x", "nul ", "CONIN$"]
    names = file_names(devices + ["console", "com", "ann"])
    for sid in devices:
        stem = names[sid].split(".")[0].lower()
        assert stem not in {"con", "prn", "aux", "nul", "conin$", "conout$"} and \
            not re.fullmatch(r"(com|lpt)[0-9]", stem), (sid, names[sid])
    assert [names[s] for s in ("console", "com", "ann")] == ["console", "com", "ann"]
    # end to end: the variant files and the feedback pages
    r = _roster(tmp_path, ["con", "ann"])
    out = tmp_path / "hw"
    assert run("vary", TOP, "--roster", r, "-o", out).exit_code == 0
    files = {row["student"]: row["file"] for row in assignment_rows(out)}
    assert files["ann"] == "11_3/ann.yaml" and files["con"].startswith("11_3/con-"), files
    result = run("check", "--answers", _sheet(tmp_path, _own_answers(out)), "--assignment",
                 out / "assignment.csv", "--feedback", tmp_path / "fb")
    assert result.exit_code == 0, result.output
    pages = sorted(p.name for p in (tmp_path / "fb").iterdir())
    assert pages[0] == "ann.md" and pages[1].startswith("con-") and len(pages) == 2, pages


@pytest.mark.parametrize(("one", "other", "words"), [
    ("\u00b5lab", "\u03bclab", "U+00B5 MICRO SIGN against U+03BC GREEK SMALL LETTER MU"),
    ("\ufb01ona", "fiona", "U+FB01 LATIN SMALL LIGATURE FI against U+0066"),
    ("ann\u00a0lee", "ann lee", "U+00A0 NO-BREAK SPACE against U+0020 SPACE"),
    ("\uff41nn", "ann", "U+FF41 FULLWIDTH LATIN SMALL LETTER A against U+0061"),
    # a spreadsheet shows both as 7: the sheet's 7 was graded on 7's variant, 007 missing,
    # and 7 named as having copied 007's numbers (found in an adversarial pass)
    ("007", "7", "drops leading zeros, and shows both as 7"),
    ("0042", "042", "shows both as 42"),
])
def test_roster_ids_that_look_alike_are_refused(run, tmp_path, one, other, words):
    """Two ids no one can tell apart on a sheet (found in an adversarial pass: `µlab` and
    `μlab` were two students, each with a variant) are refused naming both lines."""
    r = _roster(tmp_path, [other, "bob", one])
    result = run("vary", TOP, "--roster", r, "-o", tmp_path / "hw")
    assert result.exit_code == 2, result.output
    (line,) = result.stderr.splitlines()
    assert "looks the same" in line and "lines 2 and 4" in line and words in line, line
    assert not (tmp_path / "hw").exists()


def test_a_sheet_id_that_only_looks_like_a_roster_id_is_named_with_it(run, tmp_path):
    r = _roster(tmp_path, ["\u03bclab", "ann"])
    out = tmp_path / "hw"
    assert run("vary", TOP, "--roster", r, "-o", out).exit_code == 0
    sheet = put(tmp_path, "s.csv", "\u00b5lab,11/3,min_spin,900 rpm\n")
    result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv")
    assert result.exit_code == 2, result.output
    (line,) = result.stderr.splitlines()
    assert "is not in the assignment" in line and "which looks the same" in line, line
    assert "U+00B5 MICRO SIGN against U+03BC" in line, line
    # an id of digits whose leading zeros a spreadsheet dropped
    r = _roster(tmp_path, ["007", "ann"], "r2.csv")
    out = tmp_path / "hw2"
    assert run("vary", TOP, "--roster", r, "-o", out).exit_code == 0
    put(tmp_path, "s.csv", "7,11/3,min_spin,900 rpm\n")
    result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv")
    assert result.exit_code == 2, result.output
    (line,) = result.stderr.splitlines()
    assert "'7' is not in the assignment" in line and "has '007'" in line, line
    assert "drops leading zeros" in line, line
    # an id like no roster id gets no such words
    put(tmp_path, "s.csv", "zed,11/3,min_spin,900 rpm\n")
    result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv")
    assert result.exit_code == 2 and "looks the same" not in result.stderr


# ---- item 12 -----------------------------------------------------------------------------

@pytest.mark.parametrize("column", ["variant", "Problem", "file"])
def test_item12_roster_columns_named_like_gyros_own_are_refused_at_vary(run, tmp_path,
                                                                        column):
    r = put(tmp_path, "r.csv", f"student,{column}\nann,x\n")
    result = run("vary", TOP, "--roster", r, "-o", tmp_path / "hw")
    _one_line(result, "r.csv", repr(column.lower()))
    assert not (tmp_path / "hw").exists()


# ---- item 13 -----------------------------------------------------------------------------

def test_item13_ids_match_by_nfc(run, tmp_path):
    nfc, nfd = unicodedata.normalize("NFC", "café"), unicodedata.normalize("NFD", "café")
    assert nfc != nfd
    result = run("vary", TOP, "--roster", _roster(tmp_path, [nfc, "bob", nfd], "both.csv"),
                 "-o", tmp_path / "no")
    _one_line(result, "listed twice", "lines 2 and 4")
    assert not (tmp_path / "no").exists()
    for written, answered in ((nfd, nfc), (nfc, nfd)):
        out = tmp_path / f"hw-{len(written)}"
        assert run("vary", TOP, "--roster", _roster(tmp_path, [written, "bob"]),
                   "-o", out).exit_code == 0
        answers = _own_answers(out)
        assert set(answers) == {nfc, "bob"}  # the id as NFC
        sheet = _sheet(tmp_path, {answered: answers[nfc], "bob": answers["bob"]})
        graded = _grades(run, sheet, out)
        assert graded["scores"][nfc] == ONE_OF_TWO
        # a YAML sheet too
        ysheet = put(tmp_path, "a.yaml", f"{answered}:\n  11/3:\n    min_spin: "
                                         f"{answers[nfc]:.5g} rpm\n")
        graded = _grades(run, ysheet, out)
        assert graded["scores"][nfc] == ONE_OF_TWO and nfd not in graded["scores"]


# ---- item 14 -----------------------------------------------------------------------------

def test_item14_an_id_starting_with_a_quote_survives_the_round_trip(run, tmp_path):
    ids = ["'=1+1", "=1+1", "''@x", "a,'-b"]
    out = tmp_path / "hw"
    result = run("vary", TOP, "--roster", _roster(tmp_path, ids), "-o", out)
    assert result.exit_code == 0, result.output
    from gyro_cli.checking.assignment import read_assignment

    assert list(read_assignment(str(out / "assignment.csv")).students) == ids
    answers = _own_answers(out)
    graded = _grades(run, _sheet(tmp_path, answers), out)
    assert graded["scores"] == {i: ONE_OF_TWO for i in ids}
    # the handout from the roster reads its own table back the same way
    result = run("handout", TOP, "--roster", _roster(tmp_path, ids), "-o", tmp_path / "s.html")
    assert result.exit_code == 0, result.output
    with open(tmp_path / "s-key.csv", newline="") as handle:
        assert len(list(csv.reader(handle))) == 1 + 2 * len(ids)


@settings(max_examples=400, deadline=None)
@given(st.text(alphabet=st.sampled_from("'=+-@,;|\t\r\n \xa0\uff1d\uff0b\uff20"
                                        "0123456789.eE%ab"), max_size=12))
def test_item14_plain_cell_undoes_safe_cell_exactly(text):
    from gyro_cli.core.csvsafe import plain_cell, safe_cell

    assert plain_cell(safe_cell(text)) == text


@pytest.mark.parametrize("row, what", [('"a\x00b",Ann', "student id"),
                                       ('ann,"A\x00nn"', "name"),
                                       ('"a\u202eb",Ann', "student id"),
                                       ('ann,"A\x1bnn"', "name")])
def test_item14_control_characters_in_ids_and_names_are_refused(run, tmp_path, row, what):
    r = tmp_path / "r.csv"
    r.write_text(f"student,name\nbob,Bob\n{row}\n", encoding="utf-8")
    result = run("vary", TOP, "--roster", r, "-o", tmp_path / "hw")
    _one_line(result, "r.csv", "3", what, "control character")
    assert not (tmp_path / "hw").exists()


# ---- item 15 -----------------------------------------------------------------------------

def test_item15_yaml_sheet_keys_keep_their_text(run, tmp_path):
    ids = ["null", "true", "1.0", "2024-01-01", "No"]
    out = tmp_path / "hw"
    assert run("vary", TOP, "--roster", _roster(tmp_path, ids), "-o", out).exit_code == 0
    answers = _own_answers(out)
    text = "".join(f"{s}:\n  11/3:\n    min_spin: {answers[s]:.5g} rpm\n" for s in ids)
    graded = _grades(run, put(tmp_path, "a.yaml", text), out)
    assert graded["scores"] == {s: ONE_OF_TWO for s in ids}
    # without an assignment too: the student is `null` (or `~`), not `None`
    for key in ("null", "~", "NULL"):
        result = run("check", "--answers", put(tmp_path, "b.yaml", f"{key}:\n  11/3:\n"
                                               "    min_spin: 1000 rpm\n"), TOP,
                     "--format", "json")
        assert result.exit_code == 0, result.output
        assert list(json.loads(result.stdout)["scores"]) == [key]
    # `null` and `~` keep their text as keys (the loader never reads a key as null): two
    # students, each graded on their own row; an empty id is refused naming the line
    result = run("check", "--answers", put(tmp_path, "c.yaml", "null:\n  11/3:\n"
                                           "    min_spin: 1 rpm\n~:\n  11/3:\n"
                                           "    min_spin: 2 rpm\n"), TOP, "--format", "json")
    assert result.exit_code == 0, result.output
    assert list(json.loads(result.stdout)["scores"]) == ["null", "~"]
    result = run("check", "--answers", put(tmp_path, "d.yaml", "ann:\n  11/3:\n"
                                           "    min_spin: 1 rpm\n'':\n  11/3:\n"
                                           "    min_spin: 1 rpm\n"), TOP)
    _one_line(result, "d.yaml", "line 4", "empty student id")


# ---- item 16 -----------------------------------------------------------------------------

def test_item16_canvas_column_from_the_out_name_is_neutralised(run, tmp_path):
    out = tmp_path / "hw"
    assert run("vary", TOP, "--roster", _roster(tmp_path, ["ann"]), "-o", out).exit_code == 0
    sheet = _sheet(tmp_path, _own_answers(out))
    target = tmp_path / "=1+2.csv"
    result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
                 "--out", target, "--out-format", "canvas")
    assert result.exit_code == 0, result.output
    with open(target, newline="") as handle:
        header = next(csv.reader(handle))
    assert header[-1] == "'=1+2"


def test_a_canvas_gradebook_export_is_read_as_a_roster(run, tmp_path):
    """A teacher's roster straight from Canvas (Grades > Export; gyro's own --out-format
    canvas writes the same columns): its Student column holds names, a Points Possible
    row sits under the header. A fresh-clone walk-through found 'Lee, Ann' made an id and
    'Points Possible' a student, without a word. The student is the SIS User ID, else the
    Canvas ID; the name is kept."""
    roster = tmp_path / "canvas.csv"
    roster.write_text('Student,ID,SIS User ID,SIS Login ID,Section,HW 3 (123)\n'
                      '    Points Possible,,,,,2\n"Lee, Ann",101,S1,ann,A,\n'
                      '"Roe, Bob",102,,bob,A,\n"Student, Test",999,,,A,\n')
    done = run("vary", TOP, "--roster", roster, "-o", tmp_path / "hw")
    assert done.exit_code == 0, done.output
    rows = list(csv.DictReader((tmp_path / "hw" / "assignment.csv").open()))
    assert [(r["student"], r["name"]) for r in rows] == [("S1", "Lee, Ann"), ("102", "Roe, Bob")]
