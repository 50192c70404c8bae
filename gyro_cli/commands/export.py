"""`gyro export`: question banks for Moodle, QTI 1.2 (Canvas, D2L), Blackboard Learn
(an Upload Questions file) and PrairieLearn, every answer from the solver.

For each problem file: the problem as written, or with ``--variants N`` the N
variants that ``gyro vary FILE --count N --seed S`` writes (the same values, drawn
by the same code). Each is solved as ``gyro solve`` solves it (in US units when
the file says ``units: us``) and becomes a `render.bank.Variant`: the question
text, the worked answer as HTML, and one blank per number in the answers asked
(``--ask``, else the file's ``ask``, else ``find`` and ``expected``), each with
its own key. A blank accepts the problem's tolerance around the solver's value,
unless that is tighter than the value printed to 4 significant figures (what
the question asks for): then the student tolerance (``--tolerance``). A word
answer (``motion: cusps``) is a multiple choice among its kind's words
(``AnswerSpec.words``); with ``--pictures`` the worked answer's picture goes with
the feedback as a PNG. The renderers in
``render/bank_*.py`` write the files; nothing here or there computes an answer
of its own.

See docs/course.md ("Question banks") for importing the result.
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterator
from typing import TYPE_CHECKING, Any

import click

from ..checking.tolerance import STUDENT_TOLERANCE
from ..core.errors import InputError

if TYPE_CHECKING:
    from ..checking.tolerance import Tolerance
    from ..render.bank import Blank, Choice, ProblemBank, Variant
    from ..render.bank_stream import PrairieLearnSink, Sink
    from ..solving.problem import Problem

FORMATS = ("moodle", "qti", "blackboard", "prairielearn")
#: the share of a point for a carried error in a PrairieLearn question (--ecf)
DEFAULT_ECF = 0.5
#: a blank's value below this (in its unit) may not be told from 0 on a platform
TINY = 1e-9
#: the formats written as one file
FILE_FORMATS = ("moodle", "qti", "blackboard")

# ---- building the banks ----------------------------------------------------------

def _variants_of(path: str, count: int, seed: int,
                 unvaried: list[str]) -> tuple[Problem, Iterator[Problem]]:
    """The problem of ``path`` and the problems to export, one at a time: itself, or its
    variants (a file without `vary` is added to ``unvaried`` and exported as written)."""
    from ..solving.problem import load

    problem = load(path)
    if count == 1:
        return problem, iter([problem])
    if problem.vary is None:
        unvaried.append(path)
        return problem, iter([problem])
    return problem, _drawn(path, count, seed)


def _drawn(path: str, count: int, seed: int) -> Iterator[Problem]:
    from ..solving.problem import build, parse_yaml
    from .authoring import each_variant

    for name, text in each_variant(path, count, seed):
        data, lines = parse_yaml(text, name)
        yield build(f"{path} ({name})", data, lines)


def _scale(value: float, si: float, unit: str, dimension: str) -> float:
    """SI per unit of ``unit`` (from the answer itself, else from the unit)."""
    if value and si and value == value and si == si:
        return si / value
    from ..core import units

    try:
        return units.parse(f"1 {unit}", dimension, "find")[0] if unit else 1.0
    except InputError:
        return 1.0


def _asked(problem: Problem, ask: tuple[str, ...] | None) -> list[str]:
    """The answers a bank asks: ``--ask`` (those this problem finds), else what its
    statement asks (`solving.problem.asked`)."""
    from ..solving.problem import answer_names, asked

    if ask is not None:
        return [name for name in answer_names(problem) if name in ask]
    return asked(problem)


def _key(name: str, label: str, index: int, several: bool, answers: set[str],
         used: set[str]) -> str:
    """A blank's key, unique in its variant: ``precession_slow`` for the slow root of
    ``precession``, unless an answer of that name is asked too (then
    ``precession_1_slow``), and never one already used."""
    from ..render.bank import slug

    if not several:
        key = name
    else:
        tail = slug(label).replace("-", "_").lower() if label else str(index + 1)
        key = f"{name}_{tail}"
        if key in answers and key != name or key in used:
            key = f"{name}_{index + 1}" + (f"_{tail}" if label else "")
    base, n = key, 2
    while key in used:
        key, n = f"{base}_{n}", n + 1
    used.add(key)
    return key


def _blanks(problem: Problem, solved: Any, asked: list[str], student: Tolerance,
            tight: list[str], used: set[str], parts: list | None = None) -> list[Blank]:
    """One blank per numeric value of the answers asked. Each accepts the value as the
    worked answer prints it (core.expr.SIG significant figures): where the problem's tolerance
    is tighter than that, the student tolerance (``student``) is used and the answer's name
    added to ``tight``."""
    from ..checking.tolerance import student_width, tolerance_for
    from ..core.expr import SIG as digits
    from ..render.bank import Blank

    names = [a.name for a in problem.kind.answers]
    out: list[Blank] = []
    for name, answer in solved.answers.items():
        spec = problem.kind.answer(name)
        if spec is None or spec.dimension is None or name not in asked:
            continue  # a word answer (not asked as a number), or one not asked
        tol = tolerance_for(problem.tolerance, name, spec.dimension, names)
        several = len(answer.values) > 1
        for i, (value, si) in enumerate(zip(answer.values, answer.si_values)):
            if isinstance(value, str):
                continue
            label = answer.labels[i] if i < len(answer.labels) and answer.labels[i] else ""
            key = _key(name, label, i, several, set(asked), used)
            words = name.replace("_", " ")
            text = f"{words} ({label})" if label else (f"{words} ({i + 1})" if several else words)
            if tol.magnitude:  # the book quotes a magnitude: ask for it
                value, si, text = abs(value), abs(si), f"magnitude of {text}"
            unit = answer.unit or ""
            scale = _scale(value, si, unit, spec.dimension)
            half, used_tol = student_width(tol, student, float(value),
                                    tol.half_width(si, value) / abs(scale), digits)
            if used_tol is student and value:
                tight.append(name)
            fraction = used_tol.value if used_tol.form != "absolute" else half
            out.append(Blank(key, text, float(value), unit, half, tol.text, used_tol.form,
                             fraction, accepts=accepts(used_tol, half, unit),
                             digits=digits))
            if parts is not None:  # what each blank is, for errors carried forward
                from ..checking.ecf import Part

                parts.append(Part(key, name, i, False, unit, spec.dimension, tol.magnitude))
    return out


def _step_blanks(problem: Problem, solved: Any, student: Tolerance, used: set[str],
                 parts: list) -> list[Blank]:
    """One blank per step the problem asks (`steps:`), in SI, before the answers."""
    from ..checking.ecf import Part, step_names, step_tolerance
    from ..checking.tolerance import student_width
    from ..core.expr import SIG as digits
    from ..render.bank import Blank, slug

    out: list[Blank] = []
    steps = step_names(solved)
    for symbol in problem.steps:
        value, unit, dimension = steps[symbol]
        tol = step_tolerance(problem, symbol, dimension)
        key = _key("step_" + slug(symbol).replace("-", "_"), "", 0, False, set(), used)
        half, used_tol = student_width(tol, student, value, tol.half_width(value, value), digits)
        fraction = used_tol.value if used_tol.form != "absolute" else half
        out.append(Blank(key, f"{symbol} (a step of the working)", float(value), unit, half,
                         tol.text, used_tol.form, fraction,
                         accepts=accepts(used_tol, half, unit), digits=digits))
        parts.append(Part(key, symbol, 0, True, unit, dimension))
    return out


def _choices(problem: Problem, solved: Any, asked: list[str], used: set[str]
             ) -> list[Choice]:
    """One multiple-choice question per word of the word answers asked whose kind names
    their possible words (AnswerSpec.words): those words, the solver's among them."""
    from ..render.bank import Choice

    out: list[Choice] = []
    for name, answer in solved.answers.items():
        spec = problem.kind.answer(name)
        if spec is None or not spec.words or name not in asked:
            continue
        words = [v for v in answer.values if isinstance(v, str)]
        for i, word in enumerate(words):
            label = answer.labels[i] if i < len(answer.labels) and answer.labels[i] else ""
            key = _key(name, label, i, len(words) > 1, set(asked), used)
            text = name.replace("_", " ") + (f" ({label})" if label else
                                             f" ({i + 1})" if len(words) > 1 else "")
            shown = word.replace("_", " ")
            choices = tuple(dict.fromkeys([*spec.words, shown]))
            out.append(Choice(key, text, choices, shown))
    return out


