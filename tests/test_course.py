"""Per-student homework (issue 25): variants by roster, grading by assignment.

Independent references: each student's correct answers are worked here by hand
from the numbers in their own variant file (the 11/3 top: the quadratic of
Eq. 11.13 with thetaddot = 0 solved with the quadratic formula, and the least
spin of Eq. 11.21), not taken from the solver or from the file's `expected`.
The grades CSV is read back with the csv module and counted here.
"""

from __future__ import annotations

import csv
import math
from pathlib import Path

import yaml
from test_check import put

ROOT = Path(__file__).resolve().parent.parent
TOP = ROOT / "problems" / "11_3.yaml"
MOTOR = ROOT / "problems" / "11_5.yaml"
RPM = 2 * math.pi / 60
IN = 0.0254
OZF = 0.28349523125 * 9.80665  # ounce-force in N
G_US = 32.2 * 0.3048            # the textbook g for US data


def roster(tmp_path: Path, n: int, name: str = "roster.csv") -> Path:
    lines = ["student,name,section"] + [f"s{k:03d},Student {k},{1 + k % 3}" for k in range(n)]
    return put(tmp_path, name, "\n".join(lines) + "\n")


def by_hand(variant: dict) -> tuple[list[float], float]:
    """The 11/3 top's two precession rates and least spin (rpm), worked from the given
    text: m = W / g, J = m k_z^2, I = m k_O^2, (J - I) cos(theta) phidot^2 +
    J psidot phidot - m g l = 0, psidot_min = 2 sqrt((I - J) m g l cos(theta)) / J."""
    g = variant["given"]
    number = {k: float(str(v).split()[0]) for k, v in g.items()}
    assert g["weight"].endswith("oz") and g["spin"].endswith("rpm") and g["theta"].endswith("deg")
    m = number["weight"] * OZF / G_US
    J, I = m * (number["k_axial"] * IN) ** 2, m * (number["k_pivot"] * IN) ** 2
    mgl = m * G_US * number["cg_distance"] * IN
    psidot, theta = number["spin"] * RPM, math.radians(number["theta"])
    a, b, c = (J - I) * math.cos(theta), J * psidot, -mgl
    disc = math.sqrt(b * b - 4 * a * c)
    roots = sorted(((-b + disc) / (2 * a), (-b - disc) / (2 * a)), key=abs)
    least = 2 * math.sqrt((I - J) * mgl * math.cos(theta)) / J
    return [r / RPM for r in roots], least / RPM


def make_set(run, tmp_path: Path, n: int, *files: Path, seed: int = 7) -> Path:
    out = tmp_path / "hw"
    result = run("vary", *files, "--roster", roster(tmp_path, n), "--seed", seed, "-o", out)
    assert result.exit_code == 0, result.output
    return out


def assignment_rows(out: Path) -> list[dict]:
    with open(out / "assignment.csv", newline="") as handle:
        return list(csv.DictReader(handle))


def test_roster_of_50_each_graded_on_their_own_variant(run, tmp_path):
    out = make_set(run, tmp_path, 50, TOP)
    rows = assignment_rows(out)
    assert [r["student"] for r in rows] == [f"s{k:03d}" for k in range(50)]
    assert {r["section"] for r in rows} == {"1", "2", "3"}  # the roster's columns kept
    lines = ["student,problem,answer,value"]
    answers = {}
    for r in rows:
        variant = yaml.safe_load((out / r["file"]).read_text())
        assert variant["id"] == r["variant"] == f"11/3-{r['student']}"
        roots, least = by_hand(variant)
        answers[r["student"]] = (roots, least)
        lines.append(f"{r['student']},11/3,precession,{roots[0]:.4g} rpm; {roots[1]:.4g} rpm")
        lines.append(f"{r['student']},11/3,min_spin,{least:.4g} rpm")
    assert len({a[1] for a in answers.values()}) > 40  # their own numbers, not one set
    # s001 copies s000's answers (someone else's numbers), under their own problem id, to
    # 6 digits: one problem of a class of 50 at 4 digits could be chance (test_i34_feedback)
    lines = [l for l in lines if not l.startswith("s001,")]
    roots0, least0 = answers["s000"]
    lines.append(f"s001,11/3,precession,{roots0[0]:.6g} rpm; {roots0[1]:.6g} rpm")
    lines.append(f"s001,11/3,min_spin,{least0:.6g} rpm")
    sheet = put(tmp_path, "sheet.csv", "\n".join(lines) + "\n")
    grades = tmp_path / "grades.csv"
    result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv", TOP,
                 "--out", grades)
    assert result.exit_code == 0, result.output
    with open(grades, newline="") as handle:
        graded = list(csv.DictReader(handle))
    items = [g for g in graded if g["result"] != "score"]
    scores = {g["student"]: (float(g["points"]), float(g["max_points"])) for g in graded
              if g["result"] == "score"}
    assert len(items) == 50 * 2  # students x answers, not students x variants
    assert len(scores) == 50
    for student, (points, total) in scores.items():
        assert total == 2
        assert points == (0 if student == "s001" else 2), student
    copied = [g for g in items if g["student"] == "s001"]
    assert {g["result"] for g in copied} == {"wrong"}
    for g in copied:
        assert "student s000's variant 11/3-s000" in g["note"], g["note"]
        assert g["variant"] == "11/3-s001"


