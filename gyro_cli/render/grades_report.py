"""`gyro check --answers` reports: the grades as CSV, a table, or JSON."""

from __future__ import annotations

import csv
import dataclasses
import io
import json
from collections.abc import Iterable
from typing import Any

from ..checking.grades import OUT_COLUMNS, Graded
from ..core.csvsafe import safe_cell as _cell
from ..core.errors import terminal_text

# ---- output -----------------------------------------------------------------


def csv_text(graded: Graded) -> str:
    """The grades: one row per student and answer, then a score row per student."""
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    by_assignment = graded.assignment is not None  # then a last column: the variant
    writer.writerow(OUT_COLUMNS + (("variant",) if by_assignment else ()))
    for row in graded.rows:
        rel = "" if row.relative_error is None else f"{row.relative_error:.6g}"
        writer.writerow([_cell(row.student), _cell(row.problem), _cell(row.answer),
                         _cell(row.submitted), _cell(row.correct), rel, row.result,
                         f"{row.points:g}", f"{row.max_points:g}", _cell(row.note)]
                        + ([_cell(row.variant)] if by_assignment else []))
    for student, (points, total) in graded.scores.items():
        percent = 100 * points / total if total else 0.0
        writer.writerow([_cell(student), "", "", "", "", "", "score", f"{points:g}",
                         f"{total:g}", f"{percent:.1f}%"] + ([""] if by_assignment else []))
    return out.getvalue()


def table(graded: Graded) -> str:
    """The grades as a table with a header row, columns as wide as their longest cell."""
    widths = [max([len(head)] + [len(str(getattr(row, name))) for row in graded.rows])
              for head, name in (("student", "student"), ("problem", "problem"),
                                 ("answer", "answer"), ("result", "result"))]
    solver = graded.submitter is None  # --student: the solver's values are not shown
    lines = [f"{'student':<{widths[0]}} {'problem':<{widths[1]}} {'answer':<{widths[2]}} "
             f"{'result':<{widths[3]}} {'points':>6}  submitted"
             + ("  [solver: correct answer]" if solver else "")]
    for row in graded.rows:
        lines.append(f"{row.student:<{widths[0]}} {row.problem:<{widths[1]}} "
                     f"{row.answer:<{widths[2]}} {row.result:<{widths[3]}} "
                     f"{row.points:>6g}  {row.submitted or '-'}"
                     + (f"  [solver: {row.correct}]" if solver else "")
                     + (f"  {row.note}" if row.note and row.result != "correct" else ""))
    lines.append("")
    for student, (points, total) in graded.scores.items():
        percent = 100 * points / total if total else 0.0
        lines.append(f"{student:<12} score {points:g} / {total:g} ({percent:.1f}%)")
    # names and answers come from the sheet: no escape sequence reaches the terminal raw
    return "\n".join(terminal_text(line) for line in lines) + "\n"


def as_json(graded: Graded) -> str:
    return json.dumps({"rows": [_row_json(r, graded) for r in graded.rows],
                       "scores": {s: {"points": p, "max_points": t}
                                  for s, (p, t) in graded.scores.items()}}, allow_nan=False)


def _row_json(row: Any, graded: Graded) -> dict[str, Any]:
    data = dataclasses.asdict(row)
    if graded.assignment is None:
        data.pop("variant", None)
    return data


# ---- grades out: the formats the course's tools import (docs/course.md) -----------------

OUT_FORMATS = ("grades", "canvas", "gradescope", "prairielearn")
CANVAS_COLUMNS = ("Student", "ID", "SIS User ID", "SIS Login ID", "Section")
# The roster's columns (lower case, spaces or underscores) that fill Canvas's columns.
CANVAS_FROM_ROSTER = {
    "Student": ("name", "student name", "full name", "sortable name"),
    "ID": ("id", "canvas id", "canvas user id", "user id"),
    "SIS User ID": ("sis user id", "sis id"),
    "SIS Login ID": ("sis login id", "login id", "login"),
    "Section": ("section", "sections"),
}