def accepts(tol: Tolerance, half: float, unit: str) -> str:
    """What a blank accepts, in words: ``within 1%``, ``to 3 significant figures``,
    ``within 0.01 rad/s``."""
    from ..render.bank import number_text

    if tol.form == "relative":
        return f"within {100 * tol.value:g}%"
    if tol.form == "sig":
        return f"correct to {int(tol.value)} significant figures"
    return f"within {float(number_text(half)):.3g} {unit}".strip()


def _data_lines(solved: Any) -> list[tuple[str, str]]:
    return [(g.key.replace("_", " "), g.text.replace("_", " ")
             + (f" ({g.note})" if g.note else "")) for g in solved.solution.given]


def variant_of(problem: Problem, number: int, title: str,
               ask: tuple[str, ...] | None = None, student: Tolerance | None = None,
               tight: list[str] | None = None, pictures: bool = False,
               ecf_share: float = DEFAULT_ECF, parts_out: list | None = None) -> Variant:
    """One problem solved and laid out as a bank's variant; its question text is its
    `statement` filled from its own given values (core/statement.py), else a sentence
    built from ``title``, its data and what is asked, then the precision asked and the
    tolerance accepted. ``ask``: the answers to ask (``--ask``; None: the file's `ask`,
    else all); ``student``: the tolerance of a blank whose problem's is tighter than the
    printed answer (`_blanks`), whose answer names go to ``tight``; ``pictures``: draw the
    worked answer's picture (a released top's axis path, a bicycle's eigenvalues) as PNG;
    ``parts_out``: given a list, what each blank is (`checking.ecf.Part`) is added to it."""
    import dataclasses

    from ..checking.tolerance import parse_tolerance
    from ..render import html
    from ..render.bank import Variant, blank_prompt, precision_html, statement_html
    from ..solving.solve import asking, solve

    student = student or parse_tolerance(STUDENT_TOLERANCE, None, "--tolerance")
    asked = _asked(problem, ask)
    problem = asking(problem, [name for name in problem.expected  # every answer it has an
                               if problem.kind.answer(name) is not None])  # expected value of
    solved = si_solved = solve(problem)
    if problem.steps:
        from ..checking.ecf import check_steps

        check_steps(problem, solved)
    if problem.units == "us":
        from ..render.us_units import to_us

        solved = to_us(solved)
    used: set[str] = set()  # the keys given so far (numbers and choices share them)
    parts: list = []
    blanks = _step_blanks(problem, si_solved, student, used, parts) if problem.steps else []
    blanks += _blanks(problem, solved, asked, student, tight if tight is not None else [],
                      used, parts)
    choices = _choices(problem, solved, asked, used)
    if parts_out is not None:
        parts_out.extend(parts)
    given = {str(k): v if isinstance(v, str) else str(v)
             for k, v in (problem.data.get("given") or {}).items()}
    text = statement_html(problem.statement_text() or None, title, _data_lines(solved),
                          [blank_prompt(b) for b in blanks]
                          + [c.label for c in choices]) + precision_html(blanks)
    # The page's anchors come from the file's path, which has no business in a bank: from
    # the problem id instead (11/3-v02 -> p-11-3-v02).
    shown = dataclasses.replace(solved, problem=dataclasses.replace(solved.problem, file=""))
    feedback = f'<div class="gyro">{html.worked_answer(shown, level=3, picture=False)}</div>'
    words = [name for name, answer in solved.answers.items() if name in asked
             and not getattr(problem.kind.answer(name), "words", ()) and (
                 getattr(problem.kind.answer(name), "dimension", None) is None
                 or any(isinstance(v, str) for v in answer.values))]
    figure, alt = _picture(shown) if pictures else (b"", "")
    variant = Variant(number, str(problem.id), given, text, feedback, blanks, words, choices,
                      figure, alt)
    if problem.steps:  # errors carried forward across the blanks (PrairieLearn's grade())
        from ..checking.ecf import table

        variant.carry = {"share": ecf_share, "from": table(problem, si_solved, parts),
                         "labels": {p.key: p.name for p in parts if p.is_step}}
    return variant


