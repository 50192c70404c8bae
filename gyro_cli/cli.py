"""The command line: solve, check, simulate, new, schema, vary, handout, kinds.

Every command exits 0 on success, 1 when an answer does not match (check), 2 on
bad input or usage, with a one-line message and never a traceback, and 3 when
gyro itself failed on a file (an internal error: one line naming the file, then
the next file goes on).
"""

from __future__ import annotations

import gc
import os
import sys
from typing import NoReturn

# Start-up makes few reference cycles; the collector's default first threshold (700
# allocations) ran it about forty times during the imports alone. A solve keeps the raised
# threshold; every other command gets the default back when it is looked up (`get_command`):
# a bank's or a roster's garbage grows with its variants (export --variants 2000 peaked at
# 83 MB with the raised threshold, 29 MB with the default).
GC_DEFAULT = gc.get_threshold()
gc.set_threshold(10_000, *GC_DEFAULT[1:])

import click  # noqa: E402

from . import __version__
from .commands.exits import INTERNAL, fail, internal
from .commands.exits import outputs_apart as _outputs_apart
from .core.errors import InputError, terminal_text
from .render.formats import HELP as FORMAT_HELP
from .render.formats import NAMES as FORMATS

# click's own words for --help and --version, written here: click translates them with
# gettext, whose first call imports locale (about 1 ms of every run)
HELP_TEXT = "Show this message and exit."
VERSION_TEXT = "Show the version and exit."


def _show_help(ctx: click.Context, _param: click.Parameter, value: bool) -> None:
    if value and not ctx.resilient_parsing:
        click.echo(ctx.get_help(), color=ctx.color)
        ctx.exit()


def _show_version(ctx: click.Context, _param: click.Parameter, value: bool) -> None:
    if value and not ctx.resilient_parsing:
        click.echo(f"gyro, version {__version__}", color=ctx.color)
        ctx.exit()


class _Command(click.Command):
    """A command whose --help option is made without gettext (click's is the same option)."""

    _help: click.Option | None = None

    def get_help_option(self, ctx: click.Context) -> click.Option | None:
        names = self.get_help_option_names(ctx)
        if not names or not self.add_help_option:
            return None
        if self._help is None:  # one object: click orders the eager callbacks by identity
            self._help = click.Option(names, is_flag=True, is_eager=True, expose_value=False,
                                      callback=_show_help, help=HELP_TEXT)
        return self._help


