"""Grading students' answers: `gyro check --answers SHEET PROBLEMS... [--out grades.csv]`.

SHEET is a CSV with the columns student, problem, answer, value (a header row
naming them is optional; several roots either as several rows or separated by
``;`` in one value), or a YAML mapping ``student -> problem id -> answer ->
value or list``. Each submitted value is graded against the solver's answer
with the problem's tolerance; roots are matched as sets as in `gyro check`.

One item = one (student, problem, answer): worth 1 point, shared among the
roots (a student who gives one of two roots gets 1/2). An item another
student answered but this one did not is `missing` (0 points). A value that
does not parse or has the wrong dimension is `invalid` (0 points, with the
reason): that is the student's slip, not a bad sheet, and the other rows are
graded. A sheet naming a problem or an answer that is not among the problem
files is bad input (exit 2).

Word answers (a released top's `motion`) are graded as words: case and
surrounding spaces do not matter, and the synonyms in ``WORD_SYNONYMS`` count
(``cusp``, ``looping``, ``wavy``, ``steady precession``...).

The sheet is read like a problem file: only a regular file, at most
``MAX_SHEET_BYTES``, and a YAML sheet with the same nesting and alias limits.
"""

from __future__ import annotations

import csv
import dataclasses
import math
import re
from dataclasses import dataclass, field
from typing import Any, TypedDict

from ..core.errors import InputError
from ..core.units import MANTISSA, NUMBER, SUPERSCRIPT, SUPERSCRIPTS
from ..core.work import num
from . import check
from .copies import Match, VariantIndex, whose
from .ecf import check_steps
from .expected import answer_signs, parse_value
from .matching import diagnose, graded_lines, ordered
from .tolerance import tolerance_for

COLUMNS = ("student", "problem", "answer", "value")
HEADER_WORDS = {"student": "student", "name": "student", "problem": "problem",
                "problem id": "problem", "problem_id": "problem", "id": "problem",
                "answer": "answer", "answer name": "answer", "answer_name": "answer",
                "value": "value", "value with unit": "value"}
OUT_COLUMNS = ("student", "problem", "answer", "submitted", "correct", "relative_error",
               "result", "points", "max_points", "note")
MAX_SHEET_BYTES = 20_000_000

# A word answer and the other ways students write it (compared in lower case).
WORD_SYNONYMS = {
    "cusps": ("cusp", "cusped", "cuspidal", "cusps"),
    "loops": ("loop", "looped", "looping", "loops"),
    "waves": ("wave", "wavy", "waving", "undulating", "waves"),
    "steady": ("steady", "steady precession", "uniform precession", "no nutation"),
    "sleeping": ("sleeping", "asleep", "sleeping top", "sleeps"),
}


class _Where(TypedDict):
    """Where in the answer sheet an InputError points."""

    file: str
    line: int | None


@dataclass
class Submission:
    student: str
    problem: str
    answer: str
    values: list[Any]
    line: int | None = None
    # (line, values) of each sheet row merged into this one (a CSV root a row)
    rows: list[tuple[int | None, list[Any]]] = field(default_factory=list)


@dataclass
class GradeRow:
    student: str
    problem: str
    answer: str
    submitted: str
    correct: str
    relative_error: float | None
    result: str  # correct | partial | wrong | invalid | missing | error (internal)
    points: float
    max_points: float = 1.0
    note: str = ""  # for the teacher: may name the solver's value and other students
    variant: str = ""  # graded by assignment: the variant this student was given
    # for the student: what was off, with no number derived from the solver's value
    # and no other student named (feedback pages, Gradescope, PrairieLearn)
    feedback: str = ""
    # the same without hints (--no-hints): each value right or not, with no direction, slip
    # or place, which a student resubmitting could follow to the answer; None: as feedback
    plain: str | None = None


@dataclass
class Graded:
    rows: list[GradeRow]
    scores: dict[str, tuple[float, float]] = field(default_factory=dict)
    errors: list[str] = field(default_factory=list)  # internal errors, one line each
    assignment: Any = None  # checking.assignment.Assignment when graded by assignment
    sheet_students: list[str] = field(default_factory=list)  # who the sheet holds answers of
    notes: list[str] = field(default_factory=list)  # for the teacher, one line each (stderr)
    submitter: str | None = None  # --student: only their rows, no solver value shown
    # each student's identity columns from a platform's download (--responses): name,
    # id, sis_id, section, read as a roster's extra columns are
    people: dict[str, dict[str, str]] = field(default_factory=dict)


# ---- reading the sheet ------------------------------------------------------

def read_sheet(path: str, decimal_comma: bool = False) -> list[Submission]:
    """The submissions in a CSV or YAML answer sheet, in sheet order (``decimal_comma``:
    the class writes ``965,4`` for 965.4)."""
    if path.endswith((".yaml", ".yml")):
        return _read_yaml(path, decimal_comma)
    return _read_csv(path, decimal_comma)


def _read_csv(path: str, decimal_comma: bool = False) -> list[Submission]:
    from ..core.csvsafe import CellRunsOn, one_line_rows
    from ..core.safeyaml import read_text
    from .assignment import student_id

    text = read_text(path, MAX_SHEET_BYTES, "an answer sheet (CSV or YAML)", "utf-8-sig")
    try:
        lines = one_line_rows(text)
        if lines and len(lines[0][1]) == 1 and lines[0][1][0].count(";") >= len(COLUMNS) - 1:
            # a spreadsheet in a language with a decimal comma saves its CSV with ';'
            lines = one_line_rows(text, ";")
    except csv.Error as err:
        raise InputError(f"not a CSV file: {err}", file=path) from None
    except CellRunsOn as err:
        raise InputError(str(err), file=path, line=err.line) from None
    head = lines[0][1] if lines else []  # a header row, if it is one
    order = list(COLUMNS)
    start = 0
    if head and all(c.strip().lower() in HEADER_WORDS for c in head if c.strip()):
        order = [HEADER_WORDS[c.strip().lower()] for c in head if c.strip()]
        for k, name in enumerate(order):
            if name in order[:k]:
                first = order.index(name)
                raise InputError(f"the header has two {name} columns ({head[first].strip()!r} "
                                 f"in column {first + 1} and {head[k].strip()!r} in column "
                                 f"{k + 1}); keep one", file=path, line=1)
        if sorted(set(order)) != sorted(COLUMNS):
            raise InputError(f"the header must name the columns {', '.join(COLUMNS)}; got "
                             f"{', '.join(head)}", file=path, line=1)
        start = 1
    merged: dict[tuple[str, str, str], Submission] = {}
    seen: dict[tuple[str, ...], int] = {}
    for number, row in lines[start:]:
        if not any(c.strip() for c in row):
            continue
        same = tuple(" ".join(c.split()) for c in row)
        if same in seen:  # a copy-paste slip: counted twice it would halve the point
            raise InputError(f"this row repeats line {seen[same]} word for word; remove one "
                             "(several roots go in one row separated by ';' or in rows with "
                             "different values)", file=path, line=number)
        seen[same] = number
        if len(row) < len(order) or any(c.strip() for c in row[len(order):]):
            raise InputError(f"expected {len(order)} columns ({', '.join(order)}), got "
                             f"{len(row)}", file=path, line=number)
        cells = {name: row[k].strip() for k, name in enumerate(order)}
        if not (cells["student"] and cells["problem"] and cells["answer"]):
            raise InputError("student, problem and answer must not be empty", file=path,
                             line=number)
        values = written_values(cells["value"].split(";"), decimal_comma)
        key = (student_id(cells["student"]), cells["problem"], cells["answer"])
        if key in merged:
            merged[key].values += values
        else:
            merged[key] = Submission(*key, list(values), number)
        merged[key].rows.append((number, values))
    return list(merged.values())


