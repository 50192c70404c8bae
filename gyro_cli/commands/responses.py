"""A platform's download of students' responses, read as a gyro answer sheet, so that
`gyro check --answers` regrades them (errors carried forward among them: the platform's
own grader marks each blank alone).

Blackboard Learn's "Download Results" of a test, in its long format ("By Question and
User", comma or tab delimited): one row per student and question, with the columns
``Username``, ``Last Name``, ``First Name``, ``Question ID``, ``Question``, ``Answer``,
``Possible Points``, ``Auto Score``, ``Manual Score``. Its Question ID is Blackboard's
own, not one gyro wrote (the upload file has no id field, render/bank_blackboard.py), so
a response is known by its question's text: the text gyro wrote for that blank (the
statement and ``precession (slow), in rpm:``), rebuilt from the same problem files,
compared as plain text (tags dropped, character references read, spaces collapsed).
Only a bank exported without ``--variants`` (each problem as written) can be matched:
a drawn variant is not in the files.

Moodle's quiz Responses report, downloaded as CSV: one row per attempt, the student's
identity columns (``Surname``, ``First name`` and the site's identity fields such as
``Username``, ``ID number`` or ``Email address``), ``State``, ``Started on`` ... and one
``Response N`` column per quiz slot, in the quiz's order. The question text is not in it
(unless asked for), so slot N is the N-th problem of the files, as the Moodle export
wrote them: one cloze question per problem, whose response reads ``part 1: 0.0001954;
part 2: 45.13; ...``, part K being the problem's K-th blank (render/bank_moodle.py).
Downloaded with its ``Right answer N`` columns, each is held to problem N's exported
answers: a quiz in another order, or a drawn variant, is refused rather than graded
against the wrong numbers.

Canvas's quiz Student Analysis (CSV) of a QTI 1.2 bank: one row per student (``name``,
``id``, ``sis_id``, ``section``, ``section_id``, ``section_sis_id``, ``submitted``,
``attempt``), then per question a column ``<question id>: <question text>`` holding the
response and a points column; each question is known by its text, as for Blackboard.
"""

from __future__ import annotations

import csv
import html
import io
import math
import os
import re
from collections.abc import Callable, Iterator
from typing import Any

from ..checking.assignment import student_id
from ..core.errors import InputError

#: the formats ``--responses`` reads
FORMATS = ("blackboard", "moodle", "canvas")
#: the columns a Blackboard long-format download must have (lower case)
NEEDED = ("username", "question", "answer")
_TAG = re.compile(r"<[^>]*>")


def plain(text: str) -> str:
    """Question text as plain words: HTML tags dropped, references read, spaces joined."""
    return " ".join(html.unescape(_TAG.sub(" ", text)).split())


#: one question's problem in a bank: (its file, the title and number the export gave
#: it, the id of the problem file it was drawn from); a problem as written is number 1
Banked = tuple[str, str | None, int, str | None]


def bank_files(paths: list[str] | tuple[str, ...], count: int = 1, seed: int = 0,
               folder: str | None = None) -> list[Banked]:
    """The problems of a bank exported from ``paths``: each file as written, or with
    ``count`` > 1 (``--variants COUNT --seed SEED``) the variants the export drew of each
    file with `vary`, written into ``folder`` to be graded against (the export draws them
    as `gyro vary --count COUNT --seed SEED` writes them)."""
    from ..solving.paths import problem_files
    from ..solving.problem import load
    from .authoring import each_variant

    files, missing = problem_files(paths)
    if missing:
        raise InputError(missing[0][1])
    out: list[Banked] = []
    for path in files:
        if count == 1:
            out.append((path, None, 1, None))
            continue
        try:
            problem = load(path)
            if problem.vary is None:  # exported as written
                out.append((path, None, 1, str(problem.id)))
                continue
            assert folder is not None, "drawn variants need a folder"
            for n, (name, text) in enumerate(each_variant(path, count, seed), 1):
                drawn = os.path.join(folder, f"{len(out):04d}-{name}")
                with open(drawn, "w", encoding="utf-8") as handle:
                    handle.write(text)
                out.append((drawn, problem.title, n, str(problem.id)))
        except InputError as err:
            raise err.located(file=path) from None
    return out