def _lost_line(path: str, variant: Variant) -> str:
    """Which blanks of a problem follow from which steps (what a format without a
    question-wide grader loses)."""
    labels = {b.key: b.label for b in variant.blanks}
    parts = [f"{', '.join(labels[t] for t in table['to'])} from {labels[source]}"
             for source, table in variant.carry["from"].items()]
    return f"{path}: errors carried forward: {'; '.join(parts)}"


def _picture(solved: Any) -> tuple[bytes, str]:
    """The worked answer's picture as PNG and its alt text (b"" for a kind without one)."""
    from ..render.picture import png

    if not solved.problem.kind.picture:
        return b"", ""
    return png(solved) or (b"", "")


def banks(paths: list[str] | tuple[str, ...], count: int = 1, seed: int = 0,
          warn: Callable[[str], None] = lambda line: None,
          ask: tuple[str, ...] | None = None, tolerance: str = STUDENT_TOLERANCE,
          pictures: bool = False) -> tuple[list[ProblemBank], list[str]]:
    """The bank of every problem file in ``paths`` (files, directories, globs), and one
    line per file that could not be exported (bad input). ``ask``: the answers to ask
    (None: each file's `ask`, else all); ``tolerance``: the student tolerance (`_blanks`);
    ``pictures``: the worked answers' pictures as PNG files (`variant_of`)."""
    from ..render.bank_stream import Sink

    return stream(paths, Sink(), count, seed, warn, ask, tolerance, pictures)