def test_adding_a_student_changes_nobody_elses_numbers(run, tmp_path):
    first = make_set(run, tmp_path / "a", 5, TOP, MOTOR)
    (tmp_path / "b").mkdir()
    more = tmp_path / "b" / "roster.csv"
    more.write_text("student\nnew-one\n" + "".join(f"s{k:03d}\n" for k in range(5)))
    out = tmp_path / "b" / "hw"
    assert run("vary", TOP, MOTOR, "--roster", more, "--seed", 7, "-o", out).exit_code == 0
    for r in assignment_rows(first):
        assert (first / r["file"]).read_text() == (out / r["file"]).read_text()
    other_seed = make_set(run, tmp_path / "c", 5, TOP, seed=8)
    assert (other_seed / "11_3" / "s000.yaml").read_text() != \
        (first / "11_3" / "s000.yaml").read_text()
    # and each variant passes its own answer key
    assert run("check", first).exit_code == 0


def test_missing_means_an_assigned_question_left_blank(run, tmp_path):
    out = make_set(run, tmp_path, 3, TOP, MOTOR)
    variant = yaml.safe_load((out / "11_3" / "s000.yaml").read_text())
    roots, least = by_hand(variant)
    sheet = put(tmp_path, "s.csv", f"s000,11/3-s000,min_spin,{least:.4g} rpm\n")
    result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
                 "--format", "json")
    assert result.exit_code == 0, result.output
    import json

    data = json.loads(result.stdout)
    # 3 students x (2 answers of 11/3 + the 1 of 11/5 its statement asks, `ask:`), whatever
    # the sheet holds (11/5's moment, never asked, was once graded missing)
    assert len(data["rows"]) == 9
    mine = [r for r in data["rows"] if r["student"] == "s000"]
    assert [(r["answer"], r["result"]) for r in mine] == [
        ("precession", "missing"), ("min_spin", "correct"), ("bearing_forces", "missing")]
    assert data["scores"]["s000"] == {"points": 1.0, "max_points": 3.0}


def test_assignment_refuses_strangers_and_doubles(run, tmp_path):
    out = make_set(run, tmp_path, 2, TOP)
    stranger = put(tmp_path, "x.csv", "zed,11/3,min_spin,900 rpm\n")
    result = run("check", "--answers", stranger, "--assignment", out / "assignment.csv")
    assert result.exit_code == 2
    assert "'zed' is not in the assignment" in result.stderr and "line 1" in result.stderr
    twice = put(tmp_path, "r2.csv", "student\nann\nbob\nann\n")
    result = run("vary", TOP, "--roster", twice, "-o", tmp_path / "hw2")
    assert result.exit_code == 2
    assert "'ann' is listed twice (lines 2 and 4)" in result.stderr
    assert not (tmp_path / "hw2").exists()
    result = run("vary", TOP, "--roster", roster(tmp_path, 2), "-o", out)
    assert result.exit_code == 2 and "exists; not overwritten" in result.stderr