class _Guarded(_Command, click.Group):
    """The last line of defence: an exception no command caught is one line and exit 3.

    Around every command (``--help`` and ``--version`` too): a failing standard
    output never stops the files asked for being written (core/streams.py: the
    reader leaving is 141, any other failure one line and exit 2), and SIGINT,
    SIGTERM and SIGHUP end gyro with 128 + the signal's number after its
    ``finally`` blocks have removed any temporary file.
    """

    def main(self, *args, **kwargs):  # type: ignore[no-untyped-def, override]
        if kwargs.get("standalone_mode", True) is False:
            return super().main(*args, **kwargs)
        from .core.streams import Interrupted, guard_output, on_signals

        guard = guard_output()
        try:
            undo = on_signals()
            code: object = 0
            try:
                try:
                    super().main(*args, **kwargs)
                except SystemExit as done:
                    code = done.code
                except Interrupted as signalled:
                    code = signalled.exit_code
                    if signalled.exit_code == 130:
                        click.echo("gyro: interrupted", err=True)
            finally:
                undo()
            code = 0 if code is None else code if isinstance(code, int) else 1
            message = guard.message()
            if message:
                click.echo(f"gyro: {message}", err=True)
            code = guard.exit_code(code)
        finally:
            guard.restore()
        sys.exit(code)

    def invoke(self, ctx: click.Context):  # type: ignore[no-untyped-def]
        try:
            return super().invoke(ctx)
        except (click.exceptions.ClickException, click.exceptions.Exit,
                click.exceptions.Abort):
            raise
        except BrokenPipeError:
            _reader_left()
        except Exception as err:
            internal(getattr(err, "gyro_file", None), err)
            sys.exit(INTERNAL)

    command_class = _Command

    # Commands whose module is imported only when they run: `gyro solve` does not pay for
    # their options. Each with the first paragraph of its help, which `gyro --help` lists
    # (tests/test_i37_speed.py holds these to the commands' own).
    LAZY = {
        "export": ("gyro_cli.commands.export", "export", "Export problem FILES as a "
                   "question bank whose every answer is gyro's."),
        "new": ("gyro_cli.commands.others", "new", "Print (or write) a commented problem "
                "template with every key of KIND."),
        "schema": ("gyro_cli.commands.others", "schema", "Print a JSON Schema of the "
                   "problem format (for editors' YAML support)."),
        "vary": ("gyro_cli.commands.others", "vary", "Write COUNT variants of FILE with "
                 "values drawn from its `vary:` block, or with --roster one variant per "
                 "student of each FILE."),
        "simulate": ("gyro_cli.commands.others", "simulate", "Integrate the top of FILE "
                     "(released_top or steady_precession) from Euler's equations and "
                     "compare with the analytic answer; --animate draws the motion."),
        "handout": ("gyro_cli.commands.others", "handout", "Write the students' question "
                    "sheets: a cover and each problem's statement with the student's "
                    "numbers; --solutions adds the worked answers."),
        "kinds": ("gyro_cli.commands.others", "kinds", "List the problem kinds with their "
                  "given keys and answers."),
    }

    def list_commands(self, ctx: click.Context) -> list[str]:
        return sorted(set(super().list_commands(ctx)) | set(self.LAZY))

    def format_commands(self, ctx: click.Context, formatter: click.HelpFormatter) -> None:
        """`gyro --help`'s list of commands, a command not loaded yet by its help above."""
        listed = []
        for name in self.list_commands(ctx):
            if name in self.LAZY and name not in self.commands:
                listed.append((name, click.Command(name, help=self.LAZY[name][2])))
            else:
                command = self.get_command(ctx, name)
                if command is not None and not command.hidden:
                    listed.append((name, command))
        if listed:
            limit = formatter.width - 6 - max(len(name) for name, _ in listed)
            with formatter.section("Commands"):
                formatter.write_dl([(name, command.get_short_help_str(limit))
                                    for name, command in listed])

    def get_command(self, ctx: click.Context, name: str) -> click.Command | None:
        if name != "solve":
            gc.set_threshold(*GC_DEFAULT)
        if name in self.LAZY and name not in self.commands:
            from importlib import import_module

            module, attribute, _ = self.LAZY[name]
            self.add_command(getattr(import_module(module), attribute), name)
        return super().get_command(ctx, name)

    def make_context(self, *args, **kwargs):  # type: ignore[no-untyped-def]
        # `gyro --help` and `gyro --version` print while the arguments are parsed, before
        # invoke: a reader that left ends them as it ends every command (click's own
        # handling would exit 1, which means "an answer is wrong").
        try:
            return super().make_context(*args, **kwargs)
        except BrokenPipeError:
            _reader_left()


