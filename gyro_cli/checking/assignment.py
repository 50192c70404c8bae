"""Rosters and assignments: who answers which variant (`gyro vary --roster`,
`gyro check --answers --assignment`).

A roster is a CSV with a ``student`` column (a header row is required; other
columns such as name, email, section or SIS ids are kept and carried into the
assignment). An assignment (``DIR/assignment.csv``, written by
``gyro vary FILE... --roster ROSTER.csv -o DIR``) has one row per student and
problem: ``student, problem, variant, file`` (the original problem's id, the
variant's id, the variant file relative to the assignment's folder), then the
roster's other columns.

Both are read strictly (docs/course.md): a header naming a column twice, a
student listed twice, an empty student id, or a (student, problem) assigned
twice is bad input naming the row.
"""

from __future__ import annotations

import csv
import hashlib
import os
import re
import unicodedata
from dataclasses import dataclass, field
from typing import Any

from ..core.csvsafe import plain_cell
from ..core.errors import InputError

ASSIGNMENT_COLUMNS = ("student", "problem", "variant", "file")
MAX_ROSTER_BYTES = 20_000_000
SAFE_NAME = re.compile(r"[^A-Za-z0-9._-]+")


@dataclass
class Student:
    id: str
    extra: dict[str, str] = field(default_factory=dict)  # the roster's other columns
    line: int | None = None


@dataclass
class Assigned:
    student: str
    problem: str  # the original problem's id
    variant: str  # the variant's id
    file: str  # the variant file (resolved against the assignment's folder)
    line: int | None = None


@dataclass
class Assignment:
    path: str
    rows: list[Assigned]
    students: dict[str, Student]
    by_item: dict[tuple[str, str], Assigned] = field(default_factory=dict)  # (student, problem)
    by_variant: dict[str, Assigned] = field(default_factory=dict)

    def problems(self) -> list[str]:
        """The original problem ids, in assignment order."""
        return list(dict.fromkeys(a.problem for a in self.rows))


def read_table(path: str, what: str, ours: bool = False
               ) -> tuple[list[str], list[tuple[int, list[str]]]]:
    """A CSV file with a header row: (column names, [(line, cells)]), blank rows skipped.

    A column named twice in the header is refused (which one would count?), and so is
    a row with more cells than the header has names. ``ours``: a file gyro wrote, whose
    cells it guarded for spreadsheets (csvsafe.py); the guard is taken off again. A
    roster is the teacher's: a leading quote in it is part of the id.
    """
    from ..core.csvsafe import CellRunsOn, one_line_rows
    from ..core.safeyaml import read_text

    text = read_text(path, MAX_ROSTER_BYTES, what, "utf-8-sig")
    try:
        rows = one_line_rows(text)
    except csv.Error as err:
        raise InputError(f"not a CSV file: {err}", file=path) from None
    except CellRunsOn as err:
        raise InputError(str(err), file=path, line=err.line) from None
    if not rows:
        raise InputError(f"empty; expected {what} with a header row", file=path)
    header = [c.strip().lower() for c in rows[0][1]]
    seen: dict[str, int] = {}
    for k, name in enumerate(header, 1):
        if name and name in seen:
            raise InputError(f"the header names column {name!r} twice (columns {seen[name]} "
                             f"and {k}); keep one", file=path, line=1)
        seen[name] = k
    out = []
    for number, row in rows[1:]:
        if not any(c.strip() for c in row):
            continue
        if len(row) > len(header) and any(c.strip() for c in row[len(header):]):
            raise InputError(f"{len(row)} cells but the header names {len(header)} columns",
                             file=path, line=number)
        cells = [plain_cell(c.strip()) if ours else c.strip() for c in row]
        out.append((number, cells + [""] * (len(header) - len(row))))
    return header, out


# Characters refused in an id: it goes into file names, variant ids and LaTeX, and two ids
# must not look alike (a bidi override or a zero-width space hides in it).
_NOT_IN_ID = frozenset(("Cc", "Cf", "Zl", "Zp", "Cs"))
_NOT_IN_NAME = frozenset(("Cc", "Zl", "Zp", "Cs"))  # a zero-width joiner is part of a name
NAME_COLUMNS = ("name", "student name", "full name", "sortable name")
# Columns gyro's assignment.csv writes itself: a roster column so named would be one twice.
RESERVED_COLUMNS = ASSIGNMENT_COLUMNS[1:]