def stream(paths: list[str] | tuple[str, ...], sink: Sink, count: int = 1, seed: int = 0,
           warn: Callable[[str], None] = lambda line: None,
           ask: tuple[str, ...] | None = None, tolerance: str = STUDENT_TOLERANCE,
           pictures: bool = False, ecf_share: float = 0.5, lost: list[str] | None = None
           ) -> tuple[list[ProblemBank], list[str]]:
    """`banks`, each variant handed to ``sink`` as it is solved (render/bank_stream.py)
    instead of held: the banks as the sink commits them (without their variants, for a
    sink that writes them out) and the lines of the files that could not be exported."""
    from ..render.bank import ProblemBank, slug
    from ..solving.paths import problem_files

    student = _student_tolerance(tolerance)
    files, missing = problem_files(paths)
    errors = [message for _, message in missing]
    out: list[ProblemBank] = []
    slugs: set[str] = set()
    ids: dict[str, str] = {}  # problem id -> the file it was exported from
    unvaried: list[str] = []
    worded: list[str] = []                # files with word answers
    words: dict[str, None] = {}           # their names, in order ("motion", "effect")
    tightened: list[str] = []             # files whose tolerance is below the printed figures
    tiny: dict[str, str] = {}              # blanks too small for a platform: text -> file
    answered: set[str] = set()            # the answers the files find (for --ask)
    for path in files:
        try:
            problem, problems = _variants_of(path, count, seed, unvaried)
            if str(problem.id) in ids:
                # One id, one category / QTI ident / PrairieLearn UUID: a second file with
                # the same id would mix its variants with the first one's.
                raise InputError(f"id {str(problem.id)!r} is already exported from "
                                 f"{ids[str(problem.id)]}; ids must differ within a bank",
                                 key="id", line=problem.line("id"))
            answered.update(problem.find, problem.expected)
            name = slug(os.path.splitext(os.path.basename(path))[0])
            unique, n = name, 2
            while unique in slugs:
                unique, n = f"{name}-{n}", n + 1
            sink.begin(ProblemBank(str(problem.id), problem.title, problem.kind.name,
                                   problem.source, unique, problem.kind.name.replace("_", " ")))
            tight: list[str] = []
            asking = 0  # the variants that ask
            said: dict[str, None] = {}  # the word answers not asked
            for n, p in enumerate(problems, 1):
                variant = variant_of(p, n, problem.title, ask, student, tight, pictures,
                                     ecf_share)
                said.update(dict.fromkeys(variant.unasked))
                if n == 1 and variant.carry.get("from") and lost is not None:
                    lost.append(_lost_line(path, variant))
                if variant.asks:
                    asking += 1
                    sink.add(variant)
                tiny.update({f"{b.label} = {b.value:.4g} {b.unit}".rstrip()
                             + f" ({os.path.basename(path)})": path
                             for b in variant.blanks if 0 < abs(b.value) < TINY})
        except InputError as err:
            sink.abort()
            errors.append(str(err.located(file=path)))
            continue
        if not asking:
            sink.abort()
            warn(f"{path}: no answer to ask; skipped")
            continue
        ids[str(problem.id)] = path
        if tight:
            tightened.append(path)
        if said:
            worded.append(path)
            words.update(said)
        slugs.add(unique)
        out.append(sink.commit(ProblemBank(str(problem.id), problem.title, problem.kind.name,
                                           problem.source, unique,
                                           problem.kind.name.replace("_", " "))))
    unknown = [name for name in ask or () if name not in answered]
    if unknown and answered:
        errors.append(f"--ask: {', '.join(map(repr, unknown))} is an answer of none of the "
                      f"files (their answers: {', '.join(sorted(answered))})")
    if unvaried:
        warn(f"{len(unvaried)} file(s) have no `vary` block and give one variant, the problem "
             f"as written: {_some(unvaried)}")
    if tightened:
        from ..core.expr import SIG

        warn(f"{len(tightened)} file(s) ask a tolerance tighter than the {SIG} significant figures "
             f"a student is asked for: those blanks accept {student.text} (--tolerance): "
             f"{_some(tightened)}")
    if tiny:
        warn(f"{len(tiny)} blank(s) hold a value below {TINY:g} in its unit, which a platform "
             "may not tell from 0 (Moodle adds 1e-14 to a numerical question's tolerance): "
             f"ask it in a smaller unit (find: moment: aN*m): {_some(list(tiny))}")
    if worded:
        warn(f"{len(worded)} file(s) have word answers without a list of choices "
             f"({', '.join(words)}), not asked: {_some(worded)}")
    return out, errors