# A number alone, as units._NUMBER reads one (the rest of a value is its unit).
_BARE = re.compile(rf"\s*{NUMBER}\s*")
_NUMBER_AND_UNIT = re.compile(rf"\s*{NUMBER}\s*([^\d\s.+\-\u2212].*|1\s*/.*)")
# "about": the signs students put before a rounded value (≈ 965.4 rpm, ~965.4 rpm)
_ABOUT = re.compile(r"\s*[\u2248\u2243~]\s*")
# a dash before a number as word processors write it (en dash, hyphen, figure dash); a
# hyphen and a space stay as written (a list's bullet, "- 45.13 rpm", is no minus)
_DASH = re.compile(r"[\u2010\u2011\u2012\u2013\u2014]\s*(?=[\d.])")
# 9.654×10^2, 9.654 x 10^2, 9.654*10**2, 9.654·10²
_TIMES_TEN = re.compile(rf"({MANTISSA})\s*[x\u00d7X*\u00b7\u22c5]\s*10"
                        r"(?:\s*(?:\^|\*\*)\s*\(?\s*([-+\u2212]?\d{1,3})\s*\)?|([" + SUPERSCRIPT
                        + r"]+))(?![\d" + SUPERSCRIPT + r"])(.*)", re.S)
# a number with a decimal comma, at the start of a value (after a sign or an about sign)
_COMMA_NUMBER = re.compile(r"(?<![\d.,])(\d{1,3}(?:\.\d{3})+|\d+),(\d+)(?![\d,])")
# under a decimal comma, dots that group thousands (965.400, 1.234.567) in a number alone
_DOT_THOUSANDS = re.compile(r"(?<![\d.,])(\d{1,3}(?:\.\d{3})+)(?![\d.,])")
# a value longer than this is not read further (units refuse a quantity of over 100)
MAX_VALUE = 200
# what follows a unit written once and is not unit: a label, a place, a direction
_NOT_UNIT = re.compile(r"\s*(?:\(|\b(?:at|on|up|upwards?|down|downwards?|inner|outer)\b).*",
                       re.S | re.I)
# roots written with a comma and a space, or "and", between them (45.13 rpm, 533.5 rpm);
# a comma inside a number (1,005) is no separator
_LIST = re.compile(r",\s+(?=[-+\u2212\u2013]?[\d.])|\s+and\s+(?=[-+\u2212\u2013]?[\d.])")


def _normal_value(value: str, decimal_comma: bool = False) -> str:
    """One value as a reader of the sheet reads it: a cell gyro's CSV writer guarded
    (``'-2.781 N m``) as the text it guarded, a leading ≈ or ~ dropped, a word
    processor's dash before the number as a minus, ``9.654×10^2`` as ``9.654e2``, and a
    full stop after the unit (``965.4 rpm.``) dropped."""
    from ..core.csvsafe import plain_cell

    value = plain_cell(value).strip()
    if len(value) > MAX_VALUE:  # refused as it stands (units.MAX_TEXT): nothing to read
        return value
    if decimal_comma:  # 965,4 is 965.4; 1.234,5 is 1234.5 and 965.400 is 965400 (dots
        # group thousands in such a class)
        value = _COMMA_NUMBER.sub(lambda m: m.group(1).replace(".", "") + "." + m.group(2),
                                  value, count=1)
        value = _DOT_THOUSANDS.sub(lambda m: m.group(1).replace(".", ""), value, count=1)
    if _ABOUT.match(value):
        value = _ABOUT.sub("", value, count=1)
    if _DASH.match(value):
        value = "-" + _DASH.sub("", value, count=1)
    power = _TIMES_TEN.fullmatch(value)
    if power:
        number, caret, raised, rest = power.groups()
        exponent = caret or raised.translate(SUPERSCRIPTS)
        value = f"{number}e{exponent.replace(chr(0x2212), '-')} {rest.strip()}".strip()
    if value.endswith(".") and value[-2:-1].isalpha():
        unit = _NUMBER_AND_UNIT.fullmatch(value)
        if unit and "." not in unit.group(1)[:-1]:  # not r.p.m.
            value = value[:-1]
    return value


def written_values(values: Any, decimal_comma: bool = False) -> list[Any]:
    """A student's values of one answer as written (a cell split at ';', a YAML list), read
    as a reader of the sheet reads them (`_normal_value`); several roots may also be joined
    by a comma and a space or by "and" (``45.13 rpm, 533.5 rpm``), and a unit written
    once, after the last of several numbers, is the unit of the bare numbers before it
    (``45.13; 533.5 rpm`` is 45.13 rpm and 533.5 rpm; a YAML list's numbers too). Empty
    values are dropped; a bare number with no unit after it is kept as it is."""
    out: list[Any] = []
    for v in values:
        if isinstance(v, str):
            parts = _LIST.split(v) if len(v) <= MAX_VALUE else [v]
            out += [_normal_value(part, decimal_comma) for part in parts]
        else:
            out.append(v)
    out = [v for v in out if not (isinstance(v, str) and not v)]
    unit = None
    for k in range(len(out) - 1, -1, -1):
        value = out[k]
        if isinstance(value, (int, float)) and not isinstance(value, bool) and \
                not decimal_comma:  # YAML's number: a bare number as written (under a
            value = repr(value)     # decimal comma YAML has split 45,13 at its comma)
        elif not isinstance(value, str) or len(value) > MAX_VALUE:
            unit = None
            continue
        if _BARE.fullmatch(value):
            if unit is not None:
                out[k] = f"{value} {unit}"
            continue
        match = _NUMBER_AND_UNIT.fullmatch(value)
        # the unit alone: not the label or place words after it (62.95 N (B), 62.95 N at B)
        unit = _NOT_UNIT.sub("", match.group(1)).strip() or None if match else None
    return out


def _read_yaml(path: str, decimal_comma: bool = False) -> list[Submission]:
    from ..solving.problem import read_yaml
    from .assignment import student_id

    data, _ = read_yaml(path, MAX_SHEET_BYTES)
    root = _refuse_repeated_keys(path)
    if not isinstance(data, dict):
        raise InputError("expected a mapping: student -> problem id -> answer -> value",
                         file=path)
    out = []
    for student, problems, node, line in _as_written(data, root, path, "student id"):
        student = student_id(student)
        where = _Where(file=path, line=line)
        if not isinstance(problems, dict):
            raise InputError(f"student {student!r}: expected a mapping of problem ids", **where)
        for problem, answers, inner, _ in _as_written(problems, node, path, "problem id"):
            if not isinstance(answers, dict):
                raise InputError(f"student {student!r}, problem {problem!r}: expected a mapping "
                                 "of answer names to values", **where)
            for answer, value, _, _ in _as_written(answers, inner, path, "answer name"):
                values = value if isinstance(value, list) else [value]
                out.append(Submission(student, problem, answer,
                                      written_values((v for v in values if v is not None),
                                                     decimal_comma),
                                      line))
    return out


_NULL_TAG = "tag:yaml.org,2002:null"


