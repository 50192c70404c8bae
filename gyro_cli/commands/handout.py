"""`gyro handout`: the students' question sheets, and with --solutions the worked answers.

    gyro handout FILES|DIR [-o OUT.html|.tex|.pdf] [--solutions] [--course C] [--title T]
    gyro handout FILES --roster ROSTER.csv [--seed S] ...      # one sheet per student
    gyro handout --assignment DIR/assignment.csv ...            # the same, from gyro vary

A sheet has a cover (course, title, the student's name and id) and each
problem's statement (core/statement.py) with the student's numbers; a problem
without a statement gets its title, its given data and what to find. With
``--solutions`` each problem's worked answer follows its statement (the
LaTeX write-up of `gyro solve --format latex`, or the HTML of `--format html`).

With a roster or an assignment there is one file per student,
``<OUT stem>-<student>.<ext>`` beside OUT, and ``<OUT stem>-key.csv`` for the
teacher: each student's answers, as the solver gives them. ``--roster`` with a
``--seed`` draws the same numbers as ``gyro vary --roster`` with that seed.
A PDF needs pdflatex (the .tex is compiled in a temporary folder).
"""

from __future__ import annotations

import csv
import io
import os
import shutil
import subprocess
import tempfile
from dataclasses import dataclass, field
from html import escape
from typing import Any

from ..core.csvsafe import safe_cell
from ..core.errors import InputError

FORMATS = (".html", ".tex", ".pdf")


@dataclass
class Sheet:
    """One handout: for one student (or for everyone), the problems in order."""

    student: str | None
    name: str  # how the cover names the student ("" for everyone)
    problems: list[Any] = field(default_factory=list)  # solving.problem.Problem
    variants: list[str] = field(default_factory=list)  # the assigned problem id of each
    results: list[Any] = field(default_factory=list)  # each problem solved (`solved`)


def solved(sheet: Sheet) -> list[Any]:
    """Each problem of the sheet solved, once: its answer line, its worked answer and the
    teacher's key read the one result."""
    if len(sheet.results) != len(sheet.problems):
        from ..solving.solve import solve

        sheet.results = [solve(problem) for problem in sheet.problems]
    return sheet.results


def _load_all(paths: list[str]) -> list[Any]:
    from ..solving.paths import problem_files
    from ..solving.problem import load

    files, missing = problem_files(paths)
    if missing:
        raise InputError(missing[0][1])
    if not files:
        raise InputError("no problem files given")
    return [load(f) for f in files]


def sheets(paths: list[str], roster: str | None = None, assignment: str | None = None,
           seed: int = 0) -> list[Sheet]:
    """The handouts to write: one for everyone, or one per student."""
    from ..solving.problem import build, parse_yaml

    if roster and assignment:
        raise InputError("give --roster or --assignment, not both")
    if assignment:
        from ..checking.assignment import load_variant, read_assignment

        plan = read_assignment(assignment)
        out: dict[str, Sheet] = {}
        for row in plan.rows:
            sheet = out.setdefault(row.student, Sheet(row.student, _name(
                plan.students[row.student].extra, row.student)))
            sheet.problems.append(load_variant(row, assignment))
            sheet.variants.append(row.problem)
        return list(out.values())
    if roster:
        from ..checking.assignment import read_roster
        from ..solving.paths import problem_files
        from .roster import roster_variants

        files, missing = problem_files(paths)
        if missing:
            raise InputError(missing[0][1])
        students = {s.id: s for s in read_roster(roster)}
        made, table, _ = roster_variants(files, roster, seed)
        texts = dict(made)
        out = {}
        for line in csv.DictReader(io.StringIO(table)):
            from ..core.csvsafe import plain_cell

            sid = plain_cell(line["student"])
            sheet = out.setdefault(sid, Sheet(sid, _name(students[sid].extra, sid)))
            data, lines = parse_yaml(texts[line["file"]], line["file"])
            sheet.problems.append(build(line["file"], data, lines))
            sheet.variants.append(plain_cell(line["problem"]))
        return list(out.values())
    problems = _load_all(paths)
    return [Sheet(None, "", problems, [p.id for p in problems])]


