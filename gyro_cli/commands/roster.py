"""`gyro vary FILE... --roster ROSTER.csv -o DIR`: one variant per student and problem.

Each student's numbers are drawn from a ``random.Random`` seeded by a hash of
the course seed, the problem's id and the student's id, so a student's
variant depends on nothing else: adding or removing a student changes nobody
else's numbers, and the same seed gives the same files. The draw follows the
problem's `vary:` block exactly as ``gyro vary --count`` does (ranges, 3
significant figures, redrawn when there is no real solution).

Written: ``DIR/<problem file stem>/<student>.yaml`` (the variant, with its
computed `expected` answers; its id is ``<problem id>-<student>``, see
:func:`variant_ids`) and
``DIR/assignment.csv`` (student, problem, variant, file, then the roster's other
columns), the file that ``gyro check --answers --assignment`` and
``gyro handout --assignment`` read, and ``DIR/key.json``: each variant's answers
as the solver gave them, the SHA-256 of its file, a hash of gyro's source and a
digest of the key's own content, so that grading 10,000 students need not parse
and solve 10,000 files again (a variant whose file changed, or a key that was
edited, damaged or written by other code, is solved afresh).
"""

from __future__ import annotations

import copy
import csv
import hashlib
import io
import json
import os
import random
from collections.abc import Generator, Iterator
from dataclasses import dataclass
from typing import IO, TYPE_CHECKING, Any

from ..checking.assignment import (
    ASSIGNMENT_COLUMNS,
    KEY_FORMAT,
    Student,
    canonical_json,
    code_fingerprint,
    file_digest,
    file_names,
    read_roster,
)
from ..core.csvsafe import safe_cell
from ..core.errors import InputError
from .authoring import draw_variant, parse_vary, variant_yaml

if TYPE_CHECKING:
    from ..core.files import StagedFolder

MAX_DRAWS = 200  # per student and problem, before the ranges are called too wide
# variants of a set, at least, for `draw` to fork workers: a smaller class is drawn in less
# time than two workers take to start and hand it back
POOLED = 200

#: one drawn variant: its file name, YAML text (None: the worker that drew it wrote the
#: file, `RosterSet.draw`), variant id and key entry
Variant = tuple[str, str | None, str, dict[str, Any]]
#: what a problem's variants share, by the problem's index (`RosterSet._variant`)
Shared = dict[int, tuple[dict, list[str], dict, str]]


def student_rng(seed: int, problem_id: str, student: str) -> random.Random:
    """The random stream of one student's variant of one problem (stable, independent)."""
    digest = hashlib.sha256(f"gyro-roster\0{seed}\0{problem_id}\0{student}".encode()).digest()
    return random.Random(int.from_bytes(digest[:16], "big"))


def variant_ids(problem_ids: list[str], students: list[str]) -> dict[tuple[str, str], str]:
    """The variant id of each (problem, student): ``<problem id>-<student>``, unless that
    is the id of a problem of the set or another variant's plain id (problems ``P1`` and
    ``P1-2``, student ``2``); then it gets ``-`` and 8 hex digits of a hash of both ids, so
    that an id on an answer sheet names one thing."""
    from collections import Counter

    plain = {(p, s): f"{p}-{s}" for p in problem_ids for s in students}
    count = Counter(plain.values())
    taken = set(problem_ids)
    out = {}
    for (pid, sid), vid in plain.items():
        if vid in taken or count[vid] > 1:
            vid += "-" + hashlib.sha256(f"{pid}\0{sid}".encode()).hexdigest()[:8]
        out[(pid, sid)] = vid
    if len(set(out.values()) | taken) != len(out) + len(taken):  # a hash meeting an id
        clash = Counter(list(out.values()) + list(taken)).most_common(1)[0][0]
        raise InputError(f"the variant id {clash!r} would name two things; rename the "
                         "problem or the student whose id it extends")
    return out