def _bad_character(text: str, categories: frozenset[str]) -> str | None:
    return next((c for c in text if unicodedata.category(c) in categories), None)


def _plain_id(text: str, path: str, line: int, what: str = "student id") -> None:
    """An id is one line of printable text: a student id has no control, format (a bidi
    override, a zero-width space) or line-break character; a problem or variant id, which
    comes from a problem file, no control or line-break character."""
    bad = _bad_character(text, _NOT_IN_ID if what == "student id" else _NOT_IN_NAME)
    if bad is not None:
        raise InputError(f"the {what} {_shown(text)} holds a control character "
                         f"(U+{ord(bad):04X}); ids are one line of printable text",
                         file=path, line=line)


def _shown(text: str) -> str:
    return repr(" ".join(text.split())[:40])


def student_id(text: str) -> str:
    """A student id as gyro compares it: Unicode NFC, so that ``café`` typed with one
    character or with e and a combining accent is one student."""
    return unicodedata.normalize("NFC", text)


def looks_as(sid: str) -> str:
    """What an id looks like: NFKC, under which the micro sign ``µ`` is the Greek ``μ``,
    the ligature ``ﬁ`` is ``fi`` and a no-break space a space; an id of digits alone
    without its leading zeros, as a spreadsheet shows ``007`` once it has opened the file.
    Two roster ids that look alike are refused; a sheet's id that only looks like a
    roster id is named with it."""
    looks = unicodedata.normalize("NFKC", sid)
    return looks.lstrip("0") or "0" if looks.isascii() and looks.isdigit() else looks


def lookalike_words(one: str, other: str) -> str:
    """Where two ids that look alike (:func:`looks_as`) differ, for a message:
    ``U+00B5 MICRO SIGN against U+03BC GREEK SMALL LETTER MU``."""
    def named(c: str) -> str:
        return f"U+{ord(c):04X} {unicodedata.name(c, 'unnamed')}"

    if all(unicodedata.normalize("NFKC", t).isdigit() for t in (one, other)):
        return ("a spreadsheet that opens the file drops leading zeros, and shows both "
                f"as {looks_as(one)}")

    a = next((c for c in one if c not in other), None)
    b = next((c for c in other if c not in one), None)
    if a is None or b is None:
        return "their letters are written differently"
    return f"{named(a)} against {named(b)}"


def _roster_cells(header: list[str], cells: list[str], path: str, line: int) -> None:
    """A name is printable text; no cell holds a NUL."""
    for column, cell in zip(header, cells):
        categories = _NOT_IN_NAME if column.replace("_", " ") in NAME_COLUMNS else \
            frozenset()
        bad = _bad_character(cell, categories) if categories else \
            ("\0" if "\0" in cell else None)
        if bad is not None:
            what = "name" if categories else "cell"
            raise InputError(f"the {what} {_shown(cell)} (column {column!r}) holds a control "
                             f"character (U+{ord(bad):04X}); write it as printable text",
                             file=path, line=line)


def _canvas_gradebook(header: list[str], rows: list[tuple[int, list[str]]]
                      ) -> tuple[list[str], list[tuple[int, list[str]]]]:
    """A Canvas gradebook export (or gyro's --out-format canvas) read as a roster: its
    ``Student`` column holds names, so the student is the SIS User ID, else the Canvas
    ID, and the name is kept as ``name``; the rows Canvas writes under the header for
    the assignments (``Points Possible``, ``Manual Posting``) and Canvas's ``Test Student``
    (the teacher's Student View) are no students. Read as
    written, names had become ids ("Lee, Ann") and "Points Possible" a student."""
    at = {name: header.index(name) for name in ("student", "id", "sis user id")}
    named = [("name" if h == "student" else h) for h in header] + ["student"]
    out: list[tuple[int, list[str]]] = []
    for number, cells in rows:
        cells = cells + [""] * (len(header) - len(cells))
        if not cells[at["id"]].strip() and not cells[at["sis user id"]].strip():
            continue  # Points Possible, Manual Posting: a row of the gradebook's own
        if " ".join(cells[at["student"]].split()) in ("Student, Test", "Test Student"):
            continue  # Canvas's Student View, the teacher's own preview: no student
        sid = cells[at["sis user id"]].strip() or cells[at["id"]].strip()
        out.append((number, cells + [sid]))
    return named, out