def questions(bank: list[Banked]) -> dict[str, tuple[str, Any]]:
    """Each question's plain text -> (problem id, what its blank is: `checking.ecf.Part`),
    as the Blackboard export of the ``bank`` writes them."""
    return _questions_of(_variants(bank))


def _questions_of(laid: list[tuple[Any, dict[str, Any], str]]) -> dict[str, tuple[str, Any]]:
    from ..render.bank_blackboard import question_text

    out: dict[str, tuple[str, Any]] = {}
    for variant, part_of, _ in laid:
        for blank in variant.blanks:
            out[plain(question_text(variant, blank))] = (variant.ident, part_of[blank.key])
    return out


def _variants(bank: list[Banked]) -> list[tuple[Any, dict[str, Any], str]]:
    """Each problem of the ``bank`` as the export laid it out, in the files' order, with
    its blanks' parts by key and the id of the problem file it is a variant of."""
    from ..solving.problem import load
    from .export import variant_of

    out: list[tuple[Any, dict[str, Any], str]] = []
    for path, title, number, drawn_from in bank:
        try:
            problem = load(path)
            parts: list = []
            variant = variant_of(problem, number, title or problem.title, parts_out=parts)
        except InputError as err:
            raise err.located(file=path) from None
        out.append((variant, {part.key: part for part in parts}, drawn_from or variant.ident))
    return out


def blackboard_sheet(path: str, bank: list[Banked]
                     ) -> tuple[str, dict[str, dict[str, str]]]:
    """A Blackboard long-format download of responses as a gyro answer sheet (CSV text:
    student, problem, answer, value), its rows in the order of each answer's values, and
    each student's name."""
    rows = _rows(path, "a Blackboard download of results")
    header = [c.strip().lower() for c in rows[0]] if rows else []
    if not all(name in header for name in NEEDED):
        raise InputError("not a Blackboard download of results in the long format (By "
                         "Question and User): the first row must name the columns Username, "
                         f"Question and Answer; got {', '.join(rows[0]) if rows else 'nothing'}",
                         file=path, line=1)
    column = {name: header.index(name) for name in NEEDED}
    known = questions(bank)
    answers: list[tuple[str, str, str, int, str]] = []
    people: dict[str, dict[str, str]] = {}
    for number, row in _filled(rows, max(column.values()) + 1, path):
        cell = {name: row[k].strip() for name, k in column.items()}
        found = known.get(plain(cell["question"]))
        if found is None:
            raise InputError("no question of the problem files has this Question text "
                             f"({plain(cell['question'])[:60]!r}...); regrade with the files the "
                             "bank was exported from (and its --variants and --seed)",
                             file=path,
                             line=number)
        problem, part = found
        # a blank response is `missing`, as in a sheet
        value = f"{cell['answer']} {part.unit}".strip() if cell["answer"] else ""
        user = student_id(cell["username"])  # as the sheet's reader compares ids: NFC
        answers.append((user, problem, part.name, part.index, value))
        people.setdefault(user, {"name": " ".join(
            f"{_cell(row, header, 'first name')} {_cell(row, header, 'last name')}".split())})
    return _sheet(answers), people


def _cell(row: list[str], header: list[str], name: str) -> str:
    return row[header.index(name)].strip() if name in header else ""


def _filled(rows: list[list[str]], needed: int, path: str) -> Iterator[tuple[int, list[str]]]:
    """Each row after the header that is not blank, with its line number; a row shorter
    than ``needed`` columns is refused (the message counts the header's)."""
    for number, row in enumerate(rows[1:], 2):
        if not any(c.strip() for c in row):
            continue
        if len(row) < needed:
            raise InputError(f"expected {len(rows[0])} columns, got {len(row)}", file=path,
                             line=number)
        yield number, row