@dataclass
class RosterSet:
    """A roster's set before it is drawn: the problems (each with its `vary` ranges and
    file stem), the students, their file names and every variant's id."""

    problems: list[tuple[Any, list, str]]
    students: list[Student]
    names: dict[str, str]
    ids: dict[tuple[str, str], str]
    seed: int

    def files(self) -> list[str]:
        """Every variant's file name, relative to the set's folder, as `draw` makes them."""
        return [f"{stem}/{self.names[s.id]}.yaml" for _, _, stem in self.problems
                for s in self.students]

    def key_problems(self) -> dict[str, Any]:
        """The key's entry of each problem: its kind, tolerance and the questions keyed
        (what its statement asks)."""
        from ..solving.problem import asked

        return {problem.id: {"kind": problem.kind.name, "tolerance": problem.tolerance,
                             "questions": asked(problem)}
                for problem, _, _ in self.problems}

    def draw(self, jobs: int = 1, into: StagedFolder | None = None
             ) -> Generator[Variant, None, None]:
        """Each variant in turn, problem by problem: its file name, YAML text, variant id
        and key entry (its problem, the file's SHA-256 and the solver's answers). With
        ``jobs`` > 1, a set of `POOLED` variants or more is drawn by that many forked
        workers (`checking.pool`), in the same order and to the same bytes: a variant
        depends only on the seed, its problem and its student. Workers given ``into``
        (the set's staged folder, its writer thread not started) write each variant's
        file there themselves, and its text comes back as None: the files are created on
        every core, and their text is not sent back to be written."""
        from ..checking import pool

        count = len(self.problems) * len(self.students)
        if jobs > 1 and count >= POOLED and pool.forks():
            yield from self._pooled(jobs, into)
            return
        made: Shared = {}
        for p in range(len(self.problems)):
            for s in range(len(self.students)):
                yield self._variant(p, s, made)

    def _variant(self, p: int, s: int, made: Shared) -> tuple[str, str, str, dict[str, Any]]:
        """The variant of problem ``p`` for student ``s``; ``made`` holds what a problem's
        variants share (its data without `vary`, the answers keyed, the YAML of the values
        they share, the file's name), made by its first variant."""
        problem, ranges, stem = self.problems[p]
        if p not in made:
            base = copy.deepcopy(problem.data)
            base.pop("vary", None)
            made[p] = (base, _keyed(problem), {}, os.path.basename(problem.file))
        base, keyed, shared, source = made[p]
        student = self.students[s]
        rng = student_rng(self.seed, problem.id, student.id)
        variant_id = self.ids[(problem.id, student.id)]
        solved: list[Any] = []
        for _ in range(MAX_DRAWS):
            data = draw_variant(problem, base, ranges, rng, keyed, variant_id=variant_id,
                                title=f"{problem.title} ({student.id})",
                                source=f"gyro vary {source} --roster --seed "
                                       f"{self.seed}: student {student.id}",
                                solved=solved)
            if data is not None:
                break
        else:
            raise InputError(f"no draw of {MAX_DRAWS} for student {student.id!r} has "
                             "a real solution; narrow the ranges in `vary`",
                             file=problem.file, key="vary")
        text = (f"# Generated by `gyro vary {source} --roster --seed {self.seed}`: "
                f"the variant of student {' '.join(student.id.split())!r}.\n"
                + variant_yaml(data, shared))
        entry = {"problem": problem.id, "sha256": file_digest(text),
                 "answers": {n: _answer_entry(a) for n, a in solved[-1].answers.items()}}
        return f"{stem}/{self.names[student.id]}.yaml", text, variant_id, entry

    def _pooled(self, jobs: int, into: StagedFolder | None) -> Iterator[Variant]:
        """`draw` by ``jobs`` forked workers. Bad input found by a worker (a student with
        no real draw, a file it cannot write) is raised here, as it would be in this
        process."""
        from ..checking import pool

        made: Shared = {}

        def work(which: str) -> tuple[Any, ...]:
            p, s = map(int, which.split())
            try:
                name, text, variant_id, entry = self._variant(p, s, made)
                if into is not None:
                    into.write_now(name, text)
                    return name, None, variant_id, entry
                return name, text, variant_id, entry
            except InputError as err:
                return (None, err.message, err.file, err.key)

        def ended(which: str, code: Any) -> tuple[Any, ...]:
            raise RuntimeError(f"a process drawing the variants ended (exit {code}) at "
                               f"variant {which}")

        variants = [f"{p} {s}" for p in range(len(self.problems))
                    for s in range(len(self.students))]
        for drawn in pool.pooled(variants, work, jobs, None, ended, ended):
            if drawn[0] is None:
                raise InputError(drawn[1], file=drawn[2], key=drawn[3])
            yield drawn  # type: ignore[misc]

    def assignment(self) -> Iterator[str]:
        """assignment.csv, a student at a time: student, problem, variant, file, then the
        roster's other columns (by student, each student's problems in order)."""
        extra_columns = list(dict.fromkeys(k for s in self.students for k in s.extra))
        out = io.StringIO()
        writer = csv.writer(out, lineterminator="\n")
        writer.writerow(list(ASSIGNMENT_COLUMNS) + extra_columns)
        for student in self.students:
            for problem, _, stem in self.problems:
                row = [student.id, problem.id, self.ids[(problem.id, student.id)],
                       f"{stem}/{self.names[student.id]}.yaml"] \
                    + [student.extra.get(c, "") for c in extra_columns]
                writer.writerow([safe_cell(c) for c in row])
            yield out.getvalue()
            out.seek(0)
            out.truncate()