def read_roster(path: str) -> list[Student]:
    """The students of a roster CSV (a ``student`` column; the other columns kept)."""
    header, rows = read_table(path, "a roster (CSV with a student column)")
    if {"student", "id", "sis user id"} <= set(header):
        header, rows = _canvas_gradebook(header, rows)
    if "student" not in header:
        raise InputError(f"no `student` column in the header (columns: {', '.join(header)})",
                         file=path, line=1)
    reserved = next((c for c in header if c in RESERVED_COLUMNS), None)
    if reserved is not None:
        raise InputError(f"the roster has a column named {reserved!r}, which gyro's "
                         f"assignment.csv writes itself ({', '.join(ASSIGNMENT_COLUMNS)}); "
                         f"rename it (e.g. 'roster {reserved}')", file=path, line=1)
    at = header.index("student")
    students: dict[str, Student] = {}
    written: dict[str, str] = {}
    looks: dict[str, str] = {}  # looks_as(id) -> the id
    for number, cells in rows:
        if not cells[at]:
            raise InputError("empty student id", file=path, line=number)
        _plain_id(cells[at], path, number)
        _roster_cells(header, cells, path, number)
        sid = student_id(cells[at])
        if sid in students:
            forms = "; the same letters in two Unicode forms" \
                if written[sid] != cells[at] else ""
            raise InputError(f"student {sid!r} is listed twice (lines {students[sid].line} "
                             f"and {number}{forms}); keep one", file=path, line=number)
        alike = looks.setdefault(looks_as(sid), sid)
        if alike != sid:  # on an answer sheet no one could tell them apart
            raise InputError(f"student {sid!r} looks the same as student {alike!r} (lines "
                             f"{students[alike].line} and {number}: "
                             f"{lookalike_words(sid, alike)}); keep one, or give ids that "
                             "can be told apart", file=path, line=number)
        extra = {h: c for h, c in zip(header, cells) if h and h != "student"}
        students[sid] = Student(sid, extra, number)
        written[sid] = cells[at]
    if not students:
        raise InputError("no students in the roster", file=path)
    return list(students.values())


def read_assignment(path: str) -> Assignment:
    """An assignment CSV: who has which variant of which problem."""
    header, rows = read_table(path, "an assignment (assignment.csv from gyro vary --roster)",
                              ours=True)
    missing = [c for c in ASSIGNMENT_COLUMNS if c not in header]
    if missing:
        raise InputError(f"the header must name {', '.join(ASSIGNMENT_COLUMNS)}; missing "
                         f"{', '.join(missing)}", file=path, line=1)
    at = {c: header.index(c) for c in ASSIGNMENT_COLUMNS}
    folder = os.path.dirname(path)
    out = Assignment(path, [], {})
    for number, cells in rows:
        student, problem, variant, file = (cells[at[c]] for c in ASSIGNMENT_COLUMNS)
        if not (student and problem and variant and file):
            raise InputError("student, problem, variant and file must not be empty",
                             file=path, line=number)
        for text, what in ((student, "student id"), (problem, "problem id"),
                           (variant, "variant id")):
            _plain_id(text, path, number, what)
        student = student_id(student)
        row = Assigned(student, problem, variant, os.path.join(folder, file), number)
        earlier = out.by_item.get((student, problem))
        if earlier is not None:
            raise InputError(f"student {student!r} is assigned problem {problem!r} twice "
                             f"(lines {earlier.line} and {number})", file=path, line=number)
        other = out.by_variant.get(variant)
        if other is not None:
            raise InputError(f"variant {variant!r} is assigned twice (lines {other.line} and "
                             f"{number}); each student has their own", file=path, line=number)
        out.rows.append(row)
        out.by_item[(student, problem)] = row
        out.by_variant[variant] = row
        if student not in out.students:
            extra = {h: c for h, c in zip(header, cells) if h and h not in ASSIGNMENT_COLUMNS}
            out.students[student] = Student(student, extra, number)
    if not out.rows:
        raise InputError("no rows: expected student, problem, variant, file", file=path)
    return out


KEY_FORMAT = "gyro-roster-key/1"
MAX_KEY_BYTES = 200_000_000