def _rows(path: str, what: str) -> list[list[str]]:
    """A download's CSV rows: comma or tab delimited, UTF-8 or UTF-16 (with its mark)."""
    from ..checking.grades import MAX_SHEET_BYTES
    from ..core.safeyaml import read_bytes

    data = read_bytes(path, MAX_SHEET_BYTES, what)
    # a tab-delimited download may come as UTF-16 with a byte-order mark
    encoding = "utf-16" if data[:2] in (b"\xff\xfe", b"\xfe\xff") else "utf-8-sig"
    try:
        text = data.decode(encoding)
    except UnicodeDecodeError:
        raise InputError("is not " + ("UTF-16" if encoding == "utf-16" else "UTF-8") + " text",
                         file=path) from None
    first = text.split("\n", 1)[0]
    try:
        return list(csv.reader(io.StringIO(text, newline=""),
                               delimiter="\t" if "\t" in first else ","))
    except csv.Error as err:
        raise InputError(f"is not CSV: {err}", file=path) from None


def _sheet(answers: list[tuple[str, str, str, int, str]]) -> str:
    """(student, problem, answer, index, value) as a gyro answer sheet, each answer's
    values in one row in the order of its blanks. A blank left empty (value "") keeps its
    row, so that a student who typed nothing at all is graded (every answer `missing`,
    0 points) instead of left out of the grades."""
    values: dict[tuple[str, str, str], list[str]] = {}  # an answer's values in one row
    for student, problem, name, _, value in sorted(answers, key=lambda a: a[:4]):
        typed = values.setdefault((student, problem, name), [])
        if value:
            typed.append(value)
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(("student", "problem", "answer", "value"))
    for key, written in values.items():
        writer.writerow((*key, "; ".join(written)))
    return out.getvalue()


#: Moodle's identity columns, the first filled one naming the student (lower case)
MOODLE_WHO = ("username", "id number", "email address")
_RESPONSE = re.compile(r"response (\d+)")
#: a cloze response as Moodle summarises it: "part 1: 0.0001954; part 2: 45.13"
_PART = re.compile(r"(?:^|;\s*)part (\d+):\s*", re.IGNORECASE)


#: in a download read with every attempt: the student an attempt's entry is of, and the
#: attempt's number (of equal grades the later attempt is kept)
ATTEMPT_OF = "attempt of"
ATTEMPT_NUMBER = "attempt number"


def best_of_attempts(graded: Any, keep: str = "best") -> Any:
    """A grading of a download read with every attempt as one of its students, each on
    the attempt the quiz keeps, or their attempts' mean (`checking.grades.best_attempts`)."""
    from ..checking.grades import best_attempts

    return best_attempts(graded, ATTEMPT_OF, ATTEMPT_NUMBER, keep)