_PLAIN = (str, int, float, bool, type(None))


def _answer_entry(answer: Any) -> dict[str, Any]:
    """``dataclasses.asdict(answer)`` of a solver's answer, made directly where every field
    is a plain value or a list of them (as it is: a tenth of drawing a variant otherwise)."""
    import dataclasses

    entry = {}
    for name in answer.__dataclass_fields__:
        value = getattr(answer, name)
        if value.__class__ is list and all(v.__class__ in _PLAIN for v in value):
            value = list(value)
        elif value.__class__ not in _PLAIN:
            return dataclasses.asdict(answer)
        entry[name] = value
    return entry


def _keyed(problem: Any) -> list[str]:
    """The answers a variant's `expected` gives: the file's expected ones, else its find."""
    return [name for name in problem.expected if problem.kind.answer(name) is not None] \
        or list(problem.find)  # not `steps` nor a step asked (`steps:`)


def roster_set(paths: list[str], roster: str, seed: int) -> RosterSet:
    """The set of ``paths`` for the students of ``roster`` (bad input found before anything
    is drawn: two files of one stem or one id, a `vary` block that is not one)."""
    from ..solving.problem import load

    students = read_roster(roster)
    stems: dict[str, str] = {}
    problems: list[tuple[Any, list, str]] = []
    for path in paths:
        problem = load(path)
        try:
            ranges = parse_vary(problem)
        except InputError as err:
            raise err.located(file=path, line=problem.line(err.key)) from None
        stem = os.path.splitext(os.path.basename(path))[0]
        if stem in stems:
            raise InputError(f"two problem files named {stem}.yaml ({stems[stem]} and {path}); "
                             "rename one", file=path)
        stems[stem] = path
        if any(p.id == problem.id for p, _, _ in problems):
            raise InputError(f"problem id {problem.id!r} is also in another file given",
                             file=path, key="id")
        problems.append((problem, ranges, stem))
    ids = variant_ids([p.id for p, _, _ in problems], [s.id for s in students])
    return RosterSet(problems, students, file_names([s.id for s in students]), ids, seed)


class KeyWriter:
    """key.json written as the variants come: its text goes to a temporary file, and its
    digest (`checking.assignment.key_digest`: canonical JSON, keys sorted) is computed at
    the end over the variants' canonical texts, read back in the order of their ids. The
    bytes are those of ``json.dumps(key)`` and the digest that of ``key_digest(key)``."""

    FLUSH = 1 << 20  # bytes held before they go to the temporary files

    def __init__(self, head: dict[str, Any]) -> None:
        import tempfile

        self.head = head  # format, code, seed, problems
        self.text: IO[bytes] = tempfile.TemporaryFile()
        self.canonical: IO[bytes] = tempfile.TemporaryFile()
        self.index: list[tuple[str, int, int]] = []  # variant id, offset, length
        # The pieces not yet written, and the canonical file's length once they are: a
        # write and a tell per variant were 40,000 system calls for a class of 10,000.
        self.held: list[bytes] = []
        self.held_canonical: list[bytes] = []
        self.size = self.held_size = 0
        self.held.append((_KEY_TEXT.encode(head)[:-1] + ', "variants": {').encode())

    def add(self, variant_id: str, entry: dict[str, Any]) -> None:
        piece = _KEY_TEXT.encode({variant_id: entry})[1:-1]
        self.held.append(((", " if self.index else "") + piece).encode())
        canon = canonical_json({variant_id: entry})[1:-1].encode()
        self.index.append((variant_id, self.size, len(canon)))
        self.size += len(canon)
        self.held_canonical.append(canon)
        self.held_size += len(canon) + len(piece)
        if self.held_size > self.FLUSH:
            self._flush()

    def _flush(self) -> None:
        self.text.write(b"".join(self.held))
        self.canonical.write(b"".join(self.held_canonical))
        self.held.clear()
        self.held_canonical.clear()
        self.held_size = 0

    def digest(self) -> str:
        import hashlib

        self._flush()
        digest = hashlib.sha256((canonical_json(self.head)[:-1] + ',"variants":{').encode())
        for n, (_, offset, length) in enumerate(sorted(self.index)):
            self.canonical.seek(offset)
            digest.update((b"," if n else b"") + self.canonical.read(length))
        digest.update(b"}}")
        return digest.hexdigest()

    def chunks(self) -> Iterator[bytes]:
        """key.json: what was written, then the digest."""
        tail = f'}}, "digest": {json.dumps(self.digest())}}}'.encode()
        self.text.seek(0)
        while True:
            data = self.text.read(1 << 20)
            if not data:
                break
            yield data
        yield tail