def code_fingerprint() -> str:
    """A hash of gyro's own source: answers stored by one version of the solver are not
    trusted by another."""
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    digest = hashlib.sha256()
    for path in sorted(root.rglob("*.py")):
        digest.update(path.relative_to(root).as_posix().encode() + b"\0")
        digest.update(path.read_bytes())
    return digest.hexdigest()


def file_digest(text: str | bytes) -> str:
    return hashlib.sha256(text.encode("utf-8") if isinstance(text, str) else text).hexdigest()


def key_digest(data: dict) -> str:
    """The SHA-256 of a key's content (every field but ``digest`` itself, answers
    included), as canonical JSON: what `gyro vary` wrote is what grading uses."""
    body = {k: v for k, v in data.items() if k != "digest"}
    return file_digest(canonical_json(body))


def canonical_json(data: dict) -> str:
    """The canonical JSON a key's digest is taken over (keys sorted, no spaces, ASCII,
    no NaN); `gyro vary` writes its digest from the same, piece by piece."""
    global _CANONICAL
    if _CANONICAL is None:
        import json

        _CANONICAL = json.JSONEncoder(sort_keys=True, separators=(",", ":"),
                                      ensure_ascii=True, allow_nan=False)
    return _CANONICAL.encode(data)


_CANONICAL: Any = None  # made on first use: json is not imported by a solve


def read_key(path: str) -> tuple[dict | None, str]:
    """The stored answer key of a roster set (``key.json`` beside the assignment) and "",
    or None and why it is not used (then every variant is read and solved): "" when there
    is none, else a note for the teacher (damaged, edited, or written by other code)."""
    import json

    from ..core.safeyaml import read_bytes

    if not os.path.isfile(path):
        return None, ""
    try:
        data = json.loads(read_bytes(path, MAX_KEY_BYTES, "a key file"))
    except (InputError, ValueError, RecursionError):
        return None, "key.json does not verify (not a readable key); re-solving the variants"
    if isinstance(data, dict) and data.get("format") == KEY_FORMAT \
            and data.get("code") != code_fingerprint():  # an older key has no digest yet
        return None, "key.json was written by other gyro code; re-solving the variants"
    fault = key_fault(data)
    if fault:
        return None, f"key.json does not verify ({fault}); re-solving the variants"
    return data, ""


def key_fault(data: object) -> str:
    """What is wrong with a key's content ("" when it is whole and its digest matches)."""
    from dataclasses import fields

    from ..solving.solve import Reported

    if not (isinstance(data, dict) and data.get("format") == KEY_FORMAT):
        return f"not a {KEY_FORMAT} key"
    try:
        if data.get("digest") != key_digest(data):
            return "its digest does not match its content: edited or damaged"
    except (TypeError, ValueError):
        return "it holds values JSON cannot write back"
    if not isinstance(data.get("code"), str):
        return "no code fingerprint"
    problems, variants = data.get("problems"), data.get("variants")
    if not (isinstance(problems, dict) and isinstance(variants, dict)):
        return "no problems or variants"
    for pid, about in problems.items():
        if not (isinstance(about, dict) and isinstance(about.get("kind"), str)
                and _strings(about.get("questions"))):
            return f"problem {pid!r} is incomplete"
    answer_fields = {f.name for f in fields(Reported)}
    for vid, entry in variants.items():
        fault = _variant_fault(entry, problems, answer_fields)
        if fault:
            return f"variant {vid!r}: {fault}"
    return ""


def _variant_fault(entry: object, problems: dict, answer_fields: set[str]) -> str:
    """What is wrong with one variant's entry of a key ("" when nothing)."""
    if not (isinstance(entry, dict) and isinstance(entry.get("problem"), str)
            and entry["problem"] in problems
            and isinstance(entry.get("sha256"), str) and isinstance(entry.get("answers"), dict)):
        return "incomplete"
    answers = entry["answers"]
    missing = [q for q in problems[entry["problem"]]["questions"] if q not in answers]
    if missing:
        return f"no answer {missing[0]!r}"
    bad = next((name for name, answer in answers.items()
                if not _answer_whole(answer, answer_fields)), None)
    return f"answer {bad!r} is damaged" if bad is not None else ""


