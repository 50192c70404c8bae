"""`gyro handout` (issue 25.4): question sheets with each student's numbers, solutions, key.

The numbers a sheet must show are read here from the student's variant as
`gyro vary --roster` writes it with the same seed; LaTeX is compiled with
pdflatex where it is installed (skipped with the reason otherwise).
"""

from __future__ import annotations

import csv
import html
import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest
import yaml
from test_check import put

ROOT = Path(__file__).resolve().parent.parent
TOP, MOTOR = ROOT / "problems" / "11_3.yaml", ROOT / "problems" / "11_5.yaml"


def roster(tmp_path: Path) -> Path:
    return put(tmp_path, "roster.csv", "student,name\nann,Ann <b>Lee</b>\nbob,Bob & Roy\n")


def test_handout_by_roster_with_solutions_end_to_end(run, tmp_path, monkeypatch):
    r = roster(tmp_path)
    monkeypatch.chdir(tmp_path)
    # the command as it is: default output handout.html, a sheet per student
    result = run("handout", TOP, MOTOR, "--roster", r, "--solutions")
    assert result.exit_code == 0, result.output
    assert sorted(os.listdir(tmp_path)) == ["handout-ann.html", "handout-bob.html",
                                            "handout-key.csv", "roster.csv"]
    assert run("vary", TOP, MOTOR, "--roster", r, "-o", tmp_path / "hw").exit_code == 0
    for student in ("ann", "bob"):
        page = (tmp_path / f"handout-{student}.html").read_text()
        for stem in ("11_3", "11_5"):
            given = yaml.safe_load((tmp_path / "hw" / stem / f"{student}.yaml").read_text())["given"]
            assert f"spins at {given['spin']}" in page or f"turns at {given['spin']}" in page
        assert page.count("<article") == 2  # the two worked answers
        assert "<b>" not in page and "Ann &lt;b&gt;Lee&lt;/b&gt; (ann)" in page or \
            student == "bob"
    with open(tmp_path / "handout-key.csv", newline="") as handle:
        key = list(csv.DictReader(handle))
    assert [(k["student"], k["problem"], k["answer"]) for k in key][:2] == \
        [("ann", "11/3", "precession"), ("ann", "11/3", "min_spin")]
    ann = yaml.safe_load((tmp_path / "hw" / "11_3" / "ann.yaml").read_text())["expected"]
    assert key[1]["correct"] == ann["min_spin"]
    # written again: refused, nothing replaced
    again = run("handout", TOP, MOTOR, "--roster", r)
    assert again.exit_code == 2 and "exists; not overwritten" in again.stderr


def test_handout_from_an_assignment_is_the_same_sheet(run, tmp_path):
    r = roster(tmp_path)
    assert run("vary", TOP, "--roster", r, "--seed", 5, "-o", tmp_path / "hw").exit_code == 0
    a = run("handout", "--assignment", tmp_path / "hw" / "assignment.csv", "-o",
            tmp_path / "a" / "s.tex")
    assert a.exit_code == 2 and "no such directory" in a.stderr
    (tmp_path / "a").mkdir()
    (tmp_path / "b").mkdir()
    a = run("handout", "--assignment", tmp_path / "hw" / "assignment.csv", "-o",
            tmp_path / "a" / "s.tex")
    b = run("handout", TOP, "--roster", r, "--seed", 5, "-o", tmp_path / "b" / "s.tex")
    assert a.exit_code == 0 and b.exit_code == 0, a.output + b.output
    assert (tmp_path / "a" / "s-ann.tex").read_text() == (tmp_path / "b" / "s-ann.tex").read_text()
    # the key lies beside the sheets, named like them: the teacher is told to keep it back
    # (a fresh-clone walk-through handed out s-* with the key among them)
    assert f"{tmp_path / 'a' / 's-key.csv'} is the teacher's key" in a.stderr, a.stderr


