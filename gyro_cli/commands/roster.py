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
import os
import random
from typing import Any

from ..checking.assignment import (ASSIGNMENT_COLUMNS, KEY_FORMAT, code_fingerprint,
                                   file_digest, file_names, key_digest, read_roster)
from ..core.csvsafe import safe_cell
from ..core.errors import InputError
from .authoring import draw_variant, parse_vary, variant_yaml

MAX_DRAWS = 200  # per student and problem, before the ranges are called too wide


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


def roster_variants(paths: list[str], roster: str, seed: int
                    ) -> tuple[list[tuple[str, str]], str, str]:
    """Every (relative file name, YAML text) of the set, the assignment CSV's text and the
    key's (key.json: each variant's answers as the solver gave them, with the hash of its
    file, so grading need not read and solve 10,000 files again)."""
    import dataclasses
    import json

    from ..solving.problem import load

    students = read_roster(roster)
    names = file_names([s.id for s in students])
    extra_columns = list(dict.fromkeys(k for s in students for k in s.extra))
    files: list[tuple[str, str]] = []
    out = io.StringIO()
    writer = csv.writer(out, lineterminator="\n")
    writer.writerow(list(ASSIGNMENT_COLUMNS) + extra_columns)
    stems: dict[str, str] = {}
    problems = []
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
    rows = []
    ids = variant_ids([p.id for p, _, _ in problems], [s.id for s in students])
    key: dict[str, Any] = {"format": KEY_FORMAT, "code": code_fingerprint(), "seed": seed,
                           "problems": {}, "variants": {}}
    for problem, ranges, stem in problems:
        base = copy.deepcopy(problem.data)
        base.pop("vary", None)
        keyed = list(problem.expected) or list(problem.find)
        key["problems"][problem.id] = {
            "kind": problem.kind.name, "tolerance": problem.tolerance,
            "questions": list(dict.fromkeys(list(problem.find) + keyed))}
        source = os.path.basename(problem.file)
        for student in students:
            rng = student_rng(seed, problem.id, student.id)
            variant_id = ids[(problem.id, student.id)]
            solved: list[Any] = []
            for _ in range(MAX_DRAWS):
                data = draw_variant(problem, base, ranges, rng, keyed, variant_id=variant_id,
                                    title=f"{problem.title} ({student.id})",
                                    source=f"gyro vary {source} --roster --seed {seed}: "
                                           f"student {student.id}", solved=solved)
                if data is not None:
                    break
            else:
                raise InputError(f"no draw of {MAX_DRAWS} for student {student.id!r} has a "
                                 "real solution; narrow the ranges in `vary`",
                                 file=problem.file, key="vary")
            name = f"{stem}/{names[student.id]}.yaml"
            text = (f"# Generated by `gyro vary {source} --roster --seed {seed}`: "
                    f"the variant of student {' '.join(student.id.split())!r}.\n"
                    + variant_yaml(data))
            files.append((name, text))
            key["variants"][variant_id] = {
                "problem": problem.id, "sha256": file_digest(text),
                "answers": {n: dataclasses.asdict(a) for n, a in solved[-1].answers.items()}}
            rows.append([student.id, problem.id, variant_id, name]
                        + [student.extra.get(c, "") for c in extra_columns])
    order = {s.id: k for k, s in enumerate(students)}
    rows.sort(key=lambda r: order[r[0]])  # by student, each student's problems in order
    for row in rows:
        writer.writerow([safe_cell(c) for c in row])
    key["digest"] = key_digest(key)  # covers the answers: an edited key is not used
    return files, out.getvalue(), json.dumps(key, allow_nan=False)


def write_roster_variants(paths: list[str], roster: str, seed: int, out_dir: str,
                          force: bool) -> list[str]:
    """Write the set and ``out_dir/assignment.csv``; nothing over an existing file without
    ``force`` (checked before anything is written). The set is written whole or not at
    all (core/files.py: write_set), and never over one of its inputs."""
    from ..core.files import refuse_outputs_over_inputs, write_set_in

    files, assignment, key = roster_variants(paths, roster, seed)
    if os.path.exists(out_dir) and not os.path.isdir(out_dir):
        raise InputError("exists and is not a directory", file=out_dir)
    targets = [(os.path.join(out_dir, name), text) for name, text in files]
    targets.append((os.path.join(out_dir, "key.json"), key))
    targets.append((os.path.join(out_dir, "assignment.csv"), assignment))
    refuse_outputs_over_inputs([target for target, _ in targets], [*paths, roster],
                               option="a variant", yaml_output=True)
    if not force:
        clash = [t for t, _ in targets if os.path.lexists(t)]
        if clash:
            raise InputError(f"exists; not overwritten (use --force to replace it; {len(clash)} "
                             "file(s) of the set already there)", file=clash[0])
    write_set_in(out_dir, targets, force=force)
    return [target for target, _ in targets]