def moodle_sheet(path: str, bank: list[Banked], decimal_comma: bool = False,
                 every_attempt: bool = False, notes: list[str] | None = None
                 ) -> tuple[str, dict[str, dict[str, str]]]:
    """A Moodle quiz Responses report (CSV) as a gyro answer sheet, and each student's
    name: Response N is the N-th problem of the ``bank``; a student's finished attempt
    started last is the one read (`_by_start`), and an attempt not finished (State) is not
    graded,
    as Moodle grades none; each number is read as Moodle reads it (`moodle_number`, with
    the site's ``decimal_comma``). With ``every_attempt`` each finished attempt is an
    entry of its own, ``<student> (attempt N)``, whose identity names its student
    (ATTEMPT_OF), for `checking.grades.best_attempts`."""
    rows = _rows(path, "a Moodle quiz responses report")
    header = [c.strip().lower() for c in rows[0]] if rows else []
    slots = {int(m.group(1)): k for k, name in enumerate(header)
             if (m := _RESPONSE.fullmatch(name))}
    if not slots or "surname" not in header:
        raise InputError("not a Moodle quiz Responses report: the first row must name the "
                         "columns Surname, First name, ... and Response 1, Response 2, ...; "
                         f"got {', '.join(rows[0]) if rows else 'nothing'}", file=path, line=1)
    problems = [(variant, part_of) for variant, part_of, _ in _variants(bank)]
    if sorted(slots) != list(range(1, len(problems) + 1)):
        raise InputError(f"has Response columns {', '.join(map(str, sorted(slots)))}, expected "
                         f"1 to {len(problems)}: one per problem file, the quiz's questions "
                         "in the order the bank was exported", file=path, line=1)
    right = {int(m.group(1)): k for k, name in enumerate(header)
             if (m := _RIGHT_ANSWER.fullmatch(name)) and int(m.group(1)) in slots}
    by_student: dict[str, list[tuple[str, str, str, int, str]]] = {}
    named: dict[str, int] = {}  # a student known by name alone -> the line of their row
    people: dict[str, dict[str, str]] = {}
    state = header.index("state") if "state" in header else None
    finished: dict[str, list[tuple[int, list[str]]]] = {}  # student -> (line, row)s
    unfinished = 0
    for number, row in _filled(rows, len(header), path):
        student, by_name = _moodle_student(header, row)
        student = student_id(student)  # as the sheet's reader compares ids: NFC
        if not student or student.lower().startswith("overall average"):
            continue  # the report's average row is no one's attempt
        if state is not None and row[state].strip().lower() != "finished":
            unfinished += 1
            continue  # in progress, overdue, never submitted: Moodle grades none of them
        if by_name:
            if student in named:
                raise InputError(f"rows {named[student]} and {number} both name {student!r} "
                                 "and the report shows no identity field (Username, ID number "
                                 "or Email address) to tell two students from two attempts: "
                                 "download it with one", file=path, line=number)
            named[student] = number
        finished.setdefault(student, []).append((number, row))
        for slot, k in right.items():
            _same_question(row[k], slot, *problems[slot - 1], path, number, decimal_comma)

    def one_attempt(student: str, who: str, attempt: int, number: int,
                    row: list[str]) -> None:
        """One attempt's answers under ``who`` (every blank: an empty one is `missing`)."""
        answers: list[tuple[str, str, str, int, str]] = []
        for slot, (variant, part_of) in enumerate(problems, 1):
            for blank in variant.blanks:
                part = part_of[blank.key]
                answers.append((who, variant.ident, part.name, part.index, ""))
            for part, typed in _parts(row[slots[slot]], variant, part_of, path, number):
                answers.append((who, variant.ident, part.name, part.index,
                                _with_unit(moodle_number(typed, decimal_comma),
                                           part.unit)))
        by_student[who] = answers
        people[who] = {"name": _moodle_name(header, row)} | (
            {ATTEMPT_OF: student, ATTEMPT_NUMBER: str(attempt)} if every_attempt else {})

    for student, attempts in finished.items():
        # in the order they were started (a report may list the newest first)
        attempts = _by_start(header, attempts, path, student, not every_attempt) \
            if len(attempts) > 1 else attempts
        if not every_attempt:
            one_attempt(student, student, len(attempts), *attempts[-1])
            continue
        for attempt, (number, row) in enumerate(attempts, 1):
            one_attempt(student, f"{student} (attempt {attempt})", attempt, number, row)
    if not right and notes is not None:
        notes.append("the report has no Right answer columns, so gyro cannot check that the "
                     "quiz's question N is problem N as exported (a quiz in another order, or "
                     "a bank of drawn variants, would be graded against the wrong numbers): "
                     "download it with Right answer ticked")
    if unfinished and notes is not None:
        notes.append(f"{unfinished} attempt(s) not finished (State) are not graded, as Moodle "
                     "grades none")
    return _sheet([a for answers in by_student.values() for a in answers]), people


#: the report's column of a slot's right answer (its option "Right answer")
_RIGHT_ANSWER = re.compile(r"right answer (\d+)")
#: a right answer equal to the exported value: the bank writes every digit (repr), and a
#: drawn variant's or another problem's value is farther than this
_SAME_VALUE = 1e-6