def _as_written(data: dict, node: Any, path: str, what: str
                ) -> list[tuple[str, Any, Any, int | None]]:
    """(key as written, value, value's node, key's line) of one mapping of a YAML sheet.

    The loader keeps an unquoted ``true``, ``1.0`` or date key as its text; a key YAML
    reads as null (``null``, ``~``) is a name too, the text written. An empty key, or two
    that YAML would read as the same null, is refused naming the line.
    """
    import yaml

    written: dict[Any, tuple[str, Any, int]] = {}
    pairs = node.value if isinstance(node, yaml.MappingNode) else []
    for key, value in pairs:
        if not isinstance(key, yaml.ScalarNode) or key.tag == "tag:yaml.org,2002:merge":
            continue
        name = None if key.tag == _NULL_TAG else key.value
        line = key.start_mark.line + 1
        if name is None and None in written:
            raise InputError(f"the keys {written[None][0]!r} (line {written[None][2]}) and "
                             f"{key.value!r} are both null to YAML, so one key; quote the "
                             f"{what} ('null')", file=path, line=line)
        written[name] = (key.value if name is None else name, value, line)
    out = []
    for name, value in data.items():
        text, inner, line = written.get(name, (name, None, None))
        if not isinstance(text, str) or not text.strip():
            raise InputError(f"an empty {what} (or one that is not text: {text!r})",
                             file=path, line=line)
        out.append((text, value, inner, line))
    return out


def _refuse_repeated_keys(path: str) -> Any:
    """A key written twice at any depth of a YAML sheet is bad input (YAML keeps the last
    one silently, so one of the student's answers would be dropped without a word).
    Returns the document's root node."""
    import yaml

    from ..core import safeyaml

    text = safeyaml.read_text(path, MAX_SHEET_BYTES, "an answer sheet (CSV or YAML)")
    try:
        _, node = safeyaml.load(text)
    except Exception:  # read_yaml has already reported what is wrong with it
        return None
    stack = [(node, "")]
    while stack:
        item, where = stack.pop()
        if isinstance(item, yaml.MappingNode):
            lines: dict[str, int] = {}
            for key, value in item.value:
                name = str(key.value)
                line = key.start_mark.line + 1
                if name in lines:
                    raise InputError(f"{where + name!r} is written twice (lines {lines[name]} "
                                     f"and {line}); YAML would keep only the last: keep one",
                                     file=path, line=line)
                lines[name] = line
                stack.append((value, f"{where}{name} > "))
        elif isinstance(item, yaml.SequenceNode):
            stack.extend((v, where) for v in item.value)
    return node


# ---- grading ----------------------------------------------------------------

def load_problems(paths: list[str] | tuple[str, ...]) -> dict[str, Any]:
    """The problems to grade against, by id; any bad file is bad input."""
    from ..solving.problem import load

    files, errors = check.collect(paths)
    if errors:
        raise InputError(errors[0].error or "bad path")
    by_id: dict[str, Any] = {}
    for path in files:
        try:
            problem = load(path)
        except InputError:
            raise
        except Exception as err:  # a bug: reported (exit 3) naming the file
            err.gyro_file = path  # type: ignore[attr-defined]
            raise
        if problem.id in by_id:
            raise InputError(f"problem id {problem.id!r} is also in {by_id[problem.id].file}",
                             file=path, key="id")
        by_id[problem.id] = problem
    return by_id


def grade(sheet: str, paths: list[str] | tuple[str, ...],
          assignment: str | None = None, credit: dict[str, float] | None = None,
          student: str | None = None, reveal: bool = False,
          decimal_comma: bool = False) -> Graded:
    """Grade every submission in ``sheet`` against the problems under ``paths``.

    With ``assignment`` (an assignment.csv from ``gyro vary --roster``) each student
    is graded only on their own variants (:func:`grade_assigned`). With ``student``
    (the submitter, inside an autograder) the sheet must name no one else, and the
    grades are theirs only, without the solver's values (:func:`conceal`).
    ``decimal_comma``: the class writes ``965,4`` for 965.4 (else a comma in a number
    is refused as ambiguous).
    """
    if student is not None:
        from .assignment import student_id

        student = student_id(student)  # the sheet's and the roster's ids are NFC
    if assignment is not None:
        graded = grade_assigned(sheet, paths, assignment, credit, submitter=student,
                                decimal_comma=decimal_comma)
    else:
        graded = _grade_sheet(sheet, paths, credit, submitter=student,
                              decimal_comma=decimal_comma)
    return conceal(graded, student, reveal) if student is not None else graded


def _solved_for(problem: Any, names: Any, key: str, solved: dict[str, Any],
                graded: Graded, locate: bool = False) -> None:
    """``solved[key]``: the problem solved asking also for the answers ``names`` (a step
    asked, `steps:`, is no answer: it is checked to be a step of the working). Bad input
    stops the grading (``locate``: named with the problem's file); a bug makes this
    problem's rows errors and the rest is graded."""
    from ..solving.solve import solve_asking

    try:
        solved[key] = solve_asking(problem, [n for n in names
                                             if problem.kind.answer(n) is not None])
        check_steps(problem, solved[key])
    except InputError as err:
        if locate:
            raise err.located(file=problem.file) from None
        raise
    except Exception as err:
        from ..core.errors import internal_message

        graded.errors.append(internal_message(problem.file, err))


def _grade_sheet(sheet: str, paths: list[str] | tuple[str, ...],
                 credit: dict[str, float] | None, submitter: str | None,
                 decimal_comma: bool = False) -> Graded:
    """Every submission of ``sheet`` against the problem of its id under ``paths``."""

    submissions = read_sheet(sheet, decimal_comma)
    if submitter is not None:
        _submitter_only(submissions, submitter, sheet)
    problems = load_problems(paths)
    asked: dict[str, dict[str, None]] = {}
    for s in submissions:
        problem = problems.get(s.problem)
        if problem is None:
            raise InputError(f"problem {s.problem!r} (student {s.student!r}) is not among the "
                             f"problem files given (ids: {', '.join(sorted(problems)) or 'none'})",
                             file=sheet, line=s.line)
        s.answer = _answer_named(problem, s.answer)
        if problem.kind.answer(s.answer) is None and s.answer not in problem.steps:
            answers = ", ".join(a.name for a in problem.kind.answers)
            steps = f"; steps: {', '.join(problem.steps)}" if problem.steps else ""
            raise InputError(f"problem {s.problem!r} has no answer {s.answer!r} (answers: "
                             f"{answers}{steps})", file=sheet, line=s.line)
        questions = asked.setdefault(s.problem, dict.fromkeys(problem.steps))
        questions[s.answer] = None
    submissions = _merged(submissions)  # `min spin` and `min_spin` in two rows: one answer
    graded = Graded([])
    solved: dict[str, Any] = {}
    for pid, names in asked.items():
        _solved_for(problems[pid], names, pid, solved, graded)
    for s in submissions:  # rows that repeat (an ordered answer's values in their order)
        _refuse_repeated_rows(s, problems[s.problem], sheet,
                              _in_order(solved.get(s.problem), s.answer))
    items = [(pid, name) for pid, names in asked.items() for name in names]
    students = list(dict.fromkeys(s.student for s in submissions))
    graded.sheet_students = students
    by_key = {(s.student, s.problem, s.answer): s for s in submissions}
    for student in students:
        total = 0.0
        carrying = Carrying(credit)
        for pid, name in items:
            submission = by_key.get((student, pid, name))
            values = submission.values if submission else None
            if pid not in solved:
                row = GradeRow(student, pid, name, _submitted(values), "", None, "error", 0.0,
                               note="internal error solving the problem (please report)",
                               feedback=ERROR_FEEDBACK)
            else:
                try:
                    row = grade_item(student, problems[pid], name, reported(solved[pid], name),
                                     values, credit)
                    carrying.add(pid, problems[pid], solved[pid], name, row, values)
                except Exception as err:  # a bug: this row is an error, the rest is graded
                    from ..core.errors import internal_message

                    line = internal_message(problems[pid].file, err)
                    if line not in graded.errors:
                        graded.errors.append(line)
                    row = GradeRow(student, pid, name, _submitted(values), "", None, "error",
                                   0.0, note=line, feedback=ERROR_FEEDBACK)
            graded.rows.append(row)
        carrying.carry(graded.errors)
        total = sum(row.points for row in graded.rows if row.student == student)
        graded.scores[student] = (total, float(len(items)))
    return graded