def given_away(sheet: Sheet) -> list[tuple[str, str, str]]:
    """Where one problem of the sheet gives, as its data, what another asks: a given
    shown in its statement equal (to 0.05 %, not zero, not a round number) to an answer
    the other asks, of the same dimension (a top of 11/3's precessing at 11/3's 45.13
    rpm). Each as (what gives it away, what it gives away, the values)."""
    from ..checking.grades import reported
    from ..core.expr import num
    from ..solving.problem import graded_questions, params_by_name

    asked = []  # (problem, answer, dimension, SI value, as printed)
    for problem, result, pid in zip(sheet.problems, solved(sheet), sheet.variants):
        for name in graded_questions(problem):
            spec = problem.kind.answer(name)
            if spec is not None and spec.dimension is not None:
                answer = reported(result, name)
                unit = answer.unit or answer.si_unit
                asked += [(pid, name, spec.dimension, float(si), f"{num(v)} {unit}")
                          for si, v in zip(answer.si_values, answer.values)]
    found = []
    for problem, pid in zip(sheet.problems, sheet.variants):
        template = problem.data.get("statement")
        params, written = params_by_name(problem.kind), problem.data.get("given", {})
        for key, value in problem.given.values.items():
            param = params.get(key)
            if param is None or not isinstance(value, float) or value == 0 or (
                    isinstance(template, str) and "{" + key + "}" not in template) \
                    or _digits(written.get(key)) < 3:
                continue  # not a quantity, not shown to the student, or a round number
                # (30 deg, 3 rad/s: met by chance; 45.13 rpm is a result carried over)
            found += [(f"problem {pid}'s {key}", f"the answer {name} of problem {other}",
                       f"{' '.join(str(written.get(key)).split())} and {shown}")
                      for other, name, dimension, si, shown in asked
                      if other != pid and dimension == param.dimension
                      and abs(si - value) <= 5e-4 * abs(si)]
    return found


def answers_given_away(todo: list[Sheet]) -> list[str]:
    """`given_away` of every sheet, a sentence for each pair of problems: the values of
    the one sheet, or of the first of the students' sheets where it is found."""
    found: dict[tuple[str, str], list[tuple[str | None, str]]] = {}
    for sheet in todo:
        for giver, given, values in given_away(sheet):
            found.setdefault((giver, given), []).append((sheet.student, values))
    return [f"{giver} is {given} ({values}"
            + (f", {student}'s; so on {len(where)} of {len(todo)} sheets)"
               if student is not None else ")")
            for (giver, given), where in found.items() for student, values in where[:1]]


def _digits(written: Any) -> int:
    """The significant digits of the number a given is written with (``45.13 rpm``: 4,
    ``30 deg``: 1, ``0.10 m``: 1); 0 where none is found."""
    import re

    found = re.search(r"\d[\d.]*", str(written))
    return len(found.group().replace(".", "").strip("0")) if found else 0


def _name(extra: dict[str, str], student: str) -> str:
    for key in ("name", "student name", "full name"):
        for k, v in extra.items():
            if k.replace("_", " ").lower() == key and v:
                return f"{v} ({student})"
    return student


def statement_of(problem: Any) -> str:
    """The problem as the student reads it: its statement filled in, or else its title,
    data and what to find."""
    text = problem.statement_text()
    if text:
        return text
    given = "; ".join(f"{k} = {' '.join(str(v).split())}"
                      for k, v in problem.data.get("given", {}).items())
    asked = ", ".join(problem.find)
    return f"{problem.title + '. ' if problem.title else ''}Given: {given}. Find: {asked}."


_COUNT = {2: "two", 3: "three", 4: "four"}


def answer_form(problem: Any, result: Any, pid: str) -> str:
    """How to write the answers on a sheet (docs/check.md): the problem id, then each
    question graded (`graded_questions`) with its unit, how many values it takes and
    their order. ``Answer as problem 11/3-ann: precession in rpm, two values (slow; fast,
    in any order); min_spin in rpm.``"""
    from ..checking.grades import reported
    from ..checking.matching import ordered
    from ..solving.problem import graded_questions

    parts = []
    for name in graded_questions(problem):
        answer = reported(result, name)
        if answer.unit is None and answer.si_unit is None:
            words = [str(v) for v in answer.values]
            spec = problem.kind.answer(name)
            choices = f" ({' or '.join(spec.words)})" if spec is not None and spec.words else ""
            labels = [str(x) for x in answer.labels if x]
            several = f"{_COUNT.get(len(words), str(len(words)))} words separated by ';'" + \
                (f" ({'; '.join(labels)})" if len(labels) == len(words) else "")
            parts.append(f"{name}: {'a word' if len(words) < 2 else several}{choices}")
            continue
        unit = answer.unit or "SI units"
        text = f"{name} in {unit}"
        n = len(answer.values)
        if n > 1:
            labels = [str(x) for x in answer.labels if x]
            order = ("in that order" if ordered(list(answer.labels)) else "in any order") \
                if len(labels) == n else ("in any order" if not labels else "")
            listed = f"{'; '.join(labels)}, {order}" if len(labels) == n else order
            text += f", {_COUNT.get(n, str(n))} values separated by ';' ({listed})"
        parts.append(text)
    return f"Answer as problem {pid}: " + "; ".join(parts) + "."