def test_unsafe_student_ids_make_safe_file_names(run, tmp_path):
    r = put(tmp_path, "r.csv", 'student\n../../etc/passwd\n"=cmd|\' /C calc\'!A0"\nAnn\nann\n')
    out = tmp_path / "hw"
    result = run("vary", TOP, "--roster", r, "-o", out)
    assert result.exit_code == 0, result.output
    files = sorted(p.relative_to(out).as_posix() for p in out.rglob("*.yaml"))
    assert len(files) == 4 and all(f.startswith("11_3/") and ".." not in f for f in files)
    rows = assignment_rows(out)
    assert rows[1]["student"].startswith("'=")  # neutralised for a spreadsheet
    # ... and read back by gyro as the id it was
    sheet = put(tmp_path, "s.csv", "\"=cmd|' /C calc'!A0\",11/3,min_spin,900 rpm\n")
    result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv")
    assert result.exit_code == 0, result.output


def test_an_edited_variant_is_solved_again_not_graded_by_the_stored_key(run, tmp_path):
    out = make_set(run, tmp_path, 2, TOP)
    assert (out / "key.json").is_file()
    path = out / "11_3" / "s000.yaml"
    variant = yaml.safe_load(path.read_text())
    variant["given"]["spin"] = "2500 rpm"  # the teacher changed this student's numbers
    path.write_text(yaml.safe_dump(variant, sort_keys=False))
    roots, least = by_hand(variant)
    sheet = put(tmp_path, "s.csv", f"s000,11/3,precession,{roots[0]:.4g} rpm; "
                                   f"{roots[1]:.4g} rpm\n")
    result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
                 "--format", "json")
    assert result.exit_code == 0, result.output
    assert '"result": "correct"' in result.stdout
    # ... and the teacher is told which file changed (a handout made before shows the
    # numbers drawn; found unsaid in an adversarial pass)
    notes = [line for line in result.stderr.splitlines() if line.startswith("gyro: note:")]
    assert len(notes) == 1 and "1 variant file(s) changed since gyro vary" in notes[0]
    assert "s000.yaml" in notes[0] and "s001.yaml" not in notes[0]
    # a damaged key is ignored (every variant solved), not an error
    (out / "key.json").write_text("{not json")
    result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
                 "--format", "json")
    assert result.exit_code == 0 and '"result": "correct"' in result.stdout


def _graded_set(run, tmp_path):
    """Three students (roster with Canvas's columns); s000 right, s001 half, s002 blank."""
    r = put(tmp_path, "roster.csv", "student,name,sis_user_id,section\n"
                                    "s000,Ann Lee,A100,L1\ns001,Bob Roy,A101,L2\n"
                                    "s002,Cy Dee,,L1\n")
    out = tmp_path / "hw"
    assert run("vary", TOP, "--roster", r, "-o", out).exit_code == 0
    lines = []
    for student in ("s000", "s001"):
        roots, least = by_hand(yaml.safe_load((out / "11_3" / f"{student}.yaml").read_text()))
        lines.append(f"{student},11/3,precession,{roots[0]:.4g} rpm; {roots[1]:.4g} rpm")
        lines.append(f"{student},11/3,min_spin,{least * (1 if student == 's000' else 2):.4g} rpm")
    return put(tmp_path, "sheet.csv", "\n".join(lines) + "\n"), out / "assignment.csv"


def test_grades_out_canvas_gradebook_csv(run, tmp_path):
    sheet, assignment = _graded_set(run, tmp_path)
    target = tmp_path / "HW 3.csv"
    result = run("check", "--answers", sheet, "--assignment", assignment, "--out", target,
                 "--out-format", "canvas")
    assert result.exit_code == 0, result.output
    with open(target, newline="") as handle:
        rows = list(csv.reader(handle))
    # Canvas's import: these five columns first, then the assignment; "Points Possible" row
    assert rows[0] == ["Student", "ID", "SIS User ID", "SIS Login ID", "Section", "HW 3"]
    assert rows[1][0].strip() == "Points Possible" and rows[1][5] == "2"
    assert rows[2] == ["Ann Lee", "", "A100", "", "L1", "2"]
    assert rows[3] == ["Bob Roy", "", "A101", "", "L2", "1"]
    assert rows[4] == ["Cy Dee", "", "s002", "", "L1", "0"]  # gyro's id where the SIS id is blank