def _same_question(cell: str, slot: int, variant: Any, part_of: dict[str, Any], path: str,
                   line: int, decimal_comma: bool) -> None:
    """Refuse a row whose ``Right answer N`` is not problem N's as exported: the quiz's
    slot N holds another problem (the quiz built in another order) or a drawn variant (a
    bank exported with --variants), which would be graded against problem N unnoticed."""
    blanks = {blank.key: blank for blank in variant.blanks}
    try:
        parts = _parts(cell, variant, part_of, path, line)
    except InputError:  # parts that its question does not have
        parts, same = [], False
    else:
        same = True
    for part, typed in parts:
        value = blanks[part.key].value
        try:  # the number as Moodle reads it, before its unit
            right = float(moodle_number(typed, decimal_comma).split()[0])
        except (ValueError, IndexError):
            right = math.nan
        if not abs(right - value) <= _SAME_VALUE * abs(value):
            same = False
    if not same:
        raise InputError(
            f"Right answer {slot} is not {variant.ident}'s as the bank gives it "
            f"({_exported_answer(variant)}): the quiz's question {slot} is another problem "
            "(a quiz in another order than the files) or a drawn variant (a bank exported "
            "with --variants cannot be regraded); regrade with the files in the quiz's order",
            file=path, line=line)


def _exported_answer(variant: Any) -> str:
    """A question's right answer as Moodle's report sums it up, shortened to 4 digits."""
    if len(variant.blanks) == 1 and not variant.choices:
        return f"{variant.blanks[0].value:.4g}"
    return "; ".join(f"part {k}: {blank.value:.4g}" for k, blank in enumerate(variant.blanks, 1))



def _by_start(header: list[str], attempts: list[tuple[int, list[str]]], path: str,
              student: str, strict: bool = True) -> list[tuple[int, list[str]]]:
    """A student's finished attempts in the order they were started (``Started on``, as
    Moodle writes a date: ``27 November 2026, 9:00 AM``). When a date cannot be read the
    report's own order may be the newest first: refused when ``strict`` (the latest
    attempt is the one graded), else the rows' order (every attempt is graded)."""
    import datetime

    column = header.index("started on") if "started on" in header else None
    when = []
    for number, row in attempts:
        text = " ".join(row[column].replace(",", " ").split()) if column is not None else ""
        for form in ("%d %B %Y %I:%M %p", "%A %d %B %Y %I:%M %p", "%d %b %Y %I:%M %p",
                     "%Y-%m-%d %H:%M:%S", "%Y-%m-%d %H:%M", "%d %B %Y %H:%M"):
            try:
                when.append(datetime.datetime.strptime(text, form))
                break
            except ValueError:
                continue
        else:
            if not strict:
                return attempts
            raise InputError(f"{student!r} has {len(attempts)} finished attempts and this "
                             f"one's Started on ({text[:40]!r}) is no date gyro reads, so "
                             "which is the latest is unknown: download the report with its "
                             "dates, or grade the best attempt (--attempts best)",
                             file=path, line=number)
    order = sorted(range(len(attempts)), key=lambda k: (when[k], k))
    return [attempts[k] for k in order]


#: a typed number as Moodle's numerical questions read it: digits with '.' or ',', spaces
#: (thousands), a trailing point (``965.``), and a power of ten written e, E, x10^,
#: *10^, ×10^ or x10**; then the unit typed, kept as typed
_MOODLE_NUMBER = re.compile(r"\s*([-+\u2212]?[\d.,\s]*\d\.?)\s*"
                            r"(?:(?:e|E|(?:x|X|\*|×)\s*10\s*(?:\^|\*\*))\s*([-+\u2212]?\d+))?(.*)",
                            re.S)
_PLAIN_NUMBER = re.compile(r"[-+]?(?:\d+(?:\.\d*)?|\.\d+)")