def _roster_value(extra: dict[str, str], names: tuple[str, ...]) -> str:
    for key, value in extra.items():
        if key.replace("_", " ").strip().lower() in names and value:
            return value
    return ""


def canvas_csv(graded: Graded, column: str) -> str:
    """A Canvas gradebook import: Student, ID, SIS User ID, SIS Login ID, Section, then the
    assignment's column (points), after a "Points Possible" row.

    Names, ids and sections come from the roster's columns when the grades were made by
    assignment; a student with none of ID, SIS User ID and SIS Login ID gets gyro's student
    id as the SIS User ID, so that Canvas can match the row.
    """
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(list(CANVAS_COLUMNS) + [_cell(column)])  # named after --out: user text
    totals = {total for _, total in graded.scores.values()}
    writer.writerow(["    Points Possible", "", "", "", "",
                     f"{max(totals):g}" if totals else ""])
    students = graded.assignment.students if graded.assignment is not None else {}
    for student, (points, _total) in graded.scores.items():
        extra = students[student].extra if student in students else \
            graded.people.get(student, {})
        cells = {name: _roster_value(extra, keys) for name, keys in CANVAS_FROM_ROSTER.items()}
        cells["Student"] = cells["Student"] or student
        if not (cells["ID"] or cells["SIS User ID"] or cells["SIS Login ID"]):
            cells["SIS User ID"] = student
        writer.writerow([_cell(cells[c]) for c in CANVAS_COLUMNS] + [f"{points:g}"])
    return out.getvalue()


def _student_rows(graded: Graded, student: str) -> list[Any]:
    return [r for r in graded.rows if r.student == student]


def _test_name(row: Any) -> str:
    return f"{row.problem}: {row.answer}"


def student_note(row: Any, reveal: bool = False) -> str:
    """What a student is told about one answer: the grading's words for them (no solver
    value, no other student), and with ``reveal`` (after the due date) the answer."""
    text = row.feedback
    if reveal and row.correct and row.result not in ("correct", "extra", "error"):
        shown = f"the answer: {row.correct}"
        if row.relative_error is not None:
            shown += f" (yours is off by {row.relative_error * 100:+.3g}%)"
        text = f"{text}; {shown}" if text else shown
    return text


def _test_output(row: Any, reveal: bool = False) -> str:
    text = f"submitted: {row.submitted or '(nothing)'}; result: {row.result}"
    note = student_note(row, reveal)
    return text + (f"; {note}" if note else "")


def gradescope_results(graded: Graded, student: str, reveal: bool = False) -> str:
    """Gradescope's autograder results.json for one student: a test per answer (name,
    score, max_score, status, output) and the total score. The texts are the student's
    (:func:`student_note`)."""
    rows = _student_rows(graded, student)
    points, total = graded.scores.get(student, (0.0, 0.0))
    tests = [{"name": _test_name(r), "score": r.points, "max_score": r.max_points,
              "status": "passed" if r.points >= r.max_points > 0 else "failed",
              "output": _test_output(r, reveal), "visibility": "visible"}
             for r in rows if r.max_points > 0]
    return json.dumps({"score": points, "output": f"{student}: {points:g} of {total:g} points "
                       "(graded by gyro)", "visibility": "visible", "tests": tests},
                      indent=2, allow_nan=False) + "\n"