def _student_tolerance(text: str) -> Tolerance:
    """``--tolerance``: a relative tolerance or significant figures (an absolute one would
    need every answer's unit)."""
    from ..checking.tolerance import parse_tolerance

    tol = parse_tolerance(text, None, "--tolerance")
    if tol.form == "absolute" or tol.magnitude or (tol.form == "relative" and tol.value <= 0):
        raise InputError(f"expected a relative tolerance (\"1%\") or significant figures "
                         f"(\"3 sig\"), got {text!r}", key="--tolerance")
    return tol


def _ask_option(text: str | None) -> tuple[str, ...] | None:
    """``--ask NAMES``: answer names, comma-separated."""
    if text is None:
        return None
    names = tuple(dict.fromkeys(n.strip() for n in text.split(",") if n.strip()))
    if not names or not all(n.replace("_", "").isalnum() for n in names):
        raise InputError(f"expected answer names separated by commas (precession,min_spin), "
                         f"got {text!r}", key="--ask")
    return names


def _some(paths: list[str]) -> str:
    return ", ".join(paths[:3]) + (f" and {len(paths) - 3} more" if len(paths) > 3 else "")


# ---- writing -----------------------------------------------------------------------

def sink_for(fmt: str) -> Sink:
    """Where `stream` puts the variants of a ``fmt`` export: files on disk as they come."""
    from ..render import bank_stream

    return {"moodle": bank_stream.MoodleSink, "qti": bank_stream.QtiSink,
            "blackboard": bank_stream.BlackboardSink,
            "prairielearn": bank_stream.PrairieLearnSink}.get(fmt, bank_stream.Sink)()