# ---- LaTeX ------------------------------------------------------------------------------

def latex_sheet(sheet: Sheet, course: str, title: str, solutions: bool) -> str:
    from ..render.mathprint import text_escape
    from ..render.writeup import PREAMBLE, latex

    heading = f"{course} -- {title}" if course else title
    body = [PREAMBLE, f"\\title{{{text_escape(heading)}}}",
            f"\\author{{{text_escape(sheet.name)}}}" if sheet.name else "\\author{}",
            "\\date{}", "\\begin{document}", "\\maketitle", ""]
    for k, (problem, result, pid) in enumerate(zip(sheet.problems, solved(sheet),
                                                   sheet.variants), 1):
        body.append(f"\\section*{{Problem {k} ({text_escape(str(pid))})}}")
        body.append(text_escape(statement_of(problem)))
        body.append("")
        body.append(f"\\emph{{{text_escape(answer_form(problem, result, str(pid)))}}}")
        body.append("")
        if solutions:
            body.append(latex(result, level="subsection*"))
    body.append("\\end{document}")
    return "\n".join(body) + "\n"


def compile_pdf(tex: str) -> bytes:
    """The PDF of a LaTeX document (pdflatex twice, in a temporary folder)."""
    exe = shutil.which("pdflatex")
    if exe is None:
        raise InputError("a PDF needs pdflatex, which is not installed (Debian: apt-get "
                         "install texlive-latex-base texlive-latex-recommended); write .tex or "
                         ".html instead")
    with tempfile.TemporaryDirectory(prefix="gyro-handout-") as folder:
        source = os.path.join(folder, "handout.tex")
        with open(source, "w", encoding="utf-8") as handle:
            handle.write(tex)
        for _ in range(2):
            done = subprocess.run([exe, "-interaction=nonstopmode", "-halt-on-error",
                                   "-no-shell-escape", "handout.tex"], cwd=folder,
                                  stdout=subprocess.PIPE, stderr=subprocess.STDOUT, timeout=120)
            if done.returncode != 0:
                tail = done.stdout.decode("utf-8", "replace").strip().splitlines()[-1:]
                raise InputError(f"pdflatex failed: {' '.join(tail)[:200]}")
        with open(os.path.join(folder, "handout.pdf"), "rb") as handle:
            return handle.read()


# ---- HTML -------------------------------------------------------------------------------

def html_sheet(sheet: Sheet, course: str, title: str, solutions: bool) -> str:
    from ..render import html

    heading = f"{course}: {title}" if course else title
    body = [f"<h1>{escape(heading)}</h1>"]
    if sheet.name:
        body.append(f"<p>For {escape(sheet.name)}</p>")
    for k, (problem, result, pid) in enumerate(zip(sheet.problems, solved(sheet),
                                                   sheet.variants), 1):
        form = answer_form(problem, result, str(pid))
        body.append(f"<section aria-labelledby=\"p{k}\"><h2 id=\"p{k}\">Problem {k} "
                    f"({escape(str(pid))})</h2>\n<p>{escape(statement_of(problem))}</p>\n"
                    f"<p class=\"answer-form\"><em>{escape(form)}</em></p>")
        if solutions:
            body.append(html.worked_answer(result, level=3, ident=f"solution-{k}"))
        body.append("</section>")
    return html.document(heading + (f" ({sheet.name})" if sheet.name else ""), "\n".join(body))


# ---- the files --------------------------------------------------------------------------