def test_grades_out_gradescope_and_prairielearn_results(run, tmp_path):
    import json

    sheet, assignment = _graded_set(run, tmp_path)
    for fmt in ("gradescope", "prairielearn"):
        folder = tmp_path / fmt
        result = run("check", "--answers", sheet, "--assignment", assignment, "--out", folder,
                     "--out-format", fmt)
        assert result.exit_code == 0, result.output
        assert sorted(p.name for p in folder.iterdir()) == ["s000.json", "s001.json",
                                                            "s002.json"]
        bob = json.loads((folder / "s001.json").read_text())
        if fmt == "gradescope":  # results.json of Gradescope's autograder specification
            assert bob["score"] == 1
            assert [(t["name"], t["score"], t["max_score"], t["status"]) for t in bob["tests"]] \
                == [("11/3: precession", 1, 1, "passed"), ("11/3: min_spin", 0, 1, "failed")]
            assert all(isinstance(t["output"], str) for t in bob["tests"])
        else:  # PrairieLearn's external grader results: score a fraction, gradable
            assert bob["gradable"] is True and bob["score"] == 0.5
            assert [(t["name"], t["points"], t["max_points"]) for t in bob["tests"]] == \
                [("11/3: precession", 1, 1), ("11/3: min_spin", 0, 1)]
            # which way it is off, not by how much (the solver's value): issue 34, item 9
            assert bob["tests"][1]["message"].endswith("rpm: too high")
    # one student's sheet (as inside an autograder): --out is the results file itself
    one = put(tmp_path, "one.csv", sheet.read_text().splitlines()[0] + "\n")
    target = tmp_path / "results.json"
    result = run("check", "--answers", one, "--assignment", assignment, "--out", target,
                 "--out-format", "gradescope")
    assert result.exit_code == 0
    assert json.loads(target.read_text())["tests"]


def _slipped_sheet(run, tmp_path):
    """s000..s004 each give min_spin with one slip: none, x 2 pi, minus, minus x 2 pi, x 60."""
    out = make_set(run, tmp_path, 5, TOP)
    factors = {"s000": 1, "s001": 2 * math.pi, "s002": -1, "s003": -2 * math.pi, "s004": 60}
    lines = []
    for student, factor in factors.items():
        _, least = by_hand(yaml.safe_load((out / "11_3" / f"{student}.yaml").read_text()))
        lines.append(f"{student},11/3,min_spin,{least * factor:.5g} rpm")
    return put(tmp_path, "slips.csv", "\n".join(lines) + "\n"), out / "assignment.csv"


def test_credit_for_named_slips(run, tmp_path):
    import json

    sheet, assignment = _slipped_sheet(run, tmp_path)

    def points(*extra):
        result = run("check", "--answers", sheet, "--assignment", assignment, "--format",
                     "json", *extra)
        assert result.exit_code == 0, result.output
        rows = json.loads(result.stdout)["rows"]
        return {r["student"]: r["points"] for r in rows if r["answer"] == "min_spin"}

    assert points() == {"s000": 1, "s001": 0, "s002": 0, "s003": 0, "s004": 0}
    # 2 pi half, sign half; both slips at once: half of half; 60 is not in the policy
    assert points("--credit", "2pi=0.5,sign=0.5") == \
        {"s000": 1, "s001": 0.5, "s002": 0.5, "s003": 0.25, "s004": 0}
    assert points("--credit", "2pi=0.5") == \
        {"s000": 1, "s001": 0.5, "s002": 0, "s003": 0, "s004": 0}
    for bad, message in (("pi=0.5", "with a slip among 2pi, rpm"), ("2pi=2", "between 0 and 1"),
                         ("2pi", "expected slip=fraction")):
        result = run("check", "--answers", sheet, "--assignment", assignment, "--credit", bad)
        assert result.exit_code == 2 and message in result.stderr, result.output


def test_feedback_pages(run, tmp_path):
    sheet, assignment = _slipped_sheet(run, tmp_path)
    folder = tmp_path / "feedback"
    result = run("check", "--answers", sheet, "--assignment", assignment, "--feedback", folder,
                 "--credit", "2pi=0.5")
    assert result.exit_code == 0, result.output
    assert sorted(p.name for p in folder.iterdir()) == [f"s00{k}.md" for k in range(5)]
    ann = (folder / "s000.md").read_text()
    assert "Score: 1 of 2 points (50.0%)" in ann
    assert "## Right" in ann and "11/3, min\\_spin" in ann
    assert "precession: not answered" in ann
    bob = (folder / "s001.md").read_text()
    assert "likely slip: a factor of 2 pi" in bob and "0.5 of 1 points" in bob
    # the solver's value is not on the page (it can go out before the due date)
    variant = yaml.safe_load((assignment.parent / "11_3" / "s001.yaml").read_text())
    assert variant["expected"]["min_spin"].split()[0] not in bob
    again = run("check", "--answers", sheet, "--assignment", assignment, "--feedback", folder)
    assert again.exit_code == 2 and "exists; not overwritten" in again.stderr