def write(banks_: list[ProblemBank], fmt: str, out: str, force: bool,
          inputs: list[str] | tuple[str, ...] = (), sink: Sink | None = None) -> list[str]:
    """Write the export to ``out`` (a file for moodle, qti and blackboard, a directory
    for prairielearn): never one of the ``inputs`` (the problem files), never a file that
    exists without ``force``, and the question directories all or nothing. The paths
    written. ``sink``: the streamed export (`sink_for`) when the banks hold no variants."""
    from ..core.files import refuse_input_as_output, write_atomic, write_set
    from ..render.bank_stream import PrairieLearnSink, QtiSink, _Body

    if fmt in FILE_FORMATS:
        _refuse_directory(out)
        refuse_input_as_output(out, inputs, option="--output")
        if isinstance(sink, (_Body, QtiSink)):
            return [str(write_atomic(out, sink.chunks(), force=force))]
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
    if isinstance(sink, PrairieLearnSink):
        return _write_questions(sink, out, force, inputs)
    items = [(os.path.join(out, rel), text)
             for rel, text in bank_prairielearn.files(banks_).items()]
    _refuse_targets([target for target, _ in items], inputs, force)
    for target, _ in items:
        os.makedirs(os.path.dirname(target), exist_ok=True)
    return [str(path) for path in write_set(items, force=force)]


def _refuse_targets(targets: list[str], inputs: list[str] | tuple[str, ...],
                    force: bool) -> None:
    """Before a question directory is written: none of its files over an input (the inputs
    looked up once), and none over an existing file without ``force``."""
    from ..core.files import refuse_outputs_over_inputs

    refuse_outputs_over_inputs(targets, inputs, option="--output", yaml_output=True)
    if not force:
        clash = [target for target in targets if os.path.lexists(target)]
        if clash:
            raise InputError(f"exists; not overwritten (use --force to replace it; {len(clash)} "
                             "file(s) of this export already there)", file=clash[0])


def _write_questions(sink: PrairieLearnSink, out: str, force: bool,
                     inputs: list[str] | tuple[str, ...]) -> list[str]:
    """`write` of PrairieLearn questions streamed (`sink`): the same checks, then each file
    staged from disk, and all placed or none."""
    from ..core.files import StagedSet

    targets = [os.path.join(out, rel) for rel in sink.names()]
    _refuse_targets(targets, inputs, force)
    for target in targets:
        os.makedirs(os.path.dirname(target), exist_ok=True)
    with StagedSet(force, None, targets) as staged:
        for target, (_, chunks) in zip(targets, sink.files()):
            staged.add(target, chunks)
        return [str(path) for path in staged.place()]


def _refuse_directory(out: str) -> None:
    if os.path.isdir(out):
        raise InputError("is a directory; give the file to write (a .xml for moodle, a .zip "
                         "for qti, a .txt for blackboard)", file=out)