def grade_work(problem: Any, result: Any, values: dict[str, list[Any]],
               credit: dict[str, float] | None = None, student: str = "student"
               ) -> dict[str, GradeRow]:
    """One student's values for one solved problem (answers and steps by name, in the order
    given) graded as a sheet grades them, errors carried forward under ``credit``."""
    carrying = Carrying(credit)
    rows = {}
    for name, given in values.items():
        rows[name] = grade_item(student, problem, name, reported(result, name), given, credit)
        carrying.add(problem.id, problem, result, name, rows[name], given)
    errors: list[str] = []
    carrying.carry(errors)
    if errors:
        raise RuntimeError(errors[0])
    return rows


def _merged(submissions: list[Submission]) -> list[Submission]:
    """Submissions of one student's answer (its name written two ways) as one, in sheet
    order: their values are its roots, as two rows of one name are."""
    out: dict[tuple[str, str, str], Submission] = {}
    for s in submissions:
        first = out.setdefault((s.student, s.problem, s.answer), s)
        if first is not s:
            first.values = first.values + s.values
            first.rows = first.rows + s.rows
    return list(out.values())


def _answer_named(problem: Any, name: str) -> str:
    """An answer's name as a student may write it (``Min_Spin``, ``min spin``,
    ``min-spin``): the kind's answer it names, else ``name`` as written. A step's symbol
    (``I``, ``J``) is matched as written: its case is the symbol's."""
    if problem.kind.answer(name) is not None or name in getattr(problem, "steps", []):
        return name
    plain = re.sub(r"[\s\-]+", "_", name.strip().lower())
    return plain if problem.kind.answer(plain) is not None else name


def reported(result: Any, name: str) -> Any:
    """An answer's values as solved, or a step's (a question of `steps:`)."""
    answer = result.answers.get(name)
    if answer is not None:
        return answer
    from .ecf import step_reported

    return step_reported(result, name)


class Carrying:
    """A student's graded items, problem by problem, for errors carried forward."""

    def __init__(self, credit: dict[str, float] | None) -> None:
        from .ecf import policy_share

        self.share = policy_share(credit)
        self.by_problem: dict[str, tuple[Any, Any, list[Any]]] = {}

    def add(self, key: str, problem: Any, result: Any, name: str, row: GradeRow,
            values: list[Any] | None) -> None:
        if self.share is None or not values or not hasattr(result, "solution"):
            return
        from .ecf import Item, step_tolerance

        spec = problem.kind.answer(name)
        if spec is None:
            dimension = reported(result, name).dimension
            tolerance = step_tolerance(problem, name, dimension)
        else:
            dimension = spec.dimension
            tolerance = tolerance_for(problem.tolerance, name, dimension,
                                      [a.name for a in problem.kind.answers])
        entry = self.by_problem.setdefault(key, (problem, result, []))
        labels = list(reported(result, name).labels)
        entry[2].append(Item(name, row, [_unlabelled(v, labels) for v in values], dimension,
                             tolerance, spec is None))

    def carry(self, errors: list[str]) -> None:
        """Give each problem's carried credit (a failure here is an internal error of that
        problem, its rows graded as they were)."""
        from .ecf import carry

        if self.share is None:
            return
        for problem, result, items in self.by_problem.values():
            if not any(it.row.result in ("wrong", "partial") for it in items):
                continue
            slipped = {it.name for it in items if "[credit " in it.row.note}
            try:
                carry(items, problem, result, _graph(result), self.share, slipped)
            except InputError:
                continue
            except Exception as err:  # a bug: said, and the rows keep their grades
                from ..core.errors import internal_message

                line = internal_message(problem.file, err)
                if line not in errors:
                    errors.append(line)


_GRAPHS: dict[int, tuple[Any, Any]] = {}


def _graph(result: Any) -> Any:
    """The dependency graph of a solved problem, made once per solve."""
    from ..solving.deps import graph

    cached = _GRAPHS.get(id(result))
    if cached is None or cached[0] is not result:
        if len(_GRAPHS) > 256:
            _GRAPHS.clear()
        cached = _GRAPHS[id(result)] = (result, graph(result.problem, result))
    return cached[1]