def test_a_student_id_with_a_line_break_is_refused(run, tmp_path):
    # it would reach file names, variant ids and the LaTeX write-up's comment line
    r = put(tmp_path, "r.csv", 'student\nann\n"x\n\\\\input{/etc/hostname}"\n')
    result = run("vary", TOP, "--roster", r, "-o", tmp_path / "hw")
    # refused as every cell over a line break is (tests/test_csv_one_line_cells.py)
    assert result.exit_code == 2 and "a cell runs over a line break" in result.stderr
    assert "line 3" in result.stderr and not (tmp_path / "hw").exists()


def _solver_answer(run, variant: Path, name: str) -> str:
    import json

    done = run("solve", "--format", "json", variant)
    answer = json.loads(done.stdout)["answers"][name]
    return "; ".join(f"{v!r} {answer['unit']}" for v in answer["values"])


def test_a_student_is_graded_on_what_their_statement_asks(run, tmp_path):
    """11/5's statement asks the supports' forces alone (`ask: [bearing_forces]`): a full
    answer to it is full marks, with the key and without it, and the moment the file also
    finds is not a question (it was graded `missing`, half the points, in every student's
    feedback)."""
    out = make_set(run, tmp_path, 2, MOTOR)
    answer = _solver_answer(run, out / "11_5" / "s000.yaml", "bearing_forces")
    sheet = put(tmp_path, "s.csv", f"s000,11/5,bearing_forces,{answer}\n")
    for keyed in (True, False):
        if not keyed:
            (out / "key.json").rename(tmp_path / "key.json")
        feedback = tmp_path / f"fb-{keyed}"
        result = run("check", "--answers", sheet, "--assignment", out / "assignment.csv",
                     "--feedback", feedback, "--format", "json")
        assert result.exit_code == 0, result.output
        import json

        data = json.loads(result.stdout)
        assert data["scores"]["s000"] == {"points": 1.0, "max_points": 1.0}, keyed
        assert {r["answer"] for r in data["rows"]} == {"bearing_forces"}, keyed
        assert "moment" not in (feedback / "s000.md").read_text(encoding="utf-8")


def test_vary_roster_counts_the_variants_it_wrote(run, tmp_path):
    """2 students x 2 problems are 4 variant files (key.json was counted as a fifth)."""
    result = run("vary", TOP, MOTOR, "--roster", roster(tmp_path, 2), "-o", tmp_path / "hw")
    assert result.exit_code == 0, result.output
    written = sorted(p for p in (tmp_path / "hw").rglob("*.yaml"))
    assert len(written) == 4
    assert "wrote 4 variant file(s), the key and the assignment:" in result.stderr


def test_a_copy_names_every_student_who_drew_the_same_numbers(run, tmp_path):
    """s0374 and s0487 draw the same 11/3 (seed 2026): answers with those numbers are
    either's, and the teacher's note names both, not the first in order alone."""
    import json

    path = put(tmp_path, "r.csv", "student\ns0000\ns0374\ns0487\n")
    assert run("vary", TOP, "--roster", path, "--seed", "2026", "-o",
               tmp_path / "hw").exit_code == 0
    given = [yaml.safe_load((tmp_path / "hw" / "11_3" / f"{s}.yaml").read_text())["given"]
             for s in ("s0374", "s0487", "s0000")]
    assert given[0] == given[1] != given[2]  # the premise: two alike, the copier's own not
    theirs = json.loads(run("solve", "--format", "json",
                            tmp_path / "hw" / "11_3" / "s0487.yaml").stdout)["answers"]
    rows = [f"s0000,11/3,{name},{'; '.join(f'{v!r} rpm' for v in theirs[name]['values'])}"
            for name in ("precession", "min_spin")]
    sheet = put(tmp_path, "s.csv", "\n".join(rows) + "\n")
    result = run("check", "--answers", sheet, "--assignment", tmp_path / "hw" / "assignment.csv",
                 "--format", "json")
    notes = [r["note"] for r in json.loads(result.stdout)["rows"] if r["student"] == "s0000"]
    assert len(notes) == 2 and all("s0374" in n and "s0487" in n for n in notes), notes