def moodle_number(typed: str, decimal_comma: bool = False) -> str:
    """A response's number written as Moodle's numerical question reads it (its answer
    processor, ``apply_units``): spaces dropped; a '.' or several ',' make ',' a thousands
    separator; else a single ',' is the site's: a thousands separator where the site's
    language writes one with ',' (English: ``965,4`` is 9654), the decimal point where it
    writes a decimal comma (``decimal_comma``: ``965,4`` is 965.4); ``9.283x10^2`` is
    ``9.283e2``; ``965.`` is 965. The unit typed after it is kept. Text that holds no
    such number is returned as typed (and graded `invalid` with its reason)."""
    match = _MOODLE_NUMBER.fullmatch(typed.replace("\u2212", "-"))
    if match is None:
        return typed
    digits, power, rest = match.groups()
    digits = "".join(digits.split())
    if "." in digits or digits.count(",") > 1:
        digits = digits.replace(",", "")
    else:
        digits = digits.replace(",", "." if decimal_comma else "")
    if not _PLAIN_NUMBER.fullmatch(digits):
        return typed  # 1.2.3, or a comma where the site reads none
    number = digits + (f"e{power.replace(chr(0x2212), '-')}" if power else "")
    return f"{number} {rest.strip()}".strip() if rest.strip() else number


def _with_unit(typed: str, unit: str) -> str:
    """A typed number with its blank's unit; typed with a unit (Moodle's numerical
    question asks for one), as typed."""
    try:
        float(typed.replace("\u2212", "-"))  # the minus sign of a page or handout too
    except ValueError:
        return typed
    return f"{typed} {unit}".strip()


def _moodle_student(header: list[str], row: list[str]) -> tuple[str, bool]:
    """Who made an attempt: the first identity field filled, else surname and first name
    (then True: a name, which two students may share)."""
    for name in MOODLE_WHO:
        if name in header and row[header.index(name)].strip():
            return row[header.index(name)].strip(), False
    return " ".join(f"{_cell(row, header, 'surname')} {_cell(row, header, 'first name')}"
                    .split()), True


def _moodle_name(header: list[str], row: list[str]) -> str:
    return " ".join(f"{_cell(row, header, 'first name')} {_cell(row, header, 'surname')}"
                    .split())


def _parts(cell: str, variant: Any, part_of: dict[str, Any], path: str,
           line: int) -> list[tuple[Any, str]]:
    """A response cell's typed numbers, each with its blank's part: a cloze's ``part K: x``
    (part K the K-th blank; word answers after the blanks are not regraded), or a
    single-blank question's number alone."""
    cell = cell.strip()
    if cell in ("", "-") or not variant.blanks:
        return []  # nothing typed, or a word answer alone (not regraded)
    pieces = _PART.split(cell)
    if len(pieces) == 1:
        if len(variant.blanks) != 1 or variant.choices:
            raise InputError(f"the response to {variant.ident} ({cell[:40]!r}) is not in "
                             "parts (part 1: ...; part 2: ...) as its cloze question gives",
                             file=path, line=line)
        return [(part_of[variant.blanks[0].key], cell)]
    out = []
    for k, typed in zip(pieces[1::2], pieces[2::2]):
        index, typed = int(k) - 1, typed.strip()
        if not 0 <= index < len(variant.blanks) + len(variant.choices):
            raise InputError(f"the response to {variant.ident} has part {k}; its question "
                             f"has {len(variant.blanks) + len(variant.choices)} parts",
                             file=path, line=line)
        if index < len(variant.blanks) and typed not in ("", "-"):
            out.append((part_of[variant.blanks[index].key], typed))
    return out


def _choice_text(variant: Any, choice: Any) -> str:
    """A word answer's question text as the QTI export writes it (render/bank_qti.py)."""
    from ..render.bank import choice_prompt, html_text

    return variant.statement_html + f"<p>{html_text(choice_prompt(choice))}:</p>"


#: a Canvas Student Analysis question column: "<question id>: <question text>"
_CANVAS_QUESTION = re.compile(r"(\d+):\s(.*)", re.S)


def _compact(text: str) -> str:
    """Question text with no spaces at all: Canvas strips the tags without a space."""
    return "".join(plain(text).split())