def grade_assigned(sheet: str, paths: list[str] | tuple[str, ...], assignment_path: str,
                   credit: dict[str, float] | None = None, submitter: str | None = None,
                   decimal_comma: bool = False) -> Graded:
    """Each student graded on their own variant of each assigned problem only.

    The questions of a problem are the answers its variants ask for (`find`, and
    `expected`); one row per student and question, so rows and time grow with the
    number of students. The sheet may name the original problem id (mapped to the
    student's variant by the assignment) or the variant's id; a variant that is
    another student's is graded against the student's own, with a note. Wrong
    answers that match another student's variants so closely that chance cannot
    explain it (:mod:`.copies`) say whose numbers they used, in the teacher's note only.
    """
    import os

    from ..solving.problem import graded_questions, load
    from .assignment import load_variant, read_assignment, read_key

    plan = read_assignment(assignment_path)
    submissions = read_sheet(sheet, decimal_comma)
    if submitter is not None:
        if submitter not in plan.students:
            raise InputError(f"--student {submitter!r} is not in the assignment"
                             f"{_looks_like(submitter, plan.students)}",
                             file=assignment_path)
        _submitter_only(submissions, submitter, sheet)
    stored_key, why = read_key(os.path.join(os.path.dirname(assignment_path), "key.json"))
    graded = Graded([], assignment=plan, notes=[why] if why else [],
                    sheet_students=list(dict.fromkeys(s.student for s in submissions)))
    variants: dict[str, Any] = {}
    stored: dict[str, Any] = {}  # variant -> answers from the key (file unchanged)
    seen_files: dict[str, str] = {}
    changed: list[str] = []  # variant files edited since gyro vary wrote them
    # A submitter (--student) is graded on their own variants alone: a classmate's file,
    # missing or broken, neither stops their grading nor is named to them.
    mine = [row for row in plan.rows if submitter is None or row.student == submitter]
    for planned in plan.rows:
        seen_files[os.path.realpath(planned.file)] = planned.variant
    for planned in mine:
        # errors carried forward solve again: the stored answers are not enough
        keyed = _from_key(stored_key, planned, changed) \
            if stored_key and "ecf" not in (credit or {}) else None
        if keyed is not None:
            variants[planned.variant], stored[planned.variant] = keyed
            continue
        variants[planned.variant] = load_variant(planned, assignment_path)
    if changed:  # the teacher's to know: a handout made before shows other numbers
        graded.notes.append(
            f"{len(changed)} variant file(s) changed since gyro vary wrote them, graded as "
            f"they are now (a handout made before shows the numbers drawn): "
            f"{', '.join(changed[:3])}{' and more' if len(changed) > 3 else ''}")
    if paths:  # the originals (or the variants' folder): every assigned problem among them
        files, errors = check.collect(paths)
        if errors:
            raise InputError(errors[0].error or "bad path")
        originals = {load(f).id for f in files if os.path.realpath(f) not in seen_files}
        if originals:
            for pid in plan.problems():
                if pid not in originals:
                    raise InputError(f"the assignment's problem {pid!r} is not among the problem "
                                     f"files given (ids: {', '.join(sorted(originals))})",
                                     file=assignment_path)
    questions: dict[str, list[str]] = {}
    for planned in mine:
        if planned.problem not in questions:
            problem = variants[planned.variant]
            # what the student's statement asks, as a bank asks it; another answer is `extra`
            questions[planned.problem] = graded_questions(problem)
    # an answer's name written two ways (`Precession`, `precession`) is one answer
    for s in submissions:
        held = plan.by_item.get((s.student, s.problem)) or plan.by_variant.get(s.problem)
        if held is not None and held.variant in variants:
            s.answer = _answer_named(variants[held.variant], s.answer)
    submissions = _merged(submissions)
    items: dict[tuple[str, str, str], Submission] = {}
    named: dict[tuple[str, str, str], str] = {}  # the sheet's id each item was given under
    notes: dict[tuple[str, str, str], list[str]] = {}
    extra: list[tuple[Submission, Any]] = []
    # (submission, its variant, and the first of the same question under another id)
    alike: list[tuple[Submission, str, tuple[Submission, str] | None]] = []
    assigned = set(plan.problems())
    for s in submissions:
        where = _Where(file=sheet, line=s.line)
        if s.student not in plan.students:
            raise InputError(f"student {s.student!r} is not in the assignment "
                             f"{assignment_path}{_looks_like(s.student, plan.students)}",
                             **where)
        if s.problem in assigned and s.problem in plan.by_variant:
            holder = plan.by_variant[s.problem]
            whose_id = "a student's" if submitter is not None else \
                f"student {holder.student}'s"
            raise InputError(f"the id {s.problem!r} is both problem {s.problem} of the "
                             f"assignment and {whose_id} variant of problem "
                             f"{holder.problem} (assignment line {holder.line}); write the "
                             "student's own variant id instead", **where)
        own = plan.by_item.get((s.student, s.problem))
        note = ""
        if own is None:
            other = plan.by_variant.get(s.problem)
            # A submitter (--student, inside an autograder) is told the same of another
            # student's variant id as of an unknown one: else trying ids would tell who
            # is enrolled. The teacher's own run grades it and notes whose it is.
            if other is None or (submitter is not None and other.student != s.student):
                nor_what = "one of their own variants" if submitter is not None else \
                    "one of its variants"
                raise InputError(f"problem {s.problem!r} (student {s.student!r}) is neither a "
                                 f"problem of the assignment ({', '.join(plan.problems())}) nor "
                                 f"{nor_what}", **where)
            own = plan.by_item.get((s.student, other.problem))
            if own is None:
                raise InputError(f"student {s.student!r} is not assigned problem "
                                 f"{other.problem!r}", **where)
            if other.student != s.student:
                note = (f"answered variant {other.variant} (student {other.student}'s numbers); "
                        f"graded on their own variant {own.variant}")
        problem = variants[own.variant]
        s.answer = _answer_named(problem, s.answer)
        if problem.kind.answer(s.answer) is None and \
                s.answer not in getattr(problem, "steps", []):
            names = ", ".join(a.name for a in problem.kind.answers)
            raise InputError(f"problem {own.problem!r} has no answer {s.answer!r} (answers: "
                             f"{names})", **where)
        alike.append((s, own.variant, None))  # rows that repeat: checked once solved
        if s.answer not in questions[own.problem]:
            extra.append((s, own))
            continue
        key = (s.student, own.problem, s.answer)
        if key in items:  # the same question under a second id: one question all the same
            alike.append((s, own.variant, (items[key], named[key])))
            continue
        items[key] = Submission(s.student, own.problem, s.answer, list(s.values), s.line)
        named[key] = s.problem
        if note:
            notes.setdefault(key, []).append(note)
    solved: dict[str, Any] = {}
    for variant, problem in variants.items():
        if variant in stored:
            solved[variant] = stored[variant]
            continue
        _solved_for(problem, questions[plan.by_variant[variant].problem], variant, solved,
                    graded, locate=True)
    for s, variant, first in alike:  # an ordered answer's values compared in their order
        in_order = _in_order(solved.get(variant), s.answer)
        if first is None:
            _refuse_repeated_rows(s, variants[variant], sheet, in_order)
        else:
            _same_answer(first[0], first[1], s, variants[variant], sheet, in_order)
    lookup = VariantIndex(plan, variants, solved) if submitter is None else None
    extras_by_student: dict[str, list[tuple[Submission, Any]]] = {}
    for s, own in extra:
        extras_by_student.setdefault(s.student, []).append((s, own))
    assigned_problems = plan.problems()
    for student in plan.students if submitter is None else [submitter]:
        total = maximum = 0.0
        rows: list[GradeRow] = []
        wrong: dict[str, tuple[Any, dict[str, list[Any]]]] = {}
        carrying = Carrying(credit)
        for own in (plan.by_item[(student, pid)] for pid in assigned_problems
                    if (student, pid) in plan.by_item):
            problem = variants[own.variant]
            given: dict[str, list[Any]] = {}
            for name in questions[own.problem]:
                key = (student, own.problem, name)
                submission = items.get(key)
                values = submission.values if submission else None
                if own.variant not in solved:
                    row = GradeRow(student, own.problem, name, _submitted(values), "", None,
                                   "error", 0.0, note="internal error solving the problem "
                                   "(please report)")
                    row.feedback = ERROR_FEEDBACK
                else:
                    try:
                        row = grade_item(student, problem, name,
                                         reported(solved[own.variant], name), values, credit)
                        carrying.add(own.variant, problem, solved[own.variant], name, row,
                                     values)
                    except Exception as err:  # a bug: this row is an error
                        from ..core.errors import internal_message

                        line = internal_message(problem.file, err)
                        if line not in graded.errors:
                            graded.errors.append(line)
                        row = GradeRow(student, own.problem, name, _submitted(values), "",
                                       None, "error", 0.0, note=line, feedback=ERROR_FEEDBACK)
                    if row.result in ("wrong", "partial"):
                        wrong.setdefault(own.problem, (own, given))
                if values:
                    given[name] = values
                row.problem, row.variant = own.problem, own.variant
                if notes.get(key):
                    row.note = "; ".join(notes[key] + ([row.note] if row.note else []))
                    row.feedback = "; ".join([f"graded on your own variant {own.variant}"]
                                             + ([row.feedback] if row.feedback else []))
                    if row.plain is not None:
                        row.plain = "; ".join([f"graded on your own variant {own.variant}"]
                                              + ([row.plain] if row.plain else []))
                rows.append(row)
                maximum += row.max_points
        carrying.carry(graded.errors)
        total = sum(row.points for row in rows)
        if lookup is not None:  # --student: the submitter's output must not confirm whose
            _name_match(rows, whose(lookup, student, wrong, len(plan.students)))
        graded.rows += rows
        for s, own in extras_by_student.get(student, []):
            text = (f"not asked in problem {own.problem} (it asks: "
                    f"{', '.join(questions[own.problem])}); not graded")
            graded.rows.append(GradeRow(student, own.problem, s.answer, _submitted(s.values),
                                        "", None, "extra", 0.0, 0.0, note=text,
                                        variant=own.variant, feedback=text))
        graded.scores[student] = (total, maximum)
    return graded