def prairielearn_results(graded: Graded, student: str, reveal: bool = False) -> str:
    """PrairieLearn's external-grader results.json for one student: gradable, score as a
    fraction 0..1, a message, and a test per answer (name, points, max_points, message).
    The texts are the student's (:func:`student_note`)."""
    rows = _student_rows(graded, student)
    points, total = graded.scores.get(student, (0.0, 0.0))
    tests = [{"name": _test_name(r), "description": f"the answer {r.answer} of problem "
              f"{r.problem}", "points": r.points, "max_points": r.max_points,
              "message": (student_note(r, reveal) or RESULT_WORDS.get(r.result, r.result))
              if r.result != "correct" else "correct",
              "output": _test_output(r, reveal)}
             for r in rows if r.max_points > 0]
    return json.dumps({"gradable": True, "score": points / total if total else 0.0,
                       "message": f"{points:g} of {total:g} points", "output": "",
                       "tests": tests}, indent=2, allow_nan=False) + "\n"


def graded_inputs(graded: Graded, read: Iterable[str] = ()) -> list[str]:
    """Every file the grading read: ``read`` (the sheet, the problem files) and, graded by
    assignment, the assignment, its key.json and each variant file; no output may
    replace one of them (core/files.py: refuse_outputs_over_inputs)."""
    import os

    inputs = list(read)
    plan = graded.assignment
    if plan is not None:
        inputs += [plan.path, os.path.join(os.path.dirname(plan.path), "key.json")]
        inputs += [row.file for row in plan.rows]
    return inputs


Target = tuple[str, str]  # (path, text): one file of what a grading writes


def out_files(graded: Graded, out: str, fmt: str, read: Iterable[str] = (),
              reveal: bool = False) -> tuple[list[Target], str | None]:
    """The files ``--out`` writes in ``fmt``, and the folder they go into (None for one
    file): the JSON formats are one file per student, ``out`` itself when it ends in
    .json (the sheet must hold one student), else ``out/<student>.json`` for every
    student graded. None may replace a file the grading read (:func:`graded_inputs` of
    ``read``), with or without ``force``: refused here, before anything is written."""
    import os

    from ..core.errors import InputError
    from ..core.files import refuse_outputs_over_inputs

    folder = None
    if fmt in ("grades", "canvas"):
        column = os.path.splitext(os.path.basename(out))[0] or "gyro"
        targets = [(out, csv_text(graded) if fmt == "grades" else canvas_csv(graded, column))]
    else:
        results = gradescope_results if fmt == "gradescope" else prairielearn_results
        if out.endswith(".json"):  # one student's results, as inside an autograder
            if len(graded.sheet_students) != 1:
                raise InputError(f"a .json file holds one student's results; the sheet has "
                                 f"{len(graded.sheet_students)} students: give a directory",
                                 file=out)
            targets = [(out, results(graded, graded.sheet_students[0], reveal))]
        else:
            from ..checking.assignment import file_names

            names = file_names(list(graded.scores))
            targets = [(os.path.join(out, names[s] + ".json"), results(graded, s, reveal))
                       for s in graded.scores]
            folder = out
    refuse_outputs_over_inputs([t for t, _ in targets], graded_inputs(graded, read),
                               option="--out")
    return targets, folder


def write_out(graded: Graded, out: str, fmt: str, force: bool,
              read: Iterable[str] = (), reveal: bool = False) -> list[str]:
    """Write the grades to ``out`` in ``fmt`` (:func:`out_files`): every file, or none."""
    return write_outputs(graded, force, read, reveal, out=out, fmt=fmt)


