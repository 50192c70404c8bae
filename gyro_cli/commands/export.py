"""`gyro export`: question banks for Moodle, QTI 1.2 (Canvas, D2L), Blackboard Learn
(an Upload Questions file) and PrairieLearn, every answer from the solver.

For each problem file: the problem as written, or with ``--variants N`` the N
variants that ``gyro vary FILE --count N --seed S`` writes (the same values, drawn
by the same code). Each is solved as ``gyro solve`` solves it (in US units when
the file says ``units: us``) and becomes a `render.bank.Variant`: the question
text, the worked answer as HTML, and one blank per number in the answers the file
asks for (``find`` and ``expected``), with the problem's tolerance around the
solver's value. Word answers (``motion: cusps``) are not asked. The renderers in
``render/bank_*.py`` write the files; nothing here or there computes an answer
of its own.

See docs/course.md ("Question banks") for importing the result.
"""

from __future__ import annotations

import os
import sys
from typing import TYPE_CHECKING, Any, Callable

import click

from ..core.errors import InputError

if TYPE_CHECKING:
    from ..render.bank import Blank, ProblemBank, Variant
    from ..solving.problem import Problem

FORMATS = ("moodle", "qti", "blackboard", "prairielearn")
#: the formats written as one file
FILE_FORMATS = ("moodle", "qti", "blackboard")


# ---- building the banks ----------------------------------------------------------

def _variants_of(path: str, count: int, seed: int,
                 unvaried: list[str]) -> tuple["Problem", list["Problem"]]:
    """The problem of ``path`` and the problems to export: itself, or its variants
    (a file without `vary` is added to ``unvaried`` and exported as written)."""
    from ..solving.problem import build, load, parse_yaml
    from .authoring import variants

    problem = load(path)
    if count == 1:
        return problem, [problem]
    if problem.vary is None:
        unvaried.append(path)
        return problem, [problem]
    out = []
    for name, text in variants(path, count, seed):
        data, lines = parse_yaml(text, name)
        out.append(build(f"{path} ({name})", data, lines))
    return problem, out


def _scale(value: float, si: float, unit: str, dimension: str) -> float:
    """SI per unit of ``unit`` (from the answer itself, else from the unit)."""
    if value and si and value == value and si == si:
        return si / value
    from ..core import units

    try:
        return units.parse(f"1 {unit}", dimension, "find")[0] if unit else 1.0
    except InputError:
        return 1.0


def _blanks(problem: "Problem", solved: Any) -> list["Blank"]:
    """One blank per numeric value of the answers the problem asks for."""
    from ..checking.tolerance import tolerance_for
    from ..render.bank import Blank, slug

    names = [a.name for a in problem.kind.answers]
    out = []
    for name, answer in solved.answers.items():
        spec = problem.kind.answer(name)
        if spec is None or spec.dimension is None:
            continue  # a word answer: not asked
        tol = tolerance_for(problem.tolerance, name, spec.dimension, names)
        several = len(answer.values) > 1
        for i, (value, si) in enumerate(zip(answer.values, answer.si_values)):
            if isinstance(value, str):
                continue
            label = answer.labels[i] if i < len(answer.labels) and answer.labels[i] else ""
            key = name if not several else \
                f"{name}_{slug(label).replace('-', '_').lower() if label else i + 1}"
            words = name.replace("_", " ")
            text = f"{words} ({label})" if label else (f"{words} ({i + 1})" if several else words)
            if tol.magnitude:  # the book quotes a magnitude: ask for it
                value, si, text = abs(value), abs(si), f"magnitude of {text}"
            unit = answer.unit or ""
            scale = _scale(value, si, unit, spec.dimension)
            half = tol.half_width(si, value) / abs(scale)
            fraction = tol.value if tol.form != "absolute" else half
            out.append(Blank(key, text, float(value), unit, half, tol.text, tol.form, fraction))
    return out


def _with_expected(problem: "Problem") -> "Problem":
    """The problem asking also for every answer it has an expected value of."""
    import dataclasses

    find = dict(problem.find)
    for name in problem.expected:
        find.setdefault(name, None)
    return dataclasses.replace(problem, find=find)


def _data_lines(solved: Any) -> list[tuple[str, str]]:
    return [(g.key.replace("_", " "), g.text.replace("_", " ")
             + (f" ({g.note})" if g.note else "")) for g in solved.solution.given]