def _reader_left() -> None:
    """The reader left (gyro solve ... | head): end quietly, as a program killed by SIGPIPE
    would (128 + 13), not with an internal error."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError):
        pass
    sys.exit(141)


@click.group(cls=_Guarded, context_settings={"help_option_names": ["-h", "--help"]})
@click.option("--version", is_flag=True, is_eager=True, expose_value=False,
              callback=_show_version, help=VERSION_TEXT)
def main() -> None:
    """Worked answers to textbook problems of gyroscopic motion (Chapter 11).

    Write a problem as a YAML file with units, then `gyro solve FILE`.
    """




@main.command()
@click.argument("files", nargs=-1, required=True, metavar="FILES|DIRS")
@click.option("--format", "fmt", type=click.Choice(FORMATS), default="text", show_default=True,
              help=FORMAT_HELP)
@click.option("--plot", "plot_file", metavar="FILE",
              help="released_top: also draw the axis's path, theta(t) and phidot(t) to FILE "
                   "(.png, .svg or .pdf); bicycle: the eigenvalues against speed; one problem "
                   "file.")
@click.option("--force", is_flag=True, help="With --plot: replace FILE if it exists.")
@click.option("--standalone", is_flag=True,
              help="With --format latex: a complete document (preamble, title, one section "
                   "per problem) that pdflatex compiles as it is.")
@click.option("--units", "system", type=click.Choice(("si", "us")), default=None,
              help="us: work the problem in slug, ft and lbf (steps, Given table, answers "
                   "the file gives no unit for), as US textbooks do; si (the default, or the "
                   "file's `units` key).")
@click.option("--animate", "embed", is_flag=True,
              help="With --format html: embed an animation of the motion (as `gyro simulate "
                   "--animate`) in the worked answer of each problem whose kind moves.")
def solve(files: tuple[str, ...], fmt: str, plot_file: str | None = None,
          force: bool = False, standalone: bool = False, system: str | None = None,
          embed: bool = False) -> None:
    """Solve problem FILES and print worked answers.

    FILES may also be directories (every *.yaml and *.yml in them, as for
    `gyro check`) or quoted globs.
    """
    from .api import document as compose
    from .api import solve_file as solve_problem
    from .render import formats
    from .solving.paths import problem_files

    paths, missing = problem_files(files)
    _outputs_apart(paths, plot=plot_file)
    for _, message in missing:
        click.echo(f"gyro: {terminal_text(message)}", err=True)
    if plot_file and len(paths) != 1:
        fail("--plot draws one problem: give one FILE")
    if standalone and fmt != "latex":
        fail("--standalone goes with --format latex")
    if embed and fmt != "html":
        fail("--animate goes with --format html (an animation file alone: gyro simulate "
             "FILE --animate OUT)")
    bad, crashed = len(missing), 0
    output = formats.get(fmt)
    composed = output.composes(standalone)  # one document of every file, at the end
    done: list = []
    pieces: list[str | None] = []
    scripts: list[str] = []
    for i, path in enumerate(paths):
        try:
            result = solve_problem(path, units=system)
            level = 1 if len(paths) == 1 else 2
            if embed:
                from .render.animate import player_script

                motion = result.animation_html()
                text: str | None = result.html(level=level, animation=motion)
                scripts += [player_script(result.animation_id)] if motion else []
            else:
                text = None if standalone else result.render(fmt, level)
        except InputError as err:
            click.echo(f"gyro: {err}", err=True)
            bad += 1
            continue
        except Exception as err:  # a bug: say so on one line, solve the next file
            internal(path, err)
            crashed += 1
            continue
        if composed:
            done.append(result)
            pieces.append(text)
        else:
            click.echo((output.separator if i else "") + (text or ""), nl=False)
        if plot_file:  # after the worked answer, so a refused plot does not hide it
            from .render.plot import plot_result

            try:
                plot_result(result.solved, plot_file, force=force)
            except InputError as err:
                click.echo(f"gyro: {err}", err=True)
                bad += 1
    if done:
        click.echo(compose(done, fmt, standalone=standalone, pieces=pieces, scripts=scripts),
                   nl=False)
    if crashed:
        sys.exit(INTERNAL)
    if bad:
        sys.exit(2)


@main.command()
@click.argument("paths", nargs=-1)
@click.option("--format", "fmt", type=click.Choice(("table", "json")), default="table",
              show_default=True, help="table: one line per answer; json: one document.")
@click.option("--junit", "junit_file", metavar="FILE",
              help="Also write JUnit XML to FILE (a testsuite per file, a testcase per answer).")
@click.option("--strict", is_flag=True,
              help="Count problems without expected answers as failures (exit 1).")
@click.option("--jobs", "-j", type=click.IntRange(min=1), default=None, metavar="N",
              help="Check the files in N worker processes [default: the CPUs available].")
@click.option("--timeout", type=click.FloatRange(min=0, min_open=True), default=60.0,
              show_default=True, metavar="SECONDS",
              help="Time limit per file: a file that takes longer is an internal error, the "
                   "others go on.")
@click.option("--shard", metavar="K/N",
              help="Check only the K-th of N stable parts of the files (by a hash of each "
                   "path), for one job of a CI matrix of N jobs.")
@click.option("--merge", is_flag=True,
              help="PATHS are JSON reports (--format json) of shards: print them as one "
                   "report (and --junit), with the summary and exit code of the whole.")
@click.option("--answers", "sheet", metavar="SHEET",
              help="Grade students' answers in SHEET (CSV or YAML) instead of the answer key.")
@click.option("--responses", type=click.Choice(("blackboard", "moodle", "canvas")),
              default=None,
              help="With --answers: SHEET is a platform's download of the responses to a "
                   "bank gyro exported from PATHS (blackboard: its Download Results, By "
                   "Question and User; moodle: the quiz's Responses report as CSV; canvas: "
                   "the quiz's Student Analysis of a QTI bank), "
                   "regraded by gyro (errors carried forward too).")
@click.option("--variants", "count", type=click.IntRange(1, 10_000), default=1,
              metavar="N", help="With --responses blackboard|canvas: the bank was exported "
                                "with --variants N (and --seed): each response is graded "
                                "against the variant its question drew.")
@click.option("--seed", type=int, default=0, show_default=True,
              help="With --variants: the bank's --seed.")
@click.option("--attempts", type=click.Choice(("latest", "best", "first", "average")),
              default="latest", show_default=True,
              help="With --responses moodle|canvas: regrade each student's latest attempt; "
                   "or every attempt, keeping the one with the most points (best), the first "
                   "(first), or the mean of their points (average), as the quiz keeps a "
                   "grade.")
@click.option("--decimal-comma", is_flag=True,
              help="With --answers: the class writes a decimal comma (965,4 is 965.4; "
                   "1.234,5 is 1234.5); by default a comma in a number is refused as "
                   "ambiguous. With --responses moodle: the site's language writes one, as "
                   "Moodle reads it there; by default, as on an English site, ',' separates "
                   "thousands (965,4 is 9654).")
@click.option("--out", metavar="FILE", help="With --answers: write the grades CSV to FILE.")
@click.option("--out-format", "out_format", default="grades", show_default=True,
              type=click.Choice(("grades", "canvas", "gradescope", "prairielearn")),
              help="With --out: gyro's grades CSV, a Canvas gradebook import CSV, or "
                   "Gradescope's / PrairieLearn's results.json (one per student: FILE for "
                   "one student, else a directory of STUDENT.json).")
@click.option("--credit", metavar="SLIP=SHARE,...",
              help="With --answers: partial credit for a value off by a named slip, e.g. "
                   "2pi=0.5,sign=0.5 (slips: 2pi, rpm, 60, g, deg, 10, sign); ecf=S: the "
                   "share for a value right for the student's own wrong earlier values "
                   "(errors carried forward).")
@click.option("--feedback", "feedback_dir", metavar="DIR",
              help="With --answers: write each student a short page (DIR/STUDENT.md): what "
                   "was right, what was off and the likely slip.")
@click.option("--reveal", is_flag=True,
              help="With --feedback or a Gradescope / PrairieLearn --out: show each student "
                   "the answers they did not get right (after the due date).")
@click.option("--no-hints", "no_hints", is_flag=True,
              help="With --feedback, --student or a Gradescope / PrairieLearn --out: tell "
                   "each student only whether each value is right, not too high or too low, "
                   "its likely slip or its place (with resubmissions those lead to the "
                   "answer).")
@click.option("--assignment", metavar="ASSIGNMENT.csv",
              help="With --answers: grade each student only on their own variants, as "
                   "ASSIGNMENT.csv (from gyro vary --roster) gives them; PATHS optional.")
@click.option("--student", metavar="ID",
              help="With --answers: the one student who submitted SHEET (inside an "
                   "autograder): a row naming anyone else is refused, and only their grades "
                   "are printed and written, without the solver's values.")
@click.option("--html", "html_file", metavar="FILE",
              help="Also write the report as a self-contained HTML page to FILE: failing "
                   "answers first, each linking to its worked answer.")
@click.option("--force", is_flag=True, help="With --out, --html or --feedback: replace the "
              "files that exist.")
def check(paths: tuple[str, ...], fmt: str, junit_file: str | None, strict: bool,
          sheet: str | None, out: str | None, force: bool, html_file: str | None = None,
          assignment: str | None = None, out_format: str = "grades",
          credit: str | None = None, feedback_dir: str | None = None,
          reveal: bool = False, jobs: int | None = None, timeout: float = 60.0,
          shard: str | None = None, merge: bool = False, student: str | None = None,
          responses: str | None = None, decimal_comma: bool = False,
          attempts: str = "latest", no_hints: bool = False, count: int = 1,
          seed: int = 0) -> None:
    """Solve problem files and compare with their `expected` answers.

    PATHS are files, directories (searched recursively for *.yaml and *.yml)
    or globs. Exit 0 when every answer matches, 1 when one does not (or
    nothing was compared), 2 when a file is bad (the others are still checked).
    Each file's lines are printed as soon as it is checked.
    """
    if not paths and not (sheet and assignment):
        fail("give the problem files or directories to check (PATHS)")
    if sheet is None:
        if assignment or credit is not None or feedback_dir or student is not None or reveal \
                or responses or decimal_comma or no_hints:
            fail("--assignment, --credit, --feedback, --student, --reveal, --no-hints, "
                 "--responses and --decimal-comma go with --answers SHEET")
        if out or (force and not html_file) or out_format != "grades":
            fail("--out and --out-format go with --answers SHEET, --force with --out or --html")
        if merge and (shard or html_file or jobs):
            fail("--merge joins JSON reports: it goes with --format, --junit and --strict only")
        found = None
        if junit_file is not None or html_file is not None:
            from .solving.paths import problem_files

            identities: dict[str, tuple[int, int]] = {}
            found = problem_files(paths, identities)  # collected once: for this and the run
            _outputs_apart(found[0], identities, junit=junit_file, html=html_file)
            del identities  # a bank's worth: not kept for the run
            if junit_file and html_file and os.path.abspath(junit_file) == \
                    os.path.abspath(html_file):
                fail("--junit and --html name the same file")
        from .core.streams import cpus

        _check_key(paths, fmt, junit_file, strict, html_file, force, jobs or cpus(), timeout,
                   shard, merge, found)
    if junit_file or strict or html_file or jobs or shard or merge:
        fail("--junit, --html, --strict, --jobs, --shard and --merge go with checking the "
             "answer key, not with --answers")
    if out_format != "grades" and not out:
        fail("--out-format goes with --out FILE")
    if reveal and not (feedback_dir or out_format in ("gradescope", "prairielearn")):
        fail("--reveal goes with --feedback DIR or --out-format gradescope|prairielearn")
    if no_hints and not (feedback_dir or student is not None
                         or out_format in ("gradescope", "prairielearn")):
        fail("--no-hints goes with --feedback DIR, --student ID or --out-format "
             "gradescope|prairielearn (the teacher's grades keep every note)")
    from .api import grade
    from .render import grades_report

    read = [sheet]  # and, graded by assignment, what grades_report.graded_inputs adds
    if out is not None or feedback_dir:
        from .solving.paths import problem_files

        read += problem_files(paths)[0]
    if out is not None:
        _outputs_apart(read, out=out)

    if decimal_comma and responses not in (None, "moodle"):
        fail("--decimal-comma goes with a sheet or --responses moodle (Canvas and Blackboard "
             "keep the number as typed)")
    if attempts != "latest" and responses not in ("moodle", "canvas"):
        fail("--attempts goes with --responses moodle or canvas")
    if attempts != "latest" and student is not None:
        fail(f"--attempts {attempts} grades a whole class's download, not one --student")
    if responses and assignment:
        fail("--responses reads a bank exported from PATHS, not --assignment variants")
    if (count != 1 or seed != 0) and responses not in ("blackboard", "canvas"):
        fail("--variants and --seed go with --responses blackboard or canvas, whose "
             "downloads give each response's question (Moodle's report does not say which "
             "variant a student drew)")
    try:
        graded = _grade_responses(sheet, responses, paths, credit, student, reveal,
                                  decimal_comma, attempts, not no_hints, count, seed) \
            if responses else \
            grade(sheet, paths, assignment=assignment, credit=credit, student=student,
                  reveal=reveal, decimal_comma=decimal_comma, hints=not no_hints)
        if out or feedback_dir:  # one set: a refused --feedback leaves no --out behind
            grades_report.write_outputs(graded, force, read, reveal, out=out or None,
                                        fmt=out_format, feedback=feedback_dir or None)
    except InputError as err:
        fail(err)
    for line in graded.notes:
        click.echo(f"gyro: note: {terminal_text(line)}", err=True)
    for line in graded.errors:
        click.echo(f"gyro: {terminal_text(line)}", err=True)
    click.echo(grades_report.as_json(graded) if fmt == "json" else grades_report.table(graded),
               nl=fmt == "json")
    if graded.errors:
        sys.exit(INTERNAL)


def _grade_responses(download: str, platform: str, paths: tuple[str, ...],
                     credit: str | None, student: str | None,
                     reveal: bool, decimal_comma: bool = False,
                     attempts: str = "latest", hints: bool = True, count: int = 1,
                     seed: int = 0):  # type: ignore[no-untyped-def]
    """Grade a platform's download of responses: read as a gyro answer sheet (written to
    a scratch folder that is removed after, with the variants of a bank exported with
    ``count`` > 1, against which each student is graded alone: `each_alone`)."""
    import tempfile

    from .api import grade
    from .commands.responses import (
        bank_files,
        blackboard_sheet,
        canvas_sheet,
        each_alone,
        moodle_sheet,
    )

    notes: list[str] = []
    every_attempt = attempts != "latest"
    with tempfile.TemporaryDirectory() as scratch:
        bank = bank_files(paths, count, seed, scratch)
        if platform == "moodle":
            text, people = moodle_sheet(download, bank, decimal_comma, every_attempt, notes)
        elif platform == "canvas":
            text, people = canvas_sheet(download, bank, every_attempt)
        else:
            text, people = blackboard_sheet(download, bank)
        files = [banked[0] for banked in bank]
        if count == 1:
            sheet = os.path.join(scratch, "responses.csv")
            with open(sheet, "w", encoding="utf-8", newline="") as out:
                out.write(text)
            graded = grade(sheet, files, credit=credit, student=student, reveal=reveal,
                           hints=hints)
        else:
            graded = each_alone(text, scratch, lambda sheet: grade(
                sheet, files, credit=credit, student=student, reveal=reveal, hints=hints))
    graded.people = people  # the platform's names and ids, for --out-format canvas
    graded.notes[:0] = notes
    if every_attempt:
        from .commands.responses import best_of_attempts

        graded = best_of_attempts(graded, attempts)
    return graded


def _check_key(paths: tuple[str, ...], fmt: str, junit_file: str | None, strict: bool,
               html_file: str | None, force: bool, jobs: int, timeout: float,
               shard: str | None, merge: bool,
               found: tuple[list[str], list[tuple[str, str]]] | None = None) -> NoReturn:
    """`gyro check` of the answer key: each file's result printed (and spooled for JUnit)
    as it comes, in the files' order, then the summary; exits with the run's code."""
    from .api import check_stream
    from .render import check_report, junit

    def printed(problem):  # type: ignore[no-untyped-def]
        return check_report.printed(problem, fmt, junit_file is not None)

    try:
        run = check_stream(paths, strict=strict, jobs=jobs, timeout=timeout, shard=shard,
                           merge=merge, worked=bool(html_file), then=printed,
                           idle=sys.stdout.flush, found=found)
        if junit_file:
            from .core.files import refuse_special

            refuse_special(junit_file)  # before the run, not after it
    except InputError as err:
        fail(err)
    tally = run.tally
    spool = junit.Spool() if junit_file else None
    stream = check_report.JsonStream() if fmt == "json" else None
    click.echo(stream.head() if stream else check_report.table_head(), nl=False)
    write = sys.stdout.write  # flushed when the next result is not ready (idle), not per file
    try:
        for problem in run.results:
            if problem.error:
                sys.stdout.flush()  # the report so far, then its error on stderr
                click.echo(f"gyro: {terminal_text(problem.error)}", err=True)
            tally.count(problem.status, problem.internal, problem.passed, problem.failed)
            if spool:
                spool.add_text(*problem.junit)
            write(stream.line(problem.report) if stream else problem.report)
    finally:
        run.close()  # a reader that left, or Ctrl-C: the workers end now
    click.echo(stream.tail(tally, run.shards) if stream else check_report.summary_line(tally))
    if spool and junit_file:
        from .core.files import write_atomic

        try:
            write_atomic(junit_file, spool.chunks(), force=True)
        except InputError as err:
            fail(err)
    if html_file:
        from .core.files import write_atomic

        try:
            assert run.report is not None  # worked=True keeps the report
            write_atomic(html_file, run.report.html(page=True), force=force)
        except InputError as err:
            fail(err)
    sys.exit(tally.exit_code)


if __name__ == "__main__":
    main()