def best_attempts(graded: Graded, attempt_of: str, attempt_number: str,
                  keep: str = "best") -> Graded:
    """A grading of every attempt (entries whose identity in ``graded.people`` names their
    student under ``attempt_of`` and the attempt's number under ``attempt_number``) as a
    grading of students, as the quiz keeps a grade (``keep``):

    - ``best``: each student's attempt with the most points regraded (of equal ones the
      later), its rows and score theirs (a quiz that keeps the highest grade);
    - ``first``: the first attempt's (a quiz that keeps the first);
    - ``average``: the score the mean of the attempts' points, the rows the latest
      attempt's, a note saying so (a quiz that keeps the average)."""
    def number(entry: str) -> int:
        text = graded.people.get(entry, {}).get(attempt_number, "0")
        return int(text) if text.isdigit() else 0

    def rank(entry: str) -> tuple[float, int]:
        if keep == "first":
            return (0.0, -number(entry))
        if keep == "average":
            return (0.0, number(entry))  # the latest attempt's rows are shown
        return graded.scores[entry][0], number(entry)

    from collections import Counter

    best: dict[str, str] = {}  # student -> their kept attempt's entry
    tried: dict[str, list[str]] = {}  # student -> every attempt's entry
    for entry in graded.scores:
        student = graded.people.get(entry, {}).get(attempt_of, entry)
        tried.setdefault(student, []).append(entry)
        if student not in best or rank(entry) >= rank(best[student]):
            best[student] = entry
    kept = {entry: student for student, entry in best.items()}
    graded.rows = [r for r in graded.rows if r.student in kept]
    for row in graded.rows:
        row.student = kept[row.student]
    tries = Counter(graded.people.get(e, {}).get(attempt_of, e) for e in graded.scores)
    several = sum(1 for n in tries.values() if n > 1)
    scores = {student: graded.scores[entry] for student, entry in best.items()}
    if keep == "average":
        scores = {student: (round(sum(graded.scores[e][0] for e in tried[student])
                                  / len(tried[student]), 4), graded.scores[entry][1])
                  for student, entry in best.items()}
    graded.scores = scores
    graded.people = {student: {k: v for k, v in graded.people.get(entry, {}).items()
                               if k not in (attempt_of, attempt_number)}
                     for student, entry in best.items()}
    graded.sheet_students = list(best)
    if several:
        how = {"best": "the attempt with the most points regraded",
               "first": "their first attempt",
               "average": "the mean of their attempts' points regraded (the rows shown are "
                          "the latest attempt's)"}[keep]
        graded.notes.append(f"{several} student(s) made several attempts: each is graded on "
                            f"{how}")
    return graded


def _submitter_only(submissions: list[Submission], student: str, sheet: str) -> None:
    """With --student the sheet is that student's submission: a row naming anyone else is
    refused (graded, it would give them the submitter's work)."""
    for s in submissions:
        if s.student != student:
            raise InputError(f"this row names student {s.student!r}, but the submitter is "
                             f"{student!r} (--student); a submission holds its submitter's "
                             "answers only", file=sheet, line=s.line)


def _looks_like(sid: str, students: Any) -> str:
    """``; the assignment has 'μ1', which looks the same (...)`` when a roster id only
    looks like ``sid`` (`assignment.looks_as`: a micro sign for a mu, a no-break space)."""
    from .assignment import lookalike_words, looks_as

    looks = looks_as(sid)
    alike = next((other for other in students if looks_as(other) == looks), None)
    if alike is None:
        return ""
    return (f"; the assignment has {alike!r}, which looks the same "
            f"({lookalike_words(sid, alike)})")


def _in_order(result: Any, name: str) -> bool:
    """Whether an answer's values have places (A, B; outer, inner), as solved: then two
    lists of values are one answer only in the same order."""
    if result is None:
        return False
    try:
        return ordered(list(reported(result, name).labels))
    except (KeyError, AttributeError):
        return False  # an answer not solved for (one not asked)


def _same_answer(first: Submission, first_id: str, again: Submission, problem: Any,
                 sheet: str, in_order: bool = False) -> None:
    """A question answered under two ids (``11/3`` and ``11/3-ann``): the same values
    (:func:`same_values`) count once; different ones are refused naming both lines (which
    one would count?)."""
    if same_values(first.values, again.values, problem, again.answer, in_order):
        return
    lines = (f"lines {first.line} and {again.line}" if first.line != again.line
             else f"line {first.line}")
    raise InputError(f"student {again.student!r} answers {again.answer} of problem "
                     f"{first.problem} twice, under {first_id!r} and {again.problem!r} "
                     f"({lines}), with different values; keep one", file=sheet,
                     line=again.line)


def _refuse_repeated_rows(submission: Submission, problem: Any, sheet: str,
                          in_order: bool = False) -> None:
    """Two rows of one question giving the same values (:func:`same_values`: ``991.9 rpm``
    and ``991.9rpm``) are a copy-paste slip, refused as a row repeated word for word is
    (`_read_csv`): merged as two roots they would halve the point."""
    for k, (line, values) in enumerate(submission.rows):
        for earlier, before in submission.rows[:k]:
            if same_values(before, values, problem, submission.answer, in_order):
                raise InputError(f"this row gives the values of line {earlier} again "
                                 f"({'; '.join(map(str, values))}); remove one (several "
                                 "roots go in one row separated by ';' or in rows with "
                                 "different values)", file=sheet, line=line)


def same_values(first: list[Any], again: list[Any], problem: Any, name: str,
                in_order: bool = False) -> bool:
    """Whether two lists of submitted values are one answer: each value read as the
    answer's quantity (``991.9 rpm``, ``991.9rpm`` and ``991.9 RPM`` are one, ``5 mN*m``
    and ``5 MN*m`` two; a step's in whichever dimension reads it), a value that does not
    read as one compared as its text without spaces, a word answer's words ignoring case
    and spacing; roots in any order, the values of an answer with places (``in_order``:
    A, B) in theirs."""
    from ..core.units import DIMENSIONS

    spec = problem.kind.answer(name)
    # a step asked as a question has no spec: its dimension is the one its text reads in
    dimensions = [spec.dimension] if spec is not None else list(DIMENSIONS)

    def key(value: Any) -> tuple[str, Any]:
        text = str(value)
        if dimensions == [None]:
            return "word", " ".join(text.split()).casefold()
        for dimension in dimensions:
            try:
                return "si " + str(dimension), parse_value(value, dimension, name).si
            except Exception:  # not this dimension's quantity (graded `invalid`)
                continue
        return "text", "".join(text.split())

    def keys(values: list[Any]) -> list[tuple[str, Any]]:
        found = [key(v) for v in values]
        return found if in_order else sorted(found, key=repr)

    return keys(first) == keys(again)


def conceal(graded: Graded, student: str, reveal: bool = False) -> Graded:
    """The submitter's grades only, each note the student-facing one (too high, too low, a
    root is missing: no other student, no number of the solver's); without ``reveal``
    (after the due date) no correct answer and no relative error either (with the value
    submitted it gives the answer)."""
    graded.rows = [r for r in graded.rows if r.student == student]
    graded.scores = {student: graded.scores.get(student, (0.0, 0.0))}
    graded.sheet_students = [student]
    graded.submitter = student
    for row in graded.rows:
        if not reveal:
            row.correct, row.relative_error = "", None
        row.note = row.feedback
    return graded


def withhold_hints(graded: Graded) -> Graded:
    """--no-hints: each student-facing note says only whether a value is right (a root
    missing said, more values than asked counted for the whole answer: grade_item's
    ``plain``), not which way it is off, its likely slip or its place: with
    resubmissions, "too high" halves the range each time (6 tries from a 100x range) and a
    slip gives the answer in one. The teacher's notes keep everything."""
    for row in graded.rows:
        if row.plain is not None:
            row.feedback = row.plain
            if graded.submitter is not None:  # conceal() made the printed note the feedback
                row.note = row.feedback
    return graded


ERROR_FEEDBACK = "not graded: gyro failed on this problem (your teacher is told)"