def write_outputs(graded: Graded, force: bool, read: Iterable[str] = (),
                  reveal: bool = False, *, out: str | None = None, fmt: str = "grades",
                  feedback: str | None = None) -> list[str]:
    """Write what a grading was asked for, ``--out`` (:func:`out_files`) and ``--feedback``
    (:func:`feedback_files`), as one set: every check (a file that exists without
    ``force``, an input in the way, a file where a folder should be) is made before the
    first file is written, and a failure leaves none of them: a refused ``--feedback``
    leaves no new grades file behind."""
    import os

    from ..core.errors import InputError
    from ..core.files import write_set, write_set_in

    read = list(read)
    targets: list[Target] = []
    folders: list[str] = []
    if out is not None:
        files, folder = out_files(graded, out, fmt, read, reveal)
        targets += files
        if folder is not None:
            folders.append(folder)
    if feedback is not None:
        targets += feedback_files(graded, feedback, read, reveal)
        folders.append(feedback)
    seen: set[str] = set()
    for path, _ in targets:
        same = os.path.normcase(os.path.abspath(path))
        if same in seen:
            raise InputError("--out and --feedback would both write this file; give them "
                             "different places", file=path)
        seen.add(same)
    if out is not None and out not in folders and not os.path.isdir(os.path.dirname(out) or "."):
        raise InputError(f"cannot write: no such directory {os.path.dirname(out)!r}",
                         file=out)  # one file's folder is not made, as for any output
    # write_set_in makes every folder a file goes into, and removes them on a failure
    written = write_set_in(folders[0], targets, force) if folders else write_set(targets, force)
    return [str(path) for path in written]


# ---- feedback: a short page per student -------------------------------------------------

RESULT_WORDS = {"correct": "right", "partial": "partly right", "wrong": "off",
                "carried": "right for your own earlier values (error carried forward)",
                "invalid": "not readable", "missing": "not answered", "extra": "not asked",
                "error": "not graded (gyro failed on the problem)"}


def feedback_text(graded: Graded, student: str, reveal: bool = False) -> str:
    """One student's feedback as Markdown: the score, then each answer: right, or which
    way it was off and the likely slip (:func:`student_note`). Without ``reveal`` no number
    derived from the solver's values is printed, so the page can go out before the due
    date; with it (after the due date) each answer not right shows the solver's value."""
    points, total = graded.scores.get(student, (0.0, 0.0))
    percent = 100 * points / total if total else 0.0
    lines = [f"# Feedback for {_md(student)}", "",
             f"Score: {points:g} of {total:g} points ({percent:.1f}%).", ""]
    rows = [r for r in graded.rows if r.student == student]
    right = [r for r in rows if r.result == "correct"]
    other = [r for r in rows if r.result != "correct"]
    if right:
        lines += ["## Right", ""]
        lines += [f"- {_md(r.problem)}, {_md(r.answer)}: {_md(r.submitted)}" for r in right]
        lines.append("")
    if other:
        lines += ["## To look at again", ""]
        for r in other:
            text = f"- {_md(r.problem)}, {_md(r.answer)}: {RESULT_WORDS.get(r.result, r.result)}"
            if r.submitted:
                text += f" (you gave {_md(r.submitted)})"
            note = student_note(r, reveal)
            if note:
                text += f". {_md(note)}"
            lines.append(text + f"; {r.points:g} of {r.max_points:g} points.")
        lines.append("")
    return "\n".join(lines)


def _md(text: Any) -> str:
    """User text for Markdown: no raw HTML, no markup characters that change the page."""
    import html as _html

    out = _html.escape(" ".join(str(text).split()), quote=False)
    for ch in "\\`*_[]#|<>!":
        out = out.replace(ch, "\\" + ch) if ch not in "<>" else out
    return out


def feedback_files(graded: Graded, folder: str, read: Iterable[str] = (),
                   reveal: bool = False) -> list[Target]:
    """``folder/<student>.md`` for every student graded (:func:`feedback_text`); none may
    replace a file the grading read (:func:`graded_inputs`): refused here, before
    anything is written."""
    import os

    from ..checking.assignment import file_names
    from ..core.errors import InputError
    from ..core.files import refuse_outputs_over_inputs

    if os.path.exists(folder) and not os.path.isdir(folder):
        raise InputError("exists and is not a directory", file=folder)
    names = file_names(list(graded.scores))
    targets = [(os.path.join(folder, names[s] + ".md"), feedback_text(graded, s, reveal))
               for s in graded.scores]
    refuse_outputs_over_inputs([t for t, _ in targets], graded_inputs(graded, read),
                               option="--feedback")
    return targets
