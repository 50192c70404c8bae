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
"""

from __future__ import annotations

import csv
import html
import io
import re
from typing import Any

from ..core.errors import InputError

#: the formats ``--responses`` reads
FORMATS = ("blackboard",)
#: the columns a Blackboard long-format download must have (lower case)
NEEDED = ("username", "question", "answer")
_TAG = re.compile(r"<[^>]*>")


def plain(text: str) -> str:
    """Question text as plain words: HTML tags dropped, references read, spaces joined."""
    return " ".join(html.unescape(_TAG.sub(" ", text)).split())


def questions(paths: list[str] | tuple[str, ...]) -> dict[str, tuple[str, Any]]:
    """Each question's plain text -> (problem id, what its blank is: `checking.ecf.Part`),
    as the Blackboard export of ``paths`` writes them."""
    from ..render.bank_blackboard import question_text
    from ..solving.paths import problem_files
    from ..solving.problem import load
    from .export import variant_of

    files, missing = problem_files(paths)
    if missing:
        raise InputError(missing[0][1])
    out: dict[str, tuple[str, Any]] = {}
    for path in files:
        try:
            problem = load(path)
            parts: list = []
            variant = variant_of(problem, 1, problem.title, parts_out=parts)
        except InputError as err:
            raise err.located(file=path) from None
        part_of = {part.key: part for part in parts}
        for blank in variant.blanks:
            out[plain(question_text(variant, blank))] = (variant.ident, part_of[blank.key])
    return out


def blackboard_sheet(path: str, paths: list[str] | tuple[str, ...]) -> str:
    """A Blackboard long-format download of responses as a gyro answer sheet (CSV text:
    student, problem, answer, value), its rows in the order of each answer's values."""
    from ..checking.grades import MAX_SHEET_BYTES
    from ..core.safeyaml import read_bytes

    data = read_bytes(path, MAX_SHEET_BYTES, "a Blackboard download of results")
    # a tab-delimited download may come as UTF-16 with a byte-order mark
    encoding = "utf-16" if data[:2] in (b"\xff\xfe", b"\xfe\xff") else "utf-8-sig"
    try:
        text = data.decode(encoding)
    except UnicodeDecodeError:
        raise InputError("is not " + ("UTF-16" if encoding == "utf-16" else "UTF-8") + " text",
                         file=path) from None
    first = text.split("\n", 1)[0]
    rows = list(csv.reader(io.StringIO(text, newline=""),
                           delimiter="\t" if "\t" in first else ","))
    header = [c.strip().lower() for c in rows[0]] if rows else []
    if not all(name in header for name in NEEDED):
        raise InputError("not a Blackboard download of results in the long format (By "
                         "Question and User): the first row must name the columns Username, "
                         f"Question and Answer; got {', '.join(rows[0]) if rows else 'nothing'}",
                         file=path, line=1)
    column = {name: header.index(name) for name in NEEDED}
    known = questions(paths)
    answers: list[tuple[str, str, str, int, str]] = []
    for number, row in enumerate(rows[1:], 2):
        if not any(c.strip() for c in row):
            continue
        if len(row) <= max(column.values()):
            raise InputError(f"expected {len(header)} columns, got {len(row)}", file=path,
                             line=number)
        cell = {name: row[k].strip() for name, k in column.items()}
        found = known.get(plain(cell["question"]))
        if found is None:
            raise InputError("no question of the problem files has this Question text "
                             f"({plain(cell['question'])[:60]!r}...); regrade with the files the "
                             "bank was exported from (without --variants)", file=path,
                             line=number)
        if not cell["answer"]:
            continue  # a blank response: missing, as in a sheet
        problem, part = found
        value = f"{cell['answer']} {part.unit}".strip()
        answers.append((cell["username"], problem, part.name, part.index, value))
    values: dict[tuple[str, str, str], list[str]] = {}  # an answer's values in one row
    for student, problem, name, _, value in sorted(answers, key=lambda a: a[:4]):
        values.setdefault((student, problem, name), []).append(value)
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(("student", "problem", "answer", "value"))
    for key, written in values.items():
        writer.writerow((*key, "; ".join(written)))
    return out.getvalue()