def variant_of(problem: "Problem", number: int, title: str) -> "Variant":
    """One problem solved and laid out as a bank's variant; its question text is its
    `statement` filled from its own given values (core/statement.py), else a sentence
    built from ``title``, its data and what is asked."""
    import dataclasses

    from ..render import html
    from ..render.bank import Variant, blank_prompt, statement_html
    from ..solving.solve import solve

    problem = _with_expected(problem)
    solved = solve(problem)
    if problem.units == "us":
        from ..render.us_units import to_us

        solved = to_us(solved)
    blanks = _blanks(problem, solved)
    given = {str(k): v if isinstance(v, str) else str(v)
             for k, v in (problem.data.get("given") or {}).items()}
    text = statement_html(problem.statement_text() or None, title, _data_lines(solved),
                          [blank_prompt(b) for b in blanks])
    # The page's anchors come from the file's path, which has no business in a bank: from
    # the problem id instead (11/3-v02 -> p-11-3-v02).
    shown = dataclasses.replace(solved, problem=dataclasses.replace(solved.problem, file=""))
    feedback = f'<div class="gyro">{html.worked_answer(shown, level=3, picture=False)}</div>'
    words = [name for name, answer in solved.answers.items()
             if getattr(problem.kind.answer(name), "dimension", None) is None
             or any(isinstance(v, str) for v in answer.values)]
    return Variant(number, str(problem.id), given, text, feedback, blanks, words)


def banks(paths: list[str] | tuple[str, ...], count: int = 1, seed: int = 0,
          warn: Callable[[str], None] = lambda line: None
          ) -> tuple[list["ProblemBank"], list[str]]:
    """The bank of every problem file in ``paths`` (files, directories, globs), and one
    line per file that could not be exported (bad input)."""
    from ..render.bank import ProblemBank, slug
    from ..solving.paths import problem_files

    files, missing = problem_files(paths)
    errors = [message for _, message in missing]
    out: list[ProblemBank] = []
    slugs: set[str] = set()
    ids: dict[str, str] = {}  # problem id -> the file it was exported from
    unvaried: list[str] = []
    worded: list[str] = []                # files with word answers
    words: dict[str, None] = {}           # their names, in order ("motion", "effect")
    for path in files:
        try:
            problem, problems = _variants_of(path, count, seed, unvaried)
            if str(problem.id) in ids:
                # One id, one category / QTI ident / PrairieLearn UUID: a second file with
                # the same id would mix its variants with the first one's.
                raise InputError(f"id {str(problem.id)!r} is already exported from "
                                 f"{ids[str(problem.id)]}; ids must differ within a bank",
                                 key="id", line=problem.line("id"))
            variants = [variant_of(p, n, problem.title) for n, p in enumerate(problems, 1)]
        except InputError as err:
            errors.append(str(err.located(file=path)))
            continue
        if not any(v.blanks for v in variants):
            warn(f"{path}: no numeric answer to ask (word answers are not exported); skipped")
            continue
        ids[str(problem.id)] = path
        if any(v.unasked for v in variants):
            worded.append(path)
            for variant in variants:
                words.update(dict.fromkeys(variant.unasked))
        name = slug(os.path.splitext(os.path.basename(path))[0])
        unique, n = name, 2
        while unique in slugs:
            unique, n = f"{name}-{n}", n + 1
        slugs.add(unique)
        out.append(ProblemBank(str(problem.id), problem.title, problem.kind.name,
                               problem.source, unique, problem.kind.name.replace("_", " "),
                               [v for v in variants if v.blanks]))
    if unvaried:
        warn(f"{len(unvaried)} file(s) have no `vary` block and give one variant, the problem "
             f"as written: {_some(unvaried)}")
    if worded:
        warn(f"{len(worded)} file(s) have word answers ({', '.join(words)}), not asked (a bank "
             f"asks numbers): {_some(worded)}")
    return out, errors


def _some(paths: list[str]) -> str:
    return ", ".join(paths[:3]) + (f" and {len(paths) - 3} more" if len(paths) > 3 else "")


# ---- writing -----------------------------------------------------------------------