def _name_match(rows: list[GradeRow], match: Match | None) -> None:
    """The teacher's note on each wrong row of a problem whose answers are another
    student's: whose variant, and how unlikely a coincidence is."""
    if match is None:
        return
    for row in rows:
        if row.problem in match.variants and row.result in ("wrong", "partial"):
            theirs, own = match.variants[row.problem]
            same = (f" (student {', student '.join(match.also)} drew the same numbers)"
                    if match.also else "")
            row.note = (f"these are the answers to student {match.student}'s variant {theirs}"
                        f"{same}, not to this student's own {own} (expected number of students "
                        f"matched by chance in this class: {match.chance:.1g}); "
                        + row.note).rstrip("; ")


def _from_key(key: dict, row: Any, changed: list[str] | None = None
              ) -> tuple[Any, Any] | None:
    """A variant's problem and answers from the stored key, when its file is the one the
    key was made with (same SHA-256); else None, and the file is read and solved (a
    file whose digest differs is added to ``changed``)."""
    from types import SimpleNamespace

    from ..core.safeyaml import read_bytes
    from ..kinds import get as kind_named
    from ..solving.problem import MAX_FILE_BYTES
    from ..solving.solve import Reported
    from .assignment import file_digest

    entry = key["variants"].get(row.variant)
    if not isinstance(entry, dict) or entry.get("problem") != row.problem:
        return None
    about = key["problems"].get(row.problem)
    try:
        data = read_bytes(row.file, MAX_FILE_BYTES)
        if file_digest(data) != entry.get("sha256"):
            if changed is not None:
                changed.append(row.file)
            return None
        if re.search(rb"^steps\s*:", data, re.M):  # steps asked: graded from the worked answer
            return None
        kind = kind_named(about["kind"])
        answers = {name: Reported(**value) for name, value in entry["answers"].items()}
        questions = list(about["questions"])
    except InputError:
        return None  # the slow path says what is wrong with the file
    except (KeyError, TypeError):
        return None  # a damaged key: solve instead
    problem = SimpleNamespace(id=row.variant, kind=kind, tolerance=about.get("tolerance"),
                              file=row.file, find={q: None for q in questions}, expected={},
                              ask=questions)
    return problem, SimpleNamespace(answers=answers)


def grade_item(student: str, problem: Any, name: str, reported: Any,
               values: list[Any] | None, credit: dict[str, float] | None = None) -> GradeRow:
    """One student's answer to one question, against the solver's answer.

    ``credit``: the share of a value's point given when its likely slip is one of the
    named slips (SLIP_NAMES), e.g. {"2pi": 0.5}; a slip with the sign as well needs both.
    """
    spec = problem.kind.answer(name)
    if spec is None:  # a step of the worked answer asked as a question (`steps:`)
        from .ecf import step_tolerance

        dimension = reported.dimension
        tolerance = step_tolerance(problem, name, dimension)
    else:
        dimension = spec.dimension
        names = [a.name for a in problem.kind.answers]
        tolerance = tolerance_for(problem.tolerance, name, dimension, names)
    correct = _correct_text(reported)
    row = GradeRow(student, problem.id, name, "", correct, None, "missing", 0.0)
    if not values:
        row.note = "no answer submitted"
        return row
    row.submitted = _submitted(values)
    if dimension is None:
        return _grade_words(row, values, reported)
    parsed = []
    sides, signs = (spec.sides, answer_signs(spec, reported)) if spec is not None else ((), ())
    for value in values:
        try:
            parsed.append(_student_value(value, dimension, name, list(reported.labels),
                                         sides, signs))
        except InputError as err:
            row.result, row.note = "invalid", _on_a_sheet(err.message)
            row.feedback = row.note
            return row
        except Exception:  # the unit parser failed on it: still the student's slip
            row.result = "invalid"
            row.note = f"cannot read {' '.join(str(value).split())[:60]!r} as a quantity"
            row.feedback = row.note
            return row
    if not ordered(list(reported.labels)) and not all(p.side is not None for p in parsed):
        # roots matched as a set, unless the student names the root of every value: then
        # `533.5 rpm (slow)` is compared with the slow root (and is not it)
        parsed = [dataclasses.replace(p, side=None) for p in parsed]
    if any(p.side is None for p in parsed) and any(p.side is not None for p in parsed):
        # a place named for some values: theirs are kept, the others take the places left,
        # in order (`35.15 N at B; 62.95 N` puts 62.95 N at A)
        free = [k for k in range(len(reported.si_values))
                if k not in {p.side for p in parsed}]
        parsed = [p if p.side is not None else
                  dataclasses.replace(p, side=free.pop(0) if free else len(parsed) + 99)
                  for p in parsed]
    lines = graded_lines(name, parsed, tolerance, reported)
    passed = sum(line.passed for line in lines)
    row.points = round(passed / len(lines), 4) if lines else 0.0
    row.result = "correct" if passed == len(lines) else ("partial" if passed else "wrong")
    # Here the solver's value is the truth and the student's the one that is off.
    errors = [(_si(line.expected_si) - _si(line.got_si)) / abs(_si(line.got_si))
              for line in lines if line.expected is not None and line.got_si is not None
              and float(line.got_si) != 0]
    errors = [e for e in errors if math.isfinite(e)]  # 1e308 s against 2 s: no figure
    row.relative_error = max(errors, key=abs) if errors else None
    notes, feedback, plain = [], [], []
    credited = 0.0
    for line in lines:
        if line.passed:
            continue
        if line.expected is None:
            notes.append(f"missing root {line.got}")
            feedback.append("a root is missing")
            plain.append(feedback[-1])
        elif line.got_si is None:
            notes.append(f"{line.expected}: no such root")
            feedback.append(f"{line.expected}: no such root (one value too many)")
            plain.append(feedback[-1])
        else:
            unhinted = f"{line.expected}: not right"
            truth, submitted = _si(line.got_si), _si(line.expected_si)
            off = (submitted - truth) / abs(truth) * 100 if truth else math.inf
            note = (f"{line.expected}: off by {off:+.3g}%" if math.isfinite(off)
                    else f"{line.expected}: wrong")
            said = f"{line.expected}: {direction(truth, submitted)}"
            slip = diagnose(truth, submitted, abs(truth) * 0.01, [])
            placed = line.slip if (line.slip or "").startswith(("the order", "the place")) else ""
            twice = any(other is not line and other.passed and other.got_si is not None and
                        abs(_si(other.got_si) - submitted) <= 0.01 * abs(_si(other.got_si))
                        for other in lines)
            if twice:  # the root another value is, again: not "too low" for this one
                note += " (the same root as another value: given twice)"
                said = f"{line.expected}: given twice (another of your values is that root; " \
                       "one is missing)"
            elif placed:  # right for another of the answer's places (A for B): say so
                note += f" (likely slip: {placed})"
                said = f"{line.expected}: not in its place (likely slip: {_place_for_student(placed)})"
            elif slip:
                note += f" (likely slip: {slip.replace('got is', 'submitted is')})"
                said += f" (likely slip: {_slip_for_student(slip)})"
                share, named = slip_credit(slip, credit)
                if share:
                    credited += share
                    note += f" [credit {share:g} for {' and '.join(named)}]"
                    said += f" [credit {share:g} for {' and '.join(named)}]"
                    unhinted += f" [credit {share:g}]"
            notes.append(note)
            feedback.append(said)
            plain.append(unhinted)
    row.note = "; ".join(notes)
    row.feedback = "; ".join(feedback)
    row.plain = "; ".join(plain)
    extra = sum(line.got_si is None for line in lines)
    if extra:  # which value was left over would say which one is nearer the answer
        given = sum(line.expected is not None for line in lines)
        row.plain = f"{given} values given, {given - extra} asked: " + \
            ("not right" if not passed else f"{passed} of them right")
    if credited and lines:
        row.points = round((passed + credited) / len(lines), 4)
        row.result = "partial" if row.result == "wrong" else row.result
    return row