def key_csv(sheets_: list[Sheet]) -> str:
    """The teacher's key: student, problem, variant, question, the solver's value; the
    questions are what grading grades (the steps asked, `steps:`, then what the
    statement asks, `ask:`), not every answer the kind computes."""
    from ..checking.grades import _correct_text, reported
    from ..solving.problem import graded_questions

    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(["student", "problem", "variant", "answer", "correct"])
    for sheet in sheets_:
        for problem, result, pid in zip(sheet.problems, solved(sheet), sheet.variants):
            for name in graded_questions(problem):
                writer.writerow([safe_cell(c) for c in (sheet.student or "", pid, problem.id,
                                                       name,
                                                       _correct_text(reported(result, name)))])
    return out.getvalue()


def _inputs(paths: list[str], roster: str | None, assignment: str | None,
            todo: list[Sheet]) -> list[str]:
    """The files the handout read: the problem files (or, by assignment, each variant
    file), the roster, the assignment."""
    from ..solving.paths import problem_files

    read = [p for p in (roster, assignment) if p]
    if assignment:  # and gyro vary's key.json beside it, which a --key could name
        read.append(os.path.join(os.path.dirname(assignment), "key.json"))
        return read + [problem.file for sheet in todo for problem in sheet.problems]
    return read + problem_files(paths)[0]


def _same_file(a: str, b: str) -> bool:
    """One file by two names, as far as can be known before either exists: the folders
    resolved (a symbolic link), the names compared without case (a file system that folds
    case would make them one file)."""
    def resolved(path: str) -> tuple[str, str]:
        folder, name = os.path.split(os.path.abspath(path))
        return os.path.realpath(folder), name.casefold()

    return resolved(a) == resolved(b)


def write_handouts(paths: list[str], out: str, roster: str | None, assignment: str | None,
                   seed: int, solutions: bool, course: str, title: str,
                   force: bool, key: str | None = None,
                   warnings: list[str] | None = None) -> list[str]:
    """Write the handout(s) and, per student, the key CSV (``key``, by default
    ``<OUT stem>-key.csv`` beside the sheets; the last path returned); nothing over an
    existing file without ``force`` (checked before anything is written). ``warnings``
    receives, for sheets without solutions, where one problem's data is another's answer."""
    from ..checking.assignment import file_names
    from ..core.files import StagedSet, refuse_outputs_over_inputs

    stem, ext = os.path.splitext(out)
    if ext.lower() not in FORMATS:
        raise InputError(f"the handout is .html, .tex or .pdf, got {ext or 'no extension'!r}",
                         file=out)
    todo = sheets(paths, roster, assignment, seed)
    per_student = todo[0].student is not None
    names = file_names([s.student for s in todo if s.student is not None]) \
        if per_student else {}
    targets: list[tuple[str, Any]] = []
    for sheet in todo:
        target = f"{stem}-{names[sheet.student]}{ext}" if sheet.student is not None else out
        targets.append((target, sheet))
    if key is not None and not per_student:
        raise InputError("--key is the teacher's key of a class's sheets: it goes with "
                         "--roster or --assignment", file=key)
    if per_student:
        key = key or f"{stem}-key.csv"
        if _same_file(key, out):
            raise InputError("--key names OUT, the sheets' own name: give the key a name of "
                             "its own", file=key)
        if any(_same_file(key, t) for t, _ in targets):
            raise InputError("--key names a student's sheet: give the key a name of its own",
                             file=key)
        targets.append((key, None))
    refuse_outputs_over_inputs([target for target, _ in targets],
                               _inputs(paths, roster, assignment, todo), option="the handout")
    for path in (out, key) if key else (out,):
        folder = os.path.dirname(path) or "."
        if not os.path.isdir(folder):
            raise InputError(f"cannot write: no such directory {folder!r}", file=path)
    # every sheet and the key, or none: a PDF that fails for one student leaves no
    # class half written (each file is staged as it is made and placed at the end)
    with StagedSet(force, None, [target for target, _ in targets]) as staged:
        for target, sheet in targets:
            if sheet is None:
                data: str | bytes = key_csv(todo)
            elif ext.lower() == ".html":
                data = html_sheet(sheet, course, title, solutions)
            else:
                data = latex_sheet(sheet, course, title, solutions)
                if ext.lower() == ".pdf":
                    data = compile_pdf(data)
            staged.add(target, data)
        staged.place()
    if warnings is not None and not solutions:
        warnings += answers_given_away(todo)
    return [target for target, _ in targets]