def canvas_sheet(path: str, bank: list[Banked], every_attempt: bool = False
                 ) -> tuple[str, dict[str, dict[str, str]]]:
    """A Canvas quiz Student Analysis report (CSV) of a QTI bank as a gyro answer sheet,
    and each student's Canvas identity (name, Canvas id, SIS id, section: the gradebook
    columns of `--out-format canvas`). Each question column is matched by its text; a
    student is their SIS id, else their Canvas id; of several attempts, the highest
    counts (the attempt column, whatever the rows' order), or with ``every_attempt`` each
    is an entry of its own, as `moodle_sheet` makes them; an attempt left blank is
    graded, every answer `missing`."""
    rows = _rows(path, "a Canvas Student Analysis report")
    header = [c.strip() for c in rows[0]] if rows else []
    names = [c.lower() for c in header]
    if not all(name in names for name in ("name", "id", "sis_id", "attempt")):
        raise InputError("not a Canvas quiz Student Analysis report: the first row must "
                         "name the columns name, id, sis_id, ..., attempt, then each question "
                         f"as 'ID: text'; got {', '.join(header[:8]) or 'nothing'}",
                         file=path, line=1)
    laid = _variants(bank)
    known = {_compact(text): found for text, found in _questions_of(laid).items()}
    words = {_compact(_choice_text(variant, choice))
             for variant, _, _ in laid for choice in variant.choices}
    origin = {variant.ident: drawn_from for variant, _, drawn_from in laid}
    asked: dict[int, tuple[str, Any]] = {}
    for k, name in enumerate(header[names.index("attempt") + 1:], names.index("attempt") + 1):
        m = _CANVAS_QUESTION.fullmatch(name)
        if m is None:
            continue  # a points column, n correct, n incorrect, score
        found = known.get(_compact(m.group(2)))
        if found is None and _compact(m.group(2)) in words:
            continue  # a word answer's multiple choice: Canvas's mark stands
        if found is None:
            raise InputError(f"no question of the problem files has the text of column "
                             f"{k + 1} ({plain(m.group(2))[:60]!r}...); regrade with the files "
                             "the bank was exported from (and its --variants and --seed)",
                             file=path,
                             line=1)
        asked[k] = found
    column = {name: names.index(name) for name in ("name", "id", "sis_id", "attempt")}
    latest: dict[str, tuple[int, list[str]]] = {}  # Canvas id -> (attempt, row)
    every: dict[tuple[str, int], list[str]] = {}  # (Canvas id, attempt) -> row
    for line, row in _filled(rows, len(header), path):
        canvas_id = row[column["id"]].strip()
        if not canvas_id:
            raise InputError("a row with no Canvas id (column id)", file=path, line=line)
        attempt = _attempt(row[column["attempt"]], path, line)
        if (canvas_id, attempt) in every:  # which of the two counts is the rows' order
            raise InputError(f"Canvas id {canvas_id}'s attempt {attempt} is listed twice",
                             file=path, line=line)
        every[canvas_id, attempt] = row
        if canvas_id not in latest or attempt >= latest[canvas_id][0]:
            latest[canvas_id] = (attempt, row)  # the highest attempt, in any row order
    people: dict[str, dict[str, str]] = {}
    students: dict[str, str] = {}  # student -> Canvas id
    answers: list[tuple[str, str, str, int, str]] = []
    chosen = sorted(every.items(), key=lambda e: e[0][1]) if every_attempt else \
        [((canvas_id, attempt), row) for canvas_id, (attempt, row) in latest.items()]
    for (canvas_id, attempt), row in chosen:
        # a student is who their latest attempt names (an SIS id added later, say), for
        # every attempt of their Canvas id
        named_row = latest[canvas_id][1]
        sis_id = named_row[column["sis_id"]].strip()
        student = student_id(sis_id or canvas_id)  # as the sheet's reader compares: NFC
        if students.setdefault(student, canvas_id) != canvas_id:  # one's SIS id, other's id
            raise InputError(f"two students would be graded as {student!r}: Canvas ids "
                             f"{students[student]} and {canvas_id} (one's SIS id is the "
                             "other's Canvas id); give every student an SIS id, or none",
                             file=path)
        who = f"{student} (attempt {attempt})" if every_attempt else student
        people[who] = {"name": named_row[column["name"]].strip(), "id": canvas_id,
                       "sis_id": sis_id, "section": named_row[names.index("section")].strip()
                       if "section" in names else ""} | (
            {ATTEMPT_OF: student, ATTEMPT_NUMBER: str(attempt)} if every_attempt else {})
        for k, (problem, part) in asked.items():
            typed = row[k].strip()
            answers.append((who, problem, part.name, part.index,
                            _with_unit(typed, part.unit) if typed else ""))
    return _sheet(_drawn_once(answers, origin, path)), people