def _answer_whole(answer: object, answer_fields: set[str]) -> bool:
    """A stored answer has every field of a reported answer (``answer_fields``), of the
    right types."""
    if not (isinstance(answer, dict) and set(answer) == answer_fields):
        return False
    plain = (int, float, str)
    return (isinstance(answer["name"], str) and isinstance(answer["symbol"], str)
            and all(isinstance(answer[k], str) or answer[k] is None for k in ("unit", "si_unit"))
            and all(isinstance(answer[k], list)
                    and all(isinstance(v, plain) and not isinstance(v, bool) for v in answer[k])
                    for k in ("values", "si_values"))
            and _strings(answer["labels"]) and _sign_words(answer["signs"]))


def _sign_words(value: object) -> bool:
    """A stored answer's own sign words: None (the kind's), or [word, +1 or -1] pairs."""
    return value is None or (isinstance(value, list) and all(
        isinstance(p, list) and len(p) == 2 and isinstance(p[0], str) and p[1] in (1, -1)
        and not isinstance(p[1], bool) for p in value))


def _strings(value: object) -> bool:
    return isinstance(value, list) and all(isinstance(v, str) for v in value)


def load_variant(row: Assigned, assignment_path: str) -> Any:
    """The variant file of an assignment row, loaded, holding the variant the row names
    (a row pointing at another student's file is refused naming the row): the one check
    of `gyro check --assignment` and `gyro handout --assignment`."""
    from ..solving.problem import load

    try:
        problem = load(row.file)
    except InputError as err:
        raise err.located(file=row.file) from None
    except Exception as err:  # a bug: reported (exit 3) naming the file
        err.gyro_file = row.file  # type: ignore[attr-defined]
        raise
    if problem.id != row.variant:
        raise InputError(f"{row.file} holds problem {problem.id!r}, but the assignment "
                         f"says variant {row.variant!r}", file=assignment_path, line=row.line)
    return problem


# Names gyro gives its own files beside the students' (key.json, assignment.csv, the
# handout's OUT-key.csv): no student's file is named so.
RESERVED_NAMES = frozenset(("key", "assignment"))
# Names Windows keeps for devices, whatever follows a dot: `con.md` is the console there.
WINDOWS_DEVICES = frozenset(("con", "prn", "aux", "nul", "conin$", "conout$")) | \
    frozenset(f"{port}{n}" for port in ("com", "lpt") for n in range(10))


def _a_device(name: str) -> bool:
    """Whether Windows would take a file ``name.EXT`` for a device (`WINDOWS_DEVICES`)."""
    return name.split(".")[0].rstrip(" ").lower() in WINDOWS_DEVICES


def file_names(students: list[str]) -> dict[str, str]:
    """A file name stem per student id, unique across the whole list and case-insensitively
    too (a file system that folds case). A safe id is its own name unless an earlier id
    took it (in any case), gyro names its own files so (RESERVED_NAMES) or Windows keeps
    it for a device (`con`, `nul`, `com1`: WINDOWS_DEVICES); any other id gets its safe
    letters and a hash of the exact id, never a name another student has."""
    out: dict[str, str] = {}
    taken: set[str] = set()
    for sid in students:  # first the ids that are their own names
        if sid not in out and _safe_letters(sid) == sid and sid.lower() not in taken \
                and sid.lower() not in RESERVED_NAMES and not _a_device(sid):
            out[sid] = sid
            taken.add(sid.lower())
    for sid in students:
        if sid not in out:
            out[sid] = _hashed_name(sid, taken)
            taken.add(out[sid].lower())
    return out


def _safe_letters(sid: str) -> str:
    return SAFE_NAME.sub("_", sid).strip("._-")[:60]


def _hashed_name(sid: str, taken: set[str]) -> str:
    """``<safe letters>-<hash>``, the hash longer (then numbered) until no one has it."""
    stem = _safe_letters(sid) or "student"
    if _a_device(stem + "-"):  # `con.x-<hash>` would still be the device on Windows
        stem = "_" + stem
    digest = hashlib.sha256(sid.encode("utf-8", "surrogatepass")).hexdigest()
    for size in (8, 16, 64):
        name = f"{stem}-{digest[:size]}"
        if name.lower() not in taken:
            return name
    number = 2
    while f"{name}-{number}".lower() in taken:
        number += 1
    return f"{name}-{number}"