def _blackboard_notes(records: int, choices: bool, warn: Callable[[str], None]) -> None:
    """What a Blackboard upload file lacks: more lines than Blackboard recommends per
    upload (``records`` lines written), and the worked answers (no feedback field in a NUM
    line), and the word answers (``choices``: some were asked)."""
    from ..render.bank_blackboard import RECOMMENDED_RECORDS

    if records > RECOMMENDED_RECORDS:
        warn(f"{records} questions: Blackboard recommends at most {RECOMMENDED_RECORDS} per "
             "uploaded file (browser time-outs); export fewer problems per file "
             "(docs/course.md, Blackboard Learn)")
    warn("a Blackboard upload file has no feedback field: the worked answers are not in it")
    if choices:
        warn("word answers (multiple choice in the other formats) are not in a Blackboard "
             "file: it holds NUM questions")


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
@click.option("--ask", "ask_text", metavar="NAMES",
              help="The answers to ask, comma-separated (precession,min_spin); a file asks "
                   "those of them it finds. Default: each file's `ask:`, else every answer "
                   "of its find and expected.")
@click.option("--tolerance", default=STUDENT_TOLERANCE, show_default=True,
              help="What a blank accepts where the problem's tolerance is tighter than the "
                   "significant figures the question asks for (\"1%\" or \"3 sig\").")
@click.option("--pictures/--no-pictures", default=True, show_default=True,
              help="Package the worked answer's picture (a released top's axis path, a "
                   "bicycle's eigenvalues) as a PNG with the feedback (not in blackboard).")
@click.option("--ecf", "ecf_share", type=click.FloatRange(0, 1), default=DEFAULT_ECF,
              show_default=True,
              help="prairielearn: the share of a point for an answer right for the "
                   "student's own wrong earlier step (a file's `steps:`), errors carried "
                   "forward by the question's grade(); the teacher's choice.")
@click.option("--force", is_flag=True, help="Replace files of OUT that exist.")
def export(files: tuple[str, ...], fmt: str, count: int, seed: int, out: str,
           ask_text: str | None, tolerance: str, pictures: bool, ecf_share: float,
           force: bool) -> None:
    """Export problem FILES as a question bank whose every answer is gyro's.

    FILES may be directories (every *.yaml and *.yml in them) or quoted globs.
    Exit 0 when every file was exported, 2 when one was bad (the others are
    still exported).
    """
    def warn(line: str) -> None:
        click.echo(f"gyro: {line}", err=True)

    from ..render.bank_stream import BlackboardSink
    from ..solving.paths import problem_files

    try:
        _student_tolerance(tolerance)
        ask = _ask_option(ask_text)
    except InputError as err:
        warn(str(err))
        sys.exit(2)
    sink = sink_for(fmt)
    lost: list[str] = []
    made, errors = stream(files, sink, count, seed, warn, ask, tolerance,
                          pictures and fmt != "blackboard", ecf_share, lost)
    if fmt != "prairielearn":
        how = {"blackboard": "gyro check --answers DOWNLOAD --responses blackboard PATHS "
                             "--credit ecf=S (DOWNLOAD: the test's Download Results, By "
                             "Question and User)",
               "moodle": "gyro check --answers DOWNLOAD --responses moodle PATHS --credit "
                         "ecf=S (DOWNLOAD: the quiz's Responses report as CSV, its questions "
                         "in the bank's order)",
               "qti": "gyro check --answers DOWNLOAD --responses canvas PATHS --credit "
                      "ecf=S (DOWNLOAD: a Canvas quiz's Student Analysis)"}[fmt]
        for line in lost:
            warn(f"{line}; a {fmt} question grades each blank alone, so these lose errors "
                 f"carried forward: regrade the responses with {how}")
    for line in errors:
        warn(line)
    if not made:
        warn("nothing to export")
        sys.exit(2)
    try:
        written = write(made, fmt, out, force, problem_files(files)[0], sink)
    except InputError as err:
        warn(str(err))
        sys.exit(2)
    questions = sum(b.size for b in made)
    shown = out if fmt != "prairielearn" else f"{out} ({len(written)} files)"
    if isinstance(sink, BlackboardSink):
        _blackboard_notes(sink.records, sink.choices, warn)
        shown += f" ({sink.records} NUM questions)"
    click.echo(f"wrote {shown}: {len(made)} problem(s), {questions} variant(s)", err=True)
    if errors:
        sys.exit(2)