def write(banks_: list["ProblemBank"], fmt: str, out: str, force: bool,
          inputs: list[str] | tuple[str, ...] = ()) -> list[str]:
    """Write the export to ``out`` (a file for moodle, qti and blackboard, a directory
    for prairielearn): never one of the ``inputs`` (the problem files), never a file that
    exists without ``force``, and the question directories all or nothing. The paths
    written."""
    from ..core.files import refuse_input_as_output, write_atomic, write_set

    if fmt in FILE_FORMATS:
        _refuse_directory(out)
        refuse_input_as_output(out, inputs, option="--output")
        if fmt == "moodle":
            from ..render import bank_moodle

            return [str(write_atomic(out, bank_moodle.xml(banks_), force=force))]
        if fmt == "blackboard":
            from ..render import bank_blackboard

            return [str(write_atomic(out, bank_blackboard.text(banks_), force=force))]
        from ..render import bank_qti

        return [str(write_atomic(out, bank_qti.package(banks_), force=force))]
    from ..render import bank_prairielearn

    if os.path.exists(out) and not os.path.isdir(out):
        raise InputError("exists and is not a directory (PrairieLearn questions are "
                         "directories: give the course's questions/ folder or a new one)",
                         file=out)
    items = [(os.path.join(out, rel), text)
             for rel, text in bank_prairielearn.files(banks_).items()]
    for target, _ in items:
        refuse_input_as_output(target, inputs, option="--output", yaml_output=True)
    if not force:
        clash = [target for target, _ in items if os.path.lexists(target)]
        if clash:
            raise InputError(f"exists; not overwritten (use --force to replace it; {len(clash)} "
                             "file(s) of this export already there)", file=clash[0])
    for target, _ in items:
        os.makedirs(os.path.dirname(target), exist_ok=True)
    return [str(path) for path in write_set(items, force=force)]


def _refuse_directory(out: str) -> None:
    if os.path.isdir(out):
        raise InputError("is a directory; give the file to write (a .xml for moodle, a .zip "
                         "for qti, a .txt for blackboard)", file=out)


def _blackboard_notes(made: list["ProblemBank"], warn: Callable[[str], None]) -> None:
    """What a Blackboard upload file lacks: more lines than Blackboard recommends per
    upload, and the worked answers (no feedback field in a NUM line)."""
    from ..render.bank_blackboard import RECOMMENDED_RECORDS

    records = sum(len(v.blanks) for b in made for v in b.variants)
    if records > RECOMMENDED_RECORDS:
        warn(f"{records} questions: Blackboard recommends at most {RECOMMENDED_RECORDS} per "
             "uploaded file (browser time-outs); export fewer problems per file "
             "(docs/course.md, Blackboard Learn)")
    warn("a Blackboard upload file has no feedback field: the worked answers are not in it")


# ---- the command --------------------------------------------------------------------

@click.command("export")
@click.argument("files", nargs=-1, required=True, metavar="FILES|DIRS")
@click.option("--to", "fmt", type=click.Choice(FORMATS), required=True,
              help="moodle: Moodle XML (a category per problem); qti: a QTI 1.2 zip for "
                   "Canvas and D2L; blackboard: a Blackboard Learn Upload Questions "
                   "file (one NUM question per number asked); prairielearn: a "
                   "question directory per problem.")
@click.option("--variants", "count", type=click.IntRange(1, 10_000), default=1,
              show_default=True,
              help="Variants per problem, drawn from its `vary:` block as `gyro vary` "
                   "draws them (1: the problem as written).")
@click.option("--seed", type=int, default=0, show_default=True,
              help="Random seed of the variants (as gyro vary --seed).")
@click.option("-o", "--output", "out", metavar="OUT", required=True,
              help="The file to write (moodle: .xml, qti: .zip, blackboard: .txt) or, for "
                   "prairielearn, the directory to write the question directories into.")
@click.option("--force", is_flag=True, help="Replace files of OUT that exist.")
def export(files: tuple[str, ...], fmt: str, count: int, seed: int, out: str,
           force: bool) -> None:
    """Export problem FILES as a question bank whose every answer is gyro's.

    FILES may be directories (every *.yaml and *.yml in them) or quoted globs.
    Exit 0 when every file was exported, 2 when one was bad (the others are
    still exported).
    """
    def warn(line: str) -> None:
        click.echo(f"gyro: {line}", err=True)

    from ..solving.paths import problem_files

    made, errors = banks(files, count, seed, warn)
    for line in errors:
        warn(line)
    if not made:
        warn("nothing to export")
        sys.exit(2)
    try:
        written = write(made, fmt, out, force, problem_files(files)[0])
    except InputError as err:
        warn(str(err))
        sys.exit(2)
    questions = sum(len(b.variants) for b in made)
    shown = out if fmt != "prairielearn" else f"{out} ({len(written)} files)"
    if fmt == "blackboard":
        _blackboard_notes(made, warn)
        shown += f" ({sum(len(v.blanks) for b in made for v in b.variants)} NUM questions)"
    click.echo(f"wrote {shown}: {len(made)} problem(s), {questions} variant(s)", err=True)
    if errors:
        sys.exit(2)