def direction(truth: float, submitted: float) -> str:
    """Which way a wrong value is off, in words that do not give the answer away."""
    if truth and submitted and (truth < 0) != (submitted < 0):
        return "the wrong sign"
    if truth < 0:
        return "too large in size" if submitted < truth else "too small in size"
    return "too high" if submitted > truth else "too low"


def _place_for_student(slip: str) -> str:
    """`matching.compare`'s order or place slip as the student reads it: which order the
    answer asks for, not which of the solver's values theirs is."""
    if slip.startswith("the order"):
        return "the order: " + slip.rpartition("; ")[2].replace("this answer", "the answer")
    return "the place: the words give another place than the value's"


def _slip_for_student(slip: str) -> str:
    """A likely slip as the student reads it: "yours" and "the answer", no solver value."""
    return slip.replace("got is", "yours is").replace("times expected", "times the answer") \
        .replace("minus the expected value", "minus the answer")


# Named slips (the names of --credit) and the words of matching.diagnose that name them.
SLIP_NAMES = {
    "2pi": "a factor of 2 pi",
    "rpm": "a factor of 60/(2 pi)",
    "60": "a factor of 60:",
    "g": "a factor of g",
    "deg": "a factor of 180/pi",
    "10": "a power of ten",
    "sign": "the sign",
}


def parse_credit(text: str) -> dict[str, float]:
    """``2pi=0.5,sign=0.5`` -> {"2pi": 0.5, "sign": 0.5}; InputError naming what is wrong."""
    out: dict[str, float] = {}
    for part in (p.strip() for p in text.split(",")):
        if not part:
            continue
        name, eq, value = part.partition("=")
        name = name.strip().lower()
        if not eq or (name not in SLIP_NAMES and name != "ecf"):
            raise InputError(f"--credit: expected slip=fraction with a slip among "
                             f"{', '.join(SLIP_NAMES)}, or ecf=fraction (errors carried "
                             f"forward), got {part!r}")
        try:
            share = float(value)
        except ValueError:
            share = math.nan
        if not 0 <= share <= 1:
            raise InputError(f"--credit: the share for {name} must lie between 0 and 1, "
                             f"got {value.strip()!r}")
        out[name] = share
    return out


def slip_credit(slip: str, credit: dict[str, float] | None) -> tuple[float, list[str]]:
    """The share of a point a slip earns under ``credit`` (0 when a slip it involves is not
    named there), and the slips' names."""
    if not credit:
        return 0.0, []
    named = [name for name, words in SLIP_NAMES.items() if name != "sign" and words in slip]
    if slip.startswith("the sign") or slip.endswith("and the sign") or \
            " and the sign" in slip:
        named.append("sign")
    if not named or any(n not in credit for n in named):
        return 0.0, named
    share = 1.0
    for n in named:
        share *= credit[n]
    return share, named


def _si(value: float | str | None) -> float:
    """A compared number in SI (a numeric answer's check holds one wherever it is read)."""
    if value is None:
        raise TypeError("a compared value in SI is missing")
    return float(value)


def _submitted(values: list[Any] | None) -> str:
    return "; ".join(" ".join(str(v).split()) for v in values or [])


def normal_word(value: Any) -> str:
    """A word answer as compared: lower case, one space, no trailing full stop."""
    return " ".join(str(value).lower().split()).strip(" .!")


def _label_of(value: Any, labels: list[str]) -> tuple[str, int] | None:
    """``45.13 rpm (slow)`` -> ("45.13 rpm", the index of ``slow`` among ``labels``) where
    the bracket at the end names one of them; else None. No regular expression: a long
    cell must not cost more than its length."""
    if not isinstance(value, str) or not value.rstrip().endswith(")"):
        return None
    text = value.rstrip()
    start = text.rfind("(")
    if start < 0:
        return None
    word = text[start + 1:-1].strip().lower()
    names = [x.lower() for x in labels]
    return (text[:start].rstrip(), names.index(word)) if word and word in names else None


def _student_value(value: Any, dimension: str, name: str, labels: list[str],
                   sides: tuple[str, ...], signs: tuple[tuple[str, int], ...]) -> Any:
    """A student's value of a quantity, written as gyro prints it or as books do: with
    its label in brackets (``45.13 rpm (slow)`` is placed at the slow root, where every
    value names its root, `grade_item`; ``35.15 N (A)`` is placed at A), or with the words of an
    answer that reads them (``35.15 N up at B``, as an answer key may: `_parse_worded`)."""
    from .expected import _parse_worded

    label = _label_of(value, labels)
    if label is not None:  # placed; a root's label only where every value has one (below)
        return dataclasses.replace(parse_value(label[0], dimension, name), side=label[1])
    if sides or signs:
        return _parse_worded(value, dimension, name, sides, signs)
    return parse_value(value, dimension, name)


def _unlabelled(value: Any, labels: list[str]) -> Any:
    """``45.13 rpm (slow)`` as ``45.13 rpm`` where ``slow`` is one of the answer's labels
    (for errors carried forward, which read values without their places)."""
    label = _label_of(value, labels)
    return label[0] if label is not None else value


def _on_a_sheet(message: str) -> str:
    """A unit reader's message as it reads on a sheet: a problem file's advice on comments
    ('#', which a sheet's value does not take) and pint's dimension formula left out, and
    the separator of roots named where a value holds a comma."""
    message = re.sub(r"\s*\(a comment needs '#'\)|; a comment needs '#'", "", message)
    message = re.sub(r" \(dimension [^()]*\[[^()]*\)", "", message)
    if re.search(r"'[-+\u2212]?\d+,\d", message):  # 965,4: a decimal comma or 1,005?
        message += ("; write the decimal point as '.' (965.4), no thousands separator, and "
                    "several roots separated by ';'")
    elif "unexpected ','" in message:
        message += "; several roots go in one cell separated by ';'"
    return message


def _grade_words(row: GradeRow, values: list[Any], reported: Any) -> GradeRow:
    """Words against the solver's words, each side as a set of different words (a word
    written twice, or by a synonym, counts once on either side): the share of the point is
    the words in common over the larger set's size. [stable, stable] against `stable`
    is right; against `stable; unstable` it is half right (it had been given the point:
    the solver's repeated word was matched twice by the student's one)."""
    truth = [str(v) for v in reported.si_values]
    submitted = []
    for value in values:
        if isinstance(value, (dict, list, bool)) or not str(value).strip():
            row.result, row.note = "invalid", f"expected a word, got {value!r}"
            row.feedback = row.note
            return row
        submitted.append(normal_word(value))

    def accepted(word: str) -> set[str]:
        return set(WORD_SYNONYMS.get(word.lower(), ())) | {word.lower()}

    right = list(dict.fromkeys(w.lower() for w in truth))  # the solver's words, once each
    # each student word as the solver's word it names (a synonym), else as written
    named = list(dict.fromkeys(next((w for w in right if s in accepted(w)), s)
                               for s in submitted))
    hits = sum(1 for w in right if w in named)
    extra = [s for s in named if s not in right]
    row.points = round(hits / max(len(right), len(named)), 4) if right else 0.0
    row.result = "correct" if hits == len(right) and not extra else (
        "partial" if hits else "wrong")
    if row.result != "correct":
        row.note = f"expected {', '.join(truth)}, got {row.submitted}"
        row.feedback = ("not all the right words" if hits else "not the right word") + \
            (f"; not among them: {', '.join(extra)}" if hits and extra else "")
    return row


def _correct_text(reported: Any) -> str:
    if reported.unit is None and reported.si_unit is None:
        return "; ".join(str(v) for v in reported.values)
    return "; ".join(f"{num(v)} {reported.unit}" for v in reported.values)