def _drawn_once(answers: list[tuple[str, str, str, int, str]], origin: dict[str, str],
                path: str) -> list[tuple[str, str, str, int, str]]:
    """A bank of drawn variants has columns for each variant's numbers, and a student's
    quiz drew one variant of each number: of a student's columns for one answer of one
    problem, those of the variant typed into are graded, the others, blank, are not
    theirs; where all are blank, the first variant's are kept (missing, 0 points,
    whichever variant was drawn), so that every student is graded on every answer once.
    The values of one answer typed into two variants (a quiz that drew the two roots from
    two variants) are refused: one answer cannot be graded against two problems.
    ``origin``: each variant's problem id -> the id of the file it was drawn from (a file
    as written: its own, and nothing changes)."""
    groups: dict[tuple[str, str, str], list[int]] = {}
    for k, (who, problem, name, _, _) in enumerate(answers):
        groups.setdefault((who, origin.get(problem, problem), name), []).append(k)
    keep: set[int] = set()
    for (who, drawn_from, name), members in groups.items():
        typed = list(dict.fromkeys(answers[k][1] for k in members if answers[k][4]))
        if len(typed) > 1:
            raise InputError(f"{who}'s {name} of {drawn_from} is typed into the questions of "
                             f"{' and '.join(typed)}: the values of one answer drawn from two "
                             "variants cannot be graded as one answer, so this download "
                             "cannot be regraded (a quiz that draws a problem's numbers "
                             "together, from one variant, can)", file=path)
        chosen = typed[0] if typed else answers[members[0]][1]
        keep.update(k for k in members if answers[k][1] == chosen)
    return [answer for k, answer in enumerate(answers) if k in keep]


def _attempt(cell: str, path: str, line: int) -> int:
    """A Canvas row's attempt number; a row without one is refused (which of a student's
    attempts counts would depend on the rows' order)."""
    if cell.strip().isdigit():
        return int(cell.strip())
    raise InputError(f"attempt {cell.strip()!r} is not an attempt number (1, 2, ...)",
                     file=path, line=line)


def each_alone(text: str, scratch: str, grade: Callable[[str], Any]) -> Any:
    """A sheet of responses to a bank of drawn variants (CSV ``text``), each student graded
    alone by ``grade`` (a sheet's path -> `checking.grades.Graded`): a student is graded on
    the variants their own rows name, where a sheet graded whole grades every student on
    every problem any row names, so on every variant. The grades of all, joined in the
    sheet's order; ``scratch``: a folder for the students' sheets."""
    from ..checking.grades import Graded

    rows = list(csv.reader(io.StringIO(text)))
    by_student: dict[str, list[list[str]]] = {}
    for row in rows[1:]:
        by_student.setdefault(row[0], []).append(row)
    whole = Graded([])
    for k, own in enumerate(by_student.values()):
        sheet = os.path.join(scratch, f"responses-{k}.csv")
        with open(sheet, "w", encoding="utf-8", newline="") as out:
            csv.writer(out, lineterminator="\n").writerows([rows[0], *own])
        graded = grade(sheet)
        whole.rows += graded.rows
        whole.scores.update(graded.scores)
        whole.sheet_students += graded.sheet_students
        whole.errors += [line for line in graded.errors if line not in whole.errors]
        whole.notes += [line for line in graded.notes if line not in whole.notes]
        whole.submitter = graded.submitter
    return whole