# The encoder of ``json.dumps(..., allow_nan=False)``, made once (json.dumps makes one a
# call when given any option); the canonical one is `checking.assignment.canonical_json`.
_KEY_TEXT = json.JSONEncoder(allow_nan=False)


def roster_variants(paths: list[str], roster: str, seed: int
                    ) -> tuple[list[tuple[str, str]], str, str]:
    """Every (relative file name, YAML text) of the set, the assignment CSV's text and the
    key's (key.json: each variant's answers as the solver gave them, with the hash of its
    file, so grading need not read and solve 10,000 files again), held in memory
    (`gyro handout --roster`; `write_roster_variants` streams them)."""
    made = roster_set(paths, roster, seed)
    key = KeyWriter(_key_head(made))
    files = []
    for name, text, variant_id, entry in made.draw():
        assert text is not None, "drawn without a folder to write into: the text comes back"
        files.append((name, text))
        key.add(variant_id, entry)
    return files, "".join(made.assignment()), b"".join(key.chunks()).decode()


def _key_head(made: RosterSet) -> dict[str, Any]:
    return {"format": KEY_FORMAT, "code": code_fingerprint(), "seed": made.seed,
            "problems": made.key_problems()}


def write_roster_variants(paths: list[str], roster: str, seed: int, out_dir: str,
                          force: bool, jobs: int = 1) -> list[str]:
    """Write the set and ``out_dir/assignment.csv``; nothing over an existing file without
    ``force`` (checked before anything is drawn). Each variant is written (to a temporary
    file) as it is drawn, so 10,000 students need not be held in memory; the set is placed
    whole or not at all (core/files.py: StagedSet, or StagedFolder for a new ``out_dir``),
    and never over one of its inputs. ``jobs``: workers drawing the set (`RosterSet.draw`)."""
    import contextlib

    from ..core.files import StagedFolder, StagedSet, refuse_outputs_over_inputs

    made = roster_set(paths, roster, seed)
    if os.path.exists(out_dir) and not os.path.isdir(out_dir):
        raise InputError("exists and is not a directory", file=out_dir)
    targets = [os.path.join(out_dir, name) for name in made.files()]
    targets += [os.path.join(out_dir, "key.json"), os.path.join(out_dir, "assignment.csv")]
    new_folder = bool(out_dir.strip()) and not os.path.lexists(out_dir)
    if not new_folder:
        refuse_outputs_over_inputs(targets, [*paths, roster], option="a variant",
                                   yaml_output=True)
        if not force:
            clash = [t for t in targets if os.path.lexists(t)]
            if clash:
                raise InputError(f"exists; not overwritten (use --force to replace it; "
                                 f"{len(clash)} file(s) of the set already there)",
                                 file=clash[0])
    key = KeyWriter(_key_head(made))
    staged: StagedFolder | StagedSet
    if new_folder:
        staged = StagedFolder(out_dir)  # no file of the set, nor an input, in it
    else:
        staged = StagedSet(force, out_dir, targets, sync_each=False)
    with staged:
        # the workers, if any, are forked at the first variant, before the staged folder's
        # writer thread starts (at the first file handed to it); they write into the
        # staged folder, so they are ended (closing) before it is removed or placed
        drawn = made.draw(jobs, staged if isinstance(staged, StagedFolder) else None)
        with contextlib.closing(drawn):
            for name, text, variant_id, entry in drawn:
                if text is not None:
                    staged.add(os.path.join(out_dir, name), text)
                key.add(variant_id, entry)
        staged.add(targets[-2], key.chunks())
        staged.add(targets[-1], made.assignment())
        staged.place()
    return targets