def test_one_handout_for_everyone_states_every_bundled_problem(run, tmp_path):
    out = tmp_path / "all.tex"
    result = run("handout", ROOT / "problems", "-o", out, "--course", "ME 301 & co", "--title",
                 "Chapter 11 {all}")
    assert result.exit_code == 0, result.output
    tex = out.read_text()
    assert tex.count("\\section*{Problem ") == len(list((ROOT / "problems").glob("*.yaml")))
    assert "ME 301 \\& co -- Chapter 11 \\{all\\}" in tex
    assert "A top of weight 3 oz has radii of gyration of 0.84 in" in tex
    assert "{spin}" not in tex


def test_handout_refuses_an_unknown_format_and_a_missing_pdflatex(run, tmp_path, monkeypatch):
    result = run("handout", TOP, "-o", tmp_path / "h.docx")
    assert result.exit_code == 2 and ".html, .tex or .pdf" in result.stderr
    if shutil.which("pdflatex") is None:
        result = run("handout", TOP, "-o", tmp_path / "h.pdf")
        assert result.exit_code == 2 and "needs pdflatex" in result.stderr
        assert not (tmp_path / "h.pdf").exists()


@pytest.mark.skipif(shutil.which("pdflatex") is None,
                    reason="pdflatex is not installed (apt-get install texlive-latex-base "
                           "texlive-latex-recommended texlive-latex-extra)")
def test_handout_latex_compiles_clean(run, tmp_path):
    out = tmp_path / "h.tex"
    result = run("handout", TOP, MOTOR, "--roster", roster(tmp_path), "--solutions", "-o", out)
    assert result.exit_code == 0, result.output
    for tex in tmp_path.glob("h-*.tex"):
        done = subprocess.run(["pdflatex", "-interaction=nonstopmode", "-halt-on-error",
                               tex.name], cwd=tmp_path, capture_output=True, text=True,
                              timeout=120)
        assert done.returncode == 0, done.stdout[-2000:]
        assert "Overfull \\hbox" not in done.stdout


def test_the_teachers_key_lists_what_grading_grades(run, tmp_path):
    """A step asked (`steps: [I]`) is a row of the key and 11/5's `moment`, which its
    statement does not ask, is none (an adversarial pass found the step missing and the
    unasked moment listed): the key's questions are key.json's, what a student is graded
    on, each with the value grading takes as right."""
    top = tmp_path / "top.yaml"
    top.write_text(TOP.read_text().replace("tolerance: 1%\n", "tolerance: 1%\nsteps: [I]\n"))
    r = roster(tmp_path)
    assert run("handout", top, MOTOR, "--roster", r, "--seed", 4,
               "-o", tmp_path / "h.html").exit_code == 0
    with open(tmp_path / "h-key.csv", newline="") as handle:
        key = list(csv.DictReader(handle))
    assert [(k["student"], k["problem"], k["answer"]) for k in key] == [
        (s, p, a) for s in ("ann", "bob")
        for p, a in (("11/3", "I"), ("11/3", "precession"), ("11/3", "min_spin"),
                     ("11/5", "bearing_forces"))]
    assert run("vary", top, MOTOR, "--roster", r, "--seed", 4,
               "-o", tmp_path / "hw").exit_code == 0
    stored = json.loads((tmp_path / "hw" / "key.json").read_text())
    assert {p: about["questions"] for p, about in stored["problems"].items()} == \
        {"11/3": ["precession", "min_spin"], "11/5": ["bearing_forces"]}
    # every value of the key, answered, is graded right
    sheet = tmp_path / "sheet.csv"
    sheet.write_text("student,problem,answer,value\n" + "".join(
        f"{k['student']},{k['problem']},{k['answer']},{k['correct']}\n" for k in key))
    graded = run("check", "--answers", sheet, "--assignment",
                 tmp_path / "hw" / "assignment.csv", "--format", "json")
    assert graded.exit_code == 0, graded.output
    rows = json.loads(graded.stdout)["rows"]
    assert len(rows) == 8 and all(row["result"] == "correct" for row in rows), rows


def test_a_sheet_that_fails_leaves_no_class_half_written(run, tmp_path, monkeypatch):
    """Each sheet and the key are placed together at the end: a PDF that failed for the
    second student had left the first's sheet written (and a rerun refused over it)."""
    from gyro_cli.commands import handout
    from gyro_cli.core.errors import InputError

    made = []

    def compile_once(tex: str) -> bytes:
        made.append(tex)
        if len(made) == 2:
            raise InputError("pdflatex failed: ! Emergency stop.")
        return b"%PDF-1.5 stand-in\n"

    monkeypatch.setattr(handout, "compile_pdf", compile_once)
    r = roster(tmp_path)
    out = tmp_path / "out"
    out.mkdir()
    result = run("handout", TOP, "--roster", r, "-o", out / "s.pdf")
    assert result.exit_code == 2 and "pdflatex failed" in result.stderr, result.output
    assert len(made) == 2 and list(out.iterdir()) == []
    made.clear()
    monkeypatch.setattr(handout, "compile_pdf", lambda tex: b"%PDF-1.5 stand-in\n")
    result = run("handout", TOP, "--roster", r, "-o", out / "s.pdf")
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in out.iterdir()) == ["s-ann.pdf", "s-bob.pdf", "s-key.csv"]
    # a roster's numbers are drawn from the seed: the teacher is reminded which
    assert "drawn from --seed 0" in result.stderr and "--assignment" in result.stderr


def test_each_sheet_says_how_to_write_its_answers(run, tmp_path):
    """A student's sheet names the problem id to write, each question graded with its
    unit, how many values and in which order (a fresh-clone walk-through: the sheets
    named no answer, and one wrong name stops the grading of a whole class)."""
    out = tmp_path / "s.html"
    done = run("handout", TOP, MOTOR, "-o", out)
    assert done.exit_code == 0, done.output
    text = html.unescape(out.read_text())
    assert ("Answer as problem 11/3: precession in rpm, two values separated by ';' (slow; "
            "fast, in any order); min_spin in rpm.") in text
    assert ("Answer as problem 11/5: bearing_forces in N, two values separated by ';' "
            "(A; B, in that order).") in text


def test_the_key_goes_to_the_teachers_folder_and_the_sheets_folder_holds_only_sheets(
        run, tmp_path):
    # The quick-start had written the sheets into the assignment's folder, beside key.json,
    # assignment.csv and their own key: a teacher handing out "the hw3 folder" (a helper
    # did) gave every student every answer. --key puts the key elsewhere.
    r = roster(tmp_path)
    assert run("vary", TOP, "--roster", r, "-o", tmp_path / "hw").exit_code == 0
    (tmp_path / "sheets").mkdir()
    out = run("handout", "--assignment", tmp_path / "hw" / "assignment.csv", "-o",
              tmp_path / "sheets" / "hw.html", "--key", tmp_path / "hw" / "hw-key.csv")
    assert out.exit_code == 0, out.output
    assert sorted(os.listdir(tmp_path / "sheets")) == ["hw-ann.html", "hw-bob.html"]
    assert f"{tmp_path / 'hw' / 'hw-key.csv'} is the teacher's key" in out.stderr
    with open(tmp_path / "hw" / "hw-key.csv", newline="") as handle:
        assert {row["student"] for row in csv.DictReader(handle)} == {"ann", "bob"}


def test_key_goes_with_a_class(run, tmp_path):
    out = run("handout", TOP, "-o", tmp_path / "all.html", "--key", tmp_path / "k.csv")
    assert out.exit_code == 2 and "goes with --roster or --assignment" in out.stderr


@pytest.mark.parametrize("where, said", [
    ("sheets/hw-ann.html", "--key names a student's sheet"),
    ("hw/assignment.csv", "assignment.csv"),
    ("nowhere/key.csv", "no such directory"),
    ("link/hw-ann.html", "--key names a student's sheet"),   # ann's sheet through a link
    ("sheets/HW-ANN.html", "--key names a student's sheet"),  # one file where case folds
    ("sheets/hw.html", "--key names OUT"),                     # a CSV of answers among sheets
    ("hw/key.json", "replace an input file"),                  # gyro vary's own key
])
def test_a_key_that_would_replace_a_sheet_or_an_input_is_refused(run, tmp_path, where, said):
    r = roster(tmp_path)
    assert run("vary", TOP, "--roster", r, "-o", tmp_path / "hw").exit_code == 0
    (tmp_path / "sheets").mkdir()
    (tmp_path / "link").symlink_to(tmp_path / "sheets")
    inputs = [tmp_path / "hw" / name for name in ("key.json", "assignment.csv")]
    before = [path.read_bytes() for path in inputs]
    out = run("handout", "--assignment", tmp_path / "hw" / "assignment.csv", "-o",
              tmp_path / "sheets" / "hw.html", "--key", tmp_path / where, "--force")
    assert out.exit_code == 2 and out.stderr.count("\n") == 1 and said in out.stderr, out.stderr
    assert os.listdir(tmp_path / "sheets") == []
    assert [path.read_bytes() for path in inputs] == before


# ---- one problem's data is another's answer ------------------------------------------------

def test_a_sheet_whose_problem_gives_anothers_answer_is_warned(run, tmp_path):
    # euler_top_11_3 is 11/3's top precessing at the slow rate 11/3 asks for, 45.13 rpm
    out = tmp_path / "hw.html"
    result = run("handout", ROOT / "problems" / "11_3.yaml",
                 ROOT / "problems" / "euler_top_11_3.yaml", "-o", out)
    assert result.exit_code == 0, result.output
    [warning] = [line for line in result.stderr.splitlines() if "warning" in line]
    assert "problem euler-11/3's phi_rate is the answer precession of problem 11/3" in warning
    assert "45.13 rpm and 45.13 rpm" in warning and "gives that answer away" in warning
    assert out.exists()  # written: the teacher decides


@pytest.mark.parametrize("others", [["11_5.yaml"], ["11_2_released_top.yaml"]])
def test_round_or_unrelated_data_is_not_warned(run, tmp_path, others):
    # 11/3's theta = 30 deg is the released top's theta_min = 30 deg: a round number met
    # by chance, which a student learns nothing from
    result = run("handout", ROOT / "problems" / "11_3.yaml",
                 *[ROOT / "problems" / o for o in others], "-o", tmp_path / "hw.html")
    assert result.exit_code == 0 and "warning" not in result.stderr, result.stderr


def test_a_sheet_with_solutions_is_not_warned(run, tmp_path):
    result = run("handout", ROOT / "problems" / "11_3.yaml",
                 ROOT / "problems" / "euler_top_11_3.yaml", "--solutions",
                 "-o", tmp_path / "hw.html")
    assert result.exit_code == 0 and "warning" not in result.stderr, result.stderr


def test_students_sheets_are_warned_once_for_the_pair_with_the_count(run, tmp_path):
    # an assignment written by hand: ann and bob each given 11/3 and the top of 11/3
    rows = ["student,problem,variant,file,name"]
    for student in ("ann", "bob"):
        for name, pid in (("11_3", "11/3"), ("euler_top_11_3", "euler-11/3")):
            text = (ROOT / "problems" / f"{name}.yaml").read_text()
            (tmp_path / f"{student}-{name}.yaml").write_text(
                text.replace(f'id: "{pid}"', f'id: "{pid}-{student}"', 1))
            rows.append(f"{student},{pid},{pid}-{student},{student}-{name}.yaml,{student}")
    (tmp_path / "assignment.csv").write_text("\n".join(rows) + "\n")
    (tmp_path / "out").mkdir()
    result = run("handout", "--assignment", tmp_path / "assignment.csv",
                 "-o", tmp_path / "out" / "hw.html", "--key", tmp_path / "key.csv")
    assert result.exit_code == 0, result.output
    [warning] = [line for line in result.stderr.splitlines() if "warning" in line]
    assert "problem euler-11/3's phi_rate is the answer precession of problem 11/3" in warning
    assert "ann's; so on 2 of 2 sheets" in warning, warning
